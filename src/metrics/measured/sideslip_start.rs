//! The sideslip a measured piece holds before its step. Every metric is a
//! change from the initial window (`metrics/mod.rs`), the steady sideslip
//! too: a run that starts with sideslip (a car trimmed against conicity
//! or a bank, a sensor's zero offset) reads a steady sideslip that is not
//! the sideslip it ends at. `simulate` says so of its trim; `metrics` said
//! nothing and printed `-0.0718 deg` for a history running from 0.0513°
//! to -0.0205° (round 50). Units: rad.

use crate::measured::MeasuredRun;
use crate::metrics::{initial, MetricSettings, StepMetrics};

/// The share of the steady sideslip change a start must reach to be said:
/// below it the change and the end read alike to the table's precision
/// (a start 5 % of the change moves the end by 5 %).
const SAID_SHARE: f64 = 0.05;

/// Standard errors of the initial window's mean a start must stand from
/// zero to be said: a sensor's noise about zero is no start.
const SAID_ERRORS: f64 = 3.0;

/// The sideslip `piece` holds before its step, rad: the mean of `beta`
/// over the initial window as the metrics `m` take it (from the first
/// sample to [`initial::initial_end`]), where it stands apart from zero:
/// at least [`SAID_SHARE`] of the steady sideslip change and
/// [`SAID_ERRORS`] standard errors of that mean. None otherwise, or
/// without `beta`.
pub(super) fn sideslip_start(
    piece: &MeasuredRun,
    m: &StepMetrics,
    settings: &MetricSettings,
) -> Option<f64> {
    let (beta, change) = (piece.beta.as_ref()?, m.beta_steady?);
    let end = initial::initial_end(&piece.t, &piece.steer, settings);
    let before: Vec<f64> = (0..piece.t.len())
        .filter(|&i| piece.t[i] <= end && beta[i].is_finite())
        .map(|i| beta[i])
        .collect();
    let n = before.len() as f64;
    if n < 2.0 {
        return None;
    }
    let mean = before.iter().sum::<f64>() / n;
    let var = before.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let error = (var / n).sqrt();
    (mean.abs() >= SAID_SHARE * change.abs() && mean.abs() > SAID_ERRORS * error && mean != 0.0)
        .then_some(mean)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A piece at 0.01 s whose sideslip holds `start` (rad, with
    /// alternating noise `noise`) for 1 s, then steps by −0.02 rad.
    fn piece(start: f64, noise: f64) -> MeasuredRun {
        let t: Vec<f64> = (0..400).map(|i| f64::from(i) * 0.01).collect();
        let steer: Vec<f64> = t
            .iter()
            .map(|&x| if x < 1.0 { 0.0 } else { 0.02 })
            .collect();
        let beta: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                let jitter = if i % 2 == 0 { noise } else { -noise };
                start + jitter + if x < 1.0 { 0.0 } else { -0.02 }
            })
            .collect();
        let n = t.len();
        MeasuredRun::new("p.csv", t, vec![20.0; n], steer, vec![0.0; n]).with_beta(Some(beta))
    }

    fn said(start: f64, noise: f64) -> Option<f64> {
        let mut m = crate::metrics::applicability::tests::moderate();
        m.beta_steady = Some(-0.02);
        sideslip_start(&piece(start, noise), &m, &MetricSettings::default())
    }

    #[test]
    fn a_start_apart_from_zero_is_said_with_its_value() {
        let s = said(0.0012, 1e-4).expect("a start of 6 % of the change");
        assert!((s - 0.0012).abs() < 1e-5, "{s}");
        let s = said(-0.015, 0.0).expect("a start of 75 % of the change");
        assert!((s + 0.015).abs() < 1e-15, "{s}");
        // Below 5 % of the change, or within the noise of its mean: none.
        assert_eq!(said(0.0009, 0.0), None);
        assert_eq!(said(0.0, 1e-3), None);
        assert_eq!(said(0.0011, 0.02), None);
    }
}
