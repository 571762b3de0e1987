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

mod gim;
mod linear;
mod magic_simple;
pub mod mf;
pub mod pac89;
pub mod unitire;

pub use gim::Gim;
pub use linear::Linear;
pub use magic_simple::MagicSimple;
pub use mf::MagicFormula;
pub use pac89::{Pac89, Pac89Form};
pub use unitire::{UniTire, UniTireLateral, UniTireLongitudinal};

use serde::{Deserialize, Serialize};

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
    pub fn lateral_sliding_speed(&self) -> f64 {
        self.speed.abs() * self.alpha.sin().abs()
    }

    /// Longitudinal sliding speed of the contact patch, m/s: `V·|κ|`.
    pub fn longitudinal_sliding_speed(&self) -> f64 {
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

    /// Cornering stiffness ∂fy/∂α at α = 0, N/rad, at load `fz` (no camber).
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        let s = |a| SlipState::lateral(a, fz);
        (self.lateral_force(&s(STIFFNESS_STEP)) - self.lateral_force(&s(-STIFFNESS_STEP)))
            / (2.0 * STIFFNESS_STEP)
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
}

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

/// The tyre models, a closed set: the `model` key of a tyre file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum ModelName {
    /// [`Gim`].
    Gim,
    /// [`MagicSimple`].
    MagicSimple,
    /// [`UniTire`].
    Unitire,
    /// [`Pac89`].
    Pac89,
    /// [`Linear`].
    Linear,
    /// [`MagicFormula`].
    MagicFormula,
}

impl ModelName {
    /// Every model, in the order of the [`Tyre`] variants.
    pub const ALL: [ModelName; 6] = [
        ModelName::Gim,
        ModelName::MagicSimple,
        ModelName::Unitire,
        ModelName::Pac89,
        ModelName::Linear,
        ModelName::MagicFormula,
    ];

    /// The name as a tyre file writes it.
    pub fn as_str(self) -> &'static str {
        match self {
            ModelName::Gim => "gim",
            ModelName::MagicSimple => "magic-simple",
            ModelName::Unitire => "unitire",
            ModelName::Pac89 => "pac89",
            ModelName::Linear => "linear",
            ModelName::MagicFormula => "magic-formula",
        }
    }
}

impl std::fmt::Display for ModelName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::str::FromStr for ModelName {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|m| m.as_str() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|m| m.as_str()).collect();
                format!("unknown tyre model `{s}`: one of {}", names.join(", "))
            })
    }
}

/// Names accepted by the `model` key.
pub const MODEL_NAMES: [&str; 6] = [
    "gim",
    "magic-simple",
    "unitire",
    "pac89",
    "linear",
    "magic-formula",
];

impl Tyre {
    /// The model of this tyre.
    pub fn model(&self) -> ModelName {
        match self {
            Tyre::Gim(_) => ModelName::Gim,
            Tyre::MagicSimple(_) => ModelName::MagicSimple,
            Tyre::Unitire(_) => ModelName::Unitire,
            Tyre::Pac89(_) => ModelName::Pac89,
            Tyre::Linear(_) => ModelName::Linear,
            Tyre::MagicFormula(_) => ModelName::MagicFormula,
        }
    }

    /// The `model` key of this tyre.
    pub fn model_name(&self) -> &'static str {
        self.model().as_str()
    }

    fn inner(&self) -> &dyn TyreModel {
        match self {
            Tyre::Gim(t) => t,
            Tyre::MagicSimple(t) => t,
            Tyre::Unitire(t) => t,
            Tyre::Pac89(t) => t,
            Tyre::Linear(t) => t,
            Tyre::MagicFormula(t) => t.as_ref(),
        }
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
            match &mut t {
                Tyre::Gim(g) => g.cornering_stiffness *= k,
                Tyre::MagicSimple(m) => m.b *= k,
                Tyre::Unitire(u) => u.lateral.scale_stiffness(k),
                Tyre::Pac89(p) => p.a[3] *= k,
                Tyre::Linear(l) => l.cornering_stiffness *= k,
                Tyre::MagicFormula(m) => m.coefficients.LKY *= k,
            }
        }
        t
    }

    /// Checks the parameters for physical sense; the error names the key.
    pub fn validate(&self) -> Result<(), crate::error::ParamError> {
        match self {
            Tyre::Gim(t) => t.validate(),
            Tyre::MagicSimple(t) => t.validate(),
            Tyre::Unitire(t) => t.validate(),
            Tyre::Pac89(t) => t.validate(),
            Tyre::Linear(t) => t.validate(),
            Tyre::MagicFormula(t) => t.validate(),
        }
    }
}

