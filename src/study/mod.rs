//! Tyre cornering stiffness against handling (Wang & Liang): the forward map
//! from front/rear cornering stiffness (k1, k2) to the step-steer metrics,
//! Wang & Liang's Gaussian RBF network that maps Er back to (k1, k2), and the
//! inverse as it really is — one Er value fixes a curve of (k1, k2), not a
//! point — with the best combination on it under a stated preference.
//!
//! Stiffness is per tyre, N/rad inside (files may give N/deg); each axle's
//! tyre is scaled to it at its static wheel load
//! ([`crate::tyre::Tyre::with_cornering_stiffness`]), its friction limit kept.
//! Every combination is simulated with the scenario's step steer and
//! evaluated with [`crate::metrics::step_metrics`]; combinations run in
//! parallel (rayon).

pub mod inverse;
pub mod rbf;

use crate::manoeuvre::Manoeuvre;
use crate::metrics::{step_metrics, MetricSettings, StepMetrics};
use crate::sim::Integrator;
use crate::vehicle::{State, VehicleModel};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Everything needed to evaluate one stiffness combination.
#[derive(Debug, Clone)]
pub struct Study {
    /// The vehicle with its base tyres.
    pub model: VehicleModel,
    /// The manoeuvre (a step steer).
    pub manoeuvre: Manoeuvre,
    /// Integration settings.
    pub integrator: Integrator,
    /// Metric settings.
    pub metrics: MetricSettings,
}

/// One evaluated combination.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Front cornering stiffness per tyre, N/rad.
    pub k_front: f64,
    /// Rear cornering stiffness per tyre, N/rad.
    pub k_rear: f64,
    /// Its metrics (`None` when the response has no steady state).
    pub metrics: Option<StepMetrics>,
}

impl Study {
    /// The model with each axle's tyres scaled to the given stiffness.
    pub fn model_for(&self, k_front: f64, k_rear: f64) -> VehicleModel {
        let (sf, sr) = self.model.vehicle.static_axle_loads();
        let mut m = self.model.clone();
        m.front = self.model.front.with_cornering_stiffness(k_front, 0.5 * sf);
        m.rear = self.model.rear.with_cornering_stiffness(k_rear, 0.5 * sr);
        m
    }

    /// Simulates one combination.
    pub fn evaluate(&self, k_front: f64, k_rear: f64) -> Sample {
        let m = self.model_for(k_front, k_rear);
        let h = self.integrator.run(&m, &self.manoeuvre, State::default());
        let metrics = step_metrics(
            &h.t,
            &h.steer,
            &h.yaw_rate,
            Some(&h.ay),
            Some(&h.beta),
            &self.metrics,
        )
        .ok();
        Sample {
            k_front,
            k_rear,
            metrics,
        }
    }

    /// Er of one combination (NaN without a steady state).
    pub fn er(&self, k_front: f64, k_rear: f64) -> f64 {
        self.evaluate(k_front, k_rear)
            .metrics
            .and_then(|m| m.er)
            .unwrap_or(f64::NAN)
    }

    /// Simulates every combination in parallel; `progress` counts them.
    pub fn evaluate_all(&self, pairs: &[(f64, f64)], progress: &AtomicUsize) -> Vec<Sample> {
        pairs
            .par_iter()
            .map(|&(kf, kr)| {
                let s = self.evaluate(kf, kr);
                progress.fetch_add(1, Ordering::Relaxed);
                s
            })
            .collect()
    }
}

/// A metric of a sample by name (the CSV column names).
pub fn metric(m: &StepMetrics, name: &str) -> f64 {
    match name {
        "er" => m.er.unwrap_or(f64::NAN),
        "yaw_rate_total_variance" => m.yaw_rate_total_variance,
        "ay_total_variance" => m.ay_total_variance.unwrap_or(f64::NAN),
        "yaw_rate_response_time" => m.yaw_rate_response_time,
        "ay_response_time" => m.ay_response_time.unwrap_or(f64::NAN),
        "yaw_rate_overshoot" => m.yaw_rate_overshoot,
        "yaw_rate_peak_time" => m.yaw_rate_peak_time.unwrap_or(f64::NAN),
        "yaw_rate_gain" => m.yaw_rate_gain,
        "beta_steady" => m.beta_steady.unwrap_or(f64::NAN),
        "tb" => m.tb.unwrap_or(f64::NAN),
        _ => f64::NAN,
    }
}

/// Metric names in table order.
pub const METRICS: [&str; 10] = [
    "er",
    "yaw_rate_total_variance",
    "ay_total_variance",
    "yaw_rate_response_time",
    "yaw_rate_peak_time",
    "yaw_rate_overshoot",
    "ay_response_time",
    "yaw_rate_gain",
    "beta_steady",
    "tb",
];

#[cfg(test)]
mod tests;
