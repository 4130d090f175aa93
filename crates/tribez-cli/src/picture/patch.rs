//! Pictures of patches (`tribez plot`): the geometry is sampled at exact sample points, and a
//! picture needs no more than its pixels' precision, so the values are summed in `f64`
//! ([`Fast`]): the Bernstein form `Σ_α C(n;α) c_α λ^α`, with the control points translated to the
//! first one and scaled by a power of two `S ≥ max |c_α − c_0|`, each `C(n;α)(c_α − c_0)/S`
//! rounded once from its exact value. On the closed domain (`λ ≥ 0`, `Σ λ^α C(n;α) = 1`) every
//! term is at most 1 in magnitude, so the error of a value is at most about `(N + n + m + 2)·2^-53·S`
//! (`N ≤ 250,000` control points, `S < 4 max |c_α − c_0|`): below `10^-9` of the net's extent,
//! and the picture's frame holds the whole net. A rational patch's denominator is summed the same way with
//! a running bound; where it is not certainly `2^20` times larger than its error, that point is
//! evaluated exactly (where the denominator vanishes the point is left out). An S-patch takes
//! its float Wachspress coordinates first (exactly where they are not finite). The exact path
//! ran in the order of `N·n` big-number operations per point: minutes at degree 200.
//!
//! * Over a triangle (or an S-patch's polygon) in R^3, and the graph of a scalar patch: a shaded
//!   projection (painter's algorithm over the sampled triangles, far ones first; Lambert shading
//!   by a light from the upper left, front and back faces in different hues), the images of the
//!   domain's edges, and the control net on top.
//! * In the plane (d = 2): the image of the domain with iso-parameter lines (`λ_k = 1/10, …,
//!   9/10`), triangles where the map folds over in another colour, the control net on top.
//! * Curves (m = 1): the curve (or its graph, d = 1) with its control polygon.
//!
//! A control point `c_α` of a scalar patch is drawn at `(ξ_α, c_α)` with the Bézier abscissa
//! `ξ_α = Σ α_k a_k / n` (docs/theory.md §9), so the net of the graph is the graph's net.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use rayon::prelude::*;

use super::project::{Frame, View, cross, dot, normalize, sub};
use super::svg::{Rgb, Svg};
use crate::error::CliError;
use tribez::Patch;
use tribez::constructions::ControlNet;
use tribez::constructions::multinomial;
use tribez::format::round_f64;

/// The colour of control nets (points, lines and labels): a magenta no surface colour is near.
pub const NET: Rgb = Rgb(220, 38, 127);
/// Front faces of shaded surfaces (before shading).
pub const FRONT: Rgb = Rgb(96, 156, 222);
/// Back faces of shaded surfaces (before shading).
pub const BACK: Rgb = Rgb(184, 184, 160);
/// Planar images of the domain.
pub const PLANE: Rgb = Rgb(204, 224, 244);
/// Planar triangles where the map folds over (reversed orientation).
pub const FOLDED: Rgb = Rgb(244, 204, 184);
/// The images of the domain's edges, and curves.
pub const EDGE: Rgb = Rgb(34, 34, 34);
/// Iso-parameter lines.
pub const ISO: Rgb = Rgb(110, 122, 136);

/// The largest `--samples` (segments per domain edge).
pub const MAX_SAMPLES: usize = 256;
/// At most this many points are sampled in all (S-patches over many-sided polygons take fewer
/// segments per fan triangle).
const MAX_POINTS: usize = 200_000;
/// At most this many Bernstein terms are summed for an S-patch's fan (points × control points;
/// more sides or control points take fewer segments per fan triangle). A triangle of degree 200
/// at 256 segments sums about 8.5·10^8.
const MAX_TERMS: usize = 1_000_000_000;
/// `--labels all` labels nets of at most this many points (larger nets: corners only).
const MAX_LABELS: usize = 1_000;

/// Which control points carry their multi-index.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Labels {
    /// None.
    None,
    /// The corner control points (`n e_k`).
    Corners,
    /// Every control point (nets of at most 1,000 points; larger ones: the corners).
    All,
}

/// What to draw and how.
#[derive(Clone, Debug)]
pub struct PlotOptions {
    /// The view of pictures in R^3.
    pub view: View,
    /// Segments per domain edge.
    pub samples: usize,
    /// Control point labels.
    pub labels: Labels,
    /// The title (the patch file's name).
    pub title: String,
}

/// A patch prepared for drawing: its domain, its net with the abscissae, how values become
/// picture points.
struct Geometry<'a> {
    /// The net (multi-indices and exact points).
    net: &'a ControlNet<BigRational>,
    /// The domain's vertices (a simplex's `m + 1`, or a polygon's), exact.
    vertices: Vec<Vec<BigRational>>,
    /// An S-patch (inputs are `(x, y)`; else barycentric).
    polygon: bool,
    /// Dimension of the points.
    d: usize,
}

