//! What a fresh user tripped on in `diagnose`, run as
//! a user runs the tool: a logged roll left out of the gap in silence;
//! `--batch` handed a campaign folder (two "failed" campaigns, exit 0) or
//! a file ("Not a directory"), and a fleet whose count took failures for
//! diagnoses; a glob in `[runs] files` answered with a `dir` that reads
//! more runs, a glob in `dir` answered "does not exist", and a run listed
//! twice said with one path twice.

use super::*;

/// The bundled sedan's `[vehicle]` table.
const SEDAN: &str = "[vehicle]\nmass = 1530\nyaw_inertia = 2315\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";

/// A synthetic handling campaign (rig data, 8 runs at 100 Hz) in `dir/c`.
fn handling_campaign(dir: &Path) -> PathBuf {
    synth_campaign(dir, "c", &["--seed", "1"])
}

/// A campaign file `dir/<name>.toml` of the sedan with `runs` as its
/// `[runs]` table's body (line 10 is the table's first key).
fn campaign_file(dir: &Path, name: &str, runs: &str) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{SEDAN}[runs]\n{runs}")).unwrap();
    path
}

/// A logged roll (declared in degrees) was read and compared with
/// nothing, and the report never said so: a note names what it is used
/// for.
#[test]
fn a_logged_roll_is_said_to_be_left_out_of_the_gap() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    // A roll column, in degrees, on every run: 0.3° per m/s² of ay.
    for e in fs::read_dir(c.join("runs")).unwrap() {
        let p = e.unwrap().path();
        let text = fs::read_to_string(&p).unwrap();
        let mut lines = text.lines();
        let head = lines.next().unwrap();
        let ay = head.split(',').position(|h| h == "ay").unwrap();
        let mut out = format!("{head},roll\n");
        for l in lines {
            let v: f64 = l.split(',').nth(ay).unwrap().parse().unwrap();
            out.push_str(&format!("{l},{:.5}\n", 0.3 * v));
        }
        fs::write(&p, out).unwrap();
    }
    // One candidate keeps the run short; synth's vehicle.toml ends in its
    // [diagnose] table.
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(
        &v,
        format!("{text}effects = [\"sensor_bias\"]\n\n[runs]\ndegrees = [\"roll\"]\n"),
    )
    .unwrap();
    let (stdout, d) = diagnose(&c);
    // Since session 98 the roll levels ay (`trips_s98_real28`).
    let said = "roll: logged in 8 of 8 runs, converted from the degrees `degrees` under [runs] declares: ay levelled by it before every fit";
    assert!(stdout.contains(&format!("note: {said}")), "{stdout}");
    assert!(d.to_string().contains(said), "{d}");
}

/// `diagnose --batch` on a campaign folder diagnosed its `runs/` and its
/// `vehicle.toml` as two campaigns, both failed, and exited 0; on a file
/// it said "Not a directory": each is named, with the command to run.
#[test]
fn batch_is_refused_a_campaign_folder_and_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    let out = dir.path().join("out");
    let batch = |what: &Path| {
        let o = run(&[
            "diagnose",
            "--batch",
            what.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success(), "expected failure");
        assert!(!out.exists(), "a refused batch must not leave outputs");
        stderr(&o)
    };
    let e = batch(&c);
    assert!(
        e.contains(&format!("{}: --batch reads a folder of campaigns (its sub-folders and .toml files), and this folder is itself one campaign (vehicle.toml and runs/): drop --batch to diagnose it, `handling diagnose {}`", c.display(), c.display())),
        "{e}"
    );
    let v = c.join("vehicle.toml");
    let e = batch(&v);
    assert!(
        e.contains(&format!("{}: --batch reads a folder of campaigns (its sub-folders and .toml files), and this is a file: drop --batch to diagnose it, `handling diagnose {}`", v.display(), v.display())),
        "{e}"
    );
    assert!(!e.contains("Not a directory"), "{e}");
}

