//! `identify --model mf61|mf62` as one job: Wei et al.'s (2010) five stages
//! and the combined `Mz`, `Mx` and `My` stages after them
//! ([`crate::identify::mf_staged`]) on rig data (with its `mx`, `my`
//! columns when measured), the result written as a .tir (a
//! template's constants and layout kept) that is read back and checked to
//! reproduce the fitted forces. This file holds the job's report and its
//! lines; the run itself is `staged_run.rs`.

use super::level_names::LevelNames;
use super::Options;
use crate::format::{exact, plural};
use crate::identify::mf_staged::{
    self, rms_text, HoldReason, PooledSigma, RowAccount, StagedReport,
};
use crate::jobs::tyre_eval::gives_none;
use crate::report::plot::Figure;
use crate::report::OutputLock;
use crate::tyre::mf::MagicFormula;
use serde::Serialize;

/// One fitted stage's figure and the file it is written to.
#[derive(Debug, Clone, Serialize)]
pub struct StageFigure {
    /// The stage drawn.
    pub stage: mf_staged::Stage,
    /// `<out>.<stage>.png` beside the tyre file.
    pub path: std::path::PathBuf,
    /// Its panels.
    #[serde(skip)]
    pub figure: Figure,
}

/// The report of the staged Magic Formula fit.
#[derive(Debug, Clone, Serialize)]
pub struct StagedJob {
    /// The stages.
    #[serde(flatten)]
    pub report: StagedReport,
    /// The data file.
    pub data: String,
    /// The options that change the fit, and the command that repeats it.
    #[serde(rename = "options")]
    pub recorded: super::RecordedOptions,
    /// Samples and rows fitted.
    pub rows: RowAccount,
    /// The coefficients held with `--hold` (each written at its value).
    pub held: Vec<super::holds::Held>,
    /// The fit's overall σ: pooled over every raw sample and measured
    /// channel of the file (the stages' σ are over their own rows).
    pub sigma_pooled: PooledSigma,
    /// Largest relative difference between the forces of the written .tir
    /// read back and the fitted ones.
    pub round_trip_relative_difference: f64,
    /// The curvatures `Ey`, `Ex` of the written file above 1 over the
    /// fitted data, each where it is largest (none: none is).
    pub curvature_above_one: Vec<super::curvature::CurvatureExcess>,
    /// The written tyre's pure curve beyond any tyre's (a peak |F|/Fz
    /// above 5, or a force turning against its slip), which `tyre-eval`
    /// and `simulate` refuse: said, and the file written all the same;
    /// first, a template's such curve.
    pub pure_curve_warning: Vec<String>,
    /// The written file's own checks, as `tyre-eval` makes them
    /// (`written_checks.rs`): a peak |F|/Fz above 2.5, a longitudinal slip
    /// stiffness negative inside its load range.
    pub file_warnings: Vec<String>,
    /// Warnings on the data read: forces far too small for their loads
    /// (`force_scale.rs`), as every model's fit gives them.
    pub input_warnings: Vec<String>,
    /// The .tir text written.
    #[serde(skip)]
    pub tir: String,
    /// The lines saying the longitudinal force and the wheel moments are
    /// not fitted, and what the written file's are ([`unfitted_blocks`]).
    #[serde(skip)]
    pub unfitted: Vec<String>,
    /// What the job was asked.
    #[serde(skip)]
    pub options: Options,
    /// Measured against fitted, a figure per stage fitted (a panel per
    /// camber, pressure and, where needed, load, each with its σ).
    pub figures: Vec<StageFigure>,
    /// Files beside the outputs, named as this fit's, that it does not
    /// write: `<out>.png`, the one figure of an earlier release's staged
    /// fit (now `<out>.<stage>.png`). Said and kept: nothing tells that
    /// this tool wrote it, and a file the tool cannot tell it wrote is
    /// not deleted.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub not_from_this_fit: Vec<std::path::PathBuf>,
    /// The outputs, held for this run until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
}

impl StagedJob {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let o = &self.options;
        let mut out = vec![format!(
            "{}: {}, {}; model {}, start {}",
            o.data.display(),
            plural(self.rows.samples, "sample", "samples"),
            plural(self.rows.rows, "row", "rows"),
            o.model,
            o.start.as_str()
        )];
        out.extend(
            self.input_warnings
                .iter()
                .map(|w| format!("  warning: {w}")),
        );
        if let Some(g) = &self.rows.thinning {
            out.extend(g.lines().iter().map(|l| format!("  {l}")));
        }
        out.extend(super::holds::held_lines(&self.held));
        let named = self
            .rows
            .thinning
            .as_ref()
            .map_or(&[][..], |g| &g.levels[..]);
        out.extend(stage_lines(&self.report, named, true));
        out.push(format!("  {}", self.sigma_pooled.line()));
        out.extend(
            self.curvature_above_one
                .iter()
                .map(|e| format!("  warning: {}", e.line())),
        );
        out.extend(
            self.pure_curve_warning
                .iter()
                .chain(&self.file_warnings)
                .map(|w| format!("  warning: {w}")),
        );
        out.extend(self.unfitted.iter().map(|l| format!("  {l}")));
        out.extend(self.not_from_this_fit.iter().map(|p| {
            format!(
                "  note: {} beside it is not from this fit (an earlier fit's single figure; this fit's are one per stage, <out>.<stage>.png): kept, remove it by hand",
                p.display()
            )
        }));
        out
    }
}

