//! Printing: exact rationals as `p/q`, rationals as correctly rounded decimals, floats as
//! shortest round-trip decimals and as exact C99 hex floats.

use std::cmp::Ordering;
use std::sync::OnceLock;

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::format::{BinaryFloat, emin, exp_ones, fields, frac_bits};
use super::round::floor_log2_mag;

/// `p/q` in lowest terms with `q > 0`, or `p` when `q = 1`; the sign is on `p`
/// and `-0` never appears. (A rational with zero denominator, which only
/// `Ratio::new_raw` can build, prints as `p/0`.)
///
/// Not quadratic in the gcd: a `BigRational` with a positive denominator is in lowest terms
/// (num-rational keeps that invariant, and tribez builds `new_raw` values only in lowest terms),
/// so no gcd is taken (num-bigint's binary gcd is quadratic in the length); the digits come from
/// `push_decimal`.
///
/// ```
/// use tribez::hazmat::number::{format_rational, parse_rational};
/// assert_eq!(format_rational(&parse_rational("-6/4").unwrap()), "-3/2");
/// assert_eq!(format_rational(&parse_rational("10000000000000000000").unwrap()), "10000000000000000000");
/// ```
pub fn format_rational(q: &BigRational) -> String {
    let mut out = String::new();
    push_rational(&mut out, q);
    out
}

/// Append [`format_rational`]`(q)` to `out`.
pub fn push_rational(out: &mut String, q: &BigRational) {
    let (n, d) = (q.numer(), q.denom());
    if d.is_zero() {
        push_signed(out, n);
        out.push_str("/0");
        return;
    }
    if d.sign() == Sign::Plus {
        debug_assert!(n.gcd(d).is_one(), "rational not in lowest terms");
        push_signed(out, n);
        if !d.is_one() {
            out.push('/');
            push_decimal(out, d.magnitude());
        }
        return;
    }
    push_rational(out, &q.reduced());
}

/// Append the decimal digits of `x` (with a leading `-` when negative) to `out`.
fn push_signed(out: &mut String, x: &BigInt) {
    if x.sign() == Sign::Minus {
        out.push('-');
    }
    push_decimal(out, x.magnitude());
}

/// `10^19`, the largest power of ten below `2^64`; it is at least `2^63` (its top bit is set).
const TEN19: u64 = 10_000_000_000_000_000_000;

/// Append the decimal digits of `x` to `out` (as `x.to_string()`, and equal to it: tested).
///
/// In chunks of 19 digits, the base-`10^19` digits of `x`: by repeated division by `10^19`, one
/// limb at a time, each step a division of a two-limb number by the normalised one-limb divisor
/// through its precomputed reciprocal (Möller and Granlund, "Improved division by invariant
/// integers", Algorithm 4: two products and no division instruction per limb, where num-bigint
/// divides by `10^9` with two hardware divisions per limb); two passes run in one sweep over
/// the limbs, so that their remainder chains overlap. Numbers of 48 limbs or more are first
/// split in two by one division by `10^(19·2^k)` (the largest such power not above the square
/// root of the number, computed once per process), recursively, which makes the quadratic part
/// run at the speed of num-bigint's long division; below 48 limbs (measured on this project's
/// bench `numbers`) the division chains are faster than num-bigint's division and its
/// allocations. A number of [`super::MAX_DIGITS`] digits prints in tens of milliseconds.
pub fn push_decimal(out: &mut String, x: &BigUint) {
    let bits = x.bits();
    if bits <= 64 * SMALL_LIMBS as u64 {
        push_limbs::<SMALL_LIMBS, { digits_for(SMALL_LIMBS) }, { text_for(SMALL_LIMBS) }>(out, x);
    } else if bits <= 64 * MEDIUM_LIMBS as u64 {
        push_limbs::<MEDIUM_LIMBS, { digits_for(MEDIUM_LIMBS) }, { text_for(MEDIUM_LIMBS) }>(
            out, x,
        );
    } else if bits <= 64 * (SPLIT_LIMBS as u64 - 1) {
        push_limbs::<SPLIT_LIMBS, { digits_for(SPLIT_LIMBS) }, { text_for(SPLIT_LIMBS) }>(out, x);
    } else {
        split_decimal(out, x, None);
    }
}

/// The digits of `x`, which has at most `L` limbs, with the buffers of [`push_chunks`] sized
/// for `L` limbs (`D` and `T`): short numbers, the most common, then zero only short buffers.
fn push_limbs<const L: usize, const D: usize, const T: usize>(out: &mut String, x: &BigUint) {
    let mut limbs = [0u64; L];
    let mut len = 0;
    for (slot, limb) in limbs.iter_mut().zip(x.iter_u64_digits()) {
        *slot = limb;
        len += 1;
    }
    push_chunks::<D, T>(out, &mut limbs[..len], None);
}

