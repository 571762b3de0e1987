//! A fresh-eyes tester's findings (session 111) in `identify`: rig data
//! whose `fy` and `mz` both slope the wrong way against `alpha` were told
//! to "negate the `alpha` column", which gives the mirror of the tyre
//! when `fy` and `mz` were the columns flipped (its ply steer and conicity
//! reversed); and a `.tir` written without a template carried `INFLPRES =
//! 0` (a flat tyre to MFeval and ADAMS) and `VERTICAL_STIFFNESS = 0` (a
//! division by zero for the rolling radius), `WIDTH` and `ASPECT_RATIO`
//! 0, none of them said. The rig data are MFeval's MF 6.1 sample
//! (`tests/fixtures/tir`) evaluated by `tyre-eval`: an asymmetric tyre
//! (61 N of `fy` at zero slip and camber, the mean over 4000 and 6752 N),
//! whose `fy` falls with camber (about 1 of the load per rad).

use super::*;

/// The MF 6.1 sample's `fz, alpha, camber, fy, mz` at loads 4000 and
/// 6752 N, slip angles −6° to 6° by 0.25°, each camber of `cambers`
/// (degrees), 16.7 m/s, and `pressure` (Pa) where given.
fn truth(dir: &Path, cambers: &[f64], pressure: Option<f64>) -> Vec<[f64; 5]> {
    let mut points = String::from("fz,kappa,alpha,camber,speed");
    points += if pressure.is_some() {
        ",pressure\n"
    } else {
        "\n"
    };
    for fz in [4000.0, 6752.0] {
        for &g in cambers {
            for k in -24..=24 {
                let alpha = (0.25 * f64::from(k)).to_radians();
                points += &format!("{fz},0,{alpha},{},16.7", f64::to_radians(g));
                points += &pressure.map_or("\n".into(), |p| format!(",{p}\n"));
            }
        }
    }
    let input = written(dir, "points.csv", &points);
    let out = dir.join("truth.csv");
    mf61_evaluated(&input, &out);
    let text = fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let columns = [at("fz"), at("alpha"), at("camber"), at("fy"), at("mz")];
    lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            columns.map(|i| v[i])
        })
        .collect()
}

/// A rig file `fz,alpha,fy,mz` (and `camber` last when `with_camber`) of
/// `rows`, `alpha` times `alpha_sign`, `fy` and `mz` times `force_sign`.
fn rig(rows: &[[f64; 5]], alpha_sign: f64, force_sign: f64, with_camber: bool) -> String {
    let mut s = String::from("fz,alpha,fy,mz");
    s += if with_camber { ",camber\n" } else { "\n" };
    for [fz, alpha, camber, fy, mz] in rows {
        s += &format!(
            "{fz},{},{},{}",
            alpha_sign * alpha,
            force_sign * fy,
            force_sign * mz
        );
        s += &if with_camber {
            format!(",{camber}\n")
        } else {
            "\n".into()
        };
    }
    s
}

/// `identify rig.csv --model linear --load 4000` on `text`, refused: its
/// stderr.
fn refused_rig(dir: &Path, text: &str) -> String {
    written(dir, "rig.csv", text);
    let o = run_in(
        dir,
        &[
            "identify", "rig.csv", "--model", "linear", "--load", "4000", "--out", "fit.toml",
        ],
    );
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(!dir.join("fit.toml").exists(), "{e}");
    e
}

