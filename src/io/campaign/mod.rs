//! Test campaigns for the sim-to-real diagnosis: a vehicle, its
//! road, optionally its tyres or tyre rig data, and measured runs
//! (`FORMATS.md`). A campaign is a TOML file, or a folder laid out as
//!
//! ```text
//! vehicle.toml   # [vehicle] (FORMATS.md); optional [road], [roll], [diagnose]
//! tyre_rig.csv   # optional rig data: the base tyre model is fitted to it
//! runs/*.csv     # measured runs
//! ```
//!
//! A campaign file has the same tables plus `[tyres]` (`file` or `front` and
//! `rear` tyre files, or `rig` data with the `model` to fit) and `[runs]`
//! (`files` and/or a `dir`, and `segment`, s, to cut long logs into
//! pieces); paths are relative to the file.
//!
//! Runs are checked (`runs.rs`): a run shorter than [`MIN_RUN_SECONDS`] or
//! [`MIN_RUN_SAMPLES`] is refused; the sensor offsets their standstills and
//! straights show are measured on the runs as read
//! ([`crate::measured::calibration`]); then each is cleaned
//! ([`crate::measured::clean`]):
//! split at time gaps, glitches repaired or masked, samples below
//! `[diagnose] min_speed` (default 5 m/s) excluded, the moving pieces
//! replayed separately and the short ones dropped, all in the campaign's
//! [`CleaningReport`](crate::measured::clean::CleaningReport);
//! different sample rates between runs are fine (each run is compared at its
//! own sample times). Units: SI, rad.
//!
//! Layout: this file reads the campaign's tables and its tyres; `runs.rs`
//! finds, reads and cleans its runs, each checked by `run_checks.rs`
//! (every run checked before any is refused).

mod ax_check;
mod copies;
mod degrees;
mod few_runs;
mod glob;
mod kind;
mod levelled;
mod pieces;
mod rig_model;
mod run_checks;
mod runs;
mod steer_unit;
pub(crate) mod swept;
mod yaw_unit;

use super::paths::beside;
use super::rig::read_rig;
use super::tables::{
    apply_tyre_mode, check_road, check_vehicle, load_axle_tyre, static_wheel_loads, Road,
};
use super::toml_file::{param_error, TomlSource};
pub use crate::diagnose::campaign::prior::{AxlePrior, TyreClass};
use crate::diagnose::campaign::TyreFile;
pub use crate::diagnose::campaign::{
    BaseTyres, Campaign, DiagnoseSettings, SensorPositions, StatedUncertainty,
};
use crate::diagnose::effects::{EffectKind, RollModel};
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::scale::{
    beyond_signal, signal_rms, stated_of, ESTIMATED, ESTIMATED_REACH, SENSOR_FLOOR,
};
use crate::error::{
    named, BeyondSignal, CampaignReason, GivenTyres, InputError, InputProblem, Limit, NameKind,
    OptionsError, ParamError, ParamReason, TyreSourceError,
};
use crate::io::AngleColumn;
pub use crate::measured::clean::{MIN_RUN_SAMPLES, MIN_RUN_SECONDS};
use crate::vehicle::Vehicle;
use run_checks::file_error;
pub use runs::RunSpec;
use runs::{read_runs, run_files};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The `[tyres]` table.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TyreSpec {
    /// One tyre file for all four wheels.
    pub file: Option<PathBuf>,
    /// Front tyre file.
    pub front: Option<PathBuf>,
    /// Rear tyre file.
    pub rear: Option<PathBuf>,
    /// Tyre rig data (CSV, FORMATS.md).
    pub rig: Option<PathBuf>,
    /// Model fitted to the rig data (default pac89).
    pub model: Option<String>,
    /// MFeval's `useMode` for Magic Formula (.tir) tyre files (default 121).
    pub mode: Option<u32>,
    /// Without tyre data: the class of the car's tyres, whose ranges are
    /// the prior of the axles identified from the runs (default `road`).
    pub class: Option<String>,
    /// Without tyre data: the 95 % range of the axle cornering
    /// coefficient, 1/rad (instead of the class's).
    pub cornering: Option<[f64; 2]>,
    /// Without tyre data: the 95 % range of the peak friction (instead of
    /// the class's).
    pub friction: Option<[f64; 2]>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct CampaignFile {
    #[serde(default)]
    name: Option<String>,
    vehicle: Vehicle,
    #[serde(default)]
    road: Road,
    #[serde(default)]
    tyres: Option<TyreSpec>,
    #[serde(default)]
    runs: Option<RunSpec>,
    #[serde(default)]
    roll: RollModel,
    #[serde(default)]
    diagnose: DiagnoseSettings,
    #[serde(default)]
    channels: StatedUncertainty,
    #[serde(default)]
    sensors: SensorPositions,
}

/// A refusal of what a `degrees` entry declares (`declared`), at that
/// entry of the campaign file.
fn degrees_entry<'a>(
    src: &'a TomlSource,
    declared: &'a [AngleColumn],
) -> impl Fn(AngleColumn, InputProblem) -> InputError + 'a {
    move |column, problem| {
        let k = declared.iter().position(|c| *c == column);
        let key = k.map_or("runs.degrees".into(), |k| format!("runs.degrees[{k}]"));
        src.located(src.key_span(&key), problem)
    }
}

