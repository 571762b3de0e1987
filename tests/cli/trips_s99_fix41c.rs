//! A fresh user's findings in `simulate`, `metrics`, `identify` and campaign
//! inputs: a crawl's sideslip on linear tyres judged by their
//! slip angles, a slip angle said as the history holds it, a layout no car
//! has, the low-pass boundary at exactly 0.4 × the sampling rate, rate
//! advice a log already meets, a time gap that ends the measured piece, a
//! campaign's `rear` defaulting to `front`, a fit's points thinned into
//! bins, and a runs folder named with what it holds.

use super::*;

/// The linear sedan (the tester's `lin.toml`) with `vehicle` edits,
/// stepped by `steer` rad at `speed` m/s until `end` s, written to
/// `dir/lin.toml`: the scenario path.
fn linear_car(dir: &Path, vehicle: &[(&str, &str)], speed: f64, steer: f64, end: f64) -> PathBuf {
    let mut v = VEHICLE.to_string();
    for (from, to) in vehicle {
        v = v.replace(from, to);
    }
    let text = format!(
        "name = \"lin\"\n{v}[tyres]\nfront = \"{}\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed:?}\nsteer = {steer:?}\nstart = 1.0\nrise_time = 0.1\nend = {end:?}\n",
        root().join("tyres/linear.toml").display()
    );
    let path = dir.join("lin.toml");
    fs::write(&path, text).unwrap();
    path
}

/// `simulate path --out dir/out`: what it said (stdout, then stderr),
/// and the output folder.
fn simulated(path: &Path, dir: &Path) -> (String, PathBuf) {
    let out = dir.join("out");
    let o = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    (
        String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o),
        out,
    )
}

#[test]
fn a_crawls_sideslip_on_linear_tyres_is_judged_by_their_slip_angles() {
    // 1 m/s, 0.3 rad: β = 10.28° is the geometry's b·δ/l = 10.33°, at
    // steady slip angles of 0.05° and 0.03° (1.3° and 0.13° at most, in
    // the steer's ramp); it was said to take the tyres beyond a linear
    // tyre's range of validity.
    let dir = tempfile::tempdir().unwrap();
    let sc = linear_car(dir.path(), &[], 1.0, 0.3, 8.0);
    let (said, out) = simulated(&sc, dir.path());
    let json = read_json(&out.join("metrics.json"));
    for text in [said, json["warnings"].to_string()] {
        assert!(
            text.contains("the steady sideslip is 10.3°, beyond 10°, but no slide: the linear tyres' slip angles stay within 1.3° (front) and 0.13° (rear), short of the 3°"),
            "{text}"
        );
        assert!(text.contains("(β ≈ b·δ/l)"), "{text}");
        assert!(!text.contains("range of validity"), "{text}");
    }
}

#[test]
fn a_spinning_cars_slip_angle_is_said_as_the_history_holds_it() {
    // The oversteering linear car (a and b swapped) at 35 m/s, above its
    // critical speed of 32.2 m/s: its slip angles run to tens of radians,
    // and were said wrapped, "180.0°".
    let dir = tempfile::tempdir().unwrap();
    let sc = linear_car(
        dir.path(),
        &[("a = 1.11\nb = 1.67", "a = 1.67\nb = 1.11")],
        35.0,
        0.001,
        20.0,
    );
    let (said, out) = simulated(&sc, dir.path());
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let (mut largest, mut at) = (0.0_f64, 0.0);
    for line in history.lines().skip(1) {
        let c: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
        if c[6].abs() > largest.abs() {
            (largest, at) = (c[6], c[0]);
        }
    }
    assert!(largest.abs() > std::f64::consts::PI, "{largest}");
    let expected = format!(
        "the front axle's slip angle reaches {:.0}° ({} rad: the small-angle model's",
        largest.to_degrees(),
        (largest * 100.0).round() / 100.0
    );
    assert!(said.contains(&expected), "{expected}\n{said}");
    assert!(said.contains(&format!("at t = {at:.2} s")), "{said}");
    assert!(!said.contains("180.0°"), "{said}");
}

