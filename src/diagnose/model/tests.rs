use super::*;
use crate::manoeuvre::Manoeuvre;
use crate::manoeuvre::{SineSteer, StepSteer};
use crate::sim::Integrator;
use crate::tyre::Pac89;
use crate::tyre::Tyre;
use crate::vehicle::{State, Vehicle};

fn pac89_model() -> VehicleModel {
    let t = Tyre::Pac89(Pac89::adams_example());
    VehicleModel::new(Vehicle::compact_sedan(), t.clone(), t)
}

/// Linear tyres, small-angle kinematics, no load transfer: the textbook
/// bicycle model, whose steady gains are closed-form.
fn linear_model() -> VehicleModel {
    crate::vehicle::linear_bicycle()
}

fn step(speed: f64, amplitude: f64, end: f64) -> Manoeuvre {
    Manoeuvre::StepSteer(StepSteer {
        speed,
        amplitude,
        trim: 0.0,
        start: 0.5,
        rise_time: 0.1,
        end,
    })
}

fn steady_yaw_rate(model: &Augmented, speed: f64, steer: f64) -> f64 {
    let drive = Drive::new(&step(speed, steer, 15.0), 0.002);
    let r = model.simulate(&drive, [0.0; 6]);
    *r.yaw_rate.last().unwrap()
}

#[test]
fn with_every_effect_off_it_is_the_base_model() {
    let base = pac89_model();
    let m = step(25.0, 0.04, 4.0);
    let reference = Integrator {
        step: 1e-3,
        friction: 0.9,
        method: crate::sim::Method::Rk4,
    }
    .run(&base, &m, State::default());
    let a = Augmented::new(base, 0.9);
    let r = a.simulate(&Drive::new(&m, 1e-3), [0.0; 6]);
    assert_eq!(r.t.len(), reference.t.len());
    for i in 0..reference.t.len() {
        assert!((r.yaw_rate[i] - reference.yaw_rate[i]).abs() < 1e-9);
        assert!((r.beta[i] - reference.beta[i]).abs() < 1e-9);
        assert!((r.ay[i] - reference.ay[i]).abs() < 1e-7);
    }
}

#[test]
fn roll_steer_changes_the_understeer_gradient_by_its_closed_form() {
    // δ = l/R + (K − (ε_f − ε_r)·k)·ay in the steady state.
    let base = linear_model();
    let (u, steer) = (20.0, 0.01);
    let l = base.vehicle.wheelbase();
    let k_base = base.understeer_gradient();
    let mut a = Augmented::new(base, 1.0);
    a.effects_mut().roll_steer = [-0.1, 0.05];
    let k = k_base - (-0.1 - 0.05) * a.effects().roll.gradient;
    let expected = steer * u / (l + k * u * u);
    let got = steady_yaw_rate(&a, u, steer);
    assert!((got / expected - 1.0).abs() < 1e-6, "{got} {expected}");
    // Without it, the base gain.
    a.effects_mut().roll_steer = [0.0; 2];
    let base_gain = steer * u / (l + k_base * u * u);
    assert!((steady_yaw_rate(&a, u, steer) / base_gain - 1.0).abs() < 1e-6);
}

#[test]
fn compliance_and_stiffness_scale_act_as_a_softer_front_axle() {
    // Steering compliance c in series with the front axle's stiffness Cf:
    // Cf' = Cf / (1 + c·Cf); a stiffness scale s: Cf' = s·Cf.
    let base = linear_model();
    let (u, steer) = (25.0, 0.01);
    let (cf, cr) = base.axle_cornering_stiffness();
    let v = base.vehicle.clone();
    let gain = |cf: f64| {
        let k = v.mass / v.wheelbase() * (v.b / cf - v.a / cr);
        steer * u / (v.wheelbase() + k * u * u)
    };
    let mut a = Augmented::new(base, 1.0);
    a.effects_mut().steering_compliance = 2e-6;
    let expected = gain(cf / (1.0 + 2e-6 * cf));
    let got = steady_yaw_rate(&a, u, steer);
    assert!((got / expected - 1.0).abs() < 1e-6, "{got} {expected}");
    a.effects_mut().steering_compliance = 0.0;
    a.effects_mut().cornering_stiffness_scale = [0.8, 1.0];
    let got = steady_yaw_rate(&a, u, steer);
    assert!((got / gain(0.8 * cf) - 1.0).abs() < 1e-6);
    // A lag state with compliance reaches the same steady state.
    a.effects_mut().cornering_stiffness_scale = [1.0; 2];
    a.effects_mut().steering_compliance = 2e-6;
    a.effects_mut().relaxation_length = 0.5;
    let got = steady_yaw_rate(&a, u, steer);
    assert!((got / gain(cf / (1.0 + 2e-6 * cf)) - 1.0).abs() < 1e-6);
}

