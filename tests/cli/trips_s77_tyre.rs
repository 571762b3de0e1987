//! What a fresh user tripped on in `.tir` files, `tyre-eval` and
//! `identify` (a fresh user's fourth round), run as a user runs the tool: a public
//! `.tir` whose longitudinal slip stiffness turns negative inside its own
//! load range, said only per point; a Magic Formula fit outside any
//! tyre's cornering stiffness written without a word (and then refused by
//! every reader); pressures in two units (2.2 bar and 220 kPa) said with
//! one unit; and a template's `NOMPRES` far from the data's pressures,
//! which put the peak friction into the pressure terms.

use super::*;

/// `FSAE_Defaults.tir` (`PKX1 = 50`, `PKX2 = −80`, `FNOMIN = 1000 N`,
/// `FZMAX = 2000 N`): its `Kxκ` turns negative from 1625 N. Said when the
/// file is read, at its lines, whatever loads the points evaluate (here
/// one point at 1000 N, where the stiffness is still positive and no
/// per-point check fires); every other public `.tir` is read without it.
#[test]
fn a_tir_whose_longitudinal_stiffness_turns_negative_in_its_range_is_said_when_read() {
    let test = "a_tir_whose_longitudinal_stiffness_turns_negative_in_its_range_is_said_when_read";
    let Some(fsae) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let dir = scratch(&[(
        "p.csv",
        "fz,kappa,alpha,camber,speed\n1000,0.05,0.02,0,15\n",
    )]);
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            fsae.to_str().unwrap(),
            "p.csv",
            "--out",
            "o.csv",
        ],
    );
    assert!(o.status.success(), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    let text = fs::read_to_string(&fsae).unwrap();
    let line_of = |key: &str| {
        1 + text
            .lines()
            .position(|l| l.split_whitespace().next() == Some(key))
            .unwrap()
    };
    let (pkx1, pkx2, fzmax) = (line_of("PKX1"), line_of("PKX2"), line_of("FZMAX"));
    let warning = err
        .lines()
        .find(|l| l.contains("longitudinal slip stiffness Kxκ"))
        .unwrap_or_else(|| panic!("no warning of Kxκ at read: {err}"));
    for part in [
        format!("FSAE_Defaults.tir:{pkx1}:"),
        format!("PKX1 = 50 at line {pkx1}"),
        format!("PKX2 = -80 at line {pkx2}"),
        "turns negative from Fz = 1625 N".into(),
        format!("FZMAX = 2000 N (line {fzmax}) lies beyond it"),
    ] {
        assert!(warning.contains(&part), "{part:?} not in {warning}");
    }
    // Every public .tir is still read, and only this one says it.
    let Some(folder) = shared_data(test, "tir_public/README.md") else {
        return;
    };
    let mut read = 0;
    for entry in fs::read_dir(folder.parent().unwrap()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("tir") {
            continue;
        }
        let o = run_in(
            dir.path(),
            &[
                "tyre-eval",
                path.to_str().unwrap(),
                "p.csv",
                "--out",
                "all.csv",
            ],
        );
        assert!(o.status.success(), "{}: {o:?}", path.display());
        let said = String::from_utf8_lossy(&o.stderr).contains("Kxκ");
        assert_eq!(said, path == fsae, "{}: {o:?}", path.display());
        read += 1;
    }
    assert_eq!(read, 13);
}

/// A lateral force whose slope at zero slip is 1.0·Fz per rad (below any
/// tyre's 1.5, which every reader refuses): `identify --model mf61` fits
/// it closely and used to write the file without a word. It now says so
/// at fit time, with the readers' numbers, and still writes it.
#[test]
fn a_magic_formula_fit_outside_any_tyres_cornering_stiffness_is_said_when_written() {
    let mut csv = String::from("fz,alpha,camber,fy\n");
    for fz in [1000.0, 2000.0, 3000.0_f64] {
        for i in -60..=60 {
            let a = f64::from(i) * 0.005;
            let (b, c) = (1.0 / 1.3, 1.3);
            csv += &format!("{fz},{a},0,{}\n", fz * (c * (b * a).atan()).sin());
        }
    }
    let dir = scratch(&[("low.csv", &csv)]);
    let o = run_in(
        dir.path(),
        &["identify", "low.csv", "--model", "mf61", "--out", "low.tir"],
    );
    assert!(o.status.success(), "{o:?}");
    let said = String::from_utf8_lossy(&o.stderr).to_string() + &String::from_utf8_lossy(&o.stdout);
    let warning = said
        .lines()
        .find(|l| l.contains("warning: the fitted `PKY1`"))
        .unwrap_or_else(|| panic!("no warning of the stiffness: {said}"));
    assert!(
        warning.contains("1 N/rad per N of load") && warning.contains("below any tyre's 1.5"),
        "{warning}"
    );
    assert!(
        warning.contains("tyre-eval and simulate refuse it"),
        "{warning}"
    );
    // Written, and refused on reading with the same numbers.
    let tir = fs::read_to_string(dir.path().join("low.tir")).unwrap();
    assert!(tir.contains("$ warning: the fitted `PKY1`"), "{tir}");
    fs::write(
        dir.path().join("p.csv"),
        "fz,kappa,alpha,camber,speed\n2000,0,0.05,0,16.7\n",
    )
    .unwrap();
    let o = run_in(
        dir.path(),
        &["tyre-eval", "low.tir", "p.csv", "--out", "o.csv"],
    );
    assert!(!o.status.success(), "{o:?}");
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("1 N/rad per N of load"),
        "{o:?}"
    );
}

/// Pressures of 2.2 and 220 beside each other (bar and kPa slipped) were
/// refused by the column's median (220) at the first cell, with the
/// column said in kPa: 2.2 kPa is no tyre's. Each cell is said with its
/// own unit.
#[test]
fn pressures_in_two_units_are_each_said_in_their_own() {
    let test = "pressures_in_two_units_are_each_said_in_their_own";
    let Some(tir) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let points = "fz,kappa,alpha,camber,speed,pressure\n\
                  1000,0,0.05,0,16.7,2.2\n\
                  1000,0,0.05,0,16.7,220\n";
    let dir = scratch(&[("p.csv", points)]);
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "p.csv",
            "--out",
            "o.csv",
        ],
    );
    assert!(!o.status.success(), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    let cell = |at: &str| {
        err.lines()
            .find(|l| l.contains(at))
            .unwrap_or_else(|| panic!("{at} not named: {err}"))
            .to_string()
    };
    assert!(cell("p.csv:2:6").contains("220000 Pa (2.2 bar)"), "{err}");
    assert!(cell("p.csv:3:6").contains("220000 Pa (220 kPa)"), "{err}");
    // One unit for the whole column is still said once, by its median.
    let points = "fz,kappa,alpha,camber,speed,pressure\n\
                  1000,0,0.05,0,16.7,83\n\
                  1000,0,0.05,0,16.7,85\n";
    fs::write(dir.path().join("q.csv"), points).unwrap();
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "q.csv",
            "--out",
            "o.csv",
        ],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("is the column in kPa?"), "{err}");
    assert!(!err.contains("q.csv:3:6"), "{err}");
}
