//! Every candidate is nested in the base model: with its parameters at
//! their "off" values ([`crate::diagnose::effects::Parameter::off`], NaN
//! meaning the vehicle's own share) the augmented model replays a run to
//! exactly the base model's history and observations. A fit that starts
//! there (the diagnosis puts a particle and the polish start at the off
//! values) can then never end worse in sample than the base model.

use super::*;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::replay::Prepared;
use crate::measured::MeasuredRun;
use crate::tyre::{Pac89, Tyre};
use crate::vehicle::Vehicle;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The base model: Pac89 tyres, load transfer, exact kinematics.
fn base() -> Augmented {
    let t = Tyre::Pac89(Pac89::adams_example());
    Augmented::new(
        VehicleModel::new(Vehicle::compact_sedan(), t.clone(), t),
        0.9,
    )
}

/// 8 s at 100 Hz steering a 0.5 Hz sine of 0.03 rad at `speed(t)`, the
/// speed logged with 0.03 m/s of white noise; with an `ax` channel (the
/// speed's slope plus 0.05 m/s² of noise) when `with_ax`.
fn run(name: &str, speed: impl Fn(f64) -> f64, slope: f64, with_ax: bool) -> MeasuredRun {
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    let mut gauss = || crate::identify::data::gauss(&mut rng);
    let t: Vec<f64> = (0..801).map(|k| k as f64 * 0.01).collect();
    let n = t.len();
    let steer = t
        .iter()
        .map(|&x| 0.03 * (std::f64::consts::TAU * 0.5 * x).sin())
        .collect();
    let speed = t.iter().map(|&x| speed(x) + 0.03 * gauss()).collect();
    let ax = with_ax.then(|| (0..n).map(|_| slope + 0.05 * gauss()).collect());
    MeasuredRun::new(name, t, speed, steer, vec![0.01; n])
        .with_ay(vec![0.0; n])
        .with_beta(vec![0.002; n])
        .with_ax(ax)
}

/// Constant speed and braking, each without and with `ax`.
fn runs() -> Vec<MeasuredRun> {
    let braking = |x: f64| 25.0 - 3.0 * (x - 1.0).clamp(0.0, 5.0);
    vec![
        run("constant.csv", |_| 20.0, 0.0, false),
        run("constant_ax.csv", |_| 20.0, 0.0, true),
        run("braking.csv", braking, -3.0, false),
        run("braking_ax.csv", braking, -3.0, true),
    ]
}

/// `a` and `b` agree to 1e-12 (relative to their size, at least 1).
fn same(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let tol = 1e-12 * x.abs().max(y.abs()).max(1.0);
        assert!(
            (x - y).abs() <= tol || (x.is_nan() && y.is_nan()),
            "{what}[{i}]: {x} vs {y}"
        );
    }
}

fn same_history(a: &TimeHistory, b: &TimeHistory, what: &str) {
    for (name, x, y) in [
        ("t", &a.t, &b.t),
        ("steer", &a.steer, &b.steer),
        ("speed", &a.speed, &b.speed),
        ("beta", &a.beta, &b.beta),
        ("yaw_rate", &a.yaw_rate, &b.yaw_rate),
        ("ay", &a.ay, &b.ay),
        ("alpha_front", &a.alpha_front, &b.alpha_front),
        ("alpha_rear", &a.alpha_rear, &b.alpha_rear),
        ("fy_front", &a.fy_front, &b.fy_front),
        ("fy_rear", &a.fy_rear, &b.fy_rear),
        ("roll", &a.roll, &b.roll),
    ] {
        same(x, y, &format!("{what}: {name}"));
    }
    for w in 0..4 {
        same(&a.fz[w], &b.fz[w], &format!("{what}: fz[{w}]"));
    }
}

fn same_observed(a: &Observed, b: &Observed, what: &str) {
    same(
        &a.yaw_rate,
        &b.yaw_rate,
        &format!("{what}: observed yaw_rate"),
    );
    same(&a.ay, &b.ay, &format!("{what}: observed ay"));
    same(&a.beta, &b.beta, &format!("{what}: observed beta"));
    same(&a.roll, &b.roll, &format!("{what}: observed roll"));
}

