"""The package's reports as typed, frozen objects.

Each job's report arrives from Rust as the JSON the command-line tool
writes; these classes give its main fields names, units and types (nested
tables the classes do not name stay dicts and lists). Every report keeps
the JSON form: ``to_dict()`` returns it (a copy), key for key as the
CLI's file. Reports compare by value and pickle, so they come back from
Dask or multiprocessing workers whole.

Units: SI and radians (N, m, s, m/s, rad, rad/s); the exceptions are named
on the field (``%``, ``s·deg``).
"""

from __future__ import annotations

import copy
import dataclasses
import enum
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple


def _json_field() -> Any:
    # The report's JSON form; excluded from repr (it repeats the fields),
    # part of equality (two reports are equal when their JSON is).
    return field(default=None, repr=False)


def _named(cls: Any, d: Dict[str, Any], **typed: Any) -> Any:
    """An instance of ``cls`` from the report dict ``d``: each field from
    its key (None where absent), ``typed`` overriding, ``d`` kept whole."""
    kw = {f.name: d.get(f.name) for f in dataclasses.fields(cls) if f.name != "_raw"}
    kw.update(typed)
    return cls(**kw, _raw=d)


class _Report:
    """The JSON form of a report."""

    _raw: Dict[str, Any]

    def to_dict(self) -> Dict[str, Any]:
        """The report as the CLI's JSON content (a copy)."""
        return copy.deepcopy(self._raw)


