//! The ranges of the rig data a fit was made on (load, slip angle, slip
//! ratio, camber, pressure), which the written file states: a `.tir`'s
//! validity ranges (`FZMIN`…`PRESMAX`, so that `tyre-eval` saturates past
//! the data instead of extrapolating silently) with a `$` comment, and a
//! `#` comment in a TOML tyre. A variable the rows hold at one value has
//! no `.tir` range written (a slip-ratio range of 0 to 0 would cut every
//! longitudinal force off), and the comment says so; a TOML tyre's
//! `[fitted_ranges]` states a load, camber or pressure at one value as
//! `[v, v]`, which `tyre-eval` counts points past.

use crate::format::readable;
use crate::identify::data::{Condition, RigData, Sweep};
use crate::identify::grouping::SlipAxis;
use crate::identify::grouping::{Levels, Variable};
use crate::identify::mf_staged::MfRow;
use crate::io::fitted_ranges::FittedRanges;
use crate::tyre::mf::{MfLimits, TyreSide};

/// A variable's smallest and largest value over some rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Span {
    /// The variable, as the rig file names it.
    pub name: &'static str,
    /// Its unit in the comment.
    pub unit: &'static str,
    /// Smallest value (the crate's convention, SI).
    pub lo: f64,
    /// Largest value.
    pub hi: f64,
}

impl Span {
    /// The span of `values` (`None`: no value).
    fn of(
        name: &'static str,
        unit: &'static str,
        values: impl Iterator<Item = f64>,
    ) -> Option<Span> {
        let (lo, hi) = values
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        (lo <= hi).then_some(Span { name, unit, lo, hi })
    }

    /// `fz 534 to 2751 N`, or `kappa at 0` for one value.
    fn text(&self) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        if self.lo < self.hi {
            format!(
                "{} {} to {}{unit}",
                self.name,
                readable(self.lo, 4),
                readable(self.hi, 4)
            )
        } else {
            format!("{} at {}{unit}", self.name, readable(self.lo, 4))
        }
    }
}

