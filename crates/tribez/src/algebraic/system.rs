//! Two polynomial equations in two unknowns, solved exactly over a region of the plane
//! (docs/theory.md §16.5, §16.6): the shared engine of curve intersection, `locate` and `ray`.
//!
//! The unknowns are `x` and `y`; each equation is a [`BiPoly`] in `y` with coefficients in `x`.
//! `R_x = Res_y(f, g)` is isolated over the `x`-range, `R_y = Res_x(f, g)` over the `y`-range; a
//! root `β` of `R_x` with `s_1(β) ≠ 0` (first subresultant in `y`) has the single partner
//! `y = −s_0(β)/s_1(β)`, matched to a root of `R_y` by exact signs; the remaining roots are
//! resolved from the `y` side the same way.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::bivariate::{BiPoly, add, horner, mul, resultant, shear, subresultant1, trim};
use super::interval::{IntBiPoly, Scaled, horner_scaled};
use super::{AlgebraicError, IntPoly, RealAlgebraic};

type Q = BigRational;

fn q(k: i64) -> Q {
    Q::from_integer(BigInt::from(k))
}

/// The half-plane `a·x + b·y + c ≥ 0`.
#[derive(Clone, Debug)]
pub struct Half {
    /// Coefficient of `x`.
    pub a: Q,
    /// Coefficient of `y`.
    pub b: Q,
    /// Constant.
    pub c: Q,
}

/// Where solutions are sought: `x` and `y` ranges (`None`: all reals, bounded by Cauchy's bound
/// of the resultant) and half-planes.
#[derive(Clone, Debug)]
pub struct Region {
    /// The closed range of `x`.
    pub x: Option<(Q, Q)>,
    /// The closed range of `y`.
    pub y: Option<(Q, Q)>,
    /// Further constraints.
    pub halves: Vec<Half>,
}

impl Region {
    /// `[0, 1]²`.
    pub fn unit_square() -> Self {
        Region {
            x: Some((q(0), q(1))),
            y: Some((q(0), q(1))),
            halves: Vec::new(),
        }
    }

    /// The triangle `x ≥ 0, y ≥ 0, x + y ≤ 1`.
    pub fn triangle() -> Self {
        Region {
            x: Some((q(0), q(1))),
            y: Some((q(0), q(1))),
            halves: vec![Half {
                a: q(-1),
                b: q(-1),
                c: q(1),
            }],
        }
    }

    /// The whole plane.
    pub fn plane() -> Self {
        Region {
            x: None,
            y: None,
            halves: Vec::new(),
        }
    }
}

/// One variable as a rational function of the other at an algebraic value.
///
/// Plainly (`shear = 0`) the base is `x` and `y = num/den` at it, or the base is `y` and
/// `x = num/den`. Sheared (`shear = λ ≠ 0`), the base is `b = x − λ·y` with `y = num/den(b)`
/// (`base_is_x`) or `b = y − λ·x` with `x = num/den(b)`: the unknowns of a system solved with
/// one family of lines slanted (docs/theory.md §16.5).
#[derive(Clone, Debug)]
pub struct Partner {
    /// Is the base variable `x` (then `y = num/den` at it), or `y`?
    pub base_is_x: bool,
    /// The shear `λ` of the base variable (0 for `x` or `y` itself).
    pub shear: Q,
    /// Numerator (polynomial in the base variable).
    pub num: Vec<Q>,
    /// Denominator (non-zero at the base value).
    pub den: Vec<Q>,
}

/// A solution `(x, y)`.
#[derive(Clone, Debug)]
pub struct Solution {
    /// `x`.
    pub x: RealAlgebraic,
    /// `y`.
    pub y: RealAlgebraic,
    /// Multiplicity as a root of the resultant of the side it was found from.
    pub multiplicity: usize,
    /// For each flag polynomial: does it vanish here?
    pub flags: Vec<bool>,
    /// How the other variable depends on the base one.
    pub partner: Partner,
    /// The base value `x − λ·y` or `y − λ·x` of a sheared partner (`None` when the base is `x`
    /// or `y` itself).
    pub sheared_base: Option<RealAlgebraic>,
}

impl Solution {
    /// The base value (`x` or `y`, as [`Partner::base_is_x`] says, or the sheared one).
    pub fn base(&self) -> &RealAlgebraic {
        if let Some(b) = &self.sheared_base {
            b
        } else if self.partner.base_is_x {
            &self.x
        } else {
            &self.y
        }
    }

