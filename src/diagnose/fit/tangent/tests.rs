//! The exact Jacobian against central differences of the residuals, for
//! every candidate effect, jointly with the axle characteristics, under
//! RK4 and under ROS34PW2; and against one-sided differences on a lower
//! bound (a delay or a lag at zero).

use super::*;
use crate::diagnose::effects::{EffectKind, RollDynamics};
use crate::diagnose::fit::problem::Problem;
use crate::measured::MeasuredRun;
use crate::optim::local::Residuals;
use crate::sim::Drive;
use crate::tyre::Tyre;
use crate::vehicle::{SteerPath, Vehicle, VehicleModel};

/// A run of `truth` driven through a steer sine while speeding up from 14
/// to 22 m/s over a road whose bank follows a slow sine, logged at 25 Hz
/// with every channel (yaw rate, ay, sideslip, ax and bank), prepared at
/// `step` with the load-transfer loop at rounding.
fn run(truth: &Augmented, step: f64, speed0: f64) -> Prepared {
    let t: Vec<f64> = (0..150).map(|i| 0.04 * i as f64).collect();
    let speed: Vec<f64> = t.iter().map(|&x| speed0 + 1.3 * x).collect();
    let steer: Vec<f64> = t
        .iter()
        .map(|&x| 0.03 * (std::f64::consts::TAU * 0.7 * (x - 0.5)).sin() * f64::from(x > 0.5))
        .collect();
    let bank: Vec<f64> = t.iter().map(|&x| 0.04 * (0.9 * x).sin()).collect();
    let drive = Drive::replay(&t, &steer, &speed, 1e-3, crate::sim::FixedStep::Rk4).with_channels(
        &t,
        None,
        Some(&bank),
    );
    let h = truth.simulate_from(&drive, 0.0, 0.0);
    let at = |v: &[f64]| -> Vec<f64> {
        t.iter()
            .map(|&s| crate::manoeuvre::interpolate(&h.t, v, s))
            .collect()
    };
    let (yaw_rate, ay, beta, n) = (at(&h.yaw_rate), at(&h.ay), at(&h.beta), t.len());
    let logged = MeasuredRun::new("run.csv", t, speed, steer, yaw_rate)
        .with_ay(ay)
        .with_beta(beta)
        .with_bank(bank)
        .with_ax(vec![1.3; n]);
    let mut p = Prepared::new(&logged, step, 25.0);
    p.load_tolerance = 1e-15;
    p
}

/// The plain model of parameters `q` of `layout` on `base`: what a
/// problem's `build` gives.
fn build(layout: &Layout, base: &Augmented, q: &[f64]) -> Augmented {
    layout.model(base, q)
}

/// A parameter value inside its box, 31.3 % of the way from its off value
/// (the middle when it has none) to its upper bound: a delay then falls
/// between the replay's stage times, where its residuals are smooth (a
/// delayed break point on a stage time is a kink, which central
/// differences straddle).
fn inside(q: &crate::diagnose::effects::Parameter) -> f64 {
    let (lo, hi) = q.bounds;
    let from = if q.off.is_finite() {
        q.off
    } else {
        0.5 * (lo + hi)
    };
    from + 0.313 * (hi - from)
}

/// The compact sedan on simplified-Magic-Formula axles with load
/// transfer, at road friction 0.9.
fn sedan() -> Augmented {
    let (f, r) = crate::diagnose::base::identify::axle_tyres(&[0.5, 0.55, 0.5]);
    Augmented::new(VehicleModel::new(Vehicle::compact_sedan(), f, r), 0.9)
}

/// The largest difference between a column of `exact` and of `reference`
/// over the column's largest entry.
/// A column the model does not see (a load transfer on tyres whose force
/// is proportional to their load) is compared with the largest entry of
/// the whole Jacobian: its differences are rounding.
fn column_errors(exact: &DMatrix<f64>, reference: &DMatrix<f64>) -> Vec<f64> {
    let floor = 1e-6 * exact.amax();
    (0..exact.ncols())
        .map(|k| {
            let scale = exact.column(k).amax().max(reference.column(k).amax());
            (exact.column(k) - reference.column(k)).amax() / scale.max(floor)
        })
        .collect()
}

