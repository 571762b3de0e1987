//! The diagnosis's conclusion once the search has run: the verdict's
//! look-alikes (confounded where the runs do not tell them apart, unless
//! the verdict's set, fitted with one in its first effect's place, does
//! clearly worse, or the standstills contradict its bank:
//! [`crate::diagnose::verdict::standstills`]), and the verdict made from the search, the ranked
//! singles and the held-out shrinkage ([`crate::diagnose::verdict::conclude`]).

use crate::diagnose::campaign::{Campaign, StatedFriction};
use crate::diagnose::effects::EffectKind;
use crate::diagnose::report::{
    Confounded, Evidence, InSet, MassAlike, Narrowed, NotIdentifiable, OutsideLibrary,
    ParameterValue, Ranked, Shrinkage, Verdict, VerdictWarning,
};
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::class::class_mismatch;
use crate::diagnose::verdict::conclude::verdict;
use crate::diagnose::verdict::rules::ACCEPT;
use crate::diagnose::verdict::score::{Context, Scored};
use crate::diagnose::verdict::search::{lookalikes_alone, Search};
use crate::diagnose::verdict::standstills::set_aside;
use crate::diagnose::verdict::twins::{confounded_with, in_set};

/// The verdict, the groups of look-alikes it is confounded with, and the
/// look-alikes fitted in its set ([`in_set`]) with their rows.
pub(super) struct Concluded {
    pub(super) verdict: Verdict,
    pub(super) confounded: Vec<Confounded>,
    pub(super) swapped: Vec<(InSet, Option<Ranked>)>,
}

/// The conclusion of a search `found` over the `singles` (cross-validated
/// ones best first, `order`) against the base model `base` (`significant`:
/// its gap is above noise), with the verdict's held-out `shrinkage`.
pub(super) fn conclude(
    ctx: &Context,
    c: &Campaign,
    found: &Search,
    (singles, order): (&[Scored], &[usize]),
    (base, significant): (&Baseline, bool),
    shrinkage: &[Shrinkage],
) -> Concluded {
    let chosen = found.chosen.as_ref();
    let mut confounded = chosen.map_or_else(Vec::new, |sc| {
        confounded_with(sc, singles, (&found.lookalikes, found.grown_from), base)
    });
    // A set's look-alikes fitted in it: their rows join the combinations,
    // and those the set tells apart are confounded no longer.
    let swapped = chosen.map_or_else(Vec::new, |sc| {
        in_set(ctx, sc, singles, &confounded, base, &found.combinations)
    });
    told_apart(&mut confounded, &swapped);
    let base_no_tyre = ctx
        .bases
        .identification
        .as_ref()
        .map_or_else(Vec::new, |i| i.no_tyre.clone());
    let mut verdict = verdict(
        found,
        (singles, order),
        base,
        significant,
        shrinkage,
        &base_no_tyre,
        &ctx.calibrated,
    );
    from_campaign(&mut verdict, c);
    // Axles outside the stated tyre class but inside another's: the class
    // to check, not a model-form error outside the library.
    if let Verdict::NotIdentifiable(NotIdentifiable { tyre_class, .. })
    | Verdict::OutsideLibrary(OutsideLibrary { tyre_class, .. }) = &mut verdict
    {
        let identified = ctx.bases.identification.as_ref();
        let rows = order.iter().map(|&i| base.rank(&singles[i]));
        *tyre_class = class_mismatch(
            &c.prior,
            identified.map(|i| (&i.parameters[..], &i.no_tyre[..])),
            rows.chain(found.combinations.iter().cloned()),
            100.0 * ACCEPT,
        );
    }
    // The verdict is one of its look-alikes until a test separates them.
    if let Verdict::Explained(e) = &mut verdict {
        // Its own axles outside the stated class, inside another's.
        let own = chosen.map(|sc| base.rank(sc)).into_iter();
        let class = class_mismatch(&c.prior, None, own, f64::NEG_INFINITY);
        e.warnings.extend(class.map(VerdictWarning::TyreClass));
        e.evidence.extend(mass_alike(&e.parameters, c));
        // A set that took its twin's place: the window is its own first
        // single's, the single it was grown from a look-alike of it.
        let start = match (found.grown_from, chosen) {
            (Some(_), Some(sc)) => singles.iter().position(|s| s.kinds[0] == sc.kinds[0]),
            _ => found.start,
        };
        e.confounded_with = lookalikes_alone(singles, &confounded, start, base);
        e.in_set = swapped.iter().map(|(s, _)| s.clone()).collect();
        // A single's bank-like look-alike the standstills contradict is
        // set aside, not confounded (a set's look-alikes are judged in it).
        if let (Some(l), true) = (&mut e.confounded_with, e.in_set.is_empty()) {
            let alone = |k: EffectKind| {
                let s = singles.iter().find(|s| s.kinds[0] == k)?;
                Some(base.rank(s).parameters)
            };
            set_aside(l, &mut confounded, &e.parameters, alone, &ctx.calibrated);
        }
    }
    Concluded {
        verdict,
        confounded,
        swapped,
    }
}

