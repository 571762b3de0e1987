//! A simulated step's yaw-rate peak read on the rows: under RK4 (no dense
//! output) or a low-pass (the filter runs on the rows), the peak is the
//! highest row, not located between rows, so its time is resolved to half
//! the row interval, as a log's peak is to half its sample interval
//! (`metrics`' [`GRID_SAID`] rule). Under Dormand–Prince without a filter
//! the peak is located on the dense output and needs no such word. Times
//! in s.

use super::super::metrics::GRID_SAID;
use crate::io::Scenario;
use crate::metrics::StepMetrics;
use crate::sim::Method;

/// What is said of the peak time of `m` where it was read on the rows of
/// `sc`'s run every `sc.integrator.step` s and half that is [`GRID_SAID`]
/// of the peak time or more (a 0.05 s RK4 step's 0.025 s of a 0.35 s
/// peak); `None` where it was located on the dense output or the rows
/// resolve it.
pub(super) fn on_the_rows(sc: &Scenario, m: &StepMetrics) -> Option<String> {
    let tp = m.yaw_rate_peak_time?;
    let step = sc.integrator.step;
    let rows = match (sc.integrator.method, m.filter_hz) {
        (Method::Dopri5(_) | Method::Dop853(_), None) => return None,
        (Method::Rk4, None) => "a row of the RK4 run (no dense output to locate it between rows)",
        (_, Some(_)) => "a row of the low-passed record (the filter runs on the rows)",
    };
    let grid = 0.5 * step;
    (step.is_finite() && grid >= GRID_SAID * tp.abs()).then(|| {
        format!(
            "the yaw-rate peak time, {} s, is {rows}: it is resolved to ±{} s, half the {} s step ({} % of it){}; a smaller `step` reads it finer{}",
            crate::format::readable(tp, 4),
            crate::format::readable(grid, 2),
            crate::format::readable(step, 3),
            crate::format::rounded(100.0 * grid / tp.abs(), 2),
            match m.tb {
                Some(_) => ", and TB with it",
                None => "",
            },
            match sc.integrator.method {
                Method::Rk4 => ", as does Dormand–Prince (`method = \"dopri5\"`), which locates the peak on its dense output",
                Method::Dopri5(_) | Method::Dop853(_) => "",
            }
        )
    })
}
