//! `identify` as one job: rig data in; a fitted tyre file, its JSON report
//! and its figure out. The models of [`crate::tyre::swarm_models`] are fitted by
//! a swarm and a local polish (Zhang & Li (2017), Zhang et al. (2021)):
//! lateral force first (or the longitudinal force of a file without lateral
//! data), then the aligning moment and the longitudinal force where the data
//! and the model have them; PAC89 also by Zhang et al.'s (2021) two-stage
//! identification, the better of the two written. The Magic Formula 6.1 /
//! 6.2 is fitted by Wei et al.'s (2010) staged Levenberg–Marquardt
//! ([`crate::identify::mf_staged`]) and written as a .tir ([`staged`]).

use crate::identify::data::Condition;
use crate::identify::grouping::{group, Grouping, GroupingReport, SlipAxis, Variable};
use crate::io::rig::read_rig;
mod choices;
mod curvature;
pub use curvature::{Curvature, CurvatureExcess, Pac89Reversal};
mod curvature_hold;
pub use curvature_hold::CurvatureHeld;
mod command;
pub use command::{RecordedHold, RecordedOptions};
mod linear_window;
mod nompres;
pub use linear_window::LinearWindow;
mod notes;
pub use notes::Note;
mod outputs;
mod pure_rows;
mod ranges;
mod summary;
mod written;
use outputs::{output_lock, outputs};
mod figures;
mod flat_alpha;
mod force_scale;
mod further;
mod holds;
pub use holds::Held;
use holds::{held_by_fits, holds_of};
mod staged;
mod two_stage;
pub use two_stage::{TwoStageReport, Written};
mod staged_figure;

use crate::error::{Error, FitError, Limit, NameKind, OptionsError, ParamError};
use crate::identify::{fit_channel_holding, start_tyre_of, Channel, Fit, FitSettings};
use crate::report::plot::Figure;
use crate::report::{refuse_overwrites, write_bytes, write_json_sorted, OutputLock};
use crate::tyre::mf::MfCoefficients;
use crate::tyre::{Identification, ModelName, SlipState, Tyre};
pub use choices::{IdentifyModel, Polish, StartArg};
use serde::Serialize;
use staged::run_staged;
pub use staged::StagedJob;
use std::path::PathBuf;

/// What `identify` is asked to do. The fields are public for struct
/// literals (the command line, Python); [`run`] checks them first
/// ([`Options::validate`]), so no fit starts from a bin or a level that is
/// not a number.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Rig data file.
    pub data: PathBuf,
    /// The model.
    pub model: IdentifyModel,
    /// Seed of the swarm.
    pub seed: u64,
    /// Tyre file to write (default: [`Options::output_path`]).
    pub out: Option<PathBuf>,
    /// Keep only the load level holding this value, N.
    pub load: Option<f64>,
    /// Keep only the pressure level holding this value, Pa.
    pub pressure: Option<f64>,
    /// Keep only the camber level holding this value, rad.
    pub camber: Option<f64>,
    /// The polish after the swarm.
    pub local: Polish,
    /// Slip-angle bin for thinning, degrees (0: none).
    pub alpha_bin_deg: f64,
    /// Slip-ratio bin for thinning (0: none).
    pub kappa_bin: f64,
    /// Magic Formula: where the parameters start.
    pub start: StartArg,
    /// Magic Formula: the .tir whose constants and layout are kept.
    pub template: Option<PathBuf>,
    /// Magic Formula: Levenberg–Marquardt iterations per step.
    pub max_iterations: usize,
    /// Magic Formula: coefficients held at a value the user gives
    /// (`.tir` name, value in the file's SI units), in every stage.
    pub hold: Vec<(String, f64)>,
}

