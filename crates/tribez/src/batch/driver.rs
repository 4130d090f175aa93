//! Driving a run: [`BatchChecker`] streams a results file in chunks (the next read while the
//! current one is judged on all cores), or judges rows held in memory in slabs between stop tests;
//! the [`Accumulator`] assembles the report in input order.

use std::io::{BufReader, Read};
use std::path::Path;

use super::judge::{Prepared, RowOutcome};
use super::parse::{self, Chunk, Num, RowReader};
use super::{Accumulator, BatchError, BatchOptions, BatchReport, Format, ResultsChecker};
use super::{STOP_SLAB, STOP_SLAB_MIN, STOP_SLAB_TIME};
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::io::{InputError, RowsProblem};
use crate::patch::BezierPatch;

#[cfg(doc)]
use super::{CHUNK, FailedRow};

/// Rows held in memory ([`BatchChecker::check_rows_until`]): row-major inputs and claimed
/// values, row `i` numbered `first_row + i`.
pub(super) struct MemoryRows<'a> {
    pub(super) points: &'a [f64],
    pub(super) values: &'a [f64],
    pub(super) first_row: usize,
}

/// The batch checker for one patch and one set of options (prepared once, then any number of
/// batches).
pub struct BatchChecker {
    pub(super) prepared: Prepared,
}

impl BatchChecker {
    /// Prepare to judge results about `patch` with `options`.
    pub fn new(patch: BezierPatch, options: &BatchOptions) -> Result<Self, BatchError> {
        Ok(BatchChecker {
            prepared: Prepared::new(options, patch)?,
        })
    }

    /// The algorithm a `bound` tolerance refers to.
    pub fn algorithm(&self) -> Algorithm {
        self.prepared.algorithm
    }

    /// [`ResultsChecker::check_file`], and `row(point)` called with every judged row's [`RowPoint`], in
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
}

/// Rows `inputs…, claimed…` (the patch's `m + 1` barycentric or `m` Cartesian coordinates, then
/// its `dim` claimed coordinates); `subject` names the patch in the report.
impl ResultsChecker for BatchChecker {
    type Report = BatchReport;

    fn check_reader<R: Read + Send>(
        &self,
        reader: R,
        format: Format,
        file: &str,
        subject: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<BatchReport, BatchError> {
        check_reader(
            &self.prepared,
            reader,
            format,
            file,
            subject,
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

/// The numbers of an in-memory row: with a precision each value is rounded to it (an `f32`
/// batch takes the nearest `f32`); the value as intended is the `f64` given. For an `f64` batch
/// that is the float itself, whose exact value [`Accumulator::intended`] takes from it when a
/// report needs it (most rows never do: no big rational is built per number).
pub(super) fn memory_num(x: f64, precision: Option<Precision>) -> Num {
    if !x.is_finite() {
        return Num::NotFinite(format!("`{x}`"), x);
    }
    match precision {
        Some(Precision::F64) => Num::Value {
            float: x,
            text_exact: None,
        },
        Some(Precision::F32) => {
            let y = x as f32;
            if !y.is_finite() {
                return Num::NotFinite(format!("`{x}` overflows f32"), f64::from(y));
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
    pub(super) fn of(o: &RowOutcome) -> Self {
        let floats = |xs: &[Num]| {
            xs.iter()
                .map(|x| match x {
                    Num::Value { float, .. } => *float,
                    Num::NotFinite(_, x) => *x,
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
        let mut verdicts = vec![
            RowVerdict {
                row: 0,
                pass: false,
                fell_back: false,
                ulps: f64::NAN,
            };
            n
        ];
        let rows = MemoryRows {
            points,
            values,
            first_row,
        };
        let (mut start, mut slab) = (0, STOP_SLAB_MIN);
        while start < n {
            if let Some(s) = stop() {
                return Ok(Err(s));
            }
            let end = (start + slab).min(n);
            let began = std::time::Instant::now();
            let slabs = acc.judge_memory(&rows, start, &mut verdicts[start..end]);
            acc.merge_memory(slabs);
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
