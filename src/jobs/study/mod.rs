//! `study` as one job (Wang & Liang): a study file in; the (k1, k2) map of
//! every metric, Wang & Liang's RBF network with its re-simulated
//! validation, and the inverse (regions, Er curves, the best combination
//! refined by simulation) out, as `study.csv`, `maps.png`, `rbf.json`,
//! `rbf.png`, `inverse.json` and `summary.json`; stiffness per tyre in the file's unit.

use crate::study::inverse::{best_on_curve, distance, Map, MapEdge};
use crate::study::rbf::Rbf;
use crate::study::stiffness::NoTyreHas;
use crate::study::{Metric, NotHandling, Sample, StiffnessUnit, Study};

mod figures;
mod lines;
mod numbers;
mod rbf_fit;
pub use rbf_fit::RbfFit;
mod table;
pub use table::StudySummary;
mod rbf_verdict;
pub use rbf_verdict::{RbfRefusal, RbfStatus};
mod target_range;
use crate::error::{Error, InputError, MergeInput, OptionsError};
use crate::io::study::{load_study, Inverse, StudyInput};
use crate::jobs::shard::{
    input_copies, read_shards, write_shard, Shard, ShardFile, ShardJob, ShardReport,
};
use crate::report::progress::Progress;
use crate::report::{refuse_overwrites, write_json_sorted, OutputLock};
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;
pub use target_range::{MapReach, ReachPoint, TargetReach};

/// One held-out pair: its Er, the network's answer, and that answer's Er
/// re-simulated.
#[derive(Debug, Clone, Serialize)]
pub struct Validation {
    /// Er of the pair, s.
    pub er_target: f64,
    /// The pair's front stiffness.
    pub k_front_true: f64,
    /// The pair's rear stiffness.
    pub k_rear_true: f64,
    /// The network's front stiffness.
    pub k_front_predicted: f64,
    /// The network's rear stiffness.
    pub k_rear_predicted: f64,
    /// Er of the answer, simulated, s.
    pub er_resimulated: f64,
    /// Its error against the target, %.
    pub error_percent: f64,
}

/// `rbf.json`: Wang & Liang's network Er → (k1, k2).
#[derive(Debug, Clone, Serialize)]
pub struct RbfReport {
    /// Spread, s.
    pub spread: f64,
    /// Pairs trained on.
    pub training_pairs: usize,
    /// Condition number of the training system.
    pub condition_number: f64,
    /// The directions (singular values) its solve kept, of one per
    /// training pair.
    pub directions_kept: usize,
    /// Whether it interpolates its pairs or is a regression.
    pub fit: RbfFit,
    /// The largest spread at which it would keep every direction (an
    /// interpolant), s; None where no spread does.
    pub interpolating_spread: Option<f64>,
    /// Largest misfit of a training pair (either axle).
    pub largest_training_misfit: f64,
    /// The held-out pairs.
    pub validation: Vec<Validation>,
    /// Stiffness unit.
    pub unit: StiffnessUnit,
    /// The network's answer over the training range of Er, for `rbf.png`:
    /// (Er s, k1, k2 in `unit`).
    #[serde(skip)]
    pub prediction: Vec<[f64; 3]>,
}

/// The best combination on an Er curve, refined by simulation.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BestAnswer {
    /// Front stiffness.
    pub k_front: f64,
    /// Rear stiffness.
    pub k_rear: f64,
    /// The target's metric there, simulated (its unit: `study.csv`'s).
    pub resimulated: f64,
    /// Relative distance to the current tyres.
    pub distance_to_reference: f64,
    /// The map's edge the answer was held to (the curve may come closer
    /// beyond it, where the map has no data); None inside the map.
    pub at_map_edge: Option<MapEdge>,
}

