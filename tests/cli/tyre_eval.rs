//! What `tyre-eval` cannot stand behind, said at the points it concerns: a
//! tyre without a longitudinal force evaluated at a slip ratio, or without
//! an overturning or rolling resistance moment, a Magic Formula `my` past
//! the speed its speed terms reach, a load its vertical model carries at
//! no loaded radius, a TOML tyre off the road, the loads a slip
//! stiffness's sign change is named within, a negative speed and a
//! pressure row in kPa; a model that does not couple fx and fy and a
//! resultant beyond friction, a Magic Formula mz at zero speed, and a
//! PAC89 or UniTire stiffness in another unit.

use super::*;
use crate::trips_identify::{identify_with, rig, stdout};

/// The MF 6.1 sample file of the fixtures, with `edits` (key, value) made.
pub(crate) fn mf61(dir: &Path, edits: &[(&str, &str)]) -> PathBuf {
    let text = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let mut out = String::new();
    for line in text.lines() {
        let key = line.split_whitespace().next().unwrap_or("");
        match edits.iter().find(|(k, _)| *k == key) {
            Some((k, v)) => out += &format!("{k} = {v}\n"),
            None => out += &format!("{line}\n"),
        }
    }
    let path = dir.join("tyre.tir");
    fs::write(&path, out).unwrap();
    path
}

/// `tyre-eval` of `tyre` at the points `csv` (written to `dir`), with
/// `args`: the output, and the CSV written.
pub(crate) fn eval(dir: &Path, tyre: &Path, csv: &str, args: &[&str]) -> (Output, String) {
    fs::write(dir.join("p.csv"), csv).unwrap();
    let _ = fs::remove_file(dir.join("f.csv"));
    let mut all = vec![
        "tyre-eval",
        tyre.to_str().unwrap(),
        "p.csv",
        "--out",
        "f.csv",
    ];
    all.extend_from_slice(args);
    let o = bin().args(all).current_dir(dir).output().unwrap();
    let written = fs::read_to_string(dir.join("f.csv")).unwrap_or_default();
    (o, written)
}

/// The column `name` of a written CSV.
pub(crate) fn column(csv: &str, name: &str) -> Vec<f64> {
    let mut lines = csv.lines();
    let at = lines
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no {name}: {csv}"));
    lines
        .map(|l| l.split(',').nth(at).unwrap().parse().unwrap())
        .collect()
}

/// A .tir `identify` wrote from cornering-only data (PDX1 = PKX1 = 0) gave
/// fx = 0 at every slip ratio without a word; its identify line said the
/// coefficients kept "the defaults" as if they gave a force.
#[test]
fn a_tyre_without_longitudinal_force_is_warned_of_at_a_slip_ratio() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let tir = dir.path().join("m.tir");
    let o = identify_with(dir.path(), "mf61", &[], &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = "the written file's longitudinal force is 0 at any slip ratio (PDX1 = 0, PKX1 = 0)";
    assert!(String::from_utf8_lossy(&o.stdout).contains(said));
    assert!(fs::read_to_string(&tir).unwrap().contains(said));
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0.05,0.02,0,20\n4000,0,0.02,0,20\n4000,-0.1,0,0,20\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(column(&written, "fx"), [0.0, 0.0, 0.0]);
    assert!(
        stderr(&o).contains("warning: 2 of 3 points have kappa ≠ 0 and fx = 0: the tyre has no longitudinal force (PDX1 = 0, PKX1 = 0"),
        "{}",
        stderr(&o)
    );
    // A file with a longitudinal force: nothing to say.
    let (o, _) = eval(dir.path(), &mf61(dir.path(), &[]), points, &[]);
    assert!(
        o.status.success() && !stderr(&o).contains("fx = 0"),
        "{}",
        stderr(&o)
    );
}

