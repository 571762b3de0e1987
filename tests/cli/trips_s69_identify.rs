//! What a user still tripped on in `identify`: a parameter held as
//! undetermined at a stated value the data reject (UniTire's aligning c9
//! at its start value 0.3, 270 standard errors from the free fit), then
//! said but still held there; a later
//! channel's held lines printed in the lateral force's block, with the
//! block's name repeated in its note; a two-stage line whose stage 2
//! percentage said nothing of what it is; a rig file in degrees refused
//! once per cell; `--seed -1` taken for a flag. The fits run on one
//! pressure and camber of the Hoosier file (395 points) or a part of it.

use super::*;

/// The Hoosier file, or `None` (skipped) where the shared data are absent.
pub(crate) fn hoosier(test: &str) -> Option<PathBuf> {
    shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")
}

/// `identify rig --model model` at the Hoosier file's 83.4 kPa and 0°
/// level, written to `out`: the terminal.
fn one_level(rig: &Path, model: &str, out: &Path) -> String {
    at_pressure(rig, model, out, &["--camber", "0"])
}

/// `identify rig --model model --pressure 83400` with `extra` arguments,
/// written to `out`: the terminal.
/// Several tests fit the same level alike: the run is made once
/// ([`shared_runs::identified`]) and its files copied to `out`.
pub(crate) fn at_pressure(rig: &Path, model: &str, out: &Path, extra: &[&str]) -> String {
    let mut args = vec!["--model", model, "--pressure", "83400"];
    args.extend_from_slice(extra);
    shared_runs::identified(rig, &args, out)
}

/// The held lines of `text` whose value is not the stated one but the
/// nearest the data allow, each with its parameter's name; every one
/// names the option that holds a value of the user's own.
fn moved(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| l.contains("the end of the free fit's ±2 standard errors nearest"))
        .map(|l| {
            let name = l
                .split("held: ")
                .nth(1)
                .unwrap()
                .split(" = ")
                .next()
                .unwrap();
            assert!(l.contains(&format!("--hold {name}=VALUE")), "{l}");
            name.to_string()
        })
        .collect()
}

/// The most UniTire's aligning σ may rise by its holds on the Hoosier
/// file's 83.4 kPa, 0° level, in points of %: measured +0.066 (9.667 →
/// 9.733 %, c3, c4, c6, c10 held at their start values; c9's hold at the
/// end of its ±2 standard errors nearest its start value 0.3 refused by
/// the guard, which had held it at 0.3 for 25.073 %).
const UNITIRE_ALIGNING_RISE: f64 = 0.2;

/// UniTire's aligning c9, stated 0.3 where the free fit gave 0.0002 ±
/// 0.0011, is no longer held where the data reject it: no held value lies
/// more than two standard errors from the free fit, each held line (on the
/// terminal and in the file's header) says the value held and the start
/// value, the report keeps both, and the aligning σ barely rises; the
/// aligning moment's held lines sit in its block, after its σ line, and
/// its note names the parameters without the block's prefix.
#[test]
fn a_held_value_is_one_the_data_allow_and_said_with_the_aligning_block() {
    let Some(rig) = hoosier("a_held_value_is_one_the_data_allow_and_said_with_the_aligning_block")
    else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("u.toml");
    let text = one_level(&rig, "unitire", &out);
    let file = fs::read_to_string(&out).unwrap();
    assert_eq!(moved(&file), moved(&text), "{file}");
    let report = read_json(&out.with_extension("report.json"));
    let held = undetermined_holds(&report);
    assert!(!held.is_empty(), "{text}");
    for h in &held {
        let (name, value) = (h["name"].as_str().unwrap(), h["value"].as_f64().unwrap());
        let (fitted, stated) = (h["fitted"].as_f64().unwrap(), h["stated"].as_f64().unwrap());
        assert_eq!(h["held_at"].as_f64(), Some(value), "{h}");
        if let Some(se) = h["std_error"].as_f64() {
            assert!((value - fitted).abs() <= 2.0 * se * (1.0 + 1e-9), "{h}");
        }
        for said in [&text, &file] {
            let line = said
                .lines()
                .find(|l| l.contains(&format!("held: {name} = ")))
                .unwrap_or_else(|| panic!("no held line of {name}: {said}"));
            assert!(
                line.contains(&format!("held at the model's start value {stated}"))
                    || (line.contains(&format!("nearest the model's start value {stated} "))
                        && moved(line) == [name]),
                "{line}"
            );
        }
    }
    let aligning = &report["aligning"];
    let (sigma, free) = (
        aligning["sigma_percent"].as_f64().unwrap(),
        aligning["free_sigma_percent"].as_f64().unwrap(),
    );
    assert!(
        sigma < free + UNITIRE_ALIGNING_RISE,
        "{sigma} against {free}"
    );
    // The aligning block: its σ line, then its held lines and note.
    let at = |needle: &str| {
        text.find(needle)
            .unwrap_or_else(|| panic!("no {needle:?} in {text}"))
    };
    let sigma = at("  aligning moment: σ ");
    assert!(at("  held: aligning.c") > sigma, "{text}");
    assert!(
        at("  σ ") < sigma && !text[..sigma].contains("held: aligning."),
        "{text}"
    );
    let note = text
        .lines()
        .find(|l| l.contains("held at the model's start values") && l.contains("as the data"))
        .unwrap();
    assert!(
        note.starts_with("  aligning moment: c") && !note.contains("aligning.c"),
        "{note}"
    );
}

