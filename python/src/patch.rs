//! `NativePatch`: a patch of any kind (the library's), built from files, text or `bezier`-style
//! nodes, evaluated exactly and on tribez's own float path.

use std::path::PathBuf;

use num_rational::BigRational;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use rayon::prelude::*;

use tribez::capability::PointEvaluator;
use tribez::constructions::{ControlNet, binomial, check_barycentric};
use tribez::format::{format_rational, parse_rational};
use tribez::kernels::Float;
use tribez::limits::{MAX_CONTROL_POINTS, MAX_DEGREE, MAX_SIMPLEX_DIMENSION};
use tribez::{CoreError, Degree, Patch, PatchKind, SimplexDim};

use crate::{guard, input_error};

/// Parse a number in tribez's syntax; its exact value in lowest terms (`p/q` or `p`).
#[pyfunction]
pub fn parse_number(py: Python<'_>, text: &str) -> PyResult<String> {
    guard(py, || {
        parse_rational(text)
            .map(|q| format_rational(&q))
            .map_err(|e| input_error(py, e))
    })
}

/// A patch of any kind.
#[pyclass(module = "tribez._native", frozen)]
pub struct NativePatch {
    pub(crate) patch: Patch,
}

impl NativePatch {
    /// The control net (the homogeneous one's point part for rational patches).
    pub(crate) fn net(&self) -> &ControlNet<BigRational> {
        self.patch.control_net()
    }
}

fn parse_all(py: Python<'_>, rows: &[Vec<String>], what: &str) -> PyResult<Vec<Vec<BigRational>>> {
    rows.iter()
        .enumerate()
        .map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(|(j, t)| {
                    parse_rational(t).map_err(|e| input_error(py, format!("{what}[{i}][{j}]: {e}")))
                })
                .collect()
        })
        .collect()
}

/// The degree `n` with `C(n + m, m) = count`, if any.
fn degree_of(count: usize, m: usize) -> Option<usize> {
    (0..=MAX_DEGREE).find(|&n| binomial((n + m) as u64, m as u64) == count as u128)
}

