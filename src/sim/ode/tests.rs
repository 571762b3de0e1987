//! Tests of the integrators: orders of convergence, dense output, events
//! and the step-size control against closed-form solutions.

use super::*;

/// A damped oscillator ẍ + 2ζω ẋ + ω² x = 0 with a closed form.
struct Oscillator {
    omega: f64,
    zeta: f64,
    calls: usize,
}

impl OdeSystem<2> for Oscillator {
    fn derivatives(&mut self, _t: f64, x: &[f64; 2]) -> [f64; 2] {
        self.calls += 1;
        [
            x[1],
            -2.0 * self.zeta * self.omega * x[1] - self.omega * self.omega * x[0],
        ]
    }
}

fn exact(o: &Oscillator, t: f64) -> f64 {
    // x(0) = 1, ẋ(0) = 0, underdamped.
    let wd = o.omega * (1.0 - o.zeta * o.zeta).sqrt();
    let s = o.zeta * o.omega;
    (-s * t).exp() * ((wd * t).cos() + s / wd * (wd * t).sin())
}

#[test]
fn dopri5_meets_its_tolerance_on_a_damped_oscillator() {
    let mut errs = Vec::new();
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let mut o = Oscillator {
            omega: 12.0,
            zeta: 0.3,
            calls: 0,
        };
        let tol = Tolerances {
            rtol,
            atol: rtol * 1e-2,
            max_step: 1.0,
        };
        let sol = dopri5(&mut o, 0.0, 3.0, [1.0, 0.0], &[], &tol);
        assert_eq!(sol.stats.evaluations, o.calls);
        // Dense output between steps as well as at them.
        let err = (0..=3000)
            .map(|i| 1e-3 * i as f64)
            .map(|t| (sol.state(t)[0] - exact(&o, t)).abs())
            .fold(0.0, f64::max);
        errs.push((rtol, err, sol.stats.accepted));
    }
    for (rtol, err, _) in &errs {
        // The global error of a tolerance-controlled method stays within a
        // modest multiple of the tolerance.
        assert!(*err < 50.0 * rtol, "rtol {rtol}: error {err}");
    }
    // Fifth order: 100× tighter tolerance costs about 100^(1/5) ≈ 2.5× the steps.
    let ratio = errs[3].2 as f64 / errs[2].2 as f64;
    assert!((1.8..3.5).contains(&ratio), "{errs:?}");
}

#[test]
fn dense_output_is_fourth_order_between_steps() {
    // With steps forced long, the interpolant's own error dominates and
    // must fall as h^5 per step (local order of a 4th-order interpolant).
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
        let sol = dopri5(&mut o, 0.0, h, [1.0, 0.0], &[], &tol);
        (0..=20)
            .map(|i| h * i as f64 / 20.0)
            .map(|t| (sol.state(t)[0] - t.cos()).abs())
            .fold(0.0, f64::max)
    };
    let (e1, e2) = (run(0.2), run(0.1));
    let order = (e1 / e2).log2();
    assert!(
        (4.5..6.0).contains(&order),
        "local order {order} ({e1}, {e2})"
    );
}

/// ẋ = min(t, 1): a kink in the input (as at the end of a steer ramp)
/// that the solver must not straddle; x = t²/2, then 1/2 + (t − 1).
struct Ramp;
impl OdeSystem<1> for Ramp {
    fn derivatives(&mut self, t: f64, _x: &[f64; 1]) -> [f64; 1] {
        [t.min(1.0)]
    }
}

#[test]
fn breakpoints_land_exactly_and_keep_kinks_exact() {
    let tol = Tolerances::default();
    let sol = dopri5(&mut Ramp, 0.0, 2.0, [0.0], &[1.0, 5.0, -1.0], &tol);
    assert!(sol.step_times().any(|t| t == 1.0));
    assert_eq!(sol.end(), 2.0);
    let exact = |t: f64| if t <= 1.0 { 0.5 * t * t } else { t - 0.5 };
    // Each piece is a polynomial the fifth-order method integrates exactly.
    for t in [0.3, 0.999, 1.0, 1.001, 1.5, 2.0] {
        assert!((sol.state(t)[0] - exact(t)).abs() < 1e-13, "t {t}");
    }
    // Without the breakpoint a step straddles the kink and is inexact.
    let loose = Tolerances {
        rtol: 1e-3,
        atol: 1e-3,
        max_step: 0.3,
    };
    let straddled = dopri5(&mut Ramp, 0.0, 2.0, [0.0], &[], &loose);
    assert!(!straddled.step_times().any(|t| t == 1.0));
    assert!((straddled.state(2.0)[0] - 1.5).abs() > 1e-8);
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
    let sol = dopri5(&mut Jump, 0.0, 2.0, [0.0], &[1.0], &Tolerances::default());
    for t in [0.5, 0.999, 1.0, 1.5, 2.0] {
        assert!(
            (sol.state(t)[0] - t.min(1.0)).abs() < 1e-13,
            "t {t}: {}",
            sol.state(t)[0]
        );
    }
}