/// PAC89's two-stage line says what stage 2 is and what its percentage
/// is of; the aligning moment's held lines (camber terms, c9) follow its
/// σ line, not the lateral force's held lines.
#[test]
fn pac89s_two_stage_line_says_what_stage_2_is_and_held_lines_sit_with_their_channel() {
    let Some(rig) =
        hoosier("pac89s_two_stage_line_says_what_stage_2_is_and_held_lines_sit_with_their_channel")
    else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let text = one_level(&rig, "pac89", &dir.path().join("p.toml"));
    let two = text
        .lines()
        .find(|l| l.contains("two-stage (Zhang"))
        .unwrap();
    for said in [
        "% (each condition's own curve, B, C, D, E, Sh, Sv fitted to it alone), stage 2 ",
        "% (a0..a13 fitted to those coefficients as laws of load and camber), after the joint polish ",
        "% (a0..a13 on all points together); σ over all points",
        "; a condition's σ is its RMS error as % of its RMS measured force, the mean over the 5 conditions",
    ] {
        assert!(two.contains(said), "no {said:?} in {two}");
    }
    let lines: Vec<&str> = text.lines().collect();
    let sigma = lines
        .iter()
        .position(|l| l.starts_with("  aligning moment: σ "))
        .unwrap();
    for (i, l) in lines.iter().enumerate() {
        let aligning = l.starts_with("  held: c");
        let lateral = l.starts_with("  held: a");
        assert!(
            !aligning || i > sigma,
            "{l} before the aligning block: {text}"
        );
        assert!(!lateral || i < sigma, "{l} in the aligning block: {text}");
    }
    assert!(
        lines[sigma..]
            .iter()
            .any(|l| l.starts_with("  held: c9 = ")),
        "{text}"
    );
}

