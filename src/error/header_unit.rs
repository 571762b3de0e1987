//! A CSV header column written as a column the command reads with a unit
//! after it (`alpha [deg]`, `speed (km/h)`, `fz_kN`), as loggers and rigs
//! write them: the unit is read, as a [`Unit`], and a unit other than the
//! one `FORMATS.md` reads the column in is refused with what to do for
//! that unit and that command ([`UnitAdvice`]): convert the values by the
//! unit's factor and name the column, or, where the reader takes the
//! column in degrees, name it and declare it so with the reader's own key
//! ([`DeclaredBy`]). Renaming alone would keep the values in their unit
//! and read them as SI. Factors: 1° = π/180 rad, 1 km/h = 1/3.6 m/s,
//! 1 mph = 0.44704 m/s, g = 9.80665 m/s² (standard gravity, CGPM 1901),
//! 1 lbf = 4.44822 N, 1 psi = 6894.76 Pa. A yaw rate in deg/s is advised
//! the same way, except a campaign's run among runs in rad/s, converted in
//! its own file (÷ 57.2958: [`YawAdvice`]).

use thiserror::Error;

/// Where a run's angle columns are declared in degrees: the reader that
/// reads the run, and so the one key a refusal names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DeclaredBy {
    /// `metrics --degrees COLUMN`.
    MetricsOption,
    /// A campaign's `[runs] degrees`.
    CampaignRuns,
    /// A replay scenario's `[manoeuvre] degrees`.
    ReplayManoeuvre,
}

impl DeclaredBy {
    /// The job that reads the file, as a message names it.
    pub fn job(self) -> &'static str {
        match self {
            DeclaredBy::MetricsOption => "`metrics`",
            DeclaredBy::CampaignRuns => "`diagnose`",
            DeclaredBy::ReplayManoeuvre => "a replay",
        }
    }

    /// The option or key, as a message names it.
    pub fn words(self) -> &'static str {
        match self {
            DeclaredBy::MetricsOption => "`--degrees` to `metrics`",
            DeclaredBy::CampaignRuns => "`degrees` under [runs]",
            DeclaredBy::ReplayManoeuvre => "`degrees` under [manoeuvre]",
        }
    }

    /// The declaration of `column` in degrees, as the user writes it.
    pub fn declaration(self, column: &str) -> String {
        match self {
            DeclaredBy::MetricsOption => format!("`--degrees {column}` to `metrics`"),
            DeclaredBy::CampaignRuns => format!(
                "`degrees = [\"{column}\"]` under [runs] in a campaign file (a campaign folder is read so by a campaign file whose [runs] has `dir` = its runs folder)"
            ),
            DeclaredBy::ReplayManoeuvre => {
                format!("`degrees = [\"{column}\"]` under [manoeuvre] in the scenario")
            }
        }
    }
}

/// How a `column` in degrees (deg/s) is declared to the reader that read
/// it (`by`): its own key only (a replay's refusal named `metrics
/// --degrees` and a campaign's `[runs]`, which a scenario has not).
pub(super) fn declare(column: &str, by: DeclaredBy) -> String {
    format!("declare it so: {}", by.declaration(column))
}

/// What a refusal of a yaw rate in deg/s advises ([`super::UnitSlip::YawRate`],
/// [`super::UnitSlip::YawRateInDegPerS`]): the run read alone, or with
/// runs whose yaw rate is in deg/s too, declares the column with its
/// reader's key; a campaign's run among runs that read in rad/s is
/// converted in its own file, as `degrees` under [runs] converts every
/// run's (a campaign has no per-run unit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum YawAdvice {
    /// Convert the column, or declare it in degrees by this key.
    Declare(DeclaredBy),
    /// Convert this run's file: other runs of its campaign read in rad/s.
    OwnFile(RunsInRadians),
}

/// A campaign's runs as a refusal of one run's yaw rate in deg/s counts
/// them ([`YawAdvice::OwnFile`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunsInRadians {
    /// The runs refused for a yaw rate in deg/s, this one among them.
    pub in_degrees: usize,
    /// The runs whose yaw rate, judged against their steer by a neutral
    /// car's r = u·δ/l, reads in rad/s.
    pub radians: usize,
    /// The campaign's run files.
    pub of: usize,
}

impl YawAdvice {
    /// The advice after "is the column in deg/s?": `convert` (as the
    /// refusal words it) or declare it; or, in a campaign whose other runs
    /// read in rad/s, convert this run's file.
    pub(super) fn words(self, convert: &str) -> String {
        let r = match self {
            YawAdvice::Declare(by) => return format!("{convert}, or {}", declare("yaw_rate", by)),
            YawAdvice::OwnFile(r) => r,
        };
        let these = match r.in_degrees {
            1 => "this run alone logs it so".to_string(),
            n => format!(
                "{n} of the campaign's {} runs log it so, this one among them",
                r.of
            ),
        };
        // A campaign advised so has other runs: "runs" is plural.
        let (verb, whose) = match r.radians {
            1 => ("reads", "its"),
            _ => ("read", "their"),
        };
        format!(
            "{these}, where {} of the campaign's {} runs {verb} {whose} yaw rate in rad/s, judged against {whose} steer by a neutral car's r = u·δ/l: a campaign has no per-run unit (`degrees = [\"yaw_rate\"]` under [runs] would convert every run's yaw rate, those in rad/s too): convert this run's `yaw_rate` to rad/s in its file (÷ 57.2958), or leave the run out of the campaign",
            r.radians, r.of,
        )
    }
}

