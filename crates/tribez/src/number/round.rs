//! Correct rounding of a rational to a binary format (round to nearest, ties to even),
//! with integers only (docs/theory.md §14.4).

use std::cmp::Ordering;

use num_bigint::{BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

use super::format::{BinaryFloat, emin, exp_ones, frac_bits, is_nan, key};

/// A binary floating-point format.
#[derive(Clone, Copy)]
pub(super) struct Format {
    /// Significand bits, hidden bit included.
    pub prec: u32,
    pub emin: i64,
    pub emax: i64,
}

#[cfg(test)]
pub(super) const BINARY64: Format = Format {
    prec: 53,
    emin: -1022,
    emax: 1023,
};
#[cfg(test)]
pub(super) const BINARY32: Format = Format {
    prec: 24,
    emin: -126,
    emax: 127,
};

/// The part of a scaled magnitude below its integer part, compared with 1/2.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Tail {
    Zero,
    BelowHalf,
    Half,
    AboveHalf,
}

impl Tail {
    fn new(half_bit: bool, sticky: bool) -> Self {
        match (half_bit, sticky) {
            (false, false) => Tail::Zero,
            (false, true) => Tail::BelowHalf,
            (true, false) => Tail::Half,
            (true, true) => Tail::AboveHalf,
        }
    }
}

/// A rounded magnitude: `m·2^(e−prec+1)` with `m < 2^prec`, `e ≥ emin`
/// (`m < 2^(prec−1)` only when `e = emin`: subnormal or zero), or infinity.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Magnitude {
    Finite { m: u64, e: i64 },
    Infinite,
}

/// Rounded magnitude and how it compares with the exact magnitude.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) struct Rounded {
    mag: Magnitude,
    dir: Ordering,
}

/// Rounds `q` in `format`: the sign (true when `q < 0`) and the rounded
/// magnitude; `None` for a zero denominator.
fn round_rational(q: &BigRational, format: Format) -> Option<(bool, Rounded)> {
    let (n, d) = (q.numer(), q.denom());
    if d.is_zero() {
        return None;
    }
    let neg = !n.is_zero() && ((n.sign() == Sign::Minus) != (d.sign() == Sign::Minus));
    Some((neg, round_magnitude(n.magnitude(), d.magnitude(), format)))
}

/// RN(a/b) for `a ≥ 0`, `b > 0` (docs/theory.md §14.4).
fn round_magnitude(a: &BigUint, b: &BigUint, f: Format) -> Rounded {
    if a.is_zero() {
        return Rounded {
            mag: Magnitude::Finite { m: 0, e: f.emin },
            dir: Ordering::Equal,
        };
    }
    if let (Some(a), Some(b)) = (a.to_u64(), b.to_u64()) {
        return round_small(a, b, f);
    }
    round_big(a, b, f)
}

/// Bits `t .. t+64` of `a`, i.e. `floor(a / 2^t) mod 2^64`, without allocating.
fn bits_at(a: &BigUint, t: u64) -> u64 {
    let Ok(index) = usize::try_from(t / 64) else {
        return 0;
    };
    let offset = t % 64;
    let mut digits = a.iter_u64_digits().skip(index);
    let lo = digits.next().unwrap_or(0);
    if offset == 0 {
        lo
    } else {
        (lo >> offset) | (digits.next().unwrap_or(0) << (64 - offset))
    }
}

/// The 64 leading bits of `a` (which has `len ≥ 1` bits), left-aligned.
fn top_u64(a: &BigUint, len: u64) -> u64 {
    if len >= 64 {
        bits_at(a, len - 64)
    } else {
        bits_at(a, 0) << (64 - len)
    }
}

pub(super) fn is_power_of_two(b: &BigUint) -> bool {
    b.trailing_zeros() == Some(b.bits() - 1)
}

