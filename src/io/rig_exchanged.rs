//! A rig file's negative loads: every load negative is a sign convention
//! (SAE's z axis points down); an `fz` column shaped as a lateral force
//! beside an `fy` column shaped as loads is the two columns exchanged; any
//! other negative load is a bad sample, refused at its cell (row, line,
//! column, value). Loads in N, ISO 8855 (a load is positive).
//!
//! The exchange is told by the columns' shapes, not by a share of
//! negative samples (fresh-eyes round 39: one row of three at −4000 N
//! beside an `fy` of 500, 900, 1300 N was refused as an exchange):
//! - `fz` reads as a lateral force over a slip-angle sweep: both signs on
//!   a good share of samples each ([`EXCHANGED_SHARE`]), extremes of
//!   about one size ([`SYMMETRY`]), and no hole around zero (its values
//!   fill its range: a force crosses zero continuously, while loads with
//!   some signs flipped leave a gap of twice the lightest load);
//! - `fy` reads as loads: positive throughout, at levels (values grouped,
//!   each group [`LEVEL_SAMPLES`] samples on average).

use super::columns::Columns;
use crate::error::{InputError, InputProblem, LoadAndForceExchanged, EXCHANGED_SHARE};
use std::path::Path;

/// The least ratio of the smaller extreme of `fz` to the larger (in size)
/// read as a force swept both ways: a slip sweep reaches about the same
/// force either side (a tyre's asymmetry, conicity and ply steer, is a
/// few %); a third allows a sweep offset from zero.
const SYMMETRY: f64 = 1.0 / 3.0;

/// The largest gap between successive sorted `fz` values, as a share of
/// their range, of a column that fills its range: a sweep of 10 angles
/// leaves gaps of about a ninth; loads of one level with some signs
/// flipped leave one of the whole range.
const FILLED_GAP: f64 = 0.25;

/// The gap between successive sorted `fy` values, as a share of the
/// largest, that parts two load levels: a rig's levels differ by a
/// quarter of the largest or more (TTC's 222 to 1557 N), a level's own
/// scatter is a few %.
const LEVEL_GAP: f64 = 0.05;

/// The fewest samples per level on average of a column at load levels: a
/// rig holds each load over a sweep of slip angles.
const LEVEL_SAMPLES: usize = 4;

/// The refusals of the negative loads of `fz` (read from `c`): one for
/// `fz` and `fy` exchanged, at the first negative load, or one per
/// negative load.
pub(super) fn negative_loads(path: &Path, c: &Columns, fz: &[f64]) -> Vec<InputError> {
    let finite: Vec<f64> = fz.iter().copied().filter(|v| v.is_finite()).collect();
    let negative = finite.iter().filter(|v| **v < 0.0).count();
    let Some(first) = fz.iter().position(|v| *v < 0.0) else {
        return Vec::new();
    };
    if let Some(e) = exchanged(c.get("fy"), &finite, negative) {
        return vec![c.error_at(path, first, "fz", e.into())];
    }
    let every = negative == finite.len();
    fz.iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite() && **v < 0.0)
        .map(|(i, &value)| c.error_at(path, i, "fz", InputProblem::NegativeLoad { value, every }))
        .collect()
}

/// `fz` and `fy` exchanged: `fz` (its finite values, `negative` of them
/// below zero) shaped as a swept lateral force, `fy` as loads.
fn exchanged(fy: Option<&[f64]>, fz: &[f64], negative: usize) -> Option<LoadAndForceExchanged> {
    let fy = fy?;
    if fy.iter().any(|v| !v.is_finite() || *v <= 0.0) || !at_levels(fy) {
        return None;
    }
    let (lo, hi) = range(fz);
    let share = |k: usize| k as f64 / fz.len().max(1) as f64;
    let positive = fz.iter().filter(|v| **v > 0.0).count();
    let both = share(negative) >= EXCHANGED_SHARE && share(positive) >= EXCHANGED_SHARE;
    let symmetric = lo < 0.0 && hi > 0.0 && (-lo).min(hi) >= SYMMETRY * (-lo).max(hi);
    if !(both && symmetric && fills_range(fz)) {
        return None;
    }
    Some(LoadAndForceExchanged {
        negative,
        samples: fz.len(),
        fz: (lo, hi),
        fy: range(fy),
    })
}

/// The smallest and largest of `v`.
fn range(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(*x), hi.max(*x))
        })
}

