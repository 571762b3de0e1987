//! Step-steer metrics of a measured run as a logger wrote it: the run is
//! cleaned ([`crate::measured::clean`]: standstills, crawling and glitches),
//! and of its moving pieces, longest first, the first that holds a steer
//! step is measured (`step_metrics`, on one uniform grid: `uniform.rs`): a
//! step held still over the initial window and after (not a sweep:
//! `check_step_shape`); the others are listed with why they were left
//! out. A run without `ay` gets the yaw-rate metrics only. The steer's
//! 10–90 % rise is checked against ISO 7401's 0.15 s. Units: SI, rad, s.

use super::step_shape::last_crossing;
use super::{MetricSettings, StepMetrics};
use crate::error::{InputError, InputProblem};
use crate::measured::clean::{
    clean_single_reported, median, median_interval, quantile, CleanSettings, CleaningReport,
};
use crate::measured::MeasuredRun;
use serde::Serialize;
/// ISO 7401's limit on the steer's 10–90 % rise, s.
pub(crate) const ISO_7401_RISE: f64 = 0.15;

/// Below this median of r·l/(u·δ) the steer is far larger than the yaw
/// rate it gives: a steer in degrees (57×) or a steering-wheel angle
/// (15×), not a car's understeer (0.2–1 at the handling tests' speeds;
/// lower at speed, where the limit falls with the least a car gives:
/// [`least_gain`]).
pub const STEER_IN_DEGREES: f64 = 0.1;

/// The wheelbase taken when a run comes without its vehicle, m: longer than
/// any car's, so that a real car's response is never judged too small.
pub const LONGEST_WHEELBASE: f64 = 5.0;

/// The wheelbase a run's yaw rate is judged too large against, m: shorter
/// than any car's (a kart's is about 1.05 m), so that a real car's response
/// is never judged too large.
pub const SHORTEST_WHEELBASE: f64 = 1.0;

/// Above this median of r·l/(u·δ) with [`SHORTEST_WHEELBASE`] the yaw rate
/// is too large for its steer: a 2.7 m car turning at 13.5× a neutral
/// car's rate, which only a car past its critical speed does (spinning, no
/// step response); a steer divided by 57 once more gives about 20.
pub const YAW_ABOVE_STEER: f64 = 5.0;

/// Steered samples needed to judge the steer against the yaw rate.
const STEER_CHECK_SAMPLES: usize = 50;

/// A steer is held when it has stayed within this share of its value over
/// the last [`HELD_FOR`]: the yaw rate has then followed it.
const HELD_WITHIN: f64 = 0.1;

/// How long a steer must be held, s: a car's yaw rate settles to a steer
/// within about half a second (its yaw response time is 0.1–0.3 s).
const HELD_FOR: f64 = 0.5;

/// The samples whose steer has been held: within [`HELD_WITHIN`] of its
/// value, same sign, over the last [`HELD_FOR`] (a full window of the
/// record).
fn held(t: &[f64], steer: &[f64]) -> Vec<bool> {
    let mut out = vec![false; t.len()];
    let mut from = 0;
    for i in 0..t.len() {
        while t[i] - t[from] > HELD_FOR {
            from += 1;
        }
        let full = from > 0 || t[i] - t[0] >= HELD_FOR;
        let d = steer[i];
        out[i] = full
            && steer[from..=i]
                .iter()
                .all(|&x| (x - d).abs() <= HELD_WITHIN * d.abs());
    }
    out
}

