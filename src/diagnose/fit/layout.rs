//! What a fit's parameter vector is and sets ([`Layout`]): the blocks
//! `[axles | effects | roll]` — the axle characteristics of an identified
//! base ([`crate::diagnose::base::identify`]) first when they are fitted,
//! then each candidate effect's parameters in order, then the roll
//! dynamics ([`RollDynamics`]) when a roll effect is among them — with the
//! offsets of every block and effect (the only place they are computed),
//! and the model a vector sets: the base model's effects with each
//! effect's [`crate::diagnose::effects::Effect::apply`] on top, written
//! once for any scalar, so that the plain model of a vector
//! ([`Layout::model`]) and its dual twin ([`crate::diagnose::fit::tangent`])
//! are the same arithmetic. Units: SI, rad.

use crate::diagnose::effects::{EffectKind, Group, Parameter, RollDynamics};
use crate::diagnose::model::axles::{axle_tyres, AXLE_BOUNDS};
use crate::diagnose::model::Augmented;
use crate::scalar::Scalar;
use crate::vehicle::Effects;
use std::ops::Range;

/// The layout of a fit's parameter vector: the axle characteristics first
/// when they are fitted (`axle`), then each effect's parameters in `kinds`
/// order, then the roll dynamics when a roll effect is among them.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The effects fitted, in vector order.
    pub kinds: Vec<EffectKind>,
    /// Whether the axle characteristics lead the vector.
    pub axle: bool,
}

impl Layout {
    /// The layout of `kinds`, after the axle characteristics when `axle`.
    pub fn new(kinds: &[EffectKind], axle: bool) -> Self {
        Self {
            kinds: kinds.to_vec(),
            axle,
        }
    }

    /// The number of axle characteristics leading the vector (0 or 3).
    pub fn axle_count(&self) -> usize {
        if self.axle {
            AXLE_BOUNDS.len()
        } else {
            0
        }
    }

    /// Whether the vector carries the roll dynamics (a roll effect is
    /// among the effects).
    pub fn fits_roll(&self) -> bool {
        self.kinds.iter().any(|e| e.uses_roll())
    }

    /// Where the axle characteristics are (empty when not fitted).
    pub fn axles(&self) -> Range<usize> {
        0..self.axle_count()
    }

    /// Where the effects' parameters are (all of them, in order).
    pub fn effects(&self) -> Range<usize> {
        let start = self.axle_count();
        let n: usize = self.kinds.iter().map(|e| e.parameters().len()).sum();
        start..start + n
    }

    /// Where effect `i` (of `kinds`) has its parameters.
    pub fn effect(&self, i: usize) -> Range<usize> {
        let start = self.axle_count()
            + self.kinds[..i]
                .iter()
                .map(|e| e.parameters().len())
                .sum::<usize>();
        start..start + self.kinds[i].parameters().len()
    }

    /// The parameters a candidate's global stage searches: a single's after
    /// the axle characteristics (its own and the roll dynamics of a roll
    /// effect); a set's only the added (last) effect's own one to three. A
    /// combination's starts already carry the current set at its own fit
    /// and the added effect at its single fit, with the current set's
    /// effects off beside it (`search::extensions`), and the roll dynamics
    /// as its members fitted them: what is left unknown is where the added
    /// effect sits beside the set, a grid along its one to three parameters
    /// (the polish frees them all). A swarm over them and the roll dynamics
    /// spent 90–130 replays where a roll effect was in the set; over every
    /// effect parameter of the set, about 45 for the same optimum (the
    /// book's measured history).
    pub fn global_stage(&self) -> Range<usize> {
        match self.kinds.len() {
            0 | 1 => self.axle_count()..self.roll().end,
            n => self.effect(n - 1),
        }
    }

    /// Where a set's restricted fit (Levenberg–Marquardt with the members
    /// before the added effect held) starts freeing parameters: after the
    /// axle characteristics for a single effect; for a combination, at the
    /// added (last) effect, so that its parameters and the roll dynamics
    /// after them are fitted.
    pub fn restricted_from(&self) -> usize {
        match self.kinds.len() {
            0 | 1 => self.axle_count(),
            n => self.effect(n - 1).start,
        }
    }

    /// Whether each entry of the vector only adds a constant to a measured
    /// channel ([`Parameter::additive`]; no axle characteristic does): its
    /// second derivatives are all zero.
    pub fn additive(&self) -> Vec<bool> {
        let mut marks = vec![false; self.axle_count()];
        marks.extend(self.parameters().map(|(_, q)| q.additive));
        marks
    }

    /// Where the roll dynamics are (empty when not fitted).
    pub fn roll(&self) -> Range<usize> {
        let end = self.effects().end;
        let n = if self.fits_roll() {
            RollDynamics::PARAMETERS.len()
        } else {
            0
        };
        end..end + n
    }

