//! What a fresh-eyes user still tripped on in `metrics` and `simulate`
//! input handling: a steady window reaching back over the step, a dead
//! channel, a warning only the terminal gave, a mass in tonnes, a centre of
//! gravity that tips the car over, a missing path, an initial window over
//! the step.

use super::sedan_runs::{sedan, sedan_history};
use super::*;

/// `metrics <history> --filter-hz 0 --steady-window <window>`.
fn metrics_with_window(history: &Path, window: &str) -> Output {
    run(&[
        "metrics",
        history.to_str().unwrap(),
        "--filter-hz",
        "0",
        "--steady-window",
        window,
    ])
}

/// A 5 s steady window on a 6 s record whose steer ramps from 1.0 to 1.1 s
/// averaged the ramp into the "steady" values; it is refused with where the
/// steer settles and the longest window that starts after it, and that
/// window is measured (it reads the whole step, where the 5 s window read
/// less).
#[test]
fn a_steady_window_over_the_step_is_refused_with_where_the_steer_settles() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let o = metrics_with_window(&history, "5");
    assert!(!o.status.success(), "a window over the step was measured");
    let e = stderr(&o);
    assert!(
        e.contains("inside the steady window (1.00–6.00 s, `--steady-window` = 5 s)"),
        "{e}"
    );
    assert!(
        e.contains("only at 1.10 s, so a `--steady-window` of at most 4.90 s starts after it"),
        "{e}"
    );
    let ok = metrics_with_window(&history, "4.9");
    assert!(ok.status.success(), "{}", stderr(&ok));
    let stdout = String::from_utf8_lossy(&ok.stdout);
    // The whole step is read once the window no longer reaches back over it.
    let step = stdout.lines().find(|l| l.contains("steer step")).unwrap();
    assert!(step.ends_with(" 1.0000 deg"), "{stdout}");
}

/// The same window in a scenario's `[metrics]` is refused when the
/// scenario is read, at its key, before the run.
#[test]
fn a_scenarios_steady_window_over_the_step_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let sc = sedan(dir.path(), "\n[metrics]\nsteady_window = 5.2\n");
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(e.contains("`metrics.steady_window` = 5.2"), "{e}");
    assert!(
        e.contains("starts before the steer settles at its step at 1.1 s (`start` + `rise_time`)"),
        "{e}"
    );
    assert!(
        e.contains("a `steady_window` of at most 4.90 s starts after it"),
        "{e}"
    );
}

/// The sedan's history with column `column` set to 0 on every row (a dead
/// sensor logging zeros), written as `dir/dead_<column>.csv`.
fn with_dead(history: &Path, dir: &Path, column: &str) -> PathBuf {
    let text = fs::read_to_string(history).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let at = header.split(',').position(|c| c == column).unwrap();
    let mut out = vec![header.to_string()];
    for line in lines {
        let mut cells: Vec<&str> = line.split(',').collect();
        cells[at] = "0";
        out.push(cells.join(","));
    }
    let path = dir.join(format!("dead_{column}.csv"));
    fs::write(&path, out.join("\n") + "\n").unwrap();
    path
}

