//! A fresh-eyes tester's findings (round 34) in `identify`'s written
//! ranges and words, `tyre-eval`'s refusals and `metrics`' advice: a
//! linear fit's alpha range that left out the rig's outermost samples; a
//! cornering sweep's rows at alpha ≈ 0 said as "pure longitudinal rows"; a
//! loaded radius written from a load whose effective rolling radius has
//! fallen through 0; one angle limit said two ways; window lengths said
//! as if they were the starts of the windows.

use super::*;

/// The tester's rig: the bundled linear tyre's `fy` and `mz` at 4000 N,
/// alpha −0.040 to +0.040 rad in steps of 0.001 (81 rows), `kappa` and
/// `fx` 0 throughout.
fn linear_rig() -> String {
    let mut s = String::from("fz,kappa,alpha,camber,speed,fx,fy,mz\n");
    for i in -40..=40 {
        let alpha = f64::from(i) * 0.001;
        let fy = 57296.0 * alpha;
        s += &format!("4000,0,{alpha},0,16.7,0,{fy},{}\n", 0.03 * fy);
    }
    s
}

/// The `[fitted_ranges]` key `key` of a written TOML tyre, `[lo, hi]`.
fn fitted_range(toml_text: &str, key: &str) -> [f64; 2] {
    let table: toml::Value = toml::from_str(toml_text).unwrap();
    let r = table["fitted_ranges"][key].as_array().unwrap();
    [r[0].as_float().unwrap(), r[1].as_float().unwrap()]
}

