//! The key of a panel, drawn in a column of its own beside the chart (never
//! over the data): one swatch per labelled series in the style it is drawn
//! in (line, dashes, points), and for a heat map a colour bar with its
//! quantity, unit, scale and tick values, and a swatch for cells without a
//! value.

use super::colour::colormap;
use super::series::{Series, Shape, Style, LABEL_PX, NO_VALUE};
use plotters::coord::Shift;
use plotters::prelude::*;

const FONT: (&str, u32) = ("sans-serif", LABEL_PX);
const ROW: i32 = 20;

/// Draws the key of `series` into `side`, from the top.
pub(super) fn draw<DB: DrawingBackend>(
    side: &DrawingArea<DB, Shift>,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let keyed = series.iter().filter(|s| !s.label.is_empty());
    let (at, mut y) = side_layout(series);
    for (s, top) in keyed.zip(at) {
        swatch(side, s, top)?;
        // Long labels wrap onto lines of their own rather than run off
        // the image.
        for (k, line) in wrap(&s.label, WRAP).iter().enumerate() {
            side.draw(&Text::new(
                line.clone(),
                (38, top - 7 + k as i32 * LINE),
                FONT,
            ))?;
        }
    }
    for s in series {
        if let (Style::Heat(..), Some(scale)) = (s.style, &s.scale) {
            y = colour_bar(side, s, scale, y + 8)?;
        }
    }
    Ok(())
}

/// Characters of a label's line in a key beside a chart.
const WRAP: usize = 22;
/// Height of a wrapped label's further lines, px.
const LINE: i32 = 15;
/// Top of the first entry of a key beside a chart, px.
const SIDE_TOP: i32 = 40;

/// Where the entries of a key beside a chart go: the y of each labelled
/// series' swatch, px from the top of its column, each entry as tall as its
/// wrapped label; and the y below the last. The one layout [`draw`] draws
/// and [`side_height`] measures, so that a figure can make its rows tall
/// enough for the key (a three-effect verdict's wrapped labels ran past
/// the panel and the last entry was drawn over the one before).
pub(super) fn side_layout(series: &[Series]) -> (Vec<i32>, i32) {
    let mut y = SIDE_TOP;
    let mut at = Vec::new();
    for s in series.iter().filter(|s| !s.label.is_empty()) {
        at.push(y);
        y += ROW + LINE * (wrap(&s.label, WRAP).len() as i32 - 1);
    }
    (at, y)
}

/// Height a key of `series` beside a chart takes from the top of its
/// column, px: its entries and a margin below the last (a colour bar fits
/// itself to the room left).
pub(super) fn side_height(series: &[Series]) -> i32 {
    let (at, bottom) = side_layout(series);
    if at.is_empty() {
        0
    } else {
        bottom + ROW / 2
    }
}

/// Where the entries of a key laid out below a chart `width` px wide go:
/// (x, y) of each entry's swatch, in rows from the left, each entry as wide
/// as its label; and the height of the rows, px.
pub(super) fn below_layout(labels: &[&str], width: i32) -> (Vec<(i32, i32)>, i32) {
    let (mut x, mut y) = (0, ROW / 2 + 2);
    let mut at = Vec::with_capacity(labels.len());
    for label in labels {
        let w = 46 + 7 * label.chars().count() as i32;
        if x > 0 && x + w > width {
            x = 0;
            y += ROW;
        }
        at.push((x, y));
        x += w;
    }
    let height = if labels.is_empty() { 0 } else { y + ROW / 2 };
    (at, height)
}

/// Height of the strip a key below a chart `width` px wide takes: its rows
/// and, for a heat map, a horizontal colour bar.
pub(super) fn below_height(series: &[Series], width: i32) -> i32 {
    let labels: Vec<&str> = labels(series);
    let bar = series.iter().any(|s| s.scale.is_some());
    below_layout(&labels, width).1 + if bar { BAR_BELOW } else { 0 }
}

/// Height of a horizontal colour bar with its label and ticks, px.
const BAR_BELOW: i32 = 64;

fn labels(series: &[Series]) -> Vec<&str> {
    series
        .iter()
        .filter(|s| !s.label.is_empty())
        .map(|s| s.label.as_str())
        .collect()
}

