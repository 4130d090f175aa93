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
use num_traits::{One, Zero};

use super::bivariate::{BiPoly, add, horner, mul, resultant, subresultant1};
use super::real::simplest_between;
use super::system::{Region, Solution, Solved, enclose_ratio, solve};
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

/// A piece shared by both curves: a branch of the relation `G(s, t) = 0` on which `s` and `t`
/// are both strictly monotone, from `(s[0], t[0])` to `(s[1], t[1])` with `s[0] < s[1]`:
/// for every `s` in `[s[0], s[1]]` exactly one `t` between `t[0]` and `t[1]` has
/// `A(s) = B(t)` on this piece, increasing with `s` when `t[0] < t[1]` and decreasing when
/// `t[0] > t[1]`. A curve that folds back or passes a node gives several pieces.
#[derive(Clone, Debug)]
pub struct Overlap {
    /// The parameter interval on the first curve (increasing).
    pub s: [RealAlgebraic; 2],
    /// The parameters on the second curve at `s[0]` and at `s[1]`.
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
    /// When both curves lie on one algebraic curve: the relation `G(s, t) = 0` that holds
    /// exactly on every shared piece (the square-free common factor of `F1` and `F2`, with
    /// no factor in `s` or `t` alone), as a polynomial in `s` (the `y` of [`BiPoly`]) with
    /// coefficients in `t`.
    pub relation: Option<BiPoly>,
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
    check_work(&f1, &f2)?;
    let found = match solve_points(&f1, &f2, std::slice::from_ref(&cross))? {
        Some(found) => found,
        None => return on_common_curve(b, &f1, &f2, &cross),
    };
    let mut points: Vec<Intersection> = found
        .points
        .into_iter()
        .map(|p| Intersection {
            point: point_of(b, &p.t),
            s: p.s,
            t: p.t,
            multiplicity: p.multiplicity,
            tangential: p.flags[0],
        })
        .collect();
    points.sort_by(|x, y| x.s.cmp_exact(&y.s).then_with(|| x.t.cmp_exact(&y.t)));
    Ok(CurveIntersections {
        points,
        overlaps: Vec::new(),
        resultant: found.resultant,
        relation: None,
    })
}

/// The largest work estimate [`intersect_curves`] takes on (see [`work_estimate`]).
pub const MAX_INTERSECT_WORK: u64 = 12_000_000;

/// The largest bit length of the integer coefficients of `p` scaled by the lcm of its
/// denominators.
fn int_bits(p: &BiPoly) -> u64 {
    let l = p.c.iter().flatten().fold(BigInt::one(), |l, x| {
        num_integer::Integer::lcm(&l, x.denom())
    });
    p.c.iter()
        .flatten()
        .map(|x| (x.numer() * (&l / x.denom())).bits())
        .max()
        .unwrap_or(0)
}

/// The work estimate of intersecting two curves whose equations are `f1`, `f2` (polynomials
/// in `s` with coefficients in `t`): with `D = deg_s f2·deg_t f1 + deg_s f1·deg_t f2` the
/// degree bound of the resultant and `L = (deg_s f1 + deg_s f2)·b` a bound on the bit length
/// of its coefficients (`b` the largest bit length of the equations' integer coefficients),
/// `D²·(D + L)`: root isolation by subdivision of a degree-`D` polynomial with `L`-bit
/// coefficients, and the `D + 1` determinants of the resultant, grow about so.
pub fn work_estimate(f1: &BiPoly, f2: &BiPoly) -> u64 {
    let (f1, f2) = (f1.trimmed(), f2.trimmed());
    let d = (f2.deg_y() * f1.deg_x() + f1.deg_y() * f2.deg_x()) as u64;
    let l = (f1.deg_y() + f2.deg_y()) as u64 * int_bits(&f1).max(int_bits(&f2));
    d.saturating_mul(d).saturating_mul(d.saturating_add(l))
}

