//! One real failing input per kind of [`Error`], matched on the variant
//! and its fields (never on the message text).

use super::*;
use crate::identify::data::identification_conditions;
use crate::identify::{fit_lateral, FitSettings};
use crate::jobs::identify::{IdentifyModel, Polish};
use crate::jobs::shard::Shard;
use crate::proving_ground::{Programme, Truth};
use crate::tyre::pac89::Pac89;
use crate::tyre::{SlipState, Tyre, TyreModel};
use crate::vehicle::Vehicle;
use std::path::{Path, PathBuf};

fn scenario_with(dir: &Path, from: &str, to: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("scenarios/sedan_step.toml")).unwrap();
    assert!(text.contains(from), "the scenario has `{from}`");
    let text = text.replace(from, to);
    // Relative tyre paths resolve from the scenario's folder.
    let text = text.replace("\"../tyres/", &format!("\"{}/tyres/", root.display()));
    let p = dir.join("s.toml");
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn a_cell_that_is_not_a_number_is_an_input_error_at_its_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("rig.csv");
    std::fs::write(&p, "fz,alpha,fy\n4000,0.01,-900\n4000,abc,-1800\n").unwrap();
    let e = Error::from(crate::io::rig::read_rig(&p).unwrap_err());
    assert_eq!(e.kind(), ErrorKind::Input);
    match e {
        Error::Input(InputError::Cell {
            path,
            line,
            column,
            name,
            cell,
            problem,
        }) => {
            assert_eq!((path, line, column), (p, 3, 2));
            assert_eq!((name.as_str(), cell.as_str()), ("alpha", "abc"));
            assert_eq!(problem, CellProblem::NotANumber);
        }
        other => panic!("not an input error at a cell: {other:?}"),
    }
}

#[test]
fn a_negative_mass_in_a_scenario_is_an_input_error_naming_key_and_value() {
    let dir = tempfile::tempdir().unwrap();
    let p = scenario_with(dir.path(), "mass = 1530.0", "mass = -1530.0");
    let e = Error::from(crate::io::load_scenario(&p).unwrap_err());
    match &e {
        Error::Input(InputError::Value {
            path,
            at: Some(at),
            source,
        }) => {
            assert_eq!(path, &p);
            assert_eq!(source.key, "vehicle.mass");
            assert_eq!(source.value, ParamValue::Number(-1530.0));
            let text = std::fs::read_to_string(&p).unwrap();
            let line = text.lines().position(|l| l.starts_with("mass")).unwrap() + 1;
            assert_eq!(at.line, line);
        }
        other => panic!("not a located value error: {other:?}"),
    }
    assert_eq!(e.kind(), ErrorKind::Input);
}

#[test]
fn a_vehicle_with_a_negative_height_is_a_param_error() {
    let v = Vehicle {
        cg_height: -0.1,
        ..Vehicle::compact_sedan()
    };
    let e = Error::from(v.validate().unwrap_err());
    assert_eq!(e.kind(), ErrorKind::Param);
    match e {
        Error::Param(p) => {
            assert_eq!(p.key, "cg_height");
            assert_eq!(p.value.number(), Some(-0.1));
            assert_eq!(p.reason, ParamReason::Negative);
        }
        other => panic!("not a parameter error: {other:?}"),
    }
}

#[test]
fn a_parameter_error_says_why_by_its_kind() {
    let v = Vehicle {
        yaw_inertia: 2500.0 * 1000.0,
        ..Vehicle::compact_sedan()
    };
    let e = v.validate().unwrap_err();
    assert_eq!(e.key, "yaw_inertia");
    let ParamReason::DynamicIndex { index, .. } = e.reason else {
        panic!("not a dynamic index: {e:?}");
    };
    let (lo, hi) = crate::error::DYNAMIC_INDEX;
    assert!(index > hi && lo < hi, "{index} outside {lo}–{hi}");
    let e = ParamError::in_range("step", 0.2, 0.0, 0.05, Limit::OutputStep).unwrap_err();
    assert_eq!(
        e.reason,
        ParamReason::OutOfRange {
            lo: 0.0,
            hi: 0.05,
            why: Limit::OutputStep
        }
    );
    // The message is built from the kind, with the range's ends.
    assert_eq!(
        e.to_string(),
        "`step` = 0.2: must lie in (0, 0.05]: rows (and RK4 steps) more than 50 ms apart miss the yaw mode"
    );
}

