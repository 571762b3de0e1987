//! The run of `tyre-eval` ([`run`]): the tyre file read (in MFeval's mode
//! asked for a Magic Formula tyre) and the points file read, the tyre
//! evaluated at every point, each check of the parent module made of the
//! points and their forces ([`PointChecks`]), and the output columns
//! assembled, a non-finite output refused at its point. Units: SI, rad,
//! Pa, as the points file gives them.

use super::bottoming::rim_of;
use super::columns::{self, Outputs};
use super::points::{read_points, PointColumns};
use super::{
    camber, checks, file_checks, fitted, friction, light_load, magic_formula_extras, meant,
    measured, model_loads, opposed, order, pressure, rolling, slip_ratio, standstill, stiffness,
    unfitted_lateral, unread, zero_slip, AgainstSlip, AtRest, BeyondFriction, BeyondMySpeed,
    FileChecks, LightLoad, LoadsLeft, MeasuredDifference, SignChange, StandstillMz, SteepCamber,
    TyreEvalReport, Uncoupled, ZeroOutput,
};
use crate::error::Error;
use crate::io::fitted_ranges::FittedRanges;
use crate::io::load_tyre_with_ranges;
use crate::io::tir::set_tyre_mode;
use crate::report::refuse_overwrite;
use crate::tyre::mf::TyreSide;
use crate::tyre::sizes::POINTS_MEDIAN_LOAD;
use crate::tyre::{PointForces, Tyre};
use std::path::Path;

/// Evaluates the tyre of `tyre_path` at the points of `points`, for the
/// output file `out` (never one of the inputs); `mode` is MFeval's
/// `useMode` for a Magic Formula tyre (`None`: 121).
pub fn run(
    tyre_path: &Path,
    points: &Path,
    out: &Path,
    mode: Option<u32>,
) -> Result<TyreEvalReport, Error> {
    refuse_overwrite(out, &[tyre_path.to_path_buf(), points.to_path_buf()])?;
    crate::error::OutputError::unless_a_file(out, "forces", "csv")?;
    crate::error::OutputError::unless_extension(out, "tyre-eval's forces", "csv")?;
    let (tyre, fitted_ranges) = tyre_in_mode(tyre_path, mode)?;
    let read = read_points(
        points,
        pressure::tyre_pressures(&tyre, fitted_ranges.as_ref()),
    )?;
    let p = read.pressure.clone().unwrap_or_default();
    let given = unread::Points {
        columns: [0, 1, 2, 3, 4].map(|i| &read.inputs[i].1[..]),
        pressure: &p,
    };
    let [fz, kappa, alpha, camber, speed] = given.columns;
    checked_at_points_load(tyre_path, &tyre, fz)?;
    let f = tyre.evaluate_points(fz, kappa, alpha, camber, speed, &p);
    let count = fz.len();
    let unread = unread::unread(&tyre, &given, &f);
    let lines = &read.file.lines;
    let at = (&tyre, tyre_path);
    let c = PointChecks::of(at, fitted_ranges.as_ref(), &given, (&f, &unread), lines);
    let mut extras = magic_formula_extras((&tyre, rim_of(tyre_path, &tyre)), &given, lines);
    extras.refuse(points, &read.file)?;
    let tyre_side = match &tyre {
        Tyre::MagicFormula(m) => Some(m.side),
        _ => None,
    };
    // Every model gives no force off the road: said for each, not only
    // where a loaded radius is written.
    let off_road = fz.iter().filter(|fz| **fz <= 0.0).count();
    let w = written_columns(points, &tyre, read, &f, extras.loaded_radius.take())?;
    Ok(TyreEvalReport {
        measured: w.measured,
        kept: w.kept,
        peak_friction: c.peak_friction,
        not_written: w.not_written,
        points: points.display().to_string(),
        count,
        model: tyre.model_name(),
        mode: extras.mode,
        tyre_side,
        mirrored: tyre_side == Some(TyreSide::Right),
        clamped: extras.clamped,
        below_fzmin: extras.below_fzmin,
        ranges_left: extras.ranges_left,
        loads_left: c.loads_left,
        not_meant: c.not_meant,
        radius_above_free: std::mem::take(&mut extras.radius_above_free),
        radius_past_fzmax: extras.radius_past_fzmax.take(),
        light_load: c.light_load,
        steep_camber: c.steep_camber,
        off_road,
        zero_outputs: c.zero_outputs,
        beyond_my_speed: c.beyond_my_speed,
        rolling_beyond: c.rolling_beyond,
        slip_past_lock: c.slip_past_lock,
        beyond_friction: c.beyond_friction,
        fx_at_zero_slip: c.fx_at_zero_slip,
        uncoupled: c.uncoupled,
        at_rest: c.at_rest,
        standstill_mz: c.standstill_mz,
        unread,
        longitudinal_turn: c.longitudinal_turn,
        sign_changes: c.sign_changes,
        against_slip: c.against_slip,
        opposed: c.opposed,
        fitted_ranges,
        beyond_fitted: c.beyond_fitted,
        unfitted_lateral: c.unfitted_lateral,
        columns: w.columns,
        out: out.to_path_buf(),
    })
}

