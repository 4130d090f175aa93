//! The judge of inverse problems (docs/theory.md §16): the exact answer of an `intersect`,
//! `locate`, `ray` or `height` query (real algebraic numbers), and claimed parameter tuples
//! judged against it — what an inverse claim ([`crate::claims::ops::inverse`]) and a row of an
//! inverse batch ([`crate::batch::inverse`]) share.
//!
//! A claimed tuple `c` and an exact solution `x` *accept* each other when every coordinate
//! satisfies `|c_k − x_k| ≤ 2^-20 · max(1, |x_k|)` ([`MATCH_RADIUS`], on the nearest floats) and
//! the tolerance accepts every `c_k` against the algebraic value `x_k` itself ([`accepts`]:
//! enclosures narrowed until both ends get the same verdict). The claimed tuples pass when a
//! maximum matching of this bipartite relation (Hopcroft and Karp) pairs every tuple and every
//! solution ([`findings`]); otherwise what it leaves unpaired is reported as
//! [`InverseFinding`]s, each with its text ([`FindingText`], [`judge_answer`]).

use std::borrow::Cow;
use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use crate::algebraic::{
    AlgebraicError, Curve, Expr, RealAlgebraic, intersect_curves, locate, ray_hits,
};
use crate::any_patch::AnyPatch;
use crate::certify::measures::{Leaf, Measures, Tolerance, ToleranceNeeds};
use crate::float::Precision;
use crate::patch_type::Patch;

type Q = BigRational;

/// Claimed and exact tuples may be paired only when every coordinate differs by at most
/// `2^-20 · max(1, |exact|)` (and the tolerance accepts them: [`findings`]).
pub const MATCH_RADIUS_LOG2: i32 = -20;
/// `2^MATCH_RADIUS_LOG2`, for the docs.
pub const MATCH_RADIUS: f64 = 1.0 / 1_048_576.0;
/// The largest number of claimed tuples one claim (or one row of an inverse batch) may list.
pub const MAX_CLAIMED: usize = 10_000;

/// The query of an inverse claim.
#[derive(Clone, Debug)]
pub enum InverseQuery<'a> {
    /// `intersect`: two named curves.
    Intersect {
        /// The curves' names under `[patches]`.
        names: [String; 2],
        /// The first curve.
        a: Cow<'a, Patch>,
        /// The second curve.
        b: Cow<'a, Patch>,
    },
    /// `locate`: a point of the plane.
    Locate {
        /// The planar triangle patch.
        patch: Cow<'a, Patch>,
        /// The point.
        point: [Q; 2],
        /// Search the whole parameter plane?
        anywhere: bool,
    },
    /// `ray`: a ray in space.
    Ray {
        /// The patch in ℝ³ (or functional).
        patch: Cow<'a, Patch>,
        /// Its origin.
        origin: [Q; 3],
        /// Its direction.
        direction: [Q; 3],
    },
    /// `ray` with `height`: the vertical line through a point of a functional patch's domain.
    Height {
        /// The functional triangle patch.
        patch: Cow<'a, Patch>,
        /// The point (x, y).
        at: [Q; 2],
    },
}

