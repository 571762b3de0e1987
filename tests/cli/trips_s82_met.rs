//! What a fresh user tripped on in `metrics` and in `simulate`'s replay
//! wording (session 82): a noisy step's overshoot cut short by one noise
//! dip (a rising flank's top read as the peak) with no word of its
//! spread; `ay` in ft/s² said only to "disagree"; a replay's "within three
//! noise floors (0.0021 rad/s)" whose bracket held one floor.

use super::sedan_runs::{run_file, sedan_history, Noisy};
use super::*;

/// A 200 Hz copy of the sedan's step with a gyro noise of 0.0055 rad/s
/// (the tester's nz_6.csv: 2.4 % of the step after the 10 Hz low-pass).
/// The noise-free step overshoots by 16.90 % at 0.435 s; with seed 10 one
/// noise dip at 1.30 s ended the "first stretch above the threshold" at
/// its rising flank: overshoot 12.89 % at 0.295 s, and the warning said
/// only the peak time moves. Now a dip of the noise alone does not end the
/// overshoot: 19.47 % at 0.385 s, and the warning gives the overshoot's
/// spread over the noisy copies beside the peak time's. The noise-free
/// step's figures are unchanged.
#[test]
fn a_noise_dip_does_not_cut_the_overshoot_and_its_spread_is_said() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let clean = dir.path().join("clean.csv");
    run_file(
        &history,
        5,
        Noisy {
            yaw: 0.0,
            ay: 0.0,
            seed: 1,
            ay_gain: 1.0,
        },
        &clean,
    );
    let (j, _) = metrics_json(&clean);
    let overshoot = j["yaw_rate_overshoot"].as_f64().unwrap();
    let peak = j["yaw_rate_peak_time"].as_f64().unwrap();
    assert!((overshoot - 16.90).abs() < 0.005, "{overshoot}");
    assert!((peak - 0.435).abs() < 1e-9, "{peak}");
    let noisy = dir.path().join("noisy.csv");
    run_file(
        &history,
        5,
        Noisy {
            yaw: 0.0055,
            ay: 0.1,
            seed: 10,
            ay_gain: 1.0,
        },
        &noisy,
    );
    let (j, warnings) = metrics_json(&noisy);
    let overshoot = j["yaw_rate_overshoot"].as_f64().unwrap();
    assert!((overshoot - 19.47).abs() < 0.005, "{overshoot}");
    let peak = j["yaw_rate_peak_time"].as_f64().unwrap();
    assert!((peak - 0.385).abs() < 1e-9, "{peak}");
    let spread = j["yaw_rate_overshoot_spread"].as_f64().unwrap();
    assert!((spread - 1.6).abs() < 0.05, "{spread}");
    let said = "moves by ±0.099 s (26 %, one standard deviation), and the overshoot, 19.47 %, by ±1.6 points; read the peak time and TB with it, and the overshoot as uncertain by that much";
    assert!(warnings.iter().any(|w| w.contains(said)), "{warnings:?}");
}

/// A run whose `ay` is in ft/s² (3.281 times speed × yaw rate) was
/// measured with exit 0, its ay metrics left out with "a gain, unit or
/// sign": `ay` in g and a speed in km/h are each named with their unit.
/// Now ft/s² is named too, at the first turning row, with its factor.
#[test]
fn ay_in_feet_per_second_squared_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let feet = dir.path().join("feet.csv");
    run_file(
        &history,
        10,
        Noisy {
            yaw: 0.0,
            ay: 0.0,
            seed: 1,
            ay_gain: 1.0 / 0.3048,
        },
        &feet,
    );
    let o = run(&["metrics", feet.to_str().unwrap()]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("feet.csv:"), "{e}");
    assert!(e.contains("column `ay`"), "{e}");
    assert!(e.contains("`ay` is a median 3.281 of it"), "{e}");
    assert!(
        e.contains("is `ay` in ft/s²? multiply it by 0.3048 (FORMATS.md: m/s²)"),
        "{e}"
    );
}

/// A replay's verdict read "RMS 0.0021 rad/s within three noise floors
/// (0.0021 rad/s)": the bracket held one floor, as if the RMS sat at the
/// line. Now it gives the floor and three of them.
#[test]
fn a_replay_gap_names_the_floor_and_three_of_them() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let noisy = dir.path().join("noisy.csv");
    run_file(
        &history,
        5,
        Noisy {
            yaw: 0.0055,
            ay: 0.1,
            seed: 10,
            ay_gain: 1.0,
        },
        &noisy,
    );
    let tyres = root().join("tyres");
    let scenario = dir.path().join("replay.toml");
    let text = bundled_scenario("sedan_step.toml");
    let vehicle = &text[text.find("[vehicle]").unwrap()..text.find("[tyres]").unwrap()];
    fs::write(
        &scenario,
        format!(
            "name = \"replay\"\n{vehicle}[tyres]\nfront = {:?}\nrear = {:?}\n\n[manoeuvre]\nkind = \"replay\"\nrun = {:?}\n",
            tyres.join("gim_sedan_front.toml"),
            tyres.join("gim_sedan_rear.toml"),
            noisy
        ),
    )
    .unwrap();
    let out = dir.path().join("out");
    let said = succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let all = format!(
        "{said}{}",
        fs::read_to_string(out.join("gap.txt")).unwrap_or_default()
    );
    assert!(
        all.contains("yaw_rate: no significant gap: RMS 0.0056 rad/s, within three noise floors (noise floor 0.0056 rad/s, 3× = 0.0167 rad/s)"),
        "{all}"
    );
    assert!(!all.contains("within three noise floors (0.0"), "{all}");
}
