//! Tyre models: lateral force, longitudinal force and aligning moment from the
//! slip state of one wheel.
//!
//! Units: SI and radians at this interface (N, N·m, rad, m/s). A published
//! model's own units (PAC89: kN, degrees, percent) live only inside its file.
//!
//! Sign convention (`FORMATS.md`, ISO 8855 axes with the crate's slip sign):
//! a positive slip angle gives a positive lateral force near zero slip
//! (`fy ≈ C_α·α`), a positive slip ratio a positive longitudinal force, and
//! `mz` is positive when it turns the wheel back toward zero slip, so it has
//! the sign of `fy` at small slip. In the vehicle model the slip angle of a
//! wheel is therefore `α = δ − atan(v_wheel / u_wheel)`.
//!
//! Road friction: every model has its own friction parameters, measured on the
//! rig's surface. The road's friction enters as a scale `mu_scale` on them
//! (1 reproduces the file), like the MF scaling factor λ_μ.
//!
//! Layout: this file holds the slip state, the forces and the traits every
//! model implements ([`TyreModel`] for the forces, [`Parameterised`] for the
//! lateral-force vector, [`ModelParameters`] for everything else a fit or a
//! study needs to know about the model, [`Model`] for what the registry
//! needs: name, construction, identification); one file per model, which
//! imports this file only; `registry.rs` the one list of models (one line
//! each), from which the [`Tyre`] enum, the [`ModelName`] constants and every
//! list of names (tyre files, `identify`, the CLI, Python, error messages)
//! are derived, and [`register`] for a model defined outside the crate;
//! `generate.rs` the macro that expands the list; `erased.rs` the type-erased
//! model a registered tyre is held as; `dispatch.rs` what [`Tyre`] does with
//! any model; `name.rs` the model names; `kernels.rs` the branch-free array
//! `atan`/`sin`/`cos` the Magic Formula and PAC89 evaluate in.
//!
//! Adding a model: a file `tyre/<model>.rs` with its parameter struct
//! (serde `Serialize`/`Deserialize`, `deny_unknown_fields`) implementing the
//! four traits, and one line in the list in `registry.rs`. A model defined
//! outside the crate implements the same traits and calls
//! [`register`]`::<M>()` once: its tyre files, `simulate`, `identify` (when
//! [`Model::IDENTIFICATION`] says so) and `tyre-eval` then accept it.

mod arrays;
mod dispatch;
mod erased;
mod generate;
mod gim;
mod kernels;
mod linear;
pub mod load_range;
mod magic_simple;
pub mod mf;
mod name;
pub(crate) mod pac89;
mod registry;
pub mod sizes;
pub(crate) mod unitire;

pub use gim::Gim;
pub use linear::Linear;
pub use magic_simple::MagicSimple;
pub use mf::MagicFormula;
pub use pac89::{Pac89, Pac89Form};
pub use unitire::{UniTire, UniTireLateral, UniTireLongitudinal};

pub use erased::Erased;
pub use load_range::LoadRange;
pub use name::ModelName;
pub use registry::{model_names, models, register, swarm_models, ModelEntry, Tyre};

use crate::error::ParamError;
use mf::MfVersion;
use num_dual::DualNum;
use serde::de::DeserializeOwned;
use serde::Serialize;

/// The slip state of one wheel: everything a tyre model may read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipState {
    /// Slip angle α, rad (positive gives positive `fy`).
    pub alpha: f64,
    /// Longitudinal slip ratio κ = (Ω·R_e − V_x)/V_x, dimensionless.
    pub kappa: f64,
    /// Vertical load, N (≤ 0 means the wheel is off the ground).
    pub fz: f64,
    /// Inclination (camber) angle, rad.
    pub camber: f64,
    /// Road friction as a scale on the tyre's own friction (1 = as measured).
    pub mu_scale: f64,
    /// Forward speed of the wheel centre, m/s; models with a sliding-speed
    /// friction law derive the sliding speed from it.
    pub speed: f64,
}

impl SlipState {
    /// Pure cornering at load `fz`: no longitudinal slip, no camber, μ scale 1,
    /// 20 m/s.
    pub fn lateral(alpha: f64, fz: f64) -> Self {
        Self {
            alpha,
            kappa: 0.0,
            fz,
            camber: 0.0,
            mu_scale: 1.0,
            speed: 20.0,
        }
    }