/// `linrig.csv` fitted `--model linear` said "81 used" and wrote `alpha =
/// [-0.039, 0.039]`: the linear window's reach, the outermost bin's mean,
/// not its samples'. `tyre-eval` of the written tyre at the rig's own
/// points then warned of an extrapolation.
#[test]
fn a_linear_fit_writes_ranges_that_hold_every_sample_of_its_rig() {
    let dir = scratch(&[("linrig.csv", &linear_rig())]);
    let o = run_in(
        dir.path(),
        &[
            "identify",
            "linrig.csv",
            "--model",
            "linear",
            "--out",
            "linfit.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(dir.path().join("linfit.toml")).unwrap();
    let [lo, hi] = fitted_range(&text, "alpha");
    assert!(lo <= -0.04 && hi >= 0.04, "{text}");
    assert!(lo > -0.041 && hi < 0.041, "{text}");
    let [f_lo, f_hi] = fitted_range(&text, "fz");
    assert!(f_lo <= 4000.0 && f_hi >= 4000.0, "{text}");
    let [c_lo, c_hi] = fitted_range(&text, "camber");
    assert!(c_lo <= 0.0 && c_hi >= 0.0, "{text}");
    assert!(text.contains("alpha -0.04000 to 0.04000 rad"), "{text}");
    // The tyre evaluated at the rig's own points extrapolates nowhere.
    let points: String = linear_rig()
        .lines()
        .map(|l| l.split(',').take(5).collect::<Vec<_>>().join(",") + "\n")
        .collect();
    fs::write(dir.path().join("pts.csv"), points).unwrap();
    let o = run_in(
        dir.path(),
        &["tyre-eval", "linfit.toml", "pts.csv", "--out", "chk.csv"],
    );
    let said = stderr(&o);
    assert!(o.status.success(), "{said}");
    assert!(!said.contains("extrapolation"), "{said}");
}

/// The same fit said "3 values of `fx` in the pure longitudinal rows not
/// fitted": the sweep's rows at alpha −0.001, 0 and 0.001, all at kappa 0
/// with `fx` 0. A row is pure longitudinal at |alpha| ≤ 1e-3 rad, and its
/// `fx` is said only where those rows sweep kappa (to |kappa| ≥ 0.01); a
/// file with such a sweep is still told its `fx` is not fitted.
#[test]
fn a_cornering_sweep_at_kappa_zero_is_said_to_have_no_longitudinal_rows_to_leave_out() {
    let dir = scratch(&[("linrig.csv", &linear_rig())]);
    let o = run_in(
        dir.path(),
        &[
            "identify",
            "linrig.csv",
            "--model",
            "linear",
            "--out",
            "a.toml",
        ],
    );
    let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    assert!(o.status.success(), "{said}");
    assert!(!said.contains("pure longitudinal rows"), "{said}");
    assert!(!said.contains("of `fx`"), "{said}");
    // A braking sweep at alpha 0 beside it: its `fx` is not fitted, said.
    let mut rig = linear_rig();
    for i in 1..=10 {
        let kappa = -0.01 * f64::from(i);
        rig += &format!("4000,{kappa},0,0,16.7,{},0,0\n", 4000.0 * 12.0 * kappa);
    }
    fs::write(dir.path().join("braking.csv"), rig).unwrap();
    let o = run_in(
        dir.path(),
        &[
            "identify",
            "braking.csv",
            "--model",
            "linear",
            "--out",
            "b.toml",
        ],
    );
    let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("values of `fx` in the pure longitudinal rows not fitted"),
        "{said}"
    );
}

/// `car205_60R19.tir` at 999999 N (FZMAX 10000 N) in the default mode
/// took the forces at FZMAX but wrote `rl` = 0.717 m (free radius 0.349
/// m) from the load given, where the effective rolling radius MFeval
/// takes has fallen through 0, and called it "no radius of the tyre";
/// mode 221 refused the row. Refused in every mode now, each at its row
/// with the same opening and ending; a load past FZMAX that the tyre
/// carries is still evaluated (its `rl` and `my` at the load given, as
/// MFeval gives them).
#[test]
fn a_load_whose_rolling_radius_falls_through_zero_is_refused_at_its_row_in_every_mode() {
    let Some(tir) = shared_data(
        "a_load_whose_rolling_radius_falls_through_zero_is_refused_at_its_row_in_every_mode",
        "tir_public/car205_60R19.tir",
    ) else {
        return;
    };
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n999999,0,0.05,0,16.7\n";
    let dir = scratch(&[("p.csv", points)]);
    let tir = tir.to_str().unwrap();
    for mode in [None, Some("121"), Some("221")] {
        let mut args = vec!["tyre-eval", tir, "p.csv", "--out", "e.csv"];
        args.extend(mode.iter().flat_map(|m| ["--mode", *m]));
        let o = run_in(dir.path(), &args);
        let e = stderr(&o);
        assert!(!o.status.success(), "{mode:?}: {e}");
        assert!(
            e.contains("p.csv:3:1: fz = 999999 N is more than the tyre's vertical model carries: ")
                && e.contains("so no loaded radius `rl` is physical there"),
            "{mode:?}: {e}"
        );
        assert!(!e.contains("p.csv:2:"), "{mode:?}: {e}");
        assert!(!dir.path().join("e.csv").exists(), "{mode:?}");
    }
    // Twice FZMAX: the forces at FZMAX, rl below the free radius.
    fs::write(
        dir.path().join("q.csv"),
        "fz,kappa,alpha,camber,speed\n20000,0,0.05,0,16.7\n",
    )
    .unwrap();
    let o = run_in(dir.path(), &["tyre-eval", tir, "q.csv", "--out", "f.csv"]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(!e.contains("loaded radius rl above the free radius"), "{e}");
}

/// `alpha` = 3 rad was refused as "beyond ±90°: … is the column in
/// degrees?" and 1e300 rad as "above 1.5708 rad, the largest a tyre is
/// evaluated at": one limit said two ways. Both say it as ±90° now, the
/// degrees hint only where the value could be degrees.
#[test]
fn a_slip_angle_past_ninety_degrees_is_said_against_one_limit_whatever_its_size() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,3,0,16.7\n4000,0,1e300,0,16.7\n";
    let dir = scratch(&[("p.csv", points)]);
    let tyre = root().join("tyres/linear.toml");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "p.csv",
            "--out",
            "e.csv",
        ],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("p.csv:2:3: column `alpha`: 3 rad is beyond ±90°: angles are in radians"),
        "{e}"
    );
    assert!(
        e.contains("p.csv:3:3: column `alpha`: 1e300 rad is beyond ±90° (±1.5708 rad), the largest a tyre is evaluated at (beyond it the wheel rolls backwards)"),
        "{e}"
    );
    assert!(!e.contains("is above 1.5708"), "{e}");
}

/// The bundled sedan's step (1° at 1 s, 80 km/h) with its rows from 2.0
/// to 2.29 s removed, as the tester's `gap.csv`: the piece before the hole
/// was said "none from 0.23 s to 0.87 s reads a settled response" just
/// after "a steady window must start after it at 1.11 s" — the lengths of
/// the windows tried, read as their starts. Said as lengths now, with the
/// starts they give (each window ends at the piece's end, 1.99 s).
#[test]
fn a_record_too_short_names_the_window_lengths_and_starts_it_tried() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("step.toml");
    fs::write(&scenario, bundled_scenario("sedan_step.toml")).unwrap();
    let out = dir.path().join("sim");
    scenarios::simulate_to(&scenario, &out);
    let gap = super::trips_s94_met::rewritten(
        &out.join("history.csv"),
        dir.path(),
        "gap.csv",
        "t,steer,speed,beta,yaw_rate,ay",
        // At 100 Hz, as the tester's log (the history is at 1 kHz).
        |c| (c[0] * 100.0 - (c[0] * 100.0).round()).abs() < 1e-6 && !(1.995..2.295).contains(&c[0]),
        |c| c.to_vec(),
    );
    let o = run(&["metrics", gap.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("and no window 0.23 s to 0.87 s long ending at the record's end (starting from 1.12 s to 1.76 s) reads a settled response"),
        "{e}"
    );
    assert!(!e.contains("none from 0.23 s"), "{e}");
}
