//! Tests of the figures (`plot.rs`): drawn as SVG and measured.

use super::*;

/// The numbers of attribute `attr` of every `<tag` element of an SVG.
fn attrs(svg: &str, tag: &str, attr: &str) -> Vec<f64> {
    svg.split(&format!("<{tag} "))
        .skip(1)
        .filter_map(|e| {
            let e = format!(" {e}");
            let at = e.find(&format!(" {attr}=\""))? + attr.len() + 3;
            e[at..].split('"').next()?.parse().ok()
        })
        .collect()
}

/// (x, content) of every `<text>` element of an SVG.
fn texts(svg: &str) -> Vec<(f64, String)> {
    svg.split("<text ")
        .skip(1)
        .filter_map(|e| {
            let x = attrs(&format!("<text {e}"), "text", "x").first().copied()?;
            let body = e.split_once('>')?.1.split("</text>").next()?;
            Some((x, body.trim().to_string()))
        })
        .collect()
}

/// One panel `width` px wide: `n` measured points and a model line.
fn measured_and_model(n: u32, width: u32) -> Figure {
    let x: Vec<f64> = (0..n).map(f64::from).collect();
    Figure {
        width,
        ..Figure::stack(vec![Panel {
            series: vec![
                Series::line("measured", &x, &x, 0).styled(Style::Points(2)),
                Series::line("base model", &x, &x, 1),
            ],
            ..Panel::default()
        }])
    }
}

#[test]
fn the_key_sits_beside_the_data_never_over_it() {
    let fig = measured_and_model(50, 900);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let edge = f64::from(900 - SIDE);
    let circles = attrs(&svg, "circle", "cx");
    // Every data point left of the key's column, the key's swatch in it.
    assert_eq!(circles.iter().filter(|&&c| c < edge).count(), 50);
    assert_eq!(circles.iter().filter(|&&c| c >= edge).count(), 1);
    let labels: Vec<(f64, String)> = texts(&svg)
        .into_iter()
        .filter(|(_, t)| t == "measured" || t == "base model")
        .collect();
    assert_eq!(labels.len(), 2, "{svg}");
    assert!(labels.iter().all(|(x, _)| *x >= edge), "{labels:?}");
}

#[test]
fn stacked_panels_share_one_time_axis_whether_or_not_they_have_a_key() {
    // A steer without a key above a yaw rate with one (simulate's
    // response.png): t = 10 s falls at one x in both.
    let t: Vec<f64> = (0..=10).map(f64::from).collect();
    let y: Vec<f64> = t.iter().map(|t| 0.05 * t).collect();
    let panel = |label: &str| Panel {
        series: vec![Series::line(label, &t, &y, 0)],
        x_range: Some((0.0, 10.0)),
        ..Panel::default()
    };
    let fig = Figure::stack(vec![panel(""), panel("model")]);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let tens: Vec<f64> = texts(&svg)
        .into_iter()
        .filter(|(_, t)| t == "10")
        .map(|(x, _)| x)
        .collect();
    assert_eq!(tens.len(), 2, "{svg}");
    assert!((tens[0] - tens[1]).abs() < 0.5, "{tens:?}");
    // Alone, an unkeyed panel takes the whole width.
    let alone = Figure::stack(vec![panel("")])
        .svg(Path::new("t.svg"))
        .unwrap();
    let ten = texts(&alone)
        .into_iter()
        .find(|(_, t)| t == "10")
        .unwrap()
        .0;
    assert!(ten > tens[0] + 0.5 * f64::from(SIDE), "{ten} {tens:?}");
}

#[test]
fn tick_labels_are_written_as_a_reader_writes_numbers() {
    assert_eq!(tick_label(-30.0, 20.0), "-30");
    assert_eq!(tick_label(10000.0, 20000.0), "10000");
    assert_eq!(tick_label(2.5, 20.0), "2.5");
    assert_eq!(tick_label(0.30000000000000004, 1.0), "0.3");
    assert_eq!(tick_label(0.025, 0.1), "0.025");
    assert_eq!(tick_label(-1e-17, 2.0), "0");
    assert_eq!(tick_label(1.5e-4, 1e-3), "0.00015");
}

