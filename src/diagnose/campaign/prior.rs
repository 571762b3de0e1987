//! The prior of the axle characteristics a diagnosis identifies from the
//! runs when it has no tyre data, as a campaign states it (`[tyres] class`,
//! or explicit `cornering` and `friction` ranges): each axle's cornering
//! coefficient `k` (cornering stiffness per unit load, 1/rad) and the
//! shared peak friction `D`, log-normal, stated as 95 % ranges `[lo, hi]`:
//! centre `√(lo·hi)`, standard deviation of `ln x` equal to
//! `ln(hi/lo)/(2·1.96)`. How a fit uses it is
//! `crate::diagnose::base::prior`'s.
//!
//! The classes' ranges ([`TyreClass::ranges`]) are of *axle* coefficients
//! of a single-track model, which are lower and wider than a tyre's own
//! (steering and suspension compliance, load transfer and the carcass's
//! relaxation all soften an axle): tyre coefficients of road tyres at their
//! nominal load run from about 10 to 24 1/rad, slicks from about 20 to 45,
//! truck tyres 5 to 8 (Pacejka 2012, ch. 1 and 4; Milliken & Milliken 1995,
//! ch. 2; Wong 2008, ch. 1; the public `.tir` files of the shared data,
//! whose own coefficients a CLI test checks against these ranges). Peak
//! friction on dry asphalt: road tyres 0.8–1.05, racing slicks 1.2–1.8
//! (downforce counted on the static load), truck tyres 0.6–0.85 (same
//! sources). Units: k in 1/rad, D dimensionless.

use serde::Serialize;

/// The normal quantile of a two-sided 95 % range.
pub const Z95: f64 = 1.959_964;

/// A class of tyres with its published ranges of axle characteristics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TyreClass {
    /// Passenger-car and light-truck road tyres (the default).
    Road,
    /// Racing slicks, downforce counted on the static load.
    RacingSlick,
    /// Heavy-truck tyres.
    Truck,
}

impl TyreClass {
    /// Every class.
    pub const ALL: [TyreClass; 3] = [TyreClass::Road, TyreClass::RacingSlick, TyreClass::Truck];

    /// Its name in campaign files and reports.
    pub fn name(self) -> &'static str {
        match self {
            TyreClass::Road => "road",
            TyreClass::RacingSlick => "racing_slick",
            TyreClass::Truck => "truck",
        }
    }

    /// 95 % ranges of the axle cornering coefficient (1/rad) and of the
    /// peak friction (module doc).
    pub fn ranges(self) -> ([f64; 2], [f64; 2]) {
        match self {
            TyreClass::Road => ([8.0, 35.0], [0.8, 1.05]),
            TyreClass::RacingSlick => ([12.0, 50.0], [1.2, 1.8]),
            TyreClass::Truck => ([4.0, 10.0], [0.6, 0.85]),
        }
    }
}

/// The prior of the axle characteristics: 95 % ranges of the cornering
/// coefficient (both axles) and of the peak friction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AxlePrior {
    /// The tyre class whose ranges are used where none is stated.
    pub class: TyreClass,
    /// Which ranges the campaign stated (cornering, friction) in place of
    /// the class's.
    pub stated: [bool; 2],
    /// Cornering coefficient, 1/rad: `[lo, hi]`.
    pub cornering: [f64; 2],
    /// Peak friction: `[lo, hi]`.
    pub friction: [f64; 2],
}

impl Default for AxlePrior {
    fn default() -> Self {
        Self::of(TyreClass::Road)
    }
}

impl AxlePrior {
    /// The prior of a tyre class.
    pub fn of(class: TyreClass) -> Self {
        let (cornering, friction) = class.ranges();
        Self {
            class,
            stated: [false; 2],
            cornering,
            friction,
        }
    }

    /// The centre (geometric mean) of a range.
    pub fn centre(range: [f64; 2]) -> f64 {
        (range[0] * range[1]).sqrt()
    }

    /// The standard deviation of `ln x` of a 95 % range.
    pub fn sigma_ln(range: [f64; 2]) -> f64 {
        (range[1] / range[0]).ln() / (2.0 * Z95)
    }

    /// How many standard deviations `x` lies from the centre of `range`,
    /// in `ln x` (within the 95 % range for `|z| ≤ 1.96`).
    pub fn z(range: [f64; 2], x: f64) -> f64 {
        (x / Self::centre(range)).ln() / Self::sigma_ln(range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_95_percent_range_is_two_standard_deviations_each_side_of_its_geometric_centre() {
        let r = [10.0, 40.0];
        assert!((AxlePrior::centre(r) - 20.0).abs() < 1e-12);
        assert!((AxlePrior::z(r, 40.0) - Z95).abs() < 1e-12);
        assert!((AxlePrior::z(r, 10.0) + Z95).abs() < 1e-12);
        assert!(AxlePrior::z(r, 20.0).abs() < 1e-12);
    }

    #[test]
    fn every_class_is_named_by_its_own_name_and_its_ranges_are_ordered() {
        for c in TyreClass::ALL {
            assert_eq!(
                TyreClass::ALL.iter().find(|k| k.name() == c.name()),
                Some(&c)
            );
            let (k, d) = c.ranges();
            assert!(0.0 < k[0] && k[0] < k[1] && 0.0 < d[0] && d[0] < d[1]);
        }
    }
}
