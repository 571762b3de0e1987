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
    let pts: Vec<(f64, f64)> = pairs
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    if pts.len() < MIN_PAIRS {
        return None;
    }
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxx, sxy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (x - mx), b + (x - mx) * (y - my))
    });
    let mut xs: Vec<f64> = pts.iter().map(|p| p.0).collect();
    xs.sort_by(f64::total_cmp);
    let at = |q: f64| xs[((q * (xs.len() - 1) as f64).round() as usize).min(xs.len() - 1)];
    let spread = at(0.95) - at(0.05);
    let k = sxy / sxx;
    Some((k, my - k * mx, spread))
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
}
