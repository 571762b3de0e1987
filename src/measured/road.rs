//! The road's geometry under a measured run, from its own channels: the
//! bank from the `bank` column when the run has one, else an estimate from
//! the kinematic mismatch of the lateral channels; the grade from the
//! mismatch of `ax` and the speed's derivative. Reported, not fitted: the
//! diagnosis's `bank_profile` candidate replays the measured bank only.
//!
//! Kinematics (ISO 8855, flat-road 2-DOF terms; `FORMATS.md` signs): a
//! body-fixed accelerometer reads the specific force, so on a road banked
//! by θ (positive: left edge higher) `a_y = u·r + v̇ + g·sin θ`, and on a
//! grade γ (positive: uphill, nose up) `a_x = u̇ + g·sin γ`. Hence the
//! estimates
//! - bank: `sin θ = (a_y − u·r − v̇)/g`, `v̇ = d(u·β)/dt` by central
//!   differences when the run has a `beta` column (measured at the
//!   accelerometer, as an inertial unit gives both, the lever arm's `x·ṙ`
//!   is in both and cancels); without one `v̇` is left out, zero on average
//!   over a corner but not at its entry and exit, where a step steer at
//!   80 km/h reads as degrees of bank for about a second, and the line
//!   says so;
//! - grade: `sin γ = (a_x − u̇)/g`, `u̇` by central differences.
//!
//! Both are smoothed by a centred moving average over
//! [`SMOOTHING_SECONDS`] (the sensors' noise and the `v̇` transients; within
//! half a window of a piece's ends the average is one-sided), and
//! they carry what the kinematics leaves out: the body roll and pitch of an
//! accelerometer that rolls and pitches with the body (about `g·φ` and
//! `g·θ_pitch`, a few tenths of a degree per m/s²), and sensor offsets (an
//! `a_y` offset of 0.1 m/s² reads as 0.6° of bank). The offsets the runs'
//! standstills or straights measured ([`SensorOffsets`]) are removed
//! first, and the line says so: on a flat road an accelerometer mounted
//! with an offset of −0.6 m/s² would otherwise read a bank of −3.5°, and a
//! sideslip offset `b_β` in `d(u·β)/dt` reads `b_β·u̇/g` of bank wherever
//! the car speeds up or brakes (0.01 rad at 3 m/s², 0.2°). A logged body
//! roll has levelled `a_y` before (the diagnosis's reading,
//! [`super::calibration::roll`]): its `g·φ` is then not in the estimate.
//! Masked samples are left out. Units: rad.

use super::clean::quantile;
use super::MeasuredRun;
use crate::constants::G;
use serde::Serialize;

pub use super::road_apart::{BankApart, BySpeed};
pub use super::road_scale::{scale_in_run, ScaleApart, YawScale};

/// An angle in rad as degrees to one decimal, never "-0.0".
fn deg(a: f64) -> String {
    crate::format::fixed(a.to_degrees(), 1)
}

/// Width of the centred moving average of the estimates, s.
pub(crate) const SMOOTHING_SECONDS: f64 = 1.0;

/// Steepest grade an estimate is read as a road's without a caveat, rad:
/// a 10 % grade (5.7°), beyond the 6–8 % that road design allows on
/// main roads and reached on few circuits. An estimate beyond it is more
/// likely what `a_x` and `u̇` disagree on besides the grade: the body's
/// pitch under braking (the accelerometer tilts with it), a lag between
/// the speed's source and `a_x` (a 0.1 s lag in a 1.5 g stop reads as
/// degrees), wheel slip in a wheel-speed signal.
pub const PLAUSIBLE_GRADE: f64 = 0.09967;

/// Steepest bank an estimate is read as a road's, rad: the one limit of
/// every bank ([`crate::constants::STEEPEST_BANK`], 35°; Talladega's 33°
/// is the steepest racing bank). Beyond it, a unit slip or a wrong sign in
/// `a_y`, `u` or `r`; warned of, not used.
pub const PLAUSIBLE_BANK: f64 = crate::constants::STEEPEST_BANK;

