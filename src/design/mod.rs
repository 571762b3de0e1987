//! The next test to drive: for candidate effects that explain a gap about
//! equally well (a diagnosis's confounded set, or any candidates asked
//! for), the manoeuvres within the car's and driver's limits that tell
//! them apart best, ranked by how far apart the candidates' responses are
//! in the measured channels, in units of the campaign's noise, with the
//! uncertainty of that separation.
//!
//! The candidates are those the diagnosis fitted, read back from it
//! ([`candidates`]): the base model with each candidate's values set by
//! the diagnosis's own layout, so a design replays what the diagnosis
//! replayed. The manoeuvres are a family ([`family`]) bounded by
//! [`Limits`] drawn from the campaign's runs (their speed range, a share of
//! the lateral acceleration they reached, their steer rate) and a stated
//! longitudinal acceleration; each is logged as the campaign logs and
//! replayed with every candidate ([`separation`]). For a set of more than
//! two, a manoeuvre's separation is its weakest pair's: the first member
//! (the verdict's effect) against each look-alike. The measured
//! separation of a run driven afterwards ([`measured`]) is `√(χ²_B − χ²_A)`
//! with the candidates as fitted before it: `D ± 1` on a car that behaves
//! as A, which is what makes the prediction checkable.
//!
//! Units: separations are dimensionless (noise floors); SI, rad
//! elsewhere; ISO 8855 axes.

pub mod advice;
pub mod calibration;
pub mod candidates;
pub mod evidence;
pub mod family;
pub mod labels;
pub mod lacking;
mod request;
pub mod separation;

pub use advice::{
    Advised, AdvisedBest, DiagnosisReads, Missing, Recommendation, Weak, Worth, FIRM_SIGMAS,
};
pub(crate) use calibration::{calibration, root_uncertainty, signed_root};
pub use calibration::{Calibration, ReferenceGap, CALIBRATING_D};
pub use candidates::{Fitted, FittedCandidate, FittedValue, ScreenedOut};
pub use evidence::{
    compare, measured, FittedOn, Measured, Predicted, SameRun, MAX_REPETITIONS, MISFIT_FLOORS,
};
pub use family::{Designed, Kind, Limits};
pub use request::DesignRequest;
pub use separation::Logging;

use crate::diagnose::campaign::Campaign;
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::Prepared;
use crate::error::{DesignError, Error};
use crate::manoeuvre::Manoeuvre;
use crate::measured::MeasuredRun;
use rayon::prelude::*;
use serde::Serialize;

/// The separation of the reference from one other member.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairSeparation {
    /// The other member.
    pub other: String,
    /// D, noise units.
    pub separation: f64,
}

/// A manoeuvre and how well it separates a set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scored {
    /// Its name (the scenario file's stem).
    pub name: String,
    /// Its kind.
    pub kind: Kind,
    /// What the driver does.
    pub description: String,
    /// Its length, s.
    pub duration: f64,
    /// The weakest pair's separation D, noise units.
    pub separation: f64,
    /// Each pair's.
    pub pairs: Vec<PairSeparation>,
    /// The uncertainty of `expected` (1 σ): the noise's, the first
    /// sample's and the parameters' parts (`separation`'s module doc) (the best `top` only).
    pub uncertainty: Option<f64>,
    /// The parameters' part alone.
    pub parameter_uncertainty: Option<f64>,
    /// The uncertainty on a car that behaves as the reference with noise
    /// of the stated floors: `uncertainty` before the campaign's scatter
    /// widens it ([`Calibration`]).
    pub noise_uncertainty: Option<f64>,
    /// The separation a driven run is expected to measure
    /// ([`measured`]): the signed root of `D² + shift`, the shift from
    /// the noise of its settled start, which the replays start from
    /// ([`separation::settled_start`]; the best `top` only).
    pub expected: Option<f64>,
    /// How many runs of it, added to the campaign, the diagnosis's
    /// confounding rule ([`crate::diagnose::rules::lookalike`])
    /// expects to need before it no longer calls the weakest look-alike
    /// confounded (0: the rule already tells them apart; None: more than
    /// [`MAX_REPETITIONS`]; the best `top` only).
    pub repetitions: Option<usize>,
    /// Whether a driven run is worth it ([`advice::worth`]; the best
    /// `top` only).
    pub worth: Option<Worth>,
    /// The largest |ay| of the reference's response, m/s².
    pub peak_ay: f64,
    /// The schedule.
    #[serde(skip)]
    pub manoeuvre: Manoeuvre,
}