    /// `G` written in the base variable and the other one: `G(b + λ·v, v)` with `v` the
    /// partner's variable (`λ = 0` unless sheared).
    fn oriented(&self, g: &BiPoly) -> BiPoly {
        let g = if self.partner.base_is_x {
            g.clone()
        } else {
            g.swap()
        };
        if self.partner.shear.is_zero() {
            g
        } else {
            shear(&g.swap(), &self.partner.shear).swap()
        }
    }

    /// `den^N · G(x, y)` as a polynomial in the base variable (`N` the formal degree of `G` in
    /// the other variable): the sign of `G` at the solution times the sign of `den^N`.
    pub fn substitute(&self, g: &BiPoly) -> Vec<Q> {
        self.oriented(g)
            .substitute_y(&self.partner.num, &self.partner.den)
    }

    /// The sign of `G` at the solution.
    pub fn sign_of(&self, g: &BiPoly) -> Ordering {
        let g = self.oriented(g);
        let v = self
            .base()
            .sign_of_rationals(&g.substitute_y(&self.partner.num, &self.partner.den));
        let sd = self.base().sign_of_rationals(&self.partner.den);
        if sd == Ordering::Less && g.deg_y() % 2 == 1 {
            v.reverse()
        } else {
            v
        }
    }

    /// The value `G(x, y)/H(x, y)` at the solution as an expression in the base value (`H ≠ 0`
    /// there).
    pub fn ratio(&self, g: &BiPoly, h: &BiPoly) -> Expr {
        // pad both to the same formal degree in the other variable so den^N cancels
        let (mut g, mut h) = (self.oriented(g), self.oriented(h));
        let n = g.c.len().max(h.c.len());
        g.c.resize(n, Vec::new());
        h.c.resize(n, Vec::new());
        Expr {
            base: self.base().clone(),
            num: g.substitute_y(&self.partner.num, &self.partner.den),
            den: h.substitute_y(&self.partner.num, &self.partner.den),
        }
    }
}

/// `num(β)/den(β)` for an algebraic `β` (`den(β) ≠ 0`): exact sign, comparison, rounding.
#[derive(Clone, Debug)]
pub struct Expr {
    /// `β`.
    pub base: RealAlgebraic,
    /// Numerator.
    pub num: Vec<Q>,
    /// Denominator.
    pub den: Vec<Q>,
}

impl Expr {
    /// The exact value when `β` is rational.
    pub fn rational(&self) -> Option<Q> {
        let b = self.base.as_rational()?;
        Some(horner(&self.num, b) / horner(&self.den, b))
    }

    /// The sign, exactly.
    pub fn sign(&self) -> Ordering {
        let a = self.base.sign_of_rationals(&self.num);
        let b = self.base.sign_of_rationals(&self.den);
        if b == Ordering::Less { a.reverse() } else { a }
    }

    /// How it compares with the rational `r`, exactly.
    pub fn cmp_rational(&self, r: &Q) -> Ordering {
        let p = add(
            &self.num,
            &self.den.iter().map(|c| -(c * r)).collect::<Vec<_>>(),
        );
        let a = self.base.sign_of_rationals(&p);
        let b = self.base.sign_of_rationals(&self.den);
        if b == Ordering::Less { a.reverse() } else { a }
    }

    /// A rational enclosure of width at most `width`.
    pub fn enclosure(&self, width: &Q) -> (Q, Q) {
        enclose_ratio(&self.base, &self.num, &self.den, width)
    }

    /// JSON: `{"rational", "f64", "decimal"}` when rational, else `{"f64", "decimal"}` (hex
    /// float, 17 significant digits).
    pub fn to_json(&self) -> serde_json::Value {
        use crate::number::{hex_f64, round_f64, to_decimal_string};
        match self.rational() {
            Some(r) => serde_json::json!({
                "rational": r.to_string(),
                "f64": hex_f64(round_f64(&r)),
                "decimal": to_decimal_string(&r, 17),
            }),
            None => serde_json::json!({
                "f64": hex_f64(self.to_f64()),
                "decimal": self.decimal(),
            }),
        }
    }