/// Where a road angle comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AngleSource {
    /// The run's `bank` column.
    Measured,
    /// The kinematic mismatch of the lateral channels without the
    /// sideslip's rate (`a_y − u·r`: no `beta` column).
    LateralKinematics,
    /// The kinematic mismatch of the lateral channels, `a_y − u·r −
    /// d(u·β)/dt`.
    LateralKinematicsWithSideslip,
    /// The mismatch of `a_x` and the speed's derivative, without the
    /// lateral velocity's `v·r` (no `beta` column).
    LongitudinalKinematics,
    /// The mismatch of `a_x` and the body-axis kinematics, `a_x − u̇ +
    /// u·β·r` (the sideslip at the accelerometer; a sideslip measured
    /// elsewhere moved there).
    LongitudinalKinematicsWithSideslip,
}

impl AngleSource {
    /// In words, for summaries.
    pub fn words(self) -> &'static str {
        match self {
            AngleSource::Measured => "measured",
            AngleSource::LateralKinematics => "estimated from ay − u·r",
            AngleSource::LateralKinematicsWithSideslip => "estimated from ay − u·r − d(u·β)/dt",
            AngleSource::LongitudinalKinematics => "estimated from ax − du/dt",
            AngleSource::LongitudinalKinematicsWithSideslip => "estimated from ax − du/dt + u·β·r",
        }
    }
}

/// A road angle along a run, summarised.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AngleProfile {
    /// Where it comes from.
    pub source: AngleSource,
    /// Mean, rad.
    pub mean: f64,
    /// Least, rad.
    pub min: f64,
    /// Greatest, rad.
    pub max: f64,
    /// 5th percentile, rad.
    pub p05: f64,
    /// Median, rad.
    pub median: f64,
    /// 95th percentile, rad.
    pub p95: f64,
    /// Samples it is taken over.
    pub samples: usize,
}

/// Sensor offsets the calibration measured (standstills, else straights),
/// removed from the channels before the bank is estimated from them; 0
/// where none was measured.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct SensorOffsets {
    /// Lateral accelerometer offset, m/s².
    pub ay: f64,
    /// Yaw-rate offset, rad/s.
    pub yaw_rate: f64,
    /// Sideslip offset, rad (removed before the grade is estimated; a
    /// straight's mean sideslip, where no bank is logged under it).
    pub beta: f64,
}

/// The sideslip offset the bank estimate of `run` removes: `offsets`'s
/// where the run has a `beta` column, else 0 (none is read).
fn beta_offset(run: &MeasuredRun, offsets: SensorOffsets) -> f64 {
    run.beta.as_ref().map_or(0.0, |_| offsets.beta)
}

/// The road under one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RoadGeometry {
    /// Run name.
    pub run: String,
    /// The offsets removed before the bank was estimated (None: a bank
    /// measured, or no offset known).
    pub offsets_removed: Option<SensorOffsets>,
    /// Bank (positive: left edge higher); None without `bank` and `ay`.
    pub bank: Option<AngleProfile>,
    /// Grade (positive: uphill); None without `ax`.
    pub grade: Option<AngleProfile>,
    /// The run's median speed, m/s (kept samples; NaN without any).
    pub speed: f64,
    /// The estimated bank over the run's slower and faster halves (None:
    /// its speed varies by less than [`SPEED_SPREAD`], a bank measured,
    /// or too few samples): a yaw-rate offset reads as a bank that grows
    /// with speed, a bank and an `ay` offset do not.
    pub by_speed: Option<BySpeed>,
    /// An estimated bank that is a steady value the campaign's other runs
    /// do not show (set over the campaign, [`RoadGeometry::set_apart`]):
    /// what it would be as a bank, an `ay` offset or a yaw-rate offset.
    /// None where the run's yaw-rate scale is apart (`scale_apart`): its
    /// bank is then the scale's.
    pub apart: Option<BankApart>,
    /// What the yaw rate reads of what `ay/u` says, from the slope of the
    /// bank estimate's residual on `u·r` ([`YawScale`]; None: a bank
    /// measured, no `ay`, or too little turning).
    pub yaw_scale: Option<YawScale>,
    /// A yaw-rate scale the campaign's other runs, reading the yaw rate as
    /// `ay/u` says, do not share (set over the campaign,
    /// [`RoadGeometry::set_apart`]): a scale error of the gyro or of the
    /// accelerometer.
    pub scale_apart: Option<ScaleApart>,
}

/// A run's speed varies enough to split at the median when its 95th
/// percentile over its 5th exceeds this ratio: a yaw-rate offset's bank
/// then differs between the halves by about this much, beyond the
/// sensors' noise over a 1 s average.
pub const SPEED_SPREAD: f64 = 1.25;

