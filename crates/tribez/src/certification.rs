//! A certification run ([`certify`]): run the float program of a patch of any kind (for
//! polynomial patches de Casteljau and the direct Bernstein form; homogeneous de Casteljau and
//! one division for rational patches; float Wachspress coordinates and de Casteljau for
//! S-patches) in f64 and f32 at many points, and judge it against the exact values and its proven
//! error bound ([`crate::certify::bound`], docs/theory.md §14.1).
//!
//! One code path for every kind: the kind's [`FloatEval`] and [`crate::ErrorBound`] give the
//! float program, the per-point case and the bound's explanation. The report
//! ([`CertifyReport`]) renders as the text of `tribez certify` ([`CertifyReport::text`], the
//! `Display`) and as its JSON (the [`serde::Serialize`] impl).

use std::fmt;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use serde::Serialize;

use crate::api_error::{Error, Lacks, Refusal};
use crate::capability::{FloatCase, FloatEval, FloatProgram, InputSpace};
use crate::certify::bound::roundings;
use crate::certify::measures::{Measures, sci};
use crate::certify::sample::{random_points, random_polygon_points};
use crate::domain::format_tuple;
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::io::{InputError, Problem, RowsProblem};
use crate::number::{exact_f64, round_f32, round_f64};
use crate::patch_type::Patch;
use crate::report::WorstError;

/// Where a certification run evaluates.
#[derive(Clone, Debug, PartialEq)]
pub enum CertifyPoints {
    /// These points, in the kind's coordinates ([`InputSpace`]: `m + 1` barycentric
    /// coordinates, or `(x, y)` in an S-patch's polygon); each is rounded to the precision as a
    /// float program would round it. `source` names them in errors (a file name).
    Given {
        /// The points (exact).
        points: Vec<Vec<BigRational>>,
        /// What errors call them (`"points.csv"`).
        source: String,
    },
    /// `count` reproducible random points (SplitMix64 from `seed`): inside, near the edges and
    /// outside the simplex; for an S-patch inside the polygon and near its edges and vertices (a
    /// random point rounded onto the wrong side of an edge is dropped).
    Random {
        /// How many (at least one).
        count: usize,
        /// The seed.
        seed: u64,
    },
}

/// What a certification run does ([`certify`]).
#[derive(Clone, Debug, PartialEq)]
pub struct CertifyOptions {
    /// The points.
    pub points: CertifyPoints,
    /// One precision, or `None` for both (f64, then f32).
    pub precision: Option<Precision>,
    /// One algorithm, or `None` for every algorithm of the kind's float program (for
    /// polynomial patches de Casteljau and Bernstein; the other kinds have de Casteljau only).
    pub algorithm: Option<Algorithm>,
    /// How the report names the patch (its file name, for the command line).
    pub label: String,
}

/// One algorithm in one precision, over all points.
#[derive(Clone, Debug, PartialEq)]
pub struct CertifyRow {
    /// The algorithm.
    pub algorithm: Algorithm,
    /// The precision.
    pub precision: Precision,
    /// Coordinates judged (points × coordinates of the result).
    pub coordinates: usize,
    /// The largest error in ULPs against the exact value at the inputs as seen.
    pub max_ulps: f64,
    /// The point where it occurred.
    pub worst_point: Option<Vec<BigRational>>,
    /// Coordinates that were correctly rounded.
    pub correctly_rounded: usize,
    /// The largest condition number `Σ|c_i| B_i(|λ|)`.
    pub max_condition: f64,
    /// The largest condition number relative to the exact value.
    pub max_relative_condition: f64,
    /// The largest error ÷ bound.
    pub max_bound_ratio: f64,
    /// Points where the error exceeded the proven bound (one line each).
    pub violations: Vec<String>,
    /// Points outside the bound's hypotheses (overflow, underflow, an uncertain sign): not
    /// judged.
    pub outside_hypothesis: usize,
    /// The roundings `K` of the bound `γ_K`.
    pub gamma_k: usize,
    /// The bound column's text when it is not `γ_K` (rational patches, S-patches).
    pub label: Option<String>,
    /// Further lines printed under the table.
    pub notes: Vec<String>,
    /// Each point's result, in the order of [`CertifyReport::inputs`] (what an error map draws).
    pub per_point: Vec<PointResult>,
}

