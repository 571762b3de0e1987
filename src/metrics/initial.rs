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
/// initial value) and four of its noise deviations (over the stated
/// window) from the initial value; walking back from there, every
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
    // A noisy steer strays past 5 % of a small step by noise alone (a
    // 1° step logged with 0.035° of noise: one sample in thirteen), and
    // the window cut there held a few samples, whose yaw-rate noise then
    // moved the initial value: the tester's 1° step read the yaw-rate
    // gain 11 % high. The steer has left only where it also stands beyond
    // four of its noise deviations over the whole stated window (robust
    // to a ramp inside it: the median of the differences).
    let mut all: Vec<f64> = steer[..inside]
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .collect();
    let noise_band = HELD_DEVIATIONS * median(&mut all) * MAD_TO_DEVIATION;
    let threshold = (LEFT * step.abs()).max(noise_band);
    let Some(left) = (0..inside).find(|&i| off(i) > threshold) else {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1° step at 1 s, sampled at 100 Hz, its steer logged with white
    /// noise of 3.5 % of the step (a deterministic pseudo-random series).
    fn noisy_step(noise: f64) -> (Vec<f64>, Vec<f64>) {
        let step = 1f64.to_radians();
        let mut state = 12345u64;
        let mut gauss = || {
            // Sum of twelve uniforms less six: unit variance, near Gaussian.
            (0..12)
                .map(|_| {
                    state = state
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (state >> 11) as f64 / (1u64 << 53) as f64
                })
                .sum::<f64>()
                - 6.0
        };
        let t: Vec<f64> = (0..600).map(|i| i as f64 * 0.01).collect();
        let steer = t
            .iter()
            .map(|&x| step * ((x - 1.0) / 0.1).clamp(0.0, 1.0) + noise * step * gauss())
            .collect();
        (t, steer)
    }

    #[test]
    fn a_steer_straying_past_five_percent_by_noise_keeps_the_stated_window() {
        let s = MetricSettings::default();
        let (t, steer) = noisy_step(0.035);
        // The noise alone takes samples past 5 % of the step inside the
        // stated window (what cut it before).
        let level = steer[..50].iter().sum::<f64>() / 50.0;
        let step = 1f64.to_radians();
        assert!(steer[..50].iter().any(|v| v - level > LEFT * step));
        assert_eq!(initial_end(&t, &steer, &s), t[0] + s.pre_window);
    }

    #[test]
    fn a_noisy_steer_that_leaves_inside_the_window_is_still_cut_before_its_ramp() {
        let s = MetricSettings::default();
        let (t, steer) = noisy_step(0.01);
        // The ramp starts at 1 s: with a 1.5 s window the cut falls
        // before it, not at 1.5 s.
        let s = MetricSettings {
            pre_window: 1.5,
            ..s
        };
        let end = initial_end(&t, &steer, &s);
        assert!(end <= 1.0 && end > 0.9, "cut at {end} s");
    }
}
