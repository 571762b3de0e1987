//! The base model's scores that every candidate is ranked against
//! ([`Baseline`]: its held-out and in-sample errors, the noise's, its BIC),
//! and what the ranking and the verdict's rules read of a candidate
//! against it: its report row ([`Baseline::rank`], with its warnings), its
//! reduction of the gap above noise, whether its axles are a tyre, and the
//! candidate the rules see ([`Baseline::candidate`]: idle or pressed
//! parameters). Units: SI, rad; J dimensionless, reductions in percent.

use crate::diagnose::base::identify::{AxleIdentification, NoTyre};
use crate::diagnose::base::prior::PriorReport;
use crate::diagnose::effects::{joined, Bound, EffectKind};
use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::channels::{gap_above, reduction};
use crate::diagnose::model::channels::{Channel, ChannelErrors};
use crate::diagnose::report::{
    ChannelError, HeldRollGradient, ParameterValue, RankWarning, Ranked, Refused,
};
use crate::diagnose::verdict::candidate::parameter_values;
use crate::diagnose::verdict::rules::{self, Candidate};
use crate::diagnose::verdict::score::{Context, Scored};

/// A candidate's held-out RMS error per channel, as report rows.
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
pub(crate) struct Baseline {
    /// Held-out error J of the base model, and of the noise alone.
    pub(crate) j0: f64,
    pub(crate) jn: f64,
    /// The same on all runs with the all-run fit.
    j0_in: f64,
    jn_in: f64,
    bic0: f64,
    scales: [f64; 3],
    folds: usize,
    /// The runs each fold leaves out, by name (the report's fold refits
    /// name them).
    fold_runs: Vec<Vec<String>>,
    /// Whether axle characteristics lead every parameter vector.
    axle: bool,
    /// The base's held-out errors by channel.
    pub(crate) heldout: ChannelErrors,
    /// The prior the axles are fitted against (axles identified from the
    /// runs).
    prior: Option<PriorReport>,
    /// The roll gradient the roll effects are fitted at (the campaign's):
    /// their per-radian values are said with their product with it.
    roll_gradient: HeldRollGradient,
}

impl Baseline {
    /// Why the axle characteristics fitted with a candidate are no tyre (a
    /// rigid axle, one without force, no grip, an early peak; empty for a
    /// tyre): such a candidate cannot be a verdict.
    pub(crate) fn no_tyre(&self, sc: &Scored) -> Vec<NoTyre> {
        if !self.axle {
            return Vec::new();
        }
        let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
        let shares = &p.params[a.clone()];
        let mut why = AxleIdentification::new(shares, &p.std_errors[a], None, 0).no_tyre;
        if let Some(prior) = &self.prior {
            why.extend(PriorReport::new(prior.prior, prior.friction_rule, shares).far_outside());
        }
        why
    }

    /// The parameter vector of `kinds` ([`Layout`]).
    pub(crate) fn layout(&self, kinds: &[EffectKind]) -> Layout {
        Layout::new(kinds, self.axle)
    }

    /// Whether the axles fitted with a candidate are no tyre.
    pub(crate) fn degenerate(&self, sc: &Scored) -> bool {
        !self.no_tyre(sc).is_empty()
    }

    /// Why a candidate is not the verdict ([`rules::refused`]); `gave_way`
    /// why the search started from another in its place, and `instead`
    /// the set the search ended on.
    pub(crate) fn refused(
        &self,
        sc: &Scored,
        gave_way: Option<rules::GaveWay>,
        instead: Option<Refused>,
    ) -> Refused {
        let r = self.rank(sc);
        rules::refused(
            (r.effects, r.reduction_percent, r.delta_bic),
            self.no_tyre(sc),
            gave_way,
            instead,
        )
    }

    /// What the choice of a candidate reads of it ([`rules::pick`]).
    pub(crate) fn candidate(&self, sc: &Scored) -> Candidate {
        Candidate {
            heldout: sc.heldout.combined(&self.scales),
            parameters: sc.full.free_count(),
            idle: idle(sc, &self.layout(&sc.kinds)),
            degenerate: self.degenerate(sc),
            pressed: pressed(sc, &self.layout(&sc.kinds)),
            inert: !inert(sc, &self.layout(&sc.kinds)).is_empty(),
        }
    }

