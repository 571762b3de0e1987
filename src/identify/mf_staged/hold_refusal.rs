//! A hold the guard refused (`hold_guard.rs`, `identify/spare.rs`): a
//! coefficient the data do not determine was held at its stated value
//! (the template's, or Pacejka's (2012) book default), or at the end of
//! the free fit's ±2 standard errors nearest it, the rest refitted, and
//! the refit raised the stage's σ past what a hold may cost. The
//! coefficient stays free with its warning ("not identifiable", or, where
//! the value tried lay within its linearised ±2 standard errors, fixed by
//! the data beyond that linearisation: `determination.rs`); this says
//! why it was not held: the value tried and where it comes from, the σ
//! free and held (%, of the channel's RMS) against the σ the guard
//! allows, which of the guard's two limits set it, and what the user can
//! do (`--hold NAME=VALUE` with a value they know, or data of the kind
//! that determines it). Typed, carried to the report (JSON) as it is, and
//! said in one place ([`RefusedHold::said`]), which the terminal and the
//! written file's header print.
//!
//! σ of a refit: the stage's σ is `sqrt(Σe²/ΣF²)`, so a refit of cost
//! `½Σe²` = `c` from a free fit of cost `c₀` has σ·sqrt(c/c₀); the guard's
//! allowance `g` (`spare::guard`) gives the most σ·sqrt((c₀+g)/c₀).

use super::holds::HoldSource;
use super::params::Need;
use super::problem::StageProblem;
use super::Stage;
use crate::format::exact;
use crate::identify::spare::{
    held_at, standard_errors_away, z_text, Refusal, GUARD_STANDARD_ERRORS, LEAN_STANDARD_ERRORS,
    SIGMA_RISE,
};
use crate::optim::local::Residuals;
use serde::Serialize;

/// Which of the guard's two limits (`spare::guard`, the larger) a
/// refused hold went past.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum GuardLimit {
    /// σ rising by [`SIGMA_RISE`] of itself (the larger on a rig file's
    /// many points, whose residuals are the model form's error).
    SigmaRise,
    /// The cost of one coefficient held [`GUARD_STANDARD_ERRORS`]
    /// standard errors from its optimum, to first order (`½·z²·s²`).
    StandardErrors,
}

/// The data that would determine a coefficient: the levels its term
/// varies over (`params.rs`), or, for a term every level has, more of
/// its stage's slip and loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum MoreData {
    /// More load levels (a load variation).
    Loads,
    /// More camber levels (a camber term).
    Cambers,
    /// More pressure levels (a pressure term).
    Pressures,
    /// A wider range of the stage's slip and loads.
    SlipAndLoads,
}

/// A hold the guard refused (module notes).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RefusedHold {
    /// Where the stated value comes from.
    pub source: HoldSource,
    /// The stated value.
    pub stated: f64,
    /// The value tried: `stated`, or the end of the free fit's ±2
    /// standard errors nearest it.
    pub tried_at: f64,
    /// How many standard errors `stated` lay from the free fit (`None`
    /// without a standard error).
    pub standard_errors_away: Option<f64>,
    /// The stage's σ (%) free, when the hold was tried.
    pub sigma_free_percent: f64,
    /// The stage's σ (%) with it held and the rest refitted (the better
    /// of the refit from the optimum and the stage's own fit).
    pub sigma_held_percent: f64,
    /// The most σ (%) a hold may reach and be kept.
    pub sigma_limit_percent: f64,
    /// Which limit set it.
    pub limit: GuardLimit,
    /// What data would determine the coefficient.
    pub more_data: Vec<MoreData>,
}

/// The refusal `r` of the `fit` (its `problem` at `p`) as the report
/// carries it: the coefficient's stated value and source (`stated`), its
/// standard error there (`se`, `None` at a bound) and the levels its
/// term needs (`need`).
pub(super) fn refused_hold(
    (problem, p): (&StageProblem, &[f64]),
    r: &Refusal,
    (stated, source): (f64, HoldSource),
    se: Option<f64>,
    need: Need,
) -> RefusedHold {
    let base = problem.cost(p);
    let dof = problem.count().saturating_sub(p.len()).max(1) as f64;
    let sigma = problem.sigma_percent(p);
    // σ scales with the square root of the cost (module notes).
    let scaled = |cost: f64| match base > 0.0 {
        true => sigma * (cost / base).sqrt(),
        false => 0.0,
    };
    let (sigma_limit_percent, limit) = sigma_limit(sigma, dof);
    RefusedHold {
        source,
        stated,
        tried_at: r.value,
        standard_errors_away: standard_errors_away(stated, p[r.k], se),
        sigma_free_percent: sigma,
        sigma_held_percent: scaled(r.cost),
        sigma_limit_percent,
        limit,
        more_data: more_data(need),
    }
}

