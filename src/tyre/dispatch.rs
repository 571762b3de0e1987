//! [`Tyre`]: a tyre of any model, selected at run time by the `model` key of
//! its TOML file (serde's internally tagged enum), and the dispatch to the
//! model's own knowledge ([`ModelParameters`]).
//!
//! The enum knows nothing about any model's parameters: every question
//! goes through [`Tyre::as_model`] or [`Tyre::as_model_mut`] (two match
//! blocks), and only the lateral force, the vehicle's hot loop, has a match
//! of its own so that each model's override is called directly. Units and
//! signs are those of `tyre/mod.rs`.

use super::{
    Block, Gim, Linear, MagicFormula, MagicSimple, ModelName, ModelParameters, Pac89,
    Parameterised, SlipState, TyreForces, TyreModel, UniTire,
};
use crate::error::ParamError;
use serde::{Deserialize, Serialize};

/// A tyre of any supported model, selected at run time by the `model` key of
/// its TOML file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "model", rename_all = "kebab-case")]
pub enum Tyre {
    /// Gim / brush model with adhesion and sliding regions.
    Gim(Gim),
    /// Simplified Magic Formula `Fy = μ·Fz·sin(C·atan(B·α))` (Li, Jia & Zhao).
    MagicSimple(MagicSimple),
    /// UniTire pure-slip model (Zhang & Li (2017)).
    Unitire(UniTire),
    /// PAC89 Magic Formula in the Adams numbering (Zhang et al. (2021)).
    Pac89(Pac89),
    /// Linear tyre `Fy = C_α·α` (the textbook bicycle model).
    Linear(Linear),
    /// Magic Formula 5.2/6.1/6.2, usually read from a `.tir` file.
    MagicFormula(Box<MagicFormula>),
}

impl Tyre {
    /// The model behind the tyre, for everything it knows about itself.
    pub fn as_model(&self) -> &dyn ModelParameters {
        match self {
            Tyre::Gim(t) => t,
            Tyre::MagicSimple(t) => t,
            Tyre::Unitire(t) => t,
            Tyre::Pac89(t) => t,
            Tyre::Linear(t) => t,
            Tyre::MagicFormula(t) => t.as_ref(),
        }
    }

    /// The model behind the tyre, to change its parameters.
    pub fn as_model_mut(&mut self) -> &mut dyn ModelParameters {
        match self {
            Tyre::Gim(t) => t,
            Tyre::MagicSimple(t) => t,
            Tyre::Unitire(t) => t,
            Tyre::Pac89(t) => t,
            Tyre::Linear(t) => t,
            Tyre::MagicFormula(t) => t.as_mut(),
        }
    }

    /// The model of this tyre.
    pub fn model(&self) -> ModelName {
        self.as_model().name()
    }

