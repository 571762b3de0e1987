//! What driven runs would show and did show: the runs of a designed
//! manoeuvre the diagnosis's confounding rule needs before it tells two
//! candidates apart ([`repetitions`]), and the separation a run driven
//! after the design measures with the candidates as diagnosed before it
//! ([`measured`]). Units: separations in noise floors; J dimensionless.

use super::candidates::sets;
use super::{models, separation, DesignRequest, Fitted, Logging};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::Augmented;
use crate::diagnose::Prepared;
use crate::error::Error;
use crate::measured::MeasuredRun;
use serde::Serialize;

/// The most repetitions of a manoeuvre a design counts.
pub const MAX_REPETITIONS: usize = 200;

/// The held-out errors a diagnosis reported for two candidates.
pub(crate) struct Held {
    pub(crate) reference: f64,
    pub(crate) other: f64,
    pub(crate) noise: f64,
    /// Residuals of the campaign's runs.
    pub(crate) residuals: usize,
}

/// The runs of a manoeuvre (`run`, logged) to add before the confounding
/// rule no longer holds the other for a look-alike of the reference: each
/// run is expected to add the noise's sum of squares to both candidates'
/// held-out J² (in the fits' scales) and `D²` (in those scales) to the
/// other's; the gaps above noise then follow, and
/// [`crate::diagnose::rules::lookalike`] decides.
pub(crate) fn repetitions(
    held: &Held,
    run: &Prepared,
    models: [&Augmented; 2],
    fitted: &Fitted,
    logging: &Logging,
) -> Option<usize> {
    use crate::diagnose::rules::lookalike;
    let [a, b] = models.map(|m| run.observe(m));
    let scales = fitted.scales;
    let d2 = separation::separation(&a, &b, &scales, logging).powi(2);
    // The noise's sum of squares per run, in the fits' scales.
    let mut noise = 0.0;
    let mut n = 0usize;
    for ch in crate::diagnose::Channel::ALL {
        let i = ch.index();
        if logging.channels[i] && fitted.noise_floors[i] > 0.0 {
            noise += run.times.len() as f64 * (fitted.noise_floors[i] / scales[i]).powi(2);
            n += run.times.len();
        }
    }
    let big_n = held.residuals as f64;
    let gap = |j2: f64, jn2: f64| (j2 - jn2).max(0.0).sqrt();
    // From 0: a pair the rule already tells apart (a set asked for, not
    // confounded) needs no run.
    (0..=MAX_REPETITIONS).find(|&k| {
        let total = big_n + (k * n) as f64;
        let grow = |j: f64, extra: f64| (j * j * big_n + k as f64 * (noise + extra)) / total;
        let jn2 = grow(held.noise, 0.0);
        let (ja2, jb2) = (grow(held.reference, 0.0), grow(held.other, d2));
        !lookalike(100.0, gap(jb2, jn2), gap(ja2, jn2), jn2.sqrt())
    })
}

/// The measured separation of a run driven after the design.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measured {
    /// The run.
    pub run: String,
    /// Each member's sum of squared residuals on it, in noise floors.
    pub chi_square: Vec<(String, f64)>,
    /// `√|χ²_other − χ²_reference|` against the weakest look-alike, signed:
    /// positive where the run favours the reference.
    pub separation: f64,
    /// The member the run favours (the smallest χ²).
    pub favours: String,
    /// The designed manoeuvre the run is named after and its prediction
    /// (None: no manoeuvre of the design has the run's file name).
    pub predicted: Option<Predicted>,
}

/// What a design predicted for the manoeuvre a driven run is named after.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Predicted {
    /// The manoeuvre (the run's file stem).
    pub manoeuvre: String,
    /// The separation a driven run was expected to measure, noise floors.
    pub expected: f64,
    /// Its uncertainty (1 σ).
    pub uncertainty: f64,
    /// (measured − expected) / uncertainty.
    pub deviation: f64,
    /// The largest |steer| difference between the run and the design over
    /// the run's times, rad: how closely it was driven as designed.
    pub steer_difference: f64,
    /// The share of the manoeuvre's length the run covers (1: all of it;
    /// less, a run cut short, whose separation is part of the predicted).
    pub coverage: f64,
    /// The channels the prediction counts that the run does not log: its
    /// separation lacks their part.
    pub missing_channels: Vec<crate::diagnose::Channel>,
}

/// The prediction of `set`'s ranked manoeuvre named as run `run` is, set on
/// its measurement `m`, with how much of the manoeuvre and of the
/// predicted channels (`logging`) the run holds.
pub fn compare(m: &mut Measured, set: &super::SetDesign, run: &MeasuredRun, logging: &Logging) {
    let stem = run
        .path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned());
    let Some(s) = set
        .ranked
        .iter()
        .chain(&set.named)
        .find(|s| Some(&s.name) == stem.as_ref())
    else {
        return;
    };
    let (Some(expected), Some(uncertainty)) = (s.expected, s.uncertainty) else {
        return;
    };
    let t0 = s.manoeuvre.start_time();
    let steer_difference = run
        .t
        .iter()
        .zip(&run.steer)
        .map(|(&t, &d)| (d - s.manoeuvre.steer(t0 + t - run.t[0])).abs())
        .fold(0.0, f64::max);
    let length = s.manoeuvre.end_time() - t0;
    let span = run.t.last().zip(run.t.first()).map_or(0.0, |(b, a)| b - a);
    let missing_channels = crate::diagnose::Channel::ALL
        .into_iter()
        .filter(|&c| logging.channels[c.index()] && c.of(run).is_none())
        .collect();
    m.predicted = Some(Predicted {
        manoeuvre: s.name.clone(),
        expected,
        uncertainty,
        deviation: (m.separation - expected) / uncertainty,
        steer_difference,
        coverage: if length > 0.0 {
            (span / length).min(1.0)
        } else {
            1.0
        },
        missing_channels,
    });
}

/// The measured separation of `run` for the set `members` (reference
/// first), the candidates as `fitted` before it.
pub fn measured(
    c: &Campaign,
    fitted: &Fitted,
    members: &[Vec<EffectKind>],
    run: &MeasuredRun,
) -> Result<Measured, Error> {
    let req = DesignRequest {
        sets: Some(vec![members.to_vec()]),
        ..DesignRequest::default()
    };
    let (members, _) = sets(fitted, &req)?.remove(0);
    let base = fitted.base(c);
    let models = models(&members, &base)?;
    // Started from the opening stretch's mean, not its first sample, as
    // the prediction's start terms assume.
    let prepared = separation::prepared(run, c.settings.step, c.settings.sample_rate);
    let chi: Vec<f64> = models
        .iter()
        .map(|m| separation::chi_square(&prepared, m, &fitted.noise_floors))
        .collect();
    let weakest = (1..chi.len())
        .min_by(|&a, &b| (chi[a] - chi[0]).abs().total_cmp(&(chi[b] - chi[0]).abs()))
        .unwrap_or(1);
    let diff = chi[weakest] - chi[0];
    let best = (0..chi.len())
        .min_by(|&a, &b| chi[a].total_cmp(&chi[b]))
        .unwrap_or(0);
    Ok(Measured {
        run: run.path.display().to_string(),
        chi_square: members
            .iter()
            .map(|m| m.label())
            .zip(chi.iter().copied())
            .collect(),
        separation: super::signed_root(diff),
        favours: members[best].label(),
        predicted: None,
    })
}
