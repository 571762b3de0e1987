//! A step response still oscillating at its steady window, read from the
//! envelope of its successive extrema after the step: a lightly damped
//! response `y∞ + A·e^(−σt)·cos(ωt + φ)` swings about its centre `y∞` with
//! extrema a half period apart whose distances from it fall by
//! `q = e^(−σ·T/2)` each. Three successive extrema e₁, e₂, e₃ give
//! `q = |e₃ − e₂| / |e₂ − e₁|`, the centre `y∞ = e₃ − (e₃ − e₂)·q/(1 + q)`
//! and the period `T = t₃ − t₁`; the amplitude left at the steady window is
//! `|e₃ − y∞|·q^((t_w − t₃)/(T/2))`, `t_w` the window's start (or t₃ where
//! that is later). A window whose mean sits on a crest (a sedan stepped to
//! 0.15 rad: period 3.7 s, its 5–6 s window on a crest 3.9 % of the step
//! above its centre) reads the gain 3.2 % high while its spread, a
//! quarter of the swing, passes.
//!
//! Why the extrema and not a fitted decaying cosine: the extrema need no
//! starting guess and no iteration, and their reversals, each more than
//! [`REVERSAL_NOISES`] noise deviations, are a test whose false alarms on
//! noise have a bound (below): a least-squares fit finds some frequency in
//! any noise and needs its own null distribution over the frequencies it
//! scans. A fit uses every sample; the extrema use three, and their values
//! are lifted by the noise (about a deviation or two), which
//! [`AMPLITUDE_NOISES`] takes off the amplitude before it is judged.
//!
//! False alarms: an extremum counts only once the response has turned back
//! from it by [`REVERSAL_NOISES`] (10) deviations of its noise after the
//! filter, which noise alone does only with a sample 5 deviations from the
//! curve (under 6·10⁻⁷ a sample, under the settling's `FALSE_ALARM` over a record
//! of a thousand samples), and an oscillation needs two such reversals a
//! consistent half period apart. Noise-free, a reversal must pass
//! [`LEAST_REVERSAL`] of the step (rounding is no swing). Heavy noise hides
//! an oscillation from this test (at a noise of 2 % of the step it sees
//! only swings beyond 20 %): the spread's verdict judges those.
//!
//! The lift is the noise's at the extrema, where the response's slope is
//! nil: a channel's noise read from its neighbours' differences (the
//! metrics' white-noise deviation) is its own slope times the sample
//! interval on a smooth record written finely, so on the 80 m/s sedan's
//! 1 ms `simulate` history it read 0.013 % of the sideslip's step, and its
//! three deviations took a swing of 2.02 % below the 2 % that `simulate`
//! itself judged oscillating. The lift takes the smaller of that and the
//! deviation read from second differences ([`still_noise`]), which a
//! slope does not enter and white noise gives alike ([`lift`]): one
//! history, one verdict from `simulate` (no noise) and `metrics` on the
//! file it wrote.
//!
//! Units: times s; values normalised by the step (the steady window's mean
//! 1); shares of the step dimensionless.

/// The noise deviations (after the filter) a response must turn back by
/// from an extremum for it to count.
pub(crate) const REVERSAL_NOISES: f64 = 10.0;

/// The least reversal of a noise-free record, a share of the step.
pub(crate) const LEAST_REVERSAL: f64 = 1e-3;

/// The noise deviations taken off the amplitude left before it is judged:
/// an extremum read on noisy samples stands out by about the noise's
/// largest excursion near it.
pub(crate) const AMPLITUDE_NOISES: f64 = 3.0;

/// The share of its step a response has risen to where its extrema are
/// looked for: the 90 % of its response time.
const RISEN: f64 = 0.9;

/// The most two successive half periods may differ by, as a ratio: a
/// decaying oscillation's are equal; swings of unequal spacing are no
/// one oscillation.
const HALF_PERIODS: f64 = 2.0;

