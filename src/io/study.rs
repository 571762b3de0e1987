//! Study files (the book's `docs/src/formats.md`, "The project's own files"): a scenario's tables (vehicle, tyres,
//! road, model, a step-steer manoeuvre, simulation, metrics) plus the
//! cornering-stiffness grid, Wang & Liang's RBF pairs and inverse targets.
//! Stiffness values are per tyre in the file's `unit` (`N/deg` or `N/rad`),
//! converted to N/rad on reading.

use super::axis_order::{disorder, Disorder};
use super::scenario::{
    resolve_scenario, ManoeuvreSpec, Road, Scenario, ScenarioFile, SimulationSettings, TyreRefs,
};
use super::toml_file::{param_error, TomlSource};
use crate::error::{
    FileKind, InputError, InputProblem, ParamError, ParamReason, ScenarioProblem, StiffnessGiven,
    Wanted,
};
use crate::metrics::MetricSettings;
use crate::study::stiffness::{stiffness_problem, AxleLoad};
use crate::study::{Metric, StiffnessUnit, Target};
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
    /// The values, or none when there would be more than a million (an
    /// infinite range, a tiny step).
    fn values(&self) -> Option<Vec<f64>> {
        const MAX: f64 = 1e6;
        Some(match self {
            Axis::List(v) => v.clone(),
            Axis::Step { from, to, step } if *step > 0.0 && to >= from => {
                let n = ((to - from) / step + 1e-9).floor();
                if n.is_nan() || n >= MAX {
                    return None;
                }
                (0..=n as usize).map(|i| from + i as f64 * step).collect()
            }
            Axis::Count { count, .. } if *count as f64 > MAX => return None,
            Axis::Count { from, to, count: 1 } if from == to => vec![*from],
            Axis::Count { from, to, count } if *count >= 2 => (0..*count)
                .map(|i| from + (to - from) * i as f64 / (*count - 1) as f64)
                .collect(),
            _ => Vec::new(),
        })
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

/// Inverse queries as loaded (stiffness in N/rad).
#[derive(Debug, Clone)]
pub struct Inverse {
    /// Targets, each answered on its own.
    pub targets: Vec<Target>,
    /// Windows every answer must also meet.
    pub constraints: Vec<Target>,
    /// The current tyres (k1, k2), N/rad.
    pub reference: (f64, f64),
}

/// A loaded study, stiffness in N/rad.
#[derive(Debug, Clone)]
pub struct StudyInput {
    /// The scenario part.
    pub scenario: Scenario,
    /// The file's stiffness unit, for reports.
    pub unit: StiffnessUnit,
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
    // A file of another kind is named as such, not by its first key the
    // study does not know (a study with [rbf] pairs only reads as a
    // scenario, whose error is then the study's own).
    let own = [FileKind::Study, FileKind::Scenario];
    let f: StudyFile = src
        .parse()
        .map_err(|e| super::file_kind::not_this_toml(path, Wanted::Study, &own).unwrap_or(e))?;
    let scenario = scenario_of(&f, &src)?;
    let unit_name = f.stiffness.as_ref().map_or("N/deg", |s| s.unit.as_str());
    let unit: StiffnessUnit = unit_name.parse().map_err(|e| {
        param_error(
            &src,
            None,
            ParamError::without_value("stiffness.unit", ParamReason::Name(Box::new(e))),
        )
    })?;
    let (sf, sr) = scenario.model.vehicle.static_axle_loads();
    let values = Values {
        src: &src,
        to_si: unit.to_si(),
        unit,
        loads: (0.5 * sf, 0.5 * sr),
    };
    let (front, rear) = match &f.stiffness {
        Some(s) => (
            values.stiffness("stiffness.front", &s.front)?,
            values.stiffness("stiffness.rear", &s.rear)?,
        ),
        None => (Vec::new(), Vec::new()),
    };
    let rbf = f.rbf.as_ref().map(|r| values.rbf(r)).transpose()?;
    let inverse = match &f.inverse {
        Some(inv) => {
            if front.len() < 2 || rear.len() < 2 {
                return Err(param_error(
                    &src,
                    None,
                    ParamError::without_value("inverse", ParamReason::InverseWithoutMap),
                ));
            }
            Some(values.inverse(inv)?)
        }
        None => None,
    };
    Ok(StudyInput {
        scenario,
        unit,
        front,
        rear,
        rbf,
        inverse,
    })
}

/// The scenario tables of a study file, resolved; a study needs a step steer.
fn scenario_of(f: &StudyFile, src: &TomlSource) -> Result<Scenario, InputError> {
    if !matches!(f.manoeuvre, ManoeuvreSpec::StepSteer(_)) {
        return Err(param_error(
            src,
            None,
            ParamError::without_value("manoeuvre.kind", ParamReason::StudyNeedsStepSteer),
        ));
    }
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
    resolve_scenario(&sc, src)
}

/// Converts and checks a study file's values, given in its stiffness unit.
struct Values<'a> {
    src: &'a TomlSource,
    /// N/rad per file unit.
    to_si: f64,
    /// The file's unit.
    unit: StiffnessUnit,
    /// Each axle's tyre's static load (front, rear), N: what a tyre's
    /// stiffness is judged against ([`stiffness_problem`]).
    loads: (f64, f64),
}

