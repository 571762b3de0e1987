//! A fresh-eyes tester's findings (round 36) in `identify`'s data checks,
//! holds, bounds and window: a pressure column a thousand times too large
//! fitted and written into the tyre; PAC89's camber terms held at two
//! values by its two fits; a reversed slip-angle column said as a reversed
//! `fy`; a parameter on its bound said free unbinned; `--pressure 2.6`
//! read as kPa where `tyre-eval` reads bar; a linear window that kept
//! +2.0° and dropped −2.0°; a pooled linear fit's figure drawing four
//! coinciding lines under a key of four colours.

use super::trips_s91_diag::png_pixels;
use super::*;

/// A tyre's lateral force and aligning moment at load `fz` (N) and slip
/// angle `alpha` (rad): `fz·sin(1.4·atan(10·α))` (14 N/rad per N of load
/// at zero slip, its peak `fz` at 6.4°) and a trail of 30 mm fading past
/// the peak, so that `mz` has the sign of `fy` at small slip.
fn tyre(fz: f64, alpha: f64) -> (f64, f64) {
    let fy = fz * (1.4 * (10.0 * alpha).atan()).sin();
    (fy, 0.03 * fy * (-(alpha / 0.1).powi(2)).exp())
}

/// Rig rows `fz,alpha,fy,mz` plus `extra` (a header's tail and each row's)
/// at each load of `loads`, alpha from −`reach` to +`reach` degrees in
/// steps of 0.05°, each slip as the synthetic proving ground writes it
/// (`(−12 + 0.05·k)°` in rad, full precision); `alpha_sign` −1 writes the
/// slip-angle column reversed.
fn rig(loads: &[f64], reach: f64, alpha_sign: f64, extra: (&str, &str)) -> String {
    let mut s = format!("fz,alpha,fy,mz{}\n", extra.0);
    let steps = (reach / 0.05).round() as i32;
    for &fz in loads {
        for k in -steps..=steps {
            let alpha = (0.05 * f64::from(k)).to_radians();
            let (fy, mz) = tyre(fz, alpha);
            s += &format!("{fz},{},{fy},{mz}{}\n", alpha_sign * alpha, extra.1);
        }
    }
    s
}

/// `identify rig.csv --model <model> <args> --out fit.toml` in `dir`.
fn identified(dir: &Path, model: &str, args: &[&str]) -> Output {
    let mut all = vec!["identify", "rig.csv", "--model", model];
    all.extend_from_slice(args);
    all.extend(["--out", "fit.toml"]);
    run_in(dir, &all)
}

/// Before: the Hoosier file's pressures ×1000 (82 160 kPa …) were fitted,
/// pooled into 46 "levels" and written as `[fitted_ranges] pressure =
/// [82160000.0, 84430000.0]`, which `tyre-eval` read without a word while
/// it refuses a point's pressure above 5 MPa. Now each cell above the one
/// limit is refused at its line and column with its value, ×1000 and
/// ×100 alike; ×10 (a truck's 2.2 MPa) is a tyre's.
#[test]
fn a_rig_pressure_above_any_tyres_is_refused_at_its_cells_as_tyre_eval_refuses_a_points() {
    for (pressure, refused) in [("220000000", true), ("22000000", true), ("2200000", false)] {
        let dir = scratch(&[(
            "rig.csv",
            &rig(&[4000.0], 5.0, 1.0, (",pressure", &format!(",{pressure}"))),
        )]);
        let o = identified(dir.path(), "gim", &[]);
        let e = stderr(&o);
        if !refused {
            assert!(o.status.success(), "{pressure}: {e}");
            continue;
        }
        assert!(!o.status.success(), "{pressure}: {e}");
        assert!(!dir.path().join("fit.toml").exists());
        assert!(
            e.contains(&format!("rig.csv:2:5: column `pressure`: {pressure} Pa is above 5000000 Pa, the largest a tyre is tested at (5 MPa, above any pneumatic tyre's inflation")),
            "{e}"
        );
        assert!(e.contains("(the first of 201 places refused alike)"), "{e}");
    }
}

