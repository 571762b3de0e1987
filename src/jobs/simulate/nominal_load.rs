//! A `.tir` on a car whose wheels carry a load far from the file's own
//! nominal one (`FNOMIN`): a Magic Formula's coefficients describe the
//! tyre about that load (its stiffness, peak and shape are written as
//! changes from it, `dfz = (Fz − FNOMIN)/FNOMIN`), so a truck tyre's file
//! on a sedan (30 kN nominal, 3–4 kN a wheel) runs inside the file's load
//! range yet far from any load it was measured at, and the run is not that
//! car's. Said by `simulate` with the static wheel loads. Units: N.

use crate::io::Scenario;
use crate::tyre::Tyre;
use crate::vehicle::Vehicle;

/// The band of a static wheel load over the file's `FNOMIN` a tyre is
/// chosen for, and past which it is said: a road car's wheel carries
/// 0.6–1.2 of its tyre's nominal load (FNOMIN is chosen near the rated
/// service load, e.g. 4 kN for a sedan tyre at 3–4.5 kN a wheel), a racing
/// car's 0.4–1.5 with its fuel and downforce. The rule: beyond a factor of
/// two outside the road car's band, 0.3–2.4, the file belongs to another
/// class of vehicle (a 30 kN truck tyre at 3 kN: 0.1; the 1 kN FSAE tyre
/// under a sedan: 4.5 at the front, 3.0 at the rear), on either axle
/// alike. A factor of three either way (1/3–3) let the sedan's rear on the
/// FSAE tyre (2995 N, 2.995 times its FNOMIN, past its FZMAX of 2 kN)
/// pass without a word while its front at 4.5 was said (round 48).
pub(super) const NOMINAL_SHARE: (f64, f64) = (0.6 / 2.0, 1.2 * 2.0);

/// Each axle's (front, rear) static wheel load over its `.tir`'s `FNOMIN`,
/// where beyond [`NOMINAL_SHARE`]; None for an axle within it or not on a
/// Magic Formula file.
pub(crate) fn nominal_shares_of(vehicle: &Vehicle, [f, r]: [&Tyre; 2]) -> [Option<f64>; 2] {
    let (front, rear) = vehicle.static_axle_loads();
    [(f, front), (r, rear)].map(|(tyre, load)| {
        let Tyre::MagicFormula(t) = tyre else {
            return None;
        };
        let share = 0.5 * load / t.coefficients.FNOMIN;
        (!(NOMINAL_SHARE.0..=NOMINAL_SHARE.1).contains(&share)).then_some(share)
    })
}

/// What to say of each axle (front, rear) whose `.tir` has an `FNOMIN`
/// the car's static wheel loads lie beyond [`NOMINAL_SHARE`] of (`checks`
/// words it per axle, one line for both where they say the same).
pub(super) fn far_from_nominal(sc: &Scenario) -> [Option<String>; 2] {
    far_from_nominal_of(&sc.model.vehicle, [&sc.model.front, &sc.model.rear])
}

/// [`far_from_nominal`] of a vehicle on its front and rear tyres (a
/// campaign's given tyre files, which `diagnose` says the same of).
pub(crate) fn far_from_nominal_of(vehicle: &Vehicle, [f, r]: [&Tyre; 2]) -> [Option<String>; 2] {
    let (front, rear) = vehicle.static_axle_loads();
    [(f, front), (r, rear)].map(|(tyre, load)| {
        let Tyre::MagicFormula(t) = tyre else {
            return None;
        };
        let nominal = t.coefficients.FNOMIN;
        let wheel = 0.5 * load;
        let share = wheel / nominal;
        (!(NOMINAL_SHARE.0..=NOMINAL_SHARE.1).contains(&share)).then(|| {
            format!(
                "its wheels carry {} N each standing still, {} times the file's FNOMIN = {} N: a Magic Formula describes its tyre about that load, so this is a tyre for another class of vehicle (a car's wheel carries about 0.6–1.2 of its tyre's FNOMIN, and one beyond {}–{}, a factor of two outside that, is said on either axle), and the run is not this car on its own tyres",
                crate::format::significant(wheel, 4),
                crate::format::fixed(share, 2),
                crate::format::exact(nominal),
                crate::format::exact(NOMINAL_SHARE.0),
                crate::format::exact(NOMINAL_SHARE.1),
            )
        })
    })
}
