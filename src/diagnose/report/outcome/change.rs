//! What the verdict's effects did to a channel's held-out gap: one rule
//! ([`ChannelChange::of`]) that the terminal's before → after lines, the
//! page's table, `diagnosis.json`'s `shrinkage[].change` and the verdict's
//! warnings all read, so that none of them calls a change a removal that
//! another calls noise.
//!
//! Units: RMS values and noise floors in the channel's unit (rad/s, m/s²,
//! rad); shares in percent of the gap above noise
//! (`1 − sqrt(after² − nf²)/sqrt(before² − nf²)`,
//! [`crate::diagnose::model::channels`]).

use crate::diagnose::report::values::Shrinkage;

/// A channel's held-out RMS is above noise beyond this many noise floors
/// (the gap's rule per run, the gap summary's, the page's and the
/// verdict's warnings').
pub const SIGNIFICANT_NOISE_FLOORS: f64 = 3.0;

/// The scatter of held-out scores, as a share (%) of a channel's gap above
/// noise: a gap grown by more than this under the verdict's effects, to an
/// RMS above noise, is a worsening the combined error that accepted them
/// does not show; a change within it either way is no change (RMS 0.0061 →
/// 0.0062 on a 0.0020 floor, "−1 % removed" in round 38, is neither a removal nor a
/// worsening).
pub const WORSENED: f64 = 10.0;

/// Whether an RMS `rms` stands above a noise floor `noise_floor`: beyond
/// [`SIGNIFICANT_NOISE_FLOORS`] of it.
pub fn above_noise(rms: f64, noise_floor: f64) -> bool {
    rms > SIGNIFICANT_NOISE_FLOORS * noise_floor
}

/// What the verdict's effects did to a channel's held-out gap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ChannelChange {
    /// Before and after within noise: nothing to reduce, nothing made
    /// worse (a share of a gap within noise is noise).
    WithinNoise,
    /// A gap above noise before or after that changed by no more than
    /// [`WORSENED`] of itself either way (this share, %, negative: grew):
    /// within the scatter of held-out scores, no removal and no worsening.
    Unchanged(f64),
    /// The gap changed by this share (%, negative: grew), beyond the
    /// scatter, not a worsening.
    Changed(f64),
    /// A worsening: the gap above noise grew by this share (%) to an RMS
    /// above noise (infinite: from an RMS at or below the floor, no gap
    /// above noise to take a share of).
    Worsened(f64),
}

impl ChannelChange {
    /// The change from held-out RMS `before` to `after` on a noise floor
    /// `noise_floor`, `reduction_percent` of the gap above noise removed:
    /// within noise where neither RMS is [`above_noise`]; a worsening
    /// where the RMS after is above noise, larger than before, and the gap
    /// above noise grew by more than [`WORSENED`] (or from none: an RMS
    /// before at or below the floor); unchanged where it
    /// moved by no more than [`WORSENED`] either way; else the change.
    pub fn of(before: f64, after: f64, noise_floor: f64, reduction_percent: f64) -> Self {
        let (above_before, above_after) = (
            above_noise(before, noise_floor),
            above_noise(after, noise_floor),
        );
        if !above_before && !above_after {
            Self::WithinNoise
        } else if above_after && after > before && before <= noise_floor {
            // From no gap above noise at all (an RMS at or below its
            // floor, the share defined as 0) any gap above noise is a
            // worsening by no finite share: not "unchanged", not "0 %".
            Self::Worsened(f64::INFINITY)
        } else if above_after && after > before && reduction_percent < -WORSENED {
            Self::Worsened(-reduction_percent)
        } else if reduction_percent.abs() <= WORSENED {
            Self::Unchanged(reduction_percent)
        } else {
            Self::Changed(reduction_percent)
        }
    }
}

impl Shrinkage {
    /// What the verdict's effects did to this part's gap
    /// ([`ChannelChange::of`]).
    pub fn change(&self) -> ChannelChange {
        ChannelChange::of(
            self.before,
            self.after,
            self.noise_floor,
            self.reduction_percent,
        )
    }
}
