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

pub use super::report::*;
use crate::measured::road::RoadGeometry;

use super::base::AxleIdentification;
use super::campaign::Campaign;
use super::candidates::{base_models, combined_start, parameter_values};
use super::crossval::{gap_above, prepare, reduction, singles, Context, Scored};
use super::effects::{joined, Bound, EffectKind, EffectSet, Needs};
use super::fit::{Channel, ChannelErrors};
use super::model::Observed;
pub use super::summary::observed_channel;
use super::summary::{base_run_gap, gap_summary, parts_table};
use crate::error::Error;
use rayon::prelude::*;
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
/// Look-alikes of the best single the verdict's search also starts from
/// while the set found leaves a significant gap.
pub const ALTERNATIVE_STARTS: usize = 2;
/// Held-out error, in noise levels, by which a candidate that leaves a
/// parameter idle must beat a simpler one (fewer parameters) to be
/// preferred to it.
pub const PARSIMONY: f64 = 0.1;
/// Largest number of folds.
pub const MAX_FOLDS: usize = 8;

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

fn channel_errors(e: &ChannelErrors) -> Vec<ChannelError> {
    Channel::ALL
        .into_iter()
        .filter_map(|c| {
            e.rms(c).map(|rms| ChannelError {
                channel: c,
                unit: c.unit(),
                rms,
            })
        })
        .collect()
}

/// The base model's held-out and in-sample scores that every candidate is
/// ranked against.
struct Baseline {
    /// Held-out error J of the base model, and of the noise alone.
    j0: f64,
    jn: f64,
    /// The same on all runs with the all-run fit.
    j0_in: f64,
    jn_in: f64,
    bic0: f64,
    scales: [f64; 3],
    folds: usize,
    /// Axle characteristics leading every parameter vector (0 or 3).
    axle_count: usize,
}

impl Baseline {
    /// Why the axle characteristics fitted with a candidate are no tyre (a
    /// rigid axle, one without force, no grip), if they are not: such a
    /// candidate cannot be a verdict.
    fn degenerate(&self, sc: &Scored) -> Option<String> {
        (self.axle_count == 3)
            .then(|| {
                let p = &sc.full.params;
                AxleIdentification::new(&p[..3], &sc.full.std_errors[..3], None, 0).degenerate
            })
            .flatten()
    }

    /// A scored candidate as a row of the report, with its warnings.
    fn rank(&self, sc: &Scored) -> Ranked {
        let j = sc.heldout.combined(&self.scales);
        let held = reduction(self.j0, j, self.jn);
        let j_in = sc.insample.combined(&self.scales);
        let inside = reduction(self.j0_in, j_in, self.jn_in);
        let folds = self.folds;
        let mut warnings = Vec::new();
        if inside - held > DISAGREEMENT && inside >= 100.0 * ACCEPT {
            warnings.push(format!(
                "the fit on all runs removes {inside:.0} % of the gap but only {held:.0} % on held-out runs: \
                 the effect does not generalise across runs, or the runs cannot pin its parameters"
            ));
        }
        if let Some(why) = self.degenerate(sc) {
            warnings.push(format!(
                "fitted with it, the axles are no tyre ({why}): it cannot be a verdict"
            ));
        }
        if sc.folds_converged < folds {
            warnings.push(format!(
                "{} of {folds} fold refits did not converge",
                folds - sc.folds_converged
            ));
        }
        Ranked {
            effect: joined(&sc.kinds, "+"),
            effects: sc.kinds.clone(),
            parameters: parameter_values(&sc.kinds, &sc.full, self.axle_count),
            heldout_error_before: self.j0,
            heldout_error_after: j,
            heldout_channels: channel_errors(&sc.heldout),
            reduction_percent: held,
            insample_error_after: j_in,
            insample_reduction_percent: inside,
            folds_converged: sc.folds_converged,
            folds,
            warning: (!warnings.is_empty()).then(|| warnings.join("; ")),
            bic: sc.full.bic(),
            delta_bic: sc.full.bic() - self.bic0,
        }
    }
}

