//! Logger glitches in one channel of a measured run — zero reads, isolated
//! spikes, stuck values — found with robust statistics of the channel
//! itself (the method and thresholds are described in [`super`]), and
//! their treatment: inputs (steer, speed) repaired by linear interpolation
//! in time, responses (yaw rate, ay, beta) masked. Units: the channel's SI
//! unit; times in s.

use super::moves::{beyond_resolution, Moves};
use super::repair::repair;
use super::report::{CleaningReport, Glitch, GlitchKind, RunChannel, Treatment};
use super::settled::settled_hold;
use super::steer_hold::{stuck_steer, SteerScale};
use super::{MAX_ZERO_RUN, MIN_STUCK, RANGE_FLOOR, SEARCHED, SPIKE_MADS, STUCK_CONTEXT};
use crate::measured::MeasuredRun;

/// The middle value (upper median) of `v`, sorted in place; 0 when empty.
pub(crate) fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The median of `v`, the mean of its two middle values for an even
/// count (where [`median`] takes the upper one), sorted in place; NaN when
/// empty. The estimate a robust line or scatter is built on, which must
/// not lean to one side of a pair.
pub(crate) fn midpoint_median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    match n % 2 {
        1 => v[n / 2],
        _ => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

/// The median (upper) interval between successive times `t`, s; 0 with
/// fewer than two times. The sampling a run's windows, filters and gaps
/// are judged by.
pub(crate) fn median_interval(t: &[f64]) -> f64 {
    let mut dt: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    median(&mut dt)
}

/// The nearest-rank `p`-quantile of `sorted` (ascending); None when empty.
pub(crate) fn quantile(sorted: &[f64], p: f64) -> Option<f64> {
    let last = sorted.len().checked_sub(1)?;
    Some(sorted[(last as f64 * p).round() as usize])
}

/// Robust statistics of a channel: the detection threshold T.
pub(super) struct Scale {
    pub(super) threshold: f64,
    /// How far from 0 the neighbours of a zero read must be: in a channel
    /// whose values do not repeat (no quantum, noise on every sample) an
    /// exact 0 between samples of one sign is itself improbable, so
    /// `ZERO_MADS`·σ_d suffices; a quantised channel, where 0 is one of its
    /// levels, keeps the spike threshold.
    zero_threshold: f64,
}

/// Robust spreads of the sample-to-sample differences beyond which the
/// neighbours of an exact 0 in an unquantised channel make it a zero read.
const ZERO_MADS: f64 = 4.0;
/// Share of exactly repeated successive samples above which a channel is
/// quantised.
const QUANTISED_SHARE: f64 = 0.01;
/// Differences below this share of a channel's largest magnitude are the
/// rounding of its values (a double holds about 16 digits), no quantum.
const ROUNDING: f64 = 1e-12;

/// The detection thresholds of the channel `x`, from its samples outside
/// the slow spans `slow` (from all when every sample is slow): a parked
/// car's channel can sit at exactly 0 for minutes (a GPS sideslip, a
/// gated yaw rate), and the zero differences of such a hold would shrink
/// the spread of the driving's and make its noise "spikes".
pub(super) fn scale(x: &[f64], slow: &[bool]) -> Scale {
    let all_slow = slow.iter().all(|&s| s);
    let moving = |i: usize| !slow[i] || all_slow;
    let mut d: Vec<f64> = (1..x.len())
        .filter(|&i| moving(i) && moving(i - 1))
        .map(|i| x[i] - x[i - 1])
        .collect();
    if d.is_empty() {
        d = x.windows(2).map(|w| w[1] - w[0]).collect();
    }
    // Repeats other than the zeros themselves.
    let repeats = x.windows(2).filter(|w| w[0] == w[1] && w[0] != 0.0).count();
    let quantised = repeats as f64 > QUANTISED_SHARE * d.len().max(1) as f64;
    // A quantised channel's step: its smallest difference beyond the
    // rounding of its values. A held value written back from an
    // interpolation differs by an ulp (0.0174533 and 0.017453299999999998
    // in a log resampled to 7 Hz): taken as the quantum, that 3e-18 made
    // the threshold the range floor alone, and the steer's straight
    // running before its step a zero read.
    let ulps = ROUNDING * x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let step = d
        .iter()
        .map(|v| v.abs())
        .filter(|v| *v > ulps)
        .fold(f64::INFINITY, f64::min);
    let md = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - md).abs()).collect();
    // The noise of a quantised channel is at least its step/√12, so its
    // differences spread by at least step/√6: a change of one step (one
    // count between neighbours) is the quantisation's, no spike.
    let floor = match quantised && step.is_finite() {
        true => step / 6f64.sqrt(),
        false => 0.0,
    };
    let sigma = (1.4826 * median(&mut dev)).max(floor);
    let mut s: Vec<f64> = (0..x.len()).filter(|&i| moving(i)).map(|i| x[i]).collect();
    s.sort_by(f64::total_cmp);
    let q = |p: f64| quantile(&s, p).unwrap_or(0.0);
    let range = q(0.99) - q(0.01);
    let threshold = (SPIKE_MADS * sigma).max(RANGE_FLOOR * range).max(1e-12);
    Scale {
        threshold,
        zero_threshold: if quantised {
            threshold
        } else {
            (ZERO_MADS * sigma).max(RANGE_FLOOR * range).max(1e-12)
        },
    }
}

