//! How far a straight line across a hole in time can be from the yaw rate
//! the logger did not write: the error bound of linear interpolation,
//! |r''|·L²/8 for a hole of length L between the samples either side
//! (the remainder of the two-point interpolant; any numerical analysis
//! text, e.g. Burden & Faires 2011, Theorem 3.3), with the curvature r''
//! read from the samples around the hole by a least-squares parabola.
//!
//! Why it decides whether a hole beside the peak hides it: the noise
//! already makes the peak's value uncertain by its deviation σ, and its
//! time by the width over which the curve stays within σ of its top,
//! √(2σ/|r''|) on each side. A hole whose bound is at most σ moves the
//! value by no more, and its time by at most L/2 ≤ √(2σ/|r''|): the noise's
//! own reach. One missing row at 100 Hz beside a yaw-rate peak bounds at
//! about 0.01 % of the step, where the noise was 1.4 %, and withholding the
//! peak for it threw a measured overshoot away. Units: s, rad/s, rad/s³.

use crate::stats::least_squares_parabola;

/// Fewest samples a parabola is fitted to: three fix it, two more give
/// the noise a margin.
const MIN_SAMPLES: usize = 5;

/// The largest error, rad/s, of the straight line across the hole from
/// `from` to `to` (s, the samples either side) in the yaw rate `r` at
/// times `t`, its curvature read over `window` (s) each side of the hole;
/// `None` where fewer than [`MIN_SAMPLES`] samples lie there.
pub(super) fn interpolation_bound(
    t: &[f64],
    r: &[f64],
    from: f64,
    to: f64,
    window: f64,
) -> Option<f64> {
    let length = to - from;
    curvature(t, r, from - window, to + window, 0.5 * (from + to))
        .map(|c| c.abs() * length * length / 8.0)
}

/// The second derivative, rad/s³, of the least-squares parabola through
/// the finite samples of `r` at times `t` within `[lo, hi]`, about `mid`
/// (time scaled by the window's half-width for the sums' conditioning).
fn curvature(t: &[f64], r: &[f64], lo: f64, hi: f64, mid: f64) -> Option<f64> {
    let w = (0.5 * (hi - lo)).max(f64::MIN_POSITIVE);
    let points = t
        .iter()
        .zip(r)
        .filter(|(ti, ri)| !(**ti < lo || **ti > hi) && ri.is_finite())
        .map(|(ti, ri)| ((ti - mid) / w, *ri));
    let (c, n) = least_squares_parabola(points)?;
    (n >= MIN_SAMPLES).then(|| 2.0 * c[2] / (w * w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parabolas_curvature_is_read_exactly_and_bounds_its_line() {
        // r = 0.06 − 0.5·(t − 1.4)²: r'' = −1 rad/s³.
        let t: Vec<f64> = (0..300)
            .map(|i| f64::from(i) * 0.01)
            .filter(|t| (t - 1.40).abs() > 0.015)
            .collect();
        let r: Vec<f64> = t.iter().map(|t| 0.06 - 0.5 * (t - 1.4).powi(2)).collect();
        let c = curvature(&t, &r, 1.2, 1.6, 1.4).unwrap();
        assert!((c + 1.0).abs() < 1e-9, "{c}");
        // The line from 1.39 to 1.41 misses the top by 0.5·0.01² = 5e-5,
        // which is |r''|·L²/8 with L = 0.02.
        let b = interpolation_bound(&t, &r, 1.39, 1.41, 0.1).unwrap();
        assert!((b - 5e-5).abs() < 1e-12, "{b}");
    }

    #[test]
    fn too_few_samples_give_no_bound() {
        let t = [0.0, 0.01, 0.02, 0.1];
        let r = [0.0, 0.1, 0.2, 0.3];
        assert_eq!(interpolation_bound(&t, &r, 0.02, 0.1, 0.0), None);
    }
}