    /// The nearest `f64` (ties to even): enclosures are narrowed until they round to one float;
    /// a value that is exactly a midpoint between two floats is recognised by an exact sign.
    pub fn to_f64(&self) -> f64 {
        if let Some(r) = self.rational() {
            return crate::number::round_f64(&r);
        }
        let mut w = q(1) / q(1 << 20);
        loop {
            let (lo, hi) = self.enclosure(&w);
            let (a, b) = (crate::number::round_f64(&lo), crate::number::round_f64(&hi));
            if a == b {
                return a;
            }
            // a tie between consecutive floats inside the enclosure?
            if let (Some(x), Some(y)) = (crate::number::exact_f64(a), crate::number::exact_f64(b))
                && a.next_up() == b
            {
                let mid = (x + y) / q(2);
                if self.cmp_rational(&mid) == Ordering::Equal {
                    return crate::number::round_f64(&mid);
                }
            }
            w /= q(1 << 16);
        }
    }

    /// 17 significant digits (of an enclosure narrow enough that both ends agree; at most
    /// 40 narrowings, then the midpoint's digits with `≈`).
    pub fn decimal(&self) -> String {
        if let Some(r) = self.rational() {
            return crate::number::to_decimal_string(&r, 17);
        }
        let mut w = q(1) / q(1 << 20);
        for _ in 0..40 {
            let (lo, hi) = self.enclosure(&w);
            let a = crate::number::to_decimal_string(&lo, 17);
            if a == crate::number::to_decimal_string(&hi, 17) {
                return a;
            }
            w /= q(1 << 16);
        }
        let (lo, hi) = self.enclosure(&w);
        format!(
            "≈{}",
            crate::number::to_decimal_string(&((lo + hi) / q(2)), 17)
        )
    }
}

/// A rational enclosure of `num(β)/den(β)` of width at most `width` (integer interval Horner
/// over ever narrower isolating intervals of `β`; see [`ratio_on`]).
pub fn enclose_ratio(beta: &RealAlgebraic, num: &[Q], den: &[Q], width: &Q) -> (Q, Q) {
    if let Some(b) = beta.as_rational() {
        let v = horner(num, b) / horner(den, b);
        return (v.clone(), v);
    }
    let (ni, di) = common_integers(num, den);
    let mut beta = beta.clone();
    let mut w = Q::new(BigInt::from(1), BigInt::from(1) << 20u32).min(width.clone());
    loop {
        beta.refine_to(&w);
        let (lo, hi) = beta.bounds();
        if let Some((a, b)) = ratio_on(&ni, &di, &lo, &hi)
            && &b - &a <= *width
        {
            return (a, b);
        }
        w /= q(1 << 16);
    }
}

/// Integer multiples `(N, D)` of `(num, den)` by one positive factor (their ratio unchanged).
pub(crate) fn common_integers(num: &[Q], den: &[Q]) -> (Vec<BigInt>, Vec<BigInt>) {
    let l = num.iter().chain(den).fold(BigInt::from(1), |l, x| {
        num_integer::Integer::lcm(&l, x.denom())
    });
    let f = |p: &[Q]| -> Vec<BigInt> { p.iter().map(|x| x.numer() * (&l / x.denom())).collect() };
    (f(num), f(den))
}

/// An enclosure of `N(x)/D(x)` over `x ∈ [lo, hi]` when the enclosure of `D` excludes zero
/// (both evaluated with one formal degree, so the common positive scale cancels).
pub(crate) fn ratio_on(n: &[BigInt], d: &[BigInt], lo: &Q, hi: &Q) -> Option<(Q, Q)> {
    let deg = n.len().max(d.len()).max(1) - 1;
    let x = Scaled::new(lo, hi);
    let ni = horner_scaled(n, deg, &x);
    let di = horner_scaled(d, deg, &x);
    if di.sign()? == Ordering::Equal {
        return None;
    }
    let c = [
        Q::new(ni.lo.clone(), di.lo.clone()),
        Q::new(ni.lo.clone(), di.hi.clone()),
        Q::new(ni.hi.clone(), di.lo.clone()),
        Q::new(ni.hi, di.hi),
    ];
    // invariant: the array has four corner quotients
    let a = c.iter().min().expect("four").clone();
    // invariant: the array has four corner quotients
    let b = c.iter().max().expect("four").clone();
    Some((a, b))
}

/// Cauchy's bound `1 + max |c_i / c_n|` on the absolute value of the roots.
fn cauchy(p: &IntPoly) -> Q {
    let lc = Q::from_integer(p.lc().abs());
    let m = p
        .coeffs()
        .iter()
        .map(|c| Q::from_integer(c.abs()))
        .max()
        .unwrap_or_else(Q::zero);
    q(1) + m / lc
}

