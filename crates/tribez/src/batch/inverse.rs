//! Batches of another implementation's answers to inverse problems, judged (`tribez check
//! --patch PATCH --locate-results FILE` and `--ray-results FILE`): each row is a query, then the
//! parameters the implementation claims for it, judged against the exact answer (real algebraic
//! numbers) exactly as an `op = "locate"` or `op = "ray"` claim is
//! ([`crate::claims::ops::inverse::judge_answer`]: the same pairing, tolerances, missed and
//! extra solutions).
//!
//! Rows (CSV, JSON lines or one JSON array of rows, as for [`super::BatchChecker`]):
//!
//! * **locate** (a planar triangle patch): `x, y`, then the claimed `(s, t)` pairs, as many as
//!   the code found: `x, y, s, t` for one (what `bezier`'s `Triangle.locate` returns), `x, y,
//!   s1, t1, s2, t2` for two, and `x, y, none` (or just `x, y`) for none. The exact answer is
//!   every `(s, t)` of the closed triangle `s, t ≥ 0, s + t ≤ 1` that maps to the point.
//! * **ray** (a triangle patch in ℝ³, or a functional patch as its graph): `ox, oy, oz, dx, dy,
//!   dz`, then the claimed FIRST hit `tau, s, t` (the point `o + tau·d`, the smallest `tau ≥ 0`
//!   where the ray meets the patch over its closed triangle, a touch counting as a hit), or
//!   `none` (or nothing) for a ray that misses.
//!
//! `none` may be written `none`, `null`, `""` or JSON `null`, as the only claimed field. `nan`,
//! `inf` or an empty field among the numbers is a failed row (a number that is not finite).
//!
//! With a precision, every number denotes the float nearest its text (hex floats are exact), the
//! patch is rounded likewise, and the exact answer is that of the query and patch as the float
//! code saw them. Rows are streamed in chunks of [`super::CHUNK`] (bounded memory), each line at
//! most `MAX_ROW_BYTES` (the row reader's cap) and its number of fields capped before it is split, and
//! judged in parallel; the report lists the first [`MAX_LISTED`] failures in line order.

use std::io::{BufReader, Read};

use num_rational::BigRational;
use num_traits::Zero;
use rayon::prelude::*;
use serde::Serialize;

use super::parse::{Chunk, Field, Format, Num, RowReader, each_chunk, parse_num};
use super::parse::{split_csv, split_json_row};
use super::{BatchError, MAX_LISTED, ResultsChecker};
use crate::algebraic::{check_locate_patch, check_ray_patch};
use crate::certify::measures::{Measures, Tolerance};
use crate::claims::ops::seen;
use crate::float::Precision;
use crate::io::{InputError, InverseProblem};
use crate::judge_inverse::{ExactNumber, InverseFinding, InverseQuery, MAX_CLAIMED, judge_answer};
use crate::patch_type::Patch;

type Q = BigRational;

/// Which inverse problem the rows answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum InverseKind {
    /// `x, y, s, t, …`: the parameters of a point of a planar triangle patch.
    Locate,
    /// `ox, oy, oz, dx, dy, dz, tau, s, t`: the first hit of a ray.
    Ray,
}

impl InverseKind {
    /// `locate` or `ray`.
    pub fn name(self) -> &'static str {
        match self {
            InverseKind::Locate => "locate",
            InverseKind::Ray => "ray",
        }
    }

    /// Numbers of the query.
    pub fn query_width(self) -> usize {
        match self {
            InverseKind::Locate => 2,
            InverseKind::Ray => 6,
        }
    }

    /// Numbers of one claimed tuple.
    pub fn tuple_width(self) -> usize {
        match self {
            InverseKind::Locate => 2,
            InverseKind::Ray => 3,
        }
    }

    /// The most claimed tuples a row may have.
    pub fn max_tuples(self) -> usize {
        match self {
            InverseKind::Locate => MAX_CLAIMED,
            InverseKind::Ray => 1,
        }
    }

    /// The row layout, for messages.
    pub fn layout(self) -> &'static str {
        match self {
            InverseKind::Locate => "`x, y`, then the claimed (s, t) pairs, or `none`",
            InverseKind::Ray => {
                "`ox, oy, oz, dx, dy, dz`, then the claimed first hit `tau, s, t`, or `none`"
            }
        }
    }

    /// The most fields a row may have (checked before the row is split).
    fn max_fields(self) -> usize {
        self.query_width() + self.tuple_width() * self.max_tuples()
    }
}

