//! Inverse problems on triangle patches (docs/theory.md §16.6): the parameters of a planar patch
//! that map to a point ([`locate`]) and the hits of a ray on a patch in ℝ³ ([`ray_hits`]).
//!
//! Parameters: a point of the triangle is `(λ0, λ1, λ2) = (1 − s − t, s, t)` (the multi-index
//! `α` weighs `λ0^α0 λ1^α1 λ2^α2`, so the control point `"n,0,0"` is the corner `s = t = 0`, as
//! in the Python package `bezier`'s `Triangle`).

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::bivariate::BiPoly;
use super::clip::{Clipped, bipoly_text, solve_clipped};
use super::system::{Expr, Region, Solution};
use super::{AlgebraicError, MAX_PATCH_DEGREE, RealAlgebraic, check_input};
use crate::any_patch::AnyPatch;
use crate::patch_type::Patch;

type Q = BigRational;

fn q(k: i64) -> Q {
    Q::from_integer(BigInt::from(k))
}

fn bi_mul(a: &BiPoly, b: &BiPoly) -> BiPoly {
    if a.c.is_empty() || b.c.is_empty() {
        return BiPoly::default();
    }
    let mut c = vec![Vec::new(); a.c.len() + b.c.len() - 1];
    for (j, pa) in a.c.iter().enumerate() {
        for (k, pb) in b.c.iter().enumerate() {
            let prod = super::bivariate::mul(pa, pb);
            c[j + k] = super::bivariate::add(&c[j + k], &prod);
        }
    }
    BiPoly { c }
}

fn bi_add(a: &BiPoly, b: &BiPoly) -> BiPoly {
    let n = a.c.len().max(b.c.len());
    BiPoly {
        c: (0..n)
            .map(|j| {
                super::bivariate::add(
                    a.c.get(j).map_or(&[][..], |v| v),
                    b.c.get(j).map_or(&[][..], |v| v),
                )
            })
            .collect(),
    }
}

fn bi_scale(a: &BiPoly, k: &Q) -> BiPoly {
    BiPoly {
        c: a.c
            .iter()
            .map(|p| p.iter().map(|x| x * k).collect())
            .collect(),
    }
}

fn bi_const(k: Q) -> BiPoly {
    BiPoly { c: vec![vec![k]] }
}

/// `∂/∂x` (the coefficient variable).
fn bi_dx(a: &BiPoly) -> BiPoly {
    BiPoly {
        c: a.c
            .iter()
            .map(|p| {
                p.iter()
                    .enumerate()
                    .skip(1)
                    .map(|(i, x)| x * q(i as i64))
                    .collect()
            })
            .collect(),
    }
}

/// `∂/∂y`.
fn bi_dy(a: &BiPoly) -> BiPoly {
    BiPoly {
        c: a.c
            .iter()
            .enumerate()
            .skip(1)
            .map(|(j, p)| p.iter().map(|x| x * q(j as i64)).collect())
            .collect(),
    }
}

fn factorial(n: u32) -> BigInt {
    (1..=n).fold(BigInt::one(), |f, k| f * BigInt::from(k))
}

/// `Σ_α c_α · n!/(α0! α1! α2!) · (1 − x − y)^α0 x^α1 y^α2` for the entries `(α, c_α)`.
fn bernstein(entries: &[(Vec<u32>, Q)]) -> BiPoly {
    let one_minus = BiPoly {
        c: vec![vec![q(1), q(-1)], vec![q(-1)]],
    };
    let n: u32 = entries.first().map_or(0, |(a, _)| a.iter().sum());
    let mut powers = vec![bi_const(q(1))];
    for _ in 0..n {
        // invariant: `powers` starts with one entry and only grows
        let next = bi_mul(powers.last().expect("non-empty"), &one_minus);
        powers.push(next);
    }
    let mut out = BiPoly::default();
    for (alpha, c) in entries {
        if c.is_zero() {
            continue;
        }
        let coef = Q::from_integer(
            factorial(n) / (factorial(alpha[0]) * factorial(alpha[1]) * factorial(alpha[2])),
        ) * c;
        // x^α1 y^α2
        let mut mono = BiPoly {
            c: vec![Vec::new(); alpha[2] as usize + 1],
        };
        let mut xs = vec![Q::zero(); alpha[1] as usize + 1];
        xs[alpha[1] as usize] = q(1);
        mono.c[alpha[2] as usize] = xs;
        out = bi_add(
            &out,
            &bi_scale(&bi_mul(&powers[alpha[0] as usize], &mono), &coef),
        );
    }
    out
}

