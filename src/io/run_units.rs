//! The unit checks of a measured run ([`super::read_run`]): a channel whose
//! size no car reaches in `FORMATS.md`'s unit is refused at its column and
//! first such row, naming the unit it is likely in ([`UnitSlip`]). Judged
//! on the 99th percentile of a channel's size, so that a logger's spike
//! (repaired later by the cleaning) does not refuse a file, and on the
//! median time step.

use super::columns::Columns;
use crate::error::{DeclaredBy, InputError, SpeedUnit, UnitSlip, YawAdvice};
use crate::measured::clean::{median, quantile};
use std::path::Path;

/// The largest yaw rate of a car, rad/s (172°/s; a car spinning out turns
/// at about 2 rad/s): a step steer's 10°/s read as rad/s is beyond it.
pub const MAX_YAW_RATE: f64 = 3.0;

/// The largest lateral acceleration of a car, m/s² (3.1 g; a racing car
/// with downforce reaches about 4 g only for moments).
pub const MAX_AY: f64 = 30.0;

/// The coarsest median time step of a handling run, s (5 Hz: a yaw
/// response takes 0.1–0.3 s): 10 ms written as 10 is far beyond it.
pub const MAX_TIME_STEP: f64 = 0.2;

/// The highest forward speed of a car on a handling run, m/s (540 km/h;
/// the fastest road cars reach 140 m/s): 200 km/h written as km/h is
/// beyond it.
pub const MAX_SPEED: f64 = 150.0;

/// The largest body roll, road bank or sideslip a run in radians holds,
/// rad (1 rad, 57°: steeper than any banking, far beyond any car's body
/// roll, and a sideslip past which a car is spinning, not driven); a
/// larger 99th percentile is a column in degrees.
pub const MAX_ROLL_OR_BANK: f64 = 1.0;

/// The largest body roll a run in radians holds, rad (0.2 rad, 11.5°): a
/// car on its tyres rolls about 2–7° at its grip limit (roll gradients of
/// 1–3°/g on cars, up to about 7° for a tall SUV; Gillespie 1992, ch. 8),
/// and past about 10° its inner wheels lift. [`MAX_ROLL_OR_BANK`]'s 57°
/// let a roll logged in degrees under 57 (a car rolling 3°: 0–3) pass as
/// radians and level `ay` by a roll twenty times too large.
pub const MAX_ROLL: f64 = 0.2;

/// A speed no logger's glitch of a car reads, m/s (30 times the land
/// speed record): one such sample refuses the run, where a spike below it
/// is repaired later by the cleaning.
const ABSURD_SPEED: f64 = 1e4;

/// The fewest samples whose median step judges a logger's rate.
const RATE_SAMPLES: usize = 10;

/// A turning sample's least |speed × yaw_rate|, m/s²: well above the
/// noise of a lateral accelerometer (0.1–0.3 m/s²).
const TURNING: f64 = 1.0;

/// Turning samples needed to judge `ay` against speed × yaw rate.
const TURNING_SAMPLES: usize = 50;

/// The band of ay/(speed·yaw_rate) of `ay` in g (1/9.81 = 0.10, within a
/// factor of 2), where a car's is near 1 on a flat road.
const AY_IN_G: (f64, f64) = (0.05, 0.2);

/// The band of ay/(speed·yaw_rate) of `ay` in ft/s² (3.281, within a
/// factor of 1.25), where a car's is near 1 on a flat road: a bank or a
/// sideslip rate moves single samples, not 80 % of them, this far.
const AY_IN_FEET: (f64, f64) = (2.6, 4.1);

/// The band of ay/(speed·yaw_rate) of a speed in km/h (1/3.6 = 0.28,
/// within a factor of 1.4), where a car's is near 1 on a flat road.
const SPEED_IN_KMH: (f64, f64) = (0.2, 0.4);

