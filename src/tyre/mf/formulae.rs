//! The Magic Formula's prelude in TNO's ISO-W frame: everything that
//! depends only on the load, pressure and camber, shared by all channels
//! and reusable over many slip points (see [`super::MfAtLoad`]); the
//! slip-dependent part is in [`super::slip`]. What is modelled, the sources
//! and the choices are in the parent module's notes. SI and radians; `α`
//! here is TNO's.

use super::mode::Checked;
use super::{AlphaStar, MagicFormula, MfVersion};
use crate::tyre::kernels;
use std::f64::consts::PI;

pub(super) const EPS: f64 = 1e-6;
/// `εV` of `cos'α` (eq. 4.E6a): MFeval's 1e-6 m/s; the book suggests 0.1 m/s,
/// which moves the trail by ≈ 0.1/V and is off MFeval's `Mz` by 0.6 % at 17 m/s.
pub(super) const EPS_V: f64 = 1e-6;
const A_MU: f64 = 10.0;

/// `x` moved away from zero by `EPS` in its own direction.
#[inline]
pub(super) fn guard(x: f64) -> f64 {
    if x >= 0.0 {
        x + EPS
    } else {
        x - EPS
    }
}

#[inline]
pub(super) fn sgn(x: f64) -> f64 {
    if x >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// `cos(atan(x))` without trigonometry: `1/sqrt(1 + x²)` (exact identity).
#[inline]
pub(super) fn cos_atan(x: f64) -> f64 {
    1.0 / (1.0 + x * x).sqrt()
}

/// The camber-free factors of the pure lateral force at one load and
/// pressure, from which [`LateralAtLoad`] follows at a camber.
#[derive(Debug, Clone, Copy)]
pub(super) struct LateralFree {
    pub(super) kya_scale: f64,
    pub(super) load_ratio: f64,
    pub(super) svy0: f64,
    pub(super) svyg_per_gs: f64,
    pub(super) kyg0: f64,
    pub(super) shy0: f64,
    pub(super) mu0: f64,
    pub(super) ey0: f64,
    pub(super) fz: f64,
}

/// The pure lateral force's factors at one load, pressure and camber (the
/// point's camber, or zero for the trail of 6.x `Mz`).
#[derive(Debug, Clone, Copy)]
pub(super) struct LateralAtLoad {
    /// `Kyα` moved away from zero (`guard`), the divisor of `SHy` and `SHf`.
    pub(super) kya_g: f64,
    /// `SHy` and `SVy` above `VXLOW` (no low-speed fade).
    pub(super) shy: f64,
    pub(super) svy: f64,
    /// `SHy` without its camber term, `Kyγ0·γ*` and `SVyγ` (unfaded): what
    /// `SHy` is rebuilt from below `VXLOW`, where `SVyγ` fades.
    pub(super) shy0: f64,
    pub(super) kyg_gs: f64,
    pub(super) svyg: f64,
    pub(super) cy: f64,
    pub(super) dy: f64,
    pub(super) muy: f64,
    pub(super) by: f64,
    /// `Ey = min(1, ey0·(ey_a − ey_b·sgn αy))`.
    pub(super) ey0: f64,
    pub(super) ey_a: f64,
    pub(super) ey_b: f64,
}

/// The prelude's per-load scalars (see [`MagicFormula::normalised`]).
struct Normalised {
    /// The load given (before the limit checks) and the checked loads.
    fz_given: f64,
    loads: Checked,
    /// `dfz`, `dpi`, `γ*` (sin γ or γ) and `Fz/FNOMIN` of `Mx` and `My`.
    dfz: f64,
    dpi: f64,
    gs: f64,
    fzr_mx: f64,
    fzr_my: f64,
    /// `exp(PKX3·dfz)` and `My`'s powers, the C library's calls.
    load_exp: f64,
    my_powers: f64,
    /// λ*μx, λ'μx, λ*μy, λ'μy, and `μy` without its camber factor.
    lmux_s: f64,
    lmux_p: f64,
    lmuy_s: f64,
    lmuy_p: f64,
    mu0: f64,
}

/// Everything that depends only on the load, pressure and camber (and the
/// friction scale), in the ISO-W frame: computed once per evaluation and
/// shared by all channels, or once for many slip points.
#[derive(Debug, Clone, Copy)]
pub(super) struct Prelude {
    /// The inputs the prelude was built from (rebuilt per point when the
    /// friction depends on slip speed, `LMUV ≠ 0`).
    pub(super) fz: f64,
    pub(super) gamma: f64,
    pub(super) p: f64,
    pub(super) mu_scale: f64,
    // Pure longitudinal.
    pub(super) shx: f64,
    pub(super) cx: f64,
    pub(super) dx: f64,
    pub(super) bx: f64,
    /// `PEX1 + PEX2·dfz + PEX3·dfz²`.
    pub(super) ex_load: f64,
    /// `SVx` above `VXLOW`.
    pub(super) svx: f64,
    // Pure lateral at the point's camber and at zero camber.
    pub(super) lat: LateralAtLoad,
    pub(super) flat: LateralAtLoad,
    /// `μy` without its camber factor (MFeval's 5.2 trail).
    pub(super) mu0: f64,
    // Combined slip.
    pub(super) rbx: f64,
    pub(super) exa: f64,
    /// `Fz·(RVY1 + RVY2·dfz + RVY3·γ*)`: 0 when `SVyκ` is off.
    pub(super) svyk_load: f64,
    pub(super) shyk: f64,
    pub(super) rby: f64,
    pub(super) eyk: f64,
    // Aligning moment.
    pub(super) sht: f64,
    pub(super) bt: f64,
    /// `Bt·Ct`, `Et`'s load part and its camber factor with `2/π`.
    pub(super) btct: f64,
    pub(super) et_load: f64,
    pub(super) et_gamma: f64,
    /// `Dt` and `Dr` without `sgn Vx` (and `Dr` without `cos α*`).
    pub(super) dt: f64,
    pub(super) dr: f64,
    pub(super) br: f64,
    /// `(Kxκ/Kyα')²`, the equivalent slip angles' factor on `κ²`.
    pub(super) kratio2: f64,
    /// `(SSZ3 + SSZ4·dfz)·γ`.
    pub(super) s_gamma: f64,
    // Overturning moment: `r0·Fz·λMx`, the camber/pressure constant, the
    // mixed term's amplitude (with its load cosine) and the load-camber term.
    pub(super) mx_scale: f64,
    pub(super) mx_const: f64,
    pub(super) mx_mixed: f64,
    pub(super) mx_load_camber: f64,
    /// `r0·λMx·(QSX13 + QSX14·|γ|)` and `−r0·λMx·Fz·QSX12·γ·|γ|`.
    pub(super) mx_fy: f64,
    pub(super) mx_gamma: f64,
    // Rolling resistance: `−r0·Fz0·λMy·Fz^QSY7·p^QSY8` split as its two
    // factors, and the camber part of its polynomial.
    pub(super) my_scale: f64,
    pub(super) my_powers: f64,
    pub(super) my_gamma: f64,
}

impl MagicFormula {
    /// The inflation pressure's relative increment `dpi` (0 for 5.2 and for
    /// files without `NOMPRES`: no pressure terms).
    fn dpi(&self, p: f64) -> f64 {
        let c = &self.coefficients;
        if self.version == MfVersion::Mf52 || c.NOMPRES <= 0.0 {
            0.0
        } else {
            (p - c.NOMPRES) / c.NOMPRES
        }
    }

    /// The prelude at load `fz > 0`, ISO camber `gamma`, pressure `p` (Pa),
    /// friction scale `mu_scale` and slip-speed friction factor
    /// `speed_factor` (1 without `LMUV`). Terms whose coefficients are
    /// exactly zero skip their transcendental functions. Its stages are
    /// `#[inline(always)]` functions: one body, as before the split.
    #[inline(always)]
    pub(super) fn prelude(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        speed_factor: f64,
    ) -> Prelude {
        let c = &self.coefficients;
        let v52 = self.version == MfVersion::Mf52;
        let n = self.normalised(fz, gamma, p, mu_scale, speed_factor);
        let (fz, gamma, dfz, dpi, gs) = (n.loads.fz, n.loads.gamma, n.dfz, n.dpi, n.gs);
        let fz0 = c.FNOMIN;
        let r0 = c.UNLOADED_RADIUS;
        let (cx, dx, kxk) = self.longitudinal_load(&n);
        let (lat, flat, c_mx, a_mxg) = self.lateral_and_overturning_load(&n);

        // Aligning moment. γ* in SHt, Et and Dr for every version
        // (MFeval); γ itself in Bt and Dt (TNO eqs. A58/A60) and in s (A56):
        // QBZ4 and QDZ3 linear in γ, the book's γ*, |γ*| and QBZ6 unused.
        let gz = gs;
        let (bt, dt, dr) = self.aligning_terms(n.loads.fz_trail, dfz, dpi, gamma, gz, n.lmuy_s);
        let kratio = kxk / lat.kya_g;

        let (mx_mixed, mx_load_camber) = self.moment_terms(gamma, c_mx, a_mxg);
        let fz_mx = n.loads.fz_mx;

        Prelude {
            fz: n.fz_given,
            gamma,
            p: n.loads.p,
            mu_scale,
            shx: (c.PHX1 + c.PHX2 * dfz) * c.LHX,
            cx,
            dx,
            bx: kxk / guard(cx * dx),
            ex_load: c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz,
            svx: fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * n.lmux_p,
            lat,
            flat,
            mu0: n.mu0,
            rbx: c.RBX1 + c.RBX3 * gs * gs,
            exa: self.clip_e(c.REX1 + c.REX2 * dfz),
            svyk_load: fz * (c.RVY1 + c.RVY2 * dfz + c.RVY3 * gs),
            shyk: c.RHY1 + c.RHY2 * dfz,
            rby: c.RBY1 + c.RBY4 * gs * gs,
            eyk: self.clip_e(c.REY1 + c.REY2 * dfz),
            sht: c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz,
            bt,
            btct: bt * c.QCZ1,
            et_load: c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz,
            et_gamma: (c.QEZ4 + c.QEZ5 * gz) * (2.0 / PI),
            dt,
            dr,
            br: c.QBZ9 * c.LKY / n.lmuy_s + c.QBZ10 * lat.by * lat.cy,
            kratio2: kratio * kratio,
            s_gamma: (c.SSZ3 + c.SSZ4 * dfz) * gamma,
            mx_scale: r0 * fz_mx * c.LMX,
            mx_const: c.QSX1 * c.LVMX - c.QSX2 * gamma * (1.0 + c.PPMX1 * dpi),
            mx_mixed,
            mx_load_camber,
            mx_fy: r0 * c.LMX * (c.QSX13 + c.QSX14 * gamma.abs()),
            mx_gamma: -(r0 * c.LMX) * (fz_mx * c.QSX12 * gamma * gamma.abs()),
            my_scale: -r0 * fz0 * c.LMY,
            my_powers: n.my_powers,
            // MFeval's 5.2 form has no camber term.
            my_gamma: if v52 {
                0.0
            } else {
                (c.QSY5 + c.QSY6 * n.fzr_my) * gamma * gamma
            },
        }
    }

    /// Fz normalisation and the other per-load scalars: the checked load,
    /// camber and pressure, `dfz`, `dpi`, `γ*`, the load ratios of `Mx` and
    /// `My`, their powers and the friction scales (λ*μ, digressive λ'μ).
    #[inline(always)]
    fn normalised(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        speed_factor: f64,
    ) -> Normalised {
        let c = &self.coefficients;
        // The rebuild with slip-speed friction starts from the load given.
        let fz_given = fz;
        let loads = self.checked(fz, gamma, p);
        let fz0 = c.FNOMIN;
        let fz0p = c.FNOMIN * c.LFZO;
        let dfz = (loads.fz - fz0p) / fz0p;
        let (fzr_mx, fzr_my) = (loads.fz_mx / fz0, loads.fz_my / fz0);
        // The C library's exp and ln first: every register is free across
        // their calls here, later they would spill the prelude's values.
        let load_exp = if c.PKX3 == 0.0 {
            1.0
        } else {
            (c.PKX3 * dfz).exp()
        };
        let my_powers = self.my_powers(fzr_my, loads.p);
        let dpi = self.dpi(loads.p);
        let gs = match self.options.alpha_star {
            AlphaStar::Tan => kernels::sin_cos([loads.gamma, 0.0, 0.0, 0.0], [false; 4])[0],
            AlphaStar::Angle => loads.gamma,
        };
        // Friction scaling with slip speed (λ*_μ) and its digressive form.
        let lmux_s = c.LMUX * mu_scale * speed_factor;
        let lmuy_s = c.LMUY * mu_scale * speed_factor;
        let digress = |l: f64| {
            if self.options.digressive_mu {
                A_MU * l / (1.0 + (A_MU - 1.0) * l)
            } else {
                l
            }
        };
        let (lmux_p, lmuy_p) = (digress(lmux_s), digress(lmuy_s));
        let mu0 = (c.PDY1 + c.PDY2 * dfz) * (1.0 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * lmuy_s;
        Normalised {
            fz_given,
            loads,
            dfz,
            dpi,
            gs,
            fzr_mx,
            fzr_my,
            load_exp,
            my_powers,
            lmux_s,
            lmux_p,
            lmuy_s,
            lmuy_p,
            mu0,
        }
    }

    /// Pure longitudinal at the load, everything but the slip:
    /// `(Cx, Dx, Kxκ)`.
    #[inline(always)]
    fn longitudinal_load(&self, n: &Normalised) -> (f64, f64, f64) {
        let c = &self.coefficients;
        let (fz, gamma, dfz, dpi) = (n.loads.fz, n.loads.gamma, n.dfz, n.dpi);
        let cx = c.PCX1 * c.LCX;
        let mux = (c.PDX1 + c.PDX2 * dfz)
            * (1.0 + c.PPX3 * dpi + c.PPX4 * dpi * dpi)
            * (1.0 - c.PDX3 * gamma * gamma)
            * n.lmux_s;
        let dx = mux * fz;
        let kxk = fz
            * (c.PKX1 + c.PKX2 * dfz)
            * n.load_exp
            * (1.0 + c.PPX1 * dpi + c.PPX2 * dpi * dpi)
            * c.LKX;
        (cx, dx, kxk)
    }

    /// Pure lateral at the load: the camber-free factors, then the camber
    /// terms at the point's camber and (6.x, for Mz) at zero camber; with
    /// them, as they share the array passes, the overturning moment's load
    /// angles `cos(QSX5·atan((QSX6·Fz/Fz0)²))` and `atan(QSX11·Fz/Fz0)`.
    #[inline(always)]
    fn lateral_and_overturning_load(
        &self,
        n: &Normalised,
    ) -> (LateralAtLoad, LateralAtLoad, f64, f64) {
        let c = &self.coefficients;
        let (fz, dfz, dpi, gs, fzr_mx) = (n.loads.fz, n.dfz, n.dpi, n.gs, n.fzr_mx);
        let fz0p = c.FNOMIN * c.LFZO;
        let free = LateralFree {
            kya_scale: c.PKY1 * fz0p * (1.0 + c.PPY1 * dpi) * c.LKY,
            load_ratio: (fz / fz0p) / (1.0 + c.PPY2 * dpi),
            svy0: fz * (c.PVY1 + c.PVY2 * dfz) * c.LVY * n.lmuy_p,
            svyg_per_gs: fz * (c.PVY3 + c.PVY4 * dfz) * c.LKYC * n.lmuy_p,
            kyg0: fz * (c.PKY6 + c.PKY7 * dfz) * (1.0 + c.PPY5 * dpi) * c.LKYC,
            shy0: (c.PHY1 + c.PHY2 * dfz) * c.LHY,
            mu0: n.mu0,
            ey0: (c.PEY1 + c.PEY2 * dfz) * c.LEY,
            fz,
        };
        // The angles of Kyα's load curve (at the camber and at zero camber)
        // and of the overturning moment's load terms, in two array passes.
        let (x, x0) = (
            free.load_ratio / (c.PKY2 + c.PKY5 * gs * gs),
            free.load_ratio / c.PKY2,
        );
        let [ax, ax0, a_mx, a_mxg] =
            kernels::atan([x, x0, (c.QSX6 * fzr_mx).powi(2), c.QSX11 * fzr_mx]);
        let [sx, sx0, c_mx, _] = kernels::sin_cos(
            [c.PKY4 * ax, c.PKY4 * ax0, c.QSX5 * a_mx, 0.0],
            [false, false, true, false],
        );
        let lat = self.lateral_at(&free, gs, x, sx);
        let flat = if gs == 0.0 || self.version == MfVersion::Mf52 {
            lat
        } else {
            self.lateral_at(&free, 0.0, x0, sx0)
        };
        (lat, flat, c_mx, a_mxg)
    }

    /// `Bt`, `Dt` and `Dr` of the aligning moment at load `fz` (`dfz`,
    /// `dpi` its load and pressure increments), camber `gamma` and `gz`
    /// (γ*), friction scale `lmuy_s`.
    #[inline]
    fn aligning_terms(
        &self,
        fz: f64,
        dfz: f64,
        dpi: f64,
        gamma: f64,
        gz: f64,
        lmuy_s: f64,
    ) -> (f64, f64, f64) {
        let c = &self.coefficients;
        let (fz0p, r0) = (c.FNOMIN * c.LFZO, c.UNLOADED_RADIUS);
        let bt = (c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz)
            * (1.0 + c.QBZ4 * gamma + c.QBZ5 * gamma.abs())
            * c.LKY
            / lmuy_s;
        let dt = fz
            * (r0 / fz0p)
            * (c.QDZ1 + c.QDZ2 * dfz)
            * (1.0 - c.PPZ1 * dpi)
            * (1.0 + c.QDZ3 * gamma + c.QDZ4 * gamma * gamma)
            * c.LTR;
        let dr = fz
            * r0
            * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES
                + ((c.QDZ8 + c.QDZ9 * dfz) * (1.0 + c.PPZ2 * dpi)
                    + (c.QDZ10 + c.QDZ11 * dfz) * gz.abs())
                    * gz
                    * c.LKZC)
            * lmuy_s;
        (bt, dt, dr)
    }

    /// The pure lateral factors at camber `gs` (γ* or γ) from the
    /// camber-free ones, `x = Fz/(Fz0'·(PKY2 + PKY5·γ*²))` (with its
    /// pressure factor) and `sin(PKY4·atan x)`.
    #[inline(always)]
    fn lateral_at(&self, f: &LateralFree, gs: f64, x: f64, sin_pky4: f64) -> LateralAtLoad {
        let c = &self.coefficients;
        let v52 = self.version == MfVersion::Mf52;
        // sin(2·atan x) = 2x/(1 + x²): exact for the 5.2 default PKY4 = 2.
        let shape = if c.PKY4 == 2.0 && x.is_finite() {
            2.0 * x / (1.0 + x * x)
        } else {
            sin_pky4
        };
        let kya = f.kya_scale * (1.0 - c.PKY3 * gs.abs()) * shape;
        let kya_g = guard(kya);
        let svyg = f.svyg_per_gs * gs;
        let kyg_gs = if v52 { 0.0 } else { f.kyg0 * gs };
        let shy = if v52 {
            f.shy0 + c.PHY3 * gs * c.LKYC
        } else {
            f.shy0 + (kyg_gs - svyg) / kya_g
        };
        let cy = c.PCY1 * c.LCY;
        let muy = f.mu0 * (1.0 - c.PDY3 * gs * gs);
        let dy = muy * f.fz;
        LateralAtLoad {
            kya_g,
            shy,
            svy: f.svy0 + svyg,
            shy0: f.shy0,
            kyg_gs,
            svyg,
            cy,
            dy,
            muy,
            by: kya / guard(cy * dy),
            ey0: f.ey0,
            ey_a: 1.0 + c.PEY5 * gs * gs,
            ey_b: c.PEY3 + c.PEY4 * gs,
        }
    }

    /// The load and camber terms of the overturning moment (0 when their
    /// coefficient is) from `cos(QSX5·atan((QSX6·Fz/Fz0)²))` and
    /// `atan(QSX11·Fz/Fz0)`.
    #[inline(always)]
    fn moment_terms(&self, gamma: f64, cos_mixed: f64, atan_load: f64) -> (f64, f64) {
        let c = &self.coefficients;
        let mx_mixed = if c.QSX4 == 0.0 {
            0.0
        } else {
            c.QSX4 * cos_mixed
        };
        let mx_load_camber = if c.QSX10 == 0.0 {
            0.0
        } else {
            c.QSX10 * atan_load * gamma
        };
        (mx_mixed, mx_load_camber)
    }

    /// The rolling resistance's `(Fz/Fz0)^QSY7·(p/p0)^QSY8` as one
    /// exponential of logarithms (the pressure's skipped when QSY8 = 0), at
    /// load ratio `fzr = Fz/FNOMIN`. The form follows the version, as
    /// MFeval decides it (`FITTYP` 6, MF 5.2: `Fz/Fz0`, i.e. `My ∝ Fz`; any
    /// other: TNO eq. A48), never the value of `QSY7`: a 6.x file with
    /// `QSY7 = 0` has a rolling resistance independent of the load.
    #[inline(always)]
    fn my_powers(&self, fzr: f64, p: f64) -> f64 {
        let c = &self.coefficients;
        if self.version == MfVersion::Mf52 {
            fzr
        } else {
            let pr = if c.NOMPRES > 0.0 { p / c.NOMPRES } else { 1.0 };
            let lp = if c.QSY8 == 0.0 { 0.0 } else { c.QSY8 * pr.ln() };
            (c.QSY7 * fzr.ln() + lp).exp()
        }
    }
}