#[test]
fn crossings_are_located_to_the_tolerance() {
    let mut o = Oscillator {
        omega: 2.0,
        zeta: 0.0,
        calls: 0,
    };
    let sol = dopri5(&mut o, 0.0, 4.0, [1.0, 0.0], &[], &Tolerances::default());
    // cos(2t) = 0.5 first at t = π/6.
    let t = sol
        .first_crossing(0.0, 0.01, 1e-12, |_, x| x[0] - 0.5)
        .unwrap();
    assert!((t - std::f64::consts::PI / 6.0).abs() < 1e-8, "{t}");
    // After it, the next crossing is where cos(2t) = 0.5 again: 5π/6.
    let t2 = sol
        .first_crossing(t + 1e-6, 0.01, 1e-12, |_, x| x[0] - 0.5)
        .unwrap();
    assert!((t2 - 5.0 * std::f64::consts::PI / 6.0).abs() < 1e-8, "{t2}");
    assert!(sol
        .first_crossing(0.0, 0.01, 1e-12, |_, x| x[0] - 2.0)
        .is_none());
}

#[test]
fn rk4_is_fourth_order_on_the_oscillator() {
    let run = |h: f64| {
        let mut o = Oscillator {
            omega: 3.0,
            zeta: 0.1,
            calls: 0,
        };
        let n = (2.0 / h).round() as usize;
        let mut worst: f64 = 0.0;
        let mut recorded = [f64::NAN; 2];
        let last = rk4(&mut o, 0.0, h, n, [1.0, 0.0], |o, _, t, x| {
            worst = worst.max((x[0] - exact(o, t)).abs());
            recorded = *x;
            true
        });
        // The state returned is the one recorded at the last grid point.
        assert_eq!(last, recorded);
        worst
    };
    let order = (run(0.02) / run(0.01)).log2();
    assert!((3.8..4.2).contains(&order), "{order}");
}

/// A forced oscillator with a cubic damper, ẍ = −ω²x − c·ẋ³ + sin 2t:
/// nonlinear and non-autonomous. `implicit` is the column mask the
/// Rosenbrock–W method differences.
struct Forced {
    implicit: [bool; 2],
}

impl OdeSystem<2> for Forced {
    fn derivatives(&mut self, t: f64, x: &[f64; 2]) -> [f64; 2] {
        [x[1], -9.0 * x[0] - 0.5 * x[1].powi(3) + (2.0 * t).sin()]
    }
    fn implicit_states(&self) -> [bool; 2] {
        self.implicit
    }
}

/// The forced oscillator at 2 s by RK4 (`refresh` 0) or by ROS34PW2 with
/// its Jacobian every `refresh` steps.
fn forced_at_2s(implicit: [bool; 2], h: f64, refresh: usize) -> [f64; 2] {
    let mut sys = Forced { implicit };
    let n = (2.0 / h).round() as usize;
    match refresh {
        0 => rk4(&mut sys, 0.0, h, n, [1.0, 0.0], |_, _, _, _| true),
        k => rosenbrock_w(&mut sys, 0.0, h, n, [1.0, 0.0], k, |_, _, _, _| true),
    }
}

