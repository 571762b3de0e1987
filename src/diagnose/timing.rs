//! Where a diagnosis spends its time: its wall and CPU time, the threads it
//! ran on, and the seconds and evaluations of the run set (replays of every
//! run a fit sees, one per residual vector) by phase ([`Phase`]). Every
//! diagnosis records them (`timing` in `diagnosis.json`, the CLI's last
//! line); [`crate::diagnose::pipeline::diagnose_timed`] hands them back
//! beside it.
//!
//! The seconds of a phase are the sum, over every call in it, of the time
//! between its start and its end. On one thread (`RAYON_NUM_THREADS=1`)
//! that is the CPU time of the phase and the phases add up to the wall
//! time; on several, a call waiting on a nested parallel loop also runs
//! other phases' work, so the seconds overlap and only their ratios and the
//! evaluation counts stay meaningful. Each phase's `cpu_seconds` is the
//! process's CPU time apportioned by those ratios: they sum to it, and are
//! an apportionment, not a per-phase clock. The evaluations of a fit are told
//! apart by their order: a polish ends with the optimum's linearisation,
//! `1 + n` evaluations for the residuals and the Jacobian, then
//! `n·(n + 3)/2` for the second derivatives (`n` parameters); a candidate's
//! second derivatives are taken when it is cross-validated, and timed
//! there. Evaluations at a point the run set was just replayed at (or
//! whose replay was kept) reuse that replay
//! ([`crate::diagnose::fit::problem::Problem`]), and one stopped once its
//! cost is known to be too high replays only some runs: both are counted,
//! at less than a replay's cost.
//!
//! The timing reads the clock and counts; it decides nothing, so every
//! other number of the report is the same run after run (the timing's own
//! are not).

use serde::Serialize;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A phase of a diagnosis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Phase {
    /// The base model's tyres: the axle characteristics' grid of starts and
    /// their polish (no tyre data), or the fit to the rig data.
    BaseIdentification,
    /// The base axles' Levenberg–Marquardt fit on all runs.
    BasePolish,
    /// Its linearisation (residuals, Jacobian, second derivatives).
    BaseLinearisation,
    /// The base axles refitted on every fold.
    BaseFolds,
    /// A candidate's start: the global stage over its parameters (a grid
    /// or a swarm) and, with axles identified from the runs, their grid at
    /// its values.
    CandidateSearch,
    /// A candidate's Levenberg–Marquardt polish on all runs (its
    /// finite-difference Jacobians included).
    CandidatePolish,
    /// The residuals and Jacobian of a candidate's optimum.
    CandidateJacobian,
    /// The second derivatives of a candidate's optimum.
    CandidateCurvature,
    /// A candidate's fold refits (cross-validation).
    CandidateFolds,
    /// Everything else: the base's gaps, the held-out replays before and
    /// after, the tables.
    Rest,
}

impl Phase {
    /// Every phase, in the order a diagnosis runs them.
    pub const ALL: [Phase; 10] = [
        Phase::BaseIdentification,
        Phase::BasePolish,
        Phase::BaseLinearisation,
        Phase::BaseFolds,
        Phase::CandidateSearch,
        Phase::CandidatePolish,
        Phase::CandidateJacobian,
        Phase::CandidateCurvature,
        Phase::CandidateFolds,
        Phase::Rest,
    ];

    /// The phase's name in a table.
    pub fn name(self) -> &'static str {
        match self {
            Phase::BaseIdentification => "base identification (grid + polish)",
            Phase::BasePolish => "base fit (Levenberg–Marquardt)",
            Phase::BaseLinearisation => "base linearisation",
            Phase::BaseFolds => "base fold refits",
            Phase::CandidateSearch => "candidate global stage (grid or swarm, and axle regrid)",
            Phase::CandidatePolish => "candidate fit (Levenberg–Marquardt)",
            Phase::CandidateJacobian => "candidate Jacobian",
            Phase::CandidateCurvature => "candidate second derivatives",
            Phase::CandidateFolds => "candidate fold refits",
            Phase::Rest => "the rest",
        }
    }

    fn index(self) -> usize {
        Phase::ALL.iter().position(|&p| p == self).unwrap_or(0)
    }
}

