//! The library of candidate effects: the one list (expanded by
//! `generate.rs` into [`EffectKind`], `EffectKind::ALL`, the dispatch and
//! serde by name) and one [`Effect`] impl per effect, which is everything
//! the crate knows of it but its physics: its name, parameters (units,
//! search bounds, what bounds them, the values that switch it off), the
//! signature that separates it from its look-alikes, what a run must carry
//! for it to show, whether it acts through roll, its value on the
//! augmented proving ground, and [`Effect::apply`], which sets its numbers
//! on the vehicle model's [`Effects`] (the physics that reads them is the
//! vehicle model's, [`crate::vehicle`]).
//!
//! `apply` acts on a copy of the base model's effects: it adds to what the
//! base has where the base may have some already (aero load, road bank, the
//! bank profile, longitudinal load transfer), scales what it scales (yaw
//! inertia, road friction), and replaces the rest. A fit calls it in plain
//! and in dual numbers alike, so its derivatives flow through it.
//!
//! The list's order is the order of `EffectKind::ALL` (the candidates of a
//! campaign that names none, error messages, the report's tables). Signs
//! follow ISO 8855; units: SI, rad; scales are dimensionless factors on
//! the base model's value.

use super::generate::effect_library;
use super::{par, Effect, Needs, Parameter, PerRoll};
use crate::scalar::Scalar;
use crate::vehicle::{Effects, PASSENGER_CAR_ROLL_GRADIENT};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

effect_library! {
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
    /// The steering ratio's error: the road wheels turn g·(δ + k₃·δ³) for
    /// a logged steer δ.
    SteeringRatio,
    /// An inertial unit yawed in its mount: its accelerometer reads part
    /// of the longitudinal acceleration as lateral.
    MountYaw,
}

impl Effect for RelaxationLength {
    const NAME: &'static str = "relaxation_length";
    const PARAMETERS: &'static [Parameter] =
        &[par("relaxation_length", "m", 0.0, 0.0, 3.0).floor()];
    const SIGNATURE: &'static str =
        "a lag that shrinks with speed (time constant σ/u): compare runs at two speeds";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.8];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.relaxation_length = p[0];
    }
}

impl Effect for SteeringCompliance {
    const NAME: &'static str = "steering_compliance";
    const PARAMETERS: &'static [Parameter] =
        &[par("steer_per_front_force", "rad/kN", 0.0, -0.02, 0.05)];
    /// At one lateral acceleration the front axle force (m·ay·b/l), and
    /// with it the steer lost, is the same at every speed: speed does not
    /// separate it (fresh-eyes round 18 followed that advice in vain).
    const SIGNATURE: &'static str = "a steer lost in proportion to the front axle force, at once and the same at every speed for one lateral acceleration (in the linear range a lower front cornering stiffness does the same; a roll steer follows the roll, late by the roll mode; near the limit the force saturates and so does the steer lost): a ramp steer to the limit, and a steer step";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.003];
    /// rad/kN to the model's rad/N.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.steering_compliance = p[0] * 1e-3;
    }
}

impl Effect for RollSteer {
    const NAME: &'static str = "roll_steer";
    const PARAMETERS: &'static [Parameter] = &[
        par("front", "rad/rad", 0.0, -0.5, 0.5).per_roll(PerRoll::Steer),
        par("rear", "rad/rad", 0.0, -0.5, 0.5).per_roll(PerRoll::Steer),
    ];
    const SIGNATURE: &'static str = "a steer change that follows body roll through the tyre's slip curve (saturates at the limit): a ramp steer to the limit";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = true;
    const TRUTH: &'static [f64] = &[-0.15, 0.0];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.roll_steer = [p[0], p[1]];
    }
}

impl Effect for RollCamber {
    const NAME: &'static str = "roll_camber";
    const PARAMETERS: &'static [Parameter] = &[
        par("front", "N/N per rad", 0.0, -8.0, 8.0).per_roll(PerRoll::CamberThrust),
        par("rear", "N/N per rad", 0.0, -8.0, 8.0).per_roll(PerRoll::CamberThrust),
    ];
    const SIGNATURE: &'static str = "a force change proportional to roll and load that does not saturate with slip: a ramp steer to the limit";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = true;
    const TRUTH: &'static [f64] = &[-1.5, 0.0];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.roll_camber = [p[0], p[1]];
    }
}

