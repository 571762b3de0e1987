//! The diagnosis of a campaign: base model, where the gap lies, which
//! effect explains it, how far it shrinks on held-out runs.
//!
//! 1. Base model: the campaign's tyres, or a tyre model fitted to its rig
//!    data, or — with neither — axle characteristics identified from the
//!    training runs (simplified Magic Formula per axle, `B_f`, `B_r` and a
//!    shared peak friction `D`; refitted in every fold).
//! 2. Gap: every run replayed with its own steer and speed
//!    ([`super::gap`]); noise floors pooled over runs (median).
//! 3. Candidates: every effect of the library fitted on all runs (PSO +
//!    Levenberg–Marquardt) for its parameters and BIC, then scored by
//!    K-fold cross-validation (leave-one-run-out up to eight runs; run i in
//!    fold i mod 8 beyond), each fold refitted from the all-run optimum.
//!    The held-out error is `J = sqrt(Σ_c n_c·(rms_c/s_c)²/Σ n_c)`; the noise
//!    alone would give `J_n` (the same with the noise floors), so the gap
//!    above noise is `G = sqrt(J² − J_n²)` and an effect's reduction is
//!    `1 − G_after/G_before`.
//! 4. Verdict: the best effect is accepted when it removes at least
//!    [`ACCEPT`] of the held-out gap above noise and lowers the BIC; more
//!    effects are added greedily (jointly refitted) while each removes
//!    [`ACCEPT`] of what is left (starting from a best single that removes
//!    at least [`PROMISING`], so that two effects that each explain only
//!    part of the gap are found together; the set must then pass as a
//!    whole). Effects that also pass and leave a gap
//!    above noise within [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n of the
//!    accepted one's G are reported as confounded with it, with the
//!    experiment that would separate them.
//!    A gap below [`SIGNIFICANT`]·J_n is no gap: the verdict is empty.
//!
//! Units: SI, rad; J is dimensionless (residuals over channel scales).

use super::effects::{EffectKind, EffectSet, Parameter};
use super::fit::{fit, refit, Channel, ChannelErrors, FitOutcome, Polish, Prepared, Problem};
use super::gap::{channel_gap, regime_acceleration, run_gap, ChannelGap, PartGap, Record};
use super::model::{Augmented, Observed};
use crate::identify::data::read_rig;
use crate::identify::grouping::{group, Grouping, SlipAxis};
use crate::identify::{fit_lateral, start_tyre, FitSettings};
use crate::io::campaign::{BaseTyres, Campaign};
use crate::io::MeasuredRun;
use crate::manoeuvre::interpolate;
use crate::optim::pso::{Inertia, Pso};
use crate::tyre::{MagicSimple, Tyre};
use crate::vehicle::VehicleModel;
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Share of the held-out gap above noise an effect must remove to be
/// accepted (and each further effect of what is left).
pub const ACCEPT: f64 = 0.3;
/// An effect whose remaining held-out gap above noise is at most this
/// multiple of the accepted one's (plus [`CONFOUNDED_NOISE`] noise levels)
/// explains the data about as well: it is confounded with it.
pub const CONFOUNDED: f64 = 1.5;
/// The noise allowance of the confounding test, in noise levels.
pub const CONFOUNDED_NOISE: f64 = 0.25;
/// A held-out error below this multiple of the noise level is no gap.
pub const SIGNIFICANT: f64 = 1.3;
/// Share of the gap a best single effect must remove for the greedy search
/// to start from it (a pair whose halves each remove less than [`ACCEPT`]).
pub const PROMISING: f64 = 0.1;
/// In-sample minus held-out reduction (percentage points) past which a
/// candidate's cross-validation disagrees with its fit: a warning.
pub const DISAGREEMENT: f64 = 25.0;
/// Largest number of folds.
pub const MAX_FOLDS: usize = 8;

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParameterValue {
    /// `effect.parameter`.
    pub name: String,
    /// Unit.
    pub unit: String,
    /// Value fitted on all runs.
    pub value: f64,
    /// Its standard error (from the Jacobian; residual autocorrelation makes
    /// it optimistic).
    pub std_error: f64,
}

/// Held-out RMS of one channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelError {
    /// Channel.
    pub channel: String,
    /// Unit.
    pub unit: String,
    /// Held-out RMS residual.
    pub rms: f64,
}

/// One candidate (an effect or a combination) and its scores.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ranked {
    /// The effect names joined by `+`.
    pub effect: String,
    /// The effect names.
    pub effects: Vec<String>,
    /// Fitted parameters.
    pub parameters: Vec<ParameterValue>,
    /// Held-out combined error J of the base model.
    pub heldout_error_before: f64,
    /// Held-out combined error J with the effect.
    pub heldout_error_after: f64,
    /// Held-out RMS per channel with the effect.
    pub heldout_channels: Vec<ChannelError>,
    /// Share of the held-out gap above noise removed, %.
    pub reduction_percent: f64,
    /// Combined error J of the all-run fit on all runs (in sample).
    pub insample_error_after: f64,
    /// Share of the in-sample gap above noise the all-run fit removes, %.
    pub insample_reduction_percent: f64,
    /// Folds whose refit converged (of `folds`).
    pub folds_converged: usize,
    /// Folds refitted.
    pub folds: usize,
    /// Cross-validation that disagrees with the fit, or refits that did not
    /// converge.
    pub warning: Option<String>,
    /// BIC of the all-run fit.
    pub bic: f64,
    /// BIC minus the base model's (negative: better).
    pub delta_bic: f64,
}

