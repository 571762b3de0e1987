//! What a fresh user tripped on in round 4 (issue 41) in `simulate`,
//! `metrics` and `diagnose`, run as a user runs the tool: a tyre with no
//! lateral force refused under a key the scenario does not have, a
//! vehicle that tips over at 0.31 g or is twice as wide as it is long run
//! without a word, speeds said without their unit, a 20 Hz log's peak
//! time blamed on noise, and the replay's start drawn as a gap.

use super::*;

/// The repository's MF 6.1 fixture with `key` set to `value`, written to
/// `dir/<name>`.
fn tir_with(dir: &Path, name: &str, key: &str, value: &str) -> PathBuf {
    let text = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let line = text
        .lines()
        .find(|l| l.split_whitespace().next() == Some(key))
        .unwrap()
        .to_string();
    let path = dir.join(name);
    fs::write(&path, text.replace(&line, &format!("{key} = {value}"))).unwrap();
    path
}

/// A step steer of the bundled sedan on tyre file `tyre`, written to
/// `dir/<name>.toml`.
fn sedan_on(dir: &Path, name: &str, vehicle: &str, tyre: &str) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    let text = format!("{vehicle}\n[tyres]\nfront = \"{tyre}\"\n\n{STEP}");
    fs::write(&path, text).unwrap();
    path
}

/// A `.tir` with `PKY1 = 0` (as `identify` writes a lateral block it had
/// no data for) failed as "`manoeuvre.lateral_acceleration` = 0: no steady
/// state … did not converge", a key the scenario does not have; one with
/// `LMUY = 0` likewise. Both are refused at `tyres.front`, naming
/// the file, the force and the coefficient at zero.
#[test]
fn a_tyre_with_no_lateral_force_is_refused_naming_the_file_and_the_force() {
    let dir = tempfile::tempdir().unwrap();
    for (key, tir, force) in [
        (
            "PKY1",
            "no_stiffness.tir",
            "fy changes by 0 N (0 of the load)",
        ),
        (
            "LMUY",
            "no_friction.tir",
            "fy changes by 0 N (0 of the load)",
        ),
    ] {
        tir_with(dir.path(), tir, key, "0");
        let path = sedan_on(dir.path(), key, VEHICLE, tir);
        let e = fails_cleanly("simulate", &path, dir.path());
        for said in [
            &format!("{key}.toml:11:9: `tyres.front`: the front and rear tyres ({tir}) make no usable lateral force: at the static wheel load of 4507 N their"),
            force,
            "over slip angles of ±15.0°",
            &format!("the file's {key} = 0 switches it off"),
        ] {
            assert!(e.contains(said), "{said}\n{e}");
        }
        assert!(!e.contains("lateral_acceleration"), "{e}");
    }
}
