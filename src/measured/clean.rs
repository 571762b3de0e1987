//! What a measured run holds besides the manoeuvre: standstills, crawling
//! and the glitches of real loggers (`FORMATS.md`), found, treated and
//! listed before any replay or score.
//!
//! - Time gaps longer than five median sample intervals split a run (a
//!   replay cannot bridge a dropout).
//! - Glitches are found on every sample of the driving and response channels
//!   (steer, speed; yaw rate, ay, beta) with robust statistics of the
//!   channel itself. Its scale is `σ_d = 1.4826·MAD(Δx)`, the robust spread
//!   of the sample-to-sample differences (white noise of deviation s gives
//!   `σ_d = √2·s`; a smooth signal gives its typical change per sample), with
//!   a floor of [`RANGE_FLOOR`] of the channel's 1–99 % range for noise-free
//!   channels. The detection threshold is `T = max(K·σ_d, floor)`, K =
//!   [`SPIKE_MADS`].
//!   - zero read: one to [`MAX_ZERO_RUN`] samples read as exactly 0 while the
//!     two samples on each side (on the one side at an end of the run) lie
//!     beyond T, all with one sign;
//!   - isolated spike: a sample beyond T from the line through its two
//!     neighbours, on the same side of both, while the neighbours agree with
//!     each other better than with it (a step has one side only; a peak of a
//!     smooth signal stays well inside T);
//!   - stuck value: a value held exactly for at least [`MIN_STUCK`] samples
//!     where the chance of such a hold, `n·p0^(L−1)` with p0 the channel's
//!     share of zero differences, is below 1e-3 (a quantised or noise-free
//!     channel holds values by nature and is never called stuck).
//! - Inputs that drive the replay (steer, speed) are repaired by linear
//!   interpolation in time across the glitch, so the replay is not kicked;
//!   in response channels (yaw rate, ay, beta) the sample is masked: left out
//!   of fits and scores.
//! - Samples slower than `min_speed` (a standstill when the car stops in
//!   the span, below [`STANDSTILL_SPEED`]; else a crawl) are excluded: the model is a
//!   driving model, and at a standstill its output chatters on sensor noise.
//!   The moving pieces they leave are replayed separately; in a diagnosis
//!   pieces shorter than [`MIN_RUN_SECONDS`] or [`MIN_RUN_SAMPLES`] are
//!   dropped; a single replay or the metrics of a run take its longest
//!   piece and list the others as dropped.
//!
//! Everything found, excluded or dropped is in the [`CleaningReport`].
//! Units: SI, rad, times in s.

use super::MeasuredRun;
use serde::Serialize;
use std::path::PathBuf;

/// Shortest run a diagnosis accepts, s: a step response needs its
/// pre-input window, rise and settling.
pub const MIN_RUN_SECONDS: f64 = 2.0;

/// Fewest samples a run must have.
pub const MIN_RUN_SAMPLES: usize = 20;

/// Default lowest speed of a replayed sample, m/s.
pub const DEFAULT_MIN_SPEED: f64 = 5.0;
/// Below this speed a slow span is a standstill rather than a crawl, m/s.
pub const STANDSTILL_SPEED: f64 = 0.5;
/// Spike and zero-read threshold in robust deviations of the differences.
pub const SPIKE_MADS: f64 = 10.0;
/// Threshold floor as a share of the channel's 1–99 % range.
pub const RANGE_FLOOR: f64 = 0.02;
/// Longest run of zeros still called a zero read.
pub const MAX_ZERO_RUN: usize = 10;
/// Fewest samples of an exact hold called stuck.
pub const MIN_STUCK: usize = 5;
/// Samples on each side of a hold that show how the channel moves there.
pub const STUCK_CONTEXT: usize = 10;
/// A time gap: this many median sample intervals.
pub const GAP_INTERVALS: f64 = 5.0;

/// A channel of a measured run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RunChannel {
    /// Time.
    T,
    /// Forward speed.
    Speed,
    /// Front road-wheel steer.
    Steer,
    /// Yaw rate.
    YawRate,
    /// Lateral acceleration.
    Ay,
    /// Sideslip.
    Beta,
}

impl RunChannel {
    /// Column name.
    pub fn name(self) -> &'static str {
        match self {
            RunChannel::T => "t",
            RunChannel::Speed => "speed",
            RunChannel::Steer => "steer",
            RunChannel::YawRate => "yaw_rate",
            RunChannel::Ay => "ay",
            RunChannel::Beta => "beta",
        }
    }
    /// Does it drive the replay (repaired) rather than answer it (masked).
    pub fn is_input(self) -> bool {
        matches!(self, RunChannel::Speed | RunChannel::Steer)
    }
    fn of(self, run: &MeasuredRun) -> Option<&Vec<f64>> {
        match self {
            RunChannel::T => Some(&run.t),
            RunChannel::Speed => Some(&run.speed),
            RunChannel::Steer => Some(&run.steer),
            RunChannel::YawRate => Some(&run.yaw_rate),
            RunChannel::Ay => run.ay.as_ref(),
            RunChannel::Beta => run.beta.as_ref(),
        }
    }
    fn of_mut(self, run: &mut MeasuredRun) -> Option<&mut Vec<f64>> {
        match self {
            RunChannel::T => Some(&mut run.t),
            RunChannel::Speed => Some(&mut run.speed),
            RunChannel::Steer => Some(&mut run.steer),
            RunChannel::YawRate => Some(&mut run.yaw_rate),
            RunChannel::Ay => run.ay.as_mut(),
            RunChannel::Beta => run.beta.as_mut(),
        }
    }
}

