//! The number types the algorithms are generic over.
//!
//! Every algorithm of the core (de Casteljau, blossoms, subdivision, elevation, derivatives) is
//! written once for a [`Scalar`]: a commutative ring with the few operations the algorithms use.
//! It is implemented for the exact types [`BigRational`](num_rational::BigRational) and
//! [`BigInt`](num_bigint::BigInt) (integer homogeneous evaluation) and for the machine floats
//! `f64` and `f32` (the float paths that tribez certifies).
//!
//! Floating-point order of operations is part of the contract: a weighted sum
//! `Σ_k λ_k x_k` is always computed left to right, `((λ_0 x_0 + λ_1 x_1) + λ_2 x_2) + …`, without
//! fused multiply-add, so the error bounds of `certify` describe exactly what runs.

use std::fmt::Debug;
use std::ops::{Add, Mul, Neg, Sub};

use num_traits::{One, Zero};

/// A commutative ring element usable by the generic algorithms.
pub trait Scalar:
    Clone
    + Debug
    + PartialEq
    + Zero
    + One
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + Send
    + Sync
    + 'static
{
    /// `Σ_k weights[k] · values[k]`, left to right, starting from the first product.
    ///
    /// `weights` and `values` have the same non-zero length.
    #[inline]
    fn weighted_sum<'a, I>(mut terms: I) -> Self
    where
        I: Iterator<Item = (&'a Self, &'a Self)>,
        Self: 'a,
    {
        // invariant: every caller sums over a basis of a simplex, which has at least one multi-index
        let (w, x) = terms.next().expect("weighted_sum of no terms");
        let mut acc = w.clone() * x;
        for (w, x) in terms {
            acc = acc + w.clone() * x;
        }
        acc
    }

    /// The scalar `k` (a small non-negative integer).
    fn from_u64(k: u64) -> Self;

    /// The scalar nearest the integer `k` (exact for the exact types, rounded for floats).
    fn from_biguint(k: &num_bigint::BigUint) -> Self;
}

impl Scalar for num_rational::BigRational {
    fn from_u64(k: u64) -> Self {
        Self::from_integer(k.into())
    }
    fn from_biguint(k: &num_bigint::BigUint) -> Self {
        Self::from_integer(num_bigint::BigInt::from(k.clone()))
    }
}

impl Scalar for num_bigint::BigInt {
    fn from_u64(k: u64) -> Self {
        k.into()
    }
    fn from_biguint(k: &num_bigint::BigUint) -> Self {
        k.clone().into()
    }
}

/// `x` as a `&U` when `T` is `U` (a `TypeId` comparison, resolved at compile time): how a
/// generic algorithm hands a specialised kernel its exact rationals, so that the algorithm is
/// written once and has one name. `None` when the types differ.
pub(crate) fn downcast_ref<T: 'static, U: 'static>(x: &T) -> Option<&U> {
    (x as &dyn std::any::Any).downcast_ref::<U>()
}

/// `x` moved into a `U` when `T` is `U` (see [`downcast_ref`]); `None` when the types differ.
pub(crate) fn cast<T: 'static, U: 'static>(x: T) -> Option<U> {
    let mut slot = Some(x);
    (&mut slot as &mut dyn std::any::Any)
        .downcast_mut::<Option<U>>()
        .and_then(Option::take)
}

/// The machine floats: one implementation for both formats, through
/// [`BinaryFloat`](crate::number::BinaryFloat). The weighted sum accumulates with `+=`
/// (plain float addition and multiplication, no fused multiply-add).
macro_rules! float_scalar {
    ($($t:ty),*) => {$(
        impl Scalar for $t {
            #[inline]
            fn weighted_sum<'a, I>(mut terms: I) -> Self
            where
                I: Iterator<Item = (&'a Self, &'a Self)>,
            {
                // invariant: every caller sums over a basis of a simplex, which has at least one multi-index
                let (w, x) = terms.next().expect("weighted_sum of no terms");
                let mut acc = w * x;
                for (w, x) in terms {
                    acc += w * x;
                }
                acc
            }
            fn from_u64(k: u64) -> Self {
                k as $t
            }
            fn from_biguint(k: &num_bigint::BigUint) -> Self {
                crate::number::round_to::<$t>(&num_rational::BigRational::from_integer(k.clone().into()))
            }
        }
    )*};
}

float_scalar!(f64, f32);
