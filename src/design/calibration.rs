//! How well a design's predictions can be trusted: the scatter with which
//! the campaign's own runs measure the separations their replays predict
//! ([`Calibration`]), and the scale a measured separation is read on (the
//! signed root of `χ²_B − χ²_A`, [`signed_root`]) with its uncertainty
//! ([`root_uncertainty`]). Separations in noise floors (dimensionless).
//! The method is the project's own (the book's design chapter states it);
//! the widening by a measured scatter is the Birge ratio's idea (Birge
//! 1932) applied to the separation's statistic.

use serde::Serialize;

/// How the campaign's own runs measure the separation their replays
/// predict, for the reference and its weakest look-alike. On a run where
/// the reference is the car and the residuals are noise of the stated
/// floors, `χ²_B − χ²_A` is `D² ± 2D` ([`super::separation`]); a
/// model-form error the candidates share (a tyre the base model lacks)
/// adds a scatter along the candidates' difference that the floors do not
/// hold, and runs that favour the look-alike show as scatter too: a
/// prediction assumes the reference is the car, and this measures how far
/// the campaign's runs bear that out. Each
/// run's `z = (χ²_B − χ²_A − D²)/(2D)`, over the runs that separate the
/// pair by at least [`CALIBRATING_D`], measures it: their RMS is 1 on
/// such runs of noise alone. Their replays are the candidates' all-run
/// fits, so the scatter is an in-sample one: a floor on what a new run
/// shows.
///
/// It widens the predictions only where the reference leaves a gap above
/// the noise (its held-out error above the noise level: model-form error
/// for the scatter to stand for). A campaign run's replays start from its
/// first sample, whose noise starts both candidates off the car's state,
/// and the transient that follows moves `χ²_B − χ²_A` by more than their
/// difference (a sideslip a floor off is an ay several floors off for
/// tenths of a second): on a car the reference matches to the noise (a
/// linear car logged 60 ms late) that read as 4.7 times the noise's
/// scatter and called a test "not recommended" that separated the pair on
/// every run driven (5.8 ± 1.2 over eight seeds, the noise's ± 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Calibration {
    /// The runs measured (D of at least [`CALIBRATING_D`]).
    pub runs: usize,
    /// RMS of their `z`, at least 1 (1 where no run is measured).
    pub inflation: f64,
    /// Whether it widens the predictions: the reference leaves a gap above
    /// the noise ([`ReferenceGap::model_form`]).
    pub applied: bool,
    /// The reference's held-out error and the noise level it is read
    /// against.
    pub reference: ReferenceGap,
}

impl Calibration {
    /// The factor the noise's part of an uncertainty is widened by:
    /// [`Calibration::inflation`] where applied, else 1.
    pub fn widening(&self) -> f64 {
        if self.applied {
            self.inflation
        } else {
            1.0
        }
    }
}

/// The gap the reference leaves: its held-out error against the noise
/// level (the diagnosis's J after and J_n).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReferenceGap {
    /// The reference's held-out error J.
    pub heldout_error: f64,
    /// The held-out J of the noise alone.
    pub noise_level: f64,
}

impl ReferenceGap {
    /// Whether the reference leaves a gap above the noise (J > J_n, the
    /// diagnosis's "gap above noise" above 0): model-form error its
    /// replays do not hold.
    pub fn model_form(&self) -> bool {
        self.heldout_error > self.noise_level
    }
}

/// The least separation D of a campaign run whose measurement calibrates
/// the predictions ([`Calibration`]): below it the run says nothing of
/// the candidates' difference.
pub const CALIBRATING_D: f64 = 1.0;

/// [`Calibration`] from each run's `(D², χ²_B − χ²_A)`, for a reference
/// that leaves `gap`.
pub(crate) fn calibration(
    runs: impl Iterator<Item = (f64, f64)>,
    gap: ReferenceGap,
) -> Calibration {
    let z: Vec<f64> = runs
        .filter(|(d2, m)| *d2 >= CALIBRATING_D * CALIBRATING_D && m.is_finite())
        .map(|(d2, m)| (m - d2) / (2.0 * d2.sqrt()))
        .collect();
    let rms = (z.iter().map(|x| x * x).sum::<f64>() / z.len().max(1) as f64).sqrt();
    Calibration {
        runs: z.len(),
        inflation: if z.is_empty() { 1.0 } else { rms.max(1.0) },
        applied: gap.model_form(),
        reference: gap,
    }
}

/// The measured separation's scale: `sign(x)·√|x|` of `x = χ²_B − χ²_A`.
pub(crate) fn signed_root(x: f64) -> f64 {
    x.signum() * x.abs().sqrt()
}

/// The 1 σ uncertainty of [`signed_root`] of a quantity of mean `mean` and
/// standard deviation `sd`: half the root's change over `mean ± sd`, at
/// least the noise's 1. For a large mean that is `sd/(2√mean)`, the
/// delta method's; near 0, where the root's slope is infinite, it stays
/// finite (`√sd`), so a manoeuvre expected to separate nothing is said
/// to measure 0 ± a number, not ± ∞.
pub(crate) fn root_uncertainty(mean: f64, sd: f64) -> f64 {
    (0.5 * (signed_root(mean + sd) - signed_root(mean - sd))).max(1.0)
}
