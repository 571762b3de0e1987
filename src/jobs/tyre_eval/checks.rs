//! Points `tyre-eval` evaluates but cannot stand behind, counted and said:
//!
//! - a force or moment of exactly 0 at every point where a tyre that has
//!   it gives some ([`ZeroOutput`]): `fx` at a slip ratio other than 0,
//!   `fy` at a slip angle other than 0,
//!   `mx` with a lateral force or a camber, `my` at a speed other than 0,
//!   each at a positive load. The tyre has none of it at all: a `.tir`
//!   with `PDX1 = 0` or `PKX1 = 0`, or with its `QSX` or `QSY` block all 0,
//!   and `mz` at a slip angle other than 0 (a simplified Magic Formula
//!   tyre has no aligning moment, a PAC89 file without its `c` block none),
//!   as `identify` writes from rig data without longitudinal slip or
//!   wheel moments and no template. Found by behaviour, at the points
//!   themselves, one rule for the three: no force model gives an exact 0
//!   there otherwise. The Magic Formula coefficients that cause it are
//!   named; a block not all 0 that still gives none (the public
//!   `FSAE_Defaults.tir`'s `mx`: its `QSX4` term's sine is of `QSX7` and
//!   `QSX8`, both 0) is said as giving none at these points. A model that
//!   does not read `kappa` at all (Gim, linear) is said so by `unread.rs`
//!   instead.
//! - a Magic Formula rolling resistance moment `my` at a speed where its
//!   speed terms `QSY3·|V/LONGVL| + QSY4·(V/LONGVL)⁴` alone exceed
//!   [`MY_SPEED_TERMS`]: a rolling resistance of a tenth of the load, where
//!   a car tyre's is about a hundredth. A `.tir` gives no speed range, and
//!   MFeval holds no speed at a limit: those terms, fitted about `LONGVL`,
//!   grow with the fourth power of the speed past it (the public
//!   `FSAE_Defaults.tir`'s `my` at 200 m/s is 400 times its value at 10
//!   m/s; its terms pass 0.1 at 78 m/s).
//!
//! A Magic Formula `my` below [`MY_RESOLUTION`] of `R0·|Fz|` (the low-speed
//! fade's last digits at a speed of 1e-9 m/s) is written as 0.

use super::unread::{Points, Unread};
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The size of `my`'s speed terms (a multiple of `R0·Fz`, the rolling
/// resistance coefficient) past which the speed is beyond the model.
pub const MY_SPEED_TERMS: f64 = 0.1;

/// The share of `R0·|Fz|` below which a Magic Formula `my` is written as
/// 0, N·m per N·m. Every term of `my` is `R0·Fz` times a dimensionless
/// rolling resistance coefficient (`QSY1` about 0.01), and below `VXLOW`
/// the model fades it towards 0 with the speed: the MF 6.1 sample's `my`
/// at 4 kN is −2.7e-17 N·m at 1e-9 m/s, digits of the fade's arithmetic,
/// not a moment, which a reader takes for a number that means something.
/// 1e-12 is a rolling resistance coefficient ten orders of magnitude below
/// a tyre's, below anything a rig resolves and the 1e-6 of `FNOMIN·R0` the
/// moment is matched to MFeval with, and still about 4500 times the
/// round-off (`f64::EPSILON`) of a sum of terms of the size `R0·Fz`: a
/// value below it carries no digit of the tyre.
pub const MY_RESOLUTION: f64 = 1e-12;

/// The `my` of a Magic Formula `tyre` at the loads `fz`, each below
/// [`MY_RESOLUTION`] of `R0·|fz|` written as 0 (never `-0`); a non-finite
/// value is kept, for the evaluation to refuse at its point.
pub(crate) fn resolved_my(tyre: &Tyre, fz: &[f64], my: Vec<f64>) -> Vec<f64> {
    let Tyre::MagicFormula(t) = tyre else {
        return my;
    };
    let r0 = t.coefficients.UNLOADED_RADIUS.abs();
    fz.iter()
        .zip(my)
        .map(
            |(f, m)| match m.abs() < MY_RESOLUTION * r0 * f.abs() || m == 0.0 {
                true => 0.0,
                false => m,
            },
        )
        .collect()
}

/// A force or moment a tyre may have no coefficients for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Output {
    /// The longitudinal force.
    Fx,
    /// The lateral force (a Magic Formula file `identify` wrote from data
    /// with no pure lateral rows, `PDY1 = PKY1 = 0`).
    Fy,
    /// The overturning moment (Magic Formula only).
    Mx,
    /// The rolling resistance moment (Magic Formula only).
    My,
    /// The aligning moment (a simplified Magic Formula has none; a PAC89
    /// file without its `c` block none).
    Mz,
}

