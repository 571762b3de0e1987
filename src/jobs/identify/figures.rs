//! The figures of a fit: a swarm fit's measured points against the fitted
//! curves, one panel per channel and camber, and a staged Magic Formula
//! fit's measured rows against the identified tyre, one panel per stage and
//! camber (slip angle in degrees, slip ratio in percent).

use super::SwarmReport;
use crate::format::fixed;
use crate::identify::data::{Condition, Point, SlipAxis};
use crate::identify::mf_staged::{MfRow, Stage, StageReport};
use crate::identify::Channel;
use crate::report::plot::{Figure, Panel, Series, Style};
use crate::tyre::mf::MagicFormula;
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
        let amax = c.points.iter().map(|q| q.slip().abs()).fold(0.0, f64::max);
        let speed = c.points.first().map_or(10.0, |q| q.speed);
        let xs: Vec<f64> = (0..=200)
            .map(|i| -amax + 2.0 * amax * i as f64 / 200.0)
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

/// The figure of a staged Magic Formula fit: one panel per fitted stage and
/// camber level, the stage's rows measured (large dots) against the
/// identified tyre at the same rows (small dots), a colour per load level,
/// against the stage's slip (slip ratio for pure `Fx`, combined `Fy` and
/// `Mz`, and `My`; slip angle for the others), titled
/// with the stage's σ. The y range leaves room above the data for the
/// legend (one entry per load), so that it covers none.
pub(super) fn staged_figure(tyre: &MagicFormula, stages: &[StageReport], rows: &[MfRow]) -> Figure {
    let mut panels = Vec::new();
    for s in stages.iter().filter(|s| s.skipped.is_none()) {
        let st = s.stage;
        let sel: Vec<&MfRow> = rows.iter().filter(|r| st.takes(r)).collect();
        let cambers = clusters(sel.iter().map(|r| r.camber), 0.25f64.to_radians());
        for &g in &cambers {
            let at_camber: Vec<&MfRow> = sel
                .iter()
                .copied()
                .filter(|r| nearest(&cambers, r.camber) == g)
                .collect();
            panels.push(stage_panel(tyre, s, &at_camber, g));
        }
    }
    Figure::stack(panels)
}

/// Levels of a quantity: sorted values split where consecutive ones are
/// more than `gap` apart; each level's mean.
fn clusters(values: impl Iterator<Item = f64>, gap: f64) -> Vec<f64> {
    let mut v: Vec<f64> = values.filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    let mut out: Vec<Vec<f64>> = Vec::new();
    for x in v {
        match out.last_mut() {
            Some(c) if x - c[c.len() - 1] <= gap => c.push(x),
            _ => out.push(vec![x]),
        }
    }
    out.iter()
        .map(|c| c.iter().sum::<f64>() / c.len() as f64)
        .collect()
}

fn nearest(levels: &[f64], x: f64) -> f64 {
    levels
        .iter()
        .copied()
        .min_by(|a, b| (a - x).abs().total_cmp(&(b - x).abs()))
        .unwrap_or(x)
}

fn stage_panel(tyre: &MagicFormula, s: &StageReport, rows: &[&MfRow], camber: f64) -> Panel {
    let st = s.stage;
    // The combined Fx rows sweep the slip angle at a few slip ratios; the
    // combined Fy and Mz rows (every row with longitudinal slip, α = 0
    // included) are read against the slip ratio.
    let ratio = matches!(
        st,
        Stage::PureFx | Stage::My | Stage::CombinedFy | Stage::CombinedMz
    );
    let slip = |r: &MfRow| {
        if ratio {
            100.0 * r.kappa
        } else {
            r.alpha.to_degrees()
        }
    };
    let loads = clusters(rows.iter().map(|r| r.fz), 200.0);
    let mut series = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (k, &fz) in loads.iter().enumerate() {
        let at: Vec<&&MfRow> = rows
            .iter()
            .filter(|r| nearest(&loads, r.fz) == fz)
            .collect();
        let x: Vec<f64> = at.iter().map(|r| slip(r)).collect();
        let measured: Vec<f64> = at.iter().map(|r| st.measured(r)).collect();
        let fitted: Vec<f64> = at.iter().map(|r| st.model(tyre, r)).collect();
        for y in measured.iter().chain(&fitted) {
            lo = lo.min(*y);
            hi = hi.max(*y);
        }
        series.push(Series::line(&format!("{fz:.0} N"), &x, &measured, k).styled(Style::Points(3)));
        // One legend entry per load: the fitted dots share its colour.
        series.push(Series::line("", &x, &fitted, k).styled(Style::Points(1)));
    }
    let span = (hi - lo).max(1e-9);
    let unit = match st {
        Stage::PureFx | Stage::CombinedFx => "Fx [N]",
        Stage::PureFy | Stage::CombinedFy => "Fy [N]",
        Stage::PureMz | Stage::CombinedMz => "Mz [N·m]",
        Stage::Mx => "Mx [N·m]",
        Stage::My => "My [N·m]",
    };
    Panel {
        title: format!(
            "{}, camber {}°: σ {:.2} % ({} rows); large dots measured, small fitted",
            st.label(),
            fixed(camber.to_degrees(), 2),
            s.sigma_percent,
            rows.len()
        ),
        x_label: if ratio {
            "slip ratio [%]".into()
        } else {
            "slip angle [deg]".into()
        },
        y_label: unit.into(),
        series,
        y_range: Some((
            lo - 0.05 * span,
            hi + (0.25 * loads.len() as f64 + 0.1) * span,
        )),
        ..Panel::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_split_on_gaps_and_rows_find_their_level() {
        let l = clusters([2000.0, 2010.0, 3990.0, 4000.0, 1995.0].into_iter(), 200.0);
        assert_eq!(l.len(), 2);
        assert!((l[0] - 6005.0 / 3.0).abs() < 1e-9 && (l[1] - 3995.0).abs() < 1e-9);
        assert_eq!(nearest(&l, 3100.0), l[1]);
        assert_eq!(nearest(&l, 2900.0), l[0]);
    }
}