/// A decaying oscillation read from a response's last three extrema.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ringing {
    /// The period, s.
    pub period: f64,
    /// The distance from the centre left at the steady window, a share of
    /// the step (the envelope there).
    pub amplitude: f64,
    /// The oscillation's centre, normalised (1: the steady window's mean).
    pub centre: f64,
    /// When the last extremum is, s.
    pub last: f64,
}

/// The indices of the extrema of `x` that it turns back from by more than
/// `reversal` (a zig-zag: the record's last run, not yet turned back
/// from, is none).
pub(crate) fn extrema(x: &[f64], reversal: f64) -> Vec<usize> {
    let mut out = Vec::new();
    let (mut hi, mut lo, mut dir) = (0usize, 0usize, 0i8);
    for (i, &v) in x.iter().enumerate() {
        match dir {
            0 => {
                if v > x[hi] {
                    hi = i;
                }
                if v < x[lo] {
                    lo = i;
                }
                // Rising where the high came last.
                if x[hi] - x[lo] > reversal {
                    dir = if hi > lo { 1 } else { -1 };
                }
            }
            1 => {
                if v > x[hi] {
                    hi = i;
                } else if x[hi] - v > reversal {
                    out.push(hi);
                    (dir, lo) = (-1, i);
                }
            }
            _ => {
                if v < x[lo] {
                    lo = i;
                } else if v - x[lo] > reversal {
                    out.push(lo);
                    (dir, hi) = (1, i);
                }
            }
        }
    }
    out
}

/// The decaying oscillation of the normalised response `x` (times `t`)
/// from its first rise to [`RISEN`] after `from` on, judged at the steady window starting at `window`, with
/// its noise after the filter `noise` (a share of the step): none where
/// fewer than three extrema turn back by [`REVERSAL_NOISES`] noises, their
/// half periods differ by more than [`HALF_PERIODS`], or they do not
/// decay.
pub(crate) fn ringing(t: &[f64], x: &[f64], from: f64, window: f64, noise: f64) -> Option<Ringing> {
    // From the response's own rise to 90 %: a sideslip's first swing the
    // wrong way (the sedan's β at 0.15 rad dips 3.4 % of its step against
    // it) is no extremum of the oscillation, and read as one put its
    // centre 3 % of the step off the 20 s run's.
    let after = t.partition_point(|v| *v < from);
    let start = after + x.get(after..)?.iter().position(|v| *v >= RISEN)?;
    let reversal = (REVERSAL_NOISES * noise).max(LEAST_REVERSAL);
    let ext = extrema(x.get(start..)?, reversal);
    let [i1, i2, i3] = match ext.len() {
        n if n >= 3 => [ext[n - 3], ext[n - 2], ext[n - 1]].map(|i| i + start),
        _ => return None,
    };
    let (h1, h2) = (t[i2] - t[i1], t[i3] - t[i2]);
    if h1 <= 0.0 || !(1.0 / HALF_PERIODS..=HALF_PERIODS).contains(&(h2 / h1)) {
        return None;
    }
    let (e1, e2, e3) = (x[i1], x[i2], x[i3]);
    let q = ((e3 - e2) / (e2 - e1)).abs();
    // A swing that does not decay (or a flat pair: no ratio) is no
    // oscillation settling towards a centre.
    if q.is_nan() || q >= 1.0 {
        return None;
    }
    let centre = e3 - (e3 - e2) * q / (1.0 + q);
    let half = 0.5 * (t[i3] - t[i1]);
    let at = window.max(t[i3]);
    Some(Ringing {
        period: 2.0 * half,
        amplitude: (e3 - centre).abs() * q.powf((at - t[i3]) / half),
        centre,
        last: t[i3],
    })
}

