//! The rules that choose the verdict, as pure functions of a few numbers:
//! held-out and in-sample reductions of the gap above noise (%), held-out
//! errors J and the noise level J_n (dimensionless), BIC differences,
//! parameter counts and three flags (a parameter left idle, one pressed on
//! its search bound, axles that are no tyre). The search
//! ([`super::search`]), the screening ([`super::screening`]) and the
//! verdict ([`super::conclude`]) call them and nothing else decides; the
//! tests below hold each threshold and each ordering at its boundary.
//!
//! The gap above noise is `G = sqrt(J² − J_n²)` and a reduction
//! `1 − G_after/G_before` ([`crate::diagnose::verdict::score`]). The method
//! is the project's own (the book's diagnosis chapter states it).

use crate::diagnose::model::channels::gap_above;
use crate::diagnose::report::{Refusal, Refused, VerdictKind, Window};

/// Share of the held-out gap above noise an effect must remove to be
/// accepted (and each further effect of what is left).
pub const ACCEPT: f64 = 0.3;
/// An effect whose remaining held-out gap above noise is at most this
/// multiple of the accepted one's (plus [`CONFOUNDED_NOISE`] noise levels)
/// explains the data about as well: it is confounded with it.
pub const CONFOUNDED: f64 = 1.5;
/// The noise allowance of the confounding test, in noise levels.
pub const CONFOUNDED_NOISE: f64 = 0.25;
/// A held-out error below this multiple of the noise level is no gap.
pub const SIGNIFICANT: f64 = crate::diagnose::report::outcome::SIGNIFICANT_GAP;
/// Share of the gap a best single effect must remove for the greedy search
/// to start from it (a pair whose halves each remove less than [`ACCEPT`]).
pub const PROMISING: f64 = 0.1;
/// In-sample minus held-out reduction (percentage points) past which a
/// candidate's cross-validation disagrees with its fit: a warning.
pub const DISAGREEMENT: f64 = 25.0;
/// Look-alikes of the best single the verdict's search also starts from
/// while the set found leaves a significant gap.
pub const ALTERNATIVE_STARTS: usize = 2;
/// Singles, the best in sample, whose pairs the search also tries where
/// the search from the best single on held-out runs reaches no verdict
/// ([`crate::diagnose::verdict::pairs`]).
pub const PAIRED: usize = 4;
/// Held-out error, in noise levels, by which a candidate that leaves a
/// parameter idle must beat a simpler one (fewer parameters) to be
/// preferred to it.
pub const PARSIMONY: f64 = 0.1;
/// Percentage points by which a candidate's held-out reduction may exceed
/// its in-sample one and the screening still hold.
pub const SCREEN_MARGIN: f64 = 10.0;
/// Percentage points by which a set's restricted fit (the effect it adds
/// fitted alone beside the current set held,
/// [`crate::diagnose::verdict::restricted`]) must stay below the full
/// fits' screen for its greedy step to be screened without polishing:
/// several times what refitting the current set beside it was seen to add.
pub const RESTRICTED_MARGIN: f64 = 10.0;

/// Standard errors of the all-run fit beyond which a fold's refit has
/// landed far from it. Leaving one of `k` folds out moves a determined
/// optimum by about `SE/√(k − 1)` (the grouped jackknife: Efron & Tibshirani
/// 1993, §11.5), so a refit three standard errors away found another
/// optimum on fewer runs: its held-out score measures that fit as much as
/// the effect.
pub const FOLD_FAR: f64 = 3.0;

