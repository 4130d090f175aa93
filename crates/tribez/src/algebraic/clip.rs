//! Two polynomial equations whose solution set is not finite, clipped to a closed region
//! (docs/theory.md §16.7): the degenerate answers of `locate` and `ray`.
//!
//! When `f` and `g` share a factor (or one of them is identically zero) the resultant vanishes
//! and [`solve`] gives up with [`Solved::Infinite`]. Here the common factor `h = gcd(f, g)`
//! (primitive remainder sequence in `Q[x][y]`; `h = g` when `f = 0`) splits the solutions into
//! the curve `h = 0` and the finitely many solutions of `f/h = g/h = 0`. The curve is clipped to
//! the region `{P_k ≥ 0}` (the `x`- and `y`-ranges and half-planes of a [`Region`], and further
//! polynomial conditions such as a ray's `τ ≥ 0`):
//!
//! * `h = c(x)·p(x, y)` with `c` the content in `y` (vertical lines `x = x0`, handled with the
//!   roles of `x` and `y` exchanged) and `p` primitive, both made square-free;
//! * the *critical* `x` values are the real roots of the leading coefficient `lc_y(p)`, of the
//!   discriminant-like `Res_y(p, ∂p/∂y)`, and of `Res_y(p/gcd(p, P_k), P_k)` for every condition
//!   (or `P_k` itself when it does not involve `y`), and the ends of the `x`-range. Between two
//!   consecutive critical values the real branches `y_1(x) < … < y_r(x)` of `p = 0` neither
//!   meet, nor escape, nor cross any `P_k = 0`, so each `P_k` has one sign along each branch:
//!   one rational sample `x*` per open interval decides, exactly, whether a piece of positive
//!   length lies in the region;
//! * every other point of the curve in the region lies over a critical value and is a solution
//!   of one of the zero-dimensional systems `p = ∂p/∂y = 0` (singular points, vertical
//!   tangents) or `p/gcd(p, P_k) = P_k = 0` (where the curve meets the region's boundary),
//!   solved by [`solve`] and kept when every `P_k ≥ 0` there (exact signs).
//!
//! Without a piece of positive length these points are the whole (finite) answer; with one,
//! the answer is that curve, and the points on the region's boundary are where its pieces end.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::bivariate::{BiPoly, resultant, trim};
use super::interval::IntBiPoly;
use super::system::{Region, Solution, Solved, flag_vanishes, solve};
use super::{AlgebraicError, IntPoly, RealAlgebraic, simplest_between};

type Q = BigRational;

fn q(k: i64) -> Q {
    Q::from_integer(BigInt::from(k))
}

/// What [`solve_clipped`] found.
#[derive(Clone, Debug)]
pub enum Clipped {
    /// Finitely many solutions in the region (possibly none).
    Points(Vec<Solution>),
    /// Pieces of positive length of the curve `curve = 0` lie in the region.
    Curve {
        /// The curve (the common factor of the equations, or the one that is not zero),
        /// square-free, with integer coefficients, primitive.
        curve: BiPoly,
        /// The points of the curve in the region on its boundary (some condition is zero
        /// there): where the pieces end (and points where the curve touches the boundary), by
        /// `x`, then `y`. Multiplicity 0.
        boundary: Vec<Solution>,
        /// Solutions of `f/h = g/h = 0` in the region off the curve.
        points: Vec<Solution>,
    },
    /// Both equations vanish identically: every point of the region is a solution.
    Region,
}

// ---- univariate polynomials over Q (ascending, trimmed) ----

fn scale1(p: &[Q], k: &Q) -> Vec<Q> {
    trim(p.iter().map(|x| x * k).collect())
}

/// `(quotient, remainder)` of `a` by the non-zero `b`.
fn divrem1(a: &[Q], b: &[Q]) -> (Vec<Q>, Vec<Q>) {
    let b = trim(b.to_vec());
    let mut r = trim(a.to_vec());
    let db = b.len() - 1;
    let lb = b[db].clone();
    let mut quo = vec![Q::zero(); r.len().saturating_sub(db)];
    while r.len() > db {
        let k = r.len() - 1 - db;
        let t = &r[r.len() - 1] / &lb;
        for (j, bj) in b.iter().enumerate() {
            r[k + j] -= &t * bj;
        }
        quo[k] = t;
        r = trim(r);
        // the leading coefficient cancelled exactly
    }
    (trim(quo), r)
}

