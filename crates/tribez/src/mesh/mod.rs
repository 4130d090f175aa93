//! Meshes of functional Bézier triangles sharing their ordinates (docs/theory.md §17), after
//! Wolfe's blog "Bezier Triangles": data stored per vertex, per edge and per triangle, looked up
//! by finding the triangle that contains a point.
//!
//! A [`Mesh`] has vertices `(x, y)` (exact), counter-clockwise triangles (three vertex indices),
//! a degree `n ≥ 1`, and one global vector of control ordinates in a fixed numbering
//! ([`OrdinateId`]; vertex ordinates, then edge ordinates, then triangle interiors). Triangle
//! `t` with vertices `(v0, v1, v2)` in file order is the functional patch
//! `f(λ) = Σ_{|α|=n} b_{g(t, α)} B^n_α(λ)` where `λ` are the barycentric coordinates relative to
//! `(v0, v1, v2)` and `g` = [`Mesh::global_index`]. Neighbours read the same ordinates along
//! their common edge, so the mesh is continuous (C0) by construction.
//!
//! ```
//! use tribez::mesh::{Mesh, OrdinateId};
//! use tribez::parse_rational as q;
//! // The unit square cut along its diagonal 0–2, quadratic.
//! let v = |x: &str, y: &str| [q(x).unwrap(), q(y).unwrap()];
//! let mesh = Mesh::new(
//!     vec![v("0", "0"), v("1", "0"), v("1", "1"), v("0", "1")],
//!     vec![[0, 1, 2], [0, 2, 3]],
//!     2,
//! )
//! .unwrap();
//! // 4 vertex ordinates, 5 edges (0–1, 0–2, 0–3, 1–2, 2–3) with one ordinate each, no interiors.
//! assert_eq!(mesh.ordinate_count(), 9);
//! // In triangle 1 = (0, 2, 3), α = (1, 1, 0) is the midpoint of edge 0–2: edge number 1.
//! assert_eq!(mesh.global_index(1, [1, 1, 0]), 4 + 1);
//! assert_eq!(mesh.ordinate_id(5), OrdinateId::Edge { a: 0, b: 2, k: 1 });
//! // Fill in f(x, y) = x + y: ordinates are its values at the Bézier abscissae (linear precision).
//! let f = |g: usize| -> tribez::Rational {
//!     let p = mesh.abscissa(g);
//!     &p[0] + &p[1]
//! };
//! let mesh = mesh.with_ordinates((0..9).map(f).collect()).unwrap();
//! let hits = mesh.lookup(&v("1/2", "1/2")).unwrap(); // on the diagonal: both triangles
//! assert_eq!(hits.len(), 2);
//! assert!(hits.iter().all(|(_, value)| *value == q("1").unwrap()));
//! ```

mod check;
pub use check::MAX_PROBLEMS;
mod error;
mod file;
mod float;
mod locate;
mod numbering;

use std::sync::OnceLock;

use num_rational::BigRational;
use num_traits::Zero;

pub use error::MeshError;
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub use file::fuzz_mesh;
pub use file::{
    MESH_KEYS, MeshFileProblem, MeshLines, ORDINATE_KEYS, mesh_from_document, read_mesh,
};
pub use float::FloatLookup;
pub use locate::{Located, barycentric, orient};
pub use numbering::{OrdinateId, interior_count, interior_indices, interior_rank};

use crate::simplex::Simplex;
use crate::{Degree, Patch};

/// The largest degree of a mesh.
pub const MAX_MESH_DEGREE: usize = 30;
/// The most vertices of a mesh.
pub const MAX_VERTICES: usize = 1_000_000;
/// The most triangles of a mesh.
pub const MAX_TRIANGLES: usize = 2_000_000;
/// The most control ordinates of a mesh.
pub const MAX_ORDINATES: usize = 4_000_000;

/// A triangle mesh carrying the control ordinates of a C0 piecewise-polynomial function of
/// degree `n` (see the [module documentation](self)).
#[derive(Debug, Clone)]
pub struct Mesh {
    vertices: Vec<[BigRational; 2]>,
    triangles: Vec<[usize; 3]>,
    degree: usize,
    /// The edges `[a, b]`, `a < b`, sorted.
    edges: Vec<[usize; 2]>,
    ordinates: Vec<Option<BigRational>>,
    grid: OnceLock<locate::Grid>,
}

impl PartialEq for Mesh {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices
            && self.triangles == other.triangles
            && self.degree == other.degree
            && self.ordinates == other.ordinates
    }
}

