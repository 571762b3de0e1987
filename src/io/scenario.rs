//! Scenario files: a vehicle, its tyres, the road, model options, a
//! manoeuvre, integration and metric settings (the book's `docs/src/formats.md`, "The project's own files").
//!
//! Tyre and run paths are relative to the scenario file. Units: SI, rad;
//! speeds in m/s.

use super::fitted_ranges::FittedRanges;
use super::limits::{frequency, road_wheel_steer, run_start, speed};
use super::paths::beside;
pub use super::schedule::ScheduleSpec;
use super::tables::{check_vehicle, resolve_model, ResolvedModel};
pub use super::tables::{load_tyre, Road, TyreRefs};
use super::toml_file::{param_error, TomlSource};
use super::MeasuredRun;
use crate::error::{InputError, InputProblem, Limit, ParamError, ParamReason, ScenarioProblem};
use crate::manoeuvre::{Manoeuvre, RampSteer, Replay, SineSteer, StepSteer, SweepSteer};
use crate::metrics::MetricSettings;
use crate::metrics::MIN_STEP;
use crate::sim::{Integrator, Method, MethodName, Tolerances};
use crate::vehicle::{ModelOptions, State, Vehicle, VehicleModel};
use reach::{ramp_reach, steers};
pub use replay::ReplaySpec;
use serde::Deserialize;
use std::path::{Path, PathBuf};
pub use step_steer::StepSteerSpec;
use step_steer::{steady_ay, Amplitude};

/// Integration settings (`[simulation]`, or `[integrator]`): the method,
/// the interval of the recorded rows, and Dormand–Prince's tolerances.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimulationSettings {
    /// `dopri5` (default: error-controlled, events located on the dense
    /// output), `dop853` (the same by the eighth-order pair) or `rk4`
    /// (fixed step).
    #[serde(default)]
    pub method: MethodName,
    /// Interval of the recorded rows, s, and RK4's step.
    #[serde(default = "default_step")]
    pub step: f64,
    /// Dormand–Prince relative tolerance (default [`Tolerances::default`]).
    #[serde(default)]
    pub rtol: Option<f64>,
    /// Dormand–Prince absolute tolerance, rad and rad/s.
    #[serde(default)]
    pub atol: Option<f64>,
    /// Dormand–Prince's largest step, s.
    #[serde(default)]
    pub max_step: Option<f64>,
}

pub use kmh::{KmhSpeed, KmhStatedBy};
pub use rows::MAX_ROWS;

fn default_step() -> f64 {
    Integrator::default().step
}

impl Default for SimulationSettings {
    fn default() -> Self {
        Self {
            method: MethodName::default(),
            step: default_step(),
            rtol: None,
            atol: None,
            max_step: None,
        }
    }
}

impl SimulationSettings {
    /// The validated method.
    pub fn method(&self) -> Result<Method, ParamError> {
        ParamError::in_range("step", self.step, 0.0, 0.05, Limit::OutputStep)?;
        let d = Tolerances::default();
        match self.method {
            MethodName::Rk4 => {
                for (key, v) in [
                    ("rtol", self.rtol),
                    ("atol", self.atol),
                    ("max_step", self.max_step),
                ] {
                    if let Some(v) = v {
                        return Err(ParamError::new(key, v, ParamReason::ToleranceWithRk4));
                    }
                }
                Ok(Method::Rk4)
            }
            MethodName::Dopri5 | MethodName::Dop853 => {
                let tol = Tolerances {
                    rtol: self.rtol.unwrap_or(d.rtol),
                    atol: self.atol.unwrap_or(d.atol),
                    max_step: self.max_step.unwrap_or(d.max_step),
                };
                ParamError::in_range("rtol", tol.rtol, 1e-14, 1e-2, Limit::RelativeTolerance)?;
                ParamError::in_range("atol", tol.atol, 1e-16, 1e-2, Limit::AbsoluteTolerance)?;
                ParamError::in_range("max_step", tol.max_step, 1e-6, 1.0, Limit::MaxStep)?;
                Ok(match self.method {
                    MethodName::Dop853 => Method::Dop853(tol),
                    _ => Method::Dopri5(tol),
                })
            }
        }
    }
}

