//! Last session's "noticed, not fixed" in figures, `metrics` and
//! `simulate`: a fit figure's ninth level drawn in a light blue within
//! ΔE 1.6 of the first level's pale points; a replay's measured dots in
//! full red over the model's line; a `--filter-hz` range suggested for a
//! slow log at whose low end the noise loses the yaw-rate peak; a stall's
//! advice on linear tyres that pointed to a run at 1.39 g, and that run
//! said nothing of passing the road's μ·g.

use super::calibration::Noise;
use super::trips_s91_diag::png_pixels;
use super::*;
use std::collections::HashMap;

/// CIE L*a*b* of an sRGB colour (D65), for the colour differences the
/// figures are judged by (CIE 15:2004; sRGB IEC 61966-2-1).
fn lab(c: [u8; 3]) -> [f64; 3] {
    let lin = |v: u8| {
        let v = f64::from(v) / 255.0;
        if v > 0.04045 {
            ((v + 0.055) / 1.055).powf(2.4)
        } else {
            v / 12.92
        }
    };
    let (r, g, b) = (lin(c[0]), lin(c[1]), lin(c[2]));
    let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    let d: f64 = 6.0 / 29.0;
    let f = |t: f64| {
        if t > d.powi(3) {
            t.cbrt()
        } else {
            t / (3.0 * d * d) + 4.0 / 29.0
        }
    };
    [
        116.0 * f(y) - 16.0,
        500.0 * (f(x) - f(y)),
        200.0 * (f(y) - f(z)),
    ]
}

/// The CIE76 colour difference of two sRGB colours.
fn delta_e(a: [u8; 3], b: [u8; 3]) -> f64 {
    let (p, q) = (lab(a), lab(b));
    (0..3).map(|i| (p[i] - q[i]).powi(2)).sum::<f64>().sqrt()
}

/// How many pixels of the PNG `path` are of each colour.
fn colour_counts(path: &Path) -> HashMap<[u8; 3], usize> {
    let (px, _, _) = png_pixels(path);
    let mut counts = HashMap::new();
    for p in px.chunks(3) {
        *counts.entry([p[0], p[1], p[2]]).or_insert(0) += 1;
    }
    counts
}

/// Rig rows `fz,alpha,fy,mz` at ten loads, 1000 to 6400 N, α ±8° in
/// steps of 0.1°: `fz·sin(1.4·atan(10·α))` and a 30 mm trail fading
/// past the peak.
fn ten_load_rig() -> String {
    let mut s = String::from("fz,alpha,fy,mz\n");
    for i in 0..10 {
        let fz = 1000.0 + 600.0 * f64::from(i);
        for k in -80..=80 {
            let alpha = (0.1 * f64::from(k)).to_radians();
            let fy = fz * (1.4 * (10.0 * alpha).atan()).sin();
            let mz = 0.03 * fy * (-(alpha / 0.1).powi(2)).exp();
            s += &format!("{fz},{alpha},{fy},{mz}\n");
        }
    }
    s
}

