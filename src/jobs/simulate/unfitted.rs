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

/// What `identify` writes into a `.tir` whose lateral force block it had
/// no pure lateral data for (its coefficients then the template's or the
/// defaults'): a `$` comment line starting so.
const TIR_LATERAL_UNFITTED: &str = "$ no pure lateral data: the lateral force block is not fitted";

/// The warnings of scenario `sc`'s `.tir` files that say their lateral
/// force block is not fitted (once per file): a `.tir` carries no
/// `[fitted_ranges]`, and a template's lateral block (an `FSAE_Defaults`)
/// reads as any tyre's.
pub(super) fn tir_lateral_unfitted(sc: &Scenario) -> Vec<String> {
    let mut files: Vec<&std::path::PathBuf> = sc
        .inputs
        .iter()
        .skip(1)
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("tir")))
        .collect();
    files.sort();
    files.dedup();
    files
        .into_iter()
        .filter_map(|p| {
            let text = std::fs::read(p).ok()?;
            let text = String::from_utf8_lossy(&text);
            let (k, line) = text
                .lines()
                .enumerate()
                .find(|(_, l)| l.trim_start().starts_with(TIR_LATERAL_UNFITTED))?;
            let said = line.trim_start().trim_start_matches('$').trim();
            Some(format!(
                "{}:{}: the file says its lateral force block was never fitted to data (\"{said}\"): the 2-DOF model steers on the lateral force alone, so this run's response rests on coefficients no measurement set; fit the tyre to cornering data (`identify` on a file with `alpha` and `fy`)",
                p.display(),
                k + 1
            ))
        })
        .collect()
}
