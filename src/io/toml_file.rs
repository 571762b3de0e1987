//! TOML loading with errors located in the file: parse and type errors come
//! with toml's own span, value errors found after parsing (a negative mass)
//! are located by looking the key path up in the document's spans.

mod decimal_comma;
mod home;
mod missing_table;
mod names;
mod referenced;
pub(crate) mod vehicle_keys;

use crate::error::{InputError, InputProblem, Location, ParamError};
use home::Reparse;
use serde::de::DeserializeOwned;
use std::path::{Path, PathBuf};

/// What [`TomlSource::find`] asks of every key: (dotted path, key, its
/// table, its item) to an answer that ends the search.
type KeyVisitor<'v, R> =
    dyn FnMut(&str, &str, &dyn toml_edit::TableLike, &toml_edit::Item) -> Option<R> + 'v;

/// Byte range of something in a file's text.
type Span = std::ops::Range<usize>;

/// A TOML file's path and text, kept to locate errors found after parsing.
#[derive(Debug, Clone)]
pub struct TomlSource {
    /// The file.
    pub path: PathBuf,
    /// Its text.
    pub text: String,
}

/// 1-based (line, column) of byte offset `pos` in `text`.
pub(crate) fn line_col(text: &str, pos: usize) -> (usize, usize) {
    let before = &text[..pos.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before
        .rfind('\n')
        .map_or(before.len(), |i| before.len() - i - 1);
    (line, col + 1)
}

/// toml's "expected newline, `#`" (after a value or a table header the
/// line goes on) said as what was found there and what a line holds;
/// other messages unchanged. `rest` is the text from the error's place.
fn plain_syntax(message: &str, rest: Option<&str>) -> String {
    let (after, rule) = match message {
        "expected newline, `#`" => (
            "the value",
            "TOML takes one `key = value` per line, and after the value only a `# comment`",
        ),
        "invalid table header; expected newline, `#`" => (
            "the table header",
            "a `[table]` header stands alone on its line, but for a `# comment`",
        ),
        _ => return message.to_string(),
    };
    match rest.and_then(found_text) {
        Some(found) => format!("unexpected {found} after {after}: {rule}"),
        None => message.to_string(),
    }
}

/// What `rest` starts with, as a message names it: a word or number whole
/// (`b`, `2.5`), a sign (`,`), a character that does not show by its code.
fn found_text(rest: &str) -> Option<String> {
    let word = |c: char| c.is_alphanumeric() || matches!(c, '_' | '-' | '.' | '+');
    let c = rest.chars().next()?;
    Some(if word(c) {
        let end = rest.find(|c: char| !word(c)).unwrap_or(rest.len());
        format!("`{}`", &rest[..end])
    } else if c.is_ascii_graphic() {
        format!("`{c}`")
    } else {
        format!("character {c:?} (U+{:04X})", c as u32)
    })
}

/// serde's type names in `message` said as a TOML writer says them
/// (`expected f64` → `expected a number`, `expected struct Vehicle` → `expected
/// a table`, `expected variant identifier` → `expected a name in quotes`).
fn plain_types(message: &str) -> String {
    let Some((head, expected)) = message.rsplit_once(", expected ") else {
        return message.to_string();
    };
    let word = match expected {
        "f64" | "f32" => "a number",
        "i8" | "i16" | "i32" | "i64" | "isize" => "a whole number",
        // A negative whole number is refused by these: "expected a whole
        // number" for −1 read as a contradiction.
        "u8" | "u16" | "u32" | "u64" | "usize" => "a whole number of 0 or more",
        "variant identifier" => "a name in quotes",
        e if e.starts_with("struct ") || e.starts_with("a map") => "a table",
        e if e.starts_with("a sequence") || e.starts_with("a tuple") => "an array [ … ]",
        _ => return message.to_string(),
    };
    format!("{head}, expected {word}")
}

/// The value a serde message says was of the wrong type or length
/// (`invalid type: string "fast", expected f64`, `invalid length 13, …`).
enum Offender {
    Str(String),
    Array(Option<usize>),
    Int(i64),
    Float(f64),
    Bool(bool),
    /// serde's `map`: a date or time (TOML reads `1970-01-01` as one) or
    /// an inline table.
    Map,
}

/// What `message` says the offending value was, if it says.
fn offender(message: &str) -> Option<Offender> {
    // A name no variant has: the string written (inside a tagged table
    // toml gives it no place).
    if let Some(rest) = message.strip_prefix("unknown variant `") {
        return Some(Offender::Str(rest.split('`').next()?.to_string()));
    }
    if let Some(rest) = message.strip_prefix("invalid length ") {
        let n = rest
            .split(|c: char| !c.is_ascii_digit())
            .next()?
            .parse()
            .ok()?;
        return Some(Offender::Array(Some(n)));
    }
    let what = message
        .strip_prefix("invalid type: ")?
        .split(", expected")
        .next()?;
    let quoted = |prefix: &str| what.strip_prefix(prefix)?.strip_suffix('`');
    if what == "sequence" {
        Some(Offender::Array(None))
    } else if what == "map" || what == "a date, time or table" {
        Some(Offender::Map)
    } else if let Some(s) = what.strip_prefix("string \"") {
        Some(Offender::Str(s.strip_suffix('"')?.to_string()))
    } else if let Some(v) = quoted("integer `") {
        Some(Offender::Int(v.parse().ok()?))
    } else if let Some(v) = quoted("floating point `") {
        Some(Offender::Float(v.parse().ok()?))
    } else {
        quoted("boolean `").and_then(|v| Some(Offender::Bool(v.parse().ok()?)))
    }
}

impl Offender {
    /// Whether `item` is the value described.
    fn is(&self, item: &toml_edit::Item) -> bool {
        item.as_value().is_some_and(|v| self.is_value(v))
    }

    /// Whether `v` is the value described.
    fn is_value(&self, v: &toml_edit::Value) -> bool {
        use toml_edit::Value;
        match (v, self) {
            (Value::String(s), Offender::Str(x)) => s.value() == x,
            (Value::Array(a), Offender::Array(n)) => n.is_none_or(|n| a.len() == n),
            (Value::Integer(i), Offender::Int(x)) => i.value() == x,
            (Value::Float(f), Offender::Float(x)) => f.value() == x,
            (Value::Boolean(b), Offender::Bool(x)) => b.value() == x,
            (Value::Datetime(_) | Value::InlineTable(_), Offender::Map) => true,
            _ => false,
        }
    }
}

impl TomlSource {
    /// Reads a file.
    /// A byte that is not UTF-8 is refused at its line and column (the
    /// column counts the characters before it).
    pub fn read(path: &Path) -> Result<Self, InputError> {
        let bytes = std::fs::read(path).map_err(|source| InputError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let text = String::from_utf8(bytes).map_err(|e| {
            let at = e.utf8_error().valid_up_to();
            let bytes = e.as_bytes();
            let before = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
            let line = before.matches('\n').count() + 1;
            let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
            InputError::problem_at(
                path,
                line,
                column,
                InputProblem::NotUtf8 { byte: bytes[at] },
            )
        })?;
        Ok(Self {
            path: path.to_path_buf(),
            text,
        })
    }

    /// Deserialises the whole file.
    pub fn parse<T: DeserializeOwned>(&self) -> Result<T, InputError> {
        // What serde knows and the file does not say (the names a place
        // takes, the keys of another table) is learnt by reading an edited
        // copy of the file as the same type.
        let reparse = |text: &str| {
            let e = toml::from_str::<T>(text).err()?;
            Some(e.message().trim().to_string())
        };
        // `[vehicle]` keys no vehicle reads set aside (`vehicle_keys`).
        let blanked = self.without_unread_vehicle_keys(&reparse);
        let this = blanked.as_ref().unwrap_or(self);
        toml::from_str(&this.text).map_err(|e| this.toml_error(&e, &reparse))
    }

    fn toml_error(&self, e: &toml::de::Error, reparse: &Reparse) -> InputError {
        let message = self.plain_message(e);
        let message = home::case_slip(&self.text, &message).unwrap_or(message);
        if let Some(missing) = self.missing_table(&message, e.span().as_ref(), reparse) {
            return missing;
        }
        if let Some(missing) = self.headless_table(&message, e.span().as_ref(), reparse) {
            return missing;
        }
        let (span, key) = self.place(e, &message);
        // A name's place holding no name (`kind = 3`): the names are found
        // with a string there, which serde answers with its list.
        let names = |at: Span| {
            let mut probe = self.text.clone();
            probe.replace_range(at, "\"?\"");
            let message = reparse(&probe)?;
            let rest = message.strip_prefix("unknown variant `?`, expected ")?;
            Some(rest.trim_start_matches("one of ").to_string())
        };
        let message = match (&span, message.strip_suffix(", expected a name in quotes")) {
            (Some(at), Some(head)) => match names(at.clone()) {
                Some(list) => format!("{head}, expected one of {list}"),
                None => message,
            },
            _ => message,
        };
        let message = match &key {
            Some(path) => self.sent_home(message, path, reparse),
            None => message,
        };
        match key {
            Some(key) => InputError::Key {
                path: self.path.clone(),
                at: span.map(|s| self.location(s.start)),
                key,
                detail: message,
            },
            None => self.located(span, InputProblem::Toml { detail: message }),
        }
    }

    /// An unknown key's `message` with the tables that know a key of its
    /// name (`unknown field `step` (it belongs in [simulation]), expected
    /// …`): a key in the wrong table is no misspelling, so the place said
    /// replaces a nearest name; other messages unchanged. `path` is the
    /// key's dotted path.
    fn sent_home(&self, message: String, path: &str, reparse: &Reparse) -> String {
        let refused = message
            .strip_prefix("unknown field `")
            .and_then(|r| r.split_once('`'))
            // The key found at the place is the one refused.
            .filter(|(name, _)| path.rsplit('.').next() == Some(*name));
        let Some((name, rest)) = refused else {
            return message;
        };
        // A key serde already answers with a name of its own table (a
        // sine's `steer`: `amplitude`) is no key of another table's.
        let suggested = rest.starts_with(" (did you mean");
        let clause = home::belongs(&self.text, path, reparse).or_else(|| {
            (!suggested)
                .then(|| home::anywhere::clause(&self.text, path, reparse))
                .flatten()
        });
        let Some(clause) = clause else {
            return message;
        };
        let tail = rest.find(", expected").map_or("", |i| &rest[i..]);
        format!("unknown field `{name}`{clause}{tail}")
    }

    /// toml's message for `e` in a TOML writer's words: on one line, with
    /// the nearest known name suggested, serde's type names and toml's
    /// syntax terms said plainly.
    fn plain_message(&self, e: &toml::de::Error) -> String {
        let rest = e.span().and_then(|s| self.text.get(s.start..));
        let mut message = e.message().trim().to_string();
        // toml says nothing of some characters (a lone carriage return):
        // name the one found.
        if message.is_empty() {
            let found = rest.and_then(|r| r.chars().next());
            message = found.map_or("unexpected end of file".into(), |c| {
                format!("unexpected character {c:?} (U+{:04X}) here", c as u32)
            });
        }
        // toml's syntax messages run over lines ("invalid string\nexpected
        // `\"`"): one line, as every other message (a fleet table's row).
        let message = message
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect::<Vec<_>>()
            .join("; ");
        // A number written with a decimal comma stops at the comma.
        let comma = e
            .span()
            .and_then(|s| decimal_comma::hint(&self.text, s.start));
        if let Some(hint) = comma.filter(|_| message == "expected newline, `#`") {
            return hint;
        }
        let message = names::suggest_variant(&message);
        // serde calls a TOML date a map: say what the reader wrote.
        let message = match message.strip_prefix("invalid type: map, ") {
            Some(rest) => format!("invalid type: a date, time or table, {rest}"),
            None => message,
        };
        plain_syntax(&plain_types(&message), rest)
    }

    /// Where the error saying `message` is in the file, and the dotted key
    /// it concerns where one is found.
    fn place(&self, e: &toml::de::Error, message: &str) -> (Option<Span>, Option<String>) {
        // An unknown key: toml puts it at the key, at the whole table in a
        // tagged one (`[manoeuvre]`), nowhere inside a `model`-tagged one.
        // The key of that name within the place given (anywhere without
        // one) is what is wrong.
        let unknown = message
            .strip_prefix("unknown field `")
            .and_then(|r| r.split('`').next());
        if let Some((key, at)) = unknown.and_then(|name| self.find_key(name, e.span())) {
            return (Some(at), Some(key));
        }
        let span = e.span();
        // A value of the wrong type: toml's message names the value, the
        // key is named here; a value that does not parse, by the key
        // written on its line.
        let key = span.as_ref().and_then(|s| {
            self.key_of_value_at(s.start)
                .or_else(|| self.key_on_line_of(s.start))
        });
        if key.is_some() {
            return (span, key);
        }
        // A tagged table (`[manoeuvre]`, a tyre's `model`) reports a wrong
        // type or length at the table or nowhere: the value the message
        // describes is looked up among the table's keys (the document's
        // without a span), and the error put at its key.
        match offender(message).and_then(|o| self.culprit(&o, span.clone())) {
            Some((k, at)) => (Some(at), Some(k)),
            None => (span, None),
        }
    }

    /// The dotted path of the `key = …` written on the line of byte `pos`
    /// (under the last `[table]` header before it), read from the text: a
    /// line whose value does not parse is not in the parsed document.
    fn key_on_line_of(&self, pos: usize) -> Option<String> {
        let before = self.text.get(..pos)?;
        let start = before.rfind('\n').map_or(0, |i| i + 1);
        let line = self.text[start..].lines().next()?;
        let key = line.split_once('=')?.0.trim();
        let bare = |k: &str| {
            !k.is_empty()
                && k.chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'))
        };
        if !bare(key) {
            return None;
        }
        let table = before[..start].lines().rev().find_map(|l| {
            let l = l.trim();
            let name = l.strip_prefix('[')?.split(']').next()?;
            Some(name.trim_matches(['[', ' ']).to_string())
        });
        Some(match table {
            Some(t) if bare(&t) => format!("{t}.{key}"),
            _ => key.to_string(),
        })
    }

    /// The first key (dotted path, and the key's span) within `within`
    /// (anywhere without it) whose value is the one `o` describes.
    fn culprit(&self, o: &Offender, within: Option<Span>) -> Option<(String, Span)> {
        self.find(&mut |path, _, _, item| {
            let at = item.span()?;
            let inside = within
                .as_ref()
                .is_none_or(|w| at.start >= w.start && at.start <= w.end);
            if !inside || item.as_table_like().is_some() {
                return None;
            }
            // At the value, as an error with toml's own span is.
            if o.is(item) {
                return Some((path.to_string(), at));
            }
            // A wrong element of an array (a string among a tyre's
            // coefficients): the element, at its own place.
            let array = item.as_array()?;
            array.iter().enumerate().find_map(|(i, v)| {
                (o.is_value(v) && !matches!(o, Offender::Array(_)))
                    .then(|| (format!("{path}[{i}]"), v.span().unwrap_or(at.clone())))
            })
        })
    }

    /// The dotted path of the key whose value starts at byte `pos`, or of
    /// the element of an array there (`tyres.friction[1]`): toml places a
    /// wrong element at the element itself.
    fn key_of_value_at(&self, pos: usize) -> Option<String> {
        fn within(path: &str, v: &toml_edit::Value, pos: usize) -> Option<String> {
            if v.span().is_some_and(|s| s.start == pos) {
                return Some(path.to_string());
            }
            v.as_array()?
                .iter()
                .enumerate()
                .find_map(|(i, e)| within(&format!("{path}[{i}]"), e, pos))
        }
        self.find(&mut |path, _, _, item| {
            let value = item.as_value().filter(|_| item.as_table_like().is_none())?;
            within(path, value, pos)
        })
    }

    /// The first of `visit`'s answers over every key of the document, depth
    /// first in order, given the key's dotted path, the key, its table and
    /// its item.
    fn find<R>(&self, visit: &mut KeyVisitor<R>) -> Option<R> {
        fn walk<R>(
            t: &dyn toml_edit::TableLike,
            path: &str,
            visit: &mut KeyVisitor<R>,
        ) -> Option<R> {
            for (k, item) in t.iter() {
                let here = if path.is_empty() {
                    k.to_string()
                } else {
                    format!("{path}.{k}")
                };
                if let Some(found) = visit(&here, k, t, item) {
                    return Some(found);
                }
                if let Some(inner) = item.as_table_like() {
                    if let Some(found) = walk(inner, &here, visit) {
                        return Some(found);
                    }
                }
            }
            None
        }
        let doc = toml_edit::ImDocument::parse(self.text.as_str()).ok()?;
        walk(doc.as_table(), "", visit)
    }

    /// Byte span of the value at dotted `key_path` (`vehicle.mass`), of an
    /// array's element or its table's key (`p[3]`, `portraits[1].speed`),
    /// or of the key where its value is a table: an error points at what
    /// is wrong, as toml's own errors of type do.
    pub(crate) fn key_span(&self, key_path: &str) -> Option<Span> {
        let doc = toml_edit::ImDocument::parse(self.text.as_str()).ok()?;
        let mut table: &dyn toml_edit::TableLike = doc.as_table();
        let parts: Vec<(&str, Option<usize>)> = key_path
            .split('.')
            .map(|p| match p.split_once('[') {
                Some((k, i)) => (k, i.trim_end_matches(']').parse().ok()),
                None => (p, None),
            })
            .collect();
        for (i, &(part, index)) in parts.iter().enumerate() {
            // A coefficient named as `--hold` names it (PAC89's `a3`) is
            // element 3 of the file's array `a`.
            let (part, index) = match table.get_key_value(part) {
                None => element_named(part).unwrap_or((part, index)),
                Some(_) => (part, index),
            };
            let (key, item) = table.get_key_value(part)?;
            if i + 1 == parts.len() {
                let value = item.as_value();
                let element = index
                    .and_then(|k| value?.as_array()?.get(k))
                    .and_then(|v| v.span());
                let value = value.and_then(|v| v.span());
                return element
                    .or(value)
                    .or_else(|| key.span())
                    .or_else(|| item.span());
            }
            // An element of an array of tables (`[[a]]` or `a = [{ … }]`):
            // `report.phase_portraits[1].speed`.
            table = match (index, item) {
                (Some(k), toml_edit::Item::ArrayOfTables(a)) => a.get(k)?,
                (Some(k), toml_edit::Item::Value(toml_edit::Value::Array(a))) => {
                    a.get(k)?.as_inline_table()?
                }
                (Some(_), _) => return None,
                (None, _) => item.as_table_like()?,
            };
        }
        None
    }

    /// The dotted path and span of the first key called `name` at any
    /// depth whose span starts within `within` (anywhere without it).
    fn find_key(&self, name: &str, within: Option<Span>) -> Option<(String, Span)> {
        self.find(&mut |path, key, table, _| {
            if key != name {
                return None;
            }
            let at = table.get_key_value(key).and_then(|(k, _)| k.span())?;
            let inside = within.as_ref().is_none_or(|w| w.contains(&at.start));
            inside.then(|| (path.to_string(), at))
        })
    }

    /// A located error for a value that failed validation, with the
    /// places of the keys beside it its reason compares it with.
    pub(crate) fn value_error(&self, e: &ParamError) -> InputError {
        let table = e.key.rsplit_once('.').map(|(t, _)| format!("{t}."));
        let places = (e.reason.read_with().iter())
            .map(|k| format!("{}{k}", table.as_deref().unwrap_or("")))
            .filter_map(|k| {
                let l = self.location(self.key_span(&k)?.start);
                Some(format!(
                    "`{k}` at {}:{}:{}",
                    self.path.display(),
                    l.line,
                    l.column
                ))
            })
            .collect();
        let mut source = e.clone();
        source.reason = source.reason.placed(places);
        InputError::Value {
            path: self.path.clone(),
            at: self.key_span(&e.key).map(|s| self.location(s.start)),
            source,
        }
    }

    /// The line and column of byte `pos`.
    fn location(&self, pos: usize) -> Location {
        let (line, column) = line_col(&self.text, pos);
        Location { line, column }
    }

    /// An error at `span` of this file, or of the whole file without one.
    pub(crate) fn located(&self, span: Option<Span>, problem: InputProblem) -> InputError {
        InputError::Invalid {
            path: self.path.clone(),
            at: span.map(|s| self.location(s.start)),
            problem: Box::new(problem),
        }
    }
}

/// Reads and deserialises a TOML file.
pub fn load_toml<T: DeserializeOwned>(path: &Path) -> Result<(T, TomlSource), InputError> {
    let src = TomlSource::read(path)?;
    let value = src.parse()?;
    Ok((value, src))
}

/// A validation error located in `src`, with the key prefixed by `table`.
pub fn param_error(src: &TomlSource, table: Option<&str>, e: ParamError) -> InputError {
    let e = match table {
        Some(t) => e.within(t),
        None => e,
    };
    src.value_error(&e)
}

/// An array's element named as `--hold` names it, `a3` for `a[3]`: the
/// array's name and the index, or `None` for a name not of that form.
fn element_named(part: &str) -> Option<(&str, Option<usize>)> {
    let at = part.find(|c: char| c.is_ascii_digit())?;
    let (name, index) = part.split_at(at);
    let alphabetic = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphabetic());
    alphabetic
        .then(|| (name, index.parse().ok()))
        .filter(|(_, k)| k.is_some())
}