/// The base-`10^19` digits [`push_chunks`] may produce from `limbs` limbs (its `D`).
const fn digits_for(limbs: usize) -> usize {
    limbs + 2 + FUSED
}

/// The bytes of text [`push_chunks`] may write from `limbs` limbs (its `T`).
const fn text_for(limbs: usize) -> usize {
    19 * (limbs + 2) + 1
}

/// From this many limbs on, [`push_decimal`] splits the number by a power of `10^19`.
const SPLIT_LIMBS: usize = 48;

/// Up to this many limbs (and then up to [`MEDIUM_LIMBS`]), [`push_decimal`] works in buffers
/// sized for it.
const SMALL_LIMBS: usize = 8;
const MEDIUM_LIMBS: usize = 20;

/// Division passes by `10^19` that [`push_chunks`] runs in one sweep over the limbs.
const FUSED: usize = 2;

/// `10^(19·2^k)` for `k = 0, 1, …`, each computed once.
fn power_of_ten(k: usize) -> &'static BigUint {
    static POWERS: [OnceLock<BigUint>; 24] = [const { OnceLock::new() }; 24];
    POWERS[k].get_or_init(|| match k {
        0 => BigUint::from(TEN19),
        _ => {
            let p = power_of_ten(k - 1);
            p * p
        }
    })
}

/// The digits of `x`, exactly `width` of them (leading zeros) when given.
fn split_decimal(out: &mut String, x: &BigUint, width: Option<usize>) {
    let mut limbs = x.to_u64_digits();
    let len = limbs.len();
    if len < SPLIT_LIMBS {
        push_chunks::<{ digits_for(SPLIT_LIMBS) }, { text_for(SPLIT_LIMBS) }>(
            out,
            &mut limbs,
            width.map(|w| w / 19),
        );
        return;
    }
    // the largest k with 10^(19·2^k) of at most half the limbs of x (19·2^k digits each side)
    let mut k = 0;
    while k + 1 < 24 && power_of_ten(k + 1).bits().div_ceil(64) * 2 <= len as u64 {
        k += 1;
    }
    let (hi, lo) = x.div_rem(power_of_ten(k));
    let low_digits = 19 << k;
    split_decimal(out, &hi, width.map(|w| w - low_digits));
    split_decimal(out, &lo, Some(low_digits));
}

/// The digits of the little-endian limbs `limbs` (at most `D − 2 − FUSED` of them, and fewer
/// than [`SPLIT_LIMBS`]; they are used up); with `chunks`, exactly `19·chunks` digits (leading
/// zeros), else no leading zero. Nothing is allocated: the base-`10^19` digits (`D` words) and
/// their text (`T = 19·(D − FUSED) + 1` bytes) are kept on the stack.
fn push_chunks<const D: usize, const T: usize>(
    out: &mut String,
    limbs: &mut [u64],
    chunks: Option<usize>,
) {
    const { assert!(D > 2 + FUSED && T == text_for(D - 2 - FUSED)) };
    debug_assert!(limbs.len() < SPLIT_LIMBS && limbs.len() + 2 + FUSED <= D);
    let mut len = limbs.len();
    while len > 0 && limbs[len - 1] == 0 {
        len -= 1;
    }
    // v = floor((2^128 − 1) / d) − 2^64 for the normalised d = 10^19
    let v = (u128::MAX / u128::from(TEN19) - (1u128 << 64)) as u64;
    // each limb gives at most 64/log2(10^19) < 1.02 chunks: len + 2 is enough (len ≤ 48)
    // (FUSED − 1 more: the last fused pass may produce leading zero chunks, trimmed below)
    let mut digits = [0u64; D];
    let mut count = 0;
    while len > 1 {
        if len > 2 {
            // FUSED passes in one sweep: pass s divides the quotient limb that pass s − 1 has
            // just produced, so the passes' remainder chains run side by side (each division
            // waits on the previous remainder; one chain alone leaves the multipliers idle)
            let mut r = [0u64; FUSED];
            for limb in limbs[..len].iter_mut().rev() {
                let mut x = *limb;
                for rem in &mut r {
                    (x, *rem) = div_2by1(*rem, x, TEN19, v);
                }
                *limb = x;
            }
            digits[count..count + FUSED].copy_from_slice(&r);
            count += FUSED;
        } else {
            let mut r = 0u64;
            for limb in limbs[..len].iter_mut().rev() {
                (*limb, r) = div_2by1(r, *limb, TEN19, v);
            }
            digits[count] = r;
            count += 1;
        }
        while len > 0 && limbs[len - 1] == 0 {
            len -= 1;
        }
    }
    // the last limb may exceed 10^19: one more word division
    if len == 1 {
        let top = limbs[0];
        digits[count] = top % TEN19;
        count += 1;
        if top >= TEN19 {
            digits[count] = top / TEN19;
            count += 1;
        }
    }
    while count > 1 && digits[count - 1] == 0 {
        count -= 1;
    }
    // all the chunks' digits into one buffer, checked as text once (a check per 19-digit chunk
    // cost more than the digits themselves)
    let mut text = [b'0'; T];
    let mut end = 0;
    let mut buf = [b'0'; 20];
    match chunks {
        Some(c) => {
            debug_assert!(count <= c.max(1));
            out.reserve(19 * c.max(count));
            for _ in count..c {
                out.push_str("0000000000000000000");
            }
        }
        None => {
            // the leading chunk without leading zeros (0 itself is "0")
            let top = if count == 0 {
                0
            } else {
                count -= 1;
                digits[count]
            };
            let start = fill_digits(&mut buf, top);
            end = 20 - start;
            text[..end].copy_from_slice(&buf[start..]);
        }
    }
    for &d in digits[..count].iter().rev() {
        fill_19(&mut text[end..end + 19], d);
        end += 19;
    }
    out.push_str(ascii(&text[..end]));
}