/// The yaw rate over a neutral car's where the run holds a steer: over the
/// samples at speed (at least `min_speed` and 5 m/s) steered by at least
/// 0.005 rad and 30 % of the 95th percentile of |δ| at speed, and whose
/// steer has been held for half a second ([`held`]; where the steer moves,
/// the yaw rate lags it and a ratio of the two measures the lag, not the
/// units: a frequency sweep gives medians near or below zero), the median
/// of `q = r·l/(u·δ)` and the samples; about `1/(1 + K·u²)` (0.2–1 for an
/// understeering car, somewhat above 1 for an oversteering one). None for
/// a run that neither steers nor turns (95th percentiles of |δ| and of the
/// neutral steer `|r|·l/u` both below 0.01 rad: a straight run whose steer
/// sensor sits a few milliradians off shows no gain; one turning by
/// [`GENTLE`] is judged whatever its steer) or with fewer than 50
/// such samples. A run that turns on a steer below 0.01 rad (a radian
/// steer divided by 57 once more) is judged on its steered samples alike,
/// so that its ratio, far above 1, is seen. `metrics` and `diagnose` judge
/// a run by it alike ([`steer_problem`]).
pub fn yaw_per_neutral(run: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Option<YawPerNeutral> {
    let at_speed: Vec<usize> = (0..run.t.len())
        .filter(|&i| run.speed[i] >= min_speed.max(5.0))
        .collect();
    let mut size: Vec<f64> = at_speed.iter().map(|&i| run.steer[i].abs()).collect();
    size.sort_by(f64::total_cmp);
    let p95 = quantile(&size, 0.95)?;
    let mut neutral: Vec<f64> = neutral_at_speed(run, wheelbase, min_speed)
        .iter()
        .map(|q| q.abs())
        .collect();
    neutral.sort_by(f64::total_cmp);
    let neutral_p95 = quantile(&neutral, 0.95)?;
    let turns = neutral_p95 >= TURN;
    // A gentle run (an ISO 7401 step at 100 km/h and 2 m/s² steers
    // 0.008 rad) that turns by 5 mrad of neutral steer is judged too,
    // whatever its steer (divided by 57, it is 0.00014 rad): a straight run
    // with a steer sensor a few milliradians off does not turn.
    let gentle = p95 > 0.0 && neutral_p95 >= GENTLE;
    let steered = match (p95 >= TURN, turns) {
        (true, _) => (0.3 * p95).max(0.005),
        (false, true) if p95 > 0.0 => 0.3 * p95,
        _ if gentle => 0.3 * p95,
        _ => return None,
    };
    let held = held(&run.t, &run.steer);
    let (samples, mut q): (Vec<usize>, Vec<f64>) = at_speed
        .into_iter()
        .filter(|&i| run.steer[i].abs() >= steered && held[i])
        .map(|i| {
            (
                i,
                neutral_steer(run.yaw_rate[i], wheelbase, run.speed[i]) / run.steer[i],
            )
        })
        .filter(|(_, q)| q.is_finite())
        .unzip();
    if q.len() < STEER_CHECK_SAMPLES {
        return None;
    }
    let n = q.len() as f64;
    let share = |f: fn(f64) -> bool| q.iter().filter(|x| f(**x)).count() as f64 / n;
    let (with_steer, against) = (share(|x| x > 0.0), share(|x| x < 0.0));
    let yaw: Vec<f64> = samples.iter().map(|&i| run.yaw_rate[i]).collect();
    let mut speeds: Vec<f64> = samples.iter().map(|&i| run.speed[i]).collect();
    Some(YawPerNeutral {
        median: median(&mut q),
        samples: q.len(),
        speed: median(&mut speeds),
        with_steer,
        against,
        one_value: crate::measured::one_value(&yaw),
        ay_with_steer: YawPerNeutral::ay_with_steer(run, &samples),
    })
}

/// The neutral steer `r·l/u` (95th percentile at speed, rad) from which a
/// run below [`TURN`] is still judged by [`yaw_per_neutral`].
const GENTLE: f64 = 0.005;

/// A steer or neutral steer from which a run turns, rad: a straight run's
/// steer sensor sits a few milliradians off, and its yaw rate's noise and
/// drift make a neutral steer of a few milliradians.
pub const TURN: f64 = 0.01;

/// The steer a neutral car (no under- or oversteer) needs for yaw rate
/// `yaw_rate` (rad/s) at speed `speed` (m/s) on `wheelbase` (m): `r·l/u`,
/// rad (Ackermann, small angles). A run's steer is judged against it.
pub fn neutral_steer(yaw_rate: f64, wheelbase: f64, speed: f64) -> f64 {
    yaw_rate * wheelbase / speed
}

/// The neutral steer of each sample of `run` at speed (at least
/// `min_speed` and 5 m/s), rad, in time order.
fn neutral_at_speed(run: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Vec<f64> {
    (0..run.t.len())
        .filter(|&i| run.speed[i] >= min_speed.max(5.0))
        .map(|i| neutral_steer(run.yaw_rate[i], wheelbase, run.speed[i]))
        .collect()
}

/// A steer that holds one value over the whole run while the car turns,
/// judged by the neutral steer `r·l/u` at speed (at least `min_speed` and
/// 5 m/s) with `wheelbase`: beyond 0.01 rad either way on a zero steer, or
/// both ways (5th and 95th percentiles) on any other value — no car turns
/// both ways on one steer, nor on none on a flat road. A dead steer sensor,
/// refused by `diagnose` and a replay as a dead yaw rate is.
pub fn dead_steer(run: &MeasuredRun, wheelbase: f64, min_speed: f64) -> Option<InputProblem> {
    let value = crate::measured::one_value(&run.steer)?;
    let mut neutral: Vec<f64> = neutral_at_speed(run, wheelbase, min_speed)
        .into_iter()
        .filter(|q| q.is_finite())
        .collect();
    neutral.sort_by(f64::total_cmp);
    let (lo, hi) = (quantile(&neutral, 0.05)?, quantile(&neutral, 0.95)?);
    let turns = match value == 0.0 {
        true => lo.abs().max(hi.abs()) >= TURN,
        false => lo <= -TURN && hi >= TURN,
    };
    turns.then_some(InputProblem::DeadSteer {
        value,
        neutral: if hi.abs() >= lo.abs() { hi } else { lo },
    })
}

pub use super::yaw_per_neutral::YawPerNeutral;

/// The share of held steered samples a yaw rate must turn on one side of
/// the steer to follow it: a steer in degrees or a steering-wheel angle
/// still turns the car with the steer on nearly every sample (its yaw rate
/// stands many noise spreads from 0), a yaw rate that logs noise or a
/// frozen sensor on about half or none.
const FOLLOWS_STEER: f64 = 0.8;

/// The wheelbase a run's steer is judged with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Wheelbase {
    /// The vehicle's, m (a campaign's, a replay's scenario).
    Known(f64),
    /// Not known (`metrics` on a run alone): a yaw rate too small is judged
    /// with [`LONGEST_WHEELBASE`], one too large with [`SHORTEST_WHEELBASE`],
    /// so that no real car's is refused either way.
    Unknown,
}

impl Wheelbase {
    /// The wheelbase the median of [`yaw_per_neutral`] is taken with.
    pub fn for_median(self) -> f64 {
        match self {
            Self::Known(l) => l,
            Self::Unknown => LONGEST_WHEELBASE,
        }
    }
}

/// What is wrong with a run's steer, judged by the median `median` of
/// [`yaw_per_neutral`] over `samples` held samples, taken with
/// `wheelbase`'s [`Wheelbase::for_median`], against [`STEER_IN_DEGREES`]
/// lowered by the samples' speed ([`least_gain::limit_at_speed`]): below
/// minus that limit the yaw rate turns against the steer (another sign
/// convention), below it it is far smaller than a neutral car's (a steer
/// in degrees, 57×, or a steering-wheel angle, 15×), above
/// [`YAW_ABOVE_STEER`] far larger (a steer declared in degrees that was in
/// radians). Each refuses the run, in `metrics`, in a replay and in
/// `diagnose` alike: fitted, such a steer gives a model-form error that is
/// a unit slip.
pub fn steer_problem(y: &YawPerNeutral, wheelbase: Wheelbase) -> Option<InputProblem> {
    let (median, samples) = (y.median, y.samples);
    let assumed = match wheelbase {
        Wheelbase::Known(_) => None,
        Wheelbase::Unknown => Some(LONGEST_WHEELBASE),
    };
    // r·l/(u·δ) is linear in l: the same median at the shortest wheelbase.
    let (above, assumed_above) = match wheelbase {
        Wheelbase::Known(_) => (median, None),
        Wheelbase::Unknown => (
            median * SHORTEST_WHEELBASE / LONGEST_WHEELBASE,
            Some(SHORTEST_WHEELBASE),
        ),
    };
    let (limit, at_speed) =
        least_gain::limit_at_speed(STEER_IN_DEGREES, y.speed, wheelbase.for_median());
    let units = if median < -limit {
        Some(InputProblem::YawAgainstSteer {
            median,
            samples,
            ay_with_steer: y.ay_with_steer,
        })
    } else if median < limit {
        Some(InputProblem::SteerAboveYaw {
            median,
            samples,
            assumed_wheelbase: assumed,
            at_speed,
        })
    } else if above > YAW_ABOVE_STEER {
        Some(InputProblem::YawAboveSteer {
            median: above,
            samples,
            assumed_wheelbase: assumed_above,
        })
    } else {
        None
    };
    // A yaw rate that does not follow the steer either way, or holds one
    // value wherever the steer is held, says nothing of the steer's units:
    // the channel itself is wrong. (A quantised gyro may hold one value
    // over a single steady state whose ratio is a car's: no claim then.)
    let follows = y.with_steer >= FOLLOWS_STEER || y.against >= FOLLOWS_STEER;
    match units {
        Some(_) if y.one_value.is_some() || !follows => Some(InputProblem::YawIgnoresSteer {
            with_steer: y.with_steer,
            against: y.against,
            one_value: y.one_value,
            samples,
        }),
        units => units,
    }
}

/// Refuses a run whose steer its yaw rate contradicts ([`steer_problem`],
/// wheelbase unknown), not an unstable car's divergence (the step metrics
/// say it). `diagnose` also notes a yaw rate 3× a neutral car's.
fn check_steer_units(run: &MeasuredRun, min_speed: f64) -> Result<(), InputError> {
    let wheelbase = Wheelbase::Unknown;
    let Some(y) = yaw_per_neutral(run, wheelbase.for_median(), min_speed) else {
        let p = super::moving_steer::steer_in_degrees(
            run,
            min_speed,
            LONGEST_WHEELBASE,
            STEER_IN_DEGREES,
        );
        return p.map_or(Ok(()), |p| Err(InputError::problem(&run.path, p)));
    };
    match steer_problem(&y, wheelbase) {
        Some(InputProblem::YawAboveSteer { .. }) if super::divergence::diverges_raw(run) => Ok(()),
        Some(problem) => Err(InputError::problem(&run.path, problem)),
        None => Ok(()),
    }
}

/// The metrics of a measured run and what was measured.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeasuredMetrics {
    /// The metrics.
    pub metrics: StepMetrics,
    /// The piece measured (file, and `#k` when the run was split).
    pub piece: String,
    /// Its first and last sample, s.
    pub t_start: f64,
    /// Last sample, s.
    pub t_end: f64,
    /// Time for the steer to go from 10 % to 90 % of its step, s.
    pub steer_rise_time: f64,
    /// What the user should know (a steer too slow for ISO 7401).
    pub warnings: Vec<String>,
    /// How the run was cleaned, every piece left out with its reason.
    pub cleaning: CleaningReport,
    /// The piece's median speed, m/s.
    pub speed: Option<f64>,
    /// The sideslip the piece holds before its step, rad, where it stands
    /// apart from zero: the steady sideslip is a change from it
    /// (`sideslip_start.rs`).
    #[serde(skip)]
    pub sideslip_start: Option<f64>,
    /// What the check of `ay` against `u·r` reads ([`Self::ay_check`]).
    #[serde(skip)]
    pub(crate) ay_basis: Option<ay_check::AyBasis>,
}

