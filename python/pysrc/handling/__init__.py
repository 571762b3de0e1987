"""handling: a vehicle handling simulator (Rust, through PyO3).

A 2-DOF (sideslip β, yaw rate r) vehicle model with lateral load transfer
and pluggable nonlinear tyres (Gim, simplified Magic Formula, UniTire,
PAC89, linear, Magic Formula 5.2/6.1/6.2 from .tir files). Every function
calls one function of the Rust library with the GIL released and returns
the command-line tool's report as a typed, frozen object (:class:`Simulation`,
:class:`StepMetrics`, :class:`StudySample`, :class:`Equilibria`,
:class:`Identification`, :class:`Diagnosis`, ...) whose ``to_dict()`` is
the CLI's JSON content.

Units: SI and radians everywhere (N, N·m, m, s, m/s, rad, rad/s, Pa);
ISO 8855 axes (x forward, y left, z up; positive steer turns left).

Scenarios come from files or from keywords (:class:`Scenario`,
:class:`Vehicle`, and the keywords of :func:`simulate` and
:func:`metrics`), read by the same reader with the same checks.

Errors are :class:`HandlingError`, one subclass per kind of the library's
error (``kind`` names it): an unreadable or wrong input file is
:class:`InputError` (``path``, ``line``, ``column``; ``key``, ``value``
for a wrong value), a wrong keyword :class:`InputError` too (``key``,
``value``), a non-physical parameter :class:`ParamError` (``key``,
``value``, ``reason``), a point :meth:`Tyre.forces` or
:meth:`Tyre.cornering_stiffness` is given that ``tyre-eval`` refuses
(NaN, a slip angle beyond ±90° or in degrees, a negative speed, a pressure
not in Pa, loads in kN) :class:`PointError` (``argument``, ``index``,
``value``, ``reason``; ``refused``: every one), options that name nothing known or contradict
each other :class:`OptionsError` (``name``, ``known`` for an unknown
name), a fit that cannot be made :class:`FitError`, step-steer metrics that
cannot be computed :class:`MetricsError`, a diagnosis that cannot be made
:class:`DiagnosisError`, an output that cannot be written
:class:`OutputError` (each with ``path`` where the kind has one). The
attributes come from the error's typed fields, never from its message.
"""

from __future__ import annotations

import copy
import json
import os
import re
import tempfile
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _handling
from ._handling import (
    DiagnosisError,
    FitError,
    HandlingError,
    InputError,
    MetricsError,
    OptionsError,
    OutputError,
    ParamError,
    PointError,
)
from ._reports import (
    Diagnosis,
    Equilibria,
    EquilibriaSummary,
    Identification,
    MeasuredMetrics,
    RankedEffect,
    Refused,
    Simulation,
    StepMetrics,
    StudyReport,
    StudySample,
    Verdict,
    VerdictKind,
)
from ._toml import Document

__version__ = _handling.__version__

