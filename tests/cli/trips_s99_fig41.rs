//! The Magic Formula fit figure, as a user makes it
//! (`identify cornering.csv --model mf61 --out o` on the public Hoosier
//! file): the fitted curves were drawn in black over points coloured by
//! load, so that which curve belonged to which load, and how close each
//! lay to its points, could not be read. Each load's curve is now drawn
//! in its points' colour (the figure's series are tested in
//! `src/jobs/identify/staged_figure_tests.rs`; here, on the PNG written).

use super::*;
use crate::trips_s91_diag::png_pixels;
use handling::report::plot::palette;

/// The pixels of `rgb` of exactly the colour `c`.
fn count(rgb: &[u8], c: [u8; 3]) -> usize {
    rgb.chunks_exact(3).filter(|p| *p == c).count()
}

/// Before: 106,606 pure black pixels (the 90 fitted curves, 2 px wide,
/// with the axes and text) against 23,679 to 28,407 of each load's
/// colour (its points alone). Now the curves are in the loads' colours:
/// black is left to the axes and text, fewer pixels than any one load's
/// colour, and each load's colour covers its points and its curves.
#[test]
fn each_loads_fitted_curve_is_drawn_in_its_points_colour_not_black() {
    let test = "each_loads_fitted_curve_is_drawn_in_its_points_colour_not_black";
    let Some(fit) = hoosier_mf61(test) else {
        return;
    };
    // The pure lateral force's figure (a figure per stage).
    let (rgb, w, h) = png_pixels(&fit.tir.with_extension("pure-fy.png"));
    let black = count(&rgb, [0, 0, 0]);
    // The five loads' colours, the palette's first five (none the key's grey).
    let loads: Vec<usize> = (0..5)
        .map(|k| {
            let c = palette(k);
            count(&rgb, [c.0, c.1, c.2])
        })
        .collect();
    let least = *loads.iter().min().unwrap();
    println!("{w}×{h} px: black {black}, loads {loads:?}");
    assert!(
        black < least,
        "{black} black pixels, the least-drawn load colour {least}: the curves are black"
    );
}