#[test]
fn an_unknown_model_and_a_bad_shard_are_options_errors() {
    let e = "pac2002".parse::<IdentifyModel>().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Options);
    match e {
        Error::Options(OptionsError::UnknownName { what, given, known }) => {
            assert_eq!(what, NameKind::TyreModel);
            assert_eq!(given, "pac2002");
            assert!(known.contains(&"pac89"), "{known:?}");
        }
        other => panic!("not an unknown name: {other:?}"),
    }
    let e = "newton".parse::<Polish>().unwrap_err();
    assert!(matches!(
        e,
        Error::Options(OptionsError::UnknownLocalMethod { ref given }) if given == "newton"
    ));
    let e = Shard::new(4, 3).unwrap_err();
    assert!(matches!(
        e,
        Error::Options(OptionsError::ShardOutOfRange { index: 4, count: 3 })
    ));
    let e = "3".parse::<Shard>().unwrap_err();
    assert!(matches!(e, Error::Options(OptionsError::ShardText { .. })));
    let e = crate::jobs::synth::truth_named("six-wheel").unwrap_err();
    assert!(matches!(
        e,
        Error::Options(OptionsError::UnknownName {
            what: NameKind::Truth,
            ..
        })
    ));
}

#[test]
fn pac89_on_one_load_is_a_fit_error_naming_the_loads() {
    let truth = Tyre::Pac89(Pac89::adams_example());
    let (conditions, _) = identification_conditions(&truth, 0.0, 1);
    let e = fit_lateral(&truth, &conditions[..1], &FitSettings::new(1)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Fit);
    match e {
        Error::Fit(
            ref fit @ FitError::TooFewLoads {
                needed: 3,
                ref loads,
                ..
            },
        ) => {
            assert_eq!(loads, &vec![conditions[0].fz]);
            // Said in newtons, not as a debug list (`[4000.0] N`).
            let said = fit.to_string();
            let load = format!("{:.0} N", conditions[0].fz);
            assert!(
                said.contains(&format!(
                    "the data has 1: {load}: fit a model that takes one load"
                )),
                "{said}"
            );
        }
        other => panic!("not too few loads: {other:?}"),
    }
}

#[test]
fn a_record_too_short_for_metrics_is_a_metrics_error() {
    let t = [0.0, 0.1, 0.2];
    let x = [0.0, 0.1, 0.1];
    let r = crate::metrics::step_metrics(&t, &x, &x, None, None, &Default::default());
    let e = Error::from(r.unwrap_err());
    assert_eq!(e.kind(), ErrorKind::Metrics);
    assert!(
        matches!(e, Error::Metrics(MetricsError::Shape { .. })),
        "{e}"
    );
}

/// A synthetic campaign whose rig data hold one load: the diagnosis's
/// PAC89 base model cannot be fitted to it.
#[test]
fn a_rig_of_one_load_fails_the_diagnosis() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c");
    let r =
        crate::jobs::synth::run(&[], 1, Truth::ALL[0], Programme::default(), None, &out).unwrap();
    r.write().unwrap();
    let tyre = Tyre::Pac89(Pac89::adams_example());
    let mut rig = String::from("fz,alpha,fy\n");
    for i in -20..=20 {
        let alpha = (0.5 * i as f64).to_radians();
        let fy = tyre.forces(&SlipState::lateral(alpha, 4000.0)).fy;
        rig.push_str(&format!("4000,{alpha},{fy}\n"));
    }
    let rig_path = out.join("tyre_rig.csv");
    std::fs::write(&rig_path, rig).unwrap();
    let c = crate::io::campaign::load_campaign(&out).unwrap();
    let e = crate::diagnose::diagnose(&c, None).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Diagnosis, "{e}");
    match e {
        Error::Diagnosis(DiagnosisError::RigFit { rig, .. }) => assert_eq!(rig, rig_path),
        other => panic!("not a diagnosis error: {other:?}"),
    }
}

