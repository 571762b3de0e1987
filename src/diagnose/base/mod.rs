//! How the base model is found ([`Bases`]): the campaign's tyres, a tyre
//! model fitted to its rig data, or — with neither — axle characteristics
//! identified from the runs (`identify`) and refitted on every fold and
//! with every candidate, since an effect changes what the tyres must have
//! been, against the campaign's prior of the axles (`prior`: by tyre
//! class, the peak friction held where the runs never approach it). The
//! campaign's `[roll]` is the base models' roll
//! ([`crate::vehicle::Effects::roll`]). Units: SI, rad.

pub(crate) mod beta_sign;
pub(crate) mod identify;
pub(crate) mod no_tyre;
pub mod prior;

use crate::diagnose::base::identify::{
    best_tempered, data_costs, identify_axles, AxleIdentification,
};
use crate::diagnose::base::prior::{FrictionRule, PriorReport, PriorRows};
use crate::diagnose::campaign::prior::AxlePrior;
use crate::diagnose::campaign::{BaseTyres, Campaign};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::fit::problem::Problem;
use crate::diagnose::fit::refit::{refit, training_rows};
use crate::diagnose::fit::{fit, Polish};
use crate::diagnose::model::axles::{axle_tyres, AXLE_BOUNDS};
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::Augmented;
use crate::diagnose::timing::{record_polish, Phase, Recorder, Stamps};
use crate::error::{DiagnosisError, Error};
use crate::identify::grouping::{group, Grouping, GroupingReport, SlipAxis};
use crate::identify::{fit_lateral, start_tyre_of, FitSettings};
use crate::optim::local::{Derivatives, Residuals};
use crate::optim::stats::covariance;
use crate::tyre::Tyre;
use crate::vehicle::VehicleModel;
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

/// Where the base model's tyres come from, as the report states it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum TyreSource {
    /// The campaign's tyre files.
    Given,
    /// A model fitted to the campaign's rig data.
    Rig {
        /// The model fitted.
        model: crate::tyre::ModelName,
        /// The rig data file.
        path: std::path::PathBuf,
        /// The fit's residual σ, % of the force.
        sigma_percent: f64,
    },
    /// No tyre data: axle characteristics identified from the runs (the
    /// base report's `axles`).
    FromRuns,
}

/// The base model of all runs and of every fold.
pub(super) struct Bases {
    pub(super) all: Augmented,
    pub(super) folds: Vec<Augmented>,
    pub(super) nominal_share: f64,
    /// Axle characteristics identified from the runs (all runs, per fold):
    /// refitted jointly with every candidate, since an effect changes what
    /// the tyres must have been.
    pub(super) axle: Option<(Vec<f64>, Vec<Vec<f64>>)>,
    /// How the runs pin them, and whether they are a tyre at all.
    pub(super) identification: Option<AxleIdentification>,
    /// The prior's rows every fit of the axle characteristics appends
    /// (they lead the vector).
    pub(super) prior: Option<PriorRows>,
}

/// The base models: all runs and each fold's training runs.
pub(super) fn base_models(
    c: &Campaign,
    runs: &[Prepared],
    folds: &[Vec<usize>],
    scales_hint: [f64; 3],
    timing: Option<&Recorder>,
) -> Result<(Bases, TyreSource, Option<GroupingReport>), Error> {
    let vehicle = c.vehicle.clone();
    let nominal_share = vehicle.front_transfer_share();
    let make = |f: Tyre, r: Tyre| {
        let mut m = Augmented::new(VehicleModel::new(vehicle.clone(), f, r), c.friction);
        m.effects_mut().roll = c.roll;
        // Outputs taken where the campaign states they are measured.
        let sensors = &mut m.effects_mut().sensors;
        sensors.accelerometer_x = c.sensors.accelerometer_x.unwrap_or(0.0);
        sensors.beta_at = c.sensors.beta_x;
        m
    };
    // Tyres not fitted to the runs: one model for all runs and every fold.
    let fixed = |m: Augmented| Bases {
        folds: vec![m.clone(); folds.len()],
        all: m,
        nominal_share,
        axle: None,
        identification: None,
        prior: None,
    };
    match &c.tyres {
        BaseTyres::Given(f, r, _) => Ok((
            fixed(make((**f).clone(), (**r).clone())),
            TyreSource::Given,
            None,
        )),
        BaseTyres::Rig { path, data, model } => {
            let grouped = group(path, data, &Grouping::default(), SlipAxis::Angle)?;
            let conditions = grouped.conditions;
            if conditions.is_empty() {
                return Err(DiagnosisError::NoRigCondition { rig: path.clone() }.into());
            }
            let mut loads: Vec<f64> = conditions.iter().map(|q| q.fz).collect();
            loads.sort_by(f64::total_cmp);
            let t0 = start_tyre_of(*model, loads[loads.len() / 2])?;
            let mut settings = FitSettings::new(c.settings.seed);
            settings.pso.particles = 40;
            settings.pso.iterations = 150;
            let started = Instant::now();
            let f =
                fit_lateral(&t0, &conditions, &settings).map_err(|e| DiagnosisError::RigFit {
                    rig: path.clone(),
                    source: Box::new(e),
                })?;
            if let Some(rec) = timing {
                rec.add(Phase::BaseIdentification, started.elapsed(), 0);
            }
            Ok((
                fixed(make(f.tyre.clone(), f.tyre.clone())),
                TyreSource::Rig {
                    model: *model,
                    path: path.clone(),
                    sigma_percent: f.sigma_percent,
                },
                Some(grouped.report),
            ))
        }
        BaseTyres::FromRuns => {
            let d = c.settings.derivatives;
            let rule = FrictionRule::of_runs(&c.prior, &c.runs);
            let bases = axles_from_runs(
                runs,
                folds,
                (scales_hint, nominal_share),
                (make, d),
                (c.prior, rule),
                timing,
            );
            Ok((bases, TyreSource::FromRuns, None))
        }
    }
}