impl InverseQuery<'_> {
    /// The exact answer (intersect: by `s`; locate: by `s`, then `t`; ray: by `τ`).
    pub fn answer(&self) -> Result<InverseAnswer, AlgebraicError> {
        let alg = |x: &RealAlgebraic| ExactNumber::Algebraic(x.clone());
        match self {
            InverseQuery::Intersect { names, a, b } => {
                let ca = Curve::from_patch(a, &names[0])?;
                let cb = Curve::from_patch(b, &names[1])?;
                let r = intersect_curves(&ca, &cb)?;
                let infinite = (!r.overlaps.is_empty()).then(|| {
                    let parts: Vec<String> = r
                        .overlaps
                        .iter()
                        .map(|o| {
                            format!(
                                "s from {} to {}, t from {} to {}",
                                o.s[0].decimal(17),
                                o.s[1].decimal(17),
                                o.t[0].decimal(17),
                                o.t[1].decimal(17)
                            )
                        })
                        .collect();
                    format!("the curves share a piece: {}", parts.join("; "))
                });
                Ok(InverseAnswer {
                    names: &["s", "t"],
                    solutions: r
                        .points
                        .iter()
                        .map(|p| vec![alg(&p.s), alg(&p.t)])
                        .collect(),
                    infinite,
                })
            }
            InverseQuery::Locate {
                patch,
                point,
                anywhere,
            } => {
                let r = locate(patch, point, *anywhere)?;
                Ok(InverseAnswer {
                    names: &["s", "t"],
                    solutions: r
                        .points
                        .iter()
                        .map(|p| vec![alg(&p.s), alg(&p.t)])
                        .collect(),
                    infinite: r.degenerate.as_ref().map(|d| {
                        let region = if *anywhere {
                            "the plane"
                        } else {
                            "the closed triangle"
                        };
                        if d.dimension == 2 {
                            format!("every parameter point of {region} maps to the point")
                        } else {
                            format!(
                                "a whole curve of parameters maps to the point: the pieces of {} = 0 in {region}{}",
                                d.curve,
                                boundary_text(d.boundary.iter().map(|l| (&l.s, &l.t)))
                            )
                        }
                    }),
                })
            }
            InverseQuery::Ray {
                patch,
                origin,
                direction,
            } => {
                let r = ray_hits(patch, origin, direction)?;
                Ok(InverseAnswer {
                    names: &["tau", "s", "t"],
                    solutions: r
                        .hits
                        .iter()
                        .map(|h| vec![ExactNumber::Expr(h.tau.clone()), alg(&h.s), alg(&h.t)])
                        .collect(),
                    infinite: r.degenerate.as_ref().map(|d| {
                        if d.dimension == 2 {
                            "the patch lies on the ray's line".to_string()
                        } else {
                            format!(
                                "the ray runs along the surface: the parameters on the pieces of {} = 0 in the closed triangle with τ ≥ 0{}",
                                d.curve,
                                boundary_text(d.boundary.iter().map(|h| (&h.s, &h.t)))
                            )
                        }
                    }),
                })
            }
            InverseQuery::Height { patch, at } => {
                // (x, y)'s barycentric coordinates (1 − s − t, s, t) in the domain; outside the
                // closed triangle the vertical line misses the patch
                let AnyPatch::Functional(f) = patch.as_any() else {
                    return Err(AlgebraicError::Shape(
                        "`height` takes a functional patch".into(),
                    ));
                };
                let lambda = f
                    .domain_or_reference()
                    .barycentric(at)
                    .map_err(|e| AlgebraicError::Shape(e.to_string()))?;
                let solutions = if lambda.iter().any(|l| l < &Q::zero()) {
                    Vec::new()
                } else {
                    let z = patch
                        .evaluate(&lambda)
                        .map_err(|e| AlgebraicError::Shape(e.to_string()))?;
                    vec![
                        [&z[0], &lambda[1], &lambda[2]]
                            .into_iter()
                            .map(|x| ExactNumber::Algebraic(RealAlgebraic::rational(x.clone())))
                            .collect(),
                    ]
                };
                Ok(InverseAnswer {
                    names: &["z", "s", "t"],
                    solutions,
                    infinite: None,
                })
            }
        }
    }
}

/// One exact coordinate of a solution: an algebraic number, or a rational function of one.
#[derive(Clone, Debug)]
pub enum ExactNumber {
    /// A real algebraic number.
    Algebraic(RealAlgebraic),
    /// `num(β)/den(β)`.
    Expr(Expr),
}

impl ExactNumber {
    /// The rational value, when it is rational.
    pub fn rational(&self) -> Option<Q> {
        match self {
            ExactNumber::Algebraic(x) => x.as_rational().cloned(),
            ExactNumber::Expr(e) => e.rational(),
        }
    }

    /// A rational enclosure of width at most `width`.
    pub fn enclosure(&self, width: &Q) -> (Q, Q) {
        match self {
            ExactNumber::Algebraic(x) => x.enclosure(width),
            ExactNumber::Expr(e) => e.enclosure(width),
        }
    }

