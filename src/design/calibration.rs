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
/// the campaign's runs bear that out. Each run's
/// `z = (χ²_B − χ²_A − D²)/(2D)` is exactly `−e·Δ/(σ²D)`, the reference's
/// residual `e` projected on the unit direction of the candidates'
/// difference `Δ`: standard normal on noise alone whatever D is, so every
/// run that separates the pair by [`CALIBRATING_D`] or more counts, and
/// their RMS is 1 on noise alone. Their replays are the candidates'
/// all-run fits, so the scatter is an in-sample one: a floor on what a new
/// run shows.
///
/// Each run is replayed from its settled start
/// ([`super::separation::settled_start`]), as a driven run is. From its
/// first sample, that sample's noise started both candidates off the
/// car's state and the transients that followed read as separation and
/// as scatter: a linear car logged 60 ms late, which the reference with
/// its delay matches to the noise, read D = 3.8 and 4.7 times the noise's
/// scatter from its first samples, D = 0.6 and 1.0 times settled. The
/// scatter so measured needs no switch on the reference's gap: it widens
/// every prediction by what it measures, 1 where the runs show noise
/// alone. A model-form error shows in it only along the differences the
/// campaign's runs show, which the summary says where the reference
/// leaves a gap above the noise ([`ReferenceGap::model_form`]): the
/// predictions then add the most that error can move a driven run
/// ([`ReferenceGap::along`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Calibration {
    /// The runs measured (D of at least [`CALIBRATING_D`]).
    pub runs: usize,
    /// RMS of their `z`, at least 1 (1 where no run is measured).
    pub inflation: f64,
    /// The reference's held-out error and the noise level it is read
    /// against.
    pub reference: ReferenceGap,
}

impl Calibration {
    /// The factor the noise's part of an uncertainty is widened by:
    /// [`Calibration::inflation`].
    pub fn widening(&self) -> f64 {
        self.inflation
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

    /// Whether the diagnosis calls that gap significant
    /// ([`crate::diagnose::rules::significant`]: J above 1.3 J_n).
    /// Below, the summary says the gap is within noise, as the diagnosis
    /// does, though the bound ([`ReferenceGap::along`]) still counts what
    /// J exceeds J_n by: it is smooth in the gap, no switch.
    pub fn significant(&self) -> bool {
        crate::diagnose::rules::significant(self.heldout_error, self.noise_level)
    }

    /// The model-form error's mean square per residual sample beyond the
    /// noise's, in the noise's units: `(J² − J_n²)/J_n²` where positive (J
    /// is the RMS residual per sample in the channels' scales, J_n the
    /// noise's alone), 0 where the reference matches to the noise.
    pub fn excess(&self) -> f64 {
        let (j, jn) = (self.heldout_error, self.noise_level);
        if jn > 0.0 && j > jn {
            (j * j - jn * jn) / (jn * jn)
        } else {
            0.0
        }
    }

    /// The most that model-form error of [`ReferenceGap::excess`] can add
    /// to a driven run's `z` along the candidates' difference, squared,
    /// over a run of `samples` residuals: `z = −e·Δ/(σ²D)` is at most
    /// `‖e‖/σ` (Cauchy–Schwarz), `√(excess·samples)` for the model-form part
    /// of `e`. The campaign's runs measure `z` only along the differences
    /// they show; a designed run that separates the pair far more may meet
    /// the error where they do not (the book's proving ground: campaign
    /// D = 0.5, driven runs 2.5–9.2 noise σ off a prediction the campaign's
    /// scatter alone widened). An upper bound, smooth in the gap: 0 at
    /// J ≤ J_n, so no switch.
    pub fn along(&self, samples: usize) -> f64 {
        self.excess() * samples as f64
    }
}

/// The least separation D of a campaign run whose measurement calibrates
/// the predictions ([`Calibration`]), noise floors: a tenth of one, so
/// that the candidates' difference `Δ` whose direction `z` is read along
/// is the model's, not the replays' rounding.
pub const CALIBRATING_D: f64 = 0.1;

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
