//! The prior of axles identified from the runs, and the channels'
//! trusted uncertainties, as a user states them in a campaign
//! (`[tyres] class`, `cornering`, `friction`; `[channels]`) and reads them
//! in the report: the classes' ranges against public tyre files, the peak
//! friction held where the runs never approach it, and the errors a wrong
//! table gets. An estimated sideslip trusted as an estimate, with the
//! peak friction held, is checked on the banked oval's analogue on three
//! seeds (`analogue_verdicts.rs`).

use super::*;
use handling::tyre::TyreModel;
use std::fs;

/// The cornering coefficient (cornering stiffness per unit load, 1/rad)
/// of a public `.tir` file at its nominal load.
fn coefficient(file: &str) -> Option<f64> {
    let path = shared_data(
        "public_tyre_files_lie_within_the_ranges_their_class_states",
        &format!("tir_public/{file}"),
    )?;
    let tyre = handling::io::tir::load_tir(&path).unwrap();
    let fz = tyre.coefficients.FNOMIN;
    Some(tyre.cornering_stiffness(fz) / fz)
}

/// Of the public files, the `Data_TIR` cars, the FSAE 190 and the smaller
/// truck share one set of lateral coefficients (13.3 1/rad at their
/// nominal loads): they count once, as a road tyre. The independent ones
/// are Pacejka's book's road tyre, the FSAE defaults' slick and the
/// larger truck's tyre.
#[test]
fn public_tyre_files_lie_within_the_ranges_their_class_states() {
    use handling::io::campaign::TyreClass;
    for (file, class, measured) in [
        ("car205_60R19.tir", TyreClass::Road, 13.32),
        ("PacejkaBook_Defaults.tir", TyreClass::Road, 12.00),
        ("FSAE_Defaults.tir", TyreClass::RacingSlick, 36.00),
        ("Truck_430_50R38.tir", TyreClass::Truck, 6.68),
    ] {
        let Some(k) = coefficient(file) else { return };
        // The value quoted above, as this reader evaluates the file.
        assert!((k - measured).abs() < 0.01, "{file}: {k}");
        let ([lo, hi], _) = class.ranges();
        assert!(lo < k && k < hi, "{file}: {k} outside {lo}–{hi}");
        // Each file lies outside the other classes' ranges but the
        // neighbouring one's: the classes differ.
        let others = TyreClass::ALL
            .iter()
            .filter(|c| **c != class)
            .filter(|c| {
                let ([lo, hi], _) = c.ranges();
                lo < k && k < hi
            })
            .count();
        assert!(others <= 1, "{file}: {k} lies in {others} other classes");
    }
}

/// The `[tyres]` and `[diagnose]` additions of a campaign without tyre data.
fn tables(tyres: &str, channels: &str, effects: &str) -> String {
    format!(
        "effects = [{effects}]\nmax_effects = 1\n\n[tyres]\n{tyres}\n\n[channels]\n{channels}\n"
    )
}

#[test]
fn stated_ranges_and_uncertainties_are_used_and_reported() {
    let dir = tempfile::tempdir().unwrap();
    // A friction range the runs' 1.3 m/s² exceed 0.8 of (0.12 g): the peak
    // friction is fitted, against the stated range; the sideslip's stated
    // uncertainty is its floor and scale.
    let c = synth_extended(
        dir.path(),
        "slow-oval",
        "none",
        "1",
        &tables(
            "cornering = [10.0, 30.0]\nfriction = [0.12, 0.3]",
            "beta = 0.004\nay = 0.05",
            "\"sensor_bias\"",
        ),
    );
    let (stdout, d) = diagnose_campaign(&c);
    let prior = &d["base"]["axles"]["prior"];
    assert_eq!(prior["prior"]["class"], "road", "{prior}");
    assert_eq!(prior["prior"]["stated"], serde_json::json!([true, true]));
    assert_eq!(prior["prior"]["cornering"][1], 30.0);
    assert_eq!(prior["friction_rule"]["free"], true, "{prior}");
    let threshold = prior["friction_rule"]["threshold"].as_f64().unwrap();
    assert!((threshold - 0.8 * 0.12 * 9.80665).abs() < 1e-9);
    assert_eq!(d["base"]["axles"]["parameters"][2]["held"], false);
    assert!(
        stdout.contains("prior road tyres (cornering coefficient and peak friction stated): cornering coefficient 10–30 1/rad"),
        "{stdout}"
    );
    assert!(stdout.contains("peak friction fitted: the runs reach |ay|"));
    let beta = &d["gap"]["noise"][1];
    assert_eq!(
        (beta["source"].as_str(), beta["noise_floor"].as_f64()),
        (Some("stated"), Some(0.004))
    );
    assert!(stdout.contains("beta 0.0040 rad (stated)"), "{stdout}");
    // The slow oval logs no ay: its stated uncertainty is unused, and said so.
    assert!(
        stdout.contains("[channels] ay: no run measures this channel"),
        "{stdout}"
    );
}

/// The error `diagnose` gives on a campaign whose `vehicle.toml` has
/// `extra` added.
fn refused(extra: &str, programme: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--programme", programme]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    // Into the rig campaign's `[tyres]`, else at the end.
    let text = match text.find("model = \"pac89\"\n") {
        Some(i) => format!("{}{extra}{}", &text[..i], &text[i..]),
        None => text + extra,
    };
    fs::write(&v, text).unwrap();
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("o").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    stderr(&o)
}

#[test]
fn a_wrong_prior_or_uncertainty_is_refused_with_its_key_line_and_value() {
    let e = refused("\n[tyres]\nclass = \"racing slick\"\n", "slow-oval");
    assert!(
        e.contains("vehicle.toml") && e.contains("tyres.class"),
        "{e}"
    );
    assert!(e.contains("did you mean `racing_slick`"), "{e}");
    // A word of the name, as engineers say it, is answered too.
    let e = refused("\n[tyres]\nclass = \"slick\"\n", "slow-oval");
    assert!(e.contains("did you mean `racing_slick`"), "{e}");
    let e = refused("\n[channels]\nbeta = -0.002\n", "slow-oval");
    assert!(
        e.contains("channels") && e.contains("beta") && e.contains("-0.002"),
        "{e}"
    );
    assert!(e.contains("vehicle.toml:"), "{e}");
    let e = refused("\n[tyres]\nfriction = [1.0, 0.8]\n", "slow-oval");
    assert!(
        e.contains("tyres.friction") && e.contains("upper end"),
        "{e}"
    );
    // A range no axle the identification represents can have.
    let e = refused("\n[tyres]\ncornering = [1e-9, 1e9]\n", "slow-oval");
    assert!(
        e.contains("tyres.cornering") && e.contains("0.4–4000"),
        "{e}"
    );
    // The handling programme's campaign has rig data: no axles to identify.
    let text = "class = \"road\"\n";
    let e = refused(text, "handling");
    assert!(
        e.contains("applies only without tyre files or rig data"),
        "{e}"
    );
}
