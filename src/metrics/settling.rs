//! Whether a step response has settled in its steady window: its spread
//! about the steady value beyond its white noise, within 2 % of the step,
//! or within what the noise leaves unknown of the step itself (a noisy
//! short log). Spreads and noises relative to the step (dimensionless).
//! A slow response can sit within that spread while still heading away
//! from its window's mean (an oversteering car near its critical speed
//! creeps towards a yaw rate 9 % above the window's): the window's trend,
//! its thirds' means extrapolated as a geometric approach, must also stay
//! within 2 % of the step ([`SETTLED_DRIFT`]).
//! A response settled by both that still trends, monotone across the
//! steady window and the one before it, by [`APPROACH_SAID`] or more (a
//! near-critical car's slow mode, time constant about 1 s, still rising
//! 6 s after its step: its gain 0.15 % short of the closed form) is said to
//! be approaching its steady value, with where its trend heads.
//! Where a rising lateral acceleration's trend heads is bounded by the
//! run's grip where it is known (`simulate`), and said as the window's
//! trend carried on where it is not (a measured record): [`limit`].
//! A channel whose step is within a few of its noise deviations is not
//! judged at all: its steady window's spread is its noise's, whatever the
//! car does (a synthetic 60 km/h step's sideslip moves 0.0033 rad under a
//! noise of 0.0019 rad).

use super::Normalised;
use serde::{Deserialize, Serialize};

mod grip;
mod limit;
mod null;
pub(crate) mod ringing;
mod trend;
pub use grip::AxlesGrip;
pub use limit::{AyLimit, AyLimitSource, Ceiling};
use null::noise_alone;
pub(super) use null::NoiseNull;
pub use null::FALSE_ALARM;
pub(super) use trend::{part_means, trend, trend_of_parts, Inside, Trend, TREND_PARTS};

/// The spread about the steady value, relative to the step, beyond which
/// a response has not settled.
pub(super) const SETTLED_SPREAD: f64 = 0.02;

/// How far, as a share of the step, the trend across the steady window may
/// still head beyond the window's mean: the spread's own tolerance, so a
/// response is judged settled by one measure of "within 2 %".
pub(super) const SETTLED_DRIFT: f64 = SETTLED_SPREAD;

/// How far, as a share of the step, a settled response's trend may still
/// head beyond its steady window's mean unsaid: a tenth of a percent, so
/// that a steady value printed to four decimals and 0.15 % short of the
/// steady state (a slow mode still rising) is not given as reached.
pub(super) const APPROACH_SAID: f64 = 0.001;

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
    /// Within its spread, but its trend across the steady window heads
    /// `heads` (a share of its step) beyond the window's mean, more than
    /// [`SETTLED_DRIFT`].
    Drifting {
        /// Where the trend heads beyond the window's mean, a share of the
        /// step (of the sideslip's scale, [`sideslip_scale`]).
        heads: f64,
        /// Whether the trend slows across the window (a geometric approach
        /// to a steady value); false where it holds or grows (a car
        /// leaving its steady turn).
        converging: bool,
        /// Whether it heads above the window's mean (on the step's scale);
        /// absent from a `metrics.json` written before it was kept.
        #[serde(default)]
        rising: bool,
    },
    /// Settled, but its trend across the steady window still heads `heads`
    /// (a share of its step, at least [`APPROACH_SAID`]) beyond the
    /// window's mean: its steady value not yet reached by about that much.
    Approaching {
        /// Where the trend heads beyond the window's mean, a share of the
        /// step (of the sideslip's scale).
        heads: f64,
        /// Whether it heads above the window's mean (on the step's scale).
        rising: bool,
    },
    /// A decaying oscillation still swings at the steady window by more
    /// than [`SETTLED_SPREAD`] of the step ([`ringing`]): the window's mean
    /// sits on a crest or a trough, whatever its spread.
    Oscillating {
        /// The swing left at the steady window (the envelope of its
        /// extrema there), a share of the step (of the sideslip's scale).
        amplitude: f64,
        /// Its period, s.
        period: f64,
        /// Where the oscillation's centre lies from the window's mean, a
        /// share of the step (of the sideslip's scale), above it where
        /// positive on the step's scale.
        centre: f64,
        /// When its last extremum is, s on the record's clock.
        last: f64,
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
    /// A noise-free record's verdict from its spread (a share of the step),
    /// its steady window's trend and how it moves inside that window.
    pub(super) fn of_spread(spread: f64, trend: Option<Trend>, inside: Inside) -> Self {
        let spread = turned(spread, inside, 1.0);
        if let Some(drift) = drifting(trend, 1.0, spread) {
            return drift;
        }
        match spread < SETTLED_SPREAD {
            false => Settling::NotSettled { beyond: spread },
            true => approaching(trend, 1.0),
        }
    }
}

