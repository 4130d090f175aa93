//! `check_claims` and `certify`: the library's claim-file report
//! (`tribez::claims::check_claims` → `ClaimsReport`) and certification run (`tribez::certify` →
//! `CertifyReport`), handed to Python as their JSON (the command line's `--format json`) and
//! text (what the command line prints). The Python layer reads its figures from that JSON;
//! nothing is computed here.

use std::path::PathBuf;

use pyo3::prelude::*;

use tribez::claims::{ClaimsOptions, check_claims as library_check_claims};
use tribez::{Algorithm, CertifyOptions, CertifyPoints, Precision};

use crate::patch::NativePatch;
use crate::{guard, input_error};

/// The largest number of random points of a certification run (each point is evaluated
/// exactly): the command line's limit for `--random N`.
pub const MAX_RANDOM_POINTS: usize = 1_000_000;

/// A report as the library renders it: its JSON, its text and whether it succeeded.
#[pyclass(module = "tribez._native", frozen)]
pub struct NativeDocument {
    /// `"claims"`, `"certify"` or `"inverse"`.
    #[pyo3(get)]
    kind: &'static str,
    /// The JSON report (the command line's `--format json`).
    #[pyo3(get)]
    json: String,
    /// The text report (what the command line prints).
    #[pyo3(get)]
    text: String,
    /// Every claim holds (errata aside) / every result is within its proven bound.
    #[pyo3(get)]
    success: bool,
}

impl NativeDocument {
    /// A report of `kind` from its JSON and text.
    pub(crate) fn new(kind: &'static str, json: String, text: String, success: bool) -> Self {
        NativeDocument {
            kind,
            json,
            text,
            success,
        }
    }
}

#[pymethods]
impl NativeDocument {
    /// Rebuild from its parts (pickling).
    #[staticmethod]
    fn from_parts(kind: &str, json: String, text: String, success: bool) -> PyResult<Self> {
        let kind = match kind {
            "claims" => "claims",
            "certify" => "certify",
            "inverse" => "inverse",
            other => {
                return Err(pyo3::exceptions::PyValueError::new_err(format!(
                    "unknown report kind `{other}`"
                )));
            }
        };
        Ok(NativeDocument {
            kind,
            json,
            text,
            success,
        })
    }
}

pub(crate) fn json_of(py: Python<'_>, value: impl serde::Serialize) -> PyResult<String> {
    // byte-identical to the command line's `--format json` (pretty, a final newline)
    serde_json::to_string_pretty(&value)
        .map(|j| j + "\n")
        .map_err(|e| input_error(py, format!("report: {e}")))
}

/// Check a claim file, or every claim file under a directory (the report of `tribez check
/// PATH`).
#[pyfunction]
pub fn check_claims(py: Python<'_>, path: PathBuf) -> PyResult<NativeDocument> {
    guard(py, || {
        let report = py
            .detach(|| {
                library_check_claims(&path, &ClaimsOptions::default()).map_err(|e| e.to_string())
            })
            .map_err(|e| input_error(py, e))?;
        Ok(NativeDocument {
            kind: "claims",
            json: json_of(py, &report)?,
            text: report.text(),
            success: report.success(),
        })
    })
}

/// A certification run of `patch`: at `points` (rows of exact number texts in the kind's
/// coordinates) or at `random` random points from `seed`; `precision` `"f64"`, `"f32"` or
/// `"all"`; `algorithm` `"casteljau"`, `"bernstein"` or `"all"`; `label` names the patch in the
/// report.
#[pyfunction]
#[pyo3(signature = (patch, points, random, seed, precision, algorithm, label))]
#[allow(clippy::too_many_arguments)]
pub fn certify(
    py: Python<'_>,
    patch: &NativePatch,
    points: Option<Vec<Vec<String>>>,
    random: Option<usize>,
    seed: u64,
    precision: &str,
    algorithm: &str,
    label: String,
) -> PyResult<NativeDocument> {
    guard(py, || {
        let precision = match precision {
            "all" => None,
            p => Some(
                p.parse::<Precision>()
                    .map_err(|e| input_error(py, format!("precision: {e} (or \"all\")")))?,
            ),
        };
        let algorithm = match algorithm {
            "all" => None,
            "casteljau" => Some(Algorithm::Casteljau),
            "bernstein" => Some(Algorithm::Bernstein),
            other => {
                return Err(input_error(
                    py,
                    format!(
                        "algorithm: unknown algorithm `{other}` (expected casteljau, bernstein or all)"
                    ),
                ));
            }
        };
        let points = match (points, random) {
            (Some(rows), None) => {
                let points = rows
                    .iter()
                    .enumerate()
                    .map(|(i, row)| {
                        row.iter()
                            .enumerate()
                            .map(|(j, t)| {
                                tribez::parse_rational(t)
                                    .map_err(|e| input_error(py, format!("points[{i}][{j}]: {e}")))
                            })
                            .collect::<PyResult<Vec<_>>>()
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                CertifyPoints::Given {
                    points,
                    source: "points".into(),
                }
            }
            (None, Some(count)) => {
                if count == 0 || count > MAX_RANDOM_POINTS {
                    return Err(input_error(
                        py,
                        format!(
                            "random: {count}: expected a whole number from 1 to {MAX_RANDOM_POINTS}"
                        ),
                    ));
                }
                CertifyPoints::Random { count, seed }
            }
            _ => {
                return Err(input_error(
                    py,
                    "give points or random (a number of random points), not both",
                ));
            }
        };
        let options = CertifyOptions {
            points,
            precision,
            algorithm,
            label,
        };
        let patch = patch.patch.clone();
        let report = py
            .detach(|| {
                tribez::certify_until(&patch, &options, &crate::interrupted)
                    .map_err(|e| e.to_string())
            })
            .map_err(|e| input_error(py, e))??;
        Ok(NativeDocument {
            kind: "certify",
            json: json_of(py, &report)?,
            text: report.text(),
            success: report.success(),
        })
    })
}
