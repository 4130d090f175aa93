//! Real root isolation in the Bernstein basis: Descartes' rule of signs on the Bernstein
//! coefficients over an interval, with de Casteljau subdivision at the midpoint, in integer
//! arithmetic (docs/theory.md §16.2).
//!
//! Over `[a, b]` a polynomial of degree `n` is `Σ b_i C(n, i) t^i (1 − t)^(n−i)` with
//! `x = a + (b − a) t`; the number of sign changes `V` of `(b_0, …, b_n)` (zeros skipped)
//! bounds the number of roots in the open interval and has its parity. `V = 0`: no root;
//! `V = 1` with `b_0, b_n ≠ 0`: exactly one, and `b_0, b_n` have opposite signs. Otherwise
//! the coefficients of both halves come from de Casteljau at `t = 1/2`; for a square-free
//! polynomial the recursion stops (Vincent's theorem in the Bernstein form).

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::AlgebraicError;
use super::poly::IntPoly;

/// Where a root lies: exactly at a rational, or alone in an open interval whose end points
/// the polynomial does not vanish at (and has opposite signs at).
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    /// A root at this rational.
    Exact(BigRational),
    /// Exactly one root in the open interval `(lo, hi)`.
    Open(BigRational, BigRational),
}

/// The largest number of subdivisions one isolation may take.
pub const MAX_SUBDIVISIONS: usize = 200_000;

/// `n!` as an integer.
fn factorial(n: usize) -> BigInt {
    (1..=n).fold(BigInt::one(), |f, k| f * BigInt::from(k))
}

/// Bernstein coefficients of `p` over `[a, b]`, times a positive constant (integers).
///
/// In integers only: with `a = L/D`, `b = H/D` over one denominator `D > 0` and `W = H − L`,
/// `D^n p(x)` at `x = (L + W t)/D` is `Σ a_j t^j` where `a_j = W^j · [y^j] Σ_i c_i D^(n−i) (y + L)^i`
/// (scale, Taylor shift by `L`, scale by `W`), and `n! b_i = Σ_{j ≤ i} a_j i! (n − j)!/(i − j)!`.
pub fn bernstein_on(p: &IntPoly, a: &BigRational, b: &BigRational) -> Vec<BigInt> {
    let Some(n) = p.degree() else {
        return vec![BigInt::zero()];
    };
    let den = a.denom().lcm(b.denom());
    let l = a.numer() * (&den / a.denom());
    let w = b.numer() * (&den / b.denom()) - &l;
    // c_i D^(n − i)
    let mut t: Vec<BigInt> = Vec::with_capacity(n + 1);
    let mut dpow = BigInt::one();
    for c in p.coeffs().iter().rev() {
        t.push(c * &dpow);
        dpow *= &den;
    }
    t.reverse();
    // Taylor shift by L: t(y + L)
    if !l.is_zero() {
        for i in 0..n {
            for j in (i..n).rev() {
                let x = &t[j + 1] * &l;
                t[j] += x;
            }
        }
    }
    // scale by W^j
    let mut wpow = BigInt::one();
    for x in t.iter_mut() {
        *x *= &wpow;
        wpow *= &w;
    }
    let qi = t;
    // B_i = Σ_{j ≤ i} q_j · i! (n − j)! / (i − j)!  (= n! b_i)
    let fact: Vec<BigInt> = (0..=n).map(factorial).collect();
    let mut out: Vec<BigInt> = (0..=n)
        .map(|i| {
            (0..=i)
                .filter(|&j| !qi[j].is_zero())
                .map(|j| &qi[j] * (&fact[i] * &fact[n - j] / &fact[i - j]))
                .sum()
        })
        .collect();
    reduce(&mut out);
    out
}

/// The generic rational path of [`bernstein_on`] (Horner in rationals), kept for the test
/// that the integer path equals it.
#[cfg(test)]
pub fn bernstein_on_rational(p: &IntPoly, a: &BigRational, b: &BigRational) -> Vec<BigInt> {
    let Some(n) = p.degree() else {
        return vec![BigInt::zero()];
    };
    let w = b - a;
    let mut q: Vec<BigRational> = vec![BigRational::zero(); n + 1];
    let mut len = 0;
    for c in p.coeffs().iter().rev() {
        let mut next = vec![BigRational::zero(); n + 1];
        for i in 0..len {
            next[i] += &q[i] * a;
            next[i + 1] += &q[i] * &w;
        }
        next[0] += BigRational::from_integer(c.clone());
        q = next;
        len = (len + 1).min(n + 1);
    }
    let l = q.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let qi: Vec<BigInt> = q.iter().map(|x| x.numer() * (&l / x.denom())).collect();
    let fact: Vec<BigInt> = (0..=n).map(factorial).collect();
    let mut out: Vec<BigInt> = (0..=n)
        .map(|i| {
            (0..=i)
                .filter(|&j| !qi[j].is_zero())
                .map(|j| &qi[j] * (&fact[i] * &fact[n - j] / &fact[i - j]))
                .sum()
        })
        .collect();
    reduce(&mut out);
    out
}

