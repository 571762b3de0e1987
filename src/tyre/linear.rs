//! Linear tyre `Fy = C_α·α`, `Mz = t_p·Fy`: the tyre of the textbook linear
//! bicycle model, used for closed-form checks. It has no friction limit, so
//! `mu_scale` does not act on it.
//!
//! Units: N/rad, m, rad. Signs as in `tyre/mod.rs`: `mz` has the sign of
//! `fy` at small slip (it turns the wheel back toward zero slip), so a
//! physical pneumatic trail `t_p` is positive (the contact patch's force
//! acts behind the wheel centre); `identify` fits it as the ratio of the
//! slopes of `mz` and `fy` at small slip (0.0285 m on one load of the
//! Hoosier rig file).

use super::{
    LateralForceOf, LoadNamed, LoadRange, Model, ModelParameters, Parameterised, SlipOf, SlipState,
    TyreForces, TyreModel,
};
use crate::error::ParamError;
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// Linear tyre parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Linear {
    /// Cornering stiffness C_α, N/rad (per wheel).
    pub cornering_stiffness: f64,
    /// Pneumatic trail, m.
    #[serde(default)]
    pub pneumatic_trail: f64,
}

impl Linear {
    /// A linear tyre with stiffness `c` (N/rad) and no trail.
    pub fn new(c: f64) -> Self {
        Self {
            cornering_stiffness: c,
            pneumatic_trail: 0.0,
        }
    }
    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("cornering_stiffness", self.cornering_stiffness)?;
        ParamError::finite("pneumatic_trail", self.pneumatic_trail)
    }
}

impl TyreModel for Linear {
    fn forces(&self, s: &SlipState) -> TyreForces {
        let fy = self.lateral_force(s);
        TyreForces {
            fx: 0.0,
            fy,
            mz: self.pneumatic_trail * fy,
        }
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        if s.fz <= 0.0 {
            0.0
        } else {
            self.cornering_stiffness * s.alpha
        }
    }
    /// A linear tyre does not saturate: no friction limit.
    fn friction_coefficient(&self, _fz: f64, _mu_scale: f64) -> f64 {
        f64::INFINITY
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        if fz <= 0.0 {
            0.0
        } else {
            self.cornering_stiffness
        }
    }
}

impl Parameterised for Linear {
    fn parameter_names(&self) -> Vec<&'static str> {
        vec!["cornering_stiffness"]
    }
    fn parameters(&self) -> Vec<f64> {
        vec![self.cornering_stiffness]
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.cornering_stiffness = p[0];
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![(1e3, 5e5)]
    }
}

impl LateralForceOf for Linear {
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        if s.fz <= 0.0 {
            T::from(0.0)
        } else {
            p[0] * s.alpha
        }
    }
    /// No friction limit: infinite, with zero derivatives.
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, _p: &[T], _fz: T, _mu_scale: T) -> T {
        T::from(f64::INFINITY)
    }
}

impl ModelParameters for Linear {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        Linear::validate(self)
    }
    fn check_sizes(&self) -> Result<(), ParamError> {
        super::sizes::cornering_stiffness("cornering_stiffness", self.cornering_stiffness)?;
        super::sizes::trail("pneumatic_trail", self.pneumatic_trail)
    }
    /// Its stiffness per unit of the wheel's static load, at least any
    /// tyre's ([`super::sizes::cornering_per_load`]): 1000 typed for a car
    /// tyre's 1000 N/deg gave 50 N of force at 4 kN.
    fn check_at_load(&self, load: LoadNamed) -> Result<(), ParamError> {
        let load = (load.0, load.1, false);
        super::sizes::cornering_per_load("cornering_stiffness", self.cornering_stiffness, load)
    }
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.cornering_stiffness *= k;
    }
    /// Its force does not depend on the load: no load of its own.
    fn load_range(&self) -> Option<LoadRange> {
        Some(LoadRange::any_tyre(<Self as Model>::NAME))
    }
}

impl Model for Linear {
    const NAME: &'static str = "linear";
    /// 50 kN/rad, no trail.
    fn start(_fz: f64) -> Option<Self> {
        Some(Linear::new(50_000.0))
    }
}
