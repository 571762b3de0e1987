//! What "no measured channel responds" means: a zero derivative that a
//! step into the box confirms, not one an effect has only at the bound
//! where it switches off (a relaxation length below 1 mm is no lag).

use super::refit::tests::SCALES;
use super::{fit, Polish, Problem};
use crate::diagnose::model::replay::tests::sine_runs;
use crate::diagnose::model::Augmented;
use crate::tyre::{MagicSimple, Tyre};
use crate::vehicle::{Vehicle, VehicleModel};

/// The compact sedan on simplified-Magic-Formula axles with relaxation
/// length `p[0]`, m.
fn lagged(p: &[f64]) -> Augmented {
    let tyre = Tyre::MagicSimple(MagicSimple {
        b: 12.0,
        c: 1.3,
        d: 1.0,
    });
    let mut m = VehicleModel::new(Vehicle::compact_sedan(), tyre.clone(), tyre);
    m.options.effects.relaxation_length = p[0];
    Augmented::new(m, 1.0)
}

#[test]
fn a_relaxation_length_fitted_to_no_lag_is_on_its_bound_not_unseen() {
    let runs = sine_runs(&lagged(&[0.0]));
    let problem = Problem::new(lagged, runs.iter().collect(), SCALES, vec![(0.0, 1.0)]);
    let f = fit(&problem, &[0.0], Some(&[0.0]), Polish::LevenbergMarquardt);
    assert_eq!(f.params, vec![0.0]);
    // The derivative at 0 is zero (no lag below 1 mm), the runs see 1 cm.
    assert_eq!(f.linear.as_ref().unwrap().jacobian.column(0).norm(), 0.0);
    assert!(!f.is_unseen(0), "{:?}", f.unseen);
    assert_eq!(f.free_count(), 1);
    // And a lag of the truth's is found where it is, seen (to the 3 % that
    // the replay's 10 ms steps against the truth's 1 ms leave).
    let runs = sine_runs(&lagged(&[0.4]));
    let problem = Problem::new(lagged, runs.iter().collect(), SCALES, vec![(0.0, 1.0)]);
    let f = fit(&problem, &[0.1], Some(&[0.0]), Polish::LevenbergMarquardt);
    assert!((f.params[0] - 0.4).abs() < 0.012, "{:?}", f.params);
    assert!(!f.is_unseen(0));
}

/// The second derivatives a cross-validation takes leave out an unseen
/// parameter's pairs (the fold refits hold it and zero its columns): 9
/// replays where all pairs of four parameters take 14, the other columns
/// those taken with it to the bit, and a fold refit lands on the same
/// parameters as from the full set with a curvature along the unseen
/// parameter made up (`Σ r·∇²r` strongly negative there).
#[test]
fn an_unseen_parameter_costs_no_second_derivatives_and_moves_no_fold_refit() {
    use super::refit::tests::{axle_model, runs, AXLES};
    use super::refit::{refit, training_rows};
    use super::{complete_curvature, fit_first_order, pair_index, FitOutcome};
    use nalgebra::DVector;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let runs = runs();
    let mut bounds = AXLES.to_vec();
    bounds.push((-1.0, 1.0));
    let replays = AtomicUsize::new(0);
    let counted = |p: &[f64]| {
        replays.fetch_add(1, Ordering::Relaxed);
        axle_model(&p[..3])
    };
    let four = Problem::new(counted, runs.iter().collect(), SCALES, bounds.clone());
    let off = [10.0, 10.0, 1.0, 0.0];
    let (f, at) = fit_first_order(&four, &[10.0, 10.0, 1.0, 0.7], Some(&off));
    assert_eq!(f.unseen, [false, false, false, true]);
    let at = at.expect("linearised");
    let taken = |unseen: &[bool]| {
        let mut l = f.linear.clone().expect("linearised");
        let before = replays.load(Ordering::Relaxed);
        complete_curvature(&four, &at, &mut l, unseen);
        (l, replays.load(Ordering::Relaxed) - before)
    };
    let (mut all, n_all) = taken(&[]);
    let (skipped, n_skipped) = taken(&f.unseen);
    assert_eq!((n_all, n_skipped), (14, 9));
    for a in 0..4 {
        for b in a..4 {
            let (x, y) = (
                all.curvature.column(pair_index(4, a, b)),
                skipped.curvature.column(pair_index(4, a, b)),
            );
            if b == 3 {
                assert!(y.iter().all(|&c| c == 0.0), "pair ({a}, 3)");
            } else {
                assert_eq!(x, y, "pair ({a}, {b})");
            }
        }
    }
    let r = DVector::from_column_slice(&all.residuals);
    all.curvature
        .column_mut(pair_index(4, 3, 3))
        .copy_from(&(-1e3 * &r));
    let fold = Problem::new(
        |p: &[f64]| axle_model(&p[..3]),
        runs.iter().skip(1).collect(),
        SCALES,
        bounds,
    );
    let rows = training_rows(&runs, &[0], 0);
    let from = |linear| FitOutcome {
        linear: Some(linear),
        ..f.clone()
    };
    let (a, b) = (
        refit(&fold, &from(all), &rows),
        refit(&fold, &from(skipped), &rows),
    );
    assert_eq!(a.params, b.params);
    assert!(a.params[..3] != f.params[..3], "the fold did not move");
}

