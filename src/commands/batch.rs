//! `tribez check --patch PATCH --results FILE`: judge a large batch of evaluation results from
//! another implementation, streamed in chunks (bounded memory), judged in parallel, reported in
//! input order.
//!
//! Each row: the barycentric coordinates (or `x, y, …` with `--cartesian`), then the claimed
//! coordinates of the point. CSV (`#` starts a comment line) or JSON lines (`.jsonl`, `.ndjson`:
//! one array per line; numbers or strings). With `--precision`, each number denotes the float
//! nearest its text (hex floats are exact); the claimed value is judged against the exact value
//! at the inputs as the code saw them (those floats; homogeneous form, they need not sum to 1),
//! and the error at the intended inputs (the exact text) is reported for failures and for the
//! worst row. Without a precision numbers are exact and every row is computed exactly.
//!
//! Clear rows are decided by the float filter ([`crate::certify::filter`]); only undecided ones
//! fall back to exact big-integer evaluation, and the report counts them.

use std::io::{BufRead, BufReader, IsTerminal, Write};
use std::path::Path;

use num_rational::BigRational;
use num_traits::ToPrimitive;
use rayon::prelude::*;
use serde_json::{Value as Json, json};

use super::check::Args;
use super::{CliError, Outcome};
use crate::certify::bound::{a_priori, condition};
use crate::certify::filter::{Decision, Enclosure, Filter, RowJudgement, Scratch, Thresholds};
use crate::certify::measures::{Leaf, Measures, Tolerance, as_float};
use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Precision;
use crate::io::InputError;
use crate::io::patch_file::read_patch;
use crate::number::{parse_rational, to_decimal_string};
use crate::patch::{ControlNet, Patch};
use crate::report::{Exporter, JunitCase, Render, UlpHistogram, junit_xml};

/// Rows judged per chunk (the memory bound: one chunk of lines is held at a time).
pub const CHUNK: usize = 1 << 16;
/// Failures listed in full in a report (the rest are counted).
pub const MAX_LISTED: usize = 100;

/// The algorithm a `bound` tolerance refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum AlgorithmChoice {
    /// de Casteljau (bound γ_{(m+1)n} Σ|c_i|B_i(|λ|)).
    Casteljau,
    /// The direct Bernstein form (bound γ_{N+n+m+2} Σ|c_i|B_i(|λ|)).
    Bernstein,
}

impl AlgorithmChoice {
    /// The corresponding algorithm.
    pub fn algorithm(self) -> Algorithm {
        match self {
            AlgorithmChoice::Casteljau => Algorithm::Casteljau,
            AlgorithmChoice::Bernstein => Algorithm::Bernstein,
        }
    }
}

/// One field of a row: its text and its 1-based column.
struct Field<'a> {
    text: &'a str,
    column: usize,
}

/// A parsed number: the exact value of its text, and (with a precision) the float it denotes.
#[derive(Clone, Debug)]
enum Num {
    /// `nan`, `inf` or empty: the row is a failed claim.
    NotFinite(String),
    /// A number.
    Value {
        float: f64,
        text_exact: Option<BigRational>,
    },
}

/// A failed row, in full.
#[derive(Clone, Debug)]
pub struct FailedRow {
    line: usize,
    reason: String,
    coords: Vec<FailedCoord>,
}

#[derive(Clone, Debug)]
struct FailedCoord {
    index: usize,
    decimal: String,
    hex: String,
    exact_seen: BigRational,
    seen: Measures,
    exact_intended: Option<BigRational>,
    intended: Option<Measures>,
}

/// The batch report.
pub struct BatchReport {
    file: String,
    patch: String,
    tolerance: Tolerance,
    precision: Option<Precision>,
    rows: u64,
    passed: u64,
    failed: u64,
    fell_back: u64,
    histogram: UlpHistogram,
    /// Errors of filter-decided rows enter the histogram as upper bounds.
    histogram_upper_bounds: bool,
    worst: Option<(f64, usize, Vec<FailedCoord>)>,
    failures: Vec<FailedRow>,
}

