"""billiard_shot_planner: shots of billiards by the integrated multiple-impact model of Jia, Mason and Erdmann.

The ROS-free core from Python (docs/python.md)::

    import billiard_shot_planner as bsp
    shot = bsp.predict_shot(bsp.Stroke(phi=0.0, speed=2.0), cue_ball=(-0.6, 0.0), balls={"one": (0.3, 0.05)})
    shot.strike.velocity, shot.ball("one").outcome

Table frame: origin at the centre of the cloth, x along the length, z up; SI units; strokes in this package's
convention (from_pooltool / from_fastfiz convert the others'). Errors raise billiard_shot_planner.Error, a ValueError
with `code` and `field`. With ROS, the package also holds the node's messages (billiard_shot_planner.msg, .srv).
"""
# The package may lie in two places on the path: this source directory and catkin's devel space (with the compiled
# core and the generated messages). A process that finds this one first (a Dask worker spawned with its parent's
# path, which catkin's devel space extended with the sources) must still find the other's modules.
from pkgutil import extend_path

__path__ = extend_path(__path__, __name__)

from ._core import (  # noqa: E402
    PHASES,
    BallPath,
    Configuration,
    Cue,
    Error,
    Event,
    FitResult,
    FittedParameter,
    ImpactResult,
    Limits,
    Noise,
    Plan,
    PlannedShot,
    Shot,
    Strike,
    Stroke,
    TrackFit,
    fit_tracks,
    from_fastfiz,
    from_pooltool,
    multiple_impact,
    plan_shot,
    predict_shot,
    simulate_many,
    strike,
    strike_many,
    to_fastfiz,
    to_pooltool,
)

__all__ = [
    "PHASES",
    "BallPath",
    "Configuration",
    "Cue",
    "Error",
    "Event",
    "FitResult",
    "FittedParameter",
    "ImpactResult",
    "Limits",
    "Noise",
    "Plan",
    "PlannedShot",
    "Shot",
    "Strike",
    "Stroke",
    "TrackFit",
    "fit_tracks",
    "from_fastfiz",
    "from_pooltool",
    "multiple_impact",
    "plan_shot",
    "predict_shot",
    "simulate_many",
    "strike",
    "strike_many",
    "to_fastfiz",
    "to_pooltool",
]
