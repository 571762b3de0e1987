//! Session 91, lead: fresh-eyes round 17's item (10), a campaign-wide
//! refusal of runs with the steer in degrees, said beside the other runs'
//! refusals in one pass.

use super::*;

use crate::trips_s81_diag::rewrite;

/// Two runs of eight with the steer in degrees and a third cut to 0.58 s:
/// the steer-in-degrees refusal ended the reading, and the short run was
/// said only once the user had converted the two (fresh-eyes round 17).
/// Now one pass says all three runs: the two in degrees as one refusal
/// naming both (with the advice to convert their files, `degrees` under
/// [runs] being wrong for the others), the short one in its own words, in
/// run order.
#[test]
fn runs_in_degrees_among_runs_in_radians_are_said_beside_the_other_refusals() {
    let dir = scratch(&[]);
    let camp = synth_campaign(dir.path(), "deg", &["--effects", "none", "--seed", "1"]);
    rewrite(
        &camp,
        "steer",
        &|n| n.starts_with("step_100kph"),
        &f64::to_degrees,
    );
    let mut files: Vec<PathBuf> = fs::read_dir(camp.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    let short = files
        .iter()
        .find(|p| p.ends_with("ramp_080kph.csv"))
        .unwrap();
    let text = fs::read_to_string(short).unwrap();
    let cut: String = text.lines().take(60).map(|l| format!("{l}\n")).collect();
    fs::write(short, cut).unwrap();
    let e = fails_cleanly("diagnose", &camp, dir.path());
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(lines[0], "error: 3 of 8 runs refused, in run order:", "{e}");
    assert_eq!(lines.len(), 3, "{e}");
    assert!(
        lines[1].contains("ramp_080kph.csv") && lines[1].contains("the run is 0.58 s long"),
        "{e}"
    );
    assert!(
        lines[2].contains("for the steer in 2 of the 8 runs:")
            && lines[2].contains("step_100kph_2ms2.csv (62× smaller")
            && lines[2].contains("step_100kph_6ms2.csv (65× smaller")
            && lines[2].contains("convert the steer of these runs to radians in their files")
            // The short run was refused before its steer was judged, and
            // the sweep holds no steer to judge (fresh-eyes round 19 read
            // "The other 7 runs do not" here).
            && lines[2].contains("the other 6 runs: 4 read in radians by their held steer against their yaw rate, as they should; "),
        "{e}"
    );
    assert!(!e.contains("(the first of"), "{e}");
}

/// Every run of a campaign with the steer in degrees: no run's steer
/// reads as radians against its yaw rate, so each is refused in its own
/// words, which advise `degrees` under [runs] (one line for the five steps
/// alike; two runs steer beyond ±90° read in radians). Since session 92
/// the sine sweep, without a held steer, is judged by its lagged yaw rate
/// too, and refused alike: 8 of 8, the first of 6 alike.
#[test]
fn a_campaign_all_in_degrees_is_advised_to_declare_them() {
    let dir = scratch(&[]);
    let camp = synth_campaign(dir.path(), "all", &["--effects", "none", "--seed", "1"]);
    rewrite(&camp, "steer", &|_| true, &f64::to_degrees);
    let e = fails_cleanly("diagnose", &camp, dir.path());
    assert!(
        e.starts_with("error: 8 of 8 runs refused, in run order:\n"),
        "{e}"
    );
    assert!(e.contains("(the first of 6 runs refused alike)"), "{e}");
    assert!(e.contains("is beyond ±90°"), "{e}");
    assert!(!e.contains("The other"), "{e}");
}

/// `synth --drive a.toml,b.toml` was read as one file named
/// "a.toml,b.toml" ("cannot read"), while `--effects` takes commas
/// (fresh-eyes round 18). The files are now split at commas: the same
/// scenario twice is refused as a repeat, which it could only be if both
/// were read.
#[test]
fn drive_takes_scenario_files_separated_by_commas() {
    let dir = scratch(&[]);
    let text = fs::read_to_string(root().join("scenarios/step_gbt6323_gim.toml"))
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let again = dir.path().join("again.toml");
    fs::write(&again, &text).unwrap();
    let both = format!("{},{}", again.display(), again.display());
    let out = dir.path().join("never");
    let o = run(&[
        "synth",
        "--effects",
        "sensor_delay",
        "--seed",
        "2",
        "--drive",
        &both,
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains(
            "the campaign already has a run named `again` (driven from an earlier --drive file)"
        ),
        "{e}"
    );
    assert!(!out.exists());
}

/// A rig file whose `fz` and `fy` headers are exchanged: each negative
/// "load" was refused as a bad sample ("-2577.65 N is negative … (the
/// first of 963 places)") with no word of the swap (fresh-eyes round 18).
/// Now one refusal at the first negative load asks for the swap, with the
/// count and both columns' ranges; a few negative loads among positive
/// ones are still refused each as before.
#[test]
fn a_rig_file_with_fz_and_fy_exchanged_is_asked_to_swap_them() {
    let mut swapped = String::from("alpha,fy,fz\n");
    let mut glitch = String::from("alpha,fz,fy\n");
    for (k, load) in [2000.0_f64, 4000.0].iter().enumerate() {
        for i in 0..41 {
            let alpha = (f64::from(i) - 20.0) * 0.005;
            let fy = -1.1 * load * (12.0 * alpha).atan() * 2.0 / std::f64::consts::PI;
            swapped += &format!("{alpha},{load},{fy}\n");
            let fz = if k == 0 && i == 3 { -load } else { *load };
            glitch += &format!("{alpha},{fz},{fy}\n");
        }
    }
    let dir = scratch(&[("swapped.csv", &swapped), ("glitch.csv", &glitch)]);
    let rig = dir.path().join("swapped.csv");
    let out = dir.path().join("never.toml");
    let args = |rig: &Path| {
        vec![
            "identify".to_string(),
            rig.display().to_string(),
            "--model".into(),
            "linear".into(),
            "--out".into(),
            out.display().to_string(),
        ]
    };
    let o = run(&args(&rig).iter().map(String::as_str).collect::<Vec<_>>());
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains(":23:3: columns `fz` and `fy` look exchanged: `fz` changes sign (40 of its 82 samples negative, from -2453.95 to 2453.95 N)")
            && e.contains("while `fy` is positive throughout (from 2000 to 4000 N)")
            && e.contains("swap the two names in the header"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1, "{e}");
    let o = run(&args(&dir.path().join("glitch.csv"))
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>());
    let e = stderr(&o);
    assert!(
        e.contains("column `fz`: -2000 N is negative (loads are positive in FORMATS.md)"),
        "{e}"
    );
    assert!(!e.contains("exchanged") && !out.exists(), "{e}");
}
