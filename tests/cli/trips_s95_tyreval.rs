//! What a fresh user tripped on in `tyre-eval` and the rig reader
//! (session 95, round 25's findings 3, 7, 8, 9 and a repeated header):
//! a warning that a tyre does not respond to its camber beside one that
//! extrapolates it, a "range" that is one level's noise said as a share
//! of its span, a `.tir` whose shape factor makes its force constant or
//! whose rolling resistance is 1e5 times a tyre's taken without a word, a
//! rig camber column in degrees fitted as radians, a logger's second
//! header refused as cells that are not numbers, and a `.tir` without
//! pressure terms given a pressure column without a word.

use super::*;
use std::fs;

/// The bundled `tyres/<name>` with `table` appended (a `[fitted_ranges]`).
fn with_ranges(name: &str, table: &str) -> String {
    let text = fs::read_to_string(root().join("tyres").join(name)).unwrap();
    format!("{text}\n[fitted_ranges]\n{table}")
}

/// The fixture `tests/fixtures/tir/<name>` with each `(key, value)`'s line
/// written anew (`None`: the line dropped).
fn edited_tir(name: &str, edits: &[(&str, Option<&str>)]) -> String {
    let text = fs::read_to_string(root().join("tests/fixtures/tir").join(name)).unwrap();
    let edit = |l: &str| {
        let key = l.split(['=', ' ']).next().unwrap_or("");
        match edits.iter().find(|(k, _)| *k == key) {
            Some((k, Some(v))) => Some(format!("{k} = {v}")),
            Some((_, None)) => None,
            None => Some(l.to_string()),
        }
    };
    let lines: Vec<String> = text.lines().filter_map(edit).collect();
    lines.join("\n") + "\n"
}

/// `tyre-eval tyre points --out out.csv` in `dir`: the output and stderr.
fn evaluated(dir: &Path, tyre: &str, points: &str) -> (Output, String) {
    let o = run_in(dir, &["tyre-eval", tyre, points, "--out", "out.csv"]);
    let e = stderr(&o);
    (o, e)
}

/// A column of the output CSV, by name.
fn output_column(dir: &Path, name: &str) -> Vec<f64> {
    let (head, rows) = numeric_csv(&dir.join("out.csv"));
    let i = column(&head, name);
    rows.iter().map(|r| r[i]).collect()
}

/// Finding 9: a Gim tyre fitted at one camber and one pressure level
/// (both ranges the rig's noise about them) is evaluated at a camber and
/// a pressure it does not read: the words say it does not respond, and no
/// extrapolation past a range it ignores ("4117 % of the range's span").
#[test]
fn an_input_the_tyre_does_not_read_is_not_said_as_extrapolated() {
    let table = "fz = [1503.0, 1795.0]\nalpha = [-0.169646, 0.169367]\ncamber = [-0.00036, 0.00036]\npressure = [82160.0, 84630.0]\n";
    let points = "fz,kappa,alpha,camber,speed,pressure\n1640,0,0.05,0,11,83000\n1640,0,0.05,0.03,11,97000\n1640,0,-0.05,0,11,83000\n";
    let dir = scratch(&[
        ("gim.toml", &with_ranges("gim.toml", table)),
        ("p.csv", points),
    ]);
    let (o, e) = evaluated(dir.path(), "gim.toml", "p.csv");
    assert!(o.status.success(), "{e}");
    assert!(e.contains("does not respond to `camber`"), "{e}");
    assert!(e.contains("does not respond to `pressure`"), "{e}");
    assert!(!e.contains("rig data's camber"), "{e}");
    assert!(!e.contains("rig data's pressure"), "{e}");
    // The tyre does not read them: its fy at camber 0.03 and 97 kPa is its
    // fy at camber 0 and 83 kPa (same load and slip angle).
    let fy = output_column(dir.path(), "fy");
    assert_eq!(fy[0], fy[1]);
    assert!(fy[0] > 0.0 && fy[2] == -fy[0], "{fy:?}");
}

