//! `equilibria` as one job (Li, Jia & Zhao): a sweep file in; every
//! steering equilibrium over the grid by PSO and the exact solver,
//! cross-checked, with stability and bifurcations, out as
//! `equilibria.csv`, `bifurcations.csv`, `continua.csv`, `summary.json` and
//! the figures (`figures.rs`).

mod critical;
mod figures;
mod map;
mod misses;
mod outputs;
mod slices;

use crate::equilibria::bifurcation::Bifurcation;
use crate::equilibria::pso::{Fitness, PsoSearch};
use crate::equilibria::sweep::{self, SweepResult};
use crate::equilibria::{exact, FoundBy, SearchBox};
use crate::error::{Error, MergeInput, OptionsError};
use crate::io::sweep::{load_sweep, Sweep};
use crate::jobs::shard::{
    input_copies, plural, read_shards, write_shard, Shard, ShardFile, ShardJob, ShardReport,
};
use crate::report::progress::Progress;
use crate::report::{refuse_overwrites, write_csv, write_json_sorted, OutputLock};
use crate::vehicle::{Kinematics, VehicleModel};
pub use misses::{ConditionMiss, Spot};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// `summary.json`: agreement, residuals, counts and bifurcations.
#[derive(Debug, Clone, Serialize)]
pub struct EquilibriaSummary {
    /// Sweep name.
    pub sweep: String,
    /// Conditions of the grid.
    pub conditions: usize,
    /// Conditions where PSO and the exact solver agree.
    pub agreeing: usize,
    /// The same, %.
    pub agreement_percent: f64,
    /// Each condition where they disagree or the swarm's index sum falls
    /// short of the winding number: which solver found what.
    pub misses: Vec<ConditionMiss>,
    /// Largest residual max(|β̇|, |ṙ|) of an equilibrium.
    pub max_residual: f64,
    /// PSO seed.
    pub seed: u64,
    /// PSO settings.
    pub pso: PsoSearch,
    /// The search box.
    #[serde(rename = "box")]
    pub search_box: SearchBox,
    /// Model evaluations of the swarms.
    pub pso_evaluations: usize,
    /// Wall time, s (printed, not written: the outputs of a run merged from
    /// shards are byte for byte those of the unsharded run).
    #[serde(skip)]
    pub seconds: f64,
    /// Conditions by the number of equilibria in the box.
    pub equilibria_in_box_histogram: BTreeMap<usize, usize>,
    /// Conditions with a continuum of equilibria.
    pub conditions_with_continua: usize,
    /// Bifurcations located.
    pub bifurcations: Vec<Bifurcation>,
    /// The closed-form critical speed √(−l/K) of the linear bicycle model
    /// (Genta 1997), m/s, where neither axle's tyre has a friction limit
    /// and the car oversteers (K < 0); null otherwise. A zero-eigenvalue
    /// point along speed is checked against it.
    pub critical_speed_closed_form: Option<f64>,
}

/// The report of `equilibria`.
#[derive(Debug, Clone, Serialize)]
pub struct EquilibriaReport {
    /// `summary.json`.
    pub summary: EquilibriaSummary,
    /// Every condition's equilibria.
    #[serde(skip)]
    pub result: SweepResult,
    /// The sweep as loaded.
    #[serde(skip)]
    pub sweep: Sweep,
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The output folder, held for this run until the report is dropped
    /// (shards do not take it: the shards of a job array write their own
    /// files into one folder at once).
    #[serde(skip)]
    pub lock: OutputLock,
    /// What the folder held of an earlier run: removed once written.
    #[serde(skip)]
    pub leftovers: crate::report::stale::Leftovers,
}

const FILES: [&str; 4] = [
    "equilibria.csv",
    "bifurcations.csv",
    "summary.json",
    "continua.csv",
];

/// Runs the sweep of the file `path`; `out` is the output folder (default
/// `out/<sweep name>`), checked against the inputs first.
pub fn run(path: &Path, out: Option<&Path>) -> Result<EquilibriaReport, Error> {
    let sw = load_sweep(path)?;
    let (out_dir, lock) = output_folder(&sw, out)?;
    let t0 = Instant::now();
    let res = {
        let progress = Progress::start("equilibria", sw.grid.len());
        sweep::run(
            &sw.model,
            &sw.grid,
            &sw.search_box,
            &sw.pso,
            sw.report.bifurcations,
            progress.counter(),
        )
    };
    Ok(report(sw, res, t0.elapsed().as_secs_f64(), (out_dir, lock)))
}

