//! Grouping of tyre rig samples into test conditions (nominal load, camber,
//! pressure) and thinning of each condition along its slip axis, losing
//! nothing silently.
//!
//! Rig files come in many layouts: the identification papers' tables (one
//! sample per slip angle, exact nominal loads), continuous sweeps from a rig
//! (loads that wander ±200 N about their nominal value, ramps between
//! levels), up-and-down sweeps, longitudinal sweeps on a discrete slip-ratio
//! grid. The grouping therefore assumes nothing about sample counts:
//!
//! - **Levels** of a grouping variable (load, camber, pressure) come from the
//!   gaps between its sorted values. The noise of the variable is estimated
//!   from the differences of consecutive samples in recording order (robust:
//!   the median, so ramps between levels do not count), and a gap wider than
//!   `max(resolution, 6 σ)` separates two levels — so close levels stay apart
//!   whenever the data separate them. A group wider than `8·max(resolution,
//!   6 σ)` is then split at density valleys (a histogram of bins of that
//!   width; bins holding less than 1 % of the group are *transitions*), so a
//!   ramp between two levels does not merge them. A narrower group is split
//!   on its own scale (32 bins across it, `own_scale.rs`) at a dip at least
//!   the resolution wide between parts each holding 5 % of it whose medians
//!   lie 4 within-level deviations apart (no cut inside one level's
//!   scatter); a valley's samples within 4 deviations of a level join it.
//!   Every 4th row of a rig's sweep would join levels 560 N apart without
//!   it. A level is kept whatever its share of the file; fewer than three
//!   samples apart from the rest are not a level: counted as too few for
//!   one (two rows at one load are no ramp between levels).
//! - **Selection** of one load, pressure or camber level: an error when the
//!   file has no such column or when the value lies outside every level's
//!   band (the level's range widened by the separation threshold). The
//!   level a value selects is recorded ([`Selected`]) with its nominal and
//!   its samples' range, as a value asked for need not be a nominal.
//! - **Thinning** averages the samples of one condition that fall into one
//!   slip bin (`alpha_bin` for slip angle, `kappa_bin` for slip ratio): a bin
//!   with one sample keeps it, so no slip point is ever lost; up and down
//!   sweeps through the same bin average their hysteresis.
//!
//! Every sample is accounted for in [`GroupingReport`]: used, in a
//! transition, or outside the selected level.
//! Units: N, rad, Pa, m/s; slip ratio dimensionless.
//!
//! Layout: `levels.rs` finds the levels of one variable; this file selects
//! and groups the samples into conditions; `thin.rs` thins each into fit
//! points.

mod fitted;
pub(crate) mod levels;
mod own_scale;
mod thin;

pub use super::data::SlipAxis;
pub use levels::{levels, Level, Levels, Variable, LEVEL_SAMPLES};
use levels::{levels_and_too_few, TooFew};

use super::data::{Condition, RigData};
use crate::error::{InputError, InputProblem, SampleAccount};
use crate::format::{plural, readable};
use serde::Serialize;
use std::path::Path;
use thin::{resolved_bin, thin, SweepColumns};

/// Grouping and thinning settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grouping {
    /// Smallest load difference that separates two levels, N.
    pub load_resolution: f64,
    /// Smallest camber difference that separates two levels, rad.
    pub camber_resolution: f64,
    /// Smallest pressure difference that separates two levels, Pa.
    pub pressure_resolution: f64,
    /// Slip-angle bin for thinning, rad (0: no thinning).
    pub alpha_bin: f64,
    /// Slip-ratio bin for thinning of longitudinal data (0: no thinning).
    pub kappa_bin: f64,
    /// Keep only the load level holding this value, N.
    pub load: Option<f64>,
    /// Keep only the pressure level holding this value, Pa.
    pub pressure: Option<f64>,
    /// Keep only the camber level holding this value, rad.
    pub camber: Option<f64>,
    /// Speed when the data has none, m/s.
    pub default_speed: f64,
}

impl Default for Grouping {
    fn default() -> Self {
        Self {
            load_resolution: 10.0,
            camber_resolution: 0.1f64.to_radians(),
            pressure_resolution: 1000.0,
            alpha_bin: 0.25f64.to_radians(),
            kappa_bin: 0.0025,
            load: None,
            pressure: None,
            camber: None,
            default_speed: 10.0,
        }
    }
}

