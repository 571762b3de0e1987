//! How the data determine a fitted coefficient, typed for the report
//! (JSON) and said in one place ([`Determination::said`]) for both fits
//! that refuse a hold: the staged Magic Formula fit
//! (`mf_staged/determination.rs` decides it) and the swarm fit of one
//! channel (`undetermined.rs`). A coefficient whose hold within the free
//! fit's ±2 linearised standard errors was refused is fixed by the data
//! beyond that linearisation (the cost is far from quadratic between the
//! two values): its standard error means nothing, and it is not said "not
//! identifiable" (the book rig file's QSX10, its ± 168.2 moving the fit
//! by 769.7 % of the channel's RMS). Units: the effect in % of the
//! channel's RMS (`‖J_k‖·se/‖F‖`), the correlation dimensionless.

use serde::Serialize;

/// One standard error's effect past which its digits mean nothing: more
/// than ten times the channel's RMS.
pub(crate) const ABSURD_EFFECT_PERCENT: f64 = 1000.0;

/// One standard error's effect, `percent` of the channel's RMS, in words:
/// its digits up to [`ABSURD_EFFECT_PERCENT`], a bound past it.
pub(crate) fn effect_words(percent: f64) -> String {
    if percent < ABSURD_EFFECT_PERCENT {
        format!("{percent:.1} % of the channel's RMS")
    } else {
        format!(
            "more than {} times the channel's RMS",
            ABSURD_EFFECT_PERCENT / 100.0
        )
    }
}

/// The correlation of two estimates, by the linearised covariance, at
/// which the one is named as the other's partner: the two trade along
/// one direction the data barely see (`|r|` near 1).
pub(crate) const STRONG_CORRELATION: f64 = 0.9;

/// The free parameter a coefficient's estimate is most correlated with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Partner {
    /// Its name (a `.tir`'s, or the swarm model's as `--hold` takes it).
    pub name: String,
    /// The correlation of the two estimates at the fit (−1 to 1).
    pub correlation: f64,
    /// The physical bound it sits on, if it does.
    pub on_bound: Option<f64>,
}

/// How the data determine a fitted coefficient (module notes).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Determination {
    /// Its standard error is below its magnitude, or one standard error
    /// moves the fit by under 1 % of the channel's RMS.
    Identified,
    /// Its standard error reaches its magnitude and one moves the fit by
    /// 1 % of the channel's RMS or more, or it has none.
    NotIdentifiable,
    /// Its linearised standard error says not identifiable, but a hold
    /// within it was refused: the data fix it more tightly, and the
    /// standard error (kept in `std_error`) means nothing.
    FixedBeyondLinearisation {
        /// One linearised standard error's effect alone, % of the
        /// channel's RMS.
        effect_percent: f64,
        /// The free parameter it trades with, where one is correlated
        /// with it by [`STRONG_CORRELATION`] or more.
        partner: Option<Partner>,
    },
    /// On a physical bound: the fit would take it beyond.
    OnBound {
        /// The bound.
        bound: f64,
    },
}

impl Partner {
    /// "it trades with QSX11 (correlation −0.9993 at the fit)", the
    /// partner's bound said where it sits on one.
    pub(crate) fn said(&self) -> String {
        let bound = self.on_bound.map_or(String::new(), |b| {
            format!(", itself on its physical bound {}", crate::format::exact(b))
        });
        // Four digits, or as many more as keep a correlation short of ±1
        // from reading as ±1 (−0.99998 is not "−1").
        let r = self.correlation;
        let short_of_one = |t: &String| {
            let v = t.parse::<f64>().ok();
            r.abs() == 1.0 || v.filter(|v| v.abs() >= 1.0).is_none()
        };
        let said = (4..=12)
            .map(|d| crate::format::rounded(r, d))
            .find(short_of_one)
            .unwrap_or_else(|| crate::format::rounded(r, 12));
        format!(
            "it trades with {}{bound} (correlation {said} at the fit)",
            self.name
        )
    }
}

impl Determination {
    /// The words of a coefficient fixed beyond its linearisation with
    /// standard error `se`, before its refused hold's; `None` for the
    /// others, whose words are the identifiability warning's.
    pub fn said(&self, se: Option<f64>) -> Option<String> {
        let Determination::FixedBeyondLinearisation {
            effect_percent,
            partner,
        } = self
        else {
            return None;
        };
        let why = match partner {
            Some(p) => format!("{}, along which the cost is far from quadratic", p.said()),
            None => "the cost is far from quadratic about the fit".into(),
        };
        Some(format!(
            "fixed by the data more tightly than its standard error says: the linearised standard error{} means nothing here (one of it would move the fit by {}; {why}), as its refused hold shows",
            se.map_or(String::new(), |s| format!(" {}", crate::format::readable(s, 4))),
            effect_words(*effect_percent),
        ))
    }
}