/// Effects that explain the gap about equally well.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Confounded {
    /// The effects.
    pub effects: Vec<String>,
    /// Their reductions, %.
    pub reduction_percent: Vec<f64>,
    /// The experiment that would separate them.
    pub separating_test: String,
}

/// The verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// Effects the evidence supports (empty: the gap is within noise or no
    /// effect explains it).
    pub effects: Vec<String>,
    /// Their parameters.
    pub parameters: Vec<ParameterValue>,
    /// In words.
    pub statement: String,
}

/// Before/after on held-out runs for one part of the data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Shrinkage {
    /// Channel.
    pub channel: String,
    /// `all`, a time window or a regime.
    pub part: String,
    /// Samples.
    pub samples: usize,
    /// Held-out RMS with the base model.
    pub before: f64,
    /// Held-out RMS with the verdict's effects.
    pub after: f64,
    /// Noise floor of the channel.
    pub noise_floor: f64,
    /// Share of the gap above noise removed, %.
    pub reduction_percent: f64,
}

/// Noise floor and scale of a channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelNoise {
    /// Channel.
    pub channel: String,
    /// Unit.
    pub unit: String,
    /// Median over runs of the noise floor.
    pub noise_floor: f64,
    /// Residual scale used in the fits.
    pub scale: f64,
    /// Runs measuring it.
    pub runs: usize,
}

/// The gap of one run with the base model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunGap {
    /// Run.
    pub run: String,
    /// Per channel.
    pub channels: Vec<ChannelGap>,
    /// Gain and phase error per frequency band (runs with a rich input).
    pub bands: Vec<super::gap::BandGap>,
}

/// Where the gap lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GapReport {
    /// Is there a gap above noise on held-out runs.
    pub significant: bool,
    /// Held-out J of the base model.
    pub heldout_error: f64,
    /// J of the noise alone.
    pub noise_level: f64,
    /// Noise floors.
    pub noise: Vec<ChannelNoise>,
    /// Per channel, window and regime over all runs (base model replays).
    pub parts: Vec<Shrinkage>,
    /// Per run.
    pub runs: Vec<RunGap>,
    /// The findings in words.
    pub summary: Vec<String>,
}

/// The base model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BaseReport {
    /// Where its tyres come from.
    pub tyres: String,
    /// Front tyre (all-run or rig fit).
    pub front: Tyre,
    /// Rear tyre.
    pub rear: Tyre,
}

/// Everything the diagnosis found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnosis {
    /// Campaign name.
    pub campaign: String,
    /// Seed of every random search.
    pub seed: u64,
    /// Runs, in order.
    pub runs: Vec<String>,
    /// Folds of the cross-validation.
    pub folds: usize,
    /// Notes on the inputs.
    pub notes: Vec<String>,
    /// Glitches, standstills and crawling found in the runs and what was
    /// excluded, repaired or masked.
    pub cleaning: crate::io::clean::CleaningReport,
    /// The base model.
    pub base: BaseReport,
    /// Where the gap lies.
    pub gap: GapReport,
    /// Single effects, best first.
    pub ranking: Vec<Ranked>,
    /// Combinations tried, best first.
    pub combinations: Vec<Ranked>,
    /// The verdict.
    pub verdict: Verdict,
    /// Confounded effects.
    pub confounded: Vec<Confounded>,
    /// Before and after on held-out runs, per channel, window and regime.
    pub shrinkage: Vec<Shrinkage>,
    /// Held-out replays (measured / base / verdict) for the figures.
    #[serde(skip)]
    pub overlays: Vec<Overlay>,
}

/// One run's held-out replays.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlay {
    /// Run name.
    pub run: String,
    /// Times, s.
    pub t: Vec<f64>,
    /// Measured channels.
    pub measured: Vec<(Channel, Vec<f64>)>,
    /// Base model.
    pub base: Observed,
    /// With the verdict's effects.
    pub after: Observed,
    /// Base-model combined error of the run.
    pub gap: f64,
}

/// A set of effects with their fitted values, and the model builder.
#[derive(Clone)]
struct Setting<'a> {
    base: &'a Bases,
    kinds: Vec<EffectKind>,
    fixed: EffectSet,
}

/// The base model of all runs and of every fold.
struct Bases {
    all: Augmented,
    folds: Vec<Augmented>,
    nominal_share: f64,
    /// Axle characteristics identified from the runs (all runs, per fold):
    /// refitted jointly with every candidate, since an effect changes what
    /// the tyres must have been.
    axle: Option<(Vec<f64>, Vec<Vec<f64>>)>,
}

/// Bounds of the axle characteristics fitted from runs: B front, B rear
/// (1/rad), peak friction D.
const AXLE_BOUNDS: [(f64, f64); 3] = [(2.0, 80.0), (2.0, 80.0), (0.3, 3.5)];

/// The simplified Magic Formula axle tyres of parameters (B_f, B_r, D).
fn axle_tyres(p: &[f64]) -> (Tyre, Tyre) {
    (
        Tyre::MagicSimple(MagicSimple {
            b: p[0],
            c: 1.3,
            d: p[2],
        }),
        Tyre::MagicSimple(MagicSimple {
            b: p[1],
            c: 1.3,
            d: p[2],
        }),
    )
}

/// The roll degree of freedom's dynamics, fitted with the roll effects: a
/// campaign's `[roll]` is a guess (no roll channel is needed), and roll
/// steer or camber seen through the wrong roll frequency and damping is
/// mimicked by stiffness changes of the wrong sign. The roll gradient stays
/// the campaign's: it only scales the per-radian roll-steer and roll-camber
/// values. Off values (NaN) are the campaign's.
static ROLL_DYNAMICS: [Parameter; 2] = [
    Parameter {
        name: "frequency",
        unit: "Hz",
        off: f64::NAN,
        bounds: (0.3, 5.0),
    },
    Parameter {
        name: "damping",
        unit: "-",
        off: f64::NAN,
        bounds: (0.1, 2.0),
    },
];

