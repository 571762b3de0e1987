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
//!   ramp between two levels does not merge them. A level is kept whatever
//!   its share of the file; fewer than three samples apart from the rest are
//!   not a level but ramp or isolated samples, counted as transitions.
//! - **Selection** of one pressure or camber level: an error when the file
//!   has no such column or when the value lies outside every level's band
//!   (the level's range widened by the separation threshold).
//! - **Thinning** averages the samples of one condition that fall into one
//!   slip bin (`alpha_bin` for slip angle, `kappa_bin` for slip ratio): a bin
//!   with one sample keeps it, so no slip point is ever lost; up and down
//!   sweeps through the same bin average their hysteresis.
//!
//! Every sample is accounted for in [`GroupingReport`]: used, in a
//! transition, or outside the selected level.
//! Units: N, rad, Pa, m/s; slip ratio dimensionless.

use super::data::{Point, RigData};
use crate::error::InputError;
use serde::Serialize;
use std::path::Path;

/// A grouping variable of rig data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variable {
    /// Vertical load, N.
    Load,
    /// Inclination angle, rad.
    Camber,
    /// Inflation pressure, Pa.
    Pressure,
}

impl Variable {
    /// Column name in the rig file.
    pub fn column(self) -> &'static str {
        match self {
            Variable::Load => "fz",
            Variable::Camber => "camber",
            Variable::Pressure => "pressure",
        }
    }
    /// A value in the unit people read it in.
    pub fn display(self, v: f64) -> String {
        match self {
            Variable::Load => format!("{v:.0} N"),
            Variable::Camber => format!("{:.2}°", v.to_degrees()),
            Variable::Pressure => format!("{:.1} kPa", v / 1000.0),
        }
    }
}

/// A level of a grouping variable.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Level {
    /// Smallest value in it.
    pub lo: f64,
    /// Largest value in it.
    pub hi: f64,
    /// Median of its samples: the condition's nominal value.
    pub nominal: f64,
    /// Samples in it.
    pub samples: usize,
}

/// The levels of one variable and what did not belong to any.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Levels {
    /// The variable.
    pub variable: Variable,
    /// Gap that separates two levels (the threshold used), in the
    /// variable's unit.
    pub separation: f64,
    /// Noise of the variable estimated from consecutive samples.
    pub noise: f64,
    /// The levels, ascending.
    pub levels: Vec<Level>,
    /// Samples between levels (ramps, isolated values), dropped.
    pub transition_samples: usize,
}

impl Levels {
    /// The level holding `v`.
    fn find(&self, v: f64) -> Option<usize> {
        self.levels.iter().position(|l| v >= l.lo && v <= l.hi)
    }
    /// The level a requested value selects: the one whose band (its range
    /// widened by the separation) holds it, nearest nominal first.
    fn select(&self, want: f64) -> Option<usize> {
        (0..self.levels.len())
            .filter(|&k| {
                let l = &self.levels[k];
                want >= l.lo - self.separation && want <= l.hi + self.separation
            })
            .min_by(|a, b| {
                (self.levels[*a].nominal - want)
                    .abs()
                    .total_cmp(&(self.levels[*b].nominal - want).abs())
            })
    }
}

fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    }
}

/// The levels of `values` (in recording order) of `variable`; `resolution`
/// is the smallest separation that counts as a different level.
pub fn levels(variable: Variable, values: &[f64], resolution: f64) -> Levels {
    let mut diffs: Vec<f64> = values.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    diffs.sort_by(f64::total_cmp);
    // For Gaussian noise, |x_{i+1} − x_i| has median 0.6745·√2·σ.
    let in_order = if diffs.is_empty() {
        0.0
    } else {
        median(&diffs) / (0.6745 * std::f64::consts::SQRT_2)
    };
    let mut sorted: Vec<f64> = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    // Rows not recorded level by level (a table flattened slip angle by slip
    // angle, shuffled rows) make neighbours differ by whole level steps: the
    // spread inside groups split at `resolution` bounds the noise then.
    let noise = in_order.min(spread_within(&sorted, resolution));
    let separation = resolution.max(6.0 * noise);
    let mut out = Levels {
        variable,
        separation,
        noise,
        levels: Vec::new(),
        transition_samples: 0,
    };
    let mut start = 0;
    for i in 1..=sorted.len() {
        if i == sorted.len() || sorted[i] - sorted[i - 1] > separation {
            split_valleys(&sorted[start..i], separation, &mut out);
            start = i;
        }
    }
    out
}

