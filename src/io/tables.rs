//! The tables every model-bearing file shares — `[vehicle]`, `[tyres]`,
//! `[road]`, `[model]` — resolved in one place: values checked (errors
//! name the file, line, column and value), tyre files read relative to the
//! file that names them. Scenario, sweep and study files resolve their
//! model here; campaign files their vehicle and road.
//! Units: SI, rad.

use super::fitted_ranges::FittedRanges;
use super::paths::beside;
use super::toml_file::{param_error, TomlSource};
use crate::error::{InputError, Limit, ParamError, ParamReason};
use crate::tyre::Tyre;
use crate::vehicle::{ModelOptions, Vehicle, VehicleModel};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Paths of the tyre files.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TyreRefs {
    /// Tyre file of the front wheels.
    pub front: PathBuf,
    /// Tyre file of the rear wheels (default: the front one).
    #[serde(default)]
    pub rear: Option<PathBuf>,
    /// MFeval's `useMode` for Magic Formula (.tir) tyres (default 121).
    #[serde(default)]
    pub mode: Option<u32>,
}

/// Applies a tyre table's `mode` (MFeval's `useMode`, key `key`) to the
/// tyres read from it; the error names the key and the reason.
pub(crate) fn apply_tyre_mode(
    src: &TomlSource,
    key: &str,
    mode: Option<u32>,
    tyres: &mut [&mut Tyre],
) -> Result<(), InputError> {
    let Some(code) = mode else { return Ok(()) };
    for t in tyres {
        super::tir::set_tyre_mode(t, code).map_err(|why| {
            src.value_error(&ParamError::without_value(
                key,
                ParamReason::Mode(Box::new(why)),
            ))
        })?;
    }
    Ok(())
}

/// The road.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Road {
    /// Friction coefficient, a scale on the tyres' own friction.
    #[serde(default = "one")]
    pub friction: f64,
}

impl Default for Road {
    fn default() -> Self {
        Self { friction: 1.0 }
    }
}

fn one() -> f64 {
    1.0
}

/// Reads and validates a tyre file.
pub fn load_tyre(path: &Path) -> Result<Tyre, InputError> {
    Ok(load_tyre_with_ranges(path)?.0)
}

/// Reads and validates a tyre file, with the ranges of the data a TOML
/// tyre was fitted to where it states them (`[fitted_ranges]`; a `.tir`
/// carries its own validity ranges in the tyre).
pub fn load_tyre_with_ranges(path: &Path) -> Result<(Tyre, Option<FittedRanges>), InputError> {
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("tir"))
    {
        // A TOML tyre saved as `.tir` is named as one, not read as a
        // `.tir` that fails at its first line.
        let tir = super::tir::load_tir(path).map_err(|e| {
            super::file_kind::not_a_tir(path, crate::error::Wanted::TirContent).unwrap_or(e)
        })?;
        return Ok((Tyre::MagicFormula(Box::new(tir)), None));
    }
    let (src, ranges) = super::fitted_ranges::split(&TomlSource::read(path)?)?;
    let tyre: Tyre = src.parse()?;
    tyre.validate()
        .and_then(|()| tyre.check_sizes())
        .map_err(|e| param_error(&src, None, e))?;
    Ok((tyre, ranges))
}

/// Reads a tyre file as [`load_tyre_with_ranges`] does, for an axle whose
/// wheels each carry `wheel_load` (N) standing still: a tyre with no load
/// of its own is checked at that one ([`Tyre::check_at_load`]), the error
/// at its key in its file.
pub(crate) fn load_axle_tyre(
    path: &Path,
    wheel_load: f64,
) -> Result<(Tyre, Option<FittedRanges>), InputError> {
    let (tyre, ranges) = load_tyre_with_ranges(path)?;
    let load = (crate::tyre::sizes::STATIC_WHEEL_LOAD, wheel_load);
    check_tyre_at_load(path, &tyre, load)?;
    Ok((tyre, ranges))
}

