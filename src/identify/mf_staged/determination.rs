//! How the data determine a fitted (free) coefficient of a stage, typed
//! for the report (JSON) and said in one place for the terminal and the
//! written file's header ([`Determination::said`]).
//!
//! The linearised standard error (`uncertainty.rs`: `cov = s²·(JᵀJ)⁻¹`
//! at the optimum) is the cost's curvature there: it says how far the
//! coefficient may move while the cost stays within a quadratic's reach.
//! A hold tried within the free fit's ±2 of those standard errors
//! (`spare.rs`'s [`LEAN_STANDARD_ERRORS`]) costs at most `2s²` by that
//! linearisation, under the guard's `½·2.25²·s²`, so a refusal of such a
//! hold (`hold_refusal.rs`) shows the linearisation false: the cost is far
//! from quadratic between the two values, and the data fix the coefficient
//! more tightly than its standard error says. Its ± then means nothing
//! and is not said as a "not identifiable" ±: one standard error moving
//! the fit by several times the channel's RMS (QSX10 of the book's rig
//! file, 769.7 %) is the sign. The free parameter its estimate is most
//! correlated with (`|r| ≥` [`STRONG_CORRELATION`], by the same
//! covariance) is named as the partner it trades with, flagged where it
//! sits on its bound (PKY4 = 0.1 beside PKY1 on the Hoosier file).
//!
//! A coefficient on its physical bound has no standard error worth the
//! name: the fit would take it beyond (`OnBound`). The type and its words
//! are the swarm route's too (`identify/determined.rs`).

use super::hold_refusal::RefusedHold;
use super::hold_rounds::StageFit;
use super::release::at_bound;
use super::uncertainty::Uncertainty;
use crate::identify::determined::{Determination, Partner, STRONG_CORRELATION};
use crate::identify::spare::LEAN_STANDARD_ERRORS;

impl RefusedHold {
    /// Whether the value tried lay within the free fit's ±2 linearised
    /// standard errors: the stated value itself within them, or the
    /// end of them nearest it. Its refusal then contradicts the
    /// linearisation (module notes).
    pub fn within_linearisation(&self) -> bool {
        match self.standard_errors_away {
            Some(z) => self.tried_at != self.stated || z <= LEAN_STANDARD_ERRORS,
            None => false,
        }
    }
}

/// How the data determine the `k`-th free parameter of `fit`, at `value`,
/// by its uncertainty `u` and the hold the guard refused it, if any.
pub(super) fn determination(
    fit: &StageFit,
    u: &Uncertainty,
    (k, value): (usize, f64),
    refused: Option<&RefusedHold>,
) -> Determination {
    if let Some(bound) = at_bound(fit.p[k], fit.bounds[k]) {
        return Determination::OnBound { bound };
    }
    match (u.std_error[k], refused) {
        // Only where the linearisation says not identifiable: a
        // coefficient it determines (PKY1 = -31.1 ± 0.14 on the Hoosier
        // file, its hold at the book's -15 refused) is identified, as it
        // was before the hold was tried.
        (Some(_), Some(r)) if u.flagged(k, value) && r.within_linearisation() => {
            Determination::FixedBeyondLinearisation {
                effect_percent: 100.0 * u.effect[k],
                partner: u
                    .partner(k, STRONG_CORRELATION)
                    .map(|(j, correlation)| Partner {
                        name: fit.problem.names[j].to_string(),
                        correlation,
                        on_bound: at_bound(fit.p[j], fit.bounds[j]),
                    }),
            }
        }
        _ if u.flagged(k, value) => Determination::NotIdentifiable,
        _ => Determination::Identified,
    }
}

#[cfg(test)]
mod tests {
    use super::super::holds::HoldSource;
    use super::super::{GuardLimit, MoreData, Stage};
    use super::*;

