//! What a fresh user tripped on in `diagnose`'s overlays and `identify`'s
//! selected conditions (session 83): the overlays drew each replay's start
//! transient, which the gap scan leaves out (a step's ay lines starting at
//! −0.4 m/s² where the measurement reads 0; a banked piece's "with
//! bank_profile" line jumping from 0 to −3.3 m/s²); a load level selected
//! from the Hoosier file was written with the nominal of the whole level
//! (1656 N) where its samples fitted read 1640 N.

use super::*;

/// One row of `overlays.csv`: run, channel, series, t, value.
struct Drawn {
    run: String,
    channel: String,
    series: String,
    t: f64,
    value: f64,
}

/// The rows of the `overlays.csv` in `out`.
fn overlay_rows(out: &Path) -> Vec<Drawn> {
    let text = fs::read_to_string(out.join("overlays.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("run,channel,series,t,value"));
    lines
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            Drawn {
                run: c[0].into(),
                channel: c[1].into(),
                series: c[2].into(),
                t: c[3].parse().unwrap(),
                value: c[4].parse().unwrap(),
            }
        })
        .collect()
}

/// The first row of `series` in the panel of `run`'s `channel`.
fn first<'a>(rows: &'a [Drawn], run: &str, channel: &str, series: &str) -> &'a Drawn {
    rows.iter()
        .find(|r| r.run == run && r.channel == channel && r.series == series)
        .unwrap_or_else(|| panic!("no {series} in {run} {channel}"))
}

/// Every panel's model lines start at or after the scored span's start,
/// half a second (the gap scan's first window) past the panel's first
/// measured sample; its measured dots start at that sample. A run without
/// a sideslip channel is not scored over that half second (its replay
/// starts at a sideslip of 0), so its dots start where its lines do.
fn models_start_in_the_scored_span(rows: &[Drawn], models: &[&str], sideslip_logged: bool) {
    let lead = if sideslip_logged { 0.5 } else { 0.0 };
    let mut panels: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r.run.as_str(), r.channel.as_str()))
        .collect();
    panels.dedup();
    assert!(panels.len() >= 4, "{panels:?}");
    for (run, channel) in panels {
        let t0 = first(rows, run, channel, "measured").t;
        for model in models {
            let m = first(rows, run, channel, model);
            assert!(
                m.t >= t0 + lead - 1e-9 && m.t < t0 + lead + 0.05,
                "{run} {channel} {model}: first drawn at {} s, the run at {t0} s",
                m.t
            );
        }
    }
}

/// `diagnose campaigns/synthetic.toml`'s campaign (sensor delay, seed 1):
/// overlays.png's step_040kph_3ms2 ay panel had both model lines start
/// near −0.4 m/s² at t = 3 s, where the measurement reads 0. The figure's
/// data (`overlays.csv`) now start the models at 3.52 s, the first sample
/// of the scored span, within 0.01 m/s² of 0.
#[test]
fn the_overlays_leave_out_a_replays_start_transient() {
    let dir = tempfile::tempdir().unwrap();
    let (said, _, _) = narrowed(dir.path(), "sensor_delay", "\"sensor_delay\"");
    assert!(said.contains("/overlays.csv, "), "{said}");
    let rows = overlay_rows(&dir.path().join("out"));
    let models = ["base model", "with sensor_delay"];
    models_start_in_the_scored_span(&rows, &models, true);
    let run = "step_040kph_3ms2.csv";
    assert_eq!(first(&rows, run, "ay", "measured").t, 3.0);
    for model in models {
        let m = first(&rows, run, "ay", model);
        assert!((m.t - 3.52).abs() < 1e-9, "{model}: {}", m.t);
        assert!(m.value.abs() < 0.01, "{model}: {}", m.value);
    }
}

