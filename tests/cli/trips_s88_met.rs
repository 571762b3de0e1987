//! What a fresh user tripped on in `metrics` and `simulate` (session 88):
//! a declaration in degrees refused with the fix for another column, load
//! extrapolation and sliding said of a linear tyre, an impossible steady
//! lateral acceleration unsaid, slip angles past ±180°, the speed and
//! standstill rules, a sideslip sign check deaf below a fixed floor, and
//! `E_r` biased by a coarse sample rate without a word.

use super::sedan_runs::{run_text, sedan_history};
use super::*;

/// A replay of `run` (a file beside it) on the bundled sedan, with `extra`
/// under its [manoeuvre].
fn replay_scenario(run: &Path, extra: &str) -> PathBuf {
    let base = bundled_scenario("sedan_step.toml");
    let base = base.replace("../tyres", root().join("tyres").to_str().unwrap());
    let head = &base[..base.find("[manoeuvre]").unwrap()];
    let sc = run.with_file_name("replay.toml");
    let text = format!(
        "{head}[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n{extra}",
        run.file_name().unwrap().to_str().unwrap()
    );
    fs::write(&sc, text).unwrap();
    sc
}

/// `metrics --degrees yaw_rate` on the sedan's step logged in rad/s ended
/// with the fix of a steer in degrees: "a column in degrees is declared
/// so: `metrics --degrees steer`". Now it names the declaration made:
/// "leave out `--degrees yaw_rate`"; `--degrees steer` on a steer in
/// radians likewise "leave out `--degrees steer`".
#[test]
fn a_wrong_degrees_declaration_is_named_with_its_own_fix() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("rad.csv");
    fs::write(&file, run_text(&history, 10, None)).unwrap();
    for (column, other) in [("yaw_rate", "steer"), ("steer", "yaw_rate")] {
        let o = run(&["metrics", file.to_str().unwrap(), "--degrees", column]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!(
                "column `{column}`, declared in degrees by `--degrees {column}`"
            )) && e
                .trim_end()
                .ends_with(&format!("leave out `--degrees {column}`")),
            "{e}"
        );
        assert!(!e.contains(&format!("--degrees {other}")), "{e}");
    }
}

/// A replay whose `degrees = ["yaw_rate"]` declares a yaw rate logged in
/// rad/s was refused at `manoeuvre.run` ("the run rad.csv: the yaw rate is
/// 123× smaller…") with the fix `degrees = ["steer"]`. Now it stands at the
/// `degrees` entry (line 22, column 12) and says to take it out.
#[test]
fn a_replay_refused_for_its_degrees_names_the_degrees_key() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("rad.csv");
    fs::write(&file, run_text(&history, 10, None)).unwrap();
    for column in ["yaw_rate", "steer"] {
        let sc = replay_scenario(&file, &format!("degrees = [\"{column}\"]\n"));
        let line = fs::read_to_string(&sc)
            .unwrap()
            .lines()
            .position(|l| l.starts_with("degrees"))
            .unwrap()
            + 1;
        let o = run(&[
            "simulate",
            sc.to_str().unwrap(),
            "--out",
            dir.path().join("o").to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains(&format!(
                "replay.toml:{line}:12: `manoeuvre.degrees` declares `{column}` in degrees"
            )) && e.contains(&format!(
                "take `\"{column}\"` out of `degrees` under [manoeuvre]"
            )),
            "{e}"
        );
    }
}

/// The bundled sedan step on linear tyres (the file `tyre`, both axles),
/// each wheel at its static load (`load_transfer = false`), with `edit`
/// applied to the scenario's text: what `simulate` prints (its table
/// and warnings, and stderr).
fn linear_sedan(dir: &Path, tyre: &str, edit: &dyn Fn(String) -> String) -> String {
    let t = dir.join("linear.toml");
    fs::write(&t, tyre).unwrap();
    let tyres = root().join("tyres");
    let base = bundled_scenario("sedan_step.toml")
        .replace(
            tyres.join("gim_sedan_front.toml").to_str().unwrap(),
            t.to_str().unwrap(),
        )
        .replace(
            tyres.join("gim_sedan_rear.toml").to_str().unwrap(),
            t.to_str().unwrap(),
        )
        .replace(
            "[manoeuvre]",
            "[model]\nload_transfer = false\n\n[manoeuvre]",
        );
    let sc = dir.join("linear_sedan.toml");
    fs::write(&sc, edit(base)).unwrap();
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o)
}

