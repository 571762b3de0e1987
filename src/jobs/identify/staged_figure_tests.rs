//! The staged fit's figure measured on what it draws ([`Panel::axes`],
//! the series' styles): axis ranges against the data's, the fitted model
//! as a line over each condition's points, each panel's own σ, the x
//! variable of each stage.

use super::*;
use crate::report::plot::Axes;

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
        for (m, l) in points.iter().zip(&lines) {
            // The line in black over the coloured points, in increasing x,
            // over their slip range.
            assert_eq!(l.color, INK);
            assert_ne!(m.color, INK);
            assert!(l.x.windows(2).all(|w| w[1] > w[0]), "{}", p.title);
            let (mx0, mx1) =
                m.x.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                        (a.min(*v), b.max(*v))
                    });
            assert!((l.x[0] - mx0).abs() < 1e-9 && (l.x[l.x.len() - 1] - mx1).abs() < 1e-9);
            assert!(x.0 <= mx0 && x.1 >= mx1);
        }
    }
}

#[test]
fn each_panel_reads_its_own_sigma_and_its_stages_slip_with_units() {
    let t = tyre();
    let rows = rows(&t);
    let fig = staged_figure(&t, &[Stage::PureFy, Stage::CombinedFx], &rows);
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
            titles[k].contains(&format!("σ {sigma} %, 82 rows")),
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
    assert_eq!(labels, ["measured", "fitted", "α 3.0°", "", "α 8.0°", ""]);
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
    let fig = staged_figure(&t, &[Stage::PureFy], &rows);
    assert_eq!((fig.columns, fig.panels.len(), fig.width), (3, 6, 1950));
    assert!(fig.panels[1]
        .title
        .starts_with("pure Fy, γ 0.00°, 220.0 kPa: σ"));
    assert_eq!(fig.panels[5].title, "pure Fy, γ 2.86°, 260.0 kPa: no rows");
}
