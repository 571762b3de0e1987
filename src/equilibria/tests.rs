use super::*;
use crate::tyre::{MagicSimple, Tyre};
use crate::vehicle::{Kinematics, ModelOptions, Vehicle};
use approx::assert_relative_eq;

pub(crate) fn equilibria_model(load_transfer: bool) -> VehicleModel {
    let mut m = VehicleModel::new(
        Vehicle::compact_sedan(),
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
    );
    m.options = ModelOptions {
        kinematics: Kinematics::SmallAngle,
        load_transfer,
        ..ModelOptions::default()
    };
    m
}

fn cond(steer: f64, friction: f64, kmh: f64) -> Condition {
    Condition {
        steer,
        friction,
        speed: kmh / 3.6,
    }
}

const BOX: SearchBox = SearchBox {
    beta_max: 0.6,
    yaw_rate_max: 1.5,
};

fn steer_grid(lt: bool) -> (VehicleModel, sweep::Grid) {
    (
        equilibria_model(lt),
        sweep::Grid {
            steer: (0..=10).map(|i| 0.02 * i as f64).collect(),
            friction: vec![0.8],
            speed: vec![70.0 / 3.6],
        },
    )
}

fn run(m: &VehicleModel, g: &sweep::Grid, s: &pso::PsoSearch) -> sweep::SweepResult {
    sweep::run(m, g, &BOX, s, true, &std::sync::atomic::AtomicUsize::new(0))
}

#[test]
fn linear_tyres_give_the_closed_form_steady_state() {
    let m = crate::vehicle::linear_bicycle();
    let v = &m.vehicle;
    let (cf, cr, u, d) = (110_000.0, 120_000.0, 20.0, 0.03);
    // Linear bicycle model: A·x + B·δ = 0.
    let a11 = -(cf + cr) / (v.mass * u);
    let a12 = (v.b * cr - v.a * cf) / (v.mass * u * u) - 1.0;
    let a21 = (v.b * cr - v.a * cf) / v.yaw_inertia;
    let a22 = -(v.a * v.a * cf + v.b * v.b * cr) / (v.yaw_inertia * u);
    let (b1, b2) = (cf / (v.mass * u) * d, v.a * cf / v.yaw_inertia * d);
    let det = a11 * a22 - a12 * a21;
    let beta = -(a22 * b1 - a12 * b2) / det;
    let r = -(-a21 * b1 + a11 * b2) / det;
    let c = Condition {
        steer: d,
        friction: 1.0,
        speed: u,
    };
    let ex = exact::solve(&m, &c);
    let (ps, _) = pso::search(&m, &c, &BOX, &pso::PsoSearch::default(), &[]);
    assert_eq!(ex.len(), 1);
    assert_eq!(ps.len(), 1);
    for e in [ex[0], ps[0]] {
        assert_relative_eq!(e.beta, beta, max_relative = 1e-10);
        assert_relative_eq!(e.yaw_rate, r, max_relative = 1e-10);
        assert!(e.stability.kind.is_stable());
    }
    assert_relative_eq!(r / d, m.linear_yaw_rate_gain(u), max_relative = 1e-10);
}

#[test]
fn mirrored_steer_mirrors_the_equilibria() {
    for lt in [false, true] {
        let mut m = equilibria_model(lt);
        m.options.kinematics = Kinematics::Exact;
        for d in [0.01, 0.05, 0.13] {
            let p = exact::solve(&m, &cond(d, 0.8, 70.0));
            let n = exact::solve(&m, &cond(-d, 0.8, 70.0));
            assert_eq!(p.len(), n.len());
            // Ascending αr on one side is descending on the other.
            for (a, b) in p.iter().zip(n.iter().rev()) {
                assert_relative_eq!(a.beta, -b.beta, epsilon = 1e-12);
                assert_relative_eq!(a.yaw_rate, -b.yaw_rate, epsilon = 1e-12);
                assert_eq!(a.stability.kind, b.stability.kind);
            }
            let s = pso::PsoSearch::default();
            let (pp, _) = pso::search(&m, &cond(d, 0.8, 70.0), &BOX, &s, &[]);
            let (pn, _) = pso::search(&m, &cond(-d, 0.8, 70.0), &BOX, &s, &[]);
            assert_eq!(pp.len(), pn.len());
            for (a, b) in pp.iter().zip(pn.iter().rev()) {
                assert_relative_eq!(a.beta, -b.beta, epsilon = 1e-12);
            }
        }
    }
}

