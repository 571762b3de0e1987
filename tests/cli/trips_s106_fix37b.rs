//! What fresh-eyes round 37 tripped on in the gap words of a replay and
//! a diagnosis (session 106): a gain error under a common gyro's noise
//! said as "mostly a constant offset" and "a dynamic error" at once, an
//! offset right before the input called a sensor offset, a noise-free
//! sideslip within an assumed floor without the word, the overlays
//! captioned with a verdict that had no effects and model lines starting
//! 0.5 s in without a word, and an axle value rounded coarser than its
//! standard error.

use super::*;
use crate::sedan_runs::{run_text, Noisy};
use crate::trips_s90_met::tester_step_at;

/// The tester's linear car stepped by 0.01 rad at 1 s at `speed` m/s
/// (57 296 N/rad per wheel), logged at 100 Hz with a gyro of `yaw` rad/s
/// and an accelerometer of 0.05 m/s² of white noise (seeded `seed`), its
/// sideslip noise-free: the log's text.
fn noisy_step(dir: &Path, speed: f64, yaw: f64, seed: u64) -> String {
    let sim = dir.join(format!("truth_{speed}_{seed}"));
    fs::create_dir_all(&sim).unwrap();
    let history = tester_step_at(&sim, speed, 0.1, "");
    let noisy = Noisy {
        yaw,
        ay: 0.05,
        seed,
        ay_gain: 1.0,
    };
    run_text(&history, 10, Some(noisy))
}

/// A front tyre 20 % soft (45 836.8 N/rad per wheel against 57 296).
const SOFT: &str = "model = \"linear\"\ncornering_stiffness = 45836.8\npneumatic_trail = 0.03\n";

/// The truth's tyre, 57 296 N/rad per wheel.
const STIFF: &str = "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n";

/// `simulate` of the 25 m/s step logged with a gyro of `yaw` rad/s,
/// replayed on the car with its front tyres 20 % soft: stdout.
fn soft_replay(yaw: f64) -> String {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("run.csv"), noisy_step(d, 25.0, yaw, 37)).unwrap();
    fs::write(d.join("soft.toml"), SOFT).unwrap();
    fs::write(d.join("linear.toml"), STIFF).unwrap();
    let scenario = format!(
        "name = \"rep\"\n{VEHICLE}[tyres]\nfront = \"soft.toml\"\nrear = \"linear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"replay\"\nrun = \"run.csv\"\n"
    );
    fs::write(d.join("replay.toml"), scenario).unwrap();
    let o = run_in(d, &["simulate", "replay.toml", "--out", "rep"]);
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The line of `channel` (`yaw_rate:`) in `said`.
fn line_of<'a>(said: &'a str, channel: &str) -> &'a str {
    said.lines()
        .find(|l| l.trim_start().starts_with(channel))
        .unwrap_or_else(|| panic!("{said}"))
}