/// The most σ (%) a hold may reach from a free fit at σ `sigma` (%) with
/// `dof` residual degrees of freedom, and which of the guard's two limits
/// (`spare::guard`) sets it: the cost `c₀` may grow by `½·2.25²·s²` =
/// `c₀·2.25²/dof` (`s² = 2c₀/dof`) or by σ rising 5 %, the larger, and σ
/// goes as `sqrt(c)` (module notes). One rule for the staged fit's holds
/// and a linear fit's trail given with `--hold`
/// (`jobs/identify/linear_window.rs`).
pub(crate) fn sigma_limit(sigma: f64, dof: f64) -> (f64, GuardLimit) {
    let statistical = GUARD_STANDARD_ERRORS * GUARD_STANDARD_ERRORS / dof.max(1.0);
    let rise = (1.0 + SIGMA_RISE).powi(2) - 1.0;
    let limit = match statistical > rise {
        true => GuardLimit::StandardErrors,
        false => GuardLimit::SigmaRise,
    };
    (sigma * (1.0 + statistical.max(rise)).sqrt(), limit)
}

/// The data that would determine a term needing `need` levels: each of
/// load, camber, pressure it varies over (needs more than one level of),
/// else its stage's slip and loads.
fn more_data(need: Need) -> Vec<MoreData> {
    let kinds: Vec<MoreData> = [
        (need.loads, MoreData::Loads),
        (need.cambers, MoreData::Cambers),
        (need.pressures, MoreData::Pressures),
    ]
    .into_iter()
    .filter(|(levels, _)| *levels > 1)
    .map(|(_, kind)| kind)
    .collect();
    match kinds.is_empty() {
        true => vec![MoreData::SlipAndLoads],
        false => kinds,
    }
}

impl MoreData {
    /// The words, after "data with".
    fn words(self, stage: Stage) -> String {
        match self {
            MoreData::Loads => "more load levels".into(),
            MoreData::Cambers => "more camber levels".into(),
            MoreData::Pressures => "more pressure levels".into(),
            MoreData::SlipAndLoads => format!(
                "a wider range of {} and loads",
                match stage {
                    Stage::PureFx | Stage::CombinedFx => "slip ratio",
                    Stage::PureFy | Stage::PureMz => "slip angle",
                    _ => "slip",
                }
            ),
        }
    }
}

impl GuardLimit {
    /// The limit in words.
    pub(crate) fn words(self) -> String {
        match self {
            GuardLimit::SigmaRise => format!(
                "σ rising by {:.0} % of itself, the larger of the guard's two limits here",
                100.0 * SIGMA_RISE
            ),
            GuardLimit::StandardErrors => format!(
                "the cost of a coefficient held {GUARD_STANDARD_ERRORS} standard errors from its fit, the larger of the guard's two limits here"
            ),
        }
    }
}

