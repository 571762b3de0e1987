//! Units findings of fresh-eyes round 48 (session 113): a campaign's run
//! whose yaw rate alone is in deg/s is advised to convert its own file,
//! and `degrees = ["yaw_rate"]` making the other runs 57× small is
//! refused at that entry, not blamed on the steer; a time under a long
//! name in ms (`time [ms]`, `time_ms`, `Time (ms)`) gets the conversion,
//! not a renaming alone; a rig or points file with loads in kN and
//! pressures in bar is refused for both at once; a `.tir` far beyond its
//! FNOMIN is said on the rear axle as on the front.

use super::*;

/// The run whose yaw rate is logged in deg/s.
const DEG_RUN: &str = "step_100kph_2ms2.csv";

/// `synth --effects sensor_delay --seed 1` into `dir/camp`, with a
/// campaign file `dir/c.toml` reading its rig and runs (`runs` extra
/// lines under [runs]); returns the campaign file and the runs folder.
fn campaign(dir: &Path, runs: &str) -> (PathBuf, PathBuf) {
    let camp = synth_campaign(dir, "camp", &["--effects", "sensor_delay", "--seed", "1"]);
    let text = format!(
        "name = \"b\"\n{VEHICLE}\n[tyres]\nrig = \"camp/tyre_rig.csv\"\nmodel = \"pac89\"\n\n[runs]\ndir = \"camp/runs\"\n{runs}\n[diagnose]\nseed = 1\neffects = [\"sensor_delay\", \"relaxation_length\"]\n"
    );
    let path = dir.join("c.toml");
    fs::write(&path, text).unwrap();
    (path, camp.join("runs"))
}

/// `diagnose campaign`'s refusal (it must fail).
fn refusal(campaign: &Path, dir: &Path) -> String {
    let out = dir.join("d");
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "{}", stderr(&o));
    stderr(&o)
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

#[test]
fn one_runs_yaw_rate_in_deg_per_s_is_converted_in_its_file_not_declared() {
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "");
    map_column(&runs.join(DEG_RUN), "yaw_rate", f64::to_degrees);
    let files = run_files(&runs);
    let e = refusal(&c, dir.path());
    // Located in the run's file, at its yaw rate's column (4).
    let at = format!("{DEG_RUN}:");
    let line = e
        .lines()
        .find(|l| l.contains(&at))
        .unwrap_or_else(|| panic!("{e}"));
    assert!(line.contains("column `yaw_rate`"), "{line}");
    let others = files.len() - 1;
    assert!(
        line.contains(&format!(
            "is the column in deg/s? this run alone logs it so, where {others} of the campaign's {} runs read their yaw rate in rad/s, judged against their steer by a neutral car's r = u·δ/l: a campaign has no per-run unit",
            files.len()
        )),
        "{line}"
    );
    assert!(
        line.ends_with("convert this run's `yaw_rate` to rad/s in its file (÷ 57.2958), or leave the run out of the campaign"),
        "{line}"
    );
    // The advice that would convert every run is not given as the fix.
    assert!(!e.contains("declare it so"), "{e}");

    // Every run in deg/s: declaring it for the campaign is right, and each
    // run's refusal still says so.
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "");
    for f in run_files(&runs) {
        map_column(&runs.join(f), "yaw_rate", f64::to_degrees);
    }
    let e = refusal(&c, dir.path());
    assert!(
        e.contains("declare it so: `degrees = [\"yaw_rate\"]` under [runs]"),
        "{e}"
    );
    assert!(!e.contains("this run alone"), "{e}");
}

#[test]
fn a_declared_yaw_rate_that_makes_the_runs_57_times_small_is_refused_at_its_entry() {
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "degrees = [\"yaw_rate\"]\n");
    map_column(&runs.join(DEG_RUN), "yaw_rate", f64::to_degrees);
    let files = run_files(&runs);
    let text = fs::read_to_string(&c).unwrap();
    let line = 1 + text.lines().position(|l| l.starts_with("degrees")).unwrap();
    let e = refusal(&c, dir.path());
    // At the entry `degrees = ["yaw_rate"]` (its value's column, 12).
    let at = format!("c.toml:{line}:12: `degrees` under [runs] declares `yaw_rate` in deg/s for every run, and so read the yaw rate is far too small in {} of the {} runs: far smaller than a neutral car's for the steer in ", files.len() - 1, files.len());
    assert!(e.contains(&at), "{e}");
    // Each of the others named with its ratio, near 1/57.
    for f in files.iter().filter(|f| *f != DEG_RUN) {
        assert!(e.contains(&format!("{f} (")), "{f}: {e}");
    }
    let deg = runs.join(DEG_RUN);
    let deg = deg.display();
    assert!(
        e.contains(&format!("those runs log it in rad/s, as FORMATS.md asks. {deg} reads right so, by its steer against its yaw rate: it logs it in deg/s, and a campaign has no per-run unit: take \"yaw_rate\" out of `degrees` under [runs] and convert the yaw rate of {deg} to rad/s in its file (÷ 57.2958)")),
        "{e}"
    );
    // Not the steer's unit.
    assert!(!e.contains("is `steer` in degrees"), "{e}");

    // Every run in rad/s: the entry alone is to go.
    let dir = tempfile::tempdir().unwrap();
    let (c, runs) = campaign(dir.path(), "degrees = [\"yaw_rate\"]\n");
    let n = run_files(&runs).len();
    let e = refusal(&c, dir.path());
    assert!(
        e.contains(&format!(
            "the yaw rate is far too small in {n} of the {n} runs: "
        )),
        "{e}"
    );
    assert!(
        e.contains("those runs log it in rad/s, as FORMATS.md asks. take \"yaw_rate\" out of `degrees` under [runs]"),
        "{e}"
    );
    assert!(!e.contains("÷ 57.2958"), "{e}");
}

