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

use num_rational::BigRational;
use rayon::prelude::*;

pub mod inverse;
mod judge;
mod mesh;
mod parse;
mod report;
pub(crate) mod routed;

pub use crate::report::{ULP_BUCKETS, UlpHistogram};
pub use inverse::{
    InverseBatchChecker, InverseBatchOptions, InverseBatchReport, InverseFailedRow, InverseKind,
};
pub use mesh::MeshBatchChecker;
pub use parse::Format;
pub(crate) use parse::{fuzz_rows, open_results};
pub use report::{BatchReport, FailedCoord, FailedRow, RowDetail, WorstRow};

use crate::certify::measures::Tolerance;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::io::{InputError, RowsProblem};
use crate::patch::BezierPatch as Patch;
use judge::{Prepared, RowOutcome, RowScratch};
use parse::{Chunk, Num, RowReader, parse_row, texts_of};

/// Rows judged per chunk (the memory bound: one chunk of lines is held at a time).
pub const CHUNK: usize = 1 << 16;

/// The most rows in memory judged between two calls of the stop test of
/// [`BatchChecker::check_rows_until`]. Slabs start at [`STOP_SLAB_MIN`] rows and double while a
/// slab takes under [`STOP_SLAB_TIME`] (halving when one takes over four times that), so that
/// the stop test is asked every fraction of a second even where every row falls back to exact
/// arithmetic at a high degree. Slabs change when the stop test is asked, never a verdict.
pub const STOP_SLAB: usize = 1 << 12;
/// The fewest rows of a slab ([`STOP_SLAB`]).
pub const STOP_SLAB_MIN: usize = 16;
/// The time one slab aims at ([`STOP_SLAB`]).
pub const STOP_SLAB_TIME: std::time::Duration = std::time::Duration::from_millis(50);
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
    /// Keep every row's figures in [`BatchReport::rows`] (memory grows with the batch).
    pub row_detail: bool,
}

impl Default for BatchOptions {
    /// Exact tolerance, exact numbers, de Casteljau, barycentric inputs.
    fn default() -> Self {
        BatchOptions {
            tolerance: Tolerance::Exact,
            precision: None,
            algorithm: Algorithm::Casteljau,
            cartesian: false,
            row_detail: false,
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
    /// In-memory rows: a slice that is not a whole number of rows.
    #[error("{what}: {len} numbers is not a whole number of rows of {per_row}")]
    Shape {
        /// `points` or `values`.
        what: &'static str,
        /// Numbers per row.
        per_row: usize,
        /// Numbers given.
        len: usize,
    },
    /// In-memory rows: different numbers of rows of points and values.
    #[error("{points} rows of points but {values} rows of values")]
    RowCounts {
        /// Rows of points.
        points: usize,
        /// Rows of values.
        values: usize,
    },
    /// In-memory rows: `first_row` plus the rows passes the largest row index.
    #[error(
        "first_row {first_row} + {rows} rows passes the largest row index {}",
        usize::MAX
    )]
    RowIndexOverflow {
        /// The first row's index.
        first_row: usize,
        /// Rows given.
        rows: usize,
    },
    /// [`BatchReport::merge`]: reports judged differently or about different patches.
    #[error("reports {what} ({this} vs {other})")]
    Mismatch {
        /// What differs (`judged with different tolerances`, …).
        what: &'static str,
        /// This report's.
        this: String,
        /// The other's.
        other: String,
    },
    /// A mesh that is not valid (`check --mesh`): its first problem.
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    /// An inverse batch (`--locate-results`, `--ray-results`) with a tolerance only an
    /// evaluation has (`cond`, `bound`).
    #[error(
        "tolerance `{tolerance}` needs an evaluation (a condition number or an algorithm's bound); inverse batches take exact, ulps=N, abs=E, rel=E, correctly_rounded or faithful"
    )]
    ToleranceEvalOnly {
        /// The tolerance.
        tolerance: Tolerance,
    },
    /// `anywhere` asked of ray rows (a ray's first hit is over the closed triangle).
    #[error(
        "anywhere (parameters in the whole plane) applies to locate rows, not to ray rows (a ray's first hit is over the closed triangle)"
    )]
    AnywhereForRays,
    /// An inverse batch about a patch its problem does not take.
    #[error("{patch}: {error}")]
    InversePatch {
        /// The patch's name.
        patch: String,
        /// Why.
        error: crate::algebraic::AlgebraicError,
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
        let (file, format, reader) = parse::open_results(path)?;
        self.check_reader(reader, format, &file, patch_name, progress)
    }

    /// [`Self::check_file`], and `row(point)` called with every judged row's [`RowPoint`], in
    /// input order (what an error map draws; the rows are not kept).
    pub fn check_file_each_row(
        &self,
        path: &Path,
        patch_name: &str,
        progress: &mut dyn FnMut(u64, u64),
        row: &mut dyn FnMut(RowPoint),
    ) -> Result<BatchReport, BatchError> {
        let (file, format, reader) = parse::open_results(path)?;
        check_reader(
            &self.prepared,
            reader,
            format,
            &file,
            patch_name,
            progress,
            Some(row),
        )
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
        check_reader(
            &self.prepared,
            reader,
            format,
            file,
            patch_name,
            progress,
            None,
        )
    }
}

