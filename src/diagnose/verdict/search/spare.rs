//! A greedy step cross-validates only the sets its pick can still read.
//!
//! The step ([`super::greedy`]) reads its sets' held-out errors in one
//! place: the pick ([`rules::pick`], and [`rules::simpler_than`] for the
//! set it passes over), which reads the best set whose axles are a tyre
//! and the sets within [`PARSIMONY`] noise levels of it, or, that one
//! being pressed on a search bound, those within its look-alike window
//! ([`rules::may_be_read`]). A set whose held-out error cannot come that
//! near is not read, whatever it turns out to be.
//!
//! The bound. A set `S` extends the current set `C` by one effect; its fit
//! on all runs removes `x` % of the in-sample gap above noise `C` leaves
//! ([`Baseline::insample_extra`], known before any fold is refitted). The
//! screening's premise ([`crate::diagnose::verdict::screening`]; the
//! greedy additions are screened on it, with `C` in the base model's
//! place) is that its held-out share of what `C` leaves is at most
//! `x + `[`SCREEN_MARGIN`]. So its held-out gap above noise is at least
//! `G_S ≥ (1 − (x + SCREEN_MARGIN)/100)·G_C` (`G_C` the gap `C` leaves
//! held out, at most all of it removed), and its held-out error at least
//! `J_S ≥ √(G_S² + J_n²)`: its floor. The sets are cross-validated best
//! floor first, a few at a time (as many as the pool has threads, so
//! that no core waits); after each batch the best set read so far sets
//! the bar, and a set whose floor lies beyond it is not cross-validated.
//! The bar only falls as sets are added, so a set spared stays spared,
//! and the pick and what it passes over are those of every set
//! cross-validated (the unit test of [`rules::may_be_read`] holds this
//! against the pick itself).
//!
//! What else reads the step's rows is served where it does
//! ([`super::concluded`]): a set spared is still a set tried (the pairs
//! fallback does not fit it again), is cross-validated after all where
//! the search ends without a verdict (the refusal's words read every
//! row) or where it is a twin of the verdict (the verdict's set with
//! another first effect, which the report reads back), and is otherwise
//! reported with its floor and the bar it missed.
//!
//! Units: J dimensionless, shares in percent.

use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::gap_above;
use crate::diagnose::report::{Outranked, Screened};
use crate::diagnose::verdict::baseline::Baseline;
#[cfg(doc)]
use crate::diagnose::verdict::rules::PARSIMONY;
use crate::diagnose::verdict::rules::{self, Candidate, Reading, SCREEN_MARGIN};
use crate::diagnose::verdict::score::{Context, Fitted, Scored};
use crate::diagnose::verdict::screening::screened_row;
use crate::diagnose::verdict::search::Search;
use rayon::prelude::*;

/// A set a greedy step did not cross-validate, kept until the search ends.
pub(crate) struct Spared<'a> {
    /// Where its row would have joined the search's rows (the length of
    /// `combinations` after its step's rows).
    pub(crate) at: usize,
    /// Its fit on all runs, cross-validated after all where it must be.
    pub(crate) fitted: Fitted<'a>,
    /// Its report row: its in-sample share of what the set it extends
    /// leaves, its floor and the bar.
    pub(crate) row: Screened,
}

/// The least held-out error (J) of a set whose fit on all runs removes
/// `extra` % of the in-sample gap above noise the set it extends leaves,
/// that set leaving `g_current` held out (gap above noise) at noise level
/// `jn`: the screening's margin added, at most all of it removed.
pub(crate) fn floor(extra: f64, g_current: f64, jn: f64) -> f64 {
    let g = (1.0 - (extra + SCREEN_MARGIN).min(100.0) / 100.0) * g_current;
    (g * g + jn * jn).sqrt()
}

/// What the pick reads first of `scored` ([`rules::reading`]).
fn read_of<'s>(scored: impl Iterator<Item = &'s Scored>, base: &Baseline) -> Option<Reading> {
    let ranked: Vec<Candidate> = scored.map(|sc| base.candidate(sc)).collect();
    rules::reading(&ranked, base.jn)
}

/// The best of `scored` whose axles are a tyre and whose every effect
/// contributes: its effects and held-out error.
pub(crate) fn best_read<'s>(
    scored: impl Iterator<Item = &'s Scored>,
    base: &Baseline,
) -> Option<(&'s [EffectKind], f64)> {
    scored
        .map(|sc| (sc, base.candidate(sc)))
        .filter(|(_, c)| !c.degenerate && !c.inert)
        .min_by(|a, b| a.1.heldout.total_cmp(&b.1.heldout))
        .map(|(sc, c)| (sc.kinds.as_slice(), c.heldout))
}