#[test]
fn relaxation_length_is_a_first_order_lag_of_the_slip_angles() {
    // A lag of time constant σ/u slows the response but keeps its steady
    // state; as σ → 0 the response tends to the base model's.
    let base = linear_model();
    let m = step(20.0, 0.02, 6.0);
    let drive = Drive::new(&m, 1e-3);
    let mut a = Augmented::new(base, 1.0);
    let r0 = a.simulate(&drive, [0.0; 6]).yaw_rate;
    let mut gaps = Vec::new();
    for sigma in [0.8, 0.08, 0.008] {
        a.effects_mut().relaxation_length = sigma;
        let r = a.simulate(&drive, [0.0; 6]).yaw_rate;
        let gap = r
            .iter()
            .zip(&r0)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!((r.last().unwrap() / r0.last().unwrap() - 1.0).abs() < 1e-6);
        gaps.push(gap);
    }
    // The largest difference shrinks in proportion to σ.
    assert!(
        gaps[0] > 5.0 * gaps[1] && gaps[1] > 5.0 * gaps[2],
        "{gaps:?}"
    );
    // At 0.5 s + 0.1 s (the end of the steer ramp) a lagging tyre has built
    // less yaw rate.
    a.effects_mut().relaxation_length = 0.8;
    let r = a.simulate(&drive, [0.0; 6]).yaw_rate;
    assert!(r[650] < 0.9 * r0[650]);
}

#[test]
fn steer_reversal_mirrors_the_response_with_effects_on() {
    let mut a = Augmented::new(pac89_model(), 1.0);
    // PAC89's offsets break the mirror; symmetric tyres keep it.
    let t = Tyre::MagicSimple(crate::tyre::MagicSimple::new(10.0, 1.3));
    a.model.front = t.clone();
    a.model.rear = t;
    a.effects_mut().relaxation_length = 0.6;
    a.effects_mut().steering_compliance = 3e-6;
    a.effects_mut().roll_steer = [-0.1, 0.02];
    a.effects_mut().roll_camber = [-1.0, 0.5];
    a.effects_mut().aero_load = [1.0, 1.5];
    a.effects_mut().transfer_share = Some(0.7);
    a.effects_mut().sensors.delay = 0.03;
    a.effects_mut().sensors.accelerometer_x = 0.4;
    a.effects_mut().sensors.roll_gradient = 0.005;
    let sine = |amp: f64| {
        Manoeuvre::Sine(SineSteer {
            speed: 22.0,
            amplitude: amp,
            frequency: 0.7,
            start: 0.2,
            end: 4.0,
        })
    };
    let times: Vec<f64> = (0..380).map(|i| 0.2 + 0.01 * i as f64).collect();
    let obs = |amp: f64| {
        let d = Drive::new(&sine(amp), 2e-3);
        a.observe(&a.simulate(&d, [0.0; 6]), &times)
    };
    let (p, n) = (obs(0.05), obs(-0.05));
    for i in 0..times.len() {
        assert_eq!(p.yaw_rate[i], -n.yaw_rate[i]);
        assert_eq!(p.ay[i], -n.ay[i]);
        assert_eq!(p.beta[i], -n.beta[i]);
        assert_eq!(p.roll[i], -n.roll[i]);
    }
    assert!(p.yaw_rate.iter().any(|r| r.abs() > 0.1));
}