/// Where every sample went.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroupingReport {
    /// Samples in the file.
    pub samples: usize,
    /// Samples in the conditions.
    pub used: usize,
    /// Fit points after thinning.
    pub points: usize,
    /// The slip the thinning binned, and its bin (rad or ratio; 0: none).
    pub slip_axis: SlipAxis,
    /// Thinning bin.
    pub slip_bin: f64,
    /// Whether the bin is below the resolution of the data's slips (a
    /// slip's bin number beyond 2⁵²): every sample is then kept.
    pub slip_bin_below_resolution: bool,
    /// Levels of load, camber and (if measured) pressure.
    pub levels: Vec<Levels>,
    /// Samples between levels of some variable, dropped.
    pub dropped_in_transitions: usize,
    /// Samples in a group of values of some variable too few to be a
    /// level (fewer than [`LEVEL_SAMPLES`]), dropped: not a ramp between
    /// levels.
    pub dropped_too_few: usize,
    /// Samples at other load, pressure or camber levels than the one
    /// selected.
    pub not_selected: usize,
    /// The levels selected by a value asked for (none: every level).
    pub selected: Vec<Selected>,
}

/// The level a value asked for selects: a value inside a level's band
/// (its samples' range widened by the separation) selects it, though it
/// need not be its nominal.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Selected {
    /// The variable.
    pub variable: Variable,
    /// The value asked for (SI).
    pub requested: f64,
    /// The level selected.
    pub level: Level,
}

impl Selected {
    /// The line saying which level the value asked for selected. A
    /// camber is said as typed, in rad, with its degrees beside: "camber
    /// 1.60° asked for" answered `--camber 0.028` in a unit the user did
    /// not type, and rounded 0.0001 rad to "0.01°"; a pressure in Pa.
    pub fn line(&self) -> String {
        let v = self.variable;
        let asked = match v {
            Variable::Camber | Variable::Pressure => format!(
                "{} {} ({})",
                crate::error::Num(self.requested),
                if v == Variable::Camber { "rad" } else { "Pa" },
                v.display(self.requested)
            ),
            _ => v.display(self.requested),
        };
        format!(
            "{} {asked} asked for: the {} level selected (its samples {} to {})",
            v.column(),
            v.display(self.level.nominal),
            v.display(self.level.lo),
            v.display(self.level.hi)
        )
    }
}

impl GroupingReport {
    /// Where the samples went, as an error names it.
    pub fn account(&self) -> SampleAccount {
        SampleAccount {
            samples: self.samples,
            used: self.used,
            between_levels: self.dropped_in_transitions,
            too_few: self.dropped_too_few,
            not_selected: self.not_selected,
            levels: self
                .levels
                .iter()
                .map(|l| (l.variable, l.levels.len()))
                .collect(),
        }
    }

    /// The report's lines for a terminal.
    pub fn lines(&self) -> Vec<String> {
        let mut out = vec![format!(
            "{}: {} used in conditions, thinned to {} ({}); {}{} between levels (transitions), {} at levels not selected",
            plural(self.samples, "sample", "samples"),
            self.used,
            plural(self.points, "point", "points"),
            match self.slip_axis {
                _ if self.slip_bin_below_resolution => format!(
                    "no thinning: a bin of {} is below the resolution of the data's slips, so every sample is kept",
                    match self.slip_axis {
                        SlipAxis::Angle => format!("{}°", readable(self.slip_bin.to_degrees(), 3)),
                        SlipAxis::Ratio => readable(self.slip_bin, 3),
                    }
                ),
                SlipAxis::Angle if self.slip_bin.to_degrees() >= 1e-3 =>
                    format!("{:.3}° slip-angle bins", self.slip_bin.to_degrees()),
                SlipAxis::Angle if self.slip_bin > 0.0 =>
                    format!("{}° slip-angle bins", readable(self.slip_bin.to_degrees(), 3)),
                SlipAxis::Ratio if self.slip_bin > 0.0 =>
                    format!("{} slip-ratio bins", self.slip_bin),
                _ => "no thinning".into(),
            },
            crate::error::too_few_words(self.dropped_too_few),
            self.dropped_in_transitions,
            self.not_selected
        )];
        for l in &self.levels {
            let v = l.variable;
            let levels: Vec<String> = l
                .levels
                .iter()
                .map(|q| format!("{} ({})", v.display(q.nominal), q.samples))
                .collect();
            let mut line = format!("{} levels: {}", v.column(), levels.join(", "));
            if l.transition_samples > 0 {
                line += &format!(
                    "; {} between levels",
                    plural(l.transition_samples, "sample", "samples")
                );
            }
            out.push(line);
        }
        out.extend(self.selected.iter().map(Selected::line));
        out
    }
}

