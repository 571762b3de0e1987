//! Self-contained HTML reports: one file with its style sheet and its figures
//! (inline SVG) inside, no script and no network access, readable offline and
//! printable. A [`Page`] is built section by section; text is escaped here,
//! so callers pass plain strings.

use super::plot::Figure;
use crate::error::Error;
use std::fmt::Write as _;
use std::path::Path;

/// The page's style: readable on a laptop, one column on paper, tables that
/// do not split a row across pages.
const STYLE: &str = "\
body{font-family:'DejaVu Sans',Helvetica,Arial,sans-serif;max-width:1500px;margin:1.5em auto;\
padding:0 1em;color:#222;line-height:1.45}\
h1{font-size:1.5em;border-bottom:2px solid #1f77b4;padding-bottom:.2em}\
h2{font-size:1.2em;margin-top:1.6em;border-bottom:1px solid #ccc}\
table{border-collapse:collapse;margin:.6em 0;font-size:.9em}\
th,td{border:1px solid #ccc;padding:.25em .6em;text-align:left;vertical-align:top}\
th{background:#f0f4f8}td.num{text-align:right;font-variant-numeric:tabular-nums}\
tr{page-break-inside:avoid}\
.verdict{font-size:1.1em;background:#f6faf6;border-left:4px solid #2ca02c;padding:.5em .8em}\
.warning{background:#fff8e6;border-left:4px solid #ff7f0e;padding:.3em .8em;margin:.3em 0}\
figure{margin:.8em 0}figure svg{max-width:100%;height:auto}\
figcaption{font-size:.9em;color:#555}\
ul.lines{font-family:'DejaVu Sans Mono',monospace;font-size:.85em;list-style:none;padding-left:0}\
@media print{body{max-width:none}h2{page-break-after:avoid}figure{page-break-inside:avoid}}";

/// Text made safe for HTML element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// A table cell: text, a number right-aligned, or a link.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// Left-aligned text.
    Text(String),
    /// A number already formatted, right-aligned.
    Number(String),
    /// A link to a file relative to the page (`a/report.html`), its text
    /// the path itself.
    Link(String),
}

