//! Responses written on a grid coarse against the step they measure, and
//! steps that start from a turn.
//!
//! A logger that writes a channel in steps of q (its resolution, or the
//! digits of the file: a sideslip written in degrees to 0.1°) rounds each
//! sample by up to q/2, a deviation of q/√12 (Widrow & Kollár 2008) that
//! the noise read from neighbouring differences does not show where most
//! neighbours repeat. Where q/√12 exceeds [`COARSE_SHARE`] of the step, a
//! steady value held between two codes reads one of them: a sideslip step
//! of −0.2135° read −0.2000° (−6.3 %) and TB 0.0680 for 0.0729, said
//! nowhere. The channel, its q and the bound ±q/2 on its steady change
//! and on what is derived from it are said; the steer's too, where it is a
//! logger's grid (a steer step of a few counts: the gain per steer known
//! within ±q/2), not a simulation's sampled ramp.
//!
//! A lattice is a logger's only where something besides one ramp puts the
//! values on it. A noise-free ramp sampled at equal times changes by the
//! same amount at every sample it spans whole, and by less at its two
//! ends, where it starts and stops between samples: its values lie on the
//! lattice of that change, or of a part of it where the ends cut it
//! simply. A 100 Hz simulation's 0.15 s ramp to 0.45° taken every other
//! row (50 Hz) changes 0.03°, then 0.06° seven times, and all its values
//! lie on a 0.03° lattice that no logger wrote; its steer was warned of as
//! "written in steps of 0.03 deg" and the gain's spread grew from 0.0081
//! to 0.0222 (round 51). A quantiser shows its lattice otherwise: in
//! levels held and returned to ([`held_resolution`](crate::metrics::noise)),
//! or in a ramp whose changes inside its rise differ by whole counts (a
//! slope that is no whole number of counts per sample, rounded, changes
//! by one count, then two). So the steer's lattice is said unless its
//! changes are one such sampled ramp; a rounded ramp whose slope is a
//! whole number of counts per sample cannot be told from one, and is not
//! said.
//!
//! ISO 7401 starts the step from straight running: a step from a steady
//! turn gives changes from that turn (the table's steady ay is the
//! change), which is said where the yaw rate and ay before it both stand
//! apart from 0 beyond their own noise: each mean at least [`FROM_TURN`] of
//! its step and [`TURN_ERRORS`] standard errors, the error counting
//! correlated samples (`s·√(τ/n)`, τ the integrated autocorrelation time
//! of `measured/calibration/stats.rs`): a 0.0003 rad step's pre-step yaw
//! rate of −0.000557 rad/s under gyro noise of 0.002 rad/s (1.6 standard
//! errors of its 0.5 s mean) was said to be a turn. Units: SI, rad, s;
//! sideslip and steer said in degrees.

use super::super::StepMetrics;
use crate::measured::MeasuredRun;

/// Share of the step above which the rounding's deviation q/√12 is said.
const COARSE_SHARE: f64 = 0.05;

/// Share of the steer step above which its rounding's deviation q/√12 is
/// said: a steer held between two codes reads one of them whatever the
/// noise of the responses (a held steer is not dithered by a gyro's
/// noise), so a step of 17 counts of 0.001 rad (q/√12 1.7 %) read 0.9740°
/// for 1° and the gain 2.3 % high, 23 times the spread the noise gave it.
/// Below 1 % (a step of more than about 29 counts) the bound is under the
/// digits a gain is compared to.
const STEER_COARSE_SHARE: f64 = 0.01;

/// Most steps of its resolution a logger's channel spans (as `noise.rs`).
const GRID_LEVELS: f64 = 65536.0;

/// Share of its step that the yaw rate and ay must both read before the
/// step for it to start from a turn: offsets of a gyro and an
/// accelerometer are a few % of a step, each on its own.
const FROM_TURN: f64 = 0.2;

/// Standard errors of its noise by which each pre-step mean must stand
/// from 0 for the step to start from a turn: a straight run's mean lies
/// beyond 4 of them in about one run in 16 000 per channel (normal), and
/// both channels must.
const TURN_ERRORS: f64 = 4.0;

/// The resolution q of `x`: its smallest non-zero change, where its range
/// spans at most [`GRID_LEVELS`] of it.
fn resolution(x: &[f64]) -> Option<f64> {
    let q = x
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|d| *d > 0.0 && d.is_finite())
        .fold(f64::INFINITY, f64::min);
    let (lo, hi) = x
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    (q.is_finite() && (hi - lo) / q <= GRID_LEVELS).then_some(q)
}

