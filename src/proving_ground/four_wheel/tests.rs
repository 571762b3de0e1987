use super::*;
use crate::manoeuvre::{RampSteer, StepSteer, SweepSteer};

fn hold(speed: f64, steer: f64) -> Manoeuvre {
    Manoeuvre::StepSteer(StepSteer {
        speed,
        amplitude: steer,
        trim: 0.0,
        start: 0.5,
        rise_time: 0.15,
        end: 12.0,
    })
}

/// The last sample of a constant-steer run: (steer, r, ay, φ).
fn steady(truth: &FourWheel, speed: f64, steer: f64) -> (f64, f64, f64, f64) {
    let h = truth.simulate(&hold(speed, steer), 1e-3);
    let k = h.t.len() - 1;
    // Settled: the last second changes the yaw rate by < 1e-6 of itself.
    let r_before = h.yaw_rate[k - 1000];
    assert!((h.yaw_rate[k] - r_before).abs() < 1e-6 * h.yaw_rate[k].abs());
    (h.steer[k], h.yaw_rate[k], h.ay[k], h.roll[k])
}

#[test]
fn small_steer_understeer_gradient_is_the_linear_bicycle_closed_form() {
    // δ = L·r/u + K·a_y with K = m/L·(b/C_f − a/C_r), C per axle = 2·C_α at
    // the static wheel load. Tolerance 2 % of K: the tyre's cubic term and
    // the load transfer's second-order change of C_α at a_y ≈ 0.1 m/s².
    let v = FourWheelVehicle::sedan();
    let truth = FourWheel::new(v);
    let [wf, wr] = v.static_axle_loads();
    let cf = 2.0 * v.tyre.cornering_stiffness(0.5 * wf);
    let cr = 2.0 * v.tyre.cornering_stiffness(0.5 * wr);
    let l = v.wheelbase();
    let k_closed = v.mass / l * (v.b / cf - v.a / cr);
    assert!(k_closed > 5e-4, "the sedan understeers: {k_closed}");
    let u = 25.0;
    let steer = 0.0006;
    let (d, r, ay, _) = steady(&truth, u, steer);
    assert!(ay > 0.05 && ay < 0.2, "small lateral acceleration: {ay}");
    let k_sim = (d - l * r / u) / ay;
    assert!(
        (k_sim - k_closed).abs() < 0.02 * k_closed,
        "K simulated {k_sim:.4e}, closed form {k_closed:.4e} rad/(m/s²)"
    );
    // A stiffer rear makes the closed form and the truth move together.
    let mut stiff = truth;
    stiff.effects.stiffness_scale = [1.0, 1.3];
    let k_stiff = v.mass / l * (v.b / cf - v.a / (1.3 * cr));
    let (d, r, ay, _) = steady(&stiff, u, steer);
    let k_sim = (d - l * r / u) / ay;
    assert!(
        (k_sim - k_stiff).abs() < 0.02 * k_stiff,
        "{k_sim:.4e} vs {k_stiff:.4e}"
    );
}

#[test]
fn steady_roll_is_the_roll_moment_over_the_total_roll_stiffness() {
    let v = FourWheelVehicle::sedan();
    let truth = FourWheel::new(v);
    let (_, _, ay, phi) = steady(&truth, 22.0, 0.03);
    assert!(ay > 3.0, "a real cornering level: {ay}");
    let closed = v.mass * ay * v.roll_arm() / (v.roll_stiffness[0] + v.roll_stiffness[1]);
    assert!((phi - closed).abs() < 1e-5 * closed, "φ {phi} vs {closed}");
    // 6°/g as the vehicle is specified.
    let per_g = phi / ay * GRAVITY;
    assert!(
        (per_g - 6f64.to_radians()).abs() < 1e-9,
        "{}",
        per_g.to_degrees()
    );
}

#[test]
fn loads_sum_to_the_weight_at_every_instant_even_with_a_wheel_lifted() {
    let mut v = FourWheelVehicle::sedan();
    v.cg_height = 1.1;
    v.tyre.friction = 1.3;
    let truth = FourWheel::new(v);
    let h = truth.simulate(
        &Manoeuvre::RampSteer(RampSteer {
            speed: 20.0,
            rate: 0.03,
            start: 0.5,
            end: 6.0,
        }),
        1e-3,
    );
    let w = v.mass * GRAVITY;
    for (t, l) in h.t.iter().zip(&h.loads) {
        let sum: f64 = l.iter().sum();
        assert!((sum - w).abs() < 1e-9 * w, "t {t}: {sum} vs {w}");
        assert!(l.iter().all(|f| *f >= 0.0));
    }
    let lifted = h.loads.iter().position(|l| l[0] == 0.0);
    assert!(lifted.is_some(), "the inner front wheel lifts in this test");
    // Axle loads stay static (no pitch), also after the lift.
    let [wf, _] = v.static_axle_loads();
    let l = h.loads[h.loads.len() - 1];
    assert!((l[0] + l[1] - wf).abs() < 1e-9 * wf);
}

