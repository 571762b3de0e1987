//! Unit slips on transient runs: a step steer with a logger's noise, a
//! frequency sweep, whose per-sample ratio ay/(speed·yaw_rate) scatters
//! out of a unit's band, went through with a speed in km/h, an `ay` in g
//! or `ay` and `yaw_rate` swapped. The run-wide slope of `ay` on the
//! kinematic lateral acceleration over half-second means refuses them at
//! the column, with the slope and the unit; the same runs in SI units
//! are read.

use super::*;

/// A deterministic noise in [-amp, amp] for sample `k` (a logger's).
fn noise(k: usize, amp: f64) -> f64 {
    amp * (2.0 * ((k as f64 * 12.9898).sin() * 43758.5453).rem_euclid(1.0) - 1.0)
}

/// The run `name` of synth's handling programme, rewritten: `ay` and
/// `yaw_rate` with noise of `amp` and `amp`/30 added, then each cell of
/// column `scaled` times `factor`, or the two columns' names swapped
/// (`scaled` "swap"). Written to `dir/file`.
fn rewritten(dir: &Path, name: &str, amp: f64, scaled: &str, factor: f64, file: &str) -> PathBuf {
    let src = synthesised(&[]).join(format!("runs/{name}.csv"));
    let text = fs::read_to_string(src).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let at = |c: &str| header.iter().position(|h| h == c).unwrap();
    let (ay, r) = (at("ay"), at("yaw_rate"));
    let mut out = if scaled == "swap" {
        let h: Vec<&str> = header
            .iter()
            .map(|h| match h.as_str() {
                "ay" => "yaw_rate",
                "yaw_rate" => "ay",
                o => o,
            })
            .collect();
        h.join(",")
    } else {
        header.join(",")
    };
    out.push('\n');
    for (k, line) in lines.enumerate() {
        let mut v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        v[ay] += noise(k, amp);
        v[r] += noise(k + 7777, amp / 30.0);
        if scaled != "swap" {
            v[at(scaled)] *= factor;
        }
        let cells: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
        out += &cells.join(",");
        out.push('\n');
    }
    let path = dir.join(file);
    fs::write(&path, out).unwrap();
    path
}

/// The stderr of `metrics` on `run`, and whether it succeeded.
fn metrics_on(run: &Path) -> (bool, String) {
    let o = self::run(&["metrics", run.to_str().unwrap()]);
    (o.status.success(), stderr(&o))
}

/// A 100 km/h step steer with an accelerometer's noise of ±0.6 m/s²:
/// its speed in km/h put 80 % of the per-sample ratios nowhere and the
/// step's metrics came out of a car 3.6 times too fast; now refused at
/// `speed` with the slope (0.28); in m/s it is measured.
#[test]
fn a_noisy_step_steer_with_its_speed_in_kmh_is_refused_by_its_lateral_slope() {
    let dir = tempfile::tempdir().unwrap();
    let step = "step_100kph_2ms2";
    let ok = rewritten(dir.path(), step, 0.6, "speed", 1.0, "si.csv");
    let (read, said) = metrics_on(&ok);
    assert!(read, "{said}");
    let kmh = rewritten(dir.path(), step, 0.6, "speed", 3.6, "kmh.csv");
    let (read, said) = metrics_on(&kmh);
    assert!(!read, "{said}");
    assert!(said.contains("kmh.csv:"), "{said}");
    assert!(
        said.contains(":2: column `speed`: over 10 half-second means of the run turning at speed"),
        "{said}"
    );
    assert!(said.contains("has a slope of 0.282"), "{said}");
    assert!(
        said.contains("is `speed` in km/h? divide it by 3.6"),
        "{said}"
    );
}

/// The same step with `ay` and `yaw_rate` swapped: `metrics` blamed the
/// car's yaw rate (5.9 times a neutral car's) and `diagnose` read it;
/// now refused at `ay` as swapped.
#[test]
fn a_step_steer_with_ay_and_yaw_rate_swapped_is_refused_at_ay() {
    let dir = tempfile::tempdir().unwrap();
    let swap = rewritten(dir.path(), "step_060kph_2ms2", 0.3, "swap", 1.0, "swap.csv");
    let (read, said) = metrics_on(&swap);
    assert!(!read, "{said}");
    assert!(said.contains("swap.csv:"), "{said}");
    assert!(
        said.contains(":52:4: column `ay`: over 11 half-second means"),
        "{said}"
    );
    assert!(said.contains("has a slope of 0.00356"), "{said}");
    assert!(said.contains("and `yaw_rate` regressed on speed × `ay` + d(speed·beta)/dt has a slope of 1.018: are the `ay` and `yaw_rate` columns swapped?"), "{said}");
}

/// A frequency sweep with `ay` in g: the per-sample ratio scatters with
/// the sideslip's rate, and it went through; now refused at `ay` with its
/// slope (0.102). In m/s² it reads (and `metrics` says it holds no step).
#[test]
fn a_sweep_with_ay_in_g_is_refused_and_in_si_units_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = "sweep_080kph";
    let g = rewritten(dir.path(), sweep, 0.0, "ay", 1.0 / 9.80665, "g.csv");
    let (read, said) = metrics_on(&g);
    assert!(!read, "{said}");
    assert!(said.contains("g.csv:"), "{said}");
    assert!(
        said.contains(":5: column `ay`: over 9 half-second means"),
        "{said}"
    );
    assert!(said.contains("has a slope of 0.102"), "{said}");
    assert!(said.contains("is `ay` in g? multiply it by 9.81"), "{said}");
    let si = rewritten(dir.path(), sweep, 0.0, "ay", 1.0, "si.csv");
    let (_, said) = metrics_on(&si);
    assert!(said.contains("no step-steer metrics"), "{said}");
    assert!(!said.contains("half-second means"), "{said}");
}

/// A step steer's `beta` in percent of a radian (100×) was named as in
/// degrees (57.3×); its changes against ∫(ay/speed − yaw_rate) dt say 115×:
/// now named percent.
#[test]
fn a_step_steers_beta_in_percent_is_named_percent_not_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let pct = rewritten(
        dir.path(),
        "step_100kph_2ms2",
        0.0,
        "beta",
        100.0,
        "pct.csv",
    );
    let (read, said) = metrics_on(&pct);
    assert!(!read, "{said}");
    assert!(said.contains("pct.csv:2:6: column `beta`:"), "{said}");
    assert!(
        said.contains("its changes are 115× what ∫(ay/speed − yaw_rate) dt gives"),
        "{said}"
    );
    assert!(
        said.contains("is `beta` in percent? divide it by 100"),
        "{said}"
    );
}
