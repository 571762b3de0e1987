//! Reader and writer of TNO/ADAMS tyre property files (`.tir`) holding a
//! Magic Formula 5.2, 6.1 or 6.2 tyre.
//!
//! The format: `[SECTION]` headers, `KEY = value` lines whose value is a
//! number, a quoted string (`'…'` or `"…"`) or a bare word, comments after
//! `!` or `$` (a line starting with `$` is a comment), and free-form table
//! rows (e.g. `[SHAPE]`) that are kept as they are. `[UNITS]` names the
//! file's units; the dimensional coefficients the model reads (`FNOMIN`,
//! `UNLOADED_RADIUS`, `LONGVL`, `VXLOW`, `NOMPRES`, `INFLPRES`) are
//! converted to SI, every other Magic Formula coefficient is dimensionless.
//! `[MODEL]` gives `FITTYP` (the version) and `TYRESIDE`; the validity
//! ranges (`FZMIN`/`FZMAX`, `KPUMIN`/`KPUMAX`, `ALPMIN`/`ALPMAX`,
//! `CAMMIN`/`CAMMAX`, `PRESMIN`/`PRESMAX`) are read for MFeval's limit
//! checks ([`crate::tyre::mf::MfMode`]), loads and pressures converted.
//!
//! A value no tyre has (`FNOMIN` in kN, a radius in mm, a pressure in kPa,
//! a coefficient of 1e30) is refused at its line ([`crate::tyre::sizes`]);
//! where it is a tyre's as written but not once converted by the file's
//! `[UNITS]`, the refusal names that `[UNITS]` line (`units.rs`). A file
//! read as a tyre has its own pure-slip curves judged too (a fit's
//! template is warned of, [`TirDocument::curve_refusal`]): a peak friction above 5, or a force that turns against its
//! slip, is refused at the coefficient most likely at fault
//! (`tyre/mf/pure_curves.rs`).
//!
//! Writing starts from the file that was read and replaces only the values
//! the model holds (in the file's own units), so comments, sections and
//! keys the model does not read round-trip unchanged. Each value is
//! written as the shortest text that reads back as the same number
//! ([`crate::format::exact`]: `4000`, `1`, `1.5e-7`). The validity ranges
//! are written in their published sections (`ranges.rs`).

use crate::error::{DuplicateAt, InputError, InputProblem, ModeError};
use crate::format::exact;
use crate::tyre::mf::{
    MagicFormula, MfCoefficients, MfLimits, MfMode, MfOptions, MfVersion, TyreSide,
};
use crate::tyre::{ModelParameters, Tyre};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The value of a `KEY = value` line.
#[derive(Debug, Clone, PartialEq)]
pub enum TirValue {
    /// A number.
    Number(f64),
    /// A quoted string or a bare word (quotes removed).
    Text(String),
}

/// One `KEY = value` line.
#[derive(Debug, Clone, PartialEq)]
pub struct TirEntry {
    /// The section it is in (upper case, without brackets).
    pub section: String,
    /// The key (upper case).
    pub key: String,
    /// The value.
    pub value: TirValue,
    /// Byte range of the value in the line's text.
    span: (usize, usize),
}

/// A `.tir` file as read: its lines, parsed where they are entries.
#[derive(Debug, Clone, PartialEq)]
pub struct TirDocument {
    /// The file it came from.
    pub path: PathBuf,
    /// Each line's text and, for `KEY = value` lines, the entry.
    pub lines: Vec<(String, Option<TirEntry>)>,
}

impl TirDocument {
    /// Parses the text of a `.tir` file.
    pub fn parse(path: &Path, text: &str) -> Result<Self, InputError> {
        let mut section = String::new();
        let mut lines = Vec::new();
        let mut seen = HashMap::new();
        let mut elsewhere = HashMap::new();
        for (i, raw) in text.lines().enumerate() {
            let trimmed = raw.trim_start();
            let entry = if trimmed.is_empty()
                || trimmed.starts_with('$')
                || trimmed.starts_with('!')
                || trimmed.starts_with('{')
            {
                None
            } else if let Some(rest) = trimmed.strip_prefix('[') {
                let end = rest.find(']').ok_or_else(|| {
                    InputError::problem_at(
                        path,
                        i + 1,
                        raw.len() - trimmed.len() + 1,
                        InputProblem::TirSectionUnclosed {
                            header: trimmed.to_string(),
                        },
                    )
                })?;
                section = rest[..end].trim().to_ascii_uppercase();
                None
            } else if let Some(eq) = raw.find('=') {
                let e = parse_entry(path, i + 1, raw, eq, &section)?;
                let column = raw.len() - trimmed.len() + 1;
                refuse_duplicate(path, (i + 1, column), &e, &mut seen, &mut elsewhere)?;
                Some(e)
            } else {
                None
            };
            lines.push((raw.to_string(), entry));
        }
        Ok(Self {
            path: path.to_path_buf(),
            lines,
        })
    }

