//! Reports out: every command's result renders as text for people, JSON for machines and,
//! where it makes sense, LaTeX.

use serde_json::Value as Json;

/// Output format chosen with `--format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Text for people.
    Text,
    /// JSON for machines (exact numbers as strings in lowest terms).
    Json,
    /// LaTeX, where the result is a formula or a matrix.
    Latex,
}

/// A command's result, renderable in each format.
pub trait Render {
    /// Text for people.
    fn text(&self) -> String;
    /// The machine-readable report.
    fn json(&self) -> Json;
    /// LaTeX, if this result has a natural LaTeX form.
    fn latex(&self) -> Option<String> {
        None
    }
}

/// Render `r` in `format`; `None` when the format does not apply to this result.
pub fn render(r: &dyn Render, format: Format) -> Option<String> {
    match format {
        Format::Text => Some(r.text()),
        Format::Json => Some(format!("{:#}\n", r.json())),
        Format::Latex => r.latex(),
    }
}

/// `value` as pretty-printed JSON (two-space indents) and a final newline: how every JSON
/// report and file is written.
pub fn pretty_json(value: &impl serde::Serialize) -> String {
    let mut text = serde_json::to_string_pretty(value).unwrap_or_else(|_| "null".into());
    text.push('\n');
    text
}

/// Exact rationals as JSON strings.
pub fn json_rationals(xs: &[num_rational::BigRational]) -> Json {
    Json::Array(xs.iter().map(|x| Json::String(x.to_string())).collect())
}

/// `(a, b, c)` for people.
pub fn tuple(xs: &[num_rational::BigRational]) -> String {
    tribez::hazmat::domain::format_tuple(xs)
}

/// The reports of `check` and `certify`: text and JSON (through [`Render`]) plus JUnit XML for
/// CI dashboards. One trait for the three formats of a judging report.
pub trait Exporter: Render {
    /// JUnit XML: one `<testsuite>`, one `<testcase>` per claim file (or results file, or
    /// algorithm), with a `<failure>` listing what failed.
    fn junit(&self) -> String;
}

/// One JUnit test case: name, number of failures and the failure text (empty when it passed).
pub struct JunitCase {
    /// `classname`/`name` of the case.
    pub name: String,
    /// How many checks it contains.
    pub checks: usize,
    /// The failures, one per line.
    pub failures: Vec<String>,
}

/// JUnit XML for `cases` under the suite name `suite`.
pub fn junit_xml(suite: &str, cases: &[JunitCase]) -> String {
    let failed = cases.iter().filter(|c| !c.failures.is_empty()).count();
    let mut out = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"tribez\" tests=\"{}\" failures=\"{failed}\">\n  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failed}\" errors=\"0\">\n",
        cases.len(),
        xml_escape(suite),
        cases.len()
    );
    for c in cases {
        out += &format!(
            "    <testcase classname=\"tribez.{}\" name=\"{}\" assertions=\"{}\"",
            xml_escape(suite),
            xml_escape(&c.name),
            c.checks
        );
        if c.failures.is_empty() {
            out += "/>\n";
        } else {
            out += &format!(
                ">\n      <failure message=\"{} of {} claims failed\" type=\"tribez.claim\">{}</failure>\n    </testcase>\n",
                c.failures.len(),
                c.checks,
                xml_escape(&c.failures.join("\n"))
            );
        }
    }
    out + "  </testsuite>\n</testsuites>\n"
}

/// Escape text for XML attributes and content.
pub fn xml_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => out += "&amp;",
            '<' => out += "&lt;",
            '>' => out += "&gt;",
            '"' => out += "&quot;",
            '\'' => out += "&apos;",
            c if (c as u32) < 0x20 && c != '\n' && c != '\t' => {}
            c => out.push(c),
        }
    }
    out
}