fn monic1(p: &[Q]) -> Vec<Q> {
    let p = trim(p.to_vec());
    match p.last() {
        Some(l) => {
            let l = l.clone();
            p.iter().map(|x| x / &l).collect()
        }
        None => p,
    }
}

/// The monic gcd (`gcd(0, 0) = 0`).
fn gcd1(a: &[Q], b: &[Q]) -> Vec<Q> {
    let (mut a, mut b) = (monic1(a), monic1(b));
    while !b.is_empty() {
        let (_, r) = divrem1(&a, &b);
        a = b;
        b = monic1(&r);
    }
    a
}

fn deriv1(p: &[Q]) -> Vec<Q> {
    trim(
        p.iter()
            .enumerate()
            .skip(1)
            .map(|(i, x)| x * q(i as i64))
            .collect(),
    )
}

// ---- bivariate polynomials (in y, coefficients in x) ----

/// `p / c` for a univariate `c(x)` dividing every coefficient (`None` if it does not).
fn div_x(p: &BiPoly, c: &[Q]) -> Option<BiPoly> {
    let mut out = Vec::with_capacity(p.c.len());
    for a in &p.c {
        let (quo, r) = divrem1(a, c);
        if !r.is_empty() {
            return None;
        }
        out.push(quo);
    }
    Some(BiPoly { c: out }.trimmed())
}

/// The content in `y`: the monic gcd of the coefficients (zero for zero).
fn content_y(p: &BiPoly) -> Vec<Q> {
    p.c.iter().fold(Vec::new(), |g, a| gcd1(&g, a))
}

fn is_const(p: &BiPoly) -> bool {
    let p = p.trimmed();
    p.c.len() == 1 && p.c[0].len() <= 1
}

fn dy(p: &BiPoly) -> BiPoly {
    BiPoly {
        c: p.c
            .iter()
            .enumerate()
            .skip(1)
            .map(|(j, a)| scale1(a, &q(j as i64)))
            .collect(),
    }
    .trimmed()
}

/// The gcd in `Q[x][y]` ([`super::bivariate::gcd`], unique up to a rational constant),
/// normalised: integer coefficients, primitive, positive leading coefficient. `gcd(0, g) = g`
/// (normalised).
pub fn gcd(f: &BiPoly, g: &BiPoly) -> BiPoly {
    normalized(&super::bivariate::gcd(&f.trimmed(), &g.trimmed()))
}

/// `f / h` when `h` divides `f` in `Q[x][y]` (`None` otherwise; `h` non-zero).
pub fn div_exact(f: &BiPoly, h: &BiPoly) -> Option<BiPoly> {
    super::bivariate::div_exact(f, h).map(|p| p.trimmed())
}

/// Integer coefficients, divided by their gcd, the last non-zero coefficient (highest power of
/// `y`, then of `x`) positive.
fn normalized(p: &BiPoly) -> BiPoly {
    let p = p.trimmed();
    let all: Vec<&Q> = p.c.iter().flatten().filter(|x| !x.is_zero()).collect();
    if all.is_empty() {
        return p;
    }
    let l = all.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let g = all.iter().fold(BigInt::zero(), |g, x| {
        g.gcd(&(x.numer() * (&l / x.denom())))
    });
    let lead_negative =
        p.c.iter()
            .rev()
            .flat_map(|a| a.iter().rev())
            .find(|x| !x.is_zero())
            .is_some_and(|x| x.is_negative());
    let k = Q::new(if lead_negative { -l } else { l }, g);
    BiPoly {
        c: p.c.iter().map(|a| scale1(a, &k)).collect(),
    }
    .trimmed()
}

