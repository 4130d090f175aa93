//! Univariate polynomials with integer coefficients ([`IntPoly`]): content and primitive part,
//! exact division, pseudo-remainders, gcd by the primitive remainder sequence, square-free part
//! and square-free factorisation (Yun), and the exact sign at a rational point
//! (docs/theory.md §16.1).

use std::cmp::Ordering;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// A polynomial `Σ c_i x^i` with integer coefficients, stored in ascending order without
/// trailing zeros (the zero polynomial has no coefficients).
///
/// ```
/// use tribez::algebraic::IntPoly;
/// // (x - 1)^2 (x + 2) = x^3 - 3x + 2
/// let p = IntPoly::from_i64(&[2, -3, 0, 1]);
/// assert_eq!(p.square_free(), IntPoly::from_i64(&[-2, 1, 1])); // (x - 1)(x + 2)
/// assert_eq!(p.degree(), Some(3));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct IntPoly {
    c: Vec<BigInt>,
}

impl IntPoly {
    /// The polynomial with coefficients `c` (ascending; trailing zeros dropped).
    pub fn new(mut c: Vec<BigInt>) -> Self {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        IntPoly { c }
    }

    /// From small coefficients (ascending).
    pub fn from_i64(c: &[i64]) -> Self {
        Self::new(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    /// The primitive integer polynomial with the roots of `Σ q_i x^i` (rational coefficients,
    /// ascending): the coefficients times the lcm of their denominators, divided by their gcd,
    /// with a positive leading coefficient. Zero for the zero polynomial.
    pub fn from_rationals(q: &[BigRational]) -> Self {
        let l = q.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
        Self::new(q.iter().map(|x| x.numer() * (&l / x.denom())).collect()).primitive()
    }

    /// The coefficients, ascending (empty for zero).
    pub fn coeffs(&self) -> &[BigInt] {
        &self.c
    }

    /// Is it the zero polynomial?
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// Its degree (`None` for zero).
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// The leading coefficient (zero for zero).
    pub fn lc(&self) -> BigInt {
        self.c.last().cloned().unwrap_or_default()
    }

    /// The largest bit length of a coefficient.
    pub fn max_bits(&self) -> u64 {
        self.c.iter().map(|x| x.bits()).max().unwrap_or(0)
    }

    /// The gcd of the coefficients (non-negative; zero for zero).
    pub fn content(&self) -> BigInt {
        let mut g = BigInt::zero();
        for x in &self.c {
            g = g.gcd(x);
            if g.is_one() {
                break;
            }
        }
        g
    }

    /// Divided by its content, with a positive leading coefficient (zero stays zero).
    pub fn primitive(&self) -> Self {
        let g = self.content();
        if g.is_zero() {
            return IntPoly::default();
        }
        let g = if self.lc().is_negative() { -g } else { g };
        if g.is_one() {
            return self.clone();
        }
        IntPoly {
            c: self.c.iter().map(|x| x / &g).collect(),
        }
    }

    /// The derivative.
    pub fn derivative(&self) -> Self {
        Self::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, x)| x * BigInt::from(i))
                .collect(),
        )
    }

    /// The product.
    pub fn mul(&self, o: &IntPoly) -> Self {
        if self.is_zero() || o.is_zero() {
            return IntPoly::default();
        }
        let mut c = vec![BigInt::zero(); self.c.len() + o.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in o.c.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        Self::new(c)
    }

    /// The difference.
    pub fn sub(&self, o: &IntPoly) -> Self {
        let n = self.c.len().max(o.c.len());
        Self::new(
            (0..n)
                .map(|i| {
                    self.c.get(i).cloned().unwrap_or_default()
                        - o.c.get(i).cloned().unwrap_or_default()
                })
                .collect(),
        )
    }

    /// The pseudo-remainder `prem(self, d)`: the remainder of `lc(d)^(deg self − deg d + 1)
    /// self` divided by `d` (self if its degree is lower). `d` must not be zero.
    pub fn prem(&self, d: &IntPoly) -> Self {
        let dn = d.c.len() - 1;
        let mut r = self.c.clone();
        let lc = d.lc();
        while r.len() > dn && !r.is_empty() {
            let k = r.len() - 1 - dn;
            // invariant: the loop runs only while r is not empty
            let top = r.pop().expect("non-empty");
            for x in r.iter_mut() {
                *x *= &lc;
            }
            for (j, dj) in d.c[..dn].iter().enumerate() {
                r[k + j] -= &top * dj;
            }
            while r.last().is_some_and(Zero::is_zero) {
                r.pop();
            }
        }
        Self::new(r)
    }

    /// The exact quotient `self / d` when `d` divides `self` in `ℤ[x]` (`None` otherwise).
    pub fn div_exact(&self, d: &IntPoly) -> Option<Self> {
        let dn = d.degree()?;
        if self.is_zero() {
            return Some(IntPoly::default());
        }
        let n = self.degree()?;
        if n < dn {
            return None;
        }
        let mut r = self.c.clone();
        let mut q = vec![BigInt::zero(); n - dn + 1];
        let lc = d.lc();
        for k in (0..=n - dn).rev() {
            let top = &r[k + dn];
            if top.is_zero() {
                continue;
            }
            let (qk, rem) = top.div_rem(&lc);
            if !rem.is_zero() {
                return None;
            }
            for (j, dj) in d.c.iter().enumerate() {
                r[k + j] -= &qk * dj;
            }
            q[k] = qk;
        }
        r.iter().all(Zero::is_zero).then(|| Self::new(q))
    }

    /// The greatest common divisor, primitive with a positive leading coefficient (primitive
    /// remainder sequence; `gcd(0, 0) = 0`).
    pub fn gcd(&self, o: &IntPoly) -> Self {
        if !self.is_zero() && !o.is_zero() && self.coprime_mod_p(o) {
            return IntPoly::from_i64(&[1]);
        }
        self.gcd_prs(o)
    }

    /// The gcd by the primitive remainder sequence alone (the generic path [`IntPoly::gcd`]'s
    /// modular shortcut is tested against).
    pub fn gcd_prs(&self, o: &IntPoly) -> Self {
        let (mut a, mut b) = (self.primitive(), o.primitive());
        if a.degree() < b.degree() {
            std::mem::swap(&mut a, &mut b);
        }
        while !b.is_zero() {
            let r = a.prem(&b).primitive();
            a = b;
            b = r;
        }
        a
    }

    /// The square-free part `p / gcd(p, p')`, primitive with a positive leading coefficient.
    pub fn square_free(&self) -> Self {
        let p = self.primitive();
        if p.degree().unwrap_or(0) == 0 {
            return p;
        }
        let g = p.gcd(&p.derivative());
        // invariant: gcd(p, p′) divides p
        p.div_exact(&g)
            .expect("gcd divides the polynomial")
            .primitive()
    }

    /// The square-free factorisation: primitive square-free pairwise coprime `f_i` with
    /// `self = c · Π f_i^i` (pairs `(f_i, i)` of positive degree, `i` increasing), by the gcd
    /// chain `w = p / gcd(p, p')`, `y = gcd(w, g)`, `f_i = w / y`, `g ← g / y`, `w ← y`.
    ///
    /// ```
    /// use tribez::algebraic::IntPoly;
    /// // x (x - 1)^2 = x^3 - 2x^2 + x
    /// let f = IntPoly::from_i64(&[0, 1, -2, 1]).square_free_factors();
    /// assert_eq!(f, vec![(IntPoly::from_i64(&[0, 1]), 1), (IntPoly::from_i64(&[-1, 1]), 2)]);
    /// ```
    pub fn square_free_factors(&self) -> Vec<(IntPoly, usize)> {
        let p = self.primitive();
        let mut out = Vec::new();
        if p.degree().unwrap_or(0) == 0 {
            return out;
        }
        let mut g = p.gcd(&p.derivative());
        // invariant: gcd(p, p′) divides p
        let mut w = p.div_exact(&g).expect("gcd divides").primitive();
        let mut i = 1;
        while w.degree().unwrap_or(0) > 0 {
            let y = w.gcd(&g);
            // invariant: y = gcd(w, g) divides w
            let f = w.div_exact(&y).expect("gcd divides").primitive();
            if f.degree().unwrap_or(0) > 0 {
                out.push((f, i));
            }
            // invariant: y = gcd(w, g) divides g
            g = g.div_exact(&y).expect("gcd divides").primitive();
            w = y;
            i += 1;
        }
        out
    }

    /// The sign of the polynomial at `x` (exact; homogeneous Horner in the numerator and
    /// denominator of `x`).
    pub fn sign_at(&self, x: &BigRational) -> Ordering {
        let v = self.eval_scaled(x.numer(), x.denom());
        let s = v.sign();
        let s = if x.denom().is_negative() && self.c.len().is_multiple_of(2) {
            // d^(deg) with an odd degree and a negative d flips the sign
            flip(s)
        } else {
            s
        };
        match s {
            Sign::Minus => Ordering::Less,
            Sign::NoSign => Ordering::Equal,
            Sign::Plus => Ordering::Greater,
        }
    }

    /// `d^deg · p(n/d)` (an integer).
    pub fn eval_scaled(&self, n: &BigInt, d: &BigInt) -> BigInt {
        let Some(deg) = self.degree() else {
            return BigInt::zero();
        };
        let mut acc = self.c[deg].clone();
        let mut dpow = BigInt::one();
        for i in (0..deg).rev() {
            dpow *= d;
            acc = acc * n + &self.c[i] * &dpow;
        }
        acc
    }

    /// The exact value at a rational point.
    pub fn eval(&self, x: &BigRational) -> BigRational {
        let mut acc = BigRational::zero();
        for c in self.c.iter().rev() {
            acc = acc * x + BigRational::from_integer(c.clone());
        }
        acc
    }

    /// The polynomial `p(x + k)` for an integer `k` (Taylor shift).
    pub fn shift(&self, k: &BigInt) -> Self {
        let mut c = self.c.clone();
        let n = c.len();
        for i in 0..n {
            for j in (i..n.saturating_sub(1)).rev() {
                let t = &c[j + 1] * k;
                c[j] += t;
            }
        }
        Self::new(c)
    }
}

