//! Why axle characteristics identified from the runs are no tyre
//! ([`NoTyre`]): a characteristic on a limit no tyre reaches
//! ([`AxleLimit`]), an axle whose force peaks before 2° of slip, or one far
//! outside the prior of the car's tyres. A base that is no tyre gives no
//! model-form verdict; a candidate fitted with such axles is no verdict.
//! Units: rad, k in 1/rad, D dimensionless.

use crate::diagnose::model::axles::{coefficient, friction, AXLE_BOUNDS, SHAPE};
use serde::Serialize;

/// Names of the three characteristics.
pub const AXLE_NAMES: [&str; 3] = [
    "front cornering coefficient",
    "rear cornering coefficient",
    "peak friction",
];

/// What an axle characteristic on the edge of its box means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AxleLimit {
    /// An axle that makes (almost) no cornering force.
    NoForce,
    /// An axle that (almost) never slips.
    Rigid,
    /// A road with (almost) no grip.
    NoGrip,
    /// A tyre that never saturates on these runs: the runs stay in the
    /// linear range and the peak friction is not identified.
    Linear,
}

impl AxleLimit {
    /// Whether a base on this limit is no tyre at all (degenerate).
    pub fn degenerate(self) -> bool {
        self != AxleLimit::Linear
    }

    /// The limit parameter `i` of shares `p` stands on, if any.
    pub fn of(i: usize, p: &[f64]) -> Option<Self> {
        let (lo, hi) = AXLE_BOUNDS[i];
        let tol = 1e-6 * (hi - lo);
        let (low, high) = (p[i] - lo <= tol, hi - p[i] <= tol);
        match (i, low, high) {
            (2, true, _) => Some(AxleLimit::NoGrip),
            (2, _, true) => Some(AxleLimit::Linear),
            (_, true, _) => Some(AxleLimit::NoForce),
            (_, _, true) => Some(AxleLimit::Rigid),
            _ => None,
        }
    }
}

/// The smallest slip angle at which a pneumatic tyre's lateral force
/// peaks, rad (2°): racing slicks peak at 4–6°, road tyres later.
pub const PEAK_SLIP_MIN: f64 = 0.035;

/// The slip angle at which an axle of coefficient `k` and friction `d`
/// peaks, rad: `tan(π/2C)/B` with `B = k/(C·D)`.
pub fn peak_slip(k: f64, d: f64) -> f64 {
    (std::f64::consts::FRAC_PI_2 / SHAPE).tan() * SHAPE * d / k
}

/// The axles of shares `p` that peak before [`PEAK_SLIP_MIN`]: an axle
/// that saturates within a fraction of a degree acts like a sign function
/// of its slip, and its replays turn hypersensitive to their start (their
/// standard errors say nothing).
pub(crate) fn early_peaks(p: &[f64]) -> Vec<NoTyre> {
    let d = friction(p[2]);
    [Axle::Front, Axle::Rear]
        .into_iter()
        .zip(&p[..2])
        .filter_map(|(axle, &s)| {
            let peak_slip = peak_slip(coefficient(s), d);
            (peak_slip < PEAK_SLIP_MIN).then(|| NoTyre::EarlyPeak {
                axle,
                peak_slip,
                coefficient_over_friction: coefficient(s) / d,
            })
        })
        .collect()
}

/// An axle of the car.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Axle {
    /// The front axle.
    Front,
    /// The rear axle.
    Rear,
}

impl Axle {
    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Axle::Front => "front",
            Axle::Rear => "rear",
        }
    }
}

/// Why axle characteristics are no tyre (the base is then degenerate, and
/// a candidate fitted with such axles cannot be a verdict).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum NoTyre {
    /// A characteristic on a limit no tyre reaches (a rigid axle, one
    /// without force, a road without grip).
    Limit {
        /// The characteristic ([`AXLE_NAMES`]).
        parameter: &'static str,
        /// The limit.
        limit: AxleLimit,
    },
    /// An axle whose force peaks before [`PEAK_SLIP_MIN`] of slip.
    EarlyPeak {
        /// The axle.
        axle: Axle,
        /// The slip angle of its peak, rad.
        peak_slip: f64,
        /// Its cornering coefficient over the peak friction, 1/rad.
        coefficient_over_friction: f64,
    },
    /// A characteristic far outside the prior of the car's tyres (beyond
    /// [`crate::diagnose::base::prior::OUTSIDE_PRIOR`] standard deviations):
    /// no tyre of that class.
    OutsidePrior {
        /// The characteristic ([`AXLE_NAMES`]).
        parameter: &'static str,
        /// Its value (1/rad, or dimensionless for the friction).
        value: f64,
        /// The prior's 95 % range.
        range: [f64; 2],
        /// Standard deviations from the prior's centre, in `ln x`.
        z: f64,
    },
}