    /// The effect parameters a candidate leaves idle, as its report row
    /// gives them ([`Baseline::rank`]; [`Baseline::candidate`] reads them
    /// as one flag).
    pub(crate) fn idle_values(&self, sc: &Scored) -> Vec<ParameterValue> {
        let layout = self.layout(&sc.kinds);
        let at = layout.effects().start;
        let row = self.rank(sc).parameters;
        let idle = idle_parameters(sc, &layout);
        let effect = |i: usize| (0..sc.kinds.len()).find(|&k| layout.effect(k).contains(&i));
        let params: Vec<_> = sc
            .kinds
            .iter()
            .flat_map(|e| e.parameters().iter())
            .collect();
        let distance = |i: usize| {
            let (v, se, off) = (sc.full.params[i], sc.full.std_errors[i], params[i - at].off);
            if v == off || se.is_nan() || se <= 0.0 {
                0.0
            } else {
                (v - off).abs() / se
            }
        };
        let each: Vec<(Option<usize>, f64)> =
            idle.iter().map(|&i| (effect(i), distance(i))).collect();
        idle.iter()
            .zip(named_idle(&each))
            .filter(|(_, named)| *named)
            .filter_map(|(&i, _)| row.get(i - at).cloned())
            .collect()
    }

    /// The channel scales of the combined errors.
    pub(crate) fn scales(&self) -> [f64; 3] {
        self.scales
    }

    /// The base model's BIC.
    pub(crate) fn bic0(&self) -> f64 {
        self.bic0
    }

    /// A fit's BIC less the base model's (negative: better).
    pub(crate) fn delta_bic(&self, sc: &Scored) -> f64 {
        sc.full.bic() - self.bic0
    }

    /// The in-sample reduction (%) of a fit with errors `e` on all runs.
    pub(crate) fn insample_reduction(&self, e: &ChannelErrors) -> f64 {
        reduction(self.j0_in, e.combined(&self.scales), self.jn_in)
    }

    /// Whether the base leaves a gap above noise in sample: without one an
    /// in-sample reduction bounds nothing.
    pub(crate) fn insample_gap(&self) -> bool {
        gap_above(self.j0_in, self.jn_in) > 0.0
    }

    /// The share (%) of the in-sample gap above noise a set with all-run
    /// errors `set` leaves that a larger set with errors `larger` removes,
    /// None where `set` leaves none in sample (it then bounds nothing).
    pub(crate) fn insample_extra(
        &self,
        set: &ChannelErrors,
        larger: &ChannelErrors,
    ) -> Option<f64> {
        let j = set.combined(&self.scales);
        (gap_above(j, self.jn_in) > 0.0)
            .then(|| reduction(j, larger.combined(&self.scales), self.jn_in))
    }

    /// The least held-out error a candidate can have whose held-out
    /// reduction is at most `percent`.
    pub(crate) fn heldout_floor(&self, percent: f64) -> f64 {
        let g = (1.0 - percent.min(100.0) / 100.0) * gap_above(self.j0, self.jn);
        (g * g + self.jn * self.jn).sqrt()
    }

    /// The warning of fold refits landing far from the all-run fit
    /// ([`rules::far_folds`], over the effect and roll parameters), said
    /// where the cross-validation disagrees with the fit.
    fn folds_far(&self, sc: &Scored) -> Option<RankWarning> {
        let layout = self.layout(&sc.kinds);
        let at = layout.effects().start;
        let p = &sc.full;
        let (i, fold_value, distance, far) = rules::far_folds(
            &p.params,
            &p.std_errors,
            &sc.fold_params,
            at..p.params.len(),
        )?;
        let (group, q) = layout.parameters().nth(i - at)?;
        Some(RankWarning::FoldsFar {
            parameter: format!("{}.{}", group.name(), q.name),
            value: p.params[i],
            std_error: p.std_errors[i],
            reported_std_error: p.reported_std_errors()[i],
            fold_value,
            distance,
            far,
            folds: sc.fold_params.len(),
        })
    }

