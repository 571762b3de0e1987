//! The figure of a staged Magic Formula fit: the measured rows of each
//! fitted stage as hollow rings, a colour per condition (load, camber,
//! pressure and, for the combined-slip stages, the level of the other
//! slip; past nine conditions in a panel the colours again with diamonds
//! and dashed lines, then discs and dotted lines, [`level_style`]), and
//! the identified tyre as a line in the condition's colour
//! drawn over every condition's points: a smooth curve of
//! [`LINE_POINTS`] slips evenly spaced over the condition's own slip
//! range, at its mean load, camber, pressure, speed and other slip. A panel per stage, camber level and pressure level (and load
//! level where the other slip has several levels), each titled with its own
//! σ = sqrt(Σe²/ΣF²)·100 % over its rows (the stage's σ is over all of
//! them). The x axis is the slip the stage's rows sweep: the slip ratio
//! (percent) for the longitudinal force, pure and combined, for the
//! combined lateral force and aligning moment (the slip-ratio sweeps of a
//! drive/brake test, at their slip-angle levels) and for the rolling
//! resistance; the slip angle (degrees) for the pure lateral force, the
//! pure aligning moment and the overturning moment. The y range is the
//! data's (the key sits beside the chart, [`crate::report::plot`]).

pub(super) use super::fit_key::{key_entries, level_style, MEASURED};
use crate::format::{fixed, plural};
use crate::identify::grouping::{Levels as Named, Variable};
use crate::identify::mf_staged::{sweeps_slip_angle, MfRow, Stage, PURE_TOL};
use crate::report::plot::{tick_label, Figure, Marker, Panel, Series, Shape, Style, Tone};
use crate::tyre::mf::MagicFormula;
use std::path::{Path, PathBuf};

/// A slip variable: the x of a panel, or the level its lines are drawn at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Slip {
    /// Slip angle α (rad; degrees on the figure).
    Angle,
    /// Slip ratio κ (percent on the figure).
    Ratio,
}

impl Slip {
    /// The slip a stage's channel is read against (module notes): the
    /// one its rows sweep ([`sweeps_slip_angle`]).
    fn of_stage(st: Stage) -> Self {
        if sweeps_slip_angle(st) {
            Slip::Angle
        } else {
            Slip::Ratio
        }
    }

    fn other(self) -> Self {
        match self {
            Slip::Angle => Slip::Ratio,
            Slip::Ratio => Slip::Angle,
        }
    }

    fn of(self, r: &MfRow) -> f64 {
        match self {
            Slip::Angle => r.alpha,
            Slip::Ratio => r.kappa,
        }
    }

    fn set(self, r: &mut MfRow, v: f64) {
        match self {
            Slip::Angle => r.alpha = v,
            Slip::Ratio => r.kappa = v,
        }
    }

    /// In the figure's unit: degrees, percent.
    fn shown(self, v: f64) -> f64 {
        match self {
            Slip::Angle => v.to_degrees(),
            Slip::Ratio => 100.0 * v,
        }
    }

    fn axis(self) -> &'static str {
        match self {
            Slip::Angle => "slip angle α [deg]",
            Slip::Ratio => "slip ratio κ [%]",
        }
    }

    /// Values within this of each other are one level.
    fn gap(self) -> f64 {
        match self {
            Slip::Angle => 0.5f64.to_radians(),
            Slip::Ratio => 0.01,
        }
    }

    fn level(self, v: f64) -> String {
        match self {
            Slip::Angle => format!("α {}°", tick_label(v.to_degrees(), 10.0)),
            Slip::Ratio => format!("κ {} %", tick_label(100.0 * v, 10.0)),
        }
    }
}

/// The channel of a stage with its unit, as an axis names it.
fn channel(st: Stage) -> &'static str {
    match st {
        Stage::PureFx | Stage::CombinedFx => "Fx [N]",
        Stage::PureFy | Stage::CombinedFy => "Fy [N]",
        Stage::PureMz | Stage::CombinedMz => "Mz [N·m]",
        Stage::Mx => "Mx [N·m]",
        Stage::My => "My [N·m]",
    }
}

