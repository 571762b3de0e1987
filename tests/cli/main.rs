//! The one integration test binary: runs the `handling` CLI on the bundled
//! scenarios and on broken inputs, and checks what a user sees.

pub(crate) use std::fs;
pub(crate) use std::path::{Path, PathBuf};
pub(crate) use std::process::{Command, Output};

#[path = "../support/folders.rs"]
mod folders;
#[path = "../support/memo.rs"]
mod memo;
use folders::copy_folder;
use memo::Memo;

pub(crate) fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_handling"))
}

pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub(crate) fn run(args: &[&str]) -> Output {
    bin().args(args).current_dir(root()).output().expect("runs")
}

/// Runs the binary in `dir`.
pub(crate) fn run_in(dir: &Path, args: &[&str]) -> Output {
    bin().args(args).current_dir(dir).output().unwrap()
}

/// Says on the terminal that a test skipped itself: written to the process's
/// stderr directly, past the test harness's capture of `eprintln!`.
fn skipped(test: &str, missing: &Path) {
    use std::io::Write;
    let _ = writeln!(
        std::io::stderr().lock(),
        "SKIPPED {test}: {} is absent (the public data sets are looked for in shared/data beside the checkout)",
        missing.display()
    );
}

/// What a test that reads a public data set does when the set is missing.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum MissingData {
    /// Say so on the terminal and pass: a developer's checkout without the data.
    Skip,
    /// Fail: under CI the data are part of the environment, and a test that
    /// skips there would hide a broken set-up.
    Fail,
}

/// The decision, from the value of the environment variable `CI`: set to
/// anything but an empty string, `0` or `false`, it is CI.
pub(crate) fn on_missing_data(ci: Option<&std::ffi::OsStr>) -> MissingData {
    match ci.and_then(|v| v.to_str()) {
        Some(v) if !v.is_empty() && v != "0" && !v.eq_ignore_ascii_case("false") => {
            MissingData::Fail
        }
        // A value that is not UTF-8 is set, and not a "no".
        None if ci.is_some() => MissingData::Fail,
        _ => MissingData::Skip,
    }
}

/// The file `relative` of the public data sets (`shared/data/` beside the
/// checkout), or `None` after saying that `test` skips, when it is absent
/// outside CI. Under CI a missing file fails the test.
pub(crate) fn shared_data(test: &str, relative: &str) -> Option<PathBuf> {
    let ci = std::env::var_os("CI");
    data_file(
        &root().join("../shared/data"),
        relative,
        test,
        ci.as_deref(),
    )
}

/// `dir/relative` when it is a file; else, by [`on_missing_data`] for the
/// value `ci` of `CI`, `None` (skip) or a panic (fail).
fn data_file(
    dir: &Path,
    relative: &str,
    test: &str,
    ci: Option<&std::ffi::OsStr>,
) -> Option<PathBuf> {
    let path = dir.join(relative);
    if path.is_file() {
        return Some(path);
    }
    // A path that is there but no file (a folder named where its file was
    // meant) is the test's mistake, not missing data: refused on every
    // run, not skipped where the data sets are absent.
    if path.exists() {
        panic!(
            "{test}: {} exists but is not a file (a folder?): name a file of the public data sets",
            path.display()
        );
    }
    match on_missing_data(ci) {
        MissingData::Fail => panic!(
            "{test}: {} is absent and CI is set: under CI the public data sets must be present",
            path.display()
        ),
        MissingData::Skip => {
            skipped(test, &path);
            None
        }
    }
}

#[test]
fn missing_data_skips_outside_ci_and_fails_under_it() {
    use std::ffi::OsStr;
    assert_eq!(on_missing_data(None), MissingData::Skip);
    for no in ["", "0", "false", "FALSE"] {
        assert_eq!(
            on_missing_data(Some(OsStr::new(no))),
            MissingData::Skip,
            "{no:?}"
        );
    }
    for yes in ["true", "1", "yes", "TRUE"] {
        assert_eq!(
            on_missing_data(Some(OsStr::new(yes))),
            MissingData::Fail,
            "{yes:?}"
        );
    }
    let dir = scratch(&[("present.csv", "t\n")]);
    let ci = Some(OsStr::new("true"));
    // Present: returned, in CI or not.
    for ci in [None, ci] {
        let found = data_file(dir.path(), "present.csv", "t", ci);
        assert_eq!(found, Some(dir.path().join("present.csv")));
    }
    // Absent: skipped outside CI, a failure under it.
    assert_eq!(data_file(dir.path(), "absent.csv", "t", None), None);
    let failed = std::panic::catch_unwind(|| data_file(dir.path(), "absent.csv", "t", ci));
    let message = failed.expect_err("a missing data set fails under CI");
    let message = message.downcast_ref::<String>().unwrap();
    assert!(
        message.contains("absent.csv is absent and CI is set"),
        "{message}"
    );
    // A folder where a file is named: refused in CI or not.
    std::fs::create_dir(dir.path().join("folder")).unwrap();
    for ci in [None, ci] {
        let failed = std::panic::catch_unwind(|| data_file(dir.path(), "folder", "t", ci));
        let message = failed.expect_err("a folder is refused");
        let message = message.downcast_ref::<String>().unwrap();
        assert!(message.contains("exists but is not a file"), "{message}");
    }
}