    /// A scored candidate as a row of the report, with its warnings.
    pub(crate) fn rank(&self, sc: &Scored) -> Ranked {
        let j = sc.heldout.combined(&self.scales);
        let held = reduction(self.j0, j, self.jn);
        let j_in = sc.insample.combined(&self.scales);
        let inside = reduction(self.j0_in, j_in, self.jn_in);
        let folds = self.folds;
        let converged = sc.fold_converged.iter().filter(|&&c| c).count();
        let mut warnings = Vec::new();
        if rules::disagrees(inside, held) {
            warnings.push(RankWarning::Disagreement {
                insample_percent: inside,
                heldout_percent: held,
            });
            // Why it may: folds whose refits found other optima. Only
            // here: a model-form gap makes standard errors optimistic, so
            // folds of a candidate that generalises land a few of them
            // away too (measured: cornering_stiffness at 20 of them).
            warnings.extend(self.folds_far(sc));
        }
        let no_tyre = self.no_tyre(sc);
        if !no_tyre.is_empty() {
            warnings.push(RankWarning::AxlesNoTyre { no_tyre });
        }
        let effects = inert(sc, &self.layout(&sc.kinds));
        if !effects.is_empty() {
            let reduces_to = sc.kinds.iter().filter(|k| !effects.contains(k));
            warnings.push(RankWarning::ContributesNothing {
                reduces_to: reduces_to.copied().collect(),
                effects,
            });
        }
        if converged < folds {
            warnings.push(RankWarning::FoldsNotConverged {
                failed: folds - converged,
                folds,
            });
        }
        Ranked {
            effect: joined(&sc.kinds, "+"),
            effects: sc.kinds.clone(),
            axles: self.axle.then(|| {
                let (p, a) = (&sc.full, self.layout(&sc.kinds).axles());
                let shares = &p.params[a.clone()];
                let id = AxleIdentification::new(shares, &p.reported_std_errors()[a], None, 0);
                match &self.prior {
                    Some(r) => id.with_prior(PriorReport::new(r.prior, r.friction_rule, shares)),
                    None => id,
                }
                .parameters
            }),
            prior_weight: sc.prior_weight,
            parameters: parameter_values(
                &self.layout(&sc.kinds),
                &sc.full,
                (&sc.fold_params, &sc.fold_noise),
                j > self.jn,
            )
            .into_iter()
            .map(|v| v.with_fold_runs(&self.fold_runs, &sc.fold_converged))
            .map(|v| v.at_roll_gradient(&self.roll_gradient))
            .collect(),
            heldout_error_before: self.j0,
            heldout_error_after: j,
            heldout_channels: channel_errors(&sc.heldout),
            reduction_percent: held,
            insample_error_after: j_in,
            insample_reduction_percent: inside,
            folds_converged: converged,
            folds,
            warnings,
            bic: sc.full.bic(),
            delta_bic: sc.full.bic() - self.bic0,
            global_search: sc.full.global,
        }
    }
}

/// The base model scored on held-out and fitted runs, with the error the
/// channels' noise floors alone would give; `roll` is where the campaign
/// states the roll gradient, if it does (file, line), and its runs (those
/// that log roll are counted).
pub(crate) fn baseline(
    ctx: &Context,
    floors: &[f64; 3],
    roll: (
        Option<(std::path::PathBuf, usize)>,
        &[crate::measured::MeasuredRun],
    ),
) -> Baseline {
    let scales = ctx.scales;
    let noise_level = |e: &ChannelErrors| {
        let n: usize = e.count.iter().sum();
        let s: f64 = (0..3)
            .map(|i| e.count[i] as f64 * (floors[i] / scales[i]).powi(2))
            .sum();
        (s / n.max(1) as f64).sqrt()
    };
    let scored = ctx.score(Vec::new(), &[], 0);
    Baseline {
        j0: scored.heldout.combined(&scales),
        jn: noise_level(&scored.heldout),
        j0_in: scored.insample.combined(&scales),
        jn_in: noise_level(&scored.insample),
        bic0: scored.full.bic(),
        scales,
        folds: ctx.folds.len(),
        fold_runs: (ctx.folds.iter())
            .map(|f| f.iter().map(|&i| ctx.runs[i].name.clone()).collect())
            .collect(),
        axle: ctx.bases.axle.is_some(),
        heldout: scored.heldout,
        prior: ctx.bases.identification.as_ref().and_then(|i| i.prior),
        roll_gradient: HeldRollGradient {
            gradient: ctx.bases.all.effects().roll.gradient,
            file: roll.0.as_ref().map(|(f, _)| f.clone()),
            line: roll.0.map(|(_, l)| l),
            runs_logging_roll: roll.1.iter().filter(|r| r.roll.is_some()).count(),
        },
    }
}

/// Whether a fit leaves one of its effect parameters idle: at its
/// off value (on a physical limit there, or not), within two standard
/// errors of it, or off a bound without a standard error at all (its
/// Jacobian column all but a combination of the others': exact Jacobians
/// show a steer path's lag at a few microseconds to be its delay's twin):
/// that part of the effect is off, or the data cannot tell it from off,
/// and it reduces to a simpler one. A parameter no measured channel
/// responds to ([`crate::diagnose::fit::FitOutcome::unseen`]) is held, not
/// idle.
fn idle(sc: &Scored, layout: &Layout) -> bool {
    !idle_parameters(sc, layout).is_empty()
}

