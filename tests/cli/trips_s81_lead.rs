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
