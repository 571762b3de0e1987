//! The gap of a channel on hand-built records: noise is no gap, a slower
//! model is one, a trusted floor judges a smooth channel.

use super::*;
use crate::diagnose::report::parts::Window;
use std::f64::consts::PI;

fn grid(n: usize, dt: f64) -> Vec<f64> {
    (0..n).map(|i| i as f64 * dt).collect()
}

#[test]
fn sprague_geers_of_scaled_and_shifted_sines() {
    let t = grid(10_001, 1e-3);
    let c: Vec<f64> = t.iter().map(|x| (2.0 * PI * x).sin()).collect();
    let m: Vec<f64> = c.iter().map(|v| 1.1 * v).collect();
    let (mag, ph, _) = sprague_geers(&t, &m, &c);
    assert!((mag - 0.1).abs() < 1e-9 && ph.abs() < 1e-6, "{mag} {ph}");
    let phi = 0.3;
    let m: Vec<f64> = t.iter().map(|x| (2.0 * PI * x - phi).sin()).collect();
    let (mag, ph, comp) = sprague_geers(&t, &m, &c);
    assert!(
        mag.abs() < 1e-6 && (ph - phi / PI).abs() < 1e-4,
        "{mag} {ph}"
    );
    assert!((comp - ph).abs() < 1e-6);
}

/// A 20 s record at 100 Hz with a steer step at 5 s, and the first-order
/// yaw-rate response of time constant `tau` to it.
struct Step {
    t: Vec<f64>,
    steer: Vec<f64>,
    ay: Vec<f64>,
    speed: Vec<f64>,
}

impl Step {
    fn new() -> Self {
        let t = grid(2000, 0.01);
        let n = t.len();
        Self {
            steer: t
                .iter()
                .map(|x| if *x > 5.0 { 0.02 } else { 0.0 })
                .collect(),
            ay: vec![1.0; n],
            speed: vec![20.0; n],
            t,
        }
    }
    fn response(&self, tau: f64) -> Vec<f64> {
        self.t
            .iter()
            .map(|x| {
                if *x > 5.0 {
                    0.2 * (1.0 - (-(x - 5.0) / tau).exp())
                } else {
                    0.0
                }
            })
            .collect()
    }
    fn record(&self) -> Record<'_> {
        Record {
            start: self.t[0],
            t: &self.t,
            steer: &self.steer,
            ay: &self.ay,
            speed: &self.speed,
        }
    }
}

/// `y` plus white Gaussian noise of standard deviation `sigma` (seeded).
fn noisy(y: &[f64], sigma: f64, seed: u64) -> Vec<f64> {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    y.iter()
        .map(|v| v + sigma * crate::identify::data::gauss(&mut rng))
        .collect()
}

#[test]
fn identical_records_have_no_gap_and_noise_is_not_a_gap() {
    let s = Step::new();
    let truth = s.response(0.3);
    let g = channel_gap(Channel::YawRate, &s.record(), &truth, &truth);
    assert_eq!(g.rms, 0.0);
    assert!(!g.significant);
    // White measurement noise of 0.002 rad/s: the floor is estimated from
    // the 5 s before the input and the model is not blamed for it.
    let measured = noisy(&truth, 0.002, 12345);
    let g = channel_gap(Channel::YawRate, &s.record(), &measured, &truth);
    assert!((g.noise_floor - 0.002).abs() < 0.0003, "{}", g.noise_floor);
    assert!(!g.significant, "{}", g.verdict);
    assert!(
        g.lag1_autocorrelation.abs() < 0.1,
        "{}",
        g.lag1_autocorrelation
    );
}

