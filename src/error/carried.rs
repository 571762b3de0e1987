//! What a Magic Formula file's vertical model carries at a deflection of
//! its whole free radius, in words: its load there where it is one, and
//! none where its stiffness terms, extrapolated that far, turn the force
//! negative (the public MF 6.1 sample's −8171197641 N at 1 MN is no load
//! any tyre carries, and was quoted as one). Units: N, m.

use crate::format::significant;

/// `8020 N at a deflection of its whole free radius (0.4004 m)`, or no
/// load there where the model's force at that deflection is not positive;
/// where the effective rolling radius is the cause (`blown_rl`, the `rl`
/// MFeval's closed form gives), that.
pub(super) fn at_most(most: f64, free: f64, blown_rl: Option<f64>) -> String {
    if let Some(rl) = blown_rl {
        // The limit checks hold the load at FZMAX for the forces and the
        // vertical model, but MFeval takes the effective rolling radius Re
        // at the load given: past where it falls through 0, the wheel
        // speed Vx/Re and the free radius that grows with it blow up.
        return format!(
            "its effective rolling radius Re, which MFeval takes at the load given in every mode (past FZMAX too), falls through 0 there, and the wheel speed Vx/Re and the free radius with it blow up (rl {} m against a free radius of {} m at the point's speed)",
            significant(rl, 4),
            significant(free, 4)
        );
    }
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

/// What the limit checks do of a load not carried: hold it at `FZMAX`
/// (mode 1xx), except where the effective rolling radius is the cause
/// (`blown_rl`), refused in every mode.
pub(super) fn held(blown_rl: Option<f64>) -> &'static str {
    match blown_rl {
        Some(_) => " (refused in every mode, the limit checks on or off)",
        None => " (the limit checks, mode 1xx, hold the load at the file's FZMAX)",
    }
}