/// A greedy step's sets (`fitted`, each `current` with one effect added)
/// cross-validated where the pick can read them (every one without
/// `screening`, or where `current` leaves no in-sample gap to bound them
/// by): the scored ones, and the others with their in-sample share and
/// floor, in the order they came.
pub(crate) fn cross_validated<'a>(
    ctx: &Context<'a>,
    base: &Baseline,
    current: &Scored,
    fitted: Vec<Fitted<'a>>,
    screening: bool,
) -> (Vec<Scored>, Vec<(Fitted<'a>, f64, f64)>) {
    let all = |f: Vec<Fitted<'a>>| -> Vec<Scored> {
        f.par_iter().map(|f| ctx.cross_validate(f)).collect()
    };
    let extra: Option<Vec<f64>> = fitted
        .iter()
        .map(|f| base.insample_extra(&current.insample, &f.insample))
        .collect();
    let (true, Some(extra)) = (screening, extra) else {
        return (all(fitted), Vec::new());
    };
    let jn = base.jn;
    let g_current = gap_above(current.heldout.combined(&base.scales()), jn);
    let floors: Vec<f64> = extra.iter().map(|&x| floor(x, g_current, jn)).collect();
    let mut order: Vec<usize> = (0..fitted.len()).collect();
    order.sort_by(|&a, &b| floors[a].total_cmp(&floors[b]));
    // Pressed on a search bound or not: the fit on all runs says.
    let pressed: Vec<bool> = fitted
        .iter()
        .map(|f| base.candidate(&f.unscored()).pressed)
        .collect();
    let batch = rayon::current_num_threads().max(1);
    let mut scored: Vec<(usize, Scored)> = Vec::new();
    let mut left = order;
    loop {
        let read = read_of(scored.iter().map(|(_, s)| s), base);
        let (take, rest): (Vec<usize>, Vec<usize>) = left
            .iter()
            .copied()
            .partition(|&i| rules::may_be_read(floors[i], pressed[i], read, jn));
        if take.is_empty() {
            break;
        }
        // The lowest floors first; the others wait for the next reading.
        let (now, later) = take.split_at(take.len().min(batch));
        left = later.iter().chain(&rest).copied().collect();
        left.sort_by(|&a, &b| floors[a].total_cmp(&floors[b]));
        let done: Vec<(usize, Scored)> = now
            .par_iter()
            .map(|&i| (i, ctx.cross_validate(&fitted[i])))
            .collect();
        scored.extend(done);
    }
    let read: Vec<usize> = scored.iter().map(|(i, _)| *i).collect();
    scored.sort_by_key(|(i, _)| *i);
    let spared = fitted
        .into_iter()
        .enumerate()
        .filter(|(i, _)| !read.contains(i))
        .map(|(i, f)| (f, extra[i], floors[i]))
        .collect();
    (scored.into_iter().map(|(_, s)| s).collect(), spared)
}

/// The report row of a set spared by a greedy step from `current` (its
/// in-sample share `extra` of what `current` leaves, its `floor`), the
/// bar being the step's best set the pick read first (`best`: its
/// effects and held-out error).
pub(crate) fn spared_row(
    f: &Fitted,
    (extra, floor): (f64, f64),
    current: &[EffectKind],
    best: Option<(&[EffectKind], f64)>,
    base: &Baseline,
) -> Screened {
    let mut row = screened_row(&f.unscored(), extra, Some(current), base);
    row.outranked = best.map(|(by, heldout_error)| Outranked {
        by: by.to_vec(),
        heldout_error,
        floor,
    });
    row
}