/// One point's result in a [`CertifyRow`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointResult {
    /// The largest error in ULPs over the result's coordinates against the exact value at the
    /// inputs as seen (infinite for a non-finite result); [`CertifyRow::max_ulps`] is the
    /// largest of these.
    pub ulps: f64,
    /// The error exceeded the proven bound there (a violation).
    pub exceeded: bool,
    /// Outside the bound's hypotheses (overflow, underflow, an uncertain sign): not judged.
    pub outside_hypothesis: bool,
}

/// `--random N` points: how many, the seed, and the command that reproduces the run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RandomPoints {
    /// How many points were asked for.
    pub count: usize,
    /// The seed.
    pub seed: u64,
    /// The `tribez certify` command that reproduces the run.
    pub reproduce: String,
}

/// The report of a certification run.
#[derive(Clone, Debug, PartialEq)]
pub struct CertifyReport {
    /// The patch ([`CertifyOptions::label`]).
    pub patch: String,
    /// How many points.
    pub points: usize,
    /// The points, in the kind's coordinates (barycentric; `(x, y)` for an S-patch), exact as
    /// given or generated (each row's [`CertifyRow::per_point`] follows this order).
    pub inputs: Vec<Vec<BigRational>>,
    /// The random points' parameters, for a random run.
    pub random: Option<RandomPoints>,
    /// One row per precision and algorithm.
    pub rows: Vec<CertifyRow>,
    /// Worst errors that got worse than a recorded baseline (filled by whoever compares
    /// against one, as `tribez certify --baseline` does).
    pub baseline_regressions: Vec<String>,
    /// The bound's explanation line (the patch kind's).
    pub bound_note: String,
}

impl CertifyRow {
    /// An empty row: `gamma_k` roundings, the bound column's `label` if not `γ_K`.
    fn new(
        algorithm: Algorithm,
        precision: Precision,
        gamma_k: usize,
        label: Option<String>,
    ) -> Self {
        CertifyRow {
            algorithm,
            precision,
            coordinates: 0,
            max_ulps: 0.0,
            worst_point: None,
            correctly_rounded: 0,
            max_condition: 0.0,
            max_relative_condition: 0.0,
            max_bound_ratio: 0.0,
            violations: Vec::new(),
            outside_hypothesis: 0,
            gamma_k,
            label,
            notes: Vec::new(),
            per_point: Vec::new(),
        }
    }

    /// Every coordinate was within the proven bound.
    pub fn within_bound(&self) -> bool {
        self.violations.is_empty()
    }

    /// Fold the per-point results (in the order of `points`) into the row; returns the largest
    /// error of the float coordinates [`Acc::lambda_ulps`].
    fn fold(&mut self, accs: Vec<Acc>, points: &[Vec<BigRational>]) -> f64 {
        let mut lambda_ulps = 0.0f64;
        self.per_point.reserve(accs.len());
        for (i, c) in accs.into_iter().enumerate() {
            self.per_point.push(PointResult {
                ulps: c.ulps,
                exceeded: c.violation.is_some(),
                outside_hypothesis: c.outside,
            });
            if c.ulps > self.max_ulps {
                self.max_ulps = c.ulps;
                self.worst_point = Some(points[i].clone());
            }
            self.correctly_rounded += c.cr;
            self.coordinates += c.coords;
            self.max_condition = self.max_condition.max(c.cond);
            self.max_relative_condition = self.max_relative_condition.max(c.rel_cond);
            self.max_bound_ratio = self.max_bound_ratio.max(c.ratio);
            self.outside_hypothesis += usize::from(c.outside);
            self.violations.extend(c.violation);
            lambda_ulps = lambda_ulps.max(c.lambda_ulps);
        }
        lambda_ulps
    }
}

/// One point's results, folded into a [`CertifyRow`] by [`CertifyRow::fold`].
#[derive(Default)]
struct Acc {
    /// The largest error in ULPs over the coordinates, and how many were correctly rounded.
    ulps: f64,
    cr: usize,
    /// Coordinates judged.
    coords: usize,
    /// The largest condition number and relative condition number.
    cond: f64,
    rel_cond: f64,
    /// The largest error ÷ bound, and a bound violation if any.
    ratio: f64,
    violation: Option<String>,
    /// Outside the bound's hypotheses (not judged against it).
    outside: bool,
    /// S-patches: the largest error of the float coordinates λ̂, in ULPs.
    lambda_ulps: f64,
}

