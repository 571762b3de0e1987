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
