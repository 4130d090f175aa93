//! The C1 conditions of a mesh as exact linear constraints on its ordinates (docs/theory.md §8,
//! §18.2).
//!
//! For an interior edge `a–b` shared by triangles `T` (opposite vertex `c`) and `U` (opposite
//! vertex `d`), let `μ = (μ_a, μ_b, μ_c)` be the barycentric coordinates of `d` relative to
//! `(a, b, c)`. Both pieces agree on the edge (the mesh shares its ordinates), and they join C1
//! exactly when, for every `i + j = n − 1`,
//!
//! `u_{i,j,1} = μ_a t_{i+1,j,0} + μ_b t_{i,j+1,0} + μ_c t_{i,j,1}`,
//!
//! where `t_{i,j,k}` is `T`'s ordinate with `i` on `a`, `j` on `b`, `k` on `c`, and `u_{i,j,1}`
//! is `U`'s with `i` on `a`, `j` on `b`, 1 on `d` (the μ rule, with `a1 = a`, `a2 = b`,
//! `a3 = c`, `a4 = d`). Each is one row of `C x = 0` in the global numbering: `n` rows per
//! interior edge, at most four non-zeros each.

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::linalg::exact::SparseRow;
use crate::mesh::{Mesh, barycentric};

/// One interior edge: its vertices `a < b`, the triangle `T` and its opposite vertex `c`, and
/// the triangle `U` (the other one) with its opposite vertex `d`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InteriorEdge {
    /// The lower vertex.
    pub a: usize,
    /// The higher vertex.
    pub b: usize,
    /// The triangle of lower number.
    pub t: usize,
    /// The vertex of `t` opposite the edge.
    pub c: usize,
    /// The other triangle.
    pub u: usize,
    /// The vertex of `u` opposite the edge.
    pub d: usize,
}

/// Every edge shared by two triangles, sorted by `(a, b)`.
pub fn interior_edges(mesh: &Mesh) -> Vec<InteriorEdge> {
    let mut sides: Vec<([usize; 2], usize, usize)> = Vec::new();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        for i in 0..3 {
            let (p, q, o) = (tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]);
            sides.push(([p.min(q), p.max(q)], t, o));
        }
    }
    sides.sort_unstable();
    sides
        .windows(2)
        .filter(|w| w[0].0 == w[1].0)
        .map(|w| InteriorEdge {
            a: w[0].0[0],
            b: w[0].0[1],
            t: w[0].1,
            c: w[0].2,
            u: w[1].1,
            d: w[1].2,
        })
        .collect()
}

/// The multi-index relative to triangle `tri`'s vertices (file order) that puts `i` on `a`,
/// `j` on `b` and `k` on `o`.
fn alpha(
    tri: [usize; 3],
    (a, i): (usize, usize),
    (b, j): (usize, usize),
    (o, k): (usize, usize),
) -> [u32; 3] {
    let mut al = [0u32; 3];
    for (v, e) in [(a, i), (b, j), (o, k)] {
        let pos = tri.iter().position(|&w| w == v).unwrap_or(0);
        al[pos] = e as u32;
    }
    al
}

/// The μ of an interior edge: the barycentric coordinates of `d` relative to `(a, b, c)`.
pub fn mu(mesh: &Mesh, e: &InteriorEdge) -> [BigRational; 3] {
    let v = mesh.vertices();
    barycentric([&v[e.a], &v[e.b], &v[e.c]], &v[e.d])
}

/// The rows of `C` (`C x = 0` ⇔ the mesh is C1), `n` per interior edge, in the order of
/// [`interior_edges`] and then `i = n − 1, …, 0` (`j = n − 1 − i`).
pub fn c1_constraints(mesh: &Mesh) -> Vec<SparseRow> {
    let n = mesh.degree();
    let tris = mesh.triangles();
    let mut rows = Vec::new();
    for e in interior_edges(mesh) {
        let [ma, mb, mc] = mu(mesh, &e);
        let (tt, tu) = (tris[e.t], tris[e.u]);
        for i in (0..n).rev() {
            let j = n - 1 - i;
            let gu = mesh.global_index(e.u, alpha(tu, (e.a, i), (e.b, j), (e.d, 1)));
            let g1 = mesh.global_index(e.t, alpha(tt, (e.a, i + 1), (e.b, j), (e.c, 0)));
            let g2 = mesh.global_index(e.t, alpha(tt, (e.a, i), (e.b, j + 1), (e.c, 0)));
            let g3 = mesh.global_index(e.t, alpha(tt, (e.a, i), (e.b, j), (e.c, 1)));
            let mut row: Vec<(usize, BigRational)> = Vec::with_capacity(4);
            let mut add = |g: usize, v: BigRational| {
                if let Some(entry) = row.iter_mut().find(|(h, _)| *h == g) {
                    entry.1 += v;
                } else {
                    row.push((g, v));
                }
            };
            add(gu, BigRational::one());
            add(g1, -ma.clone());
            add(g2, -mb.clone());
            add(g3, -mc.clone());
            row.retain(|(_, v)| !v.is_zero());
            row.sort_by_key(|(g, _)| *g);
            rows.push(row);
        }
    }
    rows
}
