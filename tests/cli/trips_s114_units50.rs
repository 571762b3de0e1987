//! Units findings of fresh-eyes round 49 (session 114): `degrees =
//! ["steer"]` under [runs] on runs whose steer is in radians is one
//! refusal at that entry (its line and column), naming the runs with the
//! factor each reads off by, not one refusal per run; where other runs
//! read right so, they are named to convert in their files. A run refused
//! after its steer was judged (another sign convention) is not counted
//! among the runs that read in radians in the other runs' refusals.

use super::*;

/// `synth --effects none --seed 1` into `dir/camp`, with a campaign file
/// `dir/c.toml` reading its rig and runs (`runs`: extra lines under
/// [runs]); returns the campaign file and the runs folder.
fn campaign(dir: &Path, runs: &str) -> (PathBuf, PathBuf) {
    let camp = synth_campaign(dir, "camp", &["--effects", "none", "--seed", "1"]);
    let text = format!(
        "name = \"u\"\n{VEHICLE}\n[tyres]\nrig = \"camp/tyre_rig.csv\"\nmodel = \"pac89\"\n\n[runs]\ndir = \"camp/runs\"\n{runs}\n[diagnose]\nseed = 1\neffects = [\"sensor_delay\"]\n"
    );
    let path = dir.join("c.toml");
    fs::write(&path, text).unwrap();
    (path, camp.join("runs"))
}

/// The run files of `runs`, sorted.
fn run_files(runs: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(runs)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// `c.toml:<line>:<column>` of the first `"steer"` in the campaign file
/// `c`, 1-based, as a user's editor shows it.
fn steer_entry(c: &Path) -> String {
    let text = fs::read_to_string(c).unwrap();
    let (i, line) = text
        .lines()
        .enumerate()
        .find(|(_, l)| l.starts_with("degrees"))
        .unwrap();
    let column = 1 + line.find("\"steer\"").unwrap();
    format!("c.toml:{}:{column}: ", i + 1)
}

/// The factor the refusal `e` says run `name` reads off by: the number
/// before "× too small" after the run's path.
fn factor(e: &str, name: &str) -> f64 {
    let at = e
        .find(&format!("{name} ("))
        .unwrap_or_else(|| panic!("{name}: {e}"));
    let rest = &e[at + name.len() + 2..];
    let end = rest.find("× too small").unwrap_or_else(|| panic!("{rest}"));
    rest[..end].parse().unwrap_or_else(|_| panic!("{rest}"))
}

#[test]
fn a_declared_steer_that_makes_every_run_57_times_small_is_one_refusal_at_its_entry() {
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "degrees = [ \"steer\" ]\n");
    let files = run_files(&runs);
    let n = files.len();
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    // One refusal, at the `"steer"` element (line 17, column 13 here).
    let at = steer_entry(&c);
    assert_eq!(at, "c.toml:17:13: ");
    assert_eq!(e.matches("error:").count(), 1, "{e}");
    assert!(e.contains(&format!("{at}`degrees` under [runs] declares `steer` in degrees for every run, and so read the steer is far too small in {n} of the {n} runs, the yaw rate far larger than a neutral car's for it: ")), "{e}");
    // Each run named with the factor it reads off by: 180/π.
    for f in &files {
        let k = factor(&e, f);
        assert!((k / 57.2958 - 1.0).abs() < 0.03, "{f}: {k}: {e}");
    }
    assert!(
        e.trim_end().ends_with("as logged, those runs read as a car's, in radians as FORMATS.md asks. take \"steer\" out of `degrees` under [runs]"),
        "{e}"
    );
    // Not each run's own question, nor a count of runs refused one by one.
    assert!(!e.contains("was it already in radians"), "{e}");
    assert!(!e.contains("runs refused"), "{e}");

    // The fix said, taken: the campaign passes.
    let text = fs::read_to_string(&c).unwrap();
    fs::write(&c, text.replace("degrees = [ \"steer\" ]\n", "")).unwrap();
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(ok, "{e}");
}

#[test]
fn runs_that_read_right_under_a_declared_steer_are_named_to_convert_in_their_files() {
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "degrees = [\"yaw_rate\", \"steer\"]\n");
    // The yaw rate in deg/s in every file, as declared; the steer in
    // degrees in two files only.
    let files = run_files(&runs);
    for f in &files {
        map_column(&runs.join(f), "yaw_rate", f64::to_degrees);
    }
    let deg = ["step_060kph_2ms2.csv", "sweep_080kph.csv"];
    for f in deg {
        map_column(&runs.join(f), "steer", f64::to_degrees);
    }
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    let at = steer_entry(&c);
    assert_eq!(at, "c.toml:17:24: ");
    assert_eq!(e.matches("error:").count(), 1, "{e}");
    let small = files.len() - deg.len();
    assert!(
        e.contains(&format!(
            "{at}`degrees` under [runs] declares `steer` in degrees for every run, and so read the steer is far too small in {small} of the {} runs",
            files.len()
        )),
        "{e}"
    );
    for f in files.iter().filter(|f| !deg.contains(&f.as_str())) {
        let k = factor(&e, f);
        assert!((k / 57.2958 - 1.0).abs() < 0.03, "{f}: {k}: {e}");
    }
    // The held step and the sweep read right: their files log degrees.
    let named = |f: &str| runs.join(f).display().to_string();
    let right = format!("{}, {}", named(deg[0]), named(deg[1]));
    assert!(
        e.contains(&format!("{right} read right so, by their steer against their yaw rate: they log the steer in degrees, and a campaign has no per-run unit: take \"steer\" out of `degrees` under [runs] and convert the steer of {right} to radians in their files (× π/180 = 0.0174533)")),
        "{e}"
    );
    for f in deg {
        assert!(!e.contains(&format!("{f} (")), "{f}: {e}");
    }
}

/// The campaign's runs with the steer of `to_degrees` in degrees and that
/// of `reversed` in the other sign convention; `diagnose`'s refusal.
fn refused_with(dir: &Path, to_degrees: &[&str], reversed: &str) -> String {
    let (c, runs) = campaign(dir, "");
    for f in to_degrees {
        map_column(&runs.join(f), "steer", f64::to_degrees);
    }
    map_column(&runs.join(reversed), "steer", |d| -d);
    let (ok, e) = diagnose_status(&c, &dir.join("d"));
    assert!(!ok, "{e}");
    e
}

#[test]
fn a_run_refused_after_its_steer_was_judged_is_not_counted_as_reading_in_radians() {
    let dir = tempfile::tempdir().unwrap();
    let reversed = "step_040kph_3ms2.csv";
    let e = refused_with(
        dir.path(),
        &["step_100kph_2ms2.csv", "step_100kph_6ms2.csv"],
        reversed,
    );
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(lines[0], "error: 3 of 8 runs refused, in run order:", "{e}");
    // The reversed run refused in its own words, first in run order.
    assert!(
        lines[1].contains(reversed) && lines[1].contains("the yaw rate turns against the steer"),
        "{e}"
    );
    // 5 runs taken: 4 held in radians and the sweep; the reversed run is
    // named as refused, not counted among those that read in radians.
    let rev = Path::new(&dir.path().join("camp/runs").join(reversed))
        .display()
        .to_string();
    assert!(
        lines[2].contains("the other 6 runs: 4 read in radians by their held steer against their yaw rate, as they should; "),
        "{e}"
    );
    assert!(
        lines[2].contains(&format!("{rev} was refused for another reason")),
        "{e}"
    );
}