mod ay_check;
mod coarse_grid;
mod hole_bound;
pub mod least_gain;
mod no_step;
mod noise_spread;
mod peak_speed;
mod piece;
mod sideslip_start;
mod small_gain;
mod steady_advice;
mod uniform;
pub(crate) use ay_check::AY_METRICS;
pub use ay_check::{AyCheck, AY_CHECKED_FROM, AY_CHECK_SAMPLES, AY_DISAGREES};
pub use small_gain::{SMALL_GAIN_AY, SMALL_STEADY_GAIN};

impl MeasuredMetrics {
    /// The check of `ay` against the speed times the yaw rate
    /// ([`ay_check`]): it agrees (or is missing or too small to judge),
    /// disagrees (the ay metrics are then left out), or the run holds too
    /// few measured samples to compare.
    pub fn ay_check(&self) -> AyCheck {
        match &self.ay_basis {
            Some(b) => ay_check::ay_check(b, &self.piece),
            None => AyCheck::Agrees,
        }
    }
}

/// The first time after `from` at which `x` crosses `level` (linear
/// interpolation between samples), in the direction of `sign`.
fn crossing(t: &[f64], x: &[f64], level: f64, sign: f64, from: f64) -> Option<f64> {
    (1..t.len()).find_map(|i| {
        let (a, b) = (sign * (x[i - 1] - level), sign * (x[i] - level));
        (t[i] >= from && a < 0.0 && b >= 0.0).then(|| t[i - 1] + (t[i] - t[i - 1]) * a / (a - b))
    })
}

