//! Session 111 (pac89se44): a `--hold` name of another model's parameter
//! names that model (`jobs/identify/hold_owner.rs`). (The helper's work on
//! PAC89's other optima stays on branch `s111-pac89se44-wip`: unverified.)

use super::*;

/// A `--hold` name of another model than the one chosen says which model
/// it belongs to and the `--model` that fits it, with an example of the
/// chosen model's own: for every pair of GIM, PAC89 and the Magic
/// Formula (mf62 was told only "not one of the 177 known" of PAC89's a1).
#[test]
fn a_hold_of_another_models_parameter_names_that_model() {
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n1000,0.01,100\n")]);
    let rig = dir.path().join("rig.csv");
    let refused = |model: &str, hold: &str| {
        let o = run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            model,
            "--hold",
            hold,
        ]);
        assert!(!o.status.success(), "{model} {hold}");
        stderr(&o)
    };
    let said = refused("mf62", "a1=-22");
    assert!(
        said.contains("--hold `a1`: a1 is a parameter of the pac89 model (--model pac89), not of mf62, the model chosen: hold one of mf62's, e.g. --hold PKY4=2"),
        "{said}"
    );
    // One name of each model, given to each other model.
    let names = [("gim", "friction_decay"), ("pac89", "a1"), ("mf61", "PKY1")];
    for chosen in ["gim", "pac89", "mf62"] {
        for (owner, name) in names.iter().filter(|(o, _)| !chosen.starts_with(&o[..2])) {
            let said = refused(chosen, &format!("{name}=1"));
            assert!(
                said.contains(&format!(
                    "{name} is a parameter of the {owner} model (--model {owner}), not of {chosen}"
                )),
                "{chosen} {name}: {said}"
            );
            // The example is the chosen model's own: held, it is taken
            // past the name check (refused later by the one-row data).
            let example = said.rsplit("e.g. --hold ").next().unwrap().trim();
            let held = refused(chosen, example);
            assert!(!held.contains("is a parameter of the"), "{example}: {held}");
            assert!(!held.contains("not a parameter of"), "{example}: {held}");
        }
    }
}
