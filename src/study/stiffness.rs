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
use serde::Serialize;

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

/// An axle of the studied car.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StudyAxle {
    /// The front axle.
    Front,
    /// The rear axle.
    Rear,
}

/// A stiffness no tyre has, computed rather than given (the RBF network's
/// answer to a target beyond its data): the first axle whose stiffness
/// lies outside [`LEAST_LOAD_STIFFNESS`]–[`MOST_LOAD_STIFFNESS`] times its
/// tyre's static load per rad, and that ratio, 1/rad (NaN for no number).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NoTyreHas {
    /// The axle.
    pub axle: StudyAxle,
    /// Its stiffness per unit of its tyre's static load, 1/rad.
    pub per_load: f64,
}

impl NoTyreHas {
    /// "stiffer" or "softer" than any tyre (or no number).
    pub fn words(&self) -> String {
        let axle = match self.axle {
            StudyAxle::Front => "front",
            StudyAxle::Rear => "rear",
        };
        let than = format!(
            "(a tyre's cornering stiffness is {LEAST_LOAD_STIFFNESS}–{MOST_LOAD_STIFFNESS} times its static load per rad)"
        );
        match self.per_load {
            r if r > MOST_LOAD_STIFFNESS => format!(
                "stiffer than any tyre: the {axle}'s is {} times its tyre's static load per rad {than}",
                crate::format::significant(r, 4)
            ),
            r if r.is_finite() => format!(
                "softer than any tyre: the {axle}'s is {} times its tyre's static load per rad {than}",
                crate::format::significant(r, 4)
            ),
            _ => format!("no tyre's: the {axle}'s is no number"),
        }
    }
}

impl Study {
    /// Whether (k_front, k_rear), N/rad per tyre, is a stiffness no tyre
    /// has: the first axle outside the range a tyre's lies in, as the
    /// study file's values are judged ([`stiffness_problem`]).
    pub(crate) fn no_tyre_has(&self, k_front: f64, k_rear: f64) -> Option<NoTyreHas> {
        let loads = self.axle_loads();
        [
            (StudyAxle::Front, k_front, loads[0]),
            (StudyAxle::Rear, k_rear, loads[1]),
        ]
        .into_iter()
        .map(|(axle, k, at)| NoTyreHas {
            axle,
            per_load: k / at.load,
        })
        .find(|n| !(LEAST_LOAD_STIFFNESS..=MOST_LOAD_STIFFNESS).contains(&n.per_load))
    }

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
