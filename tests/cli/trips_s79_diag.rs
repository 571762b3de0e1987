//! What a fresh user tripped on in `diagnose` and its measured data, run
//! as a user runs the tool: a tyre model named with no rig data to fit it
//! to passed over in silence, a stated uncertainty of 1e-6 printed as
//! "0.0000", a held channel's rate said in samples alone, batch outputs
//! named `a.toml/`, a glob in `[runs] files` answered "does not exist", a
//! CSV, a `.tir` or a scenario given as a campaign answered with the TOML
//! reader's words, `min_speed = 200` taken, and a segment's noise floor
//! taken from its turning.

use super::*;

/// The bundled sedan's `[vehicle]` table.
const VEHICLE: &str = "[vehicle]\nmass = 1530\nyaw_inertia = 2315\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";

/// A synthetic handling campaign (rig data, 100 Hz runs) in `dir/c`.
fn handling_campaign(dir: &Path) -> PathBuf {
    synth_campaign(dir, "c", &["--seed", "1"])
}

/// A campaign file `dir/<name>.toml` of the sedan with `rest` after its
/// `[vehicle]` table.
fn campaign_file(dir: &Path, name: &str, rest: &str) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{VEHICLE}\n{rest}")).unwrap();
    path
}

/// `[tyres] model = "pac89"` beside tyre files, or beside no tyre data at
/// all, was passed over in silence (the files' own model used, or the
/// axles identified from the runs): refused at the key, saying why.
#[test]
fn a_tyre_model_without_rig_data_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    let runs = c.join("runs");
    let runs = runs.to_str().unwrap();
    let tyre = root().join("tyres/gim_sedan_front.toml");
    let files = campaign_file(
        dir.path(),
        "files",
        &format!(
            "[tyres]\nfile = \"{}\"\nmodel = \"pac89\"\n\n[runs]\ndir = \"{runs}\"\n",
            tyre.display()
        ),
    );
    let e = fails_cleanly("diagnose", &files, dir.path());
    assert!(
        e.contains("files.toml:12:9: `tyres.model`: `pac89` names a model to fit to rig data, but the campaign gives none: its tyres are read from the tyre files given, whose own model is used; leave `model` out, or give `rig = \"tyre_rig.csv\"` instead of the files to fit one"),
        "{e}"
    );
    let none = campaign_file(
        dir.path(),
        "none",
        &format!("[tyres]\nmodel = \"pac89\"\n\n[runs]\ndir = \"{runs}\"\n"),
    );
    let e = fails_cleanly("diagnose", &none, dir.path());
    assert!(
        e.contains("none.toml:11:9: `tyres.model`: `pac89` names a model to fit to rig data, but the campaign gives none: without tyre data the axles are identified from the runs"),
        "{e}"
    );
}

/// `[channels] yaw_rate = 1e-6` was said as "yaw_rate 0.0000 rad/s
/// (stated)", a channel trusted to nothing; and a sensor floor's scatter
/// as "scatter 4.10e-4", without its unit.
#[test]
fn a_tiny_stated_uncertainty_is_printed_with_its_digits() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}\n[channels]\nyaw_rate = 1e-6\n")).unwrap();
    let (stdout, _) = diagnose(&c);
    assert!(stdout.contains("yaw_rate 1e-6 rad/s (stated)"), "{stdout}");
    assert!(!stdout.contains("0.0000 rad/s (stated)"), "{stdout}");
}

/// A sideslip logged at 20 Hz in a 100 Hz log was said to update "every 5
/// samples (20.0 Hz)": said against the log's rate, in time, and the log's
/// rate in the JSON.
#[test]
fn a_held_channel_is_said_against_the_logs_rate() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    let run = c.join("runs/ramp_080kph.csv");
    let text = fs::read_to_string(&run).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut held = String::new();
    for (k, line) in lines.iter_mut().enumerate().skip(1) {
        let (head, beta) = line.rsplit_once(',').unwrap();
        if (k - 1) % 5 == 0 {
            held = beta.to_string();
        }
        *line = format!("{head},{held}");
    }
    fs::write(&run, lines.join("\n") + "\n").unwrap();
    let (stdout, d) = diagnose(&c);
    assert!(
        stdout.contains("updates every 5 samples of the 100 Hz log (every 0.05 s, 20 Hz): "),
        "{stdout}"
    );
    let h = &d["cleaning"]["held"][0];
    assert_eq!(h["channel"], "beta", "{h}");
    assert!(
        (h["log_rate"].as_f64().unwrap() - 100.0).abs() < 1e-9,
        "{h}"
    );
}