/// The parameter whose fold refits land farthest from the all-run fit, if
/// any lands beyond [`FOLD_FAR`] standard errors: `(index, the farthest
/// fold's value, its distance in standard errors, how many folds land
/// beyond)`. `full` and `std_errors` are the all-run fit's, `folds` each
/// fold's vector; only the parameters of `which` with a finite, positive
/// standard error are read (one on a bound or not seen has none).
pub fn far_folds(
    full: &[f64],
    std_errors: &[f64],
    folds: &[Vec<f64>],
    which: std::ops::Range<usize>,
) -> Option<(usize, f64, f64, usize)> {
    let mut worst: Option<(usize, f64, f64)> = None;
    let mut far = vec![false; folds.len()];
    for i in which {
        let se = std_errors[i];
        if !(se.is_finite() && se > 0.0) {
            continue;
        }
        for (k, f) in folds.iter().enumerate() {
            let d = (f[i] - full[i]).abs() / se;
            if d > FOLD_FAR {
                far[k] = true;
                if worst.is_none_or(|w| d > w.2) {
                    worst = Some((i, f[i], d));
                }
            }
        }
    }
    worst.map(|(i, v, d)| (i, v, d, far.iter().filter(|&&f| f).count()))
}

/// Whether a held-out error `j` leaves a gap above the noise level `jn`:
/// `J > SIGNIFICANT·J_n`.
pub fn significant(j: f64, jn: f64) -> bool {
    j > SIGNIFICANT * jn
}

/// Whether a candidate that removes `reduction_percent` of the gap (of the
/// base's, or of what the set it extends leaves) with BIC `bic` is taken
/// over the one of BIC `bic_before`: at least [`ACCEPT`] of the gap, and a
/// lower BIC.
pub fn accepted(reduction_percent: f64, bic: f64, bic_before: f64) -> bool {
    reduction_percent >= 100.0 * ACCEPT && bic < bic_before
}

/// Whether the greedy search starts from a best single that removes
/// `reduction_percent` with a BIC `delta_bic` from the base's: at least
/// [`PROMISING`] and a lower BIC (it can be half of a pair).
pub fn promising(reduction_percent: f64, delta_bic: f64) -> bool {
    reduction_percent >= 100.0 * PROMISING && delta_bic < 0.0
}

/// Whether a single whose all-run fit removes `insample_percent` of the
/// in-sample gap with a BIC `delta_bic` from the base's can be half of a
/// pair of the best singles in sample ([`PAIRED`]): it removes something
/// and lowers the BIC.
pub fn pairable(insample_percent: f64, delta_bic: f64) -> bool {
    insample_percent > 0.0 && delta_bic < 0.0
}

/// Whether a single of held-out reduction `reduction_percent` and gap
/// above noise `gap` is a look-alike of the best, whose gap is `best_gap`:
/// it passes too and leaves about as small a gap (within
/// [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n). A look-alike starts a
/// search of its own and is reported as confounded.
pub fn lookalike(reduction_percent: f64, gap: f64, best_gap: f64, jn: f64) -> bool {
    reduction_percent >= 100.0 * ACCEPT && gap <= window(best_gap, jn).bound
}

/// The confounding window of a candidate whose held-out gap above noise
/// is `gap` at noise level `jn`: [`lookalike`]'s bound,
/// [`CONFOUNDED`]·G + [`CONFOUNDED_NOISE`]·J_n, with its terms (the words
/// say them, not "about as well").
pub fn window(gap: f64, jn: f64) -> Window {
    Window::of(gap, jn, (CONFOUNDED, CONFOUNDED_NOISE))
}

/// Whether a set found from a look-alike (gap above noise `other`)
/// replaces the set found first (`current`): it leaves clearly less of
/// the gap, below 1/[`CONFOUNDED`] of it.
pub fn replaces(other: f64, current: f64) -> bool {
    other * CONFOUNDED < current
}

/// Whether a candidate's cross-validation disagrees with its fit: its fit
/// on all runs removes at least [`ACCEPT`] in sample and more than
/// [`DISAGREEMENT`] points more than on held-out runs.
pub fn disagrees(insample_percent: f64, heldout_percent: f64) -> bool {
    insample_percent - heldout_percent > DISAGREEMENT && insample_percent >= 100.0 * ACCEPT
}