/// Channels searched for glitches.
const SEARCHED: [RunChannel; 5] = [
    RunChannel::Steer,
    RunChannel::Speed,
    RunChannel::YawRate,
    RunChannel::Ay,
    RunChannel::Beta,
];

/// Kinds of logger glitch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GlitchKind {
    /// Samples read as exactly 0 amid values far from 0.
    ZeroRead,
    /// One sample far off the line through its neighbours.
    Spike,
    /// A value held exactly while the channel otherwise moves.
    Stuck,
    /// Time between samples longer than five median intervals.
    TimeGap,
}

impl GlitchKind {
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            GlitchKind::ZeroRead => "zero_read",
            GlitchKind::Spike => "spike",
            GlitchKind::Stuck => "stuck",
            GlitchKind::TimeGap => "time_gap",
        }
    }
}

impl Treatment {
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Treatment::Repaired => "repaired",
            Treatment::Masked => "masked",
            Treatment::Split => "split",
        }
    }
}

impl SlowKind {
    /// Name in reports.
    pub fn name(self) -> &'static str {
        match self {
            SlowKind::Standstill => "standstill",
            SlowKind::Crawl => "crawl",
        }
    }
}

/// A value for the terminal: six significant digits, no float noise.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let scale = 10f64.powi(5 - v.abs().log10().floor() as i32);
    format!("{}", (v * scale).round() / scale)
}

/// What was done about a glitch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Treatment {
    /// An input interpolated across it.
    Repaired,
    /// A response sample left out of fits and scores.
    Masked,
    /// The run split there.
    Split,
}

/// One glitch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Glitch {
    /// The run (file) it is in.
    pub run: String,
    /// Time of its first sample, s (for a time gap: the last sample before).
    pub t: f64,
    /// The channel.
    pub channel: RunChannel,
    /// What it is.
    pub kind: GlitchKind,
    /// The value read (for a time gap: its length, s).
    pub value: f64,
    /// Samples it covers (0 for a time gap).
    pub samples: usize,
    /// What was done.
    pub treatment: Treatment,
}

/// Why a slow span was excluded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlowKind {
    /// The car stopped in it (below 0.5 m/s at some sample).
    Standstill,
    /// The car crawled below the minimum speed without stopping.
    Crawl,
}

/// A span of samples below the minimum speed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SlowSpan {
    /// The run.
    pub run: String,
    /// First excluded sample, s.
    pub t_start: f64,
    /// Last excluded sample, s.
    pub t_end: f64,
    /// Samples excluded.
    pub samples: usize,
    /// Highest speed in the span, m/s.
    pub max_speed: f64,
    /// Standstill or crawl.
    pub kind: SlowKind,
}

/// A piece of a run (kept or dropped).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Piece {
    /// Its name (the file and a piece label).
    pub name: String,
    /// First sample, s.
    pub t_start: f64,
    /// Last sample, s.
    pub t_end: f64,
    /// Samples.
    pub samples: usize,
    /// Why a dropped piece was dropped (empty for a kept one).
    pub reason: String,
}

/// Glitches per kind.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct GlitchCounts {
    /// Zero reads.
    pub zero_read: usize,
    /// Isolated spikes.
    pub spike: usize,
    /// Stuck values.
    pub stuck: usize,
    /// Time gaps.
    pub time_gap: usize,
}

/// Everything found in and done to the runs before replay.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct CleaningReport {
    /// Lowest speed replayed, m/s.
    pub min_speed: f64,
    /// Samples read.
    pub samples_read: usize,
    /// Samples replayed (in kept pieces).
    pub samples_kept: usize,
    /// Samples excluded for low speed.
    pub samples_slow: usize,
    /// Samples in pieces too short to keep.
    pub samples_in_dropped_pieces: usize,
    /// Response samples masked from fits and scores (in kept pieces).
    pub samples_masked: usize,
    /// Input samples repaired by interpolation.
    pub samples_repaired: usize,
    /// Glitches per kind.
    pub counts: GlitchCounts,
    /// Every glitch, in run and time order.
    pub glitches: Vec<Glitch>,
    /// Spans excluded for low speed.
    pub slow: Vec<SlowSpan>,
    /// Pieces replayed.
    pub pieces: Vec<Piece>,
    /// Pieces dropped as too short.
    pub dropped_pieces: Vec<Piece>,
}