/// The band of ay/(speed·yaw_rate) of a speed in mph (1/2.237 = 0.447,
/// from the km/h band's top to the whole-run slope's 0.54, `run_slope.rs`
/// and `FORMATS.md`).
const SPEED_IN_MPH: (f64, f64) = (0.4, 0.54);

/// The band of ay/(speed·yaw_rate) of a yaw rate in deg/s (π/180 =
/// 0.0175, within a factor of 1.7), where a car's is near 1 on a flat road.
const YAW_IN_DEG: (f64, f64) = (0.01, 0.03);

/// The share of the turning samples inside [`AY_IN_G`] (or
/// [`SPEED_IN_KMH`], [`YAW_IN_DEG`]) that says the unit: on a banked oval the ratio
/// scatters (its median can lie in the band, 0.13 on the synthetic oval,
/// with 6 % of the samples in it), in g it holds.
const AY_IN_G_SHARE: f64 = 0.8;

/// The slowest sample judged for `ay`, m/s.
const MOVING: f64 = 5.0;

/// The 99th percentile of |x| and the first row beyond `limit`, when that
/// percentile is beyond it.
pub(super) fn beyond(x: &[f64], limit: f64) -> Option<(usize, f64)> {
    let p99 = p99(x)?;
    (p99 > limit).then(|| (x.iter().position(|v| v.abs() > limit).unwrap_or(0), p99))
}

/// The 99th percentile of |x| (None: no samples).
fn p99(x: &[f64]) -> Option<f64> {
    let mut size: Vec<f64> = x.iter().map(|v| v.abs()).collect();
    size.sort_by(f64::total_cmp);
    quantile(&size, 0.99)
}

/// Refuses a yaw rate beyond [`MAX_YAW_RATE`] over more than 1 % of the
/// run (deg/s).
pub(super) fn check_yaw_rate(
    path: &Path,
    c: &Columns,
    r: &[f64],
    by: DeclaredBy,
) -> Result<(), InputError> {
    match beyond(r, MAX_YAW_RATE) {
        Some((i, p99)) => Err(c.error_at(
            path,
            i,
            "yaw_rate",
            UnitSlip::YawRate {
                value: r[i],
                p99,
                limit: MAX_YAW_RATE,
                by: YawAdvice::Declare(by),
            }
            .into(),
        )),
        None => Ok(()),
    }
}

/// Refuses an `ay` beyond [`MAX_AY`] over more than 1 % of the run, or
/// whose ratio to speed × yaw rate over the turning samples (at least 50 at
/// 5 m/s or more with |speed × yaw_rate| ≥ 1 m/s²) says a unit: `ay` in g
/// ([`AY_IN_G`]), a speed in km/h ([`SPEED_IN_KMH`]) or a yaw rate in
/// deg/s ([`YAW_IN_DEG`]), located at the first turning sample.
pub(super) fn check_ay(
    path: &Path,
    c: &Columns,
    lateral: &super::run_turning::Channels,
    by: DeclaredBy,
) -> Result<(), InputError> {
    let (speed, r, ay) = (lateral.speed, lateral.r, lateral.ay);
    if let Some((i, p99)) = beyond(ay, MAX_AY) {
        let slip = UnitSlip::AyTooLarge {
            value: ay[i],
            p99,
            limit: MAX_AY,
        };
        return Err(c.error_at(path, i, "ay", slip.into()));
    }
    // Against u·(r + β̇), or u·r where the yaw rate holds: a sine's β̇
    // moves the ratio by half (`run_turning.rs`).
    let (turning, mut q) = super::run_turning::ratios(lateral, MOVING, TURNING);
    if turning.len() < TURNING_SAMPLES {
        return Ok(());
    }
    let bands = RatioBands::of(&q);
    if !bands.any() {
        return Ok(());
    }
    // A ratio in a unit's band that a constant explains (a gyro's zero
    // offset over a step) names no unit: `run_offset.rs`.
    let moving = (0..ay.len()).filter(|&i| speed[i] >= MOVING);
    let pairs = moving.map(|i| (speed[i] * r[i], ay[i]));
    if super::run_offset::an_offset(pairs, super::run_slope::SI_RANGE) {
        return Ok(());
    }
    let m = median(&mut q);
    let i = turning[0];
    let (column, slip) = bands.slip((i, m, turning.len()), speed, r, ay, by);
    Err(c.error_at(path, i, column, slip.into()))
}

