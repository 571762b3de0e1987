//! What a fresh-eyes check of the `.tir` reader and `identify` found after
//! stop 74, run as a user runs the tool: a load range in N
//! under `FORCE = 'kN'`, a radius hint that ignored its direction, a
//! published file's friction 3.4 read without a word, and a parameter at
//! its bound said as not identifiable with a 723 % effect.

use super::*;

const POINTS: &str = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";

/// `text` with `key`'s value (the first word after `=`) replaced.
fn with(text: &str, key: &str, value: &str) -> String {
    text.lines()
        .map(|l| match l.split_whitespace().next() == Some(key) {
            true => {
                let eq = l.find('=').unwrap();
                let rest = l[eq + 1..].trim_start();
                let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
                format!("{} = {value}{}\n", key, &rest[end..])
            }
            false => format!("{l}\n"),
        })
        .collect()
}

/// `tyre-eval t.tir p.csv`: its stderr, and whether it succeeded.
fn eval(tir: &str) -> (String, bool) {
    let dir = scratch(&[("t.tir", tir), ("p.csv", POINTS)]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "t.tir", "p.csv", "--out", "e.csv"],
    );
    (
        String::from_utf8_lossy(&o.stderr).to_string(),
        o.status.success(),
    )
}

/// The public car tyre in kN: FNOMIN, FZMIN, the stiffnesses in kN, the
/// pressures in Pa.
fn car_in_kn(test: &str) -> Option<String> {
    let p = shared_data(test, "tir_public/car205_60R19.tir")?;
    let t = fs::read_to_string(p).unwrap();
    let t = with(&t, "FORCE", "'kN'\nPRESSURE = 'pascal'");
    let t = with(&t, "FNOMIN", "4");
    let t = with(&t, "FZMIN", "0.1");
    let t = with(&t, "VERTICAL_STIFFNESS", "209.6515");
    let t = with(&t, "Q_FYS1", "-20.4964");
    let t = with(&t, "Q_FYS2", "-60");
    Some(with(&t, "Q_FYS3", "88.2117"))
}

/// FZMAX = 8000 (N) beside FNOMIN = 4 (kN) under FORCE = 'kN' was read
/// as an 8 MN range: refused at FZMAX's line, with the unit and factor.
#[test]
fn a_load_range_in_n_under_kn_is_refused_at_its_line() {
    let Some(t) = car_in_kn("a_load_range_in_n_under_kn_is_refused_at_its_line") else {
        return;
    };
    let (e, ok) = eval(&with(&t, "FZMAX", "10"));
    assert!(ok, "{e}");
    let (e, ok) = eval(&with(&t, "FZMAX", "8000"));
    assert!(!ok);
    assert!(
        e.contains("`FZMAX`: 8000 is 8000 kN as the file's [UNITS] FORCE reads it, 2000 times its FNOMIN = 4 kN"),
        "{e}"
    );
    assert!(
        e.contains("is it written in N? (8000 N is 8 kN, 2 times FNOMIN)"),
        "{e}"
    );
}

/// The radius hint follows its direction: too large is millimetres
/// under 'meter', too small metres under 'mm'.
#[test]
fn the_radius_hint_follows_its_direction() {
    let Some(p) = shared_data(
        "the_radius_hint_follows_its_direction",
        "tir_public/car205_60R19.tir",
    ) else {
        return;
    };
    let t = fs::read_to_string(p).unwrap();
    let (e, _) = eval(&with(&t, "UNLOADED_RADIUS", "0.0003"));
    assert!(e.contains("too small: 0.0003 m is 0.3 mm"), "{e}");
    assert!(!e.contains("millimetres, written with"), "{e}");
    let (e, _) = eval(&with(&t, "UNLOADED_RADIUS", "330"));
    assert!(
        e.contains(
            "is it in millimetres, written with LENGTH = 'meter'? (330 millimetres is 0.33 m)"
        ),
        "{e}"
    );
}