/// Loads a campaign from a TOML file or a folder.
pub fn load_campaign(path: &Path) -> Result<Campaign, InputError> {
    let folder = path.is_dir();
    let file = if folder {
        path.join("vehicle.toml")
    } else {
        path.to_path_buf()
    };
    if folder && !file.is_file() {
        return Err(file_error(path, InputProblem::NoVehicleFile));
    }
    let src = TomlSource::read(&file)?;
    let f: CampaignFile = src
        .parse()
        .map_err(|e| kind::named_kind(&file, &src.text, e))?;
    let base = file.parent().unwrap_or(Path::new(".")).to_path_buf();
    validate(&src, &f)?;
    let effects = candidate_effects(&src, &f.diagnose)?;
    let mut inputs = vec![file.clone()];
    let tyres = base_tyres(&src, &f, &base, folder, &mut inputs)?;
    let prior = axle_prior(&src, f.tyres.as_ref(), &tyres)?;
    let mut folder_notes = front_only_note(f.tyres.as_ref());
    let files = run_files(
        &src,
        f.runs.as_ref(),
        &base,
        path,
        folder,
        &mut folder_notes,
    )?;
    let declared = f.runs.as_ref().map_or(&[][..], |r| &r.degrees[..]);
    degrees::check_declared(&src, declared, &files)?;
    let copied = |first, second| runs::refuse_copy(&src, f.runs.as_ref(), &files, (first, second));
    let at_degrees = degrees_entry(&src, declared);
    let (runs, mut notes, cleaning, calibration, top_speeds) = read_runs(
        &files,
        (f.runs.as_ref().and_then(|r| r.segment), declared),
        f.diagnose.min_speed,
        f.vehicle.wheelbase(),
        &mut inputs,
        (&copied, &at_degrees),
    )?;
    notes.splice(0..0, folder_notes);
    let unread = src.unread_vehicle_keys().into_iter().map(|u| u.note());
    notes.splice(0..0, unread);
    check_stated(&src, &f.channels, &runs)?;
    let stated_rate = src.key_span("diagnose.sample_rate").is_some();
    notes.extend(rate_note(f.diagnose.sample_rate, &runs).filter(|_| stated_rate));
    notes.extend(f.sensors.note());
    if runs.len() < 2 {
        let read = (&runs[..], files.len(), &cleaning, &top_speeds[..]);
        let folder = runs_folder(f.runs.as_ref(), &base, path, folder);
        let at = (file.as_path(), folder);
        return Err(few_runs::too_few_runs(&src, at, f.diagnose.min_speed, read));
    }
    let name = campaign_name(f.name.clone(), path);
    Ok(Campaign {
        name,
        source: path.to_path_buf(),
        inputs,
        runs_folder: runs_folder(f.runs.as_ref(), &base, path, folder),
        vehicle: f.vehicle,
        friction: f.road.friction,
        friction_at: src
            .key_span("road.friction")
            .map(|s| super::toml_file::line_col(&src.text, s.start).0),
        tyres,
        prior,
        uncertainty: f.channels,
        sensors: f.sensors,
        runs,
        run_files: files.len(),
        roll: f.roll,
        roll_gradient_at: stated_at(&src, &file, "roll.gradient"),
        settings: f.diagnose,
        effects,
        notes,
        cleaning,
        calibration,
    })
}

/// The file and line where `src`, read from `file`, states `key` (None:
/// it does not).
fn stated_at(src: &TomlSource, file: &Path, key: &str) -> Option<(PathBuf, usize)> {
    let at = src.key_span(key)?;
    Some((
        file.to_path_buf(),
        super::toml_file::line_col(&src.text, at.start).0,
    ))
}

