//! Whether a cornering stiffness, per tyre, is one a tyre can have: a
//! finite number above zero, between [`LEAST_LOAD_STIFFNESS`] and
//! [`MOST_LOAD_STIFFNESS`] times the tyre's static load per rad
//! ([`StiffnessSlip`]). One check for a study file's values
//! ([`crate::io::study`]) and [`Study::evaluate_in`]'s arguments: a NaN
//! there ran the base car's tyres unscaled, −500 N/deg a car with
//! negative stiffness, 20,000 N/deg (a value in N/rad) a car 254 times
//! stiffer than its load, all without a word. Units: the value in `unit`
//! (N/deg or N/rad), the load in N.

use super::{Sample, StiffnessUnit, Study};
use crate::error::{
    ParamError, ParamReason, StiffnessGiven, StiffnessSlip, LEAST_LOAD_STIFFNESS,
    MOST_LOAD_STIFFNESS,
};

/// An axle's tyre as a stiffness is judged: its name and static load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AxleLoad {
    /// `front` or `rear`.
    pub axle: &'static str,
    /// The static load of one of its tyres, N.
    pub load: f64,
}

/// Why `value` (in `unit`), given at `key` for a tyre of `at`, is no
/// tyre's cornering stiffness; `None` for one a tyre has. A load of 0 or
/// less (no car) judges finiteness and sign only.
pub(crate) fn stiffness_problem(
    key: &str,
    value: f64,
    unit: StiffnessUnit,
    at: AxleLoad,
    given: StiffnessGiven,
) -> Option<ParamReason> {
    if !value.is_finite() {
        return Some(ParamReason::NotFinite);
    }
    if value <= 0.0 {
        return Some(ParamReason::StiffnessNotPositive);
    }
    let slip = StiffnessSlip {
        key: key.into(),
        value,
        unit: unit.as_str(),
        to_si: unit.to_si(),
        axle: at.axle,
        load: at.load,
        given,
    };
    let a_tyres = (LEAST_LOAD_STIFFNESS..=MOST_LOAD_STIFFNESS).contains(&slip.per_load());
    (at.load > 0.0 && !a_tyres).then(|| ParamReason::StiffnessAgainstLoad(Box::new(slip)))
}

impl Study {
    /// Each axle's tyre with its static load (front, rear).
    fn axle_loads(&self) -> [AxleLoad; 2] {
        let (sf, sr) = self.model.vehicle.static_axle_loads();
        [("front", sf), ("rear", sr)].map(|(axle, s)| AxleLoad {
            axle,
            load: 0.5 * s,
        })
    }

    /// The (front, rear) pairs (per tyre, in `unit`) in N/rad, each value
    /// checked as a study file's are ([`stiffness_problem`]), all before
    /// any is simulated: the first refused is named by its argument
    /// (`front_n_per_deg`, with its index among several) and value.
    pub fn checked_pairs(
        &self,
        given: &[(f64, f64)],
        unit: StiffnessUnit,
    ) -> Result<Vec<(f64, f64)>, ParamError> {
        let loads = self.axle_loads();
        let several = given.len() > 1;
        let mut pairs = Vec::with_capacity(given.len());
        for (i, &(kf, kr)) in given.iter().enumerate() {
            for (value, at) in [(kf, loads[0]), (kr, loads[1])] {
                let name = crate::error::stiffness_argument(at.axle, unit.as_str());
                let key = match several {
                    true => format!("{name}[{i}]"),
                    false => name,
                };
                if let Some(why) =
                    stiffness_problem(&key, value, unit, at, StiffnessGiven::Argument)
                {
                    return Err(ParamError::new(&key, value, why));
                }
            }
            pairs.push((kf * unit.to_si(), kr * unit.to_si()));
        }
        Ok(pairs)
    }

    /// Simulates the (front, rear) pairs (per tyre, in `unit`) one after
    /// the other, each value checked first ([`Study::checked_pairs`]).
    pub fn evaluate_in(
        &self,
        pairs: &[(f64, f64)],
        unit: StiffnessUnit,
    ) -> Result<Vec<Sample>, ParamError> {
        let pairs = self.checked_pairs(pairs, unit)?;
        Ok(pairs
            .into_iter()
            .map(|(kf, kr)| self.evaluate(kf, kr))
            .collect())
    }
}