/// The network's answer to an Er target, re-simulated, and whether it
/// stands as an answer ([`rbf_verdict`]).
#[derive(Debug, Clone, Serialize)]
pub struct RbfAnswer {
    /// Front stiffness.
    pub k_front: f64,
    /// Rear stiffness.
    pub k_rear: f64,
    /// Er there, simulated, s; None where the re-simulated response has
    /// no Er (it did not settle, or is no handling response) or where the
    /// answer is no tyre's (`no_tyre_has`: not simulated).
    pub er_resimulated: Option<f64>,
    /// The answer's stiffness no tyre has (the network extrapolating far
    /// beyond its data), if so: the answer is then not simulated.
    pub no_tyre_has: Option<NoTyreHas>,
    /// Its error against the target, %.
    pub error_percent: Option<f64>,
    /// The Er the network was trained on, smallest and largest, s: a
    /// target outside it is answered by extrapolation.
    pub trained_er: (f64, f64),
    /// Relative distance to the current tyres.
    pub distance_to_reference: f64,
    /// The network it comes from: a regression's answer is judged by its
    /// re-simulated Er alone.
    pub fit: RbfFit,
    /// Whether it stands as an answer.
    pub status: RbfStatus,
    /// Why it does not (empty where it does).
    pub refused_for: Vec<RbfRefusal>,
}

/// What a target has beyond a region: its curve, the best point on it and,
/// for Er with a network, the network's answer.
#[derive(Debug, Clone, Serialize)]
pub struct CurveAnswer {
    /// The iso-curve on the map.
    pub curve: Vec<[f64; 2]>,
    /// The best combination on it (`None`: not reached on the map).
    pub best: Option<BestAnswer>,
    /// The network's answer, for an Er target with a network (Wang &
    /// Liang's network maps Er alone).
    pub rbf: Option<RbfAnswer>,
    /// What the map reaches of the metric, and where the target lies
    /// against it (`None`: no map point has it).
    pub map_reach: Option<MapReach>,
}

/// One target of the inverse problem answered.
#[derive(Debug, Clone, Serialize)]
pub struct TargetReport {
    /// The metric.
    pub metric: Metric,
    /// Its target value.
    pub target: f64,
    /// Tolerance.
    pub tolerance: f64,
    /// Map points that meet it and every constraint.
    pub region: Vec<[f64; 2]>,
    /// The curve and the best points.
    #[serde(flatten)]
    pub curve: CurveAnswer,
}

/// `inverse.json`.
#[derive(Debug, Clone, Serialize)]
pub struct InverseReport {
    /// Stiffness unit.
    pub unit: StiffnessUnit,
    /// The current tyres.
    pub reference: [f64; 2],
    /// The targets, answered.
    pub targets: Vec<TargetReport>,
}

/// The report of `study`; the three JSON files hold its parts.
#[derive(Debug, Clone, Serialize)]
pub struct StudyReport {
    /// `summary.json`.
    pub summary: StudySummary,
    /// `rbf.json`, with RBF pairs.
    pub rbf: Option<RbfReport>,
    /// `inverse.json`, with inverse queries.
    pub inverse: Option<InverseReport>,
    /// Every sample, the map's first (rear fastest), then the RBF pairs.
    #[serde(skip)]
    pub samples: Vec<Sample>,
    /// The map.
    #[serde(skip)]
    pub map: Map,
    /// The RBF pairs' samples.
    #[serde(skip)]
    pub pairs: Vec<Sample>,
    /// The front and rear tyre models.
    #[serde(skip)]
    pub tyres: [&'static str; 2],
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The output folder, held for this run until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
    /// What the terminal says of the run's inputs (shard files given
    /// twice), after its first lines.
    #[serde(skip)]
    pub notes: Vec<String>,
}

/// The output files, in the order [`StudyReport::write`] checks them.
const FILES: [&str; 6] = [
    "study.csv",
    "maps.png",
    "rbf.json",
    "rbf.png",
    "inverse.json",
    "summary.json",
];

/// Runs the study of the file `path`; `out` is the output folder (default
/// `out/<study name>`), checked against the inputs before any simulation.
pub fn run(path: &Path, out: Option<&Path>) -> Result<StudyReport, Error> {
    let job = Job::load(path, out)?;
    let lock = OutputLock::acquire(&job.out_dir)?;
    let t0 = Instant::now();
    let samples = {
        let p = Progress::start("study", job.all.len());
        job.study.evaluate_all(&job.all, p.counter())
    };
    job.finish(samples, t0.elapsed().as_secs_f64(), lock)
}

/// Simulates shard `shard`'s combinations (map points and RBF pairs, in one
/// list) of the study of the file `path` and writes them to
/// `<out>/shard-K-of-N.json`; [`merge`] finishes the study from the N shard
/// files.
pub fn run_shard(path: &Path, shard: Shard, out: Option<&Path>) -> Result<ShardReport, Error> {
    let job = Job::load(path, None)?;
    let sc = &job.input.scenario;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sc.name), Path::to_path_buf);
    let file = out_dir.join(shard.file_name());
    refuse_overwrites([&file], &sc.inputs)?;
    let owned = shard.units(job.all.len());
    let pairs: Vec<(f64, f64)> = owned.iter().map(|&i| job.all[i]).collect();
    let results = {
        let p = Progress::start("study shard", pairs.len());
        job.study.evaluate_all(&pairs, p.counter())
    };
    write_shard(
        &file,
        &ShardFile {
            job: ShardJob::Study,
            shard,
            input: path.to_path_buf(),
            inputs: input_copies(&sc.inputs)?,
            units: job.all.len(),
            owned: owned.clone(),
            results,
        },
    )?;
    Ok(ShardReport {
        job: ShardJob::Study,
        shard,
        units: job.all.len(),
        owned: owned.len(),
        conditions: owned.len(),
        path: file,
    })
}