impl Effect for LoadTransferDistribution {
    const NAME: &'static str = "load_transfer_distribution";
    /// Off (NaN) is the vehicle's own share.
    const PARAMETERS: &'static [Parameter] = &[par("front_share", "-", f64::NAN, 0.0, 1.0).share()];
    const SIGNATURE: &'static str = "a balance change only at high lateral acceleration: compare low- and high-level steps at one speed";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.85];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.transfer_share = Some(p[0]);
    }
}

impl Effect for AeroLoad {
    const NAME: &'static str = "aero_load";
    /// No negative down-force (a lift is not the model): 0 is a physical
    /// limit.
    const PARAMETERS: &'static [Parameter] = &[
        par("front", "N/(m/s)²", 0.0, 0.0, 6.0).floor(),
        par("rear", "N/(m/s)²", 0.0, 0.0, 6.0).floor(),
    ];
    const SIGNATURE: &'static str = "grip and balance that change with speed squared at equal lateral acceleration: steps at two speeds, same level";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[1.5, 2.0];
    /// On top of the base model's own down-force.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.aero_load = [e.aero_load[0] + p[0], e.aero_load[1] + p[1]];
    }
}

impl Effect for RoadFriction {
    const NAME: &'static str = "road_friction";
    const PARAMETERS: &'static [Parameter] = &[par("friction_scale", "-", 1.0, 0.3, 1.5)];
    const SIGNATURE: &'static str =
        "no change in the linear range, a lower limit: a ramp steer to the limit";
    const NEEDS: Needs = Needs::FrictionLimit;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.75];
    /// A scale on the campaign's road friction.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.friction_scale *= p[0];
    }
}

impl Effect for RoadBank {
    const NAME: &'static str = "road_bank";
    const PARAMETERS: &'static [Parameter] = &[par("bank", "rad", 0.0, -0.15, 0.15)];
    const SIGNATURE: &'static str =
        "a constant drift present before any steer: a straight run in both directions of travel";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.03];
    /// On top of the base model's own bank.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.road_bank += p[0];
    }
}

impl Effect for CorneringStiffness {
    const NAME: &'static str = "cornering_stiffness";
    const PARAMETERS: &'static [Parameter] = &[
        par("front_scale", "-", 1.0, 0.4, 2.0),
        par("rear_scale", "-", 1.0, 0.4, 2.0),
    ];
    const SIGNATURE: &'static str =
        "a change of the linear gains at every speed and level: steps at two speeds";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.8, 1.0];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.cornering_stiffness_scale = [p[0], p[1]];
    }
}

impl Effect for YawInertia {
    const NAME: &'static str = "yaw_inertia";
    const PARAMETERS: &'static [Parameter] = &[par("scale", "-", 1.0, 0.4, 2.5)];
    const SIGNATURE: &'static str =
        "yaw-rate transient only, same steady state: a frequency sweep (yaw-rate phase)";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[1.3];
    /// A scale on the vehicle file's yaw inertia.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.yaw_inertia_scale *= p[0];
    }
}

impl Effect for SensorDelay {
    const NAME: &'static str = "sensor_delay";
    const PARAMETERS: &'static [Parameter] = &[par("delay", "s", 0.0, 0.0, 0.3).floor()];
    /// At one speed a delay of every sensor and a dead time in the steer
    /// path give the same responses: speed tells it from a relaxation
    /// length, and only a speed change at a held steer from a steer path.
    const SIGNATURE: &'static str = "every response channel late alike, by a time independent of speed (phase ∝ frequency), where a relaxation length's lag σ/u shrinks with speed and a lag in the steer path delays only what the steer causes, not the response to a speed change at a held steer (a small difference within ordinary accelerations): a sweep or steps at two speeds";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.05];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.sensors.delay = p[0];
    }
}

impl Effect for SensorBias {
    const NAME: &'static str = "sensor_bias";
    const PARAMETERS: &'static [Parameter] = &[
        par("yaw_rate", "rad/s", 0.0, -0.05, 0.05),
        // Added to ay after the dynamics (`Sensors::seen`); the other
        // two also set the replay's start (`Prepared::start_of`).
        par("ay", "m/s²", 0.0, -1.0, 1.0).additive(),
        par("beta", "rad", 0.0, -0.05, 0.05),
    ];
    const SIGNATURE: &'static str = "a constant offset that does not depend on the vehicle's direction of travel: a straight run both ways";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.008, 0.2, 0.004];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.sensors.yaw_rate_bias = p[0];
        e.sensors.ay_bias = p[1];
        e.sensors.beta_bias = p[2];
    }
}

