//! What fresh-eyes round 39 tripped on in rig rows, run signs, campaigns
//! and fleets, run as a user runs the tool: one negative load of three
//! refused as `fz` and `fy` exchanged, two sign slips in two files heard
//! one at a time, a fleet table saying 0 runs for failed campaigns that
//! read 1 and 8, a folder campaign of one run told to "set [runs]
//! segment", two dead channels counted as "2 places", and `--min-speed`
//! refused in a form of its own.

use super::*;

/// A synthetic campaign (`sensor_delay` withheld, noise seed 2) copied to
/// `dir/name`, as `handling synth --effects sensor_delay --seed 2` writes.
fn seed2(dir: &Path, name: &str) -> PathBuf {
    synth_campaign(dir, name, &["--effects", "sensor_delay", "--seed", "2"])
}

/// `identify --model linear` of rig file `rig`, expected to fail: stderr.
fn rig_refused(dir: &Path, rig: &Path) -> String {
    let out = dir.join("never.toml");
    let o = identify_to(rig, "linear", &out);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(!out.exists(), "{e}");
    e
}

/// Round 39's `rig_negfz.csv`: three rows, one load at −4000 N, `fy` of
/// 500, 900 and 1300 N. Main refused it as "columns `fz` and `fy` look
/// exchanged" (a third of the loads negative, every `fy` positive); it is
/// one bad row, said at its line, column and value.
#[test]
fn one_negative_load_of_three_is_a_bad_row_not_an_exchange() {
    let dir = scratch(&[(
        "rig_negfz.csv",
        "t,fz,alpha,camber,fy\n0,4000,0.01,0,500\n0.1,-4000,0.02,0,900\n0.2,4000,0.03,0,1300\n",
    )]);
    let e = rig_refused(dir.path(), &dir.path().join("rig_negfz.csv"));
    assert!(
        e.contains(
            "rig_negfz.csv:3:2: column `fz`: -4000 N is negative (loads are positive in FORMATS.md)"
        ),
        "{e}"
    );
    assert!(!e.contains("exchanged"), "{e}");
}

