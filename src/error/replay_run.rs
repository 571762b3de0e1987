//! A replay scenario's run refused for what the scenario's own keys
//! mend: its `[manoeuvre] min_speed` above the run's speeds, a steer the
//! run logs in degrees (`[manoeuvre] degrees`), a `degrees` entry naming a
//! column the run lacks. The refusals of the run read alone name
//! `metrics --min-speed` and `metrics --degrees`, which a scenario has
//! not; these name the scenario's keys and stand at them. m/s, rad.

use super::Num;
use std::fmt;

/// What is wrong, and the run file it is about.
#[derive(Debug, Clone, PartialEq)]
pub enum ReplayRunProblem {
    /// No two successive samples at or above `min_speed`.
    TooSlow {
        /// The run file, as the scenario names it.
        run: Box<str>,
        /// The replay's lowest speed, m/s.
        min_speed: f64,
        /// Whether the scenario states it (else the default).
        stated: bool,
        /// Samples below it, and samples read.
        slow: usize,
        /// Samples read.
        read: usize,
        /// The run's top speed, m/s.
        top: f64,
    },
    /// A steer far larger than the yaw rate it gives: in degrees, or a
    /// steering-wheel angle.
    SteerAboveYaw {
        /// The run file.
        run: Box<str>,
        /// Median of r·l/(u·δ) over the steered samples.
        median: f64,
        /// The steered samples.
        samples: usize,
        /// The limit where the speed lowered it (`least_gain.rs`).
        at_speed: Option<super::LimitAtSpeed>,
    },
    /// A `degrees` entry naming a steer or yaw rate the run logs in
    /// radians: the yaw rate then reads 57× off a neutral car's for its
    /// steer (smaller for a yaw rate, larger for a steer).
    DeclaredInDegrees {
        /// The run file.
        run: Box<str>,
        /// The column declared (`steer` or `yaw_rate`).
        column: &'static str,
        /// Median of r·l/(u·δ) over the steered samples, as declared.
        median: f64,
        /// The steered samples.
        samples: usize,
    },
    /// An angle column the run logs in degrees (its size or its ratio to
    /// `ay` says so), refused at the scenario's `run`: `detail` is the run
    /// reader's refusal, whose advice names this scenario's key (the
    /// reader was told it reads for a replay).
    InDegrees {
        /// The run file.
        run: Box<str>,
        /// The row and column of the run file it was seen at (`115:4`).
        at: Box<str>,
        /// The angle column (`steer`, `yaw_rate`).
        column: &'static str,
        /// The run reader's refusal.
        detail: Box<str>,
    },
    /// A `degrees` entry naming a column the run does not have.
    DegreesAbsent {
        /// The run file.
        run: Box<str>,
        /// The column declared.
        column: &'static str,
        /// The run's columns.
        header: Vec<String>,
    },
}

impl fmt::Display for ReplayRunProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReplayRunProblem::TooSlow { run, min_speed, stated, slow, read, top } => {
                let default = if *stated { "" } else { " (the default)" };
                write!(
                    f,
                    "the run {run} has no two successive samples at or above the replay's min_speed = {} m/s{default} ({slow} of {read} samples below it; its top speed is {} m/s): ",
                    Num(*min_speed),
                    crate::format::readable(*top, 3)
                )?;
                match *top > 0.0 {
                    true => write!(
                        f,
                        "set `min_speed` under [manoeuvre] below its top speed to replay it (a crawl's slip angles are large and its response no handling's)"
                    ),
                    false => f.write_str("the run stands still throughout: there is nothing to replay"),
                }
            }
            ReplayRunProblem::SteerAboveYaw { run, median, samples, at_speed } => write!(
                f,
                "the run {run}: the yaw rate is {} than a neutral car's for this steer (median r·l/(u·δ) = {} over {samples} steered samples{}): is `steer` in degrees (57×) or a steering-wheel angle (divide by the steering ratio), or `yaw_rate` declared in degrees while it was in rad/s? The steer is the road-wheel angle in radians; a column the run logs in degrees is declared so in this scenario: `degrees = [\"steer\"]` under [manoeuvre]",
                match *median > 0.0 {
                    true => format!("{}× smaller", crate::format::readable(1.0 / median, 2)),
                    false => "far smaller".into(),
                },
                // 0.0004 is not "0.000" beside "2500× smaller".
                crate::format::fixed_apart(&[*median], 3)[0],
                at_speed.map_or(String::new(), |a| format!("; refused {a}"))
            ),
            ReplayRunProblem::DeclaredInDegrees { run, column, median, samples } => {
                let (what, unit) = match *column {
                    "steer" => ("a steer in radians read as degrees makes it 57× larger", "radians"),
                    _ => ("a yaw rate in rad/s read as deg/s makes it 57× smaller", "rad/s"),
                };
                write!(
                    f,
                    "`manoeuvre.degrees` declares `{column}` in degrees: so read, the run {run}'s yaw rate is {} a neutral car's for its steer (median r·l/(u·δ) = {} over {samples} steered samples), as {what}: the run logs `{column}` in {unit}; take `\"{column}\"` out of `degrees` under [manoeuvre]",
                    match *median < 1.0 {
                        true => format!("{}× smaller than", crate::format::significant(1.0 / median.max(1e-9), 2)),
                        false => format!("{}×", crate::format::significant(*median, 2)),
                    },
                    crate::format::significant(*median, 3)
                )
            }
            ReplayRunProblem::InDegrees { run, at, detail, .. } => {
                write!(f, "the run {run}, at {at}: {detail}")
            }
            ReplayRunProblem::DegreesAbsent { run, column, header } => {
                write!(
                    f,
                    "`manoeuvre.degrees` names `{column}`, a column the run {run} does not have (its columns: {})",
                    header.join(", ")
                )?;
                let names: Vec<&str> = header.iter().map(String::as_str).collect();
                match crate::format::nearest_name(column, &names) {
                    Some(k) => write!(f, "; did you mean `{k}`? Rename the run's column to `{column}`"),
                    None => f.write_str("; leave it out, or name a column the run has"),
                }
            }
        }
    }
}