/// The square-free part of a polynomial primitive in `y`.
fn square_free_y(p: &BiPoly) -> BiPoly {
    let g = gcd(p, &dy(p));
    if is_const(&g) {
        return p.clone();
    }
    // invariant: gcd(p, ∂p/∂y) divides p
    div_exact(p, &g).expect("the gcd divides")
}

/// `h(x, y)` as text in the variables `x`, `y`: `s + 2t - 1`, `s^2·t - 3`.
pub fn bipoly_text(h: &BiPoly, x: &str, y: &str) -> String {
    let mut terms: Vec<(usize, usize, Q)> = Vec::new();
    for (j, a) in h.c.iter().enumerate() {
        for (i, c) in a.iter().enumerate() {
            if !c.is_zero() {
                terms.push((i, j, c.clone()));
            }
        }
    }
    // by total degree, then by the power of x, descending
    terms.sort_by_key(|t| std::cmp::Reverse((t.0 + t.1, t.0)));
    if terms.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    for (k, (i, j, c)) in terms.iter().enumerate() {
        let neg = c.is_negative();
        let a = c.abs();
        if k == 0 {
            if neg {
                out.push('-');
            }
        } else {
            out.push_str(if neg { " - " } else { " + " });
        }
        let pw = |v: &str, e: usize| match e {
            0 => None,
            1 => Some(v.to_string()),
            e => Some(format!("{v}^{e}")),
        };
        let mono: Vec<String> = [pw(x, *i), pw(y, *j)].into_iter().flatten().collect();
        let mono = mono.join("·");
        if mono.is_empty() {
            out.push_str(&a.to_string());
        } else if a.is_one() {
            out.push_str(&mono);
        } else if a.is_integer() {
            out.push_str(&format!("{a}{mono}"));
        } else {
            out.push_str(&format!("({a})·{mono}"));
        }
    }
    out
}

// ---- the region ----

/// The conditions `P ≥ 0` of a region: its ranges, its half-planes, then `extra`.
fn conditions(region: &Region, extra: &[BiPoly]) -> Vec<BiPoly> {
    let mut out = Vec::new();
    let lin = |a: Q, b: Q, c: Q| BiPoly {
        c: vec![vec![c, a], vec![b]],
    };
    if let Some((lo, hi)) = &region.x {
        out.push(lin(q(1), q(0), -lo.clone()));
        out.push(lin(q(-1), q(0), hi.clone()));
    }
    if let Some((lo, hi)) = &region.y {
        out.push(lin(q(0), q(1), -lo.clone()));
        out.push(lin(q(0), q(-1), hi.clone()));
    }
    for h in &region.halves {
        out.push(lin(h.a.clone(), h.b.clone(), h.c.clone()));
    }
    out.extend(extra.iter().map(BiPoly::trimmed));
    out.into_iter().map(|p| p.trimmed()).collect()
}

/// The sign of `p` at a solution, exactly.
fn sign_at(s: &Solution, p: &BiPoly) -> Ordering {
    let one = BiPoly {
        c: vec![vec![q(1)]],
    };
    s.ratio(p, &one).sign()
}

fn inside(s: &Solution, conds: &[BiPoly]) -> bool {
    conds.iter().all(|p| sign_at(s, p) != Ordering::Less)
}

fn on_boundary(s: &Solution, conds: &[BiPoly]) -> bool {
    conds.iter().any(|p| sign_at(s, p) == Ordering::Equal)
}

fn same(a: &Solution, b: &Solution) -> bool {
    a.x.cmp_exact(&b.x) == Ordering::Equal && a.y.cmp_exact(&b.y) == Ordering::Equal
}

fn push_new(out: &mut Vec<Solution>, s: Solution) {
    if !out.iter().any(|t| same(t, &s)) {
        out.push(s);
    }
}

/// Cauchy's bound on the roots of a non-zero polynomial (1 for a constant).
fn cauchy(p: &[Q]) -> Q {
    let p = trim(p.to_vec());
    let Some(lc) = p.last() else {
        return q(1);
    };
    let m = p
        .iter()
        .map(|c| (c / lc).abs())
        .max()
        .unwrap_or_else(Q::zero);
    q(1) + m
}