/// Conditions and the account of every sample.
#[derive(Debug, Clone, PartialEq)]
pub struct Grouped {
    /// The conditions, by pressure, camber, load.
    pub conditions: Vec<Condition>,
    /// Where every sample went.
    pub report: GroupingReport,
}

/// A camber request that selects a file without a camber column (whose
/// samples are at 0), rad.
const NO_CAMBER_COLUMN_TOLERANCE: f64 = 1e-6;

/// The level indices a [`Grouping`] selects (`None`: all). A request the
/// file cannot meet is an error.
struct Selection {
    load: Option<usize>,
    camber: Option<usize>,
    pressure: Option<usize>,
}

impl Selection {
    /// Whether a sample at level indices (`l`, `c`, `p`) is selected.
    fn keeps(&self, l: usize, c: usize, p: Option<usize>) -> bool {
        self.load.is_none_or(|w| w == l)
            && self.camber.is_none_or(|w| w == c)
            && (self.pressure.is_none() || p == self.pressure)
    }

    /// The levels selected, each with the value asked for.
    fn record(&self, g: &Grouping, all: [Option<&Levels>; 3]) -> Vec<Selected> {
        let [loads, cambers, pressures] = all;
        [
            (g.load, self.load, loads),
            (g.camber, self.camber, cambers),
            (g.pressure, self.pressure, pressures),
        ]
        .into_iter()
        .filter_map(|(asked, k, levels)| {
            let (requested, k, levels) = (asked?, k?, levels?);
            Some(Selected {
                variable: levels.variable,
                requested,
                level: levels.levels[k],
            })
        })
        .collect()
    }
}

/// The levels a [`Grouping`] selects. A request the file cannot meet is
/// an error.
fn selection(
    refuse: &dyn Fn(InputProblem) -> InputError,
    d: &RigData,
    g: &Grouping,
    loads: &Levels,
    cambers: &Levels,
    pressures: Option<&Levels>,
) -> Result<Selection, InputError> {
    let select = |l: &Levels, want: f64| {
        l.select(want).ok_or_else(|| {
            refuse(InputProblem::NoLevelNear {
                variable: l.variable,
                requested: want,
                levels: l.levels.iter().map(|q| q.nominal).collect(),
                separation: l.separation,
                slip: l.unit_slip(want),
            })
        })
    };
    let load = g.load.map(|w| select(loads, w)).transpose()?;
    let pressure = match (g.pressure, pressures) {
        (None, _) => None,
        (Some(_), None) => return Err(refuse(InputProblem::NoPressureColumn)),
        (Some(p), Some(levels)) => Some(select(levels, p)?),
    };
    let camber = match g.camber {
        None => None,
        // Without the column every sample is at camber 0 (FORMATS.md): a
        // request for 0 selects them all, any other camber is not there.
        Some(c) if !d.camber_measured && c.abs() <= NO_CAMBER_COLUMN_TOLERANCE => None,
        Some(c) if !d.camber_measured => {
            return Err(refuse(InputProblem::NoCamberColumn { camber: c }))
        }
        Some(c) => Some(select(cambers, c)?),
    };
    Ok(Selection {
        load,
        camber,
        pressure,
    })
}

/// The samples of a file sorted into conditions: each condition's (load,
/// camber, pressure) level indices with its samples, by pressure, camber,
/// load; and the samples no condition holds, counted.
struct Sorted {
    groups: Vec<(fitted::Key, Vec<usize>)>,
    /// Samples between the levels of a variable (a ramp).
    transitions: usize,
    /// Samples in a group of values too few to be a level.
    too_few: usize,
    /// Samples at levels the selection leaves out.
    not_selected: usize,
}

