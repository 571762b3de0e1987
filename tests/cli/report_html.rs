//! The shareable pages (`report.html`, `fleet.html`) opened as a reader
//! opens them: in a browser (headless Chromium), offline. A page passes
//! when Chromium renders it without a console error, its screenshot is a
//! real image, and every section the reader looks for is in the rendered
//! document.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The Chromium binary: `$CHROMIUM`, else Debian's `/usr/bin/chromium`.
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    ["/usr/bin/chromium", "/usr/bin/chromium-browser"]
        .into_iter()
        .map(PathBuf::from)
        .find(|p| p.is_file())
}

/// Chromium run headless, offline and sandboxed in a fresh profile on
/// `page`, with `extra` arguments; returns (stdout, stderr).
fn headless(bin: &Path, page: &Path, extra: &[String]) -> (String, String) {
    let profile = tempfile::tempdir().unwrap();
    let url = format!("file://{}", page.canonicalize().unwrap().display());
    let out = Command::new(bin)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .args(extra)
        .arg(&url)
        .output()
        .expect("chromium starts");
    assert!(
        out.status.success(),
        "chromium on {}: {}",
        page.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Opens `page` in headless Chromium: no console message, a screenshot that
/// is a PNG of some size, and every id of `ids` in the rendered DOM (an id
/// ending in `>svg` must hold an inline SVG). Without Chromium the check is
/// skipped with a message, except under CI, where it fails.
pub fn opens_in_a_browser(page: &Path, ids: &[&str]) {
    let Some(bin) = chromium() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but Chromium is missing: install Debian's `chromium` (.ci/run does)"
        );
        eprintln!("SKIPPED browser check of {}: no Chromium", page.display());
        return;
    };
    let shot_dir = tempfile::tempdir().unwrap();
    let shot = shot_dir.path().join("page.png");
    let (_, log) = headless(
        &bin,
        page,
        &[
            format!("--screenshot={}", shot.display()),
            "--window-size=1400,2400".into(),
        ],
    );
    let console: Vec<&str> = log.lines().filter(|l| l.contains(":CONSOLE")).collect();
    assert!(
        console.is_empty(),
        "console messages:\n{}",
        console.join("\n")
    );
    let png = std::fs::read(&shot).expect("a screenshot");
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 20_000,
        "screenshot of {} bytes",
        png.len()
    );
    let (dom, _) = headless(&bin, page, &["--dump-dom".into()]);
    for id in ids {
        let (id, svg) = match id.strip_suffix(">svg") {
            Some(id) => (id, true),
            None => (*id, false),
        };
        let at = dom
            .find(&format!("id=\"{id}\""))
            .unwrap_or_else(|| panic!("no element #{id} in the rendered page"));
        if svg {
            let rest = &dom[at..];
            let end = rest.find("</figure>").expect("figure closes");
            assert!(rest[..end].contains("<svg"), "#{id} holds no SVG");
        }
    }
}