@dataclass(frozen=True)
class StepMetrics:
    """Step-steer metrics (GB/T 6323, ISO 7401): times in s on the
    record's clock, angles in rad, the exceptions named."""

    steer_step: float
    """Steer step δ_ss − δ₀, rad (front road-wheel angle)."""
    time_zero: float
    """Time zero (50 % of the steer input), s."""
    yaw_rate_response_time: float
    """Yaw-rate response time (time zero to 90 % of steady state), s."""
    yaw_rate_peak_time: Optional[float]
    """Yaw-rate peak response time, s; None without a peak above steady state."""
    yaw_rate_overshoot: Optional[float]
    """Yaw-rate overshoot, %; None without a peak (below what the run resolves)."""
    ay_response_time: Optional[float]
    """Lateral-acceleration response time, s (None without ``ay``, or
    below what the log resolves: then ``ay_response_time_below``)."""
    ay_response_time_below: Optional[float]
    """The bound the ay response time is below, s: one sample interval of a
    log whose steer steps within one interval and whose ``ay`` reaches
    90 % at the first sample after it (None where the time is read)."""
    yaw_rate_gain: float
    """Steady-state yaw-rate gain r/δ, 1/s."""
    yaw_rate_steady: float
    """Steady-state yaw-rate change, rad/s."""
    ay_steady: Optional[float]
    """Steady-state lateral-acceleration change, m/s² (None without ``ay``)."""
    beta_steady: Optional[float]
    """Steady-state sideslip change, rad (None without a β record)."""
    tb: Optional[float]
    """TB = peak response time × |steady sideslip|, s·deg (GB/T 6323's unit)."""
    yaw_rate_total_variance: float
    """Yaw-rate total variance E_r, s."""
    ay_total_variance: Optional[float]
    """Lateral-acceleration total variance E_ay, s (None without ``ay``)."""
    er: Optional[float]
    """Er = e1·E_r + e2·E_ay, s (None without ``ay``)."""
    settled: bool
    """Whether yaw rate and ay are steady in the steady window."""
    settling: Dict[str, Any]
    """The verdict on each channel's steady window (``yaw_rate``, ``ay``,
    ``beta``; None for a channel not recorded): ``{"verdict": "settled"}``,
    ``"not_settled"`` with its spread, ``"drifting"`` with where its
    trend heads (``heads``, share of the step), whether it slows
    (``converging``) and whether it heads above the window's mean on the
    step's scale (``rising``: False for a sliding car's falling ``ay``),
    ``"approaching"`` (settled, its trend still heading ``heads`` beyond
    the mean, ``rising`` as above), ``"oscillating"`` (a decaying swing
    still at the steady window: the ``amplitude`` left there and the
    ``centre`` from the window's mean, shares of the step; its ``period``
    and its ``last`` extremum's time, s), or ``"not_judged"`` where the
    channel's step is within a few noise deviations."""
    yaw_rate_noise: float
    """Noise of the normalised yaw rate in the initial window, share of the step."""
    ay_noise: Optional[float]
    """Noise of the normalised ``ay`` (after the filter), share of its step
    (None without ``ay``): it adds to E_ay and Er as the yaw rate's to E_r."""
    yaw_rate_peak_threshold: float
    """The overshoot a maximum needed to be a peak, % of the step."""
    yaw_rate_filter_ringing: float
    """What the low-pass alone lifts the steer step by, % of it: a yaw-rate
    maximum within it is the filter's ringing, not a peak (0 unfiltered)."""
    filter_hz: Optional[float]
    """The zero-phase low-pass applied, Hz (None: unfiltered)."""
    yaw_rate_peak_time_spread: Optional[float]
    """How far the run's own noise moves the peak time: its standard
    deviation over noisy copies of the record, s (None without a peak or
    without noise; an upper estimate)."""
    yaw_rate_peak_found_share: Optional[float]
    """The share of those noisy copies that find the peak (within one peak
    time of it)."""
    yaw_rate_peak_stray_share: Optional[float]
    """The share that find a maximum only farther from it (another maximum:
    the next one, a noise bump of the steady state), left out of the
    spread."""
    yaw_rate_overshoot_spread: Optional[float]
    """How far the run's own noise moves the overshoot: its standard
    deviation over the same copies, percentage points (an upper estimate)."""
    yaw_rate_overshoot_noise_bias: Optional[float]
    """How far the run's noise lifts the overshoot on average, percentage
    points: the overshoot less its extrapolation to no noise over copies
    with a quarter, a half and all of the run's noise variance added (SIMEX; None
    without a peak or without noise)."""
    yaw_rate_response_time_spread: Optional[float]
    """How far the run's own noise moves the yaw-rate response time: its
    standard deviation over the peak's noisy copies, the initial and steady
    means' noise in their 90 % level, s (None without noise, or where most
    copies do not cross)."""
    ay_response_time_spread: Optional[float]
    """The same for the ``ay`` response time, s."""
    yaw_rate_gain_spread: Optional[float]
    """How far the noise of the initial and steady means moves the yaw-rate
    gain: its relative standard deviation (share of the gain)."""
    yaw_rate_peak_unmeasured: bool
    """Whether the yaw-rate maximum lies on samples the log does not measure
    (masked and filled by the cleaning, a clipped flat top, a hole in
    time): peak time, overshoot and TB are then withheld (None), not below
    the threshold."""
    steer_logged_late: Optional[float]
    """How long before the steer leaves its initial band the yaw rate leaves
    its own, s: the steer was logged that much late, and the response times
    and total variances are read against a misaligned steer (None where the
    yaw rate moves after the steer, or the noise cannot tell)."""
    yaw_rate_window_moving: bool
    """Whether the yaw rate still moves in its steady window: its response
    time, peak time and overshoot are read against a moving window's mean."""
    ay_window_moving: bool
    """Whether ``ay`` still moves in its steady window: its response time is
    read against a moving window's mean."""
    beta_window_moving: bool
    """Whether the sideslip has not settled in its steady window: its
    steady value is a moving window's mean."""
    total_variance_window_cut: Optional[float]
    """The length of the total-variance window where the record ends before
    ``variance_window`` from the steer onset does, s: E_r, E_ay and Er
    integrate over this much (None where the whole window is in the
    record)."""

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "StepMetrics":
        """The metrics of a report dict (its other keys ignored)."""
        return cls(**{f.name: d[f.name] for f in dataclasses.fields(cls)})

    def to_dict(self) -> Dict[str, Any]:
        """The metrics as the CLI's JSON keys."""
        return dataclasses.asdict(self)


def _metrics(d: Optional[Dict[str, Any]]) -> Optional[StepMetrics]:
    return None if d is None else StepMetrics.from_dict(d)


