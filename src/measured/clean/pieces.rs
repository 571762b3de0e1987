//! The pieces of a measured run: split at time gaps, glitches treated, the
//! slow spans (standstill, crawl) excluded and the moving pieces long
//! enough kept, each step listed in the [`CleaningReport`]; and the cleaning
//! entry points for a diagnosis, a single replay and the metrics. Times in
//! s, speeds in m/s.

use super::cut_by_gap::{gap_after, too_short};
use super::glitches::treat_glitches;
use super::held::treat_held;
use super::repair::repair;
use super::report::{
    CleaningReport, Glitch, GlitchKind, Piece, RunChannel, SlowKind, SlowSpan, Treatment,
};
use super::{CleanSettings, STANDSTILL_SPEED};
use crate::error::PieceRefusal;
use crate::measured::MeasuredRun;
use std::path::{Path, PathBuf};

/// Cuts a run into pieces of `length` seconds, labelled `[1]`, `[2]`, …
/// (a campaign's `[runs] segment`): the last one joins its predecessor
/// when shorter than a run must be ([`super::MIN_RUN_SECONDS`]).
pub fn segments(run: MeasuredRun, length: f64) -> Vec<MeasuredRun> {
    let t0 = run.t[0];
    let total = run.t[run.t.len() - 1] - t0;
    let mut count = ((total / length).round() as usize).max(1);
    if count > 1 && total - (count - 1) as f64 * length < super::MIN_RUN_SECONDS {
        count -= 1;
    }
    let mut out = Vec::new();
    let mut lo = 0;
    for k in 0..count {
        let end = if k + 1 == count {
            run.t.len()
        } else {
            run.t.partition_point(|&x| x < t0 + (k + 1) as f64 * length)
        };
        if end > lo + 1 {
            out.push(slice(&run, lo, end, &format!("[{}]", k + 1)));
        }
        lo = end;
    }
    out
}

/// The file a run was read from: its path without the labels cleaning
/// appends to a piece (`#2`, a stretch between gaps or standstills) and to
/// a segment of a long piece (`[3]`), in any number: `run.csv#2[3]` is of
/// `run.csv`. A file's own name ending in such a label would lose it too;
/// the labels are only ever compared between runs of one campaign.
pub fn source_file(path: &std::path::Path) -> String {
    let mut name = path.display().to_string();
    loop {
        let cut = if let Some(head) = name.strip_suffix(']') {
            head.rfind('[').filter(|&i| {
                i + 1 < head.len() && head[i + 1..].bytes().all(|b| b.is_ascii_digit())
            })
        } else {
            name.rfind('#').filter(|&i| {
                i + 1 < name.len() && name[i + 1..].bytes().all(|b| b.is_ascii_digit())
            })
        };
        match cut {
            Some(i) => name.truncate(i),
            None => return name,
        }
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
        // The mask is ascending: found by bisection, so that cutting a run
        // into many pieces costs pieces · log(masked), not pieces · masked.
        masked: {
            let from = run.masked.partition_point(|&i| i < lo);
            let to = run.masked.partition_point(|&i| i < hi);
            run.masked[from..to.max(from)]
                .iter()
                .map(|&i| i - lo)
                .collect()
        },
        clock: run.clock,
    }
}

/// The index ranges `[lo, hi)` between time gaps of a run
/// ([`super::gaps`]), listing the gaps.
fn split_times(run: &MeasuredRun, report: &mut CleaningReport) -> Vec<(usize, usize)> {
    let pieces = super::gapless(&run.t);
    for &(_, i) in &pieces[..pieces.len() - 1] {
        report.push_glitch(Glitch {
            run: run.path.display().to_string(),
            t: run.t[i - 1],
            channel: RunChannel::T,
            kind: GlitchKind::TimeGap,
            value: run.t[i] - run.t[i - 1],
            samples: 0,
            treatment: Treatment::Split,
            dropped_with: None,
        });
    }
    pieces
}

