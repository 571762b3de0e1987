//! Every number of a vehicle model and its effects that a fit may vary, in
//! a scalar of [`crate::scalar`] ([`ModelScalars`]): the right-hand side
//! ([`super::VehicleModel::rates`]) reads them from here, so that in dual
//! numbers it carries their derivatives; the rest of the model (mass,
//! geometry, options) stays plain. Units: SI, rad.

use super::effects::MIN_RELAXATION_LENGTH;
use super::VehicleModel;
pub use crate::scalar::{off, Scalar};

/// Every number of a vehicle model and its effects that a fit may vary, in
/// the scalar `T` ([`VehicleModel::scalars`] gives the model's own in
/// `f64`). Units as in [`super::Effects`] and [`super::Vehicle`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelScalars<T> {
    /// Yaw moment of inertia, kg·m².
    pub yaw_inertia: T,
    /// Front share χ of the lateral load transfer.
    pub transfer_share: T,
    /// Road friction as a scale on the tyres' own.
    pub friction: T,
    /// Aero load per speed squared (front, rear), N/(m/s)².
    pub aero_load: [T; 2],
    /// Constant road bank, rad.
    pub road_bank: T,
    /// Scale of the measured bank.
    pub bank_profile_scale: T,
    /// Relaxation length, m.
    pub relaxation_length: T,
    /// Steering compliance, rad/N.
    pub steering_compliance: T,
    /// Roll steer (front, rear), rad/rad.
    pub roll_steer: [T; 2],
    /// Roll camber thrust (front, rear), N/N per rad.
    pub roll_camber: [T; 2],
    /// Cornering-stiffness scales (front, rear).
    pub stiffness_scale: [T; 2],
    /// Share of the rigid longitudinal load transfer.
    pub longitudinal_load_transfer: T,
    /// Combined slip: drive front share, brake front share, force share.
    pub combined_slip: Option<[T; 3]>,
    /// Roll model: gradient (rad per m/s²), frequency (Hz), damping ratio.
    pub roll: [T; 3],
    /// The dual directions reserved for the load-transfer solve's lateral
    /// acceleration and a compliant front axle's slip angle (unused in
    /// plain numbers).
    pub directions: [usize; 2],
}

impl VehicleModel {
    /// The model's own [`ModelScalars`] on a road of friction `friction`.
    pub fn scalars(&self, friction: f64) -> ModelScalars<f64> {
        let e = &self.options.effects;
        ModelScalars {
            yaw_inertia: self.vehicle.yaw_inertia,
            transfer_share: self.vehicle.front_transfer_share(),
            friction,
            aero_load: e.aero_load,
            road_bank: e.road_bank,
            bank_profile_scale: e.bank_profile_scale,
            relaxation_length: e.relaxation_length,
            steering_compliance: e.steering_compliance,
            roll_steer: e.roll_steer,
            roll_camber: e.roll_camber,
            stiffness_scale: e.cornering_stiffness_scale,
            longitudinal_load_transfer: e.longitudinal_load_transfer,
            combined_slip: e
                .combined_slip
                .map(|c| [c.drive_front_share, c.brake_front_share, c.force_share]),
            roll: [e.roll.gradient, e.roll.frequency, e.roll.damping],
            directions: [0, 0],
        }
    }
}

impl ModelScalars<f64> {
    /// The same numbers in scalar `T`, as constants, with `directions`
    /// reserved for the implicit solves.
    pub fn lift<T: Scalar>(&self, directions: [usize; 2]) -> ModelScalars<T> {
        let l2 = |x: [f64; 2]| x.map(T::from);
        ModelScalars {
            yaw_inertia: T::from(self.yaw_inertia),
            transfer_share: T::from(self.transfer_share),
            friction: T::from(self.friction),
            aero_load: l2(self.aero_load),
            road_bank: T::from(self.road_bank),
            bank_profile_scale: T::from(self.bank_profile_scale),
            relaxation_length: T::from(self.relaxation_length),
            steering_compliance: T::from(self.steering_compliance),
            roll_steer: l2(self.roll_steer),
            roll_camber: l2(self.roll_camber),
            stiffness_scale: l2(self.stiffness_scale),
            longitudinal_load_transfer: T::from(self.longitudinal_load_transfer),
            combined_slip: self.combined_slip.map(|c| c.map(T::from)),
            roll: self.roll.map(T::from),
            directions,
        }
    }
}

impl<T: Scalar> ModelScalars<T> {
    /// The values without their derivatives.
    pub fn re(&self) -> ModelScalars<f64> {
        let re2 = |x: [T; 2]| [x[0].re(), x[1].re()];
        ModelScalars {
            yaw_inertia: self.yaw_inertia.re(),
            transfer_share: self.transfer_share.re(),
            friction: self.friction.re(),
            aero_load: re2(self.aero_load),
            road_bank: self.road_bank.re(),
            bank_profile_scale: self.bank_profile_scale.re(),
            relaxation_length: self.relaxation_length.re(),
            steering_compliance: self.steering_compliance.re(),
            roll_steer: re2(self.roll_steer),
            roll_camber: re2(self.roll_camber),
            stiffness_scale: re2(self.stiffness_scale),
            longitudinal_load_transfer: self.longitudinal_load_transfer.re(),
            combined_slip: self
                .combined_slip
                .map(|c| [c[0].re(), c[1].re(), c[2].re()]),
            roll: [self.roll[0].re(), self.roll[1].re(), self.roll[2].re()],
            directions: self.directions,
        }
    }

    /// The bank the model runs on with a measured bank `measured` (rad):
    /// [`super::Effects::bank`].
    pub(crate) fn bank(&self, measured: f64) -> T {
        if off(self.bank_profile_scale) {
            self.road_bank
        } else {
            self.road_bank + self.bank_profile_scale * measured
        }
    }

    /// Whether the slip angles lag ([`super::Effects::lagged`]).
    pub(crate) fn lagged(&self) -> bool {
        self.relaxation_length.re() >= MIN_RELAXATION_LENGTH
    }

    /// The longitudinal force per wheel (front, rear), N, of combined slip
    /// ([`super::CombinedSlip`]) for a car of mass `mass` at longitudinal
    /// acceleration `ax`: a share of `m·ax` split between the axles by the
    /// drive split or the brake balance, evenly between an axle's wheels.
    /// None when the tyres carry none of it (`force_share` 0), so that the
    /// model takes its pure-slip path bit for bit.
    pub(crate) fn wheel_forces(&self, mass: f64, ax: f64) -> Option<[T; 2]> {
        let [drive, brake, force_share] = self.combined_slip?;
        if off(force_share) {
            return None;
        }
        let share = if ax >= 0.0 { drive } else { brake };
        let total = force_share * mass * ax;
        Some([share * 0.5 * total, (T::from(1.0) - share) * 0.5 * total])
    }
}
