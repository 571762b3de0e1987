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

#[cfg(test)]
mod tests {
    use super::*;

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
