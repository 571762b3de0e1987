//! Gim's analytical tyre model (Gim & Nikravesh 1990), pure cornering, as
//! Wang & Liang uses it: a brush model with a parabolic pressure distribution, an
//! adhesion region at the leading edge and a sliding region behind it.
//!
//! With `ln = 1 − K·|tan α| / (3·μ·Fz)` the normalised adhesion length
//! (Pacejka, *Tire and Vehicle Dynamics*, eq. 3.15–3.17, brush model):
//! `Fy = μ·Fz·(1 − ln³)·sgn α` and `Mz = μ·Fz·(l/2)·θ·tan α·ln³` with
//! `θ = K/(3μFz)`, full sliding (`ln ≤ 0`) from `|tan α| = 3μFz/K`, and the
//! pneumatic trail `l/6` at small slip. Gim's sliding friction falls with the
//! slip, `μ = μ0·(1 − A_s·s)` with `s = |tan α|`; it is written here as
//! `μ = μ0/(1 + A_s·s)`, equal to first order, so that it stays positive and
//! keeps falling at large slip instead of turning negative (a floor would
//! give a constant sliding force and with it a continuum of equilibria).
//! `A_s = 0` gives the classic Fiala / brush closed form.
//!
//! Units: N, N/rad, m, rad. Signs as in `tyre/mod.rs`.

use super::{
    safe_tan, safe_tan_of, Block, LateralForceOf, LoadRange, Model, ModelParameters, Parameterised,
    SlipOf, SlipState, TyreForces, TyreModel,
};
use crate::error::ParamError;
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// Gim / brush tyre parameters for one wheel.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gim {
    /// Cornering stiffness at the reference load, N/rad.
    pub cornering_stiffness: f64,
    /// Contact patch length l′, m.
    pub contact_length: f64,
    /// Peak friction coefficient μ0 on the reference surface.
    #[serde(default = "one")]
    pub friction: f64,
    /// Gim's friction fall-off with slip A_s (0 = constant friction).
    #[serde(default)]
    pub friction_decay: f64,
    /// Load at which `cornering_stiffness` holds, N (only used when
    /// `load_exponent ≠ 0`).
    #[serde(default = "default_reference_load")]
    pub reference_load: f64,
    /// Stiffness load sensitivity: K = K_ref·(Fz/Fz_ref)^n (0 = constant K,
    /// as in Wang & Liang).
    #[serde(default)]
    pub load_exponent: f64,
}

fn one() -> f64 {
    1.0
}
fn default_reference_load() -> f64 {
    4000.0
}

impl Gim {
    /// A Gim tyre with constant friction and load-independent stiffness.
    pub fn new(cornering_stiffness: f64, contact_length: f64, friction: f64) -> Self {
        Self {
            cornering_stiffness,
            contact_length,
            friction,
            friction_decay: 0.0,
            reference_load: default_reference_load(),
            load_exponent: 0.0,
        }
    }

    fn stiffness_at(&self, fz: f64) -> f64 {
        if self.load_exponent == 0.0 {
            self.cornering_stiffness
        } else {
            self.cornering_stiffness * (fz / self.reference_load).powf(self.load_exponent)
        }
    }

    /// (fy, mz) for pure cornering.
    fn cornering(&self, s: &SlipState) -> (f64, f64) {
        if s.fz <= 0.0 {
            return (0.0, 0.0);
        }
        let k = self.stiffness_at(s.fz);
        let t = safe_tan(s.alpha);
        // Both are odd in the slip: zero at none, also where a load next to
        // zero (a subnormal) makes θ = K/(3μFz) infinite and θ·0 undefined.
        if t == 0.0 {
            return (0.0, 0.0);
        }
        let mu = self.friction * s.mu_scale / (1.0 + self.friction_decay * t.abs());
        if mu <= 0.0 {
            return (0.0, 0.0);
        }
        let theta = k / (3.0 * mu * s.fz);
        let ln = 1.0 - theta * t.abs();
        if ln <= 0.0 {
            return (mu * s.fz * t.signum(), 0.0);
        }
        let ln3 = ln * ln * ln;
        let fy = mu * s.fz * (1.0 - ln3) * t.signum();
        let mz = mu * s.fz * 0.5 * self.contact_length * theta * t * ln3;
        (fy, mz)
    }

    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("cornering_stiffness", self.cornering_stiffness)?;
        ParamError::positive("contact_length", self.contact_length)?;
        ParamError::positive("friction", self.friction)?;
        ParamError::non_negative("friction_decay", self.friction_decay)?;
        ParamError::positive("reference_load", self.reference_load)?;
        ParamError::finite("load_exponent", self.load_exponent)
    }
}

