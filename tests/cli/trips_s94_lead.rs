//! What fresh-eyes users tripped on in session 94, run as a user runs the
//! tool.

use super::trips_s69_identify::{at_pressure, hoosier};
use super::trips_s93_diag::{linear_roll_steer, roll_steer_design};
use super::*;

/// Before: the diagnosis advised any manoeuvre the campaign lacked whose
/// predicted responses differed by a noise floor (D ≥ 1), where `design`
/// judged the same manoeuvre "not recommended" by the separation a driven
/// run is expected to measure, its uncertainty and the campaign's own
/// separation (round 23: an advised sweep at D = 1.0 that `design` put at
/// 1.0 ± 1.4). Now the advice carries the design's expected separation,
/// uncertainty and worth for that manoeuvre, to rounding, and its words
/// follow the worth.
#[test]
fn the_diagnosis_advises_a_lacking_run_by_the_designs_own_rule() {
    let dir = tempfile::tempdir().unwrap();
    let c = linear_roll_steer(dir.path());
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    let best = &d["confounded"][0]["separating_runs"]["pairs"][0]["best"];
    let name = best["name"].as_str().unwrap_or_else(|| panic!("{said}"));
    let set = &roll_steer_design(&out, &dir.path().join("design"));
    let scored = set["ranked"].as_array().unwrap();
    let scored = scored.iter().find(|s| s["name"] == name).unwrap();
    for key in ["expected", "uncertainty"] {
        let (a, b) = (best[key].as_f64().unwrap(), scored[key].as_f64().unwrap());
        assert!(
            (a - b).abs() <= 1e-9 * b.abs().max(1.0),
            "{key}: {a} against {b}"
        );
    }
    let campaign = set["campaign_separation"].as_f64().unwrap();
    let stated = best["campaign_separation"].as_f64().unwrap();
    assert!(
        (campaign - stated).abs() <= 1e-9 * campaign,
        "{campaign} against {stated}"
    );
    assert_eq!(best["worth"], scored["worth"], "{said}");
    // The words follow the worth: a run the design does not recommend is
    // not offered as the one to drive.
    let line = said.lines().find(|l| l.starts_with("confounded:")).unwrap();
    let recommended = scored["worth"] == "separates";
    assert_eq!(!recommended, line.contains("none of the"), "{line}");
    if scored["worth"] == "below_campaign" {
        assert!(line.contains(&format!("(D = {campaign:.1})")), "{line}");
    }
}

/// The handling programme's runs (no effect withheld) cut to start one
/// second into their turn, without their sideslip column: what a logger
/// without a sideslip gives once its pieces start mid-turn.
fn mid_turn_without_sideslip(dir: &Path) -> PathBuf {
    let c = synth_campaign(dir, "c", &["--seed", "1"]);
    for entry in fs::read_dir(c.join("runs")).unwrap() {
        let path = entry.unwrap().path();
        let text = fs::read_to_string(&path).unwrap();
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let (t, steer, beta) = (col("t"), col("steer"), col("beta"));
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        let value = |r: &[&str], k: usize| r[k].parse::<f64>().unwrap();
        let peak = rows
            .iter()
            .fold(0.0_f64, |m, r| m.max(value(r, steer).abs()));
        let turning = rows
            .iter()
            .find(|r| value(r, steer).abs() > 0.5 * peak)
            .unwrap();
        let from = value(turning, t) + 1.0;
        let keep = |r: &[&str]| {
            let row: Vec<&str> = (0..r.len()).filter(|&k| k != beta).map(|k| r[k]).collect();
            row.join(",")
        };
        let mut out = vec![keep(&header)];
        out.extend(rows.iter().filter(|r| value(r, t) >= from).map(|r| keep(r)));
        fs::write(&path, out.join("\n") + "\n").unwrap();
    }
    c
}

