//! Tests of the input problems' messages.

use super::*;
use crate::error::{MetricsError, PieceRefusal, MOST_CAMBER, STEEP_CAMBER};

fn slope(
    slope: f64,
    standard_error: f64,
    above: usize,
    below: usize,
    combined: bool,
) -> SmallSlipSlope {
    SmallSlipSlope {
        slope,
        standard_error,
        above,
        below,
        small_slip: 0.035,
        combined,
    }
}

// The messages the readers wrote as text before they were typed, word
// for word (the CLI's users and tests read them), by theme.

/// A rig channel of the wrong sign: `fy`, `mz` and `fx`.
#[test]
fn messages_read_as_the_text_they_replace_wrong_signs() {
    let fy = InputProblem::WrongSign {
        channel: RigChannel::Fy,
        position: 3,
        slope: slope(-12345.678, 12.3456, 6, 5, false),
        beside: None,
    };
    assert_eq!(fy.to_string(), "column `fy` (column 3 of the header) has the wrong sign: near zero slip (|alpha| ≤ 0.035 rad) its least-squares slope against `alpha` is -12346 N/rad (standard error 12 N/rad) from 11 samples (6 with alpha > 0, 5 with alpha < 0); FORMATS.md (ISO 8855) requires a positive slope there: a positive slip angle gives a positive lateral force (fy ≈ +C_alpha·alpha). The file is likely in the SAE or another sign convention: negate the `fy` column");
    let mz = InputProblem::WrongSign {
        channel: RigChannel::Mz,
        position: 4,
        slope: slope(-150.0, 2.0, 5, 5, true),
        beside: Some(50000.0),
    };
    assert_eq!(mz.to_string(), "column `mz` (column 4 of the header) has the wrong sign: near zero slip (|alpha| ≤ 0.035 rad, |kappa| ≤ 0.035) its least-squares slope against `alpha` is -150.0 N·m/rad (standard error 2.0 N·m/rad) from 10 samples (5 with alpha > 0, 5 with alpha < 0), while that of `fy` is 50000 N/rad; FORMATS.md (ISO 8855) requires `mz` to have the sign of `fy` at small slip (it turns the wheel back toward zero slip), so a slope of the same sign. The file is likely in the SAE or another sign convention: negate the `mz` column");
    let fx = InputProblem::WrongSign {
        channel: RigChannel::Fx,
        position: 2,
        slope: slope(-3000.0, 10.0, 6, 6, true),
        beside: None,
    };
    assert_eq!(fx.to_string(), "column `fx` (column 2 of the header) has the wrong sign: near zero slip (|kappa| ≤ 0.035, |alpha| ≤ 0.035 rad) its least-squares slope against `kappa` is -3000 N (standard error 10 N) from 12 samples (6 with kappa > 0, 6 with kappa < 0); FORMATS.md (ISO 8855) requires a positive slope there: x points forward, so a positive (driving) slip ratio gives a positive longitudinal force (fx ≈ +C_kappa·kappa). The file is likely in the SAE or another sign convention: negate the `fx` column");
}

/// No level near the one requested: as typed, and a unit's slip.
#[test]
fn messages_read_as_the_text_they_replace_levels() {
    let level = InputProblem::NoLevelNear {
        variable: Variable::Pressure,
        requested: 250e3,
        levels: vec![200e3, 220e3],
        separation: 5e3,
        slip: None,
    };
    assert_eq!(level.to_string(), "no pressure level near the requested 250000 Pa (250 kPa) (levels: 200.0 kPa, 220.0 kPa; a level holds values within 5.0 kPa of its range)");
    // A load in kN, a camber in degrees, where the option takes SI: the
    // request as typed, then the conversion and the level it selects.
    let kn = InputProblem::NoLevelNear {
        variable: Variable::Load,
        requested: 1.65,
        levels: vec![534.0, 1656.0],
        separation: 96.0,
        slip: Some(LevelSlip {
            meant: 1650.0,
            unit: "kN",
            level: Some(1656.0),
        }),
    };
    assert!(
        kn.to_string().contains(
            "the requested 1.65 N; the value is read in N: did you mean 1650 N (1.65 kN), which selects the 1656 N level? (levels: 534 N, 1656 N;"
        ),
        "{kn}"
    );
    let degrees = InputProblem::NoLevelNear {
        variable: Variable::Camber,
        requested: 1.6,
        levels: vec![0.0, 1.6_f64.to_radians()],
        separation: 0.2_f64.to_radians(),
        slip: Some(LevelSlip {
            meant: 1.6_f64.to_radians(),
            unit: "°",
            level: Some(1.6_f64.to_radians()),
        }),
    };
    assert!(
        degrees.to_string().contains(
            "the requested 1.6 rad (91.67°); the value is read in rad: did you mean 0.0279253 rad (1.6°), which selects the 1.60° level?"
        ),
        "{degrees}"
    );
}

