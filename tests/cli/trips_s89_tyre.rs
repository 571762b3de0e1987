//! What a fresh user tripped on (round 15), in `tyre-eval`, in `identify`'s
//! reading of a rig file and in `diagnose`'s gap map: a right-side `.tir`
//! mirrored without a word, a camber in degrees read as radians, a units
//! row quoted without its first cell, run dots drawn like the verdict's.

use super::*;

/// A right-side `.tir` (`TYRESIDE = 'RIGHT'`, MFeval's public MF 6.1 file)
/// is evaluated mirrored into a left tyre. A tester who evaluated the
/// file's equations by hand got −158.0 N at zero slip where `tyre-eval`
/// wrote +158.0 N, and nothing said why. The closing line says it now, with
/// what the mirroring is — checked here against the same file made
/// left-side: `fy`, `mz`, `mx` of the right file at (α, γ) are the left
/// file's at (−α, −γ), negated — and that MFeval applies no `TYRESIDE`;
/// the left file's line says nothing of it.
#[test]
fn a_right_side_tir_says_on_its_closing_line_that_it_is_mirrored() {
    let right = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    assert_eq!(right.matches("'RIGHT'").count(), 1);
    let left = right.replace("'RIGHT'", "'LEFT'");
    let dir = scratch(&[
        ("right.tir", &right),
        ("left.tir", &left),
        (
            "p.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0,0,16.7\n4000,0.02,0.05,0.03,16.7\n",
        ),
        (
            "m.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0,0,16.7\n4000,0.02,-0.05,-0.03,16.7\n",
        ),
    ]);
    let said = "; the file's TYRESIDE is 'RIGHT': evaluated mirrored into a left tyre, as every tyre here (its equations at −alpha and −camber, with fy, mz and mx negated; MFeval applies no TYRESIDE); wrote ";
    let mut outs = Vec::new();
    for (tir, points, mirrored) in [("right.tir", "p.csv", true), ("left.tir", "m.csv", false)] {
        let out = dir.path().join(format!("{tir}.csv"));
        let o = run_in(
            dir.path(),
            &["tyre-eval", tir, points, "--out", out.to_str().unwrap()],
        );
        assert!(o.status.success(), "{}", stderr(&o));
        let said_out = String::from_utf8_lossy(&o.stdout).into_owned();
        assert_eq!(said_out.contains(said), mirrored, "{tir}: {said_out}");
        assert!(!stderr(&o).contains("TYRESIDE"), "{}", stderr(&o));
        outs.push(numeric_csv(&out));
    }
    let ((head, r), (_, l)) = (&outs[0], &outs[1]);
    // At zero slip (the first point) the right file's fy is the opposite
    // of the left's, not zero: what the tester's hand value showed.
    assert!(r[0][column(head, "fy")].abs() > 10.0, "{:?}", r[0]);
    for (name, sign) in [
        ("fx", 1.0),
        ("fy", -1.0),
        ("mz", -1.0),
        ("mx", -1.0),
        ("my", 1.0),
    ] {
        let c = column(head, name);
        for (a, b) in r.iter().zip(l) {
            assert!(
                (a[c] - sign * b[c]).abs() <= 1e-9 * b[c].abs().max(1.0),
                "{name}: right {} left {}",
                a[c],
                b[c]
            );
        }
    }
}

/// A camber of 0.5 in a points file (0.5° meant) read as 0.5 rad = 28.6°:
/// within ±45°, so no degrees question was asked, and a Magic Formula
/// file then held it to its `CAMMAX` with a range warning (no word of
/// the unit). A column whose every camber other than 0 is steeper than
/// 20° (no car tyre's, in radians) is asked as degrees now, each such cell
/// at its file, line and column with its value; a column with a car's
/// camber (0.1 rad) beside a steep one is in radians, and evaluated.
#[test]
fn a_camber_column_in_degrees_within_45_radians_is_asked_as_degrees() {
    let dir = scratch(&[
        (
            "deg.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n4000,0,0.05,0.5,20\n4000,0,0.05,-0.4,20\n",
        ),
        (
            "rad.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0.05,0.1,20\n4000,0,0.05,0.5,20\n",
        ),
    ]);
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let out = dir.path().join("f.csv");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "deg.csv",
            "--out",
            "f.csv",
        ],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    for (cell, value) in [
        ("deg.csv:3:4", "0.5 rad (28.6°)"),
        ("deg.csv:4:4", "-0.4 rad (-22.9°)"),
    ] {
        assert!(
            e.contains(&format!("{cell}: column `camber`: {value} is beyond ±20° (0.349 rad), as every camber of the column other than 0 is")),
            "{e}"
        );
    }
    assert!(!out.exists());
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "rad.csv",
            "--out",
            "f.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.exists());
}

/// A rig file's units row `s,N,rad,rad,N,Nm,Pa,m/s` was quoted as
/// `N, rad, rad, N, Nm, Pa, m/s`: without its first cell, under the time
/// column `identify` does not read. The row is quoted whole, as the file
/// has it.
#[test]
fn a_rig_files_units_row_is_quoted_with_its_first_cell() {
    let mut rig = String::from("t,fz,alpha,camber,fy,mz,pressure,speed\ns,N,rad,rad,N,Nm,Pa,m/s\n");
    for i in 0..40 {
        let alpha = (i as f64 - 20.0) * 0.005;
        rig.push_str(&format!(
            "{},4000,{alpha},0,{},{},83000,11.2\n",
            i as f64 * 0.01,
            4000.0 * 20.0 * alpha,
            40.0 * 20.0 * alpha
        ));
    }
    let dir = scratch(&[("rig.csv", &rig)]);
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "linear", "--out", "t.toml",
        ],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("rig.csv:2:2: column `fz`: no cell of this row is a number (`s, N, rad, rad, N, Nm, Pa, m/s`): a row of units under the header?"),
        "{e}"
    );
}

/// The gap map's small dots (each run's share, base model) had no key and
/// looked like the verdict's discs. Each channel's are keyed now, in every
/// panel (report.html's drawing of `gap_map.png`).
#[test]
fn the_gap_maps_run_dots_have_a_key_of_their_own() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let out = dir.path().join("d");
    diagnose_to(&c, &out);
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    // The key wraps a long entry over lines: the drawn texts, joined.
    let texts: Vec<&str> = page
        .split('>')
        .filter_map(|t| t.split('<').next())
        .map(str::trim)
        .filter(|t| !t.is_empty())
        .collect();
    let page = texts.join(" ");
    for ch in ["yaw rate r", "lateral acceleration a_y", "sideslip β"] {
        let key = format!("{ch}, each run, base model");
        assert_eq!(page.matches(&key).count(), 3, "{key}");
    }
}
