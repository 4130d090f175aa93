//! Every intersection of two planar Bézier curves, exactly (docs/theory.md §16.5).
//!
//! With `A(s) = (X_A, Y_A)/W_A` and `B(t) = (X_B, Y_B)/W_B` (a polynomial curve has `W = 1`),
//! the intersections are the common zeros of
//! `F1 = X_A(s) W_B(t) − X_B(t) W_A(s)` and `F2 = Y_A(s) W_B(t) − Y_B(t) W_A(s)` in
//! `[0, 1]²`. The resultant `R(t) = Res_s(F1, F2)` vanishes at every such `t`; its roots in
//! `[0, 1]` are isolated (square-free factors, with their multiplicities). Where the first
//! subresultant `S_1 = c1(t) s + c0(t)` has `c1(β) ≠ 0`, the common root in `s` is unique,
//! `s = −c0(β)/c1(β)`; whether it lies in `[0, 1]` is decided by exact signs, and it is
//! matched with the root of `Res_t(F1, F2)` it equals by exact signs too. Where `c1(β) = 0`
//! (the line `t = β` meets the curve pair more than once) the roles of `s` and `t` are
//! exchanged. The intersection is tangential when the tangents `X'W − XW'`, `Y'W − YW'` are
//! parallel there (an exact sign at β); its multiplicity is that of `β` in `R`. When `R`
//! vanishes identically the curves share a component: the overlap is found from the end
//! points of each curve located on the other.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::bivariate::{BiPoly, add, horner, mul};
use super::number::simplest_between;
use super::system::{Region, Solved, enclose_ratio, solve};
use super::{AlgebraicError, IntPoly, MAX_CURVE_DEGREE, RealAlgebraic, check_input};
use crate::patch_type::Patch;

type Q = BigRational;

/// A planar Bézier curve: control points and, for a rational curve, weights (non-zero).
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// The control points `P_0, …, P_n`.
    pub points: Vec<[Q; 2]>,
    /// The weights, for a rational curve.
    pub weights: Option<Vec<Q>>,
}

/// One intersection point.
#[derive(Clone, Debug)]
pub struct Intersection {
    /// The parameter on the first curve.
    pub s: RealAlgebraic,
    /// The parameter on the second curve.
    pub t: RealAlgebraic,
    /// Its multiplicity as a root of the resultant (`None` where the curves overlap and it is
    /// an end point of an overlap that only touches).
    pub multiplicity: Option<usize>,
    /// Are the tangents parallel (or one vanishes) there?
    pub tangential: bool,
    /// The point, as two rational enclosures `[lo, hi]` (equal when exact).
    pub point: [(Q, Q); 2],
}

/// A piece shared by both curves: `A([s0, s1]) = B([t0, t1])` (as sets).
#[derive(Clone, Debug)]
pub struct Overlap {
    /// The parameter interval on the first curve.
    pub s: [RealAlgebraic; 2],
    /// The parameter interval on the second curve (in the order matching `s`).
    pub t: [RealAlgebraic; 2],
}

/// All intersections of two curves.
#[derive(Clone, Debug, Default)]
pub struct CurveIntersections {
    /// Isolated intersection points, by increasing `s` (then `t`).
    pub points: Vec<Intersection>,
    /// Shared pieces.
    pub overlaps: Vec<Overlap>,
    /// `Res_s(F1, F2)` as a primitive integer polynomial in `t` (zero when the curves overlap).
    pub resultant: IntPoly,
}

fn q(k: i64) -> Q {
    Q::from_integer(BigInt::from(k))
}

