//! What a log's sample interval limits in the step-steer metrics, said
//! where it does, with the bias measured for the kind of step the log
//! holds: a steer rise within one sample interval (the step is faster
//! than the log: a 1 ms step at 100 Hz read "rise 0.008 s"; its onset, and
//! every time from it, known to half an interval), a response time within
//! two (its crossing interpolated between samples that far apart), and the
//! total variances of a log of 12.5 Hz or slower or of a step inside one
//! interval, biased by where the samples fall on the step.
//!
//! The biases are measured on the tester's linear 2-DOF car (1530 kg,
//! 2315 kg·m², a = 1.11 m, b = 1.67 m, linear tyres of 57 296 N/rad per
//! wheel, no load transfer) stepped by 0.01 rad at 25 m/s, simulated at
//! 1 kHz and logged at each rate from 200 placings of the step between
//! samples (the 1 kHz rows interpolated at 200 offsets; the test in
//! `coarse_tables.rs` reruns it and asserts the tables), read by
//! `metrics` as a user runs it (its 10 Hz low-pass on logs of 25 Hz and
//! faster), against the closed form (which `simulate`'s own metrics of the
//! same step match to four digits): the instant step's yaw-rate response
//! time 0.158 s, E_r 0.0442 s, E_ay 0.0476 s; the step ramped over 0.1 s,
//! 0.163 s, 0.0304 s and 0.0428 s. An instant step's error is set by where
//! it falls between samples: at 10 Hz E_r reads −77 % to +142 %, and the
//! tester's 12.5 Hz log, one placing, −13 %. Units: s, Hz, %.

use crate::metrics::StepMetrics;

/// The sample interval from which the total variances of a step the log
/// resolves are said, s: 12.5 Hz, where a ramped step's E_r reads up to
/// 17 % off ([`RAMPED`]; within 10 % at 20 Hz and faster).
pub const VARIANCE_COARSE: f64 = 0.08;

/// How many sample intervals a response time must span to be given
/// without its resolution.
pub const RESPONSE_INTERVALS: f64 = 2.0;

/// The least and largest reading over the 200 placings of the step, % of
/// the closed form.
type Range = (f64, f64);

/// One log rate's measured biases.
#[derive(Debug, Clone, Copy)]
pub struct Bias {
    /// The log's rate, Hz.
    pub hz: f64,
    /// The yaw-rate response time's.
    pub response: Range,
    /// E_r's.
    pub e_r: Range,
    /// E_ay's.
    pub e_ay: Range,
}

/// A measured step of the linear car: its name, the closed form's
/// yaw-rate response time, E_r and E_ay (s), and its biases by log rate,
/// fastest first.
pub struct StepKind {
    /// What the step is.
    pub name: &'static str,
    /// The closed form's yaw-rate response time, E_r and E_ay, s.
    pub exact: (f64, f64, f64),
    /// The biases, fastest log first.
    pub rows: [Bias; 7],
}

const fn bias(hz: f64, response: Range, e_r: Range, e_ay: Range) -> Bias {
    Bias {
        hz,
        response,
        e_r,
        e_ay,
    }
}

/// The instant step (the tester's `rise_time = 0`).
pub const INSTANT: StepKind = StepKind {
    name: "instant step",
    exact: (0.158, 0.0442, 0.0476),
    rows: [
        bias(100.0, (-2.0, 3.0), (-23.0, -5.0), (-5.0, -1.0)),
        bias(50.0, (-5.0, 7.0), (-31.0, 7.0), (-8.0, 2.0)),
        bias(20.0, (-13.0, 17.0), (-47.0, 63.0), (-13.0, 10.0)),
        bias(12.5, (-24.0, 26.0), (-67.0, 109.0), (-21.0, 15.0)),
        bias(10.0, (-23.0, 40.0), (-77.0, 142.0), (-27.0, 17.0)),
        bias(7.0, (-34.0, 55.0), (-91.0, 222.0), (-41.0, 23.0)),
        bias(5.0, (-37.0, 79.0), (-98.0, 339.0), (-60.0, 35.0)),
    ],
};

/// The step ramped over 0.1 s.
pub const RAMPED: StepKind = StepKind {
    name: "step ramped over 0.1 s",
    exact: (0.163, 0.0304, 0.0428),
    rows: [
        bias(100.0, (0.0, 0.0), (-2.0, -1.0), (0.0, 0.0)),
        bias(50.0, (0.0, 0.0), (-2.0, 0.0), (0.0, 0.0)),
        bias(20.0, (0.0, 2.0), (-5.0, 7.0), (-1.0, 2.0)),
        bias(12.5, (1.0, 5.0), (-10.0, 17.0), (-3.0, 5.0)),
        bias(10.0, (-3.0, 14.0), (-19.0, 27.0), (-6.0, 8.0)),
        bias(7.0, (2.0, 22.0), (-52.0, 72.0), (-15.0, 21.0)),
        bias(5.0, (-29.0, 58.0), (-87.0, 138.0), (-34.0, 39.0)),
    ],
};