/// Runs the binary with `args`, asserts it succeeds; its stdout.
pub(crate) fn succeeds(args: &[&str]) -> String {
    let o = run(args);
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub(crate) fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `text` as the report page writes it (`report::html::escape`), to find
/// a terminal line on the page.
pub(crate) fn escaped(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&#39;")
}

/// The stage `name` of a staged Magic Formula fit's report.
pub(crate) fn stage<'a>(report: &'a serde_json::Value, name: &str) -> &'a serde_json::Value {
    report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["stage"] == name)
        .unwrap_or_else(|| panic!("no stage {name}: {report}"))
}

/// The value of `key` in a `.tir` text (its comment after `$` dropped).
pub(crate) fn tir_value(text: &str, key: &str) -> f64 {
    text.lines()
        .find_map(|l| {
            let (k, v) = l.split_once('=')?;
            (k.trim() == key).then(|| v.split('$').next().unwrap().trim().parse().unwrap())
        })
        .unwrap_or_else(|| panic!("{key}: {text}"))
}

/// The noise-free forces and moments `tyre-eval` gives of `tir` over the
/// book's grid (`docs/examples/mf_grid.csv`), written to `dir/grid_rig.csv`:
/// a rig file `identify` reads.
pub(crate) fn grid_rig(tir: &Path, dir: &Path) -> PathBuf {
    let rig = dir.join("grid_rig.csv");
    let grid = root().join("docs/examples/mf_grid.csv");
    succeeds(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        grid.to_str().unwrap(),
        "--out",
        rig.to_str().unwrap(),
    ]);
    rig
}

/// Maps every value of column `name` (its header names it) of the CSV
/// file at `path` by `f`: a sensor's offset, sign or gain slipped in.
pub(crate) fn map_column(path: &Path, name: &str, f: impl Fn(f64) -> f64) {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let k = header.split(',').position(|c| c == name).unwrap();
    let mut out = format!("{header}\n");
    for l in lines {
        let mut cells: Vec<String> = l.split(',').map(str::to_string).collect();
        cells[k] = format!("{}", f(cells[k].parse::<f64>().unwrap()));
        out += &(cells.join(",") + "\n");
    }
    fs::write(path, out).unwrap();
}

/// Writes the log `csv` to `dir/run.csv` and a scenario replaying it on
/// [`VEHICLE`] with `dir/tyre.toml` on both axles, `dir/replay.toml`.
pub(crate) fn replay_of(dir: &Path, csv: &str) -> PathBuf {
    fs::write(dir.join("run.csv"), csv).unwrap();
    let scenario = dir.join("replay.toml");
    fs::write(
        &scenario,
        format!("name = \"replay\"\n{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n"),
    )
    .unwrap();
    scenario
}

/// `said` with every temporary directory's random name (`.tmpXXXXXX`,
/// tempfile's six letters) replaced by `.tmp`: a test that says a word
/// is absent must not fail because the random name spells it (CI once
/// drew `.tmphlp0zV`, which holds "mph").
pub(crate) fn without_temp_names(said: &str) -> String {
    let mut out = String::with_capacity(said.len());
    let mut rest = said;
    while let Some(at) = rest.find("/.tmp") {
        out.push_str(&rest[..at + 5]);
        rest = &rest[at + 5..];
        let name = rest
            .char_indices()
            .take_while(|(_, c)| c.is_ascii_alphanumeric())
            .count();
        rest = &rest[name..];
    }
    out.push_str(rest);
    out
}

