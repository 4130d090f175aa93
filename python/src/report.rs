//! `NativeReport`: the library's batch report (`tribez::batch::BatchReport`) with per-row
//! arrays, and `check_rows`, which judges numpy rows with the library's batch engine.

use std::sync::{Arc, OnceLock};

use num_rational::BigRational;
use num_traits::ToPrimitive;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBytes, PyType};
use rayon::prelude::*;
use serde_json::{Value as Json, json};

use tribez::batch::{
    BatchChecker, BatchOptions, BatchReport, FailedCoord, FailedRow, RowVerdict, ULP_BUCKETS,
    UlpHistogram, WorstRow,
};
use tribez::constructions::{BezierPatch, ControlNet};
use tribez::format::{
    exact_f32, exact_f64, parse_rational, round_f32, round_f64, ulps_error_f32, ulps_error_f64,
};
use tribez::kernels::ExactEvaluator;
use tribez::report::Measures;
use tribez::{Algorithm, Patch, Precision, Tolerance};

use crate::patch::{NativePatch, f64s};
use crate::{guard, input_error, precision_arg, tolerance_arg};

/// The numbers of a 2-D numpy array of `width` columns, read in place (no copy): `array` must
/// be a `numpy.ndarray` of native-endian float64, C-contiguous (what the Python layer's
/// `float_rows` returns); an array whose data is not aligned for `f64` is copied. The slice lives
/// as long as the borrow of `array`, which keeps the array (and so its data) alive.
///
/// The array is read while the GIL is released: like numpy's own operations that release it,
/// this assumes no other thread writes to it meanwhile (documented on `tribez.check`).
fn f64_rows<'a>(
    py: Python<'_>,
    array: &'a Bound<'_, PyAny>,
    width: usize,
    what: &str,
) -> PyResult<std::borrow::Cow<'a, [f64]>> {
    use std::borrow::Cow;
    static NDARRAY: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let ndarray = NDARRAY.get_or_try_init(py, || {
        py.import("numpy")?
            .getattr("ndarray")?
            .cast_into::<PyType>()
            .map(Bound::unbind)
            .map_err(PyErr::from)
    })?;
    let native = if cfg!(target_endian = "little") {
        "<f8"
    } else {
        ">f8"
    };
    let bad = || {
        input_error(
            py,
            format!("{what}: expected a C-contiguous float64 numpy array"),
        )
    };
    if !array.get_type().is(ndarray.bind(py)) {
        return Err(bad());
    }
    let interface = array.getattr("__array_interface__")?;
    let typestr: String = interface.get_item("typestr")?.extract()?;
    let shape: Vec<usize> = interface.get_item("shape")?.extract()?;
    let contiguous = interface.get_item("strides")?.is_none();
    let (address, _readonly): (usize, bool) = interface.get_item("data")?.extract()?;
    if typestr != native || !contiguous || shape.len() != 2 || shape[1] != width {
        return Err(bad());
    }
    let len = shape[0]
        .checked_mul(width)
        .ok_or_else(|| input_error(py, format!("{what}: too many numbers")))?;
    if len == 0 {
        return Ok(Cow::Borrowed(&[]));
    }
    let ptr = address as *const f64;
    if ptr.is_null() {
        return Err(bad());
    }
    if !ptr.is_aligned() {
        // SAFETY: the ndarray's data holds `len` float64 values from `address` (its shape,
        // C-contiguous, 8-byte items), alive while `array` is; read unaligned, byte by byte.
        let bytes = unsafe { std::slice::from_raw_parts(address as *const u8, len * 8) };
        return Ok(Cow::Owned(f64s(bytes)));
    }
    // SAFETY: as above, and the pointer is aligned for f64; the slice borrows `array`, which
    // holds a reference to the ndarray and so keeps its data alive.
    Ok(Cow::Borrowed(unsafe {
        std::slice::from_raw_parts(ptr, len)
    }))
}

