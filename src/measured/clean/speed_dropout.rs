//! A speed read as exactly 0 for one sample or a few while the car drives
//! (a wheel-speed or GPS logger's dropout): a zero read, not a standstill.
//! The statistics of `glitches.rs` cannot see it: a noise-free speed held
//! at 20 m/s is quantised by the dropout's own jump, and its zero sample
//! lies below `min_speed`, where a glitch is taken for part of a slow span.
//! It is told by the physics instead: to read 0 at a sample, the car must
//! have stopped from the speed of the sample before within one interval,
//! and to read the speed after, started again within one; beyond
//! [`MAX_ACCELERATION`] both ways, no car did. A real standstill, approached
//! by braking, reads speeds near 0 beside its zeros and stays one.
//! Units: m/s, s.

use super::repair::repair;
use super::report::{CleaningReport, Glitch, GlitchKind, RunChannel, Treatment};
use super::MAX_ZERO_RUN;
use crate::constants::G;
use crate::measured::MeasuredRun;

/// The largest deceleration (or acceleration) a car reaches, m/s²: 1.5 g,
/// a racing slick's grip on a dry road (a road car brakes at about 1 g and
/// accelerates at less).
pub(super) const MAX_ACCELERATION: f64 = 1.5 * G;

/// Repairs the speed's zero reads no car can drive
/// ([`super::speed_dropout`]) and lists them in `report`: before the
/// slow samples are read, where such a sample would be a standstill.
pub(super) fn speed_dropouts(run: &mut MeasuredRun, min_speed: f64, report: &mut CleaningReport) {
    let found = impossible_zeros(&run.t, &run.speed, min_speed);
    let mut bad = vec![false; run.t.len()];
    for &(start, len) in &found {
        bad[start..start + len].iter_mut().for_each(|b| *b = true);
        report.samples_repaired += len;
        report.push_glitch(Glitch {
            run: run.path.display().to_string(),
            t: run.t[start],
            channel: RunChannel::Speed,
            kind: GlitchKind::ZeroRead,
            value: 0.0,
            samples: len,
            treatment: Treatment::Repaired,
            dropped_with: None,
        });
    }
    if !found.is_empty() {
        repair(&run.t, &mut run.speed, &bad);
    }
    speed_dips(run, min_speed, report);
}

/// Repairs the speed's dips below `min_speed` no car can drive (a sign
/// flipped for a sample, [`impossible_dips`]) and lists them as spikes:
/// left in, a dip would be a slow span (a "crawl" at -20 m/s) that splits
/// the run in two.
fn speed_dips(run: &mut MeasuredRun, min_speed: f64, report: &mut CleaningReport) {
    let found = impossible_dips(&run.t, &run.speed, min_speed);
    let mut bad = vec![false; run.t.len()];
    for &(start, len) in &found {
        bad[start..start + len].iter_mut().for_each(|b| *b = true);
        report.samples_repaired += len;
        // The sample farthest below the speeds beside the dip.
        let value = run.speed[start..start + len]
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        report.push_glitch(Glitch {
            run: run.path.display().to_string(),
            t: run.t[start],
            channel: RunChannel::Speed,
            kind: GlitchKind::Spike,
            value,
            samples: len,
            treatment: Treatment::Repaired,
            dropped_with: None,
        });
    }
    if !found.is_empty() {
        repair(&run.t, &mut run.speed, &bad);
    }
}

/// The runs of exact zeros in `speed` (sampled at `t`), as (first sample,
/// samples), of at most [`MAX_ZERO_RUN`] samples, between samples at
/// `min_speed` or faster from which the car could neither have stopped by
/// the first zero nor have started again to the sample after the last at
/// [`MAX_ACCELERATION`].
pub(super) fn impossible_zeros(t: &[f64], speed: &[f64], min_speed: f64) -> Vec<(usize, usize)> {
    let n = speed.len();
    let mut out = Vec::new();
    let mut i = 1;
    while i + 1 < n {
        if speed[i] != 0.0 {
            i += 1;
            continue;
        }
        let j = (i..n).find(|&k| speed[k] != 0.0).unwrap_or(n);
        if j < n && j - i <= MAX_ZERO_RUN {
            let (before, after) = (speed[i - 1].abs(), speed[j].abs());
            let stop = before / MAX_ACCELERATION > t[i] - t[i - 1];
            let start = after / MAX_ACCELERATION > t[j] - t[j - 1];
            if before >= min_speed && after >= min_speed && stop && start {
                out.push((i, j - i));
            }
        }
        i = j;
    }
    out
}