/// Checks the tyre of file `path` at a load it is used at
/// ([`Tyre::check_at_load`]), the error at its key in its file.
pub(crate) fn check_tyre_at_load(
    path: &Path,
    tyre: &Tyre,
    load: crate::tyre::LoadNamed,
) -> Result<(), InputError> {
    match tyre.check_at_load(load) {
        Ok(()) => Ok(()),
        Err(e) => {
            let (src, _) = super::fitted_ranges::split(&TomlSource::read(path)?)?;
            Err(param_error(&src, None, e))
        }
    }
}

/// The static load on each wheel of the front and of the rear axle, N.
pub(crate) fn static_wheel_loads(vehicle: &Vehicle) -> (f64, f64) {
    let (front, rear) = vehicle.static_axle_loads();
    (0.5 * front, 0.5 * rear)
}

/// Checks a `[vehicle]` table.
pub(crate) fn check_vehicle(src: &TomlSource, vehicle: &Vehicle) -> Result<(), InputError> {
    vehicle
        .validate()
        .map_err(|e| param_error(src, Some("vehicle"), e))
}

/// The largest road friction, a scale on the tyres' own (1 = the rig's
/// surface): a road grippier than three rig surfaces is a slip of the pen.
pub(crate) const MAX_ROAD_FRICTION: f64 = 3.0;

/// Checks a `[road]` table.
pub(crate) fn check_road(src: &TomlSource, road: &Road) -> Result<(), InputError> {
    // A road with no grip is said as not positive, not as beyond the
    // range's top ("a speed or a percentage?", which fits 150, not 0): in a
    // campaign as in a scenario.
    if road.friction <= 0.0 {
        let e = ParamError::positive("friction", road.friction).unwrap_err();
        return Err(param_error(src, Some("road"), e));
    }
    ParamError::in_range(
        "friction",
        road.friction,
        0.0,
        MAX_ROAD_FRICTION,
        Limit::RoadFriction,
    )
    .map_err(|e| param_error(src, Some("road"), e))
}

/// The model of a file's `[vehicle]`, `[tyres]` and `[model]` tables, the
/// tyre files read and the ranges their tyres were fitted to.
pub(crate) struct ResolvedModel {
    /// The vehicle model.
    pub model: VehicleModel,
    /// The tyre files read (front, rear).
    pub files: [PathBuf; 2],
    /// Their `[fitted_ranges]` (front, rear; `None`: the file states none).
    pub fitted_ranges: [Option<FittedRanges>; 2],
}

/// The model of a file's `[vehicle]`, `[tyres]` and `[model]` tables
/// ([`ResolvedModel`]).
pub(crate) fn resolve_model(
    src: &TomlSource,
    vehicle: &Vehicle,
    tyres: &TyreRefs,
    options: ModelOptions,
) -> Result<ResolvedModel, InputError> {
    check_vehicle(src, vehicle)?;
    options
        .effects
        .validate()
        .map_err(|e| param_error(src, Some("model.effects"), e))?;
    let dir = src.path.parent().unwrap_or(Path::new("."));
    let front_path = beside(dir, &tyres.front);
    let rear_path = beside(dir, tyres.rear.as_ref().unwrap_or(&tyres.front));
    src.referenced_tyre("tyres.front", &front_path, false)?;
    if tyres.rear.is_some() {
        src.referenced_tyre("tyres.rear", &rear_path, false)?;
    }
    let (front_load, rear_load) = static_wheel_loads(vehicle);
    let (mut front, front_ranges) = load_axle_tyre(&front_path, front_load)?;
    let (mut rear, rear_ranges) = load_axle_tyre(&rear_path, rear_load)?;
    apply_tyre_mode(src, "tyres.mode", tyres.mode, &mut [&mut front, &mut rear])?;
    let mut model = VehicleModel::new(vehicle.clone(), front, rear);
    model.options = options;
    Ok(ResolvedModel {
        model,
        files: [front_path, rear_path],
        fitted_ranges: [front_ranges, rear_ranges],
    })
}
