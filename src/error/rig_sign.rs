//! A rig channel's sign at small slip (FORMATS.md, ISO 8855): which
//! channels it fixes, the least-squares slope found near zero slip, and the
//! message of a channel in another sign convention, or of `fy` and `mz`
//! both sloping the wrong way against `alpha` (a reversed `alpha`, or
//! reversed `fy` and `mz`: the slopes cannot tell which, see
//! [`Reversal`]). Slopes in N/rad, N·m/rad or N per unit slip ratio; the
//! camber thrust per unit load per rad; cambers in rad (said in degrees).

use crate::format::{plural, significant};

/// A rig channel whose sign FORMATS.md (ISO 8855) fixes at small slip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RigChannel {
    /// Lateral force, against the slip angle.
    Fy,
    /// Aligning moment, against the slip angle.
    Mz,
    /// Longitudinal force, against the slip ratio.
    Fx,
    /// The slip angle, or the two forces against it: `fy` and `mz` both
    /// slope the wrong way against `alpha`, which a reversed `alpha` and
    /// reversed `fy` and `mz` make alike; what tells them apart.
    Alpha(Reversal),
}

/// What tells a reversed `alpha` from reversed `fy` and `mz`. Both fix the
/// two slopes, but they give mirror-image tyres, `Fy'(α) = −Fy(−α)`: a
/// symmetric tyre is its own mirror, while the offsets at zero slip (ply
/// steer, conicity, camber thrust) change sign. Without a camber thrust
/// the data cannot tell which was flipped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reversal {
    /// The header positions of `fy` and `mz` (1-based).
    pub forces: [usize; 2],
    /// `fy` at zero slip as logged (the small-slip line at `alpha` = 0),
    /// N, and its standard error, N.
    pub offset: (f64, f64),
    /// The camber thrust found near zero slip, where `camber` was logged
    /// with a spread of cambers.
    pub camber: Option<CamberSlope>,
}

/// The least-squares slope of `fy/fz` against `camber` near zero slip,
/// fitted beside the slip angle (`fy/fz = a·alpha + b·camber + c`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CamberSlope {
    /// `b`, per rad of camber (a share of the load).
    pub per_load: f64,
    /// Its standard error, per rad.
    pub standard_error: f64,
    /// Samples fitted.
    pub samples: usize,
    /// The lowest and highest camber fitted, rad.
    pub range: (f64, f64),
}

/// Which columns the data show reversed, beside `fy` and `mz` both sloping
/// the wrong way against `alpha`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Flipped {
    /// Nothing here decides: the offsets change sign with the fix (by
    /// less than the noise shows, where the small-slip line finds none).
    Undecided,
    /// The camber thrust has a tyre's sign with `fy` as logged.
    Alpha,
    /// The camber thrust points away from the lean with `fy` as logged.
    Forces,
}

/// How many standard errors from zero a camber slope must lie to decide
/// (as a slope's sign must, `io/rig.rs`).
const STANDARD_ERRORS: f64 = 3.0;

impl Reversal {
    fn flipped(&self) -> Flipped {
        match self.camber {
            Some(c) if c.per_load.abs() <= STANDARD_ERRORS * c.standard_error => Flipped::Undecided,
            Some(c) if c.per_load < 0.0 => Flipped::Alpha,
            Some(_) => Flipped::Forces,
            None => Flipped::Undecided,
        }
    }
}

impl RigChannel {
    /// The column's name.
    pub fn column(self) -> &'static str {
        match self {
            RigChannel::Fy => "fy",
            RigChannel::Mz => "mz",
            RigChannel::Fx => "fx",
            RigChannel::Alpha(_) => "alpha",
        }
    }
    /// The slip column the channel is judged against.
    fn slip(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Mz | RigChannel::Alpha(_) => "alpha",
            RigChannel::Fx => "kappa",
        }
    }
    /// The slope's unit.
    fn unit(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Alpha(_) => "N/rad",
            RigChannel::Mz => "N·m/rad",
            RigChannel::Fx => "N",
        }
    }
    /// The sign FORMATS.md requires, in words.
    fn requires(self) -> &'static str {
        match self {
            RigChannel::Fy | RigChannel::Alpha(_) => "a positive slope there: a positive slip angle gives a positive lateral force (fy ≈ +C_alpha·alpha)",
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
    if let RigChannel::Alpha(r) = channel {
        let [fy, mz] = r.forces;
        let head = format!(
            "columns `alpha`, `fy` and `mz` (columns {position}, {fy} and {mz} of the header): near zero slip ({window}) both forces slope the wrong way against the slip angle: `fy`'s least-squares slope is {described}, and `mz`'s {} N·m/rad; FORMATS.md (ISO 8855) requires {}, and `mz` the sign of `fy`. Either `alpha` is reversed or `fy` and `mz` both are: each fixes both slopes",
            significant(beside.unwrap_or(f64::NAN), 4),
            channel.requires()
        );
        return head + &which_reversed(&r);
    }
    let versus = beside.map_or(String::new(), |f| {
        format!(", while that of `fy` is {} N/rad", significant(f, 4))
    });
    format!(
        "column `{column}` (column {position} of the header) has the wrong sign: near zero slip ({window}) its least-squares slope against `{slip}` is {described}{versus}; FORMATS.md (ISO 8855) requires {}. The file is likely in the SAE or another sign convention: negate the `{column}` column",
        channel.requires()
    )
}

