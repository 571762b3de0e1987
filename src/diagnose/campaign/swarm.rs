//! The swarm size of a campaign's `[diagnose] particles` and `iterations`
//! read and checked in one statement of their range, at the key: a whole
//! number from 1 to [`MAX_SWARM`]. A fresh-eyes tester read "expected a
//! whole number of 0 or more" for −3, then "must be greater than 0" for 0,
//! and saw 10⁹ taken without a word (a swarm that size never ends: every
//! particle of every iteration is one replay of all the runs).

use serde::de::{self, Deserializer, Unexpected, Visitor};
use std::fmt;

/// The largest swarm size and iteration count a campaign may ask: 1000 ×
/// 1000 is a million replays of every run for one fit, against 120 with
/// the defaults (10 × 12).
pub const MAX_SWARM: u64 = 1000;

/// The range statement both keys share.
struct SwarmSize;

impl Visitor<'_> for SwarmSize {
    type Value = usize;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(
            f,
            "a whole number from 1 to {MAX_SWARM} (a fit with a swarm replays every run once per particle and iteration: 10 particles × 12 iterations, the defaults, is 120 replays, {MAX_SWARM} × {MAX_SWARM} a million)"
        )
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<usize, E> {
        if (1..=MAX_SWARM).contains(&v) {
            Ok(v as usize)
        } else {
            Err(E::invalid_value(Unexpected::Unsigned(v), &self))
        }
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<usize, E> {
        match u64::try_from(v) {
            Ok(v) => self.visit_u64(v),
            Err(_) => Err(E::invalid_value(Unexpected::Signed(v), &self)),
        }
    }
}

/// `[diagnose] particles` or `iterations`: a whole number from 1 to
/// [`MAX_SWARM`].
pub fn swarm_size<'de, D: Deserializer<'de>>(d: D) -> Result<usize, D::Error> {
    d.deserialize_u64(SwarmSize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Deserialize)]
    struct Keys {
        #[serde(deserialize_with = "swarm_size")]
        particles: usize,
    }

    fn read(v: &str) -> Result<usize, String> {
        toml::from_str::<Keys>(&format!("particles = {v}"))
            .map(|k| k.particles)
            .map_err(|e| e.message().to_string())
    }

    #[test]
    fn every_value_outside_the_range_is_refused_with_the_same_range() {
        assert_eq!(read("1"), Ok(1));
        assert_eq!(read("1000"), Ok(1000));
        for v in ["-3", "0", "1001", "1000000000", "2.5"] {
            let e = read(v).unwrap_err();
            assert!(
                e.contains("expected a whole number from 1 to 1000 (a fit with a swarm"),
                "{v}: {e}"
            );
        }
    }
}