/// The samples of `d` sorted into the conditions at its `[loads, cambers]`
/// and `pressures` levels that `selection` keeps.
fn sorted(
    d: &RigData,
    [loads, cambers]: [&Levels; 2],
    pressures: Option<&Levels>,
    selection: &Selection,
    too_few: &[TooFew; 3],
) -> Sorted {
    let mut groups: Vec<(fitted::Key, Vec<usize>)> = Vec::new();
    let (mut transitions, mut not_selected, mut few) = (0, 0, 0);
    for i in 0..d.len() {
        let p_val = d.pressure.as_ref().map(|p| p[i]);
        let l = loads.find(d.fz[i]);
        let c = cambers.find(d.camber[i]);
        let p = match (pressures, p_val) {
            (Some(levels), Some(v)) => levels.find(v).map(Some),
            _ => Some(None),
        };
        let (Some(l), Some(c), Some(p)) = (l, c, p) else {
            let [fz, camber, pressure] = too_few;
            if fz.holds(d.fz[i])
                || camber.holds(d.camber[i])
                || p_val.is_some_and(|v| pressure.holds(v))
            {
                few += 1;
            } else {
                transitions += 1;
            }
            continue;
        };
        if !selection.keeps(l, c, p) {
            not_selected += 1;
            continue;
        }
        match groups.iter_mut().find(|e| e.0 == (l, c, p)) {
            Some(e) => e.1.push(i),
            None => groups.push(((l, c, p), vec![i])),
        }
    }
    groups.sort_by_key(|e| (e.0 .2, e.0 .1, e.0 .0));
    Sorted {
        groups,
        transitions,
        too_few: few,
        not_selected,
    }
}