/// What a unit measures; each is read in one SI unit ([`Quantity::si`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// s.
    Time,
    /// rad.
    Angle,
    /// rad/s.
    AngularRate,
    /// m/s.
    Speed,
    /// m/s².
    Acceleration,
    /// N.
    Force,
    /// N·m.
    Moment,
    /// Pa.
    Pressure,
    /// A ratio (slip ratio), 1.
    Ratio,
}

impl Quantity {
    /// The unit `FORMATS.md` reads the quantity in.
    pub fn si(self) -> Unit {
        match self {
            Quantity::Time => Unit::Second,
            Quantity::Angle => Unit::Radian,
            Quantity::AngularRate => Unit::RadianPerSecond,
            Quantity::Speed => Unit::MetrePerSecond,
            Quantity::Acceleration => Unit::MetrePerSecondSquared,
            Quantity::Force => Unit::Newton,
            Quantity::Moment => Unit::NewtonMetre,
            Quantity::Pressure => Unit::Pascal,
            Quantity::Ratio => Unit::One,
        }
    }

    /// Its name in a sentence.
    fn name(self) -> &'static str {
        match self {
            Quantity::Time => "a time",
            Quantity::Angle => "an angle",
            Quantity::AngularRate => "an angular rate",
            Quantity::Speed => "a speed",
            Quantity::Acceleration => "an acceleration",
            Quantity::Force => "a force",
            Quantity::Moment => "a moment",
            Quantity::Pressure => "a pressure",
            Quantity::Ratio => "a ratio",
        }
    }
}

/// A unit a header states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Unit {
    Second,
    Millisecond,
    Radian,
    Degree,
    RadianPerSecond,
    DegreePerSecond,
    MetrePerSecond,
    KilometrePerHour,
    MilePerHour,
    MetrePerSecondSquared,
    StandardGravity,
    Newton,
    Kilonewton,
    PoundForce,
    NewtonMetre,
    KilonewtonMetre,
    NewtonMillimetre,
    Pascal,
    Kilopascal,
    Megapascal,
    Bar,
    Psi,
    One,
    Percent,
}

/// Every unit with its spellings (lower case, spaces removed) and the
/// quantity it measures; the first spelling is the one a message shows.
const UNITS: [(Unit, &[&str], Quantity); 24] = [
    (Unit::Second, &["s", "sec"], Quantity::Time),
    (Unit::Millisecond, &["ms"], Quantity::Time),
    (Unit::Radian, &["rad"], Quantity::Angle),
    (
        Unit::Degree,
        &["deg", "°", "degree", "degrees"],
        Quantity::Angle,
    ),
    (Unit::RadianPerSecond, &["rad/s"], Quantity::AngularRate),
    (
        Unit::DegreePerSecond,
        &["deg/s", "°/s", "dps", "degs"],
        Quantity::AngularRate,
    ),
    (Unit::MetrePerSecond, &["m/s", "mps"], Quantity::Speed),
    (
        Unit::KilometrePerHour,
        &["km/h", "kmh", "kph"],
        Quantity::Speed,
    ),
    (Unit::MilePerHour, &["mph"], Quantity::Speed),
    (
        Unit::MetrePerSecondSquared,
        &["m/s²", "m/s2", "m/s^2", "m/s/s", "ms-2", "mps2"],
        Quantity::Acceleration,
    ),
    (Unit::StandardGravity, &["g"], Quantity::Acceleration),
    (Unit::Newton, &["n"], Quantity::Force),
    (Unit::Kilonewton, &["kn"], Quantity::Force),
    (Unit::PoundForce, &["lbf", "lb"], Quantity::Force),
    (
        Unit::NewtonMetre,
        &["n·m", "nm", "n.m", "n*m", "n-m"],
        Quantity::Moment,
    ),
    (
        Unit::KilonewtonMetre,
        &["kn·m", "knm", "kn.m"],
        Quantity::Moment,
    ),
    (
        Unit::NewtonMillimetre,
        &["n·mm", "nmm", "n.mm"],
        Quantity::Moment,
    ),
    (Unit::Pascal, &["pa"], Quantity::Pressure),
    (Unit::Kilopascal, &["kpa"], Quantity::Pressure),
    (Unit::Megapascal, &["mpa"], Quantity::Pressure),
    (Unit::Bar, &["bar"], Quantity::Pressure),
    (Unit::Psi, &["psi"], Quantity::Pressure),
    (Unit::One, &["-", "1"], Quantity::Ratio),
    (Unit::Percent, &["%"], Quantity::Ratio),
];