/// A sideslip column of zeros was read as a steady sideslip of 0 and a TB
/// of 0; its metrics are now absent (`null`), and the warning names the
/// file, the column and its value, in `--json` as on the terminal.
#[test]
fn a_dead_sideslip_channel_is_left_out_and_said_not_read_as_zero() {
    let dir = tempfile::tempdir().unwrap();
    let csv = with_dead(&sedan_history(dir.path()), dir.path(), "beta");
    let o = run(&["metrics", csv.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(j["beta_steady"].is_null() && j["tb"].is_null(), "{j}");
    // The other metrics are measured as before.
    assert!(
        (j["yaw_rate_gain"].as_f64().unwrap() - 3.7096).abs() < 0.01,
        "{j}"
    );
    let said = format!(
        "{}: channel `beta` holds one value (0) over the whole run: a dead or unplugged sensor; its metrics (steady sideslip and TB) are left out (null in --json)",
        csv.display()
    );
    assert!(j["warnings"].to_string().contains(&said), "{j}");
    assert!(
        stderr(&o).contains(&format!("warning: {said}")),
        "{}",
        stderr(&o)
    );
    let table = succeeds(&["metrics", csv.to_str().unwrap()]);
    let line = table
        .lines()
        .find(|l| l.contains("steady sideslip"))
        .unwrap();
    assert!(line.ends_with("— deg"), "{table}");
}

/// A yaw rate of zeros was refused as a steer in degrees ("the yaw rate is
/// far smaller than a neutral car's"): it is refused as the dead sensor it
/// is, by `diagnose`'s rule and words; a dead `ay` is left out and said.
#[test]
fn a_dead_yaw_rate_is_refused_as_dead_and_a_dead_ay_is_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let yaw = with_dead(&history, dir.path(), "yaw_rate");
    let o = run(&["metrics", yaw.to_str().unwrap()]);
    assert!(!o.status.success(), "a dead yaw rate was measured");
    let e = stderr(&o);
    assert!(
        e.contains(
            "channel `yaw_rate` holds one value (0) over the whole run: a dead or unplugged sensor"
        ),
        "{e}"
    );
    assert!(!e.contains("far smaller"), "{e}");
    let ay = with_dead(&history, dir.path(), "ay");
    let o = run(&["metrics", ay.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(j["ay_steady"].is_null() && j["er"].is_null(), "{j}");
    let w = j["warnings"].to_string();
    assert!(w.contains("channel `ay` holds one value (0)"), "{w}");
    assert!(!w.contains("the run has no `ay`"), "said twice: {w}");
}

/// The words of a response that has not settled in the steady window
/// (the channels that have not follow, each with its spread).
const NOT_SETTLED: &str = "the response has not settled in the steady window: the ";

/// A steady window from 1.1 s, where the sedan's yaw rate still rings: the
/// terminal warned that it had not settled and `--json` did not; the
/// warning is the report's now, said once by both.
#[test]
fn metrics_json_says_a_response_has_not_settled_as_the_terminal_does() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let o = metrics_with_window(&history, "4.9");
    assert!(o.status.success(), "{}", stderr(&o));
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert_eq!(said.matches(NOT_SETTLED).count(), 1, "{said}");
    let h = history.to_str().unwrap();
    let args = [
        "metrics",
        h,
        "--filter-hz",
        "0",
        "--steady-window",
        "4.9",
        "--json",
    ];
    let j: serde_json::Value = serde_json::from_str(&succeeds(&args)).unwrap();
    assert_eq!(j["settled"], false, "{j}");
    assert!(j["warnings"].to_string().contains(NOT_SETTLED), "{j}");
    // A settled response is not warned of.
    let settled = metrics_with_window(&history, "1");
    assert!(!String::from_utf8_lossy(&settled.stdout).contains("not settled"));
    assert!(!stderr(&settled).contains("not settled"));
}

/// `simulate`'s `metrics.json` carries the same warning.
#[test]
fn simulates_metrics_json_says_a_response_has_not_settled() {
    let dir = tempfile::tempdir().unwrap();
    let sc = sedan(dir.path(), "\n[metrics]\nsteady_window = 4.9\n");
    let out = dir.path().join("out");
    let stdout = succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(stdout.matches(NOT_SETTLED).count(), 1, "{stdout}");
    let j = read_json(&out.join("metrics.json"));
    assert!(j["warnings"].to_string().contains(NOT_SETTLED), "{j}");
}

/// `simulate` of the sedan whose `[vehicle]` has `from` replaced by `to`:
/// its stderr, the run refused.
fn sedan_vehicle_refused(from: &str, to: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("sedan_step.toml");
    assert!(text.contains(from), "{from}");
    let sc = dir.path().join("sedan_step.toml");
    fs::write(&sc, text.replace(from, to)).unwrap();
    let out = dir.path().join("out");
    refused(
        &run(&[
            "simulate",
            sc.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]),
        &out,
    )
}

/// A mass in tonnes (1.53) was blamed on `yaw_inertia` with a ratio of
/// `8.162e2`; it is refused at `mass`, with the kilograms meant.
#[test]
fn a_mass_in_tonnes_is_refused_at_mass_not_blamed_on_the_inertia() {
    let e = sedan_vehicle_refused("mass = 1530.0", "mass = 1.53");
    assert!(e.contains("`vehicle.mass` = 1.53: a vehicle with a wheelbase of 2.78 m (a + b) weighs at least 50 kg"), "{e}");
    assert!(
        e.contains("is the mass in tonnes? give it in kg (1530 kg for 1.53 t)"),
        "{e}"
    );
    assert!(!e.contains("yaw_inertia"), "{e}");
    // An inertia off by 1e4 says both values and the radius of gyration
    // they imply, in plain numbers.
    let e = sedan_vehicle_refused("yaw_inertia = 2315.0", "yaw_inertia = 23150000.0");
    assert!(e.contains("`vehicle.yaw_inertia` = 23150000: with mass = 1530 kg it gives a radius of gyration √(yaw_inertia/mass) of 123 m, against √(a·b) = 1.36 m from the axles: yaw_inertia / (mass·a·b) = 8162"), "{e}");
    assert!(
        !without_temp_names(&e).contains("e3") && !without_temp_names(&e).contains("e2"),
        "{e}"
    );
}

/// A centre of gravity 5.5 m up (for 0.55) was simulated without a word:
/// the car would tip over standing at 0.14 g.
#[test]
fn a_cg_height_that_tips_the_car_over_is_refused_at_its_key() {
    let e = sedan_vehicle_refused("cg_height = 0.55", "cg_height = 5.5");
    assert!(e.contains("sedan_step.toml:13:13: `vehicle.cg_height` = 5.5: the car would tip over at 0.14 g of lateral acceleration"), "{e}");
    assert!(
        e.contains("a cg_height of at most track/(2·0.3) = 2.58 m"),
        "{e}"
    );
    // A tall van's 1.5 m on the same track tips at 0.52 g: accepted.
    let dir = tempfile::tempdir().unwrap();
    let sc = dir.path().join("tall.toml");
    let text = bundled_scenario("sedan_step.toml").replace("cg_height = 0.55", "cg_height = 1.5");
    fs::write(&sc, text).unwrap();
    let out = dir.path().join("out");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
}

/// `simulate sc/s.toml` run from `dir`, `sc/s.toml` holding `text`: its
/// stderr, the run refused.
fn simulate_from(dir: &Path, text: &str) -> String {
    fs::create_dir_all(dir.join("sc")).unwrap();
    fs::write(dir.join("sc/s.toml"), text).unwrap();
    let o = bin()
        .args(["simulate", "sc/s.toml", "--out", "out"])
        .current_dir(dir)
        .output()
        .unwrap();
    refused(&o, &dir.join("out"))
}

/// A tyre path `../tyres/…` that does not exist was printed as
/// `tyres/…` (relative to the working directory) beside "paths are
/// relative to the folder of sc/s.toml"; the message gives the path as
/// written and where it leads, absolute, and a replay's run alike.
#[test]
fn a_missing_path_is_given_as_written_and_as_resolved() {
    let dir = tempfile::tempdir().unwrap();
    let home = dir.path().canonicalize().unwrap();
    let tyre = format!("{}/tyres/gim_sedan_front.toml", root().display());
    let text = bundled_scenario("sedan_step.toml").replace(&tyre, "../tyres/absent.toml");
    let e = simulate_from(&home, &text);
    let expected = format!(
        "sc/s.toml:16:9: `tyres.front` = \"../tyres/absent.toml\" names {}, which does not exist (\"../tyres/absent.toml\" read from sc, the folder of sc/s.toml)",
        home.join("tyres/absent.toml").display()
    );
    assert!(e.contains(&expected), "{e}");
    let replay = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{tyre}\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"../runs/absent.csv\"\n"
    );
    let e = simulate_from(&home, &replay);
    let expected = format!(
        "`manoeuvre.run` = \"../runs/absent.csv\" names {}, which does not exist (\"../runs/absent.csv\" read from sc, the folder of sc/s.toml)",
        home.join("runs/absent.csv").display()
    );
    assert!(e.contains(&expected), "{e}");
}

/// A 1.2 s initial window over the sedan's step at 1.0 s was refused as a
/// steer that "moves … at 0.00 s" (the first sample against the window's
/// mean, which the step pulls); it says where the steer moves, and the
/// longest window that ends before it.
#[test]
fn an_initial_window_over_the_step_says_where_the_steer_moves() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let h = history.to_str().unwrap();
    let o = run(&["metrics", h, "--filter-hz", "0", "--pre-window", "1.2"]);
    assert!(!o.status.success(), "a window over the step was measured");
    let e = stderr(&o);
    assert!(e.contains("the steer moves by more than 5 % of its step at 1.00 s, inside the initial window (0.00–1.20 s)"), "{e}");
    assert!(
        e.contains("one of at most 1.00 s ends before it moves"),
        "{e}"
    );
    assert!(!e.contains("at 0.00 s"), "{e}");
}

