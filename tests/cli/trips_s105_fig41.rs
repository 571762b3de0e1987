//! Round 35's figure findings, on the PNGs a user's commands write.
//!
//! The fits' figures (`identify … --model mf61`, one per stage, and the
//! swarm fits' `--model magic-simple`) drew each load's measured points
//! in the colour of its fitted line: on the Hoosier file's ~400 points a
//! panel the points formed a band in which the line could not be seen.
//! The points are now pale and the line, in the full colour, is drawn over
//! them. A replay's panels (`simulate` of a `kind = "replay"` scenario)
//! had plotters' minor grid at ten lines a labelled step whatever the
//! panel's height: the sideslip panel's lines lay 2 px apart and read as
//! a grey fill.

use super::*;
use crate::trips_s91_diag::png_pixels;
use handling::report::plot::palette;

/// A pure lateral sweep of the MF 6.1 fixture at three loads, ±12° every
/// 0.1° (241 rows a load, as dense as a rig's), with ±1.5 % scatter, in
/// `dir/dense.csv`.
fn dense_lateral_rig(dir: &Path) -> PathBuf {
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [3000, 4500, 6000] {
        for i in -120..=120 {
            let alpha = (0.1 * f64::from(i)).to_radians();
            points += &format!("{fz},0,{alpha},0,16.7\n");
        }
    }
    let clean = dir.join("clean.csv");
    mf61_evaluated(&written(dir, "points.csv", &points), &clean);
    let (head, rows) = numeric_csv(&clean);
    let (fz, alpha, fy) = (
        column(&head, "fz"),
        column(&head, "alpha"),
        column(&head, "fy"),
    );
    let mut text = String::from("fz,alpha,fy\n");
    for (i, r) in rows.iter().enumerate() {
        let scatter = 1.0 + 0.015 * (((i * 7) % 5) as f64 - 2.0) / 2.0;
        text += &format!("{},{},{}\n", r[fz], r[alpha], r[fy] * scatter);
    }
    written(dir, "dense.csv", &text)
}

/// How the pixels of load `k`'s line colour lie in the chart of a
/// one-column fit figure of three loads (left of its key's 200 px
/// column): the columns holding it; those of its span without it where
/// no other load's line crosses it there; the median over its columns of
/// its vertical spread (px) and its pixels per column; whether each
/// column's pixels touch the next column's; and how many pixels are a
/// paler tint of it (its points, drawn lighter).
#[derive(Debug)]
struct Trace {
    columns: usize,
    hidden: usize,
    median_spread: usize,
    per_column: f64,
    joined: bool,
    paler: usize,
}

/// Whether pixel `p` is colour `c` mixed with white, at a share of
/// white between 15 and 85 % (within 6 levels in every channel).
fn paler_tint(p: &[u8], c: [u8; 3]) -> bool {
    let i = (0..3).max_by_key(|&i| 255 - c[i]).unwrap();
    let share = f64::from(255 - p[i]) / f64::from(255 - c[i]);
    let mixed = |j: usize| 255.0 - share * f64::from(255 - c[j]);
    share > 0.15 && share < 0.85 && (0..3).all(|j| (f64::from(p[j]) - mixed(j)).abs() <= 6.0)
}

/// The line colour of load `k` (the palette's first three).
fn line_colour(k: usize) -> [u8; 3] {
    let c = palette(k);
    [c.0, c.1, c.2]
}

fn trace(png: &Path, k: usize) -> Trace {
    let (rgb, w, h) = png_pixels(png);
    let c = line_colour(k);
    let chart = w - 200;
    let mut spans: Vec<Option<(usize, usize)>> = vec![None; chart];
    let mut crossed = vec![false; chart];
    let (mut paler, mut drawn) = (0, 0);
    for y in 0..h {
        for (x, span) in spans.iter_mut().enumerate() {
            let p = &rgb[3 * (y * w + x)..3 * (y * w + x) + 3];
            if p == c {
                drawn += 1;
                *span = Some(span.map_or((y, y), |(a, _)| (a, y)));
            } else if (0..3).any(|j| j != k && p == line_colour(j)) {
                crossed[x] = true;
            } else if paler_tint(p, c) {
                paler += 1;
            }
        }
    }
    let at: Vec<usize> = (0..chart).filter(|&x| spans[x].is_some()).collect();
    let (first, last) = (at[0], at[at.len() - 1]);
    let hidden = (first..=last)
        .filter(|&x| spans[x].is_none() && !crossed[x])
        .count();
    let mut spread: Vec<usize> = at
        .iter()
        .filter_map(|&x| spans[x].map(|(a, b)| b - a))
        .collect();
    spread.sort_unstable();
    let joined = (first..last).all(|x| match (spans[x], spans[x + 1]) {
        (Some((a0, b0)), Some((a1, b1))) => a0 <= b1 + 1 && a1 <= b0 + 1,
        _ => true,
    });
    Trace {
        columns: at.len(),
        hidden,
        median_spread: spread[spread.len() / 2],
        per_column: f64::from(drawn) / at.len() as f64,
        joined,
        paler,
    }
}