/// An estimated bank whose 5–95 % range lies this far (rad, 0.5°) or more
/// from the campaign's other runs' median on one side is a steady value
/// they do not show: the 0.086 m/s² of `ay` it takes is above an
/// accelerometer's scatter over the 1 s average (0.05 m/s² a sample).
pub const APART_BANK: f64 = 0.5 * std::f64::consts::PI / 180.0;

impl RoadGeometry {
    /// The road under `run`, named `name`, a bank estimated with the
    /// sensor `offsets` removed; `beta_ahead` m: how far ahead of the
    /// accelerometer the sideslip is measured (0 where one unit gives
    /// both), for the grade's lateral-velocity term.
    pub fn of(name: &str, run: &MeasuredRun, offsets: SensorOffsets, beta_ahead: f64) -> Self {
        let estimated = run.bank.is_none() && run.ay.is_some();
        let bank = match (&run.bank, &run.ay) {
            (Some(b), _) => profile(AngleSource::Measured, b.clone(), &[]),
            (None, Some(ay)) => profile(
                if run.beta.is_some() {
                    AngleSource::LateralKinematicsWithSideslip
                } else {
                    AngleSource::LateralKinematics
                },
                bank_estimate(run, ay, offsets),
                &run.masked,
            ),
            (None, None) => None,
        };
        let grade = run.ax.as_ref().and_then(|ax| {
            profile(
                if run.beta.is_some() {
                    AngleSource::LongitudinalKinematicsWithSideslip
                } else {
                    AngleSource::LongitudinalKinematics
                },
                grade_estimate(run, ax, offsets, beta_ahead),
                &run.masked,
            )
        });
        Self {
            run: name.to_string(),
            offsets_removed: (estimated
                && (offsets.ay, offsets.yaw_rate, beta_offset(run, offsets)) != (0.0, 0.0, 0.0))
                .then_some(SensorOffsets {
                    beta: beta_offset(run, offsets),
                    ..offsets
                }),
            by_speed: match (&run.bank, &run.ay) {
                (None, Some(ay)) => by_speed(run, &bank_estimate(run, ay, offsets)),
                _ => None,
            },
            yaw_scale: match (&run.bank, &run.ay) {
                (None, Some(ay)) => yaw_scale(run, ay, offsets),
                _ => None,
            },
            scale_apart: None,
            speed: median_speed(run),
            bank,
            grade,
            apart: None,
        }
    }

    /// Marks the runs of a campaign (`roads`) whose estimated bank is a
    /// steady value the others do not show ([`BankApart`]): its 5–95 %
    /// range [`APART_BANK`] or more to one side of the median of the
    /// other runs' medians, of two other runs or more; and those whose
    /// yaw-rate scale the others do not share ([`ScaleApart`],
    /// [`super::road_scale::set_apart`]), whose bank is then the scale's.
    pub fn set_apart(roads: Vec<RoadGeometry>) -> Vec<RoadGeometry> {
        let mut roads = Self::bank_apart(roads);
        let scales: Vec<Option<YawScale>> = roads.iter().map(|g| g.yaw_scale).collect();
        for (g, a) in roads.iter_mut().zip(super::road_scale::set_apart(&scales)) {
            g.scale_apart = a;
            if a.is_some() {
                g.apart = None;
            }
        }
        roads
    }

    /// The runs whose estimated bank is a steady value the others do not
    /// show ([`BankApart`]).
    fn bank_apart(mut roads: Vec<RoadGeometry>) -> Vec<RoadGeometry> {
        let medians: Vec<Option<f64>> = roads
            .iter()
            .map(|g| g.estimated_bank().map(|b| b.median))
            .collect();
        for (i, g) in roads.iter_mut().enumerate() {
            let mut others: Vec<f64> = medians
                .iter()
                .enumerate()
                .filter_map(|(j, m)| (j != i).then_some(*m).flatten())
                .collect();
            let Some(b) = g.estimated_bank().copied() else {
                continue;
            };
            if others.len() < 2 || g.speed.is_nan() || g.speed <= 0.0 {
                continue;
            }
            others.sort_by(f64::total_cmp);
            let o = quantile(&others, 0.5).expect("two runs or more");
            if b.p05 - o >= APART_BANK || o - b.p95 >= APART_BANK {
                let ay_offset = G * (b.median - o).sin();
                g.apart = Some(BankApart {
                    bank: b.median,
                    others: o,
                    other_runs: others.len(),
                    ay_offset,
                    yaw_rate_offset: -ay_offset / g.speed,
                });
            }
        }
        roads
    }

