//! The figure of a swarm fit: its measured points against the fitted
//! curves, one panel per channel, camber and pressure (slip angle in
//! degrees, slip ratio in percent), each titled with its own σ =
//! sqrt(Σe²/ΣF²)·100 % over its points and its levels spelt as the
//! terminal spells them ([`Variable::display`]); a colour per load within
//! a panel (past nine loads the colours again, the lines dashed), keyed
//! by the load its line is drawn at (the report's `curves[].fz`, with its
//! level's name where that differs), the key opening with what is
//! measured (points) and what fitted (lines), the lines drawn over every
//! load's points; where the model gives every load one curve (a linear
//! tyre's), that curve drawn once in ink, keyed so, and the loads keyed by
//! their points. The staged Magic Formula fit's is in `staged_figure.rs`.

use super::level_names::LevelNames;
use super::staged_figure::{key_entries, level_style, MEASURED};
use super::SwarmReport;
use crate::format::{fixed, plural};
use crate::identify::data::{Condition, Point, SlipAxis};
use crate::identify::Channel;
use crate::report::plot::{Figure, Panel, Series, Style, Tone, INK};
use crate::tyre::Tyre;

/// Measured points against the fitted curves of every channel fitted.
pub(super) fn fit_figure(r: &SwarmReport) -> Figure {
    let first = r.fit.channel;
    let mut channels: Vec<(Channel, &[Condition])> = Vec::new();
    if first == Channel::LateralForce {
        channels.push((Channel::LateralForce, &r.conditions));
    }
    // A linear tyre's trail is fitted to `mz` too (over the window's
    // points), and drawn as the other fits are.
    let trail = r.linear_window.as_ref().and_then(|w| w.judged_trail());
    if r.aligning.is_some() || trail.is_some() {
        channels.push((Channel::AligningMoment, &r.conditions));
    }
    if first == Channel::LongitudinalForce {
        channels.push((Channel::LongitudinalForce, &r.conditions));
    } else if r.longitudinal.is_some() {
        channels.push((Channel::LongitudinalForce, &r.longitudinal_conditions));
    }
    figure(
        &r.options.model.to_string(),
        &r.tyre,
        &channels,
        &r.level_names(),
    )
}

/// The figure of `tyre` fitted as `model` on each channel's conditions
/// (module notes): a column per pressure level.
fn figure(
    model: &str,
    tyre: &Tyre,
    channels: &[(Channel, &[Condition])],
    names: &LevelNames,
) -> Figure {
    let mut panels = Vec::new();
    let mut columns = 1;
    for &(ch, conds) in channels {
        // Pressures are the columns: a tyre engineer reads one pressure
        // down a column and compares pressures across a row.
        let pressures = levels(conds.iter().filter_map(|c| c.pressure), 1.0);
        columns = columns.max(pressures.len());
        for g in levels(conds.iter().map(|c| c.camber), 1e-3) {
            for p in pressures_or_none(&pressures) {
                let at: Vec<&Condition> = conds
                    .iter()
                    .filter(|c| (c.camber - g).abs() < 1e-3 && same_pressure(c.pressure, p))
                    .collect();
                panels.push(panel(model, tyre, ch, &at, (g, p), names));
            }
        }
    }
    // The key's top margin, a 20 px row per entry and the x labels below
    // set the row's height where they need more than 260 px.
    super::staged_figure::keyed(panels, columns, 260)
}

/// The distinct values (within `tol`), ascending.
fn levels(values: impl Iterator<Item = f64>, tol: f64) -> Vec<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() < tol);
    v
}

/// The pressures to draw a panel for: each level, or one panel without.
fn pressures_or_none(pressures: &[f64]) -> Vec<Option<f64>> {
    if pressures.is_empty() {
        vec![None]
    } else {
        pressures.iter().map(|p| Some(*p)).collect()
    }
}

fn same_pressure(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() < 1.0,
        (None, None) => true,
        _ => false,
    }
}

/// The panel's title: model, channel, levels as the terminal spells them,
/// its own σ over its points.
fn title(
    model: &str,
    ch: Channel,
    (camber, pressure): (f64, Option<f64>),
    names: &LevelNames,
    sigma: f64,
    n: usize,
) -> String {
    let mut t = format!("{model} {}, γ {}", ch.quantity(), names.camber(camber));
    if let Some(p) = pressure {
        t += &format!(", {}", names.pressure(p));
    }
    format!(
        "{t}: σ {} %, {}",
        fixed(sigma, 2),
        plural(n, "point", "points")
    )
}

