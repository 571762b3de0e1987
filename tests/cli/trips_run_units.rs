//! Measured runs written in another unit or sign than FORMATS.md's that
//! pass every size check (a speed in km/h below any car's top speed in m/s,
//! a sideslip in degrees below 1 "rad", a steer divided by 57 once more, a
//! speed logged backwards), and a response that leads the steer: each
//! caught by the kinematics the run's own channels obey, as a user runs
//! the tool.

use super::*;

/// The rows of the bundled sedan step (80 km/h, 1°) as `simulate` writes
/// them, with the columns of a logger: t, speed, steer, yaw_rate, ay, beta,
/// and `edit` applied to each row's (speed, steer, beta).
fn logged(dir: &Path, edit: fn(&mut [f64; 6])) -> PathBuf {
    let out = dir.join("sim");
    if !out.join("history.csv").exists() {
        let o = run(&[
            "simulate",
            "scenarios/sedan_step.toml",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let text = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let cols = ["t", "speed", "steer", "yaw_rate", "ay", "beta"].map(at);
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let mut row = cols.map(|k| v[k]);
        edit(&mut row);
        let cells: Vec<String> = row.iter().map(|x| format!("{x}")).collect();
        csv += &(cells.join(",") + "\n");
    }
    let p = dir.join("run.csv");
    fs::write(&p, csv).unwrap();
    p
}

/// A replay scenario `name` beside `run` (the bundled sedan, its tyres
/// found from anywhere) with `extra` lines under its `[manoeuvre]`.
fn replay_scenario(run: &Path, name: &str, extra: &str) -> PathBuf {
    let base = fs::read_to_string(root().join("scenarios/sedan_step.toml")).unwrap();
    let base = base.replace("../tyres", root().join("tyres").to_str().unwrap());
    let head = &base[..base.find("[manoeuvre]").unwrap()];
    let sc = run.with_file_name(name);
    let text = format!(
        "{head}[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n{extra}",
        run.file_name().unwrap().to_str().unwrap()
    );
    fs::write(&sc, text).unwrap();
    sc
}

/// `metrics` of `path` with `extra` options: success, stdout and stderr.
pub(super) fn metrics(path: &Path, extra: &[&str]) -> (bool, String, String) {
    let mut args = vec!["metrics", path.to_str().unwrap()];
    args.extend_from_slice(extra);
    let o = run(&args);
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    (o.status.success(), said, stderr(&o))
}

#[test]
fn a_speed_in_km_h_below_any_cars_top_speed_in_m_s_is_refused_by_ay_against_speed_times_yaw_rate() {
    let dir = tempfile::tempdir().unwrap();
    // 80 km/h written as 80: below the 150 m/s no car reaches.
    let p = logged(dir.path(), |r| r[1] *= 3.6);
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok);
    assert!(e.contains("run.csv:"), "{e}");
    assert!(
        e.contains("column `speed`: 79.9") && e.contains("is `speed` in km/h? divide it by 3.6"),
        "{e}"
    );
    // In m/s the same run is measured.
    let p = logged(dir.path(), |_| {});
    assert!(metrics(&p, &[]).0);
}

/// A speed in mph (a US logger's, the TTC rig's own channel) was read as
/// m/s and the run's ay then blamed on "the accelerometer or the gyro":
/// speed × yaw rate 2.237 times ay is the same slip as km/h's 3.6.
#[test]
fn a_speed_in_mph_is_refused_by_ay_against_speed_times_yaw_rate() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged(dir.path(), |r| r[1] *= 2.23694);
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok);
    assert!(
        e.contains("column `speed`: 49.7")
            && e.contains("(1/2.23694 = 0.447): is `speed` in mph? divide it by 2.23694"),
        "{e}"
    );
    assert!(!e.contains("km/h"), "{e}");
}