/// Judge in-memory rows with the library's batch engine (the GIL released meanwhile): `points`
/// and `values` C-contiguous float64 numpy arrays of `width` and `dimension` columns, read in
/// place.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn check_rows(
    py: Python<'_>,
    patch: &NativePatch,
    points: &Bound<'_, PyAny>,
    values: &Bound<'_, PyAny>,
    width: usize,
    dimension: usize,
    tolerance: &str,
    precision: &str,
    cartesian: bool,
    algorithm: &str,
    first_row: usize,
) -> PyResult<NativeReport> {
    guard(py, || {
        let Some(poly) = patch.patch.polynomial().cloned() else {
            return Err(input_error(
                py,
                format!(
                    "patch: this is {}; check judges polynomial Bézier patches (rational patches and S-patches: claim files)",
                    patch.patch.described()
                ),
            ));
        };
        let tolerance = tolerance_arg(py, tolerance)?;
        let precision = precision_arg(py, precision)?;
        let algorithm = match algorithm {
            "bernstein" => Algorithm::Bernstein,
            _ => Algorithm::Casteljau,
        };
        let options = BatchOptions {
            tolerance,
            precision: Some(precision),
            algorithm,
            cartesian,
            row_detail: false,
        };
        let name = poly.name.clone().unwrap_or_else(|| "the patch".into());
        let key = judged_key(&patch.patch, algorithm, cartesian);
        let checker = BatchChecker::new(poly.clone(), &options).map_err(|e| input_error(py, e))?;
        let pts = f64_rows(py, points, width, "points")?;
        let vals = f64_rows(py, values, dimension, "values")?;
        let rows = RowsRef {
            patch: &poly,
            precision,
            cartesian,
            points: &pts,
            values: &vals,
            width,
            dim: dimension,
        };
        let (report, verdicts, detail) = py
            .detach(|| {
                let (report, verdicts) = match checker.check_rows_until(
                    &pts,
                    &vals,
                    first_row,
                    "<arrays>",
                    &name,
                    &crate::interrupted,
                ) {
                    Ok(Ok(done)) => done,
                    Ok(Err(stop)) => return Ok(Err(stop)),
                    Err(e) => return Err(e.to_string()),
                };
                // The detail, where it costs no exact arithmetic but at ties, now (the arrays
                // are not kept); else later, from a copy of the rows, when first asked for.
                let detail = rows
                    .detail_is_cheap()
                    .then(|| rows.detail(&verdicts, first_row, true));
                Ok(Ok((report, verdicts, detail)))
            })
            .map_err(|e| input_error(py, e))??;
        let (detail, source) = match detail {
            Some(d) => (OnceLock::from(d), None),
            None => (OnceLock::new(), Some(Arc::new(rows.to_owned()))),
        };
        Ok(NativeReport {
            report,
            verdicts,
            detail,
            source,
            key,
        })
    })
}

/// What a report was judged about, beyond what the library's merge compares (tolerance,
/// precision, patch name): the patch itself (an FNV-1a hash of its JSON patch file, stable
/// across processes and machines), the algorithm and the input space. Reports merge only with
/// equal keys.
fn judged_key(patch: &Patch, algorithm: Algorithm, cartesian: bool) -> String {
    let text = patch.to_json();
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    let algorithm = match algorithm {
        Algorithm::Bernstein => "bernstein",
        _ => "casteljau",
    };
    let space = if cartesian {
        "cartesian"
    } else {
        "barycentric"
    };
    format!("patch {hash:016x}, {algorithm}, {space} points")
}

/// The numbers of the rows judged, kept until the per-row detail is first asked for.
pub(crate) struct Rows {
    patch: BezierPatch,
    precision: Precision,
    cartesian: bool,
    points: Vec<f64>,
    values: Vec<f64>,
    width: usize,
    dim: usize,
}

impl Rows {
    fn borrowed(&self) -> RowsRef<'_> {
        RowsRef {
            patch: &self.patch,
            precision: self.precision,
            cartesian: self.cartesian,
            points: &self.points,
            values: &self.values,
            width: self.width,
            dim: self.dim,
        }
    }
}

/// The rows judged, borrowed (from the caller's arrays, or from [`Rows`]).
struct RowsRef<'a> {
    patch: &'a BezierPatch,
    precision: Precision,
    cartesian: bool,
    points: &'a [f64],
    values: &'a [f64],
    width: usize,
    dim: usize,
}