/// FSAE_Defaults.tir peaks at |Fy|/Fz 3.37: read, with a warning saying
/// the number, load and slip.
#[test]
fn a_public_file_with_friction_above_2_5_is_warned_of() {
    let Some(p) = shared_data(
        "a_public_file_with_friction_above_2_5_is_warned_of",
        "tir_public/FSAE_Defaults.tir",
    ) else {
        return;
    };
    let (e, ok) = eval(&fs::read_to_string(p).unwrap());
    assert!(ok, "{e}");
    assert!(e.contains("warning: the file's pure lateral force peaks at |Fy|/Fz = 3.37 at Fz = 250 N and slip angle 0.256 rad, 14.7°, above"), "{e}");
    let car = shared_data(
        "a_public_file_with_friction_above_2_5_is_warned_of",
        "tir_public/car205_60R19.tir",
    )
    .unwrap();
    let (e, _) = eval(&fs::read_to_string(car).unwrap());
    assert!(!e.contains("peaks at"), "{e}");
}

/// A template whose curve is no tyre's is warned of at its line, as the
/// tyre would be refused (the fit sets what it starts from); the fit runs.
#[test]
fn a_template_with_a_curve_beyond_any_tyre_is_warned_of() {
    let test = "a_template_with_a_curve_beyond_any_tyre_is_warned_of";
    let (Some(p), Some(rig)) = (
        shared_data(test, "tir_public/car205_60R19.tir"),
        shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv"),
    ) else {
        return;
    };
    let tir = with(&fs::read_to_string(p).unwrap(), "PDY1", "9.0");
    let dir = scratch(&[("t.tir", &tir)]);
    // The template is judged before the data are read: the fit's own
    // length does not move the warning (the same line at 10 iterations
    // per step as at the default), and 10 take a tenth of the time.
    let args = ["identify", rig.to_str().unwrap(), "--model", "mf61"];
    let capped = ["--max-iterations", "10"];
    let o = run_in(
        dir.path(),
        &[
            &args[..],
            &capped,
            &["--template", "t.tir", "--out", "h.tir"],
        ]
        .concat(),
    );
    let e = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("warning: the template's curves are no tyre's: "),
        "{e}"
    );
    assert!(
        e.contains("t.tir:") && e.contains("`PDY1`") && e.contains("beyond the friction 5"),
        "{e}"
    );
}

/// The Hoosier mf61 fit: PKY4 stopped at its bound 0.1 is said so, not
/// as not identifiable by 723 %; LONGVL is said in km/h too.
#[test]
fn a_parameter_at_its_bound_is_said_at_its_bound() {
    let Some(fit) = hoosier_mf61("a_parameter_at_its_bound_is_said_at_its_bound") else {
        return;
    };
    let text = fit.stdout.clone() + &fit.stderr;
    assert!(
        text.contains("held: PKY4 = 2: stopped at its lower bound 0.1 when fitted (0.10"),
        "{text}"
    );
    assert!(!text.contains("% of the channel's RMS, which the other parameters' trade-off undoes): held at the Pacejka 2012 book default 2"), "{text}");
    assert!(
        text.contains("held: LONGVL = 11.2 m/s (40.3 km/h)"),
        "{text}"
    );
    // The report says what the terminal says: at its bound, with no
    // standard error or effect taken through it.
    let report = read_json(&fit.tir.with_extension("report.json"));
    let pky4 = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|s| s["parameters"].as_array().unwrap())
        .find(|p| p["name"] == "PKY4")
        .unwrap()["held"]
        .clone();
    assert_eq!(
        pky4["at_bound"],
        serde_json::json!([0.1, [0.1, 5.0]]),
        "{pky4}"
    );
    for key in ["std_error", "effect_percent", "standard_errors_away"] {
        assert!(pky4[key].is_null(), "{key}: {pky4}");
    }
}
