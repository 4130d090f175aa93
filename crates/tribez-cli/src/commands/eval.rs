//! `tribez eval`: exact values of a patch of any kind at points, with its float program beside
//! them (every precision asked for, every algorithm of the kind), judged in ULPs against the
//! exact values at the inputs as the code saw them and at the intended inputs.
//!
//! One code path for every kind: the kind's capabilities ([`tribez::ExactEval`],
//! [`tribez::FloatEval`]) do the kind-specific work.

use std::path::PathBuf;

use num_rational::BigRational;
use rayon::prelude::*;
use serde::{Serialize, Serializer};
#[cfg(test)]
use serde_json::Value as Json;

use super::{CliError, Outcome, OutputTarget, check_barycentric, parse_list};
use crate::cli::{OutputArgs, TextOrJson};
use crate::output::{self, Sink};
#[cfg(test)]
use crate::report::{Render, to_json};
use tribez::CoreError;
use tribez::Precision;
use tribez::capability::{FloatProgram, InputSpace, PointEvaluator};
use tribez::files::read_points;
use tribez::format::{push_rational, ulps_decimal};
use tribez::kernels::word_point;
use tribez::{Patch, PatchKind};

// Arguments of `tribez eval` (a plain comment: see `Command`).
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
#[derive(Serialize)]
pub struct FloatCoordinate {
    decimal: String,
    hex: String,
    #[serde(serialize_with = "opt_rational")]
    exact: Option<BigRational>,
    /// Error in ULPs against the exact value at the inputs as the float code saw them.
    #[serde(rename = "ulps_vs_exact_at_inputs", serialize_with = "opt_rational")]
    ulps_algorithm: Option<BigRational>,
    /// Error in ULPs against the exact value at the intended inputs.
    #[serde(
        rename = "ulps_vs_exact_at_intended_inputs",
        serialize_with = "opt_rational"
    )]
    ulps_total: Option<BigRational>,
}

/// One float path's result at one point.
#[derive(Serialize)]
pub struct FloatResult {
    #[serde(serialize_with = "precision_name")]
    precision: Precision,
    algorithm: &'static str,
    /// The exact values of the rounded inputs.
    #[serde(serialize_with = "rationals")]
    inputs: Vec<BigRational>,
    /// The exact value at those inputs (`None`: undefined there).
    #[serde(serialize_with = "opt_rationals")]
    exact_at_inputs: Option<Vec<BigRational>>,
    #[serde(rename = "value")]
    coords: Vec<FloatCoordinate>,
}

/// The result at one point.
#[derive(Serialize)]
pub struct PointResult {
    #[serde(serialize_with = "rationals")]
    at: Vec<BigRational>,
    #[serde(serialize_with = "rationals")]
    point: Vec<BigRational>,
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "opt_rationals"
    )]
    cartesian: Option<Vec<BigRational>>,
    /// The barycentric coordinates the kind computed on its way (an S-patch's Wachspress
    /// coordinates).
    #[serde(
        rename = "wachspress",
        skip_serializing_if = "Option::is_none",
        serialize_with = "opt_rationals"
    )]
    lambda: Option<Vec<BigRational>>,
    #[serde(rename = "float", skip_serializing_if = "Vec::is_empty")]
    floats: Vec<FloatResult>,
}

/// The whole evaluation report as one tree: the reference the streamed output of [`run`] is
/// tested against (the generic JSON exporter and `text()`).
#[cfg(test)]
#[derive(Serialize)]
pub struct EvalReport {
    #[serde(rename = "patch")]
    file: String,
    /// `"rational"`, `"s-patch"`; `None` for polynomial patches.
    #[serde(skip_serializing_if = "Option::is_none")]
    kind: Option<&'static str>,
    #[serde(skip)]
    header: String,
    results: Vec<PointResult>,
}

/// An exact rational as a JSON string `p/q` in lowest terms.
struct Exact<'a>(&'a BigRational);

impl Serialize for Exact<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        // one buffer per thread: the digits are written, then copied into the output
        thread_local! {
            static TEXT: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
        }
        TEXT.with_borrow_mut(|text| {
            text.clear();
            push_rational(text, self.0);
            s.serialize_str(text)
        })
    }
}

fn rationals<S: Serializer>(xs: &[BigRational], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(xs.iter().map(Exact))
}