    /// The bank, where estimated (not measured).
    fn estimated_bank(&self) -> Option<&AngleProfile> {
        self.bank
            .as_ref()
            .filter(|b| b.source != AngleSource::Measured)
    }

    /// One angle in words. An estimate's extremes are its worst samples (a
    /// sensor lag in a hard stop reads as a steep grade): its bulk is said.
    fn part(&self, what: &str, p: &AngleProfile) -> String {
        if p.source == AngleSource::Measured {
            // No "-0.0°": a median of −0.01° is 0.0°.
            return format!(
                "{what} measured {}° to {}° (mean {}°)",
                deg(p.min),
                deg(p.max),
                deg(p.mean)
            );
        }
        let lateral = matches!(
            p.source,
            AngleSource::LateralKinematics | AngleSource::LateralKinematicsWithSideslip
        );
        let offsets = match self.offsets_removed {
            Some(o) if lateral => super::road_words::removed(o.ay, o.yaw_rate, o.beta),
            _ => String::new(),
        };
        let caveat = match p.source {
            AngleSource::LateralKinematics | AngleSource::LateralKinematicsWithSideslip
                if p.p05.abs().max(p.p95.abs()) > PLAUSIBLE_BANK =>
            {
                " (warning: steeper than any road's 35°: more likely a unit slip or a wrong sign in ay, speed or yaw_rate than a bank; reported, not used)"
            }
            AngleSource::LateralKinematics => {
                " (no beta column: the sideslip's rate v̇ is left out, so a corner's entry and exit read as bank)"
            }
            AngleSource::LongitudinalKinematics
            | AngleSource::LongitudinalKinematicsWithSideslip
                if p.p05.abs().max(p.p95.abs()) > PLAUSIBLE_GRADE =>
            {
                " (steeper than a 10 % grade: more likely what ax and du/dt disagree on besides the grade, the body's pitch, a lag between the speed and ax, wheel slip in the speed; reported, not used)"
            }
            AngleSource::LongitudinalKinematics => {
                " (no beta column: the lateral velocity's v·r is left out, so a corner reads as grade)"
            }
            _ => "",
        };
        let apart = match (self.scale_apart, self.apart) {
            (Some(s), _) if lateral => super::road_scale::words(&s),
            (None, Some(a)) if lateral => super::road_apart::apart(&a, self.speed, self.by_speed),
            _ => String::new(),
        };
        // A run whose yaw rate's scale is apart has no bank to state: what
        // its mismatch reads as an angle is the scale's, in step with the
        // turning, and is said as such.
        let what = match self.scale_apart {
            Some(_) if lateral => "no bank: the angle",
            _ => what,
        };
        format!(
            "{what} {}{offsets} {}° to {}° (5–95 %; median {}°){caveat}{apart}",
            p.source.words(),
            deg(p.p05),
            deg(p.p95),
            deg(p.median)
        )
    }

    /// One line for a summary, None when neither angle is known.
    pub fn line(&self) -> Option<String> {
        let mut parts: Vec<String> = [("bank", &self.bank), ("grade", &self.grade)]
            .into_iter()
            .filter_map(|(w, p)| p.as_ref().map(|p| self.part(w, p)))
            .collect();
        if self.bank.is_none() && !parts.is_empty() {
            parts.insert(0, "bank unknown (no bank or ay column)".into());
        }
        (!parts.is_empty()).then(|| format!("{}: {}", self.run, parts.join("; ")))
    }
}

/// `asin((a_y − b_ay − u·(r − b_r) − d(u·(β − b_β))/dt)/g)` smoothed, rad per
/// sample: the sensors' offsets `b` removed, the sideslip's rate where the
/// run has `beta` (a sample beside a masked one has none: NaN, left out).
pub(crate) fn bank_estimate(run: &MeasuredRun, ay: &[f64], offsets: SensorOffsets) -> Vec<f64> {
    let sine: Vec<f64> = lateral_mismatch(run, ay, offsets)
        .into_iter()
        .map(|e| e / G)
        .collect();
    smoothed_angle(&run.t, &sine, &run.masked)
}

