//! Units written in a CSV header: `alpha [deg]`, `speed (km/h)`, `fz_kN`,
//! as loggers and rigs write them. A header column that is a column the
//! reader reads followed by a unit is recognised as that column with that
//! unit ([`crate::error::Unit`]):
//! - in brackets or parentheses after the name, any unit text (a text
//!   that names no known unit is refused as such);
//! - after an underscore (`alpha_deg`, `yaw_rate_deg_s`, `FZ_kN`), only a
//!   known unit of the column's own quantity: `speed_ms` (milliseconds?
//!   m/s?) is left to the did-you-mean of a misspelt name.
//!
//! The column's own SI unit (`alpha [rad]`, `fz [N]`, `t_s`), under the
//! column's exact name, is checked and accepted: the column is read. Any
//! other unit of the column's quantity is refused with the conversion
//! (or, for a run's angle in degrees, the reader's key to declare it):
//! the values are never read in a unit the header says they are not in.
//! Columns the reader only knows of (`also_read`) are accepted in SI and
//! otherwise left as they are, unread.

use crate::error::{DeclaredBy, HeaderUnit, Quantity, Stated, Unit, UnitAdvice};

/// The columns with a unit, and the quantity `FORMATS.md` reads each as
/// (its unit: [`Quantity::si`]).
const QUANTITIES: [(&str, Quantity); 19] = [
    ("t", Quantity::Time),
    ("speed", Quantity::Speed),
    ("steer", Quantity::Angle),
    ("alpha", Quantity::Angle),
    ("camber", Quantity::Angle),
    ("beta", Quantity::Angle),
    ("roll", Quantity::Angle),
    ("bank", Quantity::Angle),
    ("yaw_rate", Quantity::AngularRate),
    ("ay", Quantity::Acceleration),
    ("ax", Quantity::Acceleration),
    ("fz", Quantity::Force),
    ("fy", Quantity::Force),
    ("fx", Quantity::Force),
    ("mz", Quantity::Moment),
    ("mx", Quantity::Moment),
    ("my", Quantity::Moment),
    ("pressure", Quantity::Pressure),
    ("kappa", Quantity::Ratio),
];

/// The column `name` (its static name) and its quantity, where it has one.
fn quantity_of(name: &str) -> Option<(&'static str, Quantity)> {
    QUANTITIES.iter().copied().find(|(c, _)| *c == name)
}

/// The run's angle columns a reader may declare in degrees (deg/s for the
/// yaw rate): `AngleColumn`'s.
const DECLARABLE: [&str; 5] = ["steer", "yaw_rate", "beta", "roll", "bank"];

/// A header column's name and the unit text after it, and whether that
/// text was bracketed.
fn split(h: &str) -> Option<(&str, String, bool)> {
    for (open, close) in [('[', ']'), ('(', ')')] {
        if let Some(inner) = h.strip_suffix(close) {
            let at = inner.rfind(open)?;
            let name = inner[..at].trim();
            return (!name.is_empty()).then(|| (name, inner[at + 1..].trim().to_string(), true));
        }
    }
    None
}