/// The spared sets at the search's end (`out`, its verdict settled):
/// without a verdict every one is cross-validated after all, and with
/// one those that are its twins (its set with another first effect, which
/// the report reads back from the rows); each joins the rows where its
/// step's did, so that the first tried of a set is still the row kept.
/// The others are reported as spared, their folds counted as done.
pub(super) fn settled(ctx: &Context, base: &Baseline, out: &mut Search) {
    let spared = std::mem::take(&mut out.spared);
    let twin = |k: &[EffectKind]| match &out.chosen {
        None => true,
        Some(c) => {
            c.kinds.len() > 1
                && k.len() == c.kinds.len()
                && c.kinds[1..].iter().all(|e| k.contains(e))
        }
    };
    let (read, kept): (Vec<Spared>, Vec<Spared>) =
        spared.into_iter().partition(|s| twin(&s.row.effects));
    let scored: Vec<(usize, Scored)> = read
        .par_iter()
        .map(|s| (s.at, ctx.cross_validate(&s.fitted)))
        .collect();
    // Ascending positions, each shifted by the rows inserted before it.
    for (n, (at, sc)) in scored.into_iter().enumerate() {
        out.combinations.insert(at + n, base.rank(&sc));
    }
    for s in kept {
        if let Some(rec) = ctx.timing {
            rec.candidate(false);
        }
        for _ in 0..ctx.folds.len() {
            ctx.tick();
        }
        out.screened.push(s.row);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn a_sets_floor_is_the_gap_left_after_its_in_sample_share_and_the_margin() {
        // 20 % in sample, 30 % with the margin: 0.7 of a gap of 4.
        let j = floor(20.0, 4.0, 1.0);
        assert!((j - (2.8f64 * 2.8 + 1.0).sqrt()).abs() < 1e-12, "{j}");
        // At most all of the gap removed: the noise alone.
        assert_eq!(floor(95.0, 4.0, 1.0), 1.0);
        // A set worse in sample than the one it extends: above its gap.
        assert!(floor(-30.0, 4.0, 1.0) > (17.0f64).sqrt());
    }

    use crate::diagnose::verdict::rules::{may_be_read, pick, reading, simpler_than, window};

    fn cand(heldout: f64, parameters: usize, idle: bool, degenerate: bool) -> Candidate {
        Candidate {
            heldout,
            parameters,
            idle,
            degenerate,
            pressed: false,
            inert: false,
        }
    }

    fn pressed(c: Candidate) -> Candidate {
        Candidate { pressed: true, ..c }
    }

    /// The pick and what it passes over (their held-out errors), of
    /// `ranked` with `extra` among them.
    fn read_with(ranked: &[Candidate], extra: Option<Candidate>, jn: f64) -> [Option<f64>; 2] {
        let mut all = ranked.to_vec();
        all.extend(extra);
        all.sort_by(|a, b| a.heldout.total_cmp(&b.heldout));
        let at = |k: Option<usize>| k.map(|k| all[k].heldout);
        [at(pick(&all, jn)), at(simpler_than(&all, jn))]
    }

    #[test]
    fn a_set_the_pick_cannot_read_is_spared_and_one_it_can_is_not() {
        let jn = 1.0;
        let read = |ranked: &[Candidate]| reading(ranked, jn);
        // The best 2.0, not pressed: read up to 2.0 + PARSIMONY·jn.
        let plain = read(&[cand(2.0, 5, false, false)]);
        assert!(may_be_read(2.1, false, plain, jn));
        assert!(!may_be_read(2.1 + 1e-9, false, plain, jn));
        assert!(!may_be_read(2.1 + 1e-9, true, plain, jn));
        // Nothing read yet: everything can be.
        assert!(may_be_read(50.0, false, None, jn));
        // The best pressed, none inside its window: a set not pressed is
        // read up to the window (gap bound 1.5·√3 + 0.25 = 2.848, J =
        // √(2.848² + 1) = 3.019); a pressed one only as near as the best.
        let lone = read(&[pressed(cand(2.0, 5, false, false))]);
        let bound = (window(3f64.sqrt(), jn).bound.powi(2) + 1.0).sqrt();
        assert!((bound - 3.0185).abs() < 1e-3, "{bound}");
        assert!(may_be_read(bound - 1e-9, false, lone, jn));
        assert!(!may_be_read(bound + 1e-9, false, lone, jn));
        assert!(!may_be_read(2.5, true, lone, jn));
        // One inside the window (2.5): the pick reads it, and a set not
        // pressed only as near as it.
        let inside = read(&[
            pressed(cand(2.0, 5, false, false)),
            cand(2.5, 5, false, false),
        ]);
        assert!(may_be_read(2.6, false, inside, jn));
        assert!(!may_be_read(2.6 + 1e-9, false, inside, jn));
        // Against the pick itself: a set spared, given any held-out error
        // at or above its floor and any other flags, leaves the pick and
        // what it passes over as they were.
        let steps = [
            vec![cand(2.0, 5, true, false), cand(2.05, 4, false, false)],
            vec![
                pressed(cand(2.0, 5, false, false)),
                cand(2.9, 6, true, false),
            ],
            vec![cand(1.5, 5, false, true), cand(2.0, 5, true, false)],
            vec![pressed(cand(2.0, 5, true, false))],
            vec![
                pressed(cand(2.0, 5, false, false)),
                cand(2.2, 6, false, false),
            ],
        ];
        let mut spared = 0;
        for ranked in &steps {
            let alone = read_with(ranked, None, jn);
            for floor in [2.0, 2.1, 2.2, 2.3, 2.5, 3.0, 3.1, 4.0] {
                for own in [false, true] {
                    if may_be_read(floor, own, read(ranked), jn) {
                        continue;
                    }
                    spared += 1;
                    for (idle, degenerate, inert) in
                        (0..8).map(|b| (b & 1 > 0, b & 2 > 0, b & 4 > 0))
                    {
                        for j in [floor, floor + 0.05, floor + 1.0] {
                            let extra = Candidate {
                                pressed: own,
                                inert,
                                ..cand(j, 1, idle, degenerate)
                            };
                            let with = read_with(ranked, Some(extra), jn);
                            assert_eq!(with, alone, "{ranked:?}: {extra:?}");
                        }
                    }
                }
            }
        }
        assert!(spared >= 20, "{spared}");
        // One the rule reads can move the pick: a simpler set within the
        // parsimony window of an idle best is taken instead.
        let ranked = &steps[0];
        assert!(may_be_read(2.08, false, read(ranked), jn));
        let extra = cand(2.08, 1, false, false);
        assert_ne!(
            read_with(ranked, Some(extra), jn),
            read_with(ranked, None, jn)
        );
    }
}