/// Solves shard `shard`'s lines of the sweep of the file `path` and writes
/// them to `<out>/shard-K-of-N.json` (default folder `out/<sweep name>`);
/// [`merge`] makes the outputs of the whole sweep from the N shard files.
pub fn run_shard(path: &Path, shard: Shard, out: Option<&Path>) -> Result<ShardReport, Error> {
    let sw = load_sweep(path)?;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sw.name), Path::to_path_buf);
    let file = out_dir.join(shard.file_name());
    refuse_overwrites([&file], &sw.inputs)?;
    let units = sweep::grid_lines(&sw.grid).len();
    let owned = shard.units(units);
    let results = {
        let n = owned.len() * sw.grid.steer.len();
        let progress = Progress::start("equilibria shard", n);
        sweep::solve_lines(
            &sw.model,
            &sw.grid,
            &sw.search_box,
            &sw.pso,
            &owned,
            progress.counter(),
        )
    };
    let conditions = results.iter().map(Vec::len).sum();
    write_shard(
        &file,
        &ShardFile {
            job: ShardJob::Equilibria,
            shard,
            input: path.to_path_buf(),
            inputs: input_copies(&sw.inputs)?,
            units,
            owned: owned.clone(),
            results,
        },
    )?;
    Ok(ShardReport {
        job: ShardJob::Equilibria,
        shard,
        units,
        owned: owned.len(),
        conditions,
        path: file,
    })
}

/// The sweep of a set of shard files ([`run_shard`]): checked to be every
/// shard of one run on unchanged inputs, assembled, its bifurcations
/// located; its outputs (written by [`EquilibriaReport::write`]) are those
/// of the unsharded run, byte for byte.
pub fn merge(shards: &[PathBuf], out: Option<&Path>) -> Result<EquilibriaReport, Error> {
    let t0 = Instant::now();
    let read = read_shards::<Vec<sweep::PointResult>>(ShardJob::Equilibria, shards)?;
    let mut sw = load_sweep(&read.input)?;
    sw.notes.extend(read.note());
    let (input, lines) = (read.input, read.results);
    let (out_dir, lock) = output_folder(&sw, out)?;
    let res = sweep::assemble(&sw.model, &sw.grid, lines, sw.report.bifurcations);
    if res.points.len() != sw.grid.len() {
        return Err(OptionsError::MergeCount {
            input: MergeInput::Sweep,
            path: input,
            held: res.points.len(),
            expected: sw.grid.len(),
        }
        .into());
    }
    Ok(report(sw, res, t0.elapsed().as_secs_f64(), (out_dir, lock)))
}

/// The output folder (default `out/<sweep name>`), none of whose outputs
/// is an input, held for this run.
fn output_folder(sw: &Sweep, out: Option<&Path>) -> Result<(PathBuf, OutputLock), Error> {
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sw.name), Path::to_path_buf);
    refuse_overwrites(&FILES.map(|f| out_dir.join(f)), &sw.inputs)?;
    let lock = OutputLock::acquire(&out_dir)?;
    Ok((out_dir, lock))
}

/// The report of a solved sweep.
fn report(
    sw: Sweep,
    res: SweepResult,
    seconds: f64,
    (out_dir, lock): (PathBuf, OutputLock),
) -> EquilibriaReport {
    let n = sw.grid.len();
    let agree = res.agreeing();
    let mut counts = BTreeMap::new();
    for p in &res.points {
        let k = p.found.iter().filter(|f| f.in_box).count();
        *counts.entry(k).or_insert(0usize) += 1;
    }
    let summary = EquilibriaSummary {
        sweep: sw.name.clone(),
        conditions: n,
        agreeing: agree,
        agreement_percent: 100.0 * agree as f64 / n as f64,
        misses: misses::misses(&res, sw.pso.certify),
        max_residual: res
            .points
            .iter()
            .flat_map(|p| &p.found)
            .map(|f| f.equilibrium.residual)
            .fold(0.0, f64::max),
        seed: sw.pso.seed,
        pso: sw.pso,
        search_box: sw.search_box,
        pso_evaluations: res.points.iter().map(|p| p.pso_evaluations).sum(),
        seconds,
        equilibria_in_box_histogram: counts,
        conditions_with_continua: res.points.iter().filter(|p| !p.continua.is_empty()).count(),
        bifurcations: res.bifurcations.clone(),
        critical_speed_closed_form: linear_critical_speed(&sw.model),
    };
    let mut r = EquilibriaReport {
        summary,
        result: res,
        sweep: sw,
        out_dir,
        lock,
        leftovers: Default::default(),
    };
    r.leftovers = crate::report::stale::leftovers(&r.out_dir, &outputs::OWN, &r.outputs());
    r
}

