//! PAC89 Magic Formula (Bakker, Nyborg & Pacejka 1989) in the coefficient
//! numbering of the Adams "PAC89" tyre property file: lateral a0..a13,
//! longitudinal b0..b10, aligning c0..c17 (Zhang et al. (2021) uses the lateral set).
//!
//! `Y = D·sin(C·atan(B·x − E·(B·x − atan(B·x)))) + Sv`, `x = X + Sh`, with
//! lateral (X = α in degrees, γ camber in degrees, Fz in kN):
//! `C = a0`, `D = a1·Fz² + a2·Fz`, `BCD = a3·sin(2·atan(Fz/a4))·(1 − a5·|γ|)`,
//! `E = a6·Fz + a7`, `Sh = a8·γ + a9·Fz + a10`, `Sv = a11·Fz·γ + a12·Fz + a13`;
//! longitudinal (X = κ in percent): `C = b0`, `D = b1·Fz² + b2·Fz`,
//! `BCD = (b3·Fz² + b4·Fz)·exp(−b5·Fz)`, `E = b6·Fz² + b7·Fz + b8`,
//! `Sh = b9·Fz + b10`, `Sv = 0`;
//! aligning (X = α in degrees): `C = c0`, `D = c1·Fz² + c2·Fz`,
//! `BCD = (c3·Fz² + c4·Fz)·(1 − c6·|γ|)·exp(−c5·Fz)`,
//! `E = (c7·Fz² + c8·Fz + c9)·(1 − c10·|γ|)`, `Sh = c11·γ + c12·Fz + c13`,
//! `Sv = (c14·Fz² + c15·Fz)·γ + c16·Fz + c17`.
//!
//! The raw equations give Fy > 0 for α > 0 (as this crate wants) and an
//! aligning moment of the opposite sign (SAE); `mz` is returned negated so
//! that it has the sign of `fy` at small slip. The 1987 paper numbers its
//! coefficients differently; a file must name its `form`, and only
//! `adams-pac89` is accepted. Road friction scales D and divides B, so the
//! peak follows μ while the cornering stiffness BCD stays (a tyre's stiffness
//! does not depend on the road). The offsets Sh, Sv make the model not odd.
//! A car's four wheels are evaluated together in SIMD lanes (`lanes.rs`),
//! with their forces' load derivatives for the load-transfer loop (`load_jets.rs`).

mod lanes;
mod load_jets;

use super::{
    Block, Identification, LateralForceOf, LoadRange, Model, ModelParameters, Parameterised,
    SlipOf, SlipState, TyreForces, TyreModel,
};
use crate::error::{ParamError, ParamReason};
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// Which coefficient numbering a PAC89 file uses. Read from its name
/// (`adams-pac89`, `pacejka-1987`, or with `_`) through a string, so that
/// a value of another type inside the `model`-tagged tyre table is named
/// with its key and line like any other.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", try_from = "String")]
pub enum Pac89Form {
    /// The Adams PAC89 numbering (a0..a13, b0..b10, c0..c17): supported.
    AdamsPac89,
    /// The 1987 paper's numbering (a1..a13 ...): refused.
    #[serde(rename = "pacejka-1987")]
    Pacejka1987,
}

impl TryFrom<String> for Pac89Form {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        const NAMES: [&str; 2] = ["adams-pac89", "pacejka-1987"];
        match s.replace('_', "-").as_str() {
            "adams-pac89" => Ok(Pac89Form::AdamsPac89),
            "pacejka-1987" => Ok(Pac89Form::Pacejka1987),
            _ => Err(format!(
                "unknown variant `{s}`, expected one of `{}`, `{}`",
                NAMES[0], NAMES[1]
            )),
        }
    }
}

/// PAC89 coefficients in the Adams numbering.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pac89 {
    /// Coefficient numbering; must be `adams-pac89`.
    pub form: Pac89Form,
    /// Lateral coefficients a0..a13.
    #[serde(deserialize_with = "super::arrays::exactly")]
    pub a: [f64; 14],
    /// Longitudinal coefficients b0..b10 (absent: no longitudinal force).
    #[serde(default, deserialize_with = "super::arrays::exactly_optional")]
    pub b: Option<[f64; 11]>,
    /// Aligning coefficients c0..c17 (absent: no aligning moment).
    #[serde(default, deserialize_with = "super::arrays::exactly_optional")]
    pub c: Option<[f64; 18]>,
}