impl Options {
    /// Checks the numbers: the bins (degrees, slip ratio) finite and
    /// non-negative, a pressure (Pa) positive, a camber (rad) finite; the
    /// error names the option as the command line and Python do
    /// (`bin_deg`, `bin_kappa`, `pressure`, `camber`).
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::non_negative("bin_deg", self.alpha_bin_deg)?;
        ParamError::non_negative("bin_kappa", self.kappa_bin)?;
        // 0 keeps every sample: the range is closed, [0, 2] (a lower end
        // a rounding guard below 0 reads so).
        let zero = -f64::MIN_POSITIVE;
        ParamError::in_range(
            "bin_deg",
            self.alpha_bin_deg,
            zero,
            2.0,
            Limit::SlipAngleBin,
        )?;
        ParamError::in_range("bin_kappa", self.kappa_bin, zero, 0.05, Limit::SlipRatioBin)?;
        if let Some(l) = self.load {
            ParamError::positive("load", l)?;
        }
        if let Some(p) = self.pressure {
            ParamError::positive("pressure", p)?;
        }
        if let Some(c) = self.camber {
            ParamError::finite("camber", c)?;
        }
        // No iteration is no fit: its report would read as one.
        ParamError::positive("max_iterations", self.max_iterations as f64)?;
        for (name, v) in &self.hold {
            ParamError::finite(name, *v)?;
            ParamError::in_range(name, *v, -1e6, 1e6, Limit::HoldValue)?;
        }
        Ok(())
    }

    /// Refuses `--load` / `--pressure` / `--camber` for a model whose fit takes every
    /// level (the staged Magic Formula): silently fitting all samples when
    /// one level was asked for would write a tyre of other conditions.
    fn validate_levels(&self) -> Result<(), Error> {
        if self.model.swarm_model().is_some() {
            return Ok(());
        }
        let given = [
            ("load", self.load),
            ("pressure", self.pressure),
            ("camber", self.camber),
        ];
        match given.iter().find(|(_, v)| v.is_some()) {
            Some((option, _)) => Err(OptionsError::LevelSelectionNotTaken {
                option,
                model: self.model.to_string(),
            }
            .into()),
            None => Ok(()),
        }
    }

    /// Checks the `--hold` names: coefficients of a `.tir` for the staged
    /// Magic Formula fit, the model's parameters (every block it fits:
    /// lateral, aligning, longitudinal) for a swarm fit.
    fn validate_holds(&self) -> Result<(), Error> {
        if self.hold.is_empty() {
            return Ok(());
        }
        for (i, (name, v)) in self.hold.iter().enumerate() {
            if let Some((_, first)) = self.hold[..i].iter().find(|(n, _)| n == name) {
                return Err(OptionsError::HoldTwice {
                    name: name.clone(),
                    first: *first,
                    second: *v,
                }
                .into());
            }
        }
        let Some(model) = self.model.swarm_model() else {
            for (name, _) in &self.hold {
                crate::error::named(MfCoefficients::NAMES, |k| k, NameKind::MfCoefficient, name)?;
            }
            return holds::check_hold_values(None, &self.hold);
        };
        let known = crate::identify::fitted_names(&start_tyre_of(model, 1.0)?);
        for (name, _) in &self.hold {
            if !known.contains(name) {
                return Err(OptionsError::UnknownHold {
                    model: model.as_str().into(),
                    given: name.clone(),
                    known,
                }
                .into());
            }
        }
        holds::check_hold_values(Some(model), &self.hold)
    }
}

/// The report of `identify`: `<out>.report.json` holds its serialised form.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum IdentifyReport {
    /// A swarm fit.
    Swarm(Box<SwarmReport>),
    /// The staged Magic Formula fit.
    Staged(Box<StagedJob>),
}