/// Finding 9: a PAC89 tyre whose aligning moment reads the camber, fitted
/// at one camber level (−0.00036 to 0.00045 rad, the rig's spread about
/// 0): a point at 0.05 rad is said past that one level by 0.05 − 0.00045
/// = 0.04955 rad, not as "6117 %" of a span that is noise; a fitted load
/// range (a sweep) keeps its share of the span: 9000 N past 2000–6000 N
/// is 75 %.
#[test]
fn a_range_of_one_level_is_said_by_its_distance_not_a_share_of_its_noise() {
    let table = "fz = [2000.0, 6000.0]\ncamber = [-0.00036, 0.00045]\n";
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n4000,0,0.05,0.05,20\n9000,0,0.05,0,20\n";
    let dir = scratch(&[
        ("pac.toml", &with_ranges("pac89_adams_example.toml", table)),
        ("p.csv", points),
    ]);
    let (o, e) = evaluated(dir.path(), "pac.toml", "p.csv");
    assert!(o.status.success(), "{e}");
    let camber = e
        .lines()
        .find(|l| l.contains("rig data's camber"))
        .unwrap_or_else(|| panic!("{e}"));
    assert!(camber.contains("one level at 4.5e-5 rad"), "{camber}");
    assert!(
        camber.contains("0.04955 rad past the range's end"),
        "{camber}"
    );
    assert!(!camber.contains('%'), "{camber}");
    assert!(
        e.contains("the farthest at 9000 N, 75.0 % of the range's span past its end"),
        "{e}"
    );
    // The camber is read: the aligning moment moves with it.
    let mz = output_column(dir.path(), "mz");
    assert!((mz[1] - mz[0]).abs() > 1e-3 * mz[0].abs(), "{mz:?}");
}

/// Finding 8: a `.tir` with `PCY1 = 0` (and one with `LCY = 0`) gives the
/// shifts' force at every slip angle, C = 0 in `sin(C·atan(B·α))`: refused
/// at the key that zeroes C, as a shape factor above 2 is; the file as
/// published is read.
#[test]
fn a_tir_shape_factor_of_zero_is_refused_at_its_key() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,-0.1,0,20\n4000,0,0.1,0,20\n";
    for key in ["PCY1", "LCY"] {
        let tir = edited_tir("MagicFormula61_Parameters.tir", &[(key, Some("0"))]);
        let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
        let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
        assert!(!o.status.success(), "{key}: {e}");
        let line = e
            .lines()
            .find(|l| l.contains(&format!("`{key}`")))
            .unwrap_or_else(|| panic!("{key}: {e}"));
        assert!(line.contains("the same at every slip angle"), "{line}");
        assert!(line.contains("C = PCY1·LCY = 0 "), "{line}");
        assert!(!dir.path().join("out.csv").exists());
    }
    let tir = edited_tir("MagicFormula61_Parameters.tir", &[]);
    let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
    let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
    assert!(o.status.success(), "{e}");
    let fy = output_column(dir.path(), "fy");
    assert!(fy[1] - fy[0] > 0.5 * 4000.0, "{fy:?}");
}

