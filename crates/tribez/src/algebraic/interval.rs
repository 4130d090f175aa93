//! Interval filters in integer arithmetic (docs/theory.md §16.3): the sign of a polynomial over a
//! rational interval or box, decided without exact evaluation at an algebraic number when the
//! enclosure of its values excludes zero.
//!
//! Over `[L/D, H/D]` (one common denominator `D > 0`) the integer `D^n · p(x)` for `p` of formal
//! degree `n` is enclosed by homogeneous Horner on integer intervals:
//! `acc ← acc · [L, H] + c_i · D^(n − i)`, from `i = n` down to `0`. Every operation is an
//! integer interval operation, so the enclosure is rigorous; its width shrinks linearly with
//! `H − L`, so a non-zero value's sign is found once the interval is narrow enough. A zero value
//! is never decided here: the callers fall back to exact arithmetic (a gcd with the number's
//! polynomial, or exact substitution).

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

type Q = BigRational;

/// A closed integer interval `[lo, hi]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntInterval {
    /// The lower end.
    pub lo: BigInt,
    /// The upper end.
    pub hi: BigInt,
}

impl IntInterval {
    /// The point interval `[x, x]`.
    pub fn point(x: BigInt) -> Self {
        IntInterval {
            lo: x.clone(),
            hi: x,
        }
    }

    /// The product of two intervals.
    pub fn mul(&self, o: &IntInterval) -> IntInterval {
        if self.lo == self.hi && o.lo == o.hi {
            return IntInterval::point(&self.lo * &o.lo);
        }
        let p = [
            &self.lo * &o.lo,
            &self.lo * &o.hi,
            &self.hi * &o.lo,
            &self.hi * &o.hi,
        ];
        // invariant: the array has four products
        let lo = p.iter().min().expect("four").clone();
        // invariant: the array has four products
        let hi = p.iter().max().expect("four").clone();
        IntInterval { lo, hi }
    }

    /// The sum with a number.
    pub fn add_int(&mut self, x: &BigInt) {
        self.lo += x;
        self.hi += x;
    }

    /// The sum of two intervals.
    pub fn add(&mut self, o: &IntInterval) {
        self.lo += &o.lo;
        self.hi += &o.hi;
    }

