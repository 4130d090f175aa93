//! What the reports share: the worst error of one operation, algorithm and precision (what a
//! baseline records, like a libm's table of known worst cases), and the histogram of errors in
//! ULPs that batch and claim reports print.

mod histogram;

/// The error of one claimed number against its exact value, every way it is measured (the
/// coordinates of a failed batch row carry them).
pub use crate::certify::measures::Measures;
pub use histogram::{ULP_BUCKETS, UlpHistogram};

use serde::Serialize;

/// The worst error of one (operation, algorithm, precision) over a run.
///
/// Serialized as `{"op", "algorithm", "precision", "ulps", "at"}` (an entry of a baseline file).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WorstError {
    /// The operation (`eval`, or a claim's operation).
    pub op: String,
    /// The algorithm (`casteljau`, `bernstein`, or `claimed` for other code's results).
    pub algorithm: String,
    /// `f64`, `f32` or `exact`.
    pub precision: String,
    /// The worst error in ULPs.
    pub ulps: f64,
    /// Where it occurred (a point, `FILE / CLAIM`, or `FILE:LINE`).
    pub at: String,
}
