//! What a Magic Formula file's vertical model carries at a deflection of
//! its whole free radius, in words: its load there where it is one, and
//! none where its stiffness terms, extrapolated that far, turn the force
//! negative (the public MF 6.1 sample's −8171197641 N at 1 MN is no load
//! any tyre carries, and was quoted as one). Units: N, m.

use crate::format::significant;

/// `8020 N at a deflection of its whole free radius (0.4004 m)`, or no
/// load there where the model's force at that deflection is not positive.
pub(super) fn at_most(most: f64, free: f64) -> String {
    match most > 0.0 && most.is_finite() {
        true => format!(
            "{} N at a deflection of its whole free radius ({} m)",
            significant(most, 4),
            significant(free, 4)
        ),
        false => format!(
            "no load at a deflection of its whole free radius ({} m), where its vertical stiffness terms, extrapolated that far, give a negative force, no tyre's",
            significant(free, 4)
        ),
    }
}
