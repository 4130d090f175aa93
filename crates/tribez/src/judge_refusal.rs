//! Why the judge cannot judge a float result: a capability the kind lacks, a point outside the
//! proven bound's hypotheses, an undefined value, a non-finite number, a size that does not
//! match. Data only (below the input layer, so that a claim file's error can carry it); at the
//! public surface it is [`crate::Error::Refusal`] (and [`crate::Error::Core`]).

use num_rational::BigRational;

use crate::certify::measures::Tolerance;
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;

/// Why a float result cannot be judged ([`crate::Error::Refusal`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Refusal {
    /// A mathematical precondition the input violates (a number that overflows the
    /// precision, a value undefined at the input).
    #[error(transparent)]
    Core(#[from] CoreError),
    /// The kind of patch lacks a capability.
    #[error("{kind}: {what}")]
    Unsupported {
        /// The kind, with its article (`"an S-patch"`).
        kind: &'static str,
        /// What it cannot do.
        what: Lacks,
    },
    /// A point outside the hypotheses of the proven bound.
    #[error("no bound at this point in {precision}: {reason}")]
    NoBound {
        /// The precision.
        precision: Precision,
        /// Why.
        reason: &'static str,
    },
    /// The exact value is undefined at the input as seen.
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
    /// A value that is not a finite number.
    #[error("the {what} {value} is not a finite number")]
    NotFinite {
        /// `"input"`.
        what: &'static str,
        /// The value.
        value: f64,
    },
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
}

/// What a kind of patch cannot do ([`Refusal::Unsupported`]).
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