/// Why a manoeuvre of the family was left out.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Excluded {
    /// The reference's response goes beyond the lateral limit.
    BeyondLateralLimit {
        /// The manoeuvre.
        name: String,
        /// Its peak |ay|, m/s².
        peak_ay: f64,
        /// The limit, m/s².
        limit: f64,
    },
    /// A candidate's replay diverged.
    Diverged {
        /// The manoeuvre.
        name: String,
    },
}

/// Where a set comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SetSource {
    /// The diagnosis found it confounded.
    Confounded,
    /// The user asked for it.
    Requested,
}

/// The predicted responses of a set's members to one manoeuvre.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// The manoeuvre's name.
    pub name: String,
    /// Residual times, s.
    pub times: Vec<f64>,
    /// Steer and speed at those times.
    pub steer: Vec<f64>,
    /// Speed, m/s.
    pub speed: Vec<f64>,
    /// Each member's label and response.
    pub members: Vec<(String, Observed)>,
}

/// The design for one set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SetDesign {
    /// The members' labels, the reference first.
    pub members: Vec<String>,
    /// Where the set comes from.
    pub source: SetSource,
    /// What the diagnosis reads of the set with the campaign's runs.
    pub reads: DiagnosisReads,
    /// How far apart the reference's and its weakest look-alike's fitted
    /// models replay the campaign's runs, D over all their samples (it
    /// sums over samples where the diagnosis's held-out errors average
    /// over them: a pair the diagnosis confounds can differ by D ≫ 1).
    pub campaign_separation: f64,
    /// The samples of the campaign's runs D sums over.
    pub campaign_samples: usize,
    /// How the campaign's runs measure the separations their replays
    /// predict: the scatter the expected separations' uncertainties are
    /// widened by.
    pub calibration: Calibration,
    /// The manoeuvres within the limits, best first.
    pub ranked: Vec<Scored>,
    /// Whether any of them is worth driving ([`advice::recommendation`]).
    pub recommendation: Recommendation,
    /// What the diagnosis advises to separate each member's effects, and
    /// where the family's manoeuvres of that test rank.
    pub advised: Vec<Advised>,
    /// Manoeuvres asked for by name ([`DesignRequest::also`]) beyond the
    /// best, completed alike (no scenario file is written for them).
    pub named: Vec<Scored>,
    /// What was left out, and why.
    pub excluded: Vec<Excluded>,
    /// The best manoeuvre's predicted responses (for the figure).
    #[serde(skip)]
    pub best: Option<Prediction>,
}

/// The design.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Design {
    /// The limits the manoeuvres keep to.
    pub limits: Limits,
    /// How the campaign logs (the designed runs are logged alike).
    #[serde(skip)]
    pub logging: Logging,
    /// Manoeuvres in the family.
    pub family: usize,
    /// The manoeuvres of the family the limits leave out, by kind and
    /// speed (a speed change too short at the stated |ax|, …).
    pub left_out_by_limits: Vec<String>,
    /// The noise floor of each channel the separations are counted in.
    #[serde(skip)]
    pub noise_floors: [f64; 3],
    /// One per set.
    pub sets: Vec<SetDesign>,
}

/// The models of `members` on `base`.
fn models(members: &[FittedCandidate], base: &Augmented) -> Result<Vec<Augmented>, Error> {
    members
        .iter()
        .map(|m| {
            m.model(base).ok_or_else(|| {
                DesignError::Layout {
                    candidate: m.label(),
                }
                .into()
            })
        })
        .collect()
}

