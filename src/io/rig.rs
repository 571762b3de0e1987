//! Tyre rig files (`docs/FORMATS.md`): a CSV with the load `fz` and a
//! lateral sweep (`alpha`, `fy`, optionally `mz`), a longitudinal sweep
//! (`kappa`, `fx`) or both, plus optional `camber`, `pressure` and `speed`,
//! and the wheel moments `mx`, `my` ([`read_rig_with_moments`]).
//! Read into [`RigData`] with every error located in the file; the data's
//! sense is checked here (positive loads in N, not kN, angles in radians, the signs of
//! the forces and the aligning moment at small slip).
//!
//! Units: N, N·m, rad, Pa, m/s; slip ratio dimensionless. Signs as in
//! `tyre/mod.rs` (a positive slip angle gives a positive `fy`).

use super::columns::Columns;
use super::rig_checks::{
    check_friction, check_grip, check_size, negative_speeds, sample_errors, speed_beyond_any,
    take_sweeps, Taken,
};
pub use super::rig_checks::{MAX_RIG_FORCE, MAX_RIG_MOMENT};
use super::rig_rows::Known;
use crate::error::{InputError, InputProblem, Reversal, RigChannel, SmallSlipSlope, UnitSlip};
use crate::identify::data::RigData;
use std::path::Path;

/// The wheel moments of a rig file, one per sample in file order, if
/// measured: `mx` (overturning moment) and `my` (rolling-resistance
/// moment), N·m, ISO-W axes of a left tyre (`mx` positive about the
/// forward axis, `my` negative while rolling forward).
pub(crate) type Moments = [Option<Vec<f64>>; 2];

/// Reads rig data as [`read_rig`] does and, in the same read, its wheel
/// moments ([`Moments`]), each beyond [`MAX_RIG_MOMENT`] refused at its row
/// once the rig data are read.
pub(crate) fn read_rig_with_moments(path: &Path) -> Result<(RigData, Moments), InputError> {
    let (d, mut c) = read_rig_columns(path, &["mx", "my"])?;
    let (mx, my) = (c.take_optional("mx"), c.take_optional("my"));
    let mut errors = check_size(path, &c, "mx", mx.as_deref(), MAX_RIG_MOMENT, "N·m");
    errors.extend(check_size(
        path,
        &c,
        "my",
        my.as_deref(),
        MAX_RIG_MOMENT,
        "N·m",
    ));
    refuse_all(path, errors)?;
    Ok((d, [mx, my]))
}

/// Refuses `errors` together, in file order, if any.
fn refuse_all(path: &Path, errors: Vec<InputError>) -> Result<(), InputError> {
    InputError::all_in_file_order(path, errors).map_or(Ok(()), Err)
}

/// Reads rig data: lateral (`alpha`, `fy`) and/or longitudinal (`kappa`,
/// `fx`) sweeps; a file with neither pair is refused.
pub fn read_rig(path: &Path) -> Result<RigData, InputError> {
    read_rig_columns(path, &[]).map(|(d, _)| d)
}

