//! The diagnosis of a campaign: base model, where the gap lies, which
//! effect explains it, how far it shrinks on held-out runs.
//!
//! 1. Base model: the campaign's tyres, or a tyre model fitted to its rig
//!    data, or — with neither — axle characteristics identified from the
//!    training runs (simplified Magic Formula per axle, `B_f`, `B_r` and a
//!    shared peak friction `D`; refitted in every fold) — `candidates.rs`,
//!    `base.rs`.
//! 2. Gap: every run replayed with its own steer and speed
//!    ([`crate::diagnose::report::gap`], `summary.rs`); noise floors pooled over runs
//!    (median: [`crate::diagnose::report::trust`], the rule a `simulate`
//!    replay uses too).
//! 3. Candidates: every effect of the library fitted on all runs (PSO +
//!    Levenberg–Marquardt) for its parameters and BIC, then scored by
//!    K-fold cross-validation (leave-one-run-out up to eight runs; run i in
//!    fold i mod 8 beyond), each fold refitted from the all-run optimum.
//!    The held-out error is `J = sqrt(Σ_c n_c·(rms_c/s_c)²/Σ n_c)`; the noise
//!    alone would give `J_n` (the same with the noise floors), so the gap
//!    above noise is `G = sqrt(J² − J_n²)` and an effect's reduction is
//!    `1 − G_after/G_before` — `crossval.rs` (folds, scoring, at most
//!    [`MAX_FOLDS`] folds), `fit.rs` (the fits) and `refit.rs` (the fold
//!    refits).
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
//!    The search and the ranking against the base model are in
//!    `search.rs`, its rules and thresholds in `rules.rs`, the verdict's
//!    case in `conclude.rs`; the report words it (`report/words.rs`).
//!
//! This file runs the steps in order ([`diagnose`]) and assembles the
//! report ([`crate::diagnose::report`]).
//!
//! Units: SI, rad; J is dimensionless (residuals over channel scales).
//!
//! [`ACCEPT`]: crate::diagnose::verdict::rules::ACCEPT
//! [`PROMISING`]: crate::diagnose::verdict::rules::PROMISING
//! [`CONFOUNDED`]: crate::diagnose::verdict::rules::CONFOUNDED
//! [`CONFOUNDED_NOISE`]: crate::diagnose::verdict::rules::CONFOUNDED_NOISE
//! [`SIGNIFICANT`]: crate::diagnose::verdict::rules::SIGNIFICANT

use crate::diagnose::model::scale::{ScaleSource, SCATTER_EXCESS};
pub use crate::diagnose::report::summary::observed_channel;
pub use crate::diagnose::report::{
    BaseReport, ChannelNoise, Diagnosis, GapReport, Overlay, PartAxis, Ranked, RunGap, Shrinkage,
    Verdict,
};
use crate::diagnose::report::{CalibrationSource, GapFinding, Note, Unseen};

use crate::diagnose::base::{base_models, Bases, TyreSource};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::{EffectKind, Needs};
use crate::diagnose::model::channels::{Channel, ChannelErrors};
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::report::shares::{channel_shares, error_rows};
use crate::diagnose::report::summary::steady_offsets;
use crate::diagnose::report::summary::{base_run_gap, dominant, gap_summary, parts_table};
use crate::diagnose::report::trust::{channel_trust, Trust};
use crate::diagnose::timing::{Recorder, Timing};
use crate::diagnose::verdict::baseline::{baseline, Baseline};
use crate::diagnose::verdict::score::{prepare, Calibrated, Context, Scored, MAX_FOLDS};
use crate::diagnose::verdict::screening::singles;
use crate::diagnose::verdict::search::{search, Searched};
use crate::diagnose::verdict::{calibration::offsets_matched, rules};
use crate::error::{DiagnosisError, Error};
use crate::identify::grouping::GroupingReport;
use crate::measured::calibration::PLAUSIBLE_AY_OFFSET;
use crate::measured::road::{RoadGeometry, SensorOffsets};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

mod conclusion;
mod limits;
mod rig_notes;
mod tyre_loads;
use conclusion::{conclude, with_rows};

