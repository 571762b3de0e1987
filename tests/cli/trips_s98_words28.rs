//! What fresh users read in the diagnosis's words (session 98, round 28
//! and 28B): a printed ± that was not the diagnosis.json's, no word of the
//! channel that carries the combined error.

use super::*;
use crate::scenarios::simulated_rows;
use crate::trips_s95_real::{campaign, logged};

/// The linear car's step of 0.005 rad at `speed` m/s (1 s to 10 s), its
/// rows every 0.01 s, each response channel (beta, yaw rate, ay) taken
/// `delay` rows late and `ay` read `ay_offset` m/s² high: a logger's rows
/// (t, steer, speed, beta, yaw_rate, ay) for [`logged`].
fn step_rows(dir: &Path, name: &str, speed: f64, delay: usize, ay_offset: f64) -> Vec<Vec<f64>> {
    let manoeuvre = format!(
        "kind = \"step-steer\"\nspeed = {speed:?}\nsteer = 0.005\nstart = 1.0\nend = 10.0\n"
    );
    let rows = simulated_rows(dir, name, &manoeuvre);
    (0..rows.len())
        .map(|i| {
            let late = &rows[i.saturating_sub(delay)];
            vec![
                rows[i][0],
                rows[i][1],
                rows[i][2],
                late[3],
                late[4],
                late[5] + ay_offset,
            ]
        })
        .collect()
}

/// A campaign of two steps (20 and 30 m/s) logged with the ordinary
/// noise, responses `delay` rows late and `ay` `ay_offset` high, with
/// `effects` the candidates.
fn steps(dir: &Path, delay: usize, ay_offset: f64, effects: &str) -> PathBuf {
    let runs: Vec<(String, String)> = [("step20", 20.0), ("step30", 30.0)]
        .into_iter()
        .enumerate()
        .map(|(k, (name, speed))| {
            let rows = step_rows(dir, name, speed, delay, ay_offset);
            let text = logged(&rows, (3 + k as u64, 1.0), |_, _| true, |i| rows[i][1]);
            (format!("{name}.csv"), text)
        })
        .collect();
    campaign(dir, effects, &runs)
}

/// Round 28B (`sed.toml`): before the verdict ay stood at 12.8 noise
/// floors, beta 3.2, the yaw rate 2.4 — on equal samples ay carried about
/// 91 % of J² — and nothing said which channel the fits answer to. Now
/// diagnosis.json gives each channel's share of the held-out J², before
/// the verdict and with it, and the terminal and page name the channel
/// that carries more than two thirds of it. Here a logger's ay offset of
/// 0.6 m/s² (12 floors) on two steps: the shares are recomputed from the
/// JSON's own rows (samples, RMS, scale).
#[test]
fn the_channel_that_carries_most_of_the_combined_error_is_named_with_its_share() {
    let dir = tempfile::tempdir().unwrap();
    let c = steps(dir.path(), 0, 0.6, "\"sensor_bias\"");
    let out = dir.path().join("out");
    let (stdout, d) = diagnose_to(&c, &out);
    let shares = d["gap"]["channel_shares"]
        .as_array()
        .unwrap_or_else(|| panic!("no channel_shares: {}", d["gap"]));
    let scale = |ch: &serde_json::Value| {
        d["gap"]["noise"]
            .as_array()
            .unwrap()
            .iter()
            .find(|n| &n["channel"] == ch)
            .unwrap()["scale"]
            .as_f64()
            .unwrap()
    };
    let rows: Vec<&serde_json::Value> = d["shrinkage"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["part"] == "all")
        .collect();
    assert_eq!(rows.len(), shares.len(), "{}", d["gap"]["channel_shares"]);
    let weight = |s: &serde_json::Value, k: &str| {
        s["samples"].as_f64().unwrap() * (s[k].as_f64().unwrap() / scale(&s["channel"])).powi(2)
    };
    for key in ["before", "after"] {
        let total: f64 = rows.iter().map(|s| weight(s, key)).sum();
        for s in &rows {
            let share = shares
                .iter()
                .find(|x| x["channel"] == s["channel"])
                .unwrap();
            let said = share[format!("{key}_percent")].as_f64().unwrap();
            assert!(
                (said - 100.0 * weight(s, key) / total).abs() < 1e-6,
                "{share}"
            );
        }
    }
    let ay = shares.iter().find(|x| x["channel"] == "ay").unwrap();
    let p = ay["before_percent"].as_f64().unwrap();
    assert!(p > 200.0 / 3.0, "{ay}");
    let line = format!("ay {p:.0} % of the base model");
    assert!(stdout.contains(&line), "{line}\n{stdout}");
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains(&line), "the page names it too");
}

/// Round 28B (`rn4lt.out`): "front_share = 0.4366 ± 0.000114 (the fold
/// refits scatter ± 0.00223, 8× …)" while diagnosis.json's `std_error`
/// was 0.00223 (`fold_spread`): the truth 0.45 lay 118 printed standard
/// errors off, 6 of the JSON's. The book's synthetic campaign shows the
/// same on relaxation_length. Now every parameter reported from its fold
/// spread leads the terminal and the page with the JSON's ±, the
/// asymptotic one in the parenthesis.
#[test]
fn a_parameter_reported_from_its_fold_spread_prints_the_jsons_standard_error() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, d, page) = narrowed(
        dir.path(),
        "sensor_delay",
        "\"sensor_delay\", \"relaxation_length\"",
    );
    let mut checked = 0;
    for r in d["ranking"].as_array().unwrap() {
        let effect = r["effect"].as_str().unwrap();
        let row = stdout
            .lines()
            .find(|l| l.split_whitespace().next() == Some(effect))
            .unwrap_or_else(|| panic!("{effect}\n{stdout}"));
        for p in r["parameters"].as_array().unwrap() {
            if p["std_error_basis"] != "fold_spread" {
                continue;
            }
            let name = p["name"].as_str().unwrap();
            let (se, asymptotic) = (
                p["std_error"].as_f64().unwrap(),
                p["asymptotic_std_error"].as_f64().unwrap(),
            );
            let after = &row[row.find(&format!("{name} = ")).unwrap()..];
            let printed: f64 = after
                .split("± ")
                .nth(1)
                .unwrap()
                .split([' ', ',', ')'])
                .next()
                .unwrap()
                .parse()
                .unwrap();
            assert!(
                (printed - se).abs() <= 0.01 * se,
                "{printed} against {se}: {row}"
            );
            assert!(
                se > 1.5 * asymptotic || after.contains("(the fold refits' spread"),
                "{row}"
            );
            checked += 1;
        }
    }
    // relaxation_length's spread far beyond its asymptotic error, as the book shows.
    assert!(checked >= 1, "{stdout}");
    assert!(
        stdout.contains("relaxation_length.relaxation_length = ")
            && stdout.contains("the asymptotic error does not cover"),
        "{stdout}"
    );
    assert!(
        page.contains("the asymptotic error does not cover"),
        "the page words it alike"
    );
}
