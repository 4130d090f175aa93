//! Exact rational linear algebra, the plain way: sparse rows of rationals, Gauss–Jordan
//! elimination to the reduced row echelon form, and the null-space basis it gives.
//!
//! Used for the smoothness constraints (few non-zeros, small numbers) and as the reference that
//! the fast solver ([`super::psd`]) is tested against.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::number::{q_add, q_mul, ratio};

/// A sparse rational vector: `(index, value)` with non-zero values, indices increasing.
pub type SparseRow = Vec<(usize, BigRational)>;

/// The reduced row echelon form of a set of rows over `cols` columns.
#[derive(Debug, Clone, PartialEq)]
pub struct Rref {
    /// Number of columns.
    pub cols: usize,
    /// The non-zero rows; row `i` has a 1 in column `pivots[i]` and a 0 in every other pivot
    /// column.
    pub rows: Vec<SparseRow>,
    /// The pivot column of each row.
    pub pivots: Vec<usize>,
}

/// Gauss–Jordan elimination of `rows` (each over `cols` columns), one row at a time: a row is
/// reduced by the pivot rows so far; if something is left, its **last** non-zero column becomes
/// a new pivot (so the unknowns of lowest index stay free), the row is scaled to 1 there and
/// that column is cleared from the earlier rows.
pub fn rref(rows: &[SparseRow], cols: usize) -> Rref {
    let mut out: Vec<BTreeMap<usize, BigRational>> = Vec::new();
    let mut pivots: Vec<usize> = Vec::new();
    let mut pivot_row: BTreeMap<usize, usize> = BTreeMap::new();
    for row in rows {
        let mut r: BTreeMap<usize, BigRational> =
            row.iter().filter(|(_, v)| !v.is_zero()).cloned().collect();
        // Reduce by existing pivots present in r.
        let present: Vec<usize> = r
            .keys()
            .filter(|c| pivot_row.contains_key(c))
            .copied()
            .collect();
        for c in present {
            let Some(f) = r.get(&c).cloned() else {
                continue;
            };
            let pr = &out[pivot_row[&c]];
            axpy(&mut r, &-f, pr);
        }
        let Some((&pc, pv)) = r.iter().next_back() else {
            continue;
        };
        let inv = pv.recip();
        for v in r.values_mut() {
            *v = q_mul(v, &inv);
        }
        // Clear column pc from the earlier rows.
        for prev in out.iter_mut() {
            if let Some(f) = prev.get(&pc).cloned() {
                axpy(prev, &-f, &r);
            }
        }
        pivot_row.insert(pc, out.len());
        pivots.push(pc);
        out.push(r);
    }
    Rref {
        cols,
        rows: out.into_iter().map(|r| r.into_iter().collect()).collect(),
        pivots,
    }
}

/// `r += f·s` (sparse), dropping zeros.
fn axpy(r: &mut BTreeMap<usize, BigRational>, f: &BigRational, s: &BTreeMap<usize, BigRational>) {
    for (c, v) in s {
        let t = q_mul(f, v);
        let e = r.entry(*c).or_insert_with(BigRational::zero);
        *e = q_add(e, &t);
        if e.is_zero() {
            r.remove(c);
        }
    }
}

/// A basis of the null space of the matrix whose reduced form is `rref`, as a map `x = Z y`:
/// `Z` has one column per free (non-pivot) column `f` (in increasing order), with `x_f = y_f`
/// and `x_p = −Σ_f R_{p f} y_f` for each pivot `p`. Returned by rows of `Z`: `z[i]` lists
/// `(free position, coefficient)` for unknown `i`.
pub fn null_space_map(rref: &Rref) -> (Vec<SparseRow>, Vec<usize>) {
    let mut is_pivot = vec![false; rref.cols];
    for &p in &rref.pivots {
        is_pivot[p] = true;
    }
    let free: Vec<usize> = (0..rref.cols).filter(|&c| !is_pivot[c]).collect();
    let mut free_pos = vec![usize::MAX; rref.cols];
    for (k, &f) in free.iter().enumerate() {
        free_pos[f] = k;
    }
    let mut z: Vec<SparseRow> = vec![Vec::new(); rref.cols];
    for &f in &free {
        z[f] = vec![(free_pos[f], BigRational::one())];
    }
    for (row, &p) in rref.rows.iter().zip(&rref.pivots) {
        let mut entries: SparseRow = row
            .iter()
            .filter(|(c, _)| *c != p)
            .map(|(c, v)| (free_pos[*c], -v))
            .collect();
        entries.sort_by_key(|(k, _)| *k);
        z[p] = entries;
    }
    (z, free)
}

/// A rational vector as integers over one positive common denominator.
#[derive(Debug, Clone, PartialEq)]
pub struct IntVec {
    /// The numerators.
    pub num: Vec<BigInt>,
    /// The common denominator, positive.
    pub den: BigInt,
}

impl IntVec {
    /// From rationals (the least common denominator).
    pub fn from_rationals(v: &[BigRational]) -> Self {
        let den = v.iter().fold(BigInt::one(), |l, q| l.lcm(q.denom()));
        let num = v.iter().map(|q| q.numer() * (&den / q.denom())).collect();
        IntVec { num, den }
    }