/// Work units reported to the progress counter for a campaign.
pub fn work_units(c: &Campaign) -> usize {
    let folds = c.runs.len().min(MAX_FOLDS);
    let singles = c.effects.len() * (1 + folds);
    let combos = c.settings.max_effects.saturating_sub(1) * c.effects.len() * (1 + folds);
    1 + singles + combos
}

/// The yaw-rate and `ay` offsets of `calibrated` (0 where none was
/// measured), for the road's bank estimate. An `ay` offset beyond
/// [`PLAUSIBLE_AY_OFFSET`] is no mounting offset but, without a bank
/// column, a car parked on a bank (`g·sin θ`): it is not removed, or the
/// banking it stood on would vanish from the estimate.
fn offsets(calibrated: &Calibrated) -> SensorOffsets {
    let of = |ch: Channel| calibrated[ch.index()].map_or(0.0, |(mean, ..)| mean);
    let ay = of(Channel::Ay);
    SensorOffsets {
        ay: if ay.abs() <= PLAUSIBLE_AY_OFFSET {
            ay
        } else {
            0.0
        },
        yaw_rate: of(Channel::YawRate),
        beta: of(Channel::Beta),
    }
}

/// Each response channel's offset as the runs' standstills measured it,
/// else their straights (mean and standard error).
fn calibrated(c: &Campaign) -> Calibrated {
    use crate::measured::calibration::SpanKind;
    use crate::measured::clean::RunChannel;
    Channel::ALL.map(|ch| {
        let run_channel = match ch {
            Channel::YawRate => RunChannel::YawRate,
            Channel::Ay => RunChannel::Ay,
            Channel::Beta => RunChannel::Beta,
        };
        let k = c
            .calibration
            .channels
            .iter()
            .find(|k| k.channel == run_channel)?;
        // The calibration's own rule: a standstill offset that only a
        // logged bank not acting on the car explains is no evidence.
        let o = k.offset?;
        let on = match o.from {
            SpanKind::Standstill => CalibrationSource::Standstills,
            SpanKind::Straight => CalibrationSource::Straights,
        };
        // The logged bank the standstills' ay was read through (its mean
        // there): the verdict re-reads them through the bank it fits.
        let bank = k
            .bank
            .filter(|_| on == CalibrationSource::Standstills)
            .map(|b| (b.bank_term / crate::constants::G).clamp(-1.0, 1.0).asin());
        Some((o.mean, o.std_error, on, bank))
    })
}

/// The channels with an uncertainty stated under `[channels]` that no run
/// measures (absent from the noise table `noise`).
fn noise_unmeasured<'a>(
    c: &'a Campaign,
    noise: &'a [ChannelNoise],
) -> impl Iterator<Item = Channel> + 'a {
    let u = &c.uncertainty;
    Channel::ALL
        .into_iter()
        .zip([u.yaw_rate, u.ay, u.beta])
        .filter(|(ch, stated)| stated.is_some() && !noise.iter().any(|n| n.channel == *ch))
        .map(|(ch, _)| ch)
}

/// The note of a channel stated more precise than its own scatter shows
/// ([`SCATTER_EXCESS`]).
fn below_scatter(n: &ChannelNoise) -> Option<Note> {
    (n.source == ScaleSource::Stated && n.scatter > SCATTER_EXCESS * n.noise_floor).then_some(
        Note::UncertaintyBelowScatter {
            channel: n.channel,
            stated: n.noise_floor,
            scatter: n.scatter,
            weighted: n.scale,
        },
    )
}

/// Held-out replays of every run, before and after, largest base gap first.
fn overlays(ctx: &Context, before: &[Observed], after: &[Observed]) -> Vec<Overlay> {
    let mut out: Vec<Overlay> = ctx
        .runs
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut e = ChannelErrors::default();
            for (ch, m) in &r.measured {
                let sim = observed_channel(&before[i], *ch);
                for (y, x) in sim.iter().zip(m) {
                    e.sum_sq[ch.index()] += (y - x) * (y - x);
                    e.count[ch.index()] += 1;
                }
            }
            Overlay {
                run: r.name.clone(),
                start: r.start_time(),
                t: r.times.clone(),
                measured: r.measured.clone(),
                base: before[i].clone(),
                after: after[i].clone(),
                gap: e.combined(&ctx.scales),
            }
        })
        .collect();
    out.sort_by(|a, b| b.gap.total_cmp(&a.gap));
    out
}