/// How one row came out.
struct RowOutcome {
    line: usize,
    pass: bool,
    fell_back: bool,
    /// The largest error in ULPs over the coordinates (upper bound if filter-decided).
    ulps: f64,
    failure: Option<String>,
    /// The parsed row (kept for failures and the worst row, to report them exactly).
    inputs: Vec<Num>,
    claimed: Vec<Num>,
}

/// Everything prepared once per patch.
struct Prepared {
    patch: Patch,
    precision: Option<Precision>,
    tolerance: Tolerance,
    algorithm: Algorithm,
    cartesian: bool,
    filter: Option<(Filter, Thresholds)>,
    seen: ExactEvaluator,
    seen_net: ControlNet<BigRational>,
    intended: ExactEvaluator,
}

fn parse_num(
    f: &Field<'_>,
    precision: Option<Precision>,
    file: &str,
    line: usize,
) -> Result<Num, InputError> {
    let t = f.text.trim().trim_matches('"');
    let lower = t.to_ascii_lowercase();
    let body = lower.trim_start_matches(['+', '-']);
    if t.is_empty() || body == "nan" || body == "inf" || body == "infinity" {
        return Ok(Num::NotFinite(if t.is_empty() {
            "empty field".into()
        } else {
            format!("`{t}`")
        }));
    }
    let bad = |msg: String| InputError {
        file: file.into(),
        line: Some(line),
        column: Some(f.column),
        key: None,
        message: msg,
    };
    match precision {
        Some(p) => {
            // Fast path: the standard library's correctly rounded decimal parsing.
            let fast = match p {
                Precision::F64 => t.parse::<f64>().ok(),
                Precision::F32 => t.parse::<f32>().ok().map(f64::from),
            };
            if let Some(x) = fast.filter(|x| x.is_finite()) {
                return Ok(Num::Value {
                    float: x,
                    text_exact: None,
                });
            }
            let q = parse_rational(t).map_err(|e| bad(format!("malformed number: {e}")))?;
            match as_float(&q, p) {
                Some(x) => Ok(Num::Value {
                    float: crate::number::round_f64(&x),
                    text_exact: Some(q),
                }),
                None => Ok(Num::NotFinite(format!("`{t}` overflows {}", p.name()))),
            }
        }
        None => {
            let q = parse_rational(t).map_err(|e| bad(format!("malformed number: {e}")))?;
            Ok(Num::Value {
                float: crate::number::round_f64(&q),
                text_exact: Some(q),
            })
        }
    }
}

impl Num {
    /// The exact value of the text (intended).
    fn text_value(&self, text: &str) -> Option<BigRational> {
        match self {
            Num::Value {
                text_exact: Some(q),
                ..
            } => Some(q.clone()),
            Num::Value { .. } => parse_rational(text).ok(),
            Num::NotFinite(_) => None,
        }
    }
}

fn split_csv(line: &str) -> Vec<Field<'_>> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, ch) in line.char_indices() {
        if ch == ',' {
            out.push(Field {
                text: &line[start..i],
                column: start + 1,
            });
            start = i + 1;
        }
    }
    out.push(Field {
        text: &line[start..],
        column: start + 1,
    });
    out
}