/// The files beside the tyre file `out` named as a fit's outputs that a
/// staged fit does not write (`<out>.png`), where they exist.
pub(super) fn not_from_this_fit(out: &std::path::Path) -> Vec<std::path::PathBuf> {
    let single = out.with_extension("png");
    if single.is_file() {
        vec![single]
    } else {
        Vec::new()
    }
}

/// The terminal's lines of each stage of `report` (indented as the
/// summary gives them): its σ or why it was skipped, where its error lies
/// (loads named as `named`, the grouping's levels, name them), its
/// warnings and what it held. The written file's header repeats them
/// without the seconds (`timed` false), so that a refit of the same data
/// writes the same file.
pub(super) fn stage_lines(
    report: &StagedReport,
    named: &[crate::identify::grouping::Levels],
    timed: bool,
) -> Vec<String> {
    let mut out = Vec::new();
    for s in &report.stages {
        let (sigma, moved) = crate::identify::mf_staged::sigma_said(s);
        match &s.skipped {
            Some(why) => out.push(format!("  {:<12} skipped: {why}", s.stage.label())),
            None => out.push(format!(
                "  {:<12} {:>5} points, {} free: {sigma} (start {:.2} %{moved}{}), RMS error {}{}",
                s.stage.label(),
                s.points,
                s.parameters.iter().filter(|p| p.free).count(),
                s.sigma_start_percent,
                Some(s.paper_sigma_percent)
                    .filter(|p| p.is_finite())
                    .map_or(String::new(), |p| format!(
                        "; Wei et al. 2010 reached {p:.2} % on their own rig data"
                    )),
                rms_text(s.rms, s.stage.unit()),
                if timed {
                    format!(", {:.2} s", s.seconds)
                } else {
                    String::new()
                }
            )),
        }
        let names = LevelNames::of(named, &[]);
        let load = |fz: f64| names.load(fz);
        if let Some(line) = s.error_spread.as_ref().and_then(|e| e.line_naming(&load)) {
            out.push(format!("    where the error lies: {line}"));
        }
        out.extend(s.warnings.iter().map(|w| format!("    warning: {w}")));
        // What was held at a stated value rather than fitted (the
        // parameters held for want of levels are in the report).
        out.extend(s.parameters.iter().filter_map(|p| match &p.held {
            Some(
                why @ (HoldReason::NotIdentifiable { .. }
                | HoldReason::AtCurvatureClip { .. }
                | HoldReason::Given),
            ) => Some(format!(
                "    held: {} = {}: {}",
                p.name,
                p.value,
                why.said(p.name)
            )),
            _ => None,
        }));
        out.extend(level_held_lines(&s.parameters));
        // A free parameter's warning, and the hold the guard refused it
        // (said by the refusal itself, `mf_staged::RefusedHold`).
        out.extend(s.parameters.iter().filter_map(|p| {
            let refused = p.hold_refused.as_ref().map(|r| r.said(p.name, s.stage));
            let w: Vec<String> = p.warning.iter().cloned().chain(refused).collect();
            (!w.is_empty()).then(|| {
                format!(
                    "    warning: {} = {}: {}",
                    p.name,
                    crate::format::rounded(p.value, 4),
                    w.join("; ")
                )
            })
        }));
    }
    out
}