impl StepKind {
    /// The row of a log at `hz`: the fastest measured rate at or below it
    /// (a slower log is biased at least as much), the slowest for a log
    /// slower than every row.
    pub fn row(&self, hz: f64) -> &Bias {
        self.rows
            .iter()
            .find(|b| b.hz <= hz * (1.0 + 1e-3))
            .unwrap_or(&self.rows[self.rows.len() - 1])
    }
}

/// A range of readings as words: "from −71 % to +181 %".
fn range(r: Range) -> String {
    let pc = |x: f64| match x {
        0.0 => "0 %".to_string(),
        x => format!("{x:+} %").replace('-', "−"),
    };
    match r.0 == r.1 {
        true if r.0 == 0.0 => "within 0.5 %".to_string(),
        true => format!("{} (within 0.5 %)", pc(r.0)),
        false => format!("from {} to {}", pc(r.0), pc(r.1)),
    }
}

/// Within this share of the closed form (%) a table's rate reads the
/// response time at every placing: the rate advised to read it finer.
const RESPONSE_WITHIN: f64 = 10.0;

/// The ramp of [`RAMPED`], s: a log whose sample interval is as long can
/// not tell it from an instant step, for at some placings the whole ramp
/// falls between two samples (at 10 Hz, 46 of 200 placings read its rise
/// under one interval, as an instant step's), and at others a sample on
/// it reads a rise an instant step never shows only by chance.
const RAMP: f64 = 0.1;

/// The slowest rate of `kind`'s table that reads the response time within
/// [`RESPONSE_WITHIN`] at every placing (none: no rate does).
fn within(kind: &StepKind) -> Option<&Bias> {
    let ok =
        |b: &&Bias| b.response.0.abs() <= RESPONSE_WITHIN && b.response.1.abs() <= RESPONSE_WITHIN;
    kind.rows.iter().rev().find(ok)
}

/// The step whose table the advice of a log at `hz` is read from: `kind`,
/// the shape its steer reads; but a log too coarse to tell [`RAMPED`] from
/// [`INSTANT`] (its interval as long as the ramp) reads one or the other by
/// where its samples fall, so it is advised by the stricter of the two
/// (the one that needs the faster log), the same at every placing, and
/// says so.
fn advised_kind(kind: &StepKind, hz: f64) -> (&StepKind, Option<String>) {
    if 1.0 / hz < RAMP * (1.0 - 1e-6) {
        return (kind, None);
    }
    let need = |k: &StepKind| within(k).map_or(f64::INFINITY, |b| b.hz);
    let stricter = match need(&INSTANT) >= need(&RAMPED) {
        true => &INSTANT,
        false => &RAMPED,
    };
    let note = format!(
        "; a {} Hz log cannot tell a step ramped over {RAMP} s from an instant one (at some placings the whole ramp falls between two samples), so the advice is the stricter one, the {}'s",
        crate::format::rounded(hz, 3),
        stricter.name
    );
    (stricter, Some(note))
}

/// The rate advice for a response time of a log at `hz` holding a step
/// of `kind`: the slowest rate of the table that reads it within
/// [`RESPONSE_WITHIN`] at every placing. From the step and the table, not
/// from the time read: that moves with where the samples fall (a 7 Hz
/// log was told "log at 9 Hz or faster" at one placing and "at 11 Hz" at
/// the next, and at 10 Hz an instant step still reads −23 … +40 %); and
/// on a log too coarse to tell the tables' steps apart, from the stricter
/// ([`advised_kind`]: a 10 Hz log of the ramped step was advised 12.5 Hz
/// at one placing and 50 Hz at the next).
fn finer(kind: &StepKind, hz: f64) -> String {
    let (kind, note) = advised_kind(kind, hz);
    let note = note.unwrap_or_default();
    match within(kind) {
        Some(b) if b.hz > hz * (1.0 + 1e-3) => format!(
            "log at {} Hz or faster to read it finer (the {} read it {} there){note}",
            b.hz,
            kind.name,
            range(b.response)
        ),
        Some(_) => format!(
            "at this rate the table's logs read it within {RESPONSE_WITHIN} % at every placing of the step"
        ),
        None => format!(
            "no rate of the table reads it within {RESPONSE_WITHIN} % at every placing of the step{note}"
        ),
    }
}

/// What the row of `kind` at `hz` is: "the linear car's instant step
/// (…), logged at 10 Hz".
fn measured_at(kind: &StepKind, b: &Bias) -> String {
    format!(
        "the linear car's 0.01 rad {} at 25 m/s (closed form: yaw-rate response time {} s, E_r {} s, E_ay {} s), logged at {} Hz with the step at 200 placings between samples,",
        kind.name,
        kind.exact.0,
        kind.exact.1,
        kind.exact.2,
        b.hz
    )
}

