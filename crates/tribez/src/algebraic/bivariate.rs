//! Bivariate polynomials with rational coefficients, and elimination: the resultant and the
//! first subresultant with respect to one variable, computed by evaluation at integer points,
//! fraction-free determinants (Bareiss) and Newton interpolation (docs/theory.md §16.4).

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

type Q = BigRational;

/// `Σ c[j][i] x^i y^j`: a polynomial in `y` whose coefficients are polynomials in `x`
/// (ascending in both). The *formal* degree in `y` is `c.len() − 1`: leading coefficients
/// that vanish are kept, so the Sylvester matrix has the size the formal degrees give and its
/// determinant is a polynomial identity (evaluation commutes with it).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct BiPoly {
    /// `c[j]`: the coefficient of `y^j`, a polynomial in `x` (ascending).
    pub c: Vec<Vec<Q>>,
}

impl BiPoly {
    /// The formal degree in `y`.
    pub fn deg_y(&self) -> usize {
        self.c.len().saturating_sub(1)
    }

    /// The degree in `x` (of the largest coefficient list).
    pub fn deg_x(&self) -> usize {
        self.c
            .iter()
            .map(|p| p.iter().rposition(|x| !x.is_zero()).unwrap_or(0))
            .max()
            .unwrap_or(0)
    }

    /// The polynomial in `y` at `x` (formal length kept).
    pub fn at_x(&self, x: &Q) -> Vec<Q> {
        self.c.iter().map(|p| horner(p, x)).collect()
    }

    /// The same polynomial with the roles of `x` and `y` exchanged.
    pub fn swap(&self) -> BiPoly {
        let dx = self.c.iter().map(Vec::len).max().unwrap_or(0);
        let mut c = vec![vec![Q::zero(); self.c.len()]; dx];
        for (j, p) in self.c.iter().enumerate() {
            for (i, a) in p.iter().enumerate() {
                c[i][j] = a.clone();
            }
        }
        BiPoly { c }
    }

    /// The same polynomial with its actual degrees: trailing zero coefficients dropped in `x`
    /// and in `y` (an identically zero polynomial keeps one empty coefficient).
    pub fn trimmed(&self) -> BiPoly {
        let mut c: Vec<Vec<Q>> = self.c.iter().map(|p| trim(p.clone())).collect();
        while c.len() > 1 && c.last().is_some_and(Vec::is_empty) {
            c.pop();
        }
        BiPoly { c }
    }

    /// Is every coefficient zero?
    pub fn is_zero(&self) -> bool {
        self.c.iter().all(|p| p.iter().all(Zero::is_zero))
    }

    /// `Σ_j c_j(x) num(x)^j den(x)^(N − j)` with `N` the formal degree in `y`: the polynomial
    /// in `x` that `den^N · F(x, num/den)` is.
    pub fn substitute_y(&self, num: &[Q], den: &[Q]) -> Vec<Q> {
        let n = self.deg_y();
        let mut out = vec![Q::zero()];
        let mut np = vec![Q::one()];
        let mut dp: Vec<Vec<Q>> = vec![vec![Q::one()]];
        for _ in 0..n {
            // invariant: `dp` starts with one entry and only grows
            let next = mul(dp.last().expect("non-empty"), den);
            dp.push(next);
        }
        for (j, cj) in self.c.iter().enumerate() {
            let term = mul(&mul(cj, &np), &dp[n - j]);
            out = add(&out, &term);
            np = mul(&np, num);
        }
        trim(out)
    }
}

/// The value of `Σ p_i x^i` at `x`.
pub fn horner(p: &[Q], x: &Q) -> Q {
    let mut acc = Q::zero();
    for c in p.iter().rev() {
        acc = acc * x + c;
    }
    acc
}

/// The product of two polynomials (ascending).
pub fn mul(a: &[Q], b: &[Q]) -> Vec<Q> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut c = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            c[i + j] += x * y;
        }
    }
    c
}

/// The sum of two polynomials (ascending).
pub fn add(a: &[Q], b: &[Q]) -> Vec<Q> {
    let n = a.len().max(b.len());
    (0..n)
        .map(|i| {
            let mut s = a.get(i).cloned().unwrap_or_else(Q::zero);
            if let Some(y) = b.get(i) {
                s += y;
            }
            s
        })
        .collect()
}