/// Per-row figures beyond the verdicts, aligned with them: the error in ULPs at the inputs as
/// intended, and whether every coordinate is the correctly rounded value at the inputs as seen.
#[derive(Clone, Debug, Default)]
pub(crate) struct Detail {
    ulps_intended: Vec<f64>,
    correctly_rounded: Vec<bool>,
}

/// The float of `precision` that `x` denotes (an f32 batch rounds to the nearest f32), or
/// `None` if it is not finite there.
fn seen_float(x: f64, precision: Precision) -> Option<f64> {
    let y = match precision {
        Precision::F32 => f64::from(x as f32),
        Precision::F64 => x,
    };
    y.is_finite().then_some(y)
}

fn ulps_of(y: &BigRational, q: &BigRational, precision: Precision) -> f64 {
    if y == q {
        return 0.0;
    }
    match precision {
        Precision::F32 => ulps_error_f32(y, q),
        Precision::F64 => ulps_error_f64(y, q),
    }
    .to_f64()
    .unwrap_or(f64::INFINITY)
}

impl RowsRef<'_> {
    /// A copy to keep.
    fn to_owned(&self) -> Rows {
        Rows {
            patch: self.patch.clone(),
            precision: self.precision,
            cartesian: self.cartesian,
            points: self.points.to_vec(),
            values: self.values.to_vec(),
            width: self.width,
            dim: self.dim,
        }
    }

    /// Whether [`RowsRef::detail`] needs exact arithmetic only at ties (errors of exactly 1/2
    /// ulp, rare): an f64 batch (its inputs as intended are the floats seen) about a net whose
    /// control points are f64s. Its errors at the intended inputs are then the verdicts'.
    fn detail_is_cheap(&self) -> bool {
        self.precision == Precision::F64
            && self
                .patch
                .net
                .coords()
                .iter()
                .all(|q| as_float(q, Precision::F64).as_ref() == Some(q))
    }

    /// The row-by-row detail (exact arithmetic where it can differ from the verdicts' figures).
    ///
    /// The inputs as intended are the numbers given (f64), the patch as intended its exact
    /// control points; as seen, both are rounded to the precision. Where they coincide (a net
    /// whose control points are floats of the precision, a row whose inputs are too: always in
    /// f64) the error at the inputs as intended is the error as seen, already known; otherwise it
    /// is computed exactly, or, without `exact`, left unknown (NaN): the cheap detail, which is
    /// what a report carries when it is pickled or merged before its rows were read.
    /// "Correctly rounded" is `ulps_seen <= 1/2` (1/2 is a boundary the batch engine settles
    /// exactly), except at exactly 1/2, a possible tie, settled exactly (rare: always done).
    fn detail(&self, verdicts: &[RowVerdict], first_row: usize, exact: bool) -> Detail {
        let p = self.precision;
        let net = &self.patch.net;
        let seen_net: ControlNet<BigRational> =
            net.map(|q| as_float(q, p).unwrap_or_else(|| q.clone()));
        let net_is_seen = seen_net.coords() == net.coords();
        let intended = ExactEvaluator::new(net);
        let seen = ExactEvaluator::new(&seen_net);
        let point = |xs: Vec<BigRational>| -> Option<Vec<BigRational>> {
            if self.cartesian {
                self.patch.domain_or_reference().barycentric(&xs).ok()
            } else {
                Some(xs)
            }
        };
        let (ulps_intended, correctly_rounded): (Vec<f64>, Vec<bool>) = verdicts
            .par_iter()
            .map(|v| {
                let i = v.row - first_row;
                let xs = &self.points[i * self.width..(i + 1) * self.width];
                let ys = &self.values[i * self.dim..(i + 1) * self.dim];
                if !v.ulps.is_finite() {
                    return (f64::INFINITY, false);
                }
                if ys.iter().any(|&y| seen_float(y, p).is_none()) {
                    return (f64::INFINITY, false);
                }
                let claimed = || -> Vec<BigRational> {
                    ys.iter()
                        .filter_map(|&y| seen_float(y, p).and_then(exact_f64))
                        .collect()
                };
                let inputs_seen = xs.iter().all(|&x| seen_float(x, p) == Some(x));
                let ulps_intended = if net_is_seen && inputs_seen {
                    v.ulps
                } else if !exact {
                    f64::NAN
                } else {
                    let lambda = xs
                        .iter()
                        .map(|&x| exact_f64(x))
                        .collect::<Option<Vec<_>>>()
                        .and_then(point);
                    match lambda {
                        None => f64::INFINITY,
                        Some(l) => intended
                            .evaluate_fast(&l)
                            .iter()
                            .zip(&claimed())
                            .map(|(q, y)| ulps_of(y, q, p))
                            .fold(0.0, f64::max),
                    }
                };
                let correctly_rounded = if v.ulps == 0.5 {
                    let lambda = xs
                        .iter()
                        .map(|&x| seen_float(x, p).and_then(exact_f64))
                        .collect::<Option<Vec<_>>>()
                        .and_then(point);
                    lambda.is_some_and(|l| {
                        seen.evaluate_fast(&l)
                            .iter()
                            .zip(&claimed())
                            .all(|(q, y)| as_float(q, p).as_ref() == Some(y))
                    })
                } else {
                    v.ulps < 0.5
                };
                (ulps_intended, correctly_rounded)
            })
            .unzip();
        Detail {
            ulps_intended,
            correctly_rounded,
        }
    }
}