/// The Adams example coefficient set (the Adams/Tire PAC89 documentation).
pub(crate) const ADAMS_EXAMPLE_A: [f64; 14] = [
    1.65, -34.0, 1250.0, 3036.0, 12.8, 0.00501, -0.02103, 0.77394, 0.002289, 0.013442, 0.003709,
    19.1656, 1.21356, 6.26206,
];
/// Longitudinal part of the Adams example set.
pub(crate) const ADAMS_EXAMPLE_B: [f64; 11] = [
    1.67272, -9.46, 1490.0, 30.0, 176.0, 0.0886, 0.00402, -0.0615, 0.20, 0.0299, -0.176,
];
/// Aligning part of the Adams example set.
pub(crate) const ADAMS_EXAMPLE_C: [f64; 18] = [
    2.34, 1.495, 6.416654, -3.57403, -0.087737, 0.09841, 0.0027699, -0.0001151, 0.10, -1.3329,
    0.025501, -0.02357, 0.03027, -0.0647, 0.0211329, 0.89469, -0.099443, -3.336941,
];

/// A search box around a coefficient set: the shape factor C (index 0)
/// within (1, 3), every other coefficient within ±(5·|c| + 1) of its value.
pub(crate) fn bounds_around(set: &[f64]) -> Vec<(f64, f64)> {
    set.iter()
        .enumerate()
        .map(|(i, c)| {
            if i == 0 {
                (1.0, 3.0)
            } else {
                (c - 5.0 * c.abs() - 1.0, c + 5.0 * c.abs() + 1.0)
            }
        })
        .collect()
}

/// The Magic Formula sine curve `D·sin(C·atan(B·x − E·(B·x − atan(B·x))))`.
#[inline]
pub fn magic_formula(b: f64, c: f64, d: f64, e: f64, x: f64) -> f64 {
    let bx = b * x;
    d * (c * (bx - e * (bx - bx.atan())).atan()).sin()
}

/// [`magic_formula`] in any scalar of `num-dual` (the same arithmetic).
#[inline]
fn magic_formula_of<T: DualNum<f64> + Copy>(b: T, c: T, d: T, e: T, x: T) -> T {
    let bx = b * x;
    d * (c * (bx - e * (bx - bx.atan())).atan()).sin()
}

/// Coefficients of one Magic Formula curve at a given load and camber (in
/// plain numbers, or in a scalar of `num-dual` for the lateral curve's
/// derivatives).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveCoefficients<T = f64> {
    /// Stiffness factor B (per degree or per percent).
    pub b: T,
    /// Shape factor C.
    pub c: T,
    /// Peak value D (N or N·m).
    pub d: T,
    /// Curvature factor E.
    pub e: T,
    /// Horizontal shift (degrees or percent).
    pub sh: T,
    /// Vertical shift (N or N·m).
    pub sv: T,
}

impl CurveCoefficients {
    /// The curve at input `x` (degrees or percent) in the model's units.
    pub fn eval(&self, x: f64) -> f64 {
        magic_formula(self.b, self.c, self.d, self.e, x + self.sh) + self.sv
    }
}

/// B = BCD/(C·D) without 0/0 at vanishing load.
fn stiffness_factor<T: DualNum<f64> + Copy>(bcd: T, c: T, d: T) -> T {
    let cd = c * d;
    if cd.abs() < 1e-12 {
        T::from(0.0)
    } else {
        bcd / cd
    }
}

/// The lateral curve of coefficients `a` (a0..a13) at `fz_kn` (kN) and
/// camber `gamma_deg` (degrees), raw units, in any scalar of `num-dual`:
/// [`Pac89::lateral_curve`] is this in plain numbers. `1 − x` is written
/// `−x + 1` (a dual number takes a plain one on its right only): the same
/// rounding.
fn lateral_curve_of<T: DualNum<f64> + Copy>(
    a: &[T],
    fz_kn: T,
    gamma_deg: f64,
) -> CurveCoefficients<T> {
    let c = a[0];
    let d = a[1] * fz_kn * fz_kn + a[2] * fz_kn;
    // sin(2·atan z) = 2z/(1 + z²): the same value without two
    // transcendental calls in the hot loop.
    let z = fz_kn / a[4];
    let bcd = a[3] * (z * 2.0 / (z * z + 1.0)) * (-(a[5] * gamma_deg.abs()) + 1.0);
    CurveCoefficients {
        b: stiffness_factor(bcd, c, d),
        c,
        d,
        e: a[6] * fz_kn + a[7],
        sh: a[8] * gamma_deg + a[9] * fz_kn + a[10],
        sv: a[11] * fz_kn * gamma_deg + a[12] * fz_kn + a[13],
    }
}