/// A fleet counted a failed campaign among the campaigns ("2 campaigns: 0
/// diagnosed, 2 failed") and exited 0 when nothing was diagnosed: it says
/// how many of how many were diagnosed, and a batch that diagnosed
/// nothing fails after writing the table of why.
#[test]
fn a_batch_that_diagnoses_nothing_fails_after_its_table() {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("batch");
    fs::create_dir_all(&batch).unwrap();
    // Two campaigns whose runs do not exist.
    for name in ["a", "b"] {
        campaign_file(&batch, name, "dir = \"nowhere\"\n");
    }
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        "--batch",
        batch.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "a batch that diagnosed nothing failed");
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("fleet: 0 of 2 campaigns diagnosed, 2 failed (each one's reason below)"),
        "{said}"
    );
    assert!(said.contains(&format!("{:<24} FAILED: ", "a")), "{said}");
    let e = stderr(&o);
    let table = out.join("fleet.csv");
    assert!(
        e.contains(&format!("{}: none of its 2 campaigns could be diagnosed (each one's reason is listed above and in {}): no fleet to compare", batch.display(), table.display())),
        "{e}"
    );
    assert!(table.is_file());
}

/// `files = ["runs/step_1*.csv"]` was answered "give it as `dir =
/// \"runs\"` instead", which reads every run, not the three it meant: a
/// pattern that matches some of the folder is answered with the list of
/// what it matches; one that matches the folder's runs with `dir`, the
/// same runs.
#[test]
fn a_glob_in_the_run_files_is_answered_with_what_selects_the_same_runs() {
    let dir = tempfile::tempdir().unwrap();
    handling_campaign(dir.path());
    let some = campaign_file(dir.path(), "some", "files = [\"c/runs/step_1*.csv\"]\n");
    let e = fails_cleanly("diagnose", &some, dir.path());
    assert!(
        e.contains("some.toml:10:10: `runs.files` = \"c/runs/step_1*.csv\": the list names files as written, not a pattern (no file is named so): it matches 3 of the folder's 8 *.csv files: list them, `files = [\"c/runs/step_100kph_2ms2.csv\", \"c/runs/step_100kph_6ms2.csv\", \"c/runs/step_120kph_4ms2.csv\"]` (`dir = \"c/runs\"` would read all 8)"),
        "{e}"
    );
    let all = campaign_file(dir.path(), "all", "files = [\"c/runs/*.csv\"]\n");
    let e = fails_cleanly("diagnose", &all, dir.path());
    assert!(
        e.contains("all.toml:10:10: `runs.files` = \"c/runs/*.csv\": the list names files as written, not a pattern (no file is named so): to read every *.csv of a folder, give it as `dir = \"c/runs\"` instead, which reads the same 8 files"),
        "{e}"
    );
    let none = campaign_file(dir.path(), "none", "files = [\"c/runs/x*.csv\"]\n");
    let e = fails_cleanly("diagnose", &none, dir.path());
    assert!(
        e.contains("none.toml:10:10: `runs.files` = \"c/runs/x*.csv\": the list names files as written, not a pattern (no file is named so): no file of `c/runs` matches it: list the runs by name under `files` (`dir = \"c/runs\"` reads all 8 *.csv files of the folder)"),
        "{e}"
    );
}

/// `dir = "runs/*.csv"` was answered "names …/runs/*.csv, which does not
/// exist": a folder is named by `dir`, and the answer selects the same
/// runs.
#[test]
fn a_glob_in_the_runs_folder_is_answered_with_the_folder() {
    let dir = tempfile::tempdir().unwrap();
    handling_campaign(dir.path());
    let all = campaign_file(dir.path(), "all", "dir = \"c/runs/*.csv\"\n");
    let e = fails_cleanly("diagnose", &all, dir.path());
    assert!(
        e.contains("all.toml:10:7: `runs.dir` = \"c/runs/*.csv\" names a folder, not a pattern (no folder is named so): give the folder, `dir = \"c/runs\"`, which reads its *.csv files, the same 8"),
        "{e}"
    );
    assert!(!e.contains("does not exist"), "{e}");
    let one = campaign_file(dir.path(), "one", "dir = \"c/runs/sweep*\"\n");
    let e = fails_cleanly("diagnose", &one, dir.path());
    assert!(
        e.contains("one.toml:10:7: `runs.dir` = \"c/runs/sweep*\" names a folder, not a pattern (no folder is named so): it matches 1 of the folder's 8 *.csv files: list it, `files = [\"c/runs/sweep_080kph.csv\"]` (`dir = \"c/runs\"` would read all 8)"),
        "{e}"
    );
    let folders = campaign_file(dir.path(), "folders", "dir = \"c*/runs\"\n");
    let e = fails_cleanly("diagnose", &folders, dir.path());
    assert!(
        e.contains("folders.toml:10:7: `runs.dir` = \"c*/runs\" names a folder, not a pattern (no folder is named so): a wildcard in a folder's name is not expanded: list the runs by name under `files`"),
        "{e}"
    );
}

