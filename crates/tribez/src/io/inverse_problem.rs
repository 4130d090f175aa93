//! What is wrong in the inputs of an inverse claim (`intersect`, `locate`, `ray`) or of a batch
//! of located points or ray hits ([`super::Problem::Inverse`]): the figures of each message as
//! data.

use crate::error::AlgebraicError;

/// What is wrong in an inverse claim's or batch's inputs.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum InverseProblem {
    /// `patches` of an `intersect` claim names other than two curves.
    #[error("an intersection needs two curves, {named} named")]
    CurveCount {
        /// How many names were given.
        named: usize,
    },
    /// A ray whose direction is the zero vector.
    #[error("the ray's direction is zero")]
    ZeroDirection,
    /// More claimed tuples (or batch rows) than the limit.
    #[error("{count} claimed tuples, above the limit of {limit}")]
    TooManyClaimed {
        /// How many.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// A claimed tuple with the wrong number of parameters.
    #[error("{found} parameters, expected {expected} ({names})")]
    TupleWidth {
        /// How many were given.
        found: usize,
        /// How many the operation has.
        expected: usize,
        /// Their names (`"s, t"`, `"tau, s, t"`).
        names: &'static str,
    },
    /// A row of an inverse batch that is not its query then whole claimed tuples (or `none`).
    #[error("{found} columns; a {kind} row is {layout}")]
    RowColumns {
        /// Columns in the row (an upper bound when it is too long to be split).
        found: usize,
        /// `locate` or `ray`.
        kind: &'static str,
        /// The row layout.
        layout: &'static str,
    },
    /// A `ray` claim with `height` and also `origin` or `direction`.
    #[error(
        "`height` is the vertical line through a point: give it instead of `origin` and `direction`"
    )]
    HeightAndRay,
    /// A `ray` claim with `height` on a patch that is not a functional triangle patch.
    #[error("`height` takes a functional patch over a triangle (m = 2), not {what}")]
    HeightNotFunctional {
        /// What the patch is.
        what: String,
    },
    /// The exact computation refused the input (shape, caps, an unsupported configuration).
    #[error(transparent)]
    Algebraic(#[from] AlgebraicError),
}