impl Geometry<'_> {
    /// A value (and its domain position) as a point of the picture's space: itself (d = 2, 3),
    /// or its graph `(domain position, value)` (d = 1).
    fn point(&self, domain: &[f64], value: &[f64]) -> [f64; 3] {
        match (self.d, domain.len()) {
            (1, 1) => [domain[0], value[0], 0.0],
            (1, _) => [domain[0], domain[1], value[0]],
            (2, _) => [value[0], value[1], 0.0],
            _ => [value[0], value[1], value[2]],
        }
    }

    /// Does the picture live in R^3 (projected and shaded)?
    fn three_d(&self) -> bool {
        let m = if self.polygon {
            2
        } else {
            self.vertices.len() - 1
        };
        self.d == 3 || (self.d == 1 && m == 2)
    }

    /// The Cartesian position in the domain of the point with weights `w` on the vertices
    /// (barycentric, or an S-patch control point's `α / n`).
    fn domain_of(&self, w: &[BigRational]) -> Vec<BigRational> {
        let dim = self.vertices[0].len();
        let total: BigRational = w.iter().sum();
        let total = if total.is_zero() {
            BigRational::one()
        } else {
            total
        };
        (0..dim)
            .map(|c| {
                self.vertices
                    .iter()
                    .zip(w)
                    .map(|(v, x)| &v[c] * x)
                    .sum::<BigRational>()
                    / &total
            })
            .collect()
    }
}

/// One sample: where in the domain (Cartesian) and the exact input the kind takes.
struct Sample {
    domain: Vec<BigRational>,
    input: Vec<BigRational>,
}

/// Evaluate every sample (in parallel) and convert to picture points: in f64 by [`Fast`] where
/// it can, exactly where it cannot; a point where the patch is undefined (a rational patch's
/// zero denominator) is `None`.
fn evaluate(patch: &Patch, g: &Geometry<'_>, samples: &[Sample]) -> Vec<Option<[f64; 3]>> {
    // made only if a point needs it: preparing the exact kernel costs as much as a picture
    let evaluator = std::sync::OnceLock::new();
    let fast = Fast::new(patch);
    samples
        .par_iter()
        .map_init(Vec::new, |scratch, s| {
            let value = match fast.as_ref().and_then(|f| f.value(&s.input, scratch)) {
                Some(v) => v,
                None => {
                    let exact = evaluator
                        .get_or_init(|| patch.exact().exact_evaluator())
                        .evaluate(&s.input)
                        .ok()?;
                    exact.iter().map(round_f64).collect()
                }
            };
            let domain: Vec<f64> = s.domain.iter().map(round_f64).collect();
            let p = g.point(&domain, &value);
            p.iter().all(|x| x.is_finite()).then_some(p)
        })
        .collect()
}

/// Bernstein sums in f64 for a picture (the module's documentation gives the error).
struct Fast {
    /// The net's simplex dimension and degree, the points' dimension.
    m: usize,
    n: usize,
    d: usize,
    /// Every control point's multi-index, `m + 1` entries each (canonical order).
    exponents: Vec<u16>,
    /// `C(n;α) w_α (c_α − c_0) / (S W)`, `d` per control point (`w = W = 1` unless rational).
    numerators: Vec<f64>,
    /// A rational patch's `C(n;α) w_α / W` (`W` a power of two `≥ max |w_α|`).
    denominators: Option<Vec<f64>>,
    /// `c_0` rounded, and `S`.
    origin: Vec<f64>,
    scale: f64,
    /// An S-patch's polygon, translated to its first vertex `v_0` (rounded), and `v_0` exactly.
    polygon: Option<(Vec<[f64; 2]>, [BigRational; 2])>,
}

/// A power of two `2^k ≥ x` (for `x ≥ 0`; 1 for 0), or `None` beyond f64.
fn power_of_two_above(x: &BigRational) -> Option<BigRational> {
    let f = round_f64(x);
    if !f.is_finite() {
        return None;
    }
    if f == 0.0 {
        return Some(BigRational::one());
    }
    let mut p = 1.0f64;
    while p < f {
        p *= 2.0; // ends: f is finite
    }
    while p / 2.0 >= f {
        p /= 2.0; // ends: f > 0
    }
    // f ≤ p, and x ≤ f (1 + 2^-53) since f is x rounded: 2p ≥ x
    BigRational::from_float(p * 2.0)
}

