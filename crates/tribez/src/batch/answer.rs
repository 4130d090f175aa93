//! One line of claimed coordinates, as `tribez hunt` reads each answer of its target: the common
//! forms by a fast path ([`fast_claimed_line`]), everything else by [`parse_claimed_line`],
//! which reads every syntax `check --results` reads. The two give the same numbers: a test
//! compares them on thousands of lines, and the fuzz target `hunt_answer` on any line.

use super::parse::parse_claimed_line;
use crate::float::Precision;

/// Read one line of `dim` claimed coordinates in `precision` and append them to `out`: the
/// numbers [`parse_claimed_line`] gives (each the float of the precision nearest its text;
/// `nan` and an empty field NaN, `inf` and an overflow ±∞), the common forms (hex floats and
/// plain decimals, normal in the precision) read without allocating.
///
/// Errors: [`parse_claimed_line`]'s one-line message (an empty or comment line, the wrong
/// number of numbers, a field that is not a number); `out` is then unchanged.
///
/// ```
/// use tribez::Precision;
/// use tribez::batch::read_claimed_line;
/// let mut out = Vec::new();
/// read_claimed_line("0x1.8p+0, 0.25", 2, Precision::F64, &mut out).unwrap();
/// read_claimed_line("1/3, inf", 2, Precision::F64, &mut out).unwrap();
/// assert_eq!(out, [1.5, 0.25, 1.0 / 3.0, f64::INFINITY]);
/// assert_eq!(
///     read_claimed_line("1,2,3", 2, Precision::F64, &mut out),
///     Err("3 numbers, expected 2".into())
/// );
/// assert_eq!(out.len(), 4);
/// ```
pub fn read_claimed_line(
    line: &str,
    dim: usize,
    precision: Precision,
    out: &mut Vec<f64>,
) -> Result<(), String> {
    if fast_claimed_line(line, precision, out, dim) {
        return Ok(());
    }
    out.extend(parse_claimed_line(line, dim, precision)?);
    Ok(())
}

/// The common answer lines read fast: `dim` comma-separated hex floats (`%a`) or plain decimals,
/// each finite, non-zero and normal in the precision, appended to `out` as the float of the
/// precision nearest the text (hex floats of at most 13 fraction digits are exact in `f64`;
/// decimals are read correctly rounded by the standard library). Anything else (quotes, JSON,
/// `p/q`, zeros, subnormals, not-finite values, a wrong count) returns false with `out`
/// unchanged, and the line goes to [`parse_claimed_line`], which reads every
/// syntax `check --results` reads and gives the same numbers.
pub(crate) fn fast_claimed_line(
    line: &str,
    precision: Precision,
    out: &mut Vec<f64>,
    dim: usize,
) -> bool {
    let start = out.len();
    let mut fields = line.trim().split(',');
    for _ in 0..dim {
        let value = fields.next().map(str::trim).and_then(|f| {
            if f.len() > 40 {
                return None;
            }
            let b = f.as_bytes();
            let unsigned = b.strip_prefix(b"-").or(b.strip_prefix(b"+")).unwrap_or(b);
            if unsigned.len() > 2 && (unsigned[..2] == *b"0x" || unsigned[..2] == *b"0X") {
                hex_float(f)
            } else if plain_decimal(unsigned) {
                match precision {
                    Precision::F64 => f.parse::<f64>().ok(),
                    Precision::F32 => f.parse::<f32>().ok().map(f64::from),
                }
            } else {
                None
            }
        });
        let normal = |v: f64| match precision {
            Precision::F64 => v.is_normal(),
            Precision::F32 => (v as f32).is_normal(),
        };
        match value {
            Some(v) if normal(v) => out.push(match precision {
                Precision::F64 => v,
                Precision::F32 => f64::from(v as f32),
            }),
            _ => {
                out.truncate(start);
                return false;
            }
        }
    }
    if fields.next().is_some() {
        out.truncate(start);
        return false;
    }
    true
}

/// `[+-]?0x` hex digits, an optional `.` and hex digits (at most 13 digits in all after the
/// leading one), then `p[+-]?` decimal digits: its exact value when that is a normal `f64`.
fn hex_float(f: &str) -> Option<f64> {
    let (negative, rest) = match f.as_bytes().first()? {
        b'-' => (true, &f[1..]),
        b'+' => (false, &f[1..]),
        _ => (false, f),
    };
    let rest = rest.get(2..)?;
    let (mantissa, exponent) = rest.split_once(['p', 'P'])?;
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int.len() != 1 || frac.len() > 13 {
        return None;
    }
    let mut m: u64 = 0;
    for c in int.bytes().chain(frac.bytes()) {
        m = m * 16 + u64::from((c as char).to_digit(16)?);
    }
    let e = exponent.strip_prefix('+').unwrap_or(exponent);
    if e.is_empty()
        || e.len() > 6
        || !e
            .trim_start_matches('-')
            .bytes()
            .all(|c| c.is_ascii_digit())
    {
        return None;
    }
    let e: i32 = e.parse().ok()?;
    // m < 2^53 is an f64, and so is 2^shift: their product is exact unless it leaves the
    // normal range (refused below)
    let shift = e - 4 * frac.len() as i32;
    if !(-1000..=1000).contains(&shift) || m >= 1 << 53 {
        return None;
    }
    let v = m as f64 * f64::from_bits(((shift + 1023) as u64) << 52);
    let v = if negative { -v } else { v };
    v.is_normal().then_some(v)
}

