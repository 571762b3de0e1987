//! The two files of `tyre-eval` given in the wrong order: a points CSV
//! where the tyre file goes is refused as such, before it is read as a
//! tyre (as TOML, its header `fz,kappa,…` gave only a parse error at
//! line 1, column 3, with no word of the order).

use crate::error::{InputError, InputProblem};
use std::path::Path;

/// Refuses a `tyre` path that is a points CSV: a `.csv` name, or (any
/// other name but `.toml`) a first line that is a CSV header, naming
/// `fz` among comma- or semicolon-separated columns and holding no `=`
/// or `[` of a TOML file.
pub(crate) fn refuse_points_as_tyre(tyre: &Path) -> Result<(), InputError> {
    // A file plainly of another kind (a scenario, a history, a folder) is
    // named as what it is, with the command that reads it.
    let points = ["fz", "kappa", "alpha", "camber", "speed"];
    if let Some(e) = crate::io::file_kind::not_a_tyre(tyre, &points) {
        return Err(e);
    }
    let ext = tyre.extension().and_then(|e| e.to_str()).unwrap_or("");
    // A `.tir` name on a points CSV (no `[MODEL]`: its header first) is
    // the order's slip as much as a `.csv` name.
    let tir = ext.eq_ignore_ascii_case("tir");
    if ext.eq_ignore_ascii_case("toml") || (tir && !first_line_is_points_header(tyre)) {
        return Ok(());
    }
    let csv = ext.eq_ignore_ascii_case("csv") || first_line_is_points_header(tyre);
    match csv {
        true => Err(InputError::Invalid {
            path: tyre.to_path_buf(),
            at: None,
            problem: Box::new(InputProblem::PointsAsTyre),
        }),
        false => Ok(()),
    }
}

/// True when the file's first line reads as a points CSV's header (an
/// unreadable file is left to the tyre reader to say).
fn first_line_is_points_header(path: &Path) -> bool {
    let Ok(text) = std::fs::read_to_string(path) else {
        return false;
    };
    let line = text.lines().next().unwrap_or("").trim();
    let columns: Vec<&str> = line.split([',', ';']).map(str::trim).collect();
    columns.len() > 1 && !line.contains(['=', '[']) && columns.contains(&"fz")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tyre_file_by_its_extension_is_never_refused_here() {
        assert!(refuse_points_as_tyre(Path::new("tyres/linear.toml")).is_ok());
        assert!(refuse_points_as_tyre(Path::new("no_such.tir")).is_ok());
        let e = refuse_points_as_tyre(Path::new("points.csv")).unwrap_err();
        assert!(e
            .to_string()
            .contains("the order is `tyre-eval <tyre> <points>`"));
    }
}
