use super::*;
use crate::manoeuvre::{Manoeuvre, StepSteer};
use crate::sim::{Integrator, Method};
use crate::tyre::{Gim, Pac89, Tyre};
use approx::assert_relative_eq;
use nalgebra::{Matrix2, Vector2};

fn sedan() -> Vehicle {
    Vehicle::compact_sedan()
}

fn linear_model() -> VehicleModel {
    super::linear_bicycle()
}

/// Classical RK4 at 1 ms: the fixed grid these tests' tolerances and
/// evaluation counts are set for (the default integrator is Dormand–Prince).
fn rk4_1ms() -> Integrator {
    Integrator {
        step: 1e-3,
        friction: 1.0,
        method: Method::Rk4,
    }
}

fn step(speed: f64, amplitude: f64) -> Manoeuvre {
    Manoeuvre::StepSteer(StepSteer {
        speed,
        amplitude,
        trim: 0.0,
        start: 0.5,
        rise_time: 0.0,
        end: 8.0,
    })
}

#[test]
fn linear_steady_yaw_gain_matches_the_bicycle_model() {
    let m = linear_model();
    let (cf, cr) = (110_000.0, 120_000.0);
    let v = sedan();
    let l = v.a + v.b;
    let k = v.mass / l * (v.b / cf - v.a / cr);
    assert_relative_eq!(m.understeer_gradient(), k, max_relative = 1e-6);
    for u in [10.0, 22.2, 35.0] {
        let gain = u / (l + k * u * u);
        let h = rk4_1ms().run(&m, &step(u, 0.01), State::default());
        let r_end = *h.yaw_rate.last().unwrap();
        assert_relative_eq!(r_end / 0.01, gain, max_relative = 1e-6);
        let ss = m
            .steady_state_for_lateral_acceleration(u, 1.0, 2.0)
            .unwrap();
        assert_relative_eq!(ss.yaw_rate / ss.steer, gain, max_relative = 1e-9);
    }
    // 100 g needs a steer past any wheel's lock: refused, naming both.
    let e = m
        .steady_state_for_lateral_acceleration(20.0, 1.0, 1000.0)
        .unwrap_err();
    assert_eq!((e.speed, e.ay), (20.0, 1000.0));
    // The limit said is the largest ay held (the linear tyres' 45° cap).
    let (limit, ay) = (e.limit.unwrap(), |a| {
        m.steady_state_for_lateral_acceleration(20.0, 1.0, a)
    });
    assert!(ay(0.999 * limit).is_ok() && ay(1.001 * limit).is_err());
    assert_eq!(
        e.to_string(),
        format!(
            "no steady state at 20 m/s with ay = 1000 m/s²: beyond the vehicle's lateral limit at this speed, {} m/s² with these tyres and this road (the largest steady ay, within 45° of steer and sideslip)",
            crate::format::readable(limit, 3)
        )
    );
}

/// The linear model's step response in closed form, x(t) = A⁻¹(e^{At} − I)·B·δ,
/// against the RK4 record.
#[test]
fn linear_transient_matches_the_matrix_exponential() {
    let m = linear_model();
    let v = sedan();
    let (cf, cr) = (110_000.0, 120_000.0);
    let u = 25.0;
    let a = Matrix2::new(
        -(cf + cr) / (v.mass * u),
        (v.b * cr - v.a * cf) / (v.mass * u * u) - 1.0,
        (v.b * cr - v.a * cf) / v.yaw_inertia,
        -(v.a * v.a * cf + v.b * v.b * cr) / (v.yaw_inertia * u),
    );
    let b = Vector2::new(cf / (v.mass * u), v.a * cf / v.yaw_inertia);
    let delta = 0.01;
    // Steered from t = 0 on (start before the record), so no discontinuity
    // falls inside an integration step and RK4's O(h⁴) accuracy shows.
    let man = Manoeuvre::StepSteer(StepSteer {
        start: -1.0,
        ..match step(u, delta) {
            Manoeuvre::StepSteer(s) => s,
            _ => unreachable!(),
        }
    });
    let h = rk4_1ms().run(&m, &man, State::default());
    let inv = a.try_inverse().unwrap();
    for (i, &t) in h.t.iter().enumerate().step_by(97) {
        let x = inv * ((a * t).exp() - Matrix2::identity()) * b * delta;
        assert_relative_eq!(h.beta[i], x[0], epsilon = 1e-11);
        assert_relative_eq!(h.yaw_rate[i], x[1], epsilon = 1e-11);
    }
}

