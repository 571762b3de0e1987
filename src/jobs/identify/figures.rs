//! The figure of a swarm fit: its measured points against the fitted
//! curves, one panel per channel and camber (slip angle in degrees, slip
//! ratio in percent); the staged Magic Formula fit's is in
//! `staged_figure.rs`.

use super::SwarmReport;
use crate::format::fixed;
use crate::identify::data::{Condition, Point, SlipAxis};
use crate::identify::Channel;
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::tyre::Tyre;

/// Measured points against the fitted curves of every channel fitted.
pub(super) fn fit_figure(r: &SwarmReport) -> Figure {
    let first = r.fit.channel;
    let mut channels: Vec<(Channel, &[Condition])> = Vec::new();
    if first == Channel::LateralForce {
        channels.push((Channel::LateralForce, &r.conditions));
    }
    if r.aligning.is_some() {
        channels.push((Channel::AligningMoment, &r.conditions));
    }
    if first == Channel::LongitudinalForce {
        channels.push((Channel::LongitudinalForce, &r.conditions));
    } else if r.longitudinal.is_some() {
        channels.push((Channel::LongitudinalForce, &r.longitudinal_conditions));
    }
    let mut cambers: Vec<f64> = r.conditions.iter().map(|c| c.camber).collect();
    cambers.sort_by(f64::total_cmp);
    cambers.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    let model = r.options.model.as_str();
    let panels = channels
        .iter()
        .flat_map(|&(ch, conds)| cambers.iter().map(move |&g| (ch, conds, g)))
        .map(|(ch, conds, g)| panel(model, &r.tyre, ch, conds, g))
        .collect();
    Figure::stack(panels)
}

/// One channel at one camber: a colour per load.
fn panel(model: &str, tyre: &Tyre, ch: Channel, conditions: &[Condition], camber: f64) -> Panel {
    let slip = |v: f64| {
        if ch == Channel::LongitudinalForce {
            100.0 * v
        } else {
            v.to_degrees()
        }
    };
    let mut series = Vec::new();
    for (k, c) in conditions
        .iter()
        .filter(|c| (c.camber - camber).abs() < 1e-3)
        .enumerate()
    {
        let (x, y): (Vec<f64>, Vec<f64>) = c
            .points
            .iter()
            .map(|q| (slip(q.slip()), ch.measured(q)))
            .filter(|p| p.1.is_finite())
            .unzip();
        series.push(Series::line("", &x, &y, k).styled(Style::Points(2)));
        // The fitted curve over the condition's own slip range: the y
        // axis is then the data's, not the model's beyond them.
        let (lo, hi) = c
            .points
            .iter()
            .map(|q| q.slip())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        let speed = c.points.first().map_or(10.0, |q| q.speed);
        let xs: Vec<f64> = (0..=200)
            .map(|i| lo + (hi - lo) * i as f64 / 200.0)
            .collect();
        let ys: Vec<f64> = xs
            .iter()
            .map(|a| {
                let axis = match ch {
                    Channel::LongitudinalForce => SlipAxis::Ratio,
                    _ => SlipAxis::Angle,
                };
                ch.model(tyre, &Point::unmeasured(axis, *a, c.fz, c.camber, speed))
            })
            .collect();
        let xd: Vec<f64> = xs.iter().map(|a| slip(*a)).collect();
        series.push(Series::line(&format!("{:.0} N", c.fz), &xd, &ys, k));
    }
    Panel {
        title: format!(
            "{model} fit, camber {}°: points measured, lines fitted",
            fixed(camber.to_degrees(), 2)
        ),
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
