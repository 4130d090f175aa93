//! The minimum-norm C0 fit when the data have fewer distinct points than the mesh has
//! ordinates (docs/theory.md §18.4), from the rows of the design matrix instead of the normal
//! equations.
//!
//! The normal matrix `G = AᵀA` (`N × N`) then has a kernel of dimension at least `N − m`
//! (`m` distinct points), and the general path ([`crate::linalg::lsq`]) lifts one kernel vector
//! per non-pivot ordinate and solves an `(N − r) × (N − r)` system for the minimum norm: with
//! the large numbers of a high degree, minutes. Here the work is `m × m`:
//!
//! * Merge equal points (their rows are equal): row `i` of `A_u` is `a_i = β_i/d_i`
//!   (integers `β_i`, `d_i > 0`; `B` the integer rows, `Δ = diag(d_i)`, `A_u = Δ⁻¹B`) with the
//!   mean `v̄_i` of its values. The objective is `Σ_i c_i (a_i x − v̄_i)² + const` (`c_i` rows at
//!   point `i`).
//! * If `B` has full row rank `m` (certified: the exact solver finds `rank BBᵀ = m`), the
//!   system `A_u x = v̄` is consistent, its solutions are exactly the minimisers, and the one of
//!   least norm is `x = A_uᵀ(A_uA_uᵀ)⁻¹v̄ = Bᵀ(BBᵀ)⁻¹Δv̄`: solve `(BBᵀ) y = Δv̄`, `x = Bᵀy`.
//!   The rank of `A` (and of `G`) is `m`.
//! * Ordinate `c` is undetermined iff some kernel vector of `B` is non-zero at `c`, i.e. iff
//!   `e_c` is not in the row space of `B`. The reduced row echelon form of `B` modulo a prime
//!   `p`, with `m` pivots (else the next prime), has pivot columns `P` with `B_P` invertible
//!   modulo `p`, hence over ℚ; `R = B_P⁻¹B` reduces modulo `p` to the echelon form. A column
//!   `c ∉ P` is undetermined (`e_c − (R_c on P)` is in the kernel); a pivot column whose row of
//!   the echelon form has a non-zero entry modulo `p` outside `P` is undetermined (that entry of
//!   `R` is non-zero over ℚ). Only a pivot column whose row is zero modulo `p` outside `P` is
//!   decided exactly: `e_c` is in the row space iff `y = (BBᵀ)⁻¹ B e_c` satisfies `Bᵀy = e_c`.
//!
//! `None` (the caller takes the general path) if `B` is not of full row rank, if `m` is above
//! [`MAX_ROWS`], or if no prime gives `m` pivots.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::Design;
use crate::linalg::exact::{IntVec, SparseRow};
use crate::linalg::modp::{PRIMES, inv, mul, reduce, sub};
use crate::linalg::psd::solve_psd;
use crate::number::{q_add, q_mul, ratio};

/// The most distinct points this path takes (its `m²` products of sparse rows).
pub(crate) const MAX_ROWS: usize = 1000;

/// A minimum-norm fit from the rows.
pub(crate) struct RowsMinNorm {
    /// The ordinates.
    pub(crate) x: Vec<BigRational>,
    /// The rank of the design matrix (the number of distinct points).
    pub(crate) rank: usize,
    /// The ordinates the data do not determine, increasing.
    pub(crate) undetermined: Vec<usize>,
    /// The residual sum of squares.
    pub(crate) rss: BigRational,
}

type IntRow = Vec<(usize, BigInt)>;

fn sparse_dot(a: &IntRow, b: &IntRow) -> BigInt {
    let (mut i, mut j, mut s) = (0, 0, BigInt::zero());
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                s += &a[i].1 * &b[j].1;
                i += 1;
                j += 1;
            }
        }
    }
    s
}

/// The minimum-norm fit of `design` with `n` ordinates (module docs), or `None`.
pub(crate) fn minimum_norm_by_rows(design: &Design, n: usize) -> Option<RowsMinNorm> {
    let m = design.distinct.len();
    if m > MAX_ROWS || m >= n {
        return None;
    }
    let b: Vec<IntRow> = design
        .distinct
        .iter()
        .map(|(r, _, _)| {
            let row = &design.rows[*r];
            let mut v: IntRow = design.indices[row.triangle]
                .iter()
                .zip(&row.beta)
                .filter(|(_, x)| !x.is_zero())
                .map(|(&g, x)| (g, x.clone()))
                .collect();
            v.sort_by_key(|e| e.0);
            v
        })
        .collect();
    let mut gram: Vec<SparseRow> = vec![Vec::new(); m];
    for i in 0..m {
        for j in i..m {
            let d = sparse_dot(&b[i], &b[j]);
            if !d.is_zero() {
                let q = BigRational::from_integer(d);
                if i != j {
                    gram[j].push((i, q.clone()));
                }
                gram[i].push((j, q));
            }
        }
    }
    for row in &mut gram {
        row.sort_by_key(|e| e.0);
    }
    // Δv̄: d_i · (sum of the values at point i) / (their count).
    let g: Vec<BigRational> = design
        .distinct
        .iter()
        .map(|(r, sum, count)| {
            let d = BigRational::from_integer(design.rows[*r].den.clone());
            q_mul(&d, &(sum / BigRational::from_integer(BigInt::from(*count))))
        })
        .collect();
    let sol = solve_psd(&gram, &g).ok()?;
    if sol.rank != m {
        return None;
    }
    let x = transpose_times(&b, &sol.y, n);
    let undetermined = undetermined(&b, &gram, n)?;
    let rss = rss_by_rows(design, &x);
    Some(RowsMinNorm {
        x,
        rank: m,
        undetermined,
        rss,
    })
}

