//! Numbers in and out: parse the number syntax of patch files, claim files and the command line
//! into exact rationals, print exact values (`p/q`, decimals, ULP counts) and floats (shortest
//! round-trip decimals, C99 hex floats), round a rational correctly to `f64`/`f32`, take the
//! exact value of a float, and measure an error in ULPs (docs/theory.md §14.3, §14.4).
//!
//! A curated list of the functions the command line and the Python package use; everything
//! here is exact (no floating-point operation computes a value).
//!
//! ```
//! use tribez::format::*;
//! // f64:0.1 is the float nearest 1/10, exactly 3602879701896397 / 2^55
//! let x = parse_rational("f64:0.1").unwrap();
//! assert_eq!(format_rational(&x), "3602879701896397/36028797018963968");
//! assert_eq!(exact_f64(0.1), Some(x.clone()));
//! assert_eq!(round_f64(&parse_rational("1/10").unwrap()), 0.1);
//! assert_eq!(hex_f64(0.1), "0x1.999999999999ap-4");
//! // fl(0.1) − 1/10 = (36028797018963970 − 36028797018963968) / (10 · 2^55) = 2^-55 / 5, and
//! // the ULP of f64 at 1/10 ∈ [2^-4, 2^-3) is 2^-56: the error is 2/5 ULP
//! let e = ulps_error_f64(&x, &parse_rational("1/10").unwrap());
//! assert_eq!(format_rational(&e), "2/5");
//! assert_eq!(ulps_decimal(&e), "0.4");
//! assert_eq!(to_decimal_string(&parse_rational("2/3").unwrap(), 5), "0.66667");
//! assert_eq!(format_tuple(&[parse_rational("1/2").unwrap(), parse_rational("-3").unwrap()]), "(1/2, -3)");
//! ```

pub use crate::number::{
    BinaryFloat, MAX_DIGITS, MAX_EXPONENT, NumberError, display_f32, display_f64, exact_f32,
    exact_f64, format_points, format_rational, format_tuple, hex_f32, hex_f64, parse_rational,
    push_rational, round_f32, round_f64, to_decimal_string, ulps_decimal, ulps_error_f32,
    ulps_error_f64,
};
