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
//! evaluated as `simulate` evaluates one run
//! ([`crate::metrics::simulated_step_metrics`]: on the Dormand–Prince dense
//! solution, the peak located between rows; on the rows under RK4 or a
//! low-pass); combinations run in parallel (rayon).

pub(crate) mod inverse;
pub(crate) mod rbf;
pub(crate) mod response;
pub(crate) mod stiffness;

pub use inverse::MapEdge;
pub use response::{NotHandling, ReportedSample, Response, SideslipEnd};
pub use stiffness::{NoTyreHas, StudyAxle};

use crate::error::{named, NameKind, OptionsError};
use crate::manoeuvre::Manoeuvre;
use crate::metrics::{simulated_step_metrics, MetricSettings, StepMetrics};
use crate::sim::Integrator;
use crate::tyre::{Tyre, TyreModel};
use crate::vehicle::{State, VehicleModel};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// Front cornering stiffness per tyre, N/rad.
    pub k_front: f64,
    /// Rear cornering stiffness per tyre, N/rad.
    pub k_rear: f64,
    /// Its metrics (`None` when the response has no steady state).
    pub metrics: Option<StepMetrics>,
    /// Where neither axle's tyre has a friction limit and the combination
    /// oversteers past its critical speed: (critical speed √(−l/K), the
    /// step's speed), m/s. The linear car's steady turn is then unstable
    /// (Genta 1997; Milliken & Milliken 1995) and its response diverges
    /// with no grip limit to stop it: [`Response::Unstable`].
    #[serde(default)]
    pub unstable: Option<(f64, f64)>,
    /// Neither axle's tyre has a friction limit (linear): a large sideslip
    /// is then no slide past a grip ([`Response::LargeSideslip`]).
    #[serde(default)]
    pub unlimited: bool,
}

impl Study {
    /// The model with each axle's tyres scaled to the given stiffness.
    pub(crate) fn model_for(&self, k_front: f64, k_rear: f64) -> VehicleModel {
        let (sf, sr) = self.model.vehicle.static_axle_loads();
        let mut m = self.model.clone();
        m.front = self.model.front.with_cornering_stiffness(k_front, 0.5 * sf);
        m.rear = self.model.rear.with_cornering_stiffness(k_rear, 0.5 * sr);
        m
    }

    /// Simulates one combination (N/rad per tyre) as given: the study
    /// file's reader has checked its values; values from elsewhere go
    /// through [`Study::evaluate_in`], which checks them as the file's.
    pub fn evaluate(&self, k_front: f64, k_rear: f64) -> Sample {
        let m = self.model_for(k_front, k_rear);
        // Measured as `simulate` measures the same car: on the dense
        // solution where there is one (the peak located between rows, to
        // the tolerance), on the rows otherwise (RK4, a low-pass).
        let sim = self
            .integrator
            .simulate(&m, &self.manoeuvre, State::default());
        let metrics =
            simulated_step_metrics(&self.integrator, &m, &self.manoeuvre, &sim, &self.metrics).ok();
        Sample {
            k_front,
            k_rear,
            metrics,
            unstable: self.unstable(&m),
            unlimited: self.unlimited(&m),
        }
    }

    /// Whether neither of `m`'s axles' tyres has a friction limit.
    fn unlimited(&self, m: &VehicleModel) -> bool {
        let (front, rear) = m.vehicle.static_axle_loads();
        let mu = self.integrator.friction;
        let unlimited = |t: &Tyre, fz: f64| t.friction_coefficient(0.5 * fz, mu).is_infinite();
        unlimited(&m.front, front) && unlimited(&m.rear, rear)
    }

    /// (critical speed, step speed), m/s, where `m`'s tyres have no
    /// friction limit on either axle and the step runs above the critical
    /// speed ([`Sample::unstable`]). With a limit on an axle the car
    /// finds the limit instead, and its response says what happened there.
    fn unstable(&self, m: &VehicleModel) -> Option<(f64, f64)> {
        if !self.unlimited(m) {
            return None;
        }
        let u_crit = m.critical_speed()?;
        let mn = &self.manoeuvre;
        let speed = [mn.start_time(), mn.end_time()]
            .map(|t| mn.speed(t))
            .into_iter()
            .fold(0.0_f64, f64::max);
        (speed > u_crit).then_some((u_crit, speed))
    }