impl Parameterised for Tyre {
    fn parameter_names(&self) -> Vec<&'static str> {
        self.parameterised().parameter_names()
    }
    fn parameters(&self) -> Vec<f64> {
        self.parameterised().parameters()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        match self {
            Tyre::Gim(t) => t.set_parameters(p),
            Tyre::MagicSimple(t) => t.set_parameters(p),
            Tyre::Unitire(t) => t.set_parameters(p),
            Tyre::Pac89(t) => t.set_parameters(p),
            Tyre::Linear(t) => t.set_parameters(p),
            Tyre::MagicFormula(t) => t.set_parameters(p),
        }
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        self.parameterised().bounds()
    }
}

impl Tyre {
    fn parameterised(&self) -> &dyn Parameterised {
        match self {
            Tyre::Gim(t) => t,
            Tyre::MagicSimple(t) => t,
            Tyre::Unitire(t) => t,
            Tyre::Pac89(t) => t,
            Tyre::Linear(t) => t,
            Tyre::MagicFormula(t) => t.as_ref(),
        }
    }

    /// Which parameters a lateral-force fit can identify from data with
    /// `loads` distinct loads and `cambers` distinct cambers: the rest stay
    /// at their start values (Gim's contact length only acts on Mz, camber
    /// terms need more than one camber, load exponents more than one load,
    /// and UniTire's sliding-speed friction law — μs/μ0, μh, Vsm — trades
    /// off against its other terms within the noise of a rig test at one
    /// speed, so it is held).
    pub fn lateral_free(&self, loads: usize, cambers: usize) -> Vec<bool> {
        match self {
            Tyre::Gim(_) => vec![true, false, true, true, loads > 1],
            Tyre::MagicSimple(_) | Tyre::Linear(_) | Tyre::MagicFormula(_) => {
                vec![true; self.parameters().len()]
            }
            Tyre::Unitire(_) => (0..10).map(|i| i < 7).collect(),
            Tyre::Pac89(_) => (0..14)
                .map(|i| cambers > 1 || ![5, 8, 11].contains(&i))
                .collect(),
        }
    }

    /// The same tyre with parameters that enter only through an even function
    /// set to their positive value (UniTire's p2 appears as (Fzn/p2)²;
    /// PAC89's a3·sin(2·atan(Fz/a4)) is unchanged when both a3 and a4 change
    /// sign), so fits that land on the mirror image report the conventional
    /// one.
    pub fn canonical(&self) -> Tyre {
        let mut t = self.clone();
        match &mut t {
            Tyre::Unitire(u) => {
                u.lateral.p[1] = u.lateral.p[1].abs();
                if let Some(l) = &mut u.longitudinal {
                    l.p[1] = l.p[1].abs();
                }
            }
            Tyre::Pac89(p) if p.a[4] < 0.0 => {
                p.a[3] = -p.a[3];
                p.a[4] = -p.a[4];
            }
            _ => {}
        }
        t
    }

    /// Names of the aligning-moment parameters (empty: the model has no
    /// aligning moment to fit).
    pub fn aligning_names(&self) -> Vec<String> {
        let n = self.aligning_parameters().len();
        match self {
            Tyre::Gim(_) => vec!["contact_length".into()],
            Tyre::Unitire(_) => (1..=n).map(|i| format!("c{i}")).collect(),
            Tyre::Pac89(_) => (0..n).map(|i| format!("c{i}")).collect(),
            _ => Vec::new(),
        }
    }

    /// The aligning-moment parameters (a model without them set gets the
    /// bundled example's as a start).
    pub fn aligning_parameters(&self) -> Vec<f64> {
        match self {
            Tyre::Gim(g) => vec![g.contact_length],
            Tyre::Unitire(u) => u
                .aligning
                .as_ref()
                .map_or(unitire::DEFAULT_ALIGNING.to_vec(), |a| a.c.to_vec()),
            Tyre::Pac89(p) => p.c.unwrap_or(pac89::ADAMS_EXAMPLE_C).to_vec(),
            _ => Vec::new(),
        }
    }

    /// Replaces the aligning-moment parameters.
    pub fn set_aligning_parameters(&mut self, v: &[f64]) {
        match self {
            Tyre::Gim(g) => g.contact_length = v[0],
            Tyre::Unitire(u) => {
                let mut c = [0.0; 10];
                c.copy_from_slice(v);
                u.aligning = Some(unitire::UniTireAligning { c });
            }
            Tyre::Pac89(p) => {
                let mut c = [0.0; 18];
                c.copy_from_slice(v);
                p.c = Some(c);
            }
            _ => {}
        }
    }

    /// Search box of the aligning-moment parameters.
    pub fn aligning_bounds(&self) -> Vec<(f64, f64)> {
        match self {
            Tyre::Gim(_) => vec![(0.02, 0.5)],
            Tyre::Unitire(_) => vec![
                (-0.1, 0.2),
                (-0.05, 0.05),
                (-0.01, 0.01),
                (-0.2, 0.2),
                (-0.05, 0.05),
                (-0.01, 0.01),
                (0.0, 10.0),
                (0.1, 100.0),
                (0.0, 10.0),
                (0.1, 100.0),
            ],
            Tyre::Pac89(_) => pac89::bounds_around(&pac89::ADAMS_EXAMPLE_C),
            _ => Vec::new(),
        }
    }