/// A linear tyre fitted at 2000–4000 N, on the sedan's 4507 N front
/// wheels: `simulate` warned "6001 of 6001 rows take the front tyres
/// outside the ranges … there, wheel loads 4507 to 4507 N". A linear
/// tyre's force has no load term: no load is extrapolated, nothing said;
/// its slip-angle range is still held to.
#[test]
fn a_linear_tyre_has_no_load_range_to_extrapolate() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = "model = \"linear\"\ncornering_stiffness = 57296.0\n\n[fitted_ranges]\nfz = [2000.0, 4000.0]\nalpha = [-0.1, 0.1]\n";
    let e = linear_sedan(dir.path(), tyre, &|s| s);
    assert!(!e.contains("wheel load"), "{e}");
    assert!(!e.contains("outside the ranges"), "{e}");
    // At 0.3 rad the slip angles leave the fitted ±0.1 rad: said, with
    // no load range.
    let e = linear_sedan(dir.path(), tyre, &|s| {
        s.replace("steer = 0.0174533", "steer = 0.3")
    });
    assert!(
        e.contains(
            "outside the ranges of the rig data they were fitted to (alpha -0.1000 to 0.1000 rad;"
        ),
        "{e}"
    );
    assert!(!e.contains("wheel load"), "{e}");
}

/// A Gim tyre fitted at 2000–4000 N on the same wheels: its loads are
/// extrapolated, and the one load it runs at (no load transfer) was said
/// as a range, "wheel loads 4507 to 4507 N"; now "a wheel load of 4507 N".
#[test]
fn one_load_beyond_the_fitted_range_is_said_as_one_load() {
    let dir = tempfile::tempdir().unwrap();
    let gim = fs::read_to_string(root().join("tyres/gim_sedan_front.toml")).unwrap();
    let tyre = format!("{gim}\n[fitted_ranges]\nfz = [2000.0, 4000.0]\n");
    let e = linear_sedan(dir.path(), &tyre, &|s| s);
    assert!(e.contains("there, a wheel load of 4507 N"), "{e}");
    assert!(!e.contains("4507 to 4507"), "{e}");
}

/// The sedan's 0.5 rad step on linear tyres: `simulate` said "the front
/// axle slides … past the peak of any tyre's curve" of a tyre with no
/// peak, and nothing of its 5.5 g steady lateral acceleration. Now the
/// axles run "beyond the linear tyre's range of validity", and "the
/// lateral acceleration reaches 5.52 g" beyond the 1.5 g any tyre gives.
#[test]
fn a_linear_tyre_never_slides_and_its_impossible_lateral_acceleration_is_said() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = fs::read_to_string(root().join("tyres/linear.toml")).unwrap();
    let e = linear_sedan(dir.path(), &tyre, &|s| {
        s.replace("steer = 0.0174533", "steer = 0.5")
    });
    assert!(!without_temp_names(&e).contains("slides"), "{e}");
    assert!(!e.contains("the car is sliding"), "{e}");
    for axle in ["front", "rear"] {
        assert!(
            e.contains(&format!(
                "the {axle} axle runs beyond the linear tyre's range of validity"
            )),
            "{e}"
        );
    }
    assert!(
        e.contains("the lateral acceleration reaches 5.52 g (54.1 m/s²)")
            && e.contains("is 5.49 g at the end of the run")
            && e.contains("beyond the 1.5 g any tyre gives"),
        "{e}"
    );
}

