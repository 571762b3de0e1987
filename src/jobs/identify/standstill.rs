//! Rig samples at rest (a `speed` below [`STANDSTILL`], m/s) set aside
//! before the fit of every model (the staged Magic Formula's and the
//! swarm models': a slip at rest is no tyre's state whatever the model),
//! counted and said. A slip is a slip
//! velocity over the speed (`κ = −Vsx/|Vx|`, `tan α = −Vsy/|Vx|`), so a
//! slip at zero speed is no state a tyre is in; and the Magic Formula's
//! aligning moment at rest loses its trail term (`t ∝ Vcx/(Vc + εV)`,
//! Pacejka 2012 eq. 4.E6a), so such rows pull the fit to a moment no
//! rolling tyre has. Every tenth row of a noise-free rig file set to
//! speed 0 moved the fit's σ from 0.003 % to 0.498 % unsaid. The rule is
//! `tyre-eval`'s ([`STANDSTILL`], `jobs/tyre_eval/standstill.rs`).
//! Units: m/s, N.

use crate::format::{plural, readable};
use crate::identify::data::RigData;
use crate::jobs::tyre_eval::STANDSTILL;

/// The samples of a rig file at rest, set aside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct AtRest {
    /// Samples set aside.
    pub(super) samples: usize,
    /// Of them, those at a slip angle or slip ratio ≠ 0.
    pub(super) with_slip: usize,
    /// Samples of the file (after a lifted wheel's).
    pub(super) of: usize,
    /// The first one's load (N) and slip angle (rad).
    pub(super) first: (f64, f64),
}

impl AtRest {
    /// The line saying what was set aside and why, of a Magic Formula
    /// fit (its aligning moment at rest said too).
    pub(super) fn line(&self) -> String {
        self.line_of(true)
    }

    /// [`Self::line`] of a fit of any model (`mf`: a Magic Formula's).
    pub(super) fn line_of(&self, mf: bool) -> String {
        let (fz, alpha) = self.first;
        let trail = match mf {
            true => ", and a Magic Formula's aligning moment at rest has no trail term",
            false => "",
        };
        format!(
            "{} of {} at rest (speed below {STANDSTILL} m/s; the first at fz = {} N, alpha = {} rad), {} at a slip angle or slip ratio ≠ 0, set aside, not fitted: a slip at zero speed is not a physical state (κ and tan α are slip velocities over the speed){trail}; give the wheel's speed",
            plural(self.samples, "sample", "samples"),
            self.of,
            readable(fz, 4),
            readable(alpha, 4),
            self.with_slip,
        )
    }
}

/// `d` and its wheel moments without the samples at rest, and what was set
/// aside; unchanged and `None` without a `speed` column or such samples.
pub(super) fn without_rest(
    d: RigData,
    moments: [Option<Vec<f64>>; 2],
) -> (RigData, [Option<Vec<f64>>; 2], Option<AtRest>) {
    let Some(speed) = d.speed.clone() else {
        return (d, moments, None);
    };
    let at_rest = |i: usize| speed[i].abs() < STANDSTILL;
    let rest: Vec<usize> = (0..d.len()).filter(|&i| at_rest(i)).collect();
    let Some(&first) = rest.first() else {
        return (d, moments, None);
    };
    let kappa = |i: usize| d.longitudinal.as_ref().map_or(0.0, |(k, _)| k[i]);
    let with_slip = rest
        .iter()
        .filter(|&&i| d.alpha[i] != 0.0 || kappa(i) != 0.0)
        .count();
    let found = AtRest {
        samples: rest.len(),
        with_slip,
        of: d.len(),
        first: (d.fz[first], d.alpha[first]),
    };
    let keep = |m: Vec<f64>| -> Vec<f64> {
        m.into_iter()
            .enumerate()
            .filter(|(i, _)| !at_rest(*i))
            .map(|(_, x)| x)
            .collect()
    };
    let moments = moments.map(|m| m.map(keep));
    (d.rows(|i| !at_rest(i)), moments, Some(found))
}
