//! What a fresh-eyes check of the `.tir` reader found after stop 73, run as
//! a user runs the tool: pressures in kPa or bar read as Pa, peak and
//! shape coefficients no tyre has, and `[UNITS]` lines the values do not
//! follow. Each is refused at its line, with the value; no published file
//! is.

use super::*;

const POINTS: &str = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";

/// The public car tyre the checks edit, or `None` (skipped) without the
/// public data.
fn car(test: &str) -> Option<String> {
    let p = shared_data(test, "tir_public/car205_60R19.tir")?;
    Some(fs::read_to_string(p).unwrap())
}

/// `text` with the value of `key`'s line replaced by `value` (the column
/// kept), and that line's number.
fn with(text: &str, key: &str, value: &str) -> (String, usize) {
    let mut at = 0;
    let out = text
        .lines()
        .enumerate()
        .map(|(i, l)| match l.split_whitespace().next() == Some(key) {
            true => {
                at = i + 1;
                let eq = l.find('=').unwrap();
                let rest = &l[eq + 1..];
                let lead = rest.len() - rest.trim_start().len();
                let end = rest[lead..]
                    .find(char::is_whitespace)
                    .unwrap_or(rest.len() - lead);
                format!("{}{value}{}\n", &l[..eq + 1 + lead], &rest[lead + end..])
            }
            false => format!("{l}\n"),
        })
        .collect();
    assert!(at > 0, "no {key} line");
    (out, at)
}

