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
//! - `α* = tan α` and `γ* = sin γ` (book eqs. 4.E3/4.E4, MFeval's default
//!   mode); [`AlphaStar::Angle`] takes `α* = α`, `γ* = γ` (MFeval's mode
//!   without α*), switchable. `cos'α` uses `Vsy = tan α·|Vx|` in both.
//! - digressive friction factor (book eq. 4.E8, `A_μ = 10`): off by
//!   default, `λ'_μ = λ*_μ`, as MFeval (its `A_μ = 1`, found to match the
//!   TNO solver); switchable on ([`MfOptions::digressive_mu`]), when it
//!   multiplies only the vertical shifts `SVx`, `SVy`.
//! - the small `ε` in denominators keeps the sign of the quantity it guards
//!   (`x + ε·sgn x`, sgn 0 = +1), so a negative `Kyα` never crosses zero.
//! - `My`: for 6.1/6.2 files the TNO form (eq. A48: `−R0·Fz0·λMy·(QSY1 +
//!   … + (QSY5 + QSY6·Fz/Fz0)·γ²)·(Fz/Fz0)^QSY7·(p/p0)^QSY8`, speed terms in
//!   `V/LONGVL`), independent of the load when `QSY7 = 0`; for 5.2 files
//!   the 5.2 form `−R0·Fz·λMy·(QSY1 + QSY2·Fx/Fz0 + QSY3·|V/LONGVL| +
//!   QSY4·(V/LONGVL)⁴)`. The version (`FITTYP`) chooses, as in MFeval.
//! - `Mz` (MFeval's `calculateMz0`/`calculateMz`, checked against its
//!   numbers, `tests/fixtures/tir/README.md`): `Bt` (TNO eq. A58) has
//!   `QBZ4·γ + QBZ5·|γ|` with γ itself and divides by `λ*_μy`; `Dt` (A60)
//!   has `QDZ3·γ + QDZ4·γ²` with γ itself (the book's 4.E43 has `|γ*|`),
//!   `PPZ1` and `sgn(Vx)`; `SHt`, `Et` (`QEZ5`) and `Dr` (`QDZ8..QDZ11`)
//!   take `γ*`; `Et` has the book's `2/π` and is clipped at 1. The residual
//!   torque `Dr` ends in `cos α*` (MFeval; the book prints `cos'α`), and the
//!   combined `Mzr = Dr·cos(atan(Br·αr,eq))` has no further cosine (eq.
//!   4.E75). `Kyα`, `SHy`, `SVy`, `By`, `Cy` inside `Mz` are the cambered
//!   ones; the trail multiplies `Fy' = Gyκ·Fy0(γ = 0)` (6.x) or
//!   `Fy − SVyκ` with SVyκ at the zero-camber `μy` (MFeval's 5.2 form).
//!   5.2 files use `γ*` in `Mz` like 6.x, and `SHy = … + PHY3·γ*·λKyγ`.
//! - `Mx`: the TNO 6.1 form (`QSX1..QSX14`, `PPMX1`); 5.2 files leave
//!   `QSX4..QSX14` at 0 and reduce to the 5.2 form.
//! - 6.2 differs from 6.1 in its forces and moments only in transient
//!   parts not modelled here, so both use the same steady-state equations;
//!   its vertical force (camber, `Fy`-shift and pressure terms) and hence
//!   its loaded radius differ ([`vertical`], [`MagicFormula::loaded_radius`]).
//! - PAC2002 (5.2) files' `LGAX`, `LGAY`, `LGAZ` — ADAMS' camber scaling
//!   factors of the Fx, Fy and Mz channels — are not read: MFeval has no
//!   such parameters (the coefficient set of its `readTIR`, as ported to
//!   MFeval.jl's `TireParams`, lists none), so its 5.2 camber terms are
//!   scaled by `LKYC`/`LKZC` only, as here. The public files checked
//!   against it all have them at 1; a file with one of them ≠ 1 is
//!   evaluated as MFeval evaluates it.
//!
//! - `Kyγ0` carries `(1 + PPY5·dpi)` (book eq. 4.E30 and MFeval; TyreDyn
//!   (van Rossem, 2025) evaluates `1 − PPY5·dpi`, which moves its cambered
//!   `Fy` at pressures off `NOMPRES`).
//! - `cos'α = Vcx/(Vc + εV)` with `εV = 1e-6 m/s` (MFeval; eq. 4.E6a suggests 0.1); the trail is
//!   multiplied by `λ_Fz0` (TNO); the equivalent slip angles of combined
//!   `Mz` combine tangents (TNO eqs. A54/A55), `s` uses `Fy/Fz0` and `γ`.
//! - MFeval's modes (`useMode` 111, 121, 211, 221; [`MfMode`], default 121):
//!   with its limit checks on, inputs are saturated to the file's ranges
//!   ([`MfLimits`]) and the curvature factors `E` clipped at 1; off, both
//!   are evaluated as given. Turn slip (units digit 2) is not modelled.
//!   In every mode, as MFeval: below `FZMIN`, `Mx` takes `Fz·(Fz/FZMIN)²`
//!   and `My` `Fz·(Fz/FZMIN)`; `My` follows the wheel's direction of
//!   rotation (it changes sign, over a quarter sine, where the wheel spins
//!   backward past κ ≈ −1).
//!
//! Turn slip is off (all ζ = 1). Low speed: below `VXLOW` the vertical
//! shifts (`SVx`, `SVy`, `SVyκ`) and `My` fade linearly with `|V|/VXLOW`, so
//! a standing tyre at zero slip has no force, in every mode (MFeval's own
//! low-speed reductions, taken with its limit checks, differ below
//! `VXLOW`; its references here are at 16.7 m/s). Zero or negative load gives
//! zero forces.

