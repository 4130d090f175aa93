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
//! Clear rows are decided by the float filter (`crate::certify::filter`); only undecided ones
//! fall back to exact big-integer evaluation, and the report counts them.
//!
//! `options` and `error` hold what a run is asked and why it cannot be; `driver` drives a run
//! (streaming chunks, judging them on all cores) and `accumulator` assembles the report in input
//! order; `parse` reads rows, `judge` judges one row (filter, then exact), `report` renders the
//! report (text, JSON).

mod accumulator;
mod answer;
mod checker;
mod driver;
mod error;
pub mod inverse;
mod judge;
mod mesh;
mod options;
mod parse;
mod report;
pub(crate) mod routed;

pub use crate::report::{ULP_BUCKETS, UlpHistogram};
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub(crate) use answer::fast_claimed_line as answer_fast_path;
pub use answer::read_claimed_line;
pub use checker::ResultsChecker;
pub use driver::{BatchChecker, RowPoint, RowVerdict};
pub use error::BatchError;
pub use inverse::{
    InverseBatchChecker, InverseBatchOptions, InverseBatchReport, InverseFailedRow, InverseKind,
};
pub use mesh::MeshBatchChecker;
pub use options::BatchOptions;
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub(crate) use parse::fuzz_rows;
pub use parse::{Format, parse_claimed_line};
pub use report::{BatchReport, FailedCoord, FailedRow, RowDetail, WorstRow};

use accumulator::Accumulator;

/// Rows judged per chunk (the memory bound: one chunk of lines is held at a time).
pub const CHUNK: usize = 1 << 16;

/// The most rows in memory judged between two calls of the stop test of
/// [`BatchChecker::check_rows_until`]. Slabs start at [`STOP_SLAB_MIN`] rows and double while a
/// slab takes under [`STOP_SLAB_TIME`] (halving when one takes over four times that), so that
/// the stop test is asked every fraction of a second even where every row falls back to exact
/// arithmetic at a high degree. Slabs change when the stop test is asked, never a verdict.
pub const STOP_SLAB: usize = 1 << 16;
/// The fewest rows of a slab ([`STOP_SLAB`]).
pub const STOP_SLAB_MIN: usize = 16;
/// The time one slab aims at ([`STOP_SLAB`]).
pub const STOP_SLAB_TIME: std::time::Duration = std::time::Duration::from_millis(50);
/// Failures listed in full in a report (the rest are counted).
pub const MAX_LISTED: usize = 100;
/// At most this many rows tied (within their enclosures) for the largest error are kept to be
/// settled exactly; past it, later ties are dropped (any of them would do).
const MAX_CANDIDATES: usize = 256;