#[test]
fn rk4_is_fourth_order() {
    let mut m = VehicleModel::new(
        sedan(),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Pac89(Pac89::adams_example()),
    );
    m.options.load_transfer = true;
    let man = Manoeuvre::StepSteer(StepSteer {
        speed: 22.0,
        amplitude: 0.03,
        trim: 0.0,
        start: -1.0, // steered from t = 0: a smooth forcing
        rise_time: 0.0,
        end: 1.0,
    });
    let run = |h: f64| {
        let hist = Integrator {
            step: h,
            ..rk4_1ms()
        }
        .run(&m, &man, State::default());
        *hist.yaw_rate.last().unwrap()
    };
    let (r1, r2, r3) = (run(0.02), run(0.01), run(0.005));
    let ratio = (r1 - r2) / (r2 - r3);
    assert!((12.0..20.0).contains(&ratio), "error ratio {ratio}");
}

fn nonlinear_model() -> VehicleModel {
    VehicleModel::new(
        sedan(),
        Tyre::Gim(Gim::new(55_000.0, 0.18, 1.0)),
        Tyre::Pac89(Pac89 {
            a: {
                let mut a = crate::tyre::pac89::ADAMS_EXAMPLE_A;
                // No offsets so the model is symmetric.
                a[8..].iter_mut().for_each(|x| *x = 0.0);
                a
            },
            ..Pac89::adams_example()
        }),
    )
}

#[test]
fn mirrored_steer_mirrors_every_output() {
    let m = nonlinear_model();
    let man = step(25.0, 0.05);
    let integ = rk4_1ms();
    let p = integ.run(&m, &man, State::default());
    let n = integ.run(&m, &man.mirrored(), State::default());
    for i in 0..p.len() {
        assert_eq!(p.beta[i], -n.beta[i]);
        assert_eq!(p.yaw_rate[i], -n.yaw_rate[i]);
        assert_eq!(p.ay[i], -n.ay[i]);
        assert_eq!(p.fy_front[i], -n.fy_front[i]);
        assert_eq!(p.fz[0][i], n.fz[1][i]);
        assert_eq!(p.fz[2][i], n.fz[3][i]);
    }
}

#[test]
fn load_transfer_loop_is_solved_not_lagged() {
    let m = nonlinear_model();
    let x = State {
        beta: -0.02,
        yaw_rate: 0.35,
    };
    let inp = Inputs::steady(0.06, 22.0, 1.0);
    let o = m.evaluate(&x, &inp);
    assert!(
        o.load_iterations > 1 && o.load_iterations < 15,
        "{}",
        o.load_iterations
    );
    // The loads of the answer give back exactly the answer's ay.
    let fz = m.wheel_loads(o.ay);
    for (a, b) in fz.iter().zip(o.fz) {
        assert_relative_eq!(*a, b, max_relative = 1e-9);
    }
    let wheel = |tyre, alpha, i: usize| VehicleModel::wheel_force(tyre, alpha, fz[i], &inp);
    let f = wheel(&m.front, o.alpha_front, 0) + wheel(&m.front, o.alpha_front, 1);
    let r = wheel(&m.rear, o.alpha_rear, 2) + wheel(&m.rear, o.alpha_rear, 3);
    assert_relative_eq!(
        (f * inp.steer.cos() + r) / m.vehicle.mass,
        o.ay,
        max_relative = 1e-12
    );
    // Load transfer conserves the total load and balances the roll moment.
    let (sf, sr) = m.vehicle.static_axle_loads();
    assert_relative_eq!(fz.iter().sum::<f64>(), sf + sr, max_relative = 1e-12);
    let v = &m.vehicle;
    let moment = (fz[1] - fz[0]) / 2.0 * v.track_front + (fz[3] - fz[2]) / 2.0 * v.track_rear;
    assert_relative_eq!(moment, v.mass * o.ay * v.cg_height, max_relative = 1e-12);
    // Positive ay (left turn) loads the right (outer) wheels.
    assert!(o.ay > 0.0 && fz[1] > fz[0] && fz[3] > fz[2]);
}

#[test]
fn load_transfer_lowers_the_axle_force_of_a_saturating_tyre() {
    let mut m = nonlinear_model();
    let x = State {
        beta: 0.0,
        yaw_rate: 0.3,
    };
    let inp = Inputs::steady(0.08, 20.0, 1.0);
    let with = m.evaluate(&x, &inp).fy_front;
    m.options.load_transfer = false;
    let without = m.evaluate(&x, &inp).fy_front;
    assert!(with < without, "{with} vs {without}");
}

