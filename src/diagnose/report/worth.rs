//! Whether a manoeuvre is worth driving to separate two candidate
//! effects: the one rule `handling design` ranks its manoeuvres by and the
//! diagnosis's advice on a base without a friction limit
//! ([`super::separating`]) words its best by.
//!
//! A driven run is expected to measure a separation `expected ±
//! uncertainty` (`crate::design::separation`'s module doc derives both);
//! it separates the pair only when `expected` lies beyond its 1 σ and is
//! at least the separation the campaign's own runs already show.
//!
//! One so recommended whose `expected` lies within [`FIRM_SIGMAS`] of its
//! own uncertainty is weak ([`weak`]): one run of it measures 0 or less —
//! no separation, or the wrong candidate favoured — with the chance
//! Φ(−expected/uncertainty) on a normal spread (Putnam's sweep, 277.9 ±
//! 268.9: 1.03 σ, 15 %). The design's list and the diagnosis's confounded
//! advice both say so in [`Weak::words`].
//!
//! Units: separations D in noise floors.

use serde::Serialize;

/// Whether one manoeuvre is worth driving to separate a pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Worth {
    /// Expected to separate beyond its own uncertainty, by at least the
    /// campaign's separation.
    Separates,
    /// Its expected separation lies within its own uncertainty: one run
    /// may show no separation, or favour the wrong candidate.
    WithinUncertainty,
    /// Beyond its uncertainty, but less than the campaign's runs already
    /// separate the pair by, without the diagnosis telling them apart.
    BelowCampaign,
    /// The diagnosis already tells the pair apart: no run is needed to
    /// separate them, whatever it would add.
    AlreadyToldApart,
}

/// The worth of a manoeuvre a driven run of which is expected to measure
/// `expected ± uncertainty` against a campaign that separates the pair by
/// `campaign` (D over all its runs). A non-finite value is no separation.
pub fn worth(expected: f64, uncertainty: f64, campaign: f64) -> Worth {
    if !(expected.is_finite() && uncertainty.is_finite() && expected > uncertainty) {
        Worth::WithinUncertainty
    } else if campaign.is_finite() && expected < campaign {
        Worth::BelowCampaign
    } else {
        Worth::Separates
    }
}

/// The expected separation, in units of its own uncertainty, from which
/// one run separates a pair firmly: below it a normal spread puts 0 within
/// 2 σ, and one run favours the wrong candidate with a chance above 2.3 %.
pub const FIRM_SIGMAS: f64 = 2.0;

/// A recommended manoeuvre whose expected separation lies within
/// [`FIRM_SIGMAS`] of its own uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Weak {
    /// Its expected separation over its uncertainty.
    pub sigmas: f64,
    /// The chance that one run measures 0 or less (no separation, or the
    /// wrong candidate favoured), on a normal spread: Φ(−sigmas).
    pub wrong: f64,
}

/// Whether a manoeuvre of worth `worth`, a driven run of which is expected
/// to measure `expected ± uncertainty`, is recommended
/// ([`Worth::Separates`]) but weakly: `expected` within [`FIRM_SIGMAS`] of
/// `uncertainty`.
pub fn weak(worth: Worth, expected: f64, uncertainty: f64) -> Option<Weak> {
    let sigmas = expected / uncertainty;
    (worth == Worth::Separates && sigmas < FIRM_SIGMAS).then(|| Weak {
        sigmas,
        wrong: 0.5 * libm::erfc(sigmas / std::f64::consts::SQRT_2),
    })
}

impl Weak {
    /// In words: its ratio and the chance one run misleads.
    pub fn words(&self) -> String {
        format!(
            "weak: expected at {:.2} times its own uncertainty, below {FIRM_SIGMAS}, so one run lands at or below 0 (no separation, or the wrong candidate favoured) with a chance of {:.0} % on a normal spread: it separates them as a series, not in one run",
            self.sigmas,
            100.0 * self.wrong
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Putnam's sweep, 277.9 ± 268.9 and recommended, is weak at 1.03 σ
    /// with Φ(−1.03) = 15 %; at 2 σ (Φ(−2) = 2.3 %) a run is firm; a run
    /// not recommended is no weak recommendation, however close.
    #[test]
    fn a_recommended_run_within_two_of_its_uncertainty_is_weak() {
        let putnam = weak(Worth::Separates, 277.9, 268.9).unwrap();
        assert!((putnam.sigmas - 277.9 / 268.9).abs() < 1e-12);
        assert!((putnam.wrong - 0.1507).abs() < 5e-4, "{}", putnam.wrong);
        assert!(
            putnam.words().starts_with("weak: expected at 1.03 times its own uncertainty, below 2, so one run lands at or below 0 (no separation, or the wrong candidate favoured) with a chance of 15 % on"),
            "{}",
            putnam.words()
        );
        assert_eq!(weak(Worth::Separates, 4.0, 2.0), None);
        assert!(weak(Worth::Separates, 3.9, 2.0).is_some());
        assert_eq!(weak(Worth::BelowCampaign, 3.9, 2.0), None);
        assert_eq!(weak(Worth::WithinUncertainty, 3.1, 9.5), None);
    }

    /// 3.1 ± 9.5 is no separation, whatever the campaign; 27 ± 1.9 against
    /// a campaign of 8.2 is; 5 ± 1 against a campaign of 7.5 adds less than
    /// the campaign already shows.
    #[test]
    fn a_separation_within_its_uncertainty_or_below_the_campaigns_is_not_recommended() {
        assert_eq!(worth(3.1, 9.5, 7.5), Worth::WithinUncertainty);
        assert_eq!(worth(3.1, 9.5, 0.5), Worth::WithinUncertainty);
        assert_eq!(worth(27.0, 1.9, 8.2), Worth::Separates);
        assert_eq!(worth(5.0, 1.0, 7.5), Worth::BelowCampaign);
        assert_eq!(worth(f64::NAN, 1.0, 7.5), Worth::WithinUncertainty);
        assert_eq!(worth(5.0, 1.0, f64::NAN), Worth::Separates);
    }
}