/// A manoeuvre as written in a file; `kind` selects it.
#[derive(Debug, Clone, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum ManoeuvreSpec {
    /// GB/T 6323 / ISO 7401 step steer.
    #[serde(alias = "step_steer")]
    StepSteer(StepSteerSpec),
    /// Ramp steer.
    #[serde(alias = "ramp_steer")]
    RampSteer(RampSteer),
    /// Sine steer.
    Sine(SineSteer),
    /// Linear frequency sweep.
    Sweep(SweepSteer),
    /// Replay of a measured run.
    Replay(ReplaySpec),
    /// Steer and speed at breakpoints, linear between them (a manoeuvre
    /// `handling design` writes: a turn with a speed change, a lane
    /// change, a constant radius at rising speed).
    Schedule(ScheduleSpec),
}

/// A scenario file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioFile {
    /// Short name used in reports.
    #[serde(default)]
    pub name: Option<String>,
    /// Free text.
    #[serde(default)]
    pub description: Option<String>,
    /// The `[vehicle]` table of `FORMATS.md`.
    pub vehicle: Vehicle,
    /// Tyre files.
    pub tyres: TyreRefs,
    /// Road.
    #[serde(default)]
    pub road: Road,
    /// Model options.
    #[serde(default)]
    pub model: ModelOptions,
    /// The manoeuvre.
    pub manoeuvre: ManoeuvreSpec,
    /// Integration (`[simulation]`; `[integrator]` is the same table).
    #[serde(default, alias = "integrator")]
    pub simulation: SimulationSettings,
    /// Metric settings.
    #[serde(default)]
    pub metrics: MetricSettings,
}

/// A loaded, validated scenario ready to run.
#[derive(Debug, Clone)]
pub struct Scenario {
    /// Name (file stem when the file has none).
    pub name: String,
    /// The vehicle model.
    pub model: VehicleModel,
    /// The manoeuvre, amplitudes resolved.
    pub manoeuvre: Manoeuvre,
    /// Integration settings with the road friction.
    pub integrator: Integrator,
    /// Metric settings.
    pub metrics: MetricSettings,
    /// Initial state.
    pub initial: State,
    /// The measured run a replay came from.
    pub measured: Option<MeasuredRun>,
    /// Every file read (the CLI never writes over one of them).
    pub inputs: Vec<PathBuf>,
    /// What cleaning the replayed run found and excluded.
    pub cleaning: Option<crate::measured::clean::CleaningReport>,
    /// The ranges the front and rear tyres were fitted to, where their
    /// files state them (`[fitted_ranges]`).
    pub fitted_ranges: [Option<FittedRanges>; 2],
    /// The steady lateral acceleration a step steer was sized for
    /// (`lateral_acceleration`), m/s²: its change from straight running,
    /// as the metrics' steady ay (on a bank the accelerometer reads
    /// g·sin θ more); None for any other amplitude.
    pub asked_ay: Option<f64>,
    /// `[vehicle]` keys the tool does not read, set aside.
    pub unread: Vec<crate::io::toml_file::vehicle_keys::UnreadKey>,
    /// What reading the scenario found to say: a replayed run's bank
    /// applied, a table the manoeuvre does not read.
    pub remarks: Vec<crate::error::ScenarioRemark>,
    /// A stated speed that reads as km/h written as m/s ([`kmh`]).
    pub kmh_speed: Option<KmhSpeed>,
}

/// The checks every timed manoeuvre shares: a speed on a road and an end
/// after the start.
fn timing(v: f64, start: f64, end: f64) -> Result<(), ParamError> {
    speed(v)?;
    run_start(start)?;
    ParamError::in_range(
        "end",
        end,
        start,
        crate::constants::LONGEST_RUN,
        Limit::EndAfterStart,
    )
}

fn check(src: &TomlSource, r: Result<(), ParamError>) -> Result<(), InputError> {
    r.map_err(|e| param_error(src, Some("manoeuvre"), e))
}

/// Reads, validates and resolves a scenario file.
/// A file of another kind (a CSV, a `.tir`, a tyre file, a report, a
/// binary file) is refused as what it is ([`layout::other_kind`]).
pub fn load_scenario(path: &Path) -> Result<Scenario, InputError> {
    let read = TomlSource::read(path).and_then(|src| {
        layout::check(&src)?;
        let f: ScenarioFile = src.parse()?;
        Ok((f, src))
    });
    let (f, src) = read.map_err(|e| match e {
        // A folder is named as one (a campaign's, which `diagnose`
        // reads), not as the OS's "Is a directory".
        InputError::Io { .. } if !path.is_dir() => e,
        e => layout::other_kind(path).unwrap_or(e),
    })?;
    resolve_scenario(&f, &src)
}

