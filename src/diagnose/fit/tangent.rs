//! Exact derivatives of a fit's residuals: the runs replayed once in dual
//! numbers ([`crate::sim::tangent`]) instead of once per parameter by
//! forward differences. A [`Layout`] says what a parameter vector sets —
//! the axle characteristics of an identified base ([`crate::diagnose::base::identify`]), the
//! effects' parameters ([`crate::diagnose::effects::EffectSet::set`]), the roll
//! dynamics — and builds the model's numbers, its tyres' parameters, its
//! sensors and its steer path in a dual scalar (`DualSVec64<N>`, the
//! parameters seeded in directions `0..n`, two more reserved for the
//! model's implicit solves). Every effect acts linearly on the numbers it
//! sets (an offset added, a value scaled), so a number's derivative is the
//! parameter's times a constant; the axle characteristics go through
//! their shares' closed forms in the dual scalar itself.
//!
//! The Jacobian is that of the discrete replay the residuals come from,
//! to rounding: the same grid, method (RK4 or ROS34PW2), stage inputs and
//! load-transfer seeds. The residuals themselves stay the plain replay's.
//! A model whose tyres have no generic force (a model registered from
//! outside the crate) falls back to forward differences. Units: SI, rad.

use crate::diagnose::effects::sensors::SensorsOf;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::fit::layout::{fits_roll, Layout};
use crate::diagnose::model::axles::axle_parameters;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::{Augmented, SteerPath};
use crate::manoeuvre::interpolate_of;
use crate::scalar::Scalar;
use crate::sim::tangent::ModelOf;
use crate::vehicle::wheels::ParamTyres;
use crate::vehicle::{ModelScalars, LOAD_TOLERANCE};
use nalgebra::{ComplexField, DMatrix};
use num_dual::DualSVec64;

/// A model in a dual scalar: its vehicle numbers and tyres, sensors and
/// steer path, built from a parameter vector.
struct Tangent<T> {
    scalars: ModelScalars<T>,
    tyre_params: Option<[Vec<T>; 2]>,
    sensors: SensorsOf<T>,
    steer_path: SteerPath<T>,
}

/// `value` with the derivative of parameter `p` (seeded) times `factor`:
/// the number an effect sets linearly, `value = c + factor·p`.
fn moved<T: Scalar>(value: f64, p: T, factor: f64) -> T {
    T::from(value) + (p - p.re()) * factor
}

impl Layout {
    /// The numbers of `plain` (the plain model of `p`) in scalar `T`, with
    /// the parameters `pt` (`p` seeded) moving those they set.
    fn tangent<T: Scalar>(&self, plain: &Augmented, pt: &[T]) -> Tangent<T> {
        let (model, friction) = plain.model();
        let e = &plain.effects;
        let mut sc = model.scalars(friction).lift::<T>([pt.len(), pt.len() + 1]);
        let mut sensors = e.sensors.of::<T>();
        let mut path = SteerPath {
            delay: T::from(e.steer_path[0]),
            lag: T::from(e.steer_path[1]),
        };
        let mut k = 0;
        let tyre_params = self.axle.then(|| {
            k = 3;
            axle_parameters(&pt[..3])
        });
        for &kind in &self.kinds {
            let q = &pt[k..k + kind.parameters().len()];
            let d = |x: &mut T, i: usize, factor: f64| *x = moved(x.re(), q[i], factor);
            match kind {
                EffectKind::RelaxationLength => d(&mut sc.relaxation_length, 0, 1.0),
                EffectKind::SteeringCompliance => d(&mut sc.steering_compliance, 0, 1e-3),
                EffectKind::RollSteer => {
                    d(&mut sc.roll_steer[0], 0, 1.0);
                    d(&mut sc.roll_steer[1], 1, 1.0);
                }
                EffectKind::RollCamber => {
                    d(&mut sc.roll_camber[0], 0, 1.0);
                    d(&mut sc.roll_camber[1], 1, 1.0);
                }
                EffectKind::LoadTransferDistribution => d(&mut sc.transfer_share, 0, 1.0),
                EffectKind::AeroLoad => {
                    d(&mut sc.aero_load[0], 0, 1.0);
                    d(&mut sc.aero_load[1], 1, 1.0);
                }
                EffectKind::RoadFriction => d(&mut sc.friction, 0, plain.friction),
                EffectKind::RoadBank => d(&mut sc.road_bank, 0, 1.0),
                EffectKind::CorneringStiffness => {
                    d(&mut sc.stiffness_scale[0], 0, 1.0);
                    d(&mut sc.stiffness_scale[1], 1, 1.0);
                }
                EffectKind::YawInertia => d(&mut sc.yaw_inertia, 0, plain.base.vehicle.yaw_inertia),
                EffectKind::SensorDelay => d(&mut sensors.delay, 0, 1.0),
                EffectKind::SensorBias => {
                    d(&mut sensors.yaw_rate_bias, 0, 1.0);
                    d(&mut sensors.ay_bias, 1, 1.0);
                    d(&mut sensors.beta_bias, 2, 1.0);
                }
                EffectKind::AccelerometerRoll => d(&mut sensors.roll_gradient, 0, 1.0),
                EffectKind::AccelerometerPosition => d(&mut sensors.accelerometer_x, 0, 1.0),
                EffectKind::LongitudinalLoadTransfer => {
                    d(&mut sc.longitudinal_load_transfer, 0, 1.0)
                }
                EffectKind::CombinedSlip => {
                    if let Some(c) = sc.combined_slip.as_mut() {
                        for (i, x) in c.iter_mut().enumerate() {
                            d(x, i, 1.0);
                        }
                    }
                }
                EffectKind::BankProfile => {
                    d(&mut sc.bank_profile_scale, 0, 1.0);
                    d(&mut sc.road_bank, 1, 1.0);
                }
                EffectKind::SteerPath => {
                    d(&mut path.delay, 0, 1.0);
                    d(&mut path.lag, 1, 1.0);
                }
            }
            k += q.len();
        }
        if fits_roll(&self.kinds) {
            sc.roll[1] = moved(sc.roll[1].re(), pt[k], 1.0);
            sc.roll[2] = moved(sc.roll[2].re(), pt[k + 1], 1.0);
        }
        Tangent {
            scalars: sc,
            tyre_params,
            sensors,
            steer_path: path,
        }
    }
}

