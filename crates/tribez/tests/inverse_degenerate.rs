//! `locate` and `ray` where the two equations share a factor (tribez issue 35 §4): the curve of
//! solutions is clipped to the closed triangle (and to τ ≥ 0). Every expected value is derived
//! by hand in the comments (the patches are linear or quadratic).

use num_rational::BigRational;
use tribez::Patch;
use tribez::algebraic::{Hit, Located, RealAlgebraic, locate, ray_hits};
use tribez::parse_rational;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

fn fx(name: &str) -> Patch {
    Patch::from_file(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fixtures/inverse/degenerate")
            .join(name),
    )
    .unwrap()
}

fn r(x: &RealAlgebraic) -> BigRational {
    x.as_rational().expect("rational").clone()
}

fn st(l: &Located) -> (BigRational, BigRational) {
    (r(&l.s), r(&l.t))
}

fn tst(h: &Hit) -> (BigRational, BigRational, BigRational) {
    (h.tau.rational().expect("rational"), r(&h.s), r(&h.t))
}

#[test]
fn a_constant_patch_maps_everything_or_nothing() {
    let c = fx("const.toml");
    // X − 1·W ≡ 0 and Y − 2·W = −1: no parameter maps to (1, 2)
    let found = locate(&c, &[q("1"), q("2")], false).unwrap();
    assert!(!found.infinite && found.points.is_empty() && found.degenerate.is_none());
    // and not anywhere in the plane either
    let found = locate(&c, &[q("1"), q("2")], true).unwrap();
    assert!(!found.infinite && found.points.is_empty());
    // (1, 1): both equations vanish identically, the whole triangle (dimension 2)
    let found = locate(&c, &[q("1"), q("1")], false).unwrap();
    assert!(found.infinite);
    assert_eq!(found.degenerate.as_ref().unwrap().dimension, 2);
}

#[test]
fn a_collinear_patch_is_clipped_to_the_triangle() {
    let p = fx("collinear.toml");
    // x = s + 2t, y = 0: s + 2t = 5 with s, t ≥ 0, s + t ≤ 1 means s + 2t ≤ 2: no point
    let found = locate(&p, &[q("5"), q("0")], false).unwrap();
    assert!(!found.infinite && found.points.is_empty());
    // s + 2t = 2 touches the triangle at its corner (0, 1) only: on the triangle
    // s + 2t = (s + t) + t ≤ 1 + 1, with equality iff s + t = 1 and t = 1
    let found = locate(&p, &[q("2"), q("0")], false).unwrap();
    assert!(!found.infinite);
    let pts: Vec<_> = found.points.iter().map(st).collect();
    assert_eq!(pts, vec![(q("0"), q("1"))]);
    assert!(found.points[0].jacobian_zero); // the Jacobian of a collinear patch is 0
    // s + 2t = 1: the segment from (0, 1/2) (on s = 0) to (1, 0) (on t = 0)
    let found = locate(&p, &[q("1"), q("0")], false).unwrap();
    assert!(found.infinite && found.points.is_empty());
    let d = found.degenerate.unwrap();
    assert_eq!(d.dimension, 1);
    assert_eq!(d.curve, "s + 2t - 1");
    let ends: Vec<_> = d.boundary.iter().map(st).collect();
    assert_eq!(ends, vec![(q("0"), q("1/2")), (q("1"), q("0"))]);
    // (5, 0) anywhere in the plane: the whole line s + 2t = 5
    assert!(locate(&p, &[q("5"), q("0")], true).unwrap().infinite);
    // off the line y = 0: none (the second equation is the non-zero constant −1)
    let found = locate(&p, &[q("1"), q("1")], true).unwrap();
    assert!(!found.infinite && found.points.is_empty());
}

#[test]
fn an_isolated_point_and_a_circle_of_a_folded_patch() {
    let p = fx("circle.toml");
    // (x, y) = (q, 2q), q = (s − 1/4)^2 + (t − 1/4)^2: q = 0 only at (1/4, 1/4)
    let found = locate(&p, &[q("0"), q("0")], false).unwrap();
    assert!(!found.infinite);
    let pts: Vec<_> = found.points.iter().map(st).collect();
    assert_eq!(pts, vec![(q("1/4"), q("1/4"))]);
    // the same in the whole plane
    let found = locate(&p, &[q("0"), q("0")], true).unwrap();
    assert_eq!(found.points.len(), 1);
    assert!(!found.infinite);
    // q = 1/16: the circle of radius 1/4 about (1/4, 1/4); it lies in the triangle (its
    // distance to s + t = 1 is (1/2)/√2 > 1/4) and touches s = 0 at (0, 1/4), t = 0 at (1/4, 0)
    let found = locate(&p, &[q("1/16"), q("1/8")], false).unwrap();
    assert!(found.infinite);
    let d = found.degenerate.unwrap();
    assert_eq!(d.dimension, 1);
    // 16((s − 1/4)^2 + (t − 1/4)^2 − 1/16) = 16s^2 + 16t^2 − 8s − 8t + 1
    assert_eq!(d.curve, "16s^2 + 16t^2 - 8s - 8t + 1");
    let ends: Vec<_> = d.boundary.iter().map(st).collect();
    assert_eq!(ends, vec![(q("0"), q("1/4")), (q("1/4"), q("0"))]);
    // q = 1: radius 1 about (1/4, 1/4): s^2 + t^2 − (s + t)/2 + 1/8 = 1 on the triangle? The
    // largest q on the triangle is at a corner: q(1, 0) = q(0, 1) = 9/16 + 1/16 = 5/8 < 1: none
    let found = locate(&p, &[q("1"), q("2")], false).unwrap();
    assert!(!found.infinite && found.points.is_empty());
}

