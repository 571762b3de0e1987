//! The refusal of a tyre that makes no lateral force at the car's wheel
//! load ([`ParamReason::NoLateralForce`]): no turn and no steady state can
//! be simulated with it, and the steady-state solver's "did not converge"
//! named a key the scenario does not have. Units: N, rad (said in degrees).

use super::ParamReason;
use crate::format::readable;

/// What [`ParamReason::NoLateralForce`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct NoLateralForce {
    /// The axles whose tyres they are (`front`, `rear`, `front and rear`).
    pub axles: &'static str,
    /// The tyre file, as the scenario names it.
    pub file: String,
    /// The static load on each of the axle's wheels, N.
    pub load: f64,
    /// The largest change of the lateral force from its value at zero slip
    /// over the slip angles tried, N.
    pub largest: f64,
    /// The largest slip angle tried, rad.
    pub slip: f64,
    /// The file's coefficients at zero that switch the lateral force off
    /// (a `.tir`'s `PKY1`, `PDY1`, `LKY`, `LMUY`), by name.
    pub zeros: Vec<&'static str>,
}

impl From<NoLateralForce> for ParamReason {
    fn from(n: NoLateralForce) -> Self {
        ParamReason::NoLateralForce(Box::new(n))
    }
}

/// The message of [`ParamReason::NoLateralForce`].
pub(super) fn no_lateral_force(n: &NoLateralForce) -> String {
    let head = format!(
        "the {} tyres ({}) make no usable lateral force: at the static wheel load of {} N their fy changes by {} N ({} of the load) over slip angles of ±{}°, where any tyre's peak is at least 0.05 of its load (on ice), so no turn and no steady state can be simulated",
        n.axles,
        n.file,
        readable(n.load, 4),
        readable(n.largest, 3),
        readable(n.largest / n.load, 2),
        readable(n.slip.to_degrees(), 3),
    );
    match n.zeros.as_slice() {
        [] => format!(
            "{head}: check the file's lateral coefficients (`handling tyre-eval` draws its curve)"
        ),
        z => format!(
            "{head}: the file's {} switches it off{}: give the tyre's lateral coefficients",
            z.iter()
                .map(|k| format!("{k} = 0"))
                .collect::<Vec<_>>()
                .join(" and "),
            match z.contains(&"PKY1") {
                true => " (as `identify` writes a lateral block it had no lateral data for)",
                false => "",
            }
        ),
    }
}
