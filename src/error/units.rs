//! A channel of an input file whose size says it is written in another
//! unit than `FORMATS.md`'s (SI, radians, seconds): a yaw rate in deg/s, a
//! lateral acceleration in g or ft/s², a time in milliseconds, a wheel
//! load in kN, a speed in km/h; and a rig force
//! no tyre carries. Each is judged on what no car reaches in the unit
//! `FORMATS.md` asks for, and its message names the column, the value and
//! the unit it is likely in.

use super::number::Num;
use crate::format::{fixed, plural, significant};
use thiserror::Error;

/// How a `column` in degrees is declared ([`super::header_unit`]).
pub(super) use super::header_unit::declare;

/// A column whose values are in another unit than `FORMATS.md`'s.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum UnitSlip {
    /// A yaw rate beyond what any car reaches, over more than 1 % of the
    /// run (a spike alone is repaired later).
    #[error("column `yaw_rate`: {} rad/s is beyond ±{} rad/s ({:.0}°/s), which no car's yaw rate reaches (the run's 99th percentile of |yaw_rate| is {} rad/s): the yaw rate is in rad/s (FORMATS.md); is the column in deg/s? {}", Num(*value), Num(*limit), limit.to_degrees(), significant(*p99, 3), by.words("divide it by 57.3"))]
    YawRate {
        /// The first yaw rate beyond the limit, as read.
        value: f64,
        /// The 99th percentile of |yaw_rate|, as read.
        p99: f64,
        /// The largest yaw rate accepted, rad/s.
        limit: f64,
        /// What to do: declare the column in degrees (where the reader
        /// takes it so), or convert this run's file.
        by: super::YawAdvice,
    },
    /// A lateral acceleration beyond what any car reaches, over more than
    /// 1 % of the run.
    #[error("column `ay`: {} m/s² is beyond ±{} m/s² ({} g), which no car's lateral acceleration reaches (the run's 99th percentile of |ay| is {} m/s²): `ay` is in m/s² (FORMATS.md); is the column in ft/s² (divide it by 3.281) or another unit?", Num(*value), Num(*limit), fixed(limit / 9.80665, 1), significant(*p99, 3))]
    AyTooLarge {
        /// The first |ay| beyond the limit, as read.
        value: f64,
        /// The 99th percentile of |ay|, as read.
        p99: f64,
        /// The largest |ay| accepted, m/s².
        limit: f64,
    },
    /// A lateral acceleration about 1/9.81 of speed × yaw rate: in g.
    #[error("column `ay`: {} where speed × yaw_rate is {} m/s²: over {} turning at |speed × yaw_rate| ≥ {} m/s², `ay` is a median {} of it, where a car's lateral acceleration is about speed × yaw_rate: is `ay` in g? multiply it by 9.81 (FORMATS.md: m/s²)", Num(*value), significant(*expected, 3), plural(*samples, "sample", "samples"), Num(*turning), fixed(*median, 3))]
    AyInG {
        /// The row's `ay`, as read.
        value: f64,
        /// The row's speed × yaw rate, m/s².
        expected: f64,
        /// The median of ay/(speed·yaw_rate) over the turning samples.
        median: f64,
        /// The turning samples.
        samples: usize,
        /// The least |speed × yaw_rate| of a turning sample, m/s².
        turning: f64,
    },
    /// A lateral acceleration about 3.281 times speed × yaw rate: in ft/s².
    #[error("column `ay`: {} where speed × yaw_rate is {} m/s²: over {} turning at |speed × yaw_rate| ≥ {} m/s², `ay` is a median {} of it, where a car's lateral acceleration is about speed × yaw_rate (1 m = 3.281 ft): is `ay` in ft/s²? multiply it by 0.3048 (FORMATS.md: m/s²)", Num(*value), significant(*expected, 3), plural(*samples, "sample", "samples"), Num(*turning), fixed(*median, 3))]
    AyInFeet {
        /// The row's `ay`, as read.
        value: f64,
        /// The row's speed × yaw rate, m/s².
        expected: f64,
        /// The median of ay/(speed·yaw_rate) over the turning samples.
        median: f64,
        /// The turning samples.
        samples: usize,
        /// The least |speed × yaw_rate| of a turning sample, m/s².
        turning: f64,
    },
    /// A median time step no handling run is logged at.
    #[error("column `t`: the median time step is {} ({}), coarser than any handling run is logged at (at most {} s, {} Hz): `t` is in seconds (FORMATS.md){}", apart(*step, *limit), rate(*step), Num(*limit), Num(1.0 / limit), in_ms(*step))]
    TimeStep {
        /// The median step, as read.
        step: f64,
        /// The largest median step accepted, s.
        limit: f64,
    },
    /// A wheel load of a few units: in kN.
    #[error("column `fz`: {} N, in a file whose median load is {} N: no tyre is tested at a median load below {} N (a car tyre carries 2,000–8,000 N): `fz` is in N (FORMATS.md); is the column in kN? multiply it by 1000", Num(*value), Num(*median), Num(*limit))]
    LoadInKn {
        /// The first load below the limit, as read.
        value: f64,
        /// The median load, as read.
        median: f64,
        /// The smallest median load accepted, N.
        limit: f64,
    },
    /// One load of a few units between loaded rows: in kN.
    #[error("column `fz`: {} N between rows at {} and {} N, where no tyre test dips below {} N for one sample: `fz` is in N (FORMATS.md); is the cell in kN? {} kN is {} N", Num(*value), Num(neighbours[0]), Num(neighbours[1]), Num(*limit), Num(*value), Num(value * 1e3))]
    LoadRowInKn {
        /// The load, as read.
        value: f64,
        /// The loads of the rows before and after, as read.
        neighbours: [f64; 2],
        /// The smallest load accepted between loaded rows, N.
        limit: f64,
    },
    /// An inflation pressure of a few units: in kPa, bar or psi.
    #[error("column `pressure`: {} Pa, in a file whose median pressure is {} Pa: no inflated tyre runs below {} Pa (0.1 bar; a racing slick runs at about 70 kPa, a car tyre at 200–300 kPa): `pressure` is in Pa (FORMATS.md); {}", Num(*value), Num(*median), Num(*limit), column_meant(*median, meant))]
    PressureNotInPa {
        /// The first pressure below the limit, as read.
        value: f64,
        /// The median pressure, as read.
        median: f64,
        /// The smallest median pressure accepted, Pa.
        limit: f64,
        /// The median read in the unit that lands it among the tyre's
        /// pressures (or a pneumatic tyre's), where one does.
        meant: Option<PressureMeant>,
    },
    /// One inflation pressure of a few units in a column whose median is
    /// in Pa: that value written in kPa, bar or psi.
    #[error("column `pressure`: {} Pa: no inflated tyre runs below {} Pa (0.1 bar), and the column's median is {} Pa: `pressure` is in Pa (FORMATS.md): {}", Num(*value), Num(*limit), Num(*median), pressure_meant(*value, meant))]
    PressureRowNotInPa {
        /// The pressure, as read.
        value: f64,
        /// The median pressure of the column, as read.
        median: f64,
        /// The smallest pressure accepted, Pa.
        limit: f64,
        /// The reading in another unit that lands among the tyre's
        /// pressures, where one does.
        meant: Option<PressureMeant>,
    },
    /// A forward speed beyond any car's over more than 1 % of the run, or
    /// one sample beyond any vehicle's at all (no logger's glitch of a
    /// car's speed reads 1e308).
    #[error("column `speed`: {} m/s is beyond {} m/s ({} km/h), which no car's speed reaches (the run's 99th percentile of |speed| is {} m/s): `speed` is the forward speed in m/s (FORMATS.md); is the column in km/h (divide it by 3.6) or another unit?", apart(*value, *limit), Num(*limit), fixed(limit * 3.6, 0), apart(*p99, *limit))]
    SpeedBeyondAnyCar {
        /// The first speed beyond the limit, as read.
        value: f64,
        /// The 99th percentile of |speed|, as read.
        p99: f64,
        /// The largest speed accepted, m/s.
        limit: f64,
    },
    /// A speed whose product with the yaw rate is about 3.6 times the
    /// lateral acceleration: in km/h (or 2.237 times: in mph).
    #[error("column `speed`: {} where `ay` is a median {} of speed × yaw_rate over {} turning at |speed × yaw_rate| ≥ {} m/s², where a car's lateral acceleration is about speed × yaw_rate (1/{} = {}): is `speed` in {}? divide it by {} (FORMATS.md: m/s)", Num(*value), fixed(*median, 3), plural(*samples, "sample", "samples"), Num(*turning), unit.per_m_s(), fixed(1.0 / unit.per_m_s(), 3), unit.name(), unit.per_m_s())]
    SpeedPerHour {
        /// The unit the ratio points to.
        unit: SpeedUnit,
        /// The speed at the first turning sample, as read.
        value: f64,
        /// Median of ay/(speed·yaw_rate) over the turning samples.
        median: f64,
        /// Turning samples judged.
        samples: usize,
        /// The least |speed × yaw_rate| of a turning sample, m/s².
        turning: f64,
    },
    /// A speed whose change is about 3.6 (2.237) times what `ax`
    /// integrates to: in km/h (mph), judged where the run has no `ay`.
    #[error("column `speed`: {} where `ax` integrated over {} of {} s in which the speed changes by {} or more is a median {} of that change, where a car's longitudinal acceleration integrates to its change of speed (1/{} = {}): is `speed` in {}? divide it by {} (FORMATS.md: m/s)", Num(*value), plural(*stretches, "stretch", "stretches"), Num(*span), Num(*change), fixed(*median, 3), unit.per_m_s(), fixed(1.0 / unit.per_m_s(), 3), unit.name(), unit.per_m_s())]
    SpeedPerHourByAx {
        /// The unit the ratio points to.
        unit: SpeedUnit,
        /// The speed at the first stretch judged, as read.
        value: f64,
        /// Median of ∫ax dt / Δspeed over the stretches.
        median: f64,
        /// Stretches judged.
        stretches: usize,
        /// Their length, s.
        span: f64,
        /// The least speed change of a stretch judged, as read.
        change: f64,
    },
    /// A yaw rate whose speed × yaw rate is 57 times the lateral
    /// acceleration: in deg/s, below the size check's limit.
    #[error("column `yaw_rate`: {} where `ay` is a median {} of speed × yaw_rate over {} turning at |speed × yaw_rate| ≥ {} m/s², where a car's lateral acceleration is about speed × yaw_rate (π/180 = 0.0175): is `yaw_rate` in deg/s? {}", Num(*value), fixed(*median, 4), plural(*samples, "sample", "samples"), Num(*turning), by.words("Convert it"))]
    YawRateInDegPerS {
        /// The yaw rate at the first turning sample, as read.
        value: f64,
        /// Median of ay/(speed·yaw_rate) over the turning samples.
        median: f64,
        /// Turning samples judged.
        samples: usize,
        /// The least |speed × yaw_rate| of a turning sample, m/s².
        turning: f64,
        /// What to do: declare the column in degrees (where the reader
        /// takes it so), or convert this run's file.
        by: super::YawAdvice,
    },
    /// A yaw rate 57 times too small against `ay`: declared in deg/s while
    /// in rad/s.
    #[error("column `yaw_rate`: {} where `ay` is a median {} of speed × yaw_rate over {}, where a car's lateral acceleration is about speed × yaw_rate: the yaw rate is about 57 times too small; was it declared in degrees (`degrees = [\"yaw_rate\"]`, `--degrees yaw_rate`) while it was in rad/s?", Num(*value), fixed(*median, 1), plural(*samples, "turning sample", "turning samples"))]
    YawRateTooSmall {
        /// The yaw rate at the first turning sample, as converted.
        value: f64,
        /// Median of ay/(speed·yaw_rate) over the turning samples.
        median: f64,
        /// Turning samples judged.
        samples: usize,
    },
    /// A steer or yaw rate declared in degrees that was in radians, as the
    /// yaw rate against the steer says (r·l/(u·δ) 57× off a neutral car's:
    /// a yaw rate in rad/s read as deg/s is 57× smaller, a steer in
    /// radians read as degrees 57× smaller, its yaw rate 57× larger).
    #[error("column `{column}`, declared in degrees by {declared}: so read, the yaw rate is {} a neutral car's for this steer (median r·l/(u·δ) = {} over {samples} steered samples{}), as {} makes it 57× {}: the column is in {} (FORMATS.md); leave out {declared}", if *median < 1.0 { format!("{}× smaller than", significant(1.0 / median.max(1e-9), 2)) } else { format!("{}×", significant(*median, 2)) }, significant(*median, 3), wheelbase.map_or(String::new(), |l| format!(", with l = {} m, {} any car's wheelbase", Num(l), if *median < 1.0 { "longer than" } else { "shorter than" })), if *column == "steer" { "a steer in radians read as degrees" } else { "a yaw rate in rad/s read as deg/s" }, if *column == "steer" { "larger" } else { "smaller" }, if *column == "steer" { "radians" } else { "rad/s" })]
    DeclaredInDegrees {
        /// The column declared (`steer` or `yaw_rate`).
        column: &'static str,
        /// The declaration, as the user wrote it (`` `--degrees steer` ``).
        declared: &'static str,
        /// Median of r·l/(u·δ) over the steered samples.
        median: f64,
        /// The steered samples.
        samples: usize,
        /// The wheelbase l taken when the vehicle's is not known, m.
        wheelbase: Option<f64>,
    },
    /// A sideslip declared in degrees that was in radians.
    #[error("column `beta`: {} as read, declared in degrees, is a median {} of what a car turning as this one does shows (3 m × yaw_rate/speed + 0.1 rad per g of speed × yaw_rate) over {}: a car's is 0.08–0.5 of it, so the column was already in radians; drop `beta` from the columns declared in degrees", Num(*value), fixed(*median, 4), plural(*samples, "turning sample", "turning samples"))]
    BetaDeclaredInDegrees {
        /// The sideslip at the first turning sample, as the file has it.
        value: f64,
        /// Median of |β|/bound over the turning samples, converted.
        median: f64,
        /// Turning samples judged.
        samples: usize,
    },
    /// A speed whose median is backwards at speed: another sign
    /// convention.
    #[error("column `speed`: {} m/s, and the run's median is {} m/s: `speed` is the forward speed, positive (FORMATS.md, ISO 8855); is the column in another sign convention? negate it", Num(*value), fixed(*median, 2))]
    SpeedBackwards {
        /// The first speed backwards beyond 5 m/s, as read.
        value: f64,
        /// The run's median speed, as read.
        median: f64,
    },
    /// A sideslip many times what a turning car shows: in degrees.
    #[error("column `beta`: {} rad where a car turning as this one does shows at most about {} rad (3 m × yaw_rate/speed + 0.1 rad per g of speed × yaw_rate), and over {} `beta` is a median {}× that: is `beta` in degrees? Convert it, or say so: `degrees = [\"beta\"]` under [runs] in a campaign or a replay's [manoeuvre], `--degrees beta` to `metrics`", Num(*value), significant(*bound, 2), plural(*samples, "turning sample", "turning samples"), fixed(*median, 1))]
    BetaInDegrees {
        /// The sideslip at the first turning sample, as read.
        value: f64,
        /// The bound there, rad.
        bound: f64,
        /// Median of |β| over the bound.
        median: f64,
        /// Turning samples judged.
        samples: usize,
    },
    /// A body roll, road bank or sideslip column whose size says degrees.
    #[error("column `{column}`: {} rad is beyond ±{:.0}°, and the run's 99th percentile of |{column}| is {} rad: angles are in radians (FORMATS.md); is the column in degrees? Convert it, or say so: `degrees = [\"{column}\"]` under [runs] in a campaign or a replay's [manoeuvre]{}", Num(*value), limit.to_degrees(), significant(*p99, 3), if *column == "bank" { "; `metrics` does not read it" } else { match *column { "roll" => ", `--degrees roll` to `metrics`", _ => ", `--degrees beta` to `metrics`" } })]
    RollInDegrees {
        /// The column (`roll`, `bank`, `beta`).
        column: &'static str,
        /// The first value beyond the limit, as read.
        value: f64,
        /// The 99th percentile of |value|.
        p99: f64,
        /// The largest accepted, rad.
        limit: f64,
    },
    /// A rig force or moment no tyre carries (a value scaled by a wrong
    /// factor, or an overflow of the logger).
    #[error("column `{column}`: {} {unit} is beyond ±{} {unit}, which no tyre on a rig carries: `{column}` is in {unit} (FORMATS.md); is the column scaled by a wrong factor?", Num(*value), Num(*limit))]
    RigBeyondAnyTyre {
        /// The column (`fy`, `fx`, `mz`, `mx`, `my`).
        column: &'static str,
        /// The first value beyond the limit, as read.
        value: f64,
        /// The largest size accepted.
        limit: f64,
        /// The column's unit.
        unit: &'static str,
    },
    /// A rig sample whose force is more than [`MAX_RIG_FRICTION`] times
    /// its load: a spike, or a row in another unit.
    #[error("column `{column}`: {} N at fz {} N {} (the limit there is {MAX_RIG_FRICTION} × (fz + a twentieth of the file's median load, {} N) = {} N)", Num(*value), Num(*fz), super::rig_row::above_load(*value, *fz), Num(*median), Num(MAX_RIG_FRICTION * (fz + 0.05 * median)))]
    RigForceAboveLoad {
        /// The column (`fy`, `fx`).
        column: &'static str,
        /// The force, N.
        value: f64,
        /// The sample's load, N.
        fz: f64,
        /// The file's median load, N.
        median: f64,
    },
    /// A rig aligning moment more than [`MAX_RIG_ARM`] times its load: an
    /// arm no tyre has (a moment in N·mm, or a spike).
    #[error("column `mz`: {} N·m at fz {} N is {} m times the load, where a tyre's aligning moment is its pneumatic trail (a few centimetres) times a force within about twice the load: no tyre passes {MAX_RIG_ARM} m × (fz + a twentieth of the file's median load, {} N) = {} N·m; `mz` is in N·m (FORMATS.md): {}", Num(*value), Num(*fz), Num(*arm), Num(*median), Num(MAX_RIG_ARM * (fz + 0.05 * median)), arm_hint(*arm))]
    RigMomentAboveLoad {
        /// The moment, N·m.
        value: f64,
        /// The sample's load, N.
        fz: f64,
        /// The moment over that load plus a twentieth of the median, m.
        arm: f64,
        /// The file's median load, N.
        median: f64,
    },
    /// Rig `fy` and `mz` columns exchanged: the `mz` column holds forces of
    /// a tyre's lateral force's size against the load, the `fy` column
    /// values a pneumatic trail's share of them (`io/rig_rows.rs`).
    #[error("column `mz`: {} at fz {} N is {} times the load, a lateral force's size, and the `fy` column (column {fy_column}) beside it holds values {} m times `mz`'s (their 90th percentiles of |value|, {} and {}): a pneumatic trail of {} mm, an aligning moment's size; the columns `fy` and `mz` look swapped: exchange their names in the header (FORMATS.md: `fy` in N, `mz` in N·m). A moment in N·mm would leave `fy` a force of its load's size", Num(*value), Num(*fz), crate::format::readable((value / fz).abs(), 3), crate::format::readable(*ratio, 2), significant(*fy_p90, 3), significant(*mz_p90, 3), crate::format::readable(1000.0 * ratio, 2))]
    RigFyMzSwapped {
        /// The `mz` column's largest |value| (a force), as read.
        value: f64,
        /// That row's load, N.
        fz: f64,
        /// The `fy` column's 90th percentile of |value|.
        fy_p90: f64,
        /// The `mz` column's 90th percentile of |value|.
        mz_p90: f64,
        /// `fy_p90 / mz_p90`, m if `fy` held the moment.
        ratio: f64,
        /// The `fy` column's position in the header (1-based).
        fy_column: usize,
    },
    /// A rig column whose largest force, over a sweep that reaches
    /// `slip` (rad or slip ratio), is below [`MIN_RIG_GRIP`] of its load:
    /// forces in kN beside loads in N, or a column scaled down.
    #[error("column `{column}`: its largest force, {} N at fz {} N, is {} of the load over a sweep reaching {}, where every tyre makes more than {MIN_RIG_GRIP} of its load: {}", Num(*value), Num(*fz), crate::format::readable((value / fz).abs(), 3), sweep_reach(column, *slip), grip_hint((value / fz).abs()))]
    RigForcesBelowGrip {
        /// The column (`fy`, `fx`).
        column: &'static str,
        /// The largest force relative to its load, N.
        value: f64,
        /// That sample's load, N.
        fz: f64,
        /// The largest slip the sweep reaches (rad, or slip ratio).
        slip: f64,
    },
    /// Loads in lbf beside forces in N (`rig_load_lbf.rs`).
    #[error(transparent)]
    RigLoadInLbf(#[from] super::rig_load_lbf::RigLoadInLbf),
    /// An aligning moment in kN·m (`rig_moment_knm.rs`).
    #[error(transparent)]
    RigMomentInKnm(#[from] super::rig_moment_knm::RigMomentInKnm),
    /// A rig speed beyond any rig's (`rig_row.rs`).
    #[error(transparent)]
    RigSpeedBeyondAny(#[from] super::rig_row::RigSpeedBeyondAny),
    /// Slip angles in degrees under a linear fit (`slip_degrees.rs`).
    #[error(transparent)]
    SlipAngleInDegrees(#[from] super::slip_degrees::SlipAngleInDegrees),
    /// A run's `ay` against its speed and yaw rate off by a unit's
    /// factor (`lateral_slope.rs`).
    #[error(transparent)]
    LateralSlope(#[from] super::lateral_slope::LateralSlope),
    /// A yaw rate a small share of a steady `ay` (`yaw_scale.rs`).
    #[error(transparent)]
    YawScale(#[from] super::yaw_scale::YawScale),
    /// A sideslip in percent of a radian (`lateral_slope.rs`).
    #[error(transparent)]
    BetaInPercent(#[from] super::lateral_slope::BetaInPercent),
    /// A road bank in degrees (`bank_degrees.rs`).
    #[error(transparent)]
    BankInDegrees(#[from] super::bank_degrees::BankInDegrees),
    /// A road bank logged in the other sign (`bank_reversed.rs`).
    #[error(transparent)]
    BankReversed(#[from] super::bank_reversed::BankReversed),
    /// A lateral acceleration logged in the other sign ([`AyReversed`]).
    #[error(transparent)]
    AyReversed(#[from] AyReversed),
}

/// A run's `ay` logged in the other sign: over its turning half-second
/// means `ay` is about −1 times the kinematic lateral acceleration `u·r +
/// d(u·β)/dt (+ g·sin bank)`, where ISO 8855 gives +1 (y to the left, yaw
/// positive turning left: a left turn pushes the car left). Judged by
/// `io/run_ay_sign.rs`. Units: m/s².
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `ay`: {} where speed × yaw_rate{} is {} m/s²: over {bins} half-second means of the run turning at speed (R² {}), `ay` regressed on speed × yaw_rate{}{} has a slope of {}, where a car's is about +1 (between {} and {}): `ay` is positive to the left and `yaw_rate` turning left (ISO 8855, FORMATS.md), and a car turning left is pushed to the left; `steer` turns with `yaw_rate`, so this `ay` is logged in the other sign (an accelerometer mounted the other way round, or a logger's y axis to the right): negate the column", Num(*value), if *with_bank == Some(true) { " + g·sin(bank)" } else { "" }, fixed(*expected, 2), fixed(*r2, 3), if *with_beta { " + d(speed·beta)/dt" } else { "" }, bank_words(*with_bank), fixed(*slope, 3), Num(range.0), Num(range.1))]
pub struct AyReversed {
    /// `ay` at the row named (the first of the turning mean whose
    /// regressor is largest), as read.
    pub value: f64,
    /// speed × yaw rate (+ g·sin(bank) where the fit takes it) at that
    /// row, m/s².
    pub expected: f64,
    /// The fitted slope of `ay` on the kinematic lateral acceleration
    /// (through the origin).
    pub slope: f64,
    /// The fit's R² (through the origin).
    pub r2: f64,
    /// The turning means fitted.
    pub bins: usize,
    /// Whether the d(u·β)/dt term was in the regressor (a `beta` column).
    pub with_beta: bool,
    /// With a `bank` column, whether its g·sin(bank) was in the regressor
    /// (the better fit: the car feels the logged bank) or left out (it
    /// does not); None without one.
    pub with_bank: Option<bool>,
    /// The slopes of a run in SI units and ISO signs.
    pub range: (f64, f64),
}

/// The bank's part of the regressor's words.
fn bank_words(with_bank: Option<bool>) -> &'static str {
    match with_bank {
        Some(true) => " + g·sin(bank)",
        Some(false) => " (the logged bank left out: `ay` fits better without it)",
        None => "",
    }
}

/// The slip a sweep of `column` reaches, with its unit: a slip angle in
/// rad and degrees (`fy`), a slip ratio (`fx`), to 3 digits.
fn sweep_reach(column: &str, slip: f64) -> String {
    let n = |v: f64| crate::format::readable(v, 3);
    match column {
        "fx" => format!("a slip ratio of {}", n(slip)),
        _ => format!(
            "a slip angle of {} rad ({}°)",
            n(slip),
            n(slip.to_degrees())
        ),
    }
}

/// The question a rig aligning moment of `arm` (m of its load) ends on:
/// N·mm where a thousandth of it is a tyre's.
fn arm_hint(arm: f64) -> &'static str {
    if arm / 1000.0 <= MAX_RIG_ARM {
        "is the column in N·mm? divide it by 1000"
    } else {
        "a spike of the logger, or a row in another unit?"
    }
}

/// The largest aligning moment per unit load a rig sample may hold, m:
/// `mz = t·fy` with a pneumatic trail `t` of a few centimetres (at most
/// 0.25 m on any tyre, [`crate::tyre::sizes::MAX_TRAIL`] is twice that)
/// and `|fy|` within twice the load; the Hoosier file's largest is 0.04 m.
pub const MAX_RIG_ARM: f64 = 0.5;

/// The question a rig force of `share` of its load ends on: kN where a
/// thousand times it is a tyre's grip.
fn grip_hint(share: f64) -> &'static str {
    if (MIN_RIG_GRIP..=MAX_RIG_FRICTION).contains(&(1000.0 * share)) {
        "is the column in kN? multiply it by 1000"
    } else {
        "is the column scaled, or in another unit?"
    }
}

/// The least share of its load a tyre's force reaches at a slip angle of
/// [`MIN_RIG_SLIP`] (or that slip ratio): a truck tyre's cornering
/// coefficient of about 5 1/rad gives 0.05 at 0.01 rad, a car's 0.13.
pub const MIN_RIG_GRIP: f64 = 0.02;

/// The slip (rad, or slip ratio) a sweep must reach for its forces to be
/// judged against [`MIN_RIG_GRIP`].
pub const MIN_RIG_SLIP: f64 = 0.01;

/// The most a rig sample's force may be, in multiples of its load (plus a
/// twentieth of the median load, for samples near zero load): 5, past
/// any tyre's friction (a racing slick reaches about 2; the Hoosier rig
/// file's largest is 1.37).
pub const MAX_RIG_FRICTION: f64 = 5.0;

/// A pressure read in another unit that lands among a tyre's pressures
/// ([`UnitSlip::PressureRowNotInPa`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureMeant {
    /// The value converted to Pa.
    pub pa: f64,
    /// The unit it reads in: `kPa`, `bar`, `psi`.
    pub unit: &'static str,
    /// The pressures it lands among, Pa.
    pub among: [f64; 2],
    /// What they are (`the file's PRESMIN to PRESMAX`).
    pub what: &'static str,
}

/// The question a pressure `value` of a few Pa raises: the reading that
/// lands among the tyre's pressures, as [`super::level_slip`] offers the
/// one that selects a level; else every unit it may be in.
fn pressure_meant(value: f64, meant: &Option<PressureMeant>) -> String {
    match meant {
        Some(m) => format!(
            "did you mean {} Pa ({} {}), within {} ({} to {} Pa)?",
            significant(m.pa, 4),
            Num(value),
            m.unit,
            m.what,
            Num(m.among[0]),
            Num(m.among[1])
        ),
        None => {
            "is the value in kPa (multiply it by 1000), bar (by 100000) or psi (by 6895)?".into()
        }
    }
}

/// The question a whole column of pressures of a few Pa raises: the unit
/// its `median` reads in among the tyre's pressures, with the factor that
/// converts the column, as [`pressure_meant`] answers for one cell; else
/// every unit it may be in.
fn column_meant(median: f64, meant: &Option<PressureMeant>) -> String {
    match meant {
        Some(m) => format!(
            "is the column in {unit}? its median, {} {unit}, is {} Pa, within {} ({} to {} Pa): multiply the column by {}",
            Num(median),
            significant(m.pa, 4),
            m.what,
            Num(m.among[0]),
            Num(m.among[1]),
            significant(m.pa / median, 4),
            unit = m.unit,
        ),
        None => "is the column in kPa (multiply it by 1000), bar (by 100000) or psi (by 6895)?"
            .into(),
    }
}

/// A speed `v` refused against `limit`, m/s, to the digits that tell it
/// from the limit: a 99th percentile of 150.0000004 m/s read "150 m/s" at
/// six digits, a value that looks legal beside a limit of 150 m/s.
fn apart(v: f64, limit: f64) -> String {
    super::number::numbers_apart(v, &[limit]).0
}

/// `x` to three significant digits, as a message shows a number.
fn three(x: f64) -> Num {
    Num(significant(x, 3).parse().unwrap_or(x))
}

/// The sample rate of a time step read as seconds.
fn rate(step: f64) -> String {
    format!("{} Hz if in seconds", three(1.0 / step))
}

/// The question a step of that size raises: milliseconds, when read so
/// it is a rate a handling run is logged at (a step of 1 to 200: 1 kHz to
/// 5 Hz; a step of 0.2 to 1 is a log of 1 to 5 Hz, which read in ms would
/// be 1 to 5 kHz, so no unit is suggested), else microseconds, when read
/// so it is one (a step of 200 to 200 000: 5 Hz to 5 kHz; 10 000 µs is
/// 100 Hz).
fn in_ms(step: f64) -> String {
    if (1.0..=200.0).contains(&step) {
        format!(
            "; is `t` in milliseconds ({} ms: {} Hz)? divide it by 1000",
            Num(step),
            three(1000.0 / step)
        )
    } else if (200.0..=200_000.0).contains(&step) {
        format!(
            "; is `t` in microseconds ({} µs: {} Hz)? divide it by 1000000",
            Num(step),
            three(1e6 / step)
        )
    } else {
        String::new()
    }
}

/// A unit a logger writes a speed in besides m/s.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpeedUnit {
    /// Kilometres per hour.
    Kmh,
    /// Miles per hour (US and UK loggers, the TTC rig's own channels).
    Mph,
}

impl SpeedUnit {
    /// Its name as a user writes it.
    pub fn name(self) -> &'static str {
        match self {
            SpeedUnit::Kmh => "km/h",
            SpeedUnit::Mph => "mph",
        }
    }
    /// The unit's value of 1 m/s (the divisor back to m/s).
    pub fn per_m_s(self) -> f64 {
        match self {
            SpeedUnit::Kmh => 3.6,
            SpeedUnit::Mph => 2.23694,
        }
    }
}
