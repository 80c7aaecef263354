"""simulate_many: each row the answer of predict_shot for that stroke (exactly: the same pure function), whatever the
number of threads; a bad row reports its own error and leaves the others; a bad array raises Error."""
import math

import numpy as np
import pytest

import billiard_shot_planner as bsp

CUE, BALLS = (0.2, 0.1), {"one": (0.8, 0.4), "two": (-0.5, -0.3)}


def strokes(n=24, seed=7):
    rng = np.random.default_rng(seed)
    rows = np.column_stack(
        [
            rng.uniform(-math.pi, math.pi, n),  # phi
            rng.uniform(0.0, 0.3, n),  # theta
            rng.uniform(0.5, 4.0, n),  # speed
            rng.uniform(-0.3, 0.3, n),  # a
            rng.uniform(-0.3, 0.3, n),  # b
        ]
    )
    rows[0] = (math.atan2(0.3, 0.6), 0.0, 2.0, 0.0, 0.0)  # straight in: one pots
    return rows


@pytest.mark.parametrize("threads", [1, 2, 0])
def test_every_row_is_the_single_shot(threads):
    rows = strokes()
    batch = bsp.simulate_many(rows, cue_ball=CUE, balls=BALLS, threads=threads)
    assert batch["ids"] == ["cue", "one", "two"]
    assert batch["velocity"].shape == (len(rows), 3)
    assert batch["final_position"].shape == (len(rows), 3, 3)
    assert batch["pocket"].shape == (len(rows), 3)
    for i, row in enumerate(rows):
        shot = bsp.predict_shot(bsp.Stroke(*row), cue_ball=CUE, balls=BALLS)
        assert batch["error"][i] is None
        assert np.array_equal(batch["velocity"][i], shot.strike.velocity)
        for k, ball in enumerate(shot.balls):
            assert np.array_equal(batch["final_position"][i, k], ball.final_position)
            assert batch["pocket"][i, k] == ball.pocket
    assert batch["pocket"][0, 1] == "top_right"  # the straight-in row pots ball one in the (+x, +y) corner
    assert batch["pocket"][0, 0] == ""  # the cue ball stays on the table


def test_a_bad_row_reports_its_error_and_spares_the_others():
    rows = strokes(4)
    rows[2, 3] = 1.5  # a hit point off the ball
    batch = bsp.simulate_many(rows, cue_ball=CUE, balls=BALLS)
    error = batch["error"][2]
    assert isinstance(error, bsp.Error) and error.field == "a" and error.code == "invalid_argument"
    assert np.all(np.isnan(batch["velocity"][2])) and np.all(batch["pocket"][2] == "")
    assert all(batch["error"][i] is None for i in (0, 1, 3))


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"strokes": np.zeros((3, 4))}, "strokes"),
        ({"strokes": "fast"}, "strokes"),
        ({"strokes": np.zeros(5)}, "strokes"),
        ({"strokes": np.zeros((1, 5)), "threads": -1}, "threads"),
        ({"strokes": np.zeros((1, 5)), "cue_ball": (math.nan, 0.0)}, "cue_ball"),
    ],
)
def test_a_bad_batch_raises_naming_the_field(kwargs, field):
    arguments = {"cue_ball": CUE, **kwargs}
    with pytest.raises(bsp.Error) as raised:
        bsp.simulate_many(**arguments)
    assert raised.value.field == field


def test_an_empty_batch_is_empty():
    batch = bsp.simulate_many(np.zeros((0, 5)), cue_ball=CUE)
    assert batch["velocity"].shape == (0, 3) and batch["error"] == []


def test_every_strike_row_is_the_single_strike():
    # Ball "one" frozen to the cue ball along +x: strokes towards it move both in one impact.
    frozen = {"one": (CUE[0] + 2 * 0.0286, CUE[1]), "two": (-0.5, -0.3)}
    rows = strokes(16, seed=3)
    rows[1] = (0.0, 0.0, 2.0, 0.0, 0.0)  # straight into the frozen ball
    rows[2] = (0.0, 0.0, 2.0, 5.0, 0.0)  # off the ball: a row's own error
    batch = bsp.strike_many(rows, cue_ball=CUE, balls=frozen, threads=2)
    assert batch["ids"] == ["cue", "one", "two"]
    assert batch["other_velocity"].shape == (len(rows), 2, 3)
    for i, row in enumerate(rows):
        if i == 2:
            assert batch["error"][i].field == "a" and np.all(np.isnan(batch["velocity"][i]))
            continue
        single = bsp.strike(bsp.Stroke(*row), cue_ball=CUE, balls=frozen)
        assert batch["error"][i] is None
        assert np.array_equal(batch["velocity"][i], single.velocity)
        assert np.array_equal(batch["angular_velocity"][i], single.angular_velocity)
        assert batch["miscue"][i] == single.miscue
    # The frozen ball moves off along the line of centres, faster than the cue ball; the far one does not move.
    assert batch["other_velocity"][1, 0, 0] > batch["velocity"][1, 0] > 0.0
    assert np.all(np.delete(batch["other_velocity"][:, 1], 2, axis=0) == 0.0)
