//! The axles' tyres as the right-hand side ([`super::VehicleModel::rates`])
//! evaluates them, in the scalar it runs in ([`super::scalar::Scalar`]):
//! in plain numbers the tyre models' own methods ([`PlainTyres`]); in dual
//! numbers their generic lateral force with the lateral parameter vectors
//! as scalars too ([`ParamTyres`]), so a fit of tyre parameters gets their
//! derivatives through the model. Every wheel of an axle carries the
//! axle's tyre, at no camber and no longitudinal slip. Units: SI, rad.

use super::scalar::Scalar;
use crate::tyre::{SlipOf, SlipState, Tyre, TyreModel};

/// Front and rear axle index.
pub(crate) const FRONT: usize = 0;
/// Rear axle index.
pub(crate) const REAR: usize = 1;

/// The axles' tyres in scalar `T`.
pub trait AxleTyres<T: Scalar>: Sync {
    /// The same tyres in plain numbers (what the implicit solves iterate).
    fn plain(&self) -> PlainTyres<'_>;

    /// `Fy/Fz` of axle `axle`'s tyre at slip angle `alpha`, friction scale
    /// `mu` and speed `speed` when its force is proportional to its load,
    /// else None ([`TyreModel::lateral_force_per_load`]).
    fn per_load(&self, axle: usize, alpha: T, mu: T, speed: f64) -> Option<T>;

    /// A wheel's lateral force at load `fz`, N.
    fn wheel(&self, axle: usize, alpha: T, fz: T, mu: T, speed: f64) -> T;

    /// The four wheels' lateral forces (FL, FR, RL, RR), N, at the axles'
    /// slip angles `alpha` (front, rear) and the loads `fz`: by default a
    /// [`AxleTyres::wheel`] each.
    fn wheels(&self, alpha: [T; 2], fz: [T; 4], mu: T, speed: f64) -> [T; 4] {
        std::array::from_fn(|i| self.wheel(i / 2, alpha[i / 2], fz[i], mu, speed))
    }

    /// The friction circle's radius per unit load
    /// ([`TyreModel::friction_coefficient`]).
    fn friction_coefficient(&self, axle: usize, fz: T, mu: T) -> T;
}

/// The model's tyres in plain numbers.
#[derive(Debug, Clone, Copy)]
pub struct PlainTyres<'a> {
    /// Front and rear tyre.
    pub tyres: [&'a Tyre; 2],
}

impl AxleTyres<f64> for PlainTyres<'_> {
    fn plain(&self) -> PlainTyres<'_> {
        *self
    }
    fn per_load(&self, axle: usize, alpha: f64, mu: f64, speed: f64) -> Option<f64> {
        self.tyres[axle].lateral_force_per_load(&SlipState {
            alpha,
            kappa: 0.0,
            fz: 1.0,
            camber: 0.0,
            mu_scale: mu,
            speed,
        })
    }
    fn wheel(&self, axle: usize, alpha: f64, fz: f64, mu: f64, speed: f64) -> f64 {
        self.tyres[axle].lateral_force(&SlipState {
            alpha,
            kappa: 0.0,
            fz,
            camber: 0.0,
            mu_scale: mu,
            speed,
        })
    }
    /// One call for the set ([`TyreModel::lateral_forces`]): a model that
    /// evaluates the four wheels together (PAC89, in SIMD lanes) does.
    fn wheels(&self, alpha: [f64; 2], fz: [f64; 4], mu: f64, speed: f64) -> [f64; 4] {
        let [front, rear] = self.tyres;
        front.lateral_forces(rear, &four_wheels(alpha, fz, mu, speed))
    }
    fn friction_coefficient(&self, axle: usize, fz: f64, mu: f64) -> f64 {
        self.tyres[axle].friction_coefficient(fz, mu)
    }
}

