//! Reports out: every command produces a report value ([`Render`]); one [`Exporter`] per
//! format writes it: text for people, JSON for machines, LaTeX where the result is a formula or
//! a matrix, JUnit XML for the judging reports.

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

/// A command's result: what every command produces, rendered by one of the [`Exporter`]s.
///
/// Reports are typed values; their JSON comes from `#[derive(Serialize)]` (with [`to_json`]),
/// never from hand-built JSON.
pub trait Render {
    /// Text for people.
    fn text(&self) -> String;
    /// The machine-readable report.
    fn json(&self) -> Json;
    /// LaTeX, if this result has a natural LaTeX form.
    fn latex(&self) -> Option<String> {
        None
    }
    /// JUnit test cases, for the judging reports (`check`, `certify`).
    fn junit(&self) -> Option<JunitSuite> {
        None
    }
}

/// One way of writing a report: text, JSON, LaTeX or JUnit XML (as hyperfine's exporters).
pub trait Exporter {
    /// The report in this format; `None` when the format does not apply to it.
    fn export(&self, report: &dyn Render) -> Option<String>;
}

/// Text for people.
pub struct TextExporter;
/// Pretty-printed JSON (two-space indents), with a final newline.
pub struct JsonExporter;
/// LaTeX, for formulas and matrices.
pub struct LatexExporter;
/// JUnit XML, for CI dashboards: one `<testsuite>`, one `<testcase>` per claim file (or
/// results file, or algorithm and precision), with a `<failure>` listing what failed.
pub struct JunitExporter;

impl Exporter for TextExporter {
    fn export(&self, report: &dyn Render) -> Option<String> {
        Some(report.text())
    }
}

impl Exporter for JsonExporter {
    fn export(&self, report: &dyn Render) -> Option<String> {
        Some(format!("{:#}\n", report.json()))
    }
}

impl Exporter for LatexExporter {
    fn export(&self, report: &dyn Render) -> Option<String> {
        report.latex()
    }
}

impl Exporter for JunitExporter {
    fn export(&self, report: &dyn Render) -> Option<String> {
        report.junit().map(|s| junit_xml(s.suite, &s.cases))
    }
}

/// The exporter of an output format.
pub fn exporter(format: Format) -> &'static dyn Exporter {
    match format {
        Format::Text => &TextExporter,
        Format::Json => &JsonExporter,
        Format::Latex => &LatexExporter,
    }
}

/// Render `r` in `format`; `None` when the format does not apply to this result.
pub fn render(r: &dyn Render, format: Format) -> Option<String> {
    exporter(format).export(r)
}

/// A typed report as JSON (through its `Serialize` impl).
pub fn to_json(report: &impl serde::Serialize) -> Json {
    serde_json::to_value(report).unwrap_or(Json::Null)
}

/// `value` as pretty-printed JSON (two-space indents) and a final newline: how JSON files are
/// written.
pub fn pretty_json(value: &impl serde::Serialize) -> String {
    let mut text = serde_json::to_string_pretty(value).unwrap_or_else(|_| "null".into());
    text.push('\n');
    text
}

/// Exact rationals as strings `p/q` (lowest terms), for JSON.
pub fn strings(xs: &[num_rational::BigRational]) -> Vec<String> {
    xs.iter().map(ToString::to_string).collect()
}

/// `(a, b, c)` for people.
pub fn tuple(xs: &[num_rational::BigRational]) -> String {
    tribez::format::format_tuple(xs)
}

/// The test cases of a JUnit report, under the suite name `suite` (`check`, `certify`).
pub struct JunitSuite {
    /// The suite's name.
    pub suite: &'static str,
    /// Its cases.
    pub cases: Vec<JunitCase>,
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
fn junit_xml(suite: &str, cases: &[JunitCase]) -> String {
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

/// Serialization helpers of the typed reports.
pub mod ser {
    use num_rational::BigRational;
    use serde::ser::{SerializeMap, Serializer};

    /// Exact rationals as a list of strings `p/q` (`#[serde(serialize_with)]`).
    pub fn rationals<S: Serializer>(xs: &[BigRational], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(xs.iter().map(ToString::to_string))
    }

    /// A JSON object whose keys keep their order.
    pub struct OrderedMap<V>(pub Vec<(String, V)>);

    impl<V: serde::Serialize> serde::Serialize for OrderedMap<V> {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let mut map = s.serialize_map(Some(self.0.len()))?;
            for (k, v) in &self.0 {
                map.serialize_entry(k, v)?;
            }
            map.end()
        }
    }
}
