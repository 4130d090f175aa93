//! Exact linear least squares: minimise `‖A x − b‖²` over `x` in the null space of a constraint
//! matrix `C` (docs/theory.md §18.2–§18.4).
//!
//! The data enter only through the normal equations `G = AᵀA`, `h = Aᵀb` and `bᵀb`
//! ([`NormalEquations`]), accumulated exactly row by row, or block by block
//! ([`BlockSums`]: rows that touch the same few unknowns, summed over integers with a common
//! denominator). The constraints are eliminated: the reduced row echelon form of `C` gives a
//! basis `Z` of its null space ([`super::exact::null_space_map`]), `x = Z y`, and `y` solves the
//! reduced normal equations `ZᵀGZ y = Zᵀh`, a symmetric positive semidefinite system solved by
//! [`super::psd::solve_psd`] with its rank certified. If the rank is short, the unknowns `x_i`
//! with a non-zero entry in some column of `Z K` (`K` a kernel basis) are not determined by the
//! data; with [`Regularize::MinimumNorm`] the solution of least Euclidean norm `‖x‖₂` among the
//! minimisers is returned, `x = x₀ + W t` with `W = Z K` and `WᵀW t = −Wᵀx₀`.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::LinalgError;
use super::exact::{IntVec, SparseRow, dot, null_space_map, rref};
use super::psd::solve_psd;
use crate::number::{q_add, q_mul, q_sub, ratio};

/// The normal equations of a least-squares problem, accumulated exactly: `G = Σ aᵢᵀaᵢ`,
/// `h = Σ bᵢ aᵢᵀ`, `bᵀb = Σ bᵢ²` over the rows `aᵢ x ≈ bᵢ`.
#[derive(Debug, Clone, PartialEq)]
pub struct NormalEquations {
    unknowns: usize,
    /// `G` by rows, both halves, non-zero entries only.
    gram: Vec<BTreeMap<usize, BigRational>>,
    rhs: Vec<BigRational>,
    bb: BigRational,
    rows: usize,
}

impl NormalEquations {
    /// No rows yet, `unknowns` unknowns.
    pub fn new(unknowns: usize) -> Self {
        NormalEquations {
            unknowns,
            gram: vec![BTreeMap::new(); unknowns],
            rhs: vec![BigRational::zero(); unknowns],
            bb: BigRational::zero(),
            rows: 0,
        }
    }

    /// Number of unknowns.
    pub fn unknowns(&self) -> usize {
        self.unknowns
    }

    /// Number of rows added.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// `G_ij`.
    pub fn gram(&self, i: usize, j: usize) -> BigRational {
        self.gram[i]
            .get(&j)
            .cloned()
            .unwrap_or_else(BigRational::zero)
    }

    /// `h_i`.
    pub fn rhs(&self, i: usize) -> &BigRational {
        &self.rhs[i]
    }

    /// `bᵀb`.
    pub fn bb(&self) -> &BigRational {
        &self.bb
    }

    /// The rows of `G` (sparse).
    pub fn gram_rows(&self) -> Vec<SparseRow> {
        self.gram
            .iter()
            .map(|r| r.iter().map(|(j, v)| (*j, v.clone())).collect())
            .collect()
    }

    fn add_gram(&mut self, i: usize, j: usize, v: &BigRational) {
        if v.is_zero() {
            return;
        }
        let e = self.gram[i].entry(j).or_insert_with(BigRational::zero);
        *e = q_add(e, v);
        if e.is_zero() {
            self.gram[i].remove(&j);
        }
    }