/// The fields of a JSON-lines row (an array of numbers, strings or nulls).
fn split_json<'a>(line: &'a str, file: &str, line_no: usize) -> Result<Vec<Field<'a>>, InputError> {
    let bad = |col: usize, msg: &str| InputError {
        file: file.into(),
        line: Some(line_no),
        column: Some(col),
        key: None,
        message: msg.into(),
    };
    let t = line.trim_end();
    let open = t
        .find('[')
        .ok_or_else(|| bad(1, "expected a JSON array `[…]`"))?;
    if !t[..open].trim().is_empty() || !t.ends_with(']') {
        return Err(bad(1, "expected a JSON array `[…]`"));
    }
    let inner = &t[open + 1..t.len() - 1];
    if inner.trim().is_empty() {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    let mut start = 0;
    for (i, ch) in inner
        .char_indices()
        .chain(std::iter::once((inner.len(), ',')))
    {
        if ch == ',' {
            let raw = &inner[start..i];
            let lead = raw.len() - raw.trim_start().len();
            let text = raw.trim();
            let text = if text == "null" { "" } else { text };
            if text.contains(['[', '{', ']', '}']) {
                return Err(bad(
                    open + 2 + start + lead,
                    "expected numbers, strings or null",
                ));
            }
            out.push(Field {
                text,
                column: open + 2 + start + lead,
            });
            start = i + 1;
        }
    }
    Ok(out)
}

impl Prepared {
    fn new(args: &Args, patch: Patch) -> Result<Self, CliError> {
        let tolerance = match &args.tolerance {
            Some(t) => {
                Tolerance::parse(t).map_err(|e| CliError::Usage(format!("--tolerance: {e}")))?
            }
            None => Tolerance::Exact,
        };
        let precision = match &args.precision {
            Some(p) => Some(
                p.parse::<Precision>()
                    .map_err(|e| CliError::Usage(format!("--precision: {e}")))?,
            ),
            None => None,
        };
        if tolerance.needs_precision() && precision.is_none() {
            return Err(CliError::Usage(format!(
                "--tolerance {tolerance} needs --precision f64 or f32"
            )));
        }
        let algorithm = args.algorithm.algorithm();
        let seen_net = match precision {
            Some(p) => {
                if patch.net.coords().iter().any(|q| as_float(q, p).is_none()) {
                    return Err(CliError::Usage(format!(
                        "a control point of the patch overflows {}",
                        p.name()
                    )));
                }
                patch.net.map(|q| as_float(q, p).unwrap_or_default())
            }
            None => patch.net.clone(),
        };
        let (m, n) = (patch.net.m(), patch.net.degree());
        let filter = precision.filter(|_| !args.cartesian).map(|p| {
            let fnet = seen_net.map(crate::number::round_f64);
            (
                Filter::new(&fnet),
                Thresholds::new(&tolerance, p, algorithm, m, n),
            )
        });
        Ok(Prepared {
            seen: ExactEvaluator::new(&seen_net),
            intended: ExactEvaluator::new(&patch.net),
            seen_net,
            patch,
            precision,
            tolerance,
            algorithm,
            cartesian: args.cartesian,
            filter,
        })
    }

    fn width(&self) -> usize {
        let m = self.patch.net.m();
        if self.cartesian { m } else { m + 1 }
    }

    /// Barycentric coordinates of an input row (exact), as seen or intended.
    fn barycentric(&self, xs: Vec<BigRational>) -> Option<Vec<BigRational>> {
        if self.cartesian {
            self.patch.domain_or_reference().barycentric(&xs).ok()
        } else {
            Some(xs)
        }
    }