#[test]
fn roll_follows_lateral_acceleration_and_camber_thrust_adds_force() {
    let mut a = Augmented::new(linear_model(), 1.0);
    let drive = Drive::new(&step(20.0, 0.02, 10.0), 1e-3);
    let r = a.simulate(&drive, [0.0; 6]);
    let n = r.roll.len() - 1;
    assert!((r.roll[n] - a.effects().roll.gradient * r.ay[n]).abs() < 1e-9);
    // Rear camber thrust toward the turn adds rear force: less yaw rate.
    a.effects_mut().roll_camber = [0.0, 2.0];
    let r2 = a.simulate(&drive, [0.0; 6]);
    assert!(r2.yaw_rate[n] < 0.99 * r.yaw_rate[n]);
}

#[test]
fn a_runs_measured_bank_and_ax_reach_the_model_only_through_their_effects() {
    let m = step(25.0, 0.04, 4.0);
    let t = [m.start_time(), m.end_time()];
    let plain = Drive::new(&m, 1e-3);
    let measured = Drive::new(&m, 1e-3).with_channels(&t, Some(&[-5.0, -5.0]), Some(&[0.1, 0.1]));
    let run = |a: &Augmented, d: &Drive| a.simulate(d, [0.0; 6]).yaw_rate;
    // Effects off: the channels change nothing, to the bit.
    let base = Augmented::new(pac89_model(), 1.0);
    assert_eq!(run(&base, &plain), run(&base, &measured));
    // The measured bank at scale 1 is the constant bank, to the bit.
    let mut profile = base.clone();
    profile.effects_mut().bank_profile_scale = 1.0;
    let mut constant = base.clone();
    constant.effects_mut().road_bank = 0.1;
    assert_eq!(run(&profile, &measured), run(&constant, &plain));
    assert_ne!(run(&profile, &measured), run(&base, &plain));
    // Braking at 5 m/s² moves load forward: the response changes, and only
    // with the measured ax (the speed is constant, so du/dt is zero).
    let mut pitch = base.clone();
    pitch.effects_mut().longitudinal_load_transfer = 1.0;
    assert_eq!(run(&pitch, &plain), run(&base, &plain));
    let braking = run(&pitch, &measured);
    let level = run(&base, &measured);
    assert!(
        (braking.last().unwrap() - level.last().unwrap()).abs() > 1e-4,
        "{} vs {}",
        braking.last().unwrap(),
        level.last().unwrap()
    );
}

