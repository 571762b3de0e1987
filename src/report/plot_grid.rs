//! The minor grid behind a panel's data: light lines between the labelled
//! (bold) ones that plotters draws, at a step of a half, a quarter or a
//! fifth of theirs, and only as fine as stays legible: at least
//! [`GRID_PX`] apart on the image, else none.
//!
//! plotters' own minor grid asks for up to ten lines per labelled step
//! whatever the panel's size: a replay's sideslip panel over −6°…12°
//! (labels every 2°) drew a line every 0.2°, 90 lines 2 px apart over its
//! 180 px, and read as a grey panel rather than a grid. Positions are in
//! data units; the labelled lines are plotters' own key points (the same
//! function, the same count), so that a minor line never falls on one.

use plotters::coord::ranged1d::Ranged;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// A panel's chart: f64 on both axes.
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Least distance between two lines of the grid, px: closer, a light
/// grid reads as a grey fill.
pub const GRID_PX: f64 = 8.0;

/// The colour of a minor grid line (plotters' labelled lines are darker).
const MINOR: RGBColor = RGBColor(235, 235, 235);

/// The minor lines of an axis over `range` drawn `px` pixels long, whose
/// labelled lines plotters places as at most `labels` key points: between
/// those, at the finest of a fifth (a quarter where the labelled step is
/// 2·10ⁿ) or a half of their step whose lines lie at least [`GRID_PX`]
/// apart; none where even a half would be closer, or with fewer than two
/// labelled lines.
pub fn minor_lines(range: (f64, f64), labels: usize, px: f64) -> Vec<f64> {
    let (lo, hi) = (range.0.min(range.1), range.0.max(range.1));
    if !(lo.is_finite() && hi.is_finite() && hi > lo && px > 0.0) {
        return Vec::new();
    }
    let major = RangedCoordf64::from(lo..hi).key_points(labels);
    if major.len() < 2 {
        return Vec::new();
    }
    let step = major[1] - major[0];
    // plotters' steps are 1, 2 or 5 times a power of ten.
    let mantissa = step / 10f64.powf(step.log10().floor());
    let splits: [u32; 2] = if (mantissa - 2.0).abs() < 0.1 {
        [4, 2]
    } else {
        [5, 2]
    };
    let px_per_unit = px / (hi - lo);
    let Some(n) = splits
        .into_iter()
        .find(|&n| step / f64::from(n) * px_per_unit >= GRID_PX)
    else {
        return Vec::new();
    };
    let minor = step / f64::from(n);
    let first = ((lo - major[0]) / minor).ceil() as i64;
    let last = ((hi - major[0]) / minor).floor() as i64;
    (first..=last)
        .filter(|k| k.rem_euclid(i64::from(n)) != 0)
        .map(|k| major[0] + k as f64 * minor)
        .collect()
}

/// Draws the minor grid of `chart` whose x and y axes carry at most
/// `labels` = (x, y) labelled lines ([`minor_lines`]); before the mesh,
/// so that the labelled lines and the axes are drawn over it.
pub(super) fn draw_minor<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    labels: (usize, usize),
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let (x, y) = (chart.x_range(), chart.y_range());
    let xs = minor_lines((x.start, x.end), labels.0, f64::from(w));
    let ys = minor_lines((y.start, y.end), labels.1, f64::from(h));
    let style = MINOR.stroke_width(1);
    chart.draw_series(
        xs.into_iter()
            .map(|v| PathElement::new(vec![(v, y.start), (v, y.end)], style)),
    )?;
    chart.draw_series(
        ys.into_iter()
            .map(|v| PathElement::new(vec![(x.start, v), (x.end, v)], style)),
    )?;
    Ok(())
}
