//! Exact numbers: parsing and printing of rationals, exact values of `f64`/`f32`,
//! correctly rounded rational → float conversions, ULPs and step distances.
//!
//! Everything here is exact: no floating-point operation is used to compute a
//! value (the only float arithmetic is a first guess of a decimal exponent in
//! [`to_decimal_string`], which is then corrected exactly). See docs/theory.md §14.3
//! (exact value of an f64) and §14.4 (ULPs, round-to-nearest with integers only).
//!
//! ```
//! use tribez::hazmat::number::*;
//! let q = parse_rational("f64:0.1").unwrap();
//! assert_eq!(format_rational(&q), "3602879701896397/36028797018963968");
//! assert_eq!(round_f64(&parse_rational("1/10").unwrap()), 0.1);
//! ```

use std::cmp::Ordering;

use num_bigint::{BigUint, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

pub use num_bigint::BigInt;
pub use num_rational::BigRational;

/// The exact number type of the crate.
pub type Rational = BigRational;

/// Largest accepted magnitude of a written exponent (`1e100000` is accepted,
/// `1e100001` is rejected), so that hostile input cannot allocate huge integers.
pub const MAX_EXPONENT: u64 = 100_000;

/// Why a text could not be read as an exact number.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NumberError {
    /// The text was empty or only whitespace.
    #[error("empty text: expected a number")]
    Empty,
    /// The text matches none of the accepted forms.
    #[error(
        "`{0}`: not a number (expected an integer, p/q, decimal, hex float, or f64:/f32: prefix)"
    )]
    Syntax(String),
    /// A fraction `p/0`.
    #[error("`{0}`: zero denominator")]
    ZeroDenominator(String),
    /// `nan` (any case, any sign).
    #[error("`{0}`: NaN has no exact value")]
    Nan(String),
    /// `inf` or `infinity` (any case, any sign).
    #[error("`{0}`: infinity has no exact value")]
    Infinite(String),
    /// A written exponent with magnitude above [`MAX_EXPONENT`].
    #[error("`{0}`: exponent magnitude above 100000")]
    ExponentTooLarge(String),
    /// An `f64:`/`f32:` value that rounds to an infinity.
    #[error("`{text}`: not a finite {format}")]
    NotFinite {
        /// The offending text.
        text: String,
        /// `"f64"` or `"f32"`.
        format: &'static str,
    },
}

// ---------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------

/// Parses `text` exactly; no floating-point step anywhere.
///
/// Accepted forms (surrounding whitespace ignored, at most one leading sign):
/// * integers `7`, `-12`, `+3`;
/// * fractions `p/q` (`4/9`, `-3/6`): decimal integers, sign on `p` only, `q ≠ 0`;
/// * decimals `0.125`, `-1.5e-3`, `.5`, `5.`, `1E10`, `2e+3`, with their exact
///   value (`1.5e-3` = 3/2000);
/// * C99 hex floats `0x1.8p-3`, `-0X1P+4`, `0x.8p0`, `0x10` (exponent optional,
///   it is a power of two written in decimal);
/// * `f64:TEXT` / `f32:TEXT`: the exact value of the float nearest to TEXT (any of
///   the forms above, parsed exactly then rounded once with [`round_f64`] /
///   [`round_f32`]); rounding to an infinity is an error.
///
/// Rejected: empty text, `nan`, `inf`, `infinity`, zero denominators, a sign on
/// a denominator, repeated signs, digit separators, and written exponents with
/// magnitude above [`MAX_EXPONENT`].
///
/// ```
/// use tribez::hazmat::number::{format_rational, parse_rational};
/// let q = |s| format_rational(&parse_rational(s).unwrap());
/// assert_eq!(q("-1.5e-3"), "-3/2000");
/// assert_eq!(q("0x1.8p-3"), "3/16");
/// assert_eq!(q(" -3/6 "), "-1/2");
/// assert_eq!(q("f32:0.1"), "13421773/134217728");
/// assert!(parse_rational("1/0").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<BigRational, NumberError> {
    let t = text.trim();
    if t.is_empty() {
        return Err(NumberError::Empty);
    }
    if let Some(rest) = t.strip_prefix("f64:") {
        let x = round_f64(&parse_plain(rest.trim(), t)?);
        return exact_f64(x).ok_or_else(|| NumberError::NotFinite {
            text: t.to_owned(),
            format: "f64",
        });
    }
    if let Some(rest) = t.strip_prefix("f32:") {
        let x = round_f32(&parse_plain(rest.trim(), t)?);
        return exact_f32(x).ok_or_else(|| NumberError::NotFinite {
            text: t.to_owned(),
            format: "f32",
        });
    }
    parse_plain(t, t)
}

/// Alias of [`parse_rational`], for number texts read from JSON/TOML files: the
/// exact value of the number as written.
pub fn parse_number_text(text: &str) -> Result<BigRational, NumberError> {
    parse_rational(text)
}

/// Parses the forms without prefix; `whole` is the text quoted in errors.
fn parse_plain(s: &str, whole: &str) -> Result<BigRational, NumberError> {
    let syntax = || NumberError::Syntax(whole.to_owned());
    let (neg, body) = split_sign(s);
    if body.eq_ignore_ascii_case("nan") {
        return Err(NumberError::Nan(whole.to_owned()));
    }
    if body.eq_ignore_ascii_case("inf") || body.eq_ignore_ascii_case("infinity") {
        return Err(NumberError::Infinite(whole.to_owned()));
    }
    if let Some((num, den)) = body.split_once('/') {
        let num = parse_digits(num, 10).ok_or_else(syntax)?;
        let den = parse_digits(den, 10).ok_or_else(syntax)?;
        if den.is_zero() {
            return Err(NumberError::ZeroDenominator(whole.to_owned()));
        }
        return Ok(BigRational::new(signed(neg, num), BigInt::from(den)));
    }
    let hex = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X"));
    if let Some(hex) = hex {
        let (mantissa, exp) = match hex.split_once(['p', 'P']) {
            Some((m, e)) => (m, parse_exponent(e, whole)?),
            None => (hex, 0),
        };
        let (m, frac_len) = parse_mantissa(mantissa, 16).ok_or_else(syntax)?;
        let e2 = exp - 4 * i64::try_from(frac_len).map_err(|_| syntax())?;
        return Ok(dyadic(neg, m, e2));
    }
    let (mantissa, exp) = match body.split_once(['e', 'E']) {
        Some((m, e)) => (m, parse_exponent(e, whole)?),
        None => (body, 0),
    };
    let (m, frac_len) = parse_mantissa(mantissa, 10).ok_or_else(syntax)?;
    let e10 = exp - i64::try_from(frac_len).map_err(|_| syntax())?;
    let too_large = || NumberError::ExponentTooLarge(whole.to_owned());
    let p = u32::try_from(e10.unsigned_abs()).map_err(|_| too_large())?;
    let power = BigUint::from(10u32).pow(p);
    Ok(if e10 >= 0 {
        BigRational::from_integer(signed(neg, m * power))
    } else {
        BigRational::new(signed(neg, m), BigInt::from(power))
    })
}