/// How every row of an inverse batch is judged.
#[derive(Clone, Debug)]
pub struct InverseBatchOptions {
    /// Locate or ray rows.
    pub kind: InverseKind,
    /// The tolerance every claimed parameter is judged with (against its algebraic value):
    /// `exact`, `ulps=N`, `abs=E`, `rel=E`, `correctly_rounded`, `faithful`.
    pub tolerance: Tolerance,
    /// Each number denotes the nearest float of this precision; `None`: numbers are exact.
    pub precision: Option<Precision>,
    /// Locate: the exact answer is every parameter point of the whole plane that maps to the
    /// point (`tribez locate --anywhere`), not only those of the closed triangle. Code that
    /// extrapolates (Newton's method left to run outside the triangle) is judged with it.
    /// Refused for ray rows.
    pub anywhere: bool,
}

/// A row as read: where it is, its query and its claimed tuples (numbers and their texts).
#[derive(Clone, Debug)]
pub struct InverseRow {
    /// The line the row starts on (1-based).
    pub line: usize,
    query: Vec<Num>,
    tuples: Vec<Vec<Num>>,
    query_text: Vec<String>,
    tuple_text: Vec<Vec<String>>,
}

/// One disagreement of a failed row (a finding of
/// [`crate::claims::ops::inverse::judge_answer`]).
#[derive(Clone, Debug, Serialize)]
pub struct RowMismatch {
    /// `missed`, `extra`, `coordinate`, `infinite` or `not_finite`.
    pub kind: &'static str,
    /// Where: `solution 1`, `[0]` (the first claimed tuple), `[0][1]` (its second coordinate).
    pub path: String,
    /// The claimed tuple, as text.
    pub claimed: String,
    /// The exact solution, as text (algebraic numbers with their polynomial and interval).
    pub exact: String,
    /// Why it is not accepted.
    pub reason: String,
    /// A coordinate's error against its algebraic value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub measures: Option<Measures>,
}

/// A failed row, in full.
#[derive(Clone, Debug, Serialize)]
pub struct InverseFailedRow {
    /// The line the row starts on.
    pub line: usize,
    /// The query as written.
    pub query: Vec<String>,
    /// The claimed tuples as written.
    pub claimed: Vec<Vec<String>>,
    /// The exact solutions for the query as seen (ray: the first hit only); empty for a row
    /// with a number that is not finite.
    pub exact: Vec<Vec<ExactNumber>>,
    /// What is wrong.
    pub mismatches: Vec<RowMismatch>,
}

/// The report of an inverse batch.
#[derive(Clone, Debug, Serialize)]
pub struct InverseBatchReport {
    /// The results file.
    pub results: String,
    /// The patch's name.
    pub patch: String,
    /// Locate or ray rows.
    pub kind: InverseKind,
    /// The tolerance.
    #[serde(serialize_with = "tolerance_text")]
    pub tolerance: Tolerance,
    /// The precision of the numbers (`None`: exact numbers).
    #[serde(serialize_with = "precision_name")]
    pub precision: Option<Precision>,
    /// Locate over the whole plane ([`InverseBatchOptions::anywhere`]).
    pub anywhere: bool,
    /// Rows checked.
    pub checked: u64,
    /// Rows whose claim holds.
    pub passed: u64,
    /// Rows whose claim fails.
    pub failed: u64,
    /// Exact solutions no claimed tuple was paired with (over all rows).
    pub missed: u64,
    /// Claimed tuples paired with no exact solution.
    pub extra: u64,
    /// Paired coordinates that break the tolerance.
    pub out_of_tolerance: u64,
    /// Rows whose query has infinitely many solutions.
    pub infinite: u64,
    /// Rows with a number that is not finite.
    pub not_finite: u64,
    /// The first failed rows (at most [`MAX_LISTED`]), in line order.
    pub failures: Vec<InverseFailedRow>,
    /// Failed rows not listed.
    pub failures_not_listed: u64,
}

