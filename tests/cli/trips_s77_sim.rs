//! What a fresh user tripped on in `simulate`,
//! `metrics`, run as a user runs the tool: a tyre with no
//! lateral force refused under a key the scenario does not have, a
//! vehicle that tips over at 0.31 g or is twice as wide as it is long run
//! without a word, speeds said without their unit, and a 20 Hz log's peak
//! time blamed on noise.

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
/// `LMUY = 0` likewise. The latter is refused at `tyres.front`, naming
/// the file, the force and the coefficient at zero; the former, with a
/// lateral peak (`PDY1`), by the `.tir` reader at its line as a cornering
/// stiffness below any tyre's (session 97, as `PKY1 = -0.5` is).
#[test]
fn a_tyre_with_no_lateral_force_is_refused_naming_the_file_and_the_force() {
    let dir = tempfile::tempdir().unwrap();
    tir_with(dir.path(), "no_stiffness.tir", "PKY1", "0");
    let path = sedan_on(dir.path(), "PKY1", VEHICLE, "no_stiffness.tir");
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("no_stiffness.tir:206:")
            && e.contains("`PKY1`: 0 gives the tyre a cornering stiffness"),
        "{e}"
    );
    for (key, tir, force) in [(
        "LMUY",
        "no_friction.tir",
        "fy changes by 0 N (0 of the load)",
    )] {
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

/// `simulate` the bundled sedan's 1° step with rows every `step` s into
/// `dir/<name>`; the history's path.
fn sedan_history(dir: &Path, name: &str, step: f64) -> PathBuf {
    let text = bundled_scenario("sedan_step.toml");
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{text}\n[simulation]\nstep = {step}\n")).unwrap();
    let out = dir.join(name);
    succeeds(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    out.join("history.csv")
}

/// `metrics` on a run with neither `ay` nor `ax` said "its speed runs
/// 22.2–22.2 with a median of 22.2": speeds without their unit.
#[test]
fn metrics_says_the_unit_of_the_speeds_it_could_not_check() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path(), "sedan", 0.01);
    let text = fs::read_to_string(&history).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let keep = ["t", "speed", "steer", "yaw_rate", "beta"];
    let cols: Vec<usize> = keep
        .iter()
        .map(|k| header.iter().position(|h| h == k).unwrap())
        .collect();
    let rows: Vec<String> = text
        .lines()
        .map(|l| {
            let v: Vec<&str> = l.split(',').collect();
            cols.iter().map(|&i| v[i]).collect::<Vec<_>>().join(",")
        })
        .collect();
    let run = dir.path().join("no_ay.csv");
    fs::write(&run, rows.join("\n") + "\n").unwrap();
    let o = run_in(dir.path(), &["metrics", "no_ay.csv"]);
    let said = format!("{}{}", stderr(&o), String::from_utf8_lossy(&o.stdout));
    assert!(
        said.contains(
            "read as m/s, its speed runs 22.2–22.2 m/s with a median of 22.2 m/s (80.0 km/h)"
        ),
        "{said}"
    );
}

/// `metrics` on a 20 Hz log read its peak time at a sample (0.400 s
/// against 0.435 s at 1 kHz) without a word on the grid, and on a noisy
/// one blamed the noise for it. The resolution, ±half a sample interval,
/// is said; a 1 kHz run says none.
#[test]
fn metrics_says_the_peak_time_resolution_of_a_coarse_log() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path(), "coarse", 0.05);
    let o = run(&["metrics", history.to_str().unwrap(), "--filter-hz", "0"]);
    let said = format!("{}{}", stderr(&o), String::from_utf8_lossy(&o.stdout));
    for line in [
        "yaw-rate peak time           0.4500 s",
        "the yaw-rate peak time, 0.450 s, is a sample of a 20.0 Hz log (the peak is not interpolated between samples): it is resolved to ±0.025 s, half the 0.0500 s sample interval (5.6 % of it), and TB with it",
    ] {
        assert!(said.contains(line), "{line}\n{said}");
    }
    assert!(!said.contains("flat within the noise"), "{said}");
    let fine = sedan_history(dir.path(), "fine", 0.001);
    let o = run(&["metrics", fine.to_str().unwrap(), "--filter-hz", "0"]);
    let said = format!("{}{}", stderr(&o), String::from_utf8_lossy(&o.stdout));
    assert!(!said.contains("is a sample of a"), "{said}");
}

/// `cg_height = 2.5` on a 1.55 m track (the car rolls over at 0.31 g) and
/// `track = 5.5` on a 2.78 m wheelbase (twice as wide as long) ran without
/// a word: only values beyond any vehicle's were refused. Both are warned
/// with their numbers and the range of road vehicles; the bundled sedan
/// says neither.
#[test]
fn simulate_warns_of_a_car_that_rolls_over_early_or_is_wider_than_long() {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("sedan_step.toml");
    for (name, from, to, said) in [
        (
            "tall",
            "cg_height = 0.55",
            "cg_height = 2.5",
            "the static stability factor track/(2·cg_height) = 1.55/(2·2.5) is 0.31 g: the car rolls over at 3.0 m/s² of lateral acceleration, where a road car holds 1.0–1.5 g (NHTSA's rollover ratings)",
        ),
        (
            "wide",
            "track_front = 1.55",
            "track_front = 5.5",
            "track_front = 5.5 m on a wheelbase a + b = 2.78 m gives track/wheelbase = 1.98, wider than any vehicle's 1.4 (road cars 0.5–0.75, a kart up to about 1.3)",
        ),
    ] {
        assert!(text.contains(from), "{from}");
        let path = dir.path().join(format!("{name}.toml"));
        fs::write(&path, text.replacen(from, to, 1)).unwrap();
        let o = run(&["simulate", path.to_str().unwrap(), "--out", dir.path().join(name).to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(out.contains(said), "{said}\n{out}");
    }
    let path = dir.path().join("sedan.toml");
    fs::write(&path, &text).unwrap();
    let o = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        dir.path().join("sedan").to_str().unwrap(),
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        !out.contains("static stability") && !out.contains("track/wheelbase"),
        "{out}"
    );
}