/// [`Pac89::scaled`] in any scalar: the lateral force of a curve at input
/// `x` (degrees) with friction scale `mu` (none unless `mu > 0`).
fn scaled_of<T: DualNum<f64> + Copy>(curve: CurveCoefficients<T>, mu: T, x: T) -> T {
    if mu.re() > 0.0 {
        magic_formula_of(curve.b / mu, curve.c, curve.d * mu, curve.e, x + curve.sh) + curve.sv * mu
    } else {
        T::from(0.0)
    }
}

impl Pac89 {
    /// The Adams example tyre (all three sets).
    pub fn adams_example() -> Self {
        Self {
            form: Pac89Form::AdamsPac89,
            a: ADAMS_EXAMPLE_A,
            b: Some(ADAMS_EXAMPLE_B),
            c: Some(ADAMS_EXAMPLE_C),
        }
    }

    /// Lateral curve at `fz_kn` (kN) and camber `gamma_deg` (degrees), raw units.
    pub(crate) fn lateral_curve(&self, fz_kn: f64, gamma_deg: f64) -> CurveCoefficients {
        lateral_curve_of(&self.a, fz_kn, gamma_deg)
    }

    /// Longitudinal curve at `fz_kn` (kN), raw units (x in percent).
    pub(crate) fn longitudinal_curve(b: &[f64; 11], fz_kn: f64) -> CurveCoefficients {
        let c = b[0];
        let d = b[1] * fz_kn * fz_kn + b[2] * fz_kn;
        let bcd = (b[3] * fz_kn * fz_kn + b[4] * fz_kn) * (-b[5] * fz_kn).exp();
        CurveCoefficients {
            b: stiffness_factor(bcd, c, d),
            c,
            d,
            e: b[6] * fz_kn * fz_kn + b[7] * fz_kn + b[8],
            sh: b[9] * fz_kn + b[10],
            sv: 0.0,
        }
    }

    /// Aligning curve at `fz_kn` (kN) and camber `gamma_deg`, raw units (SAE sign).
    pub(crate) fn aligning_curve(c: &[f64; 18], fz_kn: f64, gamma_deg: f64) -> CurveCoefficients {
        let shape = c[0];
        let d = c[1] * fz_kn * fz_kn + c[2] * fz_kn;
        let bcd = (c[3] * fz_kn * fz_kn + c[4] * fz_kn)
            * (1.0 - c[6] * gamma_deg.abs())
            * (-c[5] * fz_kn).exp();
        CurveCoefficients {
            b: stiffness_factor(bcd, shape, d),
            c: shape,
            d,
            e: (c[7] * fz_kn * fz_kn + c[8] * fz_kn + c[9]) * (1.0 - c[10] * gamma_deg.abs()),
            sh: c[11] * gamma_deg + c[12] * fz_kn + c[13],
            sv: (c[14] * fz_kn * fz_kn + c[15] * fz_kn) * gamma_deg + c[16] * fz_kn + c[17],
        }
    }