    /// Er of one combination (NaN where the response is no handling
    /// response, [`Response`]).
    pub fn er(&self, k_front: f64, k_rear: f64) -> f64 {
        self.value(Metric::Er, k_front, k_rear)
    }

    /// `metric` of one combination (NaN where the response is no handling
    /// response, [`Response`]).
    pub fn value(&self, metric: Metric, k_front: f64, k_rear: f64) -> f64 {
        metric.of_sample(&self.evaluate(k_front, k_rear))
    }

    /// Simulates every combination in parallel; `progress` counts them.
    /// A combination listed twice is simulated once: Wang & Liang's RBF
    /// pairs lie on the map's grid (all 51 of the bundled study's, the
    /// same bits: `io/study.rs` adds the offset in the file's unit), and
    /// the same car gives the same sample.
    pub(crate) fn evaluate_all(&self, pairs: &[(f64, f64)], progress: &AtomicUsize) -> Vec<Sample> {
        let (unique, of) = first_of_each(pairs);
        let samples: Vec<Sample> = unique
            .par_iter()
            .map(|&i| {
                let s = self.evaluate(pairs[i].0, pairs[i].1);
                progress.fetch_add(1, Ordering::Relaxed);
                s
            })
            .collect();
        progress.fetch_add(pairs.len() - unique.len(), Ordering::Relaxed);
        of.iter().map(|&u| samples[u]).collect()
    }
}

/// The index in `pairs` of each distinct combination's first listing (by
/// its exact bits), and for every listing the position of its combination
/// among those.
fn first_of_each(pairs: &[(f64, f64)]) -> (Vec<usize>, Vec<usize>) {
    let mut seen = std::collections::HashMap::new();
    let mut unique = Vec::new();
    let of = pairs
        .iter()
        .enumerate()
        .map(|(i, p)| {
            *seen
                .entry((p.0.to_bits(), p.1.to_bits()))
                .or_insert_with(|| {
                    unique.push(i);
                    unique.len() - 1
                })
        })
        .collect();
    (unique, of)
}

/// A step-steer metric of the study: a column of `study.csv` and a metric
/// an inverse query names. Its serde name is the column name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Er, the combined total variance (Wang & Liang), s.
    Er,
    /// Total variance of the yaw rate, s.
    YawRateTotalVariance,
    /// Total variance of the lateral acceleration, s.
    AyTotalVariance,
    /// Yaw-rate response time, s.
    YawRateResponseTime,
    /// Yaw-rate peak time, s.
    YawRatePeakTime,
    /// Yaw-rate overshoot, %.
    YawRateOvershoot,
    /// Lateral-acceleration response time, s.
    AyResponseTime,
    /// Steady yaw-rate gain, 1/s.
    YawRateGain,
    /// Steady sideslip, rad.
    BetaSteady,
    /// TB (GB/T 6323), s·deg.
    Tb,
}

impl Metric {
    /// Every metric, in the order of the columns of `study.csv`.
    pub const ALL: [Metric; 10] = [
        Metric::Er,
        Metric::YawRateTotalVariance,
        Metric::AyTotalVariance,
        Metric::YawRateResponseTime,
        Metric::YawRatePeakTime,
        Metric::YawRateOvershoot,
        Metric::AyResponseTime,
        Metric::YawRateGain,
        Metric::BetaSteady,
        Metric::Tb,
    ];