/// A response channel as the coarse-grid check reads it: its name, its
/// samples, its step, the scale and unit it is said in, and what depends
/// on it.
type Written<'a> = (
    &'a str,
    Option<&'a [f64]>,
    Option<f64>,
    f64,
    &'a str,
    &'a str,
);

/// The warnings of `piece`'s channels written coarsely against their
/// steps in `m`.
pub(super) fn coarse(piece: &MeasuredRun, m: &StepMetrics) -> Vec<String> {
    let deg = 180.0 / std::f64::consts::PI;
    // Responses only: a noise-free steer ramp takes few values, each a
    // multiple of its sample's change, and is no logger's grid.
    let channels: [Written; 3] = [
        (
            "yaw_rate",
            Some(&piece.yaw_rate),
            Some(m.yaw_rate_steady),
            1.0,
            "rad/s",
            "the yaw-rate gain and the overshoot",
        ),
        (
            "ay",
            piece.ay.as_deref(),
            m.ay_steady,
            1.0,
            "m/s²",
            "the steady ay",
        ),
        (
            "beta",
            piece.beta.as_deref(),
            m.beta_steady,
            deg,
            "deg",
            "the steady sideslip and TB",
        ),
    ];
    channels
        .into_iter()
        .filter_map(|(name, x, step, scale, unit, derived)| {
            let (q, step) = (resolution(x?)?, step?.abs());
            let share = q / 12f64.sqrt() / step;
            (share > COARSE_SHARE && step > 0.0).then(|| {
                format!(
                    "{name} is written in steps of {} {unit} and its step is {} {unit}, {} of them: the rounding's deviation q/√12 is {} % of the step, so its steady change is known only within ±q/2 = ±{} % (where noise does not dither it), and {derived} with it; log it finer",
                    crate::format::rounded(q * scale, 3),
                    crate::format::readable(step * scale, 4),
                    crate::format::readable(step / q, 2),
                    crate::format::readable(100.0 * share, 2),
                    crate::format::readable(50.0 * q / step, 2),
                )
            })
        })
        .collect()
}

/// The warning of a steer written on a grid coarse against its step: a
/// steer step of a few logger counts is known only within ±q/2, and the
/// yaw-rate gain (yaw rate per steer) with it. A steer is a logger's grid
/// only where its grid shows in held levels or a dither
/// ([`held_resolution`](crate::metrics::noise)), not in a ramp's few
/// samples, every sample is a whole number of steps q from the first, and
/// its changes are not one sampled ramp's ([`sampled_ramp`]): a
/// noise-free ramp (or a jump) sampled by a simulation changes by the
/// same amount at every sample inside its rise, and by a part of it at
/// its ends, and is no grid.
pub(super) fn coarse_steer(piece: &MeasuredRun, m: &StepMetrics) -> Option<String> {
    let x = &piece.steer;
    // Read from held levels or many, not a ramp's few samples.
    let q = grid_of(x)?;
    let step = m.steer_step.abs();
    let share = q / 12f64.sqrt() / step;
    if !(share > STEER_COARSE_SHARE && step > 0.0 && on_grid(x, q)) || sampled_ramp(x) {
        return None;
    }
    let deg = 180.0 / std::f64::consts::PI;
    Some(format!(
        "steer is written in steps of {} deg and its step is {} deg, {} of them: the rounding's deviation q/√12 is {} % of the step, so the steer step is known only within ±q/2 = ±{} %, and the yaw-rate gain (yaw rate per steer) with it (its deviation is in the gain's stated spread); log it finer",
        crate::format::rounded(q * deg, 3),
        crate::format::readable(step * deg, 4),
        crate::format::rounded(step / q, 2),
        crate::format::readable(100.0 * share, 2),
        crate::format::rounded(50.0 * q / step, 3),
    ))
}

/// Fewest distinct levels from which a channel's smallest change is read
/// as its grid where no held level shows one: a steer rounded to 0.001
/// rad through a 100 Hz ramp takes ten levels, one or two counts apart,
/// with only its initial and stepped values held; a noise-free 20–25 Hz
/// ramp takes four (its initial value, two ramp samples, its step), which
/// are no grid (they read a 0.2° one: `noise.rs`).
const GRID_LEVELS_SEEN: usize = 6;

/// The grid `x` is written on: read from its held levels
/// ([`held_resolution`](crate::metrics::noise)), or its smallest change
/// where it takes at least [`GRID_LEVELS_SEEN`] levels; None where neither
/// shows one (the callers also ask every sample on it and no one ramp).
fn grid_of(x: &[f64]) -> Option<f64> {
    crate::metrics::noise::held_resolution(x).or_else(|| {
        let q = resolution(x)?;
        let mut levels: Vec<f64> = x.iter().copied().filter(|v| v.is_finite()).collect();
        levels.sort_by(f64::total_cmp);
        levels.dedup();
        (levels.len() >= GRID_LEVELS_SEEN).then_some(q)
    })
}