/// A longitudinal acceleration that shows, m/s²: well above a logger's
/// noise on `ax` and a speed trace's differencing noise.
const VISIBLE_AX: f64 = 0.5;

/// The campaign's candidate effects that its runs can show, and a note for
/// each one left out (an effect of braking and throttle without a
/// longitudinal acceleration, a bank profile without a `bank` channel, an
/// accelerometer roll where every run logs the roll that levels its `ay`,
/// or where no run logs `ay`: [`Unseen::accelerometer_roll`]).
fn visible_effects(c: &Campaign) -> (Vec<EffectKind>, Vec<Note>) {
    // The acceleration the replays use: the measured ax, else the
    // smoothed speed derivative (a raw difference of a noisy speed would
    // admit braking effects on constant-speed runs).
    let accelerates = c.runs.iter().any(|r| {
        r.longitudinal_acceleration()
            .iter()
            .any(|a| a.abs() > VISIBLE_AX)
    });
    let banked = c.runs.iter().any(|r| r.bank.is_some());
    let with_ay = c.runs.iter().filter(|r| r.ay.is_some());
    let roll_unseen = Unseen::accelerometer_roll(
        with_ay.clone().count(),
        with_ay.filter(|r| r.roll.is_some()).count(),
    );
    // Linear base tyres have no limit for a friction scale to lower.
    let linear_base = c.tyres.linear();
    let mut notes = Vec::new();
    let effects = c
        .effects
        .iter()
        .copied()
        .filter(|e| {
            let lacks = match e.needs() {
                Needs::LongitudinalAcceleration if !accelerates => {
                    Unseen::LongitudinalAcceleration {
                        threshold: VISIBLE_AX,
                    }
                }
                Needs::BankChannel if !banked => Unseen::BankChannel,
                Needs::FrictionLimit if linear_base => Unseen::FrictionLimit,
                // A logged roll levels ay (`io::campaign`'s reading).
                _ if *e == EffectKind::AccelerometerRoll => match roll_unseen {
                    Some(unseen) => unseen,
                    None => return true,
                },
                _ => return true,
            };
            notes.push(Note::NotACandidate { effect: *e, lacks });
            false
        })
        .collect();
    // A bank seen through the yaw rate alone: axles identified from the
    // same runs can take up its lateral force (a banked oval without
    // sideslip or ay diagnosed "no significant gap").
    let blind = c
        .runs
        .iter()
        .filter(|r| r.bank.is_some() && r.beta.is_none() && r.ay.is_none())
        .count();
    if blind > 0 && matches!(c.tyres, crate::diagnose::campaign::BaseTyres::FromRuns) {
        notes.push(Note::BankOnlyInYawRate {
            runs: blind,
            of: c.runs.len(),
        });
    }
    (effects, notes)
}

/// A note on the runs the base model is too stiff to replay by RK4 on the
/// campaign's `step`, which it replays by ROS34PW2
/// ([`crate::diagnose::model::replay::Prepared::drive_for`]); every fit picks per model.
fn grid_note(ctx: &Context, step: f64) -> Option<Note> {
    let stiff = ctx
        .runs
        .iter()
        .filter(|r| {
            r.drive_for(&ctx.bases.all).method == crate::diagnose::model::FixedStep::RosenbrockW
        })
        .count();
    (stiff > 0).then_some(Note::StiffReplay {
        step,
        runs: stiff,
        of: ctx.runs.len(),
    })
}

/// Where the gap lies: every run replayed by the all-run base model, each
/// channel against its trusted noise floor.
fn base_gaps(c: &Campaign, all: &Augmented, trust: &Trust) -> Vec<RunGap> {
    let floors = (&trust.floors, &trust.countings);
    c.runs
        .par_iter()
        .map(|run| base_run_gap(all, run, c.settings.step, floors))
        .collect()
}

