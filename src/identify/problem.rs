//! The least-squares problem of a rig fit: the measured quantity it
//! matches ([`Channel`]), the residuals of the model's free parameters at
//! the rig points, and their Jacobian ([`Derivatives`]). The Jacobian of
//! the lateral force is exact, from one evaluation of each point in
//! forward-mode dual numbers (`num-dual`'s `DualSVec64<N>`, N the free
//! parameters rounded up to 4, 8, 12 or 16; no allocation per point),
//! for every model with a generic lateral force
//! ([`Tyre::lateral_force_of`]); the aligning-moment and
//! longitudinal-force blocks, the Magic Formula and models registered at
//! run time difference their residuals (forward differences, one
//! evaluation of every point per parameter, [`inward_jacobian`]). Units:
//! N, N·m, rad, as in `tyre/mod.rs`.

use super::data;
use crate::optim::local::{inward_jacobian, Residuals};
use crate::tyre::{Parameterised, SlipOf, Tyre, TyreModel};
use data::Condition;
use nalgebra::{Const, DMatrix, U1};
use num_dual::DualSVec64;
use rayon::prelude::*;
use serde::Serialize;

/// The measured quantity a fit matches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Channel {
    /// Lateral force Fy, N.
    LateralForce,
    /// Aligning moment Mz, N·m (with the lateral parameters held).
    AligningMoment,
    /// Longitudinal force Fx, N, on points whose slip column holds κ and
    /// force column Fx ([`data::RigData::longitudinal_view`]).
    LongitudinalForce,
}

impl Channel {
    /// What the channel measures, for messages.
    pub fn quantity(self) -> &'static str {
        match self {
            Channel::LateralForce => "lateral force",
            Channel::AligningMoment => "aligning moment",
            Channel::LongitudinalForce => "longitudinal force",
        }
    }

    /// The measured value of a point.
    pub fn measured(self, q: &data::Point) -> f64 {
        match self {
            Channel::LateralForce => q.fy(),
            Channel::AligningMoment => q.mz(),
            Channel::LongitudinalForce => q.fx(),
        }
    }

    /// The model's value at a point.
    pub fn model(self, t: &Tyre, q: &data::Point) -> f64 {
        let s = q.slip_state();
        match self {
            Channel::LateralForce => t.lateral_force(&s),
            Channel::AligningMoment => super::aligning::aligning_moment(t, &s),
            Channel::LongitudinalForce => t.forces(&s).fx,
        }
    }

    pub(super) fn names(self, t: &Tyre) -> Vec<String> {
        match self {
            Channel::LateralForce => t.parameter_names().iter().map(|n| n.to_string()).collect(),
            Channel::AligningMoment => t.aligning_names(),
            Channel::LongitudinalForce => t.longitudinal_names(),
        }
    }

    pub(super) fn parameters(self, t: &Tyre) -> Vec<f64> {
        match self {
            Channel::LateralForce => t.parameters(),
            Channel::AligningMoment => t.aligning_parameters(),
            Channel::LongitudinalForce => t.longitudinal_parameters(),
        }
    }

    pub(super) fn set(self, t: &mut Tyre, p: &[f64]) {
        match self {
            Channel::LateralForce => t.set_parameters(p),
            Channel::AligningMoment => t.set_aligning_parameters(p),
            Channel::LongitudinalForce => t.set_longitudinal_parameters(p),
        }
    }

    pub(super) fn bounds(self, t: &Tyre) -> Vec<(f64, f64)> {
        match self {
            Channel::LateralForce => t.bounds(),
            Channel::AligningMoment => t.aligning_bounds(),
            Channel::LongitudinalForce => t.longitudinal_bounds(),
        }
    }

    pub(super) fn free(self, t: &Tyre, loads: usize, cambers: usize) -> Vec<bool> {
        match self {
            Channel::LateralForce => t.lateral_free(loads, cambers),
            Channel::AligningMoment => t.aligning_free(cambers),
            Channel::LongitudinalForce => t.longitudinal_free(),
        }
    }
}

pub use crate::optim::local::Derivatives;

/// The least-squares problem of one channel over the free parameters.
pub struct FitProblem {
    base: Tyre,
    pub(super) channel: Channel,
    /// Indices of the free parameters in the channel's vector.
    pub(super) free: Vec<usize>,
    pub(super) points: Vec<data::Point>,
    /// The Jacobian is exact: asked for, the lateral force, a model with a
    /// generic one and at most [`MAX_EXACT`] free parameters.
    exact: bool,
}

/// The most free parameters an exact Jacobian takes (the widest dual
/// number below; PAC89 has fourteen).
const MAX_EXACT: usize = 16;

/// Points per parallel task of the residuals and the exact Jacobian: a
/// point costs a fraction of a microsecond, so a task of a few hundred
/// outweighs rayon's scheduling, and the Hoosier cornering file's 3,551
/// points still make more tasks than cores. Each point's values go to
/// their own slots, so the results do not depend on the split.
const CHUNK: usize = 256;

impl FitProblem {
    /// The problem of fitting `start`'s free lateral-force parameters.
    pub fn new(start: &Tyre, free: &[bool], conditions: &[Condition]) -> Self {
        Self::for_channel(start, Channel::LateralForce, free, conditions)
    }

