//! Curve intersections against independent expected values: fixtures/inverse/derive.py (SymPy:
//! resultants, exact real roots, multiplicities, pairs matched at 60 digits) and cases derived
//! by hand below (overlaps, a degenerate curve).

use std::path::PathBuf;

use tribez::Patch;
use tribez::algebraic::{Curve, RealAlgebraic, intersect_curves};

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse")
}

fn curve(name: &str) -> Curve {
    let p = Patch::from_file(dir().join(name)).unwrap();
    Curve::from_patch(&p, name).unwrap()
}

fn q(s: &str) -> tribez::Rational {
    tribez::parse_rational(s).unwrap()
}

fn rational_text(x: &RealAlgebraic) -> Option<String> {
    x.as_rational().map(ToString::to_string)
}

#[test]
fn intersections_match_sympy() {
    let text = std::fs::read_to_string(dir().join("expected.json")).unwrap();
    let cases: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut points = 0;
    for case in cases.as_array().unwrap() {
        let (a, b) = (case["a"].as_str().unwrap(), case["b"].as_str().unwrap());
        let got = intersect_curves(&curve(a), &curve(b)).unwrap();
        if case.get("overlap").is_some() {
            assert!(!got.overlaps.is_empty(), "{a} × {b}: an overlap expected");
            continue;
        }
        let want = case["intersections"].as_array().unwrap();
        assert_eq!(
            got.points.len(),
            want.len(),
            "{a} × {b}: number of intersections"
        );
        for (g, w) in got.points.iter().zip(want) {
            let ctx = format!("{a} × {b} at s = {}", w["s"]);
            let f = |k: &str| w[k].as_str().unwrap().parse::<f64>().unwrap();
            assert_eq!(g.s.to_f64(), f("s"), "{ctx}: s");
            assert_eq!(g.t.to_f64(), f("t"), "{ctx}: t");
            assert_eq!(
                rational_text(&g.s).as_deref(),
                w["s_rational"].as_str(),
                "{ctx}"
            );
            assert_eq!(
                rational_text(&g.t).as_deref(),
                w["t_rational"].as_str(),
                "{ctx}"
            );
            assert_eq!(
                g.multiplicity,
                Some(w["multiplicity"].as_u64().unwrap() as usize),
                "{ctx}"
            );
            assert_eq!(
                g.tangential,
                w["tangential"].as_bool().unwrap(),
                "{ctx}: tangency"
            );
            points += 1;
        }
    }
    assert!(points >= 25, "only {points} intersections checked");
}

#[test]
fn an_overlap_is_reported_with_its_parameter_intervals() {
    // cubic_a over s ∈ [1/4, 3/4], reversed (by its blossom): s from 1/4 to 3/4 is t from 1 to 0
    let got = intersect_curves(
        &curve("cubic_a.toml"),
        &curve("cubic_a_reversed_shifted.toml"),
    )
    .unwrap();
    assert!(got.points.is_empty());
    assert_eq!(got.overlaps.len(), 1);
    let o = &got.overlaps[0];
    let r = |x: &RealAlgebraic| x.as_rational().cloned().unwrap();
    assert_eq!([r(&o.s[0]), r(&o.s[1])], [q("1/4"), q("3/4")]);
    assert_eq!([r(&o.t[0]), r(&o.t[1])], [q("1"), q("0")]);
    // two collinear segments: (0,0)–(2,2) and (1,1)–(3,3) share s ∈ [1/2, 1], t ∈ [0, 1/2]
    let seg = |a: [&str; 2], b: [&str; 2]| Curve {
        points: vec![a.map(q), b.map(q)],
        weights: None,
    };
    let got = intersect_curves(&seg(["0", "0"], ["2", "2"]), &seg(["1", "1"], ["3", "3"])).unwrap();
    assert_eq!(got.overlaps.len(), 1);
    let o = &got.overlaps[0];
    assert_eq!([r(&o.s[0]), r(&o.s[1])], [q("1/2"), q("1")]);
    assert_eq!([r(&o.t[0]), r(&o.t[1])], [q("0"), q("1/2")]);
    // segments on one line that only touch: (0,0)–(1,1) and (1,1)–(2,2) meet at s = 1, t = 0
    let got = intersect_curves(&seg(["0", "0"], ["1", "1"]), &seg(["1", "1"], ["2", "2"])).unwrap();
    assert!(got.overlaps.is_empty());
    assert_eq!(got.points.len(), 1);
    assert_eq!(got.points[0].s.as_rational(), Some(&q("1")));
    assert_eq!(got.points[0].t.as_rational(), Some(&q("0")));
}

#[test]
fn a_degenerate_curve_is_a_point() {
    // every control point (1/2, 1/4): the parabola passes there at t = 1/2, for every s
    let p = Curve {
        points: vec![[q("1/2"), q("1/4")]; 3],
        weights: None,
    };
    let got = intersect_curves(&p, &curve("parabola.toml")).unwrap();
    assert_eq!(got.overlaps.len(), 1);
    let o = &got.overlaps[0];
    assert_eq!(o.s[0].as_rational(), Some(&q("0")));
    assert_eq!(o.s[1].as_rational(), Some(&q("1")));
    assert_eq!(o.t[0].as_rational(), Some(&q("1/2")));
    // a point off the curve: nothing
    let off = Curve {
        points: vec![[q("1/2"), q("1/3")]; 2],
        weights: None,
    };
    let got = intersect_curves(&curve("parabola.toml"), &off).unwrap();
    assert!(got.points.is_empty() && got.overlaps.is_empty());
}

