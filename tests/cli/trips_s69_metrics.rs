//! `metrics` on run files laid out as real loggers write them: a step and
//! its return in one log, a header with units in brackets, a capitalised
//! header, a byte-order mark and CRLF line endings.

use super::*;

/// The sedan's step (1° at 1.0–1.1 s, to 6 s) at 100 Hz: t, speed,
/// steer, yaw_rate and ay of each row.
fn sedan_rows(dir: &Path) -> Vec<[f64; 5]> {
    let sedan = super::trips_s66::Sedan::simulated(dir);
    let at = |k: &str| sedan.header.iter().position(|h| h == k).unwrap();
    let cols = [at("t"), at("speed"), at("steer"), at("yaw_rate"), at("ay")];
    sedan
        .rows
        .iter()
        .step_by(10)
        .map(|row| cols.map(|c| row[c]))
        .collect()
}

/// `rows` as a run file: `header` and `end` (the line ending) as given.
fn run_text(header: &str, rows: &[[f64; 5]], end: &str) -> String {
    let mut text = format!("{header}{end}");
    for r in rows {
        let cells: Vec<String> = r.iter().map(f64::to_string).collect();
        text += &format!("{}{end}", cells.join(","));
    }
    text
}

const HEADER: &str = "t,speed,steer,yaw_rate,ay";

/// A log of a step and, 6 s on, the step back (or a second step on top)
/// was refused as holding "no steer step: the steer stays at 0 rad" (the
/// initial and steady windows both at rest) or as a 6 s "ramp steer": the
/// first step is now measured, on the run cut before the second, as the
/// step alone measures, and the warning says the run holds two steps and
/// where.
#[test]
fn a_run_holding_a_step_and_its_return_measures_its_first_step_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let alone = dir.path().join("alone.csv");
    fs::write(&alone, run_text(HEADER, &rows, "\n")).unwrap();
    let (one, said) = metrics_json(&alone);
    assert!(!said.iter().any(|w| w.contains("steer steps")), "{said:?}");
    let last = *rows.last().unwrap();
    for (name, sign) in [("back.csv", -1.0), ("again.csv", 1.0)] {
        let second = rows.iter().map(|r| {
            let mut s = *r;
            s[0] += last[0] + 0.01;
            for k in 2..5 {
                s[k] = last[k] + sign * r[k];
            }
            s
        });
        let both: Vec<[f64; 5]> = rows.iter().copied().chain(second).collect();
        let path = dir.path().join(name);
        fs::write(&path, run_text(HEADER, &both, "\n")).unwrap();
        let (j, said) = metrics_json(&path);
        assert!(
            said.iter().any(
                |w| w.contains("the run holds 2 steer steps (at 1.05 s, 7.0")
                    && w.contains("the first is measured")
            ),
            "{name}: {said:?}"
        );
        for k in [
            "yaw_rate_response_time",
            "yaw_rate_gain",
            "ay_response_time",
        ] {
            let (a, b) = (j[k].as_f64().unwrap(), one[k].as_f64().unwrap());
            assert!(
                (a - b).abs() < 1e-3 * b.abs(),
                "{name} {k}: {a} against {b}"
            );
        }
    }
}

/// A header with each column's unit in brackets was refused for its four
/// required columns (round 30), then answered "rename it" (round 36): a
/// header that states the units the tool reads is read as the bare one,
/// and one stating another unit is refused with its conversion.
#[test]
fn a_header_with_si_units_in_brackets_is_read_and_another_unit_refused_with_its_factor() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let measured = |header: &str| {
        let path = dir.path().join("units.csv");
        fs::write(&path, run_text(header, &rows, "\n")).unwrap();
        run(&["metrics", path.to_str().unwrap(), "--json"])
    };
    let bare = measured("t,speed,steer,yaw_rate,ay");
    let si = measured("t [s],speed [m/s],steer [rad],yaw_rate [rad/s],ay [m/s^2]");
    assert!(si.status.success(), "{}", stderr(&si));
    assert_eq!(bare.stdout, si.stdout);
    let g = measured("t [s],speed [m/s],steer [rad],yaw_rate [rad/s],ay [g]");
    let e = stderr(&g);
    assert!(!g.status.success(), "{e}");
    assert!(
        e.contains("units.csv:1:5:") && e.contains("ay [g]") && e.contains("9.80665"),
        "{e}"
    );
}

