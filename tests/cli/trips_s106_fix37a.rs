//! A fresh-eyes tester's findings (round 37) in `identify`: a stage of
//! the data start that stopped near-singular held a template's true
//! coefficient "where the data would not put it"; `--template` given a
//! TOML tyre, a scenario or a rig file answered as a broken `.tir` (and
//! `tyre-eval` a TOML tyre saved as `.tir`); a Gim contact length of
//! 0.40 m written without a word; one note's loads in three roundings;
//! a linear window said as `|alpha| <= 2 deg` while its written ranges
//! reach 2.11°.

use super::*;

/// A saturating tyre's lateral force and aligning moment at load `fz`
/// (N) and slip angle `alpha` (rad): `fz·sin(1.4·atan(10·α))` and a trail
/// of 30 mm fading past the peak.
fn tyre(fz: f64, alpha: f64) -> (f64, f64) {
    let fy = fz * (1.4 * (10.0 * alpha).atan()).sin();
    (fy, 0.03 * fy * (-(alpha / 0.1).powi(2)).exp())
}

/// Rig rows `fz,alpha,fy,mz` at each of `loads`, alpha from −`reach` to
/// +`reach` degrees in steps of 0.05° (in rad).
fn rig(loads: &[f64], reach: f64) -> String {
    let mut s = String::from("fz,alpha,fy,mz\n");
    let steps = (reach / 0.05).round() as i32;
    for &fz in loads {
        for k in -steps..=steps {
            let alpha = (0.05 * f64::from(k)).to_radians();
            let (fy, mz) = tyre(fz, alpha);
            s += &format!("{fz},{alpha},{fy},{mz}\n");
        }
    }
    s
}

/// A TOML tyre, as the book's `tyres/linear.toml`.
const LINEAR_TOML: &str = "# Linear tyre Fy = C_alpha * alpha\nmodel = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n";

/// Before: `--template tyre.toml` said "`# Linear tyre …` is not a key",
/// a scenario or a rig file "missing key `FITTYP` in [MODEL]", as if each
/// were a broken `.tir`. Now each is named as what it is, with the
/// command that reads it, as `tyre-eval` names its tyre.
#[test]
fn a_template_that_is_a_toml_tyre_a_scenario_or_a_rig_file_is_named_as_such() {
    let dir = scratch(&[
        ("rig.csv", &rig(&[3000.0, 5000.0], 8.0)),
        ("tyre.toml", LINEAR_TOML),
        ("scenario.toml", &bundled_scenario("sedan_step.toml")),
    ]);
    for (template, kind) in [
        ("tyre.toml", "this is a tyre file (`model = \"linear\"`)"),
        ("scenario.toml", "this is a scenario"),
        ("rig.csv", "this is a tyre rig file"),
    ] {
        let o = run_in(
            dir.path(),
            &[
                "identify",
                "rig.csv",
                "--model",
                "mf61",
                "--template",
                template,
                "--out",
                "fit.tir",
            ],
        );
        assert!(!o.status.success(), "{template}");
        let said = stderr(&o);
        assert!(said.contains(kind), "{template}: {said}");
        assert!(
            said.contains("not a Magic Formula tyre property file (.tir, with [MODEL] and FITTYP), which `handling identify --template` takes"),
            "{template}: {said}"
        );
        assert!(!said.contains("FITTYP` in [MODEL]"), "{said}");
        assert!(!said.contains("is not a key"), "{said}");
        assert!(!dir.path().join("fit.tir").exists());
    }
}

/// Before: a TOML tyre saved as `lin.tir` and given to `tyre-eval` was
/// refused as "`# Linear tyre …` is not a key" at line 1. Now it is named
/// a TOML tyre, with the rename that reads it.
#[test]
fn a_toml_tyre_saved_as_tir_is_named_a_toml_tyre_with_the_rename_that_reads_it() {
    let dir = scratch(&[
        ("lin.tir", LINEAR_TOML),
        ("p.csv", "fz,kappa,alpha,camber,speed\n6000,0,0.05,0,16.7\n"),
    ]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "lin.tir", "p.csv", "--out", "f.csv"],
    );
    assert!(!o.status.success());
    let said = stderr(&o);
    assert!(
        said.contains("this is a tyre file (`model = \"linear\"`), not a Magic Formula tyre property file (.tir, with [MODEL] and FITTYP), which its .tir name promises: rename it .toml"),
        "{said}"
    );
    assert!(!said.contains("is not a key"), "{said}");
}

