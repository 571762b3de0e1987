//! The sizes a tyre file's dimensional parameters can hold: a value no
//! tyre has in the file's unit is a unit slip (a contact length of 180 for
//! 180 mm, a load of 4 for 4 kN, a coefficient of 1e30), refused when the
//! file is read, at its key, with the unit it is likely in
//! ([`crate::error::Limit`] says why). The limits lie well outside every
//! tyre, so that no real one and no fitted one (the fits' boxes are
//! narrower) is refused. Units: SI, as the models hold them (N, m, N/rad,
//! Pa); a Magic Formula file's values after its `[UNITS]` are applied.

use crate::error::{Limit, ParamError, ParamReason, PerLoad};
use crate::tyre::mf::MfCoefficients;

/// The longest contact patch, m (a car tyre's is 0.1–0.25 m, a truck's
/// about 0.3 m).
pub const MAX_CONTACT_LENGTH: f64 = 1.0;

/// The stiffest tyre's cornering stiffness, N/rad (a truck tyre's is
/// about 3e5 N/rad, a car's 5e4–1.5e5).
pub const MAX_CORNERING_STIFFNESS: f64 = 2e6;

/// The least cornering stiffness, N/rad: a bicycle tyre's is about 5e3,
/// a car tyre's 5e4–1.5e5; a car tyre's stiffness typed in N/deg (500–2,500)
/// lands below or near it. Under the fits' box (1e3), so that no fitted
/// tyre is refused.
pub const MIN_CORNERING_STIFFNESS: f64 = 900.0;

/// The least cornering stiffness per unit of a tyre's own load, `Cα/Fz`
/// at its stated (reference or rated) load, 1/rad. Pacejka's example car
/// tyre, a 205/60R15 (*Tyre and Vehicle Dynamics*, 2012; MFeval's public
/// `PacejkaBook_Defaults.tir`), has 12.0 at its FNOMIN of 4 kN; Gillespie
/// (*Fundamentals of Vehicle Dynamics*, 1992, pp. 347–355) gives 0.08–0.18
/// per degree for bias-ply and 0.11–0.19 for radial car tyres (4.6–10.9
/// 1/rad); the public `.tir` files evaluated at their FNOMIN (the fixtures
/// and the public MFeval and Simscape sets) lie between 6.7 (a 430/50R38
/// tyre at 30 kN) and 44 (car tyres), up to 61 at a quarter of it. A
/// stiffness typed in N/deg is 57.3 times too small: 0.08–1.07 there. The
/// floor lies between, three times below the softest tyre's and above
/// every N/deg figure of those files. A Gim fit's box starts at it
/// ([`crate::tyre::Parameterised::bounds`]), so `identify` writes no
/// stiffness the readers refuse.
pub const MIN_CORNERING_PER_LOAD: f64 = 1.5;

/// The least |`a3`| of a PAC89 file, N/deg: `a3` bounds its lateral
/// curve's cornering stiffness `BCD = a3·sin(2·atan(Fz/a4))` (PAC89's
/// slip angle is in degrees). A car tyre's is 1000–3000 N/deg;
/// [`MIN_CORNERING_STIFFNESS`] is 15.7 N/deg, rounded down here, under
/// the fit's box (100). An `a3` typed in kN/deg (1–3) lands below. No
/// upper end: a tyre whose stiffness rises in proportion to the load to
/// the last load tested is fitted with `a3` and `a4` both far above any
/// load (Zhang et al.'s two-stage fit reaches 1e11), which `BCD` never
/// reaches.
pub const MIN_PAC89_A3: f64 = 15.0;

/// The least `p3` of a UniTire file's lateral or longitudinal block: the
/// slip stiffness per unit load at light load, `K/Fz` per unit `tan α` or
/// slip ratio `Sx` (`K = Fz·(p3 + p4·Fzn + p5·Fzn²)`), 10–30 for road and
/// racing tyres. The same per degree (0.17–0.5) or per percent of slip
/// (0.1–0.3) lands below it; under the fit's box (1), so that no fitted
/// tyre is refused.
pub const MIN_UNITIRE_P3: f64 = 0.9;

/// The loads of a tyre, N: a bicycle's above 100 N, a mining truck's
/// below 1e5 N.
pub const TYRE_LOAD: (f64, f64) = (100.0, 1e5);

/// The largest friction coefficient, μ (racing slicks reach about 1.8).
pub const MAX_FRICTION: f64 = 5.0;

/// The largest |pneumatic trail|, m (a car tyre's is a few centimetres).
pub const MAX_TRAIL: f64 = 0.5;

/// A tyre's unloaded radius, m: a kart's is above 0.1 m, a mining
/// truck's below 2 m.
pub const UNLOADED_RADIUS: (f64, f64) = (0.05, 2.0);