impl EquilibriaReport {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let (sw, s) = (&self.sweep, &self.summary);
        let mut out = self.sweep_lines();
        let unlimited = crate::jobs::simulate::unlimited::friction_ignored;
        if let Some(note) = unlimited(&sw.model, &sw.grid.friction) {
            out.push(format!(
                "  note: {note}, so every friction of the sweep gives the same equilibria"
            ));
        }
        out.extend(sw.notes.iter().map(|n| format!("  note: {n}")));
        if s.conditions_with_continua > 0 {
            out.push(format!(
                "  {} a continuum of equilibria (both axles sliding at constant force: \
                 the tyres' sliding force does not fall with slip); see continua.csv",
                match s.conditions_with_continua {
                    1 => "1 condition has".to_string(),
                    n => format!("{n} conditions have"),
                }
            ));
        }
        out.push(format!(
            "  PSO and exact agree at {}/{} conditions ({:.1} %); largest residual {:.1e}; {:.2} s",
            s.agreeing, s.conditions, s.agreement_percent, s.max_residual, s.seconds
        ));
        out.extend(misses::lines(&s.misses));
        for (k, c) in &s.equilibria_in_box_histogram {
            out.push(format!(
                "  {} with {} in the box",
                plural(*c, "condition", "conditions"),
                plural(*k, "equilibrium", "equilibria")
            ));
        }
        let critical = s.critical_speed_closed_form;
        let located = (s.bifurcations.iter()).any(|b| critical_speed_line(&sw.model, b).is_some());
        let bx = &sw.search_box;
        out.extend(critical::lines(
            &sw.model,
            (critical, located),
            &self.result,
            bx,
        ));
        for b in &s.bifurcations {
            out.push(bifurcation_line(b));
            out.extend(critical_speed_line(&self.sweep.model, b));
        }
        if sw.report.plots {
            let colours = map::colour_words(&self.result, &sw.search_box);
            out.extend(slices::figure_lines(&sw.grid, &colours));
        }
        out.extend(
            self.leftovers
                .lines("equilibria")
                .into_iter()
                .map(|l| format!("  {l}")),
        );
        out
    }

    /// The sweep in two lines: its grid, tyres and kinematics; the search
    /// box and the swarm.
    fn sweep_lines(&self) -> Vec<String> {
        let (sw, s) = (&self.sweep, &self.summary);
        vec![
        format!(
            "{}: {} ({} steer × {} friction × {} speed), tyres {} / {}, {} kinematics, {}",
            sw.name,
            plural(s.conditions, "condition", "conditions"),
            sw.grid.steer.len(),
            sw.grid.friction.len(),
            sw.grid.speed.len(),
            sw.model.front.model_name(),
            sw.model.rear.model_name(),
            match sw.model.options.kinematics {
                Kinematics::Exact => "exact",
                Kinematics::SmallAngle => "small-angle",
            },
            if sw.model.options.load_transfer {
                "with load transfer"
            } else {
                "no load transfer"
            }
        ),
        format!(
            "  box |β| ≤ {:.3} rad, |r| ≤ {:.3} rad/s; PSO seed {}, {} particles × {} iterations, fitness {}",
            sw.search_box.beta_max, sw.search_box.yaw_rate_max, sw.pso.seed, sw.pso.particles, sw.pso.iterations,
            match sw.pso.fitness {
                Fitness::Residual => "residual",
                Fitness::NewtonStep => "newton-step",
            }
        ),
        ]
    }

    /// Writes the three tables, the summary and the figures.
    pub fn write(&self) -> Result<(), Error> {
        let files = FILES.map(|f| self.out_dir.join(f));
        let r = &self.result;
        write_csv(&files[0], &EQUILIBRIA_HEADER, equilibria_rows(r))?;
        write_csv(&files[1], &BIFURCATIONS_HEADER, bifurcation_rows(r))?;
        write_csv(&files[3], &CONTINUA_HEADER, continua_rows(r))?;
        write_json_sorted(&files[2], &self.summary)?;
        let sw = &self.sweep;
        if sw.report.plots {
            let dir = &self.out_dir;
            for axis in sw.grid.varying() {
                let (diagrams, lines) = slices::diagrams(&sw.grid, axis);
                for (k, d) in diagrams.iter().enumerate() {
                    let png = dir.join(format!("{}.png", d.stem));
                    let critical = self.summary.critical_speed_closed_form;
                    figures::branch_diagram(r, (d, k, lines), &sw.search_box, critical, &png)?;
                    let rows = figures::branch_rows(r, d, &sw.search_box);
                    let header = branch_header(axis);
                    let header: Vec<&str> = header.iter().map(String::as_str).collect();
                    write_csv(&dir.join(format!("{}.csv", d.stem)), &header, rows)?;
                }
            }
            let v = sw.grid.varying();
            if v.len() >= 2 {
                let file = dir.join("stability_map.png");
                map::stability_map(r, v[0], v[1], &sw.search_box, &file)?;
            }
            for (k, c) in sw.portraits.iter().enumerate() {
                let eqs = exact::solve(&sw.model, c);
                let file = dir.join(format!("phase_portrait_{k}.png"));
                figures::phase_portrait(&sw.model, c, &sw.search_box, &eqs, &file)?;
            }
        }
        self.leftovers.remove()
    }
}