/// A `[tyres]` with `front` only runs it on both axles, as a scenario's:
/// the note saying so. Apart from [`load_campaign`] so that it reads on a
/// screen.
fn front_only_note(tyres: Option<&TyreSpec>) -> Vec<String> {
    tyres
        .filter(|t| t.file.is_none() && t.front.is_some() && t.rear.is_none() && t.rig.is_none())
        .map(|_| {
            "[tyres] gives `front` only: the rear axle runs on the front file too, at its own static load, as a scenario's `rear` defaults to its `front`".to_string()
        })
        .into_iter()
        .collect()
}

/// The campaign's `name`, else its folder's whole name (`runs_0.05` is not
/// `runs_0`: two folders must not write over each other's default output)
/// or its file's stem. Apart from [`load_campaign`] so that it reads on a
/// screen.
fn campaign_name(name: Option<String>, path: &Path) -> String {
    name.unwrap_or_else(|| {
        if path.is_dir() {
            path.file_name()
        } else {
            path.file_stem()
        }
        .map_or("campaign".into(), |s| s.to_string_lossy().into_owned())
    })
}

/// The folder whose every `*.csv` is read as a run (by [`run_files`],
/// and kept on the campaign so no output is written into it): `[runs]
/// dir`, or a campaign folder's `runs/` where no files are listed.
fn runs_folder(runs: Option<&RunSpec>, base: &Path, path: &Path, folder: bool) -> Option<PathBuf> {
    match runs {
        Some(RunSpec { dir: Some(d), .. }) => Some(beside(base, d)),
        Some(r) if !r.files.is_empty() => None,
        _ => folder.then(|| path.join("runs")),
    }
}

/// The lowest rate of the fits' residuals, Hz ([`Limit::ResidualRate`]).
const MIN_RESIDUAL_RATE: f64 = 4.0;

/// Checks the vehicle, road, roll, diagnosis and segment values.
fn validate(src: &TomlSource, f: &CampaignFile) -> Result<(), InputError> {
    check_vehicle(src, &f.vehicle)?;
    check_road(src, &f.road)?;
    f.roll
        .validate()
        .map_err(|e| param_error(src, Some("roll"), e))?;
    let p = &f.sensors;
    for (key, v) in [("accelerometer_x", p.accelerometer_x), ("beta_x", p.beta_x)] {
        if let Some(v) = v {
            ParamError::in_range(key, v, -5.0, 5.0, Limit::SensorPosition)
                .map_err(|e| param_error(src, Some("sensors"), e))?;
        }
    }
    let c = &f.channels;
    for (key, v) in [("yaw_rate", c.yaw_rate), ("ay", c.ay), ("beta", c.beta)] {
        if let Some(v) = v {
            ParamError::positive(key, v).map_err(|e| param_error(src, Some("channels"), e))?;
        }
    }
    let s = &f.diagnose;
    ParamError::in_range("step", s.step, 1e-4, 0.05, Limit::ReplayStep)
        .and_then(|_| {
            ParamError::in_range(
                "sample_rate",
                s.sample_rate,
                MIN_RESIDUAL_RATE,
                f64::INFINITY,
                Limit::ResidualRate,
            )
        })
        // One range for a negative, NaN and too high value alike.
        .and_then(|_| {
            let default = crate::measured::clean::DEFAULT_MIN_SPEED;
            crate::error::min_speed_checked(s.min_speed, default, false)
        })
        .and_then(|_| {
            ParamError::in_range(
                "max_effects",
                s.max_effects as f64,
                0.0,
                f64::INFINITY,
                Limit::MaxEffects,
            )
        })
        .map_err(|e| param_error(src, Some("diagnose"), e))?;
    if let Some(seg) = f.runs.as_ref().and_then(|r| r.segment) {
        ParamError::in_range(
            "segment",
            seg,
            MIN_RUN_SECONDS,
            f64::INFINITY,
            Limit::Segment {
                min: MIN_RUN_SECONDS,
            },
        )
        .map_err(|e| param_error(src, Some("runs"), e))?;
    }
    Ok(())
}

/// Refuses a channel uncertainty under `[channels]` beyond both the
/// channel's RMS signal over the `runs` and ten times an estimated
/// output's ([`beyond_signal`]).
fn check_stated(
    src: &TomlSource,
    stated: &StatedUncertainty,
    runs: &[crate::measured::MeasuredRun],
) -> Result<(), InputError> {
    let rms = signal_rms(runs);
    for ch in Channel::ALL {
        let Some(s) = stated_of(ch, stated) else {
            continue;
        };
        let signal = rms[ch.index()];
        if beyond_signal(ch, s, signal) {
            let reason = ParamReason::UncertaintyBeyondSignal(Box::new(BeyondSignal {
                signal,
                unit: ch.unit(),
                floor: SENSOR_FLOOR[ch.index()],
                estimated: ESTIMATED_REACH * ESTIMATED[ch.index()],
            }));
            return Err(param_error(
                src,
                Some("channels"),
                ParamError::new(ch.name(), s, reason),
            ));
        }
    }
    Ok(())
}

