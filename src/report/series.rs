//! What a figure's series are: the data, how each is drawn ([`Style`]) and in
//! which colour ([`palette`], full or pale: [`Tone`]), shared by the panel drawing
//! ([`super::plot`]) and its key (the legend column beside each panel);
//! the colours that tell levels apart ([`LEVEL_COLOURS`]), chosen by their
//! CIE76 distance (`colour.rs`) from each other and from their pale tints.

use super::colour::ColourScale;
use plotters::style::RGBColor;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// Solid line.
    Line,
    /// Dashed line.
    Dashed,
    /// Dotted line (short dashes), told apart from `Dashed` in one figure.
    Dotted,
    /// Filled circles of the given radius (px).
    Points(u32),
    /// Separate segments: points 2k and 2k + 1 are joined.
    Segments,
    /// Filled rectangles of size (dx, dy) in data units centred on each point,
    /// in the series colour.
    Cells(f64, f64),
    /// As `Cells`, coloured by the series' `values` through its
    /// [`ColourScale`] on a blue–yellow map, with a colour bar beside the
    /// panel; cells without a value are drawn light grey.
    Heat(f64, f64),
}

/// How measured samples are drawn beside a model's lines: dots (a dashed
/// line through noisy samples reads as a smear), the first series of their
/// panel, so that the model's lines are drawn over them as a fit is drawn
/// over its data (dots drawn last hid the lines wherever they agree).
pub const MEASURED_DOTS: Style = Style::Points(2);

/// The shape of a marker.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A filled circle.
    Disc,
    /// A filled diamond (a square on its corner).
    Diamond,
    /// A hollow circle (white inside, outline in the series colour).
    Ring,
}

/// A marker drawn at every point of a series, over its line if it has one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Marker {
    /// Its shape.
    pub shape: Shape,
    /// Its radius, px.
    pub size: u32,
}

/// Width of the column beside a panel that holds its legend and colour bar,
/// px.
pub(crate) const SIDE: i32 = 200;

/// The fill of a map cell without a value (distinct from every colour of
/// [`colormap`]).
pub(crate) const NO_VALUE: RGBColor = RGBColor(225, 225, 225);

/// One named series.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend label (empty: no legend entry).
    pub label: String,
    /// x values.
    pub x: Vec<f64>,
    /// y values.
    pub y: Vec<f64>,
    /// Drawing style.
    pub style: Style,
    /// Values for `Style::Heat`.
    pub values: Option<Vec<f64>>,
    /// How `values` map to colours (`Style::Heat`), with the quantity's
    /// name and unit for the colour bar.
    pub scale: Option<ColourScale>,
    /// Palette index.
    pub color: usize,
    /// A marker at every point (with `Style::Points` it replaces the discs).
    pub marker: Option<Marker>,
    /// How strongly its colour is laid on ([`Tone`]).
    pub tone: Tone,
}

/// How strongly a series' colour is laid on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Tone {
    /// The palette's colour.
    #[default]
    Full,
    /// The palette's colour mixed with white ([`PALE`]): measured points
    /// under the line fitted to them, so that the line, in the full colour
    /// and drawn after them, reads over hundreds of points (in one colour
    /// a close fit's line vanished into its points' band).
    Pale,
}

/// The share of white in a [`Tone::Pale`] colour.
pub const PALE: f64 = 0.55;

impl Series {
    /// A solid line.
    pub fn line(label: &str, x: &[f64], y: &[f64], color: usize) -> Self {
        Self {
            label: label.into(),
            x: x.to_vec(),
            y: y.to_vec(),
            style: Style::Line,
            color,
            values: None,
            scale: None,
            marker: None,
            tone: Tone::Full,
        }
    }
    /// A heat map: cells of size (dx, dy) centred on (x, y), coloured by
    /// `values` through a scale chosen for them ([`ColourScale::fit`]) and
    /// labelled `label` on its colour bar.
    pub fn heat(x: &[f64], y: &[f64], values: Vec<f64>, cell: (f64, f64), label: &str) -> Self {
        let scale = ColourScale::fit(&values, label);
        Self {
            label: String::new(),
            x: x.to_vec(),
            y: y.to_vec(),
            style: Style::Heat(cell.0, cell.1),
            values: Some(values),
            scale: Some(scale),
            color: 0,
            marker: None,
            tone: Tone::Full,
        }
    }

