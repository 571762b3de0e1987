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

/// A longitudinal force of the same tyre, N: friction 1.2, slip
/// stiffness 20 N per N of load.
fn fx(kappa: f64, fz: f64) -> f64 {
    let (d, c) = (1.2 * fz, 1.6);
    let b = 20.0 * fz / (c * d);
    let x = b * kappa;
    d * (c * (x - 0.2 * (x - x.atan())).atan()).sin()
}

/// A pure-slip file, a cornering sweep at κ = 0 and a braking/driving
/// sweep at α = 0 per load and no combined slip: `identify --model mf62`
/// fitted the combined `Fy` coefficients to the α = 0 rows (`RBY1` =
/// 27386, σ inf %) and left `RBX*` at 0 without a word. The combined
/// stages are skipped, their coefficients written as the defaults' and
/// said so on the terminal and in the .tir.
#[test]
fn a_pure_slip_file_leaves_the_combined_coefficients_unfitted_and_says_so() {
    let mut csv = cornering("fy,mz,kappa,fx", |a, fz| {
        vec![format!("{:.3},{:.4},0,0", fy(a, fz), mz(a, fz))]
    });
    for fz in [2000.0, 4000.0, 6000.0_f64] {
        for i in -40..=40 {
            let k = 0.005 * f64::from(i);
            csv += &format!("{fz},0,0,0,{k:.4},{:.3}\n", fx(k, fz));
        }
    }
    let dir = scratch(&[("pure.csv", &csv)]);
    let o = run_in(
        dir.path(),
        &["identify", "pure.csv", "--model", "mf62", "--out", "p.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("combined Fy  skipped: no combined-slip rows with a measured `fy` (both |κ| and |α| above 1e-3): the rows with longitudinal slip are all at α = 0"),
        "{said}"
    );
    let tir = fs::read_to_string(dir.path().join("p.tir")).unwrap();
    for line in [
        "$ no combined-slip data: the combined longitudinal force (RBX*, RCX1, REX*, RHX1) block is not fitted (no combined-slip rows with a measured `fx` (both |κ| and |α| above 1e-3)): its coefficients are the defaults' (no --template); the written file's longitudinal force does not fall with slip angle",
        "$ no combined-slip data: the combined lateral force (RBY*, RCY1, REY*, RHY*, RVY*) block is not fitted (no combined-slip rows with a measured `fy`",
    ] {
        assert!(tir.contains(line), "{line} not in {tir}");
        assert!(said.contains(&line[2..]), "{line} not said: {said}");
    }
    let value = |key: &str| {
        tir.lines()
            .find(|l| l.split_whitespace().next() == Some(key))
            .and_then(|l| l.split('=').nth(1))
            .map(|v| v.trim().to_string())
            .unwrap()
    };
    assert_eq!(value("RBY1"), "0");
    assert_eq!(value("RBX1"), "0");
}

/// A rig file without an `mz` column: `identify --model mf61` wrote the
/// aligning moment's coefficients at the defaults without a word. The
/// .tir and the terminal say the block is not fitted.
#[test]
fn an_mf61_fit_without_mz_says_the_aligning_moment_is_not_fitted() {
    let csv = cornering("fy", |a, fz| vec![format!("{:.3}", fy(a, fz))]);
    let dir = scratch(&[("fy.csv", &csv)]);
    let o = run_in(
        dir.path(),
        &["identify", "fy.csv", "--model", "mf61", "--out", "f.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let line = "no aligning moment data: the aligning moment block is not fitted (no pure lateral rows with a measured `mz`): its coefficients are the defaults' (no --template)";
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains(&format!("  {line}")), "{said}");
    let tir = fs::read_to_string(dir.path().join("f.tir")).unwrap();
    assert!(tir.contains(&format!("$ {line}")), "{tir}");
}

/// `--hold p3` for UniTire, whose `p3` is `lateral.p3` and
/// `longitudinal.p3`: refused with the list of every name and no hint.
/// Both block-qualified names are offered.
#[test]
fn a_hold_name_without_its_block_is_offered_the_blocks_names() {
    let csv = cornering("fy", |a, fz| vec![format!("{:.3}", fy(a, fz))]);
    let dir = scratch(&[("fy.csv", &csv)]);
    let rig = dir.path().join("fy.csv");
    let out = dir.path().join("u.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "unitire",
        "--hold",
        "p3=1",
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = refused(&o, &out);
    assert!(
        err.contains("--hold `p3`: not a parameter of the unitire model (did you mean `lateral.p3` or `longitudinal.p3`? a parameter is named with its block)"),
        "{err}"
    );
}

/// `--pressure 12` (psi) on a file at 82737 Pa: the request was said as
/// "12 Pa (0.0 kPa)" and the hint as "82737.084 Pa".
#[test]
fn a_pressure_request_in_psi_is_said_with_sensible_digits() {
    let csv = cornering("fy,pressure", |a, fz| {
        vec![format!("{:.3},82737", fy(a, fz))]
    });
    let dir = scratch(&[("p.csv", &csv)]);
    let rig = dir.path().join("p.csv");
    let out = dir.path().join("g.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "gim",
        "--pressure",
        "12",
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = refused(&o, &out);
    assert!(
        err.contains("no pressure level near the requested 12 Pa (0.012 kPa); the value is read in Pa: did you mean 82737 Pa (12 psi), which selects the 82.7 kPa level?"),
        "{err}"
    );
}

/// Two samples per slip-angle bin, 0.05° either side of its centre (up
/// and down sweeps): the `[fitted_ranges]` alpha was the bins' means,
/// ±12° (±0.20944), narrower than the ±12.05° (±0.210313 rad) the
/// samples reach; a linear tyre's, its window's bin means. The ranges
/// the samples cover are written.
#[test]
fn fitted_ranges_are_the_samples_extremes_not_the_bins_means() {
    let csv = cornering("fy", |a, fz| {
        [-0.05_f64, 0.05]
            .iter()
            .map(|d| {
                let a = a + d.to_radians();
                format!("{:.3}", fy(a, fz))
            })
            .collect()
    });
    // The rows' alpha is the bin centre's: rewrite it as each sample's.
    let mut fixed = String::from("fz,alpha,fy\n");
    for (n, line) in csv.lines().skip(1).enumerate() {
        let mut cells = line.split(',');
        let (fz, a, f) = (
            cells.next().unwrap(),
            cells.next().unwrap(),
            cells.next().unwrap(),
        );
        let d = if n % 2 == 0 { -0.05_f64 } else { 0.05 };
        let a: f64 = a.parse::<f64>().unwrap() + d.to_radians();
        fixed += &format!("{fz},{a:.7},{f}\n");
    }
    let dir = scratch(&[("two.csv", &fixed)]);
    let out = dir.path().join("gim.toml");
    let o = identify_to(&dir.path().join("two.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&out).unwrap();
    assert!(file.contains("\nalpha = [-0.210313, 0.210313]\n"), "{file}");
    // The Hoosier file's linear window (|alpha| ≤ 2°, 0.0349066 rad):
    // its bins' means gave [-0.0348928, 0.0348909]. The window keeps the
    // bins whose mean is within it, and their samples reach the outer
    // bin's edge, 2.125° (session 104): those samples were fitted.
    let test = "fitted_ranges_are_the_samples_extremes_not_the_bins_means";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let out = dir.path().join("linear.toml");
    let o = identify_to(&rig, "linear", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&out).unwrap();
    assert!(file.contains("\nalpha = [-0.037085, 0.037085]\n"), "{file}");
}

/// Five samples within ±0.02 rad at one load, fitted by GIM without a
/// word on their coverage. Warned of with the rule: five points per free
/// parameter, and slip angles past 4° for a model with a peak; a full
/// sweep is not warned of.
#[test]
fn five_samples_are_warned_of_as_too_few_and_too_narrow() {
    let mut few = String::from("fz,alpha,fy\n");
    for a in [-0.02, -0.01, 0.0, 0.01, 0.02_f64] {
        few += &format!("3000,{a},{:.3}\n", fy(a, 3000.0));
    }
    let full = cornering("fy", |a, fz| vec![format!("{:.3}", fy(a, fz))]);
    let dir = scratch(&[("few.csv", &few), ("full.csv", &full)]);
    let out = dir.path().join("few.toml");
    let o = identify_to(&dir.path().join("few.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let warning = err
        .lines()
        .find(|l| l.contains("the data are too few or too narrow for the lateral force fit"))
        .unwrap_or_else(|| panic!("no coverage warning: {err}"));
    for part in [
        "warning: the data are too few or too narrow for the lateral force fit: 5 points for 3 free parameters, fewer than the 5 per parameter",
        "|alpha| reaches 0.02 rad (1.15°) only, below the 0.0698 rad (4°) past which a tyre's lateral force peaks",
    ] {
        assert!(warning.contains(part), "{part:?} not in {warning}");
    }
    let file = fs::read_to_string(&out).unwrap();
    assert!(
        file.contains("# warning: the data are too few or too narrow"),
        "{file}"
    );
    let out = dir.path().join("full.toml");
    let o = identify_to(&dir.path().join("full.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !stderr(&o).contains("too few or too narrow"),
        "{}",
        stderr(&o)
    );
}
