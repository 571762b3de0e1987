//! `separation.png`: each set's candidates' predicted responses to its
//! best manoeuvre, overlaid per measured channel (a colour per candidate,
//! the same in every panel, each named in the key), each look-alike's
//! response less the reference's in noise floors (the candidate's colour,
//! a line style per channel), and the manoeuvre's steer and speed in
//! panels of their own, so each is drawn on an axis of its own range.
//! Units: SI, the steer in degrees.

use crate::design::{Design, Prediction};
use crate::diagnose::pipeline::observed_channel;
use crate::diagnose::Channel;
use crate::report::plot::{Figure, Panel, Series, Style, INK};

/// The palette's colours a candidate is drawn in, in member order (grey,
/// index 7, is the noise band's; light blue, 8, is for context).
const CANDIDATE_COLOURS: [usize; 8] = [0, 1, 2, 3, 4, 5, 6, 9];

/// The line styles that tell series of one colour apart.
const STYLES: [Style; 3] = [Style::Line, Style::Dashed, Style::Dotted];

/// The colour and style of member `k` of a set: a colour of its own, and
/// solid, dashed and dotted in turn, so that look-alikes lying on the
/// reference within a line's width still show, and no two of up to 24
/// members are drawn alike (8 colours, 3 styles, 8 and 3 coprime).
pub(super) fn member_look(k: usize) -> (usize, Style) {
    (
        CANDIDATE_COLOURS[k % CANDIDATE_COLOURS.len()],
        STYLES[k % STYLES.len()],
    )
}

/// The figure of `design`.
pub(super) fn figure(design: &Design) -> Figure {
    let mut panels = Vec::new();
    for set in &design.sets {
        let Some(p) = &set.best else { continue };
        let d = set.ranked.first().map_or(f64::NAN, |s| s.separation);
        panels.extend(prediction_panels(
            p,
            &design.logging.channels,
            &design.noise_floors,
            d,
        ));
    }
    Figure::stack(panels)
}

/// The panels of one set's best manoeuvre `p` (separation `d`), the
/// channels logged as `channels` says, each with its noise floor.
pub(super) fn prediction_panels(
    p: &Prediction,
    channels: &[bool; 3],
    floors: &[f64; 3],
    d: f64,
) -> Vec<Panel> {
    let logged = || Channel::ALL.into_iter().filter(|c| channels[c.index()]);
    let mut panels: Vec<Panel> = logged()
        .map(|ch| {
            let series = p
                .members
                .iter()
                .enumerate()
                .map(|(k, (label, obs))| {
                    let (colour, style) = member_look(k);
                    Series::line(label, &p.times, observed_channel(obs, ch), colour).styled(style)
                })
                .collect();
            panel(
                format!("{}: {} predicted", p.name, ch.name()),
                format!("{}, {}", ch.name(), ch.unit()),
                series,
            )
        })
        .collect();
    panels.push(difference_panel(p, channels, floors, d));
    let deg: Vec<f64> = p.steer.iter().map(|d| d.to_degrees()).collect();
    panels.push(panel(
        format!("{}: steer", p.name),
        "steer, °".into(),
        vec![Series::line("steer, °", &p.times, &deg, INK)],
    ));
    panels.push(panel(
        format!("{}: speed", p.name),
        "speed, m/s".into(),
        vec![Series::line("speed, m/s", &p.times, &p.speed, INK)],
    ));
    panels
}

/// Where the separation lives: each look-alike minus the reference, in
/// noise floors, per measured channel (the look-alike's colour, a style
/// per channel), with the ±1 floor band.
fn difference_panel(p: &Prediction, channels: &[bool; 3], floors: &[f64; 3], d: f64) -> Panel {
    let mut diff = Vec::new();
    for (k, (label, obs)) in p.members.iter().enumerate().skip(1) {
        let (colour, _) = member_look(k);
        for ch in Channel::ALL {
            let i = ch.index();
            if !channels[i] || floors[i] <= 0.0 {
                continue;
            }
            let a = observed_channel(&p.members[0].1, ch);
            let b = observed_channel(obs, ch);
            let y: Vec<f64> = a.iter().zip(b).map(|(x, y)| (y - x) / floors[i]).collect();
            let name = format!("{label}: {}", ch.name());
            diff.push(Series::line(&name, &p.times, &y, colour).styled(STYLES[i % STYLES.len()]));
        }
    }
    // One noise floor either way: where a difference leaves the band is
    // where the separation is earned.
    let t_ends = [p.times[0], *p.times.last().unwrap_or(&p.times[0])];
    for (label, y) in [("±1 noise floor", 1.0), ("", -1.0)] {
        diff.push(Series::line(label, &t_ends, &[y, y], 7).styled(Style::Dotted));
    }
    panel(
        format!(
            "{}: the look-alikes' responses less the reference's (D = {d:.1})",
            p.name
        ),
        "difference, noise floors".into(),
        diff,
    )
}

fn panel(title: String, y_label: String, series: Vec<Series>) -> Panel {
    Panel {
        title,
        x_label: "t, s".into(),
        y_label,
        series,
        x_range: None,
        y_range: None,
    }
}

#[cfg(test)]
#[path = "figure_tests.rs"]
mod tests;