/// Finding 8: `QSY1 = 1e5` (for 0.01) makes `my` 1e7 times a tyre's: the
/// rolling resistance moment over R0·Fz is said above a tenth, with the
/// constant term named and the first point's `my` as written; at the
/// published 0.01 nothing is said.
#[test]
fn a_rolling_resistance_beyond_any_tyres_is_said_with_its_constant_term() {
    let points = "fz,kappa,alpha,camber,speed\n2000,0,0,0,20\n4000,0,0.02,0,20\n";
    let tir = edited_tir("MagicFormula61_Parameters.tir", &[("QSY1", Some("1e5"))]);
    let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
    let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
    assert!(o.status.success(), "{e}");
    let line = e
        .lines()
        .find(|l| l.contains("rolling resistance moment `my` above 0.1 of R0·Fz"))
        .unwrap_or_else(|| panic!("{e}"));
    assert!(line.starts_with("warning: 2 of 2 points"), "{line}");
    assert!(
        line.contains("QSY1·LMY = 1e5") || line.contains("QSY1·LMY = 100000"),
        "{line}"
    );
    let my = output_column(dir.path(), "my");
    // −Fz0·R0·QSY1·(Fz/Fz0)^QSY7 (TNO eq. A48, at INFLPRES = NOMPRES; the
    // other terms ~1e-2 of 1e5): at 2000 N, R0 = 0.3943 m, Fz0 = FNOMIN =
    // 6752 N, QSY7 = 0.85.
    let closed = -6752.0 * 0.3943 * 1e5 * (2000.0_f64 / 6752.0).powf(0.85);
    assert!(
        (my[0] / closed - 1.0).abs() < 1e-4,
        "{} against {closed}",
        my[0]
    );
    // The first point's `my` as the line writes it is the output's.
    let said: f64 = line
        .split("my = ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!((said / my[0] - 1.0).abs() < 1e-3, "{line} / {}", my[0]);
    let tir = edited_tir("MagicFormula61_Parameters.tir", &[]);
    let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
    let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
    assert!(
        o.status.success() && !e.contains("rolling resistance moment `my` above"),
        "{e}"
    );
}

/// A rig file of a tanh lateral curve (μ 1, 15 1/rad at the origin) at
/// 2000 and 4000 N, at each camber of `cambers`, under `header`.
fn rig(cambers: &[f64]) -> String {
    let mut csv = String::from("fz,alpha,fy,camber\n");
    for fz in [2000.0, 4000.0] {
        for g in cambers {
            for i in -20..=20 {
                let a = 0.01 * f64::from(i);
                let fy = fz * (15.0 * a).tanh();
                csv.push_str(&format!("{fz},{a},{fy},{g}\n"));
            }
        }
    }
    csv
}

/// Finding 7: a rig camber column of 0 and 0.5 (meant as degrees: 28.6°
/// in radians) is asked about, cell by cell, as `tyre-eval` asks it; 0
/// and 0.05 rad (2.9°) is read.
#[test]
fn identify_asks_a_camber_column_steeper_than_20_degrees_whether_it_is_in_degrees() {
    let dir = scratch(&[
        ("deg.csv", &rig(&[0.0, 0.5])),
        ("rad.csv", &rig(&[0.0, 0.05])),
    ]);
    let args = |rig: &'static str| {
        [
            "identify", rig, "--model", "gim", "--camber", "0", "--out", "o.toml",
        ]
    };
    let o = run_in(dir.path(), &args("deg.csv"));
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("deg.csv:43:4: column `camber`: 0.5 rad (28.6°) is beyond ±20° (0.349 rad), as every camber of the column other than 0 is, where no car tyre is tested alone (no public .tir's camber range passes 15.1°); a column with a camber within ±20° is read in radians, refused only beyond ±45° (0.785 rad): angles are in radians (FORMATS.md); is the column in degrees? (the first of 82 places refused alike)"),
        "{e}"
    );
    assert!(!dir.path().join("o.toml").exists());
    let o = run_in(dir.path(), &args("rad.csv"));
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The minor item: a logger's header repeated mid-file is said once, as
/// a header again at its line, not as three cells that are not numbers.
#[test]
fn a_header_repeated_mid_file_is_said_as_a_second_header() {
    let text = rig(&[0.0]);
    let mut lines: Vec<&str> = text.lines().collect();
    lines.insert(30, "fz,alpha,fy,camber");
    let dir = scratch(&[("r.csv", &(lines.join("\n") + "\n"))]);
    let o = run_in(
        dir.path(),
        &["identify", "r.csv", "--model", "gim", "--out", "o.toml"],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("r.csv:31:1: column `fz`: this row repeats the header of line 1 (`fz, alpha, fy, camber`): a second header mid-file"),
        "{e}"
    );
    assert!(!e.contains("is not a number"), "{e}");
}

/// Finding 3's `tyre-eval` half: a `.tir` that does not respond to the
/// pressure (a 5.2 file; a 6.1 file without `NOMPRES`) given a pressure
/// column says so with why, as a TOML tyre does; the 6.1 file with its
/// `NOMPRES` reads it (fy moves from 220 to 300 kPa) and says nothing.
#[test]
fn a_tir_without_pressure_terms_says_it_ignores_the_pressure_column() {
    let points =
        "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,220000\n4000,0,0.05,0,20,300000\n";
    let cases = [
        (
            edited_tir("MagicFormula52_Parameters.tir", &[]),
            "a Magic Formula 5.2 file has no pressure terms",
        ),
        (
            edited_tir("MagicFormula61_Parameters.tir", &[("NOMPRES", None)]),
            "the file has no NOMPRES",
        ),
    ];
    for (tir, why) in cases {
        let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
        let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
        assert!(o.status.success(), "{e}");
        assert!(
            e.contains("does not respond to `pressure`: its forces and moments are the same at any value (the pressure given at 2 points ignored); "),
            "{e}"
        );
        assert!(e.contains(why), "{e}");
        let fy = output_column(dir.path(), "fy");
        assert_eq!(fy[0], fy[1]);
    }
    let tir = edited_tir("MagicFormula61_Parameters.tir", &[]);
    let dir = scratch(&[("t.tir", &tir), ("p.csv", points)]);
    let (o, e) = evaluated(dir.path(), "t.tir", "p.csv");
    assert!(o.status.success() && !e.contains("`pressure`"), "{e}");
    let fy = output_column(dir.path(), "fy");
    assert!((fy[1] - fy[0]).abs() > 1.0, "{fy:?}");
}
