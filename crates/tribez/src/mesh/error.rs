//! [`MeshError`]: what is wrong with a mesh, located (which vertex, edge, triangle or ordinate).

use super::numbering::OrdinateId;

/// What is wrong with a mesh. Every variant names where (vertex, triangle and edge numbers
/// are 0-based, as in the file); `Display` is one line.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// The degree is 0 (a constant per triangle is not continuous across edges) or above the cap.
    #[error("degree {degree} is out of range: a mesh has degree 1 to {max}")]
    Degree {
        /// The degree given.
        degree: usize,
        /// The largest degree accepted ([`super::MAX_MESH_DEGREE`]).
        max: usize,
    },
    /// Too many (or no) vertices, triangles or ordinates.
    #[error("{what}: {found}, expected {min} to {max}")]
    Count {
        /// `"vertices"`, `"triangles"`, `"ordinates"`.
        what: &'static str,
        /// How many there are.
        found: usize,
        /// The fewest accepted.
        min: usize,
        /// The most accepted.
        max: usize,
    },
    /// A triangle names a vertex that does not exist.
    #[error("triangle {triangle} names vertex {vertex}, but the vertices are 0 to {last}")]
    VertexOutOfRange {
        /// The triangle.
        triangle: usize,
        /// The vertex index given.
        vertex: usize,
        /// The last vertex index.
        last: usize,
    },
    /// A triangle names the same vertex twice.
    #[error("triangle {triangle} names vertex {vertex} twice")]
    RepeatedVertex {
        /// The triangle.
        triangle: usize,
        /// The vertex named twice.
        vertex: usize,
    },
    /// A triangle number that does not exist.
    #[error("there is no triangle {triangle}: the triangles are 0 to {last}")]
    TriangleOutOfRange {
        /// The triangle asked for.
        triangle: usize,
        /// The last triangle index.
        last: usize,
    },
    /// A triangle whose three vertices are collinear (zero area).
    #[error("triangle {triangle} is degenerate: its vertices {vertices:?} are collinear")]
    Degenerate {
        /// The triangle.
        triangle: usize,
        /// Its vertex indices.
        vertices: [usize; 3],
    },
    /// A triangle listed clockwise.
    #[error(
        "triangle {triangle} (vertices {vertices:?}) is clockwise: list its vertices counter-clockwise"
    )]
    Clockwise {
        /// The triangle.
        triangle: usize,
        /// Its vertex indices.
        vertices: [usize; 3],
    },
    /// The same three vertices twice.
    #[error("triangles {first} and {second} have the same vertices")]
    DuplicateTriangle {
        /// The first.
        first: usize,
        /// The second.
        second: usize,
    },
    /// Two vertices at the same point (the triangles using them would not share their edges).
    #[error("vertices {first} and {second} are at the same point")]
    DuplicateVertex {
        /// The first.
        first: usize,
        /// The second.
        second: usize,
    },
    /// A vertex no triangle uses (its ordinate would belong to no patch).
    #[error("vertex {vertex} is used by no triangle")]
    UnusedVertex {
        /// The vertex.
        vertex: usize,
    },
    /// Two triangles whose interiors overlap.
    #[error("triangles {first} and {second} overlap")]
    Overlap {
        /// The first.
        first: usize,
        /// The second.
        second: usize,
    },
    /// A vertex inside an edge of a triangle that does not have it as a corner.
    #[error(
        "T-junction: vertex {vertex} lies inside edge {a}–{b} of triangle {triangle} (split that triangle at the vertex)"
    )]
    TJunction {
        /// The vertex.
        vertex: usize,
        /// The edge's lower vertex.
        a: usize,
        /// The edge's higher vertex.
        b: usize,
        /// A triangle with that edge.
        triangle: usize,
    },
    /// An ordinate the file does not give.
    #[error("{0} is missing")]
    MissingOrdinate(OrdinateId),
    /// An ordinate vector of the wrong length.
    #[error("the mesh has {expected} ordinates, {found} given")]
    OrdinateCount {
        /// [`super::Mesh::ordinate_count`].
        expected: usize,
        /// The length given.
        found: usize,
    },
    /// A multi-index that is not of the mesh's degree.
    #[error("multi-index {alpha:?} does not sum to the mesh's degree {degree}")]
    MultiIndex {
        /// The multi-index.
        alpha: [u32; 3],
        /// The degree.
        degree: usize,
    },
}
