//! The zero-phase low-pass `handling metrics` runs over a measured record
//! before its metrics: a second-order Butterworth section (bilinear
//! transform, pre-warped; Butterworth 1930) run forward and backward, so
//! that no crossing moves. Units: s, Hz; the channel's own.

/// Zero-phase low-pass: a second-order Butterworth section (bilinear
/// transform, pre-warped) run forward then backward, each pass started in
/// the steady state of its first sample so the ends do not ring.
pub(crate) fn zero_phase_low_pass(x: &[f64], dt: f64, cutoff_hz: f64) -> Vec<f64> {
    let k = (std::f64::consts::PI * cutoff_hz * dt).tan();
    let norm = 1.0 / (1.0 + std::f64::consts::SQRT_2 * k + k * k);
    let b0 = k * k * norm;
    let (b1, b2) = (2.0 * b0, b0);
    let a1 = 2.0 * (k * k - 1.0) * norm;
    let a2 = (1.0 - std::f64::consts::SQRT_2 * k + k * k) * norm;
    let pass = |v: &mut Vec<f64>| {
        let Some(&first) = v.first() else { return };
        let (mut x1, mut x2, mut y1, mut y2) = (first, first, first, first);
        for s in v.iter_mut() {
            let x0 = *s;
            let y0 = b0 * x0 + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
            (x2, x1, y2, y1) = (x1, x0, y1, y0);
            *s = y0;
        }
    };
    let mut y = x.to_vec();
    pass(&mut y);
    y.reverse();
    pass(&mut y);
    y.reverse();
    y
}