/// Refuse a pair of curves whose [`work_estimate`] is above [`MAX_INTERSECT_WORK`].
fn check_work(f1: &BiPoly, f2: &BiPoly) -> Result<(), AlgebraicError> {
    let w = work_estimate(f1, f2);
    if w > MAX_INTERSECT_WORK {
        let (f1, f2) = (f1.trimmed(), f2.trimmed());
        return Err(AlgebraicError::Unsupported(format!(
            "curves whose resultant has degree up to {} with coefficients of up to about {} bits \
             (work estimate {w}, above the limit {MAX_INTERSECT_WORK}; lower the degrees or the \
             coordinates' bit lengths)",
            f2.deg_y() * f1.deg_x() + f1.deg_y() * f2.deg_x(),
            (f1.deg_y() + f2.deg_y()) as u64 * int_bits(&f1).max(int_bits(&f2)),
        )));
    }
    Ok(())
}

/// The point `B(t)` as a rational enclosure of width at most 2^-120 per coordinate.
fn point_of(b: &Curve, t: &RealAlgebraic) -> [(Q, Q); 2] {
    let [xb, yb, wb] = b.homogeneous();
    [
        enclose_ratio(t, &xb, &wb, &tiny()),
        enclose_ratio(t, &yb, &wb, &tiny()),
    ]
}

