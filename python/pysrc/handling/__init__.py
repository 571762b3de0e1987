"""handling: a vehicle handling simulator (Rust, through PyO3).

A 2-DOF (sideslip β, yaw rate r) vehicle model with lateral load transfer
and pluggable nonlinear tyres (Gim, simplified Magic Formula, UniTire,
PAC89, linear, Magic Formula 5.2/6.1/6.2 from .tir files). Every function
calls one function of the Rust library with the GIL released and returns
the same report as the command-line tool's JSON, as a dict.

Units: SI and radians everywhere (N, N·m, m, s, m/s, rad, rad/s, Pa);
ISO 8855 axes (x forward, y left, z up; positive steer turns left).

Errors are :class:`HandlingError`; an unreadable or wrong input file is
:class:`InputError` (``path``, ``line``, ``column``), a non-physical
parameter :class:`ParamError` (``key``, ``value``, ``reason``).
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, List, Optional, Sequence, Union

import numpy as np

from . import _handling
from ._handling import HandlingError, InputError, ParamError

__version__ = _handling.__version__

__all__ = [
    "HandlingError",
    "InputError",
    "ParamError",
    "Tyre",
    "Study",
    "simulate",
    "metrics",
    "equilibria",
    "study",
    "run_shard",
    "merge",
    "identify",
    "diagnose",
    "synth",
]

PathLike = Union[str, "os.PathLike[str]"]

_MOMENTS = ("mx", "my")


def _path(p: PathLike) -> str:
    return os.fspath(p)


def _opt_path(p: Optional[PathLike]) -> Optional[str]:
    return None if p is None else os.fspath(p)


class Tyre:
    """A tyre of any model, loaded from a tyre file.

    Pickles (through its JSON form), so it travels to Dask or
    multiprocessing workers.
    """

    __slots__ = ("_t",)

    def __init__(self, _inner: "_handling.Tyre") -> None:
        self._t = _inner

    @classmethod
    def load(cls, path: PathLike) -> "Tyre":
        """Loads and validates a tyre file: ``.toml`` (any model) or ``.tir``
        (Magic Formula 5.2/6.1/6.2)."""
        return cls(_handling.Tyre.load(_path(path)))

    @classmethod
    def from_json(cls, text: str) -> "Tyre":
        """The tyre from :meth:`to_json`'s text (validated)."""
        return cls(_handling.Tyre.from_json(text))

    def to_json(self) -> str:
        """The tyre as JSON (the tyre file's content, ``model`` tag
        included); exact: it round-trips every parameter bit for bit."""
        return self._t.to_json()

    @property
    def model(self) -> str:
        """The model name: ``gim``, ``magic-simple``, ``unitire``,
        ``pac89``, ``linear`` or ``magic-formula``."""
        return self._t.model

    def cornering_stiffness(self, fz: Any) -> Any:
        """Cornering stiffness ∂Fy/∂α at α = 0 and no camber, N/rad, at the
        vertical load ``fz`` (N); a float for a float, an array for an
        array."""
        if np.ndim(fz) == 0:
            return self._t.cornering_stiffness(float(fz))
        a = np.asarray(fz, dtype=np.float64)
        return np.array(
            [self._t.cornering_stiffness(float(x)) for x in a.ravel()], dtype=np.float64
        ).reshape(a.shape)

    def forces(
        self,
        fz: Any,
        kappa: Any = 0.0,
        alpha: Any = 0.0,
        camber: Any = 0.0,
        speed: Any = 20.0,
        pressure: Any = None,
    ) -> Dict[str, np.ndarray]:
        """Forces and moments at the contact patch, vectorised.

        Arguments broadcast against each other (numpy rules); the batch is
        evaluated in Rust in one call, the GIL released.

        - ``fz``: vertical load, N (≤ 0: off the ground)
        - ``kappa``: longitudinal slip ratio, dimensionless
        - ``alpha``: slip angle, rad (positive gives positive ``fy``)
        - ``camber``: inclination angle, rad
        - ``speed``: forward speed of the wheel centre, m/s
        - ``pressure``: inflation pressure, Pa (Magic Formula only; None:
          the file's)

        Returns ``fx`` (N), ``fy`` (N), ``mz`` (N·m) and, for the Magic
        Formula, ``mx`` and ``my`` (N·m), each with the broadcast shape.
        """
        args = [fz, kappa, alpha, camber, speed]
        if pressure is not None:
            args.append(pressure)
        arrays = np.broadcast_arrays(*[np.asarray(a, dtype=np.float64) for a in args])
        shape = arrays[0].shape
        flat = [np.ascontiguousarray(a.ravel()) for a in arrays]
        p = flat[5] if pressure is not None else np.empty(0, dtype=np.float64)
        fx, fy, mz, mx, my = self._t.forces_1d(*flat[:5], p)
        out = {"fx": fx.reshape(shape), "fy": fy.reshape(shape), "mz": mz.reshape(shape)}
        for name, v in zip(_MOMENTS, (mx, my)):
            if v is not None:
                out[name] = v.reshape(shape)
        return out

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Tyre) and self._t == other._t

    def __hash__(self) -> int:
        return hash(self.to_json())

    def __repr__(self) -> str:
        return f"Tyre(model={self.model!r})"

    def __reduce__(self):  # type: ignore[override]
        return (Tyre.from_json, (self.to_json(),))


