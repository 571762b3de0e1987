//! What a [`Tyre`] of any model does: every question goes to the model's
//! own knowledge ([`super::ModelParameters`]) through [`Tyre::as_model`] or
//! [`Tyre::as_model_mut`]; only the lateral force, the vehicle's hot loop,
//! calls each model's override directly. The enum, those dispatches and its
//! serde come from the registry's list (`registry.rs`); nothing here names
//! a model. The generic lateral force and friction coefficient
//! ([`LateralForceOf`], in dual numbers for exact derivatives) go to the
//! model through a visitor ([`LateralVisitor`]): `None` for a model
//! without them. Units and signs are those of `tyre/mod.rs`.

use super::{
    Block, LateralForceOf, LateralVisitor, Parameterised, PointForces, SlipOf, SlipState, Tyre,
    TyreForces, TyreModel,
};
use crate::error::ParamError;
use num_dual::DualNum;

/// The lateral force at a slip state and a camber (rad, plain).
struct LateralForceAt<'a, T> {
    p: &'a [T],
    s: &'a SlipOf<T>,
    camber: f64,
}

impl<T: DualNum<f64> + Copy> LateralVisitor for LateralForceAt<'_, T> {
    type Output = T;
    fn visit<M: LateralForceOf>(self, m: &M) -> T {
        m.lateral_force_at_camber_of(self.p, self.s, self.camber)
    }
}

/// The friction coefficient at a load and a friction scale.
struct FrictionAt<'a, T> {
    p: &'a [T],
    fz: T,
    mu_scale: T,
}

impl<T: DualNum<f64> + Copy> LateralVisitor for FrictionAt<'_, T> {
    type Output = T;
    fn visit<M: LateralForceOf>(self, m: &M) -> T {
        m.friction_coefficient_of(self.p, self.fz, self.mu_scale)
    }
}

/// The parameter vector the generic methods take.
struct LateralParameters;

impl LateralVisitor for LateralParameters {
    type Output = Vec<f64>;
    fn visit<M: LateralForceOf>(self, m: &M) -> Vec<f64> {
        m.parameters()
    }
}

/// What the vehicle model and the rig fits need in any scalar of
/// `num-dual` (dual numbers carry exact derivatives): each model's
/// [`LateralForceOf`]. `None` for a model without a generic lateral force
/// (the Magic Formula, for now) and for a model registered at run time (a
/// trait object cannot take a generic method).
impl Tyre {
    /// The pure-slip lateral force (no camber, no longitudinal slip), N,
    /// at `s` with lateral parameters `p` ([`Tyre::lateral_parameters`]'s
    /// order): in `f64` [`TyreModel::lateral_force`] of `s.value()`.
    pub fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> Option<T> {
        self.lateral_force_at_camber_of(p, s, 0.0)
    }

    /// [`Tyre::lateral_force_of`] at inclination `camber` (rad, no
    /// derivative taken in it): a rig fit's cambered points.
    pub(crate) fn lateral_force_at_camber_of<T: DualNum<f64> + Copy>(
        &self,
        p: &[T],
        s: &SlipOf<T>,
        camber: f64,
    ) -> Option<T> {
        self.visit_lateral(LateralForceAt { p, s, camber })
    }

    /// The radius of the friction circle per unit load
    /// ([`TyreModel::friction_coefficient`]) at load `fz` and friction
    /// scale `mu_scale`, with lateral parameters `p`.
    pub fn friction_coefficient_of<T: DualNum<f64> + Copy>(
        &self,
        p: &[T],
        fz: T,
        mu_scale: T,
    ) -> Option<T> {
        self.visit_lateral(FrictionAt { p, fz, mu_scale })
    }

    /// The parameters [`Tyre::lateral_force_of`] and
    /// [`Tyre::friction_coefficient_of`] take, in order (the model's
    /// [`Parameterised`] vector); `None` where those are `None`.
    pub fn lateral_parameters(&self) -> Option<Vec<f64>> {
        self.visit_lateral(LateralParameters)
    }
}

