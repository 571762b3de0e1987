//! The calibration on synthetic runs with known offsets: white and
//! autocorrelated noise, a standstill on a bank, glitches inside a
//! standstill, straights that are not straight enough, a drifting offset,
//! a run that never stops or runs straight.

use super::*;
use crate::identify::data::white_noise;

/// The truth at one instant.
#[derive(Clone, Copy, Default)]
struct Truth {
    speed: f64,
    yaw_rate: f64,
    steer: f64,
    ax: f64,
    bank: f64,
}

/// Sensor offsets (yaw rate, ay, beta) and the noise's deviations.
#[derive(Clone, Copy)]
struct Sensors {
    offset: [f64; 3],
    noise: [f64; 3],
    /// Lag-one correlation of the noise (0: white).
    phi: f64,
    /// Log the bank.
    bank_logged: bool,
}

const SENSORS: Sensors = Sensors {
    offset: [0.005, -0.6, -0.01],
    noise: [0.002, 0.05, 0.002],
    phi: 0.0,
    bank_logged: false,
};

/// First-order autoregressive noise of deviation `sd` (white when φ = 0).
fn ar1(n: usize, sd: f64, phi: f64, seed: u64) -> Vec<f64> {
    let w = white_noise(n, sd * (1.0 - phi * phi).sqrt(), seed);
    let mut x = w.clone();
    x[0] = white_noise(1, sd, seed + 1000)[0];
    for i in 1..n {
        x[i] = phi * x[i - 1] + w[i];
    }
    x
}

/// A run of `seconds` at 100 Hz logging `truth` through `s`.
fn run(seconds: f64, truth: &dyn Fn(f64) -> Truth, s: Sensors, seed: u64) -> MeasuredRun {
    let n = (seconds * 100.0) as usize;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.01).collect();
    let x: Vec<Truth> = t.iter().map(|&t| truth(t)).collect();
    let noise: Vec<Vec<f64>> = (0..3)
        .map(|k| ar1(n, s.noise[k], s.phi, seed * 10 + k as u64))
        .collect();
    let speed_noise = white_noise(n, 0.02, seed * 10 + 7);
    let col = |k: usize, f: &dyn Fn(&Truth) -> f64| -> Vec<f64> {
        x.iter()
            .zip(&noise[k])
            .map(|(x, e)| f(x) + s.offset[k] + e)
            .collect()
    };
    let speed = x
        .iter()
        .zip(&speed_noise)
        .map(|(x, e)| x.speed + e)
        .collect();
    let steer = x.iter().map(|x| x.steer).collect();
    MeasuredRun::new(
        format!("run{seed}.csv"),
        t,
        speed,
        steer,
        col(0, &|x| x.yaw_rate),
    )
    .with_ay(col(1, &|x| x.speed * x.yaw_rate + G * x.bank.sin()))
    // Sideslip in the corners only: 0 on straights.
    .with_beta(col(2, &|x| 0.1 * x.steer))
    .with_bank(s.bank_logged.then(|| x.iter().map(|x| x.bank).collect()))
    .with_ax(x.iter().map(|x| x.ax).collect::<Vec<f64>>())
}

/// Parked 20 s, off to 15 m/s, 20 s straight, a 10 s corner, 20 s
/// straight, a stop and 20 s parked: 100 s.
fn lap(t: f64) -> Truth {
    let cruise = Truth {
        speed: 15.0,
        ..Truth::default()
    };
    match t {
        t if t < 20.0 => Truth::default(),
        t if t < 25.0 => Truth {
            speed: 3.0 * (t - 20.0),
            ax: 3.0,
            ..Truth::default()
        },
        t if (45.0..55.0).contains(&t) => Truth {
            yaw_rate: 0.3,
            steer: 0.05,
            ..cruise
        },
        t if t < 75.0 => cruise,
        t if t < 80.0 => Truth {
            speed: 15.0 - 3.0 * (t - 75.0),
            ax: -3.0,
            ..Truth::default()
        },
        _ => Truth::default(),
    }
}

fn span_count(r: &CalibrationReport, kind: SpanKind) -> usize {
    r.spans.iter().filter(|s| s.kind == kind).count()
}

