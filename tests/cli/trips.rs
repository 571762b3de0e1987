//! What a new user trips on, run as a user runs the tool: each test is one
//! thing a fresh user met, and the message or refusal the tool now gives.

use super::*;

/// The stderr of `args`, which must fail.
fn fails(args: &[&str]) -> String {
    let o = run(args);
    assert!(!o.status.success(), "expected failure: {args:?}");
    stderr(&o)
}

#[test]
fn a_mistyped_effect_model_or_programme_is_answered_with_the_nearest_name() {
    let e = fails(&[
        "synth",
        "--effects",
        "sensor_dely",
        "--out",
        "/nonexistent/x",
    ]);
    assert!(
        e.contains("unknown effect `sensor_dely` (did you mean `sensor_delay`?): one of none,"),
        "{e}"
    );
    let e = fails(&["synth", "--programme", "ovl", "--out", "/nonexistent/x"]);
    assert!(e.contains("(did you mean `oval`?)"), "{e}");
    // Nothing near: no guess.
    let e = fails(&[
        "synth",
        "--programme",
        "autobahn",
        "--out",
        "/nonexistent/x",
    ]);
    assert!(!e.contains("did you mean"), "{e}");
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,800\n")]);
    let o = identify_to(
        &dir.path().join("rig.csv"),
        "pac98",
        &dir.path().join("t.toml"),
    );
    let e = refused(&o, &dir.path().join("t.toml"));
    assert!(e.contains("(did you mean `pac89`?)"), "{e}");
    // A tyre file's model, and a campaign's effects (read by the campaign
    // reader, at their key and line).
    let dir = scenario(VEHICLE, "model = \"unitrie\"\n", STEP);
    let e = simulate_err(dir.path());
    assert!(
        e.contains("tyre.toml:1:9")
            && e.contains("unknown variant `unitrie` (did you mean `unitire`?)"),
        "{e}"
    );
    let campaign = format!("{VEHICLE}\n[diagnose]\neffects = [\"relaxation_lenght\"]\n");
    let dir = scratch(&[("campaign.toml", &campaign)]);
    let e = fails_cleanly("diagnose", &dir.path().join("campaign.toml"), dir.path());
    assert!(e.contains("campaign.toml:"), "{e}");
    assert!(
        e.contains("unknown effect `relaxation_lenght` (did you mean `relaxation_length`?)"),
        "{e}"
    );
}