/// The note of a residual rate above every run's own (by its median
/// interval): every sample is taken, as at the runs' rate, which the user
/// who asked for more should know.
fn rate_note(rate: f64, runs: &[crate::measured::MeasuredRun]) -> Option<String> {
    let highest = runs
        .iter()
        .filter(|r| r.t.len() > 1)
        .map(|r| 1.0 / crate::measured::clean::median_interval(&r.t))
        .fold(0.0_f64, f64::max);
    (highest > 0.0 && rate > 1.01 * highest).then(|| {
        format!(
            "sample_rate = {} Hz under [diagnose] is above the runs' own rates (at most {} Hz): every sample is a residual, as at {} Hz",
            crate::error::Num(rate),
            crate::format::rounded(highest, 3),
            crate::format::rounded(highest, 3)
        )
    })
}

/// The candidate effects named by `[diagnose] effects` (all by default).
fn candidate_effects(
    src: &TomlSource,
    s: &DiagnoseSettings,
) -> Result<Vec<EffectKind>, InputError> {
    let Some(names) = &s.effects else {
        return Ok(EffectKind::ALL.to_vec());
    };
    // No candidate would make a verdict of "no effect explains the gap"
    // that nothing was tried for.
    if names.is_empty() {
        return Err(src.value_error(&ParamError::without_value(
            "diagnose.effects",
            ParamReason::NoEffects,
        )));
    }
    let mut kinds = Vec::with_capacity(names.len());
    for n in names {
        let kind = EffectKind::from_name(n).ok_or_else(|| {
            src.value_error(&ParamError::without_value(
                "diagnose.effects",
                ParamReason::Name(Box::new(OptionsError::UnknownName {
                    what: NameKind::Effect,
                    given: n.clone(),
                    known: EffectKind::ALL.iter().map(|e| e.name()).collect(),
                })),
            ))
        })?;
        if kinds.contains(&kind) {
            return Err(src.value_error(&ParamError::without_value(
                "diagnose.effects",
                ParamReason::EffectTwice { name: n.clone() },
            )));
        }
        kinds.push(kind);
    }
    Ok(kinds)
}

/// The prior of the axles identified from the runs: `[tyres] class`
/// (default road), its ranges replaced by `cornering` and `friction` where
/// given; refused with tyre data, which leaves no axles to identify.
fn axle_prior(
    src: &TomlSource,
    spec: Option<&TyreSpec>,
    tyres: &BaseTyres,
) -> Result<AxlePrior, InputError> {
    let Some(spec) = spec else {
        return Ok(AxlePrior::default());
    };
    let stated = [
        ("tyres.class", spec.class.is_some()),
        ("tyres.cornering", spec.cornering.is_some()),
        ("tyres.friction", spec.friction.is_some()),
    ];
    if !matches!(tyres, BaseTyres::FromRuns) {
        if let Some((key, _)) = stated.iter().find(|s| s.1) {
            return Err(
                src.value_error(&ParamError::without_value(key, ParamReason::PriorWithTyres))
            );
        }
    }
    let mut prior = match &spec.class {
        None => AxlePrior::default(),
        Some(name) => AxlePrior::of(
            named(&TyreClass::ALL, TyreClass::name, NameKind::TyreClass, name).map_err(|why| {
                src.value_error(&ParamError::without_value(
                    "tyres.class",
                    ParamReason::Name(Box::new(why)),
                ))
            })?,
        ),
    };
    // What the identification can represent (the axle shares' box).
    let boxes = [
        (0.4, 4000.0, Limit::PriorCornering),
        (0.11, 9.0, Limit::PriorFriction),
    ];
    for (i, (key, range)) in [
        ("tyres.cornering", spec.cornering),
        ("tyres.friction", spec.friction),
    ]
    .into_iter()
    .enumerate()
    {
        let Some([lo, hi]) = range else { continue };
        let (min, max, within) = boxes[i];
        ParamError::in_range(key, lo, min, max, within)
            .and_then(|_| ParamError::in_range(key, hi, min, max, within))
            .and_then(|_| ParamError::in_range(key, hi, lo, max, Limit::PriorRange))
            .map_err(|e| src.value_error(&e))?;
        if i == 0 {
            prior.cornering = [lo, hi];
        } else {
            prior.friction = [lo, hi];
        }
        prior.stated[i] = true;
    }
    Ok(prior)
}