/// `Bᵀy`, exactly.
fn transpose_times(b: &[IntRow], y: &[BigRational], n: usize) -> Vec<BigRational> {
    let yv = IntVec::from_rationals(y);
    let mut acc = vec![BigInt::zero(); n];
    for (row, yi) in b.iter().zip(&yv.num) {
        if yi.is_zero() {
            continue;
        }
        for (c, v) in row {
            acc[*c] += v * yi;
        }
    }
    acc.into_iter().map(|v| ratio(v, yv.den.clone())).collect()
}

/// The columns `c` with `e_c` outside the row space of `B` (module docs), or `None` if no
/// prime gives `m` pivots.
fn undetermined(b: &[IntRow], gram: &[SparseRow], n: usize) -> Option<Vec<usize>> {
    let m = b.len();
    'primes: for &p in &PRIMES {
        let mut w = vec![0u64; m * n];
        for (i, row) in b.iter().enumerate() {
            for (c, v) in row {
                w[i * n + c] = reduce(v, p);
            }
        }
        // Reduced row echelon form modulo p.
        let mut pivots: Vec<usize> = Vec::with_capacity(m);
        for c in 0..n {
            let r = pivots.len();
            if r == m {
                break;
            }
            let Some(pr) = (r..m).find(|&i| w[i * n + c] != 0) else {
                continue;
            };
            if pr != r {
                for j in 0..n {
                    w.swap(pr * n + j, r * n + j);
                }
            }
            let ip = inv(w[r * n + c], p);
            for j in c..n {
                w[r * n + j] = mul(w[r * n + j], ip, p);
            }
            let pivot_row: Vec<(usize, u64)> = (c..n)
                .filter(|&j| w[r * n + j] != 0)
                .map(|j| (j, w[r * n + j]))
                .collect();
            for i in 0..m {
                let f = w[i * n + c];
                if i == r || f == 0 {
                    continue;
                }
                for &(j, v) in &pivot_row {
                    w[i * n + j] = sub(w[i * n + j], mul(f, v, p), p);
                }
            }
            pivots.push(c);
        }
        if pivots.len() < m {
            continue 'primes;
        }
        let mut row_of = vec![usize::MAX; n];
        for (r, &c) in pivots.iter().enumerate() {
            row_of[c] = r;
        }
        let mut out = Vec::new();
        for c in 0..n {
            let r = row_of[c];
            if r == usize::MAX
                || (0..n).any(|j| row_of[j] == usize::MAX && w[r * n + j] != 0)
                || !in_row_space(b, gram, c, n)?
            {
                out.push(c);
            }
        }
        return Some(out);
    }
    None
}

/// Whether `e_c` is in the row space of `B` (full row rank): `y = (BBᵀ)⁻¹ B e_c`, then
/// `Bᵀy = e_c` exactly. `None` if the solver fails.
fn in_row_space(b: &[IntRow], gram: &[SparseRow], c: usize, n: usize) -> Option<bool> {
    let rhs: Vec<BigRational> = b
        .iter()
        .map(|row| {
            row.iter()
                .find(|(j, _)| *j == c)
                .map_or_else(BigRational::zero, |(_, v)| {
                    BigRational::from_integer(v.clone())
                })
        })
        .collect();
    let sol = solve_psd(gram, &rhs).ok()?;
    let x = transpose_times(b, &sol.y, n);
    Some(x.iter().enumerate().all(|(j, v)| {
        if j == c {
            v == &BigRational::from_integer(1.into())
        } else {
            v.is_zero()
        }
    }))
}

/// `Σ (f_x(x_i, y_i) − v_i)²` over every data row, exactly.
fn rss_by_rows(design: &Design, x: &[BigRational]) -> BigRational {
    let xv = IntVec::from_rationals(x);
    let mut total = BigRational::zero();
    for r in &design.rows {
        let idx = &design.indices[r.triangle];
        let s: BigInt = r
            .beta
            .iter()
            .zip(idx)
            .filter(|(b, _)| !b.is_zero())
            .map(|(b, &g)| b * &xv.num[g])
            .sum();
        let dd = &r.den * &xv.den;
        let res = ratio(s, dd) - &r.value;
        total = q_add(&total, &q_mul(&res, &res));
    }
    total
}