mod channel;
mod coefficients;
mod formulae;
mod lateral_of;
mod mode;
mod pure_curves;
mod rim_load;
pub use pure_curves::PeakFriction;
pub(crate) use pure_curves::WARN_FRICTION;
mod slip;
pub mod stated;
mod version;
pub mod vertical;

pub use channel::{Held, MfChannel, MfPoint};
pub use coefficients::{MfCoefficients, MfCoefficientsOf};
pub use mode::{InputRange, MfLimits, MfMode};
pub use version::MfVersion;

use super::{
    Identification, Model, ModelParameters, PointForces, SlipState, StagedFit, TyreForces,
    TyreModel,
};
use crate::error::ParamError;
use serde::{Deserialize, Serialize};

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
    /// `α* = tan α`, `γ* = sin γ` (TNO; MFeval's default mode).
    #[default]
    Tan,
    /// `α* = α`, `γ* = γ` (MFeval's mode without α*).
    Angle,
}

/// Switches between the documented TNO and book variants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MfOptions {
    /// Form of `α*`.
    pub alpha_star: AlphaStar,
    /// Use the book's digressive `λ'_μ` (A_μ = 10) in the vertical shifts
    /// (off: `λ'_μ = λ*_μ`, MFeval).
    pub digressive_mu: bool,
    /// MFeval's limit checks ([`MfMode`]): inputs saturated to
    /// [`MagicFormula::limits`], `E` clipped at 1.
    pub limit_checks: bool,
}

impl Default for MfOptions {
    fn default() -> Self {
        Self {
            alpha_star: AlphaStar::Tan,
            digressive_mu: false,
            limit_checks: true,
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
    /// The file's validity ranges (used with the limit checks on).
    #[serde(default)]
    pub limits: MfLimits,
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
        // A negative friction scale turns the peak, and so the force,
        // against its slip (`LMUY = -1` was read silently, and held with
        // `--hold`, where `LFZO = -1` was refused); 0 is a tyre without
        // that force, said by the evaluations' checks.
        ParamError::non_negative("LMUX", c.LMUX)?;
        ParamError::non_negative("LMUY", c.LMUY)?;
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
        // The prelude stays on this stack frame (no MfAtLoad moved around).
        let mirror = self.side == TyreSide::Right;
        let gamma = if mirror { -p.camber } else { p.camber };
        let pressure = self.pressure(p.pressure);
        let alpha = if mirror { p.alpha } else { -p.alpha };
        let o = self.evaluate_iso(p.fz, gamma, pressure, mu_scale, p.kappa, alpha, p.speed);
        to_crate(o, mirror)
    }

    /// The load-, pressure- and camber-dependent part of the formulae,
    /// prepared once for evaluating many slip points at one wheel load
    /// (crate convention; `pressure` `None` uses the file's). The result of
    /// [`MfAtLoad::forces`] equals [`Self::evaluate`]'s at the same point.
    pub fn at_load(&self, fz: f64, pressure: Option<f64>, camber: f64) -> MfAtLoad<'_> {
        self.at_load_scaled(fz, pressure, camber, 1.0)
    }

