//! Why a parameter value is wrong: the kinds of [`ParamReason`], each with
//! the values that describe it, and the physical limits of a range check
//! ([`Limit`]). The messages are built from the kinds; a caller matches the
//! kind. Units as the key's (SI unless the key names another).

use super::options::{ModeError, OptionsError};
pub(crate) use angles::{angle, compared, compared_like};
use boxed::cornering_per_load;
pub use boxed::{BeyondSignal, PerLoad};
pub use campaign::{min_speed_checked, CampaignReason, MAX_MIN_SPEED};
use checks::{cg_too_low, mass_digit, pressure_no_line, tir_per_load};
pub use checks::{CgTooLow, MassDigit, NoPressureLine, TirPerLoad, Wheelbase, DYNAMIC_INDEX};
use no_grip::no_lateral_force;
pub use no_grip::NoLateralForce;
use rollover::beyond_rollover;
pub use rollover::Rollover;
pub use schedule::ScheduleColumn;
pub use slow_steer::{SlowSteer, Waveform};
use thiserror::Error;
use tir::{declared_unit, load_off_nominal, pure_curve, tyre_pressure, unloaded_radius};
pub use tir::{CurveFault, DeclaredHow, DeclaredUnit, LoadOffNominal, PureCurve};

mod angles;
mod boxed;
pub(super) mod campaign;
mod checks;
mod limit;
mod no_grip;
mod rollover;
mod schedule;
mod slow_steer;
mod staged;
mod tir;
pub use limit::Limit;

