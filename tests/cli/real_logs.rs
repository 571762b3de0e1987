//! Real logs as loggers write them: standstills, crawling and glitches, from files through the CLI.

use super::*;

/// Deterministic measurement noise (sum of uniforms: near Gaussian, unit
/// deviation), so the files are the same on every machine.
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn gauss(&mut self) -> f64 {
        (0..12).map(|_| self.uniform()).sum::<f64>() - 6.0
    }
}

/// One logged sample: t, speed, steer, yaw rate, ay.
#[derive(Clone, Copy)]
struct Row {
    t: f64,
    speed: f64,
    steer: f64,
    yaw_rate: f64,
    ay: f64,
}

/// A log at `rate` Hz: speed and steer as functions of time; the yaw rate
/// follows the steady-state gain `u/(L + K·u²)` (L = 2.78 m, K = 0.0025
/// s²/m) with a 0.15 s lag; ay = u·r; white noise of 0.002 rad/s and
/// 0.05 m/s² on the responses.
fn log(
    rate: f64,
    seconds: f64,
    seed: u64,
    speed: impl Fn(f64) -> f64,
    steer: impl Fn(f64) -> f64,
) -> Vec<Row> {
    let mut noise = Noise(seed);
    let n = (seconds * rate).round() as usize;
    let dt = 1.0 / rate;
    let mut r = 0.0;
    (0..=n)
        .map(|i| {
            let t = i as f64 * dt;
            let (u, d) = (speed(t), steer(t));
            let target = u * d / (2.78 + 0.0025 * u * u);
            r += (target - r) * (1.0 - (-dt / 0.15f64).exp());
            let yaw_rate = r + 0.002 * noise.gauss();
            Row {
                t,
                speed: u,
                steer: d,
                yaw_rate,
                ay: u * r + 0.05 * noise.gauss(),
            }
        })
        .collect()
}

/// The log as a logger writes it: its own column order, a `bank` column
/// (a flat road), six decimals.
fn csv(rows: &[Row]) -> String {
    let mut s = String::from("t,steer,speed,ay,bank,yaw_rate\n");
    for r in rows {
        s += &format!(
            "{:.3},{:.6},{:.6},{:.6},0.000000,{:.6}\n",
            r.t, r.steer, r.speed, r.ay, r.yaw_rate
        );
    }
    s
}

/// A 0.02 rad step at `at` s.
fn step(at: f64) -> impl Fn(f64) -> f64 {
    move |t| if t >= at { 0.02 } else { 0.0 }
}

/// A campaign folder: linear tyres given, one candidate (the point is the
/// input handling, not the search).
fn campaign(runs: &[(&str, String)]) -> tempfile::TempDir {
    let v = format!(
        "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
    );
    let dir = scratch(&[
        ("vehicle.toml", &v),
        (
            "tyre.toml",
            "model = \"linear\"\ncornering_stiffness = 60000.0\n",
        ),
    ]);
    fs::create_dir(dir.path().join("runs")).unwrap();
    for (name, text) in runs {
        fs::write(dir.path().join("runs").join(name), text).unwrap();
    }
    dir
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap()
}

/// The base model's yaw-rate gap of the replayed run whose name ends with
/// `suffix`.
fn yaw_gap<'a>(d: &'a serde_json::Value, suffix: &str) -> &'a serde_json::Value {
    let r = d["gap"]["runs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["run"].as_str().unwrap().ends_with(suffix))
        .unwrap_or_else(|| panic!("no run {suffix} in {}", d["runs"]));
    &r["channels"][0]
}