class Study:
    """A cornering-stiffness study (Wang & Liang) loaded from a study file:
    its vehicle, step steer, integrator and metric settings, to simulate
    (front, rear) stiffness pairs one by one — the unit of work of
    ``handling study`` and of a distributed stiffness map.

    Pickles as its file path (reloaded where it is unpickled, so workers
    must see the same files).
    """

    __slots__ = ("_s",)

    def __init__(self, _inner: "_handling.Study") -> None:
        self._s = _inner

    @classmethod
    def load(cls, path: PathLike) -> "Study":
        """Loads and validates a study file (TOML)."""
        return cls(_handling.Study.load(_path(path)))

    @property
    def path(self) -> str:
        """The study file."""
        return os.fspath(self._s.path)

    @property
    def front(self) -> np.ndarray:
        """The map's front stiffness values per tyre, N/rad."""
        return self._s.front

    @property
    def rear(self) -> np.ndarray:
        """The map's rear stiffness values per tyre, N/rad."""
        return self._s.rear

    def grid(self) -> List[tuple]:
        """The map's (front, rear) pairs, N/rad per tyre, in the study's
        order (front outer, rear inner)."""
        return [(float(f), float(r)) for f in self.front for r in self.rear]

    def evaluate(self, k_front: Any, k_rear: Any) -> List[Dict[str, Any]]:
        """Simulates the step steer with each axle's tyres scaled to the
        cornering stiffness pairs (N/rad per tyre; arrays broadcast).
        Returns one sample per pair: ``k_front``, ``k_rear`` and
        ``metrics`` (the step-steer metrics, None without a steady state)."""
        f, r = np.broadcast_arrays(
            np.asarray(k_front, dtype=np.float64), np.asarray(k_rear, dtype=np.float64)
        )
        text = self._s.evaluate_json(
            np.ascontiguousarray(f.ravel()), np.ascontiguousarray(r.ravel())
        )
        return json.loads(text)

    def __repr__(self) -> str:
        return f"Study({self.path!r})"

    def __reduce__(self):  # type: ignore[override]
        return (Study.load, (self.path,))


def _history(columns: Dict[str, np.ndarray], pandas: Optional[bool]) -> Any:
    if pandas is False:
        return columns
    try:
        import pandas as pd  # type: ignore[import-not-found]
    except ImportError:
        if pandas:
            raise
        return columns
    return pd.DataFrame(columns)


def simulate(
    scenario: PathLike, out: Optional[PathLike] = None, pandas: Optional[bool] = None
) -> Dict[str, Any]:
    """Simulates a scenario file (TOML), as ``handling simulate``.

    Returns the report (``scenario``, ``integration``, ``tyres``,
    ``friction``, ``metrics`` — the step-steer metrics for step steers,
    times in s, ``yaw_rate_gain`` in 1/s, overshoot in %, angles in rad —
    ``lift_offs``, ``replay``) and ``history``: the time history, columns
    ``t`` (s), ``steer`` (rad), ``speed`` (m/s), ``beta`` (rad),
    ``yaw_rate`` (rad/s), ``ay`` (m/s²), ``alpha_front``/``alpha_rear``
    (rad), ``fy_front``/``fy_rear`` (N), ``fz_fl`` … ``fz_rr`` (N) and
    ``roll`` (rad, when integrated): a pandas DataFrame when pandas is
    importable (``pandas=None``) or asked for (``True``), else a dict of
    numpy arrays. With ``out`` the CLI's outputs (history.csv,
    metrics.json, response.png) are written there.
    """
    text, columns = _handling.simulate(_path(scenario), _opt_path(out))
    report = json.loads(text)
    report["history"] = _history(columns, pandas)
    return report


