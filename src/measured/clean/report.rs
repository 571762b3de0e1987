//! What the cleaning of measured runs reports: the channels, the kinds of
//! glitch and what was done about each, the slow spans and the pieces kept
//! or dropped, with their counts and a terminal summary (every item also in
//! the JSON report). Times in s, speeds in m/s, values in the channel's SI
//! unit.

use super::slow::{slow_line, slows_line};
pub use super::slow::{SlowKind, SlowSpan};
use crate::error::PieceRefusal;
use crate::format::plural;
use crate::measured::MeasuredRun;
use serde::Serialize;

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
    pub(crate) fn is_input(self) -> bool {
        matches!(self, RunChannel::Speed | RunChannel::Steer)
    }
    pub(super) fn of(self, run: &MeasuredRun) -> Option<&Vec<f64>> {
        match self {
            RunChannel::T => Some(&run.t),
            RunChannel::Speed => Some(&run.speed),
            RunChannel::Steer => Some(&run.steer),
            RunChannel::YawRate => Some(&run.yaw_rate),
            RunChannel::Ay => run.ay.as_ref(),
            RunChannel::Beta => run.beta.as_ref(),
        }
    }
    pub(super) fn of_mut(self, run: &mut MeasuredRun) -> Option<&mut Vec<f64>> {
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

/// A value for the terminal: six significant digits, no float noise.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    // Far from unity a rounded f64 prints with hundreds of digits (a cell
    // of 1e300 read as 1000000000000000600000…): an exponent there.
    if !(1e-4..1e6).contains(&v.abs()) {
        return crate::format::readable(v, 6);
    }
    let scale = 10f64.powi(5 - v.abs().log10().floor() as i32);
    format!("{}", (v * scale).round() / scale)
}

/// What was done with a glitch, as the terminal says it: its treatment,
/// and the piece it went with where that piece was dropped.
fn treated(g: &Glitch) -> String {
    match &g.dropped_with {
        Some(piece) => format!(
            "{}, then dropped with its piece {piece}",
            g.treatment.name()
        ),
        None => g.treatment.name().to_string(),
    }
}

/// A glitch as the terminal says it. A time gap's value is its length,
/// said as one with its ends ("t 86.04" read as a time stamp).
fn glitch_line(g: &Glitch) -> String {
    if g.kind == GlitchKind::TimeGap {
        return format!(
            "{} in {}: no samples for {} s (t {:.3} → {:.3} s), {}",
            g.kind.name(),
            g.run,
            short(g.value),
            g.t,
            g.t + g.value,
            treated(g)
        );
    }
    format!(
        "{} at {:.3} s in {}: {} {} ({}, {})",
        g.kind.name(),
        g.t,
        g.run,
        g.channel.name(),
        short(g.value),
        plural(g.samples, "sample", "samples"),
        treated(g)
    )
}

/// The most alike items in a row said one by one: from this many on they
/// are said in one line, with their count and first and last times.
const SAID_ONE_BY_ONE: usize = 2;

/// The lines of `items`, each with the count of items it says: a row of
/// more than [`SAID_ONE_BY_ONE`] items alike by `key` in one line (`many`),
/// the others one by one (`one`).
fn said_in_rows<T, K: PartialEq>(
    items: &[T],
    key: impl Fn(&T) -> K,
    one: impl Fn(&T) -> String,
    many: impl Fn(&[T]) -> String,
) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..=items.len() {
        if i < items.len() && key(&items[i]) == key(&items[start]) {
            continue;
        }
        let row = &items[start..i];
        match row.len() > SAID_ONE_BY_ONE {
            true => out.push((many(row), row.len())),
            false => out.extend(row.iter().map(|g| (one(g), 1))),
        }
        start = i;
    }
    out
}

