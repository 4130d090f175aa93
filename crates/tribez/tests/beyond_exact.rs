//! Exact results on Bézier curves and tetrahedra, checked against hand derivations: a cubic
//! curve halved by de Casteljau, and degree elevation on a tetrahedron (the command line's
//! part of issue 5 is crates/tribez-cli/tests/beyond.rs).

use num_rational::BigRational;
use tribez::hazmat::casteljau;
use tribez::hazmat::number::parse_rational as q;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;
use tribez::hazmat::symbolic::{Polynomial, barycentric_form};

fn r(xs: &[&str]) -> Vec<BigRational> {
    xs.iter().map(|x| q(x).unwrap()).collect()
}

#[test]
fn cubic_curve_halved_exactly() {
    // (0,0), (1,2), (3,3), (4,0) split at t = 1/2; halves derived by hand:
    // left (0,0), (1/2,1), (5/4,7/4), (2,15/8); right (2,15/8), (11/4,2), (7/2,3/2), (4,0).
    let pts: Vec<Vec<BigRational>> = [["0", "0"], ["1", "2"], ["3", "3"], ["4", "0"]]
        .iter()
        .map(|p| r(p))
        .collect();
    let net = ControlNet::from_points(1, 3, &pts);
    let levels = casteljau::levels(&net, &r(&["1/2", "1/2"]));
    let left: Vec<Vec<BigRational>> = levels.iter().map(|l| l.point(0).to_vec()).collect();
    let right: Vec<Vec<BigRational>> = levels
        .iter()
        .rev()
        .map(|l| l.point(l.len() - 1).to_vec())
        .collect();
    let want_left: Vec<Vec<BigRational>> =
        [["0", "0"], ["1/2", "1"], ["5/4", "7/4"], ["2", "15/8"]]
            .iter()
            .map(|p| r(p))
            .collect();
    let want_right: Vec<Vec<BigRational>> =
        [["2", "15/8"], ["11/4", "2"], ["7/2", "3/2"], ["4", "0"]]
            .iter()
            .map(|p| r(p))
            .collect();
    assert_eq!(left, want_left);
    assert_eq!(right, want_right);
    // each half reparametrises the curve: left(s) = p(s/2)
    let l = ControlNet::from_points(1, 3, &left);
    assert_eq!(
        casteljau::evaluate(&l, &r(&["1/3", "2/3"])),
        casteljau::evaluate(&net, &r(&["2/3", "1/3"]))
    );
}

#[test]
fn degree_elevation_identity_on_a_tetrahedron() {
    // c^(1)_α = Σ_k α_k c_{α−e_k} / (n+1) (docs/theory.md §11) gives the same polynomial:
    // its homogeneous form equals (u0 + u1 + u2 + u3) times the original one.
    let s = Simplex::new(3, 2);
    let coords: Vec<BigRational> = (0..s.len() * 3)
        .map(|i| {
            BigRational::new(
                ((i * 7 % 11) as i64 - 5).into(),
                ((i % 4) as i64 + 1).into(),
            )
        })
        .collect();
    let net = ControlNet::new(s, 3, coords);
    let up = Simplex::new(3, 3);
    let mut elevated = Vec::new();
    for alpha in up.iter() {
        for c in 0..3 {
            let mut acc = BigRational::from_integer(0.into());
            for k in 0..4 {
                if alpha[k] > 0 {
                    let mut b = alpha.to_vec();
                    b[k] -= 1;
                    acc += BigRational::from_integer(alpha[k].into()) * &net.at(&b)[c];
                }
            }
            elevated.push(acc / BigRational::from_integer(3.into()));
        }
    }
    let e = ControlNet::new(up, 3, elevated);
    let sum = (0..4).fold(Polynomial::zero(4), |a, k| {
        a.add(&Polynomial::variable(4, k))
    });
    for (lo, hi) in barycentric_form(&net).iter().zip(barycentric_form(&e)) {
        assert_eq!(lo.mul(&sum), hi);
    }
}