    /// The sign of every member, when they all have the same one (`Equal` only for `[0, 0]`).
    pub fn sign(&self) -> Option<Ordering> {
        if self.lo.is_positive() {
            Some(Ordering::Greater)
        } else if self.hi.is_negative() {
            Some(Ordering::Less)
        } else if self.lo.is_zero() && self.hi.is_zero() {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// A rational interval `[lo, hi]` over one common positive denominator: `[L/D, H/D]`.
#[derive(Clone, Debug)]
pub struct Scaled {
    /// `L`.
    pub lo: BigInt,
    /// `H`.
    pub hi: BigInt,
    /// `D > 0`.
    pub den: BigInt,
}

impl Scaled {
    /// `[lo, hi]` over a common denominator (`lo ≤ hi`).
    pub fn new(lo: &Q, hi: &Q) -> Self {
        let den = lo.denom().lcm(hi.denom());
        Scaled {
            lo: lo.numer() * (&den / lo.denom()),
            hi: hi.numer() * (&den / hi.denom()),
            den,
        }
    }

    fn interval(&self) -> IntInterval {
        IntInterval {
            lo: self.lo.clone(),
            hi: self.hi.clone(),
        }
    }
}

/// An enclosure of `D^n · p(x)` for `x` in `[L/D, H/D]`, `p = Σ c_i x^i` with integer
/// coefficients and formal degree `n ≥ c.len() − 1` (the factor `D^n` is positive).
pub fn horner_scaled(c: &[BigInt], n: usize, x: &Scaled) -> IntInterval {
    debug_assert!(c.len() <= n + 1);
    let xi = x.interval();
    let mut acc = IntInterval::point(BigInt::zero());
    let mut dpow = BigInt::one();
    // from i = n down to 0: acc ← acc·x + c_i·D^(n − i)
    for i in (0..=n).rev() {
        if i < n {
            acc = acc.mul(&xi);
        }
        if let Some(ci) = c.get(i)
            && !ci.is_zero()
        {
            acc.add_int(&(ci * &dpow));
        }
        dpow *= &x.den;
    }
    acc
}

/// The sign of the integer polynomial `c` on all of `[lo, hi]` when the interval enclosure
/// decides it (`None` otherwise).
pub fn sign_on(c: &[BigInt], lo: &Q, hi: &Q) -> Option<Ordering> {
    if c.is_empty() {
        return Some(Ordering::Equal);
    }
    horner_scaled(c, c.len() - 1, &Scaled::new(lo, hi)).sign()
}

/// A bivariate polynomial `Σ c[j][i] x^i y^j` with integer coefficients (a positive multiple of
/// a [`super::BiPoly`]), for box filters.
#[derive(Clone, Debug)]
pub struct IntBiPoly {
    c: Vec<Vec<BigInt>>,
    deg_x: usize,
}

impl IntBiPoly {
    /// A positive integer multiple of `p` (the lcm of all denominators).
    pub fn from_bipoly(p: &super::BiPoly) -> Self {
        let l =
            p.c.iter()
                .flatten()
                .fold(BigInt::one(), |l, x| l.lcm(x.denom()));
        let c: Vec<Vec<BigInt>> =
            p.c.iter()
                .map(|row| row.iter().map(|x| x.numer() * (&l / x.denom())).collect())
                .collect();
        let deg_x = c
            .iter()
            .map(|r| r.len().saturating_sub(1))
            .max()
            .unwrap_or(0);
        IntBiPoly { c, deg_x }
    }

    /// The sign of the polynomial on the whole box `x × y` when the interval enclosure decides
    /// it (`None` otherwise).
    pub fn sign_on_box(&self, x: &Scaled, y: &Scaled) -> Option<Ordering> {
        if self.c.is_empty() {
            return Some(Ordering::Equal);
        }
        let n = self.c.len() - 1;
        let yi = y.interval();
        let mut acc = IntInterval::point(BigInt::zero());
        let mut dpow = BigInt::one();
        for j in (0..=n).rev() {
            if j < n {
                acc = acc.mul(&yi);
            }
            let mut cj = horner_scaled(&self.c[j], self.deg_x, x);
            if !dpow.is_one() {
                cj = cj.mul(&IntInterval::point(dpow.clone()));
            }
            acc.add(&cj);
            dpow *= &y.den;
        }
        acc.sign()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Q {
        crate::number::parse_rational(s).unwrap()
    }

    #[test]
    fn horner_encloses_and_decides_signs() {
        // x^2 − 2 on [7/5, 3/2]: values in [49/25 − 2, 9/4 − 2] = [−1/25, 1/4]: undecided
        let p = [BigInt::from(-2), BigInt::zero(), BigInt::one()];
        assert_eq!(sign_on(&p, &q("7/5"), &q("3/2")), None);
        // on [3/2, 2]: [1/4, 2] → positive; on [0, 1]: x·x ∈ [0, 1] → [−2, −1] negative
        assert_eq!(sign_on(&p, &q("3/2"), &q("2")), Some(Ordering::Greater));
        assert_eq!(sign_on(&p, &q("0"), &q("1")), Some(Ordering::Less));
        // scaled enclosure on [1/3, 1/2] (D = 6, L = 2, H = 3): 36·(x^2 − 2) ∈ [4 − 72, 9 − 72]
        let e = horner_scaled(&p, 2, &Scaled::new(&q("1/3"), &q("1/2")));
        assert_eq!(
            e,
            IntInterval {
                lo: BigInt::from(-68),
                hi: BigInt::from(-63)
            }
        );
    }

    #[test]
    fn box_filter_decides_away_from_zero_only() {
        // x − y on [0, 1/4] × [1/2, 1]: negative; on [0, 1] × [0, 1]: undecided
        let p = super::super::BiPoly {
            c: vec![vec![q("0"), q("1")], vec![q("-1")]],
        };
        let ip = IntBiPoly::from_bipoly(&p);
        let b = |a: &str, b: &str| Scaled::new(&q(a), &q(b));
        assert_eq!(
            ip.sign_on_box(&b("0", "1/4"), &b("1/2", "1")),
            Some(Ordering::Less)
        );
        assert_eq!(ip.sign_on_box(&b("0", "1"), &b("0", "1")), None);
        // at a point exactly on the zero set the enclosure is [0, 0]
        assert_eq!(
            ip.sign_on_box(&b("1/3", "1/3"), &b("1/3", "1/3")),
            Some(Ordering::Equal)
        );
    }
}
