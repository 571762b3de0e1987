//! Fixed-length coefficient arrays read from tyre files (PAC89's a, b, c,
//! UniTire's p, c). serde's own arrays say "expected fewer elements in
//! array" for one element too many; these say the length they need, as
//! they do for one too few.

use serde::de::Error;
use serde::{Deserialize, Deserializer};

/// `v` as an array of `N`, or an error naming both lengths.
fn sized<E: Error, const N: usize>(v: Vec<f64>) -> Result<[f64; N], E> {
    let n = v.len();
    v.try_into()
        .map_err(|_| E::invalid_length(n, &format!("an array of length {N}").as_str()))
}

/// An array of exactly `N` numbers (`deserialize_with`).
pub(crate) fn exactly<'de, D: Deserializer<'de>, const N: usize>(
    d: D,
) -> Result<[f64; N], D::Error> {
    sized(Vec::<f64>::deserialize(d)?)
}

/// An optional array of exactly `N` numbers (`deserialize_with`, with
/// `default` for a missing key).
pub(crate) fn exactly_optional<'de, D: Deserializer<'de>, const N: usize>(
    d: D,
) -> Result<Option<[f64; N]>, D::Error> {
    Option::<Vec<f64>>::deserialize(d)?.map(sized).transpose()
}