/// Digits written by [`fill_digits`] as text.
fn ascii(digits: &[u8]) -> &str {
    // invariant: fill_digits writes ASCII digits (b'0' + d, d < 10) only
    std::str::from_utf8(digits).expect("ASCII digits")
}

/// `(q, r)` with `u1·2^64 + u0 = q·d + r`, `0 ≤ r < d`, for a normalised `d` (top bit set),
/// `u1 < d` and `v = floor((2^128 − 1)/d) − 2^64` (Möller–Granlund, Algorithm 4). The 128-bit
/// sum `v·u1 + u1·2^64 + u0` is formed limb by limb (as one 128-bit expression the compiler
/// multiplies `u1` by one); the first correction is branch-free (it is taken about half the
/// time), the second, rare one is a branch to a cold path. About 30% faster than the plain
/// transcription in a sweep of division chains.
#[inline(always)]
fn div_2by1(u1: u64, u0: u64, d: u64, v: u64) -> (u64, u64) {
    let p = u128::from(v) * u128::from(u1);
    let (q0, carry) = (p as u64).overflowing_add(u0);
    let q1 = ((p >> 64) as u64)
        .wrapping_add(u1)
        .wrapping_add(u64::from(carry))
        .wrapping_add(1);
    let r = u0.wrapping_sub(q1.wrapping_mul(d));
    let mask = u64::from(r > q0).wrapping_neg();
    let q1 = q1.wrapping_add(mask);
    let r = r.wrapping_add(mask & d);
    if r >= d {
        return one_more(q1, r, d);
    }
    (q1, r)
}

/// The rare second correction of [`div_2by1`].
#[cold]
#[inline(never)]
fn one_more(q1: u64, r: u64, d: u64) -> (u64, u64) {
    (q1 + 1, r - d)
}

/// The two decimal digits of each number below 100.
const PAIRS: &[u8; 200] = b"0001020304050607080910111213141516171819\
    2021222324252627282930313233343536373839\
    4041424344454647484950515253545556575859\
    6061626364656667686970717273747576777879\
    8081828384858687888990919293949596979899";

/// Write `x < 10^19` as exactly 19 digits (leading zeros) into `out`: three digits and two
/// groups of eight, each group split into pairs, so that the word divisions (products by
/// constants) are independent of one another instead of one chain of 9 divisions by 100.
fn fill_19(out: &mut [u8], x: u64) {
    debug_assert!(out.len() == 19 && x < TEN19);
    const E8: u64 = 100_000_000;
    let top = (x / (E8 * E8)) as usize;
    let rest = x % (E8 * E8);
    out[0] = b'0' + (top / 100) as u8;
    out[1..3].copy_from_slice(&PAIRS[top % 100 * 2..top % 100 * 2 + 2]);
    fill_8(&mut out[3..11], (rest / E8) as u32);
    fill_8(&mut out[11..19], (rest % E8) as u32);
}

/// Write `x < 10^8` as exactly 8 digits into `out`.
fn fill_8(out: &mut [u8], x: u32) {
    let (hi, lo) = (x / 10_000, x % 10_000);
    for (i, p) in [hi / 100, hi % 100, lo / 100, lo % 100]
        .into_iter()
        .enumerate()
    {
        let p = p as usize * 2;
        out[2 * i..2 * i + 2].copy_from_slice(&PAIRS[p..p + 2]);
    }
}

