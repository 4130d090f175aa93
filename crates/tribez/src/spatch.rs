//! S-patches (Loop and DeRose) over convex polygons, with Wachspress coordinates
//! (docs/theory.md §12).
//!
//! **Domain.** A strictly convex polygon `p_1 … p_N` (`N ≥ 3`) with rational vertices, listed
//! counter-clockwise. A clockwise list is rejected (it is not silently reversed, because the
//! control points are keyed by vertex order); so are collinear or repeated vertices, non-convex
//! and self-intersecting polygons.
//!
//! **Wachspress coordinates** (product form, polynomial, valid on the closed polygon): with
//! `A_j(p) = signedArea(p, p_j, p_{j+1})` and `C_i = signedArea(p_{i−1}, p_i, p_{i+1})`
//! (indices mod `N`),
//!
//! `ω_i(p) = C_i · Π_{j ∉ {i−1, i}} A_j(p)`,   `λ_i(p) = ω_i(p) / Σ_l ω_l(p)`.
//!
//! **S-patch of depth `d`.** Control points `P_α`, `α ∈ ℕ^N`, `|α| = d`: a Bézier simplex of
//! dimension `N − 1` composed with `λ`: `S(p) = Σ_α P_α B^d_α(λ(p))`, evaluated by the
//! `(N−1)`-simplex de Casteljau at `λ(p)`. Everything stays rational.
//!
//! ```
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::spatch::Polygon;
//! // docs/theory.md §12: the pentagon (0,0), (4,0), (5,3), (2,5), (−1,3) at p = (2,2)
//! let v: Vec<Vec<_>> = [["0","0"],["4","0"],["5","3"],["2","5"],["-1","3"]].iter().map(|p| p.iter().map(|x| q(x).unwrap()).collect()).collect();
//! let poly = Polygon::new(v).unwrap();
//! let l: Vec<String> = poly.wachspress(&[q("2").unwrap(), q("2").unwrap()]).unwrap().iter().map(|x| x.to_string()).collect();
//! assert_eq!(l, ["81/358", "81/358", "33/179", "32/179", "33/179"]);
//! ```

use std::ops::Div;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::casteljau;
use crate::error::CoreError;
use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Float;
use crate::patch::ControlNet;
use crate::scalar::Scalar;
use crate::symbolic::{Polynomial, barycentric_form};

/// A strictly convex polygon with rational vertices in counter-clockwise order.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    vertices: Vec<[BigRational; 2]>,
}

/// `(b − a) × (c − a)`: twice the signed area of the triangle `a b c`.
pub fn cross<T: Scalar>(a: &[T; 2], b: &[T; 2], c: &[T; 2]) -> T {
    (b[0].clone() - &a[0]) * (c[1].clone() - &a[1])
        - (b[1].clone() - &a[1]) * (c[0].clone() - &a[0])
}

/// The doubled Wachspress weights `2^{N−1} ω_i(p)` (the factor cancels in `λ`), ring operations
/// only, so the same code runs exactly and in floats.
pub fn doubled_omega<T: Scalar>(vertices: &[[T; 2]], p: &[T; 2]) -> Vec<T> {
    let n = vertices.len();
    let a: Vec<T> = (0..n)
        .map(|j| cross(p, &vertices[j], &vertices[(j + 1) % n]))
        .collect();
    (0..n)
        .map(|i| {
            let prev = (i + n - 1) % n;
            let c = cross(&vertices[prev], &vertices[i], &vertices[(i + 1) % n]);
            (0..n)
                .filter(|&j| j != prev && j != i)
                .fold(c, |acc, j| acc * &a[j])
        })
        .collect()
}

