//! Fit errors: a tyre fit that cannot be made (too few points, loads or
//! test conditions; a model with nothing to fit; rig data with no channel
//! the job can use) or whose result does not survive its own check; and the
//! diagnosis's failures on the rig data of its base model.

use super::{Error, Variable};
use crate::format::plural;
use std::path::PathBuf;
use thiserror::Error as ThisError;

/// The rounded loads of a message, N.
/// Loads to the newton, listed: `2000, 4000 N`.
fn rounded(loads: &[f64]) -> String {
    let listed: Vec<String> = loads.iter().map(|l| format!("{:.0}", l.round())).collect();
    format!("{} N", listed.join(", "))
}

/// What a user told of too few slip-angle bins can do: `--bin-deg 0`
/// only where every sample kept gives more points than parameters and the
/// slip angle is swept (more bins than conditions); one bin per condition
/// is no sweep, and no thinning makes a fit of it (`--bin-deg 0` then
/// wrote a tyre at σ 100 %, every parameter unseen by the data).
fn too_few_bins_advice(
    samples: usize,
    parameters: usize,
    points: usize,
    conditions: usize,
    bin_deg: f64,
) -> String {
    if points <= conditions {
        return format!(
            "each of the {} lies within one {}° bin: the slip angle is not swept, and keeping every sample (--bin-deg 0) gives no fit either; a lateral force is fitted from a slip-angle sweep (`alpha` swept past the force's peak, 4° and beyond)",
            plural(conditions, "test condition", "test conditions"),
            crate::format::readable(bin_deg, 3)
        );
    }
    match samples > parameters {
        true => format!("--bin-deg 0 keeps every sample ({samples} points)"),
        false => format!("every sample kept (--bin-deg 0) would still be no more than {parameters} points: the fit needs more samples"),
    }
}

/// "every free one's standard error exceeds its value" with the count.
fn unseen_free(free: usize) -> String {
    match free {
        0 => "none is free".to_string(),
        1 => "its one free parameter's standard error exceeds its value, or it sits on its search bound".to_string(),
        n => format!("each of its {n} free parameters has a standard error above its value or sits on its search bound"),
    }
}

/// `channel: ` when a channel is named.
fn prefix(channel: &Option<&'static str>) -> String {
    channel.map_or(String::new(), |c| format!("{c}: "))
}

