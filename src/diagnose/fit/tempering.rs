//! How much independent evidence the runs carry against a prior
//! ([`Tempering`]): a fit's data rows count every sample as an independent
//! observation with the channel's noise floor as its uncertainty, which
//! holds for white measurement noise about a right model. About a model
//! that lacks something (the reason a diagnosis runs), the scaled
//! residuals are neither unit-sized nor independent: their mean square
//! `s²` is the gap (several noise levels squared on a real log) and they
//! stay correlated over many samples (a misfit lasts as long as the
//! manoeuvre that shows it). Counted as independent unit-variance
//! samples, 20,000 of them outweigh any prior, and a fit leaves a
//! prior's range at the first small gain in fit.
//!
//! The data's cost is therefore weighed as that of `N/τ` independent
//! samples of variance `s²` (a tempered likelihood; Kennedy & O'Hagan
//! 2001 on model discrepancy, Sokal 1997 on the integrated
//! autocorrelation time), which is the same optimum as the prior's rows
//! multiplied by `√(s²·τ)` with the data's rows left as they are: the
//! costs, errors and BIC the diagnosis reports keep their meaning.
//!
//! `τ = 1 + 2 Σ_{k=1..M} ρ_k` with `ρ_k` the autocorrelation at lag `k`
//! pooled over every run and channel (uncentred: a sustained offset is
//! correlation, not a mean to remove), the window `M` the smallest with
//! `M ≥ 5·τ(M)` (Sokal's automatic window; at most 1,000 lags, so `τ` at
//! most 2,001 samples), `τ` at most the longest sequence's length. `s²` and `τ` are at least 1: white noise about a right model
//! gives the untempered fit. Units: dimensionless; τ in samples.

use serde::Serialize;

/// Sokal's window factor: the window is at least this many times `τ`.
const WINDOW_TIMES_TAU: f64 = 5.0;

/// The longest window, in lags (a misfit correlated beyond it is counted
/// as correlated over `2·MAX_LAGS + 1` samples, or a sequence's length):
/// the cost stays `MAX_LAGS` passes over the residuals on a long log.
const MAX_LAGS: usize = 1_000;

/// How the runs' residuals about a fit weigh against a prior.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tempering {
    /// Data residuals (samples over every run and channel).
    pub samples: usize,
    /// Their mean square (in noise floors squared), at least 1.
    pub residual_variance: f64,
    /// Their integrated autocorrelation time in samples, at least 1.
    pub correlation_samples: f64,
    /// `samples / correlation_samples`.
    pub effective_samples: f64,
    /// What the prior's rows are multiplied by: `√(s²·τ)`.
    pub prior_weight: f64,
}

impl Tempering {
    /// No tempering: the prior's rows as stated.
    pub const NONE: Tempering = Tempering {
        samples: 0,
        residual_variance: 1.0,
        correlation_samples: 1.0,
        effective_samples: 0.0,
        prior_weight: 1.0,
    };

    /// The tempering of scaled residuals `r`, laid out as consecutive
    /// sequences of `lengths` (each a run's channel, in time order).
    pub fn of_residuals(r: &[f64], lengths: &[usize]) -> Tempering {
        let n: usize = lengths.iter().sum();
        let r = &r[..n.min(r.len())];
        let sum_sq: f64 = r.iter().map(|x| x * x).sum();
        if r.is_empty() || !sum_sq.is_finite() || sum_sq <= 0.0 {
            return Tempering::NONE;
        }
        let variance = sum_sq / r.len() as f64;
        let longest = lengths.iter().copied().max().unwrap_or(1);
        let tau = correlation_time(r, lengths, variance, longest);
        let s2 = variance.max(1.0);
        Tempering {
            samples: r.len(),
            residual_variance: s2,
            correlation_samples: tau,
            effective_samples: r.len() as f64 / tau,
            prior_weight: (s2 * tau).sqrt(),
        }
    }
}