__all__ = [
    "HandlingError",
    "InputError",
    "ParamError",
    "PointError",
    "OptionsError",
    "FitError",
    "MetricsError",
    "DiagnosisError",
    "OutputError",
    "Tyre",
    "Vehicle",
    "Scenario",
    "Study",
    "Simulation",
    "StepMetrics",
    "MeasuredMetrics",
    "StudySample",
    "StudyReport",
    "Equilibria",
    "EquilibriaSummary",
    "Identification",
    "Diagnosis",
    "Verdict",
    "VerdictKind",
    "Refused",
    "RankedEffect",
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


def _paths(p: Union[PathLike, Iterable[PathLike]]) -> List[str]:
    """Paths given as one path or as a sequence of them: a string is one
    path, not a sequence of one-letter names."""
    if isinstance(p, (str, bytes, os.PathLike)):
        return [_path(p)]  # type: ignore[arg-type]
    return [_path(x) for x in p]


def _names(given: Union[str, Iterable[str]], what: str) -> List[str]:
    """Names given as a sequence, or as one string read as the command
    line's comma list (``"a,b"`` as ``--effects a,b``): a string is not a
    sequence of one-letter names."""
    if isinstance(given, str):
        names = [n.strip() for n in given.split(",")]
        if given.strip() and "" in names:
            raise ValueError(f"{what}: {given!r} has an empty name between its commas")
        return [n for n in names if n]
    names = list(given)
    for n in names:
        if not isinstance(n, str):
            raise TypeError(f"{what}: each name is a string, not {type(n).__name__} ({n!r})")
    return names


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
        vertical load ``fz`` (N): a float for a scalar, an array of the same
        shape for an array (evaluated in Rust in one call, the GIL
        released). A load ``tyre-eval`` refuses (NaN, beyond ±1 MN, all
        negative, in kN) raises :class:`PointError`."""
        if np.ndim(fz) == 0:
            return self._t.cornering_stiffness(float(fz))
        a = np.asarray(fz, dtype=np.float64)
        k = self._t.cornering_stiffness_1d(np.ascontiguousarray(a.ravel()))
        return k.reshape(a.shape)

    def forces(
        self,
        fz: Any,
        kappa: Any = 0.0,
        alpha: Any = 0.0,
        camber: Any = 0.0,
        speed: Any = 20.0,
        pressure: Any = None,
        mode: Optional[int] = None,
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
        - ``mode``: MFeval's ``useMode`` for a Magic Formula tyre, as
          ``tyre-eval --mode`` takes it: hundreds 1 = limit checks on, 2 =
          off; tens 1 = α* off, 2 = on; units 1 = no turn slip (turn slip is
          not modelled). None: the tyre's own (121 for a ``.tir`` file, as
          ``tyre-eval`` without ``--mode``). A code it refuses (any
          integer but its three-digit codes, a negative one included), or a
          mode for another model, raises :class:`OptionsError` in its
          words.

        Returns ``fx`` (N), ``fy`` (N), ``mz`` (N·m) and, for the Magic
        Formula, ``mx`` and ``my`` (N·m), each with the broadcast shape.

        The points are checked as ``tyre-eval`` checks a points file: a
        value it refuses raises :class:`PointError` naming the argument,
        the index in the flattened broadcast arrays and the value; slip
        ratios beyond ±1 are warned of (``UserWarning``), as it warns, and
        so are the points outside a ``.tir`` file's ranges (load, slip,
        camber, pressure), in its words: with the file's limit checks on
        they are evaluated at the range's end (a 40 kN load of a file
        whose ``FZMAX`` is 18 kN gives the forces at 18 kN); with
        ``mode=221`` (limit checks off) at the value given, and the warning
        says so.
        """
        args = [fz, kappa, alpha, camber, speed]
        if pressure is not None:
            args.append(pressure)
        arrays = np.broadcast_arrays(*[np.asarray(a, dtype=np.float64) for a in args])
        shape = arrays[0].shape
        flat = [np.ascontiguousarray(a.ravel()) for a in arrays]
        p = flat[5] if pressure is not None else np.empty(0, dtype=np.float64)
        fx, fy, mz, mx, my = self._t.forces_1d(*flat[:5], p, mode)
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


_VEHICLE_REQUIRED = ("mass", "yaw_inertia", "a", "b", "track_front", "track_rear", "cg_height")
_VEHICLE_OPTIONAL = ("wheelbase", "load_transfer_front_share", "steering_ratio")


def _keyword_error(e: InputError, doc: Document, what: str, strip: str = "") -> InputError:
    """The reader's error at a line of a keyword document, as the keyword
    (``key``, dotted) and the value given for it (``value``)."""
    key, value = doc.at(getattr(e, "line", None))
    # The reader's reason without its key and value (for a wrong value, the
    # parameter error's own reason), which the message below names.
    reason = getattr(e, "reason", None) or str(e)
    comma = _decimal_comma(value)
    if comma is not None:
        reason = f"{value!r} is a string with a decimal comma, not a number: write {comma} (a float, not a string)"
    if key is not None and strip and key.startswith(strip):
        key = key[len(strip):]
    if key is None:
        message = f"{what} keywords: {reason}"
    else:
        message = f"{what} keyword `{key}` = {value!r}: {reason}"
    err = InputError(message)
    err.kind = "input"
    err.key = key
    err.value = value
    err.path = None
    err.line = None
    err.column = None
    err.reason = reason
    err.problem = getattr(e, "problem", None)
    return err


def _decimal_comma(value: Any) -> Optional[str]:
    """``"1530,0"``'s number with a decimal point (``1530.0``); None where
    ``value`` is no string of a number written with a decimal comma."""
    if isinstance(value, str):
        m = re.fullmatch(r"\s*([+-]?\d+),(\d+)\s*", value)
        if m:
            return f"{m.group(1)}.{m.group(2)}"
    return None


class Vehicle:
    """Vehicle parameters: a scenario's ``[vehicle]`` table, read and
    checked by the library's scenario reader (a wrong value raises
    :class:`InputError` with ``key`` and ``value``).

    - ``mass``: m, kg
    - ``yaw_inertia``: yaw moment of inertia Iz, kg·m²
    - ``a``, ``b``: centre of gravity to the front / rear axle, m
    - ``track_front``, ``track_rear``: track widths, m
    - ``cg_height``: centre-of-gravity height, m
    - ``wheelbase``: m, optional; when given it must equal a + b to 1 mm
    - ``load_transfer_front_share``: front share χ of the lateral load
      transfer, in [0, 1] (default b / (a + b))
    - ``steering_ratio``: steering-wheel angle / road-wheel angle,
      optional (checked, unused by the 2-DOF model)

    Compares by value and pickles (as its parameters).
    """

    __slots__ = ("_p",)

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
        wheelbase: Optional[float] = None,
        load_transfer_front_share: Optional[float] = None,
        steering_ratio: Optional[float] = None,
    ) -> None:
        given = dict(
            mass=mass,
            yaw_inertia=yaw_inertia,
            a=a,
            b=b,
            track_front=track_front,
            track_rear=track_rear,
            cg_height=cg_height,
            wheelbase=wheelbase,
            load_transfer_front_share=load_transfer_front_share,
            steering_ratio=steering_ratio,
        )
        doc = Document()
        doc.table(["vehicle"], {k: v for k, v in given.items() if v is not None})
        try:
            text = _handling.vehicle_from_toml(doc.text(), "<Vehicle keywords>")
        except InputError as e:
            raise _keyword_error(e, doc, "Vehicle", strip="vehicle.") from None
        self._p: Dict[str, float] = json.loads(text)

    @classmethod
    def from_dict(cls, d: Mapping[str, float]) -> "Vehicle":
        """The vehicle of a ``[vehicle]`` table as a dict (:meth:`to_dict`)."""
        return cls(**d)

    @classmethod
    def load(cls, path: PathLike) -> "Vehicle":
        """The ``[vehicle]`` table of a TOML file (a scenario, sweep, study
        or campaign ``vehicle.toml``); errors name the file and line."""
        p = _path(path)
        try:
            with open(p, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            err = InputError(f"{p}: {e.strerror}")
            err.path, err.line, err.column, err.reason = p, None, None, str(e.strerror)
            err.key, err.value, err.kind, err.problem = None, None, "input", None
            raise err from None
        v = cls.__new__(cls)
        v._p = json.loads(_handling.vehicle_from_toml(text, p))
        return v

    def to_dict(self) -> Dict[str, float]:
        """The ``[vehicle]`` table (SI), optional keys only when given."""
        return dict(self._p)

    mass = property(lambda self: self._p["mass"], doc="Mass, kg.")
    yaw_inertia = property(lambda self: self._p["yaw_inertia"], doc="Yaw moment of inertia, kg·m².")
    a = property(lambda self: self._p["a"], doc="Centre of gravity to the front axle, m.")
    b = property(lambda self: self._p["b"], doc="Centre of gravity to the rear axle, m.")
    track_front = property(lambda self: self._p["track_front"], doc="Front track width, m.")
    track_rear = property(lambda self: self._p["track_rear"], doc="Rear track width, m.")
    cg_height = property(lambda self: self._p["cg_height"], doc="Centre-of-gravity height, m.")
    wheelbase = property(
        lambda self: self._p.get("wheelbase", self._p["a"] + self._p["b"]),
        doc="Wheelbase, m (a + b unless given).",
    )

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Vehicle) and self._p == other._p

    def __hash__(self) -> int:
        return hash(tuple(sorted(self._p.items())))

    def __repr__(self) -> str:
        return "Vehicle(" + ", ".join(f"{k}={v!r}" for k, v in self._p.items()) + ")"

    def __reduce__(self):  # type: ignore[override]
        return (Vehicle.from_dict, (self.to_dict(),))


