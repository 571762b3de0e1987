//! The step steer's speed-ups (session 106): the right-hand side's
//! kinematics (`tan β`, the two slip angles' `atan`, the steer's `cos`)
//! from the crate's SIMD kernels instead of four calls of the C library.
//! What a user sees must not move: the bundled PAC89 step's GB/T 6323
//! metrics at the default rtol 1e-9 are main's to 1e-9 relative, in no
//! more work than main's.

use super::scenarios::simulate_to;
use super::{read_json, root};

/// `metrics.json` of `scenarios/step_gbt6323_pac89.toml` as main
/// (`717eb64d`, before the kernels) wrote it.
const MAINS: [(&str, f64); 9] = [
    ("steer_step", 0.011816354035736259),
    ("yaw_rate_response_time", 0.1672281867873473),
    ("ay_response_time", 0.28302473148855056),
    ("yaw_rate_gain", 7.6165701982102325),
    ("yaw_rate_steady", 0.09000009000009),
    ("beta_steady", -0.001253290478325426),
    ("yaw_rate_total_variance", 0.023706726658856064),
    ("ay_total_variance", 0.020509400815831354),
    ("er", 0.04421612747468742),
];

#[test]
fn the_pac89_step_scenarios_metrics_stay_mains_to_a_billionth_in_no_more_work() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let said = simulate_to(&root().join("scenarios/step_gbt6323_pac89.toml"), &out);
    let m = read_json(&out.join("metrics.json"));
    for (key, want) in MAINS {
        let got = m[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key}: {}", m[key]));
        let e = (got - want).abs() / want.abs();
        assert!(
            e <= 1e-9,
            "{key}: {got} vs main's {want} ({e:.1e} relative)"
        );
    }
    assert!(m["ay_steady"]
        .as_f64()
        .is_some_and(|a| (a - 2.0).abs() < 1e-12));
    // Main's work: 212 steps (3 rejected), 1294 evaluations, 1314 tyre-set
    // evaluations; a change within rounding may move a step, not more.
    let at = |word: &str| {
        let head = said.lines().next().unwrap();
        let before = &head[..head.find(word).unwrap_or_else(|| panic!("{word}: {head}"))];
        before
            .split_whitespace()
            .last()
            .unwrap()
            .trim_start_matches('(')
            .parse::<usize>()
            .unwrap()
    };
    let (steps, evaluations) = (at(" steps"), at(" evaluations,"));
    assert!(steps <= 213 && evaluations <= 1300, "{said}");
}
