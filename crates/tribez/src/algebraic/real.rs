//! [`RealAlgebraic`]: a real algebraic number, exactly — a rational, or the only root of a
//! square-free primitive integer polynomial in an open interval with rational end points
//! (docs/theory.md §16.3).

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::AlgebraicError;
use super::interval::sign_on;
use super::isolate::{Cell, isolate};
#[cfg(test)]
use super::isolate::{bernstein_on, variations};
use super::poly::IntPoly;
use crate::number::{BinaryFloat, hex_f64, round_to, to_decimal_string};

/// An irrational real algebraic number: the only root of `poly` (square-free, primitive,
/// positive leading coefficient) in the open interval `(lo, hi)`, where `poly` has opposite
/// non-zero signs at `lo` and `hi`.
#[derive(Clone, Debug)]
pub struct Root {
    poly: IntPoly,
    lo: BigRational,
    hi: BigRational,
    /// The sign of `poly(lo)`.
    lo_sign: Ordering,
}

/// A real algebraic number: a rational given as a rational, or an irrational [`Root`].
///
/// ```
/// use tribez::algebraic::{IntPoly, RealAlgebraic};
/// use tribez::parse_rational;
/// let q = |s: &str| parse_rational(s).unwrap();
/// // the roots of x^2 - 2 in [0, 2]: √2 only
/// let roots = RealAlgebraic::roots_in(&IntPoly::from_i64(&[-2, 0, 1]), &q("0"), &q("2")).unwrap();
/// assert_eq!(roots.len(), 1);
/// let r2 = &roots[0];
/// assert!(r2.cmp_rational(&q("1414213/1000000")).is_gt());
/// assert!(r2.cmp_rational(&q("1414214/1000000")).is_lt());
/// assert_eq!(r2.to_f64(), std::f64::consts::SQRT_2); // correctly rounded
/// // a rational root is a rational: 6x^2 - 5x + 1 = (2x - 1)(3x - 1)
/// let r = RealAlgebraic::roots_in(&IntPoly::from_i64(&[1, -5, 6]), &q("0"), &q("1")).unwrap();
/// assert_eq!(r[0].as_rational(), Some(&q("1/3")));
/// assert_eq!(r[1].as_rational(), Some(&q("1/2")));
/// ```
#[derive(Clone, Debug)]
pub enum RealAlgebraic {
    /// A rational number.
    Rational(BigRational),
    /// An irrational number.
    Root(Root),
}

/// Small primes for the test "no root modulo ℓ, hence no rational root".
const PRIMES: &[u32] = &[
    3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127,
];

/// Does `p` certainly have no rational root (it has no root modulo some small prime that does
/// not divide its leading coefficient)?
fn no_rational_root(p: &IntPoly) -> bool {
    let lc = p.lc();
    PRIMES.iter().any(|&l| {
        let lb = BigInt::from(l);
        if (&lc % &lb).is_zero() {
            return false;
        }
        let c: Vec<u64> = p
            .coeffs()
            .iter()
            .map(|x| {
                let r = x.mod_floor(&lb);
                // invariant: mod_floor by the small prime lb gives 0 <= r < lb, which fits u64
                u64::try_from(r).expect("reduced modulo a small prime")
            })
            .collect();
        let l = u64::from(l);
        (0..l).all(|x| c.iter().rev().fold(0u64, |acc, &ci| (acc * x + ci) % l) != 0)
    })
}

/// The fraction with the smallest denominator strictly between `lo < hi`.
pub fn simplest_between(lo: &BigRational, hi: &BigRational) -> BigRational {
    if lo.is_negative() && hi.is_positive() {
        return BigRational::zero();
    }
    if !hi.is_positive() {
        return -simplest_between(&-hi, &-lo);
    }
    // 0 ≤ lo < hi
    let fl = lo.floor();
    let next = &fl + BigRational::one();
    if &next < hi {
        return next;
    }
    let a = hi - &fl; // in (0, 1]
    let b = lo - &fl; // in [0, 1)
    let y = if b.is_zero() {
        (BigRational::one() / a).floor() + BigRational::one()
    } else {
        simplest_between(&(BigRational::one() / a), &(BigRational::one() / b))
    };
    fl + BigRational::one() / y
}

