//! A fleet table's rows and which of them read the same runs: campaigns
//! naming one runs folder, or run files byte for byte the same in another
//! folder (a copy), are one campaign's runs and counted once, with a note
//! naming them (a fleet counted three campaign files reading one folder,
//! and a copied folder, as campaigns agreeing on a verdict).

use crate::diagnose::effects::EffectKind;
use crate::diagnose::VerdictKind;
use crate::jobs::shard::digest;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// One campaign's line of the fleet table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FleetRow {
    /// The campaign's file or folder name in the batch folder (its file's
    /// stem: the output folder's name).
    pub campaign: String,
    /// The campaign's own `name` where it differs from `campaign` (a file
    /// `a.toml` holding `name = "small"`): its report says that name, so
    /// the table says both.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Runs replayed (pieces after cleaning); for a failed campaign the
    /// runs its checks kept where its failure says them (0 unknown: round
    /// 39's fleet said 0 for a campaign of 8 runs refused on a sign).
    pub runs: usize,
    /// The run files read (None: a campaign that failed before reading
    /// them, or not known).
    #[serde(default)]
    pub runs_read: Option<usize>,
    /// Effects of the verdict (empty: no gap, or none explains it).
    pub verdict: Vec<EffectKind>,
    /// The verdict's case (None: failed).
    #[serde(default)]
    pub kind: Option<VerdictKind>,
    /// Held-out error J of the base model (None: failed).
    pub heldout_error_before: Option<f64>,
    /// Held-out J with the verdict's effects (the base model's without).
    pub heldout_error_after: Option<f64>,
    /// J of the noise alone.
    pub noise_level: Option<f64>,
    /// The best single candidate and its share of the gap removed, %: none
    /// where the gap is within noise or the best removes none of it (a
    /// campaign with no gap named steering_compliance at 0 %).
    pub best: Option<(EffectKind, f64)>,
    /// The best candidate has a parameter on a bound: its value is a
    /// limit, not a measurement, and it does not count as recurring.
    #[serde(default)]
    pub best_on_bound: bool,
    /// The verdict in words, or why the campaign failed.
    pub statement: String,
    /// Whether it failed (not read or not diagnosed).
    pub failed: bool,
    /// The effects the diagnosis leaves confounded with the verdict's (its
    /// `confounded` sets that hold one of the verdict's effects): empty
    /// where the runs tell the verdict from every look-alike.
    #[serde(default)]
    pub confounded_with: Vec<EffectKind>,
    /// Its `report.html`, relative to the fleet's folder (`a/report.html`
    /// for campaign `a.toml`); None where it failed and wrote none.
    #[serde(default)]
    pub report: Option<String>,
    /// The folder its run files were read from, canonical: campaigns
    /// that share it are one campaign's runs, counted once.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub runs_folder: Option<String>,
    /// A digest of its run files' bytes ([`runs_digest`]): campaigns whose
    /// run files are byte for byte the same (a copied folder) are one
    /// campaign's runs too, counted once.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub runs_digest: Option<String>,
}

impl FleetRow {
    /// The campaign as the terminal and the page name it: its file name,
    /// and its own `name` where that differs (`a (name "small")`).
    pub fn label(&self) -> String {
        match &self.name {
            Some(name) => format!("{} (name \"{name}\")", self.campaign),
            None => self.campaign.clone(),
        }
    }

    /// Its verdict's effects joined by `sep`, with the effects the
    /// diagnosis leaves confounded with them (`steering_compliance
    /// (confounded with cornering_stiffness)`); "—" for none.
    pub fn verdict_words(&self, sep: &str) -> String {
        if self.verdict.is_empty() {
            return "—".to_string();
        }
        self.effect_words(sep)
    }

    /// As [`Self::verdict_words`], but where no effect is named, the
    /// verdict's case in words: the terminal table has no `kind` column
    /// (fleet.csv and the page's statement do), and "—" alone read the same
    /// for a significant gap no effect explains and for no gap at all
    /// (round 41).
    pub fn verdict_or_kind_words(&self, sep: &str) -> String {
        if !self.verdict.is_empty() {
            return self.effect_words(sep);
        }
        match self.kind {
            Some(VerdictKind::OutsideLibrary) => "— (a gap no effect explains)",
            Some(VerdictKind::NoSignificantGap) => "— (no significant gap)",
            Some(VerdictKind::NotIdentifiable) => "— (base not identifiable)",
            Some(VerdictKind::Explained) | None => "—",
        }
        .to_string()
    }

    /// The verdict's effects joined by `sep`, with their confounded ones.
    fn effect_words(&self, sep: &str) -> String {
        let effects = crate::diagnose::effects::joined(&self.verdict, sep);
        if self.confounded_with.is_empty() {
            return effects;
        }
        format!(
            "{effects} (confounded with {})",
            crate::diagnose::effects::joined(&self.confounded_with, " and ")
        )
    }
}

