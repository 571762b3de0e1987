//! The slow oval's base axles left their prior (session 109).
//! From session 101 on, the base identification of the slow oval
//! (`synth --programme slow-oval --effects bank_profile --seed 1`, no tyre
//! data) picked its basin under the untempered prior, where the runs'
//! 28,690 correlated residuals outweigh it, and landed at 138 / 190 1/rad,
//! 5.6 and 6.5 σ outside the road prior's 8–35 1/rad; the tempered polish
//! (the prior ×139) only polished that basin. Such axles are no tyre
//! (they peak before 2° of slip) and too stiff for RK4 at the 0.02 s
//! step: every replay went by the implicit ROS34PW2. The base now starts
//! from the basin best under the tempered prior.

use super::*;
use handling::tyre::{Tyre, TyreModel};

/// The truth's cornering coefficient (cornering stiffness per unit load,
/// 1/rad) of each axle: synth's bundled UniTire at the static wheel loads
/// of the campaign's car (its `vehicle.toml`).
fn true_coefficients(campaign: &Path) -> [f64; 2] {
    let text = fs::read_to_string(campaign.join("vehicle.toml")).unwrap();
    let v: toml::Value = toml::from_str(&text).unwrap();
    // synth writes the mass as an integer (790), the lengths as floats.
    let num = |k: &str| {
        let x = &v["vehicle"][k];
        x.as_float()
            .or_else(|| x.as_integer().map(|i| i as f64))
            .unwrap_or_else(|| panic!("vehicle.{k}: {x}"))
    };
    let (m, a, b) = (num("mass"), num("a"), num("b"));
    let text = fs::read_to_string(root().join("tyres/unitire.toml")).unwrap();
    let tyre: Tyre = toml::from_str(&text).unwrap();
    // Half an axle's static load on each wheel.
    let wheel = |share: f64| m * 9.80665 * share / 2.0;
    [wheel(b / (a + b)), wheel(a / (a + b))].map(|fz| tyre.cornering_stiffness(fz) / fz)
}

#[test]
fn the_slow_ovals_base_axles_stay_inside_their_prior_and_replay_by_rk4() {
    let dir = tempfile::tempdir().unwrap();
    // The base is fitted before any candidate: one candidate suffices.
    let c = synth_extended(
        dir.path(),
        "slow-oval",
        "bank_profile",
        "1",
        "effects = [\"bank_profile\"]\nmax_effects = 1\n",
    );
    let (stdout, d) = diagnose_campaign(&c);
    let axles = &d["base"]["axles"];
    let prior = &axles["prior"];
    assert_eq!(prior["prior"]["cornering"], serde_json::json!([8.0, 35.0]));
    // The prior's weight as session 108 measured it on this campaign.
    let weight = prior["tempering"]["prior_weight"].as_f64().unwrap();
    assert!((weight - 139.1).abs() < 0.5, "{weight}");
    let truth = true_coefficients(&c);
    // UniTire's 14 − 2·Fz/Fz_rated at 2252 and 1622 N.
    assert!((truth[0] - 13.24).abs() < 0.01 && (truth[1] - 13.45).abs() < 0.01);
    for (i, against) in prior["against"].as_array().unwrap()[..2].iter().enumerate() {
        let z = against["z"].as_f64().unwrap();
        let k = against["value"].as_f64().unwrap();
        // Inside the prior's 95 % range (the stiff base: +5.6, +6.5 σ).
        assert!(
            z.abs() <= 1.96 && against["within"] == true,
            "axle {i}: {against}"
        );
        // Within a factor two of the truth, as the prior's own range
        // is (the stiff base: 10 and 14 times it).
        assert!(
            (k / truth[i]).ln().abs() < 2f64.ln(),
            "axle {i}: {k} against {}",
            truth[i]
        );
    }
    assert_eq!(axles["no_tyre"], serde_json::json!([]), "{axles}");
    // What the user reads: the axles within the prior, no "no tyre", and
    // the replays by the explicit RK4 (no stiff-replay note).
    assert!(stdout.contains("the axles lie within it"), "{stdout}");
    assert!(!stdout.contains("no tyre:"), "{stdout}");
    let notes = d["notes"].to_string();
    assert!(!notes.contains("too stiff for RK4"), "{notes}");
    assert!(!stdout.contains("too stiff for RK4"), "{stdout}");
}
