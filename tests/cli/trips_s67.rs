//! What a fresh-eyes user still tripped on: a points file with several bad
//! cells refused one cell at a time (fix one, run again, learn of the
//! next), and its pressures at or below zero likewise.

use super::*;

/// A tyre file for `tyre-eval`: the public MF 6.1 sample of the fixtures.
fn sample_tir() -> PathBuf {
    root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
}

#[test]
fn tyre_eval_names_every_cell_that_is_not_a_finite_number_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n\
                  4000,0,0.1,0,16\n\
                  abc,0,0.1,0,16\n\
                  4000,0,nan,0,16\n\
                  4000,inf,0.1,0,16\n\
                  4000,0,0.1,0,16\n";
    let (o, written) = super::tyre_eval::eval(dir.path(), &sample_tir(), points, &[]);
    assert!(!o.status.success() && written.is_empty(), "{written}");
    let err = stderr(&o);
    for cell in [
        "p.csv:3:1: column `fz`: `abc` is not a number",
        "p.csv:4:3: column `alpha`: nan is not a finite value",
        "p.csv:5:2: column `kappa`: inf is not a finite value",
    ] {
        assert!(err.contains(cell), "no {cell:?} in: {err}");
    }
    assert!(err.contains("3 places refused, in file order"), "{err}");
}

#[test]
fn tyre_eval_names_every_pressure_at_or_below_zero_and_bad_cell_with_the_other_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed,pressure\n\
                  4000,0,0.1,0,16,220000\n\
                  4000,0,0.1,0,16,0\n\
                  4000,0,0.1,0,-3,220000\n\
                  4000,0,0.1,0,16,-1\n\
                  abc,0,0.1,0,16,220000\n";
    let (o, written) = super::tyre_eval::eval(dir.path(), &sample_tir(), points, &[]);
    assert!(!o.status.success() && written.is_empty(), "{written}");
    let err = stderr(&o);
    let at = |cell: &str| {
        err.find(cell)
            .unwrap_or_else(|| panic!("no {cell:?} in: {err}"))
    };
    // In file order: the zero pressure, the negative speed, the negative
    // pressure.
    let order = [
        at("p.csv:3:6: column `pressure`: 0 Pa is not a positive pressure"),
        at("p.csv:4:5: column `speed`"),
        at("p.csv:5:6: column `pressure`: -1 Pa is not a positive pressure"),
        at("p.csv:6:1: column `fz`: `abc` is not a number"),
    ];
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{err}");
}

/// A lateral rig sweep at 2, 4 and 6 kN (a Magic Formula curve, friction
/// 1), with `change(row, line)` applied to each row's text.
fn rig(change: &dyn Fn(usize, String) -> String) -> String {
    let mut s = String::from("fz,alpha,fy\n");
    let mut row = 0;
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in 0..41 {
            let alpha = -0.2 + 0.01 * k as f64;
            let fy = fz * (1.3 * (10.0 * alpha).atan()).sin();
            s += &change(row, format!("{fz},{alpha},{fy}"));
            s += "\n";
            row += 1;
        }
    }
    s
}

