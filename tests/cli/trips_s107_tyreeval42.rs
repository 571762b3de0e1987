//! Session 107: `tyre-eval` past
//! a tyre's loads (a loaded radius that rose with the load past FZMAX, and
//! 400 kN on a car tyre evaluated), and a rig CSV saved as `.tir` asked
//! about a missing coefficient. Reference values: MFeval (M. Furlan,
//! BSD-3), its June 2020 C++ build (github.com/OpenTire/Sandbox,
//! `MFeval_to_C++`, commit 718b44c), run outside this repository at
//! useMode 121 and 221, κ = 0, α = 0, γ = 0, 16.7 m/s, the pressure
//! `INFLPRES`.

use super::tyre_eval::{column, eval};
use super::*;
use handling::io::load_tyre;
use handling::io::tir::TirDocument;
use handling::tyre::mf::{MagicFormula, MfInput};
use handling::tyre::Tyre;

/// The public `.tir` files (`shared/data/tir_public`) with a vertical
/// model, read; `None` after saying the test skips where they are absent.
fn public_vertical(test: &str) -> Option<Vec<(String, PathBuf, MagicFormula)>> {
    let readme = shared_data(test, "tir_public/README.md")?;
    let mut files: Vec<PathBuf> = fs::read_dir(readme.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "tir"))
        .collect();
    files.sort();
    let read = files.into_iter().filter_map(|p| match load_tyre(&p) {
        Ok(Tyre::MagicFormula(t)) if t.has_vertical_model() => {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            Some((name, p, *t))
        }
        _ => None,
    });
    Some(read.collect())
}

/// A point at load `fz` rolling straight at 16.7 m/s, at the file's
/// pressure.
fn straight(fz: f64) -> MfInput {
    MfInput {
        fz,
        kappa: 0.0,
        alpha: 0.0,
        camber: 0.0,
        speed: 16.7,
        pressure: None,
    }
}

/// Each public file's loaded radius falls with the load over its own
/// range `FZMIN`–`FZMAX` (from 1 % of `FZMAX` where `FZMIN` is 0), at
/// two speeds and at a slip angle: the tyre deflects more under more load.
/// And the load at which the file's vertical model puts the rim on the
/// road (`tyre-eval`'s bound) is past `FZMAX` on every one of them: no
/// load inside a file's range is refused.
#[test]
fn the_loaded_radius_falls_with_the_load_over_every_public_files_range() {
    let test = "the_loaded_radius_falls_with_the_load_over_every_public_files_range";
    let Some(files) = public_vertical(test) else {
        return;
    };
    assert!(files.len() >= 10, "{}", files.len());
    for (name, path, t) in &files {
        let fz_max = t.limits.fz_max.unwrap();
        let lo = t.limits.fz_min.unwrap_or(0.0).max(0.01 * fz_max);
        for (speed, alpha) in [(16.7, 0.0), (40.0, 0.0), (16.7, 0.05)] {
            let rl: Vec<f64> = (0..=200)
                .map(|k| lo + (fz_max - lo) * f64::from(k) / 200.0)
                .map(|fz| {
                    let q = MfInput {
                        speed,
                        alpha,
                        ..straight(fz)
                    };
                    t.loaded_radius(&q).unwrap()
                })
                .collect();
            for (k, w) in rl.windows(2).enumerate() {
                assert!(
                    w[1] < w[0],
                    "{name} at {speed} m/s, α {alpha}: step {k}: {w:?}"
                );
            }
        }
        let doc = TirDocument::read(path).unwrap();
        let rim = doc.rim(&t.coefficients).unwrap_or_else(|| panic!("{name}"));
        let deflection = rim.deflection(t.coefficients.UNLOADED_RADIUS);
        let at_rim = t.static_load_at(deflection, None).unwrap();
        assert!(
            at_rim > fz_max,
            "{name}: {at_rim} N at the rim, FZMAX {fz_max}"
        );
    }
}

