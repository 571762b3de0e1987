//! Whether a step response diverges: grows away from every steady value as
//! exp(λ·t), λ > 0, as the yaw rate of an unstable car does (a linear
//! 2-DOF car that oversteers, above its critical speed u_crit = √(−l/K):
//! the positive eigenvalue of its state matrix; Mitschke & Wallentowitz,
//! Segel 1956). Such a response has no steady state, and a "gain" read
//! from the last window's mean is whatever the record's length made it.
//!
//! The test reads the last half of the record after the steer is held
//! (then, on a log too short for that, its last three quarters), in
//! [`SEGMENTS`] equal segments: the means m_k of x = c + A·e^{λt} (of its linear interpolant between samples) differ
//! by d_k = m_{k+1} − m_k = A'·e^{λ·k·h} whatever the constant c (the
//! steady value a divergent car never reaches), so ln|d_k| is a line of
//! slope λ·h. A divergence is every difference of one sign, beyond what
//! the noise leaves unknown of two segment means, growing from each to the
//! next at a like rate (an exponential's ratios are equal; a parabola's
//! shrink, a linear drift's are 1, noise's scatter), by at least
//! [`MIN_GROWTH`] from the first to the last, and moving the response by
//! more than 2 % of its step over the fitted half. λ in 1/s, times in s.

/// The equal segments the fitted half of the record is cut into.
const SEGMENTS: usize = 6;

/// The least growth of the last segment difference over the first: below
/// it a slow drift (ratio 1) and an exponential are not told apart. Four
/// of six segments apart, it asks the fitted half to span about one time
/// constant or more (λ = 0.5 1/s over a half of 2 s grows 1.95 times: a
/// slower divergence stays "not settled", as a drift does).
const MIN_GROWTH: f64 = 2.0;

/// The most the largest ratio's logarithm may exceed the smallest's, a
/// factor: an exponential's are equal; a parabola's from rest fall by 4.4
/// over the same five differences.
const RATIO_SPREAD: f64 = 3.0;

/// The least samples a segment's mean is read from.
const MIN_SEGMENT_SAMPLES: usize = 5;

/// The share of the step the response must move over the fitted half: a
/// response that moves less there has settled by the metrics' own 2 %.
const MIN_MOVE: f64 = 0.02;

/// A divergence fitted from a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Divergence {
    /// The growth rate λ, 1/s (the time constant is 1/λ).
    pub rate: f64,
    /// The fitted stretch's start, s.
    pub from: f64,
    /// Its end (the record's), s.
    pub to: f64,
}

/// The divergence of `x` (sampled at `t`) after `held`, the time the steer
/// is held from, if it diverges: `noise` is its raw noise deviation and
/// `step` its change from the initial window to the steady one, both in
/// its unit.
pub(crate) fn diverging(
    t: &[f64],
    x: &[f64],
    held: f64,
    noise: f64,
    step: f64,
) -> Option<Divergence> {
    let end = *t.last()?;
    // The last half first; on a short log a slow divergence grows less
    // than [`MIN_GROWTH`] there (λ = 0.6 1/s over the last 1.5 s of a 4 s
    // log: 1.75 times), and the last three quarters are read too. The car's
    // fast mode (its other eigenvalue, −9 1/s and below on a car) has died
    // away a quarter of a second after the steer is held; a stable car's
    // approach or overshoot there has shrinking or changing differences,
    // refused by the same tests.
    FROM_HELD
        .iter()
        .find_map(|f| diverging_from(t, x, held + f * (end - held), noise, step))
}

/// Where the fitted stretch starts, as a share of the time from the steer
/// held to the record's end: the last half, then the last three quarters.
const FROM_HELD: [f64; 2] = [0.5, 0.25];

/// [`diverging`] over `from` to the record's end.
fn diverging_from(t: &[f64], x: &[f64], from: f64, noise: f64, step: f64) -> Option<Divergence> {
    let end = *t.last()?;
    let h = (end - from) / SEGMENTS as f64;
    if h.is_nan() || h <= 0.0 {
        return None;
    }
    let mut means = Vec::with_capacity(SEGMENTS);
    let mut fewest = usize::MAX;
    for k in 0..SEGMENTS {
        let (lo, hi) = (from + k as f64 * h, from + (k + 1) as f64 * h);
        let inside = t.iter().filter(|&&s| s >= lo && s <= hi).count();
        if inside < MIN_SEGMENT_SAMPLES {
            return None;
        }
        fewest = fewest.min(inside);
        means.push(integral(t, x, lo, hi) / h);
    }
    if (means[SEGMENTS - 1] - means[0]).abs() < MIN_MOVE * step.abs() {
        return None;
    }
    let d: Vec<f64> = means.windows(2).map(|w| w[1] - w[0]).collect();
    // Three deviations of a difference of two means of `fewest` samples.
    let resolved = (3.0 * noise * (2.0 / fewest as f64).sqrt()).max(1e-4 * step.abs());
    let sign = d[0].signum();
    if d.iter().any(|v| v * sign <= resolved) {
        return None;
    }
    let ln: Vec<f64> = d.iter().map(|v| v.abs().ln()).collect();
    let steps: Vec<f64> = ln.windows(2).map(|w| w[1] - w[0]).collect();
    let (least, most) = steps
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &s| {
            (a.min(s), b.max(s))
        });
    if least <= 0.0 || most > RATIO_SPREAD * least || ln[ln.len() - 1] - ln[0] < MIN_GROWTH.ln() {
        return None;
    }
    // The least-squares slope of ln|d_k| on k, per segment.
    let n = ln.len() as f64;
    let k_mean = (n - 1.0) / 2.0;
    let ln_mean = ln.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (k, v) in ln.iter().enumerate() {
        let dk = k as f64 - k_mean;
        sxy += dk * (v - ln_mean);
        sxx += dk * dk;
    }
    Some(Divergence {
        rate: sxy / sxx / h,
        from,
        to: end,
    })
}