/// A lateral-acceleration offset adds a constant to ay after the
/// dynamics (`Sensors::seen`), so every second derivative with it is zero
/// and the second differences skip it: 9 replays for it beside the
/// yaw-rate and sideslip offsets (which also set each replay's start, and
/// are differenced) and a steering compliance, where all pairs of the four
/// take 14; the other columns the same to the bit. Its columns the full
/// differences find are rounding: under 1e-6 of the compliance's own (an
/// offset that entered the dynamics, or scaled with another parameter,
/// would fail this).
#[test]
fn an_ay_offset_costs_no_second_derivatives_its_differences_being_rounding() {
    use super::curvature::curvature;
    use super::layout::Layout;
    use super::{pair_index, unknown_curvature};
    use crate::diagnose::effects::EffectKind::{SensorBias, SteeringCompliance};
    use crate::optim::local::{Derivatives, Residuals};
    use std::sync::atomic::{AtomicUsize, Ordering};
    let layout = Layout::new(&[SensorBias, SteeringCompliance], false);
    assert_eq!(layout.additive(), [false, true, false, false]);
    let base = lagged(&[0.0]);
    let truth = [0.008, 0.2, 0.004, 0.003];
    let runs = sine_runs(&layout.model(&base, &truth));
    let bounds: Vec<(f64, f64)> = layout.parameters().map(|(_, q)| q.bounds).collect();
    let replays = AtomicUsize::new(0);
    let counted = |p: &[f64]| {
        replays.fetch_add(1, Ordering::Relaxed);
        layout.model(&base, p)
    };
    let problem = Problem::new(counted, runs.iter().collect(), SCALES, bounds).with_layout(
        layout.clone(),
        &base,
        Derivatives::Differences,
    );
    let p = [0.01, 0.1, 0.0, 0.002];
    let mut r0 = vec![0.0; problem.count()];
    problem.residuals(&p, &mut r0);
    let taken = |skip: &[bool]| {
        let before = replays.load(Ordering::Relaxed);
        let c = curvature(&problem, &p, &r0, skip);
        (c, replays.load(Ordering::Relaxed) - before)
    };
    let (all, n_all) = taken(&[]);
    let skip = unknown_curvature(&problem, 4, &[]);
    assert_eq!(skip, [false, true, false, false]);
    let (skipped, n_skipped) = taken(&skip);
    assert_eq!((n_all, n_skipped), (14, 9));
    let largest = all.column(pair_index(4, 3, 3)).amax();
    assert!(largest > 0.0, "the compliance has no curvature");
    for a in 0..4 {
        for b in a..4 {
            let c = pair_index(4, a, b);
            if a != 1 && b != 1 {
                assert_eq!(all.column(c), skipped.column(c), "({a}, {b})");
                continue;
            }
            assert!(skipped.column(c).iter().all(|&x| x == 0.0), "({a}, {b})");
            let rounding = all.column(c).amax();
            assert!(
                rounding < 1e-6 * largest,
                "({a}, {b}): {rounding:e} against {largest:e}"
            );
        }
    }
}
