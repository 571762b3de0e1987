//! The analogues of real logs through the CLI, as a user generates them:
//! `handling synth --programme sedan-winding | slow-oval-no-beta |
//! slow-oval-estimated-beta | racing-rear-steer`. What the files must show
//! before any diagnosis: their channels and rates, the standstills and the
//! offsets a logger shows on them, the steer held at 20 Hz and its
//! progressive ratio, an estimated sideslip's small scatter against its
//! large error, and the truth's values stated in the campaign.

use super::*;
use std::fs;

/// The columns of a run file: its header and its columns by name.
fn columns(path: &Path) -> (String, std::collections::HashMap<String, Vec<f64>>) {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let names: Vec<&str> = header.split(',').collect();
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    for l in lines {
        for (c, x) in cols.iter_mut().zip(l.split(',')) {
            c.push(x.parse().unwrap());
        }
    }
    let map = names.iter().map(|n| n.to_string()).zip(cols).collect();
    (header, map)
}

fn mean(v: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = v.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    s / n as f64
}

fn rms(v: impl Iterator<Item = f64>) -> f64 {
    mean(v.map(|x| x * x)).sqrt()
}

/// The sample-to-sample scatter of `v`: the RMS first difference over √2
/// (what white noise's standard deviation would be).
fn scatter(v: &[f64]) -> f64 {
    rms(v.windows(2).map(|w| w[1] - w[0])) / 2f64.sqrt()
}

/// The longest stretch of zero speed (s) starting after `after` s.
fn longest_standstill(t: &[f64], speed: &[f64], after: f64) -> f64 {
    let (mut best, mut start) = (0.0f64, None);
    for (i, (&ti, &u)) in t.iter().zip(speed).enumerate() {
        if ti < after {
            continue;
        }
        match (u == 0.0, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                best = best.max(t[i - 1] - t[s]);
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        best = best.max(t[t.len() - 1] - t[s]);
    }
    best
}

#[test]
fn the_sedan_analogue_logs_a_hand_driven_winding_track_with_a_loggers_offsets() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "sedan", &["--programme", "sedan-winding"]);
    // No rig data: the axles come from the runs.
    assert!(!c.join("tyre_rig.csv").exists());
    let toml = fs::read_to_string(c.join("vehicle.toml")).unwrap();
    for line in [
        "mass = 2300",
        "yaw_inertia = 4800",
        "a = 1.464",
        "b = 1.586",
        "cg_height = 0.56",
        "#   ay_offset = -0.6",
        "#   yaw_rate_offset = 0.005",
        "#   beta_offset = -0.01",
        "#   beta_measured_ahead = 0.5",
        "#   steering_ratio = 16",
        "#   steering_progression = 0.15",
        "#   steer_sensor_rate = 20",
    ] {
        assert!(toml.lines().any(|l| l == line), "{line} in\n{toml}");
    }
    let mut parked = (Vec::new(), Vec::new(), Vec::new());
    for run in ["winding_lap", "winding_stop", "winding_mirrored"] {
        let (header, col) = columns(&c.join("runs").join(format!("{run}.csv")));
        assert_eq!(header, "t,speed,steer,yaw_rate,ay,ax,beta");
        let (t, u) = (&col["t"], &col["speed"]);
        // 100 Hz, long runs, 0 to 19 m/s with the slow corners' 3–8 m/s.
        assert!((t[1] - t[0] - 0.01).abs() < 1e-9);
        assert!(t[t.len() - 1] >= 110.0, "{run}: {} s", t[t.len() - 1]);
        let top = u.iter().cloned().fold(0.0, f64::max);
        assert!((18.5..19.6).contains(&top), "{run}: top speed {top}");
        let slow = u.iter().filter(|&&v| (3.0..8.0).contains(&v)).count();
        assert!(slow >= 1000, "{run}: {slow} samples at 3–8 m/s");
        // Parked at the start (5 or 10 s).
        assert!(longest_standstill(t, u, 0.0) >= 4.5, "{run}");
        // Up to about 0.5 g, both ways, the accelerometer's offset taken out.
        let ay: Vec<f64> = col["ay"].iter().map(|a| a + 0.6).collect();
        let (lo, hi) = ay
            .iter()
            .fold((0.0f64, 0.0f64), |(l, h), &a| (l.min(a), h.max(a)));
        assert!(
            lo < -4.0 && hi > 4.0 && lo > -7.0 && hi < 7.0,
            "{run}: ay {lo}..{hi}"
        );
        for (i, &v) in u.iter().enumerate() {
            if v == 0.0 {
                parked.0.push(col["ay"][i]);
                parked.1.push(col["yaw_rate"][i]);
                parked.2.push(col["beta"][i]);
            }
        }
        if run == "winding_stop" {
            // A stop of 15 s in mid-run.
            let mid = longest_standstill(t, u, 20.0);
            assert!((13.0..16.0).contains(&mid), "{run}: stop of {mid} s");
        }
    }
    // Standing still, the response channels read their offsets (noise of
    // 0.06 m/s², 0.002 rad/s and 0.002 rad over > 2,000 samples).
    assert!(parked.0.len() > 2000, "{} parked samples", parked.0.len());
    let ay0 = mean(parked.0.iter().copied());
    let r0 = mean(parked.1.iter().copied());
    let beta0 = mean(parked.2.iter().copied());
    assert!((ay0 + 0.6).abs() < 0.01, "ay at rest {ay0}");
    assert!((r0 - 0.005).abs() < 3e-4, "yaw rate at rest {r0}");
    assert!((beta0 + 0.01).abs() < 3e-4, "sideslip at rest {beta0}");
}

