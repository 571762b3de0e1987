//! One output channel of the Magic Formula (`Fx`, `Fy`, `Mz`, `Mx` or `My`)
//! in any scalar of the `num-dual` crate, with the coefficients as scalars
//! too ([`MfCoefficientsOf`]): in dual numbers it carries the exact
//! derivatives of the channel with respect to the coefficients being
//! fitted (forward mode, to rounding), which is what the staged
//! identification's Jacobians are (`identify::mf_staged`).
//!
//! The same formulae as [`super::formulae`] and [`super::slip`] (the
//! equations, sources and choices are in the parent module's notes), written
//! plainly, one scalar at a time, and only as far as the channel asked for
//! needs them: a pure `Fy` point computes the lateral curve, not the
//! aligning moment's. The fast path of `tyre-eval` and the vehicle stays
//! [`MagicFormula::evaluate`] (array kernels over `f64`); the two agree to
//! 1e-12 relative on the MFeval fixtures' grids (`channel_tests.rs`, every
//! mode). Differences that are not rounding: none in value; in derivative,
//! the coefficients the fast path compares with exact numbers to skip a
//! term (`PKY4 = 2`, `QSX4 = 0`, …) are always differentiated here, and the
//! branches (`E` clipped at 1, the limit checks, `sgn`, `|·|`) take the
//! derivative of the branch the value takes. The structural constants
//! `VXLOW`, `LONGVL` (in the rolling direction), `INFLPRES` and the limits
//! enter as plain numbers.
//!
//! A point prepared once ([`MagicFormula::prepare_point`]) keeps its
//! inputs after the limit checks and, in plain numbers, the parts of the
//! evaluation that no variable enters ([`Held`]: the lateral force in a
//! fit of the aligning moment's coefficients, …), so that the passes of a
//! Jacobian and the iterations of a fit evaluate only what moves.
//!
//! Units: SI and radians, crate convention at the interface (as
//! [`MagicFormula::evaluate`]); TNO's ISO-W inside.

mod point;

use super::coefficients::MfCoefficientsOf;
use super::formulae::EPS_V;
use super::{AlphaStar, MagicFormula, MfInput, TyreSide};
use num_dual::DualNum;
use point::{Inputs, Parts, Point};
use std::f64::consts::PI;

/// An output channel of the Magic Formula.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MfChannel {
    /// Longitudinal force `fx`, N (combined slip).
    Fx,
    /// Lateral force `fy`, N (combined slip).
    Fy,
    /// Aligning moment `mz`, N·m.
    Mz,
    /// Overturning moment `mx`, N·m.
    Mx,
    /// Rolling-resistance moment `my`, N·m.
    My,
}

/// The parts of an evaluation none of whose coefficients is a variable:
/// computed in plain numbers, then lifted (no derivatives carried through
/// them). Found from the names of the variables ([`Held::except`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Held {
    /// Pure and combined `Fx` (`P?X*`, `R?X*`).
    longitudinal: bool,
    /// The pure lateral force (`P?Y*`).
    lateral: bool,
    /// `Gyκ` and `SVyκ` (`R?Y*`).
    combined_lateral: bool,
    /// The trail and residual torque of `Mz` (`Q?Z*`, `PPZ*`).
    aligning: bool,
}

impl Held {
    /// Nothing held: every part in the scalar given.
    pub const NONE: Held = Held {
        longitudinal: false,
        lateral: false,
        combined_lateral: false,
        aligning: false,
    };

    /// What is held when exactly the coefficients `variables` carry
    /// derivatives: the parts none of them enters. A name outside the
    /// families above (a scaling factor, `FNOMIN`, …) enters every part:
    /// then nothing is held.
    pub fn except(variables: &[&str]) -> Held {
        let family = |name: &str| {
            let b = name.as_bytes();
            match (b.first(), b.get(2)) {
                (Some(b'P'), Some(b'X')) | (Some(b'R'), Some(b'X')) => Some(0),
                (Some(b'P'), Some(b'Y')) => Some(1),
                (Some(b'R'), Some(b'Y')) => Some(2),
                (Some(b'Q'), Some(b'Z')) | (Some(b'P'), Some(b'Z')) => Some(3),
                // Fitted in no part above: the moments' own coefficients.
                _ if name.starts_with("SSZ")
                    || name.starts_with("QSX")
                    || name.starts_with("QSY")
                    || name == "PPMX1" =>
                {
                    Some(4)
                }
                _ => None,
            }
        };
        let mut varied = [false; 5];
        for name in variables {
            match family(name) {
                Some(f) => varied[f] = true,
                None => return Held::NONE,
            }
        }
        Held {
            longitudinal: !varied[0],
            lateral: !varied[1],
            combined_lateral: !varied[2],
            aligning: !varied[3],
        }
    }
}

/// A point prepared for evaluating channels with the same held parts
/// ([`MagicFormula::prepare_point`]).
#[derive(Debug, Clone, Copy)]
pub struct MfPoint {
    /// `None` at zero, negative or non-finite load: no force.
    x: Option<Inputs>,
    mirror: bool,
    parts: Parts,
}

