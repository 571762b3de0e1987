//! The yaw-rate channel's scale relative to `ay`'s in one run
//! ([`YawScale`]) and a run whose scale the campaign's other runs do not
//! share ([`ScaleApart`]), read from the residual of the road's bank
//! estimate ([`super::road`]).
//!
//! Kinematics (ISO 8855, flat-road 2-DOF terms): `a_y = u·r + v̇ + g·sin θ`.
//! A gyro that reads `k` times the true yaw rate (or an accelerometer that
//! reads `1/k` times the true `a_y`) leaves the residual `e = a_y − u·r_m −
//! v̇ = (1/k − 1)·u·r_m` (`r_m = k·r`), which grows in proportion to the
//! turning `x = u·r_m`; a steady bank, an `ay` offset and (at one speed) a
//! yaw-rate offset add a constant. So the least-squares line `e = c + s·x`
//! over the run's samples gives the scale `k = 1/(1 + s)`: what the yaw
//! rate reads of what `ay/u` says. Both `e` and `x` are the 1 s moving
//! averages of the bank estimate (the same linear filter on both keeps the
//! line: the noise of `d(u·β)/dt` averages out).
//!
//! Its standard error counts correlated samples honestly: the smoothed
//! residuals are correlated over about the window, so the slope's variance
//! is the sandwich `Σ_i Σ_j x̃_i ẽ_i x̃_j ẽ_j / S_xx²` (`x̃` centred, `ẽ` the
//! residuals of the line), its lag sums taken while the score `x̃·ẽ`'s
//! autocovariance stays positive (Geyer's initial positive sequence): white
//! residuals give `σ/√S_xx`, residuals held for `m` samples `√m` times it.
//!
//! What else makes the slope: a road banked in step with the turning (a
//! banked oval's turns: no bank on the straights, `θ` in the turns) gives
//! `e = g·sin θ` wherever `x = u²/R`, a slope `g·sin θ·R/u²` that at one
//! speed no single run tells from a scale; over runs at other speeds it
//! falls as `1/u²`, a scale stays. A run is set apart only where the other
//! runs read the yaw rate as `ay/u` says (their median within
//! [`APART_SCALE`] of 1: their roads are flat in the turns and their gyros
//! true), and the words say what reads alike. Units: scales and slopes
//! dimensionless, `x` and `e` m/s².

use serde::Serialize;

/// A run's scale departs from the other runs' median when it differs by
/// this fraction or more (3 %): beyond what a car's body roll puts in an
/// accelerometer that rolls with it (`g·φ` with a roll gradient of a few
/// degrees per g is a few per cent of `a_y`, alike in every run of the
/// car) and what the campaign's runs scatter by (±3 % on the synth's
/// handling programme with its noise).
pub const APART_SCALE: f64 = 0.03;

/// ... and by this many standard errors (the run's and the others'
/// together): a departure the noise makes once in about 15 000 runs.
pub const APART_ERRORS: f64 = 4.0;

/// The least spread of the turning `u·r` (its standard deviation, m/s²)
/// a run's slope is read over: below it (a straight, a gentle lane change)
/// the run barely turns and the slope is the noise's.
pub const LEAST_TURNING: f64 = 0.5;

/// The fewest samples a slope is read over.
const LEAST_SAMPLES: usize = 20;

/// The least-squares line of `e` on `x` over their finite sample pairs:
/// slope, intercept, the slope's standard error ([`slope_error`]) and the
/// samples' worth of independent information the error counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LineFit {
    /// `de/dx`.
    pub slope: f64,
    /// `e` at `x = 0`.
    pub intercept: f64,
    /// The slope's standard error.
    pub slope_error: f64,
    /// The sample pairs taken.
    pub samples: usize,
    /// The sample pairs over the score's correlation length (`samples`
    /// for white residuals).
    pub independent_samples: f64,
}

/// The line of `e` on `x` ([`LineFit`]) over the pairs where both are
/// finite, None with fewer than [`LEAST_SAMPLES`] of them or a spread of
/// `x` below [`LEAST_TURNING`].
pub(crate) fn line_fit(x: &[f64], e: &[f64]) -> Option<LineFit> {
    let pairs: Vec<(f64, f64)> = x
        .iter()
        .zip(e)
        .map(|(x, e)| (*x, *e))
        .filter(|(x, e)| x.is_finite() && e.is_finite())
        .collect();
    let n = pairs.len();
    if n < LEAST_SAMPLES {
        return None;
    }
    let mx = pairs.iter().map(|p| p.0).sum::<f64>() / n as f64;
    let me = pairs.iter().map(|p| p.1).sum::<f64>() / n as f64;
    let sxx: f64 = pairs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx / (n as f64) < LEAST_TURNING * LEAST_TURNING {
        return None;
    }
    let slope = pairs.iter().map(|p| (p.0 - mx) * (p.1 - me)).sum::<f64>() / sxx;
    let score: Vec<f64> = pairs
        .iter()
        .map(|p| (p.0 - mx) * (p.1 - me - slope * (p.0 - mx)))
        .collect();
    let (variance, white) = score_variance(&score);
    Some(LineFit {
        slope,
        intercept: me - slope * mx,
        slope_error: variance.sqrt() / sxx,
        samples: n,
        independent_samples: if variance > 0.0 {
            n as f64 * white / variance
        } else {
            n as f64
        },
    })
}