impl Polygon {
    /// Check and store the polygon: at least 3 vertices in `ℚ²`, strictly convex,
    /// counter-clockwise (every vertex strictly left of every edge it is not on).
    pub fn new(vertices: Vec<Vec<BigRational>>) -> Result<Self, CoreError> {
        let n = vertices.len();
        if n < 3 {
            return Err(CoreError::PolygonTooSmall { found: n });
        }
        let mut vs = Vec::with_capacity(n);
        for (i, v) in vertices.into_iter().enumerate() {
            let [x, y]: [BigRational; 2] =
                v.try_into()
                    .map_err(|v: Vec<BigRational>| CoreError::WrongLength {
                        what: format!("polygon vertex {}", i + 1),
                        expected: 2,
                        found: v.len(),
                    })?;
            vs.push([x, y]);
        }
        let mut left = true;
        let mut right = true;
        let mut witness = None;
        for i in 0..n {
            let (a, b) = (&vs[i], &vs[(i + 1) % n]);
            for (k, c) in vs.iter().enumerate() {
                if k == i || k == (i + 1) % n {
                    continue;
                }
                let s = cross(a, b, c);
                if !s.is_positive() {
                    left = false;
                    witness.get_or_insert((k, i, s.is_zero()));
                }
                if !s.is_negative() {
                    right = false;
                }
            }
        }
        if left {
            return Ok(Polygon { vertices: vs });
        }
        if right {
            return Err(CoreError::Clockwise);
        }
        // invariant: neither `left` (every vertex strictly left) nor `right` held, so the loop recorded a witness
        let (k, i, on) = witness.expect("some vertex is not strictly left");
        Err(CoreError::NotConvex {
            vertex: k + 1,
            point: vs[k].to_vec(),
            on,
            edge: i + 1,
            vertices: n,
        })
    }

    /// Number of vertices `N`.
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Never true.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The vertices.
    pub fn vertices(&self) -> &[[BigRational; 2]] {
        &self.vertices
    }

    /// `A_j(p) = signedArea(p, p_j, p_{j+1})`, `j = 1..N`.
    pub fn areas(&self, p: &[BigRational; 2]) -> Vec<BigRational> {
        let n = self.len();
        let half = BigRational::new(1.into(), 2.into());
        (0..n)
            .map(|j| cross(p, &self.vertices[j], &self.vertices[(j + 1) % n]) * &half)
            .collect()
    }

    /// `C_i = signedArea(p_{i−1}, p_i, p_{i+1})`, `i = 1..N`.
    pub fn corner_areas(&self) -> Vec<BigRational> {
        let n = self.len();
        let half = BigRational::new(1.into(), 2.into());
        (0..n)
            .map(|i| {
                cross(
                    &self.vertices[(i + n - 1) % n],
                    &self.vertices[i],
                    &self.vertices[(i + 1) % n],
                ) * &half
            })
            .collect()
    }

    /// The point as a pair, checked to lie in the closed polygon.
    fn inside(&self, p: &[BigRational]) -> Result<[BigRational; 2], CoreError> {
        let [x, y]: [BigRational; 2] =
            p.to_vec()
                .try_into()
                .map_err(|v: Vec<BigRational>| CoreError::WrongLength {
                    what: "point".into(),
                    expected: 2,
                    found: v.len(),
                })?;
        let q = [x, y];
        if let Some(j) = self.areas(&q).iter().position(Signed::is_negative) {
            return Err(CoreError::OutsidePolygon {
                point: p.to_vec(),
                edge: j + 1,
                vertices: self.len(),
            });
        }
        Ok(q)
    }

    /// Wachspress coordinates `λ(p)` of a point of the closed polygon, exactly.
    pub fn wachspress(&self, p: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        let q = self.inside(p)?;
        Ok(normalise(doubled_omega(&self.vertices, &q)))
    }

    /// `ω_i` (product form, with the true areas) as polynomials in `x, y`.
    pub fn omega_polynomials(&self) -> Vec<Polynomial> {
        let n = self.len();
        let x = Polynomial::variable(2, 0);
        let y = Polynomial::variable(2, 1);
        let half = BigRational::new(1.into(), 2.into());
        let a: Vec<Polynomial> = (0..n)
            .map(|j| {
                let (pj, pk) = (&self.vertices[j], &self.vertices[(j + 1) % n]);
                let c = |v: &BigRational| Polynomial::constant(2, v.clone());
                let (ax, ay) = (c(&pj[0]).sub(&x), c(&pj[1]).sub(&y));
                let (bx, by) = (c(&pk[0]).sub(&x), c(&pk[1]).sub(&y));
                ax.mul(&by).sub(&ay.mul(&bx)).scale(&half)
            })
            .collect();
        let cs = self.corner_areas();
        (0..n)
            .map(|i| {
                let prev = (i + n - 1) % n;
                (0..n)
                    .filter(|&j| j != prev && j != i)
                    .fold(Polynomial::constant(2, cs[i].clone()), |acc, j| {
                        acc.mul(&a[j])
                    })
            })
            .collect()
    }
}