#[test]
fn white_noise_offsets_come_back_from_standstills_and_straights() {
    let r = calibrate(&[run(100.0, &lap, SENSORS, 1)]);
    assert_eq!(span_count(&r, SpanKind::Standstill), 2, "{:?}", r.spans);
    assert_eq!(span_count(&r, SpanKind::Straight), 2, "{:?}", r.spans);
    assert!(r.rejected.is_empty(), "{:?}", r.rejected);
    // The standstills: 0–20 s and 80–100 s less the settling cuts and the
    // running median's half window at the ends of the motion.
    let s = &r.spans[0];
    assert!(
        s.t_start >= 1.0 && s.t_end < 19.2 && s.seconds() > 17.5,
        "{s:?}"
    );
    for (ch, k) in [
        (RunChannel::YawRate, 0),
        (RunChannel::Ay, 1),
        (RunChannel::Beta, 2),
    ] {
        let c = r.channel(ch).expect("measured");
        let truth = SENSORS.offset[k];
        for p in [c.standstill, c.straight].into_iter().flatten() {
            assert!(
                (p.mean - truth).abs() < 4.0 * p.std_error,
                "{ch:?}: {} ± {}",
                p.mean,
                p.std_error
            );
            assert!(p.consistent, "{ch:?}: {p:?}");
        }
        assert!(c.agreement.is_none_or(|a| a.agree), "{ch:?}: {c:?}");
    }
    // White noise: each span's standard error is s/√n.
    for s in &r.spans {
        for m in &s.channels {
            let k = CHANNELS.iter().position(|&c| c == m.channel).unwrap();
            let white = SENSORS.noise[k] / (m.samples as f64).sqrt();
            assert!((m.std_error / white - 1.0).abs() < 0.2, "{m:?}");
        }
    }
    // Sideslip on straights only: undefined standing still.
    let beta = r.channel(RunChannel::Beta).unwrap();
    assert!(beta.standstill.is_none() && beta.straight.is_some());
    let line = r.channel(RunChannel::Ay).unwrap().line();
    assert!(line.starts_with("ay offset -0."), "{line}");
    assert!(
        line.contains(" m/s² at 2 standstills (") && line.contains("on 2 straights ("),
        "{line}"
    );
    assert!(line.ends_with(": agree"), "{line}");
    assert_eq!(r.lines().len(), 3);
}

#[test]
fn without_ax_the_speeds_slope_keeps_the_ramps_out_of_the_straights() {
    let mut r = run(100.0, &lap, SENSORS, 2);
    r.ax = None;
    let c = calibrate(&[r]);
    let straights: Vec<&CalibrationSpan> = c
        .spans
        .iter()
        .filter(|s| s.kind == SpanKind::Straight)
        .collect();
    assert_eq!(straights.len(), 2, "{:?} {:?}", c.spans, c.rejected);
    // The ramp to 15 m/s ends at 25 s, the stop starts at 75 s.
    assert!(straights[0].t_start > 25.0 && straights[1].t_end < 75.0);
    assert!(c.rejected.is_empty(), "{:?}", c.rejected);
}

#[test]
fn autocorrelated_noise_gets_an_honest_standard_error() {
    // AR(1) noise with φ = 0.98 (a correlation time of 99 samples, 1 s):
    // over 100 parked runs the errors of the means, in standard errors,
    // scatter with a deviation near 1. The white-noise error s/√n would
    // make it about 10.
    let sensors = Sensors {
        phi: 0.98,
        ..SENSORS
    };
    let parked = |_| Truth::default();
    let mut z = Vec::new();
    let mut naive = Vec::new();
    for seed in 0..100 {
        let r = calibrate(&[run(34.0, &parked, sensors, seed)]);
        let p = r.channel(RunChannel::Ay).unwrap().standstill.unwrap();
        assert_eq!(p.spans, 1);
        z.push((p.mean + 0.6) / p.std_error);
        naive.push((p.mean + 0.6) / (0.05 / (p.samples as f64).sqrt()));
    }
    let sd = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
    assert!((0.8..1.25).contains(&sd(&z)), "{}", sd(&z));
    assert!(sd(&naive) > 5.0, "{}", sd(&naive));
    let span = &calibrate(&[run(34.0, &parked, sensors, 7)]).spans[0];
    let ay = span
        .channels
        .iter()
        .find(|m| m.channel == RunChannel::Ay)
        .unwrap();
    assert!(
        ay.effective_samples < ay.samples as f64 / 30.0,
        "{} of {}",
        ay.effective_samples,
        ay.samples
    );
}