/// The report of a swarm fit: the lateral (or longitudinal) fit, then the
/// further channels fitted with it held.
#[derive(Debug, Clone, Serialize)]
pub struct SwarmReport {
    /// The first channel's direct fit.
    #[serde(flatten)]
    pub fit: Fit,
    /// PAC89: the two-stage identification.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub two_stage: Option<TwoStageReport>,
    /// PAC89: which fit was written.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub written: Option<Written>,
    /// `--model linear`: the small-slip window fitted, the points left
    /// out and the pneumatic trail.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub linear_window: Option<LinearWindow>,
    /// PAC89: its lateral curvature `E` above 1 over the fitted loads and
    /// where its lateral force changes sign.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pac89_reversal: Option<Pac89Reversal>,
    /// PAC89: the lateral curvature held at its limit where the free fit's
    /// reversed the force, and that fit's σ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curvature_held: Option<CurvatureHeld>,
    /// The aligning moment's fit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub aligning: Option<Fit>,
    /// The longitudinal force's fit after a lateral one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub longitudinal: Option<Fit>,
    /// The data file.
    pub data: String,
    /// The options that change the fit, and the command that repeats it.
    #[serde(rename = "options")]
    pub recorded: RecordedOptions,
    /// The parameters held with `--hold`.
    pub held: Vec<Held>,
    /// What the terminal and the file's header say beside the numbers:
    /// a parameter fitted by a later channel, a block not fitted, a
    /// level pooled into a model without terms for it, a parameter not
    /// identified.
    pub notes: Vec<Note>,
    /// The lateral columns set aside at `alpha` 0 throughout, said.
    pub flat_alpha: Option<String>,
    /// The rows of combined slip left out, and the slip ratios reached.
    pub set_aside: crate::identify::pure::SetAside,
    /// The rig's forces far too small for their loads (`force_scale.rs`).
    #[serde(skip)]
    pub small_forces: Vec<String>,
    /// The extremes of the samples' slip angle and slip ratio fitted.
    #[serde(skip)]
    pub sample_slips: [Option<(f64, f64)>; 2],
    /// Where every sample went.
    pub grouping: GroupingReport,
    /// The same for the longitudinal data fitted after a lateral fit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub longitudinal_grouping: Option<GroupingReport>,
    /// The tyre written (every channel fitted).
    #[serde(skip)]
    pub tyre: Tyre,
    /// The text of the tyre file, its header included, checked to be read
    /// back by the tyre reader.
    #[serde(skip)]
    pub file: String,
    /// What the job was asked.
    #[serde(skip)]
    pub options: Options,
    /// Load levels pooled into one fit of a model whose force does not
    /// change with load (a warning when more than one; 0 for a model
    /// whose force does).
    #[serde(skip)]
    pub loads_pooled: usize,
    /// Pressure levels pooled into one fit (a warning when more than one).
    #[serde(skip)]
    pub pressures_pooled: usize,
    /// Camber levels pooled into one fit of a model without camber terms
    /// (a warning when more than one; 0 for a model with them).
    #[serde(skip)]
    pub cambers_pooled: usize,
    /// The conditions of the first channel.
    #[serde(skip)]
    pub conditions: Vec<Condition>,
    /// The longitudinal conditions after a lateral fit.
    #[serde(skip)]
    pub longitudinal_conditions: Vec<Condition>,
    /// The outputs, held for this run until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
}

impl IdentifyReport {
    /// The tyre file, the report and (swarm fits) the figure.
    pub fn outputs(&self) -> Vec<PathBuf> {
        match self {
            IdentifyReport::Swarm(r) => outputs(&r.options, true),
            IdentifyReport::Staged(r) => outputs(&r.options, true),
        }
    }

    /// Warnings on the fit's inputs: levels pooled into a model without
    /// terms for them.
    pub fn warnings(&self) -> Vec<String> {
        match self {
            IdentifyReport::Swarm(r) => r.input_warnings(),
            IdentifyReport::Staged(_) => Vec::new(),
        }
    }

    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        match self {
            IdentifyReport::Swarm(r) => r.summary(),
            IdentifyReport::Staged(r) => r.summary(),
        }
    }

    /// The figure written beside the tyre file: measured against fitted.
    pub fn figure(&self) -> Figure {
        match self {
            IdentifyReport::Swarm(r) => figures::fit_figure(r),
            IdentifyReport::Staged(r) => r.figure.clone(),
        }
    }

    /// Writes the tyre file, the report and the figure.
    pub fn write(&self) -> Result<(), Error> {
        let files = self.outputs();
        match self {
            IdentifyReport::Swarm(r) => {
                write_bytes(&files[0], r.file.as_bytes())?;
                write_json_sorted(&files[1], r)?;
                self.figure().save(&files[2])
            }
            IdentifyReport::Staged(r) => {
                write_bytes(&files[0], r.tir.as_bytes())?;
                write_json_sorted(&files[1], r)?;
                r.figure.save(&files[2])
            }
        }
    }

    /// The closing line: what was written.
    pub fn wrote(&self) -> String {
        let f: Vec<String> = self
            .outputs()
            .iter()
            .map(|p| p.display().to_string())
            .collect();
        match self {
            IdentifyReport::Swarm(_) => format!("wrote {}, {} and {}", f[0], f[1], f[2]),
            IdentifyReport::Staged(r) => format!(
                "identified in {:.2} s; wrote {}, {} and {}",
                r.report.seconds, f[0], f[1], f[2]
            ),
        }
    }
}