fn check_reader<R: Read + Send>(
    p: &Prepared,
    reader: R,
    format: Format,
    file: &str,
    patch_name: &str,
    progress: &mut dyn FnMut(u64, u64),
    mut each_row: Option<&mut dyn FnMut(RowPoint)>,
) -> Result<BatchReport, BatchError> {
    let mut reader = RowReader::new(BufReader::with_capacity(1 << 20, reader), format, file)
        .expect_columns(p.width() + p.patch.net.dim());
    let mut acc = Accumulator::new(p, file, patch_name, Some(format));
    // Chunks of CHUNK rows: the next one is read (one thread) while the current one is judged
    // (the others), so reading overlaps the work and memory stays bounded.
    let mut chunk = Chunk::default();
    let mut next = Chunk::default();
    let mut eof = reader.read(&mut chunk)?;
    let want_points = each_row.is_some();
    loop {
        let rows: Vec<(usize, usize, &str)> = chunk.rows().collect();
        let (read, slabs) = rayon::join(
            || {
                if eof {
                    Ok(true)
                } else {
                    reader.read(&mut next)
                }
            },
            || acc.judge_slabs(&rows, format, want_points),
        );
        acc.merge(slabs, &rows, each_row.as_deref_mut())?;
        let next_eof = read?;
        progress(acc.report.checked, acc.report.failed);
        if eof {
            break;
        }
        drop(rows);
        std::mem::swap(&mut chunk, &mut next);
        eof = next_eof;
    }
    if acc.report.checked == 0 {
        return Err(InputError::file(file, RowsProblem::NoResultRows).into());
    }
    Ok(acc.finish())
}

/// One line of claimed coordinates, as a results row's claimed columns are read (CSV, or one
/// JSON array when the line starts with `[`): `dim` numbers in any syntax `check --results`
/// reads, each the float of `precision` nearest its text (hex floats exact; `nan`, `inf` and an
/// empty field give NaN, a failed row when judged). What `tribez hunt` reads of its target.
///
/// Errors: one line saying what is wrong (an empty or comment line, the wrong number of
/// numbers, a field that is not a number, with its 1-based column).
pub fn parse_claimed_line(
    text: &str,
    dim: usize,
    precision: Precision,
) -> Result<Vec<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Err("an empty line".into());
    }
    let format = if t.starts_with('[') {
        Format::JsonLines
    } else {
        Format::Csv
    };
    match parse_row(format, text, 1, 1, 0, dim, Some(precision), "") {
        Ok(Some((_, claimed))) => Ok(claimed
            .iter()
            .map(|x| match x {
                Num::Value { float, .. } => *float,
                Num::NotFinite(_) => f64::NAN,
            })
            .collect()),
        Ok(None) => Err("a comment line".into()),
        Err(e) => Err(match (&*e.problem, e.column) {
            (crate::io::Problem::Rows(RowsProblem::ColumnCount { found, .. }), _) => {
                format!("{found} numbers, expected {dim}")
            }
            (p, Some(c)) => format!("column {c}: {p}"),
            (p, None) => p.to_string(),
        }),
    }
}

