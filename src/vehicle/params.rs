//! Vehicle mass and geometry: the `[vehicle]` table of `FORMATS.md`.
//!
//! Units: kg, kg·m², m. `a`, `b` are the distances from the centre of gravity
//! to the front and rear axle.

use crate::constants::G;
use crate::error::{
    CgTooLow, MassDigit, ParamError, ParamReason, VehicleLimit, DYNAMIC_INDEX, MAX_STEERING_RATIO,
    MIN_STEERING_RATIO,
};
use serde::{Deserialize, Serialize};

/// Vehicle parameters. Unknown keys are refused, so a misspelt key is an error.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Vehicle {
    /// Mass m, kg.
    pub mass: f64,
    /// Yaw moment of inertia Iz, kg·m².
    pub yaw_inertia: f64,
    /// Centre of gravity to front axle, m.
    pub a: f64,
    /// Centre of gravity to rear axle, m.
    pub b: f64,
    /// Front track width, m.
    pub track_front: f64,
    /// Rear track width, m.
    pub track_rear: f64,
    /// Centre-of-gravity height, m.
    pub cg_height: f64,
    /// Wheelbase, m: optional; when given it must equal a + b (to 1 mm).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wheelbase: Option<f64>,
    /// Front share χ of the lateral load transfer (default b/l, Wang & Liang).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_transfer_front_share: Option<f64>,
    /// Steering ratio (steering-wheel angle / road-wheel angle): optional;
    /// accepted (FORMATS.md allows it) and validated, not used by the 2-DOF
    /// model, whose input is the road-wheel angle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub steering_ratio: Option<f64>,
}

/// Tolerance on a + b = wheelbase, m.
const WHEELBASE_TOLERANCE: f64 = 1e-3;

/// Largest mass, kg: above any wheeled vehicle (a loaded mining truck is
/// 6e5 kg). A larger value is a unit slip (grams).
const MAX_MASS: f64 = 1e6;

/// Largest axle distance or track, m: a unit slip (millimetres) beyond.
const MAX_LENGTH: f64 = 30.0;

/// Least mass of a vehicle whose wheelbase is at least [`MASS_CHECK_WHEELBASE`],
/// kg: a kart without its driver is about 75 kg. Less is a mass in tonnes
/// (1.53 for 1530 kg), which the dynamic index blamed on `yaw_inertia`.
const MIN_MASS: f64 = 50.0;

/// Wheelbase from which [`MIN_MASS`] holds, m: below it (a scale model,
/// a robot) nothing is judged by the mass alone.
const MASS_CHECK_WHEELBASE: f64 = 1.0;

/// Least static stability factor `track/(2·cg_height)`, the lateral
/// acceleration (in g) at which a rigid car on a flat road tips over:
/// road cars 1.0–1.5, a loaded tanker truck about 0.35. Below 0.3 g the
/// centre of gravity is in the wrong unit or another key's value (5.5 m
/// for 0.55).
const MIN_TIP_OVER: f64 = 0.3;

/// Largest static stability factor `track/(2·cg_height)`, g: road cars
/// have 1.0–1.5 (NHTSA's rollover ratings: passenger cars 1.2–1.5, SUVs
/// 1.0–1.3), the lowest racing cars about 2.5–3 (a Formula 1 car's centre
/// of gravity some 0.3 m up on a 1.6 m track; a kart's 0.2–0.25 m on
/// 1.2 m; the Putnam Dallara here 0.3 m on 1.55 m: 2.6). Above 5 the height
/// is a digit off (0.055 m for a sedan's 0.55 gives 14) or in another unit.
const MAX_TIP_OVER: f64 = 5.0;