/// The MF 6.1 sample's `my` at 200 m/s (V/LONGVL = 12.05: 0.0004·12.05 + 4e-5·12.05⁴ = 0.848
/// against QSY1 = 0.01) was written without a word.
#[test]
fn a_rolling_resistance_moment_past_its_speed_terms_reach_is_warned_of() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,16.6\n4000,0,0,0,200\n4000,0,0,0,150\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let my = column(&written, "my");
    assert!(my[1].abs() > 50.0 * my[0].abs(), "{my:?}");
    // 0.0004·x + 4e-5·x⁴ = 0.1 at x = 7.06, 117 m/s.
    let e = stderr(&o);
    assert!(
        e.contains("warning: 2 of 3 points faster than 117 m/s, where the speed terms of `my`")
            && e.contains("(at 200 m/s the terms come to 0.848, against QSY1 = 0.01)"),
        "{e}"
    );
    let (o, _) = eval(
        dir.path(),
        &tir,
        "fz,kappa,alpha,camber,speed\n4000,0,0,0,100\n",
        &[],
    );
    assert!(
        o.status.success() && !stderr(&o).contains("`my`"),
        "{}",
        stderr(&o)
    );
    // Without speed terms, no speed is past them.
    let flat = mf61(dir.path(), &[("QSY3", "0"), ("QSY4", "0")]);
    let (o, _) = eval(dir.path(), &flat, points, &[]);
    assert!(
        o.status.success() && !stderr(&o).contains("`my`"),
        "{}",
        stderr(&o)
    );
}

/// With the limit checks off (mode 221) a load far past FZMAX gave a
/// loaded radius of 3e-14 m (the bisection's end at a deflection of the
/// whole radius), or below 0 on other files, as MFeval's closed form does.
#[test]
fn a_load_the_vertical_model_does_not_carry_is_refused_at_its_row() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,16\n1000000,0,0,0,16\n";
    let (o, _) = eval(dir.path(), &tir, points, &["--mode", "221"]);
    let e = stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("p.csv:3:1: fz = 1000000 N is more than the tyre's vertical model carries: ")
            && e.contains("so no loaded radius `rl` is physical there"),
        "{e}"
    );
    assert!(!e.contains("p.csv:2:"), "{e}");
    // The limit checks hold the load at FZMAX (18000 N): a radius below
    // the free one and above 0 (40 kN: 1 MN puts the tyre on its rim,
    // refused in every mode since session 107).
    let (o, _) = eval(dir.path(), &tir, points, &[]);
    assert!(stderr(&o).contains("p.csv:3:1: fz = 1000000 N is more than the tyre's vertical model carries: by its own vertical stiffness"), "{}", stderr(&o));
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,16\n40000,0,0,0,16\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rl = column(&written, "rl");
    assert!(rl.iter().all(|r| *r > 0.3 && *r < 0.3945), "{rl:?}");
}

/// A TOML tyre at zero load gave no force and no word, where a
/// Magic Formula file's points off the road were counted.
#[test]
fn a_toml_tyre_off_the_road_is_counted_as_a_magic_formula_one_is() {
    let dir = tempfile::tempdir().unwrap();
    let points =
        "fz,kappa,alpha,camber,speed\n0,0.05,0.05,0,20\n0,0.05,0.05,0,20\n3000,0.05,0.05,0,20\n";
    for toml in ["pac89_adams_example.toml", "unitire.toml", "gim.toml"] {
        let (o, written) = eval(dir.path(), &root().join("tyres").join(toml), points, &[]);
        assert!(o.status.success(), "{toml}: {}", stderr(&o));
        assert!(
            stdout(&o).contains("3 points of p.csv (")
                && stdout(&o).contains("; 2 points at fz ≤ 0 (off the road): no force; wrote "),
            "{toml}: {}",
            stdout(&o)
        );
        assert_eq!(column(&written, "fy")[..2], [0.0, 0.0], "{toml}");
    }
}