/// The header of a branch diagram's `.csv` along `axis`.
fn branch_header(axis: crate::equilibria::bifurcation::Axis) -> Vec<String> {
    let a = axis.name();
    vec![
        format!("from_{a}"),
        "from_beta".into(),
        "from_yaw_rate".into(),
        "from_kind".into(),
        format!("to_{a}"),
        "to_beta".into(),
        "to_yaw_rate".into(),
        "to_kind".into(),
    ]
}

const EQUILIBRIA_HEADER: [&str; 14] = [
    "steer",
    "friction",
    "speed",
    "beta",
    "yaw_rate",
    "kind",
    "eig1_re",
    "eig1_im",
    "eig2_re",
    "eig2_im",
    "residual",
    "found_by",
    "in_box",
    "alpha_rear",
];

/// One row per equilibrium found.
fn equilibria_rows(r: &SweepResult) -> impl Iterator<Item = Vec<String>> + '_ {
    r.points.iter().flat_map(|p| {
        p.found.iter().map(move |f| {
            let (c, e) = (p.condition, &f.equilibrium);
            let ev = e.stability.eigenvalues;
            let by = match f.found_by {
                FoundBy::Both => "both",
                FoundBy::Exact => "exact",
                FoundBy::Pso => "pso",
            };
            vec![
                c.steer.to_string(),
                c.friction.to_string(),
                c.speed.to_string(),
                e.beta.to_string(),
                e.yaw_rate.to_string(),
                e.stability.kind.name().to_string(),
                ev[0].0.to_string(),
                ev[0].1.to_string(),
                ev[1].0.to_string(),
                ev[1].1.to_string(),
                format!("{:e}", e.residual),
                by.to_string(),
                f.in_box.to_string(),
                e.alpha_rear.to_string(),
            ]
        })
    })
}

const BIFURCATIONS_HEADER: [&str; 12] = [
    "kind",
    "axis",
    "steer",
    "friction",
    "speed",
    "beta",
    "yaw_rate",
    "residual",
    "criterion",
    "kind_a",
    "kind_b",
    "verified",
];

/// The closed-form critical speed where both axles' tyres have no friction
/// limit ([`EquilibriaSummary::critical_speed_closed_form`]).
fn linear_critical_speed(model: &crate::vehicle::VehicleModel) -> Option<f64> {
    let unlimited = crate::jobs::simulate::unlimited::static_friction(model, 1.0);
    if unlimited.iter().all(|mu| mu.is_infinite()) {
        model.critical_speed()
    } else {
        None
    }
}

