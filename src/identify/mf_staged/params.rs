//! The stages of Wei et al. (2010) and what each may fit: the coefficients
//! of each function with the load, camber and pressure levels they need to
//! be identifiable, the sign-blind ones, and the physical bounds the
//! data-started fits keep (ISO-W signs, as in the `.tir`).

use super::{MfRow, PURE_TOL};
use crate::tyre::mf::MagicFormula;
use serde::Serialize;

/// The five cases of Wei et al. (2010), in their order, then the stages
/// they leave out: combined-slip aligning moment (`s·Fx`), overturning
/// moment and rolling-resistance moment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Stage {
    /// Pure longitudinal force.
    PureFx,
    /// Pure lateral force.
    PureFy,
    /// Pure aligning moment.
    PureMz,
    /// Combined-slip longitudinal force.
    CombinedFx,
    /// Combined-slip lateral force.
    CombinedFy,
    /// Combined-slip aligning moment: the moment arm `s` of `Fx`
    /// (`SSZ1..4`), from the combined rows' `mz`.
    CombinedMz,
    /// Overturning moment `Mx` (`QSX*`), from every row with an `mx`.
    Mx,
    /// Rolling-resistance moment `My` (`QSY*`), from every row with an `my`.
    My,
}

impl Stage {
    /// All stages in order.
    pub const ALL: [Stage; 8] = [
        Stage::PureFx,
        Stage::PureFy,
        Stage::PureMz,
        Stage::CombinedFx,
        Stage::CombinedFy,
        Stage::CombinedMz,
        Stage::Mx,
        Stage::My,
    ];

    /// The residual Wei et al. (2010) report for this case, % (NaN for the
    /// stages the paper does not fit).
    pub fn paper_sigma_percent(self) -> f64 {
        match self {
            Stage::PureFx => 1.03,
            Stage::PureFy => 1.20,
            Stage::PureMz => 4.82,
            Stage::CombinedFx => 1.96,
            Stage::CombinedFy => 3.01,
            Stage::CombinedMz | Stage::Mx | Stage::My => f64::NAN,
        }
    }