/// The spans of the staged fit's rows: load, slip ratio, slip angle,
/// camber, pressure (where measured).
pub(crate) fn row_spans(rows: &[MfRow]) -> Vec<Span> {
    [
        Span::of("fz", "N", rows.iter().map(|r| r.fz)),
        Span::of("kappa", "", rows.iter().map(|r| r.kappa)),
        Span::of("alpha", "rad", rows.iter().map(|r| r.alpha)),
        Span::of("camber", "rad", rows.iter().map(|r| r.camber)),
        Span::of("pressure", "Pa", rows.iter().filter_map(|r| r.pressure)),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The validity ranges of `spans` in the file frame of a tyre of `side`
/// (a left tyre's ISO slip angle is the crate's negated; a right tyre's
/// inclination is the camber negated), a range for each span that is not
/// one value; `base` keeps the others.
pub(crate) fn mf_limits(spans: &[Span], side: TyreSide, base: MfLimits) -> MfLimits {
    let mut limits = base;
    for s in spans.iter().filter(|s| s.lo < s.hi) {
        let flip = match (s.name, side) {
            ("alpha", TyreSide::Left) | ("camber", TyreSide::Right) => -1.0,
            _ => 1.0,
        };
        let (a, b) = (flip * s.lo, flip * s.hi);
        let keys = match s.name {
            "fz" => ["FZMIN", "FZMAX"],
            "kappa" => ["KPUMIN", "KPUMAX"],
            "alpha" => ["ALPMIN", "ALPMAX"],
            "camber" => ["CAMMIN", "CAMMAX"],
            _ => ["PRESMIN", "PRESMAX"],
        };
        limits.set(keys[0], a.min(b));
        limits.set(keys[1], a.max(b));
    }
    limits
}

/// The comment on the ranges of a `.tir`: those written, and the
/// variables held at one value, whose range is not written (`kept`: the
/// template's, where it gives one).
pub(crate) fn tir_comment(spans: &[Span], template: bool) -> String {
    let varied: Vec<String> = spans
        .iter()
        .filter(|s| s.lo < s.hi)
        .map(Span::text)
        .collect();
    let fixed: Vec<String> = spans
        .iter()
        .filter(|s| s.lo >= s.hi)
        .map(Span::text)
        .collect();
    let mut s = format!(
        "$ validity ranges: those of the rig rows fitted ({}), written as FZMIN…PRESMAX\n",
        varied.join(", ")
    );
    if !fixed.is_empty() {
        let kept = if template {
            "the template's range, if any, is kept"
        } else {
            "no range is written"
        };
        s += &format!("$ at one value in the rows: {}: {kept}\n", fixed.join(", "));
    }
    s
}

/// The spans of a swarm fit's conditions: load, slip angle or ratio,
/// camber, pressure (where measured).
pub(crate) fn condition_spans(conditions: &[Condition]) -> Vec<Span> {
    let points = || conditions.iter().flat_map(|c| &c.points);
    let alpha = points().filter_map(|p| match p.sweep {
        Sweep::Lateral { alpha, .. } => Some(alpha),
        _ => None,
    });
    let kappa = points().filter_map(|p| match p.sweep {
        Sweep::Longitudinal { kappa, .. } => Some(kappa),
        _ => None,
    });
    [
        Span::of("fz", "N", points().map(|p| p.fz)),
        Span::of("alpha", "rad", alpha),
        Span::of("kappa", "", kappa),
        Span::of("camber", "rad", points().map(|p| p.camber)),
        Span::of(
            "pressure",
            "Pa",
            conditions.iter().filter_map(|c| c.pressure),
        ),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The spans of every condition a swarm fit ran on (lateral and
/// longitudinal), widened to the samples fitted there
/// ([`SwarmReport::sample_spans`](super::SwarmReport)): what the written
/// file's header and `[fitted_ranges]` state as fitted.
pub(crate) fn fitted_spans(r: &super::SwarmReport) -> Vec<Span> {
    let conditions: Vec<_> = r
        .conditions
        .iter()
        .chain(&r.longitudinal_conditions)
        .cloned()
        .collect();
    let spans = widened_to(condition_spans(&conditions), &r.sample_spans);
    widened_to_slips(spans, r.sample_slips)
}

/// `spans` each widened to the span of the same name in `reached`.
fn widened_to(mut spans: Vec<Span>, reached: &[Span]) -> Vec<Span> {
    for s in &mut spans {
        if let Some(r) = reached.iter().find(|r| r.name == s.name) {
            (s.lo, s.hi) = (s.lo.min(r.lo), s.hi.max(r.hi));
        }
    }
    spans
}

/// `spans` with their slip angle and slip ratio widened to `reached`
/// (`[alpha, kappa]`, the samples' extremes): the slips as the samples
/// reached them, not as their bins' means — one rule for the swarm fits and
/// the staged Magic Formula fit, so that `pac89` and `mf61` state the same
/// range of one file.
fn widened_to_slips(mut spans: Vec<Span>, reached: [Option<(f64, f64)>; 2]) -> Vec<Span> {
    for s in &mut spans {
        let reached = match s.name {
            "alpha" => reached[0],
            "kappa" => reached[1],
            _ => None,
        };
        if let Some((lo, hi)) = reached {
            (s.lo, s.hi) = (s.lo.min(lo), s.hi.max(hi));
        }
    }
    spans
}

/// `spans` of the staged fit's rows (means over slip-angle bins) with their
/// slips widened to those of the samples of `d` inside the spans' load,
/// camber and pressure ([`slip_extremes`]): the Hoosier file's samples
/// reach 0.17026 rad where its bins' means reach 0.16956, and a `.tir`
/// whose `ALPMAX` is the latter saturates its own rig's extreme samples.
pub(crate) fn widened_to_sample_slips(spans: Vec<Span>, d: &RigData) -> Vec<Span> {
    let inside = |name: &str, v: f64| {
        spans
            .iter()
            .find(|s| s.name == name)
            .is_none_or(|s| (s.lo..=s.hi).contains(&v))
    };
    let keep = |i: usize| {
        inside("fz", d.fz[i])
            && inside("camber", d.camber[i])
            && d.pressure.as_ref().is_none_or(|p| inside("pressure", p[i]))
    };
    let reached = [
        slip_extremes(d, SlipAxis::Angle, f64::INFINITY, &keep),
        slip_extremes(d, SlipAxis::Ratio, f64::INFINITY, &keep),
    ];
    widened_to_slips(spans, reached)
}

/// Sets the slips, loads, cambers and pressures the samples `d` of `r`'s
/// first fit reach ([`sample_reach`]; a linear tyre's within its window).
pub(crate) fn set_first_sample_slips(r: &mut super::SwarmReport, d: &RigData) {
    use crate::identify::Channel;
    let (axis, k) = match r.fit.channel {
        Channel::LongitudinalForce => (SlipAxis::Ratio, 1),
        _ => (SlipAxis::Angle, 0),
    };
    let window = linear_window_reach(r);
    let (slips, spans) = sample_reach(d, axis, &r.grouping.levels, &r.conditions, window);
    r.sample_slips[k] = slips;
    r.sample_spans = union(&r.sample_spans, &spans);
    if let (Some(w), Some((lo, hi))) = (r.linear_window.as_mut(), slips) {
        // The window's line says how far its bins' samples reach.
        w.samples_reach_deg = Some(lo.abs().max(hi.abs()).to_degrees());
    }
}

/// How far from zero slip angle the samples of a linear tyre's fit reach
/// (rad; infinite where its window left no point out). The window keeps
/// the points, means over slip bins, within it: a sample of a kept bin
/// lies up to half a bin past its mean's bin centre, so the reach is the
/// outer edge of the outermost kept bin. (The window's own reach, the
/// largest bin mean, left a rig's ±0.040 rad samples out of a written
/// `alpha = [-0.039, 0.039]`, where every sample was fitted.)
fn linear_window_reach(r: &super::SwarmReport) -> f64 {
    let Some(w) = r.linear_window.as_ref() else {
        return f64::INFINITY;
    };
    if w.points_left_out == 0 && w.loads_left_out.is_empty() {
        return f64::INFINITY;
    }
    let largest = r
        .conditions
        .iter()
        .flat_map(|c| &c.points)
        .map(|p| p.slip().abs())
        .fold(0.0, f64::max);
    let bin = r.options.alpha_bin_deg.to_radians();
    match bin > 0.0 {
        true => ((largest / bin).round() + 0.5) * bin,
        false => largest,
    }
}

/// The spans of `a` and `b` joined name by name.
pub(crate) fn union(a: &[Span], b: &[Span]) -> Vec<Span> {
    let mut out = a.to_vec();
    for s in b {
        match out.iter_mut().find(|o| o.name == s.name) {
            Some(o) => (o.lo, o.hi) = (o.lo.min(s.lo), o.hi.max(s.hi)),
            None => out.push(*s),
        }
    }
    out
}

/// The level index of `v` among `levels`' levels of `variable` (`None`
/// without such levels: every value alike).
fn level_of(levels: &[Levels], variable: Variable, v: Option<f64>) -> Option<usize> {
    let l = levels.iter().find(|l| l.variable == variable)?;
    let v = v?;
    l.levels.iter().position(|q| q.holds(v))
}

/// What the samples of `d` fitted in `conditions` (grouped at `levels`)
/// reach, within `max_abs` of zero slip along `axis` (a linear tyre's
/// window): the smallest and largest slip, and the spans of their load,
/// camber and pressure. A sample is fitted when its load, camber and
/// pressure levels are those of a condition (a condition's nominal is the
/// median of its samples, inside its levels): the samples, not the
/// conditions' points, which are means over slip bins (the Hoosier
/// file's 1656 N level at 0° and 83.4 kPa: samples 1503 to 1795 N, its
/// points' means 1601 to 1681 N), nor every sample of the levels (1474 to
/// 1823 N at every camber and pressure).
pub(crate) fn sample_reach(
    d: &RigData,
    axis: SlipAxis,
    levels: &[Levels],
    conditions: &[Condition],
    max_abs: f64,
) -> (Option<(f64, f64)>, Vec<Span>) {
    let key = |fz: f64, camber: f64, pressure: Option<f64>| {
        (
            level_of(levels, Variable::Load, Some(fz)),
            level_of(levels, Variable::Camber, Some(camber)),
            level_of(levels, Variable::Pressure, pressure),
        )
    };
    let keys: Vec<_> = conditions
        .iter()
        .map(|c| key(c.fz, c.camber, c.pressure))
        .collect();
    let pressure = |i: usize| d.pressure.as_ref().map(|p| p[i]);
    let keep = |i: usize| keys.contains(&key(d.fz[i], d.camber[i], pressure(i)));
    let slips = slip_extremes(d, axis, max_abs, &keep);
    let (slip, force) = match axis {
        SlipAxis::Angle => (&d.alpha, &d.fy),
        SlipAxis::Ratio => match d.longitudinal.as_ref() {
            Some((k, f)) => (k, f),
            None => return (slips, Vec::new()),
        },
    };
    let fitted: Vec<usize> = (0..d.len())
        .filter(|&i| force[i].is_finite() && slip[i].abs() <= max_abs && keep(i))
        .collect();
    let spans = [
        Span::of("fz", "N", fitted.iter().map(|&i| d.fz[i])),
        Span::of("camber", "rad", fitted.iter().map(|&i| d.camber[i])),
        Span::of("pressure", "Pa", fitted.iter().filter_map(|&i| pressure(i))),
    ];
    (slips, spans.into_iter().flatten().collect())
}

/// The smallest and largest slip along `axis` of the samples of `d` with
/// a measured force, within `max_abs` of zero, that `keep` keeps (by
/// index): the range the data cover, shared by every fit's stated ranges.
fn slip_extremes(
    d: &RigData,
    axis: SlipAxis,
    max_abs: f64,
    keep: &dyn Fn(usize) -> bool,
) -> Option<(f64, f64)> {
    let (slip, force) = match axis {
        SlipAxis::Angle => (&d.alpha, &d.fy),
        SlipAxis::Ratio => d.longitudinal.as_ref().map(|(k, f)| (k, f))?,
    };
    let within =
        (0..d.len()).filter(|&i| force[i].is_finite() && slip[i].abs() <= max_abs && keep(i));
    Span::of("slip", "", within.map(|i| slip[i])).map(|s| (s.lo, s.hi))
}

/// `spans` of thinned rows (means over slip-angle bins) widened to the
/// sample ranges of the levels `levels` that they reach: a bin's mean load
/// lies inside its level, so the rows' span is narrower than what the rig
/// tested, and a `.tir`'s `FZMIN` from it would saturate a tested load (the
/// Hoosier file's 420 N at the means' 455 N).
pub(crate) fn widened_to_reached_levels(mut spans: Vec<Span>, levels: &[Levels]) -> Vec<Span> {
    for s in &mut spans {
        let variable = match s.name {
            "fz" => Variable::Load,
            "camber" => Variable::Camber,
            "pressure" => Variable::Pressure,
            _ => continue,
        };
        let reached = levels
            .iter()
            .filter(|l| l.variable == variable)
            .flat_map(|l| &l.levels)
            .filter(|q| q.hi >= s.lo && q.lo <= s.hi)
            .map(|q| (q.lo, q.hi))
            .collect::<Vec<_>>();
        for (lo, hi) in reached {
            s.lo = s.lo.min(lo);
            s.hi = s.hi.max(hi);
        }
    }
    spans
}

/// The `[fitted_ranges]` of `spans`: each that is not one value (a
/// slip-ratio range of 0 to 0 would count every longitudinal point), and
/// a load, camber or pressure the data hold at one value as `[v, v]`: a
/// fit at one load is no fit at another (`--model linear --load 4000`
/// stated no load, and `tyre-eval` at 2000 N said nothing).
pub(crate) fn fitted_ranges(spans: &[Span]) -> FittedRanges {
    let mut r = FittedRanges::default();
    let level = |s: &Span| ["fz", "camber", "pressure"].contains(&s.name);
    for s in spans.iter().filter(|s| s.lo < s.hi || level(s)) {
        let range = Some([s.lo, s.hi]);
        match s.name {
            "fz" => r.fz = range,
            "alpha" => r.alpha = range,
            "kappa" => r.kappa = range,
            "camber" => r.camber = range,
            _ => r.pressure = range,
        }
    }
    r
}

/// The line on a swarm fit's data ranges (without its mark).
pub(crate) fn toml_line(spans: &[Span]) -> String {
    let all: Vec<String> = spans.iter().map(Span::text).collect();
    format!(
        "ranges of the rig data fitted: {}; the tyre is not checked beyond them",
        all.join(", ")
    )
}
