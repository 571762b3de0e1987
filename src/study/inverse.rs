//! The inverse problem on a full (k1, k2) map: a target value of a metric
//! (Er, or any metric) is met along a curve, not at a point. The curve is
//! traced by linear interpolation of the map along both axes; a set of
//! targets with tolerances selects a region of map points; the best
//! combination under a preference (closest to the current tyres, distances
//! relative to them) starts from the closest curve point and is refined with
//! the simulator itself: k2 solved for the target by secant at each k1, and
//! k1 chosen by golden-section search. The refinement is held to the map
//! (its range of k1 and k2): beyond it the map has no data, and a best
//! point there was reported as if the map had found it.

use super::{Metric, Sample, Study, Target};
use serde::Serialize;

/// A full map: every front value with every rear value.
#[derive(Debug, Clone)]
pub struct Map {
    /// Front stiffness values, N/rad, ascending.
    pub front: Vec<f64>,
    /// Rear stiffness values, N/rad, ascending.
    pub rear: Vec<f64>,
    /// Samples, rear fastest: index `i_front·rear.len() + i_rear`.
    pub samples: Vec<Sample>,
}

/// The ranges a map spans, N/rad: (lowest, highest) of each axle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapBounds {
    /// Front stiffness.
    pub front: (f64, f64),
    /// Rear stiffness.
    pub rear: (f64, f64),
}

/// The edge of the map a best combination was held to: the curve may come
/// closer to the reference beyond it, where the map has no data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MapEdge {
    /// The lowest front stiffness of the map.
    FrontLowest,
    /// The highest front stiffness of the map.
    FrontHighest,
    /// The lowest rear stiffness of the map.
    RearLowest,
    /// The highest rear stiffness of the map.
    RearHighest,
}

impl MapEdge {
    /// The words for it: which axle, which end.
    pub fn words(self) -> &'static str {
        match self {
            MapEdge::FrontLowest => "the lowest front stiffness",
            MapEdge::FrontHighest => "the highest front stiffness",
            MapEdge::RearLowest => "the lowest rear stiffness",
            MapEdge::RearHighest => "the highest rear stiffness",
        }
    }
}

impl MapBounds {
    /// How far `kr` lies outside the rear range, relative to its width
    /// (0 inside).
    fn rear_excess(&self, kr: f64) -> f64 {
        let (lo, hi) = self.rear;
        ((lo - kr).max(kr - hi).max(0.0)) / (hi - lo).max(f64::MIN_POSITIVE)
    }

    /// The edge (k1, k2) lies on, if any: within 1e-4 of the front range's
    /// width of a front end (the golden section closes to far less), within
    /// 1e-3 of the rear range's width of a rear end or beyond it.
    pub fn edge(&self, (kf, kr): (f64, f64)) -> Option<MapEdge> {
        let (f, r) = (self.front, self.rear);
        let (wf, wr) = (f.1 - f.0, r.1 - r.0);
        if kf <= f.0 + 1e-4 * wf {
            Some(MapEdge::FrontLowest)
        } else if kf >= f.1 - 1e-4 * wf {
            Some(MapEdge::FrontHighest)
        } else if kr <= r.0 + 1e-3 * wr {
            Some(MapEdge::RearLowest)
        } else if kr >= r.1 - 1e-3 * wr {
            Some(MapEdge::RearHighest)
        } else {
            None
        }
    }
}

/// The best combination on a curve ([`best_on_curve`]), N/rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Best {
    /// Front stiffness.
    pub k_front: f64,
    /// Rear stiffness.
    pub k_rear: f64,
    /// The metric simulated there.
    pub value: f64,
    /// The map's edge it was held to, if any.
    pub edge: Option<MapEdge>,
}

impl Map {
    /// The ranges the map spans.
    pub fn bounds(&self) -> MapBounds {
        let ends = |v: &[f64]| (v[0], v[v.len() - 1]);
        MapBounds {
            front: ends(&self.front),
            rear: ends(&self.rear),
        }
    }

    /// The metric at grid point (i, j).
    pub fn value(&self, metric: Metric, i: usize, j: usize) -> f64 {
        metric.of_sample(&self.samples[i * self.rear.len() + j])
    }

    /// The metric at grid point (i, j) as the step measures it
    /// ([`Metric::measured`]: no overshoot below the threshold).
    pub fn measured(&self, metric: Metric, i: usize, j: usize) -> f64 {
        metric.measured_of_sample(&self.samples[i * self.rear.len() + j])
    }

    /// Points (k1, k2) where `metric` equals `target`, by linear interpolation
    /// along rear lines and along front lines, sorted by k1.
    pub(crate) fn iso_curve(&self, metric: Metric, target: f64) -> Vec<(f64, f64)> {
        let (nf, nr) = (self.front.len(), self.rear.len());
        let mut pts = Vec::new();
        let cross = |a: f64, b: f64| {
            let (da, db) = (a - target, b - target);
            (da.is_finite() && db.is_finite() && da * db <= 0.0 && da != db).then(|| da / (da - db))
        };
        for i in 0..nf {
            for j in 0..nr.saturating_sub(1) {
                if let Some(w) = cross(self.value(metric, i, j), self.value(metric, i, j + 1)) {
                    pts.push((
                        self.front[i],
                        self.rear[j] + w * (self.rear[j + 1] - self.rear[j]),
                    ));
                }
            }
        }
        for j in 0..nr {
            for i in 0..nf.saturating_sub(1) {
                if let Some(w) = cross(self.value(metric, i, j), self.value(metric, i + 1, j)) {
                    pts.push((
                        self.front[i] + w * (self.front[i + 1] - self.front[i]),
                        self.rear[j],
                    ));
                }
            }
        }
        pts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        pts.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9);
        pts
    }

    /// Map points meeting every target within its tolerance.
    pub(crate) fn region(&self, targets: &[Target]) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        for (i, &kf) in self.front.iter().enumerate() {
            for (j, &kr) in self.rear.iter().enumerate() {
                if targets
                    .iter()
                    .all(|t| (self.value(t.metric, i, j) - t.value).abs() <= t.tolerance)
                {
                    out.push((kf, kr));
                }
            }
        }
        out
    }
}

