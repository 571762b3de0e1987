//! A step steer as a scenario file gives it (`kind = "step-steer"`): its
//! keys, their defaults, and which of its two amplitudes is given.

use crate::error::{InputError, Limit, ParamError, ParamReason};
use crate::io::limits::{run_start, speed};
use crate::io::toml_file::{param_error, TomlSource};
use crate::vehicle::VehicleModel;
use serde::Deserialize;

/// Step steer as written in a file: the amplitude is either a steer angle or
/// the steady lateral acceleration it must produce (GB/T 6323: 2 m/s²).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepSteerSpec {
    /// Forward speed, m/s.
    pub speed: f64,
    /// Steer step, rad, from the straight-running steer.
    #[serde(default)]
    pub steer: Option<f64>,
    /// Steady lateral acceleration to reach from straight running, m/s²
    /// (sign gives the direction).
    #[serde(default)]
    pub lateral_acceleration: Option<f64>,
    /// Time the steer starts, s.
    #[serde(default = "default_start")]
    pub start: f64,
    /// 0–100 % rise time of the linear steer ramp, s (ISO 7401: 10–90 %
    /// within 0.15 s, so at most 0.1875 s; GB/T 6323: at most 0.2 s).
    #[serde(default = "default_rise")]
    pub rise_time: f64,
    /// End of the run, s.
    #[serde(default = "default_end")]
    pub end: f64,
}

fn default_start() -> f64 {
    1.0
}
/// Longest 0–100 % steer ramp a step steer may have, inclusive: ISO 7401
/// asks for the steer to go from 10 % to 90 % within 0.15 s, 0.8 of a
/// linear ramp, so 0.1875 s. Written as the number itself (3/16, exact in
/// binary): `0.15 / 0.8` is 0.18749999999999997 in `f64`, which refused
/// the `rise_time = 0.1875` the message and the book say is allowed.
pub(crate) const MAX_RAMP_TIME: f64 = 0.1875;

fn default_rise() -> f64 {
    0.1
}
fn default_end() -> f64 {
    6.0
}

/// The one amplitude a step steer is given.
pub(crate) enum Amplitude {
    /// `steer`, rad.
    Steer(f64),
    /// `lateral_acceleration`, m/s².
    LateralAcceleration(f64),
}

impl StepSteerSpec {
    /// The amplitude given, from `src`. Both given is refused at the later
    /// of the two in the file, the key that makes it two; neither, at the
    /// manoeuvre's `kind`, as no key holds what is missing.
    pub(crate) fn amplitude(&self, src: &TomlSource) -> Result<Amplitude, InputError> {
        let e = match (self.steer, self.lateral_acceleration) {
            (Some(d), None) => return Ok(Amplitude::Steer(d)),
            (None, Some(ay)) => return Ok(Amplitude::LateralAcceleration(ay)),
            (None, None) => ParamError::without_value("kind", ParamReason::StepSteerNoAmplitude),
            (Some(d), Some(ay)) => {
                let at = |k: &str| src.key_span(&format!("manoeuvre.{k}")).map(|s| s.start);
                let (key, v) = if at("steer") > at("lateral_acceleration") {
                    ("steer", d)
                } else {
                    ("lateral_acceleration", ay)
                };
                ParamError::new(key, v, ParamReason::StepSteerBothAmplitudes)
            }
        };
        Err(param_error(src, Some("manoeuvre"), e))
    }

    /// Its timing, refused at the first key out of its range: a speed, a
    /// start in the run, a rise time within ISO 7401's
    /// ([`MAX_RAMP_TIME`]), and an end that leaves 2 s to settle after
    /// the ramp.
    pub(super) fn timing(&self) -> Result<(), ParamError> {
        speed(self.speed)?;
        run_start(self.start)?;
        ParamError::in_range(
            "rise_time",
            self.rise_time,
            -1e-12,
            MAX_RAMP_TIME,
            Limit::RampTime,
        )?;
        ParamError::in_range(
            "end",
            self.end,
            self.start + self.rise_time + 2.0,
            crate::constants::LONGEST_RUN,
            Limit::SettleTime,
        )
    }
}

/// A steady `lateral_acceleration`: finite, and one the car holds on four
/// wheels: at or beyond its rollover threshold g·t/(2h) it is refused at
/// its key ([`crate::error::Rollover`]), as the 2-DOF model would simulate
/// it as if the inner wheels stayed down.
pub(super) fn steady_ay(ay: f64, model: &VehicleModel) -> Result<(), ParamError> {
    ParamError::finite("lateral_acceleration", ay)?;
    let v = &model.vehicle;
    let r = crate::error::Rollover::of(v.track_front, v.track_rear, v.cg_height);
    match r.reached_by(ay) {
        true => Err(ParamError::new(
            "lateral_acceleration",
            ay,
            ParamReason::from(r),
        )),
        false => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use crate::error::{InputError, ParamReason};
    use std::path::Path;

    /// The bundled PAC89 step on a road banked 0.05 rad, asked for 12 m/s²
    /// (the tyres' 12 + g·sin θ is past their limit, short of rollover).
    fn banked_step_past_the_limit() -> InputError {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(root.join("scenarios/step_gbt6323_pac89.toml"))
            .unwrap()
            .replace("\"../tyres/", &format!("\"{}/tyres/", root.display()))
            .replace(
                "load_transfer = true",
                "load_transfer = true\neffects = { road_bank = 0.05 }",
            )
            .replace(
                "lateral_acceleration = 2.0 ",
                "lateral_acceleration = 12.0 ",
            );
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("banked.toml");
        std::fs::write(&path, text).unwrap();
        match crate::io::load_scenario(&path) {
            Ok(_) => panic!("a step past the limit was read"),
            Err(e) => e,
        }
    }

    #[test]
    fn a_banked_steps_refusal_keeps_the_tyres_ay_whole_and_says_it_to_six_digits() {
        let e = banked_step_past_the_limit();
        let InputError::Value { source, .. } = &e else {
            panic!("{e}")
        };
        let ParamReason::NoSteadyState(m) = &source.reason else {
            panic!("{e}")
        };
        // The data: the change asked plus the bank's pull, every digit.
        let ay = 12.0 + 9.80665 * 0.05f64.sin();
        assert!((m.ay - ay).abs() < 1e-12, "{} vs {ay}", m.ay);
        assert_ne!(m.ay, 12.4901, "the field rounded");
        // The sentence: six significant digits.
        let said = e.to_string();
        assert!(said.contains("with ay = 12.4901 m/s²:"), "{said}");
        assert!(m.to_string().contains("with ay = 12.4901 m/s²:"), "{m}");
    }
}