impl MagicFormula {
    /// Channel `channel` at point `p` (crate convention, as
    /// [`Self::evaluate`]) with coefficients `c` in scalar `T`; 0 at zero,
    /// negative or non-finite load. With `c = self.coefficients.lift()` in
    /// `f64` it equals `evaluate`'s channel to rounding.
    pub fn channel_of<T: DualNum<f64> + Copy>(
        &self,
        c: &MfCoefficientsOf<T>,
        p: &MfInput,
        channel: MfChannel,
    ) -> T {
        let point = self.prepare_point(&self.coefficients.lift(), Held::NONE, p);
        self.channel_at(c, &point, channel)
    }

    /// Point `p` prepared: its inputs after the limit checks, and the
    /// parts `held` evaluated with the coefficients `plain` — which must be
    /// the values of the coefficients [`Self::channel_at`] is later given
    /// in every part held ([`Held::except`] of the variables).
    pub fn prepare_point(&self, plain: &MfCoefficientsOf<f64>, held: Held, p: &MfInput) -> MfPoint {
        let mirror = self.side == TyreSide::Right;
        let mut point = MfPoint {
            x: (p.fz > 0.0 && p.fz.is_finite()).then(|| self.inputs(p, mirror)),
            mirror,
            parts: Parts::default(),
        };
        let Some(x) = &point.x else {
            return point;
        };
        let none = Parts::default();
        let q = Point::new(self, plain, x, &none);
        let parts = &mut point.parts;
        if held.lateral {
            let lat = q.lateral(x.gs);
            parts.lat = Some(lat);
            parts.fy0 = Some(q.fy0(&lat));
            let lat0 = if x.gs == 0.0 { lat } else { q.lateral(0.0) };
            parts.lat0 = Some(lat0);
            parts.fy0_flat = Some(q.fy0(&lat0));
        }
        if held.longitudinal {
            parts.fx = Some(q.fx());
            parts.kxk = Some(q.kxk());
        }
        if held.combined_lateral {
            parts.combined = Some(q.combined_y());
        }
        if held.lateral && held.longitudinal && held.combined_lateral && held.aligning {
            let (fy, lat, gyk, per_mu) = q.fy();
            parts.torque = Some(q.torque(fy, &lat, gyk, per_mu));
        }
        point
    }

    /// Channel `channel` at a prepared point with coefficients `c` (crate
    /// convention; see [`Self::prepare_point`]).
    pub fn channel_at<T: DualNum<f64> + Copy>(
        &self,
        c: &MfCoefficientsOf<T>,
        point: &MfPoint,
        channel: MfChannel,
    ) -> T {
        let Some(x) = &point.x else {
            return T::from(0.0);
        };
        let q = Point::new(self, c, x, &point.parts);
        let iso = match channel {
            MfChannel::Fx => q.fx(),
            MfChannel::Fy => q.fy().0,
            MfChannel::Mz => q.mz(),
            MfChannel::Mx => q.mx(),
            MfChannel::My => q.my(),
        };
        // ISO-W (of the mirrored tyre) → crate convention.
        let flip = match channel {
            MfChannel::Fy | MfChannel::Mx => point.mirror,
            MfChannel::Mz => !point.mirror,
            MfChannel::Fx | MfChannel::My => false,
        };
        if flip {
            -iso
        } else {
            iso
        }
    }

    /// The inputs of `p` (`fz > 0`) after the crate → ISO-W mapping, the
    /// `TYRESIDE` mirror and the limit checks (as [`Self::evaluate`]).
    fn inputs(&self, p: &MfInput, mirror: bool) -> Inputs {
        let k = &self.coefficients;
        let gamma = if mirror { -p.camber } else { p.camber };
        let alpha = if mirror { p.alpha } else { -p.alpha };
        let loads = self.checked(p.fz, gamma, self.pressure(p.pressure));
        let vx = p.speed;
        let my_reversal = Self::rolling_direction(p.kappa, vx, k.VXLOW);
        let (kappa, alpha) = self.checked_slip(p.kappa, alpha);
        let sgn_vx = if vx >= 0.0 { 1.0 } else { -1.0 };
        let low = if vx.abs() < k.VXLOW {
            vx.abs() / k.VXLOW
        } else {
            1.0
        };
        let tan_a = if alpha.abs() < 0.5 * PI {
            alpha.sin() / alpha.cos()
        } else {
            alpha.sin() / alpha.cos().abs().max(1e-12)
        };
        let (astar, gs) = match self.options.alpha_star {
            AlphaStar::Tan => (tan_a * sgn_vx, loads.gamma.sin()),
            AlphaStar::Angle => (alpha * sgn_vx, loads.gamma),
        };
        Inputs {
            fz: loads.fz,
            fz_trail: loads.fz_trail,
            fz_mx: loads.fz_mx,
            fz_my: loads.fz_my,
            gamma: loads.gamma,
            gs,
            p: loads.p,
            kappa,
            astar,
            trail_cos: {
                let vsy = vx.abs() * tan_a;
                sgn_vx * (vx / ((vx * vx + vsy * vsy).sqrt() + EPS_V))
            },
            residual_cos: sgn_vx * astar.cos(),
            vx,
            sgn_vx,
            low,
            my_low: low * my_reversal,
        }
    }
}