    /// Judge one row exactly; `texts` are the row's fields (for the intended values).
    fn exact_row(
        &self,
        inputs: &[Num],
        claimed: &[Num],
        texts: Option<&[&str]>,
        detail: bool,
    ) -> (bool, f64, Option<String>, Vec<FailedCoord>) {
        let seen_in: Option<Vec<BigRational>> = inputs
            .iter()
            .map(|x| match x {
                Num::Value { float, text_exact } => match self.precision {
                    Some(_) => crate::number::exact_f64(*float),
                    None => text_exact.clone(),
                },
                Num::NotFinite(_) => None,
            })
            .collect();
        let Some(lambda) = seen_in.and_then(|x| self.barycentric(x)) else {
            return (false, f64::INFINITY, Some("an input is not a finite number (or the Cartesian point has no barycentric coordinates)".into()), Vec::new());
        };
        let exact = self.seen.evaluate_fast(&lambda);
        let cond = if self.tolerance.needs_condition() {
            Some(condition(&self.seen_net, &lambda))
        } else {
            None
        };
        let (m, n) = (self.patch.net.m(), self.patch.net.degree());
        let intended: Option<Vec<BigRational>> = if detail {
            texts
                .and_then(|t| {
                    inputs
                        .iter()
                        .zip(t)
                        .map(|(x, s)| x.text_value(s))
                        .collect::<Option<Vec<_>>>()
                })
                .and_then(|x| self.barycentric(x))
                .map(|l| self.intended.evaluate_fast(&l))
        } else {
            None
        };
        let mut pass = true;
        let mut worst = 0f64;
        let mut reason = None;
        let mut coords = Vec::new();
        for (c, y) in claimed.iter().enumerate() {
            let Num::Value { float, text_exact } = y else {
                pass = false;
                worst = f64::INFINITY;
                if let Num::NotFinite(what) = y {
                    reason.get_or_insert_with(|| {
                        format!(
                            "claimed coordinate {} is not a finite number: {what}",
                            c + 1
                        )
                    });
                }
                continue;
            };
            let yq = match self.precision {
                Some(_) => crate::number::exact_f64(*float).unwrap_or_default(),
                None => text_exact.clone().unwrap_or_default(),
            };
            let leaf = Leaf {
                precision: self.precision,
                condition: cond.as_ref().map(|s| s[c].clone()),
                bound: cond.as_ref().and_then(|s| {
                    a_priori(
                        self.algorithm,
                        self.precision.unwrap_or(Precision::F64),
                        m,
                        n,
                        &s[c],
                        &lambda,
                    )
                }),
            };
            let ok = self
                .tolerance
                .accepts(&yq, &exact[c], &leaf)
                .unwrap_or(false);
            let meas = Measures::new(&yq, &exact[c], self.precision.or(Some(Precision::F64)));
            let u = meas
                .ulps
                .as_ref()
                .and_then(ToPrimitive::to_f64)
                .unwrap_or(f64::INFINITY);
            worst = worst.max(u);
            if !ok {
                pass = false;
                reason.get_or_insert_with(|| {
                    format!(
                        "coordinate {} breaks tolerance `{}`: {}",
                        c + 1,
                        self.tolerance,
                        meas.text()
                    )
                });
            }
            if detail {
                let (decimal, hex) = match self.precision {
                    Some(Precision::F32) => (
                        crate::number::display_f32(*float as f32),
                        crate::number::hex_f32(*float as f32),
                    ),
                    _ => (
                        crate::number::display_f64(*float),
                        crate::number::hex_f64(*float),
                    ),
                };
                let ei = intended.as_ref().map(|v| v[c].clone());
                coords.push(FailedCoord {
                    index: c,
                    decimal,
                    hex,
                    intended: ei.as_ref().map(|e| Measures::new(&yq, e, self.precision)),
                    exact_intended: ei,
                    exact_seen: exact[c].clone(),
                    seen: meas,
                });
            }
        }
        (pass, worst, reason, coords)
    }