/// The real roots of `p` (rational coefficients, non-zero) in `[lo, hi]`.
fn real_roots(p: &[Q], lo: &Q, hi: &Q) -> Result<Vec<RealAlgebraic>, AlgebraicError> {
    let ip = IntPoly::from_rationals(&trim(p.to_vec()));
    if ip.degree().unwrap_or(0) == 0 {
        return Ok(Vec::new());
    }
    RealAlgebraic::roots_in(&ip, lo, hi)
}

/// A rational strictly between `a < b`.
fn between(a: &RealAlgebraic, b: &RealAlgebraic) -> Q {
    let mut w = q(1) / q(1 << 10);
    loop {
        let (_, ah) = a.enclosure(&w);
        let (bl, _) = b.enclosure(&w);
        if ah < bl {
            return simplest_between(&ah, &bl);
        }
        w /= q(1 << 16);
    }
}

/// The conditions with `x` and `y` exchanged; a solution likewise.
fn swap_solution(s: Solution) -> Solution {
    let mut partner = s.partner;
    partner.base_is_x = !partner.base_is_x;
    Solution {
        x: s.y,
        y: s.x,
        multiplicity: s.multiplicity,
        flags: s.flags,
        partner,
        sheared_base: s.sheared_base,
    }
}

/// The points of `{f = g = 0}` in `region` (and `extra`, each `P ≥ 0`), each with whether each
/// of `flags` vanishes there: finitely many ([`Clipped::Points`]), a curve with pieces of
/// positive length ([`Clipped::Curve`]), or the whole region ([`Clipped::Region`]; refused with
/// `extra` conditions, whose set in the region is not decided). `region` must be bounded or the
/// whole plane ([`Region::triangle`], [`Region::unit_square`], [`Region::plane`]).
pub fn solve_clipped(
    f: &BiPoly,
    g: &BiPoly,
    region: &Region,
    extra: &[BiPoly],
    flags: &[BiPoly],
) -> Result<Clipped, AlgebraicError> {
    let conds = conditions(region, extra);
    if let Solved::Points { solutions, .. } = solve(f, g, region, flags)? {
        // `solve` keeps to the region itself: only the further conditions are left
        let extra: Vec<BiPoly> = extra.iter().map(BiPoly::trimmed).collect();
        return Ok(Clipped::Points(
            solutions
                .into_iter()
                .filter(|s| inside(s, &extra))
                .collect(),
        ));
    }
    let (f, g) = (f.trimmed(), g.trimmed());
    if f.is_zero() && g.is_zero() {
        if conds
            .iter()
            .all(|p| is_const(p) && sign_const(p) != Ordering::Less)
            || extra.is_empty()
        {
            return Ok(Clipped::Region);
        }
        return Err(AlgebraicError::Unsupported(
            "both equations vanish identically (the patch lies on the ray's line)".into(),
        ));
    }
    let (h, rest) = if f.is_zero() {
        (normalized(&g), None)
    } else if g.is_zero() {
        (normalized(&f), None)
    } else {
        let h = gcd(&f, &g);
        let internal =
            || AlgebraicError::Unsupported("a gcd that does not divide (internal)".into());
        let a = div_exact(&f, &h).ok_or_else(internal)?;
        let b = div_exact(&g, &h).ok_or_else(internal)?;
        (h, Some((a, b)))
    };
    let mut points = Vec::new();
    if let Some((a, b)) = rest
        && !is_const(&a)
        && !is_const(&b)
    {
        match solve(&a, &b, region, &[])? {
            Solved::Points { solutions, .. } => {
                for s in solutions {
                    if inside(&s, &conds) {
                        push_new(&mut points, s);
                    }
                }
            }
            Solved::Infinite => {
                return Err(AlgebraicError::Unsupported(
                    "the equations divided by their gcd still share a factor (internal)".into(),
                ));
            }
        }
    }
    let (piece, on_curve) = clip_curve(&h, region, &conds)?;
    let int_flags: Vec<IntBiPoly> = flags.iter().map(IntBiPoly::from_bipoly).collect();
    let with_flags = |mut s: Solution| {
        s.flags = flags
            .iter()
            .zip(&int_flags)
            .map(|(g, gi)| flag_vanishes(&s, g, gi))
            .collect();
        s
    };
    let sort = |v: &mut Vec<Solution>| {
        v.sort_by(|a, b| a.x.cmp_exact(&b.x).then_with(|| a.y.cmp_exact(&b.y)));
    };
    if piece {
        let mut boundary: Vec<Solution> = on_curve
            .into_iter()
            .filter(|s| on_boundary(s, &conds))
            .map(with_flags)
            .collect();
        sort(&mut boundary);
        let mut off: Vec<Solution> = points
            .into_iter()
            .filter(|s| sign_at(s, &h) != Ordering::Equal)
            .map(with_flags)
            .collect();
        sort(&mut off);
        return Ok(Clipped::Curve {
            curve: h,
            boundary,
            points: off,
        });
    }
    for s in on_curve {
        push_new(&mut points, s);
    }
    let mut points: Vec<Solution> = points.into_iter().map(with_flags).collect();
    sort(&mut points);
    Ok(Clipped::Points(points))
}

