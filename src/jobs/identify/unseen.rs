//! A swarm fit the data do not see, refused before anything is written:
//! no free parameter determined (each one's standard error larger than its
//! value, or the value on its search bound; the rest held) and a σ of
//! 100 % or more, the fit explaining no more of the data than a zero force.
//! Rig data whose slip angle stays within a fraction of a degree of 0 (a
//! braking test's lateral channel) gave such a fit at σ 100.002 % when
//! `--bin-deg 0` kept every sample; a file written from it is a tyre the
//! optimiser made up. Slips in rad (degrees in the words), σ in %.

use crate::error::{Error, FitError};
use crate::identify::data::Condition;
use crate::identify::{Channel, Fit, ParameterReport};

/// The σ at and above which a fit explains nothing: a zero force
/// misses by exactly 100 %.
const NOTHING_EXPLAINED_PERCENT: f64 = 100.0;

/// The slip angle past which a tyre's lateral force peaks, rad (4°), and
/// the slip ratio past which its longitudinal force does: a sweep short of
/// them is why the data see nothing; one past them that still sees
/// nothing points at the force's sign or a sweep on one side of 0.
const SWEPT_ALPHA: f64 = 0.0698;
const SWEPT_KAPPA: f64 = 0.1;

/// The largest |slip| (rad: slip angle, or slip ratio on a longitudinal
/// sweep) of the conditions' fit points.
fn slip_reach(conditions: &[Condition]) -> f64 {
    conditions
        .iter()
        .flat_map(|c| c.points.iter().map(|q| q.slip().abs()))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max)
}

/// Whether the data determine parameter `p`: free, its standard error
/// finite and below its magnitude, and its value inside its search bounds.
fn seen(p: &ParameterReport) -> bool {
    let (lo, hi) = p.bounds;
    let edge = 1e-9 * (hi - lo).abs().max(f64::MIN_POSITIVE);
    let on_bound = (p.value - lo).abs() <= edge || (hi - p.value).abs() <= edge;
    p.free
        && !on_bound
        && p.std_error
            .is_some_and(|se| se.is_finite() && se < p.value.abs())
}

/// Refuses `fit` (to `conditions`) where the data see none of its
/// parameters and it explains none of them ([`FitError::NotSeen`]).
pub(super) fn refuse_unseen(fit: &Fit, conditions: &[Condition]) -> Result<(), Error> {
    let explains_nothing =
        fit.sigma_percent.is_nan() || fit.sigma_percent >= NOTHING_EXPLAINED_PERCENT;
    if !explains_nothing || fit.parameters.iter().any(seen) {
        return Ok(());
    }
    let reach = slip_reach(conditions);
    let slip = match fit.channel {
        Channel::LongitudinalForce => (
            "|kappa|",
            crate::format::readable(reach, 3),
            if reach < SWEPT_KAPPA {
                " only: a longitudinal force is fitted from a slip-ratio sweep (`kappa` swept past the force's peak, 0.1 and beyond) at two loads or more"
            } else {
                ": check the force's sign (FORMATS.md: fx ≈ +C_kappa·kappa) and that each load's sweep crosses kappa = 0"
            },
        ),
        _ => (
            "|alpha|",
            format!("{}°", crate::format::readable(reach.to_degrees(), 3)),
            if reach < SWEPT_ALPHA {
                " only: a lateral force is fitted from a slip-angle sweep (`alpha` swept past the force's peak, 4° and beyond) at two loads or more"
            } else {
                ": check the force's sign (FORMATS.md: fy ≈ +C_alpha·alpha) and that each load's sweep crosses alpha = 0"
            },
        ),
    };
    Err(FitError::NotSeen {
        model: fit.model,
        quantity: fit.channel.quantity(),
        free: fit.parameters.iter().filter(|p| p.free).count(),
        sigma_percent: fit.sigma_percent,
        slip,
    }
    .into())
}
