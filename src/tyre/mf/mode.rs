//! MFeval's evaluation modes and the validity ranges of a `.tir` file.
//!
//! MFeval (M. Furlan) takes a three-digit `useMode`: hundreds 1 = limit
//! checks on, 2 = off; tens 1 = `α*` off (`α* = α`, `γ* = γ`), 2 = on
//! (`α* = tan α·sgn Vx`, `γ* = sin γ`); units 1 = combined slip without
//! turn slip, 2 = with turn slip (not modelled here: refused by name). Its
//! default, and the crate's, is 121.
//!
//! With the limit checks on, MFeval (its `Solver.parseInputs`) saturates
//! the inputs to the ranges of the file's `[*_LIMITS]` sections before
//! evaluating: slip ratio to `[KPUMIN, KPUMAX]`, slip angle to `[ALPMIN,
//! ALPMAX]`, inclination to `[CAMMIN, CAMMAX]`, pressure to `[PRESMIN,
//! PRESMAX]`, load to `FZMAX`; the aligning moment's trail and residual
//! torque take at least `FZMIN` (its `Fz_lowLimit`); and it clips the
//! curvature factors `E` at 1. Whatever the mode, `Mx` is evaluated at
//! `Fz·(Fz/FZMIN)²` and `My` at the unclamped `Fz·(Fz/FZMIN)` below
//! `FZMIN`. A range the file does not give is not checked. Angles are
//! those of the file's own frame (TNO's ISO-W, before a right-side file is
//! mirrored). Units: N, rad, Pa.

use super::{AlphaStar, MagicFormula};
use crate::error::{ModeDigit, ModeError, ParamError};
use serde::{Deserialize, Serialize};

/// One of MFeval's `useMode` settings the crate evaluates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct MfMode {
    /// Saturate inputs to the file's ranges and clip `E` at 1 (hundreds
    /// digit 1).
    pub limit_checks: bool,
    /// Form of `α*` (tens digit: 1 `Angle`, 2 `Tan`).
    pub alpha_star: AlphaStar,
}

impl Default for MfMode {
    /// 121: limit checks on, `α*` on, no turn slip (MFeval's default).
    fn default() -> Self {
        Self {
            limit_checks: true,
            alpha_star: AlphaStar::Tan,
        }
    }
}

impl MfMode {
    /// The mode of an MFeval `useMode` code (111, 121, 211 or 221); the
    /// reason otherwise, naming the digit that is refused.
    pub fn from_use_mode(code: u32) -> Result<Self, ModeError> {
        let (h, t, u) = (code / 100, code / 10 % 10, code % 10);
        if !(100..1000).contains(&code) {
            return Err(ModeError::NotThreeDigits { code });
        }
        let digit = |place, digit, allowed| ModeDigit {
            place,
            digit,
            allowed,
        };
        let mut bad = Vec::new();
        if !(1..=2).contains(&h) {
            bad.push(digit("hundreds", h, "1 or 2"));
        }
        if !(1..=2).contains(&t) {
            bad.push(digit("tens", t, "1 or 2"));
        }
        // Units 2 alone is turn slip, refused by name below.
        if u != 1 && (u != 2 || !bad.is_empty()) {
            bad.push(digit("units", u, "1"));
        }
        if !bad.is_empty() {
            return Err(ModeError::Digits { code, bad });
        }
        if u == 2 {
            return Err(ModeError::TurnSlip { code });
        }
        Ok(Self {
            limit_checks: h == 1,
            alpha_star: if t == 1 {
                AlphaStar::Angle
            } else {
                AlphaStar::Tan
            },
        })
    }

    /// Every `useMode` code the crate evaluates, with what it does, the
    /// default first: the list a refused `--mode` is answered with.
    pub const CODES: [(u32, &'static str); 4] = [
        (121, "limit checks on, α* on (MFeval's default)"),
        (111, "limit checks on, α* off (α* = α, γ* = γ)"),
        (221, "limit checks off, α* on"),
        (211, "limit checks off, α* off"),
    ];

    /// The `useMode` code of this mode.
    pub fn use_mode(self) -> u32 {
        let h = if self.limit_checks { 100 } else { 200 };
        let t = match self.alpha_star {
            AlphaStar::Angle => 10,
            AlphaStar::Tan => 20,
        };
        h + t + 1
    }
}

/// The validity ranges of a `.tir` file (`[VERTICAL]` `FZMIN`/`FZMAX`,
/// `[LONG_SLIP_RANGE]`, `[SLIP_ANGLE_RANGE]`, `[INCLINATION_ANGLE_RANGE]`,
/// `[INFLATION_PRESSURE_RANGE]`), SI; `None` where the file gives none.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MfLimits {
    /// `FZMIN`, N.
    pub fz_min: Option<f64>,
    /// `FZMAX`, N.
    pub fz_max: Option<f64>,
    /// `KPUMIN`.
    pub kappa_min: Option<f64>,
    /// `KPUMAX`.
    pub kappa_max: Option<f64>,
    /// `ALPMIN`, rad (the file's frame).
    pub alpha_min: Option<f64>,
    /// `ALPMAX`, rad.
    pub alpha_max: Option<f64>,
    /// `CAMMIN`, rad (the file's frame).
    pub camber_min: Option<f64>,
    /// `CAMMAX`, rad.
    pub camber_max: Option<f64>,
    /// `PRESMIN`, Pa.
    pub pressure_min: Option<f64>,
    /// `PRESMAX`, Pa.
    pub pressure_max: Option<f64>,
}