/// The numbers of an in-memory row: with a precision each value is rounded to it (an `f32`
/// batch takes the nearest `f32`); the value as intended is the `f64` given. For an `f64` batch
/// that is the float itself, whose exact value [`Accumulator::intended`] takes from it when a
/// report needs it (most rows never do: no big rational is built per number).
fn memory_num(x: f64, precision: Option<Precision>) -> Num {
    if !x.is_finite() {
        return Num::NotFinite(format!("`{x}`"));
    }
    match precision {
        Some(Precision::F64) => Num::Value {
            float: x,
            text_exact: None,
        },
        Some(Precision::F32) => {
            let y = x as f32;
            if !y.is_finite() {
                return Num::NotFinite(format!("`{x}` overflows f32"));
            }
            Num::Value {
                float: f64::from(y),
                text_exact: crate::number::exact_f64(x),
            }
        }
        None => Num::Value {
            float: x,
            text_exact: crate::number::exact_f64(x),
        },
    }
}

/// What one in-memory row came to (for per-row arrays; cheap, unlike
/// [`BatchOptions::row_detail`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowVerdict {
    /// The row's number (counted from `first_row`).
    pub row: usize,
    /// Within the tolerance.
    pub pass: bool,
    /// The float filter could not decide it: judged in exact arithmetic.
    pub fell_back: bool,
    /// The largest error in ULPs over its coordinates at the inputs as seen (exact when
    /// computed exactly, else the upper end of a compensated enclosure, tight to a small
    /// fraction of an ulp; infinite for a non-finite number).
    pub ulps: f64,
}

/// One judged row as an error map draws it ([`BatchChecker::check_file_each_row`]).
#[derive(Clone, Debug, PartialEq)]
pub struct RowPoint {
    /// The row's number (as [`FailedRow::line`]).
    pub row: usize,
    /// Its input coordinates as the code saw them (barycentric, or Cartesian with
    /// [`BatchOptions::cartesian`]); NaN where a number is not finite.
    pub inputs: Vec<f64>,
    /// Its claimed coordinates as floats (NaN where a number is not finite): with the inputs,
    /// [`BatchChecker::check_rows`] judges the same row again in memory.
    pub claimed: Vec<f64>,
    /// Within the tolerance.
    pub pass: bool,
    /// The largest error in ULPs over its coordinates, as the histogram counts it (exact, or
    /// the upper end of a compensated enclosure for a row the float filter decided; infinite
    /// for a non-finite number).
    pub ulps: f64,
    /// A lower bound on that error (equal to `ulps` when it was computed exactly).
    pub ulps_lower: f64,
}

impl RowPoint {
    fn of(o: &RowOutcome) -> Self {
        let floats = |xs: &[Num]| {
            xs.iter()
                .map(|x| match x {
                    Num::Value { float, .. } => *float,
                    Num::NotFinite(_) => f64::NAN,
                })
                .collect()
        };
        RowPoint {
            row: o.line,
            inputs: floats(&o.inputs),
            claimed: floats(&o.claimed),
            pass: o.pass,
            ulps: o.ulps,
            ulps_lower: o.ulps_lower,
        }
    }
}

/// Where a row came from, to find its inputs as intended: a file's row text (and the column it
/// starts at), or memory (the numbers themselves).
enum Source<'a> {
    Text(&'a str, usize),
    Memory,
}

/// A row judged, with its detail when asked for.
struct Judged {
    outcome: RowOutcome,
    detail: Option<RowDetail>,
}

/// Rows judged together on one thread (a task of a chunk's parallel pass).
const SLAB: usize = 4096;

/// The counts of a report, summed over rows (any order).
#[derive(Default)]
struct Tally {
    checked: u64,
    passed: u64,
    failed: u64,
    fell_back: u64,
    histogram_exact: usize,
    histogram: UlpHistogram,
}

impl Tally {
    /// Count a judged row.
    fn count(&mut self, o: &RowOutcome) {
        self.checked += 1;
        self.histogram.add(o.ulps);
        if o.fell_back {
            self.fell_back += 1;
        }
        if o.settled_exactly {
            self.histogram_exact += 1;
        }
        if o.pass {
            self.passed += 1;
        } else {
            self.failed += 1;
        }
    }

    /// Add the counts to a report's.
    fn add_to(&self, report: &mut BatchReport) {
        report.checked += self.checked;
        report.passed += self.passed;
        report.failed += self.failed;
        report.fell_back += self.fell_back;
        report.histogram_exact += self.histogram_exact;
        for (a, b) in report
            .histogram
            .counts
            .iter_mut()
            .zip(self.histogram.counts)
        {
            *a += b;
        }
    }
}