impl Root {
    /// The polynomial (square-free, primitive, positive leading coefficient).
    pub fn poly(&self) -> &IntPoly {
        &self.poly
    }

    /// The current isolating interval `(lo, hi)`.
    pub fn interval(&self) -> (&BigRational, &BigRational) {
        (&self.lo, &self.hi)
    }

    /// Halve the interval, keeping the root inside.
    pub fn bisect(&mut self) {
        let mid = (&self.lo + &self.hi) / BigRational::from_integer(BigInt::from(2));
        let s = self.poly.sign_at(&mid);
        debug_assert!(
            s != Ordering::Equal,
            "an irrational root is never a midpoint"
        );
        if s == self.lo_sign {
            self.lo = mid;
        } else {
            self.hi = mid;
        }
    }

    /// Narrow until `hi − lo ≤ width` (`width > 0`): Newton steps in dyadic arithmetic whose
    /// result is verified by two exact signs (an interval of width `≤ width/2` around the
    /// Newton iterate where the polynomial changes sign), bisection when a step fails.
    pub fn refine_to(&mut self, width: &BigRational) {
        let mut fails = 0;
        while &(&self.hi - &self.lo) > width {
            if fails < 6 && self.newton_jump(width) {
                continue;
            }
            fails += 1;
            for _ in 0..4 {
                self.bisect();
            }
        }
    }

    /// Bisect until `hi − lo ≤ width` (the generic path [`Root::refine_to`] is tested against).
    #[cfg(test)]
    pub fn bisect_to(&mut self, width: &BigRational) {
        while &(&self.hi - &self.lo) > width {
            self.bisect();
        }
    }

    /// Narrow the interval by a factor `2^k` at least.
    pub fn narrow_by(&mut self, k: u32) {
        let w = (&self.hi - &self.lo) / BigRational::from_integer(BigInt::one() << k);
        self.refine_to(&w);
    }

    /// One attempt: Newton's iteration `x ← x − p(x)/p'(x)` from the midpoint on dyadic numbers
    /// `m/2^K` (`2^−K ≤ width/8`), then the interval `[x − e, x + e]` (`e = 2^−(K−2)`, clipped
    /// to the current one) is kept if `p` has the signs of a root there. Any failure leaves the
    /// interval as it was.
    fn newton_jump(&mut self, width: &BigRational) -> bool {
        // K with 2^-K ≤ width / 8
        let k = (width.denom().bits() + 3).saturating_sub(width.numer().bits()) + 1;
        let k = u32::try_from(k).unwrap_or(u32::MAX);
        if k > 1 << 20 {
            return false;
        }
        let scale = BigInt::one() << k;
        let dp = self.poly.derivative();
        let n = self.poly.degree().unwrap_or(0);
        if n < 2 {
            return false;
        }
        let mid = (&self.lo + &self.hi) / BigRational::from_integer(BigInt::from(2));
        let mut m = (mid * BigRational::from_integer(scale.clone()))
            .floor()
            .to_integer();
        let in_range = |m: &BigInt| -> bool {
            let x = BigRational::new(m.clone(), scale.clone());
            x > self.lo && x < self.hi
        };
        // iterations: quadratic convergence from ~2^-4 relative needs ~log2(K) steps
        let steps = 4 + (64 - u64::from(k).leading_zeros()) as usize;
        let mut converged = false;
        for _ in 0..steps {
            // f = 2^(Kn) p(m/2^K), g = 2^(K(n−1)) p'(m/2^K): m/2^K − f/(2^K g) ⇒ new m = m − f/g
            let f = self.poly.eval_scaled(&m, &scale);
            let g = dp.eval_scaled(&m, &scale);
            if g.is_zero() {
                return false;
            }
            let step = f.div_floor(&g);
            if step.is_zero() || step == BigInt::from(-1) {
                converged = true;
                m -= step;
                break;
            }
            m -= step;
            if !in_range(&m) {
                return false;
            }
        }
        if !converged {
            return false;
        }
        let e = BigInt::from(4);
        let a = BigRational::new(&m - &e, scale.clone()).max(self.lo.clone());
        let b = BigRational::new(&m + &e, scale.clone()).min(self.hi.clone());
        if a >= b {
            return false;
        }
        let sa = if a == self.lo {
            self.lo_sign
        } else {
            self.poly.sign_at(&a)
        };
        let sb = if b == self.hi {
            self.lo_sign.reverse()
        } else {
            self.poly.sign_at(&b)
        };
        if sa == self.lo_sign && sb == self.lo_sign.reverse() {
            self.lo = a;
            self.hi = b;
            true
        } else {
            false
        }
    }

