//! Dormand–Prince on the nonlinear model with load transfer against a
//! fine classical RK4 (0.1 ms) on a 0.04 rad step steer at 80 km/h: the
//! simulation's rows, and the solver alone (`solve_dopri5`, what the peer
//! comparison with SciPy times) at tight and loose tolerances. Units: SI, rad.

use super::*;
use crate::sim::{DenseSolution, TimeHistory, Tolerances};

/// The step steer these tests integrate: 0.04 rad at 22.2 m/s from 0.5 s.
fn the_step() -> Manoeuvre {
    Manoeuvre::StepSteer(StepSteer {
        speed: 22.2222,
        amplitude: 0.04,
        trim: 0.0,
        start: 0.5,
        rise_time: 0.1,
        end: 4.0,
    })
}

/// The tight tolerances the simulation is checked at.
const TIGHT: Tolerances = Tolerances {
    rtol: 1e-9,
    atol: 1e-11,
    max_step: 0.05,
};

/// Dormand–Prince at 1 ms rows with tolerances `tol`.
fn dopri5_at(tol: Tolerances) -> Integrator {
    Integrator {
        step: 1e-3,
        method: Method::Dopri5(tol),
        ..Integrator::default()
    }
}

/// The reference (RK4 at 0.1 ms) and the simulation by Dormand–Prince at
/// [`TIGHT`]: its history and dense solution.
fn reference_and_simulation(m: &VehicleModel) -> (TimeHistory, TimeHistory, DenseSolution<2>) {
    let man = the_step();
    let fine = Integrator {
        step: 1e-4,
        ..rk4_1ms()
    }
    .run(m, &man, State::default());
    let sim = dopri5_at(TIGHT).simulate(m, &man, State::default());
    (fine, sim.history, sim.dense.expect("a dense solution"))
}

#[test]
fn dopri5_agrees_with_fine_rk4_on_a_step_steer_with_load_transfer() {
    let m = nonlinear_model();
    let (fine, h, sol) = reference_and_simulation(&m);
    assert_eq!(h.len(), 4001);
    let r_ss = fine.yaw_rate.last().copied().unwrap();
    for (i, t) in h.t.iter().enumerate() {
        let j = i * 10;
        assert!((fine.t[j] - t).abs() < 1e-12);
        assert!(
            (h.yaw_rate[i] - fine.yaw_rate[j]).abs() < 1e-7 * r_ss.abs(),
            "t {t}: {} vs {}",
            h.yaw_rate[i],
            fine.yaw_rate[j]
        );
        assert!((h.ay[i] - fine.ay[j]).abs() < 1e-6, "t {t}");
    }
    // A few hundred steps, not thousands.
    assert!(sol.stats.accepted < 400, "{:?}", sol.stats);
}

#[test]
fn dopri5_alone_is_the_simulations_solution_and_loose_still_agrees_with_fine_rk4() {
    let m = nonlinear_model();
    let man = the_step();
    let (fine, h, sol) = reference_and_simulation(&m);
    let r_ss = fine.yaw_rate.last().copied().unwrap();
    // The solver alone (what an ODE solver returns, the peer comparison's
    // job): the same solution as the simulation's, to the bit, and at
    // SciPy's rtol 1e-6 with no largest step still within 1e-6 of r_ss
    // of the fine RK4 at its rows, in fewer steps.
    let integ = dopri5_at(TIGHT);
    let alone = integ
        .solve_dopri5(&m, &man, State::default(), &TIGHT)
        .expect("(β, r) alone");
    assert_eq!(alone, sol);
    let loose = Tolerances {
        rtol: 1e-6,
        atol: 1e-9,
        max_step: f64::INFINITY,
    };
    let coarse = integ
        .solve_dopri5(&m, &man, State::default(), &loose)
        .expect("(β, r) alone");
    let mut states = Vec::new();
    coarse.states_into(&h.t, &mut states);
    for (i, x) in states.iter().enumerate() {
        let r = fine.yaw_rate[i * 10];
        assert!(
            (x[1] - r).abs() < 1e-6 * r_ss.abs(),
            "t {}: {} vs {r}",
            h.t[i],
            x[1]
        );
    }
    assert!(
        coarse.stats.accepted < sol.stats.accepted / 2,
        "{:?}",
        coarse.stats
    );
}

#[test]
fn dopri5_alone_has_no_solution_with_states_beyond_beta_and_r() {
    // With states beyond (β, r) there is no (β, r) solution to return.
    let mut lagged = nonlinear_model();
    lagged.options.effects.relaxation_length = 0.5;
    assert!(dopri5_at(TIGHT)
        .solve_dopri5(&lagged, &the_step(), State::default(), &TIGHT)
        .is_none());
}

/// The peer comparison's job (`sim::peer`, as `benches/simulate.rs` and
/// `examples/peer_jobs.rs` run it): the compact sedan on four PAC89 wheels (the
/// Adams example) with load transfer and exact kinematics, a 10 s step of
/// 0.012 rad in 0.1 s at 80 km/h.
fn peer_step() -> (VehicleModel, Manoeuvre) {
    let job = crate::sim::peer::PeerStepSteer::new();
    (job.model, job.manoeuvre)
}

/// The solver alone at SciPy's rtol 1e-10 (the ≥ 300× job) against a
/// reference by the same solver at rtol 1e-13 (its error a thousandth of
/// the job's): the yaw rate every 10 ms within 3e-11 of its steady value and
/// the sideslip (small when steady) within 1.5e-9 of its own, three times
/// what was measured (9.1e-12 and 4.4e-10, session 106), in no more
/// right-hand sides than before the step steer's speed-ups (2428, session 104). A
/// faster right-hand side or step control that lost accuracy, or bought
/// speed with more steps, fails here.
#[test]
fn the_pac89_step_at_scipys_tolerance_keeps_its_accuracy_against_a_tight_reference() {
    let (model, man) = peer_step();
    let integ = dopri5_at(TIGHT);
    let solve = |rtol: f64, atol: f64| {
        let tol = Tolerances {
            rtol,
            atol,
            max_step: f64::INFINITY,
        };
        integ
            .solve_dopri5(&model, &man, State::default(), &tol)
            .expect("(β, r) alone")
    };
    let (job, reference) = (solve(1e-10, 1e-13), solve(1e-13, 1e-16));
    let grid: Vec<f64> = (0..=1000).map(|i| f64::from(i) * 0.01).collect();
    let (mut x, mut x_ref) = (Vec::new(), Vec::new());
    job.states_into(&grid, &mut x);
    reference.states_into(&grid, &mut x_ref);
    let steady = x_ref.last().copied().unwrap();
    let worst = |k: usize| {
        x.iter()
            .zip(&x_ref)
            .map(|(a, b)| (a[k] - b[k]).abs() / steady[k].abs())
            .fold(0.0, f64::max)
    };
    let (beta, r) = (worst(0), worst(1));
    eprintln!(
        "beta {beta:.2e}, yaw rate {r:.2e} of steady; {:?}; reference {:?}",
        job.stats, reference.stats
    );
    assert!(
        r < 3e-11 && beta < 1.5e-9,
        "yaw rate {r:e}, sideslip {beta:e}"
    );
    assert!(job.stats.evaluations <= 2428, "{:?}", job.stats);
}
