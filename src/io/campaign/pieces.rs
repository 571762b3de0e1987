//! The pieces a campaign's runs are cleaned into ([`super::runs`]): cut
//! into segments of `[runs] segment` s, what cleaning left of each run to
//! replay (time gaps, pieces) said in a note, and each raw run's top
//! speed. Units: s, m/s.

use crate::measured::clean::{segments, CleaningReport, GlitchKind, Piece};
use crate::measured::MeasuredRun;

/// The pieces cut into segments so far: the longest (s, said when none
/// was cut) and whether any was.
#[derive(Default)]
pub(super) struct Cutting {
    pub(super) longest: f64,
    pub(super) was_cut: bool,
}

impl Cutting {
    /// `piece` cut into segments of `seg` s, appended to `runs`, the kept
    /// ones listed in `cleaning`'s pieces.
    pub(super) fn cut(
        &mut self,
        piece: MeasuredRun,
        seg: f64,
        cleaning: &mut CleaningReport,
        runs: &mut Vec<MeasuredRun>,
    ) {
        self.longest = self.longest.max(piece.t[piece.t.len() - 1] - piece.t[0]);
        let cut = segments(piece, seg);
        self.was_cut |= cut.len() > 1;
        cleaning.pieces.extend(cut.iter().filter_map(Piece::kept));
        runs.extend(cut);
    }
}

/// The note on what cleaning run `name` left to replay (`cleaning`'s
/// glitches from `listed` and pieces from `kept` on are the run's): none,
/// or its time gaps and pieces where it is not one piece whole.
pub(super) fn pieces_note(
    name: &str,
    cleaning: &CleaningReport,
    (listed, kept): (usize, usize),
    min_speed: f64,
) -> Option<String> {
    let gaps: Vec<String> = cleaning.glitches[listed..]
        .iter()
        .filter(|g| g.kind == GlitchKind::TimeGap)
        .map(|g| format!("{:.3}–{:.3} s", g.t, g.t + g.value))
        .collect();
    let pieces = cleaning.pieces.len() - kept;
    if pieces == 0 {
        return Some(format!(
            "{name}: nothing left to replay (every sample below min_speed = {min_speed} m/s, or in pieces too short)"
        ));
    }
    if gaps.is_empty() && pieces == 1 {
        return None;
    }
    let gaps = if gaps.is_empty() {
        String::new()
    } else {
        format!("time gaps at {}; ", gaps.join(", "))
    };
    Some(match pieces {
        1 => format!("{name}: {gaps}one piece left to replay"),
        k => format!("{name}: {gaps}split into {k} pieces replayed separately"),
    })
}

/// Each raw run's file and top speed, m/s.
pub(super) fn top_speeds(raw: &[MeasuredRun]) -> Vec<(String, f64)> {
    raw.iter()
        .map(|r| {
            let top = r.speed.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (r.path.display().to_string(), top)
        })
        .collect()
}

/// The note of a `segment` (s) that cut no piece, the `longest` lasting
/// less than one and a half segments: asked for and silently without
/// effect, a segment of 1e9 s read as if it had cut the logs.
pub(super) fn uncut_note(segment: f64, longest: f64) -> String {
    format!(
        "segment = {} s under [runs] cut nothing: the longest piece lasts {} s, less than one and a half segments, so every piece is replayed whole",
        crate::error::Num(segment),
        crate::format::fixed(longest, 1)
    )
}
