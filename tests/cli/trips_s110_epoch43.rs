//! Fresh-eyes round 43's findings 1 and 8 (session 110): real loggers'
//! time columns and dropouts.
//!
//! 1. The book's synthetic campaign (`synth --effects sensor_delay --seed
//!    1`) found `sensor_delay.delay = 0.04960 s` explaining 85 % of the
//!    gap; the same runs on Unix-epoch seconds (t + 1701234567) found no
//!    delay at all ("0.0 % in sample") and another verdict. A wall clock is
//!    rebased to each run's first sample when read, and said: the verdict
//!    and the fitted delay are the same to every printed digit.
//! 2. A NaN or an empty cell in `ay` is refused as `FORMATS.md` requires,
//!    said as a logger's dropout with how to mark one (its rows left out),
//!    and a file so mended is read, the hole said.
//! 3. A clock that wraps (a 16-bit millisecond counter; a period of its
//!    own, the channels running on) is said as a wrapped clock with how to
//!    unwrap it, not as a new recording to split.

use super::*;

/// The offset of a Unix-epoch clock, s.
const EPOCH: f64 = 1701234567.0;

/// The runs of campaign `c`.
fn runs(c: &Path) -> Vec<PathBuf> {
    let mut r: Vec<PathBuf> = fs::read_dir(c.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    r.sort();
    r
}

/// The line of `said` that starts (after its indent) with `start`.
fn line_of<'a>(said: &'a str, start: &str) -> &'a str {
    said.lines()
        .find(|l| l.trim_start().starts_with(start))
        .unwrap_or_else(|| panic!("no line `{start}`: {said}"))
}

/// The candidates table's row of `effect` without its ΔBIC (a sum over
/// every sample, not a printed figure of the fit), and the verdict line.
fn outcome(said: &str, effect: &str) -> (String, String) {
    let row = line_of(said, &format!("{effect} "));
    let cells: Vec<&str> = row.split_whitespace().collect();
    // effect, J after, held out, %, in sample, %, ΔBIC, parameters…
    let mut kept: Vec<&str> = cells[..6].to_vec();
    kept.extend(&cells[7..]);
    (kept.join(" "), line_of(said, "verdict:").to_string())
}

#[test]
fn an_epoch_clock_gives_the_verdict_and_the_delay_of_the_logs_own() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["--effects", "sensor_delay", "--seed", "1"];
    let own = synth_campaign(dir.path(), "own", &args);
    let epoch = synth_campaign(dir.path(), "epoch", &args);
    for r in runs(&epoch) {
        map_column(&r, "t", |t| t + EPOCH);
    }
    let first: f64 = fs::read_to_string(&runs(&epoch)[0])
        .unwrap()
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(first > EPOCH, "{first}");
    let (said_own, d_own) = diagnose_to(&own, &dir.path().join("own_out"));
    let (said_epoch, d_epoch) = diagnose_to(&epoch, &dir.path().join("epoch_out"));
    let (row_own, verdict_own) = outcome(&said_own, "sensor_delay");
    let (row_epoch, verdict_epoch) = outcome(&said_epoch, "sensor_delay");
    assert!(
        verdict_own.contains("verdict: sensor_delay explains the gap"),
        "{said_own}"
    );
    assert!(row_own.contains("sensor_delay.delay = 0.049"), "{row_own}");
    assert_eq!(row_epoch, row_own, "{said_epoch}");
    assert_eq!(verdict_epoch.replace("epoch", "own"), verdict_own);
    // The clock is said, at each run's first sample on the log's clock,
    // and only where it was rebased.
    let n = runs(&epoch).len();
    let line = line_of(&said_epoch, "cleaning: clock: ");
    let head = format!("cleaning: clock: {n} runs on a wall clock, its time rebased to 0 at its first sample when read, so that the clock's origin does not matter (the times said are from that sample): ");
    assert!(line.trim_start().starts_with(&head), "{line}");
    let first_run = format!("{} from {first:.3} s", runs(&epoch)[0].display());
    assert!(line.contains(&first_run), "{first_run}\n{line}");
    assert_eq!(said_epoch.matches(" from 17012345").count(), n, "{line}");
    assert!(!said_own.contains("clock: "), "{said_own}");
    let clocks = d_epoch["cleaning"]["clocks"].as_array().unwrap();
    assert_eq!(clocks.len(), runs(&epoch).len(), "{clocks:?}");
    assert_eq!(clocks[0]["origin"].as_f64().unwrap(), first);
    assert!(d_own["cleaning"]["clocks"].as_array().unwrap().is_empty());
}

