//! UniTire pure-slip model (Guo Konghui), in the form identified by Zhang & Li (2017)
//! (Zhang & Li 2017, eqs. 3–15).
//!
//! Dimensionless force `F̄ = 1 − exp(−φ − E·φ² − (E² + 1/12)·φ³)` with
//! `φy = Ky·tan α/(μy·Fz)` (cornering) or `φx = Kx·Sx/(μx·Fz)` (longitudinal);
//! `Fy = F̄y·μy·Fz`, `Fx = F̄x·μx·Fz`, `Mz = Fy·Dx`.
//! Load dependence with `Fzn = Fz/Fz_rated`:
//! `E = ½ + (p1/2)·exp(−(Fzn/p2)²)`, `K = Fz·(p3 + p4·Fzn + p5·Fzn²)`,
//! friction against sliding speed Vs:
//! `μ = μs + (μ0 − μs)·exp(−μh²·ln²(Vs/Vsm + exp(−Vs/Vsm)))`,
//! `μ0 = p6·exp(−Fzn/p7)`, `μs = p8·μ0`, `μh = p9·μ0`, `Vsm = p10·μ0`.
//! Aligning arm `Dx = (Dx0 + De)·exp(−D1·φy − D2·φy²) − De`, with
//! `Dx0 = c1 + c2·Fz + c3·Fz²`, `De = c4 + c5·Fz + c6·Fz²`,
//! `D1 = c7·exp(−Fz/c8)`, `D2 = c9·exp(−Fz/c10)`, Fz in **kN** in these ten
//! (the paper leaves the unit open; kN keeps the coefficients of order one),
//! Dx in m. φy enters Dx by magnitude so that Mz stays odd.
//!
//! Slip: Zhang & Li's (2017) `Sx = (ΩRe − V cos α)/(ΩRe)` relates to this crate's
//! `κ = (ΩRe − V)/V` as `Sx = κ/(1 + κ)` at zero slip angle.
//! The road friction scales the final μ. Odd in α and in Sx.

use super::{
    safe_tan, safe_tan_of, Block, LateralForceOf, LoadRange, Model, ModelParameters, Parameterised,
    SlipOf, SlipState, TyreForces, TyreModel,
};
use crate::error::ParamError;
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// Ten parameters of one direction (Zhang & Li's (2017) a1..a10 or b1..b10).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UniTireLateral {
    /// p1..p10 as in the module docs.
    #[serde(deserialize_with = "super::arrays::exactly")]
    pub p: [f64; 10],
}

/// Ten longitudinal parameters a1..a10 (same laws as the lateral ones).
pub type UniTireLongitudinal = UniTireLateral;

/// A neutral start for the aligning arm: 35 mm trail at zero slip falling to
/// −10 mm as φ grows.
pub(crate) const DEFAULT_ALIGNING: [f64; 10] =
    [0.035, 0.004, 0.0, 0.01, 0.0, 0.0, 1.2, 10.0, 0.3, 10.0];

/// A start for the longitudinal parameters (the bundled example's).
pub(crate) const DEFAULT_LONGITUDINAL: [f64; 10] =
    [0.2, 1.0, 18.0, -1.5, 0.1, 1.15, 9.0, 0.75, 0.5, 4.0];

/// Ten aligning-arm parameters c1..c10.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UniTireAligning {
    /// c1..c10 as in the module docs (Fz in kN, Dx in m).
    #[serde(deserialize_with = "super::arrays::exactly")]
    pub c: [f64; 10],
}

/// UniTire parameters for one wheel.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UniTire {
    /// Rated load Fz_rated, N.
    pub rated_load: f64,
    /// Cornering parameters b1..b10.
    pub lateral: UniTireLateral,
    /// Longitudinal parameters a1..a10 (absent: no longitudinal force).
    #[serde(default)]
    pub longitudinal: Option<UniTireLongitudinal>,
    /// Aligning arm parameters c1..c10 (absent: no aligning moment).
    #[serde(default)]
    pub aligning: Option<UniTireAligning>,
}

/// Dimensionless UniTire force F̄(φ, E), odd in φ.
pub(crate) fn dimensionless_force(phi: f64, e: f64) -> f64 {
    dimensionless_force_of(phi, e)
}

