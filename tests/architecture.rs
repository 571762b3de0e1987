//! The shape of the source tree, checked: no import cycle between files, no
//! module importing one of its own or a higher layer (the order is
//! [`LAYERS`]), no source file or function over the size a reader can hold, and no
//! internal label or path outside the repository in the project's text.
//!
//! The import graph is read from the text of `src/`: every `crate::`,
//! `super::` and `self::` path (in `use` items, grouped or not, and inline in
//! code) is resolved to the file of the deepest module it names. A path that
//! goes through a re-export (`pub use child::Item` in a parent) is followed to
//! where the item lives, so a parent that only re-exports its children and a
//! child that uses its parent's own items are not mistaken for a cycle; a
//! parent's `mod child;` declaration is not an import. The layer check reads
//! the library's own code only: test modules and `#[cfg(test)]` items may
//! use anything.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Module path (`["diagnose", "fit"]`) of every file under `src/`.
fn modules(root: &Path) -> BTreeMap<Vec<String>, PathBuf> {
    let mut out = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().and_then(|e| e.to_str()) != Some("rs") {
                continue;
            }
            let rel = path.strip_prefix(root).unwrap();
            let mut segs: Vec<String> = rel
                .iter()
                .map(|s| s.to_string_lossy().trim_end_matches(".rs").to_string())
                .collect();
            let last = segs.last().unwrap().clone();
            if last == "mod" || (segs.len() == 1 && (last == "lib" || last == "main")) {
                segs.pop();
            }
            if segs.is_empty() && last == "main" {
                continue; // the binary: it imports the library, nothing imports it
            }
            out.insert(segs, path);
        }
    }
    out
}