/// The homogeneous coordinates `(X_1, …, X_d, W)` of a triangle patch as polynomials in
/// `(x, y) = (s, t)`; a functional patch as its graph `(x, y, f)` over its domain.
fn homogeneous(p: &Patch, which: &str, d_expected: usize) -> Result<Vec<BiPoly>, AlgebraicError> {
    let shape = p.shape();
    let functional = matches!(p.as_any(), AnyPatch::Functional(_));
    let d = if functional { 3 } else { shape.dimension };
    if shape.simplex_dim != 2 || d != d_expected {
        return Err(AlgebraicError::Shape(format!(
            "{which} must be a triangle patch (m = 2) with points in ℝ^{d_expected}, not one with m = {}, d = {}",
            shape.simplex_dim, shape.dimension
        )));
    }
    if shape.degree > MAX_PATCH_DEGREE {
        return Err(AlgebraicError::DegreeTooHigh {
            what: "a patch",
            degree: shape.degree,
            max: MAX_PATCH_DEGREE,
        });
    }
    let (net, weights) = match p.as_any() {
        AnyPatch::Bezier(b) | AnyPatch::Functional(b) => (b, None),
        AnyPatch::Rational(r) => (&r.patch, Some(&r.weights)),
        AnyPatch::SPatch(_) => {
            return Err(AlgebraicError::Shape(format!(
                "{which} must be a Bézier, rational or functional triangle patch, not an S-patch"
            )));
        }
    };
    let entries: Vec<(Vec<u32>, Vec<Q>)> = net
        .net
        .entries()
        .map(|(a, c)| (a.to_vec(), c.to_vec()))
        .collect();
    for (_, c) in &entries {
        for x in c {
            check_input("a control point", x)?;
        }
    }
    let w: Vec<Q> = match weights {
        Some(w) => {
            for x in w {
                check_input("a weight", x)?;
            }
            w.clone()
        }
        None => vec![q(1); entries.len()],
    };
    let comp = |k: usize| -> BiPoly {
        bernstein(
            &entries
                .iter()
                .zip(&w)
                .map(|((a, c), w)| (a.clone(), &c[k] * w))
                .collect::<Vec<_>>(),
        )
    };
    let mut out: Vec<BiPoly> = Vec::new();
    if functional {
        let dom = net.domain_or_reference();
        let [v0, v1, v2] = [0, 1, 2].map(|i| &dom.vertices()[i]);
        for k in 0..2 {
            // v0 + x (v1 − v0) + y (v2 − v0)
            out.push(BiPoly {
                c: vec![vec![v0[k].clone(), &v1[k] - &v0[k]], vec![&v2[k] - &v0[k]]],
            });
        }
        out.push(comp(0));
    } else {
        for k in 0..shape.dimension {
            out.push(comp(k));
        }
    }
    out.push(bernstein(
        &entries
            .iter()
            .zip(&w)
            .map(|((a, _), w)| (a.clone(), w.clone()))
            .collect::<Vec<_>>(),
    ));
    Ok(out)
}

/// A parameter point found by [`locate`].
#[derive(Clone, Debug)]
pub struct Located {
    /// `s = λ1`.
    pub s: RealAlgebraic,
    /// `t = λ2`.
    pub t: RealAlgebraic,
    /// `λ0 = 1 − s − t`.
    pub lambda0: Expr,
    /// Does the Jacobian `∂(x, y)/∂(s, t)` vanish there?
    pub jacobian_zero: bool,
    /// Multiplicity as a root of the resultant.
    pub multiplicity: usize,
}

/// A solution set that is not a finite set of points: the two equations share a factor, and
/// what of its zero set lies in the region has positive length (or area). See
/// docs/theory.md §16.7.
#[derive(Clone, Debug)]
pub struct Degenerate<T> {
    /// `2`: every parameter point of the region is a solution (both equations vanish
    /// identically: a constant patch at the point); `1`: pieces of positive length of the curve
    /// [`Degenerate::curve`].
    pub dimension: usize,
    /// The curve `h(s, t) = 0` the pieces lie on (dimension 1): the common factor of the two
    /// equations, square-free, integer coefficients, as text in `s` and `t` (empty for
    /// dimension 2).
    pub curve: String,
    /// The points of the curve in the region that lie on the region's boundary (an edge of the
    /// closed triangle; for a ray, also `τ = 0`): where its pieces end, and where it touches
    /// the boundary; by `s`, then `t`, exactly (multiplicity 0).
    pub boundary: Vec<T>,
}

