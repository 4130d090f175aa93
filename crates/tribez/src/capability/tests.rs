//! The constructions written once over [`Constructions::linear_net`]: each kind keeps its kind,
//! its name, and Cartesian values over a Cartesian domain.

use num_rational::BigRational;

use super::{Split, constructions};
use crate::any_patch::AnyPatch;
use crate::domain::Domain;
use crate::number::parse_rational as q;
use crate::patch::{BezierPatch, ControlNet};
use crate::rational::RationalPatch;
use crate::subdivide::HalvingOrder;

fn v(xs: &[&str]) -> Vec<BigRational> {
    xs.iter().map(|x| q(x).unwrap()).collect()
}

/// A functional quadratic over the triangle (0,0), (2,0), (0,2): f = 4λ₁λ₂ + λ₂² + … (any net).
fn hill() -> AnyPatch {
    let b = ["0", "1", "3", "2", "1/2", "-1"].map(|x| v(&[x]));
    let mut p = BezierPatch::new(ControlNet::from_points(2, 2, &b));
    p.name = Some("hill".into());
    p.domain = Some(Domain::new(vec![v(&["0", "0"]), v(&["2", "0"]), v(&["0", "2"])]).unwrap());
    AnyPatch::Functional(p)
}

/// A rational quadratic over the same triangle (weights 1, 2, 1, 3, 1, 2).
fn rational_hill() -> AnyPatch {
    let AnyPatch::Functional(p) = hill() else {
        unreachable!()
    };
    AnyPatch::Rational(RationalPatch::new(p, v(&["1", "2", "1", "3", "1", "2"])))
}

fn value(p: &AnyPatch, at: &[BigRational]) -> Vec<BigRational> {
    crate::Patch::from(p.clone()).evaluate(at).unwrap()
}

fn domain(p: &AnyPatch) -> Domain {
    constructions(p).unwrap().domain()
}

/// `Σ μ_k f_k`: the parent's barycentric point of the piece's point `μ`.
fn in_parent(f: &[Vec<BigRational>], mu: &[BigRational]) -> Vec<BigRational> {
    (0..f[0].len())
        .map(|i| f.iter().zip(mu).map(|(fk, m)| &fk[i] * m).sum())
        .collect()
}

#[test]
fn a_subpatch_keeps_kind_and_name_and_maps_its_domain() {
    let f = vec![
        v(&["1", "0", "0"]),
        v(&["1/2", "1/2", "0"]),
        v(&["1/3", "1/3", "1/3"]),
    ];
    let mu = v(&["1/5", "3/10", "1/2"]);
    for parent in [hill(), rational_hill()] {
        let sub = constructions(&parent).unwrap().subpatch(&f).unwrap();
        assert_eq!(sub.kind_name(), parent.kind_name());
        // the same polynomial (rational function) over the sub-simplex: p′(μ) = p(Σ μ_k f_k)
        let lambda = in_parent(&f, &mu);
        assert_eq!(value(&sub, &mu), value(&parent, &lambda));
        // and the same Cartesian point: the piece's domain is the image of f
        assert_eq!(
            domain(&sub).cartesian(&mu),
            domain(&parent).cartesian(&lambda)
        );
        // (1/2,1/2,0) is (1, 0) in the parent's domain (0,0), (2,0), (0,2)
        assert_eq!(domain(&sub).vertices()[1], v(&["1", "0"]));
    }
}

#[test]
fn a_split_on_a_facet_leaves_the_degenerate_piece_out() {
    let t = v(&["1/2", "1/2", "0"]);
    for parent in [hill(), rational_hill()] {
        let c = constructions(&parent).unwrap();
        let pieces = c.pieces(&Split::At(&t)).unwrap();
        // piece 2 (0-based) would replace corner 2 by a point of the opposite edge
        assert_eq!(pieces.iter().map(|p| p.index).collect::<Vec<_>>(), [0, 1]);
        let mu = v(&["1/4", "1/4", "1/2"]);
        for piece in &pieces {
            let lambda = in_parent(&piece.domain_in_parent, &mu);
            assert_eq!(value(&piece.patch, &mu), value(&parent, &lambda));
            assert_eq!(piece.patch.kind_name(), parent.kind_name());
        }
        // a whole split refuses it
        assert!(c.split_at(&t).is_err());
    }
}

#[test]
fn every_split_gives_the_parents_values() {
    let mu = v(&["1/7", "2/7", "4/7"]);
    let splits = [
        Split::At(&[q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()]),
        Split::Midpoints,
        Split::Halve {
            edge: (0, 2),
            add_and_halve: None,
        },
        Split::Halve {
            edge: (0, 2),
            add_and_halve: Some(HalvingOrder::TopDown),
        },
    ];
    for parent in [hill(), rational_hill()] {
        let c = constructions(&parent).unwrap();
        for split in &splits {
            let pieces = c.pieces(split).unwrap();
            let expected = match split {
                Split::At(_) => 3,
                Split::Midpoints => 4,
                Split::Halve { .. } => 2,
            };
            assert_eq!(pieces.len(), expected, "{split:?}");
            for piece in &pieces {
                let lambda = in_parent(&piece.domain_in_parent, &mu);
                assert_eq!(value(&piece.patch, &mu), value(&parent, &lambda));
                assert_eq!(
                    domain(&piece.patch).cartesian(&mu),
                    domain(&parent).cartesian(&lambda)
                );
            }
        }
        // both ways of halving give the same pieces
        let [a, b] = [&splits[2], &splits[3]].map(|s| c.pieces(s).unwrap());
        assert_eq!(a, b);
    }
}

#[test]
fn elevation_keeps_kind_name_domain_and_values() {
    let at = v(&["1/3", "1/4", "5/12"]);
    for parent in [hill(), rational_hill()] {
        let up = constructions(&parent).unwrap().elevate(3).unwrap();
        assert_eq!(up.kind_name(), parent.kind_name());
        assert_eq!(crate::Patch::from(up.clone()).degree(), 5);
        assert_eq!(value(&up, &at), value(&parent, &at));
        assert_eq!(domain(&up), domain(&parent));
        assert_eq!(up.clone().name_mut().as_deref(), Some("hill"));
    }
}

#[test]
fn bad_edges_and_split_points_of_the_wrong_length_are_errors() {
    let parent = hill();
    let c = constructions(&parent).unwrap();
    let bad = Split::Halve {
        edge: (1, 1),
        add_and_halve: None,
    };
    assert!(c.pieces(&bad).is_err());
    let huge = Split::Halve {
        edge: (usize::MAX, 0),
        add_and_halve: None,
    };
    assert!(c.pieces(&huge).is_err());
    assert!(c.pieces(&Split::At(&v(&["1/2", "1/2"]))).is_err());
}

/// Only the polynomial kinds promise an evaluation that cannot fail at an input of the right
/// length (so that `tribez eval` may write their reports while it evaluates): a rational patch
/// fails where its weights sum to zero.
#[test]
fn only_the_polynomial_kinds_are_total() {
    for (p, total) in [(hill(), true), (rational_hill(), false)] {
        let patch = crate::Patch::from(p);
        assert_eq!(patch.exact().exact_evaluator().total(), total);
    }
    let AnyPatch::Functional(b) = hill() else {
        unreachable!()
    };
    let patch = crate::Patch::from(AnyPatch::Bezier(b));
    assert!(patch.exact().exact_evaluator().total());
}