#[test]
fn a_standstill_on_a_bank_reads_g_sin_bank_which_a_logged_bank_removes() {
    // Parked 30 s on a 0.2 rad banking (left edge up): the accelerometer
    // reads the offset plus g·sin θ = 1.948 m/s².
    let banked = |_| Truth {
        bank: 0.2,
        ..Truth::default()
    };
    let logged = Sensors {
        bank_logged: true,
        ..SENSORS
    };
    let with = calibrate(&[run(30.0, &banked, logged, 3)]);
    let without = calibrate(&[run(30.0, &banked, SENSORS, 3)]);
    let ay = |r: &CalibrationReport| *r.channel(RunChannel::Ay).unwrap();
    let (a, b) = (ay(&with), ay(&without));
    assert!(a.bank_removed && !b.bank_removed);
    let (pa, pb) = (a.standstill.unwrap(), b.standstill.unwrap());
    assert!((pa.mean + 0.6).abs() < 4.0 * pa.std_error, "{pa:?}");
    let g = G * 0.2f64.sin();
    assert!((pb.mean - (g - 0.6)).abs() < 4.0 * pb.std_error, "{pb:?}");
    let term = with.spans[0].channels[1].bank_term.unwrap();
    assert!((term - g).abs() < 1e-12, "{term}");
    assert!(a.line().starts_with("ay offset (g·sin(bank) removed) -0."));
}

#[test]
fn glitches_inside_a_standstill_are_left_out() {
    let quiet = Sensors {
        noise: [0.0005, 0.01, 0.001],
        ..SENSORS
    };
    let mut r = run(30.0, &|_| Truth::default(), quiet, 4);
    let ay = r.ay.as_mut().unwrap();
    // A zero read of five samples, a spike, a stuck value far off; a speed
    // spike that must not cut the standstill in two.
    ay[1000..1005].iter_mut().for_each(|v| *v = 0.0);
    ay[1500] = 30.0;
    ay[2000..2010].iter_mut().for_each(|v| *v = 3.2);
    r.yaw_rate[1200] = -1.0;
    r.speed[1700] = 20.0;
    let plain = ay[100..2900].iter().sum::<f64>() / 2800.0;
    let c = calibrate(&[r]);
    assert_eq!(c.spans.len(), 1, "{:?}", c.spans);
    let m = c.spans[0].channels[1];
    assert_eq!(m.outliers, 16);
    assert!((m.mean + 0.6).abs() < 4.0 * m.std_error, "{m:?}");
    // Left in, the glitches would move the mean by many standard errors.
    assert!((plain + 0.6).abs() > 20.0 * m.std_error, "{plain}");
    assert_eq!(c.spans[0].channels[0].outliers, 1);
}

#[test]
fn a_straight_not_straight_enough_is_refused_and_says_why() {
    // 15 m/s throughout: 10 s weaving (yaw rate ±0.008 rad/s every 4 s),
    // 10 s on a gentle curve (0.03 rad/s, 500 m radius), 10 s speeding up
    // from 10 to 14 m/s (ax 0.4 m/s²), each between 2 s corners.
    let corner = Truth {
        speed: 15.0,
        yaw_rate: 0.3,
        steer: 0.05,
        ..Truth::default()
    };
    let truth = |t: f64| match t {
        t if t < 2.0 => corner,
        t if t < 12.0 => Truth {
            speed: 15.0,
            yaw_rate: 0.008 * (std::f64::consts::TAU * t / 4.0).sin(),
            steer: 0.0015 * (std::f64::consts::TAU * t / 4.0).sin(),
            ..Truth::default()
        },
        t if t < 14.0 => corner,
        t if t < 24.0 => Truth {
            speed: 15.0,
            yaw_rate: 0.03,
            steer: 0.006,
            ..Truth::default()
        },
        t if t < 26.0 => corner,
        t if t < 36.0 => Truth {
            speed: 10.0 + 0.4 * (t - 26.0),
            ax: 0.4,
            ..Truth::default()
        },
        _ => corner,
    };
    // A gyro without offset: with one and no standstill to measure it, the
    // yaw-rate band of a straight stays centred on 0 and the offset uses
    // part of it.
    let gyro = Sensors {
        offset: [0.0, -0.6, -0.01],
        ..SENSORS
    };
    let r = calibrate(&[run(38.0, &truth, gyro, 5)]);
    assert_eq!(span_count(&r, SpanKind::Straight), 0, "{:?}", r.spans);
    assert_eq!(r.rejected.len(), 2, "{:?}", r.rejected);
    let weave = &r.rejected[0];
    assert!(weave.t_start > 2.0 && weave.t_end < 12.0, "{weave:?}");
    assert!(matches!(weave.reasons[..], [Rejection::YawRateVaries { std, .. }] if std > 0.005));
    let faster = &r.rejected[1];
    assert!(faster.t_start > 26.0 && faster.t_end < 36.0, "{faster:?}");
    assert!(matches!(faster.reasons[..], [Rejection::SpeedVaries { share, .. }] if share > 0.2));
    let lines = r.lines();
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].starts_with("no standstill"), "{lines:?}");
    assert!(
        lines[1].contains("the yaw rate varies by 0.005"),
        "{lines:?}"
    );
}

