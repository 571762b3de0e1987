//! The library of candidate effects of the sim-to-real diagnosis:
//! each is a model extension with one to three physical parameters, off in
//! the base model. [`EffectKind`] names them (as a campaign's
//! `[diagnose] effects` and `diagnosis.json` do), gives their parameters,
//! units, search bounds and the values that switch them off;
//! [`EffectSet`] holds the values of all of them at once, and is what the
//! augmented model (`crate::diagnose::model`) evaluates.
//!
//! Signs follow ISO 8855 (x forward, y left, z up, positive steer left,
//! positive roll φ puts the right side down, as in a left turn). Units: SI,
//! rad; scales are dimensionless factors on the base model's value.

pub mod sensors;

use crate::diagnose::effects::sensors::Sensors;
pub use crate::vehicle::RollModel;
use serde::{Deserialize, Serialize};

/// One candidate effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EffectKind {
    /// Tyre lag: first-order slip-angle response over a relaxation length.
    RelaxationLength,
    /// Steer angle lost to the front axle force through the steering system.
    SteeringCompliance,
    /// Axle steer proportional to body roll (needs the roll degree of freedom).
    RollSteer,
    /// Camber thrust proportional to body roll and load.
    RollCamber,
    /// Front share of the lateral load transfer.
    LoadTransferDistribution,
    /// Aerodynamic down-force growing with speed squared.
    AeroLoad,
    /// Road friction differing from the tyre data's.
    RoadFriction,
    /// Constant road bank (cross slope).
    RoadBank,
    /// Axle cornering stiffness differing from the tyre data's.
    CorneringStiffness,
    /// Yaw moment of inertia differing from the vehicle file's.
    YawInertia,
    /// All measured channels reported late.
    SensorDelay,
    /// Constant offsets of the yaw-rate, lateral-acceleration and sideslip
    /// sensors.
    SensorBias,
    /// A body-fixed accelerometer that rolls with the body and feels g·sin φ.
    AccelerometerRoll,
    /// An accelerometer ahead of or behind the centre of gravity.
    AccelerometerPosition,
    /// Load moved between the axles by the longitudinal acceleration.
    LongitudinalLoadTransfer,
    /// Lateral force lost to the longitudinal force of braking and drive
    /// (each tyre's friction circle), with a drive split, a brake balance
    /// and the share of `m·ax` the tyres carry.
    CombinedSlip,
    /// The road bank of the run's `bank` channel, scaled, plus an offset.
    BankProfile,
    /// The steer actuator: the road wheels follow the logged steer late
    /// (a dead time) and through a first-order lag.
    SteerPath,
}

/// What a run must carry for an effect to show in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    /// Nothing beyond steer, speed and a response.
    Nothing,
    /// A longitudinal acceleration (an `ax` channel, or a speed that
    /// changes) somewhere.
    LongitudinalAcceleration,
    /// A `bank` channel.
    BankChannel,
}

/// A parameter of an effect.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// Name in reports.
    pub name: &'static str,
    /// Unit.
    pub unit: &'static str,
    /// Value that switches the effect off.
    pub off: f64,
    /// Search bounds (lower, upper).
    pub bounds: (f64, f64),
    /// What each bound is (lower, upper).
    pub limits: (Bound, Bound),
}

/// What bounds a parameter on one side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Bound {
    /// The end of a wide search range: a fit that stops there would go
    /// further.
    Search,
    /// A limit of the quantity itself (a length, a delay or a share below
    /// 0, a share above 1): no value lies beyond it.
    Physical,
}

const fn par(name: &'static str, unit: &'static str, off: f64, lo: f64, hi: f64) -> Parameter {
    Parameter {
        name,
        unit,
        off,
        bounds: (lo, hi),
        limits: (Bound::Search, Bound::Search),
    }
}

impl Parameter {
    /// The same with its lower bound a physical limit.
    const fn floor(self) -> Self {
        Self {
            limits: (Bound::Physical, self.limits.1),
            ..self
        }
    }

    /// The same with both bounds physical limits (a share).
    const fn share(self) -> Self {
        Self {
            limits: (Bound::Physical, Bound::Physical),
            ..self
        }
    }

