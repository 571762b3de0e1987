//! Equilibrium sweep files (the book's `docs/src/formats.md`, "The project's own files"): a vehicle, its tyres,
//! model options, the swept steer / friction / speed values, the search box,
//! PSO settings and report options. Values are SI unless a `unit` says
//! otherwise (`deg`, `km/h`), converted on reading; a speed axis without a
//! unit whose fastest value reads as km/h is noted (`speed_kmh`).

use super::axis_order::{disorder, range_value, Disorder};
use super::file_kind::not_this_toml;
use super::limits::{road_wheel_steer, road_wheel_steer_degrees, MAX_SPEED};
use super::tables::{resolve_model, ResolvedModel, TyreRefs, MAX_ROAD_FRICTION};
use super::toml_file::{line_col, param_error, TomlSource};
use crate::constants::G;
use crate::equilibria::pso::PsoSearch;
use crate::equilibria::sweep::Grid;
use crate::equilibria::{Condition, SearchBox};
use crate::error::{FileKind, SwarmCount, SweepLimit, Wanted};
use crate::error::{InputError, Limit, Location, ParamError, ParamReason};
use crate::error::{MAX_BOX_SIDESLIP, MAX_BOX_YAW_RATES};
use crate::tyre::TyreModel;
use crate::vehicle::{ModelOptions, Vehicle, VehicleModel, MIN_SPEED};
use serde::Deserialize;
use std::path::{Path, PathBuf};

mod speed_kmh;

/// A range `from..=to` by `step`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RangeSpec {
    from: f64,
    to: f64,
    step: f64,
    #[serde(default)]
    unit: Option<String>,
}

/// A list with a unit.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ListSpec {
    values: Vec<f64>,
    #[serde(default)]
    unit: Option<String>,
}

/// Swept values: a number, a list, `{from, to, step, unit}` or `{values, unit}`.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum Values {
    /// One value.
    One(f64),
    /// A list.
    List(Vec<f64>),
    /// A range.
    Range(RangeSpec),
    /// A list with a unit.
    Units(ListSpec),
}

/// The three swept inputs.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepAxes {
    /// Steer (rad, or `unit = "deg"`).
    pub steer: Values,
    /// Friction scale.
    pub friction: Values,
    /// Speed (m/s, or `unit = "km/h"`).
    pub speed: Values,
}

/// One value of a phase portrait's condition: a number (SI) or
/// `{ value, unit }` in the units the sweep's axes take (`deg`, `km/h`).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum PortraitValue {
    /// SI.
    Si(f64),
    /// With a unit.
    Unit {
        /// The value in `unit`.
        value: f64,
        /// `rad`/`deg` (steer), `m/s`/`km/h` (speed).
        unit: String,
    },
}

/// A condition for a phase portrait.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PortraitSpec {
    /// Steer, rad (or `{ value, unit = "deg" }`).
    pub steer: PortraitValue,
    /// Friction scale.
    pub friction: PortraitValue,
    /// Speed, m/s (or `{ value, unit = "km/h" }`).
    pub speed: PortraitValue,
}

/// Report options.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReportSpec {
    /// Locate bifurcations along every swept axis.
    #[serde(default = "yes")]
    pub bifurcations: bool,
    /// Write PNG figures.
    #[serde(default = "yes")]
    pub plots: bool,
    /// Conditions for phase portraits (default: first and last sweep point).
    #[serde(default)]
    pub phase_portraits: Vec<PortraitSpec>,
}

fn yes() -> bool {
    true
}

impl Default for ReportSpec {
    fn default() -> Self {
        Self {
            bifurcations: true,
            plots: true,
            phase_portraits: Vec::new(),
        }
    }
}

/// A sweep file's `[box]`: either key may be left to its default.
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxSpec {
    /// |β| limit, rad (default 0.6).
    #[serde(default)]
    pub beta_max: Option<f64>,
    /// |r| limit, rad/s (default 1.2·μ_peak·μ·g/u_min).
    #[serde(default)]
    pub yaw_rate_max: Option<f64>,
}

