//! Fresh-eyes round 20 (a tester on `7b41b8b`): the inverse of `study` for
//! a target other than Er, linear tyres on a slippery road, the phase
//! portrait's search box, and a backwards sweep range.

use super::*;

/// The steady yaw-rate gain u/(l·(1 + K·u²)) of the linear bicycle with
/// cornering stiffness `kf`, `kr` per tyre (N/deg), at `u` m/s.
fn closed_form_gain(kf: f64, kr: f64, u: f64) -> f64 {
    let (m, a, b) = (1530.0, 1.11, 1.67);
    let l: f64 = a + b;
    let (cf, cr) = (2.0 * kf.to_degrees(), 2.0 * kr.to_degrees());
    let k = m / (l * l) * (b / cf - a / cr);
    u / (l * (1.0 + k * u * u))
}

/// Before: an inverse target on the yaw-rate gain said "1 map points meet
/// it" and stopped there: no curve, no best point, though the gain 4.45
/// lies inside the map (only Er was traced). Now every metric is traced:
/// the best point re-simulates to the target, and the closed form agrees.
#[test]
fn a_yaw_rate_gain_target_is_traced_to_its_best_point() {
    let sedan = linear_sedan("tyre.toml");
    let study = format!(
        "name = \"gain\"\n{sedan}[manoeuvre]
kind = \"step-steer\"
speed = 22.2222
steer = 0.0174533
start = 0.5
rise_time = 0.1
end = 6.5
[stiffness]
unit = \"N/deg\"
front = {{ from = 400.0, to = 800.0, step = 200.0 }}
rear = {{ from = 400.0, to = 800.0, step = 200.0 }}
[inverse]
targets = [{{ metric = \"yaw_rate_gain\", value = 4.45, tolerance = 0.2 }}]
reference = {{ front = 500.0, rear = 540.0 }}
"
    );
    let dir = scratch(&[("study.toml", &study), ("tyre.toml", LINEAR_1000_PER_DEG)]);
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("yaw_rate_gain = 4.45 ± 0.2: 1 map point meets it and every constraint"),
        "{said}"
    );
    assert!(
        said.contains("  yaw_rate_gain = 4.45: a curve of 4 map points; closest to (500, 540) N/deg: (536.2, 508.9) with yaw_rate_gain 4.450000 (re-simulated)"),
        "{said}"
    );
    let inv = read_json(&dir.path().join("out/inverse.json"));
    let best = &inv["targets"][0]["best"];
    let (kf, kr) = (
        best["k_front"].as_f64().unwrap(),
        best["k_rear"].as_f64().unwrap(),
    );
    assert!(
        (best["resimulated"].as_f64().unwrap() - 4.45).abs() < 1e-5,
        "{best}"
    );
    // The step response's steady gain is the closed form's to 0.05 %.
    let gain = closed_form_gain(kf, kr, 22.2222);
    assert!(
        (gain / 4.45 - 1.0).abs() < 5e-4,
        "closed form {gain} at ({kf}, {kr})"
    );
    // No network answers a gain (Wang & Liang's maps Er alone).
    assert!(inv["targets"][0]["rbf"].is_null(), "{inv}");
}

/// Before: linear tyres on a road of friction 0.2 ran to 2.6 × μ·g in
/// `equilibria` and 2.1 × in `simulate` without a word. Now both say that
/// a linear tyre has no friction limit, and `simulate` by how far the run
/// went beyond the road.
#[test]
fn linear_tyres_on_a_slippery_road_are_said_to_ignore_its_friction() {
    let sedan = linear_sedan("tyre.toml");
    let sweep = format!(
        "name = \"lin_fric\"\n{sedan}[sweep]
steer = 0.05
friction = {{ values = [0.2, 0.5, 1.0] }}
speed = 20.0
"
    );
    let scenario = format!(
        "name = \"lin_sim\"\n{sedan}[road]
friction = 0.2
[manoeuvre]
kind = \"step-steer\"
speed = 22.2222
steer = 0.05
start = 0.5
rise_time = 0.1
end = 6.5
"
    );
    let dir = scratch(&[
        ("sweep.toml", &sweep),
        ("sim.toml", &scenario),
        ("tyre.toml", LINEAR_1000_PER_DEG),
    ]);
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "eq"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  note: the front and rear tyres are linear (Fy = C·α), with no friction limit: the road friction (0.2 to 1) does not change their forces, so every friction of the sweep gives the same equilibria"),
        "{said}"
    );
    let o = run_in(dir.path(), &["simulate", "sim.toml", "--out", "sim"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let all = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    // The closed form's steady ay, u·r = u²·δ/(l·(1 + K·u²)) = 6.01 m/s²,
    // 3.1 × μ·g; the run's largest |ay| is at least that.
    let steady = 22.2222 * 0.05 * closed_form_gain(1000.0, 1000.0, 22.2222);
    assert!((steady - 6.010).abs() < 1e-3, "{steady}");
    let line = all
        .lines()
        .find(|l| {
            l.contains("with no friction limit: the road friction 0.2 does not change their forces")
        })
        .unwrap_or_else(|| panic!("{all}"));
    let reached: f64 = line.split("|ay| reaches ").nth(1).unwrap()[..5]
        .parse()
        .unwrap();
    assert!(reached >= steady && reached < 1.1 * steady, "{line}");
    assert!(
        line.contains("× the 1.961 m/s² (μ·g) this road can give"),
        "{line}"
    );
    // At friction 1 a linear car is said nothing of.
    let plain = scenario.replace("friction = 0.2", "friction = 1.0");
    fs::write(dir.path().join("sim1.toml"), plain).unwrap();
    let o = run_in(dir.path(), &["simulate", "sim1.toml", "--out", "sim1"]);
    let all = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(!all.contains("no friction limit"), "{all}");
}

/// Before: the phase portrait drew twice the search box's yaw-rate range
/// with nothing to show where the box ends, while the book said the
/// trajectories run "until they leave the box". Now the box's |r| bound is
/// drawn as two dashed lines, half-way between the centre and the edges.
#[test]
fn the_phase_portrait_marks_the_search_box() {
    let sedan = linear_sedan("tyre.toml");
    let sweep = format!(
        "name = \"lin_steer\"\n{sedan}[sweep]
steer = {{ values = [0.0, 0.02] }}
friction = 0.8
speed = 20.0
[report]
phase_portraits = [ {{ steer = 0.02, friction = 0.8, speed = 20.0 }} ]
"
    );
    let dir = scratch(&[("sweep.toml", &sweep), ("tyre.toml", LINEAR_1000_PER_DEG)]);
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "eq"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let png = dir.path().join("eq/phase_portrait_0.png");
    let (rgb, w, h) = super::trips_s91_diag::png_pixels(&png);
    let black = |y: usize| {
        (0..w)
            .filter(|&x| rgb[3 * (y * w + x)..3 * (y * w + x) + 3] == [0, 0, 0])
            .count()
    };
    let counts: Vec<usize> = (0..h).map(black).collect();
    // The x axis: the longest black row, at the plot's foot.
    let foot = (0..h).max_by_key(|&y| counts[y]).unwrap();
    let longest = counts[foot];
    // Dashed rows: black over about half the axis's length.
    let dashed: Vec<usize> = (0..h)
        .filter(|&y| counts[y] > longest / 4 && counts[y] < 3 * longest / 4)
        .collect();
    assert!(dashed.len() >= 2, "no dashed line: {dashed:?}");
    let (top, bottom) = (dashed[0] as f64, *dashed.last().unwrap() as f64);
    // The lines at ±r_max of a plot spanning ±2·r_max: the foot lies one
    // line-to-line gap below the lower line's mirror.
    let (centre, half_gap) = (0.5 * (top + bottom), 0.5 * (bottom - top));
    assert!(
        (foot as f64 - (centre + 2.0 * half_gap)).abs() <= 4.0,
        "dashed rows {dashed:?}, foot {foot}"
    );
}

/// Before: `steer = { from = 0.04, to = 0.0, step = 0.01 }` was refused at
/// the step ("`sweep.steer` = 0.01: a range needs step > 0 and to ≥ from"),
/// which was valid. Now the refusal names the key that is wrong.
#[test]
fn a_backwards_sweep_range_is_refused_at_its_end() {
    let sedan = linear_sedan("tyre.toml");
    let text = |range: &str| {
        format!("name = \"r\"\n{sedan}[sweep]\nsteer = {range}\nfriction = 0.8\nspeed = 20.0\n")
    };
    let dir = scratch(&[
        ("back.toml", &text("{ from = 0.04, to = 0.0, step = 0.01 }")),
        ("zero.toml", &text("{ from = 0.0, to = 0.04, step = 0 }")),
        ("tyre.toml", LINEAR_1000_PER_DEG),
    ]);
    let o = run_in(dir.path(), &["equilibria", "back.toml", "--out", "o1"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("back.toml:16:29: `sweep.steer.to` = 0: below `from` (0.04): a range runs upward from `from` to `to` (swap them)"),
        "{}",
        stderr(&o)
    );
    let o = run_in(dir.path(), &["equilibria", "zero.toml", "--out", "o2"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o)
            .contains("zero.toml:16:41: `sweep.steer.step` = 0: a range's step must be positive"),
        "{}",
        stderr(&o)
    );
}

/// Before: a log with its `steer` and `beta` columns exchanged was
/// measured as it came (round 18: steady sideslip 1.0000°, gain −22.9 1/s
/// on a car of gain +5.4). Now the warning leads with the exchange, from
/// `beta`'s step read as a steer: at 15 m/s the linear car's gain is
/// u/(l·(1 + K·u²)) = 4.431 1/s, so the yaw rate follows it with r/(u·δ)
/// = 0.295 1/m, while the true sideslip, (b/l − m·a·u²/(l²·C_r))/(1 +
/// K·u²) = 0.139 of the steer, read as the steer gives 2.125 1/m, above
/// any car's.
#[test]
fn a_log_with_steer_and_beta_exchanged_is_said_to_look_so() {
    let dir = tempfile::tempdir().unwrap();
    let history = super::trips_s90_met::tester_step_at(dir.path(), 15.0, 0.1, "");
    let text = fs::read_to_string(history).unwrap();
    let write = |name: &str, swap: bool| {
        let mut out = String::from("t,speed,steer,yaw_rate,ay,beta\n");
        // History columns: t, steer, speed, beta, yaw_rate, ay; every
        // 10 ms.
        for line in text.lines().skip(1).step_by(10) {
            let c: Vec<&str> = line.split(',').collect();
            let (steer, beta) = if swap { (c[3], c[1]) } else { (c[1], c[3]) };
            out.push_str(&format!(
                "{},{},{steer},{},{},{beta}\n",
                c[0], c[2], c[4], c[5]
            ));
        }
        let path = dir.path().join(name);
        fs::write(&path, out).unwrap();
        path
    };
    let (_, w) = super::trips_s90_met::measured(&write("swapped.csv", true), &[]);
    assert!(
        w.starts_with("[\"`steer` and `beta` look exchanged: `steer` steps by 0.0014 rad, and the yaw rate answers it with r/(u·δ) = 2.125 1/m, no car's"),
        "{w}"
    );
    assert!(w.contains("while `beta` steps by 0.0100 rad"), "{w}");
    assert!(w.contains("r/(u·β) = 0.295 1/m"), "{w}");
    let (j, w) = super::trips_s90_met::measured(&write("right.csv", false), &[]);
    assert!(!w.contains("exchanged"), "{w}");
    let gain = j["yaw_rate_gain"].as_f64().unwrap();
    assert!((gain - 4.431).abs() < 2e-3, "{gain}");
}