/// Code without comments and string literals (a doc comment that names a
/// path is not an import).
fn code_of(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let b: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < b.len() {
        if b[i] == '/' && b.get(i + 1) == Some(&'/') {
            while i < b.len() && b[i] != '\n' {
                i += 1;
            }
        } else if b[i] == '/' && b.get(i + 1) == Some(&'*') {
            i += 2;
            while i + 1 < b.len() && !(b[i] == '*' && b[i + 1] == '/') {
                i += 1;
            }
            i += 2;
        } else if b[i] == '"' {
            i += 1;
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == 'r' && (b.get(i + 1) == Some(&'"') || b.get(i + 1) == Some(&'#')) {
            // raw string r"…" or r#"…"#
            let mut j = i + 1;
            let mut hashes = 0;
            while b.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if b.get(j) != Some(&'"') || (i > 0 && (b[i - 1].is_alphanumeric() || b[i - 1] == '_'))
            {
                out.push(b[i]);
                i += 1;
                continue;
            }
            j += 1;
            loop {
                if j >= b.len() {
                    break;
                }
                if b[j] == '"' && (0..hashes).all(|k| b.get(j + 1 + k) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            i = j;
            out.push_str("\"\"");
        } else if b[i] == '\'' && b.get(i + 2) == Some(&'\'') && b.get(i + 1).is_some() {
            i += 3; // a char literal such as '"'
            out.push_str("' '");
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    out
}

/// Every path in a `use` tree: `a::{b, c::{d, e}}` gives `a::b`, `a::c::d`,
/// `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        return vec![tree.split(" as ").next().unwrap_or(&tree).to_string()];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(expand)
        .map(|p| {
            if p == "self" {
                prefix.trim_end_matches("::").to_string()
            } else {
                format!("{prefix}{p}")
            }
        })
        .collect()
}

/// The `use` items of a file: (is it `pub`, every path it names).
fn use_items(code: &str) -> Vec<(bool, Vec<String>)> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = find_word(rest, "use") {
        let before = rest[..at].trim_end();
        let public = before.ends_with("pub") || before.ends_with(')') && before.contains("pub(");
        let tail = &rest[at + 3..];
        let end = tail.find(';').unwrap_or(tail.len());
        let paths = expand(tail[..end].trim())
            .into_iter()
            .map(|p| p.split("as").next().unwrap().to_string())
            .collect();
        out.push((public, paths));
        rest = &tail[end..];
    }
    out
}

/// The byte offset of `word` as a whole word at the start of an item.
fn find_word(s: &str, word: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(i) = s[from..].find(word) {
        let at = from + i;
        let before = s[..at].chars().last();
        let after = s[at + word.len()..].chars().next();
        let starts = before.is_none_or(|c| c.is_whitespace() || c == ';' || c == '}' || c == '{');
        if starts && after.is_some_and(|c| c.is_whitespace()) {
            return Some(at);
        }
        from = at + word.len();
    }
    None
}

/// Inline paths `crate::a::b`, `super::a`, `self::a` in code.
fn inline_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    for head in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(i) = code[from..].find(head) {
            let at = from + i;
            let prev = code[..at].chars().last();
            from = at + head.len();
            if prev.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let len = code[at..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(code.len() - at);
            out.push(code[at..at + len].trim_end_matches(':').to_string());
        }
    }
    out
}

/// A path relative to module `at` made absolute (segments after `crate`).
fn absolute(at: &[String], is_mod_file: bool, path: &str) -> Option<Vec<String>> {
    let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let (mut base, mut rest): (Vec<String>, &[&str]) = match *segs.first()? {
        "crate" => (vec![], &segs[1..]),
        "self" => (at.to_vec(), &segs[1..]),
        "super" => {
            let mut b = at.to_vec();
            b.pop();
            (b, &segs[1..])
        }
        _ => return None,
    };
    while rest.first() == Some(&"super") {
        base.pop();
        rest = &rest[1..];
    }
    let _ = is_mod_file;
    base.extend(rest.iter().map(|s| s.to_string()));
    Some(base)
}

struct Tree {
    files: BTreeMap<Vec<String>, PathBuf>,
    /// Per module: re-exported name → absolute path it comes from.
    reexports: BTreeMap<Vec<String>, BTreeMap<String, Vec<String>>>,
    code: BTreeMap<Vec<String>, String>,
}

impl Tree {
    fn read(root: &Path) -> Tree {
        Tree::read_with(root, false)
    }

    /// The tree of the library's own code: test modules and `#[cfg(test)]`
    /// items left out.
    fn library(root: &Path) -> Tree {
        Tree::read_with(root, true)
    }

    fn read_with(root: &Path, library_only: bool) -> Tree {
        let mut files = modules(root);
        if library_only {
            let mut test_modules = Vec::new();
            for (m, path) in &files {
                for child in test_children(&code_of(&fs::read_to_string(path).unwrap())) {
                    let mut t = m.clone();
                    t.push(child);
                    test_modules.push(t);
                }
            }
            files.retain(|m, _| !test_modules.iter().any(|t| m.starts_with(t)));
        }
        let mut code = BTreeMap::new();
        let mut reexports = BTreeMap::new();
        for (m, path) in &files {
            let mut c = inline_modules_flattened(&code_of(&fs::read_to_string(path).unwrap()));
            if library_only {
                c = without_tests(&c);
            }
            let mut map = BTreeMap::new();
            for (public, paths) in use_items(&c) {
                if !public {
                    continue;
                }
                for p in paths {
                    // A re-export path without crate/self/super is relative to
                    // this module (`pub use child::Item`).
                    let full = if p.starts_with("crate")
                        || p.starts_with("self")
                        || p.starts_with("super")
                    {
                        p.clone()
                    } else {
                        format!("self::{p}")
                    };
                    if let Some(abs) = absolute(m, true, &full) {
                        if let Some(name) = abs.last() {
                            map.insert(name.clone(), abs.clone());
                        }
                    }
                }
            }
            reexports.insert(m.clone(), map);
            code.insert(m.clone(), c);
        }
        Tree {
            files,
            reexports,
            code,
        }
    }

    /// The file a path ends in: the deepest module it names, following
    /// re-exports to where the item lives.
    fn resolve(&self, path: &[String], depth: usize) -> Option<Vec<String>> {
        let mut k = path.len();
        while k > 0 && !self.files.contains_key(&path[..k]) {
            k -= 1;
        }
        let module = path[..k].to_vec();
        if depth < 8 {
            if let Some(next) = path.get(k) {
                if let Some(target) = self.reexports.get(&module).and_then(|m| m.get(next)) {
                    if target.as_slice() != &path[..=k] {
                        let mut t = target.clone();
                        t.extend(path[k + 1..].iter().cloned());
                        return self.resolve(&t, depth + 1);
                    }
                }
            }
        }
        Some(module)
    }

    fn edges(&self) -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
        let mut out: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
        for (m, c) in &self.code {
            let mut paths: Vec<String> = use_items(c)
                .into_iter()
                .filter(|(public, _)| !public)
                .flat_map(|(_, p)| p)
                .collect();
            paths.extend(inline_paths(c));
            let set = out.entry(m.clone()).or_default();
            for p in paths {
                let Some(abs) = absolute(m, true, &p) else {
                    continue;
                };
                let Some(target) = self.resolve(&abs, 0) else {
                    continue;
                };
                if &target != m && !target.is_empty() {
                    set.insert(target);
                }
            }
        }
        out
    }
}

fn name(m: &[String]) -> String {
    if m.is_empty() {
        "crate".into()
    } else {
        m.join("::")
    }
}

/// One cycle through `start`, if there is one.
fn cycle_from(
    start: &Vec<String>,
    edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
) -> Option<Vec<Vec<String>>> {
    let mut stack = vec![(start.clone(), vec![start.clone()])];
    let mut seen = BTreeSet::new();
    while let Some((node, path)) = stack.pop() {
        for next in edges.get(&node).into_iter().flatten() {
            if next == start {
                return Some(path);
            }
            if seen.insert(next.clone()) {
                let mut p = path.clone();
                p.push(next.clone());
                stack.push((next.clone(), p));
            }
        }
    }
    None
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn no_import_cycle_between_files() {
    let tree = Tree::read(&src());
    let edges = tree.edges();
    let mut cycles = BTreeSet::new();
    for m in tree.files.keys() {
        if let Some(c) = cycle_from(m, &edges) {
            let mut names: Vec<String> = c.iter().map(|m| name(m)).collect();
            // One rotation per cycle, so each is reported once.
            let min = (0..names.len()).min_by_key(|&i| names[i].clone()).unwrap();
            names.rotate_left(min);
            cycles.insert(names.join(" → "));
        }
    }
    assert!(
        cycles.is_empty(),
        "{} import cycles between files:\n{}",
        cycles.len(),
        cycles.into_iter().collect::<Vec<_>>().join("\n")
    );
}

#[test]
fn a_test_module_using_super_imports_its_own_file() {
    let c = inline_modules_flattened(&code_of(
        "use super::a::B;\nmod tests {\n    use super::*;\n    fn f() { super::g(); }\n}\nfn h() { super::k(); }\n",
    ));
    assert!(c.starts_with("use super::a::B;"));
    assert!(c.contains("use self::*;") && c.contains("self::g()"));
    assert!(c.ends_with("fn h() { super::k(); }\n"));
}

#[test]
fn the_checker_sees_a_cycle_and_a_reexport() {
    let uses = use_items(&code_of(
        "use crate::a::{b::{C, D}, e};\npub use self::f::G;\n// use crate::z;\n",
    ));
    assert_eq!(uses.len(), 2);
    assert_eq!(
        uses[0].1,
        vec!["crate::a::b::C", "crate::a::b::D", "crate::a::e"]
    );
    assert!(uses[1].0);
    let mut edges = BTreeMap::new();
    let a = vec!["a".to_string()];
    let b = vec!["b".to_string()];
    edges.insert(a.clone(), BTreeSet::from([b.clone()]));
    edges.insert(b.clone(), BTreeSet::from([a.clone()]));
    assert_eq!(cycle_from(&a, &edges), Some(vec![a.clone(), b]));
    edges.remove(&vec!["b".to_string()]);
    assert_eq!(cycle_from(&a, &edges), None);
}

/// The Python extension's sources (`python/src`, the `handling-py` crate):
/// held to the library's sizes, outside its import graph and layers.
fn python_src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("python/src")
}

#[test]
fn source_files_stay_readable() {
    let files: Vec<PathBuf> = modules(&src())
        .into_values()
        .chain(modules(&python_src()).into_values())
        .collect();
    assert!(
        files.iter().any(|p| p.ends_with("python/src/lib.rs")),
        "the Python extension's sources were not read"
    );
    let long: Vec<String> = files
        .iter()
        .filter_map(|p| {
            let n = fs::read_to_string(p).unwrap().lines().count();
            (n > 600).then(|| format!("{} ({n} lines)", p.display()))
        })
        .collect();
    assert!(
        long.is_empty(),
        "files over 600 lines:\n{}",
        long.join("\n")
    );
}

/// The functions of `code` longer than `limit` lines, as `name (N
/// lines)`: from a line opening a `fn` (under any visibility and
/// qualifiers: `pub(super) const unsafe fn`) to the line that closes it at
/// the same indentation (rustfmt's layout).
fn long_functions(code: &str, limit: usize) -> Vec<String> {
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        let body = l.trim_start();
        let indent = &l[..l.len() - body.len()];
        let Some(head) = fn_name_start(body) else {
            continue;
        };
        // A signature without a body (a trait's), or a body on its one
        // line, has nothing to count.
        if body.ends_with(';') || body.ends_with('}') {
            continue;
        }
        let close = format!("{indent}}}");
        let Some(end) = lines[i..].iter().position(|m| *m == close) else {
            continue;
        };
        let n = end + 1;
        if n > limit {
            let name: String = head
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.push(format!("{name} ({n} lines)"));
        }
    }
    out
}

