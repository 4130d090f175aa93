//! [`Mesh::check`]: is the mesh a conforming triangulation carrying every ordinate?
//! (docs/theory.md §17). Every predicate is an exact sign; floats only filter.
//!
//! Each vertex coordinate is also rounded to the nearest `f64`, `fl(x)`. Rounding to nearest
//! is monotone, so `fl(a) < fl(b)` proves `a < b` (and `fl(a) > fl(b)` proves `a > b`): exact
//! comparisons (of coordinates, bounding boxes) are decided by the floats and computed exactly
//! only when the floats tie. When `fl(x)` is finite, `x` lies in `[fl(x)⁻, fl(x)⁺]` (the
//! neighbouring floats); an orientation is first computed in interval arithmetic on these
//! enclosures, each operation rounded to nearest and then widened to the neighbouring float
//! (which bounds the exact result of that operation), and its sign is taken only when the
//! interval excludes 0 (otherwise, or when a bound is not finite, it is computed exactly). An
//! orientation of three vertices two of which are the same vertex is 0 without computing.
//!
//! Candidates for overlaps and T-junctions come from the uniform grid of `mesh::locate`
//! (whose cells are found from the rounded boxes, so that no candidate is lost); the answer
//! is the exact predicates'.

use std::cmp::Ordering;

use num_rational::BigRational;
use num_traits::Signed;

use super::locate::{Grid, MAX_CELLS_PER_TRIANGLE, orient};
use super::{Mesh, MeshError};
use crate::number::round_f64;

/// At most this many problems are listed.
pub const MAX_PROBLEMS: usize = 1000;

impl Mesh {
    /// Every problem of the mesh (at most [`MAX_PROBLEMS`]), in this order: degenerate and
    /// clockwise triangles, duplicate triangles, vertices at the same point, unused vertices,
    /// overlapping triangles, T-junctions, absent ordinates. Empty for a valid mesh.
    ///
    /// Two triangles overlap when their interiors meet: by the separating-axis theorem, closed
    /// convex polygons have disjoint interiors iff one of their edges has the other polygon
    /// entirely on its closed outer side, so `A` and `B` overlap iff every edge of each has a
    /// vertex of the other strictly on its inner side (`orient > 0`). A T-junction is a vertex
    /// in the open segment of an edge it is not an end of: `orient(a, b, v) = 0` and
    /// `(v − a)·(v − b) < 0`.
    pub fn check(&self) -> Vec<MeshError> {
        let mut out = Vec::new();
        self.check_geometry(&mut out);
        for (g, o) in self.ordinates.iter().enumerate() {
            if out.len() >= MAX_PROBLEMS {
                break;
            }
            if o.is_none() {
                out.push(MeshError::MissingOrdinate(self.ordinate_id(g)));
            }
        }
        out.truncate(MAX_PROBLEMS);
        out
    }

