//! Dixon's p-adic lifting: the exact solution of a nonsingular integer system from one
//! factorisation modulo a prime (J. D. Dixon, "Exact solution of linear equations using p-adic
//! expansions", Numerische Mathematik 40, 1982), then rational reconstruction (Wang's
//! algorithm: the extended Euclidean algorithm stopped half-way), checked exactly
//! (docs/theory.md §18.3).
//!
//! With `A z = b` (`A` an `r × r` integer matrix, invertible modulo `p`), set `R_0 = b` and, for
//! `i = 0, 1, …`: `x_i = A⁻¹ R_i mod p`, `R_{i+1} = (R_i − A x_i)/p` (an exact division). Then
//! `A (x_0 + x_1 p + … + x_{k−1} p^{k−1}) ≡ b (mod p^k)`. Once `p^k > 2H²`, where `H` is
//! Hadamard's bound `‖b‖·Π‖a_j‖` on the numerators and the denominator of Cramer's rule, each
//! entry `n/d` of `z` is the unique fraction with `|n|, d ≤ √(p^k/2)` congruent to the lifted
//! value. Every step costs one triangular solve modulo `p` and one product with the sparse
//! integer matrix: no rational arithmetic, no growth of intermediate numbers.
//!
//! Reconstruction is tried early, at a growing schedule of `k`, and the candidate is accepted
//! only if `A n = d b` holds **exactly**: the answer is certified, and an unlucky prime only
//! costs a retry with the next one.

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::modp::{DiagonalLu, reduce};

/// A sparse integer matrix by rows: `rows[i]` lists `(column, value)` with non-zero values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SparseInt {
    /// Number of columns.
    pub cols: usize,
    /// The rows.
    pub rows: Vec<Vec<(usize, BigInt)>>,
}

impl SparseInt {
    /// `Σ_j a_ij x_j` for row `i`.
    pub fn row_dot(&self, i: usize, x: &[BigInt]) -> BigInt {
        let mut acc = BigInt::zero();
        for (j, a) in &self.rows[i] {
            if !x[*j].is_zero() {
                acc += a * &x[*j];
            }
        }
        acc
    }
}

/// Solve `A_SS z = b` for each right-hand side, where `S` is the pivot list of `lu` (a
/// factorisation modulo a prime of `a`'s restriction to `S × S`) and each `b` is given in pivot
/// order. The answers are in pivot order too.
///
/// Returns `None` if the lifted candidates do not verify by the Hadamard bound: then the prime
/// divides the determinant (impossible if `lu` is an honest factorisation) or something else is
/// inconsistent, and the caller tries another prime.
pub fn solve(a: &SparseInt, lu: &DiagonalLu, rhs: &[Vec<BigInt>]) -> Option<Vec<Vec<BigRational>>> {
    let p = lu.prime();
    let s = &lu.pivots;
    let r = s.len();
    if r == 0 {
        return Some(rhs.iter().map(|_| Vec::new()).collect());
    }
    // A_SS in pivot coordinates.
    let mut pos = vec![usize::MAX; a.cols];
    for (t, &j) in s.iter().enumerate() {
        pos[j] = t;
    }
    let ass = SparseInt {
        cols: r,
        rows: s
            .iter()
            .map(|&i| {
                a.rows[i]
                    .iter()
                    .filter(|(j, _)| pos[*j] != usize::MAX)
                    .map(|(j, v)| (pos[*j], v.clone()))
                    .collect()
            })
            .collect(),
    };
    // Hadamard: bits of Π_j max(1, ‖a_j‖) (columns) and of max over right-hand sides of ‖b‖.
    let mut col_sq = vec![BigInt::zero(); r];
    for row in &ass.rows {
        for (j, v) in row {
            col_sq[*j] += v * v;
        }
    }
    let half_bits = |x: &BigInt| x.bits().div_ceil(2);
    let mut h_bits: u64 = col_sq.iter().map(half_bits).sum();
    h_bits += rhs
        .iter()
        .map(|b| half_bits(&b.iter().map(|x| x * x).sum::<BigInt>()))
        .max()
        .unwrap_or(0);
    // p > 2^30: k steps give more than 30k bits; need p^k > 2H².
    let k_max = (2 * h_bits + 2).div_ceil(30) as usize + 1;

    let cols = rhs.len();
    let mut residual: Vec<Vec<BigInt>> = rhs.to_vec();
    let mut lifted: Vec<Vec<BigInt>> = vec![vec![BigInt::zero(); r]; cols];
    let mut answers: Vec<Option<Vec<BigRational>>> = vec![None; cols];
    let mut block: Vec<Vec<Vec<u64>>> = vec![vec![Vec::new(); r]; cols];
    let mut pk = BigInt::one(); // p^k of the digits folded into `lifted`
    let mut pending = 0usize; // digits in `block` not yet folded
    let mut denominator = BigInt::one(); // running common denominator (all divide det A_SS)
    let mut next_check = 8usize.min(k_max);
    let mut x = vec![0u64; r];
    let mut k = 0usize;
    loop {
        for c in 0..cols {
            if answers[c].is_some() {
                continue;
            }
            for (t, xt) in x.iter_mut().enumerate() {
                *xt = reduce(&residual[c][t], p);
            }
            lu.solve(&mut x);
            for (t, &d) in x.iter().enumerate() {
                block[c][t].push(d);
            }
            let xb: Vec<BigInt> = x.iter().map(|&d| BigInt::from(d)).collect();
            for (t, res) in residual[c].iter_mut().enumerate() {
                let v = &*res - ass.row_dot(t, &xb);
                debug_assert!((&v % p).is_zero());
                *res = v / p;
            }
        }
        k += 1;
        pending += 1;
        if pending == 32 || k == next_check {
            // Fold the block's digits: Σ_i d_i p^i (Horner), shifted by p^(k − pending).
            for c in 0..cols {
                if answers[c].is_some() {
                    continue;
                }
                for t in 0..r {
                    let mut v = BigInt::zero();
                    for &d in block[c][t].iter().rev() {
                        v = v * p + d;
                    }
                    block[c][t].clear();
                    if !v.is_zero() {
                        lifted[c][t] += v * &pk;
                    }
                }
            }
            pk *= BigInt::from(p).pow(pending as u32);
            pending = 0;
        }
        if k == next_check {
            let bound = (&pk >> 1u32).sqrt();
            for c in 0..cols {
                if answers[c].is_some() {
                    continue;
                }
                // A candidate denominator is kept only once its vector verified.
                let mut trial = denominator.clone();
                if let Some(z) = reconstruct_vector(&lifted[c], &pk, &bound, &mut trial)
                    .filter(|z| verify(&ass, z, &rhs[c]))
                {
                    answers[c] = Some(z);
                    denominator = trial;
                }
            }
            if answers.iter().all(Option::is_some) {
                return Some(answers.into_iter().flatten().collect());
            }
            if k >= k_max {
                return None;
            }
            next_check = (k + k.div_ceil(2)).min(k_max);
        }
    }
}