    /// As [`Self::at_load`] with the friction factors multiplied by
    /// `mu_scale` (as [`Self::evaluate_scaled`]).
    pub fn at_load_scaled(
        &self,
        fz: f64,
        pressure: Option<f64>,
        camber: f64,
        mu_scale: f64,
    ) -> MfAtLoad<'_> {
        let mirror = self.side == TyreSide::Right;
        // Crate → ISO-W, then the TYRESIDE mirror (camber here, α per point).
        let gamma = if mirror { -camber } else { camber };
        let prelude = (fz > 0.0 && fz.is_finite())
            .then(|| self.prelude_out_of_line(fz, gamma, self.pressure(pressure), mu_scale, 1.0));
        MfAtLoad {
            tyre: self,
            mirror,
            prelude,
        }
    }

    /// Whether the file has a vertical model, hence a loaded radius: a 6.1
    /// or 6.2 file with a positive `VERTICAL_STIFFNESS` and `NOMPRES`.
    pub fn has_vertical_model(&self) -> bool {
        let c = &self.coefficients;
        self.version != MfVersion::Mf52 && c.VERTICAL_STIFFNESS > 0.0 && c.NOMPRES > 0.0
    }

    /// The loaded radius (m) at a point, as MFeval computes it for a 6.1 or
    /// 6.2 file ([`vertical`]); `None` for a 5.2 file or one without
    /// `VERTICAL_STIFFNESS` (no vertical model, [`Self::has_vertical_model`])
    /// and at a non-finite load, and at a load the vertical model does not
    /// carry ([`Self::loaded_radius_or_not_carried`]). At zero or negative
    /// load (the wheel off the road) it is the free-spinning radius `RΩ` at
    /// zero load.
    pub fn loaded_radius(&self, p: &MfInput) -> Option<f64> {
        self.loaded_radius_or_not_carried(p)?.ok()
    }

    /// [`Self::loaded_radius`], with a load the vertical model carries at
    /// no loaded radius above 0 said as such ([`vertical::NotCarried`]).
    pub fn loaded_radius_or_not_carried(
        &self,
        p: &MfInput,
    ) -> Option<Result<f64, vertical::NotCarried>> {
        // MF 6.1's vertical force has no camber, Fy-shift or Fy-power
        // terms: a 6.1 file that carries those keys is evaluated without.
        let mf61;
        let c = if self.version == MfVersion::Mf61 {
            let mut k = self.coefficients.clone();
            for name in vertical::MF62_ONLY {
                k.set(name, 0.0);
            }
            mf61 = k;
            &mf61
        } else {
            &self.coefficients
        };
        if !self.has_vertical_model() || !p.fz.is_finite() {
            return None;
        }
        let mirror = self.side == TyreSide::Right;
        let gamma = if mirror { -p.camber } else { p.camber };
        let alpha = if mirror { p.alpha } else { -p.alpha };
        let pressure = self.pressure(p.pressure);
        if p.fz <= 0.0 {
            // Off the road: no deflection, the free radius at zero load.
            let dpi = (self.checked(0.0, gamma, pressure).p - c.NOMPRES) / c.NOMPRES;
            return Some(Ok(vertical::radii(c, 0.0, p.kappa, p.speed, dpi).free));
        }
        // ISO-W forces of the (mirrored) tyre; the vertical model is even
        // under the mirror.
        let o = self.evaluate_iso(p.fz, gamma, pressure, 1.0, p.kappa, alpha, p.speed);
        let checked = self.checked(p.fz, gamma, pressure);
        let dpi = (checked.p - c.NOMPRES) / c.NOMPRES;
        let state = vertical::VerticalState {
            gamma: checked.gamma,
            dpi,
            radii: vertical::radii(c, p.fz, p.kappa, p.speed, dpi),
            fx: o.fx,
            fy: o.fy,
        };
        Some(vertical::loaded_radius(c, &state, checked.fz))
    }

    /// The inflation pressure a point without one is evaluated at, Pa
    /// (a vehicle's wheels: a scenario states none), and the key that
    /// gives it: `INFLPRES`, else `NOMPRES`. `None` where no pressure moves
    /// the model (a 5.2 file, or a 6.x file without `NOMPRES`: the
    /// pressure terms are off).
    pub fn own_pressure(&self) -> Option<(f64, &'static str)> {
        let c = &self.coefficients;
        if self.version == MfVersion::Mf52 || c.NOMPRES <= 0.0 {
            return None;
        }
        Some(match c.INFLPRES > 0.0 {
            true => (c.INFLPRES, "INFLPRES"),
            false => (c.NOMPRES, "NOMPRES"),
        })
    }

    pub(super) fn pressure(&self, p: Option<f64>) -> f64 {
        let c = &self.coefficients;
        p.unwrap_or(if c.INFLPRES > 0.0 {
            c.INFLPRES
        } else {
            c.NOMPRES
        })
    }
}