#[test]
fn a_temporary_directorys_random_name_is_not_read_as_words() {
    let said = "error: /tmp/.tmphlp0zV/c/runs/run.csv:2:6: is `speed` in m/s?";
    let plain = without_temp_names(said);
    assert_eq!(
        plain,
        "error: /tmp/.tmp/c/runs/run.csv:2:6: is `speed` in m/s?"
    );
    assert!(said.contains("mph") && !plain.contains("mph"));
}

/// Parses a JSON output file.
pub(crate) fn read_json(p: &Path) -> serde_json::Value {
    serde_json::from_str(&fs::read_to_string(p).unwrap()).unwrap()
}

/// Writes `files` into a fresh folder and returns it.
/// The bundled racing-log campaign (`campaigns/putnam.toml`) reading the
/// log at `log`, with `diagnose` (TOML lines: the candidates, their count)
/// added under its `[diagnose]` table.
pub(crate) fn putnam_campaign(log: &Path, diagnose: &str) -> String {
    fs::read_to_string(root().join("campaigns/putnam.toml"))
        .unwrap()
        .replace(
            "\"../../shared/data/run_iac_putnam/putnam_run4_2.csv\"",
            &format!("{:?}", log.to_str().unwrap()),
        )
        .replace(
            "[diagnose]\nseed = 1",
            &format!("[diagnose]\nseed = 1\n{diagnose}"),
        )
}

/// The text of the bundled scenario `scenarios/<name>` with its tyre
/// paths made absolute, so that it runs from any folder it is copied to.
pub(crate) fn bundled_scenario(name: &str) -> String {
    let text = fs::read_to_string(root().join("scenarios").join(name)).unwrap();
    let tyres = format!("\"{}/", root().join("tyres").display());
    text.replace("\"../tyres/", &tyres)
}

