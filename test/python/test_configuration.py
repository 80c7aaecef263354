"""Configuration: the node's defaults (checked against the shipped config/default.yaml, read here with PyYAML), the
parameters by the node's names, and refusals that name the parameter and leave the configuration as it was."""
import math
import pickle

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
    with pytest.raises(bsp.Error) as raised:
        config["ball_mass"] = "heavy"
    assert raised.value.field == "ball_mass"



def test_choices_and_flags_are_set_by_name_and_checked():
    config = bsp.Configuration()
    assert config.choices()["motion/rolling_model"] == ["paper", "pooltool"]
    assert config["motion/rolling_model"] == "paper" and config["motion/planar"] is False
    config["motion/rolling_model"] = "pooltool"
    config["motion/planar"] = True
    assert config["motion/rolling_model"] == "pooltool" and config["motion/planar"] is True
    for name, value in [("motion/rolling_model", "leckie"), ("motion/planar", "yes"), ("ball_ball/friction_model", 3)]:
        with pytest.raises(bsp.Error) as raised:
            config[name] = value
        assert raised.value.field == name
    assert config["motion/rolling_model"] == "pooltool"


def test_a_law_type_brings_its_own_parameters():
    config = bsp.Configuration()
    assert "table/cushion/law/yield_speed" not in config
    config.update({"table/cushion/law/type": "elastic_plastic", "table/cushion/law/yield_speed": 1.272})
    assert config["table/cushion/law/yield_speed"] == 1.272
    with pytest.raises(bsp.Error) as raised:
        config["table/cushion/law/type"] = "hertz_like"
    assert raised.value.field == "table/cushion/law/type"


def test_update_is_all_or_none():
    config = bsp.Configuration()
    with pytest.raises(bsp.Error) as raised:
        config.update({"ball_mass": 0.2, "table/cloth/friction": -1.0})
    assert raised.value.field == "table/cloth/friction"
    assert config["ball_mass"] == 0.17


def test_pockets_are_a_field():
    config = bsp.Configuration()
    assert len(config["table/pockets"]) == 6
    assert config["table/pockets"][3][:3] == pytest.approx((1.27, 0.635, 0.06))
    assert config["table/pockets"][3][3] == "top_right"
    config["table/pockets"] = [(1.27, 0.635, 0.05)]
    assert config["table/pockets"] == [(1.27, 0.635, 0.05, "pocket0")]  # a pocket without an id: its place
    config["table/pockets"] = [(1.27, 0.635, 0.05, "corner"), (-1.27, 0.635, 0.05)]
    assert config["table/pockets"] == [(1.27, 0.635, 0.05, "corner"), (-1.27, 0.635, 0.05, "pocket1")]
    with pytest.raises(bsp.Error) as raised:
        config["table/pockets"] = [(1.0, 2.0)]
    assert raised.value.field == "table/pockets"
    with pytest.raises(bsp.Error) as raised:
        config["table/pockets"] = [(1.27, 0.635, 0.05, "corner"), (-1.27, 0.635, 0.05, "corner")]
    assert raised.value.field == "table/pockets[1]/id"


def test_a_pickled_configuration_keeps_every_field():
    config = bsp.Configuration()
    config.update({"table/cushion/law/type": "elastic_plastic", "table/cushion/law/yield_speed": 1.5,
                   "motion/rolling_model": "pooltool", "motion/planar": True, "table/pockets": [(0.0, 0.635, 0.07)]})
    assert pickle.loads(pickle.dumps(config)).to_dict() == config.to_dict()


def shipped(name):
    return yaml.safe_load((PACKAGE_ROOT / "config" / name).read_text())


