//! No NaN or infinity in a report: the diagnosis (the whole candidate
//! library) of campaigns of degenerate runs — a constant steer (nothing to
//! fit: singular problems), pieces at zero speed between short drives, a
//! lateral-acceleration channel that is one sample away from empty (every
//! other sample held at zero), a dead `ay` sensor (zeros throughout:
//! refused, naming the run and the channel) — and the `simulate` replay and `metrics` of
//! such runs either refuse with a message naming the run, or report only
//! finite numbers (checked on the values before JSON would turn a NaN into
//! `null`).

use crate::finite::non_finite;
use crate::{fs, Path};
use handling::metrics::MetricSettings;
use std::fmt::Write;

/// A run of `n` samples at 25 Hz from per-sample (speed, steer, ay) at `t`.
fn run(n: usize, f: impl Fn(usize, f64) -> (f64, f64, f64)) -> String {
    let mut s = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in 0..n {
        let t = i as f64 / 25.0;
        let (u, d, ay) = f(i, t);
        let r = u * d / 2.78;
        writeln!(s, "{t:.2},{u},{d},{r},{ay},{}", -0.1 * d).unwrap();
    }
    s
}

/// The degenerate runs, by name: two files each.
fn degenerate() -> Vec<(&'static str, [String; 2])> {
    let constant = |n| run(n, |_, _| (20.0, 0.02, 20.0 * 20.0 * 0.02 / 2.78));
    let stop_go = |n| {
        run(n, |_, t| {
            let moving = (t % 12.0) < 3.0;
            let u = if moving { 15.0 } else { 0.0 };
            let d = 0.03 * (2.0 * t).sin();
            (u, d, u * u * d / 2.78)
        })
    };
    let empty_ay = |n| {
        run(n, |i, t| {
            let d = 0.03 * (1.5 * t).sin();
            (18.0, d, if i == 7 { 1.0 } else { 0.0 })
        })
    };
    // A dead sensor: `ay` logged as zeros throughout.
    let dead_ay = |n| {
        run(n, |_, t| {
            let d = 0.03 * (1.5 * t).sin();
            (18.0, d, 0.0)
        })
    };
    vec![
        ("constant_steer", [constant(300), constant(250)]),
        ("dead_ay", [dead_ay(300), dead_ay(260)]),
        ("zero_speed_pieces", [stop_go(900), stop_go(700)]),
        ("single_sample_ay", [empty_ay(300), empty_ay(260)]),
    ]
}

fn campaign(dir: &Path, runs: &[String; 2]) -> std::path::PathBuf {
    fs::write(dir.join("a.csv"), &runs[0]).unwrap();
    fs::write(dir.join("b.csv"), &runs[1]).unwrap();
    let tyre = fs::read_to_string(crate::root().join("tyres/linear.toml")).unwrap();
    fs::write(dir.join("tyre.toml"), tyre).unwrap();
    let text = "[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\n\
        track_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n\n[tyres]\nfile = \"tyre.toml\"\n\n\
        [runs]\nfiles = [\"a.csv\", \"b.csv\"]\nsegment = 4.0\n\n\
        [diagnose]\nseed = 1\nparticles = 8\niterations = 4\nmax_effects = 2\n";
    let p = dir.join("campaign.toml");
    fs::write(&p, text).unwrap();
    p
}

#[test]
fn degenerate_runs_give_no_nan_in_a_diagnosis() {
    for (name, runs) in degenerate() {
        let dir = tempfile::tempdir().unwrap();
        let c = campaign(dir.path(), &runs);
        let t0 = std::time::Instant::now();
        match handling::jobs::diagnose::run(&c, Some(&dir.path().join("out"))) {
            Ok(r) => {
                assert_ne!(name, "dead_ay", "a dead channel diagnosed");
                let bad = non_finite(&r.diagnosis);
                assert!(bad.is_empty(), "{name}: {bad:?}");
                // Nor in the sentences: a ratio to a zero noise floor.
                let text = serde_json::to_string(&r.diagnosis).unwrap();
                if let Some(i) = text.find("NaN") {
                    panic!(
                        "{name}: NaN in the report's text: …{}…",
                        &text[i.saturating_sub(300)..(i + 60).min(text.len())]
                    );
                }
                r.write().unwrap();
            }
            Err(e) => {
                let e = e.to_string();
                if name == "dead_ay" {
                    assert!(
                        e.contains("a.csv") && e.contains("channel `ay` holds one value (0)"),
                        "{e}"
                    );
                }
                assert!(
                    e.contains("a.csv") || e.contains("b.csv") || e.contains("campaign.toml"),
                    "{name}: {e}"
                );
            }
        }
        eprintln!("{name}: diagnosed in {:.1} s", t0.elapsed().as_secs_f64());
    }
}

#[test]
fn degenerate_runs_give_no_nan_in_metrics() {
    for (name, runs) in degenerate() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("run.csv");
        fs::write(&p, &runs[0]).unwrap();
        match handling::jobs::metrics::run(&p, &MetricSettings::default(), 5.0) {
            Ok(r) => {
                let bad = non_finite(&r);
                assert!(bad.is_empty(), "{name}: {bad:?}");
                eprintln!("{name}: metrics measured");
            }
            Err(e) => {
                assert!(e.to_string().contains("run.csv"), "{name}: {e}");
                eprintln!("{name}: {e}");
            }
        }
    }
}
