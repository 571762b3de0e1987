//! The run-wide slope check of a measured run's lateral channels
//! ([`super::read_run`]): `ay` regressed (through the origin) on the
//! kinematic lateral acceleration
//! `a = u·r + d(u·β)/dt + g·sin(bank)` (ISO 8855, `FORMATS.md` signs;
//! the β term only where the run has `beta`, the bank's only where it has
//! `bank`) over the means of consecutive [`BIN_SECONDS`] s stretches.
//! The per-sample ratio `ay/(u·r)` of [`super::run_units`] scatters on a
//! transient run (a step, a sine, a sweep: `a_y = u·(r + β̇) + u̇·β`), and
//! the channels lag each other by a sample or two; the means suppress the
//! noise and the lag, the β term the transients, and one slope over the
//! whole turning run stays near 1 where single samples do not.
//!
//! Bands, from the physics. A run in SI units has a slope near 1 less
//! what the regressor leaves out: an unmeasured road bank (`g·sin θ`
//! against `u·r`: a 10° bank at 0.8 g takes 0.2 off, a steeper one on a
//! slow car more) and the accelerometer's tilt with the body's roll
//! (`g·φ`, 5° at 1 g adds 0.09); [`SI_RANGE`] (0.6–1.6) holds those. A
//! unit slip scales the slope by its factor, and each factor's band
//! reaches a factor of 1.25 either side (1.2 for mph, whose band would
//! otherwise meet km/h's), clear of [`SI_RANGE`]:
//! - speed in km/h: 1/3.6 = 0.278, [0.22, 0.35];
//! - speed in mph: 1/2.237 = 0.447, [0.37, 0.54];
//! - `ay` in g: 1/9.81 = 0.102, [0.08, 0.13];
//! - `ay` in ft/s²: 3.281, [2.6, 4.1];
//! - yaw rate in deg/s: π/180 = 0.0175, [0.014, 0.022];
//! - `ay` and `yaw_rate` swapped: the slope is `1/u²` (0.0006–0.01 at
//!   10–40 m/s) and `yaw_rate` regressed on the regressor with `ay` read
//!   as the yaw rate has a slope in [`SI_RANGE`] with R² ≥ [`MIN_R2`]:
//!   told by that second fit, not a band.
//!
//! Not judged (the run passes): fewer than [`MIN_BINS`] turning means (at
//! [`MOVING`] m/s or more, `|mean u·r|` ≥ [`TURNING`] m/s²), or a fit
//! whose R² is below [`MIN_R2`] (the channels disagree by more than a
//! factor: a dead sensor, another axis; the cleaning and the diagnosis
//! judge those). A slope outside every band (0.35–0.37, 0.54–0.6, …) is
//! not a unit and is left to them too.
//!
//! The means themselves ([`stretches`]) are the ones every lateral check
//! of a run reads: this slope, the sign of `ay` (`run_ay_sign.rs`) and the
//! unit of `bank` (`run_bank.rs`).

use super::columns::Columns;
use crate::constants::G;
use crate::error::{BetaInPercent, InputError, LateralSlope, SlopeUnit, UnitSlip};
use std::path::Path;

/// Length of the stretches averaged, s: long against the lag between
/// channels (a sample or two) and the sensors' noise, short against a
/// corner.
pub const BIN_SECONDS: f64 = 0.5;

/// The slowest mean speed of a turning stretch, m/s.
pub const MOVING: f64 = 5.0;

/// The least |mean u·r| of a turning stretch, m/s²: well above the noise
/// of a lateral accelerometer's mean.
pub const TURNING: f64 = 1.0;

/// The fewest turning stretches judged (3 s of turning).
pub const MIN_BINS: usize = 6;

/// The least R² (through the origin) of a fit that is judged.
pub const MIN_R2: f64 = 0.8;

/// The slopes of a run in SI units.
pub const SI_RANGE: (f64, f64) = (0.6, 1.6);