    /// The bound `value` lies on (within 1e-9 of the span: the bounded fits
    /// stop exactly on a bound they press against), if any.
    pub fn bound_at(&self, value: f64) -> Option<Bound> {
        on_bound(value, self.bounds).map(|upper| if upper { self.limits.1 } else { self.limits.0 })
    }
}

/// The roll degree of freedom's dynamics, fitted with the roll effects: a
/// campaign's `[roll]` is a guess (no roll channel is needed), and roll
/// steer or camber seen through the wrong roll frequency and damping is
/// mimicked by stiffness changes of the wrong sign. The roll gradient stays
/// the campaign's: it only scales the per-radian roll-steer and roll-camber
/// values. Off values (NaN) are the campaign's.
pub static ROLL_DYNAMICS: [Parameter; 2] = [
    Parameter {
        name: "frequency",
        unit: "Hz",
        off: f64::NAN,
        bounds: (0.5, 4.0),
        limits: (Bound::Search, Bound::Search),
    },
    Parameter {
        name: "damping",
        unit: "-",
        off: f64::NAN,
        bounds: (0.2, 1.5),
        limits: (Bound::Search, Bound::Search),
    },
];

/// Whether `value` lies on the lower (`Some(false)`) or upper (`Some(true)`)
/// of `bounds`, within 1e-9 of their span (the bounded fits stop exactly
/// on a bound they press against), or on neither.
pub(crate) fn on_bound(value: f64, (lo, hi): (f64, f64)) -> Option<bool> {
    let tol = 1e-9 * (hi - lo);
    if value - lo <= tol {
        Some(false)
    } else if hi - value <= tol {
        Some(true)
    } else {
        None
    }
}

/// The names of `kinds` joined by `sep` (a candidate's label: `a+b`).
pub fn joined(kinds: &[EffectKind], sep: &str) -> String {
    let names: Vec<&str> = kinds.iter().map(|e| e.name()).collect();
    names.join(sep)
}

impl EffectKind {
    /// Every effect, in a fixed order: the candidates of a campaign that
    /// names none, and the order error messages list them in.
    pub const ALL: [EffectKind; 18] = [
        EffectKind::RelaxationLength,
        EffectKind::SteeringCompliance,
        EffectKind::RollSteer,
        EffectKind::RollCamber,
        EffectKind::LoadTransferDistribution,
        EffectKind::AeroLoad,
        EffectKind::RoadFriction,
        EffectKind::RoadBank,
        EffectKind::CorneringStiffness,
        EffectKind::YawInertia,
        EffectKind::SensorDelay,
        EffectKind::SensorBias,
        EffectKind::AccelerometerRoll,
        EffectKind::AccelerometerPosition,
        EffectKind::LongitudinalLoadTransfer,
        EffectKind::CombinedSlip,
        EffectKind::BankProfile,
        EffectKind::SteerPath,
    ];

