//! A fresh user's findings on cambers and fitted ranges (round 34): a
//! camber of 0.7 rad evaluated at a `.tir`'s `CAMMAX` beside 0.02 rad but
//! refused beside 0 as "beyond ±20°", and 1.2 rad refused as "beyond ±45°":
//! three limits in two behaviours, said two ways; a linear tyre fitted at
//! 3000–5000 N evaluated at 12 kN and 500 N without a word; and a PAC89
//! tyre fitted to rig data without a camber column said at any camber as
//! "extrapolation from that one level", where the fit saw no camber.
//! Run as a user runs them: rig files through `identify`, points through
//! `tyre-eval`.

use super::*;

/// A points file of slip angle 0.05 rad at 4 kN and 20 m/s, one point
/// per camber of `cambers` (rad).
fn points(cambers: &[f64]) -> String {
    let mut s = String::from("fz,kappa,alpha,camber,speed\n");
    for g in cambers {
        s.push_str(&format!("4000,0,0.05,{g},20\n"));
    }
    s
}

/// A lateral rig file at the loads `loads` (N), slip angles ±0.2 rad, no
/// camber column unless `cambers` gives its levels: a tyre whose
/// cornering stiffness saturates with the load (Pacejka's
/// `sin(2·atan(Fz/Fz0))`) and friction falls with it.
fn rig(loads: &[f64], cambers: &[f64]) -> String {
    let mut s = String::from(match cambers.is_empty() {
        true => "fz,alpha,fy\n",
        false => "fz,alpha,fy,camber\n",
    });
    let levels: Vec<Option<f64>> = match cambers.is_empty() {
        true => vec![None],
        false => cambers.iter().map(|g| Some(*g)).collect(),
    };
    for &fz in loads {
        let c = 68_800.0 * (2.0 * (fz / 5000.0).atan()).sin();
        let d = fz * (1.25 - 0.05 * fz / 1000.0);
        let b = c / (1.5 * d);
        for g in &levels {
            for i in -20..=20 {
                let a = 0.01 * f64::from(i);
                let fy = d * (1.5 * (b * a).atan()).sin();
                match g {
                    Some(g) => s.push_str(&format!("{fz},{a},{fy},{g}\n")),
                    None => s.push_str(&format!("{fz},{a},{fy}\n")),
                }
            }
        }
    }
    s
}

/// `tyre-eval` of the repository's MF 6.1 file (`CAMMAX` 0.0873 rad in
/// the points' frame) on
/// `name` in `dir`: its output and stderr.
fn mf61_at(dir: &Path, name: &str) -> (Output, String) {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let o = run_in(
        dir,
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            name,
            "--out",
            &format!("{name}.out.csv"),
        ],
    );
    let e = stderr(&o);
    (o, e)
}

/// The three cambers of the finding: 0.7 rad beside 0.02 rad is held to
/// `CAMMAX` with a warning; beside 0 alone it is refused by the column
/// rule, whose words now say it is the column (every camber other than 0
/// beyond ±20°) and name the ±45° refusal too; 1.2 rad is refused at
/// ±45°, naming the column rule. Both in degrees and radians, at file,
/// line and column with the value; `identify` refuses a rig's column in
/// the same words.
#[test]
fn a_camber_refused_in_one_file_and_evaluated_in_another_is_said_by_one_rule() {
    let dir = scratch(&[
        ("mixed.csv", &points(&[0.02, 0.5, 0.7])),
        ("steep.csv", &points(&[0.0, 0.7, -0.7])),
        ("far.csv", &points(&[0.0, 1.2])),
        ("rig.csv", &rig(&[3000.0, 5000.0], &[0.0, 0.5])),
    ]);
    let (o, e) = mf61_at(dir.path(), "mixed.csv");
    assert!(o.status.success(), "{e}");
    assert!(e.contains("2 of 3 points above CAMMAX = 0.0873 rad"), "{e}");
    let both = ["±20° (0.349 rad)", "±45° (0.785 rad)"];
    let (o, e) = mf61_at(dir.path(), "steep.csv");
    assert!(!o.status.success(), "{e}");
    for (cell, value, deg) in [("3:4", "0.7", "40.1"), ("4:4", "-0.7", "-40.1")] {
        let line = e
            .lines()
            .find(|l| l.contains(&format!("steep.csv:{cell}: column `camber`")))
            .unwrap_or_else(|| panic!("{e}"));
        assert!(
            line.contains(&format!("{value} rad ({deg}°) is beyond ±20° (0.349 rad), as every camber of the column other than 0 is")),
            "{line}"
        );
        assert!(line.contains("a column with a camber within ±20° is read in radians, refused only beyond ±45° (0.785 rad)"), "{line}");
    }
    assert!(!dir.path().join("steep.csv.out.csv").exists());
    let (o, e) = mf61_at(dir.path(), "far.csv");
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("far.csv:3:4: column `camber`: 1.2 rad (68.8°) is beyond ±45° (0.785 rad), steeper than any car tyre runs"),
        "{e}"
    );
    let o = run_in(
        dir.path(),
        &["identify", "rig.csv", "--model", "gim", "--out", "g.toml"],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    let line = e
        .lines()
        .find(|l| l.contains("rig.csv:43:4: column `camber`"))
        .unwrap_or_else(|| panic!("{e}"));
    assert!(line.contains("0.5 rad (28.6°) is beyond ±20° (0.349 rad), as every camber of the column other than 0 is"), "{line}");
    for limit in both {
        assert!(line.contains(limit), "{line}");
    }
}

