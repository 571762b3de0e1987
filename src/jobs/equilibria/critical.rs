//! What `equilibria` says of an oversteering car's critical speed on tyres
//! without a friction limit: the closed form √(−l/K) (Genta 1997), m/s and
//! km/h, said whether or not a bifurcation along speed located it; and,
//! where conditions near it have no equilibrium in the search box, why:
//! the linear bicycle's trim r = u·δ/(l + K·u²),
//! β = (r/u)·(b − m·a·u²/(l·C_r)) (K the understeer gradient in rad per
//! m/s², C_r the rear axle's cornering stiffness, N/rad) grows without
//! bound as u nears the critical speed and leaves the box. SI units; β and
//! r in ISO 8855 axes (positive to the left), as the sweep's.

use crate::equilibria::sweep::SweepResult;
use crate::equilibria::{Condition, SearchBox};
use crate::format::plural;
use crate::vehicle::VehicleModel;

/// The linear bicycle's steady trim (β, r) at condition `c`, rad and rad/s.
fn linear_trim(model: &VehicleModel, c: &Condition) -> [f64; 2] {
    let v = &model.vehicle;
    let (l, u) = (v.wheelbase(), c.speed);
    let (_, cr) = model.axle_cornering_stiffness();
    let r = c.steer * u / (l + model.understeer_gradient() * u * u);
    let beta = r / u * (v.b - v.mass * v.a * u * u / (l * cr));
    [beta, r]
}

/// The lines under the counts of equilibria in the box: the critical
/// speed `critical` (m/s, None: no line) unless a bifurcation along speed
/// `located` it (its own line then says it, against the same closed form),
/// and why the conditions with no equilibrium in the box have none where
/// every one's linear trim lies beyond it.
pub(super) fn lines(
    model: &VehicleModel,
    (critical, located): (Option<f64>, bool),
    res: &SweepResult,
    bx: &SearchBox,
) -> Vec<String> {
    let Some(c) = critical else {
        return Vec::new();
    };
    let mut out = Vec::new();
    out.extend((!located).then(|| format!(
        "  critical speed {c:.4} m/s ({:.2} km/h), closed form sqrt(-l/K) (K = {:.4e} rad per m/s², oversteer): \
         the linearised car runs straight stably below it, unstably above it",
        3.6 * c,
        model.understeer_gradient()
    )));
    let empty: Vec<&Condition> = res
        .points
        .iter()
        .filter(|p| !p.found.iter().any(|f| f.in_box))
        .map(|p| &p.condition)
        .collect();
    let trims: Vec<[f64; 2]> = empty.iter().map(|e| linear_trim(model, e)).collect();
    if empty.is_empty() || trims.iter().any(|t| bx.contains(*t)) {
        return out;
    }
    let mut speeds: Vec<f64> = empty.iter().map(|e| e.speed).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let near = speeds.iter().map(|u| (u - c).abs() / c).fold(0.0, f64::max);
    let listed: Vec<String> = speeds.iter().map(|u| format!("{u}")).collect();
    // The trim closest to the box, to show by how far even it misses.
    let (e, t) = empty
        .iter()
        .zip(&trims)
        .min_by(|a, b| outside(a.1, bx).total_cmp(&outside(b.1, bx)))
        .expect("conditions with none in the box");
    out.push(format!(
        "    the {} with no equilibrium in the box (speed {} m/s, within {:.1} % of the critical speed {c:.4} m/s): near it \
         the steady yaw-rate gain u/(l + K u²) grows without bound and the trim leaves the box \
         (linear bicycle, nearest the box: steer {:.4} rad at {} m/s, β {:.3} rad, r {:.3} rad/s)",
        plural(empty.len(), "condition", "conditions"),
        listed.join(", "),
        100.0 * near,
        e.steer,
        e.speed,
        t[0],
        t[1]
    ));
    out
}

/// How far a state lies outside the box, in box half-widths (at most 1:
/// inside).
fn outside(x: &[f64; 2], bx: &SearchBox) -> f64 {
    (x[0].abs() / bx.beta_max).max(x[1].abs() / bx.yaw_rate_max)
}
