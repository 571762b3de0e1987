//! What the fifth fresh-eyes check found in `simulate`: a `.tir` held at
//! its ranges' ends without a word, a lightly damped step said as a spin
//! (by `simulate`, and by `metrics` on its history),
//! metric windows refused only after the run (or cut without a word), and
//! a cornering stiffness typed in N/deg run as N/rad.
//! Each test one finding, run as a user runs it.

use super::*;
use crate::trips_simulate::simulated;

/// The bundled sedan step (Gim tyres) with `from` replaced by `to`, its
/// tyre paths made absolute.
fn sedan_step(from: &str, to: &str) -> tempfile::TempDir {
    let text = bundled_scenario("sedan_step.toml").replace(from, to);
    assert!(text.contains(to), "{text}");
    scratch(&[("scenario.toml", &text)])
}

/// The sedan on the public `FSAE_Defaults.tir` (FZMAX 2000 N) ran its
/// 3–5 kN wheels at 2000 N without a word.
#[test]
fn simulate_counts_the_rows_beyond_a_tirs_own_ranges() {
    let test = "simulate_counts_the_rows_beyond_a_tirs_own_ranges";
    let Some(tir) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let sc = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n{STEP}",
        tir.display()
    );
    let dir = scratch(&[("scenario.toml", &sc)]);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    for axle in ["front", "rear"] {
        let line = said
            .lines()
            .find(|l| {
                l.contains(&format!(
                    "take the {axle} tyres outside their .tir's validity ranges"
                ))
            })
            .unwrap_or_else(|| panic!("{said}"));
        // Every row: each wheel carries more than 2000 N throughout.
        let words: Vec<&str> = line.trim_start_matches("  warning: ").split(' ').collect();
        assert_eq!(words[0], words[2], "{line}");
        assert!(line.contains("(fz 0 to 2000 N, "), "{line}");
        assert!(
            line.contains(
                "evaluated at the ranges' ends, a load below FZMIN excepted (MFeval's limit checks"
            ),
            "{line}"
        );
        assert!(line.contains("there, wheel loads "), "{line}");
    }
}

/// The sedan's 1° step at 60 m/s rings (146 % overshoot) with its tyres
/// at 2–3° of slip, and was said to be "losing and regaining grip or
/// spinning".
#[test]
fn a_lightly_damped_step_far_below_the_grip_is_no_spin() {
    let dir = sedan_step("speed = 22.2222", "speed = 60.0");
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the yaw rate overshoots its steady value by 146 % with the tyres using no more than "),
        "{said}"
    );
    assert!(
        said.contains("no spin, but a lightly damped linear response (the yaw damping falls with speed, here 60.0 m/s)"),
        "{said}"
    );
    assert!(!said.contains("spinning"), "{said}");
    // `metrics` on the same history, a measured run whose grip no channel
    // gives, called it a spin: its sideslip says it never slid.
    let history = dir.path().join("out/history.csv");
    let o = run(&["metrics", history.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    // The warnings go to stderr, beside the table on stdout.
    let said = stderr(&o);
    assert!(
        said.contains(
            "warning: the yaw rate overshoots its steady value by 146 % with the sideslip within ±"
        ),
        "{said}"
    );
    assert!(
        said.contains("° throughout, short of the 10° of a sliding car: no spin, but a lightly damped response (the yaw damping falls with speed, here 60.0 m/s)"),
        "{said}"
    );
    assert!(!said.contains("spinning"), "{said}");
    // Without `beta` nothing tells a ringing car from a spinning one: both
    // are said.
    let text = fs::read_to_string(&history).unwrap();
    let cut: Vec<String> = text
        .lines()
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            [&cells[..3], &cells[4..]].concat().join(",")
        })
        .collect();
    assert!(text.starts_with("t,steer,speed,beta,"), "{text:.80}");
    let no_beta = dir.path().join("no_beta.csv");
    fs::write(&no_beta, cut.join("\n")).unwrap();
    let o = run(&["metrics", no_beta.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("losing and regaining grip or spinning, not the handling response the metrics describe; or, at speed, a lightly damped response that never left the tyres' linear range: the run has no `beta` to tell them apart"),
        "{}",
        stderr(&o)
    );
}