/// Before: `--model pac89` on data at one camber held a5, a8, a11 at the
/// Adams example's 0.00501, 0.002289, 19.1656 where the direct fit was
/// written (`--local lm`) and at 0 where the two-stage result was
/// (`--local none`), in the same words: 225 N of camber thrust at 4 kN and
/// 2.9°, or none. Now both fits hold them at the start's, and the words
/// say so and where those come from.
#[test]
fn pac89s_camber_terms_without_camber_data_are_held_at_one_stated_value_whatever_the_polish() {
    let dir = scratch(&[(
        "rig.csv",
        &rig(&[2000.0, 4000.0, 6000.0], 12.0, 1.0, ("", "")),
    )]);
    for local in ["lm", "none"] {
        let o = identified(dir.path(), "pac89", &["--local", local]);
        let said = String::from_utf8_lossy(&o.stdout).into_owned();
        assert!(o.status.success(), "{local}: {}", stderr(&o));
        assert!(
            said.contains("held: a5 = 0.00501, a8 = 0.002289, a11 = 19.1656: camber terms, which need more camber levels than the data's 1 level: held at the model's start values (PAC89's are the Adams/Tire documentation's example tyre's, whichever of its fits is written)"),
            "{local}: {said}"
        );
        let report = read_json(&dir.path().join("fit.report.json"));
        let held = report["held"].as_array().unwrap();
        for (name, value) in [("a5", 0.00501), ("a8", 0.002289), ("a11", 19.1656)] {
            let h = held.iter().find(|h| h["name"] == name).unwrap();
            assert_eq!(h["value"].as_f64(), Some(value), "{local}: {h}");
        }
        let tyre: toml::Value =
            toml::from_str(&fs::read_to_string(dir.path().join("fit.toml")).unwrap()).unwrap();
        let a = tyre["a"].as_array().unwrap();
        assert_eq!(a[11].as_float(), Some(19.1656), "{local}: {tyre}");
    }
}

/// Before: a rig file whose slip-angle column is reversed (`fy` and `mz`
/// both sloping the wrong way against it) was told to "negate the `fy`
/// column", which fits the same slopes but mirrors the tyre's offsets.
/// Now both reversed name `alpha`; `fy` alone reversed still names `fy`.
/// (Session 111: both reversed name `alpha` or `fy` and `mz`, which the
/// slopes cannot tell apart, `trips_s111_rigtir45.rs`.)
#[test]
fn a_reversed_slip_angle_column_is_named_where_fy_and_mz_both_slope_the_wrong_way() {
    let dir = scratch(&[("rig.csv", &rig(&[4000.0], 5.0, -1.0, ("", "")))]);
    let o = identified(dir.path(), "gim", &[]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("rig.csv: columns `alpha`, `fy` and `mz` (columns 2, 3 and 4 of the header): near zero slip (|alpha| ≤ 0.035 rad) both forces slope the wrong way against the slip angle: `fy`'s least-squares slope is -53423 N/rad (standard error 122 N/rad) from 80 samples (40 with alpha > 0, 40 with alpha < 0), and `mz`'s -1489 N·m/rad"),
        "{e}"
    );
    assert!(
        e.contains("Either `alpha` is reversed or `fy` and `mz` both are: each fixes both slopes, but they give mirror-image tyres, and these data cannot tell which"),
        "{e}"
    );
    assert!(!e.contains("negate the `fy` column"), "{e}");
    // `fy` alone reversed: its own column.
    let reversed_fy: String = rig(&[4000.0], 5.0, 1.0, ("", ""))
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let mut c: Vec<String> = l.split(',').map(String::from).collect();
            if i > 0 {
                c[2] = format!("{}", -c[2].parse::<f64>().unwrap());
            }
            c.join(",") + "\n"
        })
        .collect();
    fs::write(dir.path().join("rig.csv"), reversed_fy).unwrap();
    let e = stderr(&identified(dir.path(), "gim", &[]));
    assert!(
        e.contains("column `fy` (column 3 of the header) has the wrong sign"),
        "{e}"
    );
    assert!(e.contains("negate the `fy` column"), "{e}");
}