/// What follows `fn ` on a line that opens a function, past its visibility
/// (`pub`, `pub(crate)`, `pub(super)`, `pub(in path)`) and qualifiers
/// (`const`, `async`, `unsafe`, `extern "C"`); `None` on any other line.
fn fn_name_start(line: &str) -> Option<&str> {
    let mut rest = line;
    if let Some(r) = rest.strip_prefix("pub") {
        rest = match r.strip_prefix('(') {
            Some(inner) => inner.split_once(')')?.1,
            None => r,
        }
        .strip_prefix(' ')?;
    }
    loop {
        if let Some(r) = rest.strip_prefix("fn ") {
            return Some(r);
        }
        let word = ["const ", "async ", "unsafe ", "extern "]
            .iter()
            .find_map(|k| rest.strip_prefix(k))?;
        rest = match word.strip_prefix('"') {
            Some(abi) => abi.split_once("\" ")?.1,
            None => word,
        };
    }
}

/// The long functions of every `.rs` file under `dir`, as `file::name (N
/// lines)` with `file` relative to `dir`.
fn long_functions_under(dir: &Path, limit: usize) -> Vec<String> {
    let mut files = Vec::new();
    files_under(dir, &[".rs"], &mut files);
    files.sort();
    let mut long = Vec::new();
    for p in &files {
        let rel = p
            .strip_prefix(dir)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        for f in long_functions(&fs::read_to_string(p).unwrap(), limit) {
            long.push(format!("{rel}::{f}"));
        }
    }
    long
}