pub(crate) fn scratch(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

pub(crate) const VEHICLE: &str = "[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";
pub(crate) const GIM: &str =
    "model = \"gim\"\ncornering_stiffness = 57296.0\ncontact_length = 0.18\n";
pub(crate) const STEP: &str =
    "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\n";

/// The `[model]` table of the linear bicycle: small-angle kinematics and
/// no load transfer, where its closed forms hold.
pub(crate) const SMALL_ANGLE: &str =
    "[model]\nkinematics = \"small-angle\"\nload_transfer = false\n";
/// A linear tyre of 57 296 N/rad (1000 N/deg) per wheel.
pub(crate) const LINEAR_1000_PER_DEG: &str = "model = \"linear\"\ncornering_stiffness = 57296.0\n";

/// The sedan of [`VEHICLE`] on the tyre file `tyre` at both axles with
/// [`SMALL_ANGLE`]: the head of a scenario, sweep or study file on the
/// linear bicycle model.
pub(crate) fn linear_sedan(tyre: &str) -> String {
    format!("{VEHICLE}[tyres]\nfront = \"{tyre}\"\n{SMALL_ANGLE}")
}

/// [`linear_sedan`] with `a` and `b` swapped (1.67 m and 1.11 m): the
/// same car with its mass rearward, oversteering.
pub(crate) fn rearward_sedan(tyre: &str) -> String {
    linear_sedan(tyre).replace("a = 1.11\nb = 1.67\n", "a = 1.67\nb = 1.11\n")
}

pub(crate) fn scenario(vehicle: &str, tyre: &str, manoeuvre: &str) -> tempfile::TempDir {
    let sc = format!("{vehicle}\n[tyres]\nfront = \"tyre.toml\"\n\n{manoeuvre}");
    scratch(&[("scenario.toml", &sc), ("tyre.toml", tyre)])
}

/// Runs `command input --out dir/out`, expects it to fail without leaving
/// outputs, and returns its stderr.
pub(crate) fn fails_cleanly(command: &str, input: &Path, dir: &Path) -> String {
    let o = run(&[
        command,
        input.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "expected failure");
    assert!(
        !dir.join("out").exists(),
        "a failed run must not leave outputs"
    );
    stderr(&o)
}

/// The entries of an identify report's `held` list held because the data
/// do not determine them (`why = "undetermined"`).
pub(crate) fn undetermined_holds(report: &serde_json::Value) -> Vec<&serde_json::Value> {
    report["held"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|h| h["why"] == "undetermined")
        .collect()
}

/// Runs `identify rig --model model --out out`.
pub(crate) fn identify_to(rig: &Path, model: &str, out: &Path) -> Output {
    identify_with(rig, model, &[], out)
}

/// Runs `identify rig --model model <args> --out out` (`args` such as
/// `--bin-deg 0`).
pub(crate) fn identify_with(rig: &Path, model: &str, args: &[&str], out: &Path) -> Output {
    let mut all = vec!["identify", rig.to_str().unwrap(), "--model", model];
    all.extend_from_slice(args);
    all.extend(["--out", out.to_str().unwrap()]);
    run(&all)
}

/// MFeval's MF 6.1 sample file (the test fixtures').
pub(crate) fn mf61_fixture() -> PathBuf {
    root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
}

/// The forces and moments of [`mf61_fixture`] at the points of the CSV
/// `points`, written by `tyre-eval` to `out` (a rig file `identify`
/// reads): the run must succeed.
pub(crate) fn mf61_evaluated(points: &Path, out: &Path) {
    let tir = mf61_fixture();
    succeeds(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
}

/// Writes `text` to `dir/name`; its path.
pub(crate) fn written(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// The linear car of [`scenarios::simulated_rows`] stepped 0.01 rad at
/// 30 m/s from 1 s to `end` s, rows every 0.01 s, logged as
/// `t,speed,steer,yaw_rate,ay,beta` with each row's errors
/// `[yaw rate, ay, sideslip] = errors(noise)` added (drawn in the order
/// the closure draws them, so a seed's log stays the same), and a
/// scenario replaying it ([`replay_of`]): the scenario's path.
pub(crate) fn noisy_step_replay(
    dir: &Path,
    end: f64,
    mut noise: calibration::Noise,
    mut errors: impl FnMut(&mut calibration::Noise) -> [f64; 3],
) -> PathBuf {
    let manoeuvre = format!(
        "kind = \"step-steer\"\nspeed = 30.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = {end:.1}\n"
    );
    let rows = scenarios::simulated_rows(dir, "step", &manoeuvre);
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for c in rows.iter().filter(|c| c[0] < end - 0.005) {
        let [r, ay, beta] = errors(&mut noise);
        csv += &format!(
            "{:.2},{:.6},{:.6},{:.6},{:.6},{:.7}\n",
            c[0],
            c[2],
            c[1],
            c[4] + r,
            c[5] + ay,
            c[3] + beta
        );
    }
    replay_of(dir, &csv)
}

/// The public Hoosier cornering file fitted by `identify --model pac89`
/// (its default seed), once for every test that reads that fit: the fit
/// takes about 45 s of both cores, and the tests that check what it
/// writes, holds and says need the same run.
pub(crate) struct HoosierPac89 {
    /// What the terminal said.
    pub(crate) stdout: String,
    /// The tyre file written (its report beside it, `*.report.json`).
    pub(crate) tyre: PathBuf,
}

/// [`HoosierPac89`], fitted by the first test that asks into the test
/// run's own scratch folder; `None` where [`shared_data`] skips `test`.
pub(crate) fn hoosier_pac89(test: &str) -> Option<&'static HoosierPac89> {
    static FIT: std::sync::OnceLock<HoosierPac89> = std::sync::OnceLock::new();
    let rig = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    Some(FIT.get_or_init(|| {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("hoosier_pac89");
        fs::create_dir_all(&dir).unwrap();
        let tyre = dir.join("hoosier_pac89.toml");
        let o = identify_to(&rig, "pac89", &tyre);
        assert!(o.status.success(), "{}", stderr(&o));
        HoosierPac89 {
            stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
            tyre,
        }
    }))
}

/// The public Hoosier cornering file fitted by `identify --model mf61`
/// with its defaults, once for every test that reads that fit (four ran
/// the same command, about 15 s of both cores each).
pub(crate) struct HoosierMf61 {
    /// What the terminal said.
    pub(crate) stdout: String,
    /// Its warnings.
    pub(crate) stderr: String,
    /// The rig file fitted.
    pub(crate) rig: PathBuf,
    /// The `.tir` written (its report and figures beside it:
    /// `*.report.json`, `*.pure-fy.png`).
    pub(crate) tir: PathBuf,
}

/// [`HoosierMf61`], fitted by the first test that asks into the test
/// run's own scratch folder; `None` where [`shared_data`] skips `test`.
pub(crate) fn hoosier_mf61(test: &str) -> Option<&'static HoosierMf61> {
    static FIT: std::sync::OnceLock<HoosierMf61> = std::sync::OnceLock::new();
    let rig = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    Some(FIT.get_or_init(|| {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("hoosier_mf61");
        fs::create_dir_all(&dir).unwrap();
        let tir = dir.join("hoosier.tir");
        let o = identify_to(&rig, "mf61", &tir);
        assert!(o.status.success(), "{}", stderr(&o));
        HoosierMf61 {
            stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
            stderr: stderr(&o),
            rig,
            tir,
        }
    }))
}

/// The stderr of a run `o` that must have failed without writing `out`.
pub(crate) fn refused(o: &Output, out: &Path) -> String {
    assert!(!o.status.success(), "expected failure");
    assert!(
        !out.exists(),
        "a failed run must not leave {}",
        out.display()
    );
    stderr(o)
}

/// Writes a linear tyre file, `tyre.toml`, into campaign folder `dir`.
pub(crate) fn linear_tyre(dir: &Path) {
    fs::write(
        dir.join("tyre.toml"),
        "model = \"linear\"\ncornering_stiffness = 60000.0\n",
    )
    .unwrap();
}

/// Runs `diagnose` on a campaign folder into its `out` sub-folder; returns
/// stdout and diagnosis.json.
pub(crate) fn diagnose(dir: &Path) -> (String, serde_json::Value) {
    diagnose_to(dir, &dir.join("out"))
}

/// A synthetic campaign with `effects` on (seed 1) whose candidates are
/// narrowed to `candidates` (a TOML list's items), diagnosed into
/// `dir/out`: stdout, `diagnosis.json` and `report.html`.
pub(crate) fn narrowed(
    dir: &Path,
    effects: &str,
    candidates: &str,
) -> (String, serde_json::Value, String) {
    let campaign = synth_campaign(dir, "c", &["--effects", effects, "--seed", "1"]);
    // synth's vehicle.toml ends in its [diagnose] table.
    let vehicle = campaign.join("vehicle.toml");
    let text = fs::read_to_string(&vehicle).unwrap();
    fs::write(&vehicle, format!("{text}effects = [{candidates}]\n")).unwrap();
    let out = dir.join("out");
    let (stdout, d) = diagnose_to(&campaign, &out);
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    (stdout, d, page)
}

/// Runs `diagnose campaign --out out`; returns stdout and diagnosis.json.
pub(crate) fn diagnose_to(campaign: &Path, out: &Path) -> (String, serde_json::Value) {
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        read_json(&out.join("diagnosis.json")),
    )
}

/// The unit step response at time `tau` (s) after the step (0 before it)
/// of a second-order system of natural frequency `w` (rad/s) and damping
/// ratio `zeta` below 1: the shape of a synthetic step log's responses.
pub(crate) fn damped_step(w: f64, zeta: f64, tau: f64) -> f64 {
    if tau <= 0.0 {
        return 0.0;
    }
    let wd = w * (1.0 - zeta * zeta).sqrt();
    1.0 - (-zeta * w * tau).exp() * ((wd * tau).cos() + zeta * w / wd * (wd * tau).sin())
}

/// A fixed pseudo-random noise from `seed` (Knuth's MMIX linear
/// congruential generator): each call gives the next value, uniform in
/// ±`amp`/2, the same sequence on every machine.
pub(crate) fn lcg_noise(mut seed: u64) -> impl FnMut(f64) -> f64 {
    move |amp: f64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        amp * (((seed >> 33) as f64) / f64::from(1u32 << 31) - 0.5)
    }
}