/// Which rows of a slab may matter to the report's listed failures and worst row
/// ([`Accumulator::note`]), told without the rows of the slabs before it: the slab's first
/// [`MAX_LISTED`] failures, and every row with finite figures whose upper bound reaches a floor
/// no higher than the report's at that row (the report's floor before the chunk, raised by the
/// slab's own rows' lower bounds). A row it drops neither raises the report's floor nor becomes
/// a candidate: it would change nothing in [`Accumulator::note`], so noting only the rows it
/// keeps gives the same report.
struct Sieve {
    floor: f64,
    failures: usize,
}

impl Sieve {
    /// Whether to keep a row (in input order).
    fn keep(&mut self, o: &RowOutcome) -> bool {
        let mut keep = false;
        if !o.pass && self.failures < MAX_LISTED {
            self.failures += 1;
            keep = true;
        }
        if o.ulps.is_finite() {
            // (a row that raises the floor has ulps ≥ ulps_lower > floor)
            keep |= o.ulps >= self.floor;
            self.floor = self.floor.max(o.ulps_lower);
        }
        keep
    }
}

/// What a slab of rows came to: its counts, the rows [`Sieve`] kept (index into the rows,
/// judged row with its numbers), every row's detail (with [`BatchOptions::row_detail`]) and
/// [`RowPoint`] (when asked for), in order, and the first error, which ends the slab.
#[derive(Default)]
struct Slab {
    tally: Tally,
    kept: Vec<(usize, Judged)>,
    details: Vec<RowDetail>,
    points: Vec<RowPoint>,
    error: Option<InputError>,
}

/// A row that may be the worst: its upper bound, its number, its numbers and where it came from.
struct Candidate {
    upper: f64,
    lower: f64,
    row: usize,
    inputs: Vec<Num>,
    claimed: Vec<Num>,
    text: Option<(String, usize)>,
}

/// The report being assembled, row by row in order.
struct Accumulator<'p> {
    p: &'p Prepared,
    format: Option<Format>,
    report: BatchReport,
    /// The largest lower bound seen.
    floor: f64,
    /// Some candidate's lower bound reaches `floor` (a later row whose upper bound is at most
    /// `floor` can at best tie it, and ties go to the earlier row).
    certified: bool,
    candidates: Vec<Candidate>,
}

impl<'p> Accumulator<'p> {
    fn new(p: &'p Prepared, file: &str, patch: &str, format: Option<Format>) -> Self {
        Accumulator {
            p,
            format,
            report: BatchReport {
                file: file.into(),
                patch: patch.into(),
                tolerance: p.tolerance.clone(),
                precision: p.precision,
                checked: 0,
                passed: 0,
                failed: 0,
                fell_back: 0,
                histogram: UlpHistogram::default(),
                histogram_upper_bounds: p.filter.is_some(),
                histogram_exact: 0,
                max_ulps: None,
                worst: None,
                failures: Vec::new(),
                rows: p.row_detail.then(Vec::new),
                baseline_regressions: Vec::new(),
            },
            floor: 0.0,
            certified: false,
            candidates: Vec::new(),
        }
    }

    /// The inputs of a row as intended.
    fn intended(
        &self,
        inputs: &[Num],
        row: usize,
        source: &Source<'_>,
    ) -> Option<Vec<BigRational>> {
        match (source, self.format) {
            (Source::Text(text, col), Some(format)) => {
                let texts = texts_of(format, text, row, *col, &self.report.file);
                inputs
                    .iter()
                    .zip(&texts)
                    .map(|(x, s)| x.text_value(s))
                    .collect()
            }
            _ => inputs
                .iter()
                .map(|x| match x {
                    Num::Value {
                        text_exact: Some(q),
                        ..
                    } => Some(q.clone()),
                    // a memory row of an `f64` batch: the `f64` given is the float (`memory_num`)
                    Num::Value {
                        float,
                        text_exact: None,
                    } if matches!(source, Source::Memory) => crate::number::exact_f64(*float),
                    _ => None,
                })
                .collect(),
        }
    }

