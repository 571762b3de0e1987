//! Why an error-controlled integration stalled, as `simulate` says it: a
//! step steer whose linearised car asks for a steady lateral acceleration
//! beyond what the car holds (its inner wheels lift off, or its tyres'
//! grip ends), near an oversteering car's critical speed or not; a large
//! steer; or neither known. A tester's 1° step at 30 m/s, 2 m/s under the
//! critical speed, asked for 43.7 m/s² and was said as "linear tyres at a
//! large steer". The linear steady state is the bicycle model's
//! (Milliken & Milliken 1995, ch. 5): yaw-rate gain `u/(l + K·u²)`,
//! lateral acceleration `u²·δ/(l + K·u²)`, `K` the understeer gradient.
//! On tyres with no grip limit (linear) the step the advice suggests keeps
//! the turn within the road's μ·g as well as on four wheels.
//! Units: SI and rad inside; printed in m/s, m/s², g and degrees.

use crate::constants::G;
use crate::format::{fixed, rounded, rounded_down, significant};
use std::fmt;

/// The road-wheel steer beyond which a steer is large, rad (10°): a
/// handling step steers a few degrees (ISO 7401 sizes it for 4 m/s²,
/// about 1–2° at 80 km/h), and at a step's start, before the car turns,
/// the front slip angle is the steer itself, past any tyre's peak (3–10°).
pub const LARGE_STEER: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// The gain of an oversteering car's steady yaw rate over the neutral
/// car's `u/l` from which its speed is said to be near the critical one:
/// twice, at `u = v_crit/√2`.
pub const NEAR_CRITICAL_GAIN: f64 = 2.0;

/// What ends the steady turn a step asks for: the lower of the two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TurnLimit {
    /// The inner wheels lift off (their static load all transferred),
    /// from this lateral acceleration, m/s².
    Lift(f64),
    /// The tyres' grip (the lower axle's friction at static load times
    /// g), m/s², and that friction coefficient.
    Grip(f64, f64),
}

impl TurnLimit {
    /// The lateral acceleration of the limit, m/s².
    pub fn ay(self) -> f64 {
        match self {
            TurnLimit::Lift(a) | TurnLimit::Grip(a, _) => a,
        }
    }
}

/// A step steer whose linear steady state lies beyond the car's limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AskedTurn {
    /// The step's speed, m/s.
    pub speed: f64,
    /// The step's steer (its change), rad, magnitude.
    pub steer: f64,
    /// The wheelbase l, m.
    pub wheelbase: f64,
    /// The understeer gradient K at the static axle loads, rad/(m/s²).
    pub gradient: f64,
    /// The limit the asked turn passes.
    pub limit: TurnLimit,
    /// The road's friction where a tyre has no grip limit of its own
    /// (linear) and its μ·g lies below the limit: the advice keeps the
    /// steady turn within it too (a step that only stays on four wheels
    /// ran at 1.39 g on linear tyres).
    pub road: Option<f64>,
}

impl AskedTurn {
    /// The steady lateral acceleration the step asks for, m/s²:
    /// `u²·δ/(l + K·u²)`.
    pub fn asked(&self) -> f64 {
        let u2 = self.speed * self.speed;
        u2 * self.steer / (self.wheelbase + self.gradient * u2)
    }

    /// The steady yaw-rate gain over the neutral car's, `l/(l + K·u²)`.
    pub fn gain_factor(&self) -> f64 {
        self.wheelbase / (self.wheelbase + self.gradient * self.speed * self.speed)
    }

    /// The oversteering car's critical speed √(−l/K), m/s, where the step
    /// is near it ([`NEAR_CRITICAL_GAIN`]).
    pub fn near_critical(&self) -> Option<f64> {
        (self.gradient < 0.0 && self.gain_factor() >= NEAR_CRITICAL_GAIN)
            .then(|| (-self.wheelbase / self.gradient).sqrt())
    }

    /// The largest steer whose steady state stays at the limit at this
    /// speed, rad: `A·(l + K·u²)/u²`.
    pub fn largest_steer(&self) -> f64 {
        self.steer_for(self.limit.ay())
    }