    /// Pure longitudinal slip at load `fz`.
    pub fn longitudinal(kappa: f64, fz: f64) -> Self {
        Self {
            kappa,
            ..Self::lateral(0.0, fz)
        }
    }

    /// Lateral sliding speed of the contact patch, m/s: `V·|sin α|`.
    pub(crate) fn lateral_sliding_speed(&self) -> f64 {
        self.speed.abs() * self.alpha.sin().abs()
    }

    /// Longitudinal sliding speed of the contact patch, m/s: `V·|κ|`.
    pub(crate) fn longitudinal_sliding_speed(&self) -> f64 {
        self.speed.abs() * self.kappa.abs()
    }
}

/// Forces and moment at the contact patch in the wheel frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TyreForces {
    /// Longitudinal force, N.
    pub fx: f64,
    /// Lateral force, N.
    pub fy: f64,
    /// Aligning moment, N·m (sign of `fy` at small slip).
    pub mz: f64,
}

/// Step of the central difference for the slip stiffness at zero slip. Brush
/// models have a `|α|·α` term, so the truncation error is first order in the
/// step (relative error ≈ K·h/(3μFz) ≈ 5e-8 here); rounding stays far below.
const STIFFNESS_STEP: f64 = 1e-8;

/// A tyre model. One required method; the rest have defaults that models with a
/// closed form may override.
pub trait TyreModel {
    /// Forces and aligning moment for the given slip state.
    fn forces(&self, s: &SlipState) -> TyreForces;

    /// Lateral force only; the vehicle's hot loop calls this, so models whose
    /// full evaluation is expensive override it.
    fn lateral_force(&self, s: &SlipState) -> f64 {
        self.forces(s).fy
    }

    /// The lateral forces of a vehicle's four wheels at `s`: the first two
    /// on this tyre, the last two on `rear` (of the same model). By default
    /// one [`TyreModel::lateral_force`] each; a model whose evaluation
    /// vectorises across the wheels overrides it (PAC89).
    fn lateral_forces(&self, rear: &Self, s: &[SlipState; 4]) -> [f64; 4]
    where
        Self: Sized,
    {
        [
            self.lateral_force(&s[0]),
            self.lateral_force(&s[1]),
            rear.lateral_force(&s[2]),
            rear.lateral_force(&s[3]),
        ]
    }

    /// `Fy/Fz` at the slip state's slip angle, friction and speed when the
    /// model's lateral force is proportional to the load at every slip
    /// angle (`Fy = Fz·f(α)` for `Fz > 0`), else `None`. The vehicle's
    /// load-transfer loop moves the loads at a fixed slip angle: such a
    /// model is evaluated once per axle, not once per wheel and iteration.
    fn lateral_force_per_load(&self, _s: &SlipState) -> Option<f64> {
        None
    }

    /// Cornering stiffness ∂fy/∂α at α = 0, N/rad, at load `fz` (no camber).
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        let s = |a| SlipState::lateral(a, fz);
        (self.lateral_force(&s(STIFFNESS_STEP)) - self.lateral_force(&s(-STIFFNESS_STEP)))
            / (2.0 * STIFFNESS_STEP)
    }

    /// The radius of the friction circle per unit load at load `fz` and
    /// friction scale `mu_scale`: the largest horizontal force the tyre
    /// transmits over `fz`. The vehicle model combines a pure-slip tyre's
    /// lateral force with a longitudinal force on this circle
    /// ([`crate::vehicle::Effects::combined_slip`]). By default the peak
    /// lateral force over the load (a scan, slow); models with a friction
    /// coefficient in closed form return it.
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        if fz <= 0.0 {
            return 0.0;
        }
        self.peak_lateral_force(fz, mu_scale) / fz
    }

    /// Peak lateral force magnitude over 0 < α ≤ 30°, N, at load `fz` and
    /// friction scale `mu_scale` (a scan at 0.05°, then a golden refine).
    fn peak_lateral_force(&self, fz: f64, mu_scale: f64) -> f64 {
        let f = |a: f64| {
            self.lateral_force(&SlipState {
                mu_scale,
                ..SlipState::lateral(a, fz)
            })
            .abs()
        };
        let step = 0.05_f64.to_radians();
        let n = 600;
        let (mut best_i, mut best) = (1, f(step));
        for i in 2..=n {
            let v = f(i as f64 * step);
            if v > best {
                best = v;
                best_i = i;
            }
        }
        let (mut lo, mut hi) = ((best_i - 1) as f64 * step, (best_i + 1) as f64 * step);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let m1 = hi - g * (hi - lo);
            let m2 = lo + g * (hi - lo);
            if f(m1) < f(m2) {
                lo = m1;
            } else {
                hi = m2;
            }
        }
        best.max(f(0.5 * (lo + hi)))
    }
}

