//! Parameters a stage does not fit, and the value each is held at.
//!
//! A parameter is held, never left where an optimiser wandered, when
//! - its term needs more load, camber or pressure levels than the rows
//!   have (`params.rs`), or it is held by design (`QBZ9`, `QSY3`, `QSY4`);
//! - the user gives its value (`identify --hold NAME=VALUE`): held at it
//!   in every stage;
//! - the data do not determine it. The rule, applied after each stage's fit
//!   (data and template starts; the paper's own scheme is left as the
//!   paper has it): a free parameter is *not identifiable* when its
//!   standard error reaches its magnitude and one standard error, alone,
//!   moves the stage's channel by at least 1 % of its RMS, or when the
//!   data do not move it at all (`stages.rs`, `identifiability`). Of the
//!   parameters so flagged (the four with the largest relative standard
//!   error), the one whose hold raises the stage's cost least is held at
//!   its stated value (of holds whose costs differ by less than half a
//!   residual variance, which the data cannot tell apart, the coefficient
//!   latest in the stage's order) and the stage refitted from its
//!   optimum; this
//!   repeats until no free parameter is flagged. Two parameters that trade
//!   along one near-null direction (`PKY1` and `PKY4` along the curvature
//!   of `Kyα(Fz)` on loads that never reach its peak; `QBZ4·γ` and
//!   `QBZ5·|γ|` on cambers of one sign, where they are one function) thus
//!   lose the one the fit can best spare, and the other is determined
//!   again. A hold whose refit raises the stage's cost past the guard of
//!   `spare.rs` (about 2.5 residual variances, or σ rising by 5 % of
//!   itself, whichever is larger) is refused and the coefficient left
//!   free with its warning: the standard error judges the trade-off as
//!   linear, and where it is not, a hold the data reject would be kept
//!   (`RVY1` and `RVY6` on MFeval's own MF 6.1 grid, noise-free, held at
//!   one standard error took combined Fy's σ from 0.064 % to 0.911 %). The trying and choosing is the swarm fit's code too
//!   (`identify/spare.rs`, with this tie rule as its parameter; the rounds
//!   are `hold_rounds.rs`, and a refused hold is said with what it cost
//!   by `hold_refusal.rs`). A stated
//!   value more than two standard errors from the fitted one is said, on
//!   its held line, to be one the data lean against, with `--hold` to
//!   choose another.
//!
//! The stated value of a parameter held by the rule: the template's, when
//! a template file gives the key; else the default of Pacejka (2012),
//! *Tire and Vehicle Dynamics*, 3rd ed., as MFeval 4.0 distributes it
//! (`PacejkaBook_Defaults.tir`, MF 6.1, ISO-W signs of a left tyre, SI): the
//! secondary terms (camber, pressure, load variations) at 0, the
//! primary ones at a passenger tyre's values.

use super::book_defaults::pacejka_book_default;
use super::curvature_clip::AtClip;
use super::params::{Need, HELD};
use crate::format::{exact, readable};
use crate::identify::determined::ABSURD_EFFECT_PERCENT;
use crate::identify::spare::{held_at, held_at_tried, lean_clause};
use serde::Serialize;
use std::fmt;

/// Where the value of a held parameter comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum HoldSource {
    /// Given by the user (`--hold NAME=VALUE`).
    Given,
    /// The template file's value.
    Template,
    /// Pacejka's (2012) book default (module notes).
    PacejkaBook,
    /// The coefficient's value before the stage: the template's or its
    /// version default (a parameter held for want of levels).
    Unchanged,
}

impl fmt::Display for HoldSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            HoldSource::Given => "given with --hold",
            HoldSource::Template => "template's value",
            HoldSource::PacejkaBook => "Pacejka 2012 book default",
            HoldSource::Unchanged => "its value before the stage",
        })
    }
}