impl TyreModel for Gim {
    fn forces(&self, s: &SlipState) -> TyreForces {
        let (fy, mz) = self.cornering(s);
        TyreForces { fx: 0.0, fy, mz }
    }
    fn lateral_force(&self, s: &SlipState) -> f64 {
        self.cornering(s).0
    }
    /// The friction coefficient without sliding (its largest: friction
    /// decays with sliding speed).
    fn friction_coefficient(&self, _fz: f64, mu_scale: f64) -> f64 {
        self.friction * mu_scale
    }
    fn cornering_stiffness(&self, fz: f64) -> f64 {
        if fz <= 0.0 {
            0.0
        } else {
            self.stiffness_at(fz)
        }
    }
}

impl Parameterised for Gim {
    fn parameter_names(&self) -> Vec<&'static str> {
        vec![
            "cornering_stiffness",
            "contact_length",
            "friction",
            "friction_decay",
            "load_exponent",
        ]
    }
    fn parameters(&self) -> Vec<f64> {
        vec![
            self.cornering_stiffness,
            self.contact_length,
            self.friction,
            self.friction_decay,
            self.load_exponent,
        ]
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.cornering_stiffness = p[0];
        self.contact_length = p[1];
        self.friction = p[2];
        self.friction_decay = p[3];
        self.load_exponent = p[4];
    }
    /// The stiffness from the least per unit of the reference load any
    /// tyre has ([`crate::tyre::sizes::MIN_CORNERING_PER_LOAD`]): a fit
    /// below it would write a file the tyre readers refuse.
    fn bounds(&self) -> Vec<(f64, f64)> {
        let least = (crate::tyre::sizes::MIN_CORNERING_PER_LOAD * self.reference_load).max(1e3);
        vec![
            (least, 5e5),
            (0.02, 0.5),
            (0.1, 3.0),
            (0.0, 1.0),
            (0.0, 1.5),
        ]
    }
    /// A decay below 0 is a friction that rises with slip without end
    /// (`μ0/(1 + A_s·s)` past a pole); an exponent below 0 a stiffness
    /// that falls with load, infinite at no load.
    fn physical_floors(&self) -> Vec<Option<&'static str>> {
        vec![
            None,
            None,
            None,
            Some("a smaller decay is a friction that rises with slip"),
            Some("a smaller exponent is a stiffness that falls with load, infinite at none"),
        ]
    }
}

impl LateralForceOf for Gim {
    /// As [`Gim::cornering`]'s force, the stiffness `K·(Fz/Fz_ref)^n` as
    /// `K·e^(n·ln(Fz/Fz_ref))` (its derivative in n at n = 0 is not zero).
    fn lateral_force_of<T: DualNum<f64> + Copy>(&self, p: &[T], s: &SlipOf<T>) -> T {
        let zero = T::from(0.0);
        if s.fz <= 0.0 {
            return zero;
        }
        let (stiffness, friction, decay, exponent) = (p[0], p[2], p[3], p[4]);
        // e^0 is 1 exactly: at n = 0 the value is K's, bit for bit.
        let k = stiffness * ((s.fz / self.reference_load).ln() * exponent).exp();
        let t = safe_tan_of(s.alpha);
        // As in [`Gim::cornering`]: zero at no slip whatever θ, with the
        // slope there, K·tan α (μFz·3θ|t| to first order: the decay of
        // friction with slip is second order). Returning a constant zero
        // would drop the derivative, and with it the stiffness of straight
        // running from every exact Jacobian (equilibria's stability at
        // β = r = 0 read "degenerate").
        if t == 0.0 {
            return k * t;
        }
        let mu = friction * s.mu_scale / (decay * t.abs() + 1.0);
        if mu <= 0.0 {
            return zero;
        }
        let theta = k / (mu * 3.0 * s.fz);
        let ln = -(theta * t.abs()) + 1.0;
        if ln <= 0.0 {
            return mu * s.fz * t.signum();
        }
        mu * s.fz * (-(ln * ln * ln) + 1.0) * t.signum()
    }
    /// `μ0·μ`, as [`TyreModel::friction_coefficient`].
    fn friction_coefficient_of<T: DualNum<f64> + Copy>(&self, p: &[T], _fz: T, mu_scale: T) -> T {
        p[2] * mu_scale
    }
}