impl CleaningReport {
    /// An empty report for runs cleaned at `min_speed`.
    pub fn new(min_speed: f64) -> Self {
        Self {
            min_speed,
            ..Self::default()
        }
    }

    fn push_glitch(&mut self, g: Glitch) {
        match g.kind {
            GlitchKind::ZeroRead => self.counts.zero_read += 1,
            GlitchKind::Spike => self.counts.spike += 1,
            GlitchKind::Stuck => self.counts.stuck += 1,
            GlitchKind::TimeGap => self.counts.time_gap += 1,
        }
        self.glitches.push(g);
    }

    /// The report in a few lines for the terminal: counts per kind, the
    /// first few glitches, the slow spans and the pieces.
    pub fn summary(&self, first: usize) -> Vec<String> {
        let c = &self.counts;
        let mut out = vec![format!(
            "{} samples read, {} kept; {} below {} m/s excluded ({} standstill and {} crawl spans), {} in {} pieces dropped; glitches: {} zero reads, {} spikes, {} stuck values, {} time gaps ({} input samples repaired, {} response samples masked)",
            self.samples_read,
            self.samples_kept,
            self.samples_slow,
            self.min_speed,
            self.slow.iter().filter(|s| s.kind == SlowKind::Standstill).count(),
            self.slow.iter().filter(|s| s.kind == SlowKind::Crawl).count(),
            self.samples_in_dropped_pieces,
            self.dropped_pieces.len(),
            c.zero_read,
            c.spike,
            c.stuck,
            c.time_gap,
            self.samples_repaired,
            self.samples_masked,
        )];
        for g in self.glitches.iter().take(first) {
            out.push(format!(
                "{} at {:.3} s in {}: {} {} ({} sample(s), {})",
                g.kind.name(),
                g.t,
                g.run,
                g.channel.name(),
                short(g.value),
                g.samples,
                g.treatment.name()
            ));
        }
        if self.glitches.len() > first {
            out.push(format!(
                "… and {} more glitches (every one in the JSON report)",
                self.glitches.len() - first
            ));
        }
        for s in self.slow.iter().take(first) {
            out.push(format!(
                "{} {:.2}–{:.2} s in {} ({} samples, up to {:.2} m/s) excluded",
                s.kind.name(),
                s.t_start,
                s.t_end,
                s.run,
                s.samples,
                s.max_speed
            ));
        }
        if self.slow.len() > first {
            out.push(format!("… and {} more slow spans", self.slow.len() - first));
        }
        for p in self.dropped_pieces.iter().take(first) {
            out.push(format!(
                "piece {} ({:.2}–{:.2} s, {} samples) dropped: {}",
                p.name, p.t_start, p.t_end, p.samples, p.reason
            ));
        }
        out
    }
}

/// Cleaning settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CleanSettings {
    /// Lowest speed replayed, m/s.
    pub min_speed: f64,
    /// Shortest piece kept, s.
    pub min_piece_seconds: f64,
    /// Fewest samples of a piece kept.
    pub min_piece_samples: usize,
}

impl CleanSettings {
    /// For a diagnosis: pieces must show a response
    /// ([`MIN_RUN_SECONDS`], [`MIN_RUN_SAMPLES`]).
    pub fn diagnosis(min_speed: f64) -> Self {
        Self {
            min_speed,
            min_piece_seconds: MIN_RUN_SECONDS,
            min_piece_samples: MIN_RUN_SAMPLES,
        }
    }
    /// For one replay or one set of metrics: any piece of two samples.
    pub fn single(min_speed: f64) -> Self {
        Self {
            min_speed,
            min_piece_seconds: 0.0,
            min_piece_samples: 2,
        }
    }
}

impl Default for CleanSettings {
    fn default() -> Self {
        Self::diagnosis(DEFAULT_MIN_SPEED)
    }
}

