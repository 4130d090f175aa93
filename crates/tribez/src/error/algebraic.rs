//! [`AlgebraicError`]: why an exact algebraic computation (root isolation, the inverse problems
//! `intersect`, `locate`, `ray`) could not give an answer. It sits with the core's errors so
//! that the file layer can carry it without depending on the algebra.

/// Why an algebraic computation could not give an answer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AlgebraicError {
    /// A polynomial whose roots were asked for is zero.
    #[error("the polynomial is zero (every number is a root)")]
    ZeroPolynomial,
    /// A degree above its cap.
    #[error("{what} has degree {degree}, above the limit {max}")]
    DegreeTooHigh {
        /// What has the degree.
        what: &'static str,
        /// Its degree.
        degree: usize,
        /// The cap.
        max: usize,
    },
    /// A number too large.
    #[error("{what} has a {bits}-bit coefficient, above the limit of {max} bits")]
    CoefficientTooLarge {
        /// What has the coefficient.
        what: &'static str,
        /// Its bit length.
        bits: u64,
        /// The cap.
        max: u64,
    },
    /// Root isolation did not finish within its subdivision budget.
    #[error("root isolation stopped after {subdivisions} subdivisions")]
    Isolation {
        /// The budget.
        subdivisions: usize,
    },
    /// The input is of a shape the operation does not take.
    #[error("{0}")]
    Shape(String),
    /// A configuration the exact algorithm does not resolve (said precisely).
    #[error("not supported: {0}")]
    Unsupported(String),
}