/// Write the digits of `x` right-aligned into `buf`; returns the index of the first one.
fn fill_digits(buf: &mut [u8; 20], mut x: u64) -> usize {
    let mut i = buf.len();
    while x >= 100 {
        let p = (x % 100) as usize * 2;
        x /= 100;
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIRS[p..p + 2]);
    }
    if x >= 10 {
        let p = x as usize * 2;
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIRS[p..p + 2]);
    } else {
        i -= 1;
        buf[i] = b'0' + x as u8;
    }
    i
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
    decimal_text(q, digits)
}

/// A ULP figure for people: [`to_decimal_string`] to 4 significant digits, or to more (up to
/// 17) while those would show a multiple of 1/2 up to 1024 that the figure is not. Such values
/// are where verdicts turn (a rounding midpoint at 1/2, 1 ulp, the histogram's bucket bounds,
/// `ulps=N` tolerances), so an error just below half an ulp is not shown as `0.5`.
///
/// ```
/// use tribez::hazmat::number::{parse_rational, ulps_decimal};
/// let u = |s| ulps_decimal(&parse_rational(s).unwrap());
/// assert_eq!(u("1/2"), "0.5");
/// assert_eq!(u("0.49999926609526346"), "0.499999");
/// assert_eq!(u("1.00004"), "1.00004");
/// assert_eq!(u("0.123456"), "0.1235");
/// assert_eq!(u("3.99995"), "3.99995");
/// assert_eq!(u("2103.8"), "2104"); // beyond 1024: 4 digits
/// assert_eq!(u("0.4999999999999999999999"), "0.5"); // beyond 17 digits: the nearest text
/// ```
pub fn ulps_decimal(q: &BigRational) -> String {
    let mut text = decimal_text(q, 4);
    for digits in 5..=17 {
        let shown = match super::parse_rational(&text) {
            Ok(x) => x,
            Err(_) => break,
        };
        let doubled = &shown * BigRational::from_integer(2.into());
        let near = num_traits::Signed::abs(&shown) <= BigRational::from_integer(1024.into());
        if !near || !doubled.is_integer() || &shown == q {
            break;
        }
        text = decimal_text(q, digits);
    }
    text
}

fn decimal_text(q: &BigRational, digits: usize) -> String {
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

/// `(1/2, 1/3, 1/6)`: a tuple of exact numbers as text, for messages and reports.
pub fn format_tuple(xs: &[BigRational]) -> String {
    format!(
        "({})",
        xs.iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// `(1, 2), (7, 3)` style text for messages.
pub fn format_points(points: &[Vec<BigRational>]) -> String {
    points
        .iter()
        .map(|p| {
            format!(
                "({})",
                p.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `div_2by1` by `10^19` against the quotient and remainder of 128-bit integer division, at
    /// the edges (`u1 = d − 1`, `u0` near 0 and `2^64`) and on a million pseudo-random pairs,
    /// and how often the rare second correction was needed (it must have been exercised).
    #[test]
    fn division_by_ten_to_the_19_matches_u128() {
        let v = (u128::MAX / u128::from(TEN19) - (1u128 << 64)) as u64;
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut seconds = 0;
        let edges = [0, 1, TEN19 - 1, TEN19, u64::MAX, u64::MAX - TEN19];
        let mut check = |u1: u64, u0: u64| {
            let x = (u128::from(u1) << 64) | u128::from(u0);
            let (q, r) = div_2by1(u1, u0, TEN19, v);
            assert_eq!(
                (u128::from(q), u128::from(r)),
                (x / u128::from(TEN19), x % u128::from(TEN19)),
                "{u1}, {u0}"
            );
            // the estimate before the corrections is q − 1 or q − 2 short only in the rare case
            let p = u128::from(v) * u128::from(u1) + x;
            let estimate = ((p >> 64) as u64).wrapping_add(1);
            let r0 = u0.wrapping_sub(estimate.wrapping_mul(TEN19));
            let r1 = if r0 > p as u64 {
                r0.wrapping_add(TEN19)
            } else {
                r0
            };
            if r1 >= TEN19 {
                seconds += 1;
            }
        };
        for &u1 in &[0, 1, TEN19 / 2, TEN19 - 2, TEN19 - 1] {
            for &u0 in &edges {
                check(u1, u0);
            }
        }
        for _ in 0..1_000_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let u1 = state % TEN19;
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            check(u1, state);
        }
        assert!(seconds > 0, "the second correction never ran");
    }
}
