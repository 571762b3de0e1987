//! What filtered white noise alone does to a settling verdict's spread:
//! the null distribution the spread beyond the noise is judged against, so
//! that a settled record's noise does not read as motion more often than
//! a stated rate. Spreads and noises are shares of the step
//! (dimensionless).

/// The share of steady windows of filtered white noise alone (no motion)
/// whose spread beyond the noise a channel's verdict calls motion: one in
/// a thousand per channel. A threshold of 2 % of the step alone fired on
/// one of five noisy copies of a settled step (ay noise 5.6 % of its step,
/// 2.3 % after a 10 Hz low-pass: the sample deviation of 100 correlated
/// samples scatters by about 16 %).
pub const FALSE_ALARM: f64 = 0.001;

/// The standard normal quantile of 1 − [`FALSE_ALARM`].
const FALSE_ALARM_Z: f64 = 3.090_232;

/// Relative variance of the squared noise deviation read from the median
/// of `n` absolute differences, times `n`: the sample median of |X|, X
/// normal of deviation s, has variance 1/(4n·f(m)²) = 0.619·s²/n at its
/// median m = 0.6745·s, so m/0.6745 has relative variance 1.36/n, and
/// its square four times that.
const MEDIAN_NOISE_VARIANCE: f64 = 5.44;

/// What the verdict needs of the noise's null distribution: the filter's
/// correlation sum `Σρ(k)²` over all lags (1 unfiltered; how many samples
/// carry one sample's worth of variance information), times the samples
/// per update of a held channel, and the samples the noise was read on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct NoiseNull {
    /// `Σρ(k)²` of the noise after the filter (and the hold).
    pub per_dof: f64,
    /// The samples the noise deviation was read on (the record's).
    pub read_on: usize,
}

/// The spread beyond its noise (a share of the step) that a steady
/// window of `samples` samples of the filtered white noise `noise` (a
/// share of the step) alone exceeds with probability [`FALSE_ALARM`].
/// Its sample variance s² over the window is, in distribution, σ²·χ²_ν/ν
/// with ν = samples/Σρ² − 1 degrees of freedom (the variance of a sample
/// variance of a Gaussian process is 2σ⁴·Σρ²/N; Bartlett 1946), and σ² is
/// itself read from the median difference (relative variance
/// [`MEDIAN_NOISE_VARIANCE`]/n): their ratio has relative variance
/// 2/ν + 5.44/n, taken as a χ² of 2/that degrees of freedom, whose upper
/// quantile is Wilson & Hilferty's (1931). The spread beyond the noise
/// √(s² − σ²) passes `noise·√(q − 1)` no more often than that.
pub(super) fn noise_alone(noise: f64, samples: usize, null: NoiseNull) -> f64 {
    if noise <= 0.0 || samples < 2 {
        return 0.0;
    }
    let nu = (samples as f64 / null.per_dof.max(1.0) - 1.0).max(1.0);
    let relative = 2.0 / nu + MEDIAN_NOISE_VARIANCE / null.read_on.max(1) as f64;
    let dof = 2.0 / relative;
    let a = 2.0 / (9.0 * dof);
    let q = (1.0 - a + FALSE_ALARM_Z * a.sqrt()).powi(3);
    noise * (q - 1.0).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The threshold against simulated records of white noise through the
    /// 10 Hz zero-phase low-pass at 100 Hz, read on their last 100
    /// samples (a steady window at the record's end, where the backward
    /// pass starts): at most a few in a thousand pass it (FALSE_ALARM is
    /// one; the χ² and the median's scatter are approximations); unfiltered
    /// noise (Σρ² = 1) gets a finer threshold, relative to its deviation.
    #[test]
    fn filtered_noise_alone_passes_the_threshold_at_the_stated_rate() {
        use rand::SeedableRng;
        let (dt, hz) = (0.01, 10.0);
        let per_dof = crate::metrics::noise::correlation_sum(dt, hz);
        let gain = crate::metrics::noise::noise_gain(dt, hz);
        assert!(per_dof > 3.0 && per_dof < 8.0, "{per_dof}");
        let null = NoiseNull {
            per_dof,
            read_on: 1000,
        };
        let limit = noise_alone(gain, 100, null);
        let unfiltered = noise_alone(
            1.0,
            100,
            NoiseNull {
                per_dof: 1.0,
                read_on: 1000,
            },
        );
        assert!(unfiltered < limit / gain, "{unfiltered} {limit}");
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(47);
        let (mut passed, runs) = (0, 2000);
        for _ in 0..runs {
            let z: Vec<f64> = (0..1000)
                .map(|_| crate::optim::stats::gauss(&mut rng))
                .collect();
            let f = crate::metrics::zero_phase_low_pass(&z, dt, hz);
            let w = &f[900..];
            let m = w.iter().sum::<f64>() / 100.0;
            let var = w.iter().map(|x| (x - m).powi(2)).sum::<f64>() / 100.0;
            let sigma = gain * crate::metrics::noise::noise_deviation(&z);
            let beyond = (var - sigma * sigma).max(0.0).sqrt();
            passed += usize::from(beyond >= limit);
        }
        assert!(passed <= 8, "{passed} of {runs} passed {limit}");
    }
}
