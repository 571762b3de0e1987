//! Tyre rig data in memory (`docs/FORMATS.md`): the samples of a rig test,
//! the fit points made of them, and test points generated from a known tyre
//! at the identification papers' conditions. Reading a rig file is in
//! `io::rig`; grouping into test conditions and thinning in
//! [`super::grouping`].
//!
//! A fit point is typed by its sweep ([`Sweep`]): a cornering point carries
//! a slip angle, a lateral force and an aligning moment, a braking or
//! driving point a slip ratio and a longitudinal force, so no field means
//! one thing or another by context. Units: N, N·m, rad, Pa, m/s; slip ratio
//! dimensionless; signs as in `tyre/mod.rs`.

use crate::tyre::{SlipState, Tyre};
use serde::Serialize;

/// Rig samples.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RigData {
    /// Vertical load, N.
    pub fz: Vec<f64>,
    /// Slip angle, rad (0 in a file without lateral data).
    pub alpha: Vec<f64>,
    /// Lateral force, N (NaN in a file without lateral data).
    pub fy: Vec<f64>,
    /// Aligning moment, N·m (if measured).
    pub mz: Option<Vec<f64>>,
    /// Camber, rad (0 when absent).
    pub camber: Vec<f64>,
    /// Whether the file has a `camber` column.
    pub camber_measured: bool,
    /// Inflation pressure, Pa (if measured).
    pub pressure: Option<Vec<f64>>,
    /// Rig speed, m/s (if measured).
    pub speed: Option<Vec<f64>>,
    /// Longitudinal slip ratio and force (if a longitudinal test).
    pub longitudinal: Option<(Vec<f64>, Vec<f64>)>,
}

impl RigData {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.fz.len()
    }
    /// True without samples.
    pub fn is_empty(&self) -> bool {
        self.fz.is_empty()
    }
}

impl RigData {
    /// Whether lateral force was measured.
    pub(crate) fn has_lateral(&self) -> bool {
        self.fy.iter().any(|v| v.is_finite())
    }

    /// The longitudinal sweeps alone (`None` without them): the same
    /// samples with the lateral columns emptied (α 0, Fy NaN, no Mz).
    /// Grouped along [`SlipAxis::Ratio`], their points are longitudinal.
    pub(crate) fn longitudinal_view(&self) -> Option<RigData> {
        self.longitudinal.as_ref()?;
        let n = self.len();
        Some(RigData {
            alpha: vec![0.0; n],
            fy: vec![f64::NAN; n],
            mz: None,
            ..self.clone()
        })
    }
}

/// Which slip a sweep varies (and the thinning bins).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlipAxis {
    /// Slip angle (lateral data), rad.
    Angle,
    /// Slip ratio (longitudinal data).
    Ratio,
}

/// The sweep a fit point lies on and what was measured along it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sweep {
    /// Cornering at zero slip ratio.
    Lateral {
        /// Slip angle α, rad.
        alpha: f64,
        /// Lateral force Fy, N.
        fy: f64,
        /// Aligning moment Mz, N·m (NaN when not measured).
        mz: f64,
    },
    /// Braking or driving at zero slip angle.
    Longitudinal {
        /// Slip ratio κ.
        kappa: f64,
        /// Longitudinal force Fx, N.
        fx: f64,
    },
}

/// One fit point of a rig test: the wheel's state and what was measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigPoint {
    /// Vertical load, N.
    pub fz: f64,
    /// Camber, rad.
    pub camber: f64,
    /// Rig speed, m/s.
    pub speed: f64,
    /// The slip and the measured forces.
    pub sweep: Sweep,
}

/// The name the fits (`identify::FitProblem`, the CLI) use for a rig point.
pub type Point = RigPoint;

impl RigPoint {
    /// A cornering point (`mz` NaN when not measured).
    pub fn lateral(alpha: f64, fz: f64, camber: f64, speed: f64, fy: f64, mz: f64) -> Self {
        Self {
            fz,
            camber,
            speed,
            sweep: Sweep::Lateral { alpha, fy, mz },
        }
    }

    /// A braking or driving point.
    pub fn longitudinal(kappa: f64, fz: f64, camber: f64, speed: f64, fx: f64) -> Self {
        Self {
            fz,
            camber,
            speed,
            sweep: Sweep::Longitudinal { kappa, fx },
        }
    }

    /// A point at slip `slip` along `axis` where nothing was measured (the
    /// forces NaN): where a model curve is evaluated.
    pub(crate) fn unmeasured(axis: SlipAxis, slip: f64, fz: f64, camber: f64, speed: f64) -> Self {
        match axis {
            SlipAxis::Angle => Self::lateral(slip, fz, camber, speed, f64::NAN, f64::NAN),
            SlipAxis::Ratio => Self::longitudinal(slip, fz, camber, speed, f64::NAN),
        }
    }