#[test]
fn a_drifting_offset_is_a_finding() {
    // Two stops, the accelerometer's offset moving from -0.58 to -0.62
    // between them (its noise 0.01 m/s²).
    let quiet = Sensors {
        noise: [0.0005, 0.01, 0.001],
        ..SENSORS
    };
    let mut first = run(100.0, &lap, quiet, 6);
    let ay = first.ay.as_mut().unwrap();
    ay[..5000].iter_mut().for_each(|v| *v += 0.02);
    ay[5000..].iter_mut().for_each(|v| *v -= 0.02);
    let r = calibrate(&[first]);
    let c = r.channel(RunChannel::Ay).unwrap();
    let p = c.standstill.unwrap();
    assert!(!p.consistent && p.spans == 2, "{p:?}");
    assert!((p.least + 0.62).abs() < 0.005 && (p.greatest + 0.58).abs() < 0.005);
    // The pooled error covers the spread (τ, the scatter between the
    // stops), not the noise.
    assert!(p.std_error > 0.015, "{p:?}");
    assert!(
        c.line().contains("the standstills drift (-0.6"),
        "{}",
        c.line()
    );
    // The yaw rate did not move.
    assert!(
        r.channel(RunChannel::YawRate)
            .unwrap()
            .standstill
            .unwrap()
            .consistent
    );
}

#[test]
fn a_run_that_never_stops_or_runs_straight_measures_nothing() {
    let slalom = |t: f64| Truth {
        speed: 20.0,
        yaw_rate: 0.2 * (0.8 * t).sin(),
        steer: 0.03 * (0.8 * t).sin(),
        ..Truth::default()
    };
    let r = calibrate(&[run(60.0, &slalom, SENSORS, 8)]);
    assert!(r.spans.is_empty() && r.channels.is_empty() && r.rejected.is_empty());
    assert_eq!(r.yaw_reference, 0.0);
    let lines = r.lines();
    assert_eq!(lines.len(), 1);
    assert!(lines[0].starts_with("no standstill (speed below 0.2 m/s for 5 s)"));
    assert!(calibrate(&[]).spans.is_empty());
}

#[test]
fn a_gated_channel_holds_no_offset_and_masked_samples_are_left_out() {
    let mut r = run(30.0, &|_| Truth::default(), SENSORS, 9);
    // A yaw rate gated to exactly 0 while parked.
    r.yaw_rate.iter_mut().for_each(|v| *v = 0.0);
    // Masked ay samples (a cleaning already ran): far off, not counted.
    let ay = r.ay.as_mut().unwrap();
    ay[500..600].iter_mut().for_each(|v| *v = 50.0);
    r.masked = (500..600).collect();
    let c = calibrate(&[r]);
    let s = &c.spans[0];
    assert_eq!(s.held, vec![RunChannel::YawRate]);
    assert_eq!(s.channels.len(), 1);
    assert_eq!(s.channels[0].outliers, 0);
    assert!(c.channel(RunChannel::YawRate).is_none());
}

