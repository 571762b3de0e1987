//! What `identify` records of the choices it made for the user: a level
//! asked for by a value that is not its nominal, loads pooled into a
//! model with no load terms, the warnings the terminal gave (in the
//! written file's header and in `report.json` alike), a refused `--hold`
//! and a linear fit without small slip. Run as a user runs it, from rig
//! files.

use super::trips_identify::{identify_with, rig, rig_with_levels, stdout};
use super::*;

/// The least-squares slope through the origin of `rig(1.0)`'s points at
/// `fz` with |α| ≤ 2°: what a linear tyre fitted to that load must give.
fn small_slip_slope(fz: f64) -> f64 {
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for k in -10..=10 {
        let alpha = 0.02 * f64::from(k);
        if alpha.abs() <= 2f64.to_radians() {
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            sxy += alpha * fy;
            sxx += alpha * alpha;
        }
    }
    sxy / sxx
}

/// The value of `key = …` in a TOML tyre file's text.
fn toml_value(text: &str, key: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{key} =")))
        .unwrap_or_else(|| panic!("no {key} in {text}"));
    line.split('=').nth(1).unwrap().trim().parse().unwrap()
}

/// `identify --model linear` pooled five loads of 534–2751 N into one
/// stiffness without a word (σ 35.8 % on the Hoosier file): a linear
/// tyre's force does not change with load.
#[test]
fn loads_pooled_into_a_linear_tyre_are_warned_and_one_is_fitted_with_load() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let warning =
        "3 loads pooled into one linear fit, which has no load terms: select one with --load";
    let out = dir.path().join("all.toml");
    let o = identify_with(dir.path(), "linear", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!("warning: {warning}")),
        "{}",
        stderr(&o)
    );
    let file = fs::read_to_string(&out).unwrap();
    assert!(
        file.contains(&format!("\n# warning: {warning}\n")),
        "{file}"
    );
    let report = read_json(&out.with_extension("report.json"));
    assert!(
        report["notes"]
            .as_array()
            .unwrap()
            .contains(&serde_json::json!({"text": warning, "warning": true})),
        "{}",
        report["notes"]
    );
    // One load asked for by a value near it: the level it selects is said,
    // nothing is pooled, and the stiffness is that load's.
    let out = dir.path().join("one.toml");
    let o = identify_with(dir.path(), "linear", &["--load", "4005"], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !without_temp_names(&stderr(&o)).contains("pooled"),
        "{}",
        stderr(&o)
    );
    let selected = "fz 4005 N asked for: the 4000 N level selected (its samples 4000 N to 4000 N)";
    assert!(
        stdout(&o).contains(&format!("  {selected}\n")),
        "{}",
        stdout(&o)
    );
    let file = fs::read_to_string(&out).unwrap();
    assert!(file.contains(&format!("\n# {selected}\n")), "{file}");
    assert!(
        file.starts_with("# Identified by `handling identify "),
        "{file}"
    );
    assert!(
        file.lines().next().unwrap().contains(" --load 4005 "),
        "{file}"
    );
    let c = toml_value(&file, "cornering_stiffness");
    let want = small_slip_slope(4000.0);
    assert!((c - want).abs() <= 1e-3 * want, "{c} against {want}");
    let report = read_json(&out.with_extension("report.json"));
    let s = &report["grouping"]["selected"][0];
    assert_eq!(
        (s["variable"].as_str(), s["requested"].as_f64()),
        (Some("load"), Some(4005.0))
    );
    assert_eq!(s["level"]["nominal"].as_f64(), Some(4000.0));
    assert_eq!(report["options"]["load"].as_f64(), Some(4005.0));
    // A model whose force changes with load fits its loads: not pooled.
    let out = dir.path().join("gim.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("loads pooled"), "{}", stderr(&o));
    // A load no level lies near is refused, naming the levels.
    let o = identify_with(
        dir.path(),
        "linear",
        &["--load", "9000"],
        &dir.path().join("x.toml"),
    );
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("9000 N") && e.contains("4000 N"), "{e}");
}

