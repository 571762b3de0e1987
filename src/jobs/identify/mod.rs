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
use crate::identify::grouping::GroupingReport;
mod choices;
mod curvature;
pub use curvature::{Curvature, CurvatureExcess, Pac89Reversal};
mod curvature_hold;
pub use curvature_hold::CurvatureHeld;
mod command;
mod condition_values;
mod contact_length;
mod local_scope;
pub use command::{RecordedHold, RecordedOptions};
mod level_names;
mod linear_window;
mod nompres;
pub use linear_window::LinearWindow;
mod notes;
pub use notes::Note;
mod offset;
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
mod hold_owner;
mod hold_rules;
mod holds;
pub use holds::{parse_hold, Held};
mod staged;
mod standstill;
mod taken;
mod two_stage;
mod unseen;
mod unused_columns;
mod written_checks;
pub use taken::{check_given, FitOption};
pub use two_stage::{TwoStageReport, Written};
pub use unused_columns::Measured;
mod fit_key;
mod staged_figure;
mod staged_run;
mod template;
mod template_size;
mod template_version;

use crate::error::{Error, FitError, Limit, NameKind, OptionsError, ParamError};
use crate::identify::{start_tyre_of, Fit};
use crate::report::plot::Figure;
use crate::report::{write_bytes, write_json_sorted, OutputLock};
use crate::tyre::mf::MfCoefficients;
use crate::tyre::Tyre;
pub use choices::{IdentifyModel, Polish, StartArg};
use serde::Serialize;
use staged_run::run_staged;
mod swarm;
pub use staged::{StageFigure, StagedJob};
use std::path::PathBuf;
use swarm::run_swarm;

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
    /// Magic Formula: Levenberg–Marquardt iterations per step. `None`:
    /// the default cap (`LM_ITERATIONS`), and a stage stopped on it short
    /// of its optimum is continued; `Some(n)`: the user's cap, honoured.
    pub max_iterations: Option<usize>,
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
        // No iteration is no fit: its report would read as one; past the
        // most, a cap only lets a stage that does not converge run silently.
        if let Some(n) = self.max_iterations {
            ParamError::positive("max_iterations", n as f64)?;
            let most = crate::constants::MOST_STAGE_ITERATIONS as f64;
            ParamError::in_range(
                "max_iterations",
                n as f64,
                0.0,
                most,
                Limit::StageIterations,
            )?;
        }
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
        let given = [
            (FitOption::Load, self.load),
            (FitOption::Pressure, self.pressure),
            (FitOption::Camber, self.camber),
        ];
        let given: Vec<FitOption> = given
            .iter()
            .filter(|(_, v)| v.is_some())
            .map(|(o, _)| *o)
            .collect();
        taken::check_given(self.model, &given)
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
        // A name of another model's, said so (`hold_owner.rs`).
        for (name, _) in &self.hold {
            let own = self.model.swarm_model().map_or_else(
                || MfCoefficients::NAMES.contains(&name.as_str()),
                |m| {
                    start_tyre_of(m, holds::CHECK_LOAD)
                        .is_ok_and(|t| crate::identify::fitted_names(&t).contains(name))
                },
            );
            if let Some(e) = (!own)
                .then(|| hold_owner::of_another_model(name, self.model))
                .flatten()
            {
                return Err(e.into());
            }
        }
        let Some(model) = self.model.swarm_model() else {
            for (name, _) in &self.hold {
                crate::error::named(MfCoefficients::NAMES, |k| k, NameKind::MfCoefficient, name)
                    .map_err(|e| OptionsError::HoldNotCoefficient(Box::new(e)))?;
            }
            // The reader's own limits first (their words are the files'),
            // then the sign rules only the fit's boxes encode.
            holds::check_hold_values(None, &self.hold)?;
            return hold_rules::check_signs(None, &self.hold);
        };
        // What the fits fit, and what the file carries that is set after
        // them (a linear tyre's trail): every parameter of the file written.
        let start = start_tyre_of(model, 1.0)?;
        let mut known = crate::identify::fitted_names(&start);
        known.extend(
            crate::identify::set_after_fits(&start)
                .iter()
                .map(|n| n.to_string()),
        );
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
        holds::check_hold_values(Some(model), &self.hold)?;
        hold_rules::check_signs(Some(model), &self.hold)
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
    /// The samples at a lifted wheel's load set aside (`identify/lifted.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lifted: Option<crate::identify::lifted::Lifted>,
    /// The samples at rest set aside, said (`standstill.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at_rest: Option<String>,
    /// The file's measured `mz`, `mx`, `my`, counted for the notes on
    /// those no fit took (`unused_columns.rs`).
    #[serde(skip)]
    pub measured: Measured,
    /// The rows of combined slip left out, and the slip ratios reached.
    pub set_aside: crate::identify::pure::SetAside,
    /// The rig's forces far too small for their loads (`force_scale.rs`).
    #[serde(skip)]
    pub small_forces: Vec<String>,
    /// The extremes of the samples' slip angle and slip ratio fitted.
    #[serde(skip)]
    pub sample_slips: [Option<(f64, f64)>; 2],
    /// The spans of the load, camber and pressure of the samples fitted
    /// (every channel's): the ranges the written file states.
    #[serde(skip)]
    pub(crate) sample_spans: Vec<ranges::Span>,
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

