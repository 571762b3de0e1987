//! A rig channel's sign at small slip (FORMATS.md, ISO 8855): which
//! channels it fixes, the least-squares slope found near zero slip, and the
//! message of a channel in another sign convention, or of a slip-angle
//! column reversed (both `fy` and `mz` against it). Slopes in N/rad, N·m/rad
//! or N per unit slip ratio.

use crate::format::{plural, significant};

/// A rig channel whose sign FORMATS.md (ISO 8855) fixes at small slip.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RigChannel {
    /// Lateral force, against the slip angle.
    Fy,
    /// Aligning moment, against the slip angle.
    Mz,
    /// Longitudinal force, against the slip ratio.
    Fx,
    /// The slip angle itself: `fy` and `mz` both slope the wrong way
    /// against it, which one reversed column makes (negating `fy` and then
    /// `mz` instead mirrors the tyre's offsets about zero slip).
    Alpha,
}

impl RigChannel {
    /// The column's name.
    pub fn column(self) -> &'static str {
        match self {
            RigChannel::Fy => "fy",
            RigChannel::Mz => "mz",
            RigChannel::Fx => "fx",
            RigChannel::Alpha => "alpha",
        }
    }
    /// The slip column the channel is judged against.
    fn slip(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Mz | RigChannel::Alpha => "alpha",
            RigChannel::Fx => "kappa",
        }
    }
    /// The slope's unit.
    fn unit(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Alpha => "N/rad",
            RigChannel::Mz => "N·m/rad",
            RigChannel::Fx => "N",
        }
    }
    /// The sign FORMATS.md requires, in words.
    fn requires(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Alpha => "a positive slope there: a positive slip angle gives a positive lateral force (fy ≈ +C_alpha·alpha)",
            RigChannel::Mz => "`mz` to have the sign of `fy` at small slip (it turns the wheel back toward zero slip), so a slope of the same sign",
            RigChannel::Fx => "a positive slope there: x points forward, so a positive (driving) slip ratio gives a positive longitudinal force (fx ≈ +C_kappa·kappa)",
        }
    }
}

/// A least-squares slope of a channel against its slip near zero slip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SmallSlipSlope {
    /// The slope (N/rad, N·m/rad or N per unit slip ratio).
    pub slope: f64,
    /// Its standard error, same unit.
    pub standard_error: f64,
    /// Samples with positive slip.
    pub above: usize,
    /// Samples with negative slip.
    pub below: usize,
    /// The window: |slip| up to this (rad, or slip ratio).
    pub small_slip: f64,
    /// True when the other slip was limited to the window too (combined
    /// slip data).
    pub combined: bool,
}

/// The wrong-sign message: the slope found, the window it was fitted in,
/// what FORMATS.md requires and the likely fix (`beside`: the other
/// channel's slope, `fy`'s beside `mz`, `mz`'s beside a reversed `alpha`).
pub(super) fn wrong_sign(
    channel: RigChannel,
    position: usize,
    s: &SmallSlipSlope,
    beside: Option<f64>,
) -> String {
    let (column, slip, unit) = (channel.column(), channel.slip(), channel.unit());
    let x = s.small_slip;
    let window = match (channel, s.combined) {
        (RigChannel::Fx, true) => format!("|kappa| ≤ {x}, |alpha| ≤ {x} rad"),
        (RigChannel::Fx, false) => format!("|kappa| ≤ {x}"),
        (_, true) => format!("|alpha| ≤ {x} rad, |kappa| ≤ {x}"),
        (_, false) => format!("|alpha| ≤ {x} rad"),
    };
    let described = format!(
        "{} {unit} (standard error {} {unit}) from {} ({} with {slip} > 0, {} with {slip} < 0)",
        significant(s.slope, 4),
        significant(s.standard_error, 2),
        plural(s.above + s.below, "sample", "samples"),
        s.above,
        s.below
    );
    if channel == RigChannel::Alpha {
        return format!(
            "column `alpha` (column {position} of the header) looks reversed: near zero slip ({window}) both forces slope the wrong way against it: `fy`'s least-squares slope is {described}, and `mz`'s {} N·m/rad; FORMATS.md (ISO 8855) requires {}, and `mz` the sign of `fy`. Both channels reversed against the slip angle is the slip angle's sign: negate the `alpha` column (negating `fy` and `mz` instead fits the same slopes but mirrors the tyre's offsets about zero slip: its ply steer, conicity and camber thrust change sign)",
            significant(beside.unwrap_or(f64::NAN), 4),
            channel.requires()
        );
    }
    let versus = beside.map_or(String::new(), |f| {
        format!(", while that of `fy` is {} N/rad", significant(f, 4))
    });
    format!(
        "column `{column}` (column {position} of the header) has the wrong sign: near zero slip ({window}) its least-squares slope against `{slip}` is {described}{versus}; FORMATS.md (ISO 8855) requires {}. The file is likely in the SAE or another sign convention: negate the `{column}` column",
        channel.requires()
    )
}
