//! Intersections of curves that lie on one algebraic curve (docs/theory.md §16.5): crossings
//! at a node of the common curve, closing points, overlaps of curves that fold back, close up
//! or pass a node. Expected values: fixtures/intersect/derive.py (SymPy: the common factor G,
//! the isolated solutions off G = 0 and the pieces of G = 0, checked against the hand
//! derivations in the comments); never tribez's output.

use std::cmp::Ordering;

use tribez::algebraic::{Curve, CurveIntersections, RealAlgebraic, intersect_curves};
use tribez::parse_rational;

fn q(s: &str) -> num_rational::BigRational {
    parse_rational(s).unwrap()
}

fn curve(points: &[(&str, &str)]) -> Curve {
    Curve {
        points: points.iter().map(|(x, y)| [q(x), q(y)]).collect(),
        weights: None,
    }
}

fn seg() -> Curve {
    curve(&[("0", "0"), ("4", "0")])
}
fn fold2() -> Curve {
    curve(&[("1", "0"), ("3", "0"), ("1", "0")])
}
fn drop() -> Curve {
    curve(&[("0", "0"), ("-4", "4"), ("-4", "-4"), ("0", "0")])
}
fn nodal() -> Curve {
    curve(&[("9", "-18"), ("-7", "26"), ("-7", "-26"), ("9", "18")])
}
fn nodal_rot() -> Curve {
    curve(&[("18", "9"), ("-26", "-7"), ("26", "-7"), ("-18", "9")])
}

/// Is `x` the rational `r`?
fn is(x: &RealAlgebraic, r: &str) -> bool {
    x.cmp_exact(&RealAlgebraic::rational(q(r))) == Ordering::Equal
}

/// The isolated points as `(s, t, tangential)` must be exactly `want` (rationals).
fn points_are(r: &CurveIntersections, want: &[(&str, &str, bool)]) {
    assert_eq!(r.points.len(), want.len(), "{:?}", r.points);
    for (p, (s, t, tan)) in r.points.iter().zip(want) {
        assert!(is(&p.s, s) && is(&p.t, t), "{p:?} against {s}, {t}");
        assert_eq!(p.tangential, *tan, "{p:?}");
    }
}

/// The overlaps as `(s0, s1, t0, t1)` must be exactly `want`.
fn pieces_are(r: &CurveIntersections, want: &[(&str, &str, &str, &str)]) {
    assert_eq!(r.overlaps.len(), want.len(), "{:?}", r.overlaps);
    for (o, (s0, s1, t0, t1)) in r.overlaps.iter().zip(want) {
        assert!(
            is(&o.s[0], s0) && is(&o.s[1], s1) && is(&o.t[0], t0) && is(&o.t[1], t1),
            "{o:?} against s {s0}..{s1}, t {t0}..{t1}"
        );
    }
}

#[test]
fn two_pieces_of_a_nodal_cubic_cross_at_the_node() {
    // (u^2 − 1, u^3 − u) on y^2 = x^3 + x^2: A = P(2s − 2), B = P(2t). The node u = ±1 gives
    // s = 1/2, t = 1/2 (tangents (−4, 4) and (4, 4): transversal); the shared end point
    // A(1) = B(0) = (−1, 0) with equal tangents (tangential). G = s − t − 1 meets the square
    // only at (1, 0).
    let a = curve(&[("3", "-6"), ("1/3", "4/3"), ("-1", "2/3"), ("-1", "0")]);
    let b = curve(&[("-1", "0"), ("-1", "-2/3"), ("1/3", "-4/3"), ("3", "6")]);
    let r = intersect_curves(&a, &b).unwrap();
    points_are(&r, &[("1/2", "1/2", false), ("1", "0", true)]);
    pieces_are(&r, &[]);
}

