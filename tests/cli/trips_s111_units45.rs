//! Session 111, units45: a yaw rate in rad/s declared in degrees (read
//! 57.3× too small) was taken by `diagnose` without a word where its steer
//! is too gentle for the steer check (an ISO 7401 step at 100 km/h and
//! 2 m/s² steers 0.008 rad) and its `u·r` too small for the slope check;
//! the calibration took the steady 2 m/s² turn for a straight with an `ay`
//! offset of 1.98 m/s². And a refusal of six runs alike named the first
//! and not the two taken.

use super::calibration::{diagnosed, Noise};
use super::*;

/// The refusal's `reads N× too small`.
fn too_small(e: &str) -> f64 {
    let at = e
        .find("the yaw rate reads ")
        .unwrap_or_else(|| panic!("{e}"));
    let rest = &e[at + "the yaw rate reads ".len()..];
    rest[..rest.find('×').unwrap()].parse().unwrap()
}

/// The tester's `one_deg` campaign: synth's 100 km/h 2 m/s² step (logged
/// in rad/s) and its sweep, with `degrees = ["yaw_rate"]`. Refused at the
/// `degrees` entry with each run's factor (the step by its steady `ay`,
/// the sweep by the steer check) and the fix; `metrics` refuses the step
/// at its row and column with the factor and the fix.
#[test]
fn a_yaw_rate_declared_in_degrees_is_refused_by_its_steady_ay_in_diagnose_and_metrics() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let vehicle = fs::read_to_string(c.join("vehicle.toml")).unwrap();
    let campaign = c.join("one_deg.toml");
    let runs = "[runs]\nfiles = [\"runs/step_100kph_2ms2.csv\", \"runs/sweep_080kph.csv\"]\ndegrees = [\"yaw_rate\"]\n";
    fs::write(&campaign, format!("{vehicle}\n{runs}")).unwrap();
    let said = fails_cleanly("diagnose", &campaign, dir.path());
    // Session 113 (units48): both runs read 57× small, so the refusal
    // stands at the `degrees` entry that makes them so, once, naming each
    // run and how it was found (the sweep by its steer, the step by its
    // `ay`).
    let text = format!("{vehicle}\n{runs}");
    let line = text.lines().position(|l| l.starts_with("degrees")).unwrap() + 1;
    assert!(
        said.starts_with(&format!(
            "error: {}:{line}:12: `degrees` under [runs] declares `yaw_rate` in deg/s for every run",
            campaign.display()
        )),
        "{said}"
    );
    let step = c.join("runs/step_100kph_2ms2.csv");
    let by_ay = format!("in {} (ay/(speed·yaw_rate) = ", step.display());
    let at = said.find(&by_ay).unwrap_or_else(|| panic!("{said}"));
    let rest = &said[at + by_ay.len()..];
    let factor: f64 = rest[..rest.find(')').unwrap()].parse().unwrap();
    // 57.3 within the noise of the means.
    assert!((factor / 57.2958 - 1.0).abs() < 0.03, "{said}");
    assert!(
        said.contains(&c.join("runs/sweep_080kph.csv").display().to_string()),
        "{said}"
    );
    assert!(
        said.contains("take \"yaw_rate\" out of `degrees`"),
        "{said}"
    );
    assert!(!said.contains("calibration"), "{said}");
    // `metrics` on the step with the same declaration refuses it at its
    // row and column (the yaw rate is the file's fourth), by the factor.
    let o = run(&["metrics", step.to_str().unwrap(), "--degrees", "yaw_rate"]);
    assert!(!o.status.success());
    let m = stderr(&o);
    let place =
        &m[format!("error: {}:", step.display()).len()..m.find(": column `yaw_rate`: ").unwrap()];
    let (row, column) = place.split_once(':').unwrap();
    assert!(row.parse::<usize>().unwrap() > 100, "{m}");
    assert_eq!(column, "4", "{m}");
    assert!((too_small(&m) / 57.2958 - 1.0).abs() < 0.03, "{m}");
    assert!(
        m.contains(
            "57.3× is a yaw rate in rad/s read as deg/s: was `yaw_rate` declared in degrees"
        ) && m.contains("Take it out of `degrees`"),
        "{m}"
    );
    // Read as logged, the step is measured.
    assert!(run(&["metrics", step.to_str().unwrap()]).status.success());
}