/// Fourth-order central differences of `problem`'s residuals at `p`, with
/// steps of `step` of each parameter's box.
fn central(problem: &impl Residuals, p: &[f64], bounds: &[(f64, f64)], step: f64) -> DMatrix<f64> {
    let m = problem.count();
    let mut j = DMatrix::zeros(m, p.len());
    for k in 0..p.len() {
        let h = step * (bounds[k].1 - bounds[k].0);
        let at = |s: f64| {
            let mut q = p.to_vec();
            q[k] += s * h;
            let mut r = vec![0.0; m];
            problem.residuals(&q, &mut r);
            r
        };
        let (p1, m1, p2, m2) = (at(1.0), at(-1.0), at(2.0), at(-2.0));
        for i in 0..m {
            j[(i, k)] = (8.0 * (p1[i] - m1[i]) - (p2[i] - m2[i])) / (12.0 * h);
        }
    }
    j
}

/// The problem of `layout` on `runs` within `bounds`, its Jacobian exact
/// (one dual replay of each run).
fn exact_problem<'a>(
    (layout, base): (&'a Layout, &'a Augmented),
    runs: &'a [Prepared],
    bounds: &[(f64, f64)],
) -> Problem<'a, impl Fn(&[f64]) -> Augmented + Sync + 'a> {
    Problem::new(
        move |q: &[f64]| build(layout, base, q),
        runs.iter().collect(),
        [0.01, 0.2, 0.002],
        bounds.to_vec(),
    )
    .with_layout(
        layout.clone(),
        base,
        crate::optim::local::Derivatives::Exact,
    )
}

/// The exact Jacobian of the problem of `layout` on `runs` at `p`, and its
/// columns' errors against central differences of steps `step` of the
/// boxes.
fn check(
    (layout, base): (&Layout, &Augmented),
    runs: &[Prepared],
    p: &[f64],
    bounds: Vec<(f64, f64)>,
    step: f64,
) -> Vec<f64> {
    let problem = exact_problem((layout, base), runs, &bounds);
    let mut r = vec![0.0; problem.count()];
    problem.residuals(p, &mut r);
    let exact = problem.jacobian(p, &r, &bounds);
    assert_eq!(problem.jacobian_evaluations(p.len()), 1);
    column_errors(&exact, &central(&problem, p, &bounds, step))
}

/// How far central differences of steps 1e-3 and 5e-4 of the boxes
/// disagree, per column (relative, as [`column_errors`]).
fn reference_noise(
    (layout, base): (&Layout, &Augmented),
    runs: &[Prepared],
    p: &[f64],
    bounds: &[(f64, f64)],
) -> Vec<f64> {
    let problem = Problem::new(
        |q: &[f64]| build(layout, base, q),
        runs.iter().collect(),
        [0.01, 0.2, 0.002],
        bounds.to_vec(),
    );
    column_errors(
        &central(&problem, p, bounds, 1e-3),
        &central(&problem, p, bounds, 5e-4),
    )
}

/// The parameter vector and bounds of `kind` fitted with the axles.
fn vector(kind: EffectKind) -> (Vec<f64>, Vec<(f64, f64)>) {
    let mut p = vec![0.5, 0.55, 0.5];
    let mut b = crate::diagnose::model::axles::AXLE_BOUNDS.to_vec();
    let roll: &[crate::diagnose::effects::Parameter] = if kind.uses_roll() {
        RollDynamics::PARAMETERS
    } else {
        &[]
    };
    for q in kind.parameters().iter().chain(roll) {
        p.push(inside(q));
        b.push(q.bounds);
    }
    (p, b)
}

#[test]
fn every_effects_exact_jacobian_equals_central_differences_under_rk4() {
    let truth = sedan();
    let runs = vec![run(&truth, 0.01, 14.0)];
    for kind in EffectKind::ALL {
        let (layout, base) = (Layout::new(&[kind], true), sedan());
        let (p, bounds) = vector(kind);
        let errors = check((&layout, &base), &runs, &p, bounds, 1e-3);
        for (k, e) in errors.iter().enumerate() {
            assert!(*e < 1e-6, "{}: parameter {k}: {e:e}", kind.name());
        }
    }
}

