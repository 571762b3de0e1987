//! What a new user tripped on in `identify` (rig data → tyre parameters)
//! and `.tir` handling, round 79, run from files as a user runs the tool:
//! a cornering file with an `fx` column of zeros at κ = 0 refused with a
//! point count; combined-slip rows averaged into the pure lateral curve;
//! the staged Magic Formula fit's combined and aligning blocks left
//! without a word.

use super::*;

/// A Magic Formula-like lateral force of a tyre at load `fz`, N:
/// friction 1.1, stiffness 18 N/rad per N of load, curvature −0.5.
fn fy(alpha: f64, fz: f64) -> f64 {
    let (d, c) = (1.1 * fz, 1.3);
    let b = 18.0 * fz / (c * d);
    let x = b * alpha;
    d * (c * (x + 0.5 * (x - x.atan())).atan()).sin()
}

/// Its aligning moment, N·m: a trail of 30 mm that falls with slip.
fn mz(alpha: f64, fz: f64) -> f64 {
    0.03 * fy(alpha, fz) * (2.0 * (6.0 * alpha).atan()).cos()
}

/// A cornering rig file at 2000, 4000 and 6000 N, slip angles −12° to
/// 12° in 0.25° steps: for each, `row(alpha, fz)` gives the text of its
/// rows after `fz,alpha,` (the header `fz,alpha,` + `columns`).
fn cornering(columns: &str, row: impl Fn(f64, f64) -> Vec<String>) -> String {
    let mut csv = format!("fz,alpha,{columns}\n");
    for fz in [2000.0, 4000.0, 6000.0_f64] {
        for i in -48..=48 {
            let a = (0.25 * f64::from(i)).to_radians();
            for r in row(a, fz) {
                csv += &format!("{fz},{a:.7},{r}\n");
            }
        }
    }
    csv
}

/// A pure cornering test whose rig logged `kappa` and `fx` as 0 at every
/// row: PAC89 and UniTire refused it with "3 points with a measured
/// longitudinal force cannot fit 11 parameters". The lateral and
/// aligning blocks are fitted, and the longitudinal block is said not
/// fitted for want of a slip-ratio sweep.
#[test]
fn a_cornering_file_with_fx_zero_at_kappa_zero_fits_its_lateral_block() {
    let csv = cornering("fy,mz,kappa,fx", |a, fz| {
        vec![format!("{:.3},{:.4},0,0", fy(a, fz), mz(a, fz))]
    });
    let dir = scratch(&[("corner.csv", &csv)]);
    for model in ["pac89", "unitire"] {
        let out = dir.path().join(format!("{model}.toml"));
        let o = identify_to(&dir.path().join("corner.csv"), model, &out);
        assert!(o.status.success(), "{model}: {}", stderr(&o));
        let said = String::from_utf8_lossy(&o.stdout);
        let line = "no longitudinal data: the file's longitudinal force coefficients are not fitted (no longitudinal-slip sweep: |kappa| reaches 0 on the rows at alpha = 0, below the 0.01 a sweep must reach)";
        assert!(said.contains(line), "{model}: {said}");
        assert!(!said.contains("cannot fit"), "{model}: {said}");
        let file = fs::read_to_string(&out).unwrap();
        assert!(file.contains(&format!("# {line}")), "{model}: {file}");
        let report = read_json(&out.with_extension("report.json"));
        assert_eq!(report["set_aside"]["kappa_reach"], 0.0, "{model}");
        assert!(report["longitudinal"].is_null(), "{model}");
        assert!(report["aligning"].is_object(), "{model}");
    }
}

/// Combined-slip rows (κ = 0.1, the lateral force 0.6 of the pure one)
/// beside a cornering sweep: GIM averaged them into the pure lateral
/// bins, and its cornering stiffness came out 20 % low. They are left
/// out and counted, and the stiffness is the pure file's.
#[test]
fn combined_slip_rows_are_left_out_of_a_pure_lateral_fit_and_counted() {
    let pure = cornering("fy,mz,kappa,fx", |a, fz| {
        vec![format!("{:.3},{:.4},0,0", fy(a, fz), mz(a, fz))]
    });
    let mixed = cornering("fy,mz,kappa,fx", |a, fz| {
        vec![
            format!("{:.3},{:.4},0,0", fy(a, fz), mz(a, fz)),
            format!(
                "{:.3},{:.4},0.1,{:.3}",
                0.6 * fy(a, fz),
                0.6 * mz(a, fz),
                0.1 * fz
            ),
        ]
    });
    let dir = scratch(&[("pure.csv", &pure), ("mixed.csv", &mixed)]);
    let stiffness = |name: &str| {
        let out = dir.path().join(format!("{name}.toml"));
        let o = identify_to(&dir.path().join(format!("{name}.csv")), "gim", &out);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let file = fs::read_to_string(&out).unwrap();
        let value: f64 = file
            .lines()
            .find_map(|l| l.strip_prefix("cornering_stiffness = "))
            .unwrap()
            .parse()
            .unwrap();
        (value, stderr(&o), file)
    };
    let (pure_c, _, _) = stiffness("pure");
    let (mixed_c, err, file) = stiffness("mixed");
    assert_eq!(mixed_c, pure_c);
    // 291 of the 582 rows are at κ = 0.1; the three at α = 0 are pure
    // longitudinal, not combined.
    let line = "288 rows of the file's 582 are combined slip (|alpha| > 0.001 rad and |kappa| > 0.001), left out: the gim model is fitted to pure slip only";
    assert!(err.contains(&format!("warning: {line}")), "{err}");
    assert!(file.contains(&format!("# warning: {line}")), "{file}");
}
