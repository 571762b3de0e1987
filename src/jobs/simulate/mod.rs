//! `simulate` as one job: a scenario in; the time history (`history.csv`),
//! the step-steer metrics (`metrics.json`), the response figure
//! (`response.png`) and, for a replayed measurement, where the model and
//! the run disagree (`gap.json`) out; beside them, what the run is that
//! the scenario's words do not say ([`checks`]).

mod approach;
mod ay_ceiling;
pub(crate) mod checks;
pub(crate) mod critical;
mod grid_peak;
mod idle_effects;
mod layout;
mod lift_offs;
mod limits;
pub(crate) mod nominal_load;
mod own_peak;
mod stall;
mod straight;
mod transient;
mod unfitted;
pub(crate) mod unlimited;

use super::metrics::{metric_lines, UNITS};
use crate::diagnose::campaign::StatedUncertainty;
use crate::diagnose::report::gap::{run_gap, ChannelGap};
use crate::diagnose::report::outcome::AssumedFloor;
use crate::diagnose::report::trust::channel_trust;
use crate::diagnose::report::{words, ChannelNoise};
use crate::error::{Error, PieceRefusal};
use crate::io::{load_scenario, Scenario};
use crate::manoeuvre::Manoeuvre;
use crate::measured::clean::CleaningReport;
use crate::measured::MeasuredRun;
use crate::metrics::applicability::{
    applicability_with_grip, schedule_applicability, step_rate_applicability, Grip, Overshoot,
};
use crate::metrics::{simulated_step_metrics, AxlesGrip, StepMetrics};
use crate::report::plot::{Figure, Panel, Series, Tone, MEASURED_DOTS};
use crate::report::progress::Progress;
use crate::report::stale::{leftovers, Leftovers, OwnSet};
use crate::report::{
    refuse_overwrites, write_columns_to, write_json, write_json_sorted, OutputLock,
};
use crate::sim::{LiftOff, Method, MethodName, Simulation, TimeHistory};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// `gap.json`: a replayed run against the model, channel by channel.
#[derive(Debug, Clone, Serialize)]
pub struct ReplayGap {
    /// The run file.
    pub run: String,
    /// Per channel.
    pub channels: Vec<ChannelGap>,
    /// How far each channel is trusted, its noise floor and where it comes
    /// from, by `diagnose`'s rule on this one run.
    pub noise: Vec<ChannelNoise>,
    /// How the run was cleaned.
    pub cleaning: Option<CleaningReport>,
}

/// The report of `simulate`.
#[derive(Debug, Clone, Serialize)]
pub struct SimulateReport {
    /// Scenario name.
    pub scenario: String,
    /// The integration method.
    pub method: MethodName,
    /// The integration in words (method, steps, work).
    pub integration: String,
    /// Front and rear tyre models.
    pub tyres: [&'static str; 2],
    /// Friction scale.
    pub friction: f64,
    /// Step-steer metrics (step steers only).
    pub metrics: Option<StepMetrics>,
    /// Facts of the run the scenario does not state (a step steer's
    /// straight-running trim).
    pub notes: Vec<String>,
    /// Where the metrics describe something other than a handling
    /// response ([`applicability_with_grip`]): a slide, a spin, a crawl;
    /// and where the run is not what its input's words suggest
    /// ([`checks`]).
    pub warnings: Vec<String>,
    /// Intervals with a wheel off the ground.
    pub lift_offs: Vec<LiftOff>,
    /// A replayed measurement's gap.
    pub replay: Option<ReplayGap>,
    /// The time history.
    #[serde(skip)]
    pub history: TimeHistory,
    /// The replayed run.
    #[serde(skip)]
    pub measured: Option<MeasuredRun>,
    /// The output folder.
    #[serde(skip)]
    pub out_dir: PathBuf,
    /// The output folder, held for this run until the report is dropped.
    #[serde(skip)]
    pub lock: OutputLock,
    /// What the folder held of an earlier run: removed once written.
    #[serde(skip)]
    pub leftovers: Leftovers,
}

/// `metrics.json`.
#[derive(Serialize)]
struct MetricsFile<'a> {
    scenario: &'a str,
    units: &'static str,
    #[serde(flatten)]
    metrics: &'a StepMetrics,
    /// Intervals with a wheel off the ground (simulated runs only). Every
    /// key is written, empty lists too: a reader tells "none" from "not
    /// computed" only by a key that is always there.
    lift_offs: &'a [LiftOff],
    /// Facts of the run the scenario does not state (a trim).
    notes: &'a [String],
    /// Where the metrics do not describe a handling response.
    warnings: &'a [String],
    /// The metrics not read as the standards define them, and why: the
    /// table's marks, as `metrics --json` carries them
    /// ([`StepMetrics::marks`]).
    marks: crate::metrics::Marks,
}