/// What [`locate`] found.
#[derive(Clone, Debug)]
pub struct Locations {
    /// The parameter points, by increasing `s`, then `t` (with a curve of solutions: the
    /// isolated solutions off it).
    pub points: Vec<Located>,
    /// A piece of positive length of a curve of parameters (or the whole triangle) maps to
    /// the point: [`Locations::degenerate`] says which.
    pub infinite: bool,
    /// The solutions that are not isolated points, when there are such.
    pub degenerate: Option<Degenerate<Located>>,
}

/// `∂(P/W)` numerators: `(X_u W − X W_u)` for each coordinate, for `∂/∂x` and `∂/∂y`.
fn tangents(h: &[BiPoly]) -> [Vec<BiPoly>; 2] {
    // invariant: the homogeneous form always ends with the weight W (a polynomial patch has W = 1)
    let w = h.last().expect("W");
    let d = h.len() - 1;
    let part = |dv: &dyn Fn(&BiPoly) -> BiPoly| -> Vec<BiPoly> {
        (0..d)
            .map(|k| {
                bi_add(
                    &bi_mul(&dv(&h[k]), w),
                    &bi_scale(&bi_mul(&h[k], &dv(w)), &q(-1)),
                )
            })
            .collect()
    };
    [part(&bi_dx), part(&bi_dy)]
}

/// Does [`locate`] take `p` (a planar Bézier or rational triangle patch within the caps)? What
/// a batch of locate rows checks once, before its first row.
pub fn check_locate_patch(p: &Patch) -> Result<(), AlgebraicError> {
    if matches!(p.as_any(), AnyPatch::Functional(_)) {
        return Err(AlgebraicError::Shape(
            "locate takes a planar parametric patch (m = 2, d = 2), not a functional patch".into(),
        ));
    }
    homogeneous(p, "the patch", 2).map(|_| ())
}

/// Does [`ray_hits`] take `p` (a triangle patch in ℝ³ or a functional patch within the caps)?
pub fn check_ray_patch(p: &Patch) -> Result<(), AlgebraicError> {
    homogeneous(p, "the patch", 3).map(|_| ())
}