impl Fast {
    /// `None` when the numbers are beyond f64 (the exact path then draws what it can).
    fn new(patch: &Patch) -> Option<Fast> {
        let (net, weights, polygon) = (patch.control_net(), patch.weights(), patch.polygon());
        let (m, n, d) = (net.m(), net.degree(), net.dim());
        let first = net.points().next()?.to_vec();
        let spread = net
            .coords()
            .iter()
            .enumerate()
            .map(|(i, x)| (x - &first[i % d]).abs())
            .max()
            .unwrap_or_else(BigRational::zero);
        let scale = power_of_two_above(&spread)?;
        let wscale = match weights {
            Some(w) => power_of_two_above(&w.iter().map(|x| x.abs()).max()?)?,
            None => BigRational::one(),
        };
        let mut exponents = Vec::with_capacity(net.len() * (m + 1));
        let mut numerators = Vec::with_capacity(net.len() * d);
        let mut denominators = weights.map(|_| Vec::with_capacity(net.len()));
        for (r, (alpha, c)) in net.entries().enumerate() {
            exponents.extend(alpha.iter().map(|&a| u16::try_from(a).unwrap_or(u16::MAX)));
            let binomial = BigRational::from_integer(multinomial(alpha).into());
            let w = match weights {
                Some(w) => &binomial * &w[r] / &wscale,
                None => binomial,
            };
            for (x, o) in c.iter().zip(&first) {
                numerators.push(round_f64(&((x - o) * &w / &scale)));
            }
            if let Some(den) = denominators.as_mut() {
                den.push(round_f64(&w));
            }
        }
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        if !finite(&numerators) || !denominators.as_deref().is_none_or(finite) {
            return None;
        }
        let polygon = polygon.map(|v| {
            let v0 = v[0].clone();
            let shifted = v
                .iter()
                .map(|p| [0, 1].map(|c| round_f64(&(&p[c] - &v0[c]))))
                .collect();
            (shifted, v0)
        });
        Some(Fast {
            m,
            n,
            d,
            exponents,
            numerators,
            denominators,
            origin: first.iter().map(round_f64).collect(),
            scale: round_f64(&scale),
            polygon,
        })
    }

    /// The value at the exact input (barycentric, or an S-patch's Cartesian point), or `None`
    /// where f64 cannot give it (then the caller evaluates exactly). `scratch` holds the powers.
    fn value(&self, input: &[BigRational], scratch: &mut Vec<f64>) -> Option<Vec<f64>> {
        let lambda: Vec<f64> = match &self.polygon {
            Some((vertices, v0)) => {
                let p = [0, 1].map(|c| round_f64(&(&input[c] - &v0[c])));
                let l = tribez::kernels::wachspress_float(vertices, &p);
                if !l.iter().all(|x| x.is_finite() && *x >= 0.0) {
                    return None;
                }
                l
            }
            None => input.iter().map(round_f64).collect(),
        };
        if lambda.len() != self.m + 1 {
            return None;
        }
        // powers λ_k^e, e = 0..=n, row k at k(n + 1)
        let (n1, m1) = (self.n + 1, self.m + 1);
        scratch.clear();
        for &l in &lambda {
            let mut p = 1.0f64;
            scratch.push(p);
            for _ in 0..self.n {
                p *= l;
                scratch.push(p);
            }
        }
        let mut num = vec![0.0f64; self.d];
        let (mut den, mut den_abs) = (0.0f64, 0.0f64);
        for (r, alpha) in self.exponents.chunks_exact(m1).enumerate() {
            let mut b = 1.0f64;
            for (k, &a) in alpha.iter().enumerate() {
                b *= scratch[k * n1 + usize::from(a)];
            }
            for (c, acc) in num.iter_mut().enumerate() {
                *acc += self.numerators[r * self.d + c] * b;
            }
            if let Some(w) = &self.denominators {
                let t = w[r] * b;
                den += t;
                den_abs += t.abs();
            }
        }
        let quotient = match &self.denominators {
            Some(_) => {
                // |computed − exact| ≤ γ_K Σ|terms|, K = N + n + m + 2 roundings at most per
                // term; trust the quotient only far from a zero denominator
                let k = (self.exponents.len() / m1 + self.n + m1 + 1) as f64;
                let bound = k * f64::EPSILON * den_abs;
                // not clearly away from zero (NaN included): the exact path decides
                let margin = bound * (1u64 << 20) as f64;
                if den.abs().partial_cmp(&margin) != Some(std::cmp::Ordering::Greater) {
                    return None;
                }
                den
            }
            None => 1.0,
        };
        Some(
            num.iter()
                .zip(&self.origin)
                .map(|(x, o)| o + self.scale * (x / quotient))
                .collect(),
        )
    }
}

fn q(n: usize, d: usize) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// The barycentric grid of a triangle with `n` segments per edge: `(i, j, n − i − j) / n`, rows
/// of `i` (index [`grid_index`]).
fn grid(n: usize) -> Vec<[BigRational; 3]> {
    let mut out = Vec::with_capacity((n + 1) * (n + 2) / 2);
    for i in 0..=n {
        for j in 0..=n - i {
            out.push([q(i, n), q(j, n), q(n - i - j, n)]);
        }
    }
    out
}

