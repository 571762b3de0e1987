//! The staged fit's figure measured on what it draws ([`Panel::axes`],
//! the series' styles): axis ranges against the data's, the fitted model
//! as a line in each condition's colour over every condition's points, a
//! colour per condition, each panel's own σ, the x variable of each stage.

use super::*;
use crate::report::plot::{Axes, INK};

fn tyre() -> MagicFormula {
    crate::io::tir::read_tir_text(
        "MagicFormula61_Parameters.tir",
        include_str!("../../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
    )
    .unwrap()
}

/// A row at the given conditions whose measured channels are the tyre's
/// times (1 + `error`).
fn row(t: &MagicFormula, fz: f64, kappa: f64, alpha: f64, camber: f64, error: f64) -> MfRow {
    let mut r = MfRow {
        fz,
        kappa,
        alpha,
        camber,
        speed: 16.7,
        pressure: None,
        fx: f64::NAN,
        fy: f64::NAN,
        mz: f64::NAN,
        mx: f64::NAN,
        my: f64::NAN,
    };
    r.fx = Stage::PureFx.model(t, &r) * (1.0 + error);
    r.fy = Stage::PureFy.model(t, &r) * (1.0 + error);
    r.mz = Stage::PureMz.model(t, &r) * (1.0 + error);
    r
}

/// Pure slip-angle sweeps at two loads and two cambers (errors ±1 % at
/// camber 0, ±3 % at 2°), and slip-ratio sweeps at two slip angles.
fn rows(t: &MagicFormula) -> Vec<MfRow> {
    let mut out = Vec::new();
    for (camber, e) in [(0.0, 0.01), (2f64.to_radians(), 0.03)] {
        for fz in [3000.0, 6000.0] {
            for i in -20..=20 {
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                let a = (0.5 * f64::from(i)).to_radians();
                out.push(row(t, fz, 0.0, a, camber, sign * e));
            }
        }
    }
    for a in [3f64.to_radians(), 8f64.to_radians()] {
        // κ = 0 left out: that row would be a pure lateral one.
        for i in (-10..=10).filter(|&i| i != 0) {
            out.push(row(t, 4000.0, 0.02 * f64::from(i), a, 0.0, 0.0));
        }
    }
    out
}

fn measured_range(p: &Panel) -> (f64, f64) {
    p.series
        .iter()
        .filter(|s| s.style == Style::Points(3))
        .flat_map(|s| s.y.iter().copied())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        })
}

#[test]
fn levels_split_on_gaps_and_rows_find_their_level() {
    let l = clusters([2000.0, 2010.0, 3990.0, 4000.0, 1995.0].into_iter(), 200.0);
    assert_eq!(l.len(), 2);
    assert!((l[0] - 6005.0 / 3.0).abs() < 1e-9 && (l[1] - 3995.0).abs() < 1e-9);
    assert_eq!(nearest(&l, 3100.0), 1);
    assert_eq!(nearest(&l, 2900.0), 0);
    assert_eq!(nearest(&[], 1.0), 0);
}

