//! Session 110 (round 42, finding 1): `tyre-eval` read a slip sweep
//! written in degrees (−1.5 to 1.5 by 0.1) as radians, ±86°, and wrote
//! fy = −3078 N at −1.5 without a word; 0.5, 1, 1.5, −1 meant as degrees
//! likewise; and an `sa_deg` column of 5 beside `alpha` = 0.05 rad was
//! only named as not carried. Now a column whose every value is a round
//! number of degrees (or percent, for `kappa`), reaching past where any
//! rig sweeps with none of the small slips a sweep in radians holds, is
//! refused at its farthest row unless the header states radians; a column
//! beside that states its unit is checked against the one read. Points
//! asked in the sliding range in radians (`pac89_bounds`) are still read.

use super::tyre_eval::{column, eval};
use super::*;

/// The MF 6.1 sample file of the fixtures.
fn mf61() -> PathBuf {
    root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
}

/// A points file of `header` (its slip-angle column's name) at the slip
/// angles `alphas`, 4000 N, 16.7 m/s.
fn at_alphas(header: &str, alphas: &[f64]) -> String {
    let rows: String = alphas
        .iter()
        .map(|a| format!("4000,0,{a},0,16.7\n"))
        .collect();
    format!("fz,kappa,{header},camber,speed\n{rows}")
}

/// The tester's sweep, −1.5 to 1.5 by 0.1, written as a user's script
/// writes it (one decimal).
fn degree_sweep() -> Vec<f64> {
    (-15..=15).map(|k| f64::from(k) / 10.0).collect()
}