    /// The name in a campaign's `[diagnose] effects` and in
    /// `diagnosis.json`.
    pub fn name(self) -> &'static str {
        match self {
            EffectKind::RelaxationLength => "relaxation_length",
            EffectKind::SteeringCompliance => "steering_compliance",
            EffectKind::RollSteer => "roll_steer",
            EffectKind::RollCamber => "roll_camber",
            EffectKind::LoadTransferDistribution => "load_transfer_distribution",
            EffectKind::AeroLoad => "aero_load",
            EffectKind::RoadFriction => "road_friction",
            EffectKind::RoadBank => "road_bank",
            EffectKind::CorneringStiffness => "cornering_stiffness",
            EffectKind::YawInertia => "yaw_inertia",
            EffectKind::SensorDelay => "sensor_delay",
            EffectKind::SensorBias => "sensor_bias",
            EffectKind::AccelerometerRoll => "accelerometer_roll",
            EffectKind::AccelerometerPosition => "accelerometer_position",
            EffectKind::LongitudinalLoadTransfer => "longitudinal_load_transfer",
            EffectKind::CombinedSlip => "combined_slip",
            EffectKind::BankProfile => "bank_profile",
            EffectKind::SteerPath => "steer_path",
        }
    }

    /// What a run must carry for the effect to show.
    pub fn needs(self) -> Needs {
        match self {
            EffectKind::LongitudinalLoadTransfer | EffectKind::CombinedSlip => {
                Needs::LongitudinalAcceleration
            }
            EffectKind::BankProfile => Needs::BankChannel,
            _ => Needs::Nothing,
        }
    }

    /// Whether the effect acts through the roll degree of freedom (whose
    /// dynamics the diagnosis then fits with it).
    pub fn uses_roll(self) -> bool {
        matches!(self, EffectKind::RollSteer | EffectKind::RollCamber)
    }

    /// The effect of a name, if it is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|e| e.name() == name)
    }

    /// Its parameters. The bounds are wide physical ranges: the search must
    /// be able to find a value the truth did not use.
    pub fn parameters(self) -> &'static [Parameter] {
        const RELAXATION: [Parameter; 1] = [par("relaxation_length", "m", 0.0, 0.0, 3.0).floor()];
        const COMPLIANCE: [Parameter; 1] =
            [par("steer_per_front_force", "rad/kN", 0.0, -0.02, 0.05)];
        const ROLL_STEER: [Parameter; 2] = [
            par("front", "rad/rad", 0.0, -0.5, 0.5),
            par("rear", "rad/rad", 0.0, -0.5, 0.5),
        ];
        const ROLL_CAMBER: [Parameter; 2] = [
            par("front", "N/N per rad", 0.0, -8.0, 8.0),
            par("rear", "N/N per rad", 0.0, -8.0, 8.0),
        ];
        const SHARE: [Parameter; 1] = [par("front_share", "-", f64::NAN, 0.0, 1.0).share()];
        // No negative down-force (a lift is not the model): 0 is a
        // physical limit.
        const AERO: [Parameter; 2] = [
            par("front", "N/(m/s)^2", 0.0, 0.0, 6.0).floor(),
            par("rear", "N/(m/s)^2", 0.0, 0.0, 6.0).floor(),
        ];
        const FRICTION: [Parameter; 1] = [par("friction_scale", "-", 1.0, 0.3, 1.5)];
        const BANK: [Parameter; 1] = [par("bank", "rad", 0.0, -0.15, 0.15)];
        const STIFFNESS: [Parameter; 2] = [
            par("front_scale", "-", 1.0, 0.4, 2.0),
            par("rear_scale", "-", 1.0, 0.4, 2.0),
        ];
        const INERTIA: [Parameter; 1] = [par("scale", "-", 1.0, 0.4, 2.5)];
        const DELAY: [Parameter; 1] = [par("delay", "s", 0.0, 0.0, 0.3).floor()];
        const BIAS: [Parameter; 3] = [
            par("yaw_rate", "rad/s", 0.0, -0.05, 0.05),
            par("ay", "m/s²", 0.0, -1.0, 1.0),
            par("beta", "rad", 0.0, -0.05, 0.05),
        ];
        const ROLL: [Parameter; 1] = [par("roll_gradient", "rad/(m/s²)", 0.0, -0.03, 0.03)];
        const POSITION: [Parameter; 1] = [par("x", "m", 0.0, -2.5, 2.5)];
        const PITCH: [Parameter; 1] = [par("share", "-", 0.0, 0.0, 2.0).floor()];
        // Off when the tyres carry none of m·ax (force_share 0): the
        // lateral forces are then the pure-slip ones exactly, whatever the
        // split and balance (whose off values, rear-wheel drive and 60 % of
        // the braking in front, are only starts). The share's upper bound
        // is a search bound (the tyres may carry more than m·ax: drag and
        // rolling resistance against the throttle, an ax logged low).
        const COMBINED: [Parameter; 3] = [
            par("drive_front_share", "-", 0.0, 0.0, 1.0).share(),
            par("brake_front_share", "-", 0.6, 0.0, 1.0).share(),
            par("force_share", "-", 0.0, 0.0, 1.5).floor(),
        ];
        const PROFILE: [Parameter; 2] = [
            par("scale", "-", 0.0, -0.5, 2.0),
            par("offset", "rad", 0.0, -0.2, 0.2),
        ];
        const STEER_PATH: [Parameter; 2] = [
            par("delay", "s", 0.0, 0.0, 0.5).floor(),
            par("lag", "s", 0.0, 0.0, 0.5).floor(),
        ];
        match self {
            EffectKind::RelaxationLength => &RELAXATION,
            EffectKind::SteeringCompliance => &COMPLIANCE,
            EffectKind::RollSteer => &ROLL_STEER,
            EffectKind::RollCamber => &ROLL_CAMBER,
            EffectKind::LoadTransferDistribution => &SHARE,
            EffectKind::AeroLoad => &AERO,
            EffectKind::RoadFriction => &FRICTION,
            EffectKind::RoadBank => &BANK,
            EffectKind::CorneringStiffness => &STIFFNESS,
            EffectKind::YawInertia => &INERTIA,
            EffectKind::SensorDelay => &DELAY,
            EffectKind::SensorBias => &BIAS,
            EffectKind::AccelerometerRoll => &ROLL,
            EffectKind::AccelerometerPosition => &POSITION,
            EffectKind::LongitudinalLoadTransfer => &PITCH,
            EffectKind::CombinedSlip => &COMBINED,
            EffectKind::BankProfile => &PROFILE,
            EffectKind::SteerPath => &STEER_PATH,
        }
    }

    /// What the effect does to the measurements that no other effect does:
    /// the experiment that separates it from a look-alike.
    pub fn signature(self) -> &'static str {
        match self {
            EffectKind::RelaxationLength => {
                "a lag that shrinks with speed (time constant σ/u): compare runs at two speeds"
            }
            EffectKind::SteeringCompliance => {
                "understeer that grows with front axle force, not with roll: compare steady turns at one lateral acceleration and different speeds"
            }
            EffectKind::RollSteer => {
                "a steer change that follows body roll through the tyre's slip curve (saturates at the limit): a ramp steer to the limit"
            }
            EffectKind::RollCamber => {
                "a force change proportional to roll and load that does not saturate with slip: a ramp steer to the limit"
            }
            EffectKind::LoadTransferDistribution => {
                "a balance change only at high lateral acceleration: compare low- and high-level steps at one speed"
            }
            EffectKind::AeroLoad => {
                "grip and balance that change with speed squared at equal lateral acceleration: steps at two speeds, same level"
            }
            EffectKind::RoadFriction => {
                "no change in the linear range, a lower limit: a ramp steer to the limit"
            }
            EffectKind::RoadBank => {
                "a constant drift present before any steer: a straight run in both directions of travel"
            }
            EffectKind::CorneringStiffness => {
                "a change of the linear gains at every speed and level: steps at two speeds"
            }
            EffectKind::YawInertia => {
                "yaw-rate transient only, same steady state: a frequency sweep (yaw-rate phase)"
            }
            EffectKind::SensorDelay => {
                "a lag independent of speed and of frequency-dependent dynamics (phase ∝ frequency): a sweep at two speeds"
            }
            EffectKind::SensorBias => {
                "a constant offset that does not depend on the vehicle's direction of travel: a straight run both ways"
            }
            EffectKind::AccelerometerRoll => {
                "lateral acceleration reads high by g·sin φ while the yaw rate agrees: compare ay with u·r in steady turns"
            }
            EffectKind::AccelerometerPosition => {
                "ay error proportional to yaw acceleration, none in steady state: a frequency sweep"
            }
            EffectKind::LongitudinalLoadTransfer => {
                "a balance change that follows braking and throttle, none at constant speed: steady turns braking and accelerating"
            }
            EffectKind::CombinedSlip => {
                "grip lost in proportion to the longitudinal force, most near the limit: braking in a turn against coasting at one lateral acceleration"
            }
            EffectKind::BankProfile => {
                "a drift that follows the measured bank, not the steer: the same corner driven at two speeds"
            }
            EffectKind::SteerPath => {
                "a lag in the steer input, not the sensors: the response to a steer step changes shape (first-order filtered) as well as time, while the responses without steer (to speed changes, to the bank, a sensor's offset) keep their timing; a sensor delay shifts every channel alike: a steer step, and a speed change on a straight"
            }
        }
    }
}