/// The CSV text `log` with the cell of column `column` (1-based) at file
/// line `line` (1-based) replaced by `cell`.
pub(crate) fn with_cell(log: &str, line: usize, column: usize, cell: &str) -> String {
    let mut lines: Vec<String> = log.lines().map(str::to_string).collect();
    let mut cells: Vec<String> = lines[line - 1].split(',').map(str::to_string).collect();
    cells[column - 1] = cell.to_string();
    lines[line - 1] = cells.join(",");
    lines.join("\n") + "\n"
}

/// `metrics dir/file args…` run in `dir`: (success, stdout, stderr).
pub(crate) fn metrics_in(dir: &Path, file: &str, args: &[&str]) -> (bool, String, String) {
    let mut all = vec!["metrics", file];
    all.extend(args);
    let o = run_in(dir, &all);
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    (o.status.success(), out, stderr(&o))
}

/// Runs `diagnose campaign --out out`, which may fail: whether it
/// succeeded, and stderr.
pub(crate) fn diagnose_status(campaign: &Path, out: &Path) -> (bool, String) {
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (o.status.success(), stderr(&o))
}

/// Diagnoses each campaign into its own `out` folder, all at once (each
/// `diagnose` is its own process); stdout and diagnosis.json in order.
pub(crate) fn diagnosed_together(
    campaigns: &[std::path::PathBuf],
) -> Vec<(String, serde_json::Value)> {
    std::thread::scope(|s| {
        let jobs: Vec<_> = campaigns
            .iter()
            .map(|c| s.spawn(move || diagnose_to(c, &c.join("out"))))
            .collect();
        jobs.into_iter().map(|j| j.join().unwrap()).collect()
    })
}