    /// Lateral force with friction scaling applied to a curve.
    fn scaled(curve: CurveCoefficients, mu: f64, x: f64) -> f64 {
        // The road's own friction (μ = 1, every replay but a road-friction
        // candidate's) scales nothing: x/1 and x·1 are x exactly, so the
        // division is left out, not the value changed.
        if mu == 1.0 {
            return magic_formula(curve.b, curve.c, curve.d, curve.e, x + curve.sh) + curve.sv;
        }
        let k = if mu > 0.0 { mu } else { return 0.0 };
        magic_formula(curve.b / k, curve.c, curve.d * k, curve.e, x + curve.sh) + curve.sv * k
    }

    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        if self.form != Pac89Form::AdamsPac89 {
            return Err(ParamError::without_value(
                "form",
                ParamReason::Pac89PaperNumbering,
            ));
        }
        for (i, v) in self.a.iter().enumerate() {
            ParamError::finite(&format!("a{i}"), *v)?;
        }
        ParamError::positive("a0", self.a[0])?;
        if self.a[4] == 0.0 {
            return Err(ParamError::new("a4", 0.0, ParamReason::ZeroA4));
        }
        for (i, v) in self.b.iter().flatten().enumerate() {
            ParamError::finite(&format!("b{i}"), *v)?;
        }
        for (i, v) in self.c.iter().flatten().enumerate() {
            ParamError::finite(&format!("c{i}"), *v)?;
        }
        Ok(())
    }
}

impl Pac89 {
    /// Lateral force (N) and its partial derivatives with respect to the
    /// slip angle (N/rad) and the load (N/N) at zero camber and slip ratio,
    /// differentiated in closed form through every load-dependent
    /// coefficient (D, B = BCD/(C·D), E, Sh, Sv) and the friction scaling;
    /// `lateral_force` gives the same force. Equilibrium searches use the
    /// partials for their Jacobians instead of differencing the tyres.
    pub(crate) fn lateral_force_partials(&self, alpha: f64, fz: f64, mu: f64) -> (f64, f64, f64) {
        if fz <= 0.0 || mu <= 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let a = &self.a;
        let f = fz / 1000.0;
        let curve = self.lateral_curve(f, 0.0);
        let (c, e) = (curve.c, curve.e);
        let (bk, dk) = (curve.b / mu, curve.d * mu);
        let x = alpha.to_degrees() + curve.sh;
        let bx = bk * x;
        let at_bx = bx.atan();
        let phi = bx - e * (bx - at_bx);
        let theta = c * phi.atan();
        let (sin, cos) = theta.sin_cos();
        let fy = dk * sin + curve.sv * mu;
        // dY/dφ, and φ's partials in x, B and E.
        let dy_dphi = dk * cos * c / (1.0 + phi * phi);
        let q = 1.0 / (1.0 + bx * bx);
        let dphi_dx = bk * (1.0 - e) + e * bk * q;
        let dphi_db = x * (1.0 - e) + e * x * q;
        let dphi_de = -(bx - at_bx);
        // Load derivatives of the coefficients, per kN.
        let d = curve.d;
        let dd = 2.0 * a[1] * f + a[2];
        let z = f / a[4];
        let dbcd = a[3] * 2.0 * (1.0 - z * z) / ((1.0 + z * z) * (1.0 + z * z)) / a[4];
        let db = if (c * d).abs() < 1e-12 {
            0.0
        } else {
            (dbcd / (c * d) - curve.b * dd / d) / mu
        };
        let dy_df =
            dd * mu * sin + dy_dphi * (dphi_db * db + dphi_de * a[6] + dphi_dx * a[9]) + a[12] * mu;
        (
            fy,
            dy_dphi * dphi_dx * 180.0 / std::f64::consts::PI,
            dy_df / 1000.0,
        )
    }
}

impl TyreModel for Pac89 {
    fn forces(&self, s: &SlipState) -> TyreForces {
        if s.fz <= 0.0 {
            return TyreForces::default();
        }
        let fz_kn = s.fz / 1000.0;
        let gamma = s.camber.to_degrees();
        let alpha = s.alpha.to_degrees();
        let fy = Self::scaled(self.lateral_curve(fz_kn, gamma), s.mu_scale, alpha);
        let fx = self.b.as_ref().map_or(0.0, |b| {
            Self::scaled(
                Self::longitudinal_curve(b, fz_kn),
                s.mu_scale,
                100.0 * s.kappa,
            )
        });
        let mz = self.c.as_ref().map_or(0.0, |c| {
            -Self::scaled(Self::aligning_curve(c, fz_kn, gamma), s.mu_scale, alpha)
        });
        TyreForces { fx, fy, mz }
    }
    /// `|D| + |Sv|` over the load: no force of the curve exceeds it (the
    /// sine's largest value is 1), and it is the peak within the shift.
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        if fz <= 0.0 {
            return 0.0;
        }
        let curve = self.lateral_curve(fz / 1000.0, 0.0);
        (curve.d.abs() + curve.sv.abs()) * mu_scale / fz
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        if s.fz <= 0.0 {
            return 0.0;
        }
        let fz_kn = s.fz / 1000.0;
        Self::scaled(
            self.lateral_curve(fz_kn, s.camber.to_degrees()),
            s.mu_scale,
            s.alpha.to_degrees(),
        )
    }
    /// The four wheels in SIMD lanes ([`Pac89::lateral_forces_lanes`]):
    /// within a few ulp of [`TyreModel::lateral_force`] each.
    fn lateral_forces(&self, rear: &Self, s: &[SlipState; 4]) -> [f64; 4] {
        Self::lateral_forces_lanes([self, self, rear, rear], s)
    }
}