#[test]
fn wrong_shapes_and_caps_are_typed_errors() {
    use tribez::algebraic::AlgebraicError;
    let tri = Patch::from_file(dir().join("../finn_day30.toml")).unwrap();
    assert!(matches!(
        Curve::from_patch(&tri, "A"),
        Err(AlgebraicError::Shape(_))
    ));
    let big = Curve {
        points: vec![[q("0"), q("0")]; 14],
        weights: None,
    };
    assert!(matches!(
        big.check("A"),
        Err(AlgebraicError::DegreeTooHigh {
            degree: 13,
            max: 12,
            ..
        })
    ));
    let huge = Curve {
        points: vec![
            [q("0"), q("0")],
            [
                tribez::Rational::from_integer(num_bigint_two_pow(5000)),
                q("1"),
            ],
        ],
        weights: None,
    };
    assert!(matches!(
        huge.check("A"),
        Err(AlgebraicError::CoefficientTooLarge {
            bits: 5001,
            max: 4096,
            ..
        })
    ));
}

fn num_bigint_two_pow(k: u32) -> tribez::hazmat::number::BigInt {
    tribez::hazmat::number::BigInt::from(1) << k
}

#[test]
fn locate_and_ray_match_sympy() {
    use tribez::algebraic::{locate, ray_hits};
    let text = std::fs::read_to_string(dir().join("expected_surfaces.json")).unwrap();
    let cases: serde_json::Value = serde_json::from_str(&text).unwrap();
    let nums = |v: &serde_json::Value| -> Vec<tribez::Rational> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| q(x.as_str().unwrap()))
            .collect()
    };
    let f = |v: &serde_json::Value| v.as_str().unwrap().parse::<f64>().unwrap();
    let mut checked = 0;
    for case in cases.as_array().unwrap() {
        let name = case["patch"].as_str().unwrap();
        let patch = Patch::from_file(dir().join(name)).unwrap();
        if case["op"] == "locate" {
            let p = nums(&case["point"]);
            let got = locate(&patch, &[p[0].clone(), p[1].clone()], false).unwrap();
            let want = case["parameters"].as_array().unwrap();
            assert_eq!(got.points.len(), want.len(), "{name} {:?}", case["point"]);
            for (g, w) in got.points.iter().zip(want) {
                assert_eq!(g.s.to_f64(), f(&w["s"]), "{name} {:?}: s", case["point"]);
                assert_eq!(g.t.to_f64(), f(&w["t"]), "{name} {:?}: t", case["point"]);
                assert_eq!(g.jacobian_zero, w["jacobian_zero"].as_bool().unwrap());
                checked += 1;
            }
        } else {
            let o = nums(&case["origin"]);
            let d = nums(&case["direction"]);
            let got = ray_hits(
                &patch,
                &[o[0].clone(), o[1].clone(), o[2].clone()],
                &[d[0].clone(), d[1].clone(), d[2].clone()],
            )
            .unwrap();
            let want = case["hits"].as_array().unwrap();
            let ctx = format!("{name} {:?} {:?}", case["origin"], case["direction"]);
            assert_eq!(got.hits.len(), want.len(), "{ctx}");
            for (g, w) in got.hits.iter().zip(want) {
                assert_eq!(g.s.to_f64(), f(&w["s"]), "{ctx}: s");
                assert_eq!(g.t.to_f64(), f(&w["t"]), "{ctx}: t");
                assert_eq!(g.tau.to_f64(), f(&w["tau"]), "{ctx}: τ");
                assert_eq!(g.touch, w["touch"].as_bool().unwrap(), "{ctx}: touch");
                checked += 1;
            }
        }
    }
    assert!(checked >= 15, "only {checked} checked");
}

#[test]
fn locate_and_ray_reject_wrong_shapes() {
    use tribez::algebraic::{AlgebraicError, locate, ray_hits};
    let curve = Patch::from_file(dir().join("parabola.toml")).unwrap();
    assert!(matches!(
        locate(&curve, &[q("0"), q("0")], false),
        Err(AlgebraicError::Shape(_))
    ));
    let dome = Patch::from_file(dir().join("dome.toml")).unwrap();
    // a patch in ℝ³ is not planar
    assert!(matches!(
        locate(&dome, &[q("0"), q("0")], false),
        Err(AlgebraicError::Shape(_))
    ));
    let z = [q("0"), q("0"), q("0")];
    assert!(matches!(
        ray_hits(&dome, &z, &z),
        Err(AlgebraicError::Shape(_))
    ));
    // a flat triangle and a ray in its plane along an edge: infinitely many hits
    let flat = Patch::from_toml(
        "degree = 1\n[control_points]\n\"1,0,0\" = [0, 0, 0]\n\"0,1,0\" = [1, 0, 0]\n\"0,0,1\" = [0, 1, 0]\n",
    )
    .unwrap();
    let r = ray_hits(&flat, &[q("-1"), q("0"), q("0")], &[q("1"), q("0"), q("0")]).unwrap();
    assert!(r.infinite);
}