const FILES: [&str; 4] = ["history.csv", "metrics.json", "response.png", "gap.json"];

/// The work units ([`crate::sim::Integrator::work_units`]: rows, twice
/// under Dormand–Prince) from which a simulation shows a progress line on
/// a terminal: about a second's work; the bundled step steers' 12 000 take
/// a fraction of it, a 10-minute replay at 1 ms takes 1.2 million.
const LONG_RUN: usize = 200_000;

/// `simulate`'s outputs, as [`crate::report::stale`] finds an earlier
/// run's.
const OWN: OwnSet = OwnSet {
    names: &FILES,
    families: &[],
};

/// Simulates the scenario of the file `path`; `out` is the output folder
/// (default `out/<scenario name>`), checked against the inputs first.
/// Everything is computed before anything is written
/// ([`SimulateReport::write`]), so a failure leaves no outputs behind.
pub fn run(path: &Path, out: Option<&Path>) -> Result<SimulateReport, Error> {
    let sc = load_scenario(path)?;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sc.name), Path::to_path_buf);
    refuse_overwrites(&FILES.map(|f| out_dir.join(f)), &sc.inputs)?;
    let lock = OutputLock::acquire(&out_dir)?;
    let sim = {
        // A long run (a replay of an hour's log) shows how far it has got.
        let units = sc.integrator.work_units(&sc.manoeuvre);
        let progress = (units >= LONG_RUN).then(|| Progress::start("simulate", units));
        let counter = progress.as_ref().map(Progress::counter);
        sc.integrator
            .simulate_counted(&sc.model, &sc.manoeuvre, sc.initial, counter)
    };
    stall::refuse_stalled(path, &sc, &sim)?;
    let h = &sim.history;
    let integration = integration_words(&sc, &sim);
    let metrics = match sc.manoeuvre {
        // From the dense output under Dormand–Prince (events located to
        // the tolerance), from the rows under RK4.
        Manoeuvre::StepSteer(_) => Some(
            simulated_step_metrics(&sc.integrator, &sc.model, &sc.manoeuvre, &sim, &sc.metrics)
                .map_err(Error::Metrics)?,
        ),
        _ => None,
    };
    // An oversteering car stepped above its critical speed diverges: on
    // linear tyres always, on others where the run did not settle; its
    // "steady" values are no steady state's, so none are given.
    let unstable = match &sc.manoeuvre {
        Manoeuvre::StepSteer(s) => {
            critical::above_critical(&sc.model, sc.integrator.friction, s.speed)
        }
        _ => None,
    }
    .filter(|_| checks::gripless(&sc) || metrics.as_ref().is_some_and(|m| !m.settled));
    let metrics = metrics.filter(|_| unstable.is_none());
    let mut warnings = applicability(&sc, h, metrics.as_ref());
    warnings.extend(unstable.map(|u| u.to_string()));
    warnings.extend(step_warnings(&sc, h, metrics.as_ref()));
    let said = run_checks(&sc, h, &mut warnings);
    let replay = sc.measured.as_ref().map(|run| replay_gap(&sc, run, h));
    // The files this run writes: the history and figure always, the
    // metrics of a step steer, the gap of a replayed run.
    let written: Vec<PathBuf> = [
        Some(FILES[0]),
        metrics.is_some().then_some(FILES[1]),
        Some(FILES[2]),
        replay.is_some().then_some(FILES[3]),
    ]
    .into_iter()
    .flatten()
    .map(|f| out_dir.join(f))
    .collect();
    let leftovers = leftovers(&out_dir, &OWN, &written);
    Ok(SimulateReport {
        method: sc.integrator.method.name(),
        integration,
        tyres: [sc.model.front.model_name(), sc.model.rear.model_name()],
        friction: sc.integrator.friction,
        metrics,
        notes: said,
        warnings,
        lift_offs: h.lift_offs(),
        replay,
        history: sim.history,
        measured: sc.measured,
        scenario: sc.name,
        out_dir,
        lock,
        leftovers,
    })
}