/// Designs manoeuvres for campaign `c` as diagnosed (`fitted`).
pub fn design(c: &Campaign, fitted: &Fitted, req: &DesignRequest) -> Result<Design, Error> {
    req.validate()?;
    let limits = Limits::of(&c.runs, c.settings.min_speed, req.ay_share, req.ax);
    let logging = Logging::of(c);
    let base = fitted.base(c);
    let (mut family, left_out_by_limits) = family::family_and_left_out(&base, &limits);
    distinct_names(&mut family, c);
    // Each run replayed from its settled start, as a driven run is: from
    // its first sample, that sample's noise starts the candidates apart
    // and the transients that follow read as separation (a linear car
    // logged 60 ms late: D = 3.8 from the first samples, 0.6 settled).
    let runs = separation::campaign_prepared(c);
    let sets = candidates::sets(fitted, req)?
        .into_iter()
        .map(|(members, source)| {
            let cx = SetContext {
                c,
                fitted,
                base: &base,
                members: &members,
                models: models(&members, &base)?,
                labels: members.iter().map(|m| m.label()).collect(),
                limits: &limits,
                logging: &logging,
                runs: &runs,
            };
            design_set(&cx, source, &family, req)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Design {
        limits,
        logging,
        noise_floors: fitted.noise_floors,
        family: family.len(),
        left_out_by_limits,
        sets,
    })
}

/// Renames the manoeuvres of `family` that share a name with one of the
/// campaign's runs (`sweep_080kph` of a programme): a designed run driven
/// and logged under its scenario's name must not be taken for that run,
/// nor refused beside it.
fn distinct_names(family: &mut [Designed], c: &Campaign) {
    let taken: std::collections::HashSet<String> = c
        .runs
        .iter()
        .filter_map(|r| r.path.file_stem())
        .map(|s| s.to_string_lossy().into_owned())
        .collect();
    for d in family.iter_mut().filter(|d| taken.contains(&d.name)) {
        d.name.push_str("_designed");
    }
}

/// The separation of the reference (first) from each other member, given
/// their responses.
fn pairs(
    obs: &[Observed],
    labels: &[String],
    floors: &[f64; 3],
    logging: &Logging,
) -> Vec<PairSeparation> {
    (1..obs.len())
        .map(|k| PairSeparation {
            other: labels[k].clone(),
            separation: separation::separation(&obs[0], &obs[k], floors, logging),
        })
        .collect()
}

/// What scoring a manoeuvre for one set needs.
struct SetContext<'a> {
    c: &'a Campaign,
    fitted: &'a Fitted,
    base: &'a Augmented,
    members: &'a [FittedCandidate],
    models: Vec<Augmented>,
    labels: Vec<String>,
    limits: &'a Limits,
    logging: &'a Logging,
    /// The campaign's runs, prepared once for every set.
    runs: &'a [Prepared],
}