/// The staged Magic Formula fit alike: a coefficient the data do not
/// determine, its template value far from the free fit, is held where the
/// data allow, and its line says the value held and the template's, on
/// the terminal, in the `.tir`'s header and in the report.
#[test]
fn a_staged_fit_says_the_value_held_and_the_template_value() {
    let Some(rig) = hoosier("a_staged_fit_says_the_value_held_and_the_template_value") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    // The lateral force at 83.4 kPa and 0° camber (no mz: one stage).
    let text = fs::read_to_string(rig).unwrap();
    let mut part = String::from("t,fz,alpha,camber,fy,pressure,speed\n");
    for l in text.lines().skip(1) {
        let c: Vec<&str> = l.split(',').collect();
        let (camber, pressure): (f64, f64) = (c[3].parse().unwrap(), c[6].parse().unwrap());
        if camber.abs() < 0.01 && (80e3..87e3).contains(&pressure) {
            part += &[c[0], c[1], c[2], c[3], c[4], c[6], c[7]].join(",");
            part.push('\n');
        }
    }
    let data = dir.path().join("fy.csv");
    fs::write(&data, part).unwrap();
    let template =
        fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
            .unwrap()
            .lines()
            .map(|l| match l.split_whitespace().next() {
                Some("PKY1") => "PKY1 = -8000".to_string(),
                Some("PKY4") => "PKY4 = 12".to_string(),
                Some("PVY1") => "PVY1 = 0.1".to_string(),
                _ => l.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
    let tir = dir.path().join("t.tir");
    fs::write(&tir, template + "\n").unwrap();
    let out = dir.path().join("m.tir");
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "mf61",
        "--template",
        tir.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let held: Vec<&str> = text
        .lines()
        // A coefficient whose hold the guard refused (its hold raised σ
        // past what the data allow) stays free with its warning: only
        // the held ones say a value held.
        .filter(|l| l.contains("held: ") && l.contains("not identifiable from these data"))
        .collect();
    // PKY1 far off the template's -8000 (-264.9 ± 15640): holding it at
    // the template's value, or 2 standard errors towards it, raised σ past
    // the guard, so it stays free with its warning (it was held, and σ
    // paid for it, before the staged fit guarded its holds): refused
    // within its linearised ±2, the data fix it beyond that
    // linearisation (session 114).
    assert!(
        text.lines().any(|l| l.contains("warning: PKY1 = ")
            && l.contains("fixed by the data more tightly than its standard error says")),
        "{text}"
    );
    assert!(!held.iter().any(|l| l.contains("PKY1 =")), "{text}");
    for l in &held {
        assert!(
            l.contains("held at the template's value ")
                || l.contains("standard errors nearest the template's value "),
            "{l}"
        );
    }
    assert_eq!(moved(&fs::read_to_string(&out).unwrap()), moved(&text));
    let report = fs::read_to_string(out.with_extension("report.json")).unwrap();
    if !held.is_empty() {
        for key in ["\"standard_errors_away\"", "\"stated\"", "\"held_at\""] {
            assert!(report.contains(key), "{report}");
        }
    }
}

/// A rig file whose slip angles are in degrees is refused in one line
/// per rule, at its first place with the count, and the total kept: it
/// listed 20 lines alike and "and … more".
#[test]
fn a_rig_file_in_degrees_is_refused_once_per_rule_with_a_count() {
    let Some(rig) = hoosier("a_rig_file_in_degrees_is_refused_once_per_rule_with_a_count") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let text = fs::read_to_string(rig).unwrap();
    let mut lines = text.lines();
    let mut degrees = format!("{}\n", lines.next().unwrap());
    let mut beyond = 0;
    for l in lines {
        let mut c: Vec<String> = l.split(',').map(str::to_string).collect();
        let alpha = c[2].parse::<f64>().unwrap() * 57.2958;
        beyond += usize::from(alpha.abs() > std::f64::consts::FRAC_PI_2);
        c[2] = format!("{alpha:.6}");
        degrees += &(c.join(",") + "\n");
    }
    let data = dir.path().join("deg.csv");
    fs::write(&data, degrees).unwrap();
    let out = dir.path().join("d.tir");
    let e = refused(&identify_to(&data, "mf61", &out), &out);
    assert!(
        e.contains(&format!("deg.csv: {beyond} places refused, in file order:")),
        "{e}"
    );
    let said: Vec<&str> = e.lines().filter(|l| l.contains("column `alpha`")).collect();
    assert_eq!(said.len(), 1, "{e}");
    assert!(
        said[0].contains("deg.csv:")
            && said[0].contains(" rad is beyond ±90°")
            && said[0].ends_with(&format!("(the first of {beyond} places refused alike)")),
        "{e}"
    );
    assert!(!without_temp_names(&e).contains("more"), "{e}");
}

/// `--seed -1` was clap's "unexpected argument '-1'": now the flag, the
/// value and what a seed is, in the words a campaign's `seed = -1` gets.
#[test]
fn a_negative_seed_is_refused_as_a_seed() {
    for bad in ["-1", "1.5"] {
        let o = run(&["identify", "rig.csv", "--model", "gim", "--seed", bad]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{e}");
        assert!(
            e.contains(&format!("invalid value '{bad}' for '--seed <SEED>'"))
                && e.contains("expected a whole number of 0 or more"),
            "{e}"
        );
        assert!(!e.contains("unexpected argument"), "{e}");
    }
}