/// Channel scales before the base model exists (for the axle fit): 2 % of
/// each channel's RMS signal, refined with the noise floors later.
fn signal_scales(c: &Campaign) -> [f64; 3] {
    Channel::ALL.map(|ch| {
        let (mut s, mut n) = (0.0, 0usize);
        for r in &c.runs {
            if let Some(v) = ch.of(r) {
                s += v.iter().map(|x| x * x).sum::<f64>();
                n += v.len();
            }
        }
        if n == 0 {
            0.02
        } else {
            0.02 * (s / n as f64).sqrt().max(1e-9)
        }
    })
}

/// Noise floors pooled over runs (median), the channel scales (the floor,
/// at least `hint`) and the floors by channel index.
fn noise_table(run_gaps: &[RunGap], hint: [f64; 3]) -> (Vec<ChannelNoise>, [f64; 3], [f64; 3]) {
    let mut scales = hint;
    let mut floors = [0.0; 3];
    let noise = Channel::ALL
        .into_iter()
        .filter_map(|ch| {
            let per_run: Vec<f64> = run_gaps
                .iter()
                .filter_map(|g| g.channels.iter().find(|x| x.channel == ch))
                .map(|x| x.noise_floor)
                .collect();
            (!per_run.is_empty()).then(|| {
                let nf = median(per_run.clone());
                scales[ch.index()] = nf.max(hint[ch.index()]);
                floors[ch.index()] = nf;
                ChannelNoise {
                    channel: ch,
                    unit: ch.unit(),
                    noise_floor: nf,
                    scale: scales[ch.index()],
                    runs: per_run.len(),
                }
            })
        })
        .collect();
    (noise, scales, floors)
}

/// What the search for a verdict found.
struct Search {
    /// The accepted set, if any.
    chosen: Option<Scored>,
    /// Every combination tried, as report rows.
    combinations: Vec<Ranked>,
    /// Singles (indices) that pass and leave about the best's gap.
    lookalikes: Vec<usize>,
}

/// The verdict's search: the best single (`order` ranks `singles` by
/// held-out error), then greedy additions, each tried jointly with every
/// remaining effect.
fn search(
    ctx: &Context,
    singles: &[Scored],
    order: &[usize],
    base: &Baseline,
    max_effects: usize,
) -> Search {
    let mut out = Search {
        chosen: None,
        combinations: Vec::new(),
        lookalikes: Vec::new(),
    };
    // A candidate whose axles are no tyre cannot be the verdict, nor
    // start one.
    let order: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| base.degenerate(&singles[i]).is_none())
        .collect();
    let order = &order[..];
    let (scales, jn) = (base.scales, base.jn);
    // The best single, or a simpler one that does as well where the best
    // leaves a parameter idle: a steer path whose lag stays off is a steer
    // delay, one with a sensor delay on runs whose every response comes
    // from the steer, and must not win on the interpolation's rounding.
    let Some(&top) = order.first() else {
        return out;
    };
    let j_top = singles[top].heldout.combined(&scales);
    let first = if idle(&singles[top], base.axle_count) {
        order
            .iter()
            .copied()
            .filter(|&i| singles[i].heldout.combined(&scales) <= j_top + PARSIMONY * jn)
            .min_by_key(|&i| singles[i].full.params.len())
            .unwrap_or(top)
    } else {
        top
    };
    let best = &singles[first];
    let r = base.rank(best);
    // A best single below the acceptance share can still be half of a
    // pair of effects: the greedy search starts from it when it is
    // promising, and the set found must pass as a whole.
    if r.reduction_percent < 100.0 * PROMISING || r.delta_bic >= 0.0 {
        return out;
    }
    // Look-alikes of the accepted effect: singles that also pass and
    // leave about as small a gap.
    let g_best = gap_above(r.heldout_error_after, jn);
    out.lookalikes = order
        .iter()
        .copied()
        .filter(|&i| i != first)
        .filter(|&i| {
            let o = base.rank(&singles[i]);
            o.reduction_percent >= 100.0 * ACCEPT
                && gap_above(o.heldout_error_after, jn)
                    <= CONFOUNDED * g_best + CONFOUNDED_NOISE * jn
        })
        .collect();
    let mut current = greedy(ctx, singles, order, base, max_effects, best, &mut out);
    // The best single can be a look-alike that mimics part of a pair and
    // leads the greedy search away from it (a fast, lightly damped roll
    // steering the axles looks like a yaw inertia and aero load together).
    // While the set found leaves a significant gap, the search starts again
    // from the look-alikes (at most ALTERNATIVE_STARTS), and a set that
    // leaves clearly less of the gap (below 1/CONFOUNDED of it) replaces it.
    for &i in out.lookalikes.clone().iter().take(ALTERNATIVE_STARTS) {
        let jc = current.heldout.combined(&scales);
        if jc <= SIGNIFICANT * jn {
            break;
        }
        let other = greedy(
            ctx,
            singles,
            order,
            base,
            max_effects,
            &singles[i],
            &mut out,
        );
        let (g, g_other) = (
            gap_above(jc, jn),
            gap_above(other.heldout.combined(&scales), jn),
        );
        if g_other * CONFOUNDED < g {
            current = other;
        }
    }
    let total = reduction(base.j0, current.heldout.combined(&scales), jn);
    if total >= 100.0 * ACCEPT && current.full.bic() < base.bic0 {
        out.chosen = Some(current);
    }
    let mut seen = std::collections::HashSet::new();
    out.combinations.retain(|r| seen.insert(r.effect.clone()));
    out.combinations
        .sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    out
}

