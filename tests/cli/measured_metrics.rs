//! Step-steer metrics of measured (noisy) runs from files, through
//! `handling metrics`.

use super::*;

/// A seeded standard normal stream (splitmix64 + Box–Muller): the test's own.
struct Gauss(u64);

impl Gauss {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn next(&mut self) -> f64 {
        let (u1, u2) = (self.uniform().max(1e-300), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// Columns t, speed, steer, yaw_rate, ay, beta as a measured-run CSV, with
/// white noise of `noise` times each response's final value added.
fn run_csv(cols: &[Vec<f64>; 6], noise: f64, seed: u64) -> String {
    let mut g = Gauss(seed);
    let last = |c: &Vec<f64>| c[c.len() - 1].abs();
    let scale = [
        0.0,
        0.0,
        0.0,
        last(&cols[3]),
        last(&cols[4]),
        last(&cols[5]),
    ];
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in 0..cols[0].len() {
        let row: Vec<String> = cols
            .iter()
            .zip(scale)
            .map(|(c, sc)| format!("{}", c[i] + noise * sc * g.next()))
            .collect();
        s += &row.join(",");
        s.push('\n');
    }
    s
}

fn metrics(dir: &Path, name: &str, text: &str) -> serde_json::Value {
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    let o = run(&["metrics", path.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The step steer of `scenarios/sedan_step.toml`, simulated and sampled at
/// 100 Hz like a logger.
fn simulated_run() -> [Vec<f64>; 6] {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "simulate",
        "scenarios/sedan_step.toml",
        "--out",
        out.path().join("o").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(out.path().join("o/history.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let idx = ["t", "speed", "steer", "yaw_rate", "ay", "beta"]
        .map(|n| header.iter().position(|h| *h == n).unwrap());
    let mut cols: [Vec<f64>; 6] = Default::default();
    for (i, line) in lines.enumerate() {
        if i % 10 != 0 {
            continue;
        }
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        for (c, &k) in cols.iter_mut().zip(&idx) {
            c.push(v[k]);
        }
    }
    cols
}

fn f(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key}: {v}"))
}

#[test]
fn metrics_of_a_noisy_run_agree_with_the_noise_free_ones() {
    let cols = simulated_run();
    let dir = tempfile::tempdir().unwrap();
    let clean = metrics(dir.path(), "clean.csv", &run_csv(&cols, 0.0, 1));
    assert_eq!(clean["filter_hz"], 10.0, "the filter is stated: {clean}");
    for seed in 1..=3 {
        let noisy = metrics(dir.path(), "noisy.csv", &run_csv(&cols, 0.005, seed));
        for key in [
            "yaw_rate_response_time",
            "ay_response_time",
            "yaw_rate_peak_time",
        ] {
            let (a, b) = (f(&clean, key), f(&noisy, key));
            assert!((a - b).abs() <= 0.03, "seed {seed} {key}: {a} vs {b}");
        }
        let (a, b) = (
            f(&clean, "yaw_rate_overshoot"),
            f(&noisy, "yaw_rate_overshoot"),
        );
        assert!((a - b).abs() <= 1.0, "seed {seed} overshoot {a} vs {b}");
        let (a, b) = (
            f(&clean, "yaw_rate_total_variance"),
            f(&noisy, "yaw_rate_total_variance"),
        );
        assert!((a - b).abs() <= 0.02 * a, "seed {seed} E_r {a} vs {b}");
    }
    // The noise-free file reproduces the simulation's own metrics.
    assert!(
        (f(&clean, "yaw_rate_overshoot") - 16.90).abs() < 0.1,
        "{clean}"
    );
}

#[test]
fn a_longer_noisy_record_has_the_same_total_variance() {
    // 60 s more of steady driving: the window from the steer onset is fixed,
    // so the noise of the extra record does not add to E.
    let cols = simulated_run();
    let mut long = cols.clone();
    let dt = cols[0][1] - cols[0][0];
    let n = cols[0].len();
    for i in 1..=6000 {
        long[0].push(cols[0][n - 1] + i as f64 * dt);
        for c in long.iter_mut().skip(1) {
            let v = c[n - 1];
            c.push(v);
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let short = metrics(dir.path(), "short.csv", &run_csv(&cols, 0.005, 7));
    let long = metrics(dir.path(), "long.csv", &run_csv(&long, 0.005, 7));
    for key in ["yaw_rate_total_variance", "ay_total_variance"] {
        let (a, b) = (f(&short, key), f(&long, key));
        assert!((a - b).abs() <= 0.005 * a, "{key}: {a} vs {b}");
    }
}

#[test]
fn an_overdamped_noisy_response_has_no_overshoot() {
    // A critically damped-plus response (ζ = 1.3, ωn = 8 rad/s) to a 0.1 s
    // steer ramp, 100 Hz, 0.5 % noise.
    let (zeta, wn): (f64, f64) = (1.3, 8.0);
    let s1 = wn * (zeta - (zeta * zeta - 1.0).sqrt());
    let s2 = wn * (zeta + (zeta * zeta - 1.0).sqrt());
    let step = |t: f64| {
        if t <= 0.0 {
            0.0
        } else {
            1.0 - (s2 * (-s1 * t).exp() - s1 * (-s2 * t).exp()) / (s2 - s1)
        }
    };
    let t: Vec<f64> = (0..=800).map(|i| 0.01 * i as f64).collect();
    let ramp = |x: f64| ((x - 1.0) / 0.1).clamp(0.0, 1.0);
    // The response to a ramp is the ramp's average of step responses.
    let resp = |x: f64| {
        (0..10)
            .map(|k| step(x - 1.0 - 0.01 * k as f64))
            .sum::<f64>()
            / 10.0
    };
    let cols = [
        t.clone(),
        vec![20.0; t.len()],
        t.iter().map(|&x| 0.02 * ramp(x)).collect(),
        t.iter().map(|&x| 0.08 * resp(x)).collect(),
        t.iter().map(|&x| 1.6 * resp(x - 0.05)).collect(),
        t.iter().map(|&x| -0.004 * resp(x)).collect(),
    ];
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=12 {
        let m = metrics(dir.path(), "run.csv", &run_csv(&cols, 0.005, seed));
        assert!(m["yaw_rate_peak_time"].is_null(), "seed {seed}: {m}");
        // Below what the run resolves: not a measured 0.
        assert!(m["yaw_rate_overshoot"].is_null(), "seed {seed}: {m}");
        assert!(m["tb"].is_null());
    }
}

/// A measured-run CSV of `cols` (t, speed, steer, yaw_rate, ay, beta) with
/// the columns named in `keep` only.
fn csv_of(cols: &[Vec<f64>; 6], keep: &[&str]) -> String {
    let names = ["t", "speed", "steer", "yaw_rate", "ay", "beta"];
    let idx: Vec<usize> = keep
        .iter()
        .map(|k| names.iter().position(|n| n == k).unwrap())
        .collect();
    let mut s = keep.join(",") + "\n";
    for (i, _) in cols[0].iter().enumerate() {
        let row: Vec<String> = idx.iter().map(|&k| format!("{}", cols[k][i])).collect();
        s += &(row.join(",") + "\n");
    }
    s
}

#[test]
fn a_log_of_several_manoeuvres_is_measured_on_its_step_and_a_run_without_ay_on_yaw_rate() {
    let cols = simulated_run();
    let dir = tempfile::tempdir().unwrap();
    let all = ["t", "speed", "steer", "yaw_rate", "ay", "beta"];
    let one = metrics(dir.path(), "one.csv", &csv_of(&cols, &all));
    // The step, a 3 s standstill, then 15 s of straight driving: the longest
    // moving piece holds no step.
    let mut log = cols.clone();
    let (t_end, u) = (cols[0][cols[0].len() - 1], cols[1][0]);
    for k in 1..=1800 {
        let t = t_end + 0.01 * k as f64;
        let moving = t > t_end + 3.0;
        let row = [t, if moving { u } else { 0.0 }, 0.0, 0.0, 0.0, 0.0];
        for (c, v) in log.iter_mut().zip(row) {
            c.push(v);
        }
    }
    let multi = metrics(dir.path(), "multi.csv", &csv_of(&log, &all));
    for key in [
        "yaw_rate_response_time",
        "yaw_rate_gain",
        "ay_response_time",
        "er",
    ] {
        assert_eq!(multi[key], one[key], "{key}");
    }
    let dropped = multi["cleaning"]["dropped_pieces"].as_array().unwrap();
    assert_eq!(dropped.len(), 1, "{dropped:?}");
    assert!(
        dropped[0]["reason"]
            .as_str()
            .unwrap()
            .contains("no steer step"),
        "{dropped:?}"
    );
    assert_eq!(multi["cleaning"]["slow"][0]["kind"], "standstill");
    // Without ay: the yaw-rate metrics, the ay ones null and a warning.
    let no_ay = metrics(
        dir.path(),
        "no_ay.csv",
        &csv_of(&cols, &["t", "speed", "steer", "yaw_rate", "beta"]),
    );
    for key in [
        "yaw_rate_response_time",
        "yaw_rate_overshoot",
        "yaw_rate_gain",
        "tb",
    ] {
        assert_eq!(no_ay[key], one[key], "{key}");
    }
    for key in ["ay_response_time", "ay_steady", "ay_total_variance", "er"] {
        assert!(no_ay[key].is_null(), "{key}: {}", no_ay[key]);
    }
    assert!(no_ay["warnings"][0].as_str().unwrap().contains("no `ay`"));
    // The scenario's steer rises 10–90 % within ISO 7401's 0.15 s; a steer
    // ramped over 0.5 s does not, and is flagged.
    assert!(f(&one, "steer_rise_time") <= 0.15, "{one}");
    assert!(one["warnings"].as_array().unwrap().is_empty(), "{one}");
    let mut slow = cols.clone();
    let (t0, step) = (f(&one, "time_zero"), f(&one, "steer_step"));
    let start = t0 - 0.05;
    slow[2] = slow[0]
        .iter()
        .map(|t| step * ((t - start) / 0.5).clamp(0.0, 1.0))
        .collect();
    let ramp = metrics(dir.path(), "ramp.csv", &csv_of(&slow, &all));
    let rise = f(&ramp, "steer_rise_time");
    assert!((rise - 0.4).abs() < 0.02, "10–90 % of a 0.5 s ramp: {rise}");
    assert!(
        ramp["warnings"][0].as_str().unwrap().contains("ISO 7401"),
        "{ramp}"
    );
}

/// The bundled UniTire step overshoots by about 0.1 %, a flat maximum late
/// in the response: taken as a GB/T 6323 peak it gave a TB of 0.42 s·deg
/// that the same run measured with its noise did not show. Below the least
/// overshoot (1 % by default) neither the simulation nor the measurement
/// has a peak; with `min_overshoot = 0` both find the same one.
#[test]
fn a_flat_maximum_below_the_least_overshoot_is_no_peak_simulated_or_measured() {
    let dir = tempfile::tempdir().unwrap();
    let text = bundled_scenario("step_gbt6323_unitire.toml");
    let simulate = |name: &str, extra: &str| {
        let sc = dir.path().join(format!("{name}.toml"));
        fs::write(&sc, format!("{text}\n{extra}")).unwrap();
        let out = dir.path().join(name);
        let said = crate::scenarios::simulate_to(&sc, &out);
        (out, said)
    };
    let measure = |history: &Path, extra: &[&str]| -> serde_json::Value {
        let mut args = vec!["metrics", history.to_str().unwrap(), "--json"];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let (default, said) = simulate("default", "");
    let m = read_json(&default.join("metrics.json"));
    assert!(
        m["yaw_rate_peak_time"].is_null() && m["tb"].is_null(),
        "{m}"
    );
    assert_eq!(f(&m, "yaw_rate_peak_threshold"), 1.0);
    assert!(
        said.contains("no overshoot: no yaw-rate maximum stands more than 1 % above"),
        "{said}"
    );
    let measured = measure(&default.join("history.csv"), &[]);
    assert!(measured["yaw_rate_peak_time"].is_null(), "{measured}");
    // Any maximum: the simulation's flat peak, found again in its rows.
    let (any, _) = simulate("any", "[metrics]\nmin_overshoot = 0\n");
    let m = read_json(&any.join("metrics.json"));
    let overshoot = f(&m, "yaw_rate_overshoot");
    assert!(overshoot > 0.05 && overshoot < 0.5, "{m}");
    let rows = measure(
        &any.join("history.csv"),
        &["--filter-hz", "0", "--min-overshoot", "0"],
    );
    let (a, b) = (f(&m, "yaw_rate_peak_time"), f(&rows, "yaw_rate_peak_time"));
    assert!(
        (a - b).abs() < 0.01,
        "peak at {a} s simulated, {b} s in its rows"
    );
    assert!(f(&m, "tb") > 0.1, "{m}");
}