/// The units the slope names, with their bands.
const BANDS: [(SlopeUnit, f64, f64); 5] = [
    (SlopeUnit::SpeedKmh, 0.22, 0.35),
    (SlopeUnit::SpeedMph, 0.37, 0.54),
    (SlopeUnit::AyInG, 0.08, 0.13),
    (SlopeUnit::AyInFeet, 2.6, 4.1),
    (SlopeUnit::YawRateInDegrees, 0.014, 0.022),
];

/// The swapped fit's slopes that say a swap.
const SWAPPED: (f64, f64) = SI_RANGE;

/// The channels of a run the check reads (SI as `FORMATS.md` asks).
pub(super) struct Lateral<'a> {
    /// Time, s.
    pub t: &'a [f64],
    /// Forward speed, m/s.
    pub speed: &'a [f64],
    /// Road-wheel steer, rad.
    pub steer: &'a [f64],
    /// Yaw rate, rad/s.
    pub yaw_rate: &'a [f64],
    /// Lateral acceleration, m/s².
    pub ay: &'a [f64],
    /// Sideslip, rad.
    pub beta: Option<&'a [f64]>,
    /// Road bank, rad.
    pub bank: Option<&'a [f64]>,
    /// Its [`stretches`], made once for the checks that read them (`ay`'s
    /// sign, the bank's unit, the slope).
    pub means: std::cell::OnceCell<Vec<Stretch>>,
}

/// One [`BIN_SECONDS`] s stretch's means, the one averaging every
/// lateral check of a run reads ([`stretches`]): NaN samples are left out
/// of each mean.
pub(super) struct Stretch {
    /// The stretch's first sample.
    pub first: usize,
    /// Forward speed, m/s.
    pub speed: f64,
    /// Road-wheel steer, rad.
    pub steer: f64,
    /// speed × yaw rate, m/s².
    pub speed_yaw: f64,
    /// d(u·β)/dt, the change of u·tan β over the stretch over its
    /// duration, m/s²: 0 without `beta`, NaN on a one-sample stretch.
    pub v_dot: f64,
    /// Lateral acceleration as read, m/s².
    pub ay: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// speed × `ay` as read (`ay` taken for the yaw rate), m²/s³.
    pub speed_ay: f64,
    /// Road bank as read, rad (NaN without `bank`).
    pub bank: f64,
    /// g·sin(bank) with the bank read in radians, m/s² (0 without `bank`).
    pub bank_term: f64,
}

impl Stretch {
    /// Whether the car turns at speed here: [`MOVING`] m/s or more and
    /// |u·r| at least [`TURNING`] m/s².
    pub fn turning(&self) -> bool {
        self.speed >= MOVING && self.speed_yaw.abs() >= TURNING
    }
}

/// The run's consecutive [`BIN_SECONDS`] s stretches, parked and moving
/// alike, each with its means: made on the first call, kept on `c`.
pub(super) fn stretches<'c>(c: &'c Lateral) -> &'c [Stretch] {
    c.means.get_or_init(|| stretch_means(c))
}