    /// The `model` key of this tyre.
    pub fn model_name(&self) -> &'static str {
        self.model().as_str()
    }

    /// Scales the tyre so that its cornering stiffness at load `fz` becomes
    /// `target` (N/rad) while its friction limit stays: the stiffness
    /// parameters are scaled, not the peak force.
    pub fn with_cornering_stiffness(&self, target: f64, fz: f64) -> Tyre {
        let mut t = self.clone();
        // One multiplicative step is exact for models whose stiffness is
        // proportional to the scaled parameter; offsets (PAC89's Sh) make it
        // only nearly so, hence the few corrective passes.
        for _ in 0..20 {
            let k = target / t.cornering_stiffness(fz);
            if !k.is_finite() || (k - 1.0).abs() < 1e-12 {
                break;
            }
            t.as_model_mut().scale_cornering_stiffness(k);
        }
        t
    }

    /// Checks the parameters for physical sense; the error names the key.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.as_model().validate()
    }

    /// Which parameters a lateral-force fit can identify from data with
    /// `loads` distinct loads and `cambers` distinct cambers: the rest stay
    /// at their start values ([`ModelParameters::lateral_free`]).
    pub fn lateral_free(&self, loads: usize, cambers: usize) -> Vec<bool> {
        self.as_model().lateral_free(loads, cambers)
    }

    /// The same tyre with its sign-blind parameters in their conventional
    /// sign ([`ModelParameters::canonicalise`]).
    pub fn canonical(&self) -> Tyre {
        let mut t = self.clone();
        t.as_model_mut().canonicalise();
        t
    }

    /// Names of the aligning-moment parameters (empty: the model has no
    /// aligning moment to fit).
    pub fn aligning_names(&self) -> Vec<String> {
        self.as_model().block_names(Block::Aligning)
    }

    /// The aligning-moment parameters (a model without them set gets a
    /// start).
    pub fn aligning_parameters(&self) -> Vec<f64> {
        self.as_model().block_parameters(Block::Aligning)
    }

    /// Replaces the aligning-moment parameters.
    pub fn set_aligning_parameters(&mut self, v: &[f64]) {
        self.as_model_mut().set_block_parameters(Block::Aligning, v)
    }

    /// Search box of the aligning-moment parameters.
    pub fn aligning_bounds(&self) -> Vec<(f64, f64)> {
        self.as_model().block_bounds(Block::Aligning)
    }

    /// Which aligning parameters the data can identify.
    pub fn aligning_free(&self, cambers: usize) -> Vec<bool> {
        self.as_model().block_free(Block::Aligning, cambers)
    }

    /// Names of the longitudinal-force parameters (empty: none to fit).
    pub fn longitudinal_names(&self) -> Vec<String> {
        self.as_model().block_names(Block::Longitudinal)
    }

    /// The longitudinal parameters (a start when unset).
    pub fn longitudinal_parameters(&self) -> Vec<f64> {
        self.as_model().block_parameters(Block::Longitudinal)
    }

    /// Replaces the longitudinal parameters.
    pub fn set_longitudinal_parameters(&mut self, v: &[f64]) {
        self.as_model_mut()
            .set_block_parameters(Block::Longitudinal, v)
    }

    /// Search box of the longitudinal parameters.
    pub fn longitudinal_bounds(&self) -> Vec<(f64, f64)> {
        self.as_model().block_bounds(Block::Longitudinal)
    }

    /// Which longitudinal parameters a fit frees.
    pub fn longitudinal_free(&self) -> Vec<bool> {
        // No longitudinal term of any model depends on camber.
        self.as_model().block_free(Block::Longitudinal, 1)
    }

    /// Fewest distinct loads a lateral fit of this model needs.
    pub fn loads_needed(&self) -> usize {
        self.as_model().loads_needed()
    }

    /// True when [`Tyre::point_forces`] gives `mx` and `my`.
    pub fn has_wheel_moments(&self) -> bool {
        self.as_model().has_wheel_moments()
    }

    /// Forces and moments at one point; `pressure` (Pa) is read by the
    /// Magic Formula only (`None`: the file's inflation pressure).
    pub fn point_forces(&self, s: &SlipState, pressure: Option<f64>) -> PointForces {
        self.as_model().point_forces(s, pressure)
    }

    /// [`Tyre::point_forces`] over parallel slices (one point per index;
    /// `pressure` empty or as long as `fz`).
    pub fn evaluate_points(
        &self,
        fz: &[f64],
        kappa: &[f64],
        alpha: &[f64],
        camber: &[f64],
        speed: &[f64],
        pressure: &[f64],
    ) -> Vec<PointForces> {
        (0..fz.len())
            .map(|i| {
                let s = SlipState {
                    alpha: alpha[i],
                    kappa: kappa[i],
                    fz: fz[i],
                    camber: camber[i],
                    mu_scale: 1.0,
                    speed: speed[i],
                };
                self.point_forces(&s, pressure.get(i).copied())
            })
            .collect()
    }
}

impl Parameterised for Tyre {
    fn parameter_names(&self) -> Vec<&'static str> {
        self.as_model().parameter_names()
    }
    fn parameters(&self) -> Vec<f64> {
        self.as_model().parameters()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.as_model_mut().set_parameters(p)
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        self.as_model().bounds()
    }
}

impl TyreModel for Tyre {
    fn forces(&self, s: &SlipState) -> TyreForces {
        self.as_model().forces(s)
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        // The vehicle's hot loop: a direct call to each model's override
        // instead of one through the vtable.
        match self {
            Tyre::Gim(t) => t.lateral_force(s),
            Tyre::MagicSimple(t) => t.lateral_force(s),
            Tyre::Unitire(t) => t.lateral_force(s),
            Tyre::Pac89(t) => t.lateral_force(s),
            Tyre::Linear(t) => t.lateral_force(s),
            Tyre::MagicFormula(t) => t.lateral_force(s),
        }
    }
    fn lateral_force_per_load(&self, s: &SlipState) -> Option<f64> {
        match self {
            Tyre::MagicSimple(t) => t.lateral_force_per_load(s),
            _ => None,
        }
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        self.as_model().cornering_stiffness(fz)
    }
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        self.as_model().friction_coefficient(fz, mu_scale)
    }
}

/// Forces and moments of any tyre at one point: the Magic Formula gives all
/// five (and reads the pressure), the other models `fx`, `fy`, `mz` only.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointForces {
    /// Longitudinal force, N.
    pub fx: f64,
    /// Lateral force, N.
    pub fy: f64,
    /// Aligning moment, N·m.
    pub mz: f64,
    /// Overturning moment, N·m (Magic Formula only).
    pub mx: Option<f64>,
    /// Rolling-resistance moment, N·m (Magic Formula only).
    pub my: Option<f64>,
}
