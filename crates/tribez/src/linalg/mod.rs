//! Exact linear algebra over the rationals for least-squares fits (docs/theory.md §18).
//!
//! * [`lsq`]: the least-squares problem: normal equations accumulated exactly
//!   ([`lsq::NormalEquations`], [`lsq::BlockSums`]), linear constraints eliminated by a
//!   null-space basis, rank certified, the minimum-norm solution on request
//!   ([`lsq::solve_least_squares`]);
//! * [`psd`]: symmetric positive semidefinite systems, solved exactly with their rank and kernel;
//! * [`dixon`]: Dixon's p-adic lifting and rational reconstruction;
//! * [`modp`]: arithmetic and elimination modulo a word-size prime;
//! * [`exact`]: Gauss–Jordan over the rationals (reduced row echelon form, null spaces), the
//!   plain path the fast one is tested against.
//!
//! Why this method: the normal matrix `G = AᵀA` of a fit is small (one row per control
//! ordinate) and sparse, but its exact solution has numerators and denominators of thousands of
//! digits (Cramer's rule: determinants of the whole matrix). Fraction-free (Bareiss) elimination
//! carries such numbers through every one of its `~n³/3` updates; Dixon's lifting does the
//! `n³` part once modulo a 31-bit prime, then `O(n²)` word operations per 31 bits of the answer,
//! and its result is checked exactly, so it is certified rather than probable.
//!
//! ```
//! use num_rational::BigRational;
//! use tribez::hazmat::linalg::lsq::{NormalEquations, Regularize, solve_least_squares};
//! let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
//! // Fit y ≈ c0 + c1·t to (0, 0), (1, 1), (2, 1): the normal equations are
//! // [3 3; 3 5] c = [2; 3], so c = (1/6, 1/2), residuals (−1/6, 1/3, −1/6), RSS 1/6.
//! let mut ne = NormalEquations::new(2);
//! for (t, y) in [(0, 0), (1, 1), (2, 1)] {
//!     ne.add_row(&[(0, q(1, 1)), (1, q(t, 1))], &q(y, 1));
//! }
//! let fit = solve_least_squares(&ne, &[], Regularize::No).unwrap();
//! assert_eq!(fit.x, [q(1, 6), q(1, 2)]);
//! assert_eq!(fit.rss, q(1, 6));
//! ```

pub mod dixon;
pub mod exact;
pub mod lsq;
pub mod modp;
pub mod psd;

#[cfg(test)]
mod tests;

/// Why an exact least-squares problem has no unique answer, or could not be solved.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum LinalgError {
    /// The data do not determine every unknown: the normal matrix (reduced by the constraints)
    /// has rank `rank` below the `dimension` of the space searched.
    #[error(
        "the data determine only {rank} of {dimension} degrees of freedom; undetermined unknowns: {undetermined:?}"
    )]
    RankDeficient {
        /// The unknowns the data leave free (0-based).
        undetermined: Vec<usize>,
        /// The rank.
        rank: usize,
        /// The dimension of the space searched.
        dimension: usize,
    },
    /// No certified solution with any of the primes tried (not expected for a consistent
    /// system; a bug if it happens).
    #[error("no exact solution could be certified (after {primes} primes)")]
    Inconsistent {
        /// How many primes were tried.
        primes: usize,
    },
}