#[pymethods]
impl NativePatch {
    /// Read a patch file (.toml or .json, by extension).
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        guard(py, || {
            let patch = py
                .detach(|| Patch::from_file(&path).map_err(|e| e.to_string()))
                .map_err(|e| input_error(py, e))?;
            Ok(NativePatch { patch })
        })
    }

    /// Parse a patch from TOML text (`file` names it in error messages).
    #[staticmethod]
    fn from_toml(py: Python<'_>, text: &str, file: &str) -> PyResult<Self> {
        guard(py, || {
            let patch = Patch::from_toml_named(text, file).map_err(|e| input_error(py, e))?;
            Ok(NativePatch { patch })
        })
    }

    /// Parse a patch from JSON text (`file` names it in error messages).
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str, file: &str) -> PyResult<Self> {
        guard(py, || {
            let patch = Patch::from_json_named(text, file).map_err(|e| input_error(py, e))?;
            Ok(NativePatch { patch })
        })
    }

    /// A Bézier simplex over the `simplex`-simplex from its control points in canonical order
    /// (`points[r]` = the coordinates of control point `r`, as number texts); rational with
    /// `weights` (one per control point).
    #[staticmethod]
    #[pyo3(signature = (simplex, degree, points, weights=None))]
    fn from_nodes(
        py: Python<'_>,
        simplex: usize,
        degree: Option<usize>,
        points: Vec<Vec<String>>,
        weights: Option<Vec<String>>,
    ) -> PyResult<Self> {
        guard(py, || {
            let err = |m: String| input_error(py, m);
            if simplex == 0 || simplex > MAX_SIMPLEX_DIMENSION {
                return Err(err(format!(
                    "simplex: {simplex} is not a simplex dimension from 1 to {MAX_SIMPLEX_DIMENSION} (1 for curves, 2 for triangles, 3 for tetrahedra)"
                )));
            }
            let count = points.len();
            if count == 0 {
                return Err(err("nodes: no control points (nodes has 0 columns)".into()));
            }
            if count > MAX_CONTROL_POINTS {
                return Err(err(format!(
                    "nodes: {count} control points, above the limit of {MAX_CONTROL_POINTS}"
                )));
            }
            let n = match degree {
                Some(n) if n > MAX_DEGREE => {
                    return Err(err(format!(
                        "degree: {n} is above the limit of {MAX_DEGREE}"
                    )));
                }
                Some(n) => {
                    let expected = binomial((n + simplex) as u64, simplex as u64);
                    if expected != count as u128 {
                        return Err(err(format!(
                            "nodes: {count} control points (columns), but degree {n} on the {simplex}-simplex has {expected}"
                        )));
                    }
                    n
                }
                None => degree_of(count, simplex).ok_or_else(|| {
                    let firsts: Vec<String> = (1..=5)
                        .map(|n| binomial((n + simplex) as u64, simplex as u64).to_string())
                        .collect();
                    err(format!(
                        "nodes: {count} control points (columns) is the number of no degree on the {simplex}-simplex (degrees 1, 2, 3, ... have {}, ...)",
                        firsts.join(", ")
                    ))
                })?,
            };
            let dim = points[0].len();
            if dim == 0 {
                return Err(err(
                    "nodes: a control point needs at least one coordinate (nodes has 0 rows)"
                        .into(),
                ));
            }
            if let Some((r, p)) = points.iter().enumerate().find(|(_, p)| p.len() != dim) {
                return Err(err(format!(
                    "nodes: control point {r} has {} coordinates, but control point 0 has {dim}",
                    p.len()
                )));
            }
            let coords: Vec<BigRational> = points
                .iter()
                .enumerate()
                .flat_map(|(r, p)| p.iter().enumerate().map(move |(i, t)| (r, i, t)))
                .map(|(r, i, t)| {
                    parse_rational(t).map_err(|e| err(format!("nodes[{i}, {r}]: {e}")))
                })
                .collect::<PyResult<_>>()?;
            let rows: Vec<Vec<BigRational>> = coords.chunks(dim).map(<[_]>::to_vec).collect();
            let (m, n) = (SimplexDim(simplex), Degree(n));
            // the sizes are checked above: these cannot fail
            let built = |r: Result<Patch, tribez::Error>| r.map_err(|e| err(e.to_string()));
            let patch = match weights {
                None => built(Patch::bezier(m, n, rows))?,
                Some(w) => {
                    if w.len() != count {
                        return Err(err(format!(
                            "weights: {} weights for {count} control points (one each)",
                            w.len()
                        )));
                    }
                    let w: Vec<BigRational> = w
                        .iter()
                        .enumerate()
                        .map(|(r, t)| {
                            parse_rational(t).map_err(|e| err(format!("weights[{r}]: {e}")))
                        })
                        .collect::<PyResult<_>>()?;
                    if w.iter().all(num_traits::Zero::is_zero) {
                        return Err(err(
                            "weights: every weight is zero: the rational patch is undefined everywhere".into(),
                        ));
                    }
                    built(Patch::rational(m, n, rows, w))?
                }
            };
            Ok(NativePatch { patch })
        })
    }

    /// The degree `n`.
    #[getter]
    fn degree(&self) -> usize {
        self.net().degree()
    }

    /// The dimension `d` of the control points (the number of coordinates of a value).
    #[getter]
    fn dimension(&self) -> usize {
        self.net().dim()
    }

    /// The simplex dimension `m` (1 curves, 2 triangles, 3 tetrahedra, ...); for an S-patch
    /// over an N-gon, N - 1.
    #[getter]
    fn simplex(&self) -> usize {
        self.net().m()
    }

    /// `"bezier"`, `"rational"`, `"functional"` or `"s-patch"` (the patch file's `kind`).
    #[getter]
    fn kind(&self) -> &'static str {
        match self.patch.kind() {
            PatchKind::Bezier => "bezier",
            PatchKind::Rational => "rational",
            PatchKind::Functional => "functional",
            PatchKind::SPatch => "s-patch",
        }
    }

    /// The name from the file, if any.
    #[getter]
    fn name(&self) -> Option<String> {
        self.patch.name().map(str::to_string)
    }

    /// Number of barycentric coordinates of a point (m + 1), or 2 (Cartesian) for an S-patch.
    #[getter]
    fn point_width(&self) -> usize {
        match self.patch.polygon() {
            Some(_) => 2,
            None => self.net().m() + 1,
        }
    }

    /// The control points in canonical order, as exact texts.
    fn control_points(&self, py: Python<'_>) -> PyResult<Vec<Vec<String>>> {
        guard(py, || {
            Ok(self
                .net()
                .points()
                .map(|p| p.iter().map(format_rational).collect())
                .collect())
        })
    }

    /// The weights of a rational patch, as exact texts.
    fn weights(&self) -> Option<Vec<String>> {
        self.patch
            .weights()
            .map(|w| w.iter().map(format_rational).collect())
    }

    /// The patch file (TOML).
    fn to_toml(&self, py: Python<'_>) -> PyResult<String> {
        guard(py, || Ok(self.patch.to_toml()))
    }

    /// The patch file (JSON).
    fn to_json(&self, py: Python<'_>) -> PyResult<String> {
        guard(py, || Ok(self.patch.to_json()))
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.patch == other.patch
    }

    /// Exact values at points (number texts), each a list of exact texts.
    fn evaluate(
        &self,
        py: Python<'_>,
        points: Vec<Vec<String>>,
        cartesian: bool,
    ) -> PyResult<Vec<Vec<String>>> {
        guard(py, || {
            let pts = parse_all(py, &points, "points")?;
            let patch = &self.patch;
            let results: Vec<Result<Vec<BigRational>, String>> = py.detach(|| {
                let evaluator = patch.exact().exact_evaluator();
                pts.par_iter()
                    .enumerate()
                    .map(|(i, x)| {
                        evaluate_one(patch, evaluator.as_ref(), x, cartesian)
                            .map_err(|e| format!("points[{i}]: {e}"))
                    })
                    .collect()
            });
            results
                .into_iter()
                .map(|r| {
                    r.map(|v| v.iter().map(format_rational).collect())
                        .map_err(|e| input_error(py, e))
                })
                .collect()
        })
    }

    /// tribez's own float path at float points (`points`: the bytes of row-major f64, `width`
    /// numbers a row): de Casteljau in `precision` ("f64" or "f32") on the control net rounded
    /// to it, the points rounded to it; rational patches by homogeneous de Casteljau and one
    /// division, S-patches (Cartesian points) by float Wachspress coordinates then de Casteljau.
    /// Returns the bytes of row-major values in that precision.
    fn evaluate_float<'py>(
        &self,
        py: Python<'py>,
        points: &[u8],
        width: usize,
        precision: &str,
    ) -> PyResult<Bound<'py, PyBytes>> {
        guard(py, || {
            let expected = self.point_width();
            if width != expected {
                return Err(input_error(
                    py,
                    format!(
                        "points: rows of {width} coordinates, but this {} needs {expected}",
                        self.described()
                    ),
                ));
            }
            let xs = f64s(points);
            let patch = &self.patch;
            let out: Vec<u8> = match precision {
                "f64" => py.detach(|| float_rows::<f64>(patch, &xs, width, |x| x)),
                "f32" => py.detach(|| float_rows::<f32>(patch, &xs, width, |x| x as f32)),
                other => {
                    return Err(input_error(
                        py,
                        format!("precision: unknown precision `{other}` (expected f64 or f32)"),
                    ));
                }
            };
            Ok(PyBytes::new(py, &out))
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "<tribez.Patch {} degree={} simplex={} dimension={}{}>",
            self.kind(),
            self.degree(),
            self.simplex(),
            self.dimension(),
            self.name()
                .map(|n| format!(" name={n:?}"))
                .unwrap_or_default()
        )
    }
}

