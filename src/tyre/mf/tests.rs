//! Invariants of the Magic Formula by property test.

use super::*;
use crate::tyre::kernels;
use proptest::prelude::*;

/// A symmetric 6.1 tyre: no shifts, no asymmetric camber terms.
fn symmetric() -> MagicFormula {
    let mut c = MfCoefficients {
        FNOMIN: 4000.0,
        UNLOADED_RADIUS: 0.31,
        NOMPRES: 220_000.0,
        ..MfCoefficients::default()
    };
    for (k, v) in [
        ("PCX1", 1.6),
        ("PDX1", 1.2),
        ("PDX2", -0.1),
        ("PEX1", 0.3),
        ("PKX1", 22.0),
        ("PCY1", 1.3),
        ("PDY1", 1.1),
        ("PDY2", -0.15),
        ("PEY1", -0.8),
        ("PKY1", -15.0),
        ("PKY2", 1.7),
        ("RBX1", 12.0),
        ("RBX2", 10.0),
        ("RCX1", 1.0),
        ("RBY1", 10.0),
        ("RBY2", 8.0),
        ("RCY1", 1.0),
        ("QBZ1", 10.0),
        ("QCZ1", 1.2),
        ("QDZ1", 0.1),
        ("QEZ1", -1.0),
        ("QBZ10", 0.5),
    ] {
        assert!(c.set(k, v));
    }
    MagicFormula {
        version: MfVersion::Mf61,
        side: TyreSide::Left,
        options: MfOptions::default(),
        limits: Default::default(),
        coefficients: c,
    }
}

fn at(fz: f64, kappa: f64, alpha: f64, camber: f64) -> MfInput {
    MfInput {
        fz,
        kappa,
        alpha,
        camber,
        speed: 20.0,
        pressure: None,
    }
}

proptest! {
    #[test]
    fn symmetric_tyre_is_odd_in_slip_angle(fz in 500.0..9000.0, a in -1.2..1.2f64, k in -0.5..0.5f64) {
        let t = symmetric();
        let (p, m) = (t.evaluate(&at(fz, k, a, 0.0)), t.evaluate(&at(fz, k, -a, 0.0)));
        prop_assert!((p.fy + m.fy).abs() <= 1e-9 * p.fy.abs().max(1.0));
        prop_assert!((p.mz + m.mz).abs() <= 1e-9 * p.mz.abs().max(1.0));
        prop_assert!((p.fx - m.fx).abs() <= 1e-9 * p.fx.abs().max(1.0));
    }

    #[test]
    fn combined_force_is_below_pure(fz in 500.0..9000.0, a in -0.6..0.6f64, k in -0.5..0.5f64) {
        let t = symmetric();
        let c = t.evaluate(&at(fz, k, a, 0.0));
        let px = t.evaluate(&at(fz, k, 0.0, 0.0)).fx;
        let py = t.evaluate(&at(fz, 0.0, a, 0.0)).fy;
        prop_assert!(c.fx.abs() <= px.abs() + 1e-9);
        prop_assert!(c.fy.abs() <= py.abs() + 1e-9);
    }

    #[test]
    fn no_nan_in_the_documented_ranges(
        fz in 0.0..20000.0, a in -1.5..1.5f64, k in -1.0..1.0f64,
        g in -0.2..0.2f64, v in -40.0..60.0f64, p in 100_000.0..400_000.0,
    ) {
        let t = symmetric();
        let o = t.evaluate(&MfInput { fz, kappa: k, alpha: a, camber: g, speed: v, pressure: Some(p) });
        for x in [o.fx, o.fy, o.mz, o.mx, o.my] {
            prop_assert!(x.is_finite(), "{o:?}");
        }
    }

    #[test]
    fn continuous_at_zero_slip(fz in 500.0..9000.0, s in -0.3..0.3f64) {
        let t = symmetric();
        let h = 1e-9;
        for (k, a) in [(0.0, s), (s, 0.0)] {
            let o = t.evaluate(&at(fz, k, a, 0.0));
            let (kp, ap) = if a == 0.0 { (k, h) } else { (h, a) };
            let (km, am) = if a == 0.0 { (k, -h) } else { (-h, a) };
            let (up, dn) = (t.evaluate(&at(fz, kp, ap, 0.0)), t.evaluate(&at(fz, km, am, 0.0)));
            for (x, y, z) in [(o.fx, up.fx, dn.fx), (o.fy, up.fy, dn.fy), (o.mz, up.mz, dn.mz)] {
                prop_assert!((y - x).abs() < 1e-3 && (z - x).abs() < 1e-3, "{x} {y} {z}");
            }
        }
    }
}

#[test]
fn positive_slip_angle_gives_positive_force_and_restoring_moment() {
    let o = symmetric().evaluate(&at(4000.0, 0.0, 0.02, 0.0));
    assert!(o.fy > 0.0 && o.mz > 0.0, "{o:?}");
}