impl Unit {
    /// The unit a header's text names (any case, spaces ignored), if known.
    pub fn parse(text: &str) -> Option<Unit> {
        let t: String = text
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect::<String>()
            .to_lowercase();
        UNITS
            .iter()
            .find(|(_, names, _)| names.contains(&t.as_str()))
            .map(|(u, _, _)| *u)
    }

    fn entry(self) -> &'static (Unit, &'static [&'static str], Quantity) {
        UNITS
            .iter()
            .find(|(u, _, _)| *u == self)
            .expect("every unit is listed")
    }

    /// What it measures.
    pub fn quantity(self) -> Quantity {
        self.entry().2
    }

    /// Its symbol in a message.
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::Newton => "N",
            Unit::Kilonewton => "kN",
            Unit::NewtonMetre => "N·m",
            Unit::KilonewtonMetre => "kN·m",
            Unit::NewtonMillimetre => "N·mm",
            Unit::Pascal => "Pa",
            Unit::Kilopascal => "kPa",
            Unit::Megapascal => "MPa",
            Unit::One => "1 (no unit)",
            _ => self.entry().1[0],
        }
    }

    /// The conversion to the quantity's SI unit, as a user applies it:
    /// `× π/180 (0.0174533)`, `÷ 3.6`, `× 1000`.
    pub fn conversion(self) -> &'static str {
        match self {
            Unit::Degree | Unit::DegreePerSecond => "× π/180 = 0.0174533",
            Unit::KilometrePerHour => "÷ 3.6",
            Unit::MilePerHour => "× 0.44704",
            Unit::StandardGravity => "× 9.80665",
            Unit::Kilonewton | Unit::KilonewtonMetre | Unit::Kilopascal => "× 1000",
            Unit::Millisecond | Unit::NewtonMillimetre => "÷ 1000",
            Unit::PoundForce => "× 4.44822",
            Unit::Megapascal => "× 1000000",
            Unit::Bar => "× 100000",
            Unit::Psi => "× 6894.76",
            Unit::Percent => "÷ 100",
            _ => "× 1",
        }
    }
}

/// What a header's stated unit is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stated {
    /// A unit this tool knows.
    Known(Unit),
    /// A text in brackets that names no unit this tool knows.
    Unknown(Box<str>),
}

/// What the user is to do with a column whose header states a unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnitAdvice {
    /// Convert the values by the unit's factor and name the column.
    Convert,
    /// Name the column and declare it in degrees with this reader's key.
    Declare(DeclaredBy),
    /// The unit measures another quantity than the column: another
    /// channel, or a header written wrong.
    OtherQuantity,
    /// A unit the tool does not know: convert to the SI unit.
    UnknownUnit,
}

/// A header column that is a known column with a unit other than the one
/// the column is read in.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{}", self.words())]
pub struct HeaderUnit {
    /// The header's text, as written.
    pub header: Box<str>,
    /// The column it names.
    pub column: &'static str,
    /// What the column measures.
    pub quantity: Quantity,
    /// The unit it states.
    pub stated: Stated,
    /// What to do.
    pub advice: UnitAdvice,
}

impl HeaderUnit {
    fn words(&self) -> String {
        let (h, c) = (&self.header, self.column);
        let si = self.quantity.si().symbol();
        let unit = match &self.stated {
            Stated::Known(u) => u.symbol().to_string(),
            Stated::Unknown(t) => t.to_string(),
        };
        let head =
            format!("column `{h}` is `{c}` in {unit}, and `{c}` is read in {si} (FORMATS.md)");
        let convert = |u: &Unit| {
            format!("convert the values ({}) and name the column `{c}` (or `{c} [{si}]`): renamed alone, its values would be read as {si}", u.conversion())
        };
        match (&self.advice, &self.stated) {
            (UnitAdvice::Convert, Stated::Known(u)) => format!("{head}: {}", convert(u)),
            (UnitAdvice::Declare(by), Stated::Known(u)) => format!(
                "{head}: name the column `{c}` and declare it in degrees: {}; or {}",
                by.declaration(c),
                convert(u)
            ),
            (UnitAdvice::OtherQuantity, Stated::Known(u)) => format!(
                "column `{h}` states {}, {}'s unit, where `{c}` is {}, read in {si} (FORMATS.md): is the column another channel, or its unit written wrong?",
                u.symbol(),
                u.quantity().name(),
                self.quantity.name()
            ),
            _ => format!(
                "column `{h}` states the unit `{unit}`, which this tool does not know: `{c}` is read in {si} (FORMATS.md); convert the values to {si} and name the column `{c}` (or `{c} [{si}]`)"
            ),
        }
    }
}
