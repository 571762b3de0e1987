//! The bundled sedan's step as the `metrics` and replay tests use it: the
//! scenario, its simulated history, and run files written from that
//! history (every n-th row, with a seeded noise where asked for), shared
//! by the tests of sessions 65, 69, 81 and 82.

use super::*;

/// The bundled sedan step steer (1° at 1.0–1.1 s, to 6 s) in `dir`, with
/// `extra` appended to its text.
pub(crate) fn sedan(dir: &Path, extra: &str) -> PathBuf {
    let path = dir.join("sedan_step.toml");
    fs::write(&path, bundled_scenario("sedan_step.toml") + extra).unwrap();
    path
}

/// The sedan's history (1 kHz, noise-free), simulated into `dir/run`.
pub(crate) fn sedan_history(dir: &Path) -> PathBuf {
    let sc = sedan(dir, "");
    let out = dir.join("run");
    succeeds(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    out.join("history.csv")
}

/// xorshift64* with Box–Muller: the same noise on every machine, so a
/// run file a test writes is the same every time.
struct Noise(u64);

impl Noise {
    fn new(seed: u64) -> Self {
        Noise(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).wrapping_add(1))
    }
    fn uniform(&mut self) -> f64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        ((x.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 + 0.5) / 2f64.powi(53)
    }
    fn gauss(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// What a run file adds to the history: white noise of deviation `yaw`
/// (rad/s) on the yaw rate and `ay` (m/s²) on the lateral acceleration
/// (seed `seed`), and `ay` times `ay_gain`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Noisy {
    pub(crate) yaw: f64,
    pub(crate) ay: f64,
    pub(crate) seed: u64,
    pub(crate) ay_gain: f64,
}

/// The run columns of `history` (a CSV with a header) at every `every`-th
/// row, as `t,speed,steer,yaw_rate,ay,beta`: the cells as they are
/// without `noisy`, else the yaw rate and `ay` changed as it says.
pub(crate) fn run_text(history: &Path, every: usize, noisy: Option<Noisy>) -> String {
    let text = fs::read_to_string(history).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let wanted = ["t", "speed", "steer", "yaw_rate", "ay", "beta"];
    let at: Vec<usize> = wanted
        .iter()
        .map(|w| header.iter().position(|h| h == w).unwrap())
        .collect();
    let mut noise = noisy.map(|n| (n, Noise::new(n.seed)));
    let mut out = wanted.join(",") + "\n";
    for line in lines.step_by(every) {
        let cells: Vec<&str> = line.split(',').collect();
        let mut row: Vec<String> = at.iter().map(|&i| cells[i].to_string()).collect();
        if let Some((n, noise)) = noise.as_mut() {
            let num = |k: usize| row[k].parse::<f64>().unwrap();
            let yr = num(3) + n.yaw * noise.gauss();
            let lat = (num(4) + n.ay * noise.gauss()) * n.ay_gain;
            row[3] = yr.to_string();
            row[4] = lat.to_string();
        }
        out += &(row.join(",") + "\n");
    }
    out
}

/// [`run_text`] with `noisy` written to `to`.
pub(crate) fn run_file(history: &Path, every: usize, noisy: Noisy, to: &Path) {
    fs::write(to, run_text(history, every, Some(noisy))).unwrap();
}