/// Groups the samples of `d` (from `path`, for errors) into conditions and
/// thins each along `axis` (the slip-ratio sweeps of
/// [`RigData::longitudinal`] for [`SlipAxis::Ratio`]). Selecting a pressure
/// or camber that the file lacks, or that no level lies near, or asking for
/// a sweep it does not have, is an error.
pub fn group(
    path: &Path,
    d: &RigData,
    g: &Grouping,
    axis: SlipAxis,
) -> Result<Grouped, InputError> {
    let refuse = |problem| InputError::problem(path, problem);
    let columns = SweepColumns::of(d, axis).ok_or_else(|| refuse(InputProblem::NoLongitudinal))?;
    let (loads, few_loads) = levels_and_too_few(Variable::Load, &d.fz, g.load_resolution);
    let (cambers, few_cambers) =
        levels_and_too_few(Variable::Camber, &d.camber, g.camber_resolution);
    let (pressures, few_pressures) = match d.pressure.as_ref() {
        Some(p) => {
            let (l, f) = levels_and_too_few(Variable::Pressure, p, g.pressure_resolution);
            (Some(l), f)
        }
        None => (None, TooFew::default()),
    };
    let too_few = [few_loads, few_cambers, few_pressures];
    let selection = selection(&refuse, d, g, &loads, &cambers, pressures.as_ref())?;
    let Sorted {
        groups,
        transitions,
        too_few,
        not_selected,
    } = sorted(
        d,
        [&loads, &cambers],
        pressures.as_ref(),
        &selection,
        &too_few,
    );
    let asked = match axis {
        SlipAxis::Angle => g.alpha_bin,
        SlipAxis::Ratio => g.kappa_bin,
    };
    let (bin, below_resolution) = resolved_bin(asked, columns.slip);
    let nominals = fitted::Nominals::of(d, &groups);
    let conditions: Vec<Condition> = groups
        .into_iter()
        .map(|(key, idx)| {
            let (fz, camber, pressure) = nominals.at(key);
            Condition {
                fz,
                camber,
                pressure,
                samples: idx.len(),
                points: thin(d, &columns, &idx, bin, g.default_speed),
            }
        })
        .collect();
    let selected = selection.record(g, [Some(&loads), Some(&cambers), pressures.as_ref()]);
    let mut all_levels = vec![loads, cambers];
    all_levels.extend(pressures);
    let report = GroupingReport {
        samples: d.len(),
        used: conditions.iter().map(|c| c.samples).sum(),
        points: conditions.iter().map(|c| c.points.len()).sum(),
        slip_axis: axis,
        slip_bin: asked,
        slip_bin_below_resolution: below_resolution,
        levels: all_levels,
        dropped_in_transitions: transitions,
        dropped_too_few: too_few,
        not_selected,
        selected,
    };
    debug_assert_eq!(
        report.used + transitions + too_few + not_selected,
        report.samples
    );
    Ok(Grouped { conditions, report })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rig(fz: Vec<f64>, alpha: Vec<f64>) -> RigData {
        let n = fz.len();
        RigData {
            fy: alpha.iter().map(|a| 1000.0 * a).collect(),
            fz,
            alpha,
            camber: vec![0.0; n],
            ..RigData::default()
        }
    }

    #[test]
    fn thinning_keeps_lone_points_and_averages_shared_bins() {
        // Up and down at 1° steps: each bin holds the two sweeps' samples.
        let up: Vec<f64> = (-10..=10).map(|i| (i as f64).to_radians()).collect();
        let mut alpha = up.clone();
        alpha.extend(up.iter().rev().map(|a| a + 0.001));
        let d = rig(vec![3000.0; alpha.len()], alpha);
        let g = group(
            Path::new("x.csv"),
            &d,
            &Grouping::default(),
            SlipAxis::Angle,
        )
        .unwrap();
        assert_eq!(g.conditions.len(), 1);
        let pts = &g.conditions[0].points;
        assert_eq!(pts.len(), 21);
        for (p, a) in pts.iter().zip(&up) {
            assert!((p.slip() - (a + 0.0005)).abs() < 1e-12);
            assert!((p.fy() - 1000.0 * (a + 0.0005)).abs() < 1e-9);
        }
        assert_eq!(g.report.used, 42);
        // The papers' layout: 0.2865° apart, one sample per bin.
        let alpha: Vec<f64> = (-42..=42)
            .map(|i| (0.2865 * i as f64).to_radians())
            .collect();
        let d = rig(vec![2800.0; 85], alpha);
        let g = group(
            Path::new("x.csv"),
            &d,
            &Grouping::default(),
            SlipAxis::Angle,
        )
        .unwrap();
        assert_eq!(g.conditions[0].points.len(), 85);
    }

    #[test]
    fn longitudinal_sweeps_group_into_longitudinal_points() {
        // Slip ratios 0.001 apart with 0.0025 bins: the lateral columns
        // (here a sweep of their own) do not enter.
        let kappa: Vec<f64> = (0..40).map(|i| 0.001 * i as f64).collect();
        let fx: Vec<f64> = kappa.iter().map(|k| 2e4 * k).collect();
        let d = RigData {
            longitudinal: Some((kappa, fx)),
            ..rig(vec![3000.0; 40], vec![0.01; 40])
        };
        let g = group(
            Path::new("x.csv"),
            &d,
            &Grouping::default(),
            SlipAxis::Ratio,
        )
        .unwrap();
        let pts = &g.conditions[0].points;
        assert_eq!(g.report.used, 40);
        assert!(pts.len() < 40);
        for p in pts {
            assert_eq!(p.axis(), SlipAxis::Ratio);
            assert!((p.fx() - 2e4 * p.slip()).abs() < 1e-9);
            assert!(p.fy().is_nan() && p.mz().is_nan());
            assert_eq!(p.slip_state().alpha, 0.0);
            assert_eq!(p.slip_state().kappa, p.slip());
        }
        let e = group(
            Path::new("x.csv"),
            &rig(vec![3000.0; 4], vec![0.0; 4]),
            &Grouping::default(),
            SlipAxis::Ratio,
        )
        .unwrap_err();
        assert!(e.to_string().contains("no longitudinal data"), "{e}");
    }

    #[test]
    fn selecting_a_level_the_file_lacks_is_an_error() {
        let d = rig(vec![3000.0; 10], vec![0.0; 10]);
        let g = Grouping {
            pressure: Some(83_000.0),
            ..Grouping::default()
        };
        let e = group(Path::new("rig.csv"), &d, &g, SlipAxis::Angle).unwrap_err();
        assert!(e.to_string().contains("no `pressure` column"), "{e}");
        let mut d2 = d.clone();
        d2.pressure = Some(vec![97_000.0; 10]);
        let e = group(Path::new("rig.csv"), &d2, &g, SlipAxis::Angle).unwrap_err();
        assert!(e.to_string().contains("97.0 kPa"), "{e}");
    }

    #[test]
    fn a_file_without_camber_is_at_camber_zero() {
        let d = rig(vec![3000.0; 10], vec![0.0; 10]);
        let zero = Grouping {
            camber: Some(0.0),
            ..Grouping::default()
        };
        let all = group(
            Path::new("rig.csv"),
            &d,
            &Grouping::default(),
            SlipAxis::Angle,
        )
        .unwrap();
        let at_zero = group(Path::new("rig.csv"), &d, &zero, SlipAxis::Angle).unwrap();
        assert_eq!(at_zero.report, all.report);
        let two = Grouping {
            camber: Some(0.035),
            ..Grouping::default()
        };
        let e = group(Path::new("rig.csv"), &d, &two, SlipAxis::Angle).unwrap_err();
        assert!(e.to_string().contains("no `camber` column"), "{e}");
    }
}