#[test]
fn a_sideslip_in_degrees_is_refused_and_measured_once_declared() {
    let dir = tempfile::tempdir().unwrap();
    // The step's sideslip, about 0.5°, is 0.5 "rad" in degrees: below the
    // 1 rad a size check refuses, 15 times what this turn allows.
    let p = logged(dir.path(), |r| r[5] = r[5].to_degrees());
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok);
    assert!(
        e.contains("column `beta`:") && e.contains("is `beta` in degrees?"),
        "{e}"
    );
    assert!(e.contains("`--degrees beta` to `metrics`"), "{e}");
    let (ok, said, e) = metrics(&p, &["--degrees", "beta"]);
    assert!(ok, "{e}");
    let (_, si, _) = metrics(&logged(dir.path(), |_| {}), &[]);
    let line = |s: &str| {
        s.lines()
            .find(|l| l.contains("steady sideslip"))
            .unwrap()
            .to_string()
    };
    assert_eq!(line(&said), line(&si));
    // A name that is no angle column is refused with the one meant.
    let (ok, _, e) = metrics(&p, &["--degrees", "bet"]);
    assert!(!ok && e.contains("did you mean `beta`?"), "{e}");
}

#[test]
fn a_speed_logged_backwards_is_refused_at_its_row_not_measured_as_a_standstill() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged(dir.path(), |r| r[1] = -r[1]);
    let (ok, _, e) = metrics(&p, &["--min-speed", "0"]);
    assert!(!ok);
    assert!(
        e.contains("run.csv:2:2: column `speed`: -22.2") && e.contains("negate it"),
        "{e}"
    );
    // A lowest speed no car reaches is refused at its option.
    let (ok, _, e) = metrics(&logged(dir.path(), |_| {}), &["--min-speed", "1e308"]);
    assert!(!ok && e.contains("--min-speed"), "{e}");
}

/// Every run's steer of the campaign at `c` divided by `factor`.
fn divide_steer(c: &Path, factor: f64) {
    for e in fs::read_dir(c.join("runs")).unwrap() {
        let p = e.unwrap().path();
        let text = fs::read_to_string(&p).unwrap();
        let mut lines = text.lines();
        let head = lines.next().unwrap();
        let k = head.split(',').position(|h| h == "steer").unwrap();
        let mut out = format!("{head}\n");
        for l in lines {
            let mut cells: Vec<String> = l.split(',').map(str::to_string).collect();
            cells[k] = format!("{}", cells[k].parse::<f64>().unwrap() / factor);
            out += &(cells.join(",") + "\n");
        }
        fs::write(&p, out).unwrap();
    }
}

#[test]
fn a_steer_divided_by_57_once_more_is_refused_and_a_small_one_noted_in_the_diagnosis() {
    // Every run's steer a radian steer taken for degrees: below the 0.01
    // rad under which a run counted as not steering, while the car turns
    // at 57× a neutral car's rate for it. `metrics` and a replay refused
    // such a run; `diagnose`, with the car's wheelbase, only noted it.
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "small", &["--seed", "1"]);
    divide_steer(&c, 180.0 / std::f64::consts::PI);
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("o").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains(".csv: the yaw rate is ")
            && e.contains("× a neutral car's for this steer")
            && e.contains("no car that is not spinning turns so much for its steer"),
        "{e}"
    );
    // A steer 4× too small for the car is a steer or a wheelbase to check,
    // not a unit: noted, and the run diagnosed.
    let c = synth_campaign(dir.path(), "quarter", &["--seed", "1"]);
    divide_steer(&c, 4.0);
    // The note and the words are the runs' and the gap's, whatever the
    // candidates: one keeps the test from fitting the whole library to a
    // gap this large (three minutes of CPU).
    let vehicle = c.join("vehicle.toml");
    let text = fs::read_to_string(&vehicle).unwrap();
    fs::write(&vehicle, format!("{text}effects = [\"sensor_delay\"]\n")).unwrap();
    let (stdout, d) = diagnose_campaign(&c);
    let notes = d["notes"].to_string();
    assert!(
        notes.contains("step_040kph_3ms2.csv: the yaw rate is")
            && notes.contains("× a neutral car's for this steer"),
        "{notes}"
    );
    assert!(
        stdout.contains("is `steer` the road-wheel angle in radians"),
        "{stdout}"
    );
    // Nothing rounded to zero keeps a sign (its gap's phases printed "-0°").
    for signed_zero in ["-0°", "+0°", " -0 ", "-0.0 "] {
        assert!(!stdout.contains(signed_zero), "{signed_zero}: {stdout}");
    }
}

