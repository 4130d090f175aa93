//! `tribez certify`: run the float program of a patch of any kind (for polynomial patches de
//! Casteljau and the direct Bernstein form; homogeneous de Casteljau and one division for
//! rational patches; float Wachspress coordinates and de Casteljau for S-patches) in f64 and f32
//! and judge it against the exact values and its proven error bound
//! ([`tribez::hazmat::certify::bound`]).
//!
//! One code path for every kind: the kind's [`tribez::FloatEval`] and [`tribez::ErrorBound`]
//! give the float program, the per-point case and the bound's explanation.

use std::path::PathBuf;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use serde_json::{Value as Json, json};

use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::{Exporter, JunitCase, Render, junit_xml};
use tribez::capability::{FloatCase, FloatProgram, InputSpace};
use tribez::hazmat::certify::bound::roundings;
use tribez::hazmat::certify::measures::{Measures, sci};
use tribez::hazmat::certify::sample::{random_points, random_polygon_points};
use tribez::hazmat::exact::Algorithm;
use tribez::hazmat::float::Precision;
use tribez::hazmat::io::patch_file::read_any_patch;
use tribez::hazmat::io::points::read_points;
use tribez::hazmat::number::{round_f32, round_f64};
use tribez::{FloatEval, Patch};

/// Arguments of `tribez certify`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file.
    pub patch: PathBuf,
    /// Barycentric points (CSV or JSON, exact numbers; Cartesian x,y for an S-patch); they are
    /// rounded to the precision.
    #[arg(long, value_name = "FILE", conflicts_with = "random")]
    pub points: Option<PathBuf>,
    /// Certify at N random points (inside, near the edges and outside the triangle; for an
    /// S-patch inside the polygon, near its edges and vertices).
    #[arg(long, value_name = "N", value_parser = crate::cli::random_count, allow_negative_numbers = true)]
    pub random: Option<usize>,
    /// Seed of --random (printed, with the command that reproduces the run).
    #[arg(long, value_name = "S", default_value_t = 1, value_parser = crate::cli::seed, allow_negative_numbers = true)]
    pub seed: u64,
    /// Precision: f64, f32 or all.
    #[arg(long, value_name = "f64|f32|all", default_value = "all")]
    pub precision: String,
    /// Algorithm: casteljau, bernstein or all.
    #[arg(long, value_name = "casteljau|bernstein|all", default_value = "all")]
    pub algorithm: String,
    /// Write the worst error per algorithm and precision to FILE.
    #[arg(long, value_name = "FILE")]
    pub record_baseline: Option<PathBuf>,
    /// Fail when a worst error is larger than recorded in FILE.
    #[arg(long, value_name = "FILE")]
    pub baseline: Option<PathBuf>,
    /// Also write a JUnit XML report (one test case per algorithm and precision).
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// One algorithm in one precision, over all points.
pub struct Row {
    pub(super) algorithm: Algorithm,
    pub(super) precision: Precision,
    pub(super) cases: usize,
    pub(super) max_ulps: f64,
    pub(super) worst_point: Option<Vec<BigRational>>,
    pub(super) correctly_rounded: usize,
    pub(super) max_condition: f64,
    pub(super) max_relative_condition: f64,
    pub(super) max_bound_ratio: f64,
    pub(super) violations: Vec<String>,
    pub(super) outside_hypothesis: usize,
    pub(super) gamma_k: usize,
    /// The bound column's text when it is not `γ_K` (rational patches, S-patches).
    pub(super) label: Option<String>,
    /// Further lines printed under the table.
    pub(super) notes: Vec<String>,
}

impl Row {
    /// An empty row: `gamma_k` roundings, the bound column's `label` if not `γ_K`.
    pub(super) fn new(
        algorithm: Algorithm,
        precision: Precision,
        gamma_k: usize,
        label: Option<String>,
    ) -> Self {
        Row {
            algorithm,
            precision,
            cases: 0,
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
        }
    }