/// `FSAE_Defaults.tir` (FZMAX 2000 N) at points of 500 and 5000 N named
/// "the loads evaluated (500 to 5000 N)", where its forces are evaluated
/// at no load above 2000 N.
#[test]
fn a_slip_stiffness_sign_change_names_the_loads_the_limit_checks_leave() {
    let test = "a_slip_stiffness_sign_change_names_the_loads_the_limit_checks_leave";
    let Some(tir) = shared_data(test, "tir_public/FSAE_Defaults.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n500,0.01,0.01,0,16\n5000,0.01,0.01,0,16\n";
    let (o, _) = eval(dir.path(), &tir, points, &[]);
    let e = stderr(&o);
    assert!(
        e.contains("inside the loads evaluated (500 to 2000 N, the points' loads up to 5000 N held at the file's FZMAX)"),
        "{e}"
    );
    // With the limit checks off the loads are evaluated as given.
    let (o, _) = eval(dir.path(), &tir, points, &["--mode", "221"]);
    let e = stderr(&o);
    assert!(
        e.contains("inside the loads evaluated (500 to 5000 N):"),
        "{e}"
    );
}

/// The .tir `identify` wrote from cornering-only data gave mx = my = 0 at
/// every point without a word, its `QSX` and `QSY` blocks all 0; the
/// sample file, with both, says nothing.
#[test]
fn a_tyre_without_wheel_moments_is_warned_of() {
    let dir = scratch(&[("rig.csv", &rig(1.0))]);
    let tir = dir.path().join("m.tir");
    let o = identify_with(dir.path(), "mf61", &[], &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.02,0,20\n4000,0,0,0.02,20\n0,0,0.02,0,20\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(column(&written, "mx"), [0.0; 3]);
    assert_eq!(column(&written, "my"), [0.0; 3]);
    let e = stderr(&o);
    assert!(
        e.contains("warning: 2 of 3 points have fy or camber ≠ 0 and mx = 0: the tyre has no overturning moment (QSX1 to QSX14 all 0: the file carries no overturning moment coefficients, as `identify` writes a block it had no data to fit); its mx is not a prediction"),
        "{e}"
    );
    assert!(
        e.contains("warning: 2 of 3 points have speed ≠ 0 and my = 0: the tyre has no rolling resistance moment (QSY1 to QSY8 all 0: the file carries no rolling resistance coefficients,"),
        "{e}"
    );
    let (o, _) = eval(dir.path(), &mf61(dir.path(), &[]), points, &[]);
    let e = stderr(&o);
    assert!(
        o.status.success() && !e.contains("= 0: the tyre has no"),
        "{e}"
    );
}

/// A speed of -20 m/s was taken: the Magic Formula flipped its fy (2395 N
/// to -2302 N) and my, a Gim tyre gave the same forces as at +20 m/s.
#[test]
fn a_negative_speed_is_refused_at_its_row() {
    let dir = tempfile::tempdir().unwrap();
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n4000,0,0.05,0,-20\n4000,0,0.05,0,0\n";
    let gim = root().join("tyres/gim.toml");
    for tyre in [mf61(dir.path(), &[]), gim] {
        let (o, written) = eval(dir.path(), &tyre, points, &[]);
        let e = stderr(&o);
        assert!(!o.status.success() && written.is_empty(), "{e}");
        assert!(
            e.contains("p.csv:3:5: column `speed`: -20 m/s is negative: `speed` is the wheel's forward speed, 0 or more (FORMATS.md): a slip angle within ±90° already has the wheel rolling forwards (ISO 8855 measures it from the wheel's heading to its travel)"),
            "{e}"
        );
        assert!(!e.contains("p.csv:2:") && !e.contains("p.csv:4:"), "{e}");
    }
}

/// One row's pressure written in kPa (220) among rows in Pa passed the
/// column's median and was held at the file's PRESMIN without a word of
/// the unit; each such row is refused at its cell with the reading that
/// lands among the tyre's pressures.
#[test]
fn a_pressure_row_in_kpa_bar_or_psi_is_refused_with_the_reading_meant() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,260000\n4000,0,0.05,0,20,220\n4000,0,0.05,0,20,2.6\n4000,0,0.05,0,20,260000\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    let e = stderr(&o);
    assert!(!o.status.success() && written.is_empty(), "{e}");
    assert!(
        e.contains("p.csv:3:6: column `pressure`: 220 Pa: no inflated tyre runs below 10000 Pa (0.1 bar), and the column's median is 260000 Pa: `pressure` is in Pa (FORMATS.md): did you mean 220000 Pa (220 kPa), within the file's PRESMIN to PRESMAX (200000 to 400000 Pa)?"),
        "{e}"
    );
    assert!(
        e.contains("p.csv:4:6: column `pressure`: 2.6 Pa")
            && e.contains("did you mean 260000 Pa (2.6 bar)"),
        "{e}"
    );
    // A TOML tyre states no pressures: the column's median is the guide.
    let gim = root().join("tyres/gim.toml");
    let (o, _) = eval(dir.path(), &gim, points, &[]);
    let e = stderr(&o);
    assert!(
        e.contains("did you mean 220000 Pa (220 kPa), within half to twice the median (130000 to 520000 Pa)?"),
        "{e}"
    );
}

/// A speed of 400 m/s was said to be "outside -300 to 300 m/s" (then "outside 0 to 300 m/s"; now "above 300 m/s"), though
/// negative speeds are refused anyway; a slip angle of 5 (degrees, in a
/// column of radians) was refused with no word of degrees, where
/// `identify` asks "is the column in degrees?".
#[test]
fn a_speed_past_its_range_names_the_end_passed_and_an_angle_in_degrees_is_said_as_such() {
    let dir = tempfile::tempdir().unwrap();
    let gim = root().join("tyres/gim.toml");
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,400\n4000,0,5,0,20\n4000,0,0.05,0,20\n";
    let (o, written) = eval(dir.path(), &gim, points, &[]);
    let e = stderr(&o);
    assert!(!o.status.success() && written.is_empty(), "{e}");
    assert!(
        e.contains("p.csv:2:5: column `speed`: 400 m/s is above 300 m/s, the largest"),
        "{e}"
    );
    assert!(
        e.contains("p.csv:3:3: column `alpha`: 5 rad is beyond ±90°: angles are in radians (FORMATS.md); is the column in degrees?"),
        "{e}"
    );
    assert!(!e.contains("p.csv:4:"), "{e}");
}

/// The bundled UniTire at κ = α = 0.1 gave its pure-slip fy with its
/// pure-slip fx, a resultant 1.34 times its friction, without a word; so
/// did PAC89. A Magic Formula tyre couples them: nothing to say.
#[test]
fn an_uncoupled_model_at_combined_slip_is_said_with_its_resultant_beyond_friction() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0.1,0.1,0,20\n4000,0.1,0,0,20\n4000,0,0.1,0,20\n4000,-0.02,0.01,0,20\n";
    for toml in ["unitire.toml", "pac89_adams_example.toml"] {
        let model = toml.split(['_', '.']).next().unwrap();
        let (o, written) = eval(dir.path(), &root().join("tyres").join(toml), points, &[]);
        let e = stderr(&o);
        assert!(o.status.success(), "{toml}: {e}");
        let (fx, fy) = (column(&written, "fx"), column(&written, "fy"));
        // Each force its pure-slip one: the first row's the next two's.
        assert_eq!((fx[0], fy[0]), (fx[1], fy[2]), "{toml}");
        assert!(
            e.contains(&format!("warning: this {model} tyre does not couple fx and fy: at the 2 of 4 points at combined slip (kappa ≠ 0 and alpha ≠ 0) its fx is its pure-slip force at kappa and its fy at alpha")),
            "{toml}: {e}"
        );
        // The first point only: the last, at small slips, is within its
        // friction however the two add.
        assert!(
            e.contains("warning: 1 of 4 points has √(fx² + fy²) more than 5 % above the tyre's friction μ·Fz")
                && e.contains("at fz = 4000 N, kappa = 0.1000, alpha = 0.1000 rad: the model does not couple fx and fy (above)"),
            "{toml}: {e}"
        );
    }
    let (o, _) = eval(dir.path(), &mf61(dir.path(), &[]), points, &[]);
    let e = stderr(&o);
    assert!(
        o.status.success()
            && !without_temp_names(&e).contains("couple")
            && !e.contains("friction μ·Fz"),
        "{e}"
    );
}

