//! What a fresh user tripped on in `identify` and in campaign and scenario
//! files (round 12): a road without grip in a campaign asked whether it
//! was a speed, a per-axle array of three numbers (or a decimal comma's
//! four) run on its first two, the unfitted `mz` counted over the whole
//! file under a selection, a decay at its physical limit 0 called a
//! failed fit, a slip angle column in degrees fitted without a word, and
//! a staged fit's pooled σ led by rows no stage fits.

use super::*;

/// A campaign with a linear tyre, an empty runs folder and `road`.
fn campaign_with_road(road: &str) -> tempfile::TempDir {
    let text = format!(
        "name = \"c\"\n{VEHICLE}[tyres]\nfront = \"tyre.toml\"\n[runs]\ndir = \"runs\"\n[road]\n{road}\n"
    );
    let dir = scratch(&[("c.toml", &text)]);
    linear_tyre(dir.path());
    fs::create_dir(dir.path().join("runs")).unwrap();
    dir
}

/// `[road] friction = 0` in a campaign was asked "is it a speed or a
/// percentage?" (the range's top's hint); a scenario already said "must
/// be positive".
#[test]
fn a_campaign_road_without_grip_is_said_not_positive() {
    let dir = campaign_with_road("friction = 0");
    let e = fails_cleanly("diagnose", &dir.path().join("c.toml"), dir.path());
    assert!(
        e.contains("c.toml:15:12: `road.friction` = 0: must be positive"),
        "{e}"
    );
    assert!(!e.contains("a speed or a percentage"), "{e}");
}

/// `aero_load = [0.5, 0.6, 0.7]` ran as `[0.5, 0.6]`, and a decimal
/// comma's `[0,5, 0,6]` as `[0, 5]`: a per-axle key takes exactly two.
#[test]
fn a_per_axle_effect_of_other_than_two_numbers_is_refused_at_its_key() {
    for (value, found) in [("[0.5, 0.6, 0.7]", 3), ("[0,5, 0,6]", 4)] {
        let effects = format!("[model.effects]\naero_load = {value}\n\n{STEP}");
        let dir = scenario(VEHICLE, GIM, &effects);
        let e = simulate_err(dir.path());
        assert!(
            e.contains(&format!(
                "scenario.toml:14:13: `model.effects.aero_load`: invalid length {found}, expected an array of length 2 (front, rear); decimals take a point: [0,5, 0,6] is four numbers, [0.5, 0.6] two"
            )),
            "{value}: {e}"
        );
    }
    // Two are read as before.
    let dir = scenario(
        VEHICLE,
        GIM,
        &format!("[model.effects]\nroll_steer = [0.1, 0.0]\n\n{STEP}"),
    );
    let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
}
