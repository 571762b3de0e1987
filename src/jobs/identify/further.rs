//! The swarm fit's channels after the first: the aligning moment and the
//! longitudinal force, each where the data have it and the model has one,
//! with the parameters already fitted held. A block no data set is
//! written as the model's defaults, which the note on it names: PAC89's
//! start leaves its aligning array unset (an aligning moment of 0), so
//! the defaults' values are written into the file, as the note says.

use super::{on_data, ranges, Options, SwarmReport};
use crate::error::Error;
use crate::identify::data::RigData;
use crate::identify::grouping::{group, Grouping, SlipAxis};
use crate::identify::{fit_channel_holding, Channel, FitSettings};

/// What the later channels are fitted from.
pub(super) struct Inputs<'a> {
    /// The channel fitted first.
    pub first: Channel,
    /// Whether the data have an `mz` column.
    pub has_mz: bool,
    /// The longitudinal data, where there is a slip-ratio sweep.
    pub long_view: Option<&'a RigData>,
    /// The grouping the first channel was fitted with.
    pub grouping: &'a Grouping,
    /// The fit's settings.
    pub settings: &'a FitSettings,
}

/// Fits the aligning moment and the longitudinal force of `r` (options
/// `o`), and writes the aligning defaults where no aligning fit ran.
pub(super) fn aligning_and_longitudinal(
    o: &Options,
    r: &mut SwarmReport,
    i: Inputs,
) -> Result<(), Error> {
    let lateral_first = i.first == Channel::LateralForce;
    if lateral_first && i.has_mz && !r.tyre.aligning_names().is_empty() {
        let mz = fit_channel_holding(
            &r.tyre,
            Channel::AligningMoment,
            &r.conditions,
            i.settings,
            &o.hold,
        )
        .map_err(on_data(o, Some("aligning moment")))?;
        r.tyre = mz.tyre.clone();
        r.aligning = Some(mz);
    } else if !r.tyre.aligning_names().is_empty() {
        // The defaults the note names, written (PAC89's unset `c` array
        // would give an aligning moment of 0, not the defaults').
        let defaults = r.tyre.aligning_parameters();
        r.tyre.set_aligning_parameters(&defaults);
    }
    // The longitudinal force with the same pressure and camber selection
    // as the lateral data.
    if let (Some(view), true, true) = (
        i.long_view,
        !r.tyre.longitudinal_names().is_empty(),
        lateral_first,
    ) {
        let g = group(&o.data, view, i.grouping, SlipAxis::Ratio)?;
        let fx = fit_channel_holding(
            &r.tyre,
            Channel::LongitudinalForce,
            &g.conditions,
            i.settings,
            &o.hold,
        )
        .map_err(on_data(o, Some("longitudinal force")))?;
        r.tyre = fx.tyre.clone();
        r.longitudinal = Some(fx);
        let (levels, inf) = (&g.report.levels, f64::INFINITY);
        let (slips, spans) =
            ranges::sample_reach(view, SlipAxis::Ratio, levels, &g.conditions, inf);
        r.sample_slips[1] = slips;
        r.sample_spans = ranges::union(&r.sample_spans, &spans);
        r.longitudinal_conditions = g.conditions;
        r.longitudinal_grouping = Some(g.report);
    }
    Ok(())
}