#[test]
fn the_y_axis_spans_the_data_and_the_fit_is_a_line_over_each_conditions_points() {
    let t = tyre();
    let rows = rows(&t);
    let fig = staged_figure(
        &t,
        &[Stage::PureFy, Stage::PureMz, Stage::CombinedFx],
        &rows,
        &[],
    );
    // Pure Fy and Mz: one panel per camber; combined Fx: one per load.
    assert_eq!(fig.panels.len(), 5);
    for p in &fig.panels {
        let (lo, hi) = measured_range(p);
        let span = hi - lo;
        let Axes { x, y } = p.axes();
        assert!(
            y.0 <= lo && y.1 >= hi,
            "{}: y {y:?}, data {lo}..{hi}",
            p.title
        );
        assert!(
            y.0 >= lo - 0.1 * span && y.1 <= hi + 0.1 * span,
            "{}: y {y:?} is far wider than the data {lo}..{hi}",
            p.title
        );
        let points: Vec<&Series> = p
            .series
            .iter()
            .filter(|s| !s.x.is_empty() && s.style == Style::Points(3))
            .collect();
        let lines: Vec<&Series> = p
            .series
            .iter()
            .filter(|s| !s.x.is_empty() && s.style == Style::Line)
            .collect();
        assert_eq!(points.len(), 2, "{}", p.title);
        assert_eq!(
            lines.len(),
            points.len(),
            "{}: a line per condition",
            p.title
        );
        // Every line drawn after every condition's points, so that no
        // condition's points hide another's curve.
        let drawn: Vec<Style> = p
            .series
            .iter()
            .filter(|s| !s.x.is_empty())
            .map(|s| s.style)
            .collect();
        let first_line = drawn.iter().position(|s| *s == Style::Line).unwrap();
        assert!(
            drawn[first_line..].iter().all(|s| *s == Style::Line),
            "{}: {drawn:?}",
            p.title
        );
        // Measured as hollow rings, through which the line is seen.
        assert!(points.iter().all(|m| m.marker == Some(RING)), "{}", p.title);
        // A colour per condition, none black nor the key's grey.
        let mut colours: Vec<usize> = points.iter().map(|m| m.color).collect();
        colours.sort_unstable();
        colours.dedup();
        assert_eq!(colours.len(), points.len(), "{}: {colours:?}", p.title);
        assert!(colours.iter().all(|c| *c != INK && *c != MEASURED));
        for (m, l) in points.iter().zip(&lines) {
            a_line_over_its_points(p, m, l, x);
        }
    }
}

/// Condition `m`'s fitted line `l` in panel `p` (x axis `x`): in its points'
/// colour, at least 100 slips (far more than the condition's 41 or 20
/// points) evenly spaced in increasing x over their range, in the axis.
fn a_line_over_its_points(p: &Panel, m: &Series, l: &Series, x: (f64, f64)) {
    assert_eq!(l.color, m.color, "{}", p.title);
    assert!(
        l.x.len() >= 100 && l.x.len() > 2 * m.x.len(),
        "{}: {} points on the line, {} measured",
        p.title,
        l.x.len(),
        m.x.len()
    );
    assert!(l.x.windows(2).all(|w| w[1] > w[0]), "{}", p.title);
    // Evenly spaced: not the measured points' own slips.
    let step = l.x[1] - l.x[0];
    assert!(
        l.x.windows(2)
            .all(|w| (w[1] - w[0] - step).abs() < 1e-9 * step.abs().max(1.0)),
        "{}",
        p.title
    );
    let (mx0, mx1) =
        m.x.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(*v), b.max(*v))
            });
    assert!((l.x[0] - mx0).abs() < 1e-9 && (l.x[l.x.len() - 1] - mx1).abs() < 1e-9);
    assert!(x.0 <= mx0 && x.1 >= mx1);
}