fn opt_rationals<S: Serializer>(xs: &Option<Vec<BigRational>>, s: S) -> Result<S::Ok, S::Error> {
    match xs {
        Some(xs) => rationals(xs, s),
        None => s.serialize_none(),
    }
}

fn opt_rational<S: Serializer>(x: &Option<BigRational>, s: S) -> Result<S::Ok, S::Error> {
    match x {
        Some(x) => Exact(x).serialize(s),
        None => s.serialize_none(),
    }
}

fn precision_name<S: Serializer>(p: &Precision, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(p.name())
}

/// A float of `precision` (carried as f64), judged against the exact values at the inputs as
/// seen and as intended.
fn judge(
    precision: Precision,
    value: f64,
    exact_inputs: Option<&BigRational>,
    intended: &BigRational,
) -> FloatCoordinate {
    use tribez::format as n;
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

/// Where a raw point came from: the `k`-th `--at`, or point `i` of the `--points` file.
/// Described only when an error names it (a description formatted for every point of a large
/// file cost more than parsing it).
#[derive(Clone, Copy, Debug)]
enum Origin {
    At(usize),
    File(usize),
}

impl Origin {
    fn describe(self, args: &Args) -> String {
        match (self, &args.points) {
            (Origin::At(k), _) => format!("--at {}", args.at[k]),
            (Origin::File(i), Some(path)) => format!("{}: point {}", path.display(), i + 1),
            (Origin::File(i), None) => format!("point {}", i + 1),
        }
    }
}

/// The raw points of a run, each with where it came from.
type RawPoints = Vec<(Origin, Vec<BigRational>)>;

/// The points of `--at` and `--points`, each with its [`Origin`].
fn raw_points(args: &Args, width: usize) -> Result<RawPoints, CliError> {
    let mut raw = Vec::new();
    for (k, a) in args.at.iter().enumerate() {
        raw.push((Origin::At(k), parse_list(a, "--at")?));
    }
    if let Some(path) = &args.points {
        raw.extend(
            read_points(path, width)?
                .into_iter()
                .enumerate()
                .map(|(i, p)| (Origin::File(i), p)),
        );
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
                } else if !sums_to_one(&p, m) {
                    // the general check, and its error
                    check_barycentric(&p, m, "point")?;
                }
                Ok((p, None))
            }
        }
    }
}

/// `m + 1` non-negative coordinates with one word-sized common denominator `D` that sum to one,
/// decided on machine words (`Σ a_k = D`); `false` says nothing (the general check decides).
fn sums_to_one(p: &[BigRational], m: usize) -> bool {
    p.len() == m + 1
        && word_point(p)
            .is_some_and(|(a, d)| a.iter().map(|&x| u128::from(x)).sum::<u128>() == u128::from(d))
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

/// Run `tribez eval`: the report goes to standard output or `-o FILE` as it is produced (see
/// [`write_report`]).
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    output::stream(args.out.output.as_deref(), |sink| {
        write_report(args, None, sink)
    })?;
    Ok(Outcome {
        output: Vec::new(),
        success: true,
    })
}

impl OutputTarget for Args {
    /// The report is written by [`run`] as it is produced; nothing is left to write after it.
    fn output(&self) -> Option<&PathBuf> {
        None
    }
}

/// The most a chunk's output is sized for in advance (it still grows past it as needed).
const RESERVE_CAP: usize = 1 << 24;