# The tables of a scenario file, in the order they are written.
_TABLES = ("vehicle", "tyres", "road", "model", "manoeuvre", "simulation", "metrics")
_TYRE_FILES = {"front": "front_tyre.toml", "rear": "rear_tyre.toml"}


def _tyre(t: Any) -> Any:
    """A Tyre as is, a tyre file read (relative to the working directory);
    anything else is left for the reader to refuse."""
    if isinstance(t, Tyre):
        return t
    if isinstance(t, (str, os.PathLike)):
        return Tyre.load(t)
    return t


def _tyres(t: Any) -> Any:
    if isinstance(t, (Tyre, str, os.PathLike)):
        return {"front": _tyre(t)}
    if isinstance(t, (tuple, list)) and len(t) == 2:
        return {"front": _tyre(t[0]), "rear": _tyre(t[1])}
    if isinstance(t, Mapping):
        return {k: _tyre(v) if k in _TYRE_FILES else v for k, v in t.items()}
    return t


def _manoeuvre(m: Any) -> Any:
    if not isinstance(m, Mapping):
        return m
    m = dict(m)
    if isinstance(m.get("kind"), str):
        m["kind"] = m["kind"].replace("_", "-")
    if m.get("kind") == "replay" and isinstance(m.get("run"), (str, os.PathLike)):
        m["run"] = os.path.abspath(os.fspath(m["run"]))
    return m