    /// The nearest `f64`.
    pub fn to_f64(&self) -> f64 {
        match self {
            ExactNumber::Algebraic(x) => x.to_f64(),
            ExactNumber::Expr(e) => e.to_f64(),
        }
    }

    /// Exact text: `p/q`, or `≈ decimal (root of … in (lo, hi))`.
    pub fn text(&self) -> String {
        match self {
            ExactNumber::Algebraic(x) => x.to_text(),
            ExactNumber::Expr(e) => match e.rational() {
                Some(r) => r.to_string(),
                None => format!(
                    "≈ {} (a rational function of {})",
                    e.decimal(),
                    e.base.to_text()
                ),
            },
        }
    }
}

/// JSON: the algebraic number's or the expression's own ([`RealAlgebraic::to_json`],
/// [`Expr::to_json`]).
impl serde::Serialize for ExactNumber {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            ExactNumber::Algebraic(x) => x.serialize(s),
            ExactNumber::Expr(e) => e.serialize(s),
        }
    }
}

/// The exact answer of an inverse claim.
#[derive(Clone, Debug)]
pub struct InverseAnswer {
    /// The coordinates' names: `s, t` (intersect, locate) or `τ, s, t` (ray).
    pub names: &'static [&'static str],
    /// The isolated solutions (intersect: by `s`; locate: by `s`, then `t`; ray: by `τ`).
    pub solutions: Vec<Vec<ExactNumber>>,
    /// Why the answer is not a finite set of points, if it is not (overlapping curves; a curve
    /// of parameters; a ray along the surface).
    pub infinite: Option<String>,
}

/// What judging found wrong with an inverse claim: data, turned into the report's mismatches.
#[derive(Clone, Debug)]
pub enum InverseFinding {
    /// An exact solution that no claimed tuple is paired with.
    Missed {
        /// Its index among the exact solutions.
        solution: usize,
    },
    /// A claimed tuple paired with no exact solution.
    Extra {
        /// Its index in `expect`.
        claimed: usize,
        /// The nearest exact solution, if any.
        nearest: Option<usize>,
        /// Why it cannot be matched although some solutions accept it, if they do.
        blocked: Option<Blocked>,
    },
    /// A claimed tuple that no exact solution left unmatched accepts: a coordinate that breaks
    /// the tolerance against the nearest unmatched solution within the radius.
    Coordinate {
        /// The claimed tuple.
        claimed: usize,
        /// The exact solution it is compared with (the nearest unmatched one).
        solution: usize,
        /// Why it cannot be matched with a solution that accepts it, if some do.
        blocked: Option<Blocked>,
        /// The coordinate.
        coordinate: usize,
        /// The error against the algebraic value (measured at a rational within 2^-80 of it).
        measures: Measures,
    },
    /// A claimed count that differs.
    Count {
        /// Claimed.
        claimed: usize,
        /// Exact.
        exact: usize,
    },
    /// The answer is not a finite set of points.
    Infinite {
        /// What it is.
        what: String,
    },
}

/// A Hall violator of the matching ([`findings`]): claimed tuples (among them the one reported)
/// that are together accepted by fewer exact solutions than there are tuples, so that one of them
/// is left unmatched whatever the pairing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Blocked {
    /// The claimed tuples (indices in `expect`), in order.
    pub claimed: Vec<usize>,
    /// Every exact solution that accepts one of them (fewer than `claimed`), in order.
    pub solutions: Vec<usize>,
}

/// A finding as text: where, the claimed tuple, the exact solution (in full: polynomial,
/// isolating interval, decimal value) and why it is not accepted. An inverse claim reports it as
/// a mismatch, an inverse batch as a row's mismatch.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FindingText {
    /// Where: `solution 1`, `[0]` (the first claimed tuple), `[0][1]` (its second coordinate),
    /// `count`.
    pub path: String,
    /// The claimed tuple, as text.
    pub claimed: String,
    /// The exact solution, as text.
    pub exact: String,
    /// Why it is not accepted.
    pub reason: String,
}

fn tuple_text(xs: &[ExactNumber], names: &[&str]) -> String {
    let parts: Vec<String> = names
        .iter()
        .zip(xs)
        .map(|(n, x)| match x.rational() {
            Some(r) => format!("{n} = {r}"),
            None => format!("{n} {}", x.text()),
        })
        .collect();
    format!("({})", parts.join(", "))
}

