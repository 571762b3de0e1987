//! The tyre models' exact derivatives ([`LateralForceOf`] in dual numbers)
//! against central differences of their plain lateral force
//! ([`TyreModel::lateral_force`], fourth order), at random slip states: ∂Fy/∂(α, Fz, μ)
//! and ∂Fy/∂p for every lateral parameter, to 1e-6 relative.

use super::*;
use nalgebra::{Const, U1};
use num_dual::DualSVec64;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Directions of the dual numbers: α, Fz, μ, then up to five parameters.
const DIRECTIONS: usize = 8;
type D = DualSVec64<DIRECTIONS>;

/// The largest relative error of the dual derivatives of `tyre`'s lateral
/// force against central differences at slip angles drawn from `alphas`
/// (both signs), loads 1–6 kN and friction scales 0.6–1.2. A derivative
/// that is exactly zero (a parameter the force does not read) must
/// difference to zero exactly.
fn largest_error<M>(tyre: &M, alphas: std::ops::Range<f64>, seed: u64) -> f64
where
    M: LateralForceOf + TyreModel + Clone,
{
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let p0 = tyre.parameters();
    let n = p0.len();
    let bounds = tyre.bounds();
    assert!(3 + n <= DIRECTIONS);
    let mut worst: f64 = 0.0;
    for i in 0..40 {
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        let x0 = [
            sign * rng.random_range(alphas.clone()),
            rng.random_range(1000.0..6000.0),
            rng.random_range(0.6..1.2),
        ];
        let vars: Vec<f64> = x0.iter().chain(&p0).copied().collect();
        // The plain force as a function of every variable.
        let plain = |v: &[f64]| {
            let mut m = tyre.clone();
            m.set_parameters(&v[3..]);
            m.lateral_force(&SlipState {
                mu_scale: v[2],
                ..SlipState::lateral(v[0], v[1])
            })
        };
        let dual: Vec<D> = (0..3 + n).map(|k| D::from(vars[k]).derivative(k)).collect();
        let s = SlipOf {
            alpha: dual[0],
            fz: dual[1],
            mu_scale: dual[2],
            speed: 20.0,
        };
        let f = tyre.lateral_force_of(&dual[3..], &s);
        // The f64 form is the plain force's arithmetic (a load exponent's
        // power taken as e^(n·ln x): to rounding).
        let value = plain(&vars);
        let plain_f64 = tyre.lateral_force_of(&p0, &s.value().into_plain());
        assert!((plain_f64 - value).abs() <= 1e-14 * value.abs(), "{vars:?}");
        // Dual numbers divide by multiplying with the reciprocal: their
        // value is the force's to rounding, not to the bit.
        assert!((f.re - value).abs() <= 1e-14 * value.abs(), "{vars:?}");
        let grad = f.eps.unwrap_generic(Const::<DIRECTIONS>, U1);
        for k in 0..3 + n {
            // Central differences of fourth order, with a step the force's
            // rounding cannot swamp (a parameter the force barely reads,
            // Gim's friction decay at small slip, moves it by parts in 1e4
            // over its box): relative to the variable, or to a parameter's
            // box. Truncation (h⁴) stays below 1e-10.
            let h = if k < 3 {
                1e-4 * vars[k].abs().max(1e-2)
            } else {
                1e-3 * vars[k].abs().max(0.1 * (bounds[k - 3].1 - bounds[k - 3].0))
            };
            let at = |m: f64| {
                let mut v = vars.clone();
                v[k] = vars[k] + m * h;
                plain(&v)
            };
            let central = (8.0 * (at(1.0) - at(-1.0)) - (at(2.0) - at(-2.0))) / (12.0 * h);
            if grad[k] == 0.0 {
                assert_eq!(central, 0.0, "variable {k} at {vars:?}");
            } else {
                let e = (grad[k] - central).abs() / grad[k].abs();
                assert!(
                    e < 1e-6,
                    "variable {k} at {vars:?}: {} vs {central}",
                    grad[k]
                );
                worst = worst.max(e);
            }
        }
    }
    worst
}

impl SlipState {
    /// The same state in plain numbers for [`LateralForceOf`].
    fn into_plain(self) -> SlipOf<f64> {
        SlipOf {
            alpha: self.alpha,
            fz: self.fz,
            mu_scale: self.mu_scale,
            speed: self.speed,
        }
    }
}

#[test]
fn magic_simple_derivatives_match_central_differences() {
    let e = largest_error(&MagicSimple::new(10.0, 1.3), 0.005..0.12, 1);
    eprintln!("magic-simple: largest relative error {e:.1e}");
}

#[test]
fn linear_derivatives_match_central_differences() {
    let e = largest_error(&Linear::new(55_000.0), 0.005..0.3, 2);
    eprintln!("linear: largest relative error {e:.1e}");
}

#[test]
fn gim_derivatives_match_central_differences_while_adhering_and_sliding() {
    // Adhesion at K = 50 kN/rad, μ ≥ 0.6, Fz ≥ 1 kN needs |tan α| < 3μFz/K.
    // Below 0.01 rad the friction decay moves the force by less than a
    // part in 1e5 over its box: the differences' rounding, not the
    // derivative, would be measured.
    let constant = Gim::new(50_000.0, 0.15, 1.0);
    let e0 = largest_error(&constant, 0.01..0.03, 3);
    let loaded = Gim {
        friction_decay: 0.3,
        load_exponent: 0.6,
        ..Gim::new(30_000.0, 0.15, 1.1)
    };
    let e1 = largest_error(&loaded, 0.01..0.06, 4);
    // Full sliding: only friction, decay, load and μ act.
    let e2 = largest_error(&loaded, 0.6..0.9, 5);
    eprintln!("gim: largest relative error {:.1e}", e0.max(e1).max(e2));
}