/// The rounding's deviation q/√12 of `x`'s held `step`, as a share of it,
/// where `x` is written on a grid its held levels show (a logger's, not a
/// sampled ramp's): None where none shows.
fn rounding_share(x: &[f64], step: f64) -> Option<f64> {
    let q = grid_of(x)?;
    (step > 0.0 && on_grid(x, q) && !sampled_ramp(x)).then(|| q / 12f64.sqrt() / step)
}

/// The yaw-rate gain's share of deviation from its two channels' grids:
/// the steer's and the yaw rate's held steps each read one of the two
/// codes they lie between (up to ±q/2, a deviation q/√12 where the value
/// is anywhere between them), which no averaging of the run's noise
/// removes where the noise is below the grid; the two add in quadrature.
/// None where neither channel is on a grid.
pub(super) fn gain_rounding(piece: &MeasuredRun, m: &StepMetrics) -> Option<f64> {
    let steer = rounding_share(&piece.steer, m.steer_step.abs());
    let yaw = rounding_share(&piece.yaw_rate, m.yaw_rate_steady.abs());
    match (steer, yaw) {
        (None, None) => None,
        (s, r) => Some(s.unwrap_or(0.0).hypot(r.unwrap_or(0.0))),
    }
}

/// Whether every finite sample of `x` lies a whole number of steps `q`
/// from the first (to a thousandth of a step: a decimal grid is not exact
/// in binary).
fn on_grid(x: &[f64], q: f64) -> bool {
    let x0 = x[0];
    x.iter()
        .filter(|v| v.is_finite())
        .all(|v| ((v - x0) / q - ((v - x0) / q).round()).abs() < 1e-3)
}

/// Whether the changes of `x` are those of one ramp sampled at equal
/// times (or of a single jump): one stretch of consecutive samples, each
/// changing the same way, by the same amount `d` at every sample inside
/// the stretch and by at most `d` at its two ends (where the ramp starts
/// and stops between samples, the interval holds a part of it). A
/// rounded ramp changes by whole counts that differ inside the stretch
/// unless its slope is a whole number of counts per sample. Equal to a
/// thousandth of `d`: a decimal value is not exact in binary, and a
/// ramp's values written to 6 digits differ by less.
fn sampled_ramp(x: &[f64]) -> bool {
    let moving: Vec<usize> = x
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[1] != w[0])
        .map(|(i, _)| i)
        .collect();
    if !moving.windows(2).all(|w| w[1] == w[0] + 1) {
        return false;
    }
    let change: Vec<f64> = moving.iter().map(|&i| x[i + 1] - x[i]).collect();
    // Two changes or fewer are the ramp's ends alone.
    let (Some(first), Some(inner)) = (change.first(), change.get(1)) else {
        return true;
    };
    if change.len() == 2 {
        return first.signum() == inner.signum();
    }
    let d = *inner;
    let tolerance = 1e-3 * d.abs();
    let n = change.len();
    let equal = change[1..n - 1].iter().all(|c| (c - d).abs() <= tolerance);
    let ends = [change[0], change[n - 1]]
        .iter()
        .all(|c| c.signum() == d.signum() && c.abs() <= d.abs() + tolerance);
    equal && ends
}

/// The warning of a step that starts from a steady turn: the yaw rate and
/// ay both read at least [`FROM_TURN`] of their steps and [`TURN_ERRORS`]
/// standard errors of their means before it (over the first `pre_window`
/// s of `piece`).
pub(super) fn from_turn(piece: &MeasuredRun, m: &StepMetrics, pre_window: f64) -> Option<String> {
    let ay = piece.ay.as_deref()?;
    let ay_step = m.ay_steady?;
    let t0 = piece.t.first()?;
    let before = |x: &[f64]| {
        let v: Vec<f64> = piece
            .t
            .iter()
            .zip(x)
            .filter(|(t, x)| **t <= t0 + pre_window && x.is_finite())
            .map(|(_, x)| *x)
            .collect();
        mean_and_error(&v)
    };
    let ((r0, r_se), (a0, a_se)) = (before(&piece.yaw_rate)?, before(ay)?);
    let apart = |mean: f64, error: f64, step: f64| {
        mean.abs() >= FROM_TURN * step.abs() && mean.abs() > TURN_ERRORS * error
    };
    let turning = apart(r0, r_se, m.yaw_rate_steady) && apart(a0, a_se, ay_step);
    turning.then(|| {
        format!(
            "the step starts from a turn (before it: yaw rate {} rad/s, ay {} m/s², each more than {TURN_ERRORS} standard errors of its mean from 0), not from straight running as ISO 7401 asks: the steady values are changes from that turn (ay ends at {} m/s², the table's {} m/s² is the change), and the response is the car's about its turning state, not from straight ahead",
            crate::format::readable(r0, 3),
            crate::format::readable(a0, 3),
            crate::format::readable(a0 + ay_step, 3),
            crate::format::readable(ay_step, 4),
        )
    })
}