/// The number (N) that follows `before` in `text`.
fn number_after(text: &str, before: &str) -> f64 {
    let rest = &text[text
        .find(before)
        .unwrap_or_else(|| panic!("{before}: {text}"))
        + before.len()..];
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

/// The truth's mean `fy` at zero slip and zero camber over its loads, N.
fn offset_of(rows: &[[f64; 5]]) -> f64 {
    let at_zero: Vec<f64> = rows
        .iter()
        .filter(|r| r[1] == 0.0 && r[2] == 0.0)
        .map(|r| r[3])
        .collect();
    at_zero.iter().sum::<f64>() / at_zero.len() as f64
}

/// Before: `fy` and `mz` negated (the truth's `alpha` kept) were told
/// "negate the `alpha` column", whose tyre has the truth's offset at zero
/// slip reversed. Without camber the data cannot tell a reversed `alpha`
/// from reversed `fy` and `mz`: now both are named, each with the offset
/// it gives (one of them the truth's), and the user is asked which the
/// rig flipped and how to tell. The same words for the other flip, its
/// offsets the other way round.
#[test]
fn reversed_slopes_without_camber_name_both_fixes_and_the_offset_each_gives() {
    let dir = tempfile::tempdir().unwrap();
    let rows = truth(dir.path(), &[0.0], None);
    let offset = offset_of(&rows);
    assert!(
        offset > 30.0,
        "the sample's ply steer and conicity: {offset}"
    );
    for (alpha_sign, force_sign) in [(1.0, -1.0), (-1.0, 1.0)] {
        let e = refused_rig(dir.path(), &rig(&rows, alpha_sign, force_sign, false));
        assert!(
            e.contains("rig.csv: columns `alpha`, `fy` and `mz` (columns 2, 3 and 4 of the header): near zero slip (|alpha| ≤ 0.035 rad) both forces slope the wrong way against the slip angle"),
            "{e}"
        );
        assert!(e.contains("Either `alpha` is reversed or `fy` and `mz` both are: each fixes both slopes, but they give mirror-image tyres, and these data cannot tell which"), "{e}");
        let if_alpha = number_after(&e, "`fy` at zero slip (ply steer, conicity) is ");
        let if_forces = number_after(&e, "N if `alpha` is the one reversed and ");
        assert_eq!(if_alpha, -if_forces, "{e}");
        // The fix that undoes the flip gives the truth's offset (the small-slip
        // line's intercept over both loads, within 2 of its standard errors,
        // on the truth's side); the other, its mirror.
        let se = number_after(&e, "N if `fy` and `mz` are (standard error ");
        let right = if force_sign < 0.0 {
            if_forces
        } else {
            if_alpha
        };
        assert!(
            right > 0.0 && (right - offset).abs() <= 2.0 * se,
            "{right} ± {se} vs {offset}: {e}"
        );
        assert!(e.contains("Which did the rig flip? FORMATS.md's positive slip angle has the wheel pointing to the left of its travel and pushed to the left (+y): negate `alpha` if the rig's positive slip angle points the wheel to the right of its travel; negate `fy` and `mz` if its lateral force is positive to the right (as SAE J670's y axis points). A camber sweep logged in a `camber` column decides it from the data"), "{e}");
        assert!(!e.contains("looks reversed"), "{e}");
    }
}

/// With a camber sweep logged, the camber thrust's sign decides: `fy` as
/// logged falling with camber is a tyre's (ISO 8855 inclination), so
/// `alpha` is the reversed one; rising, `fy` and `mz` are. Following the
/// advice on the file whose forces were flipped gives back the truth's
/// data, which `identify` reads.
#[test]
fn a_logged_camber_sweep_decides_which_columns_were_reversed() {
    let dir = tempfile::tempdir().unwrap();
    let rows = truth(dir.path(), &[-4.0, 0.0, 4.0], None);
    let e = refused_rig(dir.path(), &rig(&rows, 1.0, -1.0, true));
    assert!(e.contains("the camber logged decides which, if `camber` is ISO 8855's inclination: a tyre leaning with its top to the right (a positive inclination, ISO 8855) pushes to the right (−y), so `fy` falls as camber rises"), "{e}");
    let slope = number_after(
        &e,
        "`fy`/`fz`'s least-squares slope against `camber` here is ",
    );
    // The sample's −1.13 per rad at 6752 N, read through the flip.
    assert!((0.8..1.5).contains(&slope), "{slope}: {e}");
    assert!(e.contains("from 102 samples at cambers -4.0° to 4.0°): it rises, so `fy` is reversed, and `mz` with it: negate the `fy` and `mz` columns"), "{e}");
    assert!(!e.contains("cannot tell"), "{e}");
    let e = refused_rig(dir.path(), &rig(&rows, -1.0, 1.0, true));
    assert!(e.contains(": it falls, as a tyre's does, so `fy` is as FORMATS.md has it: negate the `alpha` column"), "{e}");
    // The advice followed: the file read, as the truth's is.
    written(dir.path(), "rig.csv", &rig(&rows, 1.0, 1.0, true));
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "linear", "--load", "4000", "--out", "fit.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
}

/// `identify rig.csv --model mf62 --out fit.tir` in `dir`: the terminal.
fn fitted_tir(dir: &Path, text: &str) -> String {
    written(dir, "rig.csv", text);
    let o = run_in(
        dir,
        &["identify", "rig.csv", "--model", "mf62", "--out", "fit.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A rig file `fz,alpha,camber,fy,mz` (and `pressure` at `p`) of `rows`.
fn rig_with_pressure(rows: &[[f64; 5]], p: Option<f64>) -> String {
    let mut s = String::from("fz,alpha,camber,fy,mz");
    s += if p.is_some() { ",pressure\n" } else { "\n" };
    for [fz, alpha, camber, fy, mz] in rows {
        s += &format!("{fz},{alpha},{camber},{fy},{mz}");
        s += &p.map_or("\n".into(), |p| format!(",{p}\n"));
    }
    s
}

/// `tyre-eval fit.tir` in `dir` at the points `points` (a CSV text): each
/// output row by column name.
fn evaluated_fit(dir: &Path, points: &str) -> Vec<std::collections::HashMap<String, f64>> {
    let input = written(dir, "p.csv", points);
    let out = dir.join("eval.csv");
    let fit = dir.join("fit.tir");
    let args = [fit.to_str().unwrap(), input.to_str().unwrap()];
    succeeds(&[
        "tyre-eval",
        args[0],
        args[1],
        "--out",
        out.to_str().unwrap(),
    ]);
    let text = fs::read_to_string(&out).unwrap();
    let header: Vec<String> = text
        .lines()
        .next()
        .unwrap()
        .split(',')
        .map(String::from)
        .collect();
    text.lines()
        .skip(1)
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(|x| x.parse().unwrap()))
                .collect()
        })
        .collect()
}

/// Before: a fit without a template wrote `INFLPRES = 0`,
/// `VERTICAL_STIFFNESS = 0`, `WIDTH = 0`, `ASPECT_RATIO = 0` beside
/// `NOMPRES` = the data's pressure, none of them listed as held. Now
/// `INFLPRES` is the data's pressure and the sizes are stated (20 mm of
/// deflection at FNOMIN; 0.61 of the radius wide; aspect 0.6), each
/// listed as held on the terminal and in the report with its source; no
/// constant a reader divides by is 0, and `tyre-eval` reads the file back
/// with a loaded radius of the closed form `R0 − Fz/Cz`.
#[test]
fn a_fresh_tir_states_a_physical_inflation_stiffness_and_section_each_said_held() {
    let dir = tempfile::tempdir().unwrap();
    let rows = truth(dir.path(), &[0.0], Some(240_000.0));
    let said = fitted_tir(dir.path(), &rig_with_pressure(&rows, Some(240_000.0)));
    let tir = fs::read_to_string(dir.path().join("fit.tir")).unwrap();
    let value = |k: &str| tir_value(&tir, k);
    let fnomin = value("FNOMIN");
    assert_eq!(
        (value("NOMPRES"), value("INFLPRES")),
        (240_000.0, 240_000.0)
    );
    assert_eq!(value("VERTICAL_STIFFNESS"), fnomin / 0.020);
    assert_eq!((value("WIDTH"), value("ASPECT_RATIO")), (0.183, 0.6));
    for k in [
        "FNOMIN",
        "UNLOADED_RADIUS",
        "LONGVL",
        "VXLOW",
        "NOMPRES",
        "INFLPRES",
        "VERTICAL_STIFFNESS",
        "WIDTH",
        "ASPECT_RATIO",
        "Q_RE0",
    ] {
        assert!(value(k) > 0.0, "{k}: {tir}");
    }
    assert!(said.contains("held: INFLPRES = 240000: no --template: NOMPRES's (the data's pressure, unless held): the pressure a reader evaluates a point without one at; 0 would be a flat tyre to MFeval and ADAMS"), "{said}");
    assert!(said.contains(&format!("held: VERTICAL_STIFFNESS = {}: no --template: rig forces do not measure the vertical stiffness (a loaded radius would), so FNOMIN over a stated 20 mm of deflection at FNOMIN", fnomin / 0.020)), "{said}");
    assert!(said.contains("held: WIDTH = 0.183: no --template: rig forces do not measure the section, so 0.61 times UNLOADED_RADIUS"), "{said}");
    assert!(
        said.contains(
            "held: ASPECT_RATIO = 0.6: no --template: the median of the 13 public .tir files"
        ),
        "{said}"
    );
    // The same in the file's head and the report.
    assert!(
        tir.contains("$ held: INFLPRES = 240000: no --template: NOMPRES's (the data's pressure"),
        "{tir}"
    );
    let report = read_json(&dir.path().join("fit.report.json"));
    let held = report["held"].as_array().unwrap();
    for (name, v) in [
        ("INFLPRES", 240_000.0),
        ("VERTICAL_STIFFNESS", fnomin / 0.020),
        ("WIDTH", 0.183),
        ("ASPECT_RATIO", 0.6),
    ] {
        let h = held
            .iter()
            .find(|h| h["name"] == name)
            .unwrap_or_else(|| panic!("{name}: {report}"));
        assert_eq!(h["value"].as_f64(), Some(v), "{h}");
    }
    // Read back: at FNOMIN, standing (Q_V1 = Q_V2 = 0, no force terms),
    // Fz = Cz·(R0 − rl).
    let row = &evaluated_fit(
        dir.path(),
        &format!("fz,kappa,alpha,camber,speed\n{fnomin},0,0.02,0,16.7\n"),
    )[0];
    let rl = *row.get("rl").unwrap_or_else(|| panic!("no rl: {row:?}"));
    assert!(
        (rl - (value("UNLOADED_RADIUS") - 0.020)).abs() < 1e-9,
        "{row:?}"
    );
    assert!(row["fy"].is_finite() && row["fy"] > 0.0, "{row:?}");
}

/// Without a `pressure` column `NOMPRES` was written 0, which MF 6.x
/// readers divide by: now a stated 220 kPa, `INFLPRES` the same, both
/// said held; no pressure term is fitted, so the file's forces are the
/// same at any pressure (`tyre-eval` at 150 and 300 kPa).
#[test]
fn a_fresh_tir_without_pressure_data_states_a_pressure_its_forces_do_not_depend_on() {
    let dir = tempfile::tempdir().unwrap();
    let rows = truth(dir.path(), &[0.0], None);
    let said = fitted_tir(dir.path(), &rig_with_pressure(&rows, None));
    let tir = fs::read_to_string(dir.path().join("fit.tir")).unwrap();
    assert_eq!(
        (tir_value(&tir, "NOMPRES"), tir_value(&tir, "INFLPRES")),
        (220_000.0, 220_000.0)
    );
    assert!(said.contains("held: NOMPRES = 220000, INFLPRES = 220000: no --template: no `pressure` column, so a stated 220 kPa"), "{said}");
    assert!(!said.contains("so 0 (the pressure terms off)"), "{said}");
    let rows = evaluated_fit(dir.path(), "fz,kappa,alpha,camber,speed,pressure\n5000,0,0.05,0,16.7,150000\n5000,0,0.05,0,16.7,300000\n");
    assert!(
        rows[0]["fy"] > 1000.0 && rows[0]["fy"] == rows[1]["fy"],
        "{rows:?}"
    );
}
