//! Nonparametric (functional) patches: a scalar function over a domain simplex
//! (docs/theory.md §13; Wolfe's "1D Bézier triangle").
//!
//! `f(t) = Σ_{|α|=n} b_α B^n_α(λ(t))` with control ordinates `b_α ∈ ℚ` attached to the
//! **Bézier abscissae** `ξ_α = (α_0 a_0 + … + α_m a_m)/n` (for triangles `(i a1 + j a2 + k a3)/n`).
//! By linear precision, `Σ_α ξ_α B^n_α(λ) = t`, so the graph `(t, f(t))` is the parametric
//! Bézier simplex with control points `(ξ_α, b_α)` ([`graph`]).
//!
//! Ordinates of a polynomial `F` of degree `≤ n` ([`ordinates`]): write `t = Σ λ_k a_k`,
//! homogenise each term of degree `e` with `(Σ λ_k)^{n−e}`; then `b_α` is the coefficient of
//! `λ^α` divided by `C(n;α)` (this is the blossom value `F[a_0^{α_0}, …, a_m^{α_m}]`). For a linear
//! `ℓ` it is `b_α = ℓ(ξ_α)`.
//!
//! ```
//! use tribez::hazmat::domain::Domain;
//! use tribez::hazmat::functional::{abscissae, ordinates};
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::symbolic::Polynomial;
//! let r = |v: &[&str]| v.iter().map(|s| q(s).unwrap()).collect::<Vec<_>>();
//! let t = Domain::new(vec![r(&["1", "1"]), r(&["5", "2"]), r(&["2", "6"])]).unwrap();
//! let xi = abscissae(&t, 3);
//! assert_eq!(xi[1], r(&["7/3", "4/3"])); // ξ_210
//! assert_eq!(xi[5], r(&["8/3", "3"]));   // ξ_111, the centroid
//! // f = xy, n = 2: b_110 = (x1 y2 + x2 y1)/2 = 7/2
//! let xy = Polynomial::parse("x*y", &["x", "y"]).unwrap();
//! assert_eq!(ordinates(&t, 2, &xy).unwrap()[1], q("7/2").unwrap());
//! ```

use num_rational::BigRational;
use num_traits::Zero;

use crate::domain::Domain;
use crate::error::CoreError;
use crate::patch::{BezierPatch, ControlNet};
use crate::simplex::{Simplex, multinomial};
use crate::symbolic::Polynomial;

/// The Bézier abscissae `ξ_α = Σ_k α_k a_k / n` in canonical order (for `n = 0`: the centroid).
pub fn abscissae(domain: &Domain, n: usize) -> Vec<Vec<BigRational>> {
    let m = domain.m();
    let simplex = Simplex::new(m, n);
    let denom = BigRational::from_integer(n.max(1).into());
    simplex
        .iter()
        .map(|alpha| {
            (0..m)
                .map(|c| {
                    if n == 0 {
                        let s: BigRational = domain.vertices().iter().map(|v| v[c].clone()).sum();
                        return s / BigRational::from_integer((m + 1).into());
                    }
                    let s: BigRational = alpha
                        .iter()
                        .zip(domain.vertices())
                        .map(|(&a, v)| BigRational::from_integer(a.into()) * &v[c])
                        .sum();
                    s / &denom
                })
                .collect()
        })
        .collect()
}

/// The graph of a functional patch (`d = 1`): the parametric patch with control points
/// `(ξ_α, b_α) ∈ ℚ^{m+1}` over the same domain.
pub fn graph(patch: &BezierPatch) -> Result<BezierPatch, CoreError> {
    if patch.net.dim() != 1 {
        return Err(CoreError::NotFunctional {
            dim: patch.net.dim(),
        });
    }
    let domain = patch.domain_or_reference();
    let xi = abscissae(&domain, patch.net.degree());
    let points: Vec<Vec<BigRational>> = xi
        .into_iter()
        .zip(patch.net.points())
        .map(|(mut x, b)| {
            x.push(b[0].clone());
            x
        })
        .collect();
    Ok(BezierPatch {
        name: patch.name.as_ref().map(|n| format!("graph of {n}")),
        net: ControlNet::from_points(patch.net.m(), patch.net.degree(), &points),
        domain: patch.domain.clone(),
    })
}

