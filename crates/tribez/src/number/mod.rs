//! Exact numbers: parsing and printing of rationals, exact values of `f64`/`f32`,
//! correctly rounded rational → float conversions, ULPs and step distances.
//!
//! Everything here is exact: no floating-point operation is used to compute a
//! value (the only float arithmetic is a first guess of a decimal exponent in
//! [`to_decimal_string`], which is then corrected exactly). See docs/theory.md §14.3
//! (exact value of an f64) and §14.4 (ULPs, round-to-nearest with integers only).
//!
//! One concept per file: `parse` (number text → exact value, with its limits), `print`
//! (exact value or float → text), `format` (the binary formats `f64` and `f32` as one
//! [`BinaryFloat`] trait, their fields and the order-preserving key), `exact` (the exact
//! value of a float), `round` (correct rounding of a rational to a format, integers only),
//! `ulp` (ULPs and step distances). Every float operation is written once, generic over
//! [`BinaryFloat`] (`round_to::<f32>` rounds once from the exact value, never through
//! `f64`); the `_f64` / `_f32` names are that generic code at each format.
//!
//! ```
//! use tribez::hazmat::number::*;
//! let q = parse_rational("f64:0.1").unwrap();
//! assert_eq!(format_rational(&q), "3602879701896397/36028797018963968");
//! assert_eq!(round_f64(&parse_rational("1/10").unwrap()), 0.1);
//! assert_eq!(round_to::<f32>(&parse_rational("1/10").unwrap()), 0.1f32);
//! ```

mod arith;
mod exact;
mod format;
mod parse;
mod print;
mod round;
mod ulp;

pub use num_bigint::BigInt;
pub use num_rational::BigRational;

pub use arith::gcd;
pub(crate) use arith::{
    add as q_add, div as q_div, gcd_u64, mul as q_mul, pow as q_pow, ratio, sub as q_sub,
};
pub use exact::{exact_f32, exact_f64, exact_value, pow2};
pub use format::BinaryFloat;
pub use parse::{
    MAX_DIGITS, MAX_EXPONENT, NumberError, OutOfRange, out_of_float_range, parse_number_text,
    parse_rational,
};
pub use print::{
    display_f32, display_f64, display_float, format_points, format_rational, format_tuple, hex_f32,
    hex_f64, hex_float, push_decimal, push_rational, to_decimal_string, ulps_decimal,
};
pub use round::{
    is_faithful, is_faithful_f32, is_faithful_f64, round_f32, round_f64, round_to, round_up_f64,
};
pub(crate) use ulp::ulps_error_up;
pub use ulp::{
    floor_log2, steps, steps_f32, steps_f64, ulp, ulp_f32, ulp_f64, ulps_error, ulps_error_f32,
    ulps_error_f64,
};

/// The exact number type of the crate.
pub type Rational = BigRational;

#[cfg(test)]
mod tests;
