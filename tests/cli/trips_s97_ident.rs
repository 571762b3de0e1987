//! Findings on `identify` and `tyre-eval` (round 26C's leftovers, session
//! 97): a template's longitudinal block kept over a widened load range
//! without a word, load/camber/pressure ranges warned of for inputs the
//! model does not read, `PKY1 = 0` read where −0.5 is refused, `LMUY`
//! blamed on `PDY1`/`PKY1` or read negative, rig rows at rest set aside
//! for the staged Magic Formula only, and `simulate`'s one-level ranges.

use super::*;
use std::fs;

/// The fixture MF 6.1 `.tir` with `key`'s value replaced by `value` (the
/// line and the value's column kept).
fn mf61_with(key: &str, value: &str) -> String {
    let text = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    text.lines()
        .map(|l| match l.split_whitespace().next() == Some(key) {
            true => {
                let eq = l.find('=').unwrap();
                let rest = l[eq + 1..].trim_start();
                let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
                format!("{} {value} {}\n", &l[..=eq], &rest[end..])
            }
            false => format!("{l}\n"),
        })
        .collect()
}

/// `tyre-eval tyre points --out out` in `dir`.
fn eval_in(dir: &Path, tyre: &str, points: &str, out: &str, extra: &[&str]) -> Output {
    let mut args = vec!["tyre-eval", tyre, points, "--out", out];
    args.extend_from_slice(extra);
    run_in(dir, &args)
}

/// A rig file of a tyre `fy = Fz·sin(1.3·atan(12α))` at 2, 4 and 6 kN,
/// slip angles ±0.2 rad in 0.005 steps (243 rows); every
/// `rest_every`-th row (0: none) at speed 0, or left out (`drop_rest`).
fn rig(rest_every: usize, drop_rest: bool) -> String {
    let mut s = String::from("fz,alpha,camber,speed,fy\n");
    let mut n = 0;
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in -40..=40 {
            let alpha = 0.005 * f64::from(i);
            let fy = fz * (1.3 * (12.0f64 * alpha).atan()).sin();
            n += 1;
            let at_rest = rest_every > 0 && n % rest_every == 0;
            match (at_rest, drop_rest) {
                (true, true) => {}
                (true, false) => s.push_str(&format!("{fz},{alpha},0,0,{fy}\n")),
                _ => s.push_str(&format!("{fz},{alpha},0,16.7,{fy}\n")),
            }
        }
    }
    s
}

/// The line of `text` starting with `key` (a tyre file's value line).
fn value_line<'a>(text: &'a str, key: &str) -> &'a str {
    text.lines()
        .find(|l| l.split_whitespace().next() == Some(key))
        .unwrap_or_else(|| panic!("no {key}: {text}"))
}

