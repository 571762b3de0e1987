//! What a user tripped on in `identify`'s figures (session 101): the
//! staged Magic Formula fit drew every stage into one PNG, 1300 × 6600 px
//! on the book's MF 6.1 grid (1300 × 19,800 px on a denser one), which no
//! viewer shows at a readable scale. Now each fitted stage has its own
//! figure, `<out>.<stage>.png`, named on the terminal and in the report.

use super::*;

/// The height of the PNG `path` (its IHDR), px.
fn png_height(path: &Path) -> u32 {
    let png = fs::read(path).unwrap();
    assert_eq!(&png[1..4], b"PNG", "{}", path.display());
    u32::from_be_bytes(png[20..24].try_into().unwrap())
}

/// The book's staged fit (`docs/src/magic-formula.md`): the MF 6.1 sample
/// file evaluated on `docs/examples/mf_grid.csv` and fitted back as
/// `mf61`. Every fitted stage's figure is written, each at most 4000 px
/// tall and at least one row of panels, and no one figure of every stage.
#[test]
fn a_staged_fit_writes_a_figure_per_stage_each_of_a_readable_height() {
    let dir = tempfile::tempdir().unwrap();
    let rig = dir.path().join("rig.csv");
    mf61_evaluated(&root().join("docs/examples/mf_grid.csv"), &rig);
    let o = identify_to(&rig, "mf61", &dir.path().join("fit.tir"));
    let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(o.status.success(), "{said}");
    let report = read_json(&dir.path().join("fit.report.json"));
    let fitted: Vec<&str> = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["skipped"].is_null())
        .map(|s| s["stage"].as_str().unwrap())
        .collect();
    assert!(fitted.len() >= 5, "{fitted:?}");
    let figures = report["figures"].as_array().unwrap();
    let drawn: Vec<&str> = figures
        .iter()
        .map(|f| f["stage"].as_str().unwrap())
        .collect();
    assert_eq!(
        drawn, fitted,
        "a figure per fitted stage, in the stages' order"
    );
    for f in figures {
        let stage = f["stage"].as_str().unwrap();
        let png = dir.path().join(format!("fit.{stage}.png"));
        assert_eq!(f["path"].as_str().unwrap(), png.to_str().unwrap());
        assert!(said.contains(png.to_str().unwrap()), "{said}");
        let h = png_height(&png);
        // One row of panels (300 px) at least; a page or two at most.
        assert!((300..=4000).contains(&h), "{stage}: {h} px tall");
    }
    assert!(!dir.path().join("fit.png").exists());
    assert!(said.contains("a figure per stage fitted: "), "{said}");
}