/// The steer's 10–90 % rise: levels from the mean steer of the pre-input
/// window (as the metrics take it) and the metrics' steer step; from the
/// last crossing of 10 % before the first of 90 %, since a noisy steer
/// crosses 10 % back and forth before the step (a sensor's noise of 3 %
/// of the step read a 0.08 s ramp as 0.23 s from its first crossing).
fn steer_rise(run: &MeasuredRun, m: &StepMetrics, settings: &MetricSettings) -> f64 {
    let pre_end = super::initial::initial_end(&run.t, &run.steer, settings);
    let pre: Vec<f64> = run
        .t
        .iter()
        .zip(&run.steer)
        .filter(|(t, _)| **t <= pre_end)
        .map(|(_, d)| *d)
        .collect();
    let base = pre.iter().sum::<f64>() / pre.len().max(1) as f64;
    let sign = m.steer_step.signum();
    let level = |share: f64| base + share * m.steer_step;
    let rise = crossing(&run.t, &run.steer, level(0.9), sign, run.t[0]).and_then(|t90| {
        last_crossing(&run.t, &run.steer, level(0.1), sign, t90).map(|t10| t90 - t10)
    });
    rise.unwrap_or(f64::NAN)
}

/// The warning of a run without `ay` (a dead `ay` left out says so itself,
/// and `metrics` drops this one for it): the column, and the rows of the
/// table that read "—" for want of it, said once.
pub(crate) const NO_AY: &str =
    "the run has no `ay` column, which the ay response time, steady ay, E_ay and Er rows need: they read — (null in --json)";

