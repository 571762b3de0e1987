//! What a user still trips on in `identify`: loads in kN,
//! `--hold` names that differ from the tyre file's, holds not reported,
//! a stage that stops on its iteration cap.

use super::*;

/// Rig data at 2, 4 and 6 kN, a slip sweep of ±0.2 rad each, with `mz`;
/// loads divided by `fz_scale`.
pub(super) fn rig(fz_scale: f64) -> String {
    let mut s = String::from("fz,alpha,fy,mz\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            s += &format!("{},{alpha},{fy:.3},{:.4}\n", fz / fz_scale, 0.02 * fy);
        }
    }
    s
}

/// Runs `identify rig.csv --model model args… --out out` in `dir`.
pub(super) fn identify_with(dir: &Path, model: &str, args: &[&str], out: &Path) -> Output {
    let mut all = vec![
        "identify".to_string(),
        dir.join("rig.csv").display().to_string(),
        "--model".into(),
        model.into(),
    ];
    all.extend(args.iter().map(|a| a.to_string()));
    all.extend(["--out".into(), out.display().to_string()]);
    bin().args(&all).current_dir(dir).output().unwrap()
}

/// The entries of a report's `held` given with `--hold` (the others are
/// the values held for want of levels and the constants).
fn given(report: &serde_json::Value) -> serde_json::Value {
    let all = report["held"].as_array().unwrap();
    all.iter()
        .filter(|h| h["why"] == "given")
        .cloned()
        .collect()
}

pub(super) fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Loads in kN (2–6) were fitted as newtons.
#[test]
fn loads_in_kn_are_refused_at_their_column_with_the_hint() {
    let dir = scratch(&[("rig.csv", &rig(1000.0))]);
    for (model, out) in [("gim", "t.toml"), ("mf61", "t.tir")] {
        let out = dir.path().join(out);
        let e = refused(&identify_with(dir.path(), model, &[], &out), &out);
        assert!(
            e.contains("rig.csv:2:1: column `fz`: 2 N, in a file whose median load is 4 N: no tyre is tested at a median load below 100 N"),
            "{model}: {e}"
        );
        assert!(
            e.contains("is the column in kN? multiply it by 1000"),
            "{e}"
        );
    }
}

/// UniTire's holds were named b1.., c1.., a1.. where the file it writes
/// has `[lateral] p`, `[aligning] c`, `[longitudinal] p`; a hold of a
/// block no fit ran was dropped silently.
#[test]
fn unitire_holds_take_the_names_of_the_file_it_writes_and_are_reported() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("u.toml");
    let holds = [
        "--hold",
        "lateral.p1=0.3",
        "--hold",
        "aligning.c2=0.004",
        "--hold",
        "longitudinal.p3=18",
    ];
    let o = identify_with(dir.path(), "unitire", &holds, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    assert!(
        said.contains("held with --hold (not fitted): lateral.p1 = 0.3, aligning.c2 = 0.004"),
        "{said}"
    );
    assert!(
        said.contains("warning: --hold longitudinal.p3=18: not applied: no fit of its block ran on these data"),
        "{said}"
    );
    let tyre: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(tyre["lateral"]["p"][0].as_float(), Some(0.3));
    assert_eq!(tyre["aligning"]["c"][1].as_float(), Some(0.004));
    assert!(tyre.get("longitudinal").is_none(), "{tyre}");
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(
        given(&report),
        serde_json::json!([
            {"name": "lateral.p1", "value": 0.3, "applied": true, "why": "given"},
            {"name": "aligning.c2", "value": 0.004, "applied": true, "why": "given"},
            {"name": "longitudinal.p3", "value": 18.0, "applied": false, "why": "given"},
        ])
    );
    // The fitter's own names are no longer taken.
    let bad = dir.path().join("bad.toml");
    let e = refused(
        &identify_with(dir.path(), "unitire", &["--hold", "b1=0.3"], &bad),
        &bad,
    );
    assert!(
        e.contains("its parameters are lateral.p1, lateral.p2,"),
        "{e}"
    );
}

/// Holding the linear tyre's one parameter panicked in the swarm ("chunk
/// size must not be zero").
#[test]
fn a_linear_tyre_with_its_stiffness_held_is_written_as_held() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("l.toml");
    let o = identify_with(
        dir.path(),
        "linear",
        &["--hold", "cornering_stiffness=60000"],
        &out,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("held with --hold (not fitted): cornering_stiffness = 60000"),
        "{}",
        stdout(&o)
    );
    let tyre: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(tyre["cornering_stiffness"].as_float(), Some(60000.0));
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(report["held"][0]["applied"], true);
    assert_eq!(report["parameters"][0]["free"], false);
}