fn claimed_text(xs: &[Q]) -> String {
    let parts: Vec<String> = xs
        .iter()
        .map(|x| crate::number::to_decimal_string(x, 17))
        .collect();
    format!("({})", parts.join(", "))
}

/// `, meeting the boundary at (s, t) = (…), (…)` (nothing for no point).
fn boundary_text<'b>(
    points: impl Iterator<Item = (&'b RealAlgebraic, &'b RealAlgebraic)>,
) -> String {
    let parts: Vec<String> = points
        .map(|(s, t)| format!("({}, {})", s.to_text(), t.to_text()))
        .collect();
    if parts.is_empty() {
        String::new()
    } else {
        format!(", meeting the boundary at (s, t) = {}", parts.join(", "))
    }
}

/// Does `tolerance` accept `claimed` for the exact number `x`? Enclosures of `x` are narrowed
/// (2^-80, then by 2^-64 at a time, at most to 2^-848) until both ends get the same verdict.
/// Also returns the rational the measures are taken at (exact, or the last enclosure's
/// midpoint).
pub fn accepts(
    claimed: &Q,
    x: &ExactNumber,
    tolerance: &Tolerance,
    leaf: &Leaf,
) -> Result<(bool, Q), ToleranceNeeds> {
    if let Some(r) = x.rational() {
        return Ok((tolerance.accepts(claimed, &r, leaf)?, r));
    }
    let mut w = Q::new(BigInt::from(1), BigInt::from(1) << 80u32);
    let mut mid = Q::zero();
    for _ in 0..12 {
        let (lo, hi) = x.enclosure(&w);
        mid = (&lo + &hi) / Q::from_integer(BigInt::from(2));
        let a = tolerance.accepts(claimed, &lo, leaf)?;
        if a == tolerance.accepts(claimed, &hi, leaf)? {
            return Ok((a, mid));
        }
        w /= Q::from_integer(BigInt::from(1) << 64u32);
    }
    Ok((false, mid))
}

/// The largest coordinate distance between a claimed tuple and an exact solution's nearest
/// floats, if every coordinate lies within the pairing radius [`MATCH_RADIUS`] (relative to the
/// value's size above 1).
fn within_radius(c: &[Q], e: &[f64]) -> Option<f64> {
    let radius = 2f64.powi(MATCH_RADIUS_LOG2);
    let mut worst = 0f64;
    for (cq, ef) in c.iter().zip(e) {
        let d = (crate::number::round_f64(cq) - ef).abs();
        if d.is_nan() || d > radius * ef.abs().max(1.0) {
            return None;
        }
        worst = worst.max(d);
    }
    Some(worst)
}

/// A maximum matching of a bipartite graph by Hopcroft and Karp's algorithm (an O(E √V) sequence
/// of phases, each a breadth-first layering from the unmatched left vertices and a depth-first
/// search of vertex-disjoint shortest augmenting paths; the search is iterative, so a long path
/// cannot overflow the stack). `adj[i]` lists the right vertices `0..n_right` adjacent to left
/// vertex `i`, in the order they are tried (nearest first, so that a matching of nearest pairs
/// is kept where one is maximum). Returns the partner of each left vertex.
fn maximum_matching(adj: &[Vec<usize>], n_right: usize) -> Vec<Option<usize>> {
    const FAR: usize = usize::MAX;
    let n = adj.len();
    let mut left: Vec<Option<usize>> = vec![None; n];
    let mut right: Vec<Option<usize>> = vec![None; n_right];
    let mut dist = vec![FAR; n];
    let mut queue = std::collections::VecDeque::new();
    let mut next = vec![0usize; n];
    let mut stack = Vec::new();
    loop {
        // layers: unmatched left vertices at 0, then along alternating paths
        queue.clear();
        for (u, (d, l)) in dist.iter_mut().zip(&left).enumerate() {
            *d = if l.is_none() {
                queue.push_back(u);
                0
            } else {
                FAR
            };
        }
        let mut free_reached = false;
        while let Some(u) = queue.pop_front() {
            for &v in &adj[u] {
                match right[v] {
                    None => free_reached = true,
                    Some(w) if dist[w] == FAR => {
                        dist[w] = dist[u] + 1;
                        queue.push_back(w);
                    }
                    Some(_) => {}
                }
            }
        }
        if !free_reached {
            return left;
        }
        // augmenting paths along the layers, vertex-disjoint (a dead end leaves its layer)
        next.fill(0);
        for root in 0..n {
            if left[root].is_some() {
                continue;
            }
            stack.clear();
            stack.push(root);
            while let Some(&u) = stack.last() {
                let Some(&v) = adj[u].get(next[u]) else {
                    dist[u] = FAR;
                    stack.pop();
                    continue;
                };
                next[u] += 1;
                match right[v] {
                    None => {
                        // flip the path: each vertex of the stack takes the edge it last tried
                        for &x in &stack {
                            let y = adj[x][next[x] - 1];
                            left[x] = Some(y);
                            right[y] = Some(x);
                        }
                        stack.clear();
                    }
                    Some(w) if dist[w] == dist[u].saturating_add(1) => stack.push(w),
                    Some(_) => {}
                }
            }
        }
    }
}