fn normalise<T: Scalar + Div<Output = T>>(omega: Vec<T>) -> Vec<T> {
    let sum = omega
        .iter()
        .skip(1)
        .fold(omega[0].clone(), |acc, w| acc + w);
    omega.into_iter().map(|w| w / sum.clone()).collect()
}

/// The float Wachspress coordinates of `SPatch::evaluate_float`: the doubled product form
/// `doubled_omega` in `F`, then one division by their sum each.
pub fn wachspress_float<F: Float + Div<Output = F>>(vertices: &[[F; 2]], p: &[F; 2]) -> Vec<F> {
    normalise(doubled_omega(vertices, p))
}

/// An S-patch: a convex polygon and a Bézier simplex of dimension `N − 1` (depth = degree).
#[derive(Clone, Debug, PartialEq)]
pub struct SPatch {
    /// Free-form name.
    pub name: Option<String>,
    /// The domain polygon.
    pub polygon: Polygon,
    /// Control points `P_α`, `|α| = d`, `α ∈ ℕ^N`.
    pub net: ControlNet<BigRational>,
}

impl SPatch {
    /// An S-patch; the net's simplex dimension must be `N − 1`.
    pub fn new(polygon: Polygon, net: ControlNet<BigRational>) -> Result<Self, CoreError> {
        if net.m() + 1 != polygon.len() {
            return Err(CoreError::IndexParts {
                vertices: polygon.len(),
                parts: net.m() + 1,
            });
        }
        Ok(SPatch {
            name: None,
            polygon,
            net,
        })
    }

    /// `S(p)` exactly at a Cartesian point of the closed polygon, with `λ(p)`.
    pub fn evaluate(
        &self,
        p: &[BigRational],
    ) -> Result<(Vec<BigRational>, Vec<BigRational>), CoreError> {
        let lambda = self.polygon.wachspress(p)?;
        let value = ExactEvaluator::new(&self.net).evaluate(&lambda, Algorithm::Casteljau);
        Ok((lambda, value))
    }

    /// The float path: vertices, point and control points rounded to `F`; `λ` by the doubled
    /// product form and one division each; then de Casteljau in `F`.
    pub fn evaluate_float<F: Float + Div<Output = F>>(&self, p: &[F; 2]) -> Vec<F> {
        let verts: Vec<[F; 2]> = self
            .polygon
            .vertices
            .iter()
            .map(|v| [F::round(&v[0]), F::round(&v[1])])
            .collect();
        let lambda = wachspress_float(&verts, p);
        casteljau::evaluate(&self.net.map(F::round), &lambda)
    }