/// The prime `2^61 − 1` for the modular coprimality test.
const P61: u64 = (1 << 61) - 1;

fn mul_mod(a: u64, b: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(P61)) as u64
}

fn pow_mod(mut a: u64, mut e: u64) -> u64 {
    let mut r = 1;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a);
        }
        a = mul_mod(a, a);
        e >>= 1;
    }
    r
}

/// The coefficients modulo `P61` (ascending, trailing zeros dropped).
fn reduce_mod(c: &[BigInt]) -> Vec<u64> {
    let p = BigInt::from(P61);
    // invariant: mod_floor by P61 gives 0 <= x < P61 < 2^61
    let mut v: Vec<u64> = c
        .iter()
        .map(|x| u64::try_from(x.mod_floor(&p)).expect("reduced"))
        .collect();
    while v.last() == Some(&0) {
        v.pop();
    }
    v
}

/// The degree of `gcd(a, b)` over `GF(P61)` (`None` when both are zero).
fn gcd_degree_mod(mut a: Vec<u64>, mut b: Vec<u64>) -> Option<usize> {
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_empty() {
        // a ← a mod b
        // invariant: the loop runs only while b is not empty
        let inv = pow_mod(*b.last().expect("non-empty"), P61 - 2);
        while a.len() >= b.len() {
            // invariant: a.len() >= b.len() >= 1 here
            let top = mul_mod(*a.last().expect("non-empty"), inv);
            let shift = a.len() - b.len();
            for (j, bj) in b.iter().enumerate() {
                let t = mul_mod(top, *bj);
                a[shift + j] = (a[shift + j] + P61 - t) % P61;
            }
            while a.last() == Some(&0) {
                a.pop();
            }
            if a.is_empty() {
                break;
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().checked_sub(1)
}

impl IntPoly {
    /// Is the gcd certainly 1? Modulo the prime `2^61 − 1` not dividing the leading coefficient
    /// of `self`, the gcd has degree at least that of the integer gcd (the integer gcd's
    /// leading coefficient divides `lc(self)`, so its image keeps its degree and divides both
    /// images); degree 0 there proves the integer gcd constant.
    pub fn coprime_mod_p(&self, o: &IntPoly) -> bool {
        let a = reduce_mod(&self.c);
        if a.len() != self.c.len() {
            return false; // the prime divides lc(self)
        }
        gcd_degree_mod(a, reduce_mod(&o.c)) == Some(0)
    }
}

fn flip(s: Sign) -> Sign {
    match s {
        Sign::Minus => Sign::Plus,
        Sign::Plus => Sign::Minus,
        Sign::NoSign => Sign::NoSign,
    }
}
