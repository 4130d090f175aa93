//! Why a batch could not be checked.

use crate::certify::measures::Tolerance;
use crate::float::Precision;
use crate::io::InputError;

#[cfg(doc)]
use super::BatchReport;

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
