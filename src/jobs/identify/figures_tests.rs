//! The swarm fit's figure measured on what it draws: a panel per pressure
//! and camber, each titled with its own σ and its levels spelt as the
//! terminal spells them, a colour per load, the fit a line over the
//! points, the y axis the data's.

use super::*;
use crate::identify::data::identification_conditions;
use crate::report::plot::{Axes, INK};
use crate::tyre::Pac89;

/// The PAC89 Adams example's rig points at three loads, repeated at three
/// pressures with the measured force off the tyre's by 0, 4 and 8 % (so
/// each pressure's panel has a σ of its own).
fn conditions() -> (Tyre, Vec<Condition>) {
    let tyre = Tyre::Pac89(Pac89::adams_example());
    let (base, _) = identification_conditions(&tyre, 0.0, 1);
    let mut out = Vec::new();
    for (j, p) in [69.7e3, 83.4e3, 97.1e3].into_iter().enumerate() {
        for c in &base {
            let mut c = c.clone();
            c.pressure = Some(p);
            for q in &mut c.points {
                *q = Point::lateral(
                    q.slip(),
                    q.fz,
                    q.camber,
                    q.speed,
                    q.fy() * (1.0 + 0.04 * j as f64),
                    q.mz(),
                );
            }
            out.push(c);
        }
    }
    (tyre, out)
}

#[test]
fn a_panel_per_pressure_titled_with_its_own_sigma_and_the_terminals_levels() {
    let (tyre, conds) = conditions();
    let fig = figure(
        "pac89",
        &tyre,
        &[(Channel::LateralForce, &conds)],
        &LevelNames::default(),
    );
    assert_eq!(
        fig.panels.len(),
        3,
        "a panel per pressure at the one camber"
    );
    assert_eq!(fig.columns, 3);
    for (j, (p, kpa)) in fig.panels.iter().zip(["69.7", "83.4", "97.1"]).enumerate() {
        // σ = sqrt(Σe²/ΣF²) of a force 1 + 0.04 j times the model's.
        let r = 0.04 * j as f64;
        let sigma = 100.0 * r / (1.0 + r);
        let want = format!(
            "pac89 lateral force, γ 0.00°, {kpa} kPa: σ {} %, 255 points",
            fixed(sigma, 2)
        );
        assert_eq!(p.title, want);
        // The key says which marks are measured and which fitted, then
        // the loads as the terminal spells them ([`Variable::display`]),
        // each once, in a colour of its own that is neither black nor
        // the key's grey.
        let labelled: Vec<&Series> = p.series.iter().filter(|s| !s.label.is_empty()).collect();
        let labels: Vec<&str> = labelled.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(
            labels,
            ["measured", "fitted", "2800 N", "5700 N", "8600 N"],
            "{}",
            p.title
        );
        // Measured as points, fitted as a line, as the panel draws them.
        assert_eq!(labelled[0].style, Style::Points(2));
        assert_eq!(labelled[1].style, Style::Line);
        let mut colours: Vec<usize> = labelled[2..].iter().map(|s| s.color).collect();
        colours.dedup();
        assert_eq!(colours.len(), 3, "{}: colours {colours:?}", p.title);
        assert!(colours.iter().all(|c| *c != INK && *c != MEASURED));
        // The legend fits beside the chart: its top margin, a 20 px row
        // per entry and the x labels below.
        assert!(fig.row_height >= 40 + 20 * labels.len() as u32 + 30);
    }
}

/// Both channels' panels, lateral force and aligning moment: the y axis
/// spans the measured points without running far past them, and every
/// load's fitted line is drawn over every load's points (a line drawn
/// before the next load's points lay under them where the aligning
/// moment's curves meet).
#[test]
fn the_y_axis_spans_the_data_and_the_fit_is_a_line_over_each_loads_points() {
    let (tyre, conds) = conditions();
    let fig = figure(
        "pac89",
        &tyre,
        &[
            (Channel::LateralForce, &conds),
            (Channel::AligningMoment, &conds),
        ],
        &LevelNames::default(),
    );
    assert_eq!(fig.panels.len(), 6, "a panel per channel and pressure");
    assert!(fig.panels[3..].iter().all(|p| p.y_label == "Mz [N·m]"));
    for p in &fig.panels {
        // The key's two entries hold no data.
        let drawn = || p.series.iter().filter(|s| !s.x.is_empty());
        let points: Vec<&Series> = drawn().filter(|s| s.style == Style::Points(2)).collect();
        let lines: Vec<&Series> = drawn().filter(|s| s.style == Style::Line).collect();
        assert_eq!((points.len(), lines.len()), (3, 3), "{}", p.title);
        let styles: Vec<Style> = drawn().map(|s| s.style).collect();
        let first_line = styles.iter().position(|s| *s == Style::Line).unwrap();
        assert!(
            styles[first_line..].iter().all(|s| *s == Style::Line),
            "{}: a line drawn before a load's points: {styles:?}",
            p.title
        );
        let (lo, hi) = points
            .iter()
            .flat_map(|s| s.y.iter().copied())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        assert!(lo < 0.0 && hi > 0.0, "{}: data {lo}..{hi}", p.title);
        let span = hi - lo;
        let Axes { y, .. } = p.axes();
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
        for (m, l) in points.iter().zip(&lines) {
            // The line is the points' colour, over their slip range.
            assert_eq!(l.color, m.color);
            // A smooth curve: at least 100 slips, more than the points.
            assert!(l.x.len() >= 100 && l.x.len() > m.x.len(), "{}", p.title);
            assert!(l.x.windows(2).all(|w| w[1] > w[0]));
            assert!((l.x[0] - m.x[0]).abs() < 1e-9);
            assert!((l.x[l.x.len() - 1] - m.x[m.x.len() - 1]).abs() < 1e-9);
        }
    }
}

/// The key names the load each line is drawn at, the report's
/// `curves[].fz` (a condition's own median load), beside its level's name
/// where the levels are named by other samples: on the Hoosier file the
/// key said `1656 N` where the report said 1639.7.
#[test]
fn the_key_names_the_load_its_line_is_drawn_at_as_the_report_writes_it() {
    use crate::identify::grouping::{levels, Variable};
    let (tyre, conds) = conditions();
    // Each level's samples run 30 N above its conditions' load: the
    // level's name (their median) is 15 N above the load fitted.
    let samples: Vec<f64> = conds
        .iter()
        .flat_map(|c| (0..=30).map(move |i| c.fz + f64::from(i)))
        .collect();
    let loads = [levels(Variable::Load, &samples, 10.0)];
    let names = LevelNames::of(&loads, &[]);
    let fig = figure("pac89", &tyre, &[(Channel::LateralForce, &conds)], &names);
    let p = &fig.panels[0];
    let keys: Vec<&str> = p
        .series
        .iter()
        .skip(2)
        .filter(|s| !s.label.is_empty())
        .map(|s| s.label.as_str())
        .collect();
    let want: Vec<String> = conds[..3]
        .iter()
        // To 0.1 N, every key alike (the Hoosier file's keys once read
        // 524 N, 1639.7 N and 2736.55 N).
        .map(|c| {
            format!(
                "{:.1} N ({} level)",
                c.fz,
                Variable::Load.display(c.fz + 15.0)
            )
        })
        .collect();
    assert_eq!(keys, want);
    // The number keyed is the line's own load, not its level's.
    for (k, c) in keys.iter().zip(&conds) {
        let n: f64 = k.split(' ').next().unwrap().parse().unwrap();
        assert_eq!(n, c.fz);
    }
}
