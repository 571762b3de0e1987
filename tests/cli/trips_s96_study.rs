//! What fresh-eyes users tripped on in `design`, `study` and `simulate`
//! (session 96, round 26): a test the design called "not recommended"
//! that separated the candidates on every run driven, a sub-threshold
//! overshoot written as a measured 0, a run said to settle and not to
//! settle, and an RK4 peak time given on its grid without its resolution.

use super::*;
use rand::SeedableRng;
use std::fs;

/// The logger of the tester's campaign: 100 Hz, every response 60 ms
/// late, white noise of 0.002 rad/s, 0.03 m/s² and 0.0005 rad.
const DELAY: f64 = 0.06;
const NOISE: [f64; 3] = [0.002, 0.03, 0.0005];

/// `history.csv` of a simulation logged as the tester's logger logs:
/// rows every 0.01 s, responses `DELAY` late and noisy (seed `seed`),
/// columns t, speed, steer, yaw_rate, ay, beta.
fn logged(history: &Path, seed: u64) -> String {
    let (head, rows) = numeric_csv(history);
    let col = |name: &str| column(&head, name);
    let dt = rows[1][col("t")] - rows[0][col("t")];
    let (every, late) = ((0.01 / dt).round() as usize, (DELAY / dt).round() as usize);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut noisy = |v: f64, sd: f64| v + sd * handling::identify::data::gauss(&mut rng);
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in (0..rows.len()).step_by(every) {
        let (now, then) = (&rows[i], &rows[i.saturating_sub(late)]);
        let (r, ay, beta) = (
            noisy(then[col("yaw_rate")], NOISE[0]),
            noisy(then[col("ay")], NOISE[1]),
            noisy(then[col("beta")], NOISE[2]),
        );
        s += &format!(
            "{:.2},{},{},{r},{ay},{beta}\n",
            now[col("t")],
            now[col("speed")],
            now[col("steer")]
        );
    }
    s
}

/// Simulates `scenario` (a file) into `out`: its history.
fn simulated(scenario: &Path, out: &Path) -> PathBuf {
    super::scenarios::simulate_to(scenario, out);
    out.join("history.csv")
}

/// The tester's campaign `diag/delay60` (py/camp.py): the linear car of
/// the campaign's own tyre file stepped at 15, 25 and 35 m/s (and to the
/// right at 25) and swept at 1 Hz (25 m/s) and 2 Hz (30 m/s), logged 60 ms
/// late: the base model with a sensor delay is the car, no model-form
/// error. Its candidates are narrowed to the two delays it confounds.
pub(crate) fn delayed_campaign(dir: &Path) -> PathBuf {
    let c = dir.join("delay60");
    fs::create_dir_all(c.join("runs")).unwrap();
    linear_tyre(&c);
    fs::write(
        c.join("vehicle.toml"),
        format!("{VEHICLE}[tyres]\nfile = \"tyre.toml\"\n[diagnose]\nseed = 1\neffects = [\"sensor_delay\", \"steer_path\"]\n"),
    )
    .unwrap();
    let step = |u: f64, d: f64| {
        format!("kind = \"step-steer\"\nspeed = {u:?}\nsteer = {d:?}\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n")
    };
    let sine = |u: f64, a: f64, f: f64| {
        let t: Vec<f64> = (0..=800).map(|i| 0.01 * i as f64).collect();
        let d: Vec<f64> = t
            .iter()
            .map(|&x| {
                if x > 1.0 {
                    a * (std::f64::consts::TAU * f * (x - 1.0)).sin()
                } else {
                    0.0
                }
            })
            .collect();
        format!(
            "kind = \"schedule\"\nt = {t:?}\nsteer = {d:?}\nspeed = {:?}\n",
            vec![u; t.len()]
        )
    };
    let runs = [
        ("step15", step(15.0, 0.03)),
        ("step25", step(25.0, 0.015)),
        ("step35", step(35.0, 0.008)),
        ("stepR25", step(25.0, -0.02)),
        ("sine25_1hz", sine(25.0, 0.01, 1.0)),
        ("sine30_2hz", sine(30.0, 0.006, 2.0)),
    ];
    for (k, (name, manoeuvre)) in runs.iter().enumerate() {
        let scenario = dir.join(format!("{name}.toml"));
        fs::write(
            &scenario,
            format!("name = \"{name}\"\n{VEHICLE}[tyres]\nfront = \"delay60/tyre.toml\"\n[manoeuvre]\n{manoeuvre}[simulation]\nstep = 0.01\n"),
        )
        .unwrap();
        let history = simulated(&scenario, &dir.join(format!("sim_{name}")));
        fs::write(
            c.join(format!("runs/{name}.csv")),
            logged(&history, k as u64),
        )
        .unwrap();
    }
    c
}

