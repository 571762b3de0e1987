//! What a fresh-eyes user still tripped on, run as a user runs the tool:
//! an `identify`'d `.tir` whose lateral curvature exceeds 1 over its own
//! data without a word; `design` taking absurd limits and printing NaN, a
//! negative expected separation and a recommendation for a pair already
//! told apart, its figure's inputs in a candidate's colour; `identify
//! --bin-deg` collapsing the data at a tiny bin; `metrics` taking an
//! absurd threshold and suggesting columns it refuses; `tyre-eval`
//! dropping an input column silently; `identify` naming no column of a
//! header without `fy`. Each test one finding.

use super::*;

/// The Hoosier cornering fit reaches `Ey` above 1 within its data (PEY1
/// on its bound of 1, PEY2, PEY5 large): the file reproduces the data
/// only with limit checks clipping E at 1. `identify` says so, in its
/// output, its report and the `.tir`, with the slip angle beyond which the
/// file's lateral force without the checks changes sign where the fit's
/// does not: `tyre-eval --mode 221` against its default 121 finds the
/// change there, on a sweep in tenths of a degree.
#[test]
fn identify_warns_where_the_fitted_curvature_exceeds_one_over_its_data() {
    let test = "identify_warns_where_the_fitted_curvature_exceeds_one_over_its_data";
    // The fit `identify --model mf61` makes of the file with its defaults,
    // run once for the tests that read it.
    let Some(fit) = hoosier_mf61(test) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (text, out) = (&fit.stdout, &fit.tir);
    let line = text
        .lines()
        .find(|l| l.contains("warning: curvature Ey reaches "))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(
        line.contains("relies on a limit check clipping E at 1 (MFeval's useLimitsCheck; tyre-eval's mode 121"),
        "{line}"
    );
    let report = read_json(&out.with_extension("report.json"));
    let e = &report["curvature_above_one"][0];
    assert_eq!(e["curvature"], "Ey", "{report}");
    assert!(e["largest"].as_f64().unwrap() > 1.0, "{e}");
    let tir = std::fs::read_to_string(out).unwrap();
    assert!(tir.contains("$ warning: curvature Ey reaches "), "{tir}");
    // Where the file without the checks turns against the fit.
    let beyond = e["reverses_beyond"].as_f64().unwrap();
    let at = e["reverses_at"].as_array().unwrap();
    let (fz, camber, sign) = (
        at[0].as_f64().unwrap(),
        at[1].as_f64().unwrap(),
        at[2].as_f64().unwrap(),
    );
    assert!(beyond < e["data_slip"].as_f64().unwrap(), "{e}");
    let said: f64 = line
        .split("beyond |alpha| = ")
        .nth(1)
        .and_then(|s| s.split('°').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{line}"));
    assert!((said - beyond.to_degrees()).abs() < 0.01, "{line}");
    // In the points' frame, as the warning says it.
    let side = sign;
    assert!(
        line.contains("signs as tyre-eval's points give them"),
        "{line}"
    );
    // At the pressure of the reversal where the report names one (the scan
    // runs at the data's pressures), else at the file's own.
    let pressure = e["reverses_at_pressure"]
        .as_f64()
        .map_or(String::new(), |p| format!(",{p}"));
    let degrees: Vec<f64> = (1..=200).map(|k| 0.1 * k as f64).collect();
    let rows: String = degrees
        .iter()
        .map(|d| format!("{fz},0,{},{camber},11.2{pressure}\n", side * d.to_radians()))
        .collect();
    let header = if pressure.is_empty() { "" } else { ",pressure" };
    let points = format!("fz,kappa,alpha,camber,speed{header}\n{rows}");
    let fy = |mode: &str| {
        let (o, written) = super::tyre_eval::eval(dir.path(), out, &points, &["--mode", mode]);
        assert!(o.status.success(), "{}", stderr(&o));
        super::tyre_eval::column(&written, "fy")
    };
    let (with, without) = (fy("121"), fy("221"));
    let first = degrees
        .iter()
        .zip(with.iter().zip(&without))
        .find(|(_, (a, b))| *a * *b < 0.0)
        .map(|(d, _)| *d)
        .unwrap_or_else(|| panic!("no change of sign to 20°: {with:?} {without:?}"));
    assert!(
        first > beyond.to_degrees() && first - 0.1 <= beyond.to_degrees(),
        "tyre-eval: first opposite sign at {first}°, the warning says beyond {}°",
        beyond.to_degrees()
    );
}

/// A synthetic campaign with a sensor delay, its vehicle file claiming a
/// steer path too, diagnosed into `dir/d` (as the book's design chapter
/// does): the diagnosis `design` is run on.
fn sensor_delay_diagnosis(dir: &Path) -> PathBuf {
    let c = synth_campaign(dir, "c", &["--effects", "sensor_delay", "--seed", "1"]);
    let vehicle = c.join("vehicle.toml");
    let mut text = std::fs::read_to_string(&vehicle).unwrap();
    text += "effects = [\"sensor_delay\", \"steer_path\"]\n";
    std::fs::write(&vehicle, text).unwrap();
    let d = dir.join("d");
    diagnose_to(&c, &d);
    d
}

/// `--max-ax 1e308` printed a 309-digit limit and dropped six manoeuvres
/// unsaid; `--ay-share 0.0001` printed `|ay| ≤ 0.00` and `at most NaN ±
/// NaN`; a sweep of D = 0.2 was "expected to measure -0.5" against a book
/// that says a separation reads 0 or more. Each is now refused by name and
/// value, said, or explained.
#[test]
fn design_refuses_absurd_limits_names_what_they_leave_out_and_never_prints_nan() {
    let dir = tempfile::tempdir().unwrap();
    let d = sensor_delay_diagnosis(dir.path());
    let d = d.to_str().unwrap();
    let o = run(&["design", d, "--max-ax", "1e308"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains(
            "`--max-ax` = 1e308: must lie in (0, 15]: tyres give a car at most about 15 m/s²"
        ),
        "{e}"
    );
    let text = succeeds(&["design", d, "--max-ax", "0.1"]);
    assert!(
        text.contains("  the limits leave out 6 of the family: braking in a turn at 80 km/h and "),
        "{text}"
    );
    let report = read_json(&Path::new(d).join("design/design.json"));
    assert_eq!(report["left_out_by_limits"].as_array().unwrap().len(), 6);
    let text = succeeds(&["design", d, "--ay-share", "0.0001"]);
    assert!(!without_temp_names(&text).contains("NaN"), "{text}");
    assert!(
        text.contains("|ay| ≤ 0.000815 m/s² (0.0100 % of the"),
        "{text}"
    );
    assert!(
        text.contains("  no manoeuvre of the family fits within the limits"),
        "{text}"
    );
    // A negative expected separation is explained where it is printed.
    let text = succeeds(&["design", d]);
    for line in text.lines().filter(|l| l.contains("expected to measure -")) {
        assert!(
            line.contains("(below 0: the noise of the start the replays take costs the reference more than its look-alike"),
            "{line}"
        );
    }
}

/// A pair the diagnosis already tells apart was "recommended" to drive.
/// It is now said that none needs driving.
#[test]
fn design_does_not_recommend_a_test_for_a_pair_already_told_apart() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let d = dir.path().join("d");
    diagnose_to(&c, &d);
    let text = succeeds(&[
        "design",
        d.to_str().unwrap(),
        "--effects",
        "sensor_delay,relaxation_length",
    ]);
    assert!(!text.contains("; recommended"), "{text}");
    assert!(
        text.contains("; not needed: the diagnosis already tells them apart"),
        "{text}"
    );
    assert!(
        text.contains("  none needs driving: the diagnosis already tells them apart"),
        "{text}"
    );
    let report = read_json(&d.join("design/design.json"));
    assert_eq!(
        report["sets"][0]["recommendation"]["kind"],
        "already_told_apart"
    );
}

/// `--bin-deg 1e-20` thinned 63 samples to a handful of points (the bin
/// numbers saturated an integer) and said `0.000° slip-angle bins`;
/// `--bin-deg 5` was refused as outside `(0, 2]` though 0 is accepted.
#[test]
fn identify_never_thins_to_fewer_points_at_a_smaller_bin() {
    let csv = crate::trips_s62::rig("fz,alpha,fy", |fz, a, fy| format!("{fz},{a},{fy:.3}"));
    let dir = scratch(&[("rig.csv", &csv)]);
    let rig = dir.path().join("rig.csv");
    for bin in ["0", "1e-20", "1e-300"] {
        let out = dir.path().join(format!("t{bin}.toml"));
        let o = identify_with(&rig, "pac89", &["--bin-deg", bin], &out);
        assert!(o.status.success(), "{bin}: {}", stderr(&o));
        let text = String::from_utf8_lossy(&o.stdout).into_owned();
        assert!(text.contains("thinned to 63 points ("), "{bin}: {text}");
        if bin != "0" {
            assert!(
                text.contains(&format!("a bin of {bin}° is below the resolution of the data's slips, so every sample is kept")),
                "{text}"
            );
        }
    }
    let o = identify_with(
        &rig,
        "pac89",
        &["--bin-deg", "5"],
        &dir.path().join("t5.toml"),
    );
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("`bin_deg` = 5: must lie in [0, 2]"),
        "{}",
        stderr(&o)
    );
}