/// The MF 6.1 sample at α = −0.05 rad gave mz = +0.21 N·m at zero speed
/// (−43 N·m at 20 m/s, fy negative at both) without a word: MFeval's
/// cos'α = Vx/(Vc + εV) takes the trail's term away at Vx = 0. Kept, as
/// MFeval has it, and said with a count.
#[test]
fn a_magic_formula_mz_at_zero_speed_is_said_to_be_its_residual_torque() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,-0.05,0,20\n4000,0,-0.05,0,0\n4000,0,0.05,0,0\n4000,0,0,0,0\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    let (fy, mz) = (column(&written, "fy"), column(&written, "mz"));
    assert!(
        fy[0] < 0.0 && fy[1] < 0.0 && mz[0] < -40.0 && mz[1] > 0.0,
        "{written}"
    );
    assert!(
        e.contains("warning: 2 of the 3 points at zero speed (below 0.0001 m/s) have a slip angle ≠ 0: mz there is the residual torque alone, of the opposite sign to the same point's at VXLOW = 1.00 m/s at 1 of them (0.210 N·m against -47.5 N·m), as MFeval's formula gives it (cos'α = Vx/(Vc + εV)"),
        "{e}"
    );
    // At any speed the trail is there: nothing to say.
    let (o, _) = eval(dir.path(), &tir, &points.replace(",0\n", ",0.5\n"), &[]);
    assert!(
        o.status.success() && !stderr(&o).contains("zero speed"),
        "{}",
        stderr(&o)
    );
}