/// A smooth channel (a state estimator's output: almost no scatter
/// before the input) judged against its own scatter calls a small
/// offset a gap; against the uncertainty the campaign trusts it to, it
/// is within noise, and the floor says where it came from.
#[test]
fn a_run_is_judged_against_the_trusted_floor_not_its_own_scatter() {
    let s = Step::new();
    let truth = s.response(0.3);
    let smooth = noisy(&truth, 2e-5, 3);
    let offset: Vec<f64> = truth.iter().map(|v| v + 0.004).collect();
    let own = channel_gap(Channel::YawRate, &s.record(), &smooth, &offset);
    assert!(own.significant, "{}", own.verdict);
    assert_eq!(own.noise_source, NoiseSource::BeforeInput);
    let rec = s.record();
    let trusted = trusted_channel_gap(
        Channel::YawRate,
        &rec,
        &smooth,
        &offset,
        Some(0.005),
        FloorCounting::White,
    );
    assert!(!trusted.significant, "{}", trusted.verdict);
    assert_eq!(
        (trusted.noise_floor, trusted.noise_source),
        (0.005, NoiseSource::Trusted)
    );
    // Above three trusted floors it is a gap again; no floor (0) is
    // the run's own.
    let far: Vec<f64> = truth.iter().map(|v| v + 0.02).collect();
    assert!(
        trusted_channel_gap(
            Channel::YawRate,
            &rec,
            &smooth,
            &far,
            Some(0.005),
            FloorCounting::White
        )
        .significant
    );
    let none = trusted_channel_gap(
        Channel::YawRate,
        &rec,
        &smooth,
        &offset,
        Some(0.0),
        FloorCounting::White,
    );
    assert_eq!(none.noise_source, NoiseSource::BeforeInput);
}

#[test]
fn a_slower_model_is_a_significant_gap_that_follows_the_input() {
    let s = Step::new();
    let (measured, simulated) = (noisy(&s.response(0.2), 0.001, 7), s.response(0.5));
    let g = channel_gap(Channel::YawRate, &s.record(), &measured, &simulated);
    assert!(g.significant, "{}", g.verdict);
    // The gap lies in the transient, not before the input or late.
    let w = |window: Window| {
        g.windows
            .iter()
            .find(|p| p.name == Part::Window(window))
            .unwrap()
            .rms
    };
    assert!(w(Window::FirstHalfSecond) > 5.0 * w(Window::BeforeInput));
    assert!(w(Window::FirstHalfSecond) > 5.0 * w(Window::Later));
    assert!(g.bias < 0.0, "a slower model lags: negative residual");
    assert!(g.lag1_autocorrelation > 0.9);
}

#[test]
fn band_analysis_finds_a_pure_delay_as_phase_growing_with_frequency() {
    // A chirp 0.1–4 Hz; the model is the measurement delayed by 50 ms
    // and 10 % too strong: +0.83 dB everywhere and a phase
    // lag of 360°·f·0.05 s.
    let t = grid(6001, 0.005);
    let chirp = |x: f64| (PI * (0.1 * x + 0.65 / 2.0 * x * x / 1.0 * 0.5)).sin();
    let steer: Vec<f64> = t.iter().map(|&x| 0.02 * chirp(x)).collect();
    let measured: Vec<f64> = steer.iter().map(|d| 10.0 * d).collect();
    let simulated: Vec<f64> = t.iter().map(|&x| 11.0 * 0.02 * chirp(x - 0.05)).collect();
    let b = band_gaps(&t, &steer, &measured, &simulated);
    assert!(b.len() >= 3, "{b:?}");
    for g in &b {
        assert!(
            (g.gain_error_db - 20.0 * 1.1f64.log10()).abs() < 0.3,
            "{g:?}"
        );
        let fc = 0.5 * (g.f_low + g.f_high);
        let expected = -360.0 * fc * 0.05;
        assert!(
            (g.phase_error_deg - expected).abs() < 0.35 * expected.abs() + 2.0,
            "{g:?}"
        );
    }
    // A step has no band analysis.
    let s = Step::new();
    assert!(band_gaps(&s.t, &s.steer, &s.response(0.2), &s.response(0.3)).is_empty());
}