/// `tyre-eval t.tir p.csv` on `tir`, refused: its stderr.
fn eval_refused(tir: &str) -> String {
    let dir = scratch(&[("t.tir", tir), ("p.csv", POINTS)]);
    let o = bin()
        .args(["tyre-eval", "t.tir", "p.csv", "--out", "e.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    refused(&o, &dir.path().join("e.csv"))
}

/// `simulate` of a step steer on `tir` at the front, refused: its stderr.
fn simulate_refused(tir: &str) -> String {
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"tyre.tir\"\n\n{STEP}");
    let dir = scratch(&[("scenario.toml", &sc), ("tyre.tir", tir)]);
    fails_cleanly("simulate", &dir.path().join("scenario.toml"), dir.path())
}

/// `NOMPRES = 220` (kPa) beside `INFLPRES = 220000` made `tyre-eval` blame
/// the points file with a 13-digit negative load, and `simulate` ran on
/// it. A pressure outside any tyre's (10 kPa to 2 MPa) is refused at its
/// line, with the unit it is likely in and the other key that says so.
#[test]
fn a_pressure_in_kpa_bar_or_psi_is_refused_at_its_line() {
    let Some(t) = car("a_pressure_in_kpa_bar_or_psi_is_refused_at_its_line") else {
        return;
    };
    let (kpa, line) = with(&t, "NOMPRES", "220");
    let e = eval_refused(&kpa);
    let said = format!("t.tir:{line}:28: `NOMPRES`: 220 must lie in (10000, 2000000]: a tyre's inflation pressure is 10 kPa to 2 MPa");
    assert!(e.contains(&said), "{said}\n{e}");
    assert!(
        e.contains(
            "is it in kPa? (220 kPa is 220000 Pa); the file's INFLPRES is about 1000 times it"
        ),
        "{e}"
    );
    assert!(!e.contains("p.csv"), "{e}");
    let e = simulate_refused(&kpa);
    assert!(
        e.contains(&format!("tyre.tir:{line}:28: `NOMPRES`: 220 must")),
        "{e}"
    );

    let (bar, _) = with(&t, "NOMPRES", "2.2");
    let e = eval_refused(&bar);
    assert!(
        e.contains(
            "is it in bar? (2.2 bar is 220000 Pa); the file's INFLPRES is about 100000 times it"
        ),
        "{e}"
    );
    let (psi, line) = with(&t, "INFLPRES", "32");
    let e = eval_refused(&psi);
    assert!(
        e.contains(&format!("t.tir:{line}:28: `INFLPRES`: 32 must")),
        "{e}"
    );
    assert!(e.contains("is it in psi? (32 psi is 220632 Pa)"), "{e}");
}

/// The peak and shape checks must refuse no published file: every public
/// file and every `.tir` of the repository's fixtures evaluates (the MF
/// 5.0 file is refused for its version, as before).
#[test]
fn every_public_and_fixture_tir_file_is_read() {
    let test = "every_public_and_fixture_tir_file_is_read";
    let Some(one) = shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let mut files: Vec<PathBuf> = fs::read_dir(one.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "tir"))
        .collect();
    assert_eq!(files.len(), 13, "{files:?}");
    files.extend(
        fs::read_dir(root().join("tests/fixtures/tir"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "tir"))
            .filter(|p| !p.ends_with("chrono_335_65R22_5_G275MSA_60psi.tir")),
    );
    let dir = scratch(&[("p.csv", POINTS)]);
    for f in files {
        let o = bin()
            .args(["tyre-eval", f.to_str().unwrap(), "p.csv", "--out", "e.csv"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}: {}", f.display(), stderr(&o));
    }
}

/// `PDY1` ten times too large (8.784) gave μ ≈ 6.3; `PDX1` likewise for
/// the longitudinal force. The file's own pure curve is judged at its
/// loads and slips, against the friction 5 a TOML tyre is refused beyond.
#[test]
fn a_peak_friction_no_tyre_has_is_refused_at_its_coefficient() {
    let Some(t) = car("a_peak_friction_no_tyre_has_is_refused_at_its_coefficient") else {
        return;
    };
    let (pdy, line) = with(&t, "PDY1", "8.784");
    let e = eval_refused(&pdy);
    // At the file's FZMIN..FZMAX clipped to 1000..8000 N: its PDY2 < 0
    // raises μy to 7.38 at 1000 N, at the end of the 30° window.
    let said = format!("t.tir:{line}:28: `PDY1`: 8.784 makes the file's pure lateral force (at zero slip ratio, no camber, LONGVL = 16.7 m/s) reach |Fy|/Fz = 7.38 at Fz = 1000 N and α = 0.524 rad (30.0°), beyond the friction 5");
    assert!(e.contains(&said), "{said}\n{e}");
    let e = simulate_refused(&pdy);
    assert!(
        e.contains(&format!("tyre.tir:{line}:28: `PDY1`: 8.784 makes")),
        "{e}"
    );

    let (pdx, line) = with(&t, "PDX1", "10.422");
    let e = eval_refused(&pdx);
    let said = format!("t.tir:{line}:28: `PDX1`: 10.422 makes the file's pure longitudinal force (at zero slip angle, no camber, LONGVL = 16.7 m/s) reach |Fx|/Fz = 10.3 at Fz = 4000 N and κ = 1.00");
    assert!(e.contains(&said), "{said}\n{e}");
    // μ 4 at FNOMIN, high but a curve: read.
    let (high, _) = with(&t, "PDY1", "4");
    let dir = scratch(&[("t.tir", &high), ("p.csv", POINTS)]);
    let o = bin()
        .args(["tyre-eval", "t.tir", "p.csv", "--out", "e.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
}

/// `PCY1` ten times too large (13.332) turned the pure lateral force
/// around at α ≈ 0.16 rad, inside ALPMIN..ALPMAX: a shape factor above 2
/// is refused where the force turns against its slip.
#[test]
fn a_shape_factor_that_turns_the_force_is_refused_at_its_coefficient() {
    let Some(t) = car("a_shape_factor_that_turns_the_force_is_refused_at_its_coefficient") else {
        return;
    };
    let (pcy, line) = with(&t, "PCY1", "13.332");
    let e = eval_refused(&pcy);
    let said = format!("t.tir:{line}:28: `PCY1`: 13.332 turns the file's pure lateral force (at zero slip ratio, no camber, LONGVL = 16.7 m/s) against its slip: Fy = -63.1 N at Fz = 1000 N and α = 0.164 rad (9.40°)");
    assert!(e.contains(&said), "{said}\n{e}");
    assert!(e.contains("C = PCY1·LCY = 13.33 lies above 2"), "{e}");
    let e = simulate_refused(&pcy);
    assert!(
        e.contains(&format!("tyre.tir:{line}:28: `PCY1`: 13.332 turns")),
        "{e}"
    );

    let (pcx, line) = with(&t, "PCX1", "15.79");
    let e = eval_refused(&pcx);
    let said = format!("t.tir:{line}:28: `PCX1`: 15.79 turns the file's pure longitudinal force");
    assert!(e.contains(&said), "{said}\n{e}");
    assert!(
        e.contains("Fx = -62.0 N at Fz = 1000 N and κ = 0.232"),
        "{e}"
    );
}

/// Values in N under `FORCE = 'kilonewton'` were refused at FNOMIN asking
/// whether FNOMIN was in kN; metres under `LENGTH = 'mm'` were asked about
/// millimetres written under 'meter'. The `[UNITS]` line is named, with
/// its unit; the opposite slip keeps the value's own hint.
#[test]
fn a_units_line_the_values_do_not_follow_is_named() {
    let Some(t) = car("a_units_line_the_values_do_not_follow_is_named") else {
        return;
    };
    let (kn, units) = with(&t, "FORCE", "'kilonewton'");
    let fnomin = t.lines().position(|l| l.starts_with("FNOMIN")).unwrap() + 1;
    let e = eval_refused(&kn);
    let said = format!("t.tir:{fnomin}:28: `FNOMIN`: 4000000 is the 4000 written here read in kN, as the file's [UNITS] FORCE at line {units} declares: outside any tyre's (100, 100000] N; read in N, as written, it is a tyre's");
    assert!(e.contains(&said), "{said}\n{e}");
    assert!(!e.contains("is the value in kN?"), "{e}");

    let (mm, units) = with(&t, "LENGTH", "'mm'");
    let radius = t
        .lines()
        .position(|l| l.starts_with("UNLOADED_RADIUS"))
        .unwrap()
        + 1;
    let e = eval_refused(&mm);
    let said = format!("t.tir:{radius}:28: `UNLOADED_RADIUS`: 0.00035 is the 0.35 written here read in mm, as the file's [UNITS] LENGTH at line {units} declares: outside any tyre's (0.05, 2] m");
    assert!(e.contains(&said), "{said}\n{e}");
    assert!(!e.contains("written with LENGTH = 'meter'"), "{e}");

    // Millimetres under 'meter': the radius's own hint, as before.
    let (in_mm, radius) = with(&t, "UNLOADED_RADIUS", "350");
    let e = eval_refused(&in_mm);
    assert!(
        e.contains(&format!(
            "t.tir:{radius}:28: `UNLOADED_RADIUS`: 350 must lie in (0.05, 2]"
        )),
        "{e}"
    );
    assert!(
        e.contains(
            "is it in millimetres, written with LENGTH = 'meter'? (350 millimetres is 0.35 m)"
        ),
        "{e}"
    );
}