/// Runs `identify`: checks the options, reads and groups the data, fits,
/// and returns the report (nothing is written: [`IdentifyReport::write`]).
/// An output that is one of the inputs is refused before anything is
/// fitted.
pub fn run(o: &Options) -> Result<IdentifyReport, Error> {
    o.validate()?;
    o.validate_holds()?;
    o.validate_levels()?;
    o.validate_out()?;
    match o.model {
        IdentifyModel::Swarm(model) => {
            run_swarm(o, model).map(|r| IdentifyReport::Swarm(Box::new(r)))
        }
        IdentifyModel::Staged(_, fit) => {
            run_staged(o, fit).map(|r| IdentifyReport::Staged(Box::new(r)))
        }
    }
}

/// A failure of a fit to the data of `o`, of `channel` where named.
pub(super) fn on_data<'a>(
    o: &'a Options,
    channel: Option<&'static str>,
) -> impl Fn(Error) -> Error + 'a {
    move |e| FitError::in_data(&o.data, channel, e).into()
}

/// The swarm fit of `model`: the first channel, PAC89's two stages, the
/// aligning moment and the longitudinal force.
fn run_swarm(o: &Options, model: ModelName) -> Result<SwarmReport, Error> {
    let mut settings = FitSettings::new(o.seed);
    settings.local = o.local.into();
    // What the data do not determine is held, not written where the
    // optimiser left it (`identify/undetermined.rs`).
    settings.hold_undetermined = true;
    let (data, flat_alpha) = flat_alpha::without_flat_lateral(read_rig(&o.data)?);
    // Each force is fitted to its pure slip (`identify/pure.rs`).
    let (lateral, long_view, set_aside) = pure_rows::pure_rows(&data, &o.data, model.as_str())?;
    if !data.has_lateral() && start_tyre_of(model, 1.0)?.longitudinal_names().is_empty() {
        return Err(FitError::NoLateralData {
            data: o.data.clone(),
            model: model.as_str(),
        }
        .into());
    }
    let grouping = Grouping {
        load: o.load,
        pressure: o.pressure,
        camber: o.camber,
        alpha_bin: o.alpha_bin_deg.to_radians(),
        kappa_bin: o.kappa_bin,
        ..Grouping::default()
    };
    // After a lateral fit, an `fx` without a slip-ratio sweep is no
    // longitudinal test: not fitted, and said so.
    let long_view = long_view.filter(|_| set_aside.has_kappa_sweep() || !lateral.has_lateral());
    let (first, grouped) = match (&long_view, lateral.has_lateral()) {
        (_, true) => (
            Channel::LateralForce,
            group(&o.data, &lateral, &grouping, SlipAxis::Angle)?,
        ),
        (Some(view), false) => (
            Channel::LongitudinalForce,
            group(&o.data, view, &grouping, SlipAxis::Ratio)?,
        ),
        (None, false) => {
            return Err(FitError::NoData {
                data: o.data.clone(),
            }
            .into())
        }
    };
    let mut conditions = grouped.conditions;
    // A linear tyre is fitted to small slip only (a line through saturated
    // data is a secant).
    let mut window = None;
    if model.as_str() == "linear" && first == Channel::LateralForce {
        let smallest = linear_window::smallest_slip(&conditions);
        let (kept, w) = linear_window::windowed(conditions);
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
    let mut loads: Vec<f64> = conditions.iter().map(|c| c.fz).collect();
    loads.sort_by(f64::total_cmp);
    let tyre0 = start_tyre_of(model, loads[loads.len() / 2])?;
    refuse_overwrites(&outputs(o, true), std::slice::from_ref(&o.data))?;
    let lock = output_lock(o)?;
    // The models fitted here have no pressure terms: several pressures
    // pooled into one parameter set blur their differences into the fit.
    let levels_of = |v: Variable| {
        grouped
            .report
            .levels
            .iter()
            .find(|l| l.variable == v)
            .map_or(0, |l| l.levels.len())
    };
    let pressures_pooled = levels_of(Variable::Pressure);
    // A model whose lateral fit frees nothing more with more cambers has
    // no camber terms: pooled cambers blur into it alike.
    let many = 1000;
    let camber_terms = tyre0.lateral_free(many, many) != tyre0.lateral_free(many, 1);
    let cambers_pooled = if camber_terms {
        0
    } else {
        levels_of(Variable::Camber)
    };
    // A model whose force is the same at two loads (a linear tyre's
    // C·α) has no load terms: pooled loads blur into its one stiffness.
    let at = |fz| tyre0.point_forces(&SlipState::lateral(0.02, fz), None).fy;
    let loads_pooled = if at(1000.0) == at(3000.0) {
        levels_of(Variable::Load)
    } else {
        0
    };
    // The two-stage identification fits every coefficient: with a
    // coefficient held with --hold it is not run (the summary says so).
    let asks_two_stage = model.identification() == Identification::SwarmAndTwoStage
        && first == Channel::LateralForce
        && o.hold.is_empty();
    let (fit, stages) = two_stage::beside_direct(asks_two_stage, &conditions, &settings, || {
        fit_channel_holding(&tyre0, first, &conditions, &settings, &o.hold)
    });
    let fit = fit.map_err(on_data(o, None))?;
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
        flat_alpha,
        set_aside,
        small_forces: force_scale::small_forces(&data),
        sample_slips: [None; 2],
        grouping: grouped.report,
        longitudinal_grouping: None,
        options: o.clone(),
        loads_pooled,
        pressures_pooled,
        cambers_pooled,
        conditions,
        longitudinal_conditions: Vec::new(),
        lock,
    };
    let first_data = match first {
        Channel::LongitudinalForce => long_view.as_ref().unwrap_or(&lateral),
        _ => &lateral,
    };
    ranges::set_first_sample_slips(&mut r, first_data);
    // The two-stage result runs beside the rule that holds what the data
    // do not determine: the two free fits are compared, and the rule then
    // holds what the one written leaves undetermined (`two_stage.rs`).
    if let Some(stages) = stages {
        two_stage::two_stage(o, &mut r, &tyre0, &settings, stages)?;
    }
    if let Tyre::Pac89(_) = r.tyre {
        curvature_hold::hold_curvature(o, &mut r, &tyre0, &settings)?;
    }
    further::aligning_and_longitudinal(
        o,
        &mut r,
        further::Inputs {
            first,
            has_mz: data.mz.is_some(),
            long_view: long_view.as_ref(),
            grouping: &grouping,
            settings: &settings,
        },
    )?;
    if let Some(w) = r.linear_window.as_mut() {
        w.pneumatic_trail = linear_window::trail(&r.conditions);
        linear_window::set_trail(&mut r.tyre, w.pneumatic_trail.unwrap_or(0.0));
    }
    let fitted: Vec<String> = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()]
        .into_iter()
        .flatten()
        .flat_map(|f| f.parameters.iter().map(|p| p.name.clone()))
        .collect();
    r.held = holds_of(o, &fitted);
    let fits = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()];
    r.held.extend(held_by_fits(
        &fits.into_iter().flatten().collect::<Vec<_>>(),
        &r.tyre,
    ));
    written::finite_fits(&r).map_err(on_data(o, None))?;
    r.pac89_reversal = match (&r.tyre, r.fit.channel) {
        (Tyre::Pac89(p), Channel::LateralForce) => {
            curvature::pac89_reversal(p, &ranges::fitted_spans(&r))
        }
        _ => None,
    };
    r.notes = notes::notes(&r)
        .into_iter()
        .chain(r.warning_notes())
        .collect();
    r.file = written::tyre_file_text(&r, &o.output_path())?;
    Ok(r)
}
