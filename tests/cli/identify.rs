//! Tyre identification from rig files.

use super::trips_s69_identify::{at_pressure, hoosier};
use super::*;

fn rig_csv(rows: &[(f64, f64, f64)]) -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for (fz, a, fy) in rows {
        s.push_str(&format!("{fz},{a},{fy}\n"));
    }
    s
}

/// What `identify`'s terminal output must never show: a number printed as
/// a negative zero ("camber -0.00°"), or a two-stage line saying one σ is
/// below another while printing both alike.
pub(crate) fn assert_tidy_output(stdout: &str) {
    for word in stdout.split(|c: char| c.is_whitespace() || c == '(') {
        let number = word.trim_end_matches(['°', ',', ')', ':', '%', ';']);
        assert!(
            !(number.starts_with('-') && number.parse::<f64>() == Ok(0.0)),
            "negative zero `{word}` in: {stdout}"
        );
    }
    for line in stdout
        .lines()
        .filter(|l| l.contains("writing the two-stage result"))
    {
        let chosen = text_between(line, "σ over all points ", " %");
        assert!(
            !line.contains(&format!("< direct {chosen} %")),
            "the two σ print alike: {line}"
        );
    }
}

/// The text of `line` after `from` up to the next `to`.
fn text_between<'a>(line: &'a str, from: &str, to: &str) -> &'a str {
    let start = line.find(from).unwrap_or_else(|| panic!("{from}: {line}")) + from.len();
    let len = line[start..].find(to).unwrap_or(line.len() - start);
    &line[start..start + len]
}

#[test]
fn identify_refuses_bad_rig_data_clearly() {
    // No lateral columns.
    let dir = scratch(&[("rig.csv", "fz,kappa,fx\n4000,0.01,500\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(
        e.contains("rig.csv")
            && e.contains("no lateral data")
            && e.contains("no longitudinal force"),
        "{e}"
    );
    // Neither lateral nor longitudinal columns.
    let dir2 = scratch(&[("rig.csv", "fz,speed\n4000,10\n")]);
    let e = stderr(&run(&[
        "identify",
        dir2.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
    ]));
    assert!(
        e.contains("no lateral data") && e.contains("no longitudinal data"),
        "{e}"
    );
    // Unknown model.
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac2002",
    ]));
    assert!(e.contains("unknown tyre model `pac2002`"), "{e}");
    // A NaN cell.
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,500\n4000,NaN,600\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(e.contains("rig.csv:3:2") && e.contains("alpha"), "{e}");
    // A single load for a load-dependent model.
    let rows: Vec<(f64, f64, f64)> = (0..40)
        .map(|i| {
            (
                4000.0,
                0.005 * (i as f64 - 20.0),
                60_000.0 * 0.005 * (i as f64 - 20.0),
            )
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("at least 3 loads"), "{}", stderr(&o));
    assert!(!dir.path().join("t.toml").exists());
}