/// The swing `r` leaves at the steady window, taken to `to_scale` times
/// the step, once the noise's lift of its extrema (`noise`, a share of
/// the step) is taken off: what the settling threshold judges.
pub(crate) fn swing_left(r: &Ringing, to_scale: f64, noise: f64) -> f64 {
    (r.amplitude - AMPLITUDE_NOISES * noise) * to_scale
}

/// The white-noise deviation of `x` (its unit) from the median absolute
/// second difference (`Δ²x` of white noise of deviation σ has deviation
/// `√6·σ`, its median absolute value `0.6745·√6·σ`), and at least q/√12
/// for a channel on a logger's grid of q, as the neighbours' differences
/// read it ([`super::super::noise::noise_deviation`]). A smooth signal
/// enters it only by its curvature times the interval squared, not by its
/// slope times the interval.
pub(crate) fn still_noise(x: &[f64]) -> f64 {
    let mut d: Vec<f64> = x
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs())
        .collect();
    if d.len() < 5 {
        return 0.0;
    }
    d.sort_by(f64::total_cmp);
    let from_differences = d[d.len() / 2] / (0.6745 * 6f64.sqrt());
    match super::super::noise::held_resolution(x) {
        Some(q) => from_differences.max(q / 12f64.sqrt()),
        None => from_differences,
    }
}

/// The noise (before the filter, a share of the step) that lifts the
/// extrema of a channel whose neighbours' differences read `noise` and
/// whose second differences read `still` ([`still_noise`]): the smaller,
/// since a smooth record's slope lifts the first and white noise reads
/// alike in both. A channel held `held` samples between updates and
/// interpolated (more than 1) keeps `noise`, read on its updates: its
/// straight segments have no second differences whatever its noise.
pub(crate) fn lift(noise: f64, still: f64, held: usize) -> f64 {
    match held {
        0 | 1 => noise.min(still),
        _ => noise,
    }
}

/// The words of channel `name` still oscillating: a swing of `period` s
/// whose last extremum is at `last` s, `amplitude` (a share of the step)
/// left about its centre at the steady window, the centre `centre` (a
/// share of the step) from the window's mean; the caller's "more than
/// 2 %" follows the amplitude.
pub(crate) fn words(name: &str, amplitude: f64, period: f64, centre: f64, last: f64) -> String {
    let pc = |x: f64| crate::format::significant(100.0 * x.abs(), 2);
    // The centre above the mean: the window sits below it.
    let side = if centre > 0.0 { "below" } else { "above" };
    format!(
        "the {name} still oscillates (a decaying swing of period {} s, its last extremum at t = {last:.2} s; the window's mean lies {} % of its step {side} the oscillation's centre): it swings {} % of its step about that centre at the steady window",
        crate::format::significant(period, 2),
        pc(centre),
        pc(amplitude)
    )
}

