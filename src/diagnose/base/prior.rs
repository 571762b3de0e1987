//! What is known of a car's axles before its runs are seen: a prior on the
//! axle characteristics identified from the runs
//! ([`crate::diagnose::base::identify`]), by tyre class or as explicit
//! ranges, and the rule that holds the peak friction where the runs never
//! approach it.
//!
//! **The prior** ([`crate::diagnose::campaign::prior`]) enters a fit as
//! one row `(ln x − ln centre)/σ` per characteristic appended to the scaled
//! data residuals (a regularised, maximum a posteriori fit); the data's
//! cost, the BIC and every reported error leave the rows out
//! ([`PriorRows`]).
//!
//! **Peak friction held.** Runs that stay well below the limit do not show
//! the peak: `D` then only sets the curvature of the axle curve where the
//! runs never go, and a fit left free to move it makes it a knob that
//! soaks up whatever the model lacks. The rule ([`FrictionRule`]): `D` is
//! fitted (with its prior) where the runs' 99.5th percentile of `|ay|`
//! (the accelerometer's, else `u·r`) reaches [`FREE_SHARE`] of the
//! prior's lowest grip, `FREE_SHARE·lo·g`; else it is held at the prior's
//! centre (a row of width `HELD_WIDTH` in `ln D`, [`PriorRows`]), and the report says so.
//!
//! Units: SI, rad; k in 1/rad, D dimensionless.

use crate::constants::G;
use crate::diagnose::base::no_tyre::{NoTyre, AXLE_NAMES};
use crate::diagnose::campaign::prior::{AxlePrior, Z95};
pub use crate::diagnose::fit::prior_rows::PriorRows;
pub use crate::diagnose::fit::tempering::Tempering;
use crate::diagnose::model::axles::{coefficient, friction};
use crate::measured::MeasuredRun;
use serde::Serialize;

/// The share of the prior's lowest grip (`lo·g`) the runs' lateral
/// acceleration must reach before the peak friction is fitted: below it
/// the axle curves are straight lines the peak does not bend.
pub const FREE_SHARE: f64 = 0.8;

/// Percentile of `|ay|` the friction rule takes: the largest acceleration
/// the runs hold, not a glitch's single sample.
pub const AY_PERCENTILE: f64 = 99.5;

/// Standard deviations (in `ln x`) beyond which an axle characteristic is
/// no tyre of the prior's class: outside its 99.9 % range. A prior's 95 %
/// range may be somewhat off for a given car; this far off, the data pull
/// the axles to stand in for something the model lacks.
pub const OUTSIDE_PRIOR: f64 = 3.29;

/// Whether the peak friction is fitted, by the largest lateral
/// acceleration the runs hold against the prior's lowest grip.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FrictionRule {
    /// The runs' 99.5th percentile of `|ay|`, m/s².
    pub ay: f64,
    /// What it must reach for the peak friction to be fitted,
    /// `FREE_SHARE·lo·g`, m/s².
    pub threshold: f64,
    /// Whether the peak friction is fitted (else held at the prior's
    /// centre).
    pub free: bool,
    /// The value it is held at, or the prior's centre when free.
    pub value: f64,
}

impl FrictionRule {
    /// The rule for runs whose `|ay|` percentile is `ay` under `prior`.
    pub fn new(prior: &AxlePrior, ay: f64) -> Self {
        let threshold = FREE_SHARE * prior.friction[0] * G;
        Self {
            ay,
            threshold,
            free: ay >= threshold,
            value: AxlePrior::centre(prior.friction),
        }
    }

    /// The rule for the runs: the accelerometer's `|ay|` where logged,
    /// else `|u·r|`, pooled over the runs' samples.
    pub fn of_runs(prior: &AxlePrior, runs: &[MeasuredRun]) -> Self {
        let mut a: Vec<f64> = runs
            .iter()
            .flat_map(|r| -> Vec<f64> {
                match &r.ay {
                    Some(ay) => ay.iter().map(|x| x.abs()).collect(),
                    None => r
                        .speed
                        .iter()
                        .zip(&r.yaw_rate)
                        .map(|(u, w)| (u * w).abs())
                        .collect(),
                }
            })
            .filter(|x| x.is_finite())
            .collect();
        a.sort_by(f64::total_cmp);
        let ay = if a.is_empty() {
            0.0
        } else {
            let i = (AY_PERCENTILE / 100.0 * (a.len() - 1) as f64).round() as usize;
            a[i.min(a.len() - 1)]
        };
        Self::new(prior, ay)
    }
}

/// One axle characteristic against its prior.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AgainstPrior {
    /// Its value (1/rad, or dimensionless for the friction).
    pub value: f64,
    /// The prior's 95 % range.
    pub range: [f64; 2],
    /// Standard deviations from the prior's centre, in `ln x`.
    pub z: f64,
    /// Whether it lies within the 95 % range.
    pub within: bool,
}

impl AgainstPrior {
    /// `value` against `range`.
    pub fn new(value: f64, range: [f64; 2]) -> Self {
        let z = AxlePrior::z(range, value);
        Self {
            value,
            range,
            z,
            within: z.abs() <= Z95,
        }
    }
}