/// Whether a fit leaves one of its effect parameters idle: at its
/// physical limit, or within two standard errors of its off value (that
/// part of the effect is off and it reduces to a simpler one).
fn idle(sc: &Scored, axle_count: usize) -> bool {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    params.enumerate().any(|(i, q)| {
        let (value, se) = (
            sc.full.params[axle_count + i],
            sc.full.std_errors[axle_count + i],
        );
        q.bound_at(value) == Some(Bound::Physical)
            || (!q.off.is_nan() && (se.is_nan() || (value - q.off).abs() < 2.0 * se))
    })
}

/// Greedy additions from `start`: the effect that best closes what is left,
/// tried jointly with every remaining effect, while each removes
/// [`ACCEPT`] of what is left and lowers the BIC. Every set tried goes into
/// `out.combinations`.
fn greedy(
    ctx: &Context,
    singles: &[Scored],
    order: &[usize],
    base: &Baseline,
    max_effects: usize,
    start: &Scored,
    out: &mut Search,
) -> Scored {
    let (scales, jn) = (base.scales, base.jn);
    let mut current = start.clone();
    // Greedy: add the effect that best closes what is left.
    while current.kinds.len() < max_effects {
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
                let members = combined_start(
                    (&cur.kinds, &cur.full.params),
                    (*e, &single.full.params),
                    base.axle_count,
                );
                let added_off = ctx.off(&[*e]);
                let extended = combined_start(
                    (&cur.kinds, &cur.full.params),
                    (*e, &added_off),
                    base.axle_count,
                );
                // Each member's own optimum: the axles the added effect
                // fitted alone want can differ from the current set's.
                let mut own = members.clone();
                own[..base.axle_count].copy_from_slice(&single.full.params[..base.axle_count]);
                ctx.score(
                    kinds,
                    EffectSet::default(),
                    &[members, extended, own],
                    1000 + i as u64,
                )
            })
            .collect();
        scored.sort_by(|a, b| {
            a.heldout
                .combined(&scales)
                .total_cmp(&b.heldout.combined(&scales))
        });
        out.combinations
            .extend(scored.iter().map(|sc| base.rank(sc)));
        let Some(next) = scored.into_iter().find(|sc| base.degenerate(sc).is_none()) else {
            break;
        };
        let extra = reduction(jc, next.heldout.combined(&scales), jn);
        if extra >= 100.0 * ACCEPT && next.full.bic() < current.full.bic() {
            current = next;
        } else {
            break;
        }
    }
    current
}

