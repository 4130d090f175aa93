//! The binary floating-point formats tribez certifies, `f64` (binary64) and `f32`
//! (binary32), described once: every conversion of [`crate::number`] is written over
//! [`BinaryFloat`] and reads the fields of a float from its bits.

use std::fmt::{Display, LowerExp};

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
}

/// A binary interchange format: `f64` or `f32` (sealed). A value is
/// `(−1)^s · m · 2^(e − PREC + 1)` with the fields read from its bits
/// (sign, `BITS − PREC` exponent bits with bias `EMAX`, `PREC − 1` fraction bits).
pub trait BinaryFloat:
    Copy + PartialEq + PartialOrd + Display + LowerExp + Send + Sync + sealed::Sealed + 'static
{
    /// Total bits (64, 32).
    const BITS: u32;
    /// Significand bits, hidden bit included (53, 24).
    const PREC: u32;
    /// Largest exponent (1023, 127), also the exponent bias; the smallest normal exponent
    /// is `1 − EMAX`.
    const EMAX: i64;
    /// `"f64"` or `"f32"`.
    const NAME: &'static str;
    /// NaN.
    const NAN: Self;
    /// Zero (positive).
    const ZERO: Self;
    /// `1e-5` and `1e16` in this format: `crate::number::display_float` writes
    /// `LOW ≤ |x| < HIGH` positionally.
    const DISPLAY_LOW: Self;
    /// See [`BinaryFloat::DISPLAY_LOW`].
    const DISPLAY_HIGH: Self;
    /// The bits, widened to `u64`.
    fn to_raw(self) -> u64;
    /// The float with these bits (the low [`BinaryFloat::BITS`] bits of `bits`).
    fn from_raw(bits: u64) -> Self;
    /// `|x|`.
    fn abs(self) -> Self;
}

impl BinaryFloat for f64 {
    const BITS: u32 = 64;
    const PREC: u32 = 53;
    const EMAX: i64 = 1023;
    const NAME: &'static str = "f64";
    const NAN: Self = f64::NAN;
    const ZERO: Self = 0.0;
    const DISPLAY_LOW: Self = 1e-5;
    const DISPLAY_HIGH: Self = 1e16;
    fn to_raw(self) -> u64 {
        self.to_bits()
    }
    fn from_raw(bits: u64) -> Self {
        f64::from_bits(bits)
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
}

impl BinaryFloat for f32 {
    const BITS: u32 = 32;
    const PREC: u32 = 24;
    const EMAX: i64 = 127;
    const NAME: &'static str = "f32";
    const NAN: Self = f32::NAN;
    const ZERO: Self = 0.0;
    const DISPLAY_LOW: Self = 1e-5;
    const DISPLAY_HIGH: Self = 1e16;
    fn to_raw(self) -> u64 {
        u64::from(self.to_bits())
    }
    fn from_raw(bits: u64) -> Self {
        f32::from_bits(bits as u32)
    }
    fn abs(self) -> Self {
        f32::abs(self)
    }
}

/// The fields of a float: sign, biased exponent, fraction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Fields {
    pub neg: bool,
    pub biased: u64,
    pub frac: u64,
}

/// Number of fraction bits, `PREC − 1`.
pub(super) fn frac_bits<F: BinaryFloat>() -> u32 {
    F::PREC - 1
}

/// The all-ones biased exponent (infinities and NaNs).
pub(super) fn exp_ones<F: BinaryFloat>() -> u64 {
    (1 << (F::BITS - F::PREC)) - 1
}

/// The smallest normal exponent, `1 − EMAX`.
pub(super) fn emin<F: BinaryFloat>() -> i64 {
    1 - F::EMAX
}

pub(super) fn fields<F: BinaryFloat>(x: F) -> Fields {
    let bits = x.to_raw();
    Fields {
        neg: bits >> (F::BITS - 1) == 1,
        biased: (bits >> frac_bits::<F>()) & exp_ones::<F>(),
        frac: bits & ((1 << frac_bits::<F>()) - 1),
    }
}

pub(super) fn is_nan<F: BinaryFloat>(x: F) -> bool {
    let f = fields(x);
    f.biased == exp_ones::<F>() && f.frac != 0
}

/// Order-preserving integer key of a float (docs/theory.md §14.4): the bits when the sign
/// is clear, else −(bits without sign); ±0 both map to 0, the infinities are one step beyond
/// `±MAX`.
pub(super) fn key<F: BinaryFloat>(x: F) -> i64 {
    let bits = x.to_raw();
    let magnitude = (bits & !(1 << (F::BITS - 1))) as i64;
    if bits >> (F::BITS - 1) == 0 {
        magnitude
    } else {
        -magnitude
    }
}
