//! The documentation runs as it is written: every ```` ```console ```` block of
//! `README.md` and of the book (`docs/src/*.md`) is a trycmd case, each
//! `$ handling …` line run with the binary built by this package and its
//! output compared with the lines under it (`[..]` stands for part of a
//! line, a line `...` for any number of lines: timings, for instance).
//!
//! Each page runs in a scratch folder of its own (`<page>.in`, next to a copy
//! of the page) holding copies of the repository's input folders
//! (`scenarios`, `tyres`, `campaigns`, `docs`, `tests/fixtures`), so the
//! quoted commands read the bundled files by their repository paths and
//! write their outputs (`--out out/…`) into the scratch folder, never into
//! the checkout. Commands of one page run in order, so a page may read what
//! an earlier block wrote.
//!
//! Any other fence (```` ```sh ````, ```` ```toml ````, ```` ```text ````,
//! ```` ```python ````) is not run; a bare ```` ``` ```` fence would be read as
//! a command block, so `every_code_block_names_its_language` refuses it.
//!
//! To update the expected output after a deliberate change:
//! `TRYCMD=overwrite cargo test --release --test docs` rewrites the pages in
//! the checkout.
//!
//! The book's figures (`docs/src/images/*.png`) are the outputs of the
//! quoted commands ([`FIGURES`]): a committed figure that differs, byte
//! for byte, from the one this run's commands write fails the test, naming
//! it, so a figure in the book is made by the current tool, by the command
//! its chapter quotes; `TRYCMD=overwrite` copies the new figures over the
//! checkout's, to be committed. An image no quoted command makes is
//! refused.
//!
//! The book's table of contents is checked here too: every chapter that
//! `docs/src/SUMMARY.md` links exists, every page of `docs/src` is linked, and
//! every relative link of a page points at a file of the repository.

use std::fs;
use std::path::{Path, PathBuf};

#[path = "support/folders.rs"]
mod folders;
use folders::copy_folder;

/// The book's figures: (image in `docs/src/images`, the page whose quoted
/// commands make it, the file they write, relative to the page's scratch
/// folder).
const FIGURES: &[(&str, &str, &str)] = &[
    (
        "diagnose_gap_map.png",
        "book-diagnose",
        "out/diagnosis/gap_map.png",
    ),
    (
        "equilibria_phase_portrait.png",
        "book-equilibria",
        "out/steer/phase_portrait_1.png",
    ),
    (
        "equilibria_branches_speed_lt.png",
        "book-equilibria",
        "out/speed_lt/branches_speed.png",
    ),
    (
        "identify_mf61_pure_fy.png",
        "book-magic-formula",
        "out/fit.pure-fy.png",
    ),
    (
        "identify_mf61_combined_fy.png",
        "book-magic-formula",
        "out/fit.combined-fy.png",
    ),
    (
        "design_separation.png",
        "book-design",
        "out/delays/design/separation.png",
    ),
    ("study_maps.png", "book-study", "out/study/maps.png"),
];

/// Compares the figures the quoted commands wrote under `work` with the
/// book's, byte for byte (the figures are written the same, byte for
/// byte, by every run of the same tool): with `overwrite` copies those
/// that differ over the checkout's; otherwise fails naming each, the
/// command's page and how to update them, so that a change of a figure
/// is committed with the change of the tool that made it.
fn check_figures(work: &Path, overwrite: bool) {
    let images = root().join("docs/src/images");
    let mut stale = Vec::new();
    for (image, case, output) in FIGURES {
        let made = work.join(format!("{case}.in")).join(output);
        let fresh = fs::read(&made).unwrap_or_else(|e| {
            panic!(
                "{}: the figure of docs/src/images/{image} was not written: {e}",
                made.display()
            )
        });
        if fs::read(images.join(image)).ok().as_deref() == Some(&fresh[..]) {
            continue;
        }
        if overwrite {
            fs::write(images.join(image), fresh).unwrap();
        } else {
            stale.push(format!(
                "docs/src/images/{image}: the quoted commands of {} write another {output}",
                page_of_case(case)
            ));
        }
    }
    assert!(
        stale.is_empty(),
        "the book shows figures its quoted commands no longer make:\n{}\n\
         update them with `TRYCMD=overwrite cargo test --release --test docs` \
         and commit docs/src/images",
        stale.join("\n")
    );
}

/// The page of a scratch name ([`case_name`]'s inverse): `book-study`
/// is `docs/src/study.md`.
fn page_of_case(case: &str) -> String {
    match case.strip_prefix("book-") {
        Some(page) => format!("docs/src/{page}.md"),
        None => format!("{case}.md"),
    }
}