/// The held-out replays of every run by the base model and by the
/// verdict's (the base's again without a verdict).
fn before_after(ctx: &Context, chosen: Option<&Scored>) -> (Vec<Observed>, Vec<Observed>) {
    let base_obs = ctx.heldout_observed(None);
    let after_obs = match chosen {
        Some(sc) => ctx.heldout_observed(Some(sc)),
        None => base_obs.clone(),
    };
    (base_obs, after_obs)
}

/// The gap's findings ([`gap_summary`]), with the runs without an ay
/// channel.
fn gap_findings(
    c: &Campaign,
    run_gaps: &[RunGap],
    parts: &[Shrinkage],
    significant: bool,
    j0: f64,
    jn: f64,
) -> Vec<GapFinding> {
    let mut findings = gap_summary(run_gaps, parts, significant, j0, jn);
    let without_ay = c.runs.iter().filter(|r| r.ay.is_none()).count();
    if without_ay > 0 {
        findings.push(GapFinding::WithoutAy {
            runs: without_ay,
            of: c.runs.len(),
        });
    }
    findings
}

/// The base model as reported: where its tyres come from, the all-run
/// tyres and, for tyres identified from the runs, the axles.
fn base_report(
    bases: &Bases,
    source: TyreSource,
    rig_grouping: Option<GroupingReport>,
) -> BaseReport {
    BaseReport {
        source,
        front: bases.all.model.front.clone(),
        rear: bases.all.model.rear.clone(),
        rig_grouping,
        axles: bases.identification.clone(),
    }
}

/// Runs the diagnosis of a campaign. `progress` counts work units (as many
/// as `work_units` of the campaign). Where its time went is in the
/// report's `timing` ([`crate::diagnose::timing`]).
pub fn diagnose(c: &Campaign, progress: Option<&AtomicUsize>) -> Result<Diagnosis, Error> {
    run(c, progress, &Recorder::start())
}

/// Runs the diagnosis of a campaign and says where its time went
/// ([`crate::diagnose::timing`]): [`diagnose`] and its report's `timing`.
pub fn diagnose_timed(c: &Campaign) -> Result<(Diagnosis, Timing), Error> {
    let d = diagnose(c, None)?;
    let t = d.timing.clone();
    Ok((d, t))
}

/// The notes of a diagnosis: the campaign's own (as read) first, then the
/// candidates the runs cannot see (`visibility`), the replay grid, the
/// channel uncertainties stated but unused or below the runs' scatter.
fn notes_of(
    c: &Campaign,
    visibility: Vec<Note>,
    ctx: &Context,
    noise: &[ChannelNoise],
) -> Vec<Note> {
    let mut notes: Vec<Note> = c
        .notes
        .iter()
        .map(|text| Note::Campaign { text: text.clone() })
        .collect();
    notes.extend(visibility);
    notes.extend(grid_note(ctx, c.settings.step));
    notes.extend(noise_unmeasured(c, noise).map(|channel| Note::UncertaintyUnused { channel }));
    notes.extend(noise.iter().filter_map(below_scatter));
    notes.extend(
        noise
            .iter()
            .filter_map(|n| n.stated_excess.map(Note::UncertaintyAboveOwn)),
    );
    notes
}

/// Each replayed piece's road: bank and grade as logged or derived, with
/// the sensor offsets the standstills and straights measured removed.
fn roads(c: &Campaign, ctx: &Context) -> Vec<RoadGeometry> {
    let each = c.runs.iter().zip(&ctx.runs).map(|(m, r)| {
        let ahead = c.sensors.beta_ahead_of_accelerometer();
        RoadGeometry::of(&r.name, m, offsets(&ctx.calibrated), ahead)
    });
    RoadGeometry::set_apart(each.collect())
}

