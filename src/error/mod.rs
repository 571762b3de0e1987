//! Error types: [`Error`], the one error of the library's public functions.
//! Each failure is a kind with typed fields a caller can match on
//! ([`Error::kind`] gives the group): the input errors ([`InputError`]: the
//! file, line and column), the parameter errors ([`ParamError`]: the key,
//! the value and why it is wrong, a [`ParamReason`]), the option errors ([`OptionsError`]),
//! the fit errors ([`FitError`]), the step-steer metrics' errors
//! ([`MetricsError`]), the diagnosis's errors ([`DiagnosisError`]) and the
//! output errors ([`OutputError`]). Every message is complete on its own.

mod bank_degrees;
mod bank_reversed;
mod beta_sign;
mod bottoming;
mod camber;
mod campaign_file;
mod carried;
mod clock_fall;
mod decimal;
mod duplicate;
mod effect_limit;
mod file_kind;
mod fit;
mod foreign_format;
mod header_unit;
mod held_turn;
mod hold_rule;
mod input;
mod lateral_slope;
mod level_slip;
mod long_replay;
mod metrics;
mod min_speed;
mod missing_table;
mod none_with;
mod not_a_tyre;
mod number;
mod only_combined;
mod options;
mod output;
mod param;
mod path_found;
mod piece;
mod points_unit;
mod problem;
mod problem_name;
mod reason;
mod replay_run;
mod response_cell;
mod rig;
mod rig_exchanged;
mod rig_load_lbf;
mod rig_moment_knm;
mod rig_pressure;
mod rig_row;
mod rig_sign;
mod runs_selection;
mod scenario_file;
mod slip_degrees;
mod stall;
mod steady;
mod steer_cell;
mod steer_declared;
mod steer_runs;
mod steer_speed;
mod stiffness_unit;
mod sweep_limit;
#[cfg(test)]
mod tests;
mod too_many_rows;
mod units;
mod unseen;
mod unstable_step;
mod vehicle_limit;
mod yaw_scale;

pub use bank_degrees::BankInDegrees;
pub use bank_reversed::BankReversed;
pub use beta_sign::{BetaAgainstModel, BetaUnchecked, FilesAgainst};
pub use bottoming::{Bottoming, RimFrom};
pub use camber::{MOST_CAMBER, STEEP_CAMBER};
pub(crate) use campaign_file::folder_of;
pub use campaign_file::{CampaignFileProblem, NotCampaignKind};
pub use carried::WhyNotCarried;
pub use clock_fall::{ClockFall, Counter};
pub use duplicate::DuplicateAt;
pub use effect_limit::EffectLimit;
pub use file_kind::{FileKind, KindProblem, Wanted};
pub(crate) use fit::too_few_words;
pub use fit::{
    DesignError, DiagnosisError, FitError, SampleAccount, SkipReason, StageRows, StageSkip, Unseen,
};
pub use foreign_format::ForeignFormat;
pub use header_unit::{
    DeclaredBy, HeaderUnit, Quantity, RunsInRadians, Stated, Unit, UnitAdvice, YawAdvice,
};
pub use held_turn::{HeldTurn, HeldValue};
pub use hold_rule::{HoldAgainstRule, HoldRule};
pub(crate) use input::one_column_separator;
pub use input::{CellProblem, Counted, InputError, Location};
pub use lateral_slope::{BetaInPercent, LateralSlope, SlopeUnit};
pub use level_slip::{unit_slips, LevelSlip};
pub use long_replay::LongReplay;
pub use metrics::{MetricsError, SteadyAdvice, HELD_STEP, MIN_STRAIGHT};
pub use min_speed::{MinSpeedRemoved, TooFewRuns};
pub use missing_table::MissingTable;
pub use none_with::NoneWithEffects;
pub(crate) use number::hundredths_down;
pub use number::{number, range, Num};
pub use only_combined::OnlyCombined;
pub use options::{MergeInput, ModeDigit, ModeError, NameKind, OptionsError, ShardField};
pub use output::{OutputError, WriteStep};
pub use param::{ParamError, ParamValue};
pub use path_found::PathFound;
pub use piece::{GapAt, PieceRefusal, RefusedPiece};
pub use points_unit::{unit_factor, PointsUnit};
pub use problem::{InputProblem, RigChannel, SmallSlipSlope};
pub use reason::campaign::{GivenTyres, StagedMagicFormula, TyreSourceError};
pub use reason::{
    min_speed_checked, BeyondSignal, CampaignReason, CgTooLow, CurveFault, DeclaredHow, Limit,
    MassDigit, NoLateralForce, NoPressureLine, ParamReason, PerLoad, Rollover, ScheduleColumn,
    SlowSteer, Waveform, Wheelbase, DYNAMIC_INDEX, MAX_MIN_SPEED,
};
pub use replay_run::ReplayRunProblem;
pub use response_cell::{Response, ResponseBeyondAnyCar};
pub use rig::{Variable, INFLATION_PRESSURES, MIN_MEDIAN_LOAD, MIN_MEDIAN_PRESSURE};
pub use rig_exchanged::{LoadAndForceExchanged, EXCHANGED_SHARE};
pub use rig_load_lbf::{RigLoadInLbf, LBF_SLIP, MAX_MEDIAN_GRIP};
pub use rig_moment_knm::{RigMomentInKnm, MIN_RIG_ARM};
pub use rig_pressure::RigPressureAboveAny;
pub use rig_row::{RigSpeedBeyondAny, RigSpeedUnit};
pub use rig_sign::{CamberSlope, Reversal};
pub use runs_selection::{GlobMatch, SelectionProblem};
pub use scenario_file::{ScenarioProblem, ScenarioRemark};
pub use slip_degrees::{SlipAngleInDegrees, MAX_RIG_SLIP_ANGLE};
pub use stall::{AskedTurn, StallCause, TurnLimit, LARGE_STEER, NEAR_CRITICAL_GAIN};
pub use steady::NoSteadyState;
pub use steer_cell::SteerBeyondAnySensor;
pub use steer_declared::{DeclaredRun, SteerDeclaredRuns};
pub use steer_runs::{OtherRun, SteerInDegreesRuns, YawDeclaredRuns};
pub use steer_speed::LimitAtSpeed;
pub use stiffness_unit::{
    argument as stiffness_argument, StiffnessGiven, StiffnessSlip, LEAST_LOAD_STIFFNESS,
    MOST_LOAD_STIFFNESS,
};
pub use sweep_limit::{SwarmCount, SweepLimit, MAX_BOX_SIDESLIP, MAX_BOX_YAW_RATES};
use thiserror::Error;
pub use too_many_rows::{TooManyRows, HISTORY_ROW_BYTES};
pub use units::{
    AyReversed, PressureMeant, SpeedUnit, UnitSlip, MAX_RIG_ARM, MAX_RIG_FRICTION, MIN_RIG_GRIP,
    MIN_RIG_SLIP,
};
pub use unstable_step::{UnstableStep, RK4_STABILITY_LIMIT};
pub use vehicle_limit::{VehicleLimit, MAX_STEERING_RATIO, MIN_STEERING_RATIO};
pub use yaw_scale::YawScale;