#[test]
fn the_sedans_steer_is_held_at_20_hz_quantised_and_understates_the_tight_corners() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "sedan", &["--programme", "sedan-winding"]);
    let (_, col) = columns(&c.join("runs/winding_lap.csv"));
    let (t, steer, u, r) = (&col["t"], &col["steer"], &col["speed"], &col["yaw_rate"]);
    // The steer changes only when a new 20 Hz message arrives, in steps of
    // 0.1° of steering wheel over the fixed ratio 16.
    let quantum = 0.1f64.to_radians() / 16.0;
    let mut changes = 0;
    for i in 1..t.len() {
        let tick = (t[i] / 0.05).round() * 0.05;
        if steer[i] != steer[i - 1] {
            changes += 1;
            assert!((t[i] - tick).abs() < 1e-6, "steer changed at {} s", t[i]);
        }
        let q = steer[i] / quantum;
        assert!(
            (q - q.round()).abs() < 1e-6,
            "steer {} off the quantum",
            steer[i]
        );
    }
    assert!(changes > 1000, "{changes} changes");
    // Cornering steadily, the path curvature per logged steer, L·(r/u)/δ:
    // about 1 in the medium corners, 15 % more in the slow tight ones,
    // where 150–230° of steering wheel turn the road wheels through the
    // progressive ratio more than the fixed ratio logs.
    let l = 1.464 + 1.586;
    let (mut tight, mut medium) = (Vec::new(), Vec::new());
    for i in 50..t.len() - 50 {
        let steady = (steer[i + 50] - steer[i - 50]).abs() < 0.01 * steer[i].abs() + 0.002;
        if u[i] < 4.0 || !steady || steer[i].abs() < 0.03 {
            continue;
        }
        let gain = l * ((r[i] - 0.005) / u[i]) / steer[i];
        if steer[i].abs() > 0.15 && u[i] < 9.0 {
            tight.push(gain);
        } else if (0.05..0.13).contains(&steer[i].abs()) {
            medium.push(gain);
        }
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    assert!(tight.len() > 50 && medium.len() > 50);
    let (tight, medium) = (median(tight), median(medium));
    assert!(tight > 1.10, "tight-corner gain {tight}");
    assert!(tight - medium > 0.08, "tight {tight}, medium {medium}");
}