    /// The book rig file's QSX10: the book default 0 lies 0.04 standard
    /// errors from the free fit 5.995, and its refit raised σ ninefold.
    fn refused(stated: f64, tried_at: f64, z: Option<f64>) -> RefusedHold {
        RefusedHold {
            source: HoldSource::PacejkaBook,
            stated,
            tried_at,
            standard_errors_away: z,
            sigma_free_percent: 0.094,
            sigma_held_percent: 0.801,
            sigma_limit_percent: 0.099,
            limit: GuardLimit::SigmaRise,
            more_data: vec![MoreData::Loads, MoreData::Cambers],
        }
    }

    /// A refusal contradicts the linearisation only where the value
    /// tried lay within the ±2: the stated value within it, or its edge;
    /// a stated value beyond, or one without a standard error (on a
    /// bound), does not.
    #[test]
    fn only_a_refused_hold_within_the_linearised_two_standard_errors_refutes_it() {
        assert!(refused(0.0, 0.0, Some(0.04)).within_linearisation());
        assert!(refused(0.0, 0.0, Some(LEAN_STANDARD_ERRORS)).within_linearisation());
        assert!(!refused(0.0, 0.0, Some(2.01)).within_linearisation());
        // QSX11: the default 5 lay 2.6 away, the edge 3.9 was tried.
        assert!(refused(5.0, 3.9, Some(2.6)).within_linearisation());
        assert!(!refused(1.9896, 1.9896, None).within_linearisation());
    }

    /// The words say the data fix it, the standard error means nothing,
    /// and why, naming the partner (and its bound), never "not
    /// identifiable"; the refused hold's words then ask for no more data.
    #[test]
    fn a_coefficient_fixed_beyond_its_linearisation_is_not_called_not_identifiable() {
        let d = Determination::FixedBeyondLinearisation {
            effect_percent: 769.7,
            partner: Some(Partner {
                name: "QSX11".into(),
                correlation: -0.99934,
                on_bound: None,
            }),
        };
        assert_eq!(
            d.said(Some(168.2)).unwrap(),
            "fixed by the data more tightly than its standard error says: the linearised standard error 168.2 means nothing here (one of it would move the fit by 769.7 % of the channel's RMS; it trades with QSX11 (correlation -0.9993 at the fit), along which the cost is far from quadratic), as its refused hold shows"
        );
        let bound = Determination::FixedBeyondLinearisation {
            effect_percent: 722.3,
            partner: Some(Partner {
                name: "PKY4".into(),
                correlation: 0.95,
                on_bound: Some(0.1),
            }),
        };
        let w = bound.said(Some(5859.0)).unwrap();
        assert!(
            w.contains("it trades with PKY4, itself on its physical bound 0.1 (correlation 0.95 at the fit)"),
            "{w}"
        );
        // QSX10 against QSX11 on the book's rig: −0.99998 is not "−1".
        let near = Partner {
            name: "QSX11".into(),
            correlation: -0.999984,
            on_bound: None,
        };
        assert_eq!(
            near.said(),
            "it trades with QSX11 (correlation -0.99998 at the fit)"
        );
        let alone = Determination::FixedBeyondLinearisation {
            effect_percent: 1500.0,
            partner: None,
        };
        let w = alone.said(Some(2.0)).unwrap();
        assert!(w.contains("more than 10 times the channel's RMS; the cost is far from quadratic about the fit)"), "{w}");
        assert_eq!(Determination::NotIdentifiable.said(Some(1.0)), None);
        assert_eq!(Determination::OnBound { bound: 0.1 }.said(None), None);
        // The edge of the ±2 refused: no more data asked for; without a
        // standard error (on a bound) they are.
        let edge = refused(5.0, 3.9, Some(2.6)).said("QSX11", Stage::Mx);
        assert!(!edge.contains("fit data with"), "{edge}");
        let at_bound = refused(1.9896, 1.9896, None).said("PKY4", Stage::PureFy);
        assert!(
            at_bound.ends_with(
                "or fit data with more load levels and more camber levels, which determine it"
            ),
            "{at_bound}"
        );
    }
}