/// The integration in words: method, tolerances, steps and work.
fn integration_words(sc: &Scenario, sim: &Simulation) -> String {
    let h = &sim.history;
    match (sc.integrator.method, sim.stats()) {
        (Method::Dopri5(tol) | Method::Dop853(tol), Some(st)) => format!(
            "{}, rtol {:e}, atol {:e}: {} steps ({} rejected, {} evaluations, {} tyre-set evaluations), rows every {} s",
            sc.integrator.method.name().title(), tol.rtol, tol.atol, st.accepted, st.rejected, st.evaluations, h.load_evaluations, sc.integrator.step
        ),
        _ => format!("RK4, {} steps of {} s", h.len() - 1, sc.integrator.step),
    }
}

/// Where a step's metrics describe something other than a handling
/// response: a slide, a spin, a crawl ([`applicability_with_grip`]).
fn applicability(sc: &Scenario, h: &TimeHistory, metrics: Option<&StepMetrics>) -> Vec<String> {
    // The tyres' grip on this road (the lower axle's): a sideslip with
    // the tyres far below it is a slow car's turn, not a slide.
    let friction = checks::axle_friction(sc);
    let grip = friction.map(|[f, r]| f.min(r) * crate::constants::G);
    // The most of its grip either axle uses: a large overshoot far below
    // it is a lightly damped response, not a spin.
    let peak_share = friction.map(|mu| checks::peak_grip_used(h, mu));
    metrics.map_or_else(Vec::new, |m| {
        // A sideslip beyond 10° with both axles short of their own peaks
        // is no slide: said so here, in place of the metrics' slide.
        let own = own_peak::steady_sideslip(sc, h, m, grip);
        let m = match &own {
            Some(_) => StepMetrics {
                beta_steady: None,
                ..*m
            },
            None => *m,
        };
        own.into_iter()
            .chain(applicability_with_grip(
                &m,
                Some(sc.manoeuvre.speed(0.0)),
                grip.map(Grip::Tyres),
                match peak_share {
                    // The sideslip tells no spin only where no axle
                    // reaches its own tyres' peak.
                    Some(share) => Some(Overshoot::GripUsed {
                        share,
                        sideslip: (own_peak::axles_grip(sc, h) == AxlesGrip::BelowPeak)
                            .then(|| h.beta.iter().fold(0.0, |m: f64, b| m.max(b.abs()))),
                    }),
                    // Linear tyres are judged by their largest slip angles.
                    None => checks::gripless(sc).then(|| Overshoot::LinearSlip(largest_slip(h))),
                },
            ))
            .collect()
    })
}

/// Each axle's largest |slip angle| in the run, rad (front, rear).
fn largest_slip(h: &TimeHistory) -> [f64; 2] {
    [&h.alpha_front, &h.alpha_rear].map(|a| a.iter().fold(0.0, |m: f64, v| m.max(v.abs())))
}