    /// Add one row `Σ_k row_k x_k ≈ value` (indices may repeat; they are summed). The generic
    /// exact path; [`Self::add_block`] is the fast one.
    pub fn add_row(&mut self, row: &[(usize, BigRational)], value: &BigRational) {
        let mut merged: BTreeMap<usize, BigRational> = BTreeMap::new();
        for (i, v) in row {
            let e = merged.entry(*i).or_insert_with(BigRational::zero);
            *e = q_add(e, v);
        }
        for (i, a) in &merged {
            for (j, b) in &merged {
                let v = q_mul(a, b);
                self.add_gram(*i, *j, &v);
            }
            let v = q_mul(a, value);
            self.rhs[*i] = q_add(&self.rhs[*i], &v);
        }
        self.bb = q_add(&self.bb, &q_mul(value, value));
        self.rows += 1;
    }

    /// Add the rows summed in `block`, whose local unknown `a` is the global unknown
    /// `indices[a]` (distinct).
    pub fn add_block(&mut self, block: &BlockSums, indices: &[usize]) {
        let k = block.k;
        for a in 0..k {
            for c in 0..k {
                let num = &block.gram[a * k + c];
                if !num.is_zero() {
                    let v = ratio(num.clone(), block.gram_den.clone());
                    self.add_gram(indices[a], indices[c], &v);
                }
            }
            let num = &block.rhs[a];
            if !num.is_zero() {
                let v = ratio(num.clone(), block.rhs_den.clone());
                self.rhs[indices[a]] = q_add(&self.rhs[indices[a]], &v);
            }
        }
        self.bb = q_add(&self.bb, &block.bb);
        self.rows += block.rows;
    }

    /// `‖A x − b‖² = bᵀb − 2 hᵀx + xᵀGx`, exactly, for any `x`.
    pub fn residual_sum_of_squares(&self, x: &[BigRational]) -> BigRational {
        let xv = IntVec::from_rationals(x);
        // xᵀGx: row by row over the common denominator of x.
        let mut quad = BigRational::zero();
        for (i, row) in self.gram.iter().enumerate() {
            if xv.num[i].is_zero() {
                continue;
            }
            let mut s = BigRational::zero();
            for (j, g) in row {
                if !xv.num[*j].is_zero() {
                    s = q_add(
                        &s,
                        &q_mul(g, &BigRational::from_integer(xv.num[*j].clone())),
                    );
                }
            }
            quad = q_add(
                &quad,
                &q_mul(&s, &BigRational::from_integer(xv.num[i].clone())),
            );
        }
        let den2 = &xv.den * &xv.den;
        let quad = q_mul(&quad, &ratio(BigInt::one(), den2));
        let hx = dot(&IntVec::from_rationals(&self.rhs), &xv);
        let two_hx = &hx + &hx;
        q_add(&q_sub(&self.bb, &two_hx), &quad)
    }
}

/// Sums of rows that touch the same `k` unknowns (one triangle's ordinates), over integers: a
/// row is given as integers `β` over a positive denominator `d` (`aᵢ = β/d`), and
/// `G = Σ ββᵀ/d²`, `h = Σ β v/d` are kept as integer numerators over one common denominator
/// each, rescaled only when a row brings a new factor. Equal to adding the rows one by one with
/// [`NormalEquations::add_row`] (tested).
#[derive(Debug, Clone, PartialEq)]
pub struct BlockSums {
    k: usize,
    gram: Vec<BigInt>,
    gram_den: BigInt,
    rhs: Vec<BigInt>,
    rhs_den: BigInt,
    bb: BigRational,
    rows: usize,
}

impl BlockSums {
    /// No rows, `k` local unknowns.
    pub fn new(k: usize) -> Self {
        BlockSums {
            k,
            gram: vec![BigInt::zero(); k * k],
            gram_den: BigInt::one(),
            rhs: vec![BigInt::zero(); k],
            rhs_den: BigInt::one(),
            bb: BigRational::zero(),
            rows: 0,
        }
    }

