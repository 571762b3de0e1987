//! What `tyre-eval` says of its points' horizontal force, for any model:
//!
//! - a resultant `√(fx² + fy²)` above the tyre's friction `μ·Fz` by more
//!   than [`FRICTION_TOLERANCE`] ([`BeyondFriction`]). No tyre transmits
//!   more than its friction; the force such a point is given is not a
//!   prediction. `μ·Fz` is the tyre's own: the most it transmits in pure
//!   slip at the point's load, camber, pressure and speed, the larger of
//!   its pure longitudinal and pure lateral peaks (μx·Fz and μy·Fz, found
//!   by scanning its pure-slip curves, [`PEAK_SLIP_ANGLE`] and
//!   [`PEAK_SLIP_RATIO`]), so that a tyre gripping harder in braking than
//!   in cornering is not said to exceed its lateral friction.
//! - a model that does not couple `fx` and `fy` ([`Uncoupled`]): at every
//!   point at combined slip (`kappa` ≠ 0 and `alpha` ≠ 0) its `fx` is its
//!   pure-slip force at that slip ratio and its `fy` at that slip angle,
//!   each as if the other slip were 0 (this crate's UniTire, in Zhang &
//!   Li's (2017) pure-slip form, and PAC89 with a longitudinal block: their
//!   papers give no combined-slip law). Found by behaviour, as the unread
//!   columns are (`unread.rs`): the point re-evaluated at each pure slip
//!   gives the same force. Their resultant then reaches `√2·μ·Fz`.

use super::unread::Points;
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;
use std::collections::HashMap;

/// How far a point's `√(fx² + fy²)` may exceed the tyre's `μ·Fz` before it
/// is said, as a fraction of it: 5 %. The Magic Formula's combined-slip
/// weighting keeps its resultant near its pure-slip peak, but its shifts
/// (`SVy`, `SVyκ`) add a little: MFeval's public 6.1 and 6.2 samples
/// reach 2.6 % above it; the 5.2 sample and the Pacejka book defaults
/// 11–14 %, an uncoupled UniTire 38 %.
pub const FRICTION_TOLERANCE: f64 = 0.05;

/// The slip angles the pure lateral peak is looked for at, rad: ±30° in
/// 0.5° steps (the peaks of road and racing tyres lie at 3–12°, where a
/// curve is flat to well under [`FRICTION_TOLERANCE`] over half a step).
pub const PEAK_SLIP_ANGLE: (f64, usize) = (std::f64::consts::PI / 6.0, 60);

/// The slip ratios the pure longitudinal peak is looked for at: ±1 in
/// 0.01 steps (the peaks lie at 0.05–0.3).
pub const PEAK_SLIP_RATIO: (f64, usize) = (1.0, 100);

/// Where a `.tir` tyre's pure curves peak above any tyre's on a road or
/// rig ([`crate::tyre::mf::WARN_FRICTION`], below the refusal at 5): a
/// published file (`FSAE_Defaults.tir`, 3.4 at light load) is read, and
/// the number said. Only the forces the file describes are judged.
pub(crate) fn peak_of(tyre: &Tyre) -> Option<crate::tyre::mf::PeakFriction> {
    match tyre {
        Tyre::MagicFormula(t) => peak_of_mf(t),
        _ => None,
    }
}

/// [`peak_of`] of a Magic Formula tyre.
pub(crate) fn peak_of_mf(t: &crate::tyre::MagicFormula) -> Option<crate::tyre::mf::PeakFriction> {
    let c = &t.coefficients;
    let described = (c.PDY1 != 0.0, c.PDX1 != 0.0);
    t.peak_friction(described, crate::tyre::mf::WARN_FRICTION)
}

/// Points whose horizontal force exceeds the tyre's friction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BeyondFriction {
    /// Points at a positive load whose `√(fx² + fy²)` exceeds `μ·Fz` by
    /// more than [`FRICTION_TOLERANCE`].
    pub points: usize,
    /// The largest `√(fx² + fy²)/(μ·Fz)` among them.
    pub largest: f64,
    /// Its point: `fz` (N), `kappa`, `alpha` (rad).
    pub at: [f64; 3],
}

