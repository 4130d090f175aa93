//! ULPs and step distances (docs/theory.md §14.4).

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::exact::pow2;
use super::format::{BinaryFloat, emin, is_nan, key};
use super::round::floor_log2_mag;

/// floor(log2|q|) for `q ≠ 0`, from bit lengths only (docs/theory.md §14.4): with
/// e = bitlen(p) − bitlen(d), it is e − 1 when |p| < d·2^e, else e.
/// Returns `i64::MIN` for `q = 0`.
pub fn floor_log2(q: &BigRational) -> i64 {
    let (n, d) = (q.numer(), q.denom());
    if n.is_zero() || d.is_zero() {
        return i64::MIN;
    }
    floor_log2_mag(n.magnitude(), d.magnitude())
}

/// Binade ulp of a rational in the format `F` (docs/theory.md §14.4, as `math.ulp` on
/// float values): `2^(e−PREC+1)` with e = floor(log2|q|) clamped to ≥ `1 − EMAX`;
/// ulp(0) is the smallest subnormal. Not clamped above: beyond `MAX` it keeps growing with
/// the binade.
pub fn ulp<F: BinaryFloat>(q: &BigRational) -> BigRational {
    let e = if q.is_zero() {
        emin::<F>()
    } else {
        floor_log2(q).max(emin::<F>())
    };
    pow2(e - i64::from(F::PREC - 1))
}

/// Binade ulp of a rational (docs/theory.md §14.4, as `math.ulp` on f64 values):
/// `2^(e−52)` with e = floor(log2|q|) clamped to ≥ −1022; ulp(0) = 2^−1074.
/// (Not clamped above: beyond `f64::MAX` it keeps growing with the binade.)
pub fn ulp_f64(q: &BigRational) -> BigRational {
    ulp::<f64>(q)
}

/// Binade ulp in `f32`: `2^(e−23)` with e = floor(log2|q|) clamped to ≥ −126;
/// ulp(0) = 2^−149.
pub fn ulp_f32(q: &BigRational) -> BigRational {
    ulp::<f32>(q)
}

/// `|x − q| / ulp::<F>(q)` exactly, for `x` given as its exact rational value. It is at
/// most 1/2 when x = RN(q) in `F`.
pub fn ulps_error<F: BinaryFloat>(x: &BigRational, q: &BigRational) -> BigRational {
    (x - q).abs() / ulp::<F>(q)
}

/// `round_up_f64(&ulps_error::<F>(&exact_f64(y), q))` for a finite `y`: the error of `y` in
/// ULPs of `F` at `q`, rounded up to an `f64`, computed on integers without reducing a fraction
/// (no gcd). With `y = ±m·2^e`, `q = n/d` (`d > 0`) and `ulp::<F>(q) = 2^u`, the error is
/// `|±m·d·2^(e−s) − n·2^(−s)| / (d·2^(u−s))` with `s = min(e, u, 0)` (every shift ≥ 0).
/// `None` for a `y` that is not finite.
pub(crate) fn ulps_error_up<F: BinaryFloat>(y: f64, q: &BigRational) -> Option<f64> {
    use num_bigint::BigInt;
    if !y.is_finite() {
        return None;
    }
    let u = if q.is_zero() {
        emin::<F>()
    } else {
        floor_log2(q).max(emin::<F>())
    } - i64::from(F::PREC - 1);
    let bits = y.to_bits();
    let field = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1 << 52) - 1);
    let (m, e) = if field == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), field - 1075)
    };
    let m = if y.is_sign_negative() {
        -BigInt::from(m)
    } else {
        BigInt::from(m)
    };
    let s = e.min(u).min(0);
    let shift = |k: i64| usize::try_from(k).expect("a shift of at least 0, below 2^64");
    let (n, d) = (q.numer(), q.denom());
    let a = ((m * d) << shift(e - s)) - (n << shift(-s));
    let b = d.magnitude() << shift(u - s);
    Some(super::round::round_up_f64_ratio(a.magnitude(), &b))
}

/// `|x − q| / ulp_f64(q)` exactly, for `x` given as its exact rational value.
/// It is at most 1/2 when x = RN(q).
///
/// ```
/// use tribez::hazmat::number::{exact_f64, format_rational, parse_rational, ulps_error_f64};
/// let e = ulps_error_f64(&exact_f64(0.1).unwrap(), &parse_rational("1/10").unwrap());
/// assert_eq!(format_rational(&e), "2/5");
/// ```
pub fn ulps_error_f64(x: &BigRational, q: &BigRational) -> BigRational {
    ulps_error::<f64>(x, q)
}

/// `|x − q| / ulp_f32(q)` exactly.
pub fn ulps_error_f32(x: &BigRational, q: &BigRational) -> BigRational {
    ulps_error::<f32>(x, q)
}

/// Number of `nextafter` steps between `a` and `b`: |key(a) − key(b)| with the key of
/// docs/theory.md §14.4 (the bits, negated for a negative sign), so ±0 are the same point
/// and crossing zero counts the steps on both sides. Infinities are one step beyond `±MAX`.
/// `u64::MAX` if either is NaN.
pub fn steps<F: BinaryFloat>(a: F, b: F) -> u64 {
    if is_nan(a) || is_nan(b) {
        return u64::MAX;
    }
    key(a).abs_diff(key(b))
}

/// Number of `nextafter` steps between `a` and `b`: |key(a) − key(b)| with the
/// key of docs/theory.md §14.4, so ±0 are the same point and crossing zero counts the
/// steps on both sides (`steps_f64(-5e-324, 5e-324) = 2`). Infinities are one
/// step beyond `±MAX`. `u64::MAX` if either is NaN.
pub fn steps_f64(a: f64, b: f64) -> u64 {
    steps(a, b)
}

/// [`steps_f64`] for `f32`; `u32::MAX` if either is NaN (the largest distance between two
/// non-NaN `f32`, from −inf to +inf, is `2·0x7F80_0000`, below `u32::MAX`).
pub fn steps_f32(a: f32, b: f32) -> u32 {
    u32::try_from(steps(a, b)).unwrap_or(u32::MAX)
}
