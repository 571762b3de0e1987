//! What a user check of the CLI tripped on: a held value of `identify`
//! refused without its name, or written as 309 digits; an option refused
//! by its Python keyword without its flag; the ΔBIC column of a diagnosis
//! read as decisive where the held-out columns tell two candidates apart
//! by nothing.

use crate::{narrowed, refused, run, shared_data};

/// `identify` on the public rig file with `args`: its error (None where
/// the file is absent outside CI).
fn identify_refused(test: &str, args: &[&str]) -> Option<String> {
    let rig = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.toml");
    let mut all = vec!["identify", rig.to_str().unwrap(), "--model", "pac89"];
    all.extend(args);
    all.extend(["--out", out.to_str().unwrap()]);
    Some(refused(&run(&all), &out))
}

#[test]
fn a_held_value_refused_is_said_with_its_name_and_in_its_shortest_form() {
    let test = "a_held_value_refused_is_said_with_its_name_and_in_its_shortest_form";
    let Some(e) = identify_refused(test, &["--hold", "a1=1e308"]) else {
        return;
    };
    assert!(
        e.contains("--hold a1=1e308: `a1` = 1e308: must lie within ±1000000"),
        "{e}"
    );
    assert!(!e.contains("0000000000000"), "{e}");
    let e = identify_refused(test, &["--hold", "a1=nan"]).unwrap();
    assert!(
        e.contains("--hold a1=NaN: `a1` = NaN: must be a finite number"),
        "{e}"
    );
}

#[test]
fn an_option_refused_names_its_flag() {
    let Some(e) = identify_refused("an_option_refused_names_its_flag", &["--bin-deg", "-1"]) else {
        return;
    };
    assert!(
        e.contains("--bin-deg: `bin_deg` = -1: must not be negative"),
        "{e}"
    );
}

#[test]
fn the_candidates_table_says_its_bic_is_no_evidence_between_two_candidates() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, d, page) = narrowed(
        dir.path(),
        "sensor_delay",
        "\"sensor_delay\", \"steer_path\"",
    );
    // A significant gap, two look-alikes whose ΔBIC differ by hundreds.
    assert_eq!(d["verdict"]["kind"], "explained", "{stdout}");
    let said = "a ΔBIC difference of hundreds between two candidates is no evidence between them";
    let table = stdout.find("ΔBIC  parameters").expect("the table");
    let caveat = stdout.find(said).unwrap_or_else(|| panic!("{stdout}"));
    assert!(caveat < table, "{stdout}");
    assert!(page.contains(said), "{page}");
}
