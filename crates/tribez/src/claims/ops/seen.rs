//! The inputs as the float code saw them: numbers, points, domains and patches rounded to a
//! precision (each number to the float nearest it, [`crate::certify::measures::as_float`]).
//! Errors name the input that overflows the precision, or that rounding makes invalid.

use num_rational::BigRational;

use super::inputs::{Inputs, Point};
use crate::any_patch::AnyPatch;
use crate::capability::InputSpace;
use crate::domain::Domain;
use crate::error::CoreError;
use crate::float::Precision;
use crate::io::{ClaimProblem, InputError, Problem};
use crate::patch::BezierPatch;
use crate::rational::RationalPatch;
use crate::spatch::SPatch;

type Q = BigRational;

/// Who an error about a rounded patch is blamed on: a claim's input (its file, line and key), or
/// a whole file (a batch's patch).
pub trait Blame {
    /// The error of input `name`.
    fn blame(&self, name: &str, problem: Problem) -> InputError;
}

impl Blame for Inputs<'_> {
    fn blame(&self, name: &str, problem: Problem) -> InputError {
        self.error(name, problem)
    }
}

/// Errors blamed on a whole file (its name).
pub struct FileBlame<'a>(pub &'a str);

impl Blame for FileBlame<'_> {
    fn blame(&self, _name: &str, problem: Problem) -> InputError {
        InputError::file(self.0, problem)
    }
}

fn round(q: &Q, p: Precision) -> Option<Q> {
    crate::certify::measures::as_float(q, p)
}

/// `what` overflows precision `p`.
fn overflows(what: &'static str, precision: Precision) -> Problem {
    Problem::Overflows { what, precision }
}

/// Rounded to `p`, `what` violates a precondition.
fn rounded(what: Option<&'static str>, precision: Precision, error: CoreError) -> ClaimProblem {
    ClaimProblem::Rounded {
        what,
        precision,
        error,
    }
}

/// Numbers of input `name` rounded to `p`.
pub fn numbers(
    inputs: &Inputs<'_>,
    name: &str,
    xs: &[Q],
    p: Precision,
) -> Result<Vec<Q>, InputError> {
    xs.iter()
        .map(|q| round(q, p))
        .collect::<Option<_>>()
        .ok_or_else(|| inputs.error(name, overflows("an input", p)))
}

/// Rows of numbers of input `name` rounded to `p`.
pub fn rows(
    inputs: &Inputs<'_>,
    name: &str,
    xs: &[Vec<Q>],
    p: Precision,
) -> Result<Vec<Vec<Q>>, InputError> {
    xs.iter().map(|x| numbers(inputs, name, x, p)).collect()
}

/// A point as seen: the barycentric `at` rounded, or the Cartesian point rounded and then
/// converted exactly with `domain` (the patch's; `None` for an S-patch, whose points stay
/// Cartesian).
pub fn point(
    inputs: &Inputs<'_>,
    point: &Point,
    domain: Option<&Domain>,
    p: Precision,
) -> Result<Point, InputError> {
    match (&point.cartesian, domain) {
        (Some(x), Some(domain)) => {
            let xr = numbers(inputs, "cartesian", x, p)?;
            Ok(Point {
                at: domain
                    .barycentric(&xr)
                    .map_err(|e| inputs.error("cartesian", e))?,
                cartesian: Some(xr),
            })
        }
        (Some(x), None) => Ok(Point {
            at: Vec::new(),
            cartesian: Some(numbers(inputs, "cartesian", x, p)?),
        }),
        (None, _) => Ok(Point {
            at: numbers(inputs, "at", &point.at, p)?,
            cartesian: None,
        }),
    }
}