/// A run of 3 s at 100 Hz, straight at 20 m/s, its time in ms under
/// `header` (the first column).
fn run_in_ms(header: &str) -> String {
    let mut s = format!("{header},speed,steer,yaw_rate,ay\n");
    for i in 0..300 {
        s += &format!("{},20,0,0,0\n", i * 10);
    }
    s
}

#[test]
fn a_time_in_ms_under_a_long_name_is_converted_not_only_renamed() {
    for header in ["time [ms]", "time_ms", "Time (ms)", "t_ms"] {
        let dir = scratch(&[("r.csv", &run_in_ms(header))]);
        let o = run_in(dir.path(), &["metrics", "r.csv"]);
        assert!(!o.status.success(), "{header}");
        let e = stderr(&o);
        assert!(
            e.contains(&format!("r.csv:1:1: column `{header}` is `t` in ms, and `t` is read in s (FORMATS.md): convert the values (÷ 1000) and name the column `t` (or `t [s]`): renamed alone, its values would be read as s")),
            "{header}: {e}"
        );
        assert!(!e.contains("did you mean"), "{header}: {e}");
    }
    // In seconds, a renaming is all it takes: said as one.
    let dir = scratch(&[("r.csv", &run_in_ms("time [s]"))]);
    let e = stderr(&run_in(dir.path(), &["metrics", "r.csv"]));
    assert!(e.contains("`time [s]`: did you mean `t`?"), "{e}");
}

/// A lateral sweep at 4000 N (`fz` written as `load`), a tyre of
/// cornering stiffness 16 per unit load peaking at 1.0 of its load, at
/// `pressure` (None: no column).
fn rig(load: &str, pressure: Option<&str>) -> String {
    let p = pressure.map_or(String::new(), |p| format!(",{p}"));
    let head = if pressure.is_some() { ",pressure" } else { "" };
    let mut s = format!("fz,alpha,fy{head}\n");
    for i in -20..=20 {
        let alpha = f64::from(i) * 0.01;
        let fy = 4000.0 * (1.6 * (10.0 * alpha).atan()).sin();
        s += &format!("{load},{alpha},{fy}{p}\n");
    }
    s
}

#[test]
fn loads_in_kn_and_pressures_in_bar_are_refused_at_once() {
    let dir = scratch(&[
        ("both.csv", &rig("4", Some("2.2"))),
        ("bar.csv", &rig("4000", Some("2.2"))),
        ("kn.csv", &rig("4", None)),
        (
            "points.csv",
            "fz,kappa,alpha,camber,speed,pressure\n4,0,0.05,0,20,2.2\n4,0,0.1,0,20,2.2\n",
        ),
        ("tyre.toml", LINEAR_1000_PER_DEG),
    ]);
    let identify = |f: &str| {
        let o = run_in(
            dir.path(),
            &["identify", f, "--model", "pac89", "--out", "x"],
        );
        assert!(!o.status.success(), "{f}");
        stderr(&o)
    };
    let kn = "column `fz`: 4 N, in a file whose median load is 4 N";
    let bar = "column `pressure`: 2.2 Pa, in a file whose median pressure is 2.2 Pa";
    let e = identify("both.csv");
    assert!(e.contains(kn) && e.contains(bar), "{e}");
    // Each alone is said alone.
    let e = identify("bar.csv");
    assert!(e.contains(bar) && !e.contains("column `fz`"), "{e}");
    let e = identify("kn.csv");
    assert!(e.contains(kn) && !e.contains("column `pressure`"), "{e}");
    // The points of `tyre-eval` alike.
    let o = run_in(
        dir.path(),
        &["tyre-eval", "tyre.toml", "points.csv", "--out", "f.csv"],
    );
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("column `fz`: 4 N") && e.contains("column `pressure`: 2.2 Pa"),
        "{e}"
    );
}

#[test]
fn a_tir_far_beyond_its_fnomin_is_said_on_either_axle() {
    let test = "a_tir_far_beyond_its_fnomin_is_said_on_either_axle";
    let Some(fsae) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let Some(book) = shared_data(test, "tir_public/PacejkaBook_Defaults.tir") else {
        return;
    };
    let said = |front: &str, rear: &Path| {
        let sc = format!(
            "{VEHICLE}\n[tyres]\nfront = \"{front}\"\nrear = \"{}\"\n\n{STEP}",
            rear.display()
        );
        let dir = scratch(&[("s.toml", &sc), ("gim.toml", GIM)]);
        let o = run_in(dir.path(), &["simulate", "s.toml", "--out", "out"]);
        assert!(o.status.success(), "{}", stderr(&o));
        format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o))
    };
    // The sedan's rear wheels carry m·g·a/l/2 = 2995 N: 3.00 times the
    // FSAE tyre's FNOMIN of 1000 N, past 2.4.
    let s = said("gim.toml", &fsae);
    let line = s
        .lines()
        .find(|l| l.contains("times the file's FNOMIN"))
        .unwrap_or_else(|| panic!("{s}"));
    assert!(
        line.contains("the rear tyres' .tir: its wheels carry 2995 N each standing still, 3.00 times the file's FNOMIN = 1000 N: a Magic Formula describes its tyre about that load, so this is a tyre for another class of vehicle (a car's wheel carries about 0.6–1.2 of its tyre's FNOMIN, and one beyond 0.3–2.4"),
        "{line}"
    );
    // The book's road tyre (FNOMIN 4000 N) at 0.75: a car's tyre.
    let s = said("gim.toml", &book);
    assert!(!s.contains("times the file's FNOMIN"), "{s}");
}
