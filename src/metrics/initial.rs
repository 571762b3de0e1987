//! The end of a measured record's initial window: the stated
//! `pre_window` from the first sample, cut at the last sample before the
//! steer leaves its initial value. A log whose window reaches into the
//! steer's ramp by a sample took that sample's steer into the initial
//! value: the tester's ramped step logged at 12.5 Hz with a sample 20 %
//! up the ramp inside the window read the steer step 2.9 % small, the
//! yaw-rate gain 2.7 % high and E_r 16 % high. The check of the step's
//! shape (`step_shape.rs`) tolerates a move within the steer's noise or
//! resolution, and a noise-free steer of a few values reads its levels as
//! a coarse grid, so it let that sample through; here no noise is read
//! from levels the steer holds exactly. Units: s; the steer's unit.

use super::MetricSettings;
use crate::measured::clean::median;

/// The steer's share of its step from which it has surely left its
/// initial value (the onset of the total-variance window).
const LEFT: f64 = 0.05;
/// White-noise deviations of the steer before the step within which it
/// is still at its initial value.
const HELD_DEVIATIONS: f64 = 4.0;
/// A white noise's deviation per median absolute difference of
/// successive samples, 1/(0.6745·√2) (as `noise.rs` reads it).
const MAD_TO_DEVIATION: f64 = 1.0 / (0.6745 * std::f64::consts::SQRT_2);

/// The end of the initial window of a record sampled at `t` with the raw
/// steer `steer`, s: `t[0] + pre_window`, or, where the steer leaves its
/// initial value (the median over that window) before then, the time of
/// the last sample before it did. The steer has left where it first
/// stands 5 % of its step (the median of the steady window against the
/// initial value) from the initial value; walking back from there, every
/// sample beyond four of the steer's noise deviations (its differences'
/// robust spread before that point; 0 for a steer held exactly) is on the
/// way. Where the steer does not leave in the window, or leaves at its
/// first sample (a record cut at its step, refused by the shape check),
/// the stated window stands.
pub(crate) fn initial_end(t: &[f64], steer: &[f64], s: &MetricSettings) -> f64 {
    let nominal = t[0] + s.pre_window;
    let inside = t.partition_point(|&x| x <= nominal);
    let last = t[t.len() - 1];
    let late: Vec<f64> = (0..t.len())
        .filter(|&i| t[i] >= last - s.steady_window)
        .map(|i| steer[i])
        .collect();
    let level = median(&mut steer[..inside].to_vec());
    let step = median(&mut late.clone()) - level;
    if inside < 2 || step == 0.0 || !step.is_finite() {
        return nominal;
    }
    let off = |i: usize| (steer[i] - level) * step.signum();
    let Some(left) = (0..inside).find(|&i| off(i) > LEFT * step.abs()) else {
        return nominal;
    };
    let mut d: Vec<f64> = steer[..left + 1]
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .collect();
    let band = HELD_DEVIATIONS * median(&mut d) * MAD_TO_DEVIATION;
    let mut k = left;
    while k > 0 && off(k) > band {
        k -= 1;
    }
    match off(k) > band {
        true => nominal,
        false => t[k].min(nominal),
    }
}
