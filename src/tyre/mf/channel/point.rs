//! The formulae of one channel at a prepared point, in a scalar `T` (see
//! the parent module): the point's inputs after the limit checks and the
//! crate → ISO-W mapping ([`Inputs`]), the parts prepared in plain numbers
//! because no variable enters them ([`Parts`]), and the terms. SI and
//! radians; `α` here is TNO's.

use super::super::coefficients::MfCoefficientsOf;
use super::super::formulae::EPS;
use super::super::{MagicFormula, MfVersion};
use num_dual::DualNum;
use std::f64::consts::PI;

/// The inputs of a point after the limit checks and the crate → ISO-W
/// mapping (plain numbers: no coefficient is fitted through them).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Inputs {
    pub(super) fz: f64,
    pub(super) fz_trail: f64,
    pub(super) fz_mx: f64,
    pub(super) fz_my: f64,
    /// Inclination (ISO-W, checked) and `γ*`.
    pub(super) gamma: f64,
    pub(super) gs: f64,
    pub(super) p: f64,
    pub(super) kappa: f64,
    pub(super) astar: f64,
    /// `sgn Vx·cos'α` of the trail (eq. 4.E6, `Vsy = tan α·|Vx|`) and
    /// `sgn Vx·cos α*` of the residual torque.
    pub(super) trail_cos: f64,
    pub(super) residual_cos: f64,
    pub(super) vx: f64,
    pub(super) sgn_vx: f64,
    pub(super) low: f64,
    pub(super) my_low: f64,
}

/// The parts of a point no variable enters, in plain numbers (`None`: not
/// prepared, computed in `T`).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Parts {
    /// The pure lateral factors at the point's camber and at zero camber.
    pub(super) lat: Option<Lateral<f64>>,
    pub(super) lat0: Option<Lateral<f64>>,
    /// `Fy0` at the point's camber and at zero camber (6.x trail).
    pub(super) fy0: Option<f64>,
    pub(super) fy0_flat: Option<f64>,
    /// Combined `Fx` and `Kxκ`.
    pub(super) fx: Option<f64>,
    pub(super) kxk: Option<f64>,
    /// `Gyκ` and `SVyκ/μy`.
    pub(super) combined: Option<(f64, f64)>,
    /// `−t·Fy' + Mzr` of the aligning moment.
    pub(super) torque: Option<f64>,
}

/// A point with its coefficients in `T`: what every term reads.
pub(super) struct Point<'a, T> {
    c: &'a MfCoefficientsOf<T>,
    x: &'a Inputs,
    parts: &'a Parts,
    v52: bool,
    limit_checks: bool,
    dfz: T,
    dpi: T,
    lmux_s: T,
    lmuy_s: T,
    lmux_p: T,
    lmuy_p: T,
}

impl<'a, T: DualNum<f64> + Copy> Point<'a, T> {
    /// The point `x` of `tyre` with coefficients `c`, the parts `parts`
    /// prepared.
    pub(super) fn new(
        tyre: &MagicFormula,
        c: &'a MfCoefficientsOf<T>,
        x: &'a Inputs,
        parts: &'a Parts,
    ) -> Self {
        let v52 = tyre.version == MfVersion::Mf52;
        let fz0p = c.FNOMIN * c.LFZO;
        let dfz = (-fz0p + x.fz) / fz0p;
        let dpi = if v52 || c.NOMPRES.re() <= 0.0 {
            T::from(0.0)
        } else {
            (-c.NOMPRES + x.p) / c.NOMPRES
        };
        // λ*_μ with the slip speed (1 without LMUV); the road's friction
        // scale is 1 (the reference surface of the rig).
        let vs = x.vx.abs() * (x.kappa * x.kappa + x.astar * x.astar).sqrt();
        let speed_factor = (c.LMUV * vs / c.LONGVL + 1.0).recip();
        let lmux_s = c.LMUX * speed_factor;
        let lmuy_s = c.LMUY * speed_factor;
        let digress = |l: T| {
            if tyre.options.digressive_mu {
                l * 10.0 / (l * 9.0 + 1.0)
            } else {
                l
            }
        };
        Point {
            c,
            x,
            parts,
            v52,
            limit_checks: tyre.options.limit_checks,
            dfz,
            dpi,
            lmux_s,
            lmuy_s,
            lmux_p: digress(lmux_s),
            lmuy_p: digress(lmuy_s),
        }
    }
}