    /// The same series with another style.
    pub fn styled(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The same series with a marker at every point.
    pub fn marked(mut self, marker: Marker) -> Self {
        self.marker = Some(marker);
        self
    }

    /// The same series in another tone.
    pub fn toned(mut self, tone: Tone) -> Self {
        self.tone = tone;
        self
    }

    /// The colour it is drawn in: its palette colour in its tone.
    pub fn colour(&self) -> RGBColor {
        shade(palette(self.color), self.tone)
    }
}

/// Colour `c` in `tone`.
pub fn shade(c: RGBColor, tone: Tone) -> RGBColor {
    match tone {
        Tone::Full => c,
        Tone::Pale => {
            let mix = |v: u8| (f64::from(v) + PALE * (255.0 - f64::from(v))).round() as u8;
            RGBColor(mix(c.0), mix(c.1), mix(c.2))
        }
    }
}

/// Colour of palette index `i`.
pub fn palette(i: usize) -> RGBColor {
    const P: [RGBColor; 10] = [
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(255, 127, 14),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(23, 190, 207),
        RGBColor(127, 127, 127),
        // Light blue: context drawn behind the data (trajectories).
        RGBColor(160, 196, 222),
        // Magenta.
        RGBColor(204, 51, 153),
    ];
    match i {
        INK => RGBColor(0, 0, 0),
        // Olive (the tab10 palette's ninth): a level's colour where the
        // light blue stood within ΔE 2 of the blue's pale tint.
        OLIVE => RGBColor(188, 189, 34),
        _ => P[i % P.len()],
    }
}

/// Olive, the palette's index past [`INK`]: a level of a fit figure.
pub const OLIVE: usize = 11;

/// The palette's colours that tell a fit figure's levels apart, a line
/// in each over its points in the pale tint ([`Tone::Pale`]): the palette
/// without grey (the key's "measured" swatch) and light blue (context,
/// within ΔE 1.6 of the blue's pale tint: a ninth level's line read as
/// the first level's points). Every colour stands more than
/// [`LEVEL_FULL_APART`] from every other and more than
/// [`LEVEL_PALE_APART`] from every pale tint, its own included (tested).
pub const LEVEL_COLOURS: [usize; 9] = [0, 1, 2, 3, 4, 5, 6, 9, OLIVE];

/// The least CIE76 colour difference ([`super::colour::delta_e76`]) of
/// two levels' full colours (the closest pair, purple and magenta, is
/// 37.3 apart).
pub const LEVEL_FULL_APART: f64 = 25.0;

/// The least CIE76 colour difference of a level's full colour from any
/// level's pale tint (the closest, cyan over its own tint, is 20.5 apart;
/// six to seven just noticeable differences).
pub const LEVEL_PALE_APART: f64 = 15.0;

/// Size of the axis labels and key text, px (the panels' and the key's).
pub const LABEL_PX: u32 = 13;

/// Black: the colour of a fitted model's line drawn over measured points
/// coloured by condition (every index but it and [`OLIVE`] wraps over the
/// ten colours).
pub const INK: usize = 10;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::colour::delta_e76;

    /// Every level's line stands apart from every other level's line and
    /// from every level's pale points (its own too), and from the key's
    /// grey points: the light blue that stood at ΔE 1.6 from the blue's
    /// pale tint is not a level's.
    #[test]
    fn level_colours_stand_apart_from_each_other_and_every_pale_tint() {
        let full: Vec<RGBColor> = LEVEL_COLOURS.iter().map(|&i| palette(i)).collect();
        let mut pale: Vec<RGBColor> = full.iter().map(|&c| shade(c, Tone::Pale)).collect();
        pale.push(shade(palette(7), Tone::Pale));
        for (i, &a) in full.iter().enumerate() {
            for &b in &full[i + 1..] {
                assert!(delta_e76(a, b) > LEVEL_FULL_APART, "{a:?} {b:?}");
            }
            for &p in &pale {
                assert!(delta_e76(a, p) > LEVEL_PALE_APART, "{a:?} over {p:?}");
            }
        }
        assert!(delta_e76(palette(8), shade(palette(0), Tone::Pale)) < 2.0);
        assert!(!LEVEL_COLOURS.contains(&8) && !LEVEL_COLOURS.contains(&INK));
    }
}
