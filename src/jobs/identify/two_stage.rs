//! PAC89's second route: Zhang et al.'s (2021) two-stage identification
//! (each condition's Magic Formula coefficients, then the load and camber
//! laws through them, then a joint polish) run beside the direct swarm
//! fit, and the better of the two written. Where the two-stage result is
//! written, the report's fit is its own. The two are compared free: the
//! direct fit's σ before the parameters the data do not determine were
//! held (`identify/undetermined.rs`), so that the rule does not decide
//! the route; the two-stage result, where written, then has the same rule
//! applied (its undetermined parameters held at the start tyre's values,
//! the rest polished from its optimum). Units: N, rad (PAC89's own inside
//! its model file).

use super::{on_data, Options, SwarmReport};
use crate::error::{Error, FitError};
use crate::identify::data::{Condition, Point};
use crate::identify::pac89_two_stage::{self, TwoStage};
use crate::identify::{
    fit_report_of, hold_undetermined, sigma, Channel, Fit, FitSettings, HeldFor,
};
use crate::tyre::{Pac89, Tyre};
use serde::Serialize;

/// Which of PAC89's two fits was written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Written {
    /// Zhang et al.'s (2021) two-stage identification.
    TwoStage,
    /// The direct swarm fit.
    Direct,
    /// The direct fit again with its lateral curvature held, the fit
    /// chosen of the two having reversed the force
    /// (`curvature_hold.rs`).
    CurvatureHeld,
}

/// Zhang et al.'s (2021) two stages with the overall σ of their result.
#[derive(Debug, Clone, Serialize)]
pub struct TwoStageReport {
    /// The stages.
    #[serde(flatten)]
    pub stages: TwoStage,
    /// σ over all points of the polished result, %.
    pub polished_overall_sigma_percent: f64,
    /// σ over all points of the direct fit, %, free (before the
    /// parameters the data do not determine were held): where the
    /// two-stage result is written, the report's `sigma_percent`, curves
    /// and parameters are its own, and this is the direct fit's it was
    /// chosen over.
    pub direct_sigma_percent: f64,
}

/// The direct fit (`direct`) and, when `asks`, Zhang et al.'s (2021) two
/// stages on `conditions`, side by side: neither reads the other, and the
/// direct fit's polish leaves a core idle while it factors its Jacobian
/// (serial in the `levenberg-marquardt` crate), which the stages fill.
/// Each is computed as it would be alone, so the results do not depend on
/// the overlap. The stages hold what the data's one camber level cannot
/// fit at `start`'s values, as the direct fit does: one value for one
/// hold, whichever fit is written.
pub(super) fn beside_direct<F>(
    asks: bool,
    (start, conditions): (&Tyre, &[Condition]),
    settings: &FitSettings,
    direct: F,
) -> (Result<Fit, Error>, Option<Result<TwoStage, FitError>>)
where
    F: FnOnce() -> Result<Fit, Error> + Send,
{
    let start = match start {
        Tyre::Pac89(p) => p.a,
        _ => Pac89::adams_example().a,
    };
    rayon::join(direct, || {
        asks.then(|| pac89_two_stage::identify(conditions, settings, &start))
    })
}

/// PAC89: Zhang et al.'s (2021) two-stage identification (`stages`, from
/// [`beside_direct`]) beside the direct fit; the better of the two becomes
/// the tyre, its undetermined parameters held at `start`'s values (module
/// notes).
pub(super) fn two_stage(
    o: &Options,
    r: &mut SwarmReport,
    start: &Tyre,
    settings: &FitSettings,
    stages: Result<TwoStage, FitError>,
) -> Result<(), Error> {
    let stages = stages.map_err(|e| on_data(o, None)(e.into()))?;
    let all: Vec<Point> = r
        .conditions
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .collect();
    let tyre = Tyre::Pac89(Pac89 {
        a: stages.polished,
        b: None,
        c: None,
        ..Pac89::adams_example()
    });
    let (s, _) = sigma(&tyre, &all);
    let direct_sigma_percent = r.fit.free_sigma_percent.unwrap_or(r.fit.sigma_percent);
    let written = if s < direct_sigma_percent {
        // The report says what the file holds: the two-stage result's
        // parameters, standard errors and curves. Compared free, reported
        // free: what the direct fit held because it left it undetermined
        // is the two-stage result's own to fit (its value, not the direct
        // fit's hold, is in the file), and the rule then holds what this
        // result leaves undetermined.
        let fit = fit_report_of(
            tyre,
            Channel::LateralForce,
            &r.conditions,
            &undetermined_freed(&r.fit),
        );
        r.fit = hold_undetermined(fit, start, &r.conditions, settings);
        r.tyre = r.fit.tyre.clone();
        Written::TwoStage
    } else {
        Written::Direct
    };
    r.written = Some(written);
    r.two_stage = Some(TwoStageReport {
        stages,
        polished_overall_sigma_percent: s,
        direct_sigma_percent,
    });
    Ok(())
}

/// `fit` with the parameters it held because it left them undetermined
/// freed again (their hold records and warnings dropped); the others held
/// as they were (a camber term without camber levels).
fn undetermined_freed(fit: &Fit) -> Fit {
    let mut free = fit.clone();
    for p in &mut free.parameters {
        if matches!(p.held, Some(HeldFor::Undetermined { .. })) {
            p.free = true;
            p.held = None;
            p.warning = None;
        }
    }
    free
}