/// floor(log2(a/b)) for `a, b > 0`: with e = bitlen(a) − bitlen(b), the answer is
/// e − 1 when a < b·2^e, else e (docs/theory.md §14.4). Both sides of the comparison have
/// the same bit length, so their leading 64 bits usually decide it.
pub(super) fn floor_log2_mag(a: &BigUint, b: &BigUint) -> i64 {
    let (la, lb) = (a.bits(), b.bits());
    let e = la as i64 - lb as i64;
    let below = match top_u64(a, la).cmp(&top_u64(b, lb)) {
        Ordering::Less => true,
        Ordering::Greater => false,
        Ordering::Equal if la.max(lb) <= 64 => false,
        Ordering::Equal if e >= 0 => a < &(b << e.unsigned_abs()),
        Ordering::Equal => &(a << e.unsigned_abs()) < b,
    };
    e - i64::from(below)
}

/// RN for `a, b < 2^64` with `u128` arithmetic. Here 2^−64 < a/b < 2^64, so the
/// exponent is never clamped and never overflows (for binary32 and binary64),
/// and every intermediate is below 2^119.
pub(super) fn round_small(a: u64, b: u64, f: Format) -> Rounded {
    let (la, lb) = (64 - a.leading_zeros(), 64 - b.leading_zeros());
    let mut e = i64::from(la) - i64::from(lb);
    let (a128, b128) = (u128::from(a), u128::from(b));
    let below = if e >= 0 {
        a128 < b128 << e
    } else {
        a128 << -e < b128
    };
    e -= i64::from(below);
    let s = e - i64::from(f.prec - 1);
    let (m, r, d) = if s <= 0 {
        let n = a128 << -s;
        (n / b128, n % b128, b128)
    } else {
        let d = b128 << s;
        (a128 / d, a128 % d, d)
    };
    let tail = match r {
        0 => Tail::Zero,
        _ => match (r << 1).cmp(&d) {
            Ordering::Less => Tail::BelowHalf,
            Ordering::Equal => Tail::Half,
            Ordering::Greater => Tail::AboveHalf,
        },
    };
    finish(m as u64, e, tail, f)
}

/// RN for arbitrary `a > 0`, `b > 0`; a power-of-two `b` needs no division.
pub(super) fn round_big(a: &BigUint, b: &BigUint, f: Format) -> Rounded {
    let prec1 = i64::from(f.prec - 1);
    let dyadic_k = is_power_of_two(b).then(|| b.bits() - 1);
    let e = match dyadic_k {
        Some(k) => a.bits() as i64 - 1 - k as i64,
        None => floor_log2_mag(a, b),
    };
    if e > f.emax {
        return Rounded {
            mag: Magnitude::Infinite,
            dir: Ordering::Greater,
        };
    }
    if e < f.emin - prec1 - 1 {
        // |q| < 2^(emin−prec), half the smallest subnormal: rounds to zero.
        return Rounded {
            mag: Magnitude::Finite { m: 0, e: f.emin },
            dir: Ordering::Less,
        };
    }
    let e = e.max(f.emin);
    // Scale: m = floor(|q| / 2^s), s = e − prec + 1.
    let s = e - prec1;
    let (m, tail) = if let Some(k) = dyadic_k {
        let t = k as i64 + s; // |q| / 2^s = a / 2^t
        if t <= 0 {
            (bits_at(a, 0) << -t, Tail::Zero)
        } else {
            let t = t.unsigned_abs();
            let half = a.bit(t - 1);
            let sticky = a.trailing_zeros().is_some_and(|z| z < t - 1);
            (bits_at(a, t), Tail::new(half, sticky))
        }
    } else {
        let (m, r, d) = if s <= 0 {
            let (m, r) = (a << s.unsigned_abs()).div_rem(b);
            (m, r, std::borrow::Cow::Borrowed(b))
        } else {
            let d = b << s.unsigned_abs();
            let (m, r) = a.div_rem(&d);
            (m, r, std::borrow::Cow::Owned(d))
        };
        let tail = if r.is_zero() {
            Tail::Zero
        } else {
            match (r << 1u32).cmp(&d) {
                Ordering::Less => Tail::BelowHalf,
                Ordering::Equal => Tail::Half,
                Ordering::Greater => Tail::AboveHalf,
            }
        };
        (bits_at(&m, 0), tail)
    };
    finish(m, e, tail, f)
}

