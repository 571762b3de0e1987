//! Study files (README, "Study files"): a scenario's tables (vehicle, tyres,
//! road, model, a step-steer manoeuvre, simulation, metrics) plus the
//! cornering-stiffness grid, Wang & Liang's RBF pairs and inverse targets.
//! Stiffness values are per tyre in the file's `unit` (`N/deg` or `N/rad`),
//! converted to N/rad on reading.

use super::scenario::{
    resolve_scenario, ManoeuvreSpec, Road, Scenario, ScenarioFile, SimulationSettings, TyreRefs,
};
use super::toml_file::{param_error, TomlSource};
use crate::error::{InputError, ParamError};
use crate::metrics::MetricSettings;
use crate::vehicle::{ModelOptions, Vehicle};
use serde::Deserialize;
use std::path::Path;

/// Stiffness values: a list, `{from, to, step}` or `{from, to, count}`.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum Axis {
    /// Explicit values.
    List(Vec<f64>),
    /// By step.
    Step {
        /// First value.
        from: f64,
        /// Last value (included when on the step).
        to: f64,
        /// Step.
        step: f64,
    },
    /// By count (evenly spaced, both ends included).
    Count {
        /// First value.
        from: f64,
        /// Last value.
        to: f64,
        /// Number of values.
        count: usize,
    },
}

impl Axis {
    fn values(&self) -> Vec<f64> {
        match self {
            Axis::List(v) => v.clone(),
            Axis::Step { from, to, step } if *step > 0.0 && to >= from => {
                let n = ((to - from) / step + 1e-9).floor() as usize;
                (0..=n).map(|i| from + i as f64 * step).collect()
            }
            Axis::Count { from, to, count } if *count >= 2 => (0..*count)
                .map(|i| from + (to - from) * i as f64 / (*count - 1) as f64)
                .collect(),
            _ => Vec::new(),
        }
    }
}

/// The map grid.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StiffnessSpec {
    /// `N/deg` or `N/rad`.
    pub unit: String,
    /// Front values.
    pub front: Axis,
    /// Rear values.
    pub rear: Axis,
}

/// Wang & Liang's RBF study: pairs rear = front + offset.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RbfSpec {
    /// Front values of the pairs (stiffness unit).
    pub front: Axis,
    /// Rear − front offsets (stiffness unit).
    pub rear_offsets: Vec<f64>,
    /// Largest rear value kept (Wang & Liang: 720 N/deg, so front + 40 stops at
    /// 680 and the pairs number 26 + 25 = 51).
    #[serde(default)]
    pub rear_max: Option<f64>,
    /// RBF spread, in the unit of Er (s).
    #[serde(default = "two")]
    pub spread: f64,
    /// Indices (0-based, in pair order) held out for validation.
    pub validation: Vec<usize>,
}

fn two() -> f64 {
    2.0
}

/// A target of the inverse problem.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetSpec {
    /// Metric name (a column of study.csv).
    pub metric: String,
    /// Target value.
    pub value: f64,
    /// Tolerance for the region.
    pub tolerance: f64,
}

/// The current tyres, for the preference.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReferenceSpec {
    /// Front stiffness (stiffness unit).
    pub front: f64,
    /// Rear stiffness (stiffness unit).
    pub rear: f64,
}

/// Inverse queries.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InverseSpec {
    /// Targets, each answered on its own; the Er targets also get a curve
    /// and a best point.
    pub targets: Vec<TargetSpec>,
    /// Further metric windows every answer must also meet (the region).
    #[serde(default)]
    pub constraints: Vec<TargetSpec>,
    /// The current tyres: the best point is the closest to them.
    pub reference: ReferenceSpec,
}

/// A study file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyFile {
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    description: Option<String>,
    vehicle: Vehicle,
    tyres: TyreRefs,
    #[serde(default)]
    road: Road,
    #[serde(default)]
    model: ModelOptions,
    manoeuvre: ManoeuvreSpec,
    #[serde(default)]
    simulation: SimulationSettings,
    #[serde(default)]
    metrics: MetricSettings,
    /// The map grid.
    #[serde(default)]
    pub stiffness: Option<StiffnessSpec>,
    /// Wang & Liang's RBF pairs.
    #[serde(default)]
    pub rbf: Option<RbfSpec>,
    /// Inverse queries (need a map).
    #[serde(default)]
    pub inverse: Option<InverseSpec>,
}

/// Wang & Liang's RBF study as loaded.
#[derive(Debug, Clone)]
pub struct RbfInput {
    /// (k1, k2) pairs, N/rad.
    pub pairs: Vec<(f64, f64)>,
    /// Spread, s.
    pub spread: f64,
    /// Held-out pair indices.
    pub validation: Vec<usize>,
}

/// Inverse queries as loaded: (metric, value, tolerance) triples.
#[derive(Debug, Clone)]
pub struct Inverse {
    /// Targets, each answered on its own.
    pub targets: Vec<(String, f64, f64)>,
    /// Windows every answer must also meet.
    pub constraints: Vec<(String, f64, f64)>,
    /// The current tyres (k1, k2), N/rad.
    pub reference: (f64, f64),
}