/// A batch report and, row by row, its verdicts and errors.
#[pyclass(module = "tribez._native", frozen)]
pub struct NativeReport {
    pub(crate) report: BatchReport,
    /// Every row's verdict, by row index.
    pub(crate) verdicts: Vec<RowVerdict>,
    /// The per-row detail, computed when first asked for (from `source`).
    pub(crate) detail: OnceLock<Detail>,
    /// The rows' numbers, while the detail is not computed (reports made by `check_rows`).
    pub(crate) source: Option<Arc<Rows>>,
    /// What it was judged about ([`judged_key`]).
    pub(crate) key: String,
}

impl NativeReport {
    fn with_detail(
        report: BatchReport,
        verdicts: Vec<RowVerdict>,
        detail: Detail,
        key: String,
    ) -> Self {
        NativeReport {
            report,
            verdicts,
            detail: OnceLock::from(detail),
            source: None,
            key,
        }
    }

    /// The per-row detail (computed on first use, the GIL released meanwhile).
    ///
    /// Not `OnceLock::get_or_init` around the released GIL: a second Python thread blocking on
    /// the lock with the GIL held would deadlock the first. Two threads may both compute it; the
    /// first to finish sets it (the same figures either way).
    fn detail(&self, py: Python<'_>) -> &Detail {
        if let Some(d) = self.detail.get() {
            return d;
        }
        let d = match &self.source {
            Some(rows) => {
                let first = self.verdicts.first().map_or(0, |v| v.row);
                py.detach(|| rows.borrowed().detail(&self.verdicts, first, true))
            }
            None => Detail::default(),
        };
        let _ = self.detail.set(d);
        self.detail.get().expect("set just now")
    }

    /// The detail as far as it is known without exact arithmetic: the full detail if it was
    /// computed, else the cheap one (errors at the intended inputs that differ from the seen
    /// ones unknown, NaN). What merging and pickling carry, so that neither costs exact
    /// arithmetic per row (a Dask partition of f32 results would otherwise pay it for every row).
    fn known_detail(&self, py: Python<'_>) -> std::borrow::Cow<'_, Detail> {
        use std::borrow::Cow;
        if let Some(d) = self.detail.get() {
            return Cow::Borrowed(d);
        }
        match &self.source {
            Some(rows) => {
                let first = self.verdicts.first().map_or(0, |v| v.row);
                Cow::Owned(py.detach(|| rows.borrowed().detail(&self.verdicts, first, false)))
            }
            None => Cow::Owned(Detail::default()),
        }
    }
}

#[pymethods]
impl NativeReport {
    #[getter]
    fn passed(&self) -> u64 {
        self.report.passed
    }

    #[getter]
    fn failed(&self) -> u64 {
        self.report.failed
    }