/// The critical speed √(−l/K) of the linearised car at friction scale
/// `friction` and speed `speed`, K from each axle's cornering stiffness at
/// zero slip under its static load (a central difference of the tyre's own
/// force, as the friction scales it on the simplified Magic Formula:
/// K = B·C·D·μ per unit load there). None for a car that does not
/// oversteer. On straight running (δ = 0, β = r = 0, no load moved) this is
/// where det J of the equilibrium (0, 0) vanishes, whatever the tyres.
fn zero_slip_critical_speed(model: &VehicleModel, friction: f64, speed: f64) -> Option<f64> {
    use crate::jobs::simulate::critical::{critical_speed_of, understeer_gradient_at};
    critical_speed_of(model, understeer_gradient_at(model, friction, speed))
}

/// One located bifurcation: kind, axis, where, the state there, the two
/// kinds of equilibrium that meet, and how well it is verified.
fn bifurcation_line(b: &Bifurcation) -> String {
    format!(
        "  {} along {} at steer {:.6} rad, friction {:.4}, speed {:.3} m/s: β {:.4} rad, r {:.4} rad/s, {} + {}, residual {:.1e}, criterion {:.1e}, {}",
        b.kind.name(),
        b.axis.name(),
        b.at.steer,
        b.at.friction,
        b.at.speed,
        b.beta,
        b.yaw_rate,
        b.kinds[0].name(),
        b.kinds[1].name(),
        b.residual,
        b.criterion,
        if b.verified { "verified" } else { "NOT verified" }
    )
}

/// The line under a critical speed along speed — a zero-eigenvalue point,
/// or a pitchfork on straight running (δ = 0, where the two equilibria
/// beside (0, 0) merge with it) — in km/h too, against the closed form
/// √(−l/K) from the tyres' cornering stiffness at zero slip.
fn critical_speed_line(model: &VehicleModel, b: &Bifurcation) -> Option<String> {
    use crate::equilibria::bifurcation::{Axis, BifurcationKind};
    let straight = b.at.steer == 0.0 && b.beta.abs() < 1e-9 && b.yaw_rate.abs() < 1e-9;
    let what = match b.kind {
        BifurcationKind::ZeroEigenvalue => format!(
            "an eigenvalue crosses zero, {} below, {} above",
            b.kinds[0].name(),
            b.kinds[1].name()
        ),
        BifurcationKind::Pitchfork if straight => {
            "straight running changes stability there as the two equilibria beside it merge with it (a pitchfork)".to_string()
        }
        _ => return None,
    };
    if b.axis != Axis::Speed {
        return None;
    }
    let u = b.at.speed;
    let closed = zero_slip_critical_speed(model, b.at.friction, u);
    let against = closed.map_or_else(String::new, |c| {
        format!(
            "; closed form sqrt(-l/K) from the tyres' cornering stiffness at zero slip {c:.4} m/s ({:+.2e} %)",
            100.0 * (u - c) / c
        )
    });
    Some(format!(
        "    critical speed {u:.4} m/s ({:.2} km/h): {what}{against}",
        3.6 * u
    ))
}

/// One row per bifurcation.
fn bifurcation_rows(r: &SweepResult) -> impl Iterator<Item = Vec<String>> + '_ {
    r.bifurcations.iter().map(|b| {
        vec![
            b.kind.name().to_string(),
            b.axis.name().to_string(),
            b.at.steer.to_string(),
            b.at.friction.to_string(),
            b.at.speed.to_string(),
            b.beta.to_string(),
            b.yaw_rate.to_string(),
            format!("{:e}", b.residual),
            format!("{:e}", b.criterion),
            b.kinds[0].name().to_string(),
            b.kinds[1].name().to_string(),
            b.verified.to_string(),
        ]
    })
}

const CONTINUA_HEADER: [&str; 9] = [
    "steer",
    "friction",
    "speed",
    "alpha_rear_from",
    "alpha_rear_to",
    "beta_from",
    "beta_to",
    "yaw_rate_from",
    "yaw_rate_to",
];

/// One row per interval of a continuum of equilibria.
fn continua_rows(r: &SweepResult) -> impl Iterator<Item = Vec<String>> + '_ {
    r.points.iter().flat_map(|p| {
        let c = p.condition;
        p.continua.iter().map(move |k| {
            [
                c.steer,
                c.friction,
                c.speed,
                k.alpha_rear.0,
                k.alpha_rear.1,
                k.beta.0,
                k.beta.1,
                k.yaw_rate.0,
                k.yaw_rate.1,
            ]
            .map(|v| v.to_string())
            .to_vec()
        })
    })
}