#[test]
fn pso_and_exact_agree_on_the_equilibria_sweeps() {
    for lt in [false, true] {
        let (m, g) = steer_grid(lt);
        let r = run(&m, &g, &pso::PsoSearch::default());
        assert_eq!(r.agreeing(), r.points.len(), "load transfer {lt}");
        for p in &r.points {
            assert!(!p.found.is_empty());
            for f in &p.found {
                assert!(f.equilibrium.residual <= 1e-10, "{:?}", f);
            }
        }
        // The three equilibria at small steer: two saddles around a stable
        // straight-running node.
        let kinds: Vec<Kind> = r.points[0].exact.iter().map(|e| e.stability.kind).collect();
        assert_eq!(kinds, [Kind::Saddle, Kind::StableNode, Kind::Saddle]);
    }
    let friction = sweep::Grid {
        steer: vec![0.1],
        friction: (2..=10).map(|i| 0.1 * i as f64).collect(),
        speed: vec![30.0 / 3.6],
    };
    let speed = sweep::Grid {
        steer: vec![0.1],
        friction: vec![0.8],
        speed: (3..=12).map(|i| 10.0 * i as f64 / 3.6).collect(),
    };
    for g in [friction, speed] {
        let r = run(&equilibria_model(false), &g, &pso::PsoSearch::default());
        assert_eq!(r.agreeing(), r.points.len());
    }
}

#[test]
fn li_jia_zhao_fitness_misses_the_stable_node_the_newton_step_finds() {
    let (m, g) = steer_grid(false);
    let raw = pso::PsoSearch {
        fitness: pso::Fitness::Residual,
        certify: false,
        ..Default::default()
    };
    let r = run(&m, &g, &raw);
    let missed = r.points.len() - r.agreeing();
    assert!(
        missed > 0,
        "the residual fitness of Li, Jia & Zhao found everything this time"
    );
    let missed_nodes = r
        .points
        .iter()
        .flat_map(|p| &p.found)
        .filter(|f| {
            f.in_box && f.found_by == FoundBy::Exact && f.equilibrium.stability.kind.is_stable()
        })
        .count();
    assert!(missed_nodes > 0);
    // The winding-number certificate makes even Li, Jia & Zhao's fitness complete:
    // it keeps searching until the indices add up.
    let certified = run(
        &m,
        &g,
        &pso::PsoSearch {
            certify: true,
            ..raw
        },
    );
    assert_eq!(certified.agreeing(), certified.points.len());
}

#[test]
fn winding_number_equals_the_index_sum() {
    let m = equilibria_model(false);
    for d in [0.0, 0.03, 0.1] {
        let c = cond(d, 0.8, 70.0);
        let w = pso::winding_number(&m, &c, &BOX).unwrap();
        let sum: i32 = exact::solve(&m, &c)
            .iter()
            .filter(|e| BOX.contains([e.beta, e.yaw_rate]))
            .map(|e| if e.stability.determinant > 0.0 { 1 } else { -1 })
            .sum();
        assert_eq!(w, sum, "δ = {d}");
    }
}