/// Alike glitches in a row (one run, kind, channel and treatment) in one
/// line: their count, the first and the last.
fn glitches_line(row: &[Glitch]) -> String {
    let (g, last) = (&row[0], &row[row.len() - 1]);
    if g.kind == GlitchKind::TimeGap {
        let (lo, hi) = row.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), g| {
            (lo.min(g.value), hi.max(g.value))
        });
        let (lo, hi) = (short(lo), short(hi));
        let length = match hi == lo {
            true => lo,
            false => format!("{lo}–{hi}"),
        };
        return format!(
            "{} in {}: {} time gaps of {} s, the first t {:.3} → {:.3} s, the last t {:.3} → {:.3} s (every one in the JSON report), {}",
            g.kind.name(),
            g.run,
            row.len(),
            length,
            g.t,
            g.t + g.value,
            last.t,
            last.t + last.value,
            treated(g)
        );
    }
    let samples: usize = row.iter().map(|g| g.samples).sum();
    format!(
        "{} in {}: {} {} times, the first at {:.3} s ({}), the last at {:.3} s ({}) ({}, {})",
        g.kind.name(),
        g.run,
        g.channel.name(),
        row.len(),
        g.t,
        short(g.value),
        last.t,
        short(last.value),
        plural(samples, "sample", "samples"),
        treated(g)
    )
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

impl Treatment {
    /// What a glitch left in `channel` gets: an input is repaired (the
    /// model needs it at every step), a response masked.
    pub(crate) fn of(channel: RunChannel) -> Self {
        if channel.is_input() {
            Self::Repaired
        } else {
            Self::Masked
        }
    }
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
    /// The piece it was in, where that piece was dropped after the glitch
    /// was treated (too short, another piece used): its treatment then
    /// reached no fit or score.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dropped_with: Option<String>,
}

/// A channel logged slower than its run and held between updates,
/// interpolated between them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HeldChannel {
    /// The run.
    pub run: String,
    /// The channel.
    pub channel: RunChannel,
    /// Samples per update, the nearest whole number.
    pub every: usize,
    /// Samples per update (the mean update period in median intervals:
    /// 2.5 for a 20 Hz update in a 50 Hz log, held for 2 samples and 3).
    pub samples_per_update: f64,
    /// Updates per second, Hz.
    pub update_rate: f64,
    /// Samples per second of the log it is held in, Hz (at its median
    /// interval).
    pub log_rate: f64,
    /// The log's rate changes within the run: the hold is a different
    /// count of samples in each stretch, and `every` is the mean update
    /// period in median intervals.
    pub log_rate_changes: bool,
    /// Held samples interpolated.
    pub samples: usize,
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
    /// Why a dropped piece was dropped (`None` for a kept one; the report
    /// writes the sentence, empty for a kept one).
    #[serde(serialize_with = "reason_text")]
    pub reason: Option<PieceRefusal>,
}

/// A piece's reason as the report writes it: its sentence, or nothing.
fn reason_text<S: serde::Serializer>(r: &Option<PieceRefusal>, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&r.as_ref().map_or(String::new(), |r| r.to_string()))
}

impl Piece {
    /// The entry of a replayed piece `run` (none without samples).
    pub fn kept(run: &MeasuredRun) -> Option<Piece> {
        Some(Piece {
            name: run.path.display().to_string(),
            t_start: *run.t.first()?,
            t_end: *run.t.last()?,
            samples: run.t.len(),
            reason: None,
        })
    }
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
    /// Held samples of slower channels interpolated between their updates.
    pub samples_interpolated: usize,
    /// Channels logged slower than their run and held.
    pub held: Vec<HeldChannel>,
    /// Glitches per kind.
    pub counts: GlitchCounts,
    /// Rows missing in holes shorter than a time gap, per run that has any.
    pub missing_rows: Vec<super::missing::MissingRows>,
    /// What reads the runs across those holes (said in their line).
    #[serde(skip)]
    pub read_across: super::missing::ReadAcross,
    /// Runs whose wall clock was rebased to their first sample.
    pub clocks: Vec<crate::measured::clock::RebasedClock>,
    /// Every glitch, in run and time order.
    pub glitches: Vec<Glitch>,
    /// Spans excluded for low speed.
    pub slow: Vec<SlowSpan>,
    /// Pieces replayed.
    pub pieces: Vec<Piece>,
    /// Pieces dropped (too short, another used, later steps), each with
    /// its reason.
    pub dropped_pieces: Vec<Piece>,
}