    /// Reads and parses a `.tir` file.
    pub fn read(path: &Path) -> Result<Self, InputError> {
        let bytes = std::fs::read(path).map_err(|source| InputError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        // Some public files are Latin-1 in their comments, which are read
        // past; a byte that is not UTF-8 before a line's comment would reach
        // a key or value as `�`, so it is refused where it stands.
        if let Some((line, column, byte)) = not_utf8_outside_comments(&bytes) {
            return Err(InputError::problem_at(
                path,
                line,
                column,
                InputProblem::NotUtf8 { byte },
            ));
        }
        let text = String::from_utf8_lossy(&bytes);
        Self::parse(path, &text)
    }

    /// The entries, with their 1-based line numbers.
    pub fn entries(&self) -> impl Iterator<Item = (usize, &TirEntry)> {
        self.lines
            .iter()
            .enumerate()
            .filter_map(|(i, (_, e))| e.as_ref().map(|e| (i + 1, e)))
    }

    /// The last entry for `key` (upper case) and its line.
    pub fn get(&self, key: &str) -> Option<(usize, &TirEntry)> {
        self.entries().filter(|(_, e)| e.key == key).last()
    }

    fn text(&self, key: &str) -> Option<(usize, String)> {
        self.get(key).map(|(l, e)| match &e.value {
            TirValue::Text(t) => (l, t.trim().to_ascii_lowercase()),
            TirValue::Number(x) => (l, format!("{x}")),
        })
    }

    /// The value of the entry on `line` as the file writes it.
    fn written(&self, line: usize) -> &str {
        let (text, entry) = &self.lines[line - 1];
        entry.as_ref().map_or("", |e| &text[e.span.0..e.span.1])
    }

    /// `problem` at the value of the entry on `line`.
    fn at(&self, line: usize, problem: InputProblem) -> InputError {
        let column = self.lines[line - 1].1.as_ref().map_or(1, |e| e.span.0 + 1);
        InputError::problem_at(&self.path, line, column, problem)
    }

    /// The Magic Formula tyre of this file, in SI.
    pub fn magic_formula(&self) -> Result<MagicFormula, InputError> {
        self.core_coefficients(true)?;
        let tyre = self.template()?;
        // The curves of the forces the file describes (a template's are
        // the fit's to set, so only a tyre read to be used is judged).
        let (lateral, longitudinal) = (self.get("PDY1").is_some(), self.get("PDX1").is_some());
        tyre.check_pure_curves(lateral, longitudinal)
            .map_err(|e| self.value_error(e))?;
        self.cornering_at_nominal(&tyre)?;
        Ok(tyre)
    }

    /// The refusal a tyre read from this file as `tyre` would meet for its
    /// pure curves (of the forces the file describes), as text with the
    /// file and line, or `None`: a fit's template is warned of, not
    /// refused, as the fit sets the coefficients it starts from (a block no
    /// stage fits is written as the template has it, and said again then).
    pub fn curve_refusal(&self, tyre: &MagicFormula) -> Option<String> {
        let (lateral, longitudinal) = (self.get("PDY1").is_some(), self.get("PDX1").is_some());
        let e = tyre.check_pure_curves(lateral, longitudinal).err()?;
        Some(self.value_error(e).to_string())
    }

    /// The Magic Formula tyre of this file as a template of a fit: its
    /// constants, and coefficients that may be none (a fit sets them); the
    /// core coefficients of each force it does describe must be there.
    pub fn template(&self) -> Result<MagicFormula, InputError> {
        self.core_coefficients(false)?;
        let units = self.units()?;
        let version = match self.get("FITTYP") {
            Some((line, fittyp)) => match &fittyp.value {
                TirValue::Number(x) if x.fract() == 0.0 => MfVersion::from_fittyp(*x as i64),
                _ => None,
            }
            .ok_or_else(|| {
                self.at(
                    line,
                    InputProblem::TirUnsupportedFittyp {
                        written: self.written(line).to_string(),
                    },
                )
            })?,
            // ADAMS PAC2002 files (e.g. Chrono's) often carry no FITTYP:
            // their format is MF 5.2 (FITTYP 6).
            None => match self.text("PROPERTY_FILE_FORMAT") {
                Some((_, f)) if f == "pac2002" => MfVersion::Mf52,
                _ => return Err(InputError::problem(&self.path, InputProblem::TirNoFittyp)),
            },
        };
        let side = match self.text("TYRESIDE") {
            None => TyreSide::Left,
            Some((_, s)) if s == "left" || s == "unknown" || s == "symmetric" => TyreSide::Left,
            Some((_, s)) if s == "right" => TyreSide::Right,
            Some((line, s)) => return Err(self.at(line, InputProblem::TirSide { side: s })),
        };
        let mut c = MfCoefficients::default();
        let mut limits = MfLimits::default();
        for (line, e) in self.entries() {
            let is_limit = MfLimits::KEYS.contains(&e.key.as_str());
            if c.get(&e.key).is_none() && !is_limit {
                continue;
            }
            match &e.value {
                TirValue::Number(x) if is_limit => {
                    limits.set(&e.key, x * units.factor(&e.key));
                }
                TirValue::Number(x) => {
                    c.set(&e.key, x * units.factor(&e.key));
                }
                TirValue::Text(t) => {
                    return Err(self.at(
                        line,
                        InputProblem::TirNotANumber {
                            key: e.key.clone(),
                            text: t.clone(),
                        },
                    ));
                }
            }
        }
        for key in ["FNOMIN", "UNLOADED_RADIUS"] {
            if self.get(key).is_none() {
                return Err(InputError::problem(
                    &self.path,
                    InputProblem::TirMissingKey { key },
                ));
            }
        }
        let tyre = MagicFormula {
            version,
            side,
            options: MfOptions::default(),
            limits,
            coefficients: c,
        };
        tyre.validate()
            .and_then(|()| ModelParameters::check_sizes(&tyre))
            .map_err(|e| self.value_error(self.declared_slip(&tyre, &units, e)))?;
        self.reference_speed(&tyre)?;
        self.loads_against_nominal(&tyre, &units)?;
        Ok(tyre)
    }

    /// `e` at the line of its key, or at the file where it has none.
    fn value_error(&self, e: crate::error::ParamError) -> InputError {
        match self.get(&e.key) {
            Some((line, _)) => self.at(line, InputProblem::TirValue(e)),
            None => InputError::Value {
                path: self.path.clone(),
                at: None,
                source: e,
            },
        }
    }

    /// The file's text with the values of `tyre` in place of the ones read
    /// (in the file's units; `FITTYP` and `TYRESIDE` too). Coefficients the
    /// file lacks but `tyre` sets away from their default are appended in a
    /// section of their own. Everything else is kept as it was.
    pub fn write(&self, tyre: &MagicFormula) -> Result<String, InputError> {
        let units = self.units()?;
        let c = &tyre.coefficients;
        let mut out = String::new();
        let mut seen = std::collections::BTreeSet::new();
        for (text, entry) in &self.lines {
            let Some(e) = entry else {
                out.push_str(text);
                out.push('\n');
                continue;
            };
            let replacement = match e.key.as_str() {
                "FITTYP" => Some(tyre.version.fittyp().to_string()),
                "TYRESIDE" => Some(
                    match tyre.side {
                        TyreSide::Left => "'LEFT'",
                        TyreSide::Right => "'RIGHT'",
                    }
                    .to_string(),
                ),
                k if MfLimits::KEYS.contains(&k) => {
                    let read = match e.value {
                        TirValue::Number(x) => Some(x),
                        TirValue::Text(_) => None,
                    };
                    ranges::range_replacement(&tyre.limits, units, k, read)
                }
                k => c.get(k).map(|v| exact(v / units.factor(k))),
            };
            seen.insert(e.key.clone());
            match replacement {
                Some(r) => {
                    out.push_str(&text[..e.span.0]);
                    out.push_str(&r);
                    out.push_str(&text[e.span.1..]);
                }
                None => out.push_str(text),
            }
            out.push('\n');
        }
        let defaults = MfCoefficients::default();
        let missing: Vec<_> = MfCoefficients::NAMES
            .iter()
            .filter(|k| !seen.contains(**k) && c.get(k) != defaults.get(k))
            .collect();
        if !missing.is_empty() {
            out.push_str("$ coefficients set by handling that the original file lacked\n");
            out.push_str("[HANDLING_ADDED]\n");
            for k in missing {
                let v = c.get(k).unwrap_or(0.0) / units.factor(k);
                out.push_str(&format!("{k:<25} = {}\n", exact(v)));
            }
        }
        out.push_str(&ranges::range_sections(&tyre.limits, units, &|k| {
            seen.contains(k)
        }));
        Ok(out)
    }
}

/// A fresh `.tir` text for a tyre that did not come from a file (SI units),
/// with the physical constants it leaves at 0 stated (`stated.rs`).
pub(crate) fn write_new(tyre: &MagicFormula) -> String {
    let tyre = &crate::tyre::mf::stated::with_stated(tyre);
    let c = &tyre.coefficients;
    let mut s = String::from(
        "[MDI_HEADER]\nFILE_TYPE = 'tir'\nFILE_VERSION = 3.0\nFILE_FORMAT = 'ASCII'\n\
         $ written by handling\n[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\n\
         ANGLE = 'radians'\nMASS = 'kg'\nTIME = 'second'\n[MODEL]\n",
    );
    s.push_str(&format!("FITTYP = {}\n", tyre.version.fittyp()));
    s.push_str(match tyre.side {
        TyreSide::Left => "TYRESIDE = 'LEFT'\n",
        TyreSide::Right => "TYRESIDE = 'RIGHT'\n",
    });
    s.push_str("[COEFFICIENTS]\n");
    for k in MfCoefficients::NAMES {
        s.push_str(&format!("{k:<25} = {}\n", exact(c.get(k).unwrap_or(0.0))));
    }
    s.push_str(&ranges::range_sections(&tyre.limits, Units::SI, &|_| false));
    s
}

/// Sets MFeval's `useMode` `code` (111, 121, 211, 221) on a Magic Formula
/// tyre; the reason when the code is refused or the tyre is of another
/// model (only the Magic Formula has modes).
pub fn set_tyre_mode(tyre: &mut Tyre, code: u32) -> Result<(), ModeError> {
    let mode = MfMode::from_use_mode(code)?;
    match tyre {
        Tyre::MagicFormula(t) => {
            t.set_mode(mode);
            Ok(())
        }
        other => Err(ModeError::NotMagicFormula {
            code,
            model: other.model_name().to_string(),
        }),
    }
}

/// Reads the Magic Formula tyre of a `.tir` file.
pub fn load_tir(path: &Path) -> Result<MagicFormula, InputError> {
    TirDocument::read(path)?.magic_formula()
}

/// The first byte that is not UTF-8 outside a comment (after `$` or `!`,
/// or a line starting with `$`, `!` or `{`): its line, its column (the
/// characters before it, plus one) and the byte.
fn not_utf8_outside_comments(bytes: &[u8]) -> Option<(usize, usize, u8)> {
    for (i, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let Err(e) = std::str::from_utf8(raw) else {
            continue;
        };
        let at = e.valid_up_to();
        // Bytes before `at` are UTF-8, where `$` and `!` are themselves.
        let before = std::str::from_utf8(&raw[..at]).unwrap_or_default();
        let comment = before.contains(['$', '!']) || before.trim_start().starts_with('{');
        if !comment {
            return Some((i + 1, before.chars().count() + 1, raw[at]));
        }
    }
    None
}

fn parse_entry(
    path: &Path,
    line: usize,
    raw: &str,
    eq: usize,
    section: &str,
) -> Result<TirEntry, InputError> {
    let key = raw[..eq].trim().to_ascii_uppercase();
    let after = &raw[eq + 1..];
    let lead = after.len() - after.trim_start().len();
    let start = eq + 1 + lead;
    let body = &raw[start..];
    let at =
        |column: usize, problem: InputProblem| InputError::problem_at(path, line, column, problem);
    if key.is_empty() || key.contains(char::is_whitespace) {
        return Err(at(
            1,
            InputProblem::TirNotAKey {
                text: raw[..eq].trim().to_string(),
            },
        ));
    }
    let (value, len) = if let Some(q) = body.chars().next().filter(|c| *c == '\'' || *c == '"') {
        let end = body[1..].find(q).ok_or_else(|| {
            at(
                start + 1,
                InputProblem::TirStringUnclosed {
                    key: key.clone(),
                    body: body.to_string(),
                    quote: q,
                },
            )
        })?;
        (TirValue::Text(body[1..1 + end].to_string()), end + 2)
    } else {
        let len = body
            .find(|c: char| c == '$' || c == '!' || c.is_whitespace())
            .unwrap_or(body.len());
        let word = &body[..len];
        if word.is_empty() {
            return Err(at(start + 1, InputProblem::TirNoValue { key }));
        }
        let value = match word.parse::<f64>() {
            Ok(x) if x.is_finite() => TirValue::Number(x),
            Ok(x) => return Err(at(start + 1, InputProblem::TirNotFinite { key, value: x })),
            Err(_)
                if word.starts_with(|c: char| {
                    c.is_ascii_digit() || c == '-' || c == '+' || c == '.'
                }) =>
            {
                return Err(at(
                    start + 1,
                    InputProblem::TirNotANumber {
                        key,
                        text: word.to_string(),
                    },
                ))
            }
            Err(_) => TirValue::Text(word.to_string()),
        };
        (value, len)
    };
    Ok(TirEntry {
        section: section.to_string(),
        key,
        value,
        span: (start, start + len),
    })
}

/// The `.tir` text of an identified tyre: the template's file with the
/// values replaced (its comments and other keys kept), or a fresh file.
pub(crate) fn tir_text(
    tyre: &MagicFormula,
    template: Option<&TirDocument>,
) -> Result<String, InputError> {
    match template {
        Some(doc) => doc.write(tyre),
        None => Ok(write_new(tyre)),
    }
}

/// Reads a `.tir` text back into the tyre it describes (`name` labels
/// errors).
pub fn read_tir_text(name: &str, text: &str) -> Result<MagicFormula, InputError> {
    TirDocument::parse(Path::new(name), text)?.magic_formula()
}

mod core;
mod long_stiffness;
mod ranges;
mod rim;
mod stiffness;
mod units;

pub use long_stiffness::{longitudinal_turn, LongitudinalTurn};
pub use stiffness::{cornering_per_load, MAX_CORNERING_PER_LOAD};
use units::Units;
pub use units::LOAD_OVER_NOMINAL;

#[cfg(test)]
mod tests;

/// Refuses entry `e` at `(line, column)` of `path` where it repeats a key
/// with another value, in its section (`seen`, by section and key) or in
/// another one (`elsewhere`, by key, [UNITS] aside), and records it. Apart
/// from [`TirDocument::parse`] so that it reads on a screen.
fn refuse_duplicate(
    path: &Path,
    (line, column): (usize, usize),
    e: &TirEntry,
    seen: &mut HashMap<(String, String), (usize, TirValue)>,
    elsewhere: &mut HashMap<String, (usize, String, TirValue)>,
) -> Result<(), InputError> {
    // A second, different value of a key in its section would
    // silently win over the first (a repeated equal one is
    // harmless and read as the file's value).
    let key = (e.section.clone(), e.key.clone());
    if let Some((first, _)) = seen.get(&key).filter(|(_, v)| *v != e.value) {
        return Err(InputError::problem_at(
            path,
            line,
            column,
            InputProblem::Duplicate {
                name: e.key.clone(),
                first: DuplicateAt::Line(*first),
            },
        ));
    }
    // The same key with another value in another section: a
    // reader takes it from one of them and the other's value
    // is lost. [UNITS] names units (its MASS = 'kg' is no
    // mass), so its keys are not parameters.
    if e.section != "UNITS" {
        if let Some((first, sec, _)) = elsewhere
            .get(&e.key)
            .filter(|(_, s, v): &&(usize, String, _)| *s != e.section && *v != e.value)
        {
            return Err(InputError::problem_at(
                path,
                line,
                column,
                InputProblem::Duplicate {
                    name: e.key.clone(),
                    first: DuplicateAt::LineInSection {
                        line: *first,
                        section: sec.clone(),
                    },
                },
            ));
        }
        elsewhere
            .entry(e.key.clone())
            .or_insert((line, e.section.clone(), e.value.clone()));
    }
    seen.insert(key, (line, e.value.clone()));
    Ok(())
}