    /// Number of rows added.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Add the row `(β/d)·x ≈ value`, `d > 0`, `β.len() == k`.
    pub fn add(&mut self, beta: &[BigInt], d: &BigInt, value: &BigRational) {
        debug_assert_eq!(beta.len(), self.k);
        let k = self.k;
        let d2 = d * d;
        let f = common(&mut self.gram_den, &mut self.gram, &d2);
        for (a, ba) in beta.iter().enumerate() {
            if ba.is_zero() {
                continue;
            }
            let fa = &f * ba;
            for (c, bc) in beta.iter().enumerate().skip(a) {
                if bc.is_zero() {
                    continue;
                }
                let t = &fa * bc;
                if c != a {
                    self.gram[c * k + a] += &t;
                }
                self.gram[a * k + c] += t;
            }
        }
        if !value.is_zero() {
            let e = d * value.denom();
            let f = common(&mut self.rhs_den, &mut self.rhs, &e);
            let fv = f * value.numer();
            for (r, b) in self.rhs.iter_mut().zip(beta) {
                if !b.is_zero() {
                    *r += &fv * b;
                }
            }
            self.bb = q_add(&self.bb, &q_mul(value, value));
        }
        self.rows += 1;
    }
}

/// Make `den` a multiple of `e` (rescaling the numerators `nums`), and return `den / e`.
fn common(den: &mut BigInt, nums: &mut [BigInt], e: &BigInt) -> BigInt {
    let (q, r) = den.div_rem(e);
    if r.is_zero() {
        return q;
    }
    let l = den.lcm(e);
    let s = &l / &*den;
    for v in nums.iter_mut() {
        if !v.is_zero() {
            *v *= &s;
        }
    }
    *den = l;
    &*den / e
}

/// What to do when the data do not determine every unknown.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Regularize {
    /// An error naming the undetermined unknowns ([`LinalgError::RankDeficient`]).
    #[default]
    No,
    /// The least-squares solution of least Euclidean norm.
    MinimumNorm,
}

/// An exact least-squares solution ([`solve_least_squares`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LeastSquares {
    /// The minimiser (of least norm, if regularised).
    pub x: Vec<BigRational>,
    /// The dimension of the space searched (unknowns minus the rank of the constraints).
    pub dimension: usize,
    /// The rank of the reduced normal matrix: `dimension` when every unknown is determined.
    pub rank: usize,
    /// The unknowns the data do not determine (empty unless regularised).
    pub undetermined: Vec<usize>,
    /// The residual sum of squares `‖A x − b‖²`.
    pub rss: BigRational,
    /// A basis `W = Z K` of the directions in which the objective is constant (empty unless
    /// regularised): the kernel of the normal matrix within the space searched.
    pub kernel: Vec<Vec<BigRational>>,
}

/// Minimise `‖A x − b‖²` subject to `C x = 0` (`constraints` are the rows of `C`), exactly.
///
/// # Errors
/// [`LinalgError::RankDeficient`] when the minimiser is not unique and `regularize` is
/// [`Regularize::No`], naming the undetermined unknowns; [`LinalgError::Inconsistent`] if the
/// solver could not certify a solution (not expected).
pub fn solve_least_squares(
    ne: &NormalEquations,
    constraints: &[SparseRow],
    regularize: Regularize,
) -> Result<LeastSquares, LinalgError> {
    let n = ne.unknowns;
    let (z, free) = if constraints.is_empty() {
        let z: Vec<SparseRow> = (0..n).map(|i| vec![(i, BigRational::one())]).collect();
        (z, (0..n).collect::<Vec<_>>())
    } else {
        null_space_map(&rref(constraints, n))
    };
    let f = free.len();
    let identity = constraints.is_empty();
    // Reduced system M = ZᵀGZ, g = Zᵀh.
    let (m, g) = if identity {
        (ne.gram_rows(), ne.rhs.clone())
    } else {
        reduce(ne, &z, f)
    };
    let sol = solve_psd(&m, &g)?;
    let x0 = apply(&z, &sol.y, n);
    let w: Vec<Vec<BigRational>> = sol.kernel.iter().map(|k| apply(&z, k, n)).collect();
    let undetermined: Vec<usize> = (0..n)
        .filter(|&i| w.iter().any(|col| !col[i].is_zero()))
        .collect();
    let x = if w.is_empty() {
        x0
    } else {
        match regularize {
            Regularize::No => {
                return Err(LinalgError::RankDeficient {
                    undetermined,
                    rank: sol.rank,
                    dimension: f,
                });
            }
            Regularize::MinimumNorm => minimum_norm(&x0, &w)?,
        }
    };
    let rss = ne.residual_sum_of_squares(&x);
    Ok(LeastSquares {
        x,
        dimension: f,
        rank: sol.rank,
        undetermined: if regularize == Regularize::MinimumNorm {
            undetermined
        } else {
            Vec::new()
        },
        rss,
        kernel: w,
    })
}