/// What of the campaign a verdict without an accepted effect names: the
/// stated road friction (a base that is no tyre) and the candidates
/// `[diagnose] effects` narrowed the library to. Apart from [`conclude`]
/// so that it reads on a screen.
fn from_campaign(verdict: &mut Verdict, c: &Campaign) {
    if let Verdict::NotIdentifiable(n) = verdict {
        n.road_friction = c.friction_at.map(|line| StatedFriction {
            value: c.friction,
            line,
        });
    }
    // A campaign that names its candidates tried only those: a gap none
    // of them explains is no model-form error outside the library.
    if let Verdict::NotIdentifiable(NotIdentifiable { narrowed, .. })
    | Verdict::OutsideLibrary(OutsideLibrary { narrowed, .. }) = verdict
    {
        *narrowed = Narrowed::of(c.settings.effects.as_ref().map(|_| &c.effects[..]));
    }
}

/// Where a verdict's `parameters` scale the yaw inertia, the vehicle mass
/// that fits the runs the same ([`MassAlike`]): the user checks the
/// vehicle file's mass as well as its yaw inertia.
fn mass_alike(parameters: &[ParameterValue], c: &Campaign) -> Option<Evidence> {
    let name = format!("{}.scale", EffectKind::YawInertia.name());
    let scale = parameters.iter().find(|p| p.name == name)?.value;
    let v = &c.vehicle;
    (scale > 0.0).then(|| {
        Evidence::MassAlike(MassAlike {
            scale,
            yaw_inertia: v.yaw_inertia,
            yaw_inertia_fitted: v.yaw_inertia * scale,
            mass: v.mass,
            mass_alike: v.mass / scale,
        })
    })
}

/// `rows` with the rows of the look-alikes fitted in the verdict's set
/// ([`in_set`]) that are not among them, ordered by held-out error.
pub(super) fn with_rows(mut rows: Vec<Ranked>, swapped: &[(InSet, Option<Ranked>)]) -> Vec<Ranked> {
    rows.extend(swapped.iter().filter_map(|(_, r)| r.clone()));
    rows.sort_by(|a, b| a.heldout_error_after.total_cmp(&b.heldout_error_after));
    rows
}

/// Drops from `confounded` the look-alikes the verdict's set tells apart
/// ([`in_set`]: fitted in its first effect's place, the set does clearly
/// worse), and the group where one effect is left.
fn told_apart(confounded: &mut Vec<Confounded>, swapped: &[(InSet, Option<Ranked>)]) {
    let apart: Vec<EffectKind> = swapped
        .iter()
        .filter(|(s, _)| !s.confounded)
        .map(|(s, _)| s.effects[0])
        .collect();
    Confounded::without(confounded, &apart);
}

#[cfg(test)]
mod told_apart_tests {
    use super::*;
    use EffectKind::{AeroLoad as A, RoadFriction as F, SensorBias as B, SteerPath as S};

    #[test]
    fn a_look_alike_the_set_tells_apart_is_confounded_no_longer() {
        let row = |effects: Vec<EffectKind>, confounded| {
            let s = InSet {
                effects,
                reduction_percent: 50.0,
                gap: 1.0,
                window: crate::diagnose::verdict::rules::window(1.0, 1.0),
                confounded,
            };
            (s, None)
        };
        let group = || Confounded {
            effects: vec![A, S, F],
            reduction_percent: vec![90.0, 89.0, 88.0],
            separating_runs: None,
        };
        let mut c = vec![group()];
        told_apart(&mut c, &[row(vec![S, B], true), row(vec![F, B], false)]);
        assert_eq!(c[0].effects, [A, S]);
        assert_eq!(c[0].reduction_percent, [90.0, 89.0]);
        // Every look-alike told apart: no group is left.
        let mut c = vec![group()];
        told_apart(&mut c, &[row(vec![S, B], false), row(vec![F, B], false)]);
        assert!(c.is_empty());
    }
}
