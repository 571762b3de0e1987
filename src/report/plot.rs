//! Figures drawn with plotters and an embedded DejaVu Sans font (no system
//! fonts needed), as PNG files or as SVG text for a self-contained HTML
//! report. A [`Figure`] is a stack of panels sharing nothing but the image;
//! each panel holds line, dashed-line and point series.

pub use super::colour::{colormap, ColourScale, ScaleKind};
use crate::error::Error;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

fn ensure_font() {
    REGISTER.call_once(|| {
        // Registration only fails on a malformed font, and the font is
        // compiled in: a failure here is a build defect.
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("embedded font is invalid"));
    });
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// Solid line.
    Line,
    /// Dashed line.
    Dashed,
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

/// Width of the column beside a panel that holds its legend and colour bar,
/// px.
pub(super) const SIDE: i32 = 200;

/// The fill of a map cell without a value (distinct from every colour of
/// [`colormap`]).
pub(super) const NO_VALUE: RGBColor = RGBColor(225, 225, 225);

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
}

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
        }
    }

    /// The same series with another style.
    pub fn styled(mut self, style: Style) -> Self {
        self.style = style;
        self
    }
}

/// One panel of a figure.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    /// Title above the panel.
    pub title: String,
    /// x-axis label.
    pub x_label: String,
    /// y-axis label.
    pub y_label: String,
    /// Series drawn in order.
    pub series: Vec<Series>,
    /// Fixed x range (default: the data's).
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range (default: the data's).
    pub y_range: Option<(f64, f64)>,
}

/// A stack of panels (or a grid with `columns` > 1).
#[derive(Debug, Clone)]
pub struct Figure {
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// Panels per row.
    pub columns: usize,
    /// Image width, px.
    pub width: u32,
    /// Height of one row, px.
    pub row_height: u32,
}

/// Colour of palette index `i`.
pub fn palette(i: usize) -> RGBColor {
    const P: [RGBColor; 8] = [
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(255, 127, 14),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(23, 190, 207),
        RGBColor(127, 127, 127),
    ];
    P[i % P.len()]
}

/// Finite min/max with a margin; a flat range is widened.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        lo.abs().max(1.0) * 0.05
    };
    (lo - pad, hi + pad)
}

/// At most `max` evenly spaced points of a series (long records draw slowly).
fn thin(x: &[f64], y: &[f64], max: usize) -> Vec<(f64, f64)> {
    let stride = x.len().div_ceil(max).max(1);
    x.iter()
        .zip(y)
        .step_by(stride)
        .filter(|(a, b)| a.is_finite() && b.is_finite())
        .map(|(a, b)| (*a, *b))
        .collect()
}

impl Figure {
    /// A single-column stack of panels.
    pub fn stack(panels: Vec<Panel>) -> Self {
        Self {
            panels,
            columns: 1,
            width: 1000,
            row_height: 260,
        }
    }

    /// Renders the figure to a PNG file (written atomically).
    pub fn save(&self, path: &Path) -> Result<(), Error> {
        ensure_font();
        super::write_atomic(path, |tmp| {
            self.draw(tmp).map_err(|e| Error::output(path, e))
        })
    }

    /// The figure as SVG text (for embedding in an HTML page); `for_file`
    /// is the file it goes into, named if drawing fails.
    pub fn svg(&self, for_file: &Path) -> Result<String, Error> {
        ensure_font();
        let mut text = String::new();
        {
            let root = SVGBackend::with_string(&mut text, self.size()).into_drawing_area();
            self.draw_on(&root)
                .map_err(|e| Error::output(for_file, format!("cannot draw a figure: {e}")))?;
        }
        Ok(text)
    }

    /// Width and height of the image, px.
    fn size(&self) -> (u32, u32) {
        let rows = self.panels.len().div_ceil(self.columns).max(1);
        (self.width, self.row_height * rows as u32)
    }

    fn draw(&self, tmp: &Path) -> Result<(), Box<dyn std::error::Error>> {
        let root = BitMapBackend::new(tmp, self.size()).into_drawing_area();
        self.draw_on(&root)
    }

    fn draw_on<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        let rows = self.panels.len().div_ceil(self.columns).max(1);
        root.fill(&WHITE)?;
        let areas = root.split_evenly((rows, self.columns));
        for (area, panel) in areas.iter().zip(&self.panels) {
            draw_panel(area, panel)?;
        }
        root.present()?;
        Ok(())
    }
}

/// One panel: the chart on the left, its legend and colour bar in a column
/// of their own on the right, so that no key hides data.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let keyed = panel
        .series
        .iter()
        .any(|s| !s.label.is_empty() || s.scale.is_some());
    let width = area.dim_in_pixel().0 as i32;
    let (plot, side) = if keyed && width > 2 * SIDE {
        let (p, s) = area.split_horizontally(width - SIDE);
        (p, Some(s))
    } else {
        (area.clone(), None)
    };
    let (x0, x1) = panel
        .x_range
        .unwrap_or_else(|| range(panel.series.iter().flat_map(|s| s.x.iter().copied())));
    let (y0, y1) = panel
        .y_range
        .unwrap_or_else(|| range(panel.series.iter().flat_map(|s| s.y.iter().copied())));
    let mut chart = ChartBuilder::on(&plot)
        .caption(&panel.title, ("sans-serif", 16))
        .margin(8)
        .x_label_area_size(36)
        .y_label_area_size(64)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(&panel.x_label)
        .y_desc(&panel.y_label)
        .label_style(("sans-serif", 13))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()?;
    for s in &panel.series {
        draw_series(&mut chart, s)?;
    }
    if let Some(side) = side {
        super::legend::draw(&side, &panel.series)?;
    }
    Ok(())
}

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn draw_series<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    s: &Series,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let c = palette(s.color);
    let all = || s.x.iter().copied().zip(s.y.iter().copied());
    let cell = |x: f64, y: f64, dx: f64, dy: f64| {
        [(x - 0.5 * dx, y - 0.5 * dy), (x + 0.5 * dx, y + 0.5 * dy)]
    };
    match s.style {
        Style::Line => {
            chart.draw_series(LineSeries::new(thin(&s.x, &s.y, 4000), c.stroke_width(2)))?;
        }
        Style::Dashed => {
            chart.draw_series(DashedLineSeries::new(
                thin(&s.x, &s.y, 4000),
                6,
                4,
                c.stroke_width(2),
            ))?;
        }
        Style::Points(r) => {
            chart.draw_series(all().map(|p| Circle::new(p, r, c.filled())))?;
        }
        Style::Segments => {
            let pts: Vec<(f64, f64)> = all().collect();
            chart.draw_series(
                pts.chunks_exact(2)
                    .map(|w| PathElement::new(vec![w[0], w[1]], c.stroke_width(1))),
            )?;
        }
        Style::Cells(dx, dy) => {
            chart
                .draw_series(all().map(|(x, y)| Rectangle::new(cell(x, y, dx, dy), c.filled())))?;
        }
        Style::Heat(dx, dy) => {
            let vals = s.values.as_deref().unwrap_or(&[]);
            let scale = s.scale.as_ref();
            chart.draw_series(all().zip(vals).map(|((x, y), &v)| {
                // A cell without a value is drawn as such, never as the
                // colour of the map's minimum.
                let fill = scale
                    .and_then(|sc| sc.position(v))
                    .map_or(NO_VALUE, colormap);
                Rectangle::new(cell(x, y, dx, dy), fill.filled())
            }))?;
        }
    }
    Ok(())
}
