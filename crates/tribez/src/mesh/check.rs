//! [`Mesh::check`]: is the mesh a conforming triangulation carrying every ordinate?
//! (docs/theory.md §17). Every predicate is an exact sign.

use std::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::locate::orient;
use super::{Mesh, MeshError};

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
        let p = |v: usize| &self.vertices[v];
        // Orientation.
        let mut good = Vec::with_capacity(self.triangles.len());
        for (t, tri) in self.triangles.iter().enumerate() {
            let o = orient(p(tri[0]), p(tri[1]), p(tri[2]));
            if o.is_zero() {
                out.push(MeshError::Degenerate {
                    triangle: t,
                    vertices: *tri,
                });
            } else {
                if o.is_negative() {
                    out.push(MeshError::Clockwise {
                        triangle: t,
                        vertices: *tri,
                    });
                }
                good.push((t, o.is_negative()));
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
        // Vertices at the same point; unused vertices.
        let mut used = vec![false; self.vertices.len()];
        for tri in &self.triangles {
            for &v in tri {
                used[v] = true;
            }
        }
        let mut order: Vec<usize> = (0..self.vertices.len()).collect();
        order.sort_by(|&a, &b| cmp_point(p(a), p(b)).then(a.cmp(&b)));
        for w in order.windows(2) {
            if p(w[0]) == p(w[1]) {
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
        self.check_overlaps(&good, out);
        if out.len() >= MAX_PROBLEMS {
            return;
        }
        // T-junctions: used vertices sorted by x, each edge tests those in its x range.
        let by_x: Vec<usize> = order.into_iter().filter(|&v| used[v]).collect();
        let mut seen = vec![false; self.edges.len()];
        for (t, tri) in self.triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (tri[i].min(tri[(i + 1) % 3]), tri[i].max(tri[(i + 1) % 3]));
                let e = self.edge_index(a, b).unwrap_or(0);
                if std::mem::replace(&mut seen[e], true) {
                    continue;
                }
                let (lo, hi) = if p(a)[0] <= p(b)[0] {
                    (&p(a)[0], &p(b)[0])
                } else {
                    (&p(b)[0], &p(a)[0])
                };
                let start = by_x.partition_point(|&v| p(v)[0] < *lo);
                for &v in by_x[start..].iter().take_while(|&&v| p(v)[0] <= *hi) {
                    if v != a && v != b && inside_segment(p(a), p(b), p(v)) {
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

    /// Overlaps among the non-degenerate triangles (`(t, clockwise)`), by a sweep in `x`.
    fn check_overlaps(&self, good: &[(usize, bool)], out: &mut Vec<MeshError>) {
        let p = |v: usize| &self.vertices[v];
        // Counter-clockwise vertex order and exact bounding boxes.
        let tris: Vec<(usize, [usize; 3], [&BigRational; 4])> = good
            .iter()
            .map(|&(t, cw)| {
                let mut tri = self.triangles[t];
                if cw {
                    tri.swap(1, 2);
                }
                let xs = tri.map(|v| &p(v)[0]);
                let ys = tri.map(|v| &p(v)[1]);
                (t, tri, [min3(xs), max3(xs), min3(ys), max3(ys)])
            })
            .collect();
        let mut order: Vec<usize> = (0..tris.len()).collect();
        order.sort_by(|&i, &j| tris[i].2[0].cmp(tris[j].2[0]).then(i.cmp(&j)));
        let mut found = Vec::new();
        for (pos, &i) in order.iter().enumerate() {
            let (ti, a, bi) = &tris[i];
            for &j in &order[pos + 1..] {
                let (tj, b, bj) = &tris[j];
                if bj[0] >= bi[1] {
                    break;
                }
                if bj[2] >= bi[3] || bi[2] >= bj[3] {
                    continue;
                }
                let ta = a.map(&p);
                let tb = b.map(&p);
                if separated(ta, tb) || separated(tb, ta) {
                    continue;
                }
                found.push(((*ti).min(*tj), (*ti).max(*tj)));
                if found.len() + out.len() >= MAX_PROBLEMS {
                    break;
                }
            }
            if found.len() + out.len() >= MAX_PROBLEMS {
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
}

/// Whether some edge of the counter-clockwise triangle `a` has all of `b` on its closed outer
/// side.
fn separated(a: [&[BigRational; 2]; 3], b: [&[BigRational; 2]; 3]) -> bool {
    (0..3).any(|i| {
        b.iter()
            .all(|r| !orient(a[i], a[(i + 1) % 3], r).is_positive())
    })
}

/// `v` in the open segment `(a, b)`.
fn inside_segment(a: &[BigRational; 2], b: &[BigRational; 2], v: &[BigRational; 2]) -> bool {
    if !orient(a, b, v).is_zero() {
        return false;
    }
    let dot = (&v[0] - &a[0]) * (&v[0] - &b[0]) + (&v[1] - &a[1]) * (&v[1] - &b[1]);
    dot.is_negative()
}

fn cmp_point(a: &[BigRational; 2], b: &[BigRational; 2]) -> Ordering {
    a[0].cmp(&b[0]).then_with(|| a[1].cmp(&b[1]))
}

fn min3(a: [&BigRational; 3]) -> &BigRational {
    a[0].min(a[1]).min(a[2])
}

fn max3(a: [&BigRational; 3]) -> &BigRational {
    a[0].max(a[1]).max(a[2])
}
