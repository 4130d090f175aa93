//! `tribez eval`: exact values of a patch of any kind at points, with its float program beside
//! them (every precision asked for, every algorithm of the kind), judged in ULPs against the
//! exact values at the inputs as the code saw them and at the intended inputs.
//!
//! One code path for every kind: the kind's capabilities ([`tribez::ExactEval`],
//! [`tribez::FloatEval`]) do the kind-specific work.

use std::path::PathBuf;

use num_rational::BigRational;
use rayon::prelude::*;
use serde_json::{Value as Json, json};

use super::{CliError, Outcome, check_barycentric, parse_list};
use crate::cli::OutputArgs;
use crate::report::{Render, json_rationals, tuple};
use tribez::capability::{FloatProgram, InputSpace};
use tribez::hazmat::error::CoreError;
use tribez::hazmat::float::Precision;
use tribez::hazmat::io::patch_file::read_any_patch;
use tribez::hazmat::io::points::read_points;
use tribez::hazmat::number::to_decimal_string;
use tribez::{Patch, PatchKind};

/// Arguments of `tribez eval`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// A point: barycentric coordinates summing to 1 (`1/2,1/3,1/6`), or Cartesian with --cartesian. Repeatable.
    #[arg(long = "at", value_name = "POINT", allow_hyphen_values = true)]
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
    /// The exact value at those inputs (`None`: undefined there).
    exact_at_inputs: Option<Vec<BigRational>>,
    coords: Vec<FloatCoordinate>,
}

/// The result at one point.
pub struct PointResult {
    at: Vec<BigRational>,
    cartesian: Option<Vec<BigRational>>,
    /// The barycentric coordinates the kind computed on its way (an S-patch's Wachspress
    /// coordinates).
    lambda: Option<Vec<BigRational>>,
    point: Vec<BigRational>,
    floats: Vec<FloatResult>,
}

/// The whole evaluation report.
pub struct EvalReport {
    file: String,
    /// `"rational"`, `"s-patch"`; `None` for polynomial patches.
    kind: Option<&'static str>,
    header: String,
    results: Vec<PointResult>,
}

/// A float of `precision` (carried as f64), judged against the exact values at the inputs as
/// seen and as intended.
fn judge(
    precision: Precision,
    value: f64,
    exact_inputs: Option<&BigRational>,
    intended: &BigRational,
) -> FloatCoordinate {
    use tribez::hazmat::number as n;
    let exact = n::exact_f64(value);
    let ulps = |x: &BigRational, q: &BigRational| match precision {
        Precision::F64 => n::ulps_error_f64(x, q),
        Precision::F32 => n::ulps_error_f32(x, q),
    };
    let (decimal, hex) = match precision {
        Precision::F64 => (n::display_f64(value), n::hex_f64(value)),
        Precision::F32 => (n::display_f32(value as f32), n::hex_f32(value as f32)),
    };
    FloatCoordinate {
        decimal,
        hex,
        ulps_algorithm: exact.as_ref().zip(exact_inputs).map(|(x, e)| ulps(x, e)),
        ulps_total: exact.as_ref().map(|x| ulps(x, intended)),
        exact,
    }
}

/// Every algorithm of the float program `program` at `at`, judged.
fn float_results(
    patch: &Patch,
    program: &dyn FloatProgram,
    at: &[BigRational],
    intended: &[BigRational],
) -> Result<Vec<FloatResult>, CoreError> {
    let float = patch.float().expect("a float program was prepared");
    let input = program.round_input(at)?;
    let inputs: Vec<BigRational> = input
        .iter()
        .map(|&x| BigRational::from_float(x).expect("rounded inputs are finite"))
        .collect();
    let exact_at_inputs = program.exact_seen(&input);
    Ok(float
        .float_algorithms()
        .iter()
        .map(|&algorithm| FloatResult {
            precision: program.precision(),
            algorithm: float.algorithm_name(algorithm),
            inputs: inputs.clone(),
            coords: program
                .run(algorithm, &input)
                .iter()
                .enumerate()
                .map(|(c, &v)| {
                    judge(
                        program.precision(),
                        v,
                        exact_at_inputs.as_ref().map(|e| &e[c]),
                        &intended[c],
                    )
                })
                .collect(),
            exact_at_inputs: exact_at_inputs.clone(),
        })
        .collect())
}

/// The points of `--at` and `--points`, with a description each.
fn raw_points(args: &Args, width: usize) -> Result<Vec<(String, Vec<BigRational>)>, CliError> {
    let mut raw = Vec::new();
    for a in &args.at {
        raw.push((format!("--at {a}"), parse_list(a, "--at")?));
    }
    if let Some(path) = &args.points {
        for (i, p) in read_points(path, width)?.into_iter().enumerate() {
            raw.push((format!("{}: point {}", path.display(), i + 1), p));
        }
    }
    if raw.is_empty() {
        return Err(CliError::Usage(
            "give at least one point with --at or --points".into(),
        ));
    }
    Ok(raw)
}