/// The Python extension's functions stay under the guide's 80 lines
/// (`python/src/errors.rs`'s conversion of every error kind was 122).
#[test]
fn python_extension_functions_stay_readable() {
    let long = long_functions_under(&python_src(), 80);
    assert!(
        long.is_empty(),
        "functions over 80 lines:\n{}",
        long.join("\n")
    );
}

/// The library's and the binary's functions (tests included) stay under
/// the guide's 80 lines: a reader holds one on a screen.
#[test]
fn source_functions_stay_readable() {
    let long = long_functions_under(&src(), 80);
    assert!(
        long.is_empty(),
        "functions over 80 lines (split them into named steps):\n{}",
        long.join("\n")
    );
}

#[test]
fn the_length_check_counts_a_function_to_its_closing_brace() {
    let body = "    x();\n".repeat(79);
    let code = format!("fn short() {{\n}}\n\nimpl A {{\n    fn long() {{\n{body}    }}\n}}\n");
    assert_eq!(long_functions(&code, 80), ["long (81 lines)"]);
    assert!(long_functions(&code, 81).is_empty());
    for head in [
        "pub(super) fn long() {",
        "pub(in crate::a) const fn long() {",
        "pub async unsafe fn long() {",
        "extern \"C\" fn long() {",
    ] {
        let code = format!("{head}\n{body}}}\n");
        assert_eq!(long_functions(&code, 80), ["long (81 lines)"], "{head}");
    }
    assert_eq!(fn_name_start("let fn_x = 1;"), None);
    assert_eq!(fn_name_start("public fn x() {"), None);
}

/// The modules a file declares under `#[cfg(test)]` (`mod tests;`).
fn test_children(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("#[cfg(test)]") {
        rest = &rest[at + "#[cfg(test)]".len()..];
        let mut item = rest.trim_start();
        // Further attributes of the same item.
        while item.starts_with("#[") {
            item = item[item.find(']').map_or(item.len(), |e| e + 1)..].trim_start();
        }
        let item = item
            .strip_prefix("pub(crate)")
            .or_else(|| item.strip_prefix("pub"))
            .unwrap_or(item)
            .trim_start();
        if let Some(decl) = item.strip_prefix("mod ") {
            let name: String = decl
                .trim_start()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if decl.trim_start()[name.len()..]
                .trim_start()
                .starts_with(';')
            {
                out.push(name);
            }
        }
    }
    out
}

