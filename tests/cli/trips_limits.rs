//! What a user still trips on at the edges of the tool's values, run as a
//! user runs it: a fitted parameter beyond its box, tyre files in millimetres, kilonewtons or with a coefficient of 1e30,
//! a lock file of bytes that are no text, and the numbers of a written
//! `.tir`.

use super::*;

/// Rig data whose force keeps rising with slip past its knee (friction
/// rising with sliding): GIM's decay would fit it only below zero.
fn rising_rig() -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.03 * f64::from(k);
            let fy = fz * (15.0 * alpha).tanh() * (1.0 + 0.8 * f64::tan(alpha).abs());
            s += &format!("{fz},{alpha},{fy:.3}\n");
        }
    }
    s
}

/// The polish, unbounded, wrote `friction_decay = -0.636`, outside its
/// box [0, 1] and refused by every command that reads the file.
#[test]
fn a_gim_fit_keeps_its_parameters_in_their_box_and_says_one_on_its_bound() {
    let dir = scratch(&[
        ("rig.csv", &rising_rig()),
        ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n"),
    ]);
    let out = dir.path().join("g.toml");
    let o = identify_to(&dir.path().join("rig.csv"), "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    // On its bound 0, to rounding (the swarm's box starts the stiffness
    // at the least any tyre has per unit load since stop 72; the polish
    // ends 1e-15 off the bound).
    let line = said
        .lines()
        .find(|l| l.starts_with("  warning: friction_decay = "))
        .unwrap_or_else(|| panic!("no friction_decay warning: {said}"));
    assert!(
        line.ends_with(": on its search bound (0 to 1): the fit would take it beyond; the value is the bound, not a fit"),
        "{line}"
    );
    let report = read_json(&out.with_extension("report.json"));
    for p in report["parameters"].as_array().unwrap() {
        let (v, lo, hi) = (
            p["value"].as_f64().unwrap(),
            p["bounds"][0].as_f64().unwrap(),
            p["bounds"][1].as_f64().unwrap(),
        );
        assert!(lo <= v && v <= hi, "{p}");
    }
    let tyre: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    let decay = tyre["friction_decay"].as_float().unwrap();
    assert!((0.0..1e-12).contains(&decay), "{tyre}");
    // The file written is one the tool reads.
    let e = run(&[
        "tyre-eval",
        out.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        dir.path().join("e.csv").to_str().unwrap(),
    ]);
    assert!(e.status.success(), "{}", stderr(&e));
}

/// A tyre file's `contact_length = 180` (mm), a load in kN and a trail in
/// mm were simulated as metres and newtons.
#[test]
fn a_tyre_file_in_millimetres_or_kilonewtons_is_refused_at_its_key() {
    let cases = [
        (
            "model = \"gim\"\ncornering_stiffness = 57296.0\ncontact_length = 180\n",
            "tyre.toml:3:18: `contact_length` = 180: must lie in (0, 1]: no tyre's contact patch is longer than 1 m",
            "is the value in millimetres? (180 mm is 0.18)",
        ),
        (
            "model = \"gim\"\ncornering_stiffness = 57296.0\ncontact_length = 0.18\nreference_load = 4\n",
            "tyre.toml:4:18: `reference_load` = 4: must lie in (100, 100000]",
            "the key is in N: is the value in kN? (4 kN is 4000)",
        ),
        (
            "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 30\n",
            "tyre.toml:3:19: `pneumatic_trail` = 30: must lie within ±0.5",
            "is the value in millimetres? (30 mm is 0.03)",
        ),
        (
            "model = \"gim\"\ncornering_stiffness = 5e7\ncontact_length = 0.18\n",
            "tyre.toml:2:23: `cornering_stiffness` = 50000000: must lie in (900, 2000000]",
            "no tyre's cornering stiffness reaches 2e6 N/rad",
        ),
    ];
    for (tyre, at, hint) in cases {
        let dir = scenario(VEHICLE, tyre, STEP);
        let e = simulate_err(dir.path());
        assert!(e.contains(at), "{e}");
        assert!(e.contains(hint), "{e}");
    }
}

/// The MF 6.1 fixture with line `line` replaced by `text`.
fn tir_with(line: usize, text: &str) -> String {
    let tir = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let mut lines: Vec<&str> = tir.lines().collect();
    lines[line - 1] = text;
    lines.join("\n")
}

/// A coefficient of 1e30, a load in kN and a radius in mm were evaluated.
#[test]
fn a_tir_value_no_tyre_has_is_refused_at_its_line() {
    let cases = [
        (
            206,
            "PKY1                     = 1e30",
            "t.tir:206:28: `PKY1`: 1e30 must lie within ±1000000: no coefficient of a published Magic Formula file reaches ±1e6",
        ),
        (
            48,
            "FNOMIN                   = 6.752",
            "t.tir:48:28: `FNOMIN`: 6.752 must lie in (100, 100000]: a tyre carries 100 N (a bicycle) to 1e5 N (a mining truck); the key is in N: is the value in kN?",
        ),
        (
            28,
            "UNLOADED_RADIUS          = 394.3",
            "t.tir:28:28: `UNLOADED_RADIUS`: 394.3 must lie in (0.05, 2]: a tyre's unloaded radius is 0.05–2 m",
        ),
    ];
    let fixture =
        fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
            .unwrap();
    for (line, text, said) in cases {
        let key = text.split_whitespace().next().unwrap();
        assert!(
            fixture.lines().nth(line - 1).unwrap().starts_with(key),
            "line {line} of the fixture is {key}'s"
        );
        let dir = scratch(&[
            ("t.tir", &tir_with(line, text)),
            ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n"),
        ]);
        let out = dir.path().join("e.csv");
        let o = bin()
            .args(["tyre-eval", "t.tir", "p.csv", "--out", "e.csv"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        let e = refused(&o, &out);
        assert!(e.contains(said), "{e}");
    }
}

/// The paper's start is unbounded: on noisy data it took `PKY1` to about
/// −1.9e7 and wrote a `.tir` that every command refuses.
#[test]
fn an_mf_fit_beyond_any_tyre_is_refused_before_its_file_is_written() {
    let mut rig = String::from("fz,alpha,fy,mz\n");
    let mut i = 0.0_f64;
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin() + 30.0 * (45.1 * i).sin();
            let mz = 0.02 * fy + (45.1 * i + 1.0).sin();
            rig += &format!("{fz},{alpha},{fy:.3},{mz:.4}\n");
            i += 1.0;
        }
    }
    let dir = scratch(&[("rig.csv", &rig)]);
    let out = dir.path().join("m.tir");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "mf61",
        "--start",
        "paper",
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(e.contains("error: the fit took `PKY1` = -"), "{e}");
    assert!(
        e.contains("must lie within ±1000000: no coefficient of a published Magic Formula file reaches ±1e6"),
        "{e}"
    );
    assert!(
        e.contains("no file is written, as every command would refuse it (the default start, `--start data`, keeps each coefficient within physical bounds)"),
        "{e}"
    );
    assert!(!out.with_extension("report.json").exists());
}

/// A lock of bytes that are no text was read as no text at all and
/// reported as "empty".
#[test]
fn a_lock_of_bytes_that_are_not_text_is_not_called_empty() {
    let dir = scenario(VEHICLE, GIM, STEP);
    let out = dir.path().join("out");
    fs::create_dir(&out).unwrap();
    let lock = out.join(".handling.lock");
    fs::write(&lock, [0xff, 0xfe, 0x00, 0x9c]).unwrap();
    let then = std::time::SystemTime::now() - std::time::Duration::from_secs(60);
    fs::File::options()
        .write(true)
        .open(&lock)
        .unwrap()
        .set_modified(then)
        .unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains(".handling.lock names no process (4 bytes that are not text) and is 60 s old; taking the folder over"),
        "{e}"
    );
    assert!(!e.contains("is empty"), "{e}");
}

