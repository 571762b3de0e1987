//! The tyre models' generic lateral force and friction coefficient
//! ([`LateralForceOf`]) checked two ways. In `f64` they are the plain
//! methods ([`TyreModel::lateral_force`], [`TyreModel::friction_coefficient`])
//! bit for bit over a grid of slip states (to 1e-12 where a power is taken
//! as `e^(n·ln x)`). In dual numbers their derivatives with respect to the
//! slip angle, the load, the friction scale and every lateral parameter
//! equal fourth-order central differences of the plain methods to 1e-6
//! relative, at each model's small slip, near-peak, sliding and low-load
//! states, both signs of α.
//!
//! Where a derivative is all but zero (a parameter the force barely reads
//! there: UniTire's sliding law at a sliding speed of centimetres per
//! second moves Fy by parts in 1e10) the differences measure their own
//! rounding, not the derivative. The tolerance is therefore
//! `1e-6·|dual| + 1e-12·|F|/h`: each of the four values differenced carries
//! a rounding error below ~1000 ulps of `F` (2.2e-13·|F|), which the
//! stencil's weights (18/12) turn into at most 3.3e-13·|F|/h; the floor is
//! three times that. A derivative above `1e-6·|F|/h` relative to the
//! floor's scale is checked to 1e-6 relative.

use super::*;
use nalgebra::{Const, U1};
use num_dual::DualSVec64;

/// Directions of the dual numbers: α, Fz, μ, then up to fourteen
/// parameters (PAC89's a0..a13).
const DIRECTIONS: usize = 17;
type D = DualSVec64<DIRECTIONS>;

/// A slip state of a check: α (rad), Fz (N), μ scale, camber (rad).
#[derive(Debug, Clone, Copy)]
struct At {
    alpha: f64,
    fz: f64,
    mu: f64,
    camber: f64,
}

/// A state at `alpha_deg` degrees, no camber.
fn at(alpha_deg: f64, fz: f64, mu: f64) -> At {
    At {
        alpha: alpha_deg.to_radians(),
        fz,
        mu,
        camber: 0.0,
    }
}

/// Speed of every check, m/s (UniTire's sliding speed is `V·|sin α|`).
const SPEED: f64 = 10.0;

/// The plain slip state of variables `v` (α, Fz, μ, …) at camber `camber`.
fn plain_state(v: &[f64], camber: f64) -> SlipState {
    SlipState {
        alpha: v[0],
        kappa: 0.0,
        fz: v[1],
        camber,
        mu_scale: v[2],
        speed: SPEED,
    }
}

/// How far the dual derivatives `grad` of a function with value `value`
/// at `vars` lie from fourth-order central differences of `plain`, as the
/// worst ratio of the disagreement to the tolerance (module docs): at most
/// 1 passes. Steps are relative to the slip variables (1e-4) and to the
/// parameters or a tenth of their box (1e-3), so that truncation (h⁴)
/// stays below 1e-10 and no parameter is stepped by less than its box
/// allows.
fn worst_ratio(
    grad: &[f64],
    value: f64,
    vars: &[f64],
    bounds: &[(f64, f64)],
    plain: impl Fn(&[f64]) -> f64,
) -> f64 {
    let mut worst: f64 = 0.0;
    for k in 0..vars.len() {
        let h = if k < 3 {
            1e-4 * vars[k].abs().max(1e-2)
        } else {
            let (lo, hi) = bounds[k - 3];
            1e-3 * vars[k].abs().max(0.1 * (hi - lo))
        };
        let f = |m: f64| {
            let mut v = vars.to_vec();
            v[k] = vars[k] + m * h;
            plain(&v)
        };
        let central = (8.0 * (f(1.0) - f(-1.0)) - (f(2.0) - f(-2.0))) / (12.0 * h);
        let tolerance = 1e-6 * grad[k].abs() + 1e-12 * value.abs() / h;
        let ratio = (grad[k] - central).abs() / tolerance;
        assert!(
            ratio.is_finite(),
            "variable {k} at {vars:?}: {} vs {central}",
            grad[k]
        );
        worst = worst.max(ratio);
    }
    worst
}

