//! Round 28's `simulate` findings: an oversteering car on linear tyres
//! stepped above its critical speed with load transfer stalled
//! Dormand–Prince and was said as "a model that is not smooth", where the
//! same step without load transfer (or on RK4) is said as above its
//! critical speed; and the RK4 run printed a line per millisecond a wheel
//! was off the ground.

use super::*;

/// The tester's car: the sedan of [`VEHICLE`] on linear tyres of 100 kN/rad
/// per wheel in front and 40 kN/rad behind, stepped 0.001 rad at 45 m/s;
/// `extra` appended (an integrator table).
fn os45(extra: &str) -> tempfile::TempDir {
    let tyre = |c: &str| format!("model = \"linear\"\ncornering_stiffness = {c}\n");
    let sc = format!(
        "name = \"os45\"\n{VEHICLE}\n[tyres]\nfront = \"osF.toml\"\nrear = \"osR.toml\"\n\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 45.0\nsteer = 0.001\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n{extra}"
    );
    scratch(&[
        ("os45.toml", &sc),
        ("osF.toml", &tyre("100000.0")),
        ("osR.toml", &tyre("40000.0")),
    ])
}

/// K = (m/l)·(b/Cf − a/Cr) = (1530/2.78)·(1.67/200,000 − 1.11/80,000)
/// = −0.003041 rad/(m/s²), so √(−l/K) = 30.2 m/s, at the static axle
/// loads m·g·b/l = 9013 N and m·g·a/l = 5991 N. The old binary said
/// "the integration (Dormand–Prince) stalled at t = 2.686 s … a model
/// that is not smooth" with no word of the critical speed.
#[test]
fn a_stall_above_the_critical_speed_is_said_as_the_critical_speed() {
    let dir = os45("");
    let err = fails_cleanly("simulate", &dir.path().join("os45.toml"), dir.path());
    let (m, l, g): (f64, f64, f64) = (1530.0, 2.78, 9.80665);
    let k = m / l * (1.67 / 200_000.0 - 1.11 / 80_000.0);
    let critical = (-l / k).sqrt();
    assert!((critical - 30.24).abs() < 0.01, "{critical}");
    assert!(
        err.contains(&format!(
            "above its critical speed √(−l/K) = {critical:.1} m/s"
        )),
        "{err}"
    );
    let loads = format!(
        "{:.0} N front and {:.0} N rear",
        m * g * 1.67 / l,
        m * g * 1.11 / l
    );
    assert!(err.contains(&loads), "{loads} not in: {err}");
    assert!(err.contains("the step is at 45.0 m/s"), "{err}");
    assert!(
        err.contains("stalled at t = ") && err.contains("nothing is written"),
        "{err}"
    );
    assert!(!err.contains("forces far beyond any tyre's"), "{err}");
}

/// On RK4 the same step runs through; its wheels chatter on and off the
/// ground at each step as the car diverges: one line per wheel, with the
/// count and the first and last times (the old binary printed 112).
#[test]
fn many_lift_offs_of_a_wheel_are_one_line_with_their_count() {
    let dir = os45("\n[simulation]\nmethod = \"rk4\"\nstep = 0.001\n");
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("os45.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    let lines: Vec<&str> = said
        .lines()
        .filter(|l| l.contains("wheel lift-off"))
        .collect();
    assert!(!lines.is_empty() && lines.len() <= 4, "{lines:#?}");
    // Each wheel's count is its runs of rows at zero load in history.csv.
    let (head, rows) = numeric_csv(&out.join("history.csv"));
    for (wheel, col) in [
        ("front left", "fz_fl"),
        ("front right", "fz_fr"),
        ("rear left", "fz_rl"),
        ("rear right", "fz_rr"),
    ] {
        let c = column(&head, col);
        let off: Vec<bool> = rows.iter().map(|r| r[c] <= 0.0).collect();
        let runs = (0..off.len())
            .filter(|&i| off[i] && (i == 0 || !off[i - 1]))
            .count();
        let line = lines.iter().find(|l| l.contains(&format!(": {wheel} off")));
        let said = line.map_or(0, |l| match l.split(" off the ground ").nth(1) {
            Some(rest) if rest.contains(" times between ") => {
                rest.split(' ').next().unwrap().parse::<usize>().unwrap()
            }
            _ => 1,
        });
        assert_eq!(said, runs, "{wheel}: {lines:#?}");
    }
    assert!(
        lines.iter().any(|l| l.contains(" times between ")),
        "{lines:#?}"
    );
}
