//! An evaluation under a bound ([`Problem::residuals_below`]) whose
//! replays stop inside a run: above the bound it returns false after fewer
//! integrated rows than a whole run on each thread; below it, the
//! residuals of an evaluation without a bound, to the bit, every row
//! integrated.

use super::*;
use crate::diagnose::fit::refit::tests::SCALES;
use crate::diagnose::model::replay::tests::sine_runs;
use crate::tyre::{Pac89, Tyre};
use crate::vehicle::{Vehicle, VehicleModel};

/// The compact sedan on PAC89 tyres whose sensors report `p[0]` s late.
fn delayed(p: &[f64]) -> Augmented {
    let pac89 = Tyre::Pac89(Pac89::adams_example());
    let mut m = VehicleModel::new(Vehicle::compact_sedan(), pac89.clone(), pac89);
    m.options.effects.sensors.delay = p[0];
    Augmented::new(m, 1.0)
}

/// Every value of two residual vectors, to the bit.
fn bits(r: &[f64]) -> Vec<u64> {
    r.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn an_evaluation_above_its_bound_stops_inside_a_run() {
    let runs = sine_runs(&delayed(&[0.0]));
    let bounds = vec![(0.0, 0.3)];
    let p = [0.12];
    for set in [&runs[..1], &runs[..]] {
        let problem = || Problem::new(delayed, set.iter().collect(), SCALES, bounds.clone());
        // The whole evaluation: every run replayed, every row.
        let whole = problem();
        let mut r = vec![0.0; whole.count()];
        whole.residuals(&p, &mut r);
        let cost = 0.5 * r.iter().map(|e| e * e).sum::<f64>();
        let all_rows = whole.integrated_rows();
        let one_run = set.iter().map(|run| run.drive.steps + 1).min().unwrap();
        assert_eq!(
            all_rows,
            set.iter().map(|run| run.drive.steps + 1).sum::<usize>()
        );
        // A bound a fiftieth of the cost: false, and stopped before the
        // threads had replayed a run each whole (what a stop between whole
        // runs integrates at least: every thread takes one at the start).
        let stopped = problem();
        let mut out = vec![0.0; whole.count()];
        assert!(!stopped.residuals_below(&p, &mut out, 0.02 * cost));
        let rows = stopped.integrated_rows();
        let threads = rayon::current_num_threads().clamp(1, set.len());
        assert!(
            rows > 0 && rows < threads * one_run,
            "{rows} rows on {threads} threads, {one_run} a run"
        );
        // A bound just above the cost: every row, the residuals to the bit.
        let above = problem();
        assert!(above.residuals_below(&p, &mut out, cost * (1.0 + 1e-5)));
        assert_eq!(bits(&out), bits(&r));
        assert_eq!(above.integrated_rows(), all_rows);
        // Just below it, within the stop's margin: true, as a whole
        // evaluation decides (the caller compares the cost itself).
        let within = problem();
        assert!(within.residuals_below(&p, &mut out, cost * (1.0 - 1e-9)));
        assert_eq!(bits(&out), bits(&r));
        assert_eq!(within.integrated_rows(), all_rows);
    }
}
