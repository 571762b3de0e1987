//! The Magic Formula's pure lateral force in any scalar of the `num-dual`
//! crate ([`LateralForceOf`]): `Fy` at zero slip ratio and zero camber (the
//! vehicle model's wheel), with the lateral parameter vector of
//! [`Parameterised`] (`PCY1`, `PDY1`, `PDY2`, `PEY1`, `PEY2`, `PKY1`,
//! `PKY2`, `PHY1`, `PVY1`) as scalars and the slip angle, load and road
//! friction scale as scalars too. The formulae are those of the fast path
//! ([`MagicFormula::evaluate`]; Pacejka 2012 eqs. 4.E19–4.E30 as TNO and
//! MFeval take them, the choices in the parent module's notes) at κ = 0,
//! where the combined-slip weight is exactly 1 and `SVyκ` exactly 0; the
//! limit checks saturate the load and slip angle (derivative 0 beyond) and
//! clip `Ey` at 1. Crate convention in and out (SI, rad).

use super::{AlphaStar, MagicFormula, MfVersion, TyreSide};
use crate::tyre::{LateralForceOf, SlipOf};
use num_dual::DualNum;
use std::f64::consts::PI;

/// `x` saturated to `[lo, hi]` (derivative 0 where it is).
fn saturate<T: DualNum<f64> + Copy>(x: T, lo: Option<f64>, hi: Option<f64>) -> T {
    match (lo, hi) {
        (Some(l), _) if x.re() < l => T::from(l),
        (_, Some(h)) if x.re() > h => T::from(h),
        _ => x,
    }
}

/// `x` moved away from zero by 1e-6 in its own direction.
fn guard<T: DualNum<f64> + Copy>(x: T) -> T {
    if x.re() >= 0.0 {
        x + 1e-6
    } else {
        x - 1e-6
    }
}

/// The point in TNO's frame: load and `α*` (scalars), `γ*`, the pressure
/// and the low-speed factor (plain numbers).
struct Lateral<T> {
    fz: T,
    astar: T,
    gs: f64,
    pressure: f64,
    low: f64,
}

impl MagicFormula {
    /// The point of `s` at zero camber after the crate → ISO-W mapping, the
    /// `TYRESIDE` mirror and the limit checks (as [`Self::evaluate`]).
    fn lateral_point<T: DualNum<f64> + Copy>(&self, s: &SlipOf<T>) -> Lateral<T> {
        let c = &self.coefficients;
        let l = &self.limits;
        let mirror = self.side == TyreSide::Right;
        let alpha = if mirror { s.alpha } else { -s.alpha };
        let checked = self.checked(s.fz.re(), 0.0, self.pressure(None));
        let (fz, alpha) = if self.options.limit_checks {
            (
                saturate(s.fz, None, l.fz_max),
                saturate(alpha, l.alpha_min, l.alpha_max),
            )
        } else {
            (s.fz, alpha)
        };
        let vx = s.speed;
        let sgn_vx = if vx >= 0.0 { 1.0 } else { -1.0 };
        let (astar, gs) = match self.options.alpha_star {
            AlphaStar::Tan => {
                let (sn, cs) = (alpha.sin(), alpha.cos());
                // Beyond ±90° the slip keeps its direction (as the fast path).
                let tan = if alpha.re().abs() < 0.5 * PI {
                    sn / cs
                } else if cs.re().abs() > 1e-12 {
                    sn / cs.abs()
                } else {
                    sn / 1e-12
                };
                (tan * sgn_vx, checked.gamma.sin())
            }
            AlphaStar::Angle => (alpha * sgn_vx, checked.gamma),
        };
        Lateral {
            fz,
            astar,
            gs,
            pressure: checked.p,
            low: if vx.abs() < c.VXLOW {
                vx.abs() / c.VXLOW
            } else {
                1.0
            },
        }
    }
}