#[test]
fn the_slow_oval_variants_differ_only_in_their_sideslip() {
    let dir = tempfile::tempdir().unwrap();
    let run = "runs/slow_oval_pace100.csv";
    let plain = synth_campaign(dir.path(), "plain", &["--programme", "slow-oval"]);
    let none = synth_campaign(dir.path(), "none", &["--programme", "slow-oval-no-beta"]);
    let est = synth_campaign(
        dir.path(),
        "est",
        &["--programme", "slow-oval-estimated-beta"],
    );
    let (h_plain, plain) = columns(&plain.join(run));
    let (h_none, none) = columns(&none.join(run));
    let (h_est, est) = columns(&est.join(run));
    assert_eq!(h_plain, "t,speed,steer,yaw_rate,ax,bank,beta");
    assert_eq!(h_none, "t,speed,steer,yaw_rate,ax,bank");
    assert_eq!(h_est, h_plain);
    // The variants' runs are the slow oval's first 100 s.
    let last = |c: &std::collections::HashMap<String, Vec<f64>>| c["t"][c["t"].len() - 1];
    assert!((last(&plain) - 200.0).abs() < 1e-6 && (last(&none) - 100.0).abs() < 1e-6);
    // The same seed: the same truth and, on the first run, the same noise
    // on every other channel.
    for ch in ["speed", "steer", "yaw_rate", "ax", "bank"] {
        assert_eq!(none[ch], est[ch], "{ch}");
    }
    // The plain sideslip is the truth with white noise of 0.002 rad; the
    // estimated one scatters ten times less from sample to sample, yet
    // misses the truth by several mrad (its difference from the plain one
    // is that error and the plain noise together). Compared over the
    // first 95 s, where the two programmes drive the same legs.
    let n = 95 * 25;
    let (b_plain, b_est) = (&plain["beta"][..n], &est["beta"][..n]);
    let s_plain = scatter(b_plain);
    let s_est = scatter(b_est);
    assert!(
        (0.0017..0.0023).contains(&s_plain),
        "plain scatter {s_plain}"
    );
    assert!(s_est < 0.0005, "estimated scatter {s_est}");
    let apart = rms(b_est.iter().zip(b_plain).map(|(e, p)| e - p));
    let error = (apart * apart - 0.002f64.powi(2)).max(0.0).sqrt();
    assert!(error > 10.0 * s_est, "error {error}, scatter {s_est}");
    assert!((0.002..0.015).contains(&error), "error {error}");
    // Both campaigns state the slow oval's settings.
    for c in [&dir.path().join("none"), &dir.path().join("est")] {
        let toml = fs::read_to_string(c.join("vehicle.toml")).unwrap();
        assert!(toml.contains("[runs]\nsegment = 20"), "{toml}");
        assert!(!c.join("tyre_rig.csv").exists());
    }
}

#[test]
fn the_racing_analogue_is_logged_as_the_putnam_log_with_its_rear_steer_stated() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "racing",
        &["--programme", "racing-rear-steer", "--seed", "3"],
    );
    assert!(!c.join("tyre_rig.csv").exists());
    let toml = fs::read_to_string(c.join("vehicle.toml")).unwrap();
    for line in [
        "mass = 790",
        "yaw_inertia = 1000",
        "a = 1.248",
        "b = 1.733",
        "#   rear_roll_steer = 0.3",
        "#   beta_measured_ahead = 0.6",
        "[roll]",
        "gradient = 0.0018",
        "segment = 20",
        "step = 0.02",
    ] {
        assert!(toml.lines().any(|l| l == line), "{line} in\n{toml}");
    }
    for run in ["road_course_a", "road_course_b", "road_course_c"] {
        let (header, col) = columns(&c.join("runs").join(format!("{run}.csv")));
        assert_eq!(header, "t,speed,steer,yaw_rate,ax,beta");
        let (t, u, r) = (&col["t"], &col["speed"], &col["yaw_rate"]);
        assert!((t[1] - t[0] - 0.04).abs() < 1e-9);
        assert!((t[t.len() - 1] - 100.0).abs() < 1e-6);
        let (lo, hi) = u
            .iter()
            .fold((f64::MAX, 0.0f64), |(l, h), &v| (l.min(v), h.max(v)));
        assert!(
            (8.0..10.0).contains(&lo) && (31.0..33.0).contains(&hi),
            "{run}: {lo}..{hi}"
        );
        // The Putnam log's levels: |u·r| up to about 5.5 m/s², ax within
        // −2.7 and 1.9 m/s² plus noise.
        let ay = u
            .iter()
            .zip(r)
            .map(|(u, r)| (u * r).abs())
            .fold(0.0, f64::max);
        assert!((4.5..7.0).contains(&ay), "{run}: |u r| up to {ay}");
        let ax = &col["ax"];
        assert!(ax.iter().all(|a| (-3.0..2.3).contains(a)), "{run}");
        // Left and right corners.
        assert!(r.iter().any(|&x| x > 0.2) && r.iter().any(|&x| x < -0.2));
    }
}

#[test]
fn an_analogue_without_a_bank_channel_refuses_the_bank_profile() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sedan");
    let o = run(&[
        "synth",
        "--programme",
        "sedan-winding",
        "--effects",
        "bank_profile",
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains("bank_profile") && e.contains("sedan-winding"),
        "{e}"
    );
}