    /// Judge one row (any thread): the filter, exact arithmetic when undecided, the ULP figures
    /// settled, and the row's detail when asked for.
    fn judge(
        &self,
        row: usize,
        inputs: Vec<Num>,
        claimed: Vec<Num>,
        source: &Source<'_>,
        scratch: &mut RowScratch,
    ) -> Judged {
        let p = self.p;
        let outcome = p.row(row, inputs, claimed, scratch);
        let detail = p.row_detail.then(|| {
            let intended = self.intended(&outcome.inputs, row, source);
            let (passed, ulps, _, coords) =
                p.exact_row(&outcome.inputs, &outcome.claimed, intended.as_deref(), true);
            let finite = coords.len() == outcome.claimed.len();
            RowDetail {
                row,
                passed,
                ulps_seen: ulps,
                ulps_intended: coords
                    .iter()
                    .map(|c| {
                        c.intended
                            .as_ref()
                            .and_then(|m| m.ulps.as_ref())
                            .map(crate::number::round_up_f64)
                    })
                    .collect::<Option<Vec<f64>>>()
                    .filter(|_| finite)
                    .map(|us| us.into_iter().fold(0.0, f64::max)),
                correctly_rounded: finite
                    && coords
                        .iter()
                        .all(|c| c.seen.correctly_rounded == Some(true)),
            }
        });
        Judged { outcome, detail }
    }

    /// Judge a row of a results file (any thread): `None` for a blank or comment line. A CSV row
    /// of plain numbers that the float filter decides is judged from its floats alone, without
    /// parsing its numbers in full (the outcome's numbers are then empty).
    fn judge_text(
        &self,
        format: Format,
        (line, col, text): (usize, usize, &str),
        scratch: &mut RowScratch,
    ) -> Result<Option<Judged>, InputError> {
        let p = self.p;
        let (width, dim) = (p.width(), p.patch.net.dim());
        if let (Format::Csv, Some(precision), Some(_), false) =
            (format, p.precision, &p.filter, p.row_detail)
            && parse::csv_floats(
                text,
                width,
                dim,
                precision,
                &mut scratch.lambda,
                &mut scratch.ys,
            )
            && let Some(outcome) = p.filtered(line, scratch)
        {
            return Ok(Some(Judged {
                outcome,
                detail: None,
            }));
        }
        let file = &self.report.file;
        let Some((inputs, claimed)) =
            parse_row(format, text, line, col, width, dim, p.precision, file)?
        else {
            return Ok(None);
        };
        Ok(Some(self.judge(
            line,
            inputs,
            claimed,
            &Source::Text(text, col),
            scratch,
        )))
    }

    /// Judge rows of a results file (`(line, column, text)` as read, in input order) in
    /// parallel, in slabs of [`SLAB`] rows, each slab on one thread; `points`: keep every row's
    /// [`RowPoint`]. [`Accumulator::merge`] then adds the slabs to the report.
    fn judge_slabs(
        &self,
        rows: &[(usize, usize, &str)],
        format: Format,
        points: bool,
    ) -> Vec<Slab> {
        let p = self.p;
        let file = &self.report.file;
        rows.par_chunks(SLAB)
            .enumerate()
            .map_init(RowScratch::default, |scratch, (s, slab_rows)| {
                let mut slab = Slab::default();
                let mut sieve = Sieve {
                    floor: self.floor,
                    failures: 0,
                };
                for (k, &row) in slab_rows.iter().enumerate() {
                    let (line, col, text) = row;
                    let judged = match self.judge_text(format, row, scratch) {
                        Ok(Some(j)) => j,
                        Ok(None) => continue,
                        Err(e) => {
                            slab.error = Some(e);
                            break;
                        }
                    };
                    let Judged {
                        mut outcome,
                        detail,
                    } = judged;
                    slab.tally.count(&outcome);
                    slab.details.extend(detail);
                    let keep = sieve.keep(&outcome);
                    if (keep || points) && outcome.inputs.is_empty() {
                        // a row judged from its floats: its numbers in full
                        let width = p.width();
                        let parsed = parse_row(
                            format,
                            text,
                            line,
                            col,
                            width,
                            p.patch.net.dim(),
                            p.precision,
                            file,
                        );
                        match parsed {
                            Ok(Some((inputs, claimed))) => {
                                outcome.inputs = inputs;
                                outcome.claimed = claimed;
                            }
                            // invariant: the row was read by csv_floats just before, so parsing it again succeeds
                            _ => unreachable!("csv_floats read the row"),
                        }
                    }
                    if points {
                        slab.points.push(RowPoint::of(&outcome));
                    }
                    if keep {
                        slab.kept.push((
                            s * SLAB + k,
                            Judged {
                                outcome,
                                detail: None,
                            },
                        ));
                    }
                }
                slab
            })
            .collect()
    }