/// The study of a set of shard files ([`run_shard`]), checked to be every
/// shard of one run on unchanged inputs: the map, the network and the
/// inverse as the unsharded run makes them; its outputs are the unsharded
/// run's, byte for byte.
pub fn merge(shards: &[PathBuf], out: Option<&Path>) -> Result<StudyReport, Error> {
    let t0 = Instant::now();
    let read = read_shards::<Sample>(ShardJob::Study, shards)?;
    let note = read.note();
    let (input, units, samples) = (read.input, read.units, read.results);
    let job = Job::load(&input, out)?;
    if units != job.all.len() {
        return Err(OptionsError::MergeCount {
            input: MergeInput::Study,
            path: input,
            held: units,
            expected: job.all.len(),
        }
        .into());
    }
    let lock = OutputLock::acquire(&job.out_dir)?;
    let mut report = job.finish(samples, t0.elapsed().as_secs_f64(), lock)?;
    report.notes.extend(note);
    Ok(report)
}

/// A loaded study: its input, the model and manoeuvre, every combination to
/// simulate (the map's, then the RBF pairs) and the output folder.
struct Job {
    input: StudyInput,
    study: Study,
    /// Map points, front slowest.
    grid: Vec<(f64, f64)>,
    /// The map points, then the RBF pairs.
    all: Vec<(f64, f64)>,
    out_dir: PathBuf,
}