#[test]
fn rosenbrock_w_is_third_order_with_the_jacobian_and_without_part_of_it() {
    let reference = forced_at_2s([true; 2], 1e-4, 0);
    let errors = |implicit: [bool; 2], refresh: usize| -> Vec<f64> {
        [0.04, 0.02, 0.01, 0.005]
            .map(|h| {
                let x = forced_at_2s(implicit, h, refresh);
                (x[0] - reference[0]).hypot(x[1] - reference[1])
            })
            .to_vec()
    };
    // A W-method's order does not depend on the matrix standing in for the
    // Jacobian: the full one, a column left out, none at all. Over
    // 0.04 → 0.005 s the mean order is 3 (measured 2.93–3.02), each
    // halving gains more than 2.5.
    for implicit in [[true, true], [true, false], [false, false]] {
        let e = errors(implicit, 1);
        let mean = (e[0] / e[3]).log2() / 3.0;
        assert!((2.8..3.2).contains(&mean), "{implicit:?}: {e:?}");
        for pair in e.windows(2) {
            assert!((pair[0] / pair[1]).log2() > 2.5, "{implicit:?}: {e:?}");
        }
    }
    // One up to three steps old: still convergent, and at every step no
    // less accurate than a fresh one here (its error constant shifts as its
    // age in time shrinks: measured mean order 2.56 over this range).
    let fresh = errors([true, true], 1);
    let stale = errors([true, true], 4);
    for (s, f) in stale.iter().zip(&fresh) {
        assert!(s <= f, "stale {stale:?} fresh {fresh:?}");
    }
    assert!(stale[0] / stale[3] > 150.0, "{stale:?}");
}

/// Prothero–Robinson: ẋ = λ(x − sin t) + cos t, solution sin t from x = 0.
struct ProtheroRobinson {
    lambda: f64,
}

impl OdeSystem<1> for ProtheroRobinson {
    fn derivatives(&mut self, t: f64, x: &[f64; 1]) -> [f64; 1] {
        [self.lambda * (x[0] - t.sin()) + t.cos()]
    }
}

#[test]
fn rosenbrock_w_follows_a_very_stiff_solution_where_rk4_explodes() {
    let mut sys = ProtheroRobinson { lambda: -1e6 };
    // Started off the slow manifold by 0.5: L-stability damps the fast
    // transient within a step, and the solution then follows sin t to the
    // method's accuracy at h = 50 ms, 50,000 times the fast time constant
    // (measured 2.9e-5).
    let mut worst_after_first: f64 = 0.0;
    let last = rosenbrock_w(&mut sys, 0.0, 0.05, 40, [0.5], 1, |_, i, t, x| {
        if i > 0 {
            worst_after_first = worst_after_first.max((x[0] - t.sin()).abs());
        }
        true
    });
    assert!(worst_after_first < 5e-5, "{worst_after_first}");
    assert!((last[0] - 2.0_f64.sin()).abs() < 5e-5, "{last:?}");
    let rk = rk4(&mut sys, 0.0, 0.05, 40, [0.5], |_, _, _, _| true);
    assert!(!rk[0].is_finite() || rk[0].abs() > 1e6, "{rk:?}");
    // The stage nodes are the published ones' sums.
    assert!((W_NODES[2] - 0.731_579_957_788_852_4).abs() < 1e-15);
}

/// ẋ = −sign(x): from 1 the state reaches 0 at t = 1 and then chatters
/// about it, a right-hand side with no smooth solution to follow, as a
/// wheel lifting and landing under load transfer gives.
struct Chatter;

impl OdeSystem<1> for Chatter {
    fn derivatives(&mut self, _t: f64, x: &[f64; 1]) -> [f64; 1] {
        [-x[0].signum()]
    }
}

#[test]
fn an_integration_that_cannot_follow_its_model_stops_at_its_step_budget() {
    let tol = Tolerances::default();
    let sol = dopri5(&mut Chatter, 0.0, 3.0, [1.0], &[], &tol);
    assert!(sol.stats.stalled, "{:?}", sol.stats);
    assert_eq!(
        sol.stats.accepted + sol.stats.rejected,
        step_budget(3.0, &tol)
    );
    // It stopped near the switch, having followed the smooth part.
    assert!(sol.end() >= 1.0 - 1e-6 && sol.end() < 3.0, "{}", sol.end());
    assert!((sol.state(0.5)[0] - 0.5).abs() < 1e-9);
    // A smooth run spends a small share of the budget and is not stalled.
    let mut o = Oscillator {
        omega: 12.0,
        zeta: 0.3,
        calls: 0,
    };
    let smooth = dopri5(&mut o, 0.0, 3.0, [1.0, 0.0], &[], &tol);
    assert!(!smooth.stats.stalled);
    assert!(smooth.stats.accepted < step_budget(3.0, &tol) / 100);
}
