//! `identify` of the models fitted by a swarm and a local polish (Zhang &
//! Li (2017), Zhang et al. (2021)): the first channel (lateral force, or
//! the longitudinal force of a file without lateral data) grouped into
//! conditions and fitted, PAC89's two stages beside it, then the aligning
//! moment and the longitudinal force where the data and the model have
//! them. Forces in N, slips in rad, as the rig file gives them (SI).

use super::holds::{held_by_fits, holds_of};
use super::{
    curvature, curvature_hold, flat_alpha, force_scale, further, linear_window, notes, on_data,
    output_lock, outputs, pure_rows, ranges, two_stage, written, LinearWindow, Options,
    SwarmReport,
};
use crate::error::{Error, FitError};
use crate::identify::data::Condition;
use crate::identify::data::RigData;
use crate::identify::grouping::{group, Grouped, Grouping, SlipAxis};
use crate::identify::lifted::without_lifted;
use crate::identify::pac89_two_stage::TwoStage;
use crate::identify::pooled::Pooled;
use crate::identify::{fit_channel_holding, start_tyre_of, Channel, Fit, FitSettings};
use crate::io::rig::read_rig_with_moments;
use crate::report::refuse_overwrites;
use crate::tyre::{Identification, ModelName, Tyre};

/// The swarm fit of `model`: the first channel, PAC89's two stages, the
/// aligning moment and the longitudinal force.
pub(super) fn run_swarm(o: &Options, model: ModelName) -> Result<SwarmReport, Error> {
    let settings = swarm_settings(o);
    let d = SwarmData::read(o, model)?;
    let grouping = grouping_of(o);
    // After a lateral fit, an `fx` without a slip-ratio sweep is no
    // longitudinal test: not fitted, and said so.
    let long_view = d
        .long_view
        .clone()
        .filter(|_| d.set_aside.has_kappa_sweep() || !d.lateral.has_lateral());
    let (first, grouped) = first_channel(o, &d.lateral, long_view.as_ref(), &grouping)?;
    let (conditions, window) = fitted_conditions(o, model, first, &grouped)?;
    let measured = match &d.whole {
        Some(whole) => d
            .measured
            .of_rows(whole, &d.moments, &grouped.report.selected),
        None => d.measured,
    }
    // Counted only where the file has a longitudinal sweep (`long_view`
    // kept): a cornering sweep's rows at alpha ≈ 0 and kappa = 0 are no
    // longitudinal test, and their `fx` no data left unfitted.
    .with_pure_fx(long_view.as_ref(), &grouped.report.selected);
    let tyre0 = start_tyre_of(model, median_load(&conditions))?;
    refuse_overwrites(&outputs(o, true), std::slice::from_ref(&o.data))?;
    let lock = output_lock(o)?;
    // Counted over the conditions fitted, not the file's levels.
    let pooled = Pooled::of(&tyre0, &grouped.report).among(&conditions);
    let (fit, stages) = first_fit(o, model, (&tyre0, first), &conditions, &settings, &grouped)?;
    let mut r = SwarmReport {
        tyre: fit.tyre.clone(),
        file: String::new(),
        fit,
        two_stage: None,
        pac89_reversal: None,
        curvature_held: None,
        written: None,
        linear_window: window,
        aligning: None,
        longitudinal: None,
        data: o.data.display().to_string(),
        recorded: o.recorded(),
        held: Vec::new(),
        notes: Vec::new(),
        flat_alpha: d.flat_alpha,
        lifted: d.lifted,
        at_rest: d.at_rest,
        measured,
        set_aside: d.set_aside,
        small_forces: force_scale::small_forces(&d.data),
        sample_slips: [None; 2],
        sample_spans: Vec::new(),
        grouping: grouped.report,
        longitudinal_grouping: None,
        options: o.clone(),
        loads_pooled: pooled.loads,
        pressures_pooled: pooled.pressures,
        cambers_pooled: pooled.cambers,
        conditions,
        longitudinal_conditions: Vec::new(),
        lock,
    };
    let first_data = match first {
        Channel::LongitudinalForce => long_view.as_ref().unwrap_or(&d.lateral),
        _ => &d.lateral,
    };
    ranges::set_first_sample_slips(&mut r, first_data);
    let inputs = further::Inputs {
        first,
        has_mz: d.data.mz.is_some(),
        long_view: long_view.as_ref(),
        grouping: &grouping,
        settings: &settings,
    };
    later_fits(o, &mut r, &tyre0, stages, inputs)?;
    super::unseen::refuse_unseen(&r.fit, &r.conditions).map_err(on_data(o, None))?;
    finish(o, &mut r)?;
    Ok(r)
}

