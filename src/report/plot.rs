//! PNG figures drawn with plotters and an embedded DejaVu Sans font (no
//! system fonts needed). A [`Figure`] is a stack of panels sharing nothing but
//! the image; each panel holds line, dashed-line and point series.

use crate::error::{Error, OutputError};
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
    /// As `Cells`, coloured by the series' `values` on a blue–yellow map
    /// between the given (min, max).
    Heat(f64, f64, f64, f64),
}

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
    /// Palette index.
    pub color: usize,
}

/// A blue → green → yellow colour map (viridis-like) for t in [0, 1].
pub fn colormap(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let w = x - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |p: f64, q: f64| (p + w * (q - p)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
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
            self.draw(tmp).map_err(|e| {
                OutputError::Draw {
                    path: path.to_path_buf(),
                    detail: e.to_string(),
                }
                .into()
            })
        })
    }

    fn draw(&self, tmp: &Path) -> Result<(), Box<dyn std::error::Error>> {
        let rows = self.panels.len().div_ceil(self.columns).max(1);
        let root = BitMapBackend::new(tmp, (self.width, self.row_height * rows as u32))
            .into_drawing_area();
        root.fill(&WHITE)?;
        let areas = root.split_evenly((rows, self.columns));
        for (area, panel) in areas.iter().zip(&self.panels) {
            let (x0, x1) = panel
                .x_range
                .unwrap_or_else(|| range(panel.series.iter().flat_map(|s| s.x.iter().copied())));
            let (y0, y1) = panel
                .y_range
                .unwrap_or_else(|| range(panel.series.iter().flat_map(|s| s.y.iter().copied())));
            let mut chart = ChartBuilder::on(area)
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
            let mut labelled = false;
            for s in &panel.series {
                let c = palette(s.color);
                let all = || s.x.iter().copied().zip(s.y.iter().copied());
                let cell = |x: f64, y: f64, dx: f64, dy: f64| {
                    [(x - 0.5 * dx, y - 0.5 * dy), (x + 0.5 * dx, y + 0.5 * dy)]
                };
                let anno = match s.style {
                    Style::Line => chart
                        .draw_series(LineSeries::new(thin(&s.x, &s.y, 4000), c.stroke_width(2)))?,
                    Style::Dashed => chart.draw_series(DashedLineSeries::new(
                        thin(&s.x, &s.y, 4000),
                        6,
                        4,
                        c.stroke_width(2),
                    ))?,
                    Style::Points(r) => {
                        chart.draw_series(all().map(|p| Circle::new(p, r, c.filled())))?
                    }
                    Style::Segments => {
                        let pts: Vec<(f64, f64)> = all().collect();
                        chart.draw_series(
                            pts.chunks_exact(2)
                                .map(|w| PathElement::new(vec![w[0], w[1]], c.stroke_width(1))),
                        )?
                    }
                    Style::Cells(dx, dy) => chart.draw_series(
                        all().map(|(x, y)| Rectangle::new(cell(x, y, dx, dy), c.filled())),
                    )?,
                    Style::Heat(dx, dy, lo, hi) => {
                        let vals = s.values.clone().unwrap_or_default();
                        chart.draw_series(all().zip(vals).map(|((x, y), v)| {
                            Rectangle::new(
                                cell(x, y, dx, dy),
                                colormap((v - lo) / (hi - lo)).filled(),
                            )
                        }))?
                    }
                };
                if !s.label.is_empty() {
                    labelled = true;
                    anno.label(s.label.clone()).legend(move |(x, y)| {
                        Rectangle::new([(x, y - 4), (x + 16, y + 4)], c.filled())
                    });
                }
            }
            if labelled {
                chart
                    .configure_series_labels()
                    .label_font(("sans-serif", 13))
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .position(SeriesLabelPosition::UpperRight)
                    .draw()?;
            }
        }
        root.present()?;
        Ok(())
    }
}
