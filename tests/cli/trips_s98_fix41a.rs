//! What a fresh user tripped on in round 28 (session 98) with the inputs
//! of `identify`, `tyre-eval` and `metrics`: a column under another name
//! of a read one (`gamma`, `slip_angle`, `sideslip`) ignored silently, a
//! 1.5 Hz sine steer in m/s refused as a speed in mph, every third row of
//! a log missing said as a change of rate, a first row of decimal commas
//! called a row of units, and `--degrees` refusing a comma list.

use super::trips_s90_met::tester_step;
use super::trips_s94_met::{history_rows, written};
use super::*;

/// The tester's step (25 m/s, 0.01 rad at 1 s) as a 100 Hz log with the
/// columns t, speed, steer, yaw_rate, ay and a sideslip under `beta_name`,
/// the rows `keep` says, each row's values through `edit`; in `dir/name`.
fn step_log(
    dir: &Path,
    name: &str,
    beta_name: &str,
    keep: impl Fn(usize) -> bool,
    edit: impl Fn(&mut [f64; 6]),
) -> PathBuf {
    let history = dir.join("sim/history.csv");
    if !history.exists() {
        tester_step(dir, 0.08, "");
    }
    // history: t, steer, speed, beta, yaw_rate, ay.
    let rows = history_rows(&history);
    let lines = rows
        .iter()
        .step_by(10)
        .enumerate()
        .filter(|(i, r)| r[0] <= 8.0 + 1e-9 && keep(*i))
        .map(|(_, r)| {
            let mut v = [r[0], r[2], r[1], r[4], r[5], r[3]];
            edit(&mut v);
            v.map(|x| format!("{x}")).join(",")
        });
    let header = format!("t,speed,steer,yaw_rate,ay,{beta_name}");
    written(dir, name, &header, lines)
}

/// A rig file of a linear tyre (60 000 N/rad) at 4000 N over ±5°, at 0
/// and then 0.03 rad of camber under the column `camber_name`.
fn rig(dir: &Path, camber_name: &str) -> PathBuf {
    let lines = (0..2).flat_map(|k| {
        (0..=100).map(move |i| {
            let alpha = (f64::from(i) - 50.0) / 50.0 * 5f64.to_radians();
            let t = f64::from(k * 101 + i) * 0.01;
            format!(
                "{t},4000,{alpha},{},{}",
                f64::from(k) * 0.03,
                -60000.0 * alpha
            )
        })
    });
    let header = format!("t,fz,alpha,{camber_name},fy");
    written(dir, &format!("rig_{camber_name}.csv"), &header, lines)
}

