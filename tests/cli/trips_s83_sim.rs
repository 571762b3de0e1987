//! What a user still tripped on in `simulate` (session 83, a fresh user's report): an
//! effect's key under `[model]` or `[road]` refused without the table it
//! belongs in, a road of no friction asked whether it was a speed, a share
//! of 9.9999 % said as "10.0 %, less than the 10 %", a history's size
//! quoted at twice the file written, 2,000,002 rows said as "2000000 rows,
//! beyond the 2000000", a decimal comma named as a stray comma, and a
//! steering ratio of 1e9 read without a word.

use super::*;

/// A step steer of 1° at 80 km/h from 1 s to 6 s.
const STEP_6S: &str = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n";

/// A scenario of the sedan on a Gim tyre: `vehicle` (the `[vehicle]`
/// table), then `rest` after its `[tyres]` table.
fn sedan(vehicle: &str, rest: &str) -> tempfile::TempDir {
    let sc = format!("{vehicle}\n[tyres]\nfront = \"tyre.toml\"\n\n{rest}");
    scratch(&[("scenario.toml", &sc), ("tyre.toml", GIM)])
}

/// `simulate`'s stderr on the scenario `vehicle` + `rest`, which must fail.
fn refused(vehicle: &str, rest: &str) -> String {
    let dir = sedan(vehicle, rest);
    fails_cleanly("simulate", &dir.path().join("scenario.toml"), dir.path())
}

#[test]
fn an_effects_key_under_model_or_road_is_sent_to_model_effects() {
    let said = refused(
        VEHICLE,
        &format!("{STEP_6S}\n[model]\nrelaxation_length = 0.5\n"),
    );
    assert!(
        said.contains("scenario.toml:22:1: `model.relaxation_length`: unknown field `relaxation_length` (it belongs in [model.effects]), expected"),
        "{said}"
    );
    let said = refused(
        VEHICLE,
        &format!("{STEP_6S}\n[road]\nfriction = 1.0\nroad_bank = 0.05\n"),
    );
    assert!(
        said.contains("scenario.toml:23:1: `road.road_bank`: unknown field `road_bank` (it belongs in [model.effects]), expected `friction`"),
        "{said}"
    );
    // The name the diagnosis gives the effect, said with the key.
    let said = refused(VEHICLE, &format!("{STEP_6S}\n[road]\nbank = 0.05\n"));
    assert!(
        said.contains(
            "`road.bank`: unknown field `bank` (it belongs in [model.effects], as `road_bank`)"
        ),
        "{said}"
    );
    // A sensor's effect has no table in a scenario: said why.
    let said = refused(
        VEHICLE,
        &format!("{STEP_6S}\n[model]\nsensor_delay = 0.05\n"),
    );
    assert!(
        said.contains("(`sensor_delay` is an effect of the measurement (the sensors and the steer they log), not of the car"),
        "{said}"
    );
}

#[test]
fn an_effects_key_in_a_campaign_is_sent_to_diagnose_effects() {
    let text = format!("name = \"c\"\n{VEHICLE}\n[road]\nfriction = 1.0\nrelaxation_length = 0.5\n\n[diagnose]\nseed = 1\n");
    let dir = scratch(&[("campaign.toml", &text)]);
    let said = fails_cleanly("diagnose", &dir.path().join("campaign.toml"), dir.path());
    assert!(
        said.contains("campaign.toml:13:1: `road.relaxation_length`: unknown field `relaxation_length` (`relaxation_length` is an effect `handling diagnose` fits to the runs: name it in `[diagnose] effects = [\"relaxation_length\"]`), expected `friction`"),
        "{said}"
    );
}

#[test]
fn a_road_of_no_friction_is_said_not_positive() {
    for v in ["0", "0.0", "-0.5"] {
        let said = refused(VEHICLE, &format!("{STEP_6S}\n[road]\nfriction = {v}\n"));
        assert!(
            said.contains(&format!(
                "scenario.toml:22:12: `road.friction` = {}: must be positive",
                v.trim_end_matches(".0")
            )),
            "{said}"
        );
        assert!(!said.contains("percentage"), "{said}");
    }
}