impl Job {
    fn load(path: &Path, out: Option<&Path>) -> Result<Self, Error> {
        let input = load_study(path)?;
        let sc = &input.scenario;
        let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sc.name), Path::to_path_buf);
        refuse_overwrites(&FILES.map(|f| out_dir.join(f)), &sc.inputs)?;
        let study = Study {
            model: sc.model.clone(),
            manoeuvre: sc.manoeuvre.clone(),
            integrator: sc.integrator,
            metrics: sc.metrics,
        };
        let grid: Vec<(f64, f64)> = input
            .front
            .iter()
            .flat_map(|&f| input.rear.iter().map(move |&r| (f, r)))
            .collect();
        let rbf_pairs = input.rbf.as_ref().map_or(&[][..], |r| &r.pairs[..]);
        let all: Vec<(f64, f64)> = grid.iter().chain(rbf_pairs).copied().collect();
        if all.is_empty() {
            return Err(InputError::NothingToSimulate {
                path: path.to_path_buf(),
            }
            .into());
        }
        Ok(Self {
            input,
            study,
            grid,
            all,
            out_dir,
        })
    }

    /// The map, the network and the inverse from every combination's
    /// sample (in [`Job::all`]'s order).
    fn finish(
        self,
        samples: Vec<Sample>,
        seconds: f64,
        lock: OutputLock,
    ) -> Result<StudyReport, Error> {
        let (input, st) = (&self.input, &self.study);
        let sc = &input.scenario;
        let unit = input.unit;
        let map = Map {
            front: input.front.clone(),
            rear: input.rear.clone(),
            samples: samples[..self.grid.len()].to_vec(),
        };
        let pairs = samples[self.grid.len()..].to_vec();
        let not_handling = NotHandling::count(&samples);
        let k = unit.to_si();
        let net = (input.rbf.as_ref())
            .map(|r| rbf_fit::train(st, r, &pairs, k, unit, &sc.inputs[0]))
            .transpose()?;
        let inverse = input
            .inverse
            .as_ref()
            .map(|inv| {
                let net = net.as_ref().map(|n| (&n.0, n.1.fit));
                answer(st, input, inv, &map, net, unit)
            })
            .transpose()?;
        Ok(StudyReport {
            summary: StudySummary {
                combinations: self.all.len(),
                seconds,
                study: sc.name.clone(),
                unit,
                without_steady_state: not_handling.without_steady_state,
                unstable: not_handling.unstable,
                lowest_critical_speed: not_handling.lowest_critical_speed,
                sliding: not_handling.sliding,
                sliding_still_moving: not_handling.sliding_still_moving,
                large_sideslip: not_handling.large_sideslip,
                large_sideslip_still_moving: not_handling.large_sideslip_still_moving,
                not_settled: not_handling.not_settled,
                still_settling: not_handling.still_settling,
                largest_sideslip: not_handling.largest_sideslip,
            },
            rbf: net.map(|n| n.1),
            inverse,
            samples,
            map,
            pairs,
            tyres: [sc.model.front.model_name(), sc.model.rear.model_name()],
            out_dir: self.out_dir,
            lock,
            // The step's speed read as km/h written as m/s, by the
            // scenario reader's rule (`simulate` says it too).
            notes: sc.kmh_speed.iter().map(ToString::to_string).collect(),
        })
    }
}

/// The network's answer to the Er target `t`: re-simulated unless no tyre
/// has it, and judged against the map's `bounds` (N/rad) and the target's
/// tolerance; its distance to `reference`, its stiffness in the study's
/// unit (`k` N/rad per unit).
fn rbf_answer(
    st: &Study,
    net: &Rbf,
    fit: RbfFit,
    t: &crate::study::Target,
    bounds: crate::study::inverse::MapBounds,
    (reference, k): ((f64, f64), f64),
) -> RbfAnswer {
    let p = net.predict(t.value);
    // An answer no tyre has is no car to simulate: its "Er" would be
    // reported as the network's answer re-simulated.
    let no_tyre = st.no_tyre_has(p[0], p[1]);
    let e = match no_tyre {
        Some(_) => None,
        None => Some(st.er(p[0], p[1])).filter(|e| e.is_finite()),
    };
    let refused_for = rbf_verdict::refusals((p[0], p[1]), bounds, no_tyre.is_some(), e, t);
    RbfAnswer {
        k_front: p[0] / k,
        k_rear: p[1] / k,
        no_tyre_has: no_tyre,
        er_resimulated: e,
        error_percent: e.map(|e| 100.0 * (e - t.value) / t.value),
        trained_er: net.trained_range(),
        distance_to_reference: distance((p[0], p[1]), reference),
        fit,
        status: rbf_verdict::status(&refused_for),
        refused_for,
    }
}