/// What the yaw-rate `gain` (1/s) read from a window on a swing is, where
/// the yaw rate still oscillates about a `centre` (a share of the step
/// from the window's mean), with that centre as a gain: the better final
/// value; nothing where it does not oscillate.
pub(crate) fn gain_words(centre: Option<f64>, gain: f64) -> String {
    let Some(centre) = centre else {
        return String::new();
    };
    format!(
        "; the yaw-rate gain, {} 1/s, is no steady-state gain: read over a window on a swing of that oscillation, and the oscillation's centre is about {} 1/s (a longer record, held until the response settles, reads it)",
        crate::format::fixed(gain, 4),
        crate::format::significant(gain * (1.0 + centre), 4)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// A step response `1 − e^(−σt)·cos(ωt)` (centre 1) at 100 Hz for
    /// `end` s, normalised by its mean over the last second, as the
    /// metrics read it.
    fn record(sigma: f64, period: f64, end: f64) -> (Vec<f64>, Vec<f64>, f64) {
        let n = (end * 100.0) as usize;
        let t: Vec<f64> = (0..=n).map(|i| i as f64 / 100.0).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|&t| 1.0 - (-sigma * t).exp() * (TAU * t / period).cos())
            .collect();
        let w: Vec<f64> = y[n - 100..].to_vec();
        let mean = w.iter().sum::<f64>() / w.len() as f64;
        (t, y.iter().map(|v| v / mean).collect(), mean)
    }

    /// A lightly damped response (q = 0.27 a half period, period 3.7 s)
    /// whose 6 s record ends past a crest: its period, its centre (1 on
    /// the response's own scale, 1/mean normalised) and the envelope left
    /// at the window are recovered; the same response read to 20 s has
    /// settled.
    #[test]
    fn a_decaying_oscillation_is_read_from_its_extrema() {
        let period = 3.7;
        let sigma = -2.0 * 0.27f64.ln() / period;
        let (t, x, mean) = record(sigma, period, 6.0);
        let r = ringing(&t, &x, 0.0, 5.0, 0.0).expect("three extrema");
        assert!((r.period - period).abs() < 0.02, "{r:?}");
        assert!((r.centre - 1.0 / mean).abs() < 1e-3, "{r:?} {mean}");
        // The last crest, after the window's start: its own distance.
        let envelope = (-sigma * r.last).exp() / mean;
        assert!(
            (r.amplitude - envelope).abs() < 0.1 * envelope,
            "{r:?} {envelope}"
        );
        assert!(swing_left(&r, 1.0, 0.0) >= 0.02);
        let (t, x, _) = record(sigma, period, 20.0);
        let r = ringing(&t, &x, 0.0, 19.0, 0.0);
        assert!(r.is_none_or(|r| swing_left(&r, 1.0, 0.0) < 0.02), "{r:?}");
    }

    /// A well-damped response (ζ = 0.5: overshoot 16 %) leaves no swing
    /// at a window 5 s on, and one with no overshoot has no extrema.
    #[test]
    fn a_well_damped_response_is_not_oscillating() {
        let (t, x, _) = record(1.8, 2.0 * std::f64::consts::PI / 3.1, 6.0);
        let r = ringing(&t, &x, 0.0, 5.0, 0.0);
        assert!(r.is_none_or(|r| swing_left(&r, 1.0, 0.0) < 0.02), "{r:?}");
        let x: Vec<f64> = t.iter().map(|t| 1.0 - (-3.0 * t).exp()).collect();
        assert_eq!(ringing(&t, &x, 0.0, 5.0, 0.0), None);
    }

    /// The second differences read white noise as the neighbours'
    /// differences do (σ = 0.01 over 20 000 samples: both within 2 %), and
    /// a smooth swing written every millisecond (2 % of its step at
    /// 0.6 Hz) not by its slope: the neighbours' differences read it as a
    /// noise of its median slope times the interval over 0.6745·√2,
    /// 0.02·2π·0.6·sin(π/4)·10⁻³/0.954 = 5.6·10⁻⁵, the second differences
    /// (its curvature times the interval squared) under 10⁻⁶, which is
    /// what lifts its extrema: none.
    /// A channel held between updates keeps its neighbours' reading.
    #[test]
    fn the_lift_is_read_where_the_slope_does_not_enter() {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(114);
        let white: Vec<f64> = (0..20_000)
            .map(|_| 0.01 * crate::optim::stats::gauss(&mut rng))
            .collect();
        let first = crate::metrics::noise::noise_deviation(&white);
        let second = still_noise(&white);
        assert!((first / 0.01 - 1.0).abs() < 0.02, "{first}");
        assert!((second / 0.01 - 1.0).abs() < 0.02, "{second}");
        let swing: Vec<f64> = (0..6000)
            .map(|i| 1.0 + 0.02 * (TAU * 0.6 * i as f64 * 1e-3).cos())
            .collect();
        let first = crate::metrics::noise::noise_deviation(&swing);
        let second = still_noise(&swing);
        assert!((first / 5.6e-5 - 1.0).abs() < 0.05, "{first}");
        assert!(second < 1e-6, "{second}");
        assert_eq!(lift(first, second, 1), second);
        assert_eq!(lift(first, second, 0), second);
        assert_eq!(lift(first, second, 2), first);
        // White noise: the smaller of two readings of one deviation.
        assert_eq!(lift(0.0101, 0.0099, 1), 0.0099);
    }

    /// At the threshold: a swing left of 2.02 % of the step is 2 % or more
    /// without noise and below it with a lift of three deviations of
    /// 0.013 % (the 80 m/s sedan's sideslip read on its neighbours'
    /// differences); one of 1.98 % is below it without noise. Taken to a
    /// sideslip's scale (×0.5) the swing halves.
    #[test]
    fn the_swing_is_judged_at_the_threshold_less_its_lift() {
        let r = |amplitude: f64| Ringing {
            period: 1.7,
            amplitude,
            centre: 1.0,
            last: 5.3,
        };
        assert!(swing_left(&r(0.0202), 1.0, 0.0) >= 0.02);
        assert!(swing_left(&r(0.0202), 1.0, 1.3e-4) < 0.02);
        assert!(swing_left(&r(0.0198), 1.0, 0.0) < 0.02);
        let half = swing_left(&r(0.0404), 0.5, 0.0);
        assert!((half - 0.0202).abs() < 1e-15, "{half}");
        let lifted = swing_left(&r(0.0202), 1.0, 1e-4);
        assert!((lifted - (0.0202 - AMPLITUDE_NOISES * 1e-4)).abs() < 1e-15);
    }

    /// Noisy copies of a settled step (a first-order lag, τ = 0.2 s) at
    /// 100 Hz through the 10 Hz zero-phase low-pass, at noises of 1 % to
    /// 5 % of the step: none of 1000 is read as oscillating (the stated
    /// rate is one in a thousand); a lightly damped response (q = 0.35 a
    /// half period, period 3.4 s, its last crest 4.3 % of the step at
    /// 5.1 s) under 0.3 % noise is found in every copy, its centre within
    /// 0.5 % of the step.
    #[test]
    fn noise_alone_is_no_oscillation_and_a_real_one_is_found() {
        use rand::SeedableRng;
        let (dt, hz) = (0.01, 10.0);
        let gain = crate::metrics::noise::noise_gain(dt, hz);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(113);
        let t: Vec<f64> = (0..=600).map(|i| i as f64 * dt).collect();
        let lag: Vec<f64> = t.iter().map(|t| 1.0 - (-t / 0.2).exp()).collect();
        let period = 3.4;
        let sigma = -2.0 * 0.35f64.ln() / period;
        let (_, ring, mean) = record(sigma, period, 6.0);
        let mut fired = 0;
        for k in 0..1000 {
            let level = 0.01 * (1 + k % 5) as f64;
            let read_at = |clean: &[f64], level: f64, rng: &mut rand_chacha::ChaCha8Rng| {
                let raw: Vec<f64> = clean
                    .iter()
                    .map(|v| v + level * crate::optim::stats::gauss(rng))
                    .collect();
                let noise = gain * crate::metrics::noise::noise_deviation(&raw);
                let f = crate::metrics::zero_phase_low_pass(&raw, dt, hz);
                (ringing(&t, &f, 0.0, 5.0, noise), noise)
            };
            let (r, noise) = read_at(&lag, level, &mut rng);
            fired += usize::from(r.is_some_and(|r| swing_left(&r, 1.0, noise) >= 0.02));
            if k % 5 == 0 {
                let (r, noise) = read_at(&ring, 0.003, &mut rng);
                let r = r.expect("found under 0.3 % noise");
                assert!(swing_left(&r, 1.0, noise) >= 0.02, "{r:?}");
                assert!((r.centre - 1.0 / mean).abs() < 0.005, "{r:?}");
            }
        }
        assert!(fired <= 1, "{fired} of 1000 noisy settled steps fired");
    }
}