impl MfLimits {
    /// Ok unless `FZMAX` lies below any tyre's largest load (100 N): a
    /// file's `FZMAX = 18`, typed in kN, clamped every load to 18 N. (A
    /// `FZMAX` below `FNOMIN` alone is no slip: a staged fit from a
    /// template keeps the template's `FNOMIN` above the loads it had.)
    pub(crate) fn fz_max_in_newtons(&self, fnomin: f64) -> Result<(), ParamError> {
        use crate::error::{Limit, ParamReason};
        let least = crate::tyre::sizes::TYRE_LOAD.0;
        match self.fz_max.filter(|v| *v < least) {
            Some(v) => Err(ParamError::new(
                "FZMAX",
                v,
                ParamReason::OutOfRange {
                    lo: least,
                    hi: f64::INFINITY,
                    why: Limit::MfFzmaxInKn { fnomin },
                },
            )),
            None => Ok(()),
        }
    }
}

/// `x` saturated to `[lo, hi]` (either bound may be absent).
#[inline]
pub(super) fn saturate(x: f64, lo: Option<f64>, hi: Option<f64>) -> f64 {
    let x = lo.map_or(x, |l| if x < l { l } else { x });
    hi.map_or(x, |h| if x > h { h } else { x })
}

impl MfLimits {
    /// The `.tir` keys of the ranges, in field order.
    pub const KEYS: [&'static str; 10] = [
        "FZMIN", "FZMAX", "KPUMIN", "KPUMAX", "ALPMIN", "ALPMAX", "CAMMIN", "CAMMAX", "PRESMIN",
        "PRESMAX",
    ];

    /// The bound of `.tir` key `key` (`None`: not given, or not a range key).
    pub fn get(&self, key: &str) -> Option<f64> {
        let mut copy = *self;
        copy.slot(key).and_then(|s| *s)
    }

    /// Sets the bound of `.tir` key `key`; false for any other key.
    pub fn set(&mut self, key: &str, value: f64) -> bool {
        match self.slot(key) {
            Some(s) => {
                *s = Some(value);
                true
            }
            None => false,
        }
    }

    fn slot(&mut self, key: &str) -> Option<&mut Option<f64>> {
        Some(match key {
            "FZMIN" => &mut self.fz_min,
            "FZMAX" => &mut self.fz_max,
            "KPUMIN" => &mut self.kappa_min,
            "KPUMAX" => &mut self.kappa_max,
            "ALPMIN" => &mut self.alpha_min,
            "ALPMAX" => &mut self.alpha_max,
            "CAMMIN" => &mut self.camber_min,
            "CAMMAX" => &mut self.camber_max,
            "PRESMIN" => &mut self.pressure_min,
            "PRESMAX" => &mut self.pressure_max,
            _ => return None,
        })
    }

    /// Whether a point (file frame: load N, slip ratio, slip angle and
    /// inclination rad, pressure Pa) lies outside a range, i.e. is
    /// evaluated at a saturated input (or, below `FZMIN`, with the trail
    /// at `FZMIN`) when the limit checks are on.
    pub fn outside(&self, fz: f64, kappa: f64, alpha: f64, gamma: f64, p: f64) -> bool {
        let out = |x: f64, lo: Option<f64>, hi: Option<f64>| saturate(x, lo, hi) != x;
        (fz > 0.0 && out(fz, self.fz_min, self.fz_max))
            || out(kappa, self.kappa_min, self.kappa_max)
            || out(alpha, self.alpha_min, self.alpha_max)
            || out(gamma, self.camber_min, self.camber_max)
            || out(p, self.pressure_min, self.pressure_max)
    }
}

