//! `check_inverse`: another implementation's answers to `locate` and `ray` queries, judged by the
//! library's inverse batch checker (`tribez::batch::InverseBatchChecker`, the engine of `tribez
//! check --patch P --locate-results FILE` and `--ray-results FILE`), handed to Python as the
//! report's JSON and text. The rows arrive as number texts; they are judged as the lines of a
//! results file, so row `i` is line `i + 1` of the report.

use std::io::Cursor;

use pyo3::prelude::*;

use tribez::ResultsChecker;
use tribez::batch::{Format, InverseBatchChecker, InverseBatchOptions, InverseKind};

use crate::claims::{NativeDocument, json_of};
use crate::patch::NativePatch;
use crate::{guard, input_error, precision_arg, tolerance_arg};

/// The most rows one call judges (a results file is streamed; rows handed over from Python are
/// held in memory, twice: as Python strings and as the text judged).
pub const MAX_INVERSE_ROWS: usize = 1_000_000;

/// Judge `rows` (each the query's number texts, then the claimed tuples' texts one after another,
/// or `none` when nothing is claimed) about `patch`: `kind` `"locate"` or `"ray"`, `tolerance`
/// as the command line's `--tolerance`, `precision` `"f64"`, `"f32"` or None (exact numbers);
/// `anywhere`: locate over the whole plane; `label` names the patch in the report.
#[pyfunction]
#[pyo3(signature = (patch, kind, rows, tolerance, precision, anywhere, label))]
#[allow(clippy::too_many_arguments)]
pub fn check_inverse(
    py: Python<'_>,
    patch: &NativePatch,
    kind: &str,
    rows: Vec<Vec<String>>,
    tolerance: &str,
    precision: Option<&str>,
    anywhere: bool,
    label: String,
) -> PyResult<NativeDocument> {
    guard(py, || {
        let kind = match kind {
            "locate" => InverseKind::Locate,
            "ray" => InverseKind::Ray,
            other => {
                return Err(input_error(
                    py,
                    format!("kind: unknown inverse problem `{other}` (expected locate or ray)"),
                ));
            }
        };
        if rows.is_empty() {
            return Err(input_error(py, "rows: no rows"));
        }
        if rows.len() > MAX_INVERSE_ROWS {
            return Err(input_error(
                py,
                format!(
                    "rows: {} rows, more than the {MAX_INVERSE_ROWS} one call judges (split them, or write a results file)",
                    rows.len()
                ),
            ));
        }
        let tolerance = tolerance_arg(py, tolerance)?;
        let precision = precision.map(|p| precision_arg(py, p)).transpose()?;
        let text = results_text(&rows).map_err(|e| input_error(py, e))?;
        let options = InverseBatchOptions {
            kind,
            tolerance,
            precision,
            anywhere,
        };
        let patch = patch.patch.clone();
        let checker =
            InverseBatchChecker::new(patch, &label, &options).map_err(|e| input_error(py, e))?;
        let report = py
            .detach(|| {
                checker
                    .check_reader(
                        Cursor::new(text.into_bytes()),
                        Format::Csv,
                        "<rows>",
                        &label,
                        &mut |_, _| {},
                    )
                    .map_err(|e| e.to_string())
            })
            .map_err(|e| input_error(py, e))?;
        debug_assert_eq!(report.checked, rows.len() as u64, "every row is judged");
        Ok(NativeDocument::new(
            "inverse",
            json_of(py, &report)?,
            report.text(),
            report.failed == 0,
        ))
    })
}

/// The rows as the lines of a CSV results file. A text that would not stay one field of its line
/// (a comma, a quote or a line break in it) is refused here, with its row and column.
fn results_text(rows: &[Vec<String>]) -> Result<String, String> {
    let mut text = String::new();
    for (i, row) in rows.iter().enumerate() {
        // a blank line or one that starts with '#' would be skipped, not judged
        match row.first().map(|f| f.trim()) {
            None => return Err(format!("rows[{i}]: an empty row")),
            Some(f) if f.is_empty() || f.starts_with('#') => {
                return Err(format!(
                    "rows[{i}][0]: `{}` is not a number",
                    f.escape_debug()
                ));
            }
            Some(_) => {}
        }
        for (j, field) in row.iter().enumerate() {
            if field.contains([',', '"', '\n', '\r']) {
                return Err(format!(
                    "rows[{i}][{j}]: `{}` is not one number (it holds a comma, a quote or a line break)",
                    field.escape_debug()
                ));
            }
            if j > 0 {
                text.push(',');
            }
            text.push_str(field);
        }
        text.push('\n');
    }
    Ok(text)
}
