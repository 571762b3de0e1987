//! The numbers of a vehicle model that a fit may vary, in a scalar of
//! [`crate::scalar`] ([`ModelScalars`]): its [`Effects`] in that scalar,
//! and the vehicle numbers derived from them (the yaw inertia and the road
//! friction scaled, the front share of the load transfer). The right-hand
//! side ([`super::VehicleModel::rates`]) reads them from here, so that in
//! dual numbers it carries their derivatives; the rest of the model (mass,
//! geometry, options) stays plain. Units: SI, rad.

use super::{Effects, VehicleModel};
pub use crate::scalar::{off, Scalar};

/// The numbers of a vehicle model a fit may vary, in the scalar `T`
/// ([`VehicleModel::scalars`] gives the model's own in `f64`). Units as in
/// [`super::Effects`] and [`super::Vehicle`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelScalars<T> {
    /// The effects.
    pub effects: Effects<T>,
    /// Yaw moment of inertia (the vehicle's, scaled), kg·m².
    pub yaw_inertia: T,
    /// Front share χ of the lateral load transfer (the effects', else the
    /// vehicle's).
    pub transfer_share: T,
    /// Road friction as a scale on the tyres' own (the road's, scaled).
    pub friction: T,
    /// The dual directions reserved for the load-transfer solve's lateral
    /// acceleration and a compliant front axle's slip angle (unused in
    /// plain numbers).
    pub directions: [usize; 2],
    /// The wheel-load numbers that do not change within a run, computed
    /// once here, not at every right-hand side (the same operations, so
    /// the same values to the bit).
    pub(crate) loads: LoadConstants<T>,
}

/// The wheel-load numbers of [`super::VehicleModel::load_split_of`] and
/// the force balance that depend only on the vehicle and the transfer
/// share: static axle loads (N), lateral transfer per m/s² on each axle
/// (N per m/s², used with load transfer on), the track ratio and 1/m
/// (1/kg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LoadConstants<T> {
    pub(crate) static_axle: (f64, f64),
    pub(crate) transfer: (T, T),
    pub(crate) front_to_rear: f64,
    pub(crate) inv_mass: f64,
}

impl VehicleModel {
    /// The model's own [`ModelScalars`] on a road of friction `friction`.
    pub fn scalars(&self, friction: f64) -> ModelScalars<f64> {
        self.scalars_of(self.options.effects, friction, [0, 0])
    }

    /// The [`ModelScalars`] of this vehicle with `effects` (in scalar `T`)
    /// on a road of friction `friction`, with `directions` reserved for the
    /// implicit solves.
    pub fn scalars_of<T: Scalar>(
        &self,
        effects: Effects<T>,
        friction: f64,
        directions: [usize; 2],
    ) -> ModelScalars<T> {
        let v = &self.vehicle;
        let transfer_share = effects
            .transfer_share
            .unwrap_or_else(|| T::from(v.front_transfer_share()));
        let k = v.mass * v.cg_height;
        let loads = LoadConstants {
            static_axle: v.static_axle_loads(),
            transfer: (
                transfer_share * k / v.track_front,
                (T::from(1.0) - transfer_share) * k / v.track_rear,
            ),
            front_to_rear: v.track_front / v.track_rear,
            inv_mass: 1.0 / v.mass,
        };
        ModelScalars {
            yaw_inertia: effects.yaw_inertia_scale * v.yaw_inertia,
            transfer_share,
            friction: effects.friction_scale * friction,
            effects,
            directions,
            loads,
        }
    }
}

impl<T: Scalar> ModelScalars<T> {
    /// The longitudinal force per wheel (front, rear), N, of combined slip
    /// ([`super::CombinedSlip`]) for a car of mass `mass` at longitudinal
    /// acceleration `ax`: a share of `m·ax` split between the axles by the
    /// drive split or the brake balance, evenly between an axle's wheels.
    /// None when the tyres carry none of it (`force_share` 0), so that the
    /// model takes its pure-slip path bit for bit.
    pub(crate) fn wheel_forces(&self, mass: f64, ax: f64) -> Option<[T; 2]> {
        let c = self.effects.combined_slip?;
        if off(c.force_share) {
            return None;
        }
        let share = if ax >= 0.0 {
            c.drive_front_share
        } else {
            c.brake_front_share
        };
        let total = c.force_share * mass * ax;
        Some([share * 0.5 * total, (T::from(1.0) - share) * 0.5 * total])
    }
}
