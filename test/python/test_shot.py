"""A whole shot from Python: a ghost-ball aim (computed here) pots the ball in the corner it points at; the paths'
arrays hold together (times in order, the sampled positions equal position_at); bad input raises Error naming the
field and never crashes the interpreter."""
import math

import numpy as np
import pytest

import billiard_shot_planner as bsp

CUE, ONE = (0.2, 0.1), (0.8, 0.4)
CUT_CUE = (0.3, 0.45)  # a cut of about 30 degrees into the same pocket
CORNER = (1.27, 0.635)  # the (+x, +y) corner pocket of the default 9-ft table, index 3


def ghost_ball_stroke(cue=CUE, speed=2.0):
    radius = bsp.Configuration()["ball_radius"]
    to_pocket = np.subtract(CORNER, ONE)
    to_pocket /= np.linalg.norm(to_pocket)
    ghost = np.asarray(ONE) - 2.0 * radius * to_pocket
    aim = ghost - np.asarray(cue)
    return bsp.Stroke(phi=math.atan2(aim[1], aim[0]), speed=speed)


@pytest.mark.parametrize("cue", [CUE, CUT_CUE])
def test_a_ghost_ball_aim_pots_the_ball_in_its_corner(cue):
    # The ball's throw off the cue ball (a degree or two for a cut) moves it by centimetres over the half metre to
    # the pocket, well within the pocket's 6 cm capture radius.
    shot = bsp.predict_shot(ghost_ball_stroke(cue), cue_ball=cue, balls={"one": ONE})
    assert [b.id for b in shot.balls] == ["cue", "one"]
    assert shot.first_contact == "one"
    one = shot.ball("one")
    assert one.outcome == "pocketed"
    assert one.pocket == "top_right"
    assert any(e.type == "pocketed" for e in one.events)


def test_on_the_jaws_model_the_straight_in_shot_drops_through_the_mouth():
    """The ghost-ball aim at the corner crosses the mouth about 2 cm off its middle (18 degrees off the pocket's axis,
    5.8 cm before the corner), within its half-width less a ball radius, 2.9 cm: under table/pocket_model "jaws" it
    drops in the top-right pocket."""
    config = bsp.Configuration()
    config["table/pocket_model"] = "jaws"
    shot = bsp.predict_shot(ghost_ball_stroke(), cue_ball=CUE, balls={"one": ONE}, configuration=config)
    assert "top_right" in [pocket["id"] for pocket in config.table_outline()["pockets"]]
    assert shot.ball("one").outcome == "pocketed" and shot.ball("one").pocket == "top_right"
    with pytest.raises(bsp.Error) as raised:
        config["table/pocket_model"] = "holes"
    assert raised.value.field == "table/pocket_model"


def test_the_sampled_path_holds_together():
    shot = bsp.predict_shot(ghost_ball_stroke(), cue_ball=CUE, balls={"one": ONE})
    cue = shot.ball("cue")
    times, positions, phases = cue.sample(0.01)
    assert times.shape == (len(times),) and positions.shape == (len(times), 3) and phases.shape == times.shape
    assert np.all(np.diff(times) >= 0.0)
    assert times[0] == 0.0 and times[-1] == pytest.approx(cue.duration)
    assert np.allclose(positions[0, :2], CUE, atol=1e-12)
    for k in range(0, len(times), max(1, len(times) // 10)):
        assert np.allclose(positions[k], cue.position_at(times[k]), atol=1e-12)
    assert set(phases) <= set(range(len(bsp.PHASES)))
    assert np.allclose(cue.final_position, positions[-1], atol=1e-9)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"cue_ball": (math.nan, 0.0)}, "cue_ball"),
        ({"cue_ball": (0.0, 0.0, 0.0)}, "cue_ball"),
        ({"cue_ball": "here"}, "cue_ball"),
        ({"cue_ball": CUE, "balls": [ONE]}, "balls"),
        ({"cue_ball": CUE, "balls": {"one": (math.inf, 0.0)}}, "balls['one']"),
        ({"cue_ball": CUE, "balls": {"one": (1.0,)}}, "balls['one']"),
    ],
)
def test_bad_input_is_refused_by_name(kwargs, field):
    with pytest.raises(bsp.Error) as raised:
        bsp.predict_shot(bsp.Stroke(speed=1.0), **kwargs)
    assert raised.value.code == "invalid_argument"
    assert raised.value.field == field


def test_a_ball_off_the_table_or_a_negative_speed_is_refused():
    with pytest.raises(bsp.Error) as raised:
        bsp.predict_shot(bsp.Stroke(speed=1.0), cue_ball=(5.0, 0.0))
    assert raised.value.code == "invalid_argument"
    assert raised.value.field == "cue_ball"
    with pytest.raises(bsp.Error):
        bsp.predict_shot(bsp.Stroke(speed=-1.0), cue_ball=CUE)
    with pytest.raises(bsp.Error):
        bsp.predict_shot(bsp.Stroke(speed=1.0), cue_ball=CUE).ball("nine")


def test_the_cores_errors_come_in_the_calls_names():
    # Ball "two" overlaps "one" by a centimetre: named by its id, not by its place in the core's list.
    with pytest.raises(bsp.Error) as raised:
        bsp.predict_shot(bsp.Stroke(speed=1.0), CUE, balls={"one": (0.5, 0.3), "two": (0.5 + 0.047, 0.3)})
    assert raised.value.field == "balls['two'].position"
    # A cue whose axis passes 5 cm beside the ball: the cue as a whole.
    beside = bsp.Cue(tip=(CUE[0] - 0.05, CUE[1] + 0.05 + 0.0286, 0.0286), direction=(1.0, 0.0, 0.0), speed=1.0)
    with pytest.raises(bsp.Error) as raised:
        bsp.predict_shot(beside, CUE)
    assert raised.value.code == "invalid_shot" and raised.value.field == "cue"
    # A configuration's field by its parameter name.
    config = bsp.Configuration()
    config["table/cushion_height"] = 0.05
    config["ball_radius"] = 0.03
    with pytest.raises(bsp.Error) as raised:
        config["ball_radius"] = 0.02  # the cushion's nose would be above the ball
    assert raised.value.field == "table/cushion_height"
