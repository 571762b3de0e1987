//! Simplified Magic Formula of Li, Jia & Zhao: `Fy = D·μ·Fz·sin(C·atan(B·α))`.
//!
//! Li, Jia & Zhao write it per axle with the road friction μ in front; here it acts
//! per wheel (linear in Fz, so an axle is two wheels at half the axle load),
//! `D` is the friction on the reference surface (1 reproduces the paper) and
//! the road friction is `mu_scale`. As in the paper, μ scales the whole curve,
//! cornering stiffness `B·C·D·μ·Fz` included. No aligning moment, no camber.
//!
//! Units: B in 1/rad, C and D dimensionless, Fz in N. Odd in α.

use super::{
    LateralForceOf, LoadRange, Model, ModelParameters, Parameterised, SlipOf, SlipState,
    TyreForces, TyreModel,
};
use crate::error::{Limit, ParamError};
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// Simplified Magic Formula parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MagicSimple {
    /// Stiffness factor B, 1/rad.
    pub b: f64,
    /// Shape factor C.
    pub c: f64,
    /// Peak friction D on the reference surface (1 in Li, Jia & Zhao).
    #[serde(default = "one")]
    pub d: f64,
}

fn one() -> f64 {
    1.0
}

impl MagicSimple {
    /// A simplified Magic Formula with D = 1.
    pub fn new(b: f64, c: f64) -> Self {
        Self { b, c, d: 1.0 }
    }
    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("b", self.b)?;
        ParamError::in_range("c", self.c, 0.0, 2.0, Limit::ShapeFactor)?;
        ParamError::positive("d", self.d)
    }
}

impl TyreModel for MagicSimple {
    fn forces(&self, s: &SlipState) -> TyreForces {
        TyreForces {
            fx: 0.0,
            fy: self.lateral_force(s),
            mz: 0.0,
        }
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        if s.fz <= 0.0 {
            return 0.0;
        }
        self.d * s.mu_scale * s.fz * (self.c * (self.b * s.alpha).atan()).sin()
    }
    fn lateral_force_per_load(&self, s: &SlipState) -> Option<f64> {
        Some(self.d * s.mu_scale * (self.c * (self.b * s.alpha).atan()).sin())
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        if fz <= 0.0 {
            0.0
        } else {
            self.b * self.c * self.d * fz
        }
    }
    /// The peak factor D (the sine's largest value is 1).
    fn friction_coefficient(&self, _fz: f64, mu_scale: f64) -> f64 {
        self.d * mu_scale
    }
}

impl Parameterised for MagicSimple {
    fn parameter_names(&self) -> Vec<&'static str> {
        vec!["b", "c", "d"]
    }
    fn parameters(&self) -> Vec<f64> {
        vec![self.b, self.c, self.d]
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.b = p[0];
        self.c = p[1];
        self.d = p[2];
    }
    /// A tyre's: the shape factor `C` at least 1 (below, the sine never
    /// reaches its peak and `B`, `C`, `D` trade along a ridge; a car tyre's
    /// lateral C is 1.3–1.6, Pacejka 2012, §4.3), the peak friction `D`
    /// at least 0.5 (no tyre on a rig's dry surface peaks lower), and `B`
    /// at least 3, so that the cornering stiffness per unit load `B·C·D`
    /// is at least [`super::sizes::MIN_CORNERING_PER_LOAD`] (1.5 /rad; car
    /// tyres 5–30, Pacejka 2012): the old box's corner, 1·0.5·0.1 = 0.05
    /// /rad, was no tyre, and a fit landing there was refused when read.
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![(3.0, 60.0), (1.0, 2.0), (0.5, 4.0)]
    }
}

impl LateralForceOf for MagicSimple {
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        if s.fz <= 0.0 {
            return T::from(0.0);
        }
        let (b, c, d) = (p[0], p[1], p[2]);
        d * s.mu_scale * s.fz * (c * (b * s.alpha).atan()).sin()
    }
    /// `D·μ`, as [`TyreModel::friction_coefficient`].
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], _fz: T, mu_scale: T) -> T {
        p[2] * mu_scale
    }
}

impl ModelParameters for MagicSimple {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        MagicSimple::validate(self)
    }
    /// The stiffness per unit load `B·C·D` at least any tyre's
    /// ([`super::sizes::MIN_CORNERING_PER_LOAD`]): `B` typed per degree
    /// (0.17 for 10 per radian) gave 0.23.
    fn check_sizes(&self) -> Result<(), ParamError> {
        // D is the peak friction: 100 gave 227 kN at 4 kN.
        super::sizes::friction("d", self.d)?;
        let per_load = self.b * self.c * self.d;
        let min = super::sizes::MIN_CORNERING_PER_LOAD;
        match per_load >= min {
            true => Ok(()),
            false => Err(ParamError::new(
                "b",
                self.b,
                crate::error::ParamReason::OutOfRange {
                    lo: min / (self.c * self.d),
                    hi: f64::INFINITY,
                    why: crate::error::Limit::MagicSimplePerDegree { per_load },
                },
            )),
        }
    }
    /// The stiffness `B·C·D·μ·Fz` is proportional to B; the peak `D·μ·Fz`
    /// does not depend on it.
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.b *= k;
    }
    /// Its force is proportional to the load at every slip (852 kN at
    /// 1 MN): no load of its own.
    fn load_range(&self) -> Option<LoadRange> {
        Some(LoadRange::any_tyre(<Self as Model>::NAME))
    }
}

impl Model for MagicSimple {
    const NAME: &'static str = "magic-simple";
    /// B = 10 /rad, C = 1.3, D = 1 (Li, Jia & Zhao's range).
    fn start(_fz: f64) -> Option<Self> {
        Some(MagicSimple::new(10.0, 1.3))
    }
}