/// `kind`'s off values, NaN taken as the vehicle's nominal share.
fn off(kind: EffectKind, nominal_share: f64) -> Vec<f64> {
    kind.parameters()
        .iter()
        .map(|q| if q.off.is_nan() { nominal_share } else { q.off })
        .collect()
}

#[test]
fn every_effect_at_its_off_values_replays_the_base_models_history() {
    let base = base();
    let share = base.model.vehicle.front_transfer_share();
    let mut all_off = base.clone();
    for r in runs() {
        let p = Prepared::new(&r, 0.01, 25.0);
        let reference = p.replay(&base);
        let seen = p.observe(&base);
        assert!(reference.yaw_rate.iter().all(|x| x.is_finite()));
        assert!(
            reference.yaw_rate.iter().any(|x| x.abs() > 0.02),
            "the run turns"
        );
        for kind in EffectKind::ALL {
            let mut m = base.clone();
            kind.apply(&off(kind, share), m.effects_mut());
            kind.apply(&off(kind, share), all_off.effects_mut());
            let what = format!("{} on {}", kind.name(), r.path.display());
            same_history(&p.replay(&m), &reference, &what);
            same_observed(&p.observe(&m), &seen, &what);
        }
        let what = format!("every effect off on {}", r.path.display());
        same_history(&p.replay(&all_off), &reference, &what);
        same_observed(&p.observe(&all_off), &seen, &what);
    }
}

#[test]
fn the_longitudinal_effects_act_on_braking_and_not_on_a_noisy_constant_speed() {
    // The nesting above must not be an effect that does nothing: on, the
    // longitudinal effects change the braking run's replay. On a constant
    // speed logged with noise and no ax they change it by little (the
    // smoothed speed derivative is no longitudinal acceleration), where
    // the raw difference of the speed (4 m/s² RMS) moved it as much as a
    // braking of 3 m/s².
    let base = base();
    let runs = runs();
    let change = |kind: EffectKind, p: &[f64], r: &MeasuredRun| {
        let prepared = Prepared::new(r, 0.01, 25.0);
        let mut m = base.clone();
        kind.apply(p, m.effects_mut());
        let a = prepared.replay(&m).yaw_rate;
        let b = prepared.replay(&base).yaw_rate;
        a.iter()
            .zip(&b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    for (kind, p) in [
        (EffectKind::CombinedSlip, vec![0.0, 0.65, 1.0]),
        (EffectKind::LongitudinalLoadTransfer, vec![1.0]),
    ] {
        let braking = change(kind, &p, &runs[2]);
        let braking_ax = change(kind, &p, &runs[3]);
        let constant = change(kind, &p, &runs[0]);
        assert!(braking > 1e-3, "{}: {braking}", kind.name());
        assert!(braking_ax > 1e-3, "{}: {braking_ax}", kind.name());
        assert!(
            constant < 0.1 * braking,
            "{}: {constant} vs {braking}",
            kind.name()
        );
    }
}

#[test]
fn every_effect_at_its_truth_changes_what_the_sensors_see() {
    // The nesting above must not be an effect that does nothing: at its
    // proving-ground truth every effect changes the observations of a
    // braking run that carries `ax` and a `bank` channel (each effect's
    // needs), so an effect whose numbers no physics reads fails here.
    let base = base();
    let mut r = run(
        "braking_bank.csv",
        |x| 25.0 - 3.0 * x.clamp(0.0, 5.0),
        -3.0,
        true,
    );
    r.bank = Some(r.t.iter().map(|&x| 0.05 * (0.4 * x).sin()).collect());
    let p = Prepared::new(&r, 0.01, 25.0);
    let seen = p.observe(&base);
    for kind in EffectKind::ALL {
        let mut m = base.clone();
        kind.apply(kind.truth(), m.effects_mut());
        let o = p.observe(&m);
        let change = [
            (&o.yaw_rate, &seen.yaw_rate),
            (&o.ay, &seen.ay),
            (&o.beta, &seen.beta),
        ]
        .iter()
        .flat_map(|(a, b)| a.iter().zip(b.iter()).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
        assert!(change > 1e-9, "{}: {change:e}", kind.name());
    }
}