/// The candidates the runs can see and the notes on those they cannot; a
/// campaign whose every candidate is unseen is refused with what each lacks.
fn candidates_seen(c: &Campaign) -> Result<(Vec<EffectKind>, Vec<Note>), Error> {
    let (effects, visibility) = visible_effects(c);
    if effects.is_empty() && !c.effects.is_empty() {
        let unseen = visibility
            .iter()
            .filter_map(|n| match n {
                Note::NotACandidate { effect, lacks } => Some((effect.name().to_string(), *lacks)),
                _ => None,
            })
            .collect();
        return Err(DiagnosisError::NoCandidateSeen {
            campaign: c.source.clone(),
            unseen,
        }
        .into());
    }
    Ok((effects, visibility))
}

/// The notes on sideslip files read in the other sign convention; a
/// sideslip against the model throughout is refused before any fit.
fn beta_against(c: &Campaign, all: &Augmented) -> Result<Vec<Note>, Error> {
    let found = crate::diagnose::base::beta_sign::check(c, all).map_err(|source| {
        let campaign = c.source.clone();
        DiagnosisError::BetaAgainstModel { campaign, source }
    })?;
    Ok(found
        .into_iter()
        .map(|f| Note::BetaAgainstInFile {
            file: f.file,
            correlation: f.correlation,
            samples: f.samples,
        })
        .collect())
}

/// The candidates alone, scored, in order and ranked against the base,
/// the screened ones' rows, and the search of combinations within
/// `limits` (most effects, screening): without a significant gap nothing
/// is searched.
fn searched<'a>(
    ctx: &Context<'a>,
    effects: &[EffectKind],
    base: &Baseline,
    limits: (usize, bool),
    significant: bool,
) -> Searched<'a> {
    let (singles, order, screened, screened_rows) =
        singles(ctx, effects, base, limits.1, significant);
    let ranking: Vec<Ranked> = order.iter().map(|&i| base.rank(&singles[i])).collect();
    let found = significant.then(|| {
        let all: Vec<usize> = order.iter().chain(&screened).copied().collect();
        search(ctx, &singles, (&order, &all), base, limits)
    });
    let found = found.unwrap_or_default();
    (singles, order, ranking, screened_rows, found)
}

/// The gap report from the channels' trust (`noise`), the pooled `parts`
/// and the base model's gap on each run, against the `base` model's
/// held-out errors at the fits' `scales` (and the chosen set's, `after`,
/// for the verdict's shares): the findings ([`gap_findings`], the channel
/// that dominates), the shares, and on a verdict of no
/// significant gap what it rests on (an uncertainty stated far above its
/// channel's scatter, an assumed floor).
fn gap_report(
    c: &Campaign,
    (noise, parts, runs): (Vec<ChannelNoise>, Vec<Shrinkage>, Vec<RunGap>),
    (base, after): (&Baseline, Option<&ChannelErrors>),
    scales: &[f64; 3],
    verdict: &mut Verdict,
) -> GapReport {
    let (j0, jn) = (base.j0, base.jn);
    let significant = rules::significant(j0, jn);
    let mut findings = gap_findings(c, &runs, &parts, significant, j0, jn);
    // One computation of the shares, of the held-out errors `J` reads
    // (the verdict's `J` before and after), each channel's steady offset
    // a second number of its row: `dominant` reads them.
    let offsets = steady_offsets(&findings);
    let before = error_rows(&base.heldout, scales, &offsets);
    let after = after
        .filter(|_| !verdict.effects().is_empty())
        .map(|e| error_rows(e, scales, &[]));
    let channel_shares = channel_shares(&before, after.as_deref());
    findings.extend(dominant(&channel_shares));
    offsets_matched(verdict, &findings, &calibrated(c));
    if let Verdict::NoSignificantGap(n) = verdict {
        n.resting_on = noise.iter().filter_map(|n| n.stated_excess).collect();
        n.assumed = assumed_floors(&noise, &findings);
    }
    GapReport {
        significant,
        heldout_error: j0,
        noise_level: jn,
        noise,
        channel_shares,
        parts,
        runs,
        findings,
    }
}