    /// The geometric checks only (a mesh without ordinates passes if its triangulation is
    /// conforming).
    pub fn check_geometry(&self, out: &mut Vec<MeshError>) {
        let pts = Points::new(&self.vertices);
        // Orientation; the non-degenerate triangles with their vertices counter-clockwise.
        let mut ccw: Vec<Option<[usize; 3]>> = Vec::with_capacity(self.triangles.len());
        for (t, tri) in self.triangles.iter().enumerate() {
            match pts.orient(tri[0], tri[1], tri[2]) {
                Ordering::Equal => {
                    out.push(MeshError::Degenerate {
                        triangle: t,
                        vertices: *tri,
                    });
                    ccw.push(None);
                }
                Ordering::Less => {
                    out.push(MeshError::Clockwise {
                        triangle: t,
                        vertices: *tri,
                    });
                    ccw.push(Some([tri[0], tri[2], tri[1]]));
                }
                Ordering::Greater => ccw.push(Some(*tri)),
            }
        }
        // Duplicate triangles.
        let mut keyed: Vec<([usize; 3], usize)> = self
            .triangles
            .iter()
            .enumerate()
            .map(|(t, tri)| {
                let mut k = *tri;
                k.sort_unstable();
                (k, t)
            })
            .collect();
        keyed.sort_unstable();
        for w in keyed.windows(2) {
            if w[0].0 == w[1].0 {
                out.push(MeshError::DuplicateTriangle {
                    first: w[0].1,
                    second: w[1].1,
                });
            }
        }
        // Vertices at the same point (consecutive in the order by exact (x, y), then number);
        // unused vertices.
        let mut used = vec![false; self.vertices.len()];
        for tri in &self.triangles {
            for &v in tri {
                used[v] = true;
            }
        }
        let mut by_point: Vec<([f64; 2], usize)> = pts.near.iter().copied().zip(0..).collect();
        by_point.sort_unstable_by(|&(f, a), &(g, b)| {
            let by = |k: usize| {
                if f[k] < g[k] {
                    Ordering::Less
                } else if f[k] > g[k] {
                    Ordering::Greater
                } else {
                    pts.exact[a][k].cmp(&pts.exact[b][k])
                }
            };
            by(0).then_with(|| by(1)).then(a.cmp(&b))
        });
        let order: Vec<usize> = by_point.into_iter().map(|(_, v)| v).collect();
        // The rank of each vertex's x among the distinct x of the vertices (from `order`).
        let mut x_rank = vec![0u32; self.vertices.len()];
        for w in order.windows(2) {
            let step = pts.cmp(w[0], w[1], 0) != Ordering::Equal;
            x_rank[w[1]] = x_rank[w[0]] + u32::from(step);
        }
        for w in order.windows(2) {
            if pts.same_point(w[0], w[1]) {
                out.push(MeshError::DuplicateVertex {
                    first: w[0],
                    second: w[1],
                });
            }
        }
        for (v, &u) in used.iter().enumerate() {
            if !u {
                out.push(MeshError::UnusedVertex { vertex: v });
            }
        }
        if out.len() >= MAX_PROBLEMS {
            return;
        }
        let grid = self
            .grid
            .get_or_init(|| Grid::from_floats(&pts.near, &self.triangles));
        self.check_overlaps(&pts, &x_rank, grid, &ccw, out);
        if out.len() >= MAX_PROBLEMS {
            return;
        }
        self.check_t_junctions(&pts, grid, &order, &used, out);
    }

