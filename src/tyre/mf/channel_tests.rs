//! The generic channel evaluation ([`MagicFormula::channel_of`] in plain
//! numbers) against the fast path ([`MagicFormula::evaluate`], itself
//! checked against MFeval) on the points of every MFeval fixture grid, in
//! each of MFeval's four modes, for the file's own side and the mirrored
//! one, with and without slip-speed friction and the digressive `λ'μ`.

use super::*;
use crate::io::tir::load_tir;
use std::path::Path;

/// (tyre file, reference grid) pairs of the fixtures.
const FILES: [(&str, &str); 7] = [
    ("MagicFormula52_Parameters", "mf52"),
    ("MagicFormula61_Parameters", "mf61"),
    ("MagicFormula61_QSY7_zero", "mf61_qsy7_zero"),
    ("MagicFormula62_Parameters", "mf62"),
    ("chrono_HMMWV_Pac02Tire", "chrono_hmmwv"),
    ("chrono_mf_185_80R14", "chrono_microbus"),
    ("chrono_Sedan_Pac02Tire", "chrono_sedan"),
];

fn dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/tir")
}

/// The operating points of a grid (ISO-W angles as the crate's: the
/// points only need to cover the grid, not to match its outputs).
fn points(grid: &str) -> Vec<MfInput> {
    let mut out = Vec::new();
    for prefix in ["reference_mfeval_", "reference_mfeval_modes_"] {
        let text = std::fs::read_to_string(dir().join(format!("{prefix}{grid}.csv"))).unwrap();
        for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
            let r: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            out.push(MfInput {
                fz: r[0],
                kappa: r[1],
                alpha: r[2],
                camber: r[3],
                speed: r[4],
                pressure: Some(r[5]),
            });
        }
    }
    out
}

const CHANNELS: [MfChannel; 5] = [
    MfChannel::Fx,
    MfChannel::Fy,
    MfChannel::Mz,
    MfChannel::Mx,
    MfChannel::My,
];

fn pick(o: &MfOutput, ch: MfChannel) -> f64 {
    match ch {
        MfChannel::Fx => o.fx,
        MfChannel::Fy => o.fy,
        MfChannel::Mz => o.mz,
        MfChannel::Mx => o.mx,
        MfChannel::My => o.my,
    }
}

/// The largest difference between the two paths over `pts`, relative to
/// the larger magnitude of the two, with a floor of 1e-4 of the channel's
/// largest magnitude over the grid: where a channel crosses zero (`Fy` at
/// zero slip, `Mz` past its peak, where `t·Fy'`, `Mzr` and `s·Fx` of the
/// channel's size cancel to 2e-5 of it on MF 5.2's grid with slip-speed
/// friction) a relative difference measures the rounding of the terms
/// (≈ 1e-16 of the channel's size), not a difference of formula. Below the
/// floor the check is absolute, 1e-16 of the channel's size.
fn worst(t: &MagicFormula, pts: &[MfInput]) -> f64 {
    let c = t.coefficients.lift::<f64>();
    let fast: Vec<MfOutput> = pts.iter().map(|p| t.evaluate(p)).collect();
    let mut worst: f64 = 0.0;
    for ch in CHANNELS {
        let scale = fast.iter().map(|o| pick(o, ch).abs()).fold(0.0, f64::max);
        for (p, o) in pts.iter().zip(&fast) {
            let (a, b) = (pick(o, ch), t.channel_of(&c, p, ch));
            let d = (a - b).abs() / a.abs().max(b.abs()).max(1e-4 * scale).max(1e-300);
            assert!(d.is_finite() || a == b, "{ch:?} at {p:?}: {a} vs {b}");
            worst = worst.max(if a == b { 0.0 } else { d });
        }
    }
    worst
}

#[test]
fn the_generic_channels_equal_the_fast_path_on_every_fixture_grid() {
    let modes = [111, 121, 211, 221].map(|m| MfMode::from_use_mode(m).unwrap());
    let mut compared = 0;
    for (file, grid) in FILES {
        let base = load_tir(&dir().join(format!("{file}.tir"))).unwrap();
        let pts = points(grid);
        for mode in modes {
            for side in [TyreSide::Left, TyreSide::Right] {
                let mut t = base.clone();
                t.set_mode(mode);
                t.side = side;
                let w = worst(&t, &pts);
                assert!(
                    w <= 1e-12,
                    "{file} mode {} {side:?}: {w:.2e}",
                    mode.use_mode()
                );
                compared += pts.len();
            }
        }
        // Slip-speed friction and the digressive λ'μ (both off in the
        // files): the prelude rebuilt per point, the vertical shifts scaled.
        let mut t = base.clone();
        t.coefficients.LMUV = 0.4;
        t.options.digressive_mu = true;
        let w = worst(&t, &pts);
        assert!(w <= 1e-12, "{file} with LMUV and digressive μ: {w:.2e}");
    }
    assert!(compared > 60_000, "{compared}");
}

/// A low speed (the vertical shifts fade below `VXLOW`), a backward
/// spinning wheel (`My` turns) and zero or negative loads.
#[test]
fn the_generic_channels_equal_the_fast_path_at_low_speed_and_no_load() {
    let t = load_tir(&dir().join("MagicFormula61_Parameters.tir")).unwrap();
    let mut pts = Vec::new();
    for speed in [0.0, 0.3, -2.0, 0.9] {
        for kappa in [-1.2, -0.05, 0.0, 0.1] {
            for fz in [-100.0, 0.0, 200.0, 4000.0] {
                pts.push(MfInput {
                    fz,
                    kappa,
                    alpha: 0.07,
                    camber: 0.02,
                    speed,
                    pressure: None,
                });
            }
        }
    }
    let w = worst(&t, &pts);
    assert!(w <= 1e-12, "{w:.2e}");
}

