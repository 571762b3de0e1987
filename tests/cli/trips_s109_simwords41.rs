//! What `simulate` said of a step's trend and speed (session 109): round
//! 40's step sized for ay = 9 m/s² on friction 1 was said to head 0.63
//! m/s² beyond a mean of 9.39 m/s² (read as 10.02 m/s², past the 9.81
//! m/s² its tyres give; its trend in fact falls); a step at `speed = 80`
//! (meant as km/h) ran at 288 km/h without a word; and two rechecks: a
//! 97° steer step, a step of nothing.

use super::*;

/// The bundled sedan (Gim tyres of friction 1, a = 1.11, b = 1.67 m) with
/// `manoeuvre`, in `dir`.
fn sedan(dir: &Path, name: &str, manoeuvre: &str) -> PathBuf {
    let text = bundled_scenario("sedan_step.toml");
    let head = &text[..text.find("[manoeuvre]").unwrap()];
    written(dir, name, &format!("{head}{manoeuvre}"))
}

fn simulate(scenario: &Path, out: &Path) -> String {
    succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

/// The number just before `unit` in `said` at or after `from`.
fn number_before(said: &str, from: &str, unit: &str) -> f64 {
    let at = &said[said.find(from).unwrap_or_else(|| panic!("{from}: {said}"))..];
    let head = &at[..at.find(unit).unwrap()];
    head.trim_end().rsplit(' ').next().unwrap().parse().unwrap()
}

/// Round 40's `s_ay9.toml`: the sliding car's lateral acceleration falls
/// across its steady window (9.65 m/s² in its first half second, 9.24 in
/// its last), and its trend, said to head "0.63 m/s² beyond" a mean of
/// 9.39 m/s² (read as 10.02 m/s², past the 9.81 m/s² its tyres give), is
/// said to head back below it; the history shows the fall.
#[test]
fn a_sliding_cars_falling_trend_is_said_to_fall_not_to_pass_the_grip() {
    let dir = tempfile::tempdir().unwrap();
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nlateral_acceleration = 9.0\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n";
    let path = sedan(dir.path(), "s_ay9.toml", step);
    let out = dir.path().join("out");
    let said = simulate(&path, &out);
    let asked = line_with(
        &said,
        "the step was sized for a steady lateral acceleration of 9 m/s²",
    );
    assert!(!asked.contains("beyond that mean"), "{asked}");
    let by = number_before(asked, "its trend heads", "m/s² back below that mean");
    let m = read_json(&out.join("metrics.json"));
    let ay = &m["settling"]["ay"];
    assert_eq!(ay["verdict"], "drifting", "{m}");
    assert_eq!(ay["rising"], false, "{m}");
    let steady = m["ay_steady"].as_f64().unwrap();
    let heads = ay["heads"].as_f64().unwrap();
    assert!(
        (by - heads * steady.abs()).abs() <= 0.005,
        "{by} {heads} {steady}"
    );
    // The history's own: the steady window's (the last second) second
    // half below its first.
    let text = fs::read_to_string(out.join("history.csv")).unwrap();
    let rows: Vec<[f64; 2]> = text
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[5]]
        })
        .collect();
    let mean = |from: f64, to: f64| {
        let v: Vec<f64> = rows
            .iter()
            .filter(|r| r[0] >= from && r[0] < to)
            .map(|r| r[1])
            .collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    assert!(
        mean(5.5, 6.0) < mean(5.0, 5.5) - 0.1,
        "{} {}",
        mean(5.0, 5.5),
        mean(5.5, 6.0)
    );
    let settling = line_with(&said, "the response has not settled");
    assert!(
        settling.contains("the lateral acceleration is still drifting: the trend across its steady window heads 6.7 % of its step back below its window's mean"),
        "{settling}"
    );
}

/// The line of `said` holding `words`.
fn line_with<'a>(said: &'a str, words: &str) -> &'a str {
    said.lines()
        .find(|l| l.contains(words))
        .unwrap_or_else(|| panic!("{words}: {said}"))
}

