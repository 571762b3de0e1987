//! Whether a steer's exact hold that the glitch statistics call stuck
//! (`glitches.rs`: a hold chance would hardly give a channel moving so
//! around it) is a stuck sensor or the wheel held within the sensor's
//! resolution. A quantised steer in a steady corner (Putnam's log: steps
//! of 0.000581 rad, a resampled log's values between them) holds one
//! level for a few samples because the driver holds the wheel, and was
//! listed "stuck" and "repaired" by less than one step (9 holds, all
//! repairs under 0.00079 rad). A hold is a stuck sensor only where
//!
//! - its repair (the line across it, `repair.rs`) moves some sample by
//!   more than the steer's quantum ([`quantum`]): a smaller repair is no
//!   repair, the held level already reads the steer to its resolution;
//! - and either the car's state changes while it holds beyond what that
//!   steer explains ([`state_moves`]: the curvature r/u leaves the band the
//!   held level ± one quantum gives at the run's own curvature per steer,
//!   by more than the yaw rate's noise) or the hold is long against the
//!   steer's own movement around it ([`long_against_trend`]: the steer's
//!   trend through the hold would have carried it across
//!   [`TREND_QUANTA`] quanta meanwhile).
//!
//! A channel with no quantum (noise on every sample) has a quantum of 0:
//! every repair is one and any trend is long against it, so an exact hold
//! there stays stuck as the statistics say. The lateral acceleration is
//! not read: in a steady corner it is u·r, which the yaw rate carries, and
//! not every log has it. A hold to the end of the record has no far side
//! and is left to the statistics.
//!
//! Units: steer rad, yaw rate rad/s, speed m/s, curvature 1/m, t s.

use super::STUCK_CONTEXT;
use crate::measured::MeasuredRun;

/// Share of the steer's non-zero differences within [`QUANTUM_TOLERANCE`]
/// of one value for that value to be its quantum: noise spread over
/// continuous values puts at most about 1 % in such a window.
const QUANTUM_SHARE: f64 = 0.05;

/// Relative width of a quantum's window: a resampled log writes one step
/// as 0.000581 or 0.000582 rad.
const QUANTUM_TOLERANCE: f64 = 0.02;

/// Quanta the steer's trend through a hold must cross meanwhile for the
/// hold to be long against it: a quantised reading of a steer moving at
/// that pace changes level every third of the hold.
pub(super) const TREND_QUANTA: f64 = 3.0;

/// Least share of the run's 99th-percentile |steer| a sample is steered
/// by to count towards the curvature per steer: near zero the ratio is
/// the noise's.
const GAIN_STEER_SHARE: f64 = 0.25;

/// Fewest samples the curvature per steer is taken from.
const MIN_GAIN_SAMPLES: usize = 20;

/// Robust spreads of the yaw rate's sample differences by which the
/// curvature must leave the held steer's band to say the car moved.
const STATE_SPREADS: f64 = 3.0;

/// The middle value (upper median) of `v`, sorted in place; 0 when empty
/// (computed here as `glitches.rs` does, which asks this file and so
/// cannot be asked back).
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(0.0)
}

/// The quantum of a channel `x`: the smallest value that at least
/// [`QUANTUM_SHARE`] of its non-zero differences lie within
/// [`QUANTUM_TOLERANCE`] of (their median), or 0 where none does.
pub(super) fn quantum(x: &[f64]) -> f64 {
    // Differences below the doubles' rounding of the values are none.
    let ulps = 1e-12 * x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut d: Vec<f64> = x
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|v| *v > ulps)
        .collect();
    d.sort_by(f64::total_cmp);
    let need = (QUANTUM_SHARE * d.len() as f64).max(2.0);
    let mut hi = 0;
    for k in 0..d.len() {
        hi = hi.max(k);
        while hi < d.len() && d[hi] <= d[k] * (1.0 + QUANTUM_TOLERANCE) {
            hi += 1;
        }
        if (hi - k) as f64 >= need {
            return median(&mut d[k..hi]);
        }
    }
    0.0
}

/// What a steer's hold is judged against, from the whole run.
#[derive(Debug, Clone, Copy)]
pub(super) struct SteerScale {
    /// The steer's quantum, rad (0: none).
    pub(super) quantum: f64,
    /// The run's curvature per steer, 1/m per rad: the median r/(u·δ)
    /// over samples steered by at least [`GAIN_STEER_SHARE`] of its
    /// 99th-percentile |δ| and ten quanta (None: too few).
    pub(super) gain: Option<f64>,
    /// The robust spread of the yaw rate's sample differences, rad/s.
    pub(super) yaw_spread: f64,
}

