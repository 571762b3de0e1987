//! `report.html` of a diagnosis: the whole finding in one self-contained file
//! to share — the verdict, where the gap lies (the gap map), the base model,
//! the ranking on held-out runs, before/after per channel with the overlays
//! of the worst runs, the road under the runs and what the cleaning did.
//! Values in SI units and radians as in `diagnosis.json`; the figures are
//! those of `gap_map.png` and `overlays.png`, drawn inline as SVG.

use crate::diagnose::effects::{joined, Bound};
use crate::diagnose::report::{
    words, ChannelChange, Evidence, Parsimony, Part, Ranked, Reduction, Shrinkage, Verdict,
};
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
            "{} from {}, {}, {}, seed {}{}.",
            crate::format::plural(inputs.runs, "run", "runs"),
            crate::format::plural(inputs.run_files, "file", "files"),
            crate::format::plural(
                d.ranking.len() + d.screened_singles().count(),
                "candidate effect",
                "candidate effects"
            ),
            crate::format::plural(d.folds, "fold", "folds"),
            d.seed,
            match d.derivatives {
                crate::optim::local::Derivatives::Exact => ", exact Jacobians",
                crate::optim::local::Derivatives::Differences => "",
            }
        ),
    );
    verdict(&mut p, d);
    if !d.notes.is_empty() {
        // A warning among them says so, as the terminal does.
        let said = |n: &crate::diagnose::report::Note| match n.is_warning() {
            true => format!("warning: {}", words::note(n)),
            false => words::note(n),
        };
        let notes: Vec<String> = d.notes.iter().map(said).collect();
        p.section("notes", "Notes on the inputs").lines(&notes);
    }
    let mut findings = vec![words::channels_trusted(&d.gap.noise)];
    findings.extend(d.gap.findings.iter().map(words::finding));
    findings.extend(words::channel_shares(&d.gap.channel_shares));
    let heading = words::gap_heading(&d.gap.findings);
    let heading = heading[..1].to_uppercase() + &heading[1..];
    p.section("gap", &heading).lines(&findings);
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
        &super::diagnose_overlays::overlay_caption(d),
        path,
    )?;
    road_and_cleaning(&mut p, d);
    Ok(p)
}

/// The verdict, what was fitted with it, its warnings and evidence, and
/// the confounded sets with the tests that separate them.
fn verdict(p: &mut Page, d: &Diagnosis) {
    p.section("verdict", "Verdict")
        .paragraph("verdict", &d.verdict.statement());
    if !d.verdict.parameters().is_empty() {
        let fitted: Vec<String> = d
            .verdict
            .parameters()
            .iter()
            .map(words::parameter)
            .collect();
        let held = if d.base.axles.is_none() {
            format!(" ({})", words::TYRES_HELD)
        } else {
            String::new()
        };
        p.paragraph("verdict", &format!("Fitted: {}{held}.", fitted.join("; ")));
    }
    // The verdict's own axles where they were refitted with it (no tyre
    // data), as the terminal gives them: the base's are not what the
    // verdict stands on.
    if let Some(a) = d.verdict_row().and_then(|r| r.axles.as_ref()) {
        p.paragraph(
            "verdict",
            &format!(
                "Axles fitted with it: {}.",
                words::axle_values(a).join(", ")
            ),
        );
    }
    for w in words::verdict_warnings(&d.verdict) {
        p.paragraph("warning", &w);
    }
    if let crate::diagnose::report::Verdict::Explained(e) = &d.verdict {
        for x in &e.evidence {
            p.paragraph("verdict", &words::evidence(x));
        }
    }
    for c in &d.confounded {
        p.paragraph(
            "warning",
            &format!(
                "Confounded: the runs do not tell {} apart (their held-out gaps lie \
                 within the confounding window the verdict states). {}",
                joined(&c.effects, " and "),
                if c.separating_runs.is_some() {
                    "What separates them:"
                } else {
                    "A test that shows one of these signatures separates them:"
                }
            ),
        );
        // On a base with no friction limit the signatures' tests at the
        // limit separate nothing: what the replays separate instead.
        let tests: Vec<String> = match &c.separating_runs {
            Some(s) => vec![s.words()],
            None => c.effects.iter().map(|e| words::signatures(&[*e])).collect(),
        };
        p.lines(&tests);
    }
}

/// The base model and, when the axles were identified from the runs, their
/// values.
fn base(p: &mut Page, d: &Diagnosis) {
    let b = &d.base;
    p.section("base", "Base model")
        .paragraph("", &words::tyre_source(b));
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
                Cell::Text(
                    a.limit
                        .map_or_else(String::new, |l| words::limit_meaning(l, a.name)),
                ),
            ]
        })
        .collect();
    p.table(
        "axles",
        &["parameter", "value", "standard error", "unit", "limit"],
        &rows,
    );
    if axles.degenerate() {
        let why = words::no_tyre_list(&axles.no_tyre);
        p.paragraph("warning", &format!("degenerate base: {why}"));
    }
}