impl CleaningReport {
    /// Lists `piece` of the file `file` as dropped, and marks the glitches
    /// treated in it (every one of the file within its span but a time
    /// gap, which is where pieces part) as dropped with it: a glitch is
    /// counted once, said with what became of it.
    pub(super) fn drop_piece(&mut self, file: &str, piece: Piece) {
        for g in &mut self.glitches {
            let inside = g.t >= piece.t_start && g.t <= piece.t_end;
            if g.run == file && inside && g.kind != GlitchKind::TimeGap && g.dropped_with.is_none()
            {
                g.dropped_with = Some(piece.name.clone());
            }
        }
        self.samples_in_dropped_pieces += piece.samples;
        self.dropped_pieces.push(piece);
    }

    /// Lists `part`, a part of the run read but not cleaned nor used, as a
    /// dropped piece for `reason`: its samples are counted as read and as
    /// dropped, so that nothing read goes unsaid.
    pub fn set_aside(&mut self, part: &MeasuredRun, reason: PieceRefusal) {
        let Some(piece) = Piece::kept(part) else {
            return;
        };
        self.samples_read += piece.samples;
        self.samples_in_dropped_pieces += piece.samples;
        self.dropped_pieces.push(Piece {
            reason: Some(reason),
            ..piece
        });
    }

    /// An empty report for runs cleaned at `min_speed`.
    pub fn new(min_speed: f64) -> Self {
        Self {
            min_speed,
            ..Self::default()
        }
    }

    pub(super) fn push_glitch(&mut self, g: Glitch) {
        match g.kind {
            GlitchKind::ZeroRead => self.counts.zero_read += 1,
            GlitchKind::Spike => self.counts.spike += 1,
            GlitchKind::Stuck => self.counts.stuck += 1,
            GlitchKind::TimeGap => self.counts.time_gap += 1,
        }
        self.glitches.push(g);
    }

    /// The first line of [`Self::summary`]: every count, each noun in the
    /// number its count takes ("1 spike", "2 spikes").
    fn counts_line(&self) -> String {
        let c = &self.counts;
        let spans = |kind: SlowKind| self.slow.iter().filter(|s| s.kind == kind).count();
        let standstills = plural(
            spans(SlowKind::Standstill),
            "standstill span",
            "standstill spans",
        );
        let crawls = plural(spans(SlowKind::Crawl), "crawl span", "crawl spans");
        // Reversing is rare: said where it was found, so that the common
        // line reads as it did.
        let slow_spans = match spans(SlowKind::Reversing) {
            0 => format!("{standstills} and {crawls}"),
            r => format!(
                "{standstills}, {crawls} and {}",
                plural(r, "reversing span", "reversing spans")
            ),
        };
        // Rows dropped shorter than a gap split nothing: said beside the
        // gaps where a run has any, so that "0 time gaps" is not all.
        let holes: usize = self.missing_rows.iter().map(|m| m.holes).sum();
        let missing = match holes {
            0 => String::new(),
            h => format!(
                " and {} shorter than a gap ({} missing)",
                plural(h, "hole", "holes"),
                plural(
                    self.missing_rows.iter().map(|m| m.samples).sum(),
                    "row",
                    "rows"
                )
            ),
        };
        format!(
            "{} read, {} kept; {} below {} m/s excluded ({}), {} in {} dropped; glitches: {}, {}, {}, {}{missing} ({} repaired, {} masked)",
            plural(self.samples_read, "sample", "samples"),
            self.samples_kept,
            self.samples_slow,
            self.min_speed,
            slow_spans,
            self.samples_in_dropped_pieces,
            plural(self.dropped_pieces.len(), "piece", "pieces"),
            plural(c.zero_read, "zero read", "zero reads"),
            plural(c.spike, "spike", "spikes"),
            plural(c.stuck, "stuck value", "stuck values"),
            plural(c.time_gap, "time gap", "time gaps"),
            plural(self.samples_repaired, "input sample", "input samples"),
            plural(self.samples_masked, "response sample", "response samples"),
        )
    }

