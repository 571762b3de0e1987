//! Round 36 (finding 12): the diagnosis gave one channel two shares of
//! "the error". On the first 60 s of the Putnam log the terminal said
//! "yaw_rate carries 80 % of the base model's held-out error … it decides
//! every fit" and two lines later "combined error by channel …: yaw_rate
//! 94 % of the base model's J²": the first summed the base's held-out
//! errors with each steady offset aside, the second the parts table's
//! rows with the offsets counted. Now one computation gives each
//! channel's share of the held-out `J²` the verdict reads, with the part
//! its steady offset carries as a second number of the same row, and the
//! terminal, the page and diagnosis.json give the same share of the same
//! channel, "offset aside" and "offset counted" said together.

use super::*;

/// The synthetic campaign without effects (`synth --effects none`), its
/// logs edited as a logger's: ay read `ay_offset` m/s² high and the yaw
/// rate by a gyro whose gain is `gyro_gain`.
fn logger_campaign(dir: &Path, ay_offset: f64, gyro_gain: f64) -> PathBuf {
    let c = synth_campaign(dir, "logger", &["--effects", "none"]);
    for entry in fs::read_dir(c.join("runs")).unwrap() {
        let path = entry.unwrap().path();
        let text = fs::read_to_string(&path).unwrap();
        let mut lines = text.lines();
        let header = lines.next().unwrap();
        let names: Vec<&str> = header.split(',').collect();
        let at = |n: &str| names.iter().position(|h| *h == n).unwrap();
        let (yaw, ay) = (at("yaw_rate"), at("ay"));
        let mut out = format!("{header}\n");
        for line in lines {
            let mut cells: Vec<String> = line.split(',').map(str::to_string).collect();
            let value = |i: usize| cells[i].parse::<f64>().unwrap();
            let (r, a) = (value(yaw) * gyro_gain, value(ay) + ay_offset);
            (cells[yaw], cells[ay]) = (format!("{r:?}"), format!("{a:?}"));
            out += &(cells.join(",") + "\n");
        }
        fs::write(&path, out).unwrap();
    }
    c
}

/// The percent of key `key` in channel `ch`'s `gap.channel_shares` row.
fn share(d: &serde_json::Value, ch: &str, key: &str) -> f64 {
    let rows = d["gap"]["channel_shares"].as_array().unwrap();
    let row = rows
        .iter()
        .find(|r| r["channel"] == ch)
        .unwrap_or_else(|| panic!("no {ch} share: {}", d["gap"]["channel_shares"]));
    row[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no {key} of {ch}: {row}"))
}

/// A logger's ay offset of 0.5 m/s² (ten noise floors) and a yaw-rate gain
/// 15 % high: with ay's offset counted ay carries most of the base model's
/// held-out `J²`; with it aside the yaw rate does, and decides every fit.
/// The old terminal said "yaw_rate carries 94 %" on one line and
/// "ay 57 %, yaw_rate 42 %" on another, each of its own sum. Now the
/// shares are the JSON's `channel_shares` (counted, aside, the offset's
/// part), the dominant finding reads them, and the terminal and the page
/// say both numbers in one clause.
#[test]
fn a_channel_with_a_steady_offset_is_given_one_share_of_the_error_on_the_terminal_page_and_json() {
    let dir = tempfile::tempdir().unwrap();
    let c = logger_campaign(dir.path(), 0.5, 1.15);
    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    let page = fs::read_to_string(out.join("report.html"))
        .unwrap()
        .replace("&#39;", "'");
    let channels = ["yaw_rate", "ay", "beta"];
    let counted = channels.map(|ch| share(&d, ch, "before_percent"));
    let aside = channels.map(|ch| share(&d, ch, "before_offsets_aside_percent"));
    // Only ay has a steady offset, and it carries most of ay's part.
    let offset = share(&d, "ay", "offset_percent");
    assert!(offset > 0.8 * counted[1], "{}", d["gap"]["channel_shares"]);
    for ch in ["yaw_rate", "beta"] {
        let rows = d["gap"]["channel_shares"].as_array().unwrap();
        let row = rows.iter().find(|r| r["channel"] == ch).unwrap();
        assert!(row["offset_percent"].is_null(), "{row}");
    }
    // "Aside" is derived from the same rows: (counted − offset)/(100 − offset).
    for i in 0..3 {
        let own = counted[i] - if i == 1 { offset } else { 0.0 };
        assert!((aside[i] - 100.0 * own / (100.0 - offset)).abs() < 1e-9);
    }
    assert!(
        counted[1] > counted[0] && aside[0] > 200.0 / 3.0,
        "{aside:?}"
    );
    // The dominant finding is the yaw rate's share aside, and counted.
    let findings = d["gap"]["findings"].as_array().unwrap();
    let dominant = findings.iter().find(|f| f["kind"] == "dominant").unwrap();
    assert_eq!(dominant["channel"], "yaw_rate", "{dominant}");
    assert_eq!(dominant["share_percent"].as_f64(), Some(aside[0]));
    assert_eq!(dominant["with_offsets_percent"].as_f64(), Some(counted[0]));
    let carries = format!(
        "yaw_rate carries {:.0} % of the base model's held-out J² (each channel over its noise floor) with ay's steady offset aside ({:.0} % with it): it decides every fit",
        aside[0], counted[0]
    );
    // The shares line: the same numbers, aside and counted in one clause.
    let listed = |v: &[f64; 3], skip: usize| {
        let mut v: Vec<(&str, f64)> = channels.iter().copied().zip(v.iter().copied()).collect();
        v.sort_by(|a, b| b.1.total_cmp(&a.1));
        v.iter()
            .skip(skip)
            .map(|(c, p)| format!("{c} {p:.0} %"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let shares = format!(
        "combined error by channel (each channel's held-out samples over its noise floor): yaw_rate {:.0} % of the base model's J² ({}), more than two thirds, with ay's steady offset aside ({} with it); ",
        aside[0],
        listed(&aside, 1),
        listed(&counted, 0)
    );
    let summary: Vec<&str> = d["gap"]["summary"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    for (whose, text) in [("terminal", said.as_str()), ("page", page.as_str())] {
        assert!(text.contains(&carries), "{whose}: {carries}\n{text}");
        assert!(text.contains(&shares), "{whose}: {shares}\n{text}");
    }
    assert!(
        summary.iter().any(|l| l.starts_with(&carries)),
        "{summary:?}"
    );
}