/// The value `num(β)/den(β)`, known to be one of `candidates`: its index. Enclosures of the
/// value and of every candidate are narrowed until exactly one candidate's meets the value's
/// (the candidates are distinct numbers, and the value is one of them, so this ends); after
/// 2^-520 the exact path [`match_value_exact`] decides.
pub fn match_value(
    beta: &RealAlgebraic,
    num: &[Q],
    den: &[Q],
    candidates: &[RealAlgebraic],
) -> Option<usize> {
    if candidates.is_empty() {
        return None;
    }
    let (ni, di) = common_integers(num, den);
    let mut b = beta.clone();
    let mut cands: Vec<RealAlgebraic> = candidates.to_vec();
    let mut w = q(1) / q(1 << 20);
    for _ in 0..32 {
        b.refine_to(&w);
        let (lo, hi) = b.bounds();
        if let Some((vlo, vhi)) = ratio_on(&ni, &di, &lo, &hi) {
            let mut hit = None;
            let mut several = false;
            for (k, c) in cands.iter_mut().enumerate() {
                c.refine_to(&w);
                let (clo, chi) = c.bounds();
                if clo <= vhi && vlo <= chi {
                    if hit.is_some() {
                        several = true;
                        break;
                    }
                    hit = Some(k);
                }
            }
            if !several {
                return hit;
            }
        }
        w /= q(1 << 16);
    }
    match_value_exact(beta, num, den, candidates)
}

/// The value `num(β)/den(β)`, known to be one of `candidates`: its index (exact signs only; the
/// generic path [`match_value`] is tested against).
pub fn match_value_exact(
    beta: &RealAlgebraic,
    num: &[Q],
    den: &[Q],
    candidates: &[RealAlgebraic],
) -> Option<usize> {
    let sd = beta.sign_of_rationals(den);
    let (lo, hi) = beta.enclosure(&(q(1) / q(1 << 40)));
    let mid = (&lo + &hi) / q(2);
    let dv = horner(den, &mid);
    let guess = if dv.is_zero() {
        Q::zero()
    } else {
        horner(num, &mid) / dv
    };
    let d: Vec<Q> = candidates
        .iter()
        .map(|c| {
            let (a, b) = c.enclosure(&(q(1) / q(1 << 20)));
            ((a + b) / q(2) - &guess).abs()
        })
        .collect();
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&i, &j| d[i].cmp(&d[j]));
    let sub = |r: &Q| -> Ordering {
        let p = add(num, &den.iter().map(|c| -(c * r)).collect::<Vec<_>>());
        let s = beta.sign_of_rationals(&p);
        if sd == Ordering::Less { s.reverse() } else { s }
    };
    for k in order {
        match &candidates[k] {
            RealAlgebraic::Rational(r) => {
                if sub(r) == Ordering::Equal {
                    return Some(k);
                }
            }
            RealAlgebraic::Root(root) => {
                let (lo, hi) = root.interval();
                if sub(lo) == Ordering::Greater && sub(hi) == Ordering::Less {
                    return Some(k);
                }
            }
        }
    }
    None
}

/// What [`solve`] found.
#[derive(Clone, Debug)]
pub enum Solved {
    /// Finitely many solutions.
    Points {
        /// The solutions in the region.
        solutions: Vec<Solution>,
        /// `R_x` as a primitive integer polynomial.
        resultant: IntPoly,
    },
    /// The equations share a factor: a curve of solutions (or none, but not finitely many
    /// certified).
    Infinite,
}

fn roots(
    p: &IntPoly,
    range: &Option<(Q, Q)>,
) -> Result<Vec<(RealAlgebraic, usize)>, AlgebraicError> {
    let (a, b) = match range {
        Some(r) => r.clone(),
        None => {
            let c = cauchy(p);
            (-c.clone(), c)
        }
    };
    let mut out = Vec::new();
    for (f, m) in p.square_free_factors() {
        for r in RealAlgebraic::roots_in(&f, &a, &b)? {
            out.push((r, m));
        }
    }
    Ok(out)
}

