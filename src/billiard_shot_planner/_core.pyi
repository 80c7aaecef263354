# Type stubs of the compiled core (src/python/), for editors and type checkers.
from typing import Any, Mapping, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

PHASES: Tuple[str, str, str, str, str]

class Error(ValueError):
    """A call refused its input or could not finish."""

    code: str
    field: str

Field = float | bool | str | list[Tuple[float, float, float]]

class Configuration:
    """The shot's physics by the ROS node's parameter names (numbers, flags, choices, pockets); the node's defaults."""

    def __init__(self) -> None: ...
    @staticmethod
    def load(*paths: str) -> Configuration: ...
    def with_table_file(self, path: str) -> Configuration: ...
    def __getitem__(self, name: str) -> Field: ...
    def __setitem__(self, name: str, value: Field) -> None: ...
    def __contains__(self, name: str) -> bool: ...
    def update(self, fields: Mapping[str, Field]) -> None: ...
    def to_dict(self) -> dict[str, Field]: ...
    def names(self) -> list[str]: ...
    def choices(self) -> dict[str, list[str]]: ...
    def table_outline(self) -> dict[str, list[dict[str, Any]]]: ...
    def copy(self) -> Configuration: ...

class Stroke:
    """phi, theta in rad; speed in m/s; a (+ right) and b (+ up) in ball radii."""

    phi: float
    theta: float
    speed: float
    a: float
    b: float
    def __init__(
        self, phi: float = 0.0, theta: float = 0.0, speed: float = 1.0, a: float = 0.0, b: float = 0.0
    ) -> None: ...

class Cue:
    """The cue's pose at the ball (tip, direction of motion) and its speed, table frame."""

    tip: npt.NDArray[np.float64]
    direction: npt.NDArray[np.float64]
    speed: float
    def __init__(self, tip: Sequence[float], direction: Sequence[float], speed: float) -> None: ...

class Strike:
    velocity: npt.NDArray[np.float64]
    angular_velocity: npt.NDArray[np.float64]
    cue_velocity: float
    hit_normal: npt.NDArray[np.float64]
    cue_direction: npt.NDArray[np.float64]
    states: list[str]
    miscue: bool
    leaves_cloth: bool

class Event:
    type: str
    time: float
    position: npt.NDArray[np.float64]
    velocity: npt.NDArray[np.float64]
    angular_velocity: npt.NDArray[np.float64]
    cushion: str
    pocket: str
    ball: int

class BallPath:
    id: str
    outcome: str
    pocket: str
    final_position: npt.NDArray[np.float64]
    duration: float
    events: list[Event]
    def position_at(self, time: float) -> npt.NDArray[np.float64]: ...
    def sample(
        self, spacing: float = 0.01
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.int32]]: ...

class Shot:
    strike: Strike
    hit_point: npt.NDArray[np.float64]
    balls: list[BallPath]
    first_contact: str
    def ball(self, id: str) -> BallPath: ...

def strike(
    stroke: Stroke | Cue,
    cue_ball: Sequence[float] = (0.0, 0.0),
    balls: Optional[Mapping[str, Sequence[float]]] = None,
    configuration: Configuration = ...,
) -> Strike: ...
def predict_shot(
    stroke: Stroke | Cue,
    cue_ball: Sequence[float],
    balls: Optional[Mapping[str, Sequence[float]]] = None,
    configuration: Configuration = ...,
) -> Shot: ...
def from_pooltool(V0: float, phi: float, theta: float = 0.0, a: float = 0.0, b: float = 0.0) -> Stroke: ...
def to_pooltool(stroke: Stroke) -> Tuple[float, float, float, float, float]: ...
def from_fastfiz(a: float, b: float, theta: float, phi: float, v: float, ball_radius: float = 0.028575) -> Stroke: ...
def to_fastfiz(stroke: Stroke, ball_radius: float = 0.028575) -> Tuple[float, float, float, float, float]: ...
def simulate_many(
    strokes: npt.ArrayLike,
    cue_ball: Sequence[float],
    balls: Optional[Mapping[str, Sequence[float]]] = None,
    configuration: Configuration = ...,
    threads: int = 0,
) -> dict[str, Any]: ...
def strike_many(
    strokes: npt.ArrayLike,
    cue_ball: Sequence[float],
    balls: Optional[Mapping[str, Sequence[float]]] = None,
    configuration: Configuration = ...,
    threads: int = 0,
) -> dict[str, Any]: ...

class Noise:
    """Execution noise: one standard deviation per stroke parameter (rad, rad, m/s, m, m)."""

    phi: float
    theta: float
    speed: float
    a: float
    b: float
    def __init__(self) -> None: ...

class Limits:
    """What the robot can do (rad, m/s, ball radii, m)."""

    min_theta: float
    max_theta: float
    min_speed: float
    max_speed: float
    max_offset: float
    cue_length: float
    cue_radius: float
    rail_height: float
    def __init__(self) -> None: ...

class PlannedShot:
    stroke: Stroke
    cue: Cue
    target: str
    pocket: str
    bank_cushion: str
    cue_ball_path: str
    margin: float
    success_probability: float
    confidence: Tuple[float, float]
    rollouts: int
    target_end_points: npt.NDArray[np.float64]

class Plan:
    found: bool
    best: PlannedShot
    explanation: str
    shot: Shot
    alternatives: list[PlannedShot]
    evaluations: int
    seconds: float

def plan_shot(
    cue_ball: Sequence[float],
    balls: Mapping[str, Sequence[float]],
    target: str = "",
    pocket: str = "",
    budget: float = 0.5,
    seed: int = 1,
    rollouts: int = 200,
    threads: int = 0,
    noise: Noise = ...,
    limits: Limits = ...,
    target_first: bool = False,
    only_target: bool = False,
    cue_region: Optional[Tuple[Sequence[float], float]] = None,
    configuration: Configuration = ...,
) -> Plan: ...

class FittedParameter:
    name: str
    value: float
    sigma: float
    identifiable: bool
    at_bound: bool

class FitResult:
    parameters: list[FittedParameter]
    correlation: npt.NDArray[np.float64]
    residuals: npt.NDArray[np.float64]
    initial_cost: float
    final_cost: float
    degrees_of_freedom: int
    chi2_per_dof: float
    explains_data: bool
    converged: bool
    message: str
    iterations: int
    values: dict[str, float]
    def overlay_yaml(self, origin: str = "fitted from Python") -> str: ...

class TrackFit:
    fit: FitResult
    shot_rms: list[float]

def fit_tracks(
    shots: Sequence[Mapping[str, Any]],
    parameters: Sequence[str],
    configuration: Configuration = ...,
    position_sigma: float = 0.005,
    starts: int = 1,
    max_seconds: float = 60.0,
    threads: int = 1,
    robust_loss_sigmas: float = 0.0,
) -> TrackFit: ...

class ImpactResult:
    velocity: npt.NDArray[np.float64]
    normal_impulses: npt.NDArray[np.float64]
    tangential_impulses: npt.NDArray[np.float64]
    ends_of_compression: list[int]
    initially_slipping: list[bool]
    states: list[list[str]]
    events: list[Tuple[str, str, float]]
    initial_kinetic_energy: float
    final_kinetic_energy: float
    converged: bool

def multiple_impact(
    mass_matrix: npt.ArrayLike,
    velocity: npt.ArrayLike,
    contacts: Sequence[Mapping[str, Any]],
    relative_tolerance: float = 1e-12,
    absolute_tolerance: float = 1e-14,
    max_seconds: float = 10.0,
) -> ImpactResult: ...
