//! What a new user tripped on, mended: a campaign's rig
//! model named as a Magic Formula is answered with how such a fit is made
//! and given.

use super::*;

#[test]
fn a_campaign_naming_a_magic_formula_rig_model_is_told_to_fit_it_with_identify_and_give_the_tir() {
    let dir = tempfile::tempdir().unwrap();
    let camp = synth_campaign(dir.path(), "camp", &["--seed", "1"]);
    let path = camp.join("vehicle.toml");
    let text = fs::read_to_string(&path).unwrap();
    assert!(text.contains("model = \"pac89\""), "{text}");
    for given in ["mf61", "MF6.2"] {
        fs::write(
            &path,
            text.replace("model = \"pac89\"", &format!("model = \"{given}\"")),
        )
        .unwrap();
        let o = run(&["diagnose", camp.to_str().unwrap()]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{e}");
        let line = text
            .lines()
            .position(|l| l.starts_with("model = "))
            .unwrap()
            + 1;
        assert!(
            e.contains(&format!("vehicle.toml:{line}:"))
                && e.contains(&format!(
                    "`{given}` is no model the diagnosis fits to rig data (one of gim, magic-simple, unitire, pac89, linear): the Magic Formula is fitted in stages by `handling identify <rig> --model mf61 --out base.tir`"
                ))
                && e.contains("`[tyres] file = \"base.tir\"`"),
            "{e}"
        );
    }
}
