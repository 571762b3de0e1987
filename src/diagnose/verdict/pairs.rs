//! The pairs of the best singles in sample, tried where the search from
//! the best single on held-out runs (and from its look-alikes) ends on no
//! accepted set.
//!
//! Why. The greedy search ([`super::search`]) pairs every effect with the
//! best single only. Where an effect that is not part of the truth mimics
//! half of it best (a relaxation length standing for a sensor delay beside
//! a yaw inertia the vehicle file states 1.5× too large), the pair the
//! truth is never formed: the best single's pairs all stop short of
//! acceptance, and the verdict called a model-form error outside the
//! library. The pairs of the [`PAIRED`] singles that remove most of the
//! in-sample gap (each lowering the BIC, [`rules::pairable`]) are formed
//! too, those the search already tried left out: at most
//! `PAIRED·(PAIRED − 1)/2` = 6 more sets, 3 where the best single is among
//! them (its pairs were all tried), each fitted and cross-validated as the
//! greedy search's are. The best of them by the
//! rules of the greedy step ([`rules::pick`]) that passes as a whole
//! ([`rules::accepted`] against the base model) starts a greedy search of
//! its own, and the set it ends on is the verdict where it passes.
//! Verdicts the search reaches are untouched: the pairs are tried only
//! where it reached none.
//!
//! Units: J dimensionless, reductions in percent; the method is the
//! project's own.

use crate::diagnose::effects::{set_of, EffectKind};
use crate::diagnose::model::channels::reduction;
use crate::diagnose::report::Ranked;
use crate::diagnose::verdict::baseline::Baseline;
use crate::diagnose::verdict::rules::{self, Candidate, PAIRED};
use crate::diagnose::verdict::score::{Context, Fitted, Scored, Started};
use rayon::prelude::*;

/// A candidate the search passed over for a simpler one within the
/// parsimony window ([`rules::simpler_than`]), and the one it took.
#[derive(Clone)]
pub(crate) struct Simpler {
    /// Passed over: it leaves a parameter idle.
    pub(crate) over: Scored,
    /// Taken in its place: fewer parameters, within [`rules::PARSIMONY`]
    /// noise levels of its held-out error.
    pub(crate) taken: Scored,
}

/// Where the verdict came from the pairs of the best singles in sample:
/// the set the greedy search from the best single (and its look-alikes)
/// ended on with no verdict, the pair taken, and the singles paired.
#[derive(Clone)]
pub(crate) struct Fallback {
    /// The set the greedy search ended on, refused.
    pub(crate) ended: Scored,
    /// The pair that passed and started the search that reached the
    /// verdict.
    pub(crate) pair: Scored,
    /// The best singles in sample whose pairs were formed, best first.
    pub(crate) from: Vec<EffectKind>,
}

/// Of `all` (indices into `singles`, cross-validated and screened), the
/// [`PAIRED`] that remove most of the in-sample gap and lower the BIC,
/// best first.
fn best_in_sample(singles: &[Scored], all: &[usize], base: &Baseline) -> Vec<usize> {
    let mut ranked: Vec<(usize, f64)> = all
        .iter()
        .map(|&i| (i, base.insample_reduction(&singles[i].insample)))
        .filter(|&(i, r)| rules::pairable(r, singles[i].full.bic() - base.bic0()))
        .collect();
    ranked.sort_by(|a, b| b.1.total_cmp(&a.1));
    ranked.into_iter().take(PAIRED).map(|(i, _)| i).collect()
}

/// The pairs of `best` (effects, best first) whose sets the search has not
/// tried (`tried`), each as its two places in `best`, the better first.
fn untried(best: &[EffectKind], tried: &[Vec<EffectKind>]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    for a in 0..best.len() {
        for b in a + 1..best.len() {
            let set = set_of(&[best[a], best[b]]);
            if !tried.iter().any(|t| set_of(t) == set) {
                pairs.push((a, b));
            }
        }
    }
    pairs
}

/// The untried pairs of the best singles in sample (`all` indexing
/// `singles`), each started by `extend` (the greedy step's starts of a
/// single extended by an effect), fitted, cross-validated and added to
/// `combinations` (the search's rows so far, read for the sets tried, with
/// the sets the greedy steps `spared`); the
/// one to take ([`rules::pick`]) where
/// it passes as a whole against the base model, with the pair it was taken
/// over for parsimony ([`rules::simpler_than`]), if any, and the best
/// singles in sample whose pairs were formed, best first.
pub(crate) fn paired<'a>(
    ctx: &Context<'a>,
    (singles, all): (&[Scored], &[usize]),
    base: &Baseline,
    (combinations, spared): (&mut Vec<Ranked>, &[Vec<EffectKind>]),
    extend: impl Fn(&Scored, EffectKind) -> Vec<Started<'a>> + Sync,
) -> Option<(Scored, Option<Simpler>, Vec<EffectKind>)> {
    let best = best_in_sample(singles, all, base);
    let tried: Vec<Vec<EffectKind>> = (combinations.iter().map(|r| r.effects.clone()))
        .chain(spared.iter().cloned())
        .collect();
    let kinds: Vec<EffectKind> = best.iter().map(|&i| singles[i].kinds[0]).collect();
    let pairs = untried(&kinds, &tried);
    if pairs.is_empty() {
        return None;
    }
    let fitted: Vec<Fitted> = pairs
        .par_iter()
        .flat_map(|&(a, b)| extend(&singles[best[a]], kinds[b]))
        .map(|s| ctx.polish(s))
        .collect();
    let scales = base.scales();
    let mut scored: Vec<Scored> = fitted.par_iter().map(|f| ctx.cross_validate(f)).collect();
    scored.sort_by(|a, b| {
        a.heldout
            .combined(&scales)
            .total_cmp(&b.heldout.combined(&scales))
    });
    combinations.extend(scored.iter().map(|sc| base.rank(sc)));
    let ranked: Vec<Candidate> = scored.iter().map(|sc| base.candidate(sc)).collect();
    let k = rules::pick(&ranked, base.jn)?;
    let over = rules::simpler_than(&ranked, base.jn).map(|t| scored[t].clone());
    let pair = scored.swap_remove(k);
    let total = reduction(base.j0, pair.heldout.combined(&scales), base.jn);
    let over = over.map(|over| Simpler {
        over,
        taken: pair.clone(),
    });
    rules::accepted(total, pair.full.bic(), base.bic0()).then_some((pair, over, kinds))
}

#[cfg(test)]
mod tests {
    use super::*;
    use EffectKind::{RelaxationLength as R, SensorDelay as D, SteerPath as S, YawInertia as I};

    #[test]
    fn the_pairs_left_are_those_of_the_best_singles_the_search_did_not_try() {
        // The search paired the best (R) with every effect, in any order.
        let tried = vec![vec![R, S], vec![D, R], vec![R, I]];
        assert_eq!(untried(&[R, S, D, I], &tried), [(1, 2), (1, 3), (2, 3)]);
        // Nothing tried: every pair once, the better first.
        assert_eq!(untried(&[D, I, R], &[]), [(0, 1), (0, 2), (1, 2)]);
        assert!(untried(&[R], &[]).is_empty());
        assert!(untried(&[R, D], &[vec![D, R]]).is_empty());
    }
}
