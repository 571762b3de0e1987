//! The versions of the Magic Formula a `.tir` file holds (its `FITTYP`):
//! 5.2 (PAC2002), 6.1 and 6.2, which differ in their pressure, camber and
//! moment terms (Pacejka (2012), ch. 4.3; the TNO MF-Tyre 6.1/6.2 equation
//! manual). This file imports nothing of the crate, so that the tyre
//! registry can name a version without importing the model.

use serde::{Deserialize, Serialize};

/// Which Magic Formula a file holds, from its `FITTYP`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MfVersion {
    /// MF 5.2 / PAC2002 (`FITTYP` 6 or 21).
    Mf52,
    /// MF 6.1 (`FITTYP` 61).
    Mf61,
    /// MF 6.2 (`FITTYP` 62).
    Mf62,
}

impl MfVersion {
    /// The version for a `FITTYP` value.
    pub fn from_fittyp(fittyp: i64) -> Option<Self> {
        match fittyp {
            6 | 21 => Some(Self::Mf52),
            61 => Some(Self::Mf61),
            62 => Some(Self::Mf62),
            _ => None,
        }
    }
    /// The `FITTYP` value written for this version.
    pub fn fittyp(self) -> i64 {
        match self {
            Self::Mf52 => 6,
            Self::Mf61 => 61,
            Self::Mf62 => 62,
        }
    }
}
