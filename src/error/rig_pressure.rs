//! A rig file's inflation pressure above any pneumatic tyre's
//! ([`crate::constants::MOST_PRESSURE`], the limit `tyre-eval` refuses a
//! point's pressure by): a column written a thousand times too large
//! (82 160 kPa for the Hoosier file's 82.16 kPa) was fitted, pooled into
//! 46 levels and written into the tyre file's fitted ranges without a word.

use super::number::Num;
use thiserror::Error;

/// A rig file's pressure above [`crate::constants::MOST_PRESSURE`].
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `pressure`: {} Pa is above {} Pa, the largest a tyre is tested at (5 MPa, above any pneumatic tyre's inflation: a car's is 200–300 kPa, a truck's up to 1 MPa); pressures are in Pa (FORMATS.md): check the column's unit and scale", Num(*value), Num(*limit))]
pub struct RigPressureAboveAny {
    /// The pressure as read, Pa.
    pub value: f64,
    /// The limit, Pa.
    pub limit: f64,
}