/// The prior of an identified base, the friction rule, and where the
/// identified axles lie against it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PriorReport {
    /// The prior.
    pub prior: AxlePrior,
    /// Whether the peak friction was fitted, and why.
    pub friction_rule: FrictionRule,
    /// Front coefficient, rear coefficient, peak friction against it.
    pub against: [AgainstPrior; 3],
    /// How the runs weighed against it in the fits.
    pub tempering: Tempering,
}

impl PriorReport {
    /// The report of shares `p` (`[s_f, s_r, t]`) under `prior` and `rule`.
    pub fn new(prior: AxlePrior, rule: FrictionRule, p: &[f64]) -> Self {
        Self {
            prior,
            friction_rule: rule,
            against: [
                AgainstPrior::new(coefficient(p[0]), prior.cornering),
                AgainstPrior::new(coefficient(p[1]), prior.cornering),
                AgainstPrior::new(friction(p[2]), prior.friction),
            ],
            tempering: Tempering::NONE,
        }
    }

    /// The same report with the fits' `tempering`.
    pub fn with_tempering(self, tempering: Tempering) -> Self {
        Self { tempering, ..self }
    }

    /// Whether every axle characteristic lies within its prior's range.
    pub fn within(&self) -> bool {
        self.against.iter().all(|a| a.within)
    }

    /// The characteristics beyond [`OUTSIDE_PRIOR`] standard deviations
    /// (a held friction is where the prior put it).
    pub fn far_outside(&self) -> Vec<NoTyre> {
        self.against
            .iter()
            .zip(AXLE_NAMES)
            .take(if self.friction_rule.free { 3 } else { 2 })
            .filter(|(a, _)| a.z.abs() > OUTSIDE_PRIOR)
            .map(|(a, parameter)| NoTyre::OutsidePrior {
                parameter,
                value: a.value,
                range: a.range,
                z: a.z,
            })
            .collect()
    }
}

/// The prior's rows of `prior` with the peak friction by `rule`, on axle
/// shares at `offset` of a fit's vector.
pub fn rows(prior: &AxlePrior, rule: &FrictionRule, offset: usize) -> PriorRows {
    PriorRows::new(prior, (!rule.free).then_some(rule.value), offset)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::campaign::prior::TyreClass;
    use crate::diagnose::model::axles::shares;

    #[test]
    fn friction_is_fitted_only_where_the_runs_reach_eight_tenths_of_the_lowest_grip() {
        let road = AxlePrior::of(TyreClass::Road);
        // 0.8 · 0.8 · g = 6.28 m/s².
        let below = FrictionRule::new(&road, 6.2);
        assert!(!below.free);
        assert!((below.threshold - 0.64 * G).abs() < 1e-12);
        assert!((below.value - (0.8f64 * 1.05).sqrt()).abs() < 1e-12);
        assert!(FrictionRule::new(&road, 6.3).free);
    }

    #[test]
    fn the_rows_are_zero_at_the_centre_and_one_per_standard_deviation_off_it() {
        let prior = AxlePrior::of(TyreClass::Road);
        let rule = FrictionRule::new(&prior, 9.0);
        let rows = rows(&prior, &rule, 1);
        let k0 = AxlePrior::centre(prior.cornering);
        let d0 = AxlePrior::centre(prior.friction);
        let sk = AxlePrior::sigma_ln(prior.cornering);
        let p = |kf: f64, kr: f64, d: f64| {
            let mut v = vec![0.3];
            v.extend(shares(kf, kr, d));
            v
        };
        let mut r = [0.0; 3];
        rows.write(&p(k0, k0, d0), &mut r);
        assert!(r.iter().all(|x| x.abs() < 1e-9), "{r:?}");
        rows.write(&p(k0 * sk.exp(), k0 / sk.exp(), d0), &mut r);
        assert!(
            (r[0] - 1.0).abs() < 1e-9 && (r[1] + 1.0).abs() < 1e-9,
            "{r:?}"
        );
    }

    #[test]
    fn the_rows_jacobian_matches_their_differences() {
        let prior = AxlePrior::of(TyreClass::RacingSlick);
        for rule in [
            FrictionRule::new(&prior, 20.0),
            FrictionRule::new(&prior, 1.0),
        ] {
            let rows = rows(&prior, &rule, 0);
            let p = vec![0.55, 0.7, 0.6, 0.01];
            let j = rows.jacobian(&p, 4);
            for c in 0..4 {
                let h = 1e-7;
                let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
                let mut q = p.clone();
                q[c] += h;
                rows.write(&q, &mut a);
                q[c] -= 2.0 * h;
                rows.write(&q, &mut b);
                for i in 0..3 {
                    let fd = (a[i] - b[i]) / (2.0 * h);
                    assert!(
                        (fd - j[(i, c)]).abs() <= 1e-5 * (1.0 + fd.abs()),
                        "row {i} col {c}: {fd} against {}",
                        j[(i, c)]
                    );
                }
            }
        }
    }

    #[test]
    fn a_held_friction_starts_the_grid_at_its_value() {
        let prior = AxlePrior::of(TyreClass::Truck);
        let held = rows(&prior, &FrictionRule::new(&prior, 1.0), 0);
        let t = held.grid_friction(0.8);
        assert!((friction(t) - AxlePrior::centre(prior.friction)).abs() < 1e-12);
        let free = rows(&prior, &FrictionRule::new(&prior, 9.0), 0);
        assert_eq!(free.grid_friction(0.8), 0.8);
    }
}