/// A piece of a lap starts in the middle of its driving: the steer leaves
/// its first value at once, so "the first 0.5 s of the input" would be a
/// time a steering correction picked. Its gap is split by regime only;
/// the same step after 0.5 s held still is split by time too.
#[test]
fn a_run_with_no_steady_start_is_not_split_by_time_after_an_input() {
    let s = Step::new();
    let (measured, simulated) = (s.response(0.2), s.response(0.5));
    let from = |k: usize| {
        let rec = Record {
            start: s.t[k],
            t: &s.t[k..],
            steer: &s.steer[k..],
            ay: &s.ay[k..],
            speed: &s.speed[k..],
        };
        channel_gap(Channel::YawRate, &rec, &measured[k..], &simulated[k..])
    };
    // The step at 5 s; a record from 4.6 s holds the steer 0.4 s, one from
    // 4.4 s 0.6 s, one from 5.5 s not at all (the input is under way).
    for (k, timed) in [(0, true), (440, true), (460, false), (550, false)] {
        let g = from(k);
        assert!(g.significant, "{}", g.verdict);
        assert_eq!(
            !g.windows.is_empty(),
            timed,
            "from sample {k}: {:?}",
            g.windows
        );
        assert!(!g.regimes.is_empty());
        assert_eq!(
            g.verdict.contains("largest in the window"),
            timed,
            "{}",
            g.verdict
        );
    }
}

/// A steer at the noise level drives no band response above the gyro's
/// noise: round 29's straights (white noise of 0.0002 rad at 20 m/s, a
/// gyro of 0.0017 rad/s) read "0.10–0.30 Hz off by −7 dB, +100°". Every
/// band that holds the steer's power is counted as without steer content;
/// the chirp of 0.02 rad, the same gyro noise on both, keeps its bands.
#[test]
fn bands_are_said_only_where_the_steer_drives_a_response_above_the_noise() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(29);
    let mut gauss = || crate::optim::stats::gauss(&mut rng);
    let t = grid(1001, 0.01);
    let gyro = 0.0017;
    let steer: Vec<f64> = t.iter().map(|_| 0.0002 * gauss()).collect();
    // A yaw-rate gain of 5 1/s, lagging one sample, plus the gyro's noise.
    let gain = |k: usize| 5.0 * steer[k.saturating_sub(1)];
    let simulated: Vec<f64> = (0..t.len()).map(gain).collect();
    let measured: Vec<f64> = (0..t.len()).map(|k| gain(k) + gyro * gauss()).collect();
    let quiet = band_gaps_above(&t, &steer, &measured, &simulated, gyro);
    assert!(quiet.found.is_empty(), "{quiet:?}");
    assert!(quiet.without_steer >= 3, "{quiet:?}");
    // Without a floor the same run reads every band, as before.
    assert!(band_gaps(&t, &steer, &measured, &simulated).len() >= 3);
    // A chirp of 0.02 rad over 30 s with the same gyro noise keeps them.
    let t = grid(6001, 0.005);
    let chirp = |x: f64| (PI * (0.1 * x + 0.65 / 2.0 * x * x / 1.0 * 0.5)).sin();
    let steer: Vec<f64> = t.iter().map(|&x| 0.02 * chirp(x)).collect();
    let measured: Vec<f64> = steer.iter().map(|d| 10.0 * d + gyro * gauss()).collect();
    let simulated: Vec<f64> = steer.iter().map(|d| 11.0 * d).collect();
    let swept = band_gaps_above(&t, &steer, &measured, &simulated, gyro);
    assert!(
        swept.found.len() >= 3 && swept.without_steer == 0,
        "{swept:?}"
    );
}

/// A step record whose response is a slow first-order one (0.04 rad/s
/// steady, time constant 4 s), its
/// simulation `(1 + k)` times it plus `offset` after the input, the
/// measurement with white noise `sigma`: the channel's gap.
fn gained(k: f64, offset: f64, sigma: f64, seed: u64) -> ChannelGap {
    let s = Step::new();
    let truth: Vec<f64> = s.response(4.0).iter().map(|v| 0.2 * v).collect();
    let simulated: Vec<f64> = truth
        .iter()
        .zip(&s.t)
        .map(|(v, t)| (1.0 + k) * v + if *t > 5.0 { offset } else { 0.0 })
        .collect();
    let measured = noisy(&truth, sigma, seed);
    channel_gap(Channel::YawRate, &s.record(), &measured, &simulated)
}