    /// The sign of `x − self` … reversed: how `self` compares with the rational `x`.
    pub fn cmp_rational(&self, x: &BigRational) -> Ordering {
        if x <= &self.lo {
            return Ordering::Greater;
        }
        if x >= &self.hi {
            return Ordering::Less;
        }
        // inside: the sign of poly(x) tells the side (x is not the root: the root is irrational)
        if self.poly.sign_at(x) == self.lo_sign {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }
}

impl RealAlgebraic {
    /// The number `x`.
    pub fn rational(x: BigRational) -> Self {
        RealAlgebraic::Rational(x)
    }

    /// The real roots of `p` (non-zero) in `[a, b]` (`a ≤ b`), increasing, each once: a
    /// rational root as a rational, an irrational one with the square-free part of `p` (or of
    /// its factor left after dividing out the rational roots) and an isolating interval.
    pub fn roots_in(
        p: &IntPoly,
        a: &BigRational,
        b: &BigRational,
    ) -> Result<Vec<RealAlgebraic>, AlgebraicError> {
        if p.is_zero() {
            return Err(AlgebraicError::ZeroPolynomial);
        }
        super::check_poly(p)?;
        if a > b {
            return Ok(Vec::new());
        }
        let sf = p.square_free();
        if a == b {
            return Ok(if sf.sign_at(a) == Ordering::Equal {
                vec![RealAlgebraic::Rational(a.clone())]
            } else {
                Vec::new()
            });
        }
        let cells = isolate(&sf, a, b)?;
        // divide out the rational roots found at subdivision points
        let mut poly = sf;
        for c in &cells {
            if let Cell::Exact(x) = c {
                poly = divide_root(&poly, x);
            }
        }
        let mut out = Vec::with_capacity(cells.len());
        for c in cells {
            match c {
                Cell::Exact(x) => out.push(RealAlgebraic::Rational(x)),
                Cell::Open(lo, hi) => {
                    let mut root = Root {
                        lo_sign: poly.sign_at(&lo),
                        poly: poly.clone(),
                        lo,
                        hi,
                    };
                    match rational_in(&mut root) {
                        Some(x) => {
                            poly = divide_root(&poly, &x);
                            out.push(RealAlgebraic::Rational(x));
                        }
                        None => out.push(RealAlgebraic::Root(root)),
                    }
                }
            }
        }
        // the irrational roots keep the polynomial left after every rational root is divided out
        for r in out.iter_mut() {
            if let RealAlgebraic::Root(root) = r
                && root.poly != poly
            {
                root.poly = poly.clone();
                root.lo_sign = poly.sign_at(&root.lo);
            }
        }
        Ok(out)
    }

    /// The rational, if it is one.
    pub fn as_rational(&self) -> Option<&BigRational> {
        match self {
            RealAlgebraic::Rational(x) => Some(x),
            RealAlgebraic::Root(_) => None,
        }
    }

    /// The irrational root, if it is one.
    pub fn as_root(&self) -> Option<&Root> {
        match self {
            RealAlgebraic::Rational(_) => None,
            RealAlgebraic::Root(r) => Some(r),
        }
    }

    /// A rational enclosure `[lo, hi]` of width at most `width` (`lo = hi` for a rational).
    pub fn enclosure(&self, width: &BigRational) -> (BigRational, BigRational) {
        match self {
            RealAlgebraic::Rational(x) => (x.clone(), x.clone()),
            RealAlgebraic::Root(r) => {
                let mut r = r.clone();
                r.refine_to(width);
                (r.lo, r.hi)
            }
        }
    }