#[test]
fn the_exact_jacobian_of_a_stiff_replay_by_ros34pw2_equals_central_differences() {
    // Racing axles (k of 60 and 80 1/rad) at 3–8 m/s on a 20 ms step: too
    // stiff for RK4, the replay runs by ROS34PW2.
    let mut car = sedan();
    car.model.vehicle = crate::vehicle::racing_car();
    let shares = crate::diagnose::base::identify::shares(60.0, 80.0, 1.6);
    (car.model.front, car.model.rear) = crate::diagnose::base::identify::axle_tyres(&shares);
    let runs = vec![run(&car, 0.02, 3.0)];
    assert_eq!(
        runs[0].drive_for(&car).method,
        crate::sim::FixedStep::RosenbrockW
    );
    for kind in [
        EffectKind::RelaxationLength,
        EffectKind::SteeringCompliance,
        EffectKind::RollCamber,
        EffectKind::SteerPath,
    ] {
        let layout = Layout::new(&[kind], true);
        let model = (&layout, &car);
        let (mut p, bounds) = vector(kind);
        p[..3].copy_from_slice(&shares);
        // ROS34PW2's matrix W is a forward difference of the right-hand
        // side (step 1e-7): its rounding, ~1e-9 of W, makes the plain
        // replay rough at about that level, which the differences amplify
        // by 1/step. Their own noise is measured by two step sizes; the
        // exact Jacobian must agree within 1e-6 or twice that noise.
        let errors = check(model, &runs, &p, bounds.clone(), 1e-3);
        let noise = reference_noise(model, &runs, &p, &bounds);
        for (k, e) in errors.iter().enumerate() {
            assert!(
                noise[k] < 1e-5,
                "{}: parameter {k}: noise {:e}",
                kind.name(),
                noise[k]
            );
            let allowed = 1e-6_f64.max(2.0 * noise[k]);
            assert!(
                *e < allowed,
                "{}: parameter {k}: {e:e} (noise {:e})",
                kind.name(),
                noise[k]
            );
        }
    }
}

#[test]
fn on_a_zero_delay_or_lag_the_exact_jacobian_is_the_one_sided_derivative_into_the_box() {
    let truth = sedan();
    let runs = [run(&truth, 0.01, 14.0)];
    for (kind, p) in [
        (EffectKind::SensorDelay, vec![0.0]),
        (EffectKind::SteerPath, vec![0.0, 0.0]),
        (EffectKind::SteerPath, vec![0.0537, 0.0]),
    ] {
        let (layout, base) = (Layout::new(&[kind], false), sedan());
        let bounds: Vec<(f64, f64)> = kind.parameters().iter().map(|q| q.bounds).collect();
        let problem = exact_problem((&layout, &base), &runs, &bounds);
        let mut r0 = vec![0.0; problem.count()];
        problem.residuals(&p, &mut r0);
        let exact = problem.jacobian(&p, &r0, &bounds);
        // Second-order one-sided differences into the box.
        let m = problem.count();
        let mut one_sided = DMatrix::zeros(m, p.len());
        for k in 0..p.len() {
            let h = 1e-5;
            let at = |s: f64| {
                let mut q = p.clone();
                q[k] += s * h;
                let mut r = vec![0.0; m];
                problem.residuals(&q, &mut r);
                r
            };
            let (r1, r2) = (at(1.0), at(2.0));
            for i in 0..m {
                one_sided[(i, k)] = (-3.0 * r0[i] + 4.0 * r1[i] - r2[i]) / (2.0 * h);
            }
        }
        for (k, e) in column_errors(&exact, &one_sided).iter().enumerate() {
            assert!(
                exact.column(k).amax() > 0.0,
                "{}: {k} sees nothing",
                kind.name()
            );
            assert!(*e < 1e-3, "{} at {p:?}: parameter {k}: {e:e}", kind.name());
        }
    }
}

#[test]
fn the_steer_paths_derivatives_are_its_central_differences() {
    use num_dual::Dual64;
    let t: Vec<f64> = (0..60).map(|i| 0.04 * i as f64).collect();
    let steer: Vec<f64> = t.iter().map(|&x| (2.0 * x).sin() * 0.03).collect();
    let at: Vec<f64> = (0..500).map(|i| 0.005 * i as f64).collect();
    // Delay, lag, and the ratio's gain and cubic term (a steer of 0.03 rad
    // at k₃ = 40 rad⁻² is 4 % off linear: the cubic's derivative is seen).
    for which in 0..4 {
        let p = [0.155, 0.155, 0.93, 40.0];
        let path = |v: [f64; 4]| {
            SteerPath {
                delay: v[0],
                lag: v[1],
                gain: v[2],
                cubic: v[3],
            }
            .apply(&t, &steer, &at)
        };
        let seed = |k: usize| Dual64::new(p[k], if which == k { 1.0 } else { 0.0 });
        let dual = SteerPath {
            delay: seed(0),
            lag: seed(1),
            gain: seed(2),
            cubic: seed(3),
        }
        .apply(&t, &steer, &at);
        let h = 1e-5;
        let shift = |s: f64| {
            let mut q = p;
            q[which] += s * h;
            path(q)
        };
        let (a, b) = (shift(1.0), shift(-1.0));
        for i in 0..at.len() {
            let c = (a[i] - b[i]) / (2.0 * h);
            assert!(
                (dual[i].eps - c).abs() < 1e-6,
                "{which} {i} {}: {} vs {c}",
                at[i],
                dual[i].eps
            );
        }
    }
}