/// [`read_rig`], and the columns with the `moments` of them read besides
/// (for [`read_rig_with_moments`]) left to take.
fn read_rig_columns(path: &Path, moments: &[&str]) -> Result<(RigData, Columns), InputError> {
    const OPTIONAL: [&str; 8] = [
        "alpha", "fy", "mz", "camber", "pressure", "speed", "kappa", "fx",
    ];
    let optional: Vec<&str> = OPTIONAL.iter().chain(moments).copied().collect();
    // The wheel moments are known names, read only where asked for.
    let layout = super::columns::Layout {
        required: &["fz"],
        optional: &optional,
        also_read: Some(&["mx", "my"]),
    };
    let (mut c, mut errors) = super::columns::read_columns_with_bad_cells(path, layout)?;
    let fz = c.take("fz");
    // Every sample no tyre test holds, refused together with the cells
    // that are no numbers: a user fixing the file learns of them all at
    // once. (A cell that is no finite number is said as such alone.)
    // Every load negative is a convention (SAE's z axis points down), and
    // said so; one negative among positive loads is a bad sample.
    errors.extend(super::rig_exchanged::negative_loads(path, &c, &fz));
    errors.extend(negative_speeds(path, &c));
    errors.extend(speed_beyond_any(path, &c));
    let taken = take_sweeps(path, &mut c, fz, &mut errors)?;
    errors.extend(sample_errors(path, &c, &taken));
    refuse_all(path, errors)?;
    // The pressure's unit is judged on its own cells, apart from the
    // loads' and forces': a file with loads in kN and pressures in bar
    // is refused for both at once, not mended and rerun to hear of the
    // second (round 48).
    let pressure = c.take_optional("pressure");
    let (pressure, pressure_slip) = match pressure.map(|p| checked_pressure(path, &c, p)) {
        Some(Err(e)) => (None, Some(e)),
        p => (p.and_then(Result::ok), None),
    };
    let units = check_units(path, &c, &taken).and_then(|()| check_shapes(path, &c, &taken));
    refuse_all(
        path,
        [units.err(), pressure_slip].into_iter().flatten().collect(),
    )?;
    let Taken {
        fz,
        lateral,
        longitudinal,
        camber,
        mz,
    } = taken;
    let n = fz.len();
    let (alpha, fy) = lateral.unwrap_or_else(|| (vec![0.0; n], vec![f64::NAN; n]));
    let d = RigData {
        camber_measured: camber.is_some(),
        camber: camber.unwrap_or_else(|| vec![0.0; n]),
        mz,
        pressure,
        speed: c.take_optional("speed"),
        longitudinal,
        fz,
        alpha,
        fy,
    };
    Ok((d, c))
}

/// The units the columns were written in: loads in kN or lbf, a lone force
/// in kN, moments exchanged with forces or in kN·m, slip angles in degrees.
fn check_units(path: &Path, c: &Columns, t: &Taken) -> Result<(), InputError> {
    let fz = &t.fz;
    check_load_unit(path, c, fz)?;
    super::rig_rows::refuse_loads_in_kn(path, c, fz)?;
    // Before each sample's force is judged against its load: loads in lbf
    // make every force look too large, and are said as what they are.
    for (column, sweep) in [("fy", t.lateral()), ("fx", t.longitudinal())] {
        sweep.map_or(Ok(()), |s| {
            super::rig_scale::refuse_loads_in_lbf(path, c, column, s, fz)
        })?;
    }
    // After the loads' units: a lone cell in kN makes its force look a
    // hundred times the load, and is said as what it is.
    let median = crate::measured::clean::median(&mut fz.clone());
    let forces = [
        ("fy", t.lateral().map(|l| l.1)),
        ("fx", t.longitudinal().map(|l| l.1)),
    ];
    let mut errors = Vec::new();
    for (column, values) in forces {
        errors.extend(check_friction(path, c, column, values, fz, median));
    }
    refuse_all(path, errors)?;
    if let Some(mz) = &t.mz {
        // Before the moment's arm: `fy` and `mz` exchanged give an arm
        // of N·mm's size, and are said as what they are.
        if let Some(sweep) = t.lateral() {
            super::rig_rows::refuse_swapped_fy_mz(path, c, sweep, mz, fz, median)?;
        }
        super::rig_rows::refuse_moments_beyond_any_arm(path, c, mz, fz, median)?;
        let alpha = t.lateral().map_or(&[][..], |l| l.0);
        super::rig_scale::refuse_moments_in_knm(path, c, alpha, mz, fz)?;
    }
    if let Some((alpha, fy)) = &t.lateral {
        let kappa = t.longitudinal().map(|l| l.0);
        super::rig_degrees::refuse_alpha_in_degrees(path, c, (alpha, fy), kappa, fz)?;
    }
    Ok(())
}

/// The sweeps' shapes: grip no tyre has, and the signs of the curves.
fn check_shapes(path: &Path, c: &Columns, t: &Taken) -> Result<(), InputError> {
    let sweeps = [("fy", t.lateral.as_ref()), ("fx", t.longitudinal.as_ref())];
    for (column, sweep) in sweeps {
        if let Some((slip, force)) = sweep {
            check_grip(path, c, column, (slip, force), &t.fz)?;
        }
    }
    check_signs(path, c, t)
}

