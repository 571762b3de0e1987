//! A scenario speed that reads as km/h written as m/s: a step at
//! `speed = 80` (meant as ISO 7401's 80 km/h) ran at 288 km/h without a
//! word. Speeds are m/s; one a scenario states for a timed manoeuvre
//! (a step, ramp, sine or sweep's `speed`, a schedule's fastest) at or
//! above [`KMH_NOTE_SPEED`] (180 km/h) is run as written and said with
//! what it would be in km/h: a note, not a refusal (a fast car's run is
//! a run). Handling tests run well below it (ISO 7401's step steer and
//! ISO 3888's lane change at 80 km/h, ISO 4138's constant radius slower),
//! and any test speed from 50 km/h up written in km/h reaches it.
//!
//! An equilibrium sweep's speed axis given without a unit keeps the same
//! rule ([`kmh_note`], from `io::sweep`): its fastest value from
//! [`KMH_NOTE_SPEED`] up is noted, with the axis's `unit = "km/h"` as the
//! remedy (its phase portraits off the axis get their own km/h hint). A
//! replayed or campaign log's speed is read against its yaw rate and
//! lateral acceleration (`io::run_units`).
//!
//! Units: m/s; km/h only as said.

use crate::io::toml_file::{line_col, TomlSource};
use crate::manoeuvre::Manoeuvre;
use std::fmt;
use std::path::PathBuf;

/// The speed from which a scenario's speed is said in km/h as well, m/s
/// (180 km/h).
pub const KMH_NOTE_SPEED: f64 = 50.0;

/// A scenario speed at or above [`KMH_NOTE_SPEED`], where the file
/// states it.
#[derive(Debug, Clone, PartialEq)]
pub struct KmhSpeed {
    /// The scenario file.
    pub path: PathBuf,
    /// The key as the file writes it (`manoeuvre.speed`, or an element of
    /// a schedule's).
    pub key: String,
    /// 1-based line and column of its value (0, 0 where not found).
    pub at: (usize, usize),
    /// The speed, m/s.
    pub speed: f64,
    /// What states it: a manoeuvre, or a sweep's axis.
    pub stated_by: KmhStatedBy,
}

/// What states a speed noted in km/h: its remedy differs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KmhStatedBy {
    /// A scenario's manoeuvre: the run is at it.
    Manoeuvre,
    /// An equilibrium sweep's speed axis, given without a unit: the
    /// equilibria are solved at it; the axis takes `unit = "km/h"`.
    SweepAxis,
}

/// The note on speed `speed` (m/s) that `src` states at `key`, where at or
/// above [`KMH_NOTE_SPEED`]: the one rule for every speed a file states.
pub(crate) fn kmh_note(
    src: &TomlSource,
    key: &str,
    speed: f64,
    stated_by: KmhStatedBy,
) -> Option<KmhSpeed> {
    if speed.is_nan() || speed < KMH_NOTE_SPEED {
        return None;
    }
    let at = src
        .key_span(key)
        .map_or((0, 0), |span| line_col(&src.text, span.start));
    Some(KmhSpeed {
        path: src.path.clone(),
        key: key.to_string(),
        at,
        speed,
        stated_by,
    })
}

/// The fastest speed manoeuvre `m` states, where at or above
/// [`KMH_NOTE_SPEED`]; a replay of a measured run (`replayed`) states
/// none (its log's speeds are read as a log's).
pub(super) fn kmh_speed(src: &TomlSource, m: &Manoeuvre, replayed: bool) -> Option<KmhSpeed> {
    if replayed {
        return None;
    }
    let (key, speed) = match m {
        // A schedule: its fastest breakpoint, the element named.
        Manoeuvre::Replay(r) => {
            let (i, v) = r
                .speed
                .iter()
                .copied()
                .enumerate()
                .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
            (format!("manoeuvre.speed[{i}]"), v)
        }
        m => ("manoeuvre.speed".to_string(), m.speed(0.0)),
    };
    kmh_note(src, &key, speed, KmhStatedBy::Manoeuvre)
}

/// `v` to two decimals, trailing zeros dropped (288, 22.22).
fn short(v: f64) -> String {
    let s = format!("{v:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

impl fmt::Display for KmhSpeed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let place = match self.at {
            (0, _) => self.path.display().to_string(),
            (line, col) => format!("{}:{line}:{col}", self.path.display()),
        };
        let v = short(self.speed);
        let (done, remedy) = match self.stated_by {
            KmhStatedBy::Manoeuvre => ("the run is at", format!("write {}", short(self.speed / 3.6))),
            KmhStatedBy::SweepAxis => (
                "the equilibria are solved at",
                "give the axis `unit = \"km/h\"` (`speed = { values = [...], unit = \"km/h\" }`, or a range's `unit`)".to_string(),
            ),
        };
        write!(
            f,
            "{place}: `{}`: speed = {v} m/s is {} km/h; {v} km/h is {} m/s: speeds are in m/s, and handling tests run well below {} km/h (ISO 7401's step steer at 80 km/h), so {done} {v} m/s as written; if km/h was meant, {remedy}",
            self.key,
            short(3.6 * self.speed),
            short(self.speed / 3.6),
            short(3.6 * KMH_NOTE_SPEED),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manoeuvre::{Manoeuvre, StepSteer};

    fn source(text: &str) -> TomlSource {
        TomlSource {
            path: PathBuf::from("s.toml"),
            text: text.into(),
        }
    }

    fn step(speed: f64) -> Manoeuvre {
        Manoeuvre::StepSteer(StepSteer {
            speed,
            amplitude: 0.01,
            trim: 0.0,
            start: 1.0,
            rise_time: 0.1,
            end: 6.0,
        })
    }

    #[test]
    fn a_speed_from_180_kmh_is_said_in_kmh_too() {
        let src = source("[manoeuvre]\nkind = \"step-steer\"\nspeed = 80.0\n");
        let said = kmh_speed(&src, &step(80.0), false).unwrap().to_string();
        assert_eq!(
            said,
            "s.toml:3:9: `manoeuvre.speed`: speed = 80 m/s is 288 km/h; 80 km/h is 22.22 m/s: speeds are in m/s, and handling tests run well below 180 km/h (ISO 7401's step steer at 80 km/h), so the run is at 80 m/s as written; if km/h was meant, write 22.22"
        );
        // At the threshold it is said, below it not; a replay states none.
        assert!(kmh_speed(&src, &step(50.0), false).is_some());
        assert_eq!(kmh_speed(&src, &step(49.99), false), None);
        assert_eq!(kmh_speed(&src, &step(80.0), true), None);
    }
}