/// Drop trailing zeros.
pub fn trim(mut p: Vec<Q>) -> Vec<Q> {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
    p
}

/// The determinant of a square matrix of rationals: rows scaled to integers, then Bareiss's
/// fraction-free elimination.
/// `p(x, y' + λx)`: the polynomial in the sheared unknown `y' = y − λx` (binomial expansion
/// of `(y' + λx)^j`).
pub fn shear(p: &BiPoly, lam: &Q) -> BiPoly {
    let n = p.c.len();
    let mut c: Vec<Vec<Q>> = vec![Vec::new(); n.max(1)];
    for (j, cj) in p.c.iter().enumerate() {
        let mut lp = Q::one(); // λ^(j − k)
        for k in (0..=j).rev() {
            // C(j, k) λ^(j−k) x^(j−k) c_j(x) y'^k
            let f = Q::from_integer(BigInt::from(crate::simplex::binomial_exact(
                j as u64, k as u64,
            ))) * &lp;
            let mut term = vec![Q::zero(); j - k];
            term.extend(cj.iter().map(|a| a * &f));
            c[k] = add(&c[k], &term);
            lp *= lam;
        }
    }
    BiPoly { c }
}

#[cfg(test)]
pub fn det(m: &[Vec<Q>]) -> Q {
    let n = m.len();
    if n == 0 {
        return Q::one();
    }
    let mut scale = BigInt::one();
    let mut a: Vec<Vec<BigInt>> = m
        .iter()
        .map(|row| {
            let l = row.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
            scale *= &l;
            row.iter().map(|x| x.numer() * (&l / x.denom())).collect()
        })
        .collect();
    let mut sign = 1;
    let mut prev = BigInt::one();
    for k in 0..n - 1 {
        if a[k][k].is_zero() {
            let Some(p) = (k + 1..n).find(|&i| !a[i][k].is_zero()) else {
                return Q::zero();
            };
            a.swap(k, p);
            sign = -sign;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = &a[i][j] * &a[k][k] - &a[i][k] * &a[k][j];
                a[i][j] = v / &prev;
            }
        }
        prev = a[k][k].clone();
    }
    let d = a[n - 1][n - 1].clone() * BigInt::from(sign);
    Q::new(d, scale)
}

/// The rows of the Sylvester-type matrix for subresultant index `j`: `q − j` shifted copies of
/// `f` and `p − j` of `g` (coefficients descending), `p + q − j` columns.
fn rows<T: Clone + Zero>(f: &[T], g: &[T], j: usize) -> Vec<Vec<T>> {
    let (p, q) = (f.len() - 1, g.len() - 1);
    let cols = p + q - j;
    let mut out = Vec::with_capacity(p + q - 2 * j);
    for (poly, copies, deg) in [(f, q - j, p), (g, p - j, q)] {
        for i in 0..copies {
            let mut row = vec![T::zero(); cols];
            for (k, c) in poly.iter().rev().enumerate() {
                row[i + k] = c.clone();
            }
            debug_assert!(i + deg < cols);
            out.push(row);
        }
    }
    out
}

/// The resultant of two polynomials in `y` (formal degrees `p, q ≥ 0`, not both zero),
/// coefficients descending in the Sylvester matrix.
#[cfg(test)]
fn res_univariate(f: &[Q], g: &[Q]) -> Q {
    det(&rows(f, g, 0))
}

/// The first subresultant `(s1, s0)` of two polynomials in `y` of formal degrees `p, q ≥ 2`.
#[cfg(test)]
fn sres1_univariate(f: &[Q], g: &[Q]) -> (Q, Q) {
    let m = rows(f, g, 1);
    let n = m.len(); // p + q − 2 rows, p + q − 1 columns
    let c1: Vec<Vec<Q>> = m.iter().map(|r| r[..n].to_vec()).collect();
    let c0: Vec<Vec<Q>> = m
        .iter()
        .map(|r| {
            let mut v = r[..n - 1].to_vec();
            v.push(r[n].clone());
            v
        })
        .collect();
    (det(&c1), det(&c0))
}