/// The runs of at most [`MAX_ZERO_RUN`] samples below `min_speed` (of any
/// sign, exact zeros among them) between samples at `min_speed` or faster,
/// entered from the sample before and left to the sample after each at
/// more than [`MAX_ACCELERATION`]: no car drove them (a speed read with its
/// sign flipped for a sample is one), as (first sample, samples).
pub(super) fn impossible_dips(t: &[f64], speed: &[f64], min_speed: f64) -> Vec<(usize, usize)> {
    let n = speed.len();
    let mut out = Vec::new();
    let mut i = 1;
    while i + 1 < n {
        if speed[i] >= min_speed || speed[i - 1] < min_speed {
            i += 1;
            continue;
        }
        let j = (i..n).find(|&k| speed[k] >= min_speed).unwrap_or(n);
        if j < n && j - i <= MAX_ZERO_RUN {
            let jump = |a: usize, b: usize| (speed[b] - speed[a]).abs() / (t[b] - t[a]);
            if jump(i - 1, i) > MAX_ACCELERATION && jump(j - 1, j) > MAX_ACCELERATION {
                out.push((i, j - i));
            }
        }
        i = j;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At 100 Hz, one zero amid 20 m/s (a stop in 0.01 s: 204 g) is a
    /// zero read; so are three; a stop braked at 8 m/s² to zeros and a
    /// start from them is none, nor a zero at the record's end.
    #[test]
    fn a_dropout_no_car_can_drive_is_found_and_a_braked_stop_is_not() {
        let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.01).collect();
        let mut u = vec![20.0; 200];
        u[50] = 0.0;
        u[120..123].iter_mut().for_each(|v| *v = 0.0);
        u[199] = 0.0;
        assert_eq!(impossible_zeros(&t, &u, 5.0), vec![(50, 1), (120, 3)]);
        // 20 m/s braked at 8 m/s² to rest at 1 s, standing 0.5 s, then
        // starting at 3 m/s².
        let braked: Vec<f64> = t
            .iter()
            .map(|&s| match s {
                s if s < 1.0 => 8.0 * (1.0 - s),
                s if s < 1.5 => 0.0,
                s => 3.0 * (s - 1.5),
            })
            .collect();
        assert!(impossible_zeros(&t, &braked, 0.0).is_empty());
        // A stop in one interval from 20 m/s to three zeros, and a start
        // from them at 3 m/s²: a car cannot stop so, but it can start so,
        // and both are asked.
        let abrupt: Vec<f64> = t
            .iter()
            .map(|&s| match s {
                s if s < 0.995 => 20.0,
                s if s < 1.025 => 0.0,
                s => 3.0 * (s - 1.02),
            })
            .collect();
        assert!(impossible_zeros(&t, &abrupt, 0.0).is_empty());
    }

    /// At 100 Hz, one sample at -20 m/s amid +20 m/s (4,000 m/s² each
    /// way) and two at 3 m/s are dips no car drives; a braking to 4 m/s at
    /// 8 m/s² and back is a real slow span, nor is a dip at the record's
    /// end one (no sample after it).
    #[test]
    fn a_sign_flip_among_fast_samples_is_a_dip_and_a_braked_slowdown_is_not() {
        let t: Vec<f64> = (0..400).map(|k| k as f64 * 0.01).collect();
        let mut u = vec![20.0; 400];
        u[50] = -20.0;
        u[80..82].iter_mut().for_each(|v| *v = 3.0);
        // 20 → 4 m/s at 8 m/s² (2 s) and back: samples 150–350.
        for (k, v) in u.iter_mut().enumerate().take(350).skip(150) {
            let s = (k as f64 - 150.0) * 0.01;
            *v = (20.0 - 8.0 * s.min(2.0 - s).min(1.0)).max(4.0);
        }
        u[399] = -20.0;
        assert_eq!(impossible_dips(&t, &u, 5.0), vec![(50, 1), (80, 2)]);
    }
}