/// The accepted first effect's look-alikes, less those the verdict took in
/// as well, with the experiments that would separate them.
fn confounded_with(
    chosen: &Scored,
    singles: &[Scored],
    lookalikes: &[usize],
    base: &Baseline,
) -> Vec<Confounded> {
    let first = singles
        .iter()
        .find(|x| x.kinds[0] == chosen.kinds[0])
        .expect("the verdict starts from a scored single");
    let members: Vec<&Scored> = std::iter::once(first)
        .chain(
            lookalikes
                .iter()
                .map(|&i| &singles[i])
                .filter(|x| !chosen.kinds.contains(&x.kinds[0])),
        )
        .collect();
    if members.len() < 2 {
        return Vec::new();
    }
    vec![Confounded {
        effects: members.iter().map(|x| x.kinds[0]).collect(),
        reduction_percent: members
            .iter()
            .map(|x| base.rank(x).reduction_percent)
            .collect(),
        separating_test: members
            .iter()
            .map(|x| format!("{}: {}", x.kinds[0].name(), x.kinds[0].signature()))
            .collect::<Vec<_>>()
            .join("; "),
    }]
}

/// The verdict in words.
fn verdict_of(
    chosen: Option<&Scored>,
    base: &Baseline,
    significant: bool,
    ranking: &[Ranked],
    degenerate: Option<&str>,
) -> Verdict {
    let (j0, jn) = (base.j0, base.jn);
    // A base that is no tyre gives no model-form verdict: what no
    // candidate explains may be the base's own collapse.
    if let (None, Some(why), true) = (chosen, degenerate, significant) {
        return Verdict {
            effects: Vec::new(),
            parameters: Vec::new(),
            warnings: Vec::new(),
            statement: format!(
                "the base model is not identifiable from these runs: {why}; no candidate effect fitted with it gives axles that are a tyre and removes {:.0} % of the gap (held-out error {j0:.3}, noise level {jn:.3}), so there is no model-form verdict",
                100.0 * ACCEPT
            ),
        };
    }
    match chosen {
        Some(sc) => {
            let r = base.rank(sc);
            // Accepted at 30 %: where most of the gap stays, the verdict
            // says so.
            let statement = if r.reduction_percent >= 50.0 {
                format!(
                    "{} explains the gap: held-out error {:.3} → {:.3} (noise level {:.3}), {:.1} % of the gap above noise removed",
                    r.effect, j0, r.heldout_error_after, jn, r.reduction_percent
                )
            } else {
                format!(
                    "{} explains part of the gap: held-out error {:.3} → {:.3} (noise level {:.3}), {:.1} % of the gap above noise removed; the other {:.1} % no candidate explains",
                    r.effect,
                    j0,
                    r.heldout_error_after,
                    jn,
                    r.reduction_percent,
                    100.0 - r.reduction_percent
                )
            };
            Verdict {
                effects: r.effects.clone(),
                parameters: r.parameters.clone(),
                statement,
                warnings: Vec::new(),
            }
        }
        None => Verdict {
            effects: Vec::new(),
            parameters: Vec::new(),
            warnings: Vec::new(),
            statement: if !significant {
                format!(
                    "no significant gap: held-out error {j0:.3} is within {SIGNIFICANT} × the noise level {jn:.3}"
                )
            } else {
                format!(
                    "a gap (held-out error {j0:.3}, noise level {jn:.3}) that no candidate effect explains: the best, {}, removes {:.1} % of it (acceptance needs {:.0} %) — a model-form error outside the library",
                    ranking.first().map_or("none", |r| r.effect.as_str()),
                    ranking.first().map_or(0.0, |r| r.reduction_percent),
                    100.0 * ACCEPT
                )
            },
        },
    }
}

/// A channel's gap above noise grown by more than this share (%) under the
/// verdict's effects is worth a warning: beyond the scatter of held-out
/// scores, and the combined error that accepted them does not show it.
const WORSENED: f64 = 10.0;