    /// Overlaps among the non-degenerate triangles (`ccw[t]`: counter-clockwise vertices), in
    /// the order of a sweep by exact `x_min` (then triangle number): each triangle against the
    /// later ones whose open boxes meet its own. If there are too many, the first ones found
    /// this way are kept (then sorted). The later ones are found in the grid: those listed in
    /// its cells (each pair in the first cell the two share) and those in `everywhere`,
    /// from where their rounded `x_min` reaches the triangle's to where it passes its `x_max`.
    /// Exact `x` are compared by `x_rank`, each vertex's rank among the distinct `x`.
    fn check_overlaps(
        &self,
        pts: &Points,
        x_rank: &[u32],
        grid: &Grid,
        ccw: &[Option<[usize; 3]>],
        out: &mut Vec<MeshError>,
    ) {
        // Bounding boxes as vertices [x_min, x_max, y_min, y_max] (exact extremes).
        let boxes: Vec<[usize; 4]> = self
            .triangles
            .iter()
            .map(|tri| {
                let ext = |k: usize, want: Ordering| {
                    let cmp = |v: usize, e: usize| match k {
                        0 => x_rank[v].cmp(&x_rank[e]),
                        _ => pts.cmp(v, e, 1),
                    };
                    tri[1..]
                        .iter()
                        .fold(tri[0], |e, &v| if cmp(v, e) == want { v } else { e })
                };
                [
                    ext(0, Ordering::Less),
                    ext(0, Ordering::Greater),
                    ext(1, Ordering::Less),
                    ext(1, Ordering::Greater),
                ]
            })
            .collect();
        // The same boxes rounded (the rounded extremes are the extremes of the rounded
        // coordinates).
        let fbox: Vec<[f64; 4]> = boxes
            .iter()
            .map(|b| {
                [
                    pts.near[b[0]][0],
                    pts.near[b[1]][0],
                    pts.near[b[2]][1],
                    pts.near[b[3]][1],
                ]
            })
            .collect();
        let mut sweep: Vec<(u32, usize)> = (0..self.triangles.len())
            .filter(|&t| ccw[t].is_some())
            .map(|t| (x_rank[boxes[t][0]], t))
            .collect();
        sweep.sort_unstable();
        const NONE: u32 = u32::MAX;
        let mut rank = vec![NONE; self.triangles.len()];
        for (r, &(_, t)) in sweep.iter().enumerate() {
            rank[t] = r as u32;
        }
        let budget = MAX_PROBLEMS - out.len();
        let mut found = Vec::new();
        let mut hits: Vec<(u32, usize)> = Vec::new();
        for &(_, t) in &sweep {
            hits.clear();
            let (rt, xmin, xmax) = (rank[t], fbox[t][0], fbox[t][1]);
            let (range, _) = grid.triangle_cells(t);
            // The candidates of one list (sorted by rounded x_min): from the first whose x_min
            // may equal t's to the last whose x_min may be below t's x_max.
            let mut scan = |list: &[u32], cell: Option<(usize, usize)>| {
                let start = list.partition_point(|&u| fbox[u as usize][0] < xmin);
                for &u in &list[start..] {
                    let u = u as usize;
                    if fbox[u][0] > xmax {
                        break;
                    }
                    if rank[u] == NONE || rank[u] <= rt {
                        continue;
                    }
                    if let Some((cx, cy)) = cell {
                        // only in the first cell shared with t
                        let (ru, _) = grid.triangle_cells(u);
                        if range[0].max(ru[0]) != cx || range[2].max(ru[2]) != cy {
                            continue;
                        }
                    }
                    if overlap(pts, x_rank, &boxes, &fbox, ccw, t, u) {
                        hits.push((rank[u], u));
                    }
                }
            };
            scan(grid.everywhere(), None);
            if grid.side() > 1 {
                for cy in range[2]..=range[3] {
                    for cx in range[0]..=range[1] {
                        scan(grid.cell_triangles(cy * grid.side() + cx), Some((cx, cy)));
                    }
                }
            }
            hits.sort_unstable();
            for &(_, u) in &hits {
                found.push((t.min(u), t.max(u)));
                if found.len() >= budget {
                    break;
                }
            }
            if found.len() >= budget {
                break;
            }
        }
        found.sort_unstable();
        out.extend(
            found
                .into_iter()
                .map(|(first, second)| MeshError::Overlap { first, second }),
        );
    }