fn sign_const(p: &BiPoly) -> Ordering {
    let p = p.trimmed();
    p.c[0]
        .first()
        .map_or(Ordering::Equal, |c| c.cmp(&Q::zero()))
}

/// The curve `h = 0` in the region `{P ≥ 0 : P ∈ conds}`: is there a piece of positive length,
/// and the points of the curve in the region over the critical `x` values (multiplicity 0).
fn clip_curve(
    h: &BiPoly,
    region: &Region,
    conds: &[BiPoly],
) -> Result<(bool, Vec<Solution>), AlgebraicError> {
    let h = h.trimmed();
    if is_const(&h) {
        return Ok((false, Vec::new()));
    }
    let c = content_y(&h);
    // invariant: the content in y divides h, by its definition
    let p = div_x(&h, &c).expect("the content divides");
    let mut piece = false;
    let mut points = Vec::new();
    if p.deg_y() >= 1 {
        let (pc, pts) = clip_primitive(&square_free_y(&p), region, conds)?;
        piece |= pc;
        points.extend(pts);
    }
    if c.len() >= 2 {
        // vertical lines x = x0: the same with x and y exchanged
        let c = divrem1(&c, &gcd1(&c, &deriv1(&c))).0;
        let lines = BiPoly { c: vec![c] }.swap().trimmed();
        let swapped = Region {
            x: region.y.clone(),
            y: region.x.clone(),
            halves: Vec::new(),
        };
        let conds: Vec<BiPoly> = conds.iter().map(|p| p.swap().trimmed()).collect();
        let (pc, pts) = clip_primitive(&lines, &swapped, &conds)?;
        piece |= pc;
        for s in pts {
            push_new(&mut points, swap_solution(s));
        }
    }
    Ok((piece, points))
}