/// A tyre's inflation pressure, Pa: a kart's is about 60 kPa, a car's
/// 200–300 kPa, a truck's 600–900 kPa, a track bicycle's up to 1.4 MPa.
/// A pressure in kPa, bar or psi read as Pa (220, 2.2, 32) lands far below.
pub const TYRE_PRESSURE: (f64, f64) = (1e4, 2e6);

/// The largest |coefficient| of a Magic Formula file, in SI: its
/// dimensionless coefficients stay within about ±2,000 in published
/// files (RBY4 of some reaches 1,747).
pub const MAX_MF_COEFFICIENT: f64 = 1e6;

/// The largest stiffness (N/m) or pressure (Pa) of a Magic Formula file:
/// vertical stiffnesses are below 2e6 N/m, pressures below 1e6 Pa.
pub const MAX_MF_DIMENSIONAL: f64 = 1e8;

/// The coefficients of a Magic Formula file in N/m or Pa.
const MF_DIMENSIONAL: [&str; 3] = ["VERTICAL_STIFFNESS", "NOMPRES", "INFLPRES"];

/// A contact length, m.
pub(crate) fn contact_length(key: &str, v: f64) -> Result<(), ParamError> {
    ParamError::in_range(
        key,
        v,
        0.0,
        MAX_CONTACT_LENGTH,
        Limit::ContactLength { given: v },
    )
}

/// A cornering stiffness, N/rad: a small positive one is said as the
/// N/deg it likely is, with the value given converted.
pub(crate) fn cornering_stiffness(key: &str, v: f64) -> Result<(), ParamError> {
    let why = match v > 0.0 && v <= MIN_CORNERING_STIFFNESS {
        true => Limit::CorneringStiffnessInDegrees { given: v },
        false => Limit::CorneringStiffness,
    };
    ParamError::in_range(
        key,
        v,
        MIN_CORNERING_STIFFNESS,
        MAX_CORNERING_STIFFNESS,
        why,
    )
}

