//! The terminal's lines of a swarm fit of `identify`: the data and their
//! levels, the holds, each channel's σ and curves, and the warnings on
//! its parameters.

use super::holds::{held_lines, Held};
use super::notes::{held_as_given, later_fit_notes, undetermined_note, unfitted_notes};
use super::{Polish, SwarmReport, TwoStageReport, Written};
use crate::format::{decimals_or_digits, distinct};
use crate::identify::{Fit, HeldFor};
use crate::tyre::Identification;

impl SwarmReport {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let mut out = self.data_lines();
        // Each channel's held lines sit with its block: the lateral
        // force's (and every --hold) here, before its σ table.
        out.extend(held_lines(&self.held_in(Block::First)));
        out.extend(self.two_stage_lines());
        out.extend(self.first_fit_lines());
        out.extend(self.written_line());
        out.extend(super::local_scope::local_note(self).map(|n| format!("  {n}")));
        out.extend(
            super::notes::sigma_notes(&self.fit, &self.level_names())
                .iter()
                .map(|n| n.line(" ")),
        );
        out.extend(
            super::offset::offset_note(&self.fit, &self.conditions, &self.level_names())
                .map(|n| n.line(" ")),
        );
        out.extend(self.later_fit_lines());
        out.extend(unfitted_notes(self).iter().map(|n| n.line(" ")));
        out.extend(
            self.curvature_held
                .as_ref()
                .map(|x| format!("  {}", x.line())),
        );
        out.extend(
            self.pac89_reversal
                .map(|x| format!("  warning: {}", x.line())),
        );
        out
    }

    /// The data's line (conditions, model, seed), then what was left out
    /// (a lifted wheel's, a standstill's samples) and the grouping's
    /// levels.
    fn data_lines(&self) -> Vec<String> {
        let o = &self.options;
        let mut out = vec![format!(
            "{}: {}; model {}, seed {}",
            o.data.display(),
            crate::jobs::shard::plural(self.conditions.len(), "condition", "conditions"),
            o.model,
            o.seed
        )];
        out.extend(self.lifted.map(|l| format!("  {}", l.line())));
        out.extend(self.at_rest.iter().map(|l| format!("  {l}")));
        out.extend(self.grouping.lines().iter().map(|l| format!("  {l}")));
        out
    }

    /// The two-stage identification's line: why it was not run (asked
    /// for by the model, but `--hold` given), or its statistics.
    fn two_stage_lines(&self) -> Vec<String> {
        let o = &self.options;
        let mut out = Vec::new();
        let two_stage_asked = o
            .model
            .swarm_model()
            .is_some_and(|m| m.identification() == Identification::SwarmAndTwoStage);
        if self.two_stage.is_none() && two_stage_asked && !o.hold.is_empty() {
            out.push("  two-stage (Zhang et al. 2021): not run, it fits every coefficient and --hold holds some; the direct fit written".into());
        }
        if let Some(t) = &self.two_stage {
            // Two statistics: the paper's mean of the conditions' σ, and the
            // σ over all points that is compared with the direct fit's and
            // written; a lone "after the joint polish" read as the latter.
            // What each stage is and what its percentage is of, in the
            // words of the σ line: "stage 2 41.688 %" alone read as
            // nothing a tyre engineer could place.
            out.push(format!(
                "  two-stage (Zhang et al. 2021): mean of the conditions' σ: stage 1 {:.3} % (each condition's own curve, B, C, D, E, Sh, Sv fitted to it alone), stage 2 {:.3} % (a0..a13 fitted to those coefficients as laws of load and camber), after the joint polish {:.3} % (a0..a13 on all points together); σ over all points after the joint polish {:.3} % (direct fit {:.3} %); a condition's σ is its RMS error as % of its RMS measured force, the mean over the {}",
                t.stages.stage1_mean_sigma,
                t.stages.stage2_mean_sigma,
                t.stages.polished_mean_sigma,
                t.polished_overall_sigma_percent,
                t.direct_sigma_percent,
                crate::jobs::shard::plural(t.stages.stage1.len(), "condition", "conditions"),
            ));
        }
        out
    }

    /// The first fit's σ line, its σ per condition, its parameters'
    /// warnings and the linear window.
    fn first_fit_lines(&self) -> Vec<String> {
        let f = &self.fit;
        let mut out = vec![format!(
            "  {}, RMS {} N, {} evaluations, {:.2} s",
            swarm_and_polish(f, self.options.local),
            decimals_or_digits(f.rms, 1, 3),
            f.evaluations,
            f.seconds
        )];
        let names = self.level_names();
        for c in &f.curves {
            // Levels as the grouping's lines and the figure name them.
            out.push(format!(
                "    Fz {:>9}, camber {:>6}, pressure {}: {:>4} points, σ {:.3} %, RMS {} N",
                names.load(c.fz),
                names.camber(c.camber),
                c.pressure.map_or("—".into(), |p| names.pressure(p)),
                c.points,
                c.sigma_percent,
                decimals_or_digits(c.rms, 1, 3)
            ));
        }
        out.extend(super::condition_values::own_values_note(self).map(|n| format!("  {n}")));
        out.extend(parameter_warnings(f, &self.options.hold));
        if let Some(w) = &self.linear_window {
            out.extend(w.lines(" "));
        }
        out
    }

    /// Which of PAC89's fits was written and why (`Written`), or `None`.
    fn written_line(&self) -> Option<String> {
        match (self.written?, &self.two_stage, &self.curvature_held) {
            (Written::TwoStage, Some(t), _) => Some(self.two_stage_written(t)),
            (Written::Direct, Some(t), _) => Some(self.direct_written(t)),
            (Written::CurvatureHeld, _, Some(h)) => Some(format!(
                "  writing the direct fit again with its lateral curvature held (σ over all points {} %): the better of the direct fit and the two-stage result, σ {} %, turned the lateral force around (below)",
                crate::format::readable(h.sigma_percent, 4),
                crate::format::readable(h.free_sigma_percent, 4)
            )),
            _ => None,
        }
    }

    /// The line of the two-stage result `t` written.
    fn two_stage_written(&self, t: &TwoStageReport) -> String {
        // With the digits that tell the two apart: it was chosen for
        // being lower, which three decimals can hide.
        let (c, d, differ) = distinct(
            t.polished_overall_sigma_percent,
            t.direct_sigma_percent,
            3,
            6,
        );
        let against = if differ {
            format!("{c} % < direct {d} %")
        } else {
            format!("{c} %, the direct fit's {d} % to the printed precision, lower beyond it")
        };
        // The file holds the result with what the data do not
        // determine held, whose σ is not the free one compared.
        let held = self.undetermined_held();
        if held.is_empty() || self.fit.sigma_percent == t.polished_overall_sigma_percent {
            format!("  writing the two-stage result (σ over all points {against})")
        } else {
            format!(
                "  writing the two-stage result with {} held: σ over all points {:.3} % (the σ line above); fitted free it was {against}",
                held.join(", "),
                self.fit.sigma_percent
            )
        }
    }

    /// The line of the direct fit written, the two-stage result `t` not.
    fn direct_written(&self, t: &TwoStageReport) -> String {
        let (d, c, differ) = distinct(
            t.direct_sigma_percent,
            t.polished_overall_sigma_percent,
            3,
            6,
        );
        let against = if differ {
            format!("{d} % ≤ two-stage {c} %")
        } else {
            format!(
                "{d} %, the two-stage result's {c} % to the printed precision, not lower beyond it"
            )
        };
        // The file holds the fit with what the data do not determine
        // held, whose σ is not the free fit's the choice compared.
        let held = self.undetermined_held();
        if held.is_empty() || self.fit.sigma_percent == t.direct_sigma_percent {
            format!("  writing the direct fit (σ over all points {against})")
        } else {
            format!(
                "  writing the direct fit with {} held: σ over all points {:.3} % (the σ line above); fitted free it was {against}",
                held.join(", "),
                self.fit.sigma_percent
            )
        }
    }

    /// The later fits' lines: the aligning moment's, then the
    /// longitudinal force's (its grouping first), each with its holds,
    /// parameter warnings and notes.
    fn later_fit_lines(&self) -> Vec<String> {
        let hold = &self.options.hold;
        let mut out = Vec::new();
        if let Some(mz) = &self.aligning {
            out.push(format!(
                "  aligning moment: {}, RMS {} N·m, {:.2} s",
                swarm_and_polish(mz, self.options.local),
                decimals_or_digits(mz.rms, 2, 3),
                mz.seconds
            ));
            out.extend(held_lines(&self.held_in(Block::Aligning)));
            out.extend(parameter_warnings(mz, hold));
            out.extend(later_fit_notes(self, mz).iter().map(|n| n.line(" ")));
        }
        if let (Some(g), Some(fx)) = (&self.longitudinal_grouping, &self.longitudinal) {
            out.extend(g.lines().iter().map(|l| format!("  longitudinal: {l}")));
            out.push(format!(
                "  longitudinal force: {}, RMS {} N, {:.2} s",
                swarm_and_polish(fx, self.options.local),
                decimals_or_digits(fx.rms, 1, 3),
                fx.seconds
            ));
            out.extend(held_lines(&self.held_in(Block::Longitudinal)));
            out.extend(parameter_warnings(fx, hold));
            out.extend(later_fit_notes(self, fx).iter().map(|n| n.line(" ")));
        }
        out
    }
}