/// The index of `(i, j)` in [`grid`].
fn grid_index(n: usize, i: usize, j: usize) -> usize {
    // rows 0..i hold (n + 1) + n + … + (n + 2 − i) points
    i * (n + 1) - i * (i.saturating_sub(1)) / 2 + j
}

/// The triangles of [`grid`] (counter-clockwise in `(i, j)`).
fn grid_triangles(n: usize, base: usize) -> Vec<[usize; 3]> {
    let mut out = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n - i {
            let a = base + grid_index(n, i, j);
            let b = base + grid_index(n, i + 1, j);
            let c = base + grid_index(n, i, j + 1);
            out.push([a, b, c]);
            if i + j + 1 < n {
                let d = base + grid_index(n, i + 1, j + 1);
                out.push([b, d, c]);
            }
        }
    }
    out
}

/// Everything sampled: the mesh (points and triangles), polylines (the domain's edges, the
/// iso-parameter lines, a curve), the net.
struct Scene {
    points: Vec<Option<[f64; 3]>>,
    triangles: Vec<[usize; 3]>,
    edges: Vec<Vec<Option<[f64; 3]>>>,
    iso: Vec<Vec<Option<[f64; 3]>>>,
    net_points: Vec<[f64; 3]>,
    net_lines: Vec<(usize, usize)>,
    net_labels: Vec<(usize, String, bool)>,
    three_d: bool,
    description: String,
}

/// The geometry of a patch of any kind, or why it cannot be drawn.
fn geometry<'a>(patch: &'a Patch, file: &str) -> Result<Geometry<'a>, CliError> {
    let shape = patch.shape();
    let (net, vertices, polygon) = (
        patch.control_net(),
        patch.domain_vertices(),
        patch.polygon().is_some(),
    );
    let m = shape.simplex_dim;
    if !polygon && m > 2 {
        return Err(CliError::Usage(format!(
            "{file}: `tribez plot` draws curves, triangles and S-patches; this patch is over the {m}-simplex"
        )));
    }
    if !(1..=3).contains(&shape.dimension) {
        return Err(CliError::Usage(format!(
            "{file}: `tribez plot` draws points in 1 to 3 dimensions; this patch's are in {}",
            shape.dimension
        )));
    }
    Ok(Geometry {
        net,
        vertices,
        polygon,
        d: shape.dimension,
    })
}

/// Sample a patch and its net.
fn scene(patch: &Patch, options: &PlotOptions, file: &str) -> Result<Scene, CliError> {
    let g = geometry(patch, file)?;
    let sampled = sample(&g, options.samples);
    let points = evaluate(patch, &g, &sampled.samples);
    let take = |r: &std::ops::Range<usize>| points[r.clone()].to_vec();
    let edges = sampled.edges.iter().map(take).collect();
    let iso = sampled.iso.iter().map(take).collect();
    // the net: points (scalar patches at their abscissae), lines between neighbours
    let indices: Vec<Vec<u32>> = g.net.entries().map(|(a, _)| a.to_vec()).collect();
    Ok(Scene {
        points,
        triangles: sampled.triangles,
        edges,
        iso,
        net_points: net_points(&g),
        net_lines: net_lines(&g, &indices),
        net_labels: net_labels(&indices, options.labels),
        three_d: g.three_d(),
        description: description(patch, &g),
    })
}

/// The domain points a picture evaluates: the surface's grid (and its triangles), its edges
/// and iso-lines as ranges of the samples.
struct Sampled {
    samples: Vec<Sample>,
    triangles: Vec<[usize; 3]>,
    edges: Vec<std::ops::Range<usize>>,
    iso: Vec<std::ops::Range<usize>>,
}

