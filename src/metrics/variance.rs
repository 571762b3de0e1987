//! Guo Konghui's total variance (Wang & Liang): `E_x = ∫ (δ̂ − x̂)² dt` of
//! two normalised records on one time grid, by the trapezoid. Units: s.

/// ∫ (a − b)² dt over [from, to] (trapezoid, partial end intervals
/// interpolated).
pub(super) fn total_variance(t: &[f64], a: &[f64], b: &[f64], from: f64, to: f64) -> f64 {
    let mut e = 0.0;
    for i in 1..t.len() {
        let (lo, hi) = (t[i - 1].max(from), t[i].min(to));
        if hi <= lo {
            continue;
        }
        let h = t[i] - t[i - 1];
        let at = |x: f64| {
            let w = (x - t[i - 1]) / h;
            (a[i - 1] - b[i - 1]) * (1.0 - w) + (a[i] - b[i]) * w
        };
        let (d0, d1) = (at(lo), at(hi));
        e += 0.5 * (d0 * d0 + d1 * d1) * (hi - lo);
    }
    e
}