    /// A name people read.
    pub fn label(self) -> &'static str {
        match self {
            Stage::PureFx => "pure Fx",
            Stage::PureFy => "pure Fy",
            Stage::PureMz => "pure Mz",
            Stage::CombinedFx => "combined Fx",
            Stage::CombinedFy => "combined Fy",
            Stage::CombinedMz => "combined Mz",
            Stage::Mx => "Mx",
            Stage::My => "My",
        }
    }

    /// The rig file's column of this stage's channel.
    pub fn column(self) -> &'static str {
        match self {
            Stage::PureFx | Stage::CombinedFx => "fx",
            Stage::PureFy | Stage::CombinedFy => "fy",
            Stage::PureMz | Stage::CombinedMz => "mz",
            Stage::Mx => "mx",
            Stage::My => "my",
        }
    }

    /// What this stage's channel is, in words (`pure lateral force`).
    pub fn quantity(self) -> &'static str {
        match self {
            Stage::PureFx => "pure longitudinal force",
            Stage::PureFy => "pure lateral force",
            Stage::PureMz => "pure aligning moment",
            Stage::CombinedFx => "longitudinal force under combined slip",
            Stage::CombinedFy => "lateral force under combined slip",
            Stage::CombinedMz => "aligning moment under combined slip",
            Stage::Mx => "overturning moment",
            Stage::My => "rolling resistance moment",
        }
    }

    /// The unit of this stage's channel.
    pub fn unit(self) -> &'static str {
        match self {
            Stage::PureFx | Stage::CombinedFx | Stage::PureFy | Stage::CombinedFy => "N",
            _ => "N·m",
        }
    }

    /// The measured value of this stage's channel in a row (NaN: not measured).
    pub fn measured(self, r: &MfRow) -> f64 {
        match self {
            Stage::PureFx | Stage::CombinedFx => r.fx,
            Stage::PureFy | Stage::CombinedFy => r.fy,
            Stage::PureMz | Stage::CombinedMz => r.mz,
            Stage::Mx => r.mx,
            Stage::My => r.my,
        }
    }

    /// The tyre's value of this stage's channel at a row.
    pub fn model(self, t: &MagicFormula, r: &MfRow) -> f64 {
        let o = t.evaluate(&r.input());
        match self {
            Stage::PureFx | Stage::CombinedFx => o.fx,
            Stage::PureFy | Stage::CombinedFy => o.fy,
            Stage::PureMz | Stage::CombinedMz => o.mz,
            Stage::Mx => o.mx,
            Stage::My => o.my,
        }
    }

    /// Whether a row belongs to this stage (its channel measured).
    ///
    /// The combined `Fy` and `Mz` stages take every row with longitudinal
    /// slip, the pure longitudinal ones (α = 0) included: there `Fy` is
    /// `Gyκ·Fy0(0) + SVyκ` and `Mz` carries `s·Fx`, and these rows are what
    /// separates `SVyκ` (`RVY1..3`, `RVY5`, `RVY6`: at α = 0 its
    /// `cos(atan(RVY4·α))` is 1) from the weighting `Gyκ`; no other stage
    /// fits `Fy` or `Mz` on them. The combined `Fx` stage keeps the rows with
    /// both slips: at κ = 0 `Fx` is `Gxα` times the small offset `Fx0(0)`.
    pub fn takes(self, r: &MfRow) -> bool {
        let pure_a = r.alpha.abs() <= PURE_TOL;
        let pure_k = r.kappa.abs() <= PURE_TOL;
        self.measured(r).is_finite()
            && match self {
                Stage::PureFx => pure_a,
                Stage::PureFy | Stage::PureMz => pure_k,
                Stage::CombinedFx => !pure_a && !pure_k,
                Stage::CombinedFy | Stage::CombinedMz => !pure_k,
                Stage::Mx | Stage::My => true,
            }
    }

    /// The stages whose parameters this one builds on: a stage run on
    /// another's defaults fits its own coefficients to that stage's error.
    /// The combined `Mz` takes the longitudinal force twice, in `s·Fx` and
    /// in the equivalent slip angle's `Kxκ/Kyα·κ`, and the combined `Fy`
    /// in `t·Fy'`: on a file without a longitudinal sweep (`PDX1` =
    /// `PKX1` = 0) it fitted `SSZ1` to a wrong-signed moment at σ 138 %.
    pub(super) fn needs(self) -> &'static [Stage] {
        match self {
            Stage::PureFx | Stage::PureFy | Stage::My => &[],
            Stage::PureMz | Stage::CombinedFy | Stage::Mx => &[Stage::PureFy],
            Stage::CombinedFx => &[Stage::PureFx],
            Stage::CombinedMz => &[
                Stage::PureMz,
                Stage::PureFx,
                Stage::CombinedFx,
                Stage::CombinedFy,
            ],
        }
    }

    pub(super) fn parameters(self) -> &'static [(&'static str, Need)] {
        match self {
            Stage::PureFx => PURE_FX,
            Stage::PureFy => PURE_FY,
            Stage::PureMz => PURE_MZ,
            Stage::CombinedFx => COMBINED_FX,
            Stage::CombinedFy => COMBINED_FY,
            Stage::CombinedMz => COMBINED_MZ,
            Stage::Mx => MX,
            Stage::My => MY,
        }
    }
}

/// The levels of load, camber and pressure a parameter needs to be
/// identifiable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Need {
    pub(super) loads: u8,
    pub(super) cambers: u8,
    pub(super) pressures: u8,
}

const fn n(loads: u8, cambers: u8, pressures: u8) -> Need {
    Need {
        loads,
        cambers,
        pressures,
    }
}
pub(super) const ANY: Need = n(1, 1, 1);
const L2: Need = n(2, 1, 1);
const L3: Need = n(3, 1, 1);
const L4: Need = n(4, 1, 1);
const C2: Need = n(1, 2, 1);
const C3: Need = n(1, 3, 1);
const C2L2: Need = n(2, 2, 1);
const C3L2: Need = n(2, 3, 1);
const P2: Need = n(1, 1, 2);
const P3: Need = n(1, 1, 3);
const P2C2: Need = n(1, 2, 2);
/// Never fitted (see the module notes on `QBZ9`).
pub(super) const HELD: Need = n(u8::MAX, u8::MAX, u8::MAX);