/// `x = Z y`.
fn apply(z: &[SparseRow], y: &[BigRational], n: usize) -> Vec<BigRational> {
    (0..n)
        .map(|i| {
            z[i].iter().fold(BigRational::zero(), |s, (k, c)| {
                if y[*k].is_zero() {
                    s
                } else {
                    q_add(&s, &q_mul(c, &y[*k]))
                }
            })
        })
        .collect()
}

/// `M = ZᵀGZ` (sparse rows) and `g = Zᵀh`.
fn reduce(ne: &NormalEquations, z: &[SparseRow], f: usize) -> (Vec<SparseRow>, Vec<BigRational>) {
    let n = ne.unknowns;
    // T = G Z, row i: Σ_j G_ij Z_j.
    let mut m: Vec<BTreeMap<usize, BigRational>> = vec![BTreeMap::new(); f];
    let mut g = vec![BigRational::zero(); f];
    for i in 0..n {
        if z[i].is_empty() {
            continue;
        }
        let mut t: BTreeMap<usize, BigRational> = BTreeMap::new();
        for (j, gij) in &ne.gram[i] {
            for (b, zjb) in &z[*j] {
                let e = t.entry(*b).or_insert_with(BigRational::zero);
                *e = q_add(e, &q_mul(gij, zjb));
            }
        }
        for (a, zia) in &z[i] {
            for (b, tb) in &t {
                if tb.is_zero() {
                    continue;
                }
                let e = m[*a].entry(*b).or_insert_with(BigRational::zero);
                *e = q_add(e, &q_mul(zia, tb));
            }
            if !ne.rhs[i].is_zero() {
                g[*a] = q_add(&g[*a], &q_mul(zia, &ne.rhs[i]));
            }
        }
    }
    let m = m
        .into_iter()
        .map(|r| r.into_iter().filter(|(_, v)| !v.is_zero()).collect())
        .collect();
    (m, g)
}

/// The point of least norm on `x₀ + span(W)`: `x₀ + W t` with `WᵀW t = −Wᵀx₀`.
fn minimum_norm(
    x0: &[BigRational],
    w: &[Vec<BigRational>],
) -> Result<Vec<BigRational>, LinalgError> {
    let q = w.len();
    let wi: Vec<IntVec> = w.iter().map(|c| IntVec::from_rationals(c)).collect();
    let xi = IntVec::from_rationals(x0);
    let m: Vec<SparseRow> = (0..q)
        .map(|a| {
            (0..q)
                .map(|b| (b, dot(&wi[a], &wi[b])))
                .filter(|(_, v)| !v.is_zero())
                .collect()
        })
        .collect();
    let g: Vec<BigRational> = (0..q).map(|a| -dot(&wi[a], &xi)).collect();
    let t = solve_psd(&m, &g)?;
    if t.rank != q {
        return Err(LinalgError::Inconsistent { primes: 0 });
    }
    let mut x = x0.to_vec();
    for (col, ta) in w.iter().zip(&t.y) {
        if ta.is_zero() {
            continue;
        }
        for (xi, c) in x.iter_mut().zip(col) {
            if !c.is_zero() {
                *xi = q_add(xi, &q_mul(c, ta));
            }
        }
    }
    Ok(x)
}
