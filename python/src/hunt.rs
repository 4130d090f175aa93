//! `hunt`: the library's hunt for the inputs where another implementation is least accurate
//! (`tribez::hunt::hunt`, what `tribez hunt` runs), with a Python function as the target, and
//! `NativeHunt`, its report rendered as the command line renders it (text, JSON, a claim file).
//!
//! The search and the judging run with the GIL released; the GIL is taken again for each call of
//! the target: `call(rows, n, first)` (the Python layer's wrapper around the user's function)
//! receives the `n` rows from row `first` as the bytes of row-major native-endian `f64` and
//! answers the bytes of `n` rows of `d` float64 numbers, or raises. Its exception ends the hunt
//! at once and reaches the caller unchanged. Pending signals (Ctrl-C) are run before every call.

use num_rational::BigRational;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use serde_json::{Map, Value as Json, json};

use tribez::hunt::{HuntError, HuntOptions, HuntReport, HuntRow, decimal, hex};
use tribez::{Patch, Precision};

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

fn hexes(p: Precision, xs: &[f64]) -> Vec<String> {
    xs.iter().map(|&x| hex(p, x)).collect()
}

/// An error in ULPs as the command line's hunt report writes it: `0`, 4 decimals without
/// trailing zeros from 0.001 to 10^6, else 4 significant digits in exponent form.
fn ulps_text(u: f64) -> String {
    if u == 0.0 {
        "0".into()
    } else if !u.is_finite() {
        "not finite".into()
    } else if (1e-3..1e6).contains(&u.abs()) {
        format!("{u:.4}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{u:.3e}")
    }
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

impl NativeHunt {
    fn row_json(&self, r: &HuntRow) -> Json {
        let p = self.report.precision;
        json!({
            "row": r.row,
            "input": hexes(p, &r.input),
            "claimed": hexes(p, &r.claimed),
            "exact": r.exact.iter().map(|q| q.to_string()).collect::<Vec<_>>(),
            "exact_decimal": r.exact.iter().map(|q| decimal(q, 17)).collect::<Vec<_>>(),
            "ulps": if r.ulps.is_finite() { json!(r.ulps) } else { Json::Null },
            "breaks": !r.passed,
            "reason": r.reason,
        })
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

    /// The worst rows, worst first: (row, input, claimed, exact as `p/q` texts, ulps, passed,
    /// reason).
    #[allow(clippy::type_complexity)]
    fn worst(
        &self,
    ) -> Vec<(
        u64,
        Vec<f64>,
        Vec<f64>,
        Vec<String>,
        f64,
        bool,
        Option<String>,
    )> {
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
        let h = &self.report;
        let p = h.precision;
        let mut out = format!(
            "tribez.hunt: {} on {} ({} {}, tolerance {})\n",
            self.program,
            self.patch,
            if h.cartesian {
                "Cartesian"
            } else {
                "barycentric"
            },
            p.name(),
            h.tolerance
        );
        out += &format!(
            "{} rows evaluated ({} uniform, {} at the places floats fail, {} local moves); {} broke the tolerance\n",
            h.evaluated, h.by_kind[0], h.by_kind[1], h.by_kind[2], h.broke
        );
        out += &format!("seed: {}\n", h.seed);
        if !h.worst.is_empty() {
            out += &format!("the {} worst rows:\n", h.worst.len());
        }
        for (i, r) in h.worst.iter().enumerate() {
            out += &format!(
                "{:>3}. row {}: {} ulp, {} the tolerance{}\n",
                i + 1,
                r.row,
                ulps_text(r.ulps),
                if r.passed { "within" } else { "breaks" },
                r.reason
                    .as_ref()
                    .map(|s| format!(" ({s})"))
                    .unwrap_or_default()
            );
            out += &format!("     input    {}\n", hexes(p, &r.input).join(", "));
            out += &format!("     claimed  {}\n", hexes(p, &r.claimed).join(", "));
            let exact: Vec<String> = r.exact.iter().map(|q| decimal(q, 17)).collect();
            out += &format!("     exact    {}\n", exact.join(", "));
        }
        out += &format!("reproduce: {}\n", self.reproduce);
        out
    }

    /// The JSON report (the keys of `tribez hunt --format json`; `program` is the function's
    /// name, `reproduce` the Python call).
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        let h = &self.report;
        let value = json!({
            "command": "hunt",
            "patch": self.patch,
            "program": [self.program],
            "precision": h.precision.name(),
            "tolerance": h.tolerance.to_string(),
            "cartesian": h.cartesian,
            "seed": h.seed,
            "budget": h.budget,
            "evaluated": h.evaluated,
            "broke": h.broke,
            "uniform": h.by_kind[0],
            "special": h.by_kind[1],
            "local": h.by_kind[2],
            "passed": h.broke == 0,
            "worst": h.worst.iter().map(|r| self.row_json(r)).collect::<Vec<_>>(),
            "reproduce": self.reproduce,
        });
        json_of(py, &value)
    }

    /// The claim file of the worst rows (as `tribez hunt --claims-out`): `patch_file` is the
    /// patch file's path relative to the claim file's directory; without one the patch is
    /// embedded as an inline `[patch]` table.
    #[pyo3(signature = (patch_file, patch))]
    fn claims_text(&self, patch_file: Option<String>, patch: &NativePatch) -> String {
        let h = &self.report;
        let p = h.precision;
        let mut s = format!(
            "# The worst rows `tribez.hunt` found (seed {}): `tribez check` judges them again.\n# {}\nsource = {}\n",
            h.seed,
            self.reproduce,
            toml_str(&format!("tribez.hunt of {}", self.program)),
        );
        match patch_file {
            Some(file) => s += &format!("patch = {}\n", toml_str(&file)),
            None => match patch.patch.to_json_value() {
                Json::Object(m) => toml_table(&mut s, "patch", &m),
                other => s += &format!("patch = {}\n", toml_value(&other)),
            },
        }
        let list = |xs: &[f64]| {
            format!(
                "[{}]",
                hexes(p, xs)
                    .iter()
                    .map(|x| toml_str(x))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        for r in &h.worst {
            s += &format!(
                "\n[[claim]]\nid = \"hunt-row-{}\"\nop = \"eval\"\nprecision = \"{}\"\ntolerance = {}\n{} = {}\nexpect = {}\n",
                r.row,
                p.name(),
                toml_str(&h.tolerance.to_string()),
                if h.cartesian { "cartesian" } else { "at" },
                list(&r.input),
                list(&r.claimed)
            );
        }
        s
    }
}
