//! What a fresh user tripped on (round 14), fixed by the lead: a diagnosis
//! written into the folder its runs are read from, and names that got no
//! "did you mean" (a manoeuvre kind by one word of it, an effect by the
//! name engineers also give it).

use super::*;

/// `handling diagnose c8 --out c8/runs` was accepted: the diagnosis wrote
/// `overlays.csv` among the runs and the next diagnosis of the same
/// campaign failed on it, reading its `run` header as "a header further
/// down". The folder of runs is refused as an output, named with where the
/// diagnosis goes without `--out`, before anything is written; another
/// folder is still taken.
#[test]
fn a_diagnosis_is_not_written_into_the_folder_its_runs_are_read_from() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c8",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let runs = c.join("runs");
    let before = fs::read_dir(&runs).unwrap().count();
    for out in [runs.clone(), runs.join("..").join("runs")] {
        let o = run(&[
            "diagnose",
            c.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success(), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains("is the folder this campaign reads its runs from")
                && e.contains(&format!(
                    "without --out it goes to {}",
                    Path::new("out").join("c8").display()
                )),
            "{e}"
        );
    }
    assert_eq!(
        fs::read_dir(&runs).unwrap().count(),
        before,
        "written into runs/"
    );
    let elsewhere = dir.path().join("d");
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        elsewhere.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(elsewhere.join("overlays.csv").is_file());
}

/// The bundled step scenario with its manoeuvre's `kind` replaced.
fn scenario_of_kind(dir: &Path, kind: &str) -> PathBuf {
    let text = fs::read_to_string(root().join("scenarios/step_gbt6323_pac89.toml")).unwrap();
    assert!(text.contains("kind = \"step-steer\""));
    let p = dir.join(format!("{kind}.toml"));
    let tyres = root().join("tyres");
    let text = text
        .replace("kind = \"step-steer\"", &format!("kind = \"{kind}\""))
        .replace("../tyres", tyres.to_str().unwrap());
    fs::write(&p, text).unwrap();
    p
}

/// `kind = "step"` was answered "did you mean `sweep`?" (two edits), and
/// `ramp` and `steer-step` got no suggestion: each word of `step-steer`
/// matched both of its spellings (`step-steer`, `step_steer`), which made
/// it ambiguous. A name spelt two ways is one name now; a word several
/// names share (`steer`) suggests none rather than a stranger.
#[test]
fn a_manoeuvre_kind_named_by_one_of_its_words_is_answered_with_its_name() {
    let dir = tempfile::tempdir().unwrap();
    for (given, meant) in [
        ("step", Some("step-steer")),
        ("ramp", Some("ramp-steer")),
        ("steer-step", Some("step-steer")),
        ("steer", None),
    ] {
        let p = scenario_of_kind(dir.path(), given);
        let out = dir.path().join(format!("out-{given}"));
        let o = run(&[
            "simulate",
            p.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(e.contains(&format!("unknown variant `{given}`")), "{e}");
        match meant {
            Some(m) => assert!(
                e.contains(&format!("(did you mean `{m}`?)")),
                "{given}: {e}"
            ),
            None => assert!(!e.contains("did you mean"), "{given}: {e}"),
        }
    }
}

/// `--effects tyre_lag` listed the nineteen effects without a suggestion:
/// spelling cannot find `relaxation_length` (the length of the tyre's
/// first-order lag). Names engineers also give an effect are answered
/// with it, on the command line and in a campaign file alike.
#[test]
fn an_effect_asked_for_by_another_name_engineers_use_is_suggested() {
    let dir = tempfile::tempdir().unwrap();
    for (given, meant) in [
        ("tyre_lag", "relaxation_length"),
        ("tire-lag", "relaxation_length"),
        ("latency", "sensor_delay"),
        ("downforce", "aero_load"),
    ] {
        let out = dir.path().join(given);
        let o = run(&[
            "synth",
            "--effects",
            given,
            "--seed",
            "1",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!(
                "unknown effect `{given}` (did you mean `{meant}`?)"
            )),
            "{e}"
        );
        assert!(!out.exists());
    }
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, text + "effects = [\"tyre_lag\"]\n").unwrap();
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("d").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("(did you mean `relaxation_length`?)"),
        "{}",
        stderr(&o)
    );
}

