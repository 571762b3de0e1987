//! What fresh users tripped on in session 93 (rounds 22 and 22B), fixed by
//! the lead: a log whose rate changes cut into one-sample pieces, Gim tyres'
//! straight running called degenerate.

use super::*;

/// A linear-range step of the tester's linear car, written at 200 Hz until
/// 3 s and at 20 Hz after (a logger that slows down between tests): the
/// book's rule split it at every 20 Hz interval, five of the median's, and
/// dropped 100 one-sample pieces. A change of rate is no time gap: the log
/// is one piece, and its steady yaw-rate gain is the closed form's.
#[test]
fn a_log_whose_rate_changes_is_not_cut_into_one_sample_pieces() {
    let dir = tempfile::tempdir().unwrap();
    let history = trips_s90_met::tester_step(dir.path(), 0.1, "");
    let path = trips_s94_met::rewritten(
        &history,
        dir.path(),
        "mixed.csv",
        "t,steer,speed,beta,yaw_rate,ay",
        |c| {
            let ms = trips_s94_met::millis(c);
            if ms < 3000 {
                ms % 5 == 0
            } else {
                ms % 50 == 0
            }
        },
        <[f64]>::to_vec,
    );
    let o = run(&["metrics", path.to_str().unwrap(), "--json"]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("0 in 0 pieces dropped") && e.contains("0 time gaps"),
        "{e}"
    );
    let (j, w) = trips_s90_met::measured(&path, &[]);
    // u/(l(1 + K u²)) of the tester's car at 25 m/s: 5.60416 1/s.
    let gain = j["yaw_rate_gain"].as_f64().unwrap();
    assert!((gain - 5.60416).abs() < 5e-3, "{gain} {w}");
}

/// The linear 2-DOF model's eigenvalues about straight running, axle
/// stiffnesses `cf`, `cr` (N/rad), speed `u`: the tester's car.
fn bicycle_eigenvalues(cf: f64, cr: f64, u: f64) -> [(f64, f64); 2] {
    let (m, iz, a, b) = (1530.0, 2315.0, 1.11, 1.67);
    let a11 = -(cf + cr) / (m * u);
    let a12 = (b * cr - a * cf) / (m * u * u) - 1.0;
    let a21 = (b * cr - a * cf) / iz;
    let a22 = -(a * a * cf + b * b * cr) / (iz * u);
    let (h, det) = (0.5 * (a11 + a22), a11 * a22 - a12 * a21);
    let disc = h * h - det;
    if disc >= 0.0 {
        [(h + disc.sqrt(), 0.0), (h - disc.sqrt(), 0.0)]
    } else {
        [(h, (-disc).sqrt()), (h, -(-disc).sqrt())]
    }
}

/// Gim tyres at zero slip: their exact force derivative dropped the slope
/// there (the force is zero by a branch), so straight running read
/// "degenerate" with eigenvalues 0, and at 33 m/s a saddle. Its
/// linearisation is the linear bicycle's with K per wheel: a stable focus
/// with the closed form's eigenvalues, at every speed.
#[test]
fn gim_tyres_run_straight_as_the_linear_bicycle_linearises() {
    let gim =
        "model = \"gim\"\ncornering_stiffness = 57296.0\ncontact_length = 0.18\nfriction = 1.0\n";
    let scenario = &format!("name = \"z\"\n{VEHICLE}[tyres]\nfront = \"gim.toml\"\nrear = \"gim.toml\"\n[sweep]\nsteer = 0.0\nfriction = 0.8\nspeed = {{ values = [40.0, 80.0, 120.0], unit = \"km/h\" }}\n[pso]\nseed = 1\n");
    let dir = scratch(&[("gim.toml", gim), ("z.toml", scenario)]);
    let path = dir.path().join("z.toml");
    let out = dir.path().join("out");
    let o = run(&[
        "equilibria",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(out.join("equilibria.csv")).unwrap();
    let mut rows = 0;
    for line in text.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        let (beta, r): (f64, f64) = (c[3].parse().unwrap(), c[4].parse().unwrap());
        if beta.abs() > 1e-9 || r.abs() > 1e-9 {
            continue;
        }
        rows += 1;
        let u: f64 = c[2].parse().unwrap();
        let want = bicycle_eigenvalues(2.0 * 57296.0, 2.0 * 57296.0, u);
        assert_eq!(c[5], "stable-focus", "{line}");
        let got = [(c[6], c[7]), (c[8], c[9])]
            .map(|(re, im)| (re.parse::<f64>().unwrap(), im.parse::<f64>().unwrap()));
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g.0 - w.0).abs() < 1e-6 * w.0.abs(),
                "{line} against {want:?}"
            );
            assert!(
                (g.1.abs() - w.1.abs()).abs() < 1e-6 * w.1.abs(),
                "{line} against {want:?}"
            );
        }
    }
    assert_eq!(rows, 3, "{text}");
}

