//! The symbolic form of a patch: each coordinate as a polynomial in the barycentric variables
//! (the homogeneous form `Σ C(n;α) c_α λ^α`), or in the Cartesian variables of a domain (the
//! barycentric coordinates substituted as affine polynomials, Cramer's rule), and the default
//! variable names.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::Polynomial;
use crate::domain::Domain;
use crate::patch::ControlNet;
use crate::simplex::multinomial;

/// Default variable names for `m + 1` barycentric coordinates: `u, v, w` for triangles, `u, v`
/// for curves, `u0, u1, …` otherwise.
pub fn barycentric_names(m: usize) -> Vec<String> {
    match m {
        1 => vec!["u".into(), "v".into()],
        2 => vec!["u".into(), "v".into(), "w".into()],
        _ => (0..=m).map(|k| format!("u{k}")).collect(),
    }
}

/// Default Cartesian variable names: `x`, `x, y`, `x, y, z`, else `x1, …`.
pub fn cartesian_names(m: usize) -> Vec<String> {
    match m {
        1 => vec!["x".into()],
        2 => vec!["x".into(), "y".into()],
        3 => vec!["x".into(), "y".into(), "z".into()],
        _ => (1..=m).map(|k| format!("x{k}")).collect(),
    }
}

/// The homogeneous polynomial of each coordinate, in the barycentric variables.
pub fn barycentric_form(net: &ControlNet<BigRational>) -> Vec<Polynomial> {
    let nv = net.m() + 1;
    (0..net.dim())
        .map(|c| {
            let mut p = Polynomial::zero(nv);
            for (alpha, pt) in net.entries() {
                let k = BigRational::from_integer(BigInt::from(multinomial(alpha)));
                p.add_term(alpha.to_vec(), k * &pt[c]);
            }
            p
        })
        .collect()
}

/// The barycentric coordinates of a domain as affine polynomials in the Cartesian variables.
pub fn barycentric_of_cartesian(domain: &Domain) -> Vec<Polynomial> {
    let m = domain.m();
    let zero = vec![BigRational::zero(); m];
    // invariant: `zero` has the domain's m coordinates
    let base = domain.barycentric(&zero).expect("dimension matches");
    let mut out: Vec<Polynomial> = base
        .iter()
        .map(|b| Polynomial::constant(m, b.clone()))
        .collect();
    for c in 0..m {
        let mut unit = zero.clone();
        unit[c] = BigRational::one();
        // invariant: `unit` has the domain's m coordinates
        let at = domain.barycentric(&unit).expect("dimension matches");
        for (k, poly) in out.iter_mut().enumerate() {
            let slope = &at[k] - &base[k];
            *poly = poly.add(&Polynomial::variable(m, c).scale(&slope));
        }
    }
    out
}

/// Each coordinate as a polynomial in the Cartesian variables of `domain`.
pub fn cartesian_form(net: &ControlNet<BigRational>, domain: &Domain) -> Vec<Polynomial> {
    let subs = barycentric_of_cartesian(domain);
    barycentric_form(net)
        .iter()
        .map(|p| p.compose(&subs))
        .collect()
}