/// The inverse queries on the map: each target's region with the
/// constraints, and for Er its curve, the best combination on it and the
/// network's answer.
fn answer(
    st: &Study,
    input: &StudyInput,
    inv: &Inverse,
    map: &Map,
    net: Option<(&Rbf, RbfFit)>,
    unit: StiffnessUnit,
) -> Result<InverseReport, Error> {
    let k = unit.to_si();
    let per_unit = |p: &(f64, f64)| [p.0 / k, p.1 / k];
    let constraints = &inv.constraints;
    let reference = inv.reference;
    // Each target's best combination is a serial search of simulations,
    // independent of the others': searched side by side, collected in the
    // file's order.
    let targets =
        (inv.targets.par_iter())
            .map(|&t| {
                let mut all = vec![t];
                all.extend(constraints.iter().copied());
                let region = map.region(&all).iter().map(per_unit).collect();
                let curve = map.iso_curve(t.metric, t.value);
                let span = 2.0 * (input.front[1] - input.front[0]);
                let bounds = map.bounds();
                let best = best_on_curve(st, t.metric, &curve, bounds, reference, (t.value, span))
                    .map(|b| BestAnswer {
                        k_front: b.k_front / k,
                        k_rear: b.k_rear / k,
                        resimulated: b.value,
                        distance_to_reference: distance((b.k_front, b.k_rear), reference),
                        at_map_edge: b.edge,
                    });
                let rbf = net
                    .filter(|_| t.metric == Metric::Er)
                    .map(|(net, fit)| rbf_answer(st, net, fit, &t, bounds, (reference, k)));
                let curve = CurveAnswer {
                    curve: curve.iter().map(per_unit).collect(),
                    best,
                    rbf,
                    map_reach: MapReach::of(map, t.metric, t.value, unit),
                };
                TargetReport {
                    metric: t.metric,
                    target: t.value,
                    tolerance: t.tolerance,
                    region,
                    curve,
                }
            })
            .collect();
    Ok(InverseReport {
        unit,
        reference: per_unit(&reference),
        targets,
    })
}

impl StudyReport {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let s = &self.summary;
        let u = s.unit;
        let mut out = vec![
            format!(
                "{}: {} map combinations + {} RBF pairs, tyres {} / {}, step steer",
                s.study,
                self.map.samples.len(),
                self.pairs.len(),
                self.tyres[0],
                self.tyres[1]
            ),
            format!(
                "  simulated {} combinations in {:.2} s",
                s.combinations, s.seconds
            ),
        ];
        out.extend(self.notes.iter().map(|n| format!("  note: {n}")));
        out.extend(table::not_handling_line(s));
        out.extend(table::still_settling_line(s));
        if let Some(r) = &self.rbf {
            out.push(format!(
                "  RBF (spread {} s): trained on {} pairs, condition number {:.2e}, largest training misfit {:.3} {u}",
                r.spread, r.training_pairs, r.condition_number, r.largest_training_misfit
            ));
            out.extend(r.regression_note().map(|n| format!("  note: {n}")));
            out.push(format!("  validation (Wang & Liang, table 3): Er target → predicted k1, k2 [{u}] → Er re-simulated, error"));
            out.extend(r.validation.iter().map(|v| {
                format!(
                    "    Er {:.5} ({:.0}, {:.0}) → ({:.1}, {:.1}) → Er {:.5}, {:+.2} %",
                    v.er_target,
                    v.k_front_true,
                    v.k_rear_true,
                    v.k_front_predicted,
                    v.k_rear_predicted,
                    v.er_resimulated,
                    v.error_percent
                )
            }));
        }
        if let Some(inv) = &self.inverse {
            for t in &inv.targets {
                out.extend(lines::target_lines(t, inv.reference, u, &self.map));
            }
        }
        out
    }

    /// Writes the table, the figures and the JSON files into the output
    /// folder.
    pub fn write(&self) -> Result<(), Error> {
        let files = FILES.map(|f| self.out_dir.join(f));
        let u = self.summary.unit;
        table::write(&files[0], &self.samples, u)?;
        if let Some(r) = &self.rbf {
            write_json_sorted(&files[2], r)?;
            figures::rbf_pairs(&self.pairs, r, u).save(&files[3])?;
        }
        let mut curves = Vec::new();
        if let Some(inv) = &self.inverse {
            write_json_sorted(&files[4], inv)?;
            curves.extend(inv.targets.iter().map(|t| figures::Curve {
                metric: t.metric,
                target: t.target,
                points: &t.curve.curve[..],
            }));
        }
        if self.map.front.len() >= 2 && self.map.rear.len() >= 2 {
            figures::heat_maps(&self.map, u, &curves).save(&files[1])?;
        }
        write_json_sorted(&files[5], &self.summary)
    }
}
