//! A points file's measured outputs (`fx`, `fy`, `mz` in N and N·m, `mx`,
//! `my` in N·m, as FORMATS.md's rig columns): kept in the output under
//! their own names, the model's then written as `fx_model`, `fy_model`,
//! `mz_model` (and `mx_model`, `my_model`, `rl_model`), so no measured value is
//! overwritten by a model's under its name; and each measured channel
//! compared with the model's at the points on the road (`fz > 0`): mean
//! and RMS of model − measured, the RMS relative to the measured RMS, and
//! the largest difference with its line. Without a measured column the
//! output keeps its plain names (`fx`, `fy`, …).

use serde::Serialize;

/// The output columns a points file may carry as measured, in the order
/// they are written.
pub(super) const MEASURED: [&str; 5] = ["fx", "fy", "mz", "mx", "my"];

/// The model's column `name` in a file that keeps measured columns.
pub(super) fn model_name(name: &'static str) -> &'static str {
    match name {
        "fx" => "fx_model",
        "fy" => "fy_model",
        "mz" => "mz_model",
        "mx" => "mx_model",
        "my" => "my_model",
        "rl" => "rl_model",
        other => other,
    }
}

/// A measured channel against the model's at the points on the road.
#[derive(Debug, Clone, Serialize)]
pub struct MeasuredDifference {
    /// The channel (`fy`, …).
    pub channel: &'static str,
    /// Points compared (on the road, `fz > 0`).
    pub points: usize,
    /// Mean of model − measured, N or N·m.
    pub mean: f64,
    /// RMS of model − measured, N or N·m.
    pub rms: f64,
    /// RMS of the measured values, N or N·m.
    pub measured_rms: f64,
    /// The model − measured of the largest magnitude, N or N·m.
    pub largest: f64,
    /// Its line in the points file.
    pub line: usize,
}

/// Each measured channel of `measured` against the model's column of the
/// same channel among `columns`, at the points whose load `fz` is
/// positive; `lines` are the points file's lines.
pub(super) fn differences(
    measured: &[(&'static str, Vec<f64>)],
    columns: &[(&'static str, Vec<f64>)],
    fz: &[f64],
    lines: &[usize],
) -> Vec<MeasuredDifference> {
    let on_road: Vec<usize> = (0..fz.len()).filter(|&i| fz[i] > 0.0).collect();
    measured
        .iter()
        .filter_map(|(channel, m)| {
            let model = &columns.iter().find(|(n, _)| *n == model_name(channel))?.1;
            let d: Vec<(usize, f64)> = on_road.iter().map(|&i| (i, model[i] - m[i])).collect();
            let n = d.len() as f64;
            let &(i, largest) = d.iter().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
            Some(MeasuredDifference {
                channel,
                points: d.len(),
                mean: d.iter().map(|p| p.1).sum::<f64>() / n,
                rms: (d.iter().map(|p| p.1 * p.1).sum::<f64>() / n).sqrt(),
                measured_rms: (on_road.iter().map(|&i| m[i] * m[i]).sum::<f64>() / n).sqrt(),
                largest,
                line: lines.get(i).copied().unwrap_or(0),
            })
        })
        .collect()
}

impl MeasuredDifference {
    /// "fy: model − measured over 120 points: mean 12.3 N, RMS 45.6 N
    /// (3.41 % of the measured RMS 1337 N), largest -150 N at line 57".
    pub fn line(&self) -> String {
        let unit = if self.channel.starts_with('f') {
            "N"
        } else {
            "N·m"
        };
        let n = |v: f64| crate::format::readable(v, 4);
        let share = match self.measured_rms > 0.0 {
            true => format!(
                " ({} % of the measured RMS {} {unit})",
                crate::format::readable(100.0 * self.rms / self.measured_rms, 3),
                n(self.measured_rms)
            ),
            false => String::new(),
        };
        // Equal to the last digit everywhere: no line holds a largest.
        if self.largest == 0.0 {
            return format!(
                "`{}` model − measured over {}: equal at every point (no difference)",
                self.channel,
                crate::format::plural(self.points, "point", "points"),
            );
        }
        format!(
            "`{}` model − measured over {}: mean {} {unit}, RMS {} {unit}{share}, largest {} {unit} at line {}",
            self.channel,
            crate::format::plural(self.points, "point", "points"),
            n(self.mean),
            n(self.rms),
            n(self.largest),
            self.line
        )
    }
}

/// The line saying which measured columns are kept and how the model's
/// are named, or `None` without measured columns.
pub(super) fn kept_line(
    measured: &[(&'static str, Vec<f64>)],
    columns: &[(&'static str, Vec<f64>)],
) -> Option<String> {
    if measured.is_empty() {
        return None;
    }
    let quoted = |names: Vec<&str>| -> String {
        names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let kept = quoted(measured.iter().map(|(n, _)| *n).collect());
    let model = quoted(
        columns
            .iter()
            .map(|(n, _)| *n)
            .filter(|n| n.ends_with("_model"))
            .collect(),
    );
    Some(format!(
        "the points file's measured {kept} kept under {} names; the model's outputs written as {model}",
        if measured.len() == 1 { "its" } else { "their" }
    ))
}
