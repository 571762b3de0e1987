//! The value each condition of a swarm fit was fitted at, said where it
//! is not the name of its level. Every line names a level by the median
//! of every sample of it in the file (`level_names.rs`: the Hoosier
//! file's 1656 N), while a condition's own load, camber and pressure are
//! the medians of its samples fitted (`identify/grouping/fitted.rs`:
//! 1639.7 N at 0° and 83.4 kPa), which the report's `curves`, the figure's
//! fitted lines and the tyre's reference load are. Unsaid, the terminal's
//! `Fz 1656 N` and the report's `1639.7` read as two loads of one fit.
//! Units: N, rad (said in degrees), Pa (said in kPa).

use super::level_names::LevelNames;
use super::SwarmReport;
use crate::identify::grouping::Variable;
use crate::identify::CurveReport;

/// The note of the conditions whose own load, camber or pressure is not
/// the name of its level as the terminal spells both (`None`: each is).
pub(crate) fn own_values_note(r: &SwarmReport) -> Option<String> {
    let names = r.level_names();
    let curves = [Some(&r.fit), r.longitudinal.as_ref()]
        .into_iter()
        .flatten()
        .flat_map(|f| f.curves.iter());
    let mut said: Vec<String> = Vec::new();
    for c in curves {
        for entry in differing(c, &names) {
            if !said.contains(&entry) {
                said.push(entry);
            }
        }
    }
    (!said.is_empty()).then(|| {
        format!(
            "a condition's load, camber and pressure are the medians of its samples fitted (the report's `curves`, the figure's fitted lines and the tyre's reference load where its model has one), inside the level the lines above name by every sample of it in the file: {}",
            said.join(", ")
        )
    })
}

/// A condition's own load `fz` to 0.1 N ([`own_load_text`]), the report's
/// number, with its level's name where that differs (`1639.7 N (1656 N
/// level)`), else the level's name alone: the figure's key of the line
/// drawn at it.
pub(crate) fn own_load(fz: f64, names: &LevelNames) -> String {
    let level = names.load(fz);
    if Variable::Load.display(fz) == level {
        level
    } else {
        format!("{} ({level} level)", own_load_text(fz))
    }
}

/// A condition's own load, N, to 0.1 N whatever its digits, in the
/// figure's key: the report's `curves[].fz` is the median of the samples
/// fitted, which has as many digits as the samples do or one more, and
/// said as written one key read `524 N`, `1639.7 N`, `2736.55 N`, three
/// rules for one quantity.
fn own_load_text(fz: f64) -> String {
    format!("{} N", crate::format::fixed(fz, 1))
}

/// The words of `c`'s values that its level is named otherwise, each to
/// the rounding of its level's name (`1640 N in the 1656 N level`), as
/// the terminal spells it.
fn differing(c: &CurveReport, names: &LevelNames) -> Vec<String> {
    let mut out = Vec::new();
    // The load too as its level is named, in whole newtons: said to 0.1 N
    // beside a level so named, the note read `1082.0 N in the 1095 N
    // level`, two rules in one phrase.
    let mut other = |variable: Variable, v: f64| {
        let (own, level) = (variable.display(v), names.name(variable, v));
        if own != level {
            let what = match variable {
                Variable::Load => String::new(),
                _ => format!("{} ", variable.column()),
            };
            out.push(format!("{what}{own} in the {level} level"));
        }
    };
    other(Variable::Load, c.fz);
    other(Variable::Camber, c.camber);
    if let Some(p) = c.pressure {
        other(Variable::Pressure, p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::grouping::levels;

    fn curve(fz: f64) -> CurveReport {
        CurveReport {
            fz,
            camber: 0.0,
            pressure: None,
            points: 10,
            samples: 10,
            sigma_percent: 1.0,
            rms: 1.0,
        }
    }

    #[test]
    fn a_condition_inside_its_level_is_said_with_its_own_load() {
        // A level whose samples' median is 1656 N, fitted at 1639.7 N.
        let fz: Vec<f64> = (0..41).map(|i| 1506.0 + 7.5 * f64::from(i)).collect();
        let loads = [levels(Variable::Load, &fz, 10.0)];
        let names = LevelNames::of(&loads, &[]);
        assert_eq!(names.load(1639.7), "1656 N");
        assert_eq!(
            differing(&curve(1639.7), &names),
            vec!["1640 N in the 1656 N level".to_string()]
        );
        // At its level's name, within its rounding, or outside every
        // level, nothing to say.
        assert!(differing(&curve(1656.0), &names).is_empty());
        assert!(differing(&curve(1655.6), &names).is_empty());
        assert!(differing(&curve(4000.0), &names).is_empty());
        // The figure's key: the report's number beside the level's name.
        assert_eq!(own_load(1639.7, &names), "1639.7 N (1656 N level)");
        assert_eq!(own_load(1656.0, &names), "1656 N");
        // One rule for every load of a key: 0.1 N (the Hoosier file's
        // loads once read 524 N, 1639.7 N and 2736.55 N in one key).
        assert_eq!(own_load_text(524.0), "524.0 N");
        assert_eq!(own_load_text(2736.57), "2736.6 N");
    }

    #[test]
    fn a_notes_load_and_its_levels_name_are_said_to_one_rounding() {
        // The Hoosier file's second level, named 1095 N, fitted at
        // 1082.04 N: the note read `1082.0 N in the 1095 N level`.
        let fz: Vec<f64> = (0..41).map(|i| 1065.0 + 1.5 * f64::from(i)).collect();
        let loads = [levels(Variable::Load, &fz, 10.0)];
        let names = LevelNames::of(&loads, &[]);
        assert_eq!(names.load(1082.04), "1095 N");
        let said = differing(&curve(1082.04), &names);
        assert_eq!(said, vec!["1082 N in the 1095 N level".to_string()]);
        // Both numbers of the phrase spelt by one rule: whole newtons.
        let numbers: Vec<&str> = said[0]
            .split(' ')
            .filter(|w| w.starts_with(|c: char| c.is_ascii_digit()))
            .collect();
        assert_eq!(numbers, ["1082", "1095"]);
    }
}