/// The loads, inclination and pressure one evaluation works with (file
/// frame, SI), after the limit checks.
#[derive(Debug, Clone, Copy)]
pub(super) struct Checked {
    /// The forces' load (at most `FZMAX` with the checks on).
    pub fz: f64,
    /// The aligning moment's trail and residual torque load (at least
    /// `FZMIN` with the checks on: MFeval's `Fz_lowLimit`).
    pub fz_trail: f64,
    /// The overturning moment's load, `Fz·(Fz/FZMIN)²` below `FZMIN`.
    pub fz_mx: f64,
    /// The rolling resistance's load: the unsaturated one, `Fz·(Fz/FZMIN)`
    /// below `FZMIN`.
    pub fz_my: f64,
    /// Inclination, rad.
    pub gamma: f64,
    /// Pressure, Pa.
    pub p: f64,
}

impl MagicFormula {
    /// The load-side inputs of a point after the limit checks (`fz > 0`
    /// as given, `gamma` in the file's frame).
    #[inline(always)]
    pub(super) fn checked(&self, fz: f64, gamma: f64, p: f64) -> Checked {
        let l = &self.limits;
        let below = |f: f64, power: i32| match l.fz_min {
            Some(m) if f < m => f * (f / m).powi(power),
            _ => f,
        };
        let fz_my = below(fz, 1);
        if !self.options.limit_checks {
            return Checked {
                fz,
                fz_trail: fz,
                fz_mx: below(fz, 2),
                fz_my,
                gamma,
                p,
            };
        }
        let fz = saturate(fz, None, l.fz_max);
        Checked {
            fz,
            fz_trail: saturate(fz, l.fz_min, None),
            fz_mx: below(fz, 2),
            fz_my,
            gamma: saturate(gamma, l.camber_min, l.camber_max),
            p: saturate(p, l.pressure_min, l.pressure_max),
        }
    }

    /// The slip ratio and slip angle (file frame) after the limit checks.
    #[inline(always)]
    pub(super) fn checked_slip(&self, kappa: f64, alpha: f64) -> (f64, f64) {
        if !self.options.limit_checks {
            return (kappa, alpha);
        }
        let l = &self.limits;
        (
            saturate(kappa, l.kappa_min, l.kappa_max),
            saturate(alpha, l.alpha_min, l.alpha_max),
        )
    }

    /// `E` clipped at 1 when the limit checks are on (MFeval), as it is.
    #[inline(always)]
    pub(super) fn clip_e(&self, e: f64) -> f64 {
        if self.options.limit_checks {
            e.min(1.0)
        } else {
            e
        }
    }

    /// The mode the tyre is evaluated in.
    pub fn mode(&self) -> MfMode {
        MfMode {
            limit_checks: self.options.limit_checks,
            alpha_star: self.options.alpha_star,
        }
    }

    /// Evaluates the tyre in `mode` from now on.
    pub fn set_mode(&mut self, mode: MfMode) {
        self.options.limit_checks = mode.limit_checks;
        self.options.alpha_star = mode.alpha_star;
    }

    /// Whether the point (crate convention) lies outside the file's ranges
    /// and the limit checks are on: it is then evaluated at the limits.
    pub fn is_clamped(&self, p: &super::MfInput) -> bool {
        !self.ranges_left(p).is_empty()
    }

    /// The ranges the limit checks hold a point's inputs to (below
    /// `FZMIN` only the trail's load is held), in the
    /// crate's frame (the columns of `tyre-eval`'s points), in the order
    /// load, slip ratio, slip angle, camber, pressure; none with the checks
    /// off. A left-side file's slip angle is the crate's negated, a right
    /// side file's inclination (as `evaluate` mirrors them): the range is
    /// negated and its ends swapped there.
    pub fn input_ranges(&self) -> Vec<InputRange> {
        if !self.options.limit_checks {
            return Vec::new();
        }
        self.file_ranges()
    }

    /// The file's ranges as [`Self::input_ranges`] gives them, whether or
    /// not the limit checks hold a point to them: with the checks off, the
    /// ranges a point is evaluated beyond as given.
    pub fn file_ranges(&self) -> Vec<InputRange> {
        let l = &self.limits;
        let mirror = self.side == super::TyreSide::Right;
        let range =
            |keys, column, unit, lo: Option<f64>, hi: Option<f64>, negated: bool| InputRange {
                keys,
                column,
                unit,
                lo: if negated { hi.map(|h| -h) } else { lo },
                hi: if negated { lo.map(|l| -l) } else { hi },
            };
        vec![
            range(["FZMIN", "FZMAX"], "fz", "N", l.fz_min, l.fz_max, false),
            range(
                ["KPUMIN", "KPUMAX"],
                "kappa",
                "",
                l.kappa_min,
                l.kappa_max,
                false,
            ),
            range(
                ["ALPMIN", "ALPMAX"],
                "alpha",
                "rad",
                l.alpha_min,
                l.alpha_max,
                !mirror,
            ),
            range(
                ["CAMMIN", "CAMMAX"],
                "camber",
                "rad",
                l.camber_min,
                l.camber_max,
                mirror,
            ),
            range(
                ["PRESMIN", "PRESMAX"],
                "pressure",
                "Pa",
                l.pressure_min,
                l.pressure_max,
                false,
            ),
        ]
    }

