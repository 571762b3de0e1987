//! A `[model.effects]` key that holds one number per axle (front, rear):
//! read as exactly two. serde's fixed-size array takes the first two of a
//! longer array and drops the rest, so `aero_load = [0.5, 0.6, 0.7]` ran
//! as `[0.5, 0.6]` and a decimal comma, `[0,5, 0,6]`, as `[0, 5]`: a
//! length other than two is refused at the key, with the count expected.

use serde::de::{Deserialize, Deserializer, Error, Expected};
use std::fmt;

/// What a per-axle key expects, said for a length of `found`.
struct TwoNumbers {
    found: usize,
}

impl Expected for TwoNumbers {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "an array of length 2 (front, rear)")?;
        if self.found > 2 {
            // The likeliest way to write more than two: decimals with a
            // comma, each one read as two numbers.
            write!(
                f,
                "; decimals take a point: [0,5, 0,6] is four numbers, [0.5, 0.6] two"
            )?;
        }
        Ok(())
    }
}

/// The front and rear values of a per-axle key: an array of exactly two.
pub(crate) fn front_rear<'de, D, T>(d: D) -> Result<[T; 2], D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    let values = Vec::<T>::deserialize(d)?;
    let found = values.len();
    <[T; 2]>::try_from(values).map_err(|_| D::Error::invalid_length(found, &TwoNumbers { found }))
}