impl SteerScale {
    /// Of `run`, its samples marked `slow` left out.
    pub(super) fn of(run: &MeasuredRun, slow: &[bool]) -> Self {
        let (d, r, u) = (&run.steer, &run.yaw_rate, &run.speed);
        let q = quantum(d);
        let mut a: Vec<f64> = d.iter().map(|v| v.abs()).collect();
        a.sort_by(f64::total_cmp);
        // The nearest-rank 99th percentile.
        let p99 = a
            .len()
            .checked_sub(1)
            .map_or(0.0, |last| a[(last as f64 * 0.99).round() as usize]);
        let least = (GAIN_STEER_SHARE * p99).max(10.0 * q);
        let mut ratios: Vec<f64> = (0..d.len())
            .filter(|&k| !slow[k] && d[k].abs() >= least && d[k] != 0.0 && u[k] > 0.0)
            .map(|k| r[k] / (u[k] * d[k]))
            .collect();
        let gain = (ratios.len() >= MIN_GAIN_SAMPLES).then(|| median(&mut ratios));
        let mut diffs: Vec<f64> = (1..r.len())
            .filter(|&k| !slow[k] && !slow[k - 1])
            .map(|k| r[k] - r[k - 1])
            .collect();
        let md = median(&mut diffs);
        let mut dev: Vec<f64> = diffs.iter().map(|v| (v - md).abs()).collect();
        Self {
            quantum: q,
            gain,
            yaw_spread: 1.4826 * median(&mut dev),
        }
    }
}

/// Whether the repair of the steer's hold at samples `i..j` (the line
/// from sample `i − 1` to sample `j` across it) moves a sample by more
/// than the quantum `q`.
pub(super) fn repair_exceeds(t: &[f64], x: &[f64], i: usize, j: usize, q: f64) -> bool {
    let (l, r) = (i - 1, j);
    (i..j).any(|k| {
        let line = x[l] + (x[r] - x[l]) * (t[k] - t[l]) / (t[r] - t[l]);
        (line - x[k]).abs() > q
    })
}

/// Whether the car's curvature r/u leaves the band the held steer
/// explains (its level ± one quantum, at the run's curvature per steer)
/// over the hold at samples `i..j`, from its first two samples to its
/// last two, by more than [`STATE_SPREADS`] of the yaw rate's spread at
/// the hold's speed: the wheel turned while the sensor read one value.
/// A curvature settling towards the band is the car answering the steer
/// it holds. False where the run shows no curvature per steer.
pub(super) fn state_moves(run: &MeasuredRun, s: &SteerScale, i: usize, j: usize) -> bool {
    let Some(g) = s.gain else {
        return false;
    };
    let v = run.steer[i];
    let (a, b) = (g * (v - s.quantum), g * (v + s.quantum));
    let (lo, hi) = (a.min(b), a.max(b));
    let off = |k: usize| {
        let kappa = run.yaw_rate[k] / run.speed[k].max(f64::MIN_POSITIVE);
        (lo - kappa).max(kappa - hi).max(0.0)
    };
    let start = 0.5 * (off(i) + off(i + 1));
    let end = 0.5 * (off(j - 2) + off(j - 1));
    let noise = STATE_SPREADS * s.yaw_spread / run.speed[i].max(f64::MIN_POSITIVE);
    end - start > noise
}

/// Whether the hold of `x` at samples `i..j` is long against the steer's
/// trend through it: the means of the [`STUCK_CONTEXT`] samples on each
/// side, apart by their centres, give a pace that over the hold's
/// samples crosses more than [`TREND_QUANTA`] quanta `q`. A steady
/// corner's steer dithers about one level and has no trend; a steer
/// dwelling at a peak comes back to where it rose from.
pub(super) fn long_against_trend(x: &[f64], i: usize, j: usize, q: f64) -> bool {
    let c = STUCK_CONTEXT;
    let mean = |from: usize, to: usize| x[from..to].iter().sum::<f64>() / (to - from) as f64;
    let pace = (mean(j, j + c) - mean(i - c, i)).abs() / (j - i + c) as f64;
    (j - i) as f64 * pace > TREND_QUANTA * q
}

/// Whether the steer's exact hold at samples `start..start + len` of `run`
/// is a stuck sensor (module doc); one with fewer than [`STUCK_CONTEXT`]
/// samples on either side is left to the statistics.
pub(super) fn stuck_steer(run: &MeasuredRun, s: &SteerScale, start: usize, len: usize) -> bool {
    let (i, j, x) = (start, start + len, &run.steer);
    if i < STUCK_CONTEXT || j + STUCK_CONTEXT > x.len() {
        return true;
    }
    repair_exceeds(&run.t, x, i, j, s.quantum)
        && (state_moves(run, s, i, j) || long_against_trend(x, i, j, s.quantum))
}

#[cfg(test)]
#[path = "steer_hold_tests.rs"]
mod tests;