/// Each of the three loads' fitted curves in `png` is one unbroken line
/// in its full colour across the chart, broken only where another
/// load's line crosses it (so drawn over its points: a hollow point drawn
/// after it would break it), a line's width thick (its points are not in
/// its colour), over points drawn in a paler tint.
fn fitted_lines_read_over_their_points(png: &Path) {
    for k in 0..3 {
        let t = trace(png, k);
        println!("{}: load {k}: {t:?}", png.display());
        let ok = t.columns >= 500
            && t.hidden == 0
            && t.joined
            && t.median_spread <= 4
            && t.per_column <= 3.5
            && t.paler >= 600;
        assert!(ok, "{}: load {k}: {t:?}", png.display());
    }
}

/// Before: the rings of each load were drawn in its line's colour, 2 px
/// wide: in a column through the band of points the colour spread over
/// the rings' height (median 6 px, 6.6 to 7.0 px of it a column where
/// the line alone has 2.8 to 3.2), under 430 pixels of a paler tint (the
/// rings' smoothed edges; now 3200 to 3400), and the line could not be
/// told from its points.
#[test]
fn a_staged_fits_curve_is_a_line_in_its_full_colour_over_paler_points() {
    let dir = tempfile::tempdir().unwrap();
    let rig = dense_lateral_rig(dir.path());
    let out = dir.path().join("fit.tir");
    let o = identify_to(&rig, "mf61", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    fitted_lines_read_over_their_points(&out.with_extension("pure-fy.png"));
}

/// Before: a swarm fit drew each load's points as filled dots of its
/// line's colour: 4.1 to 4.5 px of it a column (the line alone 2.9 to
/// 3.2), under 270 pixels of a paler tint (now 940 to 1140).
#[test]
fn a_swarm_fits_curve_is_a_line_in_its_full_colour_over_paler_points() {
    let dir = tempfile::tempdir().unwrap();
    let rig = dense_lateral_rig(dir.path());
    let out = dir.path().join("simple.toml");
    let o = identify_to(&rig, "magic-simple", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    fitted_lines_read_over_their_points(&out.with_extension("png"));
}

/// A replay log of 20 s at 20 m/s with a slow steer, a yaw rate and a
/// lateral acceleration of its size, and a sideslip of a tenth of a
/// degree (a small range: plotters' minor step was a hundredth of it).
fn small_sideslip_log() -> String {
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in 0..=2000 {
        let t = 0.01 * f64::from(i);
        let s = (0.5 * t).sin();
        csv += &format!(
            "{t:.2},20.0,{:.6},{:.6},{:.6},{:.7}\n",
            0.02 * s,
            0.1 * s,
            2.0 * s,
            0.002 * s
        );
    }
    csv
}

/// The rows (or columns, `across`) of panel band `rows` of `png` that are
/// a minor grid line: at least 300 px of the chart's light grey.
fn grid_lines(rgb: &[u8], w: usize, rows: std::ops::Range<usize>, across: bool) -> Vec<usize> {
    const MINOR: [u8; 3] = [235, 235, 235];
    let (x0, x1) = (80, w - 220);
    let is = |x: usize, y: usize| rgb[3 * (y * w + x)..3 * (y * w + x) + 3] == MINOR;
    if across {
        (x0..x1)
            .filter(|&x| rows.clone().filter(|&y| is(x, y)).count() >= 100)
            .collect()
    } else {
        rows.filter(|&y| (x0..x1).filter(|&x| is(x, y)).count() >= 300)
            .collect()
    }
}

/// Before: every panel of `response.png` had a light line every 2 to 3 px
/// (the sideslip's every 0.002°, 90 of them over 180 px). Now no two
/// lines of a panel's minor grid are closer than 7 px, in x and in y, and
/// the grid is still there.
#[test]
fn a_replays_panels_draw_their_minor_grid_no_finer_than_it_reads() {
    let dir = tempfile::tempdir().unwrap();
    linear_tyre(dir.path());
    let scenario = replay_of(dir.path(), &small_sideslip_log());
    let out = dir.path().join("out");
    scenarios::simulate_to(&scenario, &out);
    let (rgb, w, h) = png_pixels(&out.join("response.png"));
    let panels = 5;
    let band = h / panels;
    let mut drawn = 0;
    for k in 0..panels {
        // Below the panel's title, above its x labels.
        let rows = k * band + 40..(k + 1) * band - 40;
        for across in [false, true] {
            let at = grid_lines(&rgb, w, rows.clone(), across);
            drawn += at.len();
            let closest = at.windows(2).map(|p| p[1] - p[0]).min();
            println!(
                "panel {k}, across {across}: {} lines, closest {closest:?}",
                at.len()
            );
            assert!(
                closest.is_none_or(|d| d >= 7),
                "panel {k} (across {across}): minor lines {closest:?} px apart: {at:?}"
            );
        }
    }
    assert!(drawn >= 20, "{drawn} minor grid lines in the figure");
}