/// A relative path as a URL: each byte other than an unreserved one or
/// `/` percent-encoded (RFC 3986), so a folder named `a b#1` links to it.
pub fn href(path: &str) -> String {
    let mut out = String::with_capacity(path.len());
    for b in path.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            out.push(b as char);
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

impl From<&str> for Cell {
    fn from(s: &str) -> Self {
        Cell::Text(s.to_string())
    }
}

impl From<String> for Cell {
    fn from(s: String) -> Self {
        Cell::Text(s)
    }
}

/// An HTML page under construction.
#[derive(Debug, Clone)]
pub struct Page {
    body: String,
}

impl Page {
    /// A page with its title (also the first heading).
    pub fn new(title: &str) -> Self {
        let mut body = String::new();
        let _ = writeln!(body, "<h1>{}</h1>", escape(title));
        Self { body }
    }

    /// A section heading; `id` names it for links and for tests.
    pub fn section(&mut self, id: &str, heading: &str) -> &mut Self {
        let _ = writeln!(
            self.body,
            "<h2 id=\"{}\">{}</h2>",
            escape(id),
            escape(heading)
        );
        self
    }

    /// A paragraph; `class` styles it (`verdict`, `warning`) when not empty.
    pub fn paragraph(&mut self, class: &str, text: &str) -> &mut Self {
        if class.is_empty() {
            let _ = writeln!(self.body, "<p>{}</p>", escape(text));
        } else {
            let _ = writeln!(
                self.body,
                "<p class=\"{}\">{}</p>",
                escape(class),
                escape(text)
            );
        }
        self
    }

    /// Lines kept as they are (a terminal report), one per list item.
    pub fn lines(&mut self, lines: &[String]) -> &mut Self {
        self.body.push_str("<ul class=\"lines\">\n");
        for l in lines {
            let _ = writeln!(self.body, "<li>{}</li>", escape(l));
        }
        self.body.push_str("</ul>\n");
        self
    }

    /// A table with its header row; `id` names it.
    pub fn table(&mut self, id: &str, header: &[&str], rows: &[Vec<Cell>]) -> &mut Self {
        let _ = writeln!(self.body, "<table id=\"{}\"><thead><tr>", escape(id));
        for h in header {
            let _ = write!(self.body, "<th>{}</th>", escape(h));
        }
        self.body.push_str("</tr></thead><tbody>\n");
        for row in rows {
            self.body.push_str("<tr>");
            for c in row {
                match c {
                    Cell::Text(t) => {
                        let _ = write!(self.body, "<td>{}</td>", escape(t));
                    }
                    Cell::Number(t) => {
                        let _ = write!(self.body, "<td class=\"num\">{}</td>", escape(t));
                    }
                    Cell::Link(path) => {
                        let (url, text) = (escape(&href(path)), escape(path));
                        let _ = write!(self.body, "<td><a href=\"{url}\">{text}</a></td>");
                    }
                }
            }
            self.body.push_str("</tr>\n");
        }
        self.body.push_str("</tbody></table>\n");
        self
    }

    /// A figure drawn inline as SVG, with its caption; `file` is the page's
    /// file (named if drawing fails).
    pub fn figure(
        &mut self,
        id: &str,
        figure: &Figure,
        caption: &str,
        file: &Path,
    ) -> Result<&mut Self, Error> {
        let svg = figure.svg(file)?;
        // The SVG's own XML declaration is not allowed inside HTML.
        let svg = svg.trim_start_matches(|c| c != '<');
        let svg = match svg.strip_prefix("<?xml") {
            Some(rest) => rest.split_once("?>").map_or(rest, |(_, r)| r),
            None => svg,
        };
        let _ = writeln!(
            self.body,
            "<figure id=\"{}\">{}<figcaption>{}</figcaption></figure>",
            escape(id),
            svg.trim(),
            escape(caption)
        );
        Ok(self)
    }

    /// The complete document.
    pub fn finish(&self, title: &str) -> String {
        format!(
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
             <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
             <title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{}</body>\n</html>\n",
            escape(title),
            self.body
        )
    }

    /// Writes the document to `path` (atomically).
    pub fn write(&self, title: &str, path: &Path) -> Result<(), Error> {
        super::write_bytes(path, self.finish(title).as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::plot::{Panel, Series};

    #[test]
    fn text_is_escaped_everywhere() {
        let mut p = Page::new("a <b> & 'c'");
        p.section("s\"1", "x > y")
            .paragraph("", "<script>alert(1)</script>")
            .table("t", &["<h>"], &[vec![Cell::Text("&".into())]]);
        let html = p.finish("<t>");
        assert!(!html.contains("<script>"), "{html}");
        assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
        assert!(html.contains("<h1>a &lt;b&gt; &amp; &#39;c&#39;</h1>"));
        assert!(html.contains("id=\"s&quot;1\""));
        assert!(html.contains("<title>&lt;t&gt;</title>"));
        assert!(html.contains("<th>&lt;h&gt;</th>") && html.contains("<td>&amp;</td>"));
    }

    /// A link cell's URL is percent-encoded and its text escaped: a
    /// folder `a b#<1>` links to `a%20b%23%3C1%3E/report.html`.
    #[test]
    fn a_link_cell_is_an_encoded_url_with_escaped_text() {
        let mut p = Page::new("links");
        p.section("s", "s").table(
            "t",
            &["report"],
            &[vec![Cell::Link("a b#<1>/report.html".into())]],
        );
        let html = p.finish("links");
        assert!(
            html.contains(
                "<td><a href=\"a%20b%23%3C1%3E/report.html\">a b#&lt;1&gt;/report.html</a></td>"
            ),
            "{html}"
        );
    }

    #[test]
    fn a_figure_is_inline_svg_without_xml_declaration() {
        let fig = Figure::stack(vec![Panel {
            title: "yaw rate".into(),
            x_label: "t, s".into(),
            y_label: "r, rad/s".into(),
            series: vec![Series::line(
                "measured",
                &[0.0, 1.0, 2.0],
                &[0.0, 0.1, 0.2],
                0,
            )],
            ..Panel::default()
        }]);
        let mut p = Page::new("figure");
        p.figure("f", &fig, "caption", Path::new("report.html"))
            .unwrap();
        let html = p.finish("figure");
        assert!(!html.contains("<?xml"));
        let start = html.find("<figure id=\"f\"><svg").expect("inline svg");
        assert!(html[start..].contains("</svg><figcaption>caption</figcaption></figure>"));
        // Self-contained: no script, no external resource.
        for external in ["<script", "<link", "src=", "url(", "@import"] {
            assert!(!html.contains(external), "{external} in {html}");
        }
    }
}
