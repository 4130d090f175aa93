//! What a batch is asked: the options every row is judged with.

use crate::certify::measures::Tolerance;
use crate::exact::Algorithm;
use crate::float::Precision;

#[cfg(doc)]
use super::BatchReport;

/// How every row of a batch is judged.
#[derive(Clone, Debug)]
pub struct BatchOptions {
    /// The tolerance every row is judged with.
    pub tolerance: Tolerance,
    /// Each number denotes the nearest float of this precision; `None`: numbers are exact.
    pub precision: Option<Precision>,
    /// The algorithm whose a-priori bound a `bound` tolerance uses.
    pub algorithm: Algorithm,
    /// The input columns are Cartesian coordinates in the patch's domain (else barycentric).
    pub cartesian: bool,
    /// Keep every row's figures in [`BatchReport::rows`] (memory grows with the batch).
    pub row_detail: bool,
}

impl Default for BatchOptions {
    /// Exact tolerance, exact numbers, de Casteljau, barycentric inputs.
    fn default() -> Self {
        BatchOptions {
            tolerance: Tolerance::Exact,
            precision: None,
            algorithm: Algorithm::Casteljau,
            cartesian: false,
            row_detail: false,
        }
    }
}