/// The effects `confounded` (a diagnosis's confounded sets) leaves
/// confounded with one of `verdict`'s, each once, in the sets' order.
pub(super) fn confounded_with(
    verdict: &[EffectKind],
    confounded: &[crate::diagnose::report::Confounded],
) -> Vec<EffectKind> {
    let mut out: Vec<EffectKind> = Vec::new();
    for set in confounded
        .iter()
        .filter(|c| c.effects.iter().any(|e| verdict.contains(e)))
    {
        for e in &set.effects {
            if !verdict.contains(e) && !out.contains(e) {
                out.push(*e);
            }
        }
    }
    out
}

/// The canonical folder of a campaign's run files (`None`: it has none,
/// or it does not load). Three campaign files naming one `runs` folder
/// were counted as three campaigns agreeing on a verdict.
pub(super) fn runs_folder_of(campaign: &Path) -> Option<String> {
    let c = crate::io::campaign::load_campaign(campaign).ok()?;
    let folder = c.runs_folder?.canonicalize().ok()?;
    Some(folder.display().to_string())
}

/// A digest of the bytes of the run files of `folder` (its `*.csv`, as the
/// campaign reads them), whatever their names: equal for a copy of the
/// folder. `None` where one cannot be read (the diagnosis said why).
pub(super) fn runs_digest(folder: &Path) -> Option<String> {
    let mut digests = std::fs::read_dir(folder)
        .ok()?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x.eq_ignore_ascii_case("csv")))
        .map(|p| std::fs::read(p).ok().map(|b| digest(&b)))
        .collect::<Option<Vec<u64>>>()?;
    digests.sort_unstable();
    let all: Vec<u8> = digests.iter().flat_map(|d| d.to_le_bytes()).collect();
    Some(format!("{:016x}", digest(&all)))
}

/// The runs a failed campaign (at `campaign`, failing with `e`) kept and
/// the run files it read: as its refusal counts them (runs refused, too
/// few runs), else as the campaign loads (a failure after loading, such
/// as a `beta` against the base model), else unknown (0, None).
pub(super) fn failed_runs(campaign: &Path, e: &crate::error::Error) -> (usize, Option<usize>) {
    if let crate::error::Error::Input(i) = e {
        if let Some((kept, read)) = i.runs_counted() {
            return (kept, Some(read));
        }
    }
    match crate::io::campaign::load_campaign(campaign) {
        Ok(c) => (c.runs.len(), Some(c.run_files)),
        Err(_) => (0, None),
    }
}

/// Whether rows `a` and `b` read the same runs: one folder, or run files
/// byte for byte the same.
fn same_runs(a: &FleetRow, b: &FleetRow) -> bool {
    let same = |x: &Option<String>, y: &Option<String>| x.is_some() && x == y;
    same(&a.runs_folder, &b.runs_folder) || same(&a.runs_digest, &b.runs_digest)
}

/// Whether row `i` is the first of the rows reading its run files (a row
/// with no known folder always is).
pub(super) fn first_of_its_runs(rows: &[FleetRow], i: usize) -> bool {
    !rows[..i].iter().any(|p| same_runs(p, &rows[i]))
}

/// The campaigns diagnosed, those reading the same run files counted
/// once: what the recurring effects are counted out of.
pub(super) fn distinct_diagnosed(rows: &[FleetRow]) -> usize {
    (0..rows.len())
        .filter(|&i| !rows[i].failed && first_of_its_runs(rows, i))
        .count()
}

/// A note for each set of campaigns that read the same run files.
pub(super) fn shared_runs_notes(rows: &[FleetRow]) -> Vec<String> {
    (0..rows.len())
        .filter(|&i| first_of_its_runs(rows, i))
        .filter_map(|i| {
            let folder = rows[i].runs_folder.as_ref()?;
            let same: Vec<&str> = rows
                .iter()
                .filter(|r| r.runs_folder.as_ref() == Some(folder))
                .map(|r| r.campaign.as_str())
                .collect();
            (same.len() > 1).then(|| {
                format!(
                    "  note: {} read the same run files ({folder}): one campaign's runs, counted once below",
                    same.join(", ")
                )
            })
        })
        .chain(copied_runs_note(rows))
        .collect()
}

/// The note on the campaigns whose run files are, byte for byte, an
/// earlier campaign's in another folder (a copied runs folder): each
/// with the one it repeats, counted once.
fn copied_runs_note(rows: &[FleetRow]) -> Option<String> {
    let copies: Vec<String> = (0..rows.len())
        .filter_map(|j| {
            let i = (0..j).find(|&i| same_runs(&rows[i], &rows[j]))?;
            let (a, b) = (&rows[j], &rows[i]);
            (a.runs_folder != b.runs_folder).then(|| {
                let folder = |r: &FleetRow| r.runs_folder.clone().unwrap_or_default();
                format!(
                    "{} = {} ({} = {})",
                    a.campaign,
                    b.campaign,
                    folder(a),
                    folder(b)
                )
            })
        })
        .collect();
    (!copies.is_empty()).then(|| {
        format!(
            "  note: {} run files identical, byte for byte, to another's in another folder (a copy): counted once below: {}",
            match copies.len() {
                1 => "1 campaign reads".to_string(),
                n => format!("{n} campaigns read"),
            },
            copies.join("; ")
        )
    })
}