/// A run selected by `files` and again by `dir` was said "the run
/// c/runs/sweep_080kph.csv is listed twice (as c/runs/sweep_080kph.csv
/// too)": each entry that selects it is named with its line and column.
#[test]
fn a_run_selected_twice_names_both_entries_where_they_are() {
    let dir = tempfile::tempdir().unwrap();
    handling_campaign(dir.path());
    let both = campaign_file(
        dir.path(),
        "both",
        "dir = \"c/runs\"\nfiles = [\"c/runs/sweep_080kph.csv\"]\n",
    );
    let e = fails_cleanly("diagnose", &both, dir.path());
    let at = both.display();
    let run = dir.path().join("c/runs/sweep_080kph.csv");
    let run = run.display();
    assert!(
        e.contains(&format!("both.toml:11:10: the run {run} is listed twice: by `runs.files[0]` = \"c/runs/sweep_080kph.csv\" ({at}:11:10) and by `runs.dir` = \"c/runs\" ({at}:10:7), which reads every *.csv of the folder: each run is held out once, so select it once")),
        "{e}"
    );
    let twice = campaign_file(
        dir.path(),
        "twice",
        "files = [\"c/runs/sweep_080kph.csv\", \"c/./runs/sweep_080kph.csv\"]\n",
    );
    let e = fails_cleanly("diagnose", &twice, dir.path());
    let at = twice.display();
    let run = dir.path().join("c/runs/sweep_080kph.csv");
    let run = run.display();
    assert!(
        e.contains(&format!("twice.toml:10:37: the run {run} is listed twice: by `runs.files[0]` = \"c/runs/sweep_080kph.csv\" ({at}:10:10) and by `runs.files[1]` = \"c/./runs/sweep_080kph.csv\" ({at}:10:37)")),
        "{e}"
    );
}

/// A yaw-rate offset of -4.6e-5 ± 1.4e-4 rad/s at a standstill was said
/// "-0.0000 ± 0.0001 rad/s", an offset below zero the digits do not show.
/// Its error, led by a 1, now keeps two digits, and the value is said to
/// the same place: a sign only where a digit shows it.
#[test]
fn an_offset_within_its_error_of_zero_is_never_a_signed_zero() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "so", &["--programme", "slow-oval"]);
    // The standstill's yaw-rate offset is 5.4e-5 rad/s as synthesised:
    // 1e-4 less makes it -4.6e-5, within its ± 1.4e-4 of zero.
    for e in fs::read_dir(c.join("runs")).unwrap() {
        let p = e.unwrap().path();
        let text = fs::read_to_string(&p).unwrap();
        let mut lines = text.lines();
        let head = lines.next().unwrap();
        let r = head.split(',').position(|h| h == "yaw_rate").unwrap();
        let mut out = format!("{head}\n");
        for l in lines {
            let mut v: Vec<String> = l.split(',').map(str::to_string).collect();
            let y: f64 = v[r].parse().unwrap();
            v[r] = format!("{}", y - 1e-4);
            out.push_str(&v.join(","));
            out.push('\n');
        }
        fs::write(&p, out).unwrap();
    }
    // One candidate keeps the run short; synth's vehicle.toml ends in its
    // [diagnose] table.
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}effects = [\"sensor_bias\"]\n")).unwrap();
    let (stdout, d) = diagnose(&c);
    let mean = d["calibration"]["channels"][0]["standstill"]["mean"]
        .as_f64()
        .unwrap();
    assert!((-5e-5..-4e-5).contains(&mean), "{mean}");
    assert!(
        stdout.contains(
            "calibration: yaw_rate offset -0.00005 ± 0.00014 rad/s at 1 standstill (18 s)"
        ),
        "{stdout}"
    );
    assert!(!stdout.contains("-0.0000 "), "{stdout}");
}