/// Whether a candidate carries the roll-dynamics parameters.
fn fits_roll(kinds: &[EffectKind]) -> bool {
    kinds.iter().any(|e| e.uses_roll())
}

/// The model of a candidate's parameter vector: the axle characteristics
/// first when they are fitted (`axle`), then each effect's parameters, then
/// the roll dynamics when a roll effect is among them ([`ROLL_DYNAMICS`]).
fn with_effects(
    base: &Augmented,
    fixed: &EffectSet,
    kinds: &[EffectKind],
    axle: bool,
    p: &[f64],
) -> Augmented {
    let mut m = base.clone();
    m.effects = *fixed;
    let mut k = 0;
    if axle {
        (m.base.front, m.base.rear) = axle_tyres(&p[..3]);
        k = 3;
    }
    for e in kinds {
        let n = e.parameters().len();
        m.effects.set(*e, &p[k..k + n]);
        k += n;
    }
    if fits_roll(kinds) {
        m.roll.frequency = p[k];
        m.roll.damping = p[k + 1];
    }
    m
}

/// The start of a combination: the axle characteristics and effect values
/// of the current set, the added effect's values from its single fit, and
/// the roll dynamics from whichever of the two fitted them (the current
/// set first).
fn combined_start(
    current: (&[EffectKind], &[f64]),
    added: (EffectKind, &[f64]),
    axle_count: usize,
) -> Vec<f64> {
    let (kinds, p) = current;
    let effect_len: usize = kinds.iter().map(|e| e.parameters().len()).sum();
    let end = axle_count + effect_len;
    let n = added.0.parameters().len();
    let mut start = p[..end].to_vec();
    start.extend(&added.1[axle_count..axle_count + n]);
    if fits_roll(kinds) {
        start.extend(&p[end..end + 2]);
    } else if added.0.uses_roll() {
        start.extend(&added.1[axle_count + n..axle_count + n + 2]);
    }
    start
}

impl Setting<'_> {
    fn axle(&self) -> bool {
        self.base.axle.is_some()
    }
    /// The effect parameters in vector order, the roll dynamics last.
    fn parameters(&self) -> impl Iterator<Item = &'static Parameter> + '_ {
        let roll = if fits_roll(&self.kinds) {
            &ROLL_DYNAMICS[..]
        } else {
            &[]
        };
        self.kinds
            .iter()
            .flat_map(|e| e.parameters().iter())
            .chain(roll.iter())
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        let axle = if self.axle() { &AXLE_BOUNDS[..] } else { &[] };
        axle.iter()
            .copied()
            .chain(self.parameters().map(|q| q.bounds))
            .collect()
    }
    fn off(&self) -> Vec<f64> {
        let axle = self.base.axle.as_ref().map_or(&[][..], |a| &a.0[..]);
        let roll = self.base.all.roll;
        let mut p: Vec<f64> = axle
            .iter()
            .copied()
            .chain(self.kinds.iter().flat_map(|e| {
                e.parameters().iter().map(|q| {
                    if q.off.is_nan() {
                        self.base.nominal_share
                    } else {
                        q.off
                    }
                })
            }))
            .collect();
        if fits_roll(&self.kinds) {
            p.extend([roll.frequency, roll.damping]);
        }
        p
    }
}

/// Everything scored for one candidate.
struct Scored {
    kinds: Vec<EffectKind>,
    full: FitOutcome,
    /// Errors of the all-run fit on all runs.
    insample: ChannelErrors,
    heldout: ChannelErrors,
    fold_params: Vec<Vec<f64>>,
    folds_converged: usize,
}

struct Context<'a> {
    runs: Vec<Prepared>,
    folds: Vec<Vec<usize>>,
    scales: [f64; 3],
    bases: &'a Bases,
    pso: Pso,
    progress: Option<&'a AtomicUsize>,
}

