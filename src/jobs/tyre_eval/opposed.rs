//! Forces written against their own slip inside the tyre's ranges: a
//! `fy` whose sign is opposite to `alpha`'s, an `fx` whose sign is
//! opposite to `kappa`'s (ISO 8855: a positive slip gives a positive
//! force). No tyre does that, and `tyre-eval` writes it like any other
//! value unless it is said: a Magic Formula fit whose curvature `Ey`
//! exceeds 1 keeps its sign only while MFeval's limit checks clip `E`
//! at 1 (mode 121); with them off (mode 221) the Hoosier rig file's
//! `mf61` fit gives −2711 N at +9° and 2750 N, inside the data's 9.7°.
//!
//! Found by behaviour, for any model: the force written has the sign
//! opposite to its slip, and so has its change from the force at zero
//! slip under the same conditions (a camber thrust or ply steer may
//! oppose a small slip: that part is the tyre's, not counted), by more
//! than [`OPPOSED_SHARE`] of the load. Only points inside the tyre's own
//! ranges are counted (a `.tir`'s limits, a TOML tyre's
//! `[fitted_ranges]`; every point where it states none): past them the
//! range warnings already say the values are extrapolations.

use super::unread::Points;
use crate::format::{plural, readable};
use crate::io::fitted_ranges::{FittedRanges, RangePoint};
use crate::tyre::mf::MfInput;
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The share of `fz` by which a force must oppose its slip to be
/// counted: above the round-off of a force at its zero crossing, below
/// any force a rig measures (2.75 N at 2750 N).
pub const OPPOSED_SHARE: f64 = 1e-3;

/// Which ranges a point was judged inside.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Within {
    /// A `.tir`'s load, slip, camber and pressure limits.
    FileLimits,
    /// A TOML tyre's `[fitted_ranges]`, the rig data's.
    FittedRanges,
    /// The tyre states no range: every point.
    NoRange,
}

/// Points whose force opposes its slip.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Opposed {
    /// `fy` (against `alpha`) or `fx` (against `kappa`).
    pub force: &'static str,
    /// The ranges the points lie inside.
    pub within: Within,
    /// Such points.
    pub points: usize,
    /// The first: its line in the points file, its load (N), slip (rad
    /// or ratio), camber (rad), the force written and the force at zero
    /// slip there (N), and its other slip (ratio or rad), at which both
    /// forces are evaluated.
    pub first: (usize, [f64; 6]),
    /// MFeval's mode with the limit checks off (`None`: on, or another
    /// model).
    pub checks_off: Option<u32>,
}

impl Opposed {
    /// The sentence on the terminal, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let (line, [fz, slip, camber, force, at_zero, other]) = self.first;
        let n = |v: f64| readable(v, 4);
        let angle = |a: f64| format!("{} rad ({}°)", n(a), n(a.to_degrees()));
        // The point's other slip too: at combined slip it shapes the force.
        let (slip_name, slip_text, what) = match self.force {
            "fy" => (
                "alpha",
                format!("{}, kappa = {}", angle(slip), n(other)),
                "lateral force",
            ),
            _ => (
                "kappa",
                format!("{}, alpha = {}", n(slip), angle(other)),
                "longitudinal force",
            ),
        };
        let within = match self.within {
            Within::FileLimits => "inside the file's ranges of load, slip, camber and pressure",
            Within::FittedRanges => "inside the ranges of the rig data it was fitted to",
            Within::NoRange => "(the tyre states no range)",
        };
        let mode = match self.checks_off {
            Some(m) => format!(
                "; evaluated with the limit checks off (mode {m}): a file whose curvature E exceeds 1 (as `identify` warns) keeps its force's sign only with them on: evaluate in mode 121, or refit"
            ),
            None => String::new(),
        };
        format!(
            "{} of {} {within} {} a {what} against {} slip ({} of opposite sign to {slip_name}, beyond what it gives at {slip_name} = 0; the first at line {line}: fz = {} N, {slip_name} = {slip_text}, camber = {} rad: {} = {} N, {} N at {slip_name} = 0): no tyre's force opposes its slip, so the values written there describe no tyre{mode}",
            self.points,
            plural(count, "point", "points"),
            if self.points == 1 { "has" } else { "have" },
            if self.points == 1 { "its" } else { "their" },
            self.force,
            n(fz),
            n(camber),
            self.force,
            n(force),
            n(at_zero),
        )
    }
}