    /// Refine the isolating interval in place to width at most `width`.
    pub fn refine_to(&mut self, width: &BigRational) {
        if let RealAlgebraic::Root(r) = self {
            r.refine_to(width);
        }
    }

    /// How the number compares with a rational, exactly.
    pub fn cmp_rational(&self, x: &BigRational) -> Ordering {
        match self {
            RealAlgebraic::Rational(y) => y.cmp(x),
            RealAlgebraic::Root(r) => r.cmp_rational(x),
        }
    }

    /// The sign of the polynomial `q` at the number, exactly.
    ///
    /// ```
    /// use tribez::algebraic::{IntPoly, RealAlgebraic};
    /// use tribez::parse_rational;
    /// let q = |s: &str| parse_rational(s).unwrap();
    /// let r2 = RealAlgebraic::roots_in(&IntPoly::from_i64(&[-2, 0, 1]), &q("0"), &q("2")).unwrap();
    /// // x^4 - 4 = (x^2 - 2)(x^2 + 2) vanishes at √2; x^3 - 3 is negative there (2√2 < 3)
    /// assert!(r2[0].sign_of(&IntPoly::from_i64(&[-4, 0, 0, 0, 1])).is_eq());
    /// assert!(r2[0].sign_of(&IntPoly::from_i64(&[-3, 0, 0, 1])).is_lt());
    /// ```
    pub fn sign_of(&self, q: &IntPoly) -> Ordering {
        match self {
            RealAlgebraic::Rational(x) => q.sign_at(x),
            RealAlgebraic::Root(r) => {
                if q.is_zero() {
                    return Ordering::Equal;
                }
                let mut r = r.clone();
                // the interval filter, on the isolating interval and twice narrowed by 2^-16
                for round in 0..3 {
                    if let Some(s) = sign_on(q.coeffs(), &r.lo, &r.hi) {
                        return s;
                    }
                    if round < 2 {
                        for _ in 0..16 {
                            r.bisect();
                        }
                    }
                }
                // does q vanish at the root? Only a common factor with the root's polynomial
                // can make it vanish there, and that factor changes sign over the interval
                let g = r.poly.gcd(q);
                if g.degree().unwrap_or(0) > 0 && g.sign_at(&r.lo) != g.sign_at(&r.hi) {
                    return Ordering::Equal;
                }
                // q(root) ≠ 0: the enclosure excludes zero once the interval is narrow enough
                loop {
                    for _ in 0..8 {
                        r.bisect();
                    }
                    if let Some(s) = sign_on(q.coeffs(), &r.lo, &r.hi) {
                        return s;
                    }
                }
            }
        }
    }

    /// The sign of `q` at the number by the Bernstein coefficients over ever narrower isolating
    /// intervals and a gcd (the generic exact path that [`RealAlgebraic::sign_of`]'s interval
    /// filter is tested against).
    #[cfg(test)]
    pub fn sign_of_generic(&self, q: &IntPoly) -> Ordering {
        match self {
            RealAlgebraic::Rational(x) => q.sign_at(x),
            RealAlgebraic::Root(r) => {
                if q.is_zero() {
                    return Ordering::Equal;
                }
                let mut r = r.clone();
                let mut checked_gcd = false;
                let mut tries = 0;
                loop {
                    let bc = bernstein_on(q, &r.lo, &r.hi);
                    if variations(&bc) == 0 {
                        // invariant: q is a non-zero polynomial, so its Bernstein coefficients on an interval are not all zero
                        let nz = bc.iter().find(|x| !x.is_zero()).expect("q is not zero");
                        return if nz.is_positive() {
                            Ordering::Greater
                        } else {
                            Ordering::Less
                        };
                    }
                    tries += 1;
                    if !checked_gcd && tries > 6 {
                        checked_gcd = true;
                        let g = r.poly.gcd(q);
                        if g.degree().unwrap_or(0) > 0 && g.sign_at(&r.lo) != g.sign_at(&r.hi) {
                            return Ordering::Equal;
                        }
                    }
                    r.bisect();
                }
            }
        }
    }

