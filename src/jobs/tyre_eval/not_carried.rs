//! The points whose load a Magic Formula file's vertical model does not
//! carry at any loaded radius (the limit checks off), refused at their
//! cell: the load's, or the pressure's where a pressure past the file's
//! `PRESMIN`–`PRESMAX` is the cause (the load is carried at the range's
//! end). Units: N, Pa, m.

use crate::error::{Error, InputProblem};
use crate::tyre::mf::MfInput;
use std::path::Path;

/// A point whose load the vertical model does not carry: its row, what
/// the model carries, and the point's pressure where that is the cause
/// (outside the file's range, and carried at the range's end).
pub(super) type NotCarriedAt = (usize, crate::tyre::mf::vertical::NotCarried, Option<f64>);

/// The pressure of `q` where it, not the load, is why the vertical model
/// of `t` does not carry the point: outside the file's pressure range, and
/// carried at the range's nearer end.
pub(super) fn pressure_to_blame(t: &crate::tyre::mf::MagicFormula, q: &MfInput) -> Option<f64> {
    let p = q.pressure?;
    let l = &t.limits;
    let within = p
        .max(l.pressure_min.unwrap_or(p))
        .min(l.pressure_max.unwrap_or(p));
    let carried = |pressure| {
        let at = MfInput {
            pressure: Some(pressure),
            ..*q
        };
        matches!(t.loaded_radius_or_not_carried(&at), Some(Ok(_)))
    };
    (within != p && carried(within)).then_some(p)
}

/// Refuses the points whose load the vertical model does not carry, at
/// the point's row and the load's column; where the pressure is the cause
/// ([`pressure_to_blame`]), at the pressure's column.
pub(super) fn refuse_not_carried(
    points: &Path,
    file: &crate::io::Columns,
    not_carried: &[NotCarriedAt],
) -> Result<(), Error> {
    let errors = not_carried
        .iter()
        .map(|(i, n, blamed)| match blamed {
            Some(pressure) => {
                let pressure = *pressure;
                let problem = InputProblem::PressureCarriesNoLoad {
                    pressure,
                    most: n.most,
                    free: n.free,
                };
                file.error_at(points, *i, "pressure", problem)
            }
            _ => {
                let problem = InputProblem::LoadNotCarried {
                    fz: n.fz,
                    most: n.most,
                    free: n.free,
                };
                file.error_at(points, *i, "fz", problem)
            }
        })
        .collect();
    match crate::error::InputError::all_of(points, errors) {
        Some(e) => Err(e.into()),
        None => Ok(()),
    }
}
