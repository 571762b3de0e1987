//! A longitudinal force at zero slip ratio beyond what a free-rolling tyre
//! gives, counted and said: a free-rolling tyre's `fx` is its rolling
//! resistance, about 1 % of its load, and a Magic Formula's horizontal and
//! vertical shifts (`PHX1`, `PHX2`, `PVX1`, `PVX2`) give a few percent at
//! most in the published files (1–3.5 % at `FNOMIN` across the MF 5.2 /
//! 6.1 / 6.2 samples and the Chrono files); the public `car235_80R17.tir`'s
//! `PHX1 = 0.01014` gives 773 N at 4000 N, 19 %: a car pushed at 0.19 g by
//! tyres that do not slip. Above [`ZERO_SLIP_SHARE`] of `fz` the points
//! are counted and the coefficients that make the force are named (those
//! whose removal alone takes a third of it off at the largest point).
//! Units: N.

use super::unread::Points;
use crate::format::{exact, plural, rounded};
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The share of `fz` above which `|fx|` at zero slip ratio is said.
pub const ZERO_SLIP_SHARE: f64 = 0.05;

/// The Magic Formula coefficients that give `fx` at zero slip ratio: the
/// horizontal shift `SHx` and the vertical shift `SVx`.
const SHIFTS: [&str; 4] = ["PHX1", "PHX2", "PVX1", "PVX2"];

/// Points at zero slip ratio whose `|fx|` exceeds [`ZERO_SLIP_SHARE`] of
/// their load.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FxAtZeroSlip {
    /// The points (at a positive load).
    pub points: usize,
    /// The largest `|fx|/fz`'s point: its line in the points file, `fx`
    /// and `fz`, N.
    pub largest: (usize, f64, f64),
    /// The Magic Formula coefficients that make it, with their values
    /// (empty for another model).
    pub coefficients: Vec<(&'static str, f64)>,
}

/// The points of `p` (outputs `f`, file lines `lines`) at `kappa = 0` with
/// `|fx|` above [`ZERO_SLIP_SHARE`] of `fz`; `None` where there are none.
pub(crate) fn fx_at_zero_slip(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    lines: &[usize],
) -> Option<FxAtZeroSlip> {
    let [fz, kappa, ..] = p.columns;
    let share = |i: usize| f[i].fx.abs() / fz[i];
    let over: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && kappa[i] == 0.0 && share(i) > ZERO_SLIP_SHARE)
        .collect();
    let &worst = over
        .iter()
        .max_by(|&&a, &&b| share(a).total_cmp(&share(b)))?;
    Some(FxAtZeroSlip {
        points: over.len(),
        largest: (
            lines.get(worst).copied().unwrap_or(0),
            f[worst].fx,
            fz[worst],
        ),
        coefficients: responsible(tyre, p, worst, f[worst].fx),
    })
}

/// The shifts of a Magic Formula `tyre` whose removal alone takes a third
/// of `fx` off at point `i` of `p` (every shift not 0 where none does).
fn responsible(tyre: &Tyre, p: &Points, i: usize, fx: f64) -> Vec<(&'static str, f64)> {
    let Tyre::MagicFormula(t) = tyre else {
        return Vec::new();
    };
    let given: Vec<(&'static str, f64)> = SHIFTS
        .iter()
        .filter_map(|&n| t.coefficients.get(n).map(|v| (n, v)))
        .filter(|(_, v)| *v != 0.0)
        .collect();
    let at = |c: &[f64]| vec![c[i]];
    let [fz, kappa, alpha, camber, speed] = p.columns.map(at);
    let pressure: Vec<f64> = p.pressure.get(i).copied().into_iter().collect();
    let without = |name: &str| {
        let mut m = t.clone();
        m.coefficients.set(name, 0.0);
        let f =
            Tyre::MagicFormula(m).evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &pressure);
        f[0].fx
    };
    let named: Vec<(&'static str, f64)> = given
        .iter()
        .copied()
        .filter(|(n, _)| (fx - without(n)).abs() >= fx.abs() / 3.0)
        .collect();
    if named.is_empty() {
        given
    } else {
        named
    }
}

impl FxAtZeroSlip {
    /// The sentence on the terminal, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let (line, fx, fz) = self.largest;
        let cause = match self.coefficients.as_slice() {
            [] => "the model's offsets give it".to_string(),
            c => {
                let each: Vec<String> = c
                    .iter()
                    .map(|(n, v)| format!("{n} = {}", exact(*v)))
                    .collect();
                let verb = if c.len() == 1 { "gives" } else { "give" };
                format!("the file's {} {verb} it", each.join(", "))
            }
        };
        format!(
            "{} of {} at kappa = 0 have |fx| above {} % of fz (the largest {} N at fz = {} N, line {line}: {} %), where a free-rolling tyre gives its rolling resistance, about 1 %: {cause}; check them",
            self.points,
            plural(count, "point", "points"),
            rounded(100.0 * ZERO_SLIP_SHARE, 3),
            rounded(fx, 4),
            rounded(fz, 6),
            rounded(100.0 * fx.abs() / fz, 2),
        )
    }
}