/// The pooled autocorrelation of the sequences at lag `k` (uncentred),
/// over `variance`.
fn autocorrelation(r: &[f64], lengths: &[usize], variance: f64, k: usize) -> f64 {
    let (mut sum, mut pairs) = (0.0, 0usize);
    let mut start = 0;
    for &len in lengths {
        let s = &r[start..start + len];
        if len > k {
            sum += s[..len - k]
                .iter()
                .zip(&s[k..])
                .map(|(a, b)| a * b)
                .sum::<f64>();
            pairs += len - k;
        }
        start += len;
    }
    if pairs == 0 {
        0.0
    } else {
        sum / pairs as f64 / variance
    }
}

/// The integrated autocorrelation time with Sokal's window, within
/// `[1, longest]`.
fn correlation_time(r: &[f64], lengths: &[usize], variance: f64, longest: usize) -> f64 {
    let mut tau = 1.0;
    for m in 1..longest.min(MAX_LAGS + 1) {
        tau += 2.0 * autocorrelation(r, lengths, variance, m);
        if m as f64 >= WINDOW_TIMES_TAU * tau {
            break;
        }
    }
    tau.clamp(1.0, longest as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::data::white_noise;

    fn white(n: usize, seed: u64) -> Vec<f64> {
        white_noise(n, 1.0, seed)
    }

    #[test]
    fn white_unit_noise_about_a_right_model_is_not_tempered() {
        let r = white(20_000, 1);
        let t = Tempering::of_residuals(&r, &[5_000; 4]);
        assert!(t.correlation_samples < 1.3, "{t:?}");
        assert!(t.prior_weight < 1.2, "{t:?}");
        assert_eq!(t.samples, 20_000);
    }

    #[test]
    fn an_ar1_misfit_counts_its_closed_form_correlation_time_and_variance() {
        // x_t = φ x_{t−1} + σ e_t: variance σ²/(1 − φ²), τ = (1 + φ)/(1 − φ).
        let phi: f64 = 0.9;
        let sigma = 2.0;
        let e = white(200_000, 7);
        let mut x = vec![0.0; e.len()];
        for t in 1..e.len() {
            x[t] = phi * x[t - 1] + sigma * e[t];
        }
        let t = Tempering::of_residuals(&x, &[50_000; 4]);
        let tau = (1.0 + phi) / (1.0 - phi);
        let var = sigma * sigma / (1.0 - phi * phi);
        assert!((t.correlation_samples / tau - 1.0).abs() < 0.1, "{t:?}");
        assert!((t.residual_variance / var - 1.0).abs() < 0.05, "{t:?}");
        assert!((t.prior_weight - (var * tau).sqrt()).abs() / t.prior_weight < 0.08);
        assert!((t.effective_samples - 200_000.0 / t.correlation_samples).abs() < 1e-6);
    }

    #[test]
    fn a_sustained_offset_is_one_observation_per_sequence() {
        // A constant misfit of 3 noise floors over four sequences of 500.
        let r = vec![3.0; 2_000];
        let t = Tempering::of_residuals(&r, &[500; 4]);
        assert_eq!(t.correlation_samples, 500.0);
        assert_eq!(t.effective_samples, 4.0);
        assert!((t.prior_weight - (9.0f64 * 500.0).sqrt()).abs() < 1e-9);
    }

    #[test]
    fn lags_never_pair_samples_of_different_sequences() {
        // Alternating signs between sequences, constant within: pairs that
        // crossed a boundary would lower τ below the sequences' length.
        let mut r = Vec::new();
        for k in 0..10 {
            let s = if k % 2 == 0 { 1.0 } else { -1.0 };
            r.extend(std::iter::repeat_n(s, 100));
        }
        let t = Tempering::of_residuals(&r, &[100; 10]);
        assert_eq!(t.correlation_samples, 100.0);
    }

    #[test]
    fn residuals_within_the_noise_floor_do_not_loosen_the_prior() {
        let r = white_noise(4_000, 0.2, 3);
        let t = Tempering::of_residuals(&r, &[4_000]);
        assert_eq!(t.residual_variance, 1.0);
        assert!(t.prior_weight >= 1.0);
        assert_eq!(Tempering::of_residuals(&[], &[]), Tempering::NONE);
    }
}