/// The other side of the rule, on a rig's shape: a swept lateral force
/// under `fz` (both signs, filling its range) beside loads under `fy` at
/// three levels with a rig's 1 % scatter is the exchange, asked as one
/// swap at the first negative "load".
#[test]
fn a_swept_force_under_fz_beside_loads_at_levels_is_an_exchange() {
    let mut rig = String::from("alpha,fz,fy\n");
    let mut k = 0_u32;
    for load in [1500.0_f64, 3000.0, 4500.0] {
        for i in 0..21 {
            let alpha = (f64::from(i) - 10.0) * 0.01;
            let force = -1.1 * load * (10.0 * alpha).atan() * 2.0 / std::f64::consts::PI;
            // A deterministic scatter of ±1 % about the level.
            k += 1;
            let scatter = 1.0 + 0.01 * (f64::from(k) * 2.3).sin();
            rig += &format!("{alpha},{force},{}\n", load * scatter);
        }
    }
    let dir = scratch(&[("swapped.csv", &rig)]);
    let e = rig_refused(dir.path(), &dir.path().join("swapped.csv"));
    assert!(
        e.contains("swapped.csv:13:2: columns `fz` and `fy` look exchanged: `fz` changes sign (30 of its 63 samples negative")
            && e.contains("swap the two names in the header"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1, "{e}");
}

/// Round 39's `c_two`: `yaw_rate` negated in one run file, `beta` in
/// another. Main refused the yaw rate alone and said nothing of the other
/// file: the user mended one, reran, and only then heard of the second.
/// The `beta` check needs the base model fitted to every run, so the
/// refusal says that the other runs' `beta` is not checked yet; mending
/// the yaw rate as asked, the rerun names the `beta` file.
#[test]
fn a_yaw_rate_refused_says_the_other_runs_sideslip_is_not_checked_yet() {
    let dir = tempfile::tempdir().unwrap();
    let c = seed2(dir.path(), "c_two");
    let yaw = c.join("runs/step_060kph_2ms2.csv");
    map_column(&yaw, "yaw_rate", |v| -v);
    map_column(&c.join("runs/step_120kph_4ms2.csv"), "beta", |v| -v);
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(lines[0], "error: 1 of 8 runs refused, in run order:", "{e}");
    assert!(
        lines[1].contains("step_060kph_2ms2.csv: the yaw rate turns against the steer")
            && lines[1].ends_with("`yaw_rate` is in the other sign convention; negate it"),
        "{e}"
    );
    assert!(
        lines[2].contains("ramp_080kph.csv: taken, but its `beta` (and of ")
            && lines[2].contains("step_120kph_4ms2.csv")
            && lines[2].contains("is not checked yet: their signs are judged against the base model's sideslip, which is fitted only once every run is taken"),
        "{e}"
    );
    assert_eq!(lines.len(), 3, "{e}");
    // Negating the yaw rate back, as asked: the `beta` file is named.
    map_column(&yaw, "yaw_rate", |v| -v);
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    assert!(
        e.contains("`beta` of ")
            && e.contains("step_120kph_4ms2.csv moves against the base model's sideslip"),
        "{e}"
    );
}

/// Round 39's fleet: campaign `b` (one run after checking) and `c` (a
/// reversed `beta`) failed and fleet.csv said `runs` = 0 for both,
/// although `b` read 1 run and `c` 8. A failed campaign's runs kept and
/// files read are said in fleet.csv, fleet.json and fleet.html.
#[test]
fn a_failed_campaign_of_the_fleet_says_its_runs() {
    let dir = tempfile::tempdir().unwrap();
    let fleet = dir.path().join("fleet");
    fs::create_dir_all(&fleet).unwrap();
    seed2(&fleet, "a");
    let b = seed2(&fleet, "b");
    for f in fs::read_dir(b.join("runs")).unwrap() {
        let f = f.unwrap().path();
        if !f.ends_with("step_120kph_4ms2.csv") {
            fs::remove_file(f).unwrap();
        }
    }
    let c = seed2(&fleet, "c");
    map_column(&c.join("runs/step_100kph_6ms2.csv"), "beta", |v| -v);
    let out = dir.path().join("dg_fleet");
    let o = run(&[
        "diagnose",
        "--batch",
        fleet.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let said = stderr(&o);
    let csv = fs::read_to_string(out.join("fleet.csv")).unwrap_or_else(|_| panic!("{said}"));
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let cells = |k: usize| {
        let r = &rows[k];
        (
            r[at("campaign")],
            r[at("runs")],
            r[at("runs_read")],
            r[at("failed")],
        )
    };
    assert_eq!(cells(0), ("a", "8", "8", "false"), "{csv}");
    assert_eq!(cells(1), ("b", "1", "1", "true"), "{csv}");
    assert_eq!(cells(2), ("c", "8", "8", "true"), "{csv}");
    let json = read_json(&out.join("fleet.json"));
    let row = |k: usize| &json["campaigns"][k];
    assert_eq!(
        (row(1)["runs"].clone(), row(1)["runs_read"].clone()),
        (1.into(), 1.into()),
        "{json}"
    );
    assert_eq!(
        (row(2)["runs"].clone(), row(2)["runs_read"].clone()),
        (8.into(), 8.into()),
        "{json}"
    );
    let html = fs::read_to_string(out.join("fleet.html")).unwrap();
    for campaign in ["b", "c"] {
        let runs = if campaign == "b" { "1" } else { "8" };
        let row = html
            .split("<tr>")
            .find(|r| r.contains(&format!("{campaign}: FAILED")))
            .unwrap_or_else(|| panic!("{html}"));
        assert!(
            row.contains(&format!("<td class=\"num\">{runs}</td>")),
            "{row}"
        );
    }
}

/// Round 39's `c_few` and fleet `b`: a campaign folder of one 6 s run was
/// told "set [runs] segment = … to cut a long log into pieces", with no
/// word of where a folder campaign writes it, for a run too short to cut.
/// It is told to add a run file to its `runs/`; following that, it is
/// diagnosed.
#[test]
fn a_folder_campaign_of_one_short_run_is_told_to_add_a_run_file() {
    let dir = tempfile::tempdir().unwrap();
    let spare = seed2(dir.path(), "spare");
    let c = seed2(dir.path(), "few");
    for f in fs::read_dir(c.join("runs")).unwrap() {
        let f = f.unwrap().path();
        if !f.ends_with("step_120kph_4ms2.csv") {
            fs::remove_file(f).unwrap();
        }
    }
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    let runs = c.join("runs");
    assert!(
        e.contains(&format!(
            "1 run after checking (601 of 601 samples at or above min_speed = 5 m/s in pieces long enough): held-out scoring needs at least two: add a run file to `{}` (the campaign reads every *.csv there as a run)",
            runs.display()
        )),
        "{e}"
    );
    assert!(!e.contains("segment"), "{e}");
    fs::copy(
        spare.join("runs/step_060kph_2ms2.csv"),
        runs.join("step_060kph_2ms2.csv"),
    )
    .unwrap();
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(ok, "{e}");
}

/// A folder campaign of one long log (a 6 s step logged four times over,
/// 24 s): told where `segment` goes (its vehicle.toml, which takes a
/// `[runs]` table) and what to write; following that, it is diagnosed.
#[test]
fn a_folder_campaign_of_one_long_log_is_told_where_to_write_segment() {
    let dir = tempfile::tempdir().unwrap();
    let c = seed2(dir.path(), "long");
    let step = fs::read_to_string(c.join("runs/step_100kph_6ms2.csv")).unwrap();
    for f in fs::read_dir(c.join("runs")).unwrap() {
        fs::remove_file(f.unwrap().path()).unwrap();
    }
    let mut lines = step.lines();
    let mut log = format!("{}\n", lines.next().unwrap());
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let span = rows[rows.len() - 1][0] - rows[0][0] + 0.01;
    for k in 0..4 {
        for r in &rows {
            let t = ((r[0] + f64::from(k) * span) * 1e6).round() / 1e6;
            let rest: Vec<String> = r[1..].iter().map(f64::to_string).collect();
            log += &format!("{t},{}\n", rest.join(","));
        }
    }
    fs::write(c.join("runs/log.csv"), log).unwrap();
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    let vehicle = c.join("vehicle.toml");
    assert!(
        e.contains(&format!(
            "; or cut the 24.0 s log into pieces of 10 s: write a table `[runs]` holding `segment = 10` into {} (a campaign folder's vehicle.toml takes one)",
            vehicle.display()
        )),
        "{e}"
    );
    let text = fs::read_to_string(&vehicle).unwrap();
    fs::write(&vehicle, text + "\n[runs]\nsegment = 10\n").unwrap();
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(ok, "{e}");
}

/// A run with `ay` and `beta` dead (one value throughout): main opened its
/// refusal "2 places refused, in file order"; they are two channels.
#[test]
fn two_dead_channels_are_counted_as_channels() {
    let dir = tempfile::tempdir().unwrap();
    let c = seed2(dir.path(), "dead");
    let run = c.join("runs/step_100kph_6ms2.csv");
    map_column(&run, "ay", |_| 0.0);
    map_column(&run, "beta", |_| 0.0);
    let (ok, e) = diagnose_status(&c, &dir.path().join("d"));
    assert!(!ok, "{e}");
    assert!(
        e.contains("step_100kph_6ms2.csv: 2 channels refused:\n")
            && e.contains("channel `ay` holds one value (0) over the whole run")
            && e.contains("channel `beta` holds one value (0) over the whole run"),
        "{e}"
    );
    assert!(!e.contains("places"), "{e}");
}

/// `metrics --min-speed 500` was refused by the option's parser in a form
/// of its own ("the lowest speed kept is a speed of 0 to 150 m/s (no car
/// runs faster)"), where `--min-overshoot 500` and a campaign's
/// `min_speed` say the key, the value and the range: now it reads as they
/// do, with the value to write as the option takes it.
#[test]
fn metrics_min_speed_is_refused_as_the_other_settings_are() {
    let dir = tempfile::tempdir().unwrap();
    let c = seed2(dir.path(), "m");
    let run_file = c.join("runs/step_100kph_6ms2.csv");
    let refused = |option: &str, value: &str| {
        let o = run(&["metrics", run_file.to_str().unwrap(), option, value]);
        assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
        stderr(&o)
    };
    let e = refused("--min-speed", "500");
    assert!(
        e.starts_with("error: --min-speed: `min_speed` = 500: must lie in [0, 100]: it is the speed in m/s below which samples are left out as slow")
            && e.contains("write a speed in m/s, such as `--min-speed 5` (the default)"),
        "{e}"
    );
    let e = refused("--min-speed", "200");
    assert!(
        e.contains("is it in km/h? 200 km/h is 55.6 m/s: write `--min-speed 55.6`"),
        "{e}"
    );
    let o = refused("--min-overshoot", "500");
    assert!(
        o.starts_with("error: --min-overshoot: `min_overshoot` = 500: must lie in [0, 100]"),
        "{o}"
    );
}