#[test]
fn each_panel_reads_its_own_sigma_and_its_stages_slip_with_units() {
    let t = tyre();
    let rows = rows(&t);
    let fig = staged_figure(&t, &[Stage::PureFy, Stage::CombinedFx], &rows, &[]);
    let titles: Vec<&str> = fig.panels.iter().map(|p| p.title.as_str()).collect();
    // Camber 0: ±1 % errors, camber 2°: ±3 %.
    let mut sigmas = Vec::new();
    for (k, camber) in [(0, 0.0), (1, 2f64.to_radians())] {
        let at: Vec<&MfRow> = rows
            .iter()
            .filter(|r| r.kappa == 0.0 && r.camber == camber)
            .collect();
        let e2: f64 = at
            .iter()
            .map(|r| (Stage::PureFy.model(&t, r) - r.fy).powi(2))
            .sum();
        let y2: f64 = at.iter().map(|r| r.fy * r.fy).sum();
        let sigma = fixed(100.0 * (e2 / y2).sqrt(), 2);
        assert!(
            titles[k].contains(&format!("σ {sigma} %, 82 points")),
            "{} lacks σ {sigma} %",
            titles[k]
        );
        sigmas.push(sigma);
    }
    assert_eq!(sigmas, ["1.00", "3.00"]);
    assert!(
        titles[0].starts_with("pure Fy, γ 0.00°: σ"),
        "{}",
        titles[0]
    );
    assert!(
        titles[1].starts_with("pure Fy, γ 2.00°: σ"),
        "{}",
        titles[1]
    );
    let fy = &fig.panels[0];
    assert_eq!(
        (fy.x_label.as_str(), fy.y_label.as_str()),
        ("slip angle α [deg]", "Fy [N]")
    );
    // Combined Fx against the slip ratio it sweeps, a line per slip angle.
    let fx = &fig.panels[2];
    assert_eq!(
        (fx.x_label.as_str(), fx.y_label.as_str()),
        ("slip ratio κ [%]", "Fx [N]")
    );
    assert!(
        fx.title
            .starts_with("combined Fx, γ 0.00°, Fz 4000 N: σ 0.00 %"),
        "{}",
        fx.title
    );
    let labels: Vec<&str> = fx.series.iter().map(|s| s.label.as_str()).collect();
    // The levels' entries on their lines, drawn after the points.
    assert_eq!(labels, ["measured", "fitted", "", "", "α 3°", "α 8°"]);
    // The key's swatches grey; each level's line in its points' colour.
    assert_eq!(
        (fx.series[0].color, fx.series[1].color),
        (MEASURED, MEASURED)
    );
    assert_eq!(fx.series[2].color, fx.series[4].color);
    assert_eq!(fx.series[3].color, fx.series[5].color);
    assert_ne!(fx.series[2].color, fx.series[3].color);
    let (lo, hi) = (fx.series[2].x[0], fx.series[2].x[19]);
    assert_eq!((lo, hi), (-20.0, 20.0));
}

#[test]
fn several_pressures_are_the_columns_of_the_grid() {
    let t = tyre();
    let mut rows: Vec<MfRow> = Vec::new();
    for p in [180e3, 220e3, 260e3] {
        for i in -10..=10 {
            let mut r = row(&t, 4000.0, 0.0, f64::from(i).to_radians(), 0.0, 0.0);
            r.pressure = Some(p);
            rows.push(r);
        }
    }
    // The second camber lacks the highest pressure: a blank panel keeps the grid.
    for p in [180e3, 220e3] {
        for i in -10..=10 {
            let mut r = row(&t, 4000.0, 0.0, f64::from(i).to_radians(), 0.05, 0.0);
            r.pressure = Some(p);
            rows.push(r);
        }
    }
    let fig = staged_figure(&t, &[Stage::PureFy], &rows, &[]);
    assert_eq!((fig.columns, fig.panels.len(), fig.width), (3, 6, 1950));
    assert!(fig.panels[1]
        .title
        .starts_with("pure Fy, γ 0.00°, 220.0 kPa: σ"));
    assert_eq!(
        fig.panels[5].title,
        "pure Fy, γ 2.86°, 260.0 kPa: no points"
    );
}

/// Rows of a wheel-moment rig at one load and camber: a pure slip-angle
/// sweep (0.5° steps), a pure slip-ratio sweep (29 ratios) and a grid of
/// 11 slip ratios × 7 slip angles, with measured Mx and My.
fn moment_rows(t: &MagicFormula) -> Vec<MfRow> {
    let with_moments = |mut r: MfRow| {
        r.mx = Stage::Mx.model(t, &r);
        r.my = Stage::My.model(t, &r);
        r
    };
    let mut out = Vec::new();
    for i in -30..=30 {
        let a = (0.5 * f64::from(i)).to_radians();
        out.push(with_moments(row(t, 4000.0, 0.0, a, 0.0, 0.0)));
    }
    for i in (-14..=14).filter(|&i| i != 0) {
        out.push(with_moments(row(
            t,
            4000.0,
            0.05 * f64::from(i),
            0.0,
            0.0,
            0.0,
        )));
    }
    for k in [
        -0.5, -0.2, -0.1, -0.05, -0.02, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0,
    ] {
        for a in [-8.0, -4.0, -2.0, 2.0, 4.0, 8.0, 12.0f64] {
            out.push(with_moments(row(t, 4000.0, k, a.to_radians(), 0.0, 0.0)));
        }
    }
    out
}