/// The Hall violator through the unmatched left vertex `i`: the left vertices reachable from it
/// by alternating paths (an edge, then a matched edge back), and their neighbours. With the
/// matching maximum, every such neighbour is matched, to one of those left vertices, so there
/// is one neighbour fewer than left vertices.
fn hall_violator(i: usize, adj: &[Vec<usize>], left: &[Option<usize>], n_right: usize) -> Blocked {
    let mut right_of = vec![None; n_right];
    for (u, v) in left.iter().enumerate() {
        if let Some(v) = v {
            right_of[*v] = Some(u);
        }
    }
    let mut seen_left = vec![false; adj.len()];
    let mut seen_right = vec![false; n_right];
    let mut todo = vec![i];
    seen_left[i] = true;
    while let Some(u) = todo.pop() {
        for &v in &adj[u] {
            if !seen_right[v] {
                seen_right[v] = true;
                if let Some(w) = right_of[v].filter(|&w| !seen_left[w]) {
                    seen_left[w] = true;
                    todo.push(w);
                }
            }
        }
    }
    let on = |xs: Vec<bool>| -> Vec<usize> {
        xs.iter()
            .enumerate()
            .filter(|x| *x.1)
            .map(|x| x.0)
            .collect()
    };
    Blocked {
        claimed: on(seen_left),
        solutions: on(seen_right),
    }
}

