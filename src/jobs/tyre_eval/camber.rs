//! A camber steeper than any car tyre's measured range, evaluated by a
//! model that states no camber range: said, with the force it gives.
//!
//! A Magic Formula file states its own range (`CAMMIN`/`CAMMAX`) and
//! `tyre-eval` says the points past it (`ranges.rs`); a TOML tyre written
//! by `identify` states the cambers it was fitted to (`[fitted_ranges]`),
//! and the points past those are counted too. A hand-written PAC89, Gim,
//! simplified Magic Formula or UniTire file states neither, and its camber
//! terms, polynomials in γ fitted to a few degrees, extrapolate without
//! bound: the Adams PAC89 example at 86° of camber gives a lateral force of
//! 2.3 times the load. Above [`STEEP_CAMBER`] a point is said, whatever the
//! model: none of the thirteen public `.tir` files states a camber range
//! beyond 15.1° (`CAMMAX` 0.264 rad; the others 0.1–0.2 rad). Radians
//! inside, degrees in the sentence; the lateral force over the load is the
//! model's, in the points' frame.

use crate::format::{plural, readable, rounded};
use crate::io::fitted_ranges::FittedRanges;
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The camber above which a point of a model with no stated camber range
/// is said, rad (20°): the rig reader's, past which a column reads as
/// degrees.
pub use crate::io::STEEP_CAMBER;

/// The points at a camber steeper than [`STEEP_CAMBER`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SteepCamber {
    /// Points above it.
    pub points: usize,
    /// The steepest point's line in the points file (1-based).
    pub line: usize,
    /// Its camber, rad.
    pub camber: f64,
    /// Its lateral force over its load there (`fy / fz`).
    pub fy_over_fz: f64,
}

impl SteepCamber {
    /// The warning, for `model` and `count` points in all.
    pub fn line(&self, model: &str, count: usize) -> String {
        format!(
            "{} of {} at a camber steeper than ±{}°, beyond any car tyre's measured range (no public .tir states one past 15.1°): a {model} file states no camber range to hold them to (a .tir's CAMMIN/CAMMAX) and its camber terms are extrapolated; the steepest, {}° at line {}, gives fy = {}·fz",
            self.points,
            plural(count, "point", "points"),
            rounded(STEEP_CAMBER.to_degrees(), 3),
            readable(self.camber.to_degrees(), 3),
            self.line,
            readable(self.fy_over_fz, 3),
        )
    }
}

/// The points of `camber` (at file lines `lines`, forces `f`, loads `fz`)
/// steeper than [`STEEP_CAMBER`] where `tyre` states no camber range and
/// `fitted` none either; `None` where there are none, where the model
/// does not read camber (said by `unread.rs`) or where a range says them.
pub fn steep_camber(
    tyre: &Tyre,
    fitted: Option<&FittedRanges>,
    camber_read: bool,
    [fz, camber]: [&[f64]; 2],
    f: &[PointForces],
    lines: &[usize],
) -> Option<SteepCamber> {
    let ranged =
        matches!(tyre, Tyre::MagicFormula(_)) || fitted.is_some_and(|r| r.camber.is_some());
    if ranged || !camber_read {
        return None;
    }
    let steep: Vec<usize> = (0..camber.len())
        .filter(|&i| camber[i].abs() > STEEP_CAMBER)
        .collect();
    let &i = steep
        .iter()
        .max_by(|&&a, &&b| camber[a].abs().total_cmp(&camber[b].abs()))?;
    Some(SteepCamber {
        points: steep.len(),
        line: lines.get(i).copied().unwrap_or(0),
        camber: camber[i],
        fy_over_fz: f[i].fy / fz[i],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::{Pac89, SlipState};

    fn forces(t: &Tyre, fz: &[f64], camber: &[f64]) -> Vec<PointForces> {
        fz.iter()
            .zip(camber)
            .map(|(&z, &g)| {
                let mut s = SlipState::lateral(0.0, z);
                s.camber = g;
                t.point_forces(&s, None)
            })
            .collect()
    }

    /// The Adams PAC89 example at 86° of camber: said, with its force;
    /// at 10° or with a fitted camber range, not.
    #[test]
    fn a_steep_camber_of_a_model_without_a_camber_range_is_said() {
        let t = Tyre::Pac89(Pac89::adams_example());
        let fz = [4000.0, 4000.0, 4000.0];
        let camber = [0.1, 1.5, -0.5];
        let f = forces(&t, &fz, &camber);
        let s = steep_camber(&t, None, true, [&fz, &camber], &f, &[2, 3, 4]).unwrap();
        assert_eq!((s.points, s.line, s.camber), (2, 3, 1.5));
        assert!(s.fy_over_fz.abs() > 1.5, "{s:?}");
        let gentle = [0.1, 0.2, -0.3];
        let f = forces(&t, &fz, &gentle);
        assert!(steep_camber(&t, None, true, [&fz, &gentle], &f, &[2, 3, 4]).is_none());
        let ranges = FittedRanges {
            camber: Some([-0.1, 0.1]),
            ..FittedRanges::default()
        };
        let f = forces(&t, &fz, &camber);
        assert!(steep_camber(&t, Some(&ranges), true, [&fz, &camber], &f, &[2, 3, 4]).is_none());
        assert!(steep_camber(&t, None, false, [&fz, &camber], &f, &[2, 3, 4]).is_none());
    }
}