impl Mesh {
    /// A mesh without ordinates (every ordinate absent): checks the sizes against the caps, the
    /// degree (`1 ≤ n ≤` [`MAX_MESH_DEGREE`]), and that every triangle names three distinct
    /// existing vertices. The geometry (orientation, overlaps, T-junctions) is checked by
    /// [`Mesh::check`].
    pub fn new(
        vertices: Vec<[BigRational; 2]>,
        triangles: Vec<[usize; 3]>,
        degree: usize,
    ) -> Result<Mesh, MeshError> {
        count("vertices", vertices.len(), 3, MAX_VERTICES)?;
        count("triangles", triangles.len(), 1, MAX_TRIANGLES)?;
        if degree == 0 || degree > MAX_MESH_DEGREE {
            return Err(MeshError::Degree {
                degree,
                max: MAX_MESH_DEGREE,
            });
        }
        for (t, tri) in triangles.iter().enumerate() {
            for (i, &v) in tri.iter().enumerate() {
                if v >= vertices.len() {
                    return Err(MeshError::VertexOutOfRange {
                        triangle: t,
                        vertex: v,
                        last: vertices.len() - 1,
                    });
                }
                if tri[..i].contains(&v) {
                    return Err(MeshError::RepeatedVertex {
                        triangle: t,
                        vertex: v,
                    });
                }
            }
        }
        let mut edges: Vec<[usize; 2]> = triangles
            .iter()
            .flat_map(|t| (0..3).map(move |i| sorted(t[i], t[(i + 1) % 3])))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        let total = ordinate_total(vertices.len(), edges.len(), triangles.len(), degree);
        count("ordinates", total.unwrap_or(usize::MAX), 0, MAX_ORDINATES)?;
        let total = total.unwrap_or(0);
        Ok(Mesh {
            vertices,
            triangles,
            degree,
            edges,
            ordinates: vec![None; total],
            grid: OnceLock::new(),
        })
    }

    /// The vertices `(x, y)`.
    pub fn vertices(&self) -> &[[BigRational; 2]] {
        &self.vertices
    }

    /// The triangles (vertex indices, counter-clockwise in a valid mesh).
    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The edges `[a, b]` (`a < b`), sorted: edge `e` in [`OrdinateId`] numbering.
    pub fn edges(&self) -> &[[usize; 2]] {
        &self.edges
    }

    /// The edge number of `a–b` (either order), if some triangle has that edge.
    pub fn edge_index(&self, a: usize, b: usize) -> Option<usize> {
        self.edges.binary_search(&sorted(a, b)).ok()
    }

    /// The ordinates in the global numbering (`None` where absent).
    pub fn ordinates(&self) -> &[Option<BigRational>] {
        &self.ordinates
    }

    /// `V + E(n−1) + T(n−1)(n−2)/2`.
    pub fn ordinate_count(&self) -> usize {
        self.ordinates.len()
    }

    /// The same geometry with degree `n` and no ordinates.
    pub fn with_degree(&self, n: usize) -> Result<Mesh, MeshError> {
        Mesh::new(self.vertices.clone(), self.triangles.clone(), n)
    }

    /// The same geometry and degree with every ordinate given (in the global numbering).
    pub fn with_ordinates(&self, ordinates: Vec<BigRational>) -> Result<Mesh, MeshError> {
        self.with_optional_ordinates(ordinates.into_iter().map(Some).collect())
    }

    /// The same geometry and degree with these ordinates (some may be absent).
    pub fn with_optional_ordinates(
        &self,
        ordinates: Vec<Option<BigRational>>,
    ) -> Result<Mesh, MeshError> {
        if ordinates.len() != self.ordinate_count() {
            return Err(MeshError::OrdinateCount {
                expected: self.ordinate_count(),
                found: ordinates.len(),
            });
        }
        Ok(Mesh {
            ordinates,
            ..self.clone()
        })
    }

    fn vertex_end(&self) -> usize {
        self.vertices.len()
    }

    fn edge_end(&self) -> usize {
        self.vertices.len() + self.edges.len() * (self.degree - 1)
    }

    /// Where ordinate `g` sits. Panics if `g ≥` [`Mesh::ordinate_count`].
    pub fn ordinate_id(&self, g: usize) -> OrdinateId {
        assert!(g < self.ordinate_count(), "ordinate {g} out of range");
        let n = self.degree;
        if g < self.vertex_end() {
            OrdinateId::Vertex { v: g }
        } else if g < self.edge_end() {
            let r = g - self.vertex_end();
            let [a, b] = self.edges[r / (n - 1)];
            OrdinateId::Edge {
                a,
                b,
                k: r % (n - 1) + 1,
            }
        } else {
            let r = g - self.edge_end();
            let per = interior_count(n);
            let index = r % per;
            let alpha = interior_indices(n)[index];
            OrdinateId::Interior {
                triangle: r / per,
                index,
                alpha,
            }
        }
    }

