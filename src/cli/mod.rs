//! Argument parsing and printing; every command is one library function
//! ([`handling::jobs`], [`handling::jobs::identify::run`], [`handling::jobs::study::run`])
//! whose report the command writes and prints.

/// `println!` that ends the process quietly when the reader of stdout has
/// gone (`handling … | head -1`), as Unix tools do, where `println!`
/// panics. The outputs are written before anything is printed.
macro_rules! say {
    ($($t:tt)*) => {
        $crate::handling_cli::say_line(format_args!($($t)*))
    };
}

mod design;
mod diagnose;
mod equilibria;
mod identify;
mod simulate;
mod study;
mod tyre_eval;

use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::ErrorKind;
use clap::{Parser, Subcommand};
use std::ffi::OsStr;
use std::marker::PhantomData;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "handling",
    version,
    about = "Vehicle handling simulator: 2-DOF model with load transfer and nonlinear tyres"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate a scenario; writes history.csv, metrics.json and response.png.
    Simulate(simulate::SimulateArgs),
    /// Steering equilibria over a sweep: PSO and exact solver, stability,
    /// bifurcations; writes equilibria.csv, bifurcations.csv, summary.json, PNGs.
    Equilibria(equilibria::EquilibriaArgs),
    /// Cornering stiffness against handling (Wang & Liang): map, RBF, inverse;
    /// writes study.csv, maps.png, rbf.json, rbf.png, inverse.json, summary.json.
    Study(study::StudyArgs),
    /// Fit a tyre model to rig data (CSV, FORMATS.md): its lateral force
    /// by PSO then Levenberg–Marquardt or modified Gauss–Newton, or the
    /// Magic Formula's Fy, Fx, Mz and combined slip stage by stage; writes
    /// a tyre file, a JSON report and a PNG.
    Identify(identify::IdentifyArgs),
    /// The sim-to-real gap of a campaign (a TOML file or a folder with
    /// vehicle.toml, runs/*.csv and optionally tyre_rig.csv): where the base
    /// model is wrong, which candidate effect explains it, how far the
    /// held-out gap shrinks; writes diagnosis.json, gap_map.png,
    /// overlays.png and report.html.
    Diagnose(diagnose::DiagnoseArgs),
    /// Virtual proving ground: writes a campaign folder measured on a truth
    /// model with the given effects on (noise, UniTire tyres; the diagnosis
    /// fits PAC89 to its rig data, or on the slow oval, which has none,
    /// identifies the axles from the runs).
    Synth(diagnose::SynthArgs),
    /// The next test to drive: for the candidates a diagnosis confounds
    /// (or those named), the manoeuvres within the runs' limits that tell
    /// them apart best, with their predicted separation in noise floors;
    /// writes design.json, scenarios/*.toml and separation.png.
    Design(design::DesignArgs),
    /// Forces and moments of a tyre file (.tir or .toml) at the points of a
    /// CSV with columns fz, kappa, alpha, camber, speed and optionally
    /// pressure (SI, rad, Pa); writes them with fx, fy, mz (and mx, my for
    /// the Magic Formula).
    TyreEval(tyre_eval::TyreEvalArgs),
    /// Step-steer metrics of a measured run (CSV, FORMATS.md).
    Metrics(simulate::MetricsArgs),
    /// The outputs of a sharded `equilibria`, `study` or `diagnose --batch`
    /// run from its shard files, byte for byte those of the unsharded run.
    Merge(equilibria::MergeArgs),
}

/// Parses the arguments, runs the command, prints errors; exit code 1 on error.
pub fn run() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Simulate(a) => simulate::simulate(a),
        Command::Equilibria(a) => equilibria::equilibria(a),
        Command::Study(a) => study::study(a),
        Command::Identify(a) => identify::identify(a),
        Command::Diagnose(a) => diagnose::diagnose(a),
        Command::Synth(a) => diagnose::synth(a),
        Command::Design(a) => design::design(a),
        Command::TyreEval(a) => tyre_eval::tyre_eval(a),
        Command::Metrics(a) => simulate::metrics(a),
        Command::Merge(a) => equilibria::merge(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // The library's errors say everything in their own message; the
            // chain would repeat the OS error of an unreadable file.
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Prints a report's lines.
fn print(lines: &[String]) {
    for l in lines {
        say!("{l}");
    }
}

/// Set once stdout's reader has gone (`handling … | head`).
static STDOUT_CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Writes one line to stdout (see `say!`). Once the reader of a pipe has
/// closed it, the rest of the summary is dropped and the job runs on: its
/// outputs are files, and exiting at the print left the run's folder lock
/// behind for the next run to take over as a killed run's.
pub(crate) fn say_line(args: std::fmt::Arguments) {
    use std::io::Write;
    use std::sync::atomic::Ordering;
    if STDOUT_CLOSED.load(Ordering::Relaxed) {
        return;
    }
    let mut out = std::io::stdout().lock();
    if let Err(e) = writeln!(out, "{args}").and_then(|()| out.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            STDOUT_CLOSED.store(true, Ordering::Relaxed);
            return;
        }
        eprintln!("error: writing to stdout: {e}");
        std::process::exit(1);
    }
}

/// A whole number of 0 or more (a seed): a negative one, which clap took
/// for an unknown flag (`unexpected argument '-1'`), or any other text is
/// refused in the words the TOML reader refuses a campaign's `seed = -1`
/// with; clap names the flag and the value before them.
fn whole_number(s: &str) -> Result<u64, String> {
    s.parse::<u64>()
        .map_err(|_| "expected a whole number of 0 or more".to_string())
}

/// A count written out (`300`): `1e3`, which clap's own parser refused
/// with "invalid digit found in string", is asked for in digits.
fn count(s: &str) -> Result<usize, String> {
    s.parse::<usize>()
        .map_err(|_| format!("expected a whole number written in digits (such as 300), not `{s}`"))
}

/// The parser of a closed set of names the library lists (the registry's
/// models, a job's choices): its values listed in the help, an unknown
/// value refused with the library's own message (`FromStr`), which names
/// the value and every known one.
#[derive(Clone, Copy)]
struct Named<T> {
    names: fn() -> Vec<&'static str>,
    parsed: PhantomData<T>,
}

/// [`Named`] for `T`, whose names `names` gives.
fn named<T>(names: fn() -> Vec<&'static str>) -> Named<T> {
    Named {
        names,
        parsed: PhantomData,
    }
}

impl<T> TypedValueParser for Named<T>
where
    T: std::str::FromStr + Clone + Send + Sync + 'static,
    T::Err: std::fmt::Display,
{
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        _: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<T, clap::Error> {
        let fail =
            |message: String| clap::Error::raw(ErrorKind::InvalidValue, message).with_cmd(cmd);
        let text = value
            .to_str()
            .ok_or_else(|| fail(format!("{value:?} is not UTF-8\n")))?;
        text.parse().map_err(|e| fail(format!("{e}\n")))
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new((self.names)().into_iter().map(PossibleValue::new)))
    }
}