#[test]
fn no_axis_tick_of_a_drawn_figure_ends_in_a_lone_zero_decimal() {
    // Axes over −30..30 deg and −10000..10000 N: plotters' own labels
    // would read `-30.0` and `10000.0`.
    let x = [-30.0, 0.0, 30.0];
    let fig = Figure::stack(vec![Panel {
        series: vec![Series::line("", &x, &[-10000.0, 0.0, 10000.0], 0)],
        x_range: Some((-30.0, 30.0)),
        y_range: Some((-10000.0, 10000.0)),
        ..Panel::default()
    }]);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let ticks: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
    for t in ["-30", "0", "30", "-10000", "10000"] {
        assert!(ticks.iter().any(|s| s == t), "{t} missing from {ticks:?}");
    }
    assert!(
        ticks.iter().all(|t| !t.ends_with(".0")),
        "a tick ends in .0: {ticks:?}"
    );
}

#[test]
fn the_axes_drawn_are_the_fixed_ranges_or_the_datas_with_a_margin() {
    let p = Panel {
        series: vec![Series::line("", &[0.0, 10.0], &[-1.0, 3.0], 0)],
        ..Panel::default()
    };
    assert_eq!(
        p.axes(),
        Axes {
            x: (-0.5, 10.5),
            y: (-1.2, 3.2)
        }
    );
    let fixed = Panel {
        y_range: Some((0.0, 1.0)),
        ..p
    };
    assert_eq!(fixed.axes().y, (0.0, 1.0));
    // 13 px labels on a 1000 px figure print at 6.3 pt at 170 mm.
    let f = Figure::stack(vec![]);
    assert!((f.printed_label_points() - 6.26).abs() < 0.01);
}

#[test]
fn a_heat_map_has_a_colour_bar_with_its_unit_scale_ticks_and_missing_cells() {
    let (x, y) = (vec![0.0, 1.0, 0.0, 1.0], vec![0.0, 0.0, 1.0, 1.0]);
    let values = vec![1.0, 10.0, 100.0, f64::NAN];
    let fig = Figure::stack(vec![Panel {
        series: vec![Series::heat(&x, &y, values, (1.0, 1.0), "TB [s·deg]")],
        ..Panel::default()
    }]);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let texts: Vec<String> = texts(&svg).into_iter().map(|t| t.1).collect();
    for text in [
        "TB [s·deg]",
        "log scale",
        "1.000",
        "10.0",
        "100",
        "no value",
    ] {
        assert!(
            texts.iter().any(|t| t == text),
            "{text} missing from {texts:?}"
        );
    }
}

#[test]
fn a_narrow_panel_keeps_its_key_below_the_chart() {
    let fig = measured_and_model(20, 320);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let lowest = attrs(&svg, "circle", "cy")
        .into_iter()
        .take(20)
        .fold(f64::NEG_INFINITY, f64::max);
    for label in ["measured", "base model"] {
        let y: Vec<f64> = svg
            .split("<text ")
            .skip(1)
            .filter(|e| {
                let body = e.split_once('>').map_or("", |b| b.1);
                body.split("</text>").next().map(str::trim) == Some(label)
            })
            .filter_map(|e| attrs(&format!("<text {e}"), "text", "y").first().copied())
            .collect();
        assert!(!y.is_empty(), "{label} missing from a 320 px panel");
        assert!(
            y.iter().all(|&y| y > lowest),
            "{label} at {y:?}, data down to {lowest}"
        );
    }
}

/// A grid's long panel title stays inside its panel, key column
/// included: centred over the chart alone, the Hoosier fit's "magic-simple
/// lateral force, γ 0.00°, 69.7 kPa: σ 10.91 %, 393 points" began left of
/// the image in the first column. Set smaller where it would not fit.
#[test]
fn a_long_panel_title_stays_inside_its_panel() {
    let title = "magic-simple lateral force, γ 0.00°, 69.7 kPa: σ 10.91 %, 393 points";
    let panel = || Panel {
        title: title.to_string(),
        ..measured_and_model(20, 650).panels.remove(0)
    };
    for width in [1950, 1500] {
        let fig = Figure {
            width,
            columns: 3,
            ..Figure::stack(vec![panel(), panel(), panel()])
        };
        let svg = fig.svg(Path::new("test.svg")).unwrap();
        let column = f64::from(width) / 3.0;
        let titles: Vec<&str> = svg
            .split("<text ")
            .filter(|e| e.contains("magic-simple lateral"))
            .collect();
        assert_eq!(titles.len(), 3, "{width}");
        for (k, t) in titles.iter().enumerate() {
            let attr = |name: &str| -> f64 {
                let at = t.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
                t[at..].split('"').next().unwrap().parse().unwrap()
            };
            // Centred over its whole panel, at a size whose text fits it
            // (this title's characters average under half their size).
            assert!(t.contains("text-anchor=\"middle\""), "{t}");
            let centre = (k as f64 + 0.5) * column;
            assert!((attr("x") - centre).abs() <= 1.0, "{width}: {t}");
            let size = attr("font-size");
            let chars = title.chars().count() as f64;
            assert!(
                chars * 0.5 * size <= column && size <= 16.0,
                "{width}: {size} px: {t}"
            );
        }
    }
}