/// The tyre of `tyre_path` (refused where it is a points file) with the
/// ranges it was fitted to, a Magic Formula tyre in MFeval's `mode`.
fn tyre_in_mode(
    tyre_path: &Path,
    mode: Option<u32>,
) -> Result<(Tyre, Option<FittedRanges>), Error> {
    order::refuse_points_as_tyre(tyre_path)?;
    let (mut tyre, fitted_ranges) = load_tyre_with_ranges(tyre_path)?;
    if let Some(code) = mode {
        set_tyre_mode(&mut tyre, code).map_err(|why| Error::Options(why.into()))?;
    }
    Ok((tyre, fitted_ranges))
}

/// The tyre of `tyre_path` checked at the median of the points' loads on
/// the road (`fz`): a tyre with no load of its own (linear) is checked
/// at the points'.
fn checked_at_points_load(tyre_path: &Path, tyre: &Tyre, fz: &[f64]) -> Result<(), Error> {
    let mut on_road: Vec<f64> = fz.iter().copied().filter(|f| *f > 0.0).collect();
    if !on_road.is_empty() {
        let load = (
            POINTS_MEDIAN_LOAD,
            crate::measured::clean::median(&mut on_road),
        );
        crate::io::check_tyre_at_load(tyre_path, tyre, load)?;
    }
    Ok(())
}

/// What the evaluation at the points says beside the forces: each
/// check of its own file (`stiffness.rs`, `friction.rs`, ...), made of
/// the tyre, the points and the forces there.
struct PointChecks {
    peak_friction: Option<crate::tyre::mf::PeakFriction>,
    longitudinal_turn: Option<crate::io::tir::LongitudinalTurn>,
    sign_changes: Vec<SignChange>,
    against_slip: Vec<AgainstSlip>,
    beyond_fitted: fitted::BeyondFitted,
    unfitted_lateral: Option<unfitted_lateral::UnfittedLateral>,
    zero_outputs: Vec<ZeroOutput>,
    opposed: Vec<opposed::Opposed>,
    beyond_my_speed: Option<BeyondMySpeed>,
    rolling_beyond: Option<rolling::RollingBeyond>,
    slip_past_lock: Option<slip_ratio::SlipPastLock>,
    beyond_friction: Option<BeyondFriction>,
    uncoupled: Option<Uncoupled>,
    at_rest: Option<AtRest>,
    standstill_mz: Option<StandstillMz>,
    fx_at_zero_slip: Option<zero_slip::FxAtZeroSlip>,
    light_load: Option<LightLoad>,
    loads_left: Vec<LoadsLeft>,
    not_meant: Vec<meant::NotMeant>,
    steep_camber: Option<SteepCamber>,
}