/// The slope the words give ("the simulation reads X % of the
/// measurement").
fn reads_percent(verdict: &str) -> f64 {
    verdict
        .split("the simulation reads ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{verdict}"))
}

/// A pure gain error (the simulation 25 % above a measured step, no
/// intercept) is a gain error at every gyro noise a yaw-rate sensor has,
/// 0 to 0.005 rad/s, and its slope the closed form's 125 %: fitted against
/// the measured channel, a noise of 0.002 rad/s cut the correlation below
/// 0.9 and flattened the slope (errors in variables), and the gap read
/// "mostly a constant offset" beside "a dynamic error".
#[test]
fn a_pure_gain_error_is_a_gain_error_at_any_gyro_noise() {
    for (sigma, seed) in [(0.0, 1), (0.0003, 2), (0.001, 3), (0.002, 4), (0.005, 5)] {
        let g = gained(0.25, 0.0, sigma, seed);
        assert!(g.gap_found, "{sigma}: {}", g.verdict);
        assert!(g.verdict.contains("a gain error"), "{sigma}: {}", g.verdict);
        assert!(
            !g.verdict.contains("mostly a constant offset"),
            "{sigma}: {}",
            g.verdict
        );
        assert!(
            !g.verdict.contains("a dynamic error"),
            "{sigma}: {}",
            g.verdict
        );
        let percent = reads_percent(&g.verdict);
        assert!((percent - 125.0).abs() < 1.5, "{sigma}: {}", g.verdict);
    }
}

/// A pure offset over the whole run (the simulation 0.004 rad/s above a
/// measurement with 0.001 rad/s of noise, before the input too) is a
/// constant offset and no gain error (it has no slope), nor one that
/// comes with the input.
#[test]
fn a_pure_offset_is_an_offset_not_a_gain_error() {
    let s = Step::new();
    let truth: Vec<f64> = s.response(4.0).iter().map(|v| 0.2 * v).collect();
    let simulated: Vec<f64> = truth.iter().map(|v| v + 0.004).collect();
    let measured = noisy(&truth, 0.001, 9);
    let g = channel_gap(Channel::YawRate, &s.record(), &measured, &simulated);
    assert!(
        g.verdict.contains("the gap is mostly a constant offset"),
        "{}",
        g.verdict
    );
    assert!(!g.verdict.contains("gain error"), "{}", g.verdict);
    assert!(!g.verdict.contains("comes with the input"), "{}", g.verdict);
}

/// An offset that comes with the input (0.01 rad/s from the step on,
/// over a response that swings about zero, 0.04 rad/s at 0.5 Hz: no line
/// through it), the window before the input right: no sensor's zero
/// offset, which would show before the input too, and the residual, a
/// step like the steer's, a dynamic error; never "mostly a constant
/// offset", with or without "a sensor's zero offset".
#[test]
fn an_offset_that_comes_with_the_input_is_no_sensor_offset() {
    let s = Step::new();
    let after = |t: f64| t > 5.0;
    let truth: Vec<f64> =
        s.t.iter()
            .map(|&t| match after(t) {
                true => 0.04 * (PI * (t - 5.0)).sin(),
                false => 0.0,
            })
            .collect();
    let simulated: Vec<f64> = truth
        .iter()
        .zip(&s.t)
        .map(|(v, &t)| v + if after(t) { 0.01 } else { 0.0 })
        .collect();
    let measured = noisy(&truth, 0.001, 11);
    let g = channel_gap(Channel::YawRate, &s.record(), &measured, &simulated);
    assert!(g.gap_found, "{}", g.verdict);
    assert!(!g.verdict.contains("gain error"), "{}", g.verdict);
    assert!(
        g.verdict.contains("the gap's mean comes with the input")
            && g.verdict.contains("so no sensor's zero offset"),
        "{}",
        g.verdict
    );
    assert!(
        !g.verdict.contains("mostly a constant offset"),
        "{}",
        g.verdict
    );
    assert!(g.verdict.contains("a dynamic error"), "{}", g.verdict);
}
