//! Whether the RBF network's answer to an Er target is an answer. Wang &
//! Liang's network (Gaussian radial basis functions, Er in s → (k1, k2) in
//! N/rad) is fitted on pairs inside the study's map and carries no
//! information beyond them: away from its centres its output decays to
//! the weights' bias, whatever the target. An answer is refused (a typed
//! [`RbfStatus`] with each [`RbfRefusal`]) where it lies outside the map's
//! range of k1 or k2, where its Er re-simulated misses the target by more
//! than the target's tolerance (or none is re-simulated), or where it is a
//! stiffness no tyre has (not simulated). Round 44: the coarse Wang & Liang
//! study asked for Er = 0.6 s answered (4645.7, 1822.3) N/deg, seven times
//! the map's stiffest front, whose Er re-simulated 0.0385 s (−93.6 %): it
//! was printed as an answer. An answer inside the map that re-simulates
//! within its tolerance is the answer it was.

use crate::study::inverse::MapBounds;
use crate::study::Target;
use serde::Serialize;

/// Whether the network's answer stands as an answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RbfStatus {
    /// Inside the map, re-simulated within the target's tolerance.
    Answer,
    /// Not an answer: `refused_for` says why.
    Refused,
}

/// Why the network's answer is not an answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RbfRefusal {
    /// A stiffness no tyre has: not simulated.
    NoTyre,
    /// Outside the map's range of front or rear stiffness, where the
    /// network has no data.
    OutsideMap,
    /// No Er re-simulated there (the response is no handling response or
    /// does not settle within the step): nothing confirms it.
    NoErResimulated,
    /// Its Er re-simulated misses the target by more than its tolerance.
    MissesTarget,
}

/// How far outside a map's range, relative to its width, a stiffness may
/// lie and still be inside it: the network's answer is a float, the map's
/// ends the file's values converted to N/rad (1e-9 of a 500 N/deg range
/// is 3e-5 N/rad).
const INSIDE: f64 = 1e-9;

/// Whether `k` (N/rad) lies outside `(lo, hi)` by more than [`INSIDE`] of
/// its width (of `hi` where the range is one value).
fn outside((lo, hi): (f64, f64), k: f64) -> bool {
    let slack = INSIDE * (hi - lo).max(hi.abs());
    k < lo - slack || k > hi + slack
}

/// Why the answer `k` (k1, k2 in N/rad) to `target` is refused, in the
/// order the terminal says them; none where it is an answer. `no_tyre`:
/// a stiffness no tyre has (not simulated); `er`: its Er re-simulated.
pub(super) fn refusals(
    k: (f64, f64),
    bounds: MapBounds,
    no_tyre: bool,
    er: Option<f64>,
    target: &Target,
) -> Vec<RbfRefusal> {
    let mut out = Vec::new();
    if no_tyre {
        out.push(RbfRefusal::NoTyre);
    }
    if outside(bounds.front, k.0) || outside(bounds.rear, k.1) {
        out.push(RbfRefusal::OutsideMap);
    }
    match er {
        _ if no_tyre => {}
        None => out.push(RbfRefusal::NoErResimulated),
        Some(e) if (e - target.value).abs() > target.tolerance => {
            out.push(RbfRefusal::MissesTarget)
        }
        Some(_) => {}
    }
    out
}

/// The status of an answer refused for `refused` (none: an answer).
pub(super) fn status(refused: &[RbfRefusal]) -> RbfStatus {
    match refused.is_empty() {
        true => RbfStatus::Answer,
        false => RbfStatus::Refused,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::Metric;

    const BOUNDS: MapBounds = MapBounds {
        front: (200.0, 700.0),
        rear: (220.0, 720.0),
    };

    fn er(value: f64, tolerance: f64) -> Target {
        Target {
            metric: Metric::Er,
            value,
            tolerance,
        }
    }

    /// The coarse study's answer to Er 0.6: far past the front's 700 and
    /// 94 % short of the target, refused for both; one inside the map
    /// within its tolerance stands.
    #[test]
    fn an_answer_beyond_the_map_or_the_tolerance_is_refused() {
        let t = er(0.6, 0.005);
        let r = refusals((4645.7, 1822.3), BOUNDS, false, Some(0.038543), &t);
        assert_eq!(r, [RbfRefusal::OutsideMap, RbfRefusal::MissesTarget]);
        assert_eq!(status(&r), RbfStatus::Refused);
        let t = er(0.13, 0.005);
        let r = refusals((493.2, 526.1), BOUNDS, false, Some(0.129662), &t);
        assert!(r.is_empty(), "{r:?}");
        assert_eq!(status(&r), RbfStatus::Answer);
        // Just past the tolerance, and just past the rear's end.
        let r = refusals((493.2, 526.1), BOUNDS, false, Some(0.1351), &t);
        assert_eq!(r, [RbfRefusal::MissesTarget]);
        let r = refusals((493.2, 720.01), BOUNDS, false, Some(0.13), &t);
        assert_eq!(r, [RbfRefusal::OutsideMap]);
        // On the map's edge, to rounding: inside.
        let r = refusals(
            (700.0 * (1.0 + 1e-13), 220.0),
            BOUNDS,
            false,
            Some(0.13),
            &t,
        );
        assert!(r.is_empty(), "{r:?}");
        let r = refusals((500.0, 500.0), BOUNDS, false, None, &t);
        assert_eq!(r, [RbfRefusal::NoErResimulated]);
        let r = refusals((1e6, 500.0), BOUNDS, true, None, &t);
        assert_eq!(r, [RbfRefusal::NoTyre, RbfRefusal::OutsideMap]);
    }
}