/// The worst ratio (≤ 1 passes) over the lateral force and the friction
/// coefficient of `tyre` at state `s`: the dual value equals the plain one
/// to 1e-12 relative (dual numbers divide through the reciprocal), the dual
/// derivatives the central differences.
fn check<M>(tyre: &M, s: At) -> f64
where
    M: LateralForceOf + TyreModel + Clone,
{
    let p0 = tyre.parameters();
    let n = p0.len();
    assert!(3 + n <= DIRECTIONS);
    let vars: Vec<f64> = [s.alpha, s.fz, s.mu].iter().chain(&p0).copied().collect();
    let dual: Vec<D> = (0..3 + n).map(|k| D::from(vars[k]).derivative(k)).collect();
    let with = |v: &[f64]| {
        let mut m = tyre.clone();
        m.set_parameters(&v[3..]);
        m
    };
    let force = |v: &[f64]| with(v).lateral_force(&plain_state(v, s.camber));
    let friction = |v: &[f64]| with(v).friction_coefficient(v[1], v[2]);
    let slip = SlipOf {
        alpha: dual[0],
        fz: dual[1],
        mu_scale: dual[2],
        speed: SPEED,
    };
    let mut worst: f64 = 0.0;
    let f = tyre.lateral_force_at_camber_of(&dual[3..], &slip, s.camber);
    let mu = tyre.friction_coefficient_of(&dual[3..], dual[1], dual[2]);
    for (d, plain) in [(f, &force as &dyn Fn(&[f64]) -> f64), (mu, &friction)] {
        let value = plain(&vars);
        let grad = d.eps.unwrap_generic(Const::<DIRECTIONS>, U1);
        if value.is_infinite() {
            // No friction limit (the linear tyre): nothing to differentiate.
            assert_eq!(d.re, value);
            assert!(grad.iter().all(|g| *g == 0.0), "{grad:?}");
            continue;
        }
        assert!(
            (d.re - value).abs() <= 1e-12 * value.abs(),
            "{} vs {value} at {s:?}",
            d.re
        );
        worst = worst.max(worst_ratio(
            &grad.as_slice()[..3 + n],
            value,
            &vars,
            &tyre.bounds(),
            plain,
        ));
    }
    worst
}

/// [`check`] at every state and at its mirror in α; the worst ratio.
fn check_states<M>(tyre: &M, states: &[At]) -> f64
where
    M: LateralForceOf + TyreModel + Clone,
{
    let mut worst: f64 = 0.0;
    for s in states {
        for sign in [1.0, -1.0] {
            let s = At {
                alpha: sign * s.alpha,
                ..*s
            };
            let r = check(tyre, s);
            assert!(r <= 1.0, "{r:.2} times the tolerance at {s:?}");
            worst = worst.max(r);
        }
    }
    worst
}

#[test]
fn magic_simple_derivatives_match_central_differences() {
    let tyre = MagicSimple {
        d: 0.95,
        ..MagicSimple::new(10.0, 1.3)
    };
    // Peak at C·atan(B·α) = π/2: α ≈ 15°.
    let states = [
        at(0.3, 4000.0, 1.0),
        at(15.0, 5000.0, 0.9),
        at(35.0, 4000.0, 1.1),
        at(8.0, 300.0, 1.0),
    ];
    let r = check_states(&tyre, &states);
    eprintln!("magic-simple: worst {r:.1e} of the tolerance");
}

#[test]
fn linear_derivatives_match_central_differences() {
    let states = [
        at(0.3, 4000.0, 1.0),
        at(5.0, 5000.0, 0.9),
        at(25.0, 4000.0, 1.1),
        at(3.0, 300.0, 1.0),
    ];
    let r = check_states(&Linear::new(55_000.0), &states);
    eprintln!("linear: worst {r:.1e} of the tolerance");
}