/// A glitch found at samples `start..start + len` of one channel.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Found {
    start: usize,
    len: usize,
    kind: GlitchKind,
}

/// The glitches of one channel sampled at `t`, in sample order. `slow`
/// marks samples below the minimum speed (a hold there is a stopped car).
/// Zero reads are found first, then spikes among the samples left, then
/// stuck values among those left.
fn detect(x: &[f64], slow: &[bool]) -> Vec<Found> {
    let n = x.len();
    if n < 5 {
        return Vec::new();
    }
    let mut flagged = vec![false; n];
    let mut out = Vec::new();
    // A hold to the end of the record is judged first and kept out of the
    // spread: its zero differences would make the noise before it spikes.
    let tail = frozen_tail(x, slow, &flagged);
    let sc = match tail {
        Some(f) => {
            flagged[f.start..].iter_mut().for_each(|b| *b = true);
            out.push(f);
            let held: Vec<bool> = (0..n).map(|i| slow[i] || i >= f.start).collect();
            scale(x, &held)
        }
        None => scale(x, slow),
    };
    zero_reads(x, &sc, &mut flagged, &mut out);
    spikes(x, sc.threshold, &mut flagged, &mut out);
    stuck_values(x, slow, &mut flagged, &mut out);
    // The slow spans are excluded whole (and counted as such): a glitch
    // wholly inside one changes nothing that is replayed.
    out.retain(|f| !slow[f.start..f.start + f.len].iter().all(|&s| s));
    out.sort_by_key(|f| f.start);
    out
}

