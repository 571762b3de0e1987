//! Whether a step response has settled in its steady window: its spread
//! about the steady value beyond its white noise, within 2 % of the step,
//! or within what the noise leaves unknown of the step itself (a noisy
//! short log). Spreads and noises relative to the step (dimensionless).
//! A channel whose step is within a few of its noise deviations is not
//! judged at all: its steady window's spread is its noise's, whatever the
//! car does (a synthetic 60 km/h step's sideslip moves 0.0033 rad under a
//! noise of 0.0019 rad).

use super::Normalised;
use serde::{Deserialize, Serialize};

/// The spread about the steady value, relative to the step, beyond which
/// a response has not settled.
pub(super) const SETTLED_SPREAD: f64 = 0.02;

/// The noise deviations (of the raw channel) a step must exceed for its
/// settling to be judged: within them the step itself is uncertain by a
/// third or more, and the spread beyond the noise is the noise's own scatter.
pub const JUDGED_NOISES: f64 = 3.0;

/// The verdict on one channel's steady window.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "verdict")]
pub enum Settling {
    /// Within [`SETTLED_SPREAD`] of its step beyond its noise (or within
    /// what the noise leaves unknown of the step).
    #[default]
    Settled,
    /// Spread beyond its noise by `beyond` (a share of its step).
    NotSettled {
        /// The spread beyond the noise, a share of the step (of the
        /// sideslip's scale, [`sideslip_scale`]).
        beyond: f64,
    },
    /// Its step is within [`JUDGED_NOISES`] of its noise: not judged.
    NotJudged {
        /// The step, in the channel's unit (rad/s, m/s², rad).
        step: f64,
        /// The raw noise deviation, in the same unit.
        noise: f64,
    },
}

/// The verdict on each channel the metrics read.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ChannelSettling {
    /// The yaw rate's.
    pub yaw_rate: Settling,
    /// The lateral acceleration's (none without `ay`).
    pub ay: Option<Settling>,
    /// The sideslip's (none without `beta`).
    pub beta: Option<Settling>,
}

impl Settling {
    /// A noise-free record's verdict from its spread (a share of the step).
    pub(super) fn of_spread(spread: f64) -> Self {
        match spread < SETTLED_SPREAD {
            true => Settling::Settled,
            false => Settling::NotSettled { beyond: spread },
        }
    }
}

impl ChannelSettling {
    /// Whether no channel judged has failed to settle.
    pub fn settled(&self) -> bool {
        let ok = |s: &Settling| !matches!(s, Settling::NotSettled { .. });
        ok(&self.yaw_rate) && self.ay.iter().all(ok) && self.beta.iter().all(ok)
    }

    /// Each channel with its name and unit.
    fn named(&self) -> Vec<(&'static str, &'static str, Settling)> {
        let mut out = vec![("yaw rate", "rad/s", self.yaw_rate)];
        out.extend(self.ay.map(|s| ("lateral acceleration", "m/s²", s)));
        out.extend(self.beta.map(|s| ("sideslip", "rad", s)));
        out
    }

    /// The warning of the channels that have not settled, each named with
    /// its spread; the grip limit is named only where the sideslip alone
    /// moves while the yaw rate and lateral acceleration hold.
    pub fn not_settled_warning(&self) -> Option<String> {
        let named = self.named();
        let failed: Vec<String> = named
            .iter()
            .filter_map(|(name, _, s)| match s {
                Settling::NotSettled { beyond } => Some(format!(
                    "the {name} spreads by {} % of its step beyond its noise",
                    crate::format::significant(100.0 * beyond, 2)
                )),
                _ => None,
            })
            .collect();
        if failed.is_empty() {
            return None;
        }
        let held = |s: &Settling| matches!(s, Settling::Settled);
        let grip = matches!(self.beta, Some(Settling::NotSettled { .. }))
            && held(&self.yaw_rate)
            && self.ay.iter().all(held);
        let grip = match grip {
            true => "; the yaw rate and lateral acceleration have settled: at its grip limit a car can hold them while its sideslip grows",
            false => "",
        };
        Some(format!(
            "the response has not settled in the steady window: {}, more than {} %{grip}",
            failed.join(", "),
            crate::error::Num(100.0 * SETTLED_SPREAD)
        ))
    }

    /// The warnings of the channels whose settling is not judged, each
    /// with its step and noise.
    pub fn not_judged_warnings(&self) -> Vec<String> {
        self.named()
            .into_iter()
            .filter_map(|(name, unit, s)| match s {
                Settling::NotJudged { step, noise } => Some(format!(
                    "the {name}'s settling is not judged: its step of {} {unit} is {} times its noise deviation of {} {unit} (under {}), so the spread of its steady window is its noise's whatever the car does; its steady value is uncertain by as much, and the run's settling is judged on the other channels",
                    crate::format::significant(step, 3),
                    crate::format::significant(step.abs() / noise, 2),
                    crate::format::significant(noise, 2),
                    crate::error::Num(JUDGED_NOISES),
                )),
                _ => None,
            })
            .collect()
    }
}

/// The scale a sideslip's spread is judged on, rad: its step `beta_step`,
/// or the steer step `steer_step` where that is larger (a sideslip that
/// barely changes, near the speed where it changes sign, is not judged
/// against its own near-zero step). A car sliding at its grip limit keeps
/// its yaw rate and lateral acceleration while its sideslip grows: only
/// the sideslip shows that it has not settled.
pub(super) fn sideslip_scale(beta_step: f64, steer_step: f64) -> f64 {
    beta_step.abs().max(steer_step.abs())
}

/// The spread of a response beyond the white noise `noise` left in it
/// after the filter, `√(spread² − noise²)` (both relative to the step):
/// unfiltered, a gyro's noise of 3 % of the step is no motion.
fn beyond_noise(spread: f64, noise: f64) -> f64 {
    (spread * spread - noise * noise).max(0.0).sqrt()
}

/// The verdict on a measured response `n` whose noise after the filter is
/// `noise`, both taken to a scale `to_scale` times the step (1 but for the
/// sideslip, [`sideslip_scale`]): not judged where the step is within
/// [`JUDGED_NOISES`] of the raw noise; else within [`SETTLED_SPREAD`] beyond its noise, its band widened
/// to what the noise leaves unknown of the step itself: the step is the
/// difference of two window means of `N` samples, each uncertain by `σ/√N`
/// (σ the raw noise relative to the step), so it is known to `2·σ·√(2/N)`
/// (two deviations of the difference). A spread judged against a band
/// finer than the step is known to calls a noisy short log unsettled for
/// its noise; `√(2/N)` is also the relative deviation of a sample
/// variance, which the spread beyond the noise is judged by.
pub(super) fn verdict(n: &Normalised, noise: f64, to_scale: f64) -> Settling {
    let raw_noise = n.noise * n.steady.abs();
    if n.steady.abs() < JUDGED_NOISES * raw_noise {
        return Settling::NotJudged {
            step: n.steady,
            noise: raw_noise,
        };
    }
    let band = 2.0 * n.noise * to_scale * (2.0 / n.samples.max(1) as f64).sqrt();
    let beyond = beyond_noise(n.spread * to_scale, noise * to_scale);
    match beyond < SETTLED_SPREAD || beyond < band {
        true => Settling::Settled,
        false => Settling::NotSettled { beyond },
    }
}