/// What the header says of one column.
pub(super) enum Reading {
    /// The column under its name and its SI unit: read as the column.
    Accept(&'static str),
    /// The column in another unit: refused.
    Refuse(HeaderUnit),
}

/// The column among `checked` and `known` that `name` names: its exact
/// name (true), or in other letters' case or a rig's channel name (false).
fn column_named(name: &str, checked: &[&str], known: &[&str]) -> Option<(&'static str, bool)> {
    let all = || checked.iter().chain(known).copied();
    if let Some(c) = all().find(|c| *c == name) {
        return Some((quantity_of(c)?.0, true));
    }
    // Whatever its case and separators: `Yaw Rate [deg/s]` is `yaw_rate`
    // in deg/s, as `yaw_rate [deg/s]` is; read as a misspelt name, its
    // did-you-mean `yaw_rate` read the deg/s as rad/s (round 50).
    let plain = super::aliases::plain(name);
    let same = |c: &str| super::aliases::plain(c) == plain;
    let listed: Vec<&str> = all().collect();
    // A rig's channel name (`SA`, `FZ`), not another name of the column
    // (`steering_angle` may be the handwheel's: a did-you-mean says it).
    let rig = super::RIG_NAMES.iter().find(|(rig, _)| same(rig));
    let rig = rig.and_then(|(_, ours)| listed.iter().copied().find(|c| c == ours));
    // A long name of the time (`time`, `Zeit`): `time [ms]` and `time_ms`
    // are `t` in ms, whose did-you-mean `t` left the values 1000 times too
    // large (round 48), as `t_ms` is. One rule for every reader of a `t`.
    let time = super::TIME_NAMES.iter().any(|n| same(n)) && listed.contains(&"t");
    let c = all().find(|c| same(c)).or(rig).or(time.then_some("t"))?;
    Some((quantity_of(c)?.0, false))
}

/// The reading of the header column `h` by a reader of the columns
/// `checked` (read) and `known` (only known of), whose run angles are
/// declared in degrees by `by` where it has one (`declared`: the columns
/// it declares so); `None`: no column with a unit, left to the other
/// header checks.
pub(super) fn reading(
    h: &str,
    (checked, known): (&[&str], &[&str]),
    by: Option<DeclaredBy>,
    declared: &[&str],
) -> Option<Reading> {
    let (column, exact, stated, bracketed) = match split(h) {
        Some((name, text, true)) => {
            let (column, exact) = column_named(name, checked, known)?;
            let stated = Unit::parse(&text).map_or(Stated::Unknown(text.into()), Stated::Known);
            (column, exact, stated, true)
        }
        _ => suffixed(h, checked, known)?,
    };
    let (_, quantity) = quantity_of(column)?;
    let advice = match &stated {
        Stated::Known(u) if *u == quantity.si() => return exact.then_some(Reading::Accept(column)),
        Stated::Known(u) if u.quantity() != quantity => {
            // `speed_ms` may be a misspelt `speed` in m/s: said as a slip.
            if !bracketed {
                return None;
            }
            UnitAdvice::OtherQuantity
        }
        // Declared in degrees and stated so: the two agree, and the
        // declaration converts it (`beta_deg` with `--degrees beta`).
        Stated::Known(Unit::Degree | Unit::DegreePerSecond) if declared.contains(&column) => {
            return exact.then_some(Reading::Accept(column));
        }
        Stated::Known(u) => match by {
            Some(by)
                if DECLARABLE.contains(&column)
                    && matches!(u, Unit::Degree | Unit::DegreePerSecond) =>
            {
                UnitAdvice::Declare(by)
            }
            _ => UnitAdvice::Convert,
        },
        Stated::Unknown(_) => UnitAdvice::UnknownUnit,
    };
    // A column the reader does not read is not refused for its unit.
    if !checked.contains(&column) {
        return None;
    }
    Some(Reading::Refuse(HeaderUnit {
        header: h.into(),
        column,
        quantity,
        stated,
        advice,
    }))
}

/// A column named with its unit after an underscore (`alpha_deg`,
/// `yaw_rate_deg_s`, `FZ_kN`): the column, whether its name is exact, the
/// unit, and false (not bracketed); only a known unit of the column's
/// quantity.
fn suffixed(
    h: &str,
    checked: &[&str],
    known: &[&str],
) -> Option<(&'static str, bool, Stated, bool)> {
    // The longest name first: `yaw_rate_deg` is `yaw_rate`, not `yaw`.
    let mut cuts: Vec<usize> = h.match_indices('_').map(|(i, _)| i).collect();
    cuts.reverse();
    cuts.into_iter().find_map(|at| {
        let (name, tail) = (&h[..at], &h[at + 1..]);
        let (column, exact) = column_named(name, checked, known)?;
        let unit = Unit::parse(&tail.replace('_', "/"))?;
        (Some(unit.quantity()) == quantity_of(column).map(|q| q.1)).then_some((
            column,
            exact,
            Stated::Known(unit),
            false,
        ))
    })
}

/// The header as a reader matches it: each column with a unit accepted
/// under its name, and each refused under its name too (so that it is not
/// also said missing), with the refusals at their 1-based positions.
pub(super) fn canonical(
    header: &csv::StringRecord,
    checked: &[&str],
    known: &[&str],
    (by, declared): (Option<DeclaredBy>, &[&str]),
) -> (csv::StringRecord, Vec<(usize, HeaderUnit)>) {
    let mut refused = Vec::new();
    // A column with a unit beside the column under its own name (`sa_deg`
    // beside `alpha`) is another column, left under its name (a reader
    // names the columns it does not read): renamed, it was refused as
    // `alpha` named twice, at a column headed `sa_deg` (round 41).
    let beside = |c: &str, h: &str| h != c && header.iter().any(|o| o == c);
    let names: Vec<String> = header
        .iter()
        .enumerate()
        .map(|(i, h)| match reading(h, (checked, known), by, declared) {
            Some(Reading::Accept(c)) if beside(c, h) => h.to_string(),
            Some(Reading::Refuse(r)) if beside(r.column, h) => h.to_string(),
            Some(Reading::Accept(c)) => c.to_string(),
            Some(Reading::Refuse(r)) => {
                let c = r.column.to_string();
                refused.push((i + 1, r));
                c
            }
            None => h.to_string(),
        })
        .collect();
    (csv::StringRecord::from(names), refused)
}

/// The columns of `checked` whose header (`headers`, read as `named`)
/// states the column's own SI unit under its exact name (`alpha [rad]`,
/// `kappa [-]`): renamed to the column, and not refused (a refused one
/// ends the reading).
pub(super) fn stated_si(
    headers: &csv::StringRecord,
    named: &csv::StringRecord,
    checked: &[&str],
) -> Vec<String> {
    headers
        .iter()
        .zip(named.iter())
        .filter(|(h, n)| h != n && checked.contains(n))
        .filter(|(h, _)| {
            matches!(
                reading(h, (checked, &[]), None, &[]),
                Some(Reading::Accept(_))
            )
        })
        .map(|(_, n)| n.to_string())
        .collect()
}

/// The unit the header column `h` states for `column` (`sa_deg`,
/// `SA [deg]`, `alpha [rad]` for `alpha`), where it names that column with
/// a known unit of its quantity; `None` otherwise (the column's bare name
/// included: it states no unit).
pub(crate) fn unit_of(h: &str, column: &str) -> Option<Unit> {
    let (_, quantity) = quantity_of(column)?;
    match reading(h, (&[column], &[]), None, &[])? {
        Reading::Accept(_) => Some(quantity.si()),
        Reading::Refuse(r) => match r.stated {
            Stated::Known(u) if u.quantity() == quantity => Some(u),
            _ => None,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const RUN: [&str; 5] = ["t", "speed", "steer", "yaw_rate", "ay"];

    fn refused(h: &str, by: Option<DeclaredBy>) -> Option<HeaderUnit> {
        match reading(h, (&RUN, &[]), by, &[]) {
            Some(Reading::Refuse(r)) => Some(r),
            _ => None,
        }
    }

    #[test]
    fn units_in_brackets_and_after_an_underscore_are_read_as_the_column_s() {
        for h in [
            "t [s]",
            "speed (m/s)",
            "steer_rad",
            "yaw_rate [rad/s]",
            "ay [m/s^2]",
        ] {
            assert!(
                matches!(reading(h, (&RUN, &[]), None, &[]), Some(Reading::Accept(_))),
                "{h}"
            );
        }
        // The SI unit under another case is a renaming, said as a slip.
        assert!(reading("Speed [m/s]", (&RUN, &[]), None, &[]).is_none());
        let r = refused("yaw_rate_deg_s", Some(DeclaredBy::MetricsOption)).unwrap();
        assert_eq!(
            (r.column, r.stated),
            ("yaw_rate", Stated::Known(Unit::DegreePerSecond))
        );
        assert_eq!(r.advice, UnitAdvice::Declare(DeclaredBy::MetricsOption));
        // Without a key to declare degrees by, the conversion.
        let r = refused("steer [deg]", None).unwrap();
        assert_eq!(r.advice, UnitAdvice::Convert);
        assert_eq!(
            refused("ay [g]", None).unwrap().stated,
            Stated::Known(Unit::StandardGravity)
        );
        assert_eq!(
            refused("speed [deg]", None).unwrap().advice,
            UnitAdvice::OtherQuantity
        );
        assert_eq!(
            refused("speed [furlong]", None).unwrap().advice,
            UnitAdvice::UnknownUnit
        );
        // The time under a long name, in ms: the conversion, not a
        // renaming alone; in s, a renaming (a slip, said elsewhere).
        for h in ["time [ms]", "time_ms", "Time (ms)", "timestamp_ms"] {
            let r = refused(h, None).unwrap_or_else(|| panic!("{h}"));
            assert_eq!((r.column, r.advice), ("t", UnitAdvice::Convert), "{h}");
        }
        assert!(reading("time [s]", (&RUN, &[]), None, &[]).is_none());
        assert!(refused("time [ms]", None).is_some_and(|r| r.to_string().contains("(÷ 1000)")));
        // `speed_ms` is no unit of a speed after an underscore: a slip.
        assert!(reading("speed_ms", (&RUN, &[]), None, &[]).is_none());
        // A rig's channel name with its unit is the column it stands for.
        let rig = ["fz", "alpha"];
        match reading("SA_deg", (&rig, &[]), None, &[]) {
            Some(Reading::Refuse(r)) => assert_eq!(r.column, "alpha"),
            _ => panic!("SA_deg not read"),
        }
    }

    /// A name and its unit are read alike whatever the name's case and
    /// separators: `Yaw Rate [deg/s]` is refused as `yaw_rate` in deg/s
    /// with the advice `yaw_rate [deg/s]` gets, not left to a
    /// did-you-mean that would read the deg/s as rad/s (round 50).
    #[test]
    fn a_name_with_spaces_or_capitals_gets_the_unit_advice_of_the_column() {
        let by = Some(DeclaredBy::MetricsOption);
        let said = refused("yaw_rate [deg/s]", by).unwrap();
        for h in [
            "Yaw Rate [deg/s]",
            "YAW-RATE (deg/s)",
            "YawRate [deg/s]",
            "Yaw Rate_deg_s",
        ] {
            let r = refused(h, by).unwrap_or_else(|| panic!("{h}"));
            assert_eq!((r.column, &r.stated), ("yaw_rate", &said.stated), "{h}");
            assert_eq!(
                r.advice,
                UnitAdvice::Declare(DeclaredBy::MetricsOption),
                "{h}"
            );
        }
        // In the column's own unit, a renaming alone (a slip, said
        // elsewhere); under its exact name, read.
        assert!(reading("Yaw Rate [rad/s]", (&RUN, &[]), by, &[]).is_none());
        assert!(matches!(
            reading("yaw_rate [rad/s]", (&RUN, &[]), by, &[]),
            Some(Reading::Accept("yaw_rate"))
        ));
        // A long name of the time with spaces, in ms: the conversion.
        let r = refused("Time Stamp [ms]", None).unwrap();
        assert_eq!((r.column, r.advice), ("t", UnitAdvice::Convert));
    }

    /// `sa_deg` (or `alpha [rad]`) beside `alpha` is left under its own
    /// name, neither refused nor read as a second `alpha`; alone, refused.
    #[test]
    fn a_column_with_a_unit_beside_the_column_itself_keeps_its_name() {
        let rig = ["fz", "alpha"];
        let header = csv::StringRecord::from(vec!["fz", "alpha", "sa_deg", "alpha [rad]"]);
        let (named, refused) = canonical(&header, &rig, &[], (None, &[]));
        assert_eq!(
            named.iter().collect::<Vec<_>>(),
            ["fz", "alpha", "sa_deg", "alpha [rad]"]
        );
        assert!(refused.is_empty());
        let alone = csv::StringRecord::from(vec!["fz", "sa_deg"]);
        let (named, refused) = canonical(&alone, &rig, &[], (None, &[]));
        assert_eq!(named.iter().collect::<Vec<_>>(), ["fz", "alpha"]);
        assert_eq!(refused.len(), 1);
        assert_eq!(refused[0].0, 2);
    }

    /// `sa_deg`, `SA [deg]` and `alpha [rad]` state a unit of `alpha`;
    /// `alpha` itself, `sa_kn` (no angle) and `speed [deg]` state none.
    #[test]
    fn the_unit_a_header_states_for_a_column_is_found_by_its_name() {
        assert_eq!(unit_of("sa_deg", "alpha"), Some(Unit::Degree));
        assert_eq!(unit_of("SA [deg]", "alpha"), Some(Unit::Degree));
        assert_eq!(unit_of("alpha [rad]", "alpha"), Some(Unit::Radian));
        assert_eq!(unit_of("kappa [%]", "kappa"), Some(Unit::Percent));
        assert_eq!(unit_of("alpha", "alpha"), None);
        assert_eq!(unit_of("sa_kn", "alpha"), None);
        assert_eq!(unit_of("speed [deg]", "alpha"), None);
        let header = csv::StringRecord::from(vec!["fz", "alpha [rad]", "kappa"]);
        let checked = ["fz", "alpha", "kappa"];
        let (named, _) = canonical(&header, &checked, &[], (None, &[]));
        assert_eq!(stated_si(&header, &named, &checked), ["alpha"]);
    }

    #[test]
    fn a_unit_s_conversion_is_its_factor_to_si() {
        assert_eq!(Unit::parse(" km/h "), Some(Unit::KilometrePerHour));
        assert_eq!(Unit::parse("N·m"), Some(Unit::NewtonMetre));
        assert_eq!(Unit::parse("kPa"), Some(Unit::Kilopascal));
        assert_eq!(Unit::Kilopascal.conversion(), "× 1000");
        assert_eq!(Unit::KilometrePerHour.conversion(), "÷ 3.6");
        assert!(Unit::Degree
            .conversion()
            .contains(&format!("{:.7}", 1f64.to_radians())));
    }
}