/// The effect parameters [`idle`] finds idle, as indices into the fit's
/// vector.
fn idle_parameters(sc: &Scored, layout: &Layout) -> Vec<usize> {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    let idle = params.zip(layout.effects()).filter(|&(q, i)| {
        // Held because no measured channel responds to it: not a part of
        // the effect the runs could test, so not one they found off.
        if sc.full.is_unseen(i) {
            return false;
        }
        let (value, se) = (sc.full.params[i], sc.full.std_errors[i]);
        // Off, or no further from off than the data can tell; a value on
        // a search bound (no standard error) is pressed there, not idle.
        let off = !q.off.is_nan() && (value - q.off).abs() <= 1e-9 * (q.bounds.1 - q.bounds.0);
        match q.bound_at(value) {
            Some(Bound::Search) => false,
            Some(Bound::Physical) => off,
            None => off || (!q.off.is_nan() && (se.is_nan() || (value - q.off).abs() < 2.0 * se)),
        }
    });
    idle.map(|(_, i)| i).collect()
}

/// Of a fit's idle parameters (each its effect and its distance from off
/// in standard errors, 0 at off), those the words name idle: per effect,
/// the nearest off. Two parameters of one effect that trade against each
/// other (a steer path's delay and lag) are each within two standard
/// errors of off while their sum is determined: the one at off (the lag at
/// 6e-5 s, 0.001 standard errors) is idle, the other (the delay at
/// 0.0496 ± 0.0621 s) carries the effect and is not.
fn named_idle(idle: &[(Option<usize>, f64)]) -> Vec<bool> {
    idle.iter()
        .map(|&(effect, d)| {
            idle.iter()
                .filter(|(e, _)| *e == effect)
                .all(|&(_, other)| d <= other)
        })
        .collect()
}

/// The effects of a set that contribute nothing
/// ([`rules::contributes_nothing`]: every parameter at its off value
/// within its standard error), in the set's order; none of a single,
/// which the parsimony rule reads ([`idle`]). A parameter no measured
/// channel responds to is held, not found off: it reads as on.
pub(crate) fn inert(sc: &Scored, layout: &Layout) -> Vec<EffectKind> {
    if sc.kinds.len() < 2 {
        return Vec::new();
    }
    let readings: Vec<Vec<rules::OffReading>> = (0..sc.kinds.len())
        .map(|k| {
            let params = sc.kinds[k].parameters().iter();
            params
                .zip(layout.effect(k))
                .map(|(q, i)| rules::OffReading {
                    value: sc.full.params[i],
                    off: if sc.full.is_unseen(i) {
                        f64::NAN
                    } else {
                        q.off
                    },
                    std_error: sc.full.std_errors[i],
                    range: q.bounds.1 - q.bounds.0,
                })
                .collect()
        })
        .collect();
    rules::inert_effects(&readings)
        .into_iter()
        .map(|k| sc.kinds[k])
        .collect()
}

/// Whether one of a fit's effect parameters (not the roll dynamics, whose
/// damping a roll effect presses on its bound where the runs barely roll)
/// lies on the end of its search range ([`Bound::Search`]).
fn pressed(sc: &Scored, layout: &Layout) -> bool {
    let params = sc.kinds.iter().flat_map(|e| e.parameters().iter());
    params
        .zip(layout.effects())
        .any(|(q, i)| q.bound_at(sc.full.params[i]) == Some(Bound::Search))
}

#[cfg(test)]
mod named_idle_tests {
    use super::named_idle;

    /// Round 19's campaign yi: steer_path.delay = 0.0496 ± 0.0621 s (0.80
    /// standard errors) and steer_path.lag = 6.4e-5 ± 0.0622 s (0.001),
    /// both within two of off: only the lag is named idle.
    #[test]
    fn of_two_idle_parameters_of_one_effect_the_nearest_off_is_named() {
        let delay = 0.0496 / 0.0621;
        let lag = 6.423e-5 / 0.0622;
        assert_eq!(
            named_idle(&[(Some(0), delay), (Some(0), lag)]),
            [false, true]
        );
        // Each effect its own: one idle parameter of another is named.
        let each = [(Some(0), delay), (Some(0), lag), (Some(1), 1.5)];
        assert_eq!(named_idle(&each), [false, true, true]);
        // Both at off: both named.
        assert_eq!(named_idle(&[(Some(0), 0.0), (Some(0), 0.0)]), [true, true]);
    }
}