/// A `[tyres] model` refused where there is no rig data to fit it to (tyre
/// files, or none; `rig_found` a campaign folder's `tyre_rig.csv`): the
/// name would be passed over in silence.
fn model_without_rig(src: &TomlSource, spec: &TyreSpec, rig_found: bool) -> Result<(), InputError> {
    let files = spec.file.is_some() || spec.front.is_some() || spec.rear.is_some();
    let (Some(model), None) = (&spec.model, &spec.rig) else {
        return Ok(());
    };
    let given = match (files, rig_found) {
        (true, _) => GivenTyres::Files,
        (false, false) => GivenTyres::Nothing,
        (false, true) => return Ok(()),
    };
    Err(src.value_error(&ParamError::without_value(
        "tyres.model",
        ParamReason::Campaign(Box::new(CampaignReason::ModelWithoutRig(TyreSourceError {
            model: model.clone(),
            given,
        }))),
    )))
}

/// A given tyre file read from `path` with its `[fitted_ranges]`: the
/// loads it states it was fitted at, which the diagnosis notes a car's
/// wheels leaving.
fn tyre_file(path: PathBuf, ranges: Option<super::fitted_ranges::FittedRanges>) -> TyreFile {
    let fitted_loads = ranges.and_then(|r| r.fz);
    TyreFile { path, fitted_loads }
}

/// Where the base tyres come from: tyre files, rig data (read here) with
/// the model to fit, or nothing (axles identified from the runs).
fn base_tyres(
    src: &TomlSource,
    f: &CampaignFile,
    base: &Path,
    folder: bool,
    inputs: &mut Vec<PathBuf>,
) -> Result<BaseTyres, InputError> {
    let spec = f.tyres.clone().unwrap_or_default();
    let rig_default = base.join("tyre_rig.csv");
    model_without_rig(src, &spec, folder && rig_default.is_file())?;
    let rig = match (&spec.file, &spec.front, &spec.rear, &spec.rig) {
        (Some(t), None, None, None) => {
            let t = beside(base, t);
            inputs.push(t.clone());
            src.referenced_tyre("tyres.file", &t, true)?;
            // One file on both axles: checked at the heavier wheel.
            let (front, rear) = static_wheel_loads(&f.vehicle);
            let (mut tyre, ranges) = load_axle_tyre(&t, front.max(rear))?;
            apply_tyre_mode(src, "tyres.mode", spec.mode, &mut [&mut tyre])?;
            let file = tyre_file(t, ranges);
            let files = Box::new([file.clone(), file]);
            return Ok(BaseTyres::Given(
                Box::new(tyre.clone()),
                Box::new(tyre),
                files,
            ));
        }
        // `rear` defaults to `front`, as a scenario's does (noted where
        // the campaign is read); a campaign had refused it.
        (None, Some(fr), re, None) => {
            let (fr, re) = (beside(base, fr), beside(base, re.as_ref().unwrap_or(fr)));
            inputs.push(fr.clone());
            src.referenced_tyre("tyres.front", &fr, true)?;
            if spec.rear.is_some() {
                inputs.push(re.clone());
                src.referenced_tyre("tyres.rear", &re, true)?;
            }
            let (front, rear) = static_wheel_loads(&f.vehicle);
            let ((mut f, fr_ranges), (mut r, re_ranges)) =
                (load_axle_tyre(&fr, front)?, load_axle_tyre(&re, rear)?);
            apply_tyre_mode(src, "tyres.mode", spec.mode, &mut [&mut f, &mut r])?;
            let files = Box::new([tyre_file(fr, fr_ranges), tyre_file(re, re_ranges)]);
            return Ok(BaseTyres::Given(Box::new(f), Box::new(r), files));
        }
        (None, None, None, Some(rig)) => {
            let rig = beside(base, rig);
            src.referenced_file("tyres.rig", &rig)?;
            rig
        }
        (None, None, None, None) if folder && rig_default.is_file() => rig_default,
        (None, None, None, None) => return Ok(BaseTyres::FromRuns),
        _ => {
            return Err(
                src.value_error(&ParamError::without_value("tyres", ParamReason::TyreSource))
            )
        }
    };
    let model = rig_model::rig_model(src, spec.model.as_deref().unwrap_or("pac89"))?;
    let data = read_rig(&rig)?;
    inputs.push(rig.clone());
    Ok(BaseTyres::Rig {
        path: rig,
        data: Box::new(data),
        model,
    })
}