impl Acc {
    /// Measure `y` (floats of `precision`, as f64) against `exact` (ULPs, correct rounding);
    /// `None` measures of a non-finite value count as an infinite error.
    fn measure(&mut self, precision: Precision, y: &[f64], exact: &[BigRational]) {
        for (v, q) in y.iter().zip(exact) {
            let Some(yq) = exact_f64(*v) else {
                continue;
            };
            let meas = Measures::new(&yq, q, Some(precision));
            self.ulps = self
                .ulps
                .max(meas.ulps.as_ref().map_or(f64::INFINITY, round_f64));
            if meas.correctly_rounded == Some(true) {
                self.cr += 1;
            }
        }
    }

    /// Judge `|y − exact| ≤ bound` per coordinate (`what` names the quantity in a violation).
    fn judge(
        &mut self,
        y: &[f64],
        exact: &[BigRational],
        bound: &[BigRational],
        at: &[BigRational],
        what: &str,
    ) {
        for (c, ((v, q), b)) in y.iter().zip(exact).zip(bound).enumerate() {
            let Some(yq) = exact_f64(*v) else {
                continue;
            };
            let err = (yq - q).abs();
            if !b.is_zero() {
                self.ratio = self.ratio.max(round_f64(&(&err / b)));
            }
            if err > *b {
                self.violation = Some(format!(
                    "at {} coordinate {c}: {what}error {} exceeds the bound {}",
                    format_tuple(at),
                    sci(&err),
                    sci(b)
                ));
            }
        }
    }

    /// One point's certified case ([`crate::ErrorBound::certify`]), folded; `coordinate` names
    /// one intermediate coordinate in a violation.
    fn of_case(precision: Precision, case: FloatCase, coordinate: &str) -> Acc {
        let mut acc = Acc {
            coords: case.y.len(),
            outside: case.outside,
            ..Acc::default()
        };
        if let Some(q) = &case.exact {
            acc.measure(precision, &case.y, q);
        }
        if let Some(k) = &case.condition {
            for (c, kc) in k.iter().enumerate() {
                acc.cond = acc.cond.max(round_f64(kc));
                if let Some(q) = case.exact.as_ref().filter(|q| !q[c].is_zero()) {
                    acc.rel_cond = acc.rel_cond.max(round_f64(&(kc / q[c].abs())));
                }
            }
        }
        if let Some(cc) = &case.coordinates {
            let mut lacc = Acc::default();
            lacc.measure(precision, &cc.values, &cc.exact);
            acc.lambda_ulps = lacc.ulps;
        }
        if !case.outside {
            if let (Some(q), Some(b)) = (&case.exact, &case.bound) {
                acc.judge(&case.y, q, b, &case.input, "");
            }
            if let Some((cc, b)) = case
                .coordinates
                .as_ref()
                .and_then(|cc| Some((cc, cc.bound.as_ref()?)))
            {
                acc.judge(&cc.values, &cc.exact, b, &case.input, coordinate);
            }
        }
        if let Some(f) = case.failure {
            acc.violation = Some(f);
        }
        acc
    }
}

/// Points judged between two calls of a run's stop test ([`certify_until`]).
const SLAB: usize = 64;

/// One algorithm of the float program `program`, over all points, in slabs of [`SLAB`] points
/// with the stop test between them (`Ok(Err(s))`: stopped).
fn certify_row<S>(
    program: &dyn FloatProgram,
    algorithm: Algorithm,
    points: &[Vec<BigRational>],
    (m, n): (usize, usize),
    stop: &dyn Fn() -> Option<S>,
) -> Result<Result<CertifyRow, S>, Error> {
    let precision = program.precision();
    let bound = program
        .error_bound()
        .ok_or_else(|| CoreError::NoProvenBound {
            precision: precision.name(),
        })?;
    let text = bound.text(algorithm);
    let coordinate = text.coordinates.as_ref().map_or("", |c| c.one);
    let mut accs: Vec<Acc> = Vec::with_capacity(points.len());
    for slab in points.chunks(SLAB) {
        if let Some(s) = stop() {
            return Ok(Err(s));
        }
        accs.par_extend(slab.par_iter().map(|point| {
            // rounded as the float code rounds (an overflow is an infinite input)
            let input: Vec<f64> = point
                .iter()
                .map(|x| match precision {
                    Precision::F64 => round_f64(x),
                    Precision::F32 => f64::from(round_f32(x)),
                })
                .collect();
            Acc::of_case(precision, bound.certify(algorithm, &input), coordinate)
        }));
    }
    let mut row = CertifyRow::new(algorithm, precision, roundings(algorithm, m, n), text.label);
    let lambda_ulps = row.fold(accs, points);
    if let Some(c) = &text.coordinates {
        row.notes.push(format!(
            "{}: max error {} ulp (within the relative bound θ wherever judged)",
            c.all,
            g(lambda_ulps)
        ));
    }
    if let Some(outside) = text.outside.filter(|_| row.outside_hypothesis > 0) {
        row.notes.push(format!(
            "{} points not judged: {outside}",
            row.outside_hypothesis
        ));
    }
    Ok(Ok(row))
}