fn binom(n: usize, k: usize) -> BigInt {
    let mut c = BigInt::one();
    for i in 0..k {
        c = c * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    c
}

/// The power-basis coefficients of `Σ c_i B^n_i(u)`.
pub fn power_basis(c: &[Q]) -> Vec<Q> {
    let n = c.len() - 1;
    (0..=n)
        .map(|k| {
            let mut acc = Q::zero();
            for (i, ci) in c.iter().enumerate().take(k + 1) {
                if ci.is_zero() {
                    continue;
                }
                let b = binom(n, i) * binom(n - i, k - i);
                let term = ci * Q::from_integer(b);
                if (k - i) % 2 == 0 {
                    acc += term;
                } else {
                    acc -= term;
                }
            }
            acc
        })
        .collect()
}

impl Curve {
    /// A planar curve from a patch: a Bézier or rational simplex with `m = 1` and points in
    /// the plane (`d = 2`) of degree at most [`MAX_CURVE_DEGREE`].
    pub fn from_patch(p: &Patch, which: &str) -> Result<Curve, AlgebraicError> {
        let shape = p.shape();
        if shape.simplex_dim != 1 || shape.dimension != 2 {
            return Err(AlgebraicError::Shape(format!(
                "{which} must be a planar curve (m = 1, d = 2), not a patch with m = {}, d = {}",
                shape.simplex_dim, shape.dimension
            )));
        }
        use crate::any_patch::AnyPatch;
        let (net, weights) = match p.as_any() {
            AnyPatch::Bezier(b) => (b, None),
            AnyPatch::Rational(r) => (&r.patch, Some(r.weights.clone())),
            other => {
                return Err(AlgebraicError::Shape(format!(
                    "{which} must be a Bézier or rational curve, not {}",
                    other.described()
                )));
            }
        };
        let points: Vec<[Q; 2]> = net
            .net
            .entries()
            .map(|(_, c)| [c[0].clone(), c[1].clone()])
            .collect();
        let c = Curve { points, weights };
        c.check(which)?;
        Ok(c)
    }

    /// Check the caps and that the weights do not vanish on `[0, 1]`.
    pub fn check(&self, _which: &str) -> Result<(), AlgebraicError> {
        let n = self.degree();
        if n > MAX_CURVE_DEGREE {
            return Err(AlgebraicError::DegreeTooHigh {
                what: "a curve",
                degree: n,
                max: MAX_CURVE_DEGREE,
            });
        }
        for p in &self.points {
            check_input("a control point", &p[0])?;
            check_input("a control point", &p[1])?;
        }
        if let Some(w) = &self.weights {
            for x in w {
                check_input("a weight", x)?;
            }
            let wp = IntPoly::from_rationals(&power_basis(w));
            if wp.is_zero() || !RealAlgebraic::roots_in(&wp, &q(0), &q(1))?.is_empty() {
                return Err(AlgebraicError::Unsupported(
                    "a rational curve whose weight function vanishes on [0, 1]".into(),
                ));
            }
        }
        Ok(())
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.points.len().saturating_sub(1)
    }

    /// `(X, Y, W)` in the power basis (ascending).
    pub fn homogeneous(&self) -> [Vec<Q>; 3] {
        let n1 = self.points.len();
        let w: Vec<Q> = match &self.weights {
            Some(w) => w.clone(),
            None => vec![Q::one(); n1],
        };
        let x: Vec<Q> = self.points.iter().zip(&w).map(|(p, w)| &p[0] * w).collect();
        let y: Vec<Q> = self.points.iter().zip(&w).map(|(p, w)| &p[1] * w).collect();
        [power_basis(&x), power_basis(&y), power_basis(&w)]
    }

    /// Is the curve a single point (all control points equal)?
    pub fn is_point(&self) -> bool {
        self.points.iter().all(|p| p == &self.points[0])
    }

    /// The exact point at a rational parameter.
    pub fn at(&self, u: &Q) -> [Q; 2] {
        let [x, y, w] = self.homogeneous();
        let wv = horner(&w, u);
        [horner(&x, u) / &wv, horner(&y, u) / &wv]
    }

    /// The parameters `u ∈ [0, 1]` with `curve(u) = p` (`None`: the curve is the point `p`
    /// everywhere).
    pub fn parameters_of(&self, p: &[Q; 2]) -> Result<Option<Vec<RealAlgebraic>>, AlgebraicError> {
        let [x, y, w] = self.homogeneous();
        let gx = add(&x, &w.iter().map(|c| -(c * &p[0])).collect::<Vec<_>>());
        let gy = add(&y, &w.iter().map(|c| -(c * &p[1])).collect::<Vec<_>>());
        let g = IntPoly::from_rationals(&gx).gcd(&IntPoly::from_rationals(&gy));
        if g.is_zero() {
            return Ok(None);
        }
        if g.degree() == Some(0) {
            return Ok(Some(Vec::new()));
        }
        RealAlgebraic::roots_in(&g, &q(0), &q(1)).map(Some)
    }
}

/// `F(s, t) = P_A(s) W_B(t) − P_B(t) W_A(s)` as a polynomial in `s` (the `y` of [`BiPoly`])
/// with coefficients in `t`.
fn equation(pa: &[Q], wa: &[Q], pb: &[Q], wb: &[Q]) -> BiPoly {
    let c = (0..pa.len().max(wa.len()))
        .map(|j| {
            let a = pa.get(j).cloned().unwrap_or_else(Q::zero);
            let wj = wa.get(j).cloned().unwrap_or_else(Q::zero);
            let n = wb.len().max(pb.len());
            (0..n)
                .map(|i| {
                    let wbi = wb.get(i).cloned().unwrap_or_else(Q::zero);
                    let pbi = pb.get(i).cloned().unwrap_or_else(Q::zero);
                    &a * &wbi - &pbi * &wj
                })
                .collect()
        })
        .collect();
    BiPoly { c }
}

fn neg(p: &[Q]) -> Vec<Q> {
    p.iter().map(|x| -x).collect()
}

/// A rational strictly between two algebraic numbers `a < b`.
fn rational_between(a: &RealAlgebraic, b: &RealAlgebraic) -> Q {
    let mut w = q(1) / q(16);
    loop {
        let (_, ahi) = a.enclosure(&w);
        let (blo, _) = b.enclosure(&w);
        if ahi < blo {
            return simplest_between(&ahi, &blo);
        }
        w /= q(16);
    }
}

/// Every intersection of two planar curves in `[0, 1]²`, exactly.
///
/// ```
/// use tribez::algebraic::{Curve, intersect_curves};
/// use tribez::parse_rational;
/// let q = |s: &str| parse_rational(s).unwrap();
/// let p = |x: &str, y: &str| [q(x), q(y)];
/// // the parabola (s, s^2)... as a quadratic: control points (0,0), (1/2,0), (1,1);
/// // the line y = 1/2 from (0, 1/2) to (1, 1/2) meets it at s = 1/√2, t = 1/√2
/// let a = Curve { points: vec![p("0", "0"), p("1/2", "0"), p("1", "1")], weights: None };
/// let b = Curve { points: vec![p("0", "1/2"), p("1", "1/2")], weights: None };
/// let x = intersect_curves(&a, &b).unwrap();
/// assert_eq!(x.points.len(), 1);
/// assert_eq!(x.points[0].s.to_f64(), std::f64::consts::FRAC_1_SQRT_2);
/// assert_eq!(x.points[0].t.to_f64(), std::f64::consts::FRAC_1_SQRT_2);
/// assert!(!x.points[0].tangential);
/// ```
pub fn intersect_curves(a: &Curve, b: &Curve) -> Result<CurveIntersections, AlgebraicError> {
    a.check("the first curve")?;
    b.check("the second curve")?;
    let (zero, one) = (RealAlgebraic::rational(q(0)), RealAlgebraic::rational(q(1)));
    let full = || [zero.clone(), one.clone()];
    // degenerate curves: single points
    match (a.is_point(), b.is_point()) {
        (true, true) => {
            let mut out = CurveIntersections::default();
            if a.points[0] == b.points[0] {
                out.overlaps.push(Overlap {
                    s: full(),
                    t: full(),
                });
            }
            return Ok(out);
        }
        (true, false) => {
            let ts = b.parameters_of(&a.points[0])?.unwrap_or_default();
            return Ok(CurveIntersections {
                overlaps: ts
                    .into_iter()
                    .map(|t| Overlap {
                        s: full(),
                        t: [t.clone(), t],
                    })
                    .collect(),
                ..Default::default()
            });
        }
        (false, true) => {
            let ss = a.parameters_of(&b.points[0])?.unwrap_or_default();
            return Ok(CurveIntersections {
                overlaps: ss
                    .into_iter()
                    .map(|s| Overlap {
                        s: [s.clone(), s],
                        t: full(),
                    })
                    .collect(),
                ..Default::default()
            });
        }
        (false, false) => {}
    }
    let [xa, ya, wa] = a.homogeneous();
    let [xb, yb, wb] = b.homogeneous();
    // polynomials in s (the unknown y of the solver) with coefficients in t (its x)
    let f1 = equation(&xa, &wa, &xb, &wb);
    let f2 = equation(&ya, &wa, &yb, &wb);
    // tangent directions (X'W − XW', Y'W − YW') and their cross product G(s, t)
    let tangent = |x: &[Q], y: &[Q], w: &[Q]| -> [Vec<Q>; 2] {
        let d = |p: &[Q]| -> Vec<Q> {
            p.iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * q(i as i64))
                .collect()
        };
        [
            add(&mul(&d(x), w), &neg(&mul(x, &d(w)))),
            add(&mul(&d(y), w), &neg(&mul(y, &d(w)))),
        ]
    };
    let [tax, tay] = tangent(&xa, &ya, &wa);
    let [tbx, tby] = tangent(&xb, &yb, &wb);
    let cross = {
        // TAx(s)·TBy(t) − TAy(s)·TBx(t)
        let rows = tax.len().max(tay.len()).max(1);
        let cols = tbx.len().max(tby.len()).max(1);
        let get = |v: &[Q], i: usize| v.get(i).cloned().unwrap_or_else(Q::zero);
        BiPoly {
            c: (0..rows)
                .map(|j| {
                    (0..cols)
                        .map(|i| get(&tax, j) * get(&tby, i) - get(&tay, j) * get(&tbx, i))
                        .collect()
                })
                .collect(),
        }
    };
    let (solutions, resultant) = match solve(&f1, &f2, &Region::unit_square(), &[cross])? {
        Solved::Infinite => return overlap(a, b),
        Solved::Points {
            solutions,
            resultant,
        } => (solutions, resultant),
    };
    let mut points: Vec<Intersection> = solutions
        .into_iter()
        .map(|sol| {
            // the point from the curve whose parameter is the base value
            let point = if sol.partner.base_is_x {
                [
                    enclose_ratio(&sol.x, &xb, &wb, &tiny()),
                    enclose_ratio(&sol.x, &yb, &wb, &tiny()),
                ]
            } else {
                [
                    enclose_ratio(&sol.y, &xa, &wa, &tiny()),
                    enclose_ratio(&sol.y, &ya, &wa, &tiny()),
                ]
            };
            Intersection {
                s: sol.y,
                t: sol.x,
                multiplicity: Some(sol.multiplicity),
                tangential: sol.flags[0],
                point,
            }
        })
        .collect();
    points.sort_by(|x, y| x.s.cmp_exact(&y.s).then_with(|| x.t.cmp_exact(&y.t)));
    Ok(CurveIntersections {
        points,
        overlaps: Vec::new(),
        resultant,
    })
}