    /// Judge one row: filter first, exact when undecided.
    fn row(
        &self,
        line: usize,
        inputs: Vec<Num>,
        claimed: Vec<Num>,
        scratch: &mut RowScratch,
    ) -> RowOutcome {
        let finite = |xs: &[Num]| xs.iter().all(|x| matches!(x, Num::Value { .. }));
        if !finite(&inputs) || !finite(&claimed) {
            let (_, _, reason, _) = self.exact_row(&inputs, &claimed, None, false);
            return RowOutcome {
                line,
                pass: false,
                fell_back: false,
                ulps: f64::INFINITY,
                failure: reason,
                inputs,
                claimed,
            };
        }
        if let Some((filter, th)) = &self.filter {
            let float = |x: &Num| match x {
                Num::Value { float, .. } => *float,
                Num::NotFinite(_) => f64::NAN,
            };
            let (sc, enc, lambda, ys) = scratch;
            lambda.clear();
            lambda.extend(inputs.iter().map(float));
            ys.clear();
            ys.extend(claimed.iter().map(float));
            enc.resize(filter.dim(), Enclosure::default());
            let RowJudgement { decision, ulps } = filter.judge(th, lambda, ys, sc, enc);
            match decision {
                Decision::Pass => {
                    return RowOutcome {
                        line,
                        pass: true,
                        fell_back: false,
                        ulps,
                        failure: None,
                        inputs,
                        claimed,
                    };
                }
                Decision::Fail => {
                    return RowOutcome {
                        line,
                        pass: false,
                        fell_back: false,
                        ulps,
                        failure: Some(String::new()),
                        inputs,
                        claimed,
                    };
                }
                Decision::Undecided => {}
            }
        }
        let (pass, ulps, reason, _) = self.exact_row(&inputs, &claimed, None, false);
        RowOutcome {
            line,
            pass,
            fell_back: self.filter.is_some(),
            ulps,
            failure: if pass { None } else { reason },
            inputs,
            claimed,
        }
    }
}

/// Per-thread buffers of the filter: its scratch, the enclosures, the row's inputs and claimed
/// values as floats.
type RowScratch = (Scratch, Vec<Enclosure>, Vec<f64>, Vec<f64>);

/// A parsed row: its input numbers and its claimed numbers.
type Row = (Vec<Num>, Vec<Num>);

/// Up to [`CHUNK`] lines of a results file, read into one buffer (no allocation per line).
#[derive(Default)]
struct Chunk {
    /// The lines' text, one after another (each with its line ending, as read).
    text: String,
    /// Byte offset of each line's start in `text`.
    starts: Vec<usize>,
    /// 1-based number of the first line.
    first_line: usize,
}

impl Chunk {
    /// Read the next lines, numbering them from `first_line`; true at the end of the file.
    fn read(
        &mut self,
        reader: &mut impl BufRead,
        first_line: usize,
        file: &str,
    ) -> Result<bool, InputError> {
        self.text.clear();
        self.starts.clear();
        self.first_line = first_line;
        while self.starts.len() < CHUNK {
            let start = self.text.len();
            let n = reader.read_line(&mut self.text).map_err(|e| {
                InputError::file(
                    file,
                    format!("cannot read line {}: {e}", first_line + self.starts.len()),
                )
            })?;
            if n == 0 {
                return Ok(true);
            }
            self.starts.push(start);
        }
        Ok(false)
    }

    fn len(&self) -> usize {
        self.starts.len()
    }

    /// The text of line number `no` (which must be in this chunk).
    fn line(&self, no: usize) -> &str {
        let i = no - self.first_line;
        let end = self.starts.get(i + 1).copied().unwrap_or(self.text.len());
        &self.text[self.starts[i]..end]
    }

    /// `(line number, text)` for every line.
    fn lines(&self) -> impl Iterator<Item = (usize, &str)> + '_ {
        (0..self.len()).map(|i| (self.first_line + i, self.line(self.first_line + i)))
    }
}

/// Read one data line into numbers; `None` for blank and comment lines.
fn parse_line(
    line: &str,
    json_lines: bool,
    width: usize,
    dim: usize,
    precision: Option<Precision>,
    file: &str,
    line_no: usize,
) -> Result<Option<Row>, InputError> {
    let t = line.trim();
    if t.is_empty() || t.starts_with('#') {
        return Ok(None);
    }
    let fields = if json_lines {
        split_json(line, file, line_no)?
    } else {
        split_csv(line)
    };
    if fields.len() != width + dim {
        return Err(InputError {
            file: file.into(),
            line: Some(line_no),
            column: None,
            key: None,
            message: format!(
                "{} columns, expected {} ({width} input coordinates, then the {dim} claimed coordinates of the point)",
                fields.len(),
                width + dim
            ),
        });
    }
    let nums = fields
        .iter()
        .map(|f| parse_num(f, precision, file, line_no))
        .collect::<Result<Vec<_>, _>>()?;
    let mut inputs = nums;
    let claimed = inputs.split_off(width);
    Ok(Some((inputs, claimed)))
}