/// The slip state in a scalar of the `num-dual` crate (a plain `f64`, or a
/// dual number that carries derivatives): the inputs a derivative is taken
/// with respect to — slip angle, load and friction scale; camber and speed
/// stay plain numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipOf<T> {
    /// Slip angle α, rad.
    pub alpha: T,
    /// Vertical load, N.
    pub fz: T,
    /// Road friction scale.
    pub mu_scale: T,
    /// Forward speed of the wheel centre, m/s.
    pub speed: f64,
}

impl<T: DualNum<f64> + Copy> SlipOf<T> {
    /// The plain-number slip state of this one (derivatives dropped; no
    /// longitudinal slip, no camber).
    pub fn value(&self) -> SlipState {
        SlipState {
            alpha: self.alpha.re(),
            kappa: 0.0,
            fz: self.fz.re(),
            camber: 0.0,
            mu_scale: self.mu_scale.re(),
            speed: self.speed,
        }
    }
}

/// A tyre model's pure-slip lateral force in any scalar of the `num-dual`
/// crate, with its lateral parameter vector ([`Parameterised`], in that
/// order) as scalars too: in dual numbers it gives the exact derivatives of
/// the force with respect to the slip state and the parameters (forward
/// mode, to rounding), with `f64` the force itself, the same arithmetic as
/// [`TyreModel::lateral_force`] (no camber, no longitudinal slip: the
/// vehicle model's wheel). The derivative of a model's kink (a wheel off
/// the ground, full sliding) is that of the branch its value takes.
pub trait LateralForceOf: Parameterised {
    /// The lateral force at `s` with parameters `p`, N.
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T;

    /// [`TyreModel::friction_coefficient`] in any scalar, with parameters
    /// `p`: the radius of the friction circle per unit load at load `fz`
    /// and friction scale `mu_scale` (the same closed form, the same
    /// arithmetic).
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], fz: T, mu_scale: T) -> T;

    /// [`LateralForceOf::lateral_force_of`] at inclination `camber` (rad,
    /// a plain number: no derivative is taken in it), as
    /// [`TyreModel::lateral_force`] of the same slip state with that
    /// camber: what a rig fit on cambered points differentiates. By
    /// default the force does not read camber; a model whose force does
    /// (PAC89) overrides it.
    fn lateral_force_at_camber_of<T: DualNum<f64> + Copy>(
        &self,
        p: &[T],
        s: &SlipOf<T>,
        camber: f64,
    ) -> T {
        let _ = camber;
        self.lateral_force_of(p, s)
    }
}

/// What [`Tyre`]'s generic methods ask of one model's [`LateralForceOf`]
/// (a trait object cannot take a generic method, so each question is a
/// visitor the registry's dispatch hands the model).
pub(crate) trait LateralVisitor {
    /// The answer.
    type Output;
    /// The answer of model `m`.
    fn visit<M: LateralForceOf>(self, m: &M) -> Self::Output;
}

/// A model that may have a generic lateral force: every [`LateralForceOf`]
/// model has (`Some`); a model without one says so by its own `None` impl
/// (next to the registry's list).
pub(crate) trait MaybeLateralForceOf {
    /// Visitor `v`'s answer, `None` without a generic lateral force.
    fn visit_lateral<V: LateralVisitor>(&self, v: V) -> Option<V::Output>;
}

impl<M: LateralForceOf> MaybeLateralForceOf for M {
    fn visit_lateral<V: LateralVisitor>(&self, v: V) -> Option<V::Output> {
        Some(v.visit(self))
    }
}

