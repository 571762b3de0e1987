//! Finding the standstills and the straights of a raw run (the rules are in
//! [`super`]): every criterion is applied to centred running medians over
//! [`super::MEDIAN_WINDOW`], so that an isolated spike, a zero read or a
//! short hold of a logger neither breaks a span nor makes one; the run is
//! taken piece by piece between its time gaps, so no span bridges a
//! dropout. Indices are the run's samples; spans are `[lo, hi)`.

use super::report::{Criteria, RejectedStraight, Rejection};
use crate::constants::G;
use crate::measured::clean::{gapless, median, median_interval};
use crate::measured::MeasuredRun;

/// Centred running median of `x` over `2h + 1` samples (fewer at the ends).
fn running_median(x: &[f64], h: usize) -> Vec<f64> {
    let n = x.len();
    let mut buf = Vec::with_capacity(2 * h + 1);
    (0..n)
        .map(|i| {
            buf.clear();
            buf.extend_from_slice(&x[i.saturating_sub(h)..(i + h + 1).min(n)]);
            let k = buf.len() / 2;
            *buf.select_nth_unstable_by(k, f64::total_cmp).1
        })
        .collect()
}

/// The running medians of one channel of `run`, piece by piece between its
/// time gaps, over `window` seconds.
pub(super) fn smoothed(run: &MeasuredRun, x: &[f64], window: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(x.len());
    for (lo, hi) in gapless(&run.t) {
        let dt = median_interval(&run.t[lo..hi]);
        let h = if dt > 0.0 {
            ((0.5 * window / dt).round() as usize).max(1)
        } else {
            1
        };
        out.extend(running_median(&x[lo..hi], h));
    }
    out
}

/// The speed's derivative without `ax`: central differences of its running
/// median `u` across one window (one-sided at the pieces' ends).
fn slope(t: &[f64], u: &[f64], window: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(u.len());
    for (lo, hi) in gapless(t) {
        for i in lo..hi {
            let a = lo + t[lo..i].partition_point(|&s| s < t[i] - 0.5 * window);
            let b = i + t[i..hi].partition_point(|&s| s <= t[i] + 0.5 * window) - 1;
            out.push(if t[b] > t[a] {
                (u[b] - u[a]) / (t[b] - t[a])
            } else {
                0.0
            });
        }
    }
    out
}

/// The maximal stretches where `ok` holds, within the run's gapless
/// pieces, cut by `trim` seconds at each end and at least `seconds` long
/// after the cut.
fn stretches(t: &[f64], ok: &[bool], trim: f64, seconds: f64) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (lo, hi) in gapless(t) {
        let mut i = lo;
        while i < hi {
            if !ok[i] {
                i += 1;
                continue;
            }
            let mut j = i;
            while j < hi && ok[j] {
                j += 1;
            }
            let (a, b) = (t[i] + trim, t[j - 1] - trim);
            let first = i + t[i..j].partition_point(|&s| s < a);
            let end = i + t[i..j].partition_point(|&s| s <= b);
            if end > first && t[end - 1] - t[first] >= seconds {
                out.push((first, end));
            }
            i = j;
        }
    }
    out
}

/// The standstills of `run`.
pub(super) fn standstills(run: &MeasuredRun, c: &Criteria) -> Vec<(usize, usize)> {
    let u = smoothed(run, &run.speed, c.median_window);
    let ok: Vec<bool> = u.iter().map(|&v| v.abs() < c.standstill_speed).collect();
    stretches(&run.t, &ok, c.standstill_trim, c.standstill_seconds)
}

/// The steer that holds the run straight: the median of the steer's
/// running median over the moving samples whose yaw rate and `ay` pass;
/// None without any.
fn straight_steer(d: &[f64], pass: &dyn Fn(usize) -> bool) -> Option<f64> {
    let mut on: Vec<f64> = (0..d.len()).filter(|&i| pass(i)).map(|i| d[i]).collect();
    (!on.is_empty()).then(|| median(&mut on))
}

/// The straights of `run` (judged against the yaw rate `yaw_reference`)
/// and the candidates refused.
pub(super) fn straights(
    run: &MeasuredRun,
    yaw_reference: f64,
    c: &Criteria,
) -> (Vec<(usize, usize)>, Vec<RejectedStraight>) {
    let w = c.median_window;
    let u = smoothed(run, &run.speed, w);
    let r = smoothed(run, &run.yaw_rate, w);
    let d = smoothed(run, &run.steer, w);
    let ax = match &run.ax {
        Some(a) => smoothed(run, a, w),
        None => slope(&run.t, &u, w),
    };
    // The accelerometer, less a logged bank's term: a yaw rate read too
    // small (in rad/s declared in deg/s) keeps a steady turn within the
    // yaw bands, and its 2 m/s² were taken for an `ay` offset.
    let ay = run.ay.as_ref().map(|a| {
        let level: Vec<f64> = match &run.bank {
            Some(b) => a.iter().zip(b).map(|(a, b)| a - G * b.sin()).collect(),
            None => a.clone(),
        };
        smoothed(run, &level, w)
    });
    let turning = |i: usize| {
        let dr = r[i] - yaw_reference;
        u[i] < c.straight_speed
            || dr.abs() > c.straight_yaw_rate
            || (u[i] * dr).abs() > c.straight_lateral
            || ay.as_ref().is_some_and(|a| a[i].abs() > c.straight_ay)
    };
    let Some(d0) = straight_steer(&d, &|i| !turning(i)) else {
        return (Vec::new(), Vec::new());
    };
    let ok: Vec<bool> = (0..u.len())
        .map(|i| {
            !turning(i) && (d[i] - d0).abs() <= c.straight_steer && ax[i].abs() <= c.straight_ax
        })
        .collect();
    let mut kept = Vec::new();
    let mut refused = Vec::new();
    for (lo, hi) in stretches(&run.t, &ok, c.straight_trim, c.straight_seconds) {
        let mut reasons = whole_span(&u[lo..hi], &r[lo..hi], c);
        reasons.extend(swings(run, (lo, hi), yaw_reference, d0, c));
        if reasons.is_empty() {
            kept.push((lo, hi));
        } else {
            refused.push(RejectedStraight {
                run: run.path.display().to_string(),
                t_start: run.t[lo],
                t_end: run.t[hi - 1],
                reasons,
            });
        }
    }
    (kept, refused)
}