    /// The current enclosure: the isolating interval of a root, `[x, x]` for a rational.
    pub fn bounds(&self) -> (BigRational, BigRational) {
        match self {
            RealAlgebraic::Rational(x) => (x.clone(), x.clone()),
            RealAlgebraic::Root(r) => (r.lo.clone(), r.hi.clone()),
        }
    }

    /// The sign of a polynomial with rational coefficients (ascending) at the number.
    pub fn sign_of_rationals(&self, q: &[BigRational]) -> Ordering {
        // from_rationals makes the leading coefficient positive: undo a sign flip
        let p = IntPoly::from_rationals(q);
        let flipped = q
            .iter()
            .rev()
            .find(|x| !x.is_zero())
            .is_some_and(|x| x.is_negative());
        let s = self.sign_of(&p);
        if flipped { s.reverse() } else { s }
    }

    /// Exact comparison of two real algebraic numbers.
    pub fn cmp_exact(&self, other: &RealAlgebraic) -> Ordering {
        match (self, other) {
            (RealAlgebraic::Rational(x), _) => other.cmp_rational(x).reverse(),
            (_, RealAlgebraic::Rational(y)) => self.cmp_rational(y),
            (RealAlgebraic::Root(a), RealAlgebraic::Root(b)) => {
                // equal iff b is a root of gcd(Pa, Pb) inside a's interval
                let g = a.poly.gcd(&b.poly);
                if g.degree().unwrap_or(0) > 0
                    && g.sign_at(&b.lo) != g.sign_at(&b.hi)
                    && a.cmp_rational(&b.lo).is_gt()
                    && a.cmp_rational(&b.hi).is_lt()
                {
                    // g's only root in b's interval is b, and a (a root of g too when g
                    // changes sign over a's interval) lies there
                    if g.sign_at(&a.lo) != g.sign_at(&a.hi) {
                        return Ordering::Equal;
                    }
                }
                let (mut a, mut b) = (a.clone(), b.clone());
                loop {
                    if a.hi <= b.lo {
                        return Ordering::Less;
                    }
                    if b.hi <= a.lo {
                        return Ordering::Greater;
                    }
                    a.bisect();
                    b.bisect();
                }
            }
        }
    }

    /// The nearest float of format `F`, ties to even (refined until the interval rounds to one
    /// float; a rational is rounded once).
    pub fn round<F: BinaryFloat>(&self) -> F {
        match self {
            RealAlgebraic::Rational(x) => round_to(x),
            RealAlgebraic::Root(r) => {
                let mut r = r.clone();
                loop {
                    let (a, b): (F, F) = (round_to(&r.lo), round_to(&r.hi));
                    if a == b {
                        return a;
                    }
                    r.narrow_by(16);
                }
            }
        }
    }

    /// The nearest `f64`, ties to even.
    pub fn to_f64(&self) -> f64 {
        self.round::<f64>()
    }

    /// The nearest `f32`, ties to even.
    pub fn to_f32(&self) -> f32 {
        self.round::<f32>()
    }

    /// The decimal text correctly rounded to `digits` significant digits.
    pub fn decimal(&self, digits: usize) -> String {
        match self {
            RealAlgebraic::Rational(x) => to_decimal_string(x, digits),
            RealAlgebraic::Root(r) => {
                let mut r = r.clone();
                loop {
                    let a = to_decimal_string(&r.lo, digits);
                    if a == to_decimal_string(&r.hi, digits) {
                        return a;
                    }
                    r.narrow_by(16);
                }
            }
        }
    }

    /// The interval refined until it rounds to one `f64` (for printing).
    fn printed_interval(&self) -> Option<(BigRational, BigRational)> {
        let RealAlgebraic::Root(r) = self else {
            return None;
        };
        let mut r = r.clone();
        loop {
            if round_to::<f64>(&r.lo) == round_to::<f64>(&r.hi) {
                return Some((r.lo, r.hi));
            }
            r.bisect();
        }
    }

