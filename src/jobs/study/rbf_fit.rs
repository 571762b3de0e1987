//! Wang & Liang's (2009) RBF network Er → (k1, k2) of a study: trained
//! on the `[rbf]` pairs that reached a steady state (an Er), all but the
//! validation ones, and checked by re-simulating its answers. Stiffness in
//! N/rad inside, reported per the study's unit; Er in s.
//!
//! Whether it interpolates ([`RbfFit`]): `newrbe`'s network passes through
//! its pairs, but with the paper's spread of 2 s against Er values about
//! 0.01 s apart its design is numerically singular (condition number 1e17,
//! past double precision's 1e16), the solve keeps only the directions above
//! [`RCOND`] of the largest, and the network is a least-squares fit that
//! misses its own pairs (by 21 N/deg on the book's coarse study). That is
//! said, with the spread from which down it would interpolate; its answers
//! are then to be judged by their re-simulated Er, not by the network.

use super::{RbfReport, Validation};
use crate::error::{Error, InputError};
use crate::io::study::RbfInput;
use crate::study::rbf::{Rbf, RCOND};
use crate::study::{Metric, Sample, StiffnessUnit, Study};
use serde::Serialize;
use std::path::Path;

/// What the trained network is, by the directions its solve kept.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RbfFit {
    /// Every direction kept (condition number at most `1/RCOND`): it
    /// passes through its training pairs, as `newrbe`'s does.
    Interpolant,
    /// Some dropped (condition number above `1/RCOND`): a least-squares
    /// fit through the directions kept, which misses its own pairs.
    Regression,
}

impl RbfReport {
    /// The note on a network that is a regression, with what it means for
    /// its answers and what makes it an interpolant; None for an
    /// interpolant.
    pub(super) fn regression_note(&self) -> Option<String> {
        if self.fit == RbfFit::Interpolant {
            return None;
        }
        let u = self.unit;
        let limit = 1.0 / RCOND;
        let digits = match self.condition_number > 1e16 {
            true => ", beyond double precision's 1e16: its smallest singular values are rounding",
            false => "",
        };
        let spread = match self.interpolating_spread {
            Some(s) => {
                // The pairs' Er, from the prediction drawn over it.
                let er = match (self.prediction.first(), self.prediction.last()) {
                    (Some(a), Some(b)) => {
                        format!(", against the pairs' Er of {:.3}–{:.3} s,", a[0], b[0])
                    }
                    _ => String::new(),
                };
                format!(
                    "a spread of {} s or less{er} keeps every direction and makes it an interpolant; fewer pairs, farther apart in Er, allow a wider one",
                    crate::format::significant(floor_two_digits(s), 2),
                )
            }
            None => "no spread makes it an interpolant: pairs share an Er".into(),
        };
        let worst = (self.validation.iter()).map(|v| v.error_percent).fold(
            None,
            |w: Option<f64>, e| match w {
                Some(w) if w.abs() >= e.abs() => Some(w),
                _ => Some(e),
            },
        );
        let judged = match worst {
            Some(w) => format!("the validation's re-simulated Er, off by {w:+.2} % at worst"),
            None => "their re-simulated Er (no pair is held out to validate it)".into(),
        };
        Some(format!(
            "the network is a regression, not an interpolant: its condition number is above {limit:.0e} (where its solve drops a direction as rounding){digits}, so the solve kept {} of its {} directions and the network passes up to {:.3} {u} from its own pairs, where Wang & Liang's newrbe passes through them; its answers, within its pairs' Er and the map, are a smooth fit's and as good as {judged} (an interpolant need not validate better); {spread}",
            self.directions_kept, self.training_pairs, self.largest_training_misfit
        ))
    }
}

/// `v` > 0 rounded down to two significant digits: a spread said as one
/// that keeps every direction must not round up past the one found.
fn floor_two_digits(v: f64) -> f64 {
    let m = 10f64.powf(v.log10().floor() - 1.0);
    (v / m).floor() * m
}

/// Training pairs with an Er an RBF network needs.
const MIN_TRAINING_PAIRS: usize = 2;

/// Wang & Liang's RBF network Er → (k1, k2), trained on all pairs but the
/// validation ones and checked by re-simulating its answers.
pub(super) fn train(
    st: &Study,
    r: &RbfInput,
    pairs: &[Sample],
    k: f64,
    unit: StiffnessUnit,
    path: &Path,
) -> Result<(Rbf, RbfReport), Error> {
    let er: Vec<f64> = pairs.iter().map(|s| Metric::Er.of_sample(s)).collect();
    let train: Vec<usize> = (0..pairs.len())
        .filter(|i| !r.validation.contains(i) && er[*i].is_finite())
        .collect();
    // Two centres at least: an RBF through one point, or none, has no
    // shape (nalgebra's SVD of an empty matrix panicked here).
    if train.len() < MIN_TRAINING_PAIRS {
        return Err(InputError::TooFewRbfPairs {
            path: path.to_path_buf(),
            usable: train.len(),
            training: (0..pairs.len())
                .filter(|i| !r.validation.contains(i))
                .count(),
            min: MIN_TRAINING_PAIRS,
        }
        .into());
    }
    let train_er: Vec<f64> = train.iter().map(|&i| er[i]).collect();
    let net = Rbf::train(
        &train_er,
        &train
            .iter()
            .map(|&i| vec![pairs[i].k_front, pairs[i].k_rear])
            .collect::<Vec<_>>(),
        r.spread,
    );
    let misfit = train
        .iter()
        .map(|&i| {
            let p = net.predict(er[i]);
            ((p[0] - pairs[i].k_front) / k)
                .abs()
                .max(((p[1] - pairs[i].k_rear) / k).abs())
        })
        .fold(0.0, f64::max);
    let validation = r
        .validation
        .iter()
        .map(|&i| {
            let p = net.predict(er[i]);
            let er_sim = st.er(p[0], p[1]);
            Validation {
                er_target: er[i],
                k_front_true: pairs[i].k_front / k,
                k_rear_true: pairs[i].k_rear / k,
                k_front_predicted: p[0] / k,
                k_rear_predicted: p[1] / k,
                er_resimulated: er_sim,
                error_percent: 100.0 * (er_sim - er[i]) / er[i],
            }
        })
        .collect();
    let prediction = prediction_curve(&net, &train_er, k);
    let report = RbfReport {
        spread: r.spread,
        training_pairs: train.len(),
        condition_number: net.condition,
        directions_kept: net.kept,
        fit: match net.kept < train.len() {
            true => RbfFit::Regression,
            false => RbfFit::Interpolant,
        },
        interpolating_spread: Rbf::interpolating_spread(&train_er),
        largest_training_misfit: misfit,
        validation,
        unit,
        prediction,
    };
    Ok((net, report))
}

/// The network's answer over its training range of Er (`er`, the training
/// pairs' values), for rbf.png: 200 points of `[Er, k_front, k_rear]` with
/// the stiffnesses in units of `k`, none where the range is a point. Apart
/// from [`train`] so that it reads on a screen.
fn prediction_curve(net: &Rbf, er: &[f64], k: f64) -> Vec<[f64; 3]> {
    let (lo, hi) = er
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    (0..200)
        .filter(|_| hi > lo)
        .map(|j| {
            let e = lo + (hi - lo) * f64::from(j) / 199.0;
            let p = net.predict(e);
            [e, p[0] / k, p[1] / k]
        })
        .collect()
}
