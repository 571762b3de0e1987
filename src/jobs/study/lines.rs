//! What the terminal says of one answered inverse target: the map points
//! that meet it, the best combination on its curve (held to the map, and
//! said so where it sits on the map's edge), and for Er the RBF network's
//! answer — said to be an extrapolation outside the Er it was trained on,
//! not re-simulated where it is a stiffness no tyre has, and refused as an
//! answer outside the map or off its target's tolerance, with what the map
//! reaches ([`super::rbf_verdict`]). Stiffness in the study's unit, Er in s.

use super::target_range::{beyond_the_map, span, unit, MapReach, TargetReach};
use super::{BestAnswer, RbfAnswer, RbfFit, RbfRefusal, RbfStatus, TargetReport};
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
            "  {name} = {}: a curve of {} map points; closest to ({:.0}, {:.0}) {u}: ({:.1}, {:.1}) with {name} {:.6} (re-simulated), relative distance {:.3}{}",
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
            beyond_the_map(map, t.metric, t.target, u)
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
/// has, not; refused as an answer outside the map or off its target's
/// tolerance; with the range the network was trained on where the target
/// lies outside it, and what the map reaches where it is refused.
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
    // An answer stands only re-simulated within its tolerance.
    let (Some(e), Some(p), RbfStatus::Answer) = (r.er_resimulated, r.error_percent, r.status)
    else {
        return refused_line(t, r, map, u, &extrapolation);
    };
    // A regression's answer (see the note under the RBF line) is as good
    // as its re-simulated Er, whatever the network's misfit.
    let regression = match r.fit {
        RbfFit::Regression => {
            "; from the network as a regression: trust it as far as its re-simulated Er"
        }
        RbfFit::Interpolant => "",
    };
    format!(
        "    RBF answer: ({:.1}, {:.1}) {u}, Er {e:.6} re-simulated ({p:+.2} %), relative distance {:.3}{extrapolation}{regression}",
        r.k_front, r.k_rear, r.distance_to_reference,
    )
}

/// The network's answer refused (simulated, but outside the map or off
/// its target's tolerance): why, and what the map reaches of Er.
fn refused_line(
    t: &TargetReport,
    r: &RbfAnswer,
    map: &Map,
    u: StiffnessUnit,
    extrapolation: &str,
) -> String {
    let b = map.bounds();
    let k = u.to_si();
    let g = |v: f64| crate::format::rounded(v / k, 6);
    let why: Vec<String> = r
        .refused_for
        .iter()
        .filter_map(|why| match why {
            RbfRefusal::OutsideMap => Some(format!(
                "outside the map it was fitted on (front {}–{}, rear {}–{} {u}), where an RBF network has no data and does not extrapolate",
                g(b.front.0), g(b.front.1), g(b.rear.0), g(b.rear.1)
            )),
            RbfRefusal::MissesTarget => Some(format!(
                "its Er re-simulated, {} s ({:+.2} %), misses Er {} by more than its tolerance of {} s",
                crate::format::significant(r.er_resimulated?, 5),
                r.error_percent?,
                t.target,
                t.tolerance
            )),
            RbfRefusal::NoErResimulated => Some("no Er re-simulated there to confirm it (the response there is no handling response: it slides, is unstable or does not settle within the step)".to_string()),
            RbfRefusal::NoTyre => None,
        })
        .collect();
    format!(
        "    RBF answer: none: the network gives ({:.1}, {:.1}) {u}, relative distance {:.3}: {}; not an answer{extrapolation}{}",
        r.k_front,
        r.k_rear,
        r.distance_to_reference,
        why.join("; and "),
        reach_words(t, t.curve.map_reach.as_ref(), u)
    )
}

/// What the map reaches of Er beside a refused answer: the target
/// unreachable within it, with the nearest value and where; or within
/// it, answered (or not) by the best combination on its curve.
fn reach_words(t: &TargetReport, reach: Option<&MapReach>, u: StiffnessUnit) -> String {
    let Some(m) = reach else {
        return "; no map point has an Er (none is a handling response)".into();
    };
    let g = |v: f64| crate::format::significant(v, 4);
    let range = format!(
        "its Er spans {}–{} s",
        g(m.lowest.value),
        g(m.highest.value)
    );
    match (m.target, &t.curve.best) {
        (TargetReach::Within, Some(_)) => format!(
            "; the map reaches Er {} ({range}): the best combination on its curve, above, answers it",
            t.target
        ),
        (TargetReach::Within, None) => format!(
            "; the map's {range}, Er {} within it, but no point on its curve re-simulates to it",
            t.target
        ),
        _ => format!(
            "; Er {} is unreachable within the map ({range}): {}",
            t.target,
            m.nearest_words(Metric::Er, u).unwrap_or_default()
        ),
    }
}