/// `--pressure 80000` selected the 83.4 kPa level of the Hoosier file
/// (its samples reach 81.3 kPa) and the header recorded only 80000.
#[test]
fn a_level_asked_for_off_its_nominal_is_said_with_the_level_it_selects() {
    let dir = scratch(&[("rig.csv", &rig_with_levels())]);
    let out = dir.path().join("g.toml");
    let args = ["--pressure", "180500", "--camber", "0.0001"];
    let o = identify_with(dir.path(), "gim", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&out).unwrap();
    for line in [
        "pressure 180500 Pa (180.5 kPa) asked for: the 180.0 kPa level selected (its samples 180.0 kPa to 180.0 kPa)",
        "camber 0.0001 rad (0.01°) asked for: the 0.00° level selected (its samples 0.00° to 0.00°)",
    ] {
        assert!(stdout(&o).contains(&format!("  {line}\n")), "{}", stdout(&o));
        assert!(file.contains(&format!("\n# {line}\n")), "{file}");
    }
    let report = read_json(&out.with_extension("report.json"));
    let selected = report["grouping"]["selected"].as_array().unwrap();
    let nominal = |v: &str| {
        selected
            .iter()
            .find(|s| s["variable"] == v)
            .map(|s| s["level"]["nominal"].as_f64().unwrap())
    };
    assert_eq!(
        (nominal("pressure"), nominal("camber")),
        (Some(180e3), Some(0.0))
    );
    assert_eq!(nominal("load"), None, "no load was asked for");
}

/// The lines of `text` that begin, once trimmed, with one of `marks`.
fn marked<'a>(text: &'a str, marks: &[&str]) -> Vec<&'a str> {
    text.lines()
        .map(str::trim)
        .filter(|l| marks.iter().any(|m| l.starts_with(m)))
        .collect()
}

/// The terminal warned (not identified, past a bound, levels pooled) and
/// the file written carried none of it: a tyre file read a year later
/// said nothing of what its fit left undetermined.
#[test]
fn every_warning_the_terminal_gives_is_in_the_written_file_and_the_report() {
    let dir = scratch(&[("rig.csv", &rig_with_levels())]);
    for model in ["gim", "linear", "magic-simple", "unitire", "pac89"] {
        let out = dir.path().join(format!("{model}.toml"));
        let o = identify_with(dir.path(), model, &[], &out);
        assert!(o.status.success(), "{model}: {}", stderr(&o));
        let said = format!("{}{}", stdout(&o), stderr(&o));
        let warned = marked(&said, &["warning:"]);
        // Pressures, and for most of them cambers, are pooled: at least
        // one warning to carry.
        assert!(!warned.is_empty(), "{model}: {said}");
        let file = fs::read_to_string(&out).unwrap();
        let header: Vec<&str> = file.lines().take_while(|l| l.starts_with('#')).collect();
        let header = header.join("\n").replace("# ", "");
        let written = marked(&header, &["warning:"]);
        let (mut a, mut b) = (warned.clone(), written.clone());
        a.sort_unstable();
        b.sort_unstable();
        assert_eq!(a, b, "{model}: the terminal's warnings and the header's");
        let report = read_json(&out.with_extension("report.json"));
        let notes: Vec<String> = report["notes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|n| n["warning"] == true)
            .map(|n| format!("warning: {}", n["text"].as_str().unwrap()))
            .collect();
        for w in &warned {
            assert!(
                notes.iter().any(|n| n == w),
                "{model}: {w} not in {notes:?}"
            );
        }
    }
    // The staged Magic Formula fit: each stage's σ, its warnings (a stage
    // stopped on its cap) and what it held, in the .tir's header.
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("m.tir");
    let o = identify_with(dir.path(), "mf61", &["--max-iterations", "2"], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let lines = marked(&said, &["warning:", "held:", "pure Fy", "pure Mz"]);
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("warning: not converged")),
        "{said}"
    );
    let tir = fs::read_to_string(&out).unwrap();
    for l in lines {
        // The file's stage lines carry no seconds (a refit writes the same
        // file); the rest is the terminal's line.
        let l = l
            .rsplit_once(", ")
            .filter(|(_, t)| t.ends_with(" s"))
            .map_or(l, |(h, _)| h);
        assert!(tir.contains(&format!("\n$ {l}")), "{l}\n{tir}");
    }
}

