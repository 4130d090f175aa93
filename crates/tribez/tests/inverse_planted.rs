//! `locate` never leaves out a preimage: random planar quadratic patches built to map three
//! chosen parameter points to the same point, in the arrangement that once lost one of them.
//!
//! The points are `P0 = (s0, t0)`, `P1 = (s0, t1)`, `P2 = (s1, t0)`: `P0` shares its `s` with
//! `P1` and its `t` with `P2`, so neither unknown alone separates the three. Every quadratic
//! that vanishes at all three is `a(s − s0)(s − s1) + b(t − t0)(t − t1) + c(s − s0)(t − t0)`
//! (each product vanishes at each point, by inspection; the conditions are three and the
//! quadratics six, so these three products span them). The patch is `(f, g) + (x0, y0)` for two
//! such quadratics `f`, `g`; it maps `P0`, `P1`, `P2` to `(x0, y0)`. Its control points are the
//! blossoms of `f` and `g` at the vertices `(0, 0)`, `(1, 0)`, `(0, 1)`, computed here from the
//! power form (the blossom of `s²` is `s1·s2`, of `s·t` is `(s1·t2 + s2·t1)/2`, of `s` is
//! `(s1 + s2)/2`). What `locate` returns is checked against the plant: all three points are
//! there, every rational point it returns maps to `(x0, y0)` exactly, and there are at most
//! four (Bézout: two conics meet in at most four points unless they share a component).

use proptest::prelude::*;
use tribez::algebraic::locate;
use tribez::{Degree, Patch, Rational, SimplexDim};

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// `c0 + c1 s + c2 t + c3 s² + c4 st + c5 t²`.
type Quadratic = [Rational; 6];

/// `(s − a)(s − b)`, `(t − a)(t − b)`, `(s − a)(t − b)` in the power form.
fn ss(a: &Rational, b: &Rational) -> Quadratic {
    let z = r(0, 1);
    [a * b, -(a + b), z.clone(), r(1, 1), z.clone(), z]
}
fn tt(a: &Rational, b: &Rational) -> Quadratic {
    let z = r(0, 1);
    [a * b, z.clone(), -(a + b), z.clone(), z, r(1, 1)]
}
fn st(a: &Rational, b: &Rational) -> Quadratic {
    let z = r(0, 1);
    [a * b, -b.clone(), -a.clone(), z.clone(), r(1, 1), z]
}

fn combine(k: &[Rational; 3], q: &[Quadratic; 3]) -> Quadratic {
    std::array::from_fn(|i| &k[0] * &q[0][i] + &k[1] * &q[1][i] + &k[2] * &q[2][i])
}

fn value(q: &Quadratic, s: &Rational, t: &Rational) -> Rational {
    &q[0] + &q[1] * s + &q[2] * t + &q[3] * s * s + &q[4] * s * t + &q[5] * t * t
}

/// The blossom at `(s1, t1)`, `(s2, t2)`.
fn blossom(q: &Quadratic, p1: (&Rational, &Rational), p2: (&Rational, &Rational)) -> Rational {
    let half = r(1, 2);
    let ((s1, t1), (s2, t2)) = (p1, p2);
    &q[0]
        + &q[1] * (s1 + s2) * &half
        + &q[2] * (t1 + t2) * &half
        + &q[3] * s1 * s2
        + &q[4] * (s1 * t2 + s2 * t1) * &half
        + &q[5] * t1 * t2
}

fn small() -> impl Strategy<Value = Rational> {
    (-6i64..=6, 1i64..=4).prop_map(|(n, d)| r(n, d))
}

fn coordinate() -> impl Strategy<Value = Rational> {
    (0i64..=8).prop_map(|n| r(n, 8))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn three_preimages_sharing_their_lines_are_all_found(
        s0 in coordinate(), s1 in coordinate(), t0 in coordinate(), t1 in coordinate(),
        kf in [small(), small(), small()], kg in [small(), small(), small()],
        x0 in small(), y0 in small(),
    ) {
        // three distinct points in the closed triangle
        prop_assume!(s0 != s1 && t0 != t1);
        for (s, t) in [(&s0, &t0), (&s0, &t1), (&s1, &t0)] {
            prop_assume!(s + t <= r(1, 1));
        }
        let basis = [ss(&s0, &s1), tt(&t0, &t1), st(&s0, &t0)];
        let (f, g) = (combine(&kf, &basis), combine(&kg, &basis));
        // f and g independent (otherwise a whole conic maps to the point)
        let cross: Vec<Rational> = (0..3).map(|i| &kf[i] * &kg[(i + 1) % 3] - &kf[(i + 1) % 3] * &kg[i]).collect();
        prop_assume!(cross.iter().any(|c| *c != r(0, 1)));
        let (z, one) = (r(0, 1), r(1, 1));
        let vertex = [(&z, &z), (&one, &z), (&z, &one)];
        // canonical order of degree 2 over the triangle: 200, 110, 020, 101, 011, 002
        let net: Vec<Vec<Rational>> = [(0, 0), (0, 1), (1, 1), (0, 2), (1, 2), (2, 2)]
            .iter()
            .map(|&(a, b)| {
                vec![
                    blossom(&f, vertex[a], vertex[b]) + &x0,
                    blossom(&g, vertex[a], vertex[b]) + &y0,
                ]
            })
            .collect();
        let patch = Patch::bezier(SimplexDim(2), Degree(2), net).unwrap();
        // the patch is (f, g) + (x0, y0): check at the planted points through the library's own
        // evaluation, with (λ0, λ1, λ2) = (1 − s − t, s, t)
        for (s, t) in [(&s0, &t0), (&s0, &t1), (&s1, &t0)] {
            let p = patch.evaluate(&[&one - s - t, s.clone(), t.clone()]).unwrap();
            prop_assert_eq!(&p, &vec![&value(&f, s, t) + &x0, &value(&g, s, t) + &y0]);
        }
        let found = match locate(&patch, &[x0.clone(), y0.clone()], false) {
            Ok(found) => found,
            // a refusal is honest (never a wrong answer); none is expected here
            Err(e) => return Err(TestCaseError::fail(format!("refused: {e}"))),
        };
        prop_assume!(!found.infinite);
        prop_assert!(found.points.len() <= 4, "{} points", found.points.len());
        let rational: Vec<(Rational, Rational)> = found
            .points
            .iter()
            .filter_map(|p| Some((p.s.as_rational()?.clone(), p.t.as_rational()?.clone())))
            .collect();
        for (s, t) in &rational {
            prop_assert_eq!(value(&f, s, t), r(0, 1), "({}, {}) is not a preimage", s, t);
            prop_assert_eq!(value(&g, s, t), r(0, 1), "({}, {}) is not a preimage", s, t);
        }
        for (s, t) in [(&s0, &t0), (&s0, &t1), (&s1, &t0)] {
            prop_assert!(
                rational.iter().any(|(a, b)| a == s && b == t),
                "the preimage ({}, {}) is missing from {:?}", s, t, rational
            );
        }
    }
}
