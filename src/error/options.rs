//! Option errors: options of a job that name nothing known or contradict
//! each other or the job's other inputs (shard files of different runs,
//! inputs changed since the shards were run).

use std::path::PathBuf;
use thiserror::Error;

/// The closed sets whose members are named by the user.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum NameKind {
    /// A tyre model (`gim`, `pac89`, …).
    TyreModel,
    /// A study metric.
    Metric,
    /// A cornering-stiffness unit.
    Unit,
    /// A synthetic driving programme.
    Programme,
    /// A synthetic campaign's truth (a vehicle).
    Truth,
    /// A candidate effect of the diagnosis.
    Effect,
    /// Where the staged Magic Formula fit starts.
    Start,
    /// A coefficient of a Magic Formula `.tir` (`PKY4`, …).
    MfCoefficient,
    /// A class of tyres (the prior of axles identified from runs).
    TyreClass,
    /// A job that shards one input file (`equilibria`, `study`).
    Job,
}

impl NameKind {
    /// Every kind.
    pub const ALL: [NameKind; 10] = [
        NameKind::TyreModel,
        NameKind::Metric,
        NameKind::Unit,
        NameKind::Programme,
        NameKind::Truth,
        NameKind::Effect,
        NameKind::Start,
        NameKind::MfCoefficient,
        NameKind::TyreClass,
        NameKind::Job,
    ];

    /// The kind as the messages name it.
    pub fn as_str(self) -> &'static str {
        match self {
            NameKind::TyreModel => "tyre model",
            NameKind::Metric => "metric",
            NameKind::Unit => "unit",
            NameKind::Programme => "programme",
            NameKind::Truth => "truth",
            NameKind::Effect => "effect",
            NameKind::Start => "start",
            NameKind::MfCoefficient => "Magic Formula coefficient",
            NameKind::TyreClass => "tyre class",
            NameKind::Job => "job",
        }
    }
}

impl std::fmt::Display for NameKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The two merges of shard results whose unit count is checked against
/// the input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MergeInput {
    /// A sweep of equilibria: its units are conditions.
    Sweep,
    /// A cornering-stiffness study: its units are combinations.
    Study,
}

impl MergeInput {
    fn units(self) -> &'static str {
        match self {
            MergeInput::Sweep => "conditions",
            MergeInput::Study => "combinations",
        }
    }
    fn name(self) -> &'static str {
        match self {
            MergeInput::Sweep => "sweep",
            MergeInput::Study => "study",
        }
    }
}

/// What two shard files of one merge disagree on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShardField {
    /// The job that wrote them.
    Job,
    /// The input they were run on.
    Input,
    /// N, or the number of units.
    Count,
}

impl std::fmt::Display for ShardField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ShardField::Job => "the job",
            ShardField::Input => "the input",
            ShardField::Count => "the shard count",
        })
    }
}

/// The known names of a set as an error lists them: all of a short set,
/// the count of a long one (the 180 keys of a `.tir`).
fn listing(known: &[&str]) -> String {
    if known.len() <= 24 {
        format!("one of {}", known.join(", "))
    } else {
        format!("not one of the {} known", known.len())
    }
}