const PURE_FX: &[(&str, Need)] = &[
    ("PCX1", ANY),
    ("PDX1", ANY),
    ("PDX2", L2),
    ("PDX3", C2),
    ("PEX1", ANY),
    ("PEX2", L2),
    ("PEX3", L3),
    ("PEX4", ANY),
    ("PKX1", ANY),
    ("PKX2", L2),
    ("PKX3", L3),
    ("PHX1", ANY),
    ("PHX2", L2),
    ("PVX1", ANY),
    ("PVX2", L2),
    ("PPX1", P2),
    ("PPX2", P3),
    ("PPX3", P2),
    ("PPX4", P3),
];

const PURE_FY: &[(&str, Need)] = &[
    ("PCY1", ANY),
    ("PDY1", ANY),
    ("PDY2", L2),
    ("PDY3", C2),
    ("PEY1", ANY),
    ("PEY2", L2),
    ("PEY3", ANY),
    ("PEY4", C2),
    ("PEY5", C3),
    ("PKY1", ANY),
    ("PKY2", L2),
    ("PKY3", C2),
    ("PKY4", L4),
    ("PKY5", C3),
    ("PKY6", C2),
    ("PKY7", C2L2),
    ("PHY1", ANY),
    ("PHY2", L2),
    ("PVY1", ANY),
    ("PVY2", L2),
    ("PVY3", C2),
    ("PVY4", C2L2),
    ("PPY1", P2),
    ("PPY2", P2),
    ("PPY3", P2),
    ("PPY4", P3),
    ("PPY5", P2C2),
];

const PURE_MZ: &[(&str, Need)] = &[
    ("QBZ1", ANY),
    ("QBZ2", L2),
    ("QBZ3", L3),
    ("QBZ4", C2),
    ("QBZ5", C3),
    ("QBZ9", HELD),
    ("QBZ10", ANY),
    ("QCZ1", ANY),
    ("QDZ1", ANY),
    ("QDZ2", L2),
    ("QDZ3", C2),
    ("QDZ4", C3),
    ("QDZ6", ANY),
    ("QDZ7", L2),
    ("QDZ8", C2),
    ("QDZ9", C2L2),
    ("QDZ10", C3),
    ("QDZ11", C3L2),
    ("QEZ1", ANY),
    ("QEZ2", L2),
    ("QEZ3", L3),
    ("QEZ4", ANY),
    ("QEZ5", C2),
    ("QHZ1", ANY),
    ("QHZ2", L2),
    ("QHZ3", C2),
    ("QHZ4", C2L2),
    ("PPZ1", P2),
    ("PPZ2", P2C2),
];

const COMBINED_FX: &[(&str, Need)] = &[
    ("RBX1", ANY),
    ("RBX2", ANY),
    ("RBX3", C2),
    ("RCX1", ANY),
    ("REX1", ANY),
    ("REX2", L2),
    ("RHX1", ANY),
];

const COMBINED_FY: &[(&str, Need)] = &[
    ("RBY1", ANY),
    ("RBY2", ANY),
    ("RBY3", ANY),
    ("RBY4", C2),
    ("RCY1", ANY),
    ("REY1", ANY),
    ("REY2", L2),
    ("RHY1", ANY),
    ("RHY2", L2),
    ("RVY1", ANY),
    ("RVY2", L2),
    ("RVY3", C2),
    ("RVY4", ANY),
    ("RVY5", ANY),
    ("RVY6", ANY),
];

const COMBINED_MZ: &[(&str, Need)] = &[("SSZ1", ANY), ("SSZ2", ANY), ("SSZ3", C2), ("SSZ4", C2L2)];

/// The TNO 6.1 overturning moment. The cosine-of-load times
/// sine-of-camber-and-force term (`QSX4..QSX9`) and the arctangent load
/// term (`QSX10`, `QSX11`) start off zero (`start.rs`): at zero their
/// gradients vanish together.
const MX: &[(&str, Need)] = &[
    ("QSX1", ANY),
    ("QSX2", C2),
    ("QSX3", ANY),
    ("QSX4", ANY),
    ("QSX5", L2),
    ("QSX6", L2),
    ("QSX7", C2),
    ("QSX8", ANY),
    ("QSX9", ANY),
    ("QSX10", C2),
    ("QSX11", C2L2),
    ("QSX12", C3),
    ("QSX13", L2),
    ("QSX14", C2L2),
    ("PPMX1", P2C2),
];