// The laws of one direction in any scalar of `num-dual`, with its ten
// parameters `p` as scalars too: the plain methods of `UniTireLateral` are
// these at `f64`, so the generic lateral force has their arithmetic. `1 − x`
// is written `−x + 1` (a dual number takes a plain one on its right only):
// the same rounding.

/// [`dimensionless_force`]: `F̄·sgn φ` (F̄ ≥ 0, so `copysign`'s value).
fn dimensionless_force_of<T: DualNum<f64> + Copy>(phi: T, e: T) -> T {
    let a = phi.abs();
    let f = -((-a - e * a * a - (e * e + 1.0 / 12.0) * a * a * a).exp()) + 1.0;
    f * phi.signum()
}

/// [`UniTireLateral::curvature`].
fn curvature_of<T: DualNum<f64> + Copy>(p: &[T], fzn: T) -> T {
    p[0] * 0.5 * (-(fzn / p[1]).powi(2)).exp() + 0.5
}

/// [`UniTireLateral::stiffness`].
fn stiffness_of<T: DualNum<f64> + Copy>(p: &[T], fz: T, fzn: T) -> T {
    fz * (p[2] + p[3] * fzn + p[4] * fzn * fzn)
}

/// [`UniTireLateral::friction`].
fn friction_of<T: DualNum<f64> + Copy>(p: &[T], fzn: T, vs: T) -> T {
    let mu0 = p[5] * (-fzn / p[6]).exp();
    let mus = p[7] * mu0;
    let muh = p[8] * mu0;
    let vsm = p[9] * mu0;
    let l = (vs / vsm + (-vs / vsm).exp()).ln();
    mus + (mu0 - mus) * (-muh * muh * l * l).exp()
}

impl UniTireLateral {
    /// Curvature factor E at normalised load.
    pub(crate) fn curvature(&self, fzn: f64) -> f64 {
        curvature_of(&self.p, fzn)
    }
    /// Slip stiffness K, N per unit slip.
    pub fn stiffness(&self, fz: f64, fzn: f64) -> f64 {
        stiffness_of(&self.p, fz, fzn)
    }
    /// Friction coefficient at sliding speed `vs` (m/s).
    pub fn friction(&self, fzn: f64, vs: f64) -> f64 {
        friction_of(&self.p, fzn, vs)
    }
    pub(crate) fn scale_stiffness(&mut self, k: f64) {
        self.p[2] *= k;
        self.p[3] *= k;
        self.p[4] *= k;
    }
    /// (force, φ) for slip `s` (tan α or Sx) at load `fz`.
    fn force(&self, slip: f64, fz: f64, rated: f64, vs: f64, mu_scale: f64) -> (f64, f64) {
        let fzn = fz / rated;
        let mu = self.friction(fzn, vs) * mu_scale;
        if mu <= 0.0 {
            return (0.0, f64::INFINITY);
        }
        let phi = self.stiffness(fz, fzn) * slip / (mu * fz);
        (dimensionless_force(phi, self.curvature(fzn)) * mu * fz, phi)
    }
    fn validate(&self, table: &str) -> Result<(), ParamError> {
        for (i, v) in self.p.iter().enumerate() {
            ParamError::finite(&format!("{table}.p[{i}]"), *v)?;
        }
        ParamError::positive(&format!("{table}.p[1]"), self.p[1])?;
        ParamError::positive(&format!("{table}.p[5]"), self.p[5])?;
        ParamError::positive(&format!("{table}.p[6]"), self.p[6])?;
        ParamError::non_negative(&format!("{table}.p[7]"), self.p[7])?;
        ParamError::positive(&format!("{table}.p[9]"), self.p[9])
    }
}

impl UniTireAligning {
    /// Aligning arm Dx, m, at load `fz_kn` (kN) and |φy|.
    pub(crate) fn arm(&self, fz_kn: f64, phi: f64) -> f64 {
        let c = &self.c;
        let dx0 = c[0] + c[1] * fz_kn + c[2] * fz_kn * fz_kn;
        let de = c[3] + c[4] * fz_kn + c[5] * fz_kn * fz_kn;
        let d1 = c[6] * (-fz_kn / c[7]).exp();
        let d2 = c[8] * (-fz_kn / c[9]).exp();
        let p = phi.abs();
        (dx0 + de) * (-d1 * p - d2 * p * p).exp() - de
    }
}

