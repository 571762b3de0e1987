//! Tyres with no friction limit on a road with a friction below 1: a linear
//! tyre's force `Fy = C_α·α` ignores the road's friction (Pacejka 2012,
//! §1.3: the linear range holds only well below the limit), so an
//! equilibrium or a run on it is the same on ice as on dry asphalt. The
//! tool says so where the road's friction is stated below 1 or swept,
//! and of a run whose |ay| passes μ·g on any road, friction 1 too, rather
//! than report a lateral acceleration no such road can give.
//!
//! Units: friction dimensionless; accelerations m/s².

use crate::constants::G;
use crate::tyre::TyreModel;
use crate::vehicle::VehicleModel;

/// The peak friction coefficient of the front and rear tyres at static
/// load on a road of friction `mu` (the friction scale); infinite for a
/// tyre with no limit (linear).
pub(crate) fn static_friction(model: &VehicleModel, mu: f64) -> [f64; 2] {
    let (front, rear) = model.vehicle.static_axle_loads();
    [
        model.front.friction_coefficient(0.5 * front, mu),
        model.rear.friction_coefficient(0.5 * rear, mu),
    ]
}

/// Which axles' tyres have no friction limit, in words ("the front and
/// rear tyres"), or `None` where both have one.
pub(crate) fn unlimited_tyres(model: &VehicleModel) -> Option<&'static str> {
    let unlimited = static_friction(model, 1.0).map(|mu| mu.is_infinite());
    match unlimited {
        [true, true] => Some("the front and rear tyres are"),
        [true, false] => Some("the front tyres are"),
        [false, true] => Some("the rear tyres are"),
        [false, false] => None,
    }
}

/// The note where the road friction a job was given (one value or a
/// sweep's) is not 1 and a tyre has no friction limit: its forces are the
/// same on every road.
pub(crate) fn friction_ignored(model: &VehicleModel, frictions: &[f64]) -> Option<String> {
    let which = unlimited_tyres(model)?;
    let (lo, hi) = frictions
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &f| {
            (a.min(f), b.max(f))
        });
    if frictions.is_empty() || (lo == 1.0 && hi == 1.0) {
        return None;
    }
    let road = if lo == hi {
        format!("the road friction {lo}")
    } else {
        format!("the road friction ({lo} to {hi})")
    };
    Some(format!(
        "{which} linear (Fy = C·α), with no friction limit: {road} does not change their forces"
    ))
}

/// [`friction_ignored`] for a run, with the largest |ay| it reached
/// against the `friction`·g the road can give, where it is above it: on
/// any road, friction 1 too (a 1° step at 26.4 m/s reached 1.39 g on
/// linear tyres without a word, where a car on tyres with a limit slides
/// from about 1 g).
pub(crate) fn run_beyond_road(model: &VehicleModel, friction: f64, ay: &[f64]) -> Option<String> {
    let which = unlimited_tyres(model)?;
    let note = friction_ignored(model, &[friction]);
    let peak = ay.iter().fold(0.0_f64, |m, a| m.max(a.abs()));
    let road = friction * G;
    if peak > road {
        let note = note.unwrap_or_else(|| {
            format!("{which} linear (Fy = C·α), with no friction limit of their own")
        });
        // Just past the limit reads past it: 1.026 is not "1.0 ×".
        let ratio = peak / road;
        let times = match ratio < 1.1 {
            true => format!("{ratio:.2}"),
            false => format!("{ratio:.1}"),
        };
        return Some(format!(
            "{note}, and |ay| reaches {peak:.3} m/s² ({:.2} g), {times} × the {road:.3} m/s² (μ·g) this road can give: tyres with a limit slide before that, and the run past it is no car's",
            peak / G,
        ));
    }
    note.map(|note| format!("{note}, so the run is the same on any road"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::{Linear, Tyre};
    use crate::vehicle::Vehicle;

    fn model(front: Tyre, rear: Tyre) -> VehicleModel {
        VehicleModel::new(Vehicle::compact_sedan(), front, rear)
    }

    #[test]
    fn linear_tyres_on_a_slippery_road_are_said_to_ignore_it() {
        let lin = || Tyre::Linear(Linear::new(60_000.0));
        let m = model(lin(), lin());
        let s = friction_ignored(&m, &[0.2, 0.5, 1.0]).unwrap();
        assert!(s.starts_with("the front and rear tyres are linear"), "{s}");
        assert!(s.contains("(0.2 to 1)"), "{s}");
        // At friction 1 alone there is nothing to say.
        assert_eq!(friction_ignored(&m, &[1.0]), None);
        // 5.19 m/s² on a 0.2 road: 2.6 × μ·g.
        let s = run_beyond_road(&m, 0.2, &[0.0, -5.19, 3.0]).unwrap();
        assert!(
            s.contains("|ay| reaches 5.190 m/s² (0.53 g), 2.6 × the 1.961 m/s² (μ·g) this road can give: tyres with a limit slide"),
            "{s}"
        );
        // On a road of friction 1 a run past g is said too, one within it
        // not.
        let s = run_beyond_road(&m, 1.0, &[0.0, 13.6]).unwrap();
        assert!(
            s.starts_with("the front and rear tyres are linear (Fy = C·α), with no friction limit of their own, and |ay| reaches 13.600 m/s² (1.39 g), 1.4 × the 9.807 m/s² (μ·g)"),
            "{s}"
        );
        assert_eq!(run_beyond_road(&m, 1.0, &[0.0, 9.8]), None);
        // Just past μ·g reads past it, not "1.0 ×".
        let s = run_beyond_road(&m, 1.2, &[12.075]).unwrap();
        assert!(s.contains("(1.23 g), 1.03 × the 11.768 m/s²"), "{s}");
        // A tyre with a limit on the other axle: only the linear one named.
        let m = model(lin(), Tyre::Gim(crate::tyre::Gim::new(60_000.0, 0.2, 1.0)));
        let s = friction_ignored(&m, &[0.5]).unwrap();
        assert!(s.starts_with("the front tyres are linear"), "{s}");
        assert!(s.contains("the road friction 0.5 does not"), "{s}");
    }
}
