//! The line said when `identify --model mf61|mf62` writes another Magic
//! Formula version than its `--template` holds (a 6.2 template fitted as
//! `--model mf61` was written `FITTYP = 61` without a word). The version
//! written is the one asked for; the line says what changes with it. In
//! this program's MF 6.1 and 6.2 the force and moment equations are the
//! same; the vertical model differs: 6.2's camber, Fy-shift and Fy-power
//! terms of the vertical stiffness ([`MF62_ONLY`], TNO MF-Tyre 6.2
//! equation manual; MFeval's `calculateRhoRl61` reads none of them) are
//! not read from a 6.1 file.

use crate::tyre::mf::vertical::MF62_ONLY;
use crate::tyre::mf::{MagicFormula, MfVersion};

/// The version's name and `FITTYP`, as said.
fn named(v: MfVersion) -> String {
    let name = match v {
        MfVersion::Mf52 => "MF 5.2",
        MfVersion::Mf61 => "MF 6.1",
        MfVersion::Mf62 => "MF 6.2",
    };
    format!("{name} (FITTYP = {})", v.fittyp())
}

/// The `--model` that writes version `v`, if `identify` fits it.
fn model_of(v: MfVersion) -> Option<&'static str> {
    match v {
        MfVersion::Mf52 => None,
        MfVersion::Mf61 => Some("mf61"),
        MfVersion::Mf62 => Some("mf62"),
    }
}

/// The line on a `template` of another version than the one `written`
/// (`None`: the same version).
pub(super) fn change_line(template: &MagicFormula, written: MfVersion) -> Option<String> {
    let from = template.version;
    if from == written {
        return None;
    }
    let what = match (from, written) {
        (MfVersion::Mf62, MfVersion::Mf61) => {
            let c = &template.coefficients;
            let set: Vec<String> = MF62_ONLY
                .iter()
                .filter_map(|k| c.get(k).filter(|v| *v != 0.0).map(|v| format!("{k} = {v}")))
                .collect();
            if set.is_empty() {
                "; the forces and moments are those of the same equations, and the template sets none of 6.2's vertical-stiffness terms (Q_CAM1-3, Q_FYS1-3, Q_FCY2), so nothing it holds is dropped".to_string()
            } else {
                format!(
                    "; the forces and moments are those of the same equations, but 6.2's vertical-stiffness terms the template sets ({}) stay in the file unread: a 6.1 file's vertical stiffness has no camber, Fy-shift or Fy-power terms, so its loaded radius no longer follows camber and lateral force as the template's did",
                    set.join(", ")
                )
            }
        }
        (MfVersion::Mf61, MfVersion::Mf62) => {
            "; the forces and moments are those of the same equations, and 6.2's vertical-stiffness terms (Q_CAM1-3, Q_FYS1-3, Q_FCY2) are read where the file gives them".to_string()
        }
        _ => "; its coefficients are read with the written version's equations".to_string(),
    };
    let keep = model_of(from).map_or(String::new(), |m| {
        format!(" (--model {m} keeps the template's version)")
    });
    Some(format!(
        "version: the template is {}, the written file {} as --model asks{keep}{what}",
        named(from),
        named(written),
    ))
}