/// Draws the key of `series` into `strip`, below a chart too narrow for a
/// column beside it: the entries in rows, then a heat map's colour bar
/// lying down.
pub(super) fn draw_below<DB: DrawingBackend>(
    strip: &DrawingArea<DB, Shift>,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let width = strip.dim_in_pixel().0 as i32;
    let keyed: Vec<&Series> = series.iter().filter(|s| !s.label.is_empty()).collect();
    let (at, height) = below_layout(&labels(series), width);
    for (s, (x, y)) in keyed.iter().zip(at) {
        let w = (width - x).max(1) as u32;
        let cell = strip.clone().shrink((x, y - ROW / 2), (w, ROW as u32));
        swatch(&cell, s, ROW / 2)?;
        cell.draw(&Text::new(s.label.clone(), (38, ROW / 2 - 7), FONT))?;
    }
    for s in series {
        if let (Style::Heat(..), Some(scale)) = (s.style, &s.scale) {
            let top = height + 4;
            let missing = s
                .values
                .as_deref()
                .is_some_and(|v| v.iter().any(|x| !x.is_finite()));
            let name = format!(
                "{} ({}{})",
                scale.label,
                scale.kind.name(),
                if missing { "; grey: no value" } else { "" }
            );
            strip.draw(&Text::new(name, (8, top), FONT))?;
            let (left, right) = (8, width - 30);
            const STEPS: i32 = 64;
            for k in 0..STEPS {
                let t = (f64::from(k) + 0.5) / f64::from(STEPS);
                let a = left + k * (right - left) / STEPS;
                let b = left + (k + 1) * (right - left) / STEPS;
                strip.draw(&Rectangle::new(
                    [(a, top + 18), (b + 1, top + 32)],
                    colormap(t).filled(),
                ))?;
            }
            for k in 0..=2 {
                let t = f64::from(k) / 2.0;
                let x = left + (t * f64::from(right - left)).round() as i32;
                if let Some(v) = scale.value_at(t) {
                    // The ends' labels kept inside the strip.
                    let shift = [0, 14, 30][k as usize];
                    strip.draw(&Text::new(tick(v), (x - shift, top + 36), FONT))?;
                }
            }
        }
    }
    Ok(())
}

fn swatch<DB: DrawingBackend>(
    side: &DrawingArea<DB, Shift>,
    s: &Series,
    y: i32,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let c = s.colour();
    match s.style {
        Style::Line | Style::Segments => {
            side.draw(&PathElement::new(vec![(6, y), (32, y)], c.stroke_width(2)))?;
        }
        Style::Dashed => {
            for x in [6, 16, 26] {
                side.draw(&PathElement::new(
                    vec![(x, y), (x + 6, y)],
                    c.stroke_width(2),
                ))?;
            }
        }
        Style::Dotted => {
            for x in (6..32).step_by(6) {
                side.draw(&PathElement::new(
                    vec![(x, y), (x + 2, y)],
                    c.stroke_width(2),
                ))?;
            }
        }
        Style::Points(r) if s.marker.is_none() => {
            side.draw(&Circle::new((19, y), r.clamp(2, 5), c.filled()))?;
        }
        Style::Points(_) => {}
        Style::Cells(..) | Style::Heat(..) => {
            side.draw(&Rectangle::new([(8, y - 6), (30, y + 6)], c.filled()))?;
        }
    }
    if let Some(m) = s.marker {
        let r = m.size.clamp(2, 6);
        match m.shape {
            Shape::Disc => side.draw(&Circle::new((19, y), r, c.filled()))?,
            Shape::Ring => {
                side.draw(&Circle::new((19, y), r, WHITE.filled()))?;
                side.draw(&Circle::new((19, y), r, c.stroke_width(2)))?;
            }
            Shape::Diamond => {
                let d = (r + r / 3) as i32;
                side.draw(&Polygon::new(
                    vec![(19, y - d), (19 + d, y), (19, y + d), (19 - d, y)],
                    c.filled(),
                ))?;
            }
        }
    }
    Ok(())
}