/// What the manoeuvre and its metrics say of themselves: a step still
/// settling, a filter that measures itself, a step no steering drives, a
/// steady ay asked and missed, a schedule no car on this road drives.
fn step_warnings(sc: &Scenario, h: &TimeHistory, metrics: Option<&StepMetrics>) -> Vec<String> {
    // Where the lateral acceleration heads, bounded by what this car can
    // reach on this road.
    let mut warnings: Vec<String> = metrics
        .and_then(|m| ay_ceiling::settling_warning(sc, h, m))
        .into_iter()
        .collect();
    // A `[metrics] filter_hz` slow enough to measure itself, said as
    // `metrics` says it of a log (its rows every step).
    warnings.extend(
        metrics.and_then(|m| {
            super::metrics::filter_speed::filter_measures_itself(m, sc.integrator.step)
        }),
    );
    // A total-variance window shorter than the response, said as
    // `metrics` says it of a log.
    warnings.extend(
        metrics.and_then(|m| m.variance_window_before_response(sc.metrics.variance_window)),
    );
    // A peak read on the rows (RK4, or a low-pass), said to its
    // resolution as `metrics` says a log's.
    warnings.extend(metrics.and_then(|m| grid_peak::on_the_rows(sc, m)));
    // A step no steering can drive (an instant one, at rise_time = 0).
    if let Manoeuvre::StepSteer(s) = &sc.manoeuvre {
        warnings.extend(step_rate_applicability(s.amplitude, s.rise_time));
    }
    // A step sized for a steady lateral acceleration that settles at
    // another, or settles nowhere within the run.
    if let (Some(asked), Some(m)) = (sc.asked_ay, metrics) {
        let ceiling = m.ay_steady.map(|ay| ay_ceiling::ceiling(sc, ay));
        warnings.extend(approach::asked_ay_words(sc, h, asked, m, ceiling.as_ref()));
    }
    // A schedule (a replay of no measured run) is a speed someone wrote:
    // held to what a car on this road can drive.
    if let (Manoeuvre::Replay(r), None) = (&sc.manoeuvre, &sc.measured) {
        warnings.extend(schedule_applicability(
            &r.t,
            &r.steer,
            &r.speed,
            sc.integrator.friction,
        ));
    }
    warnings
}

/// The run against its input's words ([`checks::checks`]), tyres used
/// outside what they were fitted to, and a `.tir` whose longitudinal slip
/// stiffness turns negative inside its own load range (said as
/// `tyre-eval` says it, once per file): the warnings join `warnings`, the
/// notes are returned.
fn run_checks(sc: &Scenario, h: &TimeHistory, warnings: &mut Vec<String>) -> Vec<String> {
    let mut said = checks::checks(sc, h);
    // A layout no car has, first: the rest is read on it.
    warnings.extend(layout::layout_warnings(&sc.model.vehicle));
    warnings.append(&mut said.warnings);
    warnings.extend(unfitted::longitudinal_only(sc));
    warnings.extend(unfitted::tir_lateral_unfitted(sc));
    let mut tirs: Vec<&PathBuf> = sc.inputs.iter().collect();
    tirs.dedup();
    warnings.extend(
        tirs.into_iter()
            .filter_map(|p| crate::io::tir::longitudinal_turn(p).map(|t| t.to_string())),
    );
    said.notes.extend(
        sc.measured
            .as_ref()
            .and_then(crate::io::unchecked_speed_unit),
    );
    said.notes
}

/// A replayed run's gap, channel by channel, against the floors `diagnose`
/// would trust its channels to by its own rule: a run's scatter alone
/// trusts a state estimator's smooth output, or a quiet gyro, beyond any
/// sensor of its type.
fn replay_gap(sc: &Scenario, run: &MeasuredRun, h: &TimeHistory) -> ReplayGap {
    let trust = channel_trust(std::slice::from_ref(run), &StatedUncertainty::default());
    let mut channels = run_gap(run, h, &trust.floors, &trust.countings);
    // A gap within noise only by an assumed floor says so.
    for g in &mut channels {
        let noise = trust.noise.iter().find(|n| n.channel == g.channel);
        if let Some(a) = noise.and_then(|n| AssumedFloor::of(n, g.rms)) {
            g.verdict += &format!("; {}", words::assumed_floor(&a));
        }
    }
    ReplayGap {
        run: run.path.display().to_string(),
        channels,
        noise: trust.noise,
        cleaning: sc.cleaning.clone(),
    }
}