/// Whether a series of this style is a line (solid, dashed or dotted).
fn is_line(style: Style) -> bool {
    matches!(style, Style::Line | Style::Dashed | Style::Dotted)
}

#[test]
fn levels_past_the_palette_are_told_apart_by_dash_and_marker() {
    // 27 levels, each its own style; none black nor the key's grey.
    let styles: Vec<_> = (0..27).map(level_style).collect();
    for (k, a) in styles.iter().enumerate() {
        assert!(a.colour != INK && a.colour != MEASURED, "{k}: {a:?}");
        if let Some(j) = styles[..k].iter().position(|b| b == a) {
            panic!("levels {j} and {k} are drawn alike: {a:?}");
        }
    }
    // The overturning moment's grid: 12 levels (11 slip ratios and the
    // pure sweep's 0), each line and each level's points drawn apart.
    let t = tyre();
    let fig = staged_figure(&t, &[Stage::Mx], &moment_rows(&t), &[]);
    let grid = &fig.panels[0];
    let drawn = |s: &&Series| !s.x.is_empty();
    let lines: Vec<(usize, Style)> = grid
        .series
        .iter()
        .filter(drawn)
        .filter(|s| is_line(s.style))
        .map(|s| (s.color, s.style))
        .collect();
    let points: Vec<(usize, Option<Marker>)> = grid
        .series
        .iter()
        .filter(drawn)
        .filter(|s| s.style == Style::Points(3))
        .map(|s| (s.color, s.marker))
        .collect();
    assert_eq!((lines.len(), points.len()), (12, 12), "{}", grid.title);
    for k in 0..12 {
        assert!(!lines[..k].contains(&lines[k]), "line {k}: {lines:?}");
        assert!(!points[..k].contains(&points[k]), "points {k}: {points:?}");
    }
}

#[test]
fn a_moment_stage_draws_each_pure_sweep_against_its_own_slip_and_every_key_fits_its_row() {
    let t = tyre();
    let rows = moment_rows(&t);
    let fig = staged_figure(&t, &[Stage::Mx, Stage::My], &rows, &[]);
    let x_labels: Vec<(&str, &str)> = fig
        .panels
        .iter()
        .map(|p| (p.y_label.as_str(), p.x_label.as_str()))
        .collect();
    // Each stage: the grid and its own pure sweep against the slip it
    // sweeps, then the other pure sweep against the other slip.
    assert_eq!(
        x_labels,
        [
            ("Mx [N·m]", "slip angle α [deg]"),
            ("Mx [N·m]", "slip ratio κ [%]"),
            ("My [N·m]", "slip ratio κ [%]"),
            ("My [N·m]", "slip angle α [deg]"),
        ]
    );
    for p in &fig.panels {
        let lines = p
            .series
            .iter()
            .filter(|s| is_line(s.style) && !s.x.is_empty())
            .count();
        let keyed = p.series.iter().filter(|s| !s.label.is_empty()).count();
        // Every keyed level is a sweep with its line: no entry for a
        // single point of the other slip's sweep.
        assert_eq!(keyed, lines + 2, "{}", p.title);
        assert!(
            key_height(keyed) <= fig.row_height,
            "{}: {keyed} entries in a {} px row",
            p.title,
            fig.row_height
        );
        let drawn: usize = p
            .series
            .iter()
            .filter(|s| s.style == Style::Points(3))
            .map(|s| s.x.len())
            .sum();
        assert!(p.title.ends_with(&format!("{drawn} points")), "{}", p.title);
    }
    // The grid's slip ratios and the pure slip-angle sweep's κ = 0: 12
    // lines; the pure slip-ratio sweep a line of its own.
    let keyed = |k: usize| {
        fig.panels[k]
            .series
            .iter()
            .filter(|s| !s.label.is_empty())
            .count()
    };
    assert_eq!((keyed(0), keyed(1)), (14, 3));
    assert!(fig.row_height >= key_height(14));
    // Every row on a panel of each stage: 61 + 28 + 77.
    for k in [0, 2] {
        let n = |p: &Panel| {
            p.series
                .iter()
                .filter(|s| s.style == Style::Points(3))
                .map(|s| s.x.len())
                .sum::<usize>()
        };
        assert_eq!(n(&fig.panels[k]) + n(&fig.panels[k + 1]), 166);
    }
}

