"""Type stubs of the handling package (SI units and radians throughout)."""

import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from ._reports import (
    Diagnosis as Diagnosis,
    Equilibria as Equilibria,
    EquilibriaSummary as EquilibriaSummary,
    Identification as Identification,
    MeasuredMetrics as MeasuredMetrics,
    RankedEffect as RankedEffect,
    Refused as Refused,
    Simulation as Simulation,
    StepMetrics as StepMetrics,
    StudyReport as StudyReport,
    StudySample as StudySample,
    Verdict as Verdict,
    VerdictKind as VerdictKind,
)

PathLike = Union[str, os.PathLike[str]]
ArrayLike = npt.ArrayLike

__version__: str

class HandlingError(Exception):
    """Any failure of the handling library; ``kind`` names the group
    (``input``, ``param``, ``options``, ``fit``, ``metrics``, ``diagnosis``,
    ``output``)."""
    kind: str

class InputError(HandlingError):
    """An input file that cannot be read or holds wrong content (``path``,
    ``line``, ``column``; ``key`` and ``value`` for a wrong value, for a
    CSV cell the column's name and the cell's text), or a
    wrong scenario or vehicle keyword (``key``, dotted, and ``value``;
    ``path`` and ``line`` None). ``problem`` names what is wrong with
    the content (``"NegativeLoad"``, ``"WrongSign"``, …) where the library
    types it, else None."""
    problem: Optional[str]
    path: Optional[str]
    line: Optional[int]
    column: Optional[int]
    reason: str
    key: Optional[str]
    value: Any

class ParamError(HandlingError):
    """A parameter value that is not physical."""
    key: str
    value: Optional[float]
    reason: str

class PointError(HandlingError):
    """A point ``Tyre.forces`` or ``Tyre.cornering_stiffness`` is given
    that ``tyre-eval`` refuses in a points file: the first one's
    ``argument``, ``index`` (in the flattened broadcast arrays), ``value``,
    ``reason`` and ``problem`` (None for a NaN or infinity); ``refused``:
    every one as (argument, index, value)."""
    argument: str
    index: int
    value: float
    reason: str
    problem: Optional[str]
    refused: List[Tuple[str, int, float]]

class OptionsError(HandlingError):
    """Options that name nothing known or contradict each other: for an
    unknown name ``what`` (the set), ``name`` and ``known``; ``path`` where
    a file is named."""
    what: str
    name: str
    known: List[str]
    path: Optional[str]

class FitError(HandlingError):
    """A fit that cannot be made or failed (``path`` of the data where
    known)."""
    path: Optional[str]

class MetricsError(HandlingError):
    """Step-steer metrics that cannot be computed from a response."""

class DiagnosisError(HandlingError):
    """A diagnosis that could not be made (``path`` of the input where
    known)."""
    path: Optional[str]

class OutputError(HandlingError):
    """An output that may not or could not be written (``path``)."""
    path: str

class Tyre:
    @classmethod
    def load(cls, path: PathLike) -> Tyre: ...
    @classmethod
    def from_json(cls, text: str) -> Tyre: ...
    def to_json(self) -> str: ...
    @property
    def model(self) -> str: ...
    @overload
    def cornering_stiffness(self, fz: float) -> float: ...
    @overload
    def cornering_stiffness(self, fz: npt.ArrayLike) -> Any: ...
    def forces(
        self,
        fz: ArrayLike,
        kappa: ArrayLike = ...,
        alpha: ArrayLike = ...,
        camber: ArrayLike = ...,
        speed: ArrayLike = ...,
        pressure: Optional[ArrayLike] = ...,
        mode: Optional[int] = ...,
    ) -> Dict[str, np.ndarray]: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Vehicle:
    def __init__(
        self,
        mass: float,
        yaw_inertia: float,
        a: float,
        b: float,
        track_front: float,
        track_rear: float,
        cg_height: float,
        *,
        wheelbase: Optional[float] = ...,
        load_transfer_front_share: Optional[float] = ...,
        steering_ratio: Optional[float] = ...,
    ) -> None: ...
    @classmethod
    def from_dict(cls, d: Mapping[str, float]) -> Vehicle: ...
    @classmethod
    def load(cls, path: PathLike) -> Vehicle: ...
    def to_dict(self) -> Dict[str, float]: ...
    @property
    def mass(self) -> float: ...
    @property
    def yaw_inertia(self) -> float: ...
    @property
    def a(self) -> float: ...
    @property
    def b(self) -> float: ...
    @property
    def track_front(self) -> float: ...
    @property
    def track_rear(self) -> float: ...
    @property
    def cg_height(self) -> float: ...
    @property
    def wheelbase(self) -> float: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

TyreLike = Union[Tyre, PathLike]
TyresArg = Union[TyreLike, Tuple[TyreLike, TyreLike], Mapping[str, TyreLike]]