/// The values of every effect; [`EffectSet::default`] is the base model.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct EffectSet {
    /// Relaxation length σ of both axles, m (0: no lag).
    pub relaxation_length: f64,
    /// Steer lost per front axle force, rad/N.
    pub steering_compliance: f64,
    /// Roll steer (front, rear), rad of axle steer per rad of roll.
    pub roll_steer: [f64; 2],
    /// Camber thrust per roll (front, rear): lateral force per wheel load per
    /// rad of roll.
    pub roll_camber: [f64; 2],
    /// Front share of the lateral load transfer (None: the vehicle's).
    pub load_transfer_front_share: Option<f64>,
    /// Aerodynamic down-force per axle, N per (m/s)².
    pub aero_load: [f64; 2],
    /// Road friction scale (None: the campaign's road friction).
    pub friction_scale: Option<f64>,
    /// Road bank, rad.
    pub road_bank: f64,
    /// Cornering-stiffness scale (front, rear) (None: 1).
    pub cornering_stiffness_scale: Option<[f64; 2]>,
    /// Yaw-inertia scale (None: 1).
    pub yaw_inertia_scale: Option<f64>,
    /// Share of the rigid-body longitudinal load transfer (0: none).
    pub longitudinal_load_transfer: f64,
    /// Combined slip's drive split and brake balance (front shares) and
    /// the share of `m·ax` the tyres carry (None, or a share of 0: pure
    /// slip).
    pub combined_slip: Option<[f64; 3]>,
    /// The measured bank profile's scale, and a constant bank added, rad.
    pub bank_profile: [f64; 2],
    /// The steer path's delay and first-order lag time constant, s (0, 0:
    /// the road wheels follow the logged steer).
    pub steer_path: [f64; 2],
    /// The measurement system.
    pub sensors: Sensors,
}