impl RefusedHold {
    /// The refusal as coefficient `name`'s line says it, in `stage`.
    pub fn said(&self, name: &str, stage: Stage) -> String {
        let more: Vec<String> = self.more_data.iter().map(|m| m.words(stage)).collect();
        let rose = format!(
            "the rest refitted, σ rose from {:.3} % to {:.3} %, past the {:.3} % a hold may reach ({})",
            self.sigma_free_percent,
            self.sigma_held_percent,
            self.sigma_limit_percent,
            self.limit.words(),
        );
        let source = format!("the {}", self.source);
        match self.standard_errors_away {
            // Tried at the stated value and refused by the refit. Within
            // the free fit's ±2 by its linearisation, the standard error
            // (the cost's curvature at the free fit) understates how well
            // the data fix it, as the coefficient's own words say before
            // these (`determination.rs`); past it, the data reject it.
            // Either way no more data are asked for, and nothing is
            // "allowed".
            Some(z) if self.tried_at == self.stated => {
                let side = match z <= LEAN_STANDARD_ERRORS {
                    true => " by its linearisation",
                    false => ", outside its linearised ±2",
                };
                format!(
                    "a hold was tried and refused: held at {source} {}, {} standard errors from the free fit{side}, {rose}, so it is left free where the fit put it; to hold it, give --hold {name}=VALUE with a value you know",
                    exact(self.stated),
                    z_text(z)
                )
            }
            // Tried at the edge of the ±2 and refused: the data fix it
            // more tightly than that (`determination.rs`), and more data
            // are not what it lacks.
            _ => format!(
                "a hold was tried and refused: {}, {rose}, so it is left free where the fit put it; to hold it, give --hold {name}=VALUE with a value you know{}",
                held_at(&source, self.stated, self.tried_at, self.standard_errors_away),
                match self.within_linearisation() {
                    true => String::new(),
                    false => format!(", or fit data with {}, which determine it", more.join(" and ")),
                }
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(limit: GuardLimit, tried_at: f64) -> RefusedHold {
        RefusedHold {
            source: HoldSource::Template,
            stated: -8000.0,
            tried_at,
            standard_errors_away: Some(0.5),
            sigma_free_percent: 1.683,
            sigma_held_percent: 1.912,
            sigma_limit_percent: 1.767,
            limit,
            more_data: vec![MoreData::Loads, MoreData::Cambers],
        }
    }

    /// The words name the value tried and its source, σ free, held and
    /// allowed, the limit, and the option with the data that would do.
    #[test]
    fn a_refused_hold_says_what_was_tried_what_it_cost_and_what_to_do() {
        let w = refused(GuardLimit::SigmaRise, -8000.0).said("PKY1", Stage::PureFy);
        assert_eq!(
            w,
            "a hold was tried and refused: held at the template's value -8000, 0.5 standard errors from the free fit by its linearisation, the rest refitted, σ rose from 1.683 % to 1.912 %, past the 1.767 % a hold may reach (σ rising by 5 % of itself, the larger of the guard's two limits here), so it is left free where the fit put it; to hold it, give --hold PKY1=VALUE with a value you know"
        );
        // Past the ±2 and tried there: rejected, nothing "allowed".
        let mut far = refused(GuardLimit::SigmaRise, -8000.0);
        far.standard_errors_away = Some(3.5);
        let w = far.said("PKY1", Stage::PureFy);
        assert!(w.contains("held at the template's value -8000, 3.5 standard errors from the free fit, outside its linearised ±2, the rest refitted"), "{w}");
        assert!(
            !w.contains("allow") && !w.contains("fix it more tightly"),
            "{w}"
        );
        let w = refused(GuardLimit::StandardErrors, -7000.0).said("PKY1", Stage::PureFy);
        assert!(w.contains("held at -7000, the end of the free fit's ±2 standard errors nearest the template's value -8000"), "{w}");
        assert!(w.contains("held 2.25 standard errors from its fit"), "{w}");
    }

    /// A term of every level asks for more of its stage's slip and loads;
    /// one varying with load and camber for more of both.
    #[test]
    fn the_data_asked_for_are_the_levels_the_term_varies_over() {
        let any = Need {
            loads: 1,
            cambers: 1,
            pressures: 1,
        };
        assert_eq!(more_data(any), vec![MoreData::SlipAndLoads]);
        assert_eq!(
            MoreData::SlipAndLoads.words(Stage::PureFx),
            "a wider range of slip ratio and loads"
        );
        let lc = Need {
            loads: 2,
            cambers: 3,
            pressures: 1,
        };
        assert_eq!(more_data(lc), vec![MoreData::Loads, MoreData::Cambers]);
    }

    /// On many points σ rising 5 % sets the limit; on few, 2.25 standard
    /// errors' worth: 17 points less one parameter allow
    /// sqrt(1 + 2.25²/16) = 1.14735 times σ.
    #[test]
    fn the_limit_is_the_larger_of_the_guards_two() {
        let (most, limit) = sigma_limit(10.0, 5000.0);
        assert!((most - 10.5).abs() < 1e-12, "{most}");
        assert_eq!(limit, GuardLimit::SigmaRise);
        let (most, limit) = sigma_limit(10.0, 16.0);
        assert!((most - 10.0 * (1.0 + 2.25f64.powi(2) / 16.0).sqrt()).abs() < 1e-12);
        assert!((most - 11.4735).abs() < 1e-4, "{most}");
        assert_eq!(limit, GuardLimit::StandardErrors);
    }
}
