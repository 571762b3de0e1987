//! Straight running on a banked road (fresh-eyes round 9): the trim a
//! step steer starts from held the tyres' lateral acceleration at zero,
//! so on a bank the car started in a turn down it (`r = −g·sin θ/u`,
//! −0.0221 rad/s at 0.05 rad and 80 km/h) and the advised steer had the
//! wrong sign. Straight running is zero yaw rate: the tyres hold the
//! bank's pull, `Fyf·cos δ + Fyr = m·g·sin θ`.

use super::*;

#[test]
fn a_banked_step_steer_starts_straight_with_the_tyres_holding_the_bank() {
    let bank = 0.05;
    let text = bundled_scenario("sedan_step.toml").replace(
        "[manoeuvre]",
        &format!("[model.effects]\nroad_bank = {bank}\n\n[manoeuvre]"),
    );
    let dir = scratch(&[("bank.toml", &text)]);
    let out = dir.path().join("out");
    let stdout = succeeds(&[
        "simulate",
        dir.path().join("bank.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    // Closed form of the linear bicycle at ay = g·sin θ, r = 0: the steer
    // is positive (toward the upper edge), about 0.176°.
    assert!(
        stdout.contains("straight running needs a steer of 0.176° and a sideslip of -0.282°"),
        "{stdout}"
    );
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = history.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let (t, r, ay) = (col("t"), col("yaw_rate"), col("ay"));
    let (ff, fr, steer) = (col("fy_front"), col("fy_rear"), col("steer"));
    let mass = 1530.0;
    let pull = 9.80665 * f64::sin(bank);
    let mut before_step = 0;
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        if v[t] >= 1.0 {
            break;
        }
        before_step += 1;
        assert!(v[r].abs() < 1e-9, "t = {}: yaw rate {}", v[t], v[r]);
        assert!((v[ay] - pull).abs() < 1e-6, "t = {}: ay {}", v[t], v[ay]);
        // The front force acts along the steered wheel: cos δ of it is lateral.
        let held = (v[ff] * v[steer].cos() + v[fr]) / mass;
        assert!((held - pull).abs() < 1e-6, "t = {}: ΣFy/m {held}", v[t]);
    }
    assert_eq!(before_step, 1000, "rows before the step at 1 ms");
}

/// An RK4 step past the method's stability limit for a lagged model: the
/// run blew up (angles of 1e162 rad, NaN rows) and exited 0. Refused at
/// the step with the fastest rate and a step that is stable.
#[test]
fn an_rk4_step_beyond_its_stability_limit_is_refused_at_the_step() {
    let text = bundled_scenario("sedan_step.toml").replace(
        "[manoeuvre]",
        "[model.effects]\nrelaxation_length = 0.3\n\n[integrator]\nmethod = \"rk4\"\nstep = 0.05\n\n[manoeuvre]",
    );
    let dir = scratch(&[("rk4.toml", &text)]);
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("rk4.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = refused(&o, &out);
    // u/σ = 22.2222/0.3 = 74.07 1/s; h·ρ = 3.70 > 2.785; 2.5/74.07 = 0.034 s.
    let line = text.lines().position(|l| l == "step = 0.05").unwrap() + 1;
    assert!(
        err.contains(&format!(
            "rk4.toml:{line}:8: RK4 at a fixed step of 0.05 s is unstable"
        )),
        "{err}"
    );
    assert!(err.contains("decays at 74.07 1/s at 22.2 m/s (the tyres' lag, u/σ with `relaxation_length` = 0.3 m), so h·ρ = 3.7"), "{err}");
    assert!(err.contains("use a step of at most 0.034 s"), "{err}");
    // The step it suggests runs.
    let stable = text.replace("step = 0.05", "step = 0.034");
    fs::write(dir.path().join("rk4.toml"), stable).unwrap();
    let ran = succeeds(&[
        "simulate",
        dir.path().join("rk4.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!without_temp_names(&ran).contains("NaN"), "{ran}");
}