    /// T-junctions: triangles in order, each edge where first met, the vertices in its open
    /// segment in the order of `order` (by exact (x, y), then number). The candidates of an
    /// edge are the used vertices in the grid cells of its rounded box, or, for an edge whose
    /// box covers too many cells, those between its ends in `x` (in `order`).
    fn check_t_junctions(
        &self,
        pts: &Points,
        grid: &Grid,
        order: &[usize],
        used: &[bool],
        out: &mut Vec<MeshError>,
    ) {
        let mut pos = vec![0u32; self.vertices.len()];
        for (i, &v) in order.iter().enumerate() {
            pos[v] = i as u32;
        }
        let by_x: Vec<usize> = order.iter().copied().filter(|&v| used[v]).collect();
        // The used vertices by cell (cell c holds items[start[c]..start[c + 1]]), in `order`.
        let side = grid.side();
        let (mut start, mut items) = (Vec::new(), Vec::new());
        if side > 1 {
            let cell = |v: usize| grid.point_cell(pts.near[v][0], pts.near[v][1]);
            start = vec![0u32; side * side + 1];
            for &v in &by_x {
                start[cell(v) + 1] += 1;
            }
            for c in 0..side * side {
                start[c + 1] += start[c];
            }
            let mut next = start.clone();
            items = vec![0u32; by_x.len()];
            for &v in &by_x {
                let c = cell(v);
                items[next[c] as usize] = v as u32;
                next[c] += 1;
            }
        }
        let mut seen = vec![false; self.edges.len()];
        let mut hits: Vec<(u32, usize)> = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (tri[i].min(tri[(i + 1) % 3]), tri[i].max(tri[(i + 1) % 3]));
                let e = self.edge_index(a, b).unwrap_or(0);
                if std::mem::replace(&mut seen[e], true) {
                    continue;
                }
                let (fa, fb) = (pts.near[a], pts.near[b]);
                let fbox = [
                    fa[0].min(fb[0]),
                    fa[0].max(fb[0]),
                    fa[1].min(fb[1]),
                    fa[1].max(fb[1]),
                ];
                hits.clear();
                let mut test = |v: usize| {
                    let f = pts.near[v];
                    // a vertex in the segment is in its box, so its floats are in the rounded box
                    if v != a
                        && v != b
                        && f[0] >= fbox[0]
                        && f[0] <= fbox[1]
                        && f[1] >= fbox[2]
                        && f[1] <= fbox[3]
                        && inside_segment(pts, a, b, v)
                    {
                        hits.push((pos[v], v));
                    }
                };
                let [cx0, cx1, cy0, cy1] = grid.box_cells(fbox[0], fbox[1], fbox[2], fbox[3]);
                if side > 1 && (cx1 - cx0 + 1) * (cy1 - cy0 + 1) <= MAX_CELLS_PER_TRIANGLE {
                    for cy in cy0..=cy1 {
                        for c in cy * side + cx0..=cy * side + cx1 {
                            for &v in &items[start[c] as usize..start[c + 1] as usize] {
                                test(v as usize);
                            }
                        }
                    }
                    hits.sort_unstable();
                } else {
                    let (lo, hi) = if pts.cmp(a, b, 0) != Ordering::Greater {
                        (a, b)
                    } else {
                        (b, a)
                    };
                    let first = by_x.partition_point(|&v| pts.cmp(v, lo, 0) == Ordering::Less);
                    for &v in &by_x[first..] {
                        if pts.cmp(v, hi, 0) == Ordering::Greater {
                            break;
                        }
                        test(v);
                    }
                }
                for &(_, v) in &hits {
                    out.push(MeshError::TJunction {
                        vertex: v,
                        a,
                        b,
                        triangle: t,
                    });
                    if out.len() >= MAX_PROBLEMS {
                        return;
                    }
                }
            }
        }
    }
}

/// Whether the interiors of the non-degenerate triangles `t` and `u` meet, given that `t`'s
/// exact `x_min` is not above `u`'s: their open boxes meet, and neither is separated.
fn overlap(
    pts: &Points,
    x_rank: &[u32],
    boxes: &[[usize; 4]],
    fbox: &[[f64; 4]],
    ccw: &[Option<[usize; 3]>],
    t: usize,
    u: usize,
) -> bool {
    let (bt, bu, ft, fu) = (boxes[t], boxes[u], fbox[t], fbox[u]);
    // y_min of one below y_max of the other, exactly, the floats first
    let below = |s: [usize; 4], fs: [f64; 4], r: [usize; 4], fr: [f64; 4]| match fs[2]
        .partial_cmp(&fr[3])
    {
        Some(Ordering::Less) => true,
        Some(Ordering::Greater) => false,
        _ => pts.exact[s[2]][1] < pts.exact[r[3]][1],
    };
    // x_min(t) ≤ x_min(u) < x_max(u) already
    if !(x_rank[bu[0]] < x_rank[bt[1]] && below(bu, fu, bt, ft) && below(bt, ft, bu, fu)) {
        return false;
    }
    let (Some(a), Some(b)) = (ccw[t], ccw[u]) else {
        return false;
    };
    !separated(pts, a, b) && !separated(pts, b, a)
}