/// A staged MF fit held a coefficient without a word in the .tir, and a
/// stage stopped on its iteration cap said nothing.
#[test]
fn an_mf_fit_records_its_hold_in_the_tir_and_says_a_stage_did_not_converge() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("m.tir");
    let args = ["--hold", "PKY4=2", "--max-iterations", "2"];
    let o = identify_with(dir.path(), "mf61", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    assert!(
        said.contains("held with --hold (not fitted): PKY4 = 2"),
        "{said}"
    );
    assert!(
        said.contains("warning: not converged: Levenberg–Marquardt stopped at its cap of 2 iterations per step before its convergence test"),
        "{said}"
    );
    let tir = fs::read_to_string(&out).unwrap();
    assert!(
        tir.starts_with("$ identified by `handling identify "),
        "{tir}"
    );
    assert!(
        tir.contains("\n$ held: PKY4 = 2: given with --hold, not fitted (SI units)\n"),
        "{tir}"
    );
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(
        given(&report),
        serde_json::json!([{"name": "PKY4", "value": 2.0, "applied": true, "why": "given"}])
    );
    assert!(
        unconverged_stages_warn(&report, &said) > 0,
        "two iterations stop a stage short"
    );
    // With the default cap: the warning where a stage stopped short, and
    // only there.
    let out = dir.path().join("m2.tir");
    let o = identify_with(dir.path(), "mf61", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&out.with_extension("report.json"));
    assert!(
        unconverged_stages_warn(&report, &stdout(&o)) < 3,
        "{report}"
    );
}

/// Checks that a fitted stage of `report` carries the "not converged"
/// warning, in the report and on the terminal `said`, exactly when it did
/// not converge; returns how many did not.
fn unconverged_stages_warn(report: &serde_json::Value, said: &str) -> usize {
    let fitted: Vec<&serde_json::Value> = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["skipped"].is_null())
        .collect();
    let mut unconverged = 0;
    for s in &fitted {
        let warns = s["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().starts_with("not converged"));
        assert_eq!(warns, s["converged"] == false, "{s}");
        unconverged += usize::from(warns);
    }
    assert_eq!(
        said.matches("warning: not converged").count(),
        unconverged,
        "{said}"
    );
    unconverged
}

/// Rig data at 2, 4 and 6 kN, two cambers (0, 0.03 rad) and two
/// pressures (180, 220 kPa), with `mz`: levels to select.
pub(super) fn rig_with_levels() -> String {
    let mut s = String::from("fz,alpha,camber,pressure,fy,mz\n");
    for p in [180e3, 220e3] {
        for camber in [0.0, 0.03] {
            for fz in [2000.0, 4000.0, 6000.0] {
                for k in -10..=10 {
                    let alpha = 0.02 * f64::from(k);
                    let mu = 1.4 - 0.5 * camber - (p - 200e3) * 1e-6;
                    let fy = fz * (mu * (12.0 * alpha).atan()).sin();
                    s += &format!("{fz},{alpha},{camber},{p},{fy:.3},{:.4}\n", 0.02 * fy);
                }
            }
        }
    }
    s
}

/// The text of the first line of `text` between the first pair of
/// backquotes.
fn quoted_command(text: &str) -> String {
    let line = text.lines().next().unwrap();
    let start = line.find('`').unwrap() + 1;
    let len = line[start..].find('`').unwrap();
    line[start..start + len].to_string()
}