/// Splits one optional leading `+` or `-`.
fn split_sign(s: &str) -> (bool, &str) {
    match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    }
}

fn signed(neg: bool, m: BigUint) -> BigInt {
    BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, m)
}

/// A non-empty string of digits in `radix` (10 or 16), nothing else.
fn parse_digits(s: &str, radix: u32) -> Option<BigUint> {
    if s.is_empty() || !s.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    BigUint::parse_bytes(s.as_bytes(), radix)
}

/// `int[.frac]`, at least one digit in total; returns the digits as one integer
/// and the number of fraction digits.
fn parse_mantissa(s: &str, radix: u32) -> Option<(BigUint, usize)> {
    let (int, frac) = s.split_once('.').unwrap_or((s, ""));
    let is_digits = |p: &str| p.chars().all(|c| c.is_digit(radix));
    if int.len() + frac.len() == 0 || !is_digits(int) || !is_digits(frac) {
        return None;
    }
    let m = if frac.is_empty() {
        parse_digits(int, radix)?
    } else {
        parse_digits(&[int, frac].concat(), radix)?
    };
    Some((m, frac.len()))
}

/// `[+-]digits`, decimal, magnitude at most [`MAX_EXPONENT`].
fn parse_exponent(s: &str, whole: &str) -> Result<i64, NumberError> {
    let (neg, digits) = split_sign(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(NumberError::Syntax(whole.to_owned()));
    }
    let digits = digits.trim_start_matches('0');
    let too_large = || NumberError::ExponentTooLarge(whole.to_owned());
    if digits.len() > 6 {
        return Err(too_large());
    }
    let value: u64 = if digits.is_empty() {
        0
    } else {
        digits.parse().map_err(|_| too_large())?
    };
    if value > MAX_EXPONENT {
        return Err(too_large());
    }
    let value = value as i64;
    Ok(if neg { -value } else { value })
}