/// Applies ties-to-even to the truncated significand `m` of binade `e`, then
/// handles the carry into the next binade and overflow.
fn finish(mut m: u64, mut e: i64, tail: Tail, f: Format) -> Rounded {
    let up = match tail {
        Tail::Zero | Tail::BelowHalf => false,
        Tail::Half => m & 1 == 1,
        Tail::AboveHalf => true,
    };
    let dir = match (tail, up) {
        (Tail::Zero, _) => Ordering::Equal,
        (_, true) => Ordering::Greater,
        (_, false) => Ordering::Less,
    };
    if up {
        m += 1;
        if m == 1 << f.prec {
            m = 1 << (f.prec - 1);
            e += 1;
        }
    }
    if e > f.emax {
        return Rounded {
            mag: Magnitude::Infinite,
            dir: Ordering::Greater,
        };
    }
    Rounded {
        mag: Magnitude::Finite { m, e },
        dir,
    }
}

/// The float with sign `neg` and rounded magnitude `mag`: biased exponent `e + EMAX` and
/// the fraction bits for a normal `m` (hidden bit set), the bits of `m` for a subnormal or
/// zero, all-ones exponent for infinity.
fn encode<F: BinaryFloat>(neg: bool, mag: Magnitude) -> F {
    let p = frac_bits::<F>();
    let bits = match mag {
        Magnitude::Infinite => exp_ones::<F>() << p,
        Magnitude::Finite { m, e } if m >> p != 0 => {
            (((e + F::EMAX) as u64) << p) | (m & ((1 << p) - 1))
        }
        Magnitude::Finite { m, .. } => m,
    };
    F::from_raw(bits | (u64::from(neg) << (F::BITS - 1)))
}

/// The format parameters of `F` for the integer rounding.
pub(super) fn format_of<F: BinaryFloat>() -> Format {
    Format {
        prec: F::PREC,
        emin: emin::<F>(),
        emax: F::EMAX,
    }
}

/// The float of format `F` nearest to `q`, ties to even, computed with integers only
/// (docs/theory.md §14.4) and rounded ONCE from the exact value (so `round_to::<f32>` never
/// rounds twice through `f64`): e = floor(log2|q|) clamped to ≥ `1 − EMAX`,
/// m = RN(|q|/2^(e−PREC+1)), carry m = 2^PREC into the next binade, e > EMAX gives ±inf.
/// `0` gives `+0.0`; a negative `q` too small for the smallest subnormal gives `-0.0`; a zero
/// denominator gives NaN.
///
/// ```
/// use tribez::hazmat::number::{parse_rational, round_to};
/// // 1 + 2^-24 + 2^-60 rounds up in f32; through f64 it would tie and round down to 1.
/// let q = parse_rational("0x1.000001000000001p0").unwrap();
/// assert_eq!(round_to::<f32>(&q), 1.0 + f32::EPSILON);
/// ```
pub fn round_to<F: BinaryFloat>(q: &BigRational) -> F {
    match round_rational(q, format_of::<F>()) {
        Some((neg, r)) => encode(neg, r.mag),
        None => F::NAN,
    }
}

/// The `f64` nearest to `q`, ties to even, computed with integers only
/// (docs/theory.md §14.4): e = floor(log2|q|) clamped to ≥ −1022, m = RN(|q|/2^(e−52)),
/// carry m = 2^53 into the next binade, e > 1023 gives ±inf (so 2^1024 − 2^970,
/// a tie, rounds to inf). Subnormals are exact multiples of 2^−1074. `0` gives
/// `+0.0`; a negative `q` too small for the smallest subnormal gives `-0.0` (as
/// IEEE 754 and `str::parse` do). A zero denominator gives NaN.
///
/// ```
/// use tribez::hazmat::number::{parse_rational, round_f64};
/// let r = |s| round_f64(&parse_rational(s).unwrap());
/// assert_eq!(r("1/3"), 1.0 / 3.0);
/// assert_eq!(r("0x1.00000000000008p0"), 1.0); // 1 + 2^-53: tie, to even
/// assert_eq!(r("0x1.fffffffffffffcp1023"), f64::INFINITY); // 2^1024 - 2^970
/// ```
pub fn round_f64(q: &BigRational) -> f64 {
    round_to(q)
}

