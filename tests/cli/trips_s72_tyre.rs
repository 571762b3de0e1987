//! What a fresh-eyes check of `tyre-eval` and the tyre files found
//! (stop 72), run as a user runs the tool.

use super::*;
use crate::tyre_eval::{column, eval};
use std::fs;

/// The MF 6.1 fixture.
fn mf61() -> PathBuf {
    root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A points file whose every load is negative (a TTC/SAE rig's z axis
/// points down) was evaluated as wheels off the road: all-zero forces,
/// exit 0. Refused at each load, as `identify` refuses a rig file's, for
/// any model; a negative load among others is refused too (a wheel off
/// the road is at 0).
#[test]
fn a_points_file_whose_every_load_is_negative_is_refused_as_identify_does() {
    let dir = tempfile::tempdir().unwrap();
    let all = "fz,kappa,alpha,camber,speed\n-4000,0,0.05,0,16.7\n-2000,0.1,0.05,0,16.7\n";
    let told = "every load of the file is: a rig whose z axis points down (SAE's axes) logs them so; negate the column";
    for tyre in [mf61(), root().join("tyres/gim.toml")] {
        let (o, written) = eval(dir.path(), &tyre, all, &[]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{e}");
        assert!(written.is_empty(), "{written}");
        for (line, value) in [(2, "-4000"), (3, "-2000")] {
            let at = format!("p.csv:{line}:1: column `fz`: {value} N is negative (loads are positive in FORMATS.md); {told}");
            assert!(e.contains(&at), "{e}");
        }
        assert!(!e.contains("off the road"), "{e}");
    }
    // A negative load among positive ones or zeros is refused too, at its
    // cell, without the advice to negate the column (session 105: it was
    // evaluated as a wheel off the road); a load of 0 is one.
    for mixed in [
        "fz,kappa,alpha,camber,speed\n-4000,0,0.05,0,16.7\n2000,0.1,0.05,0,16.7\n",
        "fz,kappa,alpha,camber,speed\n-4000,0,0.05,0,16.7\n0,0.1,0.05,0,16.7\n",
    ] {
        let (o, written) = eval(dir.path(), &mf61(), mixed, &[]);
        let e = stderr(&o);
        assert!(!o.status.success(), "{e}");
        assert!(written.is_empty(), "{written}");
        assert!(
            e.contains("p.csv:2:1: column `fz`: -4000 N is negative"),
            "{e}"
        );
        assert!(!without_temp_names(&e).contains("negate"), "{e}");
    }
    let (o, written) = eval(
        dir.path(),
        &mf61(),
        "fz,kappa,alpha,camber,speed\n0,0,0.05,0,16.7\n2000,0.1,0.05,0,16.7\n",
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("1 point at fz ≤ 0 (off the road): no force"),
        "{}",
        stdout(&o)
    );
    assert_eq!(column(&written, "fy")[0], 0.0);
}

/// The MF 6.1 fixture with `FREFF` = 0.8: its effective rolling radius
/// falls to 0 at about 150 kN, within the loads a points file may give.
fn soft_effective_radius(dir: &Path) -> PathBuf {
    let text = fs::read_to_string(mf61()).unwrap();
    let edited: String = text
        .lines()
        .map(|l| match l.split_whitespace().next() {
            Some("FREFF") => "FREFF = 0.8\n".to_string(),
            _ => format!("{l}\n"),
        })
        .collect();
    let path = dir.join("freff.tir");
    fs::write(&path, edited).unwrap();
    path
}

/// A 100 N point at 50 m/s was warned of as a loaded radius above the
/// free radius "where the effective radius has fallen through 0 (a load far
/// past FZMAX)": its rl of 0.3961 m is the free radius's growth with speed
/// (Q_V1), which the static UNLOADED_RADIUS of 0.3943 m leaves out. The
/// reference is the free radius at the point's speed; where rl still
/// exceeds it, what drives it is said: the slip ratio of a spinning wheel,
/// or a load far past the file's.
#[test]
fn a_loaded_radius_is_judged_against_the_free_radius_at_its_speed_with_its_cause() {
    let dir = tempfile::tempdir().unwrap();
    let growth = "fz,kappa,alpha,camber,speed\n20,0,0,0,30\n100,0,0,0,50\n";
    let (o, written) = eval(dir.path(), &mf61(), growth, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rl = column(&written, "rl");
    assert!(rl[1] > 0.3943 && rl[1] < 0.3962, "{rl:?}");
    assert!(
        !stderr(&o).contains("loaded radius rl above"),
        "{}",
        stderr(&o)
    );
    // A wheel spinning at eleven times the road speed: the slip ratio.
    let spin = "fz,kappa,alpha,camber,speed\n4000,10,0,0,16.7\n4000,0,0,0,16.7\n";
    let head =
        "1 of 2 points on the road with a loaded radius rl above the free radius at their speed";
    for tir in ["MagicFormula61_Parameters", "MagicFormula62_Parameters"] {
        let tir = root().join(format!("tests/fixtures/tir/{tir}.tir"));
        let (o, _) = eval(dir.path(), &tir, spin, &[]);
        let said = stderr(&o);
        assert!(o.status.success(), "{said}");
        assert!(said.contains(head), "{said}");
        assert!(
            said.contains("their slip ratio spins the wheel at 1 + kappa times its free-rolling speed (11.0 at the first)")
                && said.contains("the first at line 2, fz = 4000 N, kappa = 10.0, speed = 16.7 m/s: rl = 0.4110 m, free radius 0.3944 m"),
            "{said}"
        );
        assert!(
            !said.contains("their load") && !said.contains("FZMAX)"),
            "{said}"
        );
    }
    // A load far past the file's: the effective radius falls to 0, and
    // the point is refused at its row (session 104; it was written and
    // warned of).
    let heavy = "fz,kappa,alpha,camber,speed\n4000,0,0,0,16.7\n150000,0,0,0,16.7\n";
    let (o, _) = eval(dir.path(), &soft_effective_radius(dir.path()), heavy, &[]);
    let said = stderr(&o);
    assert!(!o.status.success(), "{said}");
    assert!(
        said.contains("p.csv:3:1: fz = 150000 N is more than the tyre's vertical model carries: its effective rolling radius Re")
            && said.contains("(rl 1.803 m against a free radius of"),
        "{said}"
    );
    assert!(!said.contains("slip ratio spins"), "{said}");
    // MF 5.2 has no vertical model: no rl, nothing to say of it.
    let mf52 = root().join("tests/fixtures/tir/MagicFormula52_Parameters.tir");
    let (o, written) = eval(dir.path(), &mf52, spin, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!written.lines().next().unwrap().contains("rl"), "{written}");
    assert!(!stderr(&o).contains("loaded radius"), "{}", stderr(&o));
}

/// `cornering_stiffness = 1000` on a Gim tyre (a car tyre's N/deg figure,
/// read as N/rad: 50 N of lateral force at 4 kN and 2.9°) was taken
/// without a word; below 900 N/rad the refusal quoted "500 N/deg is 28648
/// N/rad" whatever the value. Refused at its key per unit of the tyre's
/// load, and said with the value given converted.
#[test]
fn a_cornering_stiffness_in_n_per_degree_is_refused_per_unit_load_with_its_own_value() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    let gim = fs::read_to_string(root().join("tyres/gim.toml")).unwrap();
    assert!(gim.contains("cornering_stiffness = 57296.0   #"), "{gim}");
    let cases = [
        (
            gim.replace("cornering_stiffness = 57296.0", "cornering_stiffness = 1000"),
            "g.toml:4:23: `cornering_stiffness` = 1000: over the tyre's reference_load = 4000 N (the model's default where a file states none) that is 0.250 N/rad per N (Cα/Fz), below any tyre's 1.5",
            "is the value in N/deg? multiply it by 57.3 (1000 N/deg is 57296 N/rad, 14.3 N/rad per N)",
        ),
        (
            "model = \"gim\"\ncornering_stiffness = 2500\ncontact_length = 0.18\nreference_load = 6000\n".to_string(),
            "g.toml:2:23: `cornering_stiffness` = 2500: over the tyre's reference_load = 6000 N that is 0.417 N/rad per N",
            "(2500 N/deg is 143239 N/rad, 23.9 N/rad per N)",
        ),
        (
            "model = \"linear\"\ncornering_stiffness = 800\n".to_string(),
            "g.toml:2:23: `cornering_stiffness` = 800: must lie in (900, 2000000]: no tyre's cornering stiffness is below 900 N/rad",
            "is the value in N/deg? multiply it by 57.3 (800 N/deg is 45837 N/rad)",
        ),
    ];
    for (tyre, at, slip) in cases {
        fs::write(dir.path().join("g.toml"), &tyre).unwrap();
        let (o, written) = eval(dir.path(), &dir.path().join("g.toml"), points, &[]);
        let e = stderr(&o);
        assert!(!o.status.success() && written.is_empty(), "{e}");
        assert!(e.contains(at) && e.contains(slip), "{e}");
        assert!(!e.contains("500 N/deg is 28648"), "{e}");
    }
    // A bicycle tyre at its own light load is a tyre: 2000 N/rad at 300 N.
    let bike = "model = \"gim\"\ncornering_stiffness = 2000\ncontact_length = 0.05\nreference_load = 300\n";
    fs::write(dir.path().join("g.toml"), bike).unwrap();
    let (o, _) = eval(dir.path(), &dir.path().join("g.toml"), points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Every bundled tyre with the key is read.
    for name in [
        "gim",
        "gim_sedan_front",
        "gim_sedan_rear",
        "gim_sliding_decay",
        "linear",
    ] {
        let (o, _) = eval(
            dir.path(),
            &root().join(format!("tyres/{name}.toml")),
            points,
            &[],
        );
        assert!(o.status.success(), "{name}: {}", stderr(&o));
    }
}

/// A Gim tyre whose stiffness does not depend on the load was held to any
/// tyre's loads, 100 N to 100 kN, even where its file states its
/// `reference_load`: a car tyre at 30 kN went unsaid. A load stated gives
/// the range, as the other models' do; a file that states none keeps any
/// tyre's.
#[test]
fn a_gim_tyre_that_states_its_load_is_held_to_the_loads_around_it() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n30000,0,0.05,0,16.7\n";
    let gim = fs::read_to_string(root().join("tyres/gim.toml")).unwrap();
    fs::write(
        dir.path().join("g.toml"),
        format!("{gim}reference_load = 4000\n"),
    )
    .unwrap();
    let (o, _) = eval(dir.path(), &dir.path().join("g.toml"), points, &[]);
    let said = stderr(&o);
    assert!(o.status.success(), "{said}");
    assert!(
        said.contains("warning: 1 of 2 points at a load above 12000 N, outside the loads the gim tyre is meant for (40 to 12000 N: 1 % to 3 times its reference_load = 4000 N)")
            && said.contains("the first at line 3, fz = 30000 N"),
        "{said}"
    );
    let (o, _) = eval(dir.path(), &root().join("tyres/gim.toml"), points, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("outside the loads"), "{}", stderr(&o));
}