class Scenario:
    """A simulation scenario from keywords: the tables of a scenario file
    (the book's docs/src/formats.md, "The project's own files") written as a TOML document and read by the
    library's scenario reader, so it is checked exactly as a file is; a
    wrong keyword raises :class:`InputError` with ``key`` (dotted, e.g.
    ``vehicle.mass``) and ``value`` (the value given).

    - ``vehicle``: a :class:`Vehicle` or a dict of its keys (SI)
    - ``tyres``: one :class:`Tyre` or tyre file for both axles, a
      ``(front, rear)`` pair, or ``{"front": ..., "rear": ...}``; files
      are read now (relative to the working directory), so the scenario
      holds its tyres and travels whole to other processes
    - ``manoeuvre``: a dict with ``kind`` ``step-steer`` (``speed`` m/s,
      ``steer`` rad or ``lateral_acceleration`` m/s², ``start``,
      ``rise_time``, ``end`` s), ``ramp-steer``, ``sine``, ``sweep`` or
      ``replay`` (``run``: a measured run, relative to the working
      directory); ``step_steer`` spelt with underscores is accepted
    - ``road``: ``{"friction": scale on the tyres' friction}``
    - ``model``: ``{"kinematics": "exact" | "small-angle",
      "load_transfer": bool, "effects": {...}}``
    - ``simulation`` (or its alias ``integrator``): ``{"method": "dopri5"
      | "rk4", "step": s, "rtol": ..., "atol": rad, "max_step": s}``
    - ``metrics``: the step-steer metric settings (``pre_window``,
      ``steady_window``, ``variance_window`` s, ``e1``, ``e2``,
      ``filter_hz`` Hz, ``min_overshoot`` %)
    - ``name`` (default ``scenario``), ``description``

    Compares by value and pickles (its keywords, tyres included).
    """

    __slots__ = ("_kw",)

    def __init__(
        self,
        vehicle: Union[Vehicle, Mapping[str, float], None] = None,
        tyres: Any = None,
        manoeuvre: Optional[Mapping[str, Any]] = None,
        *,
        road: Optional[Mapping[str, Any]] = None,
        model: Optional[Mapping[str, Any]] = None,
        simulation: Optional[Mapping[str, Any]] = None,
        integrator: Optional[Mapping[str, Any]] = None,
        metrics: Optional[Mapping[str, Any]] = None,
        name: Optional[str] = None,
        description: Optional[str] = None,
    ) -> None:
        if isinstance(vehicle, (str, bytes, os.PathLike)):
            raise TypeError(
                f"Scenario({os.fsdecode(vehicle)!r}): Scenario() takes a scenario's tables as keywords; "
                "to read a scenario file use Scenario.load(path)"
            )
        if simulation is not None and integrator is not None:
            raise TypeError("Scenario: give `simulation` or its alias `integrator`, not both")
        kw: Dict[str, Any] = {
            "name": name,
            "description": description,
            "vehicle": vehicle.to_dict() if isinstance(vehicle, Vehicle) else vehicle,
            "tyres": None if tyres is None else _tyres(tyres),
            "road": road,
            "model": model,
            "manoeuvre": _manoeuvre(manoeuvre),
            "simulation": integrator if simulation is None else simulation,
            "metrics": metrics,
        }
        self._kw = {k: copy.deepcopy(v) for k, v in kw.items() if v is not None}
        with tempfile.TemporaryDirectory(prefix="handling-") as d:
            self._run(d, _handling.check_scenario)

    @classmethod
    def load(cls, path: PathLike) -> "Scenario":
        """Reads a scenario file (TOML) as ``handling simulate`` does: the
        library's reader and checks, errors as :class:`InputError` with the
        file, line and column. Tyre files, and a replay's measured run, are
        read relative to the scenario file, as the CLI reads them; the
        scenario then holds its tyres and travels whole to other processes.
        ``write(folder)`` writes it back to a file the CLI runs to the same
        result."""
        p = _path(path)
        _handling.check_scenario(p)
        tables = json.loads(_handling.toml_file_json(p))
        folder = os.path.dirname(os.path.abspath(p))

        def beside(f: str) -> str:
            return os.path.join(folder, f)

        tyres = dict(tables.get("tyres", {}))
        for k in _TYRE_FILES:
            if isinstance(tyres.get(k), str):
                tyres[k] = Tyre.load(beside(tyres[k]))
        tables["tyres"] = tyres
        manoeuvre = tables.get("manoeuvre")
        if isinstance(manoeuvre, dict) and isinstance(manoeuvre.get("run"), str):
            manoeuvre["run"] = beside(manoeuvre["run"])
        # The file's name when it has none, as the CLI names its report.
        tables.setdefault("name", os.path.splitext(os.path.basename(p))[0])
        return cls(**tables)

    def _document(self) -> Document:
        doc = Document()
        for k in ("name", "description"):
            if k in self._kw:
                doc.entry(k, k, self._kw[k])
        for t in _TABLES:
            if t not in self._kw:
                continue
            v = self._kw[t]
            if t == "tyres" and isinstance(v, Mapping):
                v = {k: _TYRE_FILES[k] if isinstance(x, Tyre) else x for k, x in v.items()}
            if isinstance(v, Mapping):
                doc.table([t], v)
            else:
                doc.entry(t, t, v)
        # The reader's errors at a tyre line name the Tyre given.
        tyres = self._kw.get("tyres")
        if isinstance(tyres, Mapping):
            doc.keys = [
                (k, tyres[k.split(".", 1)[1]])
                if k and k.startswith("tyres.") and isinstance(tyres.get(k.split(".", 1)[1]), Tyre)
                else (k, v)
                for k, v in doc.keys
            ]
        return doc

    def to_toml(self) -> str:
        """The scenario file's text; a :class:`Tyre` appears as the tyre
        file :meth:`write` writes beside it."""
        return self._document().text()

    def write(self, folder: PathLike) -> str:
        """Writes ``scenario.toml`` and its tyre files into ``folder``
        (created if missing); returns the scenario file's path, which
        ``handling simulate`` runs to the same result."""
        os.makedirs(_path(folder), exist_ok=True)
        path, _ = self._write(_path(folder))
        return path

    def _write(self, folder: str) -> Tuple[str, Document]:
        tyres = self._kw.get("tyres")
        if isinstance(tyres, Mapping):
            for k, t in tyres.items():
                if isinstance(t, Tyre):
                    _, text = t._t.to_file_text()
                    with open(os.path.join(folder, _TYRE_FILES[k]), "w", encoding="utf-8") as f:
                        f.write(text)
        doc = self._document()
        path = os.path.join(folder, "scenario.toml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(doc.text())
        return path, doc

    def _run(self, folder: str, job: Any, *args: Any) -> Any:
        """``job(scenario file, *args)`` on the scenario written in
        ``folder``; the reader's errors in it as keyword errors."""
        path, doc = self._write(folder)
        try:
            return job(path, *args)
        except InputError as e:
            if getattr(e, "path", None) != path:
                raise
            raise _keyword_error(e, doc, "Scenario") from None

    @property
    def name(self) -> str:
        """The name used in reports and as the default output folder."""
        return self._kw.get("name", "scenario")

    @property
    def tyres(self) -> Tuple["Tyre", "Tyre"]:
        """The (front, rear) tyres."""
        t = self._kw["tyres"]
        return (t["front"], t.get("rear", t["front"]))

    @property
    def vehicle(self) -> Vehicle:
        """The vehicle."""
        return Vehicle.from_dict(self._kw["vehicle"])

    def keywords(self) -> Dict[str, Any]:
        """The keywords (a copy; tyres as a ``{"front", "rear"}`` dict of
        :class:`Tyre`), which ``Scenario(**keywords)`` takes back."""
        return copy.deepcopy(self._kw)

    def replace(self, **changes: Any) -> "Scenario":
        """A copy with the given keywords replaced (checked again)."""
        kw = self.keywords()
        kw.update(changes)
        return Scenario(**kw)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scenario) and self._kw == other._kw

    def __hash__(self) -> int:
        return hash(self.to_toml())

    def __repr__(self) -> str:
        return f"Scenario(name={self.name!r})"

    def __reduce__(self):  # type: ignore[override]
        return (_scenario_from_keywords, (self._kw,))