/// Why a stage's parameter is held, not fitted.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "why", rename_all = "kebab-case")]
pub enum HoldReason {
    /// Its term needs more levels than the rows have: (needed, present)
    /// for loads, cambers and pressures.
    Levels {
        /// Levels needed: load, camber, pressure.
        need: [u8; 3],
        /// Levels in the stage's rows.
        have: [usize; 3],
    },
    /// Never fitted (the module notes of `mf_staged` say why).
    ByDesign {
        /// Why this coefficient.
        design: DesignHold,
    },
    /// The user gave its value.
    Given,
    /// Fitted first, and not determined by the data (module notes).
    NotIdentifiable {
        /// Where it stood when it was flagged.
        fitted: f64,
        /// Its standard error there (`None`: the data do not move it).
        std_error: Option<f64>,
        /// One standard error's effect on the stage's channel, % of its RMS
        /// (`null` at a bound, where it means nothing).
        #[serde(serialize_with = "crate::report::finite_or_null")]
        effect_percent: f64,
        /// Where its stated value comes from.
        source: HoldSource,
        /// Its stated value (the template's or the book's).
        stated: f64,
        /// The value held: `stated`, or the end of `fitted ± 2` standard
        /// errors nearest it where `stated` lies beyond (`spare.rs`).
        held_at: f64,
        /// How many standard errors `stated` lies from `fitted` (`None`
        /// without a standard error).
        standard_errors_away: Option<f64>,
        /// The bound of its physical box `fitted` stood at, and the box
        /// (`None`: inside it). There the data push it beyond, and its
        /// standard error and effect, taken as if the box were not there,
        /// mean nothing (PKY4 at 0.1001 of 0.1..5 on the Hoosier file was
        /// said to move the fit by 723 %).
        at_bound: Option<(f64, (f64, f64))>,
        /// The stage's σ (%) with it held and the rest refitted, and
        /// fitted free just before (`None`: not measured).
        sigma_held_free: Option<[f64; 2]>,
        /// Which of the stage's holds for want of data it was, in the
        /// order they were made, and how many there were: the last one's
        /// σ held is the σ the stage's own fit ended at (`None`: not
        /// counted, the paper's scheme).
        hold_order: Option<[usize; 2]>,
    },
    /// Its curvature factor reaches the Magic Formula's clip at 1 over
    /// every row it shapes, where the force does not depend on it: held
    /// where the fit left it (`curvature_clip.rs`), not for want of data.
    AtCurvatureClip {
        /// Where the fit left it, and it is held.
        fitted: f64,
        /// The factor, and where it reaches 1.
        clip: AtClip,
    },
}

/// The σ of a hold's round, held against free, with the digits that tell
/// them apart (`fixed_apart`; two that agree to a millionth of
/// themselves print alike, as the hold then costs nothing), and which of
/// the stage's holds it was (`order`): the round's σ is not the stage's
/// (a later hold, or a later stage, moves that; the stage's line says
/// how), and "σ 1.245514 % held against 1.245514 % free" beside the
/// stage's "σ 1.689 %" read as two measures of one fit.
fn held_free([held, free]: [f64; 2], order: Option<[usize; 2]>) -> String {
    let shown = if (held - free).abs() <= 1e-6 * free.abs() {
        let same = format!("{held:.3}");
        [same.clone(), same]
    } else {
        let v = crate::format::fixed_apart(&[held, free], 3);
        [v[0].clone(), v[1].clone()]
    };
    let round = order.map_or(String::new(), |[k, n]| {
        format!(" (in the round of the stage's hold {k} of {n}, in the order they were made)")
    });
    format!(
        "; σ {} % held against {} % free{round}{}",
        shown[0],
        shown[1],
        held_below_free(held, free)
    )
}

/// What a hold that lowered the stage's σ says of the fit before it: a
/// fit with one coefficient fewer free cannot end below one that reached
/// its optimum, so the free fit had stopped short (a local minimum, or
/// its iteration cap). Measured on MFeval's grid: QSX6 held, σ 0.355 %
/// against 0.404 % free, unsaid.
fn held_below_free(held: f64, free: f64) -> &'static str {
    if held < free - 1e-6 * free.abs() {
        ": lower held than free, so the fit with it free had stopped short of its optimum (a local minimum, or its iteration cap); the held fit, the better, is kept"
    } else {
        ""
    }
}

