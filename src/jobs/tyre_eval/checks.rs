//! Points `tyre-eval` evaluates but cannot stand behind, counted and said:
//!
//! - a longitudinal force of exactly 0 at a slip ratio other than 0 and a
//!   positive load: the tyre has no longitudinal force at all (a `.tir`
//!   with `PDX1 = 0` or `PKX1 = 0`, as `identify` writes from a rig file
//!   without longitudinal slip and no template). Found by behaviour, at
//!   the points themselves: no force model gives an exact 0 off zero slip
//!   otherwise. A model that does not read `kappa` at all (Gim, linear) is
//!   said so by `unread.rs` instead.
//! - a Magic Formula rolling resistance moment `my` at a speed where its
//!   speed terms `QSY3·|V/LONGVL| + QSY4·(V/LONGVL)⁴` alone exceed
//!   [`MY_SPEED_TERMS`]: a rolling resistance of a tenth of the load, where
//!   a car tyre's is about a hundredth. A `.tir` gives no speed range, and
//!   MFeval holds no speed at a limit: those terms, fitted about `LONGVL`,
//!   grow with the fourth power of the speed past it (the public
//!   `FSAE_Defaults.tir`'s `my` at 200 m/s is 400 times its value at 10
//!   m/s; its terms pass 0.1 at 78 m/s).

use super::unread::{Points, Unread};
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The size of `my`'s speed terms (a multiple of `R0·Fz`, the rolling
/// resistance coefficient) past which the speed is beyond the model.
pub const MY_SPEED_TERMS: f64 = 0.1;

/// Points with a slip ratio at which the tyre gives no longitudinal force.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NoLongitudinalForce {
    /// Points at a positive load with `kappa` ≠ 0 and `fx` = 0.
    pub points: usize,
    /// A Magic Formula file's peak factor and slip stiffness coefficients
    /// (`PDX1`, `PKX1`), which say why.
    pub pdx1_pkx1: Option<(f64, f64)>,
}

impl NoLongitudinalForce {
    /// The sentence on the terminal.
    pub fn line(&self, count: usize) -> String {
        let why = match self.pdx1_pkx1 {
            Some((d, k)) => format!(
                " (PDX1 = {}, PKX1 = {}: as `identify` writes a longitudinal block it had no data to fit)",
                crate::format::exact(d),
                crate::format::exact(k)
            ),
            None => String::new(),
        };
        format!(
            "{} of {} {} kappa ≠ 0 and fx = 0: the tyre has no longitudinal force{why}; its fx is not a prediction",
            self.points,
            crate::format::plural(count, "point", "points"),
            if self.points == 1 { "has" } else { "have" }
        )
    }
}

/// The points of `p` where `tyre`'s outputs `f` have no longitudinal
/// force at a slip ratio; `None` where there are none, or where `unread`
/// already says the model does not read `kappa`.
pub(crate) fn no_longitudinal_force(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    unread: &[Unread],
) -> Option<NoLongitudinalForce> {
    if unread.iter().any(|u| u.column == "kappa") {
        return None;
    }
    let [fz, kappa, ..] = p.columns;
    let points = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && kappa[i] != 0.0 && f[i].fx == 0.0)
        .count();
    let pdx1_pkx1 = match tyre {
        Tyre::MagicFormula(t) => Some((t.coefficients.PDX1, t.coefficients.PKX1)),
        _ => None,
    };
    (points > 0).then_some(NoLongitudinalForce { points, pdx1_pkx1 })
}

/// Points whose speed is beyond a Magic Formula file's rolling
/// resistance model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BeyondMySpeed {
    /// Points at a positive load faster than `speed`.
    pub points: usize,
    /// The speed past which `my`'s speed terms exceed [`MY_SPEED_TERMS`],
    /// m/s.
    pub speed: f64,
    /// The file's `LONGVL`, m/s.
    pub longvl: f64,
    /// The fastest point's speed, m/s, and the speed terms there.
    pub fastest: (f64, f64),
    /// The file's `QSY1` (the rolling resistance at rest).
    pub qsy1: f64,
}

impl BeyondMySpeed {
    /// The sentence on the terminal.
    pub fn line(&self, count: usize) -> String {
        let n = |v: f64| crate::format::significant(v, 3);
        format!(
            "{} of {} faster than {} m/s, where the speed terms of `my` (QSY3·|V/LONGVL| + QSY4·(V/LONGVL)⁴, fitted about LONGVL = {} m/s) give a rolling resistance above {MY_SPEED_TERMS} of the load (a car tyre's is about 0.01): a .tir has no speed range and MFeval holds no speed at a limit, so `my` there is an extrapolation (at {} m/s the terms come to {}, against QSY1 = {})",
            self.points,
            crate::format::plural(count, "point", "points"),
            n(self.speed),
            n(self.longvl),
            n(self.fastest.0),
            n(self.fastest.1),
            crate::format::exact(self.qsy1)
        )
    }
}

/// The points of `p` at which a Magic Formula `tyre`'s `my` is beyond its
/// speed terms' reach; `None` for another model, a file without speed
/// terms, or no such point.
pub(crate) fn beyond_my_speed(tyre: &Tyre, p: &Points) -> Option<BeyondMySpeed> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let c = &t.coefficients;
    let v0 = c.LONGVL;
    let terms = |v: f64| {
        let x = (v / v0).abs();
        (c.QSY3 * x + c.QSY4 * x.powi(4)).abs() * c.LMY.abs()
    };
    let [fz, _, _, _, speed] = p.columns;
    let fast: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && terms(speed[i]) > MY_SPEED_TERMS)
        .collect();
    let fastest = fast
        .iter()
        .map(|&i| speed[i].abs())
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))?;
    // The speed where the terms reach the limit: they rise with |V|, so
    // a bisection between 0 and the fastest point finds it.
    let (mut lo, mut hi) = (0.0, fastest);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if terms(mid) > MY_SPEED_TERMS {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(BeyondMySpeed {
        points: fast.len(),
        speed: hi,
        longvl: v0,
        fastest: (fastest, terms(fastest)),
        qsy1: c.QSY1,
    })
}
