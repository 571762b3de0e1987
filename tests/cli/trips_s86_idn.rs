//! What a fresh user tripped on in `identify` on rig data: the ranges a
//! fitted file states, the names of load levels across outputs, a glitch
//! masked in a piece dropped whole, the Magic Formula fit's pooled σ over
//! rows no stage of a channel fits, and a steady lateral acceleration
//! beyond the car's rollover threshold.

use super::*;

/// The Hoosier file fitted by `magic-simple` at its 1656 N level, 0° and
/// 83.4 kPa, written to `out` in `dir`; the terminal's text.
fn hoosier_at_1656(rig: &Path, out: &Path) -> String {
    succeeds(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "magic-simple",
        "--load",
        "1656",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ])
}

/// `[fitted_ranges]` of a fit at one level, camber and pressure said fz
/// 1601–1681 N, the span of its points' means over slip bins, where the
/// samples fitted run from 1503 to 1795 N: `tyre-eval` at 1750 N called
/// that load an extrapolation.
#[test]
fn the_fitted_ranges_span_every_sample_fitted() {
    let test = "the_fitted_ranges_span_every_sample_fitted";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n1750,0,0.05,0,10\n")]);
    let out = dir.path().join("ms.toml");
    hoosier_at_1656(&rig, &out);
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains("\nfz = [1503.0, 1795.0]\n"), "{text}");
    assert!(text.contains("fz 1503 to 1795 N"), "{text}");
    let o = run_in(dir.path(), &["tyre-eval", "ms.toml", "p.csv", "--out", "e.csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("extrapolation"), "{}", stderr(&o));
}