impl InverseBatchReport {
    /// The report for people: the counts, then each listed failure with what is wrong (a missed
    /// solution shown exactly: its polynomial, isolating interval and decimal value).
    pub fn text(&self) -> String {
        let mut out = format!(
            "{}: {} {} rows checked against {}{} (tolerance {}, {})\n",
            self.results,
            self.checked,
            self.kind.name(),
            self.patch,
            if self.anywhere {
                ", parameters anywhere in the plane"
            } else {
                ""
            },
            self.tolerance,
            self.precision.map_or("exact numbers".to_string(), |p| format!(
                "each number the nearest {}; the exact answer is that of the query and patch as the code saw them",
                p.name()
            ))
        );
        out += &format!("  passed {}, failed {}", self.passed, self.failed);
        let parts: Vec<String> = [
            (self.missed, "missed solutions"),
            (self.extra, "extra tuples"),
            (self.out_of_tolerance, "coordinates out of tolerance"),
            (self.infinite, "rows with infinitely many solutions"),
            (self.not_finite, "rows with a number that is not finite"),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, what)| format!("{n} {what}"))
        .collect();
        if !parts.is_empty() {
            out += &format!(" ({})", parts.join(", "));
        }
        out += "\n";
        if !self.failures.is_empty() {
            out += "\nFailures\n";
            for f in &self.failures {
                let claimed = if f.claimed.is_empty() {
                    "none".to_string()
                } else {
                    f.claimed
                        .iter()
                        .map(|t| format!("({})", t.join(", ")))
                        .collect::<Vec<_>>()
                        .join(" ")
                };
                out += &format!(
                    "  line {}: ({}) claimed {}\n",
                    f.line,
                    f.query.join(", "),
                    claimed
                );
                for m in &f.mismatches {
                    out += &format!("    {}\n", m.reason);
                }
            }
            if self.failures_not_listed > 0 {
                out += &format!("  … and {} more\n", self.failures_not_listed);
            }
        }
        out
    }
}

fn tolerance_text<S: serde::Serializer>(t: &Tolerance, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&t.text())
}

fn precision_name<S: serde::Serializer>(p: &Option<Precision>, s: S) -> Result<S::Ok, S::Error> {
    match p {
        Some(p) => s.serialize_str(p.name()),
        None => s.serialize_none(),
    }
}

/// A row judged.
struct RowOutcome {
    failure: Option<InverseFailedRow>,
    counts: [u64; 5],
}

/// Judges batches of inverse answers about one patch.
pub struct InverseBatchChecker {
    options: InverseBatchOptions,
    /// The patch as the code saw it (rounded to the precision).
    patch: Patch,
}

impl InverseBatchChecker {
    /// Prepare to judge rows about `patch` (named `patch_name` in errors). Errors: a tolerance
    /// that needs a precision without one, or an evaluation's tolerance (`cond`, `bound`); a
    /// patch the problem does not take (locate: a planar Bézier or rational triangle patch; ray:
    /// a triangle patch in ℝ³ or a functional one), or that overflows the precision.
    pub fn new(
        patch: Patch,
        patch_name: &str,
        options: &InverseBatchOptions,
    ) -> Result<Self, BatchError> {
        let tolerance = options.tolerance.clone();
        if tolerance.needs_condition() {
            return Err(BatchError::ToleranceEvalOnly { tolerance });
        }
        if tolerance.needs_precision() && options.precision.is_none() {
            return Err(BatchError::ToleranceNeedsPrecision { tolerance });
        }
        if options.anywhere && options.kind == InverseKind::Ray {
            return Err(BatchError::AnywhereForRays);
        }
        let patch = match options.precision {
            Some(p) => Patch::from(seen::any_patch(
                &seen::FileBlame(patch_name),
                patch.as_any(),
                p,
            )?),
            None => patch,
        };
        match options.kind {
            InverseKind::Locate => check_locate_patch(&patch),
            InverseKind::Ray => check_ray_patch(&patch),
        }
        .map_err(|error| BatchError::InversePatch {
            patch: patch_name.into(),
            error,
        })?;
        Ok(InverseBatchChecker {
            options: options.clone(),
            patch,
        })
    }

