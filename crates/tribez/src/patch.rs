//! Control nets of Bézier simplices, and the polynomial [`BezierPatch`] a file describes.
//!
//! A [`ControlNet<T>`] of degree `n` over the `m`-simplex holds one point of `ℝ^d` (`d >= 1`)
//! for every multi-index `|α| = n`, stored in the canonical order of [`crate::simplex`]. It
//! describes the polynomial map
//!
//! `p(λ) = Σ_{|α|=n} c_α B^n_α(λ)`,  `B^n_α(λ) = n!/(α_0!⋯α_m!) λ_0^{α_0} ⋯ λ_m^{α_m}`,
//!
//! a homogeneous form of degree `n` in the barycentric coordinates `λ = (λ_0, …, λ_m)`
//! (`(u, v, w)` on a triangle). Corner `k` interpolates `c_{n e_k}`.

use num_rational::BigRational;

use crate::domain::Domain;
use crate::simplex::{self, Simplex};

/// The control points of a Bézier simplex, generic over the number type.
#[derive(Clone, Debug, PartialEq)]
pub struct ControlNet<T> {
    simplex: Simplex,
    dim: usize,
    /// Point `r` occupies `coords[r*dim .. (r+1)*dim]`.
    coords: Vec<T>,
}

impl<T: Clone> ControlNet<T> {
    /// A net from flat coordinates in canonical order (`len = C(n+m,m) · dim`).
    pub fn new(simplex: Simplex, dim: usize, coords: Vec<T>) -> Self {
        assert!(dim >= 1, "points need at least one coordinate");
        assert_eq!(
            coords.len(),
            simplex.len() * dim,
            "wrong number of coordinates"
        );
        ControlNet {
            simplex,
            dim,
            coords,
        }
    }

    /// A net from a list of points in canonical order.
    pub fn from_points(m: usize, degree: usize, points: &[Vec<T>]) -> Self {
        let dim = points.first().map_or(1, Vec::len);
        let coords = points.iter().flat_map(|p| p.iter().cloned()).collect();
        ControlNet::new(Simplex::new(m, degree), dim, coords)
    }

    /// The multi-indices of the net.
    pub fn simplex(&self) -> &Simplex {
        &self.simplex
    }

    /// Dimension `m` of the domain simplex.
    pub fn m(&self) -> usize {
        self.simplex.dimension()
    }

    /// Degree `n`.
    pub fn degree(&self) -> usize {
        self.simplex.degree()
    }

    /// Dimension `d` of the points.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Number of control points.
    pub fn len(&self) -> usize {
        self.simplex.len()
    }

    /// Never true.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// All coordinates, point after point.
    pub fn coords(&self) -> &[T] {
        &self.coords
    }

    /// Control point of rank `r`.
    pub fn point(&self, r: usize) -> &[T] {
        &self.coords[r * self.dim..(r + 1) * self.dim]
    }

    /// Control point `c_α`.
    pub fn at(&self, alpha: &[u32]) -> &[T] {
        self.point(self.simplex.rank(alpha))
    }

    /// The points in canonical order.
    pub fn points(&self) -> impl ExactSizeIterator<Item = &[T]> + '_ {
        self.coords.chunks_exact(self.dim)
    }

    /// Multi-indices paired with their points.
    pub fn entries(&self) -> impl Iterator<Item = (&[u32], &[T])> + '_ {
        self.simplex.iter().zip(self.points())
    }

    /// Apply `f` to every coordinate.
    pub fn map<U: Clone>(&self, f: impl FnMut(&T) -> U) -> ControlNet<U> {
        ControlNet {
            simplex: self.simplex.clone(),
            dim: self.dim,
            coords: self.coords.iter().map(f).collect(),
        }
    }

    /// Coordinate `c` of every point, as a scalar net (`d = 1`).
    pub fn component(&self, c: usize) -> ControlNet<T> {
        let coords = self.points().map(|p| p[c].clone()).collect();
        ControlNet::new(self.simplex.clone(), 1, coords)
    }

    /// The corner point `c_{n e_k}`.
    pub fn corner(&self, k: usize) -> &[T] {
        self.at(&simplex::corner(self.m(), self.degree(), k))
    }

    /// The net of the face spanned by the given vertices (in that order): a Bézier simplex of
    /// dimension `vertices.len() − 1`. For two vertices `a, b` this is the boundary curve from
    /// corner `a` to corner `b`, control points `c_{(n−j) e_a + j e_b}`, `j = 0..n`.
    pub fn face(&self, vertices: &[usize]) -> ControlNet<T> {
        assert!(vertices.len() >= 2);
        let sub = Simplex::new(vertices.len() - 1, self.degree());
        let mut full = vec![0u32; self.m() + 1];
        let mut coords = Vec::with_capacity(sub.len() * self.dim);
        for beta in sub.iter() {
            full.iter_mut().for_each(|x| *x = 0);
            for (&v, &b) in vertices.iter().zip(beta) {
                full[v] = b;
            }
            coords.extend_from_slice(self.at(&full));
        }
        ControlNet::new(sub, self.dim, coords)
    }
}

/// A Bézier simplex with exact rational control points, as read from a patch file.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch {
    /// Free-form name from the file.
    pub name: Option<String>,
    /// The control net.
    pub net: ControlNet<BigRational>,
    /// The domain simplex in `ℝ^m`; `None` means the reference simplex of [`Domain::reference`].
    pub domain: Option<Domain>,
}

impl BezierPatch {
    /// A patch over the reference domain.
    pub fn new(net: ControlNet<BigRational>) -> Self {
        BezierPatch {
            name: None,
            net,
            domain: None,
        }
    }

    /// The domain, or the reference simplex if none was given.
    pub fn domain_or_reference(&self) -> Domain {
        self.domain
            .clone()
            .unwrap_or_else(|| Domain::reference(self.net.m()))
    }
}