    /// The slip the sweep varies.
    pub fn axis(&self) -> SlipAxis {
        match self.sweep {
            Sweep::Lateral { .. } => SlipAxis::Angle,
            Sweep::Longitudinal { .. } => SlipAxis::Ratio,
        }
    }

    /// The slip along the sweep: α (rad) or κ.
    pub fn slip(&self) -> f64 {
        match self.sweep {
            Sweep::Lateral { alpha, .. } => alpha,
            Sweep::Longitudinal { kappa, .. } => kappa,
        }
    }

    /// Measured lateral force, N (NaN on a longitudinal sweep).
    pub fn fy(&self) -> f64 {
        match self.sweep {
            Sweep::Lateral { fy, .. } => fy,
            Sweep::Longitudinal { .. } => f64::NAN,
        }
    }

    /// Measured aligning moment, N·m (NaN when not measured).
    pub fn mz(&self) -> f64 {
        match self.sweep {
            Sweep::Lateral { mz, .. } => mz,
            Sweep::Longitudinal { .. } => f64::NAN,
        }
    }

    /// Measured longitudinal force, N (NaN on a cornering sweep).
    pub fn fx(&self) -> f64 {
        match self.sweep {
            Sweep::Lateral { .. } => f64::NAN,
            Sweep::Longitudinal { fx, .. } => fx,
        }
    }

    /// The wheel's state at the point: the sweep's slip, the other slip 0,
    /// road friction as measured (μ scale 1).
    pub(crate) fn slip_state(&self) -> SlipState {
        let (alpha, kappa) = match self.sweep {
            Sweep::Lateral { alpha, .. } => (alpha, 0.0),
            Sweep::Longitudinal { kappa, .. } => (0.0, kappa),
        };
        SlipState {
            alpha,
            kappa,
            fz: self.fz,
            camber: self.camber,
            mu_scale: 1.0,
            speed: self.speed,
        }
    }
}

/// One test condition and its fit points.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Nominal load, N.
    pub fz: f64,
    /// Nominal camber, rad.
    pub camber: f64,
    /// Nominal pressure, Pa (if measured).
    pub pressure: Option<f64>,
    /// Raw samples in it.
    pub samples: usize,
    /// Fit points (thinned), all on the sweep grouped.
    pub points: Vec<RigPoint>,
}

/// Zhang & Li's (2017) test points generated from a known tyre: loads 2800 / 5700 /
/// 8600 N, slip angles 0 … ±12.0321° in 0.2865° steps (85 per load), camber
/// 0, 10 m/s, with multiplicative Gaussian noise of relative size `noise`
/// (seeded) on the lateral force and the aligning moment. Returns the
/// conditions and the lateral-force noise's own σ (%), the floor a fit
/// cannot beat on average.
pub fn identification_conditions(truth: &Tyre, noise: f64, seed: u64) -> (Vec<Condition>, f64) {
    use crate::tyre::TyreModel;
    use rand::SeedableRng;
    // Separate streams for Fy and Mz noise, so adding one channel does not
    // change the other's draws.
    let mut rng_fy = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut rng_mz = rand_chacha::ChaCha8Rng::seed_from_u64(seed ^ 0x9E37_79B9_7F4A_7C15);
    let (mut e2, mut y2) = (0.0, 0.0);
    let conditions = [2800.0, 5700.0, 8600.0]
        .iter()
        .map(|&fz| {
            let points: Vec<RigPoint> = (-42..=42)
                .map(|i| {
                    let alpha = (0.2865 * i as f64).to_radians();
                    let f = truth.forces(&SlipState {
                        speed: 10.0,
                        ..SlipState::lateral(alpha, fz)
                    });
                    let noisy = f.fy * (1.0 + noise * gauss(&mut rng_fy));
                    let noisy_mz = f.mz * (1.0 + noise * gauss(&mut rng_mz));
                    e2 += (noisy - f.fy) * (noisy - f.fy);
                    y2 += noisy * noisy;
                    RigPoint::lateral(alpha, fz, 0.0, 10.0, noisy, noisy_mz)
                })
                .collect();
            Condition {
                fz,
                camber: 0.0,
                pressure: None,
                samples: points.len(),
                points,
            }
        })
        .collect();
    (conditions, 100.0 * (e2 / y2).sqrt())
}

pub use crate::optim::stats::gauss;

/// `n` draws of white noise of standard deviation `sd` from seed `seed`
/// (the tests' logger noise).
#[cfg(test)]
pub(crate) fn white_noise(n: usize, sd: f64, seed: u64) -> Vec<f64> {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    (0..n).map(|_| sd * gauss(&mut rng)).collect()
}

/// Root mean square of `v` (tests).
#[cfg(test)]
pub(crate) fn rms(v: &[f64]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt()
}
