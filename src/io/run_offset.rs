//! Whether a measured run's `ay` differs from its kinematic lateral
//! acceleration (`u·r`, plus `d(u·β)/dt` and `g·sin(bank)` where the run
//! has them; ISO 8855 signs, SI units as `FORMATS.md` asks) by a constant
//! rather than by a factor. The unit checks ([`super::run_units`],
//! [`super::run_slope`]) read the ratio `ay/(u·r)` through the origin: a
//! yaw-rate gyro's zero offset of 0.03 rad/s at 25 m/s adds 0.75 m/s² to
//! `u·r`, and on a step of 1.1 m/s² the ratio reads 0.59, a speed in mph
//! (0.447) to a band wide enough for a unit. A line with an intercept
//! tells them apart: a unit scales `ay` against `u·r` (slope 1/2.237,
//! intercept 0), an offset shifts it (slope 1, intercept `−u·δr` or the
//! accelerometer's own offset). Where the slope with an intercept is a
//! car's (`run_slope`'s `SI_RANGE`, passed in) over a spread of `u·r` that fixes it, no unit is
//! named: the offset is the replay's and the diagnosis's to say (as the
//! channel's mean difference from the model).

use crate::stats::{mean, CentredSums};

/// The least spread (5th to 95th percentile) of the kinematic lateral
/// acceleration that fixes a slope with an intercept, m/s²: five times a
/// lateral accelerometer's noise (0.1 m/s²), half of the turning level of
/// the unit checks.
pub const SPREAD: f64 = 0.5;

/// The fewest pairs fitted.
const MIN_PAIRS: usize = 6;

/// Least squares of `y = k·x + c` over `pairs` (x the kinematic lateral
/// acceleration, y `ay`): the slope `k` and intercept `c`, with the
/// spread of `x`; None with fewer than [`MIN_PAIRS`] finite pairs.
pub(super) fn line(pairs: impl Iterator<Item = (f64, f64)>) -> Option<(f64, f64, f64)> {
    let (xs, ys): (Vec<f64>, Vec<f64>) = pairs
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .unzip();
    if xs.len() < MIN_PAIRS {
        return None;
    }
    let k = CentredSums::of(&xs, &ys).slope();
    let c = mean(&ys) - k * mean(&xs);
    let mut xs = xs;
    xs.sort_by(f64::total_cmp);
    let at = |q: f64| xs[((q * (xs.len() - 1) as f64).round() as usize).min(xs.len() - 1)];
    Some((k, c, at(0.95) - at(0.05)))
}

/// Whether `ay` against the kinematic lateral acceleration is a car's
/// line shifted by a constant ([`line`]'s slope within `si`, the slopes
/// of a run in SI units, over a spread of at least [`SPREAD`]): then the
/// gap is an offset, and no unit is named.
pub(super) fn an_offset(pairs: impl Iterator<Item = (f64, f64)>, si: (f64, f64)) -> bool {
    match line(pairs) {
        Some((k, _, spread)) => spread >= SPREAD && (si.0..=si.1).contains(&k),
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const SI: (f64, f64) = (0.6, 1.6);

    /// A yaw-rate offset is an offset; a speed in mph is not, with or
    /// without an accelerometer offset besides; a run with no spread
    /// cannot tell.
    #[test]
    fn an_offset_shifts_and_a_unit_scales() {
        let x: Vec<f64> = (0..100).map(|i| if i < 20 { 0.0 } else { 1.08 }).collect();
        let shifted = x.iter().map(|v| (v + 0.75, *v));
        let (k, c, spread) = line(shifted.clone()).unwrap();
        assert!(
            (k - 1.0).abs() < 1e-12 && (c + 0.75).abs() < 1e-12,
            "{k} {c}"
        );
        assert!((spread - 1.08).abs() < 1e-12);
        assert!(an_offset(shifted, SI));
        let mph = x.iter().map(|v| (v * 2.23694, *v));
        assert!(!an_offset(mph.clone(), SI));
        let (k, c, _) = line(mph).unwrap();
        assert!((k - 1.0 / 2.23694).abs() < 1e-12 && c.abs() < 1e-12);
        assert!(!an_offset(x.iter().map(|v| (v * 2.23694, v + 0.2)), SI));
        assert!(!an_offset((0..100).map(|_| (1.83, 1.08)), SI));
    }

    /// The line as it was written before it was built on `CentredSums`
    /// (means summed as Σ(x/n), where `CentredSums` divides Σx by n).
    fn by_hand(pts: &[(f64, f64)]) -> (f64, f64) {
        let n = pts.len() as f64;
        let (mx, my) = pts
            .iter()
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
        let (sxx, sxy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (x - mx), b + (x - mx) * (y - my))
        });
        let k = sxy / sxx;
        (k, my - k * mx)
    }

    /// The line on the shared centred sums is the one written out by
    /// hand, on a step, a noisy ramp, a scaled and shifted sine and a ramp
    /// with a gap (non-finite pairs dropped): bit for bit where the means
    /// are exact (multiples of 1/8 over 64 pairs, the closed form
    /// y = 4x − 3), else to the rounding of the two ways of summing the
    /// means (a few parts in 10¹⁵).
    #[test]
    fn the_line_on_centred_sums_is_the_line_by_hand() {
        let eighths = (0..64).map(|i| (0.125 * i as f64, 0.5 * i as f64 - 3.0));
        let (k, c, _) = line(eighths).unwrap();
        assert_eq!(
            (k.to_bits(), c.to_bits()),
            (4.0f64.to_bits(), (-3.0f64).to_bits())
        );
        let step: Vec<(f64, f64)> = (0..100)
            .map(|i| if i < 20 { (0.75, 0.0) } else { (1.83, 1.08) })
            .collect();
        let ramp: Vec<(f64, f64)> = (0..257)
            .map(|i| {
                let x = 0.013 * i as f64;
                (
                    x,
                    0.9 * x - 0.31 + 0.02 * ((i * 7919 % 101) as f64 / 101.0 - 0.5),
                )
            })
            .collect();
        let sine: Vec<(f64, f64)> = (0..1000)
            .map(|i| {
                let x = 4.0 * (0.01 * i as f64).sin();
                (x, x / 2.23694 + 0.17)
            })
            .collect();
        let mut gap = ramp.clone();
        gap[3].1 = f64::NAN;
        gap[40].0 = f64::INFINITY;
        for pts in [step, ramp, sine, gap] {
            let (k, c, _) = line(pts.iter().copied()).unwrap();
            let finite: Vec<(f64, f64)> = pts
                .into_iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            let (k0, c0) = by_hand(&finite);
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * b.abs();
            assert!(close(k, k0) && close(c, c0), "{k} {c} against {k0} {c0}");
        }
    }
}
