//! What a fresh user still tripped on in `identify` and `tyre-eval`
//! (session 88): slip angles in degrees inside ±90° fitted by every model
//! into a tyre 57 times too soft, measured forces of a points file
//! overwritten by `tyre-eval`, a tyre file written under `--out x.csv`,
//! pure longitudinal rows called "rows of combined Fy", a linear fit's
//! figure without its aligning-moment panel, and wording.

use super::*;

/// Rig rows of a Magic-Formula-like tyre (`Cα/Fz` 15 1/rad less a
/// load's share, peak `mu`·fz) at three loads, `alpha` to ±`reach` as
/// written in steps of `step`, read as degrees when `degrees`.
fn rig_rows(degrees: bool, mu: f64, reach: f64, step: f64) -> String {
    let mut s = String::from("fz,alpha,fy,mz\n");
    let n = (reach / step).round() as i32;
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in -n..=n {
            let written = f64::from(i) * step;
            let alpha = if degrees {
                written.to_radians()
            } else {
                written
            };
            let c = 15.0 * fz * (1.0 - fz / 20000.0);
            let fy = fz * mu * (1.4 * (c / (mu * 1.4 * fz) * alpha).atan()).sin();
            s += &format!("{fz},{written:.4},{fy:.3},{:.3}\n", 0.03 * fy);
        }
    }
    s
}

/// Slip angles written in degrees to ±1.5 (86° read as radians, inside
/// the reader's ±90°) were fitted by pac89 into a tyre of 0.26 N/rad per
/// N of load, written without a word (gim's refusal blamed its own
/// parameter in N/deg): now every model is refused by the rig reader at
/// the largest |alpha|, file:line:column, with the slope read both ways.
#[test]
fn slip_angles_in_degrees_inside_90_degrees_are_refused_for_every_model() {
    let dir = scratch(&[("deg.csv", &rig_rows(true, 1.2, 1.5, 0.05))]);
    for (model, ext) in [("pac89", "toml"), ("gim", "toml"), ("mf61", "tir")] {
        let out = dir.path().join(format!("fit_{model}.{ext}"));
        let o = identify_to(&dir.path().join("deg.csv"), model, &out);
        let e = refused(&o, &out);
        assert!(
            e.contains("deg.csv:184:2: column `alpha`: 1.5 here, the sweep's largest |alpha|, is 86° read in radians, beyond the ±0.35 rad (20°) a rig sweeps, and read in radians the slope of fy/fz against alpha over its 183 samples with |alpha| ≤ 2 is 0.206 1/rad (N/rad per N of load), below any tyre's 1.5 (a car tyre's is about 5–45); read in degrees the slope is 11.8 1/rad, a tyre's: angles are in radians (FORMATS.md); is the column in degrees? Convert it (multiply by 0.01745)"),
            "{model}: {e}"
        );
    }
}

