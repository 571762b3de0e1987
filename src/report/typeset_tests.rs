//! Tests of the text setting (`typeset.rs`): a line drawn on a bitmap and
//! its glyphs found in the pixels, against the font's metrics read apart
//! from the drawing (advance widths, kerning, outline bounds).

use super::*;
use crate::report::series::LABEL_PX;
use plotters::prelude::*;

/// Who sets a test's text: this module, or plotters' own drawing (the
/// defect, kept as the check's negative control).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Setter {
    /// [`Typeset`] over the bitmap.
    Typeset,
    /// The bare bitmap backend: plotters' `ab_glyph` text.
    Plotters,
}

/// Black `text` at `size` px drawn with its box's top left at (4, 4) on a
/// white bitmap as wide as it needs; the bitmap's ink per column (the sum
/// of the darkness of the column's pixels, 0 to 255 each).
fn column_ink(text: &str, size: u32, by: Setter) -> Vec<u32> {
    super::super::plot::ensure_font();
    let (w, h) = (Line::of(text, f64::from(size)).box_size().0 + 16, 2 * size);
    let mut rgb = vec![0u8; 3 * (w * h) as usize];
    let label = Text::new(text, (4, 4), ("sans-serif", size));
    match by {
        Setter::Typeset => {
            let root = Typeset(BitMapBackend::with_buffer(&mut rgb, (w, h))).into_drawing_area();
            root.fill(&WHITE).unwrap();
            root.draw(&label).unwrap();
            root.present().unwrap();
        }
        Setter::Plotters => {
            let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
            root.fill(&WHITE).unwrap();
            root.draw(&label).unwrap();
            root.present().unwrap();
        }
    }
    (0..w as usize)
        .map(|x| {
            (0..h as usize)
                .map(|y| 255 - u32::from(rgb[3 * (y * w as usize + x)]))
                .sum()
        })
        .collect()
}

/// The runs of inked columns, [first, last], left to right: a column is
/// inked where its darkness sums to a fifth of a pixel's or more (the
/// faintest anti-aliased fringe is not a glyph's edge).
fn ink_runs(ink: &[u32]) -> Vec<(usize, usize)> {
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for (x, &v) in ink.iter().enumerate() {
        if v < 51 {
            continue;
        }
        match runs.last_mut() {
            Some(run) if run.1 + 1 == x => run.1 = x,
            _ => runs.push((x, x)),
        }
    }
    runs
}

/// Where the font puts each glyph's ink, [left, right) px from the box's
/// left edge: its pen position (advances and kerning before it) plus its
/// left side bearing, to plus the outline's right extent.
fn metric_ink(text: &str, size: f32) -> Vec<(f32, f32)> {
    let scaled = font().as_scaled(PxScale::from(size));
    let mut pen = 0f32;
    let mut prev: Option<GlyphId> = None;
    let mut out = Vec::new();
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        pen += prev.map_or(0.0, |p| scaled.kern(p, id));
        let right = font().outline(id).unwrap().bounds.max.x * scaled.h_scale_factor();
        out.push((pen + scaled.h_side_bearing(id), pen + right));
        pen += scaled.h_advance(id);
        prev = Some(id);
    }
    out
}

/// Each glyph of `text`, found in the pixels as a run of inked columns,
/// starts and ends within a pixel of where the font's metrics put its
/// ink (the runs measured from the box's left edge at x = 4).
fn glyphs_sit_where_the_font_puts_them(text: &str, size: u32, by: Setter) {
    let runs = ink_runs(&column_ink(text, size, by));
    let want = metric_ink(text, size as f32);
    assert_eq!(runs.len(), want.len(), "{text:?} at {size} px: {runs:?}");
    for ((c, run), (left, right)) in text.chars().zip(&runs).zip(&want) {
        let (first, last) = (run.0 as f32 - 4.0, run.1 as f32 + 1.0 - 4.0);
        assert!(
            (first - left).abs() <= 1.0 && (last - right).abs() <= 1.0,
            "{text:?} at {size} px: {c:?} inked over [{first}, {last}) px, \
             the font puts it over [{left:.2}, {right:.2})"
        );
    }
}

/// Texts whose glyphs stand apart in the pixels, with the size set at: a
/// "1" has a wide left bearing (1.2 px at 13 px, 2.5 at 26).
const SPACED: [(&str, u32); 6] = [
    ("11", LABEL_PX),
    ("100", LABEL_PX),
    ("11", 26),
    ("sensor", 26),
    ("1.01", 26),
    ("11", 40),
];

#[test]
fn each_glyph_is_drawn_where_the_fonts_advances_and_bearings_put_it() {
    for (text, size) in SPACED {
        glyphs_sit_where_the_font_puts_them(text, size, Setter::Typeset);
    }
}

#[test]
fn plotters_own_text_puts_glyphs_off_their_place() {
    // The negative control: plotters 0.3.7 set each glyph's ink at the
    // truncated pen position, its bearing lost ("step_1 00", "sen sor"),
    // and the check above finds it in every text. Should a plotters
    // upgrade set text right, this fails and `Typeset` may go.
    for (text, size) in SPACED {
        let caught = std::panic::catch_unwind(|| {
            glyphs_sit_where_the_font_puts_them(text, size, Setter::Plotters)
        });
        assert!(caught.is_err(), "{text:?} at {size} px sits right");
    }
}

#[test]
fn a_text_measures_as_plotters_places_it() {
    // plotters places its Text elements (a legend's lines) by its own
    // measure: the backend's must agree with it, or a label measured to
    // fit would be drawn wider or narrower than measured.
    super::super::plot::ensure_font();
    for text in [
        "sensor_delay step_100",
        "11",
        "δ [deg]",
        "ay [m/s²]",
        "-0.25",
        "",
    ] {
        for size in [11.0, 13.0, 16.0] {
            let plotters = ("sans-serif", size).into_font().box_size(text).unwrap();
            assert_eq!(
                Line::of(text, size).box_size(),
                plotters,
                "{text:?} at {size}"
            );
        }
    }
}

#[test]
fn a_rotated_label_reads_upwards_from_its_anchor() {
    // A y axis's label is turned 270° clockwise (plotters' Rotate270):
    // its line runs up the image from the anchor, as long as its box.
    super::super::plot::ensure_font();
    let (w, h) = (60u32, 120u32);
    let mut rgb = vec![0u8; 3 * (w * h) as usize];
    {
        let root = Typeset(BitMapBackend::with_buffer(&mut rgb, (w, h))).into_drawing_area();
        root.fill(&WHITE).unwrap();
        let style = ("sans-serif", 13)
            .into_font()
            .transform(FontTransform::Rotate270)
            .color(&BLACK);
        root.draw(&Text::new("r [deg/s]", (30, 100), style))
            .unwrap();
        root.present().unwrap();
    }
    let inked = |x: usize, y: usize| rgb[3 * (y * w as usize + x)] < 128;
    let pixels: Vec<(usize, usize)> = (0..h as usize)
        .flat_map(|y| (0..w as usize).map(move |x| (x, y)))
        .filter(|&(x, y)| inked(x, y))
        .collect();
    assert!(!pixels.is_empty());
    let length = Line::of("r [deg/s]", 13.0).box_size().0 as usize;
    let (top, bottom) = (
        pixels.iter().map(|p| p.1).min().unwrap(),
        pixels.iter().map(|p| p.1).max().unwrap(),
    );
    assert!(bottom <= 100 && bottom + 3 >= 100, "{top}..{bottom}");
    assert!(
        (bottom - top).abs_diff(length) <= 3,
        "{top}..{bottom} for {length}"
    );
}