#[test]
fn gim_derivatives_match_central_differences_while_adhering_and_sliding() {
    // K = 30 kN/rad at 4 kN: full sliding from |tan α| = 3μFz/K ≈ 0.40
    // (22°); 18° adheres (ln ≈ 0.19), 35° slides. At 300 N, K = 6.3 kN/rad
    // and sliding starts at 8.7°.
    let loaded = Gim {
        friction_decay: 0.3,
        load_exponent: 0.6,
        ..Gim::new(30_000.0, 0.15, 1.1)
    };
    let states = [
        at(0.5, 4000.0, 1.0),
        at(18.0, 4000.0, 1.0),
        at(35.0, 5000.0, 0.9),
        at(3.0, 300.0, 1.0),
    ];
    let r1 = check_states(&loaded, &states);
    // Constant friction and stiffness: the derivatives in A_s and n at 0.
    let r0 = check_states(&Gim::new(50_000.0, 0.15, 1.0), &states);
    eprintln!("gim: worst {:.1e} of the tolerance", r0.max(r1));
}

#[test]
fn unitire_derivatives_match_central_differences() {
    // φ = K·tan α/(μ·Fz) ≈ 12.6·tan α at the rated load: F̄ ≈ 0.95 at 13°.
    let states = [
        at(0.3, 5700.0, 1.0),
        at(10.0, 5700.0, 0.9),
        at(30.0, 4000.0, 1.1),
        at(4.0, 500.0, 1.0),
    ];
    let r = check_states(&tests::example_unitire(), &states);
    eprintln!("unitire: worst {r:.1e} of the tolerance");
}

#[test]
fn pac89_derivatives_match_central_differences_with_and_without_camber() {
    // The Adams example peaks near 6° at 4 kN.
    let cambered = At {
        camber: 2f64.to_radians(),
        ..at(4.0, 4000.0, 1.0)
    };
    let states = [
        at(0.3, 4000.0, 1.0),
        at(6.0, 5700.0, 0.9),
        at(20.0, 4000.0, 1.1),
        at(3.0, 500.0, 1.0),
        cambered,
    ];
    let r = check_states(&Pac89::adams_example(), &states);
    eprintln!("pac89: worst {r:.1e} of the tolerance");
}

/// Magic-simple whose generic force carries a wrong α-derivative (the
/// value is the same): the check must see it.
#[derive(Debug, Clone)]
struct Skewed(MagicSimple);

impl TyreModel for Skewed {
    fn forces(&self, s: &SlipState) -> TyreForces {
        self.0.forces(s)
    }
}

impl Parameterised for Skewed {
    fn parameter_names(&self) -> Vec<&'static str> {
        self.0.parameter_names()
    }
    fn parameters(&self) -> Vec<f64> {
        self.0.parameters()
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.0.set_parameters(p)
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        self.0.bounds()
    }
}

impl LateralForceOf for Skewed {
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        // Zero in value, 1e-5 of the cornering stiffness in slope.
        let skew = (s.alpha - s.alpha.re()) * (1e-5 * 13.0) * s.fz;
        self.0.lateral_force_of(p, s) + skew
    }
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], fz: T, mu_scale: T) -> T {
        self.0.friction_coefficient_of(p, fz, mu_scale)
    }
}

#[test]
fn the_check_sees_a_derivative_wrong_by_a_part_in_1e5() {
    let r = check(&Skewed(MagicSimple::new(10.0, 1.3)), at(0.3, 4000.0, 1.0));
    assert!(r > 5.0, "{r}");
}

/// Slip angles −30°..30° (zero included), loads from off the ground to
/// 8.6 kN, three friction scales, two speeds: the plain state of each.
fn grid() -> Vec<SlipState> {
    let mut out = Vec::new();
    for i in -60..=60 {
        for fz in [-100.0, 0.0, 300.0, 2800.0, 5700.0, 8600.0] {
            for mu in [0.0, 0.5, 1.0, 1.2] {
                for speed in [10.0, 25.0] {
                    out.push(SlipState {
                        mu_scale: mu,
                        speed,
                        ..SlipState::lateral((0.5 * i as f64).to_radians(), fz)
                    });
                }
            }
        }
    }
    out
}

