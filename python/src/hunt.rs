//! `hunt`: the library's hunt for the inputs where another implementation is least accurate
//! (`tribez::hunt::hunt`, what `tribez hunt` runs), with a Python function as the target, and
//! `NativeHunt`, its report rendered by the library (`HuntReport::text`, `json`, `claims_file`: what
//! the command line prints), with the function's name and the Python call as its labels.
//!
//! The search and the judging run with the GIL released; the GIL is taken again for each call of
//! the target: `call(rows, n, first)` (the Python layer's wrapper around the user's function)
//! receives the `n` rows from row `first` as the bytes of row-major native-endian `f64` and
//! answers the bytes of `n` rows of `d` float64 numbers, or raises. Its exception ends the hunt
//! at once and reaches the caller unchanged. Pending signals (Ctrl-C) are run before every call.

use num_rational::BigRational;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use serde_json::{Map, Value as Json};

use tribez::Patch;
use tribez::hunt::{HuntError, HuntLabels, HuntOptions, HuntReport, HuntRow};

use crate::claims::json_of;
use crate::patch::{NativePatch, f64s};
use crate::{guard, input_error, precision_arg, tolerance_arg};

/// A finished hunt: the library's report, the names the report gives the patch and the function,
/// and the Python call that repeats the hunt.
#[pyclass(module = "tribez._native", frozen)]
pub struct NativeHunt {
    report: HuntReport,
    patch: String,
    program: String,
    reproduce: String,
}

/// Hunt with `call` as the target (see the module documentation). `label` names the patch,
/// `program` the function and `reproduce` is the call that repeats the hunt, in the report.
#[pyfunction]
#[pyo3(signature = (patch, call, precision, tolerance, budget, seed, cartesian, batch, top, label, program, reproduce))]
#[allow(clippy::too_many_arguments)]
pub fn hunt(
    py: Python<'_>,
    patch: &NativePatch,
    call: Py<PyAny>,
    precision: &str,
    tolerance: &str,
    budget: u64,
    seed: u64,
    cartesian: bool,
    batch: usize,
    top: usize,
    label: String,
    program: String,
    reproduce: String,
) -> PyResult<NativeHunt> {
    guard(py, || {
        let options = HuntOptions {
            precision: precision_arg(py, precision)?,
            tolerance: tolerance_arg(py, tolerance)?,
            budget,
            seed,
            cartesian,
            batch,
            top,
        };
        let patch: &Patch = &patch.patch;
        let width = if cartesian {
            patch.simplex_dim()
        } else {
            patch.simplex_dim() + 1
        };
        let result = py.detach(|| {
            let mut sent: u64 = 0;
            let mut target = |rows: &[f64]| -> Result<Vec<f64>, PyErr> {
                let n = rows.len() / width;
                let first = sent + 1;
                sent += n as u64;
                Python::attach(|py| {
                    py.check_signals()?;
                    let bytes: Vec<u8> = rows.iter().flat_map(|x| x.to_ne_bytes()).collect();
                    let answer = call.bind(py).call1((PyBytes::new(py, &bytes), n, first))?;
                    let answer = answer.cast::<PyBytes>().map_err(PyErr::from)?;
                    Ok(f64s(answer.as_bytes()))
                })
            };
            tribez::hunt::hunt(patch, &options, &mut target)
        });
        let report = match result {
            Ok(r) => r,
            Err(HuntError::Target(e)) => return Err(e),
            Err(e) => return Err(input_error(py, format!("{label}: {e}"))),
        };
        Ok(NativeHunt {
            report,
            patch: label,
            program,
            reproduce,
        })
    })
}

/// A string as a TOML basic string (JSON's escapes are TOML's).
fn toml_str(s: &str) -> String {
    serde_json::to_string(s).expect("a string serialises")
}

