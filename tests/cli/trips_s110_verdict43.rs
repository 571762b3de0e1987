//! Session 110, `verdict43`: round 43's findings on what the diagnosis's
//! verdict and page say, run as the tester ran them (a synthetic campaign
//! with logger offsets, `handling synth --effects sensor_bias --seed 4`,
//! edited, then `handling diagnose`): a set whose added effect sits at its
//! off value is not named and a class whose ranges hold the axles is (2);
//! the gap's steady offset matching the standstills' names `sensor_bias`
//! to add (4); a channel stated below its scatter says what judges its gap
//! where its floor is shown (5); the candidate table's J column holds one
//! measure (7).

use super::*;

/// The tester's synthetic campaign (logger offsets 0.008 rad/s, 0.2 m/s²,
/// 0.004 rad; seed 4) in `dir/name`, its `[tyres]` table replaced by
/// `tyres` and `extra` appended to its closing `[diagnose]` table.
fn offsets_campaign(dir: &Path, name: &str, tyres: &str, extra: &str) -> PathBuf {
    let c = synth_campaign(dir, name, &["--effects", "sensor_bias", "--seed", "4"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    let rig = "[tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n";
    assert!(text.contains(rig), "{text}");
    if tyres != rig {
        // No rig data: the axles are identified from the runs (a rig file
        // in the folder is read whether or not the campaign names it).
        fs::remove_file(c.join("tyre_rig.csv")).unwrap();
    }
    let text = text.replacen(rig, tyres, 1);
    fs::write(&v, format!("{text}{extra}")).unwrap();
    c
}

/// The terminal line starting with `start` (after its indent).
fn line<'a>(said: &'a str, start: &str) -> &'a str {
    said.lines()
        .find(|l| l.trim_start().starts_with(start))
        .unwrap_or_else(|| panic!("no line {start:?} in\n{said}"))
}

/// (2) Stated as `truck` without a rig, the pair sensor_bias+sensor_delay
/// was the verdict with `sensor_delay.delay = 0.0000 s (at its physical
/// limit)`: its gain over sensor_bias alone (4.717 → 2.789) came from the
/// axles refitted, not the delay. The delay contributes nothing, so the
/// pair reduces to sensor_bias (said on its row), which removes too little
/// to be a verdict; and the base's axles (outside truck's 95 % ranges,
/// inside road's) name road as the class to check. Stated as `road` (the
/// truth's class), sensor_bias is the verdict and no class is named.
#[test]
fn a_set_whose_added_effect_sits_off_is_not_named_and_the_class_that_holds_the_axles_is() {
    let dir = tempfile::tempdir().unwrap();
    let effects = "effects = [\"sensor_bias\", \"sensor_delay\"]\n";
    let truck = offsets_campaign(dir.path(), "truck", "[tyres]\nclass = \"truck\"\n", effects);
    let road = offsets_campaign(dir.path(), "road", "[tyres]\nclass = \"road\"\n", effects);
    let [(said, d), (road_said, road_d)]: [(String, serde_json::Value); 2] =
        diagnosed_together(&[truck.clone(), road])
            .try_into()
            .unwrap();
    // No verdict names the delay: every set that holds it at off is
    // passed over, and its row says why.
    let named = verdict_of(&d);
    assert!(!named.contains(&"sensor_delay".to_string()), "{said}");
    let inert: Vec<&serde_json::Value> = d["ranking"]
        .as_array()
        .unwrap()
        .iter()
        .chain(d["combinations"].as_array().unwrap())
        .filter(|r| {
            r["warning_details"]
                .as_array()
                .is_some_and(|w| w.iter().any(|w| w["kind"] == "contributes_nothing"))
        })
        .collect();
    for r in &inert {
        let delay = r["parameters"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["name"] == "sensor_delay.delay")
            .expect("an inert row holds the delay");
        assert_eq!(delay["value"], 0.0, "{r}");
    }
    let pair = inert
        .iter()
        .find(|r| r["effect"] == "sensor_bias+sensor_delay")
        .unwrap_or_else(|| panic!("the pair's row is said to reduce\n{said}"));
    let j = pair["heldout_error_after"].as_f64().unwrap();
    let row = line(&said, "sensor_bias+sensor_delay");
    assert!(row.contains(&format!("{j:.3}")), "{row}");
    let warning = "sensor_delay contributes nothing (every parameter at its off value, within its standard error): the set reduces to sensor_bias";
    assert!(said.contains(warning), "{said}");
    // Its J is not the verdict's.
    let after = d["verdict"]["heldout_error_after"].as_f64();
    assert_ne!(after, Some(j), "{said}");
    // The base's axles lie outside truck's 95 % ranges: road holds them.
    let axles = &d["base"]["axles"]["parameters"];
    let front = axles[0]["value"].as_f64().unwrap();
    assert!(front > 10.0 && front < 35.0, "{front}");
    let class = &d["verdict"]["tyre_class"];
    assert_eq!(class["stated"], "truck", "{}", d["verdict"]);
    assert_eq!(class["holding"][0], "road", "{}", d["verdict"]);
    let verdict = line(&said, "verdict:");
    assert!(
        verdict.contains("lie outside the prior of `[tyres] class = \"truck\"` (cornering coefficient 4–10 1/rad) but inside the ranges of road"),
        "{verdict}"
    );
    // Stated as the truth's class: sensor_bias explains it, no class.
    assert_eq!(verdict_of(&road_d), ["sensor_bias"], "{road_said}");
    assert!(road_d["verdict"]
        .get("tyre_class")
        .is_none_or(|c| c.is_null()));
    assert!(!road_said.contains("[tyres] class"), "{road_said}");
}