/// `steady_window = 10` on a 6 s step failed after the run with no file,
/// line or key; `variance_window = 100` was cut to the record silently.
#[test]
fn metric_windows_are_held_to_the_record_when_the_scenario_is_read() {
    let dir = sedan_step(
        "end = 6.0\n",
        "end = 6.0\n\n[metrics]\nsteady_window = 10\n",
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("scenario.toml:28:17: `metrics.steady_window` = 10: the initial and steady windows together (`pre_window` = 0.5 s + `steady_window` = 10 s) do not fit in the record, 0 to `end` = 6 s: shorten the window or lengthen the manoeuvre's `end`"),
        "{e}"
    );
    let dir = sedan_step(
        "end = 6.0\n",
        "end = 6.0\n\n[metrics]\nvariance_window = 100\n",
    );
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(
        said.contains("warning: the total-variance window, `variance_window` = 100 s, is longer than the record after the step (5.00 s, from the step at t = 1 s to `end` = 6 s): the variances are over what was recorded"),
        "{said}"
    );
    let dir = sedan_step("end = 6.0\n", "end = 6.0\n");
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    assert!(!said.contains("variance"), "{said}");
}

/// `cornering_stiffness = 500` (N/deg typed for N/rad, 57 times too
/// soft) ran without a word.
#[test]
fn a_cornering_stiffness_in_n_per_degree_is_refused_with_the_factor() {
    for extra in [
        "model = \"gim\"\ncontact_length = 0.18",
        "model = \"linear\"",
    ] {
        let tyre = format!("{extra}\ncornering_stiffness = 500\n");
        let dir = scenario(VEHICLE, &tyre, STEP);
        let e = simulate_err(dir.path());
        assert!(
            e.contains("`cornering_stiffness` = 500: must lie in (900, 2000000]: no tyre's cornering stiffness is below 900 N/rad"),
            "{e}"
        );
        assert!(
            e.contains("is the value in N/deg? multiply it by 57.3"),
            "{e}"
        );
    }
}

/// The MF 6.1 sample with `INFLPRES` = 150 kPa, below its `PRESMIN` of
/// 200 kPa, ran at 200 kPa (the limit checks) without a word of the
/// pressure; and a file without `FZMIN` said its load range as `fz -inf
/// to 2000 N`.
#[test]
fn simulate_checks_a_tirs_own_pressure_and_says_a_one_ended_range() {
    let text = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let edited: String = text
        .lines()
        .filter(|l| !l.starts_with("FZMIN"))
        .map(|l| match l.split_whitespace().next() {
            Some("INFLPRES") => "INFLPRES = 150000\n".to_string(),
            Some("FZMAX") => "FZMAX = 2000\n".to_string(),
            _ => format!("{l}\n"),
        })
        .collect();
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"tyre.tir\"\n\n{STEP}");
    let dir = scratch(&[("scenario.toml", &sc), ("tyre.tir", &edited)]);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok, "{err}");
    let line = said
        .lines()
        .find(|l| l.contains("take the front tyres outside their .tir's validity ranges"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.contains("(fz ≤ 2000 N, alpha -0.9600 to 0.9600 rad, kappa -1.000 to 1.000, camber -0.1050 to 0.08730 rad, pressure 200000 to 400000 Pa; "),
        "{line}"
    );
    assert!(!without_temp_names(line).contains("inf"), "{line}");
    assert!(
        line.contains("there, wheel loads ")
            && line.contains(", a pressure of 150000 Pa (the file's INFLPRES)"),
        "{line}"
    );
    // At its own pressure, within the range, the pressure is not named.
    let within = edited.replace("INFLPRES = 150000", "INFLPRES = 250000");
    let dir = scratch(&[("scenario.toml", &sc), ("tyre.tir", &within)]);
    let (ok, said, err) = simulated(dir.path());
    assert!(ok && !said.contains("a pressure of"), "{err}{said}");
}