/// The first channel's fit of `tyre0` to `conditions`, and PAC89's two
/// stages beside it where they are run. The two-stage identification fits
/// every coefficient: with a coefficient held with --hold it is not run
/// (the summary says so).
fn first_fit(
    o: &Options,
    model: ModelName,
    (tyre0, first): (&Tyre, Channel),
    conditions: &[Condition],
    settings: &FitSettings,
    grouped: &Grouped,
) -> Result<(Fit, Option<Result<TwoStage, FitError>>), Error> {
    let asks_two_stage = model.identification() == Identification::SwarmAndTwoStage
        && first == Channel::LateralForce
        && o.hold.is_empty();
    let (fit, stages) =
        two_stage::beside_direct(asks_two_stage, (tyre0, conditions), settings, || {
            fit_channel_holding(tyre0, first, conditions, settings, &o.hold)
        });
    let fit = fit
        .map_err(|e| thinned_too_far(e, &grouped.report, conditions))
        .map_err(on_data(o, None))?;
    Ok((fit, stages))
}

/// The fit's settings from the options `o`: the seed, the local polish,
/// and what the data do not determine held, not written where the
/// optimiser left it (`identify/undetermined.rs`).
fn swarm_settings(o: &Options) -> FitSettings {
    let mut settings = FitSettings::new(o.seed);
    settings.local = o.local.into();
    settings.hold_undetermined = true;
    settings
}

/// The median load of the `conditions`, N, which the start tyre is
/// built at.
fn median_load(conditions: &[Condition]) -> f64 {
    let mut loads: Vec<f64> = conditions.iter().map(|c| c.fz).collect();
    loads.sort_by(f64::total_cmp);
    loads[loads.len() / 2]
}

/// The rig data of a swarm fit as read: what was measured, the whole
/// file where a selection keeps part of it, the wheel moments, the
/// samples fitted (without a lifted wheel's, those at rest, or a lateral
/// force without slip angles), what was left out and why, and the pure
/// lateral and longitudinal rows with those set aside.
struct SwarmData {
    measured: super::Measured,
    whole: Option<RigData>,
    moments: [Option<Vec<f64>>; 2],
    data: RigData,
    lifted: Option<crate::identify::lifted::Lifted>,
    at_rest: Option<String>,
    flat_alpha: Option<String>,
    lateral: RigData,
    long_view: Option<RigData>,
    set_aside: crate::identify::pure::SetAside,
}

impl SwarmData {
    /// The data of `o` for `model`; a file without lateral data refused
    /// for a model without longitudinal terms.
    fn read(o: &Options, model: ModelName) -> Result<Self, Error> {
        // A lifted wheel's samples are no test condition (`identify/lifted.rs`).
        let (read, moments) = read_rig_with_moments(&o.data)?;
        let measured = super::Measured::of(&read, &moments);
        // The rows a selection keeps, to count what it leaves unfitted there.
        let selecting = o.load.is_some() || o.pressure.is_some() || o.camber.is_some();
        let whole = selecting.then(|| read.clone());
        let (data, lifted) = without_lifted(read);
        // Nor is a sample at rest, for any model (`standstill.rs`).
        let (data, _, at_rest) = super::standstill::without_rest(data, [None, None]);
        flat_alpha::refuse_flat_lateral(&data, &o.data)?;
        let (data, flat_alpha) = flat_alpha::without_flat_lateral(data);
        // Each force is fitted to its pure slip (`identify/pure.rs`).
        let (lateral, long_view, set_aside) = pure_rows::pure_rows(&data, &o.data, model.as_str())?;
        if !data.has_lateral() && start_tyre_of(model, 1.0)?.longitudinal_names().is_empty() {
            return Err(FitError::NoLateralData {
                data: o.data.clone(),
                model: model.as_str(),
            }
            .into());
        }
        Ok(SwarmData {
            measured,
            whole,
            moments,
            data,
            lifted,
            at_rest: at_rest.map(|r| r.line_of(false)),
            flat_alpha,
            lateral,
            long_view,
            set_aside,
        })
    }
}

/// The fits after the first channel's direct one: PAC89's two stages
/// beside it (the two free fits compared, then what the one written leaves
/// undetermined held, `two_stage.rs`), PAC89's curvature held where it
/// reverses, the aligning moment and the longitudinal force.
fn later_fits(
    o: &Options,
    r: &mut SwarmReport,
    tyre0: &Tyre,
    stages: Option<Result<TwoStage, FitError>>,
    inputs: further::Inputs,
) -> Result<(), Error> {
    if let Some(stages) = stages {
        two_stage::two_stage(o, r, tyre0, inputs.settings, stages)?;
    }
    if let Tyre::Pac89(_) = r.tyre {
        curvature_hold::hold_curvature(o, r, tyre0, inputs.settings)?;
    }
    further::aligning_and_longitudinal(o, r, inputs)
}