/// Item 1: the Hoosier file fitted on `FSAE_Defaults.tir` keeps its
/// longitudinal block (`PKX1 = 50`, `PKX2 = −80`) and widens FZMAX from
/// 2000 to the data's 2928.5 N; `tyre-eval` of the written file warned
/// that its slip stiffness turns negative from 1625 N and that its
/// |Fx|/Fz peaks at 2.56, and `identify` said neither. Now `identify`
/// says both, with the written file's name and lines, in the words
/// `tyre-eval` gives them, and writes them in the file's header.
#[test]
fn a_template_block_turning_against_its_slip_over_the_written_range_is_said_by_identify() {
    let test =
        "a_template_block_turning_against_its_slip_over_the_written_range_is_said_by_identify";
    let (Some(rig), Some(tir)) = (
        trips_s69_identify::hoosier(test),
        shared_data(test, "tir_public/FSAE_Defaults.tir"),
    ) else {
        return;
    };
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n2500,0.05,0,0,11\n")]);
    // What is said is the template's longitudinal block (no stage fits it:
    // the file has no fx) over the data's loads (FZMIN 405.3, FZMAX 2928.5
    // N), not the lateral fit: 10 iterations per step give the same words
    // as the default in a twentieth of its time.
    let o = run_in(
        dir.path(),
        &[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            "mf61",
            "--template",
            tir.to_str().unwrap(),
            "--max-iterations",
            "10",
            "--out",
            "hm.tir",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    let turn = said
        .lines()
        .find(|l| l.contains("the longitudinal slip stiffness Kxκ"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        turn.contains("turns negative from Fz = 1625 N, and the file's FZMAX = 2928 N"),
        "{turn}"
    );
    assert!(
        said.contains(
            "warning: the file's pure longitudinal force peaks at |Fx|/Fz = 2.56 at Fz = 405.3 N"
        ),
        "{said}"
    );
    // The same words as tyre-eval's of the file written, its lines too.
    let e = eval_in(dir.path(), "hm.tir", "p.csv", "out.csv", &[]);
    assert!(e.status.success(), "{}", stderr(&e));
    let turn = turn.trim_start().trim_start_matches("warning: ");
    assert!(turn.starts_with("hm.tir:"), "{turn}");
    assert!(stderr(&e).contains(turn), "{turn}\n{}", stderr(&e));
    // Its PKX1 line is the one named.
    let text = fs::read_to_string(dir.path().join("hm.tir")).unwrap();
    let line: usize = turn["hm.tir:".len()..]
        .split(':')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let pkx1 = text.lines().nth(line - 1).unwrap();
    assert!(pkx1.starts_with("PKX1"), "{pkx1}");
    assert!(text.contains(&format!("$ warning: {turn}")), "header");
    // The fx the check warns of: against its slip at 2500 N.
    let (head, rows) = numeric_csv(&dir.path().join("out.csv"));
    assert!(rows[0][column(&head, "fx")] < -2.0 * 2500.0, "{rows:?}");
}

/// Item 2: a linear tyre's `Cα·α` has no load term, camber or pressure:
/// `tyre-eval` at 4000 N past rig data at 1503–1795 N warned "755 % of
/// the range's span", `simulate` listed camber and pressure ranges. Now
/// neither says an input's range as the rig data's; the slip angle, which
/// it reads, is still said (`tyre-eval` says the loads the cornering
/// stiffness was fitted at, as what the tyre holds unchanged away from
/// them: trips_s104_camber34).
#[test]
fn a_range_of_an_input_the_model_does_not_read_is_said_by_neither_tyre_eval_nor_simulate() {
    let tyre = "model = \"linear\"\ncornering_stiffness = 33415.56\npneumatic_trail = 0.02848\n\n[fitted_ranges]\nfz = [1503.0, 1795.0]\nalpha = [-0.034865, 0.034699]\ncamber = [-0.00032, 0.00032]\npressure = [82160.0, 84280.0]\n";
    let points =
        "fz,kappa,alpha,camber,speed\n1650,0,0.02,0,11\n4000,0,0.02,0,11\n1650,0,0.3,0,11\n";
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 20.0\nsteer = 0.06\n");
    let dir = scratch(&[("tyre.toml", tyre), ("p.csv", points), ("s.toml", &sc)]);
    let o = eval_in(dir.path(), "tyre.toml", "p.csv", "out.csv", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(!e.contains("rig data's fz"), "{e}");
    assert!(
        e.contains("1 of 3 points above the rig data's alpha"),
        "{e}"
    );
    // The linear tyre's fy at 4000 N is its fy at 1650 N.
    let (head, rows) = numeric_csv(&dir.path().join("out.csv"));
    let fy = column(&head, "fy");
    assert_eq!(rows[0][fy], rows[1][fy]);
    let s = run_in(dir.path(), &["simulate", "s.toml", "--out", "sim"]);
    assert!(s.status.success(), "{}", stderr(&s));
    let said = format!("{}{}", String::from_utf8_lossy(&s.stdout), stderr(&s));
    let line = said
        .lines()
        .find(|l| l.contains("take the front tyres outside the ranges of the rig data"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(line.contains("(alpha -0.03487 to 0.03470 rad; "), "{line}");
    assert!(
        !without_temp_names(line).contains("camber")
            || line.contains("at zero slip ratio and camber"),
        "{line}"
    );
    assert!(!line.contains("pressure"), "{line}");
}

/// Item 8: `simulate` said a camber of 0 past rig data at one camber
/// level (1.6°, the rig's spread 0.0276–0.0283 rad) without its distance;
/// now it is said by its distance from that level, by tyre-eval's rule
/// (a sweep by its share of the span).
#[test]
fn simulate_says_a_one_level_range_by_its_distance() {
    let pac = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    let tyre = format!("{pac}\n[fitted_ranges]\nfz = [2000.0, 6000.0]\nalpha = [-0.2, 0.2]\ncamber = [0.0276, 0.0283]\n");
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n{STEP}");
    let dir = scratch(&[("tyre.toml", &tyre), ("s.toml", &sc)]);
    let s = run_in(dir.path(), &["simulate", "s.toml", "--out", "sim"]);
    assert!(s.status.success(), "{}", stderr(&s));
    let said = format!("{}{}", String::from_utf8_lossy(&s.stdout), stderr(&s));
    let line = said
        .lines()
        .find(|l| l.contains("take the front tyres outside"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        line.contains("a camber of 0 rad (0.02760 rad past the range's end, one level of the data at 0.02795 rad)"),
        "{line}"
    );
    assert!(!line.contains('%'), "{line}");
}

/// Item 3: a `.tir` with `PKY1 = 0` (and a lateral peak) was read, one
/// with `PKY1 = -0.5` refused as a stiffness below any tyre's: both are
/// refused, at the file's line, with the value; `--hold PKY1=0` says
/// that the file it writes is refused by tyre-eval and simulate.
#[test]
fn pky1_of_zero_is_refused_as_a_stiffness_below_any_tyres() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    for v in ["0", "-0.5"] {
        let dir = scratch(&[("e.tir", &mf61_with("PKY1", v)), ("p.csv", points)]);
        let o = eval_in(dir.path(), "e.tir", "p.csv", "out.csv", &[]);
        assert!(!o.status.success(), "PKY1 = {v}");
        let e = stderr(&o);
        assert!(e.contains("e.tir:206:"), "{e}");
        assert!(
            e.contains(&format!("`PKY1`: {v} gives the tyre a cornering stiffness")),
            "{e}"
        );
        assert!(e.contains("below any tyre's 1.5"), "{e}");
        assert!(!dir.path().join("out.csv").exists());
    }
    let dir = scratch(&[("rig.csv", &rig(0, false)), ("p.csv", points)]);
    let o = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "mf61", "--hold", "PKY1=0", "--out", "out.tir",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        said.contains("warning: the held `PKY1` = 0: ")
            && said.contains("the file is written as fitted, but tyre-eval and simulate refuse it"),
        "{said}"
    );
    let e = eval_in(dir.path(), "out.tir", "p.csv", "out.csv", &[]);
    assert!(!e.status.success() && stderr(&e).contains("`PKY1`: 0 gives"));
}

/// Item 5: `LMUY = 0` was blamed on `PDY1` and `PKY1` ("as `identify`
/// writes a lateral block it had no data to fit"); `LMUY = -1` was read
/// silently (its fy of the other sign) and `--hold LMUY=-1` accepted,
/// where `LFZO = -1` is refused; the warning of a force against its slip
/// left out the point's slip ratio.
#[test]
fn lmuy_is_named_for_its_own_zero_and_refused_negative() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    let dir = scratch(&[
        ("zero.tir", &mf61_with("LMUY", "0")),
        ("neg.tir", &mf61_with("LMUY", "-1")),
        ("e.tir", &mf61_with("PEY1", "3")),
        ("p.csv", points),
        (
            "k.csv",
            "fz,kappa,alpha,camber,speed\n4000,0.02,0.15,0,16\n",
        ),
        ("rig.csv", &rig(0, false)),
    ]);
    let o = eval_in(dir.path(), "zero.tir", "p.csv", "z.csv", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("the tyre has no lateral force (LMUY = 0: the file's scale factor switches its lateral force off)"),
        "{e}"
    );
    assert!(!e.contains("PDY1 = "), "{e}");
    let o = eval_in(dir.path(), "neg.tir", "p.csv", "n.csv", &[]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("neg.tir:133:"), "{}", stderr(&o));
    assert!(stderr(&o).contains("`LMUY`: -1"), "{}", stderr(&o));
    let h = run_in(
        dir.path(),
        &[
            "identify", "rig.csv", "--model", "mf61", "--hold", "LMUY=-1", "--out", "h.tir",
        ],
    );
    assert!(!h.status.success() && !dir.path().join("h.tir").exists());
    assert!(
        without_temp_names(&stderr(&h)).contains("LMUY"),
        "{}",
        stderr(&h)
    );
    let o = eval_in(
        dir.path(),
        "e.tir",
        "k.csv",
        "k_out.csv",
        &["--mode", "221"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("the first at line 2: fz = 4000 N, alpha = 0.1500 rad (8.594°), kappa = 0.02000, camber = 0 rad"),
        "{}",
        stderr(&o)
    );
}

/// Item 6: rig rows at rest were set aside for mf61/mf62 only; a swarm
/// model fitted them. Now every model sets them aside, counts and says
/// them, and its fit is the fit of the file without them.
#[test]
fn rig_rows_at_rest_are_set_aside_for_every_model() {
    let dir = scratch(&[
        ("rest.csv", &rig(10, false)),
        ("moving.csv", &rig(10, true)),
    ]);
    for model in ["linear", "gim"] {
        let fitted = |data: &str, out: &str| {
            let o = run_in(
                dir.path(),
                &["identify", data, "--model", model, "--out", out],
            );
            assert!(o.status.success(), "{model}: {}", stderr(&o));
            let said = String::from_utf8_lossy(&o.stdout).into_owned();
            (said, fs::read_to_string(dir.path().join(out)).unwrap())
        };
        let (said, rest) = fitted("rest.csv", &format!("{model}_rest.toml"));
        assert!(
            said.contains("24 samples of 243 at rest (speed below 0.0001 m/s; the first at fz = 2000 N, alpha = -0.1550 rad), 24 at a slip angle or slip ratio ≠ 0, set aside, not fitted"),
            "{model}: {said}"
        );
        assert!(!said.contains("Magic Formula"), "{model}: {said}");
        let (_, moving) = fitted("moving.csv", &format!("{model}_moving.toml"));
        assert_eq!(
            value_line(&rest, "cornering_stiffness"),
            value_line(&moving, "cornering_stiffness"),
            "{model}"
        );
    }
}

/// Item 4: UniTire's aligning `c9` on the Hoosier file at 83.4 kPa and 0°
/// was tried at 0.0708 (its ±2 standard errors' edge while others were
/// free, 63 standard errors off once they were held), refused by the
/// guard and never tried again. A refused hold is tried again where its
/// ±2 edge has moved: `c9` is held at 0.00244, the edge nearest its start
/// value, as the book's rule says.
#[test]
fn a_refused_swarm_hold_is_tried_again_at_its_new_two_standard_error_edge() {
    let test = "a_refused_swarm_hold_is_tried_again_at_its_new_two_standard_error_edge";
    let Some(rig) = trips_s69_identify::hoosier(test) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("uni.toml");
    let said =
        // The default seed, 1: the fit trips_s69_identify's and
        // trips_s95_ident's tests read.
        trips_s69_identify::at_pressure(&rig, "unitire", &out, &["--camber", "0"]);
    let c9 = said
        .lines()
        .find(|l| l.contains("aligning.c9 = "))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        c9.contains("held: aligning.c9 = 0.00244: not determined by these data: fitted free it was 0.0002232 ± 0.00111")
            && c9.contains("held at 0.00244, the end of the free fit's ±2 standard errors nearest the model's start value 0.3"),
        "{c9}"
    );
    assert!(!said.contains("0.07080"), "{said}");
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains("# held: aligning.c9 = 0.00244"), "{text}");
}
