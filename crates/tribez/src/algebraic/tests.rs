//! Unit tests of the algebraic module; expected values derived by hand in the comments.

use num_bigint::BigInt;
use num_rational::BigRational;

use super::*;

fn q(s: &str) -> BigRational {
    crate::number::parse_rational(s).unwrap()
}

#[test]
fn gcd_and_square_free() {
    // (x − 1)(x + 2) and (x − 1)(x − 3): gcd x − 1
    let a = IntPoly::from_i64(&[-2, 1, 1]);
    let b = IntPoly::from_i64(&[3, -4, 1]);
    assert_eq!(a.gcd(&b), IntPoly::from_i64(&[-1, 1]));
    // 4(x − 1)^3 (2x + 1): square-free part (x − 1)(2x + 1) = 2x^2 − x − 1
    let p = IntPoly::from_i64(&[-1, 1]);
    let p3 = p.mul(&p).mul(&p).mul(&IntPoly::from_i64(&[1, 2]));
    let p3 = IntPoly::new(p3.coeffs().iter().map(|c| c * 4).collect());
    assert_eq!(p3.square_free(), IntPoly::from_i64(&[-1, -1, 2]));
    assert_eq!(
        p3.square_free_factors(),
        vec![
            (IntPoly::from_i64(&[1, 2]), 1),
            (IntPoly::from_i64(&[-1, 1]), 3)
        ]
    );
}

#[test]
fn isolation_counts_and_orders_roots() {
    // (x − 1/4)(x − 1/2)(x − 3/4)·(x^2 − 1/2): roots 1/4, 1/2, 1/√2, 3/4 in [0, 1], −1/√2 out
    let p = IntPoly::from_i64(&[-1, 4])
        .mul(&IntPoly::from_i64(&[-1, 2]))
        .mul(&IntPoly::from_i64(&[-3, 4]))
        .mul(&IntPoly::from_i64(&[-1, 0, 2]));
    let r = RealAlgebraic::roots_in(&p, &q("0"), &q("1")).unwrap();
    assert_eq!(r.len(), 4);
    assert_eq!(r[0].as_rational(), Some(&q("1/4")));
    assert_eq!(r[1].as_rational(), Some(&q("1/2")));
    assert!(r[2].as_root().is_some());
    assert_eq!(r[2].to_f64(), std::f64::consts::FRAC_1_SQRT_2);
    assert_eq!(r[3].as_rational(), Some(&q("3/4")));
    // the irrational root keeps only the factor 2x^2 − 1
    assert_eq!(
        r[2].as_root().unwrap().poly(),
        &IntPoly::from_i64(&[-1, 0, 2])
    );
    // roots at the interval's ends count
    let e = RealAlgebraic::roots_in(&IntPoly::from_i64(&[0, -1, 1]), &q("0"), &q("1")).unwrap();
    assert_eq!(e.len(), 2);
    assert_eq!(e[0].as_rational(), Some(&q("0")));
    assert_eq!(e[1].as_rational(), Some(&q("1")));
}

#[test]
fn close_roots_are_separated() {
    // (3x − 1)(3d x − d − 3), d = 10^30: roots 1/3 and 1/3 + 10^-30
    let d: BigInt = BigInt::from(10).pow(30u32);
    let r1 = IntPoly::from_i64(&[-1, 3]);
    let r2 = IntPoly::new(vec![-(&d + BigInt::from(3)), &d * BigInt::from(3)]); // x = (d + 3)/(3d)
    let p = r1.mul(&r2);
    let r = RealAlgebraic::roots_in(&p, &q("0"), &q("1")).unwrap();
    assert_eq!(r.len(), 2);
    assert_eq!(r[0].as_rational(), Some(&q("1/3")));
    assert_eq!(
        r[1].as_rational(),
        Some(&BigRational::new(
            &d + BigInt::from(3),
            &d * BigInt::from(3)
        ))
    );
}

#[test]
fn comparison_and_signs() {
    let two = RealAlgebraic::roots_in(&IntPoly::from_i64(&[-2, 0, 1]), &q("0"), &q("2")).unwrap();
    let s2 = &two[0];
    // √2 written as a root of x^4 − 4x^2 + 4 − … : x^4 − 2x^2 ·… use (x^2 − 2)(x − 5)
    let other = RealAlgebraic::roots_in(
        &IntPoly::from_i64(&[-2, 0, 1]).mul(&IntPoly::from_i64(&[-5, 1])),
        &q("1"),
        &q("3/2"),
    )
    .unwrap();
    assert_eq!(s2.cmp_exact(&other[0]), std::cmp::Ordering::Equal);
    // ∛3 ≈ 1.44225 > √2 ≈ 1.41421
    let c3 = RealAlgebraic::roots_in(&IntPoly::from_i64(&[-3, 0, 0, 1]), &q("0"), &q("2")).unwrap();
    assert_eq!(s2.cmp_exact(&c3[0]), std::cmp::Ordering::Less);
    assert_eq!(c3[0].cmp_exact(s2), std::cmp::Ordering::Greater);
    // 2 − x^2·… sign of x^2 − 2 at ∛3: 3^(2/3) ≈ 2.08 > 2
    assert!(c3[0].sign_of(&IntPoly::from_i64(&[-2, 0, 1])).is_gt());
    // f32 of √2: 0x1.6a09e6p0 (the nearest float to 1.41421356…)
    assert_eq!(s2.to_f32(), std::f32::consts::SQRT_2);
}