/// [`clip_curve`] for `p` primitive and square-free with `deg_y p ≥ 1`.
fn clip_primitive(
    p: &BiPoly,
    region: &Region,
    conds: &[BiPoly],
) -> Result<(bool, Vec<Solution>), AlgebraicError> {
    let p = p.trimmed();
    let py = dy(&p);
    let mut critical: Vec<Vec<Q>> = vec![p.c[p.deg_y()].clone(), trim(resultant(&p, &py))];
    let mut systems: Vec<(BiPoly, BiPoly)> = vec![(p.clone(), py)];
    for k in conds {
        if is_const(k) {
            continue;
        }
        let pk = div_exact(&p, &gcd(&p, k)).ok_or_else(|| {
            AlgebraicError::Unsupported("a gcd that does not divide (internal)".into())
        })?;
        if is_const(&pk) {
            continue; // the whole curve lies on P_k = 0
        }
        critical.push(if k.deg_y() == 0 {
            k.c[0].clone()
        } else {
            trim(resultant(&pk, k))
        });
        systems.push((pk, k.clone()));
    }
    for c in &critical {
        if c.is_empty() {
            return Err(AlgebraicError::Unsupported(
                "a critical polynomial that vanishes identically (internal)".into(),
            ));
        }
    }
    // the critical x values, sorted, each once
    let (lo, hi) = match &region.x {
        Some(r) => r.clone(),
        None => {
            let b = critical
                .iter()
                .map(|c| cauchy(c))
                .max()
                .unwrap_or_else(|| q(1));
            (-b.clone(), b)
        }
    };
    let mut xs: Vec<RealAlgebraic> = Vec::new();
    if region.x.is_some() {
        xs.push(RealAlgebraic::rational(lo.clone()));
        xs.push(RealAlgebraic::rational(hi.clone()));
    }
    for c in &critical {
        xs.extend(real_roots(c, &lo, &hi)?);
    }
    xs.sort_by(|a, b| a.cmp_exact(b));
    xs.dedup_by(|a, b| a.cmp_exact(b) == Ordering::Equal);
    // one rational sample per open interval between critical values
    let mut samples: Vec<Q> = xs.windows(2).map(|w| between(&w[0], &w[1])).collect();
    if region.x.is_none() {
        match (xs.first(), xs.last()) {
            (Some(a), Some(b)) => {
                samples.push(a.bounds().0 - q(1));
                samples.push(b.bounds().1 + q(1));
            }
            _ => samples.push(q(0)),
        }
    }
    let mut piece = false;
    'samples: for x in &samples {
        let fy = trim(p.at_x(x));
        let b = cauchy(&fy);
        for y in real_roots(&fy, &-b.clone(), &b)? {
            if conds
                .iter()
                .all(|k| y.sign_of_rationals(&trim(k.at_x(x))) != Ordering::Less)
            {
                piece = true;
                break 'samples;
            }
        }
    }
    let ranges = Region {
        x: region.x.clone(),
        y: region.y.clone(),
        halves: Vec::new(),
    };
    let mut points = Vec::new();
    for (a, b) in &systems {
        match solve(a, b, &ranges, &[])? {
            Solved::Points { solutions, .. } => {
                for mut s in solutions {
                    if inside(&s, conds) {
                        s.multiplicity = 0;
                        push_new(&mut points, s);
                    }
                }
            }
            Solved::Infinite => {
                return Err(AlgebraicError::Unsupported(
                    "a curve and a boundary that share a factor after division (internal)".into(),
                ));
            }
        }
    }
    Ok((piece, points))
}

#[cfg(test)]
mod tests {
    use super::super::bivariate::{add, mul};
    use super::*;

    fn bp(rows: &[&[i64]]) -> BiPoly {
        BiPoly {
            c: rows
                .iter()
                .map(|r| r.iter().map(|&k| q(k)).collect())
                .collect(),
        }
    }

    fn bi_mul(a: &BiPoly, b: &BiPoly) -> BiPoly {
        let mut c = vec![Vec::new(); a.c.len() + b.c.len() - 1];
        for (j, pa) in a.c.iter().enumerate() {
            for (k, pb) in b.c.iter().enumerate() {
                c[j + k] = add(&c[j + k], &mul(pa, pb));
            }
        }
        BiPoly { c }.trimmed()
    }

    #[test]
    fn gcd_of_products() {
        // f = (x + 2y − 1)(x − y), g = (x + 2y − 1)(y + 3): gcd x + 2y − 1
        let l = bp(&[&[-1, 1], &[2]]);
        let f = bi_mul(&l, &bp(&[&[0, 1], &[-1]]));
        let g = bi_mul(&l, &bp(&[&[3], &[1]]));
        assert_eq!(gcd(&f, &g), l);
        // contents in x: f = x(x − 2), g = x^2 − 4 (no y): gcd x − 2
        assert_eq!(
            gcd(&bp(&[&[0, -2, 1]]), &bp(&[&[-4, 0, 1]])),
            bp(&[&[-2, 1]])
        );
        // coprime
        assert_eq!(gcd(&bp(&[&[0, 1]]), &bp(&[&[0], &[1]])), bp(&[&[1]]));
        assert_eq!(div_exact(&f, &l), Some(bp(&[&[0, 1], &[-1]])));
        assert_eq!(bipoly_text(&l, "s", "t"), "s + 2t - 1");
    }
}