impl SetContext<'_> {
    /// Manoeuvre `m` logged as the campaign logs, ready for replays.
    fn prepared(&self, logged: &MeasuredRun) -> Prepared {
        let set = &self.c.settings;
        Prepared::new(logged, set.step, set.sample_rate)
    }

    /// Every member's response to `d`, its pairs' separations, or why it
    /// is left out.
    fn score(&self, d: &Designed) -> Result<(Scored, Prediction), Excluded> {
        let run = self.prepared(&self.logging.run(&d.name, &d.manoeuvre));
        let obs: Vec<Observed> = self.models.iter().map(|m| run.observe(m)).collect();
        let speed: Vec<f64> = run.times.iter().map(|&t| d.manoeuvre.speed(t)).collect();
        let lateral = |o: &Observed| labels::lateral(o, &speed, self.logging);
        let peak = labels::peak(&lateral(&obs[0]));
        // Said as the best model predicts it: the reference as fitted, the
        // base only where the diagnosis found no gap.
        let predicted = labels::Predicted {
            best: (!self.fitted.no_gap)
                .then(|| (self.labels[0].as_str(), lateral(&obs[0]), &obs[0])),
            base_ay: lateral(&run.observe(self.base)),
            speed: &speed,
        };
        let description = d.description.clone() + &labels::predicted_words(d.kind, &predicted);
        let limit = self.limits.ay_max();
        if peak > 1.1 * limit {
            let name = d.name.clone();
            return Err(Excluded::BeyondLateralLimit {
                name,
                peak_ay: peak,
                limit,
            });
        }
        let pairs = pairs(&obs, &self.labels, &self.fitted.noise_floors, self.logging);
        let weakest = pairs
            .iter()
            .map(|p| p.separation)
            .fold(f64::INFINITY, f64::min);
        if !weakest.is_finite() {
            return Err(Excluded::Diverged {
                name: d.name.clone(),
            });
        }
        let prediction = Prediction {
            name: d.name.clone(),
            steer: run.times.iter().map(|&t| d.manoeuvre.steer(t)).collect(),
            speed,
            times: run.times.clone(),
            members: self.labels.iter().cloned().zip(obs).collect(),
        };
        let scored = Scored {
            name: d.name.clone(),
            kind: d.kind,
            description,
            duration: d.manoeuvre.end_time() - d.manoeuvre.start_time(),
            separation: weakest,
            pairs,
            uncertainty: None,
            parameter_uncertainty: None,
            noise_uncertainty: None,
            expected: None,
            repetitions: None,
            worth: None,
            peak_ay: peak,
            manoeuvre: d.manoeuvre.clone(),
        };
        Ok((scored, prediction))
    }

    /// The expected measured separation of `s` against its weakest pair,
    /// its uncertainty (the noise's part widened by `calibration`'s
    /// scatter and the reference's model-form bound,
    /// [`ReferenceGap::along`]), the runs the confounding rule needs and whether
    /// it is worth driving against a campaign that separates by `campaign`.
    fn complete(&self, s: &mut Scored, calibration: &Calibration, campaign: f64) {
        let weakest = s
            .pairs
            .iter()
            .position(|p| p.separation == s.separation)
            .map_or(1, |k| k + 1);
        let logged = self.logging.run(&s.name, &s.manoeuvre);
        let run = self.prepared(&logged);
        let (floors, logging) = (&self.fitted.noise_floors, self.logging);
        let pair = [&self.models[0], &self.models[weakest]];
        let observe = |m: &Augmented| run.observe(m);
        let members = [
            (&self.members[0], pair[0]),
            (&self.members[weakest], pair[1]),
        ];
        let spread = separation::parameter_spread(members, self.base, &observe, floors, logging);
        let set = &self.c.settings;
        // The start is settled over the lead-in as a driven run's is
        // ([`separation::settled_start`]): its noise is one sample's over √n.
        let n = separation::settled_start(&logged).map_or(1, |(_, n)| n) as f64;
        let start_sd = self.fitted.start_noise.map(|s| s / n.sqrt());
        let terms = separation::start_terms(
            &logged,
            pair,
            (floors, &start_sd),
            (set.step, set.sample_rate),
        );
        // χ²_B − χ²_A = D² + start + 2·D·(noise + parameters), its mean
        // D² plus the start's shift; the measured separation is its root.
        // The noise's and the start's parts widened by the scatter the
        // campaign's runs show beyond the floors; the parameters' as it is.
        let mean = terms.d2 + terms.shift;
        let sd = |g2: f64| (4.0 * terms.d2 * (g2 + spread * spread) + g2 * terms.variance).sqrt();
        s.parameter_uncertainty = Some(spread);
        s.expected = Some(signed_root(mean));
        s.noise_uncertainty = Some(root_uncertainty(mean, sd(1.0)));
        // The campaign's scatter, and the most the reference's model-form
        // error can add along this run's difference, which the campaign's
        // runs cannot measure where they barely separate the pair.
        let g2 = calibration.widening().powi(2) + calibration.reference.along(run.count());
        s.uncertainty = Some(root_uncertainty(mean, sd(g2)));
        s.worth = s
            .expected
            .zip(s.uncertainty)
            .map(|(e, u)| advice::worth(e, u, campaign));
        let held = evidence::Held {
            reference: self.members[0].heldout_error,
            other: self.members[weakest].heldout_error,
            noise: self.fitted.noise_level,
            residuals: self.runs.iter().map(Prepared::count).sum(),
        };
        s.repetitions = evidence::repetitions(&held, &run, pair, self.fitted, logging);
        if s.repetitions == Some(0) {
            s.worth = Some(Worth::AlreadyToldApart);
        }
    }
}