#[test]
fn an_identified_tyre_file_loads_and_simulates() {
    let rows: Vec<(f64, f64, f64)> = [2000.0, 4000.0, 6000.0]
        .iter()
        .flat_map(|&fz| {
            (0..41).map(move |i| {
                let a = 0.005 * (i as f64 - 20.0);
                (fz, a, fz * (1.3 * (10.0 * a).atan()).sin())
            })
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let tyre = dir.path().join("fitted.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--seed",
        "3",
        "--out",
        tyre.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fitted.report.json"));
    assert_eq!(report["seed"], 3);
    assert!(report["sigma_percent"].as_f64().unwrap() < 1e-6, "{report}");
    for key in ["model", "curves", "parameters", "evaluations", "seconds"] {
        assert!(report.get(key).is_some(), "{key}");
    }
    assert_eq!(report["curves"].as_array().unwrap().len(), 3);
    // The fitted file is a tyre file like any other.
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"fitted.toml\"\n\n{STEP}");
    fs::write(dir.path().join("scenario.toml"), sc).unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn real_hoosier_rig_data_fits_within_a_few_percent() {
    let Some(data) = shared_data(
        "real_hoosier_rig_data_fits_within_a_few_percent",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "pac89",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.path().join("pac89.toml").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // The file's camber-0 samples sit a hair below zero (-0.00017 rad…):
    // printed as "0.00°", and the two σ of the two-stage line (2.5124 %
    // and 2.5124 %, seed 1) with the digits that tell them apart.
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_tidy_output(&stdout);
    assert!(stdout.contains("camber levels: 0.00° ("), "{stdout}");
    let report: serde_json::Value = read_json(&out.path().join("pac89.report.json"));
    let sigma = report["sigma_percent"].as_f64().unwrap();
    assert!(sigma < 3.0, "σ {sigma} %");
    assert_eq!(
        report["curves"].as_array().unwrap().len(),
        5,
        "five loads at one pressure and camber"
    );
    // The report and the terminal give the parameters, σ and curves of the
    // fit the file holds: with the two-stage result written, its own (they
    // were the direct fit's).
    let written = fs::read_to_string(out.path().join("pac89.toml")).unwrap();
    let a: Vec<f64> = text_between(&written, "\na = [", "]")
        .split(", ")
        .map(|v| v.parse().unwrap())
        .collect();
    let reported: Vec<f64> = report["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["value"].as_f64().unwrap())
        .collect();
    assert_eq!(reported, a);
    // Seed 1 writes the two-stage result (its σ a hair below the direct's).
    assert_eq!(report["written"], "two-stage");
    let t = &report["two_stage"];
    // Chosen free against the direct fit's free σ; written with what it
    // leaves undetermined held, as the direct fit would be.
    let polished = t["polished_overall_sigma_percent"].as_f64().unwrap();
    assert!(polished < t["direct_sigma_percent"].as_f64().unwrap());
    if undetermined_holds(&report).is_empty() {
        assert_eq!(sigma, polished);
    } else {
        assert!(sigma > polished, "{sigma} {polished}");
        assert!(
            stdout.contains(&format!(
                "σ {sigma:.3} % held against {polished:.3} % fitted free"
            )),
            "{stdout}"
        );
    }
    assert!(
        stdout.contains(&format!("  σ {sigma:.3} % (PSO alone")),
        "{stdout}"
    );
}

#[test]
fn identify_fits_longitudinal_only_rig_data() {
    // Fx of the Adams PAC89 example at three loads (kN inside the model):
    // D·sin(C·atan(B·x − E·(B·x − atan(B·x)))), x = 100·κ + Sh.
    let b = [
        1.67272, -9.46, 1490.0, 30.0, 176.0, 0.0886, 0.00402, -0.0615, 0.20, 0.0299, -0.176,
    ];
    let mut s = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        let z: f64 = fz / 1000.0;
        let c = b[0];
        let d = b[1] * z * z + b[2] * z;
        let bb = (b[3] * z * z + b[4] * z) * (-b[5] * z).exp() / (c * d);
        let e = b[6] * z * z + b[7] * z + b[8];
        for i in -25..=25 {
            let kappa = 0.01 * i as f64;
            let x = 100.0 * kappa + b[9] * z + b[10];
            let fx = d * (c * (bb * x - e * (bb * x - (bb * x).atan())).atan()).sin();
            s.push_str(&format!("{fz},{kappa},{fx}\n"));
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("fx.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "pac89", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fx.report.json"));
    assert_eq!(report["channel"], "longitudinal-force");
    assert!(report["sigma_percent"].as_f64().unwrap() < 0.01, "{report}");
    assert!(fs::read_to_string(&out).unwrap().contains("b = ["));
}

/// The papers' layout (columns alpha, fz, fy, mz; three loads × 85 slip
/// angles 0.2865° apart) from the Adams PAC89 tyre with 1 % noise, with
/// `fy` and `mz` multiplied by `sign_fy` and `sign_mz`.
fn papers_layout_with_signs(sign_fy: f64, sign_mz: f64) -> String {
    use handling::tyre::{Pac89, SlipState, Tyre, TyreModel};
    use rand::SeedableRng;
    let t = Tyre::Pac89(Pac89::adams_example());
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let mut s = String::from("alpha,fz,fy,mz\n");
    for fz in [2800.0, 5700.0, 8600.0] {
        for i in -42..=42 {
            let a = (0.2865 * i as f64).to_radians();
            let f = t.forces(&SlipState::lateral(a, fz));
            let mut noisy = |v: f64| v * (1.0 + 0.01 * handling::identify::data::gauss(&mut rng));
            let (fy, mz) = (noisy(f.fy), noisy(f.mz));
            s += &format!("{a},{fz},{},{}\n", sign_fy * fy, sign_mz * mz);
        }
    }
    s
}

/// The number after `prefix` in `text`.
fn number_after(text: &str, prefix: &str) -> f64 {
    let rest = &text[text
        .find(prefix)
        .unwrap_or_else(|| panic!("{prefix}: {text}"))
        + prefix.len()..];
    let end = rest.find(' ').unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

#[test]
fn rig_data_in_another_sign_convention_is_refused_naming_the_column() {
    let dir = scratch(&[
        ("iso.csv", &papers_layout_with_signs(1.0, 1.0)),
        ("sae_fy.csv", &papers_layout_with_signs(-1.0, 1.0)),
        ("sae_mz.csv", &papers_layout_with_signs(1.0, -1.0)),
    ]);
    let identify = |file: &str| {
        let out = dir.path().join(format!("{file}.toml"));
        (identify_to(&dir.path().join(file), "pac89", &out), out)
    };
    // FORMATS.md's signs: fitted.
    let (o, _) = identify("iso.csv");
    assert!(o.status.success(), "{}", stderr(&o));
    // Fy negated (SAE-style): fitted to σ ≈ 1 % before, with a negative
    // cornering stiffness; now refused before anything is fitted.
    let (o, out) = identify("sae_fy.csv");
    let e = refused(&o, &out);
    assert!(!out.with_extension("report.json").exists());
    for says in [
        "sae_fy.csv: column `fy` (column 3 of the header) has the wrong sign",
        "|alpha| ≤ 0.035 rad",
        "from 36 samples (18 with alpha > 0, 18 with alpha < 0)",
        "FORMATS.md (ISO 8855) requires a positive slope",
        "fy ≈ +C_alpha·alpha",
        "SAE or another sign convention: negate the `fy` column",
    ] {
        assert!(e.contains(says), "{says}: {e}");
    }
    // The slope found is the truth's cornering stiffness, reversed (PAC89
    // Adams example: about 0.7e5–1.5e5 N/rad over these loads).
    let slope = number_after(&e, "slope against `alpha` is ");
    assert!((-2e5..-5e4).contains(&slope), "{slope}: {e}");
    // Mz negated alone: refused naming `mz`, with both slopes.
    let (o, out) = identify("sae_mz.csv");
    let e = refused(&o, &out);
    for says in [
        "sae_mz.csv: column `mz` (column 4 of the header) has the wrong sign",
        "while that of `fy` is ",
        "`mz` to have the sign of `fy` at small slip",
        "negate the `mz` column",
    ] {
        assert!(e.contains(says), "{says}: {e}");
    }
    assert!(number_after(&e, "slope against `alpha` is ") < 0.0, "{e}");
    assert!(number_after(&e, "while that of `fy` is ") > 0.0, "{e}");
}

#[test]
fn longitudinal_rig_data_with_fx_reversed_is_refused() {
    // A slip-ratio sweep whose force opposes the slip (fx ≈ −C_kappa·kappa).
    let mut s = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in -25..=25 {
            let kappa = 0.01 * i as f64;
            let fx = -fz * (1.6 * (12.0 * kappa).atan()).sin();
            s += &format!("{fz},{kappa},{fx}\n");
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("fx.toml");
    let e = refused(
        &identify_to(&dir.path().join("rig.csv"), "pac89", &out),
        &out,
    );
    for says in [
        "rig.csv: column `fx` (column 3 of the header) has the wrong sign",
        "|kappa| ≤ 0.035",
        "slope against `kappa` is -",
        "from 18 samples (9 with kappa > 0, 9 with kappa < 0)",
        "fx ≈ +C_kappa·kappa",
        "negate the `fx` column",
    ] {
        assert!(e.contains(says), "{says}: {e}");
    }
}

/// The number printed after `prefix` on the first line holding it, up to
/// the next space.
fn printed_after<'a>(stdout: &'a str, prefix: &str) -> &'a str {
    let line = stdout
        .lines()
        .find(|l| l.contains(prefix))
        .unwrap_or_else(|| panic!("no `{prefix}` in: {stdout}"));
    text_between(line, prefix, " ")
}

#[test]
fn pac89s_two_stage_line_and_sigma_line_print_the_sigma_written() {
    let dir = scratch(&[("rig.csv", &papers_layout_with_signs(1.0, 1.0))]);
    let out = dir.path().join("pac89.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "pac89", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_tidy_output(&stdout);
    let report: serde_json::Value = read_json(&dir.path().join("pac89.report.json"));
    let t = &report["two_stage"];
    let written = format!("{:.3}", report["sigma_percent"].as_f64().unwrap());
    let two_stage = format!(
        "{:.3}",
        t["polished_overall_sigma_percent"].as_f64().unwrap()
    );
    let direct = format!("{:.3}", t["direct_sigma_percent"].as_f64().unwrap());
    // The overall σ line is the written fit's, the report's.
    assert_eq!(printed_after(&stdout, "  σ "), written, "{stdout}");
    // The two-stage line names its overall σ (the one compared) apart
    // from the paper's mean of the conditions' σ.
    assert_eq!(
        printed_after(&stdout, "σ over all points after the joint polish "),
        two_stage,
        "{stdout}"
    );
    assert!(
        stdout.contains("mean of the conditions' σ: stage 1 "),
        "{stdout}"
    );
    assert!(
        stdout.contains(&format!("(direct fit {direct} %)")),
        "{stdout}"
    );
    // And the line saying which was written gives that fit's σ.
    match report["written"].as_str().unwrap() {
        "two-stage" => {
            assert_eq!(written, two_stage);
            assert!(stdout.contains("writing the two-stage result (σ over all points "));
        }
        "direct" => {
            assert_eq!(written, direct);
            // Printed with the digits that tell the two σ apart.
            let said = printed_after(&stdout, "writing the direct fit (σ over all points ");
            let decimals = said.split('.').nth(1).map_or(0, str::len) as i32;
            let value = t["direct_sigma_percent"].as_f64().unwrap();
            assert!(
                (said.parse::<f64>().unwrap() - value).abs() <= 0.5 * 10f64.powi(-decimals),
                "{said} vs {value}"
            );
        }
        w => panic!("written {w}"),
    }
}

#[test]
fn the_staged_magic_formula_fit_refuses_pressure_and_camber_selection() {
    let dir = scratch(&[("rig.csv", &papers_layout_with_signs(1.0, 1.0))]);
    let out = dir.path().join("fit.tir");
    for (option, value) in [("--pressure", "83.4"), ("--camber", "1.6")] {
        let o = run(&[
            "identify",
            dir.path().join("rig.csv").to_str().unwrap(),
            "--model",
            "mf61",
            option,
            value,
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(
            e.contains(&format!("{option} is not taken by --model mf61"))
                && e.contains("fits every load, pressure and camber level of the file"),
            "{e}"
        );
    }
}

#[test]
fn the_curve_lines_name_a_pressure_level_as_the_level_line_does() {
    // Three loads at one pressure of 69.7 kPa: the level line and every
    // curve line print it alike (they printed "70 kPa").
    let mut s = String::from("fz,alpha,fy,pressure\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in -20..=20 {
            let a = 0.005 * f64::from(i);
            s += &format!("{fz},{a},{},69700\n", fz * (1.3 * (10.0 * a).atan()).sin());
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("gim.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("pressure levels: 69.7 kPa (123)"),
        "{stdout}"
    );
    let curves: Vec<&str> = stdout.lines().filter(|l| l.contains("    Fz ")).collect();
    assert_eq!(curves.len(), 3, "{stdout}");
    for (l, fz) in curves.iter().zip(["2000 N", "4000 N", "6000 N"]) {
        assert!(
            l.contains(&format!("Fz    {fz}, camber  0.00°, pressure 69.7 kPa:")),
            "{l}"
        );
    }
}

/// UniTire's aligning c8 = 3354.6 with a standard error of 8.9e6 was
/// worded "beyond its search bound … the data take it past the box", then
/// written past its box (0.1 to 100) as "not identified": a value the data
/// do not determine is said so, and kept within its box; one past its box
/// lies there by more than twice its standard error.
#[test]
fn a_parameter_with_a_standard_error_above_its_value_is_not_identified_past_its_box_or_not() {
    let Some(data) = hoosier(
        "a_parameter_with_a_standard_error_above_its_value_is_not_identified_past_its_box_or_not",
    ) else {
        return;
    };
    let out = tempfile::tempdir().unwrap();
    let tyre = out.path().join("uni.toml");
    let stdout = at_pressure(&data, "unitire", &tyre, &["--camber", "0"]);
    let report = read_json(&tyre.with_extension("report.json"));
    let (mut undetermined_past_box, mut past_box) = (0, 0);
    for fit in [&report, &report["aligning"]] {
        for p in fit["parameters"].as_array().unwrap() {
            let (v, (lo, hi)) = (
                p["value"].as_f64().unwrap(),
                (
                    p["bounds"][0].as_f64().unwrap(),
                    p["bounds"][1].as_f64().unwrap(),
                ),
            );
            let se = p["std_error"].as_f64();
            if !p["free"].as_bool().unwrap() {
                continue;
            }
            if let (Some(s), true) = (se, v < lo || v > hi) {
                past_box += 1;
                assert!(
                    s < v.abs() && (v - hi).max(lo - v) > 2.0 * s,
                    "past its box by less than twice its standard error: {p}"
                );
            }
            if se.is_some_and(|s| s <= v.abs()) {
                continue;
            }
            // One the fit hardly feels is said in a note, not warned of.
            let Some(w) = p["warning"].as_str() else {
                let n = p["note"].as_str().unwrap();
                let effect = p["effect_percent"].as_f64().unwrap();
                assert!(n.contains("the fit hardly shows") && effect < 1.0, "{p}");
                continue;
            };
            // A bound the polish stopped on is said first (a standard
            // error there means nothing).
            assert!(
                w.starts_with("not identified by the data: ")
                    || w.starts_with("on its search bound ("),
                "{p}"
            );
            let line = format!("warning: {} = ", p["name"].as_str().unwrap());
            let said = stdout.lines().find(|l| l.contains(&line)).unwrap();
            assert!(said.ends_with(w), "{said}");
            if v < lo || v > hi {
                undetermined_past_box += 1;
                assert!(
                    w.contains("the polish drifted past its search bound"),
                    "{w}"
                );
            }
        }
    }
    // c8 (and c5) went past their box with a standard error above the
    // value; now neither is left there.
    assert_eq!(undetermined_past_box, 0, "{stdout}");
    assert_eq!(
        stdout.matches("the data take it past the box").count(),
        past_box,
        "{stdout}"
    );
}
