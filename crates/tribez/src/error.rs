//! Errors of the exact core: violated preconditions of a mathematical operation.
//!
//! The input layer ([`crate::io`]) adds the file, line and key; the command line turns either
//! into a one-line message and exit status 2.

use thiserror::Error;

/// A mathematical precondition that an input violates.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CoreError {
    /// The domain simplex has (nearly) no volume: its vertices are affinely dependent.
    #[error("degenerate domain: the vertices {0} are affinely dependent (zero area)")]
    DegenerateDomain(String),
    /// A barycentric point whose coordinates do not sum to one.
    #[error("barycentric coordinates {coords} sum to {sum}, not 1")]
    NotBarycentric { coords: String, sum: String },
    /// A point or direction with the wrong number of coordinates.
    #[error("{what} has {found} coordinates, expected {expected}")]
    WrongLength {
        what: String,
        expected: usize,
        found: usize,
    },
    /// Wrong number of blossom arguments.
    #[error("the blossom of a degree-{degree} patch takes exactly {degree} arguments, got {found}")]
    BlossomArity { degree: usize, found: usize },
    /// A barycentric direction whose components do not sum to zero.
    #[error(
        "direction {coords} sums to {sum}, not 0 (a barycentric direction is a difference of two points)"
    )]
    DirectionSum { coords: String, sum: String },
    /// A derivative of order above the degree.
    #[error(
        "derivative of order {order} requested, but the patch has degree {degree} (order must be at most the degree)"
    )]
    OrderTooHigh { order: usize, degree: usize },
    /// A number that overflows the float format it is rounded to.
    #[error("{what} overflows {precision}")]
    Overflows {
        /// What overflows (`"a control point"`, `"an input"`).
        what: &'static str,
        /// `"f64"` or `"f32"`.
        precision: &'static str,
    },
    /// Two patches that must match do not.
    #[error("{0}")]
    Mismatch(String),
    /// Anything else that the mathematics rules out, with its explanation.
    #[error("{0}")]
    Invalid(String),
}
