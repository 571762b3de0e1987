//! What a fresh user tripped on in `metrics` and `simulate` (session 88):
//! a declaration in degrees refused with the fix for another column, load
//! extrapolation and sliding said of a linear tyre, an impossible steady
//! lateral acceleration unsaid, slip angles past ±180°, the speed and
//! standstill rules, a sideslip sign check deaf below a fixed floor, and
//! `E_r` biased by a coarse sample rate without a word.

use super::sedan_runs::{run_text, sedan_history};
use super::*;

/// A replay of `run` (a file beside it) on the bundled sedan, with `extra`
/// under its [manoeuvre].
fn replay_scenario(run: &Path, extra: &str) -> PathBuf {
    let base = bundled_scenario("sedan_step.toml");
    let base = base.replace("../tyres", root().join("tyres").to_str().unwrap());
    let head = &base[..base.find("[manoeuvre]").unwrap()];
    let sc = run.with_file_name("replay.toml");
    let text = format!(
        "{head}[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n{extra}",
        run.file_name().unwrap().to_str().unwrap()
    );
    fs::write(&sc, text).unwrap();
    sc
}

/// `metrics --degrees yaw_rate` on the sedan's step logged in rad/s ended
/// with the fix of a steer in degrees: "a column in degrees is declared
/// so: `metrics --degrees steer`". Now it names the declaration made:
/// "leave out `--degrees yaw_rate`"; `--degrees steer` on a steer in
/// radians likewise "leave out `--degrees steer`".
#[test]
fn a_wrong_degrees_declaration_is_named_with_its_own_fix() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("rad.csv");
    fs::write(&file, run_text(&history, 10, None)).unwrap();
    for (column, other) in [("yaw_rate", "steer"), ("steer", "yaw_rate")] {
        let o = run(&["metrics", file.to_str().unwrap(), "--degrees", column]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!(
                "column `{column}`, declared in degrees by `--degrees {column}`"
            )) && e
                .trim_end()
                .ends_with(&format!("leave out `--degrees {column}`")),
            "{e}"
        );
        assert!(!e.contains(&format!("--degrees {other}")), "{e}");
    }
}

/// A replay whose `degrees = ["yaw_rate"]` declares a yaw rate logged in
/// rad/s was refused at `manoeuvre.run` ("the run rad.csv: the yaw rate is
/// 123× smaller…") with the fix `degrees = ["steer"]`. Now it stands at the
/// `degrees` entry (line 22, column 12) and says to take it out.
#[test]
fn a_replay_refused_for_its_degrees_names_the_degrees_key() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("rad.csv");
    fs::write(&file, run_text(&history, 10, None)).unwrap();
    for column in ["yaw_rate", "steer"] {
        let sc = replay_scenario(&file, &format!("degrees = [\"{column}\"]\n"));
        let line = fs::read_to_string(&sc)
            .unwrap()
            .lines()
            .position(|l| l.starts_with("degrees"))
            .unwrap()
            + 1;
        let o = run(&[
            "simulate",
            sc.to_str().unwrap(),
            "--out",
            dir.path().join("o").to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!(
                "replay.toml:{line}:12: `manoeuvre.degrees` declares `{column}` in degrees"
            )) && e.contains(&format!(
                "take `\"{column}\"` out of `degrees` under [manoeuvre]"
            )),
            "{e}"
        );
    }
}