/// The block of the terminal's lines a held value is said in.
#[derive(Clone, Copy, PartialEq)]
enum Block {
    /// The first fit's (the lateral force's, or a longitudinal-only
    /// file's longitudinal force), and every value given with `--hold`.
    First,
    /// The aligning moment's.
    Aligning,
    /// The longitudinal force's after a lateral fit.
    Longitudinal,
}

impl SwarmReport {
    /// The first channel's parameters held as undetermined: the holds
    /// that part the σ written from the free one the routes compared.
    fn undetermined_held(&self) -> Vec<String> {
        self.held_in(Block::First)
            .into_iter()
            .filter(|h| matches!(h.reason, HeldFor::Undetermined { .. }))
            .map(|h| h.name)
            .collect()
    }

    /// The held values said in `block`: a value held for another reason
    /// than `--hold` in the block of the later fit that has it.
    fn held_in(&self, block: Block) -> Vec<Held> {
        let has = |f: Option<&Fit>, name: &str| {
            f.is_some_and(|f| f.parameters.iter().any(|p| p.name == name))
        };
        let block_of = |h: &Held| {
            if h.reason == HeldFor::Given {
                Block::First
            } else if has(self.aligning.as_ref(), &h.name) {
                Block::Aligning
            } else if has(self.longitudinal.as_ref(), &h.name) {
                Block::Longitudinal
            } else {
                Block::First
            }
        };
        self.held
            .iter()
            .filter(|h| block_of(h) == block)
            .cloned()
            .collect()
    }
}

