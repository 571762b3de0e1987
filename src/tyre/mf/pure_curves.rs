//! A Magic Formula tyre's own pure-slip curves, judged where a `.tir` file
//! is read: a coefficient ten times too large (`PDY1 = 8.784` for 0.8784,
//! `PCY1 = 13.332` for 1.3332) passes every size check, yet gives a force
//! no tyre gives (μ ≈ 6.3 at α = 0.5 rad), or one that turns against its
//! slip well inside the file's own slip range. The TOML tyres are refused
//! beyond a friction of [`MAX_FRICTION`]; the same limit holds here.
//!
//! Each curve is the pure-slip force (the other slip, camber and the
//! pressure at the file's own, at `LONGVL`) at three loads: `FNOMIN` and the
//! ends of `FZMIN..FZMAX` clipped to a quarter and twice `FNOMIN` (a
//! Magic Formula's load terms are fitted around its nominal load; far
//! outside, a published file's μ rises past any tyre's, e.g. a negative
//! `PDY2` towards zero load). The slips: α over (0, min(ALPMAX, 30°)] and
//! [max(ALPMIN, −30°), 0), κ over (0, min(KPUMAX, 1)] and
//! [max(KPUMIN, −1), 0), on a grid of [`POINTS`] per side. Units: SI, rad.

use super::{MagicFormula, MfCoefficients};
use crate::error::{CurveFault, ParamError, ParamReason};
use crate::tyre::sizes::MAX_FRICTION;

/// Grid points on each side of a curve.
const POINTS: usize = 600;

/// The largest slip angle judged, rad (30°): beyond a rig's sweep and any
/// car's, where a file's curve is extrapolation.
const MAX_ALPHA: f64 = std::f64::consts::FRAC_PI_6;

/// The largest |slip ratio| judged (a locked wheel).
const MAX_KAPPA: f64 = 1.0;

/// A force against its slip counts as turned once it passes this share of
/// the load, after the curve has passed it on its own side: smaller ones
/// are the shifts' (`SVy`, `SHy`: a few per cent of the load at most),
/// not a turn.
const TURN: f64 = 0.05;

/// The largest |C| = |PC?1·LC?| a curve is judged flat at: a tenth of
/// any tyre's (about 1.1–1.9). A larger C that still gives a flat curve
/// has another cause, which the other checks name.
const FLAT_SHAPE: f64 = 0.1;

/// What a scan found wrong, at a load and slip.
#[derive(Clone, Copy)]
struct Fault {
    /// |F|/Fz of a peak, or the force (N) of a turn or a flat curve.
    at: f64,
    fault: CurveFault,
    load: f64,
    slip: f64,
}

/// Where a tyre's pure curve peaks highest ([`MagicFormula::peak_friction`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakFriction {
    /// The lateral curve (else the longitudinal).
    pub lateral: bool,
    /// |F|/Fz there.
    pub ratio: f64,
    /// The load, N.
    pub load: f64,
    /// The slip angle (rad) or ratio.
    pub slip: f64,
}

/// The peak |F|/Fz above which reading a `.tir` warns: racing slicks
/// reach about 1.8 on a rig, road tyres 1.0–1.3; published defaults
/// (`FSAE_Defaults.tir`, 3.4 at light load) go beyond, and are public
/// files, so they are read and the number said.
pub(crate) const WARN_FRICTION: f64 = 2.5;

impl std::fmt::Display for PeakFriction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::format::{readable, rounded};
        let (force, slip) = match self.lateral {
            true => (
                "|Fy|/Fz",
                format!(
                    "slip angle {} rad, {}°",
                    readable(self.slip, 3),
                    readable(self.slip.to_degrees(), 3)
                ),
            ),
            false => ("|Fx|/Fz", format!("slip ratio {}", readable(self.slip, 3))),
        };
        write!(
            f,
            "the file's pure {} force peaks at {force} = {} at Fz = {} N and {slip}, above the {WARN_FRICTION} of any tyre on a road or rig (racing slicks about 1.8): its forces there are the file's, not a tyre's",
            if self.lateral { "lateral" } else { "longitudinal" },
            readable(self.ratio, 3),
            rounded(self.load, 5),
        )
    }
}

/// The coefficient names of a channel: peak, its scale, its load
/// dependence, shape, the shape's scale, curvature.
struct Names {
    peak: &'static str,
    scale: &'static str,
    per_load: &'static str,
    shape: &'static str,
    shape_scale: &'static str,
    curvature: &'static str,
}