    /// The global ordinate of the Bernstein coefficient with multi-index `α = (i, j, k)`
    /// relative to triangle `triangle`'s vertices `(v0, v1, v2)` in file order: the vertex
    /// ordinate if `α = n e_i`; ordinate `k'` of edge `a–b` (`k'` = the entry of `α` on the
    /// higher vertex `b`) if exactly one entry is 0; else the triangle's interior ordinate
    /// ranked by [`interior_rank`]. Panics if the triangle does not exist or `|α| ≠ n`.
    pub fn global_index(&self, triangle: usize, alpha: [u32; 3]) -> usize {
        let n = self.degree;
        assert!(
            alpha.iter().map(|&a| a as usize).sum::<usize>() == n,
            "multi-index {alpha:?} is not of degree {n}"
        );
        let t = self.triangles[triangle];
        let zeros = alpha.iter().filter(|&&a| a == 0).count();
        match zeros {
            2 => t[alpha.iter().position(|&a| a != 0).unwrap_or(0)],
            1 => {
                let z = alpha.iter().position(|&a| a == 0).unwrap_or(0);
                let (p, q) = ((z + 1) % 3, (z + 2) % 3);
                let (a, b, kb) = if t[p] < t[q] {
                    (t[p], t[q], alpha[q])
                } else {
                    (t[q], t[p], alpha[p])
                };
                let e = self
                    .edge_index(a, b)
                    // invariant: the edge list is built from every triangle's edges when the mesh is made
                    .expect("every triangle edge is in the edge list");
                self.vertex_end() + e * (n - 1) + (kb as usize - 1)
            }
            _ => self.edge_end() + triangle * interior_count(n) + interior_rank(alpha),
        }
    }

    /// The global ordinates of triangle `t`, in the canonical multi-index order of degree `n`.
    pub fn local_indices(&self, t: usize) -> Vec<usize> {
        Simplex::new(2, self.degree)
            .iter()
            .map(|a| self.global_index(t, [a[0], a[1], a[2]]))
            .collect()
    }

    /// The Bézier abscissa of ordinate `g`: the point `Σ α_i v_i / n` it is attached to
    /// (for a polynomial `F` of degree ≤ 1 the ordinate is `F` there).
    pub fn abscissa(&self, g: usize) -> [BigRational; 2] {
        let n = BigRational::from_integer(self.degree.into());
        let weighted = |pairs: &[(usize, u32)]| {
            let mut p = [BigRational::zero(), BigRational::zero()];
            for &(v, w) in pairs {
                let w = BigRational::from_integer(w.into());
                for (pc, vc) in p.iter_mut().zip(&self.vertices[v]) {
                    *pc += &w * vc;
                }
            }
            p.map(|c| c / &n)
        };
        match self.ordinate_id(g) {
            OrdinateId::Vertex { v } => self.vertices[v].clone(),
            OrdinateId::Edge { a, b, k } => {
                weighted(&[(a, (self.degree - k) as u32), (b, k as u32)])
            }
            OrdinateId::Interior {
                triangle, alpha, ..
            } => {
                let t = self.triangles[triangle];
                weighted(&[(t[0], alpha[0]), (t[1], alpha[1]), (t[2], alpha[2])])
            }
        }
    }

    fn triangle_exists(&self, t: usize) -> Result<(), MeshError> {
        if t < self.triangles.len() {
            Ok(())
        } else {
            Err(MeshError::TriangleOutOfRange {
                triangle: t,
                last: self.triangles.len() - 1,
            })
        }
    }

    /// The control ordinates of triangle `t` in canonical order; an error naming the first
    /// absent one.
    pub fn triangle_ordinates(&self, t: usize) -> Result<Vec<BigRational>, MeshError> {
        self.triangle_exists(t)?;
        self.local_indices(t)
            .into_iter()
            .map(|g| {
                self.ordinates[g]
                    .clone()
                    .ok_or_else(|| MeshError::MissingOrdinate(self.ordinate_id(g)))
            })
            .collect()
    }

