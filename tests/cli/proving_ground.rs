//! An independent four-wheel proving ground that is not our own model:
//! `synth --truth four-wheel` then `diagnose`, as a user runs them.

use super::*;

/// `synth --truth four-wheel` into `dir/name`; returns the folder.
fn synth_four_wheel(dir: &Path, name: &str, effects: &str) -> PathBuf {
    let args = ["--truth", "four-wheel", "--effects", effects, "--seed", "2"];
    synth_campaign(dir, name, &args)
}

fn diagnose(campaign: &Path) -> (String, serde_json::Value) {
    diagnose_campaign(campaign)
}

#[test]
fn four_wheel_truth_gives_no_gap_alone_and_its_sensor_delay_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().to_path_buf();
    // The two campaigns are diagnosed side by side (two processes).
    let clean = std::thread::spawn({
        let path = path.clone();
        move || diagnose(&synth_four_wheel(&path, "none", "none"))
    });
    let delayed = diagnose(&synth_four_wheel(&path, "delay", "sensor_delay"));
    let clean = clean.join().unwrap();

    // The campaign file states a roll that is not the truth's (6°/g): the
    // diagnosis is not handed the truth.
    let vehicle: toml::Value =
        toml::from_str(&fs::read_to_string(path.join("none/vehicle.toml")).unwrap()).unwrap();
    let gradient = vehicle["roll"]["gradient"].as_float().unwrap();
    let truth_gradient = 6f64.to_radians() / 9.80665;
    assert!(
        (gradient - truth_gradient).abs() > 0.3 * truth_gradient,
        "{gradient}"
    );
    for f in [
        "tyre_rig.csv",
        "runs/sweep_080kph.csv",
        "runs/ramp_080kph.csv",
    ] {
        assert!(path.join("none").join(f).is_file(), "{f}");
    }

    // No effect: the PAC89 fit to the rig and the 2-DOF model replay the
    // four-wheel car to within the noise.
    let (stdout, d) = clean;
    assert!(stdout.contains("verdict: no significant gap"), "{stdout}");
    assert!(!d["gap"]["significant"].as_bool().unwrap());
    assert_eq!(d["verdict"]["effects"], serde_json::json!([]));

    // A sensor delay of 0.05 s on the four-wheel car is named and recovered.
    let (stdout, d) = delayed;
    assert!(
        stdout.contains("verdict: sensor_delay explains the gap"),
        "{stdout}"
    );
    assert!(d["gap"]["significant"].as_bool().unwrap());
    assert_eq!(d["verdict"]["effects"], serde_json::json!(["sensor_delay"]));
    // The verdict's row (a steer-path delay, a look-alike with an idle
    // lag parameter, may rank above it within PARSIMONY).
    let top = ranked(&d, "sensor_delay");
    let delay = top["parameters"][0]["value"].as_f64().unwrap();
    assert!((delay - 0.05).abs() < 0.005, "{delay}");
    assert!(top["reduction_percent"].as_f64().unwrap() > 70.0);
}

#[test]
fn synth_refuses_an_unknown_truth_and_an_effect_the_truth_lacks() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c");
    let o = run(&[
        "synth",
        "--truth",
        "six-wheel",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("unknown truth `six-wheel`") && e.contains("four-wheel"),
        "{e}"
    );
    let o = run(&[
        "synth",
        "--truth",
        "four-wheel",
        "--effects",
        "road_bank",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains(
            "effect `road_bank`: not one the four-wheel truth's handling programme can show"
        ) && e.contains("roll_camber"),
        "{e}"
    );
    assert!(!out.exists(), "a refused synth writes nothing");
    // The default truth is still the augmented model: no [roll] guess.
    let o = run(&[
        "synth",
        "--effects",
        "road_bank",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(out.join("vehicle.toml")).unwrap();
    assert!(
        text.contains("--truth augmented") && !text.contains("[roll]"),
        "{text}"
    );
}