const LATERAL: Names = Names {
    peak: "PDY1",
    scale: "LMUY",
    per_load: "PDY2",
    shape: "PCY1",
    shape_scale: "LCY",
    curvature: "PEY1",
};

const LONGITUDINAL: Names = Names {
    peak: "PDX1",
    scale: "LMUX",
    per_load: "PDX2",
    shape: "PCX1",
    shape_scale: "LCX",
    curvature: "PEX1",
};

impl MagicFormula {
    /// Ok when the pure lateral curve (`lateral`) and the pure longitudinal
    /// curve (`longitudinal`) stay within any tyre's: a peak |F|/Fz of at
    /// most [`MAX_FRICTION`], and no force that turns against its slip by
    /// more than [`TURN`] of the load. Else the coefficient most likely at
    /// fault, with the load and slip where it shows.
    pub(crate) fn check_pure_curves(
        &self,
        lateral: bool,
        longitudinal: bool,
    ) -> Result<(), ParamError> {
        for (judged, is_lateral) in [(lateral, true), (longitudinal, false)] {
            if !judged {
                continue;
            }
            if let Some(f) = self.flat(is_lateral) {
                return Err(self.curve_error(is_lateral, &f));
            }
            let faults: Vec<Fault> = self
                .judged_loads()
                .iter()
                .filter_map(|&fz| {
                    let (peak, turn, _) = self.scan(is_lateral, fz);
                    peak.or(turn)
                })
                .collect();
            // A too-high peak first: it names the peak coefficient, which
            // is the clearer slip when both show.
            let worst = faults
                .iter()
                .filter(|f| f.fault == CurveFault::Peak)
                .max_by(|a, b| a.at.total_cmp(&b.at));
            if let Some(f) = worst.or_else(|| faults.first()) {
                return Err(self.curve_error(is_lateral, f));
            }
        }
        Ok(())
    }

    /// The highest |F|/Fz of the pure lateral (`lateral`) and longitudinal
    /// (`longitudinal`) curves over the loads and slips
    /// [`Self::check_pure_curves`] judges, where it lies above `above`:
    /// the curve (lateral or not), |F|/Fz, the load (N) and the slip
    /// (rad, or the ratio). A published file may reach 3 (its μ rising
    /// towards light load); a warning says it with these numbers.
    pub(crate) fn peak_friction(
        &self,
        (lateral, longitudinal): (bool, bool),
        above: f64,
    ) -> Option<PeakFriction> {
        [(lateral, true), (longitudinal, false)]
            .into_iter()
            .filter(|(judged, _)| *judged)
            .flat_map(|(_, is_lateral)| {
                self.judged_loads()
                    .into_iter()
                    .filter_map(move |fz| self.scan(is_lateral, fz).2.map(|f| (is_lateral, f)))
            })
            .filter(|(_, f)| f.at > above)
            .max_by(|a, b| a.1.at.total_cmp(&b.1.at))
            .map(|(lateral, f)| PeakFriction {
                lateral,
                ratio: f.at,
                load: f.load,
                slip: f.slip,
            })
    }

    /// `FNOMIN` and the ends of the file's load range clipped to a quarter
    /// and twice `FNOMIN`, N.
    fn judged_loads(&self) -> [f64; 3] {
        let fnomin = self.coefficients.FNOMIN;
        let hi = self
            .limits
            .fz_max
            .unwrap_or(f64::INFINITY)
            .min(2.0 * fnomin);
        let lo = self.limits.fz_min.unwrap_or(0.0).max(0.25 * fnomin).min(hi);
        [lo, fnomin.clamp(lo, hi), hi]
    }