/// A cornering stiffness `v` (N/rad, the key `key`) at the tyre's own
/// load (N, its key, and whether it is the model's default) per unit of
/// that load, at least
/// [`MIN_CORNERING_PER_LOAD`]: one below is said as the N/deg it likely
/// is, with the value given converted. (Above the floor of any tyre,
/// [`cornering_stiffness`], a car tyre's N/deg figure still passes: 1000
/// N/deg read as 1000 N/rad is 0.25 per N of a 4 kN load.)
pub(crate) fn cornering_per_load(
    key: &str,
    v: f64,
    (load_key, load, default): (&'static str, f64, bool),
) -> Result<(), ParamError> {
    let per_load = v / load;
    match per_load >= MIN_CORNERING_PER_LOAD {
        true => Ok(()),
        false => Err(ParamError::new(
            key,
            v,
            ParamReason::CorneringPerLoad(Box::new(PerLoad {
                per_load,
                load_key,
                load,
                default,
                min: MIN_CORNERING_PER_LOAD,
            })),
        )),
    }
}

/// The load [`cornering_per_load`] takes a tyre's stiffness at where the
/// tyre has no load of its own: the vehicle's, standing still.
pub(crate) const STATIC_WHEEL_LOAD: &str =
    "static load on each wheel of its axle (from the vehicle's mass, a and b)";

/// The load a points file evaluates a tyre with no load of its own at.
pub(crate) const POINTS_MEDIAN_LOAD: &str = "median load of the points evaluated";

/// PAC89's `a3`, N/deg, by its size (`a3` and `a4` may both be negative,
/// [`crate::tyre::ModelParameters::canonicalise`]): one below
/// [`MIN_PAC89_A3`] is said as the kN/deg it likely is.
pub(crate) fn pac89_cornering_stiffness(key: &str, v: f64) -> Result<(), ParamError> {
    ParamError::finite(key, v)?;
    match v.abs() > MIN_PAC89_A3 {
        true => Ok(()),
        false => Err(ParamError::new(
            key,
            v,
            ParamReason::MagnitudeAtMost {
                min: MIN_PAC89_A3,
                why: Limit::Pac89CorneringStiffnessInKn,
            },
        )),
    }
}

/// The largest cornering stiffness of a PAC89 file's lateral curve,
/// `|a3·sin(2·atan(Fz/a4))|` (N/deg) over loads of 0.1 to 100 kN (`a4` in
/// kN), below [`MAX_CORNERING_STIFFNESS`]: `a3` alone has no upper end (a
/// fit with both `a3` and `a4` far above any load is a tyre), their
/// combination does, and the refusal says so with the load it peaks at.
pub(crate) fn pac89_peak_stiffness(a3: f64, a4: f64) -> Result<(), ParamError> {
    let limit = MAX_CORNERING_STIFFNESS.to_radians();
    // sin(2·atan(x)) peaks at x = 1 (Fz = a4) and is monotone either side.
    let at = |fz: f64| (a3 * (2.0 * (fz / a4).atan()).sin()).abs();
    let (peak, fz) = if (0.1..=100.0).contains(&a4.abs()) {
        (a3.abs(), a4.abs())
    } else if at(0.1) >= at(100.0) {
        (at(0.1), 0.1)
    } else {
        (at(100.0), 100.0)
    };
    if peak.is_finite() && peak <= limit {
        return Ok(());
    }
    Err(ParamError::new(
        "a3",
        a3,
        ParamReason::Pac89PeakStiffness { a4, peak, fz },
    ))
}

/// A UniTire block's `p3` (`longitudinal`: the longitudinal block's),
/// above [`MIN_UNITIRE_P3`]: a small one is said as the per-degree or
/// per-percent value it likely is.
pub(crate) fn unitire_stiffness(key: &str, v: f64, longitudinal: bool) -> Result<(), ParamError> {
    let why = match longitudinal {
        true => Limit::UniTireSlipStiffness,
        false => Limit::UniTireCorneringStiffness,
    };
    ParamError::in_range(key, v, MIN_UNITIRE_P3, f64::INFINITY, why)
}

/// A tyre's load (a reference or rated load), N.
pub(crate) fn tyre_load(key: &str, v: f64) -> Result<(), ParamError> {
    ParamError::in_range(key, v, TYRE_LOAD.0, TYRE_LOAD.1, Limit::TyreLoad)
}

/// A friction coefficient.
pub(crate) fn friction(key: &str, v: f64) -> Result<(), ParamError> {
    ParamError::in_range(key, v, 0.0, MAX_FRICTION, Limit::TyreFriction)
}

/// A pneumatic trail, m.
pub(crate) fn trail(key: &str, v: f64) -> Result<(), ParamError> {
    ParamError::in_range(key, v, -MAX_TRAIL, MAX_TRAIL, Limit::PneumaticTrail)
}

/// The coefficients of a Magic Formula tyre, in SI: its load and radius,
/// then every coefficient's size.
pub(crate) fn magic_formula(c: &MfCoefficients) -> Result<(), ParamError> {
    tyre_load("FNOMIN", c.FNOMIN)?;
    let (lo, hi) = UNLOADED_RADIUS;
    ParamError::in_range(
        "UNLOADED_RADIUS",
        c.UNLOADED_RADIUS,
        lo,
        hi,
        Limit::UnloadedRadius {
            given: c.UNLOADED_RADIUS,
        },
    )?;
    tyre_pressure("NOMPRES", c.NOMPRES, c.INFLPRES)?;
    tyre_pressure("INFLPRES", c.INFLPRES, c.NOMPRES)?;
    for name in MfCoefficients::NAMES {
        let v = c.get(name).unwrap_or(0.0);
        let (max, why) = if MF_DIMENSIONAL.contains(name) {
            (MAX_MF_DIMENSIONAL, Limit::MfDimensional)
        } else {
            (MAX_MF_COEFFICIENT, Limit::MfCoefficient)
        };
        ParamError::in_range(name, v, -max, max, why)?;
    }
    Ok(())
}

/// A Magic Formula file's pressure `v` at `key` (`NOMPRES` or
/// `INFLPRES`; 0 is none, the pressure terms off), Pa, beside the file's
/// other pressure `other`: outside [`TYRE_PRESSURE`] it is refused with
/// the unit it likely is in. That is the unit the other key says, where
/// the other is a tyre's pressure and lies that unit's factor (±15 %)
/// above it (220 beside 220000: kPa); else the one that lands it nearest
/// a car tyre's 250 kPa among the tyres' pressures (2.2: bar, not psi's
/// 15 kPa; 32: psi, not kPa's 32 kPa).
pub(crate) fn tyre_pressure(key: &str, v: f64, other: f64) -> Result<(), ParamError> {
    let (lo, hi) = TYRE_PRESSURE;
    if v <= 0.0 || (v > lo && v <= hi) || !v.is_finite() {
        return Ok(());
    }
    let units = Limit::PRESSURE_UNITS;
    let lands = |pa: f64| v * pa > lo && v * pa <= hi;
    let apart = (other > lo && other <= hi)
        .then(|| (0..units.len()).find(|&i| (other / (v * units[i].1) - 1.0).abs() <= 0.15))
        .flatten();
    let nearest = || {
        (0..units.len())
            .filter(|&i| lands(units[i].1))
            .min_by(|&i, &j| {
                let off = |k: usize| (v * units[k].1 / 2.5e5).ln().abs();
                off(i).total_cmp(&off(j))
            })
    };
    let unit = apart.or_else(nearest);
    let why = Limit::TyrePressure {
        given: v,
        unit: unit.map(|i| i as u8),
        nominal: key == "NOMPRES",
        apart: apart.is_some(),
    };
    Err(ParamError::new(
        key,
        v,
        ParamReason::OutOfRange { lo, hi, why },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A PAC89 cornering stiffness is judged by `a3·sin(2·atan(Fz/a4))`
    /// over the loads a tyre carries, not by `a3` alone: the Adams example
    /// passes, so does a fit with `a3` and `a4` both at 1e11 (at 100 kN its
    /// stiffness is 200 N/deg), and an `a3` of 1e6 N/deg with a load-sized
    /// `a4` (a force that steps at zero slip) is refused.
    #[test]
    fn a_pac89_stiffness_is_judged_with_its_load_scale() {
        assert!(pac89_peak_stiffness(1250.0, 12.8).is_ok());
        assert!(pac89_peak_stiffness(1e11, 1e11).is_ok());
        let e = pac89_peak_stiffness(1e6, 12.8).unwrap_err().to_string();
        assert!(e.contains("a step at zero slip"), "{e}");
        assert!(pac89_peak_stiffness(3e300, 12.8).is_err());
        // Just inside and just outside 2e6 N/rad at the peak (Fz = a4).
        let limit = MAX_CORNERING_STIFFNESS.to_radians();
        assert!(pac89_peak_stiffness(0.999 * limit, 12.8).is_ok());
        assert!(pac89_peak_stiffness(1.001 * limit, 12.8).is_err());
        // Said with the load it peaks at, not as a bound on a3 alone
        // (which a large a4 lets a3 pass).
        assert!(e.contains("reaches 1e6 N/deg at Fz = 12.8 kN"), "{e}");
        // The limit the message states (text, in the error layer) is this
        // module's.
        let stated = format!("any tyre's {} N/deg", limit.round());
        assert!(e.contains(&stated), "{e}");
        let e = pac89_peak_stiffness(1e9, 500.0).unwrap_err().to_string();
        assert!(e.contains("at Fz = 100 kN"), "{e}");
    }

    /// A pressure in kPa, bar or psi read as Pa is refused with the unit
    /// that the other pressure key says (its factor apart), else the one
    /// nearest a car tyre's; 0 (no pressure) and every tyre's pass.
    #[test]
    fn a_tyre_pressure_in_another_unit_is_refused_with_that_unit() {
        let unit = |v: f64, other: f64| match tyre_pressure("NOMPRES", v, other) {
            Ok(()) => None,
            Err(e) => match e.reason {
                ParamReason::OutOfRange {
                    why: Limit::TyrePressure { unit, apart, .. },
                    ..
                } => Some((unit.map(|u| Limit::PRESSURE_UNITS[u as usize].0), apart)),
                other => panic!("{other:?}"),
            },
        };
        for ok in [0.0, 60e3, 220e3, 1.4e6] {
            assert_eq!(unit(ok, 220e3), None, "{ok}");
        }
        assert_eq!(unit(220.0, 220e3), Some((Some("kPa"), true)));
        assert_eq!(unit(2.2, 220e3), Some((Some("bar"), true)));
        assert_eq!(unit(32.0, 220632.0), Some((Some("psi"), true)));
        // Alone: the reading nearest 250 kPa (2.2 bar, not 15 kPa in psi).
        assert_eq!(unit(2.2, 0.0), Some((Some("bar"), false)));
        assert_eq!(unit(32.0, 0.0), Some((Some("psi"), false)));
        assert_eq!(unit(5e6, 0.0), Some((None, false)));
        let e = tyre_pressure("INFLPRES", 220.0, 220e3)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(
                "is it in kPa? (220 kPa is 220000 Pa); the file's NOMPRES is about 1000 times it"
            ),
            "{e}"
        );
    }

    /// `a3`'s sign is a side's: −5 is refused as +5 is, −20 passes as +20
    /// does, and the refusal says the rule is on the magnitude (it read
    /// "must be greater than 15" for −5 while −20 passed).
    #[test]
    fn a_pac89_a3_is_refused_by_its_magnitude_and_said_so() {
        for v in [-5.0, 5.0, 15.0] {
            let e = pac89_cornering_stiffness("a3", v).unwrap_err().to_string();
            assert!(
                e.contains("larger than 15 in magnitude (either sign)"),
                "{e}"
            );
        }
        assert!(pac89_cornering_stiffness("a3", -20.0).is_ok());
        assert!(pac89_cornering_stiffness("a3", 20.0).is_ok());
    }
}