/// Before: a fit of ten loads drew the eighth load's line in light blue
/// (160, 196, 222), ΔE 1.6 from the pale tint (154, 194, 221) the first
/// load's points are drawn in: 3,579 and 2,211 px of two colours no
/// reader tells apart. Now the colours that cover the figure (every
/// level's fitted line and the most-drawn points, 1,500 px or more each)
/// stand more than ΔE 15 apart, nine line colours among them.
#[test]
fn a_fit_of_ten_loads_draws_no_line_in_a_colour_near_any_loads_points() {
    let dir = scratch(&[("rig.csv", &ten_load_rig())]);
    let o = run_in(
        dir.path(),
        &["identify", "rig.csv", "--model", "gim", "--out", "fit.toml"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let counts = colour_counts(&dir.path().join("fit.png"));
    // Chromatic colours only: white, black and the greys of the axes and
    // the key's swatches aside.
    let mut covering: Vec<([u8; 3], usize)> = counts
        .into_iter()
        .filter(|(c, n)| *n >= 1500 && c.iter().max().unwrap() - c.iter().min().unwrap() >= 20)
        .collect();
    covering.sort_by_key(|(_, n)| std::cmp::Reverse(*n));
    assert!(covering.len() >= 9, "{covering:?}");
    for (i, (a, na)) in covering.iter().enumerate() {
        for (b, nb) in &covering[i + 1..] {
            let d = delta_e(*a, *b);
            assert!(
                d > 15.0,
                "{a:?} ({na} px) and {b:?} ({nb} px) are ΔE {d:.1} apart"
            );
        }
    }
}

/// Before: a replay's measured samples were drawn as full red dots five
/// pixels wide, a thousand of them a band heavier than the model's line
/// over them (about 9,000 px of full red). Now they are drawn in red's pale
/// tint under the model's line in full blue: no full red at all.
#[test]
fn a_replays_measured_samples_are_pale_under_the_models_line() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = noisy_step_replay(dir.path(), 8.0, Noise(41), |n| {
        [0.002 * n.gauss(), 0.05 * n.gauss(), 0.001 * n.gauss()]
    });
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let counts = colour_counts(&out.join("response.png"));
    let px = |c: [u8; 3]| counts.get(&c).copied().unwrap_or(0);
    let (red, pale_red, blue) = (px([214, 39, 40]), px([237, 158, 158]), px([31, 119, 180]));
    assert_eq!(red, 0, "full red drawn: {red} px");
    assert!(pale_red > 2000, "pale samples: {pale_red} px");
    assert!(blue > 2000, "the model's lines: {blue} px");
}

/// A linear car stepped 1° at 25 m/s (6.2 % overshoot), its history
/// logged at 25 Hz with white noise of the
/// round-36 tester's log (yaw rate 0.002 rad/s, about 1.4 % of its step;
/// ay 0.05 m/s²; sideslip 0.001 rad; steer 0.0002 rad; speed 0.05 m/s),
/// seeded `seed`; written to `dir/log25.csv`.
fn noisy_25hz_log(dir: &Path, seed: u64) -> PathBuf {
    let sc = format!(
        "name = \"lin\"\n{}[manoeuvre]\nkind = \"step-steer\"\nspeed = 25.0\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n[simulation]\nstep = 0.001\n",
        linear_sedan("lin.toml")
    );
    fs::write(dir.join("lin.toml"), LINEAR_1000_PER_DEG).unwrap();
    fs::write(dir.join("s.toml"), sc).unwrap();
    let out = dir.join("sim");
    succeeds(&[
        "simulate",
        dir.join("s.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let history = fs::read_to_string(out.join("history.csv")).unwrap();
    let mut noise = Noise(seed);
    let mut csv = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    // History columns: t, steer, speed, beta, yaw_rate, ay.
    for line in history.lines().skip(1).step_by(40) {
        let c: Vec<f64> = line
            .split(',')
            .take(6)
            .map(|v| v.parse().unwrap())
            .collect();
        let mut n = |s: f64| s * noise.gauss();
        csv += &format!(
            "{:.2},{:.4},{:.6},{:.6},{:.5},{:.6}\n",
            c[0],
            c[2] + n(0.05),
            c[1] + n(0.0002),
            c[4] + n(0.002),
            c[5] + n(0.05),
            c[3] + n(0.001)
        );
    }
    written(dir, "log25.csv", &csv)
}

/// `metrics log --filter-hz f`: whether its yaw-rate peak was found and
/// not said to be flat within the noise, and all it said.
fn peak_holds_at(log: &Path, f: f64) -> (bool, String) {
    let (j, warnings) = super::trips_s90_met::measured(log, &["--filter-hz", &f.to_string()]);
    let found = !j["yaw_rate_peak_time"].is_null();
    (
        found && !warnings.contains("flat within the noise"),
        warnings,
    )
}

/// The number after `head` in `said`, up to " Hz".
fn hz_after(said: &str, head: &str) -> Option<f64> {
    said.split(head).nth(1)?.split(" Hz").next()?.parse().ok()
}

/// Before: the default 10 Hz on a 25 Hz log suggested "--filter-hz from
/// 6.5 Hz to below 10 Hz" by the filter's rise alone; at 6.5 Hz 9 of the
/// 32 noisy copies of the tester's log lost the peak (and the metrics
/// warned of it); on this log "from 6.1 Hz", where the metrics say the
/// peak is flat within the noise, and 5.5 Hz keeps it. Now every cut-off suggested is measured through: a
/// range is one at whose ends the peak holds, and where the rise's least
/// cut-off loses it, that is said with the highest cut-off that keeps it,
/// which keeps it, and the least, which does not.
#[test]
fn a_cutoff_suggested_for_a_slow_noisy_log_keeps_its_yaw_rate_peak() {
    let dir = tempfile::tempdir().unwrap();
    let log = noisy_25hz_log(dir.path(), 2);
    let (_, said) = super::trips_s90_met::measured(&log, &[]);
    assert!(
        said.contains("is not below 0.4 × the run's sampling rate"),
        "{said}"
    );
    if let Some(least) = hz_after(&said, "--filter-hz from ") {
        // A range: the peak holds at both its ends (below 10 Hz).
        let top = match hz_after(&said, &format!("from {least} Hz to below ")) {
            Some(limit) => limit - 0.5,
            None => {
                hz_after(&said, &format!("from {least} Hz to ")).unwrap_or_else(|| panic!("{said}"))
            }
        };
        for f in [least, top] {
            let (holds, w) = peak_holds_at(&log, f);
            assert!(
                holds,
                "suggested {f} Hz loses the peak: {w}\nadvice: {said}"
            );
        }
    } else {
        // None keeps both: the rise's least cut-off loses the peak, the
        // highest said to keep it does.
        let least = hz_after(&said, "the yaw-rate peak above the run's noise (at ")
            .unwrap_or_else(|| panic!("neither a range nor none: {said}"));
        let keeps = hz_after(&said, "it stands above the noise at ")
            .unwrap_or_else(|| panic!("no cut-off that keeps the peak: {said}"));
        assert!(keeps < least, "{said}");
        let (holds, w) = peak_holds_at(&log, keeps);
        assert!(holds, "{keeps} Hz said to keep the peak: {w}");
        let (holds, w) = peak_holds_at(&log, least);
        assert!(!holds, "{least} Hz said to lose the peak keeps it: {w}");
    }
}

/// [`VEHICLE`] with its mass rearward (a = 1.67 m, b = 1.11 m), on linear
/// tyres of 57 296 N/rad with load transfer, stepped 1° at `speed`.
fn rearward_step(speed: f64) -> String {
    let vehicle = VEHICLE.replace("a = 1.11\nb = 1.67\n", "a = 1.67\nb = 1.11\n");
    format!("name = \"os\"\n{vehicle}[tyres]\nfront = \"lin.toml\"\n[manoeuvre]\nkind = \"step-steer\"\nspeed = {speed:?}\nsteer = 0.0174533\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n")
}

/// `simulate dir/name` of `text`: whether it ran, and all it said.
fn simulated(dir: &Path, name: &str, text: &str) -> (bool, String) {
    fs::write(dir.join(name), text).unwrap();
    let o = run_in(dir, &["simulate", name, "--out", &format!("{name}.out")]);
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    (o.status.success(), said)
}

/// Before: the 1° step at 30 m/s that stalls on linear tyres was advised
/// "or of 1.00° below 26.5 m/s", and that run reached 13.6 m/s² (1.39 g)
/// with no word of the road. Now that run is said to pass the road's μ·g
/// on tyres with no limit, and the advice adds the speed that keeps the
/// steady turn within μ·g, √(g·l/(δ − g·K)) = 24.9 m/s, whose run stays
/// within it and is said nothing of.
#[test]
fn a_stall_on_linear_tyres_is_advised_a_step_within_the_roads_grip() {
    let lin = "model = \"linear\"\ncornering_stiffness = 57296.0\n";
    let dir = scratch(&[("lin.toml", lin)]);
    let (ran, err) = simulated(dir.path(), "s.toml", &rearward_step(30.0));
    assert!(!ran && err.contains("stalled at t = "), "{err}");
    let road = err
        .split("a step of at most 0.22° at 30.0 m/s, or of 1.00° below ")
        .nth(1)
        .and_then(|r| r.split(" m/s, keeps it within that too").next())
        .and_then(|v| v.parse::<f64>().ok())
        .unwrap_or_else(|| panic!("no speed within μ·g in: {err}"));
    let (m, l, g, c): (f64, f64, f64, f64) = (1530.0, 2.78, 9.80665, 2.0 * 57_296.0);
    let k = m / l * (1.11 / c - 1.67 / c);
    let within = (g * l / (0.0174533 - g * k)).sqrt();
    assert!(
        (road - within).abs() < 0.1 && road <= within,
        "{road} {within}"
    );
    assert!(
        err.contains("on the road, whose friction 1 gives 9.8 m/s² (1.00 g)"),
        "{err}"
    );
    // The speed that only keeps the car on four wheels: it runs, and
    // passes μ·g, said.
    let (ran, said) = simulated(dir.path(), "lift.toml", &rearward_step(26.4));
    assert!(ran, "{said}");
    let line = said
        .lines()
        .find(|l| {
            l.contains("(μ·g) this road can give") && l.contains("no friction limit of their own")
        })
        .unwrap_or_else(|| panic!("no word of μ·g: {said}"));
    assert!(
        line.contains(
            "linear (Fy = C·α), with no friction limit of their own, and |ay| reaches 13."
        ),
        "{line}"
    );
    // The speed within μ·g: its steady ay is below g, and nothing said.
    let (ran, said) = simulated(dir.path(), "road.toml", &rearward_step(road - 0.1));
    assert!(ran, "{said}");
    assert!(!said.contains("this road can give"), "{said}");
    let metrics = read_json(&dir.path().join("road.toml.out/metrics.json"));
    let ay = metrics["ay_steady"].as_f64().unwrap();
    assert!(ay < g, "{ay}");
}