    /// The curve of a file whose peak is a tyre's (|μ| = |PD?1·LMU?| above
    /// [`TURN`]) but whose force moves by less than [`TURN`] of the load
    /// over its whole slip range at `FNOMIN`, with a shape factor
    /// C = PC?1·LC? of at most [`FLAT_SHAPE`]: `PCY1 = 0` gave a constant
    /// −49 N at every slip angle at 2 kN (the shift `SVy` alone), which
    /// no other check saw. A file giving no force at all (`PDX1 = 0`,
    /// written by a fit without longitudinal data) is not judged here.
    fn flat(&self, lateral: bool) -> Option<Fault> {
        let n = match lateral {
            true => LATERAL,
            false => LONGITUDINAL,
        };
        let get = |k: &str| self.coefficients.get(k).unwrap_or(0.0);
        let shape = (get(n.shape) * get(n.shape_scale)).abs();
        if (get(n.peak) * get(n.scale)).abs() <= TURN || shape > FLAT_SHAPE {
            return None;
        }
        let fz = self.coefficients.FNOMIN;
        let at = self.at_load(fz, None, 0.0);
        let speed = self.coefficients.LONGVL;
        let force = |x: f64| match lateral {
            true => at.forces(0.0, x, speed).fy,
            false => at.forces(x, 0.0, speed).fx,
        };
        let end = match lateral {
            true => MAX_ALPHA,
            false => MAX_KAPPA,
        };
        let zero = force(0.0);
        let grid = (-(POINTS as i64)..=POINTS as i64).map(|i| end * i as f64 / POINTS as f64);
        let moves = grid.map(|x| (force(x) - zero).abs()).fold(0.0, f64::max);
        (moves < TURN * fz).then_some(Fault {
            at: force(end),
            fault: CurveFault::Flat,
            load: fz,
            slip: end,
        })
    }

    /// The pure curve at load `fz`: its peak beyond [`MAX_FRICTION`] (the
    /// highest), its first turn against the slip, and its highest |F|/Fz
    /// whatever its size.
    fn scan(&self, lateral: bool, fz: f64) -> (Option<Fault>, Option<Fault>, Option<Fault>) {
        let (lo_key, hi_key, max) = match lateral {
            true => ("ALPMIN", "ALPMAX", MAX_ALPHA),
            false => ("KPUMIN", "KPUMAX", MAX_KAPPA),
        };
        let speed = self.coefficients.LONGVL;
        let at = self.at_load(fz, None, 0.0);
        let force = |x: f64| match lateral {
            true => at.forces(0.0, x, speed).fy,
            false => at.forces(x, 0.0, speed).fx,
        };
        // The side a small slip pushes to (the stiffness's sign).
        let own = (force(1e-4) - force(-1e-4)).signum();
        let ends = [
            (1.0, self.limits.get(hi_key).unwrap_or(max).min(max)),
            (-1.0, (-self.limits.get(lo_key).unwrap_or(-max)).min(max)),
        ];
        let mut turn: Option<Fault> = None;
        let mut top: Option<Fault> = None;
        for (side, end) in ends.into_iter().filter(|(_, end)| *end > 0.0) {
            let mut passed = false;
            for i in 1..=POINTS {
                let x = side * end * i as f64 / POINTS as f64;
                let f = force(x);
                let ratio = f.abs() / fz;
                if top.as_ref().is_none_or(|p| ratio > p.at) {
                    top = Some(Fault {
                        at: ratio,
                        fault: CurveFault::Peak,
                        load: fz,
                        slip: x,
                    });
                }
                let along = side * own * f;
                passed |= along > TURN * fz;
                if passed && along < -TURN * fz && turn.is_none() && own != 0.0 {
                    turn = Some(Fault {
                        at: f,
                        fault: CurveFault::Reversal,
                        load: fz,
                        slip: x,
                    });
                }
            }
        }
        (top.filter(|p| p.at > MAX_FRICTION), turn, top)
    }

    /// The refusal of fault `f` of the `lateral` (else longitudinal) curve,
    /// at the coefficient most likely at fault.
    fn curve_error(&self, lateral: bool, f: &Fault) -> ParamError {
        let c = &self.coefficients;
        let n = match lateral {
            true => LATERAL,
            false => LONGITUDINAL,
        };
        let get = |k: &str| c.get(k).unwrap_or(0.0);
        let shape = get(n.shape) * get(n.shape_scale);
        let key = match f.fault {
            CurveFault::Reversal => most_likely_shape(&n, shape, get(n.shape)),
            CurveFault::Peak => most_likely_peak(c, &n, f.load),
            // The one of PC?1 and LC? nearer 0 (a scale's 1, a tyre's 1.1–1.9).
            CurveFault::Flat => match get(n.shape_scale).abs() < get(n.shape).abs() {
                true => n.shape_scale,
                false => n.shape,
            },
        };
        let reason = ParamReason::mf_pure_curve(
            (lateral, key),
            (f.at, f.fault),
            (f.load, f.slip),
            (shape, c.LONGVL),
        );
        ParamError::new(key, get(key), reason)
    }
}