@dataclass(frozen=True)
class Simulation(_Report):
    """A simulated scenario (``simulate``)."""

    scenario: str
    """The scenario's name."""
    integration: str
    """The integration in words (method, steps, work)."""
    tyres: Tuple[str, str]
    """The (front, rear) tyre models."""
    friction: float
    """The road's friction scale."""
    metrics: Optional[StepMetrics]
    """The step-steer metrics (step steers only)."""
    lift_offs: List[Dict[str, Any]]
    """Intervals with a wheel off the ground."""
    replay: Optional[Dict[str, Any]]
    """A replayed measurement's gap (replays only)."""
    history: Any = field(default=None, compare=False)
    """The time history: t (s), steer (rad), speed (m/s), beta (rad),
    yaw_rate (rad/s), ay (m/s²), alpha_front/alpha_rear (rad),
    fy_front/fy_rear (N), fz_fl … fz_rr (N), roll (rad, when integrated):
    a pandas DataFrame or a dict of numpy arrays."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any], history: Any = None) -> "Simulation":
        return _named(cls, d, tyres=tuple(d["tyres"]), metrics=_metrics(d.get("metrics")), history=history)

    def to_dict(self) -> Dict[str, Any]:
        """The report as the CLI's JSON content, with ``history``."""
        d = copy.deepcopy(self._raw)
        d["history"] = self.history
        return d