/// `A z = b` exactly, `z` rational.
fn verify(a: &SparseInt, z: &[BigRational], b: &[BigInt]) -> bool {
    // Common denominator: z = n / d.
    let d = z.iter().fold(BigInt::one(), |l, q| l.lcm(q.denom()));
    let n: Vec<BigInt> = z.iter().map(|q| q.numer() * (&d / q.denom())).collect();
    (0..a.rows.len()).all(|i| a.row_dot(i, &n) == &d * &b[i])
}

/// Reconstruct every entry of `u` (values modulo `m`) as a fraction with numerator and
/// denominator at most `bound`, sharing the running common denominator `den`: an entry `n/d`
/// whose `d` divides `den` is found by one product (`den·u mod m` is then the small numerator
/// `n·den/d`); only a new factor of the denominator costs a half extended Euclid.
fn reconstruct_vector(
    u: &[BigInt],
    m: &BigInt,
    bound: &BigInt,
    den: &mut BigInt,
) -> Option<Vec<BigRational>> {
    let half = m >> 1u32;
    let symmetric = |v: BigInt| if v > half { v - m } else { v };
    let mut out = Vec::with_capacity(u.len());
    for ui in u {
        let w = symmetric((&*den * ui).mod_floor(m));
        if w.abs() <= *bound {
            out.push(crate::number::ratio(w, den.clone()));
            continue;
        }
        let w = w.mod_floor(m);
        let (n, d) = half_gcd_reconstruct(&w, m, bound)?;
        *den *= &d;
        if *den > *bound {
            return None;
        }
        out.push(crate::number::ratio(n, den.clone()));
    }
    Some(out)
}

/// Wang's rational reconstruction: `n/d ≡ w (mod m)` with `|n| ≤ bound`, `0 < d ≤ bound`, by
/// the extended Euclidean algorithm on `(m, w)` stopped at the first remainder `≤ bound`.
fn half_gcd_reconstruct(w: &BigInt, m: &BigInt, bound: &BigInt) -> Option<(BigInt, BigInt)> {
    let (mut r0, mut r1) = (m.clone(), w.clone());
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    while r1 > *bound {
        let (q, r2) = r0.div_rem(&r1);
        let t2 = &t0 - &q * &t1;
        r0 = std::mem::replace(&mut r1, r2);
        t0 = std::mem::replace(&mut t1, t2);
    }
    if t1.is_zero() || t1.abs() > *bound {
        return None;
    }
    let (n, d) = if t1.sign() == Sign::Minus {
        (-r1, -t1)
    } else {
        (r1, t1)
    };
    Some((n, d))
}
