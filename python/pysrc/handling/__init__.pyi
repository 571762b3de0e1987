"""Type stubs of the handling package (SI units and radians throughout)."""

import os
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

PathLike = Union[str, os.PathLike[str]]
ArrayLike = npt.ArrayLike

__version__: str

class HandlingError(Exception):
    """Any failure of the handling library."""

class InputError(HandlingError):
    """An input file that cannot be read or holds wrong content."""
    path: str
    line: Optional[int]
    column: Optional[int]
    reason: str

class ParamError(HandlingError):
    """A parameter value that is not physical."""
    key: str
    value: Optional[float]
    reason: str

class Tyre:
    @classmethod
    def load(cls, path: PathLike) -> Tyre: ...
    @classmethod
    def from_json(cls, text: str) -> Tyre: ...
    def to_json(self) -> str: ...
    @property
    def model(self) -> str: ...
    def cornering_stiffness(self, fz: Any) -> Any: ...
    def forces(
        self,
        fz: ArrayLike,
        kappa: ArrayLike = ...,
        alpha: ArrayLike = ...,
        camber: ArrayLike = ...,
        speed: ArrayLike = ...,
        pressure: Optional[ArrayLike] = ...,
    ) -> Dict[str, np.ndarray]: ...
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
    def evaluate(self, k_front: ArrayLike, k_rear: ArrayLike) -> List[Dict[str, Any]]: ...

def simulate(
    scenario: PathLike, out: Optional[PathLike] = ..., pandas: Optional[bool] = ...
) -> Dict[str, Any]: ...
def metrics(
    run: PathLike,
    pre_window: float = ...,
    steady_window: float = ...,
    min_speed: float = ...,
    filter_hz: float = ...,
    variance_window: float = ...,
) -> Dict[str, Any]: ...
def equilibria(sweep: PathLike, out: Optional[PathLike] = ...) -> Dict[str, Any]: ...
def study(study_file: PathLike, out: Optional[PathLike] = ...) -> Dict[str, Any]: ...
def run_shard(
    job: str, path: PathLike, index: int, count: int, out: Optional[PathLike] = ...
) -> Dict[str, Any]: ...
def merge(shards: Iterable[PathLike], out: Optional[PathLike] = ...) -> Dict[str, Any]: ...
def identify(
    data: PathLike,
    model: str,
    seed: int = ...,
    out: Optional[PathLike] = ...,
    pressure: Optional[float] = ...,
    camber: Optional[float] = ...,
    local: str = ...,
    bin_deg: float = ...,
    bin_kappa: float = ...,
    start: str = ...,
    template: Optional[PathLike] = ...,
    max_iterations: Optional[int] = ...,
) -> Dict[str, Any]: ...
def diagnose(campaign: PathLike, out: Optional[PathLike] = ...) -> Dict[str, Any]: ...
def synth(
    out: PathLike, effects: Sequence[str] = ..., seed: int = ..., truth: str = ...
) -> Dict[str, Any]: ...