impl Tyre {
    /// The `model` key of this tyre.
    pub fn model_name(&self) -> &'static str {
        self.model().as_str()
    }

    /// Scales the tyre so that its cornering stiffness at load `fz` becomes
    /// `target` (N/rad) while its friction limit stays: the stiffness
    /// parameters are scaled, not the peak force.
    pub(crate) fn with_cornering_stiffness(&self, target: f64, fz: f64) -> Tyre {
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

    /// Checks the sizes of the dimensional parameters, as a file holds
    /// them ([`ModelParameters::check_sizes`]).
    pub fn check_sizes(&self) -> Result<(), ParamError> {
        self.as_model().check_sizes()
    }

    /// Checks the parameters against a load it is used at, N, with what
    /// that load is ([`ModelParameters::check_at_load`]).
    pub fn check_at_load(&self, load: super::LoadNamed) -> Result<(), ParamError> {
        self.as_model().check_at_load(load)
    }

    /// Which parameters a lateral-force fit can identify from data with
    /// `loads` distinct loads and `cambers` distinct cambers: the rest stay
    /// at their start values ([`ModelParameters::lateral_free`]).
    pub fn lateral_free(&self, loads: usize, cambers: usize) -> Vec<bool> {
        self.as_model().lateral_free(loads, cambers)
    }

    /// The same tyre with its sign-blind parameters in their conventional
    /// sign ([`ModelParameters::canonicalise`]).
    pub(crate) fn canonical(&self) -> Tyre {
        let mut t = self.clone();
        t.as_model_mut().canonicalise();
        t
    }

    /// Names of the aligning-moment parameters (empty: the model has no
    /// aligning moment to fit).
    pub(crate) fn aligning_names(&self) -> Vec<String> {
        self.as_model().block_names(Block::Aligning)
    }

    /// The aligning-moment parameters (a model without them set gets a
    /// start).
    pub(crate) fn aligning_parameters(&self) -> Vec<f64> {
        self.as_model().block_parameters(Block::Aligning)
    }

    /// Replaces the aligning-moment parameters.
    pub(crate) fn set_aligning_parameters(&mut self, v: &[f64]) {
        self.as_model_mut().set_block_parameters(Block::Aligning, v)
    }

    /// Search box of the aligning-moment parameters.
    pub(crate) fn aligning_bounds(&self) -> Vec<(f64, f64)> {
        self.as_model().block_bounds(Block::Aligning)
    }

    /// Which aligning parameters the data can identify.
    pub(crate) fn aligning_free(&self, cambers: usize) -> Vec<bool> {
        self.as_model().block_free(Block::Aligning, cambers)
    }

    /// Names of the longitudinal-force parameters (empty: none to fit).
    pub(crate) fn longitudinal_names(&self) -> Vec<String> {
        self.as_model().block_names(Block::Longitudinal)
    }

    /// The longitudinal parameters (a start when unset).
    pub(crate) fn longitudinal_parameters(&self) -> Vec<f64> {
        self.as_model().block_parameters(Block::Longitudinal)
    }

    /// Replaces the longitudinal parameters.
    pub(crate) fn set_longitudinal_parameters(&mut self, v: &[f64]) {
        self.as_model_mut()
            .set_block_parameters(Block::Longitudinal, v)
    }

    /// Search box of the longitudinal parameters.
    pub(crate) fn longitudinal_bounds(&self) -> Vec<(f64, f64)> {
        self.as_model().block_bounds(Block::Longitudinal)
    }

    /// Which longitudinal parameters a fit frees.
    pub(crate) fn longitudinal_free(&self) -> Vec<bool> {
        // No longitudinal term of any model depends on camber.
        self.as_model().block_free(Block::Longitudinal, 1)
    }

    /// Fewest distinct loads a lateral fit of this model needs.
    pub(crate) fn loads_needed(&self) -> usize {
        self.as_model().loads_needed()
    }

    /// True when [`Tyre::point_forces`] gives `mx` and `my`.
    pub fn has_wheel_moments(&self) -> bool {
        self.as_model().has_wheel_moments()
    }

    /// The loads the model is meant for ([`super::ModelParameters::load_range`]).
    pub fn load_range(&self) -> Option<super::LoadRange> {
        self.as_model().load_range()
    }

    /// Forces and moments at one point; `pressure` (Pa) is read by the
    /// Magic Formula only (`None`: the file's inflation pressure).
    pub(crate) fn point_forces(&self, s: &SlipState, pressure: Option<f64>) -> PointForces {
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
    fn physical_floors(&self) -> Vec<Option<&'static str>> {
        self.as_model().physical_floors()
    }
}

impl TyreModel for Tyre {
    fn forces(&self, s: &SlipState) -> TyreForces {
        self.as_model().forces(s)
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        // The vehicle's hot loop: a direct call to each model's override
        // instead of one through the vtable.
        self.lateral_force_direct(s)
    }
    fn lateral_forces(&self, rear: &Tyre, s: &[SlipState; 4]) -> [f64; 4] {
        self.lateral_forces_direct(rear, s)
    }
    fn lateral_force_per_load(&self, s: &SlipState) -> Option<f64> {
        self.lateral_force_per_load_direct(s)
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        self.as_model().cornering_stiffness(fz)
    }
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        self.as_model().friction_coefficient(fz, mu_scale)
    }
}