/// `a_y − b_ay − u·(r − b_r) − d(u·(β − b_β))/dt`, m/s² per sample: what
/// the bank estimate reads as `g·sin θ` (NaN beside a masked sample where
/// the run has `beta`).
fn lateral_mismatch(run: &MeasuredRun, ay: &[f64], offsets: SensorOffsets) -> Vec<f64> {
    let lateral: Option<Vec<f64>> = run.beta.as_ref().map(|b| {
        // The sideslip's offset is no lateral velocity: d(u·b_β)/dt =
        // b_β·u̇ would read as bank wherever the car speeds up.
        b.iter()
            .zip(&run.speed)
            .map(|(b, u)| u * (b - offsets.beta).tan())
            .collect()
    });
    let masked = |k: usize| run.masked.binary_search(&k).is_ok();
    (0..run.t.len())
        .map(|k| {
            let v_dot = match &lateral {
                Some(v) if central(k, v.len()).iter().any(|&i| masked(i)) => f64::NAN,
                Some(v) => rate(&run.t, v, k),
                None => 0.0,
            };
            ay[k] - offsets.ay - run.speed[k] * (run.yaw_rate[k] - offsets.yaw_rate) - v_dot
        })
        .collect()
}

/// The yaw rate's scale of `run` ([`YawScale`]): the line of the bank
/// estimate's residual on the turning `u·(r − b_r)` where the residual is
/// known, both averaged alike (the same linear filter keeps the line),
/// masked samples left out.
fn yaw_scale(run: &MeasuredRun, ay: &[f64], offsets: SensorOffsets) -> Option<YawScale> {
    let e = lateral_mismatch(run, ay, offsets);
    let x: Vec<f64> = (0..e.len())
        .map(|k| match e[k].is_finite() {
            true => run.speed[k] * (run.yaw_rate[k] - offsets.yaw_rate),
            false => f64::NAN,
        })
        .collect();
    let (xs, es) = (
        smooth(&run.t, &x, &run.masked),
        smooth(&run.t, &e, &run.masked),
    );
    YawScale::of_kept(&xs, &es, &run.masked)
}

/// The neighbours of sample `k` of `n` a central difference takes (one
/// side at the ends).
fn central(k: usize, n: usize) -> [usize; 2] {
    [k.saturating_sub(1), (k + 1).min(n - 1)]
}

/// `dx/dt` at sample `k` by central differences (0 for a single sample).
fn rate(t: &[f64], x: &[f64], k: usize) -> f64 {
    let [i, j] = central(k, x.len());
    if j > i {
        (x[j] - x[i]) / (t[j] - t[i])
    } else {
        0.0
    }
}

/// `asin((a_x − u̇ + v·r + x_a·r²)/g)` smoothed, rad per sample: the
/// body-axis kinematics of an accelerometer `x_a` ahead of the centre of
/// gravity, `a_x = u̇ − v·r − x_a·r² + g·sin γ` (ISO 8855; `v` the centre
/// of gravity's lateral velocity). A sideslip measured `x_β` ahead of it
/// gives `u·tan β = v + x_β·r`, so `v·r + x_a·r² = u·tan β·r − (x_β −
/// x_a)·r²`, and where one unit measures both the positions cancel.
/// Without a `beta` column `v·r` is left out (`a_x − u̇`). The yaw rate's
/// and the sideslip's `offsets` are removed first; `beta_ahead` is
/// `x_β − x_a`, m.
pub(crate) fn grade_estimate(
    run: &MeasuredRun,
    ax: &[f64],
    offsets: SensorOffsets,
    beta_ahead: f64,
) -> Vec<f64> {
    let raw: Vec<f64> = (0..run.t.len())
        .map(|k| {
            let lateral = run.beta.as_ref().map_or(0.0, |b| {
                let r = run.yaw_rate[k] - offsets.yaw_rate;
                run.speed[k] * (b[k] - offsets.beta).tan() * r - beta_ahead * r * r
            });
            (ax[k] - rate(&run.t, &run.speed, k) + lateral) / G
        })
        .collect();
    // `ax` is not among the masked response channels: only the spans the
    // cleaning masked in the others are left out with them.
    smoothed_angle(&run.t, &raw, &run.masked)
}

/// The angle whose sine is `sine` smoothed ([`smooth`]), rad per sample.
fn smoothed_angle(t: &[f64], sine: &[f64], masked: &[usize]) -> Vec<f64> {
    smooth(t, sine, masked)
        .into_iter()
        .map(|s| s.clamp(-1.0, 1.0).asin())
        .collect()
}

