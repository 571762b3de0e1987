//! What fresh-eyes users tripped on in the diagnosis in session 93, run as
//! a user runs the tool: a roll steer confounded on linear base tyres told
//! to "ramp steer to the limit" (nothing saturates on them) and to drive
//! "steps at two speeds" the campaign already had.

use super::*;

/// The handling programme's roll-steer campaign on linear tyre files,
/// its candidates narrowed to roll_steer and its look-alike.
pub(crate) fn linear_roll_steer(dir: &Path) -> PathBuf {
    let c = synth_campaign(dir, "c", &["--effects", "roll_steer", "--seed", "1"]);
    fs::remove_file(c.join("tyre_rig.csv")).unwrap();
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    let rig = "rig = \"tyre_rig.csv\"\nmodel = \"pac89\"";
    assert!(text.contains(rig), "{text}");
    let text = text.replace(rig, "file = \"tyre.toml\"");
    fs::write(
        &v,
        format!("{text}effects = [\"roll_steer\", \"cornering_stiffness\"]\n"),
    )
    .unwrap();
    linear_tyre(&c);
    c
}

/// `design`'s first set for the pair roll_steer / cornering_stiffness on
/// the diagnosis in `diagnosis`, its 30 best manoeuvres, written to `to`.
pub(crate) fn roll_steer_design(diagnosis: &Path, to: &Path) -> serde_json::Value {
    let o = run(&[
        "design",
        diagnosis.to_str().unwrap(),
        "--effects",
        "roll_steer,cornering_stiffness",
        "--top",
        "30",
        "--out",
        to.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    read_json(&to.join("design.json"))["sets"][0].clone()
}

/// Before: "confounded: roll_steer, cornering_stiffness — separate them
/// with roll_steer: … a ramp steer to the limit; cornering_stiffness: …
/// steps at two speeds", on linear tyres and a campaign with steps at five
/// speeds and a ramp. Now the advice is a manoeuvre the campaign has not
/// driven (a steer sweep at 40 km/h; its sweep is at 80 km/h), and
/// `design` replaying the two candidates as fitted on it finds their
/// responses apart by more than a noise floor, the D the diagnosis states.
#[test]
fn a_confounded_roll_steer_on_linear_tyres_is_advised_a_run_the_campaign_lacks() {
    let dir = tempfile::tempdir().unwrap();
    let c = linear_roll_steer(dir.path());
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    assert_eq!(
        d["verdict"]["effects"],
        serde_json::json!(["roll_steer"]),
        "{said}"
    );
    let set = &d["confounded"][0];
    assert_eq!(
        set["effects"],
        serde_json::json!(["roll_steer", "cornering_stiffness"]),
        "{said}"
    );
    let line = said.lines().find(|l| l.starts_with("confounded:")).unwrap();
    for stale in ["ramp steer to the limit", "steps at two speeds"] {
        assert!(!line.contains(stale), "{line}");
    }
    let best = &set["separating_runs"]["pairs"][0]["best"];
    let name = best["name"].as_str().unwrap_or_else(|| panic!("{said}"));
    assert!(line.contains(&format!("({name};")), "{line}");
    // Its kind and speed (`sweep_040kph`) are no run's of the campaign.
    let end = name.find("kph").unwrap() + 3;
    let runs: Vec<String> = fs::read_dir(c.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(runs.len(), 8, "{runs:?}");
    assert!(
        runs.iter().all(|r| !r.starts_with(&name[..end])),
        "{name} in {runs:?}"
    );
    // `design` replays the pair on its family: the advised run among them,
    // apart by more than a noise floor, by the D the diagnosis states.
    let set = roll_steer_design(&out, &dir.path().join("design"));
    let ranked = set["ranked"].as_array().unwrap();
    let scored = ranked.iter().find(|s| s["name"] == name).unwrap();
    let sep = scored["separation"].as_f64().unwrap();
    assert!(sep > 1.0, "{sep}");
    let stated = best["separation"].as_f64().unwrap();
    assert!((sep - stated).abs() < 1e-6 * sep, "{sep} against {stated}");
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("What separates them:"), "{page}");
}