/// Reads and validates the `[vehicle]` table of TOML text (a scenario's,
/// a campaign's `vehicle.toml`, or a document of that table alone), checked
/// as a scenario file's is; other tables are ignored. `path` names the text
/// in errors (line, column, key and value as for a file).
pub fn vehicle_from_text(path: &Path, text: &str) -> Result<Vehicle, InputError> {
    #[derive(Deserialize)]
    struct VehicleTable {
        vehicle: Vehicle,
    }
    let src = TomlSource {
        path: path.to_path_buf(),
        text: text.to_string(),
    };
    let t: VehicleTable = src.parse()?;
    check_vehicle(&src, &t.vehicle)?;
    Ok(t.vehicle)
}

/// Validates and resolves a parsed scenario whose text is `src` (other file
/// kinds that embed a scenario's tables use it too).
pub(crate) fn resolve_scenario(f: &ScenarioFile, src: &TomlSource) -> Result<Scenario, InputError> {
    let path = src.path.as_path();
    let ResolvedModel {
        model,
        files: tyre_files,
        fitted_ranges,
    } = resolve_model(src, &f.vehicle, &f.tyres, f.model)?;
    no_grip::lateral_force_made(src, &model, &f.tyres)?;
    no_grip::road(src, &f.road)?;
    f.metrics
        .validate()
        .map_err(|e| param_error(src, Some("metrics"), e))?;
    let method = f
        .simulation
        .method()
        .map_err(|e| param_error(src, Some(rows::integration_table(src)), e))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut inputs = vec![path.to_path_buf()];
    inputs.extend(tyre_files);
    let integrator = Integrator {
        step: f.simulation.step,
        friction: f.road.friction,
        method,
    };
    let mut remarks = Vec::new();
    let Resolved {
        manoeuvre,
        initial,
        measured,
        cleaning,
        asked_ay,
    } = match &f.manoeuvre {
        ManoeuvreSpec::StepSteer(s) => step_steer(src, s, &model, f.road.friction)?,
        ManoeuvreSpec::Replay(r) => {
            let run_path = beside(dir, &r.run);
            let r = replay::resolve(src, r, &run_path, model.vehicle.wheelbase())?;
            inputs.push(run_path);
            remarks.extend(remarks::bank_remark(src, &r.run));
            remarks.extend(remarks::ax_remark(&r.run));
            Resolved {
                manoeuvre: Manoeuvre::Replay(r.replay),
                initial: r.initial,
                measured: Some(r.run),
                cleaning: Some(r.cleaning),
                asked_ay: None,
            }
        }
        spec => Resolved::from(other_manoeuvre(src, spec, f.simulation.step)?),
    };
    check_windows(src, &f.metrics, &manoeuvre)?;
    let said = remarks::of_manoeuvre(src, &f.manoeuvre, &manoeuvre, measured.is_some());
    remarks.extend(said);
    rows::check(src, &f.simulation, &manoeuvre, measured.as_ref())?;
    stability::check(
        src,
        &f.simulation,
        method,
        &model,
        f.road.friction,
        &manoeuvre,
    )?;
    Ok(Scenario {
        // Read before the manoeuvre moves into the scenario.
        kmh_speed: kmh::kmh_speed(src, &manoeuvre, measured.is_some()),
        name: scenario_name(f, src)?,
        model,
        manoeuvre,
        integrator,
        metrics: f.metrics,
        initial,
        measured,
        inputs,
        cleaning,
        fitted_ranges,
        asked_ay,
        unread: src.unread_vehicle_keys(),
        remarks,
    })
}

/// The scenario's name, which names its output folder: its `name`,
/// refused at the key where it is no folder name, else the file's stem.
fn scenario_name(f: &ScenarioFile, src: &TomlSource) -> Result<String, InputError> {
    if let Some(name) = f.name.as_deref().filter(|n| !is_folder_name(n)) {
        let problem = ScenarioProblem::NameNotAFolder { name: name.into() };
        let span = src.key_span("name");
        return Err(src.located(span, InputProblem::Scenario(Box::new(problem))));
    }
    Ok(f.name.clone().unwrap_or_else(|| {
        src.path
            .file_stem()
            .map_or("scenario".into(), |s| s.to_string_lossy().into_owned())
    }))
}

/// A resolved manoeuvre, the state it starts from and, for a replay, the
/// measured run and its cleaning.
struct Resolved {
    manoeuvre: Manoeuvre,
    initial: State,
    measured: Option<MeasuredRun>,
    cleaning: Option<crate::measured::clean::CleaningReport>,
    asked_ay: Option<f64>,
}