/// A Magic Formula tyre at one wheel load, pressure and camber
/// ([`MagicFormula::at_load`]): what depends only on those is computed once
/// (about a quarter of the transcendental functions of a combined-slip
/// point, with camber), and [`Self::forces`] evaluates the slip part.
#[derive(Debug, Clone, Copy)]
pub struct MfAtLoad<'a> {
    tyre: &'a MagicFormula,
    mirror: bool,
    /// `None` at zero, negative or non-finite load: no force.
    prelude: Option<formulae::Prelude>,
}

impl MfAtLoad<'_> {
    /// Forces and moments at slip ratio `kappa`, slip angle `alpha` (rad)
    /// and forward speed `speed` (m/s), crate convention in and out.
    pub fn forces(&self, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        let Some(pre) = &self.prelude else {
            return MfOutput::default();
        };
        // Crate → ISO-W (α_ISO = −α), then the TYRESIDE mirror.
        let alpha = if self.mirror { alpha } else { -alpha };
        to_crate(self.tyre.forces_iso(pre, kappa, alpha, speed), self.mirror)
    }
}

/// ISO-W outputs (of the mirrored tyre when `mirror`) → crate convention.
#[inline]
fn to_crate(mut o: MfOutput, mirror: bool) -> MfOutput {
    if mirror {
        o.fy = -o.fy;
        o.mz = -o.mz;
        o.mx = -o.mx;
    }
    o.mz = -o.mz;
    o
}

impl TyreModel for MagicFormula {
    /// `|μy|·Fz`'s coefficient in closed form ([`MagicFormula::friction_of`]),
    /// not the default's scan of the lateral force.
    fn friction_coefficient(&self, fz: f64, mu_scale: f64) -> f64 {
        let c = &self.coefficients;
        self.friction_of((c.PDY1, c.PDY2), fz, mu_scale)
    }
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

impl ModelParameters for MagicFormula {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        MagicFormula::validate(self)
    }
    /// The coefficients' sizes, then `FZMAX`'s: `FZMAX = 18` (kN)
    /// clamped every load to 18 N.
    fn check_sizes(&self) -> Result<(), ParamError> {
        crate::tyre::sizes::magic_formula(&self.coefficients)?;
        self.limits.fz_max_in_newtons(self.coefficients.FNOMIN)
    }
    /// `Kyα` is proportional to its scaling factor `λ_Kyα`.
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.coefficients.LKY *= k;
    }
    fn point_forces(&self, s: &SlipState, pressure: Option<f64>) -> PointForces {
        let o = self.evaluate_scaled(
            &MfInput {
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
    fn has_wheel_moments(&self) -> bool {
        true
    }
}

impl MagicFormula {
    /// Wei et al.'s (2010) staged fit of an MF 6.1 (`identify --model mf61`).
    pub const FIT_MF61: StagedFit = StagedFit {
        name: "mf61",
        version: MfVersion::Mf61,
    };
    /// The same stages for an MF 6.2 (`identify --model mf62`).
    pub const FIT_MF62: StagedFit = StagedFit {
        name: "mf62",
        version: MfVersion::Mf62,
    };
}

impl Model for MagicFormula {
    const NAME: &'static str = "magic-formula";
    const IDENTIFICATION: Identification =
        Identification::Staged(&[Self::FIT_MF61, Self::FIT_MF62]);
    /// None: the Magic Formula is identified in stages
    /// (`identify::mf_staged`, Wei et al. (2010)), not from a start tyre.
    fn start(_fz: f64) -> Option<Self> {
        None
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
mod channel_tests;
#[cfg(test)]
mod tests;
