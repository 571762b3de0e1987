//! An error's message as Python says it: the library's messages name the
//! command line's options (`metrics --degrees steer`, "drop --load"),
//! which a Python user does not type; raised from Python they name the
//! keyword instead (`degrees=["steer"]`, "drop `load=`"). Only the
//! spelling of options changes; numbers and every other word stay.

use pyo3::prelude::*;

/// `--name` (letters, digits and dashes) as its keyword, `name` with
/// underscores.
pub(crate) fn keyword(flag: &str) -> String {
    flag.trim_start_matches("--").replace('-', "_")
}

/// A value as Python writes it: a number as it is, anything else quoted;
/// a list for `degrees` (the columns in degrees).
fn value(name: &str, v: &str) -> String {
    let quoted = |s: &str| {
        if s.parse::<f64>().is_ok() {
            s.to_string()
        } else {
            format!("\"{s}\"")
        }
    };
    if name == "degrees" {
        let each: Vec<String> = v.split(',').map(|c| format!("\"{}\"", c.trim())).collect();
        return format!("[{}]", each.join(", "));
    }
    // `mf61|mf62`: either value, each quoted.
    v.split('|').map(quoted).collect::<Vec<_>>().join("|")
}

/// A quoted command (`metrics --degrees steer`, `--camber 2`,
/// `identify --model mf61|mf62`) as keywords (`degrees=["steer"]`,
/// `camber=2`, `model="mf61"|"mf62"`; a flag alone, `--max-ax`, as
/// `max_ax`); None where it names no option.
fn quoted_command(span: &str) -> Option<String> {
    let at = span.find("--")?;
    let words: Vec<&str> = span[at..].split_whitespace().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < words.len() {
        let w = words[i];
        if !w.starts_with("--") {
            return None;
        }
        let name = keyword(w);
        match words.get(i + 1).filter(|v| !v.starts_with("--")) {
            Some(v) => {
                out.push(format!("{name}={}", value(&name, v)));
                i += 2;
            }
            // A flag alone, as in "`--max-ax` = 0": its keyword's name.
            None => {
                out.push(name);
                i += 1;
            }
        }
    }
    Some(out.join(", "))
}

/// The message with each option the command line spells (`--load`, in
/// quotes or bare) spelt as Python's keyword.
pub fn pythonic(message: &str) -> String {
    // Quoted spans first: `…` pairs.
    let mut out = String::new();
    let mut parts = message.split('`');
    if let Some(first) = parts.next() {
        out += &bare(first);
    }
    let rest: Vec<&str> = parts.collect();
    for (k, part) in rest.iter().enumerate() {
        let inside = k % 2 == 0 && k + 1 < rest.len();
        if inside {
            match quoted_command(part) {
                Some(py) => out += &format!("`{py}`"),
                None => out += &format!("`{part}`"),
            }
        } else if k % 2 == 0 {
            // An unpaired backtick: the rest as it is.
            out += "`";
            out += &bare(part);
        } else {
            out += &bare(part);
        }
    }
    out
}

/// Bare `--name` words (outside quotes) as `` `name=` ``.
fn bare(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("--") {
        let after = &rest[at + 2..];
        let len = after
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .unwrap_or(after.len());
        let starts_word = at == 0 || rest[..at].ends_with([' ', '(', '"', '\'']);
        if len == 0 || !starts_word || !after.starts_with(|c: char| c.is_ascii_lowercase()) {
            out += &rest[..at + 2];
            rest = after;
            continue;
        }
        out += &rest[..at];
        out += &format!("`{}=`", keyword(&after[..len]));
        rest = &after[len..];
    }
    out + rest
}

/// [`pythonic`] as the package's tests call it
/// (`handling._handling._pythonic`, python/tests/test_spelling.py): the
/// rule is checked through the built extension, so CI builds the library
/// once for Python and not a second time, linked to libpython, for a Rust
/// unit test of the extension crate. Not part of the package's API.
#[pyfunction]
pub(crate) fn _pythonic(message: &str) -> String {
    pythonic(message)
}