impl ModelParameters for Gim {
    fn validate(&self) -> Result<(), ParamError> {
        // The inherent check above (inherent methods take precedence).
        Gim::validate(self)
    }
    /// Each key's size, then the stiffness per unit of the reference
    /// load (once that load is a tyre's): a car tyre's N/deg figure (1000)
    /// passes the floor of any tyre's stiffness, not that of its load's.
    fn check_sizes(&self) -> Result<(), ParamError> {
        super::sizes::cornering_stiffness("cornering_stiffness", self.cornering_stiffness)?;
        super::sizes::contact_length("contact_length", self.contact_length)?;
        super::sizes::friction("friction", self.friction)?;
        super::sizes::tyre_load("reference_load", self.reference_load)?;
        // The stiffness holds at the reference load; a file that states
        // none is read at the default, a car wheel's 4 kN.
        let load = (
            "reference_load",
            self.reference_load,
            self.reference_load == default_reference_load(),
        );
        super::sizes::cornering_per_load("cornering_stiffness", self.cornering_stiffness, load)
    }
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.cornering_stiffness *= k;
    }
    /// Around its `reference_load` where the stiffness depends on the
    /// load; a stiffness that does not (`load_exponent = 0`, Wang &
    /// Liang's) holds at no load in particular (`tyre-eval` takes the
    /// `reference_load` a file states as the tyre's load there:
    /// `jobs/tyre_eval/model_loads.rs`).
    fn load_range(&self) -> Option<LoadRange> {
        Some(if self.load_exponent == 0.0 {
            LoadRange::any_tyre(<Self as Model>::NAME)
        } else {
            LoadRange::of_nominal("reference_load", self.reference_load)
        })
    }
    /// The contact length acts on Mz only (it is the aligning block), and
    /// the load exponent needs more than one load.
    fn lateral_free(&self, loads: usize, _cambers: usize) -> Vec<bool> {
        vec![true, false, true, true, loads > 1]
    }
    fn block_names(&self, block: Block) -> Vec<String> {
        match block {
            Block::Aligning => vec!["contact_length".into()],
            Block::Longitudinal => Vec::new(),
        }
    }
    fn block_parameters(&self, block: Block) -> Vec<f64> {
        match block {
            Block::Aligning => vec![self.contact_length],
            Block::Longitudinal => Vec::new(),
        }
    }
    fn set_block_parameters(&mut self, block: Block, v: &[f64]) {
        if block == Block::Aligning {
            self.contact_length = v[0];
        }
    }
    fn block_bounds(&self, block: Block) -> Vec<(f64, f64)> {
        match block {
            Block::Aligning => vec![(0.02, 0.5)],
            Block::Longitudinal => Vec::new(),
        }
    }
}

impl Model for Gim {
    const NAME: &'static str = "gim";
    /// 50 kN/rad, 0.15 m, μ 1, the stiffness referred to the data's median
    /// load.
    fn start(fz: f64) -> Option<Self> {
        Some(Gim {
            reference_load: fz,
            ..Gim::new(50_000.0, 0.15, 1.0)
        })
    }
}