def test_load_reads_the_shipped_parameter_files_in_turn():
    config = bsp.Configuration.load(str(PACKAGE_ROOT / "config" / "default.yaml"),
                                    str(PACKAGE_ROOT / "config" / "paper_masse.yaml"))
    masse = flatten(shipped("paper_masse.yaml"))
    assert masse["cue_end_mass"] == math.inf and config["cue_end_mass"] == math.inf
    assert config["cue_contact/eta2"] == masse["cue_contact/eta2"] == 7.0
    assert config["motion/planar"] is True
    # What the overlay leaves out keeps the first file's value.
    assert config["ball_ball/restitution"] == flatten(shipped("default.yaml"))["ball_ball/restitution"]
    cue = bsp.Configuration.load(str(PACKAGE_ROOT / "config" / "cues" / "hand_held.yaml"))
    assert cue["cue_mass"] == flatten(shipped("cues/hand_held.yaml"))["cue_mass"]


def test_a_table_file_brings_its_table_balls_and_laws():
    config = bsp.Configuration().with_table_file(str(PACKAGE_ROOT / "config" / "tables" / "snooker_mathavan.yaml"))
    snooker = flatten(shipped("tables/snooker_mathavan.yaml"))
    assert config["ball_mass"] == snooker["balls/mass"] == 0.1406
    assert config["table/length"] == snooker["table/length"]
    assert config["table/cushion/law/type"] == "elastic_plastic"
    assert config["table/cushion/law/yield_speed"] == snooker["table/cushion/law/yield_speed"]
    assert config["table/pockets"][0][:3] == pytest.approx((-1.7845, -0.889, 0.045))


@pytest.mark.parametrize(
    "text, field",
    [("table:\n  cloth:\n    frition: 0.2\n", "table/cloth/frition"),
     ("ball_mas: 0.2\n", "ball_mas"),
     ("motion: {rolling_model: leckie}\n", "motion/rolling_model"),
     ("table: {cloth: {friction: fast}}\n", "table/cloth/friction"),
     ("table: {pockets: [[0, 0]]}\n", "table/pockets[0]"),
     ("cue_mass: [1, 2]\n", "cue_mass")])
def test_a_bad_parameter_file_names_the_field(tmp_path, text, field):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(bsp.Error) as raised:
        bsp.Configuration.load(str(path))
    assert raised.value.field == field


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(bsp.Error) as raised:
        bsp.Configuration.load(str(tmp_path / "absent.yaml"))
    assert raised.value.field == "parameter_file"


def test_a_file_that_is_no_parameter_file_is_an_error_not_a_crash(tmp_path):
    garbage = tmp_path / "garbage.yaml"
    garbage.write_bytes(b"\xff\xfe[\x80\x81: {\n\x00\xc3")  # neither UTF-8 nor YAML: the message quotes its bytes
    for path in (str(garbage), str(tmp_path), "/dev/zero"):  # and a directory, and a device without end
        with pytest.raises(bsp.Error) as raised:
            bsp.Configuration.load(path)
        assert raised.value.field == "parameter_file", path


def test_the_table_outline_names_its_cushions_and_pockets_and_follows_the_size():
    """The 9-ft table's six pockets by id, their mouths the WPA's; a carom table's four rails and no pockets."""
    config = bsp.Configuration()
    outline = config.table_outline()
    pockets = {p["id"]: p for p in outline["pockets"]}
    assert set(pockets) == {"bottom_left", "bottom_side", "bottom_right", "top_right", "top_side", "top_left"}
    inch = 0.0254
    assert 4.5 * inch <= pockets["top_right"]["mouth"] <= 4.625 * inch
    assert 5.0 * inch <= pockets["top_side"]["mouth"] <= 5.125 * inch
    assert {s["shape"] for s in outline["cushions"]} == {"line", "arc"}
    config.update({"table/length": 2.84, "table/width": 1.42, "table/pocket_layout": "none", "table/pockets": []})
    carom = config.table_outline()
    assert carom["pockets"] == []
    assert [s["id"] for s in carom["cushions"]] == ["rail.bottom", "rail.right", "rail.top", "rail.left"]
    assert carom["cushions"][0]["start"] == (-1.42, -0.71)