/// A PAC89 `a3` of 3.036 (kN/deg typed for 3036 N/deg: a cornering
/// stiffness 1000 times too soft) and a UniTire `p3` of 0.244 (14 per
/// degree, 57 times too soft) were evaluated without a word, where a Gim
/// or linear tyre's cornering stiffness in N/deg is refused.
#[test]
fn a_pac89_or_unitire_stiffness_in_another_unit_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    let pac89 = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    let unitire = fs::read_to_string(root().join("tyres/unitire.toml")).unwrap();
    let cases = [
        (
            "p.toml",
            pac89.replace("1250.0, 3036.0,", "1250.0, 3.036,"),
            "p.toml:8:27: `a3` = 3.036: must be larger than 15 in magnitude (either sign): PAC89's cornering stiffness is BCD = a3·sin(2·atan(Fz/a4)), in N/deg",
            "is the value in kN/deg? multiply it by 1000",
        ),
        (
            "u.toml",
            unitire.replacen("1.2, 14.0, -2.0, 0.2,", "1.2, 0.244, -0.0349, 0.0035,", 1),
            "u.toml:13:16: `lateral.p[2]` = 0.244: must be greater than 0.9: UniTire's cornering stiffness",
            "are p3, p4 and p5 per degree? multiply them by 57.3",
        ),
        (
            "u.toml",
            unitire.replacen("1.0, 18.0, -1.5, 0.1,", "1.0, 0.18, -0.015, 0.001,", 1),
            "u.toml:16:16: `longitudinal.p[2]` = 0.18: must be greater than 0.9: UniTire's longitudinal slip stiffness",
            "are p3, p4 and p5 per percent of slip? multiply them by 100",
        ),
    ];
    for (name, text, said, hint) in cases {
        let tyre = dir.path().join(name);
        fs::write(&tyre, text).unwrap();
        let (o, written) = eval(dir.path(), &tyre, points, &[]);
        let e = stderr(&o);
        assert!(!o.status.success() && written.is_empty(), "{e}");
        assert!(e.contains(said) && e.contains(hint), "{e}");
    }
    // The bundled files, in their units, are read.
    for toml in ["pac89_adams_example.toml", "unitire.toml"] {
        let (o, _) = eval(dir.path(), &root().join("tyres").join(toml), points, &[]);
        assert!(o.status.success(), "{toml}: {}", stderr(&o));
    }
}

/// A .tir whose pressure coefficients turn its cornering stiffness over
/// inside its own PRESMIN–PRESMAX (the public car205_60R19.tir gave
/// fy = −1945 N at α = +0.05 rad and 800 kPa without a word): counted at
/// the points' own conditions; the sample file as published says nothing.
#[test]
fn a_cornering_stiffness_the_pressure_turns_negative_is_counted_at_the_points() {
    let dir = tempfile::tempdir().unwrap();
    let points =
        "fz,kappa,alpha,camber,speed,pressure\n4000,0,0.05,0,20,260000\n4000,0,0.05,0,20,380000\n";
    let sample = mf61(dir.path(), &[]);
    let (o, _) = eval(dir.path(), &sample, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !stderr(&o).contains("negative cornering stiffness"),
        "{}",
        stderr(&o)
    );
    // PPY1 = −3: Kyα ∝ 1 + PPY1·dpi is negative above 1/3 of NOMPRES over it.
    let turned = mf61(dir.path(), &[("PPY1", "-3.0")]);
    let (o, written) = eval(dir.path(), &turned, points, &[]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains("1 of 2 points has a negative cornering stiffness at its own load, camber, pressure and speed (the first at line 3: fz = 4000 N, camber = 0 rad, pressure = 380000 Pa): there the force opposes the slip"),
        "{e}"
    );
    let fy = column(&written, "fy");
    assert!(fy[0] > 0.0 && fy[1] < 0.0, "{fy:?}");
}