def _scenario_from_keywords(kw: Dict[str, Any]) -> Scenario:
    return Scenario(**kw)


def _scenario(scenario: Any, keywords: Dict[str, Any], what: str) -> Union[Scenario, str]:
    """A Scenario (given, or made from the keywords) or a scenario file."""
    given = {k: v for k, v in keywords.items() if v is not None}
    if isinstance(scenario, Scenario) or scenario is None:
        if given and scenario is not None:
            raise TypeError(f"{what}: give a Scenario or scenario keywords, not both ({', '.join(given)})")
        return scenario if scenario is not None else Scenario(**given)
    if given:
        raise TypeError(f"{what}: give a scenario file or scenario keywords, not both ({', '.join(given)})")
    return _path(scenario)


class Study:
    """A cornering-stiffness study (Wang & Liang) loaded from a study file:
    its vehicle, step steer, integrator and metric settings, to simulate
    (front, rear) stiffness pairs one by one — the unit of work of
    ``handling study`` and of a distributed stiffness map.

    Stiffness values are per tyre, in the unit their keywords name:
    ``evaluate(front_n_per_deg=..., rear_n_per_deg=...)`` (the study file's
    and the CLI's unit) or ``front_n_per_rad``/``rear_n_per_rad`` (SI, as
    :attr:`front`, :attr:`rear`, :meth:`grid` and the samples).

    Pickles as its absolute file path (reloaded where it is unpickled, so
    workers must see the same files, from any working directory).
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
        """The study file, absolute."""
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

    def evaluate(
        self,
        *args: Any,
        front_n_per_deg: Any = None,
        rear_n_per_deg: Any = None,
        front_n_per_rad: Any = None,
        rear_n_per_rad: Any = None,
    ) -> List[StudySample]:
        """Simulates the step steer with each axle's tyres scaled to the
        cornering stiffness pairs, per tyre, given in N/deg
        (``front_n_per_deg``, ``rear_n_per_deg``: the study file's and the
        CLI's unit) or in N/rad (``front_n_per_rad``, ``rear_n_per_rad``);
        arrays broadcast. Each value is checked as the study file's are
        (:class:`ParamError` naming the keyword, with its index among
        several, for a NaN, an infinity, a value at or below zero or one no
        tyre has against its axle's static load, such as N/rad given as
        N/deg), all before any is simulated. Returns one
        :class:`StudySample` per pair (``k_front``, ``k_rear`` in N/rad;
        ``response`` as ``study.csv``'s; ``metrics`` None where it is no
        handling response)."""
        if args:
            raise TypeError(
                "Study.evaluate: name the unit of the stiffness values, "
                "evaluate(front_n_per_deg=..., rear_n_per_deg=...) as in the study file, "
                "or evaluate(front_n_per_rad=..., rear_n_per_rad=...)"
            )
        per_deg = (front_n_per_deg, rear_n_per_deg)
        per_rad = (front_n_per_rad, rear_n_per_rad)
        given_deg = [v is not None for v in per_deg]
        given_rad = [v is not None for v in per_rad]
        # The values go to the library in their unit: it checks them as the
        # study file's (finite, positive, a tyre's against its static load),
        # naming the keyword, and converts them as the file's reader does.
        if all(given_deg) and not any(given_rad):
            f, r = (np.asarray(v, dtype=np.float64) for v in per_deg)
            unit = "N/deg"
        elif all(given_rad) and not any(given_deg):
            f, r = (np.asarray(v, dtype=np.float64) for v in per_rad)
            unit = "N/rad"
        else:
            raise TypeError(
                "Study.evaluate: give front_n_per_deg and rear_n_per_deg, "
                "or front_n_per_rad and rear_n_per_rad"
            )
        try:
            f, r = np.broadcast_arrays(f, r)
        except ValueError:
            # Two keywords that contradict each other: an OptionsError, as
            # the package's other contradicting options.
            names = ("front_n_per_deg", "rear_n_per_deg") if unit == "N/deg" else ("front_n_per_rad", "rear_n_per_rad")
            err = OptionsError(
                f"Study.evaluate: `{names[0]}` has shape {f.shape} and `{names[1]}` {r.shape}: "
                "give as many of each, or one value for either"
            )
            err.kind = "options"
            err.name = names[1]
            raise err from None
        text = self._s.evaluate_json(
            np.ascontiguousarray(f.ravel()), np.ascontiguousarray(r.ravel()), unit
        )
        return [StudySample.from_dict(d) for d in json.loads(text)]

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
    scenario: Union[PathLike, Scenario, None] = None,
    out: Optional[PathLike] = None,
    pandas: Optional[bool] = None,
    *,
    vehicle: Union[Vehicle, Mapping[str, float], None] = None,
    tyres: Any = None,
    manoeuvre: Optional[Mapping[str, Any]] = None,
    road: Optional[Mapping[str, Any]] = None,
    model: Optional[Mapping[str, Any]] = None,
    simulation: Optional[Mapping[str, Any]] = None,
    integrator: Optional[Mapping[str, Any]] = None,
    metrics: Optional[Mapping[str, Any]] = None,
    name: Optional[str] = None,
    description: Optional[str] = None,
) -> Simulation:
    """Simulates a scenario, as ``handling simulate``: a scenario file
    (TOML), a :class:`Scenario`, or the scenario's keywords (``vehicle``,
    ``tyres``, ``manoeuvre``, ``road``, ``model``, ``simulation`` or
    ``integrator``, ``metrics``, ``name``, ``description``: see
    :class:`Scenario`), which give the same result as the equivalent file.

    Returns a :class:`Simulation` (``scenario``, ``integration``,
    ``tyres``, ``friction``, ``metrics`` — a :class:`StepMetrics` for step
    steers, times in s, ``yaw_rate_gain`` in 1/s, overshoot in %, angles in
    rad — ``lift_offs``, ``replay``) with ``history``: the time history, columns
    ``t`` (s), ``steer`` (rad), ``speed`` (m/s), ``beta`` (rad),
    ``yaw_rate`` (rad/s), ``ay`` (m/s²), ``alpha_front``/``alpha_rear``
    (rad), ``fy_front``/``fy_rear`` (N), ``fz_fl`` … ``fz_rr`` (N) and
    ``roll`` (rad, when integrated): a pandas DataFrame when pandas is
    importable (``pandas=None``) or asked for (``True``), else a dict of
    numpy arrays. With ``out`` the CLI's outputs (history.csv,
    metrics.json, response.png) are written there.
    """
    sc = _scenario(
        scenario,
        dict(
            vehicle=vehicle,
            tyres=tyres,
            manoeuvre=manoeuvre,
            road=road,
            model=model,
            simulation=simulation,
            integrator=integrator,
            metrics=metrics,
            name=name,
            description=description,
        ),
        "simulate",
    )
    if isinstance(sc, Scenario):
        with tempfile.TemporaryDirectory(prefix="handling-") as d:
            text, columns = sc._run(d, _handling.simulate, _opt_path(out))
    else:
        text, columns = _handling.simulate(sc, _opt_path(out))
    return Simulation.from_dict(json.loads(text), _history(columns, pandas))


def metrics(
    run: Union[PathLike, Scenario, None] = None,
    pre_window: Optional[float] = None,
    steady_window: Optional[float] = None,
    min_speed: Optional[float] = None,
    filter_hz: Optional[float] = None,
    variance_window: Optional[float] = None,
    min_overshoot: Optional[float] = None,
    *,
    degrees: Sequence[str] = (),
    vehicle: Union[Vehicle, Mapping[str, float], None] = None,
    tyres: Any = None,
    manoeuvre: Optional[Mapping[str, Any]] = None,
    road: Optional[Mapping[str, Any]] = None,
    model: Optional[Mapping[str, Any]] = None,
    simulation: Optional[Mapping[str, Any]] = None,
    integrator: Optional[Mapping[str, Any]] = None,
    name: Optional[str] = None,
) -> Union[StepMetrics, MeasuredMetrics]:
    """Step-steer metrics.

    Of a measured run (CSV, FORMATS.md), as ``handling metrics --json``:
    windows in s (defaults 0.5, 1.0 and 4.0), ``min_speed`` in m/s
    (default 5), ``filter_hz`` the zero-phase low-pass cut-off in Hz
    (default 10; 0: unfiltered), ``min_overshoot`` the least yaw-rate
    overshoot that is a peak in % (default 1; 0: any maximum above the
    noise), ``degrees`` the run's columns in degrees (of ``steer``,
    ``yaw_rate`` in deg/s, ``beta``, ``roll``; ``handling metrics
    --degrees``; a logged ``roll`` levels ``ay`` as ``diagnose`` does); a
    :class:`MeasuredMetrics` (its
    ``metrics`` a :class:`StepMetrics`, with the run's cleaning report).
    A run without a step steer raises :class:`InputError` with its ``path``,
    as the CLI's error of that file (the file holds no step; a
    :class:`MetricsError` is a step whose metric cannot be computed).

    Of a simulated step steer, given a :class:`Scenario` or its keywords
    (``vehicle``, ``tyres``, ``manoeuvre``, ...: see :class:`Scenario`):
    the :class:`StepMetrics` of :func:`simulate`; the windows,
    ``filter_hz`` and ``min_overshoot`` given here go into the scenario's metric settings
    (``filter_hz`` 0: unfiltered, the default for simulations).
    """
    kw = dict(
        vehicle=vehicle,
        tyres=tyres,
        manoeuvre=manoeuvre,
        road=road,
        model=model,
        simulation=simulation,
        integrator=integrator,
        name=name,
    )
    if isinstance(run, Scenario) or (run is None and any(v is not None for v in kw.values())):
        if min_speed is not None:
            raise TypeError("metrics: `min_speed` applies to a measured run, not to a scenario")
        if degrees:
            raise TypeError("metrics: `degrees` applies to a measured run (a scenario's replay states it under [manoeuvre] degrees)")
        sc = _scenario(run, kw, "metrics")
        assert isinstance(sc, Scenario)
        windows = dict(
            pre_window=pre_window,
            steady_window=steady_window,
            variance_window=variance_window,
            min_overshoot=min_overshoot,
        )
        settings = dict(sc._kw.get("metrics", {}))
        settings.update({k: v for k, v in windows.items() if v is not None})
        if filter_hz is not None:
            settings.pop("filter_hz", None)
            if filter_hz != 0:
                settings["filter_hz"] = filter_hz
        if settings != sc._kw.get("metrics", {}):
            sc = sc.replace(metrics=settings)
        m = simulate(sc, pandas=False).metrics
        if m is None:
            err = OptionsError(
                f"metrics: scenario `{sc.name}`'s manoeuvre is {sc._kw['manoeuvre'].get('kind')!r}, not a step steer"
            )
            err.kind = "options"
            raise err
        return m
    if run is None:
        raise TypeError("metrics: give a measured run (CSV), a Scenario or the scenario keywords")
    if isinstance(degrees, str):
        degrees = [degrees]
    known = list(_handling.METRICS_ANGLES)
    for d in degrees:
        if d not in known:
            err = OptionsError(
                f"metrics: `{d}` is not an angle column metrics reads in degrees: one of {', '.join(known)}"
            )
            err.kind = "options"
            err.name = d
            err.known = known
            raise err
    return MeasuredMetrics.from_dict(json.loads(
        _handling.metrics(
            _path(run),
            0.5 if pre_window is None else pre_window,
            1.0 if steady_window is None else steady_window,
            5.0 if min_speed is None else min_speed,
            10.0 if filter_hz is None else filter_hz,
            4.0 if variance_window is None else variance_window,
            1.0 if min_overshoot is None else min_overshoot,
            list(degrees),
        )
    ))


def equilibria(sweep: PathLike, out: Optional[PathLike] = None) -> Equilibria:
    """Every steering equilibrium over a sweep file (Li, Jia & Zhao), as
    ``handling equilibria``: an :class:`Equilibria` whose ``summary`` is
    summary.json (:class:`EquilibriaSummary`: agreement, residuals,
    bifurcations; speeds m/s, angles rad). With ``out`` the CSV, JSON and
    PNG outputs are written there."""
    return Equilibria.from_dict(json.loads(_handling.equilibria(_path(sweep), _opt_path(out))))


def study(study_file: PathLike, out: Optional[PathLike] = None) -> StudyReport:
    """Cornering stiffness against handling (Wang & Liang), as
    ``handling study``: a :class:`StudyReport` with ``summary``, ``rbf``,
    ``inverse`` (summary.json, rbf.json, inverse.json) and ``samples``,
    every simulated combination (:class:`StudySample`: ``k_front``,
    ``k_rear`` in N/rad per tyre, ``metrics``). With ``out`` the outputs
    are written there."""
    return StudyReport.from_dict(json.loads(_handling.study(_path(study_file), _opt_path(out))))


def run_shard(
    job: str, path: PathLike, index: int, count: int, out: Optional[PathLike] = None
) -> Dict[str, Any]:
    """Shard ``index`` of ``count`` (1-based) of an ``equilibria`` sweep or
    a ``study``, as ``--shard K/N``: writes ``out/shard-K-of-N.json``. Any
    other ``job`` raises :class:`OptionsError` naming the known ones (and
    the nearest: "did you mean")."""
    return json.loads(_handling.run_shard(job, _path(path), index, count, _opt_path(out)))


def merge(shards: Iterable[PathLike], out: Optional[PathLike] = None) -> Dict[str, Any]:
    """Merges every shard file of one run, as ``handling merge``: writes
    the unsharded run's outputs (byte for byte) and returns its report.
    No shard file at all raises :class:`OptionsError`, as the CLI refuses
    ``handling merge`` without one."""
    return json.loads(_handling.merge([_path(s) for s in shards], _opt_path(out)))


def identify(
    data: PathLike,
    model: str,
    seed: Optional[int] = None,
    out: Optional[PathLike] = None,
    pressure: Optional[float] = None,
    camber: Optional[float] = None,
    local: Optional[str] = None,
    bin_deg: float = 0.25,
    bin_kappa: Optional[float] = None,
    start: Optional[str] = None,
    template: Optional[PathLike] = None,
    max_iterations: Optional[int] = None,
    hold: Optional[Mapping[str, float]] = None,
    load: Optional[float] = None,
) -> Identification:
    """Fits a tyre model to rig data (CSV), as ``handling identify``.

    ``model``: gim, magic-simple, unitire, pac89, linear, mf61, mf62;
    ``load`` in N, ``pressure`` in Pa and ``camber`` in rad select one
    level; ``bin_deg``
    is the slip-angle thinning bin in degrees. ``hold`` holds parameters
    at the values given, as ``--hold NAME=VALUE``: ``.tir`` coefficients
    for mf61/mf62 (``{"PKY4": 2.0}``), the tyre file's parameters for the
    other models (``{"a1": -22.1}`` for pac89); an unknown name is an
    :class:`OptionsError` with ``name``, ``what`` (``"pac89 parameter"``)
    and ``known``. A keyword the model's fit does not read is refused
    with an :class:`OptionsError`, as the command line refuses its flag:
    ``seed``, ``local``, ``bin_kappa``, ``load``, ``pressure``, ``camber``
    by mf61/mf62 (defaults when not given: 1, ``"lm"``, 0.0025, every
    level), ``start`` (default ``"data"``), ``template``,
    ``max_iterations`` by the swarm models. Returns an
    :class:`Identification` (``to_dict()``: ``<out>.report.json``) with
    ``tyre``: the fitted :class:`Tyre`. With
    ``out`` the tyre file, the report and the figure are written.
    """
    kw: Dict[str, Any] = {}
    if max_iterations is not None:
        kw["max_iterations"] = max_iterations
    if hold:
        kw["hold"] = [(str(k), float(v)) for k, v in hold.items()]
    if load is not None:
        kw["load"] = float(load)
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
    return Identification.from_dict(json.loads(text), Tyre(tyre))


def diagnose(campaign: PathLike, out: Optional[PathLike] = None) -> Diagnosis:
    """The sim-to-real gap of a campaign (TOML file or folder), as
    ``handling diagnose``: a :class:`Diagnosis` (``verdict``, ``ranking``;
    ``to_dict()``: diagnosis.json's content). With
    ``out`` diagnosis.json, gap_map.png, overlays.png (its data in
    overlays.csv) and report.html are written."""
    return Diagnosis.from_dict(json.loads(_handling.diagnose(_path(campaign), _opt_path(out))))


def synth(
    out: PathLike,
    effects: Union[str, Sequence[str]] = (),
    seed: int = 1,
    truth: str = "augmented",
    programme: str = "handling",
    drive: Union[PathLike, Sequence[PathLike]] = (),
    duration: Optional[float] = None,
) -> Dict[str, Any]:
    """The virtual proving ground, as ``handling synth``: writes a campaign
    folder ``out`` measured on a truth model (``augmented`` or
    ``four-wheel``) with the named effects on, driving ``programme``:
    ``handling`` (steps, a ramp and a sweep at constant speed, 100 Hz),
    ``oval`` (a 20 deg banked oval with braking, throttle and a standstill
    on the banking, 25 Hz, ``ax`` and ``bank`` channels) or ``road-course``
    (trail braking and cambered corners, 25 Hz). ``drive`` names scenario
    files (``design`` writes them) whose manoeuvres the truth drives as
    further runs. ``effects`` is a sequence of names or one string, read
    as the command line's comma list (``"sensor_delay"``,
    ``"road_bank,sensor_bias"``); ``drive`` one path or a sequence.
    ``duration`` (s) lengthens an analogue programme's runs, as
    ``--duration``: a whole number of seconds from the programme's own
    total to 3600 s (else :class:`OptionsError`)."""
    return json.loads(
        _handling.synth(
            _path(out), _names(effects, "synth: effects"), seed, truth, programme, _paths(drive), duration
        )
    )


def design(
    diagnosis: PathLike,
    campaign: Optional[PathLike] = None,
    effects: Union[str, Sequence[str]] = (),
    ay_share: float = 0.8,
    max_ax: float = 3.0,
    top: int = 3,
    measured: Union[PathLike, Sequence[PathLike]] = (),
    out: Optional[PathLike] = None,
) -> Dict[str, Any]:
    """The next test to drive, as ``handling design``: for the candidates a
    diagnosis (folder ``diagnosis``) confounds, or those named in
    ``effects`` (the reference first), the manoeuvres within the runs'
    limits that separate them best, with the separation in noise floors a
    driven run is expected to measure; runs ``measured`` driven afterwards
    are measured against it. Writes design.json, scenarios/*.toml and
    separation.png to ``out`` (default ``<diagnosis>/design``); returns
    design.json's content. ``effects`` is a sequence or one string read as
    the command line's ``--effects`` (``"a,b"``, ``a+b`` a combination);
    ``measured`` one path or a sequence."""
    return json.loads(
        _handling.design(
            _path(diagnosis),
            _opt_path(campaign),
            _names(effects, "design: effects"),
            ay_share,
            max_ax,
            top,
            _paths(measured),
            _opt_path(out),
        )
    )