/// A vertical colour bar under `top`: the quantity, the scale, five tick
/// values, and the swatch of cells without a value when there are some.
fn colour_bar<DB: DrawingBackend>(
    side: &DrawingArea<DB, Shift>,
    s: &Series,
    scale: &super::colour::ColourScale,
    top: i32,
) -> Result<i32, Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let mut y = top;
    for line in wrap(&scale.label, 24) {
        side.draw(&Text::new(line, (6, y), FONT))?;
        y += 15;
    }
    side.draw(&Text::new(scale.kind.name(), (6, y), ("sans-serif", 11)))?;
    y += 18;
    let height = (side.dim_in_pixel().1 as i32 - y - 50).clamp(60, 260);
    const STEPS: i32 = 64;
    for k in 0..STEPS {
        // Top of the bar is the largest value.
        let t = 1.0 - (k as f64 + 0.5) / STEPS as f64;
        let (a, b) = (y + k * height / STEPS, y + (k + 1) * height / STEPS);
        side.draw(&Rectangle::new([(8, a), (30, b + 1)], colormap(t).filled()))?;
    }
    side.draw(&Rectangle::new(
        [(8, y), (30, y + height)],
        BLACK.stroke_width(1),
    ))?;
    for k in 0..=4 {
        let t = f64::from(k) / 4.0;
        let at = y + ((1.0 - t) * f64::from(height)).round() as i32;
        side.draw(&PathElement::new(
            vec![(30, at), (35, at)],
            BLACK.stroke_width(1),
        ))?;
        if let Some(v) = scale.value_at(t) {
            side.draw(&Text::new(tick(v), (38, at - 6), FONT))?;
        }
    }
    y += height + 14;
    let missing = s
        .values
        .as_deref()
        .is_some_and(|v| v.iter().any(|x| !x.is_finite()));
    if missing {
        side.draw(&Rectangle::new([(8, y), (30, y + 12)], NO_VALUE.filled()))?;
        side.draw(&Rectangle::new(
            [(8, y), (30, y + 12)],
            BLACK.stroke_width(1),
        ))?;
        side.draw(&Text::new("no value", (38, y - 1), FONT))?;
        y += ROW;
    }
    Ok(y)
}

/// A tick value to three significant digits.
fn tick(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(1e-2..1e5).contains(&a) {
        format!("{v:.2e}")
    } else if a >= 100.0 {
        format!("{v:.0}")
    } else if a >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.3}")
    }
}

/// Words of `text` in lines of at most `width` characters.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split_whitespace() {
        let last = lines.last_mut().expect("one line");
        if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > width {
            lines.push(word.to_string());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_wrap_on_words_and_ticks_keep_three_digits() {
        assert_eq!(
            wrap("with sensor_delay + roll_steer", 22),
            ["with sensor_delay +", "roll_steer"]
        );
        assert_eq!(wrap("short", 22), ["short"]);
        assert_eq!(tick(0.12345), "0.123");
        assert_eq!(tick(12.345), "12.3");
        assert_eq!(tick(1234.4), "1234");
        assert_eq!(tick(1.5e-4), "1.50e-4");
    }

    #[test]
    fn a_key_beside_a_chart_gives_each_wrapped_label_its_own_lines() {
        use crate::report::series::Series;
        let entry = |label: &str| Series::line(label, &[0.0], &[0.0], 0);
        let series = [
            entry("yaw rate r, base model"),
            entry("yaw rate r, with load_transfer_distribution + roll_camber + accelerometer_position"),
            entry(""),
            entry("3 × noise floor"),
        ];
        // One line, four lines (20 + 3·15 px), one line; the unlabelled
        // series has no entry.
        let (at, bottom) = side_layout(&series);
        assert_eq!(at, [40, 60, 125]);
        assert_eq!(bottom, 145);
        assert_eq!(side_height(&series), 155);
        assert_eq!(side_height(&[entry("")]), 0);
        // Each entry starts below the previous one's last line.
        let lines = wrap(&series[1].label, WRAP).len() as i32;
        assert!(at[2] - 7 >= at[1] - 7 + (lines - 1) * LINE + LINE);
    }
}