/// One phase's share of a diagnosis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PhaseTime {
    /// The phase.
    pub phase: Phase,
    /// Seconds spent in it: the time between each of its calls' start and
    /// end, summed over the calls. On several threads the calls overlap (a
    /// call waiting on a nested parallel loop runs other phases' work
    /// meanwhile), so these sum past both the wall and the CPU time: their
    /// shares and the evaluations compare, not the seconds.
    pub seconds: f64,
    /// The process's CPU time ([`Timing::cpu_seconds`]) apportioned to the
    /// phase by its share of the phases' [`PhaseTime::seconds`]: these sum
    /// to the process's CPU time. An apportionment, not a measurement: no
    /// clock tells a phase's CPU apart where its calls run each other's
    /// work; on one thread it is the phase's own. None where the CPU time is
    /// not known.
    pub cpu_seconds: Option<f64>,
    /// Evaluations of the run set (replays of every run the fit sees).
    pub evaluations: usize,
}

/// Where a diagnosis spent its time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Timing {
    /// Wall time of the whole diagnosis, s.
    pub wall_seconds: f64,
    /// CPU time of the process over the diagnosis (user + system), s;
    /// None where the system does not tell (Linux's `/proc` does).
    pub cpu_seconds: Option<f64>,
    /// Threads of the pool the diagnosis ran on (`RAYON_NUM_THREADS`, else
    /// the cores).
    pub threads: usize,
    /// By phase ([`Phase::Rest`]: the wall time not in another phase, on
    /// one thread).
    pub phases: Vec<PhaseTime>,
    /// Candidates fitted on all runs, and of them cross-validated fold by
    /// fold (the others screened).
    pub candidates_fitted: usize,
    /// Candidates cross-validated.
    pub candidates_cross_validated: usize,
}

/// The running totals of a timed diagnosis, and when and at what CPU time
/// it started.
pub(super) struct Recorder {
    nanos: [AtomicU64; 10],
    evaluations: [AtomicUsize; 10],
    screened: AtomicUsize,
    cross_validated: AtomicUsize,
    started: Instant,
    cpu_at_start: Option<f64>,
}

impl Recorder {
    /// A recorder whose clocks start now.
    pub(super) fn start() -> Self {
        Self {
            nanos: Default::default(),
            evaluations: Default::default(),
            screened: AtomicUsize::new(0),
            cross_validated: AtomicUsize::new(0),
            started: Instant::now(),
            cpu_at_start: process_cpu_seconds(),
        }
    }

    /// Adds `elapsed` and `evaluations` to `phase`.
    pub(super) fn add(&self, phase: Phase, elapsed: Duration, evaluations: usize) {
        let k = phase.index();
        let ns = u64::try_from(elapsed.as_nanos()).unwrap_or(u64::MAX);
        self.nanos[k].fetch_add(ns, Ordering::Relaxed);
        self.evaluations[k].fetch_add(evaluations, Ordering::Relaxed);
    }

    /// Counts a candidate cross-validated, or screened (left so).
    pub(super) fn candidate(&self, cross_validated: bool) {
        let c = if cross_validated {
            &self.cross_validated
        } else {
            &self.screened
        };
        c.fetch_add(1, Ordering::Relaxed);
    }

    /// The totals so far, [`Phase::Rest`] being what the wall time since
    /// the start leaves of the others.
    pub(super) fn timing(&self) -> Timing {
        let wall = self.started.elapsed();
        let cpu = process_cpu_seconds()
            .zip(self.cpu_at_start)
            .map(|(now, then)| now - then);
        let mut phases: Vec<PhaseTime> = Phase::ALL
            .into_iter()
            .map(|p| PhaseTime {
                phase: p,
                seconds: self.nanos[p.index()].load(Ordering::Relaxed) as f64 * 1e-9,
                evaluations: self.evaluations[p.index()].load(Ordering::Relaxed),
                cpu_seconds: None,
            })
            .collect();
        let others: f64 = phases.iter().map(|p| p.seconds).sum();
        if let Some(rest) = phases.last_mut() {
            rest.seconds += (wall.as_secs_f64() - others).max(0.0);
        }
        let all: f64 = phases.iter().map(|p| p.seconds).sum();
        for p in &mut phases {
            p.cpu_seconds = cpu.filter(|_| all > 0.0).map(|c| c * p.seconds / all);
        }
        let cross_validated = self.cross_validated.load(Ordering::Relaxed);
        Timing {
            wall_seconds: wall.as_secs_f64(),
            cpu_seconds: cpu,
            threads: rayon::current_num_threads(),
            phases,
            candidates_fitted: self.screened.load(Ordering::Relaxed) + cross_validated,
            candidates_cross_validated: cross_validated,
        }
    }
}

