//! The gap map drew every part at its band's centre: three runs at 11, 12.5
//! and 14 m/s, all in the band 10–20 m/s, were one point at 15 m/s, and the
//! map could not show where in speed the gap grows. Each part is now drawn
//! at its samples' mean level, each run's share of it as a dot at the run's
//! own, and `diagnosis.json` carries both (`mean_level`, `runs`).

use crate::{diagnose_to, fs, root, run, stderr, Path};

/// The bundled sedan step as a scenario `name` driven at `speed` m/s, in
/// `dir` (its tyres named by absolute path).
fn step_at(dir: &Path, name: &str, speed: f64) -> String {
    let text = fs::read_to_string(root().join("scenarios/sedan_step.toml")).unwrap();
    let text = text
        .replace("name = \"sedan_step\"", &format!("name = \"{name}\""))
        .replace("speed = 22.2222", &format!("speed = {speed:?}"))
        .replace("\"../tyres/", &format!("\"{}/tyres/", root().display()));
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// The attribute `name` of an SVG element's text, as a number.
fn attr(element: &str, name: &str) -> Option<f64> {
    let at = element.find(&format!(" {name}=\""))? + name.len() + 3;
    element[at..].split('"').next()?.parse().ok()
}

/// The speed panel of the gap map in `report.html`: its circles (the whole
/// element text) and its numeric tick labels (anchor, x, y, value).
struct SpeedPanel {
    circles: Vec<String>,
    ticks: Vec<(String, f64, f64, f64)>,
}

fn speed_panel(page: &str) -> SpeedPanel {
    let at = page
        .find("id=\"gap-map\"")
        .expect("the page holds the gap map");
    let svg = &page[at..at + page[at..].find("</svg>").unwrap()];
    // The speed panel is the map's last: everything below its title.
    let title = svg.find(">\nHeld-out gap by speed").expect("a speed panel");
    let top = attr(&svg[svg[..title].rfind("<text ").unwrap()..title], "y").unwrap();
    let circles = svg
        .split("<circle ")
        .skip(1)
        .map(|e| format!(" {}", &e[..e.find("/>").unwrap()]))
        .filter(|e| attr(e, "cy").unwrap() > top)
        .collect();
    let ticks = svg
        .split("<text ")
        .skip(1)
        .filter_map(|e| {
            let (head, body) = e.split_once('>')?;
            let value: f64 = body.split("</text>").next()?.trim().parse().ok()?;
            let head = format!(" {head}");
            let anchor = head.split("text-anchor=\"").nth(1)?.split('"').next()?;
            let (x, y) = (attr(&head, "x")?, attr(&head, "y")?);
            (y > top).then(|| (anchor.to_string(), x, y, value))
        })
        .collect();
    SpeedPanel { circles, ticks }
}

impl SpeedPanel {
    /// The pixel of data value `v` on the axis whose tick labels are set
    /// with `anchor` (`middle`: x, below the chart; `end`: y, left of it),
    /// from its first and last tick.
    fn pixel(&self, anchor: &str, v: f64) -> f64 {
        let along = |t: &(String, f64, f64, f64)| if anchor == "middle" { t.1 } else { t.2 };
        let mut ticks: Vec<&(String, f64, f64, f64)> =
            self.ticks.iter().filter(|t| t.0 == anchor).collect();
        ticks.sort_by(|a, b| a.3.total_cmp(&b.3));
        let (a, b) = (ticks[0], ticks[ticks.len() - 1]);
        along(a) + (v - a.3) * (along(b) - along(a)) / (b.3 - a.3)
    }

    /// The centres of the circles of radius `r` in the chart (left of the
    /// key's column, the figure's last 200 of its 640 px) whose `paint`
    /// (`fill` or `stroke`) is `colour`.
    fn marks(&self, r: f64, paint: &str, colour: &str) -> Vec<(f64, f64)> {
        self.circles
            .iter()
            .filter(|c| attr(c, "r") == Some(r) && c.contains(&format!(" {paint}=\"{colour}\"")))
            .map(|c| (attr(c, "cx").unwrap(), attr(c, "cy").unwrap()))
            .filter(|(x, _)| *x < 440.0)
            .collect()
    }
}

#[test]
fn the_gap_map_draws_each_run_at_its_own_speed_inside_a_band() {
    let dir = tempfile::tempdir().unwrap();
    let speeds = [11.0, 12.5, 14.0];
    let names = ["step_11_0", "step_12_5", "step_14_0"];
    let campaign = dir.path().join("c");
    let mut args = vec!["synth", "--effects", "none", "--seed", "1"];
    let scenarios: Vec<String> = names
        .iter()
        .zip(speeds)
        .map(|(n, v)| step_at(dir.path(), n, v))
        .collect();
    for s in &scenarios {
        args.extend(["--drive", s.as_str()]);
    }
    args.extend(["--out", campaign.to_str().unwrap()]);
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    // The driven runs alone: every sample in the band 10–20 m/s.
    for e in fs::read_dir(campaign.join("runs")).unwrap() {
        let path = e.unwrap().path();
        let stem = path.file_stem().unwrap().to_str().unwrap().to_string();
        if !names.contains(&stem.as_str()) {
            fs::remove_file(path).unwrap();
        }
    }
    let out = dir.path().join("out");
    let (_, d) = diagnose_to(&campaign, &out);

    // The figure (report.html's gap map, the PNG's drawing): the yaw
    // rate's pooled ring at the runs' mean speed, 12.5 m/s (the band's
    // centre, 15, lies 2.5 m/s right of it), and a dot per run at its own
    // speed and held-out RMS over the noise floor.
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    let panel = speed_panel(&page);
    let blue = "#1F77B4";
    let rows = d["shrinkage"].as_array().unwrap();
    let row = rows
        .iter()
        .find(|r| r["channel"] == "yaw_rate" && r["part"] == "speed 10–20 m/s")
        .expect("a yaw-rate row for the band 10–20 m/s");
    let floor = row["noise_floor"].as_f64().unwrap();
    let rings = panel.marks(4.0, "stroke", blue);
    assert_eq!(rings.len(), 1, "{rings:?}");
    let (x, y) = rings[0];
    let (want_x, centre) = (panel.pixel("middle", 12.5), panel.pixel("middle", 15.0));
    assert!(
        (x - want_x).abs() <= 1.0,
        "ring at {x} px: 12.5 m/s is {want_x} px, 15 m/s {centre} px"
    );
    let want_y = panel.pixel("end", row["before"].as_f64().unwrap() / floor);
    assert!(
        (y - want_y).abs() <= 1.0,
        "ring at {y} px, its RMS at {want_y} px"
    );
    let mut dots = panel.marks(2.0, "fill", blue);
    dots.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert_eq!(dots.len(), 3, "{dots:?}");
    let shares = row["runs"].as_array().expect("the row's runs");
    for ((name, speed), (x, y)) in names.iter().zip(speeds).zip(&dots) {
        let share = shares
            .iter()
            .find(|r| r["run"].as_str().unwrap().ends_with(&format!("{name}.csv")))
            .unwrap_or_else(|| panic!("{name} missing from {shares:?}"));
        let want_x = panel.pixel("middle", speed);
        assert!(
            (x - want_x).abs() <= 1.0,
            "{name}: dot at {x} px, {speed} m/s at {want_x} px"
        );
        let want_y = panel.pixel("end", share["before"].as_f64().unwrap() / floor);
        assert!(
            (y - want_y).abs() <= 1.0,
            "{name}: dot at {y} px, its RMS at {want_y} px"
        );
        // Driven at constant speed: the run's level is its speed, exactly.
        let level = share["mean_level"].as_f64().unwrap();
        assert!((level - speed).abs() < 1e-9, "{name}: {level}");
        assert_eq!(share["samples"], 151, "{share}");
    }

    // The JSON: every channel's band at the runs' mean speed, and the
    // per-run table of gap.runs at each run's own.
    for r in rows.iter().filter(|r| r["part"] == "speed 10–20 m/s") {
        let level = r["mean_level"].as_f64().unwrap();
        assert!((level - 12.5).abs() < 1e-9, "{r}");
    }
    for (name, speed) in names.iter().zip(speeds) {
        let run = d["gap"]["runs"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["run"].as_str().unwrap().ends_with(&format!("{name}.csv")))
            .unwrap();
        let regimes = run["channels"][0]["regimes"].as_array().unwrap();
        let band = regimes
            .iter()
            .find(|p| p["name"] == "speed 10–20 m/s")
            .unwrap();
        let level = band["mean_level"].as_f64().unwrap();
        assert!((level - speed).abs() < 1e-9, "{band}");
    }
}

/// A run saved again with CRLF line endings (a copy opened and saved on
/// Windows) differs from its twin in every line's bytes and was not
/// refused: the runs are now compared as read, not as bytes.
#[test]
fn a_copy_of_a_run_saved_with_crlf_line_endings_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let c = crate::synth_campaign(dir.path(), "c", &[]);
    let runs = c.join("runs");
    let original = runs.join("step_060kph_2ms2.csv");
    let text = fs::read_to_string(&original).unwrap();
    assert!(!text.contains('\r'));
    let crlf = text.replace('\n', "\r\n");
    fs::write(runs.join("zz_copy.csv"), &crlf).unwrap();
    let out = dir.path().join("out");
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "a CRLF copy was diagnosed");
    let e = stderr(&o);
    assert!(
        e.contains(&format!(
            "the run {} is a copy of {} (the same samples), ",
            runs.join("zz_copy.csv").display(),
            original.display()
        )),
        "{e}"
    );
    assert!(
        e.contains("counts the same evidence twice; select one of them"),
        "{e}"
    );
    assert!(!out.exists());
}