/// Every solution of `f = g = 0` in `region`, each with whether each of `flags` vanishes there.
///
/// Where a solution shares its `x` with another solution and its `y` with another (so that
/// neither resultant's root has a single partner there), the system is solved again in
/// `(x, y − λ·x)` for a few small rational `λ`, which slants the lines `y = const` and leaves
/// the solutions where they are; each `y` is then identified among the roots of `R_y` by exact
/// signs (docs/theory.md §16.5). Refused only when no shear separates them.
pub fn solve(
    f: &BiPoly,
    g: &BiPoly,
    region: &Region,
    flags: &[BiPoly],
) -> Result<Solved, AlgebraicError> {
    let (ys, rx) = match solve_once(f, g, region, flags)? {
        Once::Done(solved) => return Ok(solved),
        Once::Tangled { ys, rx } => (ys, rx),
    };
    for lam in [
        q(1) / q(2),
        q(-1) / q(3),
        q(2) / q(3),
        q(-3) / q(5),
        q(3) / q(7),
    ] {
        let sheared = sheared_region(region, &lam);
        let fl: Vec<BiPoly> = flags.iter().map(|p| shear(p, &lam)).collect();
        let solutions = match solve_once(&shear(f, &lam), &shear(g, &lam), &sheared, &fl)? {
            Once::Done(Solved::Points { solutions, .. }) => solutions,
            Once::Done(Solved::Infinite) => return Ok(Solved::Infinite),
            Once::Tangled { .. } => continue,
        };
        let mut out = Vec::with_capacity(solutions.len());
        for sol in solutions {
            out.push(unshear(sol, &lam, &ys)?);
        }
        return Ok(Solved::Points {
            solutions: out,
            resultant: rx,
        });
    }
    Err(AlgebraicError::Unsupported(
        "a point where both unknowns have several partners (the equations meet more than once on both lines through it), even after shearing".into(),
    ))
}

/// The region in the sheared unknowns `(x, y' = y − λx)`: the `x`-range kept, the `y`-range
/// and every half-plane rewritten as half-planes, and a `y'`-range that contains them.
fn sheared_region(region: &Region, lam: &Q) -> Region {
    let mut halves: Vec<Half> = region
        .halves
        .iter()
        .map(|h| Half {
            a: &h.a + &h.b * lam,
            b: h.b.clone(),
            c: h.c.clone(),
        })
        .collect();
    let y = match (&region.x, &region.y) {
        (Some((xl, xh)), Some((lo, hi))) => {
            let (p, r) = (lam * xl, lam * xh);
            let (mn, mx) = if p <= r { (p, r) } else { (r, p) };
            Some((lo - mx, hi - mn))
        }
        _ => None,
    };
    if let Some((lo, hi)) = &region.y {
        // y' + λx − lo ≥ 0 and hi − y' − λx ≥ 0
        halves.push(Half {
            a: lam.clone(),
            b: q(1),
            c: -lo,
        });
        halves.push(Half {
            a: -lam,
            b: q(-1),
            c: hi.clone(),
        });
    }
    Region {
        x: region.x.clone(),
        y,
        halves,
    }
}

/// A solution of the sheared system as one of the original: `x` kept, `y = y' + λx`
/// identified among `ys` (the roots of `R_y` in the region); a partner over `x` stays one over
/// `x` (`y = (num + λ·x·den)/den`), a partner over `y'` becomes a sheared one.
fn unshear(sol: Solution, lam: &Q, ys: &[RealAlgebraic]) -> Result<Solution, AlgebraicError> {
    let internal =
        || AlgebraicError::Unsupported("a sheared solution that matches no root (internal)".into());
    let (num, den) = (&sol.partner.num, &sol.partner.den);
    if sol.partner.base_is_x {
        let num_y = add(num, &mul(&[Q::zero(), lam.clone()], den));
        let k = match_value(&sol.x, &num_y, den, ys).ok_or_else(internal)?;
        Ok(Solution {
            y: ys[k].clone(),
            partner: Partner {
                base_is_x: true,
                shear: Q::zero(),
                num: num_y,
                den: den.clone(),
            },
            ..sol
        })
    } else {
        // y = y' + λ·num/den = (y'·den + λ·num)/den over the base y'
        let lnum: Vec<Q> = num.iter().map(|c| c * lam).collect();
        let num_y = add(&mul(&[Q::zero(), Q::one()], den), &lnum);
        let k = match_value(&sol.y, &num_y, den, ys).ok_or_else(internal)?;
        Ok(Solution {
            x: sol.x,
            y: ys[k].clone(),
            multiplicity: sol.multiplicity,
            flags: sol.flags,
            partner: Partner {
                base_is_x: false,
                shear: lam.clone(),
                num: num.clone(),
                den: den.clone(),
            },
            sheared_base: Some(sol.y),
        })
    }
}

