//! What a fresh user tripped on in `identify` with the swarm models: a
//! condition's load said as its level's name on the terminal and as its
//! own in the report, a file's pure longitudinal `fx` dropped without a
//! word by a model without a longitudinal force, `--local` overridden
//! unsaid, and two samples at one load said to lie "between levels".

use super::*;

/// The Hoosier file fitted by `model` at 83.4 kPa and 0° (and `more`),
/// written to `dir/name`: the terminal's text and the tyre file's.
fn hoosier(test: &str, model: &str, more: &[&str], name: &str) -> Option<(String, String)> {
    let rig = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    let dir = scratch(&[]);
    let out = dir.path().join(name);
    let mut args = vec![
        "identify",
        rig.to_str().unwrap(),
        "--model",
        model,
        "--pressure",
        "83400",
        "--camber",
        "0",
    ];
    args.extend(more);
    args.extend(["--out", out.to_str().unwrap()]);
    let said = succeeds(&args);
    let report = out.with_extension("report.json");
    let json = read_json(&report);
    let text = fs::read_to_string(&out).unwrap();
    Some((said, format!("{text}\n{json}")))
}

/// `--load 1650`: the terminal named the condition `Fz 1656 N` (its
/// level's name) and the report and the tyre file gave 1639.7 N (the
/// median of its samples fitted), with nothing joining the two.
#[test]
fn a_conditions_own_load_is_said_beside_its_levels_name() {
    let test = "a_conditions_own_load_is_said_beside_its_levels_name";
    let Some((said, written)) = hoosier(test, "gim", &["--load", "1650"], "g.toml") else {
        return;
    };
    let line = "a condition's load, camber and pressure are the medians of its samples fitted (the report's `curves`, the figure's fitted lines and the tyre's reference load where its model has one), inside the level the lines above name by every sample of it in the file: 1640 N in the 1656 N level";
    assert!(said.contains(&format!("  {line}\n")), "{said}");
    assert!(said.contains("    Fz    1656 N, camber  0.00°"), "{said}");
    assert!(written.contains(&format!("# {line}\n")), "{written}");
    assert!(written.contains("\nreference_load = 1639.7\n"), "{written}");
    assert!(written.contains("\"fz\":1639.7"), "{written}");
}

/// `--local none` and `--local gn` wrote the same lateral force as `lm`
/// (σ 2.525 %), PAC89's two-stage result, whose joint polish is
/// Levenberg–Marquardt by its method: nothing said that `--local` did
/// not reach it.
#[test]
fn local_none_says_the_two_stage_result_has_its_own_polish() {
    let test = "local_none_says_the_two_stage_result_has_its_own_polish";
    let Some((said, written)) = hoosier(test, "pac89", &["--local", "none"], "p.toml") else {
        return;
    };
    let note = "--local none: the lateral force written is PAC89's two-stage result, which ends in the Levenberg–Marquardt joint polish of its method (Zhang et al. 2021) whatever --local says; --local none applied to the direct fit (σ ";
    assert!(said.contains(&format!("  {note}")), "{said}");
    assert!(
        said.contains("as --local none has no polish to refit with"),
        "{said}"
    );
    assert!(written.contains(&format!("# {note}")), "{written}");
    // The aligning moment, a swarm fit, is the swarm's best as it is.
    let aligning = said
        .lines()
        .find(|l| l.starts_with("  aligning moment: σ"))
        .unwrap();
    let after = |key: &str| {
        aligning
            .split(key)
            .nth(1)
            .unwrap()
            .split(" %")
            .next()
            .unwrap()
    };
    assert_eq!(after("σ "), after("PSO alone "), "{aligning}");
}

/// A rig file of a lateral sweep at kappa 0 and a longitudinal one at
/// alpha 0 (Magic Formula shapes, 4000 N): `n` rows of the latter.
fn lateral_and_longitudinal() -> (String, usize) {
    let mf = |x: f64, b: f64| 4400.0 * (1.5 * (b * x).atan()).sin();
    let mut csv = String::from("fz,kappa,alpha,fx,fy\n");
    for i in (-40..=40).filter(|i| *i != 0) {
        let a = (0.25 * f64::from(i)).to_radians();
        csv += &format!("4000,0,{a:.6},0,{:.2}\n", mf(a, 12.0));
    }
    let mut n = 0;
    for i in -40..=40 {
        let k = 0.005 * f64::from(i);
        csv += &format!("4000,{k:.4},0,{:.2},0\n", mf(k, 15.0));
        n += 1;
    }
    (csv, n)
}

/// Gim, the simple Magic Formula and the linear tyre have no longitudinal
/// force: a file's pure longitudinal sweeps were dropped without a word
/// (`mx`, `my` and `mz` not fitted were each said), and the written tyre
/// gave no `fx` at any slip ratio.
#[test]
fn a_pure_longitudinal_sweeps_fx_not_fitted_is_said() {
    let (csv, n) = lateral_and_longitudinal();
    for model in ["gim", "magic-simple", "linear"] {
        let dir = scratch(&[("rig.csv", &csv)]);
        let said = succeeds(&[
            "identify",
            dir.path().join("rig.csv").to_str().unwrap(),
            "--model",
            model,
            "--out",
            dir.path().join("t.toml").to_str().unwrap(),
        ]);
        let note = format!(
            "the {model} model has no longitudinal force (pac89 and unitire fit `fx`, as do mf61 and mf62): {n} values of `fx` in the pure longitudinal rows not fitted"
        );
        assert!(said.contains(&format!("  {note}\n")), "{model}: {said}");
        let text = fs::read_to_string(dir.path().join("t.toml")).unwrap();
        assert!(text.contains(&format!("# {note}\n")), "{model}: {text}");
    }
}

/// Two rows at one load: `no test condition found (2 samples: 0 used in
/// conditions, 2 between levels (transitions) …)`, where there is no
/// level for them to lie between; and `1 points` left out of a linear
/// tyre's window.
#[test]
fn samples_too_few_for_a_level_are_said_so() {
    let dir = scratch(&[("two.csv", "fz,alpha,fy\n4000,0.01,1000\n4000,0.02,1900\n")]);
    let o = run(&[
        "identify",
        dir.path().join("two.csv").to_str().unwrap(),
        "--model",
        "gim",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("no test condition found in the data (2 samples: 0 used in conditions, 2 samples in groups too few to be a level (fewer than 3 samples at one load, camber or pressure), 0 between levels (transitions), 0 at levels not selected"), "{e}");
    let six = "fz,alpha,fy\n4000,0.01,1000\n4000,0.02,1900\n4000,0.03,2600\n4000,0.04,3100\n4000,-0.01,-1000\n4000,-0.02,-1900\n";
    let dir = scratch(&[("six.csv", six)]);
    let said = succeeds(&[
        "identify",
        dir.path().join("six.csv").to_str().unwrap(),
        "--model",
        "linear",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(
        said.contains("(5 points; 1 point with larger |alpha| left out"),
        "{said}"
    );
}
