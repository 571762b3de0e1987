//! The verdict from what the search found: its case ([`rules::case`]),
//! and for each case what a reader needs — the explained set's figures
//! with its warnings (the channels it leaves worse on held-out runs, by
//! [`crate::diagnose::report::Shrinkage::change`], and those whose gap it
//! leaves nearly whole, [`left`]; a base that is no tyre
//! alone), the threshold of no significant gap, why the base is not
//! identifiable, or the best candidate and every rule it fails. Typed; the
//! report words it. Units: J dimensionless, reductions in percent, RMS in
//! the channel's unit.

use crate::diagnose::base::identify::NoTyre;
use crate::diagnose::effects::{same_effects, Bound, EffectKind};
use crate::diagnose::report::above_noise;
use crate::diagnose::report::outcome::{EXPLAINS_MOST, FAR_FROM_OFF};
use crate::diagnose::report::{
    ChannelChange, ChannelLeft, ChannelWorsened, Closest, Evidence, Explained, FarFromOff,
    NoSignificantGap, NotIdentifiable, OutsideLibrary, PairsFallback, ParameterValue, Parsimony,
    Part, RankWarning, Ranked, Searched, Shrinkage, Verdict, VerdictKind, VerdictWarning,
};
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::calibration::calibration_evidence;
use crate::diagnose::verdict::rules::{self, ACCEPT, SIGNIFICANT};
use crate::diagnose::verdict::score::{Calibrated, Scored};
use crate::diagnose::verdict::search::Search;

/// The verdict of a search `found` over the cross-validated `singles`
/// (`order` ranks them, best first), on a gap that is `significant` or
/// not; `shrinkage` is before and after on held-out runs, `base_no_tyre`
/// why the base alone is no tyre (empty for a tyre).
pub(crate) fn verdict(
    found: &Search,
    (singles, order): (&[Scored], &[usize]),
    base: &Baseline,
    significant: bool,
    shrinkage: &[Shrinkage],
    base_no_tyre: &[NoTyre],
    calibrated: &Calibrated,
) -> Verdict {
    let (heldout_error, noise_level) = (base.j0, base.jn);
    let kind = rules::case(
        found.chosen.is_some(),
        significant,
        !base_no_tyre.is_empty(),
    );
    match (kind, &found.chosen) {
        (VerdictKind::Explained, Some(sc)) => {
            let r = base.rank(sc);
            let mut warnings = worsened(shrinkage);
            warnings.extend(left(shrinkage));
            let on_bound = on_search_bound(&r.parameters);
            if !on_bound.is_empty() {
                warnings.push(VerdictWarning::OnSearchBound {
                    parameters: on_bound,
                });
            }
            warnings.extend(remains(&r, noise_level));
            let mut evidence = calibration_evidence(&r.parameters, calibrated);
            // Accepted, its axles are a tyre (a set whose are not is never
            // chosen): where the base's alone are not, the effects account
            // for what bent them.
            if !base_no_tyre.is_empty() {
                evidence.push(Evidence::AxlesRestored {
                    no_tyre: base_no_tyre.to_vec(),
                });
            }
            evidence.extend(chosen_over(found, singles, base, &r));
            evidence.extend(fallback(found, singles, base));
            Verdict::Explained(Explained {
                evidence,
                effects: r.effects,
                parameters: r.parameters,
                heldout_error_before: heldout_error,
                heldout_error_after: r.heldout_error_after,
                noise_level,
                reduction_percent: r.reduction_percent,
                warnings,
                // Its look-alikes are the report's `confounded`, found
                // after the verdict (`pipeline` fills them in).
                confounded_with: None,
                in_set: Vec::new(),
            })
        }
        (VerdictKind::NoSignificantGap, _) => Verdict::NoSignificantGap(NoSignificantGap {
            heldout_error,
            noise_level,
            threshold: SIGNIFICANT,
            // Named by the pipeline, which has the channels' trust.
            resting_on: Vec::new(),
            assumed: Vec::new(),
            far_from_off: far_from_off(
                order.iter().map(|&i| base.rank(&singles[i])),
                heldout_error,
            ),
        }),
        (VerdictKind::NotIdentifiable, _) => Verdict::NotIdentifiable(NotIdentifiable {
            heldout_error,
            noise_level,
            no_tyre: base_no_tyre.to_vec(),
            threshold_percent: 100.0 * ACCEPT,
            // Named by the pipeline, which has the campaign.
            road_friction: None,
            // Named by the pipeline, which has the campaign's prior.
            tyre_class: None,
            closest: closest(
                order
                    .iter()
                    .map(|&i| base.rank(&singles[i]))
                    .chain(found.combinations.iter().cloned()),
            ),
        }),
        _ => Verdict::OutsideLibrary(OutsideLibrary {
            heldout_error,
            noise_level,
            // The best single on held-out runs (the ranking's first), and
            // every rule it fails; where it fails none, the search went on
            // from a simpler one in its place or ended on a set that failed.
            refused: order.first().map(|&i| {
                let gave_way = if found.passed_over == Some(i) {
                    Some(rules::GaveWay::Pressed)
                } else {
                    found
                        .start
                        .is_some_and(|s| s != i)
                        .then_some(rules::GaveWay::Idle)
                };
                base.refused(&singles[i], gave_way, found.ended.clone())
            }),
            threshold_percent: 100.0 * ACCEPT,
            tyre_class: None,
        }),
    }
}