/// Write the report of `tribez eval` into `sink`.
///
/// Every point is evaluated and rendered on the core that evaluates it, `chunk` points per task
/// (by default many chunks per core, so that the cores share the work evenly to the end), and
/// the chunks are written in order ([`tribez::ordered::render_in_order`]): each as soon as the
/// chunks before it are, its buffer then used again. The digits of large results are much of the work, and a
/// report held whole until the end costs its size in fresh memory and a long write at the end.
///
/// Nothing is written unless every point succeeds: every point's input is checked first, and
/// the chunks wait for the last point unless the kind's evaluation cannot fail at a checked
/// input ([`PointEvaluator::total`]) and no float program runs (rounding an input can fail).
/// The error reported is that of the first failing point in the order of the points.
fn write_report(args: &Args, chunk: Option<usize>, sink: &mut Sink<'_>) -> Result<(), CliError> {
    let input = EvalInput::read(args)?;
    let (eval, raw) = input.evaluators_and_points(args)?;
    let format = args.out.format;
    let chunk = chunk
        .unwrap_or(raw.len() / (16 * rayon::current_num_threads()))
        .clamp(1, 1024);
    let checked: Vec<Result<Vec<Checked>, CliError>> = raw
        .into_par_iter()
        .map(|(origin, p)| eval.input(origin, p))
        .chunks(chunk)
        .map(|points| points.into_iter().collect())
        .collect();
    let chunks = checked.into_iter().collect::<Result<Vec<_>, _>>()?;
    let (open, close) = match format {
        TextOrJson::Json => json_envelope(&input.file, input.kind, chunks.is_empty()),
        TextOrJson::Text => (format!("{}: {}\n", input.file, input.header), String::new()),
    };
    let early = eval.exact.total() && eval.programs.is_empty();
    // the report's opening goes out before its first chunk (and alone when there is none)
    let mut opened = false;
    tribez::ordered::render_in_order(
        chunks,
        early,
        |k, points, part| render_chunk(&eval, format, k, points, part),
        |part| {
            if !opened {
                sink.write(open.as_bytes());
                opened = true;
            }
            sink.write(part.as_bytes());
        },
    )?;
    if !opened {
        sink.write(open.as_bytes());
    }
    sink.write(close.as_bytes());
    Ok(())
}

/// A point whose input is checked: where it came from, and the kind's input.
type Checked = (Origin, Input);

/// Evaluate and render chunk `k` of the points into `part` (empty); the error of its first
/// failing point.
fn render_chunk(
    eval: &Evaluators<'_>,
    format: TextOrJson,
    k: usize,
    points: Vec<Checked>,
    part: &mut String,
) -> Result<(), CliError> {
    let count = points.len();
    for (i, (origin, input)) in points.into_iter().enumerate() {
        let r = eval.result(origin, input)?;
        match format {
            TextOrJson::Json => {
                if k > 0 || i > 0 {
                    part.push(',');
                }
                push_json_point(part, &r);
            }
            TextOrJson::Text => *part += &point_text(&r),
        }
        if i == 0 {
            // The points of a batch render to about the same length: size the part once (an
            // eighth to spare) instead of growing it by copies, unless it has about that room
            // already (a buffer used before); at most RESERVE_CAP, since a first point much
            // longer than the others would otherwise reserve the chunk's length times its own.
            let need = part.len().saturating_mul(count - 1).min(RESERVE_CAP);
            if part.capacity() - part.len() < need {
                part.reserve(need + need / 8);
            }
        }
    }
    Ok(())
}

/// What `tribez eval` reads first: the patch, the number of coordinates of its points, and the
/// report's first line and `kind`.
struct EvalInput {
    file: String,
    patch: Patch,
    width: usize,
    header: String,
    kind: Option<&'static str>,
}

impl EvalInput {
    fn read(args: &Args) -> Result<Self, CliError> {
        let file = args.patch.display().to_string();
        let patch = Patch::from_file(&args.patch)?;
        let width = match patch.shape().input {
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
        let (header, kind) = header(&patch);
        Ok(EvalInput {
            file,
            patch,
            width,
            header,
            kind,
        })
    }

    /// The patch's evaluators and the points (with a description each, for errors): the points
    /// are read and parsed while the exact evaluator is prepared (both on all cores), which at
    /// high degree takes about as long. A bad point is reported before an evaluator's error, as
    /// if the points were read first.
    fn evaluators_and_points<'p>(
        &'p self,
        args: &'p Args,
    ) -> Result<(Evaluators<'p>, RawPoints), CliError> {
        let (eval, raw) = rayon::join(
            || Evaluators::new(args, &self.file, &self.patch),
            || raw_points(args, self.width),
        );
        let raw = raw?;
        Ok((eval?, raw))
    }
}

/// The patch's exact evaluator and its float programs (every precision asked for).
struct Evaluators<'p> {
    args: &'p Args,
    patch: &'p Patch,
    exact: Box<dyn PointEvaluator + 'p>,
    programs: Vec<Box<dyn FloatProgram + 'p>>,
}

