"""fit_tracks: the node's calibration from Python. Tracks sampled from a shot predicted with known constants are fitted
from other starting values; the fit must find the constants that made them (the fit inverts the model: an invariant,
not a figure of the code's), and bad input raises Error naming the field."""
import math

import numpy as np
import pytest

import billiard_shot_planner as bsp

SHOTS = [((-0.6, 0.0), bsp.Stroke(phi=0.0, speed=1.5)), ((-0.5, -0.2), bsp.Stroke(phi=0.3, speed=2.0, b=-0.3))]


def tracks(configuration, cue_ball, stroke):
    """The cue ball's path every 1/60 s (a camera's frames) for its first second."""
    times, positions, _ = bsp.predict_shot(stroke, cue_ball, configuration=configuration).ball("cue").sample(1 / 60)
    keep = times <= 1.0
    return {"cue": np.column_stack([times[keep], positions[keep, 0], positions[keep, 1]])}


def observed(configuration):
    return [{"stroke": stroke, "cue_ball": cue_ball, "tracks": tracks(configuration, cue_ball, stroke)}
            for cue_ball, stroke in SHOTS]


def test_the_fit_finds_the_constants_that_made_the_tracks():
    truth = bsp.Configuration()
    truth.update({"motion/sliding_friction": 0.2, "motion/rolling_friction": 0.015})
    result = bsp.fit_tracks(observed(truth), ["motion/sliding_friction", "motion/rolling_friction"],
                            position_sigma=0.001)
    fit = result.fit
    # Noise-free tracks: the fit lands on the truth to far better than a camera's millimetre.
    assert fit.values["motion/sliding_friction"] == pytest.approx(0.2, rel=1e-3)
    assert fit.values["motion/rolling_friction"] == pytest.approx(0.015, rel=1e-3)
    assert all(p.identifiable for p in fit.parameters)
    assert max(result.shot_rms) < 1e-4
    assert "sliding_friction: 0.2" in fit.overlay_yaml("a test")


def test_bad_input_names_the_field():
    good = observed(bsp.Configuration())
    cases = [
        (dict(shots=good, parameters=["motion/sliding_fiction"]), "parameters[0]"),
        (dict(shots=[{**good[0], "tracks": {"cue": np.zeros((4, 2))}}], parameters=["motion/sliding_friction"]),
         "shots[0].tracks.cue"),
        (dict(shots=[{**good[0], "spin": 1}], parameters=["motion/sliding_friction"]), "shots[0].spin"),
        (dict(shots=[{"cue_ball": (0, 0), "tracks": {}}], parameters=["motion/sliding_friction"]), "shots[0].stroke"),
        (dict(shots=good, parameters=["motion/sliding_friction"], position_sigma=math.nan), "position_sigma"),
        (dict(shots=good, parameters=["motion/sliding_friction"], threads=0), "threads"),
        (dict(shots=good, parameters=["motion/sliding_friction"], starts=10001), "starts"),
        (dict(shots=good, parameters=["motion/sliding_friction"], max_seconds=0), "max_seconds"),
    ]
    for kwargs, field in cases:
        with pytest.raises(bsp.Error) as raised:
            bsp.fit_tracks(**kwargs)
        assert raised.value.field == field, kwargs
    overlapping = {**good[0], "balls": {"two": (good[0]["cue_ball"][0] + 0.03, good[0]["cue_ball"][1])}}
    with pytest.raises(bsp.Error) as raised:
        bsp.fit_tracks([overlapping], ["motion/sliding_friction"])
    assert raised.value.field == "shots[0].balls['two'].position"
    nan_track = good[0]["tracks"]["cue"].copy()
    nan_track[3, 1] = math.nan
    with pytest.raises(bsp.Error) as raised:
        bsp.fit_tracks([{**good[0], "tracks": {"cue": nan_track}}], ["motion/sliding_friction"])
    assert raised.value.field.startswith("shots[0].tracks")