/// One prepared load serves many slip points with exactly the forces of
/// separate evaluations — including the paths where the prelude is not
/// enough on its own: slip-speed friction (`LMUV`, rebuilt per point), the
/// low-speed fade of the shifts (below `VXLOW`), a right-side file, camber.
#[test]
fn a_prepared_load_gives_the_forces_of_separate_evaluations() {
    let mut t = symmetric();
    for (k, v) in [
        ("PVY3", 0.05),
        ("PKY6", -0.8),
        ("RVY1", 0.02),
        ("RVY5", 1.9),
        ("RVY6", 10.0),
    ] {
        assert!(t.coefficients.set(k, v));
    }
    for (lmuv, side) in [(0.0, TyreSide::Left), (0.3, TyreSide::Right)] {
        t.coefficients.LMUV = lmuv;
        t.side = side;
        let prepared = t.at_load(4500.0, Some(200_000.0), 0.04);
        for (k, a, v) in [
            (0.0, 0.1, 20.0),
            (0.1, -0.05, 20.0),
            (-0.2, 0.3, 0.4),
            (0.05, 0.0, -3.0),
        ] {
            let one = t.evaluate(&MfInput {
                fz: 4500.0,
                kappa: k,
                alpha: a,
                camber: 0.04,
                speed: v,
                pressure: Some(200_000.0),
            });
            assert_eq!(
                prepared.forces(k, a, v),
                one,
                "κ {k} α {a} V {v} LMUV {lmuv}"
            );
        }
    }
    assert_eq!(
        t.at_load(0.0, None, 0.0).forces(0.1, 0.1, 20.0),
        MfOutput::default()
    );
}

/// The array kernels agree with the C library to within a few ulp over the
/// arguments the model gives them and beyond (the reduction's range, huge
/// and non-finite arguments).
#[test]
fn kernels_agree_with_the_c_library() {
    let mut worst: f64 = 0.0;
    let mut check = |got: f64, want: f64| {
        if want.is_nan() {
            assert!(got.is_nan());
        } else {
            let e = (got - want).abs() / want.abs().max(f64::MIN_POSITIVE);
            worst = worst.max(e.min((got - want).abs() / f64::EPSILON));
        }
    };
    let mut xs: Vec<f64> = Vec::new();
    for i in -20_000..=20_000 {
        let u = i as f64 / 20_000.0;
        xs.extend([
            u * 1e-6,
            u,
            u * 3.0,
            u * 40.0,
            u * 1e4,
            u * 2e5,
            u.powi(3) * 1e12,
        ]);
    }
    xs.extend([0.0, -0.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN, 1e300]);
    for x in &xs {
        let a = kernels::atan([*x, -*x, 0.0, 1.0]);
        check(a[0], x.atan());
        check(a[1], (-x).atan());
        let r = kernels::atan_ratio([*x, 1.0, 0.0, 0.0], [2.0, 3.0, 1.0, 1.0]);
        check(r[0], (x / 2.0).atan());
        let s = kernels::sin_cos([*x, *x, 0.0, 0.0], [false, true, false, false]);
        check(s[0], x.sin());
        check(s[1], x.cos());
    }
    assert_eq!(kernels::atan([-0.0])[0].to_bits(), (-0.0f64).to_bits());
    // Relative error, or absolute in units of ε where the value is near 0.
    assert!(worst < 4.0 * f64::EPSILON, "worst {worst:e}");
}

/// TNO eq. A48 for 6.x files: `My ∝ Fz0·(Fz/Fz0)^QSY7·(p/p0)^QSY8`, so with
/// `QSY7 = 0` the rolling resistance does not depend on the load and keeps
/// its pressure power; a 5.2 file's `My` is proportional to the load.
#[test]
fn rolling_resistance_follows_the_version_not_qsy7() {
    let mut t = symmetric();
    for (k, v) in [("QSY1", 0.01), ("QSY7", 0.0), ("QSY8", -0.4)] {
        assert!(t.coefficients.set(k, v));
    }
    let my = |t: &MagicFormula, fz: f64, p: f64| {
        t.evaluate(&MfInput {
            pressure: Some(p),
            ..at(fz, 0.0, 0.0, 0.0)
        })
        .my
    };
    let p0 = t.coefficients.NOMPRES;
    let (low, high) = (my(&t, 2000.0, p0), my(&t, 6000.0, p0));
    // −R0·Fz0·λMy·QSY1 at every load.
    let want = -0.31 * 4000.0 * 0.01;
    assert!((low - want).abs() < 1e-12 && (high - want).abs() < 1e-12);
    let p = 1.2 * p0;
    assert!((my(&t, 2000.0, p) - want * 1.2f64.powf(-0.4)).abs() < 1e-12);
    t.version = MfVersion::Mf52;
    let (low, high) = (my(&t, 2000.0, p), my(&t, 6000.0, p));
    assert!((low + 0.31 * 2000.0 * 0.01).abs() < 1e-12, "{low}");
    assert!((high / low - 3.0).abs() < 1e-12, "{high} {low}");
}
