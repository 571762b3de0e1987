//! Fresh-eyes round 11, fixed by the lead: a diagnosis whose
//! base tyre is fitted to rig data of another car's tyre says so.

use crate::{diagnose_campaign, shared_data, synth_extended};

/// A sedan's runs diagnosed on a formula-student tyre's rig test: the
/// tyre fitted to it is extrapolated to the sedan's wheel loads and blends
/// three pressures, and the notes say both before the verdict (before,
/// `notes` was empty and the verdict blamed a model-form error alone).
#[test]
fn a_rig_test_below_the_cars_wheel_loads_is_noted_in_the_diagnosis() {
    let Some(hoosier) = shared_data(
        "a_rig_test_below_the_cars_wheel_loads_is_noted_in_the_diagnosis",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let own = synth_extended(
        dir.path(),
        "handling",
        "sensor_delay",
        "1",
        "effects = [\"sensor_delay\"]\n",
    );
    // The campaign's own rig test is at the sedan's loads: no such note.
    let (_, d) = diagnose_campaign(&own);
    let kinds: Vec<&str> = d["note_details"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n["kind"].as_str().unwrap())
        .collect();
    assert!(!kinds.contains(&"tyre_loads_short"), "{kinds:?}");
    assert!(!kinds.contains(&"rig_levels_pooled"), "{kinds:?}");

    std::fs::copy(&hoosier, own.join("tyre_rig.csv")).unwrap();
    let (stdout, d) = diagnose_campaign(&own);
    let short = d["note_details"]
        .as_array()
        .unwrap()
        .iter()
        .find(|n| n["kind"] == "tyre_loads_short")
        .unwrap_or_else(|| panic!("{}", d["notes"]));
    // The sedan's static wheel loads: 1530 kg on a = 1.11, b = 1.67 m.
    let car: Vec<f64> = short["car"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let g = 9.80665 * 1530.0 / 2.78 / 2.0;
    assert!(
        (car[0] - g * 1.11).abs() < 0.5 && (car[1] - g * 1.67).abs() < 0.5,
        "{car:?}"
    );
    let rig_top = short["loads"][1].as_f64().unwrap();
    assert!(rig_top < 3000.0 && rig_top > 2500.0, "{short}");
    assert!(
        stdout.contains("the car's static wheel loads are 2995–4507 N (1.5"),
        "{stdout}"
    );
    assert!(
        stdout.contains("3 pressure levels of the rig data pooled into one pac89 fit, which has no pressure terms"),
        "{stdout}"
    );
}
