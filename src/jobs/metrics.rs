//! `metrics` as one job: the step-steer metrics of a measured run, cleaned
//! first ([`crate::metrics::measured`]); and the metric table that
//! `simulate` prints too.

use crate::error::Error;
use crate::io::{read_run_reading, AngleColumn, DeclaredBy, Slip};
use crate::measured::clean::CleaningReport;
use crate::measured::MeasuredRun;
use crate::metrics::measured::{
    measured_step_metrics, AyCheck, MeasuredMetrics, AY_METRICS, NO_AY, NO_BETA,
};
use crate::metrics::{MetricSettings, StepMetrics};
pub use body_ay::{AyColumn, RollLevelling};
use serde::Serialize;
use std::path::Path;

mod body_ay;
mod coarse;
mod declared;
mod exchanged;
pub(super) mod filter_speed;
mod gap_said;
mod noise_said;
mod steps;
mod table;

pub(crate) use table::{metric_lines, sideslip_is_its_change};

/// The units of the metric reports.
pub const UNITS: &str = "SI and rad; times in s; yaw_rate_gain in 1/s; yaw_rate_overshoot, \
                         yaw_rate_peak_threshold and yaw_rate_filter_ringing in %; \
                         yaw_rate_noise as a fraction of the step (the terminal's % / 100); \
                         tb in s·deg (GB/T 6323); total variances and er in s";

/// The optional channels of a run that the step's metrics read (`roll`
/// levels `ay`, as `diagnose` levels it): the others (bank, ax) are left
/// unread, so that a column the metrics do not use cannot refuse the run.
const METRIC_CHANNELS: [&str; 3] = ["ay", "beta", "roll"];

/// The report of `metrics` (`--json` prints it): the metrics, the piece
/// measured and how the run was cleaned.
#[derive(Debug, Clone, Serialize)]
pub struct MeasuredMetricsReport {
    /// The run file.
    pub scenario: String,
    /// [`UNITS`].
    pub units: &'static str,
    /// The metrics.
    #[serde(flatten)]
    pub metrics: StepMetrics,
    /// The metrics not read as the standards define them, and why (the
    /// table's marks: [`StepMetrics::marks`]).
    pub marks: crate::metrics::Marks,
    /// The piece measured.
    pub piece: String,
    /// Time for the steer to go from 10 % to 90 % of its step, s.
    pub steer_rise_time: f64,
    /// What the user should know.
    pub warnings: Vec<String>,
    /// How the run was cleaned.
    pub cleaning: CleaningReport,
    /// The run's optional columns that the metrics do not use (bank, ax),
    /// left unread and unchecked.
    pub unread_columns: Vec<&'static str>,
    /// The column the lateral acceleration was read from: `ay_body` where
    /// a history of `simulate` with roll carries it, `ay` levelled by a
    /// logged `roll` where the run has one.
    pub ay_column: AyColumn,
    /// How `ay` was levelled by the logged roll (null where it was not).
    pub roll_levelling: Option<RollLevelling>,
    /// The piece's first sample, s.
    #[serde(skip)]
    pub t_start: f64,
    /// Its last sample, s.
    #[serde(skip)]
    pub t_end: f64,
    /// The sideslip the piece holds before its step, rad, where it stands
    /// apart from zero: the steady sideslip is a change from it.
    #[serde(skip)]
    pub sideslip_start: Option<f64>,
}

/// Reads, cleans and measures the run `path`, after checking the settings
/// ([`MetricSettings::validate`]) and that `min_speed` (m/s) is finite.
pub fn run(
    path: &Path,
    settings: &MetricSettings,
    min_speed: f64,
) -> Result<MeasuredMetricsReport, Error> {
    run_with_degrees(path, settings, min_speed, &[])
}

