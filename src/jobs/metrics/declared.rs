//! A run refused for a yaw rate 57× off a neutral car's for its steer
//! (r·l/(u·δ), [`crate::metrics::measured::steer_problem`]) where the user
//! declared the culprit column in degrees: a yaw rate in rad/s declared in
//! deg/s reads 57× smaller, a steer in radians declared in degrees makes
//! the yaw rate read 57× larger. The refusal then names the declaration to
//! leave out, not the `--degrees steer` a steer logged in degrees needs.

use crate::error::{InputError, InputProblem, UnitSlip};
use crate::io::AngleColumn;

/// `e`, where it is such a refusal and `degrees` declares its culprit, as
/// the refusal of that declaration; else `e` as it is.
pub(super) fn name_declaration(e: InputError, degrees: &[AngleColumn]) -> InputError {
    let InputError::Invalid { path, at, problem } = e else {
        return e;
    };
    let (median, samples, wheelbase, column) = match *problem {
        InputProblem::SteerAboveYaw {
            median,
            samples,
            assumed_wheelbase,
            ..
        } => (median, samples, assumed_wheelbase, AngleColumn::YawRate),
        InputProblem::YawAboveSteer {
            median,
            samples,
            assumed_wheelbase,
        } => (median, samples, assumed_wheelbase, AngleColumn::Steer),
        _ => return InputError::Invalid { path, at, problem },
    };
    if !degrees.contains(&column) {
        return InputError::Invalid { path, at, problem };
    }
    let declared = match column {
        AngleColumn::Steer => "`--degrees steer`",
        _ => "`--degrees yaw_rate`",
    };
    let slip = UnitSlip::DeclaredInDegrees {
        column: column.name(),
        declared,
        median,
        samples,
        wheelbase,
    };
    InputError::Invalid {
        path,
        at,
        problem: Box::new(InputProblem::UnitSlip(slip)),
    }
}