/// A sweep file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    /// Name used for the output folder.
    #[serde(default)]
    pub name: Option<String>,
    /// Free text.
    #[serde(default)]
    pub description: Option<String>,
    /// The vehicle.
    pub vehicle: Vehicle,
    /// Tyre files.
    pub tyres: TyreRefs,
    /// Model options.
    #[serde(default)]
    pub model: ModelOptions,
    /// Swept values.
    pub sweep: SweepAxes,
    /// Search box (default: |β| ≤ 0.6 rad, |r| ≤ 1.2·μ_peak·μ·g/u_min).
    #[serde(default, rename = "box")]
    pub search_box: Option<BoxSpec>,
    /// PSO search settings.
    #[serde(default)]
    pub pso: PsoSearch,
    /// Report options.
    #[serde(default)]
    pub report: ReportSpec,
}

/// A loaded sweep.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Name.
    pub name: String,
    /// The model.
    pub model: VehicleModel,
    /// The grid, SI.
    pub grid: Grid,
    /// The box.
    pub search_box: SearchBox,
    /// PSO settings.
    pub pso: PsoSearch,
    /// Report options.
    pub report: ReportSpec,
    /// Phase portrait conditions.
    pub portraits: Vec<Condition>,
    /// Files read.
    pub inputs: Vec<PathBuf>,
    /// What the terminal says of the file before the results (a phase
    /// portrait away from the swept conditions).
    pub notes: Vec<String>,
}

/// The factor to SI of `unit` on `axis`, refused at `{key}.unit` where
/// the axis does not take it.
fn unit_scale(
    src: &TomlSource,
    key: &str,
    axis: &str,
    unit: Option<&str>,
) -> Result<f64, InputError> {
    Ok(match (axis, unit) {
        (_, None) => 1.0,
        ("steer", Some("rad")) | ("speed", Some("m/s")) => 1.0,
        ("steer", Some("deg")) => std::f64::consts::PI / 180.0,
        ("speed", Some("km/h")) => 1.0 / 3.6,
        // At the `unit` key, quoting the text (a unit is no number:
        // `= NaN` quoted none the user wrote).
        (_, Some(u)) => {
            let why = ParamReason::UnknownSweepUnit {
                unit: u.to_string(),
            };
            let e = ParamError::without_value(&format!("{key}.unit"), why);
            return Err(param_error(src, None, e));
        }
    })
}

fn expand(v: &Values, axis: &str, src: &TomlSource) -> Result<Vec<f64>, InputError> {
    let key = format!("sweep.{axis}");
    let err =
        |value: f64, why: ParamReason| param_error(src, None, ParamError::new(&key, value, why));
    let scale = |unit: &Option<String>| unit_scale(src, &key, axis, unit.as_deref());
    // The values as the file gives them, and the factor to SI.
    let (given, k) = match v {
        Values::One(x) => (vec![*x], 1.0),
        Values::List(l) => (l.clone(), 1.0),
        Values::Units(l) => (l.values.clone(), scale(&l.unit)?),
        Values::Range(r) => {
            let k = scale(&r.unit)?;
            // Each at its own key, with its own value.
            let at = |field: &str, value: f64, why: ParamReason| {
                let e = ParamError::new(&format!("{key}.{field}"), value, why);
                param_error(src, None, e)
            };
            if r.step.is_nan() || r.step <= 0.0 {
                return Err(at("step", r.step, ParamReason::RangeStepNotPositive));
            }
            if r.to.is_nan() || r.to < r.from {
                let why = ParamReason::RangeEndBeforeStart { from: r.from };
                return Err(at("to", r.to, why));
            }
            let n = ((r.to - r.from) / r.step + 1e-9).floor() as usize;
            if n > 1_000_000 {
                return Err(err(r.step, ParamReason::TooManyValues));
            }
            ((0..=n).map(|i| range_value(r.from, r.step, i)).collect(), k)
        }
    };
    if given.is_empty() {
        let at = match v {
            Values::Units(_) => format!("{key}.values"),
            _ => key.clone(),
        };
        let e = ParamError::without_value(&at, ParamReason::NoValues);
        return Err(param_error(src, None, e));
    }
    // One rule for every sweep axis (`super::axis_order`): the sweep is
    // traced from each value to the next, so an unsorted speed list
    // reported its critical speed three times, stability reversed, and a
    // repeated value solved its conditions twice.
    if let Some(d) = disorder(&given) {
        let (i, why) = match d {
            Disorder::Repeated { at } => (at, ParamReason::RepeatedSweepValue),
            Disorder::Descending { at, before } => (at, ParamReason::AxisOutOfOrder { before }),
        };
        let at = match v {
            Values::Units(_) => format!("{key}.values[{i}]"),
            _ => format!("{key}[{i}]"),
        };
        return Err(param_error(src, None, ParamError::new(&at, given[i], why)));
    }
    // A range is checked at the ends the file writes, each at its own
    // key: its first value out of bounds named a value the file does not
    // hold ("`sweep.steer` = 1" for `{ from = 0, to = 10, step = 1 }`).
    let written: Vec<(String, f64)> = match v {
        Values::Range(r) => vec![(format!("{key}.from"), r.from), (format!("{key}.to"), r.to)],
        _ => given.iter().map(|&x| (key.clone(), x)).collect(),
    };
    for (at, x) in written {
        axis_value(axis, &at, x, k).map_err(|e| param_error(src, None, e))?;
    }
    Ok(given.into_iter().map(|x| x * k).collect())
}

