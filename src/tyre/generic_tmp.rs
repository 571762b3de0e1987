//! Temporary generic dispatch (replaced by the tyre dispatch's own).
use super::{LateralForceOf, Parameterised, SlipOf, Tyre};
use num_dual::DualNum;

impl Tyre {
    /// Generic lateral force.
    pub fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> Option<T> {
        match self {
            Tyre::MagicSimple(t) => Some(t.lateral_force_of(p, s)),
            Tyre::Linear(t) => Some(t.lateral_force_of(p, s)),
            Tyre::Gim(t) => Some(t.lateral_force_of(p, s)),
            _ => None,
        }
    }
    /// Generic friction coefficient.
    pub fn friction_coefficient_of<T: DualNum<f64> + Copy>(
        &self,
        p: &[T],
        _fz: T,
        mu: T,
    ) -> Option<T> {
        match self {
            Tyre::MagicSimple(_) => Some(p[2] * mu),
            Tyre::Linear(_) => Some(T::from(f64::INFINITY)),
            Tyre::Gim(_) => Some(p[2] * mu),
            _ => None,
        }
    }
    /// Lateral parameters.
    pub fn lateral_parameters(&self) -> Option<Vec<f64>> {
        match self {
            Tyre::MagicSimple(t) => Some(t.parameters()),
            Tyre::Linear(t) => Some(t.parameters()),
            Tyre::Gim(t) => Some(t.parameters()),
            _ => None,
        }
    }
}
