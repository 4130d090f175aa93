//! The batch checker: judge a large batch of evaluation results from another implementation,
//! streamed in chunks (bounded memory), judged in parallel, reported in input order (what
//! `tribez check --patch PATCH --results FILE` runs).
//!
//! Each row: the barycentric coordinates (or `x, y, …` with `cartesian`), then the claimed
//! coordinates of the point. CSV (`#` starts a comment line), JSON lines (`.jsonl`, `.ndjson`,
//! `.json`: one array per line; numbers or strings), or one JSON array of such rows (a `.json`
//! file starting with `[` then `[`, rows spread over any number of lines; see `parse`). With a
//! precision, each number denotes the float
//! nearest its text (hex floats are exact); the claimed value is judged against the exact value
//! at the inputs as the code saw them (those floats; homogeneous form, they need not sum to 1),
//! and the error at the intended inputs (the exact text) is reported for failures and for the
//! worst row. Without a precision numbers are exact and every row is computed exactly.
//!
//! Clear rows are decided by the float filter ([`crate::certify::filter`]); only undecided ones
//! fall back to exact big-integer evaluation, and the report counts them.
//!
//! This file drives a run (streaming chunks, judging them on all cores, assembling the report in
//! input order); `parse` reads rows, `judge` judges one row (filter, then exact), `report`
//! renders the report (text, JSON).

use std::io::{BufReader, Read};
use std::path::Path;

use rayon::prelude::*;

mod histogram;
mod judge;
mod parse;
mod report;
mod rows;

pub use histogram::{ULP_BUCKETS, UlpHistogram};
pub use parse::Format;
pub(crate) use parse::fuzz_rows;
pub use report::{BatchReport, FailedCoord, FailedRow};
pub use rows::RowVerdict;

use crate::certify::measures::Tolerance;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::io::InputError;
use crate::patch::BezierPatch as Patch;
use judge::{Prepared, RowOutcome, RowScratch};
use parse::{Chunk, Num, RowReader, parse_row, texts_of};

/// Rows judged per chunk (the memory bound: one chunk of lines is held at a time).
pub const CHUNK: usize = 1 << 16;
/// Failures listed in full in a report (the rest are counted).
pub const MAX_LISTED: usize = 100;
/// At most this many rows tied (within their enclosures) for the largest error are kept to be
/// settled exactly; past it, later ties are dropped (any of them would do).
const MAX_CANDIDATES: usize = 256;

/// How every row of a batch is judged.
#[derive(Clone, Debug)]
pub struct BatchOptions {
    /// The tolerance every row is judged with.
    pub tolerance: Tolerance,
    /// Each number denotes the nearest float of this precision; `None`: numbers are exact.
    pub precision: Option<Precision>,
    /// The algorithm whose a-priori bound a `bound` tolerance uses.
    pub algorithm: Algorithm,
    /// The input columns are Cartesian coordinates in the patch's domain (else barycentric).
    pub cartesian: bool,
}

impl Default for BatchOptions {
    /// Exact tolerance, exact numbers, de Casteljau, barycentric inputs.
    fn default() -> Self {
        BatchOptions {
            tolerance: Tolerance::Exact,
            precision: None,
            algorithm: Algorithm::Casteljau,
            cartesian: false,
        }
    }
}

/// Why a batch could not be checked.
#[derive(Debug, thiserror::Error)]
pub enum BatchError {
    /// The results file (or reader) is unreadable or malformed.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The tolerance compares floats, so the batch needs a precision.
    #[error("tolerance `{tolerance}` needs a precision (f64 or f32)")]
    ToleranceNeedsPrecision {
        /// The tolerance.
        tolerance: Tolerance,
    },
    /// A control point is outside the precision's range.
    #[error("a control point of the patch overflows {}", precision.name())]
    ControlPointOverflows {
        /// The precision.
        precision: Precision,
    },
}

/// The batch checker for one patch and one set of options (prepared once, then any number of
/// batches).
pub struct BatchChecker {
    prepared: Prepared,
}

impl BatchChecker {
    /// Prepare to judge results about `patch` with `options`.
    pub fn new(patch: Patch, options: &BatchOptions) -> Result<Self, BatchError> {
        Ok(BatchChecker {
            prepared: Prepared::new(options, patch)?,
        })
    }

    /// The algorithm a `bound` tolerance refers to.
    pub fn algorithm(&self) -> Algorithm {
        self.prepared.algorithm
    }

