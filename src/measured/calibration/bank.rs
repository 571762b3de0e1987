//! Whether a logged bank acts on the car: the standstills' `a_y` read
//! three ways.
//!
//! **Why.** Parked on a road banked by θ (`FORMATS.md`: positive with the
//! left edge higher), a body-fixed accelerometer reads `b_ay + g·sin θ`
//! (ISO 8855; [`super`] has the derivation). With a `bank` column the
//! calibration removes `g·sin θ` and calls the rest the offset `b_ay`. That
//! holds only if the logged bank is the road under the car. Two common log
//! faults break it: a bank channel that does not act on the car (the
//! track's survey bank for a car parked off it, the bank of a lap map
//! misaligned in time, or a flat test road with a bank channel of another
//! track), and a bank channel of the other sign (a logger whose convention
//! is the right edge higher). Each reading implies its own offset:
//!
//! | reading | the offset it implies |
//! |---|---|
//! | as logged | `mean(a_y) − mean(g·sin θ)` |
//! | the bank does not act | `mean(a_y)` |
//! | the bank's sign reversed | `mean(a_y) + mean(g·sin θ)` |
//!
//! **Rule.** An accelerometer offset beyond [`PLAUSIBLE_AY_OFFSET`] (the
//! reading of a sensor tilted 6° on its mount; the bias of automotive MEMS
//! accelerometers is 0.01–0.5 m/s², Groves 2013, Table 4.1) is not taken
//! where another reading implies a smaller one: the reading that implies
//! the smallest offset is reported, and the offset as logged is not used
//! as evidence or as a start. Below that limit the logged bank is taken as
//! logged: an offset and a bank are not told apart by one mean.
//!
//! Units: m/s².

use crate::format::fixed;
use serde::Serialize;

/// The largest accelerometer offset taken without question, m/s²: g·sin 6°.
pub const PLAUSIBLE_AY_OFFSET: f64 = 1.0;

/// How the standstills' `a_y` reads the logged bank.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BankSeen {
    /// As logged (or the offset it implies is plausible).
    AsLogged,
    /// The accelerometer does not feel the logged bank.
    NotActing,
    /// It feels the logged bank with the other sign.
    Reversed,
}

/// The standstills' `a_y` against their logged bank (pooled means).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BankCheck {
    /// Mean g·sin(bank) of the logged bank, m/s².
    pub bank_term: f64,
    /// Mean `a_y` as read (the bank not removed), m/s².
    pub read: f64,
    /// Which reading implies the smallest offset, by the rule above.
    pub seen: BankSeen,
}

impl BankCheck {
    /// Judges the standstills' mean reading `read` against the mean
    /// `bank_term` = g·sin(bank) of their logged bank.
    pub fn judge(read: f64, bank_term: f64) -> Self {
        let as_logged = read - bank_term;
        let seen = if as_logged.abs() <= PLAUSIBLE_AY_OFFSET {
            BankSeen::AsLogged
        } else {
            let readings = [
                (BankSeen::AsLogged, as_logged),
                (BankSeen::NotActing, read),
                (BankSeen::Reversed, read + bank_term),
            ];
            readings
                .into_iter()
                .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
                .map_or(BankSeen::AsLogged, |r| r.0)
        };
        Self {
            bank_term,
            read,
            seen,
        }
    }

    /// The logged bank is taken as the road under the car.
    pub fn taken(&self) -> bool {
        self.seen == BankSeen::AsLogged
    }

    /// The offset the logged bank implies, m/s².
    pub fn offset_as_logged(&self) -> f64 {
        self.read - self.bank_term
    }