/// A swept value `x` of `axis` at the file's key `at`, in the unit whose
/// factor to SI is `k`, checked. The steer keeps to the road-wheel limit
/// every manoeuvre keeps to (`simulate`'s), with its words, said in the
/// unit the file gives it in; the speed keeps to a manoeuvre's range, in
/// the unit given; the friction to a road's (`[road] friction`'s). A
/// speed or friction at or below zero is said as such, not as a value
/// beyond the top of its range.
fn axis_value(axis: &str, at: &str, x: f64, k: f64) -> Result<(), ParamError> {
    match axis {
        "speed" | "friction" if x <= 0.0 => ParamError::positive(at, x),
        "steer" if k != 1.0 => road_wheel_steer_degrees(at, x),
        "steer" => road_wheel_steer(at, x),
        "speed" => {
            let (lo, hi) = (MIN_SPEED / k, MAX_SPEED / k);
            ParamError::in_range(at, x, lo, hi, Limit::ManoeuvreSpeed)
        }
        _ => ParamError::in_range(at, x, 0.0, MAX_ROAD_FRICTION, Limit::RoadFriction),
    }
}

/// The conditions of the `[report] phase_portraits` entries, each value
/// in SI or with a unit the sweep's axis takes, checked as a sweep's is,
/// at its own key: a portrait at a negative speed or at 30 rad of steer
/// was drawn.
fn portrait_conditions(
    src: &TomlSource,
    specs: &[PortraitSpec],
) -> Result<Vec<Condition>, InputError> {
    specs
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let key = |name: &str| format!("report.phase_portraits[{i}].{name}");
            let si = |axis: &str, v: &PortraitValue| match v {
                PortraitValue::Si(x) => Ok(*x),
                PortraitValue::Unit { value, unit } => {
                    Ok(value * unit_scale(src, &key(axis), axis, Some(unit))?)
                }
            };
            let (steer, friction, speed) = (
                si("steer", &p.steer)?,
                si("friction", &p.friction)?,
                si("speed", &p.speed)?,
            );
            let (speed_key, friction_key) = (&key("speed"), &key("friction"));
            let checked = road_wheel_steer(&key("steer"), steer)
                .and_then(|()| match speed {
                    x if x <= 0.0 => ParamError::positive(speed_key, x),
                    x => ParamError::in_range(
                        speed_key,
                        x,
                        MIN_SPEED,
                        MAX_SPEED,
                        Limit::ManoeuvreSpeed,
                    ),
                })
                .and_then(|()| match friction {
                    x if x <= 0.0 => ParamError::positive(friction_key, x),
                    x => ParamError::in_range(
                        friction_key,
                        x,
                        0.0,
                        MAX_ROAD_FRICTION,
                        Limit::RoadFriction,
                    ),
                });
            checked.map_err(|e| param_error(src, None, e))?;
            Ok(Condition {
                steer,
                friction,
                speed,
            })
        })
        .collect()
}