/// The control ordinates of degree `n` of a polynomial `f` in the Cartesian variables of
/// `domain` (`f` must have degree `≤ n`), in canonical order.
pub fn ordinates(domain: &Domain, n: usize, f: &Polynomial) -> Result<Vec<BigRational>, CoreError> {
    let m = domain.m();
    if f.nvars() != m {
        return Err(CoreError::WrongLength {
            what: "the function's variables".into(),
            expected: m,
            found: f.nvars(),
        });
    }
    let deg = f.degree().unwrap_or(0) as usize;
    if deg > n {
        return Err(CoreError::FunctionDegree {
            function: deg,
            patch: n,
        });
    }
    let nv = m + 1;
    // x_c = Σ_k λ_k a_k[c]
    let subs: Vec<Polynomial> = (0..m)
        .map(|c| {
            domain
                .vertices()
                .iter()
                .enumerate()
                .fold(Polynomial::zero(nv), |acc, (k, v)| {
                    acc.add(&Polynomial::variable(nv, k).scale(&v[c]))
                })
        })
        .collect();
    let sum = (0..nv).fold(Polynomial::zero(nv), |acc, k| {
        acc.add(&Polynomial::variable(nv, k))
    });
    let mut hom = Polynomial::zero(nv);
    for (e, c) in f.terms() {
        let term = Polynomial::monomial(m, e.to_vec(), c.clone()).compose(&subs);
        let total: u32 = e.iter().sum();
        hom = hom.add(&term.mul(&sum.pow(n as u32 - total)));
    }
    let simplex = Simplex::new(m, n);
    let coeffs: Vec<(Vec<u32>, BigRational)> = hom
        .terms()
        .into_iter()
        .map(|(e, c)| (e.to_vec(), c.clone()))
        .collect();
    Ok(simplex
        .iter()
        .map(|alpha| {
            coeffs
                .iter()
                .find(|(e, _)| e.as_slice() == alpha)
                .map_or_else(BigRational::zero, |(_, c)| {
                    c / BigRational::from_integer(multinomial(alpha).into())
                })
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational as q;
    use crate::symbolic::cartesian_form;
    use proptest::prelude::*;

    fn r(xs: &[&str]) -> Vec<BigRational> {
        xs.iter().map(|x| q(x).unwrap()).collect()
    }

    fn tri() -> Domain {
        Domain::new(vec![r(&["1", "1"]), r(&["5", "2"]), r(&["2", "6"])]).unwrap()
    }

    #[test]
    fn linear_precision_theory_section_13() {
        let xy = ["x", "y"];
        let l = Polynomial::parse("3 - 2x + 1/2*y", &xy).unwrap();
        let b = ordinates(&tri(), 3, &l).unwrap();
        // b_α = ℓ(ξ_α)
        for (bi, xi) in b.iter().zip(abscissae(&tri(), 3)) {
            assert_eq!(*bi, l.evaluate(&xi));
        }
        // the functional patch reproduces ℓ identically (symbolic), and its graph is (x, y, ℓ)
        let mut p = BezierPatch::new(ControlNet::new(Simplex::new(2, 3), 1, b));
        p.domain = Some(tri());
        assert_eq!(cartesian_form(&p.net, &tri()), vec![l.clone()]);
        let g = graph(&p).unwrap();
        let forms = cartesian_form(&g.net, &tri());
        assert_eq!(
            forms,
            vec![
                Polynomial::parse("x", &xy).unwrap(),
                Polynomial::parse("y", &xy).unwrap(),
                l
            ]
        );
    }

    #[test]
    fn xy_ordinates_from_the_polar_form() {
        // b200 = x1 y1 = 1, b110 = 7/2, b020 = 10, b101 = 4, b011 = 17, b002 = 12
        let f = Polynomial::parse("x*y", &["x", "y"]).unwrap();
        assert_eq!(
            ordinates(&tri(), 2, &f).unwrap(),
            r(&["1", "7/2", "10", "4", "17", "12"])
        );
        assert!(ordinates(&tri(), 1, &f).is_err());
    }

    #[test]
    fn graph_needs_one_coordinate() {
        let p = BezierPatch::new(ControlNet::new(
            Simplex::new(2, 1),
            2,
            r(&["1", "2", "3", "4", "5", "6"]),
        ));
        assert!(graph(&p).unwrap_err().to_string().contains("2 coordinates"));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        #[test]
        fn polynomials_of_degree_at_most_n_are_reproduced(c in proptest::collection::vec(-9i64..10, 6), n in 2usize..5) {
            // f = c0 + c1 x + c2 y + c3 x² + c4 xy + c5 y²
            let xy = ["x", "y"];
            let text = format!("{} + {}x + {}y + {}x^2 + {}x*y + {}y^2", c[0], c[1], c[2], c[3], c[4], c[5]).replace("+ -", "- ");
            let f = Polynomial::parse(&text, &xy).unwrap();
            let b = ordinates(&tri(), n, &f).unwrap();
            let net = ControlNet::new(Simplex::new(2, n), 1, b);
            prop_assert_eq!(cartesian_form(&net, &tri()), vec![f]);
        }
    }
}
