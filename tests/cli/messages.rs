//! What a new user reads: numbers without float noise, user words instead
//! of internal names, normalised paths, the same checks and spellings
//! across commands.

use super::*;

/// A step-steer scenario whose `[manoeuvre]` table is `manoeuvre`.
fn step_scenario(manoeuvre: &str) -> tempfile::TempDir {
    scenario(VEHICLE, GIM, &format!("[manoeuvre]\n{manoeuvre}"))
}

#[test]
fn a_range_shows_clean_bounds_and_a_guarded_zero_as_closed() {
    let dir = step_scenario(
        "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nrise_time = 0.3\n",
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("`manoeuvre.rise_time` = 0.3: must lie in [0, 0.1875]:"),
        "{e}"
    );
    assert!(
        !e.contains("0.18749999") && !e.contains("0.000000000001"),
        "{e}"
    );
}

#[test]
fn a_manoeuvre_kind_is_read_with_underscores_as_with_hyphens() {
    for kind in ["step-steer", "step_steer"] {
        let dir = step_scenario(&format!(
            "kind = \"{kind}\"\nspeed = 22.2222\nsteer = 0.0174533\n"
        ));
        let out = dir.path().join("out");
        let o = run(&[
            "simulate",
            dir.path().join("scenario.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
    }
}