@dataclass(frozen=True)
class MeasuredMetrics(_Report):
    """Step-steer metrics of a measured run (``metrics`` of a CSV run)."""

    scenario: str
    """The run's name (its file stem)."""
    metrics: StepMetrics
    """The step-steer metrics."""
    piece: str
    """The part of the run measured, in words."""
    steer_rise_time: float
    """The steer's rise time, s."""
    warnings: List[str]
    """What the reader found doubtful."""
    cleaning: Dict[str, Any]
    """What cleaning the run found and excluded."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "MeasuredMetrics":
        return _named(cls, d, metrics=StepMetrics.from_dict(d))


@dataclass(frozen=True)
class StudySample:
    """One simulated (front, rear) cornering-stiffness pair of a study."""

    k_front: float
    """Front cornering stiffness per tyre, N/rad."""
    k_rear: float
    """Rear cornering stiffness per tyre, N/rad."""
    metrics: Optional[StepMetrics]
    """The step-steer metrics of a handling response; None where
    ``response`` is no handling response (``study.csv`` leaves that row's
    cells empty: a sliding car's numbers are not its handling)."""
    response: Optional[str] = None
    """``study.csv``'s ``response``: ``"handling"``, ``"sliding"``,
    ``"unstable"``, ``"large_sideslip"``, ``"not_settled"`` or
    ``"no_steady_state"``."""
    note: Optional[str] = None
    """``study.csv``'s ``note`` on the response: why its metrics are empty,
    or how far a response still settling has to go; None for a settled
    handling response."""

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "StudySample":
        return cls(
            d["k_front"], d["k_rear"], _metrics(d.get("metrics")), d.get("response"), d.get("note")
        )

    @property
    def k_front_n_per_deg(self) -> float:
        """Front cornering stiffness per tyre, N/deg (the study file's unit)."""
        return self.k_front / _DEG_PER_RAD

    @property
    def k_rear_n_per_deg(self) -> float:
        """Rear cornering stiffness per tyre, N/deg (the study file's unit)."""
        return self.k_rear / _DEG_PER_RAD

    def to_dict(self) -> Dict[str, Any]:
        """The sample as the CLI's JSON keys."""
        m = None if self.metrics is None else self.metrics.to_dict()
        return {
            "k_front": self.k_front,
            "k_rear": self.k_rear,
            "response": self.response,
            "note": self.note,
            "metrics": m,
        }


_DEG_PER_RAD = 180.0 / 3.141592653589793


@dataclass(frozen=True)
class StudyReport(_Report):
    """A cornering-stiffness study (``study``): summary.json, rbf.json and
    inverse.json's content as dicts, and every simulated pair."""

    summary: Dict[str, Any]
    """summary.json's content."""
    rbf: Optional[Dict[str, Any]]
    """rbf.json's content (None without an RBF)."""
    inverse: Optional[Dict[str, Any]]
    """inverse.json's content (None without inverse targets)."""
    samples: List[StudySample]
    """Every simulated combination."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "StudyReport":
        return _named(cls, d, samples=[StudySample.from_dict(s) for s in d.get("samples", [])])


@dataclass(frozen=True)
class EquilibriaSummary(_Report):
    """summary.json of ``equilibria``: speeds m/s, angles rad."""

    sweep: str
    """The sweep's name."""
    conditions: int
    """Conditions (points of the sweep) solved."""
    agreeing: int
    """Conditions where the swarm search and continuation agree."""
    agreement_percent: float
    """Their share, %."""
    misses: List[Dict[str, Any]]
    """Each condition where the two disagree or the swarm's index sum falls
    short of the winding number (Poincaré–Hopf), in the sweep's order:
    its ``condition`` (``steer`` rad, ``friction``, ``speed`` m/s), the
    equilibria only the exact solver found (``exact_only``) and only the
    swarm found (``pso_only``), each with ``beta`` (rad), ``yaw_rate``
    (rad/s) and ``kind``; the swarm's ``index_sum``, the
    ``winding_number`` (None where not taken) and the ``certificate``
    (``"holds"``, ``"falls_short"``, ``"not_asked"``, …). Empty where they
    agree."""
    max_residual: float
    """Largest equation residual of an equilibrium found."""
    seed: int
    """The swarm search's seed."""
    pso_evaluations: int
    """Model evaluations of the swarm search."""
    equilibria_in_box_histogram: Dict[str, int]
    """Conditions per number of equilibria in the search box."""
    conditions_with_continua: int
    """Conditions with a continuum of equilibria."""
    bifurcations: List[Dict[str, Any]]
    """The bifurcations found along the sweep."""
    critical_speed_closed_form: Optional[float]
    """The closed-form critical speed sqrt(-l/K) of the linear bicycle
    model, m/s, where neither axle's tyre has a friction limit and the car
    oversteers (K < 0); None otherwise."""
    box: Dict[str, float]
    """The search box: ``beta_max`` (rad) and ``yaw_rate_max`` (rad/s)."""
    pso: Dict[str, Any]
    """The swarm search's settings (seed, particles, iterations, fitness, …)."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "EquilibriaSummary":
        return _named(cls, d)


@dataclass(frozen=True)
class Equilibria(_Report):
    """The report of ``equilibria``."""

    summary: EquilibriaSummary
    """summary.json."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "Equilibria":
        return _named(cls, d, summary=EquilibriaSummary.from_dict(d["summary"]))


@dataclass(frozen=True)
class Identification(_Report):
    """A tyre fitted to rig data (``identify``), as ``<out>.report.json``."""

    tyre: Any
    """The fitted :class:`Tyre`."""
    data: str
    """The rig data read."""
    model: Optional[str]
    """The model fitted (swarm fits; None for the staged Magic Formula fit,
    whose model is the tyre's)."""
    rms: Optional[float]
    """RMS of the fit's residual, N (swarm fits)."""
    sigma_percent: Optional[float]
    """The fit's headline error σ, % of the measured peak: a swarm fit's
    ``sigma_percent``, the staged Magic Formula fit's pooled one
    (``sigma_pooled.sigma_percent``); None where the report has neither."""
    parameters: Optional[List[Dict[str, Any]]]
    """The fitted parameters with their standard errors (swarm fits)."""
    lifted: Optional[Dict[str, Any]]
    """The samples at a load near zero set aside (a lifted wheel: ``samples``,
    ``of``, ``below`` N, ``median_load`` N; swarm fits; None without any)."""
    _raw: Dict[str, Any] = _json_field()

    @classmethod
    def from_dict(cls, d: Dict[str, Any], tyre: Any = None) -> "Identification":
        sigma = d.get("sigma_percent")
        if sigma is None:
            sigma = (d.get("sigma_pooled") or {}).get("sigma_percent")
        return _named(cls, d, tyre=tyre, sigma_percent=sigma)


class VerdictKind(str, enum.Enum):
    """Which case a verdict is (``verdict.kind`` in diagnosis.json)."""

    EXPLAINED = "explained"
    """Effects of the library explain the gap (all of it, or part)."""
    NO_SIGNIFICANT_GAP = "no_significant_gap"
    """The base model's held-out error is within noise."""
    NOT_IDENTIFIABLE = "not_identifiable"
    """The base model is no tyre and no candidate makes it one."""
    OUTSIDE_LIBRARY = "outside_library"
    """A gap no candidate of the library is accepted for."""


@dataclass(frozen=True)
class Refused:
    """A candidate that is not the verdict, and every rule it fails."""

    effects: List[str]
    """Its effects."""
    reduction_percent: float
    """Share of the held-out gap above noise it removes, %."""
    why: List[Dict[str, Any]]
    """The rules it fails, each a dict whose ``kind`` names it:
    ``below_acceptance`` (``threshold_percent``), ``bic_not_lower``
    (``delta_bic``), ``axles_no_tyre`` (``no_tyre``: the reasons, each with
    its ``kind``, ``limit`` or ``early_peak``), ``leaves_parameter_idle``
    (``simpler``: the candidate taken in its place, refused) and
    ``search_ended_on`` (``set``: the set its search ended on, refused)."""

    @property
    def reasons(self) -> List[str]:
        """The kinds of the rules it fails, in order."""
        return [w["kind"] for w in self.why]

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "Refused":
        return cls(effects=d["effects"], reduction_percent=d["reduction_percent"], why=d["why"])


@dataclass(frozen=True)
class Verdict:
    """What a diagnosis concludes: its case (``kind``), the effects and
    their parameters where effects explain the gap, and the case's figures;
    ``statement`` and ``warnings`` are its words."""

    kind: VerdictKind
    """Which case it is."""
    effects: List[str]
    """Effects the evidence supports (empty unless ``kind`` is explained)."""
    parameters: List[Dict[str, Any]]
    """Their fitted parameters (``name``, ``value``, standard error, unit,
    whether on a bound and whether the runs determine it). ``std_error`` is
    the larger of ``asymptotic_std_error`` and the fold refits' spread
    (``fold_std_error``) where the model leaves a gap above noise;
    ``std_error_basis`` says which (``"asymptotic"`` or ``"fold_spread"``).
    A value per radian of body roll (``roll_steer.*``, ``roll_camber.*``)
    holds only at the campaign's roll gradient, and its
    ``per_lateral_acceleration`` gives what the runs determine: its product
    with that gradient (``quantity``: ``"steer"`` or ``"camber_thrust"``;
    ``value``, ``std_error``, ``unit``) and the gradient (``roll_gradient``:
    ``gradient`` in rad per m/s², ``file`` and ``line`` of ``[roll]
    gradient`` or null for the default, ``runs_logging_roll``); ``determined``
    is at that gradient only."""
    statement: str
    """The verdict in words."""
    warnings: List[str]
    """What the verdict's effects leave worse on held-out runs, and
    parameters on their search bound, in words."""
    heldout_error: float
    """Held-out combined error J of the base model."""
    noise_level: float
    """J of the noise alone."""
    heldout_error_after: Optional[float] = None
    """Held-out J with the effects (explained)."""
    reduction_percent: Optional[float] = None
    """Share of the held-out gap above noise removed, % (explained)."""
    partial: Optional[bool] = None
    """The effects explain only part of the gap, below 50 % (explained)."""
    extent: Optional[str] = None
    """How much of the gap the effects explain, as ``statement`` says it
    (explained): ``"all"`` (what they leave is noise), ``"most"`` (50 % or
    more, a gap above noise remaining: a ``gap_remains`` warning) or
    ``"part"`` (below 50 %)."""
    warning_details: List[Dict[str, Any]] = field(default_factory=list)
    """The warnings typed (``kind``: ``channel_worsened`` with ``channel``,
    ``before``, ``after``, ``noise_floor``, ``added_percent``, ``causes``;
    ``channel_left`` with ``channel``, ``before``, ``after``,
    ``noise_floor``, ``removed_percent``, ``acceptance_percent``,
    ``causes``; ``gap_remains`` with ``heldout_error_after``,
    ``noise_level``, ``threshold``, ``left_percent`` and ``carried_by``
    (``channel``, ``share_percent``, ``causes_named``, ``causes``,
    ``noise_floor``, or null where no one channel carries what is left)
    and ``runs_carrying`` (``carried_by``: the run, or two, holding more
    than two thirds of ``J² − J_n²``, each ``run``, ``share_percent``,
    ``heldout_error``, ``scale_apart`` (its road's yaw-rate scale apart,
    or null), empty where it is spread over the runs;
    ``above_noise``, ``runs``, ``largest``; or null); ``tyres_far_from_load`` with ``front``, ``rear``; or
    ``on_search_bound`` with ``parameters``). ``causes`` lists
    what the report holds elsewhere about the channel, each with ``kind``:
    ``beta_against`` (``file``, ``correlation``), ``run_carries``
    (``run``, ``share_percent``, ``rms``, ``scale_apart``) or ``steady_offset``."""
    threshold: Optional[float] = None
    """The multiple of the noise level a gap must exceed (no significant gap)."""
    no_tyre: List[Dict[str, Any]] = field(default_factory=list)
    """Why the base model is no tyre (not identifiable)."""
    evidence: List[Dict[str, Any]] = field(default_factory=list)
    """What the runs show beside the fit (explained; ``kind``:
    ``calibration`` with ``channel``, ``fitted``, ``measured``,
    ``measured_on`` and ``agrees``; or ``axles_restored`` with
    ``no_tyre``)."""
    closest: List[Dict[str, Any]] = field(default_factory=list)
    """The candidates whose jointly fitted axles are a tyre, best held-out
    first, each with ``effects`` and ``reduction_percent`` (not
    identifiable)."""
    refused: Optional[Refused] = None
    """The best single candidate and why it was refused (outside the library)."""
    threshold_percent: Optional[float] = None
    """The share of the gap a candidate must remove, % (not identifiable,
    outside the library)."""

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "Verdict":
        kw = {f.name: d[f.name] for f in dataclasses.fields(cls) if f.name in d}
        kw["kind"] = VerdictKind(d["kind"])
        if d.get("refused") is not None:
            kw["refused"] = Refused.from_dict(d["refused"])
        return cls(**kw)


@dataclass(frozen=True)
class RankedEffect:
    """One candidate effect (or combination) of a diagnosis' ranking."""

    effect: str
    """The effect names joined by ``+``."""
    effects: List[str]
    """The effects."""
    parameters: List[Dict[str, Any]]
    """Their fitted parameters."""
    heldout_error_before: float
    """Held-out combined error J of the base model."""
    heldout_error_after: float
    """Held-out combined error J with the effect."""
    reduction_percent: float
    """Share of the held-out gap above noise removed, %."""
    warning: Optional[str]
    """Cross-validation that disagrees with the fit (and fold refits that
    landed far from it), axles that are no tyre, refits that did not
    converge, in words (None without)."""
    warning_details: Optional[List[Dict[str, Any]]]
    """The same typed (``kind``: ``disagreement``, ``folds_far``,
    ``axles_no_tyre``, ``folds_not_converged``)."""

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "RankedEffect":
        return cls(**{f.name: d.get(f.name) for f in dataclasses.fields(cls)})


def _untimed(d: Dict[str, Any]) -> Dict[str, Any]:
    return {k: v for k, v in d.items() if k != "timing"}


@dataclass(frozen=True)
class Diagnosis(_Report):
    """The sim-to-real gap of a campaign (``diagnose``), as diagnosis.json;
    the tables not named here (``gap``, ``base``, ``cleaning``, ``road``,
    ``combinations``, ``confounded``, ``shrinkage``) are in ``to_dict()``."""

    campaign: str
    """The campaign's name."""
    seed: int
    """The seed of every random search."""
    derivatives: str
    """How the fits took their Jacobians: ``"differences"`` or ``"exact"``
    (``[diagnose] derivatives``)."""
    runs: List[str]
    """The runs diagnosed."""
    folds: int
    """Cross-validation folds."""
    notes: List[str]
    """Notes on the campaign and the fit, in words."""
    note_details: List[Dict[str, Any]]
    """The same typed (``kind``: ``campaign``, ``not_a_candidate``,
    ``bank_only_in_yaw_rate``, ``stiff_replay``)."""
    verdict: Verdict
    """The verdict."""
    ranking: List[RankedEffect]
    """Every candidate effect, best first."""
    timing: Dict[str, Any] = field(default=None, compare=False)
    """Where the time went: ``wall_seconds``, ``cpu_seconds``, ``threads``
    and the ``phases``; the clock's, so left out of equality."""
    _raw: Dict[str, Any] = _json_field()

    def __eq__(self, other: object) -> bool:
        # Two diagnoses are equal when their JSON is, but for the timing.
        if not isinstance(other, Diagnosis):
            return NotImplemented
        return _untimed(self._raw) == _untimed(other._raw)

    @classmethod
    def from_dict(cls, d: Dict[str, Any]) -> "Diagnosis":
        return _named(
            cls,
            d,
            verdict=Verdict.from_dict(d["verdict"]),
            ranking=[RankedEffect.from_dict(r) for r in d["ranking"]],
        )