/// Newton interpolation through `(k, v_k)`, `k = 0, 1, …`: the coefficients (ascending).
#[cfg(test)]
fn interpolate(values: &[Q]) -> Vec<Q> {
    let n = values.len();
    let mut d = values.to_vec();
    for level in 1..n {
        for i in (level..n).rev() {
            d[i] = (&d[i] - &d[i - 1]) / Q::from_integer(BigInt::from(level));
        }
    }
    // Σ d_i Π_{k<i} (x − k), by Horner from the top
    let mut out = vec![Q::zero(); n];
    let mut len = 0;
    for i in (0..n).rev() {
        // out ← out·(x − i) + d_i
        let mut next = vec![Q::zero(); n];
        for (e, c) in out.iter().enumerate().take(len) {
            if c.is_zero() {
                continue;
            }
            next[e + 1] += c;
            next[e] -= c * Q::from_integer(BigInt::from(i));
        }
        next[0] += &d[i];
        out = next;
        len = (len + 1).min(n);
    }
    trim(out)
}

/// The degree bound in `x` of the resultant and subresultants of `f` and `g` in `y`.
fn bound(f: &BiPoly, g: &BiPoly) -> usize {
    g.deg_y() * f.deg_x() + f.deg_y() * g.deg_x()
}

/// `Res_y(f, g)`, a polynomial in `x` (ascending, trailing zeros dropped: empty when the
/// resultant vanishes identically, i.e. `f` and `g` share a factor of positive degree in `y`
/// or both formal leading coefficients vanish identically).
///
/// ```
/// use tribez::algebraic::{BiPoly, resultant};
/// use tribez::parse_rational;
/// let q = |s: &str| parse_rational(s).unwrap();
/// // f = y − x, g = y^2 − 2: Res_y = x^2 − 2
/// let f = BiPoly { c: vec![vec![q("0"), q("-1")], vec![q("1")]] };
/// let g = BiPoly { c: vec![vec![q("-2")], vec![], vec![q("1")]] };
/// assert_eq!(resultant(&f, &g), vec![q("-2"), q("0"), q("1")]);
/// ```
pub fn resultant(f: &BiPoly, g: &BiPoly) -> Vec<Q> {
    let d = bound(f, g);
    let (fi, lf) = integer_bipoly(f);
    let (gi, lg) = integer_bipoly(g);
    let values: Vec<BigInt> = (0..=d)
        .map(|k| {
            let x = BigInt::from(k);
            det_int(rows(&at_int(&fi, &x), &at_int(&gi, &x), 0))
        })
        .collect();
    // Res(l_f f, l_g g) = l_f^q l_g^p Res(f, g) (q rows of f, p rows of g)
    let scale = num_traits::pow(lf, g.deg_y()) * num_traits::pow(lg, f.deg_y());
    interpolate_int(&values, &scale)
}

/// `Res_y(f, g)` by rational evaluation, Bareiss on rationals and rational Newton
/// interpolation (the generic path [`resultant`] is tested against).
#[cfg(test)]
pub fn resultant_generic(f: &BiPoly, g: &BiPoly) -> Vec<Q> {
    let d = bound(f, g);
    let values: Vec<Q> = (0..=d)
        .map(|k| {
            let x = Q::from_integer(BigInt::from(k));
            res_univariate(&f.at_x(&x), &g.at_x(&x))
        })
        .collect();
    interpolate(&values)
}

/// A positive integer multiple of `p` (coefficient lists of the same formal lengths) and the
/// factor (the lcm of the denominators).
fn integer_bipoly(p: &BiPoly) -> (Vec<Vec<BigInt>>, BigInt) {
    let l =
        p.c.iter()
            .flatten()
            .fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let c =
        p.c.iter()
            .map(|row| row.iter().map(|x| x.numer() * (&l / x.denom())).collect())
            .collect();
    (c, l)
}

/// The polynomial in `y` at the integer `x` (formal length kept).
fn at_int(p: &[Vec<BigInt>], x: &BigInt) -> Vec<BigInt> {
    p.iter()
        .map(|c| {
            let mut acc = BigInt::zero();
            for a in c.iter().rev() {
                acc = acc * x + a;
            }
            acc
        })
        .collect()
}