/// A vehicle's mass per m² of its footprint (wheelbase × mean track),
/// kg/m², from makers' figures: a kart with its driver about 130, a
/// Formula 1 or Formula Student car 130–160, road cars 250–600 (a small
/// car 900 kg on 2.4 × 1.45 m, a large SUV 3 t on 3 × 1.7 m), a city bus
/// about 1400, a two-axle lorry 1300–1800. Only a dynamic index out of
/// range consults it, to say whether the mass (ten times off lands it
/// beyond, 3550 for a car) or the yaw inertia holds the slip.
const MASS_PER_FOOTPRINT: (f64, f64) = (50.0, 2000.0);

/// Range of a track over the wheelbase (the refusal's words state it):
/// road cars about 0.55–0.65, a
/// Formula Student car 0.8, a kart 1.1, a long truck or bus 0.3. A track
/// beyond it is in the wrong unit (mm, cm) or a key holds another's value
/// (a track of 1 µm lifts a wheel at any turn; 10 m has no vehicle).
const TRACK_TO_WHEELBASE: (f64, f64) = (0.15, 2.0);

/// Least static stability factor `track/(2·cg_height)` of a road
/// vehicle, g, below which `simulate` warns (NHTSA's rollover ratings:
/// passenger cars 1.2–1.5, SUVs and vans 1.0–1.3; heavy trucks and buses
/// lower, a loaded tanker down to 0.35, which the refusal at
/// [`MIN_TIP_OVER`] leaves in). Below 0.8 g the vehicle tips over within
/// a dry road's grip: possible for a laden truck, a slip for a car.
pub const WARN_TIP_OVER: f64 = 0.8;

/// Largest track over wheelbase of a vehicle, above which `simulate`
/// warns: road cars about 0.5–0.75 (a small car 1.4 m on 2.4 m, 0.58), a
/// Formula Student car 0.8, a kart up to about 1.3 (CIK: a wheelbase of
/// 1.01–1.07 m, an overall width of at most 1.4 m). Up to the refusal at
/// 2 the track is a value no vehicle has (5.5 m on a sedan's 2.78 m
/// wheelbase ran silently).
pub const WARN_TRACK_TO_WHEELBASE: f64 = 1.4;

impl Vehicle {
    /// Wheelbase l = a + b, m.
    pub fn wheelbase(&self) -> f64 {
        self.a + self.b
    }

    /// Static axle loads (front, rear), N.
    pub(crate) fn static_axle_loads(&self) -> (f64, f64) {
        let w = self.mass * G / self.wheelbase();
        (w * self.b, w * self.a)
    }

    /// Front share of lateral load transfer χ.
    pub(crate) fn front_transfer_share(&self) -> f64 {
        self.load_transfer_front_share
            .unwrap_or(self.b / self.wheelbase())
    }

    /// A mass below [`MIN_MASS`] for a wheelbase of at least
    /// [`MASS_CHECK_WHEELBASE`] (refused at `mass`, before the dynamic
    /// index blames `yaw_inertia` for it), and a centre of gravity so high
    /// that the car tips over at under [`MIN_TIP_OVER`] g: `cg_height >
    /// track/(2·0.3)` on the narrower track (refused at `cg_height`).
    fn plausible_mass_and_cg(&self) -> Result<(), ParamError> {
        let l = self.wheelbase();
        if l >= MASS_CHECK_WHEELBASE && self.mass < MIN_MASS {
            let reason = ParamReason::MassTooSmall {
                mass: self.mass,
                min: MIN_MASS,
                wheelbase: l,
            };
            return Err(ParamError::new("mass", self.mass, reason));
        }
        let track = self.track_front.min(self.track_rear);
        let tips_at = track / (2.0 * self.cg_height);
        if tips_at < MIN_TIP_OVER {
            let reason = ParamReason::TipsOver {
                tips_at,
                track,
                min: MIN_TIP_OVER,
            };
            return Err(ParamError::new("cg_height", self.cg_height, reason));
        }
        if tips_at > MAX_TIP_OVER {
            let reason = ParamReason::CgTooLow(Box::new(CgTooLow {
                cg_height: self.cg_height,
                track,
                max: MAX_TIP_OVER,
                min: MIN_TIP_OVER,
            }));
            return Err(ParamError::new("cg_height", self.cg_height, reason));
        }
        Ok(())
    }

