//! The pure-slip rows of rig data, for the fits of one slip at a time
//! (the swarm fits of `identify`: a lateral force `Fy(α)` at κ = 0 and a
//! longitudinal force `Fx(κ)` at α = 0). A row with both slips is
//! combined slip: averaged into a pure curve's slip bin it drags the
//! curve down (a GIM fit of a file with rows at κ = 0.1 beside its
//! cornering sweep came out 17 % soft in cornering stiffness), so it is
//! set aside and counted.
//!
//! Rules (the staged Magic Formula fit's, [`PURE_TOL`]): a row is pure
//! lateral when |κ| ≤ 1e-3 (or the file has no `kappa`), pure
//! longitudinal when |α| ≤ 1e-3 rad (or the file has no lateral data).
//! A longitudinal sweep is fitted only where its pure rows reach
//! |κ| ≥ [`MIN_KAPPA_SWEEP`]: an `fx` column of zeros (or of the rig's
//! noise) at κ = 0 beside a cornering sweep is no longitudinal test.

use super::data::RigData;
use super::mf_staged::PURE_TOL;
use serde::Serialize;

/// The least |κ| a file's pure longitudinal rows must reach to be fitted
/// as a longitudinal sweep: 0.01, where a tyre's `Fx` is still on its
/// linear slope (a passenger tyre's peak lies near κ = 0.1), the rig
/// checks' [`crate::error::MIN_RIG_SLIP`].
pub const MIN_KAPPA_SWEEP: f64 = crate::error::MIN_RIG_SLIP;

/// What was set aside of a file for the pure-slip fits.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SetAside {
    /// Rows of the file.
    pub rows: usize,
    /// Rows of combined slip (|α| and |κ| both above [`PURE_TOL`]), left
    /// out of both fits.
    pub combined: usize,
    /// The largest |κ| of the pure longitudinal rows (`None`: no
    /// `kappa`/`fx` columns).
    pub kappa_reach: Option<f64>,
    /// The column of the pair `kappa`, `fx` the file lacks where it has
    /// the other (set by the reader of the file, which knows its header).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub missing_column: Option<&'static str>,
}

impl SetAside {
    /// Whether the pure longitudinal rows reach [`MIN_KAPPA_SWEEP`].
    pub fn has_kappa_sweep(&self) -> bool {
        self.kappa_reach.is_some_and(|k| k >= MIN_KAPPA_SWEEP)
    }

    /// The line saying how many rows a pure-slip fit of `model` left out
    /// as combined slip (`None`: none).
    pub fn combined_line(&self, model: &str) -> Option<String> {
        (self.combined > 0).then(|| {
            format!(
                "{} of the file's {} are combined slip (|alpha| > {PURE_TOL} rad and |kappa| > {PURE_TOL}), left out: the {model} model is fitted to pure slip only (its lateral force at kappa = 0, its longitudinal force at alpha = 0)",
                crate::format::plural(self.combined, "row", "rows"),
                self.rows
            )
        })
    }
}

/// The pure lateral rows of `d` (all where it has no `kappa`), the pure
/// longitudinal rows' view ([`RigData::longitudinal_view`]; `None`
/// without `kappa`/`fx`), and what was set aside.
pub fn split(d: &RigData) -> (RigData, Option<RigData>, SetAside) {
    let kappa = d.longitudinal.as_ref().map(|l| l.0.as_slice());
    let lateral_data = d.has_lateral();
    let pure_k = |i: usize| kappa.is_none_or(|k| k[i].abs() <= PURE_TOL);
    let pure_a = |i: usize| !lateral_data || d.alpha[i].abs() <= PURE_TOL;
    let lateral = d.rows(pure_k);
    let longitudinal = d.longitudinal_view().map(|v| v.rows(pure_a));
    let n = d.len();
    let set_aside = SetAside {
        rows: n,
        combined: (0..n).filter(|&i| !pure_k(i) && !pure_a(i)).count(),
        kappa_reach: kappa.map(|k| {
            (0..n)
                .filter(|&i| pure_a(i) && k[i].is_finite())
                .fold(0.0_f64, |m, i| m.max(k[i].abs()))
        }),
        missing_column: None,
    };
    (lateral, longitudinal, set_aside)
}

impl RigData {
    /// The rows `i` of the file for which `keep(i)`, every column alike.
    pub(crate) fn rows(&self, keep: impl Fn(usize) -> bool) -> RigData {
        let idx: Vec<usize> = (0..self.len()).filter(|&i| keep(i)).collect();
        let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
        RigData {
            fz: pick(&self.fz),
            alpha: pick(&self.alpha),
            fy: pick(&self.fy),
            mz: self.mz.as_deref().map(pick),
            camber: pick(&self.camber),
            camber_measured: self.camber_measured,
            pressure: self.pressure.as_deref().map(pick),
            speed: self.speed.as_deref().map(pick),
            longitudinal: self.longitudinal.as_ref().map(|(k, f)| (pick(k), pick(f))),
        }
    }
}
