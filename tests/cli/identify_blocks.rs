//! What `identify` writes where the data do not reach: a block of
//! coefficients with no columns to fit said not fitted, and a linear tyre
//! fitted to the slip range where a tyre is linear. Run as a user runs it,
//! from rig files.

use super::trips_identify::{identify_with, rig, stdout};
use super::*;

/// A longitudinal-only rig file fitted with PAC89 or UniTire kept the
/// defaults' lateral coefficients silently (a lateral force of another
/// tyre); a lateral-only one its longitudinal coefficients alike.
#[test]
fn a_block_without_data_is_said_not_fitted_on_the_terminal_and_in_the_file() {
    let mut long = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0, 6000.0, 8000.0] {
        for k in -20..=20 {
            let kappa = 0.01 * f64::from(k);
            let fx = 1.2 * fz * (1.6 * (14.0 * kappa).atan()).sin();
            long += &format!("{fz},{kappa},{fx:.3}\n");
        }
    }
    // What the block then holds: the start values, or, where those give
    // no force at all (both models' longitudinal block), that.
    let not_fitted = |data: &str, what: &str, columns: &str, model: &str| {
        let holds = if data == "longitudinal" {
            "the written file's longitudinal force is 0 at any slip ratio (the {model} model's longitudinal coefficients start at zero)".replace("{model}", model)
        } else {
            format!("the defaults' values (the {model} model's start values")
        };
        format!("no {data} data: the file's {what} coefficients are not fitted (no {columns} columns in the data): {holds}")
    };
    for model in ["pac89", "unitire"] {
        for (rig, said, unsaid) in [
            (long.clone(), ("lateral", "lateral force", "alpha/fy"), None),
            (
                rig(1.0),
                ("longitudinal", "longitudinal force", "kappa/fx"),
                Some(("aligning moment", "aligning moment", "mz")),
            ),
        ] {
            let dir = scratch(&[("rig.csv", &rig)]);
            let out = dir.path().join("t.toml");
            let o = identify_with(dir.path(), model, &[], &out);
            assert!(o.status.success(), "{model}: {}", stderr(&o));
            let file = std::fs::read_to_string(&out).unwrap();
            let line = not_fitted(said.0, said.1, said.2, model);
            assert!(
                stdout(&o).contains(&format!("  {line}")),
                "{model}: {}",
                stdout(&o)
            );
            assert!(file.contains(&format!("# {line}")), "{model}: {file}");
            if let Some(u) = unsaid {
                // The rig has mz: the aligning moment was fitted.
                assert!(!file.contains(&not_fitted(u.0, u.1, u.2, model)), "{file}");
            }
        }
    }
}

/// `--model linear` drew a line through saturated data (15.6 kN/rad
/// against ~57 at zero slip on one load of the Hoosier file) and wrote
/// `pneumatic_trail = 0` silently.
#[test]
fn a_linear_tyre_is_fitted_to_small_slip_and_its_trail_to_mz() {
    let Some(data) = shared_data(
        "a_linear_tyre_is_fitted_to_small_slip_and_its_trail_to_mz",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let text = std::fs::read_to_string(data).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap();
    let col = |n: &str| head.split(',').position(|c| c == n).unwrap();
    let (fz, p, c, a, fy) = (
        col("fz"),
        col("pressure"),
        col("camber"),
        col("alpha"),
        col("fy"),
    );
    let mut one = format!("{head}\n");
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for l in lines {
        let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
        if (v[p] - 83_400.0).abs() < 2000.0 && v[c].abs() < 0.005 && (v[fz] - 1656.0).abs() < 150.0
        {
            one += &format!("{l}\n");
            if v[a].abs() <= 2f64.to_radians() {
                (sxy, sxx) = (sxy + v[a] * v[fy], sxx + v[a] * v[a]);
            }
        }
    }
    let dir = scratch(&[("rig.csv", &one)]);
    let out = dir.path().join("lin.toml");
    let o = identify_with(dir.path(), "linear", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = std::fs::read_to_string(&out).unwrap();
    let tyre: toml::Value = toml::from_str(&file).unwrap();
    let c_alpha = tyre["cornering_stiffness"].as_float().unwrap();
    let slope = sxy / sxx;
    assert!(
        (c_alpha / slope - 1.0).abs() < 0.15,
        "{c_alpha} against {slope}"
    );
    let window = "linear window: fitted to |alpha| <= 2 deg only (";
    assert!(file.contains(&format!("# {window}")), "{file}");
    assert!(stdout(&o).contains(window), "{}", stdout(&o));
    let report = read_json(&dir.path().join("lin.report.json"));
    let w = &report["linear_window"];
    assert!(w["points_left_out"].as_u64().unwrap() > 0, "{w}");
    let trail = tyre["pneumatic_trail"].as_float().unwrap();
    assert_eq!(w["pneumatic_trail"].as_f64(), Some(trail), "{w}");
    assert!(trail != 0.0 && trail.abs() < 0.1, "{trail}");
    assert!(file.contains("# pneumatic_trail = "), "{file}");
}

/// `identify --model mf61` on lateral-only rig data said its longitudinal
/// block was not fitted (Fx = 0 in the written file) but not that its
/// QSX and QSY blocks were all 0 too, so that the file's `mx` and `my`
/// are 0 everywhere; the rule that finds them is `tyre-eval`'s, which
/// then warns of the same at the points it evaluates.
#[test]
fn a_lateral_only_mf61_fit_says_its_wheel_moments_are_not_fitted() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let tir = dir.path().join("m.tir");
    let o = identify_with(dir.path(), "mf61", &[], &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&tir).unwrap();
    let lines = [
        "no longitudinal data: the longitudinal force block is not fitted (",
        "no overturning moment data: the overturning moment block is not fitted (no rows with a measured `mx`: `mx` is fitted only from a rig file with `mx`, `kappa` and `fx` columns, whose samples are its rows (a file without `kappa` and `fx` is averaged into slip-angle bins of `fy` and `mz`, and its `mx` left out); to fit it, give `mx` in a file with `kappa` and `fx` (on a cornering sweep, `kappa` = 0 and the rig's measured `fx`)): its coefficients are the defaults' (no --template); the written file's overturning moment is 0 at any lateral force or camber (QSX1 to QSX14 all 0): give --template with a tyre's overturning moment coefficients for one",
        "no rolling resistance data: the rolling resistance moment block is not fitted (no rows with a measured `my`: `my` is fitted only from a rig file with `my`, `kappa` and `fx` columns, whose samples are its rows (a file without `kappa` and `fx` is averaged into slip-angle bins of `fy` and `mz`, and its `my` left out); to fit it, give `my` in a file with `kappa` and `fx` (on a cornering sweep, `kappa` = 0 and the rig's measured `fx`)): its coefficients are the defaults' (no --template); the written file's rolling resistance moment is 0 at any speed (QSY1 to QSY8 all 0): give --template with a tyre's rolling resistance coefficients for one",
    ];
    for line in lines {
        assert!(stdout(&o).contains(&format!("  {line}")), "{}", stdout(&o));
        assert!(file.contains(&format!("$ {line}")), "{file}");
    }
    // With a template that has them, they are the template's.
    let template = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let tir = dir.path().join("t.tir");
    let args = ["--template", template.to_str().unwrap()];
    let o = identify_with(dir.path(), "mf61", &args, &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("its coefficients are the template's values; the written file's overturning moment is theirs, not these data's")
            && stdout(&o).contains("its coefficients are the template's values; the written file's rolling resistance moment is theirs, not these data's"),
        "{}",
        stdout(&o)
    );
}