#[test]
fn vehicle_validation_names_the_key() {
    let mut v = sedan();
    v.mass = -3.0;
    assert_eq!(v.validate().unwrap_err().key, "mass");
    let mut v = sedan();
    v.wheelbase = Some(2.9);
    let e = v.validate().unwrap_err();
    assert_eq!(e.key, "wheelbase");
    let crate::error::ParamReason::WheelbaseMismatch(w) = e.reason else {
        panic!("{e}");
    };
    assert_eq!((w.a, w.b), (v.a, v.b));
    let mut v = sedan();
    v.wheelbase = Some(2.7805);
    assert!(v.validate().is_ok());
}

#[test]
fn seeded_load_transfer_solves_cost_little_and_agree_with_fresh_ones() {
    let model = VehicleModel::new(
        sedan(),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Pac89(Pac89::adams_example()),
    );
    let h = rk4_1ms().run(&model, &step(22.2222, 0.012), State::default());
    let stages = 4.0 * (h.len() - 1) as f64;
    let per_stage = h.load_evaluations as f64 / stages;
    eprintln!("{per_stage}");
    assert!(
        per_stage < 1.5,
        "{per_stage} tyre-set evaluations per stage"
    );
    for i in (0..h.len()).step_by(250) {
        let x = State {
            beta: h.beta[i],
            yaw_rate: h.yaw_rate[i],
        };
        let inp = Inputs::steady(h.steer[i], h.speed[i], 1.0);
        assert_relative_eq!(model.evaluate(&x, &inp).ay, h.ay[i], epsilon = 1e-9);
    }
}

#[test]
fn effects_are_off_by_default_and_change_nothing_then() {
    assert_eq!(ModelOptions::default().effects, Effects::default());
    let opts: ModelOptions = toml::from_str("kinematics = \"exact\"\n").unwrap();
    assert_eq!(opts.effects, Effects::default());
    // A zero bank and zero aero load are exactly the base model.
    let base = nonlinear_model();
    let mut zero = base.clone();
    zero.options.effects = Effects {
        aero_load: [0.0, 0.0],
        road_bank: 0.0,
        ..Effects::default()
    };
    let x = State {
        beta: -0.01,
        yaw_rate: 0.3,
    };
    let inp = Inputs {
        steer: 0.05,
        speed: 25.0,
        speed_rate: 0.3,
        friction: 0.9,
        ax: 0.3,
        bank: 0.0,
    };
    assert_eq!(base.evaluate(&x, &inp), zero.evaluate(&x, &inp));
}

#[test]
fn a_banked_road_pulls_the_car_down_the_slope() {
    let mut m = linear_model();
    let bank = 0.05;
    m.options.effects.road_bank = bank;
    // Straight, no steer, no sideslip: the tyres carry nothing, the
    // accelerometer reads 0 and the path curves down the slope at g·sin θ.
    let o = m.evaluate(&State::default(), &Inputs::steady(0.0, 20.0, 1.0));
    assert_eq!(o.ay, 0.0);
    assert_relative_eq!(o.beta_rate, -G * bank.sin() / 20.0, max_relative = 1e-12);
    // Holding a straight line on the bank: the accelerometer reads g·sin θ
    // at zero yaw rate.
    let ss = m
        .steady_state_for_lateral_acceleration(20.0, 1.0, G * bank.sin())
        .unwrap();
    assert_relative_eq!(ss.yaw_rate, 0.0, epsilon = 1e-12);
    assert!(ss.steer > 0.0, "steering up the slope: {}", ss.steer);
}

#[test]
fn aero_load_adds_speed_squared_axle_loads() {
    let mut m = nonlinear_model();
    m.options.effects.aero_load = [0.4, 0.6];
    let (sf, sr) = m.vehicle.static_axle_loads();
    let fz = m.wheel_loads_at(0.0, 30.0);
    assert_relative_eq!(fz[0], 0.5 * sf + 0.5 * 0.4 * 900.0, max_relative = 1e-12);
    assert_relative_eq!(fz[3], 0.5 * sr + 0.5 * 0.6 * 900.0, max_relative = 1e-12);
    assert_eq!(m.wheel_loads_at(0.0, 0.0), m.wheel_loads(0.0));
}

#[test]
fn the_exact_equilibrium_solver_follows_bank_and_aero() {
    use crate::equilibria::{exact, Condition};
    let mut m = nonlinear_model();
    m.options.effects = Effects {
        aero_load: [0.3, 0.5],
        road_bank: 0.04,
        ..Effects::default()
    };
    let c = Condition {
        steer: 0.03,
        friction: 0.9,
        speed: 25.0,
    };
    let eqs = exact::solve(&m, &c);
    assert!(!eqs.is_empty());
    for e in eqs {
        assert!(e.residual < 1e-10, "{e:?}");
    }
}

