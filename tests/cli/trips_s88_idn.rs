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
            let alpha = if degrees { written.to_radians() } else { written };
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