/// [`run`] of a file whose columns `degrees` are in degrees (deg/s for the
/// yaw rate), as a campaign's `[runs] degrees` says of its files.
pub fn run_with_degrees(
    path: &Path,
    settings: &MetricSettings,
    min_speed: f64,
    degrees: &[AngleColumn],
) -> Result<MeasuredMetricsReport, Error> {
    settings.validate()?;
    // One range and one set of words with a campaign's `min_speed`.
    crate::error::min_speed_checked(min_speed, crate::measured::clean::DEFAULT_MIN_SPEED, true)?;
    let (mut run, header) =
        read_run_reading(path, (degrees, DeclaredBy::MetricsOption), &METRIC_CHANNELS)?;
    let ay_column = body_ay::body_frame_ay(path, &mut run)?;
    // Before a dead `ay` is left out: it is said as dead, not as absent.
    let unchecked = crate::io::unchecked_speed_unit(&run);
    let had_beta = run.beta.is_some();
    let mut dead = leave_out_dead_channels(&mut run)?;
    // A dead `beta` left out is said as dead, not as absent.
    let beta_dead = had_beta && run.beta.is_none();
    let ay_read = body_ay::level_by_roll(&mut run, ay_column);
    dead.extend(header.slips.iter().map(|s| slip_warning(path, s)));
    let (mut run, mut m) = match measured_step_metrics(run.clone(), min_speed, settings) {
        Ok(m) => (run, m),
        Err(e) => {
            let e = declared::name_declaration(e, degrees);
            let (run, m, said) = first_of_several(run, min_speed, settings).ok_or(e)?;
            dead.push(said);
            (run, m)
        }
    };
    let clock = run.t.clone();
    let swapped = exchanged::exchanged(&run, m.metrics.yaw_rate_response_time);
    // An `ay` that disagrees with u·r is measured again without it; one
    // the run cannot check is kept, and said.
    match m.ay_check() {
        AyCheck::Agrees => {}
        AyCheck::Disagrees(w) => {
            run.ay = None;
            m = measured_step_metrics(run.clone(), min_speed, settings)?;
            dead.push(w);
        }
        AyCheck::Unchecked(w) => m.warnings.push(w),
    }
    let dt = crate::measured::clean::median_interval(&clock);
    coarse::withhold_unresolved(&mut m.metrics, dt, m.steer_rise_time);
    if !dead.is_empty() {
        // A dead `ay`'s warning says more than that the run has none.
        m.warnings
            .retain(|w| w != NO_AY && !(beta_dead && w == NO_BETA));
        m.warnings.splice(0..0, dead);
    }
    // First: every other warning reads the steer as logged.
    m.warnings.splice(0..0, swapped);
    // After "no `ay`", which it follows from (and which a dead-channel
    // warning replaces: this one must not).
    m.warnings.extend(unchecked);
    // Settings the run cannot honour are said, not dropped.
    m.warnings
        .extend(settings_said(&m, &run, (settings, min_speed), &clock));
    Ok(MeasuredMetricsReport {
        scenario: path.display().to_string(),
        units: UNITS,
        marks: m.metrics.marks(),
        metrics: m.metrics,
        piece: m.piece,
        steer_rise_time: m.steer_rise_time,
        warnings: m.warnings,
        cleaning: m.cleaning,
        unread_columns: header.unread,
        ay_column: ay_read.column,
        roll_levelling: ay_read.levelling,
        t_start: m.t_start,
        t_end: m.t_end,
        sideslip_start: m.sideslip_start,
    })
}

/// What the run's measurement `m` (of `run`, sampled at `clock`) says of
/// the `settings` it was asked (with `min_speed`): a low-pass the
/// sampling does not allow, windows it cannot honour, noise in the total
/// variance, a peak time or response coarser than the sampling, and a
/// cutoff that moves the response it measures (measured through, so that
/// following it is not warned of again).
fn settings_said(
    m: &MeasuredMetrics,
    run: &MeasuredRun,
    (settings, min_speed): (&MetricSettings, f64),
    clock: &[f64],
) -> Vec<String> {
    let mut out = Vec::new();
    let dt = crate::measured::clean::median_interval(clock);
    // A cutoff suggested is measured through, so that following it is
    // not warned of again.
    let metrics_at = |f: f64| {
        let at = MetricSettings {
            filter_hz: Some(f),
            ..*settings
        };
        let m = measured_step_metrics(run.clone(), min_speed, &at).ok()?;
        Some(m.metrics)
    };
    if let (Some(f), None) = (settings.filter_hz, m.metrics.filter_hz) {
        let response = m.metrics.yaw_rate_response_time;
        out.push(filter_speed::not_filtered(f, dt, response, &metrics_at));
    }
    let piece = m.t_end - m.t_start;
    out.extend(windows_said(&m.metrics, settings, clock, m.t_end));
    out.extend(noise_said::noise_in_variance(
        &m.metrics,
        settings.variance_window.min(piece),
        (settings.e1, settings.e2),
    ));
    out.extend(gap_said::piece_ended_by_gap(&m.cleaning, m.t_end, dt));
    out.extend(peak_time_said(&m.metrics, dt));
    out.extend(coarse::coarse_said(&m.metrics, dt, m.steer_rise_time));
    out.extend(filter_speed::filter_measures_itself_with(
        &m.metrics,
        dt,
        &metrics_at,
    ));
    out
}