/// Largest parameter count the exact Jacobian serves (two more directions
/// are the model's implicit solves'); beyond it, forward differences.
const MAX_PARAMETERS: usize = 14;

/// The Jacobian of the scaled residuals of `runs` (rows in run order, as
/// the problem writes them) at `p` for `layout`, from one dual replay of
/// each run; None when the model's tyres have no generic force or there
/// are too many parameters.
pub(crate) fn jacobian(
    (layout, plain): (&Layout, &Augmented),
    runs: &[&Prepared],
    scales: &[f64; 3],
    p: &[f64],
) -> Option<DMatrix<f64>> {
    match p.len() + 2 {
        0..=4 => jacobian_n::<4>((layout, plain), runs, scales, p),
        5..=8 => jacobian_n::<8>((layout, plain), runs, scales, p),
        n if n <= MAX_PARAMETERS + 2 => jacobian_n::<16>((layout, plain), runs, scales, p),
        _ => None,
    }
}

fn jacobian_n<const N: usize>(
    (layout, plain): (&Layout, &Augmented),
    runs: &[&Prepared],
    scales: &[f64; 3],
    p: &[f64],
) -> Option<DMatrix<f64>> {
    use rayon::prelude::*;
    let (model, _) = plain.model();
    let pt: Vec<DualSVec64<N>> = p
        .iter()
        .enumerate()
        .map(|(k, &v)| DualSVec64::<N>::variable(v, k))
        .collect();
    let t = layout.tangent(plain, &pt);
    let tyres = match &t.tyre_params {
        Some(params) => ParamTyres::new(&model.front, &model.rear, params.clone()),
        None => ParamTyres::constant(&model.front, &model.rear),
    }?;
    let m = ModelOf {
        model: &model,
        scalars: t.scalars,
        tyres,
        load_tolerance: runs.first().map_or(LOAD_TOLERANCE, |r| r.load_tolerance),
    };
    let blocks: Vec<Vec<[f64; N]>> = runs
        .par_iter()
        .map(|r| run_rows(&m, &t, plain, r, scales))
        .collect();
    let rows: usize = blocks.iter().map(Vec::len).sum();
    let mut j = DMatrix::zeros(rows, p.len());
    for (i, row) in blocks.iter().flatten().enumerate() {
        for k in 0..p.len() {
            j[(i, k)] = row[k];
        }
    }
    Some(j)
}

/// One run's rows of the Jacobian: its replay in duals, seen by the
/// sensors, at its residual times, over its channel scales.
fn run_rows<const N: usize>(
    m: &ModelOf<DualSVec64<N>>,
    t: &Tangent<DualSVec64<N>>,
    plain: &Augmented,
    run: &Prepared,
    scales: &[f64; 3],
) -> Vec<[f64; N]>
where
    DualSVec64<N>: Scalar + ComplexField,
{
    type D<const N: usize> = DualSVec64<N>;
    let (drive, logged_t, logged_steer) = run.unsteered_drive(plain);
    let steer: Option<Vec<D<N>>> = (!t.steer_path.is_off()).then(|| {
        t.steer_path
            .apply(logged_t, logged_steer, &drive.stage_times())
    });
    let ((beta0, r0), beta_measured) = run.start_values();
    let beta = if beta_measured {
        D::<N>::from(beta0) - t.sensors.beta_bias
    } else {
        D::<N>::from(beta0)
    };
    let r = D::<N>::from(r0) - t.sensors.yaw_rate_bias;
    let first = drive.first_inputs(plain.model().1);
    let steer0 = steer.as_ref().map_or(D::<N>::from(first.steer), |s| s[0]);
    let x0 = m
        .model
        .quasi_static_of(&m.scalars, beta, r, first.speed, steer0);
    let h = m.replay(drive, steer.as_deref(), x0);
    let seen = t.sensors.seen(&h.t, &h.yaw_rate, &h.ay, &h.beta);
    let mut rows = Vec::with_capacity(run.count());
    for (c, measured) in &run.measured {
        let ys = &seen[match c {
            Channel::YawRate => 0,
            Channel::Ay => 1,
            Channel::Beta => 2,
        }];
        let s = scales[c.index()];
        for &time in run.times.iter().take(measured.len()) {
            let y = interpolate_of(&h.t, ys, D::<N>::from(time));
            // A diverged replay's residual is a constant (1e6): no slope.
            rows.push(std::array::from_fn(|k| {
                if y.re.is_finite() {
                    y.part(k) / s
                } else {
                    0.0
                }
            }));
        }
    }
    rows
}

#[cfg(test)]
mod tests;
