//! The points whose load a Magic Formula file's vertical model does not
//! carry at any loaded radius (the limit checks off), refused at their
//! cell: the load's, or the pressure's where a pressure past the file's
//! `PRESMIN`–`PRESMAX` is the cause (the load is carried at the range's
//! end); and the points whose load pushes the tyre onto its rim
//! (`bottoming.rs`), in every mode. Units: N, Pa, m.

use crate::error::{Bottoming, Error, InputProblem, WhyNotCarried};
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

/// A point whose effective rolling radius, at the load given, has fallen
/// through 0 (`radius.rs`'s load cause): its row, load (N), the `rl`
/// MFeval's closed form gives there and the free radius at its speed (m).
pub(super) type BlownAt = (usize, f64, f64, f64);

/// A point whose load pushes the tyre onto its rim: its row, load (N)
/// and the load at which the rim meets the road (`bottoming.rs`).
pub(super) type BottomedAt = (usize, f64, Bottoming);

/// Refuses the points whose load the vertical model does not carry, at
/// the point's row and the load's column; where the pressure is the cause
/// ([`pressure_to_blame`]), at the pressure's column; the points whose
/// `rl` the load blows past the free radius (`blown`), in every mode: a
/// radius written there, 0.717 m on a tyre of 0.349 m, is no tyre's; and
/// the other points whose load pushes the tyre onto its rim (`bottomed`,
/// `bottoming.rs`), in every mode. One refusal a row, the first cause.
pub(super) fn refuse_not_carried(
    points: &Path,
    file: &crate::io::Columns,
    not_carried: &[NotCarriedAt],
    (blown, bottomed): (&[BlownAt], &[BottomedAt]),
) -> Result<(), Error> {
    let at_fz = |i: usize, fz: f64, why: WhyNotCarried| {
        let problem = InputProblem::LoadNotCarried { fz, why };
        (i, file.error_at(points, i, "fz", problem))
    };
    let mut errors: Vec<_> = not_carried
        .iter()
        .map(|(i, n, blamed)| match blamed {
            Some(pressure) => {
                let problem = InputProblem::PressureCarriesNoLoad {
                    pressure: *pressure,
                    most: n.most,
                    free: n.free,
                };
                (*i, file.error_at(points, *i, "pressure", problem))
            }
            _ => {
                let (most, free) = (n.most, n.free);
                at_fz(*i, n.fz, WhyNotCarried::AtNoRadius { most, free })
            }
        })
        .collect();
    for &(i, fz, rl, free) in blown {
        errors.push(at_fz(
            i,
            fz,
            WhyNotCarried::RollingRadiusThroughZero { rl, free },
        ));
    }
    for &(i, fz, b) in bottomed {
        if errors.iter().all(|e| e.0 != i) {
            errors.push(at_fz(i, fz, WhyNotCarried::PastBottoming(Box::new(b))));
        }
    }
    errors.sort_by_key(|e| e.0);
    let errors = errors.into_iter().map(|e| e.1).collect();
    match crate::error::InputError::all_of(points, errors) {
        Some(e) => Err(e.into()),
        None => Ok(()),
    }
}