/// `diagnose --batch` wrote a campaign file `a.toml` into `out/a.toml/`, a
/// folder named as a file, and said "fleet: 2 campaigns (0 failed)": the
/// folder is the file's stem, the line says how many were diagnosed; a
/// folder `a/` beside a file `a.toml` is refused, their outputs one.
#[test]
fn a_batch_names_each_output_by_its_stem_and_counts_the_diagnosed() {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("batch");
    let c = synth_campaign(&batch, "b", &["--seed", "1"]);
    let runs = c.join("runs");
    let rig = c.join("tyre_rig.csv");
    campaign_file(
        &batch,
        "a",
        &format!(
            "[tyres]\nrig = \"{}\"\n\n[runs]\ndir = \"{}\"\n",
            rig.display(),
            runs.display()
        ),
    );
    let out = dir.path().join("out");
    let said = succeeds(&[
        "diagnose",
        "--batch",
        batch.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        said.contains("fleet: 2 of 2 campaigns diagnosed\n"),
        "{said}"
    );
    assert!(out.join("a/diagnosis.json").is_file());
    assert!(out.join("b/diagnosis.json").is_file());
    assert!(!out.join("a.toml").exists());
    // A folder `a/` beside `a.toml`.
    copy_dir(&c, &batch.join("a"));
    let o = run(&[
        "diagnose",
        "--batch",
        batch.to_str().unwrap(),
        "--out",
        dir.path().join("out2").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("the campaigns `a` and `a.toml` would both write to `a/` of the output folder: rename one"),
        "{e}"
    );
}

/// Copies folder `from` (files and one level of sub-folders) to `to`.
fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for e in fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        let target = to.join(p.file_name().unwrap());
        if p.is_dir() {
            copy_dir(&p, &target);
        } else {
            fs::copy(&p, &target).unwrap();
        }
    }
}

/// `[runs] files = ["runs/*.csv"]` was answered "names …/runs/*.csv,
/// which does not exist": a list names files, `dir` reads a folder.
#[test]
fn a_glob_in_the_run_files_is_answered_with_dir() {
    let dir = tempfile::tempdir().unwrap();
    handling_campaign(dir.path());
    let g = campaign_file(dir.path(), "g", "[runs]\nfiles = [\"c/runs/*.csv\"]\n");
    let e = fails_cleanly("diagnose", &g, dir.path());
    assert!(
        e.contains("g.toml:11:10: `runs.files` = \"c/runs/*.csv\": the list names files as written, not a pattern (no file is named so): to read every *.csv of a folder, give it as `dir = \"c/runs\"` instead"),
        "{e}"
    );
}

/// A run's CSV, a `.tir` and a scenario given to `diagnose` were answered
/// "expected `.`, `=`" and "unknown field `manoeuvre`": each is named as
/// what it is.
#[test]
fn the_wrong_kind_of_file_is_named_as_what_it_is() {
    let dir = tempfile::tempdir().unwrap();
    let c = handling_campaign(dir.path());
    let csv = c.join("runs/ramp_080kph.csv");
    let e = fails_cleanly("diagnose", &csv, dir.path());
    assert!(
        e.contains("ramp_080kph.csv: this is a CSV file (a measured run or rig data), not a campaign: list it under the campaign's [runs] files, or put it in its runs/ folder: `handling diagnose` reads a campaign"),
        "{e}"
    );
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let e = fails_cleanly("diagnose", &tir, dir.path());
    assert!(
        e.contains(
            "MagicFormula61_Parameters.tir: this is a tyre property file (.tir), not a campaign"
        ),
        "{e}"
    );
    let scenario = root().join("scenarios/sedan_step.toml");
    let e = fails_cleanly("diagnose", &scenario, dir.path());
    assert!(
        e.contains("sedan_step.toml: this is a scenario (it has a [manoeuvre]), which `handling simulate` runs, not a campaign"),
        "{e}"
    );
    assert!(!e.contains("unknown field"), "{e}");
}

/// `[diagnose] min_speed = 200` (a speed in km/h, or a slip) was taken,
/// every sample excluded as slow, and the runs blamed: refused at its
/// line, with the value in km/h converted.
#[test]
fn an_absurd_min_speed_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    handling_campaign(dir.path());
    let s = campaign_file(
        dir.path(),
        "s",
        "[runs]\ndir = \"c/runs\"\n\n[diagnose]\nmin_speed = 200\n",
    );
    let e = fails_cleanly("diagnose", &s, dir.path());
    assert!(
        e.contains("s.toml:14:13: `diagnose.min_speed` = 200: must lie in [0, 100]: it is the speed in m/s below which samples are left out as slow, and no car's handling log is measured above 100 m/s (360 km/h); the key is in m/s: is it in km/h? 200 km/h is 55.6 m/s: write `min_speed = 55.6`"),
        "{e}"
    );
}

/// The slow oval's 20 s segments have no quiet window before an input:
/// their yaw-rate scatter was the first differences' deviation over √2,
/// which holds the laps' own turning (trusted to 0.0034 rad/s); the robust
/// second differences see the gyro's noise alone.
#[test]
fn a_segment_without_a_window_takes_its_noise_from_the_second_differences() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "oval", &["--programme", "slow-oval"]);
    let (stdout, _) = diagnose(&c);
    assert!(
        stdout.contains("channels trusted to: yaw_rate 0.0030 rad/s (its scatter); beta 0.0020 rad (its scatter)"),
        "{stdout}"
    );
}
