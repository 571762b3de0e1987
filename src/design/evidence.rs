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
    /// The residuals the χ² are summed over (samples × channels logged).
    pub residuals: usize,
    /// The campaign's own run file this run is (None: a new run): the
    /// candidates were fitted to it, so it is no new evidence.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fitted_on: Option<FittedOn>,
}

/// A driven run that is one of the campaign's own (round 41: one of them
/// given to `--measured` "separated" the candidates without a word that
/// they had been fitted to it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FittedOn {
    /// The campaign's run file.
    pub run: String,
    /// How it was found.
    pub by: SameRun,
}

/// How a driven run was found to be one of the campaign's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SameRun {
    /// The same file (its canonical path).
    Path,
    /// Another file, byte for byte the same (a copy).
    Content,
}

/// The RMS miss, in noise floors, beyond which the better candidate does
/// not fit a driven run: the 3 noise floors a channel alone needs to be a
/// significant gap in `diagnose`.
pub const MISFIT_FLOORS: f64 = 3.0;

impl Measured {
    /// Where both candidates miss the run by far more than they differ:
    /// the better one's χ² above the noise's (one per residual), as noise
    /// floors (its root), where its RMS miss is beyond [`MISFIT_FLOORS`]
    /// and that root beyond [`MISFIT_FLOORS`] times the separation. Then
    /// the separation measures how differently the two miss a run neither
    /// replays (a steer logged ×1.5 separated them by 115 noise floors),
    /// not which one the car is; None where the better one fits.
    pub fn misfit(&self) -> Option<f64> {
        let n = self.residuals as f64;
        let excess = (self.best_chi_square() - n).max(0.0).sqrt();
        let rms = self.best_rms();
        (rms > MISFIT_FLOORS && excess > MISFIT_FLOORS * self.separation.abs()).then_some(excess)
    }

    /// The better candidate's χ² on the run.
    fn best_chi_square(&self) -> f64 {
        self.chi_square
            .iter()
            .map(|c| c.1)
            .fold(f64::INFINITY, f64::min)
    }

    /// The better candidate's RMS miss of the run, in noise floors.
    pub fn best_rms(&self) -> f64 {
        (self.best_chi_square() / self.residuals.max(1) as f64).sqrt()
    }
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
        residuals: prepared.count(),
        fitted_on: None,
    })
}

#[cfg(test)]
mod misfit_tests {
    use super::*;

    fn m(chi: [f64; 2], separation: f64) -> Measured {
        Measured {
            run: "r.csv".into(),
            chi_square: vec![("a".into(), chi[0]), ("b".into(), chi[1])],
            separation,
            favours: "a".into(),
            predicted: None,
            residuals: 1000,
            fitted_on: None,
        }
    }

    /// χ² 1e6 over 1000 residuals (31.6 floors RMS), 100 apart: misfit,
    /// √(1e6 − 1000) = 999.5 floors; the same 100 apart on a run fitted to
    /// 1.1 floors RMS, or a miss under three times the separation: not.
    #[test]
    fn a_separation_is_misfit_only_where_both_miss_far_beyond_it() {
        let e = m([1e6, 1e6 + 1e4], 100.0).misfit().unwrap();
        assert!((e - 999.5).abs() < 0.1, "{e}");
        assert!(m([1210.0, 11210.0], 100.0).misfit().is_none());
        assert!(m([1e6, 1e6 + 1e4], 400.0).misfit().is_none());
    }
}