/// The library's error: why a job (a command of the binary, or any public
/// function that reads, fits or writes) could not be done. Its message is
/// complete on its own; wrapped errors keep their own messages and sources.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// An input file that cannot be read or holds wrong content.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A parameter value that is not physical.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// Options that contradict each other or name nothing known.
    #[error(transparent)]
    Options(#[from] OptionsError),
    /// A fit that cannot be made or whose stages failed.
    #[error(transparent)]
    Fit(#[from] FitError),
    /// The step-steer metrics of a response could not be computed.
    #[error("step-steer metrics: {0}")]
    Metrics(#[from] MetricsError),
    /// The diagnosis could not be made.
    #[error(transparent)]
    Diagnosis(#[from] DiagnosisError),
    /// An output that may not or could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// The group of an [`Error`], to branch on without matching every kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// [`Error::Input`].
    Input,
    /// [`Error::Param`].
    Param,
    /// [`Error::Options`].
    Options,
    /// [`Error::Fit`].
    Fit,
    /// [`Error::Metrics`].
    Metrics,
    /// [`Error::Diagnosis`].
    Diagnosis,
    /// [`Error::Output`].
    Output,
}

impl ErrorKind {
    /// The group's name: `input`, `param`, `options`, `fit`, `metrics`,
    /// `diagnosis`, `output`.
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorKind::Input => "input",
            ErrorKind::Param => "param",
            ErrorKind::Options => "options",
            ErrorKind::Fit => "fit",
            ErrorKind::Metrics => "metrics",
            ErrorKind::Diagnosis => "diagnosis",
            ErrorKind::Output => "output",
        }
    }
}

impl Error {
    /// The error's group.
    pub fn kind(&self) -> ErrorKind {
        match self {
            Error::Input(_) => ErrorKind::Input,
            Error::Param(_) => ErrorKind::Param,
            Error::Options(_) => ErrorKind::Options,
            Error::Fit(_) => ErrorKind::Fit,
            Error::Metrics(_) => ErrorKind::Metrics,
            Error::Diagnosis(_) => ErrorKind::Diagnosis,
            Error::Output(_) => ErrorKind::Output,
        }
    }
}

/// The member of the closed set `all` whose name (`name`) is `s`, or the
/// error that names `s` and every member: "unknown {what} `s`: one of
/// a, b, c". The one parser of the names of closed sets (metrics, units,
/// tyre models).
pub fn named<T: Copy>(
    all: &[T],
    name: impl Fn(T) -> &'static str,
    what: NameKind,
    s: &str,
) -> Result<T, OptionsError> {
    all.iter()
        .copied()
        .find(|&m| name(m) == s)
        .ok_or_else(|| OptionsError::UnknownName {
            what,
            given: s.to_string(),
            known: all.iter().map(|&m| name(m)).collect(),
        })
}
