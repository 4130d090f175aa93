//! Multi-indices on the m-simplex, in one canonical order.
//!
//! A control point of a Bézier simplex of degree `n` over an `m`-simplex (curve `m = 1`,
//! triangle `m = 2`, tetrahedron `m = 3`, …) is labelled by a multi-index
//! `α = (α_0, …, α_m) ∈ ℕ^{m+1}` with `|α| = α_0 + … + α_m = n`; coordinate `α_k` belongs to
//! vertex `k` of the domain (for triangles `(i, j, k)` belong to `(u, v, w)`).
//!
//! **Canonical order** (docs/theory.md §1; the order of the Wikipedia article's 10×10 matrix and of the Python
//! package `bezier`): ascending in `α_m`, then `α_{m−1}`, …, then `α_1` (`α_0` is implied and
//! therefore descends). For triangles: by `k` ascending, then `j` ascending.
//!
//! ```text
//!   n = 2 triangle:  200 110 020 101 011 002
//!   n = 3 triangle:  300 210 120 030 201 111 021 102 012 003
//!
//!                 003                 row k = 3
//!               102   012             row k = 2
//!             201   111   021         row k = 1
//!           300   210   120   030     row k = 0  (the edge w = 0, from vertex 1 to vertex 2)
//! ```
//!
//! The rank (0-based position) is `rank(α) = Σ_{t=1..m} [C(s_t+t, t) − C(s_t−α_t+t, t)]` with
//! `s_t = α_0 + … + α_t`; for triangles this is `k(2n+3−k)/2 + j`.
//!
//! ```
//! use tribez::hazmat::simplex::Simplex;
//! let tri = Simplex::new(2, 3);
//! assert_eq!(tri.len(), 10);
//! assert_eq!(tri.rank(&[1, 1, 1]), 5);
//! assert_eq!(tri.index(7), &[1, 0, 2]);
//! ```

use num_bigint::BigUint;

/// Binomial coefficient `C(n, k)` as a count, to compare with a size limit: exact while the
/// computation fits `u128`, and `u128::MAX` (above every limit) past it. Never a coefficient of a
/// formula: `binomial_exact` is.
///
/// ```
/// use tribez::hazmat::simplex::binomial;
/// assert_eq!(binomial(5, 2), 10);
/// assert_eq!(binomial(2, 5), 0);
/// assert_eq!(binomial(400, 200), u128::MAX); // about 1.03e119: saturated
/// ```
pub fn binomial(n: u64, k: u64) -> u128 {
    if k > n {
        return 0;
    }
    let k = k.min(n - k);
    let mut acc: u128 = 1;
    for i in 0..k {
        // acc · (n − i) / (i + 1) = C(n, i + 1) · (i + 1)!/(i + 1)! stays an integer at every step;
        // a product past u128 means a count past every limit
        match acc.checked_mul(u128::from(n - i)) {
            Some(p) => acc = p / u128::from(i + 1),
            None => return u128::MAX,
        }
    }
    acc
}

/// Binomial coefficient `C(n, k)`, exact at any size: on a 128-bit word while it fits, then on
/// big integers (degree-200 triangles need `C(200, 100) ≈ 9.05·10^58`, beyond `u128`).
///
/// ```
/// use tribez::hazmat::simplex::binomial_exact;
/// assert_eq!(binomial_exact(5, 2).to_string(), "10");
/// // C(200, 100), from Python's math.comb(200, 100)
/// assert_eq!(
///     binomial_exact(200, 100).to_string(),
///     "90548514656103281165404177077484163874504589675413336841320"
/// );
/// ```
pub fn binomial_exact(n: u64, k: u64) -> BigUint {
    if k > n {
        return BigUint::default();
    }
    let k = k.min(n - k);
    let mut acc: u128 = 1;
    for i in 0..k {
        match acc.checked_mul(u128::from(n - i)) {
            Some(p) => acc = p / u128::from(i + 1),
            None => {
                let mut big = BigUint::from(acc);
                for i in i..k {
                    big *= n - i;
                    big /= i + 1;
                }
                return big;
            }
        }
    }
    BigUint::from(acc)
}

/// Number of multi-indices of degree `n` on the `m`-simplex: `C(n+m, m)`.
pub fn count(m: usize, n: usize) -> usize {
    // invariant: readers check the count in u128 against MAX_CONTROL_POINTS before any simplex is built (io::patch_file), and constructions stay within degree 200, m ≤ 16 (C(216, 16) < 2^64)
    usize::try_from(binomial((n + m) as u64, m as u64)).expect("simplex too large")
}