/// The piece a replay took where the run had others, said by its span and
/// samples and why it was taken: the dropped pieces' lines alone ("another
/// piece was used") left the reader to work out which.
fn replayed_piece(c: &CleaningReport) -> Option<String> {
    let p = c.pieces.first().filter(|_| !c.dropped_pieces.is_empty())?;
    let held = c
        .dropped_pieces
        .iter()
        .any(|d| matches!(d.reason, Some(PieceRefusal::SteerHeld { .. })));
    let why = match held {
        true => "the longest piece that moves the steer (a longer one holds it)",
        false => "the longest piece",
    };
    Some(format!(
        "  cleaning: replayed piece {} ({:.2}–{:.2} s, {}): {why}",
        p.name,
        p.t_start,
        p.t_end,
        crate::format::plural(p.samples, "sample", "samples")
    ))
}

impl SimulateReport {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        let mut out = vec![format!(
            "{}: {}, tyres {} / {}, friction {}",
            self.scenario, self.integration, self.tyres[0], self.tyres[1], self.friction
        )];
        if let Some(m) = &self.metrics {
            out.extend(metric_lines(m));
        }
        out.extend(self.notes.iter().map(|w| format!("  note: {w}")));
        out.extend(self.warnings.iter().map(|w| format!("  warning: {w}")));
        // The four loads always add up to the weight; a wheel at zero load
        // has lifted off, and the 2-DOF model then carries its axle on one
        // wheel.
        out.extend(lift_offs::lift_off_lines(&self.lift_offs));
        if let Some(r) = &self.replay {
            let cleaning = r.cleaning.iter().flat_map(|c| c.summary(5));
            out.extend(cleaning.map(|l| format!("  cleaning: {l}")));
            out.extend(r.cleaning.as_ref().and_then(replayed_piece));
            out.push(format!(
                "  {}",
                words::channels_trusted_for(&r.noise, words::Reader::Replay)
            ));
            out.extend(
                r.channels
                    .iter()
                    .map(|g| format!("  {}: {}", g.channel.name(), g.verdict)),
            );
        }
        out.extend(
            self.leftovers
                .lines("simulate")
                .into_iter()
                .map(|l| format!("  {l}")),
        );
        out
    }

    /// Writes the history, the metrics, the replay's gap and the figure.
    pub fn write(&self) -> Result<(), Error> {
        let files = FILES.map(|f| self.out_dir.join(f));
        // Nine significant digits: what a run integrated to a relative
        // tolerance of 1e-9 carries (17 wrote the arithmetic's noise).
        // Where the model rolls, `ay` as its accelerometer reads it: a
        // history read back as a measured run is levelled by its roll.
        let read = self.history.accelerometer_ay();
        let columns = self.history.written_columns(read.as_deref());
        write_columns_to(&files[0], &columns, Some(9))?;
        if let Some(m) = &self.metrics {
            let file = MetricsFile {
                scenario: &self.scenario,
                units: UNITS,
                metrics: m,
                lift_offs: &self.lift_offs,
                notes: &self.notes,
                warnings: &self.warnings,
                marks: m.marks(),
            };
            write_json(&files[1], &file)?;
        }
        if let Some(r) = &self.replay {
            write_json_sorted(&files[3], r)?;
        }
        let mut figure = history_figure(&self.scenario, &self.history, self.measured.as_ref());
        // A step's transient, not a pixel column of a long run.
        if let Some(m) = &self.metrics {
            transient::focus(&mut figure, &self.history, m.time_zero);
        }
        figure.save(&files[2])?;
        self.leftovers.remove()
    }
}