fn texts_of(line: &str, json_lines: bool, file: &str, line_no: usize) -> Vec<String> {
    let fields = if json_lines {
        split_json(line, file, line_no).unwrap_or_default()
    } else {
        split_csv(line)
    };
    fields
        .iter()
        .map(|f| f.text.trim().trim_matches('"').to_string())
        .collect()
}

/// Run the batch mode of `tribez check`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let patch_path = args
        .patch
        .as_ref()
        .expect("clap requires --patch with --results");
    let results = args.results.as_ref().expect("checked by the caller");
    let patch = read_patch(patch_path)?;
    let prepared = Prepared::new(args, patch)?;
    let report = check_file(&prepared, results, &patch_path.display().to_string())?;
    let success = report.failed == 0;
    if let Some(path) = &args.junit {
        super::write_atomically(path, report.junit().as_bytes())?;
    }
    let worst = report.worst_errors(prepared.algorithm);
    if let Some(path) = &args.record_baseline {
        super::baseline::record(path, &worst)?;
    }
    let mut regressions = Vec::new();
    if let Some(path) = &args.baseline {
        regressions = super::baseline::compare(path, &worst)?;
    }
    let mut outcome =
        Outcome::rendered(&report, args.out.format, success && regressions.is_empty())?;
    for r in regressions {
        outcome.output += &format!("baseline regression: {r}\n");
    }
    Ok(outcome)
}

