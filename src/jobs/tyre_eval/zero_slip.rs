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
//! A Magic Formula point below the file's `VXLOW` is judged apart: there
//! MFeval fades the vertical shift `SVx` to 0 towards rest (its factor
//! `|Vx|/VXLOW`), so that at rest `fx` is the horizontal shift's alone (the
//! MF 6.1 sample: −353.9 N at 4000 N at rest, −53.3 N from 1 m/s up), a
//! force of the speed, not of the file's shifts.
//! Units: N, m/s.

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
    /// The points (at a positive load, at or above `VXLOW`).
    pub points: usize,
    /// The largest `|fx|/fz`'s point among them: its line in the points
    /// file, `fx` and `fz`, N (None: every such point is below `VXLOW`).
    pub largest: Option<(usize, f64, f64)>,
    /// The Magic Formula coefficients that make it, with their values
    /// (empty for another model, and where no shift alone takes a third of
    /// it off).
    pub coefficients: Vec<(&'static str, f64)>,
    /// Whether the tyre is a Magic Formula (whose shifts were judged).
    #[serde(default)]
    pub magic_formula: bool,
    /// The largest point's pressure where it lies past the Magic Formula
    /// file's range, with the range (Pa): its pressure terms extrapolated
    /// there scale the force a shift gives.
    #[serde(default)]
    pub pressure_past_range: Option<(f64, f64, f64)>,
    /// Such points below a Magic Formula file's `VXLOW`: their count, the
    /// largest one's line and `fx` (N), and `VXLOW` (m/s).
    pub below_vxlow: Option<(usize, usize, f64, f64)>,
}

/// The points of `p` (outputs `f`, file lines `lines`) at `kappa = 0` with
/// `|fx|` above [`ZERO_SLIP_SHARE`] of `fz`; `None` where there are none.
pub(crate) fn fx_at_zero_slip(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    lines: &[usize],
) -> Option<FxAtZeroSlip> {
    let [fz, kappa, _, _, speed] = p.columns;
    let share = |i: usize| f[i].fx.abs() / fz[i];
    let vxlow = match tyre {
        Tyre::MagicFormula(t) => Some(t.coefficients.VXLOW),
        _ => None,
    };
    let slow = |i: usize| vxlow.is_some_and(|v| speed[i].abs() < v);
    let over: Vec<usize> = (0..fz.len())
        .filter(|&i| fz[i] > 0.0 && kappa[i] == 0.0 && share(i) > ZERO_SLIP_SHARE)
        .collect();
    let worst = |of: &[usize]| {
        of.iter()
            .copied()
            .max_by(|&a, &b| share(a).total_cmp(&share(b)))
    };
    let line = |i: usize| lines.get(i).copied().unwrap_or(0);
    let (below, moving): (Vec<usize>, Vec<usize>) = over.iter().partition(|&&i| slow(i));
    let below_vxlow = worst(&below)
        .zip(vxlow)
        .map(|(w, v)| (below.len(), line(w), f[w].fx, v));
    let largest = worst(&moving);
    if largest.is_none() && below_vxlow.is_none() {
        return None;
    }
    Some(FxAtZeroSlip {
        points: moving.len(),
        largest: largest.map(|w| (line(w), f[w].fx, fz[w])),
        coefficients: largest.map_or_else(Vec::new, |w| responsible(tyre, p, w, f[w].fx)),
        magic_formula: vxlow.is_some(),
        pressure_past_range: largest.and_then(|w| past_range(tyre, p, w)),
        below_vxlow,
    })
}

/// The pressure of point `i` where it lies past a Magic Formula file's
/// pressure range, with the range.
fn past_range(tyre: &Tyre, p: &Points, i: usize) -> Option<(f64, f64, f64)> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let pressure = *p.pressure.get(i)?;
    let (lo, hi) = (t.limits.pressure_min?, t.limits.pressure_max?);
    (!(lo..=hi).contains(&pressure)).then_some((pressure, lo, hi))
}

/// The shifts of a Magic Formula `tyre` whose removal alone takes a third
/// of `fx` off at point `i` of `p` (none where none does: a pressure far
/// past the file's range gave 3.5·Fz that a shift of −0.0016 was blamed
/// for).
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
    given
        .iter()
        .copied()
        .filter(|(n, _)| (fx - without(n)).abs() >= fx.abs() / 3.0)
        .collect()
}

impl FxAtZeroSlip {
    /// The sentence on the terminal, of `count` points.
    pub fn line(&self, count: usize) -> String {
        // The points below VXLOW: alone, or after the moving ones.
        let slow = |lead: String| {
            self.below_vxlow.map(|(n, line, fx, vxlow)| {
                format!(
                    "{lead} at kappa = 0 below the file's VXLOW = {} m/s {} |fx| above {} % of fz (the largest {} N, line {line}): MFeval fades the vertical shift SVx to 0 towards rest, so there fx is the horizontal shift's alone, a force of the low speed, not a free-rolling tyre's; give the wheel's speed for that",
                    rounded(vxlow, 4),
                    if n == 1 { "has" } else { "have" },
                    rounded(100.0 * ZERO_SLIP_SHARE, 3),
                    rounded(fx, 4),
                )
            })
        };
        let Some((line, fx, fz)) = self.largest else {
            let n = self.below_vxlow.map_or(0, |b| b.0);
            let lead = format!("{n} of {}", plural(count, "point", "points"));
            return slow(lead).unwrap_or_default();
        };
        let cause = match self.coefficients.as_slice() {
            [] if self.magic_formula => "no shift of the file (PHX1, PHX2, PVX1, PVX2) gives a third of it alone: the point's own conditions (its load, pressure or speed, past the file's ranges?) take the coefficients where they describe no tyre".to_string(),
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
        let cause = match self.pressure_past_range {
            Some((p, lo, hi)) => format!(
                "{cause}, at a pressure of {} Pa past the file's PRESMIN–PRESMAX ({}–{} Pa), where its pressure terms extrapolated scale the force (see the pressure warning)",
                rounded(p, 6),
                rounded(lo, 6),
                rounded(hi, 6)
            ),
            None => cause,
        };
        let more = self.below_vxlow.map_or(0, |b| b.0);
        let also = slow(format!("{more} more")).map_or_else(String::new, |s| format!("; and {s}"));
        format!(
            "{} of {} at kappa = 0 have |fx| above {} % of fz (the largest {} N at fz = {} N, line {line}: {} %), where a free-rolling tyre gives its rolling resistance, about 1 %: {cause}; check them{also}",
            self.points,
            plural(count, "point", "points"),
            rounded(100.0 * ZERO_SLIP_SHARE, 3),
            rounded(fx, 4),
            rounded(fz, 6),
            rounded(100.0 * fx.abs() / fz, 2),
        )
    }
}