    /// The report in a few lines for the terminal: counts per kind, the
    /// first few glitches, the slow spans and the pieces.
    pub fn summary(&self, first: usize) -> Vec<String> {
        let mut out = vec![self.counts_line()];
        out.extend(crate::measured::clock::RebasedClock::line(&self.clocks));
        out.extend(self.missing_rows.iter().map(|m| m.line(self.read_across)));
        for h in &self.held {
            if h.log_rate_changes {
                out.push(format!(
                    "held: {} in {} updates every {} s ({} Hz) in a log whose rate changes ({} Hz at its median interval): {} interpolated between its updates",
                    h.channel.name(),
                    h.run,
                    crate::format::rounded(1.0 / h.update_rate, 2),
                    crate::format::rounded(h.update_rate, 3),
                    crate::format::rounded(h.log_rate, 3),
                    plural(h.samples, "held sample", "held samples")
                ));
                continue;
            }
            // The hold in samples alone reads as a rate of its own ("every
            // 2 samples (431.8 Hz)"): said against the log's rate, in time.
            out.push(format!(
                "held: {} in {} updates every {} samples of the {} Hz log (every {} s, {} Hz): {} interpolated between its updates",
                h.channel.name(),
                h.run,
                crate::format::rounded(h.samples_per_update, 3),
                crate::format::rounded(h.log_rate, 3),
                crate::format::rounded(1.0 / h.update_rate, 2),
                crate::format::rounded(h.update_rate, 3),
                plural(h.samples, "held sample", "held samples")
            ));
        }
        // Alike glitches in a row (a 10 Hz standstill logged before 100 Hz
        // driving: a time gap at every sample) are said in one line each.
        let key = |g: &Glitch| {
            let dropped = g.dropped_with.clone();
            (g.run.clone(), g.kind, g.channel, g.treatment, dropped)
        };
        let glitches = said_in_rows(&self.glitches, key, glitch_line, glitches_line);
        out.extend(glitches.iter().take(first).map(|(l, _)| l.clone()));
        let more: usize = glitches.iter().skip(first).map(|(_, n)| n).sum();
        if more > 0 {
            out.push(format!(
                "… and {} more (every one in the JSON report)",
                plural(more, "glitch", "glitches")
            ));
        }
        let slow_line = |s: &SlowSpan| slow_line(s, self.min_speed);
        let slows_line = |r: &[SlowSpan]| slows_line(r, self.min_speed);
        let key = |s: &SlowSpan| (s.run.clone(), s.kind);
        let slow = said_in_rows(&self.slow, key, slow_line, slows_line);
        out.extend(slow.iter().take(first).map(|(l, _)| l.clone()));
        let more: usize = slow.iter().skip(first).map(|(_, n)| n).sum();
        if more > 0 {
            out.push(format!(
                "… and {} more",
                plural(more, "slow span", "slow spans")
            ));
        }
        for p in self.dropped_pieces.iter().take(first) {
            out.push(format!(
                "piece {} ({:.2}–{:.2} s, {}) dropped: {}",
                p.name,
                p.t_start,
                p.t_end,
                plural(p.samples, "sample", "samples"),
                p.reason.as_ref().map_or(String::new(), |r| r.to_string())
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn a_glitchs_value_is_said_in_six_digits_and_never_in_hundreds() {
        assert_eq!(short(-0.034872), "-0.034872");
        assert_eq!(short(2.0 / 3.0), "0.666667");
        assert_eq!(short(1e300), "1e300");
        assert_eq!(short(-1.23456789e-300), "-1.23457e-300");
        assert_eq!(short(0.0), "0");
    }
}