/// A fit's σ and its swarm's alone, "σ 4.729 % (PSO alone 4.729 %)",
/// with the polish named where the two agree to the digits shown: two
/// equal numbers read as a misprint, and `--local gn` as doing nothing
/// the user could see. The polish starts from the swarm's best and keeps
/// it unless it lowers the cost, so equal means it found nothing lower.
/// Where parameters the data do not determine were held after the swarm
/// (`undetermined.rs`), the swarm's σ is the free fit's, before them, and
/// said so on the line: "σ 2.573 % (PSO alone 2.572 %, before a6 and a7
/// were held)" read as a polish that made the fit worse.
fn swarm_and_polish(f: &Fit, local: Polish) -> String {
    let (sigma, swarm) = (f.sigma_percent, f.sigma_pso_percent);
    let held = held_after_swarm(f);
    let before = match held.len() {
        0 => String::new(),
        1 => format!(", before {} was held", held[0]),
        _ => format!(", before {} were held", and_joined(&held)),
    };
    let why = if format!("{sigma:.3}") != format!("{swarm:.3}") {
        String::new()
    } else if local == Polish::None {
        ": --local none, the swarm's best unpolished".to_string()
    } else {
        format!(
            ": the {} polish (--local {}) from the swarm's best changed σ by less than 0.001 %",
            local.method(),
            local.as_str()
        )
    };
    format!("σ {sigma:.3} % (PSO alone {swarm:.3} %{before}{why})")
}

/// The parameters of `f` held after its swarm as the data do not
/// determine them, by the names their block's lines use (UniTire's
/// `aligning.c3` is `c3` after "aligning moment:", as `notes.rs` says
/// them).
fn held_after_swarm(f: &Fit) -> Vec<&str> {
    f.parameters
        .iter()
        .filter(|p| matches!(p.held, Some(HeldFor::Undetermined { .. })))
        .map(|p| p.name.rsplit_once('.').map_or(p.name.as_str(), |(_, n)| n))
        .collect()
}

/// `names` as a list read aloud: "a6", "a6 and a7", "a6, a7 and c14".
fn and_joined(names: &[&str]) -> String {
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        Some((last, _)) => last.to_string(),
        None => String::new(),
    }
}

/// The parameters of a fit held at a value in `hold`, those the data do
/// not determine (one line), and those that carry a warning, one line
/// each.
fn parameter_warnings(f: &Fit, hold: &[(String, f64)]) -> Vec<String> {
    let undetermined = undetermined_note(f).map(|n| n.line(" "));
    undetermined
        .into_iter()
        .chain(f.parameters.iter().filter_map(|p| {
            if held_as_given(p, hold) {
                return Some(format!(
                    "  held: {} = {}: given with --hold",
                    p.name, p.value
                ));
            }
            super::notes::parameter_warning(p).map(|n| n.line(" "))
        }))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::and_joined;

    /// Names read aloud: one alone, two with "and", more with commas.
    #[test]
    fn names_are_joined_as_read_aloud() {
        assert_eq!(and_joined(&[]), "");
        assert_eq!(and_joined(&["c14"]), "c14");
        assert_eq!(and_joined(&["a6", "a7"]), "a6 and a7");
        assert_eq!(and_joined(&["a6", "a7", "c14"]), "a6, a7 and c14");
    }
}
