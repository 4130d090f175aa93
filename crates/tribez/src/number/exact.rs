//! Exact values of floats and of dyadic numbers `±m·2^e` (docs/theory.md §14.3).

use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::format::{BinaryFloat, emin, exp_ones, fields, frac_bits};

/// Exact value of a finite float (docs/theory.md §14.3), `None` for NaN and ±inf. With s, e,
/// f the sign, biased exponent and fraction fields, `p = PREC − 1` fraction bits and bias
/// `EMAX`: `x = (−1)^s·f·2^(1−EMAX−p)` when e = 0, else `(−1)^s·(2^p+f)·2^(e−EMAX−p)`
/// (for `f64`: `f·2^−1074` and `(2^52+f)·2^(e−1075)`); ±0 both give 0.
///
/// ```
/// use tribez::hazmat::number::{exact_value, format_rational};
/// assert_eq!(format_rational(&exact_value(0.1f32).unwrap()), "13421773/134217728");
/// assert_eq!(exact_value(f64::INFINITY), None);
/// ```
pub fn exact_value<F: BinaryFloat>(x: F) -> Option<BigRational> {
    let f = fields(x);
    let p = i64::from(frac_bits::<F>());
    let (m, e) = match f.biased {
        b if b == exp_ones::<F>() => return None,
        0 => (f.frac, emin::<F>() - p),
        b => (f.frac | (1 << p), b as i64 - F::EMAX - p),
    };
    Some(dyadic_u64(f.neg, m, e))
}

/// Exact value of a finite `f64` (docs/theory.md §14.3), `None` for NaN and ±inf.
/// With s, e, f the sign, biased exponent and fraction fields: `x = (−1)^s·f·2^−1074`
/// when e = 0, else `(−1)^s·(2^52+f)·2^(e−1075)`; ±0 both give 0.
///
/// ```
/// use tribez::hazmat::number::{exact_f64, format_rational};
/// assert_eq!(format_rational(&exact_f64(0.1).unwrap()), "3602879701896397/36028797018963968");
/// assert_eq!(format_rational(&exact_f64(-0.0).unwrap()), "0");
/// assert_eq!(exact_f64(f64::NAN), None);
/// ```
pub fn exact_f64(x: f64) -> Option<BigRational> {
    exact_value(x)
}

/// Exact value of a finite `f32`, `None` for NaN and ±inf: `(−1)^s·f·2^−149` when
/// e = 0, else `(−1)^s·(2^23+f)·2^(e−150)`.
pub fn exact_f32(x: f32) -> Option<BigRational> {
    exact_value(x)
}

pub(super) fn signed(neg: bool, m: BigUint) -> BigInt {
    BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, m)
}

/// `±m·2^e` in lowest terms, allocating one integer per part.
fn dyadic_u64(neg: bool, m: u64, e: i64) -> BigRational {
    if m == 0 {
        return BigRational::zero();
    }
    let z = m.trailing_zeros();
    let (m, e) = (m >> z, e + i64::from(z));
    if e >= 0 {
        let n = if e < 64 {
            BigUint::from(u128::from(m) << e)
        } else {
            BigUint::from(m) << e.unsigned_abs()
        };
        BigRational::from_integer(signed(neg, n))
    } else {
        BigRational::new_raw(
            signed(neg, BigUint::from(m)),
            BigInt::from(pow2_uint(e.unsigned_abs())),
        )
    }
}

/// `±m·2^e` in lowest terms (the power of two is cancelled against `m`).
pub(super) fn dyadic(neg: bool, mut m: BigUint, mut e: i64) -> BigRational {
    let Some(z) = m.trailing_zeros() else {
        return BigRational::zero();
    };
    if e < 0 {
        let shift = z.min(e.unsigned_abs());
        m >>= shift;
        e += shift as i64;
    }
    if e >= 0 {
        BigRational::from_integer(signed(neg, m << e.unsigned_abs()))
    } else {
        BigRational::new_raw(signed(neg, m), BigInt::from(pow2_uint(e.unsigned_abs())))
    }
}

/// `2^k` as an integer.
fn pow2_uint(k: u64) -> BigUint {
    if k < 128 {
        BigUint::from(1u128 << k)
    } else {
        let mut p = BigUint::zero();
        p.set_bit(k, true);
        p
    }
}

/// `2^k` exactly.
pub fn pow2(k: i64) -> BigRational {
    let p = BigInt::from(pow2_uint(k.unsigned_abs()));
    if k >= 0 {
        BigRational::from_integer(p)
    } else {
        BigRational::new_raw(BigInt::one(), p)
    }
}