impl Timing {
    /// The phase with the most seconds (the rest aside), if any had some.
    pub fn largest(&self) -> Option<&PhaseTime> {
        self.phases
            .iter()
            .filter(|p| p.phase != Phase::Rest && p.seconds > 0.0)
            .max_by(|a, b| a.seconds.total_cmp(&b.seconds))
    }

    /// A phase's share of the seconds of all phases, %.
    pub fn share_percent(&self, p: &PhaseTime) -> f64 {
        let all: f64 = self.phases.iter().map(|p| p.seconds).sum();
        if all > 0.0 {
            100.0 * p.seconds / all
        } else {
            0.0
        }
    }
}

/// User plus system CPU seconds of this process so far, where the system
/// says (Linux's `/proc/self/stat`, in clock ticks of 1/100 s: the
/// kernel's `USER_HZ` on every Linux the crate runs on); None elsewhere.
pub fn process_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name, which is in parentheses and may
    // hold spaces: utime and stime are the 12th and 13th of them.
    let rest = stat.rsplit_once(')')?.1;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// The instants at which a problem's model was built, one per evaluation
/// of its run set: a fit's evaluations told apart by their order.
#[derive(Default)]
pub(super) struct Stamps(Mutex<Vec<Instant>>);

impl Stamps {
    /// Notes an evaluation now.
    pub(super) fn tick(&self) {
        if let Ok(mut v) = self.0.lock() {
            v.push(Instant::now());
        }
    }

    /// Evaluations so far.
    pub(super) fn count(&self) -> usize {
        self.0.lock().map_or(0, |v| v.len())
    }

    /// The instant of evaluation `k` (in time order), if made.
    pub(super) fn at(&self, k: usize) -> Option<Instant> {
        let mut v = self.0.lock().ok()?.clone();
        v.sort();
        v.get(k).copied()
    }
}

/// Records a polish (Levenberg–Marquardt then the optimum's linearisation
/// of `n` parameters, whose Jacobian costs `jacobian` evaluations: `n` by
/// differences, 1 exact) that began at `from` with `before` evaluations
/// already stamped and has just ended: its evaluations split into the
/// polish, the residuals and Jacobian (`1 + jacobian`) and the second
/// derivatives (`n·(n + 3)/2`). Without a linearisation (`linearised`
/// false), all is polish.
pub(super) fn record_polish(
    rec: &Recorder,
    stamps: &Stamps,
    (from, before): (Instant, usize),
    (n, jacobian): (usize, usize),
    linearised: bool,
    phases: [Phase; 3],
) {
    let (jac, curv) = if linearised && n > 0 {
        (1 + jacobian, n * (n + 3) / 2)
    } else {
        (0, 0)
    };
    record_split(rec, stamps, (from, before), (jac, curv), phases);
}

/// Records a polish that began at `from` with `before` evaluations already
/// stamped and has just ended, its last `jac` evaluations the optimum's
/// residuals and Jacobian and the `curv` after them its second
/// derivatives (0: left for later, [`crate::diagnose::fit::fit_first_order`]):
/// its evaluations and time split into `phases` (polish, Jacobian, second
/// derivatives).
pub(super) fn record_split(
    rec: &Recorder,
    stamps: &Stamps,
    (from, before): (Instant, usize),
    (jac, curv): (usize, usize),
    phases: [Phase; 3],
) {
    let end = Instant::now();
    let total = stamps.count() - before;
    let polish = total.saturating_sub(jac + curv);
    let split = |k: usize| stamps.at(before + k).unwrap_or(end);
    let (t_jac, t_curv) = (split(polish), split(polish + jac));
    rec.add(phases[0], t_jac - from, polish);
    rec.add(phases[1], t_curv - t_jac, jac.min(total - polish));
    rec.add(phases[2], end - t_curv, total.saturating_sub(polish + jac));
}
