//! PAC89's lateral curvature held at its limit where the free fit's would
//! reverse the force. `E = a6·Fz + a7` (Fz in kN, Adams numbering;
//! Bakker, Pacejka and Lidner 1989) above 1 makes the lateral force fall
//! through zero past its peak (`curvature.rs`), and PAC89 has no limit
//! check to clip it as the Magic Formula 5.2/6.x files do: a file that
//! fits rig data to 10° can turn a simulated spin's tyre force around at
//! 40°. So, unless the user holds `a6` or `a7`, a fit whose `E` exceeds 1
//! over the fitted loads is fitted again with `E` constant (`a6 = 0`, `a7`
//! fitted), and, where that constant still exceeds 1, at the limit itself
//! (`a7 = 1`). A box on each coefficient cannot express `E ≤ 1` over a
//! load range (a linear constraint on both); a constant `E` is its
//! simplest feasible form and, on the Hoosier rig file, costs 0.007
//! points of σ. Both σ are reported: the user who wants the free fit
//! holds `a7` at a value of their own.
//!
//! The rule that holds what the data do not determine
//! (`identify/undetermined.rs`) runs inside each fit: the fit checked here
//! is the one written, its undetermined parameters held; the refit from
//! the start carries `a6` (and `a7`) as values given, never free, so the
//! rule cannot hold them too, and holds what the refit leaves
//! undetermined (on the Hoosier file, `a1` and `a2` of the friction's load
//! law).

use super::curvature::{pac89_reversal, Pac89Reversal};
use super::{on_data, ranges, Options, SwarmReport, Written};
use crate::error::Error;
use crate::format::readable;
use crate::identify::{fit_channel_holding, Channel, FitSettings, HeldFor};
use crate::tyre::Tyre;
use serde::Serialize;

/// The curvature held, and what the free fit was.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurvatureHeld {
    /// Where the free fit's lateral force reversed.
    pub free: Pac89Reversal,
    /// σ of the free fit, %.
    pub free_sigma_percent: f64,
    /// σ with the curvature held, %.
    pub sigma_percent: f64,
    /// The coefficients held (`a6`, and `a7` where a constant `E` fitted
    /// above 1 too) with their values.
    pub held: Vec<(String, f64)>,
    /// `E` with them held (constant over the loads).
    pub curvature: f64,
}

impl CurvatureHeld {
    /// The note, one line.
    pub fn line(&self) -> String {
        let held: Vec<String> = self
            .held
            .iter()
            .map(|(k, v)| format!("{k} = {}", readable(*v, 4)))
            .collect();
        format!(
            "lateral curvature held at E = {} over every load ({}): fitted free, E = a6·Fz + a7 reached {} at fz {} N, and PAC89, which has no limit check, then turns the lateral force around beyond |alpha| = {}° (the data reach {}°); σ {} % held against {} % free (to keep a curvature above 1, hold a7 at a value of your own with --hold)",
            readable(self.curvature, 4),
            held.join(", "),
            readable(self.free.largest, 3),
            readable(self.free.fz, 4),
            readable(self.free.reverses_beyond.to_degrees(), 3),
            readable(self.free.data_alpha.to_degrees(), 3),
            readable(self.sigma_percent, 4),
            readable(self.free_sigma_percent, 4),
        )
    }
}

/// Whether `t` is a PAC89 whose lateral force reverses over `spans`.
fn reversal(t: &Tyre, spans: &[ranges::Span]) -> Option<Pac89Reversal> {
    match t {
        Tyre::Pac89(p) => pac89_reversal(p, spans),
        _ => None,
    }
}

/// Refits `r`'s lateral force from `start` with its curvature held (module
/// notes) where the fit written reverses, unless `o` holds `a6` or `a7`;
/// records it in `r.curvature_held`.
pub(super) fn hold_curvature(
    o: &Options,
    r: &mut SwarmReport,
    start: &Tyre,
    settings: &FitSettings,
) -> Result<(), Error> {
    let given = o.hold.iter().any(|(k, _)| k == "a6" || k == "a7");
    if r.fit.channel != Channel::LateralForce || given {
        return Ok(());
    }
    let spans = ranges::fitted_spans(r);
    let Some(free) = reversal(&r.tyre, &spans) else {
        return Ok(());
    };
    let refit = |holds: &[(String, f64)]| {
        fit_channel_holding(start, Channel::LateralForce, &r.conditions, settings, holds)
            .map_err(on_data(o, None))
    };
    let mut holds = o.hold.clone();
    holds.push(("a6".into(), 0.0));
    let mut fit = refit(&holds)?;
    if reversal(&fit.tyre, &spans).is_some() {
        holds.push(("a7".into(), 1.0));
        fit = refit(&holds)?;
    }
    let ours = &holds[o.hold.len()..];
    for p in fit.parameters.iter_mut() {
        // Those this rule held, not one the undetermined rule held.
        if !p.free && ours.iter().any(|(k, _)| *k == p.name) {
            // Said by the note, not as a value given.
            p.held = Some(HeldFor::CurvatureLimit);
            p.warning = None;
        }
    }
    let value = |k: &str| fit.parameters.iter().find(|p| p.name == k).map(|p| p.value);
    let curvature = value("a7").unwrap_or(f64::NAN);
    r.curvature_held = Some(CurvatureHeld {
        free,
        free_sigma_percent: r.fit.sigma_percent,
        sigma_percent: fit.sigma_percent,
        held: ours
            .iter()
            .map(|(k, _)| (k.clone(), value(k).unwrap_or(f64::NAN)))
            .collect(),
        curvature,
    });
    // Where the two routes ran, the one chosen reversed: the file is now
    // the direct fit with the curvature held.
    if r.written.is_some() {
        r.written = Some(Written::CurvatureHeld);
    }
    r.tyre = fit.tyre.clone();
    r.fit = fit;
    Ok(())
}