#[test]
fn a_centre_of_gravity_on_an_axle_and_a_tiny_yaw_inertia_are_warned_of() {
    // a = 0.01 m of 2.78 m, Iz = 40 kg·m² (k = 0.16 m): the dynamic index
    // Iz/(m·a·b) is 0.94, a road car's, and the run said nothing.
    let dir = tempfile::tempdir().unwrap();
    let sc = linear_car(
        dir.path(),
        &[
            ("yaw_inertia = 2315.0", "yaw_inertia = 40.0"),
            ("a = 1.11\nb = 1.67", "a = 0.01\nb = 2.77"),
        ],
        30.0,
        0.01,
        8.0,
    );
    let (said, _) = simulated(&sc, dir.path());
    assert!(
        said.contains("warning: the centre of gravity is 0.01 m from the front axle, 0.36 % of the 2.78 m wheelbase: the rear axle carries 0.36 % of the weight"),
        "{said}"
    );
    assert!(
        said.contains("warning: the radius of gyration √(yaw_inertia/mass) is 0.162 m, 5.8 % of the 2.78 m wheelbase"),
        "{said}"
    );
    // The bundled layout is said nothing of.
    let dir = tempfile::tempdir().unwrap();
    let sc = linear_car(dir.path(), &[], 30.0, 0.01, 8.0);
    let (said, _) = simulated(&sc, dir.path());
    assert!(!said.contains("centre of gravity is"), "{said}");
    assert!(!said.contains("radius of gyration"), "{said}");
}

/// The linear car's step (ramped over `rise_time` s) simulated at 1 ms
/// and logged every `every` rows with its times written to two decimals,
/// as a logger writes them, leaving out the rows of `hole` (s, s): the
/// log's path.
fn logger(dir: &Path, rise_time: f64, every: usize, hole: (f64, f64)) -> PathBuf {
    let history = super::trips_s90_met::tester_step(dir, rise_time, "");
    let text = fs::read_to_string(history).unwrap();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for line in text.lines().skip(1).step_by(every) {
        let c: Vec<f64> = line
            .split(',')
            .take(6)
            .map(|v| v.parse().unwrap())
            .collect();
        if c[0] > hole.0 && c[0] < hole.1 {
            continue;
        }
        out += &format!("{:.2},{},{},{},{},{}\n", c[0], c[1], c[2], c[3], c[4], c[5]);
    }
    let path = dir.join("log.csv");
    fs::write(&path, out).unwrap();
    path
}

#[test]
fn a_low_pass_at_exactly_0_4_of_the_sampling_rate_leaves_the_run_unfiltered() {
    // A 50 Hz log whose times are written to 0.01 s: 20 Hz had filtered
    // it (its median interval a hair under 0.02 s), 20.01 Hz had not.
    // The clock starts at 16 s, as a logger's does mid-session: there
    // 0.02 s steps between decimals read 0.019999999999999574 s.
    let dir = tempfile::tempdir().unwrap();
    let log = logger(dir.path(), 0.1, 20, (0.0, 0.0));
    let text = fs::read_to_string(&log).unwrap();
    let mut late = String::new();
    for (k, line) in text.lines().enumerate() {
        match (k, line.split_once(',')) {
            (0, _) | (_, None) => late += line,
            (_, Some((t, rest))) => {
                late += &format!("{:.2},{rest}", t.parse::<f64>().unwrap() + 16.0);
            }
        }
        late += "\n";
    }
    fs::write(&log, late).unwrap();
    let (j, w) = super::trips_s90_met::measured(&log, &["--filter-hz", "20"]);
    assert!(j["filter_hz"].is_null(), "{}", j["filter_hz"]);
    assert!(
        w.contains("the low-pass at 20 Hz is not below 0.4 × the run's sampling rate: the run is not filtered (0.4 × 50 Hz = 20 Hz"),
        "{w}"
    );
    // Just below the boundary, filtered.
    let (j, w) = super::trips_s90_met::measured(&log, &["--filter-hz", "19.9"]);
    assert_eq!(j["filter_hz"], 19.9, "{w}");
}