impl PlainTyres<'_> {
    /// [`AxleTyres::wheels`] with each force's first and second derivatives
    /// in its wheel's load (N/N, 1/N; [`Tyre::lateral_forces_in_load`]):
    /// None unless the model gives them (PAC89).
    #[inline]
    pub(crate) fn wheels_in_load(
        &self,
        alpha: [f64; 2],
        fz: [f64; 4],
        mu: f64,
    ) -> Option<[[f64; 4]; 3]> {
        let [front, rear] = self.tyres;
        front.lateral_forces_in_load(rear, alpha, fz, mu)
    }
}

/// The slip states of a car's four wheels (FL, FR, RL, RR) at the axles'
/// slip angles `alpha` and the loads `fz`.
#[inline]
fn four_wheels(alpha: [f64; 2], fz: [f64; 4], mu: f64, speed: f64) -> [SlipState; 4] {
    std::array::from_fn(|i| SlipState {
        alpha: alpha[i / 2],
        kappa: 0.0,
        fz: fz[i],
        camber: 0.0,
        mu_scale: mu,
        speed,
    })
}

/// The model's tyres with their lateral parameter vectors in scalar `T`
/// (the tyre's own values, or a fit's with their derivatives).
#[derive(Debug, Clone)]
pub struct ParamTyres<'a, T> {
    plain: PlainTyres<'a>,
    params: [Vec<T>; 2],
    proportional: [bool; 2],
}

impl<'a, T: Scalar> ParamTyres<'a, T> {
    /// The tyres `front` and `rear` (their values) with parameters
    /// `params` (front, rear; in the order of their lateral parameter
    /// vectors); None when a tyre's model has no generic force.
    pub fn new(front: &'a Tyre, rear: &'a Tyre, params: [Vec<T>; 2]) -> Option<Self> {
        let plain = PlainTyres {
            tyres: [front, rear],
        };
        for (tyre, p) in plain.tyres.iter().zip(&params) {
            let s = SlipOf {
                alpha: T::from(0.01),
                fz: T::from(1000.0),
                mu_scale: T::from(1.0),
                speed: 20.0,
            };
            tyre.lateral_force_of(p, &s)?;
            tyre.friction_coefficient_of(p, s.fz, s.mu_scale)?;
        }
        let proportional = plain.tyres.map(|t| {
            t.lateral_force_per_load(&SlipState::lateral(0.01, 1.0))
                .is_some()
        });
        Some(Self {
            plain,
            params,
            proportional,
        })
    }

    /// The tyres of `front` and `rear` with their own parameters as
    /// constants; None as [`ParamTyres::new`].
    pub fn constant(front: &'a Tyre, rear: &'a Tyre) -> Option<Self> {
        let own = |t: &Tyre| -> Option<Vec<T>> {
            Some(t.lateral_parameters()?.into_iter().map(T::from).collect())
        };
        Self::new(front, rear, [own(front)?, own(rear)?])
    }

    fn force(&self, axle: usize, alpha: T, fz: T, mu: T, speed: f64) -> T {
        let s = SlipOf {
            alpha,
            fz,
            mu_scale: mu,
            speed,
        };
        // Checked in `new`.
        self.plain.tyres[axle]
            .lateral_force_of(&self.params[axle], &s)
            .unwrap_or_else(|| T::from(f64::NAN))
    }
}

impl<T: Scalar> AxleTyres<T> for ParamTyres<'_, T> {
    fn plain(&self) -> PlainTyres<'_> {
        self.plain
    }
    fn per_load(&self, axle: usize, alpha: T, mu: T, speed: f64) -> Option<T> {
        self.proportional[axle].then(|| self.force(axle, alpha, T::from(1.0), mu, speed))
    }
    fn wheel(&self, axle: usize, alpha: T, fz: T, mu: T, speed: f64) -> T {
        self.force(axle, alpha, fz, mu, speed)
    }
    fn friction_coefficient(&self, axle: usize, fz: T, mu: T) -> T {
        self.plain.tyres[axle]
            .friction_coefficient_of(&self.params[axle], fz, mu)
            .unwrap_or_else(|| T::from(f64::NAN))
    }
}
