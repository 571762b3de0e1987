//! Bad input in a TOML file, refused at the line and column of what is
//! wrong and in plain words: a key one manoeuvre kind names another way,
//! a step steer given both amplitudes, text after a value on its line, a
//! wrong element of a campaign's prior range, a key in the wrong table.

use super::*;

/// The bundled GB/T 6323 scenario, with its tyre file at the same relative
/// path (`../tyres/`), written to `scenarios/<name>.toml` of a fresh folder
/// after `edit`; the refusal of `simulate` on it.
fn refused_bundled(name: &str, edit: &dyn Fn(&str) -> String) -> String {
    let dir = tempfile::tempdir().unwrap();
    for sub in ["scenarios", "tyres"] {
        fs::create_dir(dir.path().join(sub)).unwrap();
    }
    let tyre = "tyres/pac89_adams_example.toml";
    fs::copy(root().join(tyre), dir.path().join(tyre)).unwrap();
    let text = fs::read_to_string(root().join("scenarios/step_gbt6323_pac89.toml")).unwrap();
    let file = dir.path().join(format!("scenarios/{name}.toml"));
    fs::write(&file, edit(&text)).unwrap();
    fails_cleanly("simulate", &file, dir.path())
}

/// The bundled scenario with its step steer (lines 25–31) replaced by a
/// manoeuvre of `kind` whose keys after `kind` are `keys`, from line 27.
fn with_manoeuvre(text: &str, kind: &str, keys: &str) -> String {
    let at = text.find("[manoeuvre]").unwrap();
    let end = text.find("[simulation]").unwrap();
    format!(
        "{}[manoeuvre]\nkind = \"{kind}\"\n{keys}\n{}",
        &text[..at],
        &text[end..]
    )
}

/// A sine written with a step steer's `steer` was put at the `[manoeuvre]`
/// header and answered "did you mean `speed`?". It is put at the key, and
/// a key another kind gives the same quantity is answered with this kind's
/// name for it; a misspelling, with the nearest name.
#[test]
fn a_key_another_manoeuvre_kind_uses_is_answered_at_the_key_with_this_kinds_name() {
    let cases = [
        (
            "sine",
            "speed = 20.0\nsteer = 0.02\nfrequency = 1.0\nend = 5.0",
            "sine.toml:28:1: `manoeuvre.steer`: unknown field `steer` (did you mean `amplitude`?)",
        ),
        (
            "ramp-steer",
            "speed = 20.0\nsteer = 0.02\nend = 5.0",
            "ramp-steer.toml:28:1: `manoeuvre.steer`: unknown field `steer` (did you mean `rate`?)",
        ),
        (
            "step-steer",
            "speed = 20.0\namplitude = 0.02",
            "step-steer.toml:28:1: `manoeuvre.amplitude`: unknown field `amplitude` (did you mean `steer`?)",
        ),
        (
            "sweep",
            "speed = 20.0\namplitude = 0.02\nfrequency = 1.0\nend = 5.0",
            "sweep.toml:29:1: `manoeuvre.frequency`: unknown field `frequency` (did you mean `f_start` or `f_end`?)",
        ),
    ];
    for (kind, keys, said) in cases {
        let e = refused_bundled(kind, &|t| with_manoeuvre(t, kind, keys));
        assert!(e.contains(said), "{e}");
        assert!(!e.contains("did you mean `speed`"), "{e}");
    }
    let e = refused_bundled("typo", &|t| {
        with_manoeuvre(t, "sine", "speed = 20.0\namplitud = 0.02\nfrequency = 1.0")
    });
    assert!(
        e.contains("typo.toml:28:1: `manoeuvre.amplitud`: unknown field `amplitud` (did you mean `amplitude`?)"),
        "{e}"
    );
}

/// A step steer given both `steer` and `lateral_acceleration` was refused
/// at its `kind`, as one given neither is. Both: at the later of the two,
/// whichever it is, saying both are given; neither: at `kind`, saying so.
#[test]
fn a_step_steer_given_both_amplitudes_is_refused_at_the_second() {
    // The lateral acceleration's line of the bundled file, made two lines.
    let both = |name: &str, first: &str, second: &str| {
        let two = format!("{first}\n{second}");
        refused_bundled(name, &|t| {
            t.replace("lateral_acceleration = 2.0    # m/s²", &two)
        })
    };
    let e = both("both", "steer = 0.02", "lateral_acceleration = 2.0");
    assert!(
        e.contains("both.toml:29:24: `manoeuvre.lateral_acceleration` = 2: a step steer takes one of `steer` (rad) and `lateral_acceleration` (m/s²), and both are given"),
        "{e}"
    );
    assert!(!e.contains("manoeuvre.kind"), "{e}");
    let e = both("swapped", "lateral_acceleration = 2.0", "steer = 0.02");
    assert!(
        e.contains("swapped.toml:29:9: `manoeuvre.steer` = 0.02: a step steer takes one of"),
        "{e}"
    );
    let e = refused_bundled("neither", &|t| {
        t.replace("lateral_acceleration = 2.0    # m/s²\n", "")
    });
    assert!(
        e.contains("neither.toml:26:8: `manoeuvre.kind`: a step steer needs one of `steer` (rad) and `lateral_acceleration` (m/s²), and neither is given"),
        "{e}"
    );
}