/// A named, bounded parameter vector: what identification works on.
pub trait Parameterised {
    /// Parameter names, in vector order.
    fn parameter_names(&self) -> Vec<&'static str>;
    /// Current values, in vector order.
    fn parameters(&self) -> Vec<f64>;
    /// Replaces the parameters; `p.len()` equals the number of names.
    fn set_parameters(&mut self, p: &[f64]);
    /// Plausible search box (lower, upper) for each parameter.
    fn bounds(&self) -> Vec<(f64, f64)>;
    /// For each parameter whose box's lower end is a physical limit (no
    /// tyre lies beyond it, as a decay below 0), why; `None` where the
    /// lower end only bounds the search. A fit on such a limit that the
    /// data do not pull past is a fit there, not a search stopped
    /// (`identify/parameters.rs`).
    fn physical_floors(&self) -> Vec<Option<&'static str>> {
        vec![None; self.parameter_names().len()]
    }
}

/// A parameter block beyond the lateral force (which is the model's
/// [`Parameterised`] vector): what one identification channel fits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Block {
    /// The aligning-moment parameters (fitted with the lateral ones held).
    Aligning,
    /// The longitudinal-force parameters.
    Longitudinal,
}

/// A load a tyre is used at, N, with what it is in words.
pub type LoadNamed = (&'static str, f64);

/// What a tyre model knows about its own parameters beyond the forces: its
/// checks, its parameter blocks with their bounds and which of them rig
/// data can identify, its canonical form and how its cornering stiffness
/// scales. Every model implements it in its own file; [`Tyre`] only
/// dispatches, so model internals (index lists, bounds, which coefficient
/// carries the stiffness) stay with the model. It is object safe: a tyre
/// of any model is seen through it.
///
/// Only the first two methods are required: a model without an aligning
/// moment or longitudinal force to fit, without load-dependent terms and
/// without sign-blind parameters keeps the defaults.
pub trait ModelParameters: TyreModel + Parameterised {
    /// Checks the parameters for physical sense; the error names the key.
    fn validate(&self) -> Result<(), ParamError>;

    /// Checks that each dimensional parameter has a size some tyre has in
    /// its unit ([`sizes`]): a tyre file's unit slip (a contact length in
    /// mm) is refused at its key. Run where a file is read, after
    /// [`Self::validate`].
    fn check_sizes(&self) -> Result<(), ParamError> {
        Ok(())
    }

    /// Checks the parameters against a load the tyre is used at, N, named
    /// by what it is (a vehicle's static wheel load, a points file's median
    /// load): a model whose force does not depend on the load (the linear
    /// tyre) has no load of its own for [`Self::check_sizes`] to take its
    /// stiffness per unit load at, so a car tyre's N/deg figure typed in
    /// N/rad is caught only here.
    fn check_at_load(&self, load: LoadNamed) -> Result<(), ParamError> {
        let _ = load;
        Ok(())
    }

    /// Multiplies the cornering stiffness by `k` while the friction limit
    /// stays: the parameter(s) the stiffness is proportional to are scaled.
    fn scale_cornering_stiffness(&mut self, k: f64);

    /// Fewest distinct loads a lateral fit needs.
    fn loads_needed(&self) -> usize {
        1
    }

    /// Which lateral parameters a fit can identify from data with `loads`
    /// distinct loads and `cambers` distinct cambers (the rest stay at their
    /// start values).
    fn lateral_free(&self, loads: usize, cambers: usize) -> Vec<bool> {
        let _ = (loads, cambers);
        vec![true; self.parameters().len()]
    }

    /// Sets parameters that enter only through an even function to their
    /// conventional sign, so a fit that lands on the mirror image reports
    /// the conventional one.
    fn canonicalise(&mut self) {}

    /// Names of a block's parameters (empty: the model has none to fit).
    fn block_names(&self, block: Block) -> Vec<String> {
        let _ = block;
        Vec::new()
    }

    /// A block's parameters (a model without them set gives a start).
    fn block_parameters(&self, block: Block) -> Vec<f64> {
        let _ = block;
        Vec::new()
    }

    /// Replaces a block's parameters (`v` as long as its names).
    fn set_block_parameters(&mut self, block: Block, v: &[f64]) {
        let _ = (block, v);
    }

    /// Search box of a block's parameters.
    fn block_bounds(&self, block: Block) -> Vec<(f64, f64)> {
        let _ = block;
        Vec::new()
    }

    /// Which of a block's parameters data with `cambers` distinct cambers
    /// can identify.
    fn block_free(&self, block: Block, cambers: usize) -> Vec<bool> {
        let _ = cambers;
        vec![true; self.block_parameters(block).len()]
    }

    /// Forces and moments at one point; `pressure` (Pa) is read only by
    /// models with pressure terms (the Magic Formula), which also give `mx`
    /// and `my`.
    fn point_forces(&self, s: &SlipState, pressure: Option<f64>) -> PointForces {
        let _ = pressure;
        let f = self.forces(s);
        PointForces {
            fx: f.fx,
            fy: f.fy,
            mz: f.mz,
            mx: None,
            my: None,
        }
    }

    /// True when [`ModelParameters::point_forces`] gives `mx` and `my`.
    fn has_wheel_moments(&self) -> bool {
        false
    }

    /// The loads the model is meant for ([`LoadRange`]); `None` where the
    /// model says its ranges itself (a Magic Formula file's `FZMIN`,
    /// `FZMAX`) or states none.
    fn load_range(&self) -> Option<LoadRange> {
        None
    }
}

/// How `identify` fits a model to rig data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Identification {
    /// A particle swarm and a local polish over the lateral parameter
    /// vector ([`Parameterised`]) from [`Model::start`] (which then gives a
    /// start), then the aligning and longitudinal blocks; `identify --model
    /// <name>`.
    Swarm,
    /// The swarm fit, and beside its lateral-force fit Zhang et al.'s
    /// (2021) two-stage identification: the curve coefficients B, C, D, E,
    /// Sh, Sv per condition, their load and camber laws a0..a13, then a
    /// joint polish; the better of the two is written. The two stages build
    /// a PAC89 in the Adams numbering, so this is PAC89's.
    SwarmAndTwoStage,
    /// A staged fit of the model's own, one per version it writes (the
    /// Magic Formula: Wei et al.'s (2010) stages, `mf61` and `mf62`).
    Staged(&'static [StagedFit]),
    /// Not identified from rig data.
    NotFitted,
}

impl Identification {
    /// True when the swarm fits the model (`identify --model <name>`).
    pub fn by_swarm(self) -> bool {
        matches!(self, Self::Swarm | Self::SwarmAndTwoStage)
    }
}

/// One version of a model's staged fit: the name `identify --model` takes
/// and the Magic Formula version the fit evaluates and writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StagedFit {
    /// The name on the command line and in file names (`mf61`).
    pub name: &'static str,
    /// The version fitted and written (its `FITTYP`).
    pub version: MfVersion,
}

