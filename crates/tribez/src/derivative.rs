//! Directional derivatives of any order, intermediate points and the tangent plane
//! (Floater's notes §4, Finn's notes §30.1; docs/theory.md §3 and §7).
//!
//! For barycentric directions `d^{(1)}, …, d^{(r)}` (each with `m + 1` components summing to 0)
//! and `Δ_d c_α = Σ_k d_k c_{α+e_k}`, the `r`-th directional derivative of a degree-`n` patch is
//!
//! `D_{d^{(1)}} ⋯ D_{d^{(r)}} p(λ) = n!/(n−r)! · Σ_{|α|=n−r} (Δ_{d^{(1)}} ⋯ Δ_{d^{(r)}} c)_α B^{n−r}_α(λ)`
//!
//! `= n!/(n−r)! · b[d^{(1)}, …, d^{(r)}, λ^{n−r}]`  (the blossom, docs/theory.md §4),
//!
//! computed here as `r` de Casteljau steps with the directions followed by `n − r` steps with
//! `λ`. A Cartesian vector `v` is turned into a barycentric direction by the domain (Cramer's rule,
//! Floater's notes eqs. 9–10: `Σ v_k = 0`, `Σ v_k a_k = v`). Indices follow the canonical order of
//! [`crate::simplex`]; direction component `k` belongs to domain vertex `k`.
//!
//! ```
//! use tribez::hazmat::derivative::directional_derivative;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! let r = |v: &[&str]| v.iter().map(|s| q(s).unwrap()).collect::<Vec<_>>();
//! // Finn's worked example (Finn): n = 2, at (1/2, 1/3, 1/6)
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! // on the reference triangle u = x, w = 1 − x − y, so ∂/∂x is the direction (1, 0, −1):
//! // p_x = (0, −2, 1/3) (docs/theory.md §3)
//! let px = directional_derivative(&net, &[&r(&["1", "0", "-1"])], &r(&["1/2", "1/3", "1/6"]));
//! assert_eq!(px, r(&["0", "-2", "1/3"]));
//! ```

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::casteljau;
use crate::domain::Domain;
use crate::error::CoreError;
use crate::patch::ControlNet;
use crate::scalar::Scalar;

/// `n!/(n−r)! = n (n−1) ⋯ (n−r+1)`, exactly as a big integer.
pub fn falling_factorial(n: usize, r: usize) -> num_bigint::BigUint {
    (n - r + 1..=n).fold(num_bigint::BigUint::one(), |acc, k| acc * k)
}

/// The net of the derivative `D_{d^{(1)}} ⋯ D_{d^{(r)}} p`: degree `n − r`, control points
/// `n!/(n−r)! · (Δ_{d^{(1)}} ⋯ Δ_{d^{(r)}} c)_α`, `|α| = n − r`.
///
/// Generic over the number type, any simplex dimension `m`. Panics if `r > n` (use
/// [`check_order`] first for input from users).
pub fn derivative_net<T: Scalar>(net: &ControlNet<T>, dirs: &[&[T]]) -> ControlNet<T> {
    let n = net.degree();
    let r = dirs.len();
    assert!(r <= n, "derivative of order {r} of a degree-{n} net");
    let lower = casteljau::partial_blossom(net, dirs);
    let factor = T::from_biguint(&falling_factorial(n, r));
    lower.map(|x| factor.clone() * x)
}

/// `D_{d^{(1)}} ⋯ D_{d^{(r)}} p(λ)`: `r` de Casteljau steps with the directions, then `n − r`
/// with `λ`, times `n!/(n−r)!` (docs/theory.md §7). Generic, any `m`. Panics if `r > n`.
pub fn directional_derivative<T: Scalar>(net: &ControlNet<T>, dirs: &[&[T]], at: &[T]) -> Vec<T> {
    let d = derivative_net(net, dirs);
    casteljau::evaluate(&d, at)
}

/// An error unless `order <= degree`.
pub fn check_order(order: usize, degree: usize) -> Result<(), CoreError> {
    if order > degree {
        return Err(CoreError::OrderTooHigh { order, degree });
    }
    Ok(())
}

