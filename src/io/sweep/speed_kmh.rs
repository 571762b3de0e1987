//! A sweep's speed axis given without a unit whose fastest value reads as
//! km/h written as m/s: `speed = 70` (meant as 70 km/h) solved the
//! equilibria at 252 km/h without a word. The scenario reader's rule
//! ([`kmh_note`]: from 50 m/s, 180 km/h, a note naming file:line:col),
//! applied to the fastest value the file writes: a list's element, a
//! range's `to`, a `{ values }` list's element. An axis with a `unit`
//! states its unit and gets no note. Units: m/s.

use super::{RangeSpec, Values};
use crate::io::scenario::kmh::{kmh_note, KmhSpeed, KmhStatedBy};
use crate::io::toml_file::TomlSource;

/// The note on the fastest speed of the sweep's axis `v` (at key
/// `sweep.speed`), where it is given without a unit and reaches the rule's
/// threshold.
pub(super) fn fastest(src: &TomlSource, v: &Values) -> Option<KmhSpeed> {
    let fastest = |values: &[f64], key: &str| {
        let (i, top) = values
            .iter()
            .copied()
            .enumerate()
            .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        (format!("{key}[{i}]"), top)
    };
    let (key, speed) = match v {
        Values::One(x) => ("sweep.speed".to_string(), *x),
        Values::List(l) => fastest(l, "sweep.speed"),
        Values::Units(l) if l.unit.is_none() => fastest(&l.values, "sweep.speed.values"),
        Values::Range(RangeSpec { to, unit: None, .. }) => ("sweep.speed.to".to_string(), *to),
        Values::Units(_) | Values::Range(_) => return None,
    };
    kmh_note(src, &key, speed, KmhStatedBy::SweepAxis)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn noted(axis: &str) -> Option<String> {
        let text = format!("[sweep]\nsteer = 0.1\nfriction = 0.8\nspeed = {axis}\n");
        let src = TomlSource {
            path: PathBuf::from("eq.toml"),
            text,
        };
        let v: Values = toml::from_str::<toml::Table>(&src.text).unwrap()["sweep"]["speed"]
            .clone()
            .try_into()
            .unwrap();
        fastest(&src, &v).map(|k| k.to_string())
    }

    /// The fastest value is named where the file writes it, from 50 m/s
    /// up; an axis with a unit, or slower, is not.
    #[test]
    fn a_sweeps_fastest_speed_from_50_ms_without_a_unit_is_said_in_kmh() {
        let one = noted("70").unwrap();
        assert!(
            one.starts_with(
                "eq.toml:4:9: `sweep.speed`: speed = 70 m/s is 252 km/h; 70 km/h is 19.44 m/s:"
            ),
            "{one}"
        );
        assert!(one.ends_with("so the equilibria are solved at 70 m/s as written; if km/h was meant, give the axis `unit = \"km/h\"` (`speed = { values = [...], unit = \"km/h\" }`, or a range's `unit`)"), "{one}");
        let list = noted("[20.0, 55.0, 60.0]").unwrap();
        assert!(
            list.starts_with("eq.toml:4:22: `sweep.speed[2]`: speed = 60 m/s"),
            "{list}"
        );
        let range = noted("{ from = 30.0, to = 120.0, step = 10.0 }").unwrap();
        assert!(
            range.starts_with("eq.toml:4:29: `sweep.speed.to`: speed = 120 m/s is 432 km/h"),
            "{range}"
        );
        let values = noted("{ values = [30.0, 90.0] }").unwrap();
        assert!(
            values.starts_with("eq.toml:4:27: `sweep.speed.values[1]`: speed = 90 m/s"),
            "{values}"
        );
        assert_eq!(
            noted("{ from = 30.0, to = 120.0, step = 10.0, unit = \"km/h\" }"),
            None
        );
        assert_eq!(noted("{ values = [70.0], unit = \"km/h\" }"), None);
        assert_eq!(noted("{ values = [70.0], unit = \"m/s\" }"), None);
        assert_eq!(noted("[20.0, 49.9]"), None);
        assert!(noted("50").is_some());
    }
}