    /// The dynamic index `Iz/(m·a·b)` within [`DYNAMIC_INDEX`]; outside,
    /// refused at `mass` where the mass is the likelier slip (its mass per
    /// footprint is beyond any vehicle's, [`MASS_PER_FOOTPRINT`], and ten
    /// times more or less puts both it and the index within theirs: the
    /// index alone cannot tell a mass ten times off from an inertia ten
    /// times off the other way), else at `yaw_inertia`.
    fn plausible_index(&self) -> Result<(), ParamError> {
        let ab = self.a * self.b;
        let index = |mass: f64| self.yaw_inertia / (mass * ab);
        let within = |v: f64, (lo, hi): (f64, f64)| (lo..=hi).contains(&v);
        if within(index(self.mass), DYNAMIC_INDEX) {
            return Ok(());
        }
        let footprint = (self.wheelbase(), 0.5 * (self.track_front + self.track_rear));
        let per_area = |mass: f64| mass / (footprint.0 * footprint.1);
        let likely = [10.0, 0.1]
            .into_iter()
            .map(|f| f * self.mass)
            .find(|&m| within(index(m), DYNAMIC_INDEX) && within(per_area(m), MASS_PER_FOOTPRINT));
        if let Some(likely) = likely.filter(|_| !within(per_area(self.mass), MASS_PER_FOOTPRINT)) {
            let reason = ParamReason::MassDigit(Box::new(MassDigit {
                mass: self.mass,
                likely,
                yaw_inertia: self.yaw_inertia,
                ab,
                footprint,
                per_area: MASS_PER_FOOTPRINT,
                index: DYNAMIC_INDEX,
            }));
            return Err(ParamError::new("mass", self.mass, reason));
        }
        Err(ParamError::new(
            "yaw_inertia",
            self.yaw_inertia,
            ParamReason::DynamicIndex {
                index: index(self.mass),
                mass: self.mass,
                ab,
            },
        ))
    }

    /// What is possible but unlike a road vehicle: a static stability
    /// factor below [`WARN_TIP_OVER`] (the car rolls over below it) or a
    /// track over wheelbase above [`WARN_TRACK_TO_WHEELBASE`], each said
    /// with its numbers and the range of vehicles. The values beyond any
    /// vehicle's are refused by [`Vehicle::validate`].
    pub fn unlikely(&self) -> Vec<String> {
        let mut said = Vec::new();
        let track = self.track_front.min(self.track_rear);
        let tips_at = track / (2.0 * self.cg_height);
        if tips_at < WARN_TIP_OVER {
            said.push(format!(
                "the static stability factor track/(2·cg_height) = {}/(2·{}) is {} g: the car rolls over at {} m/s² of lateral acceleration, where a road car holds 1.0–1.5 g (NHTSA's rollover ratings) and only a laden heavy truck or bus is below {} g; the 2-DOF model does not roll over (a wheel lifting is said), so check cg_height and the track",
                crate::error::Num(track),
                crate::error::Num(self.cg_height),
                crate::format::readable(tips_at, 2),
                crate::format::readable(tips_at * G, 2),
                WARN_TIP_OVER,
            ));
        }
        let l = self.wheelbase();
        let (key, t) = match self.track_rear > self.track_front {
            true => ("track_rear", self.track_rear),
            false => ("track_front", self.track_front),
        };
        {
            if t / l > WARN_TRACK_TO_WHEELBASE {
                said.push(format!(
                    "{key} = {} m on a wheelbase a + b = {} m gives track/wheelbase = {}, wider than any vehicle's {} (road cars 0.5–0.75, a kart up to about 1.3): check the track, and a and b",
                    crate::error::Num(t),
                    crate::format::rounded(l, 4),
                    crate::format::readable(t / l, 3),
                    WARN_TRACK_TO_WHEELBASE,
                ));
            }
        }
        said
    }

