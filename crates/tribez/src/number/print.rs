//! Printing: exact rationals as `p/q`, rationals as correctly rounded decimals, floats as
//! shortest round-trip decimals and as exact C99 hex floats.

use std::cmp::Ordering;

use num_bigint::{BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::format::{BinaryFloat, emin, exp_ones, fields, frac_bits};
use super::round::floor_log2_mag;

/// `p/q` in lowest terms with `q > 0`, or `p` when `q = 1`; the sign is on `p`
/// and `-0` never appears. (A rational with zero denominator, which only
/// `Ratio::new_raw` can build, prints as `p/0`.)
///
/// Not quadratic: a `BigRational` with a positive denominator is in lowest terms (num-rational
/// keeps that invariant, and tribez builds `new_raw` values only in lowest terms), so no gcd is
/// taken (num-bigint's binary gcd is quadratic in the length); the digits come from
/// num-bigint's divide-and-conquer radix conversion.
pub fn format_rational(q: &BigRational) -> String {
    let (n, d) = (q.numer(), q.denom());
    if d.is_zero() {
        return format!("{n}/0");
    }
    if d.sign() == Sign::Plus {
        debug_assert!(n.gcd(d).is_one(), "rational not in lowest terms");
        return if d.is_one() {
            n.to_string()
        } else {
            format!("{n}/{d}")
        };
    }
    let g = n.gcd(d);
    if d.sign() == Sign::Plus && g.is_one() {
        if d.is_one() {
            n.to_string()
        } else {
            format!("{n}/{d}")
        }
    } else {
        format_rational(&q.reduced())
    }
}

/// Decimal text of `q` correctly rounded (ties to even) to `digits` significant
/// digits (at least 1), with trailing zeros removed: positional for decimal
/// exponents `-5 ≤ k < min(digits, 21)`, otherwise exponent form like
/// `1.2345e-20`. For people; exact values are printed with [`format_rational`].
///
/// ```
/// use tribez::hazmat::number::{parse_rational, to_decimal_string};
/// let d = |s, n| to_decimal_string(&parse_rational(s).unwrap(), n);
/// assert_eq!(d("1/3", 5), "0.33333");
/// assert_eq!(d("2/3", 3), "0.667");
/// assert_eq!(d("-1/8", 17), "-0.125");
/// assert_eq!(d("12", 17), "12");
/// assert_eq!(d("12345", 3), "1.23e4");
/// assert_eq!(d("f64:1.2345e-20", 5), "1.2345e-20");
/// ```
pub fn to_decimal_string(q: &BigRational, digits: usize) -> String {
    let (n, d) = (q.numer(), q.denom());
    if d.is_zero() {
        return "nan".to_owned();
    }
    if n.is_zero() {
        return "0".to_owned();
    }
    let digits = digits.max(1);
    let neg = (n.sign() == Sign::Minus) != (d.sign() == Sign::Minus);
    let (a, b) = (n.magnitude(), d.magnitude());
    let Ok(digits_u32) = u32::try_from(digits) else {
        return format_rational(q);
    };
    let lower = BigUint::from(10u32).pow(digits_u32 - 1);
    let upper = &lower * 10u32;
    // First guess of k = floor(log10 |q|), then exact correction.
    let mut k = (floor_log2_mag(a, b) as f64 * std::f64::consts::LOG10_2).floor() as i64;
    let (m, k) = loop {
        // m = floor(|q| · 10^(digits-1-k)), wanted in [10^(digits-1), 10^digits).
        let s = digits as i64 - 1 - k;
        let Ok(p) = u32::try_from(s.unsigned_abs()) else {
            return format_rational(q);
        };
        let power = BigUint::from(10u32).pow(p);
        let (num, den) = if s >= 0 {
            (a * power, b.clone())
        } else {
            (a.clone(), b * power)
        };
        let (mut m, r) = num.div_rem(&den);
        if m < lower {
            k -= 1;
            continue;
        }
        if m >= upper {
            k += 1;
            continue;
        }
        let up = match (r << 1u32).cmp(&den) {
            Ordering::Less => false,
            Ordering::Equal => m.is_odd(),
            Ordering::Greater => true,
        };
        if up {
            m += 1u32;
            if m == upper {
                break (lower, k + 1);
            }
        }
        break (m, k);
    };
    let text = m.to_string();
    let sig = text.trim_end_matches('0');
    let mut out = String::with_capacity(sig.len() + 8);
    if neg {
        out.push('-');
    }
    if (-5..(digits.min(21) as i64)).contains(&k) {
        if k >= 0 {
            let int_len = k as usize + 1;
            if sig.len() <= int_len {
                out.push_str(&text[..int_len]);
            } else {
                out.push_str(&sig[..int_len]);
                out.push('.');
                out.push_str(&sig[int_len..]);
            }
        } else {
            out.push_str("0.");
            out.extend(std::iter::repeat_n('0', (-k - 1) as usize));
            out.push_str(sig);
        }
    } else {
        out.push_str(&sig[..1]);
        if sig.len() > 1 {
            out.push('.');
            out.push_str(&sig[1..]);
        }
        out.push('e');
        out.push_str(&k.to_string());
    }
    out
}

/// Shortest round-trip decimal of `x` (Rust's own formatting): `{}` for
/// `1e-5 ≤ |x| < 1e16` (the thresholds in the format of `x`) and zero, `{:e}` otherwise;
/// `inf`, `-inf`, `NaN`.
pub fn display_float<F: BinaryFloat>(x: F) -> String {
    let finite = fields(x).biased != exp_ones::<F>();
    let a = x.abs();
    if !finite || x == F::ZERO || (F::DISPLAY_LOW <= a && a < F::DISPLAY_HIGH) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Shortest round-trip decimal of `x` (Rust's own formatting): `{}` for
/// `1e-5 ≤ |x| < 1e16` and zero, `{:e}` otherwise; `inf`, `-inf`, `NaN`.
pub fn display_f64(x: f64) -> String {
    display_float(x)
}

/// Shortest round-trip decimal of `x`, as [`display_f64`] (thresholds `1e-5`, `1e16`).
pub fn display_f32(x: f32) -> String {
    display_float(x)
}

/// C99 hex-float text of `x`, exact and accepted back by [`parse_rational`](super::parse_rational): normal
/// `±0x1.hhhp±e` (trailing zero digits dropped), subnormal `±0x0.hhh…p(1−EMAX)` with all
/// `⌈(PREC−1)/4⌉` fraction digits (the fraction shifted left to fill the last digit, so the
/// last `f32` digit is even), zero `0x0p+0` / `-0x0p+0`; `inf`, `-inf`, `nan`.
pub fn hex_float<F: BinaryFloat>(x: F) -> String {
    let f = fields(x);
    if f.biased == exp_ones::<F>() {
        return match (f.frac, f.neg) {
            (0, true) => "-inf",
            (0, false) => "inf",
            _ => "nan",
        }
        .to_owned();
    }
    let p = frac_bits::<F>();
    let width = p.div_ceil(4);
    let frac = f.frac << (4 * width - p);
    let width = width as usize;
    match (f.biased, frac) {
        (0, 0) => hex_text(f.neg, 0, 0, width, 0),
        (0, _) => hex_text(f.neg, 0, frac, width, emin::<F>()),
        (b, _) => hex_text(f.neg, 1, frac, width, b as i64 - F::EMAX),
    }
}

/// C99 hex-float text of `x`, exact and accepted back by [`parse_rational`](super::parse_rational):
/// normal `±0x1.hhhp±e` (trailing zero digits dropped), subnormal
/// `±0x0.hhhhhhhhhhhhhp-1022`, zero `0x0p+0` / `-0x0p+0`; `inf`, `-inf`, `nan`.
///
/// ```
/// use tribez::hazmat::number::hex_f64;
/// assert_eq!(hex_f64(0.1), "0x1.999999999999ap-4");
/// assert_eq!(hex_f64(-1.0), "-0x1p+0");
/// assert_eq!(hex_f64(5e-324), "0x0.0000000000001p-1022");
/// ```
pub fn hex_f64(x: f64) -> String {
    hex_float(x)
}

/// C99 hex-float text of an `f32` (6 fraction hex digits, the last one even):
/// `0x1.99999ap-4` for `0.1f32`, subnormals `0x0.hhhhhhp-126`; see [`hex_f64`].
pub fn hex_f32(x: f32) -> String {
    hex_float(x)
}

fn hex_text(neg: bool, lead: u8, frac: u64, width: usize, exp: i64) -> String {
    let sign = if neg { "-" } else { "" };
    if frac == 0 {
        return format!("{sign}0x{lead}p{exp:+}");
    }
    let digits = format!("{frac:0width$x}");
    format!("{sign}0x{lead}.{}p{exp:+}", digits.trim_end_matches('0'))
}
