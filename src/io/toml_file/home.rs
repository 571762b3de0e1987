//! Where a key refused as unknown belongs, when another table of the same
//! file knows it (`step` written under `[model]` is `[simulation]`'s): the
//! file's type is asked, not a list kept here, so every TOML file the tool
//! reads answers from its own tables. A table's keys are learnt by reading
//! the file again with a key no table has put in it: serde refuses that
//! key with the table's list.

pub(super) mod anywhere;
mod foreign;

use toml_edit::{DocumentMut, TableLike};

/// A key name no table of any file has.
const PROBE: &str = "__handling_probe__";

/// What reads a file's text again as the file's type: its error message,
/// `None` where it reads.
pub(super) type Reparse<'a> = dyn Fn(&str) -> Option<String> + 'a;

/// The names serde lists after `expected ` in an unknown-name message
/// (`one of `a`, `b``, `` `a` or `b` ``, `` `a` ``).
pub(super) fn listed(rest: &str) -> Vec<&str> {
    rest.trim_start_matches("one of ")
        .split(", ")
        .flat_map(|k| k.split(" or "))
        .map(|k| k.trim_matches('`'))
        .filter(|k| !k.is_empty())
        .collect()
}

/// ` (it belongs in [simulation])` for the key at dotted `path` of `text`,
/// refused as unknown in its table: the sibling tables (the tables beside
/// it in its parent, the top-level tables for a key written before any
/// header) that know a key of that name, and the parent itself. `None`
/// where none does, or where the path goes through an array.
pub(super) fn belongs(text: &str, path: &str, reparse: &Reparse) -> Option<String> {
    let parts: Vec<&str> = path.split('.').collect();
    if parts.iter().any(|p| p.contains('[')) {
        return None;
    }
    let (key, table) = parts.split_last()?;
    let known = |at: &[&str]| known_keys(text, &parts, at, reparse).unwrap_or_default();
    if let Some(clause) = foreign::clause(path, &known(&[])) {
        return Some(clause.to_string());
    }
    // A table written where none is known (`[model.effects]`) is sent
    // only to a table that knows a table of its name, not to a key of
    // that name holding a value (a campaign's `[tyres] model`).
    let written_table = is_table(text, &parts);
    let fits = |at: &[&str]| {
        let mut at = at.to_vec();
        at.push(key);
        !written_table || known_keys(text, &parts, &at, reparse).is_some()
    };
    let mut homes = Vec::new();
    let (parent, own) = match table.split_last() {
        Some((own, parent)) => (parent, Some(*own)),
        None => (table, None),
    };
    let beside = known(parent);
    // A key of the parent's own, written inside one of its tables; not
    // where the parent's key of that name is a table itself (`roll` under
    // `[channels]` is no `[roll]` model written in the wrong place).
    let own_table = |k: &str| {
        let at: Vec<&str> = parent.iter().copied().chain([k]).collect();
        known_keys(text, &parts, &at, reparse).is_some()
    };
    if own.is_some() && beside.iter().any(|k| k == key) && !own_table(key) {
        homes.push(name(parent));
    }
    let mut siblings: Vec<(String, Vec<String>)> = Vec::new();
    for sibling in beside.into_iter().filter(|s| Some(s.as_str()) != own) {
        let at: Vec<&str> = parent.iter().copied().chain([sibling.as_str()]).collect();
        let keys = known(&at);
        if keys.iter().any(|k| k == key) && fits(&at) {
            siblings.push((sibling, keys));
        }
    }
    // Two names that take the same keys may be one table read under
    // either (`[integrator]` is `[simulation]`): said once, by its name.
    let names: Vec<&str> = siblings.iter().map(|(s, _)| s.as_str()).collect();
    let one = match siblings.as_slice() {
        [(_, a), rest @ ..] if !rest.is_empty() && rest.iter().all(|(_, k)| k == a) => {
            canonical(text, &parts, parent, &names, reparse)
        }
        _ => None,
    };
    for (sibling, _) in &siblings {
        if one.as_ref().is_none_or(|o| o == sibling) {
            let at: Vec<&str> = parent.iter().copied().chain([sibling.as_str()]).collect();
            homes.push(name(&at));
        }
    }
    (!homes.is_empty()).then(|| format!(" (it belongs {})", homes.join(" or ")))
}

/// Whether the item at `parts` of `text` is a table.
fn is_table(text: &str, parts: &[&str]) -> bool {
    let Ok(doc) = text.parse::<DocumentMut>() else {
        return false;
    };
    let mut item = doc.as_item();
    for p in parts {
        match item.get(p) {
            Some(i) => item = i,
            None => return false,
        }
    }
    item.is_table_like()
}

/// A table's place in words: `in [model.effects]`, or the top level.
fn name(table: &[&str]) -> String {
    if table.is_empty() {
        "before the first [table]".into()
    } else {
        format!("in [{}]", table.join("."))
    }
}

/// `text` without the refused key at `refused` (so that its error does
/// not come first), edited by `edit` at the table at `parent` ([] the top
/// level), as text.
fn edited(
    text: &str,
    refused: &[&str],
    parent: &[&str],
    edit: &dyn Fn(&mut dyn TableLike) -> Option<()>,
) -> Option<String> {
    let mut doc: DocumentMut = text.parse().ok()?;
    let (key, table) = refused.split_last()?;
    let mut t: &mut dyn TableLike = doc.as_table_mut();
    for p in table {
        t = t.get_mut(p)?.as_table_like_mut()?;
    }
    t.remove(key)?;
    // A table the file does not write (`[model]` of a scenario without
    // one) is made, so that the tables under it can be asked too.
    let mut t: &mut dyn TableLike = doc.as_table_mut();
    for p in parent {
        t = table_in(t, p)?;
    }
    edit(t)?;
    Some(doc.to_string())
}