impl Context<'_> {
    fn tick(&self) {
        if let Some(p) = self.progress {
            p.fetch_add(1, Ordering::Relaxed);
        }
    }

    fn training(&self, fold: usize) -> Vec<&Prepared> {
        (0..self.runs.len())
            .filter(|i| !self.folds[fold].contains(i))
            .map(|i| &self.runs[i])
            .collect()
    }

    /// Fits a candidate on all runs (PSO from `start`) and scores it on
    /// every fold, refitted from the all-run optimum ([`refit`]: its
    /// linearisation first, Levenberg–Marquardt within a budget when that
    /// does not converge; non-converged folds are counted and warned about).
    /// A `start` skips the swarm: the polish starts from it (combinations
    /// start from their members' single fits).
    fn score(
        &self,
        kinds: Vec<EffectKind>,
        fixed: EffectSet,
        start: Option<Vec<f64>>,
        salt: u64,
    ) -> Scored {
        let s = Setting {
            base: self.bases,
            kinds,
            fixed,
        };
        let problem = Problem {
            build: |p: &[f64]| with_effects(&self.bases.all, &s.fixed, &s.kinds, s.axle(), p),
            runs: self.runs.iter().collect(),
            scales: self.scales,
            bounds: s.bounds(),
        };
        let pso = Pso {
            seed: self.pso.seed ^ salt.wrapping_mul(0x9E37_79B9_7F4A_7C15),
            ..self.pso
        };
        let full = match start {
            Some(p) => fit(&problem, &p, None, Polish::LevenbergMarquardt),
            None => fit(
                &problem,
                &s.off(),
                Some((&pso, if s.axle() { 3 } else { 0 })),
                Polish::LevenbergMarquardt,
            ),
        };
        let all_model = with_effects(&self.bases.all, &s.fixed, &s.kinds, s.axle(), &full.params);
        let mut insample = ChannelErrors::default();
        for r in &self.runs {
            insample.add(&r.errors(&all_model));
        }
        self.tick();
        let per_fold: Vec<(ChannelErrors, Vec<f64>, bool)> = (0..self.folds.len())
            .map(|k| {
                let base = &self.bases.folds[k];
                let problem = Problem {
                    build: |p: &[f64]| with_effects(base, &s.fixed, &s.kinds, s.axle(), p),
                    runs: self.training(k),
                    scales: self.scales,
                    bounds: s.bounds(),
                };
                let f = refit(&problem, &full, &training_rows(&self.runs, &self.folds[k]));
                let model = with_effects(base, &s.fixed, &s.kinds, s.axle(), &f.params);
                let mut e = ChannelErrors::default();
                for &i in &self.folds[k] {
                    e.add(&self.runs[i].errors(&model));
                }
                self.tick();
                (e, f.params, f.converged)
            })
            .collect();
        let mut heldout = ChannelErrors::default();
        for (e, _, _) in &per_fold {
            heldout.add(e);
        }
        Scored {
            kinds: s.kinds,
            full,
            insample,
            heldout,
            folds_converged: per_fold.iter().filter(|f| f.2).count(),
            fold_params: per_fold.into_iter().map(|(_, p, _)| p).collect(),
        }
    }

    /// Held-out replays of every run with a candidate's fold parameters.
    fn heldout_observed(&self, sc: Option<&Scored>, fixed: &EffectSet) -> Vec<Observed> {
        let mut out = vec![Observed::default(); self.runs.len()];
        for (k, fold) in self.folds.iter().enumerate() {
            let model = match sc {
                Some(sc) => with_effects(
                    &self.bases.folds[k],
                    fixed,
                    &sc.kinds,
                    self.bases.axle.is_some(),
                    &sc.fold_params[k],
                ),
                None => self.bases.folds[k].clone(),
            };
            for &i in fold {
                let r = &self.runs[i];
                out[i] = r.observe(&model);
            }
        }
        out
    }
}

/// The residual rows of a fold's training runs (all but `held_out`) in the
/// all-run problem, whose rows follow the runs' order.
fn training_rows(runs: &[Prepared], held_out: &[usize]) -> Vec<std::ops::Range<usize>> {
    let mut start = 0;
    let mut rows = Vec::new();
    for (i, r) in runs.iter().enumerate() {
        let n = r.count();
        if !held_out.contains(&i) {
            rows.push(start..start + n);
        }
        start += n;
    }
    rows
}

fn gap_above(j: f64, jn: f64) -> f64 {
    (j * j - jn * jn).max(0.0).sqrt()
}

