//! The wheels' lift-offs of a `simulate` run in words (`history.csv`
//! has each row): a wheel at zero load has lifted off, and the 2-DOF
//! model then carries its axle on one wheel. Times in s.

use crate::sim::{LiftOff, Wheel};

/// The wheels' lift-offs in words: a wheel off the ground once in one
/// line with its interval; a wheel off and back many times (a diverging
/// run on RK4 chatters on and off at each step) in one line with the
/// count, the first start and the last end, not a line per interval.
pub(super) fn lift_off_lines(lift_offs: &[LiftOff]) -> Vec<String> {
    let name = |w: Wheel| match w {
        Wheel::FrontLeft => "front left",
        Wheel::FrontRight => "front right",
        Wheel::RearLeft => "rear left",
        Wheel::RearRight => "rear right",
    };
    let wheels = [
        Wheel::FrontLeft,
        Wheel::FrontRight,
        Wheel::RearLeft,
        Wheel::RearRight,
    ];
    wheels
        .into_iter()
        .filter_map(|w| {
            let of: Vec<&LiftOff> = lift_offs.iter().filter(|l| l.wheel == w).collect();
            let (first, last) = (of.first()?, of.last()?);
            Some(match of.len() {
                1 => format!(
                    "  wheel lift-off: {} off the ground from {:.3} s to {:.3} s",
                    name(w),
                    first.start,
                    first.end
                ),
                n => format!(
                    "  wheel lift-off: {} off the ground {n} times between {:.3} s and {:.3} s (history.csv has each row)",
                    name(w),
                    first.start,
                    last.end
                ),
            })
        })
        .collect()
}