/// Of the candidates `ranked` that lower the held-out error below
/// `before`, the one whose parameter lies farthest from its off value in
/// standard errors, where that is at least [`FAR_FROM_OFF`]: on a gap
/// within noise the rule weighs no candidate, and the words say what one
/// found. Parameters on a bound, held, or not determined are not counted.
fn far_from_off(ranked: impl Iterator<Item = Ranked>, before: f64) -> Option<FarFromOff> {
    let mut best: Option<FarFromOff> = None;
    for r in ranked.filter(|r| r.heldout_error_after < before) {
        for p in r.parameters.iter().filter(|p| {
            p.determined && p.bound.is_none() && p.held.is_none() && !p.unseen && p.std_error > 0.0
        }) {
            let Some(q) = r.effects.iter().find_map(|e| {
                e.parameters()
                    .iter()
                    .find(|q| format!("{}.{}", e.name(), q.name) == p.name)
            }) else {
                continue;
            };
            let z = (p.value - q.off).abs() / p.std_error;
            if z >= FAR_FROM_OFF && best.as_ref().is_none_or(|b| z > b.standard_errors) {
                best = Some(FarFromOff {
                    effects: r.effects.clone(),
                    parameter: p.clone(),
                    off: q.off,
                    standard_errors: z,
                    heldout_error_after: r.heldout_error_after,
                });
            }
        }
    }
    best
}

/// What the verdict (its `effects`) was chosen over on the way: a best
/// single pressed on its search bound, passed over for a look-alike inside
/// its ranges (unless a search from that best, unpressed in a set,
/// replaced the one from the look-alike), and each candidate passed over
/// for a simpler one within the parsimony window whose effects the verdict
/// does not take in after all, unless the pressed one already names it.
fn chosen_over(
    found: &Search,
    singles: &[Scored],
    base: &Baseline,
    verdict: &Ranked,
) -> Vec<Evidence> {
    let mut out = Vec::new();
    let effects = &verdict.effects;
    if let Some(i) = found
        .passed_over
        .filter(|&i| !effects.contains(&singles[i].kinds[0]))
    {
        let p = base.rank(&singles[i]);
        let pressed = on_search_bound(&p.parameters);
        let units: Vec<&str> = pressed.iter().map(|v| v.unit).collect();
        let inside = (verdict.parameters.iter()).filter(|v| units.contains(&v.unit));
        out.push(Evidence::LookalikePressed {
            pressed_ranges: searched(&p.effects, pressed.iter()),
            verdict_inside: searched(effects, inside),
            pressed,
            effects: p.effects,
            reduction_percent: p.reduction_percent,
        });
    }
    for s in &found.simpler {
        let contained = s.over.kinds.iter().all(|e| effects.contains(e));
        let named = out.iter().any(|e| {
            matches!(e, Evidence::LookalikePressed { effects: p, .. } if same_effects(p, &s.over.kinds))
        });
        if contained || named {
            continue;
        }
        let (o, t) = (base.rank(&s.over), base.rank(&s.taken));
        out.push(Evidence::ChosenForParsimony(Parsimony {
            idle: base.idle_values(&s.over),
            effects: o.effects,
            reduction_percent: o.reduction_percent,
            heldout_error: o.heldout_error_after,
            free_parameters: s.over.full.free_count(),
            taken: t.effects,
            taken_reduction_percent: t.reduction_percent,
            taken_heldout_error: t.heldout_error_after,
            taken_free_parameters: s.taken.full.free_count(),
            noise_level: base.jn,
            window_noise_levels: rules::PARSIMONY,
        }));
    }
    out
}

