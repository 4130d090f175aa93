//! `tribez eval`: exact values of a patch at points, with the float paths beside them.

use std::path::PathBuf;

use num_rational::BigRational;
use rayon::prelude::*;
use serde_json::{Value as Json, json};

use super::{CliError, Outcome, check_barycentric};
use crate::cli::OutputArgs;
use crate::report::{Render, json_rationals, tuple};
use tribez::bernstein;
use tribez::exact::ExactEvaluator;
use tribez::float::{Float, Precision, net_to};
use tribez::io::patch_file::read_any_patch;
use tribez::number::to_decimal_string;
use tribez::patch::{AnyPatch, ControlNet, Patch};

/// Arguments of `tribez eval`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// A point: barycentric coordinates summing to 1 (`1/2,1/3,1/6`), or Cartesian with --cartesian. Repeatable.
    #[arg(long = "at", value_name = "POINT")]
    pub at: Vec<String>,
    /// Read points from a CSV or JSON file (one point per row).
    #[arg(long, value_name = "FILE")]
    pub points: Option<PathBuf>,
    /// Points are Cartesian coordinates in the patch's domain (converted by Cramer's rule).
    #[arg(long)]
    pub cartesian: bool,
    /// Accept barycentric coordinates that do not sum to 1 (evaluates the homogeneous form).
    #[arg(long)]
    pub homogeneous: bool,
    /// Also run the float paths (de Casteljau and Bernstein) in this precision and show their errors.
    #[arg(long, value_name = "f64|f32|all")]
    pub float: Option<FloatChoice>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Which float precisions to show.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FloatChoice {
    /// binary64
    F64,
    /// binary32
    F32,
    /// both
    All,
}

impl FloatChoice {
    fn precisions(self) -> Vec<Precision> {
        match self {
            FloatChoice::F64 => vec![Precision::F64],
            FloatChoice::F32 => vec![Precision::F32],
            FloatChoice::All => vec![Precision::F64, Precision::F32],
        }
    }
}

/// One float coordinate, judged.
pub struct FloatCoordinate {
    decimal: String,
    hex: String,
    exact: Option<BigRational>,
    /// Error in ULPs against the exact value at the inputs as the float code saw them.
    ulps_algorithm: Option<BigRational>,
    /// Error in ULPs against the exact value at the intended inputs.
    ulps_total: Option<BigRational>,
}

/// One float path's result at one point.
pub struct FloatResult {
    precision: Precision,
    algorithm: &'static str,
    /// The exact values of the rounded inputs.
    inputs: Vec<BigRational>,
    exact_at_inputs: Vec<BigRational>,
    coords: Vec<FloatCoordinate>,
}

/// The result at one point.
pub struct PointResult {
    at: Vec<BigRational>,
    cartesian: Option<Vec<BigRational>>,
    point: Vec<BigRational>,
    floats: Vec<FloatResult>,
}

/// The whole evaluation report.
pub struct EvalReport {
    file: String,
    patch: Patch,
    results: Vec<PointResult>,
}

fn judge<F: Float>(
    value: F,
    exact_inputs: &BigRational,
    intended: &BigRational,
) -> FloatCoordinate {
    let exact = value.exact();
    FloatCoordinate {
        decimal: value.decimal(),
        hex: value.hex(),
        ulps_algorithm: exact.as_ref().map(|x| F::ulps(x, exact_inputs)),
        ulps_total: exact.as_ref().map(|x| F::ulps(x, intended)),
        exact,
    }
}

/// The float results of both algorithms at `lambda`, judged against exact values.
/// A float path prepared once per patch: the rounded net, and the exact evaluator of its exact
/// values (shared by every point, so the per-patch precomputation is not repeated per point).
struct FloatPath<F> {
    fnet: ControlNet<F>,
    exact: ExactEvaluator,
}

impl<F: Float> FloatPath<F> {
    fn new(net: &ControlNet<BigRational>) -> Self {
        let fnet: ControlNet<F> = net_to(net);
        let exact = ExactEvaluator::new(&fnet.map(|x| x.exact().unwrap_or_default()));
        FloatPath { fnet, exact }
    }
}

fn float_results<F: Float>(
    path: &FloatPath<F>,
    lambda: &[BigRational],
    intended: &[BigRational],
) -> Vec<FloatResult> {
    let fnet = &path.fnet;
    let lam: Vec<F> = lambda.iter().map(F::round).collect();
    let lam_exact: Vec<BigRational> = lam
        .iter()
        .map(|x| x.exact().expect("rounded coordinates are finite"))
        .collect();
    let exact_at_inputs = path.exact.evaluate_fast(&lam_exact);
    [
        ("casteljau", tribez::float::casteljau(fnet, &lam)),
        ("bernstein", bernstein::evaluate(fnet, &lam)),
    ]
    .into_iter()
    .map(|(algorithm, values)| FloatResult {
        precision: F::PRECISION,
        algorithm,
        inputs: lam_exact.clone(),
        exact_at_inputs: exact_at_inputs.clone(),
        coords: values
            .iter()
            .zip(&exact_at_inputs)
            .zip(intended)
            .map(|((&v, e), i)| judge(v, e, i))
            .collect(),
    })
    .collect()
}