#[test]
fn levels_are_named_by_the_groupings_nominals_as_the_terminal_names_them() {
    use crate::identify::grouping::{Level, Levels as Named, Variable};
    let t = tyre();
    // The thinned rows average 3000 and 6000 N and camber 2.00°; the
    // grouping's nominals (the medians of the raw samples, which the
    // terminal prints) are 3004 N, 5996 N and 1.99°.
    let named = |variable, separation, at: &[(f64, f64)]| Named {
        variable,
        separation,
        noise: 0.0,
        levels: at
            .iter()
            .map(|&(v, nominal)| Level {
                lo: v - 1.0e-3,
                hi: v + 1.0e-3,
                nominal,
                samples: 10,
            })
            .collect(),
        transition_samples: 0,
    };
    let groups = [
        named(Variable::Load, 10.0, &[(3000.0, 3004.0), (6000.0, 5996.0)]),
        named(
            Variable::Camber,
            0.1f64.to_radians(),
            &[(0.0, 0.0), (2f64.to_radians(), 1.99f64.to_radians())],
        ),
    ];
    let fig = staged_figure(&t, &[Stage::PureFy], &rows(&t), &groups);
    let titles: Vec<&str> = fig.panels.iter().map(|p| p.title.as_str()).collect();
    assert!(titles[1].starts_with("pure Fy, γ 1.99°: σ"), "{titles:?}");
    let labels: Vec<&str> = fig.panels[0]
        .series
        .iter()
        .map(|s| s.label.as_str())
        .filter(|l| l.ends_with(" N"))
        .collect();
    // The terminal's spelling of each nominal, from the one formatter.
    let want = [3004.0, 5996.0].map(|v| Variable::Load.display(v));
    assert_eq!(labels, want);
    assert_eq!(labels, ["3004 N", "5996 N"]);
}

/// A combined lateral stage's rows at zero slip angle (the pure
/// longitudinal sweeps, to ±100 %) are drawn in a panel of their own: the
/// combined sweeps' panel spans their ±10 %, not ±100 % (they filled a
/// tenth of its width).
#[test]
fn combined_lateral_sweeps_are_not_stretched_by_the_pure_longitudinal_ones() {
    let t = tyre();
    let mut rows = Vec::new();
    for i in (-50..=50).filter(|&i| i != 0) {
        rows.push(row(&t, 4000.0, 0.02 * f64::from(i), 0.0, 0.0, 0.0));
    }
    for a in [4f64.to_radians(), 8f64.to_radians()] {
        for i in (-10..=10).filter(|&i| i != 0) {
            rows.push(row(&t, 4000.0, 0.01 * f64::from(i), a, 0.0, 0.0));
        }
    }
    // The channel of the combined rows: the tyre's combined Fy.
    for r in rows.iter_mut() {
        r.fy = Stage::CombinedFy.model(&t, r);
    }
    let fig = staged_figure(&t, &[Stage::CombinedFy], &rows, &[]);
    assert_eq!(
        fig.panels.len(),
        2,
        "{:?}",
        fig.panels.iter().map(|p| &p.title).collect::<Vec<_>>()
    );
    let x = |p: &Panel| {
        let Axes { x, .. } = p.axes();
        x
    };
    let (combined, zero) = (x(&fig.panels[0]), x(&fig.panels[1]));
    assert!(combined.0 >= -12.0 && combined.1 <= 12.0, "{combined:?}");
    assert!(zero.0 <= -99.0 && zero.1 >= 99.0, "{zero:?}");
}

