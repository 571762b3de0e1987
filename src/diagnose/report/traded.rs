//! Two parameters of one effect that trade against each other: fitted
//! together, the runs determine their sum far better than either (a steer
//! path's delay and first-order lag: at the frequencies a driver steers
//! at, a lag τ delays the response by about τ, so a pure delay of 0.10 s
//! is fitted as any split of 0.10 s between the two). The report then
//! gives their correlation and the sum with its standard error, and says
//! the split is not determined, rather than two values whose standard
//! errors each read as determined.
//!
//! The sum's variance is `σ_a² + σ_b² + 2·C_ab` of the covariance the
//! reported standard errors are the diagonal of (the block sandwich,
//! robust to residuals correlated over time; Newey & West 1987); the
//! correlation `C_ab/(σ_a·σ_b)`. Values in the parameters' common unit.

use super::values::{jackknife, ParameterValue, Traded};

/// The sum of a pair determined far better than either: its standard
/// error below this share of the smaller of theirs (for equal standard
/// errors a correlation of −0.875 or below).
pub const TRADED_SHARE: f64 = 0.5;

/// The split of a traded pair is not determined where either's standard
/// error (or its fold scatter, where larger) exceeds this share of their
/// sum: two of them span 40 % of it. A pair fitted on runs that see the
/// split (steer sines up to 0.8 Hz: delay and lag each ± 0.0006 s of a
/// 0.10 s sum) is still traded, its sum known six times better, but split.
pub const TRADED_SPLIT: f64 = 0.1;

/// Whether `p` is fitted free inside its range with a standard error.
fn plain(p: &ParameterValue) -> bool {
    !p.unseen && p.held.is_none() && p.bound.is_none() && p.determined && p.std_error > 0.0
}

/// `b` against `a` (of one effect and unit, `covariance` their robust
/// covariance, `fold_sums` the sum in each fold refit): Some where their
/// sum is determined far better than either ([`TRADED_SHARE`]).
pub fn traded(
    a: &ParameterValue,
    b: &ParameterValue,
    covariance: f64,
    fold_sums: &[f64],
) -> Option<Traded> {
    if a.unit != b.unit || !plain(a) || !plain(b) || !covariance.is_finite() {
        return None;
    }
    // The covariance is the asymptotic one's: so are the two errors.
    let (sa, sb) = (a.asymptotic_std_error, b.asymptotic_std_error);
    let variance = sa * sa + sb * sb + 2.0 * covariance;
    let correlation = (covariance / (sa * sb)).clamp(-1.0, 1.0);
    let sum = a.value + b.value;
    let spread = |p: &ParameterValue| p.std_error.max(p.fold_std_error.unwrap_or(0.0));
    (correlation < 0.0 && variance.max(0.0).sqrt() < TRADED_SHARE * sa.min(sb)).then(|| Traded {
        with: a.name.clone(),
        correlation,
        sum,
        sum_std_error: variance.max(0.0).sqrt(),
        sum_fold_std_error: jackknife(fold_sums),
        split_undetermined: spread(a).max(spread(b)) > TRADED_SPLIT * sum.abs(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::{EffectKind, Group};

    fn steer_path(name: &str, value: f64, se: f64) -> ParameterValue {
        let q = EffectKind::SteerPath
            .parameters()
            .iter()
            .find(|q| q.name == name)
            .expect("a steer path parameter");
        ParameterValue::of(Group::Effect(EffectKind::SteerPath), q, value, se)
    }

    /// Delay 0.067 ± 0.0117 s and lag 0.033 ± 0.0114 s correlated −0.99:
    /// the sum 0.100 s is known to √(0.0117² + 0.0114² − 2·0.99·0.0117·0.0114)
    /// = 0.00163 s, a seventh of either; at −0.5 it is known to 0.0116 s,
    /// no better than either, and no trade is said.
    #[test]
    fn a_pair_correlated_minus_0_99_determines_its_sum_to_its_closed_form_error() {
        let (a, b) = (
            steer_path("delay", 0.067, 0.0117),
            steer_path("lag", 0.033, 0.0114),
        );
        let t = traded(&a, &b, -0.99 * 0.0117 * 0.0114, &[0.1, 0.101, 0.099]).expect("traded");
        let closed = (0.0117f64.powi(2) + 0.0114f64.powi(2) - 2.0 * 0.99 * 0.0117 * 0.0114).sqrt();
        assert!((t.sum_std_error - closed).abs() < 1e-12, "{t:?}");
        assert!((t.sum - 0.1).abs() < 1e-12 && (t.correlation + 0.99).abs() < 1e-12);
        assert_eq!(t.with, "steer_path.delay");
        // Either's ± 0.0117 s is above a tenth of the 0.100 s sum.
        assert!(t.split_undetermined);
        let (a, b) = (
            steer_path("delay", 0.067, 0.0006),
            steer_path("lag", 0.033, 0.0006),
        );
        let split = traded(&a, &b, -0.99 * 0.0006 * 0.0006, &[]).expect("traded");
        assert!(!split.split_undetermined, "{split:?}");
        // The jackknife of 0.100, 0.101, 0.099: √(2/3·2e-6) = 0.001155.
        let j = t.sum_fold_std_error.expect("jackknife");
        assert!((j - (2.0f64 / 3.0 * 2e-6).sqrt()).abs() < 1e-12, "{j}");
        assert!(traded(&a, &b, -0.5 * 0.0006 * 0.0006, &[]).is_none());
        // A positive correlation determines the difference, not the sum.
        assert!(traded(&a, &b, 0.99 * 0.0006 * 0.0006, &[]).is_none());
    }

    #[test]
    fn a_parameter_on_a_limit_or_of_another_unit_trades_with_nothing() {
        let a = steer_path("delay", 0.067, 0.0117);
        let on_limit = steer_path("lag", 0.0, 0.0114);
        assert!(on_limit.bound.is_some());
        assert!(traded(&a, &on_limit, -0.99 * 0.0117 * 0.0114, &[]).is_none());
        let other = ParameterValue {
            unit: "rad",
            ..steer_path("lag", 0.033, 0.0114)
        };
        assert!(traded(&a, &other, -0.99 * 0.0117 * 0.0114, &[]).is_none());
    }
}