/// Run `tribez eval`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = match read_any_patch(&args.patch)? {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p,
        AnyPatch::Rational(r) => return super::eval_beyond::rational(args, file, r),
        AnyPatch::SPatch(s) => return super::eval_beyond::spatch(args, file, s),
    };
    let m = patch.net.m();
    let width = if args.cartesian { m } else { m + 1 };
    let raw = super::eval_beyond::raw_points(args, width)?;
    let domain = patch.domain_or_reference();
    let mut points = Vec::with_capacity(raw.len());
    for (what, p) in raw {
        if args.cartesian {
            let lambda = domain
                .barycentric(&p)
                .map_err(|e| CliError::core(&what, e))?;
            points.push((lambda, Some(p)));
        } else {
            if args.homogeneous {
                if p.len() != m + 1 {
                    return Err(CliError::core(
                        &what,
                        tribez::error::CoreError::WrongLength {
                            what: "point".into(),
                            expected: m + 1,
                            found: p.len(),
                        },
                    ));
                }
            } else {
                check_barycentric(&p, m, "point").map_err(|e| CliError::core(&what, e))?;
            }
            points.push((p, None));
        }
    }
    let evaluator = ExactEvaluator::new(&patch.net);
    let precisions = args.float.map(FloatChoice::precisions).unwrap_or_default();
    let path64 = precisions
        .contains(&Precision::F64)
        .then(|| FloatPath::<f64>::new(&patch.net));
    let path32 = precisions
        .contains(&Precision::F32)
        .then(|| FloatPath::<f32>::new(&patch.net));
    let results = points
        .into_par_iter()
        .map(|(at, cartesian)| {
            let point = evaluator.evaluate_fast(&at);
            let mut floats = Vec::new();
            for p in &precisions {
                floats.extend(match p {
                    Precision::F64 => {
                        float_results(path64.as_ref().expect("prepared"), &at, &point)
                    }
                    Precision::F32 => {
                        float_results(path32.as_ref().expect("prepared"), &at, &point)
                    }
                });
            }
            PointResult {
                at,
                cartesian,
                point,
                floats,
            }
        })
        .collect();
    let report = EvalReport {
        file,
        patch,
        results,
    };
    Outcome::rendered(&report, args.out.format, true)
}

fn opt_str(q: &Option<BigRational>) -> Json {
    q.as_ref().map_or(Json::Null, |x| json!(x.to_string()))
}

fn ulps_text(q: &Option<BigRational>) -> String {
    q.as_ref().map_or("n/a".into(), |x| to_decimal_string(x, 4))
}

impl Render for EvalReport {
    fn text(&self) -> String {
        let net = &self.patch.net;
        let mut out = format!(
            "{}: degree {} over the {}-simplex, points in R^{}\n",
            self.file,
            net.degree(),
            net.m(),
            net.dim()
        );
        for r in &self.results {
            out += &format!("at {}", tuple(&r.at));
            if let Some(c) = &r.cartesian {
                out += &format!(" (Cartesian {})", tuple(c));
            }
            out += &format!(": {}\n", tuple(&r.point));
            for f in &r.floats {
                out += &format!(
                    "  {} {}: inputs as the code saw them {}\n",
                    f.precision.name(),
                    f.algorithm,
                    tuple(&f.inputs)
                );
                for (c, fc) in f.coords.iter().enumerate() {
                    out += &format!(
                        "    [{c}] {} = {} = {}; {} ulp from the exact value at those inputs ({}), {} ulp from the exact value at the intended inputs\n",
                        fc.decimal,
                        fc.hex,
                        fc.exact
                            .as_ref()
                            .map_or("not finite".into(), ToString::to_string),
                        ulps_text(&fc.ulps_algorithm),
                        f.exact_at_inputs[c],
                        ulps_text(&fc.ulps_total),
                    );
                }
            }
        }
        out
    }

    fn json(&self) -> Json {
        let results: Vec<Json> = self
            .results
            .iter()
            .map(|r| {
                let mut o =
                    json!({ "at": json_rationals(&r.at), "point": json_rationals(&r.point) });
                if let Some(c) = &r.cartesian {
                    o["cartesian"] = json_rationals(c);
                }
                if !r.floats.is_empty() {
                    o["float"] = Json::Array(
                        r.floats
                            .iter()
                            .map(|f| {
                                json!({
                                    "precision": f.precision.name(),
                                    "algorithm": f.algorithm,
                                    "inputs": json_rationals(&f.inputs),
                                    "exact_at_inputs": json_rationals(&f.exact_at_inputs),
                                    "value": f.coords.iter().map(|c| json!({
                                        "decimal": c.decimal,
                                        "hex": c.hex,
                                        "exact": opt_str(&c.exact),
                                        "ulps_vs_exact_at_inputs": opt_str(&c.ulps_algorithm),
                                        "ulps_vs_exact_at_intended_inputs": opt_str(&c.ulps_total),
                                    })).collect::<Vec<_>>(),
                                })
                            })
                            .collect(),
                    );
                }
                o
            })
            .collect();
        json!({ "patch": self.file, "results": results })
    }
}