fn tiny() -> Q {
    Q::new(BigInt::one(), BigInt::one() << 120u32)
}

/// The parameter on `c` nearest (by value) to `near` among those mapping to `p`.
fn nearest_parameter(
    c: &Curve,
    p: &[Q; 2],
    near: &Q,
) -> Result<Option<RealAlgebraic>, AlgebraicError> {
    let Some(ts) = c.parameters_of(p)? else {
        return Ok(None);
    };
    let w = q(1) / q(1 << 30);
    Ok(ts.into_iter().min_by_key(|t| {
        let (a, b) = t.enclosure(&w);
        ((a + b) / q(2) - near).abs()
    }))
}

/// Curves that share a component: the pieces of `[0, 1]` on `a` whose image lies on `b`.
fn overlap(a: &Curve, b: &Curve) -> Result<CurveIntersections, AlgebraicError> {
    // break points on a: its ends, and the parameters of b's end points
    let mut brk: Vec<(RealAlgebraic, [Q; 2])> = vec![
        (RealAlgebraic::rational(q(0)), a.at(&q(0))),
        (RealAlgebraic::rational(q(1)), a.at(&q(1))),
    ];
    for end in [q(0), q(1)] {
        let p = b.at(&end);
        for s in a.parameters_of(&p)?.unwrap_or_default() {
            brk.push((s, p.clone()));
        }
    }
    brk.sort_by(|x, y| x.0.cmp_exact(&y.0));
    brk.dedup_by(|x, y| x.0.cmp_exact(&y.0) == Ordering::Equal);
    // which pieces lie on b
    let mut on = Vec::new();
    for w in brk.windows(2) {
        let r = rational_between(&w[0].0, &w[1].0);
        let ts = b.parameters_of(&a.at(&r))?;
        let t_mid = ts.and_then(|ts| {
            ts.first().map(|t| {
                let (x, y) = t.enclosure(&(q(1) / q(1 << 30)));
                (x + y) / q(2)
            })
        });
        on.push(t_mid);
    }
    let mut out = CurveIntersections::default();
    let mut i = 0;
    while i < on.len() {
        let Some(tm) = on[i].clone() else {
            i += 1;
            continue;
        };
        let mut j = i;
        while j + 1 < on.len() && on[j + 1].is_some() {
            j += 1;
        }
        let (s0, p0) = &brk[i];
        let (s1, p1) = &brk[j + 1];
        let t0 = nearest_parameter(b, p0, &tm)?;
        let t1 = nearest_parameter(b, p1, &tm)?;
        if let (Some(t0), Some(t1)) = (t0, t1) {
            out.overlaps.push(Overlap {
                s: [s0.clone(), s1.clone()],
                t: [t0, t1],
            });
        }
        i = j + 1;
    }
    // break points on b that no overlap covers: isolated touching points
    for (k, (s, p)) in brk.iter().enumerate() {
        let left = k > 0 && on[k - 1].is_some();
        let right = k < on.len() && on[k].is_some();
        if left || right {
            continue;
        }
        if let Some(ts) = b.parameters_of(p)? {
            for t in ts {
                out.points.push(Intersection {
                    s: s.clone(),
                    t,
                    multiplicity: None,
                    tangential: true,
                    point: [(p[0].clone(), p[0].clone()), (p[1].clone(), p[1].clone())],
                });
            }
        }
    }
    Ok(out)
}

/// The point of an intersection as text: exact coordinates, or 17 significant digits of an
/// enclosure narrower than the digits shown.
pub fn point_text(point: &[(Q, Q); 2]) -> [String; 2] {
    point.clone().map(|(lo, hi)| {
        if lo == hi {
            lo.to_string()
        } else {
            let a = crate::number::to_decimal_string(&lo, 17);
            if a == crate::number::to_decimal_string(&hi, 17) {
                a
            } else {
                format!(
                    "≈{}",
                    crate::number::to_decimal_string(&((lo + hi) / q(2)), 17)
                )
            }
        }
    })
}
