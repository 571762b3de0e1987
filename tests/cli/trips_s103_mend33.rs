//! A step past the lateral limit on a bank, refused from the file: the
//! sentence says the tyres' lateral acceleration (the change asked plus
//! g·sin θ) to six digits, the rounding done where the sentence is made
//! (session 103: the error's data carried the rounded value).

use super::*;

/// The bundled PAC89 step on a road banked 0.05 rad, asked for 12 m/s²:
/// the tyres would hold 12 + g·sin 0.05 = 12.49012… m/s², past their
/// limit (9.91 m/s²) and short of the rollover's.
#[test]
fn a_banked_step_past_the_limit_says_the_tyres_ay_to_six_digits() {
    let text = bundled_scenario("step_gbt6323_pac89.toml")
        .replace(
            "load_transfer = true",
            "load_transfer = true\neffects = { road_bank = 0.05 }",
        )
        .replace(
            "lateral_acceleration = 2.0 ",
            "lateral_acceleration = 12.0 ",
        );
    let dir = scratch(&[("banked.toml", &text)]);
    let e = fails_cleanly("simulate", &dir.path().join("banked.toml"), dir.path());
    let said = "`manoeuvre.lateral_acceleration` = 12: no steady state at 22.2222 m/s with ay = 12.4901 m/s²: beyond the vehicle's lateral limit at this speed, 9.91 m/s² with these tyres and this road";
    assert!(e.contains(said), "no {said:?} in {e}");
}
