//! Round 46's findings the lead fixed: a scenario or campaign whose
//! `[vehicle]` header line alone was deleted (its keys then read as the
//! file's own) was refused as "unknown field `mass`", not as the table it
//! lacks.

use super::*;

/// The keys of a lost `[vehicle]` header sit at the top level: the file
/// is said to lack the table, with the line its header belongs above;
/// a misspelt top-level key in a file with every table stays a key refused
/// by its name.
#[test]
fn a_file_whose_vehicle_header_line_is_lost_is_said_to_lack_it_above_its_first_key() {
    let vehicle_keys = VEHICLE.trim_start_matches("[vehicle]\n");
    let scenario = format!(
        "name = \"nov\"\n\n{vehicle_keys}\n[tyres]\nfront = \"tyre.toml\"\n\n{STEP}start = 1.0\nrise_time = 0.1\nend = 6.0\n"
    );
    let campaign = format!(
        "name = \"nov\"\n{vehicle_keys}\n[tyres]\nrig = \"rig.csv\"\nmodel = \"pac89\"\n\n[runs]\ndir = \"runs\"\n"
    );
    let dir = scratch(&[
        ("scen.toml", &scenario),
        ("camp.toml", &campaign),
        ("tyre.toml", GIM),
    ]);
    let err = fails_cleanly("simulate", &dir.path().join("scen.toml"), dir.path());
    assert!(
        err.contains("scen.toml: the table `[vehicle]` is missing (the file's tables: [tyres] at line 11, [manoeuvre] at line 14), and `mass` at line 3 is one of its keys, read as a key of the file itself: add the header `[vehicle]` above line 3"),
        "{err}"
    );
    assert!(!err.contains("unknown field"), "{err}");
    let err = fails_cleanly("diagnose", &dir.path().join("camp.toml"), dir.path());
    assert!(
        err.contains("camp.toml: the table `[vehicle]` is missing (the file's tables: [tyres] at line 10, [runs] at line 14), and `mass` at line 2 is one of its keys"),
        "{err}"
    );
    // With its header back the scenario runs: the message named the fix.
    let fixed = scenario.replacen("\nmass", "\n[vehicle]\nmass", 1);
    let dir2 = scratch(&[("scen.toml", &fixed), ("tyre.toml", GIM)]);
    let o = run(&[
        "simulate",
        dir2.path().join("scen.toml").to_str().unwrap(),
        "--out",
        dir2.path().join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // A misspelt top-level key where every table is present is refused by
    // its own name, no table said missing.
    let typo = fixed.replacen("name = \"nov\"", "name = \"nov\"\nnmae = 1", 1);
    let dir3 = scratch(&[("scen.toml", &typo), ("tyre.toml", GIM)]);
    let err = fails_cleanly("simulate", &dir3.path().join("scen.toml"), dir3.path());
    assert!(err.contains(":2:1: `nmae`: unknown field `nmae`"), "{err}");
    assert!(!err.contains("is missing"), "{err}");
}