/// Every parameter point `(s, t)` of the closed triangle (of the whole plane with `anywhere`)
/// that the planar patch `p` (`m = 2`, `d = 2`; Bézier or rational, degree at most
/// [`MAX_PATCH_DEGREE`]) maps to `point`, exactly.
///
/// ```
/// use tribez::{Patch, parse_rational};
/// use tribez::algebraic::locate;
/// let q = |s: &str| parse_rational(s).unwrap();
/// // the linear patch with corners (0,0), (1,0), (0,1): (x, y) ↦ s = x, t = y
/// let p = Patch::from_toml("degree = 1\n[control_points]\n\"1,0,0\" = [0, 0]\n\"0,1,0\" = [1, 0]\n\"0,0,1\" = [0, 1]\n").unwrap();
/// let found = locate(&p, &[q("1/4"), q("1/2")], false).unwrap();
/// assert_eq!(found.points.len(), 1);
/// assert_eq!(found.points[0].s.as_rational(), Some(&q("1/4")));
/// assert_eq!(found.points[0].t.as_rational(), Some(&q("1/2")));
/// ```
pub fn locate(p: &Patch, point: &[Q; 2], anywhere: bool) -> Result<Locations, AlgebraicError> {
    if matches!(p.as_any(), AnyPatch::Functional(_)) {
        return Err(AlgebraicError::Shape(
            "locate takes a planar parametric patch (m = 2, d = 2), not a functional patch".into(),
        ));
    }
    check_input("the point", &point[0])?;
    check_input("the point", &point[1])?;
    let h = homogeneous(p, "the patch", 2)?;
    let w = &h[2];
    let f1 = bi_add(&h[0], &bi_scale(w, &-point[0].clone()));
    let f2 = bi_add(&h[1], &bi_scale(w, &-point[1].clone()));
    let [dx, dy] = tangents(&h);
    let jac = bi_add(
        &bi_mul(&dx[0], &dy[1]),
        &bi_scale(&bi_mul(&dx[1], &dy[0]), &q(-1)),
    );
    let region = if anywhere {
        Region::plane()
    } else {
        Region::triangle()
    };
    let solved = solve_clipped(&f1, &f2, &region, &[], &[jac])?;
    let one_minus = BiPoly {
        c: vec![vec![q(1), q(-1)], vec![q(-1)]],
    };
    let located = |sol: Solution| Located {
        lambda0: sol.ratio(&one_minus, &bi_const(q(1))),
        jacobian_zero: sol.flags[0],
        multiplicity: sol.multiplicity,
        s: sol.x,
        t: sol.y,
    };
    let (solutions, degenerate) = match solved {
        Clipped::Points(s) => (s, None),
        Clipped::Region => (
            Vec::new(),
            Some(Degenerate {
                dimension: 2,
                curve: String::new(),
                boundary: Vec::new(),
            }),
        ),
        Clipped::Curve {
            curve,
            boundary,
            points,
        } => (
            points,
            Some(Degenerate {
                dimension: 1,
                curve: bipoly_text(&curve, "s", "t"),
                boundary: boundary.into_iter().map(located).collect(),
            }),
        ),
    };
    let mut points: Vec<Located> = solutions.into_iter().map(located).collect();
    points.sort_by(|a, b| a.s.cmp_exact(&b.s).then_with(|| a.t.cmp_exact(&b.t)));
    Ok(Locations {
        points,
        infinite: degenerate.is_some(),
        degenerate,
    })
}

/// A hit of a ray on a patch.
#[derive(Clone, Debug)]
pub struct Hit {
    /// The ray parameter `τ ≥ 0` (the point is `origin + τ·direction`).
    pub tau: Expr,
    /// `s = λ1`.
    pub s: RealAlgebraic,
    /// `t = λ2`.
    pub t: RealAlgebraic,
    /// `λ0 = 1 − s − t`.
    pub lambda0: Expr,
    /// Does the ray touch the surface (its direction lies in the tangent plane) rather than
    /// cross it?
    pub touch: bool,
    /// Multiplicity as a root of the resultant (0 for a point of a curve of solutions).
    pub multiplicity: usize,
}

/// What [`ray_hits`] found.
#[derive(Clone, Debug)]
pub struct RayHits {
    /// The hits with `τ ≥ 0`, in order of `τ` (the first is the first hit; with a curve of
    /// hits, the isolated hits off it).
    pub hits: Vec<Hit>,
    /// The ray runs along the surface over a piece of positive length with `τ ≥ 0`
    /// (infinitely many hits): [`RayHits::degenerate`] says where.
    pub infinite: bool,
    /// The hits that are not isolated points, when there are such.
    pub degenerate: Option<Degenerate<Hit>>,
}

/// Compare two ray parameters exactly when one is rational; otherwise by enclosures narrowed
/// until they separate (two hits at the same `τ` are the same point of space, where the surface
/// meets itself: after 2^-400 they are taken as equal).
fn cmp_tau(a: &Expr, b: &Expr) -> Ordering {
    if let Some(r) = b.rational() {
        return a.cmp_rational(&r);
    }
    if let Some(r) = a.rational() {
        return b.cmp_rational(&r).reverse();
    }
    let mut w = q(1) / q(1 << 20);
    for _ in 0..20 {
        let (alo, ahi) = a.enclosure(&w);
        let (blo, bhi) = b.enclosure(&w);
        if ahi < blo {
            return Ordering::Less;
        }
        if bhi < alo {
            return Ordering::Greater;
        }
        w /= q(1 << 20);
    }
    Ordering::Equal
}