/// The windows the run cannot honour as asked, each said: a total-variance
/// window that runs past the measured piece's end (from the steer's time
/// zero, a little after its onset) or ends before the yaw rate has
/// responded (Er is then the start of a response, 0 s at a window of 5 ms),
/// and an initial or steady window shorter than two of the run's sample
/// intervals (t, s), whose mean is one noisy sample.
fn windows_said(m: &StepMetrics, s: &MetricSettings, t: &[f64], t_end: f64) -> Vec<String> {
    let mut said = Vec::new();
    let window = s.variance_window;
    if m.time_zero + window > t_end {
        said.push(format!(
            "the total-variance window, {} s from the steer's onset, runs past the end of the measured piece at {} s: the variances are over what was recorded",
            crate::error::Num(window),
            crate::format::fixed(t_end, 2)
        ));
    }
    said.extend(m.variance_window_before_response(window));
    if t.len() < 2 {
        return said;
    }
    let dt = crate::measured::clean::median_interval(t);
    for (name, w) in [("initial", s.pre_window), ("steady", s.steady_window)] {
        if w < 2.0 * dt {
            said.push(format!(
                "the {name} window, {} s, is shorter than two of the run's sample intervals ({} s): its mean is one sample, with all its noise",
                crate::error::Num(w),
                crate::format::rounded(dt, 3)
            ));
        }
    }
    said
}

/// The first step of a run that holds several ([`steps::several_steps`]),
/// measured on the run cut before the second, with the warning that says
/// so: the whole run's windows read the steer back at its start as no step
/// (or two steps as a slow ramp), and refused it with a reason that does
/// not match what the user logged. `None` where the run is no such run or
/// its first step cannot be measured either (the whole run's refusal
/// stands).
fn first_of_several(
    run: MeasuredRun,
    min_speed: f64,
    settings: &MetricSettings,
) -> Option<(MeasuredRun, MeasuredMetrics, String)> {
    let (at, cut) = steps::several_steps(&run)?;
    let first = crate::measured::clean::slice(&run, 0, cut, "");
    let mut m = measured_step_metrics(first.clone(), min_speed, settings).ok()?;
    // The rest is read too: counted and listed with its reason, not lost.
    let rest = crate::measured::clean::slice(&run, cut, run.t.len(), "");
    m.cleaning.set_aside(
        &rest,
        crate::error::PieceRefusal::LaterSteps {
            at: at[1..].to_vec(),
        },
    );
    let times: Vec<String> = at.iter().map(|t| format!("{t:.2} s")).collect();
    let said = format!(
        "{}: the run holds {} steer steps (at {}): the first is measured, on the run up to {:.2} s, before the second; cut the log into one run per step to measure the others",
        run.path.display(),
        at.len(),
        times.join(", "),
        first.t[first.t.len() - 1]
    );
    Some((first, m, said))
}

/// The warning of a header column of `path` that is a slip of spelling
/// of a channel the metrics read and the run lacks (`bta` for `beta`,
/// found by the run's reader): a run may carry columns of its own
/// (FORMATS.md), so it is said, not refused, with what the run goes
/// without.
fn slip_warning(path: &Path, slip: &Slip) -> String {
    let (found, meant) = (&slip.found, &slip.meant);
    let metrics = if meant == "beta" {
        "steady sideslip and TB"
    } else {
        AY_METRICS
    };
    format!(
        "{}: column `{found}` is not one a run has: did you mean `{meant}`? It is not read, and the metrics of `{meant}` ({metrics}) are left out (null in --json); rename it",
        path.display()
    )
}

/// Refuses a run whose yaw rate is dead ([`MeasuredRun::dead_channels`],
/// the rule `diagnose` refuses runs by), and leaves out a dead `ay` or
/// `beta`, returning the warning that says so: a sideslip sensor logging
/// zeros was read as a steady sideslip of 0 (TB 0), and a dead `ay` as a
/// response that does not change. Their metrics are `null`, not 0.
fn leave_out_dead_channels(run: &mut MeasuredRun) -> Result<Vec<String>, Error> {
    let mut warnings = Vec::new();
    // A steer held throughout gives no response to a live sensor either
    // (straight running): the run is refused as holding no step.
    if crate::measured::one_value(&run.steer).is_some() {
        return Ok(warnings);
    }
    for d in run.dead_channels() {
        let left_out = match d.channel {
            "ay" => {
                run.ay = None;
                AY_METRICS
            }
            "beta" => {
                run.beta = None;
                "steady sideslip and TB"
            }
            _ => {
                let problem = d.problem();
                return Err(crate::error::InputError::problem(&run.path, problem).into());
            }
        };
        warnings.push(format!(
            "{}: channel `{}` holds one value ({}) over the whole run: a dead or unplugged sensor; its metrics ({left_out}) are left out (null in --json), not read from it",
            run.path.display(),
            d.channel,
            crate::error::Num(d.value)
        ));
    }
    Ok(warnings)
}

