//! Wang & Liang's (2009) RBF network Er → (k1, k2) of a study: trained
//! on the `[rbf]` pairs that reached a steady state (an Er), all but the
//! validation ones, and checked by re-simulating its answers. Stiffness in
//! N/rad inside, reported per the study's unit; Er in s.

use super::{RbfReport, Validation};
use crate::error::{Error, InputError};
use crate::io::study::RbfInput;
use crate::study::rbf::Rbf;
use crate::study::{Metric, Sample, StiffnessUnit, Study};
use std::path::Path;

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
