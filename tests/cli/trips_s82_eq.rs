//! Fresh-eyes round 9 on `equilibria` and the scenario/sweep TOML checks:
//! the stability of a model with a tyre lag is the full state's (β, r and
//! the lagged slip angles), not the (β, r) model's.

use super::*;

/// The bundled speed sweep cut to steer 0.1 rad at 20 m/s, with `effects`
/// (a `[model.effects]` table's lines, or nothing) before `[sweep]`.
fn speed_sweep(effects: &str) -> String {
    let text = bundled_scenario("equilibria_speed.toml");
    let text = text.replace(
        "speed = { from = 30.0, to = 120.0, step = 10.0, unit = \"km/h\" }",
        "speed = 20.0",
    );
    text.replace("[sweep]", &format!("{effects}[sweep]"))
}

/// The high-yaw equilibrium's row of equilibria.csv (r > 0.35 rad/s):
/// kind and leading eigenvalue (re, im).
fn high_yaw_row(dir: &Path, sweep: &str) -> (String, f64, f64) {
    fs::write(dir.join("sweep.toml"), sweep).unwrap();
    let out = dir.join("out");
    succeeds(&[
        "equilibria",
        dir.join("sweep.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let csv = fs::read_to_string(out.join("equilibria.csv")).unwrap();
    let row: Vec<String> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect::<Vec<_>>())
        .find(|f| f[4].parse::<f64>().unwrap() > 0.35)
        .expect("the high-yaw equilibrium");
    (
        row[5].clone(),
        row[6].parse().unwrap(),
        row[7].parse().unwrap(),
    )
}

/// (7) A relaxation length of 3 m at 20 m/s (lag rate u/σ = 6.7 1/s, slow
/// against the axles') turns the high-yaw stable focus into an unstable
/// one; the old binary gave the model without the lag's stability.
#[test]
fn a_tyre_lag_turns_a_stable_focus_unstable() {
    let dir = tempfile::tempdir().unwrap();
    let (kind, re, im) = high_yaw_row(dir.path(), &speed_sweep(""));
    assert_eq!(kind, "stable-focus");
    assert!(
        (re + 0.004495).abs() < 1e-5 && (im - 0.64747).abs() < 1e-4,
        "{re} {im}"
    );
    let lagged = speed_sweep("[model.effects]\nrelaxation_length = 3.0\n\n");
    let (kind, re, im) = high_yaw_row(dir.path(), &lagged);
    assert_eq!(kind, "unstable-focus");
    assert!(
        (re - 0.026441).abs() < 1e-5 && (im - 0.64439).abs() < 1e-4,
        "{re} {im}"
    );
}

/// The bundled steer sweep with `line` replacing the line starting with
/// `start` (or appended where `start` is empty); its error.
fn steer_sweep_error(start: &str, line: &str) -> String {
    let text = bundled_scenario("equilibria_steer.toml");
    let text = if start.is_empty() {
        format!("{text}\n{line}\n")
    } else {
        text.lines()
            .map(|l| if l.starts_with(start) { line } else { l })
            .collect::<Vec<_>>()
            .join("\n")
    };
    let dir = scratch(&[("sweep.toml", &text)]);
    fails_cleanly("equilibria", &dir.path().join("sweep.toml"), dir.path())
}

/// (9) A speed of 1000 m/s (or km/h), a friction of 50 and `beta_max = 30`
/// (degrees) are refused at their keys with the rule and the likely slip;
/// the old binary ran them.
#[test]
fn absurd_sweep_values_are_refused_at_their_keys() {
    let e = steer_sweep_error("speed =", "speed = [20.0, 1000.0]");
    assert!(
        e.contains("sweep.toml:28:9: `sweep.speed` = 1000: must lie in (0.5, 150]: the model evaluates no speed below 0.5 m/s"),
        "{e}"
    );
    let e = steer_sweep_error("speed =", "speed = { values = [1000.0], unit = \"km/h\" }");
    assert!(
        e.contains("`sweep.speed` = 1000: must lie in (1.8, 540]"),
        "{e}"
    );
    let e = steer_sweep_error("friction =", "friction = 50.0");
    assert!(
        e.contains("sweep.toml:27:12: `sweep.friction` = 50: must lie in (0, 3]: the road's friction scales the tyres' own"),
        "{e}"
    );
    let e = steer_sweep_error("", "[box]\nbeta_max = 30\nyaw_rate_max = 1.0");
    assert!(
        e.contains("`box.beta_max` = 30: must lie in (0, 1.5708]: a sideslip beyond ±90° (1.5708 rad) is a car running backward, where the model has no equilibrium; the key is in rad: did you mean 0.5236 rad (30°)?"),
        "{e}"
    );
}

/// (9) A `[box]` with one key takes the other's default; it failed with
/// "missing field `yaw_rate_max`".
#[test]
fn a_box_with_one_key_takes_the_others_default() {
    let text = format!(
        "{}\n[box]\nbeta_max = 0.5\n",
        bundled_scenario("equilibria_steer.toml")
    );
    let dir = scratch(&[("sweep.toml", &text)]);
    let out = dir.path().join("out");
    let said = succeeds(&[
        "equilibria",
        dir.path().join("sweep.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        said.contains("box |β| ≤ 0.500 rad, |r| ≤ 0.484 rad/s"),
        "{said}"
    );
}

/// (10) A campaign, a run CSV, a history, a `.tir` and a tyre file given
/// to `equilibria` or `study` are named as what they are, with the
/// command that reads them; the old binary gave the parser's complaint
/// about their first key or line (`unknown field `rig``, `expected `.`,
/// `=``).
#[test]
fn files_of_another_kind_given_to_equilibria_or_study_are_named() {
    let dir = scratch(&[
        ("log.csv", "t,speed,steer,yaw_rate\n0,20,0,0\n0.01,20,0,0\n"),
        (
            "history.csv",
            "t,steer,speed,beta,yaw_rate,ay,alpha_front,alpha_rear,fy_front,fy_rear\n0,0,20,0,0,0,0,0,0,0\n",
        ),
        ("car.tir", "[MODEL]\nFITTYP = 61\n"),
    ]);
    let campaign = root().join("campaigns/delays.toml");
    let tyre = root().join("tyres/gim.toml");
    let cases = [
        (
            campaign,
            "this is a campaign (a TOML file with [runs] or [diagnose]), not ",
            ": `handling diagnose` reads it",
        ),
        (
            dir.path().join("log.csv"),
            "this is a measured vehicle run (columns t, speed, steer, yaw_rate), not ",
            ": `handling metrics` measures it",
        ),
        (
            dir.path().join("history.csv"),
            "this is a simulation history (history.csv, which `handling simulate` writes)",
            ": `handling metrics` measures it",
        ),
        (
            dir.path().join("car.tir"),
            "this is a Magic Formula tyre property file (.tir), not ",
            ": `handling tyre-eval` reads it",
        ),
        (
            tyre,
            "this is a tyre file (`model = \"gim\"`), not ",
            ": `handling tyre-eval` reads it",
        ),
    ];
    for (file, is, reader) in cases {
        for (command, wanted) in [
            ("equilibria", "an equilibrium sweep (a TOML file with [vehicle], [tyres] and [sweep]), which `handling equilibria` reads"),
            ("study", "a stiffness study (a TOML file with [vehicle], [tyres], [manoeuvre] and [stiffness] or [rbf]), which `handling study` reads"),
        ] {
            let e = fails_cleanly(command, &file, dir.path());
            assert!(e.contains(is) && e.contains(wanted) && e.contains(reader), "{command}: {e}");
            assert!(!e.contains("unknown field") && !e.contains("expected `.`"), "{e}");
        }
    }
}