/// Before: `identify --model mf62 --start paper --max-iterations 20` on
/// the forces of `car205_60R19.tir` over the book's grid ([`grid_rig`]) wrote a `.tir` whose pure Fx was σ 88 % and whose Kxκ
/// turned negative from 5597 N inside its own FZMAX of 6000 N, every
/// message disowning it. Now the paper's unbounded scheme's tyre whose
/// force opposes its slip inside the loads fitted is refused, nothing
/// written, with the default start named.
#[test]
fn a_papers_start_tyre_whose_slip_stiffness_turns_negative_in_its_loads_is_not_written() {
    let test =
        "a_papers_start_tyre_whose_slip_stiffness_turns_negative_in_its_loads_is_not_written";
    let Some(tir) = shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig(&tir, dir.path());
    let out = dir.path().join("fit62.tir");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "mf62",
        "--start",
        "paper",
        "--max-iterations",
        "20",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = stderr(&o);
    assert!(
        said.contains("the paper's scheme (--start paper) took PKX1 = "),
        "{said}"
    );
    assert!(said.contains("is negative from Fz = "), "{said}");
    assert!(said.contains("no file is written"), "{said}");
    assert!(said.contains("`--start data`"), "{said}");
    assert!(!out.exists());
}

/// Before: `identify` on the noise-free forces `tyre-eval` gives of
/// `car205_60R19.tir` over the book's grid, with that file as template
/// and the default data start, stopped the Mx stage near-singular
/// (condition number 4.7e11, σ 0.002 %) and held `QSX9` at 0.0504, "the
/// end of the free fit's ±2 standard errors nearest the template's value
/// 0.6269 (which lies 25.0 standard errors from the free fit, where the
/// data would not put it)", writing `QSX2` −0.0047 where the template
/// (the data's generator) has 0.9557. Now the stage is fitted again from
/// the template's values, said, and the lower cost kept: the template's
/// coefficients, and no hold that claims the data reject them.
#[test]
fn a_stage_stopped_near_singular_is_fitted_again_from_the_templates_values() {
    let test = "a_stage_stopped_near_singular_is_fitted_again_from_the_templates_values";
    let Some(tir) = shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig(&tir, dir.path());
    let out = dir.path().join("fit.tir");
    let said = succeeds(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "mf61",
        "--template",
        tir.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!said.contains("where the data would not put it"), "{said}");
    assert!(
        said.contains("a second start: the fit from the data's estimates ended near-singular"),
        "{said}"
    );
    assert!(
        said.contains("fitted again from the template's values"),
        "{said}"
    );
    let report = read_json(&out.with_extension("report.json"));
    let mx = report["stages"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["stage"] == "mx")
        .unwrap_or_else(|| panic!("{report}"));
    assert!(mx["sigma_percent"].as_f64().unwrap() < 1e-6, "{mx}");
    let text = fs::read_to_string(&out).unwrap();
    let value = |key: &str| -> f64 {
        text.lines()
            .find_map(|l| {
                let (k, v) = l.split_once('=')?;
                (k.trim() == key).then(|| v.split('$').next().unwrap().trim().parse().unwrap())
            })
            .unwrap_or_else(|| panic!("{key}: {text}"))
    };
    // The generator's values (car205_60R19.tir).
    for (key, truth) in [("QSX2", 0.9557), ("QSX9", 0.6269), ("QSX6", 20.0)] {
        let v = value(key);
        assert!(
            (v - truth).abs() < 1e-3 * truth.abs(),
            "{key} = {v}, not {truth}"
        );
    }
}

