//! What a fresh-eyes user still tripped on: a yaw rate that logs noise or
//! freezes after the step blamed on the steer's units; an overshoot below
//! what the run resolves written as a measured 0; a loaded radius past the
//! file's load range said to be evaluated at its end.

use super::*;

/// The bundled sedan step steer's history (1° at 1.0–1.1 s, to 6 s),
/// simulated once per test: its header and rows.
pub(super) struct Sedan {
    pub(super) header: Vec<String>,
    pub(super) rows: Vec<Vec<f64>>,
}

impl Sedan {
    pub(super) fn simulated(dir: &Path) -> Self {
        let text = fs::read_to_string(super::sedan_runs::sedan_history(dir)).unwrap();
        let mut lines = text.lines();
        let header = lines
            .next()
            .unwrap()
            .split(',')
            .map(str::to_string)
            .collect();
        let rows = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        Self { header, rows }
    }

    /// Writes its t, steer, speed, yaw rate and ay to `dir/name`, at
    /// 100 Hz, the steer and yaw rate of each row made by `change(t,
    /// steer, yaw_rate, row)`; returns the path.
    pub(super) fn measured(
        &self,
        dir: &Path,
        name: &str,
        change: &dyn Fn(f64, f64, f64, usize) -> (f64, f64),
    ) -> PathBuf {
        let at = |k: &str| self.header.iter().position(|h| h == k).unwrap();
        let (t, steer, speed, r, ay) =
            (at("t"), at("steer"), at("speed"), at("yaw_rate"), at("ay"));
        let mut text = String::from("t,steer,speed,yaw_rate,ay\n");
        for (i, row) in self.rows.iter().step_by(10).enumerate() {
            let (d, y) = change(row[t], row[steer], row[r], i);
            text += &format!("{},{d},{},{y},{}\n", row[t], row[speed], row[ay]);
        }
        let path = dir.join(name);
        fs::write(&path, text).unwrap();
        path
    }
}

/// A yaw rate logging only noise about zero (a channel not wired to the
/// gyro) read as "42× smaller than a neutral car's: is `steer` in
/// degrees?": now refused as not following the steer, with the shares of
/// samples turning with and against it; a steer in degrees, whose yaw rate
/// does follow it, is still asked about its units.
#[test]
fn a_yaw_rate_logging_noise_is_refused_as_not_following_the_steer_not_as_units() {
    let dir = tempfile::tempdir().unwrap();
    let sedan = Sedan::simulated(dir.path());
    // A deterministic scatter of ±0.003 rad/s about zero, both signs alike.
    let noise = |i: usize| 0.003 * (((i * 7919) % 13) as f64 - 6.0) / 6.0;
    let run_path = sedan.measured(dir.path(), "noise.csv", &|_, d, _, i| (d, noise(i)));
    let o = run(&["metrics", run_path.to_str().unwrap()]);
    assert!(!o.status.success(), "a noise-only yaw rate was measured");
    let e = stderr(&o);
    assert!(e.contains("the yaw rate does not follow the steer"), "{e}");
    assert!(e.contains("noise about zero, not a response"), "{e}");
    assert!(!e.contains("is `steer` in degrees"), "{e}");
    // The same run with its real yaw rate and the steer in degrees.
    let degrees = sedan.measured(dir.path(), "degrees.csv", &|_, d, r, _| (d.to_degrees(), r));
    let e = stderr(&run(&["metrics", degrees.to_str().unwrap()]));
    assert!(e.contains("is `steer` in degrees (57×)"), "{e}");
    assert!(!e.contains("does not follow the steer"), "{e}");
}

/// A yaw rate that freezes after the step (the sensor stops updating and
/// the logger repeats its last value to the end) is refused as frozen,
/// with the value it holds; the cleaning cannot flag a hold that reaches
/// the end of the record, so the refusal names it.
#[test]
fn a_yaw_rate_frozen_after_the_step_is_refused_as_frozen() {
    let dir = tempfile::tempdir().unwrap();
    let sedan = Sedan::simulated(dir.path());
    let run_path = sedan.measured(dir.path(), "frozen.csv", &|t, d, r, _| {
        (d, if t < 1.05 { r } else { 0.0012 })
    });
    let o = run(&["metrics", run_path.to_str().unwrap()]);
    assert!(!o.status.success(), "a frozen yaw rate was measured");
    let e = stderr(&o);
    assert!(
        e.contains("it holds one value, 0.00120 rad/s, on every one (a frozen sensor"),
        "{e}"
    );
    assert!(!e.contains("is `steer` in degrees"), "{e}");
}

/// A run whose yaw rate has no maximum above its steady state wrote
/// `"yaw_rate_overshoot": 0.0` where the terminal said "< 1 %": the file
/// now writes null, as it does the peak time, and a run with a peak
/// writes the number the terminal gives.
#[test]
fn an_overshoot_below_what_the_run_resolves_is_null_not_a_measured_zero() {
    let dir = tempfile::tempdir().unwrap();
    let sedan = Sedan::simulated(dir.path());
    // A first-order yaw rate (time constant 0.1 s): no maximum above its
    // steady state.
    let flat = sedan.measured(dir.path(), "flat.csv", &|t, d, _, _| {
        (d, 0.065 * (1.0 - (-(t - 1.05).max(0.0) / 0.1).exp()))
    });
    let (said, m) = table_and_json(&flat);
    assert!(m["yaw_rate_peak_time"].is_null(), "{said}");
    assert!(m["yaw_rate_overshoot"].is_null(), "{m}");
    assert!(overshoot_line(&said).contains("< "), "{said}");
    // A second-order response with a 16 % overshoot: a number, as said.
    let ringing = sedan.measured(dir.path(), "ringing.csv", &|t, d, _, _| {
        let s = (t - 1.05).max(0.0);
        let (z, w) = (0.5_f64, 12.0_f64);
        let wd = w * (1.0 - z * z).sqrt();
        let resp = 1.0 - (-z * w * s).exp() * ((wd * s).cos() + z * w / wd * (wd * s).sin());
        (d, 0.065 * resp)
    });
    let (said, m) = table_and_json(&ringing);
    let percent = m["yaw_rate_overshoot"]
        .as_f64()
        .unwrap_or_else(|| panic!("{m}"));
    assert!((10.0..20.0).contains(&percent), "{m}");
    let line = overshoot_line(&said);
    assert!(
        line.contains(&format!("{percent:.2}")),
        "{line} against {percent}"
    );
}

