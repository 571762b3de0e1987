//! The Magic Formula 5.2, 6.1 and 6.2 (steady state): pure and combined slip
//! longitudinal force, lateral force and aligning moment, plus overturning
//! and rolling-resistance moments, with camber, inflation pressure (6.1+),
//! the scaling factors λ and the load and speed dependences.
//!
//! Source: Pacejka, *Tire and Vehicle Dynamics*, 3rd ed. (2012), ch. 4.3, and
//! the TNO MF-Tyre/MF-Swift 6.1/6.2 equation manual as implemented by MFeval
//! (M. Furlan). Coefficients carry their `.tir` names ([`MfCoefficients`]).
//!
//! Units: SI and radians at the interface (N, N·m, m/s, Pa, rad).
//!
//! Sign convention — one mapping, applied here at the boundary only. The
//! `.tir` coefficients are fitted in TNO's ISO-W frame, where a positive slip
//! angle gives a negative lateral force (`PKY1 < 0`) and the aligning moment
//! has the opposite sign of `Fy` at small slip. The crate (`FORMATS.md`) has a
//! positive slip angle giving a positive `fy`, and `mz` with the sign of `fy`.
//! Hence `α_ISO = −α`, `fy = Fy_ISO`, `mz = −Mz_ISO`; `κ`, `fx`, camber,
//! `mx` and `my` pass through unchanged (same axes, ISO 8855).
//!
//! `TYRESIDE`: the model always presents a left-side tyre. A file fitted on
//! a right-side tyre is mirrored: evaluated at `−α_ISO`, `−γ`, with `Fy`,
//! `Mz` and `Mx` negated.
//!
//! Choices where Pacejka (2012) and the TNO solver differ (TNO/MFeval is the
//! default throughout):
//! - `α*`: `tan α` (TNO and the book agree on steady state; the book's
//!   small-angle form `α` is [`AlphaStar::Angle`], switchable).
//! - digressive friction factor `A_μ = 10`: `λ'_μ = A_μ·λ*_μ/(1+(A_μ−1)·λ*_μ)`
//!   multiplies only the vertical shifts `SVx`, `SVy`, as in TNO (book eq.
//!   4.E8); switchable off ([`MfOptions::digressive_mu`]) to use `λ*_μ`.
//! - the small `ε` in denominators keeps the sign of the quantity it guards
//!   (`x + ε·sgn x`, sgn 0 = +1), so a negative `Kyα` never crosses zero.
//! - `My`: the TNO 6.1 form (load power `QSY7`, pressure power `QSY8`, speed
//!   terms in `V/LONGVL`), not the book's 5.2 `QSY1..QSY4` polynomial alone.
//! - `Mz`: `Bt` divides by `λ*_μy` (TNO), `Dt` carries `sgn(Vx)` and the
//!   pressure term `PPZ1`, and the combined-slip `s` uses `Fy/Fz0'` (TNO).
//!   For 5.2 files `Bt` has the `QBZ4·γ` term and `SHy` the `PHY3·γ` term.
//! - `Mx`: the TNO 6.1 form (`QSX1..QSX14`, `PPMX1`); 5.2 files leave
//!   `QSX4..QSX14` at 0 and reduce to the 5.2 form.
//! - 6.2 differs from 6.1 only in transient and loaded-radius parts not
//!   modelled here, so both use the same steady-state equations.
//!
//! - `Kyγ0` carries `(1 − PPY5·dpi)`, the sign with which TyreDyn (van
//!   Rossem, 2025, after MFeval) evaluates it; Pacejka (2012) eq. 4.E30
//!   prints `(1 + pPy5·dpi)`.
//! - `cos'α = Vcx/(Vc + εV)` with `εV = 0.1 m/s` (eq. 4.E6); the trail is
//!   multiplied by `λ_Fz0` (TNO); the equivalent slip angles of combined
//!   `Mz` combine tangents (TNO eqs. A54/A55), `s` uses `Fy/Fz0` and `γ`.
//! - the factor on `atan(Bt·Ct·αt)` in `Et`: `2/π` as in the book (default)
//!   or `π/2` as TyreDyn evaluates it ([`TrailCurvature`]).
//!
//! Turn slip is off (all ζ = 1). Low speed: below `VXLOW` the vertical
//! shifts (`SVx`, `SVy`, `SVyκ`) and `My` fade linearly with `|V|/VXLOW`, so
//! a standing tyre at zero slip has no force. Zero or negative load gives
//! zero forces.

