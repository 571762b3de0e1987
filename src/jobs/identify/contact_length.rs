//! A Gim tyre's contact length fitted to the aligning moment, judged
//! against the lengths tyres have. The fit's box reaches the reader's
//! unit-slip limit (1 m, `tyre/sizes.rs`), so a fit may write a length no
//! tyre of any size has (0.40 m on the Hoosier FSAE file, a 16x7.5-10
//! tyre, where the reader's own words give a car tyre 0.1–0.25 m): said
//! as a warning on the terminal and in the report, with what it means.
//! Not held: the length is the aligning fit's one parameter, and a value
//! held would fit nothing. Units: m.

use crate::format::{fixed, readable};
use crate::tyre::Tyre;

/// The lengths of contact patch tyres have, m: a bicycle tyre's about
/// 0.04 m, a car tyre's 0.1–0.25 m, a truck tyre's about 0.3 m (Pacejka,
/// *Tire and Vehicle Dynamics*, 2012, ch. 3: the half length `a` of a car
/// tyre at its rated load is 0.05–0.12 m).
pub(crate) const TYRE_CONTACT_LENGTHS: (f64, f64) = (0.03, 0.3);

/// The warning of a Gim tyre `t` whose contact length, fitted to the
/// aligning moment at `sigma` % (its fit's σ), lies outside
/// [`TYRE_CONTACT_LENGTHS`] (`None`: another model, or a length a tyre
/// has).
pub(crate) fn size_warning(t: &Tyre, sigma: f64) -> Option<String> {
    let Tyre::Gim(g) = t else {
        return None;
    };
    let (lo, hi) = TYRE_CONTACT_LENGTHS;
    let l = g.contact_length;
    if (lo..=hi).contains(&l) {
        return None;
    }
    let side = if l > hi { "longer" } else { "shorter" };
    Some(format!(
        "contact_length = {} m is {side} than any tyre's contact patch ({lo}–{hi} m: a bicycle tyre's about 0.04 m, a car tyre's 0.1–0.25 m, a truck tyre's about 0.3 m): it is what the aligning moment's curve asked of the gim model's, not the tyre's (σ {} %): the aligning moment data are not a gim tyre's shape, or their mz channel is weak or offset; the written file's aligning moment and pneumatic trail carry it, so do not take its length or its trail as the tyre's",
        readable(l, 4),
        fixed(sigma, 1)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_contact_length_no_tyre_has_is_warned_of_and_a_car_tyres_is_not() {
        let long = Tyre::Gim(crate::tyre::Gim::new(40_000.0, 0.4011, 1.5));
        let note = size_warning(&long, 41.1).expect("0.40 m is said");
        assert!(
            note.starts_with(
                "contact_length = 0.4011 m is longer than any tyre's contact patch (0.03–0.3 m"
            ),
            "{note}"
        );
        assert!(note.contains("(σ 41.1 %)"), "{note}");
        let car = Tyre::Gim(crate::tyre::Gim::new(40_000.0, 0.18, 1.0));
        assert!(size_warning(&car, 5.0).is_none());
        let short = Tyre::Gim(crate::tyre::Gim::new(40_000.0, 0.01, 1.0));
        let note = size_warning(&short, 5.0).expect("1 cm is said");
        assert!(note.contains("is shorter than any tyre's"), "{note}");
        let other = Tyre::Linear(crate::tyre::Linear::new(40_000.0));
        assert!(size_warning(&other, 5.0).is_none());
    }
}
