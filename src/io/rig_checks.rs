//! The per-sample checks of a tyre rig file ([`super::rig`]): negative
//! speeds and speeds beyond any rig's, angles in degrees, slip ratios in percent, forces and moments
//! beyond any rig's, forces above any friction, and sweeps without grip.
//! Each refusal names its cell; the checks of whole columns' units and
//! the curves' signs stay with the reader.
//!
//! Units: N, N·m, rad, m/s, as in [`super::rig`].

use super::columns::Columns;
use crate::error::{
    InputError, InputProblem, UnitSlip, MAX_RIG_FRICTION, MIN_RIG_GRIP, MIN_RIG_SLIP,
};
use std::f64::consts::FRAC_PI_2;
use std::path::Path;

/// The largest force a rig file may hold, N: 1 MN, three times an airliner
/// tyre's load; a force scaled by 1e300 is no tyre's and would leave a
/// fit of NaN.
pub const MAX_RIG_FORCE: f64 = 1e6;

/// The largest moment a rig file may hold, N·m (1 MN at 0.1 m).
pub const MAX_RIG_MOMENT: f64 = 1e5;

/// Every value of `column` beyond ±`limit`, refused at its row.
pub(super) fn check_size(
    path: &Path,
    c: &Columns,
    column: &'static str,
    values: Option<&[f64]>,
    limit: f64,
    unit: &'static str,
) -> Vec<InputError> {
    let values = values.unwrap_or_default();
    let beyond = values
        .iter()
        .enumerate()
        .filter(|(_, x)| x.is_finite() && x.abs() > limit);
    beyond
        .map(|(i, &value)| {
            let slip = crate::error::UnitSlip::RigBeyondAnyTyre {
                column,
                value,
                limit,
                unit,
            };
            c.error_at(path, i, column, slip.into())
        })
        .collect()
}

/// Every sample of force `column` above [`MAX_RIG_FRICTION`] times its
/// load (plus a twentieth of the `median` load), refused at its row; a
/// sample refused for its size or its load's sign is not said twice.
pub(super) fn check_friction(
    path: &Path,
    c: &Columns,
    column: &'static str,
    values: Option<&[f64]>,
    fz: &[f64],
    median: f64,
) -> Vec<InputError> {
    let values = values.unwrap_or_default();
    let above = values
        .iter()
        .zip(fz)
        .enumerate()
        // A negative or oversized load, or an oversized force, is refused
        // as such already.
        .filter(|(_, (f, z))| (0.0..=MAX_RIG_FORCE).contains(*z) && f.abs() <= MAX_RIG_FORCE)
        .filter(|(_, (f, z))| f.abs() > MAX_RIG_FRICTION * (*z + 0.05 * median));
    above
        .map(|(i, (&value, &fz))| {
            let slip = crate::error::UnitSlip::RigForceAboveLoad {
                column,
                value,
                fz,
                median,
            };
            c.error_at(path, i, column, slip.into())
        })
        .collect()
}

/// Refuses a sweep (`slip`, `force`) reaching [`MIN_RIG_SLIP`] whose
/// largest force is below [`MIN_RIG_GRIP`] of its load, at that row: a
/// force column in kN beside loads in N fitted to a tyre of friction 0.001
/// and was written as a good fit.
pub(super) fn check_grip(
    path: &Path,
    c: &Columns,
    column: &'static str,
    (slip, force): (&[f64], &[f64]),
    fz: &[f64],
) -> Result<(), InputError> {
    let reach = slip
        .iter()
        .filter(|s| s.is_finite())
        .fold(0.0_f64, |m, s| m.max(s.abs()));
    let share = |i: usize| (force[i] / fz[i]).abs();
    let on_road = (0..force.len()).filter(|&i| fz[i] > 0.0 && force[i].is_finite());
    let Some(i) = on_road.max_by(|&a, &b| share(a).total_cmp(&share(b))) else {
        return Ok(());
    };
    if reach < MIN_RIG_SLIP || share(i) >= MIN_RIG_GRIP {
        return Ok(());
    }
    let slip = crate::error::UnitSlip::RigForcesBelowGrip {
        column,
        value: force[i],
        fz: fz[i],
        slip: reach,
    };
    Err(c.error_at(path, i, column, slip.into()))
}

/// A sweep's slip and force columns: (`alpha`, `fy`) or (`kappa`, `fx`).
pub(super) type Sweep = (Vec<f64>, Vec<f64>);

/// The columns of a rig file, taken from its [`Columns`] before they are
/// judged.
pub(super) struct Taken {
    pub(super) fz: Vec<f64>,
    pub(super) lateral: Option<Sweep>,
    pub(super) longitudinal: Option<Sweep>,
    pub(super) camber: Option<Vec<f64>>,
    pub(super) mz: Option<Vec<f64>>,
}

impl Taken {
    pub(super) fn lateral(&self) -> Option<(&[f64], &[f64])> {
        self.lateral
            .as_ref()
            .map(|(a, f)| (a.as_slice(), f.as_slice()))
    }

    pub(super) fn longitudinal(&self) -> Option<(&[f64], &[f64])> {
        (self.longitudinal.as_ref()).map(|(k, f)| (k.as_slice(), f.as_slice()))
    }
}

