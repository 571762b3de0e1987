//! What a fresh-eyes round on simulated real logs (round 27B) found
//! missing from the effect library: an inertial unit yawed 2° in its mount
//! (its accelerometer reads part of the longitudinal acceleration as
//! lateral) was "outside the library", the best candidate removing 0.5 %
//! of the gap. Now a candidate `mount_yaw` (ψₘ, ISO 8855: positive turns
//! the unit's x axis left; ay read as ay·cos ψₘ − ax·sin ψₘ), diagnosed as
//! a user runs it: a synthesised road course (which logs `ax`) on three
//! seeds, and a road course whose logged `ay` and `ax` the test turns itself.

use super::trips_s94_met::written;
use super::*;

/// The look-alikes a yawed mount is told from (a constant offset, an
/// accelerometer ahead of the centre of gravity, a rolling one, and the
/// effects that follow ax) beside it: the campaign's candidates, a third
/// of the library's time.
const LOOK_ALIKES: &str = "effects = [\"mount_yaw\", \"sensor_bias\", \"accelerometer_position\", \"accelerometer_roll\", \"longitudinal_load_transfer\", \"combined_slip\"]";

/// `campaign`'s `[diagnose]` restricted to [`LOOK_ALIKES`].
fn among_look_alikes(campaign: &Path) {
    let v = campaign.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    assert!(text.contains("[diagnose]\n"), "{text}");
    let text = text.replace("[diagnose]\n", &format!("[diagnose]\n{LOOK_ALIKES}\n"));
    fs::write(&v, text).unwrap();
}

/// The verdict's effects and its value of `mount_yaw.angle` with its
/// standard error.
fn named_angle(said: &str, d: &serde_json::Value) -> (Vec<String>, f64, f64) {
    let v = &d["verdict"];
    assert_eq!(v["kind"], "explained", "{said}");
    let effects = v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_string())
        .collect();
    let p = v["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "mount_yaw.angle")
        .unwrap_or_else(|| panic!("no mount_yaw.angle: {said}"));
    let value = p["value"].as_f64().unwrap();
    let se = p["std_error"].as_f64().unwrap_or(f64::NAN);
    (effects, value, se)
}

/// `synth --effects mount_yaw --programme road-course` (truth: the unit
/// turned 3° left, 0.05236 rad; trail braking and throttle out of the
/// corners, `ax` logged) on seeds 1 to 3: before, an unknown effect; now
/// each names it with its angle within 0.004 rad (0.2°) of the truth.
#[test]
fn a_synthesised_mount_yaw_is_named_on_three_seeds_with_its_angle() {
    let dir = tempfile::tempdir().unwrap();
    let campaigns: Vec<PathBuf> = ["1", "2", "3"]
        .iter()
        .map(|seed| {
            let c = synth_campaign(
                dir.path(),
                &format!("s{seed}"),
                &[
                    "--effects",
                    "mount_yaw",
                    "--programme",
                    "road-course",
                    "--seed",
                    seed,
                ],
            );
            among_look_alikes(&c);
            c
        })
        .collect();
    let results = diagnosed_together(&campaigns);
    for (said, d) in &results {
        let (effects, angle, _) = named_angle(said, d);
        assert_eq!(effects, ["mount_yaw"], "{said}");
        assert!((angle - 0.05236).abs() < 0.004, "angle {angle}: {said}");
        assert!(said.contains("mount_yaw.angle = 0.05"), "{said}");
    }
}

/// Round 27B's `s_yaw2` on the road course: its generator turns the unit
/// to the right (it writes ay·cos ψ + ax·sin ψ, and ax·cos ψ − ay·sin ψ).
/// Done here to a clean synthesised campaign's logged `ay` and `ax` by
/// the test's own arithmetic, at 3°: the verdict is mount_yaw at −3°
/// (−0.0524 rad), the sign ISO 8855's. (At 2° the road course's gap,
/// 1.23 against a noise level of 1.00, is within the verdict's 1.3 ×
/// rule: mount_yaw is listed at −0.0352 ± 0.0013 rad, the verdict "no
/// significant gap".)
#[test]
fn a_unit_turned_3_degrees_right_in_a_logged_road_course_is_a_mount_yaw_of_minus_3_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &[
            "--effects",
            "none",
            "--programme",
            "road-course",
            "--seed",
            "1",
        ],
    );
    among_look_alikes(&c);
    let runs = c.join("runs");
    let psi = 3f64.to_radians();
    for entry in fs::read_dir(&runs).unwrap() {
        let path = entry.unwrap().path();
        let text = fs::read_to_string(&path).unwrap();
        let header = text.lines().next().unwrap().to_string();
        assert_eq!(header, "t,speed,steer,yaw_rate,ay,ax,bank");
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        // Every column kept (the bank too), ay and ax turned.
        let lines: Vec<String> = text
            .lines()
            .skip(1)
            .map(|l| {
                let mut c: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
                let (ay, ax) = (c[4], c[5]);
                c[4] = ay * psi.cos() + ax * psi.sin();
                c[5] = ax * psi.cos() - ay * psi.sin();
                let cells: Vec<String> = c.iter().map(|v| format!("{v}")).collect();
                cells.join(",")
            })
            .collect();
        written(&runs, &name, &header, lines.into_iter());
    }
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    let (effects, angle, se) = named_angle(&said, &d);
    assert_eq!(effects, ["mount_yaw"], "{said}");
    assert!((angle + psi).abs() < 0.004, "angle {angle} ± {se}: {said}");
    assert!(se > 0.0 && se < 0.003, "{se}: {said}");
}