/// The diagnosis, its phases timed by `recorder`.
fn run(
    c: &Campaign,
    progress: Option<&AtomicUsize>,
    recorder: &Recorder,
) -> Result<Diagnosis, Error> {
    let timing = Some(recorder);
    let set = &c.settings;
    let (effects, visibility) = candidates_seen(c)?;
    let (runs, folds, pso) = prepare(c);
    let trust = channel_trust(&c.runs, &c.uncertainty);
    let scales = trust.scales;
    let (bases, tyre_source, rig_grouping) = base_models(c, &runs, &folds, scales, timing)?;
    if let Some(p) = progress {
        p.fetch_add(1, Ordering::Relaxed);
    }

    let beta_against = beta_against(c, &bases.all)?;
    let run_gaps = base_gaps(c, &bases.all, &trust);
    let Trust { noise, floors, .. } = trust;
    let calibrated = calibrated(c);
    let ctx = Context {
        calibrated,
        runs,
        folds,
        scales,
        bases: &bases,
        pso,
        progress,
        timing,
        derivatives: c.settings.derivatives,
        shared: Default::default(),
    };
    let base = baseline(&ctx, &floors, (c.roll_gradient_at.clone(), &c.runs));
    let significant = rules::significant(base.j0, base.jn);
    let mut notes = notes_of(c, visibility, &ctx, &noise);
    notes.extend(rig_notes::rig_notes(c, &tyre_source, rig_grouping.as_ref()));
    notes.extend(limits::contradicted(c));
    notes.extend(beta_against);
    let limits = (set.max_effects, set.screening);
    let (singles, order, ranking, screened_rows, found) =
        searched(&ctx, &effects, &base, limits, significant);
    // Before and after on held-out runs, per channel, window and regime.
    let (base_obs, after_obs) = before_after(&ctx, found.chosen.as_ref());
    let shrinkage = parts_table(&c.runs, &ctx.runs, &base_obs, &after_obs, &floors);
    // The gap's parts are the same pooled before values; their `after` is
    // the verdict's (base replays again would write after = before, which
    // says the verdict changed nothing).
    let parts = shrinkage.clone();
    let pair = (&singles[..], &order[..]);
    let done = conclude(&ctx, c, &found, pair, (&base, significant), &shrinkage);
    let mut verdict = done.verdict;
    let overlays = overlays(&ctx, &base_obs, &after_obs);
    let scored = (&base, found.chosen.as_ref().map(|s| &s.heldout));
    let gap = gap_report(c, (noise, parts, run_gaps), scored, &scales, &mut verdict);
    let road = roads(c, &ctx);
    crate::diagnose::report::cause::point(&mut verdict, &notes, &gap, &road);
    Ok(Diagnosis {
        campaign: c.name.clone(),
        source: c.source.clone(),
        source_absolute: None,
        seed: set.seed,
        derivatives: set.derivatives,
        runs: ctx.runs.iter().map(|r| r.name.clone()).collect(),
        folds: ctx.folds.len(),
        notes,
        cleaning: c.cleaning.clone(),
        calibration: c.calibration.clone(),
        road,
        base: base_report(&bases, tyre_source, rig_grouping),
        gap,
        ranking,
        screened: screened_rows.into_iter().chain(found.screened).collect(),
        combinations: with_rows(found.combinations, &done.swapped),
        verdict,
        confounded: done.confounded,
        shrinkage,
        overlays,
        timing: recorder.timing(),
    })
}

/// The channels whose held-out RMS (their [`GapFinding::Channel`]) is
/// within three noise floors only because the floor is assumed
/// ([`AssumedFloor::of`]).
fn assumed_floors(
    noise: &[crate::diagnose::report::ChannelNoise],
    findings: &[GapFinding],
) -> Vec<crate::diagnose::report::outcome::AssumedFloor> {
    findings
        .iter()
        .filter_map(|f| match f {
            GapFinding::Channel { channel, rms, .. } => noise
                .iter()
                .find(|n| n.channel == *channel)
                .and_then(|n| crate::diagnose::report::outcome::AssumedFloor::of(n, *rms)),
            _ => None,
        })
        .collect()
}
