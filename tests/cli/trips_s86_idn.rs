//! What a fresh user tripped on in `identify` on rig data: the ranges a
//! fitted file states, the names of load levels across outputs, a glitch
//! masked in a piece dropped whole, the Magic Formula fit's pooled σ over
//! rows no stage of a channel fits, and a steady lateral acceleration
//! beyond the car's rollover threshold.

use super::*;

/// The Hoosier file fitted by `magic-simple` at its 1656 N level, 0° and
/// 83.4 kPa, written to `out` in `dir`; the terminal's text.
fn hoosier_at_1656(rig: &Path, out: &Path) -> String {
    succeeds(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "magic-simple",
        "--load",
        "1656",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ])
}

/// `[fitted_ranges]` of a fit at one level, camber and pressure said fz
/// 1601–1681 N, the span of its points' means over slip bins, where the
/// samples fitted run from 1503 to 1795 N: `tyre-eval` at 1750 N called
/// that load an extrapolation.
#[test]
fn the_fitted_ranges_span_every_sample_fitted() {
    let test = "the_fitted_ranges_span_every_sample_fitted";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n1750,0,0.05,0,10\n")]);
    let out = dir.path().join("ms.toml");
    hoosier_at_1656(&rig, &out);
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains("\nfz = [1503.0, 1795.0]\n"), "{text}");
    assert!(text.contains("fz 1503 to 1795 N"), "{text}");
    let o = run_in(
        dir.path(),
        &["tyre-eval", "ms.toml", "p.csv", "--out", "e.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("extrapolation"), "{}", stderr(&o));
}

/// A condition's line named the 1656 N level by the median of the
/// samples fitted there, "Fz 1640 N", below "fz levels: … 1656 N" and
/// "the 1656 N level selected": one level, two names.
#[test]
fn a_load_level_has_one_name_in_every_line() {
    let test = "a_load_level_has_one_name_in_every_line";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = scratch(&[]);
    let out = dir.path().join("ms.toml");
    let said = hoosier_at_1656(&rig, &out);
    assert!(said.contains("fz levels: 534 N (11246), 1095 N (11247), 1656 N (11243), 2193 N (11242), 2751 N (14987)"), "{said}");
    assert!(said.contains("the 1656 N level selected"), "{said}");
    assert!(
        said.contains("    Fz    1656 N, camber  0.00°, pressure 83.4 kPa:"),
        "{said}"
    );
    // The samples' median is a value inside the level, said so, not a
    // second name of it.
    assert!(!said.contains("Fz    1640 N"), "{said}");
    assert!(said.contains(": 1640 N in the 1656 N level"), "{said}");
}

/// Exact MF 6.1 pure sweeps (`tyre-eval` of a public `.tir`: slip angle
/// at κ = 0 and slip ratio at α = 0, three loads) fitted back: the pooled
/// line gave `mz` σ 93.0 % over every sample, the pure longitudinal ones
/// whose moment only the skipped combined Mz stage fits among them; over
/// the rows its pure stage fits it is 0.089 %, and the 120 others are
/// counted and named.
#[test]
fn the_pooled_sigma_of_a_channel_is_over_the_rows_its_stages_fit() {
    let test = "the_pooled_sigma_of_a_channel_is_over_the_rows_its_stages_fit";
    let Some(tir) = shared_data(test, "tir_public/MagicFormula61_Paramerters.tir") else {
        return;
    };
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2000, 4000, 6000] {
        for i in -30..=30 {
            points += &format!("{fz},0,{:.4},0,16.7\n", f64::from(i) * 0.01);
        }
        for i in (-20..=20).filter(|i| *i != 0) {
            points += &format!("{fz},{:.4},0,0,16.7\n", f64::from(i) * 0.01);
        }
    }
    let dir = scratch(&[("pts.csv", &points)]);
    let tir = tir.to_str().unwrap();
    let o = run_in(
        dir.path(),
        &["tyre-eval", tir, "pts.csv", "--out", "ev.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run_in(
        dir.path(),
        &["identify", "ev.csv", "--model", "mf61", "--out", "fit.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("σ pooled over the 303 raw samples' rows the fitted stages take: "),
        "{said}"
    );
    assert!(
        said.contains("mz 0.089 %, RMS error 0.022 N·m, 120 samples left out (rows of pure longitudinal slip (α = 0), the combined Mz stage's, not fitted)"),
        "{said}"
    );
    let report = read_json(&dir.path().join("fit.report.json"));
    let mz = report["sigma_pooled"]["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["channel"] == "mz")
        .unwrap()
        .clone();
    assert_eq!(mz["samples"], 183, "{mz}");
    assert_eq!(mz["left_out"]["samples"], 120, "{mz}");
    assert_eq!(mz["left_out"]["stages"][0], "combined Mz", "{mz}");
    assert!(mz["sigma_percent"].as_f64().unwrap() < 0.1, "{mz}");
}

/// A step steer sized for a steady 8.5 m/s² on a car whose rollover
/// threshold g·t/(2h) is 8.445 m/s² (narrower track 1.55 m, cg 0.9 m up)
/// was simulated as if it stayed on four wheels; it is refused at its key,
/// and 8.4 m/s² below the threshold still runs.
#[test]
fn a_steady_lateral_acceleration_beyond_rollover_is_refused_at_its_key() {
    let vehicle = "[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.6\ntrack_rear = 1.55\ncg_height = 0.9\n";
    let tyre = format!("{GIM}friction = 1.3\n");
    let step = |ay: &str| {
        format!(
            "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nlateral_acceleration = {ay}\n"
        )
    };
    for ay in ["8.5", "-8.5"] {
        let dir = scenario(vehicle, &tyre, &step(ay));
        let e = simulate_err(dir.path());
        assert!(
            e.contains(&format!("scenario.toml:16:24: `manoeuvre.lateral_acceleration` = {ay}: at or beyond the rollover threshold g·t/(2h) = 9.80665 × 1.55 / (2 × 0.9) = 8.445 m/s² (0.861 g; t the narrower track, h the cg_height)")),
            "{e}"
        );
    }
    let dir = scenario(vehicle, &tyre, &step("8.4"));
    let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
}
