//! What a fresh-eyes check of `identify`, `simulate` and `diagnose` found
//! (stop 72), run as a user runs the tool.

use super::trips_s69_identify::{at_pressure, hoosier};
use super::*;

/// `synth --seed -3` was clap's "unexpected argument '-3' found" and
/// `--seed=-3` "invalid digit found in string", where `identify` says what
/// a seed is: now `synth` says it in the same words.
#[test]
fn a_negative_synth_seed_is_refused_as_identify_refuses_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c");
    for args in [["--seed", "-3"].as_slice(), ["--seed=-3"].as_slice()] {
        let mut all = vec!["synth", "--out", out.to_str().unwrap()];
        all.extend_from_slice(args);
        let o = run(&all);
        let e = stderr(&o);
        assert!(!o.status.success(), "{e}");
        assert!(
            e.contains("invalid value '-3' for '--seed <SEED>'")
                && e.contains("expected a whole number of 0 or more"),
            "{e}"
        );
        assert!(!e.contains("unexpected argument"), "{e}");
        assert!(!out.exists());
    }
}

/// A step at the friction limit warned "(steady ay 8.65 m/s² …)" where the
/// metrics' table, two lines off, read "steady ay 8.8433 m/s²": the
/// warning's figure is the last row's, and it now says so.
#[test]
fn the_at_the_limit_warning_names_the_last_rows_ay_not_a_second_steady_ay() {
    let text = bundled_scenario("sedan_step.toml").replace(
        "steer = 0.0174533    # rad = 1 deg front road-wheel angle",
        "steer = 0.5",
    );
    let dir = scratch(&[("step.toml", &text)]);
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("step.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    let warning = said
        .lines()
        .find(|l| l.contains("the busier axle uses"))
        .unwrap_or_else(|| panic!("no at-the-limit warning: {said}"));
    assert!(!warning.contains("(steady ay"), "{warning}");
    // The figure is the history's last row, at the time it gives.
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let header: Vec<&str> = history.lines().next().unwrap().split(',').collect();
    let last: Vec<f64> = history
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    let col = |name: &str| last[header.iter().position(|h| *h == name).unwrap()];
    let ay = col("ay").abs();
    let (at, t) = (
        warning.split("(ay ").nth(1).unwrap(),
        warning.split("at the last row, t = ").nth(1).unwrap(),
    );
    let num = |s: &str| -> f64 {
        s.split(' ')
            .next()
            .unwrap()
            .trim_end_matches(',')
            .parse()
            .unwrap()
    };
    assert!(
        (num(at) - ay).abs() <= 5e-3 * ay,
        "{warning}: last row ay {ay}"
    );
    assert!((num(t) - col("t")).abs() < 1e-2, "{warning}");
}

/// PAC89 on one level of the Hoosier file wrote its two-stage result, yet
/// said `held: a6 = 0.0456…: … held at the model's start value -0.02103`
/// with the file's `a[6] = 0.0457`: the direct fit's holds were carried
/// onto a result that fitted those parameters. Every hold the report and
/// the terminal state is the file's value.
#[test]
fn a_pac89_two_stage_result_writes_the_values_its_held_lines_state() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("pac.toml");
    let Some(rig) = hoosier("a_pac89_two_stage_result_writes_the_values_its_held_lines_state")
    else {
        return;
    };
    let text = at_pressure(&rig, "pac89", &out, &["--camber", "0"]);
    let report = read_json(&dir.path().join("pac.report.json"));
    assert_eq!(report["written"], "two-stage", "{text}");
    let file: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    let written = |name: &str| -> f64 {
        let (block, k) = name.split_at(1);
        file[block][k.parse::<usize>().unwrap()].as_float().unwrap()
    };
    let held = report["held"].as_array().unwrap();
    assert!(held.len() >= 3, "{report}");
    for h in held {
        let name = h["name"].as_str().unwrap();
        let value = h["value"].as_f64().unwrap();
        assert_eq!(written(name), value, "{h}");
        if h["why"] == "undetermined" {
            assert_eq!(h["held_at"].as_f64().unwrap(), value, "{h}");
        }
        let line = text
            .lines()
            .find(|l| l.starts_with("  held: ") && l.contains(&format!("{name} = ")))
            .unwrap_or_else(|| panic!("no held line for {name}: {text}"));
        let said: f64 = line
            .split(&format!("{name} = "))
            .nth(1)
            .unwrap()
            .split([':', ','])
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert_eq!(said, value, "{line}");
    }
}