/// `--min-overshoot 1e308` was taken and printed as `< 1e308 %`.
#[test]
fn metrics_refuses_a_least_overshoot_beyond_its_limit() {
    let dir = tempfile::tempdir().unwrap();
    let run_csv = dir.path().join("run.csv");
    let mut s = String::from("t,speed,steer,yaw_rate\n");
    for k in 0..400 {
        let t = f64::from(k) * 0.01;
        let d = if t < 1.0 { 0.0 } else { 0.02 };
        s += &format!("{t},20,{d},{}\n", 10.0 * d);
    }
    std::fs::write(&run_csv, s).unwrap();
    let o = run(&[
        "metrics",
        run_csv.to_str().unwrap(),
        "--min-overshoot",
        "1e308",
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("`min_overshoot` = 1e308: must lie in [0, 100]"),
        "{e}"
    );
}

/// `tyre-eval` dropped a points file's column `foo` without a word.
#[test]
fn tyre_eval_names_the_input_columns_it_does_not_carry_to_the_output() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = crate::tyre_eval::mf61(dir.path(), &[]);
    std::fs::write(
        dir.path().join("p.csv"),
        "fz,kappa,alpha,camber,speed,foo\n4000,0,0.02,0,16.7,7\n",
    )
    .unwrap();
    let o = bin()
        .args([
            "tyre-eval",
            tyre.to_str().unwrap(),
            "p.csv",
            "--out",
            "f.csv",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let all = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(
        all.contains("the points file's column `foo` is not carried to the output"),
        "{all}"
    );
}

/// A rig file without `fy` (nor `kappa`, `fx`) was refused naming no
/// column it has.
#[test]
fn identify_names_the_header_of_a_file_without_a_sweep() {
    let dir = scratch(&[("nofy.csv", "fz,alpha,foo\n2000,0.01,1\n2000,0.02,1\n")]);
    let o = identify_to(
        &dir.path().join("nofy.csv"),
        "mf61",
        &dir.path().join("n.tir"),
    );
    assert!(!o.status.success());
    assert!(
        stderr(&o)
            .contains("no longitudinal data (`kappa` and `fx`); the header has: fz, alpha, foo"),
        "{}",
        stderr(&o)
    );
}
