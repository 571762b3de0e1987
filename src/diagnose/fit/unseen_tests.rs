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
