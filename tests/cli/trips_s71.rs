//! What a user tripped on, found by a fresh-eyes check of the last
//! release: each through the binary, on files.

use super::*;
use std::fs;

/// A rig whose z axis points down (SAE's axes) logs every load negative:
/// refused at the first row as before, and said to be the convention, with
/// the column to negate; one negative load among positive ones is a bad
/// sample, and only that is said.
#[test]
fn a_rig_file_whose_loads_are_all_negative_is_told_to_negate_the_column() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let text = fs::read_to_string(c.join("tyre_rig.csv")).unwrap();
    let mut rows = text.lines();
    let header = rows.next().unwrap().to_string();
    assert!(header.starts_with("fz,"), "{header}");
    let rows: Vec<&str> = rows.collect();
    let negated: Vec<String> = rows.iter().map(|r| format!("-{r}")).collect();
    let mut one = rows.iter().map(|r| r.to_string()).collect::<Vec<_>>();
    one[4] = format!("-{}", one[4]);
    for (name, body, every) in [("all", negated, true), ("one", one, false)] {
        let rig = dir.path().join(format!("{name}.csv"));
        fs::write(&rig, format!("{header}\n{}\n", body.join("\n"))).unwrap();
        let out = dir.path().join(format!("{name}.toml"));
        let e = refused(&identify_to(&rig, "magic-simple", &out), &out);
        let first = if every { 2 } else { 6 };
        assert!(
            e.contains(&format!("{name}.csv:{first}:1: column `fz`: -")),
            "{e}"
        );
        let told = "every load of the file is: a rig whose z axis points down (SAE's axes) logs them so; negate the column";
        assert_eq!(e.contains(told), every, "{e}");
    }
}