impl Output {
    /// Its column.
    pub fn column(self) -> &'static str {
        match self {
            Output::Fx => "fx",
            Output::Fy => "fy",
            Output::Mx => "mx",
            Output::My => "my",
            Output::Mz => "mz",
        }
    }

    /// What it is, in words.
    pub(crate) fn what(self) -> &'static str {
        match self {
            Output::Fx => "longitudinal force",
            Output::Fy => "lateral force",
            Output::Mx => "overturning moment",
            Output::My => "rolling resistance moment",
            Output::Mz => "aligning moment",
        }
    }

    /// The block of a Magic Formula file that gives it.
    pub(crate) fn block(self) -> &'static str {
        match self {
            Output::Fx => "longitudinal",
            Output::Fy => "lateral",
            Output::Mx => "overturning moment",
            Output::My => "rolling resistance",
            Output::Mz => "aligning moment",
        }
    }

    /// Where a tyre without it gives none, said of a whole tyre: every
    /// point [`Self::where_given`] names.
    pub(crate) fn anywhere(self) -> &'static str {
        match self {
            Output::Fx => "at any slip ratio",
            Output::Fy => "at any slip angle",
            Output::Mx => "at any lateral force or camber",
            Output::My => "at any speed",
            Output::Mz => "at any slip angle",
        }
    }

    /// Where a tyre that has it gives some, in words ([`Self::expected`]).
    fn where_given(self) -> &'static str {
        match self {
            Output::Fx => "kappa ≠ 0",
            Output::Fy => "alpha ≠ 0",
            Output::Mx => "fy or camber ≠ 0",
            Output::My => "speed ≠ 0",
            Output::Mz => "alpha ≠ 0",
        }
    }

    /// Whether a tyre that has it gives some at point `i` of `p`, whose
    /// lateral force is `fy`: at a positive load, with a slip ratio
    /// (`fx`), a lateral force or a camber (`mx`: without either a file
    /// may give only its offset `QSX1`, often 0), a speed (`my`, which a
    /// Magic Formula fades to 0 at standstill).
    fn expected(self, p: &Points, i: usize, fy: f64) -> bool {
        let [fz, kappa, _, camber, speed] = p.columns;
        fz[i] > 0.0
            && match self {
                Output::Fx => kappa[i] != 0.0,
                Output::Fy => p.columns[2][i] != 0.0,
                Output::Mx => fy != 0.0 || camber[i] != 0.0,
                Output::My => speed[i] != 0.0,
                Output::Mz => p.columns[2][i] != 0.0,
            }
    }

    /// Its value in `f`, where the model gives it.
    fn of(self, f: &PointForces) -> Option<f64> {
        match self {
            Output::Fx => Some(f.fx),
            Output::Fy => Some(f.fy),
            Output::Mx => f.mx,
            Output::My => f.my,
            Output::Mz => Some(f.mz),
        }
    }

    /// The Magic Formula coefficients that give it none: the peak factor
    /// and slip stiffness of `fx` (either 0 is enough), the whole `QSX`
    /// or `QSY` block of a moment.
    fn coefficients(self) -> &'static [&'static str] {
        match self {
            Output::Fx => &["PDX1", "PKX1", "LMUX", "LKX"],
            Output::Fy => &["PDY1", "PKY1", "LMUY", "LKY"],
            Output::Mx => &[
                "QSX1", "QSX2", "QSX3", "QSX4", "QSX5", "QSX6", "QSX7", "QSX8", "QSX9", "QSX10",
                "QSX11", "QSX12", "QSX13", "QSX14",
            ],
            Output::My => &[
                "QSY1", "QSY2", "QSY3", "QSY4", "QSY5", "QSY6", "QSY7", "QSY8",
            ],
            // A Magic Formula file always has its trail and residual
            // moment: no block of it gives none.
            Output::Mz => &[],
        }
    }
}

/// Points at which the tyre gives none of a force or moment, where a tyre
/// that has it gives some.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ZeroOutput {
    /// The output.
    pub output: Output,
    /// Points where it is expected ([`Output::where_given`]), all at 0.
    pub points: usize,
    /// A Magic Formula file's coefficients that say why, by name: `PDX1`
    /// and `PKX1` for `fx`, a moment's `QSX` or `QSY` block (empty for
    /// another model).
    pub coefficients: Vec<(&'static str, f64)>,
}

impl ZeroOutput {
    /// The Magic Formula coefficients that give none, in words (`PDX1 =
    /// 0, PKX1 = 0`; `QSX1 to QSX14 all 0`; `its QSX1 to QSX14 give none
    /// at these points`), and whether the block is all 0; `None` for
    /// another model.
    pub(crate) fn cause(&self) -> Option<(String, bool)> {
        let all_zero = self.coefficients.iter().all(|(_, v)| *v == 0.0);
        match self.coefficients.as_slice() {
            // A force's scale factor at 0 (`LMUY`, `LKY`) where its peak
            // and stiffness are a tyre's: the scale factor is the cause.
            [_, _, scales @ ..] if self.is_force() => {
                let (core, _) = self.coefficients.split_at(2);
                let zero: Vec<String> = scales
                    .iter()
                    .filter(|(_, v)| *v == 0.0)
                    .map(|(k, _)| format!("{k} = 0"))
                    .collect();
                match core.iter().all(|(_, v)| *v != 0.0) && !zero.is_empty() {
                    true => Some((zero.join(", "), false)),
                    false => Self {
                        coefficients: core.to_vec(),
                        ..self.clone()
                    }
                    .cause(),
                }
            }
            [(a, x), (b, y)] => Some((
                format!(
                    "{a} = {}, {b} = {}",
                    crate::format::exact(*x),
                    crate::format::exact(*y)
                ),
                all_zero,
            )),
            [(first, _), .., (last, _)] if all_zero => {
                Some((format!("{first} to {last} all 0"), true))
            }
            [(first, _), .., (last, _)] => Some((
                format!("its {first} to {last} give none at these points"),
                false,
            )),
            [] | [_] => None,
        }
    }