/// Why a fit cannot be made, or failed.
#[derive(Debug, ThisError)]
#[non_exhaustive]
pub enum FitError {
    /// No more points than free parameters.
    #[error("{} with a measured {quantity} cannot fit {}", plural(*points, "point", "points"), plural(*parameters, "parameter", "parameters"))]
    TooFewPoints {
        /// Points with the quantity measured.
        points: usize,
        /// The measured quantity (`lateral force`, …).
        quantity: &'static str,
        /// Free parameters.
        parameters: usize,
    },
    /// [`FitError::TooFewPoints`] where the slip-angle thinning merged
    /// samples into bins: how many samples and how wide a bin, so that a
    /// user told "2 points" of a file with 3 rows sees where the third went.
    #[error("{} with a measured {quantity} in {} of {}° slip angle (--bin-deg) cannot fit {}; {}", plural(*samples, "sample", "samples"), plural(*points, "bin", "bins"), crate::format::readable(*bin_deg, 3), plural(*parameters, "parameter", "parameters"), too_few_bins_advice(*samples, *parameters, *points, *conditions, *bin_deg))]
    TooFewBins {
        /// Samples with the quantity measured, before thinning.
        samples: usize,
        /// The bins they were thinned to (the fit's points).
        points: usize,
        /// The bin, degrees.
        bin_deg: f64,
        /// The measured quantity (`lateral force`, …).
        quantity: &'static str,
        /// Free parameters.
        parameters: usize,
        /// The test conditions the bins lie in: as many bins as
        /// conditions is one slip angle per condition, no sweep.
        conditions: usize,
    },
    /// A fit in which the data see no parameter: every free one's standard
    /// error is larger than its value (or it sits on its search bound) and
    /// the rest are held, and the fit explains nothing of the data (σ of
    /// 100 % or more, no better than a zero force). Refused, not written:
    /// `--bin-deg 0` on rig data whose slip angle stays near 0 wrote such a
    /// file at σ 100.002 %.
    #[error("no parameter of the {model} model's {quantity} is determined by these data ({}; the rest held) and the fit explains none of them (σ {} %): it misses by more than a zero force would (is the column's sign the tyre's, as FORMATS.md fixes it?); the data do not see the model, so no tyre is written; {} reaches {}{}", unseen_free(*free), crate::format::fixed(*sigma_percent, 1), slip.0, slip.1, slip.2)]
    NotSeen {
        /// The tyre model.
        model: &'static str,
        /// The measured quantity (`lateral force`, …).
        quantity: &'static str,
        /// Free parameters (each with a standard error above its value).
        free: usize,
        /// The fit's σ, %.
        sigma_percent: f64,
        /// The slip column, its reach as read (`0.115°`), and the data that
        /// would determine the model.
        slip: (&'static str, String, &'static str),
    },
    /// A model without parameters for the quantity.
    #[error("the {model} model has no {quantity} to fit")]
    NothingToFit {
        /// The tyre model.
        model: &'static str,
        /// The quantity.
        quantity: &'static str,
    },
    /// Fewer distinct loads than the model's load dependence needs.
    #[error(
        "the {model} model's load dependence needs at least {needed} loads; the data has {}: {}: fit a model that takes one load (gim, magic-simple, linear), or, where --load selected it, drop --load",
        loads.len(),
        rounded(loads)
    )]
    TooFewLoads {
        /// The tyre model.
        model: &'static str,
        /// Loads it needs.
        needed: usize,
        /// The distinct loads of the data, N.
        loads: Vec<f64>,
    },
    /// Too few test conditions for a method.
    #[error("{method} needs at least {needed} test conditions; the data have {have}")]
    TooFewConditions {
        /// The method.
        method: &'static str,
        /// Conditions it needs.
        needed: usize,
        /// Conditions in the data.
        have: usize,
    },
    /// No stage of a staged identification had the rows it needs; each
    /// stage's reason.
    #[error("no stage could be fitted ({}){}", joined(skips), combined_set_aside(*rows, *combined))]
    NoStageFitted {
        /// Each stage's reason.
        skips: Vec<StageSkip>,
        /// The rows of the file.
        rows: usize,
        /// Those of combined slip (both |κ| and |α| above 1e-3).
        combined: usize,
    },
    /// A written tyre file that does not reproduce the fitted forces.
    #[error("the written .tir does not reproduce the fitted forces (relative difference {difference:.2e})")]
    RoundTrip {
        /// Relative difference of the forces.
        difference: f64,
    },
    /// A fit whose σ or a parameter is not a finite number: no file holds it.
    #[error("the fit's {quantity} is {value}, not a finite number: the data hold values no tyre model reproduces (check the force columns' scale); no file is written")]
    NonFiniteResult {
        /// What is not finite (`σ`, a parameter's name).
        quantity: String,
        /// Its value.
        value: f64,
    },
    /// A fitted coefficient beyond any tyre's ([`crate::tyre::sizes`]): its
    /// file would be refused by every command that reads it.
    #[error("the fit took {source}; no file is written, as every command would refuse it (the default start, `--start data`, keeps each coefficient within physical bounds)")]
    BeyondAnyTyre {
        /// The coefficient, its value and the limit.
        source: super::ParamError,
    },
    /// The paper's unbounded scheme took a longitudinal slip stiffness
    /// negative inside the loads fitted (`jobs/identify/written_checks.rs`).
    #[error("{turn}; no file is written: a tyre whose force opposes its slip inside the loads it was fitted on is no tyre (the default start, `--start data`, keeps each coefficient within physical bounds)")]
    PaperTurn {
        /// Where and how the stiffness turns, said.
        turn: String,
    },
    /// A held value's tyre whose slip stiffness turns over (`held_turn.rs`).
    #[error(transparent)]
    HeldTurn(Box<super::HeldTurn>),
    /// Rig data with a lateral force and no slip angle (`alpha` 0 in
    /// every sample) and no longitudinal sweep to fit instead: every model
    /// refuses it, as a fit there returns its start values.
    #[error("{}: `alpha` is 0 throughout its {rows} rows (|alpha| ≤ 1e-3 rad): no lateral slip to fit `fy` to, by any model; a lateral force is fitted from a slip-angle sweep (`alpha` swept past the force's peak, 4° and beyond)", data.display())]
    NoSlipAngleInFile {
        /// The rig data.
        data: PathBuf,
        /// Its rows (after a lifted wheel's and a standstill's).
        rows: usize,
    },
    /// Rig data without lateral data, for a model without a longitudinal
    /// force.
    #[error("{}: no lateral data (columns `alpha` and `fy`), and the {model} model has no longitudinal force", data.display())]
    NoLateralData {
        /// The rig data.
        data: PathBuf,
        /// The tyre model.
        model: &'static str,
    },
    /// Rig data with neither lateral nor longitudinal data.
    #[error("{}: no lateral data and no longitudinal data", data.display())]
    NoData {
        /// The rig data.
        data: PathBuf,
    },
    /// Rig data of combined-slip rows only, for a pure-slip fit.
    #[error(transparent)]
    OnlyCombined(#[from] super::OnlyCombined),
    /// Rig data in which the grouping found no test condition.
    #[error("{}: no test condition found in the data ({grouping})", data.display())]
    NoCondition {
        /// The rig data.
        data: PathBuf,
        /// Where its samples went.
        grouping: SampleAccount,
    },
    /// A linear tyre's fit with no condition holding two points within its
    /// small-slip window.
    #[error("{}: no condition has two points within |alpha| <= {window_deg} deg, where a linear tyre is fitted ({points} points, the smallest |alpha| {smallest_deg:.2} deg): a linear tyre's stiffness is the slope at small slip; fit a model with saturation (gim, magic-simple) to these data", data.display())]
    NoSmallSlip {
        /// The rig data.
        data: PathBuf,
        /// The window, degrees.
        window_deg: f64,
        /// Points before the window.
        points: usize,
        /// The smallest |α| among them, degrees.
        smallest_deg: f64,
    },
    /// A swarm fit's tyre the tyre readers would refuse: a fitted value
    /// said as the fit's (no key the user wrote, no hint at its unit), the
    /// reader's limit and the likely cause.
    #[error("{}: the fitted tyre is not written, as the tyre readers (tyre-eval, simulate) would refuse it: the fit took `{key}` to {}, which a tyre file may not hold ({limit}){}; {cause}", data.display(), super::Num(*value), if *holding { ", with the values given with --hold, which may have driven it there" } else { "" })]
    FittedRefused {
        /// The rig data.
        data: PathBuf,
        /// The fitted parameter.
        key: String,
        /// Its fitted value.
        value: f64,
        /// What the reader asks of it (`must lie in (0, 1]`).
        limit: String,
        /// Whether values were given with `--hold`.
        holding: bool,
        /// The likely cause, in words.
        cause: String,
    },
    /// A fit to rig data that failed: the data and, where several channels
    /// are fitted, the channel.
    #[error("{}: {}{source}", data.display(), prefix(channel))]
    InData {
        /// The rig data.
        data: PathBuf,
        /// The channel fitted (`aligning moment`, …).
        channel: Option<&'static str>,
        /// Why the fit failed.
        source: Box<Error>,
    },
}