/// Levels of a quantity: sorted values split where consecutive ones are
/// more than `gap` apart; each level's mean.
pub(super) fn clusters(values: impl Iterator<Item = f64>, gap: f64) -> Vec<f64> {
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

/// The index of the level nearest `x` (0 without levels: an unmeasured
/// quantity).
pub(super) fn nearest(levels: &[f64], x: f64) -> usize {
    (0..levels.len())
        .min_by(|&a, &b| (levels[a] - x).abs().total_cmp(&(levels[b] - x).abs()))
        .unwrap_or(0)
}

/// The levels of a stage's rows: camber, pressure, load and the other
/// slip, and each row's index in them.
struct Levels {
    camber: Vec<f64>,
    pressure: Vec<f64>,
    load: Vec<f64>,
    other: Vec<f64>,
    /// Per row: (camber, pressure, load, other slip) level.
    of_row: Vec<[usize; 4]>,
}

/// `values` (levels of `variable` clustered from the rows) each replaced
/// by the nominal of the grouping's level whose band holds it: the
/// figure then names a level as the terminal does (534 N, not the 532 N
/// its thinned rows average to).
///
/// Loads of rows not grouped (a file whose samples are its rows) are
/// named by their nominal, the mean rounded to [`LOAD_NOMINAL`]: a rig
/// holds a set load to a few newtons, and one condition whose rows a stage
/// averages to 3999 N and another to 4001 N is one 4000 N condition.
fn as_named(values: Vec<f64>, variable: Variable, named: &[Named]) -> Vec<f64> {
    match named.iter().find(|l| l.variable == variable) {
        Some(_) => {
            let names = super::level_names::LevelNames::of(named, &[]);
            values
                .into_iter()
                .map(|v| names.nominal(variable, v))
                .collect()
        }
        None if variable == Variable::Load => values
            .into_iter()
            .map(|v| (v / LOAD_NOMINAL).round() * LOAD_NOMINAL)
            .collect(),
        None => values,
    }
}

/// The step a load level's nominal is rounded to where the rows were
/// not grouped, N: as `identify` rounds `FNOMIN` (the median load).
const LOAD_NOMINAL: f64 = 10.0;

impl Levels {
    fn of(rows: &[&MfRow], other: Slip, named: &[Named]) -> Self {
        let p = |r: &MfRow| r.pressure.unwrap_or(f64::NAN);
        let camber = clusters(rows.iter().map(|r| r.camber), 0.25f64.to_radians());
        let camber = as_named(camber, Variable::Camber, named);
        let pressure = clusters(rows.iter().map(|r| p(r)), 2e3);
        let pressure = as_named(pressure, Variable::Pressure, named);
        let load = clusters(rows.iter().map(|r| r.fz), 200.0);
        let load = as_named(load, Variable::Load, named);
        let others = clusters(rows.iter().map(|r| other.of(r)), other.gap());
        let of_row = rows
            .iter()
            .map(|r| {
                [
                    nearest(&camber, r.camber),
                    nearest(&pressure, p(r)),
                    nearest(&load, r.fz),
                    nearest(&others, other.of(r)),
                ]
            })
            .collect();
        Self {
            camber,
            pressure,
            load,
            other: others,
            of_row,
        }
    }
}

/// The figure of the fitted `stages` (skipped ones left out) of `tyre` on
/// `rows` (module notes). The panels form a grid whose columns are the
/// pressure levels when there are several (a blank panel where a
/// condition lacks one), else two columns when there are four panels or
/// more; a row is tall enough for the longest key beside it. Levels are
/// named by the grouping's nominals `named` where the rows were grouped
/// ([`as_named`]).
pub(super) fn staged_figure(
    tyre: &MagicFormula,
    stages: &[Stage],
    rows: &[MfRow],
    named: &[Named],
) -> Figure {
    let mut panels = Vec::new();
    let mut pressures = 1;
    for &st in stages {
        let x = Slip::of_stage(st);
        let sel: Vec<&MfRow> = rows.iter().filter(|r| st.takes(r)).collect();
        // A stage fitted on every row (Mx, My) holds the pure sweeps of
        // both slips: a sweep of the other slip at zero of this one is
        // drawn against the slip it sweeps, not as a column of points. Its
        // combined rows are drawn against this slip where they sweep it (a
        // grid of slip angles at each slip ratio), else against the slip
        // ratio they sweep (a drive/brake test at a few slip-angle levels),
        // as the combined stages draw them: against the slip angle, Mx's
        // slip-ratio sweeps at α = 3° and 6° stood as vertical streaks.
        let ratio_sweeps = x == Slip::Angle && !sweeps_angle(&sel);
        let (along, across): (Vec<&MfRow>, Vec<&MfRow>) = sel.into_iter().partition(|r| {
            if ratio_sweeps {
                r.kappa.abs() <= PURE_TOL
            } else {
                x.of(r).abs() > PURE_TOL || x.other().of(r).abs() <= PURE_TOL
            }
        });
        // A combined lateral stage's rows at zero slip angle are the
        // longitudinal force's pure sweeps, to slip ratios of ±100 %: drawn
        // apart, so that they do not stretch the combined sweeps' ±10 %
        // over a tenth of the panel's width.
        let (zero, along): (Vec<&MfRow>, Vec<&MfRow>) = along.into_iter().partition(|r| {
            matches!(st, Stage::CombinedFy | Stage::CombinedMz) && r.alpha.abs() <= PURE_TOL
        });
        for (x, at) in [(x, along), (x, zero), (x.other(), across)] {
            if !at.is_empty() {
                pressures = pressures.max(stage_panels(tyre, st, x, &at, named, &mut panels));
            }
        }
    }
    let columns = if pressures > 1 {
        pressures
    } else if panels.len() >= 4 {
        2
    } else {
        1
    };
    keyed(panels, columns, ROW_HEIGHT)
}

/// The figure of each fitted stage on its own, written to `<out>.<stage>.png`
/// ([`stage_png`]): the stages in one figure were 1300 × 6600 px on the
/// book's MF 6.1 grid (40 panels), and 1300 × 19,800 px on a denser one,
/// past what a viewer shows at a readable scale; a stage's panels are a
/// page or two.
pub(super) fn stage_figures(
    tyre: &MagicFormula,
    stages: &[Stage],
    rows: &[MfRow],
    named: &[Named],
    out: &Path,
) -> Vec<super::staged::StageFigure> {
    stages
        .iter()
        .map(|&st| super::staged::StageFigure {
            stage: st,
            path: stage_png(out, st),
            figure: staged_figure(tyre, &[st], rows, named),
        })
        .collect()
}

/// The figure file of stage `st` beside the tyre file `out`: `fit.tir` →
/// `fit.pure-fy.png`, the stage spelt as the report's `stage` is.
pub(super) fn stage_png(out: &Path, st: Stage) -> PathBuf {
    let name = st.label().to_lowercase().replace(' ', "-");
    out.with_extension(format!("{name}.png"))
}

/// Whether the combined-slip rows of `sel` (both slips above
/// [`PURE_TOL`]) sweep the slip angle: at least [`SWEPT_LEVELS`] levels
/// of it (none: no combined rows, nothing to decide).
fn sweeps_angle(sel: &[&MfRow]) -> bool {
    let combined = sel
        .iter()
        .filter(|r| r.kappa.abs() > PURE_TOL && r.alpha.abs() > PURE_TOL);
    let levels = clusters(combined.clone().map(|r| r.alpha), Slip::Angle.gap()).len();
    combined.count() == 0 || levels >= SWEPT_LEVELS
}

/// Levels of a slip below which combined rows are taken as held at
/// levels of it rather than swept through it: a sweep's curve needs more
/// than a few points to be read as one.
const SWEPT_LEVELS: usize = 4;

/// A fit figure of `panels` in `columns`: 1000 px wide in one column,
/// 650 px a column in more, each row `row_height` px high unless a panel's
/// key (its labelled series) needs more ([`key_height`]).
pub(super) fn keyed(panels: Vec<Panel>, columns: usize, row_height: u32) -> Figure {
    let entries = panels
        .iter()
        .map(|p| p.series.iter().filter(|s| !s.label.is_empty()).count())
        .max()
        .unwrap_or(0);
    Figure {
        panels,
        columns,
        width: if columns == 1 {
            1000
        } else {
            650 * columns as u32
        },
        row_height: row_height.max(key_height(entries)),
    }
}

/// Height of a row of panels, px, unless a key needs more.
const ROW_HEIGHT: u32 = 300;

/// The height, px, a panel needs for a key of `entries` entries beside
/// it: the key's top margin and rows ([`crate::report::plot`]'s legend)
/// and the x axis's labels below.
fn key_height(entries: usize) -> u32 {
    40 + 20 * entries as u32 + 30
}

/// The panels of stage `st` along slip `x` on its rows `sel`, pushed onto
/// `panels`; the number of pressure levels (the grid's columns).
fn stage_panels(
    tyre: &MagicFormula,
    st: Stage,
    x: Slip,
    sel: &[&MfRow],
    named: &[Named],
    panels: &mut Vec<Panel>,
) -> usize {
    let lv = Levels::of(sel, x.other(), named);
    // A panel per load where the other slip has levels of its own: the
    // lines of a panel are then the other slip's levels.
    let by_load = lv.other.len() > 1;
    let loads = if by_load { lv.load.len() } else { 1 };
    for c in 0..lv.camber.len().max(1) {
        for l in 0..loads {
            for p in 0..lv.pressure.len().max(1) {
                let at: Vec<(usize, &MfRow)> = sel
                    .iter()
                    .zip(&lv.of_row)
                    .filter(|(_, k)| k[0] == c && k[1] == p && (!by_load || k[2] == l))
                    .map(|(r, k)| (if by_load { k[3] } else { k[2] }, *r))
                    .collect();
                let key = Key {
                    stage: st,
                    x,
                    camber: lv.camber.get(c).copied(),
                    pressure: lv.pressure.get(p).copied(),
                    load: by_load.then(|| lv.load[l]),
                };
                panels.push(panel(tyre, &key, &at, &lv, by_load));
            }
        }
    }
    lv.pressure.len()
}

/// What a panel shows: the stage, its x, and the levels it is at.
struct Key {
    stage: Stage,
    x: Slip,
    camber: Option<f64>,
    pressure: Option<f64>,
    load: Option<f64>,
}

impl Key {
    fn title(&self, tail: &str) -> String {
        let mut t = self.stage.label().to_string();
        if let Some(g) = self.camber {
            t += &format!(", γ {}", Variable::Camber.display(g));
        }
        if let Some(p) = self.pressure {
            t += &format!(", {}", Variable::Pressure.display(p));
        }
        if let Some(fz) = self.load {
            t += &format!(", Fz {}", Variable::Load.display(fz));
        }
        format!("{t}: {tail}")
    }
}

/// One panel: `rows` tagged with their line's level (load, or the other
/// slip's level with `by_other`).
fn panel(
    tyre: &MagicFormula,
    key: &Key,
    rows: &[(usize, &MfRow)],
    lv: &Levels,
    by_other: bool,
) -> Panel {
    let st = key.stage;
    let x_label = key.x.axis().to_string();
    if rows.is_empty() {
        return Panel {
            title: key.title("no points"),
            x_label,
            y_label: channel(st).into(),
            ..Panel::default()
        };
    }
    // The key opens with the grey swatches of measured (points) and
    // fitted (line), then a colour per level: its points and its fitted
    // line in that colour, so that each curve is read against its own
    // points (black lines over coloured points could not be told apart).
    let mut series = key_entries(Style::Points(3), MEASURED);
    series[0].marker = Some(RING);
    // Every level's line is drawn after every level's points: a line drawn
    // before the next level's points lay under them where two curves meet
    // (the aligning moment's near zero slip and past its peak).
    let mut lines = Vec::new();
    let (mut e2, mut y2) = (0.0, 0.0);
    let count = if by_other {
        lv.other.len()
    } else {
        lv.load.len()
    };
    for k in 0..count {
        let at: Vec<&MfRow> = rows
            .iter()
            .filter(|(level, _)| *level == k)
            .map(|(_, r)| *r)
            .collect();
        if at.is_empty() {
            continue;
        }
        // One style per level drawn in the panel, none the key's grey.
        let label = level_label(key, lv, by_other, k);
        let (points, line, sums) = level_series(tyre, key, &at, &label, lines.len());
        e2 += sums.0;
        y2 += sums.1;
        series.push(points);
        lines.push(line);
    }
    series.extend(lines);
    let sigma = 100.0 * (e2 / y2).sqrt();
    Panel {
        title: key.title(&format!(
            "σ {} %, {}",
            fixed(sigma, 2),
            // "points", as the terminal counts a stage's rows and the
            // swarm figures their points: one word for both.
            plural(rows.len(), "point", "points")
        )),
        x_label,
        y_label: channel(st).into(),
        series,
        ..Panel::default()
    }
}

/// One level's measured rows `at` (its points, ringed) and its fitted
/// line, in the panel's `drawn`-th level style, labelled `label`; and the
/// sums of squared residuals and of squared measurements over its rows.
fn level_series(
    tyre: &MagicFormula,
    key: &Key,
    at: &[&MfRow],
    label: &str,
    drawn: usize,
) -> (Series, Series, (f64, f64)) {
    let st = key.stage;
    let style = level_style(drawn);
    let colour = style.colour;
    let xs: Vec<f64> = at.iter().map(|r| key.x.shown(key.x.of(r))).collect();
    let measured: Vec<f64> = at.iter().map(|r| st.measured(r)).collect();
    let (mut e2, mut y2) = (0.0, 0.0);
    for (r, m) in at.iter().zip(&measured) {
        e2 += (st.model(tyre, r) - m).powi(2);
        y2 += m * m;
    }
    let (lx, ly) = model_line(tyre, st, key.x, at);
    // The key's entry on the level's line, as the swarm figure's; on
    // its points where it has no line (a single slip value).
    let (point_label, line_label) = if lx.is_empty() {
        (label, "")
    } else {
        ("", label)
    };
    let points = Series::line(point_label, &xs, &measured, colour)
        .styled(Style::Points(3))
        .toned(Tone::Pale);
    let points = points.marked(Marker {
        shape: style.shape,
        ..RING
    });
    let line = Series::line(line_label, &lx, &ly, colour).styled(style.line);
    (points, line, (e2, y2))
}

/// How a measured row is drawn: a ring, hollow and pale ([`Tone::Pale`]),
/// so that the level's fitted line, drawn over it in the level's full
/// colour, reads through its points (over filled dots of its colour a
/// close fit's line vanished, and over 395 rings of its colour a panel of
/// the Hoosier file's pure Fy showed bands, not lines).
const RING: Marker = Marker {
    shape: Shape::Ring,
    size: 3,
};

/// The key's name of a panel's `k`-th level: the other slip's level with
/// `by_other`, else the load, as the terminal spells it.
fn level_label(key: &Key, lv: &Levels, by_other: bool, k: usize) -> String {
    if by_other {
        key.x.other().level(lv.other[k])
    } else {
        Variable::Load.display(lv.load[k])
    }
}

/// Points of a model line: enough that the narrow peak of a combined-slip
/// aligning moment near κ = 0 on a ±100 % axis is drawn as a curve.
const LINE_POINTS: u32 = 240;

/// The tyre's channel of stage `st` along the slip `x`, over the range of
/// the condition's rows `at` ([`LINE_POINTS`] points, in increasing x), at their mean
/// load, camber, pressure, speed and other slip.
fn model_line(tyre: &MagicFormula, st: Stage, x: Slip, at: &[&MfRow]) -> (Vec<f64>, Vec<f64>) {
    let n = at.len() as f64;
    let mean = |f: &dyn Fn(&MfRow) -> f64| at.iter().map(|r| f(r)).sum::<f64>() / n;
    let pressures: Vec<f64> = at.iter().filter_map(|r| r.pressure).collect();
    let mut row = MfRow {
        fz: mean(&|r| r.fz),
        camber: mean(&|r| r.camber),
        speed: mean(&|r| r.speed),
        pressure: (!pressures.is_empty())
            .then(|| pressures.iter().sum::<f64>() / pressures.len() as f64),
        ..*at[0]
    };
    x.other().set(&mut row, mean(&|r| x.other().of(r)));
    let (lo, hi) = at
        .iter()
        .map(|r| x.of(r))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if hi <= lo {
        return (Vec::new(), Vec::new());
    }
    (0..LINE_POINTS)
        .map(|i| {
            let v = lo + (hi - lo) * f64::from(i) / f64::from(LINE_POINTS - 1);
            x.set(&mut row, v);
            (x.shown(v), st.model(tyre, &row))
        })
        .unzip()
}

#[cfg(test)]
#[path = "staged_figure_tests.rs"]
mod tests;
