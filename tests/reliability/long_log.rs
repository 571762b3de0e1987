//! Long logs: a 10⁶-row run (11 h at 25 Hz, `FORMATS.md`) with a step
//! steer, standstills, stop-and-go traffic (a piece every ten samples),
//! time gaps, and a logger glitch every thousand samples, read, cleaned
//! as `diagnose` cleans it, and measured as `metrics` measures it. Each size runs in a child process (this test
//! binary, the ignored test [`child`]) that reports its peak resident
//! memory (`VmHWM`) and the CPU time of each stage; memory and time must
//! grow linearly: 10× the rows may cost at most 20× the memory and 25× the
//! time (quadratic work would cost 100×), and at most a few seconds per
//! 10⁵ rows.

use crate::fs;
use crate::long_log_rows::long_log_rows;
use handling::measured::clean::{clean_run, CleanSettings, CleaningReport};
use handling::metrics::MetricSettings;
use std::io::{BufWriter, Write};

/// Writes the long log of `n` rows ([`long_log_rows`]) as a run file.
pub fn write_log(path: &std::path::Path, n: usize) {
    let mut w = BufWriter::new(fs::File::create(path).unwrap());
    writeln!(w, "t,speed,steer,yaw_rate,ay,beta").unwrap();
    long_log_rows(n, |[t, speed, steer, r, ay, beta]| {
        writeln!(w, "{t:.2},{speed:.4},{steer:.6},{r:.6},{ay:.5},{beta:.6}").unwrap();
    });
}

/// CPU time of this process (all threads, user and system), s: the wall
/// time of a busy machine says little.
fn cpu_seconds() -> f64 {
    let s = fs::read_to_string("/proc/self/stat").unwrap();
    let f: Vec<f64> = s
        .rsplit(')')
        .next()
        .unwrap()
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    // utime and stime, fields 14 and 15 (after the state, field 3, which
    // does not parse), in clock ticks of 1/100 s.
    (f[10] + f[11]) / 100.0
}

/// Peak resident memory of this process, kB.
fn peak_kb() -> u64 {
    let s = fs::read_to_string("/proc/self/status").unwrap();
    s.lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap()
}

#[test]
#[ignore = "run by long_logs_cost_linear_memory_and_time in a child process"]
fn child() {
    let n: usize = std::env::var("HANDLING_LONG_LOG_ROWS")
        .unwrap()
        .parse()
        .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("long.csv");
    write_log(&path, n);
    let base = peak_kb();
    let t0 = cpu_seconds();
    let run = handling::io::read_run(&path).unwrap();
    let read = cpu_seconds() - t0;
    let t0 = cpu_seconds();
    let mut report = CleaningReport::new(5.0);
    let pieces = clean_run(run.clone(), &CleanSettings::diagnosis(5.0), &mut report);
    let clean = cpu_seconds() - t0;
    assert!(pieces.len() >= n / 45_000, "{} pieces", pieces.len());
    assert!(
        report.samples_masked >= n / 997 / 3,
        "{} masked",
        report.samples_masked
    );
    drop(pieces);
    let t0 = cpu_seconds();
    let m =
        handling::metrics::measured::measured_step_metrics(run, 5.0, &MetricSettings::default());
    let metrics = cpu_seconds() - t0;
    assert!(m.is_ok(), "{:?}", m.err());
    println!(
        "LONG-LOG rows {n} read {read:.3} clean {clean:.3} metrics {metrics:.3} base_kb {base} peak_kb {}",
        peak_kb()
    );
}

/// (rows, read s, clean s, metrics s, base kB, peak kB) of a child run.
fn measure(n: usize) -> [f64; 6] {
    let o = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "--ignored",
            "--exact",
            "long_log::child",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("HANDLING_LONG_LOG_ROWS", n.to_string())
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{out}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let line = out
        .lines()
        .find_map(|l| l.find("LONG-LOG").map(|i| &l[i..]))
        .unwrap_or_else(|| panic!("no report line in {out:?}"));
    eprintln!("{line}");
    let v: Vec<f64> = line
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    v.try_into().unwrap()
}

#[test]
fn long_logs_cost_linear_memory_and_time() {
    let small = measure(100_000);
    let large = measure(1_000_000);
    for (k, stage) in [(1, "read"), (2, "cleaning"), (3, "metrics")] {
        // A floor of 50 ms: the small run's time is noise on a busy machine.
        let ratio = large[k] / small[k].max(0.05);
        assert!(
            ratio < 20.0,
            "{stage}: {:.2} s for 10⁶ rows, {:.2} s for 10⁵",
            large[k],
            small[k]
        );
        assert!(large[k] < 40.0, "{stage}: {:.1} s for 10⁶ rows", large[k]);
    }
    // Memory the stages add above the process with the log written.
    let added = |m: &[f64; 6]| (m[5] - m[4]).max(0.0);
    let per_row = added(&large) * 1024.0 / 1e6;
    assert!(per_row < 1000.0, "{per_row:.0} bytes per row");
    assert!(
        added(&large) < 20.0 * added(&small).max(10_000.0),
        "{} kB for 10⁶ rows, {} kB for 10⁵",
        added(&large),
        added(&small)
    );
}