impl ChannelSettling {
    /// Whether no channel judged has failed to settle.
    pub fn settled(&self) -> bool {
        let ok = |s: &Settling| {
            !matches!(
                s,
                Settling::NotSettled { .. }
                    | Settling::Drifting { .. }
                    | Settling::Oscillating { .. }
            )
        };
        ok(&self.yaw_rate) && self.ay.iter().all(ok) && self.beta.iter().all(ok)
    }

    /// Whether every channel that has not settled is only still
    /// converging to its steady value (none spreads, none drifts away): a
    /// slow response whose metrics a longer step would settle, not a car
    /// leaving its steady turn. The largest share still to go, if so.
    pub fn only_converging(&self) -> Option<f64> {
        let mut most: Option<f64> = None;
        for (_, _, s) in self.named() {
            match s {
                // A swing is no approach a trend carries on to.
                Settling::NotSettled { .. } | Settling::Oscillating { .. } => return None,
                Settling::Drifting {
                    converging: false, ..
                } => return None,
                Settling::Drifting { heads, .. } => {
                    most = Some(most.map_or(heads, |m| m.max(heads)))
                }
                Settling::Settled | Settling::Approaching { .. } | Settling::NotJudged { .. } => {}
            }
        }
        most
    }

    /// The largest share of its step a settled channel's trend still
    /// heads beyond its steady window's mean ([`Settling::Approaching`]),
    /// where one does: its steady value not reached by about that much.
    pub fn approaching(&self) -> Option<f64> {
        self.named()
            .into_iter()
            .filter_map(|(_, _, s)| match s {
                Settling::Approaching { heads, .. } => Some(heads),
                _ => None,
            })
            .reduce(f64::max)
    }

