//! The Magic Formula's equations at one point, in TNO's ISO-W frame: the
//! per-point shared quantities, pure and combined `Fx` and `Fy`, `Mz`, `Mx`
//! and `My` (what is modelled, the sources and the choices are in the
//! parent module's notes). SI and radians; `α` here is TNO's.

use super::{AlphaStar, MagicFormula, MfOutput, MfVersion};
use std::f64::consts::PI;

const EPS: f64 = 1e-6;
/// `εV` of `cos'α` (eq. 4.E6a): MFeval's 1e-6 m/s; the book suggests 0.1 m/s,
/// which moves the trail by ≈ 0.1/V and is off MFeval's `Mz` by 0.6 % at 17 m/s.
const EPS_V: f64 = 1e-6;
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
pub(super) struct Lateral {
    fy0: f64,
    kya: f64,
    shy: f64,
    svy: f64,
    by: f64,
    cy: f64,
    muy: f64,
}

/// What the formulae of one point share, computed once per point.
pub(super) struct Point {
    fz: f64,
    kappa: f64,
    gamma: f64,
    /// `γ* = sin γ` (`γ` itself with [`AlphaStar::Angle`], as MFeval's
    /// mode without α*): the camber of the lateral and `Mz` formulae.
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
    /// `cos'α = Vcx/(Vc + εV)`, the trail's factor.
    cos_a: f64,
    /// `cos α*` (`cos(tan α)` by default), the residual torque's factor.
    cos_astar: f64,
    lmux_s: f64,
    lmuy_s: f64,
    lmux_p: f64,
    lmuy_p: f64,
}

/// The camber-free factors of the pure lateral force at one point, shared
/// by its evaluation at the point's camber and at zero camber (for `Mz`).
pub(super) struct LateralBase {
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
        // tan α itself inside ±90° (one call instead of sin and cos);
        // beyond, sin α/|cos α| keeps the slip's direction.
        let tan_a = if alpha.abs() < 0.5 * PI {
            alpha.tan()
        } else {
            alpha.sin() / alpha.cos().abs().max(1e-12)
        };
        let (astar, gs) = match self.options.alpha_star {
            AlphaStar::Tan => (tan_a * sgn(vx), gamma.sin()),
            AlphaStar::Angle => (alpha * sgn(vx), gamma),
        };
        // cos'α = Vcx/(Vc + εV) (Pacejka 2012 eq. 4.E6)
        // and Vsy = tan α·|Vx| in either α* mode (MFeval).
        let vsy = vx.abs() * tan_a;
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
            gs,
            vx,
            fz0p,
            dfz: (fz - fz0p) / fz0p,
            dpi,
            p,
            low,
            astar,
            cos_a,
            cos_astar: astar.cos(),
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
    pub(super) fn evaluate_iso(
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

        // `svyk_per_mu`: SVyκ per unit μy (eqs. 4.E66/4.E67), so that the
        // 5.2 aligning moment can take it at the zero-camber μy as MFeval
        // does.
        let (gyk, svyk_per_mu) = if kappa == 0.0 {
            (1.0, 0.0)
        } else {
            let svyk_per_mu = fz
                * (c.RVY1 + c.RVY2 * q.dfz + c.RVY3 * gs)
                * cos_atan(c.RVY4 * q.astar)
                * (c.RVY5 * (c.RVY6 * kappa).atan()).sin()
                * c.LVYKA
                * q.low;
            let shyk = c.RHY1 + c.RHY2 * q.dfz;
            let byk = (c.RBY1 + c.RBY4 * gs * gs) * cos_atan(c.RBY2 * (q.astar - c.RBY3)) * c.LYKA;
            let cyk = c.RCY1;
            let eyk = (c.REY1 + c.REY2 * q.dfz).min(1.0);
            let gyk = mf_cos(byk, cyk, eyk, kappa + shyk) / mf_cos(byk, cyk, eyk, shyk);
            (gyk, svyk_per_mu)
        };
        let fy = gyk * lat.fy0 + lat.muy * svyk_per_mu;
        // The lateral force the trail multiplies: TNO 6.1's `Fy'` (eq.
        // 4.E74: the combined force at zero camber), and MFeval's 5.2 form
        // `Fy − SVyκ` with SVyκ at the zero-camber μy.
        let fy_trail = if self.version == MfVersion::Mf52 {
            fy - base.mu0 * svyk_per_mu
        } else {
            gyk * fy0_flat
        };
        let mz = self.aligning(&q, &lat, kxk, fx, fy, fy_trail);
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
            kyg0: fz * (c.PKY6 + c.PKY7 * dfz) * (1.0 + c.PPY5 * dpi) * c.LKYC,
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
            b.shy0 + c.PHY3 * gs * c.LKYC
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

    /// Aligning moment (ISO-W), `fy_trail` the lateral force the trail
    /// multiplies (TNO's `Fy'`, or `Fy − SVyκ` for 5.2).
    fn aligning(&self, q: &Point, lat: &Lateral, kxk: f64, fx: f64, fy: f64, fy_trail: f64) -> f64 {
        let c = &self.coefficients;
        let (fz, dfz, dpi, gamma, astar) = (q.fz, q.dfz, q.dpi, q.gamma, q.astar);
        let (fz0, fz0p, r0) = (c.FNOMIN, q.fz0p, c.UNLOADED_RADIUS);
        // γ* in SHt, Et and Dr for every version (MFeval); γ itself in Bt
        // and Dt (TNO eqs. A58/A60) and in s (A56).
        let gz = q.gs;
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
            * q.cos_astar;
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
        let et = ((c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz)
            * (1.0 + (c.QEZ4 + c.QEZ5 * gz) * (2.0 / PI) * (bt * ct * at).atan()))
        .min(1.0);
        // TNO scales the trail by λ_Fz0 as well.
        let t = dt * mf_cos(bt, ct, et, at_eq) * q.cos_a * c.LFZO;
        // Eq. 4.E75: Dr already carries its cosine; no cos'α again.
        let mzr = dr * cos_atan(br * ar_eq);
        // TNO (A56): Fy/Fz0 with the unscaled Fz0 and γ itself.
        let s = r0 * (c.SSZ1 + c.SSZ2 * (fy / fz0) + (c.SSZ3 + c.SSZ4 * dfz) * gamma) * c.LS;
        -t * fy_trail + mzr + s * fx
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