impl Values<'_> {
    fn error(&self, e: ParamError) -> InputError {
        param_error(self.src, None, e)
    }

    /// The stiffness values of `axis` in N/rad: at least one, each positive.
    fn stiffness(&self, key: &str, axis: &Axis) -> Result<Vec<f64>, InputError> {
        let v = self.in_file_unit(key, axis)?;
        Ok(v.iter().map(|x| x * self.to_si).collect())
    }

    /// Refuses a value of `values` (file unit) at `key` that no tyre on
    /// `key`'s axle has in the file's unit ([`stiffness_problem`]: one
    /// written in the other unit, one no tyre's in either), or one that is
    /// no positive number, at `key`'s line.
    fn tyre_like(&self, key: &str, values: &[f64]) -> Result<(), InputError> {
        let at = match key.ends_with("rear") {
            true => AxleLoad {
                axle: "rear",
                load: self.loads.1,
            },
            false => AxleLoad {
                axle: "front",
                load: self.loads.0,
            },
        };
        let refused = values.iter().find_map(|&value| {
            stiffness_problem(key, value, self.unit, at, StiffnessGiven::File).map(|r| (value, r))
        });
        match refused {
            Some((_, ParamReason::StiffnessAgainstLoad(slip))) => {
                let problem =
                    InputProblem::Scenario(Box::new(ScenarioProblem::StiffnessUnit(*slip)));
                Err(self.src.located(self.src.key_span(key), problem))
            }
            Some((value, why)) => Err(self.error(ParamError::new(key, value, why))),
            None => Ok(()),
        }
    }

    /// The stiffness values of `axis` in the file's unit, checked.
    fn in_file_unit(&self, key: &str, axis: &Axis) -> Result<Vec<f64>, InputError> {
        let v = axis.values().ok_or_else(|| {
            self.error(ParamError::without_value(key, ParamReason::TooManyValues))
        })?;
        if let Axis::Count { from, to, count: 1 } = *axis {
            if from != to {
                let why = ParamReason::CountOfOneTwoEnds(from, to);
                return Err(self.error(ParamError::without_value(&format!("{key}.count"), why)));
            }
        }
        // One rule for every sweep axis (`super::axis_order`): an
        // unsorted front list traced a target curve of 19 points for 10.
        if let Some(d) = disorder(&v) {
            let (i, why) = match d {
                Disorder::Repeated { at } => (at, ParamReason::RepeatedValue),
                Disorder::Descending { at, before } => (at, ParamReason::AxisOutOfOrder { before }),
            };
            let at = match axis {
                Axis::List(_) => format!("{key}[{i}]"),
                _ => key.to_string(),
            };
            return Err(self.error(ParamError::new(&at, v[i], why)));
        }
        if v.is_empty() {
            return Err(self.error(ParamError::without_value(
                key,
                ParamReason::NoValuesFromRange,
            )));
        }
        self.tyre_like(key, &v)?;
        Ok(v)
    }

    /// Wang & Liang's pairs (rear = front + offset, up to `rear_max`).
    fn rbf(&self, r: &RbfSpec) -> Result<RbfInput, InputError> {
        let k = self.to_si;
        // In the file's unit, the rear is front + offset exactly as written
        // (240, not 200·k + 40·k read back as 240.00000000000003).
        let fronts = self.in_file_unit("rbf.front", &r.front)?;
        let rear_max = r.rear_max.map_or(f64::INFINITY, |m| m * k * (1.0 + 1e-12));
        let pairs: Vec<(f64, f64)> = r
            .rear_offsets
            .iter()
            .flat_map(|off| fronts.iter().map(move |&kf| (kf * k, (kf + off) * k)))
            .filter(|&(_, kr)| kr <= rear_max)
            .collect();
        if let Some(&i) = r.validation.iter().find(|&&i| i >= pairs.len()) {
            return Err(self.error(ParamError::new(
                "rbf.validation",
                i as f64,
                ParamReason::TooFewPairs { pairs: pairs.len() },
            )));
        }
        ParamError::positive("spread", r.spread)
            .map_err(|e| param_error(self.src, Some("rbf"), e))?;
        Ok(RbfInput {
            pairs,
            spread: r.spread,
            validation: r.validation.clone(),
        })
    }

    /// The inverse queries with their metrics named and the reference in
    /// N/rad.
    fn inverse(&self, inv: &InverseSpec) -> Result<Inverse, InputError> {
        let typed = |key: &str, v: &[TargetSpec]| -> Result<Vec<Target>, InputError> {
            v.iter()
                .map(|t| {
                    let metric: Metric = t.metric.parse().map_err(|e| {
                        self.error(ParamError::without_value(
                            key,
                            ParamReason::Name(Box::new(e)),
                        ))
                    })?;
                    Ok(Target {
                        metric,
                        value: t.value,
                        tolerance: t.tolerance,
                    })
                })
                .collect()
        };
        // A tolerance is a half-width: one below zero met no map point
        // and was said as "er = 0.13 ± -0.005: 0 map points meet it".
        for (list, v) in [("targets", &inv.targets), ("constraints", &inv.constraints)] {
            for (i, t) in v.iter().enumerate() {
                let key = format!("inverse.{list}[{i}].tolerance");
                ParamError::positive(&key, t.tolerance).map_err(|e| self.error(e))?;
            }
        }
        // Er (Wang & Liang's evaluation index, s) is positive for every
        // car: a target at or below zero is a typo, never met.
        for (list, v) in [("targets", &inv.targets), ("constraints", &inv.constraints)] {
            for (i, t) in v.iter().enumerate() {
                if t.metric.eq_ignore_ascii_case("er") {
                    let key = format!("inverse.{list}[{i}].value");
                    ParamError::positive(&key, t.value).map_err(|e| self.error(e))?;
                }
            }
        }
        let reference = inv.reference;
        // A stiffness at or below zero is refused as such, before the unit
        // check (which would read −9.4 N/deg as a unit slip).
        ParamError::positive("inverse.reference.front", reference.front)
            .map_err(|e| self.error(e))?;
        ParamError::positive("inverse.reference.rear", reference.rear)
            .map_err(|e| self.error(e))?;
        self.tyre_like("inverse.reference.front", &[reference.front])?;
        self.tyre_like("inverse.reference.rear", &[reference.rear])?;
        Ok(Inverse {
            targets: typed("inverse.targets", &inv.targets)?,
            constraints: typed("inverse.constraints", &inv.constraints)?,
            reference: (
                inv.reference.front * self.to_si,
                inv.reference.rear * self.to_si,
            ),
        })
    }
}