/// [`stretches`], made.
fn stretch_means(c: &Lateral) -> Vec<Stretch> {
    let n = c.t.len();
    let v: Option<Vec<f64>> = c
        .beta
        .map(|b| b.iter().zip(c.speed).map(|(b, u)| u * b.tan()).collect());
    let mut out = Vec::new();
    let mut i = 0;
    while i < n {
        let mut j = i;
        while j < n && c.t[j] - c.t[i] < BIN_SECONDS {
            j += 1;
        }
        let mean = |f: &dyn Fn(usize) -> f64| {
            let kept: Vec<f64> = (i..j).map(f).filter(|x| x.is_finite()).collect();
            kept.iter().sum::<f64>() / kept.len() as f64
        };
        // The mean of d(u·β)/dt over the stretch: its change over it.
        let v_dot = match &v {
            Some(v) if j - i >= 2 => (v[j - 1] - v[i]) / (c.t[j - 1] - c.t[i]),
            Some(_) => f64::NAN,
            None => 0.0,
        };
        out.push(Stretch {
            first: i,
            speed: mean(&|k| c.speed[k]),
            steer: mean(&|k| c.steer[k]),
            speed_yaw: mean(&|k| c.speed[k] * c.yaw_rate[k]),
            v_dot,
            ay: mean(&|k| c.ay[k]),
            yaw_rate: mean(&|k| c.yaw_rate[k]),
            speed_ay: mean(&|k| c.speed[k] * c.ay[k]),
            bank: c.bank.map_or(f64::NAN, |b| mean(&|k| b[k])),
            bank_term: c.bank.map_or(0.0, |b| mean(&|k| G * b[k].sin())),
        });
        i = j;
    }
    out
}

/// One turning stretch's means for the slope: the kinematic lateral
/// acceleration, `ay`, the yaw rate, the kinematic lateral acceleration
/// with `ay` read as the yaw rate, and its first sample.
struct Bin {
    kinematic: f64,
    ay: f64,
    yaw_rate: f64,
    speed_ay: f64,
    first: usize,
}

/// A fit through the origin of `y` on `x`: slope and R².
pub(super) fn fit(pairs: impl Iterator<Item = (f64, f64)>) -> (f64, f64) {
    let (mut xx, mut xy, mut yy, mut pts) = (0.0, 0.0, 0.0, Vec::new());
    for (x, y) in pairs {
        xx += x * x;
        xy += x * y;
        yy += y * y;
        pts.push((x, y));
    }
    let k = xy / xx;
    let sse: f64 = pts.iter().map(|(x, y)| (y - k * x).powi(2)).sum();
    (k, 1.0 - sse / yy)
}

/// The turning stretches' means for the slope.
fn bins(c: &Lateral) -> Vec<Bin> {
    stretches(c)
        .iter()
        .filter(|s| s.turning())
        .map(|s| Bin {
            kinematic: s.speed_yaw + s.v_dot + s.bank_term,
            ay: s.ay,
            yaw_rate: s.yaw_rate,
            speed_ay: s.speed_ay + s.v_dot + s.bank_term,
            first: s.first,
        })
        .filter(|b| b.kinematic.is_finite() && b.ay.is_finite() && b.speed_ay.is_finite())
        .collect()
}

/// The slope's verdict, None where it is not judged or names no unit.
pub(super) fn slope_slip(c: &Lateral) -> Option<(usize, LateralSlope)> {
    let bins = bins(c);
    if bins.len() < MIN_BINS {
        return None;
    }
    let (slope, r2) = fit(bins.iter().map(|b| (b.kinematic, b.ay)));
    let (swapped, swapped_r2) = fit(bins.iter().map(|b| (b.speed_ay, b.yaw_rate)));
    let swap =
        slope < BANDS[4].1 && swapped_r2 >= MIN_R2 && (SWAPPED.0..=SWAPPED.1).contains(&swapped);
    // Every moving stretch, straight ones too: a constant shift of `ay`
    // against the regressor is an offset, not a unit (`run_offset.rs`).
    let moving = stretches(c).iter().filter(|s| s.speed >= MOVING);
    let offset = super::run_offset::an_offset(
        moving.map(|s| (s.speed_yaw + s.v_dot + s.bank_term, s.ay)),
        SI_RANGE,
    );
    let unit = if swap {
        SlopeUnit::Swapped
    } else if r2 < MIN_R2 || offset {
        return None;
    } else {
        BANDS
            .iter()
            .find(|(_, lo, hi)| (*lo..=*hi).contains(&slope))?
            .0
    };
    let slip = LateralSlope {
        unit,
        slope,
        r2: if swap { swapped_r2 } else { r2 },
        bins: bins.len(),
        with_beta: c.beta.is_some(),
        with_bank: c.bank.is_some(),
        range: SI_RANGE,
        swapped,
    };
    Some((bins[0].first, slip))
}