mod coefficients;

pub use coefficients::MfCoefficients;

use super::{SlipState, TyreForces, TyreModel};
use crate::error::ParamError;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Which Magic Formula a file holds, from its `FITTYP`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MfVersion {
    /// MF 5.2 / PAC2002 (`FITTYP` 6 or 21).
    Mf52,
    /// MF 6.1 (`FITTYP` 61).
    Mf61,
    /// MF 6.2 (`FITTYP` 62).
    Mf62,
}

impl MfVersion {
    /// The version for a `FITTYP` value.
    pub fn from_fittyp(fittyp: i64) -> Option<Self> {
        match fittyp {
            6 | 21 => Some(Self::Mf52),
            61 => Some(Self::Mf61),
            62 => Some(Self::Mf62),
            _ => None,
        }
    }
    /// The `FITTYP` value written for this version.
    pub fn fittyp(self) -> i64 {
        match self {
            Self::Mf52 => 6,
            Self::Mf61 => 61,
            Self::Mf62 => 62,
        }
    }
}

/// The side of the vehicle the file's tyre was fitted on (`TYRESIDE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TyreSide {
    /// Left (no mirroring).
    #[default]
    Left,
    /// Right: mirrored to a left tyre.
    Right,
}

/// The form of `α*` in the formulae.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum AlphaStar {
    /// `tan α` (TNO).
    #[default]
    Tan,
    /// `α` itself (small-angle form).
    Angle,
}

/// Switches between the documented TNO and book variants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MfOptions {
    /// Form of `α*`.
    pub alpha_star: AlphaStar,
    /// Use the digressive `λ'_μ` (A_μ = 10) in the vertical shifts.
    pub digressive_mu: bool,
    /// The factor on `atan(Bt·Ct·αt)` in the trail curvature `Et`.
    pub trail_curvature: TrailCurvature,
}

/// The factor on `atan(Bt·Ct·αt)` in the trail curvature `Et`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TrailCurvature {
    /// `2/π`, as printed in Pacejka (2012) eq. 4.E44.
    #[default]
    TwoOverPi,
    /// `π/2`, as TyreDyn (van Rossem, 2025) evaluates it.
    PiOverTwo,
}

impl Default for MfOptions {
    fn default() -> Self {
        Self {
            alpha_star: AlphaStar::Tan,
            digressive_mu: true,
            trail_curvature: TrailCurvature::TwoOverPi,
        }
    }
}

/// A Magic Formula tyre (5.2, 6.1 or 6.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MagicFormula {
    /// The formula version.
    pub version: MfVersion,
    /// The side the coefficients were fitted on.
    #[serde(default)]
    pub side: TyreSide,
    /// Model variants.
    #[serde(default)]
    pub options: MfOptions,
    /// The coefficients (SI).
    pub coefficients: MfCoefficients,
}

/// One operating point in the crate's convention (SI, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MfInput {
    /// Vertical load, N.
    pub fz: f64,
    /// Slip ratio.
    pub kappa: f64,
    /// Slip angle, rad (positive gives positive `fy`).
    pub alpha: f64,
    /// Inclination angle, rad.
    pub camber: f64,
    /// Forward speed of the wheel centre, m/s.
    pub speed: f64,
    /// Inflation pressure, Pa (`None`: the file's `INFLPRES`, else `NOMPRES`).
    pub pressure: Option<f64>,
}