/// The header named `--model gim --seed 1 --hold …` only: without the
/// `--pressure`, `--camber`, `--local` and `--bin-deg` of the fit, the
/// command it stated fitted other data.
#[test]
fn the_header_states_every_option_that_changes_the_fit_and_repeats_it() {
    let dir = scratch(&[("rig.csv", &rig_with_levels())]);
    let out = dir.path().join("g.toml");
    let args = [
        "--seed",
        "3",
        "--pressure",
        "220000",
        "--camber",
        "0.03",
        "--local",
        "gn",
        "--bin-deg",
        "0.5",
        "--hold",
        "friction_decay=0.1",
    ];
    let o = identify_with(dir.path(), "gim", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&out).unwrap();
    let rig = dir.path().join("rig.csv");
    let command = format!(
        "handling identify {} --model gim --seed 3 --pressure 220000 --camber 0.03 --local gn --bin-deg 0.5 --bin-kappa 0.0025 --hold friction_decay=0.1",
        rig.display()
    );
    assert_eq!(quoted_command(&text), command);
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(
        report["options"],
        serde_json::json!({
            "command": command, "model": "gim", "seed": 3, "load": null, "pressure": 220000.0,
            "camber": 0.03, "local": "gn", "bin_deg": 0.5, "bin_kappa": 0.0025,
            "hold": [{"name": "friction_decay", "value": 0.1}],
        })
    );
    // The stated command, run, writes the same tyre.
    let again = dir.path().join("again.toml");
    let words: Vec<&str> = command.split(' ').skip(1).collect();
    let o = bin()
        .args(&words)
        .args(["--out", again.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let body = |t: &str| t.lines().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&fs::read_to_string(&again).unwrap()), body(&text));
    // A fit of the other levels is another tyre: the options mattered.
    let other = dir.path().join("other.toml");
    let o = identify_with(dir.path(), "gim", &args[..4], &other);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_ne!(body(&fs::read_to_string(&other).unwrap()), body(&text));
}

/// A staged fit's .tir named its command only with a hold, and then
/// without its start, template, iteration cap and bin.
#[test]
fn an_mf_tir_states_the_command_that_repeats_its_fit() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("m.tir");
    let args = [
        "--start",
        "paper",
        "--max-iterations",
        "40",
        "--bin-deg",
        "0",
    ];
    let o = identify_with(dir.path(), "mf62", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let command = format!(
        "handling identify {} --model mf62 --start paper --max-iterations 40 --bin-deg 0",
        dir.path().join("rig.csv").display()
    );
    let tir = fs::read_to_string(&out).unwrap();
    assert_eq!(quoted_command(&tir), command);
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(
        report["options"],
        serde_json::json!({
            "command": command, "model": "mf62", "bin_deg": 0.0, "start": "paper",
            "template": null, "max_iterations": 40, "hold": [],
        })
    );
}

