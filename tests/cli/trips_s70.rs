//! Campaign keys that are accepted but cannot mean what they say: a
//! channel uncertainty larger than the channel's whole signal, and a
//! residual rate too low to see a car respond, are refused at their key;
//! an uncertainty the channel's own scatter contradicts, a segment longer
//! than every run and a residual rate above the logs' are noted where the
//! diagnosis is read.

use super::*;
use std::fs;

/// A `[channels]` uncertainty of 30 rad/s on runs whose yaw rate has an
/// RMS of 0.15 rad/s carries nothing: refused at its line, with the signal.
#[test]
fn an_uncertainty_above_the_channels_whole_signal_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    let text = text.replacen("[tyres]", "[channels]\nyaw_rate = 30\n\n[tyres]", 1);
    let line = text.lines().position(|l| l == "yaw_rate = 30").unwrap() + 1;
    fs::write(&v, text).unwrap();
    let o = run(&["diagnose", c.to_str().unwrap()]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains(&format!("vehicle.toml:{line}:12: `channels.yaw_rate` = 30: is at least the channel's RMS signal over the runs (0.1")),
        "{e}"
    );
    assert!(e.contains("good to about 0.0017 rad/s"), "{e}");
}

/// Residuals at 0.001 Hz (one per run, or none) miss every response:
/// refused at the key, with the range.
#[test]
fn a_residual_rate_too_low_to_see_a_cars_response_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap() + "sample_rate = 0.001\n";
    let line = text.lines().count();
    fs::write(&v, text).unwrap();
    let o = run(&["diagnose", c.to_str().unwrap()]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains(&format!(
            "vehicle.toml:{line}:15: `diagnose.sample_rate` = 0.001: must be greater than 4"
        )),
        "{e}"
    );
}