#[test]
fn a_share_just_below_ten_percent_is_said_below_it() {
    // sin(2π·0.0015942·10) = 0.099999: a hair below the 10 % a sine must
    // reach, once said as "10.0 %, less than the 10 %".
    let sine = "[manoeuvre]\nkind = \"sine\"\nspeed = 20.0\namplitude = 0.1\nfrequency = 0.0015942\nstart = 0.0\nend = 10.0\n";
    let said = refused(VEHICLE, sine);
    assert!(
        said.contains(
            "9.9999 % of its `amplitude` = 0.1 rad (5.73°), less than the 10 % a sine must reach"
        ),
        "{said}"
    );
}

/// The number before ` MB of history.csv` in `said`, in bytes.
fn quoted_size(said: &str) -> f64 {
    let head = said.split(" MB of history.csv").next().unwrap();
    let mb: f64 = head.rsplit("about ").next().unwrap().parse().unwrap();
    mb * 1e6
}

#[test]
fn the_quoted_history_size_is_the_written_ones() {
    // Refused at 2.5e-6 s: 2,400,001 rows, the size quoted for them.
    let said = refused(
        VEHICLE,
        &format!("{STEP_6S}\n[simulation]\nstep = 2.5e-6\n"),
    );
    assert!(said.contains("makes 2400001 rows (about "), "{said}");
    let per_row_quoted = quoted_size(&said) / 2_400_001.0;
    // Written at 1e-3 s: 6001 rows.
    let dir = sedan(VEHICLE, STEP_6S);
    let out = dir.path().join("out");
    let sc = dir.path().join("scenario.toml");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let written = fs::metadata(out.join("history.csv")).unwrap().len() as f64;
    let per_row_written = written / 6001.0;
    let ratio = per_row_quoted / per_row_written;
    assert!(
        (0.8..=1.2).contains(&ratio),
        "quoted {per_row_quoted} B/row, written {per_row_written}: {said}"
    );
}

#[test]
fn one_row_over_the_limit_is_counted_whole_with_the_key_to_change() {
    // 6 s / 2.9999985e-6 s = 2,000,001 steps: 2,000,002 rows.
    let said = refused(
        VEHICLE,
        &format!("{STEP_6S}\n[simulation]\nstep = 2.9999985e-6\n"),
    );
    assert!(
        said.contains("scenario.toml:22:8: `simulation.step` = 2.9999985e-6: the run lasts 6 s: a row every 2.9999985e-6 s ([simulation] step) makes 2000002 rows (about 300 MB of history.csv), 1 more than the 2000001 a history holds (a first row and 2000000 steps after it); set `step` under [simulation] to at least 3e-6 s, or shorten the run (the manoeuvre's `end`)"),
        "{said}"
    );
}

#[test]
fn a_decimal_comma_is_said_with_the_point_to_write() {
    let vehicle = VEHICLE.replace("mass = 1530.0", "mass = 1530,0   # kg");
    let said = refused(&vehicle, STEP_6S);
    assert!(
        said.contains(
            "scenario.toml:2:12: `vehicle.mass`: `1530,0`: a decimal comma? write 1530.0"
        ),
        "{said}"
    );
    let said = refused(
        VEHICLE,
        &STEP_6S.replace("steer = 0.0174533", "steer = 0,0174533"),
    );
    assert!(
        said.contains("`manoeuvre.steer`: `0,0174533`: a decimal comma? write 0.0174533"),
        "{said}"
    );
}

#[test]
fn a_steering_ratio_outside_one_to_a_hundred_is_refused_at_its_line() {
    for v in ["1e9", "0.5", "150.0"] {
        let vehicle = format!("{VEHICLE}steering_ratio = {v}\n");
        let said = refused(&vehicle, STEP_6S);
        assert!(
            said.contains("scenario.toml:9:18: `vehicle.steering_ratio` = ") && said.contains(": must lie in 1–100: a steering ratio is the steering-wheel angle over the road-wheel angle"),
            "{said}"
        );
    }
    // A car's and a kart's are read.
    for v in ["16.0", "1.0"] {
        let dir = sedan(&format!("{VEHICLE}steering_ratio = {v}\n"), STEP_6S);
        let sc = dir.path().join("scenario.toml");
        let out = dir.path().join("out");
        succeeds(&[
            "simulate",
            sc.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
    }
}