/// The determinant of an integer matrix (Bareiss's fraction-free elimination, exact divisions).
fn det_int(mut a: Vec<Vec<BigInt>>) -> BigInt {
    let n = a.len();
    if n == 0 {
        return BigInt::one();
    }
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..n - 1 {
        if a[k][k].is_zero() {
            let Some(p) = (k + 1..n).find(|&i| !a[i][k].is_zero()) else {
                return BigInt::zero();
            };
            a.swap(k, p);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = &a[i][j] * &a[k][k] - &a[i][k] * &a[k][j];
                a[i][j] = v / &prev;
            }
        }
        prev = a[k][k].clone();
    }
    let d = a[n - 1][n - 1].clone();
    if negate { -d } else { d }
}

/// The polynomial through `(k, v_k)`, `k = 0, …, d`, divided by `scale`, exactly: with the
/// forward differences `Δ^i v_0` (integers), `d!·p(x) = Σ_i Δ^i v_0 · (d!/i!) · x(x − 1)…(x − i + 1)`
/// is an integer polynomial (nested Horner in the falling factorials), then divided by `d!·scale`.
fn interpolate_int(values: &[BigInt], scale: &BigInt) -> Vec<Q> {
    let n = values.len();
    if n == 0 {
        return Vec::new();
    }
    let d = n - 1;
    let mut diff = values.to_vec();
    for level in 1..n {
        for i in (level..n).rev() {
            let t = &diff[i] - &diff[i - 1];
            diff[i] = t;
        }
    }
    // a_i = Δ^i v_0 · d!/i!
    let mut a = diff;
    let mut f = BigInt::one(); // d!/i!, for i from d down
    for i in (0..=d).rev() {
        a[i] *= &f;
        f *= BigInt::from(i.max(1));
    }
    let dfact: BigInt = (1..=d).fold(BigInt::one(), |f, k| f * BigInt::from(k));
    // out = a_d; out ← out·(x − i) + a_i for i = d − 1 … 0
    let mut out: Vec<BigInt> = vec![a[d].clone()];
    for i in (0..d).rev() {
        let mut next = vec![BigInt::zero(); out.len() + 1];
        let ib = BigInt::from(i);
        for (e, c) in out.iter().enumerate() {
            next[e + 1] += c;
            if i > 0 {
                next[e] -= c * &ib;
            }
        }
        next[0] += &a[i];
        out = next;
    }
    let den = dfact * scale;
    trim(out.into_iter().map(|c| Q::new(c, den.clone())).collect())
}

/// The first subresultant of `f` and `g` with respect to `y`: `(s1(x), s0(x))` with
/// `S_1 = s1·y + s0` (formal degrees at least 1; when one of them is 1 that polynomial itself).
/// Where `s1(x0) ≠ 0` and `Res_y(f, g)(x0) = 0`, the common root in `y` is unique and equals
/// `−s0(x0)/s1(x0)`.
pub fn subresultant1(f: &BiPoly, g: &BiPoly) -> (Vec<Q>, Vec<Q>) {
    for h in [f, g] {
        if h.deg_y() == 1 {
            return (trim(h.c[1].clone()), trim(h.c[0].clone()));
        }
    }
    if f.deg_y() == 0 || g.deg_y() == 0 {
        // no first subresultant: report s1 = 0 (every root then has to be resolved otherwise)
        return (Vec::new(), Vec::new());
    }
    let d = bound(f, g);
    let (fi, lf) = integer_bipoly(f);
    let (gi, lg) = integer_bipoly(g);
    let (mut v1, mut v0) = (Vec::with_capacity(d + 1), Vec::with_capacity(d + 1));
    for k in 0..=d {
        let x = BigInt::from(k);
        let m = rows(&at_int(&fi, &x), &at_int(&gi, &x), 1);
        let n = m.len(); // p + q − 2 rows, p + q − 1 columns
        let c1: Vec<Vec<BigInt>> = m.iter().map(|r| r[..n].to_vec()).collect();
        let c0: Vec<Vec<BigInt>> = m
            .iter()
            .map(|r| {
                let mut v = r[..n - 1].to_vec();
                v.push(r[n].clone());
                v
            })
            .collect();
        v1.push(det_int(c1));
        v0.push(det_int(c0));
    }
    // q − 1 rows of f and p − 1 of g
    let scale = num_traits::pow(lf, g.deg_y() - 1) * num_traits::pow(lg, f.deg_y() - 1);
    (interpolate_int(&v1, &scale), interpolate_int(&v0, &scale))
}