/// A JSON value as a TOML value (objects as inline tables; the patch file has no nulls).
fn toml_value(v: &Json) -> String {
    match v {
        Json::Null => "\"\"".into(),
        Json::Bool(b) => b.to_string(),
        Json::Number(x) => x.to_string(),
        Json::String(s) => toml_str(s),
        Json::Array(xs) => format!(
            "[{}]",
            xs.iter().map(toml_value).collect::<Vec<_>>().join(", ")
        ),
        Json::Object(m) => format!(
            "{{ {} }}",
            m.iter()
                .map(|(k, v)| format!("{} = {}", toml_str(k), toml_value(v)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A JSON object as the TOML table `[path]` (its sub-objects as `[path."key"]` tables after it).
fn toml_table(out: &mut String, path: &str, table: &Map<String, Json>) {
    out.push_str(&format!("\n[{path}]\n"));
    for (k, v) in table.iter().filter(|(_, v)| !v.is_object()) {
        out.push_str(&format!("{} = {}\n", toml_str(k), toml_value(v)));
    }
    for (k, v) in table {
        if let Json::Object(m) = v {
            toml_table(out, &format!("{path}.{}", toml_str(k)), m);
        }
    }
}

/// A hunt's report as plain Python values (for pickling): precision, tolerance, seed, budget,
/// cartesian, evaluated, broke, rows per kind, the worst rows (as [`NativeHunt::worst`] gives
/// them), and the names of the patch, the function and the call that repeats the hunt.
type HuntState = (
    String,
    String,
    u64,
    u64,
    bool,
    u64,
    u64,
    (u64, u64, u64),
    Vec<WorstRow>,
    String,
    String,
    String,
);

/// One worst row: (row, input, claimed, exact as `p/q` texts, ulps, passed, reason).
type WorstRow = (
    u64,
    Vec<f64>,
    Vec<f64>,
    Vec<String>,
    f64,
    bool,
    Option<String>,
);

impl NativeHunt {
    /// How the Python report names the hunt.
    fn labels(&self) -> HuntLabels<'_> {
        HuntLabels {
            tool: "tribez.hunt",
            patch: &self.patch,
            program: &self.program,
            reproduce: &self.reproduce,
        }
    }
}

#[pymethods]
impl NativeHunt {
    #[getter]
    fn evaluated(&self) -> u64 {
        self.report.evaluated
    }

    #[getter]
    fn broke(&self) -> u64 {
        self.report.broke
    }

    #[getter]
    fn seed(&self) -> u64 {
        self.report.seed
    }

    #[getter]
    fn budget(&self) -> u64 {
        self.report.budget
    }

    #[getter]
    fn precision(&self) -> &'static str {
        self.report.precision.name()
    }

    #[getter]
    fn tolerance(&self) -> String {
        self.report.tolerance.to_string()
    }

    #[getter]
    fn cartesian(&self) -> bool {
        self.report.cartesian
    }

    /// Rows of each kind: uniform, at the places floats fail, local moves.
    #[getter]
    fn by_kind(&self) -> (u64, u64, u64) {
        let [u, s, l] = self.report.by_kind;
        (u, s, l)
    }

    #[getter]
    fn max_ulps(&self) -> Option<f64> {
        self.report.max_ulps()
    }

    /// Everything the report holds, as plain values (what pickling stores): see [`HuntState`].
    fn state(&self) -> HuntState {
        let h = &self.report;
        (
            h.precision.name().to_string(),
            h.tolerance.to_string(),
            h.seed,
            h.budget,
            h.cartesian,
            h.evaluated,
            h.broke,
            (h.by_kind[0], h.by_kind[1], h.by_kind[2]),
            self.worst(),
            self.patch.clone(),
            self.program.clone(),
            self.reproduce.clone(),
        )
    }

    /// The report of [`NativeHunt::state`] again (exact values read back from their `p/q`
    /// texts); `ValueError` naming the field for a state that is not one.
    #[staticmethod]
    fn from_state(py: Python<'_>, state: HuntState) -> PyResult<NativeHunt> {
        let (
            precision,
            tolerance,
            seed,
            budget,
            cartesian,
            evaluated,
            broke,
            kinds,
            worst,
            patch,
            program,
            reproduce,
        ) = state;
        let worst = worst
            .into_iter()
            .map(|(row, input, claimed, exact, ulps, passed, reason)| {
                let exact = exact
                    .iter()
                    .map(|q| {
                        tribez::parse_rational(q).map_err(|e| {
                            input_error(py, format!("hunt state: row {row}: exact value: {e}"))
                        })
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                Ok(HuntRow {
                    row,
                    input,
                    claimed,
                    exact,
                    ulps,
                    passed,
                    reason,
                })
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok(NativeHunt {
            report: HuntReport {
                precision: precision_arg(py, &precision)?,
                tolerance: tolerance_arg(py, &tolerance)?,
                seed,
                budget,
                cartesian,
                evaluated,
                broke,
                by_kind: [kinds.0, kinds.1, kinds.2],
                worst,
            },
            patch,
            program,
            reproduce,
        })
    }

    /// The worst rows, worst first: (row, input, claimed, exact as `p/q` texts, ulps, passed,
    /// reason).
    fn worst(&self) -> Vec<WorstRow> {
        self.report
            .worst
            .iter()
            .map(|r| {
                (
                    r.row,
                    r.input.clone(),
                    r.claimed.clone(),
                    r.exact.iter().map(BigRational::to_string).collect(),
                    r.ulps,
                    r.passed,
                    r.reason.clone(),
                )
            })
            .collect()
    }

    /// The text report (as `tribez hunt` prints it; the header names the function, the last line
    /// is the Python call that repeats the hunt).
    fn text(&self) -> String {
        self.report.text(&self.labels())
    }

    /// The JSON report (the keys of `tribez hunt --format json`; `program` is the function's
    /// name, `reproduce` the Python call).
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        let value = serde_json::to_value(self.report.json(
            &self.patch,
            [&self.program],
            &self.reproduce,
        ))
        .expect("a hunt report serialises");
        json_of(py, &value)
    }

    /// The claim file of the worst rows (as `tribez hunt --claims-out`): `patch_file` is the
    /// patch file's path relative to the claim file's directory; without one the patch is
    /// embedded as an inline `[patch]` table.
    #[pyo3(signature = (patch_file, patch))]
    fn claims_text(&self, patch_file: Option<String>, patch: &NativePatch) -> String {
        let patch_toml = match patch_file {
            Some(file) => HuntReport::toml_entry("patch", &file),
            None => match patch.patch.to_json_value() {
                Json::Object(m) => {
                    let mut t = String::new();
                    toml_table(&mut t, "patch", &m);
                    t
                }
                other => format!("patch = {}\n", toml_value(&other)),
            },
        };
        self.report.claims_file(&self.labels(), &patch_toml)
    }
}