/// An angle column in degrees and a camber the file lacks.
#[test]
fn messages_read_as_the_text_they_replace_angles() {
    let angle = InputProblem::AngleInDegrees {
        column: "camber",
        value: 3.0,
        limit: std::f64::consts::FRAC_PI_4,
    };
    assert_eq!(angle.to_string(), "column `camber`: 3 rad (172°) is beyond ±45° (0.785 rad), steeper than any car tyre runs; a column whose every camber other than 0 is beyond ±20° (0.349 rad) is refused too: angles are in radians (FORMATS.md); is the column in degrees?");
    let camber = InputProblem::NoCamberColumn { camber: 0.05 };
    assert_eq!(camber.to_string(), "camber 2.86° was requested but the file has no `camber` column (its samples are at camber 0)");
}

/// A run without a steer step, and a campaign without runs.
#[test]
fn messages_read_as_the_text_they_replace_runs() {
    let step = InputProblem::NoSteerStep {
        pieces: vec![
            RefusedPiece {
                name: Some("run.csv#1".into()),
                t_start: 0.0,
                t_end: 12.5,
                reason: PieceRefusal::NoStepMetrics(MetricsError::TooShort {
                    span: 12.5,
                    pre_window: 10.0,
                    steady_window: 3.0,
                }),
            },
            RefusedPiece {
                name: Some("run.csv#2".into()),
                t_start: 13.0,
                t_end: 20.0,
                reason: PieceRefusal::AnotherPieceUsed,
            },
        ],
        gaps: vec![(12.5, 0.5)],
    };
    assert_eq!(step.to_string(), "no moving piece holds a steer step: run.csv#1 (0.00–12.50 s): no step-steer metrics (the record (12.500 s) is not longer than the initial and steady windows together (`pre_window` = 10 s + `steady_window` = 3 s)); run.csv#2 (13.00–20.00 s): another piece was used (the run is split where its clock jumps: no rows 12.500–13.000 s)");
    // A run that is one piece is the file the error names: said once.
    let whole = InputProblem::NoSteerStep {
        pieces: vec![RefusedPiece {
            name: None,
            t_start: 0.0,
            t_end: 0.3,
            reason: PieceRefusal::TooShort,
        }],
        gaps: vec![],
    };
    assert_eq!(
        whole.to_string(),
        "no step-steer metrics (the run, 0.00–0.30 s, is too short)"
    );
    let runs = |campaign_folder| InputProblem::NoRuns { campaign_folder }.to_string();
    assert_eq!(runs(None), "no measured runs: list them in [runs] files = [...] or dir = \"...\" (a campaign folder reads runs/*.csv)");
    assert_eq!(runs(Some(PathBuf::from("."))), "no measured runs: list them in [runs] files = [...] or dir = \"...\" (a campaign folder reads runs/*.csv); its folder has runs/: diagnose the folder instead, `handling diagnose .`");
}

/// The two camber refusals state the same two limits in the same
/// words, each in degrees and radians; a slip angle is said as before.
#[test]
fn both_camber_refusals_state_both_limits_alike() {
    let said = |value, limit| {
        InputProblem::AngleInDegrees {
            column: "camber",
            value,
            limit,
        }
        .to_string()
    };
    let steep = said(0.7, STEEP_CAMBER);
    let most = said(1.2, MOST_CAMBER);
    assert!(
        steep.starts_with("column `camber`: 0.7 rad (40.1°) is beyond ±20° (0.349 rad), as every camber of the column other than 0 is"),
        "{steep}"
    );
    assert!(
        most.starts_with("column `camber`: 1.2 rad (68.8°) is beyond ±45° (0.785 rad), steeper than any car tyre runs"),
        "{most}"
    );
    for s in [&steep, &most] {
        assert!(
            s.contains("±20° (0.349 rad)") && s.contains("±45° (0.785 rad)"),
            "{s}"
        );
        assert!(
            s.ends_with("angles are in radians (FORMATS.md); is the column in degrees?"),
            "{s}"
        );
    }
    let alpha = InputProblem::AngleInDegrees {
        column: "alpha",
        value: 2.0,
        limit: std::f64::consts::FRAC_PI_2,
    };
    assert_eq!(alpha.to_string(), "column `alpha`: 2 rad is beyond ±90°: angles are in radians (FORMATS.md); is the column in degrees?");
}