/// What one pass of the engine found.
enum Once {
    /// The solutions (or a shared factor).
    Done(Solved),
    /// A solution may be resolved from neither side: the roots of `R_y` in the region and
    /// `R_x`, for the sheared retry.
    Tangled { ys: Vec<RealAlgebraic>, rx: IntPoly },
}

/// One pass of [`solve`] in the given unknowns: the resultants `R_x = res_y(f, g)` and
/// `R_y = res_x(f, g)` and their roots in the region; each root `β` of `R_x` resolved over `x`
/// (`y = −c_0(β)/c_1(β)` by the first subresultant, [`solutions_over_x`]), those where `c_1(β)
/// = 0` deferred and resolved over `y` ([`deferred_solutions`]); then every solution's flags.
fn solve_once(
    f: &BiPoly,
    g: &BiPoly,
    region: &Region,
    flags: &[BiPoly],
) -> Result<Once, AlgebraicError> {
    let (f, g) = (&f.trimmed(), &g.trimmed());
    let Some(r) = Resultants::of(f, g, region)? else {
        return Ok(Once::Done(Solved::Infinite));
    };
    let OverX {
        mut solutions,
        deferred,
        matched,
    } = solutions_over_x(f, g, region, &r)?;
    if !deferred.is_empty() {
        match deferred_solutions(f, g, region, &r, &deferred, &matched) {
            Some(more) => solutions.extend(more),
            None => {
                return Ok(Once::Tangled {
                    ys: r.alpha_values,
                    rx: r.rx,
                });
            }
        }
    }
    set_flags(&mut solutions, flags);
    Ok(Once::Done(Solved::Points {
        solutions,
        resultant: r.rx,
    }))
}

/// The two resultants of a pass and their roots in the region.
struct Resultants {
    /// `R_x = res_y(f, g)`, a polynomial in `x`.
    rx: IntPoly,
    /// The roots `β` of `R_x` in the region's `x` range, with their multiplicities.
    betas: Vec<(RealAlgebraic, usize)>,
    /// The roots `α` of `R_y = res_x(f, g)` in the region's `y` range, with multiplicities.
    alphas: Vec<(RealAlgebraic, usize)>,
    /// The `α` alone.
    alpha_values: Vec<RealAlgebraic>,
}

impl Resultants {
    /// `None` when `f` or `g` is zero or a resultant vanishes (a common factor: infinitely
    /// many solutions). Errors: a resultant over the size caps.
    fn of(f: &BiPoly, g: &BiPoly, region: &Region) -> Result<Option<Self>, AlgebraicError> {
        if f.is_zero() || g.is_zero() {
            return Ok(None);
        }
        let rx = trim(resultant(f, g));
        if rx.is_empty() {
            return Ok(None);
        }
        let ry = trim(resultant(&f.swap().trimmed(), &g.swap().trimmed()));
        if ry.is_empty() {
            return Ok(None);
        }
        let rx_int = IntPoly::from_rationals(&rx);
        let ry_int = IntPoly::from_rationals(&ry);
        super::check_poly(&rx_int)?;
        super::check_poly(&ry_int)?;
        let betas = roots(&rx_int, &region.x)?;
        let alphas = roots(&ry_int, &region.y)?;
        let alpha_values = alphas.iter().map(|(a, _)| a.clone()).collect();
        Ok(Some(Resultants {
            rx: rx_int,
            betas,
            alphas,
            alpha_values,
        }))
    }
}

/// Does the value `v` lie in the closed range `r` (`None`: unbounded)?
fn in_range(v: &Expr, r: &Option<(Q, Q)>) -> bool {
    match r {
        None => true,
        Some((lo, hi)) => {
            v.cmp_rational(lo) != Ordering::Less && v.cmp_rational(hi) != Ordering::Greater
        }
    }
}

/// Is the point with coordinate `base` and the other `num/den` at `base` in the half-plane
/// `h`? With `base` the `x` coordinate (`base_is_x`): `a·β + b·num/den + c ≥ 0` ⟺
/// `((a x + c)·den + b·num)·den ≥ 0` at `β` (and the roles of `a` and `b` swapped for `y`).
fn half_ok(base: &RealAlgebraic, h: &Half, num: &[Q], den: &[Q], base_is_x: bool) -> bool {
    let (coef_base, coef_other) = if base_is_x {
        (&h.a, &h.b)
    } else {
        (&h.b, &h.a)
    };
    let lin = vec![h.c.clone(), coef_base.clone()];
    let p = add(
        &super::bivariate::mul(&lin, den),
        &num.iter().map(|x| x * coef_other).collect::<Vec<_>>(),
    );
    let s = base.sign_of_rationals(&p);
    let sd = base.sign_of_rationals(den);
    s == Ordering::Equal || s == sd
}