/// Before: `identify --pressure 2.6` on a rig at 220 kPa asked "did you
/// mean 2600 Pa (2.6 kPa)?", where `tyre-eval` reads the same 2.6 as
/// 260000 Pa (2.6 bar). Now one rule: the first of kPa, bar and psi that
/// makes it a pneumatic tyre's.
#[test]
fn a_pressure_option_of_a_few_units_is_read_as_tyre_eval_reads_a_points() {
    let dir = scratch(&[(
        "rig.csv",
        &rig(&[4000.0], 5.0, 1.0, (",pressure", ",220000")),
    )]);
    let e = stderr(&identified(dir.path(), "gim", &["--pressure", "2.6"]));
    assert!(
        e.contains("the value is read in Pa: did you mean 260000 Pa (2.6 bar)? no level lies near that either"),
        "{e}"
    );
    // Where kPa selects a level it is still asked first.
    let e = stderr(&identified(dir.path(), "gim", &["--pressure", "2.2"]));
    assert!(e.contains("did you mean 220000 Pa (2.2 bar)"), "{e}");
}

/// Before: a symmetric sweep binned in 0.25° fitted `--model linear` kept
/// the bin at +2.0° and dropped the one at −2.0° (16 points, −1.75° to
/// +2.0°): the −2.0° bin's mean lay a rounding past 2°. Now the window is
/// judged by the bins' centres, both ends in: 17 points, ±2.0°.
#[test]
fn a_linear_fits_window_keeps_the_bins_at_both_its_ends() {
    let dir = scratch(&[("rig.csv", &rig(&[4000.0], 12.0, 1.0, ("", "")))]);
    let o = identified(dir.path(), "linear", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&dir.path().join("fit.report.json"));
    let w = &report["linear_window"];
    assert_eq!(w["points_fitted"], 17, "{w}");
    assert_eq!(w["points_left_out"], 97 - 17, "{w}");
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        said.contains("linear window: fitted to |alpha| <= 2 deg only (17 points; 80 points"),
        "{said}"
    );
}

/// The RGB pixels of the PNG `path` in palette colour `rgb`.
fn pixels_of(path: &Path, rgb: [u8; 3]) -> usize {
    let (px, _, _) = png_pixels(path);
    px.chunks(3).filter(|p| *p == rgb).count()
}

/// Before: a linear fit of four loads pooled drew four coinciding fitted
/// lines, only the last (the heaviest load's orange) visible, under a key
/// of four coloured lines. Now the one curve is drawn once, in black, and
/// the loads keyed by their points: no load's line colour is drawn, where
/// the heaviest load's line took over a thousand pixels.
#[test]
fn a_pooled_linear_fits_figure_draws_its_one_curve_once() {
    let dir = scratch(&[(
        "rig.csv",
        &rig(&[2500.0, 4000.0, 5500.0, 7000.0], 12.0, 1.0, ("", "")),
    )]);
    let o = identified(dir.path(), "linear", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let png = dir.path().join("fit.png");
    // The points are drawn in their load's pale tint (55 % white), a
    // fitted line in its full colour.
    let (blue_points, orange_line) = (
        pixels_of(&png, [154, 194, 221]),
        pixels_of(&png, [255, 127, 14]),
    );
    assert!(
        blue_points > 50,
        "the lightest load's points: {blue_points}"
    );
    assert!(
        orange_line < 100,
        "the heaviest load's line colour covers {orange_line} px: a fitted line per load is drawn"
    );
}