    /// Add judged slabs to the report, in input order (`rows` as given to
    /// [`Accumulator::judge_slabs`]); `each_row` is called with every row's [`RowPoint`]. The
    /// first error in input order is returned, after the rows before it were added.
    fn merge(
        &mut self,
        slabs: Vec<Slab>,
        rows: &[(usize, usize, &str)],
        mut each_row: Option<&mut (dyn FnMut(RowPoint) + '_)>,
    ) -> Result<(), InputError> {
        for slab in slabs {
            slab.tally.add_to(&mut self.report);
            if let Some(rows) = &mut self.report.rows {
                rows.extend(slab.details);
            }
            if let Some(f) = each_row.as_mut() {
                slab.points.into_iter().for_each(f);
            }
            for (i, judged) in slab.kept {
                let (_, col, text) = rows[i];
                self.note(judged.outcome, &Source::Text(text, col));
            }
            if let Some(e) = slab.error {
                return Err(e);
            }
        }
        Ok(())
    }

    /// Count a judged row (in input order).
    fn add(&mut self, judged: Judged, source: &Source<'_>) {
        let Judged { outcome, detail } = judged;
        let mut tally = Tally::default();
        tally.count(&outcome);
        tally.add_to(&mut self.report);
        if let (Some(rows), Some(d)) = (&mut self.report.rows, detail) {
            rows.push(d);
        }
        self.note(outcome, source);
    }

    /// Note a judged row (in input order; counted apart) for the report's listed failures and
    /// worst row.
    fn note(&mut self, o: RowOutcome, source: &Source<'_>) {
        let report = &mut self.report;
        if !o.pass && report.failures.len() < MAX_LISTED {
            let intended = self.intended(&o.inputs, o.line, source);
            let (_, _, reason, coords) =
                self.p
                    .exact_row(&o.inputs, &o.claimed, intended.as_deref(), true);
            let reason = o
                .failure
                .clone()
                .filter(|r| !r.is_empty())
                .or(reason)
                .unwrap_or_else(|| "fails".into());
            self.report.failures.push(FailedRow {
                line: o.line,
                reason,
                coords,
            });
        }
        if !o.ulps.is_finite() {
            return;
        }
        if o.ulps_lower > self.floor {
            self.floor = o.ulps_lower;
            let floor = self.floor;
            self.candidates.retain(|c| c.upper >= floor);
            self.certified = false;
        }
        if o.ulps > self.floor || (o.ulps >= self.floor && !self.certified) {
            if o.ulps_lower >= self.floor {
                self.certified = true;
            }
            let text = match source {
                Source::Text(t, col) => Some((t.to_string(), *col)),
                Source::Memory => None,
            };
            self.candidates.push(Candidate {
                upper: o.ulps,
                lower: o.ulps_lower,
                row: o.line,
                inputs: o.inputs,
                claimed: o.claimed,
                text,
            });
            if self.candidates.len() >= MAX_CANDIDATES {
                self.settle_candidates();
            }
        }
    }

    /// Compute the candidates' errors exactly and keep the first of the largest.
    fn settle_candidates(&mut self) {
        for c in &mut self.candidates {
            if c.lower < c.upper {
                let (_, u, _, _) = self.p.exact_row(&c.inputs, &c.claimed, None, false);
                c.lower = u;
                c.upper = u;
            }
        }
        let best =
            self.candidates
                .iter()
                .enumerate()
                .fold(None, |best: Option<(usize, f64)>, (i, c)| match best {
                    Some((_, u)) if u >= c.upper => best,
                    _ => Some((i, c.upper)),
                });
        if let Some((i, u)) = best {
            let c = self.candidates.swap_remove(i);
            self.candidates.clear();
            self.candidates.push(c);
            self.floor = self.floor.max(u);
            self.certified = true;
        }
    }

    /// The report, with the worst row computed exactly.
    fn finish(mut self) -> BatchReport {
        self.settle_candidates();
        if let Some(c) = self.candidates.pop() {
            let source = match &c.text {
                Some((t, col)) => Source::Text(t, *col),
                None => Source::Memory,
            };
            let intended = self.intended(&c.inputs, c.row, &source);
            let (_, u, _, coords) =
                self.p
                    .exact_row(&c.inputs, &c.claimed, intended.as_deref(), true);
            self.report.max_ulps = Some(u);
            self.report.worst = Some(WorstRow {
                ulps: u,
                line: c.row,
                coords,
            });
        }
        self.report
    }
}

impl BatchChecker {
    /// Judge rows held in memory, in parallel: `points` row-major (`m + 1` barycentric
    /// coordinates per row, or `m` Cartesian ones with [`BatchOptions::cartesian`]), `values`
    /// row-major (the patch's `dim` claimed coordinates per row). Row `i` is numbered
    /// `first_row + i` in the report (so reports of consecutive slices [`BatchReport::merge`]
    /// into the report of the whole). With a precision, each value is rounded to it (the nearest
    /// `f32` for an `f32` batch) and the `f64` given is the input as intended; without one, the
    /// `f64` values are the exact numbers. `nan` and infinities are failed rows.
    ///
    /// `file` and `patch_name` name the rows and the patch in the report. Returns the report and
    /// every row's [`RowVerdict`].
    ///
    /// Errors: `points` or `values` not a whole number of rows, different numbers of rows, no
    /// rows.
    pub fn check_rows(
        &self,
        points: &[f64],
        values: &[f64],
        first_row: usize,
        file: &str,
        patch_name: &str,
    ) -> Result<(BatchReport, Vec<RowVerdict>), BatchError> {
        let none = &|| None::<std::convert::Infallible>;
        let Ok(out) = self.check_rows_until(points, values, first_row, file, patch_name, none)?;
        Ok(out)
    }

