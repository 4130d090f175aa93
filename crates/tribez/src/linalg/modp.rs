//! Arithmetic modulo a word-size prime `p < 2^31`, and Gaussian elimination modulo `p` with
//! diagonal pivots (the first step of the exact solver, docs/theory.md §18.3).
//!
//! Values are `u64` in `0 .. p`; a product of two is below `2^62`, so `a·b mod p` needs no wider
//! type. Nothing computed here is trusted on its own: the solver verifies every answer exactly
//! over the integers, so an unlucky prime costs a retry, never a wrong result.

use num_bigint::{BigInt, Sign};
use num_traits::ToPrimitive;

/// Primes just below `2^31`, tried in order (the test `primes_are_prime` checks each by trial
/// division). Each is tried only when the previous one failed a verification, which for data of
/// a few hundred bits happens with probability far below `2^-20`.
pub const PRIMES: [u64; 8] = [
    2_147_483_647,
    2_147_483_629,
    2_147_483_587,
    2_147_483_579,
    2_147_483_563,
    2_147_483_549,
    2_147_483_543,
    2_147_483_497,
];

/// `a·b mod p`.
#[inline]
pub fn mul(a: u64, b: u64, p: u64) -> u64 {
    a * b % p
}

/// `a − b mod p`.
#[inline]
pub fn sub(a: u64, b: u64, p: u64) -> u64 {
    if a >= b { a - b } else { a + p - b }
}

/// `a^(p−2) mod p`: the inverse of `a ≠ 0` (Fermat).
pub fn inv(a: u64, p: u64) -> u64 {
    let (mut base, mut e, mut r) = (a % p, p - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            r = mul(r, base, p);
        }
        base = mul(base, base, p);
        e >>= 1;
    }
    r
}

/// `x mod p` in `0 .. p`, for any integer `x`.
pub fn reduce(x: &BigInt, p: u64) -> u64 {
    let (sign, mag) = (x.sign(), x.magnitude());
    let r = (mag % p).to_u64().unwrap_or(0);
    if sign == Sign::Minus && r != 0 {
        p - r
    } else {
        r
    }
}

/// Gaussian elimination of a square matrix modulo `p` with **diagonal** pivots, chosen in
/// index order: at each step the first not-yet-pivoted index `i` whose current diagonal entry
/// `W[i][i]` is non-zero. Elimination stops when no such index is left.
///
/// The pivots `S = (s_1, …, s_r)` (in the order chosen) and the factors are kept so that
/// [`DiagonalLu::solve`] solves `A_SS z = b_S` for the submatrix of rows and columns `S`: the
/// updates of entries inside `S × S` use only entries inside `S × S`, so the elimination
/// restricted to `S` is an LU factorisation of `A_SS` (in pivot order).
///
/// For a symmetric positive semidefinite matrix over ℚ, diagonal pivoting finds a basis of its
/// row space (a zero diagonal entry of a positive semidefinite Schur complement means a zero
/// row). Modulo `p` it can find fewer pivots; the solver detects that exactly.
#[derive(Debug, Clone)]
pub struct DiagonalLu {
    p: u64,
    n: usize,
    /// Row-major `n × n`: after elimination, row `s_a` holds the multipliers of steps `< a` in
    /// the columns `s_b` (`b < a`) and the row of `U` in the columns pivoted later.
    w: Vec<u64>,
    /// The pivots in the order chosen.
    pub pivots: Vec<usize>,
    /// The inverses of the pivot entries, in pivot order.
    inv_pivot: Vec<u64>,
}

impl DiagonalLu {
    /// Eliminate the `n × n` row-major matrix `w` (entries in `0 .. p`).
    pub fn new(mut w: Vec<u64>, n: usize, p: u64) -> Self {
        debug_assert_eq!(w.len(), n * n);
        let mut done = vec![false; n];
        let mut pivots = Vec::new();
        let mut inv_pivot = Vec::new();
        while let Some(i) = (0..n).find(|&i| !done[i] && w[i * n + i] != 0) {
            done[i] = true;
            let ip = inv(w[i * n + i], p);
            pivots.push(i);
            inv_pivot.push(ip);
            let row_i: Vec<(usize, u64)> = (0..n)
                .filter(|&j| !done[j] && w[i * n + j] != 0)
                .map(|j| (j, w[i * n + j]))
                .collect();
            for k in 0..n {
                if done[k] || w[k * n + i] == 0 {
                    continue;
                }
                let f = mul(w[k * n + i], ip, p);
                w[k * n + i] = f;
                let row_k = &mut w[k * n..(k + 1) * n];
                for &(j, v) in &row_i {
                    row_k[j] = sub(row_k[j], mul(f, v, p), p);
                }
            }
        }
        DiagonalLu {
            p,
            n,
            w,
            pivots,
            inv_pivot,
        }
    }

    /// The prime.
    pub fn prime(&self) -> u64 {
        self.p
    }

    /// Solve `A_SS z = b` modulo `p`, where `b` and `z` are indexed by pivot order
    /// (`b[a]` belongs to row `s_a`, `z[a]` to column `s_a`).
    pub fn solve(&self, b: &mut [u64]) {
        let (p, n, s) = (self.p, self.n, &self.pivots);
        let r = s.len();
        // Forward: y_a = b_a − Σ_{t<a} f(s_a, t) y_t.
        for a in 0..r {
            let row = &self.w[s[a] * n..(s[a] + 1) * n];
            let mut acc = b[a];
            for t in 0..a {
                acc = sub(acc, mul(row[s[t]], b[t], p), p);
            }
            b[a] = acc;
        }
        // Back: z_a = (y_a − Σ_{t>a} U(s_a, s_t) z_t) / U(s_a, s_a).
        for a in (0..r).rev() {
            let row = &self.w[s[a] * n..(s[a] + 1) * n];
            let mut acc = b[a];
            for t in a + 1..r {
                acc = sub(acc, mul(row[s[t]], b[t], p), p);
            }
            b[a] = mul(acc, self.inv_pivot[a], p);
        }
    }
}