#[test]
fn a_140_s_standstill_is_excluded_and_the_pieces_either_side_replayed() {
    // 10 s of driving with a step, braking to a stop, 140 s parked on the
    // banking with the wheel turned (speed 0, yaw-rate noise), pulling away,
    // 10 s of driving with a step; at 50 Hz. A second, clean run.
    let speed = |t: f64| {
        if t < 10.0 {
            20.0
        } else if t < 12.0 {
            20.0 * (12.0 - t) / 2.0
        } else if t < 152.0 {
            0.0
        } else if t < 154.0 {
            20.0 * (t - 152.0) / 2.0
        } else {
            20.0
        }
    };
    let steer = |t: f64| {
        if (12.0..152.0).contains(&t) {
            0.3
        } else if (3.0..10.0).contains(&t) || t >= 157.0 {
            0.02
        } else {
            0.0
        }
    };
    let parked = log(50.0, 164.0, 1, speed, steer);
    let clean = log(50.0, 10.0, 2, |_| 20.0, step(3.0));
    let dir = campaign(&[("a_parked.csv", csv(&parked)), ("b.csv", csv(&clean))]);
    let (stdout, d) = diagnose(dir.path());
    let c = &d["cleaning"];
    // One slow span from braking below 5 m/s to pulling away past it.
    let slow = c["slow"].as_array().unwrap();
    assert_eq!(slow.len(), 1, "{slow:?}");
    assert_eq!(slow[0]["kind"], "standstill");
    assert!(slow[0]["run"].as_str().unwrap().ends_with("a_parked.csv"));
    assert!((f(&slow[0]["t_start"]) - 11.52).abs() < 0.03, "{}", slow[0]);
    assert!((f(&slow[0]["t_end"]) - 152.48).abs() < 0.03, "{}", slow[0]);
    let excluded = c["samples_slow"].as_u64().unwrap();
    assert_eq!(excluded, slow[0]["samples"].as_u64().unwrap());
    assert!((excluded as i64 - 7048).abs() <= 2, "{excluded}");
    assert_eq!(
        c["samples_read"].as_u64().unwrap(),
        c["samples_kept"].as_u64().unwrap()
            + excluded
            + c["samples_in_dropped_pieces"].as_u64().unwrap()
    );
    // Two pieces of the parked run and the clean run are replayed.
    let runs: Vec<&str> = d["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_str().unwrap())
        .collect();
    assert_eq!(runs.len(), 3, "{runs:?}");
    assert!(runs[0].ends_with("a_parked.csv#1") && runs[1].ends_with("a_parked.csv#2"));
    assert_eq!(c["pieces"].as_array().unwrap().len(), 3);
    assert!(
        stdout.contains("a_parked.csv: split into 2 pieces"),
        "{stdout}"
    );
    assert!(
        stdout.contains("(1 standstill span and 0 crawl spans)"),
        "{stdout}"
    );
    assert!(stdout.contains("standstill 11.52–152.48 s"), "{stdout}");
    // No glitch in noisy but sound data.
    assert!(
        c["glitches"].as_array().unwrap().is_empty(),
        "{}",
        c["glitches"]
    );
    // The same manoeuvre gives about the same gap with or without the stop:
    // the standstill does not dominate.
    let rms: Vec<f64> = ["a_parked.csv#1", "a_parked.csv#2", "b.csv"]
        .iter()
        .map(|r| f(&yaw_gap(&d, r)["rms"]))
        .collect();
    let (lo, hi) = (
        rms.iter().copied().fold(f64::MAX, f64::min),
        rms.iter().copied().fold(0.0, f64::max),
    );
    assert!(hi < 2.0 * lo, "{rms:?}");
}

/// Runs `metrics --json` on a file; returns the metrics and stderr.
fn metrics(path: &Path, extra: &[&str]) -> (serde_json::Value, String) {
    let mut args = vec!["metrics", path.to_str().unwrap(), "--json"];
    args.extend(extra);
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    v.as_object_mut().unwrap().remove("scenario");
    assert!(v["yaw_rate_gain"].is_number(), "{v}");
    (v, stderr(&o))
}

#[test]
fn a_crawl_at_2_m_s_is_left_out_of_metrics_and_replay() {
    // 20 s turning out of the paddock at 2 m/s, 4 s accelerating to 20 m/s,
    // then a step steer at 27 s; at 100 Hz.
    let speed = |t: f64| {
        if t < 20.0 {
            2.0
        } else if t < 24.0 {
            2.0 + 18.0 * (t - 20.0) / 4.0
        } else {
            20.0
        }
    };
    let steer = |t: f64| {
        if t < 20.0 {
            0.15
        } else if t >= 27.0 {
            0.02
        } else {
            0.0
        }
    };
    let rows = log(100.0, 34.0, 3, speed, steer);
    // The same samples from where the car passes 5 m/s.
    let from = rows.iter().position(|r| r.speed >= 5.0).unwrap();
    let dir = scratch(&[
        ("crawl.csv", &csv(&rows)),
        ("moving.csv", &csv(&rows[from..])),
    ]);
    let (mut m_crawl, err) = metrics(&dir.path().join("crawl.csv"), &[]);
    let (mut m_moving, _) = metrics(&dir.path().join("moving.csv"), &[]);
    // The same metrics; the cleaning reports and piece names differ.
    assert_eq!(m_crawl["cleaning"]["samples_slow"], 2067);
    assert_eq!(m_moving["cleaning"]["samples_slow"], 0);
    for m in [&mut m_crawl, &mut m_moving] {
        let o = m.as_object_mut().unwrap();
        o.remove("cleaning");
        o.remove("piece");
    }
    assert_eq!(m_crawl, m_moving);
    assert!(
        err.contains("(0 standstill spans and 1 crawl span)"),
        "{err}"
    );
    assert!(err.contains("crawl 0.00–20.66 s"), "{err}");
    // The crawl kept (min speed 1 m/s): a different answer.
    let (m_all, err) = metrics(&dir.path().join("crawl.csv"), &["--min-speed", "1"]);
    assert_ne!(m_all, m_moving);
    assert!(err.contains("0 below 1 m/s excluded"), "{err}");

    // A replay scenario replays the moving piece only.
    let replay = |extra: &str| {
        let sc = format!(
            "{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"crawl.csv\"\n{extra}"
        );
        fs::write(dir.path().join("replay.toml"), sc).unwrap();
        fs::write(dir.path().join("tyre.toml"), GIM).unwrap();
        let out = dir.path().join(format!("out{}", extra.len()));
        let o = run(&[
            "simulate",
            dir.path().join("replay.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let hist = fs::read_to_string(out.join("history.csv")).unwrap();
        let t0: f64 = hist
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        (t0, String::from_utf8_lossy(&o.stdout).into_owned())
    };
    let (t0, stdout) = replay("");
    assert!((t0 - rows[from].t).abs() < 1e-9, "{t0}");
    assert!(stdout.contains("crawl 0.00–20.66 s"), "{stdout}");
    let (t0, _) = replay("min_speed = 1.0\n");
    assert_eq!(t0, 0.0);
}

/// A time to the microsecond (JSON numbers do not always parse back to
/// the last bit).
fn micro(t: f64) -> f64 {
    (t * 1e6).round() / 1e6
}

/// The glitches a diagnosis listed, as (run file, t, channel, kind, value).
fn glitches(d: &serde_json::Value) -> Vec<(String, f64, String, String, f64)> {
    d["cleaning"]["glitches"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| {
            let run = g["run"].as_str().unwrap();
            (
                run.rsplit('/').next().unwrap().to_string(),
                micro(f(&g["t"])),
                g["channel"].as_str().unwrap().to_string(),
                g["kind"].as_str().unwrap().to_string(),
                f(&g["value"]),
            )
        })
        .collect()
}

#[test]
fn zero_reads_spikes_and_held_values_are_listed_and_left_out() {
    // A ramp steer at 20 m/s whose last yaw-rate sample reads 0; a step
    // run with an isolated ay spike and a steer spike; a step run whose yaw
    // rate sticks for 8 samples. 50 Hz.
    let mut ramp = log(50.0, 8.0, 4, |_| 20.0, |t| 0.01 * (t - 2.0).max(0.0));
    let last = ramp.len() - 1;
    let yaw_end = ramp[last].yaw_rate;
    ramp[last].yaw_rate = 0.0;
    let mut spiky = log(50.0, 8.0, 5, |_| 20.0, step(2.0));
    spiky[250].ay += 8.0; // t = 5.00
    spiky[150].steer = 0.2; // t = 3.00
    let mut held = log(50.0, 8.0, 6, |_| 20.0, step(2.0));
    for i in 301..309 {
        held[i].yaw_rate = held[300].yaw_rate; // 6.00–6.16 s
    }
    let fmt = |v: f64| format!("{v:.6}").parse::<f64>().unwrap();
    let dir = campaign(&[
        ("ramp.csv", csv(&ramp)),
        ("spiky.csv", csv(&spiky)),
        ("held.csv", csv(&held)),
    ]);
    let (stdout, d) = diagnose(dir.path());
    let mut found = glitches(&d);
    found.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    assert_eq!(
        found,
        vec![
            (
                "held.csv".into(),
                6.0,
                "yaw_rate".into(),
                "stuck".into(),
                fmt(held[300].yaw_rate)
            ),
            (
                "ramp.csv".into(),
                8.0,
                "yaw_rate".into(),
                "zero_read".into(),
                0.0
            ),
            ("spiky.csv".into(), 3.0, "steer".into(), "spike".into(), 0.2),
            (
                "spiky.csv".into(),
                5.0,
                "ay".into(),
                "spike".into(),
                fmt(spiky[250].ay)
            ),
        ]
    );
    let c = &d["cleaning"];
    assert_eq!(
        c["counts"],
        serde_json::json!({"zero_read": 1, "spike": 2, "stuck": 1, "time_gap": 0})
    );
    assert_eq!(c["samples_repaired"], 1);
    assert_eq!(c["samples_masked"], 1 + 1 + 9);
    assert!(
        stdout.contains("glitches: 1 zero read, 2 spikes, 1 stuck value, 0 time gaps (1 input sample repaired, 11 response samples masked)"),
        "{stdout}"
    );
    // Counts of one in the singular, the glitch's own line too.
    assert!(stdout.contains("(1 sample, "), "{stdout}");
    assert!(!stdout.contains("sample(s)"), "{stdout}");
    assert!(stdout.contains("zero_read at 8.000 s in"), "{stdout}");
    // Left out of the scores: the base model's residual never reaches the
    // zeroed end of the ramp or the ay spike; the masked samples are not
    // counted.
    let ramp_gap = yaw_gap(&d, "ramp.csv");
    assert!(
        f(&ramp_gap["max_abs"]) < 0.5 * yaw_end.abs(),
        "{ramp_gap} vs {yaw_end}"
    );
    let spiky_run = d["gap"]["runs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["run"].as_str().unwrap().ends_with("spiky.csv"))
        .unwrap();
    let ay = &spiky_run["channels"][1];
    assert_eq!(ay["channel"], "ay");
    assert!(f(&ay["max_abs"]) < 4.0, "{ay}");
    let counted: u64 = yaw_gap(&d, "held.csv")["windows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["samples"].as_u64().unwrap())
        .sum();
    // Less the 9 masked and, the log having no sideslip channel, the 25
    // samples (0.5 s at 50 Hz) of the replay's start that are not scored.
    assert_eq!(counted, held.len() as u64 - 9 - 25);
    // The steer was repaired, not the run split or refused: three runs.
    assert_eq!(d["runs"].as_array().unwrap().len(), 3);
}

/// Corrupts a synth run file as a logger would: yaw rate read as 0 at 40 %
/// of the run, an ay spike at 55 %, beta held for 6 samples from 70 %, a
/// steer spike at 85 %. Returns the (t, channel, kind) injected.
fn corrupt(path: &Path) -> Vec<(f64, String, String)> {
    let text = fs::read_to_string(path).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let header: Vec<String> = lines[0].split(',').map(String::from).collect();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let n = lines.len() - 1;
    let cell = |lines: &Vec<String>, i: usize, c: usize| -> f64 {
        lines[i].split(',').nth(c).unwrap().parse().unwrap()
    };
    let set = |lines: &mut Vec<String>, i: usize, c: usize, v: f64| {
        let mut cells: Vec<String> = lines[i].split(',').map(String::from).collect();
        cells[c] = format!("{v}");
        lines[i] = cells.join(",");
    };
    let t = |lines: &Vec<String>, i: usize| micro(cell(lines, i, col("t")));
    let mut out = Vec::new();
    // The zero read where the yaw rate is far from 0: the largest |r| in
    // the middle fifth.
    let (yr, ay, beta, steer) = (col("yaw_rate"), col("ay"), col("beta"), col("steer"));
    let i = (n * 2 / 5..n * 3 / 5)
        .max_by(|&a, &b| {
            cell(&lines, a, yr)
                .abs()
                .total_cmp(&cell(&lines, b, yr).abs())
        })
        .unwrap();
    set(&mut lines, i, yr, 0.0);
    out.push((
        t(&lines, i),
        "yaw_rate".to_string(),
        "zero_read".to_string(),
    ));
    let i = n * 11 / 20;
    let v = cell(&lines, i, ay) + 3.0;
    set(&mut lines, i, ay, v);
    out.push((t(&lines, i), "ay".into(), "spike".into()));
    let i = n * 7 / 10;
    let v = cell(&lines, i, beta);
    for k in i + 1..i + 6 {
        set(&mut lines, k, beta, v);
    }
    out.push((t(&lines, i), "beta".into(), "stuck".into()));
    let i = n * 17 / 20;
    let v = cell(&lines, i, steer) + 0.05;
    set(&mut lines, i, steer, v);
    out.push((t(&lines, i), "steer".into(), "spike".into()));
    fs::write(path, lines.join("\n") + "\n").unwrap();
    out
}

fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to.join("runs")).unwrap();
    for e in fs::read_dir(from)
        .unwrap()
        .chain(fs::read_dir(from.join("runs")).unwrap())
    {
        let p = e.unwrap().path();
        if p.is_file() {
            let rel = p.strip_prefix(from).unwrap();
            fs::copy(&p, to.join(rel)).unwrap();
        }
    }
}

#[test]
fn glitched_copies_of_synthetic_campaigns_give_the_clean_verdict() {
    let dir = tempfile::tempdir().unwrap();
    for (effects, seed) in [("sensor_delay", "3"), ("none", "4")] {
        let name = format!("{effects}_clean");
        let clean = synth_campaign(dir.path(), &name, &["--effects", effects, "--seed", seed]);
        // Three candidates keep the test short.
        let mut v = fs::read_to_string(clean.join("vehicle.toml")).unwrap();
        v += "effects = [\"sensor_delay\", \"relaxation_length\", \"cornering_stiffness\"]\n";
        fs::write(clean.join("vehicle.toml"), v).unwrap();
        let glitched = dir.path().join(format!("{effects}_glitched"));
        copy_dir(&clean, &glitched);
        let mut injected = Vec::new();
        let mut files: Vec<PathBuf> = fs::read_dir(glitched.join("runs"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        files.sort();
        for p in &files {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            injected.extend(
                corrupt(p)
                    .into_iter()
                    .map(|(t, c, k)| (name.clone(), t, c, k)),
            );
        }
        let (_, d_clean) = diagnose(&clean);
        let (_, d_glitched) = diagnose(&glitched);
        assert!(glitches(&d_clean).is_empty(), "{:?}", glitches(&d_clean));
        let mut found: Vec<(String, f64, String, String)> = glitches(&d_glitched)
            .into_iter()
            .map(|(r, t, c, k, _)| (r, t, c, k))
            .collect();
        let key = |a: &(String, f64, String, String), b: &(String, f64, String, String)| {
            a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
        };
        found.sort_by(key);
        injected.sort_by(key);
        assert_eq!(found, injected, "{effects}");
        assert_eq!(
            d_glitched["verdict"]["effects"], d_clean["verdict"]["effects"],
            "{effects}"
        );
        let j = |d: &serde_json::Value| f(&d["gap"]["heldout_error"]);
        assert!(
            (j(&d_glitched) - j(&d_clean)).abs() < 0.05 * j(&d_clean),
            "{effects}: {} vs {}",
            j(&d_glitched),
            j(&d_clean)
        );
        if effects == "sensor_delay" {
            let delay = |d: &serde_json::Value| f(&d["verdict"]["parameters"][0]["value"]);
            assert!((delay(&d_glitched) - delay(&d_clean)).abs() < 0.002);
        } else {
            assert_eq!(d_clean["verdict"]["effects"], serde_json::json!([]));
        }
    }
}

#[test]
fn responses_read_as_exactly_zero_while_parked_flag_no_glitch_in_the_driving() {
    // 6 s of driving, braking, 30 s parked with the yaw rate and ay read as
    // exactly 0 (a logger that gates its IMU at a standstill), pulling
    // away, 6 s of driving; at 100 Hz. The parked zeros once made the
    // spread of the sample-to-sample differences 0, and hundreds of
    // ordinary noise samples of the driving were masked as spikes.
    let speed = |t: f64| {
        if t < 6.0 {
            20.0
        } else if t < 8.0 {
            20.0 * (8.0 - t) / 2.0
        } else if t < 38.0 {
            0.0
        } else if t < 40.0 {
            20.0 * (t - 38.0) / 2.0
        } else {
            20.0
        }
    };
    let mut gated = log(100.0, 46.0, 3, speed, step(2.0));
    for r in &mut gated {
        if r.speed == 0.0 {
            (r.yaw_rate, r.ay) = (0.0, 0.0);
        }
    }
    let clean = log(100.0, 10.0, 4, |_| 20.0, step(3.0));
    let dir = campaign(&[("a_gated.csv", csv(&gated)), ("b.csv", csv(&clean))]);
    let (stdout, d) = diagnose(dir.path());
    let c = &d["cleaning"];
    assert!(
        c["glitches"].as_array().unwrap().is_empty(),
        "{}",
        c["glitches"]
    );
    assert!(stdout.contains("0 response samples masked"), "{stdout}");
    assert_eq!(c["slow"].as_array().unwrap().len(), 1, "{}", c["slow"]);
}

#[test]
fn a_sideslip_logged_at_10_hz_in_a_100_hz_log_is_interpolated_between_updates() {
    // A GPS sideslip updated every tenth sample and held between: its steps
    // would be residuals no model closes.
    let rows = log(100.0, 12.0, 5, |_| 20.0, step(3.0));
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for (i, r) in rows.iter().enumerate() {
        // The sideslip of the yaw response (a steady 0.3·r·l/u), held.
        let held = &rows[i - i % 10];
        let beta = 0.3 * held.yaw_rate * 2.78 / held.speed;
        s += &format!(
            "{:.3},{:.6},{:.6},{:.6},{:.6},{:.6}\n",
            r.t, r.speed, r.steer, r.yaw_rate, r.ay, beta
        );
    }
    let clean = log(100.0, 10.0, 6, |_| 20.0, step(3.0));
    let dir = campaign(&[("a_gps.csv", s), ("b.csv", csv(&clean))]);
    let (stdout, d) = diagnose(dir.path());
    let held = d["cleaning"]["held"].as_array().unwrap();
    assert_eq!(held.len(), 1, "{held:?}");
    assert_eq!(held[0]["channel"], "beta");
    assert_eq!(held[0]["every"], 10);
    assert!((held[0]["log_rate"].as_f64().unwrap() - 100.0).abs() < 1e-9);
    // 1201 samples, 121 updates (the last at 12 s, held for none): 120
    // holds of 9 samples interpolated.
    assert_eq!(held[0]["samples"], 120 * 9);
    assert_eq!(d["cleaning"]["samples_interpolated"], 120 * 9);
    assert!(
        stdout.contains("held: beta in ")
            && stdout
                .contains("updates every 10 samples of the 100 Hz log (every 0.1 s, 10 Hz): 1080 held samples interpolated"),
        "{stdout}"
    );
    // Nothing else taken for a glitch.
    assert!(
        d["cleaning"]["glitches"].as_array().unwrap().is_empty(),
        "{}",
        d["cleaning"]["glitches"]
    );
}
