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
