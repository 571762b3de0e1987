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

/// A synthetic campaign with `effects` on, diagnosed on `candidates` only
/// (a fast diagnosis); returns report.html's text and diagnosis.json.
fn diagnosed_page(
    dir: &Path,
    name: &str,
    effects: &str,
    candidates: &str,
) -> (String, serde_json::Value) {
    let mut args = vec!["--seed", "3"];
    if !effects.is_empty() {
        args.extend_from_slice(&["--effects", effects]);
    }
    let campaign = crate::synth_campaign(dir, name, &args);
    // synth's vehicle.toml ends in its [diagnose] table.
    let vehicle = campaign.join("vehicle.toml");
    let text = std::fs::read_to_string(&vehicle).unwrap();
    std::fs::write(&vehicle, format!("{text}effects = [{candidates}]\n")).unwrap();
    let out = dir.join(format!("{name}.out"));
    let (_, d) = crate::diagnose_to(&campaign, &out);
    (std::fs::read_to_string(out.join("report.html")).unwrap(), d)
}

/// The table row (`<tr>…</tr>`) of `table` whose first cell is `first`.
fn row<'a>(page: &'a str, table: &str, first: &str) -> &'a str {
    let at = page
        .find(&format!("<table id=\"{table}\""))
        .unwrap_or_else(|| panic!("no table {table}"));
    let end = at + page[at..].find("</table>").unwrap();
    let cell = format!("<tr><td>{first}</td>");
    let start = at
        + page[at..end]
            .find(&cell)
            .unwrap_or_else(|| panic!("no row {first} in {table}"));
    &page[start..start + page[start..].find("</tr>").unwrap()]
}

#[test]
fn the_page_says_why_the_verdict_is_its_row_and_what_it_fitted() {
    let dir = tempfile::tempdir().unwrap();
    let (page, d) = diagnosed_page(
        dir.path(),
        "delay",
        "sensor_delay",
        "\"sensor_delay\", \"steer_path\"",
    );
    assert_eq!(crate::verdict_of(&d), ["sensor_delay"]);
    // The verdict box holds the fitted value of its parameter.
    let p = &d["verdict"]["parameters"][0];
    let fitted = format!(
        "<p class=\"verdict\">Fitted: {} = {:.4}",
        p["name"].as_str().unwrap(),
        p["value"].as_f64().unwrap()
    );
    assert!(page.contains(&fitted), "{fitted} not in the page");
    // The tyres fitted to the rig are held: the page, as the terminal,
    // says what its standard errors leave out.
    assert!(
        page.contains("(± a standard error with the base model&#39;s tyres held as they are: their own uncertainty is not in it).")
            || page.contains("(± a standard error with the base model's tyres held as they are: their own uncertainty is not in it)."),
        "no caveat in the page"
    );
    // The two look-alikes are confounded: one sentence, then one line per
    // effect with the signature that would separate them.
    assert!(!d["confounded"].as_array().unwrap().is_empty());
    assert!(page.contains(
        "<p class=\"warning\">Confounded: the runs do not tell sensor_delay and steer_path apart \
         (their held-out gaps lie within the confounding window the verdict states). A test that \
         shows one of these signatures separates them:</p>\n<ul class=\"lines\">\n<li>sensor_delay: "
    ));
    // The ranking marks the verdict's row, explains the order, and says
    // why a row scoring better than the verdict is not it.
    assert!(row(&page, "ranking-table", "sensor_delay").ends_with("<td>the verdict</td>"));
    assert!(page.contains("The verdict is not always the top row"));
    let verdict_j = crate::ranked(&d, "sensor_delay")["heldout_error_after"]
        .as_f64()
        .unwrap();
    for r in d["ranking"].as_array().unwrap() {
        let effect = r["effect"].as_str().unwrap();
        let better = r["heldout_error_after"].as_f64().unwrap() < verdict_j;
        let why = row(&page, "ranking-table", effect).contains("J lower by");
        assert_eq!(better, why, "{effect}");
    }
}

#[test]
fn no_reduction_percentage_for_a_gap_within_noise() {
    let dir = tempfile::tempdir().unwrap();
    let (page, d) = diagnosed_page(dir.path(), "none", "", "\"sensor_delay\"");
    let mut within = 0;
    for s in d["shrinkage"].as_array().unwrap() {
        if s["part"] != "all" {
            continue;
        }
        let before = s["before"].as_f64().unwrap();
        let floor = s["noise_floor"].as_f64().unwrap();
        let cells = row(&page, "shrinkage", s["channel"].as_str().unwrap());
        let said = cells.contains("not significant");
        assert_eq!(said, before <= 3.0 * floor, "{cells}");
        within += usize::from(said);
    }
    assert!(within > 0, "no channel within its noise floors");
    // A channel judged alone is told apart from the verdict's rule, which
    // takes the channels together (a verdict of 70 % sat above a table of
    // channels each "not significant", with no word of why).
    assert!(
        page.contains("Each channel is judged alone against 3 noise floors;")
            && page.contains("share is of the combined error of all channels"),
        "the page does not say how a channel alone is judged"
    );
    if !d["gap"]["significant"].as_bool().unwrap() {
        // Without a gap nothing is searched: the candidate is screened,
        // listed as such, and ranked nowhere.
        let screened: Vec<&str> = d["screened"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["effect"].as_str().unwrap())
            .collect();
        assert_eq!(screened, ["sensor_delay"]);
        assert!(page.contains("Screened, not cross-validated"));
        assert!(page.contains("sensor_delay ("));
        assert!(!page.contains("<tr><td>sensor_delay</td>"));
    }
}