/// The parameters `values` of `effects` with the ranges their fits
/// searched (a value whose name no effect's parameter has is left out).
fn searched<'a>(
    effects: &[EffectKind],
    values: impl Iterator<Item = &'a ParameterValue>,
) -> Vec<Searched> {
    values
        .filter_map(|v| {
            let range = effects.iter().find_map(|e| {
                e.parameters()
                    .iter()
                    .find(|q| v.name == format!("{}.{}", e.name(), q.name))
                    .map(|q| q.bounds)
            })?;
            Some(Searched {
                name: v.name.clone(),
                unit: v.unit,
                value: v.value,
                range,
            })
        })
        .collect()
}

/// Where the verdict was reached from a pair of the best singles in
/// sample: the greedy search's start and the set it ended on, the pair,
/// and the start where the pair leaves it out.
fn fallback(found: &Search, singles: &[Scored], base: &Baseline) -> Option<Evidence> {
    let (f, start) = (found.fallback.as_ref()?, found.start?);
    let start = base.rank(&singles[start]);
    let (ended, pair) = (base.rank(&f.ended), base.rank(&f.pair));
    let first = start.effects[0];
    Some(Evidence::PairsFallback(PairsFallback {
        start: first,
        start_reduction_percent: start.reduction_percent,
        ended: ended.effects,
        ended_reduction_percent: ended.reduction_percent,
        threshold_percent: 100.0 * ACCEPT,
        paired_from: f.from.clone(),
        passed_over: (!pair.effects.contains(&first)).then_some(first),
        pair: pair.effects,
        pair_reduction_percent: pair.reduction_percent,
    }))
}

/// The gap a verdict that explains most of it (`ranked`) leaves above the
/// noise level `noise_level`, where that rest is itself significant
/// ([`rules::significant`]).
fn remains(ranked: &Ranked, noise_level: f64) -> Option<VerdictWarning> {
    let most = ranked.reduction_percent >= EXPLAINS_MOST;
    (most && rules::significant(ranked.heldout_error_after, noise_level)).then_some(
        VerdictWarning::GapRemains {
            heldout_error_after: ranked.heldout_error_after,
            noise_level,
            threshold: rules::SIGNIFICANT,
            left_percent: 100.0 - ranked.reduction_percent,
        },
    )
}

/// How many of the candidates whose axles are a tyre a not-identifiable
/// verdict names.
pub(crate) const CLOSEST: usize = 3;

/// Of the candidate rows `rows` (singles and sets, as ranked), those whose
/// jointly fitted axles are a tyre (no [`RankWarning::AxlesNoTyre`]), best
/// held-out first, at most [`CLOSEST`], each set once.
pub(crate) fn closest(rows: impl Iterator<Item = Ranked>) -> Vec<Closest> {
    let mut tyres: Vec<Ranked> = rows
        .filter(|r| {
            !r.warnings
                .iter()
                .any(|w| matches!(w, RankWarning::AxlesNoTyre { .. }))
        })
        .collect();
    tyres.sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    let mut out: Vec<Closest> = Vec::new();
    for r in tyres {
        let seen = out.iter().any(|c| same_effects(&c.effects, &r.effects));
        if !seen && out.len() < CLOSEST {
            out.push(Closest {
                effects: r.effects,
                reduction_percent: r.reduction_percent,
            });
        }
    }
    out
}

/// The parameters of `p` on the end of their search range.
pub(crate) fn on_search_bound(p: &[ParameterValue]) -> Vec<ParameterValue> {
    p.iter()
        .filter(|v| v.at_bound && v.bound == Some(Bound::Search))
        .cloned()
        .collect()
}