/// A channel's slip on its figure's x axis: a slip ratio in %, an angle
/// in degrees.
fn slip_shown(ch: Channel, v: f64) -> f64 {
    if ch == Channel::LongitudinalForce {
        100.0 * v
    } else {
        v.to_degrees()
    }
}

/// The fitted curve of condition `c` over its own slip range (so the y
/// axis is the data's, not the model's beyond them): x as shown, y.
fn fitted_curve(tyre: &Tyre, ch: Channel, c: &Condition) -> (Vec<f64>, Vec<f64>) {
    let axis = match ch {
        Channel::LongitudinalForce => SlipAxis::Ratio,
        _ => SlipAxis::Angle,
    };
    let (lo, hi) = c
        .points
        .iter()
        .map(|q| q.slip())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let speed = c.points.first().map_or(10.0, |q| q.speed);
    let xs: Vec<f64> = (0..=200)
        .map(|i| lo + (hi - lo) * f64::from(i) / 200.0)
        .collect();
    let ys: Vec<f64> = xs
        .iter()
        .map(|a| ch.model(tyre, &Point::unmeasured(axis, *a, c.fz, c.camber, speed)))
        .collect();
    (xs.iter().map(|a| slip_shown(ch, *a)).collect(), ys)
}

/// One channel at one camber and pressure: a colour per load, the
/// measured points and the fitted line in it.
fn panel(
    model: &str,
    tyre: &Tyre,
    ch: Channel,
    conditions: &[&Condition],
    at: (f64, Option<f64>),
    names: &LevelNames,
) -> Panel {
    // The key says which marks are measured (points) and which fitted
    // (lines), in grey, before the loads' colours: a line per load in its
    // points' colour.
    let (mut series, one) = key_of(tyre, ch, conditions);
    // Every load's fitted line is drawn after every load's points: a line
    // drawn before the next load's points lay under them where two loads'
    // curves cross or meet (the aligning moment's near zero slip and past
    // its peak).
    let mut lines = Vec::new();
    let (mut e2, mut y2, mut n) = (0.0, 0.0, 0);
    for (k, c) in conditions.iter().enumerate() {
        let measured: Vec<(f64, f64, f64)> = c
            .points
            .iter()
            .map(|q| (slip_shown(ch, q.slip()), ch.measured(q), ch.model(tyre, q)))
            .filter(|p| p.1.is_finite())
            .collect();
        for (_, m, f) in &measured {
            e2 += (f - m).powi(2);
            y2 += m * m;
        }
        n += measured.len();
        let x: Vec<f64> = measured.iter().map(|p| p.0).collect();
        let y: Vec<f64> = measured.iter().map(|p| p.1).collect();
        // A style per load, none twice in a panel, none the key's grey:
        // past nine loads the colours come again with dashed lines.
        let style = level_style(k);
        let colour = style.colour;
        // The line is drawn at the condition's own load, the report's
        // `curves[].fz`: the key says that number, and its level's name
        // where the terminal names the level otherwise (1639.7 N in the
        // 1656 N level).
        let label = super::condition_values::own_load(c.fz, names);
        let on_points = if one.is_some() { label.as_str() } else { "" };
        // Pale points under the line in the full colour: in one colour
        // a close fit's line could not be told from its points.
        let points = Series::line(on_points, &x, &y, colour).styled(Style::Points(2));
        series.push(points.toned(Tone::Pale));
        if one.is_none() {
            let (xd, ys) = fitted_curve(tyre, ch, c);
            lines.push(Series::line(&label, &xd, &ys, colour).styled(style.line));
        }
    }
    lines.extend(one.map(|(x, y)| Series::line("", &x, &y, INK)));
    series.extend(lines);
    let sigma = if y2 > 0.0 {
        100.0 * (e2 / y2).sqrt()
    } else {
        f64::NAN
    };
    Panel {
        title: title(model, ch, at, names, sigma, n),
        x_label: if ch == Channel::LongitudinalForce {
            "slip ratio [%]".into()
        } else {
            "slip angle [deg]".into()
        },
        y_label: match ch {
            Channel::LateralForce => "Fy [N]".into(),
            Channel::AligningMoment => "Mz [N·m]".into(),
            Channel::LongitudinalForce => "Fx [N]".into(),
        },
        series,
        ..Panel::default()
    }
}