/// A pressure column in pascals, or its refusal at the first cell in
/// another unit.
fn checked_pressure(path: &Path, c: &Columns, p: Vec<f64>) -> Result<Vec<f64>, InputError> {
    if let Some((i, slip)) = pressure_not_in_pa(&p, None) {
        return Err(c.error_at(path, i, "pressure", slip.into()));
    }
    // One cell in kPa among Pa: refused at it, not dropped as a sample
    // between levels.
    super::rig_rows::refuse_rows_not_in_pa(path, c, &p, None)?;
    // A column a thousand times too large passes the median: refused at
    // each cell above any tyre's, as `tyre-eval` refuses a point's.
    super::rig_rows::refuse_pressures_above_any(path, c, &p)?;
    Ok(p)
}

/// The least median load and pressure of a tyre test: defined beside the
/// unit hints that name them ([`crate::error::Variable`]).
pub use crate::error::{MIN_MEDIAN_LOAD, MIN_MEDIAN_PRESSURE};

/// Refuses loads whose median is below [`MIN_MEDIAN_LOAD`] (in kN), at the
/// first positive load below it.
fn check_load_unit(path: &Path, c: &Columns, fz: &[f64]) -> Result<(), InputError> {
    match load_in_kn(fz, |_| true) {
        Some((i, slip)) => Err(c.error_at(path, i, "fz", slip.into())),
        None => Ok(()),
    }
}

/// Where the loads of `fz` that are `judged` (a rig's all; `tyre-eval`'s
/// those on the road, a point off it being asked for on purpose) have a
/// median below [`MIN_MEDIAN_LOAD`]: the first positive load below it and
/// why, a car's loads written in kN. None when none is judged.
pub(crate) fn load_in_kn(fz: &[f64], judged: impl Fn(f64) -> bool) -> Option<(usize, UnitSlip)> {
    let (i, median) = median_below(fz, judged, MIN_MEDIAN_LOAD)?;
    let slip = UnitSlip::LoadInKn {
        value: fz[i],
        median,
        limit: MIN_MEDIAN_LOAD,
    };
    Some((i, slip))
}

pub(crate) use super::rig_rows::INFLATION;

/// Where the positive pressures of `p` have a median below
/// [`MIN_MEDIAN_PRESSURE`]: the first positive pressure below it and why
/// (written in kPa, bar or psi), with the unit the median reads in among
/// the pressures `known` of the tyre (else [`INFLATION`]). None without
/// a positive pressure.
pub(crate) fn pressure_not_in_pa(p: &[f64], known: Option<Known>) -> Option<(usize, UnitSlip)> {
    let (i, median) = median_below(p, |v| v > 0.0, MIN_MEDIAN_PRESSURE)?;
    let slip = UnitSlip::PressureNotInPa {
        value: p[i],
        median,
        limit: MIN_MEDIAN_PRESSURE,
        meant: super::rig_rows::meant(median, known.unwrap_or(INFLATION)),
    };
    Some((i, slip))
}

/// The unit rule of a column written in a unit a thousand or more times
/// too large: where the median of the `judged` values of `v` is below
/// `limit`, the first positive value below it (the row an error names)
/// and that median. None when nothing is judged or the median passes.
fn median_below(v: &[f64], judged: impl Fn(f64) -> bool, limit: f64) -> Option<(usize, f64)> {
    let mut counted: Vec<f64> = v.iter().copied().filter(|x| judged(*x)).collect();
    if counted.is_empty() {
        return None;
    }
    let median = crate::measured::clean::median(&mut counted);
    (median < limit).then(|| {
        let i = v.iter().position(|x| *x > 0.0 && *x < limit).unwrap_or(0);
        (i, median)
    })
}

