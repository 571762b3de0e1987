//! The Magic Formula's equations in TNO's ISO-W frame, in two stages: a
//! prelude of everything that depends only on the load, pressure and camber
//! (shared by all channels and reusable over many slip points, see
//! [`super::MfAtLoad`]), then the slip-dependent part of pure and combined
//! `Fx` and `Fy`, `Mz`, `Mx` and `My` (what is modelled, the sources and the
//! choices are in the parent module's notes). SI and radians; `α` here is
//! TNO's.

use super::kernels;
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

/// `cos(atan(x))` without trigonometry: `1/sqrt(1 + x²)` (exact identity).
#[inline]
fn cos_atan(x: f64) -> f64 {
    1.0 / (1.0 + x * x).sqrt()
}

/// The camber-free factors of the pure lateral force at one load and
/// pressure, from which [`LateralAtLoad`] follows at a camber.
#[derive(Debug, Clone, Copy)]
pub(super) struct LateralFree {
    kya_scale: f64,
    load_ratio: f64,
    svy0: f64,
    svyg_per_gs: f64,
    kyg0: f64,
    shy0: f64,
    mu0: f64,
    ey0: f64,
    fz: f64,
}

/// The pure lateral force's factors at one load, pressure and camber (the
/// point's camber, or zero for the trail of 6.x `Mz`).
#[derive(Debug, Clone, Copy)]
pub(super) struct LateralAtLoad {
    /// `Kyα` moved away from zero (`guard`), the divisor of `SHy` and `SHf`.
    kya_g: f64,
    /// `SHy` and `SVy` above `VXLOW` (no low-speed fade).
    shy: f64,
    svy: f64,
    /// `SHy` without its camber term, `Kyγ0·γ*` and `SVyγ` (unfaded): what
    /// `SHy` is rebuilt from below `VXLOW`, where `SVyγ` fades.
    shy0: f64,
    kyg_gs: f64,
    svyg: f64,
    cy: f64,
    dy: f64,
    muy: f64,
    by: f64,
    /// `Ey = min(1, ey0·(ey_a − ey_b·sgn αy))`.
    ey0: f64,
    ey_a: f64,
    ey_b: f64,
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
    shx: f64,
    cx: f64,
    dx: f64,
    bx: f64,
    /// `PEX1 + PEX2·dfz + PEX3·dfz²`.
    ex_load: f64,
    /// `SVx` above `VXLOW`.
    svx: f64,
    // Pure lateral at the point's camber and at zero camber.
    lat: LateralAtLoad,
    flat: LateralAtLoad,
    /// `μy` without its camber factor (MFeval's 5.2 trail).
    mu0: f64,
    // Combined slip.
    rbx: f64,
    exa: f64,
    /// `Fz·(RVY1 + RVY2·dfz + RVY3·γ*)`: 0 when `SVyκ` is off.
    svyk_load: f64,
    shyk: f64,
    rby: f64,
    eyk: f64,
    // Aligning moment.
    sht: f64,
    bt: f64,
    /// `Bt·Ct`, `Et`'s load part and its camber factor with `2/π`.
    btct: f64,
    et_load: f64,
    et_gamma: f64,
    /// `Dt` and `Dr` without `sgn Vx` (and `Dr` without `cos α*`).
    dt: f64,
    dr: f64,
    br: f64,
    /// `(Kxκ/Kyα')²`, the equivalent slip angles' factor on `κ²`.
    kratio2: f64,
    /// `(SSZ3 + SSZ4·dfz)·γ`.
    s_gamma: f64,
    // Overturning moment: `r0·Fz·λMx`, the camber/pressure constant, the
    // mixed term's amplitude (with its load cosine) and the load-camber term.
    mx_scale: f64,
    mx_const: f64,
    mx_mixed: f64,
    mx_load_camber: f64,
    /// `r0·λMx·(QSX13 + QSX14·|γ|)` and `−r0·λMx·Fz·QSX12·γ·|γ|`.
    mx_fy: f64,
    mx_gamma: f64,
    // Rolling resistance: `−r0·Fz0·λMy·Fz^QSY7·p^QSY8` split as its two
    // factors, and the camber part of its polynomial.
    my_scale: f64,
    my_powers: f64,
    my_gamma: f64,
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
    /// exactly zero skip their transcendental functions.
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
        let fz0 = c.FNOMIN;
        let fz0p = c.FNOMIN * c.LFZO;
        let r0 = c.UNLOADED_RADIUS;
        let dfz = (fz - fz0p) / fz0p;
        let fzr = fz / fz0;
        // The C library's exp and ln first: every register is free across
        // their calls here, later they would spill the prelude's values.
        let load_exp = if c.PKX3 == 0.0 {
            1.0
        } else {
            (c.PKX3 * dfz).exp()
        };
        let my_powers = self.my_powers(fzr, p);
        let dpi = self.dpi(p);
        let gs = match self.options.alpha_star {
            AlphaStar::Tan => kernels::sin_cos([gamma, 0.0, 0.0, 0.0], [false; 4])[0],
            AlphaStar::Angle => gamma,
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

        // Pure longitudinal (everything but the slip).
        let cx = c.PCX1 * c.LCX;
        let mux = (c.PDX1 + c.PDX2 * dfz)
            * (1.0 + c.PPX3 * dpi + c.PPX4 * dpi * dpi)
            * (1.0 - c.PDX3 * gamma * gamma)
            * lmux_s;
        let dx = mux * fz;
        let kxk = fz
            * (c.PKX1 + c.PKX2 * dfz)
            * load_exp
            * (1.0 + c.PPX1 * dpi + c.PPX2 * dpi * dpi)
            * c.LKX;

        // Pure lateral: the camber-free factors, then the point's camber
        // and (6.x, for Mz) zero camber.
        let free = LateralFree {
            kya_scale: c.PKY1 * fz0p * (1.0 + c.PPY1 * dpi) * c.LKY,
            load_ratio: (fz / fz0p) / (1.0 + c.PPY2 * dpi),
            svy0: fz * (c.PVY1 + c.PVY2 * dfz) * c.LVY * lmuy_p,
            svyg_per_gs: fz * (c.PVY3 + c.PVY4 * dfz) * c.LKYC * lmuy_p,
            kyg0: fz * (c.PKY6 + c.PKY7 * dfz) * (1.0 + c.PPY5 * dpi) * c.LKYC,
            shy0: (c.PHY1 + c.PHY2 * dfz) * c.LHY,
            mu0: (c.PDY1 + c.PDY2 * dfz) * (1.0 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * lmuy_s,
            ey0: (c.PEY1 + c.PEY2 * dfz) * c.LEY,
            fz,
        };
        let mu0 = free.mu0;
        // The angles of Kyα's load curve (at the camber and at zero camber)
        // and of the overturning moment's load terms, in two array passes.
        let (x, x0) = (
            free.load_ratio / (c.PKY2 + c.PKY5 * gs * gs),
            free.load_ratio / c.PKY2,
        );
        let [ax, ax0, a_mx, a_mxg] = kernels::atan([x, x0, (c.QSX6 * fzr).powi(2), c.QSX11 * fzr]);
        let [sx, sx0, c_mx, _] = kernels::sin_cos(
            [c.PKY4 * ax, c.PKY4 * ax0, c.QSX5 * a_mx, 0.0],
            [false, false, true, false],
        );
        let lat = self.lateral_at(&free, gs, x, sx);
        let flat = if gs == 0.0 || v52 {
            lat
        } else {
            self.lateral_at(&free, 0.0, x0, sx0)
        };

        // Aligning moment. γ* in SHt, Et and Dr for every version
        // (MFeval); γ itself in Bt and Dt (TNO eqs. A58/A60) and in s (A56):
        // QBZ4 and QDZ3 linear in γ, the book's γ*, |γ*| and QBZ6 unused.
        let gz = gs;
        let (bt, dt, dr) = self.aligning_terms(fz, dfz, dpi, gamma, gz, lmuy_s);
        let kratio = kxk / lat.kya_g;

        let (mx_mixed, mx_load_camber) = self.moment_terms(gamma, c_mx, a_mxg);

        Prelude {
            fz,
            gamma,
            p,
            mu_scale,
            shx: (c.PHX1 + c.PHX2 * dfz) * c.LHX,
            cx,
            dx,
            bx: kxk / guard(cx * dx),
            ex_load: c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz,
            svx: fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * lmux_p,
            lat,
            flat,
            mu0,
            rbx: c.RBX1 + c.RBX3 * gs * gs,
            exa: (c.REX1 + c.REX2 * dfz).min(1.0),
            svyk_load: fz * (c.RVY1 + c.RVY2 * dfz + c.RVY3 * gs),
            shyk: c.RHY1 + c.RHY2 * dfz,
            rby: c.RBY1 + c.RBY4 * gs * gs,
            eyk: (c.REY1 + c.REY2 * dfz).min(1.0),
            sht: c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz,
            bt,
            btct: bt * c.QCZ1,
            et_load: c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz,
            et_gamma: (c.QEZ4 + c.QEZ5 * gz) * (2.0 / PI),
            dt,
            dr,
            br: c.QBZ9 * c.LKY / lmuy_s + c.QBZ10 * lat.by * lat.cy,
            kratio2: kratio * kratio,
            s_gamma: (c.SSZ3 + c.SSZ4 * dfz) * gamma,
            mx_scale: r0 * fz * c.LMX,
            mx_const: c.QSX1 * c.LVMX - c.QSX2 * gamma * (1.0 + c.PPMX1 * dpi),
            mx_mixed,
            mx_load_camber,
            mx_fy: r0 * c.LMX * (c.QSX13 + c.QSX14 * gamma.abs()),
            mx_gamma: -(r0 * c.LMX) * (fz * c.QSX12 * gamma * gamma.abs()),
            my_scale: -r0 * fz0 * c.LMY,
            my_powers,
            my_gamma: (c.QSY5 + c.QSY6 * fzr) * gamma * gamma,
        }
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
    /// exponential of logarithms (the pressure's skipped when QSY8 = 0;
    /// 5.2: `Fz/Fz0`), at load ratio `fzr = Fz/FNOMIN`.
    #[inline(always)]
    fn my_powers(&self, fzr: f64, p: f64) -> f64 {
        let c = &self.coefficients;
        if self.version == MfVersion::Mf52 || c.QSY7 == 0.0 {
            fzr
        } else {
            let pr = if c.NOMPRES > 0.0 { p / c.NOMPRES } else { 1.0 };
            let lp = if c.QSY8 == 0.0 { 0.0 } else { c.QSY8 * pr.ln() };
            (c.QSY7 * fzr.ln() + lp).exp()
        }
    }

    /// The slip-dependent part at one point from a prelude (ISO-W).
    ///
    /// Cost: the transcendental functions (about 35 `atan`, `sin`, `cos`
    /// here, 12 more in the prelude) were 70 % of an evaluation as C
    /// library calls, one at a time. They are now evaluated in array passes
    /// of [`kernels`] (see [`Self::slip`]). Inlined scalar Cephes
    /// `atan`/`sin`/`cos` had been tried before: 10 % fewer instructions but
    /// slower on the clock than glibc's — the gain is in the lanes, not in
    /// the polynomials.
    #[inline]
    pub(super) fn forces_iso(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { self.forces_iso_avx2(l, kappa, alpha, speed) };
        }
        self.forces_iso_lanes(l, kappa, alpha, speed)
    }

    /// [`Self::forces_iso`] compiled with AVX2: four lanes per instruction
    /// instead of SSE2's two. No FMA (Rust never contracts `a·b + c`), so
    /// the result is the same to the bit.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn forces_iso_avx2(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        self.forces_iso_lanes(l, kappa, alpha, speed)
    }