/// Before: a replay without a measured sideslip started at a sideslip of
/// 0, and a piece that starts in a turn (as a logger's pieces do) scored
/// the replay settling from it as model error: on these runs, in which
/// the model is exact, "roll_camber+load_transfer_distribution explains
/// part of the gap: held-out error 3.809 → 2.089". Now the first half
/// second of such a run (the gap scan's first window) is not scored.
#[test]
fn runs_without_a_sideslip_that_start_mid_turn_show_no_gap_where_the_model_is_exact() {
    let dir = tempfile::tempdir().unwrap();
    let c = mid_turn_without_sideslip(dir.path());
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    assert_eq!(d["verdict"]["kind"], "no_significant_gap", "{said}");
    let j = d["gap"]["heldout_error"].as_f64().unwrap();
    let noise = d["gap"]["noise_level"].as_f64().unwrap();
    assert!(j < 1.2 * noise, "{j} against {noise}: {said}");
}

/// Before: a logger's spike of 9999 in one `ay` sample was masked, but
/// still counted in the channel's RMS signal, whose 2 % floors its scale:
/// the `ay` gap of a withheld sensor bias weighed a fraction of what it
/// should (held-out error 2.057 for 2.848, noise level 0.811 for 0.934).
/// Now a masked sample is no signal, and the diagnosis is the spike-free
/// campaign's to rounding. Since round 51 an `ay` of 9999 m/s² is refused
/// at its cell (no car's): five spikes of 99 m/s², within reach (and
/// under 1 % of the run, which the unit check reads), add as much to the
/// run's sum of squares as one of 221 would.
#[test]
fn a_masked_spike_does_not_set_the_scale_of_its_channel() {
    let dir = tempfile::tempdir().unwrap();
    let clean = synth_campaign(
        dir.path(),
        "clean",
        &["--effects", "sensor_bias", "--seed", "1"],
    );
    let spiked = synth_campaign(
        dir.path(),
        "spiked",
        &["--effects", "sensor_bias", "--seed", "1"],
    );
    let path = spiked.join("runs/ramp_080kph.csv");
    let text = fs::read_to_string(&path).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let ay = lines[0].split(',').position(|h| h == "ay").unwrap();
    for row in (100..=740).step_by(160) {
        let mut cells: Vec<&str> = lines[row].split(',').collect();
        cells[ay] = "99";
        lines[row] = cells.join(",");
    }
    fs::write(&path, lines.join("\n") + "\n").unwrap();
    let (_, a) = diagnose_to(&clean, &dir.path().join("a"));
    let (said, b) = diagnose_to(&spiked, &dir.path().join("b"));
    assert!(
        said.contains("runs/ramp_080kph.csv: ay 5 times, the first at 3.990 s (99), the last at 10.390 s (99) (5 samples, masked)"),
        "{said}"
    );
    assert_eq!(a["verdict"]["effects"], b["verdict"]["effects"], "{said}");
    for key in ["heldout_error", "noise_level"] {
        let (x, y) = (
            a["gap"][key].as_f64().unwrap(),
            b["gap"][key].as_f64().unwrap(),
        );
        assert!(
            (x - y).abs() < 0.005 * x,
            "{key}: {y} against {x} without the spike"
        );
    }
}

/// Before: `identify --model pac89` on the Hoosier rig file held a6 and
/// a7 (not determined by the data) and wrote that fit, σ 2.573 %, while
/// its last line said "writing the direct fit (σ over all points
/// 2.566421 % …)", the free fit's. Now the line names what is held and
/// the σ of what is written, the σ line's and the file's.
#[test]
fn identify_says_the_sigma_of_the_fit_it_writes() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("h.toml");
    let Some(rig) = hoosier("identify_says_the_sigma_of_the_fit_it_writes") else {
        return;
    };
    let said = at_pressure(&rig, "pac89", &out, &[]);
    let sigma = sigma_line(&said);
    let line = said
        .lines()
        .find(|l| l.starts_with("  writing the direct fit"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.starts_with(&format!(
            "  writing the direct fit with a6, a7 held: σ over all points {sigma} %"
        )),
        "{line}"
    );
    let file = fs::read_to_string(&out).unwrap();
    assert!(
        file.contains(&format!("sigma {sigma} %")),
        "{sigma} not in {file}"
    );
}

/// The σ an `identify` terminal `said` on its "  σ " line, as printed.
pub(crate) fn sigma_line(said: &str) -> String {
    said.lines()
        .find_map(|l| l.strip_prefix("  σ "))
        .and_then(|l| l.split(' ').next())
        .unwrap_or_else(|| panic!("{said}"))
        .to_string()
}