    /// Each range of [`Self::input_ranges`] the point `p` leaves, with its
    /// value there (crate frame; the pressure it is evaluated at). The load
    /// leaves below `FZMIN` too (the trail then takes `FZMIN`), but only
    /// above zero: a wheel off the road is no point outside a range.
    pub fn ranges_left(&self, p: &super::MfInput) -> Vec<(InputRange, f64)> {
        if !self.options.limit_checks {
            return Vec::new();
        }
        self.file_ranges_left(p)
    }

    /// [`Self::ranges_left`] whether or not the limit checks are on.
    pub fn file_ranges_left(&self, p: &super::MfInput) -> Vec<(InputRange, f64)> {
        let values = [p.fz, p.kappa, p.alpha, p.camber, self.pressure(p.pressure)];
        self.file_ranges()
            .into_iter()
            .zip(values)
            .filter(|(r, x)| (r.column != "fz" || *x > 0.0) && r.leaves(*x))
            .collect()
    }
}

/// One of a `.tir` file's ranges in the frame of the points evaluated.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct InputRange {
    /// The `.tir` keys of its ends (`["ALPMIN", "ALPMAX"]`).
    pub keys: [&'static str; 2],
    /// The input it limits, as a points file names it.
    pub column: &'static str,
    /// The input's unit (`""`: none).
    pub unit: &'static str,
    /// Lower end (`None`: not given).
    pub lo: Option<f64>,
    /// Upper end (`None`: not given).
    pub hi: Option<f64>,
}

impl InputRange {
    /// Whether `x` lies outside the range (saturated by the limit checks).
    pub fn leaves(&self, x: f64) -> bool {
        saturate(x, self.lo, self.hi) != x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn use_mode_digits_round_trip_and_turn_slip_is_refused_by_name() {
        for code in [111, 121, 211, 221] {
            assert_eq!(MfMode::from_use_mode(code).unwrap().use_mode(), code);
        }
        assert_eq!(MfMode::default().use_mode(), 121);
        let m = MfMode::from_use_mode(211).unwrap();
        assert!(!m.limit_checks && m.alpha_star == AlphaStar::Angle);
        let e = MfMode::from_use_mode(122).unwrap_err();
        assert_eq!(e, ModeError::TurnSlip { code: 122 });
        let e = e.to_string();
        assert!(e.contains("turn slip") && e.contains("121"), "{e}");
        for bad in [21, 131, 321, 120, 1121] {
            assert!(MfMode::from_use_mode(bad).is_err(), "{bad}");
        }
        // Every refused digit is named, with the whole code.
        let e = MfMode::from_use_mode(999).unwrap_err().to_string();
        assert!(
            e.starts_with(
                "mode 999: hundreds digit 9 is not 1 or 2, tens digit 9 is not 1 or 2, units digit 9 is not 1 ("
            ),
            "{e}"
        );
        let e = MfMode::from_use_mode(132).unwrap_err().to_string();
        assert!(
            e.starts_with("mode 132: tens digit 3 is not 1 or 2, units digit 2 is not 1 ("),
            "{e}"
        );
    }

    #[test]
    fn saturation_keeps_points_inside_and_moves_the_others_to_the_bound() {
        let mut l = MfLimits::default();
        assert!(
            !l.outside(1e6, 5.0, 3.0, 1.0, 1e7),
            "no ranges: nothing checked"
        );
        assert!(l.set("ALPMAX", 0.5) && l.set("ALPMIN", -0.4) && !l.set("PKY1", 1.0));
        assert_eq!(saturate(0.7, l.alpha_min, l.alpha_max), 0.5);
        assert_eq!(saturate(-0.7, l.alpha_min, l.alpha_max), -0.4);
        assert_eq!(saturate(0.1, l.alpha_min, l.alpha_max), 0.1);
        assert!(l.outside(4000.0, 0.0, 0.6, 0.0, 2e5));
        assert!(!l.outside(4000.0, 0.0, 0.5, 0.0, 2e5));
    }
}