impl UniTire {
    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("rated_load", self.rated_load)?;
        self.lateral.validate("lateral")?;
        if let Some(l) = &self.longitudinal {
            l.validate("longitudinal")?;
        }
        if let Some(a) = &self.aligning {
            for (i, v) in a.c.iter().enumerate() {
                ParamError::finite(&format!("aligning.c[{i}]"), *v)?;
            }
            ParamError::positive("aligning.c[7]", a.c[7])?;
            ParamError::positive("aligning.c[9]", a.c[9])?;
        }
        Ok(())
    }

    fn cornering(&self, s: &SlipState) -> (f64, f64) {
        self.lateral.force(
            safe_tan(s.alpha),
            s.fz,
            self.rated_load,
            s.lateral_sliding_speed(),
            s.mu_scale,
        )
    }
}

impl TyreModel for UniTire {
    fn forces(&self, s: &SlipState) -> TyreForces {
        if s.fz <= 0.0 {
            return TyreForces::default();
        }
        let (fy, phi) = self.cornering(s);
        let mz = match &self.aligning {
            Some(a) if phi.is_finite() => fy * a.arm(s.fz / 1000.0, phi),
            _ => 0.0,
        };
        let fx = match &self.longitudinal {
            Some(l) => {
                let sx = s.kappa / (1.0 + s.kappa).abs().max(1e-9);
                l.force(
                    sx,
                    s.fz,
                    self.rated_load,
                    s.longitudinal_sliding_speed(),
                    s.mu_scale,
                )
                .0
            }
            None => 0.0,
        };
        TyreForces { fx, fy, mz }
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        if s.fz <= 0.0 {
            return 0.0;
        }
        self.cornering(s).0
    }
    /// The lateral friction coefficient without sliding (its dimensionless
    /// force tends to 1 of μ·Fz).
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        self.lateral.friction(fz / self.rated_load, 0.0) * mu_scale
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        if fz <= 0.0 {
            return 0.0;
        }
        self.lateral.stiffness(fz, fz / self.rated_load)
    }
}

/// [`UniTire`]'s cornering force in any scalar: [`UniTireLateral::force`]
/// at `tan α` and the sliding speed `V·|sin α|`, through the same laws.
impl LateralForceOf for UniTire {
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        let zero = T::from(0.0);
        if s.fz <= 0.0 {
            return zero;
        }
        let vs = s.alpha.sin().abs() * s.speed.abs();
        let fzn = s.fz / self.rated_load;
        let mu = friction_of(p, fzn, vs) * s.mu_scale;
        if mu <= 0.0 {
            return zero;
        }
        let phi = stiffness_of(p, s.fz, fzn) * safe_tan_of(s.alpha) / (mu * s.fz);
        dimensionless_force_of(phi, curvature_of(p, fzn)) * mu * s.fz
    }
    /// μ0 at no sliding times the scale, as
    /// [`TyreModel::friction_coefficient`].
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], fz: T, mu_scale: T) -> T {
        friction_of(p, fz / self.rated_load, T::from(0.0)) * mu_scale
    }
}

/// The lateral parameters' names as the tyre file writes them: the
/// elements of `[lateral] p`, numbered p1..p10 as the model's (Zhang & Li's
/// b1..b10); the longitudinal `longitudinal.p1..p10` and the aligning
/// `aligning.c1..c10` alike (`--hold` takes these names).
const LATERAL_NAMES: [&str; 10] = [
    "lateral.p1",
    "lateral.p2",
    "lateral.p3",
    "lateral.p4",
    "lateral.p5",
    "lateral.p6",
    "lateral.p7",
    "lateral.p8",
    "lateral.p9",
    "lateral.p10",
];

impl Parameterised for UniTire {
    fn parameter_names(&self) -> Vec<&'static str> {
        LATERAL_NAMES.to_vec()
    }
    fn parameters(&self) -> Vec<f64> {
        self.lateral.p.to_vec()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.lateral.p.copy_from_slice(p);
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![
            (-2.0, 2.0),
            (0.2, 5.0),
            (1.0, 100.0),
            (-60.0, 60.0),
            (-30.0, 30.0),
            (0.3, 4.0),
            (0.5, 50.0),
            (0.3, 1.0),
            (0.0, 2.0),
            (0.5, 50.0),
        ]
    }
}

/// Search box of the aligning-arm parameters c1..c10 (Fz in kN, Dx in m).
const ALIGNING_BOUNDS: [(f64, f64); 10] = [
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
];