    /// The terminal's words when the logged bank is not taken, to lead
    /// the channel's line (the offset it would imply follows there); None
    /// when it is taken.
    pub fn doubt(&self) -> Option<String> {
        let why = match self.seen {
            BankSeen::AsLogged => return None,
            BankSeen::NotActing => "the logged bank does not act on the car (a flat road under it, or a bank channel of another place or time)",
            BankSeen::Reversed => "the bank channel's sign is reversed (FORMATS.md: positive with the left edge higher)",
        };
        let m = |x: f64| fixed(x, 2);
        Some(format!(
            "no offset taken, not used as evidence: parked where the logged bank gives g·sin(bank) = {} m/s², the accelerometer reads {} m/s², an offset of {} m/s², beyond the {PLAUSIBLE_AY_OFFSET} m/s² a mounted sensor shows, so {why}",
            m(self.bank_term),
            m(self.read),
            m(self.offset_as_logged())
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plausible_offset_takes_the_bank_as_logged_whatever_else_fits() {
        // Offset −0.6 on a 0.2 rad bank (1.948 m/s²): as logged.
        let c = BankCheck::judge(1.948 - 0.6, 1.948);
        assert_eq!(c.seen, BankSeen::AsLogged);
        assert!((c.offset_as_logged() + 0.6).abs() < 1e-12);
        assert!(c.doubt().is_none());
        // A small bank cannot be told from an offset: as logged even
        // though "not acting" would imply a smaller offset.
        assert_eq!(BankCheck::judge(0.05, 0.3).seen, BankSeen::AsLogged);
    }

    #[test]
    fn an_accelerometer_that_does_not_feel_a_20_degree_bank_is_not_given_a_3_m_s2_offset() {
        // The null oval: parked on 20° (right edge up), ay reads ~0.
        let term = crate::constants::G * (-0.349f64).sin();
        let c = BankCheck::judge(-0.001, term);
        assert_eq!(c.seen, BankSeen::NotActing);
        let words = c.doubt().unwrap();
        assert!(words.contains("does not act on the car"), "{words}");
        assert!(words.contains("an offset of 3.35 m/s²"), "{words}");
        assert!(
            words.contains("the accelerometer reads 0.00 m/s²"),
            "{words}"
        );
        // With a real offset of −0.6 the bank still is not felt.
        assert_eq!(BankCheck::judge(-0.6, term).seen, BankSeen::NotActing);
    }

    #[test]
    fn a_standstill_offset_read_through_a_refused_bank_is_not_the_offset_given() {
        use crate::measured::calibration::{Offset, Pooled, SpanKind};
        let pooled = |mean: f64| Pooled {
            spans: 2,
            seconds: 20.0,
            samples: 2000,
            mean,
            std_error: 0.01,
            between_spans: 0.0,
            chi2: 0.5,
            dof: 1,
            consistent: true,
            least: mean,
            greatest: mean,
        };
        let term = crate::constants::G * (-0.349f64).sin();
        let refused = BankCheck::judge(0.20, term);
        let (standstill, straight) = (pooled(0.20 - term), pooled(0.21));
        // The straights' offset, not the standstills' 3.56 read with the bank.
        let o = Offset::of(Some(&standstill), Some(&straight), Some(&refused), false).unwrap();
        assert_eq!((o.from, o.mean), (SpanKind::Straight, 0.21));
        // Without straights, none.
        assert!(Offset::of(Some(&standstill), None, Some(&refused), false).is_none());
        // A bank taken as logged: the standstills'.
        let taken = BankCheck::judge(0.20 - 0.3, -0.3);
        let o = Offset::of(Some(&standstill), Some(&straight), Some(&taken), false).unwrap();
        assert_eq!(o.from, SpanKind::Standstill);
    }

    #[test]
    fn a_bank_of_the_other_sign_is_named_as_reversed() {
        let term = crate::constants::G * 0.3f64.sin();
        let c = BankCheck::judge(-term - 0.2, term);
        assert_eq!(c.seen, BankSeen::Reversed);
        assert!(c.doubt().unwrap().contains("sign is reversed"));
        // Just inside the limit it is taken as logged.
        let c = BankCheck::judge(term + PLAUSIBLE_AY_OFFSET - 1e-9, term);
        assert_eq!(c.seen, BankSeen::AsLogged);
    }
}
