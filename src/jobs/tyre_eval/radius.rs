//! A loaded radius above the free radius at the point's speed, counted
//! and said with what drives it. A 6.1/6.2 file's free radius grows with
//! the wheel's speed, `RΩ = R0·(Q_RE0 + Q_V1·(Ω·R0/V0)²)` (Pacejka 2012,
//! eq. A3.1; Besselink et al. 2010), so `rl` at 50 m/s is above the static
//! `UNLOADED_RADIUS` on any light load: the tyre's growth, not a fault.
//! The reference is therefore `RΩ` at the point's speed as the model gives
//! it, at zero load and zero slip ratio (the wheel rolling freely: the
//! `rl` written for a point off the road at that speed); a point on the
//! road whose `rl` exceeds it has its wheel speed `Ω = (1 + κ)·Vx/Re` pushed
//! past free rolling by its slip ratio (a wheel spinning at eleven times
//! the road speed at κ = 10, whose free radius the model grows with `Ω²`),
//! or by its load: MFeval (and this evaluation, which follows it) takes the
//! effective rolling radius at the load given even past `FZMAX`, where
//! `RΩ − (Fz0/Cz)·(DREFF·atan(BREFF·Fz/Fz0) + FREFF·Fz/Fz0)` falls through
//! 0; `Vx/Re` and `RΩ` with it blow up, and `rl` jumps past the tyre's own
//! size (2.39 m on the public `fsae190_50R10.tir` at 1 MN, free radius
//! 0.233 m). Which it is is found by evaluating the point again at κ = 0,
//! then also at `FNOMIN`. Written as MFeval writes it, so that the file
//! stays comparable, and said so that no one reads it as a radius; where
//! the load is the cause, the point is refused at its row in every mode
//! ([`blown_by_load`]): MFeval's forces there are those at `FZMAX` and its
//! `rl` none (0.717 m on `car205_60R19.tir` at 999999 N, free radius
//! 0.349 m). Radii in m, loads in N.

use crate::format::{plural, readable, rounded};
use crate::tyre::mf::{MagicFormula, MfInput};
use serde::Serialize;

/// How far `rl` may pass the reference before it is said, m: a nanometre,
/// above the loaded radius's bisection (1e-13 m) and below any radius's
/// meaning. (On the fixtures and the public files, at κ = 0, every load
/// from 0.01 N to FZMAX and speeds to 299 m/s, `rl` stays below the
/// reference, the closest by 1.5e-9 m.)
const TOLERANCE: f64 = 1e-9;

/// What drives a loaded radius above the free radius at the point's speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RadiusCause {
    /// The slip ratio: at κ = 0 the point's `rl` is below the reference.
    SlipRatio,
    /// The load: at κ = 0 it is not, at `FNOMIN` and κ = 0 it is.
    Load,
    /// Neither alone: the point's speed, pressure or camber as the file's
    /// vertical model takes them.
    Other,
}

/// The points whose loaded radius exceeds the free radius at their
/// speed, for one cause.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RadiusAboveFree {
    /// What drives them.
    pub cause: RadiusCause,
    /// Points of this cause.
    pub points: usize,
    /// The file's `FNOMIN`, N, and `Q_V1`.
    pub fnomin: f64,
    /// The file's speed growth of the free radius.
    pub q_v1: f64,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its load (N), slip ratio, speed (m/s).
    pub first: [f64; 3],
    /// Its loaded radius, m.
    pub first_rl: f64,
    /// The free radius at its speed (zero load, κ = 0), m.
    pub first_free: f64,
}

/// The free radius of `t` at the speed of point `q` (its pressure and
/// camber), rolling freely: the `rl` of the point off the road at κ = 0.
fn free_at_speed(t: &MagicFormula, q: &MfInput) -> Option<f64> {
    t.loaded_radius(&MfInput {
        fz: 0.0,
        kappa: 0.0,
        ..*q
    })
}

/// Whether `rl` of `t` at point `q` is above its free radius `free`.
fn above(t: &MagicFormula, q: &MfInput, free: f64) -> bool {
    t.loaded_radius(q).is_some_and(|rl| rl > free + TOLERANCE)
}

