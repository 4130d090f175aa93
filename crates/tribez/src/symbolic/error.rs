//! [`PolyError`]: why polynomial text was refused, as data: what is wrong ([`PolyErrorKind`])
//! and where (the 1-based character), in the manner of `num-rational`'s typed parse errors.
//! `Display` is the one-line message the command line prints.

use crate::number::NumberError;

/// Polynomial text, or the variable names to read it with, that [`super::Polynomial::parse`]
/// refused.
///
/// ```
/// use tribez::hazmat::symbolic::{Polynomial, PolyErrorKind};
/// let e = Polynomial::parse("u + * v", &["u", "v"]).unwrap_err();
/// assert_eq!(e.at, Some(5));
/// assert_eq!(e.kind, PolyErrorKind::NoTerm { found: '*' });
/// assert_eq!(e.to_string(), "expected a term, found `*` at character 5");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{kind}{}", at.map(|a| format!(" at character {a}")).unwrap_or_default())]
pub struct PolyError {
    /// What is wrong.
    pub kind: PolyErrorKind,
    /// Where: the 1-based character of the text (`None` for the names, or the whole text).
    pub at: Option<usize>,
}

impl PolyError {
    /// `kind` at character `at` (1-based).
    pub(crate) fn at(kind: PolyErrorKind, at: usize) -> Self {
        PolyError { kind, at: Some(at) }
    }

    /// `kind`, not at one character.
    pub(crate) fn whole(kind: PolyErrorKind) -> Self {
        PolyError { kind, at: None }
    }
}

impl From<PolyErrorKind> for PolyError {
    fn from(kind: PolyErrorKind) -> Self {
        PolyError::whole(kind)
    }
}

/// What is wrong in polynomial text ([`PolyError::kind`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum PolyErrorKind {
    /// The text is empty (or only spaces).
    #[error("empty polynomial")]
    Empty,
    /// Variable name `index` (1-based) is empty.
    #[error("variable name {index} is empty")]
    EmptyName {
        /// Its 1-based position.
        index: usize,
    },
    /// A variable name that does not start with a letter.
    #[error("variable name {index} `{name}` must start with a letter")]
    NameStart {
        /// Its 1-based position.
        index: usize,
        /// The name.
        name: String,
    },
    /// A variable name with a character other than letters, digits and `_`.
    #[error("variable name {index} `{name}` may hold only letters, digits and `_`")]
    NameCharacters {
        /// Its 1-based position.
        index: usize,
        /// The name.
        name: String,
    },
    /// A variable name given twice.
    #[error("variable name `{name}` is given twice")]
    NameTwice {
        /// The name.
        name: String,
    },
    /// A `)` that closes nothing.
    #[error("unmatched `)`")]
    UnmatchedClose,
    /// A `(` that is never closed.
    #[error("unclosed `(`")]
    Unclosed,
    /// A character where the text should have ended.
    #[error("unexpected `{found}`")]
    Unexpected {
        /// The character.
        found: char,
    },
    /// `**` with nothing before it.
    #[error("`**` without a base")]
    PowerWithoutBase,
    /// `x**2**3` and the like.
    #[error("a chained power is ambiguous (write x**(2*3) as x**6, or use parentheses)")]
    ChainedPower,
    /// An exponent with a minus sign.
    #[error("a negative exponent is not a polynomial")]
    NegativeExponent,
    /// A power with no digits after it.
    #[error("expected an exponent (a non-negative integer) after the power")]
    NoExponent,
    /// An exponent with a fraction or an exponent of its own.
    #[error("an exponent must be a non-negative integer")]
    NotIntegerExponent,
    /// An exponent (its digits, abbreviated) above [`super::MAX_DEGREE`].
    #[error("exponent {digits} is above the maximum degree {max}")]
    ExponentTooLarge {
        /// The exponent's digits (at most 24 characters, `…` when cut).
        digits: String,
        /// The limit.
        max: u32,
    },
    /// A number right after a factor (`x2`, `(u)2`).
    #[error(
        "a number after a factor needs an explicit `*` (is `{context}` meant as a product or a power?)"
    )]
    NumberAfterFactor {
        /// The characters around it.
        context: String,
    },
    /// Parentheses nested deeper than [`super::MAX_NESTING`].
    #[error("parentheses nested deeper than {max}")]
    TooDeep {
        /// The limit.
        max: usize,
    },
    /// `()`.
    #[error("empty parentheses")]
    EmptyParentheses,
    /// The text ends where a term should be.
    #[error("expected a term at the end of the text")]
    NoTermAtEnd,
    /// A character where a term should be.
    #[error("expected a term, found `{found}`")]
    NoTerm {
        /// The character found.
        found: char,
    },
    /// A number that does not read.
    #[error(transparent)]
    Number(#[from] NumberError),
    /// A number above the coefficient size limit; `at` is its 1-based character.
    #[error("the number at character {at} has more than {max} bits (the coefficient size limit)")]
    NumberTooLarge {
        /// Where the number starts.
        at: usize,
        /// The limit.
        max: u64,
    },
    /// A name that is none of the variables (`hint`: the text looks like a product or power
    /// written without its operator).
    #[error(
        "unknown variable `{word}` (expected one of {}{})",
        names.join(", "),
        if *hint { "; write a product with `*`, a power with `**` or `^`" } else { "" }
    )]
    UnknownVariable {
        /// The word found (abbreviated).
        word: String,
        /// The variables.
        names: Vec<String>,
        /// Is it a known name followed by digits or `_`?
        hint: bool,
    },
    /// A product or power whose total degree would exceed the limit.
    #[error("degree {degree} is above the maximum degree {max} of polynomial text")]
    DegreeTooHigh {
        /// The degree.
        degree: u64,
        /// The limit.
        max: u32,
    },
    /// `p^k` whose degree would exceed the limit.
    #[error(
        "exponent {exponent} gives degree {degree}, above the maximum degree {max} of polynomial text"
    )]
    PowerDegreeTooHigh {
        /// The exponent.
        exponent: u64,
        /// The degree it gives.
        degree: u64,
        /// The limit.
        max: u32,
    },
    /// An exponent that does not fit the arithmetic.
    #[error("exponent too large")]
    ExponentOverflow,
    /// A coefficient that would exceed the size limit.
    #[error("a coefficient would have about {bits} bits, above the limit of {max} bits")]
    CoefficientTooLarge {
        /// Its estimated size in bits.
        bits: u64,
        /// The limit.
        max: u64,
    },
    /// A product of too many terms.
    #[error("a product of {left} by {right} terms is above the limit of {max} term products")]
    TooManyTermProducts {
        /// Terms of the left factor.
        left: usize,
        /// Terms of the right factor.
        right: usize,
        /// The limit.
        max: usize,
    },
    /// The text costs more exact arithmetic than the work limit.
    #[error(
        "the text needs more than {limit} word operations of exact arithmetic ({what}), above the work limit of polynomial text"
    )]
    TooMuchWork {
        /// The limit.
        limit: u64,
        /// What the work was for.
        what: String,
    },
    /// Division by a polynomial that is not a constant.
    #[error("the divisor is not a constant (only division by a number is a polynomial)")]
    DivisorNotConstant,
    /// Division by zero.
    #[error("division by zero")]
    DivisionByZero,
}