/// Zero reads: runs of exact zeros between samples far from 0 of one sign.
fn zero_reads(x: &[f64], sc: &Scale, flagged: &mut [bool], out: &mut Vec<Found>) {
    let n = x.len();
    let mut i = 0;
    while i < n {
        if x[i] != 0.0 {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < n && x[j] == 0.0 {
            j += 1;
        }
        let len = j - i;
        // Two samples on each side (two on the one side at an end of the
        // run), all far from 0 with one sign: a lone value next to the
        // zeros (a spike beside a stretch of true zeros) is not enough.
        let (mut count, mut all_far, mut sign) = (0, true, 0.0);
        for k in [i.checked_sub(2), i.checked_sub(1), Some(j), Some(j + 1)]
            .into_iter()
            .flatten()
            .filter(|&k| k < n)
        {
            if count == 0 {
                sign = x[k].signum();
            }
            all_far &= x[k].abs() > sc.zero_threshold && x[k].signum() == sign;
            count += 1;
        }
        let accepted = count >= 2 && (i > 0 || j + 1 < n) && (j < n || i >= 2) && all_far;
        if len <= MAX_ZERO_RUN && accepted {
            flagged[i..j].iter_mut().for_each(|f| *f = true);
            out.push(Found {
                start: i,
                len,
                kind: GlitchKind::ZeroRead,
            });
        }
        i = j;
    }
}

/// Isolated spikes: inside the run against both neighbours, at its ends
/// against the line through the next two.
fn spikes(x: &[f64], tt: f64, flagged: &mut [bool], out: &mut Vec<Found>) {
    let n = x.len();
    for i in 0..n {
        if flagged[i] {
            continue;
        }
        let (a, b, pred, sided) = if i == 0 {
            let (a, b) = (x[1], x[2]);
            (a, b, 2.0 * a - b, true)
        } else if i == n - 1 {
            let (a, b) = (x[n - 2], x[n - 3]);
            (a, b, 2.0 * a - b, true)
        } else {
            let (a, b) = (x[i - 1], x[i + 1]);
            let s = (x[i] - a).signum() == (x[i] - b).signum()
                && (x[i] - a).abs() > 0.5 * tt
                && (x[i] - b).abs() > 0.5 * tt
                && bends_back(x, i);
            (a, b, 0.5 * (a + b), s)
        };
        let r = x[i] - pred;
        if sided && r.abs() > tt && (a - b).abs() < r.abs() {
            flagged[i] = true;
            out.push(Found {
                start: i,
                len: 1,
                kind: GlitchKind::Spike,
            });
        }
    }
}

/// Whether the neighbours of sample `i` bend back against its own bend:
/// a one-sample excursion `h` gives second differences `h, −2h, h`
/// there, while a smooth hump sampled coarsely (a step's sideslip at
/// 25 Hz) bends one way over all three. True where a side lacks a second
/// neighbour.
fn bends_back(x: &[f64], i: usize) -> bool {
    let bend = |k: usize| x[k - 1] - 2.0 * x[k] + x[k + 1];
    let own = bend(i);
    (i < 2 || bend(i - 1) * own < 0.0) && (i + 2 >= x.len() || bend(i + 1) * own < 0.0)
}

/// A hold that runs to the end of the record (a sensor that stopped
/// updating, the logger repeating its last value): [`stuck_values`] judges
/// a hold by both sides and cannot see it. Judged by the side it has: at
/// least [`MIN_STUCK`] samples, not all slow, after a stretch of at least
/// [`STUCK_CONTEXT`] samples (up to the hold's length) that moves on most
/// samples (fewer than half its differences zero) and roughly (second
/// differences at least half the first: noise, not a smooth noise-free
/// signal), and long enough that chance would hardly hold the channel so
/// (`n·p₀^(len−1) < 1e-3`, `p₀` the share of zero differences before it).
fn frozen_tail(x: &[f64], slow: &[bool], flagged: &[bool]) -> Option<Found> {
    let n = x.len();
    let last = x[n - 1];
    let start = (0..n).rev().take_while(|&i| x[i] == last).last()?;
    let len = n - start;
    let from = start.saturating_sub(len.max(STUCK_CONTEXT));
    if start < STUCK_CONTEXT || len < MIN_STUCK || slow[start..].iter().all(|s| *s) {
        return None;
    }
    let before = Moves::over(x, flagged, from, start + 1);
    let noisy = beyond_resolution(x, flagged, start - STUCK_CONTEXT, start);
    (noisy
        && before.moving()
        && before.m1() > 0.0
        && before.rough()
        && before.chance(n, len) < 1e-3)
        .then_some(Found {
            start,
            len,
            kind: GlitchKind::Stuck,
        })
}

/// Stuck values: holds that chance would hardly give this channel.
fn stuck_values(x: &[f64], slow: &[bool], flagged: &mut [bool], out: &mut Vec<Found>) {
    let n = x.len();
    let mut i = 0;
    while i < n {
        let mut j = i + 1;
        while j < n && x[j] == x[i] {
            j += 1;
        }
        let len = j - i;
        let w = len.max(STUCK_CONTEXT);
        let (lo, hi) = (i.saturating_sub(w), (j + w).min(n));
        // A hold is judged by how the channel moves on both sides of it:
        // zero differences there (quantisation, a steady noise-free signal)
        // make it ordinary; a noisy neighbourhood (second differences as
        // large as first ones) or a release jump of the size the signal
        // would have moved meanwhile make it a stuck sensor.
        let stuck = i - lo >= STUCK_CONTEXT && hi - j >= STUCK_CONTEXT && {
            let (a, b) = (
                Moves::over(x, flagged, lo, i),
                Moves::over(x, flagged, j, hi),
            );
            let both = a.and(b);
            let jump = (x[j] - x[j - 1]).abs() >= 0.5 * len as f64 * both.m1();
            beyond_resolution(x, flagged, lo, i)
                && beyond_resolution(x, flagged, j, hi)
                && a.moving()
                && b.moving()
                && both.chance(n, len) < 1e-3
                && both.m1() > 0.0
                && (both.rough() || jump)
        };
        let stopped = slow[i..j].iter().all(|s| *s);
        if len >= MIN_STUCK && stuck && !stopped && !flagged[i..j].iter().any(|f| *f) {
            flagged[i..j].iter_mut().for_each(|f| *f = true);
            out.push(Found {
                start: i,
                len,
                kind: GlitchKind::Stuck,
            });
        }
        i = j;
    }
}

/// The response channels a settled hold is judged against.
const RESPONSES: [RunChannel; 3] = [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta];

/// Whether a response's zero run `f` opens the record and ends where a
/// steer held exactly over it changes: the response read 0 before the
/// steer moved (a noise-free record's straight running before an instant
/// step: its ay jumps with the steer, 10 zeros at 10 Hz), not a dropout.
/// Masked, it was filled with the first sample after the step, and the
/// step of `ay` read 0.652 m/s² for 1.40. A logger's noisy steer is never
/// held exactly, so a noisy log's leading zeros stay zero reads.
///
/// The zeros may end at the steer's change or one sample after it: a yaw
/// rate starts from 0 at the step's own sample (it is continuous) and ay
/// jumps with the steer, so a sample landing on the step reads 0 in the
/// one and not in the other (a 7 Hz log's gain read 86 % low with the
/// yaw rate's eight leading zeros masked).
fn zero_before_steer(steer: &[f64], f: &Found) -> bool {
    let end = f.start + f.len;
    let Some(change) = steer.iter().position(|&d| d != steer[0]) else {
        return false;
    };
    f.start == 0 && end < steer.len() && (change == end || change + 1 == end)
}

/// Whether a response's one-sample excursion `f` is the response to a
/// steer step: the steer moves by more than `floor`
/// ([`steer_step_floor`]) over the samples from two before it to one
/// after (a step between the excursion's neighbours, or just before the
/// earlier one). A coarse log samples a fast response once on its way
/// (an instant step's sideslip at 10 Hz: 0 at the step's sample, +0.00057
/// rad 0.1 s later, −0.00089 rad the next, its physical jump and turn)
/// and that sample bends back like a spike; masked, the sideslip's
/// initial response was read away. A glitch on the step's own samples
/// cannot be told from the response there, and is left in it.
fn at_steer_step(steer: &[f64], floor: f64, f: &Found) -> bool {
    let lo = f.start.saturating_sub(2);
    let hi = (f.start + f.len + 1).min(steer.len());
    let near = &steer[lo..hi];
    let max = near.iter().copied().fold(f64::MIN, f64::max);
    let min = near.iter().copied().fold(f64::MAX, f64::min);
    max - min > floor
}

/// How far the steer must move over three intervals to be a step: half
/// its 1–99 % range (a step steer's range is its step; a sweep or a
/// slalom crosses half its range in three samples only where the log
/// barely resolves it), and beyond its noise ([`SPIKE_MADS`] robust
/// spreads of its differences). The spike threshold's quantisation floor
/// is not used: a noise-free step steer holds its values, which reads as
/// a quantum of the whole step.
fn steer_step_floor(steer: &[f64]) -> f64 {
    let mut s = steer.to_vec();
    s.sort_by(f64::total_cmp);
    let range = quantile(&s, 0.99).unwrap_or(0.0) - quantile(&s, 0.01).unwrap_or(0.0);
    let mut d: Vec<f64> = steer.windows(2).map(|w| w[1] - w[0]).collect();
    let md = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - md).abs()).collect();
    let sigma = 1.4826 * median(&mut dev);
    (0.5 * range).max(SPIKE_MADS * sigma).max(1e-12)
}