    /// Fold the per-point results (in the order of `points`) into the row; returns the largest
    /// error of the float coordinates [`Acc::lambda_ulps`].
    pub(super) fn fold(&mut self, accs: Vec<Acc>, points: &[Vec<BigRational>]) -> f64 {
        let mut lambda_ulps = 0.0f64;
        for (i, c) in accs.into_iter().enumerate() {
            if c.ulps > self.max_ulps {
                self.max_ulps = c.ulps;
                self.worst_point = Some(points[i].clone());
            }
            self.correctly_rounded += c.cr;
            self.cases += c.coords;
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

/// One point's results, folded into a [`Row`] by [`Row::fold`].
#[derive(Default)]
pub(super) struct Acc {
    /// The largest error in ULPs over the coordinates, and how many were correctly rounded.
    pub(super) ulps: f64,
    pub(super) cr: usize,
    /// Coordinates judged.
    pub(super) coords: usize,
    /// The largest condition number and relative condition number.
    pub(super) cond: f64,
    pub(super) rel_cond: f64,
    /// The largest error ÷ bound, and a bound violation if any.
    pub(super) ratio: f64,
    pub(super) violation: Option<String>,
    /// Outside the bound's hypotheses (not judged against it).
    pub(super) outside: bool,
    /// S-patches: the largest error of the float coordinates λ̂, in ULPs.
    pub(super) lambda_ulps: f64,
}

impl Acc {
    /// Measure `y` (floats of `precision`, as f64) against `exact` (ULPs, correct rounding);
    /// `None` measures of a non-finite value count as an infinite error.
    fn measure(&mut self, precision: Precision, y: &[f64], exact: &[BigRational]) {
        for (v, q) in y.iter().zip(exact) {
            let Some(yq) = tribez::hazmat::number::exact_f64(*v) else {
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
            let Some(yq) = tribez::hazmat::number::exact_f64(*v) else {
                continue;
            };
            let err = (yq - q).abs();
            if !b.is_zero() {
                self.ratio = self.ratio.max(round_f64(&(&err / b)));
            }
            if err > *b {
                self.violation = Some(format!(
                    "at {} coordinate {c}: {what}error {} exceeds the bound {}",
                    crate::report::tuple(at),
                    sci(&err),
                    sci(b)
                ));
            }
        }
    }

    /// One point's certified case ([`tribez::ErrorBound::certify`]), folded; `coordinate` names
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

/// The certification report.
pub struct CertifyReport {
    patch: String,
    points: usize,
    random: Option<(usize, u64, String)>,
    rows: Vec<Row>,
    regressions: Vec<String>,
    /// The bound's explanation line (the patch kind's).
    note: String,
}

fn alg_name(a: Algorithm) -> &'static str {
    match a {
        Algorithm::Casteljau => "casteljau",
        Algorithm::Bernstein => "bernstein",
    }
}

/// One algorithm of the float program `program`, over all points.
fn certify_row(
    program: &dyn FloatProgram,
    algorithm: Algorithm,
    points: &[Vec<BigRational>],
    (m, n): (usize, usize),
) -> Result<Row, CliError> {
    let precision = program.precision();
    let bound = program.error_bound().ok_or_else(|| {
        CliError::Usage(format!(
            "{}: the float program has no proven bound",
            precision.name()
        ))
    })?;
    let text = bound.text(algorithm);
    let coordinate = text.coordinates.as_ref().map_or("", |c| c.one);
    let accs: Vec<Acc> = points
        .par_iter()
        .map(|point| {
            // rounded as the float code rounds (an overflow is an infinite input)
            let input: Vec<f64> = point
                .iter()
                .map(|x| match precision {
                    Precision::F64 => round_f64(x),
                    Precision::F32 => f64::from(round_f32(x)),
                })
                .collect();
            Acc::of_case(precision, bound.certify(algorithm, &input), coordinate)
        })
        .collect();
    let mut row = Row::new(algorithm, precision, roundings(algorithm, m, n), text.label);
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
    Ok(row)
}

/// The algorithms of `--algorithm` among those of the kind's float program.
fn algorithms(
    args: &Args,
    patch: &Patch,
    float: &dyn FloatEval,
) -> Result<Vec<Algorithm>, CliError> {
    let offered = float.float_algorithms();
    if let [only] = offered {
        return match args.algorithm.as_str() {
            "all" | "casteljau" => Ok(vec![*only]),
            other => Err(CliError::Usage(format!(
                "--algorithm {other}: {} are certified with de Casteljau only (--algorithm casteljau or all)",
                patch.kind().plural()
            ))),
        };
    }
    match args.algorithm.as_str() {
        "all" => Ok(offered.to_vec()),
        "casteljau" => Ok(vec![Algorithm::Casteljau]),
        "bernstein" => Ok(vec![Algorithm::Bernstein]),
        other => Err(CliError::Usage(format!(
            "--algorithm: unknown algorithm `{other}` (known: casteljau, bernstein, all)"
        ))),
    }
}

/// Run `tribez certify`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let patch = Patch::from(read_any_patch(&args.patch)?);
    let precisions = match args.precision.as_str() {
        "all" => vec![Precision::F64, Precision::F32],
        p => vec![
            p.parse::<Precision>()
                .map_err(|e| CliError::Usage(format!("--precision: {e}")))?,
        ],
    };
    let float = patch.float().ok_or_else(|| {
        CliError::Usage(format!(
            "{}: {} have no float program to certify",
            args.patch.display(),
            patch.kind().plural()
        ))
    })?;
    let algorithms = algorithms(args, &patch, float)?;
    let (points, random) = points_of(args, &patch)?;
    let shape = patch.shape();
    let mut rows = Vec::new();
    let mut note = "";
    for &p in &precisions {
        let program = float
            .float_program(p)
            .map_err(|e| CliError::Usage(format!("{}: {e}", p.name())))?;
        for &a in &algorithms {
            if let Some(b) = program.error_bound() {
                note = b.text(a).note;
            }
            rows.push(certify_row(
                program.as_ref(),
                a,
                &points,
                (shape.simplex_dim, shape.degree),
            )?);
        }
    }
    finish(args, rows, points.len(), random, note)
}

/// `--random N` (with its reproducing command) or `--points FILE` (barycentric, `m + 1`
/// coordinates).
type RandomInfo = Option<(usize, u64, String)>;

/// The points of `--points FILE` or `--random N`, in the kind's coordinates: barycentric
/// (`m + 1`; random points inside, near the edges and outside the simplex) or Cartesian in an
/// S-patch's polygon (random points inside it, near its edges and vertices; a point of the file
/// outside it is an error, a random one rounded onto the wrong side of an edge is dropped).
fn points_of(args: &Args, patch: &Patch) -> Result<(Vec<Vec<BigRational>>, RandomInfo), CliError> {
    let input = patch.shape().input;
    let exact = patch.exact().exact_evaluator();
    let rational = |x: f64| BigRational::from_float(x).expect("finite");
    Ok(match (&args.points, args.random) {
        (Some(path), None) => {
            let points = read_points(path, input.len())?;
            for (i, p) in points.iter().enumerate() {
                if let Err(e) = exact.coordinates(p) {
                    return Err(CliError::Usage(format!(
                        "{}: point {}: {e}",
                        path.display(),
                        i + 1
                    )));
                }
            }
            (points, None)
        }
        (None, Some(n)) => {
            if n == 0 {
                return Err(CliError::Usage("--random needs at least one point".into()));
            }
            let pts: Vec<Vec<BigRational>> = match &input {
                InputSpace::Barycentric { m } => random_points(*m, n, args.seed)
                    .into_iter()
                    .map(|p| p.into_iter().map(rational).collect())
                    .collect(),
                InputSpace::Polygon { vertices } => {
                    let verts: Vec<[f64; 2]> = vertices
                        .iter()
                        .map(|v| [round_f64(&v[0]), round_f64(&v[1])])
                        .collect();
                    random_polygon_points(&verts, n, args.seed)
                        .into_iter()
                        .map(|p| p.into_iter().map(rational).collect::<Vec<_>>())
                        .filter(|p| exact.coordinates(p).is_ok())
                        .collect()
                }
            };
            (pts, Some((n, args.seed, reproduce(args, n))))
        }
        (None, None) => {
            return Err(CliError::Usage(
                "give --points FILE or --random N [--seed S]".into(),
            ));
        }
        (Some(_), Some(_)) => unreachable!("clap rejects --points with --random"),
    })
}

/// The reproducing command of a `--random` run.
fn reproduce(args: &Args, n: usize) -> String {
    format!(
        "tribez certify {} --random {n} --seed {} --precision {} --algorithm {}",
        args.patch.display(),
        args.seed,
        args.precision,
        args.algorithm
    )
}

/// Baselines, JUnit and the outcome, common to every kind of patch.
fn finish(
    args: &Args,
    rows: Vec<Row>,
    points: usize,
    random: RandomInfo,
    note: &str,
) -> Result<Outcome, CliError> {
    let mut report = CertifyReport {
        patch: args.patch.display().to_string(),
        points,
        random,
        rows,
        regressions: Vec::new(),
        note: note.to_string(),
    };
    let worst: Vec<super::baseline::Worst> = report
        .rows
        .iter()
        .map(|r| super::baseline::Worst {
            op: "eval".into(),
            algorithm: alg_name(r.algorithm).into(),
            precision: r.precision.name().into(),
            ulps: r.max_ulps,
            at: r
                .worst_point
                .as_ref()
                .map_or(String::new(), |p| crate::report::tuple(p)),
        })
        .collect();
    let all_hold = report.rows.iter().all(|r| r.violations.is_empty());
    report.regressions = super::baseline::judge(
        args.baseline.as_deref(),
        args.record_baseline.as_deref(),
        &worst,
        all_hold,
    )?;
    let success =
        report.rows.iter().all(|r| r.violations.is_empty()) && report.regressions.is_empty();
    if let Some(path) = &args.junit {
        super::write_atomically(path, report.junit().as_bytes())?;
    }
    Outcome::rendered(&report, args.out.format, success)
}

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

impl Render for CertifyReport {
    fn text(&self) -> String {
        let mut out = format!("{}: {} points\n", self.patch, self.points);
        if let Some((n, seed, cmd)) = &self.random {
            out += &format!("random points: {n}, seed {seed}; reproduce with:\n  {cmd}\n");
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
                alg_name(r.algorithm),
                r.precision.name(),
                r.cases,
                g(r.max_ulps),
                100.0 * r.correctly_rounded as f64 / r.cases.max(1) as f64,
                g(r.max_condition),
                g(r.max_relative_condition),
                r.label
                    .clone()
                    .unwrap_or_else(|| format!("γ_{}", r.gamma_k)),
                g(r.max_bound_ratio),
                if r.violations.is_empty() {
                    "within"
                } else {
                    "EXCEEDED"
                }
            );
        }
        out += &format!("\n{}\n", self.note);
        for r in &self.rows {
            for line in &r.notes {
                out += &format!("{} {}: {line}\n", alg_name(r.algorithm), r.precision.name());
            }
            if r.outside_hypothesis > 0 && r.label.is_none() {
                // (rational patches and S-patches explain theirs in `notes`)
                out += &format!(
                    "{} {}: {} points outside the bound's hypothesis (overflow or near underflow), not judged\n",
                    alg_name(r.algorithm),
                    r.precision.name(),
                    r.outside_hypothesis
                );
            }
            for v in r.violations.iter().take(20) {
                out += &format!(
                    "BOUND EXCEEDED: {} {}: {v}\n",
                    alg_name(r.algorithm),
                    r.precision.name()
                );
            }
        }
        for reg in &self.regressions {
            out += &format!("baseline regression: {reg}\n");
        }
        out
    }

    fn json(&self) -> Json {
        json!({
            "patch": self.patch,
            "points": self.points,
            "random": self.random.as_ref().map(|(n, s, c)| json!({"count": n, "seed": s, "reproduce": c})),
            "results": self.rows.iter().map(|r| json!({
                "algorithm": alg_name(r.algorithm), "precision": r.precision.name(), "coordinates": r.cases,
                "max_ulps": r.max_ulps, "worst_point": r.worst_point.as_ref().map(|p| crate::report::json_rationals(p)),
                "correctly_rounded": r.correctly_rounded, "max_condition": r.max_condition,
                "max_relative_condition": r.max_relative_condition, "bound": r.label.clone().unwrap_or_else(|| format!("gamma_{}", r.gamma_k)),
                "max_error_over_bound": r.max_bound_ratio, "within_bound": r.violations.is_empty(), "notes": r.notes,
                "violations": r.violations, "outside_hypothesis": r.outside_hypothesis,
            })).collect::<Vec<_>>(),
            "baseline_regressions": self.regressions,
            "bound_note": self.note,
        })
    }
}

impl Exporter for CertifyReport {
    fn junit(&self) -> String {
        let cases: Vec<JunitCase> = self
            .rows
            .iter()
            .map(|r| JunitCase {
                name: format!("{} {}", alg_name(r.algorithm), r.precision.name()),
                checks: r.cases,
                failures: r.violations.clone(),
            })
            .collect();
        junit_xml("certify", &cases)
    }
}