/// The design for the set of `cx`: the family scored, the best `top`
/// completed.
fn design_set(
    cx: &SetContext,
    source: SetSource,
    family: &[Designed],
    req: &DesignRequest,
) -> Result<SetDesign, Error> {
    let (mut ranked, mut excluded) = (Vec::new(), Vec::new());
    for s in family.par_iter().map(|d| cx.score(d)).collect::<Vec<_>>() {
        match s {
            Ok(x) => ranked.push(x),
            Err(e) => excluded.push(e),
        }
    }
    ranked.sort_by(|a, b| b.0.separation.total_cmp(&a.0.separation));
    let mut named: Vec<Scored> = ranked
        .iter()
        .skip(req.top.max(1))
        .filter(|(s, _)| req.also.contains(&s.name))
        .map(|(s, _)| s.clone())
        .collect();
    let effects: Vec<_> = cx.members.iter().flat_map(|m| m.effects.clone()).collect();
    let advised = advice::advice_of(&effects, &ranked.iter().map(|(s, _)| s).collect::<Vec<_>>());
    ranked.truncate(req.top.max(1));
    let (campaign_separation, calibration) = campaign_separation(cx);
    for s in ranked.iter_mut().map(|(s, _)| s).chain(&mut named) {
        cx.complete(s, &calibration, campaign_separation);
    }
    let best = ranked.first().map(|(_, p)| p.clone());
    let ranked: Vec<Scored> = ranked.into_iter().map(|(s, _)| s).collect();
    let reads = match source {
        _ if cx.fitted.no_gap => DiagnosisReads::NoGap,
        SetSource::Confounded => DiagnosisReads::Confounded,
        SetSource::Requested => DiagnosisReads::Other,
    };
    Ok(SetDesign {
        members: cx.labels.clone(),
        source,
        reads,
        campaign_separation,
        campaign_samples: cx.runs.iter().map(Prepared::count).sum(),
        calibration,
        recommendation: advice::recommendation(&ranked, campaign_separation),
        advised,
        ranked,
        named,
        excluded,
        best,
    })
}

/// D of the reference against its weakest look-alike over all the
/// campaign's runs (each replayed from its settled start), and how those
/// runs measure it ([`Calibration`]).
fn campaign_separation(cx: &SetContext) -> (f64, Calibration) {
    let floors = &cx.fitted.noise_floors;
    // Each run's reference replay once, against every look-alike's: per
    // look-alike, (D², χ²_B − χ²_A) on the run.
    let per_run: Vec<Vec<(f64, f64)>> = cx
        .runs
        .par_iter()
        .map(|r| {
            let chi = |obs: &Observed| separation::chi_square_of(r, obs, floors);
            let reference = r.observe(&cx.models[0]);
            let chi_a = chi(&reference);
            cx.models[1..]
                .iter()
                .map(|m| {
                    let other = r.observe(m);
                    let d = separation::separation(&reference, &other, floors, cx.logging);
                    (d * d, chi(&other) - chi_a)
                })
                .collect()
        })
        .collect();
    let gap = calibration::ReferenceGap {
        heldout_error: cx.members[0].heldout_error,
        noise_level: cx.fitted.noise_level,
    };
    let total = |k: usize| per_run.iter().map(|d| d[k].0).sum::<f64>().sqrt();
    let Some(weakest) = (0..cx.models.len() - 1).min_by(|&a, &b| total(a).total_cmp(&total(b)))
    else {
        return (f64::NAN, calibration(std::iter::empty(), gap));
    };
    (
        total(weakest),
        calibration(per_run.iter().map(|d| d[weakest]), gap),
    )
}

#[cfg(test)]
mod tests;