/// `Σ_i Σ_j z_i·z_j` over the lags whose autocovariance of `z` stays
/// positive (the first lag at or below 0 ends the sum, at most half the
/// samples), and `Σ z²` alone: the variance of `Σ z` counting correlated
/// samples, and what it would be for independent ones.
fn score_variance(z: &[f64]) -> (f64, f64) {
    let white: f64 = z.iter().map(|v| v * v).sum();
    let mut total = white;
    for lag in 1..z.len() / 2 {
        let g: f64 = z.iter().zip(&z[lag..]).map(|(a, b)| a * b).sum();
        if g <= 0.0 {
            break;
        }
        total += 2.0 * g;
    }
    (total, white)
}

/// What a run's yaw rate reads of what its `ay/u` says, from the slope of
/// its bank estimate's residual on the turning ([`super::road_scale`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct YawScale {
    /// `k = 1/(1 + s)`: the yaw rate reads `k` times what `ay/u` says.
    pub scale: f64,
    /// Its standard error, `σ_s/(1 + s)²`.
    pub standard_error: f64,
    /// The slope `s` of `ay − u·r − d(u·β)/dt` on `u·r` (1 s averages).
    pub slope: f64,
    /// The slope's standard error.
    pub slope_error: f64,
    /// The samples the line took.
    pub samples: usize,
    /// Their worth in independent samples (the residuals' correlation over
    /// the 1 s average and the run's own dynamics counted).
    pub independent_samples: f64,
}

impl YawScale {
    /// The scale of the line of the residual `e` on the turning `x` (both
    /// m/s², 1 s averages, NaN where left out), None where [`line_fit`]
    /// reads no line or the slope is −1 or below (no scale: the residual
    /// cancels `u·r`, a yaw rate of another sign or unit).
    pub fn of(x: &[f64], e: &[f64]) -> Option<YawScale> {
        let f = line_fit(x, e)?;
        let one = 1.0 + f.slope;
        (one > 0.0).then_some(YawScale {
            scale: 1.0 / one,
            standard_error: f.slope_error / (one * one),
            slope: f.slope,
            slope_error: f.slope_error,
            samples: f.samples,
            independent_samples: f.independent_samples,
        })
    }

    /// [`YawScale::of`] with the samples at the `masked` indices left out.
    pub fn of_kept(x: &[f64], e: &[f64], masked: &[usize]) -> Option<YawScale> {
        let kept = |v: &[f64]| -> Vec<f64> {
            let out = v.iter().enumerate();
            out.map(|(k, v)| match masked.binary_search(&k) {
                Ok(_) => f64::NAN,
                Err(_) => *v,
            })
            .collect()
        };
        Self::of(&kept(x), &kept(e))
    }
}

/// A run whose yaw rate reads a scale of what `ay/u` says that the
/// campaign's other runs, reading it as `ay/u` says, do not share: a scale
/// error of the gyro (or of the accelerometer), which only a road banked
/// in step with the turning under this run alone reads alike at one speed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ScaleApart {
    /// The run's scale ([`YawScale::scale`]).
    pub scale: f64,
    /// Its standard error.
    pub standard_error: f64,
    /// The median of the other runs' scales.
    pub others: f64,
    /// The other runs with a scale.
    pub other_runs: usize,
    /// The run's scale over the others': the scale error.
    pub factor: f64,
}

/// Each run's [`ScaleApart`] of a campaign's `scales`: a run whose scale
/// differs from the median of the other runs' (two or more, their median
/// within [`APART_SCALE`] of 1) by [`APART_SCALE`] of it or more and by
/// [`APART_ERRORS`] standard errors (the run's and the others' median's
/// together) or more.
pub fn set_apart(scales: &[Option<YawScale>]) -> Vec<Option<ScaleApart>> {
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        super::clean::quantile(v, 0.5)
    };
    scales
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let s = (*s)?;
            let others: Vec<YawScale> = scales
                .iter()
                .enumerate()
                .filter_map(|(j, o)| (j != i).then_some(*o).flatten())
                .collect();
            if others.len() < 2 {
                return None;
            }
            let o = median(&mut others.iter().map(|o| o.scale).collect())?;
            let o_error = median(&mut others.iter().map(|o| o.standard_error).collect())?;
            let apart = (s.scale - o).abs();
            let errors = s.standard_error.hypot(o_error);
            let true_others = (o - 1.0).abs() < APART_SCALE;
            (true_others && apart >= APART_SCALE * o && apart >= APART_ERRORS * errors).then(|| {
                ScaleApart {
                    scale: s.scale,
                    standard_error: s.standard_error,
                    others: o,
                    other_runs: others.len(),
                    factor: s.scale / o,
                }
            })
        })
        .collect()
}

/// A scale apart in words, for the run's road line.
pub(crate) fn words(a: &ScaleApart) -> String {
    format!(
        "; its yaw rate reads ×{} ± {} of what ay/u says, the other {} runs' ×{} (their median): a scale error of ×{} of the gyro (or of ×{} of the accelerometer), not a bank; only a road banked in step with the turning under this run alone (as a banked oval's turns) reads alike at one speed, and the same ground at another speed tells it (a bank's slope falls as 1/u², a scale's stays)",
        crate::format::fixed(a.scale, 3),
        crate::format::fixed(a.standard_error, 3),
        a.other_runs,
        crate::format::fixed(a.others, 3),
        crate::format::fixed(a.factor, 3),
        crate::format::fixed(1.0 / a.factor, 3),
    )
}

/// A scale apart in words, for a warning that names its run: `its yaw
/// rate reads ×1.149 of what its ay/u says, …`.
pub fn scale_in_run(a: &ScaleApart) -> String {
    format!(
        "its yaw rate reads ×{} of what its ay/u says, the other runs' ×{}: a scale error of the gyro (or of the accelerometer), not a bank, as its road line says",
        crate::format::fixed(a.scale, 3),
        crate::format::fixed(a.others, 3)
    )
}

#[cfg(test)]
#[path = "road_scale_tests.rs"]
mod tests;