/// A tyre model as the registry knows it: its name, how a tyre of it is
/// read from a tyre file's table (serde, the `model` key taken off), where a
/// fit starts and how it is identified. With [`ModelParameters`] (and so
/// [`TyreModel`] and [`Parameterised`]) it is everything a job needs.
pub trait Model:
    ModelParameters
    + Clone
    + std::fmt::Debug
    + PartialEq
    + Serialize
    + DeserializeOwned
    + Send
    + Sync
    + 'static
{
    /// The `model` key of its tyre files: its name everywhere (command line,
    /// Python, reports, messages).
    const NAME: &'static str;

    /// How `identify` fits it (default: the swarm from [`Model::start`]).
    const IDENTIFICATION: Identification = Identification::Swarm;

    /// The start tyre of a fit to data whose median load is `fz`: lateral
    /// parameters only, so that no borrowed aligning or longitudinal
    /// coefficients are written (`None`: the model has no swarm fit; the
    /// Magic Formula has its own staged identification).
    fn start(fz: f64) -> Option<Self>;
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

/// `tan α` that keeps its sign and stays finite up to |α| = 90°.
pub(crate) fn safe_tan(alpha: f64) -> f64 {
    let c = alpha.cos().abs().max(1e-12);
    alpha.sin() / c
}

/// [`safe_tan`] in any scalar of `num-dual`.
pub(crate) fn safe_tan_of<T: DualNum<f64> + Copy>(alpha: T) -> T {
    let c = alpha.cos().abs();
    if c.re() < 1e-12 {
        alpha.sin() / 1e-12
    } else {
        alpha.sin() / c
    }
}

#[cfg(test)]
mod derivative_tests;
#[cfg(test)]
pub(crate) mod tests;
