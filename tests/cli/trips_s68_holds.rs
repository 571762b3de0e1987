//! What a user still tripped on: `identify --model pac89` on
//! the public Hoosier file wrote `a1 = −59.45 ± 320`, `a2 = 1328 ± 7117`
//! and `a7 = 0.9957 ± 24.4` with warnings only. The swarm fit now holds a
//! parameter the data do not determine at the model's start value and
//! refits the rest: the file's header, the terminal and the report say
//! which and why, no parameter written is left with a standard error above
//! its value that moves the fit by 1 % of its RMS unsaid, and σ barely
//! rises. A held value is one the data allow: the start value within two
//! standard errors of the free fit, else the nearest end of those two;
//! a hold that costs more than the data can ignore is refused, and the
//! parameter left free with its warning (aligning c9: start −1.3329, free
//! −0.1947 ± 0.3174, is held at −0.829, its ±2 edge rounded towards the
//! fit, at a σ rise well within the guard's 5 % of σ).

use super::*;

/// The most σ may rise by holding what the data do not determine, in
/// points of %: the lateral force (measured +0.0007, 5.8488 → 5.8495 %)
/// and the aligning moment (measured +0.003, 16.279 → 16.282 %, c6 and
/// c14 held; +0.053 when c9 was held at its start value, 3.6 standard
/// errors out).
const LATERAL_RISE: f64 = 0.01;
const ALIGNING_RISE: f64 = 0.1;

#[test]
fn pac89_on_the_hoosier_file_holds_what_the_data_do_not_determine() {
    let Some(fit) = hoosier_pac89("pac89_on_the_hoosier_file_holds_what_the_data_do_not_determine")
    else {
        return;
    };
    let (text, out) = (&fit.stdout, &fit.tyre);
    let file = fs::read_to_string(out).unwrap();
    let report = read_json(&out.with_extension("report.json"));
    let held = undetermined_holds(&report);
    let names: Vec<&str> = held.iter().map(|h| h["name"].as_str().unwrap()).collect();
    // The curvature's constant term, free beside `a6 = 0` of the curvature
    // rule (never held twice), and the aligning terms the data leave open.
    assert!(names.contains(&"a7"), "{names:?}");
    assert!(!names.contains(&"a6"), "{names:?}");
    for h in &held {
        let name = h["name"].as_str().unwrap();
        let (fitted, value) = (h["fitted"].as_f64().unwrap(), h["value"].as_f64().unwrap());
        let stated = h["stated"].as_f64().unwrap();
        assert_eq!(h["held_at"].as_f64(), Some(value), "{h}");
        // Flagged by the rule: no standard error, or one that reaches the
        // value and moves the fit by 1 % of its RMS; held where the data
        // allow, within two standard errors of the free fit, at the start
        // value when that lies within them.
        if let Some(se) = h["std_error"].as_f64() {
            assert!(se >= fitted.abs(), "{h}");
            assert!(h["effect_percent"].as_f64().unwrap() >= 1.0, "{h}");
            assert!((value - fitted).abs() <= 2.0 * se * (1.0 + 1e-9), "{h}");
            let away = h["standard_errors_away"].as_f64().unwrap();
            assert!((away - (stated - fitted).abs() / se).abs() < 1e-9, "{h}");
            if away <= 2.0 {
                assert_eq!(value, stated, "{h}");
            }
        }
        // The file's header and the terminal say it, with its reason.
        let line = format!("held: {name} = ");
        for (what, said) in [("file", &file), ("terminal", text)] {
            let at = said
                .lines()
                .find(|l| l.contains(&line))
                .unwrap_or_else(|| panic!("the {what} does not hold {name}: {said}"));
            // The value held and the start value, or the start value
            // itself when that is the one held.
            assert!(
                at.contains("not determined by these data: fitted free it was"),
                "{at}"
            );
            assert!(
                at.contains(&format!("held at the model's start value {stated}"))
                    || at.contains(&format!(
                        "standard errors nearest the model's start value {stated}"
                    )),
                "{at}"
            );
        }
        // The value written is the one held.
        let param = |f: &serde_json::Value| {
            f["parameters"]
                .as_array()
                .unwrap()
                .iter()
                .find(|p| p["name"] == name)
                .cloned()
        };
        let p = param(&report)
            .or_else(|| param(&report["aligning"]))
            .unwrap();
        assert_eq!(p["value"].as_f64(), Some(value), "{p}");
        assert!(p["warning"].is_null() && p["free"] == false, "{p}");
    }
    // No parameter written is undetermined with a visible effect unsaid:
    // one the guard left free would carry its warning; here none is.
    let mut refused = Vec::new();
    for f in [&report, &report["aligning"]] {
        for p in f["parameters"].as_array().unwrap() {
            let (Some(se), Some(v)) = (p["std_error"].as_f64(), p["value"].as_f64()) else {
                continue;
            };
            let effect = p["effect_percent"].as_f64().unwrap();
            let w = p["warning"].as_str().unwrap_or_default();
            if se >= v.abs() && effect >= 1.0 {
                assert!(w.starts_with("not identified by the data"), "{p}");
                refused.push(p["name"].as_str().unwrap());
            } else if se > v.abs() {
                // One left free for its small effect says why (a13: 4.51
                // ± 4.88 at 0.3 %).
                // Said, not warned of.
                let n = p["note"].as_str().unwrap_or_default();
                assert!(w.is_empty() && n.contains("the fit hardly shows"), "{p}");
            }
        }
    }
    assert!(refused.is_empty(), "{refused:?}: {text}");
    let c9 = held.iter().find(|h| h["name"] == "c9").expect("c9 held");
    assert_eq!(c9["value"].as_f64(), Some(-0.829), "{c9}");
    assert!(
        text.contains("so it is held at -0.829, the end of the free fit's ±2 standard errors nearest the model's start value -1.3329"),
        "{text}"
    );
    // Holding them costs little.
    for (f, rise) in [
        (&report, LATERAL_RISE),
        (&report["aligning"], ALIGNING_RISE),
    ] {
        let (held, free) = (
            f["sigma_percent"].as_f64().unwrap(),
            f["free_sigma_percent"].as_f64().unwrap(),
        );
        assert!(
            held >= free - 1e-9 && held < free + rise,
            "{held} against {free}"
        );
    }
    assert!(
        text.contains(
            "lateral force: a7 held at the model's start value, as the data do not determine it"
        ),
        "{text}"
    );
}