/// Divide by the gcd of the entries.
fn reduce(v: &mut [BigInt]) {
    let mut g = BigInt::zero();
    for x in v.iter() {
        g = g.gcd(x);
        if g.is_one() {
            return;
        }
    }
    if !g.is_zero() && !g.is_one() {
        for x in v.iter_mut() {
            *x /= &g;
        }
    }
}

/// Sign changes of the sequence, zeros skipped.
pub fn variations(b: &[BigInt]) -> usize {
    let mut last = 0i8;
    let mut v = 0;
    for x in b {
        let s = if x.is_positive() {
            1
        } else if x.is_negative() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

/// de Casteljau at `t = 1/2` on integer Bernstein coefficients: the two halves' coefficients
/// (each times a positive constant).
pub fn split(b: &[BigInt]) -> (Vec<BigInt>, Vec<BigInt>) {
    let n = b.len() - 1;
    let mut w = b.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = vec![BigInt::zero(); n + 1];
    left.push(&w[0] << n);
    right[n] = &w[n] << n;
    for k in 1..=n {
        for i in 0..=n - k {
            let t = &w[i + 1] + &w[i];
            w[i] = t;
        }
        left.push(&w[0] << (n - k));
        right[n - k] = &w[n - k] << (n - k);
    }
    reduce(&mut left);
    reduce(&mut right);
    (left, right)
}

/// The roots of the square-free polynomial `p` in the closed interval `[a, b]` (`a < b`), in
/// increasing order: a root at a rational end point of a subdivision as [`Cell::Exact`], every
/// other root alone in a [`Cell::Open`] interval.
pub fn isolate(p: &IntPoly, a: &BigRational, b: &BigRational) -> Result<Vec<Cell>, AlgebraicError> {
    let mut out = Vec::new();
    if p.degree().unwrap_or(0) == 0 {
        return Ok(out);
    }
    let w = b - a;
    let at = |c: &BigInt, k: u32| -> BigRational {
        a + &w * BigRational::new(c.clone(), BigInt::one() << k)
    };
    let coeffs = bernstein_on(p, a, b);
    if coeffs[0].is_zero() {
        out.push(Cell::Exact(a.clone()));
    }
    enum Job {
        /// Coefficients over the t-interval `[c/2^k, (c+1)/2^k]`.
        Piece(Vec<BigInt>, BigInt, u32),
        /// A root at the t-value `c/2^k`.
        Root(BigInt, u32),
    }
    let n = coeffs.len() - 1;
    let last_zero = coeffs[n].is_zero();
    let mut stack = vec![Job::Piece(coeffs, BigInt::zero(), 0u32)];
    let mut steps = 0usize;
    while let Some(job) = stack.pop() {
        let (bc, c, k) = match job {
            Job::Root(c, k) => {
                out.push(Cell::Exact(at(&c, k)));
                continue;
            }
            Job::Piece(bc, c, k) => (bc, c, k),
        };
        let v = variations(&bc);
        if v == 0 {
            continue;
        }
        if v == 1 && !bc[0].is_zero() && !bc[n].is_zero() {
            out.push(Cell::Open(at(&c, k), at(&(&c + 1), k)));
            continue;
        }
        steps += 1;
        if steps > MAX_SUBDIVISIONS {
            return Err(AlgebraicError::Isolation {
                subdivisions: MAX_SUBDIVISIONS,
            });
        }
        let (l, r) = split(&bc);
        let c2: BigInt = &c << 1;
        let mid_zero = l[n].is_zero();
        stack.push(Job::Piece(r, &c2 + 1, k + 1));
        if mid_zero {
            stack.push(Job::Root(&c2 + 1, k + 1));
        }
        stack.push(Job::Piece(l, c2, k + 1));
    }
    if last_zero {
        out.push(Cell::Exact(b.clone()));
    }
    Ok(out)
}
