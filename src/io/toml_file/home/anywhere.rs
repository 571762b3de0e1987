//! Where a key refused as unknown belongs when no table beside its own
//! knows it: an effect's key written under `[model]` or `[road]`
//! (`relaxation_length` is `[model.effects]`', two tables away from
//! `[road]`), or under the name `diagnose` gives the effect (`bank` for
//! `road_bank`, `cornering_stiffness` for `cornering_stiffness_scale`).
//! Every table the file's type knows is asked, to three levels; an effect
//! no table of the file takes is answered with where the file's kind
//! names it (a campaign's `[diagnose] effects`) or why it has no place
//! (a scenario simulates the car, not its sensors).

use super::{known_keys, name, Reparse};
use crate::diagnose::effects::EffectKind;

/// Other names a key is written under, and the key that sets it: the
/// names `diagnose` gives effects whose scenario key differs, and the
/// short names of the road's bank.
const ALIASES: &[(&str, &str)] = &[
    ("bank", "road_bank"),
    ("bank_angle", "road_bank"),
    ("bank_profile", "bank_profile_scale"),
    ("cornering_stiffness", "cornering_stiffness_scale"),
    ("road_friction", "friction"),
    ("friction_scale", "friction"),
    ("load_transfer_distribution", "load_transfer_front_share"),
    ("relaxation", "relaxation_length"),
];

/// How deep the file's tables are searched (`[model.effects]` is 2).
const DEPTH: usize = 3;

/// ` (it belongs in [model.effects])` for the value at dotted `path` of
/// `text` that its table refused and no sibling table takes: the tables
/// of the file's type anywhere that know its key (or the key it is
/// another name of, said as `(it belongs in [model.effects], as
/// `road_bank`)`); else, for an effect's name, the file kind's answer.
pub(in crate::io::toml_file) fn clause(
    text: &str,
    path: &str,
    reparse: &Reparse,
) -> Option<String> {
    let parts: Vec<&str> = path.split('.').collect();
    if parts.iter().any(|p| p.contains('[')) || super::is_table(text, &parts) {
        return None;
    }
    let (key, own) = parts.split_last()?;
    let meant = ALIASES
        .iter()
        .find(|(alias, _)| alias == key)
        .map_or(*key, |(_, k)| *k);
    let mut homes = Vec::new();
    let mut queue: Vec<Vec<String>> = vec![Vec::new()];
    let mut top = Vec::new();
    while let Some(at) = queue.pop() {
        let at_str: Vec<&str> = at.iter().map(String::as_str).collect();
        let Some(keys) = known_keys(text, &parts, &at_str, reparse) else {
            continue;
        };
        if at.is_empty() {
            top.clone_from(&keys);
        }
        if at_str.as_slice() != own
            && keys.iter().any(|k| k == meant)
            && !is_table_key(text, &parts, &at_str, meant, reparse)
        {
            homes.push(at.clone());
        }
        if at.len() < DEPTH {
            for k in keys.iter().rev() {
                let mut next = at.clone();
                next.push(k.clone());
                queue.push(next);
            }
        }
    }
    homes.sort();
    let alias = match meant != *key {
        true => format!(", as `{meant}`"),
        false => String::new(),
    };
    if !homes.is_empty() {
        let said: Vec<String> = homes
            .iter()
            .map(|h| name(&h.iter().map(String::as_str).collect::<Vec<_>>()))
            .collect();
        return Some(format!(" (it belongs {}{alias})", said.join(" or ")));
    }
    effect_clause(key, meant, &top)
}

/// Whether `key` of the table at `at` is a table itself (`roll` of a
/// campaign): a value written elsewhere is not sent to it.
fn is_table_key(text: &str, refused: &[&str], at: &[&str], key: &str, reparse: &Reparse) -> bool {
    let mut inner = at.to_vec();
    inner.push(key);
    known_keys(text, refused, &inner, reparse).is_some()
}

/// The clause for `written`, a `diagnose` effect's name `key` (or another
/// name of it) that no table of the file takes, by the file's kind (its
/// top-level keys `top`): a campaign names its candidate effects, a
/// scenario has no place for the sensors'.
fn effect_clause(written: &str, key: &str, top: &[String]) -> Option<String> {
    let effect = EffectKind::from_name(key)?;
    let key = match written == key {
        true => format!("`{key}`"),
        false => format!("`{written}`, the effect `{key}`,"),
    };
    let has = |k: &str| top.iter().any(|t| t == k);
    if has("diagnose") {
        Some(format!(
            " ({key} is an effect `handling diagnose` fits to the runs: name it in `[diagnose] effects = [\"{}\"]`)",
            effect.name()
        ))
    } else if has("manoeuvre") && crate::io::scenario::layout::MEASUREMENT.contains(&effect) {
        Some(format!(
            " ({key} is an effect of the measurement (the sensors and the steer they log), not of the car: a scenario simulates the car alone; `handling diagnose` fits it to measured runs, named in a campaign's `[diagnose] effects`)"
        ))
    } else {
        None
    }
}
