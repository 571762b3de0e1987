//! What a fresh-eyes user tripped on in `diagnose` (round 33), run as a
//! user runs the tool: a campaign that narrowed its candidates to one
//! effect was told "a model-form error outside the library" while 19 of
//! the library's 20 effects, the true one among them, were never tried; a
//! run in degrees among runs in radians was refused with "1 of the 8
//! runs … 6 runs do not", the eighth unsaid; `particles = -3` was "a whole
//! number of 0 or more" and `particles = 0` "must be greater than 0",
//! while 10⁹ particles or iterations were taken without a word; a batch
//! skipped `notes.txt` and `carD.toml.txt` without a word, did not read
//! `carC.TOML`, and named a campaign `carB.toml` in the table whose output
//! folder is `carB/`.

use super::*;

/// Before (`effects = ["road_bank"]` on a relaxation-length truth): "a
/// gap … that no candidate effect explains: the best, road_bank, removes
/// none of it … — a model-form error outside the library", on the
/// terminal, the page and in diagnosis.json. Now the verdict carries the
/// campaign's narrowing (typed: `narrowed.tried`, `narrowed.untried`), and
/// its statement names what was tried and how many of the library's
/// effects were not, and blames nothing outside the library.
#[test]
fn a_campaign_that_narrows_its_candidates_gets_no_verdict_on_the_library() {
    let dir = tempfile::tempdir().unwrap();
    let (said, d, page) = narrowed(dir.path(), "relaxation_length", "\"road_bank\"");
    let v = &d["verdict"];
    assert_eq!(v["kind"], "outside_library", "{said}");
    assert_eq!(v["narrowed"]["tried"], serde_json::json!(["road_bank"]));
    let untried: Vec<&str> = v["narrowed"]["untried"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap())
        .collect();
    assert!(untried.contains(&"relaxation_length"), "{untried:?}");
    assert!(!untried.contains(&"road_bank"), "{untried:?}");
    let statement = v["statement"].as_str().unwrap();
    let tried = format!(
        "no verdict on the library: only the campaign's `[diagnose] effects` were tried (road_bank), and {} of the library's {} effects were not",
        untried.len(),
        untried.len() + 1
    );
    assert!(
        statement.contains("that none of the campaign's candidate effects explains")
            && statement.contains(&tried),
        "{statement}"
    );
    assert!(!statement.contains("outside the library"), "{statement}");
    // The terminal and the page say the same.
    assert!(said.contains(&format!("verdict: {statement}")), "{said}");
    assert!(!said.contains("outside the library"), "{said}");
    assert!(page.contains("no verdict on the library"), "{page}");
    assert!(!page.contains("model-form error outside the library"));
}

/// Before: one step's steer in degrees among runs in radians read "… in 1
/// of the 8 runs: … 6 runs do not …", the sine sweep (judged by its
/// lagged yaw rate, not a held steer) left unsaid. Now every run is
/// accounted for, the others by name.
#[test]
fn a_run_in_degrees_among_runs_in_radians_accounts_for_every_run() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    trips_s81_diag::rewrite(
        &c,
        "steer",
        &|f| f.starts_with("step_100kph_6ms2"),
        &f64::to_degrees,
    );
    let err = fails_cleanly("diagnose", &c, dir.path());
    assert!(
        err.contains("for the steer in 1 of the 8 runs: ")
            && err.contains("the other 7 runs: 6 read in radians by their held steer"),
        "{err}"
    );
    assert!(
        err.contains(
            "sweep_080kph.csv reads in radians by its swept steer against the lagged yaw rate. "
        ),
        "{err}"
    );
}

/// A synthetic campaign whose `[diagnose]` (its last table) is extended by
/// `key = value`, and the line that key is on.
fn with_setting(dir: &Path, name: &str, key: &str, value: &str) -> (PathBuf, usize) {
    let c = synth_campaign(dir, name, &["--effects", "sensor_delay", "--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    assert!(text.ends_with('\n'), "{text}");
    let line = text.lines().count() + 1;
    fs::write(&v, format!("{text}{key} = {value}\n")).unwrap();
    (c, line)
}

/// Before: `particles = -3` read "expected a whole number of 0 or more",
/// `particles = 0` "must be greater than 0", and 10⁹ particles or
/// iterations were taken (a diagnosis that never ends). Now each is refused
/// at its key with one statement of the range, 1 to 1000, and why.
#[test]
fn a_swarm_size_outside_its_range_is_refused_with_one_statement_of_it() {
    let dir = tempfile::tempdir().unwrap();
    let range = "expected a whole number from 1 to 1000 (a fit with a swarm replays every run once per particle and iteration";
    let cases = [
        ("particles", "-3"),
        ("particles", "0"),
        ("particles", "2.5"),
        ("particles", "1000000000"),
        ("iterations", "0"),
        ("iterations", "1000000000"),
    ];
    for (i, (key, value)) in cases.into_iter().enumerate() {
        let (c, line) = with_setting(dir.path(), &format!("c{i}"), key, value);
        let err = fails_cleanly("diagnose", &c, &c);
        let at = format!("vehicle.toml:{line}:{}: `diagnose.{key}`", key.len() + 4);
        assert!(err.contains(&at), "{key} = {value}: {err}");
        assert!(err.contains(range), "{key} = {value}: {err}");
        assert!(!err.contains("0 or more"), "{err}");
    }
}

/// Before: a batch folder's `notes.txt` was skipped without a word,
/// `carB.TOML` was not read (a runs folder reads `.CSV`), and the table
/// named a campaign file `carB.toml` whose output folder is `carB/`. Now
/// the `.TOML` is a campaign named `carB`, and the skipped entry is named
/// in a note.
#[test]
fn a_batch_names_every_entry_it_skips_and_reads_toml_in_any_case() {
    let dir = tempfile::tempdir().unwrap();
    let fleet = dir.path().join("fleet");
    fs::create_dir_all(fleet.join("carA")).unwrap();
    fs::write(fleet.join("carB.TOML"), "[vehicle]\nmass = 1530.0\n").unwrap();
    fs::write(fleet.join("notes.txt"), "driven on Tuesday\n").unwrap();
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        "--batch",
        fleet.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    // Both campaigns are broken: the table is written, the run fails.
    assert!(!o.status.success());
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("fleet: 0 of 2 campaigns diagnosed, 2 failed"),
        "{said}"
    );
    assert!(said.contains(&format!("{:<24} FAILED: ", "carB")), "{said}");
    assert!(
        said.contains("note: 1 entry of the batch folder skipped, not a campaign (neither a sub-folder nor a .toml file): notes.txt"),
        "{said}"
    );
    let table = read_json(&out.join("fleet.json"));
    let names: Vec<&str> = table["campaigns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["campaign"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["carA", "carB"]);
}

/// Before: a folder holding only `carD.toml.txt` and `readme.md` was "no
/// campaign in the folder (sub-folders or .toml files)", its entries
/// unnamed. Now the refusal names them.
#[test]
fn a_batch_folder_without_a_campaign_names_what_it_holds() {
    let dir = tempfile::tempdir().unwrap();
    let fleet = dir.path().join("fleet3");
    fs::create_dir_all(&fleet).unwrap();
    fs::write(fleet.join("carD.toml.txt"), "[vehicle]\n").unwrap();
    fs::write(fleet.join("readme.md"), "fleet\n").unwrap();
    let o = run(&[
        "diagnose",
        "--batch",
        fleet.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("no campaign in the folder (sub-folders or .toml files): its 2 entries are not a campaign: carD.toml.txt, readme.md"),
        "{e}"
    );
}