/// Finds the glitches of one run (a piece between time gaps), repairs its
/// inputs, masks its responses, and lists what it found in `report`.
pub fn treat_glitches(run: &mut MeasuredRun, min_speed: f64, report: &mut CleaningReport) {
    let name = run.path.display().to_string();
    let n = run.t.len();
    super::speed_dropout::speed_dropouts(run, min_speed, report);
    let slow: Vec<bool> = run.speed.iter().map(|v| *v < min_speed).collect();
    let mut masked = vec![false; n];
    for &i in &run.masked {
        masked[i] = true;
    }
    for ch in SEARCHED {
        let Some(x) = ch.of(run) else { continue };
        let mut found = detect(x, &slow);
        // A steer that opens the record at exactly 0 is the wheels held straight
        // before the manoeuvre, not a zero read: a
        // record starts in straight running, a dropout there has no earlier
        // sample to be told from it by, and repaired, the zeros took the step's
        // value and the record began turned (a 7 Hz log's 0.1° first ramp
        // sample held from the start, and its yaw-rate gain read 53.96 where the
        // closed form is 5.409).
        // A steer's exact hold is a stuck sensor only where the car or the
        // steer's own trend says so (`steer_hold.rs`).
        if ch == RunChannel::Steer {
            found.retain(|f| f.kind != GlitchKind::ZeroRead || f.start > 0);
            if found.iter().any(|f| f.kind == GlitchKind::Stuck) {
                let s = SteerScale::of(run, &slow);
                found.retain(|f| {
                    f.kind != GlitchKind::Stuck || stuck_steer(run, &s, f.start, f.len)
                });
            }
        }
        // A response's hold that is its settled value, the other responses
        // steady with it, is no stuck sensor (`settled.rs`).
        if !ch.is_input() {
            let others: Vec<&[f64]> = RESPONSES
                .iter()
                .filter(|&&o| o != ch)
                .filter_map(|o| o.of(run).map(Vec::as_slice))
                .collect();
            found.retain(|f| {
                f.kind != GlitchKind::Stuck || !settled_hold(x, f.start, f.len, &others)
            });
            found.retain(|f| f.kind != GlitchKind::ZeroRead || !zero_before_steer(&run.steer, f));
            let step = steer_step_floor(&run.steer);
            found.retain(|f| f.kind != GlitchKind::Spike || !at_steer_step(&run.steer, step, f));
        }
        if found.is_empty() {
            continue;
        }
        let mut bad = vec![false; n];
        for f in &found {
            bad[f.start..f.start + f.len]
                .iter_mut()
                .for_each(|b| *b = true);
            report.push_glitch(Glitch {
                run: name.clone(),
                t: run.t[f.start],
                channel: ch,
                kind: f.kind,
                value: x[f.start],
                samples: f.len,
                treatment: Treatment::of(ch),
                dropped_with: None,
            });
        }
        if ch.is_input() {
            report.samples_repaired += bad.iter().filter(|b| **b).count();
            let t = run.t.clone();
            if let Some(x) = ch.of_mut(run) {
                repair(&t, x, &bad);
            }
        } else {
            for (m, b) in masked.iter_mut().zip(&bad) {
                *m |= *b;
            }
        }
    }
    run.masked = (0..n).filter(|&i| masked[i]).collect();
}

