//! Text on a bitmap set with the font's own spacing: each glyph placed at
//! its pen position (the sum of the advance widths and kerning before it,
//! px, kept as a fraction of a pixel) plus its left side bearing, and
//! rasterised there with anti-aliasing. [`Typeset`] wraps a plotters
//! drawing backend and takes over its text; everything else passes through.
//!
//! Why: plotters 0.3.7 draws `ab_glyph` text with each glyph's ink box put
//! at the pen position truncated to a whole pixel, so the left side bearing
//! is lost and the rounding errors vary from glyph to glyph: a "1" (bearing
//! 225 of 2048 font units, 1.2 px at 13 px) sat against the glyph before
//! it and "step_100" read "step_1 00". Glyphs below half the text size (a
//! minus, a point) also sat a pixel higher than the rest.
//!
//! Units: pixels, y down (the bitmap's). The size of a text is plotters':
//! the font's ascent less its descent, px (DejaVu Sans at 13 px has an em
//! of 13 / 1.164 = 11.2 px). The text's box, as plotters measures it (and
//! as its own `Text` elements are placed by it): the advance widths and
//! kerning summed, truncated to whole pixels, by the size / 1.24; the
//! baseline half the size, rounded up, below the box's top, where plotters
//! put the baseline of a capital. Rotated text (a y axis's label) turns
//! about the box's corner as plotters turns it.
//!
//! Every text is set in the embedded DejaVu Sans (Bitstream 2003, DejaVu
//! fonts 2004–2016), whatever family its style names: it is the only font
//! the figures use. SVG is not drawn here: a browser sets its text.

use ab_glyph::{point, Font, FontRef, GlyphId, PxScale, ScaleFont};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use std::sync::OnceLock;

/// DejaVu Sans, compiled in (no system fonts needed).
pub(super) static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

/// The embedded font, parsed once.
fn font() -> &'static FontRef<'static> {
    static PARSED: OnceLock<FontRef<'static>> = OnceLock::new();
    // The font is compiled in: failing to parse it is a build defect.
    PARSED.get_or_init(|| FontRef::try_from_slice(FONT).expect("embedded font is invalid"))
}

/// A line of text laid out at `size` px: each glyph with its pen position
/// (px from the box's left edge, fractional), and the total advance, px.
pub(super) struct Line {
    /// Glyphs with their pen positions.
    pub glyphs: Vec<(GlyphId, f32)>,
    /// The sum of the advances and kerning, px.
    pub advance: f32,
    /// The size set at, px.
    pub size: f32,
}

impl Line {
    /// `text` laid out at `size` px: pen positions accumulated in
    /// fractions of a pixel, never rounded on the way.
    pub fn of(text: &str, size: f64) -> Self {
        let size = size as f32;
        let scaled = font().as_scaled(PxScale::from(size));
        let mut pen = 0f32;
        let mut prev: Option<GlyphId> = None;
        let mut glyphs = Vec::with_capacity(text.len());
        for c in text.chars() {
            let id = scaled.glyph_id(c);
            if let Some(p) = prev {
                pen += scaled.kern(p, id);
            }
            glyphs.push((id, pen));
            pen += scaled.h_advance(id);
            prev = Some(id);
        }
        Self {
            glyphs,
            advance: pen,
            size,
        }
    }

    /// The text's box, px: as plotters measures it (its `Text` elements
    /// are placed with that), so that a label measured fits as drawn.
    pub fn box_size(&self) -> (u32, u32) {
        (
            self.advance.max(0.0) as u32,
            (f64::from(self.size) / 1.24) as u32,
        )
    }

    /// The baseline below the box's top, px (whole: rows of stems and
    /// bowls land on the same pixels in every glyph).
    fn baseline(&self) -> f32 {
        (self.size / 2.0).ceil()
    }

    /// Each pixel the line covers, relative to its box's top left corner,
    /// with its coverage (0 to 1): each glyph at its pen position plus its
    /// bearing, rasterised at that fractional position.
    pub fn coverage(&self, mut out: impl FnMut(i32, i32, f32)) {
        let scale = PxScale::from(self.size);
        let baseline = self.baseline();
        for &(id, pen) in &self.glyphs {
            let glyph = id.with_scale_and_position(scale, point(pen, baseline));
            if let Some(outline) = font().outline_glyph(glyph) {
                let at = outline.px_bounds().min;
                let (x0, y0) = (at.x as i32, at.y as i32);
                outline.draw(|x, y, c| {
                    if c > 0.0 {
                        out(x0 + x as i32, y0 + y as i32, c.min(1.0));
                    }
                });
            }
        }
    }
}

/// A drawing backend whose text is set by [`Line`]; everything else is
/// the wrapped backend's.
pub struct Typeset<DB>(pub DB);

impl<DB: DrawingBackend> DrawingBackend for Typeset<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.fill_polygon(vert, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.blit_bitmap(pos, size, src)
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        Ok(Line::of(text, style.size()).box_size())
    }

    /// The text anchored at `pos` as plotters anchors it (its box's
    /// corner, centre or edge), turned by the style's rotation, each pixel
    /// blended in the style's colour by its coverage.
    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let line = Line::of(text, style.size());
        let (width, height) = line.box_size();
        let (width, height) = (width as i32, height as i32);
        let anchor = style.anchor();
        let dx = match anchor.h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = match anchor.v_pos {
            VPos::Top => 0,
            VPos::Center => -height / 2,
            VPos::Bottom => -height,
        };
        let turn = style.transform();
        let (w, h) = self.0.get_size();
        let mut result = Ok(());
        line.coverage(|x, y, c| {
            let (x, y) = turn.transform(x + dx, y + dy);
            let (x, y) = (pos.0 + x, pos.1 + y);
            let inside = x >= 0 && y >= 0 && x < w as i32 && y < h as i32;
            if inside && result.is_ok() {
                let alpha = color.alpha * f64::from(c);
                result = self.0.draw_pixel((x, y), BackendColor { alpha, ..color });
            }
        });
        result
    }
}

#[cfg(test)]
#[path = "typeset_tests.rs"]
mod tests;