/// The warning of a run without `beta` (a dead `beta` left out says so
/// itself, and `metrics` drops this one for it): the sideslip and TB rows
/// read "—" without a word of why.
pub(crate) const NO_BETA: &str =
    "the run has no `beta` column, which the steady sideslip and TB rows need (TB is the yaw-rate peak time × the steady sideslip): they read — (null in --json)";

/// The warning of a steady window whose response samples the cleaning
/// masked (a stuck sensor to the end of the record, a burst of spikes) and
/// the metrics read filled from their neighbours, for a tenth of the
/// window or more: the steady state then stands on the fill. A spike or
/// two filled is what the cleaning is for, not worth a word.
fn filled_steady(piece: &MeasuredRun, window: f64) -> Option<String> {
    let last = *piece.t.last()?;
    let from = last - window;
    let inside = piece.t.iter().filter(|t| **t >= from).count();
    let masked = piece.masked.iter().filter(|&&i| piece.t[i] >= from).count();
    (10 * masked >= inside && masked > 0).then(|| {
        format!(
            "{masked} of the {inside} samples of the steady window ({from:.2}–{last:.2} s) {} masked by the cleaning (see its lines) and {} filled from the samples beside {}: the steady state, the gain and what is measured against them stand on that fill{}",
            if masked == 1 { "is" } else { "are" },
            if masked == 1 { "was" } else { "were" },
            if masked == 1 { "it" } else { "them" },
            match 2 * masked > inside {
                true => ", not on measurements: do not use these metrics",
                false => "",
            }
        )
    })
}

/// The warning of a speed that changes over the response the metrics
/// measure in `piece`: from `pre_window` before the steer's time zero to
/// the piece's end. A run-up before it (the initial window reads the
/// straight running, whose yaw rate and ay are zero at any speed) mixes
/// no speeds into a response. Which way the speed went: the last tenth
/// of those samples against their first.
fn measured_speed_varies(
    piece: &MeasuredRun,
    m: &StepMetrics,
    settings: &MetricSettings,
) -> Option<String> {
    let from = m.time_zero - settings.pre_window;
    let read: Vec<f64> = piece
        .t
        .iter()
        .zip(&piece.speed)
        .filter(|(t, u)| **t >= from && u.is_finite())
        .map(|(_, u)| *u)
        .collect();
    let tenth = (read.len() / 10).max(1);
    let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len().max(1) as f64;
    let rising =
        mean(&read[read.len().saturating_sub(tenth)..]) >= mean(&read[..tenth.min(read.len())]);
    let mut sorted = read;
    sorted.sort_by(f64::total_cmp);
    super::applicability::varying_speed(&sorted, rising)
}