/// `--hold friction=50` was fitted and written, and `tyre-eval` then
/// refused the file; a stiffness held at 1 N/rad drove the contact length
/// to thousands of metres, written alike. (A stiffness of 1000 N/rad, a
/// car tyre's N/deg figure, is now refused as held.)
#[test]
fn no_file_is_written_that_the_tyre_reader_refuses() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let cases = [
        (
            "gim",
            "friction=50",
            "t.toml",
            "`friction` = 50: must lie in (0, 5]: no tyre's friction coefficient reaches 5",
        ),
        (
            "unitire",
            "lateral.p2=-1",
            "u.toml",
            "`lateral.p2` = -1: must be positive",
        ),
        (
            "mf61",
            "FNOMIN=4",
            "m.tir",
            "`FNOMIN` = 4: must lie in (100, 100000]: a tyre carries 100 N",
        ),
        // A car tyre's N/deg figure, 0.25 N/rad per N of the load the hold
        // is checked at.
        (
            "gim",
            "cornering_stiffness=1000",
            "k.toml",
            "`cornering_stiffness` = 1000: over the tyre's reference_load = 4000 N",
        ),
    ];
    for (model, hold, out, said) in cases {
        let out = dir.path().join(out);
        let e = refused(
            &identify_with(dir.path(), model, &["--hold", hold], &out),
            &out,
        );
        assert!(e.contains(said), "{model}: {e}");
        // Refused before the data are read: nothing is fitted.
        assert!(!e.contains("rig.csv"), "{e}");
    }
    // Values within the limits that once drove another past them (the
    // contact length to 2 m, and the fit refused): the polish now keeps a
    // value the tyre file's check would refuse inside its search box, so
    // the fit is written with the contact length on its bound, said, and
    // the file is one the reader takes.
    let out = dir.path().join("k.toml");
    let args = [
        "--hold",
        "cornering_stiffness=6000",
        "--hold",
        "load_exponent=1.5",
        "--hold",
        "friction=0.2",
    ];
    let o = identify_with(dir.path(), "gim", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = format!("{}{}", stdout(&o), stderr(&o));
    assert!(
        said.contains("contact_length") && said.contains("on its search bound"),
        "{said}"
    );
    let written = fs::read_to_string(&out).unwrap();
    let length: f64 = written
        .lines()
        .find_map(|l| l.strip_prefix("contact_length = "))
        .and_then(|v| v.trim().parse().ok())
        .expect("a contact_length line");
    assert!(length > 0.0 && length <= 1.0, "{length}");
    // Within them, the file written is one the reader takes.
    let out = dir.path().join("ok.toml");
    let args = ["--hold", "friction=1.2"];
    let o = identify_with(dir.path(), "gim", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let points = dir.path().join("points.csv");
    fs::write(&points, "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,10\n").unwrap();
    let forces = dir.path().join("forces.csv");
    let e = bin()
        .args(["tyre-eval", out.to_str().unwrap(), points.to_str().unwrap()])
        .args(["--out", forces.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(e.status.success(), "{}", stderr(&e));
    assert!(fs::read_to_string(&forces).unwrap().lines().count() == 2);
}

/// Rig data of a Gim tyre (60 kN/rad, contact length 0.2 m, μ 1.2) at 2,
/// 4 and 6 kN, with its `mz`: the trail model follows them.
fn gim_rig() -> String {
    let (k, l, mu) = (60_000.0_f64, 0.2, 1.2);
    let mut s = String::from("fz,alpha,fy,mz\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in -10..=10 {
            let alpha = 0.02 * f64::from(i);
            let (t, theta) = (f64::tan(alpha), k / (3.0 * mu * fz));
            let ln = (1.0 - theta * t.abs()).max(0.0);
            let fy = mu * fz * (1.0 - ln.powi(3)) * t.signum();
            let mz = mu * fz * 0.5 * l * theta * t * ln.powi(3);
            s += &format!("{fz},{alpha},{fy},{mz}\n");
        }
    }
    s
}

/// Gim's contact length, fitted to `mz`, was printed `held: contact_length
/// = 0.3944…: not fitted…` with 17 digits; an Mz fit of σ 44.7 % said
/// nothing.
#[test]
fn gims_contact_length_is_said_fitted_to_mz_and_a_trail_that_misses_is_warned() {
    let dir = scratch(&[("rig.csv", &gim_rig())]);
    let out = dir.path().join("g.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let fitted = "contact_length = 0.2000 (standard error ";
    let line = said
        .lines()
        .find(|l| l.contains(fitted))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.ends_with("): fitted to the aligning moment (σ 0.0 %), not to the lateral force"),
        "{line}"
    );
    assert!(!said.contains("held: contact_length"), "{said}");
    assert!(!said.contains("does not follow these data"), "{said}");
    let text = fs::read_to_string(&out).unwrap();
    assert!(
        text.contains(&format!("\n# {}", line.trim_start())),
        "{text}"
    );
    let report = read_json(&out.with_extension("report.json"));
    assert_eq!(report["held"], serde_json::json!([]), "{report}");
    // Data whose mz is a fixed share of fy: the trail model misses them.
    fs::write(dir.path().join("rig.csv"), rig(1.0)).unwrap();
    let out = dir.path().join("g2.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&out.with_extension("report.json"));
    let sigma = report["aligning"]["sigma_percent"].as_f64().unwrap();
    assert!(sigma > 20.0, "{sigma}");
    let warning = format!(
        "warning: the aligning moment's σ is {sigma:.1} %: the gim model's aligning moment does not follow these data"
    );
    assert!(
        stdout(&o).contains(&format!("  {warning}")),
        "{}",
        stdout(&o)
    );
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains(&format!("\n# {warning}")), "{text}");
}

/// `tyre-eval`'s `fy` of the tyre file `tyre` at load `fz` and slip angle
/// `alpha` (rad), in `dir`.
fn fy_at(dir: &Path, tyre: &Path, fz: f64, alpha: f64) -> f64 {
    let points = dir.join("points.csv");
    fs::write(
        &points,
        format!("fz,kappa,alpha,camber,speed\n{fz},0,{alpha},0,10\n"),
    )
    .unwrap();
    let forces = dir.join("forces.csv");
    let o = bin()
        .args([
            "tyre-eval",
            tyre.to_str().unwrap(),
            points.to_str().unwrap(),
        ])
        .args(["--out", forces.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&forces).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    row[head.iter().position(|h| *h == "fy").unwrap()]
        .parse()
        .unwrap()
}

/// A .tir written by identify had no FZMIN…PRESMAX, so tyre-eval
/// extrapolated past the data silently; a cornering-only file's
/// longitudinal coefficients were said only as "pure Fx skipped".
#[test]
fn a_fitted_tir_holds_the_datas_ranges_and_says_its_longitudinal_force_is_not_fitted() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let out = dir.path().join("m.tir");
    let o = identify_with(dir.path(), "mf61", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let tir = fs::read_to_string(&out).unwrap();
    for range in [
        "[VERTICAL_FORCE_RANGE]\nFZMIN                     = 2000\nFZMAX                     = 6000\n",
        "[SLIP_ANGLE_RANGE]\nALPMIN                    = -0.2\nALPMAX                    = 0.2\n",
    ] {
        assert!(tir.contains(range), "{tir}");
    }
    // No slip ratio in the data: no range that would cut Fx off.
    assert!(!without_temp_names(&tir).contains("KPUMIN"), "{tir}");
    assert!(
        tir.contains(
            "\n$ at one value in the rows: kappa at 0, camber at 0 rad: no range is written\n"
        ),
        "{tir}"
    );
    let no_fx = "no longitudinal data: the longitudinal force block is not fitted (no pure longitudinal rows (columns `kappa` and `fx`, |α| ≤ 1e-3 rad)): its coefficients are the defaults' (no --template); the written file's longitudinal force is 0 at any slip ratio (PDX1 = 0, PKX1 = 0): give --template with a tyre's longitudinal coefficients for one";
    assert!(tir.contains(&format!("\n$ {no_fx}\n")), "{tir}");
    assert!(
        stdout(&o).contains(&format!("\n  {no_fx}\n")),
        "{}",
        stdout(&o)
    );
    // Past the data, tyre-eval holds the force at the range's edge.
    let edge = fy_at(dir.path(), &out, 6000.0, 0.2);
    assert_eq!(fy_at(dir.path(), &out, 6000.0, 0.35), edge);
    assert_eq!(fy_at(dir.path(), &out, 9000.0, 0.2), edge);
    assert!(fy_at(dir.path(), &out, 6000.0, 0.1) < edge);
    // A TOML tyre states the ranges in its header.
    let out = dir.path().join("g.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&out).unwrap();
    assert_eq!(
        text.lines().nth(1),
        Some("# ranges of the rig data fitted: fz 2000 to 6000 N, alpha -0.2000 to 0.2000 rad, camber at 0 rad; the tyre is not checked beyond them")
    );
}

/// Cambers pooled into a model without camber terms said nothing, where
/// pressures pooled alike were warned.
#[test]
fn cambers_pooled_into_a_model_without_camber_terms_are_warned_as_pressures_are() {
    let dir = scratch(&[("rig.csv", &rig_with_levels())]);
    let warning = |model: &str| {
        format!("warning: 2 cambers pooled into one {model} fit, which has no camber terms: select one with --camber")
    };
    for model in ["gim", "linear", "magic-simple", "unitire"] {
        let out = dir.path().join(format!("{model}.toml"));
        let o = identify_with(dir.path(), model, &["--pressure", "180000"], &out);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            stderr(&o).contains(&warning(model)),
            "{model}: {}",
            stderr(&o)
        );
        assert!(!stderr(&o).contains("pressures pooled"), "{}", stderr(&o));
        // One camber selected: nothing pooled (a linear tyre, which has
        // no load terms either, at one load).
        let mut args = vec!["--pressure", "180000", "--camber", "0"];
        if model == "linear" {
            args.extend(["--load", "4000"]);
        }
        let o = identify_with(dir.path(), model, &args, &out.with_extension("one.toml"));
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            !without_temp_names(&stderr(&o)).contains("pooled"),
            "{}",
            stderr(&o)
        );
    }
    // PAC89 has camber terms: its cambers are fitted, not pooled.
    let out = dir.path().join("pac89.toml");
    let o = identify_with(dir.path(), "pac89", &["--pressure", "180000"], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("cambers pooled"), "{}", stderr(&o));
    // Both pooled: both said.
    let out = dir.path().join("both.toml");
    let o = identify_with(dir.path(), "gim", &[], &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("warning: 2 pressures pooled into one gim fit, which has no pressure terms: select one with --pressure"), "{e}");
    assert!(e.contains(&warning("gim")), "{e}");
}
