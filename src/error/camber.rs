//! The one rule by which `tyre-eval` and `identify` refuse a camber
//! column's cell, and its words: beyond ±45° ([`MOST_CAMBER`]) any cell,
//! steeper than any car tyre runs; beyond ±20° ([`STEEP_CAMBER`]) a cell
//! of a column whose every camber other than 0 lies there, as a column
//! in degrees reads in radians (0.5° meant reads as 28.6°). Between, a
//! camber is read: a `.tir` holds it to its `CAMMIN`/`CAMMAX` with a
//! warning, as MFeval does with its limit checks on (useMode 1xx), and a
//! model with no camber range says the points past 20°. Each refusal
//! states both limits in degrees and radians, so that a camber evaluated
//! in one file and refused in another is said why. Radians inside.

/// The camber (20°, rad) beyond which a column whose every camber other
/// than 0 lies reads as one in degrees (`io/rig_degrees.rs`), and above
/// which a point of a model with no camber range is said
/// (`jobs/tyre_eval/camber.rs`): none of the thirteen public `.tir` files
/// states a camber range beyond 15.1° (`CAMMAX` 0.264 rad).
pub const STEEP_CAMBER: f64 = 0.349_065_850_398_865_9;

/// The camber (45°, rad) beyond which any cell is refused: steeper than
/// any car tyre runs (a car's static and roll camber stay within about
/// ±10°, the public `.tir` ranges within 15.1°; a motorcycle's lean, to
/// about 55°, is no car tyre's).
pub const MOST_CAMBER: f64 = std::f64::consts::FRAC_PI_4;

/// `±20° (0.349 rad)` of a limit `limit`, rad.
fn both_units(limit: f64) -> String {
    format!(
        "±{:.0}° ({} rad)",
        limit.to_degrees(),
        crate::format::readable(limit, 3)
    )
}

/// An angle `value` of `column` beyond `limit` (rad), in words. A camber
/// is refused by one rule, said the same way by `tyre-eval` and
/// `identify`: beyond ±45° any cell (no car tyre runs there), and beyond
/// ±20° where every camber of the column other than 0 is (no car tyre is
/// tested only there: a column in degrees read in radians); a column
/// with a camber within ±20° is read in radians, a tyre file's own range
/// (a `.tir`'s `CAMMIN`/`CAMMAX`) holding it with a warning. Both
/// refusals state both limits, so that a camber refused in one file and
/// evaluated in another is said why.
pub(super) fn camber_beyond(column: &str, value: f64, limit: f64) -> String {
    let v = super::number::Num(value);
    if column != "camber" {
        return format!("{v} rad is beyond ±{:.0}°", limit.to_degrees());
    }
    let deg = crate::format::readable(value.to_degrees(), 3);
    let [steep, most] = [STEEP_CAMBER, MOST_CAMBER].map(both_units);
    if limit <= STEEP_CAMBER {
        return format!(
            "{v} rad ({deg}°) is beyond {steep}, as every camber of the column other than 0 is, where no car tyre is tested alone (no public .tir's camber range passes 15.1°); a column with a camber within ±20° is read in radians, refused only beyond {most}"
        );
    }
    format!(
        "{v} rad ({deg}°) is beyond {}, steeper than any car tyre runs; a column whose every camber other than 0 is beyond {steep} is refused too",
        both_units(limit)
    )
}