#[test]
fn rays_in_the_plane_of_a_flat_triangle() {
    let flat = fx("flat.toml");
    let hits = |o: [&str; 3], d: [&str; 3]| ray_hits(&flat, &o.map(q), &d.map(q)).unwrap();
    // from (−1, 2, 0) along x: the line t = 2 misses the triangle (t ≤ 1)
    let h = hits(["-1", "2", "0"], ["1", "0", "0"]);
    assert!(!h.infinite && h.hits.is_empty());
    // from (−1, 1, 0): t = 1 meets the triangle at (s, t) = (0, 1) only; τ = s + 1 = 1
    let h = hits(["-1", "1", "0"], ["1", "0", "0"]);
    assert!(!h.infinite);
    let got: Vec<_> = h.hits.iter().map(tst).collect();
    assert_eq!(got, vec![(q("1"), q("0"), q("1"))]);
    assert!(h.hits[0].touch); // the direction lies in the (flat) tangent plane
    // from (0, 1/2, 0) along −x: s = −τ, so τ ≥ 0 leaves s = 0 only: one hit, τ = 0
    let h = hits(["0", "1/2", "0"], ["-1", "0", "0"]);
    assert!(!h.infinite);
    let got: Vec<_> = h.hits.iter().map(tst).collect();
    assert_eq!(got, vec![(q("0"), q("0"), q("1/2"))]);
    // from (1/4, 1/2, 0) along −x: s = 1/4 − τ on t = 1/2: the piece s ∈ [0, 1/4], ending at
    // (0, 1/2) (τ = 1/4, on s = 0) and (1/4, 1/2) (τ = 0)
    let h = hits(["1/4", "1/2", "0"], ["-1", "0", "0"]);
    assert!(h.infinite && h.hits.is_empty());
    let d = h.degenerate.unwrap();
    assert_eq!(d.curve, "2t - 1");
    let ends: Vec<_> = d.boundary.iter().map(tst).collect();
    assert_eq!(
        ends,
        vec![(q("1/4"), q("0"), q("1/2")), (q("0"), q("1/4"), q("1/2"))]
    );
    // from (−1, 0, 0) along x: the edge t = 0, s = τ − 1 ∈ [0, 1]
    assert!(hits(["-1", "0", "0"], ["1", "0", "0"]).infinite);
    // a ray off the plane still hits once: from (1/4, 1/4, 1) down, τ = 1
    let h = hits(["1/4", "1/4", "1"], ["0", "0", "-1"]);
    assert_eq!(
        h.hits.iter().map(tst).collect::<Vec<_>>(),
        vec![(q("1"), q("1/4"), q("1/4"))]
    );
}

#[test]
fn rays_on_the_parabolic_cylinder() {
    let p = fx("parabolic.toml");
    // (s, t, s^2); the ray (2, −1 + τ, 4) lies on z = x^2 at s = 2, outside the triangle
    let h = ray_hits(&p, &[q("2"), q("-1"), q("4")], &[q("0"), q("1"), q("0")]).unwrap();
    assert!(!h.infinite && h.hits.is_empty());
    // (1/2, −1 + τ, 1/4): s = 1/2, t = τ − 1 ∈ [0, 1/2]: τ from 1 to 3/2
    let h = ray_hits(
        &p,
        &[q("1/2"), q("-1"), q("1/4")],
        &[q("0"), q("1"), q("0")],
    )
    .unwrap();
    assert!(h.infinite && h.hits.is_empty());
    let d = h.degenerate.unwrap();
    assert_eq!(d.curve, "2s - 1");
    let ends: Vec<_> = d.boundary.iter().map(tst).collect();
    assert_eq!(
        ends,
        vec![(q("1"), q("1/2"), q("0")), (q("3/2"), q("1/2"), q("1/2"))]
    );
    // along −y from (1/2, −1, 1/4): t = −1 − τ < 0: no hit
    let h = ray_hits(
        &p,
        &[q("1/2"), q("-1"), q("1/4")],
        &[q("0"), q("-1"), q("0")],
    )
    .unwrap();
    assert!(!h.infinite && h.hits.is_empty());
    // (1, −1 + τ, 1): s = 1, t = τ − 1, and s + t ≤ 1 leaves t = 0: the corner (1, 0), τ = 1
    let h = ray_hits(&p, &[q("1"), q("-1"), q("1")], &[q("0"), q("1"), q("0")]).unwrap();
    assert!(!h.infinite);
    assert_eq!(
        h.hits.iter().map(tst).collect::<Vec<_>>(),
        vec![(q("1"), q("1"), q("0"))]
    );
}
