//! What a fresh-eyes user tripped on in round 44, run as a user runs the
//! tool: `study` printed the RBF network's answer to Er = 0.6 s, seven
//! times beyond the map it was fitted on and re-simulated 94 % short, as
//! an answer; `simulate` at 0.5 rad of steer bounded its yaw-rate gain
//! "off by up to about 22 %" where the window's yaw rate spans 72 % of its
//! step, and said a −49.5° slip "past its tyres' peak at 38.0°".

use super::*;

/// The bundled coarse study (map 200–700 / 220–720 N/deg) asked for
/// `er` within ± 0.005 s.
fn coarse_study_for(er: &str) -> String {
    let text = bundled_scenario("sedan_study_coarse.toml");
    let asked = "value = 0.13, tolerance = 0.005";
    assert!(text.contains(asked), "{text}");
    text.replace(asked, &format!("value = {er}, tolerance = 0.005"))
}

/// Runs `study study.toml --out o` in a fresh folder: its words, its
/// `inverse.json` and the map's handling rows of `study.csv` (its first
/// 36, the 6 × 6 map; the RBF pairs follow) as (k1, k2 in N/deg, Er).
fn studied(text: &str) -> (String, serde_json::Value, Vec<(f64, f64, f64)>) {
    let dir = scratch(&[("study.toml", text)]);
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = dir.path().join("o");
    let csv = fs::read_to_string(out.join("study.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let (kf, kr, er) = (col("k_front_N_per_deg"), col("k_rear_N_per_deg"), col("er"));
    // The columns before `note` hold no comma.
    let rows = lines
        .take(36)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter_map(|c| {
            Some((
                c[kf].parse().ok()?,
                c[kr].parse().ok()?,
                c[er].parse().ok()?,
            ))
        })
        .collect();
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        read_json(&out.join("inverse.json")),
        rows,
    )
}

/// Before: "RBF answer: (4645.7, 1822.3) N/deg, Er 0.038543 re-simulated
/// (-93.58 %) … trust it as far as its re-simulated Er". Now: no answer,
/// refused for lying outside the map and missing its target by more than
/// its tolerance (checked here against inverse.json's own numbers), with
/// Er 0.6 unreachable within the map and the nearest Er the map reaches,
/// and where, as study.csv holds them; inverse.json says it typed.
#[test]
fn an_rbf_answer_beyond_the_map_that_misses_its_target_is_refused() {
    let (said, inverse, rows) = studied(&coarse_study_for("0.6"));
    let t = &inverse["targets"][0];
    let rbf = &t["rbf"];
    assert_eq!(rbf["status"], "refused", "{rbf}");
    let (kf, kr) = (
        rbf["k_front"].as_f64().unwrap(),
        rbf["k_rear"].as_f64().unwrap(),
    );
    let er = rbf["er_resimulated"].as_f64().unwrap();
    // The refusal's grounds, from the numbers: outside 200–700 / 220–720
    // and off 0.6 by more than 0.005.
    assert!(!(200.0..=700.0).contains(&kf) || !(220.0..=720.0).contains(&kr));
    assert!((er - 0.6).abs() > 0.005, "{er}");
    assert_eq!(
        rbf["refused_for"],
        serde_json::json!(["outside_map", "misses_target"]),
        "{rbf}"
    );
    let line = said
        .lines()
        .find(|l| l.starts_with("    RBF answer: "))
        .expect(&said);
    assert!(
        line.starts_with(&format!(
            "    RBF answer: none: the network gives ({kf:.1}, {kr:.1}) N/deg, "
        )),
        "{line}"
    );
    assert!(
        line.contains("outside the map it was fitted on (front 200–700, rear 220–720 N/deg)"),
        "{line}"
    );
    assert!(
        line.contains(&format!(
            "its Er re-simulated, {} s ({:+.2} %), misses Er 0.6 by more than its tolerance of 0.005 s",
            handling::format::significant(er, 5),
            100.0 * (er - 0.6) / 0.6
        )),
        "{line}"
    );
    assert!(line.contains("; not an answer"), "{line}");
    assert!(!line.contains("trust it"), "{line}");
    // What the map reaches, from study.csv's own map rows.
    let map = rows;
    assert_eq!(map.len(), 30, "{map:?}"); // 36 less the 6 that slide
    let top = map
        .iter()
        .copied()
        .max_by(|a, b| a.2.total_cmp(&b.2))
        .unwrap();
    let low = map.iter().map(|r| r.2).fold(f64::INFINITY, f64::min);
    assert!(top.2 < 0.6, "{top:?}");
    let g = |v: f64| handling::format::significant(v, 4);
    let nearest = format!(
        "the nearest it reaches is {} s, at ({}, {}) N/deg",
        g(top.2),
        handling::format::rounded(top.0, 6),
        handling::format::rounded(top.1, 6)
    );
    assert!(
        line.contains(&format!(
            "; Er 0.6 is unreachable within the map (its Er spans {}–{} s): {nearest}",
            g(low),
            g(top.2)
        )),
        "{line}"
    );
    let reach = &t["map_reach"];
    assert_eq!(reach["target"], "above_map", "{reach}");
    assert!((reach["highest"]["value"].as_f64().unwrap() - top.2).abs() < 1e-6 * top.2);
    let at = |key: &str| reach["highest"][key].as_f64().unwrap();
    assert!((at("k_front") - top.0).abs() < 1e-9 * top.0, "{reach}");
    assert!((at("k_rear") - top.1).abs() < 1e-9 * top.1, "{reach}");
    // The map's own line says it too.
    let not_reached = said
        .lines()
        .find(|l| l.contains("Er = 0.6: not reached on the map"))
        .expect(&said);
    assert!(
        not_reached.ends_with(&format!("; unreachable within the map: {nearest}")),
        "{not_reached}"
    );
    // The regression note no longer vouches for answers beyond its pairs.
    assert!(
        said.contains("its answers, within its pairs' Er and the map, are a smooth fit's"),
        "{said}"
    );
}

/// An answer inside the map that re-simulates within its tolerance stays
/// the answer it was (the bundled study's Er = 0.13 s: "RBF answer:
/// (493.2, 526.1) N/deg, Er 0.129662 re-simulated (-0.26 %)"), typed
/// `answer`; and a target the map reaches but the network does not (Er =
/// 0.45 s, past the pairs' 0.363 s) is refused with the map's own curve
/// named as its answer.
#[test]
fn an_rbf_answer_inside_the_map_within_its_tolerance_stands() {
    let (said, inverse, _) = studied(&coarse_study_for("0.13"));
    let rbf = &inverse["targets"][0]["rbf"];
    assert_eq!(rbf["status"], "answer", "{rbf}");
    assert_eq!(rbf["refused_for"], serde_json::json!([]), "{rbf}");
    let (kf, kr) = (
        rbf["k_front"].as_f64().unwrap(),
        rbf["k_rear"].as_f64().unwrap(),
    );
    let er = rbf["er_resimulated"].as_f64().unwrap();
    assert!((200.0..=700.0).contains(&kf) && (220.0..=720.0).contains(&kr));
    assert!((er - 0.13).abs() <= 0.005, "{er}");
    assert_eq!(inverse["targets"][0]["map_reach"]["target"], "within");
    let line = said
        .lines()
        .find(|l| l.starts_with("    RBF answer: "))
        .expect(&said);
    assert!(
        line.starts_with(&format!(
            "    RBF answer: ({kf:.1}, {kr:.1}) N/deg, Er {er:.6} re-simulated ("
        )) && line.ends_with(
            "; from the network as a regression: trust it as far as its re-simulated Er"
        ),
        "{line}"
    );
    let (said, inverse, _) = studied(&coarse_study_for("0.45"));
    let t = &inverse["targets"][0];
    assert_eq!(t["map_reach"]["target"], "within", "{t}");
    assert!(t["best"].is_object(), "{t}");
    assert_eq!(t["rbf"]["status"], "refused", "{t}");
    let line = said
        .lines()
        .find(|l| l.starts_with("    RBF answer: "))
        .expect(&said);
    assert!(
        line.contains("; the map reaches Er 0.45 (its Er spans ")
            && line.ends_with("): the best combination on its curve, above, answers it"),
        "{line}"
    );
}

/// The bundled Wang & Liang sedan step with `steer` (rad), simulated: its
/// words, metrics.json and history.csv's (t, yaw rate).
fn sedan_at(steer: &str) -> (String, serde_json::Value, Vec<(f64, f64)>) {
    let text = bundled_scenario("sedan_step.toml");
    let line = text.lines().find(|l| l.starts_with("steer = ")).unwrap();
    let dir = scratch(&[("s.toml", &text.replace(line, &format!("steer = {steer}")))]);
    let o = run_in(dir.path(), &["simulate", "s.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = dir.path().join("o");
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = history.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let r = head.iter().position(|h| *h == "yaw_rate").unwrap();
    let rows = lines
        .map(|l| {
            let c: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
            (c[0], c[r])
        })
        .collect();
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        read_json(&out.join("metrics.json")),
        rows,
    )
}

/// Each signed number of degrees in `text`, in order.
fn degrees(text: &str) -> Vec<f64> {
    text.split('°')
        .filter_map(|part| {
            let n: String = part
                .chars()
                .rev()
                .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-'))
                .collect();
            n.chars().rev().collect::<String>().parse().ok()
        })
        .collect()
}

/// A −0.5 rad step's front slip reaches −49.5° and was said "past its
/// tyres' peak at 38.0°": each peak is now said with its slip's sign, so
/// the −0.5 rad run's axle words are the +0.5 rad run's mirrored (every
/// angle negated, magnitudes equal), and every angle of the −0.5 rad
/// run's axle words is negative.
#[test]
fn a_peak_slip_is_said_with_its_slips_sign() {
    let axle_words = |said: &str| -> Vec<String> {
        said.lines()
            .filter(|l| l.contains("axle's slip angle reaches"))
            .map(str::to_string)
            .collect()
    };
    let (left, _, _) = sedan_at("-0.5");
    let (right, _, _) = sedan_at("0.5");
    let (left, right) = (axle_words(&left), axle_words(&right));
    assert_eq!(left.len(), 2, "{left:?}");
    assert_eq!(right.len(), 2, "{right:?}");
    for (l, r) in left.iter().zip(&right) {
        assert!(l.contains("slip angle reaches -"), "{l}");
        assert!(l.contains("peak at -"), "{l}");
        let (dl, dr) = (degrees(l), degrees(r));
        assert!(dl.len() >= 4, "{l}");
        // "beyond 15°" is the threshold, unsigned in both.
        let signed: Vec<f64> = dl.iter().copied().filter(|d| *d != 15.0).collect();
        assert!(signed.iter().all(|d| *d < 0.0), "{l}");
        let mirrored: Vec<f64> = dr
            .iter()
            .map(|d| if *d == 15.0 { 15.0 } else { -d })
            .collect();
        assert_eq!(dl, mirrored, "{l}\n{r}");
    }
}

/// The 0.5 rad step's yaw rate spreads 22 % of its step (a deviation about
/// the steady window's mean) while its values there span 72 % of it: the
/// gain was said "off by up to about 22 %". Since session 113 (settle48)
/// the yaw rate is read as what it is, a decaying swing (a period of about
/// 3 s): the warning says the swing left at the window about its centre
/// (checked against history.csv: at least half the window's range, and
/// beyond its deviation), and no bound is claimed.
#[test]
fn an_unsettled_yaw_rates_spread_is_said_as_a_deviation_not_a_bound() {
    let (said, metrics, rows) = sedan_at("0.5");
    let end = rows.last().unwrap().0;
    let window: Vec<f64> = rows
        .iter()
        .filter(|r| r.0 >= end - 1.0 - 1e-9)
        .map(|r| r.1)
        .collect();
    let mean = window.iter().sum::<f64>() / window.len() as f64;
    let rms = (window.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / window.len() as f64).sqrt();
    let (lo, hi) = window
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    // From rest: the step is the window's mean.
    let (spread, range) = (rms / mean, (hi - lo) / mean);
    // A deviation is at most half the range (two values alone reach it).
    assert!(range > 2.0 * spread, "{range} vs {spread}");
    let yaw = &metrics["settling"]["yaw_rate"];
    assert_eq!(yaw["verdict"], "oscillating", "{yaw}");
    let swing = yaw["amplitude"].as_f64().unwrap();
    // The swing left at the window's start bounds the window's half range
    // (the swing decays) and exceeds its deviation.
    assert!(
        swing >= 0.5 * range - 0.01 && swing > spread,
        "{swing} vs {range} {spread}"
    );
    let period = yaw["period"].as_f64().unwrap();
    assert!((2.5..3.5).contains(&period), "{yaw}");
    let gain = metrics["yaw_rate_gain"].as_f64().unwrap();
    let warning = said
        .lines()
        .find(|l| l.contains("the response has not settled in the steady window"))
        .expect(&said);
    assert!(!warning.contains("off by up to"), "{warning}");
    assert!(
        warning.contains(&format!(
            "it swings {} % of its step about that centre at the steady window",
            handling::format::significant(100.0 * swing, 2)
        )),
        "{warning}"
    );
    assert!(
        warning.contains(&format!(
            "the yaw-rate gain, {gain:.4} 1/s, is no steady-state gain"
        )),
        "{warning}"
    );
}