#[test]
fn an_output_over_an_input_and_an_existing_campaign_are_output_errors() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("in.csv");
    std::fs::write(&p, "t\n0\n").unwrap();
    let e = crate::report::refuse_overwrite(&p, std::slice::from_ref(&p)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Output);
    assert!(matches!(&e, Error::Output(OutputError::Overwrite { path }) if *path == p));
    let e = crate::jobs::synth::run(
        &[],
        1,
        Truth::ALL[0],
        Programme::default(),
        None,
        dir.path(),
    )
    .unwrap_err();
    assert!(matches!(
        &e,
        Error::Output(OutputError::CampaignExists { path }) if path == dir.path()
    ));
    let below_a_file = p.join("out.json");
    let e = crate::report::refuse_overwrite(&below_a_file, &[]).unwrap_err();
    assert!(matches!(
        e,
        Error::Output(OutputError::NotAFolder { file, .. }) if file == p
    ));
}

#[test]
fn a_name_outside_its_set_is_refused_with_the_set() {
    let all = [NameKind::Metric, NameKind::Unit];
    let e = named(&all, NameKind::as_str, NameKind::Programme, "x").unwrap_err();
    assert_eq!(e.to_string(), "unknown programme `x`: one of metric, unit");
    assert_eq!(
        named(&all, NameKind::as_str, NameKind::Metric, "unit"),
        Ok(NameKind::Unit)
    );
}

#[test]
fn a_job_refuses_settings_that_are_not_numbers_before_it_reads() {
    // The paths do not exist: the settings are refused first.
    let nowhere = Path::new("no/such/run.csv");
    let settings = crate::metrics::MetricSettings {
        pre_window: 0.0,
        ..Default::default()
    };
    let e = crate::jobs::metrics::run(nowhere, &settings, 5.0).unwrap_err();
    match e {
        Error::Param(p) => {
            assert_eq!(p.key, "pre_window");
            assert_eq!(p.reason, ParamReason::NotPositive);
        }
        other => panic!("not a parameter error: {other:?}"),
    }
    let o = crate::jobs::identify::Options {
        data: nowhere.to_path_buf(),
        model: "pac89".parse().unwrap(),
        seed: 1,
        out: None,
        load: None,
        pressure: None,
        camber: None,
        local: Polish::Lm,
        alpha_bin_deg: f64::NAN,
        kappa_bin: 0.0025,
        start: crate::jobs::identify::StartArg::Data,
        template: None,
        max_iterations: Some(10),
        hold: Vec::new(),
    };
    match crate::jobs::identify::run(&o).unwrap_err() {
        Error::Param(p) => {
            assert_eq!(p.key, "bin_deg");
            assert_eq!(p.reason, ParamReason::NotFinite);
        }
        other => panic!("not a parameter error: {other:?}"),
    }
}

#[test]
fn a_scenario_with_a_window_that_is_not_positive_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let p = scenario_with(
        dir.path(),
        "[manoeuvre]",
        "[metrics]\nsteady_window = -1.0\n\n[manoeuvre]",
    );
    match crate::io::load_scenario(&p).unwrap_err() {
        InputError::Value { source, .. } => {
            assert_eq!(source.key, "metrics.steady_window");
            assert_eq!(source.reason, ParamReason::NotPositive);
        }
        other => panic!("not a located value error: {other:?}"),
    }
}