fn reduction(before: f64, after: f64, jn: f64) -> f64 {
    let g0 = gap_above(before, jn);
    if g0 <= 0.0 {
        0.0
    } else {
        100.0 * (1.0 - gap_above(after, jn) / g0)
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    if v.is_empty() {
        f64::NAN
    } else {
        v[v.len() / 2]
    }
}

/// Work units reported to the progress counter for a campaign.
pub fn work_units(c: &Campaign) -> usize {
    let folds = c.runs.len().min(MAX_FOLDS);
    let singles = c.effects.len() * (1 + folds);
    let combos = c.settings.max_effects.saturating_sub(1) * c.effects.len() * (1 + folds);
    1 + singles + combos
}

/// The base models: all runs and each fold's training runs.
fn base_models(
    c: &Campaign,
    runs: &[Prepared],
    folds: &[Vec<usize>],
    scales_hint: [f64; 3],
    pso: &Pso,
) -> Result<(Bases, String), String> {
    let vehicle = c.vehicle.clone();
    let nominal_share = vehicle.front_transfer_share();
    let make = |f: Tyre, r: Tyre| Augmented {
        roll: c.roll,
        ..Augmented::new(VehicleModel::new(vehicle.clone(), f, r), c.friction)
    };
    // Tyres not fitted to the runs: one model for all runs and every fold.
    let fixed = |m: Augmented| Bases {
        folds: vec![m.clone(); folds.len()],
        all: m,
        nominal_share,
        axle: None,
    };
    match &c.tyres {
        BaseTyres::Given(f, r) => Ok((
            fixed(make((**f).clone(), (**r).clone())),
            "given tyre files".into(),
        )),
        BaseTyres::Rig { path, model } => {
            let data = read_rig(path).map_err(|e| e.to_string())?;
            let conditions = group(path, &data, &Grouping::default(), SlipAxis::Angle)
                .map_err(|e| e.to_string())?
                .conditions;
            if conditions.is_empty() {
                return Err(format!(
                    "{}: no lateral test condition in the rig data",
                    path.display()
                ));
            }
            let mut loads: Vec<f64> = conditions.iter().map(|q| q.fz).collect();
            loads.sort_by(f64::total_cmp);
            let t0 = start_tyre(model, loads[loads.len() / 2])?;
            let mut settings = FitSettings::new(c.settings.seed);
            settings.pso.particles = 40;
            settings.pso.iterations = 150;
            let f = fit_lateral(&t0, &conditions, &settings)
                .map_err(|e| format!("{}: {e}", path.display()))?;
            Ok((
                fixed(make(f.tyre.clone(), f.tyre.clone())),
                format!(
                    "{} fitted to the rig data {} (σ {:.2} % of the force)",
                    model,
                    path.display(),
                    f.sigma_percent
                ),
            ))
        }
        BaseTyres::FromRuns => {
            // Axle characteristics from the runs: B per axle and a shared
            // peak friction D of a simplified Magic Formula (C = 1.3).
            let build = |p: &[f64]| {
                let (f, r) = axle_tyres(p);
                make(f, r)
            };
            let problem = Problem {
                build,
                runs: runs.iter().collect(),
                scales: scales_hint,
                bounds: AXLE_BOUNDS.to_vec(),
            };
            let full = fit(
                &problem,
                &[10.0, 10.0, 1.0],
                Some((pso, 0)),
                Polish::LevenbergMarquardt,
            );
            let fold_params: Vec<Vec<f64>> = (0..folds.len())
                .into_par_iter()
                .map(|k| {
                    let train: Vec<&Prepared> = (0..runs.len())
                        .filter(|i| !folds[k].contains(i))
                        .map(|i| &runs[i])
                        .collect();
                    let p = Problem {
                        build,
                        runs: train,
                        scales: scales_hint,
                        bounds: AXLE_BOUNDS.to_vec(),
                    };
                    refit(&p, &full, &training_rows(runs, &folds[k])).params
                })
                .collect();
            let p = &full.params;
            Ok((
                Bases {
                    all: build(p),
                    folds: fold_params.iter().map(|q| build(q)).collect(),
                    nominal_share,
                    axle: Some((p.clone(), fold_params)),
                },
                format!(
                    "no tyre data: axle characteristics identified from the runs (simplified Magic Formula, C = 1.3; refitted with every candidate): B front {:.2} ± {:.2}, B rear {:.2} ± {:.2} 1/rad, D {:.3} ± {:.3}",
                    p[0], full.std_errors[0], p[1], full.std_errors[1], p[2], full.std_errors[2]
                ),
            ))
        }
    }
}

/// The effect parameters of a fit whose first `skip` parameters are the
/// axle characteristics.
fn parameter_values(kinds: &[EffectKind], f: &FitOutcome, skip: usize) -> Vec<ParameterValue> {
    let named = kinds
        .iter()
        .flat_map(|e| e.parameters().iter().map(move |q| (e.name(), q)));
    let roll = fits_roll(kinds).then_some(ROLL_DYNAMICS.iter().map(|q| ("roll", q)));
    named
        .chain(roll.into_iter().flatten())
        .enumerate()
        .map(|(i, (group, q))| ParameterValue {
            name: format!("{group}.{}", q.name),
            unit: q.unit.into(),
            value: f.params[skip + i],
            std_error: f.std_errors[skip + i],
        })
        .collect()
}

fn channel_errors(e: &ChannelErrors) -> Vec<ChannelError> {
    Channel::ALL
        .into_iter()
        .filter_map(|c| {
            e.rms(c).map(|rms| ChannelError {
                channel: c.name().into(),
                unit: c.unit().into(),
                rms,
            })
        })
        .collect()
}

/// Runs the diagnosis of a campaign. `progress` counts work units (see
/// [`work_units`]).
pub fn diagnose(c: &Campaign, progress: Option<&AtomicUsize>) -> Result<Diagnosis, String> {
    let set = &c.settings;
    let runs: Vec<Prepared> = c
        .runs
        .iter()
        .map(|r| Prepared::new(r, set.step, set.sample_rate))
        .collect();
    let k = runs.len().min(MAX_FOLDS);
    let folds: Vec<Vec<usize>> = (0..k)
        .map(|f| (0..runs.len()).filter(|i| i % k == f).collect())
        .collect();
    let pso = Pso {
        particles: set.particles,
        iterations: set.iterations,
        inertia: Inertia::LinearDecreasing,
        seed: set.seed,
        parallel: false,
        ..Pso::default()
    };
    // Channel scales before the base model exists (for the axle fit): 2 % of
    // the signal, refined with the noise floors below.
    let signal = |ch: Channel| -> f64 {
        let (mut s, mut n) = (0.0, 0usize);
        for r in &c.runs {
            if let Some(v) = ch.of(r) {
                s += v.iter().map(|x| x * x).sum::<f64>();
                n += v.len();
            }
        }
        if n == 0 {
            1.0
        } else {
            (s / n as f64).sqrt().max(1e-9)
        }
    };
    let signals = Channel::ALL.map(signal);
    let hint = signals.map(|s| 0.02 * s);
    let (bases, tyre_source) = base_models(c, &runs, &folds, hint, &pso)?;
    if let Some(p) = progress {
        p.fetch_add(1, Ordering::Relaxed);
    }

    // Where the gap lies: every run replayed by the all-run base model.
    let run_gaps: Vec<RunGap> = c
        .runs
        .par_iter()
        .map(|run| base_run_gap(&bases.all, run, set.step))
        .collect();
    let noise: Vec<ChannelNoise> = Channel::ALL
        .into_iter()
        .filter_map(|ch| {
            let floors: Vec<f64> = run_gaps
                .iter()
                .filter_map(|g| g.channels.iter().find(|x| x.channel == ch.name()))
                .map(|x| x.noise_floor)
                .collect();
            (!floors.is_empty()).then(|| {
                let nf = median(floors.clone());
                ChannelNoise {
                    channel: ch.name().into(),
                    unit: ch.unit().into(),
                    noise_floor: nf,
                    scale: nf.max(hint[ch.index()]),
                    runs: floors.len(),
                }
            })
        })
        .collect();
    let mut scales = hint;
    let mut floors = [0.0; 3];
    for n in &noise {
        let ch = Channel::ALL
            .into_iter()
            .find(|c| c.name() == n.channel)
            .expect("a channel");
        scales[ch.index()] = n.scale;
        floors[ch.index()] = n.noise_floor;
    }
    let ctx = Context {
        runs,
        folds,
        scales,
        bases: &bases,
        pso,
        progress,
    };
    let noise_level = |e: &ChannelErrors| {
        let n: usize = e.count.iter().sum();
        let s: f64 = (0..3)
            .map(|i| e.count[i] as f64 * (floors[i] / scales[i]).powi(2))
            .sum();
        (s / n.max(1) as f64).sqrt()
    };

    // The base model on held-out runs.
    let base_scored = ctx.score(Vec::new(), EffectSet::default(), None, 0);
    let j0 = base_scored.heldout.combined(&scales);
    let jn = noise_level(&base_scored.heldout);
    let bic0 = base_scored.full.bic();
    let j0_in = base_scored.insample.combined(&scales);
    let jn_in = noise_level(&base_scored.insample);
    let significant = j0 > SIGNIFICANT * jn;

    // Single effects.
    let singles: Vec<Scored> = c
        .effects
        .par_iter()
        .enumerate()
        .map(|(i, e)| ctx.score(vec![*e], EffectSet::default(), None, i as u64 + 1))
        .collect();
    let axle_count = if bases.axle.is_some() { 3 } else { 0 };
    let rank = |sc: &Scored| -> Ranked {
        let j = sc.heldout.combined(&scales);
        let names: Vec<String> = sc.kinds.iter().map(|e| e.name().to_string()).collect();
        let held = reduction(j0, j, jn);
        let j_in = sc.insample.combined(&scales);
        let inside = reduction(j0_in, j_in, jn_in);
        let folds = ctx.folds.len();
        let mut warnings = Vec::new();
        if inside - held > DISAGREEMENT && inside >= 100.0 * ACCEPT {
            warnings.push(format!(
                "the fit on all runs removes {inside:.0} % of the gap but only {held:.0} % on held-out runs: \
                 the effect does not generalise across runs, or the runs cannot pin its parameters"
            ));
        }
        if sc.folds_converged < folds {
            warnings.push(format!(
                "{} of {folds} fold refits did not converge",
                folds - sc.folds_converged
            ));
        }
        Ranked {
            effect: names.join("+"),
            effects: names,
            parameters: parameter_values(&sc.kinds, &sc.full, axle_count),
            heldout_error_before: j0,
            heldout_error_after: j,
            heldout_channels: channel_errors(&sc.heldout),
            reduction_percent: held,
            insample_error_after: j_in,
            insample_reduction_percent: inside,
            folds_converged: sc.folds_converged,
            folds,
            warning: (!warnings.is_empty()).then(|| warnings.join("; ")),
            bic: sc.full.bic(),
            delta_bic: sc.full.bic() - bic0,
        }
    };
    let mut order: Vec<usize> = (0..singles.len()).collect();
    order.sort_by(|&a, &b| {
        singles[a]
            .heldout
            .combined(&scales)
            .total_cmp(&singles[b].heldout.combined(&scales))
    });
    let ranking: Vec<Ranked> = order.iter().map(|&i| rank(&singles[i])).collect();

    // Verdict: the best single, then greedy additions.
    let mut chosen: Option<Scored> = None;
    let mut combinations = Vec::new();
    let mut lookalikes: Vec<usize> = Vec::new();
    if significant && !order.is_empty() {
        let best = &singles[order[0]];
        let r = rank(best);
        // A best single below the acceptance share can still be half of a
        // pair of effects: the greedy search starts from it when it is
        // promising, and the set found must pass as a whole.
        if r.reduction_percent >= 100.0 * PROMISING && r.delta_bic < 0.0 {
            // Look-alikes of the accepted effect: singles that also pass and
            // leave about as small a gap.
            let g_best = gap_above(r.heldout_error_after, jn);
            lookalikes = order[1..]
                .iter()
                .copied()
                .filter(|&i| {
                    let o = rank(&singles[i]);
                    o.reduction_percent >= 100.0 * ACCEPT
                        && gap_above(o.heldout_error_after, jn)
                            <= CONFOUNDED * g_best + CONFOUNDED_NOISE * jn
                })
                .collect();
            let mut current = Scored {
                kinds: best.kinds.clone(),
                full: best.full.clone(),
                insample: best.insample,
                heldout: best.heldout,
                fold_params: best.fold_params.clone(),
                folds_converged: best.folds_converged,
            };
            // Greedy: add the effect that best closes what is left.
            while current.kinds.len() < set.max_effects {
                let jc = current.heldout.combined(&scales);
                if jc <= SIGNIFICANT * jn {
                    break;
                }
                // Every remaining effect: the second effect of a pair is
                // often not among the best singles (those mimic the first).
                let tries: Vec<EffectKind> = order
                    .iter()
                    .map(|&i| singles[i].kinds[0])
                    .filter(|e| !current.kinds.contains(e))
                    .collect();
                let cur = &current;
                let mut scored: Vec<Scored> = tries
                    .par_iter()
                    .enumerate()
                    .map(|(i, e)| {
                        let mut kinds = cur.kinds.clone();
                        kinds.push(*e);
                        let single = singles.iter().find(|s| s.kinds[0] == *e).expect("scored");
                        let start = combined_start(
                            (&cur.kinds, &cur.full.params),
                            (*e, &single.full.params),
                            axle_count,
                        );
                        ctx.score(kinds, EffectSet::default(), Some(start), 1000 + i as u64)
                    })
                    .collect();
                scored.sort_by(|a, b| {
                    a.heldout
                        .combined(&scales)
                        .total_cmp(&b.heldout.combined(&scales))
                });
                combinations.extend(scored.iter().map(&rank));
                let Some(next) = scored.into_iter().next() else {
                    break;
                };
                let jnext = next.heldout.combined(&scales);
                let extra = reduction(jc, jnext, jn);
                if extra >= 100.0 * ACCEPT && next.full.bic() < current.full.bic() {
                    current = next;
                } else {
                    break;
                }
            }
            let total = reduction(j0, current.heldout.combined(&scales), jn);
            if total >= 100.0 * ACCEPT && current.full.bic() < bic0 {
                chosen = Some(current);
            }
        }
    }
    combinations.sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    // The accepted first effect's look-alikes, less those the verdict took
    // in as well, with the experiments that would separate them.
    let mut confounded = Vec::new();
    if let Some(sc) = &chosen {
        let first = singles
            .iter()
            .find(|x| x.kinds[0] == sc.kinds[0])
            .expect("the verdict starts from a scored single");
        let members: Vec<&Scored> = std::iter::once(first)
            .chain(
                lookalikes
                    .iter()
                    .map(|&i| &singles[i])
                    .filter(|x| !sc.kinds.contains(&x.kinds[0])),
            )
            .collect();
        if members.len() > 1 {
            confounded.push(Confounded {
                effects: members
                    .iter()
                    .map(|x| x.kinds[0].name().to_string())
                    .collect(),
                reduction_percent: members.iter().map(|x| rank(x).reduction_percent).collect(),
                separating_test: members
                    .iter()
                    .map(|x| format!("{}: {}", x.kinds[0].name(), x.kinds[0].signature()))
                    .collect::<Vec<_>>()
                    .join("; "),
            });
        }
    }

    // Before and after on held-out runs, per channel, window and regime.
    let base_obs = ctx.heldout_observed(None, &EffectSet::default());
    let after_obs = match &chosen {
        Some(sc) => ctx.heldout_observed(Some(sc), &EffectSet::default()),
        None => base_obs.clone(),
    };
    let shrinkage = parts_table(&c.runs, &ctx.runs, &base_obs, &after_obs, &floors);
    let parts = parts_table(&c.runs, &ctx.runs, &base_obs, &base_obs, &floors);

    let verdict = match &chosen {
        Some(sc) => {
            let r = rank(sc);
            Verdict {
                effects: r.effects.clone(),
                parameters: r.parameters.clone(),
                statement: format!(
                    "{} explains the gap: held-out error {:.3} → {:.3} (noise level {:.3}), {:.0} % of the gap above noise removed",
                    r.effect, j0, r.heldout_error_after, jn, r.reduction_percent
                ),
            }
        }
        None => Verdict {
            effects: Vec::new(),
            parameters: Vec::new(),
            statement: if !significant {
                format!(
                    "no significant gap: held-out error {j0:.3} is within {SIGNIFICANT} × the noise level {jn:.3}"
                )
            } else {
                format!(
                    "a gap (held-out error {j0:.3}, noise level {jn:.3}) that no candidate effect explains: the best, {}, removes {:.0} % of it (acceptance needs {:.0} %) — a model-form error outside the library",
                    ranking.first().map_or("none", |r| r.effect.as_str()),
                    ranking.first().map_or(0.0, |r| r.reduction_percent),
                    100.0 * ACCEPT
                )
            },
        },
    };

    let mut overlays: Vec<Overlay> = (0..ctx.runs.len())
        .map(|i| {
            let r = &ctx.runs[i];
            let mut e = ChannelErrors::default();
            for (ch, m) in &r.measured {
                let sim = observed_channel(&base_obs[i], *ch);
                for (y, x) in sim.iter().zip(m) {
                    e.sum_sq[ch.index()] += (y - x) * (y - x);
                    e.count[ch.index()] += 1;
                }
            }
            Overlay {
                run: r.name.clone(),
                t: r.times.clone(),
                measured: r.measured.clone(),
                base: base_obs[i].clone(),
                after: after_obs[i].clone(),
                gap: e.combined(&scales),
            }
        })
        .collect();
    overlays.sort_by(|a, b| b.gap.total_cmp(&a.gap));

    let summary = gap_summary(&run_gaps, &parts, significant, j0, jn);
    Ok(Diagnosis {
        campaign: c.name.clone(),
        seed: set.seed,
        runs: ctx.runs.iter().map(|r| r.name.clone()).collect(),
        folds: ctx.folds.len(),
        notes: c.notes.clone(),
        cleaning: c.cleaning.clone(),
        base: BaseReport {
            tyres: tyre_source,
            front: bases.all.base.front.clone(),
            rear: bases.all.base.rear.clone(),
        },
        gap: GapReport {
            significant,
            heldout_error: j0,
            noise_level: jn,
            noise,
            parts,
            runs: run_gaps,
            summary,
        },
        ranking,
        combinations,
        verdict,
        confounded,
        shrinkage,
        overlays,
    })
}

/// A channel of an observation.
pub fn observed_channel(o: &Observed, c: Channel) -> &[f64] {
    match c {
        Channel::YawRate => &o.yaw_rate,
        Channel::Ay => &o.ay,
        Channel::Beta => &o.beta,
    }
}

/// The base model's gap on one run, at the run's own samples (the base
/// model has no sensor effects: its history is what the sensors read).
fn base_run_gap(base: &Augmented, run: &MeasuredRun, step: f64) -> RunGap {
    let p = Prepared::new(run, step, f64::INFINITY);
    let x0 = base.initial_state(&p.drive, p.start.0, p.start.1);
    let history = base.simulate(&p.drive, x0).history;
    let idx = super::gap::scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let t = pick(&run.t);
    let yaw_rate: Vec<f64> = t
        .iter()
        .map(|&t| interpolate(&history.t, &history.yaw_rate, t))
        .collect();
    RunGap {
        run: run.path.display().to_string(),
        channels: run_gap(run, &history),
        bands: super::gap::band_gaps(&t, &pick(&run.steer), &pick(&run.yaw_rate), &yaw_rate),
    }
}

/// Held-out RMS before/after pooled over runs per channel, window and regime.
fn parts_table(
    runs: &[MeasuredRun],
    prepared: &[Prepared],
    before: &[Observed],
    after: &[Observed],
    floors: &[f64; 3],
) -> Vec<Shrinkage> {
    // (channel, part) → (Σ before², Σ after², n)
    let mut acc: Vec<(Channel, String, f64, f64, usize)> = Vec::new();
    for (i, p) in prepared.iter().enumerate() {
        let run = &runs[i];
        let at = |v: &[f64]| -> Vec<f64> {
            p.times.iter().map(|&t| interpolate(&run.t, v, t)).collect()
        };
        let steer = at(&run.steer);
        let speed = at(&run.speed);
        let ay = at(&regime_acceleration(run));
        let rec = Record {
            t: &p.times,
            steer: &steer,
            ay: &ay,
            speed: &speed,
        };
        for (ch, m) in &p.measured {
            let gb = channel_gap(
                ch.name(),
                ch.unit(),
                &rec,
                m,
                observed_channel(&before[i], *ch),
            );
            let ga = channel_gap(
                ch.name(),
                ch.unit(),
                &rec,
                m,
                observed_channel(&after[i], *ch),
            );
            let all_b = PartGap {
                name: "all".into(),
                samples: m.len(),
                rms: gb.rms,
                bias: gb.bias,
            };
            let all_a = PartGap {
                rms: ga.rms,
                ..all_b.clone()
            };
            let pb = std::iter::once(&all_b)
                .chain(gb.windows.iter())
                .chain(gb.regimes.iter());
            let pa = std::iter::once(&all_a)
                .chain(ga.windows.iter())
                .chain(ga.regimes.iter());
            for (b, a) in pb.zip(pa) {
                let n = b.samples as f64;
                match acc.iter_mut().find(|x| x.0 == *ch && x.1 == b.name) {
                    Some(x) => {
                        x.2 += b.rms * b.rms * n;
                        x.3 += a.rms * a.rms * n;
                        x.4 += b.samples;
                    }
                    None => acc.push((
                        *ch,
                        b.name.clone(),
                        b.rms * b.rms * n,
                        a.rms * a.rms * n,
                        b.samples,
                    )),
                }
            }
        }
    }
    acc.into_iter()
        .filter(|x| x.4 > 0)
        .map(|(ch, part, b2, a2, n)| {
            let (before, after) = ((b2 / n as f64).sqrt(), (a2 / n as f64).sqrt());
            let nf = floors[ch.index()];
            Shrinkage {
                channel: ch.name().into(),
                part,
                samples: n,
                before,
                after,
                noise_floor: nf,
                reduction_percent: reduction(before, after, nf),
            }
        })
        .collect()
}

/// The gap in words: per channel, where it is largest and where the model is
/// right.
fn gap_summary(
    runs: &[RunGap],
    parts: &[Shrinkage],
    significant: bool,
    j0: f64,
    jn: f64,
) -> Vec<String> {
    let mut out = vec![if significant {
        format!("held-out error {j0:.3} against a noise level of {jn:.3}: the base model has a significant gap")
    } else {
        format!("held-out error {j0:.3} against a noise level of {jn:.3}: no significant gap")
    }];
    for ch in Channel::ALL {
        let rows: Vec<&Shrinkage> = parts.iter().filter(|p| p.channel == ch.name()).collect();
        let Some(all) = rows.iter().find(|p| p.part == "all") else {
            continue;
        };
        let nf = all.noise_floor;
        let wrong: Vec<String> = rows
            .iter()
            .filter(|p| p.part != "all" && p.samples >= 10 && p.before > 3.0 * nf)
            .map(|p| format!("{} ({:.3} {})", p.part, p.before, ch.unit()))
            .collect();
        let right: Vec<String> = rows
            .iter()
            .filter(|p| p.part != "all" && p.samples >= 10 && p.before <= 3.0 * nf)
            .map(|p| p.part.clone())
            .collect();
        let significant_runs = runs
            .iter()
            .filter(|r| {
                r.channels
                    .iter()
                    .any(|c| c.channel == ch.name() && c.significant)
            })
            .count();
        out.push(format!(
            "{}: RMS {:.4} {} (noise floor {:.4}); significant in {} of {} runs; wrong in: {}; right in: {}",
            ch.name(),
            all.before,
            ch.unit(),
            nf,
            significant_runs,
            runs.len(),
            if wrong.is_empty() { "nowhere".into() } else { wrong.join(", ") },
            if right.is_empty() { "nowhere".into() } else { right.join(", ") },
        ));
    }
    for r in runs {
        for b in &r.bands {
            if b.gain_error_db.abs() > 1.0 || b.phase_error_deg.abs() > 10.0 {
                out.push(format!(
                    "{}: yaw-rate response {:.2}–{:.2} Hz off by {:+.1} dB, {:+.0}°",
                    r.run, b.f_low, b.f_high, b.gain_error_db, b.phase_error_deg
                ));
            }
        }
    }
    out
}
