//! What runs lack for a candidate effect of the diagnosis to show in
//! them ([`Unseen`]): the typed reason a candidate is left out, said in a
//! note; and the one rule on an accelerometer's roll, which moves `ay`
//! alone (m/s², a body-fixed accelerometer reading g·sin φ of gravity at a
//! roll φ in rad).

use serde::Serialize;

/// What runs lack for a candidate effect to show in them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Unseen {
    /// A longitudinal acceleration above `threshold` (m/s²).
    LongitudinalAcceleration {
        /// m/s².
        threshold: f64,
    },
    /// A bank channel.
    BankChannel,
    /// Base tyres with a friction limit (the base model's are linear).
    FrictionLimit,
    /// An accelerometer roll not already known: every run logs its body
    /// roll, which levels `ay` before the fit.
    RollLogged,
    /// An accelerometer roll, which shows only in `ay`: no run logs it.
    NoAyChannel,
}

impl Unseen {
    /// Why an accelerometer roll cannot show in runs of which `with_ay`
    /// log `ay` and `ay_and_roll` log both `ay` and the body roll: none
    /// where no run logs `ay` (the only channel it moves), or where every
    /// one that does logs the roll that levels it; `None`: a candidate.
    /// The one rule the candidate list and the roll note read (round 41:
    /// the note called it no candidate on a log without `ay`, and it was
    /// screened and combined all the same).
    pub fn accelerometer_roll(with_ay: usize, ay_and_roll: usize) -> Option<Unseen> {
        if with_ay == 0 {
            Some(Unseen::NoAyChannel)
        } else if ay_and_roll == with_ay {
            Some(Unseen::RollLogged)
        } else {
            None
        }
    }
}

impl std::fmt::Display for Unseen {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unseen::LongitudinalAcceleration { threshold } => write!(
                f,
                "no run has a longitudinal acceleration above {threshold} m/s² (an ax channel or a changing speed)"
            ),
            Unseen::BankChannel => f.write_str("no run has a bank channel"),
            Unseen::NoAyChannel => f.write_str(
                "no run logs ay, the one channel an accelerometer's roll moves",
            ),
            Unseen::RollLogged => f.write_str(
                "every run logs its body roll, which levels ay before the fit: the accelerometer's g·sin φ is known, not fitted",
            ),
            Unseen::FrictionLimit => f.write_str(
                "the base model's tyres are linear, with no friction limit for a friction scale to lower: its fit would hold it at 1 whatever the runs show (give tyres with a limit, rig data or none, for axles identified from the runs)",
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No ay anywhere, or every ay levelled by a logged roll: no
    /// candidate; one run with ay and no roll: a candidate.
    #[test]
    fn an_accelerometer_roll_is_a_candidate_only_where_some_ay_is_not_levelled() {
        assert_eq!(Unseen::accelerometer_roll(0, 0), Some(Unseen::NoAyChannel));
        assert_eq!(Unseen::accelerometer_roll(3, 3), Some(Unseen::RollLogged));
        assert_eq!(Unseen::accelerometer_roll(3, 2), None);
        assert_eq!(Unseen::accelerometer_roll(3, 0), None);
    }
}