/// Digits with at most one `.` (at least one digit), then optionally `e` or `E`, a sign and
/// digits.
fn plain_decimal(b: &[u8]) -> bool {
    let (mantissa, exponent) = match b.iter().position(|&c| c == b'e' || c == b'E') {
        Some(i) => (&b[..i], Some(&b[i + 1..])),
        None => (b, None),
    };
    let digits = mantissa.iter().filter(|c| c.is_ascii_digit()).count();
    let dots = mantissa.iter().filter(|&&c| c == b'.').count();
    let mantissa_ok = digits > 0 && dots <= 1 && digits + dots == mantissa.len();
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(b"-").or(e.strip_prefix(b"+")).unwrap_or(e);
        !e.is_empty() && e.len() <= 4 && e.iter().all(u8::is_ascii_digit)
    });
    mantissa_ok && exponent_ok
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast reader gives what the library's reader gives, on the lines targets write
    /// (`%a`, `repr`, `%.17g`) and on lines it must leave to the library.
    #[test]
    fn fast_answer_lines_read_as_the_library_reads_them() {
        let mut lines: Vec<String> = [
            "0x1.8p+0",
            "0x1p-1,0x1.fffffffffffffp+1023",
            "-0x1.5555555555555p-2, 0X1.8P+0",
            " 0x1.0000000000001p+0 ",
            "+0x1.8p+0",
            "1.5,-2.25",
            "0.1,1e-5",
            "5.,.5",
            "1e308,1E-300",
            "3.4028235e38,1e39",
            "0x1.ffffffp-127,0x1.fffffffp+0",
            "0x0p+0,1",
            "-0.0,1",
            "0x1p-1074,1",
            "1e400,1",
            "nan,1",
            "inf,1",
            "1/3,1",
            "\"1.5\",1",
            "[1, 2]",
            "1,2,3",
            "1",
            "",
            "0x1.8p,1",
            "0x.8p+1,1",
            "0x10p+0,1",
            "1e,1",
            "1.2.3,1",
            "f64:0.1,1",
            "0x1.00000000000001p+0,1",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        // f64 and f32 values as hex and decimal, from a fixed generator
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..2000 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let v = f64::from_bits(x >> 2) * if x & 1 == 0 { 1.0 } else { -1.0 };
            let w = f64::from(v as f32);
            lines.push(format!(
                "{},{}",
                crate::number::hex_f64(v),
                crate::number::hex_f32(w as f32)
            ));
            lines.push(format!("{v:?},{w:e}"));
        }
        for precision in [Precision::F64, Precision::F32] {
            for line in &lines {
                let want = parse_claimed_line(line, 2, precision);
                let mut got = vec![7.0];
                if fast_claimed_line(line, precision, &mut got, 2) {
                    let want = want.unwrap_or_else(|e| panic!("{line}: fast read, library: {e}"));
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&got[1..]), bits(&want), "{line} ({precision:?})");
                } else {
                    assert_eq!(got, [7.0], "{line}");
                }
            }
        }
        // the common lines do take the fast path
        let mut got = Vec::new();
        assert!(fast_claimed_line(
            "0x1.8p+0,-0x1.5555555555555p-2",
            Precision::F64,
            &mut got,
            2
        ));
        assert!(fast_claimed_line("0.1", Precision::F32, &mut got, 1));
        assert_eq!(got, [1.5, -1.0 / 3.0, f64::from(0.1f32)]);
    }

    use proptest::prelude::*;

    /// Lines of one to three fields: numbers from random bits as targets print them, or runs of
    /// number-like tokens (signs, `0x`, hex and decimal digits, `.`, `p`, `e`, `nan`, `inf`,
    /// quotes, spaces).
    fn line() -> impl Strategy<Value = String> {
        let token = prop_oneof![
            Just("-".to_string()),
            Just("+".to_string()),
            Just("0x".to_string()),
            Just("0X".to_string()),
            Just(".".to_string()),
            Just("p".to_string()),
            Just("P".to_string()),
            Just("e".to_string()),
            Just("E".to_string()),
            Just("nan".to_string()),
            Just("inf".to_string()),
            Just("\"".to_string()),
            Just(" ".to_string()),
            "[0-9a-fA-F]{1,14}",
            "[0-9]{1,5}",
        ];
        // whole numbers as targets print them (hex floats, shortest and exponent decimals),
        // and pieces of numbers run together
        let number = prop_oneof![
            any::<u64>().prop_map(|b| crate::number::hex_f64(f64::from_bits(b))),
            any::<u32>().prop_map(|b| crate::number::hex_f32(f32::from_bits(b))),
            any::<u64>().prop_map(|b| format!("{:?}", f64::from_bits(b))),
            any::<u32>().prop_map(|b| format!("{:e}", f32::from_bits(b))),
        ];
        let pieces = proptest::collection::vec(token, 1..6).prop_map(|t| t.concat());
        let field = prop_oneof![number, pieces];
        proptest::collection::vec(field, 1..4).prop_map(|f| f.join(","))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// On any such line the fast path either refuses, leaving the buffer as it was, or
        /// gives exactly the library's numbers.
        #[test]
        fn the_fast_path_reads_what_the_library_reads(
            text in line(),
            dim in 1usize..4,
            f32 in any::<bool>(),
        ) {
            let precision = if f32 { Precision::F32 } else { Precision::F64 };
            let want = parse_claimed_line(&text, dim, precision);
            let mut got = vec![7.0];
            if fast_claimed_line(&text, precision, &mut got, dim) {
                let values = want.clone().expect("a line the fast path reads is valid");
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                prop_assert_eq!(bits(&got[1..]), bits(&values));
            } else {
                prop_assert_eq!(got, vec![7.0]);
            }
            let mut out = Vec::new();
            match read_claimed_line(&text, dim, precision, &mut out) {
                Ok(()) => prop_assert_eq!(out.len(), dim),
                Err(e) => {
                    prop_assert!(out.is_empty());
                    prop_assert_eq!(Err(e), want.map(|_| ()));
                }
            }
        }
    }
}