fn check_file(p: &Prepared, path: &Path, patch_name: &str) -> Result<BatchReport, CliError> {
    let file = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let json_lines = matches!(ext.as_str(), "jsonl" | "ndjson" | "json");
    let reader = std::fs::File::open(path)
        .map_err(|e| InputError::file(&file, format!("cannot read: {e}")))?;
    let mut reader = BufReader::with_capacity(1 << 20, reader);
    let (width, dim) = (p.width(), p.patch.net.dim());
    let progress = std::io::stderr().is_terminal();
    let mut report = BatchReport {
        file: file.clone(),
        patch: patch_name.into(),
        tolerance: p.tolerance.clone(),
        precision: p.precision,
        rows: 0,
        passed: 0,
        failed: 0,
        fell_back: 0,
        histogram: UlpHistogram::default(),
        histogram_upper_bounds: p.filter.is_some(),
        worst: None,
        failures: Vec::new(),
    };
    let mut worst_row: Option<(f64, usize, Vec<Num>, Vec<Num>)> = None;
    // Chunks of CHUNK lines: the next one is read (one thread) while the current one is judged
    // (the others), so reading overlaps the work and memory stays bounded.
    let mut chunk = Chunk::default();
    let mut next = Chunk::default();
    let mut eof = chunk.read(&mut reader, 1, &file)?;
    loop {
        let (read, outcomes) = rayon::join(
            || {
                if eof {
                    Ok(true)
                } else {
                    next.read(&mut reader, chunk.first_line + chunk.len(), &file)
                }
            },
            || -> Result<Vec<Option<RowOutcome>>, InputError> {
                chunk
                    .lines()
                    .collect::<Vec<_>>()
                    .par_iter()
                    .map_init(
                        RowScratch::default,
                        |scratch, (no, text)| -> Result<Option<RowOutcome>, InputError> {
                            let Some((inputs, claimed)) =
                                parse_line(text, json_lines, width, dim, p.precision, &file, *no)?
                            else {
                                return Ok(None);
                            };
                            Ok(Some(p.row(*no, inputs, claimed, scratch)))
                        },
                    )
                    .collect()
            },
        );
        let outcomes = outcomes?;
        let next_eof = read?;
        for o in outcomes.into_iter().flatten() {
            report.rows += 1;
            report.histogram.add(o.ulps);
            if o.fell_back {
                report.fell_back += 1;
            }
            if worst_row.as_ref().is_none_or(|w| o.ulps > w.0) && o.ulps.is_finite() {
                worst_row = Some((o.ulps, o.line, o.inputs.clone(), o.claimed.clone()));
            }
            if o.pass {
                report.passed += 1;
            } else {
                report.failed += 1;
                if report.failures.len() < MAX_LISTED {
                    let text = chunk.line(o.line);
                    let texts = texts_of(text, json_lines, &file, o.line);
                    let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
                    let (_, _, reason, coords) =
                        p.exact_row(&o.inputs, &o.claimed, Some(&refs), true);
                    let reason = o
                        .failure
                        .filter(|r| !r.is_empty())
                        .or(reason)
                        .unwrap_or_else(|| "fails".into());
                    report.failures.push(FailedRow {
                        line: o.line,
                        reason,
                        coords,
                    });
                }
            }
        }
        if progress {
            eprint!(
                "\rtribez check: {} rows, {} failed",
                report.rows, report.failed
            );
            let _ = std::io::stderr().flush();
        }
        if eof {
            break;
        }
        std::mem::swap(&mut chunk, &mut next);
        eof = next_eof;
    }
    if progress {
        eprintln!();
    }
    if report.rows == 0 {
        return Err(InputError::file(file, "no result rows").into());
    }
    if let Some((_, line, inputs, claimed)) = worst_row {
        // Recompute the worst row exactly (its filter figure is an upper bound).
        let mut reader = BufReader::new(
            std::fs::File::open(path)
                .map_err(|e| InputError::file(&file, format!("cannot read: {e}")))?,
        );
        let mut text = String::new();
        for _ in 0..line {
            text.clear();
            let _ = reader.read_line(&mut text);
        }
        let texts = texts_of(&text, json_lines, &file, line);
        let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
        let (_, u, _, coords) = p.exact_row(&inputs, &claimed, Some(&refs), true);
        report.worst = Some((u, line, coords));
    }
    Ok(report)
}

impl BatchReport {
    /// The worst error for baselines: (eval, claimed, precision).
    fn worst_errors(&self, _algorithm: Algorithm) -> Vec<super::baseline::Worst> {
        self.worst
            .iter()
            .map(|(u, line, _)| super::baseline::Worst {
                op: "eval".into(),
                algorithm: "claimed".into(),
                precision: self.precision.map_or("exact", |p| p.name()).into(),
                ulps: *u,
                at: format!("{}:{line}", self.file),
            })
            .collect()
    }
}

fn coord_text(c: &FailedCoord) -> String {
    let mut s = format!(
        "claimed {} = {}; exact at the inputs as seen {} ({})",
        c.decimal,
        c.hex,
        to_decimal_string(&c.exact_seen, 20),
        c.seen.text()
    );
    if let (Some(e), Some(m)) = (&c.exact_intended, &c.intended) {
        s += &format!(
            "; at the intended inputs {} ({})",
            to_decimal_string(e, 20),
            m.text()
        );
    }
    s
}

fn coord_json(c: &FailedCoord) -> Json {
    json!({
        "coordinate": c.index,
        "claimed": {"decimal": c.decimal, "hex": c.hex},
        "exact_at_inputs_as_seen": c.exact_seen.to_string(),
        "error_at_inputs_as_seen": c.seen.to_json(),
        "exact_at_intended_inputs": c.exact_intended.as_ref().map(ToString::to_string),
        "error_at_intended_inputs": c.intended.as_ref().map(Measures::to_json),
    })
}