/// Forces and moments in the crate's convention.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct MfOutput {
    /// Longitudinal force, N.
    pub fx: f64,
    /// Lateral force, N.
    pub fy: f64,
    /// Aligning moment, N·m (sign of `fy` at small slip).
    pub mz: f64,
    /// Overturning moment, N·m (ISO-W).
    pub mx: f64,
    /// Rolling-resistance moment, N·m (ISO-W: negative when rolling forward).
    pub my: f64,
}

const EPS: f64 = 1e-6;
const EPS_V: f64 = 0.1;
const A_MU: f64 = 10.0;

/// `x` moved away from zero by `EPS` in its own direction.
#[inline]
fn guard(x: f64) -> f64 {
    if x >= 0.0 {
        x + EPS
    } else {
        x - EPS
    }
}

#[inline]
fn sgn(x: f64) -> f64 {
    if x >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// The Magic Formula `D·sin(C·atan(B·x − E·(B·x − atan(B·x))))` without `D`.
#[inline]
fn mf_sin(b: f64, c: f64, e: f64, x: f64) -> f64 {
    let bx = b * x;
    (c * (bx - e * (bx - bx.atan())).atan()).sin()
}

/// `cos(atan(x))` without trigonometry: `1/sqrt(1 + x²)` (exact identity).
#[inline]
fn cos_atan(x: f64) -> f64 {
    1.0 / (1.0 + x * x).sqrt()
}

#[inline]
fn mf_cos(b: f64, c: f64, e: f64, x: f64) -> f64 {
    let bx = b * x;
    (c * (bx - e * (bx - bx.atan())).atan()).cos()
}

/// Pure lateral slip quantities reused by the combined slip and `Mz`.
struct Lateral {
    fy0: f64,
    kya: f64,
    shy: f64,
    svy: f64,
    by: f64,
    cy: f64,
    muy: f64,
}

/// What the formulae of one point share, computed once per point.
struct Point {
    fz: f64,
    kappa: f64,
    gamma: f64,
    /// `sin γ` (TNO's γ in the lateral formulae).
    gs: f64,
    vx: f64,
    /// `Fz0' = FNOMIN·λ_Fz0`.
    fz0p: f64,
    dfz: f64,
    dpi: f64,
    /// Inflation pressure, Pa.
    p: f64,
    /// Low-speed fade factor (1 above `VXLOW`).
    low: f64,
    astar: f64,
    cos_a: f64,
    lmux_s: f64,
    lmuy_s: f64,
    lmux_p: f64,
    lmuy_p: f64,
}

/// The camber-free factors of the pure lateral force at one point, shared
/// by its evaluation at the point's camber and at zero camber (for `Mz`).
struct LateralBase {
    fz: f64,
    /// `PKY1·Fz0'·(1 + PPY1·dpi)·λ_Ky`.
    kya_scale: f64,
    /// `(Fz/Fz0')/(1 + PPY2·dpi)`.
    load_ratio: f64,
    /// `SVy` at zero camber.
    svy0: f64,
    /// `SVyγ/sin γ`.
    svyg_per_gs: f64,
    /// `Kyγ0`.
    kyg0: f64,
    /// `SHy` without its camber term.
    shy0: f64,
    /// `μy` without its camber factor.
    mu0: f64,
    /// `Ey` without its camber and sign factor.
    ey0: f64,
}

impl MagicFormula {
    /// Checks the coefficients the model cannot work without.
    pub fn validate(&self) -> Result<(), ParamError> {
        let c = &self.coefficients;
        ParamError::positive("FNOMIN", c.FNOMIN)?;
        ParamError::positive("UNLOADED_RADIUS", c.UNLOADED_RADIUS)?;
        ParamError::positive("LONGVL", c.LONGVL)?;
        ParamError::positive("VXLOW", c.VXLOW)?;
        ParamError::non_negative("NOMPRES", c.NOMPRES)?;
        ParamError::positive("LFZO", c.LFZO)?;
        for name in MfCoefficients::NAMES {
            ParamError::finite(name, c.get(name).unwrap_or(0.0))?;
        }
        Ok(())
    }

    /// Forces and moments at one point (crate convention in and out).
    pub fn evaluate(&self, p: &MfInput) -> MfOutput {
        self.evaluate_scaled(p, 1.0)
    }

    /// As [`Self::evaluate`] with the friction factors `λ_μx`, `λ_μy`
    /// multiplied by `mu_scale` (the road's friction).
    pub fn evaluate_scaled(&self, p: &MfInput, mu_scale: f64) -> MfOutput {
        if p.fz <= 0.0 || !p.fz.is_finite() {
            return MfOutput::default();
        }
        let mirror = self.side == TyreSide::Right;
        // Crate → ISO-W, then the TYRESIDE mirror.
        let (mut alpha, mut gamma) = (-p.alpha, p.camber);
        if mirror {
            alpha = -alpha;
            gamma = -gamma;
        }
        let mut o = self.evaluate_iso(p.fz, p.kappa, alpha, gamma, p.speed, p.pressure, mu_scale);
        if mirror {
            o.fy = -o.fy;
            o.mz = -o.mz;
            o.mx = -o.mx;
        }
        o.mz = -o.mz;
        o
    }

    fn pressure(&self, p: Option<f64>) -> f64 {
        let c = &self.coefficients;
        p.unwrap_or(if c.INFLPRES > 0.0 {
            c.INFLPRES
        } else {
            c.NOMPRES
        })
    }

    /// The quantities every formula of one point shares, computed once per
    /// point (on the stack: nothing is allocated per evaluation).
    #[allow(clippy::too_many_arguments)]
    fn point(
        &self,
        fz: f64,
        kappa: f64,
        alpha: f64,
        gamma: f64,
        speed: f64,
        pressure: Option<f64>,
        mu_scale: f64,
    ) -> Point {
        let c = &self.coefficients;
        let v52 = self.version == MfVersion::Mf52;
        let fz0p = c.FNOMIN * c.LFZO;
        let p = self.pressure(pressure);
        // 5.2 has no pressure terms; a file without NOMPRES has none either.
        let dpi = if v52 || c.NOMPRES <= 0.0 {
            0.0
        } else {
            (p - c.NOMPRES) / c.NOMPRES
        };
        let vx = speed;
        let low = if vx.abs() < c.VXLOW {
            vx.abs() / c.VXLOW
        } else {
            1.0
        };
        let astar = match self.options.alpha_star {
            // tan α itself inside ±90° (one call instead of sin and cos);
            // beyond, sin α/|cos α| keeps the slip's direction.
            AlphaStar::Tan if alpha.abs() < 0.5 * PI => alpha.tan() * sgn(vx),
            AlphaStar::Tan => {
                let cs = alpha.cos().abs().max(1e-12);
                alpha.sin() / cs * sgn(vx)
            }
            AlphaStar::Angle => alpha * sgn(vx),
        };
        // cos'α = Vcx/(Vc + εV) with εV = 0.1 m/s (Pacejka 2012 eq. 4.E6).
        let vsy = vx * astar;
        let cos_a = vx / ((vx * vx + vsy * vsy).sqrt() + EPS_V);
        // Friction scaling with slip speed (λ*_μ) and its digressive form;
        // without LMUV (the usual file) the slip speed is not needed.
        let speed_factor = if c.LMUV == 0.0 {
            1.0
        } else {
            let vs = vx.abs() * (kappa * kappa + astar * astar).sqrt();
            1.0 / (1.0 + c.LMUV * vs / c.LONGVL)
        };
        let lmux_s = c.LMUX * mu_scale * speed_factor;
        let lmuy_s = c.LMUY * mu_scale * speed_factor;
        let digress = |l: f64| {
            if self.options.digressive_mu {
                A_MU * l / (1.0 + (A_MU - 1.0) * l)
            } else {
                l
            }
        };
        Point {
            fz,
            kappa,
            gamma,
            gs: gamma.sin(),
            vx,
            fz0p,
            dfz: (fz - fz0p) / fz0p,
            dpi,
            p,
            low,
            astar,
            cos_a,
            lmux_s,
            lmuy_s,
            lmux_p: digress(lmux_s),
            lmuy_p: digress(lmuy_s),
        }
    }

    /// The Magic Formula in its own ISO-W frame (`α` here is TNO's).
    ///
    /// Cost: the transcendental calls (`atan`, `sin`, `cos`, `tan`, `exp`,
    /// `ln`) are most of the time. Each is made once per point where the
    /// formulae reuse its value, and skipped where its result is known
    /// exactly: the combined-slip weights are 1 and `SVyκ` is 0 at `κ = 0`
    /// (`Gyκ`) or `α = 0` (`Gxα`), the zero-camber lateral pass is the
    /// cambered one at zero camber, and `atan(√(tan² αt))` is `αt` without
    /// longitudinal slip. (Cephes' `atan`/`sin`/`cos` inlined in place of
    /// glibc's were tried: 10 % fewer instructions, but slower on the
    /// clock, so the C library's stay.)
    #[allow(clippy::too_many_arguments)]
    fn evaluate_iso(
        &self,
        fz: f64,
        kappa: f64,
        alpha: f64,
        gamma: f64,
        speed: f64,
        pressure: Option<f64>,
        mu_scale: f64,
    ) -> MfOutput {
        let c = &self.coefficients;
        let q = self.point(fz, kappa, alpha, gamma, speed, pressure, mu_scale);
        let (fx0, kxk) = self.longitudinal(&q);

        // Pure lateral slip, and the same at zero camber for Mz: the
        // camber-free factors are shared.
        let base = self.lateral_base(&q);
        let lat = self.lateral(&base, q.astar, q.gs);
        let fy0_flat = if q.gs == 0.0 {
            lat.fy0
        } else {
            self.lateral(&base, q.astar, 0.0).fy0
        };

        // Combined slip: weighting functions (exactly 1 at zero slip of the
        // other kind: numerator and denominator are then the same number).
        let gs = q.gs;
        let gxa = if q.astar == 0.0 {
            1.0
        } else {
            let bxa = (c.RBX1 + c.RBX3 * gs * gs) * cos_atan(c.RBX2 * kappa) * c.LXAL;
            let cxa = c.RCX1;
            let exa = (c.REX1 + c.REX2 * q.dfz).min(1.0);
            let shxa = c.RHX1;
            mf_cos(bxa, cxa, exa, q.astar + shxa) / mf_cos(bxa, cxa, exa, shxa)
        };
        let fx = gxa * fx0;

        let (gyk, svyk) = if kappa == 0.0 {
            (1.0, 0.0)
        } else {
            let dvyk =
                lat.muy * fz * (c.RVY1 + c.RVY2 * q.dfz + c.RVY3 * gs) * cos_atan(c.RVY4 * q.astar);
            let svyk = dvyk * (c.RVY5 * (c.RVY6 * kappa).atan()).sin() * c.LVYKA * q.low;
            let shyk = c.RHY1 + c.RHY2 * q.dfz;
            let byk = (c.RBY1 + c.RBY4 * gs * gs) * cos_atan(c.RBY2 * (q.astar - c.RBY3)) * c.LYKA;
            let cyk = c.RCY1;
            let eyk = (c.REY1 + c.REY2 * q.dfz).min(1.0);
            let gyk = mf_cos(byk, cyk, eyk, kappa + shyk) / mf_cos(byk, cyk, eyk, shyk);
            (gyk, svyk)
        };
        let fy = gyk * lat.fy0 + svyk;
        let mz = self.aligning(&q, &lat, kxk, fx, fy, gyk * fy0_flat);
        let (mx, my) = self.wheel_moments(&q, fx, fy);
        MfOutput { fx, fy, mz, mx, my }
    }

    /// Pure longitudinal force `Fx0` and slip stiffness `Kxκ`.
    fn longitudinal(&self, q: &Point) -> (f64, f64) {
        let c = &self.coefficients;
        let (fz, dfz, dpi, gamma) = (q.fz, q.dfz, q.dpi, q.gamma);
        let shx = (c.PHX1 + c.PHX2 * dfz) * c.LHX;
        let kx = q.kappa + shx;
        let cx = c.PCX1 * c.LCX;
        let mux = (c.PDX1 + c.PDX2 * dfz)
            * (1.0 + c.PPX3 * dpi + c.PPX4 * dpi * dpi)
            * (1.0 - c.PDX3 * gamma * gamma)
            * q.lmux_s;
        let dx = mux * fz;
        let load_exp = if c.PKX3 == 0.0 {
            1.0
        } else {
            (c.PKX3 * dfz).exp()
        };
        let kxk = fz
            * (c.PKX1 + c.PKX2 * dfz)
            * load_exp
            * (1.0 + c.PPX1 * dpi + c.PPX2 * dpi * dpi)
            * c.LKX;
        let ex = ((c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz) * (1.0 - c.PEX4 * sgn(kx)) * c.LEX)
            .min(1.0);
        let bx = kxk / guard(cx * dx);
        let svx = fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * q.lmux_p * q.low;
        (dx * mf_sin(bx, cx, ex, kx) + svx, kxk)
    }

    /// The camber-free factors of the pure lateral force at a point.
    fn lateral_base(&self, q: &Point) -> LateralBase {
        let c = &self.coefficients;
        let (fz, dfz, dpi) = (q.fz, q.dfz, q.dpi);
        LateralBase {
            kya_scale: c.PKY1 * q.fz0p * (1.0 + c.PPY1 * dpi) * c.LKY,
            load_ratio: (fz / q.fz0p) / (1.0 + c.PPY2 * dpi),
            svy0: fz * (c.PVY1 + c.PVY2 * dfz) * c.LVY * q.lmuy_p * q.low,
            svyg_per_gs: fz * (c.PVY3 + c.PVY4 * dfz) * c.LKYC * q.lmuy_p * q.low,
            kyg0: fz * (c.PKY6 + c.PKY7 * dfz) * (1.0 - c.PPY5 * dpi) * c.LKYC,
            shy0: (c.PHY1 + c.PHY2 * dfz) * c.LHY,
            mu0: (c.PDY1 + c.PDY2 * dfz) * (1.0 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * q.lmuy_s,
            ey0: (c.PEY1 + c.PEY2 * dfz) * c.LEY,
            fz: q.fz,
        }
    }

    /// Pure lateral force at camber `sin γ = gs` from the shared factors.
    #[inline]
    fn lateral(&self, b: &LateralBase, astar: f64, gs: f64) -> Lateral {
        let c = &self.coefficients;
        let x = b.load_ratio / (c.PKY2 + c.PKY5 * gs * gs);
        // sin(2·atan x) = 2x/(1 + x²): the 5.2 default PKY4 = 2 needs no
        // trigonometry.
        let shape = if c.PKY4 == 2.0 && x.is_finite() {
            2.0 * x / (1.0 + x * x)
        } else {
            (c.PKY4 * x.atan()).sin()
        };
        let kya = b.kya_scale * (1.0 - c.PKY3 * gs.abs()) * shape;
        let svyg = b.svyg_per_gs * gs;
        let svy = b.svy0 + svyg;
        let shy = if self.version == MfVersion::Mf52 {
            b.shy0 + c.PHY3 * gs
        } else {
            b.shy0 + (b.kyg0 * gs - svyg) / guard(kya)
        };
        let ay = astar + shy;
        let cy = c.PCY1 * c.LCY;
        let muy = b.mu0 * (1.0 - c.PDY3 * gs * gs);
        let dy = muy * b.fz;
        let ey = (b.ey0 * (1.0 + c.PEY5 * gs * gs - (c.PEY3 + c.PEY4 * gs) * sgn(ay))).min(1.0);
        let by = kya / guard(cy * dy);
        Lateral {
            fy0: dy * mf_sin(by, cy, ey, ay) + svy,
            kya,
            shy,
            svy,
            by,
            cy,
            muy,
        }
    }

    /// Aligning moment (ISO-W), `fy_flat` the combined lateral force at
    /// zero camber (TNO's `Fy'`).
    fn aligning(&self, q: &Point, lat: &Lateral, kxk: f64, fx: f64, fy: f64, fy_flat: f64) -> f64 {
        let c = &self.coefficients;
        let v52 = self.version == MfVersion::Mf52;
        let (fz, dfz, dpi, gamma, astar) = (q.fz, q.dfz, q.dpi, q.gamma, q.astar);
        let (fz0, fz0p, r0) = (c.FNOMIN, q.fz0p, c.UNLOADED_RADIUS);
        let gz = if v52 { gamma } else { q.gs };
        let kya_p = guard(lat.kya);
        let sht = c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz;
        let at = astar + sht;
        let shf = lat.shy + lat.svy / kya_p;
        let ar = astar + shf;
        // TNO (Besselink et al. 2010, eqs. A58/A60): γ itself, QBZ4 and
        // QDZ3 linear in γ; the book's γ*, |γ*| and QBZ6 are not used.
        let bt = (c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz)
            * (1.0 + c.QBZ4 * gamma + c.QBZ5 * gamma.abs())
            * c.LKY
            / q.lmuy_s;
        let ct = c.QCZ1;
        let dt = fz
            * (r0 / fz0p)
            * (c.QDZ1 + c.QDZ2 * dfz)
            * (1.0 - c.PPZ1 * dpi)
            * (1.0 + c.QDZ3 * gamma + c.QDZ4 * gamma * gamma)
            * c.LTR
            * sgn(q.vx);
        let br = c.QBZ9 * c.LKY / q.lmuy_s + c.QBZ10 * lat.by * lat.cy;
        let dr = fz
            * r0
            * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES
                + ((c.QDZ8 + c.QDZ9 * dfz) * (1.0 + c.PPZ2 * dpi)
                    + (c.QDZ10 + c.QDZ11 * dfz) * gz.abs())
                    * gz
                    * c.LKZC)
            * q.lmuy_s
            * sgn(q.vx)
            * q.cos_a;
        let kratio = kxk / kya_p;
        let k2 = kratio * kratio * q.kappa * q.kappa;
        // TNO (A54/A55): the equivalent angles combine tangents; without
        // longitudinal slip atan(|tan a|)·sgn a is a itself inside ±90°.
        let equivalent = |a: f64| {
            if k2 == 0.0 && a.abs() < 0.5 * PI {
                a
            } else {
                let ta = a.tan();
                (ta * ta + k2).sqrt().atan() * sgn(a)
            }
        };
        let at_eq = equivalent(at);
        let ar_eq = equivalent(ar);
        let et_factor = match self.options.trail_curvature {
            TrailCurvature::TwoOverPi => 2.0 / PI,
            TrailCurvature::PiOverTwo => PI / 2.0,
        };
        let et = ((c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz)
            * (1.0 + (c.QEZ4 + c.QEZ5 * gz) * et_factor * (bt * ct * at).atan()))
        .min(1.0);
        // TNO scales the trail by λ_Fz0 as well.
        let t = dt * mf_cos(bt, ct, et, at_eq) * q.cos_a * c.LFZO;
        let mzr = dr * cos_atan(br * ar_eq) * q.cos_a;
        // TNO (A56): Fy/Fz0 with the unscaled Fz0 and γ itself.
        let s = r0 * (c.SSZ1 + c.SSZ2 * (fy / fz0) + (c.SSZ3 + c.SSZ4 * dfz) * gamma) * c.LS;
        -t * fy_flat + mzr + s * fx
    }

    /// Overturning and rolling-resistance moments (TNO 6.1 forms; 5.2 files
    /// leave the 6.1 terms at 0 and have no load/pressure powers in `My`).
    fn wheel_moments(&self, q: &Point, fx: f64, fy: f64) -> (f64, f64) {
        let c = &self.coefficients;
        let v52 = self.version == MfVersion::Mf52;
        let (fz, gamma, dpi) = (q.fz, q.gamma, q.dpi);
        let (fz0, r0) = (c.FNOMIN, c.UNLOADED_RADIUS);
        let fzr = fz / fz0;
        // Terms whose coefficient is 0 are skipped (their trigonometry
        // multiplies 0).
        let mixed = if c.QSX4 == 0.0 {
            0.0
        } else {
            c.QSX4
                * (c.QSX5 * (c.QSX6 * fzr).powi(2).atan()).cos()
                * (c.QSX7 * gamma + c.QSX8 * (c.QSX9 * fy / fz0).atan()).sin()
        };
        let load_camber = if c.QSX10 == 0.0 {
            0.0
        } else {
            c.QSX10 * (c.QSX11 * fzr).atan() * gamma
        };
        let mx = r0
            * fz
            * c.LMX
            * (c.QSX1 * c.LVMX - c.QSX2 * gamma * (1.0 + c.PPMX1 * dpi)
                + c.QSX3 * fy / fz0
                + mixed
                + load_camber)
            + r0 * c.LMX
                * (fy * (c.QSX13 + c.QSX14 * gamma.abs()) - fz * c.QSX12 * gamma * gamma.abs());

        let vr = q.vx / c.LONGVL;
        let poly = c.QSY1
            + c.QSY2 * fx / fz0
            + c.QSY3 * vr.abs()
            + c.QSY4 * vr.powi(4)
            + (c.QSY5 + c.QSY6 * fzr) * gamma * gamma;
        let powers = if v52 || c.QSY7 == 0.0 {
            fzr
        } else {
            let pr = if c.NOMPRES > 0.0 {
                q.p / c.NOMPRES
            } else {
                1.0
            };
            // Fz^QSY7·p^QSY8 as one exponential of logarithms.
            (c.QSY7 * fzr.ln() + c.QSY8 * pr.ln()).exp()
        };
        let my = -r0 * fz0 * c.LMY * poly * powers * sgn(q.vx) * q.low;
        (mx, my)
    }
}

impl TyreModel for MagicFormula {
    fn forces(&self, s: &SlipState) -> TyreForces {
        let o = self.evaluate_scaled(
            &MfInput {
                fz: s.fz,
                kappa: s.kappa,
                alpha: s.alpha,
                camber: s.camber,
                speed: s.speed,
                pressure: None,
            },
            s.mu_scale,
        );
        TyreForces {
            fx: o.fx,
            fy: o.fy,
            mz: o.mz,
        }
    }
}

/// The lateral pure-slip coefficients identification may move.
const LATERAL_NAMES: [&str; 9] = [
    "PCY1", "PDY1", "PDY2", "PEY1", "PEY2", "PKY1", "PKY2", "PHY1", "PVY1",
];

impl super::Parameterised for MagicFormula {
    fn parameter_names(&self) -> Vec<&'static str> {
        LATERAL_NAMES.to_vec()
    }
    fn parameters(&self) -> Vec<f64> {
        LATERAL_NAMES
            .iter()
            .map(|k| self.coefficients.get(k).unwrap_or(0.0))
            .collect()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        for (k, v) in LATERAL_NAMES.iter().zip(p) {
            self.coefficients.set(k, *v);
        }
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        self.parameters()
            .iter()
            .map(|v| {
                let w = v.abs().max(0.05);
                (v - 2.0 * w, v + 2.0 * w)
            })
            .collect()
    }
}

/// Forces and moments at every point of parallel slices (crate convention;
/// `pressure` `None` uses the file's). `out` is cleared and filled, one row
/// per point; nothing is allocated per point.
pub fn evaluate_batch(tyre: &MagicFormula, points: &[MfInput], out: &mut Vec<MfOutput>) {
    out.clear();
    out.reserve(points.len());
    out.extend(points.iter().map(|p| tyre.evaluate(p)));
}

#[cfg(test)]
mod tests;
