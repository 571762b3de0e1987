//! The checks `tyre-eval` makes of a Magic Formula `.tir` file itself,
//! whatever points it is given, each over the file's own load range
//! (`FZMIN`–`FZMAX`): its pure curves' peak |F|/Fz above any tyre's on a
//! road or rig ([`crate::tyre::mf::WARN_FRICTION`], 2.5;
//! `tyre/mf/pure_curves.rs`), and a longitudinal slip stiffness
//! `Fz·(PKX1 + PKX2·dfz)` that turns negative inside that range
//! (`io/tir/long_stiffness.rs`). One implementation, run by `tyre-eval`
//! on the file it reads and by `identify` on the file it writes: a fit
//! that keeps a template's longitudinal block and widens the load range
//! to the data's (the Hoosier rig file on `FSAE_Defaults.tir`: `FZMAX`
//! 2000 → 2928.5 N, `PKX1 = 50`, `PKX2 = −80`) wrote a file whose force
//! opposes its slip from 1625 N and peaks at |Fx|/Fz = 2.56, which
//! `tyre-eval` said and `identify` did not. Units: N.

use crate::io::tir::{LongitudinalTurn, TirDocument};
use crate::tyre::mf::{MagicFormula, PeakFriction};
use crate::tyre::Tyre;
use std::path::Path;

/// What the checks of a `.tir` file found (nothing: both `None`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FileChecks {
    /// The highest pure-curve peak |F|/Fz above
    /// [`crate::tyre::mf::WARN_FRICTION`], where there is one.
    pub peak_friction: Option<PeakFriction>,
    /// A longitudinal slip stiffness negative inside the file's load range.
    pub longitudinal_turn: Option<LongitudinalTurn>,
}

impl FileChecks {
    /// The warnings, one sentence each, in the order `tyre-eval` gives them.
    pub fn lines(&self) -> Vec<String> {
        let peak = self.peak_friction.iter().map(|p| p.to_string());
        peak.chain(self.longitudinal_turn.iter().map(|t| t.to_string()))
            .collect()
    }
}

/// The checks of the Magic Formula tyre `t` read from `doc` (its lines
/// name the coefficients; `None`: no file, the stiffness is not judged).
fn checks_of(doc: Option<&TirDocument>, t: &MagicFormula) -> FileChecks {
    FileChecks {
        peak_friction: super::friction::peak_of_mf(t),
        longitudinal_turn: doc.and_then(|d| d.longitudinal_turn(t)),
    }
}

/// The checks of the tyre file `path` read as `tyre` (none for another
/// model; a `.tir` is read again for its lines).
pub(crate) fn of_tyre_file(path: &Path, tyre: &Tyre) -> FileChecks {
    let Tyre::MagicFormula(t) = tyre else {
        return FileChecks::default();
    };
    let is_tir = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("tir"));
    let doc = is_tir.then(|| TirDocument::read(path).ok()).flatten();
    checks_of(doc.as_ref(), t)
}

/// The checks of the `.tir` text `text` to be written at `path` (none
/// where it does not read as a Magic Formula file: the round trip says
/// why).
pub(crate) fn of_text(path: &Path, text: &str) -> FileChecks {
    let Ok(doc) = TirDocument::parse(path, text) else {
        return FileChecks::default();
    };
    match doc.template() {
        Ok(t) => checks_of(Some(&doc), &t),
        Err(_) => FileChecks::default(),
    }
}
