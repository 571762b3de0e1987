//! What a user still trips on after the fresh-eyes round, run as a user
//! runs the tool: a measured CSV or a `.tir` saved as Latin-1, an output
//! lock whose process id now belongs to another program, a manoeuvre that
//! steers nothing, a schedule's short column, metrics windows longer than
//! the run, a refusal that names its file twice, and a swept steer beyond
//! the road-wheel limit `simulate` keeps to.

use super::*;

/// The bundled sedan step simulated into `dir/sim`: its `history.csv`
/// (a run in the measured format) as text.
fn sedan_history(dir: &Path) -> String {
    let sim = dir.join("sim");
    let o = run(&[
        "simulate",
        root().join("scenarios/sedan_step.toml").to_str().unwrap(),
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    fs::read_to_string(sim.join("history.csv")).unwrap()
}

/// Runs `metrics` on `bytes` written as `dir/name`: success and what it
/// printed (stdout, or stderr on failure).
fn metrics_of(dir: &Path, name: &str, bytes: &[u8]) -> (bool, String) {
    let file = dir.join(name);
    fs::write(&file, bytes).unwrap();
    let o = run(&["metrics", file.to_str().unwrap(), "--filter-hz", "0"]);
    let said = match o.status.success() {
        true => String::from_utf8_lossy(&o.stdout).into_owned(),
        false => stderr(&o),
    };
    (o.status.success(), said)
}

const LATIN1: &str =
    "byte 0xE9 is not UTF-8: the file must be UTF-8 text (was it saved as Latin-1 or Windows-1252?)";

/// A byte that is not UTF-8 in a row or the header of a measured run is
/// refused at its line and column, the row's naming its column, as a TOML
/// file's is (it was "malformed CSV row: CSV parse error: record 2 (line 3,
/// field: 1, …)" at column 1); one in a comment line is no refusal.
#[test]
fn a_csv_saved_as_latin1_is_refused_at_the_byte_s_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let header: Vec<&str> = history.lines().next().unwrap().split(',').collect();
    let steer = header.iter().position(|c| *c == "steer").unwrap();
    // Line 3 (the second row): its steer cell starts with é in Latin-1.
    let mut rows: Vec<Vec<u8>> = history.lines().map(|l| l.as_bytes().to_vec()).collect();
    let mut cells: Vec<Vec<u8>> = rows[2].split(|&b| b == b',').map(<[u8]>::to_vec).collect();
    cells[steer].insert(0, 0xE9);
    rows[2] = cells.join(&b',');
    let (ok, e) = metrics_of(dir.path(), "row.csv", &(rows.join(&b'\n')));
    assert!(!ok, "{e}");
    let expected = format!("row.csv:3:{}: column `steer`: {LATIN1}", steer + 1);
    assert!(e.contains(&expected), "{e}\nexpected {expected}");
    // In the header: at its line and column.
    let yaw = header.iter().position(|c| *c == "yaw_rate").unwrap();
    let mut bytes = history.replacen("yaw_rate", "yaw_r\u{0}te", 1).into_bytes();
    let at = bytes.iter().position(|&b| b == 0).unwrap();
    bytes[at] = 0xE9;
    let (ok, e) = metrics_of(dir.path(), "header.csv", &bytes);
    assert!(!ok, "{e}");
    let expected = format!("header.csv:1:{}: {LATIN1}", yaw + 1);
    assert!(e.contains(&expected), "{e}\nexpected {expected}");
    // In a comment line: read as before.
    let mut bytes = b"# essai d'\xE9t\xE9\n".to_vec();
    bytes.extend(history.as_bytes());
    let (ok, said) = metrics_of(dir.path(), "comment.csv", &bytes);
    assert!(ok, "{said}");
    assert!(said.contains("Er "), "{said}");
}

/// The line (from 1) of `file` on which `key = …` is written.
fn line_of(file: &Path, key: &str) -> usize {
    fs::read_to_string(file)
        .unwrap()
        .lines()
        .position(|l| l.starts_with(&format!("{key} =")))
        .unwrap_or_else(|| panic!("no `{key} =` in {}", file.display()))
        + 1
}

/// Sets the modification time of `file` to `seconds` ago.
fn age_by(file: &Path, seconds: u64) {
    let then = std::time::SystemTime::now() - std::time::Duration::from_secs(seconds);
    fs::File::options()
        .write(true)
        .open(file)
        .unwrap()
        .set_modified(then)
        .unwrap();
}

/// A lock left by a killed run whose process id the system has since given
/// to another program (after a restart, in a container) named a running
/// process, and was never taken over; one naming a process that may have
/// written it (started before it) is still refused.
#[cfg(target_os = "linux")]
#[test]
fn a_lock_naming_a_process_started_after_it_is_taken_over() {
    let dir = scenario(VEHICLE, GIM, STEP);
    let out = dir.path().join("out");
    fs::create_dir(&out).unwrap();
    let lock = out.join(".handling.lock");
    let args = [
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]
    .map(String::from);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    // This test's own process started before the lock: it may hold it.
    let me = std::process::id();
    fs::write(&lock, format!("{me}\n")).unwrap();
    let o = run(&args);
    let e = refused(&o, &out.join("history.csv"));
    assert!(e.contains(&format!("another run (process {me})")), "{e}");
    // A program started now, named by a lock written a minute ago.
    let mut other = Command::new("sleep").arg("30").spawn().unwrap();
    let pid = other.id();
    fs::write(&lock, format!("{pid}\n")).unwrap();
    age_by(&lock, 60);
    let o = run(&args);
    let _ = other.kill();
    let _ = other.wait();
    assert!(o.status.success(), "{}", stderr(&o));
    let note = stderr(&o);
    assert!(
        note.contains(&format!(
            "was left by process {pid}, which is no longer running: process {pid} now is another program, started "
        )) && note.contains("s after the lock was written; taking the folder over"),
        "{note}"
    );
    assert!(out.join("history.csv").is_file());
    assert!(!lock.exists(), "the lock is released after the run");
}

/// A sine or sweep of amplitude 0, or a ramp whose rate reaches no steer
/// by its end, ran as straight running without a word (a step steer of 0
/// is refused at its key): refused at the key that asks for it.
#[test]
fn a_manoeuvre_that_steers_nothing_is_refused_at_its_key() {
    let none = "the road wheels steer at most 0 rad (0.00°), less than the 0.00017 rad (0.01°) a manoeuvre must steer: the car would run straight, with no response to show";
    for (manoeuvre, key, said) in [
        (
            "kind = \"sine\"\nspeed = 20.0\namplitude = 0.0\nfrequency = 0.5\nend = 4.0\n",
            "amplitude",
            format!("`manoeuvre.amplitude` = 0: {none}"),
        ),
        (
            "kind = \"sweep\"\nspeed = 20.0\namplitude = 0\nf_start = 0.1\nf_end = 2.0\nend = 5.0\n",
            "amplitude",
            format!("`manoeuvre.amplitude` = 0: {none}"),
        ),
        (
            // From the default start, 1 s: 3 s of ramp.
            "kind = \"ramp-steer\"\nspeed = 20.0\nrate = 1e-5\nend = 4.0\n",
            "rate",
            "`manoeuvre.rate` = 1e-5: the road wheels steer at most 0.000030 rad (0.002°), less than the 0.00017 rad (0.010°)".to_string(),
        ),
    ] {
        let dir = scenario(VEHICLE, GIM, &format!("[manoeuvre]\n{manoeuvre}"));
        let file = dir.path().join("scenario.toml");
        let line = line_of(&file, key);
        let e = simulate_err(dir.path());
        // At the value: after `key = `.
        let expected = format!("{}:{line}:{}: {said}", file.display(), key.len() + 4);
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
    }
    // A small sine is a manoeuvre: run.
    let dir = scenario(
        VEHICLE,
        GIM,
        "[manoeuvre]\nkind = \"sine\"\nspeed = 20.0\namplitude = 0.001\nfrequency = 0.5\nend = 4.0\n",
    );
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A point beyond the file's load range was said to be "evaluated at the
/// ranges' ends" while its `my`, which MFeval takes at the load given,
/// read 800 kN·m at 1 MN: the line says which value keeps the load. (40
/// kN since session 107: 1 MN puts the tyre on its rim, refused.)
#[test]
fn tyre_eval_says_the_rolling_resistance_keeps_the_load_given() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let points = "fz,kappa,alpha,camber,speed\n4000,0.01,0.05,0,16.7\n40000,0,0.05,0,16.7\n";
    let dir = scratch(&[("points.csv", points)]);
    let out = dir.path().join("forces.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("1 of them outside the file's ranges of load, slip, camber or pressure, evaluated at the ranges' ends (`my` at the load given, and `rl` the free radius at the load given less the deflection at the load held within FZMAX, as MFeval does)"),
        "{said}"
    );
    // And it does: `my` grows with the load given, the forces do not.
    let text = fs::read_to_string(&out).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let (fy, my) = (
        header.iter().position(|c| *c == "fy").unwrap(),
        header.iter().position(|c| *c == "my").unwrap(),
    );
    assert!(rows[1][fy].abs() < 20_000.0, "{text}");
    // (40000/4000)^QSY7 = 7.1 at the load given; held at FZMAX, 3.6.
    assert!(rows[1][my].abs() > 5.0 * rows[0][my].abs(), "{text}");
}

/// The sedan step's history with its steer column set to 0: a run that
/// moves all through and holds no steer step.
fn flat_run(history: &str) -> String {
    let mut lines = history.lines();
    let header = lines.next().unwrap();
    let steer = header.split(',').position(|c| c == "steer").unwrap();
    let mut text = format!("{header}\n");
    for line in lines {
        let mut cells: Vec<&str> = line.split(',').collect();
        cells[steer] = "0";
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    text
}

/// A run that is one moving piece, all its samples, was named twice:
/// "flat.csv: no moving piece holds a steer step: flat.csv (0.00–6.00 s):
/// no step-steer metrics (…)"; the file is said once.
#[test]
fn metrics_names_a_single_piece_run_once() {
    let dir = tempfile::tempdir().unwrap();
    let flat = flat_run(&sedan_history(dir.path()));
    let (ok, e) = metrics_of(dir.path(), "flat.csv", flat.as_bytes());
    assert!(!ok, "{e}");
    assert!(
        e.contains("flat.csv: no step-steer metrics (no steer step: the steer stays at 0 rad (0.00°) from the initial window to the steady one"),
        "{e}"
    );
    assert_eq!(e.matches("flat.csv").count(), 1, "{e}");
}

/// `--pre-window 1e308` was refused as "shorter than the initial and
/// steady windows" without their values; a window that is no positive
/// number of seconds was refused by the library's key, `pre_window`, not
/// by the option given.
#[test]
fn metrics_windows_are_refused_with_their_values() {
    let dir = tempfile::tempdir().unwrap();
    let history = sedan_history(dir.path());
    let file = dir.path().join("run.csv");
    fs::write(&file, history).unwrap();
    let metrics = |option: &str, value: &str| {
        let o = run(&["metrics", file.to_str().unwrap(), option, value]);
        assert!(!o.status.success(), "{option} {value}");
        stderr(&o)
    };
    let e = metrics("--pre-window", "1e308");
    assert!(
        e.contains("run.csv: no step-steer metrics (the record (6.000 s) is not longer than the initial and steady windows together (`pre_window` = 1e308 s + `steady_window` = 1 s))"),
        "{e}"
    );
    let e = metrics("--steady-window", "5.5");
    assert!(
        e.contains("(`pre_window` = 0.5 s + `steady_window` = 5.5 s)"),
        "{e}"
    );
    for option in ["--pre-window", "--steady-window", "--variance-window"] {
        let name = option[2..].replace('-', "_").to_uppercase();
        for value in ["-1", "0", "inf", "NaN"] {
            let e = metrics(option, value);
            let expected = format!("invalid value '{value}' for '{option} <{name}>': a window is a positive, finite number of seconds");
            assert!(e.contains(&expected), "{e}\nexpected {expected}");
        }
    }
    // The cut-off and the lowest speed likewise, by their options (they
    // were refused by the library's keys, `filter_hz` = -1).
    for value in ["-1", "inf", "NaN"] {
        let e = metrics("--filter-hz", value);
        let expected = format!("invalid value '{value}' for '--filter-hz <FILTER_HZ>': a cut-off is a positive, finite frequency in Hz (0: unfiltered)");
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
        // The lowest speed in the words of `--min-overshoot` and of a
        // campaign's `min_speed` (round 39: a form of its own).
        let e = metrics("--min-speed", value);
        let expected =
            "must lie in [0, 100]: it is the speed in m/s below which samples are left out as slow";
        assert!(
            e.contains("--min-speed: `min_speed` = ") && e.contains(expected),
            "{e}"
        );
    }
    let e = metrics("--filter-hz", "ten");
    assert!(e.contains("not a number (a cut-off is in Hz)"), "{e}");
}

/// A schedule whose columns differ in length was refused at `t`, with
/// the three lengths: it is refused at the short column's key and line,
/// with its length and the longest's.
#[test]
fn a_schedule_s_short_column_is_refused_at_its_key() {
    let three = "[0.0, 1.0, 2.0]";
    let steers = "[0.0, 0.02, 0.02]";
    let speeds = "[20.0, 20.0, 20.0]";
    for (t, steer, speed, key, said) in [
        (
            three,
            "[0.0, 0.02]",
            speeds,
            "steer",
            "2 values where `t` has 3",
        ),
        (three, steers, "[20.0]", "speed", "1 value where `t` has 3"),
        (
            "[0.0, 1.0]",
            steers,
            speeds,
            "t",
            "2 values where `steer` has 3",
        ),
        (
            "[0.0]",
            "[0.0]",
            "[20.0]",
            "t",
            "1 breakpoint: a schedule needs at least 2",
        ),
    ] {
        let manoeuvre = format!(
            "[manoeuvre]\nkind = \"schedule\"\nt = {t}\nsteer = {steer}\nspeed = {speed}\n"
        );
        let dir = scenario(VEHICLE, GIM, &manoeuvre);
        let file = dir.path().join("scenario.toml");
        let line = line_of(&file, key);
        let e = simulate_err(dir.path());
        let expected = format!(
            "{}:{line}:{}: `manoeuvre.{key}`: {said}",
            file.display(),
            key.len() + 4
        );
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
    }
}

/// An equilibrium sweep of `steer`, `friction` and `speed` with the axis
/// `axis` set to `value`, in a fresh folder.
fn sweep_with(axis: &str, value: &str) -> tempfile::TempDir {
    let mut sweep = [("steer", "0.1"), ("friction", "0.8"), ("speed", "20.0")];
    sweep.iter_mut().find(|(a, _)| *a == axis).unwrap().1 = value;
    let lines: Vec<String> = sweep.iter().map(|(a, v)| format!("{a} = {v}")).collect();
    let file = format!(
        "{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[sweep]\n{}\n",
        lines.join("\n")
    );
    scratch(&[("sweep.toml", &file), ("tyre.toml", GIM)])
}

/// The equilibrium sweep took a steer up to ±90° where `simulate` stops at
/// ±45°, and refused any axis with one sentence of every axis's rule: a
/// swept steer keeps to `simulate`'s road-wheel limit, in its words, and
/// each refusal names only the rule broken.
#[test]
fn a_swept_steer_keeps_to_the_road_wheel_limit_of_simulate() {
    let sim = scenario(
        VEHICLE,
        GIM,
        "[manoeuvre]\nkind = \"step-steer\"\nspeed = 20.0\nsteer = 1.2\n",
    );
    let e = simulate_err(sim.path());
    let rule = e
        .split("`manoeuvre.steer` = 1.2: ")
        .nth(1)
        .unwrap_or_else(|| panic!("{e}"))
        .trim();
    assert!(rule.contains("±45°"), "{rule}");
    let sweep_err = |axis: &str, value: &str| {
        let dir = sweep_with(axis, value);
        let e = fails_cleanly("equilibria", &dir.path().join("sweep.toml"), dir.path());
        let file = dir.path().join("sweep.toml");
        let line = line_of(&file, axis);
        // A range is refused at the end it writes, at that value's column.
        let (key, column) = match value.find("to =") {
            Some(k) => (
                format!("sweep.{axis}.to"),
                axis.len() + 4 + k + "to = ".len(),
            ),
            None => (format!("sweep.{axis}"), axis.len() + 4),
        };
        (e, format!("{}:{line}:{column}: `{key}` = ", file.display()))
    };
    for steer in ["1.2", "[0.1, 1.2]", "{ from = 0.0, to = 1.2, step = 0.6 }"] {
        let (e, at) = sweep_err("steer", steer);
        let expected = format!("{at}1.2: {rule}");
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
    }
    // Given in degrees, said in degrees, without asking whether it is.
    for steer in [
        "{ values = [10.0, 50.0], unit = \"deg\" }",
        "{ from = 0.0, to = 50.0, step = 25.0, unit = \"deg\" }",
    ] {
        let (e, at) = sweep_err("steer", steer);
        let expected = format!("{at}50: must lie within ±45: no road wheel steers beyond ±45° (a car's largest mean road-wheel steer is about 35–40°)");
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
        assert!(!e.contains("in degrees?"), "{e}");
    }
    for (axis, value) in [("friction", "-1"), ("speed", "0")] {
        let (e, at) = sweep_err(axis, value);
        let expected = format!("{at}{value}: must be positive");
        assert!(e.contains(&expected), "{e}\nexpected {expected}");
        assert!(
            !without_temp_names(&e).contains("steer"),
            "names only the rule broken: {e}"
        );
    }
}

/// A Latin-1 byte inside a `.tir` value reached the number reader as `�`
/// ("`�1.0085` is not a number"): it is refused at its line and column
/// as a TOML or CSV file's is; one in a comment is read past, as before.
#[test]
fn a_tir_saved_as_latin1_is_refused_at_the_byte_s_line_and_column() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let text = fs::read_to_string(tir).unwrap();
    let dir = scratch(&[(
        "points.csv",
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n",
    )]);
    let eval = |name: &str, bytes: &[u8]| {
        let file = dir.path().join(name);
        fs::write(&file, bytes).unwrap();
        let out = dir.path().join(format!("{name}.csv"));
        let points = dir.path().join("points.csv");
        let args = [file.to_str().unwrap(), points.to_str().unwrap()];
        run(&[
            "tyre-eval",
            args[0],
            args[1],
            "--out",
            out.to_str().unwrap(),
        ])
    };
    // The value of PDY1 starts with é; a comment elsewhere holds one too.
    let mut lines: Vec<Vec<u8>> = text.lines().map(|l| l.as_bytes().to_vec()).collect();
    let pdy1 = lines.iter().position(|l| l.starts_with(b"PDY1 ")).unwrap();
    let at = lines[pdy1].iter().position(|&b| b == b'=').unwrap() + 1;
    let at = at + lines[pdy1][at..].iter().take_while(|&&b| b == b' ').count();
    lines[pdy1].insert(at, 0xE9);
    let fnomin = lines
        .iter()
        .position(|l| l.starts_with(b"FNOMIN "))
        .unwrap();
    lines[fnomin].extend(b" $ charg\xE9e");
    let o = eval("value.tir", &lines.join(&b'\n'));
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    let expected = format!("value.tir:{}:{}: {LATIN1}", pdy1 + 1, at + 1);
    assert!(e.contains(&expected), "{e}\nexpected {expected}");
    // Only the comment's: read as before.
    lines[pdy1].remove(at);
    let o = eval("comment.tir", &lines.join(&b'\n'));
    assert!(o.status.success(), "{}", stderr(&o));
}