/// A linear tyre `identify` fitted at 3000–5000 N (its `[fitted_ranges]`
/// say so) evaluated at 12 kN and 500 N: the same force as at 4 kN, where
/// every other model's fitted load range is said. Now each side is said,
/// with the count, the range and the first point; 4 kN is not.
#[test]
fn a_linear_tyre_evaluated_far_from_the_loads_it_was_fitted_at_is_warned() {
    let dir = scratch(&[
        ("rig.csv", &rig(&[3000.0, 4000.0, 5000.0], &[])),
        (
            "p.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0.02,0,20\n12000,0,0.02,0,20\n500,0,0.02,0,20\n",
        ),
        ("mid.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.02,0,20\n"),
    ]);
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "linear", "--out", "lin.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let toml = std::fs::read_to_string(dir.path().join("lin.toml")).unwrap();
    assert!(toml.contains("fz = [3000.0, 5000.0]"), "{toml}");
    let eval = |points: &str| {
        let o = run_in(
            dir.path(),
            &["tyre-eval", "lin.toml", points, "--out", "out.csv"],
        );
        assert!(o.status.success(), "{}", stderr(&o));
        stderr(&o)
    };
    let e = eval("p.csv");
    let above = "1 of 3 points at a load above 5000 N, outside the loads the linear tyre was fitted at (its [fitted_ranges]: 3000 to 5000 N): the linear model has no load term";
    assert!(e.contains(above), "{e}");
    assert!(
        e.contains("the first at line 3, fz = 1.2e4 N")
            || e.contains("the first at line 3, fz = 12000 N"),
        "{e}"
    );
    assert!(
        e.contains(
            "1 of 3 points at a load below 3000 N, outside the loads the linear tyre was fitted at"
        ),
        "{e}"
    );
    assert!(!eval("mid.csv").contains("fitted at"));
}

/// A PAC89 tyre `identify` fitted to rig data without a camber column:
/// its `[fitted_ranges]` keep `camber = [0.0, 0.0]` (the fit saw camber 0
/// only and held its camber terms), and a point at another camber is
/// said as a camber the fit never saw, not as an extrapolation.
#[test]
fn a_fit_without_a_camber_column_says_at_another_camber_that_it_saw_no_camber() {
    let dir = scratch(&[
        (
            "rig.csv",
            &rig(&[2000.0, 3000.0, 4000.0, 5000.0, 6000.0], &[]),
        ),
        ("p.csv", &points(&[0.0, 0.05])),
    ]);
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "pac89", "--out", "pac.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let toml = std::fs::read_to_string(dir.path().join("pac.toml")).unwrap();
    assert!(toml.contains("camber = [0.0, 0.0]"), "{toml}");
    let o = run_in(
        dir.path(),
        &["tyre-eval", "pac.toml", "p.csv", "--out", "out.csv"],
    );
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    let line = e
        .lines()
        .find(|l| l.contains("the rig data's camber"))
        .unwrap_or_else(|| panic!("{e}"));
    assert!(
        line.contains("the fit saw no other camber (a rig file without a `camber` column is at camber 0, FORMATS.md), so no data fixed the tyre's camber terms"),
        "{line}"
    );
    assert!(!line.contains("extrapolation"), "{line}");
}