/// The errors of a design are the diagnosis's.
pub type DesignError = DiagnosisError;

impl FitError {
    /// A failure of a fit to `data`, of `channel` where named.
    pub(crate) fn in_data(data: &std::path::Path, channel: Option<&'static str>, e: Error) -> Self {
        FitError::InData {
            data: data.to_path_buf(),
            channel,
            source: Box::new(e),
        }
    }
}

pub use super::unseen::Unseen;

/// Why the diagnosis of a campaign could not be made.
#[derive(Debug, ThisError)]
#[non_exhaustive]
pub enum DiagnosisError {
    /// Rig data of the base model with no lateral test condition.
    #[error("{}: no lateral test condition in the rig data", rig.display())]
    NoRigCondition {
        /// The rig data.
        rig: PathBuf,
    },
    /// The base model's fit to its rig data failed.
    #[error("{}: {source}", rig.display())]
    RigFit {
        /// The rig data.
        rig: PathBuf,
        /// Why the fit failed.
        source: Box<Error>,
    },
    /// A campaign whose every candidate effect needs what no run shows: a
    /// verdict would say "outside the library" with nothing tried.
    #[error("{}: none of the candidate effects its `[diagnose] effects` names can show in its runs: {}; a diagnosis would try nothing and call the gap outside the library: name a candidate the runs can show (or leave `[diagnose] effects` out for the whole library), or add runs that show these", campaign.display(), unseen.iter().map(|(e, u)| format!("{e}: {u}")).collect::<Vec<_>>().join("; "))]
    NoCandidateSeen {
        /// The campaign.
        campaign: PathBuf,
        /// Each candidate named, by name, and what the runs lack for it.
        unseen: Vec<(String, Unseen)>,
    },
    /// A measured sideslip that moves against the base model's.
    #[error("{}: {source}", campaign.display())]
    BetaAgainstModel {
        /// The campaign.
        campaign: PathBuf,
        /// The runs.
        source: super::BetaAgainstModel,
    },
    /// A design asked of a diagnosis that names no confounded set.
    #[error("the diagnosis names no confounded effects{}: ask for the candidates to separate (`--effects a,b`)", noted_words(noted))]
    NothingConfounded {
        /// The candidates a verdict of no significant gap notes fitted
        /// far from off, best held-out first (`a+b` a combination).
        noted: Vec<String>,
    },
    /// A design asked of a diagnosis that cross-validated no candidate
    /// (each screened out: on a gap within noise every one is), whatever
    /// `--effects` names: the advice is how to get held-out fits.
    #[error("the diagnosis cross-validated no candidate{}: it screened {} out before cross-validating (removing less than {screen_percent:.1} % of the gap above noise in sample), so none has a held-out fit to design with, whichever `--effects` are named; for a design, add `screening = false` under `[diagnose]` in the campaign and rerun `handling diagnose` (it then cross-validates every single effect), or drive more or longer runs that show a gap", match no_gap { true => " (its verdict: no significant gap)", false => "" }, match screened { 1 => "its one candidate".to_string(), n => format!("all {n} candidates") })]
    NothingCrossValidated {
        /// The candidates screened out.
        screened: usize,
        /// The share below which they were screened out, %.
        screen_percent: f64,
        /// Whether the verdict found no significant gap.
        no_gap: bool,
    },
    /// A design asked for a candidate the diagnosis did not fit.
    #[error("the diagnosis did not fit `{candidate}`; it fitted: {}", fitted.join(", "))]
    NotFitted {
        /// The candidate asked for.
        candidate: String,
        /// The candidates it fitted.
        fitted: Vec<String>,
    },
    /// A design asked for a candidate the diagnosis screened out.
    #[error("the diagnosis screened `{candidate}` out before cross-validating it (it removes {insample_percent:.1} % of the gap above noise {of} leaves in sample, below the {screen_percent:.1} % screen), so it has no held-out fit to design with; it cross-validated: {}", fitted.join(", "))]
    ScreenedOut {
        /// The candidate asked for.
        candidate: String,
        /// The share of the in-sample gap its all-run fit removed, %.
        insample_percent: f64,
        /// Whose gap: "the base model", or the set it extends.
        of: String,
        /// The share below which candidates are screened out, %.
        screen_percent: f64,
        /// The candidates it cross-validated.
        fitted: Vec<String>,
    },
    /// The campaign a diagnosis names, not found from here.
    #[error("{}: the campaign {} names is not found from here (a relative path is read from where `diagnose` ran){}: give it with --campaign", campaign.display(), diagnosis.display(), absolute.as_ref().map_or_else(String::new, |a| format!(", nor at {}, where it was then", a.display())))]
    CampaignNotFound {
        /// The campaign's path as the diagnosis wrote it.
        campaign: PathBuf,
        /// Its absolute path when the diagnosis was written, if known.
        absolute: Option<PathBuf>,
        /// The diagnosis file.
        diagnosis: PathBuf,
    },
    /// A campaign given with `--campaign` that lacks runs the diagnosis
    /// read: the candidates were fitted to other runs.
    #[error("{}: has no run `{run}`, which {} diagnosed ({missing} of its {diagnosed} runs missing): give the campaign that diagnosis read", campaign.display(), diagnosis.display())]
    OtherCampaign {
        /// The campaign given.
        campaign: PathBuf,
        /// The diagnosis file.
        diagnosis: PathBuf,
        /// The first diagnosed run it lacks (its file name).
        run: String,
        /// How many of the diagnosed runs it lacks.
        missing: usize,
        /// How many runs the diagnosis read.
        diagnosed: usize,
    },
    /// A design set with fewer than two members.
    #[error("a design separates at least two candidates")]
    OneMember,
    /// A candidate whose values do not match this release's layout.
    #[error("`{candidate}`: its values in the diagnosis do not match this release's parameters (diagnose again with this release)")]
    Layout {
        /// The candidate.
        candidate: String,
    },
}