/// Cleans `run`, finds the piece with a steer step and measures it.
pub fn measured_step_metrics(
    run: MeasuredRun,
    min_speed: f64,
    settings: &MetricSettings,
) -> Result<MeasuredMetrics, InputError> {
    check_steer_units(&run, min_speed)?;
    let path = run.path.clone();
    let mut cleaning = CleaningReport::new(min_speed);
    cleaning.read_across = crate::measured::clean::ReadAcross::Metrics;
    let found = clean_single_reported(
        run,
        &CleanSettings::single(min_speed),
        &mut cleaning,
        |piece, found| piece::measure(piece, found, settings),
    );
    let Some((piece, (metrics, filled, said))) = found else {
        let problem = no_step::no_step_problem(&cleaning, &path, min_speed);
        return Err(InputError::problem(&path, problem));
    };
    let steer_rise_time = steer_rise(&filled, &metrics, settings);
    let mut warnings = said;
    warnings.extend(uniform::said(&piece.t));
    warnings.extend(rise_said(steer_rise_time, median_interval(&piece.t)));
    // The piece's median speed: a crawl is said, as a slide is.
    let mut speeds: Vec<f64> = piece
        .speed
        .iter()
        .copied()
        .filter(|u| u.is_finite())
        .collect();
    speeds.sort_by(f64::total_cmp);
    let speed = speeds.get(speeds.len() / 2).copied();
    // The largest |β| the piece logs: a spinning car's passes a slide's.
    let largest_sideslip = piece.beta.as_ref().map(|b| {
        b.iter()
            .filter(|x| x.is_finite())
            .fold(0.0_f64, |m, x| m.max(x.abs()))
    });
    warnings.extend(super::applicability::applicability_measured(
        &metrics,
        speed,
        largest_sideslip,
        peak_speed::at_peak_and_steady(&piece, &metrics, settings),
    ));
    warnings.extend(metrics.steer_logged_late.map(super::steer_lead_said));
    warnings.extend(measured_speed_varies(&piece, &metrics, settings));
    warnings.extend(speed.and_then(|u| small_gain::small_gain(&metrics, u)));
    warnings.extend(noise_spread::said(&metrics));
    warnings.extend(metrics.settling_warning());
    warnings.extend(metrics.settling.not_judged_warnings());
    warnings.extend(filled_steady(&piece, settings.steady_window));
    warnings.extend(super::beta_sign::against_kinematics(&piece));
    if metrics.ay_steady.is_none() {
        warnings.push(NO_AY.into());
    }
    if piece.beta.is_none() {
        warnings.push(NO_BETA.into());
    }
    let ay_basis = ay_check::ay_basis(&piece, &metrics, settings);
    let sideslip_start = sideslip_start::sideslip_start(&filled, &metrics, settings);
    Ok(MeasuredMetrics {
        metrics,
        piece: piece.path.display().to_string(),
        t_start: piece.t[0],
        t_end: piece.t[piece.t.len() - 1],
        steer_rise_time,
        warnings,
        cleaning,
        speed,
        sideslip_start,
        ay_basis,
    })
}

/// The steer's 10–90 % rise `rise` (s) against ISO 7401's limit, on a log
/// sampled every `dt` s. Each crossing is interpolated inside the sample
/// interval that brackets it, where the steer's own crossing also lies, so
/// the true rise is at least `rise − 2·dt`: where that is within the
/// limit, the log cannot tell a slow step from a fast one (a 0.1 s ramp
/// read at 8 Hz rises "0.163 s"), and that is what is said.
fn rise_said(rise: f64, dt: f64) -> Option<String> {
    if rise <= ISO_7401_RISE {
        return None;
    }
    let shortest = (rise - 2.0 * dt).max(0.0);
    Some(match shortest <= ISO_7401_RISE {
        true => format!(
            "the steer's 10–90 % rise reads {rise:.3} s, over ISO 7401's {ISO_7401_RISE} s, but a log sampled every {} s places each of its crossings only within an interval: the rise may be as short as {shortest:.3} s, and the log cannot resolve whether the step meets ISO 7401; log faster to time it",
            crate::format::rounded(dt, 3)
        ),
        false => format!(
            "the steer rises from 10 % to 90 % of its step in {rise:.3} s; ISO 7401 asks for at most {ISO_7401_RISE} s: the response times include the ramp"
        ),
    })
}