/// The rows `lo..hi` of a run, named with `label` appended to its path.
pub fn slice(run: &MeasuredRun, lo: usize, hi: usize, label: &str) -> MeasuredRun {
    let cut = |v: &Vec<f64>| v[lo..hi].to_vec();
    let mut path = run.path.clone().into_os_string();
    path.push(label);
    MeasuredRun {
        path: PathBuf::from(path),
        t: cut(&run.t),
        speed: cut(&run.speed),
        steer: cut(&run.steer),
        yaw_rate: cut(&run.yaw_rate),
        ay: run.ay.as_ref().map(cut),
        beta: run.beta.as_ref().map(cut),
        roll: run.roll.as_ref().map(cut),
        bank: run.bank.as_ref().map(cut),
        ax: run.ax.as_ref().map(cut),
        masked: run
            .masked
            .iter()
            .filter(|&&i| i >= lo && i < hi)
            .map(|&i| i - lo)
            .collect(),
    }
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Robust statistics of a channel: the detection threshold T.
struct Scale {
    threshold: f64,
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

fn scale(x: &[f64]) -> Scale {
    let mut d: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let md = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - md).abs()).collect();
    let sigma = 1.4826 * median(&mut dev);
    let mut s = x.to_vec();
    s.sort_by(f64::total_cmp);
    let q = |p: f64| s[((s.len() - 1) as f64 * p).round() as usize];
    let range = q(0.99) - q(0.01);
    let threshold = (SPIKE_MADS * sigma).max(RANGE_FLOOR * range).max(1e-12);
    // Repeats other than the zeros themselves.
    let repeats = x.windows(2).filter(|w| w[0] == w[1] && w[0] != 0.0).count();
    let quantised = repeats as f64 > QUANTISED_SHARE * d.len().max(1) as f64;
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
fn detect(x: &[f64], slow: &[bool]) -> Vec<Found> {
    let n = x.len();
    if n < 5 {
        return Vec::new();
    }
    let sc = scale(x);
    let tt = sc.threshold;
    let mut flagged = vec![false; n];
    let mut out = Vec::new();
    // Zero reads.
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
    // Isolated spikes: inside the run against both neighbours, at its ends
    // against the line through the next two.
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
                && (x[i] - b).abs() > 0.5 * tt;
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
    // Stuck values: holds that chance would hardly give this channel.
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
            // Per side: zero differences, differences, Σ|Δx|, Σ|Δ²x|, second
            // differences; samples already found glitched are skipped.
            let side = |from: usize, to: usize| {
                let (mut zeros, mut count, mut d1, mut d2, mut count2) = (0, 0, 0.0, 0.0, 0);
                for k in from + 1..to {
                    if flagged[k] || flagged[k - 1] {
                        continue;
                    }
                    let d = x[k] - x[k - 1];
                    zeros += usize::from(d == 0.0);
                    count += 1;
                    d1 += d.abs();
                    if k >= from + 2 && !flagged[k - 2] {
                        d2 += (d - (x[k - 1] - x[k - 2])).abs();
                        count2 += 1;
                    }
                }
                (zeros, count, d1, d2, count2)
            };
            let (a, b) = (side(lo, i), side(j, hi));
            let moving = |s: (usize, usize, f64, f64, usize)| s.1 >= 3 && 2 * s.0 < s.1;
            let (zeros, count) = (a.0 + b.0, a.1 + b.1);
            let (m1, m2) = (
                (a.2 + b.2) / count.max(1) as f64,
                (a.3 + b.3) / (a.4 + b.4).max(1) as f64,
            );
            let p0 = zeros as f64 / count.max(1) as f64;
            let chance = (n as f64) * p0.powi(len as i32 - 1);
            let rough = m2 >= 0.5 * m1;
            let jump = (x[j] - x[j - 1]).abs() >= 0.5 * len as f64 * m1;
            moving(a) && moving(b) && chance < 1e-3 && m1 > 0.0 && (rough || jump)
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
    out.sort_by_key(|f| f.start);
    out
}

/// Interpolates `x` linearly in `t` across the flagged samples (held at the
/// nearest good value at an end).
fn repair(t: &[f64], x: &mut [f64], bad: &[bool]) {
    let n = x.len();
    let mut i = 0;
    while i < n {
        if !bad[i] {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < n && bad[j] {
            j += 1;
        }
        let left = i.checked_sub(1);
        let right = (j < n).then_some(j);
        for k in i..j {
            x[k] = match (left, right) {
                (Some(l), Some(r)) => x[l] + (x[r] - x[l]) * (t[k] - t[l]) / (t[r] - t[l]),
                (Some(l), None) => x[l],
                (None, Some(r)) => x[r],
                (None, None) => x[k],
            };
        }
        i = j;
    }
}

/// Finds the glitches of one run (a piece between time gaps), repairs its
/// inputs, masks its responses, and lists what it found in `report`.
pub fn treat_glitches(run: &mut MeasuredRun, min_speed: f64, report: &mut CleaningReport) {
    let name = run.path.display().to_string();
    let n = run.t.len();
    let slow: Vec<bool> = run.speed.iter().map(|v| *v < min_speed).collect();
    let mut masked = vec![false; n];
    for &i in &run.masked {
        masked[i] = true;
    }
    for ch in SEARCHED {
        let Some(x) = ch.of(run) else { continue };
        let found = detect(x, &slow);
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
                treatment: if ch.is_input() {
                    Treatment::Repaired
                } else {
                    Treatment::Masked
                },
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

/// The index ranges `[lo, hi)` between time gaps of a run, listing the gaps.
fn split_times(run: &MeasuredRun, report: &mut CleaningReport) -> Vec<(usize, usize)> {
    let mut dt: Vec<f64> = run.t.windows(2).map(|w| w[1] - w[0]).collect();
    let med = median(&mut dt);
    let mut bounds = vec![0];
    for i in 1..run.t.len() {
        if run.t[i] - run.t[i - 1] > GAP_INTERVALS * med {
            bounds.push(i);
            report.push_glitch(Glitch {
                run: run.path.display().to_string(),
                t: run.t[i - 1],
                channel: RunChannel::T,
                kind: GlitchKind::TimeGap,
                value: run.t[i] - run.t[i - 1],
                samples: 0,
                treatment: Treatment::Split,
            });
        }
    }
    bounds.push(run.t.len());
    bounds.windows(2).map(|w| (w[0], w[1])).collect()
}

fn long_enough(run: &MeasuredRun, s: &CleanSettings) -> bool {
    let n = run.t.len();
    n >= s.min_piece_samples.max(2) && run.t[n - 1] - run.t[0] >= s.min_piece_seconds
}

fn piece_of(run: &MeasuredRun, reason: &str) -> Piece {
    Piece {
        name: run.path.display().to_string(),
        t_start: run.t[0],
        t_end: run.t[run.t.len() - 1],
        samples: run.t.len(),
        reason: reason.into(),
    }
}

/// Cleans one run as read: splits it at time gaps, treats its glitches,
/// excludes samples below `settings.min_speed` and returns the moving pieces
/// long enough to replay (pieces are named `file#k` when the run was split).
/// Everything is added to `report`.
pub fn clean_run(
    run: MeasuredRun,
    settings: &CleanSettings,
    report: &mut CleaningReport,
) -> Vec<MeasuredRun> {
    report.samples_read += run.t.len();
    let parts = split_times(&run, report);
    let mut moving: Vec<MeasuredRun> = Vec::new();
    let name = run.path.display().to_string();
    for (lo, hi) in parts {
        let mut part = slice(&run, lo, hi, "");
        treat_glitches(&mut part, settings.min_speed, report);
        let n = part.t.len();
        let mut i = 0;
        while i < n {
            let slow = part.speed[i] < settings.min_speed;
            let mut j = i;
            while j < n && (part.speed[j] < settings.min_speed) == slow {
                j += 1;
            }
            if slow {
                let max_speed = part.speed[i..j].iter().copied().fold(f64::MIN, f64::max);
                let min_speed = part.speed[i..j].iter().copied().fold(f64::MAX, f64::min);
                report.samples_slow += j - i;
                report.slow.push(SlowSpan {
                    run: name.clone(),
                    t_start: part.t[i],
                    t_end: part.t[j - 1],
                    samples: j - i,
                    max_speed,
                    kind: if min_speed < STANDSTILL_SPEED {
                        SlowKind::Standstill
                    } else {
                        SlowKind::Crawl
                    },
                });
            } else {
                moving.push(slice(&part, i, j, ""));
            }
            i = j;
        }
    }
    let whole = moving.len() == 1 && moving[0].t.len() == run.t.len();
    let mut out = Vec::new();
    for (k, mut piece) in moving.into_iter().enumerate() {
        if !whole {
            piece.path = PathBuf::from(format!("{name}#{}", k + 1));
        }
        if long_enough(&piece, settings) {
            report.samples_kept += piece.t.len();
            report.samples_masked += piece.masked.len();
            report.pieces.push(piece_of(&piece, ""));
            out.push(piece);
        } else {
            report.samples_in_dropped_pieces += piece.t.len();
            report.dropped_pieces.push(piece_of(&piece, "too short"));
        }
    }
    out
}

/// Cleans a set of runs (in memory, e.g. a synthetic campaign whose runs
/// were corrupted): the kept pieces of all and one report.
pub fn clean_runs(
    runs: Vec<MeasuredRun>,
    settings: &CleanSettings,
) -> (Vec<MeasuredRun>, CleaningReport) {
    let mut report = CleaningReport::new(settings.min_speed);
    let mut out = Vec::new();
    for r in runs {
        out.extend(clean_run(r, settings, &mut report));
    }
    (out, report)
}

/// Cleans a run for a single replay: the longest moving piece (the other
/// pieces are listed as dropped). `None` when no piece is long enough.
pub fn clean_single(
    run: MeasuredRun,
    settings: &CleanSettings,
    report: &mut CleaningReport,
) -> Option<MeasuredRun> {
    clean_single_with(run, settings, report, |_| Ok(())).map(|(p, ())| p)
}

/// Cleans a run for a single use: of its moving pieces, longest first, the
/// first that `fits` accepts is kept with what `fits` made of it; every
/// other piece is listed as dropped with its reason (what `fits` said, or
/// that another piece was used). `None` when no piece is accepted.
pub fn clean_single_with<T>(
    run: MeasuredRun,
    settings: &CleanSettings,
    report: &mut CleaningReport,
    mut fits: impl FnMut(&MeasuredRun) -> Result<T, String>,
) -> Option<(MeasuredRun, T)> {
    let first = report.pieces.len();
    let pieces = clean_run(run, settings, report);
    report.pieces.truncate(first);
    let mut order: Vec<usize> = (0..pieces.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(pieces[k].t.len()));
    let mut reasons = vec![String::new(); pieces.len()];
    let mut chosen = None;
    for &k in &order {
        match fits(&pieces[k]) {
            Ok(v) => {
                chosen = Some((k, v));
                break;
            }
            Err(e) => reasons[k] = e,
        }
    }
    for (k, p) in pieces.iter().enumerate() {
        if chosen.as_ref().is_some_and(|c| c.0 == k) {
            report.pieces.push(piece_of(p, ""));
            continue;
        }
        let reason = if reasons[k].is_empty() {
            "another piece was used".to_string()
        } else {
            reasons[k].clone()
        };
        report.samples_kept -= p.t.len();
        report.samples_masked -= p.masked.len();
        report.samples_in_dropped_pieces += p.t.len();
        report.dropped_pieces.push(piece_of(p, &reason));
    }
    let (k, v) = chosen?;
    pieces.into_iter().nth(k).map(|p| (p, v))
}

/// Cleans a run read from `path` for tools that read every sample (the
/// step-steer metrics): the longest moving piece with its masked responses
/// filled ([`fill_masked`]); an error naming the file when nothing moves
/// fast and long enough.
pub fn clean_for_metrics(
    run: MeasuredRun,
    min_speed: f64,
) -> Result<(MeasuredRun, CleaningReport), crate::error::InputError> {
    let path = run.path.clone();
    let mut report = CleaningReport::new(min_speed);
    let piece = clean_single(run, &CleanSettings::single(min_speed), &mut report).ok_or_else(|| {
        crate::error::InputError::File {
            path,
            message: format!(
                "no two successive samples at or above min_speed = {min_speed} m/s ({} of {} samples below it)",
                report.samples_slow, report.samples_read
            ),
        }
    })?;
    Ok((fill_masked(&piece), report))
}

/// The run with its masked response samples interpolated across (for tools
/// that need every sample) and the mask cleared.
pub fn fill_masked(run: &MeasuredRun) -> MeasuredRun {
    let mut out = run.clone();
    let mut bad = vec![false; run.t.len()];
    for &i in &run.masked {
        bad[i] = true;
    }
    let t = run.t.clone();
    for ch in [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta] {
        if let Some(x) = ch.of_mut(&mut out) {
            repair(&t, x, &bad);
        }
    }
    out.masked.clear();
    out
}

/// Corrupts a clean run the way loggers do, for tests and benchmarks: in
/// each response channel one zero read, one isolated spike and one value
/// held for eight samples, and in the steer one spike, at seeded places in
/// the driven part of the run (away from its ends and from each other).
/// Returns what was injected, in the form the detector reports it.
pub fn inject_glitches(run: &mut MeasuredRun, seed: u64) -> Vec<Glitch> {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let n = run.t.len();
    let name = run.path.display().to_string();
    let mut taken = vec![false; n];
    let mut out = Vec::new();
    let margin = 10.min(n / 4);
    let plan: Vec<(RunChannel, GlitchKind)> =
        [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta]
            .into_iter()
            .flat_map(|c| {
                [GlitchKind::ZeroRead, GlitchKind::Spike, GlitchKind::Stuck].map(move |k| (c, k))
            })
            .chain(std::iter::once((RunChannel::Steer, GlitchKind::Spike)))
            .collect();
    for (ch, kind) in plan {
        let Some(x) = ch.of(run) else { continue };
        let tt = scale(x).threshold;
        let len = if kind == GlitchKind::Stuck { 8 } else { 1 };
        // A zero read needs a value far from 0 around it; any place will do
        // for the others.
        let mut pick = None;
        for _ in 0..2000 {
            let i = rng.random_range(margin..n - margin - len);
            let free = taken[i.saturating_sub(3)..(i + len + 3).min(n)]
                .iter()
                .all(|t| !t);
            let ok = match kind {
                GlitchKind::ZeroRead => (i - 2..i + 3).all(|k| x[k].abs() > 3.0 * tt),
                _ => true,
            };
            if free && ok {
                pick = Some(i);
                break;
            }
        }
        let Some(i) = pick else { continue };
        let Some(x) = ch.of_mut(run) else { continue };
        let value = match kind {
            GlitchKind::ZeroRead => 0.0,
            GlitchKind::Spike => {
                let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
                0.5 * (x[i - 1] + x[i + 1]) + sign * 3.0 * tt
            }
            _ => x[i],
        };
        for v in &mut x[i..i + len] {
            *v = value;
        }
        taken[i.saturating_sub(3)..(i + len + 3).min(n)]
            .iter_mut()
            .for_each(|t| *t = true);
        out.push(Glitch {
            run: name.clone(),
            t: run.t[i],
            channel: ch,
            kind,
            value,
            samples: len,
            treatment: if ch.is_input() {
                Treatment::Repaired
            } else {
                Treatment::Masked
            },
        });
    }
    out.sort_by(|a, b| a.t.total_cmp(&b.t));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    fn gauss_noise(n: usize, sigma: f64, seed: u64) -> Vec<f64> {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        (0..n)
            .map(|_| sigma * crate::identify::data::gauss(&mut rng))
            .collect()
    }

    fn no_slow(n: usize) -> Vec<bool> {
        vec![false; n]
    }

    #[test]
    fn white_noise_a_step_and_a_sweep_have_no_glitch() {
        for seed in 0..20 {
            let x = gauss_noise(5000, 0.01, seed);
            assert!(detect(&x, &no_slow(5000)).is_empty(), "seed {seed}");
        }
        // A step steer with a 0.1 s ramp at 100 Hz, noise-free and noisy.
        let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
        let step: Vec<f64> = t
            .iter()
            .map(|&x| 0.03 * ((x - 2.0) / 0.1).clamp(0.0, 1.0))
            .collect();
        assert!(detect(&step, &no_slow(1000)).is_empty());
        let sharp: Vec<f64> = t
            .iter()
            .map(|&x| if x >= 2.0 { 0.03 } else { 0.0 })
            .collect();
        assert!(detect(&sharp, &no_slow(1000)).is_empty());
        let noise = gauss_noise(1000, 2e-4, 3);
        let noisy: Vec<f64> = step.iter().zip(&noise).map(|(a, b)| a + b).collect();
        assert!(detect(&noisy, &no_slow(1000)).is_empty());
        // A noise-free first-order response written with six decimals (it
        // settles to a held value) and a steer dwell between ramps.
        let settled: Vec<f64> = t
            .iter()
            .map(|&x| {
                let r = if x > 2.0 {
                    0.2 * (1.0 - (-(x - 2.0) / 0.15).exp())
                } else {
                    0.0
                };
                (r * 1e6).round() / 1e6
            })
            .collect();
        assert!(detect(&settled, &no_slow(1000)).is_empty());
        let dwell: Vec<f64> = t
            .iter()
            .map(|&x| 0.05 * (x - 1.0).clamp(0.0, 1.0) - 0.05 * (x - 4.0).clamp(0.0, 2.0))
            .collect();
        assert!(detect(&dwell, &no_slow(1000)).is_empty());
        // A spike after the dwell is a spike; the holds around it are not
        // made stuck by it.
        let mut spiked = dwell.clone();
        spiked[800] += 0.02;
        let f = detect(&spiked, &no_slow(1000));
        assert_eq!(
            f,
            vec![Found {
                start: 800,
                len: 1,
                kind: GlitchKind::Spike
            }]
        );
        // A sine sweep 0.1–4 Hz at 100 Hz (and at 25 Hz), with noise.
        for dt in [0.01, 0.04] {
            let n = (30.0 / dt) as usize;
            let noise = gauss_noise(n, 1e-3, 5);
            let sweep: Vec<f64> = (0..n)
                .map(|i| {
                    let x = i as f64 * dt;
                    0.05 * (std::f64::consts::TAU * (0.1 * x + 0.065 * x * x)).sin() + noise[i]
                })
                .collect();
            assert!(detect(&sweep, &no_slow(n)).is_empty(), "dt {dt}");
        }
    }

    #[test]
    fn each_glitch_kind_is_found_at_its_sample() {
        let n = 2000;
        let base: Vec<f64> = (0..n)
            .map(|i| 0.2 + 0.1 * (i as f64 * 0.01).sin())
            .zip(gauss_noise(n, 0.002, 9))
            .map(|(a, b)| a + b)
            .collect();
        let mut x = base.clone();
        x[400] = 0.0;
        x[900] += 0.1;
        for v in &mut x[1300..1306] {
            *v = 0.25;
        }
        x[n - 1] = 0.0;
        let f = detect(&x, &no_slow(n));
        let got: Vec<(usize, usize, GlitchKind)> =
            f.iter().map(|f| (f.start, f.len, f.kind)).collect();
        assert_eq!(
            got,
            vec![
                (400, 1, GlitchKind::ZeroRead),
                (900, 1, GlitchKind::Spike),
                (1300, 6, GlitchKind::Stuck),
                (n - 1, 1, GlitchKind::ZeroRead),
            ]
        );
        // A hold where the car stands still is not a stuck sensor.
        let mut slow = no_slow(n);
        slow[1300..1306].iter_mut().for_each(|s| *s = true);
        assert!(detect(&x, &slow)
            .iter()
            .all(|f| f.kind != GlitchKind::Stuck));
    }

    fn run(n: usize, dt: f64, speed: impl Fn(f64) -> f64) -> MeasuredRun {
        let t: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
        let noise = gauss_noise(n, 0.002, 11);
        MeasuredRun {
            path: PathBuf::from("r.csv"),
            speed: t.iter().map(|&x| speed(x)).collect(),
            steer: t.iter().map(|&x| 0.02 * (0.5 * x).sin()).collect(),
            yaw_rate: t
                .iter()
                .zip(&noise)
                .map(|(&x, e)| 0.2 * (0.5 * x).sin() + e)
                .collect(),
            ay: None,
            beta: None,
            roll: None,
            bank: None,
            ax: None,
            masked: Vec::new(),
            t,
        }
    }

    #[test]
    fn a_standstill_splits_the_run_and_inputs_are_repaired_responses_masked() {
        // Driving to 20 s, a 10 s standstill, 0.5 s driving (too short), a
        // 1 s crawl, driving; a 1 s time gap at 40 s, driving to 53 s.
        let mut r = run(5200, 0.01, |x| {
            if (20.0..30.0).contains(&x) {
                0.0
            } else if (30.5..31.5).contains(&x) {
                2.0
            } else {
                20.0
            }
        });
        r.t.iter_mut().skip(4000).for_each(|t| *t += 1.0);
        let mid = 0.5 * (r.steer[499] + r.steer[501]);
        r.steer[500] = 0.0;
        r.yaw_rate[4500] += 0.5;
        let mut rep = CleaningReport::new(5.0);
        let pieces = clean_run(r, &CleanSettings::diagnosis(5.0), &mut rep);
        assert_eq!(pieces.len(), 3, "{:?}", rep.pieces);
        assert_eq!(rep.dropped_pieces.len(), 1, "{:?}", rep.dropped_pieces);
        assert_eq!(rep.slow.len(), 2);
        assert_eq!(rep.slow[0].kind, SlowKind::Standstill);
        assert_eq!(rep.slow[0].samples, 1000);
        assert_eq!(rep.slow[1].kind, SlowKind::Crawl);
        assert_eq!(rep.counts.time_gap, 1);
        assert_eq!(rep.counts.zero_read, 1);
        assert_eq!(rep.counts.spike, 1);
        assert_eq!(
            rep.samples_read,
            rep.samples_kept + rep.samples_slow + rep.samples_in_dropped_pieces
        );
        // The zeroed steer is interpolated, the spiked yaw rate masked.
        assert!((pieces[0].steer[500] - mid).abs() < 1e-12);
        let last = &pieces[2];
        assert_eq!(last.masked.len(), 1);
        assert!((last.t[last.masked[0]] - 46.0).abs() < 1e-9);
    }

    #[test]
    fn injected_glitches_are_found_where_they_were_put() {
        let mut r = run(3000, 0.01, |_| 20.0);
        r.ay = Some(r.yaw_rate.iter().map(|v| 20.0 * v).collect());
        let injected = inject_glitches(&mut r, 42);
        assert_eq!(injected.len(), 7);
        let mut rep = CleaningReport::new(5.0);
        let mut r2 = r.clone();
        treat_glitches(&mut r2, 5.0, &mut rep);
        for g in &injected {
            assert!(
                rep.glitches
                    .iter()
                    .any(|f| f.channel == g.channel && f.kind == g.kind && f.t == g.t),
                "{g:?} not in {:?}",
                rep.glitches
            );
        }
        assert_eq!(rep.glitches.len(), injected.len(), "{:?}", rep.glitches);
    }

    #[test]
    fn a_zero_read_of_a_sweep_is_found_below_the_spike_threshold() {
        // A frequency sweep's yaw rate moves a lot between samples, so the
        // spike threshold (10 robust spreads of the differences) exceeds
        // many of its values; an exact 0 amid unquantised samples of one
        // sign is still a zero read.
        use crate::diagnose::synth::{generate, Noise, SynthSpec};
        let s = generate(&SynthSpec {
            effects: Vec::new(),
            seed: 3,
            noise: Noise::default(),
        });
        let mut run = s
            .runs
            .iter()
            .find(|r| r.path.to_string_lossy().contains("sweep"))
            .expect("a sweep run")
            .clone();
        let sc = scale(&run.yaw_rate);
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

    #[test]
    fn glitches_injected_into_synthetic_runs_are_all_found_and_nothing_else() {
        use crate::diagnose::effects::EffectKind;
        use crate::diagnose::synth::{generate, truth_values, Noise, SynthSpec};
        for (seed, effects) in [
            (1, vec![]),
            (2, vec![EffectKind::SensorDelay]),
            (3, vec![EffectKind::RelaxationLength]),
            (
                4,
                vec![EffectKind::SensorBias, EffectKind::AccelerometerRoll],
            ),
            (5, vec![EffectKind::CorneringStiffness]),
            (6, vec![EffectKind::RoadBank]),
        ] {
            let s = generate(&SynthSpec {
                effects: effects.iter().map(|e| (*e, truth_values(*e))).collect(),
                seed,
                noise: Noise::default(),
            });
            let mut injected = Vec::new();
            let mut runs = s.runs.clone();
            for (k, r) in runs.iter_mut().enumerate() {
                injected.extend(inject_glitches(r, seed * 100 + k as u64));
            }
            let (clean, rep) = clean_runs(runs, &CleanSettings::default());
            assert_eq!(clean.len(), s.runs.len());
            let key = |g: &Glitch| {
                (
                    g.run.clone(),
                    g.channel.name(),
                    g.kind.name(),
                    g.t.to_bits(),
                )
            };
            let mut found: Vec<_> = rep.glitches.iter().map(key).collect();
            let mut want: Vec<_> = injected.iter().map(key).collect();
            found.sort();
            want.sort();
            assert_eq!(found, want, "seed {seed}");
            // Spikes and holds always find a place; zero reads need a value far
            // from 0.
            assert!(injected.len() >= 7 * s.runs.len(), "{}", injected.len());
        }
    }
}