impl PointChecks {
    /// The checks of `tyre` (read from `tyre_path`; fitted to
    /// `fitted_ranges` where its file says) at the points `given` (on
    /// the points file's `lines`), with its forces `f` there and the
    /// columns it does not read (`unread`).
    fn of(
        (tyre, tyre_path): (&Tyre, &Path),
        fitted_ranges: Option<&FittedRanges>,
        given: &unread::Points,
        (f, unread): (&[PointForces], &[unread::Unread]),
        lines: &[usize],
    ) -> Self {
        let [fz, kappa, alpha, camber, _] = given.columns;
        let p = given.pressure;
        // The file's own checks, as `identify` makes them of a file it writes.
        let FileChecks {
            peak_friction,
            longitudinal_turn,
        } = file_checks::of_tyre_file(tyre_path, tyre);
        let beyond_fitted = fitted_ranges.map_or_else(Default::default, |r| {
            let r = super::reads::read_ranges(tyre, r);
            fitted::beyond(&r, [fz, kappa, alpha, camber], p, lines)
        });
        let slip_past_lock = if unread::is_unread(unread, "kappa") {
            None
        } else {
            slip_ratio::past_lock(kappa, lines)
        };
        let (beyond_friction, uncoupled) = friction::friction(tyre, given, f);
        let camber_read = !unread::is_unread(unread, "camber");
        PointChecks {
            peak_friction,
            longitudinal_turn,
            sign_changes: stiffness::sign_changes(tyre, fz),
            against_slip: stiffness::against_slip(tyre, given, lines),
            beyond_fitted,
            unfitted_lateral: unfitted_lateral::unfitted_lateral(
                fitted_ranges,
                alpha,
                camber,
                lines,
            ),
            zero_outputs: checks::zero_outputs(tyre, given, f, unread),
            opposed: opposed::opposed(tyre, fitted_ranges, given, f, lines),
            beyond_my_speed: checks::beyond_my_speed(tyre, given),
            rolling_beyond: rolling::rolling_beyond(tyre, given, f, lines),
            slip_past_lock,
            beyond_friction,
            uncoupled,
            at_rest: standstill::at_rest(tyre, given, f, lines),
            standstill_mz: standstill::standstill_mz(tyre, given, f),
            fx_at_zero_slip: zero_slip::fx_at_zero_slip(tyre, given, f, lines),
            light_load: light_load::light_load(tyre, fz, lines),
            loads_left: model_loads::loads_left((tyre, tyre_path), fitted_ranges, fz, lines),
            not_meant: meant::not_meant(tyre, fz, alpha, lines),
            steep_camber: camber::steep_camber(
                tyre,
                fitted_ranges,
                camber_read,
                [fz, camber],
                f,
                lines,
            ),
        }
    }
}

/// The output columns and what is said of them.
struct Written {
    columns: Vec<(&'static str, Vec<f64>)>,
    /// The line naming the measured columns kept.
    kept: Option<String>,
    measured: Vec<MeasuredDifference>,
    not_written: Vec<String>,
}

/// The columns written for the points `read` of `points`: the inputs,
/// the pressure, the measured outputs the file carries, and the model's
/// forces `f` (with the `loaded_radius`); each measured output against
/// the model's; a non-finite output refused at its point (the first five
/// columns are the inputs, checked when read).
fn written_columns(
    points: &Path,
    tyre: &Tyre,
    read: PointColumns,
    f: &[PointForces],
    loaded_radius: Option<Vec<f64>>,
) -> Result<Written, Error> {
    let PointColumns {
        file,
        inputs,
        pressure,
        measured,
    } = read;
    let outputs = Outputs {
        inputs,
        pressure,
        forces: f,
        loaded_radius,
        measured: measured.clone(),
    };
    let columns = columns::columns(tyre, outputs);
    let kept = measured::kept_line(&measured, &columns);
    let measured = measured::differences(&measured, &columns, &columns[0].1, &file.lines);
    columns::refuse_non_finite(points, &file, &columns, tyre.model_name())?;
    let not_written = columns::not_written(&file, &columns);
    Ok(Written {
        columns,
        kept,
        measured,
        not_written,
    })
}