/// Every candidate (singles, then combinations) with its held-out scores.
fn ranking(p: &mut Page, d: &Diagnosis) {
    let all: Vec<&Ranked> = d.ranking.iter().chain(&d.combinations).collect();
    let verdict = d.verdict_row();
    let rows: Vec<Vec<Cell>> = all.iter().map(|r| ranked_row(r, d, verdict)).collect();
    p.section("ranking", "Candidates on held-out runs");
    p.paragraph(
        "",
        &format!(
            "Held-out combined error J of the base model {:.3}; J of the noise alone {:.3}.",
            d.gap.heldout_error, d.gap.noise_level
        ),
    );
    if all.is_empty() {
        let n = words::NONE_CROSS_VALIDATED;
        p.paragraph("", &format!("{}{}.", n[..1].to_uppercase(), &n[1..]));
        screened(p, d);
        return;
    }
    let c = words::bic_caveat(&d.gap.findings);
    p.paragraph("", &format!("{}{}.", c[..1].to_uppercase(), &c[1..]));
    p.paragraph(
        "",
        "Single effects come first, lowest held-out J first, then combinations. The verdict \
         is not always the top row: a candidate that leaves one of its parameters idle (a \
         steer-path lag that stays off) gives way to a simpler candidate whose J is as low \
         within a small share of the noise level, and effects are combined only while each \
         removes a large share of what is left and lowers the BIC. The last column says why \
         a row above the verdict is not it.",
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
            "verdict",
        ],
        &rows,
    );
    screened(p, d);
}

/// The candidates and sets screened out before cross-validation, each
/// with its in-sample reduction: the paragraphs under the ranking table.
/// Apart from [`ranking`] so that it reads on a screen.
fn screened(p: &mut Page, d: &Diagnosis) {
    let (outranked, screened_sets): (Vec<_>, Vec<_>) =
        d.screened_sets().partition(|s| s.outranked.is_some());
    let sets: Vec<String> = screened_sets
        .iter()
        .map(|s| {
            let of = joined(&s.extends, "+");
            format!(
                "{} ({} % of what {of} leaves)",
                s.effect,
                crate::format::fixed(s.insample_reduction_percent, 1)
            )
        })
        .collect();
    if let Some(first) = screened_sets.first() {
        p.paragraph(
            "",
            &format!(
                "Sets screened, not cross-validated (each removes in sample below {:.0} % − {:.0} points of the gap the set it extends leaves, so none could be added): {}.",
                first.threshold_percent,
                first.margin_percent,
                sets.join(", ")
            ),
        );
    }
    let spared: Vec<String> = outranked
        .iter()
        .filter_map(|s| {
            let o = s.outranked.as_ref()?;
            Some(format!(
                "{} (held-out J at least {:.3} against {}'s {:.3})",
                s.effect,
                o.floor,
                joined(&o.by, "+"),
                o.heldout_error
            ))
        })
        .collect();
    if !spared.is_empty() {
        p.paragraph(
            "",
            &format!(
                "Sets not cross-validated (their least possible held-out J, in sample plus the margin, is beyond what the step's pick reads of its best set): {}.",
                spared.join(", ")
            ),
        );
    }
    let singles: Vec<_> = d.screened_singles().collect();
    if let Some(first) = singles.first() {
        let names: Vec<String> = singles
            .iter()
            .map(|s| {
                let r = crate::format::fixed(s.insample_reduction_percent, 1);
                format!("{} ({r} %)", s.effect)
            })
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

fn ranked_row(r: &Ranked, d: &Diagnosis, verdict: Option<&Ranked>) -> Vec<Cell> {
    let removes = matches!(d.reductions(r)[0], Reduction::Percent(_));
    let params: Vec<String> = r
        .parameters
        .iter()
        .map(|p| words::parameter_of(p, removes))
        .collect();
    // The terminal's rule ([`Diagnosis::reductions`]), so the two agree.
    let [held_out, in_sample] = d.reductions(r).map(|x| match x {
        Reduction::WithinNoise => Cell::Text(words::reduction(x)),
        Reduction::Percent(_) => Cell::Number(words::reduction(x)),
    });
    vec![
        Cell::Text(r.effect.clone()),
        Cell::Number(format!("{:.3}", r.heldout_error_after)),
        held_out,
        in_sample,
        Cell::Number(crate::format::fixed(r.delta_bic, 0)),
        Cell::Number(format!("{} of {}", r.folds_converged, r.folds)),
        Cell::Text(params.join("; ")),
        Cell::Text(words::rank_warnings(&r.warnings).unwrap_or_default()),
        Cell::Text(verdict_role(r, verdict, d)),
    ]
}

/// The verdict column: the verdict's row, and why a row that scores better
/// than the verdict is not it, counted as the rule counts (a parameter no
/// channel responds to is not counted; an idle one is, and is named).
fn verdict_role(r: &Ranked, verdict: Option<&Ranked>, d: &Diagnosis) -> String {
    let Some(v) = verdict else {
        return String::new();
    };
    if std::ptr::eq(r, v) {
        return "the verdict".into();
    }
    if r.heldout_error_after >= v.heldout_error_after {
        return String::new();
    }
    let margin = (v.heldout_error_after - r.heldout_error_after) / d.gap.noise_level;
    let counted = |x: &Ranked| x.parameters.iter().filter(|p| !p.unseen).count();
    let (n, m) = (counted(r), counted(v));
    let pressed = |x: &Ranked| {
        x.parameters
            .iter()
            .any(|p| p.at_bound && p.bound == Some(Bound::Search))
    };
    if pressed(r) && !pressed(v) {
        format!(
            "J lower by {margin:.3} × the noise level, but only with a parameter on its \
             search bound: the verdict, inside its ranges, is taken"
        )
    } else if let Some(c) = parsimony_over(r, d) {
        let idle: Vec<&str> = c.idle.iter().map(|p| p.name.as_str()).collect();
        format!(
            "J lower by {margin:.3} × the noise level only, leaving {} idle (off, or not \
             told from off): with it counted, {n} effect parameters to the verdict's {m}, \
             and the simpler is taken",
            idle.join(", ")
        )
    } else if n > m {
        format!(
            "J lower by {margin:.3} × the noise level only, with {n} effect parameters to \
             the verdict's {m}: the simpler is taken"
        )
    } else {
        format!("J lower by {margin:.3} × the noise level; not taken: see the verdict")
    }
}

/// The verdict's parsimony evidence about the look-alike `r`, if that is
/// why `r` is not the verdict.
fn parsimony_over<'a>(r: &Ranked, d: &'a Diagnosis) -> Option<&'a Parsimony> {
    let Verdict::Explained(e) = &d.verdict else {
        return None;
    };
    e.evidence.iter().find_map(|x| match x {
        Evidence::ChosenForParsimony(c) if c.effects == r.effects => Some(c),
        _ => None,
    })
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
                Cell::Number(words::rms(s.before)),
                Cell::Number(words::rms(s.after)),
                floor_cell(s, d),
                channel_reduction(s),
                Cell::Number(s.samples.to_string()),
            ]
        })
        .collect();
    let after = if d.verdict.effects().is_empty() {
        "no verdict: after = before".to_string()
    } else {
        format!("after: with {}", joined(d.verdict.effects(), " + "))
    };
    p.section("before-after", "Before and after, per channel")
        .paragraph(
            "",
            &format!(
                "RMS over all held-out samples; {after}. {}",
                words::channels_alone()
            ),
        )
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
    if d.verdict.effects().is_empty() {
        return;
    }
    // The runs the verdict leaves significant alone, as the terminal's
    // block says them under each row.
    for c in crate::diagnose::report::left_in::runs_left_in(&d.shrinkage) {
        if let Some((head, runs)) = words::runs_left(&c) {
            p.paragraph("", &head).lines(&runs);
        }
    }
}