/// The lateral force in any scalar: [`lateral_curve_of`] and [`scaled_of`],
/// the arithmetic of [`TyreModel::lateral_force`] (bit for bit in `f64`);
/// the slip angle in degrees as `α·(180/π)`, as `f64::to_degrees` takes it.
impl LateralForceOf for Pac89 {
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        self.lateral_force_at_camber_of(p, s, 0.0)
    }
    /// `(|D| + |Sv|)·μ/Fz` at zero camber, as
    /// [`TyreModel::friction_coefficient`].
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], fz: T, mu_scale: T) -> T {
        if fz <= 0.0 {
            return T::from(0.0);
        }
        let curve = lateral_curve_of(p, fz / 1000.0, 0.0);
        (curve.d.abs() + curve.sv.abs()) * mu_scale / fz
    }
    fn lateral_force_at_camber_of<T: DualNum<f64> + Copy>(
        &self,
        p: &[T],
        s: &SlipOf<T>,
        camber: f64,
    ) -> T {
        if s.fz <= 0.0 {
            return T::from(0.0);
        }
        let curve = lateral_curve_of(p, s.fz / 1000.0, camber.to_degrees());
        scaled_of(curve, s.mu_scale, s.alpha * 1f64.to_degrees())
    }
}

impl Parameterised for Pac89 {
    fn parameter_names(&self) -> Vec<&'static str> {
        vec![
            "a0", "a1", "a2", "a3", "a4", "a5", "a6", "a7", "a8", "a9", "a10", "a11", "a12", "a13",
        ]
    }
    fn parameters(&self) -> Vec<f64> {
        self.a.to_vec()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.a.copy_from_slice(p);
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![
            (1.0, 2.0),
            (-400.0, 400.0),
            (200.0, 5000.0),
            (100.0, 20000.0),
            (0.5, 50.0),
            (-0.1, 0.1),
            (-1.0, 1.0),
            (-3.0, 1.5),
            (-0.5, 0.5),
            (-0.5, 0.5),
            (-1.0, 1.0),
            (-100.0, 100.0),
            (-100.0, 100.0),
            (-200.0, 200.0),
        ]
    }
}

/// Lateral camber terms a5, a8, a11: identifiable with more than one camber.
const LATERAL_CAMBER_TERMS: [usize; 3] = [5, 8, 11];
/// Aligning camber terms c6, c10, c11, c14, c15.
const ALIGNING_CAMBER_TERMS: [usize; 5] = [6, 10, 11, 14, 15];