/// `v` sorted (finite values).
fn sorted(v: &[f64]) -> Vec<f64> {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    s
}

/// Whether `v` fills its range: no gap between successive sorted values
/// above [`FILLED_GAP`] of the range.
fn fills_range(v: &[f64]) -> bool {
    let s = sorted(v);
    let (lo, hi) = range(v);
    let span = hi - lo;
    span > 0.0 && s.windows(2).all(|w| w[1] - w[0] <= FILLED_GAP * span)
}

/// Whether positive `v` lies at levels: its sorted values grouped where
/// successive ones part by more than [`LEVEL_GAP`] of the largest, each
/// group [`LEVEL_SAMPLES`] samples on average.
fn at_levels(v: &[f64]) -> bool {
    let s = sorted(v);
    let Some(&top) = s.last() else {
        return false;
    };
    let levels = 1 + s
        .windows(2)
        .filter(|w| w[1] - w[0] > LEVEL_GAP * top)
        .count();
    levels * LEVEL_SAMPLES <= s.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lateral force over a sweep of ±0.1 rad at `loads`, with the loads.
    fn sweep(loads: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let (mut force, mut load) = (Vec::new(), Vec::new());
        for &fz in loads {
            for i in 0..41 {
                let alpha = (f64::from(i) - 20.0) * 0.005;
                force.push(-1.1 * fz * (12.0 * alpha).atan() * 2.0 / std::f64::consts::PI);
                load.push(fz);
            }
        }
        (force, load)
    }

    fn negatives(v: &[f64]) -> usize {
        v.iter().filter(|x| **x < 0.0).count()
    }

    /// A sweep's force under `fz` and its loads under `fy` is the exchange,
    /// with the columns' ranges.
    #[test]
    fn a_force_sweep_under_fz_beside_loads_under_fy_is_an_exchange() {
        let (force, load) = sweep(&[2000.0, 4000.0]);
        let e = exchanged(Some(&load), &force, negatives(&force)).expect("an exchange");
        assert_eq!((e.negative, e.samples), (40, 82));
        assert_eq!(e.fy, (2000.0, 4000.0));
        assert!(
            (e.fz.0 + e.fz.1).abs() < 1e-9 && e.fz.1 > 2000.0,
            "{:?}",
            e.fz
        );
    }

    /// Round 39's file: one row of three at −4000 N, `fy` of 500, 900 and
    /// 1300 N (no levels) is a bad row, not an exchange; nor is it with
    /// `fy` at one level (the `fz` column has a hole around zero: loads
    /// with a sign flipped, no force swept through zero).
    #[test]
    fn one_negative_load_among_three_is_no_exchange() {
        let fz = [4000.0, -4000.0, 4000.0];
        assert_eq!(exchanged(Some(&[500.0, 900.0, 1300.0]), &fz, 1), None);
        let level = [3000.0; 3];
        assert_eq!(exchanged(Some(&level), &fz, 1), None);
        // The shape, not the count: loads of two levels, a third of them
        // flipped, beside a one-sided force at levels, still no exchange.
        let (force, load) = sweep(&[2000.0, 4000.0]);
        let flipped: Vec<f64> = load
            .iter()
            .enumerate()
            .map(|(i, v)| if i % 3 == 0 { -v } else { *v })
            .collect();
        let one_sided: Vec<f64> = (0..force.len())
            .map(|i| 1000.0 * (1 + i / 41) as f64)
            .collect();
        assert_eq!(
            exchanged(Some(&one_sided), &flipped, negatives(&flipped)),
            None
        );
        // A force swept one way only is no exchange either.
        let half: Vec<f64> = force.iter().map(|f| f.abs() - 100.0).collect();
        assert_eq!(exchanged(Some(&load), &half, negatives(&half)), None);
        // And the sweep beside an `fy` that is no loads (it changes sign).
        assert_eq!(exchanged(Some(&force), &force, negatives(&force)), None);
    }

    /// The levels of a column: two loads of 41 samples each are levels;
    /// three values of one sample each are not.
    #[test]
    fn loads_held_over_a_sweep_are_levels() {
        let (_, load) = sweep(&[2000.0, 4000.0]);
        assert!(at_levels(&load));
        assert!(!at_levels(&[500.0, 900.0, 1300.0]));
        assert!(fills_range(&sweep(&[4000.0]).0));
        assert!(!fills_range(&[4000.0, -4000.0, 4000.0]));
    }
}
