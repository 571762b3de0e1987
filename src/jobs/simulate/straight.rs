//! Straight running that needs a steer, and why: tyres that make lateral
//! force at zero slip (conicity, ply steer: a Magic Formula's `SHY`/`SVY`
//! shifts), or a road banked by `road_bank`, across which gravity pulls
//! the car with g·sin(bank) that its tyres must hold. A step steer starts
//! from the steer and sideslip that hold the car straight (its `trim`),
//! said as a note; a ramp, sine, sweep or schedule starts from zero steer
//! and sideslip, so the car drifts from the start, said as a warning with
//! the trim it would need. The cause is found by solving the trim again on
//! a flat road: what remains there is the tyres'.
//!
//! Units: rad, m/s²; printed in degrees where a driver reads them.

use crate::constants::G;
use crate::io::Scenario;
use crate::manoeuvre::Manoeuvre;
use crate::vehicle::VehicleModel;

/// The straight-running steer or sideslip below which tyres are taken to
/// make no force at zero slip, rad (0.006°, below the smallest steer step
/// the metrics take, 0.01°).
const TRIM: f64 = 1e-4;

/// Why straight running needs a steer, in words (None: it needs none).
fn cause(sc: &Scenario, speed: f64, steer: f64, beta: f64) -> Option<String> {
    if steer.abs() <= TRIM && beta.abs() <= TRIM {
        return None;
    }
    let conicity = "the tyres make lateral force at zero slip (conicity, ply steer)";
    let bank = sc.model.options.effects.road_bank;
    if bank == 0.0 {
        return Some(conicity.to_string());
    }
    let banked = format!(
        "the road is banked {} rad ({}°, `road_bank`): gravity pulls the car toward its lower edge with g·sin(bank) = {} m/s², which the tyres hold",
        crate::format::exact(bank),
        crate::format::fixed(bank.to_degrees(), 2),
        crate::format::fixed(G * bank.sin().abs(), 3)
    );
    let mut flat: VehicleModel = sc.model.clone();
    flat.options.effects.road_bank = 0.0;
    let on_flat = flat.straight_running(speed, sc.integrator.friction);
    match on_flat {
        Ok(t) if t.steer.abs() > TRIM || t.beta.abs() > TRIM => Some(format!(
            "{banked}, and {conicity}, which alone need {:.3}° of steer on a flat road",
            t.steer.to_degrees()
        )),
        _ => Some(banked),
    }
}

/// On a bank, what a step sized by `lateral_acceleration` reaches: the
/// change asked, from the trim's g·sin θ, as the metrics' steady ay reads
/// it, and what the accelerometer reads in the turn (empty elsewhere).
fn asked_change(sc: &Scenario) -> String {
    let (Some(ay), bank) = (sc.asked_ay, sc.model.bank_acceleration()) else {
        return String::new();
    };
    if bank == 0.0 {
        return String::new();
    }
    format!(
        "; `lateral_acceleration` = {} m/s² is such a change too, from the {} m/s² the accelerometer reads on the bank at straight running: the step turns the car to {} m/s² as the accelerometer reads it, and the metrics' steady ay is the {} m/s² change",
        crate::format::exact(ay),
        crate::format::fixed(bank, 3),
        crate::format::fixed(bank + ay, 3),
        crate::format::exact(ay)
    )
}

/// What is said of straight running: a fact of the run, or a doubt.
pub(super) enum Straight {
    /// A step steer's trim, where the run starts.
    Note(String),
    /// The drift of an input that starts from zero steer.
    Warning(String),
}

/// The step steer's trim as a note; for any other input that starts from
/// zero steer, the drift as a warning.
pub(super) fn straight_running(sc: &Scenario) -> Option<Straight> {
    if let Manoeuvre::StepSteer(s) = &sc.manoeuvre {
        if let Some(why) = cause(sc, s.speed, s.trim, sc.initial.beta) {
            return Some(Straight::Note(format!(
                "{why}: straight running needs a steer of {:.3}° and a sideslip of {:.3}°; the run starts there, the {:.3}° step is added to that steer, and the metrics measure changes from there ({}){}",
                s.trim.to_degrees(),
                sc.initial.beta.to_degrees(),
                s.amplitude.to_degrees(),
                crate::jobs::metrics::sideslip_is_its_change(sc.initial.beta),
                asked_change(sc)
            )));
        }
        return None;
    }
    // A replay of a measured run starts from the measured state.
    if sc.measured.is_some() {
        return None;
    }
    let speed = sc.manoeuvre.speed(sc.manoeuvre.start_time());
    let Ok(trim) = sc.model.straight_running(speed, sc.integrator.friction) else {
        return None;
    };
    let why = cause(sc, speed, trim.steer, trim.beta)?;
    Some(Straight::Warning(format!(
            "{why}: straight running at {speed:.1} m/s needs a steer of {:.3}° and a sideslip of {:.3}°, but this input starts from zero steer and sideslip, so the car drifts from the start; add the {:.3}° to the steer to start straight",
            trim.steer.to_degrees(),
            trim.beta.to_degrees(),
            trim.steer.to_degrees()
    )))
}