/// The book's own gain error (a front tyre 20 % soft on a step at 25 m/s)
/// logged with a gyro of 0.002 rad/s, near the tool's own 0.0017 floor,
/// read "the gap is mostly a constant offset … a dynamic error (gain, lag
/// or stiffness)" on the binary of session 106; with a noise-free gyro it
/// read a gain error of slope +0.277. The line is now fitted against the
/// simulated channel, which carries no measurement noise: at 0.002 and
/// 0.005 rad/s it is a gain error whose ratio is the closed form's,
/// u/(L + K·u²) of the soft car over the stiff one, 4.4610 / 5.7142: the
/// simulation reads 78.1 % (within 3 points at 0.002 rad/s and 6 at
/// 0.005: the transient and the noise).
#[test]
fn a_gain_error_under_a_common_gyro_s_noise_is_said_as_a_gain_error() {
    let closed_form = 100.0 * 4.4610 / 5.7142;
    for yaw in [0.002, 0.005] {
        let said = soft_replay(yaw);
        let line = line_of(&said, "yaw_rate:");
        assert!(line.contains("a gain error"), "{yaw}: {line}");
        assert!(!line.contains("mostly a constant offset"), "{yaw}: {line}");
        assert!(!line.contains("a dynamic error (gain"), "{yaw}: {line}");
        let percent: f64 = line
            .split("the simulation reads ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("{line}"));
        // The noise moves the slope: 124.0 to 128.9 % (the other way
        // round) over three seeds of 0.005 rad/s on the tester's own log.
        let within = 1.0 + 1000.0 * yaw;
        assert!((percent - closed_form).abs() < within, "{yaw}: {line}");
    }
}

/// The same replay's sideslip is noise-free (0 before the input: an
/// estimated output's, trusted to an assumed 0.005 rad) and off the model
/// by about 0.0007 rad: within three assumed floors only because the
/// floor is assumed. The binary of session 106 said "no significant gap"
/// without "this rests on an assumed floor", its zero scatter giving no
/// ratio to say.
#[test]
fn a_noise_free_sideslip_within_its_assumed_floor_says_it_rests_on_it() {
    let said = soft_replay(0.002);
    let beta = line_of(&said, "beta:");
    assert!(beta.contains("no significant gap"), "{beta}");
    assert!(
        beta.contains("this rests on an assumed floor: beta is read as an estimated output")
            && beta.contains("with beta trusted to its scatter, 0 rad (noise-free)")
            && beta.contains("would be a gap"),
        "{beta}"
    );
    // The gyro's and the accelerometer's lines rest on no assumed floor.
    for ch in ["yaw_rate:", "ay:"] {
        assert!(!line_of(&said, ch).contains("assumed floor"), "{said}");
    }
}

/// A campaign in `dir/name` of the stiff car's steps at 15, 20 and 25 m/s
/// (gyro noise 0.002 rad/s) with `tyres` its `[tyres]` table's body (its
/// files `tyre.toml`, the front 20 % soft, and `stiff.toml`) and
/// `effects` its candidates.
fn step_campaign(dir: &Path, name: &str, tyres: &str, effects: &str) -> PathBuf {
    let c = dir.join(name);
    fs::create_dir_all(c.join("runs")).unwrap();
    for (speed, seed) in [(15.0, 1), (20.0, 2), (25.0, 3)] {
        let run = noisy_step(dir, speed, 0.002, seed);
        fs::write(c.join(format!("runs/step{speed}.csv")), run).unwrap();
    }
    fs::write(c.join("tyre.toml"), SOFT).unwrap();
    fs::write(c.join("stiff.toml"), STIFF).unwrap();
    fs::write(
        c.join("vehicle.toml"),
        format!("{VEHICLE}\n[tyres]\n{tyres}\n\n[diagnose]\neffects = [{effects}]\n"),
    )
    .unwrap();
    c
}

/// Both diagnoses of the tests below, run at once: a model whose front
/// tyres are 20 % soft with a candidate that cannot explain it (no verdict
/// effects), and the same runs without tyre data (axles from the runs).
fn diagnosed() -> (tempfile::TempDir, Vec<(String, serde_json::Value)>) {
    let dir = tempfile::tempdir().unwrap();
    let soft = step_campaign(
        dir.path(),
        "soft",
        "front = \"tyre.toml\"\nrear = \"stiff.toml\"",
        "\"sensor_delay\"",
    );
    let axles = step_campaign(dir.path(), "axles", "class = \"road\"", "\"sensor_delay\"");
    let said = diagnosed_together(&[soft, axles]);
    (dir, said)
}

/// A model whose front tyres are 20 % soft, on steps (gyro noise 0.002
/// rad/s), leaves its base
/// residual zero before the input and a mean of several floors after it:
/// the binary of session 106 said "right in: before the input; a steady
/// offset … a sensor offset or a bias of the model", though a sensor's
/// zero offset would have made the window before the input wrong too.
/// The page's overlays, whose verdict has no effects, were captioned
/// "with the verdict's effects (solid)", and their model lines, starting
/// 0.5 s into each replay, had no word on why.
#[test]
fn an_offset_right_before_the_input_is_no_sensor_offset_and_the_overlays_say_what_they_draw() {
    let (dir, said) = diagnosed();
    let (stdout, d) = &said[0];
    assert!(
        d["verdict"]["effects"]
            .as_array()
            .is_none_or(|e| e.is_empty()),
        "{stdout}"
    );
    let line = line_of(stdout, "yaw_rate:");
    assert!(line.contains("right in: before the input"), "{line}");
    assert!(line.contains("a steady offset"), "{line}");
    assert!(
        line.contains("after the input only") && line.contains("not a sensor offset"),
        "{line}"
    );
    assert!(!line.contains("a sensor offset or a bias"), "{line}");
    let page = fs::read_to_string(dir.path().join("soft/out/report.html")).unwrap();
    assert!(
        !page.contains("with the verdict's effects (solid)"),
        "{page}"
    );
    assert!(page.contains("no solid line: the verdict names no effect"));
    assert!(page.contains("The model lines start 0.5 s into each replay"));
}

/// Axles identified from the runs were written "front cornering
/// coefficient 9.8 ± 0.0378 1/rad": a value rounded coarser than its own
/// standard error. Each is now written to its error's second significant
/// digit, in the terminal and on the page alike.
#[test]
fn an_axle_value_is_written_to_its_standard_error_s_precision() {
    let (dir, said) = diagnosed();
    let (stdout, _) = &said[1];
    let page = fs::read_to_string(dir.path().join("axles/out/report.html")).unwrap();
    for text in [stdout.as_str(), page.as_str()] {
        let after = text
            .split("front cornering coefficient ")
            .find(|s| s.split_whitespace().nth(1) == Some("±"))
            .unwrap_or_else(|| panic!("{stdout}"));
        let words: Vec<&str> = after.split_whitespace().collect();
        let (value, se) = (words[0], words[2]);
        let decimals = value.split_once('.').map_or(0, |(_, d)| d.len());
        let se: f64 = se.parse().unwrap_or_else(|_| panic!("{after}"));
        // The decimal of the error's second significant digit.
        let needed = (1 - se.log10().floor() as i64).max(0) as usize;
        assert!(decimals >= needed, "{value} ± {se}: {after}");
    }
}