def metrics(
    run: PathLike,
    pre_window: float = 0.5,
    steady_window: float = 1.0,
    min_speed: float = 5.0,
    filter_hz: float = 10.0,
    variance_window: float = 4.0,
) -> Dict[str, Any]:
    """Step-steer metrics of a measured run (CSV, FORMATS.md), as
    ``handling metrics --json``: windows in s, ``min_speed`` in m/s,
    ``filter_hz`` the zero-phase low-pass cut-off in Hz (0: unfiltered)."""
    return json.loads(
        _handling.metrics(
            _path(run), pre_window, steady_window, min_speed, filter_hz, variance_window
        )
    )


def equilibria(sweep: PathLike, out: Optional[PathLike] = None) -> Dict[str, Any]:
    """Every steering equilibrium over a sweep file (Li, Jia & Zhao), as
    ``handling equilibria``: the report's ``summary`` is summary.json
    (agreement, residuals, bifurcations; speeds m/s, angles rad). With
    ``out`` the CSV, JSON and PNG outputs are written there."""
    return json.loads(_handling.equilibria(_path(sweep), _opt_path(out)))


def study(study_file: PathLike, out: Optional[PathLike] = None) -> Dict[str, Any]:
    """Cornering stiffness against handling (Wang & Liang), as
    ``handling study``: ``summary``, ``rbf``, ``inverse`` (summary.json,
    rbf.json, inverse.json) and ``samples``, every simulated combination
    (``k_front``, ``k_rear`` in N/rad per tyre, ``metrics``). With ``out``
    the outputs are written there."""
    return json.loads(_handling.study(_path(study_file), _opt_path(out)))


def run_shard(
    job: str, path: PathLike, index: int, count: int, out: Optional[PathLike] = None
) -> Dict[str, Any]:
    """Shard ``index`` of ``count`` (1-based) of an ``equilibria`` sweep or
    a ``study``, as ``--shard K/N``: writes ``out/shard-K-of-N.json``."""
    return json.loads(_handling.run_shard(job, _path(path), index, count, _opt_path(out)))


def merge(shards: Iterable[PathLike], out: Optional[PathLike] = None) -> Dict[str, Any]:
    """Merges every shard file of one run, as ``handling merge``: writes
    the unsharded run's outputs (byte for byte) and returns its report."""
    return json.loads(_handling.merge([_path(s) for s in shards], _opt_path(out)))


def identify(
    data: PathLike,
    model: str,
    seed: int = 1,
    out: Optional[PathLike] = None,
    pressure: Optional[float] = None,
    camber: Optional[float] = None,
    local: str = "lm",
    bin_deg: float = 0.25,
    bin_kappa: float = 0.0025,
    start: str = "data",
    template: Optional[PathLike] = None,
    max_iterations: Optional[int] = None,
) -> Dict[str, Any]:
    """Fits a tyre model to rig data (CSV), as ``handling identify``.

    ``model``: gim, magic-simple, unitire, pac89, linear, mf61, mf62;
    ``pressure`` in Pa and ``camber`` in rad select one level; ``bin_deg``
    is the slip-angle thinning bin in degrees. Returns the report (as
    ``<out>.report.json``) with ``tyre``: the fitted :class:`Tyre`. With
    ``out`` the tyre file, the report and the figure are written.
    """
    kw: Dict[str, Any] = {}
    if max_iterations is not None:
        kw["max_iterations"] = max_iterations
    text, tyre = _handling.identify(
        _path(data),
        model,
        seed,
        _opt_path(out),
        pressure,
        camber,
        local,
        bin_deg,
        bin_kappa,
        start,
        _opt_path(template),
        **kw,
    )
    report = json.loads(text)
    report["tyre"] = Tyre(tyre)
    return report


def diagnose(campaign: PathLike, out: Optional[PathLike] = None) -> Dict[str, Any]:
    """The sim-to-real gap of a campaign (TOML file or folder), as
    ``handling diagnose``: the report is diagnosis.json's content. With
    ``out`` diagnosis.json, gap_map.png and overlays.png are written."""
    return json.loads(_handling.diagnose(_path(campaign), _opt_path(out)))


def synth(
    out: PathLike, effects: Sequence[str] = (), seed: int = 1, truth: str = "augmented"
) -> Dict[str, Any]:
    """The virtual proving ground, as ``handling synth``: writes a campaign
    folder ``out`` measured on a truth model (``augmented`` or
    ``four-wheel``) with the named effects on."""
    return json.loads(_handling.synth(_path(out), list(effects), seed, truth))
