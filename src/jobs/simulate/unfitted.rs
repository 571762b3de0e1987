//! Tyres fitted to longitudinal data only: a tyre file whose
//! `[fitted_ranges]` (what `identify` writes) give a slip-ratio range and
//! no slip-angle range was fitted to a braking/driving sweep alone, and
//! its lateral coefficients are whatever the fit started from. Every
//! manoeuvre `simulate` runs steers the car, so its response rests on
//! lateral forces no data set: said once per axle (once for both where
//! they share the ranges). Slip ratio dimensionless.

use crate::io::fitted_ranges::FittedRanges;
use crate::io::Scenario;

/// The warnings of scenario `sc`'s tyres fitted to longitudinal data only.
pub(super) fn longitudinal_only(sc: &Scenario) -> Vec<String> {
    let only = |r: &Option<FittedRanges>| {
        r.as_ref()
            .filter(|r| r.alpha.is_none())
            .and_then(|r| r.kappa)
    };
    let [front, rear] = [only(&sc.fitted_ranges[0]), only(&sc.fitted_ranges[1])];
    let line = |axle: &str, k: [f64; 2]| {
        format!(
            "the {axle} were fitted to longitudinal data only (their `[fitted_ranges]` give a slip ratio of {} to {} and no slip angle): their lateral behaviour, which this steered run rests on, was never fitted to data (the lateral force is the model's starting coefficients); fit them to cornering data (`identify` on a file with `alpha` and `fy`)",
            crate::error::Num(k[0]),
            crate::error::Num(k[1])
        )
    };
    match (front, rear) {
        (Some(f), Some(r)) if f == r => vec![line("front and rear tyres", f)],
        (f, r) => [("front tyres", f), ("rear tyres", r)]
            .into_iter()
            .filter_map(|(axle, k)| k.map(|k| line(axle, k)))
            .collect(),
    }
}
