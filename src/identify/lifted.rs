//! Samples of a rig file at a load near zero: a rig logs `fz` ≈ 0 while
//! the wheel is lifted between sweeps. Grouped as they were, five such
//! rows became a "0 N" test condition of one point whose σ was NaN (its
//! measured force 0), and a second load level that freed a one-load fit's
//! load law (GIM's `load_exponent` went to its bound). No tyre test is run
//! at a load that small beside its others, so they are set aside before
//! the grouping, counted and said.
//!
//! Rule: a sample whose load is below [`LIFTED_SHARE`] of the file's
//! median load (N) is a lifted wheel's. Units: N.

use super::data::RigData;
use crate::format::{plural, readable};
use serde::Serialize;

/// The share of the median load below which a sample's load is a lifted
/// wheel's: 5 %. A rig's lightest test load is a quarter or more of its
/// median (TTC's 50 lbf beside 250 lbf is a fifth), so no load level of a
/// test lies below it.
pub const LIFTED_SHARE: f64 = 0.05;

/// The samples set aside as a lifted wheel's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Lifted {
    /// Samples set aside.
    pub samples: usize,
    /// Samples of the file.
    pub of: usize,
    /// The load below which a sample is set aside, N.
    pub below: f64,
    /// The file's median load, N.
    pub median_load: f64,
}

impl Lifted {
    /// The line saying what was set aside and by which rule.
    pub fn line(&self) -> String {
        format!(
            "{} of {} at a load near zero (fz below {} N, {} % of the median load {} N: a lifted wheel) set aside, not fitted",
            plural(self.samples, "sample", "samples"),
            self.of,
            readable(self.below, 3),
            LIFTED_SHARE * 100.0,
            readable(self.median_load, 4)
        )
    }

    /// Whether the sample at load `fz` (N) is kept.
    pub fn keeps(&self, fz: f64) -> bool {
        fz >= self.below
    }
}

/// The samples of `d` at a lifted wheel's load, if any.
pub fn lifted(d: &RigData) -> Option<Lifted> {
    let mut loads: Vec<f64> = d.fz.iter().copied().filter(|v| v.is_finite()).collect();
    if loads.is_empty() {
        return None;
    }
    let median_load = crate::measured::clean::median(&mut loads);
    let below = LIFTED_SHARE * median_load;
    let samples = d.fz.iter().filter(|&&v| v < below).count();
    (samples > 0).then_some(Lifted {
        samples,
        of: d.len(),
        below,
        median_load,
    })
}

/// `d` without the samples of a lifted wheel, and what was set aside;
/// `d` unchanged and `None` without any.
pub fn without_lifted(d: RigData) -> (RigData, Option<Lifted>) {
    match lifted(&d) {
        Some(l) => (d.rows(|i| l.keeps(d.fz[i])), Some(l)),
        None => (d, None),
    }
}

/// Rig data, its wheel moments (`mx`, `my`) and the lifted samples left out.
pub type Stripped = (RigData, [Option<Vec<f64>>; 2], Option<Lifted>);

/// [`without_lifted`] of `d` and, alike, of the wheel moments `moments`
/// read beside it (one per sample of the file, if measured).
pub fn without_lifted_moments(d: RigData, moments: [Option<Vec<f64>>; 2]) -> Stripped {
    let Some(l) = lifted(&d) else {
        return (d, moments, None);
    };
    let keep = |m: Vec<f64>| -> Vec<f64> {
        m.into_iter()
            .zip(&d.fz)
            .filter(|(_, z)| l.keeps(**z))
            .map(|(x, _)| x)
            .collect()
    };
    let moments = moments.map(|m| m.map(keep));
    (d.rows(|i| l.keeps(d.fz[i])), moments, Some(l))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_below_a_twentieth_of_the_median_are_set_aside() {
        // Median (the upper one) 1620 N: 81 N the limit.
        let fz = vec![0.0, 1600.0, 1650.0, 1700.0, 80.0, 1620.0, 1680.0, 82.0];
        let n = fz.len();
        let d = RigData {
            alpha: vec![0.0; n],
            fy: vec![0.0; n],
            camber: vec![0.0; n],
            fz,
            ..RigData::default()
        };
        let (kept, l) = without_lifted(d);
        let l = l.unwrap();
        assert_eq!((l.samples, l.of), (2, 8));
        assert_eq!(kept.fz, vec![1600.0, 1650.0, 1700.0, 1620.0, 1680.0, 82.0]);
    }
}
