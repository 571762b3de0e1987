//! The aligning moment `Mz` (N·m, ISO sign: the negated SAE curve, as
//! [`crate::tyre::TyreModel::forces`] gives it) of a fit's tyre at one rig
//! point, without the forces the aligning fit does not read. A PAC89
//! tyre's `forces` evaluates its lateral force (two arctangents and a
//! sine per point) beside the moment, whose curve does not use it: on the
//! Hoosier cornering file the aligning-moment fit's residuals and
//! differenced Jacobians spent about half their time on that unread force.
//! Here PAC89's moment is the same arithmetic as in `forces`
//! (`Pac89::aligning_curve`, its friction scaling, the curve's sine), so
//! the same number to the bit (checked below); every other model's moment
//! is its `forces`' (UniTire's and the others' moments use their force).

use crate::tyre::pac89::{magic_formula, CurveCoefficients};
use crate::tyre::{Pac89, SlipState, Tyre, TyreModel};

/// `t`'s aligning moment at `s`, N·m: `t.forces(s).mz`, PAC89's without
/// its lateral and longitudinal forces.
pub(super) fn aligning_moment(t: &Tyre, s: &SlipState) -> f64 {
    match t {
        Tyre::Pac89(p) => pac89_moment(p, s),
        _ => t.forces(s).mz,
    }
}

/// PAC89's `mz` of `forces` (`src/tyre/pac89.rs`), step for step.
fn pac89_moment(p: &Pac89, s: &SlipState) -> f64 {
    if s.fz <= 0.0 {
        return 0.0;
    }
    let Some(c) = p.c.as_ref() else {
        return 0.0;
    };
    let curve = Pac89::aligning_curve(c, s.fz / 1000.0, s.camber.to_degrees());
    -scaled(curve, s.mu_scale, s.alpha.to_degrees())
}

/// PAC89's friction scaling of a curve at `x`, as `Pac89::scaled`: μ = 1
/// scales nothing (left out, not multiplied by 1), μ ≤ 0 gives 0.
fn scaled(curve: CurveCoefficients, mu: f64, x: f64) -> f64 {
    if mu == 1.0 {
        return magic_formula(curve.b, curve.c, curve.d, curve.e, x + curve.sh) + curve.sv;
    }
    let k = if mu > 0.0 { mu } else { return 0.0 };
    magic_formula(curve.b / k, curve.c, curve.d * k, curve.e, x + curve.sh) + curve.sv * k
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The moment equals `forces`' to the bit for PAC89 (the ADAMS example
    /// tyre, with and without its longitudinal block; aligning
    /// coefficients moved off the example's so every term counts) over
    /// loads (none, light, heavy), slip angles of both signs, cambers and
    /// road frictions (1, scaled, none); and a PAC89 without aligning
    /// coefficients, no load or no friction gives 0, as `forces` does.
    #[test]
    fn pac89_moment_is_forces_moment_to_the_bit() {
        let mut with = Pac89::adams_example();
        let c = with.c.as_mut().expect("the example has an aligning block");
        for (i, v) in c.iter_mut().enumerate() {
            *v += 0.01 * (i as f64 + 1.0) * (1.0 + v.abs());
        }
        let mut without_fx = with.clone();
        without_fx.b = None;
        let mut without_mz = with.clone();
        without_mz.c = None;
        let (mut compared, mut nonzero) = (0, 0);
        for p in [with, without_fx, without_mz] {
            let t = Tyre::Pac89(p);
            for fz in [-10.0, 0.0, 450.0, 2900.0, 6500.0] {
                for alpha in [-0.2, -0.01, 0.0, 0.003, 0.15] {
                    for camber in [-0.05, 0.0, 0.04] {
                        for mu in [1.0, 0.7, 0.0] {
                            let s = SlipState {
                                alpha,
                                kappa: 0.0,
                                fz,
                                camber,
                                mu_scale: mu,
                                speed: 11.0,
                            };
                            let (a, b) = (aligning_moment(&t, &s), t.forces(&s).mz);
                            assert_eq!(a.to_bits(), b.to_bits(), "{s:?}: {a} vs {b}");
                            compared += 1;
                            nonzero += usize::from(b != 0.0);
                        }
                    }
                }
            }
        }
        assert_eq!(compared, 675);
        // Every comparison with a moment to give (an aligning block, a
        // load, a friction: 2·3·5·3·2) is of a moment, not of two zeros.
        assert_eq!(nonzero, 180, "{nonzero} of {compared}");
    }
}