/// Which unit's band the ratios `ay/(speed·yaw_rate)` of the turning
/// samples fall in ([`AY_IN_G_SHARE`] of them at least).
struct RatioBands {
    in_g: bool,
    in_deg: bool,
    in_feet: bool,
    speed_unit: Option<SpeedUnit>,
    too_small: bool,
}

impl RatioBands {
    fn of(q: &[f64]) -> Self {
        let holds = |(lo, hi): (f64, f64)| {
            let inside = q.iter().filter(|v| (lo..=hi).contains(*v)).count();
            inside as f64 >= AY_IN_G_SHARE * q.len() as f64
        };
        let speed_unit = if holds(SPEED_IN_KMH) {
            Some(SpeedUnit::Kmh)
        } else if holds(SPEED_IN_MPH) {
            Some(SpeedUnit::Mph)
        } else {
            None
        };
        RatioBands {
            in_g: holds(AY_IN_G),
            in_deg: holds(YAW_IN_DEG),
            in_feet: holds(AY_IN_FEET),
            speed_unit,
            too_small: holds(YAW_TOO_SMALL),
        }
    }

    /// Whether any band holds.
    fn any(&self) -> bool {
        self.in_g || self.in_feet || self.speed_unit.is_some() || self.in_deg || self.too_small
    }

    /// The column at fault and its unit slip, located at the first turning
    /// sample `i`, with the ratios' median `m` over `samples` samples: the
    /// yaw rate's bands first, then the speed's, then ay's.
    fn slip(
        &self,
        (i, m, samples): (usize, f64, usize),
        speed: &[f64],
        r: &[f64],
        ay: &[f64],
        by: DeclaredBy,
    ) -> (&'static str, UnitSlip) {
        if self.too_small {
            // No logger writes a yaw rate 57 times too small: a yaw rate in
            // rad/s declared in deg/s and converted.
            let slip = UnitSlip::YawRateTooSmall {
                value: r[i],
                median: m,
                samples,
            };
            return ("yaw_rate", slip);
        }
        if self.in_deg {
            // Below `MAX_YAW_RATE` in deg/s (a gentle run): ay says it.
            let slip = UnitSlip::YawRateInDegPerS {
                value: r[i],
                median: m,
                samples,
                turning: TURNING,
                by: YawAdvice::Declare(by),
            };
            return ("yaw_rate", slip);
        }
        if let Some(unit) = self.speed_unit {
            // ay and yaw rate agree with each other's units (checked above and
            // by their sizes); speed × yaw rate 3.6 (2.237) times ay is a speed
            // in km/h (mph) whose values stay below any car's top speed in m/s.
            let slip = UnitSlip::SpeedPerHour {
                unit,
                value: speed[i],
                median: m,
                samples,
                turning: TURNING,
            };
            return ("speed", slip);
        }
        if self.in_feet {
            let slip = UnitSlip::AyInFeet {
                value: ay[i],
                expected: speed[i] * r[i],
                median: m,
                samples,
                turning: TURNING,
            };
            return ("ay", slip);
        }
        let slip = UnitSlip::AyInG {
            value: ay[i],
            expected: speed[i] * r[i],
            median: m,
            samples,
            turning: TURNING,
        };
        ("ay", slip)
    }
}