    /// Triangle `t` as a functional patch (`m = 2`, domain = its vertices in file order).
    pub fn triangle_patch(&self, t: usize) -> Result<Patch, crate::Error> {
        let ordinates = self.triangle_ordinates(t)?;
        let domain = self.triangles[t]
            .iter()
            .map(|&v| self.vertices[v].to_vec())
            .collect();
        Patch::functional(domain, Degree(self.degree), ordinates)
    }

    /// Every triangle containing the point (closed triangles), with exact barycentric
    /// coordinates, by increasing triangle number; empty outside the mesh. Exact
    /// (docs/theory.md §17). Degenerate triangles (collinear vertices, which [`Mesh::check`]
    /// reports) are skipped.
    pub fn locate(&self, point: &[BigRational; 2]) -> Vec<Located> {
        let grid = self
            .grid
            .get_or_init(|| locate::Grid::new(&self.vertices, &self.triangles));
        let (x, y) = (
            crate::number::round_f64(&point[0]),
            crate::number::round_f64(&point[1]),
        );
        let mut found: Vec<Located> = grid
            .candidates(x, y)
            .filter_map(|t| {
                let tri = self.triangles[t].map(|v| &self.vertices[v]);
                // a degenerate triangle (zero area: `mesh check` reports it) contains no point
                // with barycentric coordinates
                if locate::orient(tri[0], tri[1], tri[2]).is_zero() {
                    return None;
                }
                locate::inside(tri, point).then(|| Located {
                    triangle: t,
                    barycentric: barycentric(tri, point),
                })
            })
            .collect();
        found.sort_by_key(|l| l.triangle);
        found.dedup_by_key(|l| l.triangle);
        found
    }

    /// The exact value of triangle `located.triangle` at its barycentric coordinates, by
    /// de Casteljau's algorithm (docs/theory.md §2).
    pub fn value(&self, located: &Located) -> Result<BigRational, MeshError> {
        let b = self.triangle_ordinates(located.triangle)?;
        Ok(casteljau(self.degree, b, &located.barycentric))
    }

    /// `Σ_α |b_α| B^n_α(|λ|)` of triangle `located.triangle` at its barycentric coordinates: the
    /// condition number of de Casteljau's algorithm there (docs/theory.md §14.1), which the
    /// `cond` tolerances of `lookup` claims scale with.
    pub fn condition(&self, located: &Located) -> Result<BigRational, MeshError> {
        use num_traits::Signed;
        let b = self.triangle_ordinates(located.triangle)?;
        let b: Vec<BigRational> = b.iter().map(Signed::abs).collect();
        let l = located.barycentric.clone().map(|q| q.abs());
        Ok(casteljau(self.degree, b, &l))
    }

    /// Every triangle containing the point and the value there (equal for all of them in a
    /// C0 mesh); empty outside the mesh; an error if an ordinate needed is absent.
    pub fn lookup(
        &self,
        point: &[BigRational; 2],
    ) -> Result<Vec<(Located, BigRational)>, MeshError> {
        self.locate(point)
            .into_iter()
            .map(|l| {
                let v = self.value(&l)?;
                Ok((l, v))
            })
            .collect()
    }
}

/// de Casteljau for one scalar: `b` in canonical order of degree `n`; each step
/// `(λ0 b_{α+e0} + λ1 b_{α+e1}) + λ2 b_{α+e2}`, left to right.
fn casteljau<T: crate::scalar::Scalar>(n: usize, mut b: Vec<T>, lambda: &[T; 3]) -> T {
    for r in (1..=n).rev() {
        let stencil = Simplex::new(2, r).step_stencil();
        b = stencil
            .chunks_exact(3)
            .map(|s| {
                lambda[0].clone() * &b[s[0]]
                    + &(lambda[1].clone() * &b[s[1]])
                    + &(lambda[2].clone() * &b[s[2]])
            })
            .collect();
    }
    b.pop().unwrap_or_else(T::one)
}

fn sorted(a: usize, b: usize) -> [usize; 2] {
    [a.min(b), a.max(b)]
}

fn count(what: &'static str, found: usize, min: usize, max: usize) -> Result<(), MeshError> {
    if (min..=max).contains(&found) {
        Ok(())
    } else {
        Err(MeshError::Count {
            what,
            found,
            min,
            max,
        })
    }
}

/// `V + E(n−1) + T(n−1)(n−2)/2`, `None` on overflow.
fn ordinate_total(v: usize, e: usize, t: usize, n: usize) -> Option<usize> {
    v.checked_add(e.checked_mul(n - 1)?)?
        .checked_add(t.checked_mul(interior_count(n))?)
}

#[cfg(test)]
mod check_tests;
#[cfg(test)]
mod file_tests;
#[cfg(test)]
mod tests;
