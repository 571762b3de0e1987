//! What a fresh-eyes user still tripped on: a points file with several bad
//! cells refused one cell at a time (fix one, run again, learn of the
//! next), and its pressures at or below zero likewise.

use super::*;

/// A tyre file for `tyre-eval`: the public MF 6.1 sample of the fixtures.
fn sample_tir() -> PathBuf {
    root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir")
}

#[test]
fn tyre_eval_names_every_cell_that_is_not_a_finite_number_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed\n\
                  4000,0,0.1,0,16\n\
                  abc,0,0.1,0,16\n\
                  4000,0,nan,0,16\n\
                  4000,inf,0.1,0,16\n\
                  4000,0,0.1,0,16\n";
    let (o, written) = super::tyre_eval::eval(dir.path(), &sample_tir(), points, &[]);
    assert!(!o.status.success() && written.is_empty(), "{written}");
    let err = stderr(&o);
    for cell in [
        "p.csv:3:1: column `fz`: `abc` is not a number",
        "p.csv:4:3: column `alpha`: nan is not a finite value",
        "p.csv:5:2: column `kappa`: inf is not a finite value",
    ] {
        assert!(err.contains(cell), "no {cell:?} in: {err}");
    }
    assert!(err.contains("3 places refused, in file order"), "{err}");
}

#[test]
fn tyre_eval_names_every_pressure_at_or_below_zero_with_the_other_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let points = "fz,kappa,alpha,camber,speed,pressure\n\
                  4000,0,0.1,0,16,220000\n\
                  4000,0,0.1,0,16,0\n\
                  4000,0,0.1,0,-3,220000\n\
                  4000,0,0.1,0,16,-1\n";
    let (o, written) = super::tyre_eval::eval(dir.path(), &sample_tir(), points, &[]);
    assert!(!o.status.success() && written.is_empty(), "{written}");
    let err = stderr(&o);
    let at = |cell: &str| {
        err.find(cell)
            .unwrap_or_else(|| panic!("no {cell:?} in: {err}"))
    };
    // In file order: the zero pressure, the negative speed, the negative
    // pressure.
    let order = [
        at("p.csv:3:6: column `pressure`: 0 Pa is not a positive pressure"),
        at("p.csv:4:5: column `speed`"),
        at("p.csv:5:6: column `pressure`: -1 Pa is not a positive pressure"),
    ];
    assert!(order.windows(2).all(|w| w[0] < w[1]), "{err}");
}
