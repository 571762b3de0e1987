//! `report.html` of a diagnosis: the whole finding in one self-contained file
//! to share — the verdict, where the gap lies (the gap map), the base model,
//! the ranking on held-out runs, before/after per channel with the overlays
//! of the worst runs, the road under the runs and what the cleaning did.
//! Values in SI units and radians as in `diagnosis.json`; the figures are
//! those of `gap_map.png` and `overlays.png`, drawn inline as SVG.

use crate::diagnose::effects::joined;
use crate::diagnose::report::{ParameterValue, Part, Ranked};
use crate::diagnose::Diagnosis;
use crate::error::Error;
use crate::report::html::{Cell, Page};
use crate::report::plot::Figure;
use std::path::Path;

/// Cleaning lines shown in full before the rest is counted.
const CLEANING_LINES: usize = 40;

/// What the page says of the campaign beside the diagnosis.
#[derive(Debug, Clone, Copy)]
pub struct Inputs {
    /// Runs replayed (pieces after cleaning).
    pub runs: usize,
    /// Files they came from.
    pub run_files: usize,
}

/// The page of diagnosis `d`, with its gap map and overlays, to be written
/// to `path`.
pub fn page(
    d: &Diagnosis,
    inputs: Inputs,
    gap_map: &Figure,
    overlays: &Figure,
    path: &Path,
) -> Result<Page, Error> {
    let mut p = Page::new(&format!("Diagnosis of {}", d.campaign));
    p.paragraph(
        "",
        &format!(
            "{} runs from {} files, {} candidate effects, {} folds, seed {}.",
            inputs.runs,
            inputs.run_files,
            d.ranking.len() + d.screened.len(),
            d.folds,
            d.seed
        ),
    );
    p.section("verdict", "Verdict")
        .paragraph("verdict", &d.verdict.statement);
    for w in &d.verdict.warnings {
        p.paragraph("warning", w);
    }
    for c in &d.confounded {
        p.paragraph(
            "warning",
            &format!(
                "confounded: {} — separate them with {}",
                joined(&c.effects, ", "),
                c.separating_test
            ),
        );
    }
    if !d.notes.is_empty() {
        p.section("notes", "Notes on the inputs").lines(&d.notes);
    }
    p.section("gap", "Where the gap lies").lines(&d.gap.summary);
    p.figure(
        "gap-map",
        gap_map,
        "Held-out RMS over the noise floor per channel, against the time window, the \
         lateral-acceleration level and the speed band; dashed: 3 × the noise floor.",
        path,
    )?;
    base(&mut p, d);
    ranking(&mut p, d);
    shrinkage(&mut p, d);
    p.figure(
        "overlays",
        overlays,
        "Held-out replays of the runs with the largest base-model gap: measured (grey points), \
         base model (dashed), with the verdict's effects (solid).",
        path,
    )?;
    road_and_cleaning(&mut p, d);
    Ok(p)
}

/// The base model and, when the axles were identified from the runs, their
/// values.
fn base(p: &mut Page, d: &Diagnosis) {
    let b = &d.base;
    p.section("base", "Base model").paragraph("", &b.tyres);
    if let Some(g) = &b.rig_grouping {
        p.lines(&g.lines());
    }
    let Some(axles) = &b.axles else { return };
    let rows: Vec<Vec<Cell>> = axles
        .parameters
        .iter()
        .map(|a| {
            vec![
                Cell::Text(a.name.into()),
                Cell::Number(number(a.value)),
                Cell::Number(number(a.std_error)),
                Cell::Text(a.unit.into()),
                Cell::Text(a.limit.map_or_else(String::new, |l| l.meaning(a.name))),
            ]
        })
        .collect();
    p.table(
        "axles",
        &["parameter", "value", "standard error", "unit", "limit"],
        &rows,
    );
    if let Some(why) = &axles.degenerate {
        p.paragraph("warning", &format!("degenerate base: {why}"));
    }
}

