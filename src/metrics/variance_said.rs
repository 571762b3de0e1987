//! What is said of a total-variance window too short for the response it
//! integrates: `E_x = ∫ (δ̂ − x̂)² dt` over a window that ends before the
//! yaw rate reaches 90 % of its step measures only the start of the
//! response (a 5 ms window gives Er ≈ 0 s). One place words it, so that
//! `metrics` (a measured run) and `simulate` (its simulated step) say the
//! same. Units: s.

use super::StepMetrics;

impl StepMetrics {
    /// The warning of a total-variance window of `window` s that ends
    /// before the yaw rate responds (shorter than its response time), or
    /// before ay does where its variance is measured.
    pub fn variance_window_before_response(&self, window: f64) -> Option<String> {
        if window < self.yaw_rate_response_time {
            return Some(format!(
                "the total-variance window, {} s, ends before the yaw rate responds (its response time is {} s): E_r, E_ay and Er measure only the start of the response; the default is 4 s",
                crate::error::Num(window),
                crate::format::fixed(self.yaw_rate_response_time, 3)
            ));
        }
        // ay responds later than the yaw rate (its lag behind the yaw
        // rate is the sideslip's): a window between the two cuts E_ay and
        // Er short alone (0.2 s against an ay response of 0.345 s read
        // E_ay 27 % low).
        let ay = self.ay_response_time.filter(|t| window < *t)?;
        self.ay_total_variance.is_some().then(|| {
            format!(
                "the total-variance window, {} s, ends before ay responds (its response time is {} s): E_ay and Er measure only the start of its response; the default is 4 s",
                crate::error::Num(window),
                crate::format::fixed(ay, 3)
            )
        })
    }
}