/// `a; b; c`.
/// The rows of combined slip a fit with no stage set aside, counted: the
/// combined stages build on the pure ones, which have no rows of them.
fn combined_set_aside(rows: usize, combined: usize) -> String {
    match combined {
        0 => String::new(),
        n => format!(
            ": {n} of its {} {} of combined slip (both |κ| and |α| above 1e-3), set aside for the combined stages, which build on the pure ones; give rows at κ = 0 (a cornering sweep) or α = 0 (a braking or driving sweep) for those",
            plural(rows, "row", "rows"),
            if n == 1 { "is" } else { "are" }
        ),
    }
}

fn joined(skips: &[StageSkip]) -> String {
    skips
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("; ")
}

/// The rows a stage of the staged Magic Formula fit (Wei et al. 2010)
/// needs and the data lack.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ThisError)]
#[non_exhaustive]
pub enum StageRows {
    /// Pure Fx.
    #[error("no pure longitudinal rows (columns `kappa` and `fx`, |α| ≤ 1e-3 rad)")]
    PureLongitudinal,
    /// Pure Fy.
    #[error("no pure lateral rows (columns `alpha` and `fy`, |κ| ≤ 1e-3)")]
    PureLateral,
    /// Pure Mz.
    #[error("no pure lateral rows with a measured `mz`")]
    PureLateralMz,
    /// Combined Fx.
    #[error("no combined-slip rows with a measured `fx` (both |κ| and |α| above 1e-3)")]
    CombinedFx,
    /// Combined Fy.
    #[error("no rows with longitudinal slip (|κ| above 1e-3) and a measured `fy`")]
    LongitudinalSlipFy,
    /// Combined Mz.
    #[error("no rows with longitudinal slip (|κ| above 1e-3) and a measured `mz`")]
    LongitudinalSlipMz,
    /// Combined Fy or Mz on rows with longitudinal slip all at α = 0.
    #[error("no combined-slip rows with a measured `{column}` (both |κ| and |α| above 1e-3): the rows with longitudinal slip are all at α = 0, where the combined coefficients cannot be told from the pure ones")]
    OnlyPureLongitudinal {
        /// The channel's column: `fy` or `mz`.
        column: &'static str,
    },
    /// Pure Fy or Mz on rows all at α = 0 (a braking or driving sweep
    /// with `fy` and `mz` logged).
    #[error("`alpha` is 0 throughout its {rows} rows at κ = 0 (|α| ≤ 1e-3 rad): no lateral slip to fit `{column}` to")]
    NoSlipAngle {
        /// The channel's column: `fy` or `mz`.
        column: &'static str,
        /// The stage's rows.
        rows: usize,
    },
    /// Mx.
    #[error("no rows with a measured `mx`: `mx` is fitted only from a rig file with `mx`, `kappa` and `fx` columns, whose samples are its rows (a file without `kappa` and `fx` is averaged into slip-angle bins of `fy` and `mz`, and its `mx` left out); to fit it, give `mx` in a file with `kappa` and `fx` (on a cornering sweep, `kappa` = 0 and the rig's measured `fx`)")]
    Mx,
    /// My.
    #[error("no rows with a measured `my`: `my` is fitted only from a rig file with `my`, `kappa` and `fx` columns, whose samples are its rows (a file without `kappa` and `fx` is averaged into slip-angle bins of `fy` and `mz`, and its `my` left out); to fit it, give `my` in a file with `kappa` and `fx` (on a cornering sweep, `kappa` = 0 and the rig's measured `fx`)")]
    My,
}

