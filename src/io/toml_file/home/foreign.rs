//! Keys of a table that one kind of file has and another lacks, answered
//! with where the thing they set lives in the file at hand: a campaign's
//! `[model.effects]` (a scenario's table; a campaign names its candidate
//! effects in `[diagnose] effects` and fits their sizes) and a scenario's
//! `[tyres] model` (a campaign's key; a scenario's tyre model is its tyre
//! file's). Spelling alone sent the first to a campaign's `[tyres] model`
//! and the second to `mode`, MFeval's switches.

/// A refused key's dotted path, a top-level key that marks the kind of
/// file (one only that kind has), and the clause said after the key.
const FOREIGN: [(&str, &str, &str); 2] = [
    (
        "model",
        "diagnose",
        " (a campaign has no [model] table, which is a scenario's: `handling diagnose` builds its base model from [vehicle], [tyres] and [roll], and the effects it tries are named in `[diagnose] effects = [\"…\"]`, their sizes fitted to the runs)",
    ),
    (
        "tyres.model",
        "manoeuvre",
        " (a scenario's tyre model is its tyre file's: `[tyres] front = \"<tyre file>\"` (and `rear`), whose own `model = \"…\"` names it, or a .tir file; `mode` is a .tir's MFeval useMode, and `model` with `rig` is a campaign's)",
    ),
];

/// The clause for the refused key at dotted `path` of a file whose
/// top-level keys are `top`, where that key belongs to another kind of
/// file.
pub(super) fn clause(path: &str, top: &[String]) -> Option<&'static str> {
    FOREIGN
        .iter()
        .find(|(at, marker, _)| *at == path && top.iter().any(|k| k == marker))
        .map(|(_, _, clause)| *clause)
}

#[cfg(test)]
mod tests {
    use super::clause;

    #[test]
    fn a_key_of_another_kind_of_file_is_answered_for_this_kind() {
        let campaign = ["vehicle".to_string(), "diagnose".to_string()];
        assert!(clause("model", &campaign).is_some_and(|c| c.contains("[diagnose] effects")));
        let scenario = ["tyres".to_string(), "manoeuvre".to_string()];
        assert!(clause("tyres.model", &scenario).is_some_and(|c| c.contains("tyre file")));
        assert_eq!(clause("model", &scenario), None);
    }
}