pub(crate) fn simulate_err(dir: &Path) -> String {
    fails_cleanly("simulate", &dir.join("scenario.toml"), dir)
}

mod analogue_verdicts;
mod analogues;
mod calibration;
mod cross_validation;
mod design;
mod diagnose;
mod identify;
mod identify_blocks;
mod identify_hints;
mod identify_hoosier;
mod identify_records;
mod magic_formula;
mod measured_metrics;
mod messages;
mod mf_combined_fy;
mod mf_holds;
mod mf_identify;
mod mf_vertical;
mod pac89_bounds;
mod priors;
mod programmes;
mod proving_ground;
mod real_logs;
mod report_html;
mod restricted_screen;
mod rig_layouts;
mod scenarios;
mod sedan_runs;
mod set_search;
mod shards;
mod shared_runs;
mod sweeps;
mod toml_errors;
mod trips;
mod trips_applicable;
mod trips_diagnose;
mod trips_fresh;
mod trips_identify;
mod trips_inputs;
mod trips_limits;
mod trips_outputs;
mod trips_ranges;
mod trips_release;
mod trips_run_units;
mod trips_s100_fix30a;
mod trips_s100_fix30b;
mod trips_s100_fix30c;
mod trips_s100_fix30d;
mod trips_s100_perf40;
mod trips_s100_words39;
mod trips_s101_beta39;
mod trips_s101_fix31a;
mod trips_s101_fix31b;
mod trips_s101_fix31c;
mod trips_s101_fix41f;
mod trips_s101_reps40;
mod trips_s102_beta39b;
mod trips_s102_fix32a;
mod trips_s102_fix32b;
mod trips_s102_fix32c;
mod trips_s102_fix41g;
mod trips_s103_fix33a;
mod trips_s103_fix33b;
mod trips_s103_fix33c;
mod trips_s103_fix33d;
mod trips_s103_mend33;
mod trips_s103_putnam39;
mod trips_s104_camber34;
mod trips_s104_fix34b;
mod trips_s104_lead;
mod trips_s104_mend34;
mod trips_s105_fig41;
mod trips_s105_fix36a;
mod trips_s105_fix36b;
mod trips_s105_lead;
mod trips_s105_mfhold41;
mod trips_s105_ui41a;
mod trips_s105_ui41b;
mod trips_s105_words41;
mod trips_s106_fix37a;
mod trips_s106_fix37b;
mod trips_s106_lead;
mod trips_s106_mfstaged41;
mod trips_s106_shares41;
mod trips_s106_small41;
mod trips_s106_step40;
mod trips_s106_units41;
mod trips_s62;
mod trips_s62b;
mod trips_s62c;
mod trips_s62d;
mod trips_s63;
mod trips_s64;
mod trips_s64b;
mod trips_s65;
mod trips_s66;
mod trips_s67;
mod trips_s68;
mod trips_s68_holds;
mod trips_s69;
mod trips_s69_identify;
mod trips_s69_metrics;
mod trips_s70;
mod trips_s71;
mod trips_s72;
mod trips_s72_tyre;
mod trips_s73;
mod trips_s74;
mod trips_s74_tir;
mod trips_s75_replay;
mod trips_s75_sim;
mod trips_s75_tir;
mod trips_s76_identify;
mod trips_s76_input;
mod trips_s76_lead;
mod trips_s76_sim;
mod trips_s77_lead;
mod trips_s77_sim;
mod trips_s77_tyre;
mod trips_s79_diag;
mod trips_s79_lead;
mod trips_s79_sim;
mod trips_s79_tyre;
mod trips_s80_diag;
mod trips_s80_kind;
mod trips_s80_lead;
mod trips_s80_sim;
mod trips_s80_tyre;
mod trips_s81_diag;
mod trips_s81_lead;
mod trips_s81_metr;
mod trips_s81_tyre;
mod trips_s82_eq;
mod trips_s82_idf;
mod trips_s82_met;
mod trips_s82_sim;
mod trips_s82_study;
mod trips_s83_diag;
mod trips_s83_lead;
mod trips_s83_met;
mod trips_s83_sim;
mod trips_s84_idn;
mod trips_s84_lead;
mod trips_s84_sim;
mod trips_s86_idn;
mod trips_s86_lead;
mod trips_s86_met;
mod trips_s86_perf;
mod trips_s86_units;
mod trips_s87_cal;
mod trips_s87_gap;
mod trips_s87_idn;
mod trips_s87_lead;
mod trips_s88_cal;
mod trips_s88_idn;
mod trips_s88_lead;
mod trips_s88_met;
mod trips_s89_lead;
mod trips_s89_met;
mod trips_s89_perf;
mod trips_s89_tyre;
mod trips_s90_diag;
mod trips_s90_lead;
mod trips_s90_met;
mod trips_s91_diag;
mod trips_s91_lead;
mod trips_s91_met;
mod trips_s91_perf;
mod trips_s92_diag;
mod trips_s92_lead;
mod trips_s92_met;
mod trips_s93_diag;
mod trips_s93_eq;
mod trips_s93_lead;
mod trips_s93_met;
mod trips_s94_eq;
mod trips_s94_lead;
mod trips_s94_met;
mod trips_s95_bank;
mod trips_s95_ident;
mod trips_s95_real;
mod trips_s95_tyreval;
mod trips_s95_words;
mod trips_s96_held;
mod trips_s96_hold;
mod trips_s96_ident;
mod trips_s96_metrics;
mod trips_s96_real;
mod trips_s96_study;
mod trips_s97_eq;
mod trips_s97_held27;
mod trips_s97_ident;
mod trips_s97_metrics;
mod trips_s97_real;
mod trips_s97_steer;
mod trips_s97_verdict;
mod trips_s98_eq28;
mod trips_s98_fix41a;
mod trips_s98_fix41b;
mod trips_s98_mount28;
mod trips_s98_real28;
mod trips_s98_step28;
mod trips_s98_words28;
mod trips_s99_fig41;
mod trips_s99_fix41c;
mod trips_s99_fix41d;
mod trips_s99_fixes39;
mod trips_s99_perf40;
mod trips_simulate;
mod trips_units;
mod tyre_eval;
mod tyre_eval_beyond;
mod tyre_eval_loads;
mod user_trips;