    #[getter]
    fn fell_back(&self) -> u64 {
        self.report.fell_back
    }

    #[getter]
    fn tolerance(&self) -> String {
        self.report.tolerance.text()
    }

    #[getter]
    fn precision(&self) -> Option<&'static str> {
        self.report.precision.map(Precision::name)
    }

    #[getter]
    fn max_ulps(&self) -> Option<f64> {
        self.report.max_ulps
    }

    /// The worst row as JSON (the `worst` object of the JSON report, with `row` for its index).
    fn worst_json(&self, py: Python<'_>) -> PyResult<Option<String>> {
        guard(py, || {
            let worst = || {
                let mut j = self.report.json();
                let mut w = j.get_mut("worst")?.take();
                let obj = w.as_object_mut()?;
                // in-memory rows are named by index where a file's rows have line numbers
                let row = obj.remove("line")?;
                obj.insert("row".into(), row);
                Some(w.to_string())
            };
            Ok(worst())
        })
    }

    fn histogram(&self) -> Vec<(&'static str, u64)> {
        ULP_BUCKETS
            .iter()
            .copied()
            .zip(self.report.histogram.counts)
            .collect()
    }

    fn text(&self, py: Python<'_>) -> PyResult<String> {
        guard(py, || Ok(self.report.text()))
    }

