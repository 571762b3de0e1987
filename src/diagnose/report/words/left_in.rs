//! The runs a channel's gap stays significant in after the verdict's
//! effects ([`ChannelRunsLeft`]), in the words the terminal's before →
//! after block and the page's before-and-after section both print: a
//! heading naming the channel and how many runs, and which samples it
//! judges them on (the held-out ones, not all the samples where the gap
//! lies reads a run over), then one line per run with its noise floors
//! before → after over its held-out samples, the windows it stays above them
//! in and, where it is off before the input by a steady residual, the
//! offset of its sensor that reads so. Floors dimensionless; residuals and
//! offsets in the channel's unit (rad/s, m/s², rad).

use super::gap::NAMED_RUNS;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::left_in::{ChannelRunsLeft, RunLeft, RunOffset};
use crate::diagnose::report::outcome::SIGNIFICANT_NOISE_FLOORS;
use crate::format::{fixed, signed};

/// The heading and the runs' lines of `c`'s runs left above noise; None
/// where the verdict's effects leave none (a campaign they explain names
/// no run). Up to [`NAMED_RUNS`] + 1 runs are named in the campaign's
/// order; beyond, the [`NAMED_RUNS`] furthest off and a count of the rest,
/// every one in `diagnosis.json`.
pub fn runs_left(c: &ChannelRunsLeft) -> Option<(String, Vec<String>)> {
    if c.left.is_empty() {
        return None;
    }
    let head = format!(
        "{}: {} of {} runs still significant alone (above {SIGNIFICANT_NOISE_FLOORS} noise floors over the run's held-out samples, the ones the verdict is scored on; where the gap lies reads a run over all its samples, so its figure there can differ), which the share removed does not show:",
        c.channel.name(),
        c.left.len(),
        c.runs,
    );
    let mut named: Vec<&RunLeft> = c.left.iter().collect();
    let rest = named.len().saturating_sub(NAMED_RUNS + 1);
    if rest > 0 {
        named.sort_by(|a, b| b.floors_after.total_cmp(&a.floors_after));
        named.truncate(NAMED_RUNS);
    }
    let mut lines: Vec<String> = named.iter().map(|r| run_left(r, c.channel)).collect();
    if rest > 0 {
        let more = c.left.len() - NAMED_RUNS;
        let runs = if more == 1 { "run" } else { "runs" };
        lines.push(format!(
            "and {more} more {runs} (each in diagnosis.json, shrinkage[].left_in)"
        ));
    }
    Some((head, lines))
}

/// One run left: `a.csv: 3.4 → 3.4 noise floors over its 151 held-out
/// samples; above them in: before the input, later; …` and its offset
/// where it has one.
fn run_left(r: &RunLeft, channel: Channel) -> String {
    let parts = if r.parts.is_empty() {
        "in no window alone (spread over the run)".to_string()
    } else {
        let p: Vec<String> = r.parts.iter().map(|p| p.label()).collect();
        format!("above them in: {}", p.join(", "))
    };
    let offset = r
        .steady_offset
        .map_or(String::new(), |o| steady_offset(&o, channel));
    format!(
        "{}: {} → {} noise floors over its {} held-out samples; {parts}{offset}",
        r.run,
        fixed(r.floors_before, 1),
        fixed(r.floors_after, 1),
        r.samples
    )
}

/// A run's steady residual `o` (off before the input, one value through
/// the run), read as its sensor's zero offset: the gap's words for a
/// steady offset (a sensor's offset reads as a residual of the opposite
/// sign).
fn steady_offset(o: &RunOffset, channel: Channel) -> String {
    let unit = channel.unit();
    format!(
        "; off before the input too, where the response has not begun, and steady over the run: mean residual {} {unit} ({} noise floors, {:.0} % of its mean square), which reads as a zero offset of that run's {} sensor of {} {unit} (a sensor's offset reads as a residual of the opposite sign), the run's own, which the verdict's effects, fitted to every run, do not take up",
        signed(o.mean_residual, 4),
        fixed(o.floors, 1),
        100.0 * o.share,
        channel.name(),
        signed(-o.mean_residual, 4),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::report::parts::{Part, Window};

    fn left(run: &str, after: f64, offset: Option<f64>) -> RunLeft {
        RunLeft {
            run: run.into(),
            samples: 151,
            floors_before: 3.35,
            floors_after: after,
            parts: vec![
                Part::Window(Window::BeforeInput),
                Part::Window(Window::Later),
            ],
            steady_offset: offset.map(|m| RunOffset {
                mean_residual: m,
                floors: m.abs() / 0.003,
                share: 0.94,
            }),
        }
    }

    /// One run with a steady residual of −0.0093 rad/s (floor 0.003: 3.1
    /// floors) reads as a +0.0093 rad/s offset of its gyro; six runs are named by the three furthest off and a count.
    #[test]
    fn a_run_left_is_named_with_its_floors_windows_and_offset() {
        let one = ChannelRunsLeft {
            channel: Channel::YawRate,
            unit: "rad/s",
            runs: 8,
            left: vec![left("runs/b.csv", 3.4, Some(-0.0093))],
        };
        let (head, lines) = runs_left(&one).unwrap();
        assert_eq!(head, "yaw_rate: 1 of 8 runs still significant alone (above 3 noise floors over the run's held-out samples, the ones the verdict is scored on; where the gap lies reads a run over all its samples, so its figure there can differ), which the share removed does not show:");
        assert_eq!(
            lines,
            ["runs/b.csv: 3.4 → 3.4 noise floors over its 151 held-out samples; above them in: before the input, later; off before the input too, where the response has not begun, and steady over the run: mean residual -0.0093 rad/s (3.1 noise floors, 94 % of its mean square), which reads as a zero offset of that run's yaw_rate sensor of +0.0093 rad/s (a sensor's offset reads as a residual of the opposite sign), the run's own, which the verdict's effects, fitted to every run, do not take up"]
        );
        let six = ChannelRunsLeft {
            left: (0..6)
                .map(|i| left(&format!("r{i}.csv"), 3.1 + i as f64 % 4.0, None))
                .collect(),
            ..one.clone()
        };
        let (head, lines) = runs_left(&six).unwrap();
        assert!(head.starts_with("yaw_rate: 6 of 8 runs still"), "{head}");
        let named: Vec<&str> = lines.iter().map(|l| l.split(':').next().unwrap()).collect();
        assert_eq!(
            named,
            [
                "r3.csv",
                "r2.csv",
                "r1.csv",
                "and 3 more runs (each in diagnosis.json, shrinkage[].left_in)"
            ]
        );
        assert!(
            lines[0].ends_with("3.4 → 6.1 noise floors over its 151 held-out samples; above them in: before the input, later")
        );
        let none = ChannelRunsLeft {
            left: Vec::new(),
            ..one
        };
        assert_eq!(runs_left(&none), None);
    }
}
