//! Outputs: CSV, JSON and PNG files, each written to a temporary file in the
//! destination folder and renamed into place, so a failed run never leaves a
//! half-written file; and a refusal to write over any input file.

pub mod plot;
pub mod progress;

use anyhow::{bail, Context, Result};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Temporary sibling of `path`, keeping its extension (image encoders pick
/// the format from it).
fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let ext = path
        .extension()
        .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
    path.with_file_name(format!(".{name}.partial-{}{ext}", std::process::id()))
}

/// Writes through `fill` into a temporary file, then renames it to `path`.
pub fn write_atomic(path: &Path, fill: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            fs::create_dir_all(dir)
                .with_context(|| format!("{}: cannot create folder", dir.display()))?;
        }
    }
    let tmp = temp_path(path);
    let result = fill(&tmp).and_then(|()| {
        fs::rename(&tmp, path)
            .with_context(|| format!("{}: cannot move into place", path.display()))
    });
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Writes bytes atomically.
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic(path, |tmp| {
        let mut f =
            fs::File::create(tmp).with_context(|| format!("{}: cannot create", tmp.display()))?;
        f.write_all(bytes)?;
        f.sync_all()?;
        Ok(())
    })
}

/// Writes a value as pretty JSON.
pub fn write_json<T: serde::Serialize>(path: &Path, value: &T) -> Result<()> {
    let mut text = serde_json::to_string_pretty(value)?;
    text.push('\n');
    write_bytes(path, text.as_bytes())
}

/// Writes named columns of equal length as CSV with a header line.
pub fn write_columns(path: &Path, columns: &[(&str, &[f64])]) -> Result<()> {
    let n = columns.first().map_or(0, |c| c.1.len());
    if columns.iter().any(|c| c.1.len() != n) {
        bail!("{}: columns of unequal length", path.display());
    }
    let mut w = csv::Writer::from_writer(Vec::with_capacity(n * columns.len() * 12));
    w.write_record(columns.iter().map(|c| c.0))?;
    let mut row = Vec::with_capacity(columns.len());
    for i in 0..n {
        row.clear();
        row.extend(columns.iter().map(|c| format!("{}", c.1[i])));
        w.write_record(&row)?;
    }
    write_bytes(path, &w.into_inner()?)
}

/// Refuses when `out` is one of `inputs` (compared after resolving links).
pub fn refuse_overwrite(out: &Path, inputs: &[PathBuf]) -> Result<()> {
    let canon = |p: &Path| fs::canonicalize(p).ok();
    if let Some(o) = canon(out) {
        if inputs
            .iter()
            .any(|i| canon(i).as_deref() == Some(o.as_path()))
        {
            bail!(
                "{}: is an input of this run; refusing to overwrite it",
                out.display()
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failed_write_leaves_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.csv");
        let r = write_atomic(&p, |tmp| {
            fs::write(tmp, "half")?;
            bail!("boom")
        });
        assert!(r.is_err());
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0);
        write_columns(&p, &[("t", &[0.0, 1.0]), ("x", &[2.0, 3.5])]).unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "t,x\n0,2\n1,3.5\n");
        assert!(refuse_overwrite(&p, std::slice::from_ref(&p)).is_err());
    }
}