/// The generic lateral force in `f64` against the plain one over the grid
/// (cambers 0, 2°, −3°) and the friction coefficient likewise: bit for bit,
/// or to `relative` where the generic form rounds otherwise.
fn same_in_f64<M: LateralForceOf + TyreModel>(tyre: &M, relative: f64) {
    let p = tyre.parameters();
    let close = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a - b).abs() <= relative * b.abs();
    for s in grid() {
        for camber in [0.0, 2f64.to_radians(), -3f64.to_radians()] {
            let s = SlipState { camber, ..s };
            let plain = tyre.lateral_force(&s);
            let slip = SlipOf {
                alpha: s.alpha,
                fz: s.fz,
                mu_scale: s.mu_scale,
                speed: s.speed,
            };
            let generic = tyre.lateral_force_at_camber_of(&p, &slip, camber);
            assert!(close(generic, plain), "{generic} vs {plain} at {s:?}");
            if camber == 0.0 {
                assert_eq!(
                    tyre.lateral_force_of(&p, &slip).to_bits(),
                    generic.to_bits()
                );
            }
        }
        let plain = tyre.friction_coefficient(s.fz, s.mu_scale);
        let generic = tyre.friction_coefficient_of(&p, s.fz, s.mu_scale);
        assert!(close(generic, plain), "{generic} vs {plain} at {s:?}");
    }
}

#[test]
fn the_generic_forms_are_the_plain_methods_in_f64() {
    same_in_f64(&Pac89::adams_example(), 0.0);
    same_in_f64(&tests::example_unitire(), 0.0);
    same_in_f64(&MagicSimple::new(10.0, 1.3), 0.0);
    same_in_f64(&Linear::new(55_000.0), 0.0);
    same_in_f64(&Gim::new(50_000.0, 0.15, 1.0), 0.0);
    // K·(Fz/Fz_ref)^n as K·e^(n·ln(Fz/Fz_ref)): to rounding.
    let loaded = Gim {
        friction_decay: 0.3,
        load_exponent: 0.6,
        ..Gim::new(30_000.0, 0.15, 1.1)
    };
    same_in_f64(&loaded, 1e-12);
}

#[test]
fn the_tyre_dispatches_the_generic_forms_and_refuses_the_others() {
    let s = SlipState {
        mu_scale: 0.9,
        ..SlipState::lateral(0.07, 4200.0)
    };
    let slip = SlipOf {
        alpha: s.alpha,
        fz: s.fz,
        mu_scale: s.mu_scale,
        speed: s.speed,
    };
    for t in tests::all_models() {
        let p = t.lateral_parameters().unwrap();
        assert_eq!(p, t.parameters());
        assert_eq!(t.lateral_force_of(&p, &slip), Some(t.lateral_force(&s)));
        assert_eq!(
            t.friction_coefficient_of(&p, s.fz, s.mu_scale),
            Some(t.friction_coefficient(s.fz, s.mu_scale))
        );
    }
    let mf = crate::io::tir::read_tir_text(
        "MagicFormula61_Parameters.tir",
        include_str!("../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
    )
    .unwrap();
    // The Magic Formula's generic force is its own formulae written out
    // (not the vectorised fast path): equal to rounding, not bit for bit.
    let t = Tyre::MagicFormula(Box::new(mf));
    let p = t.lateral_parameters().unwrap();
    let f = t.lateral_force_of(&p, &slip).unwrap();
    assert!((f - t.lateral_force(&s)).abs() <= 1e-12 * f.abs(), "{f}");
    assert_eq!(
        t.friction_coefficient_of(&p, s.fz, s.mu_scale),
        Some(t.friction_coefficient(s.fz, s.mu_scale))
    );
    let registered = Tyre::Registered(Erased::new(Linear::new(55_000.0)));
    let p = registered.parameters();
    assert_eq!(registered.lateral_parameters(), None);
    assert_eq!(registered.lateral_force_of(&p, &slip), None);
    assert_eq!(
        registered.friction_coefficient_of(&p, s.fz, s.mu_scale),
        None
    );
}

#[test]
fn magic_formula_derivatives_match_central_differences() {
    // MFeval's public 6.1 file (its load range 0.2–11 kN); no camber, the
    // vehicle's wheel.
    let mf = crate::io::tir::read_tir_text(
        "MagicFormula61_Parameters.tir",
        include_str!("../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
    )
    .unwrap();
    let states = [
        at(0.3, 4000.0, 1.0),
        at(6.0, 5700.0, 0.9),
        at(20.0, 4000.0, 1.1),
        at(3.0, 800.0, 1.0),
    ];
    let r = check_states(&mf, &states);
    eprintln!("mf61: worst {r:.1e} of the tolerance");
}