/// The TNO 6.1 rolling resistance (eq. A48). `QSY3`, `QSY4` (speed) are
/// held: the levels counted are load, camber and pressure, and a rig test
/// usually runs at one speed.
const MY: &[(&str, Need)] = &[
    ("QSY1", ANY),
    ("QSY2", ANY),
    ("QSY3", HELD),
    ("QSY4", HELD),
    ("QSY5", C2),
    ("QSY6", C2L2),
    ("QSY7", L2),
    ("QSY8", P2),
];

/// Coefficients whose sign the model cannot see (they enter through
/// `cos(atan(·))` or a `sin(C·atan(B·x))` whose `B` flips with `C`); they are
/// reported positive (and `RVY5`, `RVY6`, which flip together, with `RVY5`
/// positive).
pub(super) const EVEN: [&str; 7] = ["PCX1", "PCY1", "RCX1", "RCY1", "RBX2", "RBY2", "RVY4"];

pub(super) fn names_of(free: &[(&'static str, Need)]) -> Vec<&'static str> {
    free.iter().map(|(k, _)| *k).collect()
}

/// Bounds that keep a fitted coefficient physical (ISO-W signs): shape
/// factors `C ≥ 1` for the pure forces (below 1 the sine never reaches its
/// peak, `D` stops being the peak force and `B`, `C`, `D` trade along a
/// ridge — the drift seen on the Hoosier data, `PCY1` → 0.5 with `PDY1` →
/// 2.3), positive friction, curvatures `E ≤ 1` (the formula clips above),
/// a sign factor `(1 ∓ PEY3)` or `(1 − PEX4·sgn κ)` that keeps its sign,
/// positive `PKY2`, `PKY4` and positive stiffness factors `QBZ1`, `RBX1`,
/// `RBY1`. Every other coefficient may move 10⁴ times its
/// start's magnitude (at least ±10⁴) either way: finite, so the projected
/// LM's step test has a scale, and wide enough not to bind on camber terms
/// that are large by nature (MFeval's `RBY4` is 1,747).
pub(super) fn physical_bounds(name: &str, start: f64) -> (f64, f64) {
    match name {
        "PCX1" | "PCY1" => (1.0, 3.0),
        "RCX1" | "RCY1" | "QCZ1" => (0.1, 5.0),
        "PDX1" | "PDY1" => (0.05, 6.0),
        "PKY2" => (0.05, 20.0),
        "PKY4" => (0.1, 5.0),
        // Stiffness factors of the trail and the combined-slip weights are
        // positive (their cosines are nearly even in them, so without a
        // bound the sign is a coin toss).
        "QBZ1" | "RBX1" | "RBY1" => (0.0, 1e4 * start.abs().max(1.0)),
        "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1" => (-50.0, 1.0),
        "PEY3" | "PEX4" => (-1.0, 1.0),
        _ => {
            let w = 1e4 * start.abs().max(1.0);
            (start - w, start + w)
        }
    }
}

/// The box of `name` where [`physical_bounds`] fixes one (a shape factor,
/// a peak, a curvature, a stiffness factor kept positive), its start's
/// aside; `None` for a coefficient the fit lets move 10⁴ times its start
/// either way, which encodes no sign. `identify --hold` checks a held
/// value against it (`jobs/identify/hold_rules.rs`).
pub(crate) fn fixed_bounds(name: &str) -> Option<(f64, f64)> {
    match name {
        "PCX1" | "PCY1" | "RCX1" | "RCY1" | "QCZ1" | "PDX1" | "PDY1" | "PKY2" | "PKY4" | "QBZ1"
        | "RBX1" | "RBY1" | "PEX1" | "PEY1" | "QEZ1" | "REX1" | "REY1" | "PEY3" | "PEX4" => {
            Some(physical_bounds(name, 0.0))
        }
        _ => None,
    }
}