    /// Judge one row: the exact answer for its query as seen, then its claimed tuples
    /// ([`crate::claims::ops::inverse::judge_answer`]). Errors (naming the file and line): a ray
    /// whose direction is zero, a query the exact computation refuses (its caps).
    pub fn judge_row(&self, row: &InverseRow, file: &str) -> Result<bool, InputError> {
        self.judge(row, file).map(|o| o.failure.is_none())
    }

    fn judge(&self, row: &InverseRow, file: &str) -> Result<RowOutcome, InputError> {
        let o = &self.options;
        let failed = |mismatches: Vec<RowMismatch>, exact: Vec<Vec<ExactNumber>>| {
            Some(InverseFailedRow {
                line: row.line,
                query: row.query_text.clone(),
                claimed: row.tuple_text.clone(),
                exact,
                mismatches,
            })
        };
        let value = |n: &Num| -> Option<Q> {
            match n {
                Num::Value { float, text_exact } => match o.precision {
                    Some(_) => crate::number::exact_f64(*float),
                    None => text_exact.clone(),
                },
                Num::NotFinite(..) => None,
            }
        };
        // numbers that are not finite: a failed row, nothing to compute
        let not_finite: Vec<RowMismatch> = row
            .query
            .iter()
            .map(|n| ("query", n))
            .chain(
                row.tuples
                    .iter()
                    .flatten()
                    .map(|n| ("claimed parameter", n)),
            )
            .filter_map(|(what, n)| match n {
                Num::NotFinite(t, _) => Some(RowMismatch {
                    kind: "not_finite",
                    path: what.into(),
                    claimed: t.clone(),
                    exact: String::new(),
                    reason: format!("a {what} is not a finite number: {t}"),
                    measures: None,
                }),
                Num::Value { .. } => None,
            })
            .collect();
        if !not_finite.is_empty() {
            return Ok(RowOutcome {
                failure: failed(not_finite, Vec::new()),
                counts: [0, 0, 0, 0, 1],
            });
        }
        let q: Vec<Q> = row.query.iter().filter_map(value).collect();
        let tuples: Vec<Vec<Q>> = row
            .tuples
            .iter()
            .map(|t| t.iter().filter_map(value).collect())
            .collect();
        let at = |problem: InverseProblem| InputError::at(file, Some(row.line), None, problem);
        let query = match o.kind {
            InverseKind::Locate => InverseQuery::Locate {
                patch: std::borrow::Cow::Borrowed(&self.patch),
                point: [q[0].clone(), q[1].clone()],
                anywhere: o.anywhere,
            },
            InverseKind::Ray => {
                let direction = [q[3].clone(), q[4].clone(), q[5].clone()];
                if direction.iter().all(Zero::is_zero) {
                    return Err(at(InverseProblem::ZeroDirection));
                }
                InverseQuery::Ray {
                    patch: std::borrow::Cow::Borrowed(&self.patch),
                    origin: [q[0].clone(), q[1].clone(), q[2].clone()],
                    direction,
                }
            }
        };
        let mut answer = query.answer().map_err(|e| at(InverseProblem::from(e)))?;
        if o.kind == InverseKind::Ray {
            // the row claims the first hit only (the hits are in the order of tau)
            answer.solutions.truncate(1);
        }
        let found = judge_answer(
            Some(tuples.as_slice()),
            tuples.len(),
            &answer,
            &o.tolerance,
            o.precision,
        )
        .map_err(|e| InputError::at(file, Some(row.line), None, e))?;
        if found.is_empty() {
            return Ok(RowOutcome {
                failure: None,
                counts: [0; 5],
            });
        }
        let mut counts = [0u64; 5];
        let mismatches = found
            .into_iter()
            .map(|(f, m)| {
                let (kind, slot, measures) = match f {
                    InverseFinding::Missed { .. } => ("missed", 0, None),
                    InverseFinding::Extra { .. } => ("extra", 1, None),
                    InverseFinding::Coordinate { measures, .. } => {
                        ("coordinate", 2, Some(measures))
                    }
                    // a row's count is that of its tuples, so never a bare count
                    InverseFinding::Count { .. } | InverseFinding::Infinite { .. } => {
                        ("infinite", 3, None)
                    }
                };
                counts[slot] += 1;
                RowMismatch {
                    kind,
                    path: m.path,
                    claimed: m.claimed,
                    exact: m.exact,
                    reason: m.reason,
                    measures,
                }
            })
            .collect();
        counts[3] = counts[3].min(1);
        Ok(RowOutcome {
            failure: failed(mismatches, answer.solutions),
            counts,
        })
    }
}