/// Multinomial coefficient `|α|! / (α_0! ⋯ α_m!)`, exact.
///
/// ```
/// use tribez::hazmat::simplex::multinomial;
/// assert_eq!(multinomial(&[1, 1, 1]).to_string(), "6");
/// assert_eq!(multinomial(&[2, 0, 1]).to_string(), "3");
/// ```
pub fn multinomial(alpha: &[u32]) -> BigUint {
    // the product of binomials C(α_0 + … + α_k, α_k), each step `acc · total / i` exact; on
    // a 128-bit word while it fits (every patch of moderate degree), then on big integers
    let mut word: u128 = 1;
    let mut total: u64 = 0;
    let mut steps = alpha.iter().flat_map(|&a| 1..=u64::from(a));
    for i in steps.by_ref() {
        total += 1;
        match word.checked_mul(u128::from(total)) {
            Some(w) => word = w / u128::from(i),
            None => {
                let mut acc = BigUint::from(word) * total / i;
                for i in steps {
                    total += 1;
                    acc *= total;
                    acc /= i;
                }
                return acc;
            }
        }
    }
    BigUint::from(word)
}

/// All multi-indices of degree `n` on the `m`-simplex, in canonical order, with rank/unrank.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Simplex {
    m: usize,
    n: usize,
    /// Flat storage: index `r` occupies `indices[r*(m+1) .. (r+1)*(m+1)]`.
    indices: Vec<u32>,
}

impl Simplex {
    /// The multi-indices of degree `n` on the `m`-simplex (`m >= 1`).
    pub fn new(m: usize, n: usize) -> Self {
        assert!(m >= 1, "a simplex has dimension at least 1");
        let len = count(m, n);
        let mut indices = Vec::with_capacity(len * (m + 1));
        let mut alpha = vec![0u32; m + 1];
        alpha[0] = n as u32;
        loop {
            indices.extend_from_slice(&alpha);
            if !next_index(&mut alpha, n as u32) {
                break;
            }
        }
        debug_assert_eq!(indices.len(), len * (m + 1));
        Simplex { m, n, indices }
    }

    /// Dimension `m` of the simplex (`m + 1` barycentric coordinates).
    pub fn dimension(&self) -> usize {
        self.m
    }

    /// Degree `n`.
    pub fn degree(&self) -> usize {
        self.n
    }

    /// Number of multi-indices, `C(n+m, m)`.
    pub fn len(&self) -> usize {
        self.indices.len() / (self.m + 1)
    }

    /// Never true: degree 0 has one index.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The multi-index of rank `r` (unrank by table look-up).
    #[allow(clippy::should_implement_trait)] // returns a slice, not `&Self::Output`
    pub fn index(&self, r: usize) -> &[u32] {
        &self.indices[r * (self.m + 1)..(r + 1) * (self.m + 1)]
    }

    /// All multi-indices in canonical order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        self.indices.chunks_exact(self.m + 1)
    }

    /// Rank of `alpha` (which must have `m + 1` entries summing to `n`).
    pub fn rank(&self, alpha: &[u32]) -> usize {
        debug_assert_eq!(alpha.len(), self.m + 1);
        rank(alpha)
    }

    /// Rank of `alpha` if it is a valid index of this simplex.
    pub fn checked_rank(&self, alpha: &[u32]) -> Option<usize> {
        let sum: u64 = alpha.iter().map(|&a| u64::from(a)).sum();
        (alpha.len() == self.m + 1 && sum == self.n as u64).then(|| rank(alpha))
    }

    /// For each index `β` of degree `n − 1`, the ranks (in this degree-`n` simplex) of
    /// `β + e_0, …, β + e_m`; flat, `m + 1` entries per `β`. This is the stencil of one
    /// de Casteljau step.
    pub fn step_stencil(&self) -> Vec<usize> {
        assert!(self.n >= 1);
        let lower = Simplex::new(self.m, self.n - 1);
        let mut out = Vec::with_capacity(lower.len() * (self.m + 1));
        let mut child = vec![0u32; self.m + 1];
        for beta in lower.iter() {
            for k in 0..=self.m {
                child.copy_from_slice(beta);
                child[k] += 1;
                out.push(rank(&child));
            }
        }
        out
    }
}

/// Rank of a multi-index in the canonical order of its degree: docs/theory.md §1,
/// `Σ_{t=1..m} [C(s_t+t, t) − C(s_t−α_t+t, t)]`, `s_t = α_0 + … + α_t`.
pub fn rank(alpha: &[u32]) -> usize {
    let mut s: u64 = u64::from(alpha[0]);
    let mut r: u128 = 0;
    for (t, &a) in alpha.iter().enumerate().skip(1) {
        let t = t as u64;
        s += u64::from(a);
        r += binomial(s + t, t) - binomial(s - u64::from(a) + t, t);
    }
    r as usize
}

