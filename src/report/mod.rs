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

/// Exact rationals as JSON strings.
pub fn json_rationals(xs: &[num_rational::BigRational]) -> Json {
    Json::Array(xs.iter().map(|x| Json::String(x.to_string())).collect())
}

/// `(a, b, c)` for people.
pub fn tuple(xs: &[num_rational::BigRational]) -> String {
    format!(
        "({})",
        xs.iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    )
}