/// Fy (N) of `t`'s fast path at slip angle `alpha` (rad), load `fz` (N)
/// and friction scale `mu`, no slip ratio or camber: what the
/// parameterised force is checked against.
fn pure_fy(t: &MagicFormula, alpha: f64, fz: f64, mu: f64) -> f64 {
    use crate::tyre::{SlipState, TyreModel};
    t.forces(&SlipState {
        alpha,
        kappa: 0.0,
        fz,
        camber: 0.0,
        mu_scale: mu,
        speed: 16.7,
    })
    .fy
}

/// ∂Fy/∂x_k by fourth-order central differences of step `h` at `x0` (the 9
/// lateral parameters, then α, Fz, μ): the derivatives' reference.
fn fy_difference(t: &MagicFormula, x0: &[f64], k: usize, h: f64) -> f64 {
    use crate::tyre::Parameterised;
    let at = |d: f64| {
        let mut x = x0.to_vec();
        x[k] += d;
        let mut u = t.clone();
        u.set_parameters(&x[..9]);
        pure_fy(&u, x[9], x[10], x[11])
    };
    (-at(2.0 * h) + 8.0 * at(h) - 8.0 * at(-h) + at(-2.0 * h)) / (12.0 * h)
}

/// Whether `t` is clamped (a load or slip-angle limit) at one end of ±2h
/// along x_k of `x0` and not at the other: differences across the kink
/// are not its derivative.
fn straddles_a_limit(t: &MagicFormula, x0: &[f64], k: usize, h: f64) -> bool {
    let clamped = |d: f64| {
        t.is_clamped(&MfInput {
            fz: x0[10] + d * f64::from(k == 10),
            kappa: 0.0,
            alpha: x0[9] + d * f64::from(k == 9),
            camber: 0.0,
            speed: 16.7,
            pressure: None,
        })
    };
    clamped(2.0 * h) != clamped(-(2.0 * h))
}

/// The pure lateral force of [`LateralForceOf`] in plain numbers equals
/// the fast path's `fy` at zero camber and slip ratio on every fixture
/// file, in each mode and on both sides, with a road friction and
/// slip-speed friction; in dual numbers its derivatives with respect to the
/// nine lateral parameters, the slip angle, the load and the friction
/// scale equal fourth-order central differences of the fast path to 1e-6
/// (floor as in the Jacobian test of the staged fit: 1e-15·S/h).
#[test]
fn the_lateral_force_of_equals_the_fast_path_with_its_derivatives() {
    use crate::tyre::{LateralForceOf, Parameterised, SlipOf};
    use num_dual::DualSVec64;
    let modes = [111, 121, 211, 221].map(|m| MfMode::from_use_mode(m).unwrap());
    let mut derivatives = 0;
    for (file, _) in FILES {
        let base = load_tir(&dir().join(format!("{file}.tir"))).unwrap();
        for (mode, side) in modes
            .iter()
            .zip([TyreSide::Left, TyreSide::Right].iter().cycle())
        {
            let mut t = base.clone();
            t.set_mode(*mode);
            t.side = *side;
            t.coefficients.LMUV = 0.2;
            let p = t.parameters();
            let scale = t.coefficients.FNOMIN;
            // Not at α = 0: where α* + SHy changes sign, `Ey`'s asymmetry
            // term `PEY3·sgn` switches, which the differences straddle.
            for alpha in [-0.3, -0.04, 0.02, 0.12, 0.5] {
                for fz in [0.3, 1.0, 1.7].map(|f| f * scale) {
                    let s = SlipOf {
                        alpha,
                        fz,
                        mu_scale: 0.9,
                        speed: 16.7,
                    };
                    let (a, b) = (t.lateral_force_of(&p, &s), pure_fy(&t, alpha, fz, 0.9));
                    assert!(
                        (a - b).abs() <= 1e-12 * a.abs().max(1e-4 * scale),
                        "{file} {:?} at {alpha}, {fz}: {a} vs {b}",
                        mode.use_mode()
                    );
                    // Dual: 9 parameters, then α, Fz, μ.
                    let v = |x: f64, k: usize| DualSVec64::<12>::from_re(x).derivative(k);
                    let pd: Vec<DualSVec64<12>> =
                        p.iter().enumerate().map(|(k, x)| v(*x, k)).collect();
                    let sd = SlipOf {
                        alpha: v(alpha, 9),
                        fz: v(fz, 10),
                        mu_scale: v(0.9, 11),
                        speed: 16.7,
                    };
                    let g = t.lateral_force_of(&pd, &sd);
                    let eps = g.eps.unwrap_generic(nalgebra::Const::<12>, nalgebra::U1);
                    for k in 0..12 {
                        let x0 = [p.clone(), vec![alpha, fz, 0.9]].concat();
                        let h = 1e-3 * x0[k].abs().max(if k == 9 { 1e-2 } else { 0.1 });
                        let d = fy_difference(&t, &x0, k, h);
                        let floor = 1e-9 * scale / h;
                        // A limit (load, slip angle) within ±2h: the
                        // differences straddle the kink.
                        if straddles_a_limit(&t, &x0, k, h) {
                            continue;
                        }
                        assert!(
                            (eps[k] - d).abs() <= 1e-6 * eps[k].abs().max(floor),
                            "{file} {:?} ∂/∂x{k} at α {alpha}, Fz {fz}: {} vs {d}",
                            mode.use_mode(),
                            eps[k]
                        );
                        derivatives += 1;
                    }
                }
            }
        }
    }
    assert!(derivatives > 1500, "{derivatives}");
}