/// `tyre-eval` said "4 of them outside the file's ranges of load, slip,
/// camber or pressure" and left the user to find which range each point
/// left: each range is now named with its count, its ends in the points'
/// frame (the sample file is a right-side tyre: its camber range mirrored)
/// and its first point's line and value.
#[test]
fn each_range_a_point_leaves_is_named_with_its_count_ends_and_first_point() {
    let dir = tempfile::tempdir().unwrap();
    let tir = mf61(dir.path(), &[]);
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n20000,0,0.05,0,20\n4000,0,1.2,0,20\n4000,0,-1.5,0.1,20\n25000,0,0,0,20\n";
    let (o, _) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (said, warned) = (stdout(&o), stderr(&o));
    assert!(
        said.contains("; 4 of them outside the file's ranges"),
        "{said}"
    );
    for line in [
        "warning: 2 of 5 points above FZMAX = 18000 N (the file's range 0 to 18000): evaluated at that end; the first at line 3, fz = 20000 N",
        "warning: 1 of 5 points above ALPMAX = 0.96 rad, in the points' frame (the file's range -0.96 to 0.96): evaluated at that end; the first at line 4, alpha = 1.2 rad",
        "warning: 1 of 5 points below ALPMIN = -0.96 rad, in the points' frame (the file's range -0.96 to 0.96): evaluated at that end; the first at line 5, alpha = -1.5 rad",
        "warning: 1 of 5 points above CAMMAX = 0.0873 rad, in the points' frame (the file's range -0.105 to 0.0873): evaluated at that end; the first at line 5, camber = 0.1 rad",
    ] {
        assert!(warned.contains(line), "{line}\n{warned}");
    }
    assert!(
        !without_temp_names(&warned).contains("KPUMIN") && !warned.contains("PRESMIN"),
        "{warned}"
    );
    // Below FZMIN a point is not saturated (MFeval's limit checks clamp
    // the load only at FZMAX): said so, and its force is the given load's.
    let tir = mf61(dir.path(), &[("FZMIN", "100")]);
    let points = "fz,kappa,alpha,camber,speed\n50,0,0.05,0,20\n100,0,0.05,0,20\n";
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: 1 of 2 points below FZMIN = 100 N (the file's range 100 to 18000): fx and fy evaluated at the load given (MFeval saturates the load only at FZMAX)"),
        "{}",
        stderr(&o)
    );
    let fy = column(&written, "fy");
    assert!((fy[0] / fy[1] - 0.5).abs() < 0.05, "{fy:?}");
}

/// The public `car235_80R17.tir`'s `PHX1 = 0.01014` gave fx = 773 N at
/// kappa = 0 and 4000 N, a car pushed at 0.19 g by tyres that do not slip,
/// without a word: said, counted, with the coefficient that makes it.
#[test]
fn a_large_fx_at_zero_slip_is_said_with_the_shift_that_makes_it() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,20\n6000,0,0.05,0,20\n4000,0.05,0,0,20\n";
    // The sample file's own shifts give about 1 % at FNOMIN: no word.
    let (o, _) = eval(dir.path(), &mf61(dir.path(), &[]), points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("kappa = 0"), "{}", stderr(&o));
    let tir = mf61(dir.path(), &[("PHX1", "0.01014")]);
    let (o, written) = eval(dir.path(), &tir, points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let fx = column(&written, "fx");
    assert!(fx[0].abs() > 0.05 * 4000.0, "{fx:?}");
    let e = stderr(&o);
    assert!(
        e.contains("warning: 2 of 3 points at kappa = 0 have |fx| above 5 % of fz (the largest ")
            && e.contains("where a free-rolling tyre gives its rolling resistance, about 1 %: the file's PHX1 = 0.01014 gives it; check them"),
        "{e}"
    );
    // At rest the sample's own fx at zero slip is 5.9 % of fz (−235.6 N;
    // within 5 % from VXLOW up): the speed's doing, said as such, not the
    // file's shifts blamed.
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0,0,0\n4000,0,0,0,20\n";
    let (o, written) = eval(dir.path(), &mf61(dir.path(), &[]), points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let fx = column(&written, "fx");
    assert!(
        fx[0].abs() > 0.05 * 4000.0 && fx[1].abs() < 0.05 * 4000.0,
        "{fx:?}"
    );
    let e = stderr(&o);
    assert!(
        e.contains("warning: 1 of 2 points at kappa = 0 below the file's VXLOW = 1 m/s has |fx| above 5 % of fz (the largest -235.6 N, line 2): MFeval fades the vertical shift SVx to 0 towards rest"),
        "{e}"
    );
    assert!(!e.contains("gives it"), "{e}");
}
