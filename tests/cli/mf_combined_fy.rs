//! The combined-slip lateral force stage of `identify --model mf61` recovers
//! a known `Gyκ` and `SVyκ` (`RBY*`, `RCY1`, `REY*`, `RHY*`, `RVY*`), signs
//! and values, from noise-free rig data that `tyre-eval` synthesised from
//! MFeval's public MF 6.1 file, whose `RVY1..RVY6` are all nonzero.
//!
//! What it guards: `Fy` on the pure longitudinal rows (κ ≠ 0, α = 0) is
//! `Gyκ·Fy0(0) + SVyκ`, and there `cos(atan(RVY4·α)) = 1`, so those rows are
//! what pins `SVyκ`'s amplitude and shape (`RVY1..3`, `RVY5`, `RVY6`). A fit
//! that leaves them out lands on another `SVyκ` that fits the combined rows
//! only (on `docs/examples/mf_grid.csv`, `RVY5`, `RVY6` of the wrong sign and
//! `fy` off by 1.5 % over the raw samples).

use super::mf_identify::{CONSTANTS_TIR, TRUTH};
use super::*;

/// Four loads and three cambers, so that the pure `Fy` stage frees every
/// term (`PKY4` needs four loads, `PEY5`, `PKY5` three cambers) and hands
/// the combined stage an exact `Fy0`; pure sweeps of κ and α and a κ × α
/// grid at α = ±4°, ±8° (as `docs/examples/mf_grid.csv`), where
/// `cos(atan(RVY4·α))` is in its 1/α regime: there the combined rows alone
/// trade `RVY1` against `RVY4`, and only the pure longitudinal rows
/// (α = 0) fix `SVyκ`'s amplitude.
fn points() -> String {
    let mut kx = vec![
        0.0, 0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0,
    ];
    kx.extend(kx.clone().iter().skip(1).map(|k| -k));
    let kc = [-0.5, -0.2, -0.1, -0.05, -0.02, 0.02, 0.05, 0.1, 0.2, 0.5];
    let ac = [-8.0, -4.0, 4.0, 8.0f64];
    let mut s = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2000.0, 4000.0, 6000.0, 8000.0] {
        for g in [0.0, 2.0, 4.0f64] {
            let g = g.to_radians();
            for k in &kx {
                s += &format!("{fz},{k},0,{g},16.7\n");
            }
            for i in -30..=30 {
                s += &format!("{fz},0,{},{g},16.7\n", (0.5 * i as f64).to_radians());
            }
            for k in kc {
                for a in ac {
                    s += &format!("{fz},{k},{},{g},16.7\n", a.to_radians());
                }
            }
        }
    }
    s
}

/// The value of `key` in a `.tir`.
fn tir_value(path: &Path, key: &str) -> f64 {
    let text = fs::read_to_string(path).unwrap();
    text.lines()
        .find_map(|l| {
            let (k, v) = l.split_once('=')?;
            (k.trim().eq_ignore_ascii_case(key)).then(|| {
                v.split_whitespace()
                    .next()
                    .unwrap()
                    .trim_matches('\'')
                    .parse::<f64>()
                    .unwrap()
            })
        })
        .unwrap_or_else(|| panic!("{key} not in {}", path.display()))
}

#[test]
fn combined_fy_stage_recovers_rvy_rhy_rby_signs_and_values_with_the_pure_longitudinal_rows() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("points.csv"), points()).unwrap();
    fs::write(d.join("constants.tir"), CONSTANTS_TIR).unwrap();
    let o = run(&[
        "tyre-eval",
        TRUTH,
        d.join("points.csv").to_str().unwrap(),
        "--out",
        d.join("rig.csv").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run(&[
        "identify",
        d.join("rig.csv").to_str().unwrap(),
        "--model",
        "mf61",
        "--template",
        d.join("constants.tir").to_str().unwrap(),
        "--out",
        d.join("fit.tir").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    println!("{out}");
    let truth = |k: &str| tir_value(&root().join(TRUTH), k);
    let fitted = |k: &str| tir_value(&d.join("fit.tir"), k);
    // The file's RVY5, RVY6 are both negative; sin(RVY5·atan(RVY6·κ)) is
    // the same with both flipped, and the fit reports RVY5 positive. RBY2
    // and RVY4 enter through cos(atan(·)) and are reported positive.
    assert!(truth("RVY5") < 0.0 && truth("RVY6") < 0.0);
    let canonical = |k: &str| match k {
        "RVY5" | "RVY6" | "RBY2" | "RVY4" => truth(k).abs(),
        _ => truth(k),
    };
    for k in [
        "RVY1", "RVY2", "RVY3", "RVY4", "RVY5", "RVY6", "RHY1", "RHY2", "RBY1", "RBY2", "RBY3",
        "RBY4", "RCY1", "REY1", "REY2",
    ] {
        let (want, got) = (canonical(k), fitted(k));
        assert!(
            want != 0.0,
            "{k} is zero in the truth: the test needs it nonzero"
        );
        assert!(
            (got - want).abs() <= 1e-4 * want.abs(),
            "{k}: fitted {got}, truth {want}"
        );
    }
    // Every row with longitudinal slip is in the combined Fy stage: the
    // pure longitudinal rows (4 loads × 3 cambers × 28 slip ratios) and the
    // combined ones (× 70).
    let report = read_json(&d.join("fit.report.json"));
    let stage = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["stage"] == "combined-fy")
        .unwrap();
    assert_eq!(stage["points"], 12 * (28 + 40));
}