/// Whether a single whose all-run fit removes `insample_percent` of the
/// in-sample gap is screened (not cross-validated): even
/// [`SCREEN_MARGIN`] points more held out would stay below [`ACCEPT`].
pub fn screened(insample_percent: f64) -> bool {
    insample_percent + SCREEN_MARGIN < 100.0 * ACCEPT
}

/// Whether a greedy step's set whose restricted fit removes
/// `insample_percent` of the in-sample gap the current set leaves is
/// screened without its full fit: [`RESTRICTED_MARGIN`] points more by
/// refitting the current set beside it would still be screened
/// ([`screened`]).
pub fn screened_restricted(insample_percent: f64) -> bool {
    screened(insample_percent + RESTRICTED_MARGIN)
}

/// Whether a screened single is cross-validated after all: its least
/// possible held-out error `floor` (that of its in-sample reduction plus
/// [`SCREEN_MARGIN`]) reaches the best cross-validated error `best`, or,
/// where its axles are a tyre (`usable`), the [`PARSIMONY`] window of the
/// best whose axles are one (`best_usable`): there the search could read
/// it.
pub fn reaches(floor: f64, usable: bool, best: f64, best_usable: f64, jn: f64) -> bool {
    floor <= best || (usable && floor <= best_usable + PARSIMONY * jn)
}

/// What a greedy step's pick reads first of the sets cross-validated so
/// far ([`pick`]): the best whose axles are a tyre and whose every effect
/// contributes (`top`, its held-out error J, and whether it is `pressed`
/// on a search bound), and where it is pressed, the best of those not
/// pressed within its look-alike window (`inside`), which the pick then
/// reads instead.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reading {
    /// The best's held-out error.
    pub top: f64,
    /// Whether the best is pressed on a search bound.
    pub pressed: bool,
    /// The held-out error of the best not pressed inside its window.
    pub inside: Option<f64>,
}

/// The [`Reading`] of candidates (in any order); None without one whose
/// axles are a tyre.
pub fn reading(candidates: &[Candidate], jn: f64) -> Option<Reading> {
    let mut ranked = candidates.to_vec();
    ranked.sort_by(|a, b| a.heldout.total_cmp(&b.heldout));
    let usable = tyres(&ranked);
    let top = ranked[*usable.first()?];
    let inside = inside_ranges(&ranked, &usable, jn).map(|k| ranked[k[0]].heldout);
    Some(Reading {
        top: top.heldout,
        pressed: top.pressed,
        inside,
    })
}

/// Whether a greedy step's set whose least possible held-out error is
/// `floor` (and which is `pressed` on a search bound or not: its fit on
/// all runs says, before any fold) can still be read by the step's pick
/// ([`pick`], [`simpler_than`]), given what it reads of the sets
/// cross-validated so far (`read`; None: nothing yet, every set can be).
/// It is read where it could rank first (`floor` below the best's J) or
/// lie within [`PARSIMONY`] noise levels of the best; and, the best being
/// pressed and the set not, where it could be read inside the best's
/// look-alike window: within [`PARSIMONY`] noise levels of the best inside
/// it, or anywhere in the window while none is. Beyond these, the set
/// moves neither the pick nor what it passes over, whatever its held-out
/// error and its other flags turn out to be. As sets are cross-validated
/// the reading only tightens, so a set once beyond it stays beyond.
pub fn may_be_read(floor: f64, pressed: bool, read: Option<Reading>, jn: f64) -> bool {
    let Some(r) = read else {
        return true;
    };
    if floor <= r.top + PARSIMONY * jn {
        return true;
    }
    if !r.pressed || pressed {
        return false;
    }
    match r.inside {
        Some(first) => floor <= first + PARSIMONY * jn,
        None => gap_above(floor, jn) <= window(gap_above(r.top, jn), jn).bound,
    }
}