impl MagicFormula {
    /// The peak factor of the pure lateral force over the load, `|μy|`
    /// (TNO eq. 4.E23 at zero camber and zero slip speed, with the
    /// pressure terms of 6.x and the road's friction scale `mu_scale` on
    /// `LMUY`), with `PDY1` and `PDY2` in scalar `T`: the radius of the
    /// friction circle per unit load.
    pub(crate) fn friction_of<T: DualNum<f64> + Copy>(
        &self,
        (pdy1, pdy2): (T, T),
        fz: T,
        mu_scale: T,
    ) -> T {
        if !(fz.re() > 0.0 && fz.re().is_finite()) {
            return T::from(0.0);
        }
        let c = &self.coefficients;
        let fz = if self.options.limit_checks {
            saturate(fz, None, self.limits.fz_max)
        } else {
            fz
        };
        let checked = self.checked(fz.re(), 0.0, self.pressure(None));
        let fz0p = c.FNOMIN * c.LFZO;
        let dfz = (fz - fz0p) / fz0p;
        let dpi = if self.version == MfVersion::Mf52 || c.NOMPRES <= 0.0 {
            0.0
        } else {
            (checked.p - c.NOMPRES) / c.NOMPRES
        };
        let lmuy_s = mu_scale * c.LMUY;
        let lmuy = if self.options.digressive_mu {
            lmuy_s * 10.0 / (lmuy_s * 9.0 + 1.0)
        } else {
            lmuy_s
        };
        ((dfz * pdy2 + pdy1) * (1.0 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * lmuy).abs()
    }
}

impl LateralForceOf for MagicFormula {
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], fz: T, mu_scale: T) -> T {
        self.friction_of((p[1], p[2]), fz, mu_scale)
    }

    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        if !(s.fz.re() > 0.0 && s.fz.re().is_finite()) {
            return T::from(0.0);
        }
        let [pcy1, pdy1, pdy2, pey1, pey2, pky1, pky2, phy1, pvy1] = std::array::from_fn(|k| p[k]);
        let c = &self.coefficients;
        let Lateral {
            fz,
            astar,
            gs,
            pressure,
            low,
        } = self.lateral_point(s);
        let vx = s.speed;
        let v52 = self.version == MfVersion::Mf52;
        let fz0p = c.FNOMIN * c.LFZO;
        let dfz = (fz - fz0p) / fz0p;
        let dpi = if v52 || c.NOMPRES <= 0.0 {
            0.0
        } else {
            (pressure - c.NOMPRES) / c.NOMPRES
        };
        // λ*_μ with the slip speed |Vx|·|α*| (κ = 0) and the road's friction.
        let vs = astar.abs() * vx.abs();
        let lmuy_s = (vs * (c.LMUV / c.LONGVL) + 1.0).recip() * s.mu_scale * c.LMUY;
        let lmuy_p = if self.options.digressive_mu {
            lmuy_s * 10.0 / (lmuy_s * 9.0 + 1.0)
        } else {
            lmuy_s
        };
        let x = fz / (fz0p * (1.0 + c.PPY2 * dpi)) / (pky2 + c.PKY5 * gs * gs);
        let kya = pky1
            * (fz0p * (1.0 + c.PPY1 * dpi) * c.LKY * (1.0 - c.PKY3 * gs.abs()))
            * (x.atan() * c.PKY4).sin();
        let kya_g = guard(kya);
        let svyg = fz * (dfz * c.PVY4 + c.PVY3) * (c.LKYC * gs) * lmuy_p;
        let kyg = if v52 {
            T::from(0.0)
        } else {
            fz * (dfz * c.PKY7 + c.PKY6) * ((1.0 + c.PPY5 * dpi) * c.LKYC * gs)
        };
        let shy0 = (phy1 + dfz * c.PHY2) * c.LHY;
        let shy = if v52 {
            shy0 + c.PHY3 * gs * c.LKYC
        } else {
            shy0 + (kyg - svyg * low) / kya_g
        };
        let svy = (fz * (pvy1 + dfz * c.PVY2) * c.LVY * lmuy_p + svyg) * low;
        let cy = pcy1 * c.LCY;
        let muy = (pdy1 + pdy2 * dfz)
            * ((1.0 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * (1.0 - c.PDY3 * gs * gs))
            * lmuy_s;
        let dy = muy * fz;
        let by = kya / guard(cy * dy);
        let ay = astar + shy;
        let sign = if ay.re() >= 0.0 { 1.0 } else { -1.0 };
        let ey = (pey1 + pey2 * dfz)
            * (c.LEY * (1.0 + c.PEY5 * gs * gs - (c.PEY3 + c.PEY4 * gs) * sign));
        let ey = if self.options.limit_checks && ey.re() > 1.0 {
            T::from(1.0)
        } else {
            ey
        };
        let bx = by * ay;
        let fy = dy * (cy * (bx - ey * (bx - bx.atan())).atan()).sin() + svy;
        if self.side == TyreSide::Right {
            -fy
        } else {
            fy
        }
    }
}
