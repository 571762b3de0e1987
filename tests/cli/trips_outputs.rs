//! What a new user trips on in the outputs and the options of `simulate`,
//! `metrics` and `tyre-eval`, run as a user runs the tool: each test one
//! thing a fresh-eyes check met, and what the tool now does.

use super::*;
use std::process::Stdio;

#[test]
fn a_reader_that_stops_early_ends_the_run_quietly_not_with_a_panic() {
    // `handling simulate … | head -1`: stdout closed before the summary
    // is printed.
    let dir = tempfile::tempdir().unwrap();
    let mut child = bin()
        .args([
            "simulate",
            "scenarios/step_gbt6323_pac89.toml",
            "--out",
            dir.path().join("x").to_str().unwrap(),
        ])
        .current_dir(root())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let o = child.wait_with_output().unwrap();
    let e = stderr(&o);
    assert!(o.status.success(), "{:?}: {e}", o.status);
    assert!(!e.contains("panicked") && !e.contains("Broken pipe"), "{e}");
    // The outputs were written before anything was printed.
    assert!(dir.path().join("x/history.csv").exists());
}

#[test]
fn metrics_options_the_run_cannot_honour_are_refused_or_said() {
    let dir = tempfile::tempdir().unwrap();
    let sim = dir.path().join("sim");
    let o = run(&[
        "simulate",
        "scenarios/step_gbt6323_pac89.toml",
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let history = sim.join("history.csv");
    let metrics = |opt: &str, value: &str| run(&["metrics", history.to_str().unwrap(), opt, value]);
    // A cut-off that is no cut-off is refused at its option with its value
    // (they ran unfiltered without a word; `-1` was taken for an option).
    for value in ["nan", "-1"] {
        let o = metrics("--filter-hz", value);
        assert!(!o.status.success(), "{value}");
        let says = format!("invalid value '{value}' for '--filter-hz <FILTER_HZ>': a cut-off is a positive, finite frequency in Hz (0: unfiltered)");
        assert!(stderr(&o).contains(&says), "{value}: {}", stderr(&o));
    }
    let o = metrics("--variance-window", "-1");
    assert!(
        stderr(&o).contains("invalid value '-1' for '--variance-window <VARIANCE_WINDOW>': a window is a positive, finite number of seconds"),
        "{}",
        stderr(&o)
    );
    // One slower than the response is refused with why (it smoothed the
    // step away and the run was blamed for having none).
    let o = metrics("--filter-hz", "0.5");
    assert!(
        stderr(&o).contains("`filter_hz` = 0.5: must be greater than 1: a zero-phase low-pass"),
        "{}",
        stderr(&o)
    );
    // One the run's sampling cannot apply, or a window past the record, is
    // measured and said.
    let o = metrics("--filter-hz", "1e9");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: the low-pass at 1000000000 Hz is not below 0.4 × the run's sampling rate: the run is not filtered"),
        "{}",
        stderr(&o)
    );
    assert!(!String::from_utf8_lossy(&o.stdout).contains("filtered:"));
    let o = metrics("--variance-window", "1e308");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: the total-variance window, 1e308 s from the steer's onset, runs past the end of the measured piece at 6.00 s"),
        "{}",
        stderr(&o)
    );
    // A window of 5 ms gave Er 0.0000 s and one of 1e-300 s a one-sample
    // steady mean, without a word.
    let o = metrics("--variance-window", "0.005");
    assert!(
        stderr(&o).contains("warning: the total-variance window, 0.005 s, ends before the yaw rate responds (its response time is 0.1"),
        "{}",
        stderr(&o)
    );
    for (option, name) in [("--steady-window", "steady"), ("--pre-window", "initial")] {
        let o = metrics(option, "1e-300");
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("warning: the {name} window, 1e-300 s, is shorter than two of the run's sample intervals")),
            "{}",
            stderr(&o)
        );
    }
    // The default windows say none of it.
    let o = run(&["metrics", history.to_str().unwrap()]);
    assert!(
        !without_temp_names(&stderr(&o)).contains("window"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_tiny_input_is_written_as_the_shortest_text_that_reads_back_not_300_digits() {
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("tiny.csv");
    fs::write(
        &points,
        "fz,kappa,alpha,camber,speed\n4000,1e-300,0.05,0,16.7\n4000,0,-0.0,0,16.7\n",
    )
    .unwrap();
    let out = dir.path().join("forces.csv");
    let o = run(&[
        "tyre-eval",
        "tyres/pac89_adams_example.toml",
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&out).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows[0][1], "1e-300", "{text}");
    // `-0.0` reads back as zero and is written as `0`.
    assert_eq!(rows[1][2], "0", "{text}");
    for (i, row) in rows.iter().enumerate() {
        for cell in row {
            assert!(cell.len() < 26 && *cell != "-0", "row {i}: `{cell}`");
            assert!(
                cell.parse::<f64>().unwrap().is_finite(),
                "row {i}: `{cell}`"
            );
        }
    }
}

#[test]
fn a_tir_cut_short_or_with_a_core_coefficient_misspelt_is_refused_not_evaluated_with_defaults() {
    let dir = tempfile::tempdir().unwrap();
    let full = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let points = dir.path().join("p.csv");
    fs::write(&points, "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n").unwrap();
    let eval = |name: &str, text: &str| {
        let tir = dir.path().join(name);
        fs::write(&tir, text).unwrap();
        let out = dir.path().join(format!("{name}.csv"));
        let o = run(&[
            "tyre-eval",
            tir.to_str().unwrap(),
            points.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        (o, out)
    };
    // The whole file evaluates (a positive lateral force at +0.05 rad).
    let (o, out) = eval("whole.tir", &full);
    assert!(o.status.success(), "{}", stderr(&o));
    let fy: f64 = fs::read_to_string(out)
        .unwrap()
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(6)
        .unwrap()
        .parse()
        .unwrap();
    assert!(fy > 1000.0, "{fy}");
    // `PCY1` renamed `PCY1X`: it gave −77 N for +3355 N, without a word.
    let (o, out) = eval("misspelt.tir", &full.replacen("\nPCY1 ", "\nPCY1X ", 1));
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("misspelt.tir: lacks PCY1 of the peak and shape coefficients every Magic Formula file carries")
            && e.contains("`PCY1X` at line 197: `PCY1` misspelt?"),
        "{e}"
    );
    assert!(!out.exists());
    // Cut short after its vertical section: every force was 0.
    let (o, _) = eval("cut.tir", &full[..3000]);
    let e = stderr(&o);
    assert!(
        e.contains("cut.tir: lacks PCX1, PDX1, PKX1, PCY1, PDY1, PKY1, QBZ1, QDZ1 of the peak and shape coefficients")
            && e.contains("is the file complete (it has 49 lines)?"),
        "{e}"
    );
    // Cut before its lateral or its aligning coefficients: the
    // longitudinal ones come first in every published file, so a file
    // that has them and lacks a later force's was cut, and wrote fy = mz =
    // 0 without a word.
    for (section, lacks) in [
        ("[LATERAL_COEFFICIENTS]", "PCY1, PDY1, PKY1, QBZ1, QDZ1"),
        ("[ALIGNING_COEFFICIENTS]", "QBZ1, QDZ1"),
    ] {
        let at = full.find(section).unwrap();
        let name = format!("cut_{}.tir", &section[1..4]);
        let (o, out) = eval(&name, &full[..at]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{e}");
        assert!(
            e.contains(&format!(
                "{name}: lacks {lacks} of the peak and shape coefficients"
            )) && e.contains("is the file complete"),
            "{e}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn identify_refuses_an_output_it_cannot_write_before_fitting() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().to_str().unwrap();
    for (data, model, out, says) in [
        (
            "docs/examples/mf_grid.csv",
            "mf61",
            folder.to_string(),
            format!("{folder}: is a folder; name the file to write in it (e.g. {folder}/fit.tir)"),
        ),
        (
            "docs/examples/mf_grid.csv",
            "mf61",
            format!("{folder}/x.toml"),
            format!("{folder}/x.toml: the mf61 model is written as a .tir file, not .toml"),
        ),
        (
            "docs/examples/tyre_points.csv",
            "pac89",
            format!("{folder}/x.tir"),
            format!("{folder}/x.tir: the pac89 model is written as a .toml file, not .tir"),
        ),
    ] {
        let o = run(&["identify", data, "--model", model, "--out", &out]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{e}");
        assert!(e.contains(&says), "{e}");
        // Refused before the fit (the folder was refused after it, at the
        // rename): nothing written.
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
    }
}

#[test]
fn metrics_on_a_log_of_driving_says_it_holds_no_step_steer() {
    // A steer that never holds: a sine from the first sample (the racing
    // log's "the record starts too close to the step").
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("t,steer,speed,yaw_rate,ay\n");
    for i in 0..2000 {
        let t = i as f64 * 0.01;
        let steer = 0.02 * (std::f64::consts::TAU * 0.5 * t + 0.3).sin();
        let r = 20.0 * steer / 2.7;
        text += &format!("{t},{steer},20,{r},{}\n", 20.0 * r);
    }
    let run_file = dir.path().join("driving.csv");
    fs::write(&run_file, text).unwrap();
    let o = run(&["metrics", run_file.to_str().unwrap()]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("no step steer in this record: the steer spans 0.0400 rad (2.29°), from -0.0200 rad (-1.15°) to 0.0200 rad (1.15°), and reverses 20 times"),
        "{e}"
    );
}