impl Render for BatchReport {
    fn text(&self) -> String {
        let mut out = format!(
            "{}: {} rows checked against {} (tolerance {}, {})\n",
            self.file,
            self.rows,
            self.patch,
            self.tolerance,
            self.precision
                .map_or("exact numbers".to_string(), |p| format!(
                    "each number the nearest {}",
                    p.name()
                ))
        );
        if self.histogram_upper_bounds {
            out += &format!(
                "  passed {}, failed {}; decided by the float filter {}, fell back to exact arithmetic {}\n",
                self.passed,
                self.failed,
                self.rows - self.fell_back,
                self.fell_back
            );
        } else {
            out += &format!(
                "  passed {}, failed {}; every row computed exactly (no float filter without --precision, or with --cartesian)\n",
                self.passed, self.failed
            );
        }
        if !self.histogram.is_empty() {
            out += &format!(
                "\nErrors in ULPs against the exact value at the inputs as the code saw them{}\n",
                if self.histogram_upper_bounds {
                    " (filter-decided rows: an upper bound)"
                } else {
                    ""
                }
            );
            out += &self.histogram.text();
        }
        if let Some((u, line, coords)) = &self.worst {
            out += &format!(
                "\nworst row (largest error bound; filter-decided rows are bounded, not measured): line {line}, exactly {} ulp\n",
                to_decimal_string(&BigRational::from_float(*u).unwrap_or_default(), 4)
            );
            for c in coords {
                out += &format!("  [{}] {}\n", c.index, coord_text(c));
            }
        }
        if !self.failures.is_empty() {
            out += "\nFailures\n";
            for f in &self.failures {
                out += &format!("  line {}: {}\n", f.line, f.reason);
                for c in &f.coords {
                    out += &format!("    [{}] {}\n", c.index, coord_text(c));
                }
            }
            if self.failed as usize > self.failures.len() {
                out += &format!(
                    "  … and {} more\n",
                    self.failed as usize - self.failures.len()
                );
            }
        }
        out += &format!(
            "\n{} claim{}: {} passed, {} failed\n",
            self.rows,
            if self.rows == 1 { "" } else { "s" },
            self.passed,
            self.failed
        );
        out
    }

    fn json(&self) -> Json {
        json!({
            "results": self.file,
            "patch": self.patch,
            "tolerance": self.tolerance.text(),
            "precision": self.precision.map(|p| p.name()),
            "summary": {
                "claims": self.rows, "passed": self.passed, "failed": self.failed,
                "filter_used": self.histogram_upper_bounds,
                "decided_by_filter": if self.histogram_upper_bounds { self.rows - self.fell_back } else { 0 }, "fell_back_to_exact": self.fell_back,
                "ulp_histogram": self.histogram.json(), "histogram_upper_bounds": self.histogram_upper_bounds,
            },
            "worst": self.worst.as_ref().map(|(u, line, coords)| json!({"ulps": u, "line": line, "coordinates": coords.iter().map(coord_json).collect::<Vec<_>>()})),
            "failures": self.failures.iter().map(|f| json!({"line": f.line, "reason": f.reason, "coordinates": f.coords.iter().map(coord_json).collect::<Vec<_>>()})).collect::<Vec<_>>(),
            "failures_not_listed": self.failed as usize - self.failures.len(),
        })
    }
}

impl Exporter for BatchReport {
    fn junit(&self) -> String {
        let mut failures: Vec<String> = self
            .failures
            .iter()
            .map(|f| format!("line {}: {}", f.line, f.reason))
            .collect();
        if self.failed as usize > self.failures.len() {
            failures.push(format!(
                "… and {} more",
                self.failed as usize - self.failures.len()
            ));
        }
        junit_xml(
            "check",
            &[JunitCase {
                name: self.file.clone(),
                checks: self.rows as usize,
                failures,
            }],
        )
    }
}