/// The whole-span tests of a candidate straight (running medians of speed
/// `u` and yaw rate `r` over it): what fails.
fn whole_span(u: &[f64], r: &[f64], c: &Criteria) -> Vec<Rejection> {
    let n = r.len() as f64;
    let mean_r = r.iter().sum::<f64>() / n;
    let std = (r.iter().map(|x| (x - mean_r).powi(2)).sum::<f64>() / n).sqrt();
    let mean_u = u.iter().sum::<f64>() / n;
    let (lo, hi) = u
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    let share = (hi - lo) / mean_u;
    let mut out = Vec::new();
    if std > c.straight_yaw_variation {
        out.push(Rejection::YawRateVaries {
            std,
            limit: c.straight_yaw_variation,
        });
    }
    if share > c.straight_speed_variation {
        out.push(Rejection::SpeedVaries {
            share,
            limit: c.straight_speed_variation,
        });
    }
    out
}

/// The root-mean-square of the raw samples of `x` over `[lo, hi)` of `run`
/// (masked samples and glitches left out) about `reference`, less the
/// channel's white noise in quadrature: what the signal itself does. The
/// noise is estimated from successive differences (`1.4826·MAD/√2`): a
/// white noise shows in full there, a swing slower than a few samples
/// barely (a 1 Hz sine at 100 Hz moves 6 % of its amplitude per sample).
/// An autocorrelated noise shows less in the differences and counts
/// partly as signal: the limit then holds the noise and the signal
/// together, the conservative side.
fn swing(run: &MeasuredRun, x: &[f64], (lo, hi): (usize, usize), reference: f64) -> f64 {
    let live: Vec<f64> = (lo..hi)
        .filter(|i| run.masked.binary_search(i).is_err())
        .map(|i| x[i])
        .collect();
    let Some((kept, _)) = super::stats::without_glitches(&live) else {
        // One value throughout: no swing beyond its distance from the
        // reference.
        return live.first().map_or(0.0, |v| (v - reference).abs());
    };
    let mut steps: Vec<f64> = kept.windows(2).map(|w| w[1] - w[0]).collect();
    let noise = match steps.len() {
        0 => 0.0,
        _ => {
            let m = median(&mut steps.clone());
            let mut dev: Vec<f64> = steps.iter_mut().map(|d| (*d - m).abs()).collect();
            1.4826 * median(&mut dev) / std::f64::consts::SQRT_2
        }
    };
    let ms = kept.iter().map(|v| (v - reference).powi(2)).sum::<f64>() / kept.len() as f64;
    (ms - noise * noise).max(0.0).sqrt()
}

/// The raw-sample tests of a candidate straight `span` of `run`: the
/// running medians hide a swing as fast as their window (a 1 Hz slalom's
/// steer and yaw rate have medians near 0 over 1 s), so the steer and the
/// yaw rate themselves, beyond their noise ([`swing`]), must stay within
/// the same bands as the medians: [`Criteria::straight_steer`] of the
/// straight-line steer `d0`, [`Criteria::straight_yaw_rate`] of
/// `yaw_reference`.
fn swings(
    run: &MeasuredRun,
    span: (usize, usize),
    yaw_reference: f64,
    d0: f64,
    c: &Criteria,
) -> Vec<Rejection> {
    let mut out = Vec::new();
    let steer = swing(run, &run.steer, span, d0);
    if steer > c.straight_steer {
        out.push(Rejection::SteerSwings {
            rms: steer,
            limit: c.straight_steer,
        });
    }
    let yaw = swing(run, &run.yaw_rate, span, yaw_reference);
    if yaw > c.straight_yaw_rate {
        out.push(Rejection::YawRateSwings {
            rms: yaw,
            limit: c.straight_yaw_rate,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_running_median_ignores_a_spike_and_keeps_a_step() {
        let mut x = vec![0.0; 50];
        x[20] = 100.0;
        x[30..].iter_mut().for_each(|v| *v = 1.0);
        let m = running_median(&x, 2);
        assert_eq!(m[20], 0.0);
        assert_eq!(m[29], 0.0);
        assert_eq!(m[30], 1.0);
    }

    #[test]
    fn stretches_are_cut_at_their_ends_and_at_time_gaps() {
        // 100 Hz, 0–10 s and 12–20 s (a 2 s dropout), all passing.
        let t: Vec<f64> = (0..1000)
            .map(|i| i as f64 * 0.01)
            .chain((0..800).map(|i| 12.0 + i as f64 * 0.01))
            .collect();
        let ok = vec![true; t.len()];
        let s = stretches(&t, &ok, 1.0, 3.0);
        assert_eq!(s.len(), 2);
        assert!((t[s[0].0] - 1.0).abs() < 1e-9 && (t[s[0].1 - 1] - 8.99).abs() < 1e-9);
        assert!((t[s[1].0] - 13.0).abs() < 1e-9 && (t[s[1].1 - 1] - 18.99).abs() < 1e-9);
        // Too short after the cut: 4.5 s less 2 s is under 3 s.
        let s = stretches(&t[..450], &ok[..450], 1.0, 3.0);
        assert!(s.is_empty());
    }
}
