//! The turning samples whose per-sample ratio `ay / a` judges a run's
//! units ([`super::run_units::check_ay`]), with `a` the kinematic lateral
//! acceleration a car in these units has there (ISO 8855, small angles,
//! SI). A car's `ay = u·(r + β̇) + u̇·β`: on a transient the `β̇` term is no
//! small part of it (in a 1.5 Hz sine steer `β̇` runs at about −0.45 r,
//! so `ay/(u·r)` sat at 0.55 over the whole run and a speed in m/s was
//! taken for mph). So:
//! - with a `beta` column, `a = u·(r + β̇)` at every turning sample, `β̇`
//!   a central difference over ±[`SLOPE_SECONDS`] s;
//! - without one, `a = u·r`, only where the yaw rate holds steady
//!   ([`steady`]), where `β̇` is near 0 too: a step's or a circle's steady
//!   turn, never a sine's, which is then not judged by these samples (the
//!   run-wide slope of `run_slope.rs` still is).

/// Half-width of the central difference of `beta`, s: short against a
/// 2 Hz sine's period (its slope then read within 4 %), long against a
/// sample (a noisy sideslip's difference averaged over several).
const SLOPE_SECONDS: f64 = 0.05;

/// Half-width of the window over which a yaw rate must hold, s: a third of
/// a 1.5 Hz sine's period and more, within a step's steady part.
const STEADY_SECONDS: f64 = 0.25;

/// How far each half-window's mean yaw rate may lie from the sample's own
/// (a mean of 5 samples), as a share of it: 10 %.
const STEADY_SHARE: f64 = 0.1;

/// And in absolute terms, rad/s: above a gyro's noise in a mean of a
/// quarter second's samples.
const STEADY_FLOOR: f64 = 0.003;

/// A run's channels, SI.
pub(super) struct Channels<'a> {
    /// Time, s.
    pub t: &'a [f64],
    /// Forward speed, m/s.
    pub speed: &'a [f64],
    /// Yaw rate, rad/s.
    pub r: &'a [f64],
    /// Lateral acceleration, m/s².
    pub ay: &'a [f64],
    /// Sideslip, rad, where logged.
    pub beta: Option<&'a [f64]>,
}

/// The samples judged and the ratio `ay / a` of each: moving at `moving`
/// m/s or more, with `|u·r|` and `|a|` at least `turning` m/s².
pub(super) fn ratios(c: &Channels, moving: f64, turning: f64) -> (Vec<usize>, Vec<f64>) {
    let n = c.ay.len().min(c.speed.len()).min(c.r.len()).min(c.t.len());
    let k_slope = samples_in(c.t, SLOPE_SECONDS);
    let k_steady = samples_in(c.t, STEADY_SECONDS);
    let mut samples = Vec::new();
    let mut ratios = Vec::new();
    for i in 0..n {
        let (u, r) = (c.speed[i], c.r[i]);
        if !(u >= moving && (u * r).abs() >= turning) {
            continue;
        }
        let a = match c.beta {
            Some(beta) => match beta_rate(c.t, beta, i, k_slope) {
                Some(rate) => u * (r + rate),
                None => continue,
            },
            None if steady(c.r, i, k_steady) => u * r,
            None => continue,
        };
        if a.abs() >= turning && c.ay[i].is_finite() {
            samples.push(i);
            ratios.push(c.ay[i] / a);
        }
    }
    (samples, ratios)
}

/// The number of samples in `seconds` at the run's median time step (1 at
/// least).
fn samples_in(t: &[f64], seconds: f64) -> usize {
    let mut steps: Vec<f64> = t
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| d.is_finite() && *d > 0.0)
        .collect();
    if steps.is_empty() {
        return 1;
    }
    let dt = crate::measured::clean::median(&mut steps);
    ((seconds / dt).round() as usize).max(1)
}

/// dβ/dt at sample `i`, rad/s: the central difference over ±`k` samples
/// (None at the run's ends or across a NaN).
fn beta_rate(t: &[f64], beta: &[f64], i: usize, k: usize) -> Option<f64> {
    let (lo, hi) = (i.checked_sub(k)?, i + k);
    let (b0, b1) = (*beta.get(lo)?, *beta.get(hi)?);
    let dt = t.get(hi)? - t[lo];
    let rate = (b1 - b0) / dt;
    (rate.is_finite() && dt > 0.0).then_some(rate)
}

/// Whether the yaw rate holds at sample `i`: the means of the `k` samples
/// before and of the `k` after each within [`STEADY_SHARE`] (and
/// [`STEADY_FLOOR`]) of the mean of the 5 samples around it. At a sine's
/// peak both halves fall away alike: each is compared with the centre, not
/// with the other.
fn steady(r: &[f64], i: usize, k: usize) -> bool {
    let (Some(lo), hi) = (i.checked_sub(k), i + k) else {
        return false;
    };
    if hi >= r.len() {
        return false;
    }
    let mean = |s: &[f64]| s.iter().sum::<f64>() / s.len() as f64;
    let centre = mean(&r[i.saturating_sub(2)..=(i + 2).min(r.len() - 1)]);
    let tol = STEADY_SHARE * centre.abs() + STEADY_FLOOR;
    let near = |m: f64| (m - centre).abs() <= tol;
    near(mean(&r[lo..i])) && near(mean(&r[i + 1..=hi]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1.5 Hz sine whose sideslip rate is −0.45 of its yaw rate and
    /// whose `ay` is u·(r + β̇): every ratio 1 with `beta`, none judged
    /// without (never steady); a held turn judged either way.
    #[test]
    fn a_sine_is_judged_by_its_sideslip_rate_or_not_at_all() {
        let dt = 0.001;
        let w = 2.0 * std::f64::consts::PI * 1.5;
        let t: Vec<f64> = (0..6000).map(|i| i as f64 * dt).collect();
        let r: Vec<f64> = t.iter().map(|t| 0.2 * (w * t).sin()).collect();
        // β = 0.45·0.2/w·cos(wt): β̇ = −0.45 r.
        let beta: Vec<f64> = t.iter().map(|t| 0.09 / w * (w * t).cos()).collect();
        let speed = vec![25.0; t.len()];
        let ay: Vec<f64> = r.iter().map(|r| 25.0 * 0.55 * r).collect();
        let mut c = Channels {
            t: &t,
            speed: &speed,
            r: &r,
            ay: &ay,
            beta: Some(&beta),
        };
        let (samples, q) = ratios(&c, 5.0, 1.0);
        assert!(samples.len() > 2000, "{}", samples.len());
        // The central difference over ±0.05 s reads β̇ times sin(wh)/(wh)
        // (0.963 at 1.5 Hz): the ratio is 0.55 / (1 − 0.45 × that), 0.971.
        let wh = w * SLOPE_SECONDS;
        let expected = 0.55 / (1.0 - 0.45 * wh.sin() / wh);
        assert!(q.iter().all(|q| (q - expected).abs() < 1e-6), "{expected}");
        c.beta = None;
        assert!(ratios(&c, 5.0, 1.0).0.is_empty());
        let held = vec![0.2; t.len()];
        c.r = &held;
        let (samples, _) = ratios(&c, 5.0, 1.0);
        assert_eq!(samples.len(), t.len() - 2 * 250);
    }
}