/// Whether some edge of the counter-clockwise triangle `a` has all of `b` on its closed outer
/// side.
fn separated(pts: &Points, a: [usize; 3], b: [usize; 3]) -> bool {
    (0..3).any(|i| {
        b.iter()
            .all(|&r| pts.orient(a[i], a[(i + 1) % 3], r) != Ordering::Greater)
    })
}

/// `v` in the open segment `(a, b)`: `orient(a, b, v) = 0` and `(v − a)·(v − b) < 0`.
fn inside_segment(pts: &Points, a: usize, b: usize, v: usize) -> bool {
    if pts.orient(a, b, v) != Ordering::Equal {
        return false;
    }
    let [a, b, v] = [a, b, v].map(|i| &pts.exact[i]);
    let dot = (&v[0] - &a[0]) * (&v[0] - &b[0]) + (&v[1] - &a[1]) * (&v[1] - &b[1]);
    dot.is_negative()
}

/// The vertices, exact and rounded to the nearest `f64`: exact comparisons and orientations
/// with the float filters of the module documentation.
struct Points<'a> {
    exact: &'a [[BigRational; 2]],
    near: Vec<[f64; 2]>,
}

impl<'a> Points<'a> {
    fn new(exact: &'a [[BigRational; 2]]) -> Self {
        let near = exact
            .iter()
            .map(|p| [round_f64(&p[0]), round_f64(&p[1])])
            .collect();
        Points { exact, near }
    }

    /// Coordinate `k` of vertex `a` against that of `b`, exactly.
    fn cmp(&self, a: usize, b: usize, k: usize) -> Ordering {
        let (x, y) = (self.near[a][k], self.near[b][k]);
        if x < y {
            Ordering::Less
        } else if x > y {
            Ordering::Greater
        } else {
            self.exact[a][k].cmp(&self.exact[b][k])
        }
    }

    fn same_point(&self, a: usize, b: usize) -> bool {
        self.near[a] == self.near[b] && self.exact[a] == self.exact[b]
    }

    /// The sign of `orient(p, q, r)` (vertex numbers), exactly.
    fn orient(&self, p: usize, q: usize, r: usize) -> Ordering {
        if p == q || q == r || r == p {
            return Ordering::Equal;
        }
        if let Some(sign) = orient_filter(self.near[p], self.near[q], self.near[r]) {
            return sign;
        }
        let o = orient(&self.exact[p], &self.exact[q], &self.exact[r]);
        if o.is_positive() {
            Ordering::Greater
        } else if o.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
}

/// The sign of `(q − p) × (r − p)` for every exact point within one float of the floats `p, q,
/// r` (each coordinate `c` in `[c⁻, c⁺]`), when interval arithmetic proves it; `None` if the
/// interval contains 0 or a bound is not finite.
fn orient_filter(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Option<Ordering> {
    type I = (f64, f64);
    let point = |c: f64| (c.next_down(), c.next_up());
    // each bound rounded to nearest, then one float outwards: it bounds the exact result
    let sub = |a: I, b: I| ((a.0 - b.1).next_down(), (a.1 - b.0).next_up());
    let mul = |a: I, b: I| {
        let c = [a.0 * b.0, a.0 * b.1, a.1 * b.0, a.1 * b.1];
        (
            c[1..].iter().fold(c[0], |m, &x| m.min(x)).next_down(),
            c[1..].iter().fold(c[0], |m, &x| m.max(x)).next_up(),
        )
    };
    let [px, py, qx, qy, rx, ry] = [p[0], p[1], q[0], q[1], r[0], r[1]].map(point);
    let d = [sub(qx, px), sub(ry, py), sub(qy, py), sub(rx, px)];
    // finite factors: no 0·∞ (NaN, which min and max would drop) in the products
    if !d.iter().all(|i| i.0.is_finite() && i.1.is_finite()) {
        return None;
    }
    let (lo, hi) = sub(mul(d[0], d[1]), mul(d[2], d[3]));
    // (∞ − ∞ is NaN, which compares false: undecided)
    if lo > 0.0 {
        Some(Ordering::Greater)
    } else if hi < 0.0 {
        Some(Ordering::Less)
    } else {
        None
    }
}