#[test]
fn wheel_loads_conserve_weight_through_lift_off() {
    let mut m = nonlinear_model();
    // A tall, narrow vehicle lifts its inner front wheel well before roll-over.
    m.vehicle.cg_height = 0.9;
    m.vehicle.track_front = 1.3;
    m.vehicle.track_rear = 1.4;
    let (sf, sr) = m.vehicle.static_axle_loads();
    let (v, chi) = (&m.vehicle, m.vehicle.front_transfer_share());
    // Inner front wheel off at ay = (sf/2)·t_f/(χ·m·h).
    let lift_front = 0.5 * sf * v.track_front / (chi * v.mass * v.cg_height);
    let roll_over = G * (v.track_front * sf + v.track_rear * sr) / (2.0 * G * v.mass * v.cg_height);
    let mut lifted = 0;
    for i in -200..=200 {
        let ay = 0.08 * i as f64;
        let fz = m.wheel_loads(ay);
        assert!(fz.iter().all(|f| *f >= 0.0), "ay {ay}: {fz:?}");
        let total: f64 = fz.iter().sum();
        assert_relative_eq!(total, sf + sr, max_relative = 1e-12);
        if ay.abs() < roll_over {
            // Below roll-over the transferred moment is the whole m·h·ay.
            let moment =
                0.5 * (fz[1] - fz[0]) * v.track_front + 0.5 * (fz[3] - fz[2]) * v.track_rear;
            assert_relative_eq!(
                moment,
                v.mass * v.cg_height * ay,
                max_relative = 1e-9,
                epsilon = 1e-6
            );
        }
        if ay.abs() > lift_front {
            lifted += 1;
            let inner = if ay > 0.0 { fz[0] } else { fz[1] };
            assert_eq!(inner, 0.0, "ay {ay}");
        }
    }
    assert!(
        lifted > 0 && lift_front < roll_over,
        "the sweep must cross lift-off"
    );
}

#[test]
fn a_simulated_lift_off_is_reported_with_its_wheel_and_time() {
    let mut m = nonlinear_model();
    m.vehicle.cg_height = 1.2;
    m.vehicle.track_front = 0.9;
    let h = rk4_1ms().run(&m, &step(20.0, 0.1), State::default());
    let lifts = h.lift_offs();
    let ay_max = h.ay.iter().fold(0.0f64, |a, b| a.max(*b));
    assert!(
        !lifts.is_empty(),
        "a 0.1 rad step at 20 m/s (ay up to {ay_max}) lifts the inner front wheel"
    );
    for l in &lifts {
        // Steering left loads the right wheels: the left ones lift.
        assert!(
            matches!(
                l.wheel,
                crate::sim::Wheel::FrontLeft | crate::sim::Wheel::RearLeft
            ),
            "{l:?}"
        );
        assert!(l.start > 0.5 && l.end >= l.start);
    }
    for i in 0..h.len() {
        let total: f64 = (0..4).map(|w| h.fz[w][i]).sum();
        assert_relative_eq!(
            total,
            h.fz[0][0] + h.fz[1][0] + h.fz[2][0] + h.fz[3][0],
            max_relative = 1e-12
        );
    }
}

#[test]
fn with_every_effect_off_the_extra_states_do_not_feed_back_bit_for_bit() {
    // The one right-hand side: with the effects off, whatever the lag and
    // roll states hold, β̇, ṙ and every output are those of (β, r) alone,
    // to the bit — and those match the 2-DOF equations written out here.
    for kinematics in [Kinematics::Exact, Kinematics::SmallAngle] {
        let mut m = nonlinear_model();
        m.options.kinematics = kinematics;
        let inp = Inputs {
            steer: 0.05,
            speed: 21.0,
            speed_rate: 0.3,
            friction: 0.9,
            ax: 0.3,
            bank: 0.0,
        };
        let x = State {
            beta: -0.02,
            yaw_rate: 0.35,
        };
        let plain = m.evaluate(&x, &inp);
        let (dx, o) = m.rates(
            &[x.beta, x.yaw_rate, 0.3, -0.2, 0.07, -0.4],
            &inp,
            &mut LoadTransferSeed::default(),
            LOAD_TOLERANCE,
        );
        assert_eq!(o, plain);
        assert_eq!([dx[0], dx[1]], [plain.beta_rate, plain.yaw_acceleration]);
        // The equations, from the outputs' own forces.
        let v = &m.vehicle;
        let cos = if kinematics == Kinematics::Exact {
            inp.steer.cos()
        } else {
            1.0
        };
        let ay = (o.fy_front * cos + o.fy_rear) / v.mass;
        assert_relative_eq!(o.ay, ay, max_relative = 1e-14);
        let yaw = (v.a * o.fy_front * cos - v.b * o.fy_rear) / v.yaw_inertia;
        assert_relative_eq!(o.yaw_acceleration, yaw, max_relative = 1e-13);
        let (af, ar) = m.slip_angles(&x, &inp);
        assert_eq!((o.alpha_front, o.alpha_rear), (af, ar));
    }
}

