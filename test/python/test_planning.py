"""plan_shot from Python: the straight-in layout of the node's plan test is planned into its corner, the plan's own
stroke replayed through predict_shot (which knows nothing of the planner) pots the ball, the estimate lies in its
interval, and bad requests raise Error naming the field."""
import math

import pytest

import billiard_shot_planner as bsp

CUE, BALLS = (0.2, 0.1), {"one": (0.8, 0.4)}
TOP_RIGHT = "top_right"


def test_a_straight_in_plan_pots_when_replayed():
    plan = bsp.plan_shot(CUE, BALLS, target="one", budget=3.0, seed=3)
    assert plan.found, plan.explanation
    best = plan.best
    assert best.target == "one" and best.pocket == TOP_RIGHT and best.cue_ball_path == "straight"
    low, high = best.confidence
    assert low <= best.success_probability <= high and best.rollouts > 0
    assert best.target_end_points.shape == (best.rollouts, 2)
    replay = bsp.predict_shot(best.stroke, cue_ball=CUE, balls=BALLS)
    assert replay.ball("one").outcome == "pocketed" and replay.ball("one").pocket == TOP_RIGHT
    assert plan.shot.ball("one").outcome == "pocketed"
    # The same seed and budget give the same plan.
    again = bsp.plan_shot(CUE, BALLS, target="one", budget=3.0, seed=3)
    assert again.best.stroke.phi == best.stroke.phi and again.best.success_probability == best.success_probability


def test_on_the_jaws_a_plan_aims_through_the_mouth_and_names_its_pocket():
    config = bsp.Configuration()
    config["table/pocket_model"] = "jaws"
    plan = bsp.plan_shot(CUE, BALLS, target="one", pocket=TOP_RIGHT, budget=3.0, configuration=config)
    assert plan.found, plan.explanation
    assert plan.best.pocket == TOP_RIGHT and plan.best.bank_cushion == ""
    replay = bsp.predict_shot(plan.best.stroke, cue_ball=CUE, balls=BALLS, configuration=config)
    assert replay.ball("one").outcome == "pocketed" and replay.ball("one").pocket == TOP_RIGHT
    # The margin is measured in the mouth: at most half its 4.5625 in less the cushion's reach, 30.4 mm.
    assert 0.0 < plan.best.margin <= 0.0305


def test_more_noise_pots_less_often():
    steady = bsp.plan_shot(CUE, BALLS, target="one", budget=3.0, seed=5)
    shaky = bsp.Noise()
    shaky.phi = 10 * shaky.phi
    noisy = bsp.plan_shot(CUE, BALLS, target="one", budget=3.0, seed=5, noise=shaky)
    assert noisy.best.success_probability < steady.best.success_probability


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"target": "nine"}, "target"),
        ({"budget": -1.0}, "budget"),
        ({"rollouts": 0}, "rollouts"),
        ({"cue_region": "here"}, "cue_region"),
        ({"pocket": "pocket17"}, "pocket"),
    ],
)
def test_a_bad_request_is_refused_by_name(kwargs, field):
    with pytest.raises(bsp.Error) as raised:
        bsp.plan_shot(CUE, BALLS, **kwargs)
    assert raised.value.field == field


def test_bad_noise_is_refused_by_name():
    noise = bsp.Noise()
    noise.phi = math.nan
    with pytest.raises(bsp.Error) as raised:
        bsp.plan_shot(CUE, BALLS, noise=noise)
    assert raised.value.field == "noise.phi"