/// `a = 1.11,` said toml's "expected newline, `#`". Whatever follows a
/// value on its line (a comma, a second key, a number), or a table header,
/// is named at its column, with what a line holds.
#[test]
fn text_after_a_value_on_its_line_is_named_in_plain_words() {
    let value = "TOML takes one `key = value` per line, and after the value only a `# comment`";
    let cases = [
        (
            "comma",
            "a = 1.11,",
            "comma.toml:9:9: `vehicle.a`: unexpected `,`",
        ),
        (
            "key",
            "a = 1.11 b = 1.67",
            "key.toml:9:10: `vehicle.a`: unexpected `b`",
        ),
        (
            "number",
            "a = 1.11 2",
            "number.toml:9:10: `vehicle.a`: unexpected `2`",
        ),
    ];
    for (name, line, said) in cases {
        let e = refused_bundled(name, &|t| t.replace("a = 1.11 ", line));
        assert!(
            e.contains(&format!("{said} after the value: {value}")),
            "{e}"
        );
        assert!(!e.contains("expected newline"), "{e}");
    }
    let e = refused_bundled("header", &|t| t.replace("[road]", "[road] friction"));
    assert!(
        e.contains("header.toml:18:8: unexpected `friction` after the table header: a `[table]` header stands alone on its line"),
        "{e}"
    );
}

/// `friction = [0.8, "1"]` in a campaign's `[tyres]` named
/// `tyres.friction`, not the element: it names `tyres.friction[1]` at the
/// string's column.
#[test]
fn a_string_in_a_prior_range_is_refused_at_its_element() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--programme", "slow-oval"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap() + "\n[tyres]\nfriction = [0.8, \"1\"]\n";
    fs::write(&v, &text).unwrap();
    let line = text
        .lines()
        .position(|l| l.starts_with("friction"))
        .unwrap()
        + 1;
    let out = dir.path().join("o");
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains(&format!(
            "vehicle.toml:{line}:18: `tyres.friction[1]`: invalid type: string \"1\", expected a number"
        )),
        "{e}"
    );
}

/// `step = 0.001` written under `[model]` was refused with `[model]`'s
/// keys and no word of where it goes. A key another table of the file
/// takes is sent there, from any table and from before the first header,
/// whether that table is written or not; `[integrator]`, another name of
/// `[simulation]`, is not named beside it; a key no table has gets no
/// home.
#[test]
fn a_key_of_another_table_is_refused_with_the_table_it_belongs_in() {
    let under_model = |t: &str| {
        t.replace(
            "load_transfer = true\n",
            "load_transfer = true\nstep = 0.001\n",
        )
    };
    let e = refused_bundled("model_step", &under_model);
    assert!(
        e.contains("model_step.toml:24:1: `model.step`: unknown field `step` (it belongs in [simulation]), expected one of `kinematics`, `load_transfer`, `effects`"),
        "{e}"
    );
    let e = refused_bundled("unwritten", &|t| {
        let t = under_model(t);
        t[..t.find("[simulation]").unwrap()].to_string()
    });
    assert!(
        e.contains(
            "unwritten.toml:24:1: `model.step`: unknown field `step` (it belongs in [simulation])"
        ),
        "{e}"
    );
    let e = refused_bundled("top", &|t| format!("step = 0.001\n{t}"));
    assert!(
        e.contains("top.toml:1:1: `step`: unknown field `step` (it belongs in [simulation]), expected one of `name`"),
        "{e}"
    );
    let e = refused_bundled("speed", &|t| t.replace("mass = ", "speed = 20.0\nmass = "));
    assert!(
        e.contains("`vehicle.speed`: unknown field `speed` (it belongs in [manoeuvre])"),
        "{e}"
    );
    let e = refused_bundled("friction", &|t| {
        t.replace("end = 6.0", "end = 6.0\nfriction = 0.8")
    });
    assert!(
        e.contains("`manoeuvre.friction`: unknown field `friction` (it belongs in [road])"),
        "{e}"
    );
    let e = refused_bundled("nowhere", &|t| {
        t.replace(
            "load_transfer = true\n",
            "load_transfer = true\nstride = 0.001\n",
        )
    });
    assert!(
        e.contains("`model.stride`: unknown field `stride`") && !e.contains("belongs"),
        "{e}"
    );
}
