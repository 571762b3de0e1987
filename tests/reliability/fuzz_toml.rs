//! Fuzzing of the TOML readers (scenario, sweep, study, campaign, tyre
//! files) and the `.tir` reader on mutations of the bundled files; see
//! [`crate::fuzz`] for what is checked.

use crate::fuzz::{fuzz, Kind};
use crate::{fs, inputs, root};

/// Fuzzes the bundled file `scenarios/<file>` through `read`, read from a
/// copy beside a copy of `tyres/`.
fn bundled_scenario<T>(
    name: &'static str,
    file: &str,
    read: impl Fn(&std::path::Path) -> Result<T, handling::error::InputError>,
) {
    let dir = tempfile::tempdir().unwrap();
    inputs::tyres_beside(dir.path());
    let valid = fs::read(root().join("scenarios").join(file)).unwrap();
    let path = dir.path().join("scenarios").join(file);
    fuzz(name, &path, &valid, Kind::Text, read);
}

#[test]
fn scenario_reader_survives_mutations() {
    bundled_scenario("scenario", "sedan_step.toml", handling::io::load_scenario);
}

#[test]
fn sweep_reader_survives_mutations() {
    bundled_scenario(
        "sweep",
        "equilibria_steer_load_transfer.toml",
        handling::io::sweep::load_sweep,
    );
}

#[test]
fn study_reader_survives_mutations() {
    bundled_scenario("study", "sedan_study.toml", handling::io::study::load_study);
}

#[test]
fn campaign_reader_survives_mutations() {
    let dir = tempfile::tempdir().unwrap();
    let valid = inputs::campaign(dir.path());
    fuzz(
        "campaign",
        &dir.path().join("campaign.toml"),
        valid.as_bytes(),
        Kind::Text,
        handling::io::campaign::load_campaign,
    );
}

#[test]
fn tyre_file_reader_survives_mutations() {
    let dir = tempfile::tempdir().unwrap();
    let valid = fs::read(root().join("tyres/pac89_adams_example.toml")).unwrap();
    fuzz(
        "tyre",
        &dir.path().join("tyre.toml"),
        &valid,
        Kind::Text,
        handling::io::load_tyre,
    );
}

#[test]
fn tir_reader_survives_mutations() {
    let dir = tempfile::tempdir().unwrap();
    let valid = fs::read(root().join("tests/fixtures/tir/MagicFormula62_Parameters.tir")).unwrap();
    fuzz(
        "tir",
        &dir.path().join("tyre.tir"),
        &valid,
        Kind::Text,
        handling::io::tir::load_tir,
    );
}