/// Rows `query…, claimed tuples…` of [`InverseBatchOptions::kind`]; `subject` names the patch in
/// the report.
impl ResultsChecker for InverseBatchChecker {
    type Report = InverseBatchReport;

    fn check_reader<R: Read + Send>(
        &self,
        reader: R,
        format: Format,
        file: &str,
        subject: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<InverseBatchReport, BatchError> {
        let o = &self.options;
        let mut rows = RowReader::new(BufReader::with_capacity(1 << 20, reader), format, file);
        let mut report = InverseBatchReport {
            results: file.into(),
            patch: subject.into(),
            kind: o.kind,
            tolerance: o.tolerance.clone(),
            precision: o.precision,
            anywhere: o.anywhere,
            checked: 0,
            passed: 0,
            failed: 0,
            missed: 0,
            extra: 0,
            out_of_tolerance: 0,
            infinite: 0,
            not_finite: 0,
            failures: Vec::new(),
            failures_not_listed: 0,
        };
        each_chunk(&mut rows, file, progress, |chunk| {
            let outcomes: Vec<Result<Option<RowOutcome>, InputError>> = chunk
                .par_iter()
                .map(|&(line, col, text)| {
                    let Some(row) =
                        parse_inverse_row(o.kind, format, text, line, col, o.precision, file)?
                    else {
                        return Ok(None);
                    };
                    self.judge(&row, file).map(Some)
                })
                .collect();
            for outcome in outcomes {
                let Some(r) = outcome? else { continue };
                report.checked += 1;
                for (n, k) in [
                    &mut report.missed,
                    &mut report.extra,
                    &mut report.out_of_tolerance,
                    &mut report.infinite,
                    &mut report.not_finite,
                ]
                .into_iter()
                .zip(r.counts)
                {
                    *n += k;
                }
                match r.failure {
                    None => report.passed += 1,
                    Some(f) => {
                        report.failed += 1;
                        if report.failures.len() < MAX_LISTED {
                            report.failures.push(f);
                        } else {
                            report.failures_not_listed += 1;
                        }
                    }
                }
            }
            Ok((report.checked, report.failed))
        })?;
        Ok(report)
    }
}

/// Is this claimed field the word for "no solution"?
fn is_none(text: &str) -> bool {
    let t = text.trim().trim_matches('"').trim();
    t.is_empty() || t.eq_ignore_ascii_case("none") || t.eq_ignore_ascii_case("null")
}

/// Read one row of an inverse batch (`None` for blank and comment lines). `line` and `col`
/// locate the row's start. Errors name the file and line: too many fields (counted before the
/// row is split), a number of fields that is not the query and whole tuples, a malformed
/// number.
pub fn parse_inverse_row(
    kind: InverseKind,
    format: Format,
    text: &str,
    line: usize,
    col: usize,
    precision: Option<Precision>,
    file: &str,
) -> Result<Option<InverseRow>, InputError> {
    let t = text.trim();
    if t.is_empty() || (format != Format::JsonArray && t.starts_with('#')) {
        return Ok(None);
    }
    let at = |problem: InverseProblem| {
        InputError::at(
            file,
            Some(line),
            (format == Format::JsonArray).then_some(col),
            problem,
        )
    };
    // every field but the last ends with a comma (numbers never contain one): cap the fields
    // before splitting the row into them
    let upper = t.bytes().filter(|&b| b == b',').count() + 1;
    if upper > kind.max_fields() {
        return Err(at(match kind {
            InverseKind::Locate => InverseProblem::TooManyClaimed {
                count: upper
                    .saturating_sub(kind.query_width())
                    .div_ceil(kind.tuple_width()),
                limit: kind.max_tuples(),
            },
            InverseKind::Ray => InverseProblem::RowColumns {
                found: upper,
                kind: kind.name(),
                layout: kind.layout(),
            },
        }));
    }
    let fields: Vec<(usize, Field<'_>)> = match format {
        Format::JsonArray => split_json_row(text, line, col, file)?,
        Format::JsonLines => split_json_row(text, line, 1, file)?,
        Format::Csv => split_csv(text).into_iter().map(|f| (line, f)).collect(),
    };
    let (qw, tw) = (kind.query_width(), kind.tuple_width());
    let rest = fields.len().saturating_sub(qw);
    let none = rest == 1 && is_none(fields[qw].1.text);
    let whole = rest.is_multiple_of(tw) && rest / tw <= kind.max_tuples();
    if fields.len() < qw || !(none || whole) {
        return Err(at(InverseProblem::RowColumns {
            found: fields.len(),
            kind: kind.name(),
            layout: kind.layout(),
        }));
    }
    let nums = |fs: &[(usize, Field<'_>)]| -> Result<(Vec<Num>, Vec<String>), InputError> {
        let mut nums = Vec::with_capacity(fs.len());
        let mut texts = Vec::with_capacity(fs.len());
        for (l, f) in fs {
            nums.push(parse_num(f, precision, file, *l)?);
            texts.push(f.text.trim().trim_matches('"').to_string());
        }
        Ok((nums, texts))
    };
    let (query, query_text) = nums(&fields[..qw])?;
    let (mut tuples, mut tuple_text) = (Vec::new(), Vec::new());
    if !none {
        for chunk in fields[qw..].chunks(tw) {
            let (n, t) = nums(chunk)?;
            tuples.push(n);
            tuple_text.push(t);
        }
    }
    Ok(Some(InverseRow {
        line,
        query,
        tuples,
        query_text,
        tuple_text,
    }))
}

/// Fuzzing entry (see [`crate::fuzz`]): every row of `data` read as an inverse results file and
/// parsed; the first byte chooses the kind (locate, ray), the format (CSV, JSON lines, JSON
/// array) and the precision (none, f64, f32). Errors are fine; a panic or a hang is the bug.
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub(crate) fn fuzz_inverse_rows(data: &[u8]) {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let kind = [InverseKind::Locate, InverseKind::Ray][usize::from(first) % 2];
    let format = [Format::Csv, Format::JsonLines, Format::JsonArray][usize::from(first / 2) % 3];
    let precision = [None, Some(Precision::F64), Some(Precision::F32)][usize::from(first / 6) % 3];
    // a small buffer, so that rows straddle refills
    let reader = std::io::BufReader::with_capacity(7, rest);
    let mut rows = RowReader::new(reader, format, "fuzz");
    let mut chunk = Chunk::default();
    loop {
        let Ok(eof) = rows.read(&mut chunk) else {
            return;
        };
        for (line, col, text) in chunk.rows() {
            let _ = parse_inverse_row(kind, format, text, line, col, precision, "fuzz");
        }
        if eof {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn anywhere_is_for_locate_rows_only() {
        let flat = Patch::from_toml(
            "degree = 1\n[control_points]\n\"1,0,0\" = [0, 0, 0]\n\"0,1,0\" = [1, 0, 0]\n\"0,0,1\" = [0, 1, 0]\n",
        )
        .unwrap();
        let options = |kind, anywhere| InverseBatchOptions {
            kind,
            tolerance: Tolerance::parse("exact").unwrap(),
            precision: None,
            anywhere,
        };
        let refused = InverseBatchChecker::new(flat.clone(), "p", &options(InverseKind::Ray, true));
        assert!(matches!(refused, Err(BatchError::AnywhereForRays)));
        assert!(InverseBatchChecker::new(flat, "p", &options(InverseKind::Ray, false)).is_ok());
    }

    fn row(kind: InverseKind, text: &str) -> Result<Option<InverseRow>, InputError> {
        parse_inverse_row(kind, Format::Csv, text, 7, 1, None, "r.csv")
    }

    #[test]
    fn rows_are_the_query_then_whole_tuples_or_none() {
        let r = row(InverseKind::Locate, "1/2,1/4,0.25,0.5")
            .unwrap()
            .unwrap();
        assert_eq!((r.query.len(), r.tuples.len()), (2, 1));
        let r = row(InverseKind::Locate, "1,1,1,0,0,1").unwrap().unwrap();
        assert_eq!(r.tuples.len(), 2);
        for none in [
            "1,2",
            "1,2,none",
            "1,2,NONE",
            "1,2,\"none\"",
            "1,2,",
            "1,2,null",
        ] {
            let r = row(InverseKind::Locate, none).unwrap().unwrap();
            assert!(r.tuples.is_empty(), "{none}");
        }
        assert!(row(InverseKind::Locate, "# comment").unwrap().is_none());
        assert!(row(InverseKind::Ray, "  ").unwrap().is_none());
        let r = row(InverseKind::Ray, "0,0,1,0,0,-1,1,0,0")
            .unwrap()
            .unwrap();
        assert_eq!((r.query.len(), r.tuples.len()), (6, 1));
        let r = row(InverseKind::Ray, "0,0,1,0,0,-1,none").unwrap().unwrap();
        assert!(r.tuples.is_empty());
        // JSON null as the only claimed field
        let r = parse_inverse_row(
            InverseKind::Locate,
            Format::JsonLines,
            "[0.5, \"1/4\", null]",
            3,
            1,
            None,
            "r.jsonl",
        )
        .unwrap()
        .unwrap();
        assert!(r.tuples.is_empty());
    }

    #[test]
    fn bad_rows_name_the_file_and_line() {
        for (kind, text, says) in [
            (InverseKind::Locate, "1,2,3", "3 columns"),
            (InverseKind::Locate, "1", "1 columns"),
            (InverseKind::Ray, "0,0,1,0,0,-1,1,0", "8 columns"),
            (InverseKind::Ray, "0,0,1,0,0,-1,1,0,0,2,0,0", "12 columns"),
            (InverseKind::Locate, "1,2,x,4", "malformed number"),
            (InverseKind::Locate, "1,2,none,none", "malformed number"),
        ] {
            let e = row(kind, text).unwrap_err().to_string();
            assert!(e.starts_with("r.csv:7"), "{e}");
            assert!(e.contains(says), "{text}: {e}");
        }
        // the fields are counted before the row is split
        let long = format!("1,2{}", ",0".repeat(2 * MAX_CLAIMED + 2));
        let e = row(InverseKind::Locate, &long).unwrap_err().to_string();
        assert!(
            e.contains("10001 claimed tuples, above the limit of 10000"),
            "{e}"
        );
    }
}