#[test]
fn mirrored_steer_mirrors_the_response_with_every_effect_on() {
    let mut truth = FourWheel::new(FourWheelVehicle::sedan());
    truth.effects = FourWheelEffects {
        relaxation_length: 0.7,
        roll_steer: [-0.12, 0.05],
        roll_camber: [0.8, 0.6],
        steering_compliance: 3e-6,
        aero_load: [1.5, 2.0],
        ..FourWheelEffects::default()
    };
    let sweep = |amplitude: f64| {
        Manoeuvre::Sweep(SweepSteer {
            speed: 25.0,
            amplitude,
            f_start: 0.2,
            f_end: 2.0,
            start: 0.5,
            end: 8.0,
        })
    };
    let left = truth.simulate(&sweep(0.04), 1e-3);
    let right = truth.simulate(&sweep(-0.04), 1e-3);
    let peak = left.ay.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    assert!(peak > 3.0, "a non-linear level: {peak}");
    let close = |a: f64, b: f64, scale: f64| (a + b).abs() <= 1e-9 * scale;
    for i in 0..left.t.len() {
        assert!(close(left.beta[i], right.beta[i], 0.1));
        assert!(close(left.yaw_rate[i], right.yaw_rate[i], 1.0));
        assert!(close(left.ay[i], right.ay[i], 10.0));
        assert!(close(left.roll[i], right.roll[i], 0.1));
        let (l, r) = (left.loads[i], right.loads[i]);
        for (a, b) in [(0, 1), (1, 0), (2, 3), (3, 2)] {
            assert!((l[a] - r[b]).abs() < 1e-6, "t {} wheel {a}", left.t[i]);
        }
    }
}

#[test]
fn relaxation_length_delays_the_yaw_response_more_at_low_speed() {
    // The tyre lag's time constant is σ/u: it delays the rise of the yaw
    // rate to half its steady value by a fraction of σ/u (the lag runs in
    // series with the yaw mode, which it partly overlaps), more in time at
    // low speed than at high speed.
    let v = FourWheelVehicle::sedan();
    let base = FourWheel::new(v);
    let mut lag = base;
    lag.effects.relaxation_length = 0.8;
    let half_time = |truth: &FourWheel, u: f64| {
        let h = truth.simulate(&hold(u, 0.01), 1e-3);
        let last = h.yaw_rate[h.yaw_rate.len() - 1];
        let k = h.yaw_rate.iter().position(|r| *r > 0.5 * last).unwrap();
        h.t[k]
    };
    let extra = [10.0, 30.0].map(|u| {
        let extra = half_time(&lag, u) - half_time(&base, u);
        let tau = 0.8 / u;
        assert!(
            extra > 0.2 * tau && extra < 1.5 * tau,
            "u {u}: {extra} vs σ/u {tau}"
        );
        extra
    });
    assert!(extra[0] > 1.5 * extra[1], "{extra:?}");
}

#[test]
fn sensors_delay_offset_and_roll_with_the_body() {
    let mut truth = FourWheel::new(FourWheelVehicle::sedan());
    let h = truth.simulate(&hold(22.0, 0.03), 1e-3);
    let times = [5.0, 11.0];
    truth.effects.sensor_delay = 0.05;
    truth.effects.sensor_bias = [0.01, 0.2, 0.003];
    truth.effects.accelerometer_rolls = true;
    let o = truth.observe(&h, &times);
    let at = |ys: &[f64], t: f64| interpolate(&h.t, ys, t);
    for (j, t) in times.iter().enumerate() {
        assert!((o.yaw_rate[j] - at(&h.yaw_rate, t - 0.05) - 0.01).abs() < 1e-12);
        assert!((o.beta[j] - at(&h.beta, t - 0.05) - 0.003).abs() < 1e-12);
        let phi = at(&h.roll, t - 0.05);
        let ay = at(&h.ay, t - 0.05);
        let read = ay * phi.cos() + GRAVITY * phi.sin() + 0.2;
        assert!((o.ay[j] - read).abs() < 1e-12);
        assert!(GRAVITY * phi.sin() > 0.3, "the roll reads as a_y");
    }
}
