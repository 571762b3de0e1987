//! The pure-slip rows of a rig file for a swarm fit (`identify/pure.rs`),
//! with what a user needs to hear of the rest: a file of combined-slip
//! rows only is refused with their count (the grouping's "0 samples"
//! alone said nothing of where they went), and where a file has one of a
//! longitudinal test's two columns, the one it lacks is named (the rig
//! reader takes `kappa` and `fx` as a pair, and a file with `fx` but no
//! `kappa` was said to have "no kappa/fx columns").

use crate::error::{FitError, OnlyCombined};
use crate::identify::data::RigData;
use crate::identify::pure::{split, SetAside};
use std::path::Path;

/// The pure lateral rows of `data` (read from `path`), the pure
/// longitudinal view and what was set aside, as [`split`] gives them;
/// refused where every row is combined slip (`model`: the model asked for).
pub(super) fn pure_rows(
    data: &RigData,
    path: &Path,
    model: &'static str,
) -> Result<(RigData, Option<RigData>, SetAside), FitError> {
    let (lateral, long_view, mut set_aside) = split(data);
    if set_aside.rows > 0 && set_aside.combined == set_aside.rows {
        return Err(OnlyCombined {
            data: path.to_path_buf(),
            rows: set_aside.rows,
            model,
            tol: crate::identify::mf_staged::PURE_TOL,
        }
        .into());
    }
    if data.longitudinal.is_none() {
        set_aside.missing_column = missing_longitudinal_column(path);
    }
    Ok((lateral, long_view, set_aside))
}

/// The column of the pair `kappa`, `fx` that the rig file `path` lacks
/// where it has the other; `None` where it has both, neither, or cannot
/// be read (the rig reader has said why by then).
fn missing_longitudinal_column(path: &Path) -> Option<&'static str> {
    let layout = crate::io::Layout {
        required: &["fz"],
        optional: &["kappa", "fx"],
        also_read: Some(&[
            "alpha", "fy", "mz", "camber", "pressure", "speed", "mx", "my",
        ]),
    };
    let (columns, _) = crate::io::read_columns_with_bad_cells(path, layout).ok()?;
    match (columns.get("kappa").is_some(), columns.get("fx").is_some()) {
        (false, true) => Some("kappa"),
        (true, false) => Some("fx"),
        _ => None,
    }
}