/// Every negative rig speed, one refusal each.
pub(super) fn negative_speeds(path: &Path, c: &Columns) -> Vec<InputError> {
    let Some(speed) = c.get("speed") else {
        return Vec::new();
    };
    speed
        .iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite() && **v < 0.0)
        .map(|(i, &value)| c.error_at(path, i, "speed", InputProblem::NegativeSpeed { value }))
        .collect()
}

/// A rig speed beyond [`crate::io::MAX_SPEED`] (the limit `metrics` holds
/// a run's speed to), refused at its first row with the rows beyond it and
/// the unit the column's median reads as a rig's speed in: a column in
/// mm/s was read silently and written into a fitted `.tir` as `LONGVL`.
pub(super) fn speed_beyond_any(path: &Path, c: &Columns) -> Option<InputError> {
    let speed = c.get("speed")?;
    let limit = crate::io::MAX_SPEED;
    let beyond = |v: &f64| v.is_finite() && *v > limit;
    let first = speed.iter().position(beyond)?;
    let mut finite: Vec<f64> = speed.iter().copied().filter(|v| v.is_finite()).collect();
    let median = crate::measured::clean::median(&mut finite);
    let slip = crate::error::RigSpeedBeyondAny {
        value: speed[first],
        limit,
        rows: speed.iter().filter(|v| beyond(v)).count(),
        median,
        unit: crate::error::RigSpeedUnit::of_median(median, limit),
    };
    Some(c.error_at(path, first, "speed", UnitSlip::from(slip).into()))
}

/// Takes the sweeps, the camber and the aligning moment; a file with
/// neither sweep is refused here, with the `errors` found so far.
pub(super) fn take_sweeps(
    path: &Path,
    c: &mut Columns,
    fz: Vec<f64>,
    errors: &mut Vec<InputError>,
) -> Result<Taken, InputError> {
    let lateral = match (c.take_optional("alpha"), c.take_optional("fy")) {
        (Some(a), Some(f)) => Some((a, f)),
        _ => None,
    };
    let longitudinal = match (c.take_optional("kappa"), c.take_optional("fx")) {
        (Some(k), Some(f)) => Some((k, f)),
        _ => None,
    };
    if lateral.is_none() && longitudinal.is_none() {
        // With the header's slips of spelling (`Fy` for `fy`) and the bad
        // cells, in one run.
        let no_sweep = || {
            InputError::problem(
                path,
                InputProblem::NoSweep {
                    header: c.header.clone(),
                },
            )
        };
        errors.push(no_sweep());
        let errors = std::mem::take(errors);
        return Err(InputError::all_in_file_order(path, errors).unwrap_or_else(no_sweep));
    }
    Ok(Taken {
        fz,
        lateral,
        longitudinal,
        camber: c.take_optional("camber"),
        mz: c.take_optional("mz"),
    })
}

/// The samples no tyre test holds, each said at its cell: angles in
/// degrees, slip ratios in percent, forces and moments beyond any rig's.
pub(super) fn sample_errors(path: &Path, c: &Columns, t: &Taken) -> Vec<InputError> {
    let mut errors = Vec::new();
    // Angles in degrees are the commonest slip of a hand-made file: a slip
    // angle past ±90° or a camber past ±45° is not a tyre test in radians.
    let angles = [
        ("alpha", t.lateral.as_ref().map(|l| &l.0), FRAC_PI_2),
        ("camber", t.camber.as_ref(), crate::error::MOST_CAMBER),
    ];
    for (name, values, limit) in angles {
        let Some(values) = values else { continue };
        // A camber column whose every tilt is steeper than 20° asked as
        // degrees (0 and 0.5 meant as degrees), as `tyre-eval` asks it.
        let limit = match name == "camber" && super::camber_in_degrees(values) {
            true => super::STEEP_CAMBER,
            false => limit,
        };
        let beyond = values
            .iter()
            .enumerate()
            .filter(|(_, v)| v.is_finite() && v.abs() > limit);
        errors.extend(beyond.map(|(i, &value)| {
            let problem = InputProblem::AngleInDegrees {
                column: name,
                value,
                limit,
            };
            c.error_at(path, i, name, problem)
        }));
    }
    // A slip ratio in percent reads as one past a locked wheel's.
    let kappa = t.longitudinal().map(|l| l.0).unwrap_or_default();
    errors.extend(
        kappa
            .iter()
            .enumerate()
            .filter(|(_, v)| v.abs() > 1.0)
            .map(|(i, &value)| {
                c.error_at(path, i, "kappa", InputProblem::SlipRatioInPercent { value })
            }),
    );
    let sized = [
        ("fz", Some(t.fz.as_slice()), MAX_RIG_FORCE, "N"),
        ("fy", t.lateral().map(|l| l.1), MAX_RIG_FORCE, "N"),
        ("fx", t.longitudinal().map(|l| l.1), MAX_RIG_FORCE, "N"),
        ("mz", t.mz.as_deref(), MAX_RIG_MOMENT, "N·m"),
    ];
    for (column, values, limit, unit) in sized {
        errors.extend(check_size(path, c, column, values, limit, unit));
    }
    errors
}