/// The channels the verdict's effects leave worse on held-out runs (all
/// samples): a worsening by [`Shrinkage::change`], above noise.
pub(crate) fn worsened(shrinkage: &[Shrinkage]) -> Vec<VerdictWarning> {
    shrinkage
        .iter()
        .filter(|s| s.part == Part::All)
        .filter_map(|s| match s.change() {
            ChannelChange::Worsened(added_percent) => {
                Some(VerdictWarning::ChannelWorsened(ChannelWorsened {
                    channel: s.channel,
                    before: s.before,
                    after: s.after,
                    noise_floor: s.noise_floor,
                    added_percent,
                }))
            }
            _ => None,
        })
        .collect()
}

/// The channels whose held-out gap (all samples) the verdict's effects
/// leave: above noise before and after, less than [`ACCEPT`] of its gap
/// above noise removed, and not worsened (that is its own warning). The
/// combined error that accepted the effects can fall through one channel
/// while another's gap stays: a verdict that "explains the gap" must not
/// hide it.
pub(crate) fn left(shrinkage: &[Shrinkage]) -> Vec<VerdictWarning> {
    let acceptance_percent = 100.0 * ACCEPT;
    shrinkage
        .iter()
        .filter(|s| s.part == Part::All)
        .filter(|s| above_noise(s.before, s.noise_floor) && above_noise(s.after, s.noise_floor))
        .filter_map(|s| match s.change() {
            ChannelChange::Changed(removed) if removed < acceptance_percent => {
                Some(VerdictWarning::ChannelLeft(ChannelLeft {
                    channel: s.channel,
                    before: s.before,
                    after: s.after,
                    noise_floor: s.noise_floor,
                    removed_percent: removed,
                    acceptance_percent,
                }))
            }
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::model::channels::Channel;

    fn offset(name: &str, value: f64, std_error: f64) -> ParameterValue {
        ParameterValue::plain(name, "m/s²", value, std_error)
    }

    #[test]
    fn only_a_parameter_on_its_search_bound_is_warned_of_not_one_on_a_physical_limit() {
        let at = |bound: Option<Bound>| ParameterValue {
            at_bound: bound.is_some(),
            bound,
            ..offset("x", 0.3, 0.01)
        };
        let p = [at(Some(Bound::Search)), at(Some(Bound::Physical)), at(None)];
        assert_eq!(on_search_bound(&p), vec![p[0].clone()]);
    }

    #[test]
    fn a_rest_above_the_significance_threshold_is_warned_of_only_where_the_sentence_does_not_say_it(
    ) {
        let with = |j: f64, reduction: f64| {
            let mut r = row(&[EffectKind::SensorDelay], j, true);
            r.reduction_percent = reduction;
            remains(&r, 1.0)
        };
        // J 1.366 against noise 1.000: above 1.3 × the noise level.
        let Some(VerdictWarning::GapRemains {
            heldout_error_after,
            threshold,
            left_percent,
            ..
        }) = with(1.366, 84.0)
        else {
            panic!("no warning at J 1.366");
        };
        assert_eq!((heldout_error_after, threshold), (1.366, SIGNIFICANT));
        assert!((left_percent - 16.0).abs() < 1e-12);
        // At the threshold and below it, the rest is noise.
        assert!(with(1.3, 84.0).is_none() && with(1.1, 90.0).is_none());
        // A verdict that explains part of the gap says the rest in its
        // sentence: no second word.
        assert!(with(2.5, 49.9).is_none());
        assert!(with(2.5, EXPLAINS_MOST).is_some());
    }

    /// A ranking row of `effects` with held-out error `j` (base 4, noise
    /// 1), its axles a tyre or not.
    fn row(effects: &[EffectKind], j: f64, tyre: bool) -> Ranked {
        let no_tyre = vec![NoTyre::Limit {
            parameter: "rear cornering coefficient",
            limit: crate::diagnose::report::AxleLimit::Rigid,
        }];
        Ranked {
            effect: crate::diagnose::effects::joined(effects, "+"),
            effects: effects.to_vec(),
            axles: None,
            prior_weight: None,
            parameters: Vec::new(),
            heldout_error_before: 4.0,
            heldout_error_after: j,
            heldout_channels: Vec::new(),
            reduction_percent: 100.0 * (4.0 - j) / 3.0,
            insample_error_after: j,
            insample_reduction_percent: 100.0 * (4.0 - j) / 3.0,
            folds_converged: 8,
            folds: 8,
            warnings: if tyre {
                Vec::new()
            } else {
                vec![RankWarning::AxlesNoTyre { no_tyre }]
            },
            bic: 0.0,
            delta_bic: 0.0,
            global_search: crate::diagnose::fit::GlobalSearch::None,
        }
    }

    #[test]
    fn the_closest_are_the_candidates_whose_axles_are_a_tyre_best_held_out_first_each_set_once() {
        use EffectKind::{RoadBank, SensorBias, SensorDelay, SteerPath, YawInertia};
        let rows = vec![
            // The best on held-out runs, but its axles are no tyre.
            row(&[RoadBank], 2.0, false),
            row(&[SensorDelay], 3.5, true),
            row(&[SensorBias, SteerPath], 3.2, true),
            // The same set in the other order: said once.
            row(&[SteerPath, SensorBias], 3.3, true),
            row(&[YawInertia], 3.9, true),
            row(&[SteerPath], 3.6, true),
        ];
        let c = closest(rows.into_iter());
        let named: Vec<&[EffectKind]> = c.iter().map(|c| c.effects.as_slice()).collect();
        assert_eq!(
            named,
            [&[SensorBias, SteerPath][..], &[SensorDelay], &[SteerPath]]
        );
        assert_eq!(c.len(), CLOSEST);
        assert!((c[0].reduction_percent - 80.0 / 3.0).abs() < 1e-9);
        // None whose axles are a tyre: none named.
        assert!(closest(vec![row(&[RoadBank], 2.0, false)].into_iter()).is_empty());
    }

    fn shrink(channel: Channel, part: Part, before: f64, after: f64, floor: f64) -> Shrinkage {
        Shrinkage {
            channel,
            part,
            samples: 1000,
            before,
            after,
            noise_floor: floor,
            reduction_percent: crate::diagnose::model::channels::reduction(before, after, floor),
            mean_level: None,
            runs: Vec::new(),
        }
    }

    #[test]
    fn a_channel_whose_gap_the_effects_leave_is_warned_of_and_not_one_within_noise_or_explained() {
        use Channel::{Ay, Beta, YawRate};
        // The sedan analogue: ay and beta fall by 61 % and 84 %, the yaw
        // rate 10× its noise floor before and after.
        let rows = [
            shrink(YawRate, Part::All, 0.0247, 0.0216, 0.0020),
            shrink(Ay, Part::All, 0.446, 0.184, 0.059),
            shrink(Beta, Part::All, 0.0147, 0.0032, 0.0022),
            // Another part's rows are not the channel's verdict.
            shrink(Ay, Part::Ay { lo: 4.0, hi: 6.0 }, 0.5, 0.5, 0.059),
        ];
        let w = left(&rows);
        assert_eq!(w.len(), 1, "{w:?}");
        let VerdictWarning::ChannelLeft(c) = &w[0] else {
            panic!("{w:?}")
        };
        assert_eq!(c.channel, YawRate);
        assert!(
            (c.removed_percent - 12.64).abs() < 0.01,
            "{}",
            c.removed_percent
        );
        assert_eq!(c.acceptance_percent, 30.0);
        // Just at the acceptance: explained; just below: left.
        let floor = 0.002;
        let at = |removed: f64| {
            let before: f64 = 0.02;
            let gap = (before * before - floor * floor).sqrt() * (1.0 - removed);
            shrink(
                YawRate,
                Part::All,
                before,
                (gap * gap + floor * floor).sqrt(),
                floor,
            )
        };
        assert!(left(&[at(0.301)]).is_empty());
        assert_eq!(left(&[at(0.299)]).len(), 1);
        // Within noise after: nothing left; a worsening is its own warning.
        assert!(left(&[shrink(Beta, Part::All, 0.0147, 0.0021, 0.0022)]).is_empty());
        let grown = shrink(Beta, Part::All, 0.0147, 0.0200, 0.0022);
        assert!(left(std::slice::from_ref(&grown)).is_empty());
        assert_eq!(worsened(&[grown]).len(), 1);
    }
}