/// Every hit `τ ≥ 0` of the ray `origin + τ·direction` on the patch `p` over its closed
/// triangle: a Bézier or rational patch with points in ℝ³, or a functional patch (its graph).
///
/// The ray is cut by two planes through it, `n_i·(P − o) = 0` with `n_i ⊥ direction`; their
/// solutions `(s, t)` in the triangle are found exactly (§16.5), and `τ = (P_k − o_k)/d_k` for a
/// coordinate `k` with `d_k ≠ 0`. The ray *touches* where `det(P_s, P_t, d) = 0`.
///
/// ```
/// use tribez::{Patch, parse_rational};
/// use tribez::algebraic::ray_hits;
/// let q = |s: &str| parse_rational(s).unwrap();
/// // the flat triangle z = 0 with corners (0,0,0), (1,0,0), (0,1,0); a ray down from (1/4,1/4,1)
/// let p = Patch::from_toml("degree = 1\n[control_points]\n\"1,0,0\" = [0, 0, 0]\n\"0,1,0\" = [1, 0, 0]\n\"0,0,1\" = [0, 1, 0]\n").unwrap();
/// let r = ray_hits(&p, &[q("1/4"), q("1/4"), q("1")], &[q("0"), q("0"), q("-1")]).unwrap();
/// assert_eq!(r.hits.len(), 1);
/// assert_eq!(r.hits[0].tau.rational(), Some(q("1")));
/// assert!(!r.hits[0].touch);
/// ```
pub fn ray_hits(p: &Patch, origin: &[Q; 3], direction: &[Q; 3]) -> Result<RayHits, AlgebraicError> {
    for x in origin.iter().chain(direction) {
        check_input("the ray", x)?;
    }
    let Some(k) = direction.iter().position(|x| !x.is_zero()) else {
        return Err(AlgebraicError::Shape("the ray's direction is zero".into()));
    };
    let h = homogeneous(p, "the patch", 3)?;
    let w = &h[3];
    let rel: Vec<BiPoly> = (0..3)
        .map(|i| bi_add(&h[i], &bi_scale(w, &-origin[i].clone())))
        .collect();
    let others: Vec<usize> = (0..3).filter(|&i| i != k).collect();
    let plane = |i: usize| {
        bi_add(
            &bi_scale(&rel[i], &direction[k]),
            &bi_scale(&rel[k], &-direction[i].clone()),
        )
    };
    let (f1, f2) = (plane(others[0]), plane(others[1]));
    let [dx, dy] = tangents(&h);
    // det(P_s, P_t, d) = d · (P_s × P_t)
    let cross = |a: usize, b: usize| {
        bi_add(
            &bi_mul(&dx[a], &dy[b]),
            &bi_scale(&bi_mul(&dx[b], &dy[a]), &q(-1)),
        )
    };
    let touch = bi_add(
        &bi_add(
            &bi_scale(&cross(1, 2), &direction[0]),
            &bi_scale(&cross(2, 0), &direction[1]),
        ),
        &bi_scale(&cross(0, 1), &direction[2]),
    );
    // τ = rel_k / (d_k W) ≥ 0 ⟺ rel_k · d_k W ≥ 0 (where W ≠ 0)
    let tau_den = bi_scale(w, &direction[k]);
    let forward = bi_mul(&rel[k], &tau_den);
    let solved = solve_clipped(&f1, &f2, &Region::triangle(), &[forward], &[touch])?;
    let one_minus = BiPoly {
        c: vec![vec![q(1), q(-1)], vec![q(-1)]],
    };
    let hit = |sol: Solution| Hit {
        tau: sol.ratio(&rel[k], &tau_den),
        lambda0: sol.ratio(&one_minus, &bi_const(q(1))),
        touch: sol.flags[0],
        multiplicity: sol.multiplicity,
        s: sol.x,
        t: sol.y,
    };
    let (solutions, degenerate) = match solved {
        Clipped::Points(s) => (s, None),
        Clipped::Region => (
            Vec::new(),
            Some(Degenerate {
                dimension: 2,
                curve: String::new(),
                boundary: Vec::new(),
            }),
        ),
        Clipped::Curve {
            curve,
            boundary,
            points,
        } => (
            points,
            Some(Degenerate {
                dimension: 1,
                curve: bipoly_text(&curve, "s", "t"),
                boundary: boundary.into_iter().map(hit).collect(),
            }),
        ),
    };
    // τ ≥ 0 is one of the conditions `solve_clipped` kept to
    let mut hits: Vec<Hit> = solutions.into_iter().map(hit).collect();
    hits.sort_by(|a, b| cmp_tau(&a.tau, &b.tau));
    Ok(RayHits {
        hits,
        infinite: degenerate.is_some(),
        degenerate,
    })
}