impl SwarmReport {
    /// The names of the levels of its data, lateral and longitudinal
    /// (`level_names.rs`).
    pub(crate) fn level_names(&self) -> level_names::LevelNames<'_> {
        let more = self
            .longitudinal_grouping
            .as_ref()
            .map_or(&[][..], |g| &g.levels[..]);
        level_names::LevelNames::of(&self.grouping.levels, more)
    }
}

impl IdentifyReport {
    /// The tyre file, the report and the figures: a swarm fit's one, a
    /// staged fit's one per stage fitted.
    pub fn outputs(&self) -> Vec<PathBuf> {
        match self {
            IdentifyReport::Swarm(r) => outputs(&r.options, true),
            IdentifyReport::Staged(r) => {
                let mut files = outputs(&r.options, false);
                files.extend(r.figures.iter().map(|f| f.path.clone()));
                files
            }
        }
    }

    /// Warnings on the fit's inputs: levels pooled into a model without
    /// terms for them.
    pub fn warnings(&self) -> Vec<String> {
        match self {
            IdentifyReport::Swarm(r) => {
                let mut w = hold_rules::beyond_box(&r.options);
                w.extend(r.input_warnings());
                w
            }
            IdentifyReport::Staged(r) => hold_rules::beyond_box(&r.options),
        }
    }

    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        match self {
            IdentifyReport::Swarm(r) => r.summary(),
            IdentifyReport::Staged(r) => r.summary(),
        }
    }

    /// The figures written beside the tyre file, in the order
    /// [`IdentifyReport::outputs`] names their files: measured against
    /// fitted.
    pub fn figures(&self) -> Vec<Figure> {
        match self {
            IdentifyReport::Swarm(r) => vec![figures::fit_figure(r)],
            IdentifyReport::Staged(r) => r.figures.iter().map(|f| f.figure.clone()).collect(),
        }
    }

    /// Writes the tyre file, the report and the figures.
    pub fn write(&self) -> Result<(), Error> {
        let files = self.outputs();
        match self {
            IdentifyReport::Swarm(r) => {
                write_bytes(&files[0], r.file.as_bytes())?;
                write_json_sorted(&files[1], r)?;
            }
            IdentifyReport::Staged(r) => {
                write_bytes(&files[0], r.tir.as_bytes())?;
                write_json_sorted(&files[1], r)?;
            }
        }
        for (figure, path) in self.figures().iter().zip(&files[2..]) {
            figure.save(path)?;
        }
        Ok(())
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
            IdentifyReport::Staged(r) if f.len() == 2 => format!(
                "identified in {:.2} s; wrote {} and {} (no stage fitted, no figure)",
                r.report.seconds, f[0], f[1]
            ),
            IdentifyReport::Staged(r) => format!(
                "identified in {:.2} s; wrote {}, {} and a figure per stage fitted: {}",
                r.report.seconds,
                f[0],
                f[1],
                f[2..].join(", ")
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

/// The rig file of `o` and its wheel moments, without a lifted wheel's
/// samples, and what was set aside (`identify/lifted.rs`).
fn read_lifted(o: &Options) -> Result<crate::identify::lifted::Stripped, Error> {
    let (d, moments) = crate::io::rig::read_rig_with_moments(&o.data)?;
    Ok(crate::identify::lifted::without_lifted_moments(d, moments))
}
