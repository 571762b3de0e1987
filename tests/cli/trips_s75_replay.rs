//! A replayed run's gap read as a user reads it: a tenth of a
//! second's lag that the whole-run RMS dilutes, a sideslip bias below three
//! noise floors but many standard errors, a noisy first sample, and a speed
//! in mph where the run has no `ay` to judge it by.

use super::*;
use rand::SeedableRng;

/// The bundled sedan step's history (80 km/h, 1°), simulated into `dir`
/// once: (header, rows).
fn history(dir: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let out = dir.join("sim");
    if !out.join("history.csv").exists() {
        let o = run(&[
            "simulate",
            "scenarios/sedan_step.toml",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let text = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (head, rows)
}

/// How a logged run departs from the simulation it is made of.
#[derive(Clone, Copy, Default)]
struct Edit {
    /// The response channels later by this, s.
    shift: f64,
    /// Added to every sideslip, rad.
    beta_offset: f64,
    /// Added to the first yaw rate, rad/s.
    first_yaw: f64,
}

/// The sedan step logged at 100 Hz with `edit` applied and sensor noise
/// (yaw rate 0.002 rad/s, ay 0.05 m/s², sideslip 0.0005 rad; seeded), as
/// `run.csv` in `dir` with a replay scenario `replay.toml` beside it.
fn logged(dir: &Path, edit: Edit) -> PathBuf {
    let (head, rows) = history(dir);
    let at = |name: &str| head.iter().position(|h| h == name).unwrap();
    let (t, u, d) = (at("t"), at("speed"), at("steer"));
    let response = [at("yaw_rate"), at("ay"), at("beta")];
    let ts: Vec<f64> = rows.iter().map(|r| r[t]).collect();
    // A response column at time x (linear between the 1 ms rows).
    let value = |c: usize, x: f64| {
        let x = x.clamp(ts[0], ts[ts.len() - 1]);
        let i = ((x - ts[0]) / (ts[1] - ts[0])).floor() as usize;
        let i = i.min(ts.len() - 2);
        let f = (x - ts[i]) / (ts[i + 1] - ts[i]);
        rows[i][c] + f * (rows[i + 1][c] - rows[i][c])
    };
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(41);
    let mut noise = |s: f64| s * handling::identify::data::gauss(&mut rng);
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for (k, r) in rows.iter().step_by(10).enumerate() {
        let x = r[t] - edit.shift;
        let mut yaw = value(response[0], x) + noise(0.002);
        if k == 0 {
            yaw += edit.first_yaw;
        }
        let ay = value(response[1], x) + noise(0.05);
        let beta = value(response[2], x) + noise(0.0005) + edit.beta_offset;
        csv += &format!("{},{},{},{yaw},{ay},{beta}\n", r[t], r[u], r[d]);
    }
    let p = dir.join("run.csv");
    fs::write(&p, csv).unwrap();
    replay_scenario(&p);
    p
}

/// A replay scenario of `run` with the bundled sedan (its tyres found from
/// anywhere), `replay.toml` beside it.
fn replay_scenario(run: &Path) -> PathBuf {
    let base = fs::read_to_string(root().join("scenarios/sedan_step.toml")).unwrap();
    let base = base.replace("../tyres", root().join("tyres").to_str().unwrap());
    let head = &base[..base.find("[manoeuvre]").unwrap()];
    let sc = run.with_file_name("replay.toml");
    let text = format!(
        "{head}[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n",
        run.file_name().unwrap().to_str().unwrap()
    );
    fs::write(&sc, text).unwrap();
    sc
}

/// `simulate replay.toml` in `dir` into `out`: its stdout and gap.json.
fn replay(dir: &Path, out: &str) -> (String, serde_json::Value) {
    let o = run_in(dir, &["simulate", "replay.toml", "--out", out]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    (said, read_json(&dir.join(out).join("gap.json")))
}

/// A channel's line on the terminal and its entry in gap.json.
fn channel<'a>(
    said: &'a str,
    gap: &'a serde_json::Value,
    name: &str,
) -> (&'a str, &'a serde_json::Value) {
    let line = said
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{name}:")))
        .unwrap_or_else(|| panic!("no {name} line in {said}"));
    let entry = gap["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["channel"] == name)
        .unwrap();
    (line, entry)
}

#[test]
fn a_tenth_of_a_second_lag_is_a_gap_in_one_stretch_and_a_time_shift_of_0_10_s() {
    let dir = tempfile::tempdir().unwrap();
    logged(
        dir.path(),
        Edit {
            shift: 0.1,
            ..Edit::default()
        },
    );
    let (said, gap) = replay(dir.path(), "o");
    for name in ["yaw_rate", "ay"] {
        let (line, c) = channel(&said, &gap, name);
        // The whole run's RMS dilutes it (unchanged, as diagnose reads it:
        // ay's 2 noise floors, the yaw rate's 3.4 on this noise), the
        // step's first half second carries it.
        let whole = c["significant"].as_bool().unwrap();
        assert_eq!(whole, name == "yaw_rate", "{line}");
        assert_eq!(c["gap_found"], true, "{line}");
        let w = &c["worst_window"];
        assert_eq!(w["significant"], true, "{line}");
        let start = w["start"].as_f64().unwrap();
        assert!((0.75..=1.25).contains(&start), "{line}");
        assert!(
            (whole || line.contains("no significant gap over the whole run (RMS"))
                && line.contains("in one stretch: RMS")
                && line.contains(&format!("from t = {start:.2} s")),
            "{line}"
        );
        // The shift, in seconds and in words, with its sign.
        let shift = c["time_shift"].as_f64().unwrap();
        assert!((shift - 0.10).abs() < 0.01, "{shift}");
        assert!(
            line.contains("the measurement lags the simulation by 0.10 s"),
            "{line}"
        );
        // The residual's likeness to the steer is not read as a lag, nor
        // set against the shift that explains it.
        assert!(
            !line.contains("follows the steer") && !line.contains("not a time shift"),
            "{line}"
        );
    }
}

#[test]
fn a_sideslip_bias_of_one_and_a_half_noise_floors_is_many_standard_errors() {
    let dir = tempfile::tempdir().unwrap();
    // The sideslip's floor is a sensor's 0.005 rad: 1.5 floors.
    logged(
        dir.path(),
        Edit {
            beta_offset: 0.0075,
            ..Edit::default()
        },
    );
    let (said, gap) = replay(dir.path(), "o");
    let (line, c) = channel(&said, &gap, "beta");
    assert!(
        (c["noise_floor"].as_f64().unwrap() - 0.005).abs() < 1e-9,
        "{line}"
    );
    assert_eq!(c["significant"], false, "{line}");
    assert_eq!(c["bias_significant"], true, "{line}");
    let se = c["bias_standard_error"].as_f64().unwrap();
    // The replay starts from the offset sideslip and settles to the
    // model's: a slow residual, its autocorrelation counted (7.3).
    assert!(0.0075 / se > 5.0, "{se}");
    assert!(
        line.contains("a bias of -0.007") && line.contains(" standard errors of "),
        "{line}"
    );
    // The clean run: neither a bias nor a stretch in any channel.
    logged(dir.path(), Edit::default());
    let (said, gap) = replay(dir.path(), "clean");
    for name in ["yaw_rate", "ay", "beta"] {
        let (line, c) = channel(&said, &gap, name);
        assert_eq!(c["gap_found"], false, "{line}");
        assert!(
            line.starts_with(&format!("  {name}: no significant gap: RMS")),
            "{line}"
        );
    }
}

#[test]
fn a_noisy_first_sample_sets_off_no_transient() {
    let dir = tempfile::tempdir().unwrap();
    // Ten noise floors on the first yaw rate.
    logged(
        dir.path(),
        Edit {
            first_yaw: 0.02,
            ..Edit::default()
        },
    );
    let (said, gap) = replay(dir.path(), "o");
    let (line, c) = channel(&said, &gap, "yaw_rate");
    assert_eq!(c["gap_found"], false, "{line}");
    // The replay starts from the first 0.2 s, not from the wild sample.
    let h = fs::read_to_string(dir.path().join("o/history.csv")).unwrap();
    let head: Vec<&str> = h.lines().next().unwrap().split(',').collect();
    let r = head.iter().position(|x| *x == "yaw_rate").unwrap();
    let first: f64 = h
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(r)
        .unwrap()
        .parse()
        .unwrap();
    assert!(first.abs() < 0.002, "{first}");
}

/// A run at 10 → 25 m/s over 10 s (1.5 m/s²), straight, at 100 Hz, with
/// `columns` of t, speed (times `scale`), steer, yaw_rate and ax where
/// asked.
fn accelerating(dir: &Path, scale: f64, with_ax: bool) -> PathBuf {
    let mut csv = String::from(if with_ax {
        "t,speed,steer,yaw_rate,ax\n"
    } else {
        "t,speed,steer,yaw_rate\n"
    });
    for i in 0..=1000 {
        let t = 0.01 * i as f64;
        let u = 10.0 + 1.5 * t;
        // A gentle weave, for a run that steers and turns.
        let d = 0.005 * (std::f64::consts::TAU * 0.2 * t).sin();
        let r = u * d / 2.78 / (1.0 + 0.002 * u * u);
        csv += &format!("{t},{},{d},{r}", scale * u);
        csv += &if with_ax {
            ",1.5\n".to_string()
        } else {
            "\n".to_string()
        };
    }
    let p = dir.join("run.csv");
    fs::write(&p, csv).unwrap();
    replay_scenario(&p);
    p
}

#[test]
fn a_speed_in_mph_is_refused_by_ax_where_the_run_has_no_ay_and_said_unchecked_without_either() {
    let dir = tempfile::tempdir().unwrap();
    accelerating(dir.path(), 2.23694, true);
    let o = run_in(dir.path(), &["simulate", "replay.toml", "--out", "o"]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("run.csv:")
            && e.contains("column `speed`")
            && e.contains("`ax` integrated over")
            && e.contains("is `speed` in mph? divide it by 2.23694"),
        "{e}"
    );
    // In m/s it is replayed, and nothing is said of the speed's unit.
    accelerating(dir.path(), 1.0, true);
    let (said, _) = replay(dir.path(), "ms");
    assert!(!said.contains("could not be checked"), "{said}");
    // Without `ax` (and `ay`) the mph run passes, but says so, with numbers.
    accelerating(dir.path(), 2.23694, false);
    let (said, _) = replay(dir.path(), "unchecked");
    assert!(
        said.contains("note: the speed's unit could not be checked")
            && said.contains("neither `ay`")
            && said.contains("its speed runs 22.4–55.9 m/s"),
        "{said}"
    );
}