#[test]
fn a_log_fast_enough_is_not_told_to_log_faster() {
    // An instant step in a 50 Hz log: E_r is biased by where the samples
    // fall, which the step causes, not the rate; it was told "log at 20 Hz
    // or faster".
    let dir = tempfile::tempdir().unwrap();
    let log = logger(dir.path(), 0.0, 20, (0.0, 0.0));
    let (_, w) = super::trips_s90_met::measured(&log, &[]);
    assert!(
        w.contains("E_r, E_ay and Er are integrals over samples 0.02 s apart (50 Hz), of a step faster than one interval"),
        "{w}"
    );
    assert!(
        w.contains("here the step, rising within one interval, not the log's rate, causes it: ramp the step over a few intervals"),
        "{w}"
    );
    assert!(!w.contains("log at 20 Hz or faster"), "{w}");
}

#[test]
fn a_time_gap_that_ends_the_measured_piece_is_said_with_what_it_cost() {
    // 100 Hz, 5 samples missing 2 s after the step (3.00–3.04 s): the gap
    // splits the run, the 5 s after it dropped, with only the cleaning's
    // "split" and "dropped" lines to say so.
    let dir = tempfile::tempdir().unwrap();
    let log = logger(dir.path(), 0.1, 10, (2.995, 3.045));
    let o = run(&["metrics", log.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o) + &String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("warning: the measured piece ends at 2.990 s where a time gap of 0.06 s (5 samples missing at the log's 0.01 s interval) splits the run: a hole longer than 5 intervals is not interpolated"),
        "{said}"
    );
    assert!(said.contains("fill it in the file"), "{said}");
    assert!(said.contains("were dropped"), "{said}");
}

#[test]
fn a_campaign_with_a_front_tyre_only_runs_it_on_both_axles_and_says_so() {
    // A scenario's `rear` defaults to its `front`; a campaign's was
    // refused ("give either `file`, or `front` and `rear`").
    let dir = tempfile::tempdir().unwrap();
    let runs = dir.path().join("runs");
    fs::create_dir(&runs).unwrap();
    for (name, rise) in [("a.csv", 0.1), ("b.csv", 0.18)] {
        let log = logger(dir.path(), rise, 10, (0.0, 0.0));
        fs::rename(&log, runs.join(name)).unwrap();
        fs::remove_dir_all(dir.path().join("sim")).unwrap();
    }
    let campaign = dir.path().join("campaign.toml");
    let tyre = root().join("tyres/linear.toml");
    let text = |rear: &str| {
        format!(
            "{VEHICLE}[tyres]\nfront = \"{}\"\n{rear}[diagnose]\neffects = [\"cornering_stiffness\"]\n[runs]\ndir = \"runs\"\n",
            tyre.display()
        )
    };
    fs::write(&campaign, text("")).unwrap();
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        dir.path().join("front").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    assert!(
        said.contains("[tyres] gives `front` only: the rear axle runs on the front file too"),
        "{said}"
    );
    // The same diagnosis as the rear named.
    let front_only = read_json(&dir.path().join("front/diagnosis.json"));
    fs::write(&campaign, text(&format!("rear = \"{}\"\n", tyre.display()))).unwrap();
    let (_, both) = diagnose_to(&campaign, &dir.path().join("both"));
    assert_eq!(front_only["verdict"], both["verdict"]);
    assert_eq!(front_only["ranking"], both["ranking"]);
}

#[test]
fn too_few_points_after_thinning_says_how_many_samples_went_into_how_many_bins() {
    // Three samples 0.0025 rad apart, two in one 0.25° bin: "2 points"
    // said of a file with three rows.
    let dir = scratch(&[(
        "rig.csv",
        "fz,alpha,fy\n1991.98,-0.2,-1845.18\n1986.76,-0.1975,-1835.99\n1997.52,-0.195,-1858.23\n",
    )]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--out",
        dir.path().join("out.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("3 samples with a measured lateral force in 2 bins of 0.250° slip angle (--bin-deg) cannot fit 3 parameters"),
        "{e}"
    );
}

#[test]
fn a_runs_folder_without_csv_files_names_what_it_holds() {
    let dir = tempfile::tempdir().unwrap();
    let runs = dir.path().join("runs");
    fs::create_dir(&runs).unwrap();
    fs::write(runs.join("notes.txt"), "driver: A\n").unwrap();
    fs::write(dir.path().join("vehicle.toml"), VEHICLE).unwrap();
    let e = fails_cleanly("diagnose", dir.path(), dir.path());
    assert!(
        e.contains("holds no *.csv file (it holds notes.txt)"),
        "{e}"
    );
}