/// Warnings for the channels the verdict's effects leave worse on
/// held-out runs (all samples).
fn worsened(shrinkage: &[Shrinkage]) -> Vec<String> {
    shrinkage
        .iter()
        .filter(|s| s.part == Part::All && s.reduction_percent < -WORSENED && s.after > s.before)
        .map(|s| {
            format!(
                "it leaves the {} gap larger on held-out runs: RMS {:.4} → {:.4} {} (noise floor {:.4}), {:.0} % of the gap above noise added; the combined error falls through the other channels (check this channel's sensor and whether the effect's physics can make it worse)",
                s.channel.name(),
                s.before,
                s.after,
                s.channel.unit(),
                s.noise_floor,
                -s.reduction_percent
            )
        })
        .collect()
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

/// The base model scored on held-out and fitted runs, with the error the
/// channels' noise floors alone would give.
fn baseline(ctx: &Context, floors: &[f64; 3]) -> Baseline {
    let scales = ctx.scales;
    let noise_level = |e: &ChannelErrors| {
        let n: usize = e.count.iter().sum();
        let s: f64 = (0..3)
            .map(|i| e.count[i] as f64 * (floors[i] / scales[i]).powi(2))
            .sum();
        (s / n.max(1) as f64).sqrt()
    };
    let scored = ctx.score(Vec::new(), EffectSet::default(), &[], 0);
    Baseline {
        j0: scored.heldout.combined(&scales),
        jn: noise_level(&scored.heldout),
        j0_in: scored.insample.combined(&scales),
        jn_in: noise_level(&scored.insample),
        bic0: scored.full.bic(),
        scales,
        folds: ctx.folds.len(),
        axle_count: if ctx.bases.axle.is_some() { 3 } else { 0 },
    }
}

/// A longitudinal acceleration that shows, m/s²: well above a logger's
/// noise on `ax` and a speed trace's differencing noise.
const VISIBLE_AX: f64 = 0.5;

/// The campaign's candidate effects that its runs can show, and a note for
/// each one left out (an effect of braking and throttle without a
/// longitudinal acceleration, a bank profile without a `bank` channel).
fn visible_effects(c: &Campaign) -> (Vec<EffectKind>, Vec<String>) {
    // The acceleration the replays use: the measured ax, else the
    // smoothed speed derivative (a raw difference of a noisy speed would
    // admit braking effects on constant-speed runs).
    let accelerates = c.runs.iter().any(|r| {
        r.longitudinal_acceleration()
            .iter()
            .any(|a| a.abs() > VISIBLE_AX)
    });
    let banked = c.runs.iter().any(|r| r.bank.is_some());
    let mut notes = Vec::new();
    let effects = c
        .effects
        .iter()
        .copied()
        .filter(|e| {
            let why = match e.needs() {
                Needs::LongitudinalAcceleration if !accelerates => format!(
                    "no run has a longitudinal acceleration above {VISIBLE_AX} m/s² (an ax channel or a changing speed)"
                ),
                Needs::BankChannel if !banked => "no run has a bank channel".to_string(),
                _ => return true,
            };
            notes.push(format!("{}: not a candidate: {why}", e.name()));
            false
        })
        .collect();
    (effects, notes)
}

/// A note on the runs the base model is too stiff to replay by RK4 on the
/// campaign's `step`, which it replays by ROS34PW2
/// ([`super::fit::Prepared::drive_for`]); every fit picks per model.
fn grid_note(ctx: &Context, step: f64) -> Option<String> {
    let stiff = ctx
        .runs
        .iter()
        .filter(|r| r.drive_for(&ctx.bases.all).method == super::model::FixedStep::RosenbrockW)
        .count();
    (stiff > 0).then(|| {
        format!(
            "replay method: the base model is too stiff for RK4 at the {step} s step on {stiff} of {} runs, replayed by the linearly implicit ROS34PW2 at that step",
            ctx.runs.len()
        )
    })
}

/// Runs the diagnosis of a campaign. `progress` counts work units (see
/// [`work_units`]).
pub fn diagnose(c: &Campaign, progress: Option<&AtomicUsize>) -> Result<Diagnosis, Error> {
    let set = &c.settings;
    let (runs, folds, pso) = prepare(c);
    let hint = signal_scales(c);
    let (bases, tyre_source, rig_grouping) = base_models(c, &runs, &folds, hint)?;
    if let Some(p) = progress {
        p.fetch_add(1, Ordering::Relaxed);
    }

    // Where the gap lies: every run replayed by the all-run base model.
    let run_gaps: Vec<RunGap> = c
        .runs
        .par_iter()
        .map(|run| base_run_gap(&bases.all, run, set.step))
        .collect();
    let (noise, scales, floors) = noise_table(&run_gaps, hint);
    let ctx = Context {
        runs,
        folds,
        scales,
        bases: &bases,
        pso,
        progress,
    };
    let base = baseline(&ctx, &floors);
    let (j0, jn) = (base.j0, base.jn);
    let significant = j0 > SIGNIFICANT * jn;
    let (effects, mut notes) = visible_effects(c);
    notes.extend(grid_note(&ctx, set.step));
    let (singles, order) = singles(&ctx, &effects);
    let ranking: Vec<Ranked> = order.iter().map(|&i| base.rank(&singles[i])).collect();

    let found = if significant {
        search(&ctx, &singles, &order, &base, set.max_effects)
    } else {
        Search {
            chosen: None,
            combinations: Vec::new(),
            lookalikes: Vec::new(),
        }
    };
    let chosen = found.chosen.as_ref();
    let confounded = chosen.map_or_else(Vec::new, |sc| {
        confounded_with(sc, &singles, &found.lookalikes, &base)
    });

    // Before and after on held-out runs, per channel, window and regime.
    let base_obs = ctx.heldout_observed(None, &EffectSet::default());
    let after_obs = match chosen {
        Some(sc) => ctx.heldout_observed(Some(sc), &EffectSet::default()),
        None => base_obs.clone(),
    };
    let shrinkage = parts_table(&c.runs, &ctx.runs, &base_obs, &after_obs, &floors);
    let parts = parts_table(&c.runs, &ctx.runs, &base_obs, &base_obs, &floors);
    let degenerate = bases
        .identification
        .as_ref()
        .and_then(|i| i.degenerate.as_deref());
    let mut verdict = verdict_of(chosen, &base, significant, &ranking, degenerate);
    if chosen.is_some() {
        verdict.warnings = worsened(&shrinkage);
        if let Some(why) = degenerate {
            verdict.warnings.push(format!(
                "the base model alone is no tyre ({why}); the reductions are measured against it, and with the verdict's effects the axles are a tyre"
            ));
        }
    }
    let overlays = overlays(&ctx, &base_obs, &after_obs);
    let mut summary = gap_summary(&run_gaps, &parts, significant, j0, jn);
    let without_ay = c.runs.iter().filter(|r| r.ay.is_none()).count();
    if without_ay > 0 {
        summary.push(format!(
            "|ay| levels are u·r on the {without_ay} of {} runs without an ay channel",
            c.runs.len()
        ));
    }
    Ok(Diagnosis {
        campaign: c.name.clone(),
        seed: set.seed,
        runs: ctx.runs.iter().map(|r| r.name.clone()).collect(),
        folds: ctx.folds.len(),
        notes: {
            notes.splice(0..0, c.notes.iter().cloned());
            notes
        },
        cleaning: c.cleaning.clone(),
        road: c
            .runs
            .iter()
            .zip(&ctx.runs)
            .map(|(m, r)| RoadGeometry::of(&r.name, m))
            .collect(),
        base: BaseReport {
            tyres: tyre_source,
            front: bases.all.base.front.clone(),
            rear: bases.all.base.rear.clone(),
            rig_grouping,
            axles: bases.identification.clone(),
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
        combinations: found.combinations,
        verdict,
        confounded,
        shrinkage,
        overlays,
    })
}