// The refusal that names the unit is `run_bank::check_slope_reading`:
// a bank of the other sign is tried first.

/// The least sideslip change a pair of means judged for
/// [`beta_factor`] carries, rad (0.3°: above a sideslip sensor's noise
/// over a mean, and what a step steer's transient moves).
const BETA_CHANGE: f64 = 0.003;

/// The factor a `beta` column is of the sideslip its run's kinematics
/// gives, and the fit's R²: the change of `beta`'s half-second means
/// regressed (through the origin) on `∫(ay/u − r) dt` between them (β̇ =
/// a_y/u − r on a flat road, ISO 8855), over the pairs of moving means
/// whose kinematic change passes [`BETA_CHANGE`]. Near 1 in radians, 57.3
/// in degrees, 100 in percent of a radian; None with fewer than
/// [`MIN_BINS`] such pairs.
pub(super) fn beta_factor(c: &Lateral, beta: &[f64]) -> Option<(f64, f64)> {
    let n = c.t.len();
    let mut means: Vec<(f64, f64, f64)> = Vec::new();
    let mut i = 0;
    while i < n {
        let mut j = i;
        while j < n && c.t[j] - c.t[i] < BIN_SECONDS {
            j += 1;
        }
        let m = (j - i) as f64;
        let u = c.speed[i..j].iter().sum::<f64>() / m;
        let rate: f64 = (i..j)
            .map(|k| c.ay[k] / c.speed[k] - c.yaw_rate[k])
            .sum::<f64>()
            / m;
        let b = beta[i..j].iter().sum::<f64>() / m;
        let t = c.t[i..j].iter().sum::<f64>() / m;
        let moving = c.speed[i..j].iter().all(|v| *v >= MOVING);
        means.push(
            if moving && u.is_finite() && b.is_finite() && rate.is_finite() {
                (t, rate, b)
            } else {
                (t, f64::NAN, f64::NAN)
            },
        );
        i = j;
    }
    let pairs: Vec<(f64, f64)> = means
        .windows(2)
        .map(|w| (0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0), w[1].2 - w[0].2))
        .filter(|(x, y)| x.is_finite() && y.is_finite() && x.abs() >= BETA_CHANGE)
        .collect();
    (pairs.len() >= BETA_PAIRS).then(|| fit(pairs.into_iter()))
}

/// The fewest pairs of means [`beta_factor`] fits: a step steer's
/// sideslip moves across one or two of them.
const BETA_PAIRS: usize = 2;

/// The factors of [`beta_factor`] that say percent of a radian (100×;
/// it reads 97–121× on synth's steps in percent, 55–69× in degrees).
const BETA_IN_PERCENT: (f64, f64) = (80.0, 160.0);

/// The least R² of [`beta_factor`]'s fit that is judged.
const BETA_R2: f64 = 0.7;

/// Refuses a `beta` in percent of a radian ([`BETA_IN_PERCENT`]), at the
/// first moving sample; degrees are named by `run_units`'s checks.
pub(super) fn check_beta_percent(
    path: &Path,
    cols: &Columns,
    c: &Lateral,
    beta: &[f64],
) -> Result<(), InputError> {
    let Some((factor, r2)) = beta_factor(c, beta) else {
        return Ok(());
    };
    if r2 < BETA_R2 || !(BETA_IN_PERCENT.0..=BETA_IN_PERCENT.1).contains(&factor) {
        return Ok(());
    }
    let i = c.speed.iter().position(|u| *u >= MOVING).unwrap_or(0);
    let slip = BetaInPercent {
        value: beta[i],
        factor,
        r2,
    };
    Err(cols.error_at(path, i, "beta", UnitSlip::from(slip).into()))
}
