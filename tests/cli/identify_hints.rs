//! The hint of a level request no level lies near (`identify --load`,
//! `--camber`, `--pressure`, which take N, rad and Pa): a value written in
//! kN, degrees, kPa, bar or psi is answered with its conversion, which
//! then selects the level the hint names; a value no unit slip explains
//! (one between two levels, in the right unit) gets the levels alone.

use super::*;
use crate::trips_identify::stdout;

/// Runs `identify` on `data` with the linear model (the quickest fit) and
/// the level options `args`.
fn identify(data: &Path, args: &[&str]) -> Output {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fit.toml");
    let mut all = vec![
        "identify",
        data.to_str().unwrap(),
        "--model",
        "linear",
        "--out",
        out.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    run(&all)
}

/// The SI value the hint of `e` offers: what follows "did you mean ".
fn offered(e: &str) -> &str {
    let from = e.find("did you mean ").expect("a hint") + "did you mean ".len();
    e[from..].split(' ').next().unwrap()
}

/// Each request of the Hoosier file's levels (loads 534 … 2751 N, cambers
/// 0°, 1.60°, 3.19°, pressures 69.7, 83.4, 97.1 kPa) in the wrong unit:
/// the hint is the conversion, and the value it offers selects the level
/// it names. Before, `--load 1.65` read "the requested 2 N; ... did you
/// mean 1650 N (1650 N)?", `--load 2` had no hint though 2000 N selects
/// the 2193 N level, and `--camber 0.05236` (3°, in rad) was offered
/// 0.000913854 rad, reading a right value as degrees.
#[test]
fn a_level_request_in_another_unit_is_answered_with_a_conversion_that_selects() {
    let Some(data) = shared_data(
        "a_level_request_in_another_unit_is_answered_with_a_conversion_that_selects",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let cases = [
        ("--load", "2", "the requested 2 N; the value is read in N: did you mean 2000 N (2 kN), which selects the 2193 N level?", "fz 2000 N asked for: the 2193 N level selected"),
        ("--load", "1.65", "the requested 1.65 N; the value is read in N: did you mean 1650 N (1.65 kN), which selects the 1656 N level?", "fz 1650 N asked for: the 1656 N level selected"),
        ("--camber", "1.6", "the requested 1.6 rad (91.67°); the value is read in rad: did you mean 0.0279253 rad (1.6°), which selects the 1.60° level?", "camber 0.0279253 rad (1.60°) asked for: the 1.60° level selected"),
        ("--pressure", "83", "the requested 83 Pa (0.083 kPa); the value is read in Pa: did you mean 83000 Pa (83 kPa), which selects the 83.4 kPa level?", "pressure 83000 Pa (83.0 kPa) asked for: the 83.4 kPa level selected"),
        ("--pressure", "12", "did you mean 82737 Pa (12 psi), which selects the 83.4 kPa level?", "pressure 82737 Pa (82.7 kPa) asked for: the 83.4 kPa level selected"),
    ];
    for (option, value, hint, selected) in cases {
        let o = identify(&data, &[option, value]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(hint),
            "{option} {value}: {e}"
        );
        assert!(e.contains("(levels: "), "{e}");
        // The value offered selects the level the hint names.
        let o = identify(&data, &[option, offered(&e)]);
        assert!(
            o.status.success(),
            "{option} {}: {}",
            offered(&e),
            stderr(&o)
        );
        assert!(stdout(&o).contains(selected), "{}", stdout(&o));
    }
}

/// A request that no conversion makes a level, or one in the right unit
/// between two levels, gets the levels and no hint.
#[test]
fn a_level_request_no_unit_slip_explains_gets_the_levels_alone() {
    let Some(data) = shared_data(
        "a_level_request_no_unit_slip_explains_gets_the_levels_alone",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let cases = [
        // 3° in rad, between the levels at 1.60° and 3.19°: read as
        // degrees it would be 0.05°, near the level at 0.
        (
            "--camber",
            "0.05236",
            "the requested 0.05236 rad (3.00°) (levels: 0.0000 rad (0.00°), 0.0278 rad (1.60°),",
        ),
        // The sign slipped, typed as it is: no degrees read into it.
        (
            "--camber",
            "-0.0279",
            "the requested -0.0279 rad (-1.60°) (levels: 0.0000 rad (0.00°),",
        ),
        (
            "--pressure",
            "250000",
            "the requested 250000 Pa (250 kPa) (levels: 69.7 kPa,",
        ),
    ];
    for (option, value, said) in cases {
        let o = identify(&data, &[option, value]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(said),
            "{option} {value}: {e}"
        );
        assert!(!e.contains("did you mean"), "{option} {value}: {e}");
    }
}

/// A rig file of 201 rows at 2500 N and 220 kPa (Pa), the fy of a linear
/// tyre, with row `row` (0-based, after the header) changed by `edit`.
fn rig_with(row: usize, edit: fn(&mut [String; 4])) -> tempfile::TempDir {
    let mut text = String::from("fz,alpha,fy,pressure\n");
    for i in 0..201 {
        let alpha = -0.1 + 0.001 * i as f64;
        let mut cells = [
            "2500".to_string(),
            format!("{alpha:.4}"),
            format!("{:.2}", 60000.0 * alpha),
            "220000".to_string(),
        ];
        if i == row {
            edit(&mut cells);
        }
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    scratch(&[("rig.csv", &text)])
}

/// One `fz` cell of 2.5 (kN) among 2500 N rows, or one `pressure` cell of
/// 220 (kPa) among 220000 Pa rows, was dropped as "1 sample between levels
/// (transitions)"; `tyre-eval` refused such a pressure at its cell.
#[test]
fn a_lone_cell_in_kn_or_kpa_is_refused_at_its_cell() {
    let dir = rig_with(50, |c| c[0] = "2.5".into());
    let o = identify(&dir.path().join("rig.csv"), &[]);
    let e = stderr(&o);
    assert!(
        !o.status.success() && e.contains("rig.csv:52:1: column `fz`: 2.5 N between rows at 2500 and 2500 N, where no tyre test dips below 100 N for one sample: `fz` is in N (FORMATS.md); is the cell in kN? 2.5 kN is 2500 N"),
        "{e}"
    );
    let dir = rig_with(100, |c| c[3] = "220".into());
    let o = identify(&dir.path().join("rig.csv"), &[]);
    let e = stderr(&o);
    assert!(
        !o.status.success() && e.contains("rig.csv:102:4: column `pressure`: 220 Pa: no inflated tyre runs below 10000 Pa (0.1 bar), and the column's median is 220000 Pa: `pressure` is in Pa (FORMATS.md): did you mean 220000 Pa (220 kPa)"),
        "{e}"
    );
    // The file as written fits.
    let dir = rig_with(0, |_| ());
    let o = identify(&dir.path().join("rig.csv"), &[]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// `identify --camber 0.0349` (2°, in rad) was answered with levels in
/// degrees alone, and `--camber 2` (degrees typed; no test's camber in
/// rad) with no word of degrees, as it selects no level. A request no
/// test has in SI gets its likeliest unit, saying it selects none either.
#[test]
fn a_request_no_test_has_in_si_gets_its_unit_even_without_a_level() {
    let Some(data) = shared_data(
        "a_request_no_test_has_in_si_gets_its_unit_even_without_a_level",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let cases = [
        ("--camber", "2", "the requested 2 rad (114.59°); the value is read in rad: did you mean 0.0349066 rad (2°)? no level lies near that either (levels: 0.0000 rad (0.00°), 0.0278 rad (1.60°), 0.0557 rad (3.19°); a level holds values within 0.0"),
        ("--camber", "0.0349", "the requested 0.0349 rad (2.00°) (levels: 0.0000 rad (0.00°), 0.0278 rad (1.60°), 0.0557 rad (3.19°);"),
        ("--load", "40", "the requested 40 N; the value is read in N: did you mean 40000 N (40 kN)? no level lies near that either (levels: 534 N, 1095 N, 1656 N, 2193 N, 2751 N;"),
        ("--load", "5", "the requested 5 N; the value is read in N: did you mean 5000 N (5 kN)? no level lies near that either (levels: 534 N,"),
    ];
    for (option, value, said) in cases {
        let o = identify(&data, &[option, value]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(said),
            "{option} {value}: {e}"
        );
    }
}

/// A `pressure` column all in kPa (220) was refused with the column's
/// median but not the reading meant, where one cell in kPa is answered
/// with it; in bar or psi alike, and in `tyre-eval` against the file's
/// PRESMIN to PRESMAX.
#[test]
fn a_pressure_column_in_kpa_bar_or_psi_is_answered_with_its_median_in_pa() {
    let cases = [
        ("220", "is the column in kPa? its median, 220 kPa, is 220000 Pa, within a pneumatic tyre's inflation pressures (50000 to 1000000 Pa): multiply the column by 1000"),
        ("2.2", "is the column in bar? its median, 2.2 bar, is 220000 Pa, within a pneumatic tyre's inflation pressures (50000 to 1000000 Pa): multiply the column by 100000"),
        ("32", "is the column in psi? its median, 32 psi, is 220632 Pa, within a pneumatic tyre's inflation pressures (50000 to 1000000 Pa): multiply the column by 6895"),
    ];
    for (cell, said) in cases {
        let dir = rig_with(0, |_| ());
        let path = dir.path().join("rig.csv");
        let text = fs::read_to_string(&path)
            .unwrap()
            .replace(",220000\n", &format!(",{cell}\n"));
        fs::write(&path, text).unwrap();
        let o = identify(&path, &[]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(&format!("rig.csv:2:4: column `pressure`: {cell} Pa, in a file whose median pressure is {cell} Pa: ")) && e.contains(said),
            "{cell}: {e}"
        );
    }
    // `tyre-eval` reads the median among the tyre's own pressures.
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.csv");
    fs::write(
        &points,
        "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,260\n4000,0,0.05,0,20,260\n",
    )
    .unwrap();
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let out = dir.path().join("f.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(
        !o.status.success() && e.contains("is the column in kPa? its median, 260 kPa, is 260000 Pa, within the file's PRESMIN to PRESMAX (200000 to 400000 Pa): multiply the column by 1000"),
        "{e}"
    );
}
