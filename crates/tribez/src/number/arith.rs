//! Rational arithmetic whose cost follows the size of the numbers, for the places where the input
//! controls that size (number text, polynomial text).
//!
//! `num-bigint` computes gcds with Stein's binary algorithm, one or two bits per pass over the
//! whole number. That is quadratic even when one operand is tiny: `gcd(10^100000, 1)` makes about
//! 166,000 passes over 5,200 words. `num-rational` calls that gcd in every constructor, product and
//! sum (a product of two integers computes `gcd(a, 1)` twice), so a coefficient of 100,000 digits
//! costs about a second per operation, and a few products of such numbers, or a power such as
//! `217^36495`, run for minutes.
//!
//! Here the gcd is Lehmer's algorithm (Knuth, *The Art of Computer Programming*, vol. 2, §4.5.2,
//! Algorithm L): it runs Euclid's algorithm on the leading 63 bits in machine words and applies
//! the accumulated 2×2 cofactor matrix to the full numbers once per about 30 bits of progress,
//! and a long division when the operands differ in size. `gcd(huge, small)` is one division.
//! The rational operations avoid gcds that are known to be 1: products of integers, powers, sums
//! over coprime denominators (Henrici's and Knuth's formulas, §4.5.1).
//!
//! Every function returns exactly what the `num-rational` operation returns (lowest terms,
//! positive denominator); the tests compare them on random operands.

use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;
use num_traits::{CheckedSub, One, Signed, ToPrimitive, Zero};