impl<'p> Evaluators<'p> {
    fn new(args: &'p Args, file: &str, patch: &'p Patch) -> Result<Self, CliError> {
        let precisions = args.float.map(FloatChoice::precisions).unwrap_or_default();
        let programs = match patch.float() {
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
        Ok(Evaluators {
            args,
            patch,
            exact: patch.exact().exact_evaluator(),
            programs,
        })
    }

    /// The raw point `p` (from `origin`, which errors name) as the kind's input, checked.
    fn input(&self, origin: Origin, p: Vec<BigRational>) -> Result<Checked, CliError> {
        input_of(self.args, self.patch, p)
            .map(|input| (origin, input))
            .map_err(|e| CliError::core(origin.describe(self.args), e))
    }

    /// The result at the checked input `(at, cartesian)` of the point from `origin`.
    fn result(&self, origin: Origin, (at, cartesian): Input) -> Result<PointResult, CliError> {
        let fail = |e| CliError::core(origin.describe(self.args), e);
        let point = self.exact.evaluate(&at).map_err(fail)?;
        let lambda = self.exact.coordinates(&at).map_err(fail)?;
        let mut floats = Vec::new();
        for program in &self.programs {
            let judged = float_results(self.patch, program.as_ref(), &at, &point).map_err(fail)?;
            floats.extend(judged);
        }
        Ok(PointResult {
            at,
            cartesian,
            lambda,
            point,
            floats,
        })
    }
}

/// The report of `tribez eval` as one tree, point by point in order (the reference of the tests).
#[cfg(test)]
fn evaluate(args: &Args) -> Result<EvalReport, CliError> {
    let input = EvalInput::read(args)?;
    let (eval, raw) = input.evaluators_and_points(args)?;
    let results = raw
        .into_iter()
        .map(|(origin, p)| {
            let (origin, input) = eval.input(origin, p)?;
            eval.result(origin, input)
        })
        .collect::<Result<_, _>>()?;
    drop(eval);
    Ok(EvalReport {
        file: input.file,
        kind: input.kind,
        header: input.header,
        results,
    })
}

/// The JSON report's text before and after its results: the same bytes as the JSON exporter
/// writes around them from the report's tree (two-space indents and a final newline).
fn json_envelope(file: &str, kind: Option<&str>, empty: bool) -> (String, String) {
    let quoted = |s: &str| serde_json::to_string(s).expect("a string serialises");
    let mut open = format!("{{\n  \"patch\": {}", quoted(file));
    if let Some(kind) = kind {
        open += &format!(",\n  \"kind\": {}", quoted(kind));
    }
    open += ",\n  \"results\": [";
    let close = if empty { "]\n}\n" } else { "\n  ]\n}\n" };
    (open, close.to_owned())
}

/// A point as serde's pretty printer writes it at depth 2 of the report (`\n` and four spaces,
/// then the object). Without float paths it is written directly ([`push_exact_point`]: its
/// strings are digits, `-` and `/`, which JSON never escapes); with them, as the `results`
/// array of a one-key object pretty-printed by serde (so that it sits at the depth it has in
/// the report), cut out of it.
fn push_json_point(out: &mut String, r: &PointResult) {
    #[derive(Serialize)]
    struct Results<'a> {
        results: &'a [PointResult],
    }
    const OPEN: &str = "{\n  \"results\": [";
    const CLOSE: &str = "\n  ]\n}";
    if r.floats.is_empty() {
        push_exact_point(out, r);
    } else {
        // serde_json's `to_string_pretty` writes a `String` without checking the UTF-8 again
        let text = serde_json::to_string_pretty(&Results {
            results: std::slice::from_ref(r),
        })
        .expect("a point result serialises");
        debug_assert!(text.starts_with(OPEN) && text.ends_with(CLOSE));
        *out += &text[OPEN.len()..text.len() - CLOSE.len()];
    }
}