/// Sample the domain with `n` steps per edge (`--samples`): a polygon as a fan of triangles
/// from its centroid, a triangle as a grid with its iso-lines (in the plane), a curve with
/// `8n` segments; every edge at `2n` steps.
fn sample(g: &Geometry<'_>, n: usize) -> Sampled {
    let m = if g.polygon { 2 } else { g.vertices.len() - 1 };
    let bary = |w: &[BigRational]| Sample {
        domain: g.domain_of(w),
        input: w.to_vec(),
    };
    let cart = |w: &[BigRational]| {
        let p = g.domain_of(w);
        Sample {
            domain: p.clone(),
            input: p,
        }
    };
    let mut samples: Vec<Sample> = Vec::new();
    let mut triangles = Vec::new();
    let mut edge_ranges: Vec<std::ops::Range<usize>> = Vec::new();
    let mut iso_ranges: Vec<std::ops::Range<usize>> = Vec::new();
    let fine = 2 * n;
    if g.polygon {
        // a fan of triangles from the centroid (the polygon is convex)
        let k = g.vertices.len();
        let mut per = n;
        let terms = g.net.len();
        while per > 1
            && (k * (per + 1) * (per + 2) / 2 > MAX_POINTS
                || k * (per + 1) * (per + 2) / 2 * terms > MAX_TERMS)
        {
            per -= 1;
        }
        let centroid = vec![q(1, k); k];
        for i in 0..k {
            let mut w_a = vec![BigRational::zero(); k];
            w_a[i] = BigRational::one();
            let mut w_b = vec![BigRational::zero(); k];
            w_b[(i + 1) % k] = BigRational::one();
            let base = samples.len();
            for [a, b, c] in grid(per) {
                // a at the vertex i, b at the vertex i + 1, c at the centroid
                let w: Vec<BigRational> = (0..k)
                    .map(|t| &a * &w_a[t] + &b * &w_b[t] + &c * &centroid[t])
                    .collect();
                samples.push(cart(&w));
            }
            triangles.extend(grid_triangles(per, base));
            let start = samples.len();
            for s in 0..=fine {
                let w: Vec<BigRational> = (0..k)
                    .map(|t| q(fine - s, fine) * &w_a[t] + q(s, fine) * &w_b[t])
                    .collect();
                samples.push(cart(&w));
            }
            edge_ranges.push(start..samples.len());
        }
    } else if m == 2 {
        let base = samples.len();
        for p in grid(n) {
            samples.push(bary(&p));
        }
        triangles = grid_triangles(n, base);
        for k in 0..3 {
            let start = samples.len();
            for s in 0..=fine {
                let mut w = vec![BigRational::zero(); 3];
                w[(k + 1) % 3] = q(fine - s, fine);
                w[(k + 2) % 3] = q(s, fine);
                samples.push(bary(&w));
            }
            edge_ranges.push(start..samples.len());
        }
        if g.d == 2 {
            for k in 0..3 {
                for level in 1..10 {
                    let t = q(level, 10);
                    let rest = BigRational::one() - &t;
                    let start = samples.len();
                    for s in 0..=n {
                        let mut w = vec![BigRational::zero(); 3];
                        w[k] = t.clone();
                        w[(k + 1) % 3] = &rest * q(n - s, n);
                        w[(k + 2) % 3] = &rest * q(s, n);
                        samples.push(bary(&w));
                    }
                    iso_ranges.push(start..samples.len());
                }
            }
        }
    } else {
        // a curve: 8 segments per --samples
        let segments = 8 * n;
        let start = samples.len();
        for s in 0..=segments {
            samples.push(bary(&[q(segments - s, segments), q(s, segments)]));
        }
        edge_ranges.push(start..samples.len());
    }
    Sampled {
        samples,
        triangles,
        edges: edge_ranges,
        iso: iso_ranges,
    }
}

/// The control points as picture points (a scalar patch's at their abscissae).
fn net_points(g: &Geometry<'_>) -> Vec<[f64; 3]> {
    let degree = g.net.degree();
    g.net
        .entries()
        .map(|(alpha, c)| {
            let w: Vec<BigRational> = alpha
                .iter()
                .map(|&a| q(a as usize, degree.max(1)))
                .collect();
            let w = if degree == 0 {
                vec![q(1, alpha.len()); alpha.len()]
            } else {
                w
            };
            let domain: Vec<f64> = g.domain_of(&w).iter().map(round_f64).collect();
            let value: Vec<f64> = c.iter().map(round_f64).collect();
            g.point(&domain, &value)
        })
        .collect()
}

/// The lines of the net between neighbouring control points (`indices` in the net's order): a
/// simplex's between every pair `i < j` of parts, an S-patch's between neighbouring vertices.
fn net_lines(g: &Geometry<'_>, indices: &[Vec<u32>]) -> Vec<(usize, usize)> {
    let simplex = g.net.simplex();
    let parts = indices.first().map_or(0, Vec::len);
    let mut net_lines = Vec::new();
    for (r, alpha) in indices.iter().enumerate() {
        for i in 0..parts {
            if alpha[i] == 0 {
                continue;
            }
            for j in 0..parts {
                // a simplex's net: every pair i < j; an S-patch's: neighbouring vertices only
                let neighbours = if g.polygon {
                    j == (i + 1) % parts
                } else {
                    j > i
                };
                if !neighbours {
                    continue;
                }
                let mut beta = alpha.clone();
                beta[i] -= 1;
                beta[j] += 1;
                if let Some(s) = simplex.checked_rank(&beta) {
                    net_lines.push((r, s));
                }
            }
        }
    }
    net_lines
}