/// The first subresultant by rational evaluation and interpolation (the generic path
/// [`subresultant1`] is tested against; formal degrees at least 2).
#[cfg(test)]
pub fn subresultant1_generic(f: &BiPoly, g: &BiPoly) -> (Vec<Q>, Vec<Q>) {
    let d = bound(f, g);
    let (mut v1, mut v0) = (Vec::with_capacity(d + 1), Vec::with_capacity(d + 1));
    for k in 0..=d {
        let x = Q::from_integer(BigInt::from(k));
        let (a, b) = sres1_univariate(&f.at_x(&x), &g.at_x(&x));
        v1.push(a);
        v0.push(b);
    }
    (interpolate(&v1), interpolate(&v0))
}

/// `P` with integer coefficients, as a polynomial in `y` over `ℤ[x]`: `p[j]` is the
/// coefficient of `y^j` (the exact arithmetic of [`gcd`] and [`div_exact`]).
type ZBi = Vec<super::IntPoly>;

fn to_zbi(p: &BiPoly) -> ZBi {
    let (c, _) = integer_bipoly(p);
    let mut z: ZBi = c.into_iter().map(super::IntPoly::new).collect();
    zbi_trim(&mut z);
    z
}

fn from_zbi(p: &[super::IntPoly]) -> BiPoly {
    let c: Vec<Vec<Q>> = p
        .iter()
        .map(|c| {
            c.coeffs()
                .iter()
                .map(|x| Q::from_integer(x.clone()))
                .collect()
        })
        .collect();
    BiPoly {
        c: if c.is_empty() { vec![Vec::new()] } else { c },
    }
}

fn zbi_trim(p: &mut ZBi) {
    while p.last().is_some_and(super::IntPoly::is_zero) {
        p.pop();
    }
}

/// The primitive part over `ℤ[x]`: every coefficient divided by the gcd of all of them (a
/// primitive polynomial in `x`) and by the gcd of the integers left; the content is returned
/// too (primitive, positive leading coefficient; zero for zero).
fn zbi_primitive(p: &[super::IntPoly]) -> (super::IntPoly, ZBi) {
    let mut g = super::IntPoly::default();
    for c in p {
        g = if g.is_zero() { c.primitive() } else { g.gcd(c) };
    }
    if g.is_zero() {
        return (g, Vec::new());
    }
    let mut q: ZBi = p
        .iter()
        .map(|c| {
            // invariant: g is the content: it divides every coefficient
            c.div_exact(&g)
                .expect("the content divides every coefficient")
        })
        .collect();
    let mut n = BigInt::zero();
    for c in &q {
        n = n.gcd(&c.content());
    }
    if !n.is_zero() && !n.is_one() {
        let d = super::IntPoly::new(vec![n]);
        // invariant: n is the gcd of the coefficients' contents: it divides each
        q = q
            .iter()
            .map(|c| c.div_exact(&d).expect("integer content"))
            .collect();
    }
    (g, q)
}

/// `prem_y(a, b)`: the remainder of `lc(b)^(deg a − deg b + 1)·a` by `b` in `ℤ[x][y]`.
fn zbi_prem(a: &[super::IntPoly], b: &[super::IntPoly]) -> ZBi {
    let db = b.len() - 1;
    let lc = b[db].clone();
    let mut r: ZBi = a.to_vec();
    zbi_trim(&mut r);
    while r.len() > db && !r.is_empty() {
        let k = r.len() - 1 - db;
        // invariant: the loop runs only while r is not empty
        let top = r.pop().expect("non-empty");
        for x in r.iter_mut() {
            *x = x.mul(&lc);
        }
        for (j, bj) in b[..db].iter().enumerate() {
            r[k + j] = r[k + j].sub(&top.mul(bj));
        }
        zbi_trim(&mut r);
    }
    r
}