/// Robust deviation (1.4826·MAD) of the values about the median of their
/// group, the sorted values split wherever consecutive ones are more than
/// `resolution` apart.
fn spread_within(sorted: &[f64], resolution: f64) -> f64 {
    let mut dev = Vec::with_capacity(sorted.len());
    let mut start = 0;
    for i in 1..=sorted.len() {
        if i == sorted.len() || sorted[i] - sorted[i - 1] > resolution {
            let m = median(&sorted[start..i]);
            dev.extend(sorted[start..i].iter().map(|v| (v - m).abs()));
            start = i;
        }
    }
    if dev.is_empty() {
        return 0.0;
    }
    dev.sort_by(f64::total_cmp);
    1.4826 * median(&dev)
}

/// Splits one gap-separated group at density valleys and records its levels.
fn split_valleys(group: &[f64], separation: f64, out: &mut Levels) {
    let (lo, hi) = (group[0], group[group.len() - 1]);
    let push = |out: &mut Levels, part: &[f64]| {
        if part.len() < 3 {
            out.transition_samples += part.len();
        } else {
            out.levels.push(Level {
                lo: part[0],
                hi: part[part.len() - 1],
                nominal: median(part),
                samples: part.len(),
            });
        }
    };
    if hi - lo <= 8.0 * separation {
        push(out, group);
        return;
    }
    let nb = ((hi - lo) / separation).ceil() as usize;
    let bin = |v: f64| (((v - lo) / separation) as usize).min(nb - 1);
    let mut counts = vec![0usize; nb];
    for &v in group {
        counts[bin(v)] += 1;
    }
    let keep = (group.len() / 100).max(3);
    let mut i = 0;
    while i < group.len() {
        if counts[bin(group[i])] < keep {
            out.transition_samples += 1;
            i += 1;
            continue;
        }
        let mut j = i;
        while j < group.len() && counts[bin(group[j])] >= keep {
            j += 1;
        }
        push(out, &group[i..j]);
        i = j;
    }
}

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
            pressure: None,
            camber: None,
            default_speed: 10.0,
        }
    }
}

/// One test condition and its fit points.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Nominal load, N.
    pub fz: f64,
    /// Nominal camber, rad.
    pub camber: f64,
    /// Nominal pressure, Pa (if measured).
    pub pressure: Option<f64>,
    /// Raw samples in it.
    pub samples: usize,
    /// Fit points (thinned).
    pub points: Vec<Point>,
}

/// Which slip the thinning bins.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlipAxis {
    /// Slip angle (lateral data), rad.
    Angle,
    /// Slip ratio (longitudinal data).
    Ratio,
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
    /// Levels of load, camber and (if measured) pressure.
    pub levels: Vec<Levels>,
    /// Samples between levels of some variable, dropped.
    pub dropped_in_transitions: usize,
    /// Samples at other pressure or camber levels than the one selected.
    pub not_selected: usize,
}