/// An oversteering car on linear tyres (rear 20 kN/rad) stepped above its
/// critical speed, small-angle kinematics, to 6.5 s: its rear slip angle
/// was printed as "reaches 203.7°", then wrapped into (−180°, 180°], a
/// number no column of `history.csv` holds (a fresh user's "180.0°"
/// of a run at 1952°). Past a quarter turn it is said as the history
/// holds it, with its radians, as the small-angle model's number.
#[test]
fn slip_angles_past_a_quarter_turn_are_said_as_the_models_number() {
    let dir = tempfile::tempdir().unwrap();
    let soft = dir.path().join("soft.toml");
    fs::write(&soft, "model = \"linear\"\ncornering_stiffness = 20000.0\n").unwrap();
    let tyre = fs::read_to_string(root().join("tyres/linear.toml")).unwrap();
    let e = linear_sedan(dir.path(), &tyre, &|s| {
        let rear = s.rfind("rear = ").unwrap();
        let end = rear + s[rear..].find('\n').unwrap();
        format!("{}rear = \"{}\"{}", &s[..rear], soft.display(), &s[end..])
            .replace(
                "load_transfer = false",
                "load_transfer = false\nkinematics = \"small-angle\"",
            )
            .replace("end = 6.0", "end = 6.5")
    });
    let said: Vec<f64> = e
        .split("slip angle reaches ")
        .skip(1)
        .map(|s| s[..s.find('°').unwrap()].parse().unwrap())
        .collect();
    assert_eq!(said.len(), 2, "{e}");
    let quarter_turn = e
        .split("slip angle reaches ")
        .skip(1)
        .filter(|s| s.contains(" rad: the small-angle model's α = δ − β − a·r/u"))
        .count();
    assert_eq!(
        quarter_turn,
        said.iter().filter(|a| a.abs() > 90.0).count(),
        "{said:?}: {e}"
    );
    assert!(said.iter().any(|a| a.abs() > 180.0), "{said:?}: {e}");
}

/// The sedan's step at 100 Hz with its speed as `speed(t)` (m/s) written
/// to `dir/name`.
fn with_speed(dir: &Path, name: &str, speed: &dyn Fn(f64) -> f64) -> PathBuf {
    let history = sedan_history(dir);
    let mut out = String::new();
    for (k, line) in run_text(&history, 10, None).lines().enumerate() {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        if k > 0 {
            cells[1] = speed(cells[0].parse().unwrap()).to_string();
        }
        out += &(cells.join(",") + "\n");
    }
    let path = dir.join(name);
    fs::write(&path, out).unwrap();
    path
}

/// A run whose speed rose from 10 m/s in its first 0.5 s and was held at
/// 22.2 m/s from there, 0.5 s before the steer's onset: `metrics` warned
/// "the speed rises over the measured piece, between 17.33 and 22.22 m/s".
/// The response the metrics measure runs at one speed: no warning.
#[test]
fn a_run_up_before_the_step_is_no_speed_change_of_the_response() {
    let dir = tempfile::tempdir().unwrap();
    let p = with_speed(dir.path(), "runup.csv", &|t| {
        if t < 0.5 {
            10.0 + (22.2222 - 10.0) * t / 0.5
        } else {
            22.2222
        }
    });
    let (_, warnings) = metrics_json(&p);
    assert!(
        !warnings.iter().any(|w| w.contains("speed rises")),
        "{warnings:?}"
    );
    // A speed that rises over the response is still said.
    let p = with_speed(dir.path(), "rising.csv", &|t| 20.0 + 0.8 * t);
    let (_, warnings) = metrics_json(&p);
    assert!(
        warnings
            .iter()
            .any(|w| w.starts_with("the speed rises over the measured piece")),
        "{warnings:?}"
    );
}

/// A log that starts from rest and climbs 0→5 m/s in 0.2 s: its slow span
/// was counted as "1 standstill span" ("standstill 0.00–0.19 s … at most
/// 4.75 m/s"). It stood below 0.5 m/s on 2 of its 20 samples: a crawl.
#[test]
fn a_climb_from_rest_is_a_crawl_not_a_standstill() {
    let dir = tempfile::tempdir().unwrap();
    let p = with_speed(dir.path(), "climb.csv", &|t| {
        if t < 0.2 {
            25.0 * t
        } else if t < 0.5 {
            5.0 + (22.2222 - 5.0) * (t - 0.2) / 0.3
        } else {
            22.2222
        }
    });
    let (j, _) = metrics_json(&p);
    let slow = j["cleaning"]["slow"].as_array().unwrap();
    assert_eq!(slow.len(), 1, "{}", j["cleaning"]);
    assert_eq!(slow[0]["kind"], "crawl", "{}", j["cleaning"]);
}