    /// Check a results file (its format told by [`Format::of`]); `patch_name` names the patch in
    /// the report. `progress(rows, failed)` is called after each chunk.
    pub fn check_file(
        &self,
        path: &Path,
        patch_name: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<BatchReport, BatchError> {
        let file = path.display().to_string();
        let format = Format::of(path, &file)?;
        let reader = std::fs::File::open(path)
            .map_err(|e| InputError::file(&file, format!("cannot read: {e}")))?;
        self.check_reader(reader, format, &file, patch_name, progress)
    }

    /// Check the rows read from `reader` in `format`; `file` names it in errors and the report.
    pub fn check_reader<R: Read + Send>(
        &self,
        reader: R,
        format: Format,
        file: &str,
        patch_name: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<BatchReport, BatchError> {
        check_reader(&self.prepared, reader, format, file, patch_name, progress)
    }
}

fn check_reader<R: Read + Send>(
    p: &Prepared,
    reader: R,
    format: Format,
    file: &str,
    patch_name: &str,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<BatchReport, BatchError> {
    let file = file.to_string();
    let (width, dim) = (p.width(), p.patch.net.dim());
    let mut reader = RowReader::new(BufReader::with_capacity(1 << 20, reader), format, &file)
        .expect_columns(width + dim);
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
        histogram_exact: 0,
        worst: None,
        failures: Vec::new(),
    };
    // The worst row: the largest lower bound seen (`floor`) and every row whose upper bound
    // reaches it (the bounds are tight after `Prepared::settle_ulps`, so only near-ties stay);
    // settled exactly at the end.
    let mut floor = 0f64;
    // (upper bound, line, inputs, claimed, the row's text and where it starts)
    type Candidate = (f64, usize, Vec<Num>, Vec<Num>, String, usize);
    let mut candidates: Vec<Candidate> = Vec::new();
    // Chunks of CHUNK rows: the next one is read (one thread) while the current one is judged
    // (the others), so reading overlaps the work and memory stays bounded.
    let mut chunk = Chunk::default();
    let mut next = Chunk::default();
    let mut eof = reader.read(&mut chunk)?;
    loop {
        let (read, outcomes) = rayon::join(
            || {
                if eof {
                    Ok(true)
                } else {
                    reader.read(&mut next)
                }
            },
            || -> Result<Vec<Option<RowOutcome>>, InputError> {
                chunk
                    .rows()
                    .collect::<Vec<_>>()
                    .par_iter()
                    .map_init(
                        RowScratch::default,
                        |scratch, (no, col, text)| -> Result<Option<RowOutcome>, InputError> {
                            let Some((inputs, claimed)) =
                                parse_row(format, text, *no, *col, width, dim, p.precision, &file)?
                            else {
                                return Ok(None);
                            };
                            let mut o = p.row(*no, inputs, claimed, scratch);
                            p.settle_ulps(&mut o, scratch);
                            Ok(Some(o))
                        },
                    )
                    .collect()
            },
        );
        let outcomes = outcomes?;
        let next_eof = read?;
        for (i, o) in outcomes.into_iter().enumerate() {
            let Some(o) = o else { continue };
            report.rows += 1;
            report.histogram.add(o.ulps);
            if o.fell_back {
                report.fell_back += 1;
            }
            if o.settled_exactly {
                report.histogram_exact += 1;
            }
            if o.ulps.is_finite() {
                if o.ulps_lower > floor {
                    floor = o.ulps_lower;
                    candidates.retain(|c| c.0 >= floor);
                }
                if o.ulps >= floor && candidates.len() < MAX_CANDIDATES {
                    let col = chunk.position(i).1;
                    candidates.push((
                        o.ulps,
                        o.line,
                        o.inputs.clone(),
                        o.claimed.clone(),
                        chunk.row(i).to_string(),
                        col,
                    ));
                }
            }
            if o.pass {
                report.passed += 1;
            } else {
                report.failed += 1;
                if report.failures.len() < MAX_LISTED {
                    let texts = texts_of(format, chunk.row(i), o.line, chunk.position(i).1, &file);
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
        progress(report.rows, report.failed);
        if eof {
            break;
        }
        std::mem::swap(&mut chunk, &mut next);
        eof = next_eof;
    }
    if report.rows == 0 {
        return Err(InputError::file(file, "no result rows").into());
    }
    // the candidates' exact errors; the first of the largest
    let worst_row = candidates
        .into_iter()
        .map(|(_, line, inputs, claimed, text, col)| {
            let (_, u, _, _) = p.exact_row(&inputs, &claimed, None, false);
            (u, line, inputs, claimed, text, col)
        })
        .fold(None, |best: Option<Candidate>, c| match &best {
            Some(b) if b.0 >= c.0 => best,
            _ => Some(c),
        });
    if let Some((_, line, inputs, claimed, text, col)) = worst_row {
        // Recompute the worst row exactly (its filter figure is an upper bound).
        let texts = texts_of(format, &text, line, col, &file);
        let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
        let (_, u, _, coords) = p.exact_row(&inputs, &claimed, Some(&refs), true);
        report.worst = Some((u, line, coords));
    }
    Ok(report)
}
