//! What a fresh user tripped on (round 14), fixed by the lead: a sideslip
//! logged negated, with a logger's scatter, went unsaid by `metrics`.

use super::*;

/// A linear car's 0.05 rad step at 15 m/s, ramped over `rise` s, simulated
/// in `dir`: its `history.csv`.
fn step_history(dir: &Path, rise: f64) -> PathBuf {
    let scenario = format!("name = \"step\"\n[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 15.0\nsteer = 0.05\nstart = 1.0\nrise_time = {rise}\nend = 8.0\n");
    fs::write(dir.join("step.toml"), scenario).unwrap();
    for (axle, c) in [("front", 50000.0), ("rear", 70000.0)] {
        let tyre =
            format!("model = \"linear\"\ncornering_stiffness = {c}\npneumatic_trail = 0.03\n");
        fs::write(dir.join(format!("{axle}.toml")), tyre).unwrap();
    }
    let o = run_in(dir, &["simulate", "step.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    dir.join("out/history.csv")
}

/// `history` logged every `every` ms (its first six columns).
fn decimated(history: &Path, every: usize) -> String {
    let text = fs::read_to_string(history).unwrap();
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for line in text.lines().skip(1).step_by(every) {
        let c: Vec<&str> = line.split(',').take(6).collect();
        out.push_str(&c.join(","));
        out.push('\n');
    }
    out
}

/// The fresh-eyes round 16 found the sample interval's warnings short: a
/// 10 Hz log (its median interval a hair under 0.1 s) got no word on E_r
/// though the book says 10 Hz or slower is warned, and an instant step
/// logged at 20 Hz (E_r +63 %) none either. Both are said now, the
/// instant step's onset with its half-interval uncertainty.
#[test]
fn total_variances_of_a_coarse_log_or_an_unresolved_step_are_said() {
    let dir = tempfile::tempdir().unwrap();
    let said = |history: &Path, every: usize, name: &str| {
        let file = dir.path().join(name);
        fs::write(&file, decimated(history, every)).unwrap();
        let o = run(&["metrics", file.to_str().unwrap(), "--filter-hz", "0"]);
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o)
    };
    let ramped = step_history(&folder(dir.path(), "ramped"), 0.15);
    let s = said(&ramped, 100, "ramped_10hz.csv");
    assert!(
        s.contains("are integrals over samples 0.1 s apart (10 Hz)"),
        "{s}"
    );
    assert!(!s.contains("uncertain by about half an interval"), "{s}");
    let s = said(&ramped, 50, "ramped_20hz.csv");
    assert!(!s.contains("are integrals over samples"), "{s}");
    let instant = step_history(&folder(dir.path(), "instant"), 0.0);
    let s = said(&instant, 50, "instant_20hz.csv");
    assert!(
        s.contains("are integrals over samples 0.05 s apart (20 Hz)"),
        "{s}"
    );
    assert!(
        s.contains("is uncertain by about half an interval, ±0.025 s"),
        "{s}"
    );
}

/// The folder `name` made in `dir`.
fn folder(dir: &Path, name: &str) -> PathBuf {
    let f = dir.join(name);
    fs::create_dir_all(&f).unwrap();
    f
}

/// White noise of unit deviation, reproducible (xorshift64, Box–Muller).
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn gauss(&mut self) -> f64 {
        let r = (-2.0 * self.uniform().ln()).sqrt();
        r * (std::f64::consts::TAU * self.uniform()).cos()
    }
}

/// `history` at 100 Hz with logger noise (β 0.001 rad, yaw rate 0.002
/// rad/s, ay 0.05 m/s²) and β multiplied by `sign`.
fn logged(history: &Path, sign: f64) -> String {
    let text = fs::read_to_string(history).unwrap();
    let mut noise = Noise(0x9E37_79B9_7F4A_7C15);
    let mut out = String::from("t,steer,speed,beta,yaw_rate,ay\n");
    for line in text.lines().skip(1).step_by(10) {
        let c: Vec<f64> = line
            .split(',')
            .take(6)
            .map(|v| v.parse().unwrap())
            .collect();
        let beta = sign * c[3] + 0.001 * noise.gauss();
        let yaw = c[4] + 0.002 * noise.gauss();
        let ay = c[5] + 0.05 * noise.gauss();
        out.push_str(&format!(
            "{},{},{},{beta:.6},{yaw:.6},{ay:.5}\n",
            c[0], c[1], c[2]
        ));
    }
    out
}

/// A sideslip logged negated (steady +0.51° read as −0.51°) with a
/// 0.001 rad scatter went unsaid by `metrics`: β̇ over 0.1 s carried
/// 0.014 rad/s of noise, the size of the step's sideslip rate, and its
/// correlation with ay/u − r (−0.46) stayed above −0.5. The window is now
/// widened where the run's own scatter asks: −0.66, said; the same run
/// logged the right way round draws no warning.
#[test]
fn a_negated_sideslip_with_scatter_is_still_seen_against_the_kinematics() {
    let dir = tempfile::tempdir().unwrap();
    let history = step_history(dir.path(), 0.15);
    for (sign, name) in [(-1.0, "negated.csv"), (1.0, "right.csv")] {
        let file = dir.path().join(name);
        fs::write(&file, logged(&history, sign)).unwrap();
        let o = run(&["metrics", file.to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
        let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
        let k: Option<f64> = said
            .split("the sideslip turns against the car: its rate correlates at ")
            .nth(1)
            .and_then(|s| s.split(' ').next())
            .and_then(|s| s.parse().ok());
        match sign < 0.0 {
            true => assert!(
                k.is_some_and(|k| (-0.75..=-0.6).contains(&k)),
                "{k:?}: {said}"
            ),
            false => assert_eq!(k, None, "{said}"),
        }
    }
}