/// The greatest common divisor of `a` and `b` (`gcd(0, 0) = 0`).
///
/// ```
/// use num_bigint::BigUint;
/// use tribez::hazmat::number::gcd;
/// let a = BigUint::from(10u32).pow(1000) * 21u32;
/// let b = BigUint::from(10u32).pow(900) * 35u32;
/// // 21·10^1000 = 21·10^100 · 10^900 and 21·10^100 is a multiple of 7 and of 5: the gcd is 35·10^900.
/// assert_eq!(gcd(&a, &b), BigUint::from(10u32).pow(900) * 35u32);
/// ```
pub fn gcd(a: &BigUint, b: &BigUint) -> BigUint {
    let (mut u, mut v) = if a >= b {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    // Invariant: u >= v.
    while !v.is_zero() {
        if let (Some(x), Some(y)) = (u.to_u64(), v.to_u64()) {
            return BigUint::from(gcd_u64(x, y));
        }
        let n = u.bits();
        if n - v.bits() >= 32 {
            let r = &u % &v;
            u = v;
            v = r;
            continue;
        }
        // Algorithm L: the leading 63 bits of u and v (shifted alike).
        let shift = n - 63;
        let mut x = i128::from((&u >> shift).to_u64().unwrap_or(0));
        let mut y = i128::from((&v >> shift).to_u64().unwrap_or(0));
        let (mut a_, mut b_, mut c_, mut d_) = (1i128, 0i128, 0i128, 1i128);
        while y + c_ != 0 && y + d_ != 0 {
            let q = (x + a_) / (y + c_);
            if q != (x + b_) / (y + d_) {
                break;
            }
            (a_, c_) = (c_, a_ - q * c_);
            (b_, d_) = (d_, b_ - q * d_);
            (x, y) = (y, x - q * y);
        }
        let combined = (b_ != 0)
            .then(|| Some((combine(&u, a_, &v, b_)?, combine(&u, c_, &v, d_)?)))
            .flatten();
        match combined {
            // Knuth shows both stay non-negative and the pair's gcd is unchanged.
            Some((nu, nv)) if nu >= nv => (u, v) = (nu, nv),
            Some((nu, nv)) => (u, v) = (nv, nu),
            // No quotient was certain: one multiprecision division step.
            None => {
                let r = &u % &v;
                u = v;
                v = r;
            }
        }
    }
    u
}

/// `a·u + b·v` when it is not negative, for cofactors of at most 64 bits (Algorithm L keeps
/// them below 2^63 with opposite signs), by two single-word products.
fn combine(u: &BigUint, a: i128, v: &BigUint, b: i128) -> Option<BigUint> {
    let au = u * u64::try_from(a.unsigned_abs()).ok()?;
    let bv = v * u64::try_from(b.unsigned_abs()).ok()?;
    match (a < 0, b < 0) {
        (false, false) => Some(au + bv),
        (false, true) => au.checked_sub(&bv),
        (true, false) => bv.checked_sub(&au),
        (true, true) => None,
    }
}

/// `gcd(a, b)` of machine words (Stein's binary algorithm: shifts and subtractions, no
/// division instruction); the one word gcd of the crate (the parser's reduction, the exact
/// kernel's reductions).
pub(crate) fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

fn ratio_raw(n: BigInt, d: BigInt) -> BigRational {
    BigRational::new_raw(n, d)
}

/// `n / d` in lowest terms with a positive denominator (as `BigRational::new`), `d ≠ 0`.
///
/// # Panics
/// If `d` is zero (as `BigRational::new`); callers check it first.
pub fn ratio(n: BigInt, d: BigInt) -> BigRational {
    assert!(!d.is_zero(), "denominator == 0");
    if n.is_zero() {
        return BigRational::zero();
    }
    let (n, d) = if d.is_negative() { (-n, -d) } else { (n, d) };
    let g = gcd(n.magnitude(), d.magnitude());
    if g.is_one() {
        return ratio_raw(n, d);
    }
    let g = BigInt::from(g);
    ratio_raw(n / &g, d / g)
}

/// `a · b`, exactly as `a * b` on `BigRational`.
pub fn mul(a: &BigRational, b: &BigRational) -> BigRational {
    if a.is_zero() || b.is_zero() {
        return BigRational::zero();
    }
    if a.denom().is_one() && b.denom().is_one() {
        return BigRational::from_integer(a.numer() * b.numer());
    }
    // Cross-cancel: gcd(a.n, b.d) and gcd(b.n, a.d); a and b are in lowest terms, so the
    // product of the quotients is too.
    let g1 = BigInt::from(gcd(a.numer().magnitude(), b.denom().magnitude()));
    let g2 = BigInt::from(gcd(b.numer().magnitude(), a.denom().magnitude()));
    let n = (a.numer() / &g1) * (b.numer() / &g2);
    let d = (a.denom() / &g2) * (b.denom() / &g1);
    ratio_raw(n, d)
}

/// `a + b`, exactly as `a + b` on `BigRational`.
pub fn add(a: &BigRational, b: &BigRational) -> BigRational {
    if a.is_zero() {
        return b.clone();
    }
    if b.is_zero() {
        return a.clone();
    }
    if a.denom().is_one() && b.denom().is_one() {
        return BigRational::from_integer(a.numer() + b.numer());
    }
    // Henrici: with g = gcd(a.d, b.d), t = a.n·(b.d/g) + b.n·(a.d/g), the sum is
    // (t / gcd(t, g)) / ((a.d/g)·(b.d/gcd(t, g))), already in lowest terms.
    let g = gcd(a.denom().magnitude(), b.denom().magnitude());
    if g.is_one() {
        let n = a.numer() * b.denom() + b.numer() * a.denom();
        if n.is_zero() {
            return BigRational::zero();
        }
        return ratio_raw(n, a.denom() * b.denom());
    }
    let g = BigInt::from(g);
    let (ad, bd) = (a.denom() / &g, b.denom() / &g);
    let t = a.numer() * &bd + b.numer() * &ad;
    if t.is_zero() {
        return BigRational::zero();
    }
    let g2 = BigInt::from(gcd(t.magnitude(), g.magnitude()));
    ratio_raw(t / &g2, ad * (b.denom() / g2))
}

/// `a − b`, exactly as `a - b` on `BigRational`.
pub fn sub(a: &BigRational, b: &BigRational) -> BigRational {
    add(a, &-b)
}

/// `a^k` (numerator and denominator raised separately: powers of coprime numbers stay coprime).
pub fn pow(a: &BigRational, k: u32) -> BigRational {
    ratio_raw(
        num_traits::pow(a.numer().clone(), k as usize),
        num_traits::pow(a.denom().clone(), k as usize),
    )
}

/// `a / b` for `b ≠ 0`.
pub fn div(a: &BigRational, b: &BigRational) -> BigRational {
    // `BigRational::recip` swaps numerator and denominator without a gcd.
    mul(a, &b.recip())
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::Sign;
    use num_integer::Integer;
    use proptest::prelude::*;

    fn big(words: &[u64]) -> BigUint {
        let mut x = BigUint::zero();
        for w in words {
            x = (x << 64u32) + BigUint::from(*w);
        }
        x
    }

    fn rat(n: &[u64], neg: bool, d: &[u64]) -> BigRational {
        let d = big(d) + 1u32;
        let n = BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, big(n));
        BigRational::new(n, BigInt::from(d))
    }

    #[test]
    fn gcd_of_a_huge_number_and_a_small_one_is_one_division() {
        let huge = BigUint::from(10u32).pow(100_000);
        assert_eq!(gcd(&huge, &BigUint::one()), BigUint::one());
        assert_eq!(gcd(&huge, &BigUint::from(4u32)), BigUint::from(4u32));
        assert_eq!(gcd(&BigUint::zero(), &huge), huge);
        assert_eq!(gcd(&BigUint::zero(), &BigUint::zero()), BigUint::zero());
    }

    #[test]
    fn gcd_of_balanced_huge_numbers_with_a_known_common_factor() {
        // 2^a·3^b·(a prime) and 2^c·5^d·(the same prime): the gcd is 2^min(a,c)·prime.
        let p = BigUint::from(1_000_000_007u64);
        let a = (BigUint::one() << 20_000u32) * BigUint::from(3u32).pow(12_000) * &p;
        let b = (BigUint::one() << 19_000u32) * BigUint::from(5u32).pow(8_000) * &p;
        assert_eq!(gcd(&a, &b), (BigUint::one() << 19_000u32) * p);
    }

    #[test]
    fn fibonacci_neighbours_are_coprime() {
        // Consecutive Fibonacci numbers are Euclid's worst case (every quotient is 1).
        let (mut f0, mut f1) = (BigUint::zero(), BigUint::one());
        for _ in 0..3000 {
            let f2 = &f0 + &f1;
            f0 = f1;
            f1 = f2;
        }
        assert_eq!(gcd(&f1, &f0), BigUint::one());
        assert_eq!(gcd(&(&f1 * 7u32), &(&f0 * 7u32)), BigUint::from(7u32));
        assert_eq!(
            gcd(&(&f1 * 12u32), &(&f0 * 18u32)),
            (&f1 * 12u32).gcd(&(&f0 * 18u32))
        );
    }

    proptest! {
        #[test]
        fn gcd_equals_num_integer(a in prop::collection::vec(any::<u64>(), 0..6),
                                  b in prop::collection::vec(any::<u64>(), 0..6),
                                  c in prop::collection::vec(any::<u64>(), 0..3)) {
            // A common factor c makes the gcd non-trivial.
            let c = big(&c) + 1u32;
            let (a, b) = (big(&a) * &c, big(&b) * &c);
            prop_assert_eq!(gcd(&a, &b), a.gcd(&b));
        }

        #[test]
        fn operations_equal_num_rational(an in prop::collection::vec(any::<u64>(), 0..4), aneg: bool,
                                         ad in prop::collection::vec(any::<u64>(), 0..3),
                                         bn in prop::collection::vec(any::<u64>(), 0..4), bneg: bool,
                                         bd in prop::collection::vec(any::<u64>(), 0..3),
                                         k in 0u32..5) {
            let a = rat(&an, aneg, &ad);
            let b = rat(&bn, bneg, &bd);
            prop_assert_eq!(mul(&a, &b), &a * &b);
            prop_assert_eq!(add(&a, &b), &a + &b);
            prop_assert_eq!(sub(&a, &b), &a - &b);
            prop_assert_eq!(pow(&a, k), num_traits::pow(a.clone(), k as usize));
            prop_assert_eq!(ratio(a.numer().clone(), b.numer().clone() + 1i32).is_zero(),
                            a.numer().is_zero());
            if !b.numer().is_zero() {
                let d = b.numer().clone();
                prop_assert_eq!(ratio(a.numer().clone(), d.clone()),
                                BigRational::new(a.numer().clone(), d));
                prop_assert_eq!(div(&a, &b), &a / &b);
            }
            // Denominators with a common factor exercise Henrici's second case.
            let c = rat(&an, bneg, &[6]);
            let e = rat(&bn, aneg, &[9]);
            prop_assert_eq!(add(&c, &e), &c + &e);
        }
    }
}
