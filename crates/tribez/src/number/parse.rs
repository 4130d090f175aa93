//! Parsing number text exactly, with limits on its size, and telling a number too large
//! for the floats from a number too long to read.

use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;
use num_traits::Zero;

use super::exact::{dyadic, signed};
use super::exact::{exact_f32, exact_f64};
use super::round::{round_f32, round_f64};

/// Largest accepted magnitude of a written exponent (`1e100000` is accepted,
/// `1e100001` is rejected), so that hostile input cannot allocate huge integers.
pub const MAX_EXPONENT: u64 = 100_000;

/// Most digits a number text may hold: the digits of the mantissa (integer and fraction
/// part, decimal or hexadecimal), or of numerator and denominator together for `p/q`.
/// A number of 100,000 digits is read in well under a second (the gcd that brings `p/q` to
/// lowest terms is quadratic in the length: a million digits took minutes); longer ones are
/// an error ([`NumberError::TooManyDigits`]) checked before any digit is converted.
pub const MAX_DIGITS: usize = 100_000;

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
    /// More than [`MAX_DIGITS`] digits.
    #[error("`{text}`: {digits} digits, above the limit of {limit} digits for a number")]
    TooManyDigits {
        /// The start of the offending text (abbreviated).
        text: String,
        /// How many digits it has.
        digits: usize,
        /// [`MAX_DIGITS`].
        limit: usize,
    },
    /// An `f64:`/`f32:` value that rounds to an infinity.
    #[error("`{text}`: not a finite {format}")]
    NotFinite {
        /// The offending text.
        text: String,
        /// `"f64"` or `"f32"`.
        format: &'static str,
    },
}

impl NumberError {
    /// True when the text was refused for its size only (a written exponent above
    /// [`MAX_EXPONENT`], or more than [`MAX_DIGITS`] digits): "too long to parse", not
    /// malformed. Whether such a number is simply too large (or too small) for a float format
    /// is told by `out_of_float_range`: with a float precision, `1e999999` rounds to
    /// infinity like `1e400` does, while `0.000…1e100001` is a finite number tribez cannot
    /// read.
    pub fn is_size_limit(&self) -> bool {
        matches!(
            self,
            NumberError::ExponentTooLarge(_) | NumberError::TooManyDigits { .. }
        )
    }
}

/// Where a well-formed number text lies, certainly, beyond the range of both float formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutOfRange {
    /// `|x| ≥ 10^400`: above every finite `f64` and `f32`; rounds to ±infinity.
    Overflow {
        /// The sign of the number.
        negative: bool,
    },
    /// `0 < |x| < 10^−400`: below half the smallest subnormal `f64` and `f32`; rounds to ±0.
    Underflow {
        /// The sign of the number.
        negative: bool,
    },
}

