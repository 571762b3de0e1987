//! DOP853 against closed forms: a damped oscillator's solution (at and
//! between the steps), the order of its steps and of its dense output,
//! breakpoints, and its evaluations against Dormand–Prince 5(4)'s.

use super::super::{dopri5, OdeSystem, Tolerances};
use super::dop853;

/// ẍ + 2ζω ẋ + ω² x = 0, counting its evaluations.
struct Oscillator {
    omega: f64,
    zeta: f64,
    calls: usize,
}

impl OdeSystem<2> for Oscillator {
    fn derivatives(&mut self, _t: f64, x: &[f64; 2]) -> [f64; 2] {
        self.calls += 1;
        let w = self.omega;
        [x[1], -2.0 * self.zeta * w * x[1] - w * w * x[0]]
    }
}

/// x(t) from x(0) = 1, ẋ(0) = 0, underdamped.
fn exact(o: &Oscillator, t: f64) -> f64 {
    let wd = o.omega * (1.0 - o.zeta * o.zeta).sqrt();
    let s = o.zeta * o.omega;
    (-s * t).exp() * ((wd * t).cos() + s / wd * (wd * t).sin())
}

fn oscillator() -> Oscillator {
    Oscillator {
        omega: 12.0,
        zeta: 0.3,
        calls: 0,
    }
}

fn tolerance(rtol: f64) -> Tolerances {
    Tolerances {
        rtol,
        atol: rtol * 1e-2,
        max_step: 1.0,
    }
}

/// The largest error of `sol`'s first state against the closed form every
/// millisecond over 3 s (between the steps as well as at them).
fn worst(o: &Oscillator, sol: &super::DenseSolution<2>) -> f64 {
    (0..=3000)
        .map(|i| 1e-3 * f64::from(i))
        .map(|t| (sol.state(t)[0] - exact(o, t)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn dop853_meets_its_tolerance_on_a_damped_oscillator_in_eighth_order_steps() {
    let mut runs = Vec::new();
    for rtol in [1e-6, 1e-8, 1e-10, 1e-12] {
        let mut o = oscillator();
        let sol = dop853(&mut o, 0.0, 3.0, [1.0, 0.0], &[], &tolerance(rtol));
        // Every evaluation counted, the dense output's included.
        assert_eq!(sol.stats.evaluations, o.calls);
        let err = worst(&o, &sol);
        runs.push((rtol, err, sol.stats.accepted));
    }
    eprintln!("{runs:?}");
    for (rtol, err, _) in &runs {
        assert!(*err < 5.0 * rtol, "rtol {rtol}: error {err}");
    }
    // Eighth order: 100× tighter costs 100^(1/8) ≈ 1.78× the steps (a
    // fifth-order pair's 2.5×).
    let ratio = runs[3].2 as f64 / runs[2].2 as f64;
    assert!((1.5..2.1).contains(&ratio), "{runs:?}");
}

#[test]
fn dop853_takes_half_the_evaluations_of_dopri5_for_the_same_error() {
    // Dormand–Prince 5(4) at rtol 1e-10 against DOP853 at rtol 1e-11 (a
    // tenth of it: the eighth-order pair's error per tolerance is larger).
    let (mut a, mut b) = (oscillator(), oscillator());
    let five = dopri5(&mut a, 0.0, 3.0, [1.0, 0.0], &[], &tolerance(1e-10));
    let eight = dop853(&mut b, 0.0, 3.0, [1.0, 0.0], &[], &tolerance(1e-11));
    let (e5, e8) = (worst(&a, &five), worst(&b, &eight));
    eprintln!(
        "dopri5 {e5:.2e} {:?}; dop853 {e8:.2e} {:?}",
        five.stats, eight.stats
    );
    assert!(e8 <= e5, "dop853 {e8:e}, dopri5 {e5:e}");
    assert!(
        2 * eight.stats.evaluations < five.stats.evaluations,
        "{:?} {:?}",
        eight.stats,
        five.stats
    );
}

#[test]
fn dense_output_is_seventh_order_between_steps() {
    // Steps forced long (a tolerance that accepts anything): the
    // interpolant's own error dominates the step's (ninth order locally)
    // and falls as h^8 per step.
    let run = |h: f64| {
        let mut o = Oscillator {
            omega: 1.0,
            zeta: 0.0,
            calls: 0,
        };
        let tol = Tolerances {
            rtol: 1.0,
            atol: 1.0,
            max_step: h,
        };
        let sol = dop853(&mut o, 0.0, h, [1.0, 0.0], &[], &tol);
        assert_eq!(sol.stats.accepted, 1);
        (0..=20)
            .map(|i| h * f64::from(i) / 20.0)
            .map(|t| (sol.state(t)[0] - t.cos()).abs())
            .fold(0.0, f64::max)
    };
    let (e1, e2) = (run(0.4), run(0.2));
    let order = (e1 / e2).log2();
    assert!(
        (7.5..9.0).contains(&order),
        "local order {order} ({e1}, {e2})"
    );
}

/// ẋ = 1 before t = 1, 0 from t = 1 on: a jump (an ideal step input).
struct Jump;
impl OdeSystem<1> for Jump {
    fn derivatives(&mut self, t: f64, _x: &[f64; 1]) -> [f64; 1] {
        [if t < 1.0 { 1.0 } else { 0.0 }]
    }
}

#[test]
fn a_jump_at_a_breakpoint_acts_from_the_breakpoint_on() {
    let sol = dop853(&mut Jump, 0.0, 2.0, [0.0], &[1.0], &Tolerances::default());
    assert!(sol.step_times().any(|t| t == 1.0));
    assert_eq!(sol.end(), 2.0);
    for t in [0.5, 0.999, 1.0, 1.5, 2.0] {
        let x = sol.state(t)[0];
        assert!((x - t.min(1.0)).abs() < 1e-13, "t {t}: {x}");
    }
}
