//! [`Error`]: the library's error at its public surface.
//!
//! It carries data (the file, line and key of bad input; the sizes that do not match; the
//! capability a kind lacks); its `Display` is the one-line message the command line prints.

use crate::certify::measures::ToleranceNeeds;
use crate::error::CoreError;
use crate::io::InputError;
pub use crate::judge_refusal::{Lacks, Refusal};

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
    /// Why a float result cannot be judged, or a call's sizes do not match: a capability the
    /// kind lacks, a point outside the proven bound's hypotheses, an undefined value, a
    /// non-finite number, a size that does not match ([`Refusal`]; never its `Core` variant,
    /// which is [`Error::Core`]).
    #[error(transparent)]
    Refusal(Refusal),
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
            other => Error::Refusal(other),
        }
    }
}

impl Error {
    /// The judge's refusal this error is, if it is one; else the error itself.
    pub fn into_refusal(self) -> Result<Refusal, Error> {
        match self {
            Error::Core(e) => Ok(Refusal::Core(e)),
            Error::Refusal(r) => Ok(r),
            other => Err(other),
        }
    }
}