impl From<Manoeuvre> for Resolved {
    fn from(manoeuvre: Manoeuvre) -> Self {
        Self {
            manoeuvre,
            initial: State::default(),
            measured: None,
            cleaning: None,
            asked_ay: None,
        }
    }
}

/// A step steer: timing checked (ISO 7401's rise time), the amplitude
/// from `steer` or from the steady `lateral_acceleration` it must reach, the
/// start at straight running (the steer and sideslip that give zero yaw
/// rate, non-zero only for tyres with offsets or on a banked road).
fn step_steer(
    src: &TomlSource,
    s: &StepSteerSpec,
    model: &VehicleModel,
    friction: f64,
) -> Result<Resolved, InputError> {
    check(src, s.timing())?;
    // The steady state at the tyres' ay `ay`, refused at the key's `asked`.
    let solve = |asked: f64, ay: f64| {
        model
            .steady_state_for_lateral_acceleration(s.speed, friction, ay)
            .map_err(|m| {
                param_error(
                    src,
                    Some("manoeuvre"),
                    ParamError::new(
                        "lateral_acceleration",
                        asked,
                        ParamReason::NoSteadyState(Box::new(m)),
                    ),
                )
            })
    };
    // Straight running: zero yaw rate, the tyres holding the bank's pull.
    let bank = model.bank_acceleration();
    let trim = solve(bank, bank)?;
    // A step steer needs a step the metrics can measure, and one a road
    // wheel can make: refused at the key that asks for it.
    let step = |key: &str, v: f64, d: f64| {
        if d.abs() < MIN_STEP {
            return Err(ParamError::new(
                key,
                v,
                ParamReason::NoSteerStep { min: MIN_STEP },
            ));
        }
        road_wheel_steer(key, d + trim.steer).map_err(|e| ParamError::new(key, v, e.reason))
    };
    let (amplitude, asked_ay) = match s.amplitude(src)? {
        Amplitude::Steer(d) => {
            check(src, ParamError::finite("steer", d))?;
            check(src, step("steer", d, d))?;
            (d, None)
        }
        Amplitude::LateralAcceleration(ay) => {
            check(src, steady_ay(ay, model))?;
            // The change from straight running, as the metrics' steady ay
            // reads it: on a bank the tyres already hold g·sin θ there (a
            // step sized to reach `ay` in all settled g·sin θ short of it).
            let d = solve(ay, bank + ay)?.steer - trim.steer;
            check(src, step("lateral_acceleration", ay, d))?;
            (d, Some(ay))
        }
    };
    Ok(Resolved {
        asked_ay,
        initial: State {
            beta: trim.beta,
            yaw_rate: trim.yaw_rate,
        },
        ..Resolved::from(Manoeuvre::StepSteer(StepSteer {
            speed: s.speed,
            amplitude,
            trim: trim.steer,
            start: s.start,
            rise_time: s.rise_time,
            end: s.end,
        }))
    })
}

/// A step steer's `[metrics]` windows against its record, refused at the
/// longer window's key, and its start against the initial window, refused
/// at `start`: found when the scenario is read, not after the run.
fn check_windows(src: &TomlSource, s: &MetricSettings, m: &Manoeuvre) -> Result<(), InputError> {
    let Manoeuvre::StepSteer(step) = m else {
        return Ok(());
    };
    // The initial values are the straight running before the step
    // (`metrics` on the history refuses a record that starts at its step).
    if step.start < s.pre_window {
        let reason = ParamReason::StepInInitialWindow {
            pre_window: s.pre_window,
        };
        let e = ParamError::new("start", step.start, reason);
        return Err(param_error(src, Some("manoeuvre"), e));
    }
    if s.pre_window + s.steady_window >= step.end {
        return Err(windows_beyond_record(src, s, step.end));
    }
    // The steady values are the held step: a window reaching back over the
    // steer's ramp reads a smaller step and hides the overshoot (the
    // measured-run check, `MetricsError::StepInSteadyWindow`, mirrored).
    let settles = step.start + step.rise_time.max(0.0);
    // (1e-9 s: a window given to the digit where the steer settles, 6 −
    // 4.9 s, is not refused for the rounding of its difference.)
    if step.end - s.steady_window < settles - 1e-9 {
        let reason = ParamReason::StepInSteadyWindow {
            settles,
            end: step.end,
        };
        let e = ParamError::new("steady_window", s.steady_window, reason);
        return Err(param_error(src, Some("metrics"), e));
    }
    Ok(())
}