    /// JSON: `{"polynomial": ["c0", …], "interval": ["lo", "hi"], "f64": "<hex>", "decimal":
    /// "<17 significant digits>"}`, or `{"rational": "p/q", "f64": …, "decimal": …}`.
    pub fn to_json(&self) -> serde_json::Value {
        let mut m = serde_json::Map::new();
        match self {
            RealAlgebraic::Rational(x) => {
                m.insert("rational".into(), x.to_string().into());
            }
            RealAlgebraic::Root(r) => {
                // invariant: every Root has a printed interval (its isolating interval)
                let (lo, hi) = self.printed_interval().expect("a root");
                m.insert(
                    "polynomial".into(),
                    r.poly
                        .coeffs()
                        .iter()
                        .map(|c| serde_json::Value::from(c.to_string()))
                        .collect(),
                );
                m.insert(
                    "interval".into(),
                    vec![lo.to_string(), hi.to_string()].into(),
                );
            }
        }
        m.insert("f64".into(), hex_f64(self.to_f64()).into());
        m.insert("decimal".into(), self.decimal(17).into());
        serde_json::Value::Object(m)
    }

    /// Text: `p/q`, or `≈ decimal (root of c0 + c1 x + … in (lo, hi))`.
    pub fn to_text(&self) -> String {
        match self {
            RealAlgebraic::Rational(x) => x.to_string(),
            RealAlgebraic::Root(r) => {
                // invariant: every Root has a printed interval (its isolating interval)
                let (lo, hi) = self.printed_interval().expect("a root");
                format!(
                    "≈ {} (root of {} in ({lo}, {hi}))",
                    self.decimal(17),
                    poly_text(&r.poly)
                )
            }
        }
    }
}

/// `c_n x^n + … + c_0` as text.
pub fn poly_text(p: &IntPoly) -> String {
    let mut s = String::new();
    for (i, c) in p.coeffs().iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let neg = c.is_negative();
        let a = c.abs();
        if s.is_empty() {
            if neg {
                s.push('-');
            }
        } else {
            s.push_str(if neg { " - " } else { " + " });
        }
        let one = a.is_one();
        match i {
            0 => s.push_str(&a.to_string()),
            _ => {
                if !one {
                    s.push_str(&a.to_string());
                }
                s.push('x');
                if i > 1 {
                    s.push('^');
                    s.push_str(&i.to_string());
                }
            }
        }
    }
    if s.is_empty() {
        s.push('0');
    }
    s
}

/// `p / (den·x − num)` for a rational root `x = num/den` of `p`, primitive.
fn divide_root(p: &IntPoly, x: &BigRational) -> IntPoly {
    let lin = IntPoly::new(vec![-x.numer().clone(), x.denom().clone()]);
    p.div_exact(&lin)
        .map(|q| q.primitive())
        .unwrap_or_else(|| p.clone())
}

/// The rational root in `root`'s interval, if the root is rational (the interval is refined:
/// a rational root `u/v` of a primitive polynomial has `v | lc`, and two such fractions differ
/// by at least `1/lc²`, so once the width is below that, the fraction of smallest denominator
/// in the interval is the only candidate).
fn rational_in(root: &mut Root) -> Option<BigRational> {
    if no_rational_root(&root.poly) {
        return None;
    }
    let lc = root.poly.lc();
    let target = BigRational::new(BigInt::one(), &lc * &lc);
    let mut step = 0u32;
    let two = BigRational::from_integer(BigInt::from(2));
    loop {
        let s = simplest_between(&root.lo, &root.hi);
        if (&lc % s.denom()).is_zero() && root.poly.sign_at(&s) == Ordering::Equal {
            return Some(s);
        }
        if &root.hi - &root.lo < target {
            return None;
        }
        for _ in 0..=step.min(16) {
            let mid = (&root.lo + &root.hi) / &two;
            match root.poly.sign_at(&mid) {
                Ordering::Equal => return Some(mid),
                s if s == root.lo_sign => root.lo = mid,
                _ => root.hi = mid,
            }
        }
        step += 1;
    }
}
