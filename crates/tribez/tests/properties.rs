//! Property tests for the identities of the theory, on random exact data (docs/theory.md §1, §3):
//! de Casteljau equals the Bernstein form; partition of unity; corners interpolate; every edge
//! is the Bézier curve of its boundary control points; affine invariance; the symbolic form
//! evaluates to the same values; the integer evaluator equals rational de Casteljau; the
//! rational blossom is symmetric, the patch on the diagonal and the control points at the corners.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

use tribez::hazmat::exact::{Algorithm, ExactEvaluator, evaluate_rational};
use tribez::hazmat::patch::{BezierPatch, ControlNet};
use tribez::hazmat::rational::RationalPatch;
use tribez::hazmat::simplex::Simplex;
use tribez::hazmat::symbolic::barycentric_form;
use tribez::{hazmat::bernstein, hazmat::casteljau};

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fn rational() -> impl Strategy<Value = BigRational> {
    (-1000i64..=1000, 1i64..=60).prop_map(|(n, d)| q(n, d))
}

/// A random net: simplex dimension m in 1..=3, degree 0..=5, points in R^1..R^3.
fn net() -> impl Strategy<Value = ControlNet<BigRational>> {
    (1usize..=3, 0usize..=5, 1usize..=3).prop_flat_map(|(m, n, d)| {
        let len = Simplex::new(m, n).len() * d;
        proptest::collection::vec(rational(), len)
            .prop_map(move |c| ControlNet::new(Simplex::new(m, n), d, c))
    })
}

/// A random point with m+1 coordinates summing to one (possibly outside the simplex).
fn point(m: usize) -> impl Strategy<Value = Vec<BigRational>> {
    proptest::collection::vec(rational(), m).prop_map(|mut v| {
        let rest = BigRational::one() - v.iter().sum::<BigRational>();
        v.push(rest);
        v
    })
}