/// A point without float paths as serde's pretty printer writes it at depth 2 of the report
/// (`\n` and four spaces, then the object), without the escape scan of every string.
fn push_exact_point(out: &mut String, r: &PointResult) {
    debug_assert!(r.floats.is_empty());
    out.push_str("\n    {");
    let mut first = true;
    let mut field = |out: &mut String, key: &str, xs: &[BigRational]| {
        out.push_str(if first { "\n      \"" } else { ",\n      \"" });
        first = false;
        out.push_str(key);
        out.push_str("\": [");
        for (i, x) in xs.iter().enumerate() {
            out.push_str(if i == 0 {
                "\n        \""
            } else {
                ",\n        \""
            });
            let start = out.len();
            push_rational(out, x);
            debug_assert!(
                out[start..]
                    .bytes()
                    .all(|b| b.is_ascii_digit() || b == b'-' || b == b'/')
            );
            out.push('"');
        }
        out.push_str(if xs.is_empty() { "]" } else { "\n      ]" });
    };
    field(out, "at", &r.at);
    field(out, "point", &r.point);
    if let Some(c) = &r.cartesian {
        field(out, "cartesian", c);
    }
    if let Some(l) = &r.lambda {
        field(out, "wachspress", l);
    }
    out.push_str("\n    }");
}

/// `(a, b, c)` for people.
fn tuple(xs: &[BigRational]) -> String {
    let mut out = String::from("(");
    for (i, x) in xs.iter().enumerate() {
        if i > 0 {
            out += ", ";
        }
        push_rational(&mut out, x);
    }
    out.push(')');
    out
}

fn ulps_text(q: &Option<BigRational>) -> String {
    q.as_ref().map_or("n/a".into(), ulps_decimal)
}

/// One point's lines of the text report.
fn point_text(r: &PointResult) -> String {
    let mut out = match (&r.cartesian, &r.lambda) {
        (Some(c), Some(l)) => format!("at {} (Wachspress {})", tuple(c), tuple(l)),
        (Some(c), None) => format!("at {} (Cartesian {})", tuple(&r.at), tuple(c)),
        (None, _) => format!("at {}", tuple(&r.at)),
    };
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
    out
}

#[cfg(test)]
impl Render for EvalReport {
    fn text(&self) -> String {
        let mut out = format!("{}: {}\n", self.file, self.header);
        out.extend(self.results.iter().map(point_text));
        out
    }