/// In a capitalised header (`T,Speed,Steer,Yaw_Rate`) the missing `steer`
/// was said to be meant by `Speed`, two edits from it, the first close
/// column: each missing column now names its nearest.
#[test]
fn a_capitalised_header_names_the_nearest_column_for_each_missing_one() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let path = dir.path().join("caps.csv");
    fs::write(&path, run_text("T,Speed,Steer,Yaw_Rate,Ay", &rows, "\n")).unwrap();
    let o = run(&["metrics", path.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("caps.csv:1:3: missing required column `steer` (the header has: T, Speed, Steer, Yaw_Rate, Ay); header column 3, `Steer`: did you mean `steer`?"),
        "{e}"
    );
    assert!(!e.contains("`Speed`: did you mean `steer`"), "{e}");
    assert!(
        e.contains("column `Ay` is not one this command reads: did you mean `ay`?"),
        "{e}"
    );
}

/// A spreadsheet's export (a byte-order mark, CRLF line endings) is read
/// as the plain file: the same metrics, no column lost to the mark.
#[test]
fn a_run_with_a_byte_order_mark_and_crlf_endings_measures_as_the_plain_run() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let plain = dir.path().join("plain.csv");
    fs::write(&plain, run_text(HEADER, &rows, "\n")).unwrap();
    let exported = dir.path().join("exported.csv");
    fs::write(
        &exported,
        format!("\u{feff}{}", run_text(HEADER, &rows, "\r\n")),
    )
    .unwrap();
    let (a, _) = metrics_json(&plain);
    let (b, said) = metrics_json(&exported);
    assert!(!said.iter().any(|w| w.contains("did you mean")), "{said:?}");
    for k in ["yaw_rate_response_time", "yaw_rate_peak_time", "er"] {
        assert_eq!(a[k], b[k], "{k}");
    }
}

/// A logger that starts a new recording in the same file sets its clock
/// back: refused at the line, with what happened and what to do (split
/// the file there), not only "time must be strictly increasing"; a steer
/// logged in degrees is refused with how to declare it.
#[test]
fn a_clock_that_restarts_and_a_steer_in_degrees_say_what_to_do() {
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let again: Vec<[f64; 5]> = rows.iter().chain(rows.iter()).copied().collect();
    let twice = dir.path().join("twice.csv");
    fs::write(&twice, run_text(HEADER, &again, "\n")).unwrap();
    let o = run(&["metrics", twice.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    // The second recording's first row is line 2 + the first's rows.
    assert!(e.contains(&format!("twice.csv:{}:", rows.len() + 2)), "{e}");
    assert!(
        e.contains("the clock goes back, as where a logger starts a new recording in the same file; split the file at this line into two runs"),
        "{e}"
    );
    let degrees: Vec<[f64; 5]> = rows
        .iter()
        .map(|r| {
            let mut d = *r;
            d[2] = d[2].to_degrees();
            d
        })
        .collect();
    let small = dir.path().join("small.csv");
    fs::write(&small, run_text(HEADER, &degrees, "\n")).unwrap();
    let o = run(&["metrics", small.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("a column in degrees is declared so: `metrics --degrees steer`, or `degrees = [\"steer\"]` under a campaign's [runs]"),
        "{e}"
    );
}

/// A steer sensor's white noise of a few % of the step crossed 10 % of
/// the step back and forth before it: the rise read 0.23 s for a 0.08 s
/// ramp (3 % noise) with a warning that the response times include the
/// ramp, and at 7.5 % the run was refused as starting too close to the
/// step. The rise is now read from the last 10 % crossing before the
/// first 90 % one, and a move within four of the filtered steer's noise
/// deviations is not a move.
#[test]
fn a_noisy_steer_sensor_neither_lengthens_the_rise_nor_refuses_the_run() {
    use rand::SeedableRng;
    let dir = tempfile::tempdir().unwrap();
    let rows = sedan_rows(dir.path());
    let step = rows.last().unwrap()[2];
    for (share, seed) in [(0.03, 1), (0.075, 2)] {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let noisy: Vec<[f64; 5]> = rows
            .iter()
            .map(|r| {
                let mut n = *r;
                n[2] += share * step * handling::identify::data::gauss(&mut rng);
                n
            })
            .collect();
        let path = dir.path().join(format!("noisy_{seed}.csv"));
        fs::write(&path, run_text(HEADER, &noisy, "\n")).unwrap();
        let o = run(&["metrics", path.to_str().unwrap()]);
        let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
        assert!(o.status.success(), "{share}: {said}");
        let rise: f64 = said
            .split("steer 10–90 % rise ")
            .nth(1)
            .and_then(|s| s.split(' ').next())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("{said}"));
        // The ramp lasts 0.1 s: 10–90 % of it is 0.08 s.
        assert!((rise - 0.08).abs() < 0.01, "{share}: rise {rise}");
        assert!(!said.contains("include the ramp"), "{said}");
    }
}