/// An `ay` column of noise (a dead accelerometer is never exactly
/// constant) gave `E_ay` 114 s and `Er` 114 s with no word but "not
/// settled": it is checked against the speed times the yaw rate (at a
/// steady state ay = u·r) and left out where it disagrees by half; the
/// live channel of the same run passes the check.
#[test]
fn an_ay_that_disagrees_with_speed_times_yaw_rate_is_left_out_and_said() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let text = fs::read_to_string(&history).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let at = header.split(',').position(|c| c == "ay").unwrap();
    let mut out = vec![header.to_string()];
    // A deterministic ±0.05 m/s² scatter about 0.
    for (k, line) in lines.enumerate() {
        let mut cells: Vec<String> = line.split(',').map(String::from).collect();
        cells[at] = format!("{}", 0.05 * ((k * 7919 % 13) as f64 / 6.0 - 1.0));
        out.push(cells.join(","));
    }
    let noisy = dir.path().join("noisy_ay.csv");
    fs::write(&noisy, out.join("\n") + "\n").unwrap();
    let o = run(&["metrics", noisy.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(j["ay_steady"].is_null() && j["er"].is_null(), "{j}");
    let w = j["warnings"].to_string();
    assert!(w.contains("the steady change of `ay` ("), "{w}");
    assert!(
        w.contains("disagrees with the speed times that of the yaw rate (22.2 m/s × "),
        "{w}"
    );
    let live = run(&["metrics", history.to_str().unwrap(), "--json"]);
    let j: serde_json::Value = serde_json::from_slice(&live.stdout).unwrap();
    assert!(j["ay_steady"].as_f64().is_some(), "{j}");
    assert!(!j["warnings"].to_string().contains("disagrees"), "{j}");
}
