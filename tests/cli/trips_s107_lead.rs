//! Round 39's findings the lead fixed: a held `PKY4` whose cornering
//! stiffness turns over inside the data's loads, written without a word;
//! a gap left in one run that the verdict's warning did not name; a
//! partial verdict's rest within the noise called unexplained.

use super::*;

/// Before: `identify rig205.csv --model mf61 --hold PKY4=-50` said only
/// "held: PKY4 = -50: given with --hold", reported pure Fy at σ 1.347 %
/// and wrote a tyre whose force at α = 0.005 rad turned over four times
/// between 2000 and 6000 N, its own FZMIN and FZMAX. Now it is refused,
/// nothing written, with the count, the loads and the fit's box for
/// PKY4; a held PKY4 inside that box is fitted and written.
#[test]
fn a_held_value_that_turns_the_cornering_stiffness_over_inside_the_loads_is_refused() {
    let test = "a_held_value_that_turns_the_cornering_stiffness_over_inside_the_loads_is_refused";
    let Some(tir) = shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig(&tir, dir.path());
    let out = dir.path().join("held.tir");
    let fit = |hold: &str| {
        run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            "mf61",
            "--hold",
            hold,
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let o = fit("PKY4=-50");
    assert!(!o.status.success());
    let said = stderr(&o);
    assert!(
        said.contains("the tyre fitted with --hold PKY4=-50 has a cornering stiffness"),
        "{said}"
    );
    let times = said
        .split("changes sign ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse::<usize>().ok())
        .unwrap_or_else(|| panic!("{said}"));
    assert!(times >= 2, "{said}");
    assert!(
        said.contains("over the data's loads, 2000 to 6000 N"),
        "{said}"
    );
    assert!(said.contains("no file is written"), "{said}");
    assert!(said.contains("PKY4 within 0.1 to 5"), "{said}");
    assert!(!out.exists());
    // car205's own PKY4 is 2: held there the stiffness keeps its sign.
    let o = fit("PKY4=2");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.exists());
}

/// Before: the synthetic campaign (`synth --effects sensor_delay --seed
/// 2`) with 0.02 rad/s added to one run's yaw rate: the verdict's warning
/// said "what it leaves is still a gap … yaw_rate carries 68 % of what it
/// leaves (an effect outside the library, the base model's own form, or
/// yaw_rate's sensor)", no run named, while `diagnosis.json`'s shrinkage
/// held that run at several noise floors and every other at one or two.
/// Now the warning names the run that carries the channel's gap left.
#[test]
fn a_gap_left_in_one_run_is_named_by_that_run_in_the_verdicts_warning() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "2"],
    );
    map_column(&c.join("runs/step_060kph_2ms2.csv"), "yaw_rate", |v| {
        v + 0.02
    });
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    let warnings: Vec<&str> = d["verdict"]["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    let rest = warnings
        .iter()
        .find(|w| w.starts_with("what it leaves is still a gap"))
        .unwrap_or_else(|| panic!("{warnings:?}\n{said}"));
    assert!(
        rest.contains("yaw_rate carries ")
            && rest.contains("step_060kph_2ms2.csv carries ")
            && rest.contains("of this channel's gap above noise left"),
        "{rest}"
    );
    assert!(!rest.contains("(an effect outside the library"), "{rest}");
    assert!(said.contains(rest), "{said}");
}

/// Before: two runs of the synthetic campaign (`synth --effects
/// sensor_delay --seed 2`): the delay came back at 0.0492 s of 0.05, and
/// the verdict said "explains part of the gap … the other 55.6 % no
/// candidate explains" with a held-out error left of 1.26 × the noise
/// level, where after most of a gap the same rest draws no warning (below
/// the 1.3 × a gap needs). Now that rest is "not shown to be a gap".
#[test]
fn a_rest_within_the_noise_of_a_partial_verdict_is_not_called_unexplained() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &["--effects", "sensor_delay", "--seed", "2"],
    );
    for f in fs::read_dir(c.join("runs")).unwrap() {
        let p = f.unwrap().path();
        let name = p.file_name().unwrap().to_str().unwrap().to_string();
        if name != "step_060kph_2ms2.csv" && name != "step_120kph_4ms2.csv" {
            fs::remove_file(p).unwrap();
        }
    }
    let (said, d) = diagnose_to(&c, &dir.path().join("out"));
    let v = &d["verdict"];
    let statement = v["statement"].as_str().unwrap_or_else(|| panic!("{v}"));
    let after = v["heldout_error_after"].as_f64().unwrap();
    let noise = v["noise_level"].as_f64().unwrap();
    assert!(
        statement.starts_with("sensor_delay explains part of the gap"),
        "{statement}"
    );
    // The closed rule: within 1.3 × the noise level, no gap shown.
    assert!(after <= 1.3 * noise, "{after} against {noise}");
    assert!(
        statement.contains("is not shown to be a gap: the held-out error left is ")
            && !statement.contains("no candidate explains"),
        "{statement}"
    );
    assert!(said.contains(statement), "{said}");
}
