//! The search's report rows tidied: one row per set of effects whatever
//! the order it was built in, and a warning on each set that fits the runs
//! worse in sample than a set it contains. Errors dimensionless (residuals
//! over channel scales).

use crate::diagnose::effects::{joined, set_of, EffectKind};
use crate::diagnose::report::{RankWarning, Ranked};
use crate::diagnose::verdict::score::Scored;

/// Relative excess of a set's in-sample error over that of a set it
/// contains past which it is warned of: above the stopping tolerance of
/// the fits (their costs agree to about 1e-6), below what a parameter held
/// at its off value may cost (up to χ²₁ = 3.84 residual variances).
const WORSE_IN_SAMPLE: f64 = 1e-3;

/// Warns of each set in `combinations` that fits the runs worse in sample
/// than a set it contains (a single of `singles`, a set `spared` with its
/// in-sample error, or another of the sets):
/// it contains that set's optimum with its other effects off, so its fit
/// stopped short of it, or held a parameter the smaller set fits, and its
/// scores understate the set.
pub(super) fn worse_than_subsets(
    singles: &[&Scored],
    spared: &[(Vec<EffectKind>, f64)],
    scales: &[f64; 3],
    combinations: &mut [Ranked],
) {
    let subsets: Vec<(Vec<EffectKind>, f64)> = singles
        .iter()
        .map(|s| (s.kinds.clone(), s.insample.combined(scales)))
        // A set a greedy step spared is still a set fitted.
        .chain(spared.iter().cloned())
        .chain(
            combinations
                .iter()
                .map(|c| (c.effects.clone(), c.insample_error_after)),
        )
        .collect();
    for c in combinations.iter_mut() {
        if let Some((k, e)) = better_subset(&c.effects, c.insample_error_after, &subsets) {
            c.warnings.push(RankWarning::WorseThanSubset {
                subset: joined(k, "+"),
                subset_error: e,
                error: c.insample_error_after,
            });
        }
    }
}

/// Of `subsets` (sets and their in-sample errors), the one with the least
/// error among those `set` strictly contains, where `set`'s own `error`
/// exceeds it by more than [`WORSE_IN_SAMPLE`].
fn better_subset<'a>(
    set: &[EffectKind],
    error: f64,
    subsets: &'a [(Vec<EffectKind>, f64)],
) -> Option<(&'a [EffectKind], f64)> {
    subsets
        .iter()
        .filter(|(k, _)| k.len() < set.len() && k.iter().all(|e| set.contains(e)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .filter(|(_, e)| error > e * (1.0 + WORSE_IN_SAMPLE))
        .map(|(k, e)| (k.as_slice(), *e))
}

/// Keeps one row per set of effects: the greedy searches from the best
/// single and from its look-alikes try a pair in both orders
/// (`steer_path+sensor_delay`, `sensor_delay+steer_path`), and a set is one
/// candidate whatever the order it was built in. The row kept is the
/// chosen set's own (its order, the numbers the verdict states) where it
/// is one of them, else the first tried.
pub(super) fn one_row_per_set(rows: &mut Vec<Ranked>, chosen: Option<&[EffectKind]>) {
    // Stable: the chosen set's row moves ahead of its other orders only.
    rows.sort_by_key(|r| Some(r.effects.as_slice()) != chosen);
    let mut seen = std::collections::HashSet::new();
    rows.retain(|r| seen.insert(set_of(&r.effects)));
}

#[cfg(test)]
mod tests {
    use super::*;
    use EffectKind::{RelaxationLength as R, SensorDelay as D, SteerPath as S};

    #[test]
    fn a_set_worse_in_sample_than_one_it_contains_is_found_with_the_best_such() {
        let subsets = vec![
            (vec![D], 2.0),
            (vec![R], 1.5),
            (vec![S], 0.5),
            (vec![D, R], 1.2),
        ];
        // D+R+S contains S (0.5), the best of its subsets.
        let found = better_subset(&[D, R, S], 0.9, &subsets).unwrap();
        assert_eq!(found, (&[S][..], 0.5));
        // D+R contains D and R, not itself nor S: 1.2 is better than both.
        assert_eq!(better_subset(&[D, R], 1.2, &subsets), None);
        assert_eq!(better_subset(&[R, D], 1.6, &subsets), Some((&[R][..], 1.5)));
        // Within the fits' tolerance it is no worse.
        assert_eq!(better_subset(&[D, R], 1.5 * (1.0 + 1e-4), &subsets), None);
        // A single contains no smaller set.
        assert_eq!(better_subset(&[S], 9.0, &subsets), None);
    }
}