/// Steer, yaw rate, lateral acceleration and sideslip against time, with a
/// replayed run's measurements as dots under the model's line (a dashed
/// line through noisy samples reads as a smear; drawn over the line, the
/// dots hid it), in the pale tint the fit figures draw measured points in:
/// in full red, a thousand dots five pixels wide outweighed the model's
/// two-pixel line they lay under.
fn history_figure(name: &str, h: &TimeHistory, measured: Option<&MeasuredRun>) -> Figure {
    let deg = |v: &[f64]| v.iter().map(|x| x.to_degrees()).collect::<Vec<_>>();
    let panel = |title: &str, y_label: &str, label: &str, y: &[f64]| Panel {
        title: title.into(),
        x_label: "t [s]".into(),
        y_label: y_label.into(),
        series: vec![Series::line(label, &h.t, y, 0)],
        ..Panel::default()
    };
    let mut panels = vec![
        panel(
            &format!("{name}: front road-wheel steer"),
            "δ [deg]",
            "",
            &deg(&h.steer),
        ),
        panel("yaw rate", "r [deg/s]", "model", &deg(&h.yaw_rate)),
        panel("lateral acceleration", "ay [m/s²]", "model", &h.ay),
        panel("sideslip", "β [deg]", "model", &deg(&h.beta)),
    ];
    // A speed that changes (a schedule, a replay) drives the response: its
    // trace goes under the steer.
    let (lo, hi) = h
        .speed
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &u| (a.min(u), b.max(u)));
    let speed_varies = hi - lo > 1e-6 * hi.abs().max(1.0);
    if speed_varies {
        panels.insert(1, panel("forward speed", "u [m/s]", "", &h.speed));
    }
    if let Some(run) = measured {
        let k = usize::from(speed_varies);
        let add = |p: &mut Panel, y: &[f64]| {
            // First, so the model's line is drawn over the samples.
            p.series.insert(
                0,
                Series::line("measured", &run.t, y, 1)
                    .styled(MEASURED_DOTS)
                    .toned(Tone::Pale),
            );
        };
        add(&mut panels[1 + k], &deg(&run.yaw_rate));
        if let Some(ay) = &run.ay {
            add(&mut panels[2 + k], ay);
        }
        if let Some(b) = &run.beta {
            add(&mut panels[3 + k], &deg(b));
        }
    }
    Figure::stack(panels)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::plot::Style;

    /// A replayed run's samples are dots drawn first in each response
    /// panel (under the model's line), in every channel the run logs.
    #[test]
    fn the_models_line_is_drawn_over_the_measured_dots() {
        let t = vec![0.0, 0.1, 0.2];
        let h = TimeHistory {
            t: t.clone(),
            steer: vec![0.0; 3],
            speed: vec![20.0; 3],
            yaw_rate: vec![0.0, 0.1, 0.2],
            ay: vec![0.0, 1.0, 2.0],
            beta: vec![0.0; 3],
            ..TimeHistory::default()
        };
        let yaw_rate = vec![0.0, 0.11, 0.19];
        let run = MeasuredRun::new("run.csv", t, vec![20.0; 3], vec![0.0; 3], yaw_rate)
            .with_ay(vec![0.0, 1.1, 1.9]);
        let f = history_figure("replay", &h, Some(&run));
        let drawn: Vec<Vec<(&str, Style)>> = f
            .panels
            .iter()
            .map(|p| {
                p.series
                    .iter()
                    .map(|s| (s.label.as_str(), s.style))
                    .collect()
            })
            .collect();
        let over = [("measured", MEASURED_DOTS), ("model", Style::Line)];
        // The samples pale, the model's line full.
        let tones: Vec<Tone> = f.panels[1].series.iter().map(|s| s.tone).collect();
        assert_eq!(tones, [Tone::Pale, Tone::Full]);
        assert_eq!(drawn[1], over);
        assert_eq!(drawn[2], over);
        // No sideslip logged: the panel holds the model alone.
        assert_eq!(drawn[3], [("model", Style::Line)]);
        assert_eq!(f.panels.iter().map(|p| p.series.len()).sum::<usize>(), 6);
    }
}