/// Every candidate (singles, then combinations) with its held-out scores.
fn ranking(p: &mut Page, d: &Diagnosis) {
    let rows: Vec<Vec<Cell>> = d
        .ranking
        .iter()
        .chain(&d.combinations)
        .map(ranked_row)
        .collect();
    p.section("ranking", "Candidates on held-out runs");
    p.paragraph(
        "",
        &format!(
            "Held-out combined error J of the base model {:.3}; J of the noise alone {:.3}.",
            d.gap.heldout_error, d.gap.noise_level
        ),
    );
    p.table(
        "ranking-table",
        &[
            "effect",
            "J after",
            "held-out reduction, %",
            "in-sample reduction, %",
            "ΔBIC",
            "folds converged",
            "parameters",
            "warning",
        ],
        &rows,
    );
    if let Some(first) = d.screened.first() {
        let names: Vec<String> = d
            .screened
            .iter()
            .map(|s| format!("{} ({:.1} %)", s.effect, s.insample_reduction_percent))
            .collect();
        p.paragraph(
            "",
            &format!(
                "Screened, not cross-validated (in-sample reduction below {:.0} % − {:.0} points, so below {:.0} % on held-out runs): {}.",
                first.threshold_percent,
                first.margin_percent,
                first.threshold_percent,
                names.join(", ")
            ),
        );
    }
}

fn ranked_row(r: &Ranked) -> Vec<Cell> {
    let params: Vec<String> = r.parameters.iter().map(parameter).collect();
    vec![
        Cell::Text(r.effect.clone()),
        Cell::Number(format!("{:.3}", r.heldout_error_after)),
        Cell::Number(format!("{:.1}", r.reduction_percent)),
        Cell::Number(format!("{:.1}", r.insample_reduction_percent)),
        Cell::Number(format!("{:.0}", r.delta_bic)),
        Cell::Number(format!("{} of {}", r.folds_converged, r.folds)),
        Cell::Text(params.join("; ")),
        Cell::Text(r.warning.clone().unwrap_or_default()),
    ]
}

/// A fitted parameter with its standard error or the bound it sits on.
fn parameter(p: &ParameterValue) -> String {
    let v = number(p.value);
    if p.bound.is_some() {
        format!("{} = {v} {} (on a bound)", p.name, p.unit)
    } else if p.std_error.is_finite() {
        format!("{} = {v} ± {} {}", p.name, number(p.std_error), p.unit)
    } else {
        format!("{} = {v} {} (not identifiable)", p.name, p.unit)
    }
}

/// Before and after per channel over all held-out samples.
fn shrinkage(p: &mut Page, d: &Diagnosis) {
    let rows: Vec<Vec<Cell>> = d
        .shrinkage
        .iter()
        .filter(|s| s.part == Part::All)
        .map(|s| {
            vec![
                Cell::Text(s.channel.name().into()),
                Cell::Text(s.channel.unit().into()),
                Cell::Number(number(s.before)),
                Cell::Number(number(s.after)),
                Cell::Number(number(s.noise_floor)),
                Cell::Number(format!("{:.0}", s.reduction_percent)),
                Cell::Number(s.samples.to_string()),
            ]
        })
        .collect();
    let after = if d.verdict.effects.is_empty() {
        "no verdict: after = before".to_string()
    } else {
        format!("after: with {}", joined(&d.verdict.effects, " + "))
    };
    p.section("before-after", "Before and after, per channel")
        .paragraph("", &format!("Held-out RMS over all samples; {after}."))
        .table(
            "shrinkage",
            &[
                "channel",
                "unit",
                "before",
                "after",
                "noise floor",
                "gap above noise removed, %",
                "samples",
            ],
            &rows,
        );
}

/// The road under the runs and the cleaning report.
fn road_and_cleaning(p: &mut Page, d: &Diagnosis) {
    let road: Vec<String> = d.road.iter().filter_map(|g| g.line()).collect();
    p.section("road", "Road geometry");
    if road.is_empty() {
        p.paragraph(
            "",
            "No bank or grade measured or estimated under these runs.",
        );
    } else {
        p.lines(&road);
    }
    let mut cleaning = d.cleaning.summary(CLEANING_LINES);
    if cleaning.is_empty() {
        cleaning.push("nothing excluded, repaired or masked".into());
    }
    p.section("cleaning", "Cleaning").lines(&cleaning);
}

/// A value to four significant digits, small ones in exponent form.
fn number(v: f64) -> String {
    if !v.is_finite() {
        "—".into()
    } else if v != 0.0 && (v.abs() < 0.01 || v.abs() >= 1e5) {
        format!("{v:.3e}")
    } else {
        format!("{v:.4}")
    }
}