    /// The highest speed at which this steer's steady state stays at the
    /// limit, m/s: `√(A·l/(δ − A·K))`, from `u²·δ = A·(l + K·u²)`.
    pub fn highest_speed(&self) -> f64 {
        self.speed_for(self.limit.ay())
    }

    /// The steer whose steady lateral acceleration at this speed is `a`,
    /// m/s², rad.
    pub fn steer_for(&self, a: f64) -> f64 {
        let u2 = self.speed * self.speed;
        a * (self.wheelbase + self.gradient * u2) / u2
    }

    /// The speed at which this steer's steady lateral acceleration is `a`,
    /// m/s², m/s.
    pub fn speed_for(&self, a: f64) -> f64 {
        (a * self.wheelbase / (self.steer - a * self.gradient)).sqrt()
    }
}

/// Why the integration stalled, as far as the scenario tells.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StallCause {
    /// A step whose steady turn the car cannot hold.
    Asked(AskedTurn),
    /// A steer beyond [`LARGE_STEER`], rad (the step's, or the largest
    /// the run reached before it stalled).
    LargeSteer(f64),
    /// Nothing the scenario's numbers single out.
    Unknown,
}

impl StallCause {
    /// Why the step was driven towards zero, in the stall's sentence.
    pub fn cause(&self) -> String {
        const EITHER: &str =
            "a wheel lifting off under load transfer, or forces far beyond any tyre's";
        match self {
            StallCause::Asked(a) => match a.limit {
                TurnLimit::Lift(_) => "a wheel lifting off under load transfer: the step asks for a turn the car does not hold on four wheels".into(),
                TurnLimit::Grip(..) => "forces beyond the tyres' grip: the step asks for a turn the tyres do not give".into(),
            },
            StallCause::LargeSteer(steer) => format!(
                "{EITHER}, at a large steer: {}° of road-wheel steer, where a handling step steers a few degrees",
                fixed(steer.to_degrees(), 1)
            ),
            StallCause::Unknown => EITHER.into(),
        }
    }

    /// What keeps the car in the model's range, as a sentence.
    pub fn advice(&self) -> String {
        match self {
            StallCause::Asked(a) => a.to_string(),
            StallCause::LargeSteer(_) => {
                "A smaller steer keeps the car in the model's range".into()
            }
            StallCause::Unknown => "A smaller manoeuvre keeps the car in the model's range".into(),
        }
    }
}