/// ∫ x dt over [lo, hi] of `x` interpolated linearly between its samples
/// (trapezoids, the end intervals cut): a segment's mean does not move
/// with how many samples fall in it.
fn integral(t: &[f64], x: &[f64], lo: f64, hi: f64) -> f64 {
    let mut sum = 0.0;
    for i in 1..t.len() {
        let (a, b) = (t[i - 1].max(lo), t[i].min(hi));
        if b <= a {
            continue;
        }
        let at = |s: f64| x[i - 1] + (x[i] - x[i - 1]) * (s - t[i - 1]) / (t[i] - t[i - 1]);
        sum += 0.5 * (at(a) + at(b)) * (b - a);
    }
    sum
}

/// Whether the yaw rate of a run as read (before its cleaning) diverges
/// ([`diverging`]) after its steer is held: the steer within 10 % of its
/// last value's change from its first. Consulted before the check of the
/// yaw rate against a neutral car's, which an unstable car's passes.
pub(crate) fn diverges_raw(run: &crate::measured::MeasuredRun) -> bool {
    let (t, steer, r) = (&run.t, &run.steer, &run.yaw_rate);
    let (Some(&s0), Some(&s1)) = (steer.first(), steer.last()) else {
        return false;
    };
    let Some(k) = steer
        .iter()
        .position(|s| (s - s0).abs() >= 0.9 * (s1 - s0).abs() && s1 != s0)
    else {
        return false;
    };
    let step = r[r.len() - 1] - r[0];
    let noise = super::noise::noise_deviation(r);
    diverging(t, r, t[k], noise, step).is_some()
}

/// [`diverging`] of the yaw rate as the metrics' refusal.
pub(crate) fn refuse(
    t: &[f64],
    x: &[f64],
    held: f64,
    noise: f64,
    step: f64,
) -> Result<(), crate::error::MetricsError> {
    match diverging(t, x, held, noise, step) {
        Some(g) => Err(crate::error::MetricsError::Diverges {
            channel: "yaw rate",
            rate: g.rate,
            from: g.from,
            to: g.to,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(dt: f64, end: f64) -> Vec<f64> {
        (0..=((end / dt).round() as usize))
            .map(|i| i as f64 * dt)
            .collect()
    }

    /// c + A·e^{λt} gives back λ, whatever c and the sign of A; a linear
    /// drift, a parabola from rest, a first-order approach and a decaying
    /// overshoot give none.
    #[test]
    fn an_exponential_gives_its_rate_and_a_drift_or_an_approach_none() {
        let t = grid(0.01, 5.0);
        for (lambda, a) in [(1.0646, 0.002), (0.8, -0.01), (2.5, 1e-5)] {
            let x: Vec<f64> = t.iter().map(|&s| 0.3 + a * (lambda * s).exp()).collect();
            let step = x[x.len() - 1] - x[0];
            let d = diverging(&t, &x, 1.0, 0.0, step).expect("diverges");
            assert!(
                (d.rate / lambda - 1.0).abs() < 1e-3,
                "{} vs {lambda}",
                d.rate
            );
        }
        let shapes: [&dyn Fn(f64) -> f64; 4] = [
            &|s| 0.4 + 0.04 * s,
            &|s| 0.4 + 0.04 * (s - 3.0).max(0.0).powi(2),
            &|s| 0.4 * (1.0 - (-s / 1.0).exp()),
            &|s| 0.4 * (1.0 - (-0.5 * s).exp() * (3.0 * s).cos()),
        ];
        for f in shapes {
            let x: Vec<f64> = t.iter().map(|&s| f(s)).collect();
            let step = x[x.len() - 1] - x[0];
            assert!(diverging(&t, &x, 1.0, 0.0, step).is_none());
        }
    }
}