/// Code whose inline modules (`mod tests { … }`) are read as the file's
/// own: inside one, `super::` names the file's module, so it is rewritten
/// to `self::` (a test module's `use super::*` is no import of the file's
/// parent).
fn inline_modules_flattened(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while let Some(at) = find_word(rest, "mod") {
        let tail = &rest[at + 3..];
        let name_len = tail
            .trim_start()
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(0);
        let after_name = tail.trim_start()[name_len..].trim_start();
        if name_len == 0 || !after_name.starts_with('{') {
            out.push_str(&rest[..at + 3]);
            rest = tail;
            continue;
        }
        let open = at + 3 + (tail.len() - after_name.len());
        let mut depth = 0;
        let mut end = rest.len();
        for (i, c) in rest[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + i + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        out.push_str(&rest[..open]);
        out.push_str(&rest[open..end].replace("super::", "self::"));
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// Code without its `#[cfg(test)]` items (a `mod tests { … }` block, a
/// `use` or a function): tests may use anything, layering is about what the
/// library's own code depends on.
fn without_tests(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while let Some(at) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..at]);
        let tail = &rest[at..];
        // The item ends at its first `;` before any `{`, or at the `}` that
        // closes its first `{`.
        let (semi, brace) = (tail.find(';'), tail.find('{'));
        let end = match (semi, brace) {
            (Some(s), Some(b)) if s < b => s + 1,
            (Some(s), None) => s + 1,
            (_, Some(b)) => {
                let mut depth = 0;
                let mut end = tail.len();
                for (i, c) in tail[b..].char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' => {
                            depth -= 1;
                            if depth == 0 {
                                end = b + i + 1;
                                break;
                            }
                        }
                        _ => {}
                    }
                }
                end
            }
            (None, None) => tail.len(),
        };
        rest = &tail[end..];
    }
    out.push_str(rest);
    out
}

/// The crate's layers, bottom first: a module may import only modules of a
/// lower layer (none of its own layer, none above). `cli` is the binary; the
/// library cannot name it. The same list, with what each layer owns, is in
/// the book's architecture chapter (`docs/src/architecture.md`).
const LAYERS: &[&[&str]] = &[
    &["constants", "format", "scalar", "stats"],
    &["error"],
    &["tyre", "optim", "manoeuvre", "report"],
    &["vehicle", "measured"],
    &["sim"],
    &["metrics", "equilibria", "identify"],
    &["study", "diagnose"],
    &["proving_ground", "design"],
    &["io"],
    &["jobs"],
    &["cli"],
];

fn layer_of(layers: &[&[&str]], module: &str) -> Option<usize> {
    layers.iter().position(|l| l.contains(&module))
}

/// Every file-level import from a top-level module into one of the same or a
/// higher layer, as `from → to (file → file)`.
fn layer_violations(
    layers: &[&[&str]],
    edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
) -> Vec<String> {
    let mut out = Vec::new();
    for (from, targets) in edges {
        let Some(a) = from.first() else { continue };
        for to in targets {
            let b = &to[0];
            if a == b {
                continue;
            }
            let (la, lb) = (layer_of(layers, a), layer_of(layers, b));
            if la.zip(lb).is_none_or(|(la, lb)| lb >= la) {
                out.push(format!("{a} → {b} ({} → {})", name(from), name(to)));
            }
        }
    }
    out
}

/// The rooms of the diagnosis (`src/diagnose/`) in the order of its
/// stages, first first: a room may import only earlier ones, so that
/// following a campaign through the diagnosis enters the rooms in order.
/// The same order is in `src/diagnose/mod.rs` and the book's architecture
/// chapter.
const DIAGNOSE_STAGES: &[&[&str]] = &[
    &["effects", "timing", "unit_ratio"],
    &["campaign"],
    &["model"],
    &["fit"],
    &["base"],
    &["report"],
    &["verdict"],
    &["pipeline"],
];

