//! The inverse problem on a full (k1, k2) map: a target value of a metric
//! (Er, or any metric) is met along a curve, not at a point. The curve is
//! traced by linear interpolation of the map along both axes; a set of
//! targets with tolerances selects a region of map points; the best
//! combination under a preference (closest to the current tyres, distances
//! relative to them) starts from the closest curve point and is refined with
//! the simulator itself: k2 solved for the target by secant at each k1, and
//! k1 chosen by golden-section search.

use super::{Metric, Sample, Study, Target};

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

impl Map {
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
/// simulation. Returns (k1, k2, the metric simulated there).
pub(crate) fn best_on_curve(
    study: &Study,
    metric: Metric,
    curve: &[(f64, f64)],
    reference: (f64, f64),
    target: f64,
    span: f64,
) -> Option<(f64, f64, f64)> {
    let start = *curve
        .iter()
        .min_by(|a, b| distance(**a, reference).total_cmp(&distance(**b, reference)))?;
    let tol = 1e-6 * target.abs().max(1e-9);
    let cost = |kf: f64| {
        solve_rear(study, metric, kf, start.1, (target, tol))
            .map_or((f64::INFINITY, f64::NAN), |kr| {
                (distance((kf, kr), reference), kr)
            })
    };
    let (mut lo, mut hi) = (start.0 - span, start.0 + span);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..25 {
        let (m1, m2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if cost(m1).0 < cost(m2).0 {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    let kf = 0.5 * (lo + hi);
    let (d, kr) = cost(kf);
    d.is_finite().then(|| (kf, kr, study.value(metric, kf, kr)))
}