#[test]
fn the_steer_sweep_has_one_verified_fold_where_node_and_saddle_meet() {
    // A softer rear axle (b = 9): a generic fold. (With identical axles
    // three equilibria meet at once: the pitchfork checked below.)
    let (mut m, g) = steer_grid(false);
    m.rear = Tyre::MagicSimple(MagicSimple::new(9.0, 1.3));
    let r = run(&m, &g, &pso::PsoSearch::default());
    assert_eq!(r.agreeing(), r.points.len());
    let folds: Vec<_> = r
        .bifurcations
        .iter()
        .filter(|b| b.kind == bifurcation::BifurcationKind::Fold)
        .collect();
    assert_eq!(folds.len(), 1, "{folds:?}");
    let f = folds[0];
    assert!(f.verified, "{f:?}");
    assert!(f.residual < 1e-8 && f.criterion.abs() < 1e-3);
    assert!(f.kinds.contains(&Kind::Saddle) && f.kinds.iter().any(|k| k.is_stable()));
    // Just before the fold the pair is there, just after it is gone.
    let before = exact::solve(
        &m,
        &Condition {
            steer: f.at.steer - 1e-9,
            ..f.at
        },
    );
    let after = exact::solve(
        &m,
        &Condition {
            steer: f.at.steer + 1e-9,
            ..f.at
        },
    );
    assert_eq!(before.len(), after.len() + 2);
}

#[test]
fn identical_axles_meet_in_a_pitchfork() {
    let (m, g) = steer_grid(false);
    let r = run(&m, &g, &pso::PsoSearch::default());
    assert_eq!(r.bifurcations.len(), 1, "{:?}", r.bifurcations);
    let b = r.bifurcations[0];
    assert_eq!(b.kind, bifurcation::BifurcationKind::Pitchfork);
    assert!(b.verified && b.at.steer > 0.057 && b.at.steer < 0.058);
    // Just before it four equilibria, just after two.
    let n = |d: f64| exact::solve(&m, &Condition { steer: d, ..b.at }).len();
    assert_eq!((n(b.at.steer - 1e-7), n(b.at.steer + 1e-7)), (4, 2));
}

#[test]
fn approaching_equilibria_without_a_count_change_are_not_a_fold() {
    // Along a speed line at small steer the node and a saddle move toward
    // each other, but no pair is created or destroyed.
    let g = sweep::Grid {
        steer: vec![0.01],
        friction: vec![0.8],
        speed: (3..=6).map(|i| 10.0 * i as f64 / 3.6).collect(),
    };
    let r = run(&equilibria_model(false), &g, &pso::PsoSearch::default());
    let counts: Vec<usize> = r.points.iter().map(|p| p.exact.len()).collect();
    assert!(counts.windows(2).all(|w| w[0] == w[1]), "{counts:?}");
    assert!(r.bifurcations.is_empty(), "{:?}", r.bifurcations);
}

#[test]
fn sweeps_are_deterministic_for_a_seed() {
    let (m, g) = steer_grid(true);
    let s = pso::PsoSearch {
        seed: 9,
        ..Default::default()
    };
    let a = run(&m, &g, &s);
    let b = run(&m, &g, &s);
    assert_eq!(a, b);
}

#[test]
fn classic_brush_tyres_give_a_continuum_when_both_axles_slide() {
    let mut m = equilibria_model(false);
    m.front = Tyre::Gim(crate::tyre::Gim::new(57_000.0, 0.18, 1.0));
    m.rear = m.front.clone();
    let c = cond(0.05, 0.8, 70.0);
    let cont = exact::continua(&m, &c);
    assert_eq!(cont.len(), 2, "{cont:?}");
    // On the continuum both axles slide: r = μ·g/u.
    for k in &cont {
        assert_relative_eq!(
            k.yaw_rate.0.abs(),
            0.8 * crate::constants::G / c.speed,
            max_relative = 1e-9
        );
    }
    // Isolated equilibria remain few, and PSO agrees on them.
    let ex = exact::solve(&m, &c);
    assert!(ex.len() <= 3, "{}", ex.len());
    let (ps, _) = pso::search(&m, &c, &BOX, &pso::PsoSearch::default(), &[]);
    let (_, agree) = sweep::cross_check(&ex, &ps, &cont, &BOX);
    assert!(agree);
    // With Gim's friction fall-off the continuum is gone.
    m.front = Tyre::Gim(crate::tyre::Gim {
        friction_decay: 0.2,
        ..crate::tyre::Gim::new(57_000.0, 0.18, 1.0)
    });
    m.rear = m.front.clone();
    assert!(exact::continua(&m, &c).is_empty());
}

