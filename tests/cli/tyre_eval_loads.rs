//! `tyre-eval` at loads a tyre is not meant for: a TOML tyre far beyond or
//! below its model's loads is said, counted, with the first point (as a
//! `.tir` file's `FZMIN` and `FZMAX` are); a `.tir` file whose rolling
//! resistance does not depend on the load says so below `FZMIN`, and a
//! load so small its square underflows is named as the cause of a
//! non-finite output; a points CSV given as the tyre file is refused with
//! the order of the arguments.

use super::*;
use crate::tyre_eval::{column, eval};

/// Loads from next to nothing to 1 MN at one slip angle.
const LOADS: &str = "fz,kappa,alpha,camber,speed\n1e-300,0,0.1,0,16.7\n4000,0,0.1,0,16.7\n30000,0,0.1,0,16.7\n999999,0,0.1,0,16.7\n";

#[test]
fn a_unitire_far_beyond_its_rated_load_is_said_once_with_the_count() {
    let dir = tempfile::tempdir().unwrap();
    let (o, _) = eval(dir.path(), &root().join("tyres/unitire.toml"), LOADS, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    assert!(
        said.contains("warning: 2 of 4 points at a load above 17100 N, outside the loads the unitire tyre is meant for (57 to 17100 N: 1 % to 3 times its rated_load = 5700 N): evaluated at the load given, an extrapolation of the model; the first at line 4, fz = 30000 N"),
        "{said}"
    );
    assert!(
        said.contains("1 of 4 points at a load below 57 N") && said.contains("fz = 1e-300 N"),
        "{said}"
    );
    assert_eq!(said.matches("outside the loads").count(), 2, "{said}");
}

#[test]
fn every_toml_model_says_the_loads_it_is_not_meant_for() {
    let dir = tempfile::tempdir().unwrap();
    for (file, model, heaviest) in [
        ("linear", "linear", "100000"),
        ("magic_simple", "magic-simple", "100000"),
        ("gim", "gim", "100000"),
        ("pac89_adams_example", "pac89", "18382"),
    ] {
        let tyre = root().join(format!("tyres/{file}.toml"));
        let (o, _) = eval(dir.path(), &tyre, LOADS, &[]);
        assert!(o.status.success(), "{file}: {}", stderr(&o));
        let said = stderr(&o);
        let below = "1 of 4 points at a load below";
        let above = format!(
            "at a load above {heaviest} N, outside the loads the {model} tyre is meant for"
        );
        assert!(
            said.contains(below) && said.contains(&above),
            "{file}: {said}"
        );
    }
}

#[test]
fn a_load_inside_the_models_range_is_not_said() {
    let dir = tempfile::tempdir().unwrap();
    let csv = "fz,kappa,alpha,camber,speed\n2000,0,0.1,0,16.7\n6000,0,0.1,0,16.7\n";
    let (o, _) = eval(dir.path(), &root().join("tyres/unitire.toml"), csv, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("outside the loads"), "{}", stderr(&o));
}

#[test]
fn a_load_free_rolling_resistance_is_said_with_its_value_below_fzmin() {
    let test = "a_load_free_rolling_resistance_is_said_with_its_value_below_fzmin";
    let Some(tir) = shared_data(test, "tir_public/Truck_430_50R38.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let csv = "fz,kappa,alpha,camber,speed\n50,0,0.05,0,16.7\n30000,0,0.05,0,16.7\n";
    let (o, written) = eval(dir.path(), &tir, csv, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    assert!(
        said.contains("the pneumatic trail at FZMIN and the overturning moment scaled down below it; this file's rolling resistance does not depend on the load (QSY7 = 0): my = -201.93 N·m at the first of them, the same at any load; the first at line 2, fz = 50 N"),
        "{said}"
    );
    assert_eq!(column(&written, "my"), vec![-201.93, -201.93]);
}

#[test]
fn a_load_whose_square_underflows_is_named_as_the_cause_of_a_non_finite_my() {
    let test = "a_load_whose_square_underflows_is_named_as_the_cause_of_a_non_finite_my";
    let Some(tir) = shared_data(test, "tir_public/Truck_430_50R38.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let csv = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n4000,0,0.05,0,16.7\n1e-290,0,0.05,0,16.7\n";
    let (o, _) = eval(dir.path(), &tir, csv, &[]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("p.csv:4:1: the magic-formula tyre gives a non-finite `my` at this point: fz = 1e-290 N is a load so small that the model's load terms underflow to 0"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_points_csv_in_the_tyre_position_is_refused_with_the_order() {
    let dir = tempfile::tempdir().unwrap();
    let csv = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    for name in ["one.csv", "one.txt"] {
        fs::write(dir.path().join(name), csv).unwrap();
        let (o, _) = eval(dir.path(), &dir.path().join(name), csv, &[]);
        assert!(!o.status.success());
        assert!(
            stderr(&o).contains(&format!("{name}: not a tyre file (.tir/.toml): it looks like a points CSV; the order is `tyre-eval <tyre> <points>`")),
            "{}",
            stderr(&o)
        );
    }
}