/// The labels of the control points `--labels` asks for: `(index in the net, text, corner)`.
fn net_labels(indices: &[Vec<u32>], labels: Labels) -> Vec<(usize, String, bool)> {
    let all = labels == Labels::All && indices.len() <= MAX_LABELS;
    indices
        .iter()
        .enumerate()
        .filter_map(|(r, alpha)| {
            let corner = alpha.iter().filter(|&&a| a > 0).count() <= 1;
            let wanted = match labels {
                Labels::None => false,
                Labels::Corners => corner,
                Labels::All => all || corner,
            };
            wanted.then(|| {
                let text = alpha
                    .iter()
                    .map(u32::to_string)
                    .collect::<Vec<_>>()
                    .join(",");
                (r, format!("({text})"), corner)
            })
        })
        .collect()
}

/// What the picture shows: kind, degree (or depth), domain and dimension.
fn description(patch: &Patch, g: &Geometry<'_>) -> String {
    let m = if g.polygon { 2 } else { g.vertices.len() - 1 };
    let shape = patch.shape();
    let over = if g.polygon {
        format!("over a {}-gon", g.vertices.len())
    } else if m == 2 {
        "over a triangle".to_string()
    } else {
        "over an interval".to_string()
    };
    format!(
        "{}, {} {}, {over}, in R^{}",
        patch.kind().name(),
        if g.polygon { "depth" } else { "degree" },
        shape.degree,
        shape.dimension
    )
}

/// The picture of `patch` as SVG (see the module's documentation).
pub fn plot(patch: &Patch, options: &PlotOptions) -> Result<String, CliError> {
    let scene = scene(patch, options, &options.title)?;
    Ok(draw(&scene, options))
}

/// Width and height of patch pictures, pixels.
const WIDTH: f64 = 800.0;
const HEIGHT: f64 = 640.0;

fn draw(scene: &Scene, options: &PlotOptions) -> String {
    let view = if scene.three_d {
        options.view
    } else {
        // the plane seen from above: x to the right, y up
        View {
            azimuth: -90.0,
            elevation: 90.0,
        }
    };
    let (r, u, v) = view.axes();
    let project = |p: [f64; 3]| [dot(r, p), dot(u, p)];
    let mesh2: Vec<Option<[f64; 2]>> = scene.points.iter().map(|p| p.map(project)).collect();
    let net2: Vec<[f64; 2]> = scene.net_points.iter().map(|&p| project(p)).collect();
    let frame = Frame::fit(
        mesh2.iter().flatten().chain(net2.iter()),
        (40.0, 56.0, WIDTH - 80.0, HEIGHT - 120.0),
    );
    let px = |p: [f64; 2]| frame.px(p);
    let mut svg = Svg::new(WIDTH, HEIGHT, &[]);
    svg.title(&format!("{}: {}", options.title, scene.description));
    svg.text(
        [20.0, 28.0],
        15.0,
        "start",
        EDGE,
        &format!("{} — {}", options.title, scene.description),
        &[("id", "title".into())],
    );
    let mut plot_attrs: Vec<(&str, String)> = vec![("id", "plot".into())];
    plot_attrs.extend(frame.attrs());
    plot_attrs.push(("data-view", format!("{} {}", view.azimuth, view.elevation)));
    svg.open_group(&plot_attrs);
    // the surface (or the plane's image), far triangles first
    let faces = faces(scene, (r, u, v), &frame);
    svg.open_group(&[("id", "surface".into())]);
    for (_, tri, colour) in &faces {
        // the outline in the fill's colour closes the hairline gaps between triangles
        svg.polygon(tri, *colour, Some((*colour, 0.6)));
    }
    svg.close_group();
    let polyline = |svg: &mut Svg, line: &[Option<[f64; 3]>], colour: Rgb, width: f64| {
        // a missing point (an undefined value) breaks the line
        for run in line.split(Option::is_none) {
            let pts: Vec<[f64; 2]> = run.iter().flatten().map(|&p| px(project(p))).collect();
            svg.polyline(&pts, colour, width, "");
        }
    };
    svg.open_group(&[("id", "iso-lines".into())]);
    for line in &scene.iso {
        polyline(&mut svg, line, ISO, 0.8);
    }
    svg.close_group();
    svg.open_group(&[("id", "domain-edges".into())]);
    for line in &scene.edges {
        polyline(&mut svg, line, EDGE, 1.8);
    }
    svg.close_group();
    draw_net(&mut svg, scene, &net2, &frame);
    svg.close_group();
    draw_legend(&mut svg, scene, view, options);
    svg.finish()
}

