//! The zero-phase low-pass `handling metrics` runs over a measured record
//! before its metrics: a second-order Butterworth section (bilinear
//! transform, pre-warped; Butterworth 1930) run forward and backward, so
//! that no crossing moves; and the rate it must stay below to be applied
//! ([`FILTER_LIMIT`]). Units: s, Hz; the channel's own.

/// The share of the sampling rate a low-pass must stay below to be
/// applied: at or above it the run is left unfiltered (a Butterworth
/// designed near Nyquist has its poles at the unit circle).
pub(crate) const FILTER_LIMIT: f64 = 0.4;

/// Whether a low-pass at `hz` is below [`FILTER_LIMIT`] of the rate of
/// samples `dt` (s) apart. A logger's times are decimal numbers a binary
/// float does not hold (0.02 s is 0.0199999… or 0.0200000…1), so the
/// median interval of a 50 Hz log can put 0.4 × its rate a hair above
/// 20 Hz: the comparison allows 1 ppm, and 20 Hz on a 50 Hz log is at
/// the limit, as the book says (`--filter-hz 20` had filtered it).
pub(crate) fn below_filter_limit(hz: f64, dt: f64) -> bool {
    hz * dt < FILTER_LIMIT * (1.0 - 1e-6)
}

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