class Scenario:
    def __init__(
        self,
        vehicle: Union[Vehicle, Mapping[str, float], None] = ...,
        tyres: Optional[TyresArg] = ...,
        manoeuvre: Optional[Mapping[str, Any]] = ...,
        *,
        road: Optional[Mapping[str, Any]] = ...,
        model: Optional[Mapping[str, Any]] = ...,
        simulation: Optional[Mapping[str, Any]] = ...,
        integrator: Optional[Mapping[str, Any]] = ...,
        metrics: Optional[Mapping[str, Any]] = ...,
        name: Optional[str] = ...,
        description: Optional[str] = ...,
    ) -> None: ...
    @classmethod
    def load(cls, path: PathLike) -> Scenario: ...
    def to_toml(self) -> str: ...
    def write(self, folder: PathLike) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def tyres(self) -> Tuple[Tyre, Tyre]: ...
    @property
    def vehicle(self) -> Vehicle: ...
    def keywords(self) -> Dict[str, Any]: ...
    def replace(self, **changes: Any) -> Scenario: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Study:
    @classmethod
    def load(cls, path: PathLike) -> Study: ...
    @property
    def path(self) -> str: ...
    @property
    def front(self) -> np.ndarray: ...
    @property
    def rear(self) -> np.ndarray: ...
    def grid(self) -> List[Tuple[float, float]]: ...
    @overload
    def evaluate(self, *, front_n_per_deg: ArrayLike, rear_n_per_deg: ArrayLike) -> List[StudySample]: ...
    @overload
    def evaluate(self, *, front_n_per_rad: ArrayLike, rear_n_per_rad: ArrayLike) -> List[StudySample]: ...

def simulate(
    scenario: Union[PathLike, Scenario, None] = ...,
    out: Optional[PathLike] = ...,
    pandas: Optional[bool] = ...,
    *,
    vehicle: Union[Vehicle, Mapping[str, float], None] = ...,
    tyres: Optional[TyresArg] = ...,
    manoeuvre: Optional[Mapping[str, Any]] = ...,
    road: Optional[Mapping[str, Any]] = ...,
    model: Optional[Mapping[str, Any]] = ...,
    simulation: Optional[Mapping[str, Any]] = ...,
    integrator: Optional[Mapping[str, Any]] = ...,
    metrics: Optional[Mapping[str, Any]] = ...,
    name: Optional[str] = ...,
    description: Optional[str] = ...,
) -> Simulation: ...
def metrics(
    run: Union[PathLike, Scenario, None] = ...,
    pre_window: Optional[float] = ...,
    steady_window: Optional[float] = ...,
    min_speed: Optional[float] = ...,
    filter_hz: Optional[float] = ...,
    variance_window: Optional[float] = ...,
    min_overshoot: Optional[float] = ...,
    *,
    degrees: Sequence[str] = ...,
    vehicle: Union[Vehicle, Mapping[str, float], None] = ...,
    tyres: Optional[TyresArg] = ...,
    manoeuvre: Optional[Mapping[str, Any]] = ...,
    road: Optional[Mapping[str, Any]] = ...,
    model: Optional[Mapping[str, Any]] = ...,
    simulation: Optional[Mapping[str, Any]] = ...,
    integrator: Optional[Mapping[str, Any]] = ...,
    name: Optional[str] = ...,
) -> Union[StepMetrics, MeasuredMetrics]: ...
def equilibria(sweep: PathLike, out: Optional[PathLike] = ...) -> Equilibria: ...
def study(study_file: PathLike, out: Optional[PathLike] = ...) -> StudyReport: ...
def run_shard(
    job: str, path: PathLike, index: int, count: int, out: Optional[PathLike] = ...
) -> Dict[str, Any]: ...
def merge(shards: Iterable[PathLike], out: Optional[PathLike] = ...) -> Dict[str, Any]: ...
def identify(
    data: PathLike,
    model: str,
    seed: Optional[int] = ...,
    out: Optional[PathLike] = ...,
    pressure: Optional[float] = ...,
    camber: Optional[float] = ...,
    local: Optional[str] = ...,
    bin_deg: float = ...,
    bin_kappa: Optional[float] = ...,
    start: Optional[str] = ...,
    template: Optional[PathLike] = ...,
    max_iterations: Optional[int] = ...,
    hold: Optional[Mapping[str, float]] = ...,
    load: Optional[float] = ...,
) -> Identification: ...
def diagnose(campaign: PathLike, out: Optional[PathLike] = ...) -> Diagnosis: ...
def synth(
    out: PathLike,
    effects: Union[str, Sequence[str]] = ...,
    seed: int = ...,
    truth: str = ...,
    programme: str = ...,
    drive: Union[PathLike, Sequence[PathLike]] = ...,
    duration: Optional[float] = ...,
) -> Dict[str, Any]: ...
def design(
    diagnosis: PathLike,
    campaign: Optional[PathLike] = ...,
    effects: Union[str, Sequence[str]] = ...,
    ay_share: float = ...,
    max_ax: float = ...,
    top: int = ...,
    measured: Union[PathLike, Sequence[PathLike]] = ...,
    out: Optional[PathLike] = ...,
) -> Dict[str, Any]: ...