/// A written `.tir` held `1e0`, `4e3` and `0e0` for 1, 4000 and 0: each
/// value is now the shortest text that reads back as the fitted value.
#[test]
fn a_written_tir_holds_each_value_exactly_without_exponent_noise() {
    let mut rig = String::from("fz,alpha,fy,mz\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * (1.4 * (12.0 * alpha).atan()).sin();
            rig += &format!("{fz},{alpha},{fy:.3},{:.4}\n", 0.02 * fy);
        }
    }
    let dir = scratch(&[("rig.csv", &rig)]);
    let out = dir.path().join("m.tir");
    let o = identify_to(&dir.path().join("rig.csv"), "mf61", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let tir = fs::read_to_string(&out).unwrap();
    let value = |key: &str| -> String {
        let line = tir
            .lines()
            .find(|l| l.split_whitespace().next() == Some(key))
            .unwrap_or_else(|| panic!("{key} in {tir}"));
        line.split('=').nth(1).unwrap().trim().to_string()
    };
    assert_eq!(value("FNOMIN"), "4000");
    assert_eq!(value("LFZO"), "1");
    assert_eq!(value("QSY1"), "0");
    let coefficients = tir.lines().skip_while(|l| *l != "[COEFFICIENTS]").skip(1);
    for line in coefficients.filter(|l| !l.starts_with(['$', '['])) {
        let Some((_, v)) = line.split_once('=') else {
            continue;
        };
        let v = v.trim();
        assert!(v.len() <= 24, "{line}");
        if let Ok(x) = v.parse::<f64>() {
            assert!(!v.ends_with("e0"), "{line}");
            assert_eq!(crate_exact(x), v, "{line}");
        }
    }
    // Every fitted coefficient reads back as the report's value, bit for bit.
    let report = read_json(&out.with_extension("report.json"));
    let mut checked = 0;
    for s in report["stages"].as_array().unwrap() {
        for p in s["parameters"].as_array().unwrap() {
            let name = p["name"].as_str().unwrap();
            let written: f64 = value(name).parse().unwrap();
            assert_eq!(written, p["value"].as_f64().unwrap(), "{name}");
            checked += 1;
        }
    }
    assert!(checked > 20, "{checked}");
}

/// The writer's rule, restated: plain decimals from 1e-4 to below 1e9,
/// an exponent beyond, 0 as `0`.
fn crate_exact(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if (1e-4..1e9).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}