    /// [`BatchChecker::check_rows`], asking `stop` on the calling thread between slabs of at
    /// most [`STOP_SLAB`] rows (sized to take a fraction of a second each): when it answers `Some(s)` the check ends with `Ok(Err(s))` (the
    /// Python package stops on Ctrl-C this way). `first_row` plus the rows passing
    /// `usize::MAX` is an error ([`BatchError::RowIndexOverflow`]), never a wrapped index.
    pub fn check_rows_until<S>(
        &self,
        points: &[f64],
        values: &[f64],
        first_row: usize,
        file: &str,
        patch_name: &str,
        stop: &dyn Fn() -> Option<S>,
    ) -> Result<Result<(BatchReport, Vec<RowVerdict>), S>, BatchError> {
        let p = &self.prepared;
        let (width, dim) = (p.width(), p.patch.net.dim());
        if !points.len().is_multiple_of(width) {
            return Err(BatchError::Shape {
                what: "points",
                per_row: width,
                len: points.len(),
            });
        }
        if !values.len().is_multiple_of(dim) {
            return Err(BatchError::Shape {
                what: "values",
                per_row: dim,
                len: values.len(),
            });
        }
        let n = points.len() / width;
        if values.len() / dim != n {
            return Err(BatchError::RowCounts {
                points: n,
                values: values.len() / dim,
            });
        }
        if n == 0 {
            return Err(InputError::file(file, RowsProblem::NoResultRows).into());
        }
        if first_row.checked_add(n - 1).is_none() {
            return Err(BatchError::RowIndexOverflow { first_row, rows: n });
        }
        let mut acc = Accumulator::new(p, file, patch_name, None);
        let mut verdicts = Vec::with_capacity(n);
        let (mut start, mut slab) = (0, STOP_SLAB_MIN);
        while start < n {
            if let Some(s) = stop() {
                return Ok(Err(s));
            }
            let end = (start + slab).min(n);
            let began = std::time::Instant::now();
            let judged: Vec<Judged> = (start..end)
                .into_par_iter()
                .map_init(RowScratch::default, |scratch, i| {
                    let inputs = points[i * width..(i + 1) * width]
                        .iter()
                        .map(|&x| memory_num(x, p.precision))
                        .collect();
                    let claimed = values[i * dim..(i + 1) * dim]
                        .iter()
                        .map(|&x| memory_num(x, p.precision))
                        .collect();
                    acc.judge(first_row + i, inputs, claimed, &Source::Memory, scratch)
                })
                .collect();
            for j in judged {
                let o = &j.outcome;
                verdicts.push(RowVerdict {
                    row: o.line,
                    pass: o.pass,
                    fell_back: o.fell_back,
                    ulps: o.ulps,
                });
                acc.add(j, &Source::Memory);
            }
            let took = began.elapsed();
            if took < STOP_SLAB_TIME {
                slab = (slab * 2).min(STOP_SLAB);
            } else if took > 4 * STOP_SLAB_TIME {
                slab = (slab / 2).max(STOP_SLAB_MIN);
            }
            start = end;
        }
        Ok(Ok((acc.finish(), verdicts)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A row with figures `lower ≤ upper` (its numbers: the point (1, 0, 0), claimed 0).
    fn outcome(line: usize, pass: bool, lower: f64, upper: f64) -> RowOutcome {
        let num = |x: f64| Num::Value {
            float: x,
            text_exact: None,
        };
        RowOutcome {
            line,
            pass,
            fell_back: false,
            ulps: upper,
            ulps_lower: lower,
            settled_exactly: false,
            failure: (!pass).then(|| "fails".to_string()),
            inputs: vec![num(1.0), num(0.0), num(0.0)],
            claimed: vec![num(0.0); 3],
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Noting only the rows [`Sieve`] keeps, slab by slab (each sieve starting from the
        /// report's floor before its chunk), leaves the report's failures, floor and candidates
        /// for the worst row as noting every row does. The figures come from a few values, so
        /// that ties and overlapping enclosures are common (and all rows may have no error).
        #[test]
        fn noting_the_rows_the_sieve_keeps_is_noting_every_row(
            rows in prop::collection::vec((0usize..5, 0usize..3, proptest::bool::weighted(0.9), proptest::bool::weighted(0.05)), 1..200),
            chunk in 1usize..40,
            slab in 1usize..12,
            exact in proptest::bool::weighted(0.2),
        ) {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../fixtures/finn_day30.toml");
            let patch = crate::io::patch_file::read_patch(&path).unwrap();
            let options = BatchOptions {
                tolerance: Tolerance::Ulps(num_rational::BigRational::from_integer(1.into())),
                precision: Some(Precision::F64),
                ..BatchOptions::default()
            };
            let p = Prepared::new(&options, patch).unwrap();
            let lowers = [0.0, 0.5, 1.0, 1.5, 3.0];
            let widths = [0.0, 0.25, 1.0];
            let outcomes = || {
                rows.iter().enumerate().map(|(i, &(l, w, pass, infinite))| {
                    let (lo, hi) = if infinite {
                        (f64::INFINITY, f64::INFINITY)
                    } else if exact {
                        // errors computed exactly: every row a tie at first
                        (lowers[l / 3], lowers[l / 3])
                    } else {
                        (lowers[l], lowers[l] + widths[w])
                    };
                    outcome(i + 1, pass, lo, hi)
                })
            };
            let mut every = Accumulator::new(&p, "f", "p", None);
            for o in outcomes() {
                every.note(o, &Source::Memory);
            }
            let mut sieved = Accumulator::new(&p, "f", "p", None);
            let all: Vec<RowOutcome> = outcomes().collect();
            for c in all.chunks(chunk) {
                let floor = sieved.floor;
                let kept: Vec<RowOutcome> = c
                    .chunks(slab)
                    .flat_map(|s| {
                        let mut sieve = Sieve { floor, failures: 0 };
                        s.iter().filter(|o| sieve.keep(o)).map(|o| outcome(o.line, o.pass, o.ulps_lower, o.ulps)).collect::<Vec<_>>()
                    })
                    .collect();
                for o in kept {
                    sieved.note(o, &Source::Memory);
                }
            }
            let state = |a: &Accumulator<'_>| {
                (
                    a.floor,
                    a.certified,
                    a.candidates.iter().map(|c| (c.row, c.lower, c.upper)).collect::<Vec<_>>(),
                    a.report.failures.iter().map(|f| f.line).collect::<Vec<_>>(),
                )
            };
            prop_assert_eq!(state(&every), state(&sieved));
        }
    }
}
