//! What is wrong with an input file's content, as typed fields: the
//! column, the value as read, the counts and limits behind the verdict.
//! Each problem's message is complete once the file (and where known the
//! line and column) is put before it by [`InputError::Invalid`].
//!
//! Units as the files write them: SI, radians; the messages print angles
//! in degrees where people read them so.
//!
//! [`InputError::Invalid`]: super::InputError::Invalid

use super::camber::camber_beyond;
use super::duplicate::DuplicateAt;
use super::level_slip::{level_list, requested as requested_text, unit_slip, LevelSlip};
use super::number::{past_end, Num};
use super::piece::RefusedPiece;
use super::rig::Variable;
use super::rig_sign::wrong_sign;
pub use super::rig_sign::{RigChannel, SmallSlipSlope};
use super::units::UnitSlip;
use super::ParamError;
use super::PathFound;
use crate::format::{plural, significant};
use std::path::PathBuf;
use thiserror::Error;

/// What is wrong with an input file's content.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum InputProblem {
    /// The CSV reader cannot open the file as CSV.
    #[error("{detail}")]
    Csv {
        /// The CSV reader's description.
        detail: String,
    },
    /// The CSV header line cannot be read.
    #[error("cannot read the header line: {detail}")]
    Header {
        /// The CSV reader's description.
        detail: String,
    },
    /// A byte that is not UTF-8 in a text file that must be.
    #[error("byte 0x{byte:02X} is not UTF-8: the file must be UTF-8 text (was it saved as Latin-1 or Windows-1252?)")]
    NotUtf8 {
        /// The byte.
        byte: u8,
    },
    /// The JSON reader's own description of a syntax or structure error
    /// (a `diagnosis.json` read back).
    #[error("{detail}")]
    Json {
        /// The JSON reader's description.
        detail: String,
    },
    /// A table the file's kind requires, absent (boxed).
    #[error("{0}")]
    MissingTable(Box<super::MissingTable>),
    /// The TOML reader's own description of a syntax or structure error.
    #[error("{detail}")]
    Toml {
        /// The TOML reader's description.
        detail: String,
    },
    /// A key naming a file or folder that does not exist, or is the other of the two.
    #[error("`{key}`{} names {}, {} ({})", written.as_ref().map_or(String::new(), |w| format!(" = \"{w}\"")), target.display(), found.describe(), read_from(written.as_deref(), base))]
    MissingFile {
        /// Dotted key.
        key: String,
        /// The path as the file writes it, when the key holds one string
        /// (boxed, as the paths: the error stays as small as it was).
        written: Option<Box<str>>,
        /// The path it resolved to.
        target: Box<std::path::Path>,
        /// The file the key is in.
        base: Box<std::path::Path>,
        /// What is there instead.
        found: PathFound,
    },
    /// A `.tir` section header without its closing bracket.
    #[error("section header `{header}` has no closing `]`")]
    TirSectionUnclosed {
        /// The header as written.
        header: String,
    },
    /// A `.tir` line whose text before `=` is not a key.
    #[error("`{text}` is not a key")]
    TirNotAKey {
        /// The text before `=`.
        text: String,
    },
    /// A `.tir` string value without its closing quote.
    #[error("`{key}`: the string {body} has no closing {quote}")]
    TirStringUnclosed {
        /// The key.
        key: String,
        /// The value as written.
        body: String,
        /// The opening quote.
        quote: char,
    },
    /// A `.tir` key without a value.
    #[error("`{key}` has no value")]
    TirNoValue {
        /// The key.
        key: String,
    },
    /// A `.tir` number that is not finite.
    #[error("`{key}`: {} is not finite", Num(*value))]
    TirNotFinite {
        /// The key.
        key: String,
        /// The value read.
        value: f64,
    },
    /// A `.tir` value that should be a number and is not (a decimal comma
    /// said as the CSV and TOML readers say it).
    #[error("`{key}`: `{text}` is not a number{}", super::decimal::tir_comma(text))]
    TirNotANumber {
        /// The key.
        key: String,
        /// The value as written.
        text: String,
    },
    /// A unit of the `[UNITS]` section that the reader does not know.
    #[error("`{key}`: unknown unit `{unit}`")]
    TirUnknownUnit {
        /// The `[UNITS]` key.
        key: &'static str,
        /// The unit as written.
        unit: String,
    },
    /// Angles given in another unit than radians.
    #[error("`ANGLE`: `{unit}`: only radians are supported for Magic Formula coefficients")]
    TirAngleNotRadians {
        /// The unit as written.
        unit: String,
    },
    /// A `FITTYP` that names no supported Magic Formula version.
    #[error(
        "`FITTYP`: `{written}` is not a supported Magic Formula (6 or 21: 5.2, 61: 6.1, 62: 6.2)"
    )]
    TirUnsupportedFittyp {
        /// The value as written.
        written: String,
    },
    /// No `FITTYP` and no PAC2002 format to stand for it.
    #[error("missing key `FITTYP` in [MODEL] (61 or 62 for MF 6.1/6.2, 6 or 21 for 5.2; or PROPERTY_FILE_FORMAT = 'PAC2002')")]
    TirNoFittyp,
    /// A `TYRESIDE` that is neither side.
    #[error("`TYRESIDE`: `{side}` is not LEFT or RIGHT")]
    TirSide {
        /// The value as written.
        side: String,
    },
    /// A key every Magic Formula file needs.
    #[error("missing key `{key}`")]
    TirMissingKey {
        /// The key.
        key: &'static str,
    },
    /// Coefficients every published Magic Formula file carries, absent.
    #[error("lacks {} of the peak and shape coefficients every Magic Formula file carries, without which its forces are meaningless: is the file complete (it has {lines} lines)?{}", missing.join(", "), near.iter().map(|(k, line, w)| format!(" `{w}` at line {line}: `{k}` misspelt?")).collect::<String>())]
    TirCoefficientsMissing {
        /// The coefficients missing.
        missing: Vec<&'static str>,
        /// Unknown keys like a missing one: (it, their line, as written).
        near: Vec<(&'static str, usize, String)>,
        /// The file's lines.
        lines: usize,
    },
    /// A coefficient whose value is not physical.
    #[error("`{}`: {} {}", .0.key, .0.value, .0.reason)]
    TirValue(ParamError),
    /// A JSON file that is not a shard file of this version.
    #[error("not a shard file of this version: {detail}")]
    NotAShard {
        /// The JSON reader's description.
        detail: String,
    },
    /// A time that does not follow the previous one.
    #[error("column `t`: {} does not follow {} (time must be strictly increasing{fall})", Num(*value), Num(*previous))]
    TimeNotIncreasing {
        /// The time, s.
        value: f64,
        /// The previous row's time, s.
        previous: f64,
        /// How it fails to follow, with what to do.
        fall: super::ClockFall,
    },
    /// A run with fewer than two samples.
    #[error("a run needs at least two samples")]
    TooFewSamples,
    /// A road-wheel steer beyond ±90° over more than 1 % of the run.
    #[error("column `steer`: {} rad is beyond ±90° (the run's 99th percentile of |steer| is {p99:.3} rad): the steer is the road-wheel angle in radians (FORMATS.md); is the column in degrees, or a steering-wheel angle (divide by the steering ratio)? A steer in degrees is converted in the file, or {}", Num(*value), super::units::declare("steer", *by))]
    SteerBeyondQuarterTurn {
        /// The first steer beyond ±90°, rad.
        value: f64,
        /// The 99th percentile of |steer|, rad.
        p99: f64,
        /// Where the reader takes the column in degrees.
        by: super::DeclaredBy,
    },
    /// One steer sample beyond any steer sensor's (`steer_cell.rs`).
    #[error(transparent)]
    SteerBeyondAnySensor(#[from] super::steer_cell::SteerBeyondAnySensor),
    /// One response sample beyond any car's (`response_cell.rs`).
    #[error(transparent)]
    ResponseBeyondAnyCar(#[from] super::response_cell::ResponseBeyondAnyCar),
    /// A negative vertical load.
    #[error("column `fz`: {} N is negative (loads are positive in FORMATS.md){}", Num(*value), if *every { "; every load of the file is: a rig whose z axis points down (SAE's axes) logs them so; negate the column" } else { "" })]
    NegativeLoad {
        /// The load, N.
        value: f64,
        /// Whether every load of the file is negative (a sign convention, not a glitch).
        every: bool,
    },
    /// `fz` and `fy` exchanged (`rig_exchanged.rs`).
    #[error(transparent)]
    LoadAndForceExchanged(#[from] super::rig_exchanged::LoadAndForceExchanged),
    /// A rig file's pressure above any tyre's (`rig_pressure.rs`).
    #[error(transparent)]
    RigPressureAboveAny(#[from] super::rig_pressure::RigPressureAboveAny),
    /// A non-positive inflation pressure.
    #[error("column `pressure`: {} Pa is not a positive pressure", Num(*value))]
    NonPositivePressure {
        /// The pressure, Pa.
        value: f64,
    },
    /// A tyre point's speed below 0 (a slip angle within ±90° rolls forwards).
    #[error("column `speed`: {} m/s is negative: `speed` is the wheel's forward speed, 0 or more (FORMATS.md): a slip angle within ±90° already has the wheel rolling forwards (ISO 8855 measures it from the wheel's heading to its travel), and the models differ on a negative speed (a Magic Formula flips fy and my, the others ignore it); give the speed's size", Num(*value))]
    NegativeSpeed {
        /// The speed, m/s.
        value: f64,
    },
    /// A tyre input outside the range a tyre model is evaluated in.
    #[error("column `{column}`: {} a tyre is evaluated at ({why})", past_end(*value, *lo, *hi, unit))]
    NotPhysical {
        /// The column.
        column: &'static str,
        /// The value read.
        value: f64,
        /// The range's lower end.
        lo: f64,
        /// The range's upper end.
        hi: f64,
        /// The column's unit.
        unit: &'static str,
        /// What the range's ends are.
        why: &'static str,
    },
    /// A tyre model that gives a non-finite output at a point; at a load
    /// so small that its square underflows (`tiny_load`), that load is
    /// the cause, said with it.
    #[error("the {model} tyre gives a non-finite `{output}` at this point{}", tiny_load.map_or(String::new(), |fz| format!(": fz = {} N is a load so small that the model's load terms underflow to 0 (no tyre on the road carries it; a wheel off the road is fz ≤ 0)", Num(fz))))]
    NonFiniteOutput {
        /// The tyre model.
        model: &'static str,
        /// The output column.
        output: &'static str,
        /// The point's load, N, where it is positive and so small that its
        /// square underflows.
        tiny_load: Option<f64>,
    },
    /// A points CSV given where `tyre-eval` takes its tyre file.
    #[error("not a tyre file (.tir/.toml): it looks like a points CSV; the order is `tyre-eval <tyre> <points>`")]
    PointsAsTyre,
    /// A load a Magic Formula file's vertical model does not carry
    /// (`carried.rs`: at no radius, Re through 0, past the rim).
    #[error("fz = {} N is more than the tyre's vertical model carries: {why}, so no loaded radius `rl` is physical there{}", Num(*fz), why.held())]
    LoadNotCarried {
        /// The load, N.
        fz: f64,
        /// Why it is not carried.
        why: super::carried::WhyNotCarried,
    },
    /// A pressure outside a Magic Formula file's range at which its
    /// vertical model does not carry the point's load, which it carries at
    /// the range's end (the limit checks off).
    #[error("pressure = {} Pa, outside the file's PRESMIN–PRESMAX, is why the tyre's vertical model does not carry this load (at most {} N at a deflection of its whole free radius, {} m, where at the range's end it carries it): its pressure terms extrapolated this far describe no tyre, and no loaded radius `rl` exists (the limit checks, mode 1xx, hold the pressure within the range)", Num(*pressure), significant(*most, 4), significant(*free, 4))]
    PressureCarriesNoLoad {
        /// The pressure, Pa.
        pressure: f64,
        /// What the vertical model carries there at most, N.
        most: f64,
        /// The free radius, m.
        free: f64,
    },
    /// A rig slip ratio beyond ±1 (a locked wheel is −1; rigs sweep to
    /// about ±0.3): a column in percent.
    #[error("column `kappa`: {} is beyond ±1 (a locked wheel's slip ratio is −1; a rig sweeps to about ±0.3): the slip ratio is a fraction (FORMATS.md); is the column in percent? divide it by 100", Num(*value))]
    SlipRatioInPercent {
        /// The slip ratio as read.
        value: f64,
    },
    /// An angle beyond what a tyre test in radians reaches ([`camber_beyond`]).
    #[error("column `{column}`: {}: angles are in radians (FORMATS.md); is the column in degrees?", camber_beyond(column, *value, *limit))]
    AngleInDegrees {
        /// The column (`alpha`, `camber`).
        column: &'static str,
        /// The angle as read, rad.
        value: f64,
        /// The largest angle accepted, rad.
        limit: f64,
    },
    /// A rig file with neither a lateral nor a longitudinal sweep.
    #[error(
        "no lateral data (columns `alpha` and `fy`) and no longitudinal data (`kappa` and `fx`); the header has: {}",
        header.join(", ")
    )]
    NoSweep {
        /// The header's names, in the file's order.
        header: Vec<String>,
    },
    /// A rig file without the lateral sweep a lateral fit needs.
    #[error("no lateral data: a lateral fit needs the columns `alpha` and `fy`")]
    NoLateral,
    /// A rig file without the longitudinal sweep the grouping needs.
    #[error("no longitudinal data (columns `kappa` and `fx`) to group")]
    NoLongitudinal,
    /// A rig channel with the opposite sign to FORMATS.md's at small slip.
    #[error("{}", wrong_sign(*channel, *position, slope, *beside))]
    WrongSign {
        /// The channel.
        channel: RigChannel,
        /// Its 1-based position in the header.
        position: usize,
        /// Its slope near zero slip ([`RigChannel::Alpha`]: `fy`'s).
        slope: SmallSlipSlope,
        /// The other channel's slope: the lateral force's, N/rad, beside
        /// [`RigChannel::Mz`]; the aligning moment's, N·m/rad, beside
        /// [`RigChannel::Alpha`].
        beside: Option<f64>,
    },
    /// A requested camber or pressure that no level of the file lies near.
    #[error("no {} level near the requested {}{} (levels: {}; a level holds values within {} of its range)", variable.column(), requested_text(*variable, *requested), unit_slip(*variable, *requested, slip), level_list(*variable, levels), variable.in_option_unit(*separation))]
    NoLevelNear {
        /// The grouping variable.
        variable: Variable,
        /// The requested value (SI).
        requested: f64,
        /// The nominal values of the file's levels (SI).
        levels: Vec<f64>,
        /// The separation of levels (SI).
        separation: f64,
        /// The request read in another unit, where it selects a level or
        /// the request is no test's in SI.
        slip: Option<LevelSlip>,
    },
    /// A pressure requested from a file without pressures.
    #[error("a pressure was requested but the file has no `pressure` column")]
    NoPressureColumn,
    /// A camber other than 0 requested from a file without cambers.
    #[error("camber {:.2}° was requested but the file has no `camber` column (its samples are at camber 0){}", camber.to_degrees(), super::level_slip::no_column_slip(super::rig::Variable::Camber, *camber))]
    NoCamberColumn {
        /// The requested camber, rad.
        camber: f64,
    },
    /// A run with no two successive samples fast enough.
    #[error("no two successive samples at or above min_speed = {} m/s ({slow} of {read} samples below it): a run this slow is measured with a lower --min-speed (min_speed in a campaign, Python's min_speed=)", Num(*min_speed))]
    NoMovingSamples {
        /// The speed threshold, m/s.
        min_speed: f64,
        /// Samples below it.
        slow: usize,
        /// Samples read.
        read: usize,
    },
    /// A run none of whose moving pieces holds a steer step.
    #[error("{}", super::piece::no_steer_step(pieces, gaps))]
    NoSteerStep {
        /// The pieces and why each was refused.
        pieces: Vec<RefusedPiece>,
        /// The time gaps that split the run into them: start, length, s.
        gaps: Vec<(f64, f64)>,
    },
    /// A runs folder without CSV files.
    #[error("no measured runs: the runs folder {} holds no *.csv file{}", folder.display(), match holds.is_empty() {
        true => " (it is empty)".to_string(),
        false => format!(" (it holds {})", holds.join(", ")),
    })]
    EmptyRunsFolder {
        /// The folder.
        folder: PathBuf,
        /// What it holds instead, by name (a folder with a trailing `/`):
        /// a user who put the runs in a subfolder or as `.txt` sees where.
        holds: Vec<String>,
    },
    /// A run listed twice.
    #[error("the run {} is listed twice (as {} too): each run is held out once", run.display(), also.display())]
    RunListedTwice {
        /// The run as listed the second time.
        run: PathBuf,
        /// The run as listed first.
        also: PathBuf,
    },
    /// A campaign that names no run.
    #[error("no measured runs: list them in [runs] files = [...] or dir = \"...\" (a campaign folder reads runs/*.csv){}", campaign_folder.as_ref().map_or(String::new(), |f| format!("; its folder has runs/: diagnose the folder instead, `handling diagnose {}`", f.display())))]
    NoRuns {
        /// The folder of the vehicle file when it is a campaign folder
        /// (it has `runs/`) passed as a file.
        campaign_folder: Option<PathBuf>,
    },
    /// A campaign folder without `vehicle.toml`.
    #[error("a campaign folder needs vehicle.toml (with a [vehicle] table), runs/*.csv and optionally tyre_rig.csv")]
    NoVehicleFile,
    /// A column named twice in a CSV header, or a key given twice in one
    /// section of a file: one of the two would be dropped silently.
    #[error("`{name}` appears twice (also {first}): keep the one that holds the value")]
    Duplicate {
        /// The column's or key's name.
        name: String,
        /// Where it appears first.
        first: DuplicateAt,
    },
    /// A known column stated in another unit than its own (`header_unit.rs`).
    #[error(transparent)]
    UnitInHeader(#[from] super::header_unit::HeaderUnit),
    /// A header column a slip of spelling away from a column the command
    /// reads and the file lacks: it would be ignored, and its values lost.
    #[error("column `{found}` is not one this command reads: did you mean `{meant}`? Rename it (a column the command does not read is ignored, and the values of `{meant}` taken as absent)")]
    Misspelled {
        /// The header's column.
        found: String,
        /// The column it likely means.
        meant: Box<str>,
    },
    /// A steer that holds one value over a whole run while the car turns
    /// (both ways, or at all on a zero steer): a dead or unplugged steer
    /// sensor, whose run a replay would drive straight.
    #[error("channel `steer` holds one value ({}) over the whole run while the yaw rate turns the car (its neutral steer r·l/u reaches {} rad at speed): a dead or unplugged steer sensor; a replay of it drives {}: fix the log or leave the run out", Num(*value), Num(*neutral), if *value == 0.0 { "straight" } else { "one constant steer" })]
    DeadSteer {
        /// The value the steer holds, rad.
        value: f64,
        /// The neutral steer `r·l/u` of largest size at speed (5th or 95th
        /// percentile), rad.
        neutral: f64,
    },
    /// A response channel that holds one value over a whole run: a dead
    /// or unplugged sensor, to which no model can be fitted (its noise
    /// floor is zero, every gap infinitely significant).
    #[error("channel `{channel}` holds one value ({}) over the whole run: a dead or unplugged sensor, which measures nothing (no model can be fitted to it, no metric read from it); {}", Num(*value), if *required { "fix the log or leave the run out" } else { "remove the column (it is optional) or fix the log" })]
    DeadChannel {
        /// The channel.
        channel: &'static str,
        /// The value it holds.
        value: f64,
        /// Whether the format requires the channel.
        required: bool,
    },
    /// A run whose yaw rate turns against its steer.
    #[error("the yaw rate turns against the steer (median r·l/(u·δ) = {median:.2} over {samples} steered samples): FORMATS.md's ISO 8855 signs give a positive yaw rate for a positive (left) steer; {}", reversed_channel(*ay_with_steer))]
    YawAgainstSteer {
        /// Median of r·l/(u·δ) over the steered samples.
        median: f64,
        /// The steered samples.
        samples: usize,
        /// The share of them whose `ay` turns with the steer, where the
        /// run has `ay`.
        ay_with_steer: Option<f64>,
    },
    /// A yaw rate that does not follow the steer: it turns with it on no
    /// more samples than against it, or holds one value wherever the steer
    /// is held (a channel logging noise, a frozen sensor).
    #[error("the yaw rate does not follow the steer: where the steer is held ({samples} samples at speed), {}; a steer in degrees or a steering-wheel angle would still turn the car with the steer on nearly all of them: is `yaw_rate` the gyro's yaw rate, logged while the car moved?", match one_value { Some(v) => format!("it holds one value, {} rad/s, on every one (a frozen sensor; the cleaning finds a stuck value only between moving samples)", crate::format::readable(*v, 3)), None => format!("it turns with the steer on {} % of them and against it on {} % (noise about zero, not a response)", crate::format::readable(100.0 * with_steer, 2), crate::format::readable(100.0 * against, 2)) })]
    YawIgnoresSteer {
        /// Share of the samples whose yaw rate turns with the steer.
        with_steer: f64,
        /// Share turning against it.
        against: f64,
        /// The one value the yaw rate holds on all of them, rad/s.
        one_value: Option<f64>,
        /// The held steered samples.
        samples: usize,
    },
    /// A steer far larger than its yaw rate: in degrees, or a steering-wheel angle.
    #[error("the yaw rate is {} than a neutral car's for this steer (median r·l/(u·δ) = {} over {samples} steered samples{}{}): is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio), or `yaw_rate` declared in degrees while it was in rad/s? The steer is the road-wheel angle in radians (a steer in degrees makes it 57× smaller on a neutral car, more on an understeering one, less where the wheelbase taken is longer than the car's); a column in degrees is declared so: `metrics --degrees steer`, or `degrees = [\"steer\"]` under a campaign's [runs]", if *median > 0.0 { format!("{}× smaller", crate::format::readable(1.0 / median, 2)) } else { "far smaller".into() }, crate::format::fixed_apart(&[*median], 3)[0], assumed_wheelbase.map_or(String::new(), |l| format!(", with l = {} m, longer than any car's wheelbase", Num(l))), at_speed.map_or(String::new(), |a| format!("; refused {a}")))]
    SteerAboveYaw {
        /// Median of r·l/(u·δ) over the steered samples.
        median: f64,
        /// The steered samples.
        samples: usize,
        /// The wheelbase l taken when the vehicle's is not known, m.
        assumed_wheelbase: Option<f64>,
        /// The limit where the speed lowered it (`least_gain.rs`).
        at_speed: Option<crate::error::LimitAtSpeed>,
    },
    /// A yaw rate far larger than a car's for its steer: a steer in
    /// radians divided by 57 once more, a yaw rate in deg/s, or a column
    /// declared in degrees that was not.
    #[error("the yaw rate is {}× a neutral car's for this steer (median r·l/(u·δ) = {} over {samples} steered samples{}): no car that is not spinning turns so much for its steer; is `steer` in radians divided by 57 once more, or `yaw_rate` in deg/s, or was a column declared in degrees already in radians?", crate::format::readable(*median, 2), crate::format::readable(*median, 3), assumed_wheelbase.map_or(String::new(), |l| format!(", with l = {} m, shorter than any car's wheelbase", Num(l))))]
    YawAboveSteer {
        /// Median of r·l/(u·δ) over the steered samples.
        median: f64,
        /// The steered samples.
        samples: usize,
        /// The wheelbase l taken where the vehicle's is not known (the
        /// shortest a car has), m.
        assumed_wheelbase: Option<f64>,
    },
    /// A column declared in degrees that the file does not have: the
    /// declaration would otherwise be dropped without a word (a misspelt
    /// header, a declaration meant for another file).
    #[error("{by} names `{column}`, a column this file does not have (its columns: {}){}", header.join(", "), crate::format::nearest_name(column, &header.iter().map(String::as_str).collect::<Vec<_>>()).map_or(String::new(), |k| format!("; did you mean `{k}`? Rename the column to `{column}`")))]
    DegreesColumnAbsent {
        /// The column declared.
        column: &'static str,
        /// Where it was declared (`--degrees` to `metrics`, `degrees`
        /// under `[runs]` or `[manoeuvre]`).
        by: &'static str,
        /// The header's columns.
        header: Vec<String>,
    },
    /// A column declared in degrees that the job does not read (`metrics
    /// --degrees roll`): the declaration would convert nothing, without a
    /// word, as [`InputProblem::DegreesColumnAbsent`]'s would.
    #[error("{by} names `{column}`, a column {job} does not read (the angle columns it reads: {}): the declaration would convert nothing; leave it out", reads.join(", "))]
    DegreesColumnUnread {
        /// The column declared.
        column: &'static str,
        /// Where it was declared.
        by: &'static str,
        /// The job that reads the file (`` `metrics` ``).
        job: &'static str,
        /// The angle columns it reads.
        reads: Vec<&'static str>,
    },
    /// A column in another unit than FORMATS.md's.
    #[error(transparent)]
    UnitSlip(#[from] UnitSlip),
    /// A `tyre-eval` points column in another unit (`points_unit.rs`).
    #[error(transparent)]
    PointsUnit(#[from] super::points_unit::PointsUnit),
    /// A run too short to show a response.
    #[error("the run is {span:.2} s long with {}: a run needs at least {} s and {min_samples} samples to show a response", plural(*samples, "sample", "samples"), Num(*min_span))]
    RunTooShort {
        /// Its duration, s.
        span: f64,
        /// Its samples.
        samples: usize,
        /// The shortest run accepted, s.
        min_span: f64,
        /// The fewest samples accepted.
        min_samples: usize,
    },
    /// Fewer than two runs left for held-out scoring (`min_speed.rs`).
    #[error("{few}")]
    TooFewRuns {
        /// The runs left and what the campaign can do about it.
        few: Box<super::TooFewRuns>,
    },
    /// A run taken beside runs refused, its `beta` not judged yet.
    #[error("{0}")]
    BetaUnchecked(super::BetaUnchecked),
    /// A campaign file that is no campaign, or lists its runs by a glob.
    #[error(transparent)]
    Campaign(Box<super::CampaignFileProblem>),
    /// A scenario file refused as a whole or at a table (boxed).
    #[error("{0}")]
    Scenario(Box<super::ScenarioProblem>),
    /// A file of another kind than the reader's, or a key naming what no file given has (boxed).
    #[error("{0}")]
    Kind(Box<super::KindProblem>),
}

/// Where [`InputProblem::MissingFile`]'s path was read from: a relative
/// path as `written` in the file `base`, from that file's folder.
fn read_from(written: Option<&str>, base: &std::path::Path) -> String {
    let folder = match base.parent().map(|p| p.display().to_string()) {
        Some(p) if !p.is_empty() => p,
        _ => ".".into(),
    };
    match written {
        Some(w) if std::path::Path::new(w).is_absolute() => {
            format!("as written in {}", base.display())
        }
        Some(w) => format!(
            "\"{w}\" read from {folder}, the folder of {}",
            base.display()
        ),
        None => format!(
            "relative paths are read from {folder}, the folder of {}",
            base.display()
        ),
    }
}

#[cfg(test)]
#[path = "problem_tests.rs"]
mod tests;

/// Which channel a yaw rate against the steer is in, by the run's `ay`
/// (`ay = u·r` in a steady turn): with the steer on 80 % of the steered
/// samples or more, the yaw rate; against it on as many, the steer.
fn reversed_channel(ay_with_steer: Option<f64>) -> String {
    match ay_with_steer {
        Some(w) if w >= 0.8 => format!("the run's `ay` turns with the steer on {:.0} % of them: `yaw_rate` is in the other sign convention; negate it", 100.0 * w),
        Some(w) if w <= 0.2 => format!("the run's `ay` turns with the yaw rate, against the steer on {:.0} % of them: `steer` is in the other sign convention; negate it", 100.0 * (1.0 - w)),
        _ => "is `steer` or `yaw_rate` in another sign convention? negate it".to_string(),
    }
}
