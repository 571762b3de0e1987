//! A loaded radius above the free radius, counted and said: MFeval (and
//! this evaluation, which follows it) takes the effective rolling radius
//! at the load given even past `FZMAX`, where `RΩ − (Fz0/Cz)·(DREFF·
//! atan(BREFF·Fz/Fz0) + FREFF·Fz/Fz0)` falls through 0; the wheel speed
//! `Vx/Re` and the centrifugal growth of the free radius with it blow up,
//! and `rl` jumps past the tyre's own size (2.39 m on the public
//! `fsae190_50R10.tir` at 1 MN, free radius 0.233 m). Written as MFeval
//! writes it, so that the file stays comparable, and said so that no one
//! reads it as a radius. Radii in m, loads in N.

use crate::format::{plural, readable, rounded};
use crate::tyre::Tyre;
use serde::Serialize;

/// The points whose loaded radius exceeds the free radius.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RadiusAboveFree {
    /// The file's `UNLOADED_RADIUS`, m.
    pub free: f64,
    /// Points above it.
    pub points: usize,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its load, N.
    pub first_fz: f64,
    /// Its loaded radius, m.
    pub first_rl: f64,
}

/// The points of load `fz` (at file lines `lines`) whose loaded radius
/// `rl` exceeds the free radius of a Magic Formula `tyre`.
pub fn above_free(
    tyre: &Tyre,
    rl: Option<&[f64]>,
    fz: &[f64],
    lines: &[usize],
) -> Option<RadiusAboveFree> {
    let (Tyre::MagicFormula(t), Some(rl)) = (tyre, rl) else {
        return None;
    };
    let free = t.coefficients.UNLOADED_RADIUS;
    // A point on the road: off it, the free-spinning radius is written.
    let above: Vec<usize> = (0..rl.len())
        .filter(|&i| fz[i] > 0.0 && rl[i] > free)
        .collect();
    let &i = above.first()?;
    Some(RadiusAboveFree {
        free,
        points: above.len(),
        first_line: lines[i],
        first_fz: fz[i],
        first_rl: rl[i],
    })
}

impl RadiusAboveFree {
    /// The warning, of `count` points.
    pub fn line(&self, count: usize) -> String {
        format!(
            "{} of {} on the road with a loaded radius rl above the free radius UNLOADED_RADIUS = {} m: written as MFeval gives it, at the load given, where the file's effective radius has fallen through 0 (a load far past FZMAX): no radius of the tyre; the first at line {}, fz = {} N, rl = {} m",
            self.points,
            plural(count, "point", "points"),
            rounded(self.free, 4),
            self.first_line,
            readable(self.first_fz, 3),
            readable(self.first_rl, 4)
        )
    }
}
