//! Why a Magic Formula file's vertical model does not carry a load, in
//! words: at no loaded radius above 0 (its load at a deflection of its
//! whole free radius where it is one, and none where its stiffness terms,
//! extrapolated that far, turn the force negative: the public MF 6.1
//! sample's −8171197641 N at 1 MN is no load any tyre carries, and was
//! quoted as one); past where its effective rolling radius falls through 0;
//! or past the load that deflects it onto its rim (`bottoming.rs`). Units:
//! N, m.

use crate::format::significant;
use std::fmt;

/// Why the vertical model does not carry a load.
#[derive(Debug, Clone, PartialEq)]
pub enum WhyNotCarried {
    /// At no loaded radius above 0 (the limit checks off): at most `most`
    /// N at a deflection of the whole free radius `free`, m.
    AtNoRadius {
        /// The most the model carries, N.
        most: f64,
        /// The free radius, m.
        free: f64,
    },
    /// The effective rolling radius, which MFeval takes at the load given
    /// in every mode, falls through 0: `rl` (m) MFeval's closed form gives
    /// against the free radius `free` (m) at the point's speed.
    RollingRadiusThroughZero {
        /// The `rl` written there, m.
        rl: f64,
        /// The free radius at the point's speed, m.
        free: f64,
    },
    /// Past the load that deflects the tyre onto its rim.
    PastBottoming(Box<super::Bottoming>),
}

impl fmt::Display for WhyNotCarried {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            // The limit checks hold the load at FZMAX for the forces and
            // the vertical model, but MFeval takes the effective rolling
            // radius Re at the load given: past where it falls through 0,
            // the wheel speed Vx/Re and the free radius that grows with it
            // blow up.
            WhyNotCarried::RollingRadiusThroughZero { rl, free } => write!(
                f,
                "its effective rolling radius Re, which MFeval takes at the load given in every mode (past FZMAX too), falls through 0 there, and the wheel speed Vx/Re and the free radius with it blow up (rl {} m against a free radius of {} m at the point's speed)",
                significant(*rl, 4),
                significant(*free, 4)
            ),
            WhyNotCarried::AtNoRadius { most, free } if *most > 0.0 && most.is_finite() => write!(
                f,
                "{} N at a deflection of its whole free radius ({} m)",
                significant(*most, 4),
                significant(*free, 4)
            ),
            WhyNotCarried::AtNoRadius { free, .. } => write!(
                f,
                "no load at a deflection of its whole free radius ({} m), where its vertical stiffness terms, extrapolated that far, give a negative force, no tyre's",
                significant(*free, 4)
            ),
            WhyNotCarried::PastBottoming(b) => write!(f, "{b}"),
        }
    }
}

impl WhyNotCarried {
    /// What the limit checks do of a load not carried: hold it at `FZMAX`
    /// (mode 1xx) where it is carried at no radius; nothing where the
    /// effective rolling radius or the rim is the cause, refused in every
    /// mode.
    pub(super) fn held(&self) -> &'static str {
        match self {
            WhyNotCarried::AtNoRadius { .. } => {
                " (the limit checks, mode 1xx, hold the load at the file's FZMAX)"
            }
            _ => " (refused in every mode, the limit checks on or off)",
        }
    }
}