#[test]
fn equilibrium_residual_jacobian_matches_differences_of_the_residual() {
    // PAC89 on four wheels with load transfer (closed-form tyre partials)
    // and Gim without (differenced tyres), both kinematics, over the box.
    use crate::tyre::{Gim, Pac89};
    use crate::vehicle::{State, VehicleModel};
    let pac = Tyre::Pac89(Pac89::adams_example());
    let gim = Tyre::Gim(Gim::new(57_296.0, 0.18, 1.0));
    let mut checked = 0;
    for (tyre, load_transfer) in [(pac, true), (gim, false)] {
        for kinematics in [Kinematics::Exact, Kinematics::SmallAngle] {
            let mut m = VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre.clone());
            m.options = ModelOptions {
                kinematics,
                load_transfer,
                ..ModelOptions::default()
            };
            let c = Condition {
                steer: 0.06,
                friction: 0.8,
                speed: 20.0,
            };
            for (b, r) in [
                (0.0, 0.0),
                (0.05, 0.3),
                (-0.2, 0.9),
                (0.3, -0.4),
                (0.02, 0.05),
            ] {
                let x = [b, r];
                let (f, j) = m.equilibrium_residual(
                    &State {
                        beta: b,
                        yaw_rate: r,
                    },
                    &c.inputs(),
                );
                let f_ref = residual_at_equilibrium_loads(&m, &c, x);
                for i in 0..2 {
                    // The same function, summed in another order.
                    assert!(
                        (f[i] - f_ref[i]).abs() <= 1e-12 * (1.0 + f_ref[i].abs()),
                        "{f:?} vs {f_ref:?}"
                    );
                }
                for k in 0..2 {
                    let h = 1e-6;
                    let (mut xp, mut xm) = (x, x);
                    xp[k] += h;
                    xm[k] -= h;
                    let (fp, fm) = (
                        residual_at_equilibrium_loads(&m, &c, xp),
                        residual_at_equilibrium_loads(&m, &c, xm),
                    );
                    for i in 0..2 {
                        let fd = (fp[i] - fm[i]) / (2.0 * h);
                        // Central differences are good to ~1e-8 relative
                        // here; Gim's own forward differences to ~1e-5.
                        let tol = if load_transfer { 1e-6 } else { 1e-4 };
                        assert!(
                            (j[i][k] - fd).abs() <= tol * (1.0 + fd.abs()),
                            "{kinematics:?} x {x:?}: J[{i}][{k}] {} vs {fd}",
                            j[i][k]
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(checked, 80);
}

#[test]
fn the_fastest_rate_is_the_largest_eigenvalue_of_straight_running() {
    // The replays' step rule rests on this estimate: for the 2-DOF model
    // (exact and small-angle kinematics, with and without load transfer)
    // it must be the largest eigenvalue magnitude of the model's own
    // Jacobian at straight running, from a soft sedan to the stiff racing
    // axles the Putnam log's fit asks for.
    let tyre = |b: f64, d: f64| Tyre::MagicSimple(MagicSimple { b, c: 1.3, d });
    for (vehicle, front, rear) in [
        (Vehicle::compact_sedan(), tyre(10.0, 1.0), tyre(12.0, 1.0)),
        (
            crate::vehicle::racing_car(),
            tyre(9.3, 3.5),
            tyre(80.0, 3.5),
        ),
    ] {
        for load_transfer in [false, true] {
            for kinematics in [Kinematics::Exact, Kinematics::SmallAngle] {
                let mut m = VehicleModel::new(vehicle.clone(), front.clone(), rear.clone());
                m.options = ModelOptions {
                    kinematics,
                    load_transfer,
                    ..ModelOptions::default()
                };
                for speed in [5.0, 15.0, 40.0] {
                    let c = Condition {
                        steer: 0.0,
                        friction: 1.0,
                        speed,
                    };
                    let s = stability::from_jacobian(stability::jacobian(&m, &c, [0.0, 0.0]));
                    let largest = s
                        .eigenvalues
                        .iter()
                        .map(|(re, im)| re.hypot(*im))
                        .fold(0.0, f64::max);
                    // The roll mode is integrated in every replay: its
                    // rate joins, from its own 2×2 system.
                    let (w, z) = (
                        std::f64::consts::TAU * m.options.effects.roll.frequency,
                        m.options.effects.roll.damping,
                    );
                    let roll = stability::from_jacobian([[0.0, 1.0], [-w * w, -2.0 * z * w]])
                        .eigenvalues
                        .iter()
                        .map(|(re, im)| re.hypot(*im))
                        .fold(0.0, f64::max);
                    assert_relative_eq!(
                        m.fastest_rate(speed, 1.0),
                        largest.max(roll),
                        max_relative = 1e-6
                    );
                }
            }
        }
    }
}

#[test]
fn a_line_of_steers_sharing_the_rear_scan_gives_the_same_equilibria_to_the_bit() {
    // The dense grids solve the rear half of the scan once per line of
    // steers; every answer must be the one a condition solved alone gives,
    // also where the speed or friction changes along the sequence.
    let m = equilibria_model(true);
    let mut rear = None;
    for (speed, friction) in [(70.0, 0.8), (70.0, 0.8), (90.0, 0.8), (90.0, 0.5)] {
        for i in 0..12 {
            let c = cond(0.02 * i as f64, friction, speed);
            let alone = exact::solve_with_continua(&m, &c);
            let along = exact::solve_with_continua_along(&m, &c, &mut rear);
            assert_eq!(format!("{alone:?}"), format!("{along:?}"), "{c:?}");
        }
    }
}

#[test]
fn every_kind_is_drawn_as_one_stability_class() {
    use crate::report::stability::Class;
    assert_eq!(Kind::StableNode.class(), Class::Stable);
    assert_eq!(Kind::StableFocus.class(), Class::Stable);
    assert_eq!(Kind::Saddle.class(), Class::Saddle);
    assert_eq!(Kind::UnstableNode.class(), Class::Unstable);
    assert_eq!(Kind::UnstableFocus.class(), Class::Unstable);
    assert_eq!(Kind::Degenerate.class(), Class::Unstable);
}

#[test]
fn the_exact_stability_jacobian_equals_central_differences() {
    use crate::tyre::{Gim, MagicSimple, Pac89, Tyre};
    use crate::vehicle::{Vehicle, VehicleModel};
    let gim = Gim {
        load_exponent: 0.8,
        ..Gim::new(60_000.0, 0.15, 1.0)
    };
    let tyres = [
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
        Tyre::Gim(gim),
        Tyre::Pac89(Pac89::adams_example()),
    ];
    for tyre in tyres {
        for roll in [false, true] {
            let mut m = VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre.clone());
            if roll {
                m.options.effects.roll_steer = [0.1, -0.05];
                m.options.effects.relaxation_length = 0.4;
            }
            for (steer, x) in [(0.02, [-0.01, 0.2]), (0.06, [-0.05, 0.45])] {
                let c = Condition {
                    steer,
                    friction: 0.9,
                    speed: 20.0,
                };
                let exact = stability::exact_jacobian(&m, &c, x).expect("generic tyres");
                let diff = stability::difference_jacobian(&m, &c, x);
                let scale = exact.iter().flatten().fold(0.0_f64, |a, v| a.max(v.abs()));
                for i in 0..2 {
                    for k in 0..2 {
                        let e = (exact[i][k] - diff[i][k]).abs() / scale;
                        assert!(e < 1e-6, "{tyre:?} roll {roll} δ {steer}: [{i}][{k}] {e:e}");
                    }
                }
            }
        }
    }
}

#[test]
fn the_lagged_jacobian_equals_central_differences_of_the_full_state() {
    use crate::equilibria::lagged;
    use crate::tyre::Pac89;
    for (tyre, lt) in [
        (Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)), false),
        (Tyre::Pac89(Pac89::adams_example()), true),
    ] {
        let mut m = equilibria_model(lt);
        (m.front, m.rear) = (tyre.clone(), tyre.clone());
        m.options.effects.relaxation_length = 3.0;
        for (steer, x) in [(0.02, [-0.01, 0.2]), (0.1, [-0.2, 0.45])] {
            let c = cond(steer, 0.8, 54.0);
            let exact = lagged::exact_jacobian(&m, &c, x).expect("generic tyres");
            let diff = lagged::difference_jacobian(&m, &c, x);
            let scale = exact.iter().flatten().fold(0.0_f64, |a, v| a.max(v.abs()));
            for i in 0..4 {
                for k in 0..4 {
                    let e = (exact[i][k] - diff[i][k]).abs() / scale;
                    assert!(e < 1e-6, "{tyre:?} δ {steer}: [{i}][{k}] {e:e}");
                }
            }
        }
    }
}

#[test]
fn a_tyre_lag_turns_a_stable_focus_unstable_as_the_full_model_integrated_shows() {
    // Steer 0.1 rad, μ 0.8, 20 m/s: the high-yaw equilibrium is a stable
    // focus of (β, r); with σ = 3 m the lag's rate u/σ = 6.7 1/s is slow
    // enough to turn it into an unstable focus. Integrating the full
    // 6-state model from a small disturbance (RK4, 1 ms) shows the growth
    // at the leading eigenvalue's real part, independent of the Jacobian.
    use crate::vehicle::{Inputs, LoadTransferSeed, State};
    let c = Condition {
        steer: 0.1,
        friction: 0.8,
        speed: 20.0,
    };
    let mut m = equilibria_model(false);
    let x = exact::solve(&m, &c)
        .into_iter()
        .map(|e| [e.beta, e.yaw_rate])
        .find(|x| x[1] > 0.35)
        .expect("the high-yaw equilibrium");
    assert_eq!(
        crate::equilibria::lagged::classify(&m, &c, x).kind,
        Kind::StableFocus
    );
    m.options.effects.relaxation_length = 3.0;
    let s = crate::equilibria::lagged::classify(&m, &c, x);
    assert_eq!(s.kind, Kind::UnstableFocus);
    let growth = s.eigenvalues[0].0;
    assert!(growth > 0.02 && growth < 0.04, "{growth}");
    let inp = Inputs::steady(c.steer, c.speed, c.friction);
    let state = State {
        beta: x[0],
        yaw_rate: x[1],
    };
    let mut q = m.quasi_static_state(&state, &inp);
    q[0] += 1e-5;
    let f = |q: &[f64; 6]| m.rates(q, &inp, &mut LoadTransferSeed::default(), 1e-12).0;
    let h = 1e-3;
    // Envelope of |β − β*| over [t, t + 20 s] (the period is ~10 s).
    let mut peaks = Vec::new();
    let mut peak = 0.0_f64;
    for n in 1..=120_000 {
        let k1 = f(&q);
        let k2 = f(&std::array::from_fn(|i| q[i] + 0.5 * h * k1[i]));
        let k3 = f(&std::array::from_fn(|i| q[i] + 0.5 * h * k2[i]));
        let k4 = f(&std::array::from_fn(|i| q[i] + h * k3[i]));
        q = std::array::from_fn(|i| q[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        peak = peak.max((q[0] - x[0]).abs());
        if n % 20_000 == 0 {
            peaks.push(peak);
            peak = 0.0;
        }
    }
    // From 40–60 s to 100–120 s: 60 s at the leading rate.
    let measured = (peaks[5] / peaks[2]).ln() / 60.0;
    assert_relative_eq!(measured, growth, max_relative = 0.1);
}
