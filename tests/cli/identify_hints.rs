//! The hint of a level request no level lies near (`identify --load`,
//! `--camber`, `--pressure`, which take N, rad and Pa): a value written in
//! kN, degrees, kPa, bar or psi is answered with its conversion, which
//! then selects the level the hint names; a value no unit slip explains
//! (one between two levels, in the right unit) gets the levels alone.

use super::*;
use crate::trips_identify::stdout;

/// Runs `identify` on `data` with the linear model (the quickest fit) and
/// the level options `args`.
fn identify(data: &Path, args: &[&str]) -> Output {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fit.toml");
    let mut all = vec![
        "identify",
        data.to_str().unwrap(),
        "--model",
        "linear",
        "--out",
        out.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    run(&all)
}

/// The SI value the hint of `e` offers: what follows "did you mean ".
fn offered(e: &str) -> &str {
    let from = e.find("did you mean ").expect("a hint") + "did you mean ".len();
    e[from..].split(' ').next().unwrap()
}

/// Each request of the Hoosier file's levels (loads 534 … 2751 N, cambers
/// 0°, 1.60°, 3.19°, pressures 69.7, 83.4, 97.1 kPa) in the wrong unit:
/// the hint is the conversion, and the value it offers selects the level
/// it names. Before, `--load 1.65` read "the requested 2 N; ... did you
/// mean 1650 N (1650 N)?", `--load 2` had no hint though 2000 N selects
/// the 2193 N level, and `--camber 0.05236` (3°, in rad) was offered
/// 0.000913854 rad, reading a right value as degrees.
#[test]
fn a_level_request_in_another_unit_is_answered_with_a_conversion_that_selects() {
    let Some(data) = shared_data(
        "a_level_request_in_another_unit_is_answered_with_a_conversion_that_selects",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let cases = [
        ("--load", "2", "the requested 2 N; the value is read in N: did you mean 2000 N (2 kN), which selects the 2193 N level?", "fz 2000 N asked for: the 2193 N level selected"),
        ("--load", "1.65", "the requested 1.65 N; the value is read in N: did you mean 1650 N (1.65 kN), which selects the 1656 N level?", "fz 1650 N asked for: the 1656 N level selected"),
        ("--camber", "1.6", "the requested 1.6 rad (91.67°); the value is read in rad: did you mean 0.0279253 rad (1.6°), which selects the 1.60° level?", "camber 1.60° asked for: the 1.60° level selected"),
        ("--pressure", "83", "the requested 83 Pa (0.1 kPa); the value is read in Pa: did you mean 83000 Pa (83 kPa), which selects the 83.4 kPa level?", "pressure 83.0 kPa asked for: the 83.4 kPa level selected"),
        ("--pressure", "12", "did you mean 82737.084 Pa (12 psi), which selects the 83.4 kPa level?", "pressure 82.7 kPa asked for: the 83.4 kPa level selected"),
    ];
    for (option, value, hint, selected) in cases {
        let o = identify(&data, &[option, value]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(hint),
            "{option} {value}: {e}"
        );
        assert!(e.contains("(levels: "), "{e}");
        // The value offered selects the level the hint names.
        let o = identify(&data, &[option, offered(&e)]);
        assert!(
            o.status.success(),
            "{option} {}: {}",
            offered(&e),
            stderr(&o)
        );
        assert!(stdout(&o).contains(selected), "{}", stdout(&o));
    }
}

/// A request that no conversion makes a level, or one in the right unit
/// between two levels, gets the levels and no hint.
#[test]
fn a_level_request_no_unit_slip_explains_gets_the_levels_alone() {
    let Some(data) = shared_data(
        "a_level_request_no_unit_slip_explains_gets_the_levels_alone",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let cases = [
        // 2° and 0.5° are no level of the file either.
        (
            "--camber",
            "2",
            "the requested 2 rad (114.59°) (levels: 0.00°, 1.60°, 3.19°;",
        ),
        (
            "--camber",
            "0.5",
            "the requested 0.5 rad (28.65°) (levels: 0.00°, 1.60°, 3.19°;",
        ),
        // 3° in rad, between the levels at 1.60° and 3.19°: read as
        // degrees it would be 0.05°, near the level at 0.
        (
            "--camber",
            "0.05236",
            "the requested 0.05236 rad (3.00°) (levels: 0.00°, 1.60°, 3.19°;",
        ),
        // The sign slipped, typed as it is: no degrees read into it.
        (
            "--camber",
            "-0.0279",
            "the requested -0.0279 rad (-1.60°) (levels: 0.00°, 1.60°, 3.19°;",
        ),
        (
            "--load",
            "40",
            "the requested 40 N (levels: 534 N, 1095 N, 1656 N, 2193 N, 2751 N;",
        ),
        // 5 kN is above the heaviest level.
        ("--load", "5", "the requested 5 N (levels: 534 N,"),
        (
            "--pressure",
            "250000",
            "the requested 250000 Pa (250.0 kPa) (levels: 69.7 kPa,",
        ),
    ];
    for (option, value, said) in cases {
        let o = identify(&data, &[option, value]);
        let e = stderr(&o);
        assert!(
            !o.status.success() && e.contains(said),
            "{option} {value}: {e}"
        );
        assert!(!e.contains("did you mean"), "{option} {value}: {e}");
    }
}