/// The algorithms asked for, among those of the kind's float program.
fn algorithms(
    asked: Option<Algorithm>,
    patch: &Patch,
    float: &dyn FloatEval,
) -> Result<Vec<Algorithm>, Error> {
    let offered = float.float_algorithms();
    match asked {
        None => Ok(offered.to_vec()),
        Some(a) if offered.contains(&a) => Ok(vec![a]),
        // a kind with one algorithm: its de Casteljau (homogeneous, or after Wachspress)
        Some(Algorithm::Casteljau) if offered.len() == 1 => Ok(offered.to_vec()),
        Some(a) => Err(Error::Refusal(Refusal::Unsupported {
            kind: patch.kind().plural(),
            what: Lacks::CertifyAlgorithm {
                algorithm: a.name(),
            },
        })),
    }
}

/// The points of a run, in the kind's coordinates ([`CertifyPoints`]).
fn points_of(patch: &Patch, options: &CertifyOptions) -> Result<Vec<Vec<BigRational>>, Error> {
    let input = patch.shape().input;
    let exact = patch.exact().exact_evaluator();
    // Only finite floats come here: `random_points` makes coordinates in [-1/2, 3/2], and
    // polygon points are checked finite below before they are converted.
    let rational = |x: f64| BigRational::from_float(x).expect("finite");
    Ok(match &options.points {
        CertifyPoints::Given { points, source } => {
            for (i, p) in points.iter().enumerate() {
                if p.len() != input.len() {
                    return Err(InputError::file(
                        source,
                        RowsProblem::PointLength {
                            index: i + 1,
                            found: p.len(),
                            expected: input.len(),
                        },
                    )
                    .into());
                }
                if let Err(error) = exact.coordinates(p) {
                    let item = Problem::Item {
                        what: "point",
                        index: i + 1,
                        error,
                    };
                    return Err(InputError::file(source, item).into());
                }
            }
            points.clone()
        }
        &CertifyPoints::Random { count, seed } => {
            if count == 0 {
                return Err(Error::Refusal(Refusal::Size {
                    what: "random points",
                    expected: 1,
                    found: 0,
                }));
            }
            match &input {
                InputSpace::Barycentric { m } => random_points(*m, count, seed)
                    .into_iter()
                    .map(|p| p.into_iter().map(rational).collect())
                    .collect(),
                InputSpace::Polygon { vertices } => {
                    let verts: Vec<[f64; 2]> = vertices
                        .iter()
                        .map(|v| [round_f64(&v[0]), round_f64(&v[1])])
                        .collect();
                    let made = random_polygon_points(&verts, count, seed);
                    // a vertex beyond f64, or sums of huge coordinates (the centroid, an edge's
                    // difference), overflow: a bad input, not a point to drop
                    if made.iter().flatten().any(|x| !x.is_finite()) {
                        let error = InputError::file(&options.label, Problem::RandomPointsOverflow)
                            .with_key("polygon");
                        return Err(error.into());
                    }
                    made.into_iter()
                        .map(|p| p.into_iter().map(rational).collect::<Vec<_>>())
                        .filter(|p| exact.coordinates(p).is_ok())
                        .collect()
                }
            }
        }
    })
}