/// Is the point `(base, num/den at base)` (or `(num/den, base)` when `!base_is_x`) in the
/// region: the other coordinate `v` within its range, and every half-plane?
fn in_region(
    region: &Region,
    base: &RealAlgebraic,
    v: &Expr,
    num: &[Q],
    den: &[Q],
    base_is_x: bool,
) -> bool {
    let range = if base_is_x { &region.y } else { &region.x };
    in_range(v, range)
        && region
            .halves
            .iter()
            .all(|h| half_ok(base, h, num, den, base_is_x))
}

/// What resolving over `x` found ([`solutions_over_x`]).
struct OverX {
    /// The solutions `(β, y(β))` in the region.
    solutions: Vec<Solution>,
    /// The roots `β` where `c_1(β) = 0` (to be resolved over `y`).
    deferred: Vec<RealAlgebraic>,
    /// Which roots `α` of `R_y` a solution took.
    matched: Vec<bool>,
}

/// Each root `β` of `R_x` with `c_1(β) ≠ 0`: its partner `y = −c_0(β)/c_1(β)` (the first
/// subresultant `c_1(x)·y + c_0(x)`), kept when in the region and identified among the roots of
/// `R_y`. Errors: a partner that matches no root (internal).
fn solutions_over_x(
    f: &BiPoly,
    g: &BiPoly,
    region: &Region,
    r: &Resultants,
) -> Result<OverX, AlgebraicError> {
    let (c1, c0) = subresultant1(f, g);
    let nc0: Vec<Q> = c0.iter().map(|c| -c).collect();
    let mut out = OverX {
        solutions: Vec::new(),
        deferred: Vec::new(),
        matched: vec![false; r.alphas.len()],
    };
    for (beta, m) in &r.betas {
        if beta.sign_of_rationals(&c1) == Ordering::Equal {
            out.deferred.push(beta.clone());
            continue;
        }
        let yv = Expr {
            base: beta.clone(),
            num: nc0.clone(),
            den: c1.clone(),
        };
        if !in_region(region, beta, &yv, &nc0, &c1, true) {
            continue;
        }
        let Some(k) = match_value(beta, &nc0, &c1, &r.alpha_values) else {
            return Err(AlgebraicError::Unsupported(
                "a solution that matches no root of the second resultant (internal)".into(),
            ));
        };
        out.matched[k] = true;
        out.solutions.push(Solution {
            x: beta.clone(),
            y: r.alpha_values[k].clone(),
            multiplicity: *m,
            flags: Vec::new(),
            partner: Partner {
                base_is_x: true,
                shear: Q::zero(),
                num: nc0.clone(),
                den: c1.clone(),
            },
            sheared_base: None,
        });
    }
    Ok(out)
}

/// The solutions over the `deferred` roots `β`, resolved from the other side: each root `α` of
/// `R_y` not yet `matched` with `d_1(α) ≠ 0` has the partner `x = −d_0(α)/d_1(α)`, kept when in
/// the region and identified among the deferred `β`. `None` (tangled) when a pair `(β, α)` with
/// `d_1(α) = 0` cannot be excluded.
fn deferred_solutions(
    f: &BiPoly,
    g: &BiPoly,
    region: &Region,
    r: &Resultants,
    deferred: &[RealAlgebraic],
    matched: &[bool],
) -> Option<Vec<Solution>> {
    let (d1, d0) = subresultant1(&f.swap().trimmed(), &g.swap().trimmed());
    let nd0: Vec<Q> = d0.iter().map(|c| -c).collect();
    // A root α of R_y with d_1(α) = 0 may have several partners too, and one of them may be
    // a deferred β whatever else α is matched with: such a pair is resolved from neither
    // side. Unless the pair is excluded (f or g has one sign over the box of their
    // isolating intervals, or the box lies outside a half-plane), the engine refuses, and
    // [`solve`] shears (docs/theory.md §16.5): never a solution silently left out.
    let (fi, gi) = (IntBiPoly::from_bipoly(f), IntBiPoly::from_bipoly(g));
    for (alpha, _) in &r.alphas {
        if alpha.sign_of_rationals(&d1) != Ordering::Equal {
            continue;
        }
        for beta in deferred {
            if !pair_excluded(beta, alpha, &fi, &gi, &region.halves) {
                return None;
            }
        }
    }
    let mut solutions = Vec::new();
    for (k, (alpha, m)) in r.alphas.iter().enumerate() {
        if matched[k] || alpha.sign_of_rationals(&d1) == Ordering::Equal {
            continue;
        }
        let xv = Expr {
            base: alpha.clone(),
            num: nd0.clone(),
            den: d1.clone(),
        };
        if !in_region(region, alpha, &xv, &nd0, &d1, false) {
            continue;
        }
        let Some(j) = match_value(alpha, &nd0, &d1, deferred) else {
            continue;
        };
        solutions.push(Solution {
            x: deferred[j].clone(),
            y: alpha.clone(),
            multiplicity: *m,
            flags: Vec::new(),
            partner: Partner {
                base_is_x: false,
                shear: Q::zero(),
                num: nd0.clone(),
                den: d1.clone(),
            },
            sheared_base: None,
        });
    }
    Some(solutions)
}

