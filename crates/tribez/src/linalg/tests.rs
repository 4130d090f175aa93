//! Tests of the exact solver against independent computations: closed forms (the inverse of
//! the Hilbert matrix), the Moore–Penrose pseudoinverse by a full-rank factorisation, and the
//! optimality conditions of constrained least squares.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

use super::LinalgError;
use super::exact::{SparseRow, dense, rref};
use super::lsq::{BlockSums, NormalEquations, Regularize, solve_least_squares};
use super::modp::{self, PRIMES};
use super::psd::solve_psd;

fn q(n: i64) -> BigRational {
    BigRational::from_integer(n.into())
}

fn sparse(m: &[Vec<BigRational>]) -> Vec<SparseRow> {
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

fn mat_vec(m: &[Vec<BigRational>], x: &[BigRational]) -> Vec<BigRational> {
    m.iter()
        .map(|r| r.iter().zip(x).map(|(a, b)| a * b).sum())
        .collect()
}

fn normal_equations(b: &[Vec<BigRational>], c: &[BigRational]) -> NormalEquations {
    let n = b.first().map_or(0, Vec::len);
    let mut ne = NormalEquations::new(n);
    for (row, v) in b.iter().zip(c) {
        let r: Vec<(usize, BigRational)> = row.iter().cloned().enumerate().collect();
        ne.add_row(&r, v);
    }
    ne
}

#[test]
fn primes_are_prime() {
    for &p in &PRIMES {
        assert!(p < 1 << 31 && p > 1 << 30);
        let mut d = 2u64;
        while d * d <= p {
            assert_ne!(p % d, 0, "{p} is divisible by {d}");
            d += 1;
        }
    }
}

#[test]
fn inverse_mod_p() {
    let p = PRIMES[0];
    for a in [1u64, 2, 3, 12345, p - 1] {
        assert_eq!(modp::mul(a, modp::inv(a, p), p), 1);
    }
    assert_eq!(modp::reduce(&BigInt::from(-1), p), p - 1);
}

/// The Hilbert matrix `H_ij = 1/(i + j − 1)` has the integer inverse
/// `(−1)^{i+j} (i+j−1) C(n+i−1, n−j) C(n+j−1, n−i) C(i+j−2, i−1)²` (Choi, "Tricks or treats with
/// the Hilbert matrix", 1983): the solver's exact solution of `H y = e_1` is its first column.
#[test]
fn hilbert_inverse_closed_form() {
    fn binom(n: i64, k: i64) -> BigInt {
        if k < 0 || k > n {
            return BigInt::zero();
        }
        (0..k).fold(BigInt::one(), |acc, i| acc * (n - i) / (i + 1))
    }
    for n in [3i64, 6, 10] {
        let h: Vec<Vec<BigRational>> = (1..=n)
            .map(|i| {
                (1..=n)
                    .map(|j| BigRational::new(1.into(), (i + j - 1).into()))
                    .collect()
            })
            .collect();
        let mut e1 = vec![q(0); n as usize];
        e1[0] = q(1);
        let sol = solve_psd(&sparse(&h), &e1).unwrap();
        assert_eq!(sol.rank, n as usize);
        assert!(sol.kernel.is_empty());
        for i in 1..=n {
            let j = 1;
            let sign = if (i + j) % 2 == 0 { 1 } else { -1 };
            let v = BigInt::from(sign * (i + j - 1))
                * binom(n + i - 1, n - j)
                * binom(n + j - 1, n - i)
                * binom(i + j - 2, i - 1).pow(2);
            assert_eq!(
                sol.y[(i - 1) as usize],
                BigRational::from_integer(v),
                "n={n} i={i}"
            );
        }
    }
}

#[test]
fn rank_deficiency_names_the_unknowns() {
    // Unknowns x0, x1, x2, x3: the rows see x0, and x1 + x2 only; x3 never.
    let rows = [
        (vec![(0, q(1))], q(2)),
        (vec![(0, q(1)), (1, q(1)), (2, q(1))], q(5)),
        (vec![(1, q(1)), (2, q(1))], q(4)),
    ];
    let mut ne = NormalEquations::new(4);
    for (r, v) in &rows {
        ne.add_row(r, v);
    }
    match solve_least_squares(&ne, &[], Regularize::No) {
        Err(LinalgError::RankDeficient {
            undetermined,
            rank,
            dimension,
        }) => {
            assert_eq!(undetermined, [1, 2, 3]);
            assert_eq!((rank, dimension), (2, 4));
        }
        other => panic!("{other:?}"),
    }
    // Minimum norm: with s = x1 + x2 the residuals are x0 − 2, x0 + s − 5, s − 4; setting the
    // derivatives to zero, 2x0 + s = 7 and x0 + 2s = 9, so x0 = 5/3, s = 11/3, split evenly
    // between x1 and x2 by the least norm; x3 = 0. Each residual is ∓1/3: RSS = 1/3.
    let fit = solve_least_squares(&ne, &[], Regularize::MinimumNorm).unwrap();
    let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    assert_eq!(fit.x, [r(5, 3), r(11, 6), r(11, 6), q(0)]);
    assert_eq!(fit.undetermined, [1, 2, 3]);
    assert_eq!(fit.rss, r(1, 3));
}

#[test]
fn constrained_fit_by_hand() {
    // Fit a line c0 + c1 t to (0, 1), (1, 0), (2, 2) with the constraint c1 = c0 (rows of C:
    // c0 − c1 = 0). Then c (1 + t) ≈ y: c = Σ(1+t)y / Σ(1+t)² = (1 + 0 + 6)/(1 + 4 + 9) = 1/2.
    let mut ne = NormalEquations::new(2);
    for (t, y) in [(0, 1), (1, 0), (2, 2)] {
        ne.add_row(&[(0, q(1)), (1, q(t))], &q(y));
    }
    let c = vec![vec![(0, q(1)), (1, q(-1))]];
    let fit = solve_least_squares(&ne, &c, Regularize::No).unwrap();
    let half = BigRational::new(1.into(), 2.into());
    assert_eq!(fit.x, [half.clone(), half]);
    assert_eq!(fit.dimension, 1);
    // Residuals 1/2 − 1, 1 − 0, 3/2 − 2: 1/4 + 1 + 1/4.
    assert_eq!(fit.rss, BigRational::new(3.into(), 2.into()));
}

fn small_matrix(rows: usize, cols: usize) -> impl Strategy<Value = Vec<Vec<BigRational>>> {
    proptest::collection::vec(proptest::collection::vec((-4i64..=4, 1i64..=3), cols), rows)
        .prop_map(|m| {
            m.into_iter()
                .map(|r| {
                    r.into_iter()
                        .map(|(n, d)| BigRational::new(n.into(), d.into()))
                        .collect()
                })
                .collect()
        })
}

/// A design matrix with a chance of rank deficiency: some columns are zeroed or copied.
fn design() -> impl Strategy<Value = (Vec<Vec<BigRational>>, Vec<BigRational>)> {
    (1usize..=6, 1usize..=8).prop_flat_map(|(cols, rows)| {
        (
            small_matrix(rows, cols),
            proptest::collection::vec((-6i64..=6, 1i64..=4), rows),
            proptest::collection::vec(0u8..4, cols),
        )
            .prop_map(move |(mut b, c, mods)| {
                for (j, m) in mods.iter().enumerate() {
                    for row in b.iter_mut() {
                        match m {
                            0 => row[j] = BigRational::zero(),
                            1 if j > 0 => {
                                row[j] = &row[j - 1] * BigRational::from_integer(2.into())
                            }
                            _ => {}
                        }
                    }
                }
                let c = c
                    .into_iter()
                    .map(|(n, d)| BigRational::new(n.into(), d.into()))
                    .collect();
                (b, c)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// The solver's rank equals the rank by Gauss–Jordan; its solution solves the normal
    /// equations; its kernel vectors are independent (one per non-pivot, with a 1 there) and
    /// annihilated; the minimum-norm solution is the pseudoinverse's `B⁺c`.
    #[test]
    fn matches_the_pseudoinverse((b, c) in design()) {
        let ne = normal_equations(&b, &c);
        let n = ne.unknowns();
        let g: Vec<Vec<BigRational>> = (0..n).map(|i| (0..n).map(|j| ne.gram(i, j)).collect()).collect();
        let h: Vec<BigRational> = (0..n).map(|i| ne.rhs(i).clone()).collect();
        let sol = solve_psd(&sparse(&g), &h).unwrap();
        let rank = dense::rank(&b);
        prop_assert_eq!(sol.rank, rank);
        prop_assert_eq!(mat_vec(&g, &sol.y), h.clone());
        prop_assert_eq!(sol.kernel.len(), n - rank);
        for k in &sol.kernel {
            prop_assert!(mat_vec(&g, k).iter().all(Zero::is_zero));
        }
        let fit = solve_least_squares(&ne, &[], Regularize::MinimumNorm).unwrap();
        let expected = mat_vec(&dense::pseudoinverse(&b), &c);
        prop_assert_eq!(&fit.x, &expected);
        let r: Vec<BigRational> = mat_vec(&b, &fit.x).iter().zip(&c).map(|(a, v)| a - v).collect();
        prop_assert_eq!(fit.rss, r.iter().map(|v| v * v).sum::<BigRational>());
        let strict = solve_least_squares(&ne, &[], Regularize::No);
        if rank == n {
            prop_assert_eq!(strict.unwrap().x, expected);
        } else {
            let is_rank_deficient = matches!(strict, Err(LinalgError::RankDeficient { .. }));
            prop_assert!(is_rank_deficient);
        }
    }

    /// Constrained least squares (`C x = 0`): the answer satisfies the constraints and the
    /// optimality condition `Bᵀ(Bx − c) ∈ row space of C` (Lagrange), checked by ranks; and
    /// with full rank it is unique, so these conditions pin it down.
    #[test]
    fn constrained_optimality((b, c) in design(), cons in small_matrix(2, 6)) {
        let n = b[0].len();
        let cons: Vec<Vec<BigRational>> = cons.into_iter().map(|r| r[..n].to_vec()).collect();
        let ne = normal_equations(&b, &c);
        let fit = solve_least_squares(&ne, &sparse(&cons), Regularize::MinimumNorm).unwrap();
        prop_assert!(mat_vec(&cons, &fit.x).iter().all(Zero::is_zero));
        let r: Vec<BigRational> = mat_vec(&b, &fit.x).iter().zip(&c).map(|(a, v)| a - v).collect();
        let grad = mat_vec(&dense::transpose(&b), &r);
        let mut with = cons.clone();
        with.push(grad);
        prop_assert_eq!(dense::rank(&with), dense::rank(&cons));
        // Dimension of the searched space: n − rank C.
        let rc = rref(&sparse(&cons), n).pivots.len();
        prop_assert_eq!(fit.dimension, n - rc);
    }

    /// Block sums over integers equal adding the rows one by one.
    #[test]
    fn block_sums_equal_rows(rows in proptest::collection::vec(
        (proptest::collection::vec(-50i64..50, 3), 1i64..40, -30i64..30, 1i64..7), 0..12)) {
        let indices = [4usize, 0, 2];
        let mut block = BlockSums::new(3);
        let mut one_by_one = NormalEquations::new(5);
        for (beta, d, vn, vd) in &rows {
            let beta_i: Vec<BigInt> = beta.iter().map(|&b| BigInt::from(b)).collect();
            let v = BigRational::new((*vn).into(), (*vd).into());
            block.add(&beta_i, &BigInt::from(*d), &v);
            let row: Vec<(usize, BigRational)> = beta
                .iter()
                .zip(indices)
                .map(|(&b, i)| (i, BigRational::new(b.into(), (*d).into())))
                .collect();
            one_by_one.add_row(&row, &v);
        }
        let mut blocked = NormalEquations::new(5);
        blocked.add_block(&block, &indices);
        prop_assert_eq!(blocked, one_by_one);
    }
}