#[cfg(test)]
#[path = "glitches_tests.rs"]
mod tests;

/// A test on a synthetic run (kept here: the layer check reads a test
/// file of its own as the module's imports).
#[cfg(test)]
mod sweep_tests {
    use super::super::report::RunChannel;
    use super::super::test_signals::no_slow;
    use super::super::{clean_runs, CleanSettings};
    use super::*;

    #[test]
    fn a_zero_read_of_a_sweep_is_found_below_the_spike_threshold() {
        // A frequency sweep's yaw rate moves a lot between samples, so the
        // spike threshold (10 robust spreads of the differences) exceeds
        // many of its values; an exact 0 amid unquantised samples of one
        // sign is still a zero read.
        use crate::proving_ground::{generate, Noise, SynthSpec};
        let s = generate(&SynthSpec {
            effects: Vec::new(),
            seed: 3,
            noise: Noise::default(),
            programme: Default::default(),
        });
        let mut run = s
            .runs
            .iter()
            .find(|r| r.path.to_string_lossy().contains("sweep"))
            .expect("a sweep run")
            .clone();
        let sc = scale(&run.yaw_rate, &no_slow(run.t.len()));
        // A sample well away from 0 but inside the spike threshold, with
        // neighbours of its sign.
        let i = (2..run.t.len() - 2)
            .find(|&i| {
                let v = run.yaw_rate[i];
                v.abs() > 0.5 * sc.threshold
                    && v.abs() < sc.threshold
                    && (i - 2..=i + 2).all(|k| {
                        run.yaw_rate[k].signum() == v.signum()
                            && run.yaw_rate[k].abs() > 0.5 * sc.threshold
                    })
            })
            .expect("a sample inside the spike threshold");
        run.yaw_rate[i] = 0.0;
        let (_, rep) = clean_runs(vec![run.clone()], &CleanSettings::default());
        assert!(
            rep.glitches.iter().any(|g| g.kind == GlitchKind::ZeroRead
                && g.channel == RunChannel::YawRate
                && g.t == run.t[i]),
            "{:?}",
            rep.glitches
        );
    }
}
