//! Real algebraic numbers and the inverse problems they answer exactly (docs/theory.md §16).
//!
//! * [`IntPoly`]: univariate integer polynomials (primitive part, gcd, square-free part and
//!   factorisation, exact sign at a rational);
//! * root isolation in the Bernstein basis (Descartes' rule of signs on the Bernstein
//!   coefficients, de Casteljau subdivision at midpoints, integer arithmetic);
//! * [`RealAlgebraic`]: a rational, or the only root of a square-free primitive integer
//!   polynomial in a rational interval — exact comparison, sign of a polynomial at it,
//!   refinement, correctly rounded `f64`/`f32`, JSON;
//! * [`BiPoly`]: bivariate polynomials with rational coefficients, their resultant and first
//!   subresultant by evaluation and interpolation;
//! * [`intersect_curves`]: every intersection of two planar Bézier curves (polynomial or
//!   rational), with tangency, multiplicity and overlaps.
//!
//! Every size the input controls is capped ([`MAX_DEGREE`], [`MAX_BITS`],
//! [`MAX_CURVE_DEGREE`], [`MAX_PATCH_DEGREE`]) with a typed error ([`AlgebraicError`]).

mod bivariate;
mod clip;
mod curves;
mod interval;
mod isolate;
mod poly;
mod real;
mod surfaces;
mod system;

pub use crate::error::AlgebraicError;
pub use bivariate::{
    BiPoly, div_exact as bivariate_div_exact, gcd as bivariate_gcd, resultant, subresultant1,
};
pub use clip::{Clipped, bipoly_text, solve_clipped};
pub use curves::{
    Curve, CurveIntersections, Intersection, MAX_INTERSECT_WORK, Overlap, intersect_curves,
    point_text, work_estimate,
};
pub use isolate::{Cell, isolate};
pub use poly::IntPoly;
pub use real::{RealAlgebraic, Root, poly_text, simplest_between};
pub use surfaces::{
    Degenerate, Hit, Located, Locations, RayHits, check_locate_patch, check_ray_patch, locate,
    ray_hits,
};
pub use system::{Expr, Half, Partner, Region, Solution, Solved, solve};

/// The largest degree of a univariate polynomial whose roots are isolated.
pub const MAX_DEGREE: usize = 2_000;
/// The largest bit length of a coefficient of such a polynomial.
pub const MAX_BITS: u64 = 1 << 20;
/// The largest degree of a curve given to [`intersect_curves`].
pub const MAX_CURVE_DEGREE: usize = 12;
/// The largest degree of a patch given to `locate` and `ray`.
pub const MAX_PATCH_DEGREE: usize = 6;
/// The largest bit length of a numerator or denominator of a control point, weight or query
/// coordinate given to the inverse problems.
pub const MAX_INPUT_BITS: u64 = 4096;

/// Check a polynomial against [`MAX_DEGREE`] and [`MAX_BITS`].
pub(crate) fn check_poly(p: &IntPoly) -> Result<(), AlgebraicError> {
    let degree = p.degree().unwrap_or(0);
    if degree > MAX_DEGREE {
        return Err(AlgebraicError::DegreeTooHigh {
            what: "a polynomial",
            degree,
            max: MAX_DEGREE,
        });
    }
    let bits = p.max_bits();
    if bits > MAX_BITS {
        return Err(AlgebraicError::CoefficientTooLarge {
            what: "a polynomial",
            bits,
            max: MAX_BITS,
        });
    }
    Ok(())
}

/// Check a rational input number against [`MAX_INPUT_BITS`].
pub(crate) fn check_input(
    what: &'static str,
    x: &num_rational::BigRational,
) -> Result<(), AlgebraicError> {
    let bits = x.numer().bits().max(x.denom().bits());
    if bits > MAX_INPUT_BITS {
        return Err(AlgebraicError::CoefficientTooLarge {
            what,
            bits,
            max: MAX_INPUT_BITS,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests;

/// JSON of the inverse problems' results (`tribez intersect`, `locate`, `ray --format json`):
/// the exact numbers as [`RealAlgebraic::to_json`] and [`Expr::to_json`] give them.
mod json {
    use serde::ser::{Serialize, SerializeMap, Serializer};

    use super::{Expr, Intersection, Located, Overlap, RealAlgebraic, point_text};

    impl Serialize for RealAlgebraic {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            self.to_json().serialize(s)
        }
    }

    impl Serialize for Expr {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            self.to_json().serialize(s)
        }
    }

    /// `{s, t, point, tangential, multiplicity}`.
    impl Serialize for Intersection {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let mut m = s.serialize_map(Some(5))?;
            m.serialize_entry("s", &self.s)?;
            m.serialize_entry("t", &self.t)?;
            m.serialize_entry("point", &point_text(&self.point))?;
            m.serialize_entry("tangential", &self.tangential)?;
            m.serialize_entry("multiplicity", &self.multiplicity)?;
            m.end()
        }
    }

    /// `{s: [from, to], t: [at s from, at s to], t_increasing}`.
    impl Serialize for Overlap {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let mut m = s.serialize_map(Some(3))?;
            m.serialize_entry("s", &self.s)?;
            m.serialize_entry("t", &self.t)?;
            m.serialize_entry(
                "t_increasing",
                &(self.t[0].cmp_exact(&self.t[1]) == std::cmp::Ordering::Less),
            )?;
            m.end()
        }
    }

    /// `{s, t, lambda0, jacobian_zero, multiplicity}`.
    impl Serialize for Located {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let mut m = s.serialize_map(Some(5))?;
            m.serialize_entry("s", &self.s)?;
            m.serialize_entry("t", &self.t)?;
            m.serialize_entry("lambda0", &self.lambda0)?;
            m.serialize_entry("jacobian_zero", &self.jacobian_zero)?;
            m.serialize_entry("multiplicity", &self.multiplicity)?;
            m.end()
        }
    }
}