/// The longest run of samples above the slow threshold, inside a slow
/// span, that joins the span: a speed flickering across the threshold at
/// a standstill or crawl (a wheel-speed sensor's noise, a GPS speed's
/// jitter) would otherwise cut the span into many, each with a moving
/// "piece" of a sample or two between them.
pub const FLICKER_SAMPLES: usize = 2;

/// Which samples are slow: below `min_speed`, and the runs of at most
/// [`FLICKER_SAMPLES`] samples at or above it that lie between slow ones.
fn slow_samples(speed: &[f64], min_speed: f64) -> Vec<bool> {
    let mut slow: Vec<bool> = speed.iter().map(|&u| u < min_speed).collect();
    let mut i = 0;
    while i < slow.len() {
        if slow[i] {
            i += 1;
            continue;
        }
        let j = (i..slow.len()).find(|&k| slow[k]).unwrap_or(slow.len());
        // Between two slow samples (not at the part's ends) and short.
        if i > 0 && j < slow.len() && j - i <= FLICKER_SAMPLES {
            slow[i..j].iter_mut().for_each(|s| *s = true);
        }
        i = j;
    }
    slow
}

/// What a slow span is: reversing where the car moves backwards (below
/// −[`STANDSTILL_SPEED`]) over more than half its samples, else a
/// standstill where it stood (`stopped` samples) over at least half, else
/// a crawl (a climb from rest through the crawl speeds among them).
fn slow_kind(speed: &[f64], stopped: usize) -> SlowKind {
    let backwards = speed.iter().filter(|&&u| u < -STANDSTILL_SPEED).count();
    if 2 * backwards > speed.len() {
        SlowKind::Reversing
    } else if 2 * stopped >= speed.len() {
        SlowKind::Standstill
    } else {
        SlowKind::Crawl
    }
}

fn long_enough(run: &MeasuredRun, s: &CleanSettings) -> bool {
    let n = run.t.len();
    n >= s.min_piece_samples.max(2) && run.t[n - 1] - run.t[0] >= s.min_piece_seconds
}