/// One force against its slip: its column, the slips, how it is read
/// from a point's forces, and the forces at zero slip.
type Side<'a> = (
    &'static str,
    &'a [f64],
    fn(&PointForces) -> f64,
    &'a [PointForces],
);

/// Whether point `i` of `p` lies inside `tyre`'s own ranges.
fn inside(tyre: &Tyre, ranges: Option<&FittedRanges>, p: &Points, i: usize) -> bool {
    let [fz, kappa, alpha, camber, speed] = p.columns;
    let pressure = p.pressure.get(i).copied();
    match (tyre, ranges) {
        (Tyre::MagicFormula(t), _) => {
            let q = MfInput {
                fz: fz[i],
                kappa: kappa[i],
                alpha: alpha[i],
                camber: camber[i],
                speed: speed[i],
                pressure,
            };
            t.file_ranges_left(&q).is_empty()
        }
        (_, Some(r)) => {
            let q = RangePoint {
                fz: fz[i],
                alpha: alpha[i],
                kappa: kappa[i],
                camber: camber[i],
                pressure,
            };
            r.left(&q).is_empty()
        }
        _ => true,
    }
}

/// The points of `p` (outputs `f`, file lines `lines`) whose `fy` or `fx`
/// opposes its slip inside `tyre`'s ranges ([`Opposed`]).
pub(crate) fn opposed(
    tyre: &Tyre,
    ranges: Option<&FittedRanges>,
    p: &Points,
    f: &[PointForces],
    lines: &[usize],
) -> Vec<Opposed> {
    let [fz, kappa, alpha, camber, speed] = p.columns;
    let zero = vec![0.0; fz.len()];
    let checks_off = match tyre {
        Tyre::MagicFormula(t) if !t.mode().limit_checks => Some(t.mode().use_mode()),
        _ => None,
    };
    let within = match (tyre, ranges) {
        (Tyre::MagicFormula(_), _) => Within::FileLimits,
        (_, Some(_)) => Within::FittedRanges,
        _ => Within::NoRange,
    };
    let lateral = tyre.evaluate_points(fz, kappa, &zero, camber, speed, p.pressure);
    let longitudinal = tyre.evaluate_points(fz, &zero, alpha, camber, speed, p.pressure);
    let sides: [(Side, &[f64]); 2] = [
        (("fy", alpha, |x| x.fy, &lateral), kappa),
        (("fx", kappa, |x| x.fx, &longitudinal), alpha),
    ];
    sides
        .into_iter()
        .filter_map(|((force, slip, of, at_zero), other)| {
            let against = |i: usize| {
                let (s, v, v0) = (slip[i], of(&f[i]), of(&at_zero[i]));
                let tol = OPPOSED_SHARE * fz[i];
                fz[i] > 0.0 && s * v < 0.0 && v.abs() > tol && s * (v - v0) < -tol * s.abs()
            };
            let found: Vec<usize> = (0..fz.len())
                .filter(|&i| against(i) && inside(tyre, ranges, p, i))
                .collect();
            let &i = found.first()?;
            let first = [
                fz[i],
                slip[i],
                camber[i],
                of(&f[i]),
                of(&at_zero[i]),
                other[i],
            ];
            Some(Opposed {
                force,
                within,
                points: found.len(),
                first: (lines.get(i).copied().unwrap_or(i + 2), first),
                checks_off,
            })
        })
        .collect()
}