/// Before: the campaign's runs "measure it with 4.7 times the noise's
/// scatter", and the best manoeuvre (braking in a turn at 90 km/h) was
/// "expected to measure 4.9 ± 8.9; not recommended"; driven on the car
/// (8 seeds) it measured 5.81 ± 1.15, every run favouring the reference.
/// The scatter was the noise of each campaign run's first sample, which
/// its replays start from (a sideslip a floor off is an ay several floors
/// off for tenths of a second), read as model-form error where the
/// reference leaves none (its held-out error below the noise level); and
/// the start of the prediction was moved by the sideslip's floor (an
/// estimated output's 0.005 rad) where its noise is ten times less. Now
/// the campaign's runs are replayed from their settled starts (session 97;
/// session 96 widened only where the reference leaves a gap above the
/// noise), and the start moves by the channels' own noise: the prediction
/// is the noise's D ± 1, recommended, and runs driven on the car land
/// within it.
#[test]
fn a_design_on_a_car_its_base_model_matches_predicts_what_driving_it_measures() {
    let dir = tempfile::tempdir().unwrap();
    let c = delayed_campaign(dir.path());
    let diagnosis = dir.path().join("diag");
    let (said, d) = diagnose_to(&c, &diagnosis);
    assert!(
        said.contains("confounded: sensor_delay, steer_path")
            || said.contains("confounded: steer_path, sensor_delay"),
        "{said}"
    );
    assert!(d["gap"]["noise"][2]["noise_floor"].as_f64().unwrap() > 5.0 * NOISE[2]);
    let o = run(&["design", diagnosis.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let design = read_json(&diagnosis.join("design/design.json"));
    let set = &design["sets"][0];
    // Replayed from their settled starts (session 97), the campaign's
    // runs measure the noise's scatter.
    let cal = &set["calibration"];
    assert!(cal["runs"].as_u64().unwrap() >= 1, "{set}");
    assert!(cal["inflation"].as_f64().unwrap() < 1.6, "{said}");
    let best = &set["ranked"][0];
    let (name, separation) = (
        best["name"].as_str().unwrap(),
        best["separation"].as_f64().unwrap(),
    );
    let (expected, uncertainty) = (
        best["expected"].as_f64().unwrap(),
        best["uncertainty"].as_f64().unwrap(),
    );
    // On a car of the reference with white noise: D ± 1 (the parameters'
    // and the averaged start's parts are small).
    assert!(separation > 3.0, "{said}");
    assert!((expected - separation).abs() < 0.5, "{said}");
    assert!((1.0..1.5).contains(&uncertainty), "{said}");
    assert_eq!(best["worth"], "separates", "{said}");
    // Driven on the car: simulated from the design's scenario, logged as
    // the campaign is, on four seeds.
    let scenario = diagnosis.join(format!("design/scenarios/{name}.toml"));
    let history = simulated(&scenario, &dir.path().join("drive"));
    let mut measured = Vec::new();
    for seed in 0..4 {
        let csv = dir.path().join(format!("{name}.csv"));
        fs::write(&csv, logged(&history, 1000 + seed)).unwrap();
        let out = dir.path().join(format!("m{seed}"));
        let o = run(&[
            "design",
            diagnosis.to_str().unwrap(),
            "--measured",
            csv.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let m = &read_json(&out.join("design.json"))["measured"][0];
        assert_eq!(m["favours"], "sensor_delay", "{m}");
        let deviation = m["predicted"]["deviation"].as_f64().unwrap();
        assert!(deviation.abs() < 3.0, "seed {seed}: {m}");
        measured.push(m["separation"].as_f64().unwrap());
    }
    let mean = measured.iter().sum::<f64>() / 4.0;
    // The mean of four within 3 standard errors of the prediction.
    assert!(
        (mean - expected).abs() < 3.0 * uncertainty / 2.0,
        "{measured:?} against {expected} ± {uncertainty}"
    );
}

/// The tester's `lin/linstudy2.toml` at front 80 000 and rear 57 000
/// N/rad (linear tyres at 30 m/s, 0.005 rad): a real yaw-rate peak of
/// 0.595 % of the step, below the 1 % threshold, written as a measured
/// `0` with "no peak above its steady value (0 % overshoot)".
fn sub_threshold_study(metrics: &str) -> (String, String) {
    let study = format!(
        "name = \"linstudy2\"\n{VEHICLE}[tyres]\nfront = \"tyre.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 30.0\nsteer = 0.005\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n[stiffness]\nunit = \"N/rad\"\nfront = [80000.0]\nrear = [57000.0]\n{metrics}"
    );
    let dir = scratch(&[("study.toml", &study)]);
    linear_tyre(dir.path());
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = fs::read_to_string(dir.path().join("out/study.csv")).unwrap();
    let mut lines = csv.lines();
    (lines.next().unwrap().into(), lines.next().unwrap().into())
}

/// The cell of column `name` in `row` under `head` (no quoted commas
/// before the note).
fn cell<'a>(head: &str, row: &'a str, name: &str) -> &'a str {
    let at = head.split(',').position(|h| h == name).unwrap();
    row.split(',').nth(at).unwrap()
}

/// Before: `yaw_rate_overshoot` 0 and "the yaw rate has no peak above its
/// steady value (0 % overshoot)" for a peak of 0.6 %. Now the cell is
/// empty, the threshold it is below is its own column, and the note says
/// it is below the threshold, not a measured 0; with `min_overshoot = 0`
/// the same combination measures the peak (between 0 and the 1 %).
#[test]
fn a_study_writes_a_sub_threshold_overshoot_as_below_its_threshold_not_as_zero() {
    let (head, row) = sub_threshold_study("");
    assert_eq!(cell(&head, &row, "yaw_rate_overshoot"), "", "{head}\n{row}");
    assert_eq!(
        cell(&head, &row, "yaw_rate_peak_threshold"),
        "1",
        "{head}\n{row}"
    );
    assert!(
        row.contains("no yaw-rate maximum stands more than 1 % above the steady value")
            && row.contains("not a measured 0")
            && !row.contains("0 % overshoot"),
        "{row}"
    );
    let (head, row) = sub_threshold_study("[metrics]\nmin_overshoot = 0.0\n");
    let overshoot: f64 = cell(&head, &row, "yaw_rate_overshoot").parse().unwrap();
    assert!(overshoot > 0.3 && overshoot < 1.0, "{row}");
    let threshold: f64 = cell(&head, &row, "yaw_rate_peak_threshold")
        .parse()
        .unwrap();
    assert!(threshold < overshoot, "{row}");
}

/// Before: the sedan stepped for 8.5 m/s² said "has not settled in the
/// steady window" and then "the run settles at 8.27 m/s² (-3 %)" (its ay
/// still rising, 8.24 → 8.40 m/s² over 5–6 s). Now it says the run has
/// not settled and is still moving, with the steady window's mean as that.
#[test]
fn a_run_that_has_not_settled_is_not_said_to_settle_at_its_mean() {
    let text = bundled_scenario("sedan_step.toml").replace(
        "steer = 0.0174533    # rad = 1 deg front road-wheel angle",
        "lateral_acceleration = 8.5",
    );
    assert!(text.contains("lateral_acceleration = 8.5"));
    let dir = scratch(&[("scenario.toml", &text)]);
    let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains("has not settled"), "{said}");
    assert!(!said.contains("the run settles at"), "{said}");
    assert!(
        said.contains("but the run has not settled: its lateral acceleration averages 8.27 m/s² (-3 %) over the steady window and is still moving"),
        "{said}"
    );
    // Still approaching the stable steady state it was solved from
    // (session 110): it ends before it settles, not on another branch.
    assert!(
        said.contains("the run ends before the car settles, still approaching the steady state its steer was solved from: at t = 6.00 s"),
        "{said}"
    );
    assert!(!said.contains("is not the one the step reaches"), "{said}");
}

/// The tester's `lin/rk4_20.toml`: the linear car stepped by 0.01 rad at
/// 25 m/s, RK4 at 0.05 s, "peak time 0.3500 s" without a word (Dormand–
/// Prince's dense output: 0.3417 s); `metrics` on such rows says the
/// resolution. Now `simulate` says it too, ±0.025 s, and the dense
/// output's peak lies within it; Dormand–Prince says nothing of a grid.
#[test]
fn an_rk4_peak_time_is_given_with_its_resolution_and_holds_the_dense_one() {
    let run_with = |simulation: &str| {
        let scenario = format!(
            "name = \"rk4_20\"\n{VEHICLE}[tyres]\nfront = \"tyre.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 25.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n{simulation}"
        );
        let dir = scratch(&[("scenario.toml", &scenario)]);
        linear_tyre(dir.path());
        let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let m = read_json(&dir.path().join("out/metrics.json"));
        (
            String::from_utf8_lossy(&o.stdout).into_owned(),
            m["yaw_rate_peak_time"].as_f64().unwrap(),
        )
    };
    let (said, grid) = run_with("[simulation]\nmethod = \"rk4\"\nstep = 0.05\n");
    let (dense_said, dense) = run_with("");
    assert!(
        said.contains("is a row of the RK4 run (no dense output to locate it between rows): it is resolved to ±0.025 s, half the 0.0500 s step"),
        "{said}"
    );
    assert!((grid - dense).abs() <= 0.025, "{grid} against {dense}");
    assert!(!dense_said.contains("resolved to"), "{dense_said}");
}