/// A point of `patch` as seen: `at` rounded, or the Cartesian point rounded and then (for a
/// patch over a simplex) converted exactly to barycentric coordinates
/// ([`crate::ExactEval::cartesian_input`]).
pub fn input(
    inputs: &Inputs<'_>,
    point: &Point,
    patch: &crate::patch_type::Patch,
    p: Precision,
) -> Result<Point, InputError> {
    match &point.cartesian {
        Some(x) => {
            let xr = numbers(inputs, "cartesian", x, p)?;
            let at = match patch.shape().input {
                InputSpace::Barycentric { .. } => patch
                    .exact()
                    .cartesian_input(&xr)
                    .map_err(|e| inputs.error("cartesian", e))?,
                InputSpace::Polygon { .. } => Vec::new(),
            };
            Ok(Point {
                at,
                cartesian: Some(xr),
            })
        }
        None => Ok(Point {
            at: numbers(inputs, "at", &point.at, p)?,
            cartesian: None,
        }),
    }
}

/// A simplex given as an op input, its vertices rounded.
pub fn domain(
    inputs: &Inputs<'_>,
    name: &str,
    d: &Domain,
    p: Precision,
) -> Result<Domain, InputError> {
    let vs = rows(inputs, name, d.vertices(), p)?;
    Domain::new(vs).map_err(|e| inputs.error(name, rounded(None, p, e)))
}

/// A polynomial patch with its control points rounded (its domain stays exact).
pub fn patch(
    inputs: &dyn Blame,
    patch: &BezierPatch,
    p: Precision,
) -> Result<BezierPatch, InputError> {
    if patch.net.coords().iter().any(|q| round(q, p).is_none()) {
        return Err(inputs.blame("patch", overflows("a control point", p)));
    }
    Ok(BezierPatch {
        net: patch.net.map(|q| round(q, p).unwrap_or_default()),
        ..patch.clone()
    })
}

/// A rational patch as seen: its homogeneous net `(w c, w)` rounded.
pub fn rational(
    inputs: &dyn Blame,
    r: &RationalPatch,
    p: Precision,
) -> Result<RationalPatch, InputError> {
    let hr = r.homogeneous().map(|q| round(q, p));
    if hr.coords().iter().any(Option::is_none) {
        return Err(inputs.blame("patch", overflows("a weighted control point", p)));
    }
    let hr = hr.map(|q| q.clone().unwrap_or_default());
    RationalPatch::from_homogeneous(&hr, &r.patch)
        .map_err(|e| inputs.blame("patch", rounded(None, p, e).into()))
}

/// An S-patch as seen: its polygon and control points rounded.
pub fn spatch(inputs: &dyn Blame, s: &SPatch, p: Precision) -> Result<SPatch, InputError> {
    let mut verts = Vec::new();
    for v in s.polygon.vertices() {
        verts.push(
            v.iter()
                .map(|q| round(q, p))
                .collect::<Option<Vec<_>>>()
                .ok_or_else(|| inputs.blame("patch", overflows("a number", p)))?,
        );
    }
    let polygon = crate::spatch::Polygon::new(verts)
        .map_err(|e| inputs.blame("patch", rounded(Some("the polygon"), p, e).into()))?;
    let net = s.net.map(|q| round(q, p));
    if net.coords().iter().any(Option::is_none) {
        return Err(inputs.blame("patch", overflows("a control point", p)));
    }
    let mut out = SPatch::new(polygon, net.map(|q| q.clone().unwrap_or_default()))
        .map_err(|e| inputs.blame("patch", e.into()))?;
    out.name = s.name.clone();
    Ok(out)
}

/// A patch of any kind as seen.
pub fn any_patch(inputs: &dyn Blame, any: &AnyPatch, p: Precision) -> Result<AnyPatch, InputError> {
    Ok(match any {
        AnyPatch::Bezier(x) => AnyPatch::Bezier(patch(inputs, x, p)?),
        AnyPatch::Functional(x) => AnyPatch::Functional(patch(inputs, x, p)?),
        AnyPatch::Rational(r) => AnyPatch::Rational(rational(inputs, r, p)?),
        AnyPatch::SPatch(s) => AnyPatch::SPatch(spatch(inputs, s, p)?),
    })
}