/// [`ParamReason::WindowsBeyondRecord`] at the longer window's key.
fn windows_beyond_record(src: &TomlSource, s: &MetricSettings, end: f64) -> InputError {
    let reason = ParamReason::WindowsBeyondRecord {
        pre_window: s.pre_window,
        steady_window: s.steady_window,
        end,
    };
    let e = match s.pre_window > s.steady_window {
        true => ParamError::new("pre_window", s.pre_window, reason),
        false => ParamError::new("steady_window", s.steady_window, reason),
    };
    param_error(src, Some("metrics"), e)
}

/// A steer of frequency `frequency` (the key `key`) the rows every `step`
/// s resolve: sampled more than twice a period (Nyquist; at exactly twice
/// the rows can fall on its zero crossings and write a sine as zeros).
fn resolved(key: &str, frequency: f64, step: f64) -> Result<(), ParamError> {
    if 2.0 * frequency * step < 1.0 {
        return Ok(());
    }
    Err(ParamError::new(
        key,
        frequency,
        ParamReason::Aliased { step, frequency },
    ))
}

/// Ramp, sine and sweep steers: their timing and rates checked, and the
/// frequencies the rows every `step` s resolve.
fn other_manoeuvre(
    src: &TomlSource,
    spec: &ManoeuvreSpec,
    step: f64,
) -> Result<Manoeuvre, InputError> {
    Ok(match spec {
        ManoeuvreSpec::RampSteer(r) => {
            check(src, timing(r.speed, r.start, r.end))?;
            check(src, ParamError::finite("rate", r.rate))?;
            check(src, ramp_reach(r))?;
            check(src, steers("rate", r.rate, r.rate * (r.end - r.start)))?;
            Manoeuvre::RampSteer(*r)
        }
        ManoeuvreSpec::Sine(s) => {
            check(src, timing(s.speed, s.start, s.end))?;
            check(src, ParamError::positive("frequency", s.frequency))?;
            check(src, frequency("frequency", s.frequency, 0.0))?;
            check(src, resolved("frequency", s.frequency, step))?;
            check(src, road_wheel_steer("amplitude", s.amplitude))?;
            check(src, steers("amplitude", s.amplitude, s.amplitude))?;
            check(src, reach::sine_reach(s))?;
            Manoeuvre::Sine(*s)
        }
        ManoeuvreSpec::Sweep(s) => {
            check(src, timing(s.speed, s.start, s.end))?;
            check(src, road_wheel_steer("amplitude", s.amplitude))?;
            check(src, steers("amplitude", s.amplitude, s.amplitude))?;
            check(src, ParamError::non_negative("f_start", s.f_start))?;
            // A guard below 0, as for the rise time: f_start = 0 is allowed
            // and the range reads [0, 50].
            check(src, frequency("f_start", s.f_start, -1e-12))?;
            check(src, ParamError::positive("f_end", s.f_end))?;
            check(src, frequency("f_end", s.f_end, 0.0))?;
            // The sweep's highest frequency, at the key that holds it.
            let (key, highest) = if s.f_start > s.f_end {
                ("f_start", s.f_start)
            } else {
                ("f_end", s.f_end)
            };
            check(src, resolved(key, highest, step))?;
            check(src, reach::sweep_reach(s, key))?;
            Manoeuvre::Sweep(*s)
        }
        ManoeuvreSpec::Schedule(s) => {
            check(src, super::schedule::check(s))?;
            Manoeuvre::Replay(Replay::of_inputs(
                s.t.clone(),
                s.steer.clone(),
                s.speed.clone(),
            ))
        }
        ManoeuvreSpec::StepSteer(_) | ManoeuvreSpec::Replay(_) => {
            unreachable!("resolved by their own functions")
        }
    })
}

/// A name `out/<name>` keeps inside `out/`: one path component.
fn is_folder_name(name: &str) -> bool {
    !(name.trim().is_empty() || name.contains(['/', '\\']) || name == "." || name == "..")
}

pub(crate) mod kmh;
pub(crate) mod layout;
mod no_grip;
mod reach;
mod remarks;
mod replay;
mod rows;
mod stability;
mod step_steer;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scenario_without_a_simulation_table_integrates_as_the_default_integrator() {
        let d = Integrator::default();
        assert_eq!(d.method, Method::Dopri5(Tolerances::default()));
        let parsed: SimulationSettings = toml::from_str("").unwrap();
        for s in [parsed, SimulationSettings::default()] {
            assert_eq!(s.method().unwrap(), d.method);
            assert_eq!(s.step, d.step);
        }
    }
}