/// The sedan's step with linear tyres on both axles and a 0.5 rad steer,
/// load transfer on (the scenario's default): about 6 g, the inner wheels
/// lifting and landing. `simulate` never ended: Dormand–Prince drove its
/// step towards zero at the step's onset and its dense output grew (2.7 GB
/// in 12 minutes, found by the met helper of session 88). It stops at its
/// step budget and says where and why, writing nothing.
#[test]
fn a_run_the_integrator_cannot_follow_is_refused_where_it_stalls_not_run_for_ever() {
    let dir = tempfile::tempdir().unwrap();
    let linear = root().join("tyres/linear.toml");
    let text = bundled_scenario("sedan_step.toml")
        .replace(
            root().join("tyres/gim_sedan_front.toml").to_str().unwrap(),
            linear.to_str().unwrap(),
        )
        .replace(
            root().join("tyres/gim_sedan_rear.toml").to_str().unwrap(),
            linear.to_str().unwrap(),
        )
        .replace("steer = 0.0174533", "steer = 0.5");
    assert!(text.contains("steer = 0.5") && text.contains("linear.toml"));
    let sc = dir.path().join("hang.toml");
    fs::write(&sc, text).unwrap();
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("hang.toml: the integration (Dormand–Prince) stalled at t = 1.0")
            && e.contains("of 6.000 s")
            && e.contains("method = \"rk4\""),
        "{e}"
    );
    assert!(!out.join("history.csv").exists());
}

/// `text` (a run file's) with column `k` (0-based) negated, or dropped.
fn column_edited(text: &str, k: usize, drop: bool) -> String {
    let mut out = String::new();
    for (row, line) in text.lines().enumerate() {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        if drop {
            cells.remove(k);
        } else if row > 0 {
            cells[k] = format!("{}", -cells[k].parse::<f64>().unwrap());
        }
        out += &(cells.join(",") + "\n");
    }
    out
}

/// A yaw rate against the steer was answered "is `steer` or `yaw_rate` in
/// another sign convention?" even where the run's `ay` says which: in a
/// steady turn ay = u·r, so an `ay` with the steer makes the yaw rate the
/// reversed channel, and one with the yaw rate the steer. Without `ay` the
/// question stays.
#[test]
fn a_yaw_rate_against_the_steer_is_blamed_on_the_channel_ay_disagrees_with() {
    use super::sedan_runs::{run_text, sedan_history};
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let text = run_text(&history, 20, None);
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let cases = [
        (
            "yaw.csv",
            column_edited(&text, col("yaw_rate"), false),
            "`yaw_rate` is in the other sign convention; negate it",
        ),
        (
            "steer.csv",
            column_edited(&text, col("steer"), false),
            "`steer` is in the other sign convention; negate it",
        ),
        (
            "no_ay.csv",
            column_edited(
                &column_edited(&text, col("yaw_rate"), false),
                col("ay"),
                true,
            ),
            "is `steer` or `yaw_rate` in another sign convention? negate it",
        ),
    ];
    for (name, body, said) in cases {
        let p = dir.path().join(name);
        fs::write(&p, body).unwrap();
        let o = run(&["metrics", p.to_str().unwrap()]);
        assert!(!o.status.success(), "{name}");
        let e = stderr(&o);
        assert!(
            e.contains("the yaw rate turns against the steer") && e.contains(said),
            "{name}: {e}"
        );
    }
}

/// `tyre-eval … --out outdir/` (a folder not yet made, written as one)
/// ended after the evaluation with "cannot move into place: Not a
/// directory (os error 20)"; `identify` likewise. A path written with a
/// trailing `/` names a folder, refused before the work as an existing
/// folder is, with the file to name in it.
#[test]
fn an_output_file_written_as_a_folder_is_refused_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let out = format!("{}/outdir/", dir.path().display());
    let o = run(&[
        "tyre-eval",
        "tyres/pac89_adams_example.toml",
        "docs/examples/tyre_points.csv",
        "--out",
        &out,
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains(&format!(
            "{out}: is a folder; name the file to write in it (e.g. {out}forces.csv)"
        )) || e.contains(&format!(
            "{out}: is a folder; name the file to write in it (e.g. {}/outdir/forces.csv)",
            dir.path().display()
        )),
        "{e}"
    );
    let o = run(&[
        "identify",
        "docs/examples/tyre_points.csv",
        "--model",
        "pac89",
        "--out",
        &out,
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(e.contains(&format!("{out}: is a folder")), "{e}");
    assert!(!dir.path().join("outdir").exists());
}