/// Certify the float program of `patch`: run it in each precision and algorithm asked for at
/// every point, and judge each result against the exact value at the inputs as seen and
/// against the proven bound (the report of `tribez certify`).
///
/// ```
/// use tribez::{CertifyOptions, CertifyPoints, Degree, Patch, SimplexDim, certify, parse_rational};
/// let q = |s: &str| parse_rational(s).unwrap();
/// let pts = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]];
/// let net = pts.iter().map(|p| p.iter().map(|x| q(&x.to_string())).collect()).collect();
/// let patch = Patch::bezier(SimplexDim(2), Degree(2), net).unwrap();
/// let options = CertifyOptions {
///     points: CertifyPoints::Random { count: 50, seed: 7 },
///     precision: None,
///     algorithm: None,
///     label: "finn".into(),
/// };
/// let report = certify(&patch, &options).unwrap();
/// // f64 and f32, de Casteljau and Bernstein, 50 points of 3 coordinates each
/// assert_eq!(report.rows.len(), 4);
/// assert!(report.rows.iter().all(|r| r.coordinates == 150 && r.within_bound()));
/// assert!(report.success());
/// ```
pub fn certify(patch: &Patch, options: &CertifyOptions) -> Result<CertifyReport, Error> {
    let Ok(report) = certify_until::<std::convert::Infallible>(patch, options, &|| None)?;
    Ok(report)
}

/// [`certify()`], asking `stop` between slabs of points (a few dozen exact evaluations): when it
/// answers `Some(s)` the run ends with `Ok(Err(s))` (the Python package stops on Ctrl-C this
/// way). `stop` runs on the calling thread.
pub fn certify_until<S>(
    patch: &Patch,
    options: &CertifyOptions,
    stop: &dyn Fn() -> Option<S>,
) -> Result<Result<CertifyReport, S>, Error> {
    let precisions = match options.precision {
        None => vec![Precision::F64, Precision::F32],
        Some(p) => vec![p],
    };
    let float = patch.float().ok_or(Error::Refusal(Refusal::Unsupported {
        kind: patch.kind().plural(),
        what: Lacks::FloatProgramToCertify,
    }))?;
    let algorithms = algorithms(options.algorithm, patch, float)?;
    let points = points_of(patch, options)?;
    let shape = patch.shape();
    let mut rows = Vec::new();
    let mut note = "";
    for &p in &precisions {
        let program = float.float_program(p).map_err(|e| CoreError::InPrecision {
            precision: p.name(),
            error: Box::new(e),
        })?;
        for &a in &algorithms {
            if let Some(b) = program.error_bound() {
                note = b.text(a).note;
            }
            match certify_row(
                program.as_ref(),
                a,
                &points,
                (shape.simplex_dim, shape.degree),
                stop,
            )? {
                Ok(row) => rows.push(row),
                Err(s) => return Ok(Err(s)),
            }
        }
    }
    let random = match options.points {
        CertifyPoints::Random { count, seed } => Some(RandomPoints {
            count,
            seed,
            reproduce: format!(
                "tribez certify {} --random {count} --seed {seed} --precision {} --algorithm {}",
                options.label,
                options.precision.map_or("all", |p| p.name()),
                options.algorithm.map_or("all", Algorithm::name)
            ),
        }),
        CertifyPoints::Given { .. } => None,
    };
    Ok(Ok(CertifyReport {
        patch: options.label.clone(),
        points: points.len(),
        inputs: points,
        random,
        rows,
        baseline_regressions: Vec::new(),
        bound_note: note.to_string(),
    }))
}

/// A float for people: up to 4 decimals between 10^-3 and 10^6, else scientific.
fn g(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if (1e-3..1e6).contains(&x.abs()) {
        format!("{x:.4}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{x:.3e}")
    }
}

impl CertifyReport {
    /// Every result within its proven bound, and no baseline regressed.
    pub fn success(&self) -> bool {
        self.rows.iter().all(CertifyRow::within_bound) && self.baseline_regressions.is_empty()
    }

    /// The worst error per algorithm and precision (operation `eval`), at its point: what a
    /// baseline records.
    pub fn worst_errors(&self) -> Vec<WorstError> {
        self.rows
            .iter()
            .map(|r| WorstError {
                op: "eval".into(),
                algorithm: r.algorithm.name().into(),
                precision: r.precision.name().into(),
                ulps: r.max_ulps,
                at: r
                    .worst_point
                    .as_ref()
                    .map_or(String::new(), |p| format_tuple(p)),
            })
            .collect()
    }

