//! The window a linear tyre is fitted in. A straight line through
//! saturated data is a secant, not the tyre's cornering stiffness (15.6
//! kN/rad through every row of one load of the Hoosier file against 33.8
//! kN/rad through those with |α| ≤ 2°, 37.6 kN/rad within 1°), so `--model linear` fits only the points of small slip angle,
//! |α| ≤ [`WINDOW_DEG`] — a rule of this program, chosen as the range
//! where a passenger-car or racing tyre's lateral force stays close to
//! its slope at zero slip — and says how many points it left out. Its
//! pneumatic trail is fitted in the same window when the data have `mz`
//! (`t_p` = the ratio of the slopes of Mz and Fy on α, as
//! [`crate::tyre::Linear`] writes `Mz = t_p·Fy`), or said held at 0.

use crate::identify::data::Condition;
use crate::tyre::Tyre;
use serde::Serialize;

/// The largest |α| a linear tyre is fitted to, degrees.
pub(crate) const WINDOW_DEG: f64 = 2.0;

/// The window of a linear fit, as written to the report.
#[derive(Debug, Clone, Serialize)]
pub struct LinearWindow {
    /// The largest |α| fitted, degrees.
    pub max_abs_alpha_deg: f64,
    /// Points fitted (after thinning: rows with `--bin-deg 0`).
    pub points_fitted: usize,
    /// Points left out, with |α| above the window.
    pub points_left_out: usize,
    /// The pneumatic trail fitted in the window, m (`None`: no `mz`, held at 0).
    pub pneumatic_trail: Option<f64>,
    /// The loads of the conditions left with fewer than two points in the
    /// window, so not fitted, N.
    pub loads_left_out: Vec<f64>,
}

impl LinearWindow {
    /// The lines said on the terminal (`mark` `" "`) and in the file's
    /// header (`mark` `"#"`).
    pub(crate) fn lines(&self, mark: &str) -> Vec<String> {
        let trail = match self.pneumatic_trail {
            Some(t) => format!(
                "pneumatic_trail = {t:.5} m fitted to mz in the same window (the ratio of the slopes of mz and fy on alpha)"
            ),
            None => "pneumatic_trail held at 0 (no mz data)".into(),
        };
        let conditions = match self.loads_left_out.len() {
            0 => String::new(),
            n => format!(
                "; {} with fewer than two points in it left out, at Fz {} N",
                crate::format::plural(n, "condition", "conditions"),
                self.loads_left_out
                    .iter()
                    .map(|f| format!("{f:.0}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        vec![
            format!(
                "{mark} linear window: fitted to |alpha| <= {} deg only ({} points; {} points with larger |alpha| left out, where the force saturates{conditions})",
                self.max_abs_alpha_deg, self.points_fitted, self.points_left_out
            ),
            format!("{mark} {trail}"),
        ]
    }
}

/// `conditions` kept to the window (a condition left with fewer than two
/// points dropped, its load said: two of a file's loads vanished without
/// a word), and the window's account (no trail yet).
pub(crate) fn windowed(conditions: Vec<Condition>) -> (Vec<Condition>, LinearWindow) {
    let max = WINDOW_DEG.to_radians();
    let total: usize = conditions.iter().map(|c| c.points.len()).sum();
    let (kept, left): (Vec<Condition>, Vec<Condition>) = conditions
        .into_iter()
        .map(|mut c| {
            c.points.retain(|p| p.slip().abs() <= max);
            c
        })
        .partition(|c| c.points.len() >= 2);
    let fitted: usize = kept.iter().map(|c| c.points.len()).sum();
    let w = LinearWindow {
        max_abs_alpha_deg: WINDOW_DEG,
        points_fitted: fitted,
        points_left_out: total - fitted,
        pneumatic_trail: None,
        loads_left_out: left.iter().map(|c| c.fz).collect(),
    };
    (kept, w)
}

/// The smallest |α| of the points of `conditions`, rad (infinite
/// without points).
pub(crate) fn smallest_slip(conditions: &[Condition]) -> f64 {
    conditions
        .iter()
        .flat_map(|c| &c.points)
        .map(|p| p.slip().abs())
        .fold(f64::INFINITY, f64::min)
}

/// The pneumatic trail of the points of `conditions` with a measured
/// `mz`: Σα·Mz / Σα·Fy, the ratio of the least-squares slopes through
/// zero of Mz and Fy on α (m); `None` without such points.
pub(crate) fn trail(conditions: &[Condition]) -> Option<f64> {
    let (mut amz, mut afy) = (0.0, 0.0);
    for p in conditions.iter().flat_map(|c| &c.points) {
        if p.mz().is_finite() && p.fy().is_finite() {
            amz += p.slip() * p.mz();
            afy += p.slip() * p.fy();
        }
    }
    (afy != 0.0 && amz.is_finite()).then(|| amz / afy)
}

/// Sets the trail of a linear `tyre` to `t`.
pub(crate) fn set_trail(tyre: &mut Tyre, t: f64) {
    if let Tyre::Linear(l) = tyre {
        l.pneumatic_trail = t;
    }
}

/// Refuses a linear fit `tyre` whose stiffness per unit of `load` (the
/// median of the window's conditions' loads) is below any tyre's while
/// the file's slip angles `alpha` reach beyond any rig's sweep in
/// radians: the column in degrees (`error/slip_degrees.rs`).
pub(crate) fn refuse_degrees(
    data: &std::path::Path,
    tyre: &Tyre,
    load: f64,
    alpha: &[f64],
) -> Result<(), crate::error::Error> {
    use crate::error::{InputError, InputProblem, SlipAngleInDegrees, UnitSlip};
    use crate::tyre::sizes::MIN_CORNERING_PER_LOAD;
    let Tyre::Linear(l) = tyre else {
        return Ok(());
    };
    let reach = alpha
        .iter()
        .filter(|a| a.is_finite())
        .fold(0.0_f64, |m, a| m.max(a.abs()));
    let stiffness = l.cornering_stiffness;
    if stiffness / load >= MIN_CORNERING_PER_LOAD || reach <= crate::error::MAX_RIG_SLIP_ANGLE {
        return Ok(());
    }
    let slip = SlipAngleInDegrees {
        stiffness,
        load,
        reach,
        least: MIN_CORNERING_PER_LOAD,
    };
    Err(InputError::problem(data, InputProblem::from(UnitSlip::from(slip))).into())
}