/// The blocks the fit wrote without data, one line each: where the pure
/// Fx stage had no rows (a cornering-only rig file), the longitudinal
/// force; where the pure Fy stage was skipped, the lateral force; where the Mx or My stage had none (no `mx`, `my` columns), the
/// overturning or rolling resistance moment. Each says that its
/// coefficients are the template's (`template`) or the defaults', and
/// what the written tyre `t` then gives: without a template none (the
/// defaults' PDX1 = PKX1 = 0, QSX*, QSY* all 0), found by `tyre-eval`'s
/// rule ([`gives_none`]), which would read as a tyre that grips only
/// sideways, or has no wheel moments, unless it is said.
pub(super) fn unfitted_blocks(
    report: &StagedReport,
    template: bool,
    t: &MagicFormula,
    combined_rows: usize,
) -> Vec<String> {
    use crate::jobs::tyre_eval::Output;
    use mf_staged::Stage;
    let tyre = crate::tyre::Tyre::MagicFormula(Box::new(t.clone()));
    // A lateral block without a fit is said too: data with only combined
    // slip (`comb_noisy.csv`, 12 pure lateral rows for 12 parameters)
    // leave it at the defaults' PDY1 = PKY1 = 0, a tyre that does not
    // corner, which no engineer takes for a fit unless it is said.
    let blocks = [
        (Stage::PureFy, Output::Fy, "pure lateral", "lateral force"),
        (
            Stage::PureMz,
            Output::Mz,
            "aligning moment",
            "aligning moment",
        ),
        (
            Stage::PureFx,
            Output::Fx,
            "longitudinal",
            "longitudinal force",
        ),
        (
            Stage::Mx,
            Output::Mx,
            "overturning moment",
            "overturning moment",
        ),
        (
            Stage::My,
            Output::My,
            "rolling resistance",
            "rolling resistance moment",
        ),
    ];
    let from = if template {
        "the template's values"
    } else {
        "the defaults' (no --template)"
    };
    blocks
        .into_iter()
        .filter_map(|(stage, o, data, block)| {
            let skipped = report.stages.iter().find(|s| s.stage == stage)?;
            let why = skipped.skipped.as_ref()?;
            let gives = match gives_none(&tyre, o).and_then(|z| z.cause()) {
                Some((cause, _)) => format!(
                    "the written file's {} is 0 {} ({cause}): give --template with a tyre's {} coefficients for one",
                    o.what(),
                    o.anywhere(),
                    o.block()
                ),
                None => format!("the written file's {} is theirs, not these data's", o.what()),
            };
            Some(format!(
                "no {data} data: the {block} block is not fitted ({why}): its coefficients are {from}; {gives}"
            ))
        })
        .chain(combined_unfitted(report, from, t, combined_rows))
        .collect()
}

/// The combined-slip blocks the fit wrote without data (the stages
/// skipped for want of combined-slip rows), one line each: their
/// coefficients are `from`, and what the written tyre `t` then does
/// under combined slip (at `FNOMIN`, α = 0.1 rad against 0, κ = 0.1
/// against 0): the defaults' `RBX1 = RBY1 = 0` leave each force as its
/// pure one, which reads as a tyre that loses no grip under combined
/// slip unless it is said.
fn combined_unfitted(
    report: &StagedReport,
    from: &str,
    t: &MagicFormula,
    combined_rows: usize,
) -> Vec<String> {
    use mf_staged::Stage;
    let fz = t.coefficients.FNOMIN;
    let tyre = crate::tyre::Tyre::MagicFormula(Box::new(t.clone()));
    let at = |kappa: f64, alpha: f64| {
        tyre.evaluate_points(
            &[fz],
            &[kappa],
            &[alpha],
            &[0.0],
            &[t.coefficients.LONGVL],
            &[],
        )[0]
    };
    let blocks = [
        (
            Stage::CombinedFx,
            "longitudinal force (RBX*, RCX1, REX*, RHX1)",
            "longitudinal force does not fall with slip angle",
            at(0.1, 0.1).fx == at(0.1, 0.0).fx,
        ),
        (
            Stage::CombinedFy,
            "lateral force (RBY*, RCY1, REY*, RHY*, RVY*)",
            "lateral force does not fall with slip ratio",
            at(0.1, 0.1).fy == at(0.0, 0.1).fy,
        ),
        (
            Stage::CombinedMz,
            "aligning moment (SSZ*)",
            "aligning moment has no arm of the longitudinal force",
            at(0.1, 0.1).mz == at(0.0, 0.1).mz,
        ),
    ];
    blocks
        .into_iter()
        .filter_map(|(stage, block, pure, is_pure)| {
            let skipped = report.stages.iter().find(|s| s.stage == stage)?;
            let why = skipped.skipped.as_ref()?;
            let gives = if is_pure {
                format!("the written file's {pure} (its pure curve under combined slip)")
            } else {
                let short = block.split(" (").next().unwrap_or(block);
                format!("the written file's {short} under combined slip is theirs, not these data's")
            };
            // A file with combined rows is not said to have none (its
            // stage skipped for the pure stage it builds on).
            let heading = match (why, combined_rows) {
                (crate::error::SkipReason::BuildsOnSkipped { .. }, n) if n > 0 => {
                    format!("{} without the pure stage", plural(n, "combined-slip row", "combined-slip rows"))
                }
                _ => "no combined-slip data".to_string(),
            };
            Some(format!(
                "{heading}: the combined {block} block is not fitted ({why}): its coefficients are {from}; {gives}"
            ))
        })
        .collect()
}

/// The terminal's lines of a stage's parameters held for want of levels
/// or by design, one per reason, each value as written.
fn level_held_lines(parameters: &[mf_staged::StageParameter]) -> Vec<String> {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    for p in parameters {
        let Some(why @ (HoldReason::Levels { .. } | HoldReason::ByDesign { .. })) = &p.held else {
            continue;
        };
        let (why, value) = (why.to_string(), format!("{} = {}", p.name, exact(p.value)));
        match groups.iter_mut().find(|g| g.0 == why) {
            Some(g) => g.1.push(value),
            None => groups.push((why, vec![value])),
        }
    }
    groups
        .into_iter()
        .map(|(why, values)| format!("    held: {}: {why}", values.join(", ")))
        .collect()
}
