//! A replayed log's `ax` in g or reversed (fresh-eyes round 7): the
//! replay took it as m/s² forward for its longitudinal load transfer
//! without a word. Its speed now says what it is (`Δu` against `∫ax dt`
//! over one-second windows, `measured::ax_agreement`). And a scenario's
//! `name` that wrote its run outside `out/` (round 8).

use super::*;

/// A 30 s replay at 100 Hz whose speed swings 20 ± 5 m/s (0.3 rad/s), its
/// `ax` the speed's derivative times `scale`, on the sedan of `VEHICLE`
/// with the bundled linear tyre and longitudinal load transfer; `simulate`'s
/// stdout.
fn replayed(dir: &Path, scale: f64) -> String {
    let scenario = replay_scenario(dir, scale, "");
    let out = dir.join(format!("out{scale}"));
    succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

/// The scenario of [`replayed`], `head` before its tables, written to
/// `dir/replay.toml` with its run.
fn replay_scenario(dir: &Path, scale: f64, head: &str) -> PathBuf {
    let mut text = String::from("t,speed,steer,yaw_rate,ax\n");
    for i in 0..=3000 {
        let t = i as f64 * 0.01;
        let u = 20.0 + 5.0 * (0.3 * t).sin();
        let ax = scale * 1.5 * (0.3 * t).cos();
        text += &format!("{t},{u},0,0,{ax}\n");
    }
    fs::write(dir.join("run.csv"), text).unwrap();
    let tyre = root().join("tyres/linear.toml");
    let scenario = dir.join("replay.toml");
    fs::write(
        &scenario,
        format!(
            "{head}{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n\n[model.effects]\nlongitudinal_load_transfer = 1\n",
            tyre.display()
        ),
    )
    .unwrap();
    scenario
}

#[test]
fn a_logged_ax_in_g_or_reversed_is_said_from_the_speed() {
    let dir = tempfile::tempdir().unwrap();
    let agreed = replayed(dir.path(), 1.0);
    assert!(!agreed.contains("`ax`"), "{agreed}");
    let in_g = replayed(dir.path(), 1.0 / 9.80665);
    assert!(
        in_g.contains("the run's `ax` reads in g, not m/s²: over its 24 one-second windows"),
        "{in_g}"
    );
    assert!(in_g.contains("is 9.81 × the integral of `ax`"), "{in_g}");
    assert!(in_g.contains("multiply the column by 9.81"), "{in_g}");
    let reversed = replayed(dir.path(), -1.0);
    assert!(
        reversed.contains("the run's `ax` is positive rearward, not forward (ISO 8855)"),
        "{reversed}"
    );
    assert!(reversed.contains("is -1.00 × the integral"), "{reversed}");
}

/// `name = "../../escaped"` wrote the run two folders above `out/`
/// (`simulate` writes into `out/<name>` without `--out`), and `name = ""`
/// into `out/` itself: both refused at the key, with nothing written.
#[test]
fn a_scenario_name_that_is_no_folder_name_is_refused_at_its_line() {
    for name in ["../../escaped", "", "a/b"] {
        let dir = tempfile::tempdir().unwrap();
        let scenario = replay_scenario(dir.path(), 1.0, &format!("name = {name:?}\n"));
        let said = fails_cleanly("simulate", &scenario, dir.path());
        assert!(said.contains("replay.toml:1:"), "{said}");
        assert!(
            said.contains(&format!("`name` = {name:?} is no folder name")),
            "{said}"
        );
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "{name}");
    }
}