/// The largest sideslip of a car turning at yaw rate `r` and speed `u`
/// that this check allows for, rad: the geometry of the turn (`b·r/u`, with
/// 3 m for any car's `b`) and the rear tyres' slip (0.1 rad per g of
/// `u·r`, a rear cornering stiffness of 10 per unit load, softer than any
/// road tyre's 15–25).
fn sideslip_bound(u: f64, r: f64) -> f64 {
    3.0 * r.abs() / u + 0.1 * (u * r).abs() / crate::constants::G
}

/// The turning samples of a run (as [`check_ay`]'s, with a finite `beta`)
/// and their |β| over [`sideslip_bound`]; None below [`TURNING_SAMPLES`].
fn sideslip_ratios(speed: &[f64], r: &[f64], beta: &[f64]) -> Option<(Vec<usize>, Vec<f64>)> {
    let turning: Vec<usize> = (0..beta.len())
        .filter(|&i| speed[i] >= MOVING && (speed[i] * r[i]).abs() >= TURNING)
        .filter(|&i| beta[i].is_finite())
        .collect();
    if turning.len() < TURNING_SAMPLES {
        return None;
    }
    let ratio = turning
        .iter()
        .map(|&i| beta[i].abs() / sideslip_bound(speed[i], r[i]))
        .collect();
    Some((turning, ratio))
}

/// Beyond this median of |β| over [`sideslip_bound`] the sideslip is in
/// degrees: a car's is 0.08–0.5 of the bound (the synthetic programme, the
/// sedan analogue, the Putnam log), in degrees 4.5–27; a car drifting at
/// 0.5 rad on a 20 m radius at 1 g reaches 2, and the sedan's 0.3 rad step
/// at 80 km/h, sliding, 3.1.
const BETA_IN_DEGREES: f64 = 4.0;

/// Below this median of |β| over [`sideslip_bound`] a `beta` declared in
/// degrees was in radians: converted, a car's 0.08–0.5 becomes 0.0014–0.009.
const BETA_DECLARED_IN_RADIANS: f64 = 0.04;

/// The band of ay/(speed·yaw_rate) of a yaw rate 57 times too small (a
/// yaw rate in rad/s declared in deg/s and converted), where a car's is
/// near 1 on a flat road.
const YAW_TOO_SMALL: (f64, f64) = (30.0, 110.0);

/// Refuses a `beta` whose median over the turning samples (as
/// [`check_ay`]'s) is beyond [`BETA_IN_DEGREES`] of [`sideslip_bound`]: a
/// sideslip in degrees that stays below 1 rad, which
/// [`check_roll_or_bank`]'s size check leaves.
pub(super) fn check_beta(
    path: &Path,
    c: &Columns,
    speed: &[f64],
    r: &[f64],
    beta: &[f64],
) -> Result<(), InputError> {
    let Some((turning, ratio)) = sideslip_ratios(speed, r, beta) else {
        return Ok(());
    };
    let m = median(&mut ratio.clone());
    if m <= BETA_IN_DEGREES {
        return Ok(());
    }
    // The first turning sample that breaks the rule the message states.
    let k = ratio.iter().position(|q| *q > BETA_IN_DEGREES).unwrap_or(0);
    let i = turning[k];
    let slip = UnitSlip::BetaInDegrees {
        value: beta[i],
        bound: sideslip_bound(speed[i], r[i]),
        median: m,
        samples: turning.len(),
    };
    Err(c.error_at(path, i, "beta", slip.into()))
}

/// Refuses a `beta` declared in degrees (and converted) whose median over
/// the turning samples is below [`BETA_DECLARED_IN_RADIANS`] of
/// [`sideslip_bound`]: it was in radians, and the conversion made it 57
/// times too small.
pub(super) fn check_beta_declared(
    path: &Path,
    c: &Columns,
    speed: &[f64],
    r: &[f64],
    beta: &[f64],
) -> Result<(), InputError> {
    let Some((turning, mut q)) = sideslip_ratios(speed, r, beta) else {
        return Ok(());
    };
    let m = median(&mut q);
    if m >= BETA_DECLARED_IN_RADIANS {
        return Ok(());
    }
    let i = turning[0];
    let slip = UnitSlip::BetaDeclaredInDegrees {
        value: beta[i].to_degrees(),
        median: m,
        samples: turning.len(),
    };
    Err(c.error_at(path, i, "beta", slip.into()))
}