/// The mean of `v` and its standard error counting correlated samples:
/// `s·√(τ/n)`, τ the integrated autocorrelation time (1 for white noise);
/// None for no samples.
fn mean_and_error(v: &[f64]) -> Option<(f64, f64)> {
    let n = v.len();
    let mean = v.iter().sum::<f64>() / n as f64;
    if n == 0 {
        return None;
    }
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n.max(2) - 1) as f64;
    let tau = crate::measured::calibration::stats::integrated_time(v, mean);
    Some((mean, (var * tau / n as f64).sqrt()))
}

#[cfg(test)]
mod tests {
    use super::{grid_of, on_grid, sampled_ramp};

    /// A 0.45° (0.00785 rad) step ramped over 0.15 s from 1.0 s, sampled
    /// every `every` ms from `first` ms for 3 s, rounded to `q` rad where
    /// given (whole milliseconds: the ramp's end is reached exactly).
    fn ramp(every: usize, first: usize, q: Option<f64>) -> Vec<f64> {
        let step = 0.45f64.to_radians();
        (first..3000)
            .step_by(every)
            .map(|ms| step * ((ms as f64 - 1000.0) / 150.0).clamp(0.0, 1.0))
            .map(|v| q.map_or(v, |q| (v / q).round() * q))
            .collect()
    }

    /// Round 51: the 100 Hz ramp taken every other row (50 Hz, its
    /// first sample 10 ms into the ramp) changes 0.03°, then 0.06° seven
    /// times, on a 0.03° lattice; both it and the 100 Hz ramp are one
    /// sampled ramp, not a grid, though each lies on a lattice.
    #[test]
    fn a_ramp_sampled_at_equal_times_is_no_grid_at_any_phase() {
        let hz100 = ramp(10, 0, None);
        let hz50 = ramp(20, 10, None);
        let q = grid_of(&hz50).expect("nine levels read a lattice");
        assert!((q - 0.03f64.to_radians()).abs() < 1e-12, "{q}");
        assert!(on_grid(&hz50, q));
        assert!(sampled_ramp(&hz100));
        assert!(sampled_ramp(&hz50));
        // Any phase, either way: the ends hold a part of the interval.
        for first in [0, 3, 7, 19] {
            let x = ramp(20, first, None);
            assert!(sampled_ramp(&x), "{first}");
            let down: Vec<f64> = x.iter().map(|v| -v).collect();
            assert!(sampled_ramp(&down), "{first}");
        }
    }

    /// A ramp rounded to a logger's 0.0003 rad counts (1.75 counts a
    /// sample at 100 Hz) changes by 1 and 2 counts inside its rise: a
    /// quantiser's grid. One held and returned to, or a ramp whose end
    /// changes more than its inside, is none either.
    #[test]
    fn a_rounded_ramp_or_a_stair_is_no_sampled_ramp() {
        let rounded = ramp(10, 0, Some(3e-4));
        assert!(!sampled_ramp(&rounded));
        let q = grid_of(&rounded).unwrap();
        assert!((q - 3e-4).abs() < 1e-12, "{q}");
        assert!(on_grid(&rounded, q));
        let dither = [0.0, 0.0, 1e-3, 0.0, 1e-3, 1e-3, 0.0];
        assert!(!sampled_ramp(&dither));
        let wide_end = [0.0, 0.0, 1e-3, 2e-3, 3e-3, 5e-3, 5e-3];
        assert!(!sampled_ramp(&wide_end));
        let back = [0.0, 0.0, 1e-3, 2e-3, 3e-3, 2e-3, 2e-3];
        assert!(!sampled_ramp(&back));
        let two_stretches = [0.0, 1e-3, 2e-3, 2e-3, 3e-3, 4e-3, 4e-3];
        assert!(!sampled_ramp(&two_stretches));
        // A jump is one.
        assert!(sampled_ramp(&[0.0, 0.0, 1e-2, 1e-2]));
    }
}