/// Why a parameter value is wrong.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ParamReason {
    /// Not a finite number.
    #[error("must be a finite number")]
    NotFinite,
    /// A step steer without a step, rad.
    #[error("a step steer needs a steer step of at least {} from straight running", angle(*min))]
    NoSteerStep {
        /// The smallest step the metrics take as one, rad.
        min: f64,
    },
    /// A ramp, sine or sweep whose steer stays below the smallest step the
    /// metrics take as one: straight running, nothing to respond to. Rad.
    #[error("the road wheels steer at most {}, less than the {} a manoeuvre must steer: the car would run straight, with no response to show", compared(*reached, *min).0, compared(*reached, *min).1)]
    NoSteer {
        /// The largest steer the manoeuvre reaches, rad.
        reached: f64,
        /// The smallest step the metrics take as one, rad.
        min: f64,
    },
    /// A sine or sweep so slow against its run that its steer stays below
    /// the smallest step the metrics take as one ([`SlowSteer`]).
    #[error("{0}")]
    SlowSteer(Box<SlowSteer>),
    /// A steer frequency the recorded rows cannot resolve: rows every
    /// `step` s sample at no more than twice the frequency (Nyquist; at
    /// exactly twice they can fall on the zero crossings), so the written
    /// history aliases the steer. Hz, s.
    #[error("the rows every {step} s ([simulation] step) sample at {} Hz, not more than twice this frequency: the written steer and response would alias (a fast steer drawn as a slow one, or as zeros where the rows fall on its zero crossings); set step below {} s, e.g. {} s, or {} s to draw the waveform", crate::format::rounded(1.0 / *step, 3), crate::format::rounded_down(0.5 / *frequency, 3), crate::format::rounded_down(0.4 / *frequency, 2), crate::format::rounded_down(0.1 / *frequency, 2))]
    Aliased {
        /// The recorded rows' interval, s.
        step: f64,
        /// The highest steer frequency, Hz.
        frequency: f64,
    },
    /// A run whose history would pass the rows a history holds.
    #[error("{0}")]
    TooManyRows(Box<super::TooManyRows>),
    /// A `[vehicle]` key outside its physical range.
    #[error("{0}")]
    VehicleRange(super::VehicleLimit),
    /// Metric windows that do not fit in a step steer's record (0 to its
    /// `end`), s: the initial window at its start, the steady at its end.
    #[error("the initial and steady windows together (`pre_window` = {} s + `steady_window` = {} s) do not fit in the record, 0 to `end` = {} s: shorten the window or lengthen the manoeuvre's `end`", super::number::Num(*pre_window), super::number::Num(*steady_window), super::number::Num(*end))]
    WindowsBeyondRecord {
        /// The initial-value window, s.
        pre_window: f64,
        /// The steady-value window, s.
        steady_window: f64,
        /// The record's end, s.
        end: f64,
    },
    /// A steady window reaching back over the step's ramp: its means would
    /// mix the step in. `settles`: where the steer reaches its step
    /// (`start + rise_time`), `end` the record's end, s.
    #[error("the steady window (the last `steady_window` s before `end` = {} s) starts before the steer settles at its step at {} s (`start` + `rise_time`): the steady values would mix the step in; a `steady_window` of at most {} s starts after it", super::number::Num(*end), super::number::Num(*settles), super::hundredths_down(end - settles + 1e-11))]
    StepInSteadyWindow {
        /// Where the steer reaches its step, s.
        settles: f64,
        /// The record's end, s.
        end: f64,
    },
    /// A step steer starting inside the metrics' initial window (0 to
    /// `pre_window`), which measures the straight running before it, s.
    #[error("the step starts inside the metrics' initial window (0 to `pre_window` = {} s), which measures the straight running before the step: the initial values would be the step's own; start the step at {} s or later, or shorten `[metrics] pre_window`", super::number::Num(*pre_window), super::number::Num(*pre_window))]
    StepInInitialWindow {
        /// The initial-value window, s.
        pre_window: f64,
    },
    /// Zero or negative where only positive values are physical.
    #[error("must be positive")]
    NotPositive,
    /// Negative where only non-negative values are physical.
    #[error("must not be negative")]
    Negative,
    /// The upper end of a `[low, high]` range at or below its lower end.
    #[error("must lie above the range's lower end, {lo}")]
    RangeReversed {
        /// The lower end.
        lo: f64,
    },
    /// A magnitude at or below `min`, for the reason `why`: the sign is
    /// free (a side's, or a convention's), the size is not.
    #[error("must be larger than {} in magnitude (either sign): {why}", super::number::Num(*.min))]
    MagnitudeAtMost {
        /// The largest magnitude refused.
        min: f64,
        /// Why.
        why: Limit,
    },
    /// A PAC89 cornering stiffness `|a3·sin(2·atan(Fz/a4))|` (N/deg)
    /// above any tyre's at the load `fz` (kN) from 0.1 to 100 kN: the
    /// combination is refused, `a3` alone has no upper end.
    #[error("with a4 = {} kN, BCD = a3·sin(2·atan(Fz/a4)) reaches {} N/deg at Fz = {} kN, above any tyre's 34907 N/deg (2e6 N/rad; a car tyre's is 1000–3000 N/deg): the lateral force would be a step at zero slip, not a curve; check a3 and a4 (a3 is the peak stiffness, reached at Fz = a4)", super::number::Num(*a4), crate::format::readable(*peak, 4), crate::format::rounded(*fz, 4))]
    Pac89PeakStiffness {
        /// `a4`, kN.
        a4: f64,
        /// The largest stiffness over the loads, N/deg.
        peak: f64,
        /// The load it is reached at, kN.
        fz: f64,
    },
    /// A tyre's cornering stiffness per unit of its own load below any
    /// tyre's ([`crate::tyre::sizes::MIN_CORNERING_PER_LOAD`]): in N/deg,
    /// the value given said converted. Boxed: the error stays small.
    #[error("{}", cornering_per_load(.0))]
    CorneringPerLoad(Box<PerLoad>),
    /// A `.tir` pressure with no `[UNITS] PRESSURE` line, no tyre's.
    #[error("{}", pressure_no_line(.0))]
    TirPressureNoLine(Box<NoPressureLine>),
    /// A `.tir` cornering stiffness per unit load beyond any tyre's.
    #[error("{}", tir_per_load(.0))]
    TirCorneringPerLoad(Box<TirPerLoad>),
    /// A vehicle's mass a digit off (mass per footprint and dynamic index).
    #[error("{}", mass_digit(.0))]
    MassDigit(Box<MassDigit>),
    /// A centre of gravity below any vehicle's for its track.
    #[error("{}", cg_too_low(.0))]
    CgTooLow(Box<CgTooLow>),
    /// A tyre that makes no lateral force at the car's wheel load.
    #[error("{}", no_lateral_force(.0))]
    NoLateralForce(Box<NoLateralForce>),
    /// A `.tir` value outside any tyre's `(lo, hi]` once converted by the
    /// unit its file's `[UNITS]` declares, but within as written: the
    /// declaration is the slip. Boxed: the error stays small.
    #[error("{}", declared_unit(.0))]
    TirDeclaredUnit(Box<DeclaredUnit>),
    /// A `.tir` file's own pure-slip force curve beyond any tyre's: a peak
    /// friction above [`crate::tyre::sizes::MAX_FRICTION`], or a force
    /// that turns against its slip. Boxed: the error stays small.
    #[error("{}", pure_curve(.0))]
    MfPureCurve(Box<PureCurve>),
    /// A `.tir` file's load key (`FZMIN`, `FZMAX`) a unit's factor off
    /// its `FNOMIN`. Boxed: the error stays small.
    #[error("{}", load_off_nominal(.0))]
    TirLoadOffNominal(Box<LoadOffNominal>),
    /// Outside the range `(lo, hi]`, for the reason `why`.
    #[error("must {}: {why}", super::number::range(*.lo, *.hi))]
    OutOfRange {
        /// The exclusive lower end.
        lo: f64,
        /// The inclusive upper end.
        hi: f64,
        /// Why the range is what it is.
        why: Limit,
    },
    /// A mass above any wheeled vehicle's (a unit slip), kg.
    #[error("above {max:e} kg, more than any wheeled vehicle: check the unit (kg)")]
    MassTooLarge {
        /// The largest mass accepted, kg.
        max: f64,
    },
    /// A length above any vehicle's (a unit slip), m.
    #[error("above {max} m: check the unit (m)")]
    LengthTooLarge {
        /// The largest length accepted, m.
        max: f64,
    },
    /// A track out of proportion with the wheelbase (a unit slip, or a
    /// key given another's value): outside 0.15–2.
    #[error("track / wheelbase = {}, outside 0.15–2 (road and racing vehicles about 0.3–1.2), with the wheelbase a + b = {} + {} = {} m: check the unit (m), that the key holds the track, and a and b (the wheelbase may be the one wrong)", crate::format::readable(*ratio, 3), super::number::Num(*a), super::number::Num(*b), crate::format::readable(a + b, 4))]
    TrackToWheelbase {
        /// Track over wheelbase.
        ratio: f64,
        /// The front axle's distance from the centre of gravity, m.
        a: f64,
        /// The rear axle's, m.
        b: f64,
    },
    /// A dynamic index `Iz/(m·a·b)` outside what a rigid vehicle can have ([`DYNAMIC_INDEX`]).
    #[error("with mass = {} kg it gives a radius of gyration √(yaw_inertia/mass) of {} m, against √(a·b) = {} m from the axles: yaw_inertia / (mass·a·b) = {}, outside {}–{} (road cars about 0.8–1.2, Milliken & Milliken); at an index of 1 the yaw inertia would be mass·a·b = {} kg·m²: check the value for a slipped digit and the units of mass and yaw_inertia (kg, kg·m²)", super::number::Num(*mass), crate::format::readable((index * ab).sqrt(), 3), crate::format::readable(ab.sqrt(), 3), crate::format::rounded(*index, 3), DYNAMIC_INDEX.0, DYNAMIC_INDEX.1, crate::format::readable(mass * ab, 4))]
    DynamicIndex {
        /// The index of the values given.
        index: f64,
        /// The mass it was computed with, kg.
        mass: f64,
        /// a·b, m².
        ab: f64,
    },
    /// A mass too small for a vehicle of its wheelbase: in tonnes, likely.
    #[error("a vehicle with a wheelbase of {} m (a + b) weighs at least {} kg (a kart without its driver is about 75 kg): is the mass in tonnes? give it in kg ({} kg for {} t)", crate::format::significant(*wheelbase, 3), super::number::Num(*min), super::number::Num(1000.0 * mass), super::number::Num(*mass))]
    MassTooSmall {
        /// The mass given, kg.
        mass: f64,
        /// The least mass accepted, kg.
        min: f64,
        /// The wheelbase, m.
        wheelbase: f64,
    },
    /// A steady lateral acceleration at or beyond the car's rollover threshold.
    #[error("{}", beyond_rollover(.0))]
    BeyondRollover(Box<Rollover>),
    /// A centre of gravity so high that the car tips over standing.
    #[error("the car would tip over at {} g of lateral acceleration (track/(2·cg_height) on the narrower track, {} m), below {} g, where even a loaded tanker truck holds about 0.35 g (cars 1.0–1.5 g): the rule asks for a cg_height of at most track/(2·0.3) = {} m; is it in another unit, or another key's value?", crate::format::significant(*tips_at, 2), super::number::Num(*track), super::number::Num(*min), crate::format::significant(track / (2.0 * min), 3))]
    TipsOver {
        /// track/(2·cg_height), g.
        tips_at: f64,
        /// The narrower track, m.
        track: f64,
        /// The least accepted, g.
        min: f64,
    },
    /// A wheelbase that is not a + b (to 1 mm).
    #[error("{}", checks::wheelbase_mismatch(.0))]
    WheelbaseMismatch(Box<Wheelbase>),
    /// A share of the lateral load transfer outside [0, 1].
    #[error("a share of the load transfer must lie in [0, 1]")]
    TransferShare,
    /// A share of a longitudinal force outside [0, 1].
    #[error("a share of the force: 0 to 1")]
    ForceShare,
    /// A PAC89 file in the 1987 paper's numbering.
    #[error("the file uses the 1987 paper's coefficient numbering; this crate implements the Adams PAC89 numbering (a0..a13, b0..b10, c0..c17): convert the file and set form = \"adams-pac89\"")]
    Pac89PaperNumbering,
    /// PAC89's a4, which divides the load, at zero.
    #[error("a4 divides the load and must not be zero")]
    ZeroA4,
    /// A sweep axis's unit that the axis does not take.
    #[error("unknown unit `{unit}` (steer: rad or deg; speed: m/s or km/h; friction: none)")]
    UnknownSweepUnit {
        /// The unit as written.
        unit: String,
    },
    /// A range's step that is not positive.
    #[error("a range's step must be positive: it runs upward from `from` to `to`")]
    RangeStepNotPositive,
    /// A range's end below its start.
    #[error("below `from` ({from}): a range runs upward from `from` to `to` (swap them)")]
    RangeEndBeforeStart {
        /// The range's start, as written.
        from: f64,
    },
    /// A range or list of more than a million values.
    #[error("more than a million values")]
    TooManyValues,
    /// A sweep axis without values.
    #[error("no values")]
    NoValues,
    /// A stiffness axis whose step or count gives no value.
    #[error("no values (a step or count that gives none?)")]
    NoValuesFromRange,
    /// A `{ from, to, count }` axis whose count of 1 cannot hold both ends (from, to).
    #[error("a count of 1 cannot hold both `from` ({0}) and `to` ({1}): give a count of 2 or more, or the one value as a list")]
    CountOfOneTwoEnds(f64, f64),
    /// A value a map axis gives twice.
    #[error("is given twice on this axis: every map point with it would be computed twice (give each value once)")]
    RepeatedValue,
    /// A value an equilibrium sweep axis gives twice.
    #[error("is given twice on this axis: every condition with it would be solved twice (give each value once)")]
    RepeatedSweepValue,
    /// A listed axis value not above the one before it: a sweep is traced
    /// along its axes, bifurcations located between neighbours.
    #[error("is below the value before it ({before}): give an axis's values in increasing order (a sweep is traced from each value to the next)")]
    AxisOutOfOrder {
        /// The value before it, as written.
        before: f64,
    },
    /// An effect the equilibrium analysis does not model.
    #[error("not modelled by the equilibrium analysis (it has aero_load, road_bank and relaxation_length): switch it off or scale the tyre files")]
    NotInEquilibrium,
    /// A tolerance given for the fixed-step RK4.
    #[error("tolerances apply to method = \"dopri5\" or \"dop853\"; RK4 has a fixed `step`")]
    ToleranceWithRk4,
    /// A lateral acceleration no steady state holds at the speed (boxed).
    #[error("{0}")]
    NoSteadyState(Box<super::NoSteadyState>),
    /// Er's weights `e1` and `e2` both 0: Er would weigh nothing and read
    /// 0 s for any response.
    #[error("with `e1` = 0 too, Er = e1·E_r + e2·E_ay weighs nothing and reads 0 s whatever the car does: give e1 or e2 a positive weight (both default to 1)")]
    ErWeightsZero,
    /// A step steer given both of its amplitudes.
    #[error("a step steer takes one of `steer` (rad) and `lateral_acceleration` (m/s²), and both are given: keep one")]
    StepSteerBothAmplitudes,
    /// A step steer given neither of its amplitudes.
    #[error("a step steer needs one of `steer` (rad) and `lateral_acceleration` (m/s²), and neither is given")]
    StepSteerNoAmplitude,
    /// An empty list of candidate effects.
    #[error("an empty list: name at least one effect, or leave the key out for the whole library")]
    NoEffects,
    /// A candidate effect listed twice.
    #[error("`{name}` is listed twice: each candidate is fitted once")]
    EffectTwice {
        /// The effect.
        name: String,
    },
    /// A channel uncertainty stated under `[channels]` at least the
    /// channel's RMS signal over the runs and ten times an estimated
    /// output's: the channel would carry nothing.
    #[error("is at least the channel's RMS signal over the runs ({} {u}) and more than {} {u}, ten times what even an estimated output of this kind is good to: a channel trusted no better than its whole motion carries nothing into any fit; a sensor of this kind is good to about {} {u} (leave the key out for the tool's estimate from the channel's own scatter, or leave the column out of the runs to leave the channel out)", crate::format::rounded(.0.signal, 3), super::number::Num(.0.estimated), super::number::Num(.0.floor), u = .0.unit)]
    UncertaintyBeyondSignal(Box<BeyondSignal>),
    /// A `[tyres]` table that names no single source of tyres.
    #[error("give either `file`, or `front` and `rear`, or `rig` (with an optional `model`)")]
    TyreSource,
    /// A prior of the axles beside tyre files or rig data (no axles to identify).
    #[error("a prior of the axles (`class`, `cornering`, `friction`) applies only without tyre files or rig data, when the diagnosis identifies the axles from the runs")]
    PriorWithTyres,
    /// A name that is no member of its closed set (a model, a unit, a
    /// metric, an effect): [`OptionsError::UnknownName`]. Boxed, as every
    /// large payload here, so that an error stays small to return.
    #[error(transparent)]
    Name(Box<OptionsError>),
    /// A campaign's key wrong for its campaign ([`CampaignReason`]).
    #[error(transparent)]
    Campaign(Box<CampaignReason>),
    /// An MFeval `useMode` code that cannot be used.
    #[error(transparent)]
    Mode(Box<ModeError>),
    /// Inverse queries without a stiffness map to invert.
    #[error("inverse queries need a [stiffness] map with at least 2 × 2 values")]
    InverseWithoutMap,
    /// A study whose manoeuvre is not a step steer.
    #[error("a study needs a step steer")]
    StudyNeedsStepSteer,
    /// A cornering stiffness that is not positive.
    #[error("a cornering stiffness must be positive")]
    StiffnessNotPositive,
    /// A cornering stiffness no tyre has against its axle's static load
    /// (an argument's; a study file's is located, `ScenarioProblem`).
    #[error("{}", .0.against_load())]
    StiffnessAgainstLoad(Box<super::StiffnessSlip>),
    /// A validation index beyond the RBF's pairs.
    #[error("no such pair: an index counts from 0 in the order `[rbf] front` × `rear_offsets` makes the pairs (each offset in turn, rear ≤ `rear_max`), and they are {pairs}: {}", if *pairs == 0 { "no index is valid".to_string() } else { format!("an index lies in 0–{}", pairs - 1) })]
    TooFewPairs {
        /// The pairs there are.
        pairs: usize,
    },
    /// A programme the four-wheel truth does not drive.
    #[error("the four-wheel truth holds its speed on a flat road: it drives the handling programme, not `{programme}`")]
    TruthProgramme {
        /// The programme asked.
        programme: String,
    },
    /// A programme whose driver cannot drive a designed manoeuvre.
    #[error("`{programme}` is driven by a closed-loop driver on its own track: it drives no designed manoeuvre (the handling programme, the ovals and the road course do)")]
    DriveProgramme {
        /// The programme asked.
        programme: String,
    },
    /// A schedule's column shorter than another (the error's key).
    #[error("{} where `{longest}` has {longest_len}: `t`, `steer` and `speed` need one value per breakpoint", crate::format::plural(*len, "value", "values"))]
    ScheduleLengths {
        /// Values in the short column.
        len: usize,
        /// The longest column.
        longest: ScheduleColumn,
        /// Values in it.
        longest_len: usize,
    },
    /// A schedule of fewer than two breakpoints.
    #[error("{}: a schedule needs at least 2, one value each in `t`, `steer` and `speed`", crate::format::plural(*len, "breakpoint", "breakpoints"))]
    ScheduleTooShort {
        /// Breakpoints given.
        len: usize,
    },
    /// A schedule's time that does not follow the one before.
    #[error("not after the time before it, {before} s: a schedule's times increase strictly")]
    ScheduleTime {
        /// The time before it, s.
        before: f64,
    },
    /// An effect the four-wheel truth does not have.
    #[error("not an effect of the four-wheel truth")]
    NotATruthEffect,
    /// The steer a ramp steer reaches by its end, rad.
    #[error("the ramp reaches {} rad ({:.0}°) by `end` = {end} s, beyond ±45° (0.785 rad; a car's largest mean road-wheel steer is about 35–40°): lower `rate` or end the run sooner{}", super::number::Num(*reached), reached.to_degrees(), if *in_degrees { "; is the rate in degrees per second? (the steer rate is in rad/s)" } else { "" })]
    RampReach {
        /// The steer at `end`, rad.
        reached: f64,
        /// The end of the run, s.
        end: f64,
        /// Whether the rate itself looks like one in degrees per second.
        in_degrees: bool,
    },
    /// A candidate named twice among those a design separates.
    #[error("`{candidate}` is given more than once")]
    GivenTwice {
        /// The candidate, `a+b`.
        candidate: String,
    },
    /// An effect given another number of parameters than it takes.
    #[error("takes {needed} parameters")]
    ParameterCount {
        /// The parameters it takes.
        needed: usize,
    },
}
