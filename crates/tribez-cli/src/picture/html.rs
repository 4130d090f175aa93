//! The self-contained HTML report of `check --html` and `certify --html`: one file, XHTML (it
//! parses as XML), the pictures inline as SVG, the style inline; no script, and nothing loaded
//! from anywhere (no `src`, no external `href`, no `url(...)`), so a CI artifact reads the same
//! offline and forever.

use super::svg::escape;

/// What the report shows, in order.
#[derive(Clone, Debug, Default)]
pub struct HtmlReport {
    /// The page's title and heading.
    pub title: String,
    /// Did every claim hold (the verdict's colour), and the verdict in words.
    pub passed: bool,
    /// The verdict in words.
    pub verdict: String,
    /// Summary rows: name, value.
    pub summary: Vec<(String, String)>,
    /// The command that reproduces the run.
    pub reproduce: String,
    /// The error maps with their histograms (one SVG document, inlined).
    pub pictures: String,
    /// Further sections: heading, then a table (header, rows) or preformatted text.
    pub sections: Vec<Section>,
    /// The run's text report, verbatim.
    pub text: String,
}

/// A section of the report.
#[derive(Clone, Debug)]
pub enum Section {
    /// A heading, an optional sentence, a table.
    Table {
        /// The heading.
        heading: String,
        /// A sentence under it (may be empty).
        note: String,
        /// Column names.
        header: Vec<String>,
        /// Cells (text; escaped here).
        rows: Vec<Vec<String>>,
    },
}

const STYLE: &str = "
body { font-family: DejaVu Sans, Helvetica, Arial, sans-serif; margin: 2em auto; max-width: 1040px; color: #222; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.15em; margin-top: 1.8em; border-bottom: 1px solid #ddd; }
.verdict { font-weight: bold; padding: 0.4em 0.8em; display: inline-block; border-radius: 4px; }
.pass { background: #e3f4e1; color: #1b5e20; }
.fail { background: #fde2e1; color: #b71c1c; }
table { border-collapse: collapse; font-size: 0.9em; }
td, th { border: 1px solid #ddd; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f4f4f4; }
td.num { font-family: DejaVu Sans Mono, monospace; word-break: break-all; }
pre { background: #f7f7f7; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }
code { font-family: DejaVu Sans Mono, monospace; }
";

/// The report as one XHTML document.
pub fn render(r: &HtmlReport) -> String {
    let mut out = String::with_capacity(r.pictures.len() + r.text.len() + 16_384);
    out.push_str("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!DOCTYPE html>\n");
    out.push_str("<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n");
    out.push_str("<meta charset=\"utf-8\"/>\n");
    out.push_str(&format!("<title>{}</title>\n", escape(&r.title)));
    out.push_str(&format!("<style>{STYLE}</style>\n</head>\n<body>\n"));
    out.push_str(&format!("<h1>{}</h1>\n", escape(&r.title)));
    out.push_str(&format!(
        "<p><span class=\"verdict {}\" id=\"verdict\">{}</span></p>\n",
        if r.passed { "pass" } else { "fail" },
        escape(&r.verdict)
    ));
    out.push_str("<h2>Summary</h2>\n<table id=\"summary\">\n");
    for (k, v) in &r.summary {
        out.push_str(&format!(
            "<tr><th>{}</th><td>{}</td></tr>\n",
            escape(k),
            escape(v)
        ));
    }
    out.push_str("</table>\n");
    out.push_str(&format!(
        "<h2>Reproduce</h2>\n<pre id=\"reproduce\"><code>{}</code></pre>\n",
        escape(&r.reproduce)
    ));
    if !r.pictures.is_empty() {
        out.push_str(&format!(
            "<h2>{}</h2>\n<div id=\"pictures\">\n",
            if r.pictures.contains("error-map") {
                "Error map and histogram"
            } else {
                "Histogram"
            }
        ));
        out.push_str(&r.pictures);
        out.push_str("</div>\n");
    }
    for s in &r.sections {
        match s {
            Section::Table {
                heading,
                note,
                header,
                rows,
            } => {
                out.push_str(&format!("<h2>{}</h2>\n", escape(heading)));
                if !note.is_empty() {
                    out.push_str(&format!("<p>{}</p>\n", escape(note)));
                }
                out.push_str("<table>\n<tr>");
                for h in header {
                    out.push_str(&format!("<th>{}</th>", escape(h)));
                }
                out.push_str("</tr>\n");
                for row in rows {
                    out.push_str("<tr>");
                    for c in row {
                        out.push_str(&format!("<td class=\"num\">{}</td>", escape(c)));
                    }
                    out.push_str("</tr>\n");
                }
                out.push_str("</table>\n");
            }
        }
    }
    out.push_str(&format!(
        "<h2>The report</h2>\n<pre id=\"text-report\">{}</pre>\n",
        escape(&r.text)
    ));
    out.push_str("</body>\n</html>\n");
    out
}

/// `args` as one shell command line (each argument quoted when it needs to be).
pub fn shell_line(args: &[String]) -> String {
    args.iter()
        .map(|a| {
            let plain = !a.is_empty()
                && a.bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b"-_./=,:+@%".contains(&b));
            if plain {
                a.clone()
            } else {
                format!("'{}'", a.replace('\'', "'\\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shell_lines_quote_what_needs_it() {
        let args = ["tribez", "check", "a b.csv", "it's", "ulps=4"].map(String::from);
        assert_eq!(
            shell_line(&args),
            r"tribez check 'a b.csv' 'it'\''s' ulps=4"
        );
    }

    #[test]
    fn the_page_escapes_its_text() {
        let page = render(&HtmlReport {
            title: "a <b> & c".into(),
            text: "</pre><script>".into(),
            ..HtmlReport::default()
        });
        assert!(page.contains("a &lt;b&gt; &amp; c"));
        assert!(!page.contains("<script"));
    }
}