fn piece_of(run: &MeasuredRun, reason: Option<PieceRefusal>) -> Piece {
    Piece::kept(run)
        .map(|p| Piece { reason, ..p })
        .expect("a piece has samples")
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
    let file = source_file(&run.path);
    crate::measured::clock::RebasedClock::note(&mut report.clocks, file, run.clock);
    let parts = split_times(&run, report);
    let mut moving: Vec<MeasuredRun> = Vec::new();
    let name = run.path.display().to_string();
    report
        .missing_rows
        .extend(super::holes::missing_rows(&name, &run.t, &parts));
    // The gap after each moving piece that ends where its part does.
    let mut gaps = Vec::new();
    let dt = super::median_interval(&run.t);
    for (lo, hi) in parts {
        let mut part = slice(&run, lo, hi, "");
        treat_held(&mut part, settings.min_speed, report);
        treat_glitches(&mut part, settings.min_speed, report);
        let n = part.t.len();
        let slow_at = slow_samples(&part.speed, settings.min_speed);
        let mut i = 0;
        while i < n {
            let slow = slow_at[i];
            let mut j = i;
            while j < n && slow_at[j] == slow {
                j += 1;
            }
            if slow {
                let max_speed = part.speed[i..j].iter().copied().fold(f64::MIN, f64::max);
                let min_speed = part.speed[i..j].iter().copied().fold(f64::MAX, f64::min);
                // Stopped for at least half the span: a climb from rest
                // through the crawl speeds is a crawl, not a standstill.
                let stopped = part.speed[i..j]
                    .iter()
                    .filter(|u| u.abs() < STANDSTILL_SPEED)
                    .count();
                report.samples_slow += j - i;
                report.slow.push(SlowSpan {
                    run: name.clone(),
                    t_start: part.t[i],
                    t_end: part.t[j - 1],
                    samples: j - i,
                    max_speed,
                    min_speed,
                    kind: slow_kind(&part.speed[i..j], stopped),
                });
            } else {
                moving.push(slice(&part, i, j, ""));
                gaps.push((j == n).then(|| gap_after(&run.t, hi, dt)).flatten());
            }
            i = j;
        }
    }
    let whole = moving.len() == 1 && moving[0].t.len() == run.t.len();
    let mut out = Vec::new();
    for (k, (mut piece, gap)) in moving.into_iter().zip(gaps).enumerate() {
        if !whole {
            piece.path = PathBuf::from(format!("{name}#{}", k + 1));
        }
        if long_enough(&piece, settings) {
            report.samples_kept += piece.t.len();
            report.samples_masked += piece.masked.len();
            report.pieces.push(piece_of(&piece, None));
            out.push(piece);
        } else {
            let why = too_short(&piece, settings.min_piece_seconds, gap);
            report.drop_piece(&name, piece_of(&piece, Some(why)));
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
    mut fits: impl FnMut(&MeasuredRun) -> Result<T, PieceRefusal>,
) -> Option<(MeasuredRun, T)> {
    clean_single_reported(run, settings, report, |p, _| fits(p))
}

/// [`clean_single_with`] whose `fits` also reads the cleaning found so far
/// (the glitches of the run, to fill each channel at its own:
/// [`fill_masked_by_channel`]).
pub fn clean_single_reported<T>(
    run: MeasuredRun,
    settings: &CleanSettings,
    report: &mut CleaningReport,
    mut fits: impl FnMut(&MeasuredRun, &CleaningReport) -> Result<T, PieceRefusal>,
) -> Option<(MeasuredRun, T)> {
    let first = report.pieces.len();
    let file = run.path.display().to_string();
    let pieces = clean_run(run, settings, report);
    report.pieces.truncate(first);
    let mut order: Vec<usize> = (0..pieces.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(pieces[k].t.len()));
    let mut reasons: Vec<Option<PieceRefusal>> = vec![None; pieces.len()];
    let mut chosen = None;
    for &k in &order {
        match fits(&pieces[k], report) {
            Ok(v) => {
                chosen = Some((k, v));
                break;
            }
            Err(e) => reasons[k] = Some(e),
        }
    }
    for (k, p) in pieces.iter().enumerate() {
        if chosen.as_ref().is_some_and(|c| c.0 == k) {
            report.pieces.push(piece_of(p, None));
            continue;
        }
        let reason = reasons[k].take().unwrap_or(PieceRefusal::AnotherPieceUsed);
        report.samples_kept -= p.t.len();
        report.samples_masked -= p.masked.len();
        report.drop_piece(&file, piece_of(p, Some(reason)));
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
    let piece =
        clean_single(run, &CleanSettings::single(min_speed), &mut report).ok_or_else(|| {
            crate::error::InputError::problem(
                &path,
                crate::error::InputProblem::NoMovingSamples {
                    min_speed,
                    slow: report.samples_slow,
                    read: report.samples_read,
                },
            )
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

/// The run with each response channel interpolated across its own masked
/// glitches (listed in `glitches`), the mask cleared: a spike of `beta`
/// leaves the yaw rate and `ay` of its sample as measured (filled in
/// every channel, the yaw rate of a 10 Hz step read its sample at 1.1 s
/// from its neighbours where only `beta` had a spike). A masked sample
/// no listed glitch of this piece accounts for (one that began before
/// the piece) is filled in every channel, as [`fill_masked`] does.
pub fn fill_masked_by_channel(run: &MeasuredRun, glitches: &[Glitch]) -> MeasuredRun {
    const RESPONSES: [RunChannel; 3] = [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta];
    let n = run.t.len();
    let file = source_file(&run.path);
    let mut bad = vec![vec![false; n]; RESPONSES.len()];
    let mut covered = vec![false; n];
    let own = glitches
        .iter()
        .filter(|g| g.treatment == Treatment::Masked && source_file(Path::new(&g.run)) == file);
    for g in own {
        let Some(c) = RESPONSES.iter().position(|&c| c == g.channel) else {
            continue;
        };
        let i = run.t.partition_point(|&t| t < g.t);
        if i == n || run.t[i] != g.t {
            continue;
        }
        for k in i..(i + g.samples).min(n) {
            bad[c][k] = true;
            covered[k] = true;
        }
    }
    for &i in run.masked.iter().filter(|&&i| !covered[i]) {
        bad.iter_mut().for_each(|b| b[i] = true);
    }
    let mut out = run.clone();
    for (c, ch) in RESPONSES.iter().enumerate() {
        if let Some(x) = ch.of_mut(&mut out) {
            repair(&run.t, x, &bad[c]);
        }
    }
    out.masked.clear();
    out
}

#[cfg(test)]
mod tests {
    use super::super::test_signals::run;
    use super::*;

    #[test]
    fn a_piece_and_its_segments_name_the_file_they_were_cut_from() {
        let file = |p: &str| source_file(std::path::Path::new(p));
        assert_eq!(file("logs/run.csv"), "logs/run.csv");
        assert_eq!(file("logs/run.csv#2"), "logs/run.csv");
        assert_eq!(file("logs/run.csv[22]"), "logs/run.csv");
        assert_eq!(file("logs/run.csv#2[3]"), "logs/run.csv");
        // Not a label: a bracket or hash without a number after it.
        assert_eq!(file("logs/run[a].csv"), "logs/run[a].csv");
        assert_eq!(file("logs/run#"), "logs/run#");
        assert_eq!(file("logs/run[]"), "logs/run[]");
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
        // Said as a gap with its ends, not as a time stamp of its length.
        let said = rep.summary(5).join("\n");
        let gap = rep
            .glitches
            .iter()
            .find(|g| g.kind == GlitchKind::TimeGap)
            .unwrap();
        let line = format!(
            "time_gap in {}: no samples for 1.01 s (t {:.3} → {:.3} s), split",
            gap.run,
            gap.t,
            gap.t + 1.01
        );
        assert!(said.contains(&line), "{said}");
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
    fn a_speed_flickering_across_the_threshold_joins_the_standstill() {
        // Driving to 20 s, a 10 s standstill at 4.9 m/s whose speed pokes
        // above 5 m/s for one sample in fifty and for two in a hundred,
        // then driving: one slow span, the flicker in it.
        let mut r = run(4000, 0.01, |x| {
            if (20.0..30.0).contains(&x) {
                4.9
            } else {
                20.0
            }
        });
        for k in (2050..2950).step_by(50) {
            r.speed[k] = 5.1;
        }
        for k in (2075..2950).step_by(100) {
            r.speed[k] = 5.2;
            r.speed[k + 1] = 5.2;
        }
        let mut rep = CleaningReport::new(5.0);
        let pieces = clean_run(r.clone(), &CleanSettings::diagnosis(5.0), &mut rep);
        assert_eq!(rep.slow.len(), 1, "{:?}", rep.slow);
        assert_eq!(rep.slow[0].samples, 1000);
        assert!(rep.dropped_pieces.is_empty(), "{:?}", rep.dropped_pieces);
        assert_eq!(pieces.len(), 2);
        // Three samples above it are motion: the span splits there.
        r.speed[2500..2503].iter_mut().for_each(|u| *u = 5.2);
        let mut rep = CleaningReport::new(5.0);
        clean_run(r, &CleanSettings::diagnosis(5.0), &mut rep);
        assert_eq!(rep.slow.len(), 2, "{:?}", rep.slow);
        assert_eq!(rep.dropped_pieces.len(), 1);
    }
}
