//! The key and level styles every tyre-fit figure shares (the swarm's
//! and the staged Magic Formula fit's): grey swatches for measured
//! (pale points) and fitted (a line) first, then a colour per level, its
//! fitted line's dash and its points' marker, 27 levels told apart: each
//! line's colour more than ΔE 15 (CIE76) from every level's pale points.

use crate::report::plot::{Series, Shape, Style, Tone};
use crate::report::series::LEVEL_COLOURS;

/// The first entries of a fit figure's key, which say how measured and
/// fitted are drawn: the measured points (grey, drawn as `points`) and
/// the fitted line (in colour `fitted`). Every fit figure's panel opens
/// its key with them; the levels' colours follow.
pub(super) fn key_entries(points: Style, fitted: usize) -> Vec<Series> {
    vec![
        Series::line("measured", &[], &[], MEASURED)
            .styled(points)
            .toned(Tone::Pale),
        Series::line("fitted", &[], &[], fitted),
    ]
}

/// How a panel's `k`-th level is drawn: its colour, its fitted line's
/// dash and its measured points' marker.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct LevelStyle {
    /// Palette index: the palette without black and the key's grey.
    pub colour: usize,
    /// Solid, dashed or dotted.
    pub line: Style,
    /// Ring, diamond or disc.
    pub shape: Shape,
}

/// The style of a panel's `k`-th level: the nine level colours of the
/// palette ([`LEVEL_COLOURS`]: neither black, the key's grey nor the light
/// blue within ΔE 1.6 of the first level's pale points) with solid lines
/// and rings, then the same colours with dashed lines and diamonds, then
/// dotted lines and discs: 27 levels told apart (a moment stage's grid of
/// slip ratios has 12; by colour alone the tenth level was drawn as the
/// first). The key shows each level's line in its dash.
pub(super) fn level_style(k: usize) -> LevelStyle {
    const CYCLES: [(Style, Shape); 3] = [
        (Style::Line, Shape::Ring),
        (Style::Dashed, Shape::Diamond),
        (Style::Dotted, Shape::Disc),
    ];
    let colours = LEVEL_COLOURS.len();
    let (line, shape) = CYCLES[(k / colours) % CYCLES.len()];
    LevelStyle {
        colour: LEVEL_COLOURS[k % colours],
        line,
        shape,
    }
}

/// The palette index of the key's "measured" swatch (grey).
pub(super) const MEASURED: usize = 7;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::colour::delta_e76;
    use crate::report::plot::{palette, shade};
    use crate::report::series::{LEVEL_FULL_APART, LEVEL_PALE_APART};

    /// Over the 27 levels a figure tells apart, every level's line is
    /// further than ΔE 15 from every level's pale points, and two levels
    /// whose lines share a colour differ in dash (past the nine colours).
    #[test]
    fn every_levels_line_stands_apart_from_every_line_and_every_levels_points() {
        let look = |k: usize| {
            let s = level_style(k);
            (palette(s.colour), s.line)
        };
        for i in 0..27 {
            let (a, dash) = look(i);
            for j in 0..27 {
                let (b, other) = look(j);
                let pale = shade(b, Tone::Pale);
                assert!(delta_e76(a, pale) > LEVEL_PALE_APART, "{i} over {j}");
                if i != j {
                    assert!(
                        dash != other || delta_e76(a, b) > LEVEL_FULL_APART,
                        "{i} {j}"
                    );
                }
            }
        }
    }
}
