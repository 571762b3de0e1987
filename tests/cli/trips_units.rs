//! What a user still trips on: points a tyre model cannot
//! load, measured runs written in another unit than FORMATS.md's, and
//! records that are not a step steer, run as a user runs the tool.

use super::*;

/// A measured run at 20 m/s: from `start` to `end` s at 100 Hz, the steer
/// `steer(t)` (rad) and the yaw rate of a car with r·l/(u·δ) = 0.6 (l =
/// 5 m) behind a 0.15 s lag, ay = u·r; each channel written times its
/// factor in `scale` (t, yaw_rate, ay).
struct Run {
    start: f64,
    end: f64,
    steer: fn(f64) -> f64,
    scale: [f64; 3],
}

/// A 0.05 rad step steer at 2 s, ramped over 0.05 s.
fn step(t: f64) -> f64 {
    0.05 * ((t - 2.0) / 0.05).clamp(0.0, 1.0)
}

const SI: Run = Run {
    start: 0.0,
    end: 6.0,
    steer: step,
    scale: [1.0, 1.0, 1.0],
};

impl Run {
    fn csv(&self) -> String {
        let mut s = String::from("t,speed,steer,yaw_rate,ay\n");
        let n = ((self.end - self.start) / 0.01).round() as usize;
        let (u, mut r) = (20.0, 0.0);
        let [ts, rs, ays] = self.scale;
        for i in 0..=n {
            let t = self.start + 0.01 * i as f64;
            let d = (self.steer)(t);
            if i > 0 {
                r += (0.6 * u * d / 5.0 - r) * (1.0 - (-0.01f64 / 0.15).exp());
            }
            s += &format!(
                "{:.6},{u},{d:.6},{:.6},{:.6}\n",
                t * ts,
                r * rs,
                u * r * ays
            );
        }
        s
    }
}