/// The key's entry of a panel's one fitted curve ([`one_curve`]).
const ONE_CURVE: &str = "fitted: one curve for every load";

/// A panel's key entries for measured and fitted, and its one fitted
/// curve where the model gives every load one (a linear tyre's, the loads
/// pooled): drawn once in ink and keyed so, the loads then keyed by their
/// points (four coinciding lines showed the last load's colour while the
/// key listed four).
fn key_of(tyre: &Tyre, ch: Channel, conditions: &[&Condition]) -> (Vec<Series>, OneCurve) {
    let mut key = key_entries(Style::Points(2), MEASURED);
    let one = one_curve(tyre, ch, conditions);
    if one.is_some() {
        key[1] = Series::line(ONE_CURVE, &[], &[], INK);
    }
    (key, one)
}

/// A panel's one fitted curve ([`one_curve`]): x as shown, y.
type OneCurve = Option<(Vec<f64>, Vec<f64>)>;

/// The fitted curve of every condition of a panel where the model gives
/// them one (no law of load: a linear tyre's, the loads pooled), over
/// their slips together: x as shown, y. `None` for one condition, or
/// curves that differ anywhere by more than a billionth of their size.
fn one_curve(tyre: &Tyre, ch: Channel, conditions: &[&Condition]) -> OneCurve {
    let axis = match ch {
        Channel::LongitudinalForce => SlipAxis::Ratio,
        _ => SlipAxis::Angle,
    };
    let (lo, hi) = conditions
        .iter()
        .flat_map(|c| &c.points)
        .map(|q| q.slip())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if conditions.len() < 2 || lo >= hi {
        return None;
    }
    let xs: Vec<f64> = (0..=200)
        .map(|i| lo + (hi - lo) * f64::from(i) / 200.0)
        .collect();
    let curve = |c: &Condition| -> Vec<f64> {
        let speed = c.points.first().map_or(10.0, |q| q.speed);
        xs.iter()
            .map(|a| ch.model(tyre, &Point::unmeasured(axis, *a, c.fz, c.camber, speed)))
            .collect()
    };
    let first = curve(conditions[0]);
    let size = first.iter().fold(0.0, |m: f64, y| m.max(y.abs()));
    let same = |ys: Vec<f64>| {
        ys.iter()
            .zip(&first)
            .all(|(a, b)| (a - b).abs() <= 1e-9 * size)
    };
    conditions[1..]
        .iter()
        .all(|c| same(curve(c)))
        .then(|| (xs.iter().map(|a| slip_shown(ch, *a)).collect(), first))
}

#[cfg(test)]
#[path = "figures_tests.rs"]
mod tests;

#[cfg(test)]
mod one_curve_tests {
    use super::*;
    use crate::identify::data::identification_conditions;
    use crate::tyre::{Linear, Pac89};

    /// A linear tyre's three loads: one ink line over the slips of all,
    /// the loads keyed by their points; a PAC89's: a line per load.
    #[test]
    fn one_curve_for_every_load_is_drawn_and_keyed_once() {
        let linear = Tyre::Linear(Linear::new(60_000.0));
        let (conds, _) = identification_conditions(&linear, 0.01, 1);
        let at: Vec<&Condition> = conds.iter().collect();
        let names = LevelNames::default();
        let p = panel(
            "linear",
            &linear,
            Channel::LateralForce,
            &at,
            (0.0, None),
            &names,
        );
        let lines: Vec<&Series> = p.series.iter().filter(|s| s.style == Style::Line).collect();
        let drawn: Vec<&&Series> = lines.iter().filter(|s| !s.x.is_empty()).collect();
        assert_eq!(drawn.len(), 1, "one line drawn");
        assert_eq!(drawn[0].color, INK);
        let keyed: Vec<&str> = p.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(
            keyed
                .iter()
                .filter(|l| !l.is_empty())
                .copied()
                .collect::<Vec<_>>(),
            ["measured", ONE_CURVE, "2800 N", "5700 N", "8600 N"]
        );
        let pac89 = Tyre::Pac89(Pac89::adams_example());
        assert!(one_curve(&pac89, Channel::LateralForce, &at).is_none());
        assert!(one_curve(&linear, Channel::LateralForce, &at[..1]).is_none());
    }
}
