//! The global numbering of a mesh's control ordinates ([`OrdinateId`]).
//!
//! With `V` vertices, `E` edges and `T` triangles of degree `n`, the ordinates are numbered
//!
//! * `0 .. V`: one per vertex, in vertex order (the ordinate `b_{n e_i}` at the corner);
//! * `V .. V + E(n−1)`: per edge, edges sorted by `(lower, higher)` vertex index, its `n − 1`
//!   interior ordinates from the lower to the higher vertex: ordinate `k = 1 … n−1` of edge
//!   `a–b` (`a < b`) sits at the Bézier abscissa `((n−k) a + k b)/n`;
//! * then per triangle its `(n−1)(n−2)/2` interior ordinates (every `α_i ≥ 1`), in the
//!   canonical multi-index order of docs/theory.md §1 relative to the triangle's vertices in
//!   file order.
//!
//! Two triangles sharing an edge therefore read the same ordinates along it: the mesh is C0 by
//! construction (docs/theory.md §17).

use std::fmt;

use crate::simplex::rank;

/// One control ordinate of a mesh, by where it sits. Vertex, edge and triangle numbers are
/// 0-based, as in the mesh file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum OrdinateId {
    /// The ordinate at vertex `v`.
    Vertex {
        /// The vertex.
        v: usize,
    },
    /// Ordinate `k` (`1 ≤ k ≤ n − 1`, counted from `a`) inside the edge `a–b`, `a < b`: the
    /// coefficient whose multi-index puts `n − k` on `a` and `k` on `b`.
    Edge {
        /// The lower vertex.
        a: usize,
        /// The higher vertex.
        b: usize,
        /// Steps from `a`, `1 … n−1`.
        k: usize,
    },
    /// An interior ordinate of a triangle: position `index` (0-based) among the triangle's
    /// interior ordinates, multi-index `alpha` relative to its vertices in file order.
    Interior {
        /// The triangle.
        triangle: usize,
        /// Position among its interior ordinates.
        index: usize,
        /// Its multi-index `(i, j, k)`, every entry `≥ 1`.
        alpha: [u32; 3],
    },
}

impl fmt::Display for OrdinateId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OrdinateId::Vertex { v } => write!(f, "the ordinate of vertex {v}"),
            OrdinateId::Edge { a, b, k } => write!(f, "edge {a}–{b}, ordinate {k}"),
            OrdinateId::Interior {
                triangle, alpha, ..
            } => write!(
                f,
                "triangle {triangle}, interior ordinate ({},{},{})",
                alpha[0], alpha[1], alpha[2]
            ),
        }
    }
}

/// Number of interior ordinates of a triangle of degree `n`: `(n−1)(n−2)/2`.
pub fn interior_count(n: usize) -> usize {
    if n < 3 { 0 } else { (n - 1) * (n - 2) / 2 }
}

/// Position of an interior multi-index (every entry `≥ 1`, sum `n`) among the interior
/// multi-indices in canonical order: the rank of `α − (1, 1, 1)` in degree `n − 3` (subtracting
/// one from every entry keeps the order).
pub fn interior_rank(alpha: [u32; 3]) -> usize {
    rank(&[alpha[0] - 1, alpha[1] - 1, alpha[2] - 1])
}

/// The interior multi-indices of degree `n`, in canonical order.
pub fn interior_indices(n: usize) -> Vec<[u32; 3]> {
    let n = n as u32;
    let mut out = Vec::with_capacity(interior_count(n as usize));
    if n < 3 {
        return out;
    }
    for k in 1..=n - 2 {
        for j in 1..=n - 1 - k {
            out.push([n - j - k, j, k]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interior_indices_follow_the_canonical_order() {
        // Degree 5: the interior indices are 311 221 131 212 122 113 (k ascending, then j),
        // written by hand from the order 300 210 … of docs/theory.md §1 shifted by 111.
        let got = interior_indices(5);
        assert_eq!(
            got,
            vec![
                [3, 1, 1],
                [2, 2, 1],
                [1, 3, 1],
                [2, 1, 2],
                [1, 2, 2],
                [1, 1, 3]
            ]
        );
        for (r, a) in got.iter().enumerate() {
            assert_eq!(interior_rank(*a), r);
        }
        assert_eq!(interior_count(5), 6);
        assert_eq!(interior_indices(3), vec![[1, 1, 1]]);
        assert!(interior_indices(2).is_empty());
    }

    #[test]
    fn display_names_the_ordinate() {
        assert_eq!(
            OrdinateId::Edge { a: 3, b: 7, k: 2 }.to_string(),
            "edge 3–7, ordinate 2"
        );
        assert_eq!(
            OrdinateId::Vertex { v: 4 }.to_string(),
            "the ordinate of vertex 4"
        );
        let id = OrdinateId::Interior {
            triangle: 2,
            index: 0,
            alpha: [1, 1, 1],
        };
        assert_eq!(id.to_string(), "triangle 2, interior ordinate (1,1,1)");
        // from degree 13 on an entry has two digits: (11,1,1), (1,11,1) and (1,1,11) are
        // three different ordinates, and their names must differ
        let names: Vec<String> = [[11, 1, 1], [1, 11, 1], [1, 1, 11]]
            .into_iter()
            .map(|alpha| {
                let id = OrdinateId::Interior {
                    triangle: 0,
                    index: interior_rank(alpha),
                    alpha,
                };
                id.to_string()
            })
            .collect();
        assert_eq!(
            names,
            [
                "triangle 0, interior ordinate (11,1,1)",
                "triangle 0, interior ordinate (1,11,1)",
                "triangle 0, interior ordinate (1,1,11)"
            ]
        );
    }
}
