//! `fleet.html`: the fleet table and the recurring effects as a
//! self-contained page to share. Each campaign links its own
//! `report.html` by its path relative to the page (`a/report.html` for
//! campaign `a.toml`, written into the fleet's folder); a failed campaign
//! wrote none and says FAILED with its error. A verdict the diagnosis
//! leaves confounded says with what, as the terminal and `fleet.csv` do.
//! Held-out errors J are dimensionless (over channel scales).

use super::rows::{distinct_diagnosed, FleetRow};
use super::FleetReport;
use crate::diagnose::effects::joined;
use crate::report::html::{Cell, Page};

/// The cells of one campaign's row.
fn row_cells(r: &FleetRow) -> Vec<Cell> {
    let number = |v: Option<f64>| v.map_or_else(|| "—".to_string(), |v| format!("{v:.3}"));
    let report = match (&r.report, r.failed) {
        (Some(path), false) => Cell::Link(path.clone()),
        // A failed campaign wrote no report: its name and why.
        _ => Cell::Text(format!("{}: FAILED: {}", r.campaign, r.statement)),
    };
    vec![
        report,
        Cell::Number(runs_words(r)),
        Cell::Text(r.verdict_words(" + ")),
        Cell::Text(if r.confounded_with.is_empty() {
            "—".into()
        } else {
            joined(&r.confounded_with, ", ")
        }),
        Cell::Number(number(r.heldout_error_before)),
        Cell::Number(number(r.heldout_error_after)),
        Cell::Number(number(r.noise_level)),
        Cell::Text(
            r.best
                .map_or_else(String::new, |b| format!("{} ({:.1} %)", b.0.name(), b.1)),
        ),
        Cell::Text(if r.failed { "FAILED: " } else { "" }.to_string() + &r.statement),
    ]
}

/// The runs cell: the runs replayed (kept, for a failed campaign), with
/// the run files read where they differ ("1 of 2 files", "12 from 3
/// files": segments), "—" where neither is known.
fn runs_words(r: &FleetRow) -> String {
    match r.runs_read {
        None if r.failed && r.runs == 0 => "—".to_string(),
        Some(read) if read != r.runs => {
            let of = if r.runs < read { "of" } else { "from" };
            format!("{} {of} {read} files", r.runs)
        }
        _ => r.runs.to_string(),
    }
}

impl FleetReport {
    /// The table and the recurring effects as a self-contained page.
    pub(super) fn page(&self) -> Page {
        let rows: Vec<Vec<Cell>> = self.campaigns.iter().map(row_cells).collect();
        let n = distinct_diagnosed(&self.campaigns);
        let recurring: Vec<Vec<Cell>> = self
            .recurring
            .iter()
            .map(|e| {
                vec![
                    Cell::Text(e.effect.name().into()),
                    Cell::Number(format!("{} of {n}{}", e.verdicts, e.confounded_words())),
                    Cell::Number(format!("{} of {n}", e.best)),
                ]
            })
            .collect();
        let mut p = Page::new("Fleet diagnosis");
        p.section("fleet", "Verdict per campaign").table(
            "fleet-table",
            &[
                "campaign report",
                "runs",
                "verdict",
                "confounded with",
                "J before",
                "J after",
                "J of the noise",
                "best single candidate",
                "statement",
            ],
            &rows,
        );
        p.section("recurring", "Recurring effects").table(
            "recurring-table",
            &[
                "effect",
                "in the verdict of (campaigns diagnosed)",
                "best single candidate in",
            ],
            &recurring,
        );
        p
    }
}