impl ModelParameters for Pac89 {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        Pac89::validate(self)
    }
    /// The lateral curve's largest cornering stiffness `a3` (N/deg) by
    /// its size: one typed in kN/deg is refused at its key, and one whose
    /// `a3·sin(2·atan(Fz/a4))` passes any tyre's at a load from 0.1 to
    /// 100 kN.
    fn check_sizes(&self) -> Result<(), ParamError> {
        super::sizes::pac89_cornering_stiffness("a3", self.a[3])?;
        super::sizes::pac89_peak_stiffness(self.a[3], self.a[4])
    }
    /// BCD = a3·sin(2·atan(Fz/a4))·(1 − a5·|γ|) is proportional to a3 (the
    /// offset Sh makes the stiffness at α = 0 only nearly so).
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.a[3] *= k;
    }
    /// D, BCD and E are functions of the load: three loads.
    fn loads_needed(&self) -> usize {
        3
    }
    /// PAC89 states no nominal load; its peak forces `(a1·Fz + a2)·Fz` and
    /// `(b1·Fz + b2)·Fz` (Fz in kN) stop growing with the load at
    /// `−a2/(2·a1)` and `−b2/(2·b1)` where `a1`, `b1` < 0, and past it
    /// more load gives less grip, which no tyre does (the Adams example's
    /// lateral force falls from 10.3 kN at 15 kN to 2.7 kN at 1 MN). The
    /// lighter of those is the heaviest load, 1 % of it the lightest.
    fn load_range(&self) -> Option<LoadRange> {
        let peak = |k1: f64, k2: f64, name: &str| {
            (k1 < 0.0 && k2 > 0.0).then(|| (-k2 / (2.0 * k1) * 1000.0, name.to_string()))
        };
        let lateral = peak(self.a[1], self.a[2], "lateral force (−a2/(2·a1)");
        let longitudinal = self
            .b
            .and_then(|b| peak(b[1], b[2], "longitudinal force (−b2/(2·b1)"));
        let Some((hi, which)) = [lateral, longitudinal]
            .into_iter()
            .flatten()
            .min_by(|x, y| x.0.total_cmp(&y.0))
        else {
            return Some(LoadRange::any_tyre(<Self as Model>::NAME));
        };
        let lo = super::load_range::LIGHT_SHARE * hi;
        Some(LoadRange {
            lo,
            hi,
            basis: format!(
                "it states no nominal load: up to where its peak {which} = {} N) stops growing with the load, from {} % of that",
                crate::format::rounded(hi, 6),
                crate::format::rounded(100.0 * super::load_range::LIGHT_SHARE, 2)
            ),
        })
    }
    fn lateral_free(&self, _loads: usize, cambers: usize) -> Vec<bool> {
        (0..14)
            .map(|i| cambers > 1 || !LATERAL_CAMBER_TERMS.contains(&i))
            .collect()
    }
    /// a3·sin(2·atan(Fz/a4)) is unchanged when a3 and a4 both change sign:
    /// a4 is conventional positive.
    fn canonicalise(&mut self) {
        if self.a[4] < 0.0 {
            self.a[3] = -self.a[3];
            self.a[4] = -self.a[4];
        }
    }
    fn block_names(&self, block: Block) -> Vec<String> {
        match block {
            Block::Aligning => (0..18).map(|i| format!("c{i}")).collect(),
            Block::Longitudinal => (0..11).map(|i| format!("b{i}")).collect(),
        }
    }
    /// Unset blocks start at the Adams example's.
    fn block_parameters(&self, block: Block) -> Vec<f64> {
        match block {
            Block::Aligning => self.c.unwrap_or(ADAMS_EXAMPLE_C).to_vec(),
            Block::Longitudinal => self.b.unwrap_or(ADAMS_EXAMPLE_B).to_vec(),
        }
    }
    fn set_block_parameters(&mut self, block: Block, v: &[f64]) {
        match block {
            Block::Aligning => {
                let mut c = [0.0; 18];
                c.copy_from_slice(v);
                self.c = Some(c);
            }
            Block::Longitudinal => {
                let mut b = [0.0; 11];
                b.copy_from_slice(v);
                self.b = Some(b);
            }
        }
    }
    fn block_bounds(&self, block: Block) -> Vec<(f64, f64)> {
        match block {
            Block::Aligning => bounds_around(&ADAMS_EXAMPLE_C),
            Block::Longitudinal => bounds_around(&ADAMS_EXAMPLE_B),
        }
    }
    fn block_free(&self, block: Block, cambers: usize) -> Vec<bool> {
        match block {
            Block::Aligning => (0..18)
                .map(|i| cambers > 1 || !ALIGNING_CAMBER_TERMS.contains(&i))
                .collect(),
            Block::Longitudinal => vec![true; 11],
        }
    }
}

impl Model for Pac89 {
    const NAME: &'static str = "pac89";
    const IDENTIFICATION: Identification = Identification::SwarmAndTwoStage;
    /// The Adams example's lateral set ([`ADAMS_EXAMPLE_A`]).
    fn start(_fz: f64) -> Option<Self> {
        Some(Pac89 {
            b: None,
            c: None,
            ..Pac89::adams_example()
        })
    }
}