/// (7) The `J after` column held held-out J for ranked candidates and
/// in-sample J for screened ones (`sensor_bias 1.805` held out above a
/// screened `sensor_bias+sensor_delay 1.418` in sample). Screened rows put
/// "—" in the column and their in-sample J, named, at the end of the line.
#[test]
fn the_j_column_holds_held_out_errors_only_and_a_screened_rows_in_sample_j_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let effects = "effects = [\"sensor_bias\", \"sensor_delay\"]\n";
    let c = offsets_campaign(dir.path(), "road", "[tyres]\nclass = \"road\"\n", effects);
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    let screened = d["screened"].as_array().unwrap();
    assert!(!screened.is_empty(), "{said}");
    for s in screened {
        let effect = s["effect"].as_str().unwrap();
        let j = s["insample_error_after"].as_f64().unwrap();
        let row = said
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{effect} ")))
            .unwrap_or_else(|| panic!("{effect} in\n{said}"));
        let cells: Vec<&str> = row.split_whitespace().collect();
        assert_eq!(cells[1], "—", "{row}");
        assert!(row.contains(&format!("J in sample {j:.3}")), "{row}");
    }
    // Ranked rows keep their held-out J in the column.
    let r = ranked(&d, "sensor_bias");
    let row = line(&said, "sensor_bias ");
    let j = r["heldout_error_after"].as_f64().unwrap();
    assert_eq!(
        row.split_whitespace().nth(1),
        Some(&*format!("{j:.3}")),
        "{row}"
    );
}

/// A deterministic normal deviate stream (an LCG through Box–Muller), for
/// standstill noise the test writes.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        let mut u = || {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let (a, b) = (u(), u());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}

/// `run` (a synthetic run: `t,speed,steer,yaw_rate,ay,beta`, 100 Hz) with
/// 5 s of standstill before it whose sensors read `offsets` (yaw rate,
/// ay, beta) plus noise of the synthetic runs' own size, the first 2 s of
/// the run ramping up from rest (as the tester's log did).
fn with_standstill(run: &Path, offsets: [f64; 3], noise: &mut Noise) {
    let text = fs::read_to_string(run).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap();
    assert_eq!(head, "t,speed,steer,yaw_rate,ay,beta");
    let mut rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let (t0, v0) = (rows[0][0], rows[0][1]);
    for (k, r) in rows.iter_mut().take(200).enumerate() {
        r[1] = v0 * k as f64 / 200.0;
    }
    let sigma = [0.003, 0.05, 0.002];
    let mut out = vec![head.to_string()];
    for k in 0..500 {
        let t = t0 - (500 - k) as f64 * 0.01;
        let s: Vec<String> = (0..3)
            .map(|i| format!("{}", offsets[i] + sigma[i] * noise.next()))
            .collect();
        out.push(format!("{t:.2},0,0,{}", s.join(",")));
    }
    out.extend(rows.iter().map(|r| {
        r.iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(",")
    }));
    fs::write(run, out.join("\n") + "\n").unwrap();
}

/// The offsets campaign with standstills before two of its runs reading
/// `offsets`, its candidates narrowed to a delay and a tyre lag.
fn standstill_campaign(dir: &Path, name: &str, offsets: [f64; 3]) -> PathBuf {
    let rig = "[tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n";
    let effects = "effects = [\"sensor_delay\", \"relaxation_length\"]\n";
    let c = offsets_campaign(dir, name, rig, effects);
    let mut noise = Noise(43);
    for run in ["step_060kph_2ms2.csv", "step_100kph_2ms2.csv"] {
        with_standstill(&c.join("runs").join(run), offsets, &mut noise);
    }
    c
}