#[test]
fn a_stiff_racing_car_is_replayed_by_a_method_it_is_stable_under() {
    // The Putnam log's fit asks for racing axles this stiff (B·C·D ≈ 360
    // per radian at the rear): at 6 m/s the yaw mode's rate is near
    // 900 1/s, so RK4 at the log's 20 ms is unstable (its chaos once let
    // the fits "explain" the data). The replay then runs by ROS34PW2 at
    // that step and must match a fine RK4 reference.
    use crate::diagnose::model::replay::Prepared;
    use crate::measured::MeasuredRun;
    let (front, rear) = crate::diagnose::base::identify::axle_tyres(
        &crate::diagnose::base::identify::shares(9.3 * 1.3 * 3.5, 80.0 * 1.3 * 3.5, 3.5),
    );
    let model = Augmented::new(
        VehicleModel::new(crate::vehicle::racing_car(), front, rear),
        1.0,
    );
    // 20 s at 25 Hz: a slow corner at 6 m/s, then accelerating to 30 m/s
    // through a weave.
    let t: Vec<f64> = (0..500).map(|i| 0.04 * i as f64).collect();
    let speed: Vec<f64> = t.iter().map(|&t| 6.0 + 24.0 * (t / 20.0).powi(2)).collect();
    let steer: Vec<f64> = t.iter().map(|&t| 0.05 * (0.8 * t).sin()).collect();
    let run = MeasuredRun::new("stiff.csv", t.clone(), speed, steer, vec![0.0; t.len()])
        .with_beta(vec![0.0; t.len()]);
    let prepared = Prepared::new(&run, 0.02, 25.0);
    let drive = prepared.drive_for(&model);
    assert_eq!((drive.method, drive.step), (FixedStep::RosenbrockW, 0.02));
    let observed = prepared.observe(&model);
    let fine = Drive::replay(&run.t, &run.steer, &run.speed, 1e-4, FixedStep::Rk4);
    let reference = model.observe(&model.simulate_from(&fine, 0.0, 0.0), &prepared.times);
    let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
    // RMS of a replay's yaw-rate error against the reference, relative.
    let error = |o: &Observed| {
        let e: Vec<f64> = o
            .yaw_rate
            .iter()
            .zip(&reference.yaw_rate)
            .map(|(a, b)| a - b)
            .collect();
        rms(&e) / rms(&reference.yaw_rate)
    };
    // Measured 2.8e-6.
    assert!(error(&observed) < 1e-5, "{}", error(&observed));
    // A tyre lag of 1.5 mm (rate 20,000 1/s at 30 m/s, a quarter of a
    // millisecond at 6 m/s) is as good as none: its replay at the same
    // 20 ms must match the lag-free reference.
    let mut lagged = model.clone();
    lagged.effects_mut().relaxation_length = 0.0015;
    assert_eq!(prepared.drive_for(&lagged).method, FixedStep::RosenbrockW);
    let lag_error = error(&prepared.observe(&lagged));
    // Measured 1.4e-5.
    assert!(lag_error < 5e-5, "{lag_error}");
    // Soft axles at the same step stay with RK4.
    let (front, rear) = crate::diagnose::base::identify::axle_tyres(
        &crate::diagnose::base::identify::shares(9.3 * 1.3, 10.0 * 1.3, 1.0),
    );
    let soft = Augmented::new(
        VehicleModel::new(crate::vehicle::racing_car(), front, rear),
        1.0,
    );
    assert_eq!(prepared.drive_for(&soft).method, FixedStep::Rk4);
    // On the campaign's own grid the first replay is unstable.
    let coarse = model.observe(
        &model.simulate_from(&prepared.drive, 0.0, 0.0),
        &prepared.times,
    );
    assert!(
        error(&coarse).is_nan() || error(&coarse) >= 0.1,
        "{}",
        error(&coarse)
    );
}

/// A 20 s run at 25 Hz, 20 m/s, with a weaving steer (for the steer path).
fn weave_run() -> crate::measured::MeasuredRun {
    let t: Vec<f64> = (0..500).map(|i| 0.04 * i as f64).collect();
    let (steer, n) = (t.iter().map(|&t| 0.03 * (1.3 * t).sin()).collect(), t.len());
    crate::measured::MeasuredRun::new("weave.csv", t, vec![20.0; n], steer, vec![0.0; n])
        .with_beta(vec![0.0; n])
        .with_ay(vec![0.0; n])
}

#[test]
fn a_steer_path_switched_off_replays_the_base_model_bit_for_bit() {
    use crate::diagnose::effects::EffectKind;
    use crate::diagnose::model::replay::Prepared;
    let run = weave_run();
    let prepared = Prepared::new(&run, 0.01, 25.0);
    let base = Augmented::new(pac89_model(), 1.0);
    let mut off = base.clone();
    EffectKind::SteerPath.apply(&[0.0, 0.0], off.effects_mut());
    assert!(matches!(
        prepared.drive_for(&off),
        std::borrow::Cow::Borrowed(_)
    ));
    let (a, b) = (prepared.replay(&base), prepared.replay(&off));
    assert_eq!(a.yaw_rate, b.yaw_rate);
    assert_eq!(a.beta, b.beta);
    assert_eq!(a.ay, b.ay);
    // Switched on it is another replay, whose steer the vehicle sees late.
    let mut on = base.clone();
    EffectKind::SteerPath.apply(&[0.05, 0.15], on.effects_mut());
    let c = prepared.replay(&on);
    assert_eq!(c.t, a.t);
    assert!(c
        .yaw_rate
        .iter()
        .zip(&a.yaw_rate)
        .any(|(x, y)| (x - y).abs() > 1e-3));
    // The logged steer is what the history records as the drive's input:
    // the transformed one, lagging the command.
    let lagged = prepared.drive_for(&on);
    let k = lagged
        .steer_samples()
        .iter()
        .zip(prepared.drive.steer_samples())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(k > 0.005, "{k}");
}