/// What the choice of a candidate reads of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Candidate {
    /// Held-out error J.
    pub heldout: f64,
    /// Parameters fitted (axles and roll dynamics included).
    pub parameters: usize,
    /// It leaves one of its effect parameters idle (off, or not told from
    /// off): it reduces to a simpler candidate.
    pub idle: bool,
    /// Its axles are no tyre: it cannot be a verdict, nor start one.
    pub degenerate: bool,
    /// One of its effect parameters is pressed on the end of its search
    /// range: the data would take it further, so its value bounds the
    /// effect's size rather than measures it.
    pub pressed: bool,
    /// One of its effects contributes nothing ([`contributes_nothing`]):
    /// it cannot be named, and the set reduces to its other effects.
    pub inert: bool,
}

/// One effect parameter as [`contributes_nothing`] reads it: its fitted
/// value, its off value (NaN: none), its standard error (NaN where it has
/// none, as on a physical limit) and its range's width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffReading {
    /// Fitted value.
    pub value: f64,
    /// The registry's off value.
    pub off: f64,
    /// Its standard error.
    pub std_error: f64,
    /// Width of its search range (what "exactly off" is measured on).
    pub range: f64,
}

impl OffReading {
    /// Whether the parameter sits at its off value: exactly (to 1e-9 of
    /// its range, as on a physical limit that is its off value, where it
    /// has no standard error), or within one standard error of it.
    pub fn sits_off(&self) -> bool {
        if self.off.is_nan() {
            return false;
        }
        let d = (self.value - self.off).abs();
        self.exactly_off() || (self.std_error.is_finite() && d <= self.std_error)
    }

    /// Whether the parameter sits exactly at its off value (to 1e-9 of
    /// its range).
    pub fn exactly_off(&self) -> bool {
        !self.off.is_nan() && (self.value - self.off).abs() <= 1e-9 * self.range
    }
}

/// Whether an effect whose parameters read `params` contributes nothing
/// to a set: every one of them sits at its off value
/// ([`OffReading::sits_off`]). Such an effect cannot be named: whatever
/// the set gains over its other effects comes from its other parameters
/// (the axles refitted under another prior weight), not from it — a
/// sensor delay at 0.0000 s (its physical limit) beside sensor offsets
/// took a truck-prior campaign's held-out error 4.717 → 2.789 by moving
/// the axles, and was named.
///
/// Of several parameters, at most one may sit off only within its
/// standard error, the others exactly: two that trade against each other
/// (a steer path's delay at 0.80 standard errors and its lag at 0.001)
/// each lie within one of off while their sum is determined, which
/// standard errors read one by one cannot tell.
pub fn contributes_nothing(params: &[OffReading]) -> bool {
    let inexact = params.iter().filter(|p| !p.exactly_off()).count();
    !params.is_empty() && params.iter().all(OffReading::sits_off) && inexact <= 1
}

/// Of a set's effects (each its parameters' readings, in the set's
/// order), the indices of those that contribute nothing
/// ([`contributes_nothing`]): the set reduces to the others.
pub fn inert_effects(effects: &[Vec<OffReading>]) -> Vec<usize> {
    (0..effects.len())
        .filter(|&k| contributes_nothing(&effects[k]))
        .collect()
}

/// Candidates best first: indices of `heldout` (held-out errors) from the
/// lowest; ties keep their order.
pub fn best_first(heldout: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..heldout.len()).collect();
    order.sort_by(|&a, &b| heldout[a].total_cmp(&heldout[b]));
    order
}

