//! Where a diagnosis's CPU time went: each phase of `diagnosis.json`'s
//! `timing.phases` carries the process's CPU seconds apportioned to it by
//! its share of the phases' summed call seconds, so that the phases' CPU
//! seconds add up to the process's (the call seconds overlap on several
//! threads and sum past it).

use super::*;

#[test]
fn the_phases_cpu_seconds_add_up_to_the_diagnosis_cpu_seconds() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c8",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let (_, d) = diagnose_campaign(&c);
    let t = &d["timing"];
    let cpu = t["cpu_seconds"].as_f64().unwrap();
    let phases = t["phases"].as_array().unwrap();
    let each: Vec<f64> = phases
        .iter()
        .map(|p| p["cpu_seconds"].as_f64().unwrap_or(f64::NAN))
        .collect();
    assert!(each.iter().all(|&c| c >= 0.0), "{t}");
    let sum: f64 = each.iter().sum();
    assert!(
        (sum - cpu).abs() <= 1e-9 * cpu.max(1.0),
        "{sum} of {cpu}: {t}"
    );
    // In proportion to the call seconds: the largest phase by seconds is
    // the largest by CPU seconds.
    let largest = |key: &str| {
        phases
            .iter()
            .max_by(|a, b| {
                a[key]
                    .as_f64()
                    .unwrap()
                    .total_cmp(&b[key].as_f64().unwrap())
            })
            .unwrap()["phase"]
            .clone()
    };
    assert_eq!(largest("seconds"), largest("cpu_seconds"), "{t}");
}