impl Effect for AccelerometerRoll {
    const NAME: &'static str = "accelerometer_roll";
    const PARAMETERS: &'static [Parameter] =
        &[par("roll_gradient", "rad/(m/s²)", 0.0, -0.03, 0.03)];
    const SIGNATURE: &'static str = "lateral acceleration reads high by g·sin φ while the yaw rate agrees: compare ay with u·r in steady turns";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[PASSENGER_CAR_ROLL_GRADIENT];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.sensors.roll_gradient = p[0];
    }
}

impl Effect for AccelerometerPosition {
    const NAME: &'static str = "accelerometer_position";
    const PARAMETERS: &'static [Parameter] = &[par("x", "m", 0.0, -2.5, 2.5)];
    /// The inertial unit's position: its accelerometer and a sideslip it
    /// measures ([`crate::vehicle::Sensors`]).
    const SIGNATURE: &'static str =
        "ay error proportional to yaw acceleration, a sideslip error proportional to yaw rate over speed: a frequency sweep and steady turns at two speeds";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.8];
    /// A correction to the accelerometer's position the campaign states
    /// (`[sensors] accelerometer_x`, 0 where none).
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.sensors.accelerometer_x += p[0];
    }
}

impl Effect for LongitudinalLoadTransfer {
    const NAME: &'static str = "longitudinal_load_transfer";
    const PARAMETERS: &'static [Parameter] = &[par("share", "-", 0.0, 0.0, 2.0).floor()];
    const SIGNATURE: &'static str = "a balance change that follows braking and throttle, none at constant speed: steady turns braking and accelerating";
    const NEEDS: Needs = Needs::LongitudinalAcceleration;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[1.0];
    /// On top of the base model's own share.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.longitudinal_load_transfer += p[0];
    }
}

impl Effect for CombinedSlip {
    const NAME: &'static str = "combined_slip";
    /// Off when the tyres carry none of m·ax (force_share 0): the lateral
    /// forces are then the pure-slip ones exactly, whatever the split and
    /// balance (whose off values, rear-wheel drive and 60 % of the braking
    /// in front, are only starts). The share's upper bound is a search
    /// bound (the tyres may carry more than m·ax: drag and rolling
    /// resistance against the throttle, an ax logged low).
    const PARAMETERS: &'static [Parameter] = &[
        par("drive_front_share", "-", 0.0, 0.0, 1.0).share(),
        par("brake_front_share", "-", 0.6, 0.0, 1.0).share(),
        par("force_share", "-", 0.0, 0.0, 1.5).floor(),
    ];
    const SIGNATURE: &'static str = "grip lost in proportion to the longitudinal force, most near the limit: braking in a turn against coasting at one lateral acceleration";
    const NEEDS: Needs = Needs::LongitudinalAcceleration;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.0, 0.65, 1.0];
    /// In place of the base model's.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.combined_slip = Some(crate::vehicle::CombinedSlip {
            drive_front_share: p[0],
            brake_front_share: p[1],
            force_share: p[2],
        });
    }
}

impl Effect for BankProfile {
    const NAME: &'static str = "bank_profile";
    const PARAMETERS: &'static [Parameter] = &[
        par("scale", "-", 0.0, -0.5, 2.0),
        par("offset", "rad", 0.0, -0.2, 0.2),
    ];
    const SIGNATURE: &'static str = "a drift that follows the measured bank, not the steer: the same corner driven at two speeds";
    const NEEDS: Needs = Needs::BankChannel;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[1.0, 0.0];
    /// On top of the base model's scale and constant bank.
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.bank_profile_scale += p[0];
        e.road_bank += p[1];
    }
}

impl Effect for SteerPath {
    const NAME: &'static str = "steer_path";
    const PARAMETERS: &'static [Parameter] = &[
        par("delay", "s", 0.0, 0.0, 0.5).floor(),
        par("lag", "s", 0.0, 0.0, 0.5).floor(),
    ];
    const SIGNATURE: &'static str = "a lag in the steer input, not the sensors: the response to a steer step changes shape (first-order filtered) as well as time, while the responses without steer (to speed changes, to the bank, a sensor's offset) keep their timing; a sensor delay shifts every channel alike: a steer step, and a speed change on a straight";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    const TRUTH: &'static [f64] = &[0.05, 0.15];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.steer_path = crate::vehicle::SteerPath {
            delay: p[0],
            lag: p[1],
            ..e.steer_path
        };
    }
}

