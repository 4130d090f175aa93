//! The exact solution of a symmetric positive semidefinite system `M y = g` with `g` in the
//! range of `M` (normal equations are always such a system), with its rank and a basis of its
//! kernel, certified (docs/theory.md §18.3).
//!
//! 1. Each row `i` of `[M | g]` is scaled by the least common denominator of its entries, giving
//!    an integer system `D M y = D g` with the same solutions and the same kernel.
//! 2. Modulo a prime `p`, Gaussian elimination with diagonal pivots ([`DiagonalLu`]) chooses
//!    pivots `S`; `(D M)_SS` is nonsingular modulo `p`, hence over ℚ.
//! 3. Dixon's lifting ([`super::dixon`]) solves, exactly, `(D M)_SS z = (D g)_S` and, for every
//!    `j ∉ S`, `(D M)_SS z_j = −(D M)_{S j}`; `y = (z on S, 0 elsewhere)` and the kernel vectors
//!    `k_j = e_j + (z_j on S)`.
//! 4. Every row of `D M y = D g` and of `D M k_j = 0` is checked exactly. Then `rank M = |S|`
//!    (a nonsingular `|S| × |S|` submatrix, and `n − |S|` independent kernel vectors), `y`
//!    solves the system and the `k_j` are a basis of the kernel. If a check fails, the prime
//!    was unlucky (it hid part of the rank) and the next prime is tried.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::LinalgError;
use super::dixon::{self, SparseInt};
use super::exact::{IntVec, SparseRow};
use super::modp::{DiagonalLu, PRIMES, reduce};

/// The solution of `M y = g` ([`solve_psd`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PsdSolution {
    /// A solution `y` (zero on the non-pivot unknowns).
    pub y: Vec<BigRational>,
    /// `rank M`.
    pub rank: usize,
    /// A basis of the kernel of `M`: one vector per non-pivot unknown `j`, with a 1 at `j`.
    pub kernel: Vec<Vec<BigRational>>,
    /// The pivots (a set of unknowns whose rows are a basis of the row space), in the order
    /// chosen.
    pub pivots: Vec<usize>,
}

/// Solve the symmetric positive semidefinite system `M y = g` exactly (module docs). `m` is
/// given by rows (each row sparse, `(column, value)`); `g` must lie in the range of `M`.
///
/// # Errors
/// [`LinalgError::Inconsistent`] if no solution verifies with any of the primes (for a
/// consistent positive semidefinite system this does not happen).
pub fn solve_psd(m: &[SparseRow], g: &[BigRational]) -> Result<PsdSolution, LinalgError> {
    let n = m.len();
    // 1. Row scaling to integers.
    let mut a = SparseInt {
        cols: n,
        rows: Vec::with_capacity(n),
    };
    let mut b = Vec::with_capacity(n);
    for (row, gi) in m.iter().zip(g) {
        let l = row
            .iter()
            .fold(gi.denom().clone(), |l, (_, v)| l.lcm(v.denom()));
        a.rows.push(
            row.iter()
                .filter(|(_, v)| !v.is_zero())
                .map(|(j, v)| (*j, v.numer() * (&l / v.denom())))
                .collect(),
        );
        b.push(gi.numer() * (&l / gi.denom()));
    }
    for &p in &PRIMES {
        if let Some(sol) = attempt(&a, &b, p) {
            return Ok(sol);
        }
    }
    Err(LinalgError::Inconsistent {
        primes: PRIMES.len(),
    })
}

fn attempt(a: &SparseInt, b: &[BigInt], p: u64) -> Option<PsdSolution> {
    let n = a.cols;
    let mut w = vec![0u64; n * n];
    for (i, row) in a.rows.iter().enumerate() {
        for (j, v) in row {
            w[i * n + j] = reduce(v, p);
        }
    }
    let lu = DiagonalLu::new(w, n, p);
    let s = lu.pivots.clone();
    let r = s.len();
    let mut in_s = vec![usize::MAX; n];
    for (t, &i) in s.iter().enumerate() {
        in_s[i] = t;
    }
    let others: Vec<usize> = (0..n).filter(|&j| in_s[j] == usize::MAX).collect();
    // Right-hand sides in pivot order: (D g)_S, then −(D M)_{S j} for each j ∉ S.
    let mut rhs: Vec<Vec<BigInt>> = Vec::with_capacity(1 + others.len());
    rhs.push(s.iter().map(|&i| b[i].clone()).collect());
    let mut col_of = vec![usize::MAX; n];
    for (k, &j) in others.iter().enumerate() {
        col_of[j] = k;
    }
    let mut kcols: Vec<Vec<BigInt>> = vec![vec![BigInt::zero(); r]; others.len()];
    for (t, &i) in s.iter().enumerate() {
        for (j, v) in &a.rows[i] {
            if col_of[*j] != usize::MAX {
                kcols[col_of[*j]][t] = -v;
            }
        }
    }
    rhs.extend(kcols);
    let z = dixon::solve(a, &lu, &rhs)?;
    let mut y = vec![BigRational::zero(); n];
    for (t, &i) in s.iter().enumerate() {
        y[i] = z[0][t].clone();
    }
    let kernel: Vec<Vec<BigRational>> = others
        .iter()
        .enumerate()
        .map(|(k, &j)| {
            let mut v = vec![BigRational::zero(); n];
            v[j] = BigRational::one();
            for (t, &i) in s.iter().enumerate() {
                v[i] = z[1 + k][t].clone();
            }
            v
        })
        .collect();
    // 4. Exact checks of the rows outside S (those in S were verified by the lifting).
    let yv = IntVec::from_rationals(&y);
    for &i in &others {
        if a.row_dot(i, &yv.num) != &yv.den * &b[i] {
            return None;
        }
    }
    for kv in &kernel {
        let kv = IntVec::from_rationals(kv);
        if others.iter().any(|&i| !a.row_dot(i, &kv.num).is_zero()) {
            return None;
        }
    }
    Some(PsdSolution {
        y,
        rank: r,
        kernel,
        pivots: s,
    })
}