#[test]
fn a_one_hertz_slalom_is_no_straight_though_its_medians_are_flat() {
    // 20 s parked, 5 s off to 15 m/s, 40 s of a 1 Hz slalom (steer ±0.02
    // rad, yaw rate ±0.1 rad/s), 5 s to a stop, 20 s parked. The 1 s
    // running medians of a 1 Hz sine are near 0: every per-sample and
    // running-median test passes; the raw swing (0.014 rad, 0.07 rad/s RMS)
    // does not.
    let w = std::f64::consts::TAU;
    let truth = |t: f64| match t {
        t if t < 20.0 => Truth::default(),
        t if t < 25.0 => Truth {
            speed: 3.0 * (t - 20.0),
            ax: 3.0,
            ..Truth::default()
        },
        t if t < 65.0 => Truth {
            speed: 15.0,
            yaw_rate: 0.1 * (w * t).sin(),
            steer: 0.02 * (w * t).sin(),
            ..Truth::default()
        },
        t if t < 70.0 => Truth {
            speed: 15.0 - 3.0 * (t - 65.0),
            ax: -3.0,
            ..Truth::default()
        },
        _ => Truth::default(),
    };
    let r = calibrate(&[run(90.0, &truth, SENSORS, 11)]);
    assert_eq!(span_count(&r, SpanKind::Standstill), 2, "{:?}", r.spans);
    assert_eq!(span_count(&r, SpanKind::Straight), 0, "{:?}", r.spans);
    assert_eq!(r.rejected.len(), 1, "{:?}", r.rejected);
    let slalom = &r.rejected[0];
    assert!(slalom.t_start > 25.0 && slalom.t_end < 65.0, "{slalom:?}");
    let (steer, yaw) = match slalom.reasons[..] {
        [Rejection::SteerSwings { rms: s, .. }, Rejection::YawRateSwings { rms: y, .. }] => (s, y),
        _ => panic!("{slalom:?}"),
    };
    assert!((steer / (0.02 / 2f64.sqrt()) - 1.0).abs() < 0.05, "{steer}");
    assert!((yaw / (0.1 / 2f64.sqrt()) - 1.0).abs() < 0.05, "{yaw}");
    // No straight offset: beta, measured on straights only, has none.
    assert!(r.channel(RunChannel::Beta).is_none());
    assert!(r.channel(RunChannel::YawRate).unwrap().straight.is_none());
}

/// At 27.8 m/s, 30 s: straight to `from` s, then a steady turn at `ay`
/// m/s² whose yaw rate reads 57.3× too small (a yaw rate in rad/s
/// declared in deg/s), its `ay` the accelerometer's as it is.
fn slipped_turn(ay: f64, from: f64) -> impl Fn(f64) -> Truth {
    let u = 27.8;
    move |t| match t < from {
        true => Truth {
            speed: u,
            ..Truth::default()
        },
        false => Truth {
            speed: u,
            yaw_rate: ay / u / 57.3,
            steer: 0.0079 * ay / 2.0,
            // The rest of `ay` (not logged as a bank): what u·r misses.
            bank: ((ay - ay / 57.3) / G).asin(),
            ..Truth::default()
        },
    }
}

/// A steady 2 m/s² turn whose yaw rate read 57× too small passed every
/// yaw test of a straight and gave an `ay` offset of 1.98 m/s²: `ay` is a
/// witness of its own now. A turn gentle enough to pass (0.8 m/s²) gives
/// an offset no accelerometer has, and is said so.
#[test]
fn a_steady_lateral_acceleration_is_no_straight_whatever_the_yaw_rate() {
    let s = Sensors {
        offset: [0.0, 0.1, 0.0],
        ..SENSORS
    };
    let r = calibrate(&[run(30.0, &slipped_turn(2.0, 12.0), s, 3)]);
    assert_eq!(span_count(&r, SpanKind::Straight), 1, "{:?}", r.spans);
    let straight = r.spans.iter().find(|s| s.kind == SpanKind::Straight);
    assert!(straight.unwrap().t_end < 12.0, "{:?}", r.spans);
    let ay = r.channel(RunChannel::Ay).unwrap();
    let p = ay.straight.unwrap();
    assert!((p.mean - 0.1).abs() < 4.0 * p.std_error, "{p:?}");
    assert!(!ay.line().contains("MEMS"), "{}", ay.line());
    let r = calibrate(&[run(30.0, &slipped_turn(0.8, 0.0), s, 3)]);
    let line = r.channel(RunChannel::Ay).unwrap().line();
    assert!(
        line.contains("; the straights' 0.90 m/s² is beyond the 0.01–0.5 m/s² of an automotive MEMS accelerometer's bias: more likely a turn read as a straight"),
        "{line}"
    );
}