/// Reads rig data and refuses a file without lateral data.
pub fn read_lateral(path: &Path) -> Result<RigData, InputError> {
    let d = read_rig(path)?;
    if d.fy.iter().all(|v| v.is_nan()) {
        return Err(InputError::problem(path, InputProblem::NoLateral));
    }
    Ok(d)
}

/// Slip angle (rad) and slip ratio up to which a tyre's forces and
/// aligning moment still rise with slip, so their slope there has the sign
/// FORMATS.md fixes whatever the tyre (2°, well inside the force peaks of
/// road and racing tyres and below where `mz` turns over).
const SMALL_SLIP: f64 = 0.035;
/// Samples needed on each side of zero slip before a sign is judged: fewer
/// cannot tell a slope from an offset (camber thrust, conicity).
const SIGN_SAMPLES_PER_SIDE: usize = 5;
/// A slope is judged wrong only this many standard errors below zero: a
/// channel that is noise at small slip (a weak `mz`) does not show a sign.
const SIGN_STANDARD_ERRORS: f64 = 3.0;

/// A least-squares line through small-slip samples.
#[derive(Debug, Clone, Copy)]
struct Slope {
    slope: f64,
    standard_error: f64,
    /// The line's value at zero slip, and its standard error.
    at_zero: (f64, f64),
    above: usize,
    below: usize,
}

impl Slope {
    /// Fits `y = slope·x + c` to the pairs, or `None` with fewer than
    /// [`SIGN_SAMPLES_PER_SIDE`] samples on either side of `x = 0`.
    fn fit(pairs: &[(f64, f64)]) -> Option<Slope> {
        let above = pairs.iter().filter(|p| p.0 > 0.0).count();
        let below = pairs.iter().filter(|p| p.0 < 0.0).count();
        if above < SIGN_SAMPLES_PER_SIDE || below < SIGN_SAMPLES_PER_SIDE {
            return None;
        }
        let m = pairs.len() as f64;
        let (mx, my) = pairs
            .iter()
            .fold((0.0, 0.0), |(sx, sy), (x, y)| (sx + x / m, sy + y / m));
        let (sxx, sxy) = pairs.iter().fold((0.0, 0.0), |(sxx, sxy), (x, y)| {
            (sxx + (x - mx) * (x - mx), sxy + (x - mx) * (y - my))
        });
        let slope = sxy / sxx;
        let rss: f64 = pairs
            .iter()
            .map(|(x, y)| (y - my - slope * (x - mx)).powi(2))
            .sum();
        let variance = rss / (m - 2.0);
        Some(Slope {
            slope,
            standard_error: (variance / sxx).sqrt(),
            at_zero: (
                my - slope * mx,
                (variance * (1.0 / m + mx * mx / sxx)).sqrt(),
            ),
            above,
            below,
        })
    }

    fn clearly_negative(&self) -> bool {
        self.slope < -SIGN_STANDARD_ERRORS * self.standard_error
    }

    fn clearly_positive(&self) -> bool {
        self.slope > SIGN_STANDARD_ERRORS * self.standard_error
    }

    /// The slope as an error reports it, fitted within [`SMALL_SLIP`] of
    /// zero slip (`combined`: of both slips).
    fn reported(&self, combined: bool) -> SmallSlipSlope {
        SmallSlipSlope {
            slope: self.slope,
            standard_error: self.standard_error,
            above: self.above,
            below: self.below,
            small_slip: SMALL_SLIP,
            combined,
        }
    }
}