/// `metrics <run>`'s table and `metrics <run> --json`'s object.
fn table_and_json(run_path: &Path) -> (String, serde_json::Value) {
    let said = succeeds(&["metrics", run_path.to_str().unwrap()]);
    let json = succeeds(&["metrics", run_path.to_str().unwrap(), "--json"]);
    (said, serde_json::from_str(&json).unwrap())
}

/// The table's overshoot line.
fn overshoot_line(said: &str) -> String {
    said.lines()
        .find(|l| l.contains("yaw-rate overshoot"))
        .unwrap_or_else(|| panic!("{said}"))
        .to_string()
}

/// With the limit checks on (mode 121) a load above `FZMAX` is said to be
/// evaluated at that end, but the loaded radius, like the rolling
/// resistance, takes the load given (MFeval's `calculateRhoRl61` takes
/// `Fz_lowLimit`, limited below only): the closing line names both, and
/// the file shows it (`rl` differs between 40 kN and the 18 kN end, the
/// forces do not).
#[test]
fn a_loaded_radius_past_the_load_range_is_said_to_take_the_load_given() {
    use super::tyre_eval::{column, eval};
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let points = "fz,kappa,alpha,camber,speed\n18000,0,0.05,0,16.7\n40000,0,0.05,0,16.7\n";
    let dir = tempfile::tempdir().unwrap();
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("(`my` at the load given, and `rl` the free radius at the load given less the deflection at the load held within FZMAX, as MFeval does)"),
        "{said}"
    );
    let (fy, rl) = (column(&written, "fy"), column(&written, "rl"));
    assert_eq!(fy[0], fy[1], "{written}");
    assert_ne!(rl[0], rl[1], "{written}");
}

/// A gyro that freezes a second after the step (400 of 601 samples at one
/// value to the end) was measured without a word, its noise before the
/// step called 66 spikes: the hold is found as stuck, the noise is not,
/// and the metrics warn that their steady window stands on the fill.
#[test]
fn a_yaw_rate_frozen_to_the_end_is_found_stuck_and_its_steady_window_said_filled() {
    let dir = tempfile::tempdir().unwrap();
    let sedan = Sedan::simulated(dir.path());
    // ±0.002 rad/s of deterministic scatter on every sample before 2 s.
    let noise = |i: usize| 0.002 * (((i * 7919) % 13) as f64 - 6.0) / 6.0;
    let run_path = sedan.measured(dir.path(), "late.csv", &|t, d, r, i| {
        (d, if t <= 2.0 { r + noise(i) } else { 0.0646 })
    });
    let o = run(&["metrics", run_path.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    // The scatter before the step is no longer taken for spikes (66 were;
    // one sample at the step's onset may be).
    let spikes: usize = e
        .split("zero reads, ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!(spikes <= 2 && e.contains(", 1 stuck value, "), "{e}");
    assert!(e.contains("stuck at 2.010 s in "), "{e}");
    assert!(
        e.contains("late.csv: yaw_rate 0.0646 (400 samples, masked)"),
        "{e}"
    );
    assert!(
        e.contains(
            "101 of the 101 samples of the steady window (5.00–6.00 s) are masked by the cleaning"
        ),
        "{e}"
    );
    assert!(e.contains("do not use these metrics"), "{e}");
    // The same run without the freeze: no stuck value, no such warning.
    let fine = sedan.measured(dir.path(), "fine.csv", &|_, d, r, i| (d, r + noise(i)));
    let e = stderr(&run(&["metrics", fine.to_str().unwrap()]));
    assert!(e.contains(" 0 stuck values"), "{e}");
    assert!(!e.contains("masked by the cleaning"), "{e}");
}

/// `--max-iterations 0` fitted nothing and reported a fit ("stopped at its
/// cap of 0 iterations", coefficients held as "the data do not move it");
/// a metrics setting the library refuses was named by its key
/// (`filter_hz`), not by the option typed.
#[test]
fn no_iterations_are_refused_and_a_refused_metrics_setting_names_its_option() {
    let dir = tempfile::tempdir().unwrap();
    let sedan = Sedan::simulated(dir.path());
    let rig = "fz,alpha,fy\n4000,0.0,0\n4000,0.05,3000\n4000,0.1,4000\n";
    fs::write(dir.path().join("rig.csv"), rig).unwrap();
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "mf61",
        "--max-iterations",
        "0",
        "--out",
        dir.path().join("x.tir").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("--max-iterations: `max_iterations` = 0: must be positive"),
        "{e}"
    );
    assert!(!dir.path().join("x.tir").exists());
    let run_path = sedan.measured(dir.path(), "run.csv", &|_, d, r, _| (d, r));
    let e = stderr(&run(&[
        "metrics",
        run_path.to_str().unwrap(),
        "--filter-hz",
        "1",
    ]));
    assert!(e.starts_with("error: --filter-hz: `filter_hz` = 1"), "{e}");
}
