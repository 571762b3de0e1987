//! `tyre-eval` past what a file or model gives: a Magic Formula file
//! evaluated with its limit checks off (mode 221) at loads beyond its
//! `FZMAX` wrote forces of a tyre at several times its rated load without
//! a word (with the checks on, the same points are said held at the end);
//! a tyre without an aligning moment (a simplified Magic Formula) wrote
//! `mz` = 0 at every slip angle without saying it has none.

use super::*;
use crate::tyre_eval::{eval, mf61};

#[test]
fn a_load_past_fzmax_with_the_limit_checks_off_is_said_evaluated_as_given() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = mf61(dir.path(), &[]);
    let csv = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n30000,0,0.05,0,20\n";
    let (off, off_csv) = eval(dir.path(), &tyre, csv, &["--mode", "221"]);
    assert!(off.status.success(), "{}", stderr(&off));
    let said = stderr(&off);
    assert!(
        said.contains("warning: 1 of 2 points above FZMAX = 18000 N (the file's range 0 to 18000): evaluated at the value given, past the range (the limit checks off, mode 2xx): an extrapolation of the file; the first at line 3, fz = 30000 N"),
        "{said}"
    );
    let (on, on_csv) = eval(dir.path(), &tyre, csv, &[]);
    assert!(on.status.success(), "{}", stderr(&on));
    assert!(
        stderr(&on).contains("1 of 2 points above FZMAX = 18000 N (the file's range 0 to 18000): evaluated at that end"),
        "{}",
        stderr(&on)
    );
    // What each says is what each wrote: the same force inside the range,
    // another at 30 kN (held at 18 kN with the checks on).
    let fy = |csv: &str| -> Vec<f64> {
        let mut lines = csv.lines();
        let at = lines
            .next()
            .unwrap()
            .split(',')
            .position(|c| c == "fy")
            .unwrap();
        lines
            .map(|l| l.split(',').nth(at).unwrap().parse().unwrap())
            .collect()
    };
    let (a, b) = (fy(&off_csv), fy(&on_csv));
    assert_eq!(a[0], b[0]);
    assert!((a[1] - b[1]).abs() > 0.01 * b[1].abs(), "{a:?} {b:?}");
}

#[test]
fn a_tyre_without_an_aligning_moment_is_warned_of_at_a_slip_angle() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = root().join("tyres/magic_simple.toml");
    let csv = "fz,kappa,alpha,camber,speed\n3000,0,0.05,0,20\n3000,0,0,0,20\n3000,0,-0.02,0,20\n";
    let (o, written) = eval(dir.path(), &tyre, csv, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: 2 of 3 points have alpha ≠ 0 and mz = 0: the tyre has no aligning moment; its mz is not a prediction"),
        "{}",
        stderr(&o)
    );
    assert!(written.lines().count() == 4, "{written}");
    // A tyre that has one (the linear tyre's pneumatic trail) is not.
    let (o, _) = eval(dir.path(), &root().join("tyres/linear.toml"), csv, &[]);
    assert!(!stderr(&o).contains("mz = 0"), "{}", stderr(&o));
}

/// `--out` naming a folder was refused after the evaluation, as "cannot
/// move into place: Is a directory (os error 21)".
#[test]
fn an_output_that_is_a_folder_is_refused_before_the_evaluation_with_a_file_to_name() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("out")).unwrap();
    fs::write(
        dir.path().join("p.csv"),
        "fz,kappa,alpha,camber,speed\n3000,0,0.05,0,20\n",
    )
    .unwrap();
    let o = bin()
        .args([
            "tyre-eval",
            root().join("tyres/linear.toml").to_str().unwrap(),
            "p.csv",
            "--out",
            "out",
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(!o.status.success());
    let e = stderr(&o);
    assert_eq!(
        e.trim_end(),
        format!(
            "error: out: is a folder; name the file to write in it (e.g. {})",
            Path::new("out").join("forces.csv").display()
        )
    );
}