    /// The parameters after the axle characteristics, in vector order,
    /// each with its group (the effect's, or the roll dynamics').
    pub fn parameters(&self) -> impl Iterator<Item = (Group, &'static Parameter)> + '_ {
        let roll = if self.fits_roll() {
            RollDynamics::PARAMETERS
        } else {
            &[]
        };
        self.kinds
            .iter()
            .flat_map(|&e| e.parameters().iter().map(move |q| (Group::Effect(e), q)))
            .chain(roll.iter().map(|q| (Group::Roll, q)))
    }

    /// The effects vector `p` sets on `base` (the base model's effects), in
    /// the scalar of `p`: each effect applied in order, then the roll
    /// dynamics.
    pub fn effects_of<T: Scalar>(&self, base: &Effects, p: &[T]) -> Effects<T> {
        let mut e = base.lift::<T>();
        for (i, kind) in self.kinds.iter().enumerate() {
            kind.apply(&p[self.effect(i)], &mut e);
        }
        if self.fits_roll() {
            RollDynamics::apply(&p[self.roll()], &mut e);
        }
        e
    }

    /// The model of vector `p` on `base`: the axle characteristics (when
    /// fitted) as its tyres, the effects set on the base model's.
    pub fn model(&self, base: &Augmented, p: &[f64]) -> Augmented {
        let mut m = base.clone();
        if self.axle {
            (m.model.front, m.model.rear) = axle_tyres(&p[self.axles()]);
        }
        m.model.options.effects = self.effects_of(base.effects(), p);
        m
    }

    /// The start of this layout with `added` appended, from a vector `p`
    /// of this layout and a vector `q` of `added` alone (same axles): the
    /// axle characteristics and effect values of `p`, the added effect's
    /// values from `q`, and the roll dynamics from whichever of the two
    /// fits them (`p` first).
    pub fn combined(&self, p: &[f64], added: EffectKind, q: &[f64]) -> Vec<f64> {
        let single = Layout::new(&[added], self.axle);
        let mut start = p[..self.effects().end].to_vec();
        start.extend(&q[single.effect(0)]);
        if self.fits_roll() {
            start.extend(&p[self.roll()]);
        } else {
            start.extend(&q[single.roll()]);
        }
        start
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_blocks_follow_each_other() {
        use EffectKind::{RoadBank, RollSteer, SensorBias};
        let l = Layout::new(&[SensorBias, RollSteer, RoadBank], true);
        assert_eq!(l.axles(), 0..3);
        assert_eq!((l.effect(0), l.effect(1), l.effect(2)), (3..6, 6..8, 8..9));
        assert_eq!((l.effects(), l.roll()), (3..9, 9..11));
        let names: Vec<&str> = l.parameters().map(|(g, _)| g.name()).collect();
        assert_eq!(names[names.len() - 3..], ["road_bank", "roll", "roll"]);
        let plain = Layout::new(&[RoadBank], false);
        assert_eq!(
            (plain.axles(), plain.effects(), plain.roll()),
            (0..0, 0..1, 1..1)
        );
        // A roll effect added to a set without one brings its dynamics.
        let p = [0.5, 0.5, 0.5, 0.03];
        let q = [0.6, 0.6, 0.6, -0.1, 0.1, 1.2, 0.7];
        let start = Layout::new(&[RoadBank], true).combined(&p, RollSteer, &q);
        assert_eq!(start, [0.5, 0.5, 0.5, 0.03, -0.1, 0.1, 1.2, 0.7]);
        // A set with roll keeps its own.
        let p2 = [0.5, 0.5, 0.5, -0.1, 0.1, 1.5, 0.5];
        let q2 = [0.6, 0.6, 0.6, 0.02];
        let start = Layout::new(&[RollSteer], true).combined(&p2, RoadBank, &q2);
        assert_eq!(start, [0.5, 0.5, 0.5, -0.1, 0.1, 0.02, 1.5, 0.5]);
    }

    #[test]
    fn a_single_searches_after_the_axles_and_a_set_only_the_effect_it_adds() {
        use EffectKind::{RelaxationLength, SensorDelay, SteerPath};
        let axles = Layout::new(&[SteerPath], true).axle_count();
        assert_eq!(Layout::new(&[SteerPath], true).restricted_from(), axles);
        assert_eq!(Layout::new(&[SteerPath], false).restricted_from(), 0);
        // The steer path's delay and lag come first; the sensor delay after.
        let set = Layout::new(&[SteerPath, SensorDelay], true);
        assert_eq!(set.restricted_from(), axles + 2);
        assert_eq!(set.global_stage(), axles + 2..axles + 3);
        let set = Layout::new(&[SensorDelay, SteerPath, RelaxationLength], false);
        assert_eq!(set.restricted_from(), 3);
    }

    #[test]
    fn a_sets_global_stage_holds_the_roll_dynamics_its_members_fitted() {
        use EffectKind::{RollSteer, SteerPath};
        let single = Layout::new(&[RollSteer], true);
        assert_eq!(
            single.global_stage(),
            single.axle_count()..single.roll().end
        );
        assert!(single.global_stage().contains(&single.roll().start));
        let set = Layout::new(&[RollSteer, SteerPath], true);
        assert_eq!(set.global_stage(), set.effect(1));
        assert_eq!(set.global_stage().len(), 2);
        assert!(!set.global_stage().contains(&set.roll().start));
    }
}
