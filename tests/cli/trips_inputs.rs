//! More of what a new user trips on in input files, run as a user runs
//! the tool: manoeuvre values no road test has, CSV files written on
//! Windows, mistyped kinds and tyre arrays of the wrong type or length.

use super::*;

/// A `[manoeuvre]` table of `kind` with `rest` after its `kind` line (so
/// the key after `kind` sits on line 15 of the scenario).
fn manoeuvre(kind: &str, rest: &str) -> String {
    format!("[manoeuvre]\nkind = \"{kind}\"\n{rest}")
}

/// The refusal of `simulate` on a scenario with the manoeuvre `m`.
fn refused_manoeuvre(m: &str) -> String {
    let dir = scenario(VEHICLE, GIM, m);
    simulate_err(dir.path())
}

/// The step steer's speed limit held only for step steers: a sine at
/// 1e308 m/s hung, a sweep or ramp at 1000 m/s ran.
#[test]
fn an_absurd_speed_is_refused_for_every_manoeuvre_kind() {
    let kinds = [
        ("sine", "amplitude = 0.02\nfrequency = 1.0\nend = 5.0\n"),
        ("ramp-steer", "rate = 0.01\nend = 5.0\n"),
        (
            "sweep",
            "amplitude = 0.02\nf_start = 0.1\nf_end = 2.0\nend = 5.0\n",
        ),
    ];
    for (kind, rest) in kinds {
        for speed in ["1000", "1e308"] {
            let e = refused_manoeuvre(&manoeuvre(kind, &format!("speed = {speed}\n{rest}")));
            assert!(
                e.contains(&format!("scenario.toml:15:9: `manoeuvre.speed` = {speed}: must lie in (0.5, 150]: the model evaluates no speed below 0.5 m/s")),
                "{kind}: {e}"
            );
        }
    }
}

/// A sine of 1 MHz or a sweep to 1 kHz ran (20 million steps): a steer
/// frequency above 50 Hz is refused at its key and line.
#[test]
fn a_steer_frequency_above_50_hz_is_refused_at_its_key() {
    let cases = [
        (
            "sine",
            "speed = 20\namplitude = 0.02\nfrequency = 1e6\nend = 5.0\n",
            "scenario.toml:17:13: `manoeuvre.frequency` = 1000000: must lie in (0, 50]",
        ),
        (
            "sweep",
            "speed = 20\namplitude = 0.02\nf_start = 0\nf_end = 1000\nend = 5.0\n",
            "scenario.toml:18:9: `manoeuvre.f_end` = 1000: must lie in (0, 50]",
        ),
        (
            "sweep",
            "speed = 20\namplitude = 0.02\nf_start = 60\nf_end = 10\nend = 5.0\n",
            "scenario.toml:17:11: `manoeuvre.f_start` = 60: must lie in [0, 50]",
        ),
    ];
    for (kind, rest, said) in cases {
        let e = refused_manoeuvre(&manoeuvre(kind, rest));
        assert!(e.contains(said), "{e}");
        assert!(
            e.contains("no handling manoeuvre steers faster than 50 Hz"),
            "{e}"
        );
    }
}

/// A ramp of 0.7 rad/s from 1 s to 6 s reaches 3.5 rad: the refusal named
/// the rate against the ±45° steer limit and asked whether 0.7 was in
/// degrees. It names the steer reached by `end`, and asks about degrees
/// only for a rate that passes the limit within a second.
#[test]
fn a_ramp_steer_run_too_long_is_refused_naming_the_steer_it_reaches() {
    let ramp = |rate: &str| {
        refused_manoeuvre(&manoeuvre(
            "ramp-steer",
            &format!("speed = 20\nrate = {rate}\nstart = 1\nend = 6\n"),
        ))
    };
    let e = ramp("0.7");
    assert!(
        e.contains("scenario.toml:16:8: `manoeuvre.rate` = 0.7: the ramp reaches 3.5 rad (201°) by `end` = 6 s, beyond ±45°"),
        "{e}"
    );
    assert!(e.contains("lower `rate` or end the run sooner"), "{e}");
    assert!(!e.contains("degrees"), "{e}");
    let e = ramp("5");
    assert!(e.contains("the ramp reaches 25 rad"), "{e}");
    assert!(e.contains("is the rate in degrees per second?"), "{e}");
}

/// `kind = "step_stear"` got serde's bare "unknown variant"; every other
/// mistyped name is answered with the nearest one.
#[test]
fn a_mistyped_manoeuvre_kind_is_answered_with_the_nearest_name() {
    let e = refused_manoeuvre(&manoeuvre("step_stear", "speed = 20\nsteer = 0.02\n"));
    assert!(
        e.contains("scenario.toml:14:8: `manoeuvre.kind`: unknown variant `step_stear` (did you mean `step_steer`?)"),
        "{e}"
    );
}

/// `start = 1970-01-01` (a TOML date) was put at the `[manoeuvre]` header
/// as "invalid type: map, expected f64", naming no key; it is put at the
/// value, as every other wrong value is, in a TOML writer's words.
#[test]
fn a_date_where_a_number_is_meant_is_refused_at_its_key() {
    let e = refused_manoeuvre(&manoeuvre(
        "step-steer",
        "speed = 20\nsteer = 0.02\nstart = 1970-01-01\n",
    ));
    assert!(
        e.contains("scenario.toml:17:9: `manoeuvre.start`: invalid type: a date, time or table, expected a number"),
        "{e}"
    );
}