#[test]
fn a_lateral_acceleration_that_leads_the_steer_has_a_negative_response_time_said_so() {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("sedan_step.toml");
    let speed = text
        .lines()
        .find(|l| l.starts_with("speed"))
        .expect("a speed key");
    let sc = dir.path().join("slow.toml");
    fs::write(&sc, text.replace(speed, "speed = 6.0")).unwrap();
    let out = dir.path().join("out");
    let said = crate::scenarios::simulate_to(&sc, &out);
    let m = read_json(&out.join("metrics.json"));
    let ta = m["ay_response_time"].as_f64().unwrap();
    assert!(ta < 0.0, "{m}");
    assert!(
        said.contains("the lateral acceleration reaches 90 % of its step")
            && said.contains("before the steer reaches half of its own"),
        "{said}"
    );
}

/// The logged step of [`logged`] with a `roll` column in degrees (2–3°, as
/// a logger writes it), beside the run.
fn logged_with_roll_in_degrees(dir: &Path) -> PathBuf {
    let p = logged(dir, |_| {});
    let text = fs::read_to_string(&p).unwrap();
    let mut lines = text.lines();
    let mut csv = format!("{},roll\n", lines.next().unwrap());
    for line in lines {
        let ay: f64 = line.split(',').nth(4).unwrap().parse().unwrap();
        csv += &format!("{line},{}\n", 2.0 + 0.3 * ay);
    }
    fs::write(&p, csv).unwrap();
    p
}

/// `metrics` reads a logged roll to level `ay` by it, as `diagnose` does:
/// one in degrees is refused as there, naming `--degrees roll`, which
/// reads it (it was left unread before).
#[test]
fn metrics_refuses_a_roll_column_in_degrees_and_reads_it_declared() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged_with_roll_in_degrees(dir.path());
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok);
    assert!(
        e.contains("column `roll`") && e.contains("`--degrees roll` to `metrics`"),
        "{e}"
    );
    let (ok, out, e) = metrics(&p, &["--degrees", "roll"]);
    assert!(ok, "{e}");
    let said = format!("{out}{e}");
    assert!(
        said.contains("roll: ay levelled by it before the metrics"),
        "{said}"
    );
    assert!(!said.contains("not read: roll"), "{said}");
    assert!(out.contains("yaw-rate gain"), "{out}");
}

#[test]
fn a_replay_declares_its_runs_roll_in_degrees_under_its_manoeuvre() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged_with_roll_in_degrees(dir.path());
    let write = |name: &str, extra: &str| replay_scenario(&p, name, extra);
    let refused = write("refused.toml", "");
    let o = run(&[
        "simulate",
        refused.to_str().unwrap(),
        "--out",
        dir.path().join("o1").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("column `roll`") && e.contains("a replay's [manoeuvre]"),
        "{e}"
    );
    let declared = write("declared.toml", "degrees = [\"roll\"]\n");
    let out = dir.path().join("o2");
    let o = run(&[
        "simulate",
        declared.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.join("history.csv").exists());
}

#[test]
fn a_gentle_yaw_rate_in_deg_per_s_is_refused_by_ay_against_speed_times_yaw_rate() {
    let dir = tempfile::tempdir().unwrap();
    // A 0.2° step: 0.75 deg/s, below the 3 rad/s no car turns at.
    let p = logged(dir.path(), |r| {
        for k in [2, 3, 4, 5] {
            r[k] *= 0.2;
        }
        r[3] = r[3].to_degrees();
    });
    let (ok, _, e) = metrics(&p, &[]);
    assert!(!ok);
    assert!(
        e.contains("column `yaw_rate`: 0.")
            && e.contains("where `ay` is a median 0.017")
            && e.contains("is `yaw_rate` in deg/s?")
            && e.contains("`--degrees yaw_rate` to `metrics`"),
        "{e}"
    );
    // Declared, it is read.
    let (ok, out, e) = metrics(&p, &["--degrees", "yaw_rate"]);
    assert!(ok, "{e}");
    assert!(out.contains("yaw-rate gain"), "{out}");
}

#[test]
fn a_steer_declared_in_degrees_that_was_in_radians_is_refused_as_a_yaw_rate_no_car_has() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged(dir.path(), |_| {});
    let (ok, _, e) = metrics(&p, &["--degrees", "steer"]);
    assert!(!ok);
    assert!(
        e.contains("the yaw rate is ")
            && e.contains("× a neutral car's for this steer")
            && e.contains("with l = 1 m, shorter than any car's wheelbase")
            && e.contains("leave out `--degrees steer`"),
        "{e}"
    );
    // Read as logged, the same run is measured.
    assert!(metrics(&p, &[]).0);
    // A yaw rate declared in deg/s that was in rad/s: the message names
    // that declaration.
    let (ok, _, e) = metrics(&p, &["--degrees", "yaw_rate"]);
    assert!(!ok);
    assert!(e.contains("leave out `--degrees yaw_rate`"), "{e}");
}