/// Relative distance of (k1, k2) from a reference combination.
pub(crate) fn distance(a: (f64, f64), reference: (f64, f64)) -> f64 {
    ((a.0 - reference.0) / reference.0).hypot((a.1 - reference.1) / reference.1)
}

/// The rear stiffness that gives `metric` = `target` at front stiffness
/// `kf`, by secant iteration from `kr0` (simulations); `None` if it does not
/// converge.
pub(crate) fn solve_rear(
    study: &Study,
    metric: Metric,
    kf: f64,
    kr0: f64,
    (target, tol): (f64, f64),
) -> Option<f64> {
    let f = |kr: f64| study.value(metric, kf, kr) - target;
    let (mut x0, mut x1) = (kr0, kr0 * 1.02);
    let (mut f0, mut f1) = (f(x0), f(x1));
    for _ in 0..30 {
        if !f1.is_finite() || !f0.is_finite() {
            return None;
        }
        if f1.abs() <= tol {
            return Some(x1);
        }
        let s = (f1 - f0) / (x1 - x0);
        if s == 0.0 || !s.is_finite() {
            return None;
        }
        let x2 = (x1 - f1 / s).clamp(0.5 * x1, 2.0 * x1);
        (x0, f0) = (x1, f1);
        x1 = x2;
        f1 = f(x1);
    }
    None
}

/// The best combination on the `metric` = `target` curve: closest to
/// `reference`. Starts from the closest curve point of the map and refines
/// over k1 within ± `span` by golden-section search with k2 solved by
/// simulation, held to the map's `bounds`: k1 within its front range, and a
/// k2 beyond its rear range costed above any inside it (growing with the
/// excess, so the search turns back to the map).
pub(crate) fn best_on_curve(
    study: &Study,
    metric: Metric,
    curve: &[(f64, f64)],
    bounds: MapBounds,
    reference: (f64, f64),
    (target, span): (f64, f64),
) -> Option<Best> {
    let start = *curve
        .iter()
        .min_by(|a, b| distance(**a, reference).total_cmp(&distance(**b, reference)))?;
    let tol = 1e-6 * target.abs().max(1e-9);
    // Off the map's rear range: above every distance a point on it has.
    const OFF_MAP: f64 = 1e6;
    let cost = |kf: f64| {
        solve_rear(study, metric, kf, start.1, (target, tol)).map_or(
            (f64::INFINITY, f64::NAN),
            |kr| {
                let excess = bounds.rear_excess(kr);
                let off = if excess > 0.0 { OFF_MAP + excess } else { 0.0 };
                (distance((kf, kr), reference) + off, kr)
            },
        )
    };
    let (mut lo, mut hi) = (
        (start.0 - span).max(bounds.front.0),
        (start.0 + span).min(bounds.front.1),
    );
    golden_section(&mut lo, &mut hi, |kf| cost(kf).0);
    let kf = 0.5 * (lo + hi);
    let (d, kr) = cost(kf);
    d.is_finite().then(|| Best {
        k_front: kf,
        k_rear: kr,
        value: study.value(metric, kf, kr),
        edge: bounds.edge((kf, kr)),
    })
}

/// Golden-section iterations of [`best_on_curve`]: the interval shrinks to
/// 0.618^25 ≈ 6e-6 of its width.
const GOLDEN_ITERATIONS: usize = 25;

/// Narrows `[lo, hi]` onto a minimum of `cost` by golden-section search,
/// one new evaluation per iteration: the interior point kept from the last
/// iteration is the golden ratio's other point of the narrowed interval
/// (`g² = 1 − g`), so its cost is reused, not re-simulated. Each cost is a
/// secant solve of several simulations, and evaluating both interior
/// points afresh every iteration doubled the inverse's simulations. The
/// interval is narrowed as before: only the kept point's position differs,
/// by rounding.
pub(crate) fn golden_section(lo: &mut f64, hi: &mut f64, cost: impl Fn(f64) -> f64) {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut m1, mut m2) = (*hi - g * (*hi - *lo), *lo + g * (*hi - *lo));
    let (mut c1, mut c2) = (cost(m1), cost(m2));
    for i in 1..=GOLDEN_ITERATIONS {
        let more = i < GOLDEN_ITERATIONS;
        if c1 < c2 {
            *hi = m2;
            if more {
                (m2, c2) = (m1, c1);
                m1 = *hi - g * (*hi - *lo);
                c1 = cost(m1);
            }
        } else {
            *lo = m1;
            if more {
                (m1, c1) = (m2, c2);
                m2 = *lo + g * (*hi - *lo);
                c2 = cost(m2);
            }
        }
    }
}
