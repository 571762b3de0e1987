//! Whether a step response has settled in its steady window: its spread
//! about the steady value beyond its white noise, within 2 % of the step,
//! or within what the noise leaves unknown of the step itself (a noisy
//! short log). Spreads and noises relative to the step (dimensionless).

use super::Normalised;

/// The spread about the steady value, relative to the step, beyond which
/// a response has not settled.
pub(super) const SETTLED_SPREAD: f64 = 0.02;

/// The scale a sideslip's spread is judged on, rad: its step `beta_step`,
/// or the steer step `steer_step` where that is larger (a sideslip that
/// barely changes, near the speed where it changes sign, is not judged
/// against its own near-zero step). A car sliding at its grip limit keeps
/// its yaw rate and lateral acceleration while its sideslip grows: only
/// the sideslip shows that it has not settled.
pub(super) fn sideslip_scale(beta_step: f64, steer_step: f64) -> f64 {
    beta_step.abs().max(steer_step.abs())
}

/// Whether a response whose steady window spreads by `spread` (relative to
/// the step) has settled, given the white noise `noise` left in it after
/// the filter (relative alike): the spread beyond the noise, `√(spread² −
/// noise²)`, within [`SETTLED_SPREAD`]. Unfiltered, a gyro's noise of 3 %
/// of the step is no motion.
pub(super) fn settled(spread: f64, noise: f64) -> bool {
    (spread * spread - noise * noise).max(0.0).sqrt() < SETTLED_SPREAD
}

/// [`settled`] for a measured response `n` whose noise after the filter is
/// `noise`, its band widened to what the noise leaves unknown of the step
/// itself: the step is the difference of two window means of `N` samples,
/// each uncertain by `σ/√N` (σ the raw noise relative to the step), so
/// it is known to `2·σ·√(2/N)` (two deviations of the difference). A
/// spread judged against a band finer than the step is known to calls a
/// noisy short log unsettled for its noise; `√(2/N)` is also the relative
/// deviation of a sample variance, which the spread beyond the noise is
/// judged by.
pub(super) fn settled_within_noise(n: &Normalised, noise: f64) -> bool {
    let band = 2.0 * n.noise * (2.0 / n.samples.max(1) as f64).sqrt();
    settled(n.spread, noise) || (n.spread * n.spread - noise * noise).max(0.0).sqrt() < band
}