/// `x` moved away from zero by `EPS` in its own direction.
fn guard<T: DualNum<f64> + Copy>(x: T) -> T {
    if x.re() >= 0.0 {
        x + EPS
    } else {
        x - EPS
    }
}

fn sgn(x: f64) -> f64 {
    if x >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// `cos(atan x) = 1/sqrt(1 + x²)`.
fn cos_atan<T: DualNum<f64> + Copy>(x: T) -> T {
    (x * x + 1.0).sqrt().recip()
}

/// `atan(B·x − E·(B·x − atan(B·x)))` of a Magic Formula curve, `bx = B·x`.
fn curve_angle<T: DualNum<f64> + Copy>(bx: T, e: T) -> T {
    (bx - e * (bx - bx.atan())).atan()
}

/// The pure lateral force's factors at one camber `gs` (`γ*`, or 0 for the
/// trail of 6.x `Mz`) and `α*`, with the low-speed fade.
#[derive(Debug, Clone, Copy)]
pub(super) struct Lateral<T> {
    kya_g: T,
    shy: T,
    svy: T,
    cy: T,
    dy: T,
    muy: T,
    by: T,
    ay: T,
    ey: T,
}

impl<T: Copy> Lateral<T> {
    fn lift<U: From<T>>(self) -> Lateral<U> {
        Lateral {
            kya_g: self.kya_g.into(),
            shy: self.shy.into(),
            svy: self.svy.into(),
            cy: self.cy.into(),
            dy: self.dy.into(),
            muy: self.muy.into(),
            by: self.by.into(),
            ay: self.ay.into(),
            ey: self.ey.into(),
        }
    }
}

impl<T: DualNum<f64> + Copy> Point<'_, T> {
    /// `E` clipped at 1 when the limit checks are on (derivative 0 there).
    fn clip_e(&self, e: T) -> T {
        if self.limit_checks && e.re() > 1.0 {
            T::from(1.0)
        } else {
            e
        }
    }

    fn fz0p(&self) -> T {
        self.c.FNOMIN * self.c.LFZO
    }

    pub(super) fn lateral(&self, gs: f64) -> Lateral<T> {
        let cached = if gs == self.x.gs {
            self.parts.lat
        } else {
            self.parts.lat0
        };
        if let Some(l) = cached {
            return l.lift();
        }
        let c = self.c;
        let (dfz, dpi, fz) = (self.dfz, self.dpi, self.x.fz);
        let fz0p = self.fz0p();
        let kya_scale = c.PKY1 * fz0p * (c.PPY1 * dpi + 1.0) * c.LKY;
        let load_ratio = (fz0p.recip() * fz) / (c.PPY2 * dpi + 1.0);
        let x = load_ratio / (c.PKY2 + c.PKY5 * (gs * gs));
        let kya = kya_scale * (-(c.PKY3 * gs.abs()) + 1.0) * (c.PKY4 * x.atan()).sin();
        let kya_g = guard(kya);
        let svyg = (c.PVY3 + c.PVY4 * dfz) * c.LKYC * self.lmuy_p * (fz * gs);
        let kyg_gs = if self.v52 {
            T::from(0.0)
        } else {
            (c.PKY6 + c.PKY7 * dfz) * (c.PPY5 * dpi + 1.0) * c.LKYC * (fz * gs)
        };
        let shy0 = (c.PHY1 + c.PHY2 * dfz) * c.LHY;
        let svy_full = (c.PVY1 + c.PVY2 * dfz) * c.LVY * self.lmuy_p * fz + svyg;
        let low = self.x.low;
        let (shy, svy) = if self.v52 {
            (shy0 + c.PHY3 * c.LKYC * gs, svy_full * low)
        } else if low == 1.0 {
            (shy0 + (kyg_gs - svyg) / kya_g, svy_full)
        } else {
            (shy0 + (kyg_gs - svyg * low) / kya_g, svy_full * low)
        };
        let cy = c.PCY1 * c.LCY;
        let mu0 = (c.PDY1 + c.PDY2 * dfz) * (c.PPY3 * dpi + c.PPY4 * dpi * dpi + 1.0) * self.lmuy_s;
        let muy = mu0 * (-(c.PDY3 * (gs * gs)) + 1.0);
        let dy = muy * fz;
        let ay = shy + self.x.astar;
        let ey0 = (c.PEY1 + c.PEY2 * dfz) * c.LEY;
        let ey_a = c.PEY5 * (gs * gs) + 1.0;
        let ey_b = c.PEY3 + c.PEY4 * gs;
        Lateral {
            kya_g,
            shy,
            svy,
            cy,
            dy,
            muy,
            by: kya / guard(cy * dy),
            ay,
            ey: self.clip_e(ey0 * (ey_a - ey_b * sgn(ay.re()))),
        }
    }

    /// `μy` without its camber factor (MFeval's 5.2 trail).
    fn mu0(&self) -> T {
        let (c, dpi) = (self.c, self.dpi);
        (c.PDY1 + c.PDY2 * self.dfz) * (c.PPY3 * dpi + c.PPY4 * dpi * dpi + 1.0) * self.lmuy_s
    }

    pub(super) fn fy0(&self, l: &Lateral<T>) -> T {
        l.dy * (l.cy * curve_angle(l.by * l.ay, l.ey)).sin() + l.svy
    }

    /// `Kxκ`.
    pub(super) fn kxk(&self) -> T {
        if let Some(k) = self.parts.kxk {
            return T::from(k);
        }
        let (c, dfz, dpi) = (self.c, self.dfz, self.dpi);
        (c.PKX1 + c.PKX2 * dfz)
            * (c.PKX3 * dfz).exp()
            * (c.PPX1 * dpi + c.PPX2 * dpi * dpi + 1.0)
            * c.LKX
            * self.x.fz
    }

    /// Pure `Fx0` at the point's slip ratio.
    fn fx0(&self) -> T {
        let (c, dfz, dpi) = (self.c, self.dfz, self.dpi);
        let cx = c.PCX1 * c.LCX;
        let mux = (c.PDX1 + c.PDX2 * dfz)
            * (c.PPX3 * dpi + c.PPX4 * dpi * dpi + 1.0)
            * (-(c.PDX3 * (self.x.gamma * self.x.gamma)) + 1.0)
            * self.lmux_s;
        let dx = mux * self.x.fz;
        let bx = self.kxk() / guard(cx * dx);
        let shx = (c.PHX1 + c.PHX2 * dfz) * c.LHX;
        let svx = (c.PVX1 + c.PVX2 * dfz) * c.LVX * self.lmux_p * self.x.fz;
        let kx = shx + self.x.kappa;
        let ex_load = c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz;
        let ex = self.clip_e(ex_load * (-(c.PEX4 * sgn(kx.re())) + 1.0) * c.LEX);
        dx * (cx * curve_angle(bx * kx, ex)).sin() + svx * self.x.low
    }

    /// Combined `Fx = Gxα·Fx0`.
    pub(super) fn fx(&self) -> T {
        if let Some(fx) = self.parts.fx {
            return T::from(fx);
        }
        let c = self.c;
        let fx0 = self.fx0();
        let rbx = c.RBX1 + c.RBX3 * (self.x.gs * self.x.gs);
        let bxa = rbx * cos_atan(c.RBX2 * self.x.kappa) * c.LXAL;
        let exa = self.clip_e(c.REX1 + c.REX2 * self.dfz);
        let n = (c.RCX1 * curve_angle(bxa * (c.RHX1 + self.x.astar), exa)).cos();
        let d = (c.RCX1 * curve_angle(bxa * c.RHX1, exa)).cos();
        n / d * fx0
    }

    /// `Gyκ` and `SVyκ` per unit `μy`: exactly 1 and 0 (with zero
    /// derivatives) at κ = 0.
    pub(super) fn combined_y(&self) -> (T, T) {
        if self.x.kappa == 0.0 {
            return (T::from(1.0), T::from(0.0));
        }
        if let Some((g, v)) = self.parts.combined {
            return (T::from(g), T::from(v));
        }
        let c = self.c;
        let (dfz, astar) = (self.dfz, self.x.astar);
        let rby = c.RBY1 + c.RBY4 * (self.x.gs * self.x.gs);
        let byk = rby * cos_atan(c.RBY2 * (-c.RBY3 + astar)) * c.LYKA;
        let shyk = c.RHY1 + c.RHY2 * dfz;
        let eyk = self.clip_e(c.REY1 + c.REY2 * dfz);
        let n = (c.RCY1 * curve_angle(byk * (shyk + self.x.kappa), eyk)).cos();
        let d = (c.RCY1 * curve_angle(byk * shyk, eyk)).cos();
        let svyk_load = (c.RVY1 + c.RVY2 * dfz + c.RVY3 * self.x.gs) * self.x.fz;
        let s_rvy = (c.RVY5 * (c.RVY6 * self.x.kappa).atan()).sin();
        let per_mu = svyk_load * cos_atan(c.RVY4 * astar) * s_rvy * c.LVYKA * self.x.low;
        (n / d, per_mu)
    }

    /// Combined `Fy` with its pure lateral factors, `Gyκ` and `SVyκ/μy`.
    pub(super) fn fy(&self) -> (T, Lateral<T>, T, T) {
        let lat = self.lateral(self.x.gs);
        let (gyk, per_mu) = self.combined_y();
        let fy0 = self.parts.fy0.map_or_else(|| self.fy0(&lat), T::from);
        (gyk * fy0 + lat.muy * per_mu, lat, gyk, per_mu)
    }

    /// `Bt`, `Dt` and `Dr` of the aligning moment.
    fn aligning_terms(&self) -> (T, T, T) {
        let (c, dfz, dpi) = (self.c, self.dfz, self.dpi);
        let (gamma, gz) = (self.x.gamma, self.x.gs);
        let r0 = c.UNLOADED_RADIUS;
        let bt = (c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz)
            * (c.QBZ4 * gamma + c.QBZ5 * gamma.abs() + 1.0)
            * c.LKY
            / self.lmuy_s;
        let dt = (r0 / self.fz0p())
            * (c.QDZ1 + c.QDZ2 * dfz)
            * (-(c.PPZ1 * dpi) + 1.0)
            * (c.QDZ3 * gamma + c.QDZ4 * (gamma * gamma) + 1.0)
            * c.LTR
            * self.x.fz_trail;
        let dr = r0
            * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES
                + ((c.QDZ8 + c.QDZ9 * dfz) * (c.PPZ2 * dpi + 1.0)
                    + (c.QDZ10 + c.QDZ11 * dfz) * gz.abs())
                    * c.LKZC
                    * gz)
            * self.lmuy_s
            * self.x.fz_trail;
        (bt, dt, dr)
    }

    /// The aligning moment (ISO-W).
    pub(super) fn mz(&self) -> T {
        let c = self.c;
        let (fy, lat, gyk, per_mu) = self.fy();
        // The trail and residual torque, prepared when nothing they
        // depend on varies (only `SSZ*` fitted).
        let torque = self
            .parts
            .torque
            .map_or_else(|| self.torque(fy, &lat, gyk, per_mu), T::from);
        let s = (c.SSZ1 + c.SSZ2 * (fy / c.FNOMIN) + (c.SSZ3 + c.SSZ4 * self.dfz) * self.x.gamma)
            * c.UNLOADED_RADIUS
            * c.LS;
        torque + s * self.fx()
    }

    /// `−t·Fy' + Mzr` of the aligning moment from the combined `Fy`, the
    /// pure lateral factors at the point's camber, `Gyκ` and `SVyκ/μy`.
    pub(super) fn torque(&self, fy: T, lat: &Lateral<T>, gyk: T, per_mu: T) -> T {
        let c = self.c;
        let (dfz, astar, gz) = (self.dfz, self.x.astar, self.x.gs);
        let fy_trail = if self.v52 {
            fy - self.mu0() * per_mu
        } else if let Some(f) = self.parts.fy0_flat {
            gyk * f
        } else if self.x.gs == 0.0 {
            gyk * self.fy0(lat)
        } else {
            gyk * self.fy0(&self.lateral(0.0))
        };
        let (bt, dt, dr) = self.aligning_terms();
        let sht = c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gz;
        let et_load = c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz;
        let et_gamma = (c.QEZ4 + c.QEZ5 * gz) * (2.0 / PI);
        let br = c.QBZ9 * c.LKY / self.lmuy_s + c.QBZ10 * lat.by * lat.cy;
        let kratio = self.kxk() / lat.kya_g;
        let k2 = kratio * kratio * (self.x.kappa * self.x.kappa);
        let at = sht + astar;
        let ar = lat.shy + lat.svy / lat.kya_g + astar;
        // TNO (A54/A55): the equivalent angles combine tangents; without
        // longitudinal slip, the angle itself inside ±90°.
        let equivalent = |a: T| {
            if k2.re() == 0.0 && a.re().abs() < 0.5 * PI {
                a
            } else {
                let (s, co) = (a.sin(), a.cos());
                ((s * s + k2 * co * co).sqrt() / co.abs()).atan() * sgn(a.re())
            }
        };
        let (at_eq, ar_eq) = (equivalent(at), equivalent(ar));
        let et = self.clip_e(et_load * (et_gamma * (bt * c.QCZ1 * at).atan() + 1.0));
        let cos_t = (c.QCZ1 * curve_angle(bt * at_eq, et)).cos();
        let t = dt * cos_t * c.LFZO * self.x.trail_cos;
        let mzr = dr * cos_atan(br * ar_eq) * self.x.residual_cos;
        mzr - t * fy_trail
    }

    /// The overturning moment (ISO-W).
    pub(super) fn mx(&self) -> T {
        let c = self.c;
        let (gamma, fy) = (self.x.gamma, self.fy().0);
        let fzr = c.FNOMIN.recip() * self.x.fz_mx;
        let r0_lmx = c.UNLOADED_RADIUS * c.LMX;
        let mixed = c.QSX4
            * (c.QSX5 * ((c.QSX6 * fzr).powi(2)).atan()).cos()
            * (c.QSX7 * gamma + c.QSX8 * (c.QSX9 * fy / c.FNOMIN).atan()).sin();
        let load_camber = c.QSX10 * (c.QSX11 * fzr).atan() * gamma;
        let constant = c.QSX1 * c.LVMX - c.QSX2 * (c.PPMX1 * self.dpi + 1.0) * gamma;
        let mx_fy = r0_lmx * (c.QSX13 + c.QSX14 * gamma.abs());
        let mx_gamma = -(r0_lmx * c.QSX12 * (self.x.fz_mx * gamma * gamma.abs()));
        r0_lmx * self.x.fz_mx * (constant + c.QSX3 * fy / c.FNOMIN + mixed + load_camber)
            + (fy * mx_fy + mx_gamma)
    }

    /// The rolling-resistance moment (ISO-W).
    pub(super) fn my(&self) -> T {
        let c = self.c;
        let fz0 = c.FNOMIN;
        let fzr = fz0.recip() * self.x.fz_my;
        let powers = if self.v52 {
            fzr
        } else {
            let pr = if c.NOMPRES.re() > 0.0 {
                c.NOMPRES.recip() * self.x.p
            } else {
                T::from(1.0)
            };
            (c.QSY7 * fzr.ln() + c.QSY8 * pr.ln()).exp()
        };
        let camber = if self.v52 {
            T::from(0.0)
        } else {
            (c.QSY5 + c.QSY6 * fzr) * (self.x.gamma * self.x.gamma)
        };
        let vr = c.LONGVL.recip() * self.x.vx;
        let vr2 = vr * vr;
        let poly =
            c.QSY1 + c.QSY2 * self.fx() / fz0 + c.QSY3 * vr.abs() + c.QSY4 * (vr2 * vr2) + camber;
        -(c.UNLOADED_RADIUS * fz0 * c.LMY) * poly * powers * (self.x.sgn_vx * self.x.my_low)
    }
}