/// A note for each portrait away from the swept conditions (drawn there
/// all the same), with the unit slip it may be: a speed of 70 given for
/// 70 km/h was drawn at 252 km/h without a word.
fn portrait_notes(grid: &Grid, portraits: &[Condition]) -> Vec<String> {
    // To six significant digits: a portrait at 19.4444 m/s is at a sweep's
    // 70 km/h (19.44444… m/s), as the bundled scenarios write it.
    let swept = |v: f64, on: &[f64]| {
        on.iter()
            .any(|&x| (x - v).abs() <= 5e-6 * x.abs().max(1e-9))
    };
    // Six significant digits, trailing zeros dropped: 70 m/s = 252 km/h.
    let g = |v: f64| {
        let s = crate::format::significant(v, 6);
        match s.contains('.') {
            true => s.trim_end_matches('0').trim_end_matches('.').to_string(),
            false => s,
        }
    };
    portraits
        .iter()
        .enumerate()
        .filter_map(|(i, c)| {
            let mut off = Vec::new();
            if !swept(c.steer, &grid.steer) {
                let hint = match swept(c.steer.to_radians(), &grid.steer) {
                    true => format!(
                        " = {}° — deg meant? (write `steer = {{ value = {}, unit = \"deg\" }}`)",
                        g(c.steer.to_degrees()),
                        g(c.steer)
                    ),
                    false => String::new(),
                };
                off.push(format!("steer {} rad{hint}", g(c.steer)));
            }
            if !swept(c.friction, &grid.friction) {
                off.push(format!("friction {}", g(c.friction)));
            }
            if !swept(c.speed, &grid.speed) {
                let hint = match swept(c.speed / 3.6, &grid.speed) {
                    true => format!(
                        " = {} km/h — km/h meant? (write `speed = {{ value = {}, unit = \"km/h\" }}`)",
                        g(c.speed * 3.6),
                        g(c.speed)
                    ),
                    false => String::new(),
                };
                off.push(format!("speed {} m/s{hint}", g(c.speed)));
            }
            (!off.is_empty()).then(|| {
                format!(
                    "phase portrait {i} is not at a swept condition: {}; drawn there all the same",
                    off.join(", ")
                )
            })
        })
        .collect()
}

/// Refuses effects the equilibrium analysis does not model: its residual
/// ([`VehicleModel::equilibrium_residual`]) has the papers' model with aero
/// load and bank; the effects it leaves out are the model's to name
/// ([`crate::vehicle::Effects::beyond_equilibrium_residual`]).
fn equilibrium_effects(src: &TomlSource, e: &crate::vehicle::Effects) -> Result<(), InputError> {
    match e.beyond_equilibrium_residual().first() {
        Some(key) => Err(param_error(
            src,
            Some("model.effects"),
            ParamError::without_value(key, ParamReason::NotInEquilibrium),
        )),
        None => Ok(()),
    }
}

/// A key of the sweep beyond its range, refused at its line.
fn beyond(src: &TomlSource, key: &str, value: f64, why: SweepLimit) -> InputError {
    InputError::Sweep {
        path: src.path.clone(),
        at: src.key_span(key).map(|s| {
            let (line, column) = line_col(&src.text, s.start);
            Location { line, column }
        }),
        key: key.into(),
        value,
        why,
    }
}

/// Refuses a `[pso]` count below what the swarm needs, at its key: the
/// optimiser itself would run 0 particles as 2 and 0 iterations as its
/// random first positions, without a word.
fn swarm_counts(src: &TomlSource, pso: &PsoSearch) -> Result<(), InputError> {
    let counts = [
        ("pso.particles", pso.particles, SwarmCount::Particles),
        ("pso.iterations", pso.iterations, SwarmCount::Iterations),
        ("pso.rounds", pso.rounds, SwarmCount::Rounds),
    ];
    match counts.into_iter().find(|(_, n, c)| *n < c.least()) {
        Some((key, n, count)) => Err(beyond(src, key, n as f64, SweepLimit::SwarmCount { count })),
        None => Ok(()),
    }
}