/// A held value the tyre reader refuses named the parameter but not the
/// option it came from.
#[test]
fn a_refused_held_value_names_the_hold_as_given() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let o = identify_with(
        dir.path(),
        "gim",
        &["--hold", "friction=50"],
        &dir.path().join("t.toml"),
    );
    assert!(!o.status.success());
    assert!(
        stderr(&o).starts_with("error: --hold friction=50: `friction` = 50: must lie in (0, 5]"),
        "{}",
        stderr(&o)
    );
}

/// A linear fit to data with no slip angle below 2° failed with the
/// general "no test condition found".
#[test]
fn a_linear_fit_without_small_slip_angles_names_the_window() {
    let mut s = String::from("fz,alpha,fy\n");
    for fz in [2000.0, 4000.0] {
        for d in 3..=12 {
            for sign in [-1.0, 1.0] {
                let alpha = sign * f64::from(d).to_radians();
                s += &format!(
                    "{fz},{alpha},{:.3}\n",
                    fz * (1.4 * (12.0 * alpha).atan()).sin()
                );
            }
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let o = identify_with(dir.path(), "linear", &[], &dir.path().join("t.toml"));
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("no condition has two points within |alpha| <= 2 deg, where a linear tyre is fitted (40 points, the smallest |alpha| 3.00 deg)"),
        "{e}"
    );
    assert!(!dir.path().join("t.toml").exists());
}

/// `tyre-eval` of a TOML tyre said nothing of inputs its model does not
/// read (a Gim tyre's camber and pressure) or of points beyond the rig
/// data it was fitted to, which its header stated in a comment only.
#[test]
fn tyre_eval_says_what_the_model_does_not_read_and_where_it_extrapolates() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let tyre = dir.path().join("g.toml");
    let o = identify_with(dir.path(), "gim", &[], &tyre);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&tyre).unwrap();
    assert!(
        file.contains("\n[fitted_ranges]\nfz = [2000.0, 6000.0]\nalpha = [-0.2, 0.2]\n"),
        "{file}"
    );
    // Inside, above the loads, beyond the slip angles.
    let points = "fz,kappa,alpha,camber,speed,pressure\n\
                  4000,0,0.1,0.02,20,200000\n\
                  9000,0,0.1,0,20,200000\n\
                  4000,0,-0.3,0,20,200000\n";
    fs::write(dir.path().join("p.csv"), points).unwrap();
    let eval = |tyre: &Path, out: &str| {
        bin()
            .args(["tyre-eval", tyre.to_str().unwrap(), "p.csv", "--out", out])
            .current_dir(dir.path())
            .output()
            .unwrap()
    };
    let o = eval(&tyre, "e.csv");
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    for w in [
        "warning: this gim tyre does not respond to `camber`: its forces and moments are the same at any value (1 point with camber ≠ 0, evaluated as at 0); its model does not read it, or its coefficients give it no effect",
        "warning: this gim tyre does not respond to `pressure`: its forces and moments are the same at any value (the pressure given at 3 points ignored); its model does not read it, or its coefficients give it no effect",
        "warning: 1 of 3 points above the rig data's fz = 6000 N the tyre was fitted to (its [fitted_ranges]: 2000 to 6000 N): evaluated by extrapolation, the farthest at 9000 N, 75.0 % of the range's span past its end; the first at line 3, fz = 9000 N",
        "warning: 1 of 3 points below the rig data's alpha = -0.2000 rad the tyre was fitted to (its [fitted_ranges]: -0.2000 to 0.2000 rad): evaluated by extrapolation, the farthest at -0.3 rad, 25.0 % of the range's span past its end; the first at line 4, alpha = -0.3 rad",
    ] {
        assert!(e.contains(w), "{w}\n{e}");
    }
    // kappa is 0 at every point: not said.
    assert!(!e.contains("`kappa`"), "{e}");
    // A hand-written tyre states no ranges: no point is counted.
    let o = eval(&root().join("tyres/gim.toml"), "e2.csv");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !stderr(&o).contains("the tyre was fitted to"),
        "{}",
        stderr(&o)
    );
    // A reversed range is refused at its element.
    fs::write(
        dir.path().join("bad.toml"),
        file.replace("fz = [2000.0, 6000.0]", "fz = [6000.0, 2000.0]"),
    )
    .unwrap();
    let o = eval(&dir.path().join("bad.toml"), "e3.csv");
    assert!(!o.status.success());
    assert!(
        stderr(&o)
            .contains("`fitted_ranges.fz[1]` = 2000: must lie above the range's lower end, 6000"),
        "{}",
        stderr(&o)
    );
}