/// The bound of `(lo, hi)` that `v` stands at, within 1e-3 of the box's
/// width: a fit that ends there was stopped by it (the projected step
/// creeps towards a bound it presses on, so a strict test would miss it).
pub(super) fn near_bound(v: f64, (lo, hi): (f64, f64)) -> Option<(f64, (f64, f64))> {
    let width = hi - lo;
    [lo, hi]
        .into_iter()
        .find(|b| width.is_finite() && (v - b).abs() <= 1e-3 * width)
        .map(|b| (b, (lo, hi)))
}

impl HoldReason {
    /// The reason as the held line of coefficient `name` says it: its
    /// words, and for a value held off its stated one, the option that
    /// holds it where the user says (`spare.rs`).
    pub fn said(&self, name: &str) -> String {
        match self {
            HoldReason::NotIdentifiable {
                stated,
                held_at,
                standard_errors_away,
                sigma_held_free,
                hold_order,
                ..
            } => format!(
                "{self}{}{}",
                lean_clause(name, *stated, *held_at, *standard_errors_away),
                sigma_held_free.map_or(String::new(), |s| held_free(s, *hold_order))
            ),
            _ => self.to_string(),
        }
    }
}

impl fmt::Display for HoldReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HoldReason::NotIdentifiable {
                fitted,
                source,
                stated,
                held_at: held,
                at_bound: Some((bound, (lo, hi))),
                ..
            } => write!(
                f,
                "{}: {}",
                stopped_at_bound(*bound, (*lo, *hi), *fitted),
                held_at(&format!("the {source}"), *stated, *held, None)
            ),
            HoldReason::Levels { need, have } => f.write_str(&lacking_levels(need, have)),
            HoldReason::ByDesign { design } => f.write_str(design.why()),
            HoldReason::Given => f.write_str("given with --hold"),
            HoldReason::AtCurvatureClip { clip, .. } => f.write_str(&clip.said()),
            HoldReason::NotIdentifiable {
                fitted,
                std_error: Some(_),
                effect_percent,
                source,
                stated,
                held_at: held,
                ..
            } if undetermined_at_all(*effect_percent) => write!(
                f,
                "not identifiable from these data when fitted: not determined at all (it stood at {}, and its standard error reaches beyond any value it could take, one of them alone moving the fit by more than {} times the channel's RMS, which the other parameters' trade-off undoes): {}",
                readable(*fitted, 5),
                ABSURD_EFFECT_PERCENT / 100.0,
                held_at(&format!("the {source}"), *stated, *held, None)
            ),
            HoldReason::NotIdentifiable {
                fitted,
                std_error: Some(se),
                effect_percent,
                source,
                stated,
                held_at: held,
                standard_errors_away,
                ..
            } => write!(
                f,
                "not identifiable from these data when fitted ({} ± {}; one \
                 standard error of it alone moves the fit by {effect_percent:.1} % of the \
                 channel's RMS, which the other parameters' trade-off undoes): {}",
                readable(*fitted, 5),
                readable(*se, 4),
                held_at_tried(
                    &format!("the {source}"),
                    *stated,
                    *held,
                    *standard_errors_away
                )
            ),
            HoldReason::NotIdentifiable {
                fitted,
                source,
                stated,
                held_at: held,
                ..
            } => write!(
                f,
                "the data do not move it (it stood at {}): {}",
                readable(*fitted, 5),
                held_at(&format!("the {source}"), *stated, *held, None)
            ),
        }
    }
}

