"""Configuration: the node's defaults (checked against the shipped config/default.yaml, read here with PyYAML), the
parameters by the node's names, and refusals that name the parameter and leave the configuration as it was."""
import math

import pytest
import yaml

import billiard_shot_planner as bsp
from conftest import PACKAGE_ROOT


def flatten(tree, prefix=""):
    """{"table": {"cloth": {"friction": 0.2}}} -> {"table/cloth/friction": 0.2}."""
    flat = {}
    for key, value in tree.items():
        name = prefix + key
        if isinstance(value, dict):
            flat.update(flatten(value, name + "/"))
        else:
            flat[name] = value
    return flat


# The library's budget of a call, as impact_solve's: the node answers a robot within 1 s, a batch may take longer.
LIBRARY_DEFAULTS = {"solver/max_seconds": 10.0}


def test_the_defaults_are_the_shipped_parameter_file():
    shipped = flatten(yaml.safe_load((PACKAGE_ROOT / "config" / "default.yaml").read_text()))
    shipped.update(LIBRARY_DEFAULTS)
    config = bsp.Configuration()
    compared = 0
    for name in config.names():
        if name in shipped and not isinstance(shipped[name], bool):
            assert config[name] == pytest.approx(float(shipped[name]), rel=1e-12), name
            compared += 1
    assert compared >= 30  # the file sets most numeric parameters explicitly


def test_a_parameter_set_by_its_name_reads_back():
    config = bsp.Configuration()
    config["cue_contact/restitution"] = 0.7
    config["table/cloth/friction"] = 0.25
    assert config["cue_contact/restitution"] == 0.7
    assert config["table/cloth/friction"] == 0.25
    assert "motion/sliding_friction" in config
    assert "no/such/parameter" not in config


def test_a_copy_is_independent():
    config = bsp.Configuration()
    copy = config.copy()
    copy["ball_mass"] = 0.2
    assert config["ball_mass"] == 0.17


@pytest.mark.parametrize("value", [1.5, -0.1, math.nan, math.inf])
def test_a_refused_value_names_the_parameter_and_changes_nothing(value):
    config = bsp.Configuration()
    with pytest.raises(bsp.Error) as raised:
        config["cue_contact/restitution"] = value
    assert raised.value.code == "invalid_argument"
    assert raised.value.field == "cue_contact/restitution"
    assert isinstance(raised.value, ValueError)
    assert config["cue_contact/restitution"] == bsp.Configuration()["cue_contact/restitution"]


def test_an_unknown_name_is_named():
    config = bsp.Configuration()
    with pytest.raises(bsp.Error) as raised:
        config["table/clth/friction"]
    assert raised.value.field == "table/clth/friction"
    with pytest.raises(bsp.Error):
        config["table/clth/friction"] = 0.2
    with pytest.raises(TypeError):
        config["ball_mass"] = "heavy"
