//! [`Error`]: the library's error at its public surface.
//!
//! It carries data (the file, line and key of bad input; the sizes that do not match; the
//! capability a kind lacks); its `Display` is the one-line message the command line prints.

use crate::certify::measures::ToleranceNeeds;
use crate::error::CoreError;
use crate::io::InputError;

/// Why a call of the library could not give an answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// Bad input in a file or text: which file, line and key, and what is wrong.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A mathematical precondition the input violates (a point of the wrong length, a
    /// degenerate domain, a vanishing denominator, a number that overflows a precision).
    #[error(transparent)]
    Core(#[from] CoreError),
    /// Sizes that do not match.
    #[error("{what}: expected {expected}, found {found}")]
    Size {
        /// What has the wrong size.
        what: &'static str,
        /// The size it must have.
        expected: usize,
        /// The size it has.
        found: usize,
    },
    /// The kind of patch lacks a capability, or a request is not defined for it.
    #[error("{kind}: {what}")]
    Unsupported {
        /// The kind, with its article (`"an S-patch"`).
        kind: &'static str,
        /// What it cannot do.
        what: String,
    },
    /// A tolerance that cannot judge this value (it lacks a precision, a condition number or a
    /// bound).
    #[error("coordinate {coordinate}: {needs}")]
    Tolerance {
        /// The coordinate judged (0-based).
        coordinate: usize,
        /// What is missing.
        needs: ToleranceNeeds,
    },
}
