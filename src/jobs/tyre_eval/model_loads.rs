//! The points at a load outside the range a TOML tyre's model is meant for
//! ([`crate::tyre::LoadRange`]: a multiple of its rated or nominal load, or
//! the loads of any tyre where its parameters state none), counted and
//! said as a `.tir` file's `FZMIN` and `FZMAX` are (`ranges.rs`): one line
//! for each side, with the count and the first point. The model is
//! evaluated at the load given: past its range its load terms extrapolate
//! (a UniTire's force falls to nothing at 1 MN, a linear tyre gives its
//! full force at 1e-300 N). A tyre fitted to rig data whose
//! `[fitted_ranges]` give the load is held to those instead (said with
//! the other fitted ranges), and a Magic Formula file to its own ranges;
//! but a model with no load term (a linear tyre, `Fy = Cα·α`) has its
//! fitted loads said here: its cornering stiffness is the tyre's at the
//! loads it was fitted at, and at another load the model gives the same
//! force without a word, where every other model's fitted range is said
//! (a load past them by more than [`SLACK`] of their span, as those are).
//! A Gim file whose stiffness does not depend on the load (`load_exponent
//! = 0`) but which states its `reference_load` is held to a multiple of
//! that, as the other models are to theirs; one that states none, to the
//! loads of any tyre. Loads in N.

use crate::format::{plural, readable, rounded};
use crate::io::fitted_ranges::{past_by, FittedRanges, SLACK};
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
    /// The range is the loads the tyre was fitted at (its
    /// `[fitted_ranges]`), of a model with no load term (a linear tyre).
    pub fitted: bool,
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
    if let Some([lo, hi]) = fitted.and_then(|r| r.fz) {
        // A model that reads the load has its fitted load range said with
        // the other fitted ranges; one that reads none (a linear tyre) is
        // said here, past the same slack.
        if super::reads::reads(tyre, fitted).fz {
            return Vec::new();
        }
        let range = LoadRange {
            lo,
            hi,
            basis: "its [fitted_ranges]".to_string(),
        };
        let side = |f: f64, below: bool| f > 0.0 && past_by([lo, hi], f, SLACK) == Some(below);
        return on_each_side(&range, true, &side, fz, lines);
    }
    let Some(range) = stated_gim_load(tyre, path).or_else(|| tyre.load_range()) else {
        return Vec::new();
    };
    let side = |f: f64, below: bool| range.outside(f) && (f < range.lo) == below;
    on_each_side(&range, false, &side, fz, lines)
}

/// The points of load `fz` on each side of `range` (`side(f, below)`),
/// below first.
fn on_each_side(
    range: &LoadRange,
    fitted: bool,
    side: &dyn Fn(f64, bool) -> bool,
    fz: &[f64],
    lines: &[usize],
) -> Vec<LoadsLeft> {
    [true, false]
        .into_iter()
        .filter_map(|below| {
            let rows: Vec<usize> = (0..fz.len()).filter(|&i| side(fz[i], below)).collect();
            let first = *rows.first()?;
            Some(LoadsLeft {
                range: range.clone(),
                below,
                points: rows.len(),
                first_line: lines.get(first).copied().unwrap_or(0),
                first_value: fz[first],
                fitted,
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
        let (lo, hi) = (rounded(r.lo, 4), rounded(r.hi, 4));
        let outside = if self.fitted {
            format!("was fitted at (its [fitted_ranges]: {lo} to {hi} N): the {model} model has no load term, so there it gives the force of the cornering stiffness fitted at those loads, unchanged, where a tyre's stiffness changes with its load")
        } else {
            format!(
                "is meant for ({lo} to {hi} N: {}): evaluated at the load given, an extrapolation of the model",
                r.basis
            )
        };
        format!(
            "{} of {} at a load {side} {} N, outside the loads the {model} tyre {outside}; the first at line {}, fz = {} N",
            self.points,
            plural(count, "point", "points"),
            rounded(end, 4),
            self.first_line,
            readable(self.first_value, 3)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::Linear;

    /// A linear tyre fitted at 3000–5000 N: 12 kN and 500 N are said, each
    /// side apart with its first line; 4 kN and 5020 N (within 1 % of the
    /// span past the end) are not; without a fitted load, nothing is.
    #[test]
    fn a_linear_tyres_fitted_loads_are_held_to_past_the_slack() {
        let t = Tyre::Linear(Linear {
            cornering_stiffness: 60e3,
            pneumatic_trail: 0.0,
        });
        let r = FittedRanges {
            fz: Some([3000.0, 5000.0]),
            ..FittedRanges::default()
        };
        let fz = [4000.0, 12_000.0, 500.0, 5020.0];
        let lines = [2, 3, 4, 5];
        let left = loads_left((&t, Path::new("t.toml")), Some(&r), &fz, &lines);
        let sides: Vec<_> = left
            .iter()
            .map(|l| (l.below, l.points, l.first_line, l.fitted))
            .collect();
        assert_eq!(sides, [(true, 1, 4, true), (false, 1, 3, true)]);
        let said = left[1].line(4, "linear");
        assert!(said.starts_with("1 of 4 points at a load above 5000 N, outside the loads the linear tyre was fitted at (its [fitted_ranges]: 3000 to 5000 N)"), "{said}");
        let none = FittedRanges::default();
        assert!(
            loads_left((&t, Path::new("t.toml")), Some(&none), &[4000.0], &[2])
                .iter()
                .all(|l| !l.fitted)
        );
    }
}