/// Of candidates ranked best first, the one to take (an index into
/// `ranked`): those whose axles are no tyre left out, the first of the
/// others, with two exceptions. Where it is pressed on a search bound and
/// a look-alike is not (one whose gap above noise is within the
/// [`lookalike`] window of it: at most [`CONFOUNDED`]·G +
/// [`CONFOUNDED_NOISE`]·J_n), only the candidates not pressed are read:
/// an effect that explains the gap only at the end of its plausible range
/// stands in for something else, where one that explains it about as well
/// from inside its range measures it (a 0.3 s sensor delay against a
/// steer path's determined delay and lag). And where the one read first
/// leaves a parameter idle, the one with the fewest parameters within
/// [`PARSIMONY`] noise levels of it is taken (the first of those with as
/// few). A candidate with an effect that contributes nothing
/// ([`Candidate::inert`]) is never taken. `None` without a candidate whose
/// axles are a tyre.
pub fn pick(ranked: &[Candidate], jn: f64) -> Option<usize> {
    let usable = tyres(ranked);
    let usable = inside_ranges(ranked, &usable, jn).unwrap_or(usable);
    let top = &ranked[*usable.first()?];
    if !top.idle {
        return usable.first().copied();
    }
    usable
        .into_iter()
        .filter(|&k| ranked[k].heldout <= top.heldout + PARSIMONY * jn)
        .min_by_key(|&k| ranked[k].parameters)
}

/// The best of `ranked` (an index) where it ranks ahead of the pick
/// `picked` and its axles are no tyre: refused alone, it can still be half
/// of a pair whose other half brings the axles back (an accelerometer's
/// offsets with a sideslip measured ahead of the centre of gravity: the
/// offsets alone leave the rear axle to stand in for the sensor's
/// position), so the search starts from it too. `None` where the pick is
/// the best, or none ahead of it is refused for its axles.
pub fn degenerate_lead(ranked: &[Candidate], picked: usize) -> Option<usize> {
    ranked[..picked.min(ranked.len())]
        .iter()
        .position(|c| c.degenerate)
}

/// The best of `ranked` whose axles are a tyre where [`pick`] passes it
/// over for being pressed on a search bound (an index into `ranked`).
pub fn passed_over(ranked: &[Candidate], jn: f64) -> Option<usize> {
    let usable = tyres(ranked);
    inside_ranges(ranked, &usable, jn).map(|_| usable[0])
}

/// The candidate [`pick`] passes over for a simpler one (an index into
/// `ranked`): the first it reads (after the candidates whose axles are no
/// tyre, and those pressed on a search bound where a look-alike is not),
/// where that one leaves a parameter idle and one with fewer parameters
/// within [`PARSIMONY`] noise levels of it is taken instead. A best
/// passed over for being pressed is [`passed_over`]'s, never this one's:
/// its reason is its bound, not its parameters.
pub fn simpler_than(ranked: &[Candidate], jn: f64) -> Option<usize> {
    let usable = tyres(ranked);
    let usable = inside_ranges(ranked, &usable, jn).unwrap_or(usable);
    let top = *usable.first()?;
    pick(ranked, jn).filter(|&k| k != top).map(|_| top)
}

/// The parsimony rule read over a verdict's set (`chosen`) and its twins
/// (`twins`: the set with a look-alike of its first effect in that
/// effect's place), as the greedy step, the pairs and the singles read it
/// ([`pick`], [`simpler_than`]) over the sets they fit: the twin taken (an
/// index into `twins`) where the rule passes the set over for it, i.e.
/// where the set leaves a parameter idle and the twin has fewer parameters
/// within [`PARSIMONY`] noise levels of it. A twin that merely does better
/// changes nothing (it stays a look-alike, confounded or told apart): only
/// the rule's own reason moves the verdict, so the set the greedy search
/// grew (a steer path with its lag idle beside a yaw inertia) and the set
/// the pairs fallback would have taken (a sensor delay beside it) read the
/// same.
pub fn simpler_twin(chosen: Candidate, twins: &[Candidate], jn: f64) -> Option<usize> {
    let all: Vec<Candidate> = std::iter::once(chosen)
        .chain(twins.iter().copied())
        .collect();
    let order = best_first(&all.iter().map(|c| c.heldout).collect::<Vec<f64>>());
    let ranked: Vec<Candidate> = order.iter().map(|&i| all[i]).collect();
    let over = simpler_than(&ranked, jn)?;
    let taken = order[pick(&ranked, jn)?];
    (order[over] == 0 && taken != 0).then(|| taken - 1)
}