    /// Which aligning parameters the data can identify (camber terms need
    /// more than one camber).
    pub fn aligning_free(&self, cambers: usize) -> Vec<bool> {
        match self {
            Tyre::Pac89(_) => (0..18)
                .map(|i| cambers > 1 || ![6, 10, 11, 14, 15].contains(&i))
                .collect(),
            _ => vec![true; self.aligning_parameters().len()],
        }
    }

    /// Names of the longitudinal-force parameters (empty: none to fit).
    pub fn longitudinal_names(&self) -> Vec<String> {
        match self {
            Tyre::Unitire(_) => (1..=10).map(|i| format!("a{i}")).collect(),
            Tyre::Pac89(_) => (0..11).map(|i| format!("b{i}")).collect(),
            _ => Vec::new(),
        }
    }

    /// The longitudinal parameters (the bundled example's when unset).
    pub fn longitudinal_parameters(&self) -> Vec<f64> {
        match self {
            Tyre::Unitire(u) => u
                .longitudinal
                .as_ref()
                .map_or(unitire::DEFAULT_LONGITUDINAL.to_vec(), |l| l.p.to_vec()),
            Tyre::Pac89(p) => p.b.unwrap_or(pac89::ADAMS_EXAMPLE_B).to_vec(),
            _ => Vec::new(),
        }
    }

    /// Replaces the longitudinal parameters.
    pub fn set_longitudinal_parameters(&mut self, v: &[f64]) {
        match self {
            Tyre::Unitire(u) => {
                let mut p = [0.0; 10];
                p.copy_from_slice(v);
                u.longitudinal = Some(UniTireLongitudinal { p });
            }
            Tyre::Pac89(t) => {
                let mut b = [0.0; 11];
                b.copy_from_slice(v);
                t.b = Some(b);
            }
            _ => {}
        }
    }

    /// Search box of the longitudinal parameters.
    pub fn longitudinal_bounds(&self) -> Vec<(f64, f64)> {
        match self {
            Tyre::Unitire(u) => u.bounds(),
            Tyre::Pac89(_) => pac89::bounds_around(&pac89::ADAMS_EXAMPLE_B),
            _ => Vec::new(),
        }
    }

    /// Which longitudinal parameters a fit frees (UniTire's sliding-speed
    /// law held, as for the lateral force).
    pub fn longitudinal_free(&self) -> Vec<bool> {
        match self {
            Tyre::Unitire(_) => (0..10).map(|i| i < 7).collect(),
            _ => vec![true; self.longitudinal_parameters().len()],
        }
    }

    /// Fewest distinct loads a lateral fit of this model needs.
    pub fn loads_needed(&self) -> usize {
        match self {
            Tyre::Unitire(_) | Tyre::Pac89(_) => 3,
            _ => 1,
        }
    }
}

impl TyreModel for Tyre {
    fn forces(&self, s: &SlipState) -> TyreForces {
        self.inner().forces(s)
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        match self {
            Tyre::Gim(t) => t.lateral_force(s),
            Tyre::MagicSimple(t) => t.lateral_force(s),
            Tyre::Unitire(t) => t.lateral_force(s),
            Tyre::Pac89(t) => t.lateral_force(s),
            Tyre::Linear(t) => t.lateral_force(s),
            Tyre::MagicFormula(t) => t.lateral_force(s),
        }
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        self.inner().cornering_stiffness(fz)
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

impl Tyre {
    /// True when [`Tyre::point_forces`] gives `mx` and `my`.
    pub fn has_wheel_moments(&self) -> bool {
        matches!(self, Tyre::MagicFormula(_))
    }

    /// Forces and moments at one point; `pressure` (Pa) is read by the
    /// Magic Formula only (`None`: the file's inflation pressure).
    pub fn point_forces(&self, s: &SlipState, pressure: Option<f64>) -> PointForces {
        match self {
            Tyre::MagicFormula(m) => {
                let o = m.evaluate_scaled(
                    &mf::MfInput {
                        fz: s.fz,
                        kappa: s.kappa,
                        alpha: s.alpha,
                        camber: s.camber,
                        speed: s.speed,
                        pressure,
                    },
                    s.mu_scale,
                );
                PointForces {
                    fx: o.fx,
                    fy: o.fy,
                    mz: o.mz,
                    mx: Some(o.mx),
                    my: Some(o.my),
                }
            }
            _ => {
                let f = self.forces(s);
                PointForces {
                    fx: f.fx,
                    fy: f.fy,
                    mz: f.mz,
                    mx: None,
                    my: None,
                }
            }
        }
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

/// `tan α` that keeps its sign and stays finite up to |α| = 90°.
pub(crate) fn safe_tan(alpha: f64) -> f64 {
    let c = alpha.cos().abs().max(1e-12);
    alpha.sin() / c
}

#[cfg(test)]
mod tests;