    /// The problem of fitting `start`'s free parameters of `channel` to the
    /// points where that channel was measured.
    pub(crate) fn for_channel(
        start: &Tyre,
        channel: Channel,
        free: &[bool],
        conditions: &[Condition],
    ) -> Self {
        Self {
            base: start.clone(),
            channel,
            free: (0..free.len()).filter(|i| free[*i]).collect(),
            points: conditions
                .iter()
                .flat_map(|c| c.points.iter().copied())
                .filter(|q| channel.measured(q).is_finite())
                .collect(),
            exact: false,
        }
        .with_derivatives(Derivatives::Exact)
    }

    /// The same problem with its Jacobian taken as `d` says (exact by
    /// default, where it can be).
    pub fn with_derivatives(mut self, d: Derivatives) -> Self {
        self.exact = d == Derivatives::Exact && self.can_be_exact();
        self
    }

    /// Whether this problem can have an exact Jacobian.
    fn can_be_exact(&self) -> bool {
        self.channel == Channel::LateralForce
            && self.base.lateral_parameters().is_some()
            && self.free.len() <= MAX_EXACT
    }

    /// The exact Jacobian at `p` through `N`-direction dual numbers (`N` ≥
    /// the free parameters; the directions beyond them stay zero): the
    /// parameters as dual numbers once, then one evaluation per point, on
    /// the stack.
    fn exact_jacobian<const N: usize>(&self, p: &[f64]) -> DMatrix<f64> {
        type D<const N: usize> = DualSVec64<N>;
        let mut full: Vec<D<N>> = self
            .channel
            .parameters(&self.base)
            .into_iter()
            .map(D::from)
            .collect();
        for (k, &i) in self.free.iter().enumerate() {
            full[i] = D::from(p[k]).derivative(k);
        }
        // Row `row` of the Jacobian is column `row` of its transpose,
        // contiguous in nalgebra's column-major storage: tasks of points
        // fill disjoint stretches of it, then one transpose.
        let n = p.len();
        let mut jt = DMatrix::zeros(n, self.points.len());
        if n == 0 {
            // Everything held: no column, and no chunk of zero width.
            return jt.transpose();
        }
        jt.as_mut_slice()
            .par_chunks_mut(n * CHUNK)
            .zip(self.points.par_chunks(CHUNK))
            .for_each(|(cols, points)| {
                for (col, q) in cols.chunks_exact_mut(n).zip(points) {
                    let s = q.slip_state();
                    let slip = SlipOf {
                        alpha: D::from(s.alpha),
                        fz: D::from(s.fz),
                        mu_scale: D::from(s.mu_scale),
                        speed: s.speed,
                    };
                    let f = self
                        .base
                        .lateral_force_at_camber_of(&full, &slip, s.camber)
                        .expect("an exact problem's model has a generic lateral force");
                    let eps = f.eps.unwrap_generic(Const::<N>, U1);
                    col.copy_from_slice(&eps.as_slice()[..n]);
                }
            });
        jt.transpose()
    }

    /// The same problem at `p` with its free parameter `k` (in the free
    /// order) held at `value`: the others stay free, in their order.
    pub(super) fn holding(&self, p: &[f64], k: usize, value: f64) -> Self {
        let mut base = self.tyre(p);
        let mut all = self.channel.parameters(&base);
        all[self.free[k]] = value;
        self.channel.set(&mut base, &all);
        let mut free = self.free.clone();
        free.remove(k);
        Self {
            base,
            free,
            points: self.points.clone(),
            ..*self
        }
    }

    /// The measured values' norm over the points, `‖F‖`.
    pub(super) fn measured_norm(&self) -> f64 {
        self.points
            .iter()
            .map(|q| self.channel.measured(q).powi(2))
            .sum::<f64>()
            .sqrt()
    }

    /// The tyre with free parameters `p`.
    pub fn tyre(&self, p: &[f64]) -> Tyre {
        let mut full = self.channel.parameters(&self.base);
        for (k, &i) in self.free.iter().enumerate() {
            full[i] = p[k];
        }
        let mut t = self.base.clone();
        self.channel.set(&mut t, &full);
        t
    }
}

impl Residuals for FitProblem {
    fn count(&self) -> usize {
        self.points.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let t = self.tyre(p);
        out.par_chunks_mut(CHUNK)
            .zip(self.points.par_chunks(CHUNK))
            .for_each(|(out, points)| {
                for (o, q) in out.iter_mut().zip(points) {
                    *o = self.channel.model(&t, q) - self.channel.measured(q);
                }
            });
    }
    /// Exact where it can be (one dual evaluation per point, the width
    /// the free parameters need), else forward differences.
    fn jacobian(&self, p: &[f64], r0: &[f64], bounds: &[(f64, f64)]) -> DMatrix<f64> {
        if !self.exact {
            return inward_jacobian(self, p, r0, bounds);
        }
        match p.len() {
            0..=4 => self.exact_jacobian::<4>(p),
            5..=8 => self.exact_jacobian::<8>(p),
            9..=12 => self.exact_jacobian::<12>(p),
            _ => self.exact_jacobian::<MAX_EXACT>(p),
        }
    }
    /// The exact Jacobian does not use the residuals.
    fn jacobian_reads_residuals(&self) -> bool {
        !self.exact
    }
    /// One pass over the points (in dual numbers) for the exact Jacobian.
    fn jacobian_evaluations(&self, n: usize) -> usize {
        if self.exact {
            1
        } else {
            n
        }
    }
}
