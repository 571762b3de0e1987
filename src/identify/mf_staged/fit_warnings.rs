//! The warnings on a fitted stage as a whole, from the final tyre's σ:
//! a stage whose error is over half its channel's RMS was written
//! without a word (a combined `Mz` at σ 138 %), and one fitted on fewer
//! than five points per free parameter (13 rows for 7 parameters) too,
//! where the swarm fits warn of both.

use super::StageReport;

/// σ, % of the channel's RMS, above which a stage's fit is warned of as
/// not reproducing the data: a fit off by half the signal has the
/// channel's shape wrong, not its detail.
pub const LARGE_SIGMA_PERCENT: f64 = 50.0;

/// σ, % of the channel's RMS, above which a stage's channel is warned of
/// as not to be relied on (up to [`LARGE_SIGMA_PERCENT`]): the swarm
/// fits' threshold (`jobs/identify/notes.rs`), so that one fit's σ of
/// 49 % is not said where another's 21 % is.
pub const UNRELIABLE_SIGMA_PERCENT: f64 = 20.0;

/// Points per free parameter below which a fit is warned of as too few
/// data, a staged fit's stage here and the swarm fits' blocks in
/// `jobs/identify/notes.rs`: five, so that each parameter rests on more
/// points than a curve's handful (a fit of three parameters to five points
/// matches them exactly and says nothing of the tyre between or beyond).
pub const MIN_POINTS_PER_PARAMETER: usize = 5;

/// The warnings of the fitted stage `r`, its σ the final tyre's.
pub(super) fn fit_warnings(r: &StageReport) -> Vec<String> {
    let mut out = Vec::new();
    if r.sigma_percent > LARGE_SIGMA_PERCENT {
        out.push(format!(
            "σ {:.0} %, above {LARGE_SIGMA_PERCENT:.0} %: the fit does not reproduce the measured `{}` (its error is over half the channel's RMS); its coefficients are no model of these data",
            r.sigma_percent,
            r.stage.column()
        ));
    } else if r.sigma_percent > UNRELIABLE_SIGMA_PERCENT {
        out.push(format!(
            "σ {:.1} %, above {UNRELIABLE_SIGMA_PERCENT:.0} %: the fit misses the measured `{}` by more than a fifth of the channel's RMS; do not rely on the file's {}",
            r.sigma_percent,
            r.stage.column(),
            r.stage.quantity()
        ));
    }
    let free = r.parameters.iter().filter(|p| p.free).count();
    if r.points < MIN_POINTS_PER_PARAMETER * free {
        out.push(format!(
            "{} for {free} free parameters, fewer than the {MIN_POINTS_PER_PARAMETER} per parameter a fit needs to rest on the data rather than match them; do not rely on the tyre beyond the points",
            crate::format::plural(r.points, "point", "points"),
        ));
    }
    out
}