/// `identify <rig> --model pac89` on `text` written as `rig.csv`, which
/// must be refused without writing: the refusal, and the folder.
fn identify_refuses(text: &str) -> (String, tempfile::TempDir) {
    let dir = scratch(&[("rig.csv", text)]);
    let out = dir.path().join("t.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "pac89", &out);
    (refused(&o, &out), dir)
}

#[test]
fn identify_refuses_a_rig_sample_whose_force_no_tyre_grips_at_by_its_line() {
    // One sample of 123 with a lateral force 200 times its load: the fit
    // took it (σ 79 %, coefficients on their bounds) and never named it.
    let spiked = rig(&|row, line| match row {
        60 => "2500,0.05,500000".into(),
        70 => "6000,0.05,40000".into(),
        _ => line,
    });
    let err = identify_refuses(&spiked).0;
    // Row 60 is line 62 (the header is line 1); `fy` is column 3.
    for said in [
        "rig.csv:62:3: column `fy`: 500000 N at fz 2500 N is 200 times the load",
        "rig.csv:72:3: column `fy`: 40000 N at fz 6000 N is 6.66667 times the load",
    ] {
        assert!(err.contains(said), "no {said:?} in: {err}");
    }
}

#[test]
fn identify_names_every_rig_sample_no_tyre_test_holds_at_once() {
    let bad = rig(&|row, line| match row {
        10 => "-4000,0.0,0.0".into(),
        20 => "4000,xx,0.0".into(),
        30 => "4000,12,3000".into(),
        50 => "4000,0.05,1e300".into(),
        _ => line,
    });
    let err = identify_refuses(&bad).0;
    assert!(err.contains("4 places refused, in file order"), "{err}");
    let at = |cell: &str| {
        err.find(cell)
            .unwrap_or_else(|| panic!("no {cell:?} in: {err}"))
    };
    let order = [
        at("rig.csv:12:1: column `fz`: -4000 N is negative"),
        at("rig.csv:22:2: column `alpha`: `xx` is not a number"),
        at("rig.csv:32:2: column `alpha`: 12 rad is beyond ±90°"),
        at("rig.csv:52:3: column `fy`: 1e300 N is beyond ±1000000 N"),
    ];
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{err}");
    // Each cell said once.
    assert_eq!(err.matches("rig.csv:52:3").count(), 1, "{err}");
}

#[test]
fn identify_and_tyre_eval_refuse_a_misspelled_column_they_would_have_ignored() {
    // `presure` was dropped without a word: the three pressures of the
    // Hoosier file pooled, its stage σ as good as the right run's.
    let text = rig(&|_, line| format!("{line},83000,0.0")).replacen(
        "fz,alpha,fy",
        "fz,alpha,fy,presure,Camber",
        1,
    );
    let (err, dir) = identify_refuses(&text);
    for said in [
        "rig.csv:1:4: column `presure` is not one this command reads: did you mean `pressure`?",
        "rig.csv:1:5: column `Camber` is not one this command reads: did you mean `camber`?",
    ] {
        assert!(err.contains(said), "no {said:?} in: {err}");
    }
    let points = "fz,kappa,alpha,camber,speed,presure\n4000,0,0.1,0,16,220000\n";
    let (o, written) = super::tyre_eval::eval(
        dir.path(),
        &root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"),
        points,
        &[],
    );
    assert!(!o.status.success() && written.is_empty(), "{written}");
    assert!(
        stderr(&o).contains(
            "p.csv:1:6: column `presure` is not one this command reads: did you mean `pressure`?"
        ),
        "{}",
        stderr(&o)
    );
}

/// `E_r` and the yaw-rate noise of `metrics --json` on `run`, and its
/// warnings.
fn yaw_variance(run_path: &Path) -> (f64, f64, Vec<String>) {
    let (j, warnings) = metrics_json(run_path);
    let number = |k: &str| j[k].as_f64().unwrap();
    (
        number("yaw_rate_total_variance"),
        number("yaw_rate_noise"),
        warnings,
    )
}

/// White noise on the yaw rate raised `E_r` from 0.050 to 0.085 s at a
/// tenth of the step, and nothing said so. It adds its variance times the
/// window, `W·σ²`, on average (one run scatters about it by as much, the
/// normalisation's own noise and the noise's product with the response
/// error adding to it): the warning says that figure, and over 24 seeds
/// of noise at 12 % of the step (100 Hz, filtered at 10 Hz) the mean rise
/// of `E_r` agrees with the mean figure within 30 % (the mean's scatter is
/// about 15 %). The clean run has no such warning.
#[test]
fn metrics_says_what_yaw_rate_noise_adds_to_the_total_variance() {
    use rand::SeedableRng;
    let dir = tempfile::tempdir().unwrap();
    let sedan = super::trips_s66::Sedan::simulated(dir.path());
    let clean = sedan.measured(dir.path(), "clean.csv", &|_, d, r, _| (d, r));
    let (e0, _, said) = yaw_variance(&clean);
    assert!(!said.iter().any(|w| w.contains("adds about")), "{said:?}");
    let at = sedan.header.iter().position(|h| h == "yaw_rate").unwrap();
    let step = sedan.rows.last().unwrap()[at] - sedan.rows[0][at];
    let (mut seen, mut figure) = (0.0, 0.0);
    for seed in 0..24 {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let noise: Vec<f64> = (0..sedan.rows.len())
            .map(|_| 0.12 * step * handling::identify::data::gauss(&mut rng))
            .collect();
        let noisy = sedan.measured(dir.path(), "noisy.csv", &|_, d, r, i| (d, r + noise[i]));
        let (e1, sigma, said) = yaw_variance(&noisy);
        // The 4 s window of `metrics`' defaults.
        let added = 4.0 * sigma * sigma;
        if seed == 0 {
            let line = said
                .iter()
                .find(|w| w.contains("adds about"))
                .unwrap_or_else(|| panic!("no noise warning at E_r {e1} (clean {e0}): {said:?}"));
            let number: f64 = line
                .split("adds about ")
                .nth(1)
                .and_then(|s| s.split(' ').next())
                .and_then(|v| v.parse().ok())
                .unwrap_or_else(|| panic!("{line}"));
            assert!((number - added).abs() < 0.01 * added, "{line}: {added}");
        }
        seen += (e1 - e0) / 24.0;
        figure += added / 24.0;
    }
    assert!(
        (figure - seen).abs() < 0.3 * figure,
        "the noise added {seen} s to E_r on average, the warnings say {figure} s"
    );
}