/// The greatest common divisor of `a` and `b` in `ℚ[x, y]`, up to a constant factor, with
/// integer coefficients (Gauss's lemma: `gcd = gcd(cont a, cont b)·gcd(pp a, pp b)` with
/// contents and primitive parts over `ℤ[x]`, the primitive parts' gcd by the primitive
/// pseudo-remainder sequence in `y`; docs/theory.md §16.5). `gcd(0, b)` is `b`'s primitive
/// multiple; `gcd(0, 0)` is zero.
///
/// ```
/// use tribez::algebraic::{BiPoly, bivariate_gcd};
/// use tribez::parse_rational;
/// let q = |s: &str| parse_rational(s).unwrap();
/// // (y − x)(y + 1) and (y − x)(x + 2): the gcd is y − x (up to a constant)
/// let a = BiPoly { c: vec![vec![q("0"), q("-1")], vec![q("1"), q("-1")], vec![q("1")]] };
/// let b = BiPoly { c: vec![vec![q("0"), q("-2"), q("-1")], vec![q("2"), q("1")]] };
/// let g = bivariate_gcd(&a, &b).trimmed();
/// assert_eq!(g.c.len(), 2);
/// assert_eq!(g.c[0].len(), 2);
/// assert_eq!(&g.c[0][1] + &g.c[1][0], q("0"));
/// ```
pub fn gcd(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let (za, zb) = (to_zbi(a), to_zbi(b));
    if za.is_empty() {
        return from_zbi(&zbi_primitive(&zb).1);
    }
    if zb.is_empty() {
        return from_zbi(&zbi_primitive(&za).1);
    }
    let (ca, mut pa) = zbi_primitive(&za);
    let (cb, mut pb) = zbi_primitive(&zb);
    let c = ca.gcd(&cb);
    if pa.len() < pb.len() {
        std::mem::swap(&mut pa, &mut pb);
    }
    while !pb.is_empty() {
        let r = zbi_prem(&pa, &pb);
        pa = pb;
        pb = zbi_primitive(&r).1;
    }
    let g: ZBi = if pa.len() <= 1 {
        vec![c]
    } else {
        pa.iter().map(|x| x.mul(&c)).collect()
    };
    from_zbi(&g)
}

/// The exact quotient `a / b` of univariate polynomials over `ℚ` (ascending) when `b ≠ 0`
/// divides `a` (`None` otherwise).
fn div_q(a: &[Q], b: &[Q]) -> Option<Vec<Q>> {
    let b = trim(b.to_vec());
    let mut r = trim(a.to_vec());
    let db = b.len().checked_sub(1)?;
    if r.is_empty() {
        return Some(Vec::new());
    }
    if r.len() <= db {
        return None;
    }
    let mut quot = vec![Q::zero(); r.len() - db];
    while r.len() > db {
        let k = r.len() - 1 - db;
        let qk = r[r.len() - 1].clone() / &b[db];
        for (j, bj) in b.iter().enumerate() {
            r[k + j] -= &qk * bj;
        }
        r.pop();
        quot[k] = qk;
        r = trim(r);
    }
    r.is_empty().then_some(quot)
}

/// The exact quotient `a / b` in `ℚ[x, y]` when `b ≠ 0` divides `a` (`None` otherwise): long
/// division in `y`, each quotient coefficient an exact division in `ℚ[x]`.
pub fn div_exact(a: &BiPoly, b: &BiPoly) -> Option<BiPoly> {
    let b = b.trimmed();
    let mut r = a.trimmed();
    if b.is_zero() {
        return None;
    }
    if r.is_zero() {
        return Some(BiPoly {
            c: vec![Vec::new()],
        });
    }
    let db = b.c.len() - 1;
    if r.c.len() <= db {
        return None;
    }
    let mut quot = vec![Vec::new(); r.c.len() - db];
    while r.c.len() > db && !r.is_zero() {
        let k = r.c.len() - 1 - db;
        // invariant: r.c.len() > db >= 0, so r has a last coefficient
        let qk = div_q(r.c.last().expect("non-empty"), &b.c[db])?;
        for (j, bj) in b.c.iter().enumerate() {
            r.c[k + j] = trim(add(
                &r.c[k + j],
                &mul(&qk, bj).iter().map(|x| -x).collect::<Vec<_>>(),
            ));
        }
        if !r.c[k + db].is_empty() {
            return None;
        }
        quot[k] = qk;
        r = r.trimmed();
    }
    r.is_zero().then_some(BiPoly { c: quot })
}