/// Before: `tyre-eval car205_60R19.tir` at 400 kN (FZMAX 10 kN) wrote
/// `rl` = 0.306156 m, above the 0.30443 m at 10 kN, with only the FZMAX
/// warning; with the limit checks off (221) 30 kN wrote `rl` = 0.2298 m,
/// a deflection of 0.12 m past the rim (MFeval: 0.229839 m). Now a load
/// past the one that, by the file's own vertical stiffness, puts the rim
/// (RIM_RADIUS + BOTTOM_OFFST) on the road is refused at its row in every
/// mode, the rim load and the keys said (in 221 the model carries 400 kN
/// at no radius at all, refused as such, as before).
#[test]
fn a_load_that_pushes_the_tyre_onto_its_rim_is_refused_at_its_row_in_every_mode() {
    let Some(tir) = shared_data(
        "a_load_that_pushes_the_tyre_onto_its_rim_is_refused_at_its_row_in_every_mode",
        "tir_public/car205_60R19.tir",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    for (mode, heavy) in [
        (None, "400000"),
        (Some("121"), "30000"),
        (Some("221"), "30000"),
    ] {
        let points = format!(
            "fz,kappa,alpha,camber,speed\n10000,0,0,0,16.7\n20000,0,0,0,16.7\n{heavy},0,0,0,16.7\n"
        );
        let args: Vec<&str> = mode.iter().flat_map(|m| ["--mode", *m]).collect();
        let (o, written) = eval(dir.path(), &tir, &points, &args);
        let e = stderr(&o);
        assert!(!o.status.success(), "{mode:?}: {e}");
        assert!(
            e.contains(&format!("p.csv:4:1: fz = {heavy} N is more than the tyre's vertical model carries: by its own vertical stiffness, standing at this point's pressure, it reaches its rim (RIM_RADIUS + BOTTOM_OFFST = 0.2413 + 0.01 m) under "))
                && e.contains("(a deflection of 0.0987 m from UNLOADED_RADIUS 0.35 m), 2.4")
                && e.contains("× its FZMAX of 10000 N; past it the rim, not the tyre, carries the load")
                && e.contains("so no loaded radius `rl` is physical there (refused in every mode, the limit checks on or off)"),
            "{mode:?}: {e}"
        );
        assert!(
            !e.contains("p.csv:2:") && !e.contains("p.csv:3:"),
            "{mode:?}: {e}"
        );
        assert!(written.is_empty(), "{mode:?}: {written}");
    }
}

/// Before: past FZMAX the loaded radius rose with the load, unsaid
/// (MFeval's: the deflection held at FZMAX, the free radius at the load
/// given). Now said per point count with the first point's `rl` against
/// its `rl` at FZMAX, the numbers still MFeval's; with the limit checks
/// off the tyre deflects by the load given, and nothing is said.
#[test]
fn a_loaded_radius_past_fzmax_is_said_to_hold_the_deflection_there_as_mfeval_does() {
    let Some(tir) = shared_data(
        "a_loaded_radius_past_fzmax_is_said_to_hold_the_deflection_there_as_mfeval_does",
        "tir_public/car205_60R19.tir",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n10000,0,0,0,16.7\n20000,0,0,0,16.7\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("1 of 2 points past FZMAX (10000 N) with the limit checks on: their loaded radius `rl` is MFeval's, the tyre's deflection at FZMAX taken from the free radius at the load given")
            && e.contains("the first at line 3, fz = 20000 N: rl = 0.304457 m, against 0.304431 m at FZMAX"),
        "{e}"
    );
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("(`my` at the load given, and `rl` the free radius at the load given less the deflection at the load held within FZMAX, as MFeval does)"),
        "{said}"
    );
    // MFeval's numbers (useMode 121): 0.304431438446 m, 0.304457416534 m.
    let rl = column(&written, "rl");
    assert!((rl[0] - 0.304431438446).abs() < 1e-6, "{rl:?}");
    assert!((rl[1] - 0.304457416534).abs() < 1e-6, "{rl:?}");
    assert!(rl[1] > rl[0], "{rl:?}");
    // Limit checks off: MFeval's 0.267184123993 m at 20 kN, below.
    let (o, written) = eval(dir.path(), &tir, points, &["--mode", "221"]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(!e.contains("past FZMAX"), "{e}");
    let rl = column(&written, "rl");
    assert!((rl[1] - 0.267184123993).abs() < 1e-6, "{rl:?}");
}

/// Before: `cp cornering.csv rig.tir; handling tyre-eval rig.tir
/// points.csv` asked about a missing PCX1, as of a `.tir` with a slip.
/// Now the file is named a tyre rig file with its columns, the command
/// that reads it (`identify`), and what `tyre-eval` takes.
#[test]
fn a_rig_csv_saved_as_tir_is_named_rig_data_that_identify_reads() {
    let Some(rig) = shared_data(
        "a_rig_csv_saved_as_tir_is_named_rig_data_that_identify_reads",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let dir = scratch(&[(
        "points.csv",
        "fz,kappa,alpha,camber,speed\n1000,0,0.05,0,11\n",
    )]);
    fs::copy(&rig, dir.path().join("rig.tir")).unwrap();
    let o = run_in(
        dir.path(),
        &["tyre-eval", "rig.tir", "points.csv", "--out", "f.csv"],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("this is a tyre rig file (columns t, fz, alpha, camber, fy, mz, pressure, speed), not a tyre file (a .tir, or a TOML file with `model = \"…\"`")
            && e.contains("`handling identify` reads it (fits a tyre to it)"),
        "{e}"
    );
    assert!(!e.contains("PCX1") && !e.contains("missing"), "{e}");
    // Named as a vehicle's tyre the same: the .tir reader names it.
    let scenario = format!("{VEHICLE}[tyres]\nfront = \"rig.tir\"\nrear = \"rig.tir\"\n{STEP}");
    fs::write(dir.path().join("s.toml"), scenario).unwrap();
    let o = run_in(dir.path(), &["simulate", "s.toml"]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(e.contains("tyre rig file") && !e.contains("PCX1"), "{e}");
}

/// Before: a points CSV saved as `.tir` and given first was read as a
/// `.tir` and refused for a missing coefficient. Now it is refused as the
/// arguments' order, as a `.csv` name is.
#[test]
fn a_points_csv_saved_as_tir_given_first_is_refused_as_the_order() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    let dir = scratch(&[("p.tir", points), ("q.csv", points)]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "p.tir", "q.csv", "--out", "f.csv"],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("it looks like a points CSV; the order is `tyre-eval <tyre> <points>`"),
        "{e}"
    );
    assert!(!e.contains("missing"), "{e}");
}