impl EffectSet {
    /// Sets `kind`'s parameters to `p` (as many as it has).
    pub fn set(&mut self, kind: EffectKind, p: &[f64]) {
        match kind {
            EffectKind::RelaxationLength => self.relaxation_length = p[0],
            EffectKind::SteeringCompliance => self.steering_compliance = p[0] * 1e-3,
            EffectKind::RollSteer => self.roll_steer = [p[0], p[1]],
            EffectKind::RollCamber => self.roll_camber = [p[0], p[1]],
            EffectKind::LoadTransferDistribution => self.load_transfer_front_share = Some(p[0]),
            EffectKind::AeroLoad => self.aero_load = [p[0], p[1]],
            EffectKind::RoadFriction => self.friction_scale = Some(p[0]),
            EffectKind::RoadBank => self.road_bank = p[0],
            EffectKind::CorneringStiffness => self.cornering_stiffness_scale = Some([p[0], p[1]]),
            EffectKind::YawInertia => self.yaw_inertia_scale = Some(p[0]),
            EffectKind::SensorDelay => self.sensors.delay = p[0],
            EffectKind::SensorBias => {
                self.sensors.yaw_rate_bias = p[0];
                self.sensors.ay_bias = p[1];
                self.sensors.beta_bias = p[2];
            }
            EffectKind::AccelerometerRoll => self.sensors.roll_gradient = p[0],
            EffectKind::AccelerometerPosition => self.sensors.accelerometer_x = p[0],
            EffectKind::LongitudinalLoadTransfer => self.longitudinal_load_transfer = p[0],
            EffectKind::CombinedSlip => self.combined_slip = Some([p[0], p[1], p[2]]),
            EffectKind::BankProfile => self.bank_profile = [p[0], p[1]],
            EffectKind::SteerPath => self.steer_path = [p[0], p[1]],
        }
    }