    /// The JSON report, byte for byte the command line's `--format json` (pretty, a final
    /// newline).
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        guard(py, || Ok(format!("{:#}\n", self.report.json())))
    }

    fn merge(&self, py: Python<'_>, other: &NativeReport) -> PyResult<NativeReport> {
        guard(py, || {
            if self.key != other.key {
                return Err(input_error(
                    py,
                    format!(
                        "merge: reports judged differently ({} vs {})",
                        self.key, other.key
                    ),
                ));
            }
            // disjoint row sets: both verdict lists are sorted by row
            let (mut i, mut j) = (0, 0);
            while i < self.verdicts.len() && j < other.verdicts.len() {
                let (a, b) = (self.verdicts[i].row, other.verdicts[j].row);
                if a == b {
                    return Err(input_error(
                        py,
                        format!(
                            "merge: both reports have row {a}: merge reports of disjoint row sets (give each part its first_row)"
                        ),
                    ));
                }
                if a < b {
                    i += 1;
                } else {
                    j += 1;
                }
            }
            let mut report = self.report.clone();
            report
                .merge(&other.report)
                .map_err(|e| input_error(py, format!("merge: {e}")))?;
            let (a, b) = (self.known_detail(py), other.known_detail(py));
            let mut rows: Vec<(RowVerdict, f64, bool)> = self
                .verdicts
                .iter()
                .zip(a.ulps_intended.iter().zip(&a.correctly_rounded))
                .chain(
                    other
                        .verdicts
                        .iter()
                        .zip(b.ulps_intended.iter().zip(&b.correctly_rounded)),
                )
                .map(|(v, (&u, &c))| (*v, u, c))
                .collect();
            rows.sort_by_key(|r| r.0.row);
            let mut detail = Detail::default();
            let mut verdicts = Vec::with_capacity(rows.len());
            for (v, u, c) in rows {
                verdicts.push(v);
                detail.ulps_intended.push(u);
                detail.correctly_rounded.push(c);
            }
            Ok(NativeReport::with_detail(
                report,
                verdicts,
                detail,
                self.key.clone(),
            ))
        })
    }

    /// Per-row arrays: (name, numpy dtype, bytes).
    fn row_arrays<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Vec<(&'static str, &'static str, Bound<'py, PyBytes>)>> {
        guard(py, || {
            let rows = &self.verdicts;
            let detail = self.detail(py);
            let mut index = Vec::with_capacity(rows.len() * 8);
            let mut passed = Vec::with_capacity(rows.len());
            let mut ulps = Vec::with_capacity(rows.len() * 8);
            let mut fell_back = Vec::with_capacity(rows.len());
            for r in rows {
                index.extend_from_slice(&(r.row as i64).to_ne_bytes());
                passed.push(u8::from(r.pass));
                ulps.extend_from_slice(&r.ulps.to_ne_bytes());
                fell_back.push(u8::from(r.fell_back));
            }
            let intended: Vec<u8> = detail
                .ulps_intended
                .iter()
                .flat_map(|u| u.to_ne_bytes())
                .collect();
            let cr: Vec<u8> = detail
                .correctly_rounded
                .iter()
                .map(|&c| u8::from(c))
                .collect();
            Ok(vec![
                ("row", "int64", PyBytes::new(py, &index)),
                ("passed", "bool", PyBytes::new(py, &passed)),
                ("ulps_seen", "float64", PyBytes::new(py, &ulps)),
                ("ulps_intended", "float64", PyBytes::new(py, &intended)),
                ("correctly_rounded", "bool", PyBytes::new(py, &cr)),
                ("fell_back", "bool", PyBytes::new(py, &fell_back)),
            ])
        })
    }

    /// The whole report as a JSON state (for pickling).
    fn state(&self, py: Python<'_>) -> PyResult<String> {
        guard(py, || {
            // infinite: null; unknown (NaN): "nan"
            let finite = |u: f64| {
                if u.is_finite() {
                    json!(u)
                } else if u.is_nan() {
                    json!("nan")
                } else {
                    Json::Null
                }
            };
            let detail = self.known_detail(py);
            let verdicts: Vec<Json> = self
                .verdicts
                .iter()
                .zip(detail.ulps_intended.iter().zip(&detail.correctly_rounded))
                .map(|(v, (&ui, &cr))| {
                    json!([v.row, v.pass, v.fell_back, finite(v.ulps), finite(ui), cr])
                })
                .collect();
            Ok(
                json!({"report": state_of(&self.report), "verdicts": verdicts, "key": self.key})
                    .to_string(),
            )
        })
    }

    #[staticmethod]
    fn from_state(py: Python<'_>, state: &str) -> PyResult<NativeReport> {
        guard(py, || {
            let j: Json = serde_json::from_str(state)
                .map_err(|e| crate::input_error(py, format!("report state: {e}")))?;
            let rows = j["verdicts"].as_array().and_then(|v| {
                v.iter()
                    .map(|r| {
                        Some((
                            RowVerdict {
                                row: r[0].as_u64()? as usize,
                                pass: r[1].as_bool()?,
                                fell_back: r[2].as_bool()?,
                                ulps: r[3].as_f64().unwrap_or(f64::INFINITY),
                            },
                            r[4].as_f64().unwrap_or(if r[4] == "nan" {
                                f64::NAN
                            } else {
                                f64::INFINITY
                            }),
                            r[5].as_bool()?,
                        ))
                    })
                    .collect::<Option<Vec<_>>>()
            });
            let key = j["key"].as_str().unwrap_or_default().to_string();
            report_of(&j["report"])
                .zip(rows)
                .map(|(report, rows)| {
                    let mut detail = Detail::default();
                    let mut verdicts = Vec::with_capacity(rows.len());
                    for (v, u, c) in rows {
                        verdicts.push(v);
                        detail.ulps_intended.push(u);
                        detail.correctly_rounded.push(c);
                    }
                    NativeReport::with_detail(report, verdicts, detail, key.clone())
                })
                .ok_or_else(|| crate::input_error(py, "report state: malformed"))
        })
    }
}

/// The float of precision `p` nearest `q`, as its exact value (`None` if it overflows).
fn as_float(q: &BigRational, p: Precision) -> Option<BigRational> {
    match p {
        Precision::F64 => exact_f64(round_f64(q)),
        Precision::F32 => exact_f32(round_f32(q)),
    }
}

fn q(x: &BigRational) -> Json {
    json!(x.to_string())
}

fn measures_state(m: &Measures) -> Json {
    json!({"abs": q(&m.abs), "rel": m.rel.as_ref().map(q), "ulps": m.ulps.as_ref().map(q),
           "cr": m.correctly_rounded})
}

fn coord_state(c: &FailedCoord) -> Json {
    json!({"index": c.index, "decimal": c.decimal, "hex": c.hex, "exact_seen": q(&c.exact_seen),
           "seen": measures_state(&c.seen), "exact_intended": c.exact_intended.as_ref().map(q),
           "intended": c.intended.as_ref().map(measures_state)})
}