/// The search box: each key as the file gives it (checked), else its
/// default (|β| ≤ 0.6 rad, |r| ≤ 1.2·μ_peak·μ·g/u_min).
fn search_box(
    src: &TomlSource,
    model: &VehicleModel,
    grid: &Grid,
    b: BoxSpec,
) -> Result<SearchBox, InputError> {
    let beyond = |key: &str, value: f64, why: SweepLimit| beyond(src, key, value, why);
    if let Some(beta) = b.beta_max {
        ParamError::positive("beta_max", beta).map_err(|e| param_error(src, Some("box"), e))?;
        if beta > MAX_BOX_SIDESLIP {
            let why = SweepLimit::Sideslip { given: beta };
            return Err(beyond("box.beta_max", beta, why));
        }
    }
    // Steady, m·u·r is the tyres' lateral force: at most μ_peak·μ·m·g.
    let steady = {
        let (sf, sr) = model.vehicle.static_axle_loads();
        let peak = |t: &crate::tyre::Tyre, fz: f64| t.peak_lateral_force(fz, 1.0) / fz;
        let mu_peak = peak(&model.front, 0.5 * sf).max(peak(&model.rear, 0.5 * sr));
        let fmax = grid.friction.iter().copied().fold(0.0, f64::max);
        let umin = grid.speed.iter().copied().fold(f64::INFINITY, f64::min);
        mu_peak * fmax * G / umin
    };
    if let Some(r) = b.yaw_rate_max {
        ParamError::positive("yaw_rate_max", r).map_err(|e| param_error(src, Some("box"), e))?;
        if r > MAX_BOX_YAW_RATES * steady {
            let why = SweepLimit::YawRate { given: r, steady };
            return Err(beyond("box.yaw_rate_max", r, why));
        }
    }
    let yaw_rate_max = b.yaw_rate_max.unwrap_or(1.2 * steady);
    Ok(SearchBox {
        beta_max: b.beta_max.unwrap_or(0.6),
        yaw_rate_max,
    })
}

/// Reads and validates a sweep file.
pub fn load_sweep(path: &Path) -> Result<Sweep, InputError> {
    let src = TomlSource::read(path)?;
    // A file of another kind is named as such, not by its first key the
    // sweep does not know.
    let f: SweepFile = src
        .parse()
        .map_err(|e| not_this_toml(path, Wanted::Sweep, &[FileKind::Sweep]).unwrap_or(e))?;
    let ResolvedModel {
        model,
        files: [front_path, rear_path],
        ..
    } = resolve_model(&src, &f.vehicle, &f.tyres, f.model)?;
    equilibrium_effects(&src, &f.model.effects)?;
    swarm_counts(&src, &f.pso)?;
    let grid = Grid {
        steer: expand(&f.sweep.steer, "steer", &src)?,
        friction: expand(&f.sweep.friction, "friction", &src)?,
        speed: expand(&f.sweep.speed, "speed", &src)?,
    };
    let search_box = search_box(&src, &model, &grid, f.search_box.unwrap_or_default())?;
    let portraits = if f.report.phase_portraits.is_empty() {
        let first = Condition {
            steer: grid.steer[0],
            friction: grid.friction[0],
            speed: grid.speed[0],
        };
        let last = Condition {
            steer: *grid.steer.last().unwrap_or(&grid.steer[0]),
            friction: *grid.friction.last().unwrap_or(&grid.friction[0]),
            speed: *grid.speed.last().unwrap_or(&grid.speed[0]),
        };
        if first == last {
            vec![first]
        } else {
            vec![first, last]
        }
    } else {
        portrait_conditions(&src, &f.report.phase_portraits)?
    };
    // The speed first: a km/h slip there explains a portrait off the axis.
    let mut notes: Vec<String> = speed_kmh::fastest(&src, &f.sweep.speed)
        .map(|k| k.to_string())
        .into_iter()
        .collect();
    notes.extend(portrait_notes(&grid, &portraits));
    let name = f.name.clone().unwrap_or_else(|| {
        path.file_stem()
            .map_or("sweep".into(), |s| s.to_string_lossy().into_owned())
    });
    Ok(Sweep {
        name,
        model,
        grid,
        search_box,
        pso: f.pso,
        report: f.report,
        portraits,
        inputs: vec![path.to_path_buf(), front_path, rear_path],
        notes,
    })
}
