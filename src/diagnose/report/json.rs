//! How the typed outcome is written to `diagnosis.json`: every field a
//! reader had keeps its name and its words ([`super::words`]), and the
//! types are added beside them — `verdict.kind` with the case's details
//! (`refused`, `no_tyre`, `warning_details`, …), `ranking[].warning_details`,
//! `note_details`, `gap.findings`, `base.source`, `base.axles.no_tyre`.
//! Units as in the report (SI, rad; J dimensionless; reductions in %).

use crate::diagnose::base::identify::{AxleIdentification, NoTyre};
use crate::diagnose::base::TyreSource;
use crate::diagnose::campaign::StatedFriction;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::report::left_in::{runs_left_in, RunLeft};
use crate::diagnose::report::outcome::{
    ClassMismatch, Closest, Evidence, Extent, GapFinding, Narrowed, Note, RankWarning, Refused,
    Verdict, VerdictKind, VerdictWarning,
};
use crate::diagnose::report::{
    words, BaseReport, ChannelChange, InSet, Lookalikes, ParameterValue, Part, Shrinkage,
};
use crate::identify::grouping::GroupingReport;
use crate::tyre::Tyre;
use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;

/// The case-specific part of the verdict.
#[derive(Serialize)]
#[serde(untagged)]
enum Details<'a> {
    Explained {
        heldout_error_after: f64,
        reduction_percent: f64,
        partial: bool,
        /// All, most or part of the gap, as the statement says.
        extent: Extent,
        /// The effect parameters on or near their search bound: the
        /// verdict is then no measurement of those effects.
        on_search_bound: Vec<&'a str>,
        warning_details: &'a [VerdictWarning],
        evidence: &'a [Evidence],
        confounded_with: Vec<EffectKind>,
        lookalikes: Option<&'a Lookalikes>,
        in_set: &'a [InSet],
    },
    NoSignificantGap {
        threshold: f64,
        resting_on: &'a [crate::diagnose::model::scale::StatedExcess],
        assumed: &'a [crate::diagnose::report::outcome::AssumedFloor],
        far_from_off: Option<&'a crate::diagnose::report::outcome::FarFromOff>,
    },
    NotIdentifiable {
        no_tyre: &'a [NoTyre],
        threshold_percent: f64,
        closest: &'a [Closest],
        road_friction: Option<&'a StatedFriction>,
        tyre_class: Option<&'a ClassMismatch>,
        narrowed: Option<&'a Narrowed>,
    },
    OutsideLibrary {
        refused: Option<&'a Refused>,
        threshold_percent: f64,
        tyre_class: Option<&'a ClassMismatch>,
        narrowed: Option<&'a Narrowed>,
        bearing: &'a [crate::diagnose::report::outcome::ChannelCause],
        runs_carrying: Option<&'a crate::diagnose::report::outcome::RunsCarrying>,
    },
}

#[derive(Serialize)]
struct VerdictJson<'a> {
    effects: &'a [EffectKind],
    parameters: &'a [ParameterValue],
    statement: String,
    warnings: Vec<String>,
    kind: VerdictKind,
    heldout_error: f64,
    noise_level: f64,
    #[serde(flatten)]
    details: Details<'a>,
}

impl Serialize for Verdict {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let (heldout_error, noise_level, details) = match self {
            Verdict::Explained(e) => (
                e.heldout_error_before,
                e.noise_level,
                Details::Explained {
                    heldout_error_after: e.heldout_error_after,
                    reduction_percent: e.reduction_percent,
                    partial: e.partial(),
                    extent: e.extent(),
                    on_search_bound: words::effect_parameters_on_bound(&e.warnings)
                        .into_iter()
                        .map(|p| p.name.as_str())
                        .collect(),
                    warning_details: &e.warnings,
                    evidence: &e.evidence,
                    confounded_with: e
                        .confounded_with
                        .iter()
                        .flat_map(|l| l.members.iter().filter(|m| m.confounded()))
                        .map(|m| m.effect)
                        .collect(),
                    lookalikes: e.confounded_with.as_ref(),
                    in_set: &e.in_set,
                },
            ),
            Verdict::NoSignificantGap(n) => (
                n.heldout_error,
                n.noise_level,
                Details::NoSignificantGap {
                    threshold: n.threshold,
                    resting_on: &n.resting_on,
                    assumed: &n.assumed,
                    far_from_off: n.far_from_off.as_ref(),
                },
            ),
            Verdict::NotIdentifiable(n) => (
                n.heldout_error,
                n.noise_level,
                Details::NotIdentifiable {
                    no_tyre: &n.no_tyre,
                    threshold_percent: n.threshold_percent,
                    closest: &n.closest,
                    road_friction: n.road_friction.as_ref(),
                    tyre_class: n.tyre_class.as_ref(),
                    narrowed: n.narrowed.as_ref(),
                },
            ),
            Verdict::OutsideLibrary(o) => (
                o.heldout_error,
                o.noise_level,
                Details::OutsideLibrary {
                    refused: o.refused.as_ref(),
                    threshold_percent: o.threshold_percent,
                    tyre_class: o.tyre_class.as_ref(),
                    narrowed: o.narrowed.as_ref(),
                    bearing: &o.bearing,
                    runs_carrying: o.runs_carrying.as_ref(),
                },
            ),
        };
        VerdictJson {
            effects: self.effects(),
            parameters: self.parameters(),
            statement: words::statement(self),
            warnings: words::verdict_warnings(self),
            kind: self.kind(),
            heldout_error,
            noise_level,
            details,
        }
        .serialize(s)
    }
}