fn net_and_point() -> impl Strategy<Value = (ControlNet<BigRational>, Vec<BigRational>)> {
    net().prop_flat_map(|n| {
        let m = n.m();
        (Just(n), point(m))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn casteljau_equals_bernstein((net, u) in net_and_point()) {
        let a = casteljau::evaluate(&net, &u);
        prop_assert_eq!(&a, &bernstein::evaluate(&net, &u));
        let fast = ExactEvaluator::new(&net);
        prop_assert_eq!(&a, &fast.evaluate(&u, Algorithm::Casteljau));
        prop_assert_eq!(&a, &fast.evaluate(&u, Algorithm::Bernstein));
    }

    #[test]
    fn homogeneous_points_need_not_sum_to_one(net in net(), raw in proptest::collection::vec(rational(), 4)) {
        // The fast integer evaluator and rational de Casteljau agree on any (m+1)-tuple.
        let u: Vec<BigRational> = raw.into_iter().take(net.m() + 1).collect();
        prop_assume!(u.len() == net.m() + 1);
        prop_assert_eq!(evaluate_rational(&net, &u, Algorithm::Casteljau), ExactEvaluator::new(&net).evaluate(&u, Algorithm::Bernstein));
    }

    #[test]
    fn partition_of_unity(m in 1usize..=4, n in 0usize..=8, u in point(4)) {
        let u: Vec<BigRational> = {
            // Re-balance a 5-coordinate point to m+1 coordinates summing to one.
            let mut v: Vec<BigRational> = u.into_iter().take(m).collect();
            v.push(BigRational::one() - v.iter().sum::<BigRational>());
            v
        };
        let total: BigRational = bernstein::basis(&Simplex::new(m, n), &u).into_iter().sum();
        prop_assert!(total.is_one());
    }

    #[test]
    fn corners_interpolate(net in net()) {
        let m = net.m();
        for k in 0..=m {
            let mut e = vec![BigRational::zero(); m + 1];
            e[k] = BigRational::one();
            prop_assert_eq!(casteljau::evaluate(&net, &e), net.corner(k).to_vec());
        }
    }

    #[test]
    fn edges_are_bezier_curves((net, t) in (net(), rational())) {
        // On the edge from corner a to corner b, the point (1-t) e_a + t e_b maps to the Bézier
        // curve with control points c_{(n-j) e_a + j e_b}, j = 0..n.
        let m = net.m();
        for a in 0..=m {
            for b in 0..=m {
                if a == b { continue; }
                let mut u = vec![BigRational::zero(); m + 1];
                u[a] = BigRational::one() - &t;
                u[b] = t.clone();
                let curve = net.face(&[a, b]);
                let s = vec![BigRational::one() - &t, t.clone()];
                prop_assert_eq!(casteljau::evaluate(&net, &u), casteljau::evaluate(&curve, &s));
            }
        }
    }

    #[test]
    fn affine_invariance((net, u) in net_and_point(), a in proptest::collection::vec(rational(), 9), b in proptest::collection::vec(rational(), 3)) {
        // x -> A x + b applied to the control points maps the surface point the same way.
        let d = net.dim();
        let map = |p: &[BigRational]| -> Vec<BigRational> {
            (0..d).map(|r| (0..d).map(|c| &a[r * 3 + c] * &p[c]).sum::<BigRational>() + &b[r]).collect()
        };
        let pts: Vec<Vec<BigRational>> = net.points().map(map).collect();
        let moved = ControlNet::from_points(net.m(), net.degree(), &pts);
        prop_assert_eq!(casteljau::evaluate(&moved, &u), map(&casteljau::evaluate(&net, &u)));
    }

    #[test]
    fn symbolic_form_evaluates_to_the_patch((net, u) in net_and_point()) {
        let values: Vec<BigRational> = barycentric_form(&net).iter().map(|p| p.evaluate(&u)).collect();
        prop_assert_eq!(values, casteljau::evaluate(&net, &u));
    }
}

/// A random rational patch (degree 1..=4, non-zero weights of both signs) and n + 1 random
/// barycentric points (n blossom arguments and one more).
fn rational_patch_and_points() -> impl Strategy<Value = (RationalPatch, Vec<Vec<BigRational>>)> {
    (1usize..=3, 1usize..=4, 1usize..=3).prop_flat_map(|(m, n, d)| {
        let len = Simplex::new(m, n).len();
        (
            proptest::collection::vec(rational(), len * d),
            proptest::collection::vec(
                (1i64..=50, 1i64..=9, any::<bool>())
                    .prop_map(|(a, b, s)| q(if s { a } else { -a }, b)),
                len,
            ),
            proptest::collection::vec(point(m), n + 1),
        )
            .prop_map(move |(c, w, pts)| {
                let net = ControlNet::new(Simplex::new(m, n), d, c);
                (RationalPatch::new(BezierPatch::new(net), w), pts)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The rational blossom X[..]/W[..] is symmetric, is the patch on the diagonal, and gives the
    /// control points at the corners: b[e_0^{α_0}, …, e_m^{α_m}] = c_α.
    #[test]
    fn rational_blossom_identities((r, pts) in rational_patch_and_points()) {
        let n = r.patch.net.degree();
        let m = r.patch.net.m();
        let args = &pts[..n];
        let mut reversed = args.to_vec();
        reversed.reverse();
        let mut rotated = args.to_vec();
        rotated.rotate_left(1);
        match r.blossom(args) {
            Ok(b) => {
                prop_assert_eq!(&b, &r.blossom(&reversed).unwrap());
                prop_assert_eq!(&b, &r.blossom(&rotated).unwrap());
            }
            Err(_) => {
                prop_assert!(r.blossom(&reversed).is_err());
                prop_assert!(r.blossom(&rotated).is_err());
            }
        }
        let u = &pts[n];
        let diagonal = vec![u.clone(); n];
        match r.evaluate(u) {
            Ok(p) => prop_assert_eq!(r.blossom(&diagonal).unwrap(), p),
            Err(_) => prop_assert!(r.blossom(&diagonal).is_err()),
        }
        for (alpha, c) in r.patch.net.entries() {
            let corners: Vec<Vec<BigRational>> = (0..=m)
                .flat_map(|k| {
                    let mut e = vec![BigRational::zero(); m + 1];
                    e[k] = BigRational::one();
                    std::iter::repeat_n(e, alpha[k] as usize)
                })
                .collect();
            prop_assert_eq!(r.blossom(&corners).unwrap(), c.to_vec());
        }
    }
}

/// Linear precision at the largest degree a patch file may have (200): the control point of
/// index α being α_0/n makes the patch the first barycentric coordinate, u, exactly (theory §1:
/// Σ C(n;α) λ^α α_0/n = λ_0 (λ_0 + λ_1 + λ_2)^(n−1)). The exact kernel's binomials C(200, k)
/// reach 9·10^58, beyond 128 bits: they must be exact, not wrapped (nor a panic).
#[test]
fn degree_200_reproduces_its_linear_function_exactly() {
    use tribez::{Degree, Patch, SimplexDim, parse_rational};
    let n = 200u32;
    let mut net = Vec::new();
    // canonical order of a triangle: α = (i, j, k) with k the slowest, then j (theory §1)
    for k in 0..=n {
        for j in 0..=n - k {
            let i = n - j - k;
            net.push(vec![
                parse_rational(&format!("{i}/{n}")).expect("a rational"),
            ]);
        }
    }
    let patch = Patch::bezier(SimplexDim(2), Degree(n as usize), net).expect("a patch");
    let q = |s: &str| parse_rational(s).expect("a rational");
    for point in [
        ["1/3", "1/3", "1/3"],
        ["1/7", "2/7", "4/7"],
        ["1", "0", "0"],
    ] {
        let at: Vec<_> = point.iter().map(|s| q(s)).collect();
        let value = patch.evaluate(&at).expect("a value");
        assert_eq!(value, vec![at[0].clone()], "at {point:?}");
    }
}