/// A yaw rate stated to 1e-7 rad/s where the gyro scatters by 0.003 from
/// sample to sample, `segment = 1e9` on 21 s runs and residuals at 1e9 Hz
/// on 100 Hz logs: diagnosed as stated, each said in the terminal and the
/// report.
#[test]
fn a_stated_uncertainty_below_the_channels_scatter_and_a_segment_that_cuts_nothing_are_noted() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap().replacen(
        "[tyres]",
        "[runs]\ndir = \"runs\"\nsegment = 1e9\n\n[channels]\nyaw_rate = 1e-7\n\n[tyres]",
        1,
    ) + "effects = [\"sensor_delay\"]\nmax_effects = 1\nsample_rate = 1e9\n";
    fs::write(&v, text).unwrap();
    let (stdout, d) = diagnose_campaign(&c);
    let notes: Vec<&str> = d["notes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    let segment = notes
        .iter()
        .find(|n| n.starts_with("segment = "))
        .unwrap_or_else(|| panic!("{notes:?}"));
    assert!(
        segment.contains("cut nothing: the longest piece lasts 21.0 s"),
        "{segment}"
    );
    let stated = notes
        .iter()
        .find(|n| n.starts_with("[channels] yaw_rate = 1e-7 rad/s"))
        .unwrap_or_else(|| panic!("{notes:?}"));
    // The scatter a MEMS gyro shows, and the ratio to what is stated.
    let scatter: f64 = stated
        .split("scatters by ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!((0.0017..0.01).contains(&scatter), "{stated}");
    // Weighted by the signal's share, not as stated: not said to dominate.
    assert!(
        stated.contains("it is weighted by") && stated.contains("% of the channel's RMS signal"),
        "{stated}"
    );
    // A residual rate above the logs' 100 Hz takes every sample.
    let rate = notes
        .iter()
        .find(|n| n.starts_with("sample_rate = "))
        .unwrap_or_else(|| panic!("{notes:?}"));
    assert!(
        rate.contains("above the runs' own rates (at most 100 Hz): every sample is a residual"),
        "{rate}"
    );
    for n in [segment, stated, rate] {
        assert!(stdout.contains(&format!("note: {n}")), "{stdout}");
    }
}

/// The bundled sedan's 1° step on roads of friction 1e-9 and 0.1 reached
/// μ·g and gave response times and an Er better than the car's own (0.0487
/// s against 0.1251 s) without a word: the friction limit is said, and a
/// sideslip that rounds to zero is printed without a sign.
#[test]
fn a_step_steer_held_at_the_friction_limit_is_said_to_measure_the_limit() {
    const AT_LIMIT: &str = "the car turns at its friction limit, so the response times, the yaw-rate gain and Er describe that limit";
    let (said, _) = super::trips_s69::sedan_on(None);
    assert!(!said.contains(AT_LIMIT), "{said}");
    for (mu, written) in [(1e-9, "1e-9"), (0.1, "0.1")] {
        let (said, m) = super::trips_s69::sedan_on(Some(mu));
        let warned = said
            .lines()
            .find(|l| l.contains(AT_LIMIT))
            .unwrap_or_else(|| panic!("μ = {mu}: {said}"));
        assert!(
            warned.contains(&format!("on a road of friction {written}")),
            "{warned}"
        );
        let ay = m["ay_steady"].as_f64().unwrap().abs();
        assert!((ay / (mu * 9.80665) - 1.0).abs() < 0.02, "{m}");
        assert!(!said.contains("-0.0000"), "{said}");
    }
}

/// The proving ground's rig data with `fy` in kN beside `fz` in N fitted
/// to a tyre of friction 0.001 and was written with "σ 3.7 %": refused at
/// the row of its largest force, with the unit named; scaled by 1e-9 the
/// question is the scale.
#[test]
fn rig_forces_a_thousand_times_too_small_are_refused_as_kilonewtons() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let text = fs::read_to_string(c.join("tyre_rig.csv")).unwrap();
    for (scale, asked) in [
        (1e-3, "is the column in kN? multiply it by 1000"),
        (1e-9, "is the column scaled, or in another unit?"),
    ] {
        let mut rows = text.lines();
        let mut out = vec![rows.next().unwrap().to_string()];
        out.extend(rows.map(|r| {
            let v: Vec<f64> = r.split(',').map(|x| x.parse().unwrap()).collect();
            format!("{},{},{}", v[0], v[1], v[2] * scale)
        }));
        let rig = dir.path().join(format!("rig_{scale}.csv"));
        fs::write(&rig, out.join("\n") + "\n").unwrap();
        let o = identify_to(&rig, "magic-simple", &dir.path().join("t.toml"));
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(e.contains(&format!("rig_{scale}.csv:")), "{e}");
        assert!(
            e.contains("column `fy`: its largest force") && e.contains(asked),
            "{e}"
        );
        assert!(!dir.path().join("t_magic-simple.toml").exists());
    }
}

/// MFeval's loaded radius at a load far past `FZMAX` (1 MN on the public
/// FSAE tyre) is 2.39 m, ten times the free radius: written as MFeval
/// gave it, and said, with the first point; refused at its row since
/// (session 104: its effective rolling radius has fallen through 0, and
/// the radius is no tyre's). 30 kN, past FZMAX too, is still evaluated
/// (100 kN was, until session 107: it puts the tyre on its rim at 35.5 kN).
#[test]
fn a_loaded_radius_above_the_free_radius_is_said() {
    let Some(tir) = shared_data(
        "a_loaded_radius_above_the_free_radius_is_said",
        "tir_public/fsae190_50R10.tir",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.csv");
    fs::write(
        &points,
        "fz,kappa,alpha,camber,speed\n1000,0,0,0,16.7\n30000,0,0,0,16.7\n999999,0,0,0,16.7\n",
    )
    .unwrap();
    let out = dir.path().join("f.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let said = stderr(&o);
    assert!(!o.status.success(), "{said}");
    assert!(
        said.contains("p.csv:4:1: fz = 999999 N is more than the tyre's vertical model carries: its effective rolling radius Re")
            && said.contains("(rl 2.386 m against a free radius of"),
        "{said}"
    );
    assert!(
        !said.contains("p.csv:3:") && !said.contains("p.csv:2:"),
        "{said}"
    );
    fs::write(
        &points,
        "fz,kappa,alpha,camber,speed\n1000,0,0,0,16.7\n30000,0,0,0,16.7\n",
    )
    .unwrap();
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rl: Vec<f64> = fs::read_to_string(&out)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
        .collect();
    assert!(rl[0] < 0.2332 && rl[1] < 0.2332, "{rl:?}");
}
