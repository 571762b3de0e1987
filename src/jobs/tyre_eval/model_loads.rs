//! The points at a load outside the range a TOML tyre's model is meant for
//! ([`crate::tyre::LoadRange`]: a multiple of its rated or nominal load, or
//! the loads of any tyre where its parameters state none), counted and
//! said as a `.tir` file's `FZMIN` and `FZMAX` are (`ranges.rs`): one line
//! for each side, with the count and the first point. The model is
//! evaluated at the load given: past its range its load terms extrapolate
//! (a UniTire's force falls to nothing at 1 MN, a linear tyre gives its
//! full force at 1e-300 N). A tyre fitted to rig data whose
//! `[fitted_ranges]` give the load is held to those instead (said with
//! the other fitted ranges), and a Magic Formula file to its own ranges.
//! A Gim file whose stiffness does not depend on the load (`load_exponent
//! = 0`) but which states its `reference_load` is held to a multiple of
//! that, as the other models are to theirs; one that states none, to the
//! loads of any tyre. Loads in N.

use crate::format::{plural, readable, rounded};
use crate::io::fitted_ranges::FittedRanges;
use crate::tyre::{LoadRange, Tyre};
use serde::Serialize;
use std::path::Path;

/// The points on one side of the model's load range.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadsLeft {
    /// The range the model is meant for.
    pub range: LoadRange,
    /// The points leave it below its lower end (else above its upper).
    pub below: bool,
    /// Points outside it on that side.
    pub points: usize,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its load, N.
    pub first_value: f64,
}

/// The load range of a Gim tyre of file `path` whose stiffness holds at
/// any load, where the file states its `reference_load`: the model's own
/// range ([`crate::tyre::ModelParameters::load_range`]) is any tyre's
/// there, as the load has a default the file may not have meant (a car
/// wheel's 4 kN on a truck tyre), but a load stated is the tyre's.
fn stated_gim_load(tyre: &Tyre, path: &Path) -> Option<LoadRange> {
    let Tyre::Gim(g) = tyre else {
        return None;
    };
    let text = std::fs::read_to_string(path).ok()?;
    let stated = text
        .parse::<toml::Table>()
        .ok()?
        .contains_key("reference_load");
    (g.load_exponent == 0.0 && stated)
        .then(|| LoadRange::of_nominal("reference_load", g.reference_load))
}

/// The points of load `fz` (at file lines `lines`) outside the load range
/// of `tyre`'s model (of file `path`), below it first; none where the
/// model states no range or the tyre's `fitted` ranges give the load.
pub(crate) fn loads_left(
    (tyre, path): (&Tyre, &Path),
    fitted: Option<&FittedRanges>,
    fz: &[f64],
    lines: &[usize],
) -> Vec<LoadsLeft> {
    if fitted.is_some_and(|r| r.fz.is_some()) {
        return Vec::new();
    }
    let Some(range) = stated_gim_load(tyre, path).or_else(|| tyre.load_range()) else {
        return Vec::new();
    };
    [true, false]
        .into_iter()
        .filter_map(|below| {
            let side = |f: f64| range.outside(f) && (f < range.lo) == below;
            let rows: Vec<usize> = (0..fz.len()).filter(|&i| side(fz[i])).collect();
            let first = *rows.first()?;
            Some(LoadsLeft {
                range: range.clone(),
                below,
                points: rows.len(),
                first_line: lines.get(first).copied().unwrap_or(0),
                first_value: fz[first],
            })
        })
        .collect()
}

impl LoadsLeft {
    /// The points in words, of `count` points of a `model` tyre.
    pub fn line(&self, count: usize, model: &str) -> String {
        let r = &self.range;
        let (side, end) = match self.below {
            true => ("below", r.lo),
            false => ("above", r.hi),
        };
        format!(
            "{} of {} at a load {side} {} N, outside the loads the {model} tyre is meant for ({} to {} N: {}): evaluated at the load given, an extrapolation of the model; the first at line {}, fz = {} N",
            self.points,
            plural(count, "point", "points"),
            rounded(end, 4),
            rounded(r.lo, 4),
            rounded(r.hi, 4),
            r.basis,
            self.first_line,
            readable(self.first_value, 3)
        )
    }
}
