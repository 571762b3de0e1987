//! The vehicle file's axle distances checked against the runs before any
//! candidate is fitted: `a` (centre of gravity to the front axle) and `b`
//! (to the rear) exchanged is a slip that conventions invite (`lf`/`lr`,
//! "front" measured from the front bumper), and the diagnosis cannot
//! recover from it: the static axle loads, the yaw moment arms and the
//! default load-transfer split (b/l) all change, the base model's
//! understeer changes sign or size, and the candidates bend to explain it
//! (a tester's campaign with `a` and `b` exchanged ran 172 s to a
//! three-effect verdict removing 95 % of a gap the exchange made).
//!
//! The check replays every run once more with `a` and `b` exchanged, the
//! tyres as they are, and compares the combined errors `J` (channels over
//! their trusted scales, as the candidates are scored). It runs only where the
//! base model's tyres are fixed (given as files, or fitted to rig data):
//! with axles identified from the runs, the per-unit-load cornering
//! coefficients re-fit around either geometry and one replay says
//! nothing. Units: SI, m, rad; J dimensionless.

use crate::diagnose::campaign::Campaign;
use crate::diagnose::model::channels::{gap_above, reduction, ChannelErrors};
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::Augmented;
use crate::error::DiagnosisError;
use rayon::prelude::*;

/// The share (%) of the base model's gap above noise that exchanging `a`
/// and `b` must remove for the vehicle file to be refused: a candidate
/// effect is accepted at 30 %; a geometry that, with no parameter fitted,
/// removes most of the gap is a file the runs contradict.
pub(crate) const SWAP_REMOVES: f64 = 70.0;

/// The base model's gap must be at least this many noise levels for the
/// check to judge (within noise, either geometry replays the runs).
const SIGNIFICANT: f64 = 3.0;

/// The combined errors of the base model and of the same model with `a`
/// and `b` exchanged, over every run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Exchanged {
    /// The vehicle file's `a` and `b`, m.
    pub(crate) a: f64,
    pub(crate) b: f64,
    /// Combined error J of the base model as given, and exchanged.
    pub(crate) given: f64,
    pub(crate) exchanged: f64,
    /// J of the noise alone.
    pub(crate) noise: f64,
}

impl Exchanged {
    /// The share (%) of the given geometry's gap above noise the exchange
    /// removes (negative where it adds).
    pub(crate) fn removes(&self) -> f64 {
        reduction(self.given, self.exchanged, self.noise)
    }

    /// Whether the runs contradict the vehicle file's `a` and `b`: the
    /// base model's gap is significant and exchanging them removes at
    /// least [`SWAP_REMOVES`] % of it.
    pub(crate) fn contradicted(&self) -> bool {
        gap_above(self.given, self.noise) >= SIGNIFICANT * self.noise
            && self.removes() >= SWAP_REMOVES
    }
}

/// The combined error over `runs` of `model`, and the noise level of
/// `floors`, both on `scales`.
fn errors(model: &Augmented, runs: &[Prepared]) -> ChannelErrors {
    runs.par_iter()
        .map(|r| r.errors(model))
        .reduce(ChannelErrors::default, |mut a, b| {
            a.add(&b);
            a
        })
}

/// The noise level `J_n` of channel floors `floors` over the samples
/// counted in `e`, on `scales`.
fn noise_level(e: &ChannelErrors, floors: &[f64; 3], scales: &[f64; 3]) -> f64 {
    let n: usize = e.count.iter().sum();
    let s: f64 = (0..3)
        .map(|i| e.count[i] as f64 * (floors[i] / scales[i]).powi(2))
        .sum();
    (s / n.max(1) as f64).sqrt()
}

/// The base model `base` against itself with `a` and `b` exchanged on
/// `runs`; `None` where they are equal (nothing to exchange).
pub(crate) fn exchanged(
    base: &Augmented,
    runs: &[Prepared],
    floors: &[f64; 3],
    scales: &[f64; 3],
) -> Option<Exchanged> {
    let v = &base.model.vehicle;
    if (v.a - v.b).abs() < 0.02 * (v.a + v.b) {
        return None;
    }
    let mut swapped = base.clone();
    std::mem::swap(&mut swapped.model.vehicle.a, &mut swapped.model.vehicle.b);
    let given = errors(base, runs);
    let other = errors(&swapped, runs);
    Some(Exchanged {
        a: v.a,
        b: v.b,
        given: given.combined(scales),
        exchanged: other.combined(scales),
        noise: noise_level(&given, floors, scales),
    })
}

/// Refuses a campaign whose `a` and `b` the runs contradict
/// ([`exchanged`]), naming the line of the file that states `a`.
pub(crate) fn check(
    c: &Campaign,
    base: &Augmented,
    runs: &[Prepared],
    (floors, scales): (&[f64; 3], &[f64; 3]),
) -> Result<(), DiagnosisError> {
    let Some(x) = exchanged(base, runs, floors, scales) else {
        return Ok(());
    };
    if !x.contradicted() {
        return Ok(());
    }
    let at = match &c.a_at {
        Some((file, line)) => format!("{}:{line}", file.display()),
        None => c.source.display().to_string(),
    };
    Err(DiagnosisError::AxleDistancesExchanged {
        at,
        a: x.a,
        b: x.b,
        given: x.given,
        exchanged: x.exchanged,
        noise: x.noise,
        removes: x.removes(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(given: f64, exchanged: f64) -> Exchanged {
        Exchanged {
            a: 1.67,
            b: 1.11,
            given,
            exchanged,
            noise: 1.0,
        }
    }

    #[test]
    fn an_exchange_removing_most_of_a_large_gap_contradicts_the_file() {
        assert!(at(23.6, 2.0).contradicted());
    }

    #[test]
    fn an_exchange_removing_less_than_the_rule_does_not() {
        // 10 → 6.2: the gap above noise 9.95 → 6.12, 38 % removed.
        let e = at(10.0, 6.2);
        assert!((e.removes() - 38.5).abs() < 1.0, "{}", e.removes());
        assert!(!e.contradicted());
    }

    #[test]
    fn a_gap_within_a_few_noise_levels_is_not_judged() {
        // The exchange removes all of it, but the gap is 2.8 noise levels.
        assert!(!at(3.0, 1.0).contradicted());
    }
}