/// A run of the synthetic campaign with the cells of `column` on rows
/// `rows` (0-based, under the header) written as `cell`, at `dir/name`.
fn with_cells(
    dir: &Path,
    name: &str,
    column: usize,
    rows: std::ops::Range<usize>,
    cell: &str,
) -> PathBuf {
    let c = synth_campaign(
        dir,
        &format!("c_{name}"),
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let text = fs::read_to_string(c.join("runs/step_060kph_2ms2.csv")).unwrap();
    let mut out = String::new();
    for (k, l) in text.lines().enumerate() {
        let mut cells: Vec<&str> = l.split(',').collect();
        if k >= 1 && rows.contains(&(k - 1)) {
            cells[column] = cell;
        }
        out += &(cells.join(",") + "\n");
    }
    let path = dir.join(name);
    fs::write(&path, out).unwrap();
    path
}

#[test]
fn a_dropout_is_refused_as_formats_requires_with_how_to_mark_one() {
    let dir = tempfile::tempdir().unwrap();
    let header = "t,speed,steer,yaw_rate,ay,beta";
    let ay = header.split(',').position(|c| c == "ay").unwrap();
    for (name, cell, said) in [
        ("nan.csv", "nan", "`nan` is"),
        ("empty.csv", "", "an empty cell is"),
    ] {
        let path = with_cells(dir.path(), name, ay, 300..310, cell);
        assert!(fs::read_to_string(&path).unwrap().starts_with(header));
        let o = run(&["metrics", path.to_str().unwrap()]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{e}");
        // Row 300 under the header is line 302; `ay` is column 5.
        let words = format!("{name}:302:5: column `ay`: {said} a logger's dropout, which FORMATS.md makes an error in a run (a NaN or a cell without a number is refused, never masked or guessed); mark a dropout by leaving its rows out of the file");
        assert!(e.contains(&words), "{e}");
        assert!(e.contains("(the first of 10 places refused alike)"), "{e}");
    }
    // The time's own cell is no dropout: a NaN there is said as before.
    let path = with_cells(dir.path(), "t.csv", 0, 300..301, "nan");
    let e = stderr(&run(&["metrics", path.to_str().unwrap()]));
    assert!(
        e.contains("t.csv:302:1: column `t`: nan is not a finite value"),
        "{e}"
    );
    // Marked as the refusal says, the run is read and the hole said.
    let kept = with_cells(dir.path(), "kept.csv", ay, 300..303, "DROP");
    let text: String = fs::read_to_string(&kept)
        .unwrap()
        .lines()
        .filter(|l| !l.contains("DROP"))
        .map(|l| format!("{l}\n"))
        .collect();
    fs::write(&kept, text).unwrap();
    let o = run(&["metrics", kept.to_str().unwrap()]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("kept.csv misses 3 samples in 1 hole in time"),
        "{said}"
    );
}

/// The synthetic run with its time written by `clock` (of the time).
fn clocked(dir: &Path, name: &str, clock: impl Fn(f64) -> f64) -> PathBuf {
    let path = with_cells(dir, name, 0, 0..0, "");
    map_column(&path, "t", clock);
    path
}

#[test]
fn a_wrapped_clock_is_said_with_how_to_unwrap_it() {
    let dir = tempfile::tempdir().unwrap();
    // A 16-bit millisecond counter that wraps mid-run.
    let path = clocked(dir.path(), "ms16.csv", |t| {
        ((t + 60.0) * 1000.0).round() % 65536.0 / 1000.0
    });
    let e = stderr(&run(&["metrics", path.to_str().unwrap()]));
    assert!(e.contains("the clock falls by 65.536 s less its step of 0.01 s, a 16-bit millisecond counter's period (2^16 ms): it reads as a wrapped clock, not a new recording; unwrap it by adding 65.536 s to the time of this row and of every row after it"), "{e}");
    assert!(!e.contains("split the file"), "{e}");
    // A period of its own (5 s), every channel running on across the fall.
    let path = clocked(dir.path(), "five.csv", |t| {
        ((t * 100.0).round() % 500.0) / 100.0
    });
    let e = stderr(&run(&["metrics", path.to_str().unwrap()]));
    assert!(e.contains("column `t`: 0 does not follow 4.99 (time must be strictly increasing: the clock goes back and resumes its step of 0.01 s with every channel running on across the fall: it reads as a wrapped clock (a counter of period 5 s), not a new recording; unwrap it by adding 5 s to the time of this row and of every row after it"), "{e}");
}