/// Too few points where the slip-angle bins merged samples, said with
/// the samples and the bin ([`FitError::TooFewBins`]): three rows 0.0025
/// rad apart, two of them in one 0.25° bin, were said as "2 points".
fn thinned_too_far(
    e: Error,
    report: &crate::identify::grouping::GroupingReport,
    conditions: &[Condition],
) -> Error {
    match e {
        Error::Fit(FitError::TooFewPoints {
            points,
            quantity,
            parameters,
        }) if report.used > points
            && report.slip_axis == crate::identify::grouping::SlipAxis::Angle
            && report.slip_bin > 0.0 =>
        {
            FitError::TooFewBins {
                samples: report.used,
                points,
                bin_deg: report.slip_bin.to_degrees(),
                quantity,
                parameters,
                conditions: conditions.len(),
            }
            .into()
        }
        e => e,
    }
}

/// The grouping the options ask for (load, pressure, camber selected;
/// the slip bins).
fn grouping_of(o: &Options) -> Grouping {
    Grouping {
        load: o.load,
        pressure: o.pressure,
        camber: o.camber,
        alpha_bin: o.alpha_bin_deg.to_radians(),
        kappa_bin: o.kappa_bin,
        ..Grouping::default()
    }
}

/// The channel fitted first and its data grouped into conditions: the
/// lateral force where the file has it, else the longitudinal force.
fn first_channel(
    o: &Options,
    lateral: &RigData,
    long_view: Option<&RigData>,
    grouping: &Grouping,
) -> Result<(Channel, Grouped), Error> {
    Ok(match (long_view, lateral.has_lateral()) {
        (_, true) => (
            Channel::LateralForce,
            group(&o.data, lateral, grouping, SlipAxis::Angle)?,
        ),
        (Some(view), false) => (
            Channel::LongitudinalForce,
            group(&o.data, view, grouping, SlipAxis::Ratio)?,
        ),
        (None, false) => {
            return Err(FitError::NoData {
                data: o.data.clone(),
            }
            .into())
        }
    })
}

/// The conditions the first channel is fitted to: a linear tyre's lateral
/// force to small slip only (a line through saturated data is a secant),
/// with the window it was cut to; none left is refused.
fn fitted_conditions(
    o: &Options,
    model: ModelName,
    first: Channel,
    grouped: &Grouped,
) -> Result<(Vec<Condition>, Option<LinearWindow>), Error> {
    let mut conditions = grouped.conditions.clone();
    let mut window = None;
    if model.as_str() == "linear" && first == Channel::LateralForce {
        let smallest = linear_window::smallest_slip(&conditions);
        let (kept, w) = linear_window::windowed(conditions, grouped.report.slip_bin);
        if kept.is_empty() && w.points_left_out > 0 {
            return Err(FitError::NoSmallSlip {
                data: o.data.clone(),
                window_deg: w.max_abs_alpha_deg,
                points: w.points_left_out,
                smallest_deg: smallest.to_degrees(),
            }
            .into());
        }
        conditions = kept;
        window = Some(w);
    }
    if conditions.is_empty() {
        return Err(FitError::NoCondition {
            data: o.data.clone(),
            grouping: grouped.report.account(),
        }
        .into());
    }
    Ok((conditions, window))
}

/// After the fits: a linear tyre's trail, the coefficients held (by
/// `--hold` and by the fits), every fitted value checked finite, PAC89's
/// reversal of its curve, the notes and the tyre file's text.
fn finish(o: &Options, r: &mut SwarmReport) -> Result<(), Error> {
    let trail = crate::identify::LINEAR_TRAIL;
    let given = o.hold.iter().find(|(n, _)| n == trail).map(|(_, v)| *v);
    if let Some(w) = r.linear_window.as_mut() {
        w.fit_trail(&mut r.tyre, &r.conditions, given);
    }
    let mut fitted: Vec<String> = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()]
        .into_iter()
        .flatten()
        .flat_map(|f| f.parameters.iter().map(|p| p.name.clone()))
        .collect();
    // A linear tyre's trail, set after its fit: applied where it was.
    if r.linear_window.is_some() {
        fitted.push(trail.into());
    }
    r.held = holds_of(o, &fitted);
    let fits = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()];
    r.held.extend(held_by_fits(
        &fits.into_iter().flatten().collect::<Vec<_>>(),
        &r.tyre,
    ));
    written::finite_fits(r).map_err(on_data(o, None))?;
    r.pac89_reversal = match (&r.tyre, r.fit.channel) {
        (Tyre::Pac89(p), Channel::LateralForce) => {
            curvature::pac89_reversal(p, &ranges::fitted_spans(r))
        }
        _ => None,
    };
    r.notes = notes::notes(r)
        .into_iter()
        .chain(super::offset::offset_note(
            &r.fit,
            &r.conditions,
            &r.level_names(),
        ))
        .chain(r.warning_notes())
        .collect();
    r.file = written::tyre_file_text(r, &o.output_path())?;
    Ok(())
}