/// The kind's input of one point (`at`), and its Cartesian coordinates if given so.
type Input = (Vec<BigRational>, Option<Vec<BigRational>>);

/// One raw point as the kind's input, checked.
fn input_of(args: &Args, patch: &Patch, p: Vec<BigRational>) -> Result<Input, CoreError> {
    let exact = patch.exact();
    match patch.shape().input {
        InputSpace::Polygon { .. } => {
            let at = exact.cartesian_input(&p)?;
            Ok((at, Some(p)))
        }
        InputSpace::Barycentric { m } => {
            if args.cartesian {
                Ok((exact.cartesian_input(&p)?, Some(p)))
            } else {
                if args.homogeneous {
                    if p.len() != m + 1 {
                        return Err(CoreError::WrongLength {
                            what: "point".into(),
                            expected: m + 1,
                            found: p.len(),
                        });
                    }
                } else {
                    check_barycentric(&p, m, "point")?;
                }
                Ok((p, None))
            }
        }
    }
}

/// The first line's description of the patch, and the report's `kind` (none for polynomial
/// patches).
fn header(patch: &Patch) -> (String, Option<&'static str>) {
    let s = patch.shape();
    let simplex = format!(
        "degree {} over the {}-simplex, points in R^{}",
        s.degree, s.simplex_dim, s.dimension
    );
    match (patch.kind(), &s.input) {
        (PatchKind::Bezier | PatchKind::Functional, _) => (simplex, None),
        (PatchKind::Rational, _) => (format!("rational, {simplex}"), Some("rational")),
        (PatchKind::SPatch, InputSpace::Polygon { vertices }) => (
            format!(
                "S-patch, depth {} over a {}-gon, points in R^{}",
                s.degree,
                vertices.len(),
                s.dimension
            ),
            Some("s-patch"),
        ),
        (PatchKind::SPatch, InputSpace::Barycentric { .. }) => {
            unreachable!("an S-patch takes Cartesian points")
        }
    }
}

/// Run `tribez eval`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from(read_any_patch(&args.patch)?);
    let shape = patch.shape();
    let width = match shape.input {
        InputSpace::Polygon { .. } => {
            if !args.cartesian {
                return Err(CliError::Usage(format!(
                    "{file} is an S-patch: give Cartesian points of its polygon with --cartesian --at x,y"
                )));
            }
            2
        }
        InputSpace::Barycentric { m } if args.cartesian => m,
        InputSpace::Barycentric { m } => m + 1,
    };
    let raw = raw_points(args, width)?;
    let precisions = args.float.map(FloatChoice::precisions).unwrap_or_default();
    let programs: Vec<Box<dyn FloatProgram + '_>> = match patch.float() {
        Some(float) => precisions
            .iter()
            .map(|&p| {
                float
                    .float_program(p)
                    .map_err(|e| CliError::core(format!("{file}: {}", p.name()), e))
            })
            .collect::<Result<_, _>>()?,
        None => Vec::new(),
    };
    let exact = patch.exact().exact_evaluator();
    // every point's result or error; the first error in the order of the points is reported
    let results: Vec<Result<PointResult, CliError>> = raw
        .into_par_iter()
        .map(|(what, p)| {
            let fail = |e| CliError::core(&what, e);
            let (at, cartesian) = input_of(args, &patch, p).map_err(fail)?;
            let point = exact.evaluate(&at).map_err(fail)?;
            let lambda = exact.coordinates(&at).map_err(fail)?;
            let mut floats = Vec::new();
            for program in &programs {
                floats.extend(float_results(&patch, program.as_ref(), &at, &point).map_err(fail)?);
            }
            Ok(PointResult {
                at,
                cartesian,
                lambda,
                point,
                floats,
            })
        })
        .collect();
    let results = results.into_iter().collect::<Result<_, _>>()?;
    let (header, kind) = header(&patch);
    let report = EvalReport {
        file,
        kind,
        header,
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
        let mut out = format!("{}: {}\n", self.file, self.header);
        for r in &self.results {
            match (&r.cartesian, &r.lambda) {
                (Some(c), Some(l)) => {
                    out += &format!("at {} (Wachspress {})", tuple(c), tuple(l));
                }
                (Some(c), None) => out += &format!("at {} (Cartesian {})", tuple(&r.at), tuple(c)),
                (None, _) => out += &format!("at {}", tuple(&r.at)),
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
                        f.exact_at_inputs
                            .as_ref()
                            .map_or("undefined".into(), |e| e[c].to_string()),
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
                if let Some(l) = &r.lambda {
                    o["wachspress"] = json_rationals(l);
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
                                    "exact_at_inputs": f.exact_at_inputs.as_ref().map_or(Json::Null, |e| json_rationals(e)),
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
        let mut o = json!({ "patch": self.file });
        if let Some(kind) = self.kind {
            o["kind"] = json!(kind);
        }
        o["results"] = Json::Array(results);
        o
    }
}
