//! What the third fresh-eyes check found: results that do not apply said
//! so (a slide, a crawl, a filter slower than the response), every bad row
//! of a points file in one error, a subnormal load, and names meant as
//! words of a known one. Each test one finding, run as a user runs it.

use super::*;

/// `simulate <file> --out <its folder>/out`.
fn simulated(file: &Path) -> Output {
    let out = file.parent().unwrap().join("out");
    run(&[
        "simulate",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A step steer of the sedan at `speed` (m/s) and `steer` (rad); the
/// terminal and metrics.json.
fn step(speed: f64, steer: f64) -> (String, serde_json::Value) {
    let manoeuvre = format!(
        "[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed}\nsteer = {steer}\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n"
    );
    let dir = scenario(VEHICLE, GIM, &manoeuvre);
    let out = dir.path().join("out");
    let o = simulated(&dir.path().join("scenario.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    (stdout(&o), read_json(&out.join("metrics.json")))
}

/// A 0.3 rad step at 80 km/h slid the car to −19° of sideslip with a
/// 504 % overshoot, and the only word was "not settled"; a step at
/// a crawl printed response times of nothing.
#[test]
fn simulate_says_when_its_step_steer_is_a_slide_a_spin_or_a_crawl() {
    // The bundled sedan (its Gim tyres) stepped to 0.3 rad, as the user did.
    let sedan = fs::read_to_string(root().join("scenarios/sedan_step.toml"))
        .unwrap()
        .replace("steer = 0.0174533", "steer = 0.3")
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("s.toml", &sedan)]);
    let out = dir.path().join("out");
    let o = simulated(&dir.path().join("s.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    assert!(
        said.contains("warning: the steady sideslip is -18.8°, beyond 10°: the car is sliding"),
        "{said}"
    );
    assert!(
        said.contains("warning: the yaw rate overshoots its steady value by 504 %"),
        "{said}"
    );
    let warnings = read_json(&out.join("metrics.json"))["warnings"].clone();
    // The slide and the spin, each axle past its peak, the response not
    // settled in the steady window, and the friction limit it ends at.
    assert_eq!(warnings.as_array().map(Vec::len), Some(6), "{warnings}");
    assert!(
        warnings
            .to_string()
            .contains("the car turns at its friction limit"),
        "{warnings}"
    );
    assert!(
        warnings
            .to_string()
            .contains("the response has not settled"),
        "{warnings}"
    );
    assert!(
        said.contains("warning: the front axle's slip angle reaches 48.1° at t = 3.86 s (beyond 15° from t = 1.09 s)"),
        "{said}"
    );
    // A car on stiffer tyres at the same step: grip regained, a spin-like peak.
    let (said, _) = step(22.2222, 0.3);
    assert!(
        said.contains("warning: the yaw rate overshoots its steady value by 114 %"),
        "{said}"
    );
    assert!(!said.contains("sliding"), "{said}");
    let (said, _) = step(1.0, 0.01);
    assert!(
        said.contains("warning: the step is at 1.00 m/s, below 5 m/s (18 km/h)"),
        "{said}"
    );
    // The total variances are a crawl's geometric lags too, said as such.
    assert!(
        said.contains("neither the response times nor the total variances (E_r, E_ay, Er"),
        "{said}"
    );
    // A 1° step at 80 km/h is a handling response: no warning.
    let (said, metrics) = step(22.2222, 0.0174533);
    assert!(!said.contains("warning:"), "{said}");
    assert_eq!(metrics["warnings"], serde_json::json!([]), "{metrics}");
}

/// `--filter-hz 0.01` smoothed a 1.2° step away and the run was blamed:
/// "no steer step … a change of 0.000026 rad".
#[test]
fn metrics_refuses_a_low_pass_slower_than_the_response() {
    let dir = tempfile::tempdir().unwrap();
    let sim = dir.path().join("sim");
    let o = run(&[
        "simulate",
        "scenarios/sedan_step.toml",
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let history = sim.join("history.csv");
    let o = run(&["metrics", history.to_str().unwrap(), "--filter-hz", "0.01"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("`filter_hz` = 0.01: must be greater than 1")
            && e.contains("the metrics would measure the filter"),
        "{e}"
    );
    // 5 Hz is a filter that keeps the response.
    let o = run(&["metrics", history.to_str().unwrap(), "--filter-hz", "5"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A points file with a non-physical value on several rows was refused
/// one row per run, and not in row order (line 8's load before line 2's
/// slip).
#[test]
fn tyre_eval_lists_every_non_physical_row_in_file_order() {
    let points = "fz,kappa,alpha,camber,speed\n4000,1e308,0,0,20\n4000,0,0,0,1e308\n4000,0,0.01,0,20\n4000,0,1e308,0,20\n1e308,0,0,0,20\n";
    let dir = scratch(&[("points.csv", points)]);
    let out = dir.path().join("out.csv");
    let o = run(&[
        "tyre-eval",
        "tests/fixtures/tir/MagicFormula61_Parameters.tir",
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains("points.csv: 4 places refused, in file order:"),
        "{e}"
    );
    let at = |needle: &str| e.find(needle).unwrap_or_else(|| panic!("{needle} in {e}"));
    let lines = [
        at("points.csv:2:2: column `kappa`: 1e308"),
        at("points.csv:3:5: column `speed`: 1e308 m/s"),
        at("points.csv:5:3: column `alpha`: 1e308 rad"),
        at("points.csv:6:1: column `fz`: 1e308 N"),
    ];
    assert!(lines.windows(2).all(|w| w[0] < w[1]), "{e}");
    // α typed as 1.5708, or a hair past 90°, reads apart from the 90° it
    // broke (it read "1.5708 rad is outside -1.5708 to 1.5708 rad"), and
    // only the end it passes is said.
    for (alpha, said) in [
        (
            "1.5708",
            "1.5708 rad is beyond ±90° (±1.570796 rad), the largest",
        ),
        (
            "1.5707963267958966",
            "1.5707963268 rad is beyond ±90° (±1.57079632679 rad), the largest",
        ),
    ] {
        let points = format!("fz,kappa,alpha,camber,speed\n4000,0,{alpha},0,20\n");
        let dir = scratch(&[("p.csv", &points)]);
        let out = dir.path().join("o.csv");
        let o = run(&[
            "tyre-eval",
            "tests/fixtures/tir/MagicFormula61_Parameters.tir",
            dir.path().join("p.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(e.contains(said), "{e}");
    }
}

/// A Gim tyre at a subnormal load and no slip gave a non-finite force
/// (θ = K/(3μFz) infinite, times a zero slip).
#[test]
fn a_gim_tyre_at_a_load_next_to_zero_gives_no_force() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n5e-324,0,0,0,0\n5e-324,0,0.05,0,16.7\n4000,0,0,0,16.7\n4000,0,-0.05,0,16.7\n";
    let dir = scratch(&[("g.csv", points)]);
    let out = dir.path().join("o.csv");
    let o = run(&[
        "tyre-eval",
        "tyres/gim.toml",
        dir.path().join("g.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let fy = head.iter().position(|c| *c == "fy").unwrap();
    let rows: Vec<f64> = lines
        .map(|l| l.split(',').nth(fy).unwrap().parse().unwrap())
        .collect();
    assert!(rows[0] > 100.0, "{rows:?}");
    assert_eq!(rows[1], 0.0);
    assert!(rows[2].is_finite() && rows[2].abs() < 1e-300, "{rows:?}");
}

/// `kind = "sine-steer"` was answered with `step-steer`.
#[test]
fn a_known_name_given_with_words_around_it_is_suggested() {
    let dir = scenario(
        VEHICLE,
        GIM,
        "[manoeuvre]\nkind = \"sine-steer\"\nspeed = 20.0\n",
    );
    let e = simulate_err(dir.path());
    assert!(e.contains("did you mean `sine`?"), "{e}");
}

/// Pressures of 2.2 and 220 (bar and kPa) were clamped to the file's range
/// and gave a force 51 % off the one at 220000 Pa, with no word of the unit.
#[test]
fn a_pressure_in_kpa_or_bar_is_refused_at_its_cell() {
    let points = "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,2.2\n4000,0,0.05,0,20,220\n4000,0,0.05,0,20,2.3\n";
    let dir = scratch(&[("p.csv", points)]);
    let out = dir.path().join("o.csv");
    let o = run(&[
        "tyre-eval",
        "tests/fixtures/tir/MagicFormula62_Parameters.tir",
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    // Each cell in its own unit: 2.2 and 2.3 bar, 220 kPa (not the
    // column by its median in bar, which made 220 a 22 MPa pressure).
    for (cell, meant) in [
        ("p.csv:2:6", "did you mean 220000 Pa (2.2 bar), within the file's PRESMIN to PRESMAX (200000 to 400000 Pa)?"),
        ("p.csv:3:6", "did you mean 220000 Pa (220 kPa), within the file's PRESMIN to PRESMAX (200000 to 400000 Pa)?"),
        ("p.csv:4:6", "did you mean 230000 Pa (2.3 bar)"),
    ] {
        let line = e.lines().find(|l| l.contains(cell)).unwrap_or_else(|| panic!("{cell}: {e}"));
        assert!(line.contains(meant), "{line}");
    }
    // Rig data in kPa, likewise, before any fit.
    let mut rig = String::from("fz,alpha,fy,pressure\n");
    for k in -5..=5 {
        let alpha = 0.02 * f64::from(k);
        rig += &format!("4000,{alpha},{},220\n", 60_000.0 * alpha);
    }
    let dir = scratch(&[("rig.csv", &rig)]);
    let fit = dir.path().join("fit.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "linear", &fit);
    let e = refused(&o, &fit);
    assert!(e.contains("rig.csv:2:4: column `pressure`: 220 Pa"), "{e}");
}

/// A 40 Hz sweep written every 0.02 s: rows at 50 Hz drew the steer as
/// slow beating and a yaw rate that decays, without a word.
#[test]
fn simulate_refuses_rows_too_coarse_for_the_steers_frequency() {
    let manoeuvre = "[manoeuvre]\nkind = \"sweep\"\nspeed = 22.2\namplitude = 0.02\nf_start = 0.1\nf_end = 40.0\nstart = 1.0\nend = 6.0\n\n[simulation]\nstep = 0.02\n";
    let dir = scenario(VEHICLE, GIM, manoeuvre);
    let path = dir.path().join("scenario.toml");
    let o = simulated(&path);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("`manoeuvre.f_end` = 40: the rows every 0.02 s ([simulation] step) sample at 50 Hz, not more than twice this frequency: the written steer and response would alias (a fast steer drawn as a slow one, or as zeros where the rows fall on its zero crossings); set step below 0.0125 s, e.g. 0.01 s, or 0.0025 s to draw the waveform"),
        "{e}"
    );
    assert!(e.contains("scenario.toml:"), "{e}");
    assert!(!dir.path().join("out").exists());
    // At the Nyquist step itself the rows can fall on the zero crossings
    // (a 10 Hz sine every 0.05 s was written as zeros): refused; the step
    // suggested runs.
    let refused_at = |text: &str| {
        let dir = scenario(VEHICLE, GIM, text);
        stderr(&simulated(&dir.path().join("scenario.toml")))
    };
    let at_nyquist = manoeuvre.replace("step = 0.02", "step = 0.0125");
    assert!(refused_at(&at_nyquist).contains("`manoeuvre.f_end` = 40: the rows every 0.0125 s"));
    let dir = scenario(
        VEHICLE,
        GIM,
        &manoeuvre.replace("step = 0.02", "step = 0.01"),
    );
    let o = simulated(&dir.path().join("scenario.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    // A sine at 30 Hz is held to the same rule, and the step it is told
    // to stay below (rounded down) is one it accepts.
    let sine = |step: &str| {
        format!("[manoeuvre]\nkind = \"sine\"\nspeed = 22.2\namplitude = 0.02\nfrequency = 30.0\nstart = 1.0\nend = 3.0\n\n[simulation]\nstep = {step}\n")
    };
    let e = refused_at(&sine("0.02"));
    assert!(
        e.contains("`manoeuvre.frequency` = 30: the rows every 0.02 s"),
        "{e}"
    );
    assert!(e.contains("set step below 0.0166 s, e.g. 0.013 s"), "{e}");
    let dir = scenario(VEHICLE, GIM, &sine("0.0166"));
    let o = simulated(&dir.path().join("scenario.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
    // A sweep run downwards: its highest frequency is at `f_start`.
    let down = manoeuvre
        .replace("f_start = 0.1", "f_start = 40.0")
        .replace("f_end = 40.0", "f_end = 0.1");
    let e = refused_at(&down);
    assert!(
        e.contains("`manoeuvre.f_start` = 40: the rows every 0.02 s"),
        "{e}"
    );
}

/// The bundled sedan scenario before its `[manoeuvre]`, its tyre paths
/// made absolute: a vehicle to write manoeuvres for.
fn sedan_head() -> String {
    let head: String = fs::read_to_string(root().join("scenarios/sedan_step.toml"))
        .unwrap()
        .lines()
        .take_while(|l| !l.starts_with("[manoeuvre]"))
        .map(|l| format!("{l}\n"))
        .collect();
    head.replace("../tyres/", &format!("{}/tyres/", root().display()))
}

/// A schedule dropping from 40 to 1 m/s in 0.5 s (8 g) and crawling for
/// 6.5 s ran without a word: the model takes the speed as given.
#[test]
fn simulate_says_when_a_schedule_brakes_past_the_tyres_grip_or_crawls() {
    let head = sedan_head();
    let schedule = |speed: &str| {
        format!("{head}[manoeuvre]\nkind = \"schedule\"\nt = [0.0, 1.0, 1.5, 8.0]\nsteer = [0.0, 0.0, 0.02, 0.02]\nspeed = {speed}\n")
    };
    // The terminal, and the height of response.png (260 px a panel, read
    // from the PNG's IHDR).
    let said_drawn = |text: String| {
        let dir = scratch(&[("s.toml", &text)]);
        let o = simulated(&dir.path().join("s.toml"));
        assert!(o.status.success(), "{}", stderr(&o));
        let png = fs::read(dir.path().join("out/response.png")).unwrap();
        let height = u32::from_be_bytes(png[20..24].try_into().unwrap());
        (stdout(&o), height)
    };
    let said = |text: String| said_drawn(text).0;
    let s = said(schedule("[40.0, 40.0, 1.0, 1.0]"));
    assert!(
        s.contains("  warning: the speed falls at 78.0 m/s² (8.0 g) from t = 1 s to 1.5 s, more than the tyres' grip on this road gives (μ·g = 9.8 m/s²)"),
        "{s}"
    );
    assert!(
        s.contains("  warning: the schedule spends 6.6 s below 5 m/s (18 km/h)"),
        "{s}"
    );
    // Braking at 0.8 g to 25 m/s: a schedule the sedan can drive.
    let (s, height) = said_drawn(schedule("[40.0, 40.0, 36.0, 25.0]"));
    assert!(!s.contains("warning"), "{s}");
    // The speed it drove is drawn under the steer: five panels, not four.
    assert_eq!(height, 5 * 260);
    assert_eq!(said_drawn(schedule("[25.0, 25.0, 25.0, 25.0]")).1, 4 * 260);
}

/// A schedule steering 0 → 0.5 rad in 1 ms at 30 m/s, and one opening
/// with its steer already applied, ran without a word: only the speed
/// was checked.
#[test]
fn simulate_says_when_a_schedule_steers_faster_than_a_steering_system_or_starts_steered() {
    let head = sedan_head();
    let said = |t: &str, steer: &str| {
        let text = format!(
            "{head}[manoeuvre]\nkind = \"schedule\"\nt = {t}\nsteer = {steer}\nspeed = [30.0, 30.0, 30.0, 30.0]\n"
        );
        let dir = scratch(&[("s.toml", &text)]);
        let o = simulated(&dir.path().join("s.toml"));
        assert!(o.status.success(), "{}", stderr(&o));
        stdout(&o)
    };
    let s = said("[0.0, 1.0, 1.001, 3.0]", "[0.0, 0.0, 0.05, 0.05]");
    assert!(
        s.contains("  warning: the steer changes at 50.0 rad/s (2865°/s at the road wheels) from t = 1 s to 1.001 s, faster than a steering system turns the wheels"),
        "{s}"
    );
    let s = said("[0.5, 1.0, 1.5, 3.0]", "[0.02, 0.02, 0.03, 0.03]");
    assert!(
        s.contains("  warning: the schedule starts with steer = 0.02 rad at t = 0.5 s, but the run starts from straight running (no yaw rate, no sideslip): it opens with an instant steer step"),
        "{s}"
    );
    // From 0, at 0.1 rad/s: a step a driver steers, nothing to say.
    let s = said("[0.0, 1.0, 1.2, 3.0]", "[0.0, 0.0, 0.02, 0.02]");
    assert!(!s.contains("warning"), "{s}");
}

/// The public `FSAE_Defaults.tir` (PKX1 = 50, PKX2 = -80: Kx/Fz = 0 at
/// dfz = 0.625, 1625 N, inside its FZMAX of 2000 N) was evaluated past that
/// load without a word: its longitudinal force there opposes the slip.
#[test]
fn tyre_eval_says_where_a_slip_stiffness_changes_sign_inside_the_loads() {
    let test = "tyre_eval_says_where_a_slip_stiffness_changes_sign_inside_the_loads";
    let Some(tir) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let points = "fz,kappa,alpha,camber,speed\n500,0.01,0.01,0,16\n1900,0.01,0.01,0,16\n";
    let dir = scratch(&[("p.csv", points)]);
    let eval = |csv: &str| {
        fs::write(dir.path().join("p.csv"), csv).unwrap();
        let _ = fs::remove_file(dir.path().join("f.csv"));
        let o = bin()
            .args([
                "tyre-eval",
                tir.to_str().unwrap(),
                "p.csv",
                "--out",
                "f.csv",
            ])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        stderr(&o)
    };
    let e = eval(points);
    let said = "warning: the longitudinal slip stiffness (the force's slope at zero slip) changes sign between fz = ";
    let at = e.find(said).unwrap_or_else(|| panic!("{e}"));
    let loads: Vec<f64> = e[at + said.len()..]
        .split(" N")
        .take(2)
        .map(|x| x.trim_start_matches(" and ").parse().unwrap())
        .collect();
    assert!(
        loads[0] <= 1625.0 && 1625.0 <= loads[1] && loads[1] - loads[0] < 50.0,
        "{e}"
    );
    // The fx written at 1900 N is against the slip, as the file says.
    let out = fs::read_to_string(dir.path().join("f.csv")).unwrap();
    let fx: f64 = out
        .lines()
        .nth(2)
        .unwrap()
        .split(',')
        .nth(5)
        .unwrap()
        .parse()
        .unwrap();
    assert!(fx < 0.0, "{out}");
    // Loads below the crossing only: nothing to say.
    let e = eval("fz,kappa,alpha,camber,speed\n500,0.01,0.01,0,16\n1500,0.01,0.01,0,16\n");
    assert!(!e.contains("changes sign"), "{e}");
}