/// A bad cell on a file's last row, behind a comment line and blank
/// lines: the reader's position of that record sits on the first line it
/// skipped, so `metrics` named line 803 for line 805 and `tyre-eval` line 4
/// for line 6. The error names the row's own line, in LF and CRLF files.
#[test]
fn a_bad_last_row_behind_comments_and_blank_lines_is_named_at_its_own_line() {
    let mut log = String::from("t,speed,steer,yaw_rate,ay\n");
    for i in 0..400 {
        log.push_str(&format!("{},25,0.01,0.05,1.2\n", f64::from(i) * 0.01));
    }
    log.push_str("# end of log\n\n4.00,25,0.01,abc,1.2\n");
    // Header on line 1, rows on 2..=401, the comment 402, blank 403.
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n\n\n\n4000,0,abc,0,20\n";
    for crlf in [false, true] {
        let fix = |s: &str| {
            if crlf {
                s.replace('\n', "\r\n")
            } else {
                s.to_string()
            }
        };
        let dir = scratch(&[("log.csv", &fix(&log)), ("points.csv", &fix(points))]);
        let o = run(&["metrics", dir.path().join("log.csv").to_str().unwrap()]);
        let e = stderr(&o);
        assert!(!o.status.success());
        assert!(e.contains("log.csv:404:4"), "crlf {crlf}: {e}");
        let out = dir.path().join("forces.csv");
        let o = run(&[
            "tyre-eval",
            "tyres/gim.toml",
            dir.path().join("points.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = stderr(&o);
        assert!(!o.status.success());
        assert!(e.contains("points.csv:6:3"), "crlf {crlf}: {e}");
    }
}

/// A time column under a unit or in a European logger's language: `time`
/// and `timestamp` got "did you mean `t`?", `Time [s]` and `Zeit` nothing.
#[test]
fn a_time_column_with_its_unit_or_in_german_gets_a_did_you_mean() {
    for header in ["Time [s]", "time [s]", "Zeit", "time"] {
        let log = format!("{header},speed,steer,yaw_rate\n0,25,0,0\n0.01,25,0,0\n");
        let dir = scratch(&[("log.csv", &log)]);
        let o = run(&["metrics", dir.path().join("log.csv").to_str().unwrap()]);
        let e = stderr(&o);
        assert!(!o.status.success());
        assert!(e.contains("did you mean `t`"), "{header}: {e}");
        assert!(e.contains(header), "{header}: {e}");
    }
}

/// A replay whose measured yaw rate carries a uniform offset of
/// 0.005 rad/s (and gyro-like noise): every 0.5 s window lies beyond what
/// noise reaches, yet the words said "a gap in one stretch" from the worst
/// of them. Now: a gap along the run, with the count of windows, and the
/// bias at its value.
#[test]
fn a_uniform_offset_is_said_along_the_run_not_in_one_stretch() {
    let dir = tempfile::tempdir().unwrap();
    let history = trips_s90_met::tester_step(dir.path(), 0.1, "");
    // A deterministic, zero-mean uniform noise (xorshift), deviation `s`.
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut noise = |s: f64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state as f64 / u64::MAX as f64 - 0.5) * s * 12f64.sqrt()
    };
    trips_s94_met::rewritten(
        &history,
        dir.path(),
        "biased.csv",
        "t,speed,steer,yaw_rate,ay,beta",
        |c| trips_s94_met::on_grid(c, 10),
        // history: t, steer, speed, beta, yaw_rate, ay.
        |c| {
            let (r, ay, beta) = (
                c[4] + 0.005 + noise(0.002),
                c[5] + noise(0.05),
                c[3] + noise(0.002),
            );
            vec![c[0], c[2], c[1], r, ay, beta]
        },
    );
    let scenario = format!(
        "name = \"rep\"\n{VEHICLE}[tyres]\nfront = \"linear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"replay\"\nrun = \"biased.csv\"\n"
    );
    let path = dir.path().join("replay.toml");
    fs::write(&path, scenario).unwrap();
    let out = dir.path().join("rep");
    let o = run(&[
        "simulate",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    let yaw = said
        .lines()
        .find(|l| l.contains("yaw_rate") && l.contains("gap"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(!yaw.contains("a gap in one stretch"), "{yaw}");
    assert!(yaw.contains("a gap along the run"), "{yaw}");
    // The bias is said at its value (the residual is simulated − measured:
    // −0.005 rad/s), to the noise's share.
    let bias: f64 = yaw
        .split("bias of ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{yaw}"));
    assert!((bias + 0.005).abs() < 5e-4, "{yaw}");
}

/// `cg_height = 0` was refused with "the static stability factor … is inf
/// g": a non-finite number in a message. It is said as what it is.
#[test]
fn a_cg_height_of_zero_is_refused_without_an_infinite_number() {
    let scenario =
        bundled_scenario("sedan_step.toml").replace("cg_height = 0.55", "cg_height = 0.0");
    assert!(scenario.contains("cg_height = 0.0"), "{scenario}");
    let dir = scratch(&[("s.toml", &scenario)]);
    let o = run(&[
        "simulate",
        dir.path().join("s.toml").to_str().unwrap(),
        "--out",
        dir.path().join("o").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(!o.status.success());
    assert!(
        e.contains("cg_height of 0 puts the centre of gravity on the road"),
        "{e}"
    );
    assert!(!e.contains("is inf") && !e.contains("inf g"), "{e}");
}

/// A quoted cell with a decimal comma (`"0,05"`, as a spreadsheet set to
/// German writes it into a CSV) was refused as "not a number" only; the
/// scenario reader already asks "a decimal comma?". A thousands separator
/// (`"4,000"`) is not taken for one.
#[test]
fn a_quoted_decimal_comma_in_a_csv_cell_is_named_as_one() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,\"0,05\",0,20\n\"4,000\",0,0.05,0,20\n";
    let dir = scratch(&[("points.csv", points)]);
    let out = dir.path().join("forces.csv");
    let o = run(&[
        "tyre-eval",
        "tyres/gim.toml",
        dir.path().join("points.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(!o.status.success());
    assert!(
        e.contains("points.csv:2:3") && e.contains("a decimal comma? write 0.05"),
        "{e}"
    );
    assert!(
        e.contains("points.csv:3:1") && e.contains("`4,000` is not a number"),
        "{e}"
    );
    assert!(!e.contains("write 4.000"), "{e}");
}

/// `[report] phase_portraits` entries were drawn whatever they held: a
/// portrait at −19.44 m/s ("u = -70.0 km/h"), at 0 m/s, at 30 rad of
/// steer. Each value is checked as a sweep's, at its own line and column.
#[test]
fn a_phase_portrait_at_an_absurd_condition_is_refused_at_its_key() {
    let base = bundled_scenario("equilibria_steer.toml");
    let entry = "{ steer = 0.1, friction = 0.8, speed = 19.4444 },";
    assert!(base.contains(entry), "{base}");
    for (bad, key, column) in [
        (
            "{ steer = 0.1, friction = 0.8, speed = -19.4444 },",
            "speed",
            42,
        ),
        ("{ steer = 0.1, friction = 0.8, speed = 0.0 },", "speed", 42),
        (
            "{ steer = 30.0, friction = 0.8, speed = 19.4444 },",
            "steer",
            13,
        ),
        (
            "{ steer = 0.1, friction = -1.0, speed = 19.4444 },",
            "friction",
            29,
        ),
    ] {
        let text = base.replace(entry, bad);
        let line = 1 + text.lines().position(|l| l.contains(bad)).unwrap();
        let dir = scratch(&[("s.toml", &text)]);
        let out = dir.path().join("o");
        let o = run(&[
            "equilibria",
            dir.path().join("s.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{bad}");
        assert!(e.contains(&format!("s.toml:{line}:{column}")), "{bad}: {e}");
        assert!(
            e.contains(&format!("phase_portraits[1].{key}")),
            "{bad}: {e}"
        );
        assert!(!out.exists(), "{bad}");
    }
}

/// `study` took a negative tolerance ("er = 0.13 ± -0.005: 0 map points
/// meet it"), a value given twice on a map axis, and refused `{ from, to,
/// count = 1 }` with "a step or count that gives none?". Each is refused
/// at its key with what is wrong.
#[test]
fn study_inputs_that_mean_nothing_are_refused_at_their_keys() {
    let base = bundled_scenario("sedan_study_coarse.toml");
    let cases = [
        (
            "tolerance = 0.005 }",
            "tolerance = -0.005 }",
            "inverse.targets[0].tolerance",
        ),
        (
            "front = { from = 200.0, to = 700.0, step = 100.0 }\nrear",
            "front = [200.0, 300.0, 200.0]\nrear",
            "stiffness.front[2]",
        ),
        (
            "front = { from = 200.0, to = 700.0, step = 100.0 }\nrear",
            "front = { from = 200.0, to = 700.0, count = 1 }\nrear",
            "stiffness.front.count",
        ),
    ];
    for (from, to, key) in cases {
        assert!(base.contains(from), "{from}");
        let text = base.replacen(from, to, 1);
        let dir = scratch(&[("s.toml", &text)]);
        let out = dir.path().join("o");
        let o = run(&[
            "study",
            dir.path().join("s.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{to}");
        assert!(e.contains(key), "{to}: {e}");
        let line = 1 + text
            .lines()
            .position(|l| l.contains(to.lines().next().unwrap()))
            .unwrap();
        assert!(e.contains(&format!("s.toml:{line}:")), "{to}: {e}");
    }
}

/// A log whose rate goes up (100 Hz, then 1000 Hz from 2 s): the low-pass
/// filter and the windows were designed at the median interval, 1 ms, and
/// ran ten times too slow over the step (response time 0.261 s read for
/// 0.132 s, E_r 0.0041 s for 0.024 s, without a word). The piece is now
/// put on one 1000 Hz grid and said so: it reads what the 1 kHz log reads.
#[test]
fn a_log_whose_rate_goes_up_reads_what_the_fast_log_reads() {
    let dir = tempfile::tempdir().unwrap();
    let history = trips_s90_met::tester_step(dir.path(), 0.1, "");
    let path = trips_s94_met::rewritten(
        &history,
        dir.path(),
        "up.csv",
        "t,steer,speed,beta,yaw_rate,ay",
        |c| trips_s94_met::millis(c) >= 2000 || trips_s94_met::on_grid(c, 10),
        <[f64]>::to_vec,
    );
    let (fast, _) = trips_s90_met::measured(&history, &[]);
    let (up, w) = trips_s90_met::measured(&path, &[]);
    assert!(w.contains("from 100 Hz to 1000 Hz"), "{w}");
    for key in ["yaw_rate_response_time", "yaw_rate_peak_time", "er"] {
        let (a, b) = (fast[key].as_f64().unwrap(), up[key].as_f64().unwrap());
        assert!((a - b).abs() < 0.02 * a, "{key}: {b} against {a}; {w}");
    }
}