/// Why a parameter stopped at `bound` of its physical box `(lo, hi)` when
/// fitted to `fitted` has no value from the data: the sentence before the
/// value it is held at.
fn stopped_at_bound(bound: f64, (lo, hi): (f64, f64), fitted: f64) -> String {
    format!(
        "stopped at its {} bound {} when fitted ({}; its physical box {} to {}): the best fit to these data lies outside the physical box, so they give it no physical value, and a standard error taken at the bound means nothing",
        if bound == lo { "lower" } else { "upper" },
        exact(bound),
        readable(fitted, 5),
        exact(lo),
        exact(hi),
    )
}

/// The levels a term needs and the rows lack: for each of load, camber
/// and pressure whose `need` exceeds what the rows `have`, both counts.
fn lacking_levels(need: &[u8; 3], have: &[usize; 3]) -> String {
    let why: Vec<String> = need
        .iter()
        .zip(have)
        .zip(["load", "camber", "pressure"])
        .filter(|((want, have), _)| usize::from(**want) > **have)
        .map(|((want, have), what)| format!("needs {want} {what} levels, the data have {have}"))
        .collect();
    why.join(", ")
}

/// Whether the standard error of a parameter, whose effect on the fit is
/// `effect_percent`, is beyond any meaning: past
/// [`ABSURD_EFFECT_PERCENT`].
fn undetermined_at_all(effect_percent: f64) -> bool {
    effect_percent >= ABSURD_EFFECT_PERCENT
}

/// Why a coefficient no stage fits is held: each said for its own
/// coefficients, where the user reads it (one sentence for both once put
/// each coefficient's line beside the other's reason).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DesignHold {
    /// `QBZ9`.
    ResidualTorqueConstant,
    /// `QSY3`, `QSY4`.
    RollingResistanceSpeed,
}

impl DesignHold {
    /// The design hold of coefficient `name` (one the table marks held).
    fn of(name: &str) -> Self {
        match name {
            "QBZ9" => DesignHold::ResidualTorqueConstant,
            _ => DesignHold::RollingResistanceSpeed,
        }
    }

    /// The words.
    fn why(self) -> &'static str {
        match self {
            DesignHold::ResidualTorqueConstant => "held by design: no stage fits it (a second constant beside QBZ10·By·Cy in the residual torque's slope, which rig data barely separate)",
            DesignHold::RollingResistanceSpeed => "held by design: no stage fits them (the rolling resistance's speed terms, which a rig at one speed does not determine)",
        }
    }
}

/// Why parameter `name`, needing `need` levels, cannot be fitted with
/// `have`.
pub(super) fn held_reason(name: &str, need: Need, have: [usize; 3]) -> Option<HoldReason> {
    if need == HELD {
        return Some(HoldReason::ByDesign {
            design: DesignHold::of(name),
        });
    }
    let want = [need.loads, need.cambers, need.pressures];
    want.iter()
        .zip(have)
        .any(|(w, h)| usize::from(*w) > h)
        .then_some(HoldReason::Levels { need: want, have })
}

/// What the user and the template say about held values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Holding {
    /// Coefficients held at a value the user gives, in every stage.
    pub given: Vec<(String, f64)>,
    /// The coefficient keys the template file gives (their values are
    /// the template tyre's).
    pub template_keys: Vec<String>,
}

impl Holding {
    /// The value the user gives for `name`, if any.
    pub(super) fn given(&self, name: &str) -> Option<f64> {
        self.given.iter().find(|(k, _)| k == name).map(|e| e.1)
    }

    /// The stated value a parameter not determined by the data is held at
    /// and its source: the template's (`template_value`) when the template
    /// file gives the key, else Pacejka's book default.
    pub(super) fn stated(&self, name: &str, template_value: Option<f64>) -> (f64, HoldSource) {
        match template_value {
            Some(v) if self.template_keys.iter().any(|k| k == name) => (v, HoldSource::Template),
            _ => (
                pacejka_book_default(name).unwrap_or(0.0),
                HoldSource::PacejkaBook,
            ),
        }
    }
}

#[cfg(test)]
#[path = "holds_tests.rs"]
mod tests;