/// The share of the peak time by which noise must move it to be said: a
/// twentieth, two 100 Hz samples of a 0.4 s peak.
pub const PEAK_SPREAD_SAID: f64 = 0.05;

/// The share of the peak time from which half a sample interval, the
/// peak time's resolution, is said: 2 %, a 50 Hz log's 0.01 s of a 0.4 s
/// peak (a 100 Hz log's 1.25 % is not said).
pub const GRID_SAID: f64 = 0.02;

/// What is said of the yaw-rate peak time on a log sampled every `dt` s:
/// the peak is a sample (no interpolation between samples; the response
/// times are crossings, interpolated, and need no such word), so it is
/// resolved to ±dt/2, said where that is [`GRID_SAID`] of it or more; the
/// noise's spread ([`peak_moved_by_noise`]) where it moves it by
/// [`PEAK_SPREAD_SAID`] or more. Where both are said and the noisy copies
/// (which carry the noise twice: their spread over √2) move it by no more
/// than one sample, the grid sets the resolution, not the noise: a 20 Hz
/// log's 0.400 s against 0.435 s at 1 kHz was blamed on the noise.
fn peak_time_said(m: &StepMetrics, dt: f64) -> Option<String> {
    let tp = m.yaw_rate_peak_time?;
    let grid = 0.5 * dt;
    let coarse = dt.is_finite() && grid >= GRID_SAID * tp.abs();
    let spread = m.yaw_rate_peak_time_spread.zip(m.yaw_rate_peak_found_share);
    let noisy = spread.filter(|&(sd, found)| sd >= PEAK_SPREAD_SAID * tp.abs() || found < 0.75);
    let grid_words = || {
        format!(
            "the yaw-rate peak time, {} s, is a sample of a {} Hz log (the peak is not interpolated between samples): it is resolved to ±{} s, half the {} s sample interval ({} % of it){}",
            crate::format::readable(tp, 3),
            crate::format::readable(1.0 / dt, 3),
            crate::format::readable(grid, 2),
            crate::format::readable(dt, 3),
            crate::format::rounded(100.0 * grid / tp.abs(), 2),
            match m.tb {
                Some(_) => ", and TB with it",
                None => "",
            }
        )
    };
    match (coarse, noisy) {
        (false, None) => None,
        (false, Some(_)) => peak_moved_by_noise(m),
        (true, None) => Some(format!("{}: log faster to read it finer", grid_words())),
        (true, Some((sd, found))) if found >= 0.75 && sd / 2f64.sqrt() <= dt => Some(format!(
            "{}; in {} copies of the run with its noise added again the peak moves by ±{} s, about one sample interval (the copies carry the noise twice){}: the grid, not the noise, limits it; log faster to read it finer",
            grid_words(),
            crate::metrics::PEAK_DRAWS,
            crate::format::readable(sd, 2),
            copies_lost(m, found),
        )),
        (true, Some(_)) => peak_moved_by_noise(m).map(|w| {
            format!(
                "{w} (beside its resolution of ±{} s, half the {} s sample interval)",
                crate::format::readable(grid, 2),
                crate::format::readable(dt, 3)
            )
        }),
    }
}

/// The noisy copies that find no peak, or only another maximum (past
/// twice the peak time: `metrics/peak.rs`), of the share `found` that
/// find it: counted and said, not averaged into the spread.
fn copies_lost(m: &StepMetrics, found: f64) -> String {
    let draws = crate::metrics::PEAK_DRAWS;
    let count = |share: f64| (share * draws as f64).round() as usize;
    let stray = count(m.yaw_rate_peak_stray_share.unwrap_or(0.0));
    let lost = draws.saturating_sub(count(found) + stray);
    match (lost, stray) {
        (0, 0) => String::new(),
        (k, 0) => format!(", and {k} of the {draws} find no peak above the threshold at all"),
        (0, j) => format!(
            ", and {j} of the {draws} find only another maximum, more than the peak time from it (left out of the spread: not this peak moved)"
        ),
        (k, j) => format!(
            ", and {k} of the {draws} find no peak above the threshold and {j} only another maximum, more than the peak time from it (left out of the spread: not this peak moved)"
        ),
    }
}