/// The rule's other side: an ice tyre in radians (peak 0.3·fz) swept far
/// past its peak (to ±0.6 rad, beyond any rig's 20°; its slope over the
/// sweep, 0.7 1/rad, reads as a tyre's in degrees) is no column in
/// degrees, as its slope within 2° of zero slip is a tyre's.
#[test]
fn a_sweep_in_radians_far_past_its_peak_is_not_taken_for_degrees() {
    let dir = scratch(&[("rad.csv", &rig_rows(false, 0.3, 0.6, 0.005))]);
    let out = dir.path().join("fit.toml");
    let o = identify_to(&dir.path().join("rad.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A points file carrying measured `fy` and `mz` came out with both
/// replaced by the model's values under the same names, without a word:
/// now the measured columns are kept under their names, the model's
/// written as `fx_model`, `fy_model`, `mz_model`, and each measured
/// channel compared with the model's.
#[test]
fn tyre_eval_keeps_measured_columns_and_compares_the_model_with_them() {
    let points = "fz,kappa,alpha,camber,speed,fy,mz\n\
                  4000,0,0.02,0,20,1100,30\n\
                  4000,0,0.05,0,20,2500,50\n\
                  4000,0,-0.05,0,20,-2500,-50\n";
    let dir = scratch(&[("pts.csv", points)]);
    let tyre = root().join("tyres/unitire.toml");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "pts.csv",
            "--out",
            "o.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    for line in [
        "the points file's measured `fy`, `mz` kept under their names; the model's outputs written as `fx_model`, `fy_model`, `mz_model`",
        "`fy` model − measured over 3 points: mean -20.69 N, RMS 41.18 N (1.93 % of the measured RMS 2138 N), largest -62.07 N at line 2",
        "`mz` model − measured over 3 points: mean 3.554 N·m, RMS 10.47 N·m (23.6 % of the measured RMS 44.35 N·m), largest 10.66 N·m at line 2",
    ] {
        assert!(said.contains(line), "{line}\n{said}");
    }
    let out = fs::read_to_string(dir.path().join("o.csv")).unwrap();
    let mut rows = out.lines();
    assert_eq!(
        rows.next(),
        Some("fz,kappa,alpha,camber,speed,fy,mz,fx_model,fy_model,mz_model")
    );
    assert!(rows
        .next()
        .unwrap()
        .starts_with("4000,0,0.02,0,20,1100,30,0,1037.92"));
}

/// `identify --out fit.csv` wrote a TOML tyre file under `.csv`, which
/// `tyre-eval` then refused as a CSV: refused before any fit, naming the
/// flag, its value and the name to give.
#[test]
fn identify_refuses_an_out_extension_other_than_its_format() {
    let dir = scratch(&[("rad.csv", &rig_rows(false, 1.2, 0.1, 0.005))]);
    let out = dir.path().join("fit.csv");
    let o = identify_to(&dir.path().join("rad.csv"), "linear", &out);
    let e = refused(&o, &out);
    let at = out.display();
    let named = dir.path().join("fit.toml");
    assert!(
        e.contains(&format!("{at}: the linear model is written as a .toml file, not .csv (`--out {at}` names the tyre file; a .toml text under this name would not read back as a .csv): name it {}", named.display())),
        "{e}"
    );
}

/// Exact MF 6.1 pure sweeps (slip angle at κ = 0, slip ratio at α = 0)
/// fitted back by mf61: the pooled line called the pure longitudinal rows
/// of `fy` "rows of combined Fy"; now they are named by their slip, with
/// the stage that would take them.
#[test]
fn left_out_rows_are_named_by_their_slip_content() {
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
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "pts.csv",
            "--out",
            "ev.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run_in(
        dir.path(),
        &["identify", "ev.csv", "--model", "mf61", "--out", "fit.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("120 samples left out (rows of pure longitudinal slip (α = 0), the combined Fy stage's, not fitted); mz "),
        "{said}"
    );
    assert!(
        said.contains("180 samples left out (rows of pure lateral slip (κ = 0), which no stage of the channel takes); fy "),
        "{said}"
    );
    assert!(!said.contains("rows of combined"), "{said}");
}

/// The height of the PNG `path` (its IHDR), px.
fn png_height(path: &Path) -> u32 {
    let png = fs::read(path).unwrap();
    u32::from_be_bytes(png[20..24].try_into().unwrap())
}

/// A `--model linear` fit's figure had no aligning-moment panel though
/// its trail is fitted to `mz`: the file with `mz` now draws two rows of
/// panels (Fy, Mz), the same file without `mz` one.
#[test]
fn a_linear_fit_figure_has_an_mz_panel_when_the_trail_is_fitted() {
    let with = rig_rows(false, 1.2, 0.03, 0.002);
    let without: String = with
        .lines()
        .map(|l| l.rsplit_once(',').unwrap().0.to_string() + "\n")
        .collect();
    let dir = scratch(&[("with.csv", &with), ("without.csv", &without)]);
    let height = |name: &str| {
        let out = dir.path().join(format!("{name}.toml"));
        let o = identify_to(&dir.path().join(format!("{name}.csv")), "linear", &out);
        assert!(o.status.success(), "{}", stderr(&o));
        png_height(&dir.path().join(format!("{name}.png")))
    };
    let (one, two) = (height("without"), height("with"));
    assert_eq!(two, 2 * one, "{one} px without mz, {two} px with");
}
