//! Exact derivatives of a fit's residuals: the runs replayed once in dual
//! numbers ([`crate::sim::tangent`]) instead of once per parameter by
//! forward differences. The model's numbers in a dual scalar
//! (`DualSVec64<N>`, the parameters seeded in directions `0..n`, two more
//! reserved for the model's implicit solves) are built by the same code as
//! the plain model of a parameter vector: the [`Layout`] applies each
//! effect to the base model's effects ([`Layout::effects_of`], every
//! effect's [`crate::diagnose::effects::Effect::apply`] written once for
//! any scalar), so the derivatives flow through the effects' own
//! arithmetic — the vehicle's numbers, the sensors and the steer path
//! alike; the axle characteristics go through their shares' closed forms
//! in the dual scalar itself.
//!
//! The Jacobian is that of the discrete replay the residuals come from,
//! to rounding: the same grid, method (RK4 or ROS34PW2), stage inputs and
//! load-transfer seeds. The residuals themselves stay the plain replay's.
//! A model whose tyres have no generic force (a model registered from
//! outside the crate) falls back to forward differences. Units: SI, rad.

use crate::diagnose::fit::layout::Layout;
use crate::diagnose::model::axles::axle_parameters;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::Augmented;
use crate::manoeuvre::interpolate_of;
use crate::scalar::Scalar;
use crate::sim::tangent::ModelOf;
use crate::vehicle::wheels::ParamTyres;
use crate::vehicle::{Effects, ModelScalars, LOAD_TOLERANCE};
use nalgebra::{ComplexField, DMatrix};
use num_dual::DualSVec64;

/// A model in a dual scalar: its numbers (effects, sensors and steer path
/// among them) and its tyres' parameters, built from a parameter vector.
struct Tangent<T> {
    scalars: ModelScalars<T>,
    tyre_params: Option<[Vec<T>; 2]>,
}

impl Layout {
    /// The numbers of the model of `pt` (the parameters, seeded) on the
    /// base model's effects `base`, in scalar `T`, for `plain` (the plain
    /// model of the same vector: its vehicle and road).
    fn tangent<T: Scalar>(&self, base: &Effects, plain: &Augmented, pt: &[T]) -> Tangent<T> {
        let effects = self.effects_of(base, pt);
        let directions = [pt.len(), pt.len() + 1];
        Tangent {
            scalars: plain.model.scalars_of(effects, plain.friction, directions),
            tyre_params: self.axle.then(|| axle_parameters(&pt[self.axles()])),
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
    model: Model,
    runs: &[&Prepared],
    scales: &[f64; 3],
    p: &[f64],
) -> Option<DMatrix<f64>> {
    match p.len() + 2 {
        0..=4 => jacobian_n::<4>(model, runs, scales, p),
        5..=8 => jacobian_n::<8>(model, runs, scales, p),
        n if n <= MAX_PARAMETERS + 2 => jacobian_n::<16>(model, runs, scales, p),
        _ => None,
    }
}

/// What a Jacobian is taken of: the layout of the vector, the base model's
/// effects it applies to, and the plain model of the vector.
pub(crate) type Model<'a> = (&'a Layout, &'a Effects, &'a Augmented);

fn jacobian_n<const N: usize>(
    (layout, base, plain): Model,
    runs: &[&Prepared],
    scales: &[f64; 3],
    p: &[f64],
) -> Option<DMatrix<f64>> {
    use rayon::prelude::*;
    let model = &plain.model;
    let pt: Vec<DualSVec64<N>> = p
        .iter()
        .enumerate()
        .map(|(k, &v)| DualSVec64::<N>::variable(v, k))
        .collect();
    let t = layout.tangent(base, plain, &pt);
    let tyres = match &t.tyre_params {
        Some(params) => ParamTyres::new(&model.front, &model.rear, params.clone()),
        None => ParamTyres::constant(&model.front, &model.rear),
    }?;
    let m = ModelOf {
        model,
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
    let effects = &t.scalars.effects;
    let (drive, logged_t, logged_steer) = run.unsteered_drive(plain);
    let steer: Option<Vec<D<N>>> = (!effects.steer_path.is_off()).then(|| {
        effects
            .steer_path
            .apply(logged_t, logged_steer, &drive.stage_times())
    });
    let ((beta0, r0), beta_measured) = run.start_values();
    let r = D::<N>::from(r0) - effects.sensors.yaw_rate_bias;
    let beta = if beta_measured {
        D::<N>::from(beta0)
            - effects.sensors.beta_bias
            - effects.sensors.sideslip_offset(r, run.start_speed())
    } else {
        D::<N>::from(beta0)
    };
    let first = drive.first_inputs(plain.friction);
    let steer0 = steer.as_ref().map_or(D::<N>::from(first.steer), |s| s[0]);
    let x0 = m
        .model
        .quasi_static_of(&m.scalars, beta, r, first.speed, steer0);
    let h = m.replay(drive, steer.as_deref(), x0);
    let speed = run.speed_at(&h.t);
    let ax = run.ax_for(&effects.sensors, &h.t);
    let seen = effects
        .sensors
        .seen(&h.t, &speed, &ax, &h.yaw_rate, &h.ay, &h.beta);
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
