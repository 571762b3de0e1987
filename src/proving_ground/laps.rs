//! The laps of the logged programmes as legs, each a duration, the speed
//! at its end, the lateral acceleration the driver asks for and the road's
//! bank: the banked oval (20° turns), the road course (banked and
//! off-camber corners, a chicane) and the slow oval of the light racing
//! car; a lap driven at another pace (the same line, speeds times the pace)
//! and a run filled or cut to a duration. Units: s, m/s, m/s² (positive
//! left), rad (positive with the road's left edge higher).

/// One leg of a lap: its duration (s), the speed at its end (m/s), the
/// lateral acceleration the driver asks for (m/s², positive left) and the
/// road's bank (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Leg {
    pub(super) duration: f64,
    pub(super) speed_end: f64,
    pub(super) ay: f64,
    pub(super) bank: f64,
}

pub(super) const fn leg(duration: f64, speed_end: f64, ay: f64, bank: f64) -> Leg {
    Leg {
        duration,
        speed_end,
        ay,
        bank,
    }
}

/// The oval's bank in the turns, rad (20°, left turns: left edge lower).
pub(super) const OVAL_BANK: f64 = -0.349_065_850_398_865_9;
/// One lap of the slow oval from 12 m/s at pace 1: 250 m turns banked 20°
/// (path acceleration u²/R), flat straights.
pub(super) fn slow_oval_lap() -> Vec<Leg> {
    let b = OVAL_BANK;
    vec![
        leg(8.0, 21.0, 0.0, 0.0),
        leg(3.0, 15.0, 0.6, b),
        leg(8.0, 15.0, 0.9, b),
        leg(3.0, 18.0, 0.5, b),
        leg(8.0, 21.0, 0.0, 0.0),
        leg(3.0, 14.0, 0.6, b),
        leg(8.0, 14.0, 0.8, b),
        leg(3.0, 12.0, 0.4, b),
    ]
}

/// `legs` filled to `duration` (s) with a straight at the last leg's
/// speed, or cut there.
pub(super) fn fill_to(mut legs: Vec<Leg>, speed: f64, duration: f64) -> Vec<Leg> {
    let mut out = Vec::new();
    let mut used = 0.0;
    for l in legs.drain(..) {
        if used + l.duration > duration {
            break;
        }
        used += l.duration;
        out.push(l);
    }
    let end = out.last().map_or(speed, |l| l.speed_end);
    if duration - used > 1e-9 {
        out.push(leg(duration - used, end, 0.0, 0.0));
    }
    out
}

/// One lap of the oval from 30 m/s on the back straight, at pace 1.
pub(super) fn oval_lap() -> Vec<Leg> {
    let b = OVAL_BANK;
    vec![
        leg(6.0, 36.0, 0.0, 0.0),
        leg(2.5, 28.0, 1.5, b),
        leg(5.0, 28.0, 4.5, b),
        leg(2.5, 32.0, 2.0, b),
        leg(5.0, 36.0, 0.0, 0.0),
        leg(2.5, 28.0, 1.5, b),
        leg(5.0, 28.0, 4.5, b),
        leg(2.5, 30.0, 2.0, b),
    ]
}

/// One lap of the road course from 30 m/s, at pace 1: T1 left (banked),
/// T2 right (off-camber), a chicane, T3 right (banked).
pub(super) fn road_course_lap() -> Vec<Leg> {
    vec![
        leg(4.0, 36.0, 0.0, 0.0),
        leg(2.5, 25.0, 1.5, -0.04),
        leg(2.0, 25.0, 5.5, -0.04),
        leg(2.5, 30.0, 2.0, 0.0),
        leg(2.0, 32.0, 0.0, 0.0),
        leg(2.5, 22.0, -1.5, -0.03),
        leg(2.5, 22.0, -5.0, -0.03),
        leg(2.5, 27.0, -2.0, 0.0),
        leg(1.5, 27.0, 3.5, 0.0),
        leg(1.5, 27.0, -3.5, 0.0),
        leg(3.0, 34.0, 0.0, 0.0),
        leg(2.5, 25.0, -1.5, 0.06),
        leg(3.0, 25.0, -5.5, 0.06),
        leg(2.5, 30.0, -2.0, 0.0),
    ]
}

/// The legs at `pace`: speeds times the pace and lateral accelerations
/// times its square (the same line driven faster), durations over it.
pub(super) fn at_pace(legs: &[Leg], pace: f64) -> Vec<Leg> {
    legs.iter()
        .map(|l| {
            leg(
                l.duration / pace,
                l.speed_end * pace,
                l.ay * pace * pace,
                l.bank,
            )
        })
        .collect()
}
