//! The cornering stiffness a `.tir` file's own coefficients give at its
//! `FNOMIN`, per unit of that load, judged as a TOML tyre's is
//! ([`crate::tyre::sizes::cornering_per_load`]): a `PKY1` with a slipped
//! digit (ten times a tyre's) passes every size check of a coefficient
//! (±1e6) and the pure curves' (its peak is `PDY1`'s), yet gives a tyre no
//! rig has measured.

use super::TirDocument;
use crate::error::{InputError, ParamError, ParamReason};
use crate::tyre::mf::MagicFormula;
use crate::tyre::sizes::MIN_CORNERING_PER_LOAD;

/// The largest cornering stiffness per unit of a tyre's own load at its
/// `FNOMIN`, `|Kyα|/Fz`, 1/rad. The public `.tir` files evaluated at their
/// FNOMIN (the thirteen in the shared data and the fixtures) lie at
/// 6.7–44 (a 430/50R38 tyre at 30 kN to car tyres; the FSAE default 36),
/// the TTC Hoosier 43075 rig file's slope at zero slip at 17–40 (2750 N to
/// 400 N), Gillespie's radial car tyres at 6.3–10.9 (*Fundamentals of
/// Vehicle Dynamics*, 1992, 0.11–0.19 per degree). The ceiling lies more
/// than twice above the stiffest of them; a `PKY1` ten times a car tyre's
/// (10–25) lands above it.
pub const MAX_CORNERING_PER_LOAD: f64 = 100.0;

/// The stiffness per unit load the slip hint aims at: the middle of the
/// published files' 6.7–44 (geometric), 1/rad.
const TYPICAL_PER_LOAD: f64 = 17.0;

impl TirDocument {
    /// Ok when the cornering stiffness `tyre` has at its `FNOMIN` (zero
    /// camber, nominal pressure: `PKY1·FNOMIN'·sin(PKY4·atan(1/PKY2))·LKY`
    /// with `FNOMIN' = FNOMIN·LFZO`, the same for MF 5.2, whose `PKY4` is
    /// 2, and 6.x) lies within [`MIN_CORNERING_PER_LOAD`] to
    /// [`MAX_CORNERING_PER_LOAD`] per unit of that load, in magnitude: the
    /// sign is the file's convention (`PKY1 < 0` in most files, `PKY1 > 0`
    /// with `PKY4 < 0` in MFeval's 6.1/6.2 samples: the same negative
    /// stiffness), a force against its slip the pure curves' check.
    /// Refused at `PKY1` with the stiffness, its share of the load, and the
    /// `PKY1` a slipped digit (or a stiffness per degree) would have had.
    pub(super) fn cornering_at_nominal(&self, tyre: &MagicFormula) -> Result<(), InputError> {
        if self.get("PKY1").is_none() {
            return Ok(());
        }
        cornering_per_load(tyre).map_or(Ok(()), |e| Err(self.value_error(e)))
    }
}

/// The refusal [`TirDocument::cornering_at_nominal`] gives a file of
/// `tyre`, at `PKY1`, without the file: what `identify` says of a fit
/// before it writes it (the readers refuse the file with these numbers).
pub fn cornering_per_load(tyre: &MagicFormula) -> Option<ParamError> {
    let c = &tyre.coefficients;
    let fz = c.FNOMIN;
    let fz0p = c.FNOMIN * c.LFZO;
    let x = (fz / fz0p) / c.PKY2;
    let kya = c.PKY1 * fz0p * (c.PKY4 * x.atan()).sin() * c.LKY;
    let per_load = (kya / fz).abs();
    // No stiffness at all is a file with no lateral force where it has no
    // lateral peak either (`PDY1 = PKY1 = 0`, as `identify` writes a
    // block no lateral data shaped; `LMUY = 0`): said by the evaluations'
    // checks (fy = 0 at a slip). With a peak, `PKY1 = 0` is a stiffness
    // below any tyre's as −0.5 is (its force the shifts' alone, the same
    // at every slip angle), refused alike.
    let no_lateral = c.PDY1 == 0.0 || c.LMUY == 0.0;
    if !per_load.is_finite()
        || (per_load == 0.0 && no_lateral)
        || (MIN_CORNERING_PER_LOAD..=MAX_CORNERING_PER_LOAD).contains(&per_load)
    {
        return None;
    }
    // The slip whose undoing lands it nearest a typical tyre: a digit
    // either way, or a stiffness written per degree (57.3 times small).
    let hint = [
        (0.1, false),
        (10.0, false),
        (180.0 / std::f64::consts::PI, true),
    ]
    .into_iter()
    .filter(|(f, _)| (MIN_CORNERING_PER_LOAD..=MAX_CORNERING_PER_LOAD).contains(&(per_load * f)))
    .min_by(|a, b| {
        let off = |f: f64| (per_load * f / TYPICAL_PER_LOAD).ln().abs();
        off(a.0).total_cmp(&off(b.0))
    });
    let reason = ParamReason::tir_cornering_per_load(
        (kya.abs(), fz, per_load),
        (MIN_CORNERING_PER_LOAD, MAX_CORNERING_PER_LOAD),
        hint.map(|(f, degrees)| (c.PKY1 * f, per_load * f, degrees)),
    );
    Some(ParamError::new("PKY1", c.PKY1, reason))
}