/// Options that name nothing known or contradict each other.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum OptionsError {
    /// A name that is no member of its closed set.
    #[error(
        "unknown {what} `{given}`{}: {}",
        crate::format::did_you_mean(given, known),
        listing(known)
    )]
    UnknownName {
        /// The set.
        what: NameKind,
        /// The name given.
        given: String,
        /// The set's members.
        known: Vec<&'static str>,
    },
    /// An MFeval `useMode` code that cannot be used.
    #[error("--mode: {0}")]
    Mode(#[from] ModeError),
    /// A Magic Formula version the tool reads from a `.tir` but
    /// `identify` does not fit (5.2: its staged fit writes 6.1 or 6.2).
    #[error(
        "--model {given}: Magic Formula {version} is a version `tyre-eval` and `simulate` read from a .tir, but `identify` does not fit it (its staged fit writes MF 6.1 or 6.2 files): give --model mf61, the nearest; the models it fits: {}",
        known.join(", ")
    )]
    VersionNotFitted {
        /// The name given.
        given: String,
        /// The version it names (`5.2`).
        version: &'static str,
        /// The models `identify` fits.
        known: Vec<&'static str>,
    },
    /// A local polish that is not one of the methods.
    #[error("unknown local method `{given}`{}: lm, gn or none", crate::format::did_you_mean(given, &["lm", "gn", "none"]))]
    UnknownLocalMethod {
        /// The name given.
        given: String,
    },
    /// An effect the truth's programme cannot show.
    #[error(
        "effect `{effect}`: not one the {truth} truth's {programme} programme can show: one of none, {}",
        known.join(", ")
    )]
    EffectNotShown {
        /// The effect.
        effect: &'static str,
        /// The truth.
        truth: &'static str,
        /// The programme.
        programme: &'static str,
        /// The effects it can show.
        known: Vec<&'static str>,
    },
    /// `synth --effects` naming an effect twice: the truth would list it
    /// twice (read as two delays, say) while applying it once.
    #[error("--effects names {effect} twice: name each effect once (its size is the truth's, not a count)")]
    EffectTwice {
        /// The effect.
        effect: &'static str,
    },
    /// `synth --duration` for a programme whose runs cannot be lengthened.
    #[error(
        "--duration {given}: the {programme} programme's runs are fixed manoeuvres or laps and cannot be lengthened; --duration lengthens the runs of {}",
        takes.iter().map(|(p, d)| format!("{p} ({d} s by default)")).collect::<Vec<_>>().join(", ")
    )]
    DurationNotTaken {
        /// The duration given, s.
        given: f64,
        /// The programme.
        programme: &'static str,
        /// The programmes that take it, with their own durations, s.
        takes: Vec<(&'static str, f64)>,
    },
    /// `synth --duration` shorter than the programme's own runs.
    #[error(
        "--duration {given}: the {programme} programme's runs last {own} s together, and --duration only lengthens them: give {own} or more"
    )]
    DurationTooShort {
        /// The duration given, s.
        given: f64,
        /// The programme.
        programme: &'static str,
        /// Its runs' own total duration, s.
        own: f64,
    },
    /// `synth --duration` no number of seconds, or beyond the longest
    /// campaign the proving ground drives.
    #[error(
        "--duration {}: {}the {programme} programme's runs last at most {most} s together (an hour of logging; each run is simulated at the truth's 2 ms step and held in memory): give a whole number of seconds from {own} to {most}",
        super::Num(*given),
        if given.is_finite() { "" } else { "no number of seconds: " }
    )]
    DurationTooLong {
        /// The duration given, s.
        given: f64,
        /// The programme.
        programme: &'static str,
        /// Its runs' own total duration, s.
        own: f64,
        /// The longest total, s.
        most: f64,
    },
    /// `synth --duration` that is no whole number of seconds.
    #[error(
        "--duration {}: the runs are lengthened to whole seconds (each in proportion and rounded, the last taking what is left, so that they add up to the total): give {} or {}",
        super::Num(*given),
        given.floor(),
        given.ceil()
    )]
    DurationNotWhole {
        /// The duration given, s.
        given: f64,
    },
    /// `synth --effects` naming `none` with effects.
    #[error("{0}")]
    NoneWithEffects(super::NoneWithEffects),
    /// A model asked of the swarm fit that only its staged fit identifies.
    #[error("the {model} model is identified by its staged fit ({})", fits.join(" or "))]
    StagedFitOnly {
        /// The model's name.
        model: String,
        /// The names of its staged fits.
        fits: Vec<&'static str>,
    },
    /// A tyre model registered under a name another model holds.
    #[error("a different tyre model is already registered as `{name}`")]
    ModelNameTaken {
        /// The name.
        name: &'static str,
    },
    /// A model that no fit identifies from rig data.
    #[error("the {model} model is not identified from rig data")]
    NotIdentified {
        /// The model's name.
        model: String,
    },
    /// `--start template` without a template file.
    #[error("--start template needs --template <file.tir>")]
    TemplateMissing,
    /// `--pressure` / `--camber` for a staged Magic Formula fit, which
    /// fits every level of the file (the model has pressure and camber
    /// terms).
    #[error(
        "--{option} is not taken by --model {model}: the staged Magic Formula fit fits every load, pressure and camber level of the file together (the model has terms in each), so it selects none; drop --{option}, or write a file holding only the level wanted"
    )]
    LevelSelectionNotTaken {
        /// The option given (`pressure`, `camber`).
        option: &'static str,
        /// The model.
        model: String,
    },
    /// An option the model's fit does not read (`identify/taken.rs`).
    #[error("--{option} is not taken by --model {model}: {why}; drop --{option}")]
    OptionNotTaken {
        /// The option given, without its dashes.
        option: &'static str,
        /// The model.
        model: String,
        /// Why the fit does not read it.
        why: &'static str,
    },
    /// `--hold` of a name that is no `.tir` coefficient (the staged Magic
    /// Formula fit): the name's own refusal, said of the option.
    #[error("--hold: {0}")]
    HoldNotCoefficient(Box<OptionsError>),
    /// `--hold` of a name that is none of the model's fitted parameters.
    #[error(
        "--hold `{given}`: not a parameter of the {model} model{}: its parameters are {}",
        hold_meant(given, known),
        known.join(", ")
    )]
    UnknownHold {
        /// The model's name.
        model: String,
        /// The name given.
        given: String,
        /// The model's parameters (every block it fits).
        known: Vec<String>,
    },
    /// `--hold` of a name that is none of the chosen model's but another
    /// model's: which, and the `--model` that fits it.
    #[error(
        "--hold `{given}`: {given} is a parameter of the {owner} model (--model {owner}), not of {model}, the model chosen: hold one of {model}'s{known}, e.g. --hold {example}"
    )]
    HoldOfOtherModel {
        /// The chosen model's parameters, `" (its parameters are a, b, …)"`
        /// where they are few enough to list (a fitter's own names, such as
        /// UniTire's `b1`, are also another model's), else empty.
        known: String,
        /// The name given.
        given: String,
        /// The model it belongs to (its `--model` value).
        owner: &'static str,
        /// The model chosen.
        model: &'static str,
        /// A hold of the chosen model's own, `NAME=VALUE`.
        example: String,
    },
    /// A `--hold` that is not `NAME=VALUE` with a number.
    #[error("--hold `{given}`: expected NAME=VALUE with a number, e.g. {example}")]
    HoldSyntax {
        /// The argument given.
        given: String,
        /// A hold of the model chosen (`a0=1.65` for pac89).
        example: String,
    },
    /// A parameter held twice (the last value would be taken silently).
    #[error("--hold {name} is given twice ({first} and {second}): hold each parameter once")]
    HoldTwice {
        /// The parameter.
        name: String,
        /// The first value.
        first: f64,
        /// The second.
        second: f64,
    },
    /// A `--hold` value the model's sign rules refuse.
    #[error("{0}")]
    HoldAgainstRule(Box<super::HoldAgainstRule>),
    /// A shard K of N outside 1 ≤ K ≤ N.
    #[error("shard {index}/{count}: expected K/N with 1 ≤ K ≤ N, e.g. 3/8")]
    ShardOutOfRange {
        /// K.
        index: usize,
        /// N.
        count: usize,
    },
    /// A shard given as text that is not K/N.
    #[error("shard `{given}`: expected K/N with 1 ≤ K ≤ N, e.g. 3/8")]
    ShardText {
        /// The text given.
        given: String,
    },
    /// A scenario driven as a run whose name the campaign already has.
    #[error(
        "--drive {}: the campaign already has a run named `{name}` ({}): each driven run is named after its file; rename the file",
        path.display(),
        if *programme { "one of the programme's own" } else { "driven from an earlier --drive file" }
    )]
    DriveName {
        /// The scenario file.
        path: PathBuf,
        /// The run's name (the file's stem).
        name: String,
        /// Whether the name is one of the programme's runs (else an
        /// earlier `--drive`'s).
        programme: bool,
    },
    /// A merge given no shard file.
    #[error("merge: no shard files given")]
    NoShards,
    /// Two shard files of different runs.
    #[error("{}: {field} differs from {}'s: shards of different runs", path.display(), first.display())]
    ShardsDiffer {
        /// The shard file.
        path: PathBuf,
        /// The first shard file of the merge.
        first: PathBuf,
        /// What differs.
        field: ShardField,
    },
    /// A shard file whose results are not its shard's units.
    #[error("{}: its results are not shard {index}/{count}'s units", path.display())]
    ShardUnits {
        /// The shard file.
        path: PathBuf,
        /// K.
        index: usize,
        /// N.
        count: usize,
    },
    /// A shard given twice.
    #[error("{}: shard {index}/{count} given twice", path.display())]
    ShardTwice {
        /// The second shard file.
        path: PathBuf,
        /// K.
        index: usize,
        /// N.
        count: usize,
    },
    /// Shards missing from a merge.
    #[error("merge: shards {} missing", missing.iter().map(|k| format!("{k}/{count}")).collect::<Vec<_>>().join(", "))]
    ShardsMissing {
        /// The missing K.
        missing: Vec<usize>,
        /// N.
        count: usize,
    },
    /// An input changed since the shards were run.
    #[error("{}: changed since the shards were run; run them again", path.display())]
    InputChanged {
        /// The input.
        path: PathBuf,
    },
    /// A fleet folder whose campaigns changed since the shards were run.
    #[error("{}: its campaigns changed since the shards were run; run them again", path.display())]
    CampaignsChanged {
        /// The fleet folder.
        path: PathBuf,
    },
    /// Shards that hold another number of units than their input has.
    #[error(
        "merge: the shards hold {held} {}, the {} {} has {expected}",
        input.units(),
        input.name(),
        path.display()
    )]
    MergeCount {
        /// The job's input kind.
        input: MergeInput,
        /// The input file.
        path: PathBuf,
        /// Units in the shards.
        held: usize,
        /// Units of the input.
        expected: usize,
    },
}