/// `±m·2^e` in lowest terms (the power of two is cancelled against `m`).
fn dyadic(neg: bool, mut m: BigUint, mut e: i64) -> BigRational {
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

// ---------------------------------------------------------------------------
// Printing
// ---------------------------------------------------------------------------

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
/// `1e-5 ≤ |x| < 1e16` and zero, `{:e}` otherwise; `inf`, `-inf`, `NaN`.
pub fn display_f64(x: f64) -> String {
    if !x.is_finite() || x == 0.0 || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Shortest round-trip decimal of `x`, as [`display_f64`] (thresholds `1e-5`, `1e16`).
pub fn display_f32(x: f32) -> String {
    if !x.is_finite() || x == 0.0 || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// C99 hex-float text of `x`, exact and accepted back by [`parse_rational`]:
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
    if x.is_nan() {
        return "nan".to_owned();
    }
    let bits = x.to_bits();
    let neg = bits >> 63 == 1;
    if x.is_infinite() {
        return if neg { "-inf" } else { "inf" }.to_owned();
    }
    let biased = ((bits >> 52) & 0x7FF) as i64;
    let frac = bits & F64_FRAC_MASK;
    match (biased, frac) {
        (0, 0) => hex_text(neg, 0, 0, 13, 0),
        (0, _) => hex_text(neg, 0, frac, 13, -1022),
        _ => hex_text(neg, 1, frac, 13, biased - 1023),
    }
}

/// C99 hex-float text of an `f32` (6 fraction hex digits, the last one even):
/// `0x1.99999ap-4` for `0.1f32`, subnormals `0x0.hhhhhhp-126`; see [`hex_f64`].
pub fn hex_f32(x: f32) -> String {
    if x.is_nan() {
        return "nan".to_owned();
    }
    let bits = x.to_bits();
    let neg = bits >> 31 == 1;
    if x.is_infinite() {
        return if neg { "-inf" } else { "inf" }.to_owned();
    }
    let biased = i64::from((bits >> 23) & 0xFF);
    let frac = u64::from(bits & F32_FRAC_MASK) << 1;
    match (biased, frac) {
        (0, 0) => hex_text(neg, 0, 0, 6, 0),
        (0, _) => hex_text(neg, 0, frac, 6, -126),
        _ => hex_text(neg, 1, frac, 6, biased - 127),
    }
}

fn hex_text(neg: bool, lead: u8, frac: u64, width: usize, exp: i64) -> String {
    let sign = if neg { "-" } else { "" };
    if frac == 0 {
        return format!("{sign}0x{lead}p{exp:+}");
    }
    let digits = format!("{frac:0width$x}");
    format!("{sign}0x{lead}.{}p{exp:+}", digits.trim_end_matches('0'))
}

// ---------------------------------------------------------------------------
// Exact values of floats
// ---------------------------------------------------------------------------

const F64_FRAC_MASK: u64 = (1 << 52) - 1;
const F32_FRAC_MASK: u32 = (1 << 23) - 1;

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
    let bits = x.to_bits();
    let biased = (bits >> 52) & 0x7FF;
    let frac = bits & F64_FRAC_MASK;
    let (m, e) = match biased {
        0x7FF => return None,
        0 => (frac, -1074),
        _ => (frac | (1 << 52), biased as i64 - 1075),
    };
    Some(dyadic_u64(bits >> 63 == 1, m, e))
}

/// Exact value of a finite `f32`, `None` for NaN and ±inf: `(−1)^s·f·2^−149` when
/// e = 0, else `(−1)^s·(2^23+f)·2^(e−150)`.
pub fn exact_f32(x: f32) -> Option<BigRational> {
    let bits = x.to_bits();
    let biased = (bits >> 23) & 0xFF;
    let frac = bits & F32_FRAC_MASK;
    let (m, e) = match biased {
        0xFF => return None,
        0 => (frac, -149),
        _ => (frac | (1 << 23), i64::from(biased) - 150),
    };
    Some(dyadic_u64(bits >> 31 == 1, u64::from(m), e))
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

// ---------------------------------------------------------------------------
// Correct rounding (round to nearest, ties to even), integers only
// ---------------------------------------------------------------------------

/// A binary floating-point format.
#[derive(Clone, Copy)]
struct Format {
    /// Significand bits, hidden bit included.
    prec: u32,
    emin: i64,
    emax: i64,
}

const BINARY64: Format = Format {
    prec: 53,
    emin: -1022,
    emax: 1023,
};
const BINARY32: Format = Format {
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
enum Magnitude {
    Finite { m: u64, e: i64 },
    Infinite,
}

/// Rounded magnitude and how it compares with the exact magnitude.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
struct Rounded {
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

fn is_power_of_two(b: &BigUint) -> bool {
    b.trailing_zeros() == Some(b.bits() - 1)
}

/// floor(log2(a/b)) for `a, b > 0`: with e = bitlen(a) − bitlen(b), the answer is
/// e − 1 when a < b·2^e, else e (docs/theory.md §14.4). Both sides of the comparison have
/// the same bit length, so their leading 64 bits usually decide it.
fn floor_log2_mag(a: &BigUint, b: &BigUint) -> i64 {
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
fn round_small(a: u64, b: u64, f: Format) -> Rounded {
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
fn round_big(a: &BigUint, b: &BigUint, f: Format) -> Rounded {
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

fn encode_f64(neg: bool, mag: Magnitude) -> f64 {
    let bits = match mag {
        Magnitude::Infinite => 0x7FF0_0000_0000_0000,
        Magnitude::Finite { m, e } if m >> 52 != 0 => {
            (((e + 1023) as u64) << 52) | (m & F64_FRAC_MASK)
        }
        Magnitude::Finite { m, .. } => m,
    };
    f64::from_bits(bits | (u64::from(neg) << 63))
}

fn encode_f32(neg: bool, mag: Magnitude) -> f32 {
    let bits = match mag {
        Magnitude::Infinite => 0x7F80_0000,
        Magnitude::Finite { m, e } if m >> 23 != 0 => {
            (((e + 127) as u32) << 23) | (m as u32 & F32_FRAC_MASK)
        }
        Magnitude::Finite { m, .. } => m as u32,
    };
    f32::from_bits(bits | (u32::from(neg) << 31))
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
    match round_rational(q, BINARY64) {
        Some((neg, r)) => encode_f64(neg, r.mag),
        None => f64::NAN,
    }
}

/// The `f32` nearest to `q`, ties to even, rounded once from the exact value
/// (never through `f64`, which could round twice): 24-bit significand, e ≥ −126,
/// subnormals multiples of 2^−149, overflow (from 2^128 − 2^103 up) to ±inf.
/// Signs of zero and NaN as in [`round_f64`].
pub fn round_f32(q: &BigRational) -> f32 {
    match round_rational(q, BINARY32) {
        Some((neg, r)) => encode_f32(neg, r.mag),
        None => f32::NAN,
    }
}

/// Whether `x` is a faithful rounding of `q`: `x = q` when `q` is an `f64`,
/// otherwise `x` is one of the two floats bracketing `q` (for |q| beyond
/// `f64::MAX` these are `±MAX` and `±inf`). `-0.0` and `+0.0` are the same;
/// NaN is never faithful.
pub fn is_faithful_f64(x: f64, q: &BigRational) -> bool {
    let Some((neg, r)) = round_rational(q, BINARY64) else {
        return false;
    };
    if x.is_nan() {
        return false;
    }
    let nearest = key_f64(encode_f64(neg, r.mag));
    let dir = if neg { r.dir.reverse() } else { r.dir };
    faithful_key(key_f64(x), nearest, dir)
}

/// [`is_faithful_f64`] for `f32`.
pub fn is_faithful_f32(x: f32, q: &BigRational) -> bool {
    let Some((neg, r)) = round_rational(q, BINARY32) else {
        return false;
    };
    if x.is_nan() {
        return false;
    }
    let nearest = key_f32(encode_f32(neg, r.mag));
    let dir = if neg { r.dir.reverse() } else { r.dir };
    faithful_key(i64::from(key_f32(x)), i64::from(nearest), dir)
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

// ---------------------------------------------------------------------------
// ULPs and step distances
// ---------------------------------------------------------------------------

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

fn ulp_in(q: &BigRational, f: Format) -> BigRational {
    let e = if q.is_zero() {
        f.emin
    } else {
        floor_log2(q).max(f.emin)
    };
    pow2(e - i64::from(f.prec - 1))
}

/// Binade ulp of a rational (docs/theory.md §14.4, as `math.ulp` on f64 values):
/// `2^(e−52)` with e = floor(log2|q|) clamped to ≥ −1022; ulp(0) = 2^−1074.
/// (Not clamped above: beyond `f64::MAX` it keeps growing with the binade.)
pub fn ulp_f64(q: &BigRational) -> BigRational {
    ulp_in(q, BINARY64)
}

/// Binade ulp in `f32`: `2^(e−23)` with e = floor(log2|q|) clamped to ≥ −126;
/// ulp(0) = 2^−149.
pub fn ulp_f32(q: &BigRational) -> BigRational {
    ulp_in(q, BINARY32)
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
    (x - q).abs() / ulp_f64(q)
}

/// `|x − q| / ulp_f32(q)` exactly.
pub fn ulps_error_f32(x: &BigRational, q: &BigRational) -> BigRational {
    (x - q).abs() / ulp_f32(q)
}

/// Order-preserving integer key of an `f64` (docs/theory.md §14.4): the bits when the
/// sign is clear, else −(bits without sign); ±0 both map to 0.
fn key_f64(x: f64) -> i64 {
    let bits = x.to_bits();
    let magnitude = (bits & !(1 << 63)) as i64;
    if bits >> 63 == 0 {
        magnitude
    } else {
        -magnitude
    }
}

fn key_f32(x: f32) -> i32 {
    let bits = x.to_bits();
    let magnitude = (bits & !(1 << 31)) as i32;
    if bits >> 31 == 0 {
        magnitude
    } else {
        -magnitude
    }
}

/// Number of `nextafter` steps between `a` and `b`: |key(a) − key(b)| with the
/// key of docs/theory.md §14.4, so ±0 are the same point and crossing zero counts the
/// steps on both sides (`steps_f64(-5e-324, 5e-324) = 2`). Infinities are one
/// step beyond `±MAX`. `u64::MAX` if either is NaN.
pub fn steps_f64(a: f64, b: f64) -> u64 {
    if a.is_nan() || b.is_nan() {
        return u64::MAX;
    }
    key_f64(a).abs_diff(key_f64(b))
}

/// [`steps_f64`] for `f32`; `u32::MAX` if either is NaN.
pub fn steps_f32(a: f32, b: f32) -> u32 {
    if a.is_nan() || b.is_nan() {
        return u32::MAX;
    }
    key_f32(a).abs_diff(key_f32(b))
}

// ---------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(s: &str) -> BigRational {
        parse_rational(s).unwrap_or_else(|e| panic!("{s}: {e}"))
    }

    fn fmt(s: &str) -> String {
        format_rational(&q(s))
    }

    fn ratio(n: i128, d: i128) -> BigRational {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }

    /// Exact decimal text of a dyadic rational m/2^k (m·5^k / 10^k).
    fn dyadic_decimal(x: &BigRational) -> String {
        let k = x.denom().bits() - 1;
        assert!(is_power_of_two(x.denom().magnitude()));
        let digits = (x.numer().abs() * BigInt::from(5u32).pow(k as u32)).to_string();
        let sign = if x.numer().sign() == Sign::Minus {
            "-"
        } else {
            ""
        };
        format!("{sign}{digits}e-{k}")
    }

    fn f64_bits_eq(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits()
    }

    // ----- parsing -----

    #[test]
    fn parses_integers_and_fractions() {
        assert_eq!(fmt("7"), "7");
        assert_eq!(fmt("-12"), "-12");
        assert_eq!(fmt("+3"), "3");
        assert_eq!(fmt("  42\t\n"), "42");
        assert_eq!(fmt("-0"), "0");
        assert_eq!(fmt("007"), "7");
        assert_eq!(fmt("4/9"), "4/9");
        assert_eq!(fmt("-3/6"), "-1/2");
        assert_eq!(fmt("+10/5"), "2");
        assert_eq!(fmt("0/5"), "0");
        assert_eq!(fmt("-0/5"), "0");
        assert_eq!(
            fmt("123456789012345678901234567890/10"),
            "12345678901234567890123456789"
        );
    }

    #[test]
    fn parses_decimals_exactly() {
        assert_eq!(fmt("0.125"), "1/8");
        assert_eq!(fmt("-1.5e-3"), "-3/2000");
        assert_eq!(fmt(".5"), "1/2");
        assert_eq!(fmt("5."), "5");
        assert_eq!(fmt("1E10"), "10000000000");
        assert_eq!(fmt("2e+3"), "2000");
        assert_eq!(fmt("0.1"), "1/10");
        assert_eq!(fmt("-0.0"), "0");
        assert_eq!(fmt("1.25e-0"), "5/4");
        assert_eq!(fmt("12.5e-1"), "5/4");
        assert_eq!(fmt("1e-00005"), "1/100000");
        assert_eq!(
            q("1e100000"),
            BigRational::from_integer(BigInt::from(10u32).pow(100_000))
        );
        assert_eq!(
            q("1e-100000").recip(),
            BigRational::from_integer(BigInt::from(10u32).pow(100_000))
        );
    }

    #[test]
    fn parses_hex_floats() {
        assert_eq!(fmt("0x1.8p-3"), "3/16");
        assert_eq!(fmt("-0X1P+4"), "-16");
        assert_eq!(fmt("0x.8p0"), "1/2");
        assert_eq!(fmt("0x10"), "16");
        assert_eq!(fmt("0xff"), "255");
        assert_eq!(fmt("0x1.p1"), "2");
        assert_eq!(fmt("0xA.Bp0"), "171/16");
        assert_eq!(fmt("0x1.8e"), "199/128"); // `e` is a hex digit, not an exponent
        assert_eq!(fmt("0x1p-1074"), format!("1/{}", BigInt::one() << 1074u32));
        assert_eq!(q("0x1.999999999999ap-4"), exact_f64(0.1).unwrap());
        assert_eq!(q("0x0.0000000000001p-1022"), exact_f64(5e-324).unwrap());
    }

    #[test]
    fn parses_float_prefixes() {
        assert_eq!(fmt("f64:0.1"), "3602879701896397/36028797018963968");
        assert_eq!(q("f64:0.1"), exact_f64(0.1).unwrap());
        assert_eq!(q("f64: -2.5e-3 "), exact_f64(-2.5e-3).unwrap());
        assert_eq!(q("f64:1/3"), exact_f64(1.0 / 3.0).unwrap());
        assert_eq!(q("f64:0x1.8p-3"), q("3/16"));
        assert_eq!(q("f64:1e-400"), BigRational::zero());
        assert_eq!(q("f64:-1e-400"), BigRational::zero());
        assert_eq!(
            q("f64:1.7976931348623157e308"),
            exact_f64(f64::MAX).unwrap()
        );
        // 0.1f32 = 13421773 / 2^27
        assert_eq!(fmt("f32:0.1"), "13421773/134217728");
        assert_eq!(q("f32:0.1"), exact_f32(0.1f32).unwrap());
        assert_eq!(q("f32:3.4028235e38"), exact_f32(f32::MAX).unwrap());
        assert_eq!(q("f32:1e-50"), BigRational::zero());
        // Rounded directly to f32: no double rounding through f64.
        let via_direct = q("f32:0x1.000001000000001p0"); // 1 + 2^-24 + 2^-60
        assert_eq!(via_direct, q("0x1.000002p0")); // 1 + 2^-23
    }

    #[test]
    fn rejects_bad_text() {
        use NumberError::*;
        let err = |s: &str| parse_rational(s).unwrap_err();
        assert_eq!(err(""), Empty);
        assert_eq!(err("   "), Empty);
        for s in [
            "abc",
            "1/-2",
            "1/+2",
            "--1",
            "+-1",
            "-+1",
            "- 1",
            "1 2",
            "1/2/3",
            "/2",
            "1/",
            ".",
            "e5",
            "1e",
            "1e+",
            "1e--5",
            "1.2.3",
            "0x",
            "0x.p1",
            "0x1p",
            "0x1.8q",
            "0xg",
            "1_000",
            "0x1_0",
            "f64:",
            "f64:f64:1",
            "f32:abc",
            "F64:1",
            "1/2.5",
            "0x10/3",
            "١",
            "1e5.5",
            "0b101",
            "1,5",
            "++1",
        ] {
            assert_eq!(err(s), Syntax(s.trim().to_owned()), "{s:?}");
        }
        assert_eq!(err("1/0"), ZeroDenominator("1/0".into()));
        assert_eq!(err("-0/00"), ZeroDenominator("-0/00".into()));
        for s in ["nan", "NaN", "-nan", "f64:nan"] {
            assert_eq!(err(s), Nan(s.into()));
        }
        for s in ["inf", "-inf", "+Infinity", "INF", "f32:inf"] {
            assert_eq!(err(s), Infinite(s.into()));
        }
        for s in [
            "1e100001",
            "1e-100001",
            "0x1p100001",
            "0e9999999999999999999999",
            "f64:1e-1000000",
        ] {
            assert_eq!(err(s), ExponentTooLarge(s.into()), "{s}");
        }
        assert_eq!(
            err("f64:1e999"),
            NotFinite {
                text: "f64:1e999".into(),
                format: "f64"
            }
        );
        assert_eq!(
            err("f64:-0x1p1024"),
            NotFinite {
                text: "f64:-0x1p1024".into(),
                format: "f64"
            }
        );
        assert_eq!(
            err("f32:1e39"),
            NotFinite {
                text: "f32:1e39".into(),
                format: "f32"
            }
        );
    }

    #[test]
    fn error_messages() {
        let msg = |s: &str| parse_rational(s).unwrap_err().to_string();
        assert_eq!(msg("1/0"), "`1/0`: zero denominator");
        assert_eq!(
            msg("abc"),
            "`abc`: not a number (expected an integer, p/q, decimal, hex float, or f64:/f32: prefix)"
        );
        assert_eq!(msg("f64:1e999"), "`f64:1e999`: not a finite f64");
        assert_eq!(msg("nan"), "`nan`: NaN has no exact value");
        assert_eq!(msg("-inf"), "`-inf`: infinity has no exact value");
    }

    // ----- printing -----

    #[test]
    fn formats_rationals() {
        assert_eq!(format_rational(&ratio(6, -4)), "-3/2");
        assert_eq!(format_rational(&ratio(0, -7)), "0");
        let raw = BigRational::new_raw(BigInt::from(6), BigInt::from(-4));
        assert_eq!(format_rational(&raw), "-3/2");
        let raw_zero = BigRational::new_raw(BigInt::from(0), BigInt::from(-4));
        assert_eq!(format_rational(&raw_zero), "0");
        let raw_int = BigRational::new_raw(BigInt::from(-8), BigInt::from(-4));
        assert_eq!(format_rational(&raw_int), "2");
    }

    #[test]
    fn decimal_strings() {
        let d = |s: &str, n| to_decimal_string(&q(s), n);
        assert_eq!(d("1/3", 5), "0.33333");
        assert_eq!(d("2/3", 3), "0.667");
        assert_eq!(d("-1/8", 17), "-0.125");
        assert_eq!(d("12", 17), "12");
        assert_eq!(d("0", 5), "0");
        assert_eq!(d("1", 1), "1");
        assert_eq!(d("100", 3), "100");
        assert_eq!(d("1000", 3), "1e3");
        assert_eq!(d("9.96", 2), "10");
        assert_eq!(d("99.6", 2), "1e2");
        assert_eq!(d("0.25", 1), "0.2"); // tie to even
        assert_eq!(d("0.35", 1), "0.4"); // tie to even
        assert_eq!(d("0.3500001", 1), "0.4");
        assert_eq!(d("1/7", 0), "0.1"); // digits clamped to 1
        assert_eq!(d("0.00001", 3), "0.00001");
        assert_eq!(d("0.000001", 3), "1e-6");
        assert_eq!(d("1.2345e-20", 5), "1.2345e-20");
        assert_eq!(d("-1.2345e-20", 3), "-1.23e-20");
        assert_eq!(d("1e300", 17), "1e300");
        assert_eq!(d("1e-300", 17), "1e-300");
        assert_eq!(
            d("123456789012345678901234567890", 40),
            "1.2345678901234567890123456789e29"
        );
        assert_eq!(
            to_decimal_string(&exact_f64(0.1).unwrap(), 17),
            "0.10000000000000001"
        );
        assert_eq!(
            to_decimal_string(&exact_f64(0.1).unwrap(), 55),
            "0.1000000000000000055511151231257827021181583404541015625"
        );
    }

    #[test]
    fn display_floats() {
        assert_eq!(display_f64(0.1), "0.1");
        assert_eq!(display_f64(1.0), "1");
        assert_eq!(display_f64(-0.0), "-0");
        assert_eq!(display_f64(1e300), "1e300");
        assert_eq!(display_f64(5e-324), "5e-324");
        assert_eq!(display_f64(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(display_f64(f64::INFINITY), "inf");
        assert_eq!(display_f32(0.1), "0.1");
        assert_eq!(display_f32(1e-40), "1e-40");
        assert_eq!(display_f32(f32::MAX), "3.4028235e38");
    }

    #[test]
    fn hex_texts() {
        assert_eq!(hex_f64(0.1), "0x1.999999999999ap-4");
        assert_eq!(q(&hex_f64(0.1)), exact_f64(0.1).unwrap());
        assert_eq!(hex_f64(1.0), "0x1p+0");
        assert_eq!(hex_f64(-1.0), "-0x1p+0");
        assert_eq!(hex_f64(0.0), "0x0p+0");
        assert_eq!(hex_f64(-0.0), "-0x0p+0");
        assert_eq!(hex_f64(1.5), "0x1.8p+0");
        assert_eq!(hex_f64(5e-324), "0x0.0000000000001p-1022");
        assert_eq!(hex_f64(f64::MIN_POSITIVE), "0x1p-1022");
        assert_eq!(hex_f64(f64::MAX), "0x1.fffffffffffffp+1023");
        assert_eq!(hex_f64(f64::INFINITY), "inf");
        assert_eq!(hex_f64(f64::NEG_INFINITY), "-inf");
        assert_eq!(hex_f64(f64::NAN), "nan");
        assert_eq!(hex_f32(0.1), "0x1.99999ap-4");
        assert_eq!(hex_f32(-2.0), "-0x1p+1");
        assert_eq!(hex_f32(f32::from_bits(1)), "0x0.000002p-126");
        assert_eq!(hex_f32(f32::MAX), "0x1.fffffep+127");
        assert_eq!(hex_f32(f32::NAN), "nan");
    }

    // ----- exact values and rounding -----

    #[test]
    fn exact_values() {
        assert_eq!(
            format_rational(&exact_f64(0.1).unwrap()),
            "3602879701896397/36028797018963968"
        );
        assert_eq!(exact_f64(1.0).unwrap(), BigRational::one());
        assert_eq!(exact_f64(-0.0).unwrap(), BigRational::zero());
        assert_eq!(exact_f64(-3.0).unwrap(), ratio(-3, 1));
        assert_eq!(exact_f64(5e-324).unwrap(), pow2(-1074));
        assert_eq!(exact_f64(f64::MIN_POSITIVE).unwrap(), pow2(-1022));
        assert_eq!(exact_f64(f64::MAX).unwrap(), pow2(1024) - pow2(971));
        assert_eq!(exact_f64(2f64.powi(100)).unwrap(), pow2(100));
        assert_eq!(exact_f64(f64::INFINITY), None);
        assert_eq!(exact_f64(f64::NAN), None);
        assert_eq!(exact_f32(0.1).unwrap(), ratio(13421773, 1 << 27));
        assert_eq!(exact_f32(f32::from_bits(1)).unwrap(), pow2(-149));
        assert_eq!(exact_f32(f32::MAX).unwrap(), pow2(128) - pow2(104));
        assert_eq!(exact_f32(f32::NEG_INFINITY), None);
    }

    #[test]
    fn round_trips_of_special_values() {
        let specials = [
            0.0,
            1.0,
            -1.0,
            0.5,
            2.0,
            1024.0,
            0.1,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            2f64.powi(-1000),
            2f64.powi(1000),
            f64::from_bits(0x000F_FFFF_FFFF_FFFF),
        ];
        for x in specials {
            assert!(f64_bits_eq(round_f64(&exact_f64(x).unwrap()), x), "{x:e}");
        }
        assert!(f64_bits_eq(round_f64(&exact_f64(-0.0).unwrap()), 0.0));
        for x in [
            0.0f32,
            1.0,
            -0.1,
            f32::MIN_POSITIVE,
            f32::from_bits(1),
            f32::MAX,
            f32::MIN,
        ] {
            assert_eq!(
                round_f32(&exact_f32(x).unwrap()).to_bits(),
                x.to_bits(),
                "{x:e}"
            );
        }
    }

    #[test]
    fn rounding_ties_and_edges() {
        let one = BigRational::one();
        // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: ties to even, down.
        assert_eq!(round_f64(&(&one + pow2(-53))), 1.0);
        // 1 + 3·2^-53 is halfway between 1 + 2^-52 and 1 + 2^-51: up.
        assert_eq!(
            round_f64(&(&one + pow2(-53) * ratio(3, 1))),
            1.0 + 2f64.powi(-51)
        );
        assert_eq!(
            round_f64(&(&one + pow2(-53) + pow2(-200))),
            1.0 + 2f64.powi(-52)
        );
        assert_eq!(round_f64(&(&one - pow2(-54))), 1.0); // tie below 1: even is 1
        assert_eq!(
            round_f64(&(&one - pow2(-54) - pow2(-300))),
            1.0 - 2f64.powi(-53)
        );
        // Overflow: 2^1024 - 2^970 is a tie between MAX and 2^1024: to infinity.
        let tie = pow2(1024) - pow2(970);
        assert_eq!(round_f64(&tie), f64::INFINITY);
        assert_eq!(round_f64(&-&tie), f64::NEG_INFINITY);
        assert_eq!(round_f64(&(&tie - pow2(-1000))), f64::MAX);
        assert_eq!(round_f64(&(&tie - BigRational::one())), f64::MAX);
        assert_eq!(round_f64(&(tie / ratio(3, 1) * ratio(3, 1))), f64::INFINITY);
        assert_eq!(round_f64(&pow2(5000)), f64::INFINITY);
        assert_eq!(round_f64(&q("1e100000")), f64::INFINITY);
        // Subnormals: 2^-1075 is a tie between 0 and 2^-1074: to 0 (even).
        assert!(f64_bits_eq(round_f64(&pow2(-1075)), 0.0));
        assert!(f64_bits_eq(round_f64(&-pow2(-1075)), -0.0));
        assert_eq!(round_f64(&(pow2(-1075) + pow2(-2000))), 5e-324);
        assert_eq!(round_f64(&(pow2(-1075) * ratio(3, 1))), 1e-323); // tie 1.5 → 2
        assert_eq!(round_f64(&q("1e-100000")), 0.0);
        assert_eq!(round_f64(&(ratio(1, 3) * pow2(-1070))), f64::from_bits(5)); // 16/3 → 5
        // The largest subnormal rounds up into the normal range.
        assert_eq!(round_f64(&(pow2(-1022) - pow2(-1076))), f64::MIN_POSITIVE);
        assert!(f64_bits_eq(round_f64(&BigRational::zero()), 0.0));
        assert!(round_f64(&BigRational::new_raw(BigInt::one(), BigInt::zero())).is_nan());
        // Small (u64) and big paths, non-dyadic.
        assert_eq!(round_f64(&ratio(1, 3)), 1.0 / 3.0);
        assert_eq!(round_f64(&ratio(-2, 3)), -2.0 / 3.0);
        assert_eq!(
            round_f64(&ratio(u64::MAX as i128, 1)),
            18446744073709551615.0
        );
        assert_eq!(
            round_f64(&ratio(1, u64::MAX as i128)),
            5.421010862427522e-20
        );
        // 2^-1050/3 = (2^24/3)·2^-1074 = 5592405.33·2^-1074
        assert_eq!(
            round_f64(&(ratio(1, 3) * pow2(-1050))),
            f64::from_bits(5592405)
        );
        assert_eq!(
            round_f64(&BigRational::new_raw(BigInt::from(1), BigInt::from(-3))),
            -1.0 / 3.0
        );
    }

    #[test]
    fn f32_rounds_once() {
        // q = 1 + 2^-24 + 2^-60: just above the midpoint of 1 and 1 + 2^-23.
        let q1 = BigRational::one() + pow2(-24) + pow2(-60);
        assert_eq!(round_f32(&q1), 1.0 + 2f32.powi(-23));
        // Via f64 it would first become 1 + 2^-24, then tie to even down to 1.
        let via_f64 = round_f64(&q1);
        assert_eq!(via_f64, 1.0 + 2f64.powi(-24));
        assert_eq!(via_f64 as f32, 1.0);
        assert_eq!(round_f32(&(BigRational::one() + pow2(-24))), 1.0);
        // Overflow tie 2^128 - 2^103.
        let tie = pow2(128) - pow2(103);
        assert_eq!(round_f32(&tie), f32::INFINITY);
        assert_eq!(round_f32(&(&tie - pow2(-10))), f32::MAX);
        // Subnormal ties around 2^-149.
        assert_eq!(round_f32(&pow2(-150)).to_bits(), 0);
        assert_eq!(round_f32(&-pow2(-150)).to_bits(), (-0.0f32).to_bits());
        assert_eq!(round_f32(&(pow2(-150) * ratio(3, 1))), f32::from_bits(2));
        assert_eq!(round_f32(&ratio(1, 10)), 0.1f32);
        assert_eq!(round_f32(&ratio(1, 3)), 1.0f32 / 3.0);
    }

    #[test]
    fn faithful() {
        let tenth = ratio(1, 10);
        assert!(is_faithful_f64(0.1, &tenth));
        assert!(is_faithful_f64(0.1f64.next_down(), &tenth)); // 0.1 is above 1/10
        assert!(!is_faithful_f64(0.1f64.next_up(), &tenth));
        assert!(!is_faithful_f64(f64::NAN, &tenth));
        assert!(is_faithful_f64(1.0, &BigRational::one()));
        assert!(!is_faithful_f64(1.0f64.next_up(), &BigRational::one()));
        assert!(is_faithful_f64(-0.0, &BigRational::zero()));
        assert!(!is_faithful_f64(5e-324, &BigRational::zero()));
        assert!(is_faithful_f64(0.0, &pow2(-1100)));
        assert!(is_faithful_f64(5e-324, &pow2(-1100)));
        assert!(is_faithful_f64(-0.0, &-pow2(-1100)));
        assert!(is_faithful_f64(-5e-324, &-pow2(-1100)));
        assert!(!is_faithful_f64(5e-324, &-pow2(-1100)));
        assert!(is_faithful_f64(f64::MAX, &pow2(2000)));
        assert!(is_faithful_f64(f64::INFINITY, &pow2(2000)));
        assert!(is_faithful_f64(f64::NEG_INFINITY, &-pow2(2000)));
        assert!(is_faithful_f64(f64::MIN, &-pow2(2000)));
        assert!(!is_faithful_f64(
            f64::INFINITY,
            &exact_f64(f64::MAX).unwrap()
        ));
        assert!(is_faithful_f32(0.1, &tenth));
        assert!(is_faithful_f32(0.1f32.next_down(), &tenth));
        assert!(!is_faithful_f32(0.1f32.next_up(), &tenth));
    }

    #[test]
    fn ulps_and_log2() {
        assert_eq!(floor_log2(&ratio(1, 1)), 0);
        assert_eq!(floor_log2(&ratio(-7, 1)), 2);
        assert_eq!(floor_log2(&ratio(8, 1)), 3);
        assert_eq!(floor_log2(&ratio(1, 10)), -4);
        assert_eq!(floor_log2(&ratio(1, 8)), -3);
        assert_eq!(floor_log2(&ratio(3, 4)), -1);
        assert_eq!(floor_log2(&(pow2(300) - pow2(-300))), 299);
        assert_eq!(floor_log2(&(pow2(300) + pow2(-300))), 300);
        assert_eq!(floor_log2(&BigRational::zero()), i64::MIN);
        assert_eq!(ulp_f64(&BigRational::one()), pow2(-52));
        assert_eq!(ulp_f64(&ratio(1, 10)), pow2(-56));
        assert_eq!(ulp_f64(&BigRational::zero()), pow2(-1074));
        assert_eq!(ulp_f64(&pow2(-1060)), pow2(-1074));
        assert_eq!(ulp_f64(&exact_f64(f64::MAX).unwrap()), pow2(971));
        assert_eq!(ulp_f32(&BigRational::one()), pow2(-23));
        assert_eq!(ulp_f32(&BigRational::zero()), pow2(-149));
        assert_eq!(ulp_f32(&pow2(-140)), pow2(-149));
        // docs/theory.md §14.4: |0.1 - 1/10| = 1/180143985094819840 = 0.4 ulp(1/10).
        let x = exact_f64(0.1).unwrap();
        assert_eq!(
            format_rational(&(&x - ratio(1, 10))),
            "1/180143985094819840"
        );
        assert_eq!(ulps_error_f64(&x, &ratio(1, 10)), ratio(2, 5));
        // (0.1 + 0.2) - 3/10 = 0.8 ulp(3/10).
        let sum = exact_f64(0.1 + 0.2).unwrap();
        assert_eq!(ulps_error_f64(&sum, &ratio(3, 10)), ratio(4, 5));
        // f32: 1/10 is in [2^-4, 2^-3), so ulp = 2^-27, and 0.1f32 = 13421773/2^27;
        // 13421773/2^27 - 1/10 = (134217730 - 134217728)/(10·2^27) = (1/5)·2^-27.
        assert_eq!(
            ulps_error_f32(&exact_f32(0.1).unwrap(), &ratio(1, 10)),
            ratio(1, 5)
        );
    }

    #[test]
    fn steps() {
        assert_eq!(steps_f64(0.1 + 0.2, 0.3), 1);
        assert_eq!(steps_f64(0.3, 0.1 + 0.2), 1);
        assert_eq!(steps_f64(-5e-324, 5e-324), 2);
        assert_eq!(steps_f64(-0.0, 0.0), 0);
        assert_eq!(steps_f64(1.0, 1.0), 0);
        assert_eq!(steps_f64(1.0, 2.0), 1 << 52);
        assert_eq!(steps_f64(f64::MAX, f64::INFINITY), 1);
        assert_eq!(
            steps_f64(f64::NEG_INFINITY, f64::INFINITY),
            2 * 0x7FF0_0000_0000_0000
        );
        assert_eq!(steps_f64(f64::NAN, 1.0), u64::MAX);
        assert_eq!(steps_f32(-f32::from_bits(1), f32::from_bits(1)), 2);
        assert_eq!(steps_f32(1.0, 1.0f32.next_up()), 1);
        assert_eq!(steps_f32(f32::NEG_INFINITY, f32::INFINITY), 2 * 0x7F80_0000);
        assert_eq!(steps_f64(round_f64(&ratio(3, 10)), 0.1 + 0.2), 1);
    }

    // ----- properties -----

    /// A decimal text with up to 25 mantissa digits, a point somewhere, and an exponent.
    fn decimal_text(exp: std::ops::Range<i32>) -> impl Strategy<Value = String> {
        (
            any::<bool>(),
            "[0-9]{1,25}",
            any::<prop::sample::Index>(),
            exp,
        )
            .prop_map(|(neg, digits, point, e)| {
                let p = point.index(digits.len() + 1);
                let sign = if neg { "-" } else { "" };
                format!("{sign}{}.{}e{e}", &digits[..p], &digits[p..])
            })
    }

    fn any_rational() -> impl Strategy<Value = BigRational> {
        (any::<i128>(), any::<u128>(), -1200i64..1200, 0u32..3).prop_map(|(n, d, k, which)| {
            let d = match which {
                0 => d.max(1),
                1 => d >> (d % 128).max(1), // often small
                _ => u128::from(d as u64 >> 40),
            }
            .max(1);
            BigRational::new(BigInt::from(n), BigInt::from(d)) * pow2(k)
        })
    }

    proptest! {
        #[test]
        fn f64_bits_round_trip(bits in any::<u64>()) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let back = round_f64(&exact_f64(x).unwrap());
            let expected = if x == 0.0 { 0.0 } else { x };
            prop_assert_eq!(back.to_bits(), expected.to_bits());
            prop_assert_eq!(q(&hex_f64(x)), exact_f64(x).unwrap());
            prop_assert_eq!(to_decimal_string(&exact_f64(x).unwrap(), 17).parse::<f64>().unwrap(), x);
            prop_assert_eq!(q(&display_f64(x)), exact_decimal_of(&display_f64(x)));
            prop_assert_eq!(display_f64(x).parse::<f64>().unwrap(), x);
        }

        #[test]
        fn f32_bits_round_trip(bits in any::<u32>()) {
            let x = f32::from_bits(bits);
            prop_assume!(x.is_finite());
            let back = round_f32(&exact_f32(x).unwrap());
            let expected = if x == 0.0 { 0.0 } else { x };
            prop_assert_eq!(back.to_bits(), expected.to_bits());
            prop_assert_eq!(q(&hex_f32(x)), exact_f32(x).unwrap());
            prop_assert_eq!(display_f32(x).parse::<f32>().unwrap(), x);
        }

        #[test]
        fn decimal_agrees_with_std_f64(s in decimal_text(-345..330)) {
            let expected: f64 = s.parse().unwrap();
            let got = round_f64(&q(&s));
            prop_assert!(got == expected && (got == 0.0 || f64_bits_eq(got, expected)), "{} → {:e} vs std {:e}", s, got, expected);
        }

        #[test]
        fn decimal_agrees_with_std_f32(s in decimal_text(-70..45)) {
            let expected: f32 = s.parse().unwrap();
            let got = round_f32(&q(&s));
            prop_assert!(got == expected && (got == 0.0 || got.to_bits() == expected.to_bits()), "{} → {:e} vs std {:e}", s, got, expected);
        }

        #[test]
        fn midpoints_tie_to_even(bits in any::<u64>()) {
            let x = f64::from_bits(bits & !(1 << 63));
            prop_assume!(x.is_finite() && x != f64::MAX);
            let mid = (exact_f64(x).unwrap() + exact_f64(x.next_up()).unwrap()) / ratio(2, 1);
            let text = dyadic_decimal(&mid);
            let expected: f64 = text.parse().unwrap();
            prop_assert_eq!(round_f64(&mid).to_bits(), expected.to_bits());
            prop_assert_eq!(round_f64(&q(&text)).to_bits(), expected.to_bits());
            // ties go to the even significand
            prop_assert_eq!(expected.to_bits() & 1, 0);
        }

        #[test]
        fn f32_midpoints_tie_to_even(bits in any::<u32>()) {
            let x = f32::from_bits(bits & !(1 << 31));
            prop_assume!(x.is_finite() && x != f32::MAX);
            let mid = (exact_f32(x).unwrap() + exact_f32(x.next_up()).unwrap()) / ratio(2, 1);
            let expected: f32 = dyadic_decimal(&mid).parse().unwrap();
            prop_assert_eq!(round_f32(&mid).to_bits(), expected.to_bits());
            prop_assert_eq!(expected.to_bits() & 1, 0);
        }

        #[test]
        fn rounding_error_within_half_ulp(r in any_rational()) {
            let x = round_f64(&r);
            if x.is_finite() {
                let err = (exact_f64(x).unwrap() - &r).abs();
                prop_assert!(err <= ulp_f64(&r) / ratio(2, 1));
                prop_assert!(ulps_error_f64(&exact_f64(x).unwrap(), &r) <= ratio(1, 2));
            } else {
                prop_assert!(r.abs() >= pow2(1024) - pow2(970));
            }
            let y = round_f32(&r);
            if y.is_finite() {
                let err = (exact_f32(y).unwrap() - &r).abs();
                prop_assert!(err <= ulp_f32(&r) / ratio(2, 1));
            } else {
                prop_assert!(r.abs() >= pow2(128) - pow2(103));
            }
        }

        #[test]
        fn small_and_big_paths_agree(a in any::<u64>(), b in 1u64.., wide in any::<bool>()) {
            let b = if wide { b } else { b >> (b % 64) }.max(1);
            let (ba, bb) = (BigUint::from(a), BigUint::from(b));
            prop_assume!(a != 0);
            for f in [BINARY64, BINARY32] {
                prop_assert_eq!(round_small(a, b, f), round_big(&ba, &bb, f));
            }
            prop_assert_eq!(floor_log2_mag(&ba, &bb), floor_log2(&ratio(i128::from(a), i128::from(b))));
            // floor_log2 defining property
            let e = floor_log2(&ratio(i128::from(a), i128::from(b)));
            let r = ratio(i128::from(a), i128::from(b));
            prop_assert!(pow2(e) <= r && r < pow2(e + 1));
        }

        #[test]
        fn faithful_pair(r in any_rational()) {
            let x = round_f64(&r);
            prop_assert!(is_faithful_f64(x, &r));
            let exact = exact_f64(x).is_some_and(|v| v == r);
            let neighbours = [x.next_down(), x.next_up()]
                .into_iter()
                .filter(|&y| y != x && is_faithful_f64(y, &r))
                .count();
            prop_assert_eq!(neighbours, if exact { 0 } else { 1 });
            let y = round_f32(&r);
            prop_assert!(is_faithful_f32(y, &r));
        }

        #[test]
        fn steps_count_next_up(bits in any::<u64>(), n in 0u64..5) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let mut y = x;
            for _ in 0..n { y = y.next_up(); }
            prop_assume!(y.is_finite());
            prop_assert_eq!(steps_f64(x, y), n);
        }

        #[test]
        fn parse_never_panics(s in "\\PC{0,30}") {
            let _ = parse_rational(&s);
        }

        #[test]
        fn parse_never_panics_on_number_like(s in "[-+ ]{0,2}(f64:|f32:)?(0[xX])?[0-9a-fA-F.]{0,6}([eEpP][-+]?[0-9]{0,7})?(/[-+]?[0-9]{0,3})?") {
            let _ = parse_rational(&s);
        }
    }

    /// The exact value of a decimal text via an independent route (std's integer parser).
    fn exact_decimal_of(s: &str) -> BigRational {
        let (mant, exp) = s.split_once('e').unwrap_or((s, "0"));
        let exp: i32 = exp.parse().unwrap();
        let (neg, mant) = mant.strip_prefix('-').map_or((false, mant), |m| (true, m));
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        let digits: BigInt = format!("{int}{frac}").parse().unwrap();
        let e = exp - frac.len() as i32;
        let power = BigRational::from_integer(BigInt::from(10).pow(e.unsigned_abs()));
        let v = BigRational::from_integer(digits);
        let v = if e >= 0 { v * power } else { v / power };
        if neg { -v } else { v }
    }
}
