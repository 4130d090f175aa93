//! Pictures of patches (`tribez plot`): the geometry is sampled from exact values (the library's
//! exact evaluation at exact sample points), converted to `f64` (correctly rounded) for drawing
//! only.
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
use num_traits::{One, Zero};
use rayon::prelude::*;

use super::project::{Frame, View, cross, dot, normalize, sub};
use super::svg::{Rgb, Svg};
use crate::error::CliError;
use tribez::Patch;
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::number::round_f64;
use tribez::hazmat::patch::ControlNet;

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

/// Evaluate every sample exactly (in parallel) and convert to picture points; a point where the
/// patch is undefined (a rational patch's zero denominator) is `None`.
fn evaluate(patch: &Patch, g: &Geometry<'_>, samples: &[Sample]) -> Vec<Option<[f64; 3]>> {
    let evaluator = patch.exact().exact_evaluator();
    samples
        .par_iter()
        .map(|s| {
            let value = evaluator.evaluate(&s.input).ok()?;
            let value: Vec<f64> = value.iter().map(round_f64).collect();
            let domain: Vec<f64> = s.domain.iter().map(round_f64).collect();
            let p = g.point(&domain, &value);
            p.iter().all(|x| x.is_finite()).then_some(p)
        })
        .collect()
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
    let (net, vertices, polygon) = match patch.as_any() {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => {
            (&p.net, p.domain_or_reference().vertices().to_vec(), false)
        }
        AnyPatch::Rational(r) => (
            &r.patch.net,
            r.patch.domain_or_reference().vertices().to_vec(),
            false,
        ),
        AnyPatch::SPatch(s) => (
            &s.net,
            s.polygon
                .vertices()
                .iter()
                .map(|v| v.to_vec())
                .collect::<Vec<_>>(),
            true,
        ),
    };
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
    let n = options.samples;
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
        while per > 1 && k * (per + 1) * (per + 2) / 2 > MAX_POINTS {
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
    let points = evaluate(patch, &g, &samples);
    let take = |r: &std::ops::Range<usize>| points[r.clone()].to_vec();
    let edges = edge_ranges.iter().map(take).collect();
    let iso = iso_ranges.iter().map(take).collect();
    // the net: points (scalar patches at their abscissae), lines between neighbours
    let degree = g.net.degree();
    let indices: Vec<Vec<u32>> = g.net.entries().map(|(a, _)| a.to_vec()).collect();
    let net_points: Vec<[f64; 3]> = g
        .net
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
        .collect();
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
    let all = options.labels == Labels::All && indices.len() <= MAX_LABELS;
    let net_labels = indices
        .iter()
        .enumerate()
        .filter_map(|(r, alpha)| {
            let corner = alpha.iter().filter(|&&a| a > 0).count() <= 1;
            let wanted = match options.labels {
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
        .collect();
    let shape = patch.shape();
    let over = if g.polygon {
        format!("over a {}-gon", g.vertices.len())
    } else if m == 2 {
        "over a triangle".to_string()
    } else {
        "over an interval".to_string()
    };
    let description = format!(
        "{}, {} {}, {over}, in R^{}",
        patch.kind().name(),
        if g.polygon { "depth" } else { "degree" },
        shape.degree,
        shape.dimension
    );
    Ok(Scene {
        points,
        triangles,
        edges,
        iso,
        net_points,
        net_lines,
        net_labels,
        three_d: g.three_d(),
        description,
    })
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
    svg.close_group();
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
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

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