/// Why a stage of the staged fit was skipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ThisError)]
#[non_exhaustive]
pub enum SkipReason {
    /// The data have none of the stage's rows.
    #[error("{0}")]
    NoRows(StageRows),
    /// Fewer rows than the stage's free parameters need: more than five
    /// beyond their count, so that the fit has residuals left to judge it
    /// by ("13 rows cannot fit 8 parameters" read as a miscount).
    #[error("{} for {}: at least {} are needed", plural(*rows, "row", "rows"), plural(*free, "parameter", "parameters"), free + 6)]
    TooFewRows {
        /// Rows the stage has.
        rows: usize,
        /// Its free parameters.
        free: usize,
    },
    /// The stage it builds on was skipped.
    #[error("it builds on the {stage} stage, which was skipped")]
    BuildsOnSkipped {
        /// That stage's label.
        stage: &'static str,
    },
}

impl serde::Serialize for SkipReason {
    /// As its message: the report's `skipped` is the sentence a reader
    /// sees.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// A skipped stage and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ThisError)]
#[error("{stage}: {reason}")]
pub struct StageSkip {
    /// The stage's label.
    pub stage: &'static str,
    /// Why.
    pub reason: SkipReason,
}

/// Where the samples of rig data went in the grouping into test
/// conditions (load, camber and pressure levels).
#[derive(Debug, Clone, PartialEq)]
pub struct SampleAccount {
    /// Samples in the file.
    pub samples: usize,
    /// Samples in conditions.
    pub used: usize,
    /// Samples between levels of some variable (transitions).
    pub between_levels: usize,
    /// Samples in groups of values too few to be a level.
    pub too_few: usize,
    /// Samples at levels other than the one selected.
    pub not_selected: usize,
    /// The levels found of each variable: (variable, count).
    pub levels: Vec<(Variable, usize)>,
}

/// The words of `n` samples in groups too few to be a level, ending in
/// ", " (none: empty): two rows at one load were said to be "between
/// levels (transitions)", where there is no level for them to lie between.
pub fn too_few_words(n: usize) -> String {
    match n {
        0 => String::new(),
        n => format!(
            "{} in groups too few to be a level (fewer than 3 samples at one load, camber or pressure), ",
            plural(n, "sample", "samples")
        ),
    }
}

impl std::fmt::Display for SampleAccount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}: {} used in conditions, {}{} between levels (transitions), {} at levels not selected",
            plural(self.samples, "sample", "samples"),
            self.used,
            too_few_words(self.too_few),
            self.between_levels,
            self.not_selected
        )?;
        for (v, n) in &self.levels {
            write!(f, "; {} levels: {n}", v.column())?;
        }
        Ok(())
    }
}

/// The candidates a diagnosis of no significant gap notes fitted far from
/// off, and how to ask for a design to separate them.
fn noted_words(noted: &[String]) -> String {
    match noted {
        [] => String::new(),
        [one] => format!(" (it finds no significant gap, and notes that {one} fits far from off: alone, there is nothing to separate it from)"),
        _ => format!(
            " (it finds no significant gap, and notes that {} fit far from off and the held-out runs do not tell them apart: `--effects {}` designs runs to separate them)",
            noted.join(", "),
            noted.join(",")
        ),
    }
}