/// The candidates whose axles are a tyre and whose every effect
/// contributes something (indices into `ranked`, in its order): a set
/// with an inert effect is the set of its others, fitted again.
fn tyres(ranked: &[Candidate]) -> Vec<usize> {
    (0..ranked.len())
        .filter(|&k| !ranked[k].degenerate && !ranked[k].inert)
        .collect()
}

/// Of the `usable` candidates (best first), those not pressed on a search
/// bound whose gap is within the look-alike window of the first, where
/// the first is pressed and there are any.
fn inside_ranges(ranked: &[Candidate], usable: &[usize], jn: f64) -> Option<Vec<usize>> {
    let first = &ranked[*usable.first()?];
    if !first.pressed {
        return None;
    }
    let window = window(gap_above(first.heldout, jn), jn).bound;
    let inside: Vec<usize> = usable
        .iter()
        .copied()
        .filter(|&k| !ranked[k].pressed && gap_above(ranked[k].heldout, jn) <= window)
        .collect();
    (!inside.is_empty()).then_some(inside)
}

/// Which case the verdict is: effects `accepted`, else no gap where it is
/// not `significant`, else not identifiable where the base is no tyre
/// (what no candidate explains may be the base's own collapse), else
/// outside the library.
pub fn case(accepted: bool, significant: bool, base_no_tyre: bool) -> VerdictKind {
    match (accepted, significant, base_no_tyre) {
        (true, _, _) => VerdictKind::Explained,
        (false, false, _) => VerdictKind::NoSignificantGap,
        (false, true, true) => VerdictKind::NotIdentifiable,
        (false, true, false) => VerdictKind::OutsideLibrary,
    }
}

/// Why the search started from another candidate than the best.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GaveWay {
    /// The best leaves a parameter idle: a simpler one as good.
    Idle,
    /// The best is pressed on a search bound: a look-alike inside its
    /// ranges.
    Pressed,
}

/// Why a candidate (its held-out reduction, BIC against the base's and
/// whether its axles are no tyre, `no_tyre` their reasons) is not the
/// verdict, by the rules it fails: its axles, the acceptance share, the
/// BIC. Where it fails none, the search went on from `instead` (the
/// candidate it `gave_way` to, else the set its own search ended on), and
/// that was refused.
pub fn refused(
    candidate: (Vec<crate::diagnose::effects::EffectKind>, f64, f64),
    no_tyre: Vec<crate::diagnose::base::identify::NoTyre>,
    gave_way: Option<GaveWay>,
    instead: Option<Refused>,
) -> Refused {
    let (effects, reduction_percent, delta_bic) = candidate;
    let mut why = Vec::new();
    if !no_tyre.is_empty() {
        why.push(Refusal::AxlesNoTyre { no_tyre });
    }
    if reduction_percent < 100.0 * ACCEPT {
        why.push(Refusal::BelowAcceptance {
            threshold_percent: 100.0 * ACCEPT,
        });
    }
    if delta_bic >= 0.0 {
        why.push(Refusal::BicNotLower { delta_bic });
    }
    if why.is_empty() {
        why.extend(instead.map(|other| match gave_way {
            Some(GaveWay::Idle) => Refusal::LeavesParameterIdle {
                simpler: Box::new(other),
            },
            Some(GaveWay::Pressed) => Refusal::PressedOnSearchBound {
                inside: Box::new(other),
            },
            None => Refusal::SearchEndedOn {
                set: Box::new(other),
            },
        }));
    }
    Refused {
        effects,
        reduction_percent,
        why,
    }
}

#[cfg(test)]
mod tests;
