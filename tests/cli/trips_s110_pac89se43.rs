//! Round 43: `identify --model pac89 --hold
//! a7=abc` is refused with an example of the chosen model's own
//! parameters, not a Magic Formula name (it said "e.g. PKY4=2", a name a
//! pac89 fit refuses). The `--hold` argument is read with the model
//! known (`jobs/identify/holds.rs`, `parse_hold`).

use super::*;

/// A `--hold` that is not NAME=VALUE is refused with an example of the
/// model chosen: a pac89 name for pac89, a `.tir` coefficient for mf61.
#[test]
fn a_malformed_hold_is_refused_with_an_example_of_the_models_own() {
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n1000,0.01,100\n")]);
    let rig = dir.path().join("rig.csv");
    let refused = |model: &str| {
        let o = run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            model,
            "--hold",
            "a7=abc",
        ]);
        assert!(!o.status.success());
        stderr(&o)
    };
    let pac89 = refused("pac89");
    assert!(
        pac89.contains("--hold `a7=abc`: expected NAME=VALUE with a number, e.g. a0=1.65"),
        "{pac89}"
    );
    assert!(!pac89.contains("PKY4"), "{pac89}");
    let mf = refused("mf61");
    assert!(mf.contains("e.g. PKY4=2"), "{mf}");
}
