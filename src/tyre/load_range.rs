//! The loads a tyre model is meant for: the range its parameters say
//! something about, which `tyre-eval` holds the points against (past it a
//! model's load terms extrapolate: UniTire's friction `p6·exp(−Fzn/p7)`
//! takes its force to nothing at 1 MN, PAC89's peak `(a1·Fz + a2)·Fz`
//! turns down, a linear tyre gives its full force at 1e-300 N).
//!
//! A model with a nominal (rated, reference) load states
//! [`LIGHT_SHARE`]`…`[`HEAVY_SHARE`] of it: the public Magic Formula files
//! give `FZMAX` 1.7–2.7 times their `FNOMIN`, and `tyre-eval` already says a
//! Magic Formula load below 1 % of `FNOMIN`. A model whose parameters say
//! no load (a linear tyre, the simplified Magic Formula, a Gim tyre of
//! load-independent stiffness) states the loads of any tyre,
//! [`super::sizes::TYRE_LOAD`]. Loads in N.

use serde::Serialize;

/// The lightest load a model is meant for, as a share of its nominal load.
pub const LIGHT_SHARE: f64 = 0.01;

/// The heaviest load a model is meant for, as a multiple of its nominal
/// load (above the 1.7–2.7 of the public `.tir` files' `FZMAX/FNOMIN`).
pub const HEAVY_SHARE: f64 = 3.0;

/// The loads a model is meant for, with what they come from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadRange {
    /// Lightest load, N.
    pub lo: f64,
    /// Heaviest load, N.
    pub hi: f64,
    /// What the range comes from, in words (a key of the model's file and
    /// its value, or the loads of any tyre).
    pub basis: String,
}

impl LoadRange {
    /// [`LIGHT_SHARE`]`…`[`HEAVY_SHARE`] of the nominal load `nominal`,
    /// the file's key `key`.
    pub fn of_nominal(key: &str, nominal: f64) -> Self {
        Self {
            lo: LIGHT_SHARE * nominal,
            hi: HEAVY_SHARE * nominal,
            basis: format!(
                "{} % to {} times its {key} = {} N",
                crate::format::rounded(100.0 * LIGHT_SHARE, 2),
                crate::format::rounded(HEAVY_SHARE, 2),
                crate::format::rounded(nominal, 6)
            ),
        }
    }

    /// The loads of any tyre, for a model whose parameters say none.
    pub fn any_tyre(model: &str) -> Self {
        let (lo, hi) = super::sizes::TYRE_LOAD;
        Self {
            lo,
            hi,
            basis: format!(
                "the loads of any tyre, a bicycle's to a mining truck's: the {model} model's parameters state no load of their own"
            ),
        }
    }

    /// True when the positive load `fz` lies outside the range (a wheel
    /// off the road, `fz ≤ 0`, is said apart).
    pub fn outside(&self, fz: f64) -> bool {
        fz > 0.0 && (fz < self.lo || fz > self.hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_nominal_load_gives_one_percent_to_three_times_it() {
        let r = LoadRange::of_nominal("rated_load", 5700.0);
        assert_eq!((r.lo, r.hi), (57.0, 17_100.0));
        assert!(r.basis.contains("rated_load = 5700 N"), "{}", r.basis);
        assert!(r.outside(30_000.0) && r.outside(1e-300) && !r.outside(4000.0));
        assert!(!r.outside(0.0) && !r.outside(-10.0));
    }
}