    /// The column name.
    pub const fn name(self) -> &'static str {
        match self {
            Metric::Er => "er",
            Metric::YawRateTotalVariance => "yaw_rate_total_variance",
            Metric::AyTotalVariance => "ay_total_variance",
            Metric::YawRateResponseTime => "yaw_rate_response_time",
            Metric::YawRatePeakTime => "yaw_rate_peak_time",
            Metric::YawRateOvershoot => "yaw_rate_overshoot",
            Metric::AyResponseTime => "ay_response_time",
            Metric::YawRateGain => "yaw_rate_gain",
            Metric::BetaSteady => "beta_steady",
            Metric::Tb => "tb",
        }
    }

    /// The metric's value in a response's metrics (`None`: the response
    /// does not have it, e.g. no lateral acceleration or no peak).
    pub fn of(self, m: &StepMetrics) -> Option<f64> {
        match self {
            Metric::Er => m.er,
            Metric::YawRateTotalVariance => Some(m.yaw_rate_total_variance),
            Metric::AyTotalVariance => m.ay_total_variance,
            Metric::YawRateResponseTime => Some(m.yaw_rate_response_time),
            Metric::AyResponseTime => m.ay_response_time,
            // The inverse reads a response without a peak (an overshoot
            // below the threshold) as 0, so that its contours close over
            // the well-damped cars; study.csv and maps.png do not
            // ([`Metric::measured`]).
            Metric::YawRateOvershoot => Some(m.yaw_rate_overshoot.unwrap_or(0.0)),
            Metric::YawRatePeakTime => m.yaw_rate_peak_time,
            Metric::YawRateGain => Some(m.yaw_rate_gain),
            Metric::BetaSteady => m.beta_steady,
            Metric::Tb => m.tb,
        }
    }

    /// The metric as the step measures it: [`Metric::of`], except that an
    /// overshoot below the peak threshold (no peak) is `None`, not a
    /// measured 0 (the metrics chapter) — `study.csv`'s cells and
    /// `maps.png`'s, where the inverse's contours read it as 0.
    pub fn measured(self, m: &StepMetrics) -> Option<f64> {
        match self {
            Metric::YawRateOvershoot => m.yaw_rate_overshoot,
            _ => self.of(m),
        }
    }

    /// [`Metric::measured`] of a sample, NaN where it has none, as
    /// [`Metric::of_sample`].
    pub(crate) fn measured_of_sample(self, s: &Sample) -> f64 {
        s.handling_metrics()
            .and_then(|m| self.measured(&m))
            .unwrap_or(f64::NAN)
    }

    /// The metric of a sample, NaN where it has none or where its response
    /// is no handling response ([`Response`]: a sliding or diverging car's
    /// numbers are not its handling) — the cells of maps and tables.
    pub(crate) fn of_sample(self, s: &Sample) -> f64 {
        s.handling_metrics()
            .and_then(|m| self.of(&m))
            .unwrap_or(f64::NAN)
    }
}

impl std::fmt::Display for Metric {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Metric {
    type Err = OptionsError;
    fn from_str(s: &str) -> Result<Self, OptionsError> {
        named(&Self::ALL, Metric::name, NameKind::Metric, s)
    }
}

/// Metric names in table order ([`Metric::ALL`]'s names).
pub(crate) const METRICS: [&str; 10] = {
    let mut names = [""; 10];
    let mut i = 0;
    while i < names.len() {
        names[i] = Metric::ALL[i].name();
        i += 1;
    }
    names
};

/// A target of the inverse problem: a metric's value within a tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Target {
    /// The metric.
    pub metric: Metric,
    /// Its target value.
    pub value: f64,
    /// The tolerance of the region.
    pub tolerance: f64,
}

/// The unit of cornering stiffness in study files and reports (values are
/// N/rad inside).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum StiffnessUnit {
    /// N/deg.
    #[default]
    #[serde(rename = "N/deg")]
    NPerDeg,
    /// N/rad.
    #[serde(rename = "N/rad")]
    NPerRad,
}

impl StiffnessUnit {
    /// The name in files and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            StiffnessUnit::NPerDeg => "N/deg",
            StiffnessUnit::NPerRad => "N/rad",
        }
    }
    /// N/rad per unit.
    pub(crate) fn to_si(self) -> f64 {
        match self {
            StiffnessUnit::NPerDeg => 180.0 / std::f64::consts::PI,
            StiffnessUnit::NPerRad => 1.0,
        }
    }
}

impl std::fmt::Display for StiffnessUnit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::str::FromStr for StiffnessUnit {
    type Err = OptionsError;
    fn from_str(s: &str) -> Result<Self, OptionsError> {
        let all = [StiffnessUnit::NPerDeg, StiffnessUnit::NPerRad];
        named(&all, StiffnessUnit::as_str, NameKind::Unit, s)
    }
}

#[cfg(test)]
mod tests;