#[test]
fn json_form() {
    let r = RealAlgebraic::roots_in(&IntPoly::from_i64(&[-2, 0, 1]), &q("0"), &q("2")).unwrap();
    let j = r[0].to_json();
    assert_eq!(j["polynomial"], serde_json::json!(["-2", "0", "1"]));
    assert_eq!(j["f64"], "0x1.6a09e667f3bcdp+0");
    // 17 significant digits of 1.41421356237309504…, the trailing zero dropped
    assert_eq!(j["decimal"], "1.414213562373095");
    let lo = q(j["interval"][0].as_str().unwrap());
    let hi = q(j["interval"][1].as_str().unwrap());
    assert!(&lo * &lo < q("2") && &hi * &hi > q("2"));
    let h = RealAlgebraic::rational(q("1/2")).to_json();
    assert_eq!(h["rational"], "1/2");
    assert_eq!(h["decimal"], "0.5");
}

#[test]
fn resultant_of_two_circles_shifted() {
    // f = y^2 + x^2 − 1, g = y^2 + (x − 1)^2 − 1: Res_y = (f − g)^2 = (2x − 1)^2 = 4x^2 − 4x + 1
    let f = BiPoly {
        c: vec![vec![q("-1"), q("0"), q("1")], vec![], vec![q("1")]],
    };
    let g = BiPoly {
        c: vec![vec![q("0"), q("-2"), q("1")], vec![], vec![q("1")]],
    };
    assert_eq!(resultant(&f, &g), vec![q("1"), q("-4"), q("4")]);
}

/// Fast paths against their generic exact paths (issue 13's speed work): the integer Bernstein
/// conversion, the modular gcd shortcut, the interval-filtered sign, Newton refinement,
/// integer resultants and subresultants, and the box filter of the flags.
mod fast_paths {
    use std::cmp::Ordering;

    use num_bigint::BigInt;
    use num_rational::BigRational;
    use proptest::prelude::*;

    use super::super::bivariate::{resultant_generic, subresultant1_generic};
    use super::super::interval::IntBiPoly;
    use super::super::isolate::{bernstein_on, bernstein_on_rational};
    use super::super::system::{flag_vanishes, flag_vanishes_exact};
    use super::*;

    fn poly() -> impl Strategy<Value = IntPoly> {
        prop::collection::vec(-40i64..=40, 2..9).prop_map(|c| IntPoly::from_i64(&c))
    }

    fn rat() -> impl Strategy<Value = BigRational> {
        (-60i64..=60, 1i64..=17).prop_map(|(n, d)| BigRational::new(n.into(), d.into()))
    }