/// Runs `synth` with `args` into `dir/name` and returns the campaign folder.
/// `synth` is deterministic in its arguments (the seed among them), so a
/// campaign is generated once per test run ([`synthesised`]) and copied:
/// the suite asks for the same campaigns many times, and a slow oval takes
/// 3 s to generate. Like `synth`, it never writes into an existing folder.
pub(crate) fn synth_campaign(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    let out = dir.join(name);
    assert!(
        !out.exists(),
        "{}: exists; synth does not overwrite a campaign",
        out.display()
    );
    copy_folder(&synthesised(args), &out);
    out
}

/// The campaign `synth args` writes, generated by the first test that asks
/// into this test run's own scratch folder (one generation per distinct
/// argument list, however many tests ask at once).
fn synthesised(args: &[&str]) -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::OnceLock;
    static MADE: Memo<Vec<String>, PathBuf> = Memo::new();
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let root = ROOT.get_or_init(|| {
        // A run's own folder, the last run's removed: a campaign cached by
        // an older binary must never be read.
        let all = Path::new(env!("CARGO_TARGET_TMPDIR")).join("synth_cache");
        let _ = fs::remove_dir_all(&all);
        let root = all.join(std::process::id().to_string());
        fs::create_dir_all(&root).unwrap();
        root
    });
    let key: Vec<String> = args.iter().map(|a| a.to_string()).collect();
    MADE.get(key, || {
        let out = root.join(NEXT.fetch_add(1, Ordering::Relaxed).to_string());
        let mut all = vec!["synth"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", out.to_str().unwrap()]);
        let o = run(&all);
        assert!(o.status.success(), "{}", stderr(&o));
        out
    })
}

/// A synthetic campaign of `programme` with `effects` withheld on noise
/// `seed`, in `dir/<programme>-<seed>`, its `vehicle.toml` (whose last
/// table is `[diagnose]`) extended by `extra`.
pub(crate) fn synth_extended(
    dir: &Path,
    programme: &str,
    effects: &str,
    seed: &str,
    extra: &str,
) -> PathBuf {
    let c = synth_campaign(
        dir,
        &format!("{programme}-{seed}"),
        &[
            "--programme",
            programme,
            "--effects",
            effects,
            "--seed",
            seed,
        ],
    );
    let v = c.join("vehicle.toml");
    let text = std::fs::read_to_string(&v).unwrap();
    std::fs::write(&v, text + extra).unwrap();
    c
}