/// `a × b` in `ℚ³`.
pub fn cross(a: &[BigRational], b: &[BigRational]) -> Vec<BigRational> {
    vec![
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn sub(a: &[BigRational], b: &[BigRational]) -> Vec<BigRational> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

/// The first-order differential geometry of a patch at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct TangentFrame {
    /// `p(λ)`.
    pub point: Vec<BigRational>,
    /// The de Casteljau points of level `n − 1`: `c^{n−1}_{e_k}(λ)`, `k = 0..=m` (for triangles
    /// `p100, p010, p001` of Finn's notes). `∂P/∂λ_k = n c^{n−1}_{e_k}` and `p(λ) = Σ λ_k c^{n−1}_{e_k}`.
    pub intermediate: Vec<Vec<BigRational>>,
    /// `∂p/∂x_c` for each Cartesian coordinate `x_c` of the domain:
    /// `n Σ_k δ^{(c)}_k c^{n−1}_{e_k}` with `δ^{(c)}` the directional coordinates of the unit vector.
    pub partials: Vec<Vec<BigRational>>,
    /// `p_x × p_y` (triangles in `ℝ³` only).
    pub normal: Option<Vec<BigRational>>,
    /// `(n²/D) (c^{n−1}_{010} − c^{n−1}_{100}) × (c^{n−1}_{001} − c^{n−1}_{100})`, `D = 2·signedArea(T)`
    /// (docs/theory.md §7): equal to [`TangentFrame::normal`] (triangles in `ℝ³` only).
    pub normal_from_intermediate: Option<Vec<BigRational>>,
    /// Whether the point is regular: the `m` partials are linearly independent (their Gram
    /// determinant `det(J Jᵀ)`, `J` the `m × d` matrix of partials, is non-zero). At a singular
    /// point (a collapsed corner, a cusp, a degenerate net) the first partials do not span a
    /// tangent plane and the normal above is the zero vector.
    pub regular: bool,
}

/// The tangent frame of a patch at barycentric `λ` over `domain` (degree `n >= 1`, any `m`).
pub fn tangent_frame(
    net: &ControlNet<BigRational>,
    domain: &Domain,
    at: &[BigRational],
) -> Result<TangentFrame, CoreError> {
    let n = net.degree();
    if n == 0 {
        return Err(CoreError::ConstantPatch);
    }
    let m = net.m();
    if domain.m() != m {
        return Err(CoreError::DomainOfPatch {
            domain: domain.m(),
            patch: m,
        });
    }
    let args = vec![at; n - 1];
    let level = casteljau::partial_blossom(net, &args);
    let intermediate: Vec<Vec<BigRational>> = (0..=m).map(|k| level.corner(k).to_vec()).collect();
    let point = casteljau::step(&level, at).point(0).to_vec();
    let nq = BigRational::from_integer(n.into());
    let mut partials = Vec::with_capacity(m);
    for c in 0..m {
        let mut unit = vec![BigRational::zero(); m];
        unit[c] = BigRational::one();
        let delta = domain.direction(&unit)?;
        let v: Vec<BigRational> = (0..net.dim())
            .map(|i| {
                intermediate
                    .iter()
                    .zip(&delta)
                    .map(|(p, dk)| dk * &p[i])
                    .sum::<BigRational>()
                    * &nq
            })
            .collect();
        partials.push(v);
    }
    let scale = (m == 2 && net.dim() == 3).then(|| &nq * &nq / domain.determinant());
    Ok(TangentFrame::assemble(point, intermediate, partials, scale))
}

impl TangentFrame {
    /// The frame from its point, level-`(n−1)` points and partials; for triangles in `ℝ³`
    /// (`scale` given) the normal `p_x × p_y` and `scale · (c_1 − c_0) × (c_2 − c_0)` (`n²/D` for
    /// a polynomial patch); and whether the point is regular.
    pub fn assemble(
        point: Vec<BigRational>,
        intermediate: Vec<Vec<BigRational>>,
        partials: Vec<Vec<BigRational>>,
        scale: Option<BigRational>,
    ) -> TangentFrame {
        let (normal, normal_from_intermediate) = match scale {
            Some(k) => {
                let c = &intermediate;
                let via = cross(&sub(&c[1], &c[0]), &sub(&c[2], &c[0]))
                    .into_iter()
                    .map(|x| x * &k)
                    .collect();
                (Some(cross(&partials[0], &partials[1])), Some(via))
            }
            None => (None, None),
        };
        let m = partials.len();
        let gram = (0..m)
            .map(|a| {
                (0..m)
                    .map(|b| {
                        partials[a]
                            .iter()
                            .zip(&partials[b])
                            .map(|(x, y)| x * y)
                            .sum()
                    })
                    .collect()
            })
            .collect();
        let regular = !crate::domain::determinant(gram).is_zero();
        TangentFrame {
            point,
            intermediate,
            partials,
            normal,
            normal_from_intermediate,
            regular,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::{barycentric_form, cartesian_form};
    use crate::testing::{finn, r};
    use proptest::prelude::*;

    #[test]
    fn finn_tangent_frame_theory_section_3() {
        let f = tangent_frame(&finn(), &Domain::reference(2), &r(&["1/2", "1/3", "1/6"])).unwrap();
        assert_eq!(f.point, r(&["4/9", "5/9", "29/36"]));
        assert_eq!(
            f.intermediate,
            vec![
                r(&["1/3", "1/6", "2/3"]),
                r(&["2/3", "5/6", "7/6"]),
                r(&["1/3", "7/6", "1/2"])
            ]
        );
        assert_eq!(
            f.partials,
            vec![r(&["0", "-2", "1/3"]), r(&["2/3", "-2/3", "4/3"])]
        );
        assert_eq!(f.normal, Some(r(&["-22/9", "2/9", "4/3"])));
        assert_eq!(f.normal_from_intermediate, f.normal);
        assert!(f.regular);
    }

    #[test]
    fn a_collapsed_corner_is_singular() {
        // Quadratic with c200 = c110 = c101 = (0,0,0): at the corner (1,0,0) the level-1 points
        // are those three control points, so both partials are zero; elsewhere it is regular.
        let pts: Vec<Vec<BigRational>> = [
            ["0", "0", "0"],
            ["0", "0", "0"],
            ["1", "0", "0"],
            ["0", "0", "0"],
            ["0", "1", "1"],
            ["0", "1", "0"],
        ]
        .iter()
        .map(|p| r(p))
        .collect();
        let net = ControlNet::from_points(2, 2, &pts);
        let corner = tangent_frame(&net, &Domain::reference(2), &r(&["1", "0", "0"])).unwrap();
        assert!(!corner.regular);
        assert_eq!(corner.normal, Some(r(&["0", "0", "0"])));
        let inside = tangent_frame(&net, &Domain::reference(2), &r(&["0", "1/2", "1/2"])).unwrap();
        assert!(inside.regular);
        // A curve (m = 1) in the plane: the Gram test is |p'|² ≠ 0; a net with equal control
        // points has p' = 0 everywhere.
        let flat = ControlNet::from_points(1, 2, &[r(&["1", "2"]), r(&["1", "2"]), r(&["1", "2"])]);
        assert!(
            !tangent_frame(&flat, &Domain::reference(1), &r(&["1/3", "2/3"]))
                .unwrap()
                .regular
        );
    }

    #[test]
    fn floater_example_theory_section_7() {
        // Finn's net over T = (1,2),(7,3),(2,8), v = (1,−2), at t = (3,4).
        let t = Domain::new(vec![r(&["1", "2"]), r(&["7", "3"]), r(&["2", "8"])]).unwrap();
        let at = t.barycentric(&r(&["3", "4"])).unwrap();
        let v = t.direction(&r(&["1", "-2"])).unwrap();
        let d1 = directional_derivative(&finn(), &[&v], &at);
        assert_eq!(d1, r(&["48/245", "-118/245", "64/245"]));
        let d2 = directional_derivative(&finn(), &[&v, &v], &at);
        assert_eq!(d2, r(&["-256/1225", "256/1225", "242/1225"]));
        // the normal identity with D = 35
        let f = tangent_frame(&finn(), &t, &at).unwrap();
        assert_eq!(f.normal, f.normal_from_intermediate);
    }

    #[test]
    fn order_above_degree_is_an_error() {
        assert_eq!(
            check_order(3, 2),
            Err(CoreError::OrderTooHigh {
                order: 3,
                degree: 2
            })
        );
        assert!(check_order(2, 2).is_ok());
    }

    #[test]
    fn curve_and_tetrahedron_derivatives() {
        // curve (m = 1): p(t) = (1−t)² ·0 + 2(1−t)t·1 + t²·4 → d/dt along (−1, 1) at t: 2(1−t)·1... check
        // p = 2uv + 4v², D_(−1,1) p = ∂_v P − ∂_u P = (2u + 8v) − 2v; at (u,v) = (1/2,1/2): 4.
        let c = ControlNet::from_points(1, 2, &[r(&["0"]), r(&["1"]), r(&["4"])]);
        assert_eq!(
            directional_derivative(&c, &[&r(&["-1", "1"])], &r(&["1/2", "1/2"])),
            r(&["4"])
        );
        // tetrahedron of degree 1: p = Σ λ_k c_k, derivative along e_3 − e_0 is c_3 − c_0 everywhere
        let t = ControlNet::from_points(3, 1, &[r(&["1"]), r(&["2"]), r(&["5"]), r(&["11"])]);
        let at = r(&["1/4", "1/4", "1/4", "1/4"]);
        assert_eq!(
            directional_derivative(&t, &[&r(&["-1", "0", "0", "1"])], &at),
            r(&["10"])
        );
    }

    #[test]
    fn degree_zero_has_no_tangent_plane() {
        let c = ControlNet::from_points(2, 0, &[r(&["1", "2", "3"])]);
        assert!(tangent_frame(&c, &Domain::reference(2), &r(&["1", "0", "0"])).is_err());
    }

    fn small() -> impl Strategy<Value = BigRational> {
        (-20i64..=20, 1i64..=6).prop_map(|(a, b)| BigRational::new(a.into(), b.into()))
    }

    fn net_strategy(m: usize) -> impl Strategy<Value = ControlNet<BigRational>> {
        (1usize..=4, 1usize..=3).prop_flat_map(move |(n, d)| {
            let len = crate::simplex::count(m, n) * d;
            proptest::collection::vec(small(), len).prop_map(move |coords| {
                ControlNet::new(crate::simplex::Simplex::new(m, n), d, coords)
            })
        })
    }

    fn bary(m: usize) -> impl Strategy<Value = Vec<BigRational>> {
        proptest::collection::vec(small(), m).prop_map(|mut v| {
            let s: BigRational = v.iter().sum();
            v.push(BigRational::one() - s);
            v
        })
    }

    fn dir(m: usize) -> impl Strategy<Value = Vec<BigRational>> {
        proptest::collection::vec(small(), m).prop_map(|mut v| {
            let s: BigRational = v.iter().sum();
            v.push(-s);
            v
        })
    }

    type Case = (
        ControlNet<BigRational>,
        Vec<BigRational>,
        Vec<Vec<BigRational>>,
    );

    fn case() -> impl Strategy<Value = Case> {
        (1usize..=3).prop_flat_map(|m| {
            net_strategy(m).prop_flat_map(move |net| {
                let n = net.degree();
                (
                    Just(net),
                    bary(m),
                    (0..=n).prop_flat_map(move |r| proptest::collection::vec(dir(m), r)),
                )
            })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// The de Casteljau derivative equals Σ_k d_k ∂/∂λ_k applied r times to the symbolic form.
        #[test]
        fn derivative_equals_symbolic_derivative((net, at, dirs) in case()) {
            let m = net.m();
            let refs: Vec<&[BigRational]> = dirs.iter().map(Vec::as_slice).collect();
            let got = directional_derivative(&net, &refs, &at);
            let mut polys = barycentric_form(&net);
            for d in &dirs {
                polys = polys.iter().map(|p| {
                    (0..=m).fold(crate::symbolic::Polynomial::zero(m + 1), |acc, k| acc.add(&p.derivative(k).scale(&d[k])))
                }).collect();
            }
            let want: Vec<BigRational> = polys.iter().map(|p| p.evaluate(&at)).collect();
            prop_assert_eq!(got, want);
        }

        /// p_x, p_y of the tangent frame equal ∂/∂x, ∂/∂y of the Cartesian form; the point and the
        /// intermediate points are coplanar and span the plane of p_x, p_y.
        #[test]
        fn tangent_frame_matches_cartesian_form(net in net_strategy(2), at in bary(2), skew in small()) {
            let domain = match Domain::new(vec![r(&["0", "0"]), vec![BigRational::from_integer(3.into()), skew.clone()], r(&["1", "2"])]) {
                Ok(d) => d,
                Err(_) => return Ok(()),
            };
            let f = tangent_frame(&net, &domain, &at).unwrap();
            let xy = domain.cartesian(&at);
            let cart = cartesian_form(&net, &domain);
            for c in 0..2 {
                let want: Vec<BigRational> = cart.iter().map(|p| p.derivative(c).evaluate(&xy)).collect();
                prop_assert_eq!(&f.partials[c], &want);
            }
            // p = Σ λ_k c_k: the point is the affine combination of the intermediate points
            let comb: Vec<BigRational> = (0..net.dim()).map(|i| f.intermediate.iter().zip(&at).map(|(p, l)| l * &p[i]).sum()).collect();
            prop_assert_eq!(&comb, &f.point);
            if net.dim() == 3 {
                prop_assert_eq!(&f.normal, &f.normal_from_intermediate);
                // the intermediate triangle's edges are combinations of p_x, p_y: both orthogonal to the normal
                let nrm = f.normal.clone().unwrap();
                for k in 1..3 {
                    let e = sub(&f.intermediate[k], &f.intermediate[0]);
                    let dot: BigRational = e.iter().zip(&nrm).map(|(a, b)| a * b).sum();
                    prop_assert!(dot.is_zero());
                    // and with the normal non-zero, spanning the same plane: the intermediate normal is a multiple
                }
                let inter = cross(&sub(&f.intermediate[1], &f.intermediate[0]), &sub(&f.intermediate[2], &f.intermediate[0]));
                prop_assert!(cross(&inter, &nrm).iter().all(Zero::is_zero));
            }
        }
    }

    #[test]
    fn float_path_runs_the_same_algorithm() {
        let net = finn().map(crate::number::round_f64);
        let px = directional_derivative(&net, &[&[1.0, 0.0, -1.0]], &[0.5, 0.25, 0.25]);
        let exact = directional_derivative(
            &finn(),
            &[&r(&["1", "0", "-1"])],
            &r(&["1/2", "1/4", "1/4"]),
        );
        let want: Vec<f64> = exact.iter().map(crate::number::round_f64).collect();
        assert_eq!(px, want);
    }
}