/// The end of the reversed-slopes message: which fix the data decide, or
/// that they cannot and how the user can tell.
fn which_reversed(r: &Reversal) -> String {
    let (offset, error) = r.offset;
    // The offset to the standard error's second digit (at most 3
    // decimals: noise-free data print 0.000, not 1e-13).
    let decimals = (1.0 - error.log10().floor()).clamp(0.0, 3.0) as usize;
    let fixed = crate::format::fixed;
    let lean = "a tyre leaning with its top to the right (a positive inclination, ISO 8855) pushes to the right (−y), so `fy` falls as camber rises (12 of the 13 public .tir files: by 0.46 to 2.0 times the load per rad)";
    match (r.flipped(), r.camber) {
        (Flipped::Alpha | Flipped::Forces, Some(c)) => {
            let slope = format!(
                "`fy`/`fz`'s least-squares slope against `camber` here is {} per rad (standard error {}, from {} at cambers {}° to {}°)",
                significant(c.per_load, 3),
                significant(c.standard_error, 2),
                plural(c.samples, "sample", "samples"),
                fixed(c.range.0.to_degrees(), 1),
                fixed(c.range.1.to_degrees(), 1)
            );
            let verdict = match r.flipped() {
                Flipped::Alpha => "it falls, as a tyre's does, so `fy` is as FORMATS.md has it: negate the `alpha` column (negating `fy` and `mz` instead would turn the camber thrust away from the lean, and mirror the tyre's ply steer and conicity)",
                _ => "it rises, so `fy` is reversed, and `mz` with it: negate the `fy` and `mz` columns (negating `alpha` instead would leave the camber thrust pointing away from the lean, and the tyre's ply steer and conicity mirrored); if the rig's camber is positive leaning to the left, it is `alpha` that is reversed, and `camber` with it",
            };
            format!(", but they give mirror-image tyres, and the camber logged decides which, if `camber` is ISO 8855's inclination: {lean}; {slope}: {verdict}")
        }
        _ => format!(
            ", but they give mirror-image tyres, and these data cannot tell which: `fy` at zero slip (ply steer, conicity) is {} N if `alpha` is the one reversed and {} N if `fy` and `mz` are (standard error {} N). Which did the rig flip? FORMATS.md's positive slip angle has the wheel pointing to the left of its travel and pushed to the left (+y): negate `alpha` if the rig's positive slip angle points the wheel to the right of its travel; negate `fy` and `mz` if its lateral force is positive to the right (as SAE J670's y axis points). A camber sweep logged in a `camber` column decides it from the data: {lean}",
            fixed(offset, decimals),
            fixed(-offset, decimals),
            fixed(error, decimals)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The message of `fy` and `mz` both reversed against `alpha`, with
    /// `fy`'s offset at zero slip and the camber slope `camber`.
    fn said(offset: (f64, f64), camber: Option<(f64, f64)>) -> String {
        let r = Reversal {
            forces: [3, 4],
            offset,
            camber: camber.map(|(per_load, standard_error)| CamberSlope {
                per_load,
                standard_error,
                samples: 48,
                range: (-0.0698, 0.0698),
            }),
        };
        let slope = SmallSlipSlope {
            slope: -47195.0,
            standard_error: 1860.0,
            above: 21,
            below: 21,
            small_slip: 0.035,
            combined: false,
        };
        wrong_sign(RigChannel::Alpha(r), 2, &slope, Some(-1458.0))
    }

    #[test]
    fn reversed_slopes_name_both_fixes_and_what_decides_between_them() {
        let head = "columns `alpha`, `fy` and `mz` (columns 2, 3 and 4 of the header): near zero slip (|alpha| ≤ 0.035 rad) both forces slope the wrong way against the slip angle: `fy`'s least-squares slope is -47195 N/rad (standard error 1860 N/rad) from 42 samples (21 with alpha > 0, 21 with alpha < 0), and `mz`'s -1458 N·m/rad; FORMATS.md (ISO 8855) requires a positive slope there: a positive slip angle gives a positive lateral force (fy ≈ +C_alpha·alpha), and `mz` the sign of `fy`. Either `alpha` is reversed or `fy` and `mz` both are: each fixes both slopes";
        // An offset and no camber: undecided, both tyres said.
        let e = said((-68.4, 2.0), None);
        assert!(e.starts_with(head), "{e}");
        assert!(e.contains("these data cannot tell which: `fy` at zero slip (ply steer, conicity) is -68.4 N if `alpha` is the one reversed and 68.4 N if `fy` and `mz` are (standard error 2.0 N). Which did the rig flip?"), "{e}");
        assert!(e.contains("negate `alpha` if the rig's positive slip angle points the wheel to the right of its travel; negate `fy` and `mz` if its lateral force is positive to the right"), "{e}");
        // A camber slope lost in its noise decides nothing.
        assert_eq!(said((-68.4, 2.0), Some((0.5, 0.3))), e);
        // An offset within its noise: still both tyres, with the noise.
        let e = said((-62.0, 40.0), None);
        assert!(e.contains("is -62 N if `alpha` is the one reversed and 62 N if `fy` and `mz` are (standard error 40 N). Which did the rig flip?"), "{e}");
        // The camber thrust decides, either way.
        let e = said((-68.4, 2.0), Some((0.9, 0.01)));
        assert!(e.contains("is 0.900 per rad (standard error 0.010, from 48 samples at cambers -4.0° to 4.0°): it rises, so `fy` is reversed, and `mz` with it: negate the `fy` and `mz` columns"), "{e}");
        let e = said((68.4, 2.0), Some((-0.9, 0.01)));
        assert!(e.contains("it falls, as a tyre's does, so `fy` is as FORMATS.md has it: negate the `alpha` column"), "{e}");
        assert!(!e.contains("cannot tell"), "{e}");
    }
}
