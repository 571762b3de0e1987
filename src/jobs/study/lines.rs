//! What the terminal says of one answered inverse target: the map points
//! that meet it, the best combination on its curve (held to the map, and
//! said so where it sits on the map's edge), and for Er the RBF network's
//! answer — said to be an extrapolation outside the Er it was trained on,
//! and not re-simulated where it is a stiffness no tyre has. Stiffness in
//! the study's unit, Er in s.

use super::target_range::{beyond_the_map, span, unit};
use super::{BestAnswer, RbfAnswer, RbfFit, TargetReport};
use crate::study::inverse::{Map, MapEdge};
use crate::study::{Metric, StiffnessUnit};

/// The lines of one answered target.
pub(super) fn target_lines(
    t: &TargetReport,
    reference: [f64; 2],
    u: StiffnessUnit,
    map: &Map,
) -> Vec<String> {
    let n = t.region.len();
    let mut out = vec![format!(
        "  {} = {} ± {}: {n} map {} every constraint",
        t.metric,
        t.target,
        t.tolerance,
        if n == 1 {
            "point meets it and"
        } else {
            "points meet it and"
        },
    )];
    // Er keeps the paper's name; the other metrics their column's.
    let name = match t.metric {
        Metric::Er => "Er".to_string(),
        m => m.to_string(),
    };
    let er = &t.curve;
    out.push(match &er.best {
        Some(b) => format!(
            "  {name} = {}: a curve of {} map points; closest to ({:.0}, {:.0}) {u}: ({:.1}, {:.1}) with {name} {:.6} (re-simulated), distance {:.3}{}",
            t.target,
            er.curve.len(),
            reference[0],
            reference[1],
            b.k_front,
            b.k_rear,
            b.resimulated,
            b.distance_to_reference,
            held(b, map, u)
        ),
        None if er.curve.is_empty() => format!(
            "  {name} = {}: not reached on the map{}",
            t.target,
            beyond_the_map(map, t.metric, t.target)
        ),
        None => format!(
            "  {name} = {}: a curve of {} map points, but no point on it re-simulates to the target (the secant in the rear stiffness did not converge from the map's closest point)",
            t.target,
            er.curve.len()
        ),
    });
    if let Some(r) = &er.rbf {
        out.push(rbf_line(t, r, map, u));
    }
    out
}

/// The words after a best combination held to the map's edge: the curve
/// may come closer beyond it, where the map has no data.
fn held(b: &BestAnswer, map: &Map, u: StiffnessUnit) -> String {
    let Some(edge) = b.at_map_edge else {
        return String::new();
    };
    let bounds = map.bounds();
    let k = u.to_si();
    let (value, key) = match edge {
        MapEdge::FrontLowest => (bounds.front.0, "front"),
        MapEdge::FrontHighest => (bounds.front.1, "front"),
        MapEdge::RearLowest => (bounds.rear.0, "rear"),
        MapEdge::RearHighest => (bounds.rear.1, "rear"),
    };
    format!(
        "; held to the map: it lies on the map's edge, {} ({} {u}), and the curve may come closer beyond it, where the map has no data (widen `[stiffness] {key}` to look there)",
        edge.words(),
        crate::format::rounded(value / k, 6)
    )
}

/// The network's answer: re-simulated, or, where it is a stiffness no tyre
/// has, not; with the range the network was trained on where the target
/// lies outside it, and the map's where neither reaches it.
fn rbf_line(t: &TargetReport, r: &RbfAnswer, map: &Map, u: StiffnessUnit) -> String {
    let (lo, hi) = r.trained_er;
    let outside = t.target < lo || t.target > hi;
    let extrapolation = match outside {
        true => format!("; an extrapolation: Er {} lies outside the Er {lo:.5}–{hi:.5} s the network was trained on, where it has no data", t.target),
        false => String::new(),
    };
    if let Some(no) = &r.no_tyre_has {
        let reach = match (t.curve.curve.is_empty(), span(map, Metric::Er)) {
            (true, Some((a, b))) => format!(
                "; Er {} is out of reach of the map (its Er spans {}–{} {}) and of any tyre the network knows",
                t.target,
                crate::format::significant(a, 4),
                crate::format::significant(b, 4),
                unit(Metric::Er)
            ),
            (true, None) => format!(
                "; Er {} is out of reach of the map (no map point has an Er) and of any tyre the network knows",
                t.target
            ),
            (false, _) => String::new(),
        };
        return format!(
            "    RBF answer: none: the network gives ({:.1}, {:.1}) {u}, {}; not simulated{extrapolation}{reach}",
            r.k_front,
            r.k_rear,
            no.words()
        );
    }
    let resimulated = match (r.er_resimulated, r.error_percent) {
        (Some(e), Some(p)) => format!("Er {e:.6} re-simulated ({p:+.2} %)"),
        _ => "no Er re-simulated (the response there does not settle to a steady state within the step)".to_string(),
    };
    // A regression's answer (see the note under the RBF line) is as good
    // as its re-simulated Er, whatever the network's misfit.
    let regression = match r.fit {
        RbfFit::Regression if r.er_resimulated.is_some() => {
            "; from the network as a regression: trust it as far as its re-simulated Er"
        }
        RbfFit::Regression => "; from the network as a regression, with no Er re-simulated to judge it by: not to be trusted",
        RbfFit::Interpolant => "",
    };
    format!(
        "    RBF answer: ({:.1}, {:.1}) {u}, {resimulated}, distance {:.3}{extrapolation}{regression}",
        r.k_front, r.k_rear, r.distance_to_reference,
    )
}