#[test]
fn bezier_package_fixture_pair_crosses_at_an_irrational_point() {
    // G = s − t − 1; off it, s = 1 − √5/3 (root of 9x^2 − 18x + 4), t = √5/3 (root of
    // 9x^2 − 5), at (−1/4, 11/8), transversal; and the shared end point (1, 0)
    let a = curve(&[
        ("0", "2"),
        ("-1/2", "1"),
        ("-1/4", "3/4"),
        ("-3/32", "53/64"),
    ]);
    let b = curve(&[
        ("-3/32", "53/64"),
        ("1/16", "29/32"),
        ("1/8", "21/16"),
        ("-3/4", "13/8"),
    ]);
    let r = intersect_curves(&a, &b).unwrap();
    assert_eq!(r.points.len(), 2, "{:?}", r.points);
    assert!(r.overlaps.is_empty());
    let p = &r.points[0];
    let s = p.s.as_root().expect("irrational");
    let t = p.t.as_root().expect("irrational");
    assert_eq!(s.poly().coeffs(), [4, -18, 9].map(num_bigint::BigInt::from));
    assert_eq!(t.poly().coeffs(), [-5, 0, 9].map(num_bigint::BigInt::from));
    // 1 − √5/3 = 0.2546440075000701…, √5/3 = 0.7453559924999299…
    assert!((p.s.to_f64() - (1.0 - 5f64.sqrt() / 3.0)).abs() < 1e-15);
    assert!((p.t.to_f64() - 5f64.sqrt() / 3.0).abs() < 1e-15);
    assert!(!p.tangential);
    assert!(p.point[0].0 <= q("-1/4") && q("-1/4") <= p.point[0].1);
    assert!(p.point[1].0 <= q("11/8") && q("11/8") <= p.point[1].1);
    assert!(is(&r.points[1].s, "1") && is(&r.points[1].t, "0") && r.points[1].tangential);
}

#[test]
fn a_curve_folding_back_on_a_segment_gives_two_pieces() {
    // fold2 = (1 + 4t − 4t^2, 0) on seg = (4s, 0): s = 1/4 + t − t^2, t ∈ [0, 1]: t from 0 up
    // to 1/2 as s goes from 1/4 to 1/2, and t from 1 down to 1/2
    let r = intersect_curves(&seg(), &fold2()).unwrap();
    points_are(&r, &[]);
    pieces_are(
        &r,
        &[("1/4", "1/2", "0", "1/2"), ("1/4", "1/2", "1", "1/2")],
    );
    // swapped: t = 1/4 + s − s^2: up from 1/4 to 1/2 on s ∈ [0, 1/2], down on [1/2, 1]
    let r = intersect_curves(&fold2(), &seg()).unwrap();
    points_are(&r, &[]);
    pieces_are(
        &r,
        &[("0", "1/2", "1/4", "1/2"), ("1/2", "1", "1/2", "1/4")],
    );
}

#[test]
fn a_closed_curve_against_itself() {
    // s = t on [0, 1], and the closing point A(0) = A(1): (0, 1) and (1, 0), transversal
    // (tangents (−12, 12) and (12, 12))
    let r = intersect_curves(&drop(), &drop()).unwrap();
    points_are(&r, &[("0", "1", false), ("1", "0", false)]);
    pieces_are(&r, &[("0", "1", "0", "1")]);
}

#[test]
fn a_loop_against_the_nodal_cubic_it_is_part_of() {
    // drop(s) = nodal(1/4 + s/2): the piece s ∈ [0, 1], t ∈ [1/4, 3/4]; the node again at
    // (0, 3/4) and (1, 1/4), crossing the other branch
    let r = intersect_curves(&drop(), &nodal()).unwrap();
    points_are(&r, &[("0", "3/4", false), ("1", "1/4", false)]);
    pieces_are(&r, &[("0", "1", "1/4", "3/4")]);
    let r = intersect_curves(&nodal(), &drop()).unwrap();
    points_are(&r, &[("1/4", "1", false), ("3/4", "0", false)]);
    pieces_are(&r, &[("1/4", "3/4", "0", "1")]);
}

#[test]
fn two_curves_through_one_point_twice_each() {
    // the nodal cubic and its quarter turn both pass the origin at 1/4 and 3/4: four pairs,
    // the mixed ones tangential (a branch of one is a branch of the other turned by 90°,
    // which is parallel to the other branch)
    let r = intersect_curves(&nodal(), &nodal_rot()).unwrap();
    points_are(
        &r,
        &[
            ("1/4", "1/4", false),
            ("1/4", "3/4", true),
            ("3/4", "1/4", true),
            ("3/4", "3/4", false),
        ],
    );
    pieces_are(&r, &[]);
}