impl NativePatch {
    fn described(&self) -> &'static str {
        self.patch
            .described()
            .trim_start_matches("a ")
            .trim_start_matches("an ")
    }
}

/// Native-endian f64s from bytes (the Python layer passes `ndarray.tobytes()` of float64).
pub(crate) fn f64s(bytes: &[u8]) -> Vec<f64> {
    bytes
        .chunks_exact(8)
        .map(|c| f64::from_ne_bytes(c.try_into().expect("8 bytes")))
        .collect()
}

fn evaluate_one(
    patch: &Patch,
    evaluator: &dyn PointEvaluator,
    x: &[BigRational],
    cartesian: bool,
) -> Result<Vec<BigRational>, CoreError> {
    if patch.polygon().is_some() {
        if !cartesian {
            return Err(CoreError::CartesianPoints {
                kind: "an S-patch",
                flag: "cartesian=True",
            });
        }
        return evaluator.evaluate(x);
    }
    let lambda = if cartesian {
        patch.exact().cartesian_input(x)?
    } else {
        check_barycentric(x, patch.simplex_dim(), "the point")?;
        x.to_vec()
    };
    evaluator.evaluate(&lambda)
}

fn float_rows<F: Float + std::ops::Div<Output = F> + ToBytes>(
    patch: &Patch,
    xs: &[f64],
    width: usize,
    round: impl Fn(f64) -> F + Sync,
) -> Vec<u8> {
    let rows: Vec<&[f64]> = xs.chunks_exact(width).collect();
    let evaluator = patch.float_evaluator::<F>();
    let values: Vec<Vec<F>> = rows
        .par_iter()
        .map(|r| {
            let input: Vec<F> = r.iter().map(|&x| round(x)).collect();
            evaluator
                .evaluate(&input)
                .expect("rows of the patch's point width (checked by the caller)")
        })
        .collect();
    let mut out = Vec::with_capacity(values.len() * values.first().map_or(0, Vec::len) * 8);
    for v in values {
        for x in v {
            x.extend_bytes(&mut out);
        }
    }
    out
}

/// Native-endian bytes of a float, for numpy's `frombuffer`.
pub(crate) trait ToBytes {
    fn extend_bytes(self, out: &mut Vec<u8>);
}

impl ToBytes for f64 {
    fn extend_bytes(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_ne_bytes());
    }
}

impl ToBytes for f32 {
    fn extend_bytes(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_ne_bytes());
    }
}
