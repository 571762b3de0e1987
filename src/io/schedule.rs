//! A manoeuvre given as a schedule (`kind = "schedule"` in a scenario's
//! `[manoeuvre]`): steer and speed at breakpoints, linear between them —
//! the form `handling design` writes its manoeuvres in — and the checks
//! that refuse a bad one at its element. Units: s, rad, m/s.

use super::limits::{road_wheel_steer, speed};
use crate::error::{ParamError, ParamReason, ScheduleColumn};
use serde::Deserialize;

/// Steer and speed given at breakpoints and linear between them, held
/// after the last: the run starts from straight running at its first
/// speed, so its first steer is normally 0.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleSpec {
    /// Breakpoint times, s, strictly increasing; the run ends at the last.
    pub t: Vec<f64>,
    /// Front road-wheel steer at each, rad.
    pub steer: Vec<f64>,
    /// Forward speed at each, m/s.
    pub speed: Vec<f64>,
}

/// A schedule's columns: equal lengths, times finite and increasing, each
/// speed and steer within the manoeuvres' limits, refused at the element.
pub(super) fn check(s: &ScheduleSpec) -> Result<(), ParamError> {
    let columns = [
        (ScheduleColumn::T, s.t.len()),
        (ScheduleColumn::Steer, s.steer.len()),
        (ScheduleColumn::Speed, s.speed.len()),
    ];
    // The first of the shortest and of the longest: a short column is
    // refused at its own key, with the length it falls short of.
    let short = columns
        .iter()
        .fold(columns[0], |a, &c| if c.1 < a.1 { c } else { a });
    let long = columns
        .iter()
        .fold(columns[0], |a, &c| if c.1 > a.1 { c } else { a });
    if short.1 < long.1 {
        let reason = ParamReason::ScheduleLengths {
            len: short.1,
            longest: long.0,
            longest_len: long.1,
        };
        return Err(ParamError::without_value(&short.0.to_string(), reason));
    }
    if short.1 < 2 {
        let reason = ParamReason::ScheduleTooShort { len: short.1 };
        return Err(ParamError::without_value("t", reason));
    }
    for (i, w) in s.t.iter().enumerate() {
        let at = |key: &str| format!("{key}[{i}]");
        ParamError::finite(&at("t"), *w)?;
        if i > 0 && *w <= s.t[i - 1] {
            let before = s.t[i - 1];
            return Err(ParamError::new(
                &at("t"),
                *w,
                ParamReason::ScheduleTime { before },
            ));
        }
        ParamError::finite(&at("steer"), s.steer[i])?;
        road_wheel_steer(&at("steer"), s.steer[i])?;
        speed(s.speed[i]).map_err(|e| ParamError::new(&at("speed"), s.speed[i], e.reason))?;
    }
    Ok(())
}