/// Whether the number text `text` (any form of [`parse_rational`] except the `f64:`/`f32:`
/// prefixes) is certainly outside the range of the floats, decided from its digits and
/// exponent alone: linear in the text, no big integer built, any length and any exponent
/// accepted. `None` for a malformed text, zero, or a value that may be in range.
///
/// This is how a caller with a float precision treats a number [`parse_rational`] refuses
/// for its size ([`NumberError::is_size_limit`]): `1e999999` as an overflow (like `1e400`,
/// whose exact value is read), `1e-999999` as an underflow, anything else as too long.
///
/// ```
/// use tribez::hazmat::number::{OutOfRange, out_of_float_range, parse_rational};
/// assert!(parse_rational("1e999999").unwrap_err().is_size_limit());
/// assert_eq!(out_of_float_range("-1e999999"), Some(OutOfRange::Overflow { negative: true }));
/// assert_eq!(out_of_float_range("0.001e-999999"), Some(OutOfRange::Underflow { negative: false }));
/// assert_eq!(out_of_float_range("1e300"), None);
/// assert_eq!(out_of_float_range("1e99x"), None);
/// ```
pub fn out_of_float_range(text: &str) -> Option<OutOfRange> {
    // Bounds lo ≤ log_b |x| < hi, with b = 10 or 2.
    const DECIMAL: i64 = 400; // 10^400 > 2^1024 > f64::MAX; 10^-400 < 2^-1075
    const BINARY: i64 = 1100; // 2^1100 > f64::MAX; 2^-1100 < 2^-1075
    let (neg, body) = split_sign(text.trim());
    let classify = |lo: i64, hi: i64, limit: i64| {
        if lo >= limit {
            Some(OutOfRange::Overflow { negative: neg })
        } else if hi <= -limit {
            Some(OutOfRange::Underflow { negative: neg })
        } else {
            None
        }
    };
    if let Some((num, den)) = body.split_once('/') {
        let (dn, dd) = (significant(num, 10)?, significant(den, 10)?);
        if dn == 0 || dd == 0 {
            return None;
        }
        // 10^(dn−1) ≤ p < 10^dn and 10^(dd−1) ≤ q < 10^dd.
        let k = dn as i64 - dd as i64;
        return classify(k - 1, k + 1, DECIMAL);
    }
    let hex = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X"));
    let (radix, digits_per_unit, mantissa, exp, limit) = match hex {
        Some(h) => match h.split_once(['p', 'P']) {
            Some((m, e)) => (16, 4, m, saturating_exponent(e)?, BINARY),
            None => (16, 4, h, 0, BINARY),
        },
        None => match body.split_once(['e', 'E']) {
            Some((m, e)) => (10, 1, m, saturating_exponent(e)?, DECIMAL),
            None => (10, 1, body, 0, DECIMAL),
        },
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let (ni, nf) = (significant(int, radix)?, digit_count(frac, radix)?);
    if int.len() + frac.len() == 0 {
        return None;
    }
    // The magnitude of the mantissa in units of `radix`: [lo, hi) in the exponent's base.
    let (lo, hi) = if ni > 0 {
        (
            digits_per_unit * (ni as i64 - 1),
            digits_per_unit * ni as i64,
        )
    } else {
        let lead = frac.bytes().take_while(|&b| b == b'0').count();
        if lead == nf {
            return None; // zero
        }
        (
            -digits_per_unit * (lead as i64 + 1),
            -digits_per_unit * lead as i64,
        )
    };
    classify(lo.saturating_add(exp), hi.saturating_add(exp), limit)
}

/// Number of digits of `s` in `radix` without leading zeros; `None` unless `s` is all digits
/// (an empty `s` has 0).
fn significant(s: &str, radix: u32) -> Option<usize> {
    digit_count(s, radix)?;
    Some(s.trim_start_matches('0').len())
}

fn digit_count(s: &str, radix: u32) -> Option<usize> {
    s.chars().all(|c| c.is_digit(radix)).then_some(s.len())
}

/// A decimal exponent `[+-]digits`, saturated far beyond any limit.
fn saturating_exponent(s: &str) -> Option<i64> {
    let (neg, digits) = split_sign(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let digits = digits.trim_start_matches('0');
    let v: i64 = if digits.len() > 15 {
        i64::MAX / 4
    } else {
        digits.parse().unwrap_or(0)
    };
    Some(if neg { -v } else { v })
}

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
/// a denominator, repeated signs, digit separators, written exponents with
/// magnitude above [`MAX_EXPONENT`], and more than [`MAX_DIGITS`] digits (both checked
/// before anything is allocated; [`NumberError::is_size_limit`] and
/// `out_of_float_range` tell a number too large for the floats from a malformed one).
/// Long texts are abbreviated in the errors.
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
            text: abbreviate(t),
            format: "f64",
        });
    }
    if let Some(rest) = t.strip_prefix("f32:") {
        let x = round_f32(&parse_plain(rest.trim(), t)?);
        return exact_f32(x).ok_or_else(|| NumberError::NotFinite {
            text: abbreviate(t),
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

/// The text quoted in an error: whole up to 64 characters, else its first 32 characters and
/// its length; control characters (a line break, a tab, `\u{15}`) written as Rust escapes, so
/// that the message stays on one line and shows what was there.
fn abbreviate(s: &str) -> String {
    let visible = |chars: &mut dyn Iterator<Item = char>| {
        let mut out = String::new();
        for c in chars {
            if c.is_control() {
                out.extend(c.escape_default());
            } else {
                out.push(c);
            }
        }
        out
    };
    let n = s.chars().count();
    if n <= 64 {
        visible(&mut s.chars())
    } else {
        format!("{}… ({n} characters)", visible(&mut s.chars().take(32)))
    }
}

fn too_many_digits(whole: &str, digits: usize) -> Result<(), NumberError> {
    if digits > MAX_DIGITS {
        return Err(NumberError::TooManyDigits {
            text: abbreviate(whole),
            digits,
            limit: MAX_DIGITS,
        });
    }
    Ok(())
}

/// Parses the forms without prefix; `whole` is the text quoted in errors.
fn parse_plain(s: &str, whole: &str) -> Result<BigRational, NumberError> {
    let syntax = || NumberError::Syntax(abbreviate(whole));
    let (neg, body) = split_sign(s);
    if body.eq_ignore_ascii_case("nan") {
        return Err(NumberError::Nan(abbreviate(whole)));
    }
    if body.eq_ignore_ascii_case("inf") || body.eq_ignore_ascii_case("infinity") {
        return Err(NumberError::Infinite(abbreviate(whole)));
    }
    if let Some(q) = small(neg, body) {
        return q;
    }
    if let Some((num, den)) = body.split_once('/') {
        if !is_digits(num, 10) || !is_digits(den, 10) {
            return Err(syntax());
        }
        too_many_digits(whole, num.len() + den.len())?;
        let num = parse_digits(num, 10).ok_or_else(syntax)?;
        let den = parse_digits(den, 10).ok_or_else(syntax)?;
        if den.is_zero() {
            return Err(NumberError::ZeroDenominator(abbreviate(whole)));
        }
        return Ok(super::arith::ratio(signed(neg, num), BigInt::from(den)));
    }
    let hex = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X"));
    if let Some(hex) = hex {
        let (mantissa, exp) = match hex.split_once(['p', 'P']) {
            Some((m, e)) => (m, parse_exponent(e, whole)?),
            None => (hex, 0),
        };
        let (m, frac_len) = parse_mantissa(mantissa, 16, whole)?;
        let e2 = exp - 4 * i64::try_from(frac_len).map_err(|_| syntax())?;
        return Ok(dyadic(neg, m, e2));
    }
    let (mantissa, exp) = match body.split_once(['e', 'E']) {
        Some((m, e)) => (m, parse_exponent(e, whole)?),
        None => (body, 0),
    };
    let (m, frac_len) = parse_mantissa(mantissa, 10, whole)?;
    let e10 = exp - i64::try_from(frac_len).map_err(|_| syntax())?;
    Ok(decimal(neg, m, e10))
}

/// The fast path of the commonest forms, an integer `p` or a fraction `p/q` of at most 19
/// digits each: read in machine words, reduced by a word gcd (no big integer until the result).
/// `None` for any other text (the general path then reads it, with its errors).
fn small(neg: bool, body: &str) -> Option<Result<BigRational, NumberError>> {
    let word = |s: &str| -> Option<u64> {
        if s.is_empty() || s.len() > 19 {
            return None;
        }
        s.bytes().try_fold(0u64, |acc, b| {
            b.is_ascii_digit().then(|| acc * 10 + u64::from(b - b'0'))
        })
    };
    let (p, q) = match body.split_once('/') {
        Some((num, den)) => (word(num)?, word(den)?),
        None => (word(body)?, 1),
    };
    if q == 0 {
        return None; // the general path words the error
    }
    let g = super::arith::gcd_u64(p, q);
    let (p, q) = if p == 0 { (0, 1) } else { (p / g, q / g) };
    Some(Ok(BigRational::new_raw(
        signed(neg && p != 0, BigUint::from(p)),
        BigInt::from(q),
    )))
}

/// `±m·10^e` in lowest terms. |e| ≤ MAX_EXPONENT + MAX_DIGITS here. For `e < 0` the
/// common factors of `m` and `10^−e` are powers of 2 and 5, removed by a shift and by
/// dividing by powers of 5 (no general gcd, which is quadratic in the length).
fn decimal(neg: bool, mut m: BigUint, e: i64) -> BigRational {
    let k = e.unsigned_abs();
    if e >= 0 {
        return BigRational::from_integer(signed(neg, m * BigUint::from(10u32).pow(k as u32)));
    }
    if m.is_zero() {
        return BigRational::zero();
    }
    let twos = m.trailing_zeros().unwrap_or(0).min(k);
    m >>= twos;
    // The number of factors 5 of m, v, in binary: with powers 5^(2^i) up to the size of m,
    // taken from the largest down whenever they divide (v < 2^(i+1) before step i); then
    // min(v, k) of them removed.
    let five = BigUint::from(5u32);
    let mut powers = vec![five.clone()];
    while powers.last().is_some_and(|p| p.bits() * 2 <= m.bits() + 1) {
        // invariant: `powers` starts with 5 and only grows
        let p = powers.last().expect("non-empty");
        powers.push(p * p);
    }
    let mut fives = 0u64;
    for (i, p) in powers.iter().enumerate().rev() {
        let (q, r) = num_integer::Integer::div_rem(&m, p);
        if r.is_zero() {
            m = q;
            fives += 1 << i;
        }
    }
    if fives > k {
        m *= five.pow((fives - k) as u32);
        fives = k;
    }
    let den = (BigUint::from(5u32).pow((k - fives) as u32)) << (k - twos);
    BigRational::new_raw(signed(neg, m), BigInt::from(den))
}

/// Splits one optional leading `+` or `-`.
fn split_sign(s: &str) -> (bool, &str) {
    match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    }
}

/// A non-empty string of digits in `radix` (10 or 16), nothing else.
fn is_digits(s: &str, radix: u32) -> bool {
    !s.is_empty() && s.chars().all(|c| c.is_digit(radix))
}

/// A non-empty string of digits in `radix` (10 or 16), nothing else.
fn parse_digits(s: &str, radix: u32) -> Option<BigUint> {
    if !is_digits(s, radix) {
        return None;
    }
    BigUint::parse_bytes(s.as_bytes(), radix)
}

/// `int[.frac]`, at least one digit in total and at most [`MAX_DIGITS`]; returns the digits
/// as one integer and the number of fraction digits.
fn parse_mantissa(s: &str, radix: u32, whole: &str) -> Result<(BigUint, usize), NumberError> {
    let syntax = || NumberError::Syntax(abbreviate(whole));
    let (int, frac) = s.split_once('.').unwrap_or((s, ""));
    let all = |p: &str| p.chars().all(|c| c.is_digit(radix));
    if int.len() + frac.len() == 0 || !all(int) || !all(frac) {
        return Err(syntax());
    }
    too_many_digits(whole, int.len() + frac.len())?;
    let m = if frac.is_empty() {
        parse_digits(int, radix)
    } else {
        parse_digits(&[int, frac].concat(), radix)
    };
    Ok((m.ok_or_else(syntax)?, frac.len()))
}

/// `[+-]digits`, decimal, magnitude at most [`MAX_EXPONENT`].
fn parse_exponent(s: &str, whole: &str) -> Result<i64, NumberError> {
    let (neg, digits) = split_sign(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(NumberError::Syntax(abbreviate(whole)));
    }
    let digits = digits.trim_start_matches('0');
    let too_large = || NumberError::ExponentTooLarge(abbreviate(whole));
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
