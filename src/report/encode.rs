//! A drawn figure's RGB pixels written as a PNG with a palette: a figure
//! of white, greys, black and a dozen series colours has about a thousand
//! distinct colours, nearly all of them the anti-aliased edges of lines,
//! discs and glyphs. The 255 most frequent are kept exactly and every
//! other pixel (about 0.1 % of them on a grid of fit panels) takes the
//! nearest of those, so the image reads as drawn at a quarter of the size
//! of true colour; zlib at its best level with adaptive filters on top
//! (plotters' own encoder writes fast and several times larger). An image
//! whose colours do not fit a palette that way (more than
//! [`MAX_INEXACT`] of its pixels would change: a map of many cells on a
//! continuous colour scale) is written in true colour.

use std::collections::HashMap;
use std::io::Write;

/// The largest share of pixels a palette may change.
const MAX_INEXACT: f64 = 0.005;

/// The colours of `rgb` (3 bytes a pixel) as a palette of at most 256
/// entries and each pixel's index in it, or `None` when more than
/// [`MAX_INEXACT`] of the pixels would take a colour not their own.
fn indexed(rgb: &[u8]) -> Option<(Vec<[u8; 3]>, Vec<u8>)> {
    let mut count: HashMap<[u8; 3], usize> = HashMap::new();
    for p in rgb.chunks_exact(3) {
        *count.entry([p[0], p[1], p[2]]).or_default() += 1;
    }
    let mut by_use: Vec<([u8; 3], usize)> = count.into_iter().collect();
    // Ties broken by colour, so that the file is the same on every run.
    by_use.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let inexact: usize = by_use.iter().skip(256).map(|c| c.1).sum();
    if inexact as f64 > MAX_INEXACT * (rgb.len() / 3) as f64 {
        return None;
    }
    let palette: Vec<[u8; 3]> = by_use.iter().take(256).map(|c| c.0).collect();
    let mut index: HashMap<[u8; 3], u8> = palette
        .iter()
        .enumerate()
        .map(|(i, c)| (*c, i as u8))
        .collect();
    let pixels = rgb
        .chunks_exact(3)
        .map(|p| {
            let c = [p[0], p[1], p[2]];
            *index.entry(c).or_insert_with(|| nearest(&palette, c))
        })
        .collect();
    Some((palette, pixels))
}

/// The index of the palette colour nearest `c` (squared RGB distance).
fn nearest(palette: &[[u8; 3]], c: [u8; 3]) -> u8 {
    let d = |p: &[u8; 3]| {
        (0..3)
            .map(|k| (i32::from(p[k]) - i32::from(c[k])).pow(2))
            .sum::<i32>()
    };
    (0..palette.len())
        .min_by_key(|&i| d(&palette[i]))
        .unwrap_or(0) as u8
}

/// Writes the `width` × `height` image `rgb` to `out` as a PNG with a
/// palette (module notes).
pub(super) fn write_png(
    out: impl Write,
    width: u32,
    height: u32,
    rgb: &[u8],
) -> Result<(), png::EncodingError> {
    let mut png = png::Encoder::new(out, width, height);
    png.set_depth(png::BitDepth::Eight);
    png.set_compression(png::Compression::Best);
    png.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    let pixels = match indexed(rgb) {
        Some((palette, pixels)) => {
            png.set_color(png::ColorType::Indexed);
            png.set_palette(palette.concat());
            pixels
        }
        None => {
            png.set_color(png::ColorType::Rgb);
            rgb.to_vec()
        }
    };
    let mut writer = png.write_header()?;
    writer.write_image_data(&pixels)?;
    writer.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_few_colours_are_kept_exactly_and_a_rare_one_takes_the_nearest() {
        // 300 colours: the 256 most frequent kept, the rest mapped.
        let mut rgb = Vec::new();
        for k in 0..300u32 {
            let n = if k < 256 { 1000 - k } else { 1 };
            for _ in 0..n {
                rgb.extend_from_slice(&[(k % 256) as u8, (k / 256) as u8 * 100, 7]);
            }
        }
        let (palette, pixels) = indexed(&rgb).unwrap();
        assert_eq!(palette.len(), 256);
        for (p, &i) in rgb.chunks_exact(3).zip(&pixels) {
            let got = palette[i as usize];
            if p[1] == 0 {
                assert_eq!(got, [p[0], p[1], p[2]]);
            } else {
                // (k, 100, 7) for k < 44: nearest is (k, 0, 7).
                assert_eq!(got, [p[0], 0, 7]);
            }
        }
    }

    #[test]
    fn an_image_of_many_colours_keeps_them_all() {
        // 1000 colours in equal shares: a palette would change most pixels.
        let rgb: Vec<u8> = (0..1000u32)
            .flat_map(|k| [(k % 256) as u8, (k / 256) as u8, 0])
            .collect();
        assert!(indexed(&rgb).is_none());
        let mut file = Vec::new();
        write_png(&mut file, 1000, 1, &rgb).unwrap();
        let mut reader = png::Decoder::new(file.as_slice()).read_info().unwrap();
        assert_eq!(reader.info().color_type, png::ColorType::Rgb);
        let mut buf = vec![0; reader.output_buffer_size()];
        reader.next_frame(&mut buf).unwrap();
        assert_eq!(buf, rgb);
    }

    #[test]
    fn the_written_png_decodes_to_the_palette_colours() {
        let rgb: Vec<u8> = (0..16 * 8)
            .flat_map(|i| {
                if i % 3 == 0 {
                    [255, 255, 255]
                } else {
                    [31, 119, 180]
                }
            })
            .collect();
        let mut file = Vec::new();
        write_png(&mut file, 16, 8, &rgb).unwrap();
        let mut decoder = png::Decoder::new(file.as_slice());
        // The indices as stored, expanded here through the palette.
        decoder.set_transformations(png::Transformations::IDENTITY);
        let mut reader = decoder.read_info().unwrap();
        let info = reader.info();
        assert_eq!((info.width, info.height), (16, 8));
        assert_eq!(info.color_type, png::ColorType::Indexed);
        let palette = info.palette.as_ref().unwrap().to_vec();
        let mut buf = vec![0; reader.output_buffer_size()];
        reader.next_frame(&mut buf).unwrap();
        let decoded: Vec<u8> = buf
            .iter()
            .flat_map(|&i| palette[3 * i as usize..3 * i as usize + 3].to_vec())
            .collect();
        assert_eq!(decoded, rgb);
    }
}