/// A channel's noise floor, and where it is stated below the channel's
/// scatter what judges its gap and what weighs it in the fits
/// ([`words::judged_apart`]), as the terminal's row says it.
fn floor_cell(s: &crate::diagnose::report::Shrinkage, d: &Diagnosis) -> Cell {
    let floor = words::rms(s.noise_floor);
    let noise = d.gap.noise.iter().find(|n| n.channel == s.channel);
    match noise.and_then(words::judged_apart) {
        Some(j) => Cell::Text(format!("{floor} (stated, {j})")),
        None => Cell::Number(floor),
    }
}

/// The share of a channel's gap removed (negative: added), or "not
/// significant" where its held-out RMS is within the noise floors before
/// and after: there is no gap to remove and the share would be noise; or
/// "unchanged" where it moved within the scatter of held-out scores. The
/// rule is the verdict's warnings' ([`Shrinkage::change`]), so the page
/// and the terminal agree.
fn channel_reduction(s: &Shrinkage) -> Cell {
    match s.change() {
        ChannelChange::WithinNoise => Cell::Text(words::within_noise(s)),
        ChannelChange::Unchanged(_) => {
            Cell::Text(words::unchanged(s.before, s.after, s.noise_floor))
        }
        ChannelChange::Changed(p) => Cell::Number(format!("{p:.0}")),
        ChannelChange::Worsened(p) if p.is_finite() => Cell::Number(format!("{:.0}", -p)),
        ChannelChange::Worsened(p) => Cell::Text(words::added(p, s.before, s.after, s.noise_floor)),
    }
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
    let calibration = d.calibration.lines();
    if !calibration.is_empty() {
        p.section(
            "calibration",
            "Sensor offsets from standstills and straights",
        )
        .lines(&calibration);
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
