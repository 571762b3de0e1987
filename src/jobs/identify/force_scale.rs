//! Rig forces far too small for their loads: a file whose `fy` is in lbf
//! against an `fz` in N (or whose forces are otherwise 4.45× too small)
//! fits a tyre of friction 0.26, which is written and simulated as any
//! other. A cornering sweep past [`SWEEP_REACH`] reaches a road tyre's
//! peak |F|/Fz of 0.6–1.8; one whose largest |fy|/fz stays under
//! [`SUSPECT_BELOW`] is warned of, with the number and the likely unit,
//! naming the column. Units: N, rad.

use crate::format::readable;
use crate::identify::data::RigData;

/// The slip angle a sweep must reach to be judged, rad (8°: past a car
/// tyre's peak at 4–8°).
pub(crate) const SWEEP_REACH: f64 = 0.1396;

/// The slip ratio a sweep must reach to be judged (past a tyre's peak at
/// 0.05–0.15).
pub(crate) const KAPPA_REACH: f64 = 0.15;

/// A largest |F|/Fz under which the forces are suspect: half a road
/// tyre's lowest peak (0.6; wet or worn, about 0.5).
pub(crate) const SUSPECT_BELOW: f64 = 0.3;

/// Newtons in a pound-force.
const LBF: f64 = 4.448222;

/// The warnings on the forces of `d`, lateral and longitudinal.
pub(super) fn small_forces(d: &RigData) -> Vec<String> {
    let mut out = Vec::new();
    out.extend(judged(&d.fz, &d.alpha, &d.fy, SWEEP_REACH).map(|p| line("fy", "alpha", p, true)));
    if let Some((kappa, fx)) = &d.longitudinal {
        out.extend(judged(&d.fz, kappa, fx, KAPPA_REACH).map(|p| line("fx", "kappa", p, false)));
    }
    out
}

/// The largest |force|/fz of a sweep reaching `reach` in |slip|, with its
/// sample's force, load and slip, where it is under [`SUSPECT_BELOW`].
fn judged(fz: &[f64], slip: &[f64], force: &[f64], reach: f64) -> Option<[f64; 4]> {
    let measured = |i: &usize| fz[*i] > 0.0 && force[*i].is_finite() && slip[*i].is_finite();
    let all: Vec<usize> = (0..fz.len()).filter(measured).collect();
    let reached = all.iter().map(|&i| slip[i].abs()).fold(0.0, f64::max);
    if reached < reach {
        return None;
    }
    let &i = all
        .iter()
        .max_by(|a, b| (force[**a].abs() / fz[**a]).total_cmp(&(force[**b].abs() / fz[**b])))?;
    let ratio = force[i].abs() / fz[i];
    (ratio < SUSPECT_BELOW).then_some([ratio, force[i], fz[i], slip[i]])
}

/// The warning on column `column` ([`judged`]'s `[ratio, force, fz, slip]`).
fn line(column: &str, slip: &str, [ratio, force, fz, s]: [f64; 4], angle: bool) -> String {
    let slip_text = match angle {
        true => format!("{} {}°", slip, readable(s.to_degrees(), 3)),
        false => format!("{} {}", slip, readable(s, 3)),
    };
    format!(
        "column `{column}`: its largest |{column}|/fz is {} ({column} = {} N at fz = {} N, {slip_text}), where a road tyre's peak is 0.6–1.8 over a sweep this far: is `{column}` in lbf against `fz` in N (4.45× too small; {} × {} = {} N)? forces are in N (FORMATS.md), and the tyre fitted to them has this friction",
        readable(ratio, 3),
        readable(force, 4),
        readable(fz, 4),
        readable(force, 4),
        readable(LBF, 4),
        readable(force * LBF, 4),
    )
}