/// What MFeval's `useMode` digits mean, for the messages.
const USE_MODE_HELP: &str = "MFeval's useMode: hundreds 1 (limit checks on) or 2 (off), \
                             tens 1 (α* off) or 2 (on), units 1 (no turn slip)";

/// A digit of an MFeval `useMode` code outside its choices.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{place} digit {digit} is not {allowed}")]
pub struct ModeDigit {
    /// Which digit (`hundreds`, `tens`, `units`).
    pub place: &'static str,
    /// Its value.
    pub digit: u32,
    /// What it may be.
    pub allowed: &'static str,
}

/// Why an MFeval `useMode` code is refused.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ModeError {
    /// Not three digits.
    #[error("mode {code} is not a three-digit code ({USE_MODE_HELP})")]
    NotThreeDigits {
        /// The code given.
        code: u32,
    },
    /// Digits outside their choices.
    #[error("mode {code}: {} ({USE_MODE_HELP})", bad.iter().map(ToString::to_string).collect::<Vec<_>>().join(", "))]
    Digits {
        /// The code given.
        code: u32,
        /// Every digit refused, hundreds first.
        bad: Vec<ModeDigit>,
    },
    /// Turn slip (units digit 2), which the crate does not model.
    #[error(
        "mode {code}: turn slip (units digit 2) is not modelled; use {}1 (combined slip without turn slip)",
        code / 10
    )]
    TurnSlip {
        /// The code given.
        code: u32,
    },
    /// A mode given for a tyre that is not a Magic Formula one.
    #[error("mode {code} is MFeval's useMode, a setting of the Magic Formula (.tir) tyres only: its digits switch the Magic Formula's input-limit checks, its α* (cos α) correction and its combined or turn slip, none of which a {model} tyre has; a {model} tyre is evaluated as its file states: drop --mode (or evaluate a .tir tyre)")]
    NotMagicFormula {
        /// The code given.
        code: u32,
        /// The tyre's model.
        model: String,
    },
}

/// The `did you mean` of a `--hold` name: every parameter whose name
/// within its block is `given` (UniTire's `p3` is `lateral.p3` and
/// `longitudinal.p3`: a block-qualified name is asked for), else the
/// nearest name ([`crate::format::did_you_mean`]).
fn hold_meant(given: &str, known: &[String]) -> String {
    let in_block: Vec<String> = known
        .iter()
        .filter(|k| k.rsplit_once('.').is_some_and(|(_, n)| n == given))
        .map(|k| format!("`{k}`"))
        .collect();
    match in_block.as_slice() {
        [] => crate::format::did_you_mean(
            given,
            &known.iter().map(String::as_str).collect::<Vec<_>>(),
        ),
        [one] => format!(" (did you mean {one}? a parameter is named with its block)"),
        [first @ .., last] => format!(
            " (did you mean {} or {last}? a parameter is named with its block)",
            first.join(", ")
        ),
    }
}
