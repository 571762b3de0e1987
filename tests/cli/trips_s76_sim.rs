//! What a fresh user still tripped on after stop 75 in `simulate` and
//! `metrics`, run as a user runs the tool: a sine so slow it steers a few
//! percent of its amplitude, a steer pulse read as no steer at all, a
//! replay that dropped the piece holding its step, compared angles
//! printed equal, and a `.tir` beyond any tyre's friction simulated
//! without the warning `tyre-eval` gives.

use super::*;

/// The bundled sedan (Gim tyres) with `manoeuvre` as its `[manoeuvre]`
/// table, written to `dir/<name>.toml`.
fn sedan_with(dir: &Path, name: &str, manoeuvre: &str) -> PathBuf {
    let text = bundled_scenario("sedan_step.toml");
    let head = text.split("[manoeuvre]").next().unwrap();
    let path = dir.join(format!("{name}.toml"));
    fs::write(&path, format!("{head}[manoeuvre]\n{manoeuvre}")).unwrap();
    path
}

/// `simulate <scenario> --out <dir>/<out>`: its stdout, or a panic with
/// its stderr.
fn simulated(scenario: &Path, out: &str) -> String {
    let out = scenario.with_file_name(out);
    succeeds(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

/// A sine of 0.001 Hz over 10 s steered 0.0063 rad of its 0.1 rad (6 %:
/// a slow ramp) and ran without a word, as did a sweep to 0.0004 Hz
/// (1.3 %): the refusal had only an absolute floor. Both are refused with
/// the share reached and the least frequency that reaches 10 %, and that
/// frequency, typed back, runs.
#[test]
fn a_sine_or_sweep_that_reaches_a_few_percent_of_its_amplitude_is_refused_with_the_share() {
    let dir = tempfile::tempdir().unwrap();
    let sine = "kind = \"sine\"\nspeed = 20.0\namplitude = 0.1\nfrequency = 0.001\nstart = 0.0\nend = 10.0\n";
    let path = sedan_with(dir.path(), "slow", sine);
    let e = fails_cleanly("simulate", &path, dir.path());
    for said in [
        "slow.toml:23:13: `manoeuvre.frequency` = 0.001: a sine of `frequency` = 0.001 Hz has a period of 1000 s against a run of 10 s",
        "within it the steer reaches only 0.0063 rad (0.36°), 6.3 % of its `amplitude` = 0.1 rad (5.73°), less than the 10 % a sine must reach to be one: the steer is a slow ramp",
        "`frequency` ≥ 0.0016 Hz reaches 10 % of it",
        "(`frequency` ≥ 0.025 Hz): is the frequency in Hz?",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    let sweep = sine
        .replace("sine", "sweep")
        .replace("frequency = 0.001", "f_start = 0.0\nf_end = 0.0004");
    let path = sedan_with(dir.path(), "slow_sweep", &sweep);
    let e = fails_cleanly("simulate", &path, dir.path());
    for said in [
        "slow_sweep.toml:24:9: `manoeuvre.f_end` = 0.0004: a sweep",
        "1.3 % of its `amplitude` = 0.1 rad (5.73°), less than the 10 % a sweep must reach",
        "`f_start` + `f_end` ≥ 0.0032 Hz reaches 10 % of it",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    // The least frequency said, typed back, runs.
    let path = sedan_with(dir.path(), "least", &sine.replace("0.001", "0.0016"));
    simulated(&path, "ran");
}

/// `metrics` on a 1° steer pulse (stepped at 1.0 s, back at 1.5 s) said
/// "the steer stays at 0 rad (0.00°) from the initial window to the
/// steady one": true of the windows, silent on the pulse between them.
/// The pulse is named by its size, start and duration, with why the
/// metrics need a held step.
#[test]
fn metrics_names_a_steer_pulse_and_why_it_needs_a_held_step() {
    let dir = tempfile::tempdir().unwrap();
    let pulse = "kind = \"schedule\"\nt = [0.0, 1.0, 1.1, 1.4, 1.5, 6.0]\nsteer = [0.0, 0.0, 0.0174533, 0.0174533, 0.0, 0.0]\nspeed = [22.2222, 22.2222, 22.2222, 22.2222, 22.2222, 22.2222]\n";
    let path = sedan_with(dir.path(), "pulse", pulse);
    simulated(&path, "run");
    let history = dir.path().join("run").join("history.csv");
    let o = run(&["metrics", history.to_str().unwrap()]);
    assert!(!o.status.success(), "a pulse was measured as a step");
    let e = stderr(&o);
    for said in [
        "no steer step: the steer is a pulse, not a step: a pulse of 0.0175 rad (1.00°) from 0 rad (0.00°), from 1.05 s for 0.40 s (times at half its size), back to 0 rad (0.00°) in the steady window",
        "the step-steer metrics (GB/T 6323 / ISO 7401 step input) read the response to a steer held after its step",
        "hold the steer after the step to the record's end, at least the last `steady_window` = 1 s",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    assert!(!e.contains("stays at"), "{e}");
}

/// The sedan's 1° step held for 12 s, logged at 100 Hz with no rows
/// from 3 to 4 s, as `dir/gap_run.csv` with a replay scenario beside it.
fn gapped_run(dir: &Path) -> PathBuf {
    let step = "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 12.0\n";
    let sc = sedan_with(dir, "long", step);
    simulated(&sc, "long");
    let text = fs::read_to_string(dir.join("long").join("history.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for l in lines.step_by(10) {
        let v: Vec<&str> = l.split(',').collect();
        let t: f64 = v[at("t")].parse().unwrap();
        if t > 3.0 + 1e-9 && t < 4.0 - 1e-9 {
            continue;
        }
        let cols = ["t", "speed", "steer", "yaw_rate", "ay", "beta"].map(|c| v[at(c)]);
        csv += &format!("{}\n", cols.join(","));
    }
    fs::write(dir.join("gap_run.csv"), csv).unwrap();
    sedan_with(dir, "replay", "kind = \"replay\"\nrun = \"gap_run.csv\"\n")
}

/// A run with a 1 s time gap replayed its longer piece (4–12 s, the
/// steer held) and dropped the piece holding the step (0–3 s) with
/// "another piece was used", naming neither. The piece that moves the
/// steer is replayed, said by its span and samples, and the held one is
/// dropped saying why and how to replay it instead.
#[test]
fn a_replay_split_by_a_time_gap_replays_the_piece_that_holds_the_step() {
    let dir = tempfile::tempdir().unwrap();
    let sc = gapped_run(dir.path());
    let said = simulated(&sc, "out");
    // The pieces are named by the run's path, as the scenario resolves it.
    for (starts, ends) in [
        ("  cleaning: piece ", "gap_run.csv#2 (4.00–12.00 s, 801 samples) dropped: its steer holds at 0.017 rad throughout (it does not move; a step moves it by 0.00017 rad or more) while another piece moves it, and that piece is replayed; to replay this one, cut the run file to its span"),
        ("  cleaning: replayed piece ", "gap_run.csv#1 (0.00–3.00 s, 301 samples): the longest piece that moves the steer (a longer one holds it)"),
    ] {
        let found = said.lines().any(|l| l.starts_with(starts) && l.ends_with(ends));
        assert!(found, "{starts}…{ends}\n{said}");
    }
    assert!(!said.contains("another piece was used"), "{said}");
    // The replayed history is the step's piece.
    let history = fs::read_to_string(dir.path().join("out").join("history.csv")).unwrap();
    let last: f64 = history
        .lines()
        .last()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((last - 3.0).abs() < 1e-6, "the history ends at {last} s");
}

/// Two angles a sentence compares printed equal: "a change of 0.00015
/// rad (0.01°), less than the 0.00017 rad (0.01°)" in `metrics`, and
/// likewise a sine's steer against the least one; a sine's amplitude
/// 0.01 was written "0.0100 rad" beside "0.010°". Compared angles now
/// differ in print, and every angle has one format.
#[test]
fn compared_angles_print_apart_and_every_angle_in_one_format() {
    let dir = tempfile::tempdir().unwrap();
    let step = "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n";
    let sc = sedan_with(dir.path(), "step", step);
    simulated(&sc, "run");
    // The step scaled to 0.00015 rad, below the 0.000175 rad a step needs.
    let text = fs::read_to_string(dir.path().join("run").join("history.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let scale = 0.00015 / 0.0174533;
    let mut csv = String::from("t,speed,steer,yaw_rate,ay\n");
    for l in lines.step_by(10) {
        let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
        csv += &format!(
            "{},{},{},{},{}\n",
            v[at("t")],
            v[at("speed")],
            v[at("steer")] * scale,
            v[at("yaw_rate")] * scale,
            v[at("ay")] * scale
        );
    }
    let tiny = dir.path().join("tiny.csv");
    fs::write(&tiny, csv).unwrap();
    let e = stderr(&run(&["metrics", tiny.to_str().unwrap()]));
    assert!(
        e.contains("the steer goes from 0 rad (0.000°) in the initial window to 0.00015 rad (0.009°) in the steady one, a change of 0.00015 rad (0.009°), less than the 0.00017 rad (0.010°) a step steer needs"),
        "{e}"
    );
    let sine = "kind = \"sine\"\nspeed = 20.0\namplitude = 0.01\nfrequency = 0.0001\nstart = 0.0\nend = 10.0\n";
    let path = sedan_with(dir.path(), "slow", sine);
    let e = fails_cleanly("simulate", &path, dir.path());
    assert!(
        e.contains("the steer reaches only 0.000063 rad (0.004°), 0.63 % of its `amplitude` = 0.01 rad (0.57°), less than the 0.00017 rad (0.010°) a manoeuvre must steer"),
        "{e}"
    );
    assert!(!e.contains("0.0100 rad"), "{e}");
}

/// `simulate` on the public `FSAE_Defaults.tir` (|Fy|/Fz 3.37 at 250 N)
/// ran without the warning `tyre-eval` gives of it; both now say it.
#[test]
fn simulate_warns_of_a_tir_beyond_any_tyres_friction_as_tyre_eval_does() {
    let test = "simulate_warns_of_a_tir_beyond_any_tyres_friction_as_tyre_eval_does";
    let Some(tir) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let sc = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n{STEP}",
        tir.display()
    );
    let dir = scratch(&[
        ("scenario.toml", &sc),
        (
            "points.csv",
            "fz,kappa,alpha,camber,speed\n1000,0,0.05,0,20\n",
        ),
    ]);
    let peak = "the file's pure lateral force peaks at |Fy|/Fz = 3.37 at Fz = 250 N and slip angle";
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tir.to_str().unwrap(),
            "points.csv",
            "--out",
            "f.csv",
        ],
    );
    assert!(stderr(&o).contains(peak), "{}", stderr(&o));
    let said = simulated(&dir.path().join("scenario.toml"), "out");
    let line = said
        .lines()
        .find(|l| l.contains(peak))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.starts_with(
            "  warning: the front and rear tyres' .tir: the file's pure lateral force"
        ),
        "{line}"
    );
}