#[test]
fn a_column_under_another_name_of_a_read_one_is_named_never_ignored() {
    let dir = tempfile::tempdir().unwrap();
    // identify: `gamma` and `inclination` pooled two cambers as 0.
    for name in ["gamma", "inclination"] {
        let p = rig(dir.path(), name);
        let out = dir.path().join(format!("fit_{name}"));
        let o = identify_to(&p, "linear", &out);
        let e = stderr(&o);
        assert!(
            !o.status.success(),
            "{}",
            String::from_utf8_lossy(&o.stdout)
        );
        assert!(
            e.contains(&format!(
                ":1:4: column `{name}` is not one this command reads: did you mean `camber`?"
            )),
            "{e}"
        );
    }
    // tyre-eval: each input under another name, with the one meant.
    linear_tyre(dir.path());
    let tyre = dir.path().join("tyre.toml");
    for (header, found, meant) in [
        ("fz,kappa,alpha,gamma,speed", "gamma", "camber"),
        ("fz,kappa,slip_angle,camber,speed", "slip_angle", "alpha"),
        ("fz,slip_ratio,alpha,camber,speed", "slip_ratio", "kappa"),
    ] {
        let p = written(
            dir.path(),
            "points.csv",
            header,
            ["4000,0,0.05,0,16.7".to_string()].into_iter(),
        );
        let out = dir.path().join("eval.csv");
        let o = run(&[
            "tyre-eval",
            tyre.to_str().unwrap(),
            p.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = stderr(&o);
        assert!(!o.status.success());
        assert!(
            e.contains(&format!("missing required column `{meant}`"))
                && e.contains(&format!("`{found}`: did you mean `{meant}`?")),
            "{e}"
        );
    }
    // metrics: a `sideslip` left unread is said with what goes without it.
    let p = step_log(dir.path(), "sideslip.csv", "sideslip", |_| true, |_| {});
    let o = run(&["metrics", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("column `sideslip` is not one a run has: did you mean `beta`?"),
        "{e}"
    );
    let text = fs::read_to_string(&p)
        .unwrap()
        .replacen("steer", "steering_angle", 1);
    fs::write(&p, text).unwrap();
    let e = stderr(&run(&["metrics", p.to_str().unwrap()]));
    assert!(
        e.contains("missing required column `steer`")
            && e.contains("`steering_angle`: did you mean `steer`?"),
        "{e}"
    );
}

/// The tester's 1.5 Hz sine steer (0.0122 rad at 25 m/s, linear tyres of
/// 50 000 and 70 000 N/rad): `ay/(u·r)` sits at 0.55 there, `ay/(u·(r +
/// β̇))` at 1. Replayed in m/s it is read; in mph it is refused, and so is
/// a step in mph without a `beta` to read β̇ from.
#[test]
fn a_fast_sine_in_m_s_is_read_and_a_speed_in_mph_still_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(
        d.join("linF.toml"),
        "model = \"linear\"\ncornering_stiffness = 50000.0\n",
    )
    .unwrap();
    fs::write(
        d.join("linR.toml"),
        "model = \"linear\"\ncornering_stiffness = 70000.0\n",
    )
    .unwrap();
    let car = format!("{VEHICLE}[tyres]\nfront = \"linF.toml\"\nrear = \"linR.toml\"\n");
    let sine = format!("name = \"sine15\"\n{car}[manoeuvre]\nkind = \"sine\"\nspeed = 25.0\namplitude = 0.0122\nfrequency = 1.5\nstart = 1.0\nend = 10.0\n");
    fs::write(d.join("sine15.toml"), sine).unwrap();
    scenarios::simulate_to(&d.join("sine15.toml"), &d.join("sim15"));
    // history: t, steer, speed, beta, yaw_rate, ay.
    let rows = history_rows(&d.join("sim15/history.csv"));
    let header = "t,steer,speed,beta,yaw_rate,ay";
    let log = |name: &str, factor: f64| {
        let lines = rows.iter().map(move |r| {
            let v = [r[0], r[1], r[2] * factor, r[3], r[4], r[5]];
            v.map(|x| format!("{x}")).join(",")
        });
        written(d, name, header, lines)
    };
    let replay = |run: &Path, name: &str| {
        let text = format!(
            "name = \"{name}\"\n{car}[manoeuvre]\nkind = \"replay\"\nrun = \"{}\"\n",
            run.file_name().unwrap().to_str().unwrap()
        );
        fs::write(d.join(format!("{name}.toml")), text).unwrap();
        let out = d.join(format!("out_{name}"));
        run_in(
            d,
            &[
                "simulate",
                &format!("{name}.toml"),
                "--out",
                out.to_str().unwrap(),
            ],
        )
    };
    let o = replay(&log("si.csv", 1.0), "si");
    assert!(o.status.success(), "{}", stderr(&o));
    let o = replay(&log("mph.csv", 2.23694), "mph");
    let e = stderr(&o);
    assert!(!o.status.success());
    assert!(
        e.contains("column `speed`: 55.9") && e.contains("is `speed` in mph?"),
        "{e}"
    );
    // Without `beta`: a step's steady turn says the unit.
    let p = step_log(d, "step_mph.csv", "beta", |_| true, |v| v[1] *= 2.23694);
    let text: String = fs::read_to_string(&p)
        .unwrap()
        .lines()
        .map(|l| l.rsplit_once(',').unwrap().0.to_string() + "\n")
        .collect();
    fs::write(&p, text).unwrap();
    let e = stderr(&run(&["metrics", p.to_str().unwrap()]));
    assert!(
        e.contains("column `speed`: 55.9") && e.contains("is `speed` in mph?"),
        "{e}"
    );
}

#[test]
fn rows_dropped_in_a_pattern_are_counted_and_the_peak_names_its_own_hole() {
    let dir = tempfile::tempdir().unwrap();
    // Every third row of the 100 Hz log dropped: 267 of 801.
    let p = step_log(dir.path(), "drop3.csv", "beta", |i| i % 3 != 1, |_| {});
    let o = run(&["metrics", p.to_str().unwrap()]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(!e.contains("rate changes"), "{e}");
    assert!(
        e.contains("the log misses 267 samples in 267 holes in time, 1 of every 3 rows throughout"),
        "{e}"
    );
    // The peak's words name the hole it lies in or beside.
    let said = e
        .lines()
        .find(|l| l.contains("largest value lies at"))
        .unwrap();
    let num = |after: &str| -> f64 {
        let rest = &said[said.find(after).unwrap() + after.len()..];
        rest.split(' ').next().unwrap().parse().unwrap()
    };
    let (at, from, to) = (num("lies at "), num(" from "), num(" to "));
    assert!(from - 0.011 <= at && at <= to + 0.011, "{said}");
}

#[test]
fn a_first_row_of_decimal_commas_is_told_of_its_commas() {
    let rows: String = (0..10)
        .map(|i| {
            format!(
                "\"{},000000\",\"25,000000\",\"0,000000\",\"0,000000\",\"0,000000\"\n",
                i
            )
        })
        .collect();
    let text = format!("\"t\",\"speed\",\"steer\",\"yaw_rate\",\"ay\"\n{rows}");
    let dir = scratch(&[("quoted.csv", &text)]);
    let e = stderr(&run(&[
        "metrics",
        dir.path().join("quoted.csv").to_str().unwrap(),
    ]));
    assert!(!e.contains("a row of units"), "{e}");
    assert!(
        e.contains("quoted.csv:2:1: column `t`: `0,000000` is not a number: a decimal comma? write 0.000000"),
        "{e}"
    );
}

#[test]
fn degrees_are_taken_as_a_comma_list() {
    let dir = tempfile::tempdir().unwrap();
    let si = step_log(dir.path(), "si.csv", "beta", |_| true, |_| {});
    let deg = step_log(
        dir.path(),
        "deg.csv",
        "beta",
        |_| true,
        |v| {
            for k in [2, 3, 5] {
                v[k] = v[k].to_degrees();
            }
        },
    );
    let gain = |args: &[&str]| {
        let o = run(args);
        assert!(o.status.success(), "{}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout).into_owned();
        out.lines()
            .find(|l| l.contains("yaw-rate gain"))
            .unwrap()
            .to_string()
    };
    let listed = gain(&[
        "metrics",
        deg.to_str().unwrap(),
        "--degrees",
        "steer,yaw_rate,beta",
    ]);
    assert_eq!(listed, gain(&["metrics", si.to_str().unwrap()]));
}