/// A loaded study, stiffness in N/rad.
#[derive(Debug, Clone)]
pub struct StudyInput {
    /// The scenario part.
    pub scenario: Scenario,
    /// N per file unit (π/180 for N/deg → N/rad is 180/π).
    pub unit_to_si: f64,
    /// Unit name for reports.
    pub unit: String,
    /// Map front values, N/rad.
    pub front: Vec<f64>,
    /// Map rear values, N/rad.
    pub rear: Vec<f64>,
    /// Wang & Liang's RBF pairs.
    pub rbf: Option<RbfInput>,
    /// Inverse targets, constraints and reference (N/rad).
    pub inverse: Option<Inverse>,
}

/// Reads and validates a study file.
pub fn load_study(path: &Path) -> Result<StudyInput, InputError> {
    let src = TomlSource::read(path)?;
    let f: StudyFile = src.parse()?;
    let sc = ScenarioFile {
        name: f.name.clone(),
        description: f.description.clone(),
        vehicle: f.vehicle.clone(),
        tyres: f.tyres.clone(),
        road: f.road,
        model: f.model,
        manoeuvre: f.manoeuvre.clone(),
        simulation: f.simulation,
        metrics: f.metrics,
    };
    if !matches!(f.manoeuvre, ManoeuvreSpec::StepSteer(_)) {
        return Err(param_error(
            &src,
            None,
            ParamError::without_value("manoeuvre.kind", "a study needs a step steer"),
        ));
    }
    let scenario = resolve_scenario(&sc, &src)?;
    let unit = f
        .stiffness
        .as_ref()
        .map_or("N/deg".to_string(), |s| s.unit.clone());
    let k = match unit.as_str() {
        "N/deg" => 180.0 / std::f64::consts::PI,
        "N/rad" => 1.0,
        u => {
            return Err(param_error(
                &src,
                None,
                ParamError::without_value(
                    "stiffness.unit",
                    &format!("unknown unit `{u}`: N/deg or N/rad"),
                ),
            ))
        }
    };
    let check = |key: &str, v: &[f64]| -> Result<Vec<f64>, InputError> {
        if v.is_empty() {
            return Err(param_error(
                &src,
                None,
                ParamError::without_value(key, "no values (a step or count that gives none?)"),
            ));
        }
        for &x in v {
            if !(x.is_finite() && x > 0.0) {
                return Err(param_error(
                    &src,
                    None,
                    ParamError::new(key, x, "a cornering stiffness must be positive"),
                ));
            }
        }
        Ok(v.iter().map(|x| x * k).collect())
    };
    let (front, rear) = match &f.stiffness {
        Some(s) => (
            check("stiffness.front", &s.front.values())?,
            check("stiffness.rear", &s.rear.values())?,
        ),
        None => (Vec::new(), Vec::new()),
    };
    let rbf = match &f.rbf {
        Some(r) => {
            let fronts = check("rbf.front", &r.front.values())?;
            let mut pairs = Vec::new();
            let rear_max = r.rear_max.map_or(f64::INFINITY, |m| m * k * (1.0 + 1e-12));
            for off in &r.rear_offsets {
                for kf in &fronts {
                    if kf + off * k <= rear_max {
                        pairs.push((*kf, kf + off * k));
                    }
                }
            }
            for &i in &r.validation {
                if i >= pairs.len() {
                    return Err(param_error(
                        &src,
                        None,
                        ParamError::new(
                            "rbf.validation",
                            i as f64,
                            &format!("only {} pairs", pairs.len()),
                        ),
                    ));
                }
            }
            ParamError::positive("spread", r.spread)
                .map_err(|e| param_error(&src, Some("rbf"), e))?;
            Some(RbfInput {
                pairs,
                spread: r.spread,
                validation: r.validation.clone(),
            })
        }
        None => None,
    };
    let inverse = match &f.inverse {
        Some(inv) => {
            if front.len() < 2 || rear.len() < 2 {
                return Err(param_error(
                    &src,
                    None,
                    ParamError::without_value(
                        "inverse",
                        "inverse queries need a [stiffness] map with at least 2 × 2 values",
                    ),
                ));
            }
            for t in inv.targets.iter().chain(&inv.constraints) {
                if !crate::study::METRICS.contains(&t.metric.as_str()) {
                    return Err(param_error(
                        &src,
                        None,
                        ParamError::without_value(
                            "inverse.targets",
                            &format!(
                                "unknown metric `{}`; one of {}",
                                t.metric,
                                crate::study::METRICS.join(", ")
                            ),
                        ),
                    ));
                }
            }
            let triples = |v: &[TargetSpec]| {
                v.iter()
                    .map(|t| (t.metric.clone(), t.value, t.tolerance))
                    .collect()
            };
            Some(Inverse {
                targets: triples(&inv.targets),
                constraints: triples(&inv.constraints),
                reference: (inv.reference.front * k, inv.reference.rear * k),
            })
        }
        None => None,
    };
    Ok(StudyInput {
        scenario,
        unit_to_si: k,
        unit,
        front,
        rear,
        rbf,
        inverse,
    })
}