    /// Whether each channel's steady window still moves (the yaw rate's,
    /// the lateral acceleration's, the sideslip's): spread beyond its
    /// noise, swinging, or drifting towards a steady value (one drifting
    /// without slowing is no steady state at all, marked so apart); a
    /// sideslip's window also where it drifts without slowing (a grip
    /// limit's slide: its steady value is that window's mean either way).
    /// The one rule the sampled and the continuous metrics take their
    /// `*_window_moving` flags from, so `simulate` and `metrics` of one
    /// history mark alike.
    pub(super) fn windows_moving(&self) -> [bool; 3] {
        let moving = |s: Settling| {
            matches!(
                s,
                Settling::NotSettled { .. }
                    | Settling::Oscillating { .. }
                    | Settling::Drifting {
                        converging: true,
                        ..
                    }
            )
        };
        [
            moving(self.yaw_rate),
            self.ay.is_some_and(moving),
            self.beta
                .is_some_and(|b| moving(b) || matches!(b, Settling::Drifting { .. })),
        ]
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
    /// moves while the yaw rate and lateral acceleration hold; a yaw rate
    /// that has not settled makes the yaw-rate `gain` (1/s) no
    /// steady-state gain, said with how far it may be off.
    pub fn not_settled_warning(&self, gain: f64) -> Option<String> {
        self.not_settled_warning_within(gain, None)
    }

    /// [`Self::not_settled_warning`] of a run whose lateral acceleration's
    /// limit is known (`ceiling`, a simulation's) or not (`None`, a
    /// measured record's): where its trend heads is said as
    /// the `limit` module says it.
    pub fn not_settled_warning_within(
        &self,
        gain: f64,
        ceiling: Option<&Ceiling>,
    ) -> Option<String> {
        self.not_settled_warning_known(gain, ceiling, AxlesGrip::Unknown)
    }

    /// [`Self::not_settled_warning_within`] of a run that knows whether its
    /// axles reach their tyres' peak (`axles`): a sideslip moving while
    /// the yaw rate and lateral acceleration hold is said against it
    /// ([`grip::words`]).
    pub fn not_settled_warning_known(
        &self,
        gain: f64,
        ceiling: Option<&Ceiling>,
        axles: AxlesGrip,
    ) -> Option<String> {
        let named = self.named();
        let failed: Vec<String> = named
            .iter()
            .filter_map(|(name, _, s)| unsettled_words(name, s, ceiling))
            .collect();
        if failed.is_empty() {
            return None;
        }
        let held = |s: &Settling| matches!(s, Settling::Settled);
        // A sideslip that spreads, or drifts without slowing, beside a
        // yaw rate and ay that hold: a grip limit's slide.
        let grip = matches!(
            self.beta,
            Some(
                Settling::NotSettled { .. }
                    | Settling::Drifting {
                        converging: false,
                        ..
                    }
            )
        ) && held(&self.yaw_rate)
            && self.ay.iter().all(held);
        let grip = match grip {
            true => grip::words(axles),
            false => "",
        };
        // The yaw rate's spread or trend, a share of its step, is how far
        // the gain read from the window's mean may be off its steady state.
        // A drift that does not slow has no steady state to be off from:
        // its trend over one window bounds nothing (a yaw rate rising
        // linearly after the step read "off by up to about 4.9 %" with the
        // gain 28 % above the car's).
        // A spread is a deviation about the window's mean, no bound: a
        // sliding car's yaw rate spread 22 % of its step over a window its
        // values spanned 72 % of, said "off by up to about 22 %".
        let off = match self.yaw_rate {
            Settling::NotSettled { beyond } => Some((Some(beyond), true)),
            Settling::Drifting {
                heads, converging, ..
            } => Some((converging.then_some(heads), false)),
            _ => None,
        };
        let centre = match self.yaw_rate {
            Settling::Oscillating { centre, .. } => Some(centre),
            _ => None,
        };
        let gain = off.map_or_else(|| ringing::gain_words(centre, gain), |(off, spread)| {
            let pc = |off: f64| crate::format::significant(100.0 * off, 2);
            let bound = match off {
                Some(off) if spread => format!(
                    "by {} % of its step about the window's mean, a deviation and no bound: its values there range wider, and where it settles this record does not say",
                    pc(off)
                ),
                Some(off) => format!("it may be off by up to about {} %", pc(off)),
                None => "and it drifts without slowing, so this record bounds neither where it settles nor whether it does".to_string(),
            };
            format!(
                "; the yaw-rate gain, {} 1/s, is no steady-state gain: read over a window its yaw rate still moves in, {bound} (a longer record, held until the response settles, reads it)",
                crate::format::fixed(gain, 4),
            )
        });
        Some(format!(
            "the response has not settled in the steady window: {}, more than {} %{grip}{gain}",
            failed.join(", "),
            crate::error::Num(100.0 * SETTLED_SPREAD)
        ))
    }

    /// The warning of the channels settled but still approaching their
    /// steady values ([`Settling::Approaching`]), each with where its trend
    /// heads; with the yaw-rate `gain` (1/s) it heads to where the yaw
    /// rate approaches.
    pub fn approaching_warning(&self, gain: f64) -> Option<String> {
        self.approaching_warning_within(gain, None)
    }

    /// [`Self::approaching_warning`] with the lateral acceleration's limit
    /// known or not, as [`Self::not_settled_warning_within`] takes it.
    pub fn approaching_warning_within(
        &self,
        gain: f64,
        ceiling: Option<&Ceiling>,
    ) -> Option<String> {
        let mut yaw = None;
        let each: Vec<String> = self
            .named()
            .into_iter()
            .filter_map(|(name, _, s)| match s {
                Settling::Approaching { heads, rising } => {
                    if name == "yaw rate" {
                        yaw = Some(if rising { 1.0 + heads } else { 1.0 - heads });
                    }
                    Some(format!(
                        "the {name} still {} across its steady window, its trend {}",
                        if rising { "grows" } else { "falls back" },
                        limit::trend_words(
                            name,
                            (heads, rising),
                            ceiling,
                            (limit::Verb::Participle, "the window's mean")
                        ),
                    ))
                }
                _ => None,
            })
            .collect();
        if each.is_empty() {
            return None;
        }
        let gain = yaw.map_or(String::new(), |to| {
            format!(
                " (the yaw-rate gain {} 1/s heads to about {} 1/s)",
                crate::format::fixed(gain, 4),
                crate::format::significant(gain * to, 4)
            )
        });
        Some(format!(
            "the response is settled (within {} % of its step) but has not reached its steady state: {}; the steady values are short of it by about as much{gain}: a longer record, or a later steady window, reads them closer",
            crate::error::Num(100.0 * SETTLED_SPREAD),
            each.join(", ")
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

/// The words of one channel `name` that has not settled (`s`), none where
/// it has; where its trend heads is said as the `limit` module says it.
fn unsettled_words(name: &str, s: &Settling, ceiling: Option<&Ceiling>) -> Option<String> {
    match s {
        Settling::NotSettled { beyond } => Some(format!(
            "the {name} spreads by {} % of its step beyond its noise",
            crate::format::significant(100.0 * beyond, 2)
        )),
        Settling::Drifting {
            heads,
            converging,
            rising,
        } => Some(format!(
            "the {name} is still {}: the trend across its steady window {}",
            if *converging { "settling" } else { "drifting" },
            limit::trend_words(
                name,
                (*heads, *rising),
                ceiling,
                // A drift that does not slow has no steady value to head
                // beyond: its window's mean is the level.
                (
                    limit::Verb::Finite,
                    match converging {
                        true => "its steady value",
                        false => "its window's mean",
                    }
                )
            ),
        )),
        Settling::Oscillating {
            amplitude,
            period,
            centre,
            last,
        } => Some(ringing::words(name, *amplitude, *period, *centre, *last)),
        _ => None,
    }
}

/// `v` where the channel does not still swing at its steady window, else
/// [`Settling::Oscillating`]: `ring` (its oscillation, [`ringing`]) taken
/// to `to_scale` times the step, judged with the noise after the filter
/// that lifts its extrema, `noise` (a share of the step). A channel not
/// judged stays so. The one judge of a swing: `simulate`'s record with
/// no noise, a measured one with its lift ([`ringing::lift`]), which on a
/// history `simulate` wrote is its curvature's (3·10⁻⁷ of the sideslip's
/// step on the 80 m/s sedan's), so that one history gets one verdict from
/// both.
pub(super) fn with_ringing(
    v: Settling,
    ring: Option<ringing::Ringing>,
    to_scale: f64,
    noise: f64,
) -> Settling {
    match ring {
        Some(r)
            if !matches!(v, Settling::NotJudged { .. })
                && ringing::swing_left(&r, to_scale, noise) >= SETTLED_SPREAD =>
        {
            Settling::Oscillating {
                amplitude: r.amplitude * to_scale,
                period: r.period,
                centre: (r.centre - 1.0) * to_scale,
                last: r.last,
            }
        }
        _ => v,
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

/// The spread `beyond` (a share of the step, at `to_scale` times it) of a
/// response that turns inside its window ([`Inside`]) by more than the
/// spread allows: an overshoot not decayed has not settled, and its
/// window's mean may be off by about the window's range (a spread that
/// fails already bounds it: a window holding the rise ranges over most of
/// the step). One rule for a measured and a simulated record: a
/// simulated yaw rate climbing 4.5 % of its step across its window, its
/// spread 1.3 %, was called settled beside `metrics` on its own history.
fn turned(beyond: f64, inside: Inside, to_scale: f64) -> f64 {
    if beyond < SETTLED_SPREAD && inside.peak * to_scale >= SETTLED_SPREAD {
        beyond.max(SETTLED_SPREAD).max(inside.range * to_scale)
    } else {
        beyond
    }
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
/// The band is also widened to the spread beyond the noise that the
/// noise alone exceeds at [`FALSE_ALARM`] ([`noise_alone`], `null` the
/// filtered noise's correlation and the record's length).
pub(super) fn verdict(n: &Normalised, noise: f64, to_scale: f64, null: NoiseNull) -> Settling {
    let raw_noise = n.noise * n.steady.abs();
    if n.steady.abs() < JUDGED_NOISES * raw_noise {
        return Settling::NotJudged {
            step: n.steady,
            noise: raw_noise,
        };
    }
    let band = (2.0 * n.noise * to_scale * (2.0 / n.samples.max(1) as f64).sqrt())
        .max(noise_alone(noise * to_scale, n.steady_samples, null));
    let beyond = beyond_noise(n.spread * to_scale, noise * to_scale);
    let beyond = turned(beyond, n.inside, to_scale);
    // Within the band the noise leaves unknown of the step, no spread.
    let spread = if beyond >= band { beyond } else { 0.0 };
    if let Some(drift) = drifting(n.trend, to_scale, spread) {
        return drift;
    }
    if spread >= SETTLED_SPREAD {
        return Settling::NotSettled { beyond };
    }
    approaching(n.trend, to_scale)
}

/// The verdict on a response whose `trend` (taken to `to_scale` times the
/// step) moves one way across both windows and heads [`SETTLED_DRIFT`] or
/// more beyond its window's mean: drifting where its spread (`spread`, a
/// share of the step, 0 where within the noise's band) passes, and, where
/// the spread fails too, where the trend does not slow. A spread is a
/// deviation about the window's mean, and of a ramp it is a fraction of
/// the ramp's rise: a yaw rate rising 10 %/s to the record's end spread by
/// 2.1 % and was read "off by up to about 2.1 %" with its gain 40 % above
/// the car's; a trend that does not slow has no steady value to be off
/// from. A slowing trend with a failing spread stays a spread (not
/// settled), as a study's samples take it.
fn drifting(trend: Option<Trend>, to_scale: f64, spread: f64) -> Option<Settling> {
    let Trend {
        heads,
        converging,
        rising,
    } = trend?;
    let heads = heads * to_scale;
    let passes = spread < SETTLED_SPREAD;
    (heads >= SETTLED_DRIFT && (passes || !converging)).then_some(Settling::Drifting {
        heads,
        converging,
        rising,
    })
}

/// The verdict on a response settled by its spread and drift whose
/// `trend` (taken to `to_scale` times the step) still heads
/// [`APPROACH_SAID`] or more beyond its window's mean: approaching.
fn approaching(trend: Option<Trend>, to_scale: f64) -> Settling {
    match trend {
        Some(Trend { heads, rising, .. }) if heads * to_scale >= APPROACH_SAID => {
            Settling::Approaching {
                heads: heads * to_scale,
                rising,
            }
        }
        _ => Settling::Settled,
    }
}

#[cfg(test)]
mod tests;
