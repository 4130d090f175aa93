//! [`Error`]: the library's error at its public surface.
//!
//! It carries data (the file, line and key of bad input; the sizes that do not match; the
//! capability a kind lacks); its `Display` is the one-line message the command line prints.

use num_rational::BigRational;

use crate::certify::measures::{Tolerance, ToleranceNeeds};
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;
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
    /// An inverse problem (roots, intersections, locate, ray) that cannot be answered: a cap
    /// exceeded, a shape the operation does not take, a configuration it does not resolve.
    #[error(transparent)]
    Algebraic(#[from] crate::algebraic::AlgebraicError),
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

/// What a kind of patch cannot do ([`Error::Unsupported`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Lacks {
    /// It has no float program.
    #[error("it has no float program")]
    FloatProgram,
    /// Its float program has no such algorithm.
    #[error(
        "its float program has no algorithm `{algorithm}`: it is {path} (algorithm `{}`) only",
        names(has)
    )]
    Algorithm {
        /// The algorithm asked for.
        algorithm: Algorithm,
        /// The algorithms it has.
        has: &'static [Algorithm],
        /// The name of its float path (`"homogeneous de Casteljau"`).
        path: &'static str,
    },
    /// Certification of this kind runs de Casteljau only (`kind` is then the plural).
    #[error("certified with de Casteljau only, not with {algorithm}")]
    CertifyAlgorithm {
        /// The algorithm's name in reports.
        algorithm: &'static str,
    },
    /// Nothing to certify (`kind` is then the plural).
    #[error("have no float program to certify")]
    FloatProgramToCertify,
    /// Its float program has no proven error bound.
    #[error("its float program has no error bound")]
    ErrorBound,
    /// `cond=K` means nothing for it: its float program adds an error the condition number
    /// does not measure.
    #[error(
        "tolerance `{tolerance}` is not defined for {kinds} (their float program adds an error the condition number Σ|P_α|B_α does not measure): use `bound`, the proven bound of the whole float path"
    )]
    CondTolerance {
        /// The tolerance.
        tolerance: Tolerance,
        /// The kind, plural (`"S-patches"`).
        kinds: &'static str,
    },
}

fn names(algorithms: &[Algorithm]) -> String {
    algorithms
        .iter()
        .map(|a| a.name())
        .collect::<Vec<_>>()
        .join("`, `")
}