/// Judge findings of claimed tuples against the exact answer (the typed core of `judge_answer`;
/// `Err` when the tolerance needs what an inverse claim lacks, e.g. `bound`).
///
/// The verdict is that of a matching: claimed tuple `i` may be matched with exact solution `j`
/// when every coordinate lies within the pairing radius ([`MATCH_RADIUS`]) and the tolerance
/// accepts every coordinate of `i` against the algebraic value of `j`. The claim holds when a
/// maximum matching of that bipartite graph (Hopcroft and Karp's algorithm) pairs every
/// claimed tuple and every exact solution, each with a distinct partner (so the counts agree);
/// whether it does is independent of the order of the tuples. Otherwise every tuple and solution
/// the matching leaves unpaired is a finding: an unpaired tuple is compared with the nearest
/// unpaired solution within the radius (the coordinates that break the tolerance), or else is
/// *extra*; an unpaired solution is *missed*. An unpaired tuple that some solutions do accept
/// carries the Hall violator that blocks it ([`Blocked`]): tuples accepted, together, by fewer
/// solutions than there are tuples.
pub fn findings(
    claimed_tuples: Option<&[Vec<Q>]>,
    claimed_count: usize,
    answer: &InverseAnswer,
    tolerance: &Tolerance,
    precision: Option<Precision>,
) -> Result<Vec<InverseFinding>, ToleranceNeeds> {
    let mut out = Vec::new();
    if let Some(what) = &answer.infinite {
        out.push(InverseFinding::Infinite { what: what.clone() });
    }
    let Some(tuples) = claimed_tuples else {
        if claimed_count != answer.solutions.len() {
            out.push(InverseFinding::Count {
                claimed: claimed_count,
                exact: answer.solutions.len(),
            });
        }
        return Ok(out);
    };
    let approx: Vec<Vec<f64>> = answer
        .solutions
        .iter()
        .map(|s| s.iter().map(ExactNumber::to_f64).collect())
        .collect();
    let leaf = Leaf {
        precision,
        ..Leaf::default()
    };
    let n_exact = answer.solutions.len();
    // the pairs within the radius, nearest first; the accepted ones are the matching's edges
    let mut near: Vec<Vec<(f64, usize)>> = Vec::with_capacity(tuples.len());
    let mut adj: Vec<Vec<usize>> = Vec::with_capacity(tuples.len());
    for c in tuples {
        let mut cands: Vec<(f64, usize)> = approx
            .iter()
            .enumerate()
            .filter_map(|(j, e)| within_radius(c, e).map(|d| (d, j)))
            .collect();
        cands.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(Ordering::Equal));
        let mut edges = Vec::new();
        for &(_, j) in &cands {
            let mut all = true;
            for (cq, x) in c.iter().zip(&answer.solutions[j]) {
                if !accepts(cq, x, tolerance, &leaf)?.0 {
                    all = false;
                    break;
                }
            }
            if all {
                edges.push(j);
            }
        }
        near.push(cands);
        adj.push(edges);
    }
    let matching = maximum_matching(&adj, n_exact);
    let mut used = vec![false; n_exact];
    for j in matching.iter().flatten() {
        used[*j] = true;
    }
    for (i, c) in tuples.iter().enumerate() {
        if matching[i].is_some() {
            continue;
        }
        let blocked = (!adj[i].is_empty()).then(|| hall_violator(i, &adj, &matching, n_exact));
        // the nearest solution within the radius that the matching left unpaired
        let Some(&(_, j)) = near[i].iter().find(|(_, j)| !used[*j]) else {
            let nearest = (0..approx.len()).min_by(|&a, &b| {
                let d = |k: usize| -> f64 {
                    c.iter()
                        .zip(&approx[k])
                        .map(|(x, e)| (crate::number::round_f64(x) - e).abs())
                        .fold(0.0, f64::max)
                };
                d(a).partial_cmp(&d(b)).unwrap_or(Ordering::Equal)
            });
            out.push(InverseFinding::Extra {
                claimed: i,
                nearest,
                blocked,
            });
            continue;
        };
        used[j] = true;
        let before = out.len();
        for (k, (cq, x)) in c.iter().zip(&answer.solutions[j]).enumerate() {
            let (ok, at) = accepts(cq, x, tolerance, &leaf)?;
            if !ok {
                out.push(InverseFinding::Coordinate {
                    claimed: i,
                    solution: j,
                    blocked: blocked.clone(),
                    coordinate: k,
                    measures: Measures::new(cq, &at, precision),
                });
            }
        }
        if out.len() == before {
            // unreachable with a maximum matching (i and j would be an augmenting path), but
            // an unmatched tuple must never pass
            out.push(InverseFinding::Extra {
                claimed: i,
                nearest: Some(j),
                blocked,
            });
        }
    }
    for (j, u) in used.iter().enumerate() {
        if !u {
            out.push(InverseFinding::Missed { solution: j });
        }
    }
    Ok(out)
}

/// Judge claimed tuples (or, with `claimed_tuples` `None`, a bare claimed count) against the
/// exact answer: every finding with its text (the exact solution shown in full). What an
/// inverse claim ([`crate::claims::ops::inverse::judge`]) and a row of an inverse batch
/// ([`crate::batch::inverse`]) both call. `Err` when the tolerance needs what an inverse answer lacks (`cond`, `bound`).
pub fn judge_answer(
    claimed_tuples: Option<&[Vec<Q>]>,
    claimed_count: usize,
    answer: &InverseAnswer,
    tolerance: &Tolerance,
    precision: Option<Precision>,
) -> Result<Vec<(InverseFinding, FindingText)>, ToleranceNeeds> {
    Ok(
        findings(claimed_tuples, claimed_count, answer, tolerance, precision)?
            .into_iter()
            .map(|f| {
                let m = mismatch(&f, claimed_tuples, answer, tolerance);
                (f, m)
            })
            .collect(),
    )
}

