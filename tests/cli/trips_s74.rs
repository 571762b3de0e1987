//! What a fresh-eyes check found after stop 73, run as a user runs the
//! tool.

use super::*;
use std::fs;

/// The Hoosier rig file kept every 2nd, 4th or 8th row (a logger at a
/// lower rate, or a file thinned to share): its loads vary with slip by
/// ±150 N, so consecutive rows of the thinned file differ by 31–53 N, read
/// as noise, and the separation it set joined the five loads into three
/// (every 2nd row) or one (every 4th, refused: "the data has 1: 1677 N").
/// Each rate, from whichever row it starts, now finds the full file's five
/// loads, within 5 N of their nominals, and fits them as the full file
/// does.
#[test]
fn a_rig_file_kept_every_few_rows_keeps_its_loads_apart() {
    let test = "a_rig_file_kept_every_few_rows_keeps_its_loads_apart";
    let Some(data) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    // Without its `mz` column: the loads are grouped from `fz` and the
    // lateral force fitted first, the same with it or without (the five
    // nominals, curves and σ alike); the aligning-moment fit, half the
    // run's time, is not what this test is about.
    let text = without_column(&fs::read_to_string(data).unwrap(), "mz");
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let rows: Vec<&str> = lines.collect();
    let dir = tempfile::tempdir().unwrap();
    // Every 8th row from the 4th (or 6th, 8th) split the lightest load
    // off and merged the other four into one at 2142 N.
    for (every, from) in [(2, 0), (4, 0), (8, 0), (8, 3), (8, 5), (8, 7)] {
        let kept: Vec<&str> = rows.iter().skip(from).step_by(every).copied().collect();
        let sub = dir.path().join(format!("every_{every}_from_{from}"));
        fs::create_dir(&sub).unwrap();
        fs::write(
            sub.join("rig.csv"),
            format!("{header}\n{}\n", kept.join("\n")),
        )
        .unwrap();
        let extra = ["--pressure", "83000", "--camber", "0"];
        let (report, _) = super::rig_layouts::identify(&sub, "rig.csv", "pac89", &extra);
        let every = format!("{every} from {from}");
        let nominals = super::rig_layouts::load_nominals(&report);
        assert_eq!(nominals.len(), 5, "every {every}: {nominals:?}");
        for (got, full) in nominals.iter().zip([534.0, 1095.0, 1656.0, 2193.0, 2751.0]) {
            assert!((got - full).abs() < 5.0, "every {every}: {nominals:?}");
        }
        assert_eq!(report["curves"].as_array().unwrap().len(), 5);
        let sigma = report["sigma_percent"].as_f64().unwrap();
        assert!(sigma < 3.5, "every {every}: σ {sigma} %");
    }
}

/// The CSV `text` without its column `name` (which it must have).
pub(crate) fn without_column(text: &str, name: &str) -> String {
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let drop = header.iter().position(|c| *c == name).unwrap();
    text.lines()
        .map(|l| {
            let kept: Vec<&str> = (l.split(',').enumerate())
                .filter(|(i, _)| *i != drop)
                .map(|(_, c)| c)
                .collect();
            kept.join(",") + "\n"
        })
        .collect()
}

/// A rig file with the Tire Test Consortium's channel names and units in
/// the header (`Fy_N,SA_deg,FZ_kN,MZ,P,t`): the missing `fz` was said to
/// be meant by `MZ` (one letter from it in capitals) at column 1, and
/// `SA_deg` and `P` were not named. Each column is now named for what it
/// means, at its own column: a name in capitals or with a unit after it
/// before a near spelling, and the rig's `SA`, `IA`, `P`, `V` for
/// `alpha`, `camber`, `pressure`, `speed`.
#[test]
fn a_rig_header_in_the_ttc_names_is_refused_naming_what_each_column_means() {
    let dir = scratch(&[
        ("units.csv", "Fy_N,SA_deg,FZ_kN,MZ,P,t\n100,1,2,3,83,0\n"),
        (
            "ttc.csv",
            "ET,FZ,SA,IA,P,V,FY,MZ\n0,-2000,1,0,83,40,100,3\n",
        ),
    ]);
    let e = stderr(&run_in(
        dir.path(),
        &["identify", "units.csv", "--model", "gim"],
    ));
    for said in [
        // A unit in the header is read as one and told its conversion.
        "units.csv:1:3: column `FZ_kN` is `fz` in kN, and `fz` is read in N (FORMATS.md): convert the values (",
        "units.csv:1:2: column `SA_deg` is `alpha` in ",
        "units.csv:1:4: column `MZ` is not one this command reads: did you mean `mz`?",
        "units.csv:1:5: column `P` is not one this command reads: did you mean `pressure`?",
    ] {
        assert!(e.contains(said), "{said}\n{e}");
    }
    let e = stderr(&run_in(
        dir.path(),
        &["identify", "ttc.csv", "--model", "gim"],
    ));
    for (column, found, meant) in [
        (3, "SA", "alpha"),
        (4, "IA", "camber"),
        (5, "P", "pressure"),
        (6, "V", "speed"),
        (7, "FY", "fy"),
    ] {
        let said = format!(
            "ttc.csv:1:{column}: column `{found}` is not one this command reads: did you mean `{meant}`?"
        );
        assert!(e.contains(&said), "{said}\n{e}");
    }
    assert!(
        e.contains("ttc.csv:1:2: missing required column `fz`"),
        "{e}"
    );
}

/// `tyre-eval` at slip ratios 5, 10 and −3 (a column in percent) wrote
/// the saturated tail of the curve without a word; they are now counted
/// with the first one's line and the farthest value, and the percent
/// asked about. ±1 (a locked wheel, one spun to twice the road speed) is
/// not.
#[test]
fn slip_ratios_past_a_locked_wheel_are_warned_of_at_their_line() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0.05,0,0,16.7\n4000,5,0,0,16.7\n4000,10,0,0,16.7\n4000,-3,0,0,16.7\n4000,-1,0,0,16.7\n";
    let dir = scratch(&[("p.csv", points)]);
    let tyre = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "p.csv",
            "--out",
            "f.csv",
        ],
    );
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    assert!(
        e.contains(
            "3 points of 5 at a slip ratio beyond ±1 (the first at line 3, κ = 5; the farthest 10)"
        ) && e.contains("is the column in percent? divide it by 100"),
        "{e}"
    );
    let fine = "fz,kappa,alpha,camber,speed\n4000,0.05,0,0,16.7\n4000,-1,0,0,16.7\n";
    fs::write(dir.path().join("q.csv"), fine).unwrap();
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "q.csv",
            "--out",
            "g.csv",
        ],
    );
    assert!(o.status.success());
    assert!(!stderr(&o).contains("beyond ±1"), "{}", stderr(&o));
}