/// `metrics` on `run` written as `run.csv`: its success and output.
fn metrics_of(run: &Run) -> (bool, String) {
    let dir = scratch(&[("run.csv", &run.csv())]);
    let o = bin()
        .args(["metrics", "run.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    (o.status.success(), text)
}

/// The refusal of `metrics` on `run`.
fn refused_run(run: &Run) -> String {
    let (ok, text) = metrics_of(run);
    assert!(!ok, "expected a refusal: {text}");
    text
}

/// `tyre-eval` of the MF 6.1 fixture at the points of `points` (CSV
/// text): its output, the CSV it writes to, and the scratch folder that
/// holds both.
fn mf61_at(points: &str) -> (Output, PathBuf, tempfile::TempDir) {
    let dir = scratch(&[("points.csv", points)]);
    let out = dir.path().join("out.csv");
    let o = run(&[
        "tyre-eval",
        "tests/fixtures/tir/MagicFormula61_Parameters.tir",
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (o, out, dir)
}

/// An MF 6.1 file at fz ≤ 0 lost its `rl` column when the first point was
/// unloaded, and was refused ("non-finite `rl`") when a later one was.
#[test]
fn tyre_eval_writes_rl_on_every_row_with_the_free_radius_off_the_road() {
    let (o, out, _dir) = mf61_at(
        "fz,kappa,alpha,camber,speed\n0,0,0.01,0,20\n4000,0,0.01,0,20\n0,0,0.01,0,20\n0.001,0,0.01,0,20\n",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("2 points at fz ≤ 0 (off the road): no force, `rl` the free radius"),
        "{said}"
    );
    let text = fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(head.last(), Some(&"rl"), "{head:?}");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 4);
    for row in &rows {
        assert_eq!(row.len(), head.len(), "{row:?}");
    }
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let rl: Vec<f64> = rows.iter().map(|r| r[col("rl")]).collect();
    // Off the road: the free radius, the limit of the loaded radius as the
    // load falls to zero (1 mN deflects the tyre by nanometres), no force.
    assert_eq!(rl[0], rl[2]);
    assert!(rl[3] <= rl[0] && rl[0] - rl[3] < 1e-7, "{rl:?}");
    assert!(rl[0] - rl[1] > 0.01, "4 kN deflects the tyre: {rl:?}");
    for i in [0, 2] {
        for f in ["fx", "fy", "mz", "mx", "my"] {
            assert_eq!(rows[i][col(f)], 0.0, "{f} of row {i}");
        }
    }
}

/// `fz = 4` (a car's 4 kN written in kN) was evaluated as 4 N: the loads
/// on the road are refused at their cell when their median is no tyre
/// test's; points off the road (`fz ≤ 0`) do not count.
#[test]
fn tyre_eval_refuses_loads_in_kn_at_their_cell() {
    let (o, out, _dir) = mf61_at(
        "fz,kappa,alpha,camber,speed\n0,0,0.01,0,20\n4,0,0.01,0,20\n4.5,0,0.02,0,20\n5,0,0.03,0,20\n",
    );
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("points.csv:3:1: column `fz`: 4 N, in a file whose median load is 4.5 N")
            && e.contains("is the column in kN?"),
        "{e}"
    );
    assert!(!out.exists());
}

/// The same generator in SI units is measured: the refusals below are the
/// units' and the records', not the generator's.
#[test]
fn a_step_steer_run_in_si_units_is_measured() {
    let (ok, text) = metrics_of(&SI);
    assert!(ok, "{text}");
    assert!(
        text.contains("steer step                   2.8648 deg"),
        "{text}"
    );
}

/// A yaw rate in deg/s was measured as rad/s (a gain 57× too large).
#[test]
fn a_yaw_rate_in_degrees_per_second_is_refused_at_its_column() {
    let e = refused_run(&Run {
        scale: [1.0, 180.0 / std::f64::consts::PI, 1.0],
        ..SI
    });
    assert!(e.contains("run.csv:213:4: column `yaw_rate`: 3.085"), "{e}");
    assert!(
        e.contains("rad/s is beyond ±3 rad/s (172°/s), which no car's yaw rate reaches (the run's 99th percentile of |yaw_rate| is 6.88 rad/s)"),
        "{e}"
    );
    assert!(
        e.contains("is the column in deg/s? divide it by 57.3"),
        "{e}"
    );
}

/// `ay` in g was measured as m/s² (a steady ay 9.8× too small).
#[test]
fn a_lateral_acceleration_in_g_is_refused_at_its_column() {
    let e = refused_run(&Run {
        scale: [1.0, 1.0, 1.0 / 9.80665],
        ..SI
    });
    assert!(e.contains("run.csv:244:5: column `ay`: 0.2276"), "{e}");
    assert!(
        e.contains("`ay` is a median 0.102 of it, where a car's lateral acceleration is about speed × yaw_rate: is `ay` in g? multiply it by 9.81"),
        "{e}"
    );
}

/// `ay` beyond 30 m/s² (a 1.2 g turn written in ft/s²) is no car's.
#[test]
fn a_lateral_acceleration_beyond_30_m_s2_is_refused_at_its_column() {
    let e = refused_run(&Run {
        steer: |t| 5.0 * step(t),
        scale: [1.0, 1.0, 3.28084],
        ..SI
    });
    assert!(e.contains("column `ay`: 30."), "{e}");
    assert!(
        e.contains("m/s² is beyond ±30 m/s² (3.1 g), which no car's lateral acceleration reaches (the run's 99th percentile of |ay| is 39.4 m/s²)"),
        "{e}"
    );
    assert!(
        e.contains("is the column in ft/s² (divide it by 3.281)"),
        "{e}"
    );
}

/// A time in ms (10 ms steps written as 10) was measured as seconds: a
/// response time of 341 s.
#[test]
fn a_time_in_milliseconds_is_refused_with_its_step() {
    let e = refused_run(&Run {
        scale: [1000.0, 1.0, 1.0],
        ..SI
    });
    assert!(
        e.contains("run.csv:3:1: column `t`: the median time step is 10 (0.1 Hz if in seconds), coarser than any handling run is logged at (at most 0.2 s, 5 Hz)"),
        "{e}"
    );
    assert!(
        e.contains("is `t` in milliseconds (10 ms: 100 Hz)? divide it by 1000"),
        "{e}"
    );
}

/// A record starting 0.2 s before the step was measured with the step in
/// its initial window: a steer step of 1.29° for the 2.86° given. Where
/// the steer moves is read on the raw steer: its first sample past 5 % of
/// the step, 2.01 s (the low-pass spreads the step ahead of itself).
#[test]
fn a_record_starting_just_before_the_step_is_refused_with_the_reason() {
    let e = refused_run(&Run { start: 1.8, ..SI });
    assert!(
        e.contains("the steer moves by more than 5 % of its step at 2.01 s, inside the initial window (1.80–2.30 s) whose means are the initial values: the record starts too close to the step"),
        "{e}"
    );
    assert!(e.contains("`pre_window` = 0.5 s before the step"), "{e}");
}

/// A frequency sweep whose last second's mean differs from its first's
/// was measured as a step of 0.05°.
#[test]
fn a_sweep_is_refused_as_a_step_steer_with_the_reason() {
    let e = refused_run(&Run {
        end: 10.0,
        steer: |t| {
            let s = t - 1.0;
            if s > 0.0 {
                0.05 * (std::f64::consts::TAU * (0.2 * s + 0.1 * s * s)).sin()
            } else {
                0.0
            }
        },
        ..SI
    });
    // A sweep reverses its steer again and again: no step at all, said
    // with its span and reversals (stop 75; it was "does not hold its step").
    assert!(
        e.contains("no step-steer metrics (no step steer in this record: the steer spans"),
        "{e}"
    );
    assert!(e.contains("and reverses"), "{e}");
}