/// The surface's triangles as drawn: `(depth, pixels, colour)`, shaded by their normal in 3D
/// (far triangles first); in the plane, the triangles of the orientation fewer triangles have
/// are the folds.
fn faces(
    scene: &Scene,
    (r, u, v): ([f64; 3], [f64; 3], [f64; 3]),
    frame: &Frame,
) -> Vec<(f64, [[f64; 2]; 3], Rgb)> {
    let project = |p: [f64; 3]| [dot(r, p), dot(u, p)];
    let px = |p: [f64; 2]| frame.px(p);
    let light = normalize([
        -0.35 * r[0] + 0.55 * u[0] + 0.75 * v[0],
        -0.35 * r[1] + 0.55 * u[1] + 0.75 * v[1],
        -0.35 * r[2] + 0.55 * u[2] + 0.75 * v[2],
    ]);
    let mut faces: Vec<(f64, [[f64; 2]; 3], Rgb)> = scene
        .triangles
        .iter()
        .filter_map(|t| {
            let [a, b, c] = t.map(|i| scene.points[i]);
            let (a, b, c) = (a?, b?, c?);
            let depth = (dot(v, a) + dot(v, b) + dot(v, c)) / 3.0;
            let pa = px(project(a));
            let pb = px(project(b));
            let pc = px(project(c));
            let colour = if scene.three_d {
                let n = normalize(cross(sub(b, a), sub(c, a)));
                let base = if dot(n, v) >= 0.0 { FRONT } else { BACK };
                base.scaled(0.45 + 0.55 * dot(n, light).abs())
            } else {
                // the orientation, decided below
                let area = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (pb[1] - pa[1]);
                if area < 0.0 {
                    PLANE
                } else if area > 0.0 {
                    FOLDED
                } else {
                    ISO
                }
            };
            Some((depth, [pa, pb, pc], colour))
        })
        .collect();
    if !scene.three_d {
        // folds: the triangles of the orientation fewer triangles have
        let (neg, pos) = faces.iter().fold((0, 0), |(n, p), f| {
            (
                n + usize::from(f.2 == PLANE),
                p + usize::from(f.2 == FOLDED),
            )
        });
        for f in &mut faces {
            f.2 = match (f.2 == PLANE, f.2 == FOLDED) {
                (true, _) => {
                    if neg >= pos {
                        PLANE
                    } else {
                        FOLDED
                    }
                }
                (_, true) => {
                    if neg >= pos {
                        FOLDED
                    } else {
                        PLANE
                    }
                }
                _ => PLANE,
            };
        }
    }
    if scene.three_d {
        faces.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    faces
}

/// The control net on top: its lines, its points and their labels (`net2`: the points
/// projected).
fn draw_net(svg: &mut Svg, scene: &Scene, net2: &[[f64; 2]], frame: &Frame) {
    let px = |p: [f64; 2]| frame.px(p);
    // the control net on top
    svg.open_group(&[("id", "control-net".into())]);
    for &(a, b) in &scene.net_lines {
        svg.line(px(net2[a]), px(net2[b]), NET, 1.3);
    }
    let radius = if net2.len() > 400 { 2.0 } else { 4.0 };
    for (i, &p) in net2.iter().enumerate() {
        svg.circle(
            px(p),
            radius,
            Some(NET),
            Some((Rgb(255, 255, 255), 0.8)),
            &[("class", "net-point".into()), ("data-index", i.to_string())],
        );
    }
    for (i, text, corner) in &scene.net_labels {
        let at = px(net2[*i]);
        svg.text(
            [at[0] + 7.0, at[1] - 7.0],
            if *corner { 13.0 } else { 10.0 },
            "start",
            NET,
            text,
            &[("class", "net-label".into())],
        );
    }
    svg.close_group();
}

/// The legend under the picture: the net, the faces' colours, the view and the sampling.
fn draw_legend(svg: &mut Svg, scene: &Scene, view: View, options: &PlotOptions) {
    // the legend
    let y = HEIGHT - 36.0;
    svg.circle([28.0, y - 4.0], 4.0, Some(NET), None, &[]);
    svg.text(
        [38.0, y],
        12.0,
        "start",
        EDGE,
        &format!("control net ({} points)", scene.net_points.len()),
        &[],
    );
    let (swatch, what) = if scene.three_d {
        (FRONT, "front faces (back faces grey)")
    } else {
        (PLANE, "image of the domain (folds in orange)")
    };
    if !scene.triangles.is_empty() {
        svg.rect(220.0, y - 10.0, 12.0, 12.0, swatch, None);
        svg.text([238.0, y], 12.0, "start", EDGE, what, &[]);
    }
    let how = if scene.three_d {
        format!(
            "view azimuth {}°, elevation {}°; ",
            view.azimuth, view.elevation
        )
    } else {
        String::new()
    };
    svg.text(
        [20.0, HEIGHT - 14.0],
        11.0,
        "start",
        ISO,
        &format!(
            "{how}sampled from exact values, {} segments per domain edge",
            if scene.triangles.is_empty() {
                8 * options.samples
            } else {
                options.samples
            }
        ),
        &[],
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixture(name: &str) -> Patch {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
        Patch::from_file(root.join(name)).unwrap()
    }

    /// The f64 sums of a picture against the exact values, rounded, at a grid of the domain
    /// (triangles: barycentric; S-patches: the fan's Cartesian points): within `1e-9` of the
    /// net's extent (the module's bound), and every point evaluated in f64 (none fell back).
    fn agrees_with_exact(patch: &Patch, samples: &[Vec<BigRational>], extent: f64) {
        let fast = Fast::new(patch).expect("numbers within f64");
        let exact = patch.exact().exact_evaluator();
        let mut scratch = Vec::new();
        for s in samples {
            let got = fast
                .value(s, &mut scratch)
                .unwrap_or_else(|| panic!("{s:?} fell back to the exact path"));
            let want: Vec<f64> = exact.evaluate(s).unwrap().iter().map(round_f64).collect();
            for (g, w) in got.iter().zip(&want) {
                assert!((g - w).abs() <= 1e-9 * extent, "at {s:?}: {g} vs {w}");
            }
        }
    }

    fn bary_grid(n: usize) -> Vec<Vec<BigRational>> {
        grid(n).into_iter().map(|p| p.to_vec()).collect()
    }

    #[test]
    fn f64_sums_agree_with_the_exact_values() {
        // a quartic far from the origin: 10^20 + small offsets (the translation to the first
        // control point keeps the spread, 1 to 9, in view; without it 10^20 · 2^-53 ≈ 10^4)
        let n = 4;
        let far = BigRational::from_integer(num_bigint::BigInt::from(10u32).pow(20));
        let pts: Vec<Vec<BigRational>> = (0..15)
            .map(|i: i64| {
                (0..3)
                    .map(|c: i64| {
                        &far + BigRational::from_integer(((i * 7 + c * 3) % 9 + 1).into())
                    })
                    .collect()
            })
            .collect();
        let p = Patch::bezier(tribez::SimplexDim(2), tribez::Degree(n), pts).unwrap();
        agrees_with_exact(&p, &bary_grid(9), 8.0);
        // a rational patch with positive weights, an S-patch, a curve
        agrees_with_exact(&fixture("beyond/octant_quartic.toml"), &bary_grid(9), 1.0);
        let on_curve: Vec<Vec<BigRational>> = (0..=8).map(|i| vec![q(8 - i, 8), q(i, 8)]).collect();
        agrees_with_exact(&fixture("beyond/cubic_curve.toml"), &on_curve, 4.0);
        let pentagon = fixture("beyond/pentagon_depth2.toml");
        let v = pentagon.polygon().expect("an S-patch");
        let k = v.len();
        // convex combinations of three vertices v_0, v_i, v_{i+1} with positive weights:
        // strictly inside the polygon (i + 1 < k: the wrap-around i = k − 1 gives a point on the
        // edge v_0 v_{k−1}, where float Wachspress coordinates may dip below 0 and the exact
        // path rightly takes over)
        let inside: Vec<Vec<BigRational>> = (1..k - 1)
            .map(|i| {
                (0..2)
                    .map(|c| {
                        (&v[0][c] * q(2, 5) + &v[i][c] * q(2, 5) + &v[i + 1][c] * q(1, 5)).clone()
                    })
                    .collect()
            })
            .collect();
        agrees_with_exact(&pentagon, &inside, 10.0);
    }

    #[test]
    fn a_denominator_near_zero_is_left_to_the_exact_path() {
        // weights 1, -1 on a line: W(λ) = λ_0 − λ_1 vanishes at (1/2, 1/2)
        let text = "degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1\"]\n[weights]\n\"1,0\" = \"1\"\n\"0,1\" = \"-1\"\n";
        let p = Patch::from_toml(text).unwrap();
        let fast = Fast::new(&p).unwrap();
        let mut scratch = Vec::new();
        assert_eq!(fast.value(&[q(1, 2), q(1, 2)], &mut scratch), None);
        // away from it: x = (w_0 c_0 λ_0 + w_1 c_1 λ_1) / (w_0 λ_0 + w_1 λ_1) = −λ_1 / (λ_0 − λ_1)
        // = −(1/4)/(1/2) = −1/2 at (3/4, 1/4)
        assert_eq!(
            fast.value(&[q(3, 4), q(1, 4)], &mut scratch),
            Some(vec![-0.5])
        );
    }

    #[test]
    fn the_grid_indexes_its_rows() {
        for n in 1..7 {
            let g = grid(n);
            assert_eq!(g.len(), (n + 1) * (n + 2) / 2);
            for i in 0..=n {
                for j in 0..=n - i {
                    let p = &g[grid_index(n, i, j)];
                    assert_eq!((p[0].clone(), p[1].clone()), (q(i, n), q(j, n)));
                }
            }
            assert_eq!(grid_triangles(n, 0).len(), n * n);
        }
    }
}