/// The warning of a yaw-rate peak the run's noise moves by
/// [`PEAK_SPREAD_SAID`] of its time or more, or loses in a quarter of
/// noisy copies or more (`metrics/peak.rs`): its time, and TB with it, are
/// then the noise's as much as the car's.
fn peak_moved_by_noise(m: &StepMetrics) -> Option<String> {
    let tp = m.yaw_rate_peak_time?;
    let (sd, found) = (m.yaw_rate_peak_time_spread?, m.yaw_rate_peak_found_share?);
    let draws = crate::metrics::PEAK_DRAWS;
    let lost = copies_lost(m, found);
    let tb = match m.tb {
        Some(_) => " and TB with it",
        None => "",
    };
    // The overshoot is the same sample's height: the noise moves it too.
    let overshoot = match m.yaw_rate_overshoot.zip(m.yaw_rate_overshoot_spread) {
        Some((o, sd)) => format!(
            ", and the overshoot, {} %, by ±{} points",
            crate::format::fixed(o, 2),
            crate::format::fixed(sd, 1)
        ),
        None => String::new(),
    };
    let also = match overshoot.is_empty() {
        true => "",
        false => ", and the overshoot",
    };
    Some(format!(
        "the yaw-rate peak is flat within the noise ({}): in {draws} copies of the run with its noise added again (seed {}) the peak time, {} s, moves by ±{} s ({} %, one standard deviation){overshoot}{lost}; read the peak time{tb}{also} as uncertain by that much (an upper estimate: a copy carries the noise twice), or filter harder (--filter-hz) or log a quieter gyro",
        m.yaw_rate_noise_text(),
        crate::metrics::PEAK_SEED,
        crate::format::readable(tp, 3),
        crate::format::readable(sd, 2),
        crate::format::rounded(100.0 * sd / tp.abs(), 2),
    ) + &noise_bias_said(m))
}

/// What the run's noise does to the overshoot on average
/// (`metrics/peak.rs`): the highest of a noisy curve lies above the
/// curve's, so the overshoot reads high. Said with the estimate without
/// it and its spread; empty where the copies give no bias. The peak
/// time's shift is not said: its extrapolation scattered more than the
/// shift (round 48: 20 seeds, RMS error 0.066 s corrected against 0.050 s
/// read).
fn noise_bias_said(m: &StepMetrics) -> String {
    let (Some(o), Some(b)) = (m.yaw_rate_overshoot, m.yaw_rate_overshoot_noise_bias) else {
        return String::new();
    };
    format!(
        "; the noise also biases the overshoot: a maximum of a noisy curve lies above the curve's, and copies with a quarter, a half and all of the run's noise variance added again, extrapolated to none (SIMEX), lift it by {} points on average, so without that bias the overshoot is about {} % (±{} points); the peak time's shift is not estimated (its extrapolation scatters more than the shift)",
        crate::format::signed(b, 2),
        crate::format::fixed(o - b, 2),
        crate::format::fixed(m.yaw_rate_overshoot_spread.unwrap_or(0.0), 1),
    )
}

impl MeasuredMetricsReport {
    /// How the run was cleaned and measured, and the warnings: the lines
    /// beside the table.
    pub fn notes(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .cleaning
            .summary(usize::MAX)
            .iter()
            .map(|l| format!("cleaning: {l}"))
            .collect();
        out.push(format!(
            "measured piece: {} ({:.2}–{:.2} s); steer 10–90 % rise {:.3} s",
            self.piece, self.t_start, self.t_end, self.steer_rise_time
        ));
        if !self.unread_columns.is_empty() {
            out.push(format!(
                "not read: {} (the step's metrics use t, speed, steer, yaw_rate, {})",
                self.unread_columns.join(", "),
                METRIC_CHANNELS.join(", ")
            ));
        }
        let ay_read = body_ay::AyRead {
            column: self.ay_column,
            levelling: self.roll_levelling,
        };
        out.extend(ay_read.note());
        out.extend(self.warnings.iter().map(|w| format!("warning: {w}")));
        out
    }

    /// The run's name and its metric table.
    pub fn table(&self) -> Vec<String> {
        let mut out = vec![self.scenario.clone()];
        out.extend(metric_lines(&self.metrics));
        let change = self.sideslip_start.zip(self.metrics.beta_steady);
        out.extend(change.map(|(start, change)| table::sideslip_line(start, change)));
        out
    }
}