/// Each solution's flags: which of `flags` vanish at it.
fn set_flags(solutions: &mut [Solution], flags: &[BiPoly]) {
    let int_flags: Vec<IntBiPoly> = flags.iter().map(IntBiPoly::from_bipoly).collect();
    for s in solutions.iter_mut() {
        s.flags = flags
            .iter()
            .zip(&int_flags)
            .map(|(g, gi)| flag_vanishes(s, g, gi))
            .collect();
    }
}

/// Is `(β, α)` provably not a solution in the region? At isolating widths 2^-20, 2^-60 and
/// 2^-120: `f` or `g` has one non-zero sign over the box `β-interval × α-interval`, or
/// `a·x + b·y + c` is negative over the whole box for one of the half-planes. `false` when
/// no refinement decides (as at a solution, where both enclosures contain 0).
fn pair_excluded(
    beta: &RealAlgebraic,
    alpha: &RealAlgebraic,
    fi: &IntBiPoly,
    gi: &IntBiPoly,
    halves: &[Half],
) -> bool {
    let (mut x, mut y) = (beta.clone(), alpha.clone());
    for k in [20u32, 60, 120] {
        let w = Q::new(BigInt::from(1), BigInt::from(1) << k);
        x.refine_to(&w);
        y.refine_to(&w);
        let (xl, xh) = x.bounds();
        let (yl, yh) = y.bounds();
        let (bx, by) = (Scaled::new(&xl, &xh), Scaled::new(&yl, &yh));
        let nonzero = |p: &IntBiPoly| {
            matches!(
                p.sign_on_box(&bx, &by),
                Some(Ordering::Less | Ordering::Greater)
            )
        };
        // the largest value of a·x + b·y + c over the box
        let outside = |h: &Half| {
            let ax = if h.a.is_negative() {
                &h.a * &xl
            } else {
                &h.a * &xh
            };
            let by = if h.b.is_negative() {
                &h.b * &yl
            } else {
                &h.b * &yh
            };
            (ax + by + &h.c).is_negative()
        };
        if nonzero(fi) || nonzero(gi) || halves.iter().any(outside) {
            return true;
        }
    }
    false
}

/// Does `g` vanish at the solution? First the box filter (the integer enclosure of `g` over
/// the isolating intervals of `x` and `y`, narrowed to 2^-20, 2^-60 and 2^-120), then the exact
/// sign of `den^N · g(β, num/den)` at the base value `β` ([`flag_vanishes_exact`]).
pub(crate) fn flag_vanishes(s: &Solution, g: &BiPoly, gi: &IntBiPoly) -> bool {
    let (mut x, mut y) = (s.x.clone(), s.y.clone());
    for k in [20u32, 60, 120] {
        let w = Q::new(BigInt::from(1), BigInt::from(1) << k);
        x.refine_to(&w);
        y.refine_to(&w);
        let (xl, xh) = x.bounds();
        let (yl, yh) = y.bounds();
        if let Some(sign) = gi.sign_on_box(&Scaled::new(&xl, &xh), &Scaled::new(&yl, &yh)) {
            return sign == Ordering::Equal;
        }
    }
    flag_vanishes_exact(s, g)
}

/// Does `g` vanish at the solution, by exact substitution (the generic path).
pub fn flag_vanishes_exact(s: &Solution, g: &BiPoly) -> bool {
    s.base().sign_of_rationals(&s.substitute(g)) == Ordering::Equal
}