/// What the axle shares set on the models `make` builds (their tyres),
/// and a model it builds.
fn axle_layout(make: impl Fn(Tyre, Tyre) -> Augmented) -> (Layout, Augmented) {
    let (f, r) = axle_tyres(&[0.5, 0.5, 0.5]);
    (Layout::new(&[], true), make(f, r))
}

/// The timing phases of the base fit's polish: its steps, then its
/// Jacobian and curvature (as [`record_polish`] takes them).
const BASE_POLISH_PHASES: [Phase; 3] = [
    Phase::BasePolish,
    Phase::BaseLinearisation,
    Phase::BaseLinearisation,
];

/// The runs a fold trains on: all but its `held_out` ones, in order.
/// Apart from [`axles_from_runs`] so that it reads on a screen.
fn training_runs<'a>(runs: &'a [Prepared], held_out: &[usize]) -> Vec<&'a Prepared> {
    (0..runs.len())
        .filter(|i| !held_out.contains(i))
        .map(|i| &runs[i])
        .collect()
}

/// The base model of axle characteristics identified from the runs (no
/// tyre data; [`crate::diagnose::base::identify`]): a grid of starts, the best basins
/// polished, the best of them fitted, then refitted on every fold.
fn axles_from_runs(
    runs: &[Prepared],
    folds: &[Vec<usize>],
    (scales_hint, nominal_share): ([f64; 3], f64),
    (make, derivatives): (impl Fn(Tyre, Tyre) -> Augmented + Sync, Derivatives),
    (prior, rule): (AxlePrior, FrictionRule),
    timing: Option<&Recorder>,
) -> Bases {
    let rows = crate::diagnose::base::prior::rows(&prior, &rule, 0);
    let build = |p: &[f64]| {
        let (f, r) = axle_tyres(p);
        make(f, r)
    };
    let stamps = timing.map(|_| Stamps::default());
    let (layout, model) = axle_layout(&make);
    let problem = Problem::new(
        |p: &[f64]| counted(&stamps, build, p),
        runs.iter().collect(),
        scales_hint,
        AXLE_BOUNDS.to_vec(),
    )
    .with_layout(layout.clone(), &model, derivatives)
    .with_prior(Some(rows));
    let t0 = Instant::now();
    let (polished, starts) = identify_axles(&problem);
    // The runs' evidence against the prior, from their residuals about the
    // untempered best: every later fit weighs the prior by it, and this one
    // starts from the basin best under it (`best_tempered`).
    let tempering = problem.tempering(&polished[0].1);
    let data = data_costs(&polished, &problem);
    let rows = rows.tempered(tempering.prior_weight);
    let problem = problem.with_prior(Some(rows));
    let start = best_tempered(&data, &problem).unwrap_or_else(|| polished[0].1.clone());
    let mark = (Instant::now(), stamps.as_ref().map_or(0, Stamps::count));
    let full = fit(&problem, &start, None, Polish::LevenbergMarquardt);
    if let (Some(rec), Some(st)) = (timing, &stamps) {
        rec.add(Phase::BaseIdentification, mark.0 - t0, mark.1);
        let n = full.params.len();
        let jacobian = problem.jacobian_evaluations(n);
        let linear = full.linear.is_some();
        record_polish(rec, st, mark, (n, jacobian), linear, BASE_POLISH_PHASES);
    }
    let fold_params: Vec<Vec<f64>> = (0..folds.len())
        .into_par_iter()
        .map(|k| {
            let t0 = Instant::now();
            let train = training_runs(runs, &folds[k]);
            let stamps = timing.map(|_| Stamps::default());
            let p = Problem::new(
                |p: &[f64]| counted(&stamps, build, p),
                train,
                scales_hint,
                AXLE_BOUNDS.to_vec(),
            )
            .with_layout(layout.clone(), &model, derivatives)
            .with_prior(Some(rows));
            let held_out = &folds[k];
            let q = refit(&p, &full, &training_rows(runs, held_out, PriorRows::ROWS)).params;
            if let (Some(rec), Some(st)) = (timing, &stamps) {
                rec.add(Phase::BaseFolds, t0.elapsed(), st.count());
            }
            q
        })
        .collect();
    let p = &full.params;
    let cov = full
        .linear
        .as_ref()
        .and_then(|l| covariance(&l.jacobian, 2.0 * full.cost));
    let id = AxleIdentification::new(p, &full.reported_std_errors(), cov.as_ref(), starts)
        .with_prior(PriorReport::new(prior, rule, p).with_tempering(tempering));
    Bases {
        all: build(p),
        folds: fold_params.iter().map(|q| build(q)).collect(),
        nominal_share,
        axle: Some((p.clone(), fold_params)),
        identification: Some(id),
        prior: Some(rows),
    }
}

/// The model of `p`, the evaluation stamped when the diagnosis is timed.
fn counted(stamps: &Option<Stamps>, build: impl Fn(&[f64]) -> Augmented, p: &[f64]) -> Augmented {
    if let Some(st) = stamps {
        st.tick();
    }
    build(p)
}
