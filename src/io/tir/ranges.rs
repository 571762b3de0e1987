//! The validity ranges of a written `.tir` (`FZMIN`/`FZMAX`,
//! `KPUMIN`/`KPUMAX`, `ALPMIN`/`ALPMAX`, `CAMMIN`/`CAMMAX`,
//! `PRESMIN`/`PRESMAX`) in the sections published files hold them
//! (`[VERTICAL_FORCE_RANGE]`, `[LONG_SLIP_RANGE]`, …): a fresh file gets a
//! section for each range the tyre has; a template's file has the values it
//! holds replaced where the tyre's differ, and the ranges it lacks added.

use super::Units;
use crate::format::exact;
use crate::tyre::mf::MfLimits;

/// Each range's section and its two keys, as published files write them.
pub(crate) const RANGE_SECTIONS: [(&str, [&str; 2]); 5] = [
    ("INFLATION_PRESSURE_RANGE", ["PRESMIN", "PRESMAX"]),
    ("VERTICAL_FORCE_RANGE", ["FZMIN", "FZMAX"]),
    ("LONG_SLIP_RANGE", ["KPUMIN", "KPUMAX"]),
    ("SLIP_ANGLE_RANGE", ["ALPMIN", "ALPMAX"]),
    ("INCLINATION_ANGLE_RANGE", ["CAMMIN", "CAMMAX"]),
];

/// The sections of the ranges `limits` gives whose keys `present` does not
/// name (none for a fresh file), the values in `units`.
pub(super) fn range_sections(
    limits: &MfLimits,
    units: Units,
    present: &dyn Fn(&str) -> bool,
) -> String {
    let mut s = String::new();
    for (section, keys) in RANGE_SECTIONS {
        let missing: Vec<(&str, f64)> = keys
            .iter()
            .filter(|k| !present(k))
            .filter_map(|k| limits.get(k).map(|v| (*k, v / units.factor(k))))
            .collect();
        if missing.is_empty() {
            continue;
        }
        s.push_str(&format!("[{section}]\n"));
        for (k, v) in missing {
            s.push_str(&format!("{k:<25} = {}\n", exact(v)));
        }
    }
    s
}

/// The text of range key `key` of a file read as `written` (SI after
/// `units`): the tyre's value where it differs, `None` to keep the file's.
pub(super) fn range_replacement(
    limits: &MfLimits,
    units: Units,
    key: &str,
    written: Option<f64>,
) -> Option<String> {
    let v = limits.get(key)?;
    let factor = units.factor(key);
    (written.map(|w| w * factor) != Some(v)).then(|| exact(v / factor))
}