/// A log at 25 m/s, 100 Hz, 20 s: steer `steer`, `ay` steady at `ay`
/// (noise 0.05 m/s²), the yaw rate `yaw` (noise 0.002 rad/s × `yaw` of
/// the true one's scale: read as logged).
fn steady(seed: u64, steer: f64, ay: f64, yaw: f64, scale: f64) -> String {
    let mut noise = Noise(seed);
    let mut s = String::from("t,speed,steer,yaw_rate,ay\n");
    for i in 0..2000 {
        s += &format!(
            "{:.2},25.0,{steer:.6},{:.7},{:.5}\n",
            i as f64 * 0.01,
            yaw + 0.002 * scale * noise.gauss(),
            ay + 0.05 * noise.gauss()
        );
    }
    s
}

/// A steady 2 m/s² with the steer straight and no yaw rate (a banked road
/// without its bank column) is no straight, and a steady 0.8 m/s² whose
/// yaw rate reads 57.3× too small (too gentle for any check of the yaw
/// rate's unit) passes the straights' tests but gives an offset no
/// accelerometer has, said with what it more likely is.
#[test]
fn a_steady_ay_is_no_straight_and_an_offset_no_accelerometer_has_is_said() {
    let slipped = 1.0 / 57.2958;
    let gentle = steady(2, 0.0056, 0.8, 0.8 / 25.0 * slipped, slipped);
    let (_dir, stdout, d) = diagnosed(&[
        ("banked.csv", steady(1, 0.0, 2.0, 0.0, 1.0)),
        ("gentle.csv", gentle),
    ]);
    let line = stdout
        .lines()
        .find(|l| l.starts_with("  calibration: ay offset"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(
        line.contains(" m/s² on 1 straight (")
            && line.contains("; the straights' 0.80 m/s² is beyond the 0.01–0.5 m/s² of an automotive MEMS accelerometer's bias: more likely a turn read as a straight (a yaw rate read too small: is its unit right?)"),
        "{stdout}"
    );
    let spans = d["calibration"]["spans"].as_array().unwrap();
    assert!(
        spans
            .iter()
            .all(|s| s["run"].as_str().unwrap().ends_with("gentle.csv")),
        "{spans:?}"
    );
    assert_eq!(d["calibration"]["criteria"]["straight_ay"], 1.0);
}

/// synth's campaign with `degrees = ["yaw_rate"]` on runs in rad/s but
/// the sweep's (written in deg/s here): six read 57× small by the steer
/// check, the 100 km/h step by its steady `ay`; the run taken, the sweep,
/// is named. Since session 113 (round 48) the seven are one refusal at
/// the `degrees` entry, their cause, which names the sweep as the run
/// that reads right so (to convert in its file).
#[test]
fn runs_refused_alike_name_the_runs_that_passed() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let vehicle = c.join("vehicle.toml");
    let text = fs::read_to_string(&vehicle).unwrap();
    let runs = "[runs]\ndegrees = [\"yaw_rate\"]\n";
    fs::write(&vehicle, format!("{text}\n{runs}")).unwrap();
    let sweep = c.join("runs/sweep_080kph.csv");
    map_column(&sweep, "yaw_rate", f64::to_degrees);
    let e = fails_cleanly("diagnose", &c, dir.path());
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(lines.len(), 1, "{e}");
    assert!(
        lines[0].contains("vehicle.toml:")
            && lines[0].contains("the yaw rate is far too small in 7 of the 8 runs: far smaller than a neutral car's for the steer in "),
        "{e}"
    );
    assert!(
        lines[0].contains("step_100kph_2ms2.csv (ay/(speed·yaw_rate) = "),
        "{e}"
    );
    let sweep = sweep.display();
    assert!(
        lines[0].contains(&format!("{sweep} reads right so"))
            && lines[0].contains(&format!(
                "convert the yaw rate of {sweep} to rad/s in its file"
            )),
        "{e}"
    );
}