/// A ranked candidate's warnings: `warning` (one line, or null) and
/// `warning_details`.
pub(crate) fn rank_warnings<S: Serializer>(w: &[RankWarning], s: S) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(2))?;
    m.serialize_entry("warning", &words::rank_warnings(w))?;
    m.serialize_entry("warning_details", w)?;
    m.end()
}

/// The notes: `notes` (sentences) and `note_details`.
pub(crate) fn notes<S: Serializer>(n: &[Note], s: S) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(2))?;
    let lines: Vec<String> = n.iter().map(words::note).collect();
    m.serialize_entry("notes", &lines)?;
    m.serialize_entry("note_details", n)?;
    m.end()
}

/// Where the gap lies: `summary` (sentences) and `findings`.
pub(crate) fn findings<S: Serializer>(f: &[GapFinding], s: S) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(2))?;
    let lines: Vec<String> = f.iter().map(words::finding).collect();
    m.serialize_entry("summary", &lines)?;
    m.serialize_entry("findings", f)?;
    m.end()
}

/// Confounded effects: `effects` and the `separating_test` their
/// signatures give.
pub(crate) fn confounded<S: Serializer>(e: &[EffectKind], s: S) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(2))?;
    m.serialize_entry("effects", e)?;
    m.serialize_entry("separating_test", &words::signatures(e))?;
    m.end()
}

/// The axles identified from the runs, with `degenerate` (why they are no
/// tyre, in words, or null) beside the typed `no_tyre`.
#[derive(Serialize)]
struct AxlesJson<'a> {
    #[serde(flatten)]
    id: &'a AxleIdentification,
    degenerate: Option<String>,
}

fn axles(id: &AxleIdentification) -> AxlesJson<'_> {
    AxlesJson {
        id,
        degenerate: id.degenerate().then(|| words::no_tyre_list(&id.no_tyre)),
    }
}

#[derive(Serialize)]
struct BaseJson<'a> {
    tyres: String,
    source: &'a TyreSource,
    front: &'a Tyre,
    rear: &'a Tyre,
    rig_grouping: &'a Option<GroupingReport>,
    axles: Option<AxlesJson<'a>>,
}

impl Serialize for BaseReport {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        BaseJson {
            tyres: words::tyre_source(self),
            source: &self.source,
            front: &self.front,
            rear: &self.rear,
            rig_grouping: &self.rig_grouping,
            axles: self.axles.as_ref().map(axles),
        }
        .serialize(s)
    }
}

/// What the verdict's effects did to a part's gap, as `shrinkage[].change`.
#[derive(Serialize)]
#[serde(rename_all = "snake_case")]
enum ChangeKind {
    WithinNoise,
    Unchanged,
    Changed,
    Worsened,
}

#[derive(Serialize)]
struct ShrinkageJson<'a> {
    channel: crate::diagnose::model::channels::Channel,
    part: &'a crate::diagnose::report::Part,
    samples: usize,
    before: f64,
    after: f64,
    noise_floor: f64,
    reduction_percent: Option<f64>,
    change: ChangeKind,
    mean_level: Option<f64>,
    runs: &'a [crate::diagnose::report::RunPart],
    #[serde(skip_serializing_if = "Option::is_none")]
    left_in: Option<&'a [RunLeft]>,
}

/// A part's before and after with the rule the terminal and the page say
/// it by ([`Shrinkage::change`]): within noise, the share of the gap is
/// `null`, since a share of noise (−73 %, −138 %) is no change at all;
/// `unchanged` keeps its share, within the scatter of held-out scores; a
/// worsening from an RMS at or below the floor has none (`null`). An
/// all-samples row carries `left_in` where given: the runs the verdict's
/// effects leave above noise in its channel (empty: none).
fn shrinkage_json<'a>(row: &'a Shrinkage, left_in: Option<&'a [RunLeft]>) -> ShrinkageJson<'a> {
    let (reduction_percent, change) = match row.change() {
        ChannelChange::WithinNoise => (None, ChangeKind::WithinNoise),
        ChannelChange::Unchanged(_) => (Some(row.reduction_percent), ChangeKind::Unchanged),
        ChannelChange::Changed(_) => (Some(row.reduction_percent), ChangeKind::Changed),
        ChannelChange::Worsened(p) => (
            p.is_finite().then_some(row.reduction_percent),
            ChangeKind::Worsened,
        ),
    };
    ShrinkageJson {
        channel: row.channel,
        part: &row.part,
        samples: row.samples,
        before: row.before,
        after: row.after,
        noise_floor: row.noise_floor,
        reduction_percent,
        change,
        mean_level: row.mean_level,
        runs: &row.runs,
        left_in,
    }
}

impl Serialize for Shrinkage {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        shrinkage_json(self, None).serialize(s)
    }
}

/// The held-out table `rows`, each all-samples row with its channel's
/// runs left above noise ([`runs_left_in`]), so that a reader of the
/// table finds them beside the channel's before and after.
pub(crate) fn shrinkage<S: Serializer>(rows: &[Shrinkage], s: S) -> Result<S::Ok, S::Error> {
    let left = runs_left_in(rows);
    let of = |row: &Shrinkage| {
        (row.part == Part::All)
            .then(|| left.iter().find(|c| c.channel == row.channel))
            .flatten()
            .map(|c| c.left.as_slice())
    };
    s.collect_seq(rows.iter().map(|r| shrinkage_json(r, of(r))))
}
