//! The float lookup a GPU runs (docs/theory.md §17): barycentric coordinates computed in floats
//! from the float point, then de Casteljau in floats.
//!
//! With the triangle's vertices `p0, p1, p2` and its ordinates rounded to the float type once
//! (nearest, ties to even), and the point `x` as a float:
//!
//! ```text
//!   d  = (x1 − x0)(y2 − y0) − (y1 − y0)(x2 − x0)
//!   λ1 = ((x − x0)(y2 − y0) − (y − y0)(x2 − x0)) / d
//!   λ2 = ((x1 − x0)(y − y0) − (y1 − y0)(x − x0)) / d
//!   λ0 = (1 − λ1) − λ2
//! ```
//!
//! each operation rounded in order, no fused multiply-add; then de Casteljau's steps
//! `b ← (λ0 b_{α+e0} + λ1 b_{α+e1}) + λ2 b_{α+e2}` (the order of [`crate::scalar::Scalar`]).

use std::ops::Div;

use num_rational::BigRational;

use super::{Mesh, MeshError, casteljau};
use crate::float::Float;

/// One float lookup in one triangle.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatLookup<F> {
    /// The triangle.
    pub triangle: usize,
    /// The barycentric coordinates computed in floats.
    pub barycentric: [F; 3],
    /// The value computed in floats.
    pub value: F,
    /// The exact value of the triangle's polynomial at the float point (the input as seen; the
    /// polynomial continued beyond the triangle if the rounded point left it).
    pub exact_seen: BigRational,
}

impl Mesh {
    /// The float lookup of the point `(x, y)` (floats) in triangle `t` (see the module
    /// documentation of `mesh::float`): errors only for a triangle that does not exist or an
    /// absent ordinate; a non-finite result is returned as computed.
    pub fn float_lookup<F: Float + Div<Output = F>>(
        &self,
        t: usize,
        point: [F; 2],
    ) -> Result<FloatLookup<F>, MeshError> {
        let b = self.triangle_ordinates(t)?;
        let v = self.triangles[t].map(|i| self.vertices[i].clone().map(|c| F::round(&c)));
        let [x, y] = point;
        let d =
            (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]);
        let l1 = ((x - v[0][0]) * (v[2][1] - v[0][1]) - (y - v[0][1]) * (v[2][0] - v[0][0])) / d;
        let l2 = ((v[1][0] - v[0][0]) * (y - v[0][1]) - (v[1][1] - v[0][1]) * (x - v[0][0])) / d;
        let l0 = (F::one() - l1) - l2;
        let lambda = [l0, l1, l2];
        let value = casteljau(self.degree, b.iter().map(F::round).collect(), &lambda);
        let exact_seen = match (point[0].exact(), point[1].exact()) {
            (Some(px), Some(py)) => {
                let tri = self.triangles[t].map(|i| &self.vertices[i]);
                let l = super::barycentric(tri, &[px, py]);
                casteljau(self.degree, b, &l)
            }
            _ => BigRational::default(),
        };
        Ok(FloatLookup {
            triangle: t,
            barycentric: lambda,
            value,
            exact_seen,
        })
    }
}