#[test]
fn with_given_tyres_of_every_model_every_effects_exact_jacobian_holds() {
    use crate::tyre::{Gim, Pac89};
    let gim = Gim {
        load_exponent: 0.8,
        friction_decay: 0.1,
        ..Gim::new(60_000.0, 0.15, 1.0)
    };
    let tyres = [
        Tyre::Gim(gim),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Unitire(crate::tyre::tests::example_unitire()),
        Tyre::MagicFormula(Box::new(
            crate::io::tir::read_tir_text(
                "MagicFormula61_Parameters.tir",
                include_str!("../../../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
            )
            .unwrap(),
        )),
    ];
    for tyre in tyres {
        let car = Augmented::new(
            VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre.clone()),
            0.9,
        );
        let runs = vec![run(&car, 0.01, 14.0)];
        for kind in EffectKind::ALL {
            let layout = Layout::new(&[kind], false);
            let (p, bounds) = vector(kind);
            let (p, bounds) = (&p[3..], &bounds[3..]);
            let errors = check((&layout, &car), &runs, p, bounds.to_vec(), 1e-3);
            // The brush model's transition to full sliding is a kink of
            // its higher derivatives, which central differences feel: the
            // exact Jacobian must agree within 1e-6 or twice the
            // differences' own disagreement between two steps.
            let noise = reference_noise((&layout, &car), &runs, p, bounds);
            for (k, e) in errors.iter().enumerate() {
                let name = kind.name();
                assert!(
                    noise[k] < 1e-4,
                    "{tyre:?} {name}: parameter {k}: noise {:e}",
                    noise[k]
                );
                let allowed = 1e-6_f64.max(2.0 * noise[k]);
                assert!(*e < allowed, "{tyre:?} {name}: parameter {k}: {e:e}");
            }
        }
    }
}

#[test]
fn zz_dump_bits() {
    use std::fmt::Write;
    let truth = sedan();
    let runs = [run(&truth, 0.01, 14.0)];
    let mut out = String::new();
    let mut sets: Vec<Vec<EffectKind>> = EffectKind::ALL.iter().map(|k| vec![*k]).collect();
    sets.push(vec![EffectKind::RoadBank, EffectKind::BankProfile]);
    sets.push(vec![EffectKind::BankProfile, EffectKind::RoadBank]);
    sets.push(vec![EffectKind::AeroLoad, EffectKind::YawInertia]);
    sets.push(vec![
        EffectKind::RoadFriction,
        EffectKind::CorneringStiffness,
        EffectKind::RollSteer,
    ]);
    sets.push(vec![
        EffectKind::SensorBias,
        EffectKind::RollCamber,
        EffectKind::SteerPath,
    ]);
    for (n, kinds) in sets.iter().enumerate() {
        let axle = n % 2 == 0;
        let (layout, base) = (Layout::new(kinds, axle), sedan());
        let mut p = if axle { vec![0.5, 0.55, 0.5] } else { vec![] };
        let mut bounds = if axle {
            crate::diagnose::model::axles::AXLE_BOUNDS.to_vec()
        } else {
            vec![]
        };
        let roll: &[crate::diagnose::effects::Parameter] = if kinds.iter().any(|k| k.uses_roll()) {
            RollDynamics::PARAMETERS
        } else {
            &[]
        };
        for q in kinds.iter().flat_map(|k| k.parameters().iter()).chain(roll) {
            p.push(inside(q));
            bounds.push(q.bounds);
        }
        let problem = exact_problem((&layout, &base), &runs, &bounds);
        let mut r = vec![0.0; problem.count()];
        problem.residuals(&p, &mut r);
        let j = problem.jacobian(&p, &r, &bounds);
        let names: Vec<&str> = kinds.iter().map(|k| k.name()).collect();
        writeln!(out, "set {} axle {axle}", names.join("+")).unwrap();
        for x in &r {
            write!(out, "{:016x} ", x.to_bits()).unwrap();
        }
        writeln!(out).unwrap();
        for x in j.iter() {
            write!(out, "{:016x} ", x.to_bits()).unwrap();
        }
        writeln!(out).unwrap();
    }
    let path = std::env::var("DUMP").unwrap_or("/tmp/effects_dump.txt".into());
    std::fs::write(path, out).unwrap();
}