/// Refuses a median time step above [`MAX_TIME_STEP`] (a time in ms),
/// judged on runs of at least 10 samples, at the first step of that size.
pub(super) fn check_time_step(path: &Path, c: &Columns, t: &[f64]) -> Result<(), InputError> {
    if t.len() < RATE_SAMPLES {
        return Ok(());
    }
    let steps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let mut sorted = steps.clone();
    let step = median(&mut sorted);
    // A 5 Hz log's steps read 0.2 s to the rounding of its times (1.8 −
    // 1.6 = 0.20000000000000018): the limit is accepted to a part in 10⁶.
    if step <= MAX_TIME_STEP * (1.0 + 1e-6) {
        return Ok(());
    }
    let i = steps.iter().position(|s| *s >= step).map_or(1, |k| k + 1);
    let slip = UnitSlip::TimeStep {
        step,
        limit: MAX_TIME_STEP,
    };
    Err(c.error_at(path, i, "t", slip.into()))
}

/// Refuses a speed beyond [`MAX_SPEED`] over more than 1 % of the run (a
/// speed in km/h), or any sample beyond any vehicle's (a value such as
/// 1e308 that no arithmetic on the run survives).
pub(super) fn check_speed(path: &Path, c: &Columns, u: &[f64]) -> Result<(), InputError> {
    let found = match u.iter().position(|v| v.abs() > ABSURD_SPEED) {
        Some(i) => Some((i, p99(u).unwrap_or(0.0))),
        None => beyond(u, MAX_SPEED),
    };
    // A car reverses slowly and briefly: a run whose median is backwards
    // at speed is a forward speed logged in another sign convention.
    let mut sorted = u.to_vec();
    let backwards = !u.is_empty() && median(&mut sorted) < -MOVING;
    if found.is_none() && backwards {
        let i = u.iter().position(|v| *v < -MOVING).unwrap_or(0);
        let slip = UnitSlip::SpeedBackwards {
            value: u[i],
            median: median(&mut sorted),
        };
        return Err(c.error_at(path, i, "speed", slip.into()));
    }
    match found {
        Some((i, p99)) => Err(c.error_at(
            path,
            i,
            "speed",
            UnitSlip::SpeedBeyondAnyCar {
                value: u[i],
                p99,
                limit: MAX_SPEED,
            }
            .into(),
        )),
        None => Ok(()),
    }
}

/// Refuses a roll, bank or sideslip column whose 99th percentile of
/// |value| is beyond [`MAX_ROLL`] (roll) or [`MAX_ROLL_OR_BANK`] (bank,
/// sideslip): in degrees, it would read as a car on its side.
pub(super) fn check_roll_or_bank(
    path: &Path,
    c: &Columns,
    column: &'static str,
    v: &[f64],
) -> Result<(), InputError> {
    let limit = match column {
        "roll" => MAX_ROLL,
        _ => MAX_ROLL_OR_BANK,
    };
    let Some((i, p99)) = beyond(v, limit) else {
        return Ok(());
    };
    let slip = UnitSlip::RollInDegrees {
        column,
        value: v[i],
        p99,
        limit,
    };
    Err(c.error_at(path, i, column, slip.into()))
}

/// The stretch over which `ax` is integrated against the speed's change, s
/// (long against an accelerometer's noise and a speed's quantisation).
const AX_SPAN: f64 = 0.5;

/// The least speed change over a stretch judged, m/s (|ax| of about
/// 1 m/s² for [`AX_SPAN`]: well above the noise of either channel).
const AX_CHANGE: f64 = 0.5;