/// The public `car145_70R13.tir` at the tester's degree sweep: refused at
/// line 2 (−1.5, the first of the farthest), column 3, with both readings
/// and both ways out; stated in radians, it is evaluated as written, and
/// converted to radians it is evaluated with no word of degrees.
#[test]
fn a_slip_sweep_in_degrees_is_refused_at_its_farthest_row_unless_stated_in_radians() {
    let test = "a_slip_sweep_in_degrees_is_refused_at_its_farthest_row_unless_stated_in_radians";
    let Some(tir) = shared_data(test, "tir_public/car145_70R13.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let (o, written) = eval(dir.path(), &tir, &at_alphas("alpha", &degree_sweep()), &[]);
    let e = stderr(&o);
    assert!(!o.status.success() && written.is_empty(), "{e}");
    assert!(
        e.contains("p.csv:2:3: column `alpha`: -1.5 here, the column's largest |alpha|, is -85.9° read in radians, beyond the 34° (0.6 rad) past which no rig sweeps and every tyre's force has peaked, while every one of its 31 values is a round number of degrees (a multiple of 0.05) and none but 0 is within 0.05 (2.86°)"),
        "{e}"
    );
    assert!(
        e.contains("read in degrees, it reaches -1.5°. Angles are in radians (FORMATS.md): is the column in degrees? Convert it (× π/180 = 0.0174533); if it is in radians, say so in the header: `alpha [rad]`"),
        "{e}"
    );
    // Said in radians by the header: read as written, the 86° points.
    let (o, written) = eval(
        dir.path(),
        &tir,
        &at_alphas("alpha [rad]", &degree_sweep()),
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(column(&written, "alpha"), degree_sweep());
    // Converted: a sweep of ±1.5°, its force rising with the slip on each
    // side of 0 and odd about it within the tyre's own offset.
    let radians: Vec<f64> = degree_sweep().iter().map(|d| d.to_radians()).collect();
    let (o, written) = eval(dir.path(), &tir, &at_alphas("alpha", &radians), &[]);
    assert!(
        o.status.success() && !stderr(&o).contains("degrees"),
        "{}",
        stderr(&o)
    );
    let fy = column(&written, "fy");
    assert!(fy.windows(2).all(|w| w[1] > w[0]), "{fy:?}");
    assert!(fy[0] < 0.0 && fy[30] > 0.0, "{fy:?}");
}

/// 0.25, 0.5, 1, 1.5, −1 meant as degrees: refused at 1.5 (line 5), with
/// the count of values judged.
#[test]
fn slip_angles_of_small_round_degrees_are_refused_as_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let points = at_alphas("alpha", &[0.5, 1.0, 1.5, -1.0, 0.25]);
    let (o, written) = eval(dir.path(), &mf61(), &points, &[]);
    let e = stderr(&o);
    assert!(!o.status.success() && written.is_empty(), "{e}");
    assert!(
        e.contains("p.csv:4:3: column `alpha`: 1.5 here, the column's largest |alpha|, is 85.9° read in radians")
            && e.contains("every one of its 5 values is a round number of degrees"),
        "{e}"
    );
    assert_eq!(e.matches("column `alpha`").count(), 1, "one refusal: {e}");
}

/// Points in the sliding range computed in radians (5°, 30°, 40°, 60°,
/// 80°, as `pac89_bounds` asks a fitted file) and a small slip beside far
/// ones (0.05 with 1.2 and −1.5 rad, a `.tir`'s ALPMAX probed) are read:
/// evaluated, with no word of degrees.
#[test]
fn slip_angles_in_the_sliding_range_in_radians_are_still_evaluated() {
    let dir = tempfile::tempdir().unwrap();
    let sliding: Vec<f64> = [5.0f64, 30.0, 40.0, 60.0, 80.0]
        .iter()
        .flat_map(|d| [d.to_radians(), -d.to_radians()])
        .collect();
    for alphas in [sliding, vec![0.05, 0.05, 1.2, -1.5, 0.0]] {
        let (o, written) = eval(dir.path(), &mf61(), &at_alphas("alpha", &alphas), &[]);
        let e = stderr(&o);
        assert!(o.status.success() && !e.contains("degrees"), "{e}");
        assert_eq!(column(&written, "alpha"), alphas);
    }
}

/// `sa_deg` beside `alpha`: 2.86 and 5.73 agree with 0.05 and 0.1 rad to
/// the hundredth of a degree they are written to (evaluated, the column
/// named as not carried); 5 and −3 do not (refused at each row and the
/// `sa_deg` column, with both values); 0.5 beside 0.5 is the same number.
#[test]
fn a_slip_angle_column_beside_alpha_is_checked_against_it_row_by_row() {
    let dir = tempfile::tempdir().unwrap();
    let with = |sa: [&str; 2], alpha: [&str; 2]| {
        format!(
            "fz,kappa,alpha,camber,speed,sa_deg\n4000,0,{},0,16.7,{}\n4000,0,{},0,16.7,{}\n",
            alpha[0], sa[0], alpha[1], sa[1]
        )
    };
    let (o, _) = eval(
        dir.path(),
        &mf61(),
        &with(["2.86", "5.73"], ["0.05", "0.1"]),
        &[],
    );
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(e.contains("sa_deg") && e.contains("not carried"), "{e}");
    let (o, written) = eval(
        dir.path(),
        &mf61(),
        &with(["5", "-3"], ["0.05", "0.1"]),
        &[],
    );
    let e = stderr(&o);
    assert!(!o.status.success() && written.is_empty(), "{e}");
    for said in [
        "p.csv:2:6: column `sa_deg`: 5° beside `alpha` = 0.05 rad on this row (2.865° in `sa_deg`'s unit): they differ by more than the 0.5° `sa_deg` is written to",
        "p.csv:3:6: column `sa_deg`: -3° beside `alpha` = 0.1 rad on this row (5.73° in `sa_deg`'s unit)",
        "`tyre-eval` reads `alpha` (radians, FORMATS.md) and not `sa_deg`: which one holds the slip angle?",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    let (o, _) = eval(
        dir.path(),
        &mf61(),
        &with(["0.5", "1.0"], ["0.5", "1.0"]),
        &[],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains(
            "(`alpha` holds the same number as `sa_deg`: is `alpha` in `sa_deg`'s unit too?)"
        ),
        "{e}"
    );
}

/// A slip ratio of 5, 10 and −3 beside 0 is warned of as past lock, not
/// refused (a spinning wheel's 10 is asked on purpose: `trips_s72_tyre`).
/// A camber of 0.5 and −0.4 beside 0 stated in radians (`camber [rad]`)
/// is read, not asked as degrees.
#[test]
fn a_camber_stated_in_radians_is_read_as_written() {
    let dir = tempfile::tempdir().unwrap();
    let kappa = "fz,kappa,alpha,camber,speed\n4000,0,0,0,16.7\n4000,5,0,0,16.7\n4000,10,0,0,16.7\n4000,-3,0,0,16.7\n";
    let (o, written) = eval(dir.path(), &mf61(), kappa, &[]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(e.contains("3 points of 4 at a slip ratio beyond ±1"), "{e}");
    assert_eq!(column(&written, "kappa"), [0.0, 5.0, 10.0, -3.0]);
    let camber = |h: &str| {
        format!(
            "fz,kappa,alpha,{h},speed\n4000,0,0.05,0,20\n4000,0,0.05,0.5,20\n4000,0,0.05,-0.4,20\n"
        )
    };
    let (o, _) = eval(dir.path(), &mf61(), &camber("camber"), &[]);
    assert!(
        stderr(&o).contains("p.csv:3:4: column `camber`: 0.5 rad (28.6°) is beyond ±20°"),
        "{}",
        stderr(&o)
    );
    let (o, written) = eval(dir.path(), &mf61(), &camber("camber [rad]"), &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(column(&written, "camber"), [0.0, 0.5, -0.4]);
}