    /// The mass and lengths below their limits, and each track within its
    /// ratio to the wheelbase. Apart from [`Self::validate`] so that it
    /// reads on a screen; in its order, which decides the error said.
    fn plausible_sizes(&self) -> Result<(), ParamError> {
        if self.mass > MAX_MASS {
            return Err(ParamError::new(
                "mass",
                self.mass,
                ParamReason::MassTooLarge { max: MAX_MASS },
            ));
        }
        for (key, v) in [
            ("a", self.a),
            ("b", self.b),
            ("track_front", self.track_front),
            ("track_rear", self.track_rear),
            ("cg_height", self.cg_height),
        ] {
            if v > MAX_LENGTH {
                return Err(ParamError::new(
                    key,
                    v,
                    ParamReason::LengthTooLarge { max: MAX_LENGTH },
                ));
            }
        }
        for (key, track) in [
            ("track_front", self.track_front),
            ("track_rear", self.track_rear),
        ] {
            let ratio = track / self.wheelbase();
            if !(TRACK_TO_WHEELBASE.0..=TRACK_TO_WHEELBASE.1).contains(&ratio) {
                let reason = ParamReason::TrackToWheelbase {
                    ratio,
                    a: self.a,
                    b: self.b,
                };
                return Err(ParamError::new(key, track, reason));
            }
        }
        Ok(())
    }

    /// Checks every value for physical sense; the error names the key.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("mass", self.mass)?;
        ParamError::positive("yaw_inertia", self.yaw_inertia)?;
        ParamError::positive("a", self.a)?;
        ParamError::positive("b", self.b)?;
        ParamError::positive("track_front", self.track_front)?;
        ParamError::positive("track_rear", self.track_rear)?;
        ParamError::non_negative("cg_height", self.cg_height)?;
        self.plausible_sizes()?;
        // After the track (a track in the wrong unit is the track's error,
        // not the height's) and before the dynamic index (a mass in tonnes
        // is the mass's, not the inertia's).
        self.plausible_mass_and_cg()?;
        self.plausible_index()?;
        if let Some(l) = self.wheelbase {
            ParamError::positive("wheelbase", l)?;
            if (l - self.wheelbase()).abs() > WHEELBASE_TOLERANCE {
                return Err(ParamError::new(
                    "wheelbase",
                    l,
                    ParamReason::WheelbaseMismatch(Box::new(crate::error::Wheelbase {
                        a: self.a,
                        b: self.b,
                        wheelbase: l,
                        places: Vec::new(),
                    })),
                ));
            }
        }
        if let Some(chi) = self.load_transfer_front_share {
            if !(0.0..=1.0).contains(&chi) {
                return Err(ParamError::new(
                    "load_transfer_front_share",
                    chi,
                    ParamReason::TransferShare,
                ));
            }
        }
        if let Some(r) = self.steering_ratio {
            ParamError::positive("steering_ratio", r)?;
            // Not used by the model, but read: 1e9 is a slip, not a car.
            if !(MIN_STEERING_RATIO..=MAX_STEERING_RATIO).contains(&r) {
                let reason = ParamReason::VehicleRange(VehicleLimit::SteeringRatio);
                return Err(ParamError::new("steering_ratio", r, reason));
            }
        }
        Ok(())
    }

    /// Wang & Liang's reference passenger car (a compact sedan with Gim tyres).
    /// Wang & Liang's Table 1 did not survive; these are typical values of its
    /// class, stated so that results can be reproduced.
    pub fn compact_sedan() -> Self {
        Self {
            mass: 1530.0,
            yaw_inertia: 2315.0,
            a: 1.11,
            b: 1.67,
            track_front: 1.55,
            track_rear: 1.55,
            cg_height: 0.55,
            wheelbase: None,
            load_transfer_front_share: None,
            steering_ratio: None,
        }
    }
}
