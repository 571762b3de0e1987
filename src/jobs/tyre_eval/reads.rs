//! Which inputs a tyre's model reads, the one rule by which `tyre-eval`
//! and `simulate` judge a tyre's ranges: a point beyond the range of an
//! input the model does not read is no extrapolation (a linear tyre's
//! `Cα·α` has no load term, so a load of 4000 N past rig data at
//! 1503–1795 N was said "755 % of the range's span past its end"; a
//! simulation listed the camber and pressure ranges of the same tyre).
//!
//! Found by behaviour, as `unread.rs` finds a points file's columns the
//! model does not read: the tyre is evaluated at two probe points inside
//! its ranges (a slip angle, slip ratio and camber off zero) and again
//! with one input changed (the load and the pressure raised by a quarter,
//! the slip ratio and camber set to 0); an input is read when an output
//! (`fx`, `fy`, `mz`) moves. A Magic Formula file is not probed (it holds
//! each input at its range's end, which a probe would take for an input
//! not read): it reads every input, and the pressure only where its
//! `FITTYP`, `NOMPRES` and pressure terms give it one (`unread.rs`).
//! Units: N, rad, Pa.

use crate::io::fitted_ranges::FittedRanges;
use crate::tyre::{PointForces, Tyre};

/// The inputs a tyre reads, of those a range may be stated for (the
/// slip angle is read by every model).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Reads {
    /// The load.
    pub fz: bool,
    /// The slip ratio.
    pub kappa: bool,
    /// The camber.
    pub camber: bool,
    /// The pressure.
    pub pressure: bool,
}

/// The probe: two points (load, slip ratio, slip angle, camber, speed,
/// pressure), each input changed in turn.
type Columns = [[f64; 2]; 6];

/// Which inputs `tyre` reads, probed within `ranges` where it states
/// them (module notes).
pub fn reads(tyre: &Tyre, ranges: Option<&FittedRanges>) -> Reads {
    if let Tyre::MagicFormula(t) = tyre {
        return Reads {
            fz: true,
            kappa: true,
            camber: true,
            pressure: super::unread::mf_no_pressure(t).is_none(),
        };
    }
    let mid = |r: Option<[f64; 2]>, or: f64| r.map_or(or, |[lo, hi]| 0.5 * (lo + hi));
    let fz = mid(ranges.and_then(|r| r.fz), 3000.0);
    let p = mid(ranges.and_then(|r| r.pressure), 200e3);
    let base: Columns = [
        [fz, 1.2 * fz],
        [0.05, -0.03],
        [0.05, -0.03],
        [0.02, -0.01],
        [20.0, 20.0],
        [p, p],
    ];
    let eval = |c: &Columns| -> Vec<PointForces> {
        tyre.evaluate_points(&c[0], &c[1], &c[2], &c[3], &c[4], &c[5])
    };
    let f0 = eval(&base);
    let moves = |k: usize, change: fn(f64) -> f64| {
        let mut c = base;
        c[k] = c[k].map(change);
        let f = eval(&c);
        f.iter()
            .zip(&f0)
            .any(|(a, b)| a.fx != b.fx || a.fy != b.fy || a.mz != b.mz)
    };
    Reads {
        fz: moves(0, |v| 1.25 * v),
        kappa: moves(1, |_| 0.0),
        camber: moves(3, |_| 0.0),
        pressure: moves(5, |v| 1.25 * v),
    }
}

/// `r` without the ranges of the inputs `tyre` does not read: a point
/// past them is evaluated as at any value, no extrapolation.
pub fn read_ranges(tyre: &Tyre, r: &FittedRanges) -> FittedRanges {
    let reads = reads(tyre, Some(r));
    let kept = |read: bool, range: Option<[f64; 2]>| range.filter(|_| read);
    FittedRanges {
        fz: kept(reads.fz, r.fz),
        kappa: kept(reads.kappa, r.kappa),
        camber: kept(reads.camber, r.camber),
        pressure: kept(reads.pressure, r.pressure),
        ..*r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::Linear;

    fn tyre_file(name: &str) -> Tyre {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        crate::io::load_tyre(&root.join("tyres").join(name)).unwrap()
    }

    #[test]
    fn a_linear_tyre_reads_no_load_and_pac89_reads_load_slip_ratio_and_camber() {
        let linear = Tyre::Linear(Linear {
            cornering_stiffness: 60e3,
            pneumatic_trail: 0.03,
        });
        let none = Reads {
            fz: false,
            kappa: false,
            camber: false,
            pressure: false,
        };
        assert_eq!(reads(&linear, None), none);
        let pac89 = reads(&tyre_file("pac89_adams_example.toml"), None);
        assert_eq!(
            pac89,
            Reads {
                fz: true,
                kappa: true,
                camber: true,
                pressure: false
            }
        );
        let gim = reads(&tyre_file("gim.toml"), None);
        assert_eq!(gim, Reads { fz: true, ..none });
    }

    #[test]
    fn only_the_ranges_of_inputs_read_are_kept() {
        let r = FittedRanges {
            fz: Some([1503.0, 1795.0]),
            alpha: Some([-0.03, 0.03]),
            kappa: Some([0.0, 0.001]),
            camber: Some([-3e-4, 3e-4]),
            pressure: Some([82e3, 84e3]),
        };
        let linear = Tyre::Linear(Linear {
            cornering_stiffness: 33e3,
            pneumatic_trail: 0.03,
        });
        let kept = read_ranges(&linear, &r);
        assert_eq!(kept.alpha, r.alpha);
        assert_eq!(
            (kept.fz, kept.kappa, kept.camber, kept.pressure),
            (None, None, None, None)
        );
        let pac = read_ranges(&tyre_file("pac89_adams_example.toml"), &r);
        assert_eq!((pac.fz, pac.camber, pac.pressure), (r.fz, r.camber, None));
    }
}