fn tiny() -> Q {
    Q::new(BigInt::one(), BigInt::one() << 120u32)
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

/// A solution of two equations in `(s, t)`: the parameters, the multiplicity (as a root of
/// the resultant it was found from) and whether each flag polynomial vanishes there.
struct Found {
    s: RealAlgebraic,
    t: RealAlgebraic,
    multiplicity: Option<usize>,
    flags: Vec<bool>,
}

/// The solutions of `f1 = f2 = 0` in `[0, 1]²` and `Res_s(f1, f2)`.
struct FoundAll {
    points: Vec<Found>,
    resultant: IntPoly,
}

/// Every solution of `f1 = f2 = 0` (polynomials in `s` with coefficients in `t`) in
/// `[0, 1]²`, each with whether each of `flags` vanishes there; `None` when the resultant
/// vanishes identically (the equations share a factor). Points that share both their `s` and
/// their `t` with other solutions (as where each curve passes twice) are separated by the
/// engine's shear ([`solve`]).
fn solve_points(
    f1: &BiPoly,
    f2: &BiPoly,
    flags: &[BiPoly],
) -> Result<Option<FoundAll>, AlgebraicError> {
    match solve(f1, f2, &Region::unit_square(), flags)? {
        Solved::Infinite => Ok(None),
        Solved::Points {
            solutions,
            resultant,
        } => Ok(Some(FoundAll {
            points: solutions
                .into_iter()
                .map(|sol| Found {
                    s: sol.y,
                    t: sol.x,
                    multiplicity: Some(sol.multiplicity),
                    flags: sol.flags,
                })
                .collect(),
            resultant,
        })),
    }
}

/// `∂p/∂y`.
fn d_y(p: &BiPoly) -> BiPoly {
    let c: Vec<Vec<Q>> =
        p.c.iter()
            .enumerate()
            .skip(1)
            .map(|(j, cj)| cj.iter().map(|a| a * q(j as i64)).collect())
            .collect();
    BiPoly {
        c: if c.is_empty() { vec![Vec::new()] } else { c },
    }
}

/// `∂p/∂x`.
fn d_x(p: &BiPoly) -> BiPoly {
    BiPoly {
        c: p.c
            .iter()
            .map(|cj| {
                cj.iter()
                    .enumerate()
                    .skip(1)
                    .map(|(i, a)| a * q(i as i64))
                    .collect()
            })
            .collect(),
    }
}

/// `p` divided by its contents in both variables (the gcd of its coefficients as a
/// polynomial in `y`, then in `x`) and by its repeated factors: square-free, with no factor
/// in one variable alone.
fn reduced(p: &BiPoly) -> BiPoly {
    let strip = |p: &BiPoly| -> BiPoly {
        let p = p.trimmed();
        let mut g = BiPoly {
            c: vec![p.c[0].clone()],
        };
        for cj in &p.c[1..] {
            g = super::bivariate::gcd(
                &g,
                &BiPoly {
                    c: vec![cj.clone()],
                },
            );
        }
        super::bivariate::div_exact(&p, &g).unwrap_or(p)
    };
    let p = strip(&strip(p).swap()).swap().trimmed();
    let g = super::bivariate::gcd(&p, &d_y(&p)).trimmed();
    super::bivariate::div_exact(&p, &g).unwrap_or(p).trimmed()
}

/// The sign of `g` at a solution whose base value is algebraic and whose other unknown is
/// `num/den` of it: the sign of `den^N·g(…)` (a polynomial in the base) times `sign(den)^N`.
fn sign_at(sol: &Solution, g: &BiPoly) -> Ordering {
    sol.sign_of(g)
}

/// The points `(b, y)`, `y ∈ [0, 1]`, of `p = 0` over an algebraic `x = b`, increasing in
/// `y`. The candidates `y` are the roots of `Res_x(m_b(x), p(x, y))` (`m_b` the polynomial
/// of `b`); at each, the first subresultant in `x` gives the unique common root
/// `x = −d_0(y)/d_1(y)`, which is `b` exactly when it lies in `b`'s isolating interval.
fn fiber(p: &BiPoly, b: &RealAlgebraic) -> Result<Vec<Solution>, AlgebraicError> {
    let (m, interval): (Vec<Q>, Option<(Q, Q)>) = match b {
        RealAlgebraic::Rational(r) => (vec![-r.clone(), Q::one()], None),
        RealAlgebraic::Root(root) => {
            let (lo, hi) = root.interval();
            (
                root.poly()
                    .coeffs()
                    .iter()
                    .map(|c| Q::from_integer(c.clone()))
                    .collect(),
                Some((lo.clone(), hi.clone())),
            )
        }
    };
    let fm = BiPoly {
        c: m.iter().map(|c| vec![c.clone()]).collect(),
    };
    let pw = p.swap().trimmed();
    let r = IntPoly::from_rationals(&resultant(&fm, &pw));
    if r.is_zero() {
        return Err(AlgebraicError::Unsupported(
            "a shared curve with a whole line of parameters (internal)".into(),
        ));
    }
    let (d1, d0) = subresultant1(&fm, &pw);
    let nd0 = neg(&d0);
    let mut out = Vec::new();
    for y in RealAlgebraic::roots_in(&r, &q(0), &q(1))? {
        if y.sign_of_rationals(&d1) == Ordering::Equal {
            return Err(AlgebraicError::Unsupported(
                "a shared curve that meets a line of constant parameter at two conjugate points"
                    .into(),
            ));
        }
        if let Some((lo, hi)) = &interval {
            let e = super::system::Expr {
                base: y.clone(),
                num: nd0.clone(),
                den: d1.clone(),
            };
            if e.cmp_rational(lo) != Ordering::Greater || e.cmp_rational(hi) != Ordering::Less {
                continue;
            }
        }
        out.push(Solution {
            x: b.clone(),
            y,
            multiplicity: 1,
            flags: Vec::new(),
            partner: super::system::Partner {
                base_is_x: false,
                shear: Q::zero(),
                num: nd0.clone(),
                den: d1.clone(),
            },
            sheared_base: None,
        });
    }
    Ok(out)
}

/// The roots in `[0, 1]` of a polynomial with rational coefficients (none if it is zero).
fn unit_roots(p: &[Q]) -> Result<Vec<RealAlgebraic>, AlgebraicError> {
    let p = IntPoly::from_rationals(p);
    if p.is_zero() {
        return Ok(Vec::new());
    }
    RealAlgebraic::roots_in(&p, &q(0), &q(1))
}

/// The real curve `p(x, y) = 0` in `[0, 1]²` (square-free, no factor in one variable alone):
/// its pieces, each strictly monotone in both unknowns, as `((x0, y0), (x1, y1))` with
/// `x0 < x1`, and its isolated points (docs/theory.md §16.5, "Overlaps"). A sweep in `x`: the
/// fibers over the break values ([`sweep_breaks`]), with the arcs each point sends left and
/// right ([`arc_counts`]); the arcs over each interval between breaks ([`interval_arcs`]);
/// arcs merged into monotone pieces ([`merge_arcs`]).
#[allow(clippy::type_complexity)]
fn curve_in_square(
    p: &BiPoly,
) -> Result<(Vec<[(RealAlgebraic, RealAlgebraic); 2]>, Vec<Solution>), AlgebraicError> {
    let (py, px) = (d_y(p).trimmed(), d_x(p).trimmed());
    let pyy = d_y(&py).trimmed();
    let breaks = sweep_breaks(p, &py, &px)?;
    let last = breaks.len() - 1;
    let mut fibers: Vec<Fiber> = Vec::new();
    for (i, b) in breaks.iter().enumerate() {
        let mut f = Vec::new();
        for sol in fiber(p, b)? {
            let mut lr = arc_counts(&sol, &py, &px, &pyy);
            if i == 0 {
                lr[0] = Some(0);
            }
            if i == last {
                lr[1] = Some(0);
            }
            f.push((sol, lr));
        }
        fibers.push(f);
    }
    let mut arcs: Vec<Vec<(usize, usize)>> = Vec::new();
    for i in 0..last {
        arcs.push(interval_arcs(p, &breaks, &mut fibers, i)?);
    }
    let pieces = merge_arcs(&fibers, &arcs);
    let mut isolated = Vec::new();
    for f in fibers {
        for (sol, lr) in f {
            if lr == [Some(0), Some(0)] {
                isolated.push(sol);
            }
        }
    }
    Ok((pieces, isolated))
}

/// The points of the curve over one break value, each with how many arcs leave it to the left
/// and to the right (`None`: to be found from the count of arcs over the neighbouring interval).
type Fiber = Vec<(Solution, [Option<usize>; 2])>;

/// The sweep's break values in `[0, 1]`, sorted, without repeats: critical points of the
/// projection on x (`p = p_y = 0`), turning points in y (`p = p_x = 0`), the sides `y = 0` and
/// `y = 1`, and `x = 0, 1`.
fn sweep_breaks(
    p: &BiPoly,
    py: &BiPoly,
    px: &BiPoly,
) -> Result<Vec<RealAlgebraic>, AlgebraicError> {
    let mut breaks = vec![RealAlgebraic::rational(q(0)), RealAlgebraic::rational(q(1))];
    let y1: Vec<Q> = p.c.iter().fold(Vec::new(), |acc, c| add(&acc, c));
    for poly in [resultant(p, py), resultant(p, px), p.c[0].clone(), y1] {
        breaks.extend(unit_roots(&poly)?);
    }
    breaks.sort_by(|a, b| a.cmp_exact(b));
    breaks.dedup_by(|a, b| a.cmp_exact(b) == Ordering::Equal);
    Ok(breaks)
}

/// How many arcs leave the curve's point `sol` (with `0 ≤ y ≤ 1`) to the left and to the right,
/// from the signs of `p_y`, `p_x` and `p_yy` there; `None` where the signs do not tell (a
/// singular point, or a tangency the second derivative does not decide).
fn arc_counts(sol: &Solution, py: &BiPoly, px: &BiPoly, pyy: &BiPoly) -> [Option<usize>; 2] {
    let interior = sol.y.cmp_rational(&q(0)) == Ordering::Greater
        && sol.y.cmp_rational(&q(1)) == Ordering::Less;
    let at_lo = sol.y.cmp_rational(&q(0)) == Ordering::Equal;
    let sy = sign_at(sol, py);
    let sx = sign_at(sol, px);
    if sy != Ordering::Equal {
        if interior {
            [Some(1), Some(1)]
        } else if sx == Ordering::Equal {
            [None, None]
        } else {
            // y = φ(x), φ' = −p_x/p_y: into y > 0 on the right when φ' > 0
            let rising = sx != sy;
            let right = rising == at_lo;
            [Some(usize::from(!right)), Some(usize::from(right))]
        }
    } else if sx != Ordering::Equal {
        // x = ψ(y) with ψ' = 0, ψ'' = −p_yy/p_x: both branches on the side of ψ''
        let syy = sign_at(sol, pyy);
        if syy == Ordering::Equal {
            [None, None]
        } else {
            let k = if interior { 2 } else { 1 };
            if syy != sx {
                [Some(0), Some(k)]
            } else {
                [Some(k), Some(0)]
            }
        }
    } else {
        [None, None]
    }
}

/// The arcs over the open interval between breaks `i` and `i + 1`, as pairs (point of fiber
/// `i`, point of fiber `i + 1`) in order of `y`; the unknown counts of arcs leaving the two
/// fibers into it are settled from the number of arcs over the interval (the roots in `[0, 1]`
/// at a rational between the breaks). Errors: counts that do not add up (internal), two
/// unknown counts that the number of arcs cannot settle.
fn interval_arcs(
    p: &BiPoly,
    breaks: &[RealAlgebraic],
    fibers: &mut [Fiber],
    i: usize,
) -> Result<Vec<(usize, usize)>, AlgebraicError> {
    let r = rational_between(&breaks[i], &breaks[i + 1]);
    let m = unit_roots(&p.at_x(&r))?.len();
    for (fi, side) in [(i, 1usize), (i + 1, 0usize)] {
        let known: usize = fibers[fi].iter().filter_map(|(_, lr)| lr[side]).sum();
        let unknown: Vec<usize> = (0..fibers[fi].len())
            .filter(|&k| fibers[fi][k].1[side].is_none())
            .collect();
        if known > m || (unknown.is_empty() && known != m) {
            return Err(AlgebraicError::Unsupported(
                "a shared curve whose arcs do not add up (internal)".into(),
            ));
        }
        match unknown.len() {
            0 => {}
            1 => fibers[fi][unknown[0]].1[side] = Some(m - known),
            _ if known == m => {
                for k in unknown {
                    fibers[fi][k].1[side] = Some(0);
                }
            }
            _ => {
                return Err(AlgebraicError::Unsupported(
                    "a shared curve with two singular points over one parameter value".into(),
                ));
            }
        }
    }
    let ends = |fi: usize, side: usize| -> Vec<usize> {
        let mut v = Vec::new();
        for (k, (_, lr)) in fibers[fi].iter().enumerate() {
            for _ in 0..lr[side].unwrap_or(0) {
                v.push(k);
            }
        }
        v
    };
    let (from, to) = (ends(i, 1), ends(i + 1, 0));
    Ok(from.into_iter().zip(to).collect())
}

/// The monotone pieces: arcs merged through points with one arc on each side and the same
/// direction in `y`, each as its two ends `(x, y)`.
fn merge_arcs(
    fibers: &[Fiber],
    arcs: &[Vec<(usize, usize)>],
) -> Vec<[(RealAlgebraic, RealAlgebraic); 2]> {
    let last = arcs.len();
    let dir = |i: usize, a: (usize, usize)| -> Ordering {
        fibers[i + 1][a.1].0.y.cmp_exact(&fibers[i][a.0].0.y)
    };
    let mut pieces = Vec::new();
    for i in 0..last {
        for &a in &arcs[i] {
            let joins = |i: usize, node: usize, d: Ordering| -> Option<usize> {
                // the arc of interval i leaving `node` (in fiber i), when it continues one arc
                if i == last {
                    return None;
                }
                let [l, r] = fibers[i][node].1;
                if l != Some(1) || r != Some(1) {
                    return None;
                }
                let next = arcs[i].iter().position(|x| x.0 == node)?;
                (dir(i, arcs[i][next]) == d).then_some(next)
            };
            let d = dir(i, a);
            if i > 0 && fibers[i][a.0].1 == [Some(1), Some(1)] {
                let before = arcs[i - 1].iter().find(|x| x.1 == a.0);
                if before.is_some_and(|&x| dir(i - 1, x) == d) {
                    continue; // continues an arc of the interval before
                }
            }
            let start = (fibers[i][a.0].0.x.clone(), fibers[i][a.0].0.y.clone());
            let (mut j, mut cur) = (i, a);
            while let Some(n) = joins(j + 1, cur.1, d) {
                j += 1;
                cur = arcs[j][n];
            }
            let end = (
                fibers[j + 1][cur.1].0.x.clone(),
                fibers[j + 1][cur.1].0.y.clone(),
            );
            pieces.push([start, end]);
        }
    }
    pieces
}

/// Two curves whose equations share a factor `G` (`F_i = G·H_i`): both lie on one algebraic
/// curve. The solution set is `{G = 0} ∪ {H_1 = H_2 = 0}`: the pieces and isolated points of
/// `G = 0` in `[0, 1]²` ([`curve_in_square`]), and the solutions of `H_1 = H_2 = 0` off
/// `G = 0` (points where the curves meet without sharing a piece: a node of the common
/// curve, a closing point).
fn on_common_curve(
    b: &Curve,
    f1: &BiPoly,
    f2: &BiPoly,
    cross: &BiPoly,
) -> Result<CurveIntersections, AlgebraicError> {
    let g0 = super::bivariate::gcd(f1, f2).trimmed();
    let h1 = super::bivariate::div_exact(f1, &g0).map(|h| h.trimmed());
    let h2 = super::bivariate::div_exact(f2, &g0).map(|h| h.trimmed());
    let (Some(h1), Some(h2)) = (h1, h2) else {
        return Err(AlgebraicError::Unsupported(
            "the common factor does not divide (internal)".into(),
        ));
    };
    let constant = |h: &BiPoly| h.c.len() == 1 && h.c[0].len() <= 1;
    let mut points = Vec::new();
    if !(h1.is_zero() || h2.is_zero() || constant(&h1) || constant(&h2)) {
        let Some(found) = solve_points(&h1, &h2, &[cross.clone(), g0.clone()])? else {
            return Err(AlgebraicError::Unsupported(
                "the cofactors share a factor (internal)".into(),
            ));
        };
        for f in found.points {
            if f.flags[1] {
                continue; // on G = 0: a point of a piece or an isolated point of G
            }
            points.push(Intersection {
                point: point_of(b, &f.t),
                s: f.s,
                t: f.t,
                multiplicity: f.multiplicity,
                tangential: f.flags[0],
            });
        }
    }
    // G in (x, y) = (t, s)
    let g = reduced(&g0);
    let (pieces, isolated) = curve_in_square(&g)?;
    for sol in isolated {
        points.push(Intersection {
            point: point_of(b, &sol.x),
            tangential: sign_at(&sol, cross) == Ordering::Equal,
            s: sol.y,
            t: sol.x,
            multiplicity: None,
        });
    }
    points.sort_by(|x, y| x.s.cmp_exact(&y.s).then_with(|| x.t.cmp_exact(&y.t)));
    let mut overlaps: Vec<Overlap> = pieces
        .into_iter()
        .map(|[(x0, y0), (x1, y1)]| {
            if y0.cmp_exact(&y1) == Ordering::Greater {
                Overlap {
                    s: [y1, y0],
                    t: [x1, x0],
                }
            } else {
                Overlap {
                    s: [y0, y1],
                    t: [x0, x1],
                }
            }
        })
        .collect();
    overlaps.sort_by(|a, b| {
        a.s[0]
            .cmp_exact(&b.s[0])
            .then_with(|| a.t[0].cmp_exact(&b.t[0]))
    });
    Ok(CurveIntersections {
        points,
        overlaps,
        resultant: IntPoly::default(),
        relation: Some(g),
    })
}