impl GroupingReport {
    /// The report's lines for a terminal.
    pub fn lines(&self) -> Vec<String> {
        let mut out = vec![format!(
            "{} samples: {} used in conditions, thinned to {} points ({}); {} between levels (transitions), {} at levels not selected",
            self.samples,
            self.used,
            self.points,
            match self.slip_axis {
                SlipAxis::Angle if self.slip_bin > 0.0 =>
                    format!("{:.3}° slip-angle bins", self.slip_bin.to_degrees()),
                SlipAxis::Ratio if self.slip_bin > 0.0 =>
                    format!("{} slip-ratio bins", self.slip_bin),
                _ => "no thinning".into(),
            },
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
                line += &format!("; {} samples between levels", l.transition_samples);
            }
            out.push(line);
        }
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

/// Groups the samples of `d` (from `path`, for errors) into conditions and
/// thins each along `axis`. Selecting a pressure or camber that the file
/// lacks, or that no level lies near, is an error.
pub fn group(
    path: &Path,
    d: &RigData,
    g: &Grouping,
    axis: SlipAxis,
) -> Result<Grouped, InputError> {
    let refuse = |message: String| InputError::File {
        path: path.to_path_buf(),
        message,
    };
    let loads = levels(Variable::Load, &d.fz, g.load_resolution);
    let cambers = levels(Variable::Camber, &d.camber, g.camber_resolution);
    let pressures = d
        .pressure
        .as_ref()
        .map(|p| levels(Variable::Pressure, p, g.pressure_resolution));
    let select = |l: &Levels, want: f64| {
        l.select(want).ok_or_else(|| {
            let have: Vec<String> = l
                .levels
                .iter()
                .map(|q| l.variable.display(q.nominal))
                .collect();
            refuse(format!(
                "no {} level near the requested {} (levels: {}; a level holds values within {} of its range)",
                l.variable.column(),
                l.variable.display(want),
                have.join(", "),
                l.variable.display(l.separation)
            ))
        })
    };
    let want_p = match (g.pressure, &pressures) {
        (None, _) => None,
        (Some(_), None) => {
            return Err(refuse(
                "a pressure was requested but the file has no `pressure` column".into(),
            ))
        }
        (Some(p), Some(levels)) => Some(select(levels, p)?),
    };
    let want_c = match g.camber {
        None => None,
        // Without the column every sample is at camber 0 (FORMATS.md): a
        // request for 0 selects them all, any other camber is not there.
        Some(c) if !d.camber_measured && c.abs() <= NO_CAMBER_COLUMN_TOLERANCE => None,
        Some(c) if !d.camber_measured => {
            return Err(refuse(format!(
                "camber {:.2}° was requested but the file has no `camber` column (its samples are at camber 0)",
                c.to_degrees()
            )))
        }
        Some(c) => Some(select(&cambers, c)?),
    };
    // (load, camber, pressure) level indices and the samples there.
    type Key = (usize, usize, Option<usize>);
    let mut groups: Vec<(Key, Vec<usize>)> = Vec::new();
    let (mut transitions, mut not_selected) = (0, 0);
    for i in 0..d.len() {
        let p_val = d.pressure.as_ref().map(|p| p[i]);
        let l = loads.find(d.fz[i]);
        let c = cambers.find(d.camber[i]);
        let p = match (&pressures, p_val) {
            (Some(levels), Some(v)) => levels.find(v).map(Some),
            _ => Some(None),
        };
        let (Some(l), Some(c), Some(p)) = (l, c, p) else {
            transitions += 1;
            continue;
        };
        if want_c.is_some_and(|w| w != c) || (want_p.is_some() && p != want_p) {
            not_selected += 1;
            continue;
        }
        match groups.iter_mut().find(|e| e.0 == (l, c, p)) {
            Some(e) => e.1.push(i),
            None => groups.push(((l, c, p), vec![i])),
        }
    }
    groups.sort_by_key(|e| (e.0 .2, e.0 .1, e.0 .0));
    let bin = match axis {
        SlipAxis::Angle => g.alpha_bin,
        SlipAxis::Ratio => g.kappa_bin,
    };
    let conditions: Vec<Condition> = groups
        .into_iter()
        .map(|((l, c, p), idx)| Condition {
            fz: loads.levels[l].nominal,
            camber: cambers.levels[c].nominal,
            pressure: p.and_then(|k| pressures.as_ref().map(|ps| ps.levels[k].nominal)),
            samples: idx.len(),
            points: thin(d, &idx, bin, g.default_speed),
        })
        .collect();
    let mut all_levels = vec![loads, cambers];
    all_levels.extend(pressures);
    let report = GroupingReport {
        samples: d.len(),
        used: conditions.iter().map(|c| c.samples).sum(),
        points: conditions.iter().map(|c| c.points.len()).sum(),
        slip_axis: axis,
        slip_bin: bin,
        levels: all_levels,
        dropped_in_transitions: transitions,
        not_selected,
    };
    debug_assert_eq!(report.used + transitions + not_selected, report.samples);
    Ok(Grouped { conditions, report })
}

/// The fit points of the samples `idx`: the mean of the samples in each
/// slip bin of width `bin` (each sample its own point when `bin` is 0). A bin
/// with one sample keeps it as it is.
fn thin(d: &RigData, idx: &[usize], bin: f64, default_speed: f64) -> Vec<Point> {
    let speed = |i: usize| d.speed.as_ref().map_or(default_speed, |s| s[i]);
    let mz = |i: usize| d.mz.as_ref().map_or(f64::NAN, |m| m[i]);
    let point = |i: usize| [d.alpha[i], d.fz[i], d.camber[i], speed(i), d.fy[i], mz(i)];
    if bin <= 0.0 {
        return idx.iter().map(|&i| point(i)).collect();
    }
    let mut bins: std::collections::BTreeMap<i64, (Point, usize)> = Default::default();
    for &i in idx {
        let e = bins
            .entry((d.alpha[i] / bin).round() as i64)
            .or_insert(([0.0; 6], 0));
        for (acc, v) in e.0.iter_mut().zip(point(i)) {
            *acc += v;
        }
        e.1 += 1;
    }
    bins.into_values()
        .map(|(s, n)| s.map(|v| v / n as f64))
        .collect()
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

    fn nominals(l: &Levels) -> Vec<f64> {
        l.levels.iter().map(|q| q.nominal).collect()
    }

    #[test]
    fn exact_levels_one_sample_per_slip_point_are_each_a_level() {
        let v: Vec<f64> = [2800.0, 5700.0, 8600.0]
            .iter()
            .flat_map(|f| std::iter::repeat_n(*f, 85))
            .collect();
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(nominals(&l), vec![2800.0, 5700.0, 8600.0]);
        assert_eq!(l.transition_samples, 0);
    }

    #[test]
    fn levels_interleaved_row_by_row_stay_apart() {
        // The papers' table flattened one slip angle at a time: every row
        // changes load, so neighbours differ by whole level steps.
        let v: Vec<f64> = (0..85).flat_map(|_| [2800.0, 5700.0, 8600.0]).collect();
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(nominals(&l), vec![2800.0, 5700.0, 8600.0]);
        assert_eq!(l.noise, 0.0);
    }

    #[test]
    fn close_noisy_levels_stay_apart_and_a_small_one_is_kept() {
        // Bicycle-tyre loads 50 N apart, ±3 N noise, and a fourth level with
        // 0.5 % of the samples.
        let mut rng = 1u64;
        let mut noise = || {
            rng = rng
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((rng >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 6.0
        };
        let mut v = Vec::new();
        for (f, n) in [(340.0, 1000), (390.0, 1000), (440.0, 1000), (490.0, 15)] {
            v.extend((0..n).map(|_| f + noise()));
        }
        let l = levels(Variable::Load, &v, 10.0);
        let got = nominals(&l);
        assert_eq!(got.len(), 4, "{got:?}");
        for (g, want) in got.iter().zip([340.0, 390.0, 440.0, 490.0]) {
            assert!((g - want).abs() < 1.0, "{got:?}");
        }
        assert_eq!(l.levels[3].samples, 15);
    }

    #[test]
    fn a_ramp_between_two_levels_is_a_transition_not_a_bridge() {
        // Two wandering levels (±150 N) joined by 40-sample ramps in
        // recording order.
        let mut v = Vec::new();
        for k in 0..3000 {
            v.push(1000.0 + 150.0 * (k as f64 * 0.01).sin());
        }
        for k in 0..40 {
            v.push(1150.0 + (2100.0 - 1150.0) * k as f64 / 40.0);
        }
        for k in 0..3000 {
            v.push(2200.0 + 150.0 * (k as f64 * 0.013).cos());
        }
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(l.levels.len(), 2, "{:?}", l.levels);
        assert!((l.levels[0].nominal - 1000.0).abs() < 20.0);
        assert!((l.levels[1].nominal - 2200.0).abs() < 20.0);
        assert!(l.transition_samples > 0 && l.transition_samples <= 40);
        let accounted: usize =
            l.levels.iter().map(|q| q.samples).sum::<usize>() + l.transition_samples;
        assert_eq!(accounted, v.len());
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
            assert!((p[0] - (a + 0.0005)).abs() < 1e-12);
            assert!((p[4] - 1000.0 * (a + 0.0005)).abs() < 1e-9);
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
