//! Session 98, the step steer's speed: under Dormand–Prince the
//! load-transfer solve of each stage starts from that stage's own last three
//! solutions, so a PAC89 step steer solves its loads about once per
//! right-hand side, as `simulate` counts them ("tyre-set evaluations").

use crate::{bundled_scenario, run, scratch, stderr};

/// The evaluations and tyre-set evaluations `simulate` reports.
fn work(stdout: &str) -> (f64, f64) {
    let line = stdout
        .lines()
        .find(|l| l.contains("tyre-set evaluations"))
        .unwrap_or_else(|| panic!("no work line in {stdout}"));
    let number_before = |word: &str| -> f64 {
        let head = &line[..line.find(word).unwrap_or_else(|| panic!("{word}: {line}"))];
        let n = head.trim_end().rsplit([' ', '(']).next().unwrap();
        n.parse().unwrap_or_else(|_| panic!("{n:?} in {line}"))
    };
    (
        number_before(" evaluations,"),
        number_before(" tyre-set evaluations"),
    )
}

/// The bundled PAC89 step steer (four wheels, lateral load transfer) at
/// SciPy's tight setting (rtol 1e-10, atol 1e-13) and at the default: at
/// most 1.05 tyre-set evaluations per right-hand side (before: 1.15 at the
/// default, 1.18 at rtol 1e-10, where a stage's seed was extrapolated from
/// the stages before it and one in six solves took a second pass).
#[test]
fn a_pac89_step_steer_solves_its_loads_about_once_a_right_hand_side() {
    let text = bundled_scenario("step_gbt6323_pac89.toml");
    assert!(text.contains("[simulation]\n"), "{text}");
    for (name, extra) in [("default", ""), ("tight", "rtol = 1e-10\natol = 1e-13\n")] {
        let scenario = text.replace("[simulation]\n", &format!("[simulation]\n{extra}"));
        let dir = scratch(&[("s.toml", &scenario)]);
        let out = dir.path().join("out");
        let o = run(&[
            "simulate",
            dir.path().join("s.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let stdout = String::from_utf8_lossy(&o.stdout);
        let (evaluations, tyre_sets) = work(&stdout);
        assert!(evaluations > 500.0, "{name}: {stdout}");
        let per = tyre_sets / evaluations;
        assert!(
            (1.0..=1.05).contains(&per),
            "{name}: {per:.3} tyre-set evaluations per right-hand side: {stdout}"
        );
    }
}