    fn bipoly() -> impl Strategy<Value = BiPoly> {
        prop::collection::vec(prop::collection::vec(rat(), 1..4), 2..4).prop_map(|c| BiPoly { c })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn integer_bernstein_equals_rational(p in poly(), a in rat(), b in rat()) {
            prop_assume!(a < b && !p.is_zero());
            prop_assert_eq!(bernstein_on(&p, &a, &b), bernstein_on_rational(&p, &a, &b));
        }

        #[test]
        fn gcd_shortcut_equals_prs(a in poly(), b in poly(), c in poly()) {
            // a·c and b·c share c (at least)
            let (x, y) = (a.mul(&c), b.mul(&c));
            prop_assume!(!x.is_zero() && !y.is_zero());
            prop_assert_eq!(x.gcd(&y), x.gcd_prs(&y));
            prop_assert_eq!(a.gcd(&b), a.gcd_prs(&b));
        }

        #[test]
        fn filtered_sign_equals_generic(p in poly(), q in poly(), k in poly()) {
            prop_assume!(!p.is_zero() && !q.is_zero());
            let Ok(roots) = RealAlgebraic::roots_in(&p, &BigRational::from_integer((-50).into()), &BigRational::from_integer(50.into())) else {
                return Err(TestCaseError::fail("isolation"));
            };
            for r in &roots {
                prop_assert_eq!(r.sign_of(&q), r.sign_of_generic(&q));
                // a multiple of the root's own polynomial vanishes there
                let v = match r.as_root() { Some(root) => root.poly().mul(&k), None => p.mul(&k) };
                prop_assert_eq!(r.sign_of(&v), r.sign_of_generic(&v));
                if !k.is_zero() {
                    prop_assert_eq!(r.sign_of(&v), Ordering::Equal);
                }
            }
        }

        #[test]
        fn newton_refinement_keeps_the_root(p in poly(), e in 1u32..200) {
            prop_assume!(!p.is_zero());
            let (lo, hi) = (BigRational::from_integer((-50).into()), BigRational::from_integer(50.into()));
            for r in RealAlgebraic::roots_in(&p, &lo, &hi).unwrap() {
                let Some(root) = r.as_root() else { continue };
                let w = BigRational::new(1.into(), BigInt::from(1) << e);
                let (mut a, mut b) = (root.clone(), root.clone());
                a.refine_to(&w);
                b.bisect_to(&w);
                let ((alo, ahi), (blo, bhi)) = (a.interval(), b.interval());
                prop_assert!(ahi - alo <= w && bhi - blo <= w);
                // both enclose the one root: the intervals meet, and p changes sign over each
                prop_assert!(alo <= bhi && blo <= ahi);
                prop_assert_ne!(root.poly().sign_at(alo), root.poly().sign_at(ahi));
                prop_assert_eq!(r.to_f64(), RealAlgebraic::Root(b.clone()).to_f64());
            }
        }

        #[test]
        fn integer_resultants_equal_rational(f in bipoly(), g in bipoly()) {
            prop_assert_eq!(resultant(&f, &g), resultant_generic(&f, &g));
            if f.deg_y() >= 2 && g.deg_y() >= 2 {
                prop_assert_eq!(subresultant1(&f, &g), subresultant1_generic(&f, &g));
            }
        }

        #[test]
        fn box_filter_equals_exact_substitution(f in bipoly(), g in bipoly(), h in bipoly()) {
            let Ok(Solved::Points { solutions, .. }) = solve(&f, &g, &Region::unit_square(), &[]) else {
                return Ok(());
            };
            for s in &solutions {
                // f and g vanish at every solution (a wrongly matched partner would show here),
                // h wherever the exact path says so
                for (k, flag) in [&f, &g, &h].into_iter().enumerate() {
                    let fast = flag_vanishes(s, flag, &IntBiPoly::from_bipoly(flag));
                    prop_assert_eq!(fast, flag_vanishes_exact(s, flag));
                    if k < 2 {
                        prop_assert!(fast);
                    }
                }
            }
        }
    }
}

#[test]
fn solve_finds_points_resolved_from_neither_side() {
    // f = x² + y² − x − y (the circle through (0,0), (1,0), (0,1), (1,1)), g = x·y (the axes):
    // f = g = 0 exactly at (0,0), (0,1), (1,0) (x = 0 gives y² − y = 0, y = 0 gives x² − x = 0).
    // x = 1 has the single partner y = 0 and y = 1 the single partner x = 0, but (0,0) shares
    // its x with (0,1) and its y with (1,0): it is resolved from neither side. The engine once
    // returned the other two points alone; the shear y' = y − λx separates it.
    let f = BiPoly {
        c: vec![vec![q("0"), q("-1"), q("1")], vec![q("-1")], vec![q("1")]],
    };
    let g = BiPoly {
        c: vec![vec![q("0")], vec![q("0"), q("1")]],
    };
    // x + y − 1 vanishes at (0,1) and (1,0), not at (0,0)
    let flag = BiPoly {
        c: vec![vec![q("-1"), q("1")], vec![q("1")]],
    };
    for region in [Region::plane(), Region::unit_square(), Region::triangle()] {
        let Ok(Solved::Points { solutions, .. }) =
            solve(&f, &g, &region, std::slice::from_ref(&flag))
        else {
            panic!("not points");
        };
        let mut pts: Vec<(BigRational, BigRational, bool)> = solutions
            .iter()
            .map(|s| {
                // the partner is consistent: f and g vanish through it, the flag as computed
                assert_eq!(s.sign_of(&f), std::cmp::Ordering::Equal);
                assert_eq!(s.sign_of(&g), std::cmp::Ordering::Equal);
                assert_eq!(s.sign_of(&flag) == std::cmp::Ordering::Equal, s.flags[0]);
                let x = s.x.as_rational().expect("rational").clone();
                let y = s.y.as_rational().expect("rational").clone();
                (x, y, s.flags[0])
            })
            .collect();
        pts.sort();
        assert_eq!(
            pts,
            vec![
                (q("0"), q("0"), false),
                (q("0"), q("1"), true),
                (q("1"), q("0"), true)
            ]
        );
    }
    // Shifted by (2, 0) the point (2, 0) is outside the unit square, and so are (3, 0) and
    // (2, 1); no solution in the square, and nothing to refuse (every pair is excluded).
    let fs = BiPoly {
        // (x − 2)² + y² − (x − 2) − y = x² − 5x + 6 + y² − y
        c: vec![vec![q("6"), q("-5"), q("1")], vec![q("-1")], vec![q("1")]],
    };
    let gs = BiPoly {
        // (x − 2)·y
        c: vec![vec![q("0")], vec![q("-2"), q("1")]],
    };
    match solve(&fs, &gs, &Region::unit_square(), &[]) {
        Ok(Solved::Points { solutions, .. }) => assert!(solutions.is_empty()),
        other => panic!("{other:?}"),
    }
}
