//! What is said of a total-variance window too short for the response it
//! integrates: `E_x = ∫ (δ̂ − x̂)² dt` over a window that ends before the
//! yaw rate reaches 90 % of its step measures only the start of the
//! response (a 5 ms window gives Er ≈ 0 s). One place words it, so that
//! `metrics` (a measured run) and `simulate` (its simulated step) say the
//! same. Units: s.

use super::StepMetrics;

impl StepMetrics {
    /// The warning of a total-variance window of `window` s that ends
    /// before the yaw rate responds (shorter than its response time).
    pub fn variance_window_before_response(&self, window: f64) -> Option<String> {
        (window < self.yaw_rate_response_time).then(|| {
            format!(
                "the total-variance window, {} s, ends before the yaw rate responds (its response time is {} s): E_r, E_ay and Er measure only the start of the response; the default is 4 s",
                crate::error::Num(window),
                crate::format::fixed(self.yaw_rate_response_time, 3)
            )
        })
    }
}
