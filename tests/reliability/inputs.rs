//! Valid inputs in the formats of `FORMATS.md`, made here: a measured run
//! (a sine steer at constant speed with every optional channel), tyre rig
//! data, and a campaign folder that reads them.

use crate::{fs, Path};
use std::fmt::Write;

/// A measured run of `n` samples at `hz`: speed 20 m/s, a 0.5 Hz sine
/// steer of 0.03 rad and the steady responses of a neutral car.
pub fn run_csv(n: usize, hz: f64) -> String {
    let mut s = String::with_capacity(n * 96);
    s.push_str("t,speed,steer,yaw_rate,ay,beta,roll,bank,ax\n");
    for i in 0..n {
        let t = i as f64 / hz;
        let steer = 0.03 * (std::f64::consts::PI * t).sin();
        let r = 20.0 * steer / 2.78;
        writeln!(
            s,
            "{t:.4},{:.4},{steer:.6},{r:.6},{:.5},{:.6},{:.6},0.0,{:.4}",
            20.0 + 0.01 * (t * 0.1).sin(),
            20.0 * r,
            -0.2 * steer,
            0.01 * steer,
            0.05 * (t * 0.3).cos(),
        )
        .unwrap();
    }
    s
}

/// Tyre rig data: three loads, a slip sweep of ±0.2 rad each, with `mz`.
pub fn rig_csv() -> String {
    let mut s = String::from("fz,alpha,fy,mz,camber\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            writeln!(s, "{fz},{alpha},{fy:.3},{:.4},0.0", 0.02 * fy).unwrap();
        }
    }
    s
}

/// A campaign file (two runs, a linear tyre file) whose files are written
/// into `dir`; returns its text.
pub fn campaign(dir: &Path) -> String {
    fs::write(dir.join("a.csv"), run_csv(500, 50.0)).unwrap();
    fs::write(dir.join("b.csv"), run_csv(400, 50.0)).unwrap();
    let tyre = fs::read_to_string(crate::root().join("tyres/linear.toml")).unwrap();
    fs::write(dir.join("tyre.toml"), tyre).unwrap();
    "name = \"fuzzed\"

[vehicle]
mass = 1530.0
yaw_inertia = 2315.0
a = 1.11
b = 1.67
track_front = 1.55
track_rear = 1.55
cg_height = 0.55

[road]
friction = 1.0

[tyres]
file = \"tyre.toml\"

[runs]
files = [\"a.csv\", \"b.csv\"]
segment = 4.0

[diagnose]
seed = 1
min_speed = 5.0
"
    .to_string()
}

/// Copies the repository's `tyres/` folder into `dir/tyres`, so that a
/// scenario written to `dir/scenarios/` finds its tyre files.
pub fn tyres_beside(dir: &Path) {
    let to = dir.join("tyres");
    fs::create_dir_all(&to).unwrap();
    for e in fs::read_dir(crate::root().join("tyres")).unwrap() {
        let p = e.unwrap().path();
        fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
    fs::create_dir_all(dir.join("scenarios")).unwrap();
}