impl Effect for SteeringRatio {
    const NAME: &'static str = "steering_ratio";
    /// The gain g is the car's road-wheel steer per logged steer: a log
    /// whose steer reads 8 % high (a ratio stated 8 % low) has g = 1/1.08
    /// = 0.926. Its bounds 0.7–1.4 are a search range: a ratio stated for
    /// another car of the class (passenger cars' overall ratios run from
    /// about 12:1 to 20:1, Gillespie 1992 ch. 8; a sports car's quick
    /// rack about 10:1) is wrong by a factor within 20/14 = 1.43 either
    /// way of the class's middle. The cubic k₃ (rad⁻² of logged road-wheel
    /// steer) is a variable-ratio rack's: the local ratio falls off centre
    /// as 1/(1 + 3k₃δ²); racks that go from about 16:1 on centre to 12:1
    /// at 0.35 rad of road-wheel steer (−25 %) have k₃ ≈ +0.9, so ±3 rad⁻²
    /// holds a ratio that changes by up to half from centre to lock in
    /// either direction (quicker or slower off centre).
    const PARAMETERS: &'static [Parameter] = &[
        par("gain", "-", 1.0, 0.7, 1.4),
        par("cubic", "rad⁻²", 0.0, -3.0, 3.0),
    ];
    /// A front cornering-stiffness scale multiplies the whole front slip
    /// (steer, sideslip and yaw rate alike), a steering compliance takes a
    /// steer in proportion to the front force: both change the understeer
    /// gradient, so the yaw-rate gain's ratio between two speeds. A ratio
    /// multiplies the steer alone: every steer-driven response scaled by
    /// one factor at every speed and level, its speed dependence and its
    /// shape in time kept (a steer path changes the timing, not the size).
    const SIGNATURE: &'static str = "every response to steer scaled by one factor at every speed, its timing and its change with speed kept (the understeer gradient is the car's): a front cornering stiffness or a steering compliance changes the understeer gradient and with it the gain's ratio between speeds, a steer path the timing; the cubic term grows the gain with the steer at one speed where a tyre's saturation shrinks it: steps at two speeds, and at two levels at one low speed";
    const NEEDS: Needs = Needs::Nothing;
    const USES_ROLL: bool = false;
    /// A ratio stated 10 % quick, constant.
    const TRUTH: &'static [f64] = &[0.9, 0.0];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.steer_path.gain = p[0];
        e.steer_path.cubic = p[1];
    }
}

impl Effect for MountYaw {
    const NAME: &'static str = "mount_yaw";
    /// ψₘ, ISO 8855 (z up): positive turns the unit's x axis to the left,
    /// and its accelerometer reads ay·cos ψₘ − ax·sin ψₘ
    /// ([`crate::vehicle::Sensors`]). Its bounds ±0.1 rad (±5.7°) are a
    /// search range: a unit squared to the car's centre line by eye or
    /// against a bracket sits within a few degrees of it (a 0.3 m unit
    /// with one end 1.5 cm off the line is turned 2.9°), and a turn
    /// beyond 5° is plain to see on the car.
    const PARAMETERS: &'static [Parameter] = &[par("angle", "rad", 0.0, -0.1, 0.1)];
    /// A sensor offset reads the same at every ax, a position ahead of
    /// the centre of gravity adds x·ṙ (zero on a straight and in a steady
    /// turn), a rolling unit g·sin φ (with ay): only the mount's yaw reads
    /// braking and throttle on a straight as a lateral acceleration,
    /// −ax·sin ψₘ, with the yaw rate and the sideslip unmoved.
    const SIGNATURE: &'static str = "a lateral acceleration read in proportion to the longitudinal one (−ax·sin ψₘ) while the yaw rate and the sideslip agree: braking and accelerating on a straight read as a lateral acceleration, where a sensor offset stays the same at every ax, an accelerometer ahead of the centre of gravity reads the yaw acceleration (nothing on a straight) and a rolling one g·sin φ with ay: a straight braked and accelerated";
    const NEEDS: Needs = Needs::LongitudinalAcceleration;
    const USES_ROLL: bool = false;
    /// Turned 3° to the left.
    const TRUTH: &'static [f64] = &[0.05236];
    fn apply<T: Scalar>(p: &[T], e: &mut Effects<T>) {
        e.sensors.mount_yaw = p[0];
    }
}
