//! A scenario's tyres that make no lateral force at the car's wheel loads
//! (a `.tir` with `PKY1 = 0`, as `identify` writes a lateral block it had
//! no data for): refused at the scenario's `tyres` key, naming the file
//! and the force, before the steady-state solver fails on it and names a
//! key the scenario does not have. Units: N, rad.

use crate::error::{InputError, NoLateralForce, ParamError};
use crate::io::tables::{check_road, static_wheel_loads, Road, TyreRefs};
use crate::io::toml_file::{param_error, TomlSource};
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::VehicleModel;

/// The largest slip angle tried, rad (15°): past the peak of any road or
/// racing tyre's curve (3–10°).
const SLIP: f64 = 15.0 * std::f64::consts::PI / 180.0;

/// Slip angles tried on each side of zero.
const POINTS: usize = 30;

/// The share of its load below which a tyre's largest lateral force counts
/// as none: a tyre on ice makes 0.05–0.1 of its load. (A `.tir` with
/// `PDY1 = 0` keeps ±0.8 % of its load from `PDY2` off its nominal load.)
const NO_FORCE: f64 = 0.02;

/// Checks `[road]`: a friction at or below zero (a road with no grip) is
/// said as not positive, not as beyond the range's top ("a speed or a
/// percentage?", which fits 150, not 0), as `equilibria`'s sweep says it.
pub(crate) fn road(src: &TomlSource, road: &Road) -> Result<(), InputError> {
    if road.friction <= 0.0 {
        let e = ParamError::positive("friction", road.friction).unwrap_err();
        return Err(param_error(src, Some("road"), e));
    }
    check_road(src, road)
}

/// Refuses the first axle whose tyres make no lateral force at its static
/// wheel load, at `tyres.front` (or `tyres.rear` where the rear names its
/// own file).
pub(crate) fn lateral_force_made(
    src: &TomlSource,
    model: &VehicleModel,
    refs: &TyreRefs,
) -> Result<(), InputError> {
    let (front_load, rear_load) = static_wheel_loads(&model.vehicle);
    let front = largest_change(&model.front, front_load);
    let rear = largest_change(&model.rear, rear_load);
    let none = |largest: f64, load: f64| largest < NO_FORCE * load;
    let one_file = refs.rear.as_ref().is_none_or(|r| *r == refs.front);
    let (key, axles, tyre, largest, load) = match (one_file, none(front, front_load)) {
        (true, true) => ("front", "front and rear", &model.front, front, front_load),
        (false, true) => ("front", "front", &model.front, front, front_load),
        _ if none(rear, rear_load) => ("rear", "rear", &model.rear, rear, rear_load),
        _ => return Ok(()),
    };
    let file = match key {
        "rear" => refs.rear.as_ref().unwrap_or(&refs.front),
        _ => &refs.front,
    };
    let reason = NoLateralForce {
        axles,
        file: file.display().to_string(),
        load,
        largest,
        slip: SLIP,
        zeros: zeros(tyre),
    };
    let e = ParamError::without_value(key, reason);
    Err(param_error(src, Some("tyres"), e))
}

/// The largest |fy(α) − fy(0)| over ±[`SLIP`] at load `fz`, N.
fn largest_change(tyre: &Tyre, fz: f64) -> f64 {
    let fy = |alpha: f64| tyre.lateral_force(&SlipState::lateral(alpha, fz));
    let at_zero = fy(0.0);
    (1..=POINTS)
        .flat_map(|k| {
            let alpha = SLIP * k as f64 / POINTS as f64;
            [alpha, -alpha]
        })
        .map(|alpha| (fy(alpha) - at_zero).abs())
        .fold(0.0, f64::max)
}

/// A `.tir`'s coefficients at zero that switch its lateral force off.
fn zeros(tyre: &Tyre) -> Vec<&'static str> {
    let Tyre::MagicFormula(t) = tyre else {
        return Vec::new();
    };
    let c = &t.coefficients;
    [
        ("PKY1", c.PKY1),
        ("PDY1", c.PDY1),
        ("LKY", c.LKY),
        ("LMUY", c.LMUY),
    ]
    .into_iter()
    .filter(|(_, v)| *v == 0.0)
    .map(|(k, _)| k)
    .collect()
}