/// Unrank by the closed formula of docs/theory.md §1 (no table): for `t = m` down to `1`, `α_t` is
/// the largest `a ≤ s` with `C(s+t,t) − C(s−a+t,t) ≤ r`.
pub fn unrank(m: usize, n: usize, mut r: usize) -> Vec<u32> {
    let mut alpha = vec![0u32; m + 1];
    let mut s = n as u64;
    for t in (1..=m as u64).rev() {
        let top = binomial(s + t, t);
        let mut a = 0u64;
        while a < s && top - binomial(s - (a + 1) + t, t) <= r as u128 {
            a += 1;
        }
        r -= (top - binomial(s - a + t, t)) as usize;
        alpha[t as usize] = a as u32;
        s -= a;
    }
    alpha[0] = s as u32;
    alpha
}

/// Advance `alpha` to the next multi-index in canonical order; false after the last.
fn next_index(alpha: &mut [u32], n: u32) -> bool {
    let m = alpha.len() - 1;
    // Positions 1..=m form a counter, position 1 least significant, with Σ ≤ n.
    let mut tail: u32 = alpha[1..].iter().sum();
    for t in 1..=m {
        if tail < n {
            alpha[t] += 1;
            alpha[0] = n - tail - 1;
            return true;
        }
        tail -= alpha[t];
        alpha[t] = 0;
    }
    false
}

/// The unit multi-index `e_k` scaled by `n`: the corner `k` of the net.
pub fn corner(m: usize, n: usize, k: usize) -> Vec<u32> {
    let mut a = vec![0u32; m + 1];
    a[k] = n as u32;
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(s: &Simplex) -> Vec<String> {
        s.iter()
            .map(|a| a.iter().map(|x| x.to_string()).collect::<String>())
            .collect()
    }

    #[test]
    fn canonical_order_matches_theory_section_1() {
        assert_eq!(
            names(&Simplex::new(2, 2)),
            ["200", "110", "020", "101", "011", "002"]
        );
        assert_eq!(
            names(&Simplex::new(2, 3)),
            [
                "300", "210", "120", "030", "201", "111", "021", "102", "012", "003"
            ]
        );
        assert_eq!(names(&Simplex::new(1, 3)), ["30", "21", "12", "03"]);
    }

    #[test]
    fn triangle_rank_closed_form() {
        // rank(i,j,k) = k(2n+3-k)/2 + j (docs/theory.md §1), checked against enumeration.
        for n in 0..40usize {
            let s = Simplex::new(2, n);
            for (r, a) in s.iter().enumerate() {
                let (j, k) = (a[1] as usize, a[2] as usize);
                assert_eq!(k * (2 * n + 3 - k) / 2 + j, r);
                assert_eq!(s.rank(a), r);
            }
        }
    }

    #[test]
    fn rank_unrank_any_dimension() {
        for m in 1..=5 {
            for n in 0..=7 {
                let s = Simplex::new(m, n);
                assert_eq!(s.len() as u128, binomial((n + m) as u64, m as u64));
                for (r, a) in s.iter().enumerate() {
                    assert_eq!(rank(a), r);
                    assert_eq!(unrank(m, n, r), a);
                    assert_eq!(a.iter().sum::<u32>() as usize, n);
                }
            }
        }
    }

    #[test]
    fn numbers_from_the_theory() {
        let s = Simplex::new(2, 3);
        assert_eq!(s.rank(&[1, 1, 1]), 5);
        assert_eq!(unrank(2, 3, 7), vec![1, 0, 2]);
        let tri: Vec<String> = s.iter().map(|a| multinomial(a).to_string()).collect();
        assert_eq!(tri, ["1", "3", "3", "1", "3", "6", "3", "3", "3", "1"]);
        // The trinomials of degree n sum to 3^n.
        for n in 0..12 {
            let total: BigUint = Simplex::new(2, n).iter().map(multinomial).sum();
            assert_eq!(total, BigUint::from(3u32).pow(n as u32));
        }
        // across the end of the 128-bit path: |α|! / Π α_k! from factorials on big integers
        let factorial = |k: u32| (1..=k).fold(BigUint::from(1u32), |acc, i| acc * i);
        for alpha in [
            [40u32, 40, 40],
            [0, 70, 1],
            [33, 34, 35],
            [100, 0, 0],
            [60, 61, 0],
        ] {
            let by_factorials = factorial(alpha.iter().sum())
                / alpha.iter().map(|&a| factorial(a)).product::<BigUint>();
            assert_eq!(multinomial(&alpha), by_factorials, "{alpha:?}");
        }
    }

    #[test]
    fn stencil_points_to_children() {
        let s = Simplex::new(2, 2);
        let st = s.step_stencil();
        // beta = 100 -> 200, 110, 101 ; beta = 001 -> 101, 011, 002
        assert_eq!(&st[0..3], &[0, 1, 3]);
        assert_eq!(&st[6..9], &[3, 4, 5]);
    }
}