    /// `kind`'s parameters as set here (its "off" values when it is off;
    /// the load-transfer share then takes `nominal_share`).
    pub fn get(&self, kind: EffectKind, nominal_share: f64) -> Vec<f64> {
        match kind {
            EffectKind::RelaxationLength => vec![self.relaxation_length],
            EffectKind::SteeringCompliance => vec![self.steering_compliance * 1e3],
            EffectKind::RollSteer => self.roll_steer.to_vec(),
            EffectKind::RollCamber => self.roll_camber.to_vec(),
            EffectKind::LoadTransferDistribution => {
                vec![self.load_transfer_front_share.unwrap_or(nominal_share)]
            }
            EffectKind::AeroLoad => self.aero_load.to_vec(),
            EffectKind::RoadFriction => vec![self.friction_scale.unwrap_or(1.0)],
            EffectKind::RoadBank => vec![self.road_bank],
            EffectKind::CorneringStiffness => {
                self.cornering_stiffness_scale.unwrap_or([1.0; 2]).to_vec()
            }
            EffectKind::YawInertia => vec![self.yaw_inertia_scale.unwrap_or(1.0)],
            EffectKind::SensorDelay => vec![self.sensors.delay],
            EffectKind::SensorBias => vec![
                self.sensors.yaw_rate_bias,
                self.sensors.ay_bias,
                self.sensors.beta_bias,
            ],
            EffectKind::AccelerometerRoll => vec![self.sensors.roll_gradient],
            EffectKind::AccelerometerPosition => vec![self.sensors.accelerometer_x],
            EffectKind::LongitudinalLoadTransfer => vec![self.longitudinal_load_transfer],
            EffectKind::CombinedSlip => self.combined_slip.unwrap_or([0.0, 0.6, 0.0]).to_vec(),
            EffectKind::BankProfile => self.bank_profile.to_vec(),
            EffectKind::SteerPath => self.steer_path.to_vec(),
        }
    }

    /// True when any effect needs the roll degree of freedom.
    pub fn uses_roll(&self) -> bool {
        self.roll_steer != [0.0; 2] || self.roll_camber != [0.0; 2]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bound_is_named_for_what_it_is() {
        let relaxation = EffectKind::RelaxationLength.parameters()[0];
        assert_eq!(relaxation.bound_at(0.0), Some(Bound::Physical));
        assert_eq!(relaxation.bound_at(3.0), Some(Bound::Search));
        assert_eq!(relaxation.bound_at(0.5), None);
        // Within 1e-9 of the span, not beyond.
        assert_eq!(relaxation.bound_at(3.0 * 0.9e-9), Some(Bound::Physical));
        assert_eq!(relaxation.bound_at(3.0 * 1.1e-9), None);
        let bank = EffectKind::RoadBank.parameters()[0];
        assert_eq!(bank.bound_at(-0.15), Some(Bound::Search));
        // Combined slip's drive split and brake balance (not its share of
        // m·ax, which may exceed 1).
        for share in EffectKind::CombinedSlip.parameters()[..2]
            .iter()
            .chain(EffectKind::LoadTransferDistribution.parameters())
        {
            assert_eq!(share.bound_at(0.0), Some(Bound::Physical));
            assert_eq!(share.bound_at(1.0), Some(Bound::Physical));
        }
        // A physical limit is where the quantity ends: below zero for a
        // length, a delay or a share, above one for a share of a whole.
        for k in EffectKind::ALL {
            for q in k.parameters() {
                let (lo, hi) = q.bounds;
                if q.limits.0 == Bound::Physical {
                    assert_eq!(lo, 0.0, "{}.{}", k.name(), q.name);
                }
                if q.limits.1 == Bound::Physical {
                    assert_eq!((lo, hi), (0.0, 1.0), "{}.{}", k.name(), q.name);
                }
            }
        }
    }

    #[test]
    fn names_round_trip_and_off_values_are_the_base_model() {
        for k in EffectKind::ALL {
            assert_eq!(EffectKind::from_name(k.name()), Some(k));
            let p = k.parameters();
            assert!((1..=3).contains(&p.len()), "{}", k.name());
            for q in p {
                assert!(q.bounds.0 < q.bounds.1);
                assert!(q.off.is_nan() || (q.bounds.0..=q.bounds.1).contains(&q.off));
            }
            // Setting the off values gives the base model back (the share's
            // off value is the vehicle's own, tested in the model).
            if k != EffectKind::LoadTransferDistribution {
                let mut e = EffectSet::default();
                let off: Vec<f64> = p.iter().map(|q| q.off).collect();
                e.set(k, &off);
                assert_eq!(e.get(k, 0.5), off);
            }
        }
        assert_eq!(EffectKind::from_name("relaxation"), None);
    }
}
