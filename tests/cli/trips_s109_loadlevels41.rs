//! Fresh-eyes round 40's finding 4 (session 109): a rig file of three loads
//! (2000, 4000 and 6000 N, 121 slip angles each) whose load carries 1 %
//! Gaussian noise, as a load-controlled rig's does, read its 6000 N level
//! as three ("5899 N (9), 6007 N (98), 6112 N (11)") and PAC89's figure
//! drew one sweep twice. `identify` with GIM and PAC89 now says three
//! levels, each holding its 121 samples, named by their medians, and fits
//! three conditions, one curve each.

use super::*;
use handling::tyre::{Pac89, SlipState, Tyre, TyreModel};
use rand::SeedableRng;

/// The loads the rig held, N.
const LOADS: [f64; 3] = [2000.0, 4000.0, 6000.0];
/// Slip angles per load: −0.24 to 0.24 rad in steps of 0.004 rad.
const SWEEP: usize = 121;
/// The load's noise, a share of the load.
const NOISE: f64 = 0.01;

/// Writes `rig.csv` into `dir`: each load swept through [`SWEEP`] slip
/// angles, its `fz` scattered by [`NOISE`] of it (seeded), `fy` PAC89's
/// (ADAMS example) at the sample's own load. Returns the file and each
/// level's loads as written.
fn noisy_rig(dir: &Path, seed: u64) -> (PathBuf, Vec<Vec<f64>>) {
    let tyre = Tyre::Pac89(Pac89::adams_example());
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut text = String::from("fz,alpha,camber,fy\n");
    let mut levels = Vec::new();
    for f in LOADS {
        let mut level = Vec::new();
        for i in 0..SWEEP {
            let alpha = -0.24 + 0.004 * i as f64;
            let fz = f * (1.0 + NOISE * handling::identify::data::gauss(&mut rng));
            // Written to 0.1 N as the rig files are: the level's loads
            // are the values read back.
            let fz = (fz * 10.0).round() / 10.0;
            let fy = tyre.lateral_force(&SlipState::lateral(alpha, fz));
            text += &format!("{fz:.1},{alpha:.3},0,{fy:.2}\n");
            level.push(fz);
        }
        levels.push(level);
    }
    (written(dir, "rig.csv", &text), levels)
}

/// The median of `v`.
fn median_of(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    if n % 2 == 1 {
        s[n / 2]
    } else {
        0.5 * (s[n / 2 - 1] + s[n / 2])
    }
}

/// The `fz levels:` line of `stdout`, as (load, samples) pairs.
fn said_levels(stdout: &str) -> Vec<(f64, usize)> {
    let line = stdout
        .lines()
        .find_map(|l| l.trim().strip_prefix("fz levels: "))
        .unwrap_or_else(|| panic!("no fz levels line:\n{stdout}"));
    // "1999 N (121), 3998 N (121), …", then maybe "; … between levels".
    let list = line.split(';').next().unwrap();
    list.split(", ")
        .map(|item| {
            let (load, rest) = item.split_once(" N (").unwrap_or_else(|| panic!("{line}"));
            let samples = rest.trim_end_matches(')');
            (load.parse().unwrap(), samples.parse().unwrap())
        })
        .collect()
}

/// `identify` with GIM and PAC89 on the noisy rig of several seeds: the
/// terminal names three load levels of 121 samples, each at the median of
/// the loads written at it (to the 1 N it prints) and within half a noise
/// deviation of the load the rig held (the median's standard error is 0.11
/// of one); the report holds the same, nothing between levels, and one
/// fitted curve per load, each drawn at a load of its own level.
#[test]
fn three_noisy_loads_are_three_levels_of_121_samples() {
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=3 {
        let (rig, written) = noisy_rig(dir.path(), seed);
        for model in ["gim", "pac89"] {
            let out = dir.path().join(format!("{model}{seed}.toml"));
            let o = identify_to(&rig, model, &out);
            let said = String::from_utf8_lossy(&o.stdout).into_owned();
            let at = format!("{model}, seed {seed}:\n{said}{}", stderr(&o));
            assert!(o.status.success(), "{at}");
            let levels = said_levels(&said);
            assert_eq!(levels.len(), 3, "{at}");
            for (((load, samples), level), f) in levels.iter().zip(&written).zip(LOADS) {
                assert_eq!(*samples, SWEEP, "{at}");
                assert!((load - median_of(level)).abs() <= 0.5, "{at}");
                assert!((load - f).abs() < 0.5 * NOISE * f, "{at}");
            }
            let report = read_json(&out.with_extension("report.json"));
            let grouped = &report["grouping"]["levels"][0];
            assert_eq!(grouped["variable"], "load", "{at}");
            assert_eq!(grouped["transition_samples"], 0, "{at}");
            let held: Vec<u64> = grouped["levels"]
                .as_array()
                .unwrap()
                .iter()
                .map(|l| l["samples"].as_u64().unwrap())
                .collect();
            assert_eq!(held, [SWEEP as u64; 3], "{at}");
            let curves = report["curves"].as_array().unwrap();
            let mut drawn: Vec<f64> = curves.iter().map(|c| c["fz"].as_f64().unwrap()).collect();
            drawn.sort_by(f64::total_cmp);
            assert_eq!(drawn.len(), 3, "{at}: {drawn:?}");
            for (fz, level) in drawn.iter().zip(&written) {
                let (lo, hi) = level
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                        (a.min(*v), b.max(*v))
                    });
                assert!((lo..=hi).contains(fz), "{at}: {drawn:?}");
            }
        }
    }
}
