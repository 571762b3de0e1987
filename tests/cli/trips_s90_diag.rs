//! What fresh-eyes users tripped on in round 16, run as a user
//! runs the tool: a vehicle file's yaw inertia 1.5× the car's beside a
//! sensor delay called a model-form error outside the library (the pair
//! the truth is never tried), a wheelbase that is not a + b refused
//! without the difference or where a and b are, a replay's advice on a
//! channel near the sensor/estimate line that the replay cannot follow,
//! and a negative sideslip said to grow.

use super::*;

/// `synth --effects sensor_delay --seed 1`, its vehicle file's `from`
/// line replaced by `to`.
pub(crate) fn edited_campaign(dir: &Path, from: &str, to: &str) -> PathBuf {
    let c = synth_campaign(dir, "c", &["--effects", "sensor_delay", "--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    assert!(text.contains(from), "{text}");
    fs::write(&v, text.replace(from, to)).unwrap();
    c
}

/// Before: the best single (relaxation_length, 28.6 %) started the search,
/// its pairs stopped short (relaxation_length+yaw_inertia 40.3 %, 16 % of
/// what it leaves), and the verdict read "a model-form error outside the
/// library"; sensor_delay+yaw_inertia was never fitted. Now the pairs of
/// the best singles in sample are tried where the search reached no
/// verdict, and the verdict is the truth: the delay, and the inertia scaled
/// to the car's 2315/3500 = 0.661.
#[test]
fn a_yaw_inertia_too_large_beside_a_sensor_delay_is_named_as_the_pair_it_is() {
    let run = shared_runs::yaw_inertia_3500_beside_a_delay();
    let (said, d) = (&run.said, &run.d);
    let v = &d["verdict"];
    assert_eq!(v["kind"], "explained", "{said}");
    let mut effects: Vec<&str> = v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap())
        .collect();
    effects.sort_unstable();
    assert_eq!(effects, ["sensor_delay", "yaw_inertia"], "{said}");
    let value = |name: &str| {
        v["parameters"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["name"] == name)
            .and_then(|p| p["value"].as_f64())
            .unwrap_or_else(|| panic!("{name}: {said}"))
    };
    let scale = value("yaw_inertia.scale");
    assert!((scale - 2315.0 / 3500.0).abs() < 0.03, "{scale}");
    let delay = value("sensor_delay.delay");
    assert!((delay - 0.05).abs() < 0.005, "{delay}");
    assert!(v["reduction_percent"].as_f64().unwrap() > 60.0, "{said}");
    assert!(!said.contains("outside the library"), "{said}");
}

/// Before: "`vehicle.wheelbase` = 2.87: a + b = 1.11 + 1.67 = 2.7800 m
/// differs from the wheelbase by more than 1 mm" (no difference, no place
/// of a and b). Now the two lengths, their difference in mm and where `a`
/// and `b` are in the file.
#[test]
fn a_wheelbase_that_is_not_a_plus_b_is_refused_with_the_difference_and_the_places() {
    let dir = tempfile::tempdir().unwrap();
    let c = edited_campaign(dir.path(), "b = 1.67\n", "b = 1.67\nwheelbase = 2.87\n");
    let text = fs::read_to_string(c.join("vehicle.toml")).unwrap();
    let line = |key: &str| 1 + text.lines().position(|l| l.starts_with(key)).unwrap();
    let e = fails_cleanly("diagnose", &c, dir.path());
    let file = c.join("vehicle.toml").display().to_string();
    assert!(
        e.contains(&format!(
            "{file}:{}:13: `vehicle.wheelbase` = 2.87: the wheelbase is 2.87 m and a + b = 1.11 + 1.67 = 2.78 m (`vehicle.a` at {file}:{}:5, `vehicle.b` at {file}:{}:5): it is 90 mm longer than a + b, and the two must agree to 1 mm",
            line("wheelbase"),
            line("a ="),
            line("b =")
        )),
        "{e}"
    );
}

/// Before: a replay (`simulate` with `kind = "replay"`) said of a sideslip
/// near the sensor/estimate line "where you know which it is, state its
/// uncertainty under [channels]": a scenario has no `[channels]`. Now it
/// gives the floor the other reading takes, to read the gap against. The
/// run is `trips_s84_lead`'s logged step with a sideslip scattered ±0.0008
/// rad (0.27 of the slip sensor's floor: near the line at 0.5, read as an
/// estimated output).
#[test]
fn a_replay_near_the_sensor_estimate_line_gives_the_other_floor_not_a_table_it_lacks() {
    use super::trips_s84_lead::{step_run, trust_line};
    let line = trust_line(&step_run(0.0008));
    assert!(
        !line.contains("state its uncertainty under [channels]"),
        "{line}"
    );
    assert!(
        line.contains("read as an estimated output, a shorter or calmer stretch may read it as a sensor: where you know it is a sensor, read its gap against a sensor's floor, 0.0017 rad, in place of 0.0050 rad (`diagnose` takes it stated under a campaign's [channels])"),
        "{line}"
    );
}

/// Before: on a step whose sideslip is negative and keeps growing in
/// magnitude while the yaw rate and ay hold, `metrics` said "while its
/// sideslip grows" (β falls). Now it says the magnitude |β| grows.
#[test]
fn a_negative_sideslip_that_keeps_growing_is_said_to_grow_in_magnitude() {
    let csv = growing_sideslip_log();
    let dir = scratch(&[("run.csv", &csv)]);
    let o = run(&["metrics", dir.path().join("run.csv").to_str().unwrap()]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(
        said.contains("the yaw rate and lateral acceleration have settled while the sideslip has not: a car at its grip limit can hold them while the magnitude of its sideslip |β| grows, a possibility"),
        "{said}"
    );
    assert!(!said.contains("while its sideslip grows"), "{said}");
}

/// A 9 s, 100 Hz step (steer 0.02 rad at 1 s, 20 m/s) whose yaw rate and ay
/// settle in 0.15 s while its negative sideslip keeps growing in magnitude
/// by 0.006 rad/s from 2 s: a car sliding at its grip limit, as a log
/// shows it. Also `trips_s113_settle48`'s.
pub(super) fn growing_sideslip_log() -> String {
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in 0..=900 {
        let t = f64::from(i) / 100.0;
        let rise = |tau: f64| {
            if t > 1.0 {
                1.0 - (-(t - 1.0) / tau).exp()
            } else {
                0.0
            }
        };
        let r = 0.2 * rise(0.15);
        let beta = -(0.02 * rise(0.15) + 0.006 * (t - 2.0).max(0.0));
        let steer = if t > 1.0 { 0.02 } else { 0.0 };
        csv += &format!("{t:.2},20,{steer},{r:.6},{:.5},{beta:.6}\n", 20.0 * r);
    }
    csv
}