/// Withholds an ay response time the log cannot read: where the steer
/// steps within one sample interval `dt` (its 10–90 % rise `steer_rise`
/// under `dt`, s) and `ay` is at 90 % at the first sample after it (a car
/// whose front force follows the steer at once), both crossings fall in
/// the step's one interval and the time read is where the samples fall
/// (+dt/2 from time zero, interpolated half-way, to the sample after):
/// it printed "0.000 s". Said below `dt` instead, in the table and the
/// JSON alike ([`StepMetrics::ay_response_time_below`]).
pub fn withhold_unresolved(m: &mut StepMetrics, dt: f64, steer_rise: f64) {
    if !(dt.is_finite() && dt > 0.0 && steer_rise < dt) {
        return;
    }
    if m.ay_response_time.is_some_and(|t| t.abs() < dt) {
        m.ay_response_time = None;
        m.ay_response_time_below = Some(dt);
    }
}

/// The warnings of what the sample interval `dt` (s) limits in `m`, with
/// the steer's 10–90 % rise `steer_rise` (s).
pub fn coarse_said(m: &StepMetrics, dt: f64, steer_rise: f64) -> Vec<String> {
    let mut said = Vec::new();
    if !(dt.is_finite() && dt > 0.0) {
        return said;
    }
    let hz = crate::format::rounded(1.0 / dt, 3);
    let interval = crate::format::rounded(dt, 3);
    // A step inside one interval has its onset known only to about half
    // an interval, and every time measured from it carries that.
    let unresolved = steer_rise < dt;
    let kind = if unresolved { &INSTANT } else { &RAMPED };
    let row = kind.row(1.0 / dt);
    if unresolved {
        said.push(format!(
            "the steer's 10–90 % rise reads {} s, within one {interval} s sample interval of a {hz} Hz log: the step is faster than the log resolves, and its rise is only known to be under {interval} s; its onset, and every time measured from it (response times, peak time, E_r, E_ay), is uncertain by about half an interval, ±{} s, and the crossings after it by their interpolation between samples ({} read its yaw-rate response time {} of the closed form)",
            crate::format::fixed(steer_rise, 3),
            crate::format::rounded(dt / 2.0, 3),
            measured_at(kind, row),
            range(row.response)
        ));
    }
    let times = [
        ("yaw-rate", Some(m.yaw_rate_response_time)),
        ("ay", m.ay_response_time),
    ];
    for (name, t) in times {
        // A time at or below 0 is no lag to resolve: the table marks it
        // "(before the steer)" and the noise or the lead is said.
        let Some(t) = t.filter(|t| *t > 0.0 && *t < RESPONSE_INTERVALS * dt) else {
            continue;
        };
        said.push(format!(
            "the {name} response time, {} s, spans {} sample intervals of a {hz} Hz log: a crossing interpolated between samples {interval} s apart is limited by the sample interval ({} read the yaw-rate response time {} of the closed form); {}",
            crate::format::fixed(t, 3),
            crate::format::rounded(t / dt, 2),
            measured_at(kind, row),
            range(row.response),
            finer(kind, 1.0 / dt)
        ));
    }
    if m.ay_response_time_below.is_some() {
        said.push(format!(
            "the ay reaches 90 % of its step at the first sample after the steer's step, within the one {interval} s interval the steer steps in: its response time is only known to be under {interval} s (`ay_response_time` null, `ay_response_time_below` {interval} in --json), not read from a {hz} Hz log; ramp the step over a few intervals, or log faster, to read it"
        ));
    }
    // The median interval of a log may read a hair under its period.
    let coarse = dt >= VARIANCE_COARSE * (1.0 - 1e-6);
    if coarse || unresolved {
        let ay = m.ay_total_variance.is_some();
        // The advice fits the log: a 50 Hz log of an unresolved step was
        // told to log at 20 Hz or faster, which it already did.
        let advice = match coarse {
            true => "log at 20 Hz or faster, and ramp the step over a few intervals, to compare them",
            false => "here the step, rising within one interval, not the log's rate, causes it: ramp the step over a few intervals to compare them",
        };
        said.push(format!(
            "E_r{} are integrals over samples {interval} s apart ({hz} Hz){}: they are biased by where the samples fall on the step ({} read E_r {}{}): {advice}",
            if ay { ", E_ay and Er" } else { "" },
            match unresolved {
                true => ", of a step faster than one interval",
                false => ", a log of 12.5 Hz or slower",
            },
            measured_at(kind, row),
            range(row.e_r),
            match ay {
                true => format!(" and E_ay {}", range(row.e_ay)),
                false => String::new(),
            }
        ));
    }
    said
}

#[cfg(test)]
#[path = "coarse_tables.rs"]
mod tables;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_log_reads_the_row_of_the_fastest_rate_at_or_below_its_own() {
        assert_eq!(INSTANT.row(10.0).hz, 10.0);
        assert_eq!(INSTANT.row(9.99).hz, 7.0);
        assert_eq!(INSTANT.row(12.5).hz, 12.5);
        assert_eq!(INSTANT.row(1000.0).hz, 100.0);
        assert_eq!(INSTANT.row(3.0).hz, 5.0);
        assert_eq!(range((-71.0, 181.0)), "from −71 % to +181 %");
        assert_eq!(range((0.0, 0.0)), "within 0.5 %");
    }
}