impl fmt::Display for AskedTurn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let asked = self.asked();
        let k = significant(self.gradient, 3);
        let head = match self.near_critical() {
            Some(critical) => format!(
                "At {} m/s the car runs near its critical speed √(−l/K) = {} m/s (it oversteers: understeer gradient K = {k} rad/(m/s²) from the tyres' cornering stiffness at the static axle loads), where its steady yaw-rate gain u/(l + K·u²) is {} times the neutral car's u/l, so the",
                fixed(self.speed, 1),
                fixed(critical, 1),
                significant(self.gain_factor(), 2)
            ),
            None => format!(
                "At {} m/s (understeer gradient K = {k} rad/(m/s²) from the tyres' cornering stiffness at the static axle loads) the",
                fixed(self.speed, 1)
            ),
        };
        let limit = match self.limit {
            TurnLimit::Lift(a) => format!(
                "the {} m/s² ({} g) from which the inner wheels lift off (their static load all transferred to the outer wheels)",
                fixed(a, 1),
                fixed(a / G, 2)
            ),
            TurnLimit::Grip(a, mu) => format!(
                "the {} m/s² ({} g) the tyres' grip gives (friction {} at the static loads)",
                fixed(a, 1),
                fixed(a / G, 2),
                rounded(mu, 3)
            ),
        };
        write!(
            f,
            "{head} {}° step asks for a steady lateral acceleration u²·δ/(l + K·u²) = {} m/s² ({} g), beyond {limit}. A step of at most {}° at {} m/s, or of {}° below {} m/s, keeps the steady state within it",
            fixed(self.steer.to_degrees(), 2),
            fixed(asked, 1),
            fixed(asked / G, 2),
            rounded_down(self.largest_steer().to_degrees(), 2),
            fixed(self.speed, 1),
            fixed(self.steer.to_degrees(), 2),
            rounded_down(self.highest_speed(), 3)
        )?;
        if let Some(mu) = self.road {
            let a = mu * G;
            write!(
                f,
                "; on the road, whose friction {} gives {} m/s² ({} g), a step of at most {}° at {} m/s, or of {}° below {} m/s, keeps it within that too: the linear tyres have no grip limit of their own and run past it without sliding",
                rounded(mu, 3),
                fixed(a, 1),
                fixed(mu, 2),
                rounded_down(self.steer_for(a).to_degrees(), 2),
                fixed(self.speed, 1),
                fixed(self.steer.to_degrees(), 2),
                rounded_down(self.speed_for(a), 3)
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tester's car: 1530 kg, a = 1.67 m, b = 1.11 m on linear tyres
    /// of 57,296 N/rad per wheel, stepped 1° at 30 m/s.
    fn tester() -> AskedTurn {
        let c = 2.0 * 57_296.0;
        let l = 2.78;
        AskedTurn {
            speed: 30.0,
            steer: 1f64.to_radians(),
            wheelbase: l,
            gradient: 1530.0 / l * (1.11 / c - 1.67 / c),
            limit: TurnLimit::Lift(G * 1.55 / (2.0 * 0.55)),
            road: None,
        }
    }

    /// K = −0.00269 rad/(m/s²), v_crit = √(2.78/0.00269) = 32.2 m/s;
    /// u²δ/(l + Ku²) = 900·0.017453/(2.78 − 2.4206) = 43.7 m/s².
    #[test]
    fn a_step_near_the_critical_speed_asks_for_the_bicycle_models_turn() {
        let a = tester();
        assert!((a.asked() - 43.71).abs() < 0.01, "{}", a.asked());
        let critical = a.near_critical().expect("near");
        assert!((critical - 32.15).abs() < 0.01, "{critical}");
        // The largest steer and the highest speed reach the limit exactly.
        let at_steer = AskedTurn {
            steer: a.largest_steer(),
            ..a
        };
        assert!((at_steer.asked() - a.limit.ay()).abs() < 1e-9);
        let at_speed = AskedTurn {
            speed: a.highest_speed(),
            ..a
        };
        assert!((at_speed.asked() - a.limit.ay()).abs() < 1e-9);
        let said = a.to_string();
        assert!(
            said.contains("near its critical speed √(−l/K) = 32.2 m/s"),
            "{said}"
        );
        assert!(
            said.contains("= 43.7 m/s² (4.46 g), beyond the 13.8 m/s²"),
            "{said}"
        );
    }

    /// On linear tyres the advice keeps the turn within the road's μ·g
    /// too: at friction 1, 9.807 m/s² at 30 m/s is a step of
    /// 9.807·(2.78 − 0.00269·900)/900 = 0.2244°, and 1° holds it up to
    /// √(9.807·2.78/(0.017453 + 9.807·0.00269)) = 24.9 m/s (26.5 m/s
    /// holds it on four wheels, at 1.4 g).
    #[test]
    fn on_linear_tyres_the_advice_keeps_the_turn_within_the_roads_grip() {
        let a = AskedTurn {
            road: Some(1.0),
            ..tester()
        };
        let g = a.steer_for(G).to_degrees();
        let u = a.speed_for(G);
        assert!((g - 0.2244).abs() < 1e-3, "{g}");
        assert!((u - 24.94).abs() < 0.01, "{u}");
        let at = AskedTurn { speed: u, ..a };
        assert!((at.asked() - G).abs() < 1e-9);
        let said = a.to_string();
        assert!(
            said.contains("keeps the steady state within it; on the road, whose friction 1 gives 9.8 m/s² (1.00 g), a step of at most 0.22° at 30.0 m/s, or of 1.00° below 24.9 m/s, keeps it within that too"),
            "{said}"
        );
        assert!(!tester().to_string().contains("on the road"));
    }

    /// Far below the critical speed (gain factor under 2) no critical
    /// speed is said.
    #[test]
    fn a_step_far_below_the_critical_speed_does_not_name_it() {
        let a = AskedTurn {
            speed: 15.0,
            steer: 0.1,
            ..tester()
        };
        assert!(a.gain_factor() < NEAR_CRITICAL_GAIN);
        assert_eq!(a.near_critical(), None);
        assert!(!a.to_string().contains("critical"), "{a}");
    }
}