/// A parameter held twice was taken at its last value silently, a road
/// friction of 100 ran for minutes into a spin, and a held value was
/// written among the warnings.
#[test]
fn a_hold_given_twice_and_a_road_friction_past_any_road_are_refused() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let args = ["--hold", "friction=1.5", "--hold", "friction=1.6"];
    let o = identify_with(dir.path(), "gim", &args, &dir.path().join("t.toml"));
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains(
            "error: --hold friction is given twice (1.5 and 1.6): hold each parameter once"
        ),
        "{}",
        stderr(&o)
    );
    // Held once: said as held, not warned of.
    let out = dir.path().join("h.toml");
    let o = identify_with(dir.path(), "gim", &args[..2], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&out).unwrap();
    assert!(!file.contains("warning: friction ="), "{file}");
    let scenario = fs::read_to_string(root().join("scenarios/sedan_step.toml"))
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let scenario = match scenario.find("[road]") {
        Some(_) => scenario.replacen("friction = 1.0", "friction = 100.0", 1),
        None => format!("{scenario}\n[road]\nfriction = 100.0\n"),
    };
    fs::write(dir.path().join("s.toml"), &scenario).unwrap();
    let o = bin()
        .args(["simulate", "s.toml", "--out", "out"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains(
            "`road.friction` = 100: must lie in (0, 3]: the road's friction scales the tyres' own"
        ),
        "{e}"
    );
}

/// The written `[fitted_ranges]` ran over the thinned points' loads (bin
/// means, 1601–1681 N on a Hoosier level whose samples ran 1474–1823 N),
/// so `tyre-eval` called measured loads an extrapolation.
#[test]
fn the_fitted_ranges_hold_every_sample_of_the_levels_fitted() {
    // Loads wandering ±50 N about 2, 4 and 6 kN, several samples a bin.
    let mut s = String::from("fz,alpha,fy\n");
    for fz0 in [2000.0, 4000.0, 6000.0] {
        for k in 0..=400 {
            let alpha = -0.2 + 0.001 * f64::from(k);
            let fz = fz0 + 50.0 * (0.37 * f64::from(k)).sin();
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            s += &format!("{fz:.3},{alpha},{fy:.3}\n");
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("g.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = fs::read_to_string(&out).unwrap();
    let line = file.lines().find(|l| l.starts_with("fz = [")).unwrap();
    let v: Vec<f64> = line
        .trim_start_matches("fz = [")
        .trim_end_matches(']')
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect();
    assert!(v[0] <= 1950.5 && v[1] >= 6049.5, "{line}");
    assert!(v[0] >= 1949.0 && v[1] <= 6051.0, "{line}");
}
