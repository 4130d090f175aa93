//! `tribez certify`: run tribez's own float algorithms (de Casteljau and the direct Bernstein
//! form, generic code in f64 and f32) and judge them against the exact values and their proven
//! a-priori error bounds ([`tribez::certify::bound`]). Rational patches and S-patches:
//! [`super::certify_beyond`].

use std::path::PathBuf;
use tribez::certify::sample::random_points;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use serde_json::{Value as Json, json};
use tribez::number::round_f64;

use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::{Exporter, JunitCase, Render, junit_xml};
use tribez::certify::Certifier;
use tribez::certify::bound::{a_priori, condition, roundings};
use tribez::certify::measures::Measures;
use tribez::exact::Algorithm;
use tribez::float::{Float, Precision};
use tribez::io::patch_file::read_any_patch;
use tribez::io::points::read_points;
use tribez::patch::{AnyPatch, Patch};

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
    #[arg(long, value_name = "N")]
    pub random: Option<usize>,
    /// Seed of --random (printed, with the command that reproduces the run).
    #[arg(long, value_name = "S", default_value_t = 1)]
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
    /// Measure `y` against `exact` (ULPs, correct rounding); `None` measures of a non-finite
    /// value count as an infinite error.
    pub(super) fn measure<F: Float>(&mut self, y: &[F], exact: &[BigRational]) {
        for (v, q) in y.iter().zip(exact) {
            let Some(yq) = v.exact() else { continue };
            let meas = Measures::new(&yq, q, Some(F::PRECISION));
            self.ulps = self
                .ulps
                .max(meas.ulps.as_ref().map_or(f64::INFINITY, round_f64));
            if meas.correctly_rounded == Some(true) {
                self.cr += 1;
            }
        }
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

fn certify_one<F: Float>(patch: &Patch, algorithm: Algorithm, points: &[Vec<BigRational>]) -> Row {
    let cert = Certifier::<F>::new(&patch.net);
    let (m, n) = (patch.net.m(), patch.net.degree());
    let cases: Vec<Acc> = points
        .par_iter()
        .map(|point| {
            let lam: Vec<F> = point.iter().map(F::round).collect();
            let y = tribez::certify::run(algorithm, &cert.net, &lam);
            let lam_q: Vec<BigRational> =
                lam.iter().map(|x| x.exact().unwrap_or_default()).collect();
            let outside = y.iter().any(|v| !v.finite())
                || (algorithm == Algorithm::Bernstein
                    && tribez::certify::bernstein_may_underflow(&cert.net, &lam));
            let p = cert.exact.evaluate_fast(&lam_q);
            let cond = condition(&cert.exact_net, &lam_q);
            let mut case = Acc {
                coords: y.len(),
                outside,
                ..Acc::default()
            };
            case.measure(&y, &p);
            for (c, v) in y.iter().enumerate() {
                case.cond = case.cond.max(round_f64(&cond[c]));
                if !p[c].is_zero() {
                    case.rel_cond = case.rel_cond.max(round_f64(&(&cond[c] / p[c].abs())));
                }
                let Some(yq) = v.exact() else { continue };
                if outside {
                    continue;
                }
                let abs = (&yq - &p[c]).abs();
                if let Some(b) = a_priori(algorithm, F::PRECISION, m, n, &cond[c], &lam_q) {
                    if !b.is_zero() {
                        case.ratio = case.ratio.max(round_f64(&(&abs / &b)));
                    }
                    if abs > b {
                        case.violation = Some(format!(
                            "at {} coordinate {c}: error {} exceeds the bound {}",
                            crate::report::tuple(&lam_q),
                            tribez::certify::measures::sci(&abs),
                            tribez::certify::measures::sci(&b)
                        ));
                    }
                }
            }
            case
        })
        .collect();
    let mut row = Row::new(algorithm, F::PRECISION, roundings(algorithm, m, n), None);
    row.fold(cases, points);
    row
}

/// Run `tribez certify`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let any = read_any_patch(&args.patch)?;
    let precisions = match args.precision.as_str() {
        "all" => vec![Precision::F64, Precision::F32],
        p => vec![
            p.parse::<Precision>()
                .map_err(|e| CliError::Usage(format!("--precision: {e}")))?,
        ],
    };
    let patch = match any {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p,
        AnyPatch::Rational(r) => {
            let (rows, points, random) = super::certify_beyond::rational(args, &r, &precisions)?;
            return finish(
                args,
                rows,
                points,
                random,
                super::certify_beyond::RATIONAL_NOTE,
            );
        }
        AnyPatch::SPatch(sp) => {
            let (rows, points, random) = super::certify_beyond::spatch(args, &sp, &precisions)?;
            return finish(
                args,
                rows,
                points,
                random,
                super::certify_beyond::SPATCH_NOTE,
            );
        }
    };
    let m = patch.net.m();
    let algorithms = match args.algorithm.as_str() {
        "all" => vec![Algorithm::Casteljau, Algorithm::Bernstein],
        "casteljau" => vec![Algorithm::Casteljau],
        "bernstein" => vec![Algorithm::Bernstein],
        other => {
            return Err(CliError::Usage(format!(
                "--algorithm: unknown algorithm `{other}` (known: casteljau, bernstein, all)"
            )));
        }
    };
    let (points, random) = points_of(args, m)?;
    let mut rows = Vec::new();
    for &p in &precisions {
        for &a in &algorithms {
            rows.push(match p {
                Precision::F64 => certify_one::<f64>(&patch, a, &points),
                Precision::F32 => certify_one::<f32>(&patch, a, &points),
            });
        }
    }
    finish(args, rows, points.len(), random, POLYNOMIAL_NOTE)
}

const POLYNOMIAL_NOTE: &str = "bound: |fl(p) − P(λ)| ≤ γ_K Σ|c_i| B_i(|λ|) (γ_K = Kε/(1−Kε)); cond = Σ|c_i|B_i(|λ|), relcond = cond/|P|; err/bound = largest observed error over its bound";

/// `--random N` (with its reproducing command) or `--points FILE` (barycentric, `m + 1`
/// coordinates).
pub(super) type RandomInfo = Option<(usize, u64, String)>;

pub(super) fn points_of(
    args: &Args,
    m: usize,
) -> Result<(Vec<Vec<BigRational>>, RandomInfo), CliError> {
    Ok(match (&args.points, args.random) {
        (Some(path), None) => (read_points(path, m + 1)?, None),
        (None, Some(n)) => {
            if n == 0 {
                return Err(CliError::Usage("--random needs at least one point".into()));
            }
            let pts: Vec<Vec<BigRational>> = random_points(m, n, args.seed)
                .into_iter()
                .map(|p| {
                    p.into_iter()
                        .map(|x| BigRational::from_float(x).expect("finite"))
                        .collect()
                })
                .collect();
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
pub(super) fn reproduce(args: &Args, n: usize) -> String {
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
    if let Some(path) = &args.record_baseline {
        super::baseline::record(path, &worst)?;
    }
    if let Some(path) = &args.baseline {
        report.regressions = super::baseline::compare(path, &worst)?;
    }
    let success =
        report.rows.iter().all(|r| r.violations.is_empty()) && report.regressions.is_empty();
    if let Some(path) = &args.junit {
        super::write_atomically(path, report.junit().as_bytes())?;
    }
    Outcome::rendered(&report, args.out.format, success)
}

pub(super) fn g(x: f64) -> String {
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