#[test]
fn a_scenario_with_lag_and_roll_steer_integrates_the_extra_states() {
    // Roll steer (ε_f, ε_r) changes the understeer gradient by
    // −(ε_f − ε_r)·k (k the roll gradient); a relaxation length only delays
    // the response. Both methods integrate six states and record the roll.
    use crate::sim::Tolerances;
    let mut m = linear_model();
    m.options.effects.roll_steer = [-0.1, 0.05];
    m.options.effects.relaxation_length = 0.4;
    let k = m.options.effects.roll.gradient;
    let (u, steer) = (20.0, 0.01);
    let l = m.vehicle.wheelbase();
    let gradient = m.understeer_gradient() - (-0.1 - 0.05) * k;
    let expected = steer * u / (l + gradient * u * u);
    for method in [Method::Rk4, Method::Dopri5(Tolerances::default())] {
        let integrator = Integrator {
            method,
            ..Integrator::default()
        };
        let sim = integrator.simulate(&m, &step(u, steer), State::default());
        let h = &sim.history;
        let r = *h.yaw_rate.last().unwrap();
        assert_relative_eq!(r, expected, max_relative = 1e-6);
        assert_eq!(h.roll.len(), h.t.len());
        assert_relative_eq!(
            *h.roll.last().unwrap(),
            k * h.ay.last().unwrap(),
            max_relative = 1e-6
        );
        assert!(sim.dense.is_none());
        // Lagged: the tyres' slip angle trails its kinematic value early on.
        let i = h.t.iter().position(|&t| t > 0.505).unwrap();
        let (af, _) = m.slip_angles(
            &State {
                beta: h.beta[i],
                yaw_rate: h.yaw_rate[i],
            },
            &Inputs::steady(
                h.steer[i] + m.options.effects.roll_steer[0] * h.roll[i],
                u,
                1.0,
            ),
        );
        assert!(h.alpha_front[i] < 0.8 * af, "{} {af}", h.alpha_front[i]);
    }
}

/// The steer cosine a run keeps between right-hand sides (`SteerCosine`)
/// changes no bit: over steers repeated, changed, signed zeros and a NaN,
/// the PAC89 sedan's derivatives and outputs with one cache kept across
/// the calls are those of a fresh cache each call (`rates`), and the
/// cached cosine is the C library's of the same steer.
#[test]
fn the_kept_steer_cosine_is_the_steers_own_to_the_bit() {
    let m = crate::sim::peer::PeerStepSteer::new().model;
    let sc = m.scalars(1.0);
    let mut kept = SteerCosine::default();
    let x = [0.004, 0.12, 0.0, 0.0, 0.0, 0.0];
    let steers = [
        0.0,
        0.0,
        0.012,
        0.012,
        -0.0,
        0.011,
        0.012,
        f64::NAN,
        0.3,
        0.3,
    ];
    for steer in steers {
        assert_eq!(kept.of(steer).to_bits(), steer.cos().to_bits(), "{steer}");
        let inp = Inputs::steady(steer, 22.2, 1.0);
        let (mut a, mut b) = (LoadTransferSeed::default(), LoadTransferSeed::default());
        let fresh = m.rates(&x, &inp, &mut a, LOAD_TOLERANCE);
        let cached = m.rates_in(&sc, &x, &inp, (&mut b, &mut kept), LOAD_TOLERANCE);
        let bits = |(dx, o): &(StateVector, Outputs)| {
            let mut v: Vec<u64> = dx.iter().map(|d| d.to_bits()).collect();
            v.extend([o.ay, o.fy_front, o.fy_rear, o.alpha_front].map(f64::to_bits));
            v
        };
        assert_eq!(bits(&fresh), bits(&cached), "{steer}");
    }
}

mod dop853;
mod dopri5;
mod equilibrium;
mod longitudinal;