/// Runs `diagnose` on a campaign (outputs beside it, `<campaign>.out`):
/// its stdout and `diagnosis.json`.
pub(crate) fn diagnose_campaign(campaign: &Path) -> (String, serde_json::Value) {
    diagnose_to(campaign, &campaign.with_extension("out"))
}

/// The ranking row of `effect` (a single or `a+b`) in a diagnosis.
pub(crate) fn ranked<'a>(d: &'a serde_json::Value, effect: &str) -> &'a serde_json::Value {
    d["ranking"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["effect"] == effect)
        .unwrap_or_else(|| panic!("{effect} is not ranked"))
}

/// The row of `effect` in a diagnosis's ranking or its screened rows.
pub(crate) fn fitted_row<'a>(d: &'a serde_json::Value, effect: &str) -> &'a serde_json::Value {
    d["ranking"]
        .as_array()
        .unwrap()
        .iter()
        .chain(d["screened"].as_array().unwrap())
        .find(|r| r["effect"] == effect)
        .unwrap_or_else(|| panic!("{effect} not fitted"))
}

/// The index of column `name` in a header.
pub(crate) fn column(head: &[String], name: &str) -> usize {
    head.iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}"))
}

/// A numeric CSV's header and rows.
pub(crate) fn numeric_csv(p: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = fs::read_to_string(p).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (head, rows)
}

/// The effects a diagnosis's verdict names.
pub(crate) fn verdict_of(d: &serde_json::Value) -> Vec<String> {
    d["verdict"]["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_string())
        .collect()
}

/// Runs `metrics <run> --json`, which must succeed: its report and the
/// report's warnings.
pub(crate) fn metrics_json(run_csv: &Path) -> (serde_json::Value, Vec<String>) {
    let o = run(&["metrics", run_csv.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let warnings = j["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect();
    (j, warnings)
}

/// `text` (a run CSV, time first) with its last row repeated one time step
/// later.
pub(crate) fn one_sample_longer(text: &str) -> String {
    let rows: Vec<&str> = text.lines().collect();
    let t = |row: &str| -> f64 { row.split(',').next().unwrap().parse().unwrap() };
    let (last, before) = (rows[rows.len() - 1], rows[rows.len() - 2]);
    let next = t(last) + (t(last) - t(before));
    let rest = &last[last.find(',').unwrap()..];
    format!("{}{next:.4}{rest}\n", text)
}
mod trips_s107_diagwords42;
mod trips_s107_lead;
mod trips_s107_mf42;
mod trips_s107_runwords42;
mod trips_s107_tyreeval42;
mod trips_s108_diagwords43;
mod trips_s108_lead;
mod trips_s108_mf43;
mod trips_s108_runwords43;
mod trips_s109_eqstudy41;
mod trips_s109_fleetdesign41;
mod trips_s109_gyroscale41;
mod trips_s109_lead;
mod trips_s109_loadlevels41;
mod trips_s109_perf40f;
mod trips_s109_simwords41;
mod trips_s110_epoch43;
mod trips_s110_lead;
mod trips_s110_metrics42;
mod trips_s110_pac89se43;
mod trips_s110_simulate42;
mod trips_s110_studyeq42;
mod trips_s110_tyreeval42;
mod trips_s110_verdict43;
mod trips_s111_holdowner;
mod trips_s111_lead;
mod trips_s111_metrics44;
mod trips_s111_perfdiag44;
mod trips_s111_rigtir45;
mod trips_s111_studysim44;
mod trips_s111_units45;
mod trips_s111_words44;
mod trips_s112_folds47;
mod trips_s112_lead;
mod trips_s112_metrics47;
mod trips_s112_perfdiag46;
mod trips_s112_perfstep46;
mod trips_s113_floors48;
mod trips_s113_lead;
mod trips_s113_settle48;
mod trips_s113_units48;
mod trips_s114_ident50;
mod trips_s114_metrics50;
mod trips_s114_tyres50;
mod trips_s114_units50;
mod trips_s114_words50;
mod trips_s115_clean51;
mod trips_s115_gain51;
mod trips_s115_known51;
mod trips_s115_roll51;