/// The Hoosier file's cornering data at 83.4 kPa and 0°, fitted with
/// `--model gim` in a tempdir: its terminal and its report (`None`: the
/// data are absent outside CI).
fn hoosier_gim(test: &str) -> Option<(String, serde_json::Value)> {
    let data = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("hgim.toml");
    let said = succeeds(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "gim",
        "--pressure",
        "83400",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    Some((said, read_json(&out.with_extension("report.json"))))
}

/// Before: the Hoosier FSAE tyre's Gim fit wrote `contact_length =
/// 0.4011` (σ 41.1 % on the aligning moment) with no word on its size,
/// while the tool's own refusal text gives a car tyre 0.1–0.25 m. Now a
/// warning says no tyre's patch is that long and what it means, on the
/// terminal and in the report's notes.
#[test]
fn a_gim_contact_length_longer_than_any_tyres_is_warned_of() {
    let test = "a_gim_contact_length_longer_than_any_tyres_is_warned_of";
    let Some((said, report)) = hoosier_gim(test) else {
        return;
    };
    let warning = "contact_length = 0.4011 m is longer than any tyre's contact patch (0.03–0.3 m";
    assert!(said.contains(&format!("warning: {warning}")), "{said}");
    assert!(
        said.contains("the aligning moment data are not a gim tyre's shape"),
        "{said}"
    );
    let notes = report["notes"].as_array().unwrap();
    assert!(
        notes
            .iter()
            .any(|n| n["warning"] == true && n["text"].as_str().unwrap().starts_with(warning)),
        "{notes:?}"
    );
}

/// Before: one note said the conditions' own loads as `524 N`, `1082 N`,
/// `1639.7 N`, `2194.3 N`, `2736.55 N` (the report's digits, three
/// roundings), as the figure's key did; then each to 0.1 N, beside level
/// names in whole newtons (`1082.0 N in the 1095 N level`, round 38). Now
/// each as its level is named, in whole newtons.
#[test]
fn a_notes_loads_are_said_to_one_rounding() {
    let test = "a_notes_loads_are_said_to_one_rounding";
    let Some((said, _)) = hoosier_gim(test) else {
        return;
    };
    let note = said
        .lines()
        .find(|l| l.contains("inside the level the lines above name"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(note.contains("524 N in the 534 N level"), "{note}");
    assert!(note.contains("1640 N in the 1656 N level"), "{note}");
    assert!(!note.contains("2736.55"), "{note}");
    // The own load before each ` N in the `, and the level's name after.
    let pieces: Vec<&str> = note.split(" N in the ").collect();
    assert!(pieces.len() >= 6, "{note}");
    for (i, p) in pieces.iter().enumerate() {
        let own = p.rsplit(' ').next().unwrap();
        let level = p.split(' ').next().unwrap();
        if i + 1 < pieces.len() {
            assert!(own.parse::<u32>().is_ok(), "{own}: {note}");
        }
        if i > 0 {
            assert!(level.parse::<u32>().is_ok(), "{level}: {note}");
        }
    }
}

/// Before: a linear fit said `linear window: fitted to |alpha| <= 2 deg
/// only` while its `[fitted_ranges]` alpha reached 2.11° (the Hoosier
/// file): a slip-angle bin is in the window by its centre, and its
/// samples spread about it. Now the line says how far the samples fitted
/// reach, as the ranges written do.
#[test]
fn a_linear_window_says_how_far_its_bins_samples_reach() {
    let dir = scratch(&[("rig.csv", &rig(&[4000.0], 8.0))]);
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "linear", "--out", "fit.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    let text = fs::read_to_string(dir.path().join("fit.toml")).unwrap();
    let alpha = text
        .lines()
        .find(|l| l.starts_with("alpha = ["))
        .unwrap_or_else(|| panic!("{text}"));
    let hi: f64 = alpha
        .trim_start_matches("alpha = [")
        .trim_end_matches(']')
        .split(',')
        .map(|v| v.trim().parse::<f64>().unwrap().abs())
        .fold(0.0, f64::max);
    assert!(hi.to_degrees() > 2.05, "{alpha}");
    let reach = format!(
        "a slip-angle bin is in the window by its centre, and the samples of those fitted reach |alpha| = {:.2} deg, the [fitted_ranges] written",
        hi.to_degrees()
    );
    let line = said
        .lines()
        .find(|l| l.contains("linear window: fitted to |alpha| <= 2 deg only"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(line.contains(&reach), "{line}");
    assert!(text.contains(&reach), "{text}");
}