/// A linear oversteering car (a = 1.59, b = 1.19 m) stepped at 35 m/s,
/// near its critical speed of 38.0 m/s, for ay = 7.8 m/s²: 7 s after the
/// step its lateral acceleration averages 7.10 m/s², still rising, and
/// its trend heads to the 7.8 m/s² its steer was solved for (the linear
/// model's steady state). On a road of friction 0.76 (μ·g = 7.453 m/s²,
/// which linear tyres ignore: the same run) that trend would pass μ·g,
/// and is said to climb toward it, the room left adding up to it; a
/// measured copy's words say the trend is the window's carried on.
#[test]
fn a_rising_trend_that_would_pass_the_road_s_grip_is_said_to_climb_toward_it() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = root().join("tyres/linear.toml");
    let car = |friction: f64| {
        format!("[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.59\nb = 1.19\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n\n[tyres]\nfront = \"{t}\"\nrear = \"{t}\"\n\n[road]\nfriction = {friction}\n\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 35.0\nlateral_acceleration = 7.8\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n", t = tyre.display())
    };
    let out = dir.path().join("out");
    let said = simulate(&written(dir.path(), "over.toml", &car(1.0)), &out);
    let asked = line_with(
        &said,
        "the step was sized for a steady lateral acceleration of 7.8 m/s²",
    );
    let mean = number_before(asked, "averages", "m/s²");
    let by = number_before(asked, "its trend heads", "m/s² beyond that mean");
    // Each printed to 0.01 m/s²: the sum to 0.01.
    assert!((mean + by - 7.8).abs() <= 0.0101, "{mean} + {by}");
    // The same run on a road of friction 0.76.
    let said = simulate(&written(dir.path(), "over.toml", &car(0.76)), &out);
    let asked = line_with(
        &said,
        "the step was sized for a steady lateral acceleration of 7.8 m/s²",
    );
    assert!(
        asked.contains(
            "is still moving: its trend climbs toward the 7.45 m/s² (μ·g) this road can give, "
        ),
        "{asked}"
    );
    assert!(!asked.contains("beyond that mean"), "{asked}");
    let room = number_before(asked, "this road can give,", "m/s² above that mean");
    let limit = 0.76 * 9.80665;
    assert!((mean + room - limit).abs() <= 0.0101, "{mean} + {room}");
    let m = read_json(&out.join("metrics.json"));
    let steady = m["ay_steady"].as_f64().unwrap();
    let settling = line_with(&said, "the response has not settled");
    let share = number_before(
        settling,
        "this road can give,",
        "% of its step above its steady value (a line through the window would pass it",
    );
    assert!(
        (share / 100.0 - (limit / steady - 1.0)).abs() <= 0.0005,
        "{share} {steady}"
    );
    // Measured, the record's grip is unknown: its trend is said as the
    // window's carried on.
    let history = out.join("history.csv");
    // Its warnings are on stderr.
    let o = run(&["metrics", history.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    let settling = line_with(&said, "the response has not settled");
    assert!(
        settling.contains("the lateral acceleration is still settling: the trend across its steady window heads ")
            && settling.contains("% of its step beyond its steady value (the window's trend carried on: the car's grip, which this record does not give, bounds where it ends)"),
        "{settling}"
    );
}

/// Round 40's `s_kmh.toml`: a step at `speed = 80` runs at 80 m/s as
/// written, said with its km/h and the m/s of 80 km/h, at its line and
/// column; from 50 m/s (180 km/h) on, not below; a schedule's fastest
/// breakpoint named by its element.
#[test]
fn a_speed_that_reads_as_kmh_is_said_in_kmh_too() {
    let dir = tempfile::tempdir().unwrap();
    let step = |speed: &str| {
        format!("[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed}\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n")
    };
    let path = sedan(dir.path(), "s_kmh.toml", &step("80.0"));
    let said = simulate(&path, &dir.path().join("out"));
    let line = 1 + fs::read_to_string(&path)
        .unwrap()
        .lines()
        .position(|l| l.starts_with("speed = 80.0"))
        .unwrap();
    assert!(
        said.contains(&format!("  note: {}:{line}:9: `manoeuvre.speed`: speed = 80 m/s is 288 km/h; 80 km/h is 22.22 m/s: speeds are in m/s", path.display())),
        "{said}"
    );
    assert!(said.contains("if km/h was meant, write 22.22"), "{said}");
    for (speed, noted) in [("50.0", true), ("49.9", false), ("22.2222", false)] {
        let path = sedan(dir.path(), "s.toml", &step(speed));
        let said = simulate(&path, &dir.path().join("out"));
        assert_eq!(said.contains("km/h is"), noted, "{speed}: {said}");
    }
    let schedule = "[manoeuvre]\nkind = \"schedule\"\nt = [0.0, 1.0, 1.5, 4.0]\nsteer = [0.0, 0.0, 0.01, 0.01]\nspeed = [20.0, 20.0, 60.0, 60.0]\n";
    let path = sedan(dir.path(), "sched.toml", schedule);
    let said = simulate(&path, &dir.path().join("out"));
    assert!(
        said.contains("`manoeuvre.speed[2]`: speed = 60 m/s is 216 km/h; 60 km/h is 16.67 m/s"),
        "{said}"
    );
}

/// The rechecks: a 97° step (1.693 rad) is refused at its key, not
/// run without a word; `steer = 0` is refused naming the scenario file,
/// line and column, before any metrics.
#[test]
fn a_97_degree_step_and_a_step_of_nothing_are_refused_at_the_file_s_key() {
    let dir = tempfile::tempdir().unwrap();
    let step = |steer: &str| {
        format!("[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = {steer}\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n")
    };
    for (steer, words) in [
        ("1.693", "`manoeuvre.steer` = 1.693: must lie within ±0.785398: no road wheel steers beyond ±45°"),
        ("0.0", "`manoeuvre.steer` = 0: a step steer needs a steer step of at least 0.00017 rad (0.01°) from straight running"),
    ] {
        let path = sedan(dir.path(), "s.toml", &step(steer));
        let line = 1 + fs::read_to_string(&path)
            .unwrap()
            .lines()
            .position(|l| l.starts_with("steer = "))
            .unwrap();
        let e = fails_cleanly("simulate", &path, dir.path());
        assert!(
            e.contains(&format!("{}:{line}:9: {words}", path.display())),
            "{e}"
        );
    }
}