    /// The S-patch as a rational map in `x, y`: numerators `Σ_α P_α C(d;α) Π ω_i^{α_i}` (one per
    /// coordinate) and the common denominator `(Σ ω)^d`.
    pub fn rational_form(&self) -> (Vec<Polynomial>, Polynomial) {
        let omega = self.polygon.omega_polynomials();
        let nums = barycentric_form(&self.net)
            .iter()
            .map(|p| p.compose(&omega))
            .collect();
        let sum = omega.iter().fold(Polynomial::zero(2), |acc, w| acc.add(w));
        (nums, sum.pow(self.net.degree() as u32))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational as q;
    use crate::simplex::Simplex;
    use num_traits::One;
    use proptest::prelude::*;

    fn r(xs: &[&str]) -> Vec<BigRational> {
        xs.iter().map(|x| q(x).unwrap()).collect()
    }

    fn pentagon() -> Polygon {
        Polygon::new(
            [["0", "0"], ["4", "0"], ["5", "3"], ["2", "5"], ["-1", "3"]]
                .iter()
                .map(|p| r(p))
                .collect(),
        )
        .unwrap()
    }

    fn net(m: usize, d: usize, seed: i64) -> ControlNet<BigRational> {
        let s = Simplex::new(m, d);
        let coords = (0..s.len() * 3)
            .map(|i| {
                BigRational::new(
                    ((i as i64 * 37 + seed) % 23 - 11).into(),
                    ((i as i64 + seed) % 5 + 1).into(),
                )
            })
            .collect();
        ControlNet::new(s, 3, coords)
    }

    #[test]
    fn pentagon_numbers_theory_section_12() {
        let p = pentagon();
        let at = [q("2").unwrap(), q("2").unwrap()];
        assert_eq!(p.areas(&at), r(&["4", "4", "9/2", "9/2", "4"]));
        assert_eq!(p.corner_areas(), r(&["6", "6", "11/2", "6", "11/2"]));
        let l = p.wachspress(&at).unwrap();
        assert_eq!(l, r(&["81/358", "81/358", "33/179", "32/179", "33/179"]));
    }

    #[test]
    fn bad_polygons() {
        let poly = |v: &[[&str; 2]]| {
            Polygon::new(v.iter().map(|p| r(p)).collect())
                .unwrap_err()
                .to_string()
        };
        let cw = poly(&[["0", "0"], ["0", "1"], ["1", "0"]]);
        assert!(cw.contains("clockwise"), "{cw}");
        let nonconvex = poly(&[["0", "0"], ["4", "0"], ["1", "1"], ["0", "4"]]);
        assert!(nonconvex.contains("not strictly convex"), "{nonconvex}");
        // a pentagram: the pentagon's vertices in the order 1, 3, 5, 2, 4
        let star = poly(&[["0", "0"], ["5", "3"], ["-1", "3"], ["4", "0"], ["2", "5"]]);
        assert!(star.contains("self-intersecting"), "{star}");
        let collinear = poly(&[["0", "0"], ["1", "0"], ["2", "0"], ["0", "1"]]);
        assert!(collinear.contains("on the line"), "{collinear}");
        assert!(poly(&[["0", "0"], ["1", "0"]]).contains("at least 3"));
    }

    #[test]
    fn outside_points_are_rejected() {
        let e = pentagon()
            .wachspress(&r(&["10", "0"]))
            .unwrap_err()
            .to_string();
        assert!(e.contains("outside the polygon"), "{e}");
        // vertices and edges are fine
        assert_eq!(
            pentagon().wachspress(&r(&["4", "0"])).unwrap(),
            r(&["0", "1", "0", "0", "0"])
        );
        assert_eq!(
            pentagon().wachspress(&r(&["2", "0"])).unwrap(),
            r(&["1/2", "1/2", "0", "0", "0"])
        );
    }

    #[test]
    fn partition_of_unity_and_linear_precision_symbolically() {
        // Σ ω_i p_i − (Σ ω) p ≡ 0 and λ sums to one (Σλ = Σω/Σω) — as polynomial identities.
        let p = pentagon();
        let omega = p.omega_polynomials();
        let sum = omega.iter().fold(Polynomial::zero(2), |a, w| a.add(w));
        for c in 0..2 {
            let lhs = omega
                .iter()
                .zip(p.vertices())
                .fold(Polynomial::zero(2), |a, (w, v)| a.add(&w.scale(&v[c])));
            let rhs = sum.mul(&Polynomial::variable(2, c));
            assert!(lhs.sub(&rhs).is_zero());
        }
        // Σω has degree N − 3 = 2, each ω_i degree N − 2 = 3
        assert_eq!(sum.degree(), Some(2));
        assert!(omega.iter().all(|w| w.degree() == Some(3)));
    }

    #[test]
    fn triangle_s_patch_is_the_bezier_triangle() {
        let tri = r(&["1", "1", "5", "2", "2", "6"]);
        let verts: Vec<Vec<BigRational>> = tri.chunks(2).map(<[BigRational]>::to_vec).collect();
        let poly = Polygon::new(verts.clone()).unwrap();
        let s = SPatch::new(poly, net(2, 3, 4)).unwrap();
        let dom = crate::domain::Domain::new(verts).unwrap();
        for pt in [["8/3", "3"], ["7/3", "4/3"], ["2", "3"], ["5", "2"]] {
            let p = r(&pt);
            let (l, v) = s.evaluate(&p).unwrap();
            assert_eq!(l, dom.barycentric(&p).unwrap());
            assert_eq!(v, casteljau::evaluate(&s.net, &l));
        }
    }

    #[test]
    fn plane_reproduction_and_rational_form() {
        // control points Σ (α_k/d) p_k (and a third coordinate 0) reproduce the point itself
        let p = pentagon();
        let d = 2;
        let s = Simplex::new(4, d);
        let mut coords = Vec::new();
        for alpha in s.iter() {
            for c in 0..2 {
                let v: BigRational = alpha
                    .iter()
                    .zip(p.vertices())
                    .map(|(&a, v)| BigRational::from_integer(a.into()) * &v[c])
                    .sum();
                coords.push(v / BigRational::from_integer(d.into()));
            }
            coords.push(BigRational::zero());
        }
        let sp = SPatch::new(p, ControlNet::new(s, 3, coords)).unwrap();
        let (_, v) = sp.evaluate(&r(&["2", "2"])).unwrap();
        assert_eq!(v, r(&["2", "2", "0"]));
        let (nums, den) = sp.rational_form();
        let xy = [q("3").unwrap(), q("5/2").unwrap()];
        let at = sp.evaluate(&xy).unwrap().1;
        for (n, want) in nums.iter().zip(&at) {
            assert_eq!(n.evaluate(&xy) / den.evaluate(&xy), *want);
        }
        assert_eq!(at, r(&["3", "5/2", "0"]));
    }

    #[test]
    fn float_path_is_close() {
        let sp = SPatch::new(pentagon(), net(4, 2, 1)).unwrap();
        let (_, exact) = sp.evaluate(&r(&["2", "2"])).unwrap();
        let f = sp.evaluate_float::<f64>(&[2.0, 2.0]);
        for (a, b) in f.iter().zip(&exact) {
            assert!((a - crate::number::round_f64(b)).abs() < 1e-12, "{a} {b}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(40))]
        #[test]
        fn coordinates_partition_unity_reproduce_points_and_edges_are_bezier_curves(
            a in 0i64..20, b in 0i64..20, c in 1i64..20, e in 0usize..5, t in 0i64..=16,
        ) {
            let p = pentagon();
            // an interior point as a convex combination of three vertices
            let s = a + b + c;
            let v = p.vertices();
            let pt: Vec<BigRational> = (0..2).map(|k| (BigRational::from_integer(a.into()) * &v[0][k] + BigRational::from_integer(b.into()) * &v[2][k] + BigRational::from_integer(c.into()) * &v[3][k]) / BigRational::from_integer(s.into())).collect();
            let l = p.wachspress(&pt).unwrap();
            prop_assert!(l.iter().sum::<BigRational>().is_one());
            for k in 0..2 {
                let back: BigRational = l.iter().zip(v).map(|(x, vv)| x * &vv[k]).sum();
                prop_assert_eq!(&back, &pt[k]);
            }
            // the edge e → e+1 maps to the Bézier curve of the face [e, e+1]
            let sp = SPatch::new(p.clone(), net(4, 3, 7)).unwrap();
            let tt = BigRational::new(t.into(), 16.into());
            let one = BigRational::one();
            let f = (e + 1) % 5;
            let q2: Vec<BigRational> = (0..2).map(|k| (&one - &tt) * &v[e][k] + &tt * &v[f][k]).collect();
            let (_, val) = sp.evaluate(&q2).unwrap();
            prop_assert_eq!(val, casteljau::evaluate(&sp.net.face(&[e, f]), &[&one - &tt, tt.clone()]));
        }
    }
}
