//! A rig file whose loads are in lbf beside forces in N: its forces read
//! 4.45 times larger against their loads than any tyre's. A GIM fit of
//! such a file wrote friction 3.0 (its bound) and a cornering stiffness of
//! 98 /rad per newton of load (a tyre's is 5–45); with a slick's forces it
//! was refused on `fy` ("a spike of the logger?"), not on `fz`.

use super::number::Num;
use crate::format::readable;
use thiserror::Error;

/// Newtons in a pound-force.
pub const LBF: f64 = 4.448222;

/// The largest median |force|/fz a tyre's sweep has past
/// [`LBF_SLIP`]: 2.5, above a racing slick's peak of about 2 (the Hoosier
/// rig file's median there is 1.11); a road tyre's loads in lbf read
/// 3.5–5.
pub const MAX_MEDIAN_GRIP: f64 = 2.5;

/// The slip from which a sweep's |force|/fz is judged: 4° (or a slip
/// ratio of 0.07), near a tyre's peak, where its force is most of its
/// grip.
pub const LBF_SLIP: f64 = 0.07;

/// A rig file's loads whose median |force|/fz past [`LBF_SLIP`] is above
/// [`MAX_MEDIAN_GRIP`].
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `fz`: the median |{force}|/fz of the {samples} samples past {} is {} (this row's load: {} N), where a tyre grips at most about 2 times its load (a racing slick; a road tyre 0.6–1.2; the limit is {MAX_MEDIAN_GRIP}): the loads are too small for the forces; is `fz` in lbf against `{force}` in N? multiply it by {LBF} ({} × {LBF} = {} N); loads are in N (FORMATS.md)", slip_text(force, *slip), readable(*median, 3), Num(*fz), Num(*fz), readable(fz * LBF, 5))]
pub struct RigLoadInLbf {
    /// The force column judged (`fy`, `fx`).
    pub force: &'static str,
    /// The load at the median row, as read.
    pub fz: f64,
    /// The median |force|/fz.
    pub median: f64,
    /// The samples judged.
    pub samples: usize,
    /// The slip they are past (rad, or slip ratio).
    pub slip: f64,
}

/// "|alpha| 4°" or "|kappa| 0.07".
fn slip_text(force: &str, slip: f64) -> String {
    match force {
        "fx" => format!("|kappa| {}", readable(slip, 3)),
        _ => format!("|alpha| {}°", readable(slip.to_degrees(), 3)),
    }
}