#[test]
fn six_digit_tick_labels_are_spaced_to_fit_the_axis() {
    // 90000–130000 N/rad: labels of up to 6 digits, (6 + 1 + 2)·0.6·13 =
    // 70.2 px each: 7 across 500 px, and none of them closer than a label.
    let n = x_label_count(500, (85000.0, 135000.0));
    assert_eq!(n, 7);
    assert!(500.0 / n as f64 >= 6.0 * 0.6 * f64::from(LABEL_PX), "{n}");
    // Short labels on a wide axis keep plotters' 10; a narrow one 2.
    assert_eq!(x_label_count(1200, (0.0, 10.0)), 10);
    assert_eq!(x_label_count(40, (85000.0, 135000.0)), 2);
}

/// A replay's sideslip over −6°…12° on a 180 px axis: plotters' minor
/// grid drew a line every 0.2° (2 px apart, a grey fill); between the
/// labels every 2° the half step, 1°, is the finest 8 px apart.
#[test]
fn the_minor_grid_is_no_finer_than_a_legible_spacing() {
    use super::super::plot_grid::{minor_lines, GRID_PX};
    let lines = minor_lines((-6.0, 12.0), 10, 180.0);
    let odd: Vec<f64> = (-5..=11).step_by(2).map(f64::from).collect();
    assert_eq!(lines.len(), odd.len(), "{lines:?}");
    assert!(lines.iter().zip(&odd).all(|(a, b)| (a - b).abs() < 1e-9));
    // With room, a quarter of a labelled step of 2: 16 px apart, none on
    // a labelled line (the even values).
    let fine = minor_lines((-6.0, 12.0), 10, 580.0);
    // −6…12 every 0.5 less the ten labelled values.
    assert_eq!(fine.len(), 37 - 10, "{fine:?}");
    for w in fine.windows(2) {
        assert!((w[1] - w[0]) * 580.0 / 18.0 >= GRID_PX, "{fine:?}");
    }
    assert!(fine
        .iter()
        .all(|v| (v / 2.0 - (v / 2.0).round()).abs() > 1e-9));
    // A fifth of a labelled step of 1000 N, 200 N, where it fits; none on
    // an axis too short for a half.
    let force = minor_lines((-3500.0, 3500.0), 10, 700.0);
    assert!((force[1] - force[0] - 200.0).abs() < 1e-6, "{force:?}");
    assert!(minor_lines((-3500.0, 3500.0), 10, 80.0).is_empty());
    assert!(minor_lines((0.0, f64::NAN), 10, 300.0).is_empty());
}

/// A fit's points pale under its line in the full colour, drawn after
/// them: the SVG's discs are the pale tint and its line comes last.
#[test]
fn pale_points_are_drawn_in_a_tint_and_under_the_line_drawn_after_them() {
    let x: Vec<f64> = (0..20).map(f64::from).collect();
    let fig = Figure::stack(vec![Panel {
        series: vec![
            Series::line("", &x, &x, 0)
                .styled(Style::Points(2))
                .toned(Tone::Pale),
            Series::line("fitted", &x, &x, 0),
        ],
        ..Panel::default()
    }]);
    let svg = fig.svg(Path::new("test.svg")).unwrap();
    let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
    let (full, pale) = (palette(0), shade(palette(0), Tone::Pale));
    assert_eq!(pale, RGBColor(154, 194, 221));
    let first_line = svg.find(&format!("stroke=\"{}\"", hex(full)));
    let last_disc = svg.rfind(&format!("fill=\"{}\"", hex(pale)));
    assert!(
        matches!((last_disc, first_line), (Some(d), Some(l)) if d < l),
        "{svg}"
    );
    assert!(!svg.contains(&format!("fill=\"{}\"", hex(full))), "{svg}");
}