/// What drives `rl` of point `q` above `free`: the point again at κ = 0,
/// then also at `FNOMIN`.
fn cause(t: &MagicFormula, q: &MfInput, free: f64) -> RadiusCause {
    let still = MfInput { kappa: 0.0, ..*q };
    if !above(t, &still, free) {
        return RadiusCause::SlipRatio;
    }
    let nominal = MfInput {
        fz: t.coefficients.FNOMIN,
        ..still
    };
    // The load is the cause only above the file's nominal load: there Re
    // falls through 0. A light load whose rl rounds past the free radius
    // (337.6 N on MFeval's test file) is no blown radius.
    match above(t, &nominal, free) || q.fz <= t.coefficients.FNOMIN {
        false => RadiusCause::Load,
        true => RadiusCause::Other,
    }
}

/// The points `inputs` (at file lines `lines`) on the road whose loaded
/// radius `rl` exceeds the free radius of `t` at their speed, one entry
/// per cause, in the order of their first points.
pub(super) fn above_free(
    t: &MagicFormula,
    rl: &[f64],
    inputs: &[MfInput],
    lines: &[usize],
) -> Vec<RadiusAboveFree> {
    let mut out: Vec<RadiusAboveFree> = Vec::new();
    for (i, q) in inputs.iter().enumerate() {
        // Off the road the free radius itself is written.
        if q.fz <= 0.0 || rl[i].is_nan() {
            continue;
        }
        let Some(free) = free_at_speed(t, q).filter(|f| rl[i] > f + TOLERANCE) else {
            continue;
        };
        let cause = cause(t, q, free);
        match out.iter_mut().find(|r| r.cause == cause) {
            Some(r) => r.points += 1,
            None => out.push(RadiusAboveFree {
                cause,
                points: 1,
                fnomin: t.coefficients.FNOMIN,
                q_v1: t.coefficients.Q_V1,
                first_line: lines[i],
                first: [q.fz, q.kappa, q.speed],
                first_rl: rl[i],
                first_free: free,
            }),
        }
    }
    out
}

/// The points of `inputs` whose loaded radius `rl` is above the free
/// radius at their speed for their load ([`RadiusCause::Load`]): the
/// effective rolling radius, taken at the load given, fallen through 0.
/// Refused in every mode ([`super::not_carried`]): no radius of the tyre.
pub(super) fn blown_by_load(
    t: &MagicFormula,
    rl: &[f64],
    inputs: &[MfInput],
) -> Vec<super::not_carried::BlownAt> {
    inputs
        .iter()
        .enumerate()
        .filter(|(i, q)| q.fz > 0.0 && !rl[*i].is_nan())
        .filter_map(|(i, q)| {
            let free = free_at_speed(t, q).filter(|f| rl[i] > f + TOLERANCE)?;
            (cause(t, q, free) == RadiusCause::Load).then_some((i, q.fz, rl[i], free))
        })
        .collect()
}

impl RadiusAboveFree {
    /// The warning, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let [fz, kappa, speed] = self.first;
        let why = match self.cause {
            RadiusCause::SlipRatio => format!(
                "their slip ratio spins the wheel at 1 + kappa times its free-rolling speed ({} at the first), and the file grows the free radius with the square of the wheel's speed (Q_V1 = {}): at kappa = 0 the same points' rl is below it",
                readable((1.0 + kappa).abs(), 3),
                readable(self.q_v1, 4)
            ),
            RadiusCause::Load => format!(
                "their load, far past the loads the file is made for (at FNOMIN = {} N the same points' rl is below it), where the file's effective rolling radius Re has fallen through 0 and the wheel speed Vx/Re, and the free radius with it, blow up: no radius of the tyre",
                rounded(self.fnomin, 6)
            ),
            RadiusCause::Other => "neither their slip ratio nor their load alone (at kappa = 0 and FNOMIN rl is still above it): their speed, pressure and camber as the file's vertical model takes them".to_string(),
        };
        format!(
            "{} of {} on the road with a loaded radius rl above the free radius at their speed (the rl of a wheel rolling freely off the road at that speed): {why}; written as MFeval gives it; the first at line {}, fz = {} N, kappa = {}, speed = {} m/s: rl = {} m, free radius {} m",
            self.points,
            plural(count, "point", "points"),
            self.first_line,
            readable(fz, 3),
            readable(kappa, 3),
            readable(speed, 3),
            readable(self.first_rl, 4),
            readable(self.first_free, 4)
        )
    }
}