#[test]
fn the_diagnosis_rooms_import_only_earlier_stages() {
    let inner: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = Tree::library(&src())
        .edges()
        .into_iter()
        .filter(|(from, _)| from.len() > 1 && from[0] == "diagnose")
        .map(|(from, to)| {
            let to = to
                .into_iter()
                .filter(|t| t.len() > 1 && t[0] == "diagnose")
                .map(|t| t[1..].to_vec())
                .collect();
            (from[1..].to_vec(), to)
        })
        .collect();
    let rooms: BTreeSet<&String> = inner.keys().filter_map(|m| m.first()).collect();
    let declared: Vec<&str> = DIAGNOSE_STAGES
        .iter()
        .flat_map(|l| l.iter().copied())
        .collect();
    let missing: Vec<&&String> = rooms
        .iter()
        .filter(|r| !declared.contains(&r.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "diagnosis rooms without a stage: {missing:?}"
    );
    let violations = layer_violations(DIAGNOSE_STAGES, &inner);
    assert!(
        violations.is_empty(),
        "{} imports against the diagnosis's stage order:\n{}",
        violations.len(),
        violations.join("\n")
    );
}

#[test]
fn every_module_has_a_layer() {
    let tops: BTreeSet<String> = modules(&src())
        .keys()
        .filter_map(|m| m.first().cloned())
        .collect();
    let declared: Vec<&str> = LAYERS.iter().flat_map(|l| l.iter().copied()).collect();
    let missing: Vec<&String> = tops
        .iter()
        .filter(|t| !declared.contains(&t.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "top-level modules without a layer in LAYERS: {missing:?}"
    );
    let gone: Vec<&&str> = declared.iter().filter(|d| !tops.contains(**d)).collect();
    assert!(
        gone.is_empty(),
        "LAYERS names modules that do not exist: {gone:?}"
    );
    let unique: BTreeSet<&&str> = declared.iter().collect();
    assert_eq!(unique.len(), declared.len(), "a module in two layers");
}

#[test]
fn no_module_imports_one_above_it() {
    let violations = layer_violations(LAYERS, &Tree::library(&src()).edges());
    assert!(
        violations.is_empty(),
        "{} imports against the layer order (a module may import only lower layers):\n{}",
        violations.len(),
        violations.join("\n")
    );
}

#[test]
fn the_layer_check_sees_an_upward_import_and_skips_tests() {
    let m = |s: &str| s.split("::").map(String::from).collect::<Vec<_>>();
    let mut edges = BTreeMap::new();
    edges.insert(m("tyre::gim"), BTreeSet::from([m("error::param")]));
    edges.insert(
        m("error::problem"),
        BTreeSet::from([m("identify::grouping")]),
    );
    edges.insert(m("sim"), BTreeSet::from([m("sim::ode"), m("metrics")]));
    edges.insert(m("vehicle"), BTreeSet::from([m("measured")]));
    assert_eq!(
        layer_violations(LAYERS, &edges),
        vec![
            "error → identify (error::problem → identify::grouping)",
            "sim → metrics (sim → metrics)",
            "vehicle → measured (vehicle → measured)",
        ]
    );
    let code = code_of(
        "use crate::a;\n#[cfg(test)]\nmod tests {\n use crate::b::{c, d};\n fn f() {}\n}\n\
         #[cfg(test)]\n#[path = \"x.rs\"]\nmod fixtures;\n#[cfg(test)]\nuse crate::e;\nfn g() {}\n",
    );
    assert_eq!(test_children(&code), vec!["fixtures".to_string()]);
    let kept = without_tests(&code);
    assert_eq!(
        use_items(&kept),
        vec![(false, vec!["crate::a".to_string()])],
        "{kept}"
    );
    assert!(kept.contains("fn g()"), "{kept}");
}

/// Every file under `dir` (recursively) whose name ends in one of `exts`.
fn files_under(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if path.is_dir() {
            // Built or installed trees are not the project's text.
            if !["target", "book", ".venv", "node_modules"].contains(&name.as_str())
                && !name.starts_with('.')
            {
                files_under(&path, exts, out);
            }
        } else if exts.iter().any(|e| name.ends_with(e)) {
            out.push(path);
        }
    }
}

/// The internal labels and outside paths in `text`: a ticket's number or
/// possessive (the tracker's word followed by a number or by 's), a path
/// into the machine the project was built on, and (where
/// `data_paths_allowed` is false) the data folder beside the checkout. The
/// patterns are assembled from pieces so that this file passes its own
/// check.
fn labels_in(text: &str, data_paths_allowed: bool) -> Vec<String> {
    let lower = text.to_lowercase();
    let mut out = Vec::new();
    let ticket = ["iss", "ue"].concat();
    let mut from = 0;
    while let Some(i) = lower[from..].find(&ticket) {
        let at = from + i;
        let after = &lower[at + ticket.len()..];
        let numbered = after
            .trim_start_matches([' ', '#'])
            .starts_with(|c: char| c.is_ascii_digit());
        if numbered || after.starts_with("'s") {
            out.push(text[at..(at + 12).min(text.len())].to_string());
        }
        from = at + ticket.len();
    }
    let mut outside = vec![["/wo", "rk/"].concat()];
    if !data_paths_allowed {
        outside.push(["../sh", "ared"].concat());
    }
    for p in outside {
        if lower.contains(&p) {
            out.push(p);
        }
    }
    out
}

#[test]
fn no_internal_labels_or_outside_paths() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = Vec::new();
    for (dir, exts) in [
        ("src", &["rs"][..]),
        ("tests", &["rs"]),
        ("benches", &["rs"]),
        ("scenarios", &["toml", "md"]),
        ("docs", &["md"]),
        ("python", &["rs", "py", "md", "toml"]),
    ] {
        let mut files = Vec::new();
        files_under(&root.join(dir), exts, &mut files);
        for f in files {
            // The tests and benches read the public data sets beside the
            // checkout, and the book names them where it quotes a figure
            // measured on them.
            let data_paths_allowed = ["tests", "benches", "docs"].contains(&dir);
            for l in labels_in(&fs::read_to_string(&f).unwrap(), data_paths_allowed) {
                found.push(format!("{}: {l}", f.strip_prefix(root).unwrap().display()));
            }
        }
    }
    for f in ["README.md", "CHANGELOG.md"] {
        for l in labels_in(&fs::read_to_string(root.join(f)).unwrap(), false) {
            found.push(format!("{f}: {l}"));
        }
    }
    assert!(
        found.is_empty(),
        "internal labels or outside paths:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_label_check_sees_a_ticket_and_an_outside_path() {
    let ticket = ["Iss", "ue 12's targets"].concat();
    assert_eq!(labels_in(&ticket, true).len(), 1);
    assert_eq!(labels_in(&["(iss", "ue #4)"].concat(), true).len(), 1);
    assert_eq!(
        labels_in(&["the iss", "ue's words"].concat(), true).len(),
        1
    );
    assert_eq!(labels_in("an issue of the rig", true), Vec::<String>::new());
    let data = ["../sh", "ared/data/x.csv"].concat();
    assert_eq!(labels_in(&data, true), Vec::<String>::new());
    assert_eq!(labels_in(&data, false).len(), 1);
    assert_eq!(labels_in(&["see /wo", "rk/notes"].concat(), true).len(), 1);
}

/// The crate doc (`src/lib.rs`) is the map a reader of the library starts
/// from: its table names every top-level module the library declares, in
/// the order of the layers.
#[test]
fn the_crate_doc_maps_every_module_in_layer_order() {
    let lib = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs")).unwrap();
    let doc: String = lib
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .collect::<Vec<_>>()
        .join("\n");
    let declared: Vec<&str> = lib
        .lines()
        .filter_map(|l| l.strip_prefix("pub mod "))
        .map(|l| l.trim_end_matches(';'))
        .collect();
    assert!(declared.len() >= 10, "{declared:?}");
    let mut rows: Vec<(usize, &str)> = Vec::new();
    for m in &declared {
        let at = doc.find(&format!("| [`{m}`] |"));
        let Some(at) = at else {
            panic!("src/lib.rs: the crate doc's table leaves out the module `{m}`");
        };
        rows.push((at, m));
    }
    rows.sort();
    let layers: Vec<usize> = rows
        .iter()
        .map(|(_, m)| layer_of(LAYERS, m).unwrap_or_else(|| panic!("`{m}` has no layer")))
        .collect();
    assert!(
        layers.windows(2).all(|w| w[0] <= w[1]),
        "src/lib.rs: the crate doc's table is not in layer order: {:?}",
        rows.iter().map(|(_, m)| m).collect::<Vec<_>>()
    );
}