#[test]
fn every_book_image_is_made_by_a_quoted_command_and_shown() {
    let mut on_disk: Vec<String> = fs::read_dir(root().join("docs/src/images"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut made: Vec<String> = FIGURES.iter().map(|f| f.0.to_string()).collect();
    made.sort();
    assert_eq!(
        on_disk, made,
        "docs/src/images holds an image no quoted command makes, or lacks one"
    );
    let book: String = pages()
        .iter()
        .map(|p| fs::read_to_string(p).unwrap())
        .collect();
    for (image, ..) in FIGURES {
        assert!(
            book.contains(&format!("](images/{image})")),
            "no page shows images/{image}"
        );
    }
}

/// Repository folders a quoted command may read.
const INPUTS: &[&str] = &["scenarios", "tyres", "campaigns", "docs", "tests/fixtures"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and the book's pages, in a stable order.
fn pages() -> Vec<PathBuf> {
    let mut pages = vec![root().join("README.md")];
    let mut book: Vec<PathBuf> = fs::read_dir(root().join("docs/src"))
        .expect("docs/src")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    book.sort();
    pages.extend(book);
    pages
}

/// The scratch name of a page: `README`, `book-simulate`, …
fn case_name(page: &Path) -> String {
    let stem = page.file_stem().unwrap().to_string_lossy().into_owned();
    if page.parent() == Some(&root()) {
        stem
    } else {
        format!("book-{stem}")
    }
}

#[test]
fn quoted_commands_run_as_written() {
    let work = tempfile::tempdir().unwrap();
    let cases = trycmd::TestCases::new();
    cases
        .register_bin("handling", Path::new(env!("CARGO_BIN_EXE_handling")))
        .timeout(std::time::Duration::from_secs(300));
    // A page may show a written file with `cat`; trycmd ignores a command
    // whose program it cannot resolve, so it is registered by its path.
    let cat = std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default())
        .map(|dir| dir.join("cat"))
        .find(|p| p.is_file())
        .expect("cat on the PATH");
    cases.register_bin("cat", cat);
    let mut copies = Vec::new();
    for page in pages() {
        if !fs::read_to_string(&page).unwrap().contains("```console") {
            continue;
        }
        let name = case_name(&page);
        let copy = work.path().join(format!("{name}.md"));
        fs::write(
            &copy,
            with_final_newlines(&fs::read_to_string(&page).unwrap()),
        )
        .unwrap();
        let scratch = work.path().join(format!("{name}.in"));
        for dir in INPUTS {
            copy_folder(&root().join(dir), &scratch.join(dir));
        }
        cases.case(&copy);
        copies.push((page, copy));
    }
    assert!(copies.len() >= 2, "no page quotes a command");
    cases.run();
    let overwrite = std::env::var_os("TRYCMD").is_some_and(|m| m == "overwrite");
    check_figures(work.path(), overwrite);
    // `TRYCMD=overwrite` rewrote the copies: carry them back.
    if overwrite {
        for (page, copy) in copies {
            let text = fs::read_to_string(copy).unwrap();
            fs::write(page, without_final_newlines(&text)).unwrap();
        }
    }
}

/// trycmd takes a command's expected output up to the next `$` line or the
/// closing fence and drops its last newline, so that output ending in a
/// newline needs an empty line before them. The pages leave that line out
/// (the book would show it); their copies get it, except after a `...`
/// line, which matches the newline itself.
fn with_final_newlines(text: &str) -> String {
    let mut out = String::new();
    let mut in_console = false;
    // The block's line before this one (none on its first line).
    let mut previous: Option<&str> = None;
    for line in text.lines() {
        if in_console {
            let closes = line.starts_with("```");
            let output_ends = closes || line.starts_with("$ ");
            if output_ends && previous.is_some_and(|p| p != "..." && !p.is_empty()) {
                out.push('\n');
            }
            in_console = !closes;
            previous = Some(line);
        } else {
            in_console = line.starts_with("```console");
            previous = None;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// The inverse of [`with_final_newlines`], for `TRYCMD=overwrite`.
fn without_final_newlines(text: &str) -> String {
    let mut out: Vec<&str> = Vec::new();
    let mut in_console = false;
    for line in text.lines() {
        if in_console {
            let closes = line.starts_with("```");
            if (closes || line.starts_with("$ ")) && out.last() == Some(&"") {
                out.pop();
            }
            in_console = !closes;
        } else {
            in_console = line.starts_with("```console");
        }
        out.push(line);
    }
    out.join("\n") + "\n"
}

#[test]
fn copies_give_trycmd_the_final_newlines_and_lose_them_again() {
    let page = "text\n```console\n$ a\nout a\n$ b\n$ c\n...\n```\n\n```sh\nx\n```\n";
    let copy = "text\n```console\n$ a\nout a\n\n$ b\n\n$ c\n...\n```\n\n```sh\nx\n```\n";
    assert_eq!(with_final_newlines(page), copy);
    assert_eq!(without_final_newlines(copy), page);
}

/// The fenced blocks of a markdown text: (line of the opening fence, info string).
fn fences(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut open: Option<String> = None;
    for (i, line) in text.lines().enumerate() {
        let ticks = line.chars().take_while(|&c| c == '`').count();
        match &open {
            None if ticks >= 3 => {
                open = Some("`".repeat(ticks));
                out.push((i + 1, line[ticks..].trim().to_string()));
            }
            Some(fence) if line.trim_end() == fence.as_str() => open = None,
            _ => {}
        }
    }
    out
}

#[test]
fn every_code_block_names_its_language() {
    let mut checked = pages();
    checked.push(root().join("CHANGELOG.md"));
    for page in checked {
        let text = fs::read_to_string(&page).unwrap();
        for (line, info) in fences(&text) {
            assert!(
                !info.is_empty(),
                "{}:{line}: a code block without a language is run as commands; name it (console, sh, toml, text, python)",
                page.display()
            );
        }
    }
}

#[test]
fn fences_are_read_with_their_languages() {
    let text = "a\n```console\n$ handling\n```\n````toml\n```\n````\n```\n";
    assert_eq!(
        fences(text),
        vec![
            (2, "console".to_string()),
            (5, "toml".to_string()),
            (8, String::new())
        ]
    );
}

/// The targets of the inline links `[text](target)` of a markdown text,
/// outside code blocks and code spans.
fn links(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if in_code {
            continue;
        }
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(j) = after.find(')') else { break };
            let before = &rest[..i];
            // A `](` inside a code span is code, not a link.
            if before.matches('`').count() % 2 == 0 {
                out.push(after[..j].to_string());
            }
            rest = &after[j..];
        }
    }
    out
}

#[test]
fn links_are_read_from_text_only() {
    let text = "see [a](a.md#x) and `[b](b.md)`\n```text\n[c](c.md)\n```\n![f](../plots/f.png)\n";
    assert_eq!(links(text), vec!["a.md#x", "../plots/f.png"]);
}

/// A relative link's file, or `None` for a web address or an anchor alone.
fn link_target(page: &Path, link: &str) -> Option<PathBuf> {
    if link.contains("://") || link.starts_with('#') || link.starts_with("mailto:") {
        return None;
    }
    let file = link.split('#').next().unwrap();
    Some(page.parent().unwrap().join(file))
}

/// The anchor mdbook gives a heading (`mdbook-html`'s `id_from_content`,
/// applied to the heading's text without its code-span backticks).
fn heading_id(heading: &str) -> String {
    heading
        .replace('`', "")
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '_' || c == '-' {
                Some(c)
            } else if c.is_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// The anchors of a markdown page's headings, outside code blocks.
fn anchors(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
        } else if !in_code && line.starts_with('#') {
            out.push(heading_id(line.trim_start_matches('#')));
        }
    }
    out
}

#[test]
fn headings_give_mdbooks_anchors() {
    assert_eq!(
        heading_id(" The project's own files"),
        "the-projects-own-files"
    );
    assert_eq!(heading_id(" `handling tyre-eval`"), "handling-tyre-eval");
    assert_eq!(
        anchors("# A b\n```sh\n# not a heading\n```\n## Public measured data\n"),
        vec!["a-b", "public-measured-data"]
    );
}

#[test]
fn relative_links_point_at_files_and_headings_of_the_repository() {
    let root = fs::canonicalize(root()).unwrap();
    for page in pages() {
        let text = fs::read_to_string(&page).unwrap();
        for link in links(&text) {
            let Some(target) = link_target(&page, &link) else {
                if let Some(anchor) = link.strip_prefix('#') {
                    assert!(
                        anchors(&text).iter().any(|a| a == anchor),
                        "{}: no heading gives the anchor of `{link}`",
                        page.display()
                    );
                }
                continue;
            };
            let found = fs::canonicalize(&target).unwrap_or_else(|_| {
                panic!("{}: the link `{link}` points at nothing", page.display())
            });
            assert!(
                found.starts_with(&root),
                "{}: the link `{link}` leaves the repository",
                page.display()
            );
            if let Some((_, anchor)) = link.split_once('#') {
                let target_text = fs::read_to_string(&found).unwrap();
                assert!(
                    anchors(&target_text).iter().any(|a| a == anchor),
                    "{}: no heading of {} gives the anchor of `{link}`",
                    page.display(),
                    found.display()
                );
            }
        }
    }
}

#[test]
fn the_summary_lists_every_page_and_only_pages_that_exist() {
    let src = root().join("docs/src");
    let summary = fs::read_to_string(src.join("SUMMARY.md")).unwrap();
    let listed: Vec<String> = links(&summary);
    assert!(!listed.is_empty(), "SUMMARY.md lists no chapter");
    for chapter in &listed {
        assert!(
            src.join(chapter).is_file(),
            "SUMMARY.md lists `{chapter}`, which does not exist"
        );
    }
    for page in pages().into_iter().skip(1) {
        let name = page.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            name == "SUMMARY.md" || listed.contains(&name),
            "docs/src/{name} is not in SUMMARY.md"
        );
    }
}