/// `synth --programme oval --effects bank_profile --seed 2`, diagnosed:
/// the second piece of the stop on the banking (from 64.96 s, its ay
/// −3.33 m/s²) had its "with bank_profile" line start at 0 and jump to
/// −3.3. It now starts at 65.48 s on the measurement's level.
#[test]
fn a_banked_pieces_overlay_starts_on_the_measurement() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "--programme",
        "oval",
        "--effects",
        "bank_profile",
        "--seed",
        "2",
    ];
    let campaign = synth_campaign(dir.path(), "oval", &args);
    let vehicle = campaign.join("vehicle.toml");
    let text = fs::read_to_string(&vehicle).unwrap();
    fs::write(&vehicle, format!("{text}effects = [\"bank_profile\"]\n")).unwrap();
    let out = dir.path().join("out");
    let (_, d) = diagnose_to(&campaign, &out);
    assert_eq!(
        d["verdict"]["effects"][0], "bank_profile",
        "{}",
        d["verdict"]
    );
    let rows = overlay_rows(&out);
    models_start_in_the_scored_span(&rows, &["base model", "with bank_profile"], false);
    let run = "oval_stop_on_banking.csv#2";
    // The piece starts at 64.96 s; without a sideslip channel its first
    // half second is not scored, and its dots start with the lines.
    let measured = first(&rows, run, "ay", "measured");
    assert!((measured.t - 65.48).abs() < 1e-9, "{}", measured.t);
    let with = first(&rows, run, "ay", "with bank_profile");
    assert!((with.t - 65.48).abs() < 1e-9, "{}", with.t);
    assert!((with.value + 3.28).abs() < 0.05, "{}", with.value);
}

/// The Hoosier file's samples at 1656 N, 0° and 83.4 kPa written to a file
/// of their own (the level's band of each variable): 1249 samples.
fn hoosier_subset(full: &Path, to: &Path) {
    let text = fs::read_to_string(full).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let names: Vec<&str> = header.split(',').collect();
    let col = |n: &str| names.iter().position(|h| *h == n).unwrap();
    let (fz, camber, pressure) = (col("fz"), col("camber"), col("pressure"));
    let mut out = format!("{header}\n");
    for line in lines {
        let c: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
        if (1400.0..1900.0).contains(&c[fz])
            && c[camber].abs() < 0.5f64.to_radians()
            && (81_000.0..86_000.0).contains(&c[pressure])
        {
            out += line;
            out.push('\n');
        }
    }
    fs::write(to, out).unwrap();
}

/// `identify cornering.csv --load 1650 --pressure 83400 --camber 0` read
/// "Fz 1656 N" and wrote reference_load = 1656.0, the median of the 1656 N
/// level over every camber and pressure of the file; the same 1249 samples
/// alone read 1640 N. Now both write 1639.7, each line naming the level
/// of the file it read.
#[test]
fn a_selected_condition_takes_its_load_from_the_samples_fitted() {
    let test = "a_selected_condition_takes_its_load_from_the_samples_fitted";
    let Some(full) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let subset = dir.path().join("subset.csv");
    hoosier_subset(&full, &subset);
    let fit = |data: &Path, name: &str, select: &[&str]| {
        let tyre = dir.path().join(name);
        let mut args = vec!["identify", data.to_str().unwrap(), "--model", "gim"];
        args.extend(select);
        args.extend(["--out", tyre.to_str().unwrap()]);
        let said = succeeds(&args);
        (said, fs::read_to_string(tyre).unwrap())
    };
    let select = ["--load", "1650", "--pressure", "83400", "--camber", "0"];
    let (said_full, tyre_full) = fit(&full, "full.toml", &select);
    let (said_subset, tyre_subset) = fit(&subset, "subset.toml", &[]);
    // The condition's line names its level as every output does: by the
    // median of every sample of the level in the file read (the whole
    // file's 1656 N level; the subset's own level, its 1249 samples).
    for (said, tyre, level) in [
        (&said_full, &tyre_full, 1656),
        (&said_subset, &tyre_subset, 1640),
    ] {
        assert!(said.contains(": 1249 used in conditions"), "{said}");
        assert!(
            said.contains(&format!(
                "Fz    {level} N, camber  0.00°, pressure 83.4 kPa:   79 points"
            )),
            "{said}"
        );
        assert!(tyre.contains("\nreference_load = 1639.7\n"), "{tyre}");
    }
    // The level selected is still named by the file's nominal.
    assert!(
        said_full.contains(
            "fz 1650 N asked for: the 1656 N level selected (its samples 1474 N to 1823 N)"
        ),
        "{said_full}"
    );
}