    /// Back to rationals in lowest terms.
    pub fn to_rationals(&self) -> Vec<BigRational> {
        self.num
            .iter()
            .map(|n| ratio(n.clone(), self.den.clone()))
            .collect()
    }
}

/// `Σ a_i b_i` of two rational vectors, exactly.
pub fn dot(a: &IntVec, b: &IntVec) -> BigRational {
    let s: BigInt = a
        .num
        .iter()
        .zip(&b.num)
        .filter(|(x, y)| !x.is_zero() && !y.is_zero())
        .map(|(x, y)| x * y)
        .sum();
    ratio(s, &a.den * &b.den)
}

/// Dense rational matrix helpers for tests and small problems.
#[cfg(test)]
pub mod dense {
    use super::*;

    /// The rows of a dense matrix as sparse rows (the non-zero entries with their columns).
    fn sparse_rows(m: &[Vec<BigRational>]) -> Vec<SparseRow> {
        m.iter()
            .map(|r| {
                r.iter()
                    .enumerate()
                    .filter(|(_, v)| !v.is_zero())
                    .map(|(c, v)| (c, v.clone()))
                    .collect()
            })
            .collect()
    }

    /// The rank of a dense rational matrix.
    pub fn rank(m: &[Vec<BigRational>]) -> usize {
        let cols = m.first().map_or(0, Vec::len);
        rref(&sparse_rows(m), cols).pivots.len()
    }

    /// `A B`.
    pub fn mul(a: &[Vec<BigRational>], b: &[Vec<BigRational>]) -> Vec<Vec<BigRational>> {
        let n = b.first().map_or(0, Vec::len);
        a.iter()
            .map(|row| {
                (0..n)
                    .map(|j| {
                        row.iter()
                            .zip(b)
                            .fold(BigRational::zero(), |s, (x, brow)| s + x * &brow[j])
                    })
                    .collect()
            })
            .collect()
    }

    /// `Aᵀ`.
    pub fn transpose(a: &[Vec<BigRational>]) -> Vec<Vec<BigRational>> {
        let n = a.first().map_or(0, Vec::len);
        (0..n)
            .map(|j| a.iter().map(|r| r[j].clone()).collect())
            .collect()
    }

    /// The inverse of a nonsingular matrix (Gauss–Jordan on `[A | I]`).
    pub fn inverse(a: &[Vec<BigRational>]) -> Vec<Vec<BigRational>> {
        let n = a.len();
        let mut m: Vec<Vec<BigRational>> = a
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let mut r = r.clone();
                r.extend((0..n).map(|j| {
                    if i == j {
                        BigRational::one()
                    } else {
                        BigRational::zero()
                    }
                }));
                r
            })
            .collect();
        for c in 0..n {
            let p = (c..n).find(|&i| !m[i][c].is_zero()).expect("nonsingular");
            m.swap(c, p);
            let inv = m[c][c].recip();
            for v in m[c].iter_mut() {
                *v = &*v * &inv;
            }
            for i in 0..n {
                if i != c && !m[i][c].is_zero() {
                    let f = m[i][c].clone();
                    let pivot_row = m[c].clone();
                    for (v, pv) in m[i].iter_mut().zip(&pivot_row) {
                        *v = &*v - &f * pv;
                    }
                }
            }
        }
        m.into_iter().map(|r| r[n..].to_vec()).collect()
    }

    /// The Moore–Penrose pseudoinverse by a full-rank factorisation `A = F G` (`F` the pivot
    /// columns of `A`, `G` the non-zero rows of its reduced row echelon form):
    /// `A⁺ = Gᵀ (G Gᵀ)⁻¹ (Fᵀ F)⁻¹ Fᵀ`.
    pub fn pseudoinverse(a: &[Vec<BigRational>]) -> Vec<Vec<BigRational>> {
        let cols = a.first().map_or(0, Vec::len);
        let rows = sparse_rows(a);
        // Column pivots: the rref of the rows gives the row space G; F are the columns of A at
        // the pivots of the standard (first non-zero) echelon form, which `rref` does not use,
        // so take G = rref rows (any basis of the row space) and F = A Gᵀ (G Gᵀ)⁻¹.
        let r = rref(&rows, cols);
        let g: Vec<Vec<BigRational>> = r
            .rows
            .iter()
            .map(|row| {
                let mut d = vec![BigRational::zero(); cols];
                for (c, v) in row {
                    d[*c] = v.clone();
                }
                d
            })
            .collect();
        if g.is_empty() {
            return vec![vec![BigRational::zero(); a.len()]; cols];
        }
        let gt = transpose(&g);
        let ggt_inv = inverse(&mul(&g, &gt));
        let f = mul(&mul(a, &gt), &ggt_inv);
        let ft = transpose(&f);
        let ftf_inv = inverse(&mul(&ft, &f));
        mul(&mul(&mul(&gt, &ggt_inv), &ftf_inv), &ft)
    }
}