/// Rows not grouped (the samples are the rows) whose one 4000 N condition
/// a stage averages to 3999 N and another to 4001 N: every panel names it
/// 4000 N (the figure read "3999 N" in the pure Fy key and "Fz 4001 N" in
/// the combined titles).
#[test]
fn a_load_condition_is_named_by_its_rounded_nominal_in_every_panel() {
    let t = tyre();
    let mut rows = Vec::new();
    for fz in [3999.0, 6002.0] {
        for i in -20..=20 {
            rows.push(row(
                &t,
                fz,
                0.0,
                (0.5 * f64::from(i)).to_radians(),
                0.0,
                0.0,
            ));
        }
    }
    for a in [3f64.to_radians(), 8f64.to_radians()] {
        for i in (-10..=10).filter(|&i| i != 0) {
            rows.push(row(&t, 4001.0, 0.02 * f64::from(i), a, 0.0, 0.0));
        }
    }
    let fig = staged_figure(&t, &[Stage::PureFy, Stage::CombinedFx], &rows, &[]);
    let labels: Vec<&str> = fig.panels[0]
        .series
        .iter()
        .map(|s| s.label.as_str())
        .filter(|l| l.ends_with(" N"))
        .collect();
    assert_eq!(labels, ["4000 N", "6000 N"]);
    let combined: Vec<&str> = fig.panels[1..].iter().map(|p| p.title.as_str()).collect();
    assert!(
        combined.iter().any(|t| t.contains("Fz 4000 N")),
        "{combined:?}"
    );
    for p in &fig.panels {
        let said = p
            .series
            .iter()
            .map(|s| s.label.as_str())
            .chain([p.title.as_str()]);
        for l in said {
            assert!(!l.contains("3999") && !l.contains("4001"), "{l}");
        }
    }
}

/// Slip-ratio sweeps at α = 3° and 6° (a drive/brake test's combined
/// rows) beside a pure slip-angle sweep: drawn against the slip angle,
/// Mx's combined rows stood as two vertical streaks; they are drawn
/// against the slip ratio they sweep, the slip-angle panel holding the
/// pure sweep alone.
#[test]
fn moment_rows_swept_in_slip_ratio_at_few_slip_angles_are_drawn_against_the_slip_ratio() {
    let t = tyre();
    let mut rows: Vec<MfRow> = (-30..=30)
        .map(|i| row(&t, 4000.0, 0.0, (0.5 * f64::from(i)).to_radians(), 0.0, 0.0))
        .collect();
    for a in [3.0f64, 6.0] {
        for k in (-20..=20).filter(|&k| k != 0) {
            rows.push(row(
                &t,
                4000.0,
                0.01 * f64::from(k),
                a.to_radians(),
                0.0,
                0.0,
            ));
        }
    }
    for r in &mut rows {
        r.mx = Stage::Mx.model(&t, r);
    }
    let fig = staged_figure(&t, &[Stage::Mx], &rows, &[]);
    let points = |p: &Panel| {
        p.series
            .iter()
            .filter(|s| s.style == Style::Points(3))
            .map(|s| s.x.len())
            .sum::<usize>()
    };
    let by_axis = |axis: &str| -> usize {
        fig.panels
            .iter()
            .filter(|p| p.x_label == axis)
            .map(points)
            .sum()
    };
    assert_eq!(by_axis("slip angle α [deg]"), 61);
    assert_eq!(by_axis("slip ratio κ [%]"), 80);
}
