//! What a fresh-eyes check of `identify` and `tyre-eval` found after stop
//! 75, run as a user runs the tool: a force written against its
//! slip in silence, a lateral block no fit ran on left unsaid, a held line
//! whose value is not the one written, a template's nominal pressure
//! outside the data's, a longitudinal sweep refused for its `fy` column
//! at `alpha` 0, digits past meaning, and a Magic Formula version the
//! tool reads taken for a misspelt one it fits.

use super::*;

/// The MF 6.1 sample the points are generated from.
fn mf61() -> String {
    fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")).unwrap()
}

/// `text` with `key`'s value replaced by `value`.
fn with(text: &str, key: &str, value: &str) -> String {
    let out: String = text
        .lines()
        .map(|l| match l.split_whitespace().next() == Some(key) {
            true => {
                let eq = l.find('=').unwrap();
                let rest = l[eq + 1..].trim_start();
                let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
                format!("{} {value} {}\n", &l[..=eq], &rest[end..])
            }
            false => format!("{l}\n"),
        })
        .collect();
    assert_ne!(out.trim_end(), text.trim_end(), "no {key} line");
    out
}

/// Both streams of `o`, for lines either may carry.
fn said(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(o))
}

/// Rig-like rows of the MF 6.1 sample at loads 2, 4 and 6 kN, every
/// `(kappa, alpha)` of `slips`, evaluated by `tyre-eval` into `rig.csv` in
/// `dir` (with its `fx, fy, mz, mx, my, rl` columns).
fn rig(dir: &Path, slips: &[(f64, f64)]) {
    let mut p = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2000, 4000, 6000] {
        for (k, a) in slips {
            p += &format!("{fz},{k},{a},0,16.7\n");
        }
    }
    fs::write(dir.join("t.tir"), mf61()).unwrap();
    fs::write(dir.join("p.csv"), p).unwrap();
    let o = run_in(dir, &["tyre-eval", "t.tir", "p.csv", "--out", "rig.csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Slip ratios from −0.3 to 0.3 in steps of 0.0075 (0 among them).
fn kappas() -> impl Iterator<Item = f64> {
    (-40..=40).map(|i| f64::from(i) * 0.0075)
}

/// With MFeval's limit checks off (mode 221), a fit whose curvature E
/// exceeds 1 gave the Hoosier file's fy = −2711 N at α = +9°, inside its
/// range, and `tyre-eval` wrote it without a word. Every force of the
/// opposite sign to its slip inside the file's ranges is counted, the
/// first named; with the checks on (121) the same file keeps its sign.
#[test]
fn a_force_against_its_slip_inside_the_ranges_is_warned() {
    let tir = with(&mf61(), "PEY1", "3");
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16\n4000,0,0.15,0,16\n4000,0,-0.15,0,16\n4000,0.1,0,0,16\n";
    let dir = scratch(&[("e.tir", &tir), ("p.csv", points)]);
    let off = run_in(
        dir.path(),
        &[
            "tyre-eval",
            "e.tir",
            "p.csv",
            "--mode",
            "221",
            "--out",
            "a.csv",
        ],
    );
    assert!(off.status.success(), "{}", stderr(&off));
    let e = stderr(&off);
    assert!(
        e.contains("warning: 2 of 4 points inside the file's ranges of load, slip, camber and pressure have a lateral force against their slip (fy of opposite sign to alpha, beyond what it gives at alpha = 0; the first at line 3: fz = 4000 N, alpha = 0.1500 rad (8.594°)"),
        "{e}"
    );
    assert!(
        e.contains("evaluated with the limit checks off (mode 221)"),
        "{e}"
    );
    let on = run_in(
        dir.path(),
        &["tyre-eval", "e.tir", "p.csv", "--out", "b.csv"],
    );
    assert!(on.status.success(), "{}", stderr(&on));
    assert!(
        !stderr(&on).contains("against their slip"),
        "{}",
        stderr(&on)
    );
}

/// Combined-slip rows with too few pure lateral ones (α of 0, ±0.035 and
/// 0.07 rad at κ = 0) skipped the pure Fy stage and wrote PDY1 = PKY1 = 0
/// without the closing line every other block no fit ran on gets; and
/// `tyre-eval` of that file said nothing of its fy = 0 at α ≠ 0.
#[test]
fn a_lateral_block_no_fit_ran_on_is_said_at_fit_and_at_evaluation() {
    let dir = tempfile::tempdir().unwrap();
    let slips: Vec<(f64, f64)> = kappas()
        .flat_map(|k| [-0.07, 0.0, 0.035, 0.07].map(|a| (k, a)))
        .collect();
    rig(dir.path(), &slips);
    let o = run_in(
        dir.path(),
        &["identify", "rig.csv", "--model", "mf61", "--out", "c.tir"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let s = said(&o);
    assert!(s.contains("pure Fy      skipped: "), "{s}");
    assert!(
        s.contains("no pure lateral data: the lateral force block is not fitted (")
            && s.contains("its coefficients are the defaults' (no --template); the written file's lateral force is 0 at any slip angle (PDY1 = 0, PKY1 = 0): give --template with a tyre's lateral coefficients for one"),
        "{s}"
    );
    // A noise-free fit's spread by load in digits that show it.
    assert!(!s.contains("σ 0.0 % at"), "{s}");
    let points = "fz,kappa,alpha,camber,speed\n3000,0,0.05,0,16\n3000,0.05,0,0,16\n";
    fs::write(dir.path().join("q.csv"), points).unwrap();
    let e = run_in(
        dir.path(),
        &["tyre-eval", "c.tir", "q.csv", "--out", "e.csv"],
    );
    assert!(e.status.success(), "{}", stderr(&e));
    assert!(
        stderr(&e).contains("warning: 1 of 2 points has alpha ≠ 0 and fy = 0: the tyre has no lateral force (PDY1 = 0, PKY1 = 0: as `identify` writes a lateral block it had no data to fit); its fy is not a prediction"),
        "{}",
        stderr(&e)
    );
}

/// A longitudinal sweep at α = 0 written by `tyre-eval` (its `fy` and
/// `mz` columns kept) was refused by PAC89 as "3 points with a measured
/// lateral force cannot fit 11 parameters", while the same file without
/// those columns fits its longitudinal force. The lateral columns are set
/// aside, counted, and the longitudinal force fitted.
#[test]
fn lateral_columns_at_alpha_zero_are_set_aside_for_the_longitudinal_fit() {
    let dir = tempfile::tempdir().unwrap();
    let slips: Vec<(f64, f64)> = kappas().map(|k| (k, 0.0)).collect();
    rig(dir.path(), &slips);
    let o = run_in(
        dir.path(),
        &["identify", "rig.csv", "--model", "pac89", "--out", "l.toml"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let s = said(&o);
    assert!(
        s.contains("alpha is 0 throughout (|alpha| ≤ 0.001 rad in all 243 rows): no lateral slip to fit, so its 243 values of `fy` and 243 of `mz` are not fitted, and the longitudinal force is fitted as from a file without them"),
        "{s}"
    );
    assert!(dir.path().join("l.toml").exists());
}

/// Lateral forces in kN beside loads in N are refused with the share and
/// the sweep's reach in a few digits and with their units (it said "is
/// 0.001077848 of the load over a sweep reaching a slip of 0.20944").
#[test]
fn forces_below_any_grip_are_said_in_few_digits_with_the_slip_unit() {
    let dir = tempfile::tempdir().unwrap();
    let slips: Vec<(f64, f64)> = (-12..=12).map(|i| (0.0, f64::from(i) * 0.01745)).collect();
    rig(dir.path(), &slips);
    let text = fs::read_to_string(dir.path().join("rig.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let fy = header.iter().position(|h| *h == "fy").unwrap();
    let mut kn = String::from("fz,kappa,alpha,camber,speed,fy\n");
    for l in lines {
        let c: Vec<&str> = l.split(',').collect();
        let f: f64 = c[fy].parse().unwrap();
        kn += &format!(
            "{},{},{},{},{},{}\n",
            c[0],
            c[1],
            c[2],
            c[3],
            c[4],
            f / 1000.0
        );
    }
    fs::write(dir.path().join("kn.csv"), kn).unwrap();
    let o = run_in(
        dir.path(),
        &["identify", "kn.csv", "--model", "linear", "--out", "k.toml"],
    );
    let e = refused(&o, &dir.path().join("k.toml"));
    assert!(
        e.contains("of the load over a sweep reaching a slip angle of 0.209 rad ("),
        "{e}"
    );
}

/// `mf52` was answered "did you mean `mf62`?": 5.2 is a version the
/// readers take and `identify` does not fit, said so with the models it
/// fits.
#[test]
fn a_magic_formula_version_the_tool_reads_but_does_not_fit_is_said_so() {
    let dir = scratch(&[("r.csv", "fz,alpha,fy\n4000,0.01,900\n")]);
    let o = run_in(
        dir.path(),
        &["identify", "r.csv", "--model", "mf52", "--out", "z.tir"],
    );
    let e = refused(&o, &dir.path().join("z.tir"));
    assert!(
        e.contains("--model mf52: Magic Formula 5.2 is a version `tyre-eval` and `simulate` read from a .tir, but `identify` does not fit it")
            && e.contains("give --model mf61, the nearest; the models it fits: gim, magic-simple, unitire, pac89, linear, mf61, mf62"),
        "{e}"
    );
    assert!(!e.contains("did you mean"), "{e}");
}

/// The Hoosier file fitted from the public FSAE template held QBZ1 "at
/// the template's value 11.692" and wrote 2.98; and kept the template's
/// NOMPRES = 220 kPa while the data's pressures are 68–99 kPa, in
/// silence. Every held line's value is the one written, and a template's
/// nominal pressure outside the data's is replaced by theirs, said.
#[test]
fn a_template_fit_writes_its_held_values_and_warns_of_its_nominal_pressure() {
    let test = "a_template_fit_writes_its_held_values_and_warns_of_its_nominal_pressure";
    // `identify <hoosier> --model mf61 --template fsae190_50R10.tir --out
    // h.tir`, run once for this test and trips_s95_ident's.
    let Some(fit) = shared_runs::hoosier_on_fsae190(test) else {
        return;
    };
    let s = format!("{}{}", fit.stdout, fit.stderr);
    let tir = fs::read_to_string(fit.dir.join("h.tir")).unwrap();
    let written = |name: &str| -> f64 {
        let l = tir
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no {name} in the file"));
        l.split('=')
            .nth(1)
            .unwrap()
            .split_whitespace()
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    let mut template_holds = 0;
    for l in s.lines().map(str::trim).filter(|l| l.starts_with("held: ")) {
        let (name, rest) = l["held: ".len()..].split_once(" = ").unwrap();
        let Some(at) = l.split("held at the template's value ").nth(1) else {
            continue;
        };
        template_holds += 1;
        let value: f64 = rest.split(':').next().unwrap().parse().unwrap();
        let stated: f64 = at.split([',', ';', ' ']).next().unwrap().parse().unwrap();
        assert_eq!(value, stated, "{l}");
        assert_eq!(written(name), value, "{l}");
    }
    assert!(template_holds > 0, "{s}");
    // The template's NOMPRES (220 kPa) lies outside the data's 68–99 kPa:
    // the fit is made about the data's median pressure, said, and the
    // peak friction is no longer carried by the pressure terms (the old
    // fit: PDY1 on its bound 0.05, PPY3 = −25.9).
    let nompres = s
        .lines()
        .find(|l| l.trim_start().starts_with("held: NOMPRES = 83400: "))
        .unwrap_or_else(|| panic!("NOMPRES not set to the data's median: {s}"));
    assert!(
        nompres.contains("in place of the template's 220000 Pa")
            && nompres.contains("67840 to 99200 Pa")
            && nompres.contains("give --hold NOMPRES=220000")
            && !nompres.contains("no --template"),
        "{nompres}"
    );
    assert_eq!(written("NOMPRES"), 83400.0);
    assert!(written("PDY1") > 0.1, "PDY1 on its bound: {s}");
    assert!(written("PPY3").abs() < 5.0, "PPY3 = {}", written("PPY3"));
}

/// A linear fit of the Hoosier file (no load, camber or pressure terms)
/// warned that "the linear model's laws of load, camber and pressure do
/// not carry its curve" to the light load it misses: laws it does not
/// have. It says it has none.
#[test]
fn a_model_without_laws_of_condition_is_not_said_to_have_them() {
    let test = "a_model_without_laws_of_condition_is_not_said_to_have_them";
    let Some(data) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let o = run_in(
        dir.path(),
        &[
            "identify",
            data.to_str().unwrap(),
            "--model",
            "linear",
            "--out",
            "l.toml",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let s = said(&o);
    assert!(
        s.contains("the linear model has no law of load, camber or pressure (one curve for every condition): it cannot follow them"),
        "{s}"
    );
    assert!(!s.contains("model's laws of"), "{s}");
}