/// The Hall violator of an unmatched tuple, as the end of its mismatch's reason.
fn blocked_text(
    blocked: Option<&Blocked>,
    tuples: Option<&[Vec<Q>]>,
    answer: &InverseAnswer,
    tolerance: &Tolerance,
) -> String {
    let Some(b) = blocked else {
        return String::new();
    };
    let list = |xs: Vec<String>| xs.join(", ");
    format!(
        "; no pairing can give it a solution that accepts it: the claimed tuples {} are accepted (within `{tolerance}`) only by {} {}",
        list(
            b.claimed
                .iter()
                .map(|&i| format!(
                    "[{i}] {}",
                    tuples.map_or_else(String::new, |t| claimed_text(&t[i]))
                ))
                .collect()
        ),
        if b.solutions.len() == 1 {
            "the exact solution"
        } else {
            "the exact solutions"
        },
        list(
            b.solutions
                .iter()
                .map(|&j| format!(
                    "{} {}",
                    j + 1,
                    tuple_text(&answer.solutions[j], answer.names)
                ))
                .collect()
        ),
    )
}

fn mismatch(
    f: &InverseFinding,
    tuples: Option<&[Vec<Q>]>,
    answer: &InverseAnswer,
    tolerance: &Tolerance,
) -> FindingText {
    let exact_text = |j: usize| tuple_text(&answer.solutions[j], answer.names);
    let claimed = |i: usize| tuples.map_or_else(String::new, |t| claimed_text(&t[i]));
    match f {
        InverseFinding::Missed { solution } => FindingText {
            path: format!("solution {}", solution + 1),
            claimed: "(none)".into(),
            exact: exact_text(*solution),
            reason: format!(
                "missed: no claimed tuple within 2^{MATCH_RADIUS_LOG2} of the exact solution {}",
                exact_text(*solution)
            ),
        },
        InverseFinding::Extra {
            claimed: i,
            nearest,
            blocked,
        } => {
            let near = |j: usize| {
                tuples.is_some_and(|t| {
                    let e: Vec<f64> = answer.solutions[j]
                        .iter()
                        .map(ExactNumber::to_f64)
                        .collect();
                    within_radius(&t[*i], &e).is_some()
                })
            };
            FindingText {
                path: format!("[{i}]"),
                claimed: claimed(*i),
                exact: nearest.map_or_else(|| "(no solution)".into(), exact_text),
                reason: match nearest {
                    Some(j) if near(*j) => format!(
                        "extra: every exact solution within 2^{MATCH_RADIUS_LOG2} is paired with another tuple (the nearest is {}){}",
                        exact_text(*j),
                        blocked_text(blocked.as_ref(), tuples, answer, tolerance)
                    ),
                    Some(j) => format!(
                        "extra: no exact solution within 2^{MATCH_RADIUS_LOG2} (the nearest is {})",
                        exact_text(*j)
                    ),
                    None => "extra: there is no exact solution".into(),
                },
            }
        }
        InverseFinding::Coordinate {
            claimed: i,
            solution,
            blocked,
            coordinate,
            measures,
        } => FindingText {
            path: format!("[{i}][{coordinate}]"),
            claimed: claimed(*i),
            exact: exact_text(*solution),
            reason: format!(
                "{} = {} breaks tolerance `{tolerance}` against {}: {}{}",
                answer.names[*coordinate],
                tuples.map_or_else(String::new, |t| crate::number::to_decimal_string(
                    &t[*i][*coordinate],
                    17
                )),
                answer.solutions[*solution][*coordinate].text(),
                measures.text(),
                blocked_text(blocked.as_ref(), tuples, answer, tolerance)
            ),
        },
        InverseFinding::Count { claimed, exact } => FindingText {
            path: "count".into(),
            claimed: claimed.to_string(),
            exact: exact.to_string(),
            reason: format!(
                "{claimed} claimed, {exact} exact: {}",
                (0..answer.solutions.len())
                    .map(exact_text)
                    .collect::<Vec<_>>()
                    .join("; ")
            ),
        },
        InverseFinding::Infinite { what } => FindingText {
            path: "count".into(),
            claimed: tuples.map_or(0, <[_]>::len).to_string(),
            exact: "infinitely many".into(),
            reason: what.clone(),
        },
    }
}

