//! The longitudinal slip stiffness a `.tir` file's own coefficients give
//! across its own load range, judged when the file is read: `Kxκ =
//! Fz·(PKX1 + PKX2·dfz)·exp(PKX3·dfz)·LKX` (MF 5.2 and 6.x alike, at
//! `NOMPRES`; `dfz = (Fz − FNOMIN')/FNOMIN'`) changes sign where `PKX1 +
//! PKX2·dfz` crosses 0, the exponential being positive. The public
//! `FSAE_Defaults.tir` (`PKX1 = 50`, `PKX2 = −80`, `FNOMIN = 1000 N`)
//! turns negative from 1625 N, and its `FZMAX` is 2000 N: between them its
//! longitudinal force opposes its slip. Warned of, not refused: it is a
//! public file people use, and below 1625 N its forces are a tyre's; the
//! warning says it whatever loads are evaluated (a points file at 1000 N
//! would otherwise never learn of it).

use super::TirDocument;
use crate::format::exact;
use crate::tyre::mf::MagicFormula;
use std::fmt;
use std::path::PathBuf;

/// A longitudinal slip stiffness that is negative over part (or all) of a
/// `.tir` file's load range.
#[derive(Debug, Clone, PartialEq)]
pub struct LongitudinalTurn {
    /// The file.
    pub path: PathBuf,
    /// `PKX1` and its line.
    pub pkx1: (f64, usize),
    /// `PKX2` and its line (`None`: not in the file, 0).
    pub pkx2: (f64, Option<usize>),
    /// The load where `PKX1 + PKX2·dfz` is 0, N (`None`: negative over
    /// the whole range, no crossing in it).
    pub from: Option<f64>,
    /// Whether the stiffness is negative above `from` (else below).
    pub above: bool,
    /// The file's load range, N: `FZMIN` (0 where absent) and `FZMAX`
    /// with its line.
    pub range: (f64, f64, usize),
}

impl fmt::Display for LongitudinalTurn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = |v: f64| crate::format::readable(v, 4);
        let (lo, hi, hi_line) = self.range;
        let pkx2 = match self.pkx2.1 {
            Some(l) => format!("PKX2 = {} at line {l}", exact(self.pkx2.0)),
            None => "PKX2 = 0, absent".into(),
        };
        write!(
            f,
            "{}:{}: the longitudinal slip stiffness Kxκ = Fz·(PKX1 + PKX2·dfz)·exp(PKX3·dfz) \
             (PKX1 = {} at line {}, {pkx2}) ",
            self.path.display(),
            self.pkx1.1,
            exact(self.pkx1.0),
            self.pkx1.1,
        )?;
        match (self.from, self.above) {
            (Some(from), true) => write!(
                f,
                "turns negative from Fz = {} N, and the file's FZMAX = {} N (line {hi_line}) lies \
                 beyond it: from {} to {} N, inside the file's own load range",
                n(from),
                n(hi),
                n(from),
                n(hi)
            )?,
            (Some(from), false) => write!(
                f,
                "is negative below Fz = {} N, and the file's FZMIN = {} N lies below it: from {} to \
                 {} N, inside the file's own load range",
                n(from),
                n(lo),
                n(lo),
                n(from)
            )?,
            (None, _) => write!(
                f,
                "is negative over the file's whole load range, {} to {} N (FZMAX at line \
                 {hi_line}): there",
                n(lo),
                n(hi)
            )?,
        }
        write!(
            f,
            ", its longitudinal force opposes its slip (ISO 8855: a positive slip ratio gives a \
             positive force), so the forces evaluated there are the file's coefficients', not a \
             tyre's; check PKX1 and PKX2 (or keep the loads below that)"
        )
    }
}

impl TirDocument {
    /// The [`LongitudinalTurn`] of `tyre` (this file's) within its
    /// `FZMIN`–`FZMAX` at its `NOMPRES`, where the file gives `PKX1` and
    /// `FZMAX`; `None` where the stiffness keeps its sign there.
    pub fn longitudinal_turn(&self, tyre: &MagicFormula) -> Option<LongitudinalTurn> {
        let (pkx1_line, _) = self.get("PKX1")?;
        let (hi_line, _) = self.get("FZMAX")?;
        let c = &tyre.coefficients;
        let hi = tyre.limits.fz_max?;
        let lo = tyre.limits.fz_min.unwrap_or(0.0).max(0.0);
        let fz0 = c.FNOMIN * c.LFZO;
        if !(fz0 > 0.0 && hi > lo && c.LKX > 0.0) {
            return None;
        }
        // Kxκ/Fz's sign, a line in the load (the exponential is positive).
        let g = |fz: f64| c.PKX1 + c.PKX2 * (fz - fz0) / fz0;
        let (g_lo, g_hi) = (g(lo), g(hi));
        if g_lo >= 0.0 && g_hi >= 0.0 {
            return None;
        }
        let from = (g_lo > 0.0 || g_hi > 0.0).then(|| fz0 * (1.0 - c.PKX1 / c.PKX2));
        Some(LongitudinalTurn {
            path: self.path.clone(),
            pkx1: (c.PKX1, pkx1_line),
            pkx2: (c.PKX2, self.get("PKX2").map(|(l, _)| l)),
            from,
            above: g_hi <= 0.0,
            range: (lo, hi, hi_line),
        })
    }
}

/// The [`LongitudinalTurn`] of the `.tir` file `path` (`None` for another
/// file, or one that reads as no Magic Formula tyre: its reader says why).
pub fn longitudinal_turn(path: &std::path::Path) -> Option<LongitudinalTurn> {
    let is_tir = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("tir"));
    if !is_tir {
        return None;
    }
    let doc = TirDocument::read(path).ok()?;
    let tyre = doc.magic_formula().ok()?;
    doc.longitudinal_turn(&tyre)
}