impl BeyondFriction {
    /// The sentence on the terminal (`uncoupled`: the model does not
    /// couple `fx` and `fy`, said there).
    pub fn line(&self, count: usize, uncoupled: bool) -> String {
        let [fz, kappa, alpha] = self.at;
        let n = |v: f64| crate::format::readable(v, 4);
        let why = match uncoupled {
            true => ": the model does not couple fx and fy (above)",
            false => "",
        };
        format!(
            "{} of {} {} √(fx² + fy²) more than {} % above the tyre's friction μ·Fz (the most it transmits in pure slip at the point's load, camber, pressure and speed), up to {}·μ·Fz at fz = {} N, kappa = {}, alpha = {} rad{why}: no tyre transmits more than its friction, so those forces are not a prediction",
            self.points,
            crate::format::plural(count, "point", "points"),
            if self.points == 1 { "has" } else { "have" },
            crate::format::fixed(100.0 * FRICTION_TOLERANCE, 0),
            crate::format::fixed(self.largest, 2),
            n(fz),
            n(kappa),
            n(alpha)
        )
    }
}

/// Points at combined slip where the model gives each force as in pure
/// slip.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Uncoupled {
    /// Points at a positive load with `kappa` ≠ 0 and `alpha` ≠ 0 (all of
    /// them evaluated as pure slip).
    pub points: usize,
}

impl Uncoupled {
    /// The sentence on the terminal, for `model`.
    pub fn line(&self, count: usize, model: &str) -> String {
        format!(
            "this {model} tyre does not couple fx and fy: at the {} of {} at combined slip (kappa ≠ 0 and alpha ≠ 0) its fx is its pure-slip force at kappa and its fy at alpha, each as if the other slip were 0 (the {model} model here has no combined-slip law), so together they are no combined-slip prediction, and their resultant can reach √2 times the tyre's friction",
            self.points,
            crate::format::plural(count, "point", "points")
        )
    }
}

/// One point's pure-slip forces: `fx` at its slip ratio and no slip
/// angle, `fy` at its slip angle and no slip ratio.
struct Pure {
    fx: f64,
    fy: f64,
}

/// The pure-slip forces of `tyre` at the points `idx` of `p`.
fn pure_forces(tyre: &Tyre, p: &Points, idx: &[usize]) -> Vec<Pure> {
    let [fz, kappa, alpha, camber, speed] = p.columns;
    let pick = |c: &[f64]| idx.iter().map(|&i| c[i]).collect::<Vec<f64>>();
    let pressure = match p.pressure.is_empty() {
        true => Vec::new(),
        false => pick(p.pressure),
    };
    let (fz, camber, speed) = (pick(fz), pick(camber), pick(speed));
    let zero = vec![0.0; idx.len()];
    let x = tyre.evaluate_points(&fz, &pick(kappa), &zero, &camber, &speed, &pressure);
    let y = tyre.evaluate_points(&fz, &zero, &pick(alpha), &camber, &speed, &pressure);
    x.iter()
        .zip(&y)
        .map(|(x, y)| Pure { fx: x.fx, fy: y.fy })
        .collect()
}

/// What the forces `f` of `tyre` at the points `p` exceed and lack:
/// the points beyond its friction, and whether it couples `fx` and `fy`
/// (module notes).
pub(crate) fn friction(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
) -> (Option<BeyondFriction>, Option<Uncoupled>) {
    let [fz, kappa, alpha, ..] = p.columns;
    let loaded: Vec<usize> = (0..f.len()).filter(|&i| fz[i] > 0.0).collect();
    let pure = pure_forces(tyre, p, &loaded);
    let combined: Vec<(usize, &Pure)> = loaded
        .iter()
        .zip(&pure)
        .filter(|(&i, _)| kappa[i] != 0.0 && alpha[i] != 0.0)
        .map(|(&i, q)| (i, q))
        .collect();
    let as_pure = |(i, q): &(usize, &Pure)| f[*i].fx == q.fx && f[*i].fy == q.fy;
    let both = combined
        .iter()
        .any(|(i, _)| f[*i].fx != 0.0 && f[*i].fy != 0.0);
    let uncoupled = (both && combined.iter().all(as_pure)).then_some(Uncoupled {
        points: combined.len(),
    });
    // A point's force within the tolerance of its own pure-slip forces is
    // within it of the peaks, which are at least those: only the others
    // are scanned for the peaks.
    let resultant = |i: usize| f[i].fx.hypot(f[i].fy);
    let suspect: Vec<usize> = loaded
        .iter()
        .zip(&pure)
        .filter(|(&i, q)| resultant(i) > (1.0 + FRICTION_TOLERANCE) * q.fx.abs().max(q.fy.abs()))
        .map(|(&i, _)| i)
        .collect();
    let mut peaks = Peaks::default();
    let mut beyond: Option<BeyondFriction> = None;
    for i in suspect {
        let ratio = resultant(i) / peaks.of(tyre, p, i);
        if ratio <= 1.0 + FRICTION_TOLERANCE {
            continue;
        }
        let b = beyond.get_or_insert(BeyondFriction {
            points: 0,
            largest: 0.0,
            at: [0.0; 3],
        });
        b.points += 1;
        if ratio > b.largest {
            b.largest = ratio;
            b.at = [fz[i], kappa[i], alpha[i]];
        }
    }
    (beyond, uncoupled)
}