fn state_of(r: &BatchReport) -> Json {
    json!({
        "file": r.file, "patch": r.patch, "tolerance": r.tolerance.text(),
        "precision": r.precision.map(Precision::name),
        "rows": r.checked, "passed": r.passed, "failed": r.failed, "fell_back": r.fell_back,
        "histogram": r.histogram.counts.to_vec(), "upper": r.histogram_upper_bounds,
        "hexact": r.histogram_exact,
        "worst": r.worst.as_ref().map(|w| json!({"ulps": w.ulps, "line": w.line,
            "coords": w.coords.iter().map(coord_state).collect::<Vec<_>>()})),
        "failures": r.failures.iter().map(|f| json!({"line": f.line, "reason": f.reason,
            "coords": f.coords.iter().map(coord_state).collect::<Vec<_>>()})).collect::<Vec<_>>(),
    })
}

fn rat(j: &Json) -> Option<BigRational> {
    parse_rational(j.as_str()?).ok()
}

fn opt_rat(j: &Json) -> Option<Option<BigRational>> {
    if j.is_null() {
        Some(None)
    } else {
        rat(j).map(Some)
    }
}

fn measures_of(j: &Json) -> Option<Measures> {
    Some(Measures {
        abs: rat(&j["abs"])?,
        rel: opt_rat(&j["rel"])?,
        ulps: opt_rat(&j["ulps"])?,
        correctly_rounded: j["cr"].as_bool(),
    })
}

fn coord_of(j: &Json) -> Option<FailedCoord> {
    Some(FailedCoord {
        index: j["index"].as_u64()? as usize,
        decimal: j["decimal"].as_str()?.to_string(),
        hex: j["hex"].as_str()?.to_string(),
        exact_seen: rat(&j["exact_seen"])?,
        seen: measures_of(&j["seen"])?,
        exact_intended: opt_rat(&j["exact_intended"])?,
        intended: if j["intended"].is_null() {
            None
        } else {
            Some(measures_of(&j["intended"])?)
        },
    })
}

fn coords_of(j: &Json) -> Option<Vec<FailedCoord>> {
    j.as_array()?.iter().map(coord_of).collect()
}

fn report_of(j: &Json) -> Option<BatchReport> {
    let counts: Vec<u64> = j["histogram"]
        .as_array()?
        .iter()
        .map(Json::as_u64)
        .collect::<Option<_>>()?;
    Some(BatchReport {
        file: j["file"].as_str()?.to_string(),
        patch: j["patch"].as_str()?.to_string(),
        tolerance: Tolerance::parse(j["tolerance"].as_str()?).ok()?,
        precision: match j["precision"].as_str() {
            None => None,
            Some(p) => Some(p.parse().ok()?),
        },
        checked: j["rows"].as_u64()?,
        passed: j["passed"].as_u64()?,
        failed: j["failed"].as_u64()?,
        fell_back: j["fell_back"].as_u64()?,
        histogram: UlpHistogram {
            counts: counts.try_into().ok()?,
        },
        histogram_upper_bounds: j["upper"].as_bool()?,
        histogram_exact: j["hexact"].as_u64()? as usize,
        worst: if j["worst"].is_null() {
            None
        } else {
            let w = &j["worst"];
            Some(WorstRow {
                ulps: w["ulps"].as_f64()?,
                line: w["line"].as_u64()? as usize,
                coords: coords_of(&w["coords"])?,
            })
        },
        max_ulps: if j["worst"].is_null() {
            None
        } else {
            Some(j["worst"]["ulps"].as_f64()?)
        },
        rows: None,
        baseline_regressions: Vec::new(),
        failures: j["failures"]
            .as_array()?
            .iter()
            .map(|f| {
                Some(FailedRow {
                    line: f["line"].as_u64()? as usize,
                    reason: f["reason"].as_str()?.to_string(),
                    coords: coords_of(&f["coords"])?,
                })
            })
            .collect::<Option<_>>()?,
    })
}