/// Refuses a speed whose change is 3.6 (2.237) times what `ax` integrates
/// to over the same stretches: in km/h (mph). The run's own check where it
/// has no `ay` to judge the speed by ([`check_ay`]): over the stretches of
/// [`AX_SPAN`] s (at least 50, from every sample, at 5 m/s or more) where
/// the speed changes by [`AX_CHANGE`] or more, the ratio ∫ax dt / Δspeed is
/// near 1 for a speed in m/s, and in the bands of [`check_ay`] for one per
/// hour.
pub(super) fn check_speed_by_ax(
    path: &Path,
    c: &Columns,
    t: &[f64],
    speed: &[f64],
    ax: &[f64],
) -> Result<(), InputError> {
    let n = t.len();
    let mut q = Vec::new();
    let mut first = None;
    let mut k = 0;
    for i in 0..n {
        while k < n && t[k] - t[i] < AX_SPAN {
            k += 1;
        }
        if k >= n {
            break;
        }
        let du = speed[k] - speed[i];
        if speed[i] < MOVING || du.abs() < AX_CHANGE {
            continue;
        }
        let integral: f64 = (i..k)
            .map(|j| 0.5 * (ax[j] + ax[j + 1]) * (t[j + 1] - t[j]))
            .sum();
        first.get_or_insert(i);
        q.push(integral / du);
    }
    if q.len() < TURNING_SAMPLES {
        return Ok(());
    }
    let holds = |(lo, hi): (f64, f64)| {
        let inside = q.iter().filter(|v| (lo..=hi).contains(*v)).count();
        inside as f64 >= AY_IN_G_SHARE * q.len() as f64
    };
    let unit = if holds(SPEED_IN_KMH) {
        SpeedUnit::Kmh
    } else if holds(SPEED_IN_MPH) {
        SpeedUnit::Mph
    } else {
        return Ok(());
    };
    let i = first.unwrap_or(0);
    let stretches = q.len();
    let slip = UnitSlip::SpeedPerHourByAx {
        unit,
        value: speed[i],
        median: median(&mut q),
        stretches,
        span: AX_SPAN,
        change: AX_CHANGE,
    };
    Err(c.error_at(path, i, "speed", slip.into()))
}

/// A run with neither accelerometer channel: its speed's unit is
/// judged by `ay` against speed × yaw rate, or by `ax` against the speed's
/// change, and this one offers neither (said by `simulate`'s replay,
/// `metrics` and `diagnose`), so a speed in km/h or mph below
/// any car's top speed in m/s passes unseen. Said with the speeds read.
///
/// An `ay` that holds one value over the whole run (a dead sensor) checks
/// nothing either, and is said as present but dead, not as absent.
pub fn unchecked_speed_unit(run: &crate::measured::MeasuredRun) -> Option<String> {
    let dead_ay = run.ay.as_deref().and_then(crate::measured::one_value);
    if (run.ay.is_some() && dead_ay.is_none()) || run.ax.is_some() || run.speed.is_empty() {
        return None;
    }
    let lacks = match dead_ay {
        Some(v) => format!(
            "has an `ay` column, but it holds one value ({}) over the whole run, a dead sensor that cannot be judged against speed × yaw_rate, and no `ax` (judged against the speed's change)",
            crate::error::Num(v)
        ),
        None => "has neither `ay` (judged against speed × yaw_rate) nor `ax` (against the speed's change)".into(),
    };
    let mut u = run.speed.clone();
    u.sort_by(f64::total_cmp);
    let median = u[u.len() / 2];
    Some(format!(
        "the speed's unit could not be checked: {} {lacks}; read as m/s, its speed runs {}–{} m/s with a median of {} m/s ({} km/h); a column in km/h or mph would read 3.6 or 2.24 times too fast here",
        run.path.display(),
        crate::format::significant(u[0], 3),
        crate::format::significant(u[u.len() - 1], 3),
        crate::format::significant(median, 3),
        crate::format::significant(3.6 * median, 3),
    ))
}