/// The least `f64` not below `q` (`+∞` above `f64::MAX`, `f64::MIN` below it), so that for
/// every float `t` the comparison `q ≤ t` holds exactly when `round_up_f64(q) ≤ t`: an exact
/// figure rounded this way lands on the right side of every float threshold (the histogram
/// buckets of errors in ULPs, whose bounds 1/2, 1, 2, … are floats), which rounding to nearest
/// does not promise (1/2 + 2^-148 rounds to 1/2).
///
/// ```
/// use tribez::hazmat::number::{parse_rational, round_up_f64};
/// let r = |s| round_up_f64(&parse_rational(s).unwrap());
/// assert_eq!(r("0.5"), 0.5);
/// assert_eq!(r("0x1.0000000000000000000000000000000001p-1"), 0.5f64.next_up()); // 1/2 + 2^-137
/// assert_eq!(r("1/3"), (1.0f64 / 3.0).next_up()); // 1/3 rounds down to nearest
/// assert_eq!(r("1/10"), 0.1); // the nearest, 0.1000000000000000055511151231257827…, is above
/// assert_eq!(r("0x1p-2000"), 5e-324); // above 0: the least subnormal
/// assert_eq!(r("0"), 0.0);
/// ```
pub fn round_up_f64(q: &BigRational) -> f64 {
    let x = round_f64(q);
    match super::exact_f64(x) {
        Some(v) if v < *q => x.next_up(),
        Some(_) => x,
        // ±∞: beyond the largest float on that side
        None if x > 0.0 => x,
        None => f64::MIN,
    }
}

/// [`round_up_f64`] of the magnitude `a/b` (`b > 0`) given as a fraction that need not be in
/// lowest terms: the least `f64` not below `a/b`, without a gcd (the correctly rounded
/// magnitude, moved up one float when it lies below `a/b`).
pub(crate) fn round_up_f64_ratio(a: &BigUint, b: &BigUint) -> f64 {
    let r = round_magnitude(a, b, format_of::<f64>());
    let x: f64 = encode(false, r.mag);
    if r.dir == Ordering::Less && x.is_finite() {
        x.next_up()
    } else {
        x
    }
}

/// The `f32` nearest to `q`, ties to even, rounded once from the exact value
/// (never through `f64`, which could round twice): 24-bit significand, e ≥ −126,
/// subnormals multiples of 2^−149, overflow (from 2^128 − 2^103 up) to ±inf.
/// Signs of zero and NaN as in [`round_f64`].
pub fn round_f32(q: &BigRational) -> f32 {
    round_to(q)
}

/// Whether `x` is a faithful rounding of `q` in its format: `x = q` when `q` is
/// representable, otherwise `x` is one of the two floats bracketing `q` (for |q| beyond
/// `MAX` these are `±MAX` and `±inf`). `-0.0` and `+0.0` are the same; NaN is never
/// faithful.
pub fn is_faithful<F: BinaryFloat>(x: F, q: &BigRational) -> bool {
    let Some((neg, r)) = round_rational(q, format_of::<F>()) else {
        return false;
    };
    if is_nan(x) {
        return false;
    }
    let nearest = key(encode::<F>(neg, r.mag));
    let dir = if neg { r.dir.reverse() } else { r.dir };
    faithful_key(key(x), nearest, dir)
}

/// [`is_faithful`] in `f64`.
pub fn is_faithful_f64(x: f64, q: &BigRational) -> bool {
    is_faithful(x, q)
}

/// [`is_faithful`] in `f32`.
pub fn is_faithful_f32(x: f32, q: &BigRational) -> bool {
    is_faithful(x, q)
}

/// `nearest` is the key of RN(q) and `dir` the order of RN(q) against q; the
/// other bracketing float is one step away on the side of q.
fn faithful_key(x: i64, nearest: i64, dir: Ordering) -> bool {
    match dir {
        Ordering::Equal => x == nearest,
        Ordering::Less => x == nearest || x == nearest + 1,
        Ordering::Greater => x == nearest || x == nearest - 1,
    }
}
