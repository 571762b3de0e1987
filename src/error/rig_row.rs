//! A rig row no rig logs in a test. A `speed` beyond any car's or rig's
//! (the limit `metrics` holds a run's speed to, [`crate::io::MAX_SPEED`],
//! 150 m/s): a column in another unit. A speed in mm/s (11178 for the TTC
//! rig's 11.2 m/s) was read silently and written into a fitted `.tir` as
//! `LONGVL` = 11169.9 m/s (40212 km/h); the unit that brings the column's
//! median to a speed a rig runs at is named ([`RigSpeedUnit`]). And a
//! force at zero load, which was said as `inf times the load`
//! ([`above_load`]). Units: m/s, N.

use super::number::Num;
use crate::format::{plural, readable};
use thiserror::Error;

/// A unit a rig's speed column may be written in besides m/s, each with
/// the divisor that takes it to m/s. Miles per hour (the TTC rig's own
/// channels) is not told from km/h by the size of a speed: every median
/// that reads as a speed in mph does in km/h too, and the words name both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RigSpeedUnit {
    /// Kilometres per hour (or miles per hour).
    Kmh,
    /// Millimetres per second.
    MmPerS,
}

impl RigSpeedUnit {
    /// Every unit, in the order they are tried.
    pub const ALL: [RigSpeedUnit; 2] = [RigSpeedUnit::Kmh, RigSpeedUnit::MmPerS];

    /// Its name as a user writes it.
    pub fn name(self) -> &'static str {
        match self {
            RigSpeedUnit::Kmh => "km/h (or mph, ÷ 2.237)",
            RigSpeedUnit::MmPerS => "mm/s",
        }
    }

    /// The unit's value of 1 m/s (the divisor back to m/s).
    pub fn per_m_s(self) -> f64 {
        match self {
            RigSpeedUnit::Kmh => 3.6,
            RigSpeedUnit::MmPerS => 1000.0,
        }
    }

    /// The first unit in which `median` (as read) is a speed within
    /// (0, `limit`] m/s.
    pub fn of_median(median: f64, limit: f64) -> Option<Self> {
        Self::ALL.into_iter().find(|u| {
            let v = median / u.per_m_s();
            v > 0.0 && v <= limit
        })
    }
}

/// The words naming `unit` for a column of median `median`, or asking.
fn unit_words(unit: Option<RigSpeedUnit>, median: f64) -> String {
    match unit {
        Some(u) => format!(
            "is the column in {}? read so, its median is {} m/s, a rig's speed: divide it by {}",
            u.name(),
            readable(median / u.per_m_s(), 3),
            u.per_m_s()
        ),
        None => "in none of km/h, mph or mm/s is its median a rig's speed: is it another column?"
            .to_string(),
    }
}

/// A rig speed beyond [`crate::io::MAX_SPEED`], refused at its first row.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("column `speed`: {} m/s is beyond {} m/s ({} km/h), which no tyre rig or car runs at ({} of the file beyond it; the column's median is {}): `speed` is the wheel's forward speed in m/s (FORMATS.md); {}", Num(*value), Num(*limit), readable(limit * 3.6, 3), plural(*rows, "row", "rows"), Num(*median), unit_words(*unit, *median))]
pub struct RigSpeedBeyondAny {
    /// The first speed beyond the limit, as read.
    pub value: f64,
    /// The largest speed accepted, m/s.
    pub limit: f64,
    /// The rows beyond it.
    pub rows: usize,
    /// The column's median, as read.
    pub median: f64,
    /// The unit its median reads as a rig's speed in, if any.
    pub unit: Option<RigSpeedUnit>,
}

/// What a rig force `value` (N) above its load `fz` (N) is
/// ([`super::UnitSlip::RigForceAboveLoad`]): a multiple of it, or at zero
/// load no ratio (it was written `inf times the load`) but a force no
/// tyre carries off the road.
pub(super) fn above_load(value: f64, fz: f64) -> String {
    if fz == 0.0 {
        return "is a force at zero load, and a tyre carries none off the road: the wheel lifted off the rig's belt or drum (a row logged outside the test?), or is `fz` in another sign or unit?".to_string();
    }
    format!(
        "is {} times the load, which no tyre grips at (a racing slick reaches about 2): a spike of the logger, or a row in another unit?",
        Num((value / fz).abs())
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_is_the_first_that_makes_the_median_a_speed() {
        // 200 km/h read in m/s passes 150 m/s; in km/h it is 55.6 m/s.
        let kmh = RigSpeedUnit::of_median(200.0, 150.0);
        assert_eq!(kmh, Some(RigSpeedUnit::Kmh));
        // The TTC rig's 11.2 m/s in mm/s: 3105 m/s read in km/h.
        let mm = RigSpeedUnit::of_median(11178.0, 150.0);
        assert_eq!(mm, Some(RigSpeedUnit::MmPerS));
        // 540 km/h is the limit itself; past 150 km/s no unit is a speed.
        assert_eq!(RigSpeedUnit::of_median(540.0, 150.0), kmh);
        assert_eq!(RigSpeedUnit::of_median(150_001.0, 150.0), None);
    }
}