    /// The report for people (what `tribez certify` prints).
    pub fn text(&self) -> String {
        let mut out = format!("{}: {} points\n", self.patch, self.points);
        if let Some(r) = &self.random {
            out += &format!(
                "random points: {}, seed {}; reproduce with:\n  {}\n",
                r.count, r.seed, r.reproduce
            );
        }
        out += &format!(
            "\n{:<10} {:<5} {:>9} {:>10} {:>9} {:>11} {:>11} {:>8} {:>9} {:>8}\n",
            "algorithm",
            "prec",
            "coords",
            "max ulp",
            "cr share",
            "max cond",
            "max relcond",
            "bound",
            "err/bound",
            "verdict"
        );
        for r in &self.rows {
            out += &format!(
                "{:<10} {:<5} {:>9} {:>10} {:>8.2}% {:>11} {:>11} {:>8} {:>9} {:>8}\n",
                r.algorithm.name(),
                r.precision.name(),
                r.coordinates,
                g(r.max_ulps),
                100.0 * r.correctly_rounded as f64 / r.coordinates.max(1) as f64,
                g(r.max_condition),
                g(r.max_relative_condition),
                r.label
                    .clone()
                    .unwrap_or_else(|| format!("γ_{}", r.gamma_k)),
                g(r.max_bound_ratio),
                if r.within_bound() {
                    "within"
                } else {
                    "EXCEEDED"
                }
            );
        }
        out += &format!("\n{}\n", self.bound_note);
        for r in &self.rows {
            let (a, p) = (r.algorithm.name(), r.precision.name());
            for line in &r.notes {
                out += &format!("{a} {p}: {line}\n");
            }
            if r.outside_hypothesis > 0 && r.label.is_none() {
                // (rational patches and S-patches explain theirs in `notes`)
                out += &format!(
                    "{a} {p}: {} points outside the bound's hypothesis (overflow or near underflow), not judged\n",
                    r.outside_hypothesis
                );
            }
            for v in r.violations.iter().take(20) {
                out += &format!("BOUND EXCEEDED: {a} {p}: {v}\n");
            }
        }
        for reg in &self.baseline_regressions {
            out += &format!("baseline regression: {reg}\n");
        }
        out
    }
}

impl fmt::Display for CertifyReport {
    /// [`CertifyReport::text`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text())
    }
}

/// The report as JSON (the layout of `tribez certify --format json`).
#[derive(Serialize)]
struct ReportJson<'a> {
    patch: &'a str,
    points: usize,
    random: Option<&'a RandomPoints>,
    results: Vec<RowJson<'a>>,
    baseline_regressions: &'a [String],
    bound_note: &'a str,
}

#[derive(Serialize)]
struct RowJson<'a> {
    algorithm: &'static str,
    precision: &'static str,
    coordinates: usize,
    max_ulps: f64,
    worst_point: Option<Vec<String>>,
    correctly_rounded: usize,
    max_condition: f64,
    max_relative_condition: f64,
    bound: String,
    max_error_over_bound: f64,
    within_bound: bool,
    notes: &'a [String],
    violations: &'a [String],
    outside_hypothesis: usize,
}

impl Serialize for CertifyReport {
    /// The layout of `tribez certify --format json`: the patch, the number of points, the random
    /// points' parameters, one result per algorithm and precision (exact points as strings
    /// `p/q`; the bound `gamma_K` or the kind's label), baseline regressions, the bound's note.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        ReportJson {
            patch: &self.patch,
            points: self.points,
            random: self.random.as_ref(),
            results: self
                .rows
                .iter()
                .map(|r| RowJson {
                    algorithm: r.algorithm.name(),
                    precision: r.precision.name(),
                    coordinates: r.coordinates,
                    max_ulps: r.max_ulps,
                    worst_point: r
                        .worst_point
                        .as_ref()
                        .map(|p| p.iter().map(ToString::to_string).collect()),
                    correctly_rounded: r.correctly_rounded,
                    max_condition: r.max_condition,
                    max_relative_condition: r.max_relative_condition,
                    bound: r
                        .label
                        .clone()
                        .unwrap_or_else(|| format!("gamma_{}", r.gamma_k)),
                    max_error_over_bound: r.max_bound_ratio,
                    within_bound: r.within_bound(),
                    notes: &r.notes,
                    violations: &r.violations,
                    outside_hypothesis: r.outside_hypothesis,
                })
                .collect(),
            baseline_regressions: &self.baseline_regressions,
            bound_note: &self.bound_note,
        }
        .serialize(s)
    }
}