    /// The prelude and the slip part at one point (ISO-W): one evaluation.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn evaluate_iso(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        kappa: f64,
        alpha: f64,
        speed: f64,
    ) -> MfOutput {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { self.evaluate_iso_avx2(fz, gamma, p, mu_scale, kappa, alpha, speed) };
        }
        let pre = self.prelude(fz, gamma, p, mu_scale, 1.0);
        self.forces_iso_lanes(&pre, kappa, alpha, speed)
    }

    /// [`Self::evaluate_iso`] compiled with AVX2 (as [`Self::forces_iso_avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[allow(clippy::too_many_arguments)]
    fn evaluate_iso_avx2(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        kappa: f64,
        alpha: f64,
        speed: f64,
    ) -> MfOutput {
        let pre = self.prelude(fz, gamma, p, mu_scale, 1.0);
        self.forces_iso_lanes(&pre, kappa, alpha, speed)
    }

    #[inline(always)]
    fn forces_iso_lanes(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        let c = &self.coefficients;
        let vx = speed;
        let sgn_vx = sgn(vx);
        let low = if vx.abs() < c.VXLOW {
            vx.abs() / c.VXLOW
        } else {
            1.0
        };
        // tan α = sin α/cos α inside ±90°; beyond, sin α/|cos α| keeps the
        // slip's direction.
        let [sin_a, cos_a, ..] =
            kernels::sin_cos([alpha, alpha, 0.0, 0.0], [false, true, false, false]);
        let tan_a = if alpha.abs() < 0.5 * PI {
            sin_a / cos_a
        } else {
            sin_a / cos_a.abs().max(1e-12)
        };
        let astar = match self.options.alpha_star {
            AlphaStar::Tan => tan_a * sgn_vx,
            AlphaStar::Angle => alpha * sgn_vx,
        };
        let own;
        let l = if c.LMUV == 0.0 {
            l
        } else {
            // λ*_μ depends on the slip speed: the prelude is this point's
            // (rebuilt out of line, this path is rare).
            let vs = vx.abs() * (kappa * kappa + astar * astar).sqrt();
            let speed_factor = 1.0 / (1.0 + c.LMUV * vs / c.LONGVL);
            if speed_factor == 1.0 {
                l
            } else {
                own = self.prelude_out_of_line(l.fz, l.gamma, l.p, l.mu_scale, speed_factor);
                &own
            }
        };
        self.slip(l, kappa, astar, tan_a, vx, sgn_vx, low)
    }

    /// [`Self::prelude`] as a call (for [`super::MfAtLoad`] and the
    /// slip-speed friction path), not inlined into every caller.
    #[inline(never)]
    pub(super) fn prelude_out_of_line(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        speed_factor: f64,
    ) -> Prelude {
        self.prelude(fz, gamma, p, mu_scale, speed_factor)
    }

    /// The shifts and curvature of the pure lateral force at `α*` with the
    /// low-speed fade: `(αy, Ey, SHy, SVy)`.
    #[inline(always)]
    fn lateral_input(&self, f: &LateralAtLoad, astar: f64, low: f64) -> (f64, f64, f64, f64) {
        let (shy, svy) = if low == 1.0 {
            (f.shy, f.svy)
        } else if self.version == MfVersion::Mf52 {
            (f.shy, f.svy * low)
        } else {
            let svyg = f.svyg * low;
            (f.shy0 + (f.kyg_gs - svyg) / f.kya_g, f.svy * low)
        };
        let ay = astar + shy;
        let ey = (f.ey0 * (f.ey_a - f.ey_b * sgn(ay))).min(1.0);
        (ay, ey, shy, svy)
    }

    /// The slip part. Every Magic Formula curve `sin/cos(C·atan(B·x −
    /// E·(B·x − atan(B·x))))` of the point — pure `Fx0`, `Fy0` (and at zero
    /// camber), the numerators and denominators of `Gxα` and `Gyκ`, the
    /// trail — and the other angles are set up first and evaluated together
    /// in a few array passes of [`kernels`], one per stage of their
    /// dependency chain. Where the old scalar code skipped a call because
    /// its result was known (a weight of exactly 1 at zero slip of the other
    /// kind, `SVyκ = 0` at `κ = 0`, `E = 0`) the lanes give the same result
    /// exactly: equal inputs, equal bits.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn slip(
        &self,
        l: &Prelude,
        kappa: f64,
        astar: f64,
        tan_a: f64,
        vx: f64,
        sgn_vx: f64,
        low: f64,
    ) -> MfOutput {
        let c = &self.coefficients;

        // Set-up: pure longitudinal, pure lateral at the point's camber and
        // at zero camber (6.x Mz), the weights' slopes, the trail's angles.
        let kx = kappa + l.shx;
        let ex = (l.ex_load * (1.0 - c.PEX4 * sgn(kx)) * c.LEX).min(1.0);
        let (ay, ey, shy, svy) = self.lateral_input(&l.lat, astar, low);
        let (ay0, ey0, _, svy0) = self.lateral_input(&l.flat, astar, low);
        let bxa = l.rbx * cos_atan(c.RBX2 * kappa) * c.LXAL;
        let byk = l.rby * cos_atan(c.RBY2 * (astar - c.RBY3)) * c.LYKA;
        let at = astar + l.sht;
        let ar = astar + shy + svy / l.lat.kya_g;

        // Stage 1: sin and cos of the trail's and the residual torque's
        // angles (their tangents).
        let [s_at, c_at, s_ar, c_ar] =
            kernels::sin_cos([at, at, ar, ar], [false, true, false, true]);
        // TNO (A54/A55): the equivalent angles combine tangents,
        // atan(√(tan² a + k²))·sgn a = atan(√(sin² a + k²·cos² a)/|cos a|)·sgn a;
        // without longitudinal slip that is a itself inside ±90°.
        let k2 = l.kratio2 * kappa * kappa;
        let eq = |s: f64, co: f64| ((s * s + k2 * co * co).sqrt(), co.abs());
        let ((n_at, d_at), (n_ar, d_ar)) = (eq(s_at, c_at), eq(s_ar, c_ar));

        // Stage 2: the inner atan of every curve, atan(RVY6·κ), Et's atan
        // and the equivalent angles.
        let bx = [
            l.bx * kx,
            l.lat.by * ay,
            l.flat.by * ay0,
            bxa * (astar + c.RHX1),
            bxa * c.RHX1,
            byk * (kappa + l.shyk),
            byk * l.shyk,
        ];
        let e = [ex, ey, ey0, l.exa, l.exa, l.eyk, l.eyk];
        let [i0, i1, i2, i3, i4, i5, i6, a_rvy, a_et, eq_t, eq_r, _] = kernels::atan_ratio(
            [
                bx[0],
                bx[1],
                bx[2],
                bx[3],
                bx[4],
                bx[5],
                bx[6],
                c.RVY6 * kappa,
                l.btct * at,
                n_at,
                n_ar,
                0.0,
            ],
            [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, d_at, d_ar, 1.0],
        );
        let inner = [i0, i1, i2, i3, i4, i5, i6];
        let equivalent = |a: f64, q: f64| {
            if k2 == 0.0 && a.abs() < 0.5 * PI {
                a
            } else {
                q * sgn(a)
            }
        };
        let at_eq = equivalent(at, eq_t);
        let ar_eq = equivalent(ar, eq_r);

        // Stage 3: the outer atan of every curve, the trail's inner one.
        let y: [f64; 7] = std::array::from_fn(|k| bx[k] - e[k] * (bx[k] - inner[k]));
        let bt_at = l.bt * at_eq;
        let [o0, o1, o2, o3, o4, o5, o6, i_t] =
            kernels::atan([y[0], y[1], y[2], y[3], y[4], y[5], y[6], bt_at]);
        let et = (l.et_load * (1.0 + l.et_gamma * a_et)).min(1.0);
        let y_t = bt_at - et * (bt_at - i_t);

        // Stage 4: sin (pure forces) or cos (weights) of C·θ, the sine of
        // SVyκ.
        let (cxa, cyk) = (c.RCX1, c.RCY1);
        let [f_x, f_y, f_y0, gx_n, gx_d, gy_n, gy_d, s_rvy] = kernels::sin_cos(
            [
                l.cx * o0,
                l.lat.cy * o1,
                l.flat.cy * o2,
                cxa * o3,
                cxa * o4,
                cyk * o5,
                cyk * o6,
                c.RVY5 * a_rvy,
            ],
            [false, false, false, true, true, true, true, false],
        );

        let fx0 = l.dx * f_x + l.svx * low;
        let fy0 = l.lat.dy * f_y + svy;
        let fy0_flat = l.flat.dy * f_y0 + svy0;
        // Combined slip: weighting functions (exactly 1 at zero slip of the
        // other kind: numerator and denominator are then the same number).
        let fx = gx_n / gx_d * fx0;
        // `svyk_per_mu`: SVyκ per unit μy (eqs. 4.E66/4.E67), so that the
        // 5.2 aligning moment can take it at the zero-camber μy as MFeval
        // does.
        let svyk_per_mu = l.svyk_load * cos_atan(c.RVY4 * astar) * s_rvy * c.LVYKA * low;
        let gyk = gy_n / gy_d;
        let fy = gyk * fy0 + l.lat.muy * svyk_per_mu;
        // The lateral force the trail multiplies: TNO 6.1's `Fy'` (eq.
        // 4.E74: the combined force at zero camber), and MFeval's 5.2 form
        // `Fy − SVyκ` with SVyκ at the zero-camber μy.
        let fy_trail = if self.version == MfVersion::Mf52 {
            fy - l.mu0 * svyk_per_mu
        } else {
            gyk * fy0_flat
        };

        // Aligning moment. cos'α = Vcx/(Vc + εV) (Pacejka 2012 eq. 4.E6)
        // with Vsy = tan α·|Vx| in either α* mode (MFeval); TNO scales the
        // trail by λ_Fz0 as well.
        let vsy = vx.abs() * tan_a;
        let cos_a = vx / ((vx * vx + vsy * vsy).sqrt() + EPS_V);
        // Stages 5 and 6: the trail's outer atan and cosine, beside the
        // overturning moment's atan and sine (they need Fy), and cos α*.
        let fz0 = c.FNOMIN;
        let [o_t, a_mx, ..] = kernels::atan([y_t, c.QSX9 * fy / fz0, 0.0, 0.0]);
        let [cos_t, sin_mx, cos_astar, _] = kernels::sin_cos(
            [c.QCZ1 * o_t, c.QSX7 * l.gamma + c.QSX8 * a_mx, astar, 0.0],
            [true, false, true, false],
        );
        let t = l.dt * sgn_vx * cos_t * cos_a * c.LFZO;
        // The residual torque ends in cos α* (MFeval); eq. 4.E75: no cos'α
        // again in Mzr.
        let mzr = l.dr * sgn_vx * cos_astar * cos_atan(l.br * ar_eq);
        // TNO (A56): Fy/Fz0 with the unscaled Fz0 and γ itself.
        let r0 = c.UNLOADED_RADIUS;
        let s = r0 * (c.SSZ1 + c.SSZ2 * (fy / fz0) + l.s_gamma) * c.LS;
        let mz = -t * fy_trail + mzr + s * fx;

        // Overturning moment (TNO 6.1; 5.2 files leave the 6.1 terms at 0).
        let mixed = if l.mx_mixed == 0.0 {
            0.0
        } else {
            l.mx_mixed * sin_mx
        };
        let mx = l.mx_scale * (l.mx_const + c.QSX3 * fy / fz0 + mixed + l.mx_load_camber)
            + (fy * l.mx_fy + l.mx_gamma);

        // Rolling-resistance moment (TNO 6.1 form; 5.2 without the powers).
        let vr = vx / c.LONGVL;
        let vr2 = vr * vr;
        let poly =
            c.QSY1 + c.QSY2 * fx / fz0 + c.QSY3 * vr.abs() + c.QSY4 * (vr2 * vr2) + l.my_gamma;
        let my = l.my_scale * poly * l.my_powers * sgn_vx * low;
        MfOutput { fx, fy, mz, mx, my }
    }
}