/// The sliding-speed friction law (μs/μ0, μh, Vsm: p8..p10) trades off
/// against the other terms within the noise of a rig test at one speed, so
/// fits of either direction hold it: p1..p7 are free.
fn without_sliding_law() -> Vec<bool> {
    (0..10).map(|i| i < 7).collect()
}

impl ModelParameters for UniTire {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        UniTire::validate(self)
    }
    /// The rated load, and each block's slip stiffness per unit load at
    /// light load, `p3`: one typed per degree or per percent of slip is
    /// refused at its key.
    fn check_sizes(&self) -> Result<(), ParamError> {
        super::sizes::tyre_load("rated_load", self.rated_load)?;
        super::sizes::unitire_stiffness("lateral.p[2]", self.lateral.p[2], false)?;
        match &self.longitudinal {
            Some(l) => super::sizes::unitire_stiffness("longitudinal.p[2]", l.p[2], true),
            None => Ok(()),
        }
    }
    /// K = Fz·(p3 + p4·Fzn + p5·Fzn²) is proportional to p3..p5.
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.lateral.scale_stiffness(k);
    }
    /// E(Fzn), K(Fzn) and μ0(Fzn) need three loads.
    fn loads_needed(&self) -> usize {
        3
    }
    fn lateral_free(&self, _loads: usize, _cambers: usize) -> Vec<bool> {
        without_sliding_law()
    }
    /// Around its rated load: past a few times it the friction
    /// `p6·exp(−Fzn/p7)` takes the force to nothing (0.0003 N at 1 MN).
    fn load_range(&self) -> Option<LoadRange> {
        Some(LoadRange::of_nominal("rated_load", self.rated_load))
    }
    /// p2 enters as (Fzn/p2)² only: its sign is conventional positive.
    fn canonicalise(&mut self) {
        self.lateral.p[1] = self.lateral.p[1].abs();
        if let Some(l) = &mut self.longitudinal {
            l.p[1] = l.p[1].abs();
        }
    }
    fn block_names(&self, block: Block) -> Vec<String> {
        match block {
            Block::Aligning => (1..=10).map(|i| format!("aligning.c{i}")).collect(),
            Block::Longitudinal => (1..=10).map(|i| format!("longitudinal.p{i}")).collect(),
        }
    }
    /// Unset blocks start at [`DEFAULT_ALIGNING`] / [`DEFAULT_LONGITUDINAL`].
    fn block_parameters(&self, block: Block) -> Vec<f64> {
        match block {
            Block::Aligning => self
                .aligning
                .as_ref()
                .map_or(DEFAULT_ALIGNING.to_vec(), |a| a.c.to_vec()),
            Block::Longitudinal => self
                .longitudinal
                .as_ref()
                .map_or(DEFAULT_LONGITUDINAL.to_vec(), |l| l.p.to_vec()),
        }
    }
    fn set_block_parameters(&mut self, block: Block, v: &[f64]) {
        let mut p = [0.0; 10];
        p.copy_from_slice(v);
        match block {
            Block::Aligning => self.aligning = Some(UniTireAligning { c: p }),
            Block::Longitudinal => self.longitudinal = Some(UniTireLongitudinal { p }),
        }
    }
    /// The longitudinal laws are the lateral ones: the same box.
    fn block_bounds(&self, block: Block) -> Vec<(f64, f64)> {
        match block {
            Block::Aligning => ALIGNING_BOUNDS.to_vec(),
            Block::Longitudinal => self.bounds(),
        }
    }
    fn block_free(&self, block: Block, _cambers: usize) -> Vec<bool> {
        match block {
            Block::Aligning => vec![true; 10],
            Block::Longitudinal => without_sliding_law(),
        }
    }
}

impl Model for UniTire {
    const NAME: &'static str = "unitire";
    /// The bundled `tyres/unitire.toml` (Zhang & Li (2017)'s form) rated at
    /// the data's median load, lateral parameters only.
    fn start(fz: f64) -> Option<Self> {
        // The file's table without its `model` key is the model's own.
        let mut table: toml::Table = include_str!("../../tyres/unitire.toml")
            .parse()
            .expect("the bundled UniTire file is TOML");
        table.remove("model");
        let mut u: UniTire = table
            .try_into()
            .expect("the bundled UniTire file holds a UniTire");
        u.rated_load = fz;
        u.longitudinal = None;
        u.aligning = None;
        Some(u)
    }
}