/// Refuses rig data whose forces or aligning moment have the opposite sign
/// to FORMATS.md's at small slip. A fit cannot see a flipped sign: it fits
/// the mirror image just as well (negative cornering stiffness, small σ),
/// and the tyre written from it steers the vehicle the wrong way.
fn check_signs(path: &Path, c: &Columns, t: &Taken) -> Result<(), InputError> {
    let (lateral, mz, longitudinal) = (t.lateral(), t.mz.as_deref(), t.longitudinal());
    let refuse = |channel: RigChannel, slope: SmallSlipSlope, beside: Option<f64>| {
        InputError::problem(
            path,
            InputProblem::WrongSign {
                channel,
                position: c.column(channel.column()),
                slope,
                beside,
            },
        )
    };
    // Each channel is judged at small values of the other slip, so combined
    // slip (a braking tyre's reduced Fy) does not blur the slope.
    let small = |s: Option<&[f64]>, i: usize| s.is_none_or(|s| s[i].abs() <= SMALL_SLIP);
    if let Some((alpha, fy)) = lateral {
        let kappa = longitudinal.map(|l| l.0);
        let near: Vec<usize> = (0..alpha.len())
            .filter(|&i| small(Some(alpha), i) && small(kappa, i))
            .collect();
        let combined = kappa.is_some();
        let pairs =
            |y: &[f64]| -> Vec<(f64, f64)> { near.iter().map(|&i| (alpha[i], y[i])).collect() };
        if let Some(fy_slope) = Slope::fit(&pairs(fy)) {
            let mz_slope = mz.and_then(|mz| Slope::fit(&pairs(mz)));
            if fy_slope.clearly_negative() {
                // Both channels reversed against the slip angle: a reversed
                // `alpha`, or reversed `fy` and `mz`; a camber thrust (or
                // no offset to mirror) may tell which.
                let reversed = mz_slope.filter(Slope::clearly_negative);
                return Err(match reversed {
                    Some(m) => {
                        let camber = t.camber.as_deref().and_then(|g| {
                            super::rig_camber::camber_slope(&near, (alpha, fy), &t.fz, g)
                        });
                        let r = Reversal {
                            forces: [c.column("fy"), c.column("mz")],
                            offset: fy_slope.at_zero,
                            camber,
                        };
                        refuse(
                            RigChannel::Alpha(r),
                            fy_slope.reported(combined),
                            Some(m.slope),
                        )
                    }
                    None => refuse(RigChannel::Fy, fy_slope.reported(combined), None),
                });
            }
            if let Some(mz_slope) = mz_slope {
                if fy_slope.clearly_positive() && mz_slope.clearly_negative() {
                    return Err(refuse(
                        RigChannel::Mz,
                        mz_slope.reported(combined),
                        Some(fy_slope.slope),
                    ));
                }
            }
        }
    }
    if let Some((kappa, fx)) = longitudinal {
        let alpha = lateral.map(|l| l.0);
        let pairs: Vec<(f64, f64)> = (0..kappa.len())
            .filter(|&i| small(Some(kappa), i) && small(alpha, i))
            .map(|i| (kappa[i], fx[i]))
            .collect();
        if let Some(s) = Slope::fit(&pairs).filter(Slope::clearly_negative) {
            return Err(refuse(RigChannel::Fx, s.reported(alpha.is_some()), None));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slope_needs_samples_on_both_sides_of_zero() {
        let line = |xs: &[f64]| -> Vec<(f64, f64)> { xs.iter().map(|&x| (x, -5.0 * x)).collect() };
        // Four below zero: no judgement, however clear the slope.
        let few = line(&[
            -0.03, -0.02, -0.01, -0.005, 0.0, 0.01, 0.02, 0.03, 0.04, 0.05,
        ]);
        assert!(Slope::fit(&few).is_none());
        let enough = line(&[
            -0.03, -0.02, -0.01, -0.005, -0.001, 0.01, 0.02, 0.03, 0.04, 0.05,
        ]);
        let s = Slope::fit(&enough).unwrap();
        assert!((s.slope + 5.0).abs() < 1e-12 && s.clearly_negative());
        assert_eq!((s.above, s.below), (5, 5));
    }

    #[test]
    fn a_slope_lost_in_noise_is_not_judged() {
        // A weak channel: slope −1 under noise of ±1 on a ±0.03 range.
        let pairs: Vec<(f64, f64)> = (-6..=6)
            .filter(|&i| i != 0)
            .map(|i| {
                let x = 0.005 * i as f64;
                (x, -x + if i % 2 == 0 { 1.0 } else { -1.0 })
            })
            .collect();
        let s = Slope::fit(&pairs).unwrap();
        assert!(s.slope < 0.0);
        assert!(!s.clearly_negative() && !s.clearly_positive());
    }
}