    /// Whether it is a force (`fx`, `fy`), whose first two coefficients
    /// are its peak and stiffness and the rest their scale factors.
    fn is_force(&self) -> bool {
        matches!(self.output, Output::Fx | Output::Fy) && self.coefficients.len() > 2
    }

    /// The sentence on the terminal.
    pub fn line(&self, count: usize) -> String {
        let o = self.output;
        let block = o.block();
        let scaled = self.cause().filter(|(c, _)| c.starts_with('L'));
        let why = match self.cause() {
            Some((cause, _)) if scaled.is_some() => format!(
                " ({cause}: the file's scale factor switches its {block} force off)"
            ),
            Some((cause, _)) if self.coefficients.len() == 2 || self.is_force() => format!(
                " ({cause}: as `identify` writes a {block} block it had no data to fit)"
            ),
            Some((cause, true)) => format!(
                " ({cause}: the file carries no {block} coefficients, as `identify` writes a block it had no data to fit)"
            ),
            Some((cause, false)) => format!(" ({cause})"),
            None => String::new(),
        };
        format!(
            "{} of {} {} {} and {} = 0: the tyre has no {}{why}; its {} is not a prediction",
            self.points,
            crate::format::plural(count, "point", "points"),
            if self.points == 1 { "has" } else { "have" },
            o.where_given(),
            o.column(),
            o.what(),
            o.column()
        )
    }
}

/// The outputs `tyre` gives none of at the points `p` (outputs `f`): each
/// exactly 0 at every point where a tyre that has it gives some, and at
/// one at least, and 0 too where [`gives_none`] looks (a Gim tyre's `mz`
/// is 0 past full sliding by its brush model, a prediction, and it gives
/// some at small slip: not said). A slip ratio the model does not read
/// (`unread`) is said there instead.
pub(crate) fn zero_outputs(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    unread: &[Unread],
) -> Vec<ZeroOutput> {
    let kappa_unread = super::unread::is_unread(unread, "kappa");
    [Output::Fx, Output::Fy, Output::Mx, Output::My, Output::Mz]
        .into_iter()
        .filter(|o| !(*o == Output::Fx && kappa_unread))
        .filter_map(|o| zero_output(o, tyre, p, f).filter(|_| gives_none(tyre, o).is_some()))
        .collect()
}

/// The output `o` of `tyre` where it gives none at all: [`zero_output`]'s
/// rule at points where a tyre that has it gives some (loads of 1, 3 and
/// 6 kN, slip ratios of ±0.1, a slip angle of 0.05 rad, a camber of 0.02
/// rad, 10 m/s), so that `identify` says what a tyre it writes lacks by
/// the rule `tyre-eval` warns by. `None` where it gives some, or where
/// the model has no such output.
pub(crate) fn gives_none(tyre: &Tyre, o: Output) -> Option<ZeroOutput> {
    let fz = [1000.0, 1000.0, 3000.0, 3000.0, 6000.0, 6000.0];
    let kappa = [-0.1, 0.1, -0.1, 0.1, -0.1, 0.1];
    let (alpha, camber, speed) = ([0.05; 6], [0.02; 6], [10.0; 6]);
    let f = tyre.evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &[]);
    let p = Points {
        columns: [&fz, &kappa, &alpha, &camber, &speed],
        pressure: &[],
    };
    zero_output(o, tyre, &p, &f)
}

/// [`zero_outputs`] for one output `o`.
fn zero_output(o: Output, tyre: &Tyre, p: &Points, f: &[PointForces]) -> Option<ZeroOutput> {
    let mut points = 0;
    for (i, fi) in f.iter().enumerate() {
        let value = o.of(fi)?;
        if o.expected(p, i, fi.fy) {
            if value != 0.0 {
                return None;
            }
            points += 1;
        }
    }
    let coefficients = match tyre {
        Tyre::MagicFormula(t) => o
            .coefficients()
            .iter()
            .map(|&n| (n, t.coefficients.get(n).unwrap_or(f64::NAN)))
            .collect(),
        _ => Vec::new(),
    };
    (points > 0).then_some(ZeroOutput {
        output: o,
        points,
        coefficients,
    })
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
