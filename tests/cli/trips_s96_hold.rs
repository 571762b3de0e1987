//! What a user tripped on: a `--hold` of the wrong ISO sign taken without a word, a critical speed taken at
//! road friction 1 on a road of 0.5, and a share of R0·Fz printed to six
//! digits.

use super::*;

/// `--hold PKY1=50` (ISO-W's −50 with its sign slipped) was fitted
/// around: σ 29.6 % on the Hoosier file and a `PCY1` = 2.99 the readers
/// then refuse. It is refused before any data are read, naming the
/// option, the value, the rule (Kyα < 0 in ISO-W) and the value meant;
/// so are a negative peak `PDY1`, a negative slip stiffness `PKX1` and
/// PAC89's stiffness `a3` of the other sign than its fit box.
#[test]
fn a_held_value_of_the_wrong_iso_sign_is_refused_with_its_rule() {
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,-500\n")]);
    let rig = dir.path().join("rig.csv");
    let refused = |model: &str, hold: &str| {
        let o = run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            model,
            "--hold",
            hold,
        ]);
        assert!(!o.status.success(), "{model} --hold {hold} taken");
        stderr(&o)
    };
    let e = refused("mf61", "PKY1=50");
    assert!(
        e.contains("--hold PKY1=50: the lateral stiffness factor has the wrong sign"),
        "{e}"
    );
    assert!(
        e.contains("Kyα = PKY1·FNOMIN·sin(PKY4·atan(Fz/(PKY2·FNOMIN)))·LKY is negative"),
        "{e}"
    );
    assert!(e.contains("did you mean -50?"), "{e}");
    let e = refused("mf62", "PDY1=-1.2");
    assert!(
        e.contains("--hold PDY1=-1.2: PDY1 (the peak friction at FNOMIN) is positive"),
        "{e}"
    );
    assert!(
        e.contains("within 0.05 to 6") && e.contains("did you mean 1.2?"),
        "{e}"
    );
    let e = refused("mf61", "PKX1=-20");
    assert!(
        e.contains("--hold PKX1=-20: the longitudinal slip stiffness")
            && e.contains("did you mean 20?"),
        "{e}"
    );
    let e = refused("pac89", "a3=-1000");
    assert!(e.contains("--hold a3=-1000: a3 is positive in every tyre the fit makes (it keeps a3 within 100 to 20000"), "{e}");
}

/// A held value of the right sign outside the box the fit searches
/// (magic-simple's `b` of 3 to 60 /rad) is fitted around, and said.
#[test]
fn a_held_value_outside_the_fit_box_is_warned_of() {
    let mut csv = String::from("fz,alpha,fy\n");
    for fz in [2000.0, 4000.0] {
        for i in 0..41 {
            let a = 0.005 * (i as f64 - 20.0);
            csv.push_str(&format!(
                "{fz},{a},{}\n",
                fz * (1.3 * (70.0 * a).atan()).sin()
            ));
        }
    }
    let dir = scratch(&[("rig.csv", &csv)]);
    let out = dir.path().join("t.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--hold",
        "b=70",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("warning: --hold b=70: outside the box the fit searches for it, 3 to 60"),
        "{e}"
    );
    // Within the box: no such warning.
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--hold",
        "b=50",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        o.status.success() && !stderr(&o).contains("outside the box"),
        "{}",
        stderr(&o)
    );
}

/// An oversteering car on simplified Magic Formula tyres (front b = 12,
/// rear b = 8, c = 1.3, d = 1: cornering stiffness b·c·d·μ·Fz per wheel),
/// m = 1530 kg, a = 1.2, b = 1.5 m. Closed form: Cf = 2·12·1.3·μ·Fzf/2,
/// Cr = 2·8·1.3·μ·Fzr/2, K = (m/l)(b/Cf − a/Cr) ∝ 1/μ, u_crit = √(−l/K)
/// = 28.75 m/s at μ = 1 and 28.75/√2 = 20.33 m/s at μ = 0.5. A step at
/// 24 m/s on a road of 0.5 lies above the critical speed there; the old
/// binary took the stiffness at μ = 1 (critical speed 28.7 m/s), said
/// nothing and measured the spin as a handling response.
#[test]
fn the_critical_speed_is_taken_at_the_road_friction() {
    let tyre = |b: f64| format!("model = \"magic-simple\"\nb = {b}\nc = 1.3\nd = 1.0\n");
    let scenario = |mu: f64| {
        format!("name = \"over\"\n[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.2\nb = 1.5\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n[road]\nfriction = {mu}\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 24.0\nsteer = 0.005\nstart = 1.0\nrise_time = 0.1\nend = 8.0\n")
    };
    let dir = scratch(&[
        ("front.toml", &tyre(12.0)),
        ("rear.toml", &tyre(8.0)),
        ("half.toml", &scenario(0.5)),
    ]);
    let (l, m, a, b, g) = (2.7, 1530.0, 1.2, 1.5, 9.81);
    let (fzf, fzr) = (m * g * b / l, m * g * a / l);
    let closed = |mu: f64| {
        let (cf, cr) = (12.0 * 1.3 * mu * fzf, 8.0 * 1.3 * mu * fzr);
        let k = m / l * (b / cf - a / cr);
        (-l / k).sqrt()
    };
    let out = dir.path().join("out");
    let said = succeeds(&[
        "simulate",
        dir.path().join("half.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let expected = format!("above its critical speed √(−l/K) = {:.1} m/s", closed(0.5));
    assert_eq!(format!("{:.1}", closed(0.5)), "20.3");
    assert!(said.contains(&expected), "{said}");
    assert!(
        said.contains("cornering stiffness at static load on this road of friction 0.5"),
        "{said}"
    );
    assert!(!out.join("metrics.json").exists());
}

/// tyre-eval's rolling resistance warning on a `.tir` with `QSY1 = 1e5`
/// (for 0.01) printed "up to 120022 times R0·Fz": three significant
/// digits, as the warning's other numbers.
#[test]
fn the_rolling_resistance_share_is_said_to_three_digits() {
    let tir = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap()
        .lines()
        .map(|l| {
            if l.starts_with("QSY1 ") {
                "QSY1 = 1e5".to_string()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let points =
        "fz,kappa,alpha,camber,speed\n2000,0,-0.1,0,16.7\n2000,0,0,0,16.7\n4000,0,0.02,0,16.7\n";
    let dir = scratch(&[("q.tir", &tir), ("p.csv", points)]);
    let o = run(&[
        "tyre-eval",
        dir.path().join("q.tir").to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        dir.path().join("e.csv").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    let share = e
        .split("up to ")
        .nth(1)
        .and_then(|s| s.split(" times R0·Fz").next())
        .expect(&e);
    let v: f64 = share.parse().expect(share);
    let digits = share.trim_end_matches('0').len();
    assert!(v > 1e5 && digits <= 3, "{share}: {e}");
}
