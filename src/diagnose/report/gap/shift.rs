//! Whether a replay's time shift is resolved: the correlation peak
//! ([`super::scan::time_shift`]) always lands somewhere, and on a log whose
//! clock is right its noise alone moves it by a sample or two (a replay of
//! an exactly timed sideslip read "the measurement leads the simulation by
//! 0.02 s" while the residual's RMS stayed within 2 % over ±0.03 s).
//!
//! A shift is said only where it is at least [`SHIFT_STANDARD_ERRORS`] of
//! its own standard error: that of the least-squares delay of
//! `measured(t) = simulated(t − τ) + e`, linearised about the shift found,
//! `σ_τ = σ_e·√(τ_e/Σ ṡ²)` (σ_e the RMS of the residual at that shift, τ_e
//! the noise's integrated autocorrelation time in samples, ṡ the simulated
//! channel's rate at the shifted times): the Cramér–Rao bound of a delay
//! estimate in additive noise (Carter 1987, time-delay estimation). A
//! model error left in the residual raises σ_e and makes the test only
//! more cautious.
//!
//! Units: s; the channel's own for the signals.

/// Standard errors of its own estimate a time shift must reach to be said
/// (a normal tail of 6e-5 on both sides, as a bias's
/// [`super::scan::BIAS_STANDARD_ERRORS`]).
pub const SHIFT_STANDARD_ERRORS: f64 = 4.0;

/// The standard error of a time shift `shift` (s) of `measured` behind
/// `simulated`, both sampled every `dt` s, with the noise correlated over
/// `tau` samples; None where too few samples lie within the shifted range
/// or the simulated channel does not move.
pub(super) fn standard_error(
    dt: f64,
    measured: &[f64],
    simulated: &[f64],
    shift: f64,
    tau: f64,
) -> Option<f64> {
    let n = measured.len().min(simulated.len());
    let k = shift / dt;
    let (mut sse, mut rate2, mut count) = (0.0, 0.0, 0usize);
    for (i, m) in measured.iter().enumerate().take(n) {
        // simulated(t_i − shift), between samples j and j + 1.
        let at = i as f64 - k;
        if at < 1.0 || at > (n - 2) as f64 {
            continue;
        }
        let j = (at.floor() as usize).min(n - 3);
        let w = at - j as f64;
        let s = simulated[j] * (1.0 - w) + simulated[j + 1] * w;
        let rate = (simulated[j + 1] - simulated[j]) / dt;
        sse += (m - s) * (m - s);
        rate2 += rate * rate;
        count += 1;
    }
    (count >= 8 && rate2 > 0.0).then(|| (sse / count as f64 * tau.max(1.0) / rate2).sqrt())
}

/// True where `shift` (s) is resolved: at least [`SHIFT_STANDARD_ERRORS`]
/// of its [`standard_error`].
pub(super) fn resolved(dt: f64, measured: &[f64], simulated: &[f64], shift: f64, tau: f64) -> bool {
    standard_error(dt, measured, simulated, shift, tau)
        .is_some_and(|se| shift.abs() >= SHIFT_STANDARD_ERRORS * se)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optim::stats::gauss;
    use rand::SeedableRng;

    /// A smooth step at 1 s sampled every 10 ms over 6 s.
    fn step(t: f64) -> f64 {
        0.07 / (1.0 + (-(t - 1.0) / 0.05).exp())
    }

    #[test]
    fn noise_alone_resolves_no_shift_and_a_tenth_of_a_second_is_resolved() {
        let dt = 0.01;
        let t: Vec<f64> = (0..601).map(|i| i as f64 * dt).collect();
        let sim: Vec<f64> = t.iter().map(|&x| step(x)).collect();
        let mut said = 0;
        for seed in 0..200 {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let meas: Vec<f64> = sim.iter().map(|s| s + 0.002 * gauss(&mut rng)).collect();
            if let Some(shift) = super::super::scan::time_shift(dt, &meas, &sim) {
                said += usize::from(resolved(dt, &meas, &sim, shift, 1.0));
            }
            // A real lag of 0.1 s on the same noise is always resolved.
            let late: Vec<f64> = t
                .iter()
                .map(|&x| step(x - 0.1) + 0.002 * gauss(&mut rng))
                .collect();
            let shift = super::super::scan::time_shift(dt, &late, &sim).unwrap();
            assert!((shift - 0.1).abs() < 0.01, "{seed}: {shift}");
            assert!(resolved(dt, &late, &sim, shift, 1.0), "{seed}");
        }
        // Four standard errors: about one run in 16,000 of pure noise.
        assert!(said <= 1, "{said} of 200 noise-only runs said a shift");
    }

    #[test]
    fn the_standard_error_is_the_delay_estimates() {
        // σ_e/√(Σ ṡ²) for white noise: a ramp of slope 1 over 100 samples
        // of 10 ms with σ_e = 0.01 gives 0.01/√100 = 1 ms.
        let dt = 0.01;
        let sim: Vec<f64> = (0..102).map(|i| i as f64 * dt).collect();
        let meas: Vec<f64> = sim
            .iter()
            .enumerate()
            .map(|(i, s)| s + if i % 2 == 0 { 0.01 } else { -0.01 })
            .collect();
        let se = standard_error(dt, &meas, &sim, 0.0, 1.0).unwrap();
        assert!((se - 0.001).abs() < 1e-9, "{se}");
    }
}
