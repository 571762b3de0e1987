//! A lateral force at zero slip the fitted model does not give: rig data
//! whose force crosses α = 0 at fy ≠ 0 (ply steer and conicity; PAC89's
//! shifts put 110.5 N there at 4000 N) fitted by a model odd in α (linear,
//! Gim, the simplified Magic Formula) miss by that offset at every point,
//! and the σ alone reads as the model not following the data. Measured,
//! not guessed: each condition's force at zero slip, the constant of the
//! least-squares parabola through its points within the linear window
//! (±2°; a line where they are too few for one), less
//! the fitted model's own force at α = 0 there, is the offset the model
//! leaves; the fit's σ with its curve shifted by that offset, condition by
//! condition, is what the rest of the misfit makes. Said where the shift
//! takes σ down by at least [`SAID_SHARE`] of itself. Units: N, rad.

use super::linear_window::{in_window, JUDGED_POINTS, WINDOW_DEG};
use super::notes::Note;
use crate::format::{fixed, readable};
use crate::identify::data::{Condition, RigPoint, SlipAxis, Sweep};
use crate::identify::{Channel, Fit};
use crate::tyre::Tyre;

/// The share of the fit's σ the shifted curve must take off for the
/// offset to be said: a fifth, past what the line's own noise moves.
pub(crate) const SAID_SHARE: f64 = 0.2;

/// The offset of `c`'s lateral force at zero slip that `tyre` does not
/// give, N (`None`: fewer than [`JUDGED_POINTS`] points within the window,
/// or no spread of slip among them).
fn unexplained(tyre: &Tyre, c: &Condition) -> Option<f64> {
    // The window's rule unthinned: within ±2° to a file's rounding, so
    // that the points at −2° count as those at +2° do.
    let within: Vec<(f64, f64)> = c
        .points
        .iter()
        .filter(|p| matches!(p.sweep, Sweep::Lateral { .. }))
        .filter(|p| p.fy().is_finite() && in_window(p.slip(), 0.0))
        .map(|p| (p.slip(), p.fy()))
        .collect();
    let intercept = intercept(&within)?;
    let speed = c.points.first()?.speed;
    let zero = RigPoint::unmeasured(SlipAxis::Angle, 0.0, c.fz, c.camber, speed);
    Some(intercept - Channel::LateralForce.model(tyre, &zero))
}

/// The force at zero slip of the points `(α, F)`: the constant of a
/// least-squares parabola through them, or of a line where fewer than
/// four points or three distinct slips allow no parabola (`None`: fewer
/// than [`JUDGED_POINTS`] points, or no spread of slip). A line's
/// constant reads the curve's bend as offset: PAC89's shifted curve at
/// 4000 N, 110.46 N at zero slip, gives 95.1 N by a line through ±2°, 109.0
/// N by a parabola.
fn intercept(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < JUDGED_POINTS {
        return None;
    }
    // Slips scaled to their largest, so that the normal equations hold
    // numbers of one size.
    let scale = points.iter().map(|p| p.0.abs()).fold(0.0, f64::max);
    let mut slips: Vec<f64> = points.iter().map(|p| p.0 / scale).collect();
    slips.sort_by(f64::total_cmp);
    slips.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    if scale <= 0.0 || points.len() < 4 || slips.len() < 3 {
        return line(points);
    }
    let mut a = nalgebra::Matrix3::<f64>::zeros();
    let mut b = nalgebra::Vector3::<f64>::zeros();
    for (x, y) in points {
        let u = x / scale;
        let row = nalgebra::Vector3::new(1.0, u, u * u);
        a += row * row.transpose();
        b += row * *y;
    }
    a.lu().solve(&b).map(|c| c[0]).filter(|c| c.is_finite())
}

/// The constant of the least-squares line through `points` (`None`: no
/// spread of slip).
fn line(points: &[(f64, f64)]) -> Option<f64> {
    let m = points.len() as f64;
    let (ma, mf) = points
        .iter()
        .fold((0.0, 0.0), |(a, f), (x, y)| (a + x / m, f + y / m));
    let (sxx, sxy) = points.iter().fold((0.0, 0.0), |(xx, xy), (x, y)| {
        (xx + (x - ma) * (x - ma), xy + (x - ma) * (y - mf))
    });
    (sxx > 0.0).then(|| mf - sxy / sxx * ma)
}

/// The note on the offset at zero slip `f`'s model leaves in the
/// lateral force of `conditions` (module notes), or `None`.
pub(crate) fn offset_note(
    f: &Fit,
    conditions: &[Condition],
    names: &super::level_names::LevelNames<'_>,
) -> Option<Note> {
    if f.channel != Channel::LateralForce {
        return None;
    }
    let offsets: Vec<Option<f64>> = conditions.iter().map(|c| unexplained(&f.tyre, c)).collect();
    let (mut e2, mut y2) = (0.0, 0.0);
    for (c, o) in conditions.iter().zip(&offsets) {
        for p in c.points.iter().filter(|p| p.fy().is_finite()) {
            let e = Channel::LateralForce.model(&f.tyre, p) + o.unwrap_or(0.0) - p.fy();
            e2 += e * e;
            y2 += p.fy() * p.fy();
        }
    }
    let shifted = 100.0 * (e2 / y2).sqrt();
    if !shifted.is_finite() || shifted > (1.0 - SAID_SHARE) * f.sigma_percent {
        return None;
    }
    let (c, o) = conditions
        .iter()
        .zip(&offsets)
        .filter_map(|(c, o)| o.map(|o| (c, o)))
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
    let more = match conditions.len() {
        1 => String::new(),
        n => format!(" (the largest of the {n} conditions')"),
    };
    Some(Note::said(format!(
        "the data have fy = {} N at zero slip at fz {}{more}, the constant of a parabola through their points within ±{WINDOW_DEG}° (a ply-steer or conicity offset), which the {} model has no term for: its curve shifted by each condition's offset would fit at σ {} % against the {} % fitted; subtract it from the data, or fit a model with shifts (pac89, mf61)",
        readable(o, 4),
        // The level as every other line names it, not its samples' median.
        names.load(c.fz),
        f.model,
        fixed(shifted, 3),
        fixed(f.sigma_percent, 3),
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_force_at_zero_slip_is_a_parabolas_constant_and_a_lines_on_three_points() {
        // A curve bent as a shifted tyre's: a line's constant is off by
        // the bend, a parabola's exact.
        let curve = |a: f64| 110.0 + 98_000.0 * a - 400_000.0 * a * a;
        let points: Vec<(f64, f64)> = (-6..=6)
            .map(|k| 0.005 * f64::from(k))
            .map(|a| (a, curve(a)))
            .collect();
        let c = intercept(&points).unwrap();
        assert!((c - 110.0).abs() < 1e-9, "{c}");
        assert!((line(&points).unwrap() - 110.0).abs() > 10.0);
        // Three points (a binned ±0.29° sweep): the line through them.
        let three = [(-0.005, -380.0), (0.0, 110.0), (0.005, 600.0)];
        assert!((intercept(&three).unwrap() - 110.0).abs() < 1e-9);
        assert_eq!(intercept(&three[..2]), None);
        assert_eq!(intercept(&[(0.0, 1.0), (0.0, 2.0), (0.0, 3.0)]), None);
    }
}