    fn json(&self) -> Json {
        to_json(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::render;
    use proptest::prelude::*;
    use std::path::Path;
    use tribez::format::parse_rational;

    fn args(patch: &str, at: &[&str], cartesian: bool, float: Option<FloatChoice>) -> Args {
        Args {
            patch: Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../fixtures")
                .join(patch),
            at: at.iter().map(|s| s.to_string()).collect(),
            points: None,
            cartesian,
            homogeneous: false,
            float,
            out: OutputArgs {
                format: TextOrJson::Json,
                output: None,
            },
        }
    }

    /// The streamed JSON and the parallel text are the bytes the generic exporters write from
    /// the report's tree and its `text()`: every kind, with and without float paths.
    #[test]
    fn streamed_output_equals_the_generic_rendering() {
        let cases = [
            args(
                "finn_day30.toml",
                &["1/2,1/3,1/6", "-1,1,1", "0.1,0.3,0.6"],
                false,
                Some(FloatChoice::All),
            ),
            args(
                "finn_day30.toml",
                &["1/3,1/5"],
                true,
                Some(FloatChoice::F32),
            ),
            args("finn_day30.toml", &["0,0,1"], false, None),
            args("finn_day30.toml", &["1/3,1/5", "0,0"], true, None),
            args("beyond/pentagon_depth2.toml", &["2,2", "1,1"], true, None),
            args("beyond/octant_quartic.toml", &["1/2,1/4,1/4"], false, None),
            args(
                "beyond/octant_quartic.toml",
                &["1/2,1/4,1/4", "1,0,0"],
                false,
                Some(FloatChoice::All),
            ),
            args(
                "beyond/pentagon_depth2.toml",
                &["2,2", "1,1"],
                true,
                Some(FloatChoice::F64),
            ),
            args(
                "beyond/tetra_quadratic.toml",
                &["1/4,1/4,1/4,1/4"],
                false,
                Some(FloatChoice::All),
            ),
        ];
        for a in &cases {
            let report = evaluate(a).unwrap();
            let generic = render(&report, crate::report::Format::Json).unwrap();
            let text_args = Args {
                out: OutputArgs {
                    format: TextOrJson::Text,
                    output: None,
                },
                at: a.at.clone(),
                patch: a.patch.clone(),
                points: None,
                ..*a
            };
            let name = a.patch.display();
            assert_eq!(written(a, None).unwrap(), generic, "{name}");
            assert_eq!(written(&text_args, None).unwrap(), report.text());
            for chunk in 1..=3 {
                let json = written(a, Some(chunk)).unwrap();
                assert_eq!(json, generic, "{name} by {chunk}");
                let text = written(&text_args, Some(chunk)).unwrap();
                assert_eq!(text, report.text(), "{name} by {chunk}");
            }
        }
    }

    /// What [`write_report`] writes with `chunk` points per task, or its error and whatever it
    /// wrote before failing (which must be nothing).
    fn written(a: &Args, chunk: Option<usize>) -> Result<String, (String, Vec<u8>)> {
        let mut bytes = Vec::new();
        let mut sink = Sink::new(&mut bytes);
        let result = write_report(a, chunk, &mut sink);
        drop(sink);
        match result {
            Ok(()) => Ok(String::from_utf8(bytes).unwrap()),
            Err(e) => Err((e.to_string(), bytes)),
        }
    }

    /// A failing point in a late chunk leaves the report unwritten, and the error is the first
    /// failing point's: a point off its simplex, found by the check of every input (a kind
    /// whose evaluation cannot fail, which writes chunks as soon as they are ready), and a
    /// point where a rational patch's weight vanishes, found only by evaluating it (its chunks
    /// wait for the last one).
    #[test]
    fn a_failing_late_point_leaves_the_report_unwritten() {
        let bad_input = args(
            "finn_day30.toml",
            &[
                "1/2,1/3,1/6",
                "0,0,1",
                "1/3,1/3,1/3",
                "1/2,1/2,1/2",
                "1,1,1",
                "0,1,0",
            ],
            false,
            None,
        );
        let dir = tempfile::tempdir().unwrap();
        // W(λ) = λ0² + 2·2·λ0λ1 + 4·λ1², zero at λ = (2, −1)
        let conic = dir.path().join("conic.toml");
        std::fs::write(
            &conic,
            "degree = 2\n[control_points]\n\"2,0\" = [1, 0]\n\"1,1\" = [1, 1]\n\"0,2\" = [0, 1]\n\
             [weights]\n\"2,0\" = 1\n\"1,1\" = 2\n\"0,2\" = 4\n",
        )
        .unwrap();
        let mut vanishing = args(
            "finn_day30.toml",
            &["1/2,1/2", "0,1", "3,-2", "2,-1", "4,-3", "1,0"],
            false,
            None,
        );
        vanishing.patch = conic;
        for (a, named) in [(&bad_input, "--at 1/2,1/2,1/2"), (&vanishing, "--at 2,-1")] {
            assert!(written(a, None).is_err());
            for chunk in 1..=4 {
                let (e, bytes) = written(a, Some(chunk)).unwrap_err();
                assert!(e.starts_with(named), "{e}");
                assert!(
                    bytes.is_empty(),
                    "by {chunk}: {}",
                    String::from_utf8_lossy(&bytes)
                );
            }
        }
        // without the failing point, the report is written whole
        vanishing.at.remove(3);
        let report = written(&vanishing, Some(1)).unwrap();
        assert_eq!(report.matches("\"point\"").count(), 5, "{report}");
    }

    proptest! {
        /// The word check of `Σλ = 1` agrees with the general one whenever it says yes, and says
        /// yes for every non-negative word-sized point that sums to one.
        #[test]
        fn word_sum_check_agrees_with_the_general_check(a in 0u64..1 << 40, b in 0u64..1 << 40,
                                                        q in 1u64..1 << 40, c_neg: bool) {
            let c = i128::from(q) - i128::from(a) - i128::from(b);
            let c = if c_neg { -c } else { c };
            let p: Vec<BigRational> = [format!("{a}/{q}"), format!("{b}/{q}"), format!("{c}/{q}")]
                .iter()
                .map(|t| parse_rational(t).unwrap())
                .collect();
            let general = check_barycentric(&p, 2, "point").is_ok();
            if sums_to_one(&p, 2) {
                prop_assert!(general);
            }
            if general && c >= 0 {
                prop_assert!(sums_to_one(&p, 2));
            }
            prop_assert!(!sums_to_one(&p, 3));
        }
    }
}