/// The table under `t` called `name`, made where there is none.
fn table_in<'t>(t: &'t mut dyn TableLike, name: &str) -> Option<&'t mut dyn TableLike> {
    t.entry(name)
        .or_insert(toml_edit::table())
        .as_table_like_mut()
}

/// The keys serde knows in the table at `at` ([] the top level) of `text`,
/// the refused key at `refused` taken out: `None` where the table is no
/// table of named keys (a value, a tagged table without its tag, a map of
/// any keys).
fn known_keys(text: &str, refused: &[&str], at: &[&str], reparse: &Reparse) -> Option<Vec<String>> {
    let (parent, last) = match at.split_last() {
        Some((last, parent)) => (parent, Some(*last)),
        None => (at, None),
    };
    let probe = edited(text, refused, parent, &|t| {
        let t = match last {
            Some(last) => table_in(t, last)?,
            None => t,
        };
        t.insert(PROBE, toml_edit::value(0));
        Some(())
    })?;
    let message = reparse(&probe)?;
    let rest = message.strip_prefix(&format!("unknown field `{PROBE}`, expected "))?;
    Some(listed(rest).into_iter().map(String::from).collect())
}

/// Which of the tables `names` under `parent` is the one the others are
/// other names of: serde refuses two names of one field given together
/// as a duplicate of its own name.
fn canonical(
    text: &str,
    refused: &[&str],
    parent: &[&str],
    names: &[&str],
    reparse: &Reparse,
) -> Option<String> {
    let both = edited(text, refused, parent, &|t| {
        for n in names {
            table_in(t, n)?;
        }
        Some(())
    })?;
    let message = reparse(&both)?;
    let name = message
        .strip_prefix("duplicate field `")?
        .split('`')
        .next()?;
    names.contains(&name).then(|| name.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct File {
        name: Option<String>,
        model: Option<Model>,
        #[serde(alias = "integrator")]
        simulation: Option<Simulation>,
    }
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Model {
        kinematics: Option<String>,
    }
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Simulation {
        step: Option<f64>,
        name: Option<String>,
    }

    fn reparse(text: &str) -> Option<String> {
        toml::from_str::<File>(text)
            .err()
            .map(|e| e.message().trim().to_string())
    }

    #[test]
    fn a_key_of_another_table_is_sent_there_and_a_stranger_nowhere() {
        let text = "[model]\nkinematics = \"exact\"\nstep = 0.001\n";
        let said = belongs(text, "model.step", &reparse);
        assert_eq!(said.as_deref(), Some(" (it belongs in [simulation])"));
        // Before any header: the tables are asked.
        let said = belongs("step = 0.001\n[model]\n", "step", &reparse);
        assert_eq!(said.as_deref(), Some(" (it belongs in [simulation])"));
        // Known at the top and in a sibling: both said.
        let said = belongs("[model]\nname = \"a\"\n", "model.name", &reparse);
        assert_eq!(
            said.as_deref(),
            Some(" (it belongs before the first [table] or in [simulation])")
        );
        assert_eq!(
            belongs(
                text.replace("step", "stpe").as_str(),
                "model.stpe",
                &reparse
            ),
            None
        );
    }

    /// `[channels] roll` was sent "before the first [table]" because the
    /// campaign has a `[roll]` table: a key named like one of the parent's
    /// tables is no key of the parent's.
    #[test]
    fn a_key_named_like_a_table_of_the_parent_is_not_sent_there() {
        let said = belongs("[model]\nsimulation = 1\n", "model.simulation", &reparse);
        assert_eq!(said, None);
    }

    #[test]
    fn serdes_lists_are_read_in_each_of_their_forms() {
        assert_eq!(listed("one of `a`, `b`, `c`"), ["a", "b", "c"]);
        assert_eq!(listed("`a` or `b`"), ["a", "b"]);
        assert_eq!(listed("`a`"), ["a"]);
    }
}

/// A required key refused as missing (`missing field `model``) where the
/// file writes it in another case (`Model = "gim"`): that key named, with
/// the fix, since keys are matched exactly and lower case.
pub(super) fn case_slip(text: &str, message: &str) -> Option<String> {
    let name = message.strip_prefix("missing field `")?.split('`').next()?;
    let written = text.lines().find_map(|l| {
        let key = l.split_once('=')?.0.trim();
        (key != name && key.eq_ignore_ascii_case(name)).then_some(key)
    })?;
    Some(format!(
        "missing field `{name}`: the file writes `{written}`, and keys are matched as written, in lower case: rename it `{name}`"
    ))
}

#[cfg(test)]
mod case_tests {
    use super::case_slip;

    #[test]
    fn a_required_key_written_in_capitals_is_named_with_its_fix() {
        let said = case_slip("Model = \"gim\"\nfriction = 1\n", "missing field `model`");
        assert_eq!(
            said.as_deref(),
            Some("missing field `model`: the file writes `Model`, and keys are matched as written, in lower case: rename it `model`")
        );
        assert_eq!(case_slip("friction = 1\n", "missing field `model`"), None);
        assert_eq!(case_slip("Model = 1\n", "invalid type"), None);
    }
}
