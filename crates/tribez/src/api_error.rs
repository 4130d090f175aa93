//! [`Error`]: the library's error at its public surface.
//!
//! It carries data (the file, line and key of bad input; the sizes that do not match; the
//! capability a kind lacks); its `Display` is the one-line message the command line prints.

use num_rational::BigRational;

use crate::certify::measures::ToleranceNeeds;
use crate::error::CoreError;
use crate::float::Precision;
use crate::io::InputError;
pub use crate::judge_refusal::Lacks;
use crate::judge_refusal::Refusal;

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
    /// An inverse problem (roots, intersections, locate, ray) that cannot be answered: a cap
    /// exceeded, a shape the operation does not take, a configuration it does not resolve.
    #[error(transparent)]
    Algebraic(#[from] crate::algebraic::AlgebraicError),
    /// A mesh that is not valid, or a request it cannot answer (docs/theory.md §17).
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    /// A least-squares fit that has no answer: a data point outside the mesh, data that do not
    /// determine every ordinate, a tolerance that does not apply (docs/theory.md §18).
    #[error(transparent)]
    Fit(#[from] crate::fit::FitError),
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
        what: Lacks,
    },
    /// `tolerance = "bound"` at a point outside the hypotheses of the float program's proven
    /// bound.
    #[error("no bound at this point in {precision}: {reason}")]
    NoBound {
        /// The precision.
        precision: Precision,
        /// Why, for this kind ([`crate::ErrorBound::no_bound_reason`]).
        reason: &'static str,
    },
    /// The float program's exact value is undefined at the input as it saw it (a vanishing
    /// denominator, a point outside the rounded polygon).
    #[error(
        "{kind} is undefined at the input as seen {} (in {precision})",
        crate::domain::format_tuple(input)
    )]
    Undefined {
        /// The kind, with its article.
        kind: &'static str,
        /// The input as seen.
        input: Vec<BigRational>,
        /// The precision.
        precision: Precision,
    },
    /// A claimed or input value that is not a finite number.
    #[error("the {what} {value} is not a finite number")]
    NotFinite {
        /// `"input"`.
        what: &'static str,
        /// The value.
        value: f64,
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

impl From<Refusal> for Error {
    fn from(r: Refusal) -> Self {
        match r {
            Refusal::Core(e) => Error::Core(e),
            Refusal::Unsupported { kind, what } => Error::Unsupported { kind, what },
            Refusal::NoBound { precision, reason } => Error::NoBound { precision, reason },
            Refusal::Undefined {
                kind,
                input,
                precision,
            } => Error::Undefined {
                kind,
                input,
                precision,
            },
            Refusal::NotFinite { what, value } => Error::NotFinite { what, value },
            Refusal::Size {
                what,
                expected,
                found,
            } => Error::Size {
                what,
                expected,
                found,
            },
        }
    }
}

impl Error {
    /// The judge's refusal this error is, if it is one; else the error itself.
    pub fn into_refusal(self) -> Result<Refusal, Error> {
        Ok(match self {
            Error::Core(e) => Refusal::Core(e),
            Error::Unsupported { kind, what } => Refusal::Unsupported { kind, what },
            Error::NoBound { precision, reason } => Refusal::NoBound { precision, reason },
            Error::Undefined {
                kind,
                input,
                precision,
            } => Refusal::Undefined {
                kind,
                input,
                precision,
            },
            Error::NotFinite { what, value } => Refusal::NotFinite { what, value },
            Error::Size {
                what,
                expected,
                found,
            } => Refusal::Size {
                what,
                expected,
                found,
            },
            other => return Err(other),
        })
    }
}