/// `form = 1` in a PAC89 file said "invalid type: unit variant, expected
/// string only" with no key or line; a misspelt form had no line either.
#[test]
fn a_pac89_form_of_the_wrong_type_or_name_is_refused_at_its_key() {
    let text = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    let cases = [
        (
            "form = 1",
            "tyre.toml:7:8: `form`: invalid type: integer `1`, expected a string",
        ),
        (
            "form = \"adams-pac98\"",
            "tyre.toml:7:8: `form`: unknown variant `adams-pac98` (did you mean `adams-pac89`?)",
        ),
    ];
    for (form, said) in cases {
        let tyre = text.replace("form = \"adams-pac89\"", form);
        let dir = scratch(&[
            ("tyre.toml", &tyre),
            (
                "points.csv",
                "fz,kappa,alpha,camber,speed\n4000,0,0.01,0,20\n",
            ),
        ]);
        let out = dir.path().join("out.csv");
        let o = run(&[
            "tyre-eval",
            dir.path().join("tyre.toml").to_str().unwrap(),
            dir.path().join("points.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(e.contains(said), "{e}");
    }
}

/// The bundled PAC89 file with its `a = [...]` line replaced by `a`.
fn pac89_with_a(a: &str) -> String {
    let text = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    text.lines()
        .map(|l| if l.starts_with("a = ") { a } else { l })
        .collect::<Vec<_>>()
        .join("\n")
}

/// A string among a tyre's coefficients said `invalid type: string
/// "1.65", expected f64` with no key or line; one element too many said
/// "expected fewer elements in array".
#[test]
fn a_tyre_array_of_the_wrong_type_or_length_is_refused_at_its_key_with_its_length() {
    let good = "a = [1.65, -34.0, 1250.0, 3036.0, 12.8, 0.00501, -0.02103, 0.77394, 0.002289, 0.013442, 0.003709, 19.1656, 1.21356, 6.26206]";
    let cases = [
        (
            good.replace("[1.65,", "[\"1.65\","),
            "tyre.toml:8:6: `a[0]`: invalid type: string \"1.65\", expected a number",
        ),
        (
            good.replace("[1.65,", "[1.65, 9.0,"),
            "tyre.toml:8:5: `a`: invalid length 15, expected an array of length 14",
        ),
        (
            good.replace("[1.65, -34.0,", "[1.65,"),
            "tyre.toml:8:5: `a`: invalid length 13, expected an array of length 14",
        ),
    ];
    for (a, said) in cases {
        let dir = scratch(&[
            ("tyre.toml", &pac89_with_a(&a)),
            (
                "points.csv",
                "fz,kappa,alpha,camber,speed\n4000,0,0.01,0,20\n",
            ),
        ]);
        let out = dir.path().join("out.csv");
        let o = run(&[
            "tyre-eval",
            dir.path().join("tyre.toml").to_str().unwrap(),
            dir.path().join("points.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(e.contains(said), "{e}");
    }
}

/// With CRLF line endings every CSV reader put an error one line short: a
/// NaN on line 3 on line 2, a bad first row on the header's line 1.
#[test]
fn a_crlf_csv_reports_the_true_line() {
    for ending in ["\n", "\r\n"] {
        let csv = |lines: &[&str]| lines.join(ending) + ending;
        let dir = scratch(&[
            (
                "run.csv",
                &csv(&[
                    "# a comment",
                    "t,speed,steer,yaw_rate,ay",
                    "0,20,0,0,0",
                    "0.01,20,NaN,0,0",
                ]),
            ),
            ("rig.csv", &csv(&["fz,alpha,fy", "4000,x,800"])),
            (
                "points.csv",
                &csv(&[
                    "fz,kappa,alpha,camber,speed",
                    "4000,0,0.01,0,20",
                    "4000,0,0.01,0",
                ]),
            ),
        ]);
        let p = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
        let e = stderr(&run(&["metrics", &p("run.csv")]));
        assert!(e.contains("run.csv:4:3: column `steer`"), "{ending:?}: {e}");
        let out = dir.path().join("t.toml");
        let e = refused(&identify_to(&dir.path().join("rig.csv"), "gim", &out), &out);
        assert!(e.contains("rig.csv:2:2: column `alpha`"), "{ending:?}: {e}");
        let out = dir.path().join("out.csv");
        let o = run(&[
            "tyre-eval",
            "tyres/gim.toml",
            &p("points.csv"),
            "--out",
            out.to_str().unwrap(),
        ]);
        let e = refused(&o, &out);
        assert!(
            e.contains("points.csv:3:1: malformed CSV row: found a record with 4 fields, but the previous record has 5"),
            "{ending:?}: {e}"
        );
    }
}

/// `speed = "fast"` said `expected f64`, `vehicle = 3` said `expected struct
/// Vehicle` and `kind = 3` said `expected variant identifier` without the
/// kinds: serde's words, not a TOML writer's.
#[test]
fn a_value_of_the_wrong_type_is_answered_in_a_toml_writers_words() {
    let kinds = "expected one of `step-steer`, `step_steer`, `ramp-steer`, `ramp_steer`, `sine`, `sweep`, `replay`, `schedule`";
    let e = refused_manoeuvre("[manoeuvre]\nkind = 3\n");
    assert!(
        e.contains(&format!(
            "`manoeuvre.kind`: invalid type: integer `3`, {kinds}"
        )),
        "{e}"
    );
    let e = refused_manoeuvre(&manoeuvre("step-steer", "speed = \"fast\"\nsteer = 0.02\n"));
    assert!(
        e.contains("`manoeuvre.speed`: invalid type: string \"fast\", expected a number"),
        "{e}"
    );
    let dir = scenario(
        &format!(
            "vehicle = 3\n{}",
            VEHICLE.replace("[vehicle]", "[not_vehicle]")
        ),
        GIM,
        &manoeuvre("step-steer", "speed = 20\nsteer = 0.02\n"),
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains(":1:11: `vehicle`: invalid type: integer `3`, expected a table"),
        "{e}"
    );
}