#[test]
fn a_column_declared_in_degrees_that_was_in_radians_is_refused_and_a_repeat_converts_once() {
    let dir = tempfile::tempdir().unwrap();
    let p = logged(dir.path(), |_| {});
    // beta in rad declared in degrees: 57 times too small for a car.
    let (ok, _, e) = metrics(&p, &["--degrees", "beta"]);
    assert!(!ok);
    assert!(
        e.contains("column `beta`:")
            && e.contains("declared in degrees")
            && e.contains("so the column was already in radians; drop `beta`"),
        "{e}"
    );
    // A yaw rate in rad/s declared in deg/s.
    let (ok, _, e) = metrics(&p, &["--degrees", "yaw_rate"]);
    assert!(!ok);
    assert!(
        e.contains("yaw_rate") && e.contains("declared in degrees"),
        "{e}"
    );
    // A beta in degrees declared twice is converted once, as once.
    let deg = logged(dir.path(), |r| r[5] = r[5].to_degrees());
    let (ok, once, e) = metrics(&deg, &["--degrees", "beta"]);
    assert!(ok, "{e}");
    let (ok, twice, e) = metrics(&deg, &["--degrees", "beta", "--degrees", "beta"]);
    assert!(ok, "{e}");
    assert_eq!(once, twice);
    assert!(
        once.contains("steady sideslip             -0.5790 deg"),
        "{once}"
    );
}

#[test]
fn simulates_own_history_of_a_slide_is_measured_not_refused_as_beta_in_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let base = fs::read_to_string(root().join("scenarios/sedan_step.toml")).unwrap();
    let base = base
        .replace("../tyres", root().join("tyres").to_str().unwrap())
        .replace("steer = 0.0174533", "steer = 0.3");
    let sc = dir.path().join("big.toml");
    fs::write(&sc, base).unwrap();
    let out = dir.path().join("big");
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (ok, _, e) = metrics(&out.join("history.csv"), &["--filter-hz", "0"]);
    assert!(ok, "{e}");
    assert!(e.contains("the car is sliding"), "{e}");
}

#[test]
fn a_replay_whose_steer_is_declared_in_degrees_but_was_in_radians_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // A 3° step (the 1° one, tripled): a turn the check judges.
    let p = logged(dir.path(), |r| {
        for k in [2, 3, 4, 5] {
            r[k] *= 3.0;
        }
    });
    let sc = replay_scenario(&p, "replay.toml", "degrees = [\"steer\"]\n");
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        dir.path().join("o").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("replay.toml:")
            && e.contains("the run run.csv's yaw rate is ")
            && e.contains("× a neutral car's for its steer")
            && e.contains("take `\"steer\"` out of `degrees` under [manoeuvre]"),
        "{e}"
    );
}