/// (4) The standstills measured `ay offset 0.2028 ± 0.0018 m/s²`, the
/// ay gap's steady offset was −0.1917 m/s², and with sensor_bias not a
/// candidate the verdict advised trying every effect. Where they match
/// (opposite signs, within three combined standard errors) the verdict
/// names sensor_bias to add; where the standstills read no offset, it
/// does not.
#[test]
fn a_steady_offset_the_standstills_measured_names_sensor_bias_to_add() {
    let dir = tempfile::tempdir().unwrap();
    let biased = standstill_campaign(dir.path(), "biased", [0.008, 0.2, 0.004]);
    let clean = standstill_campaign(dir.path(), "clean", [0.0, 0.0, 0.0]);
    let [(said, d), (clean_said, clean_d)]: [(String, serde_json::Value); 2] =
        diagnosed_together(&[biased, clean]).try_into().unwrap();
    assert!(said.contains("calibration: ay offset 0.1"), "{said}");
    let offsets = d["verdict"]["narrowed"]["offsets"].as_array().unwrap();
    let ay = offsets
        .iter()
        .find(|o| o["channel"] == "ay")
        .unwrap_or_else(|| panic!("{}", d["verdict"]));
    let (residual, measured) = (
        ay["residual"].as_f64().unwrap(),
        ay["measured"].as_f64().unwrap(),
    );
    // Opposite signs, each about the truth's 0.2 m/s².
    assert!(residual < -0.15 && measured > 0.15, "{ay}");
    let se = ay["residual_std_error"]
        .as_f64()
        .unwrap()
        .hypot(ay["measured_std_error"].as_f64().unwrap());
    assert!((residual + measured).abs() <= 3.0 * se, "{ay}");
    let verdict = line(&said, "verdict:");
    assert!(
        verdict.contains("the ay gap's steady offset -0.")
            && verdict.contains("matches the standstills' ay offset 0.")
            && verdict.contains(": add sensor_bias to [diagnose] effects"),
        "{verdict}"
    );
    let page = fs::read_to_string(dir.path().join("biased/out/report.html")).unwrap();
    assert!(
        page.contains(": add sensor_bias to [diagnose] effects"),
        "{page}"
    );
    // Standstills that read no offset point at nothing.
    assert!(clean_said.contains("calibration:"), "{clean_said}");
    assert!(!clean_said.contains("add sensor_bias"), "{clean_said}");
    let none = &clean_d["verdict"]["narrowed"]["offsets"];
    assert!(none.as_array().is_some_and(|o| o.is_empty()), "{none}");
}

/// (5) `[channels] ay = 0.01`, below the channel's scatter: the note said
/// "it is weighted by 0.061 m/s² instead" while the trust line said
/// `ay 0.0100 m/s² (stated)` and the before → after row `(noise floor
/// 0.0100)`. Each now says that the stated value judges the gap and the
/// fits weigh it by their scale, with the numbers of `diagnosis.json`'s
/// noise table; the page's cell says the same. The yaw rate, stated above
/// its scatter, says nothing of the kind.
#[test]
fn a_channel_stated_below_its_scatter_says_what_judges_its_gap_where_its_floor_is_shown() {
    let dir = tempfile::tempdir().unwrap();
    let extra = "effects = [\"sensor_bias\", \"sensor_delay\"]\n\n[channels]\nay = 0.01\nyaw_rate = 0.003\n";
    let rig = "[tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n";
    let c = offsets_campaign(dir.path(), "stated", rig, extra);
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    let noise = d["gap"]["noise"].as_array().unwrap();
    let ay = noise.iter().find(|n| n["channel"] == "ay").unwrap();
    let f = |k: &str| ay[k].as_f64().unwrap();
    assert_eq!(f("noise_floor"), 0.01);
    assert!(f("scatter") > 0.04 && f("scale") > f("scatter"), "{ay}");
    let judged = format!(
        "below its scatter {:.4} m/s²: its gap is judged against the stated 0.0100 m/s², the fits weigh it by {:.4} m/s²",
        f("scatter"),
        f("scale")
    );
    let trust = line(&said, "channels trusted to:");
    assert!(
        trust.contains(&format!("ay 0.0100 m/s² (stated), {judged}")),
        "{trust}"
    );
    assert!(trust.contains("yaw_rate 0.0030 rad/s (stated);"), "{trust}");
    let row = line(&said, "ay        ");
    assert!(
        row.contains(&format!("(noise floor 0.0100, stated, {judged}):")),
        "{row}"
    );
    let yaw = line(&said, "yaw_rate  ");
    assert!(!yaw.contains("below its scatter"), "{yaw}");
    let note = line(&said, "note: [channels] ay = 0.01");
    assert!(
        note.contains("it is weighted by 0.0")
            && note.contains("its gap is judged against the stated 0.01 m/s² all the same"),
        "{note}"
    );
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        page.contains(&escaped(&format!("0.0100 (stated, {judged})"))),
        "{page}"
    );
}