/// The coefficient a peak beyond any tyre's is most likely due to: the
/// peak itself where it alone is beyond, its scale far from the 1 a fit
/// leaves, the load term where it carries the peak there; else the peak.
fn most_likely_peak(c: &MfCoefficients, n: &Names, fz: f64) -> &'static str {
    let get = |k: &str| c.get(k).unwrap_or(0.0);
    let fz0 = c.FNOMIN * c.LFZO;
    let dfz = (fz - fz0) / fz0;
    if get(n.peak).abs() > MAX_FRICTION {
        n.peak
    } else if get(n.scale).abs() > 2.0 {
        n.scale
    } else if (get(n.peak) + get(n.per_load) * dfz).abs() > MAX_FRICTION {
        n.per_load
    } else {
        n.peak
    }
}

/// The coefficient a turn against the slip is most likely due to: with
/// C = PC?1·LC? above 2 (past which `sin(C·atan(B·x))` turns negative), the
/// one of the two beyond 2; else the curvature.
fn most_likely_shape(n: &Names, shape: f64, pc1: f64) -> &'static str {
    match (shape.abs() > 2.0, pc1.abs() > 2.0) {
        (true, true) => n.shape,
        (true, false) => n.shape_scale,
        (false, _) => n.curvature,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The MF 6.1 sample of the fixtures, as read, before its curves are
    /// judged.
    fn sample() -> MagicFormula {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/fixtures/tir/MagicFormula61_Parameters.tir"
        );
        crate::io::tir::TirDocument::read(std::path::Path::new(path))
            .and_then(|d| d.template())
            .unwrap()
    }

    fn refused(edit: impl Fn(&mut MfCoefficients)) -> ParamError {
        let mut t = sample();
        edit(&mut t.coefficients);
        t.check_pure_curves(true, true).unwrap_err()
    }

    #[test]
    fn a_published_tyres_curves_pass_and_the_loads_are_clipped_about_fnomin() {
        let t = sample();
        assert!(t.check_pure_curves(true, true).is_ok());
        // FZMIN = 0 and FZMAX = 18000 around FNOMIN = 6752: a quarter and
        // twice FNOMIN.
        assert_eq!(t.judged_loads(), [1688.0, 6752.0, 13504.0]);
    }

    /// Each slip is named by the coefficient that makes it: the peak, its
    /// scale, the shape and its scale, lateral and longitudinal.
    #[test]
    fn the_coefficient_at_fault_is_named() {
        let key = |e: ParamError| (e.key.clone(), e.to_string());
        let (k, e) = key(refused(|c| c.PDY1 *= 10.0));
        assert_eq!(k, "PDY1");
        assert!(e.contains("reach |Fy|/Fz = "), "{e}");
        assert_eq!(key(refused(|c| c.LMUY = 8.0)).0, "LMUY");
        let (k, e) = key(refused(|c| c.PCY1 *= 10.0));
        assert_eq!(k, "PCY1");
        assert!(e.contains("C = PCY1·LCY = 14.76 lies above 2"), "{e}");
        assert_eq!(key(refused(|c| c.LCY = 10.0)).0, "LCY");
        assert_eq!(key(refused(|c| c.PDX1 *= 10.0)).0, "PDX1");
        assert_eq!(key(refused(|c| c.PCX1 *= 10.0)).0, "PCX1");
        // A shape factor of 0 leaves the shifts' force at every slip.
        let (k, e) = key(refused(|c| c.PCY1 = 0.0));
        assert_eq!(k, "PCY1");
        assert!(e.contains("the same at every slip angle"), "{e}");
        assert_eq!(key(refused(|c| c.LCX = 0.0)).0, "LCX");
        // A longitudinal block the file does not describe is not judged.
        let mut t = sample();
        t.coefficients.PDX1 *= 10.0;
        assert!(t.check_pure_curves(true, false).is_ok());
    }

    /// The limit is the TOML tyres' friction 5: a peak just under passes,
    /// just over is refused (PDY1 alone sets μy at FNOMIN here: the
    /// sample's PDY2 lowers it above FNOMIN, raises it below).
    #[test]
    fn the_peak_limit_is_the_toml_tyres_friction() {
        let peak = |pdy1: f64| {
            let mut t = sample();
            t.coefficients.PDY1 = pdy1;
            t.check_pure_curves(true, false)
        };
        assert!(peak(4.0).is_ok());
        let e = peak(5.5).unwrap_err().to_string();
        assert!(e.contains("beyond the friction 5"), "{e}");
    }
}