#[cfg(test)]
mod matching_tests {
    use super::{hall_violator, maximum_matching};

    /// The size of a maximum matching by trying every injection (small graphs only).
    fn brute_force(adj: &[Vec<usize>], used: &mut [bool], i: usize) -> usize {
        if i == adj.len() {
            return 0;
        }
        let mut best = brute_force(adj, used, i + 1); // i unmatched
        for &j in &adj[i] {
            if !used[j] {
                used[j] = true;
                best = best.max(1 + brute_force(adj, used, i + 1));
                used[j] = false;
            }
        }
        best
    }

    fn check(adj: &[Vec<usize>], n_right: usize) {
        let m = maximum_matching(adj, n_right);
        // a matching: edges of the graph, distinct partners
        let mut taken = vec![false; n_right];
        for (i, j) in m.iter().enumerate() {
            if let Some(j) = *j {
                assert!(adj[i].contains(&j), "{adj:?}: {m:?}");
                assert!(!taken[j], "{adj:?}: {m:?}");
                taken[j] = true;
            }
        }
        let size = m.iter().flatten().count();
        assert_eq!(
            size,
            brute_force(adj, &mut vec![false; n_right], 0),
            "{adj:?}"
        );
        // every unmatched left vertex with neighbours has a Hall violator: |N(S)| < |S|
        for (i, j) in m.iter().enumerate() {
            if j.is_none() && !adj[i].is_empty() {
                let b = hall_violator(i, adj, &m, n_right);
                assert!(b.claimed.contains(&i));
                assert!(b.solutions.len() < b.claimed.len(), "{adj:?}: {b:?}");
                for &u in &b.claimed {
                    assert!(adj[u].iter().all(|v| b.solutions.contains(v)));
                }
            }
        }
    }

    #[test]
    fn greedy_is_not_maximum_but_this_is() {
        // the example: tuple 0 accepts both roots (nearest the second), tuple 1 only the
        // second; nearest-first would give root 1 to tuple 0 and leave tuple 1 without one
        let adj = vec![vec![1, 0], vec![1]];
        assert_eq!(maximum_matching(&adj, 2), vec![Some(0), Some(1)]);
        check(&adj, 2);
        // both accept only root 1: one is left, and the violator is both tuples and root 1
        let adj = vec![vec![1], vec![1]];
        let m = maximum_matching(&adj, 2);
        assert_eq!(m.iter().flatten().count(), 1);
        let i = m.iter().position(Option::is_none).unwrap();
        let b = hall_violator(i, &adj, &m, 2);
        assert_eq!((b.claimed, b.solutions), (vec![0, 1], vec![1]));
    }

    #[test]
    fn maximum_on_random_small_graphs() {
        // SplitMix64, so that the graphs are the same on every run
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        for _ in 0..2000 {
            let n_left = (next() % 7) as usize;
            let n_right = (next() % 7) as usize;
            let density = next() % 100;
            let adj: Vec<Vec<usize>> = (0..n_left)
                .map(|_| (0..n_right).filter(|_| next() % 100 < density).collect())
                .collect();
            check(&adj, n_right);
        }
    }

    #[test]
    fn a_long_augmenting_chain() {
        // tuple i < n-1 accepts solutions i+1 and i, tried in that order, the last tuple only
        // solution n-1: the first phase matches i with i+1 and leaves the last tuple; the
        // second flips an augmenting path through all n tuples (deeper than a recursive search
        // could safely go)
        let n = 100_000;
        let adj: Vec<Vec<usize>> = (0..n)
            .map(|i| {
                if i + 1 < n {
                    vec![i + 1, i]
                } else {
                    vec![n - 1]
                }
            })
            .collect();
        let m = maximum_matching(&adj, n);
        assert!(m.iter().enumerate().all(|(i, j)| *j == Some(i)));
    }
}
