//! The key and level styles every tyre-fit figure shares (the swarm's
//! and the staged Magic Formula fit's): grey swatches for measured
//! (pale points) and fitted (a line) first, then a colour per level, its
//! fitted line's dash and its points' marker, 27 levels told apart.

use crate::report::plot::{Series, Shape, Style, Tone, INK};

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

/// The style of a panel's `k`-th level: the nine colours of the palette
/// that are neither black nor the key's grey with solid lines and rings,
/// then the same colours with dashed lines and diamonds, then dotted lines
/// and discs: 27 levels told apart (a moment stage's grid of slip ratios
/// has 12; by colour alone the tenth level was drawn as the first).
pub(super) fn level_style(k: usize) -> LevelStyle {
    const CYCLES: [(Style, Shape); 3] = [
        (Style::Line, Shape::Ring),
        (Style::Dashed, Shape::Diamond),
        (Style::Dotted, Shape::Disc),
    ];
    let colours = INK - 1;
    let c = k % colours;
    let (line, shape) = CYCLES[(k / colours) % CYCLES.len()];
    LevelStyle {
        colour: if c >= MEASURED { c + 1 } else { c },
        line,
        shape,
    }
}

/// The palette index of the key's "measured" swatch (grey).
pub(super) const MEASURED: usize = 7;
