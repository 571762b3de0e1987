//! The one integration test binary: runs the `handling` CLI on the bundled
//! scenarios and on broken inputs, and checks what a user sees.

pub(crate) use std::fs;
pub(crate) use std::path::{Path, PathBuf};
pub(crate) use std::process::{Command, Output};

pub(crate) fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_handling"))
}

pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub(crate) fn run(args: &[&str]) -> Output {
    bin().args(args).current_dir(root()).output().expect("runs")
}

/// Says on the terminal that a test skipped itself: written to the process's
/// stderr directly, past the test harness's capture of `eprintln!`.
pub(crate) fn skipped(test: &str, missing: &Path) {
    use std::io::Write;
    let _ = writeln!(
        std::io::stderr().lock(),
        "SKIPPED {test}: {} is absent",
        missing.display()
    );
}

pub(crate) fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Parses a JSON output file.
pub(crate) fn read_json(p: &Path) -> serde_json::Value {
    serde_json::from_str(&fs::read_to_string(p).unwrap()).unwrap()
}

/// Writes `files` into a fresh folder and returns it.
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

/// Runs `identify rig --model model --out out`.
pub(crate) fn identify_to(rig: &Path, model: &str, out: &Path) -> Output {
    run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        model,
        "--out",
        out.to_str().unwrap(),
    ])
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

pub(crate) fn simulate_err(dir: &Path) -> String {
    fails_cleanly("simulate", &dir.join("scenario.toml"), dir)
}

mod cross_validation;
mod diagnose;
mod identify;
mod magic_formula;
mod measured_metrics;
mod mf_identify;
mod programmes;
mod proving_ground;
mod real_logs;
mod report_html;
mod rig_layouts;
mod scenarios;
mod shards;
mod sweeps;

/// Runs `synth` with `args` into `dir/name` and returns the campaign folder.
pub(crate) fn synth_campaign(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    let out = dir.join(name);
    let mut all = vec!["synth"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let o = run(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    out
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

/// The effects a diagnosis's verdict names.
pub(crate) fn verdict_of(d: &serde_json::Value) -> Vec<String> {
    d["verdict"]["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_string())
        .collect()
}
