//! Why a campaign's key is wrong for the campaign it is in: a Magic
//! Formula named as the rig model ([`StagedMagicFormula`]), a tyre model
//! named with no rig data to fit it to ([`TyreSourceError`]), a
//! `min_speed` outside the range any car's log is measured in. Speeds in
//! m/s.

pub use super::staged::{GivenTyres, StagedMagicFormula, TyreSourceError};
use thiserror::Error;

/// The highest `[diagnose] min_speed` taken, m/s (360 km/h): no car's
/// handling log is measured above it, so a larger value is a speed in
/// km/h, or a slip.
pub const MAX_MIN_SPEED: f64 = 100.0;

/// Why a campaign's key is wrong for its campaign.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CampaignReason {
    /// A Magic Formula named as a campaign's rig model.
    #[error(transparent)]
    StagedMagicFormula(StagedMagicFormula),
    /// A `[tyres] model` with no rig data to fit it to.
    #[error(transparent)]
    ModelWithoutRig(TyreSourceError),
    /// A `min_speed` outside `[0, MAX_MIN_SPEED]` (negative, not a
    /// number, or above: a speed in km/h, or a slip), m/s: said as the
    /// campaign file's other keys' ranges are, with a value to write.
    #[error("{}", min_speed_range(*min_speed, *default, *option))]
    MinSpeedRange {
        /// The value given, m/s.
        min_speed: f64,
        /// The default, advised where the value reads as no speed, m/s.
        default: f64,
        /// Given as `metrics --min-speed` (else a campaign's key): the
        /// value to write is said in that form.
        option: bool,
    },
}

/// `min_speed` (m/s) refused outside `[0, MAX_MIN_SPEED]` as
/// [`CampaignReason::MinSpeedRange`]: one range and one set of words for
/// a campaign's `[diagnose] min_speed` and `metrics --min-speed` (which
/// its parser refused in a form of its own, "the lowest speed kept is a
/// speed of 0 to 150 m/s", fresh-eyes round 39), `option` saying which.
pub fn min_speed_checked(
    min_speed: f64,
    default: f64,
    option: bool,
) -> Result<(), crate::error::ParamError> {
    if (0.0..=MAX_MIN_SPEED).contains(&min_speed) {
        return Ok(());
    }
    let reason = CampaignReason::MinSpeedRange {
        min_speed,
        default,
        option,
    };
    let reason = super::ParamReason::Campaign(Box::new(reason));
    Err(crate::error::ParamError::new(
        "min_speed",
        min_speed,
        reason,
    ))
}

/// The words of [`CampaignReason::MinSpeedRange`] for the value `v`, m/s:
/// the range, why it ends where it does, and what to write (the value in
/// km/h converted where it reads as one, else the `default`).
fn min_speed_range(v: f64, default: f64, option: bool) -> String {
    use crate::format::rounded;
    let written = |v: &str| match option {
        true => format!("`--min-speed {v}`"),
        false => format!("`min_speed = {v}`"),
    };
    let write = match v > MAX_MIN_SPEED && v / 3.6 <= MAX_MIN_SPEED {
        true => format!(
            "the {} is in m/s: is it in km/h? {} km/h is {} m/s: write {}",
            if option { "option" } else { "key" },
            rounded(v, 6),
            rounded(v / 3.6, 3),
            written(&rounded(v / 3.6, 3))
        ),
        false => format!(
            "write a speed in m/s, such as {} (the default)",
            written(&rounded(default, 3))
        ),
    };
    format!(
        "must lie in [0, {}]: it is the speed in m/s below which samples are left out as slow, and no car's handling log is measured above {} m/s ({} km/h); {write}",
        rounded(MAX_MIN_SPEED, 4),
        rounded(MAX_MIN_SPEED, 4),
        rounded(MAX_MIN_SPEED * 3.6, 4)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A negative, a NaN, a km/h and a far too high `min_speed` read one
    /// range and say what to write (main said "must not be negative",
    /// "must be a finite number" and "is above 100 m/s" in three forms).
    #[test]
    fn every_min_speed_refused_reads_one_range_and_what_to_write() {
        for v in [-1.0, f64::NAN, 200.0, 1000.0] {
            let e = CampaignReason::MinSpeedRange {
                min_speed: v,
                default: 5.0,
                option: false,
            }
            .to_string();
            assert!(e.starts_with("must lie in [0, 100]: it is the speed in m/s below which samples are left out as slow"), "{e}");
        }
        let km = CampaignReason::MinSpeedRange {
            min_speed: 200.0,
            default: 5.0,
            option: false,
        }
        .to_string();
        assert!(
            km.ends_with("is it in km/h? 200 km/h is 55.6 m/s: write `min_speed = 55.6`"),
            "{km}"
        );
        let far = CampaignReason::MinSpeedRange {
            min_speed: 1000.0,
            default: 5.0,
            option: false,
        }
        .to_string();
        assert!(
            far.ends_with("write a speed in m/s, such as `min_speed = 5` (the default)"),
            "{far}"
        );
        // `metrics --min-speed` reads the same, with the option's form.
        let e = min_speed_checked(200.0, 5.0, true).unwrap_err().to_string();
        assert!(
            e.starts_with("`min_speed` = 200: must lie in [0, 100]")
                && e.ends_with("the option is in m/s: is it in km/h? 200 km/h is 55.6 m/s: write `--min-speed 55.6`"),
            "{e}"
        );
        assert!(min_speed_checked(100.0, 5.0, true).is_ok());
    }
}