/// The tyre's pure-slip peaks, `μ·Fz`, per condition (load, camber,
/// pressure, speed) of the points: a points file holds few conditions.
#[derive(Default)]
struct Peaks(HashMap<[u64; 4], f64>);

impl Peaks {
    /// `μ·Fz` at the condition of point `i` of `p`: the larger of the
    /// peaks of the pure longitudinal and lateral forces.
    fn of(&mut self, tyre: &Tyre, p: &Points, i: usize) -> f64 {
        let [fz, _, _, camber, speed] = p.columns;
        let pressure = p.pressure.get(i).copied();
        let key = [fz[i], camber[i], speed[i], pressure.unwrap_or(f64::NAN)].map(f64::to_bits);
        *self.0.entry(key).or_insert_with(|| {
            let scan = |(end, n): (f64, usize)| -> Vec<f64> {
                (-(n as i64)..=n as i64)
                    .map(|k| end * k as f64 / n as f64)
                    .collect()
            };
            let (kappas, alphas) = (scan(PEAK_SLIP_RATIO), scan(PEAK_SLIP_ANGLE));
            let at = |m: usize| {
                let pressure = pressure.map_or(Vec::new(), |v| vec![v; m]);
                (
                    vec![fz[i]; m],
                    vec![camber[i]; m],
                    vec![speed[i]; m],
                    pressure,
                )
            };
            let (l, c, v, pr) = at(kappas.len());
            let zero = vec![0.0; kappas.len()];
            let x = tyre.evaluate_points(&l, &kappas, &zero, &c, &v, &pr);
            let (l, c, v, pr) = at(alphas.len());
            let zero = vec![0.0; alphas.len()];
            let y = tyre.evaluate_points(&l, &zero, &alphas, &c, &v, &pr);
            let px = x.iter().map(|f| f.fx.abs()).fold(0.0, f64::max);
            let py = y.iter().map(|f| f.fy.abs()).fold(0.0, f64::max);
            px.max(py)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tyre_file(name: &str) -> Tyre {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        crate::io::load_tyre(&root.join("tyres").join(name)).unwrap()
    }

    /// `friction` of `tyre` at one point at 4 kN, 20 m/s.
    fn at(tyre: &Tyre, kappa: f64, alpha: f64) -> (Option<BeyondFriction>, Option<Uncoupled>) {
        let (fz, kappa, alpha, camber, speed) = ([4000.0], [kappa], [alpha], [0.0], [20.0]);
        let f = tyre.evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &[]);
        let p = Points {
            columns: [&fz, &kappa, &alpha, &camber, &speed],
            pressure: &[],
        };
        friction(tyre, &p, &f)
    }

    #[test]
    fn unitire_at_combined_slip_is_uncoupled_and_beyond_its_friction() {
        let t = tyre_file("unitire.toml");
        let (beyond, uncoupled) = at(&t, 0.1, 0.1);
        assert_eq!(uncoupled, Some(Uncoupled { points: 1 }));
        let b = beyond.expect("beyond its friction");
        // Both forces near their peaks: the resultant near √2 of μ·Fz.
        assert!(b.largest > 1.2 && b.largest < 1.42, "{b:?}");
        // In pure slip it is neither.
        assert_eq!(at(&t, 0.1, 0.0), (None, None));
        assert_eq!(at(&t, 0.0, 0.1), (None, None));
    }

    #[test]
    fn a_model_with_a_combined_slip_law_is_coupled_and_within_its_friction() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let tir = root.join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
        let t = crate::io::load_tyre(&tir).unwrap();
        assert_eq!(at(&t, 0.1, 0.1), (None, None));
        // A lateral-only model has no fx to couple.
        assert_eq!(at(&tyre_file("gim.toml"), 0.1, 0.1), (None, None));
    }
}