/// Centred moving average over [`SMOOTHING_SECONDS`] by time, masked
/// samples left out (a sample with no unmasked neighbour in its window is
/// NaN).
fn smooth(t: &[f64], v: &[f64], masked: &[usize]) -> Vec<f64> {
    let half = 0.5 * SMOOTHING_SECONDS;
    let keep: Vec<bool> = (0..v.len())
        .map(|k| masked.binary_search(&k).is_err() && v[k].is_finite())
        .collect();
    // Running sums over the kept samples make the window O(1) per sample.
    let mut sum = vec![0.0; v.len() + 1];
    let mut count = vec![0usize; v.len() + 1];
    for k in 0..v.len() {
        sum[k + 1] = sum[k] + if keep[k] { v[k] } else { 0.0 };
        count[k + 1] = count[k] + usize::from(keep[k]);
    }
    (0..v.len())
        .map(|k| {
            let lo = t.partition_point(|x| *x < t[k] - half);
            let hi = t.partition_point(|x| *x <= t[k] + half);
            let n = count[hi] - count[lo];
            if n == 0 {
                f64::NAN
            } else {
                (sum[hi] - sum[lo]) / n as f64
            }
        })
        .collect()
}

/// The median speed of `run`'s kept samples, m/s (NaN without any).
fn median_speed(run: &MeasuredRun) -> f64 {
    let mut u: Vec<f64> = kept(&run.speed, &run.masked);
    u.sort_by(f64::total_cmp);
    quantile(&u, 0.5).unwrap_or(f64::NAN)
}

/// The finite values of `v` not at a `masked` index.
fn kept(v: &[f64], masked: &[usize]) -> Vec<f64> {
    v.iter()
        .enumerate()
        .filter(|(k, x)| x.is_finite() && masked.binary_search(k).is_err())
        .map(|(_, x)| *x)
        .collect()
}

/// The estimated `bank` (rad per sample) of `run` over its slower and
/// faster halves, split at its median speed, where its speed varies by
/// [`SPEED_SPREAD`] or more (at least ten kept samples a half).
fn by_speed(run: &MeasuredRun, bank: &[f64]) -> Option<BySpeed> {
    let pairs: Vec<(f64, f64)> = (0..run.t.len())
        .filter(|k| run.masked.binary_search(k).is_err())
        .map(|k| (run.speed[k], bank[k]))
        .filter(|(u, b)| u.is_finite() && b.is_finite())
        .collect();
    let mut u: Vec<f64> = pairs.iter().map(|p| p.0).collect();
    u.sort_by(f64::total_cmp);
    let (lo, mid, hi) = (quantile(&u, 0.05)?, quantile(&u, 0.5)?, quantile(&u, 0.95)?);
    if lo.is_nan() || lo <= 0.0 || hi / lo < SPEED_SPREAD {
        return None;
    }
    let half = |slow: bool| -> Option<(f64, f64)> {
        let mut side: Vec<(f64, f64)> = pairs
            .iter()
            .copied()
            .filter(|p| (p.0 < mid) == slow)
            .collect();
        if side.len() < 10 {
            return None;
        }
        let mut us: Vec<f64> = side.iter().map(|p| p.0).collect();
        us.sort_by(f64::total_cmp);
        side.sort_by(|a, b| a.1.total_cmp(&b.1));
        let bs: Vec<f64> = side.iter().map(|p| p.1).collect();
        Some((quantile(&us, 0.5)?, quantile(&bs, 0.5)?))
    };
    let ((slow_speed, slow_bank), (fast_speed, fast_bank)) = (half(true)?, half(false)?);
    Some(BySpeed {
        slow_speed,
        slow_bank,
        fast_speed,
        fast_bank,
    })
}

/// The summary of an angle series over its kept, finite samples.
fn profile(source: AngleSource, v: Vec<f64>, masked: &[usize]) -> Option<AngleProfile> {
    let kept: Vec<f64> = v
        .iter()
        .enumerate()
        .filter(|(k, x)| x.is_finite() && masked.binary_search(k).is_err())
        .map(|(_, x)| *x)
        .collect();
    if kept.is_empty() {
        return None;
    }
    let mut sorted = kept.clone();
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| quantile(&sorted, q).expect("samples kept");
    Some(AngleProfile {
        source,
        mean: kept.iter().sum::<f64>() / kept.len() as f64,
        min: sorted[0],
        max: sorted[sorted.len() - 1],
        p05: at(0.05),
        median: at(0.5),
        p95: at(0.95),
        samples: kept.len(),
    })
}

#[cfg(test)]
#[path = "road_tests.rs"]
mod tests;
