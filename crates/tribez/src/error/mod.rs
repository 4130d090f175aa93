//! Errors of the exact core: violated preconditions of a mathematical operation.
//!
//! The input layer ([`crate::io`]) adds the file, line and key; the command line turns either
//! into a one-line message and exit status 2.

mod algebraic;

use num_rational::BigRational;
use thiserror::Error;

pub use algebraic::AlgebraicError;

use crate::number::{format_points, format_tuple};

/// A mathematical precondition that an input violates.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CoreError {
    /// The domain simplex has (nearly) no volume: its vertices are affinely dependent.
    #[error("degenerate domain: the vertices {0} are affinely dependent (zero area)")]
    DegenerateDomain(String),
    /// A barycentric point whose coordinates do not sum to one.
    #[error("barycentric coordinates {coords} sum to {sum}, not 1")]
    NotBarycentric {
        /// The coordinates, as text.
        coords: String,
        /// Their sum, as text.
        sum: String,
    },
    /// A point or direction with the wrong number of coordinates.
    #[error("{what} has {found} coordinates, expected {expected}")]
    WrongLength {
        /// What has the wrong length (`"point"`, `"direction"`, …).
        what: String,
        /// The number of coordinates it needs.
        expected: usize,
        /// The number given.
        found: usize,
    },
    /// Wrong number of blossom arguments.
    #[error("the blossom of a degree-{degree} patch takes exactly {degree} arguments, got {found}")]
    BlossomArity {
        /// The degree `n`: the number of arguments needed.
        degree: usize,
        /// The number given.
        found: usize,
    },
    /// A barycentric direction whose components do not sum to zero.
    #[error(
        "direction {coords} sums to {sum}, not 0 (a barycentric direction is a difference of two points)"
    )]
    DirectionSum {
        /// The components, as text.
        coords: String,
        /// Their sum, as text.
        sum: String,
    },
    /// A derivative of order above the degree.
    #[error(
        "derivative of order {order} requested, but the patch has degree {degree} (order must be at most the degree)"
    )]
    OrderTooHigh {
        /// The order asked for.
        order: usize,
        /// The patch's degree.
        degree: usize,
    },
    /// A number that overflows the float format it is rounded to.
    #[error("{what} overflows {precision}")]
    Overflows {
        /// What overflows (`"a control point"`, `"an input"`).
        what: &'static str,
        /// `"f64"` or `"f32"`.
        precision: &'static str,
    },
    /// A simplex dimension `m` of 0.
    #[error("the simplex dimension m must be at least 1")]
    SimplexDimZero,
    /// Fewer items (control points, weights) than a degree over a simplex needs.
    #[error("degree {degree} over the {m}-simplex needs more {what} than the {found} given")]
    TooFew {
        /// The degree.
        degree: usize,
        /// The simplex dimension.
        m: usize,
        /// What is counted (`"control points"`, `"weights"`).
        what: &'static str,
        /// How many were given.
        found: usize,
    },
    /// A domain of fewer than two vertices.
    #[error("a domain needs at least two vertices")]
    DomainTooSmall,
    /// Two domains (of a join) over simplices of different dimensions.
    #[error("the domains are a {a}-simplex and a {b}-simplex")]
    DomainDimensions {
        /// The first domain's dimension.
        a: usize,
        /// The second's.
        b: usize,
    },
    /// A domain whose dimension is not the patch's.
    #[error("the domain is a {domain}-simplex, the patch is over a {patch}-simplex")]
    DomainOfPatch {
        /// The domain's dimension.
        domain: usize,
        /// The patch's simplex dimension.
        patch: usize,
    },
    /// Two patches of a join over simplices of different dimensions.
    #[error("the patches are over a {a}-simplex and a {b}-simplex")]
    SimplexDimensions {
        /// The first patch's simplex dimension.
        a: usize,
        /// The second's.
        b: usize,
    },
    /// Two patches of a join of different degrees.
    #[error(
        "the patches have degrees {a} and {b}: a join needs equal degrees (elevate the lower one first)"
    )]
    Degrees {
        /// The first patch's degree.
        a: usize,
        /// The second's.
        b: usize,
    },
    /// Two patches of a join whose control points have different dimensions.
    #[error("the control points have {a} and {b} coordinates")]
    PointDimensions {
        /// The first patch's.
        a: usize,
        /// The second's.
        b: usize,
    },
    /// The two domains of a join are one simplex.
    #[error(
        "the two domains are the same simplex [{}]: they must share exactly one {} (give each patch its own `domain`)",
        format_points(vertices),
        facet_word(*m)
    )]
    SameDomain {
        /// Its vertices.
        vertices: Vec<Vec<BigRational>>,
        /// The simplex dimension.
        m: usize,
    },
    /// The two domains of a join share no facet.
    #[error(
        "the domains [{}] and [{}] share no {} ({common} common vertices, {m} needed)",
        format_points(a),
        format_points(b),
        facet_word(*m)
    )]
    NoSharedFacet {
        /// The first domain's vertices.
        a: Vec<Vec<BigRational>>,
        /// The second's.
        b: Vec<Vec<BigRational>>,
        /// The simplex dimension (a facet has `m` vertices).
        m: usize,
        /// The vertices they share.
        common: usize,
    },
    /// A facet that is not `m` distinct vertices numbered 1 to `m + 1`.
    #[error(
        "the common {} needs {m} distinct vertices of A, numbered 1 to {}",
        facet_word(*m),
        m + 1
    )]
    FacetVertices {
        /// The simplex dimension.
        m: usize,
    },
    /// A C¹ neighbour whose new vertex lies on A's side of the common facet.
    #[error(
        "the new vertex {} lies on the same side of the common {} as A's vertex {opposite} (μ = {}): the triangles would overlap",
        format_tuple(vertex),
        facet_word(*m),
        format_tuple(mu)
    )]
    Overlap {
        /// The new vertex.
        vertex: Vec<BigRational>,
        /// The simplex dimension.
        m: usize,
        /// A's vertex off the facet (1-based).
        opposite: usize,
        /// The new vertex's barycentric coordinates in A's domain.
        mu: Vec<BigRational>,
    },
    /// A split point on a face of the domain (`subdivide` at a point).
    #[error(
        "the split point lies on the face opposite corner {corner} (coordinate {corner} is 0), so piece {corner} would be degenerate; use `halve` or `subpatch` instead"
    )]
    SplitOnFace {
        /// The corner (1-based).
        corner: usize,
    },
    /// An edge that is not two distinct corners.
    #[error("edge {i},{j}: an edge is two distinct corners numbered 1 to {corners}")]
    BadEdge {
        /// The first corner given.
        i: usize,
        /// The second.
        j: usize,
        /// The number of corners.
        corners: usize,
    },
    /// The four-way midpoint split of a patch that is not a triangle.
    #[error(
        "the four-way midpoint split is defined for triangles; this patch is over the {m}-simplex (use `subdivide --at` or `halve`)"
    )]
    MidpointSplit {
        /// The patch's simplex dimension.
        m: usize,
    },
    /// A functional patch whose points are not ordinates.
    #[error(
        "a functional patch has one ordinate per control point, this one has {dim} coordinates"
    )]
    NotFunctional {
        /// The points' dimension.
        dim: usize,
    },
    /// A function of higher degree than the patch that is to represent it.
    #[error("the function has degree {function}, above the patch degree {patch}")]
    FunctionDegree {
        /// The function's degree.
        function: usize,
        /// The patch's.
        patch: usize,
    },
    /// A point where a rational patch's denominator vanishes.
    #[error(
        "the rational patch is undefined at {}: its denominator Σ w_α B_α vanishes there (zero or negative weights)",
        format_tuple(at)
    )]
    RationalUndefined {
        /// The point (barycentric).
        at: Vec<BigRational>,
    },
    /// A weight 0 where tribez needs non-zero weights.
    #[error(
        "control point {} has weight 0 (a point at infinity); tribez needs non-zero weights here",
        index.iter().map(ToString::to_string).collect::<Vec<_>>().join(",")
    )]
    ZeroWeight {
        /// The control point's multi-index.
        index: Vec<u32>,
    },
    /// A derivative of a rational patch of too high an order.
    #[error(
        "a derivative of order {order} of a rational patch: at most {limit} directions (the work grows as 3^order)"
    )]
    RationalOrder {
        /// The order asked for.
        order: usize,
        /// The limit.
        limit: usize,
    },
    /// A tangent frame of a rational patch where a de Casteljau point is at infinity.
    #[error(
        "the level-{level} de Casteljau point {point} has weight 0 at {}: it is at infinity, so the tangent frame is not defined there",
        format_tuple(at)
    )]
    FrameAtInfinity {
        /// The de Casteljau level.
        level: usize,
        /// The point's index at that level.
        point: usize,
        /// Where (barycentric).
        at: Vec<BigRational>,
    },
    /// A rational blossom whose weight blossom vanishes.
    #[error(
        "the rational blossom b[{args}] is undefined: the weight blossom W[{args}] (the blossom of the denominator Σ w_α B_α) is 0",
        args = args.iter().map(|a| format_tuple(a)).collect::<Vec<_>>().join(", ")
    )]
    BlossomUndefined {
        /// The blossom's arguments.
        args: Vec<Vec<BigRational>>,
    },
    /// A kind evaluated at Cartesian points, asked for barycentric ones (`flag`: how the
    /// caller asks for Cartesian points, e.g. `"cartesian=True"`).
    #[error("{kind} is evaluated at Cartesian points ({flag})")]
    CartesianPoints {
        /// The kind, with its article (`"an S-patch"`).
        kind: &'static str,
        /// How to give Cartesian points.
        flag: &'static str,
    },
    /// A patch of degree 0 has no tangent plane.
    #[error("a patch of degree 0 is constant: it has no tangent plane")]
    ConstantPatch,
    /// A polygon of fewer than three vertices.
    #[error("a polygon needs at least 3 vertices, found {found}")]
    PolygonTooSmall {
        /// Vertices given.
        found: usize,
    },
    /// A clockwise polygon.
    #[error(
        "the polygon is clockwise: list its vertices counter-clockwise (tribez does not reverse them, since the control points are keyed by vertex order)"
    )]
    Clockwise,
    /// A polygon that is not strictly convex.
    #[error(
        "the polygon is not strictly convex (or is self-intersecting): vertex {vertex} {} is {} the line through edge {edge}–{}",
        format_tuple(point),
        if *on { "on" } else { "right of" },
        edge % vertices + 1
    )]
    NotConvex {
        /// The offending vertex (1-based).
        vertex: usize,
        /// Its coordinates.
        point: Vec<BigRational>,
        /// On the line (else right of it).
        on: bool,
        /// The edge from this vertex (1-based) to the next.
        edge: usize,
        /// The number of vertices.
        vertices: usize,
    },
    /// A point outside an S-patch's polygon.
    #[error(
        "the point {} is outside the polygon (right of edge {edge}–{}); Wachspress coordinates are used on the closed polygon only",
        format_tuple(point),
        edge % vertices + 1
    )]
    OutsidePolygon {
        /// The point.
        point: Vec<BigRational>,
        /// The edge it is right of, from this vertex (1-based) to the next.
        edge: usize,
        /// The number of vertices.
        vertices: usize,
    },
    /// An S-patch whose control points are not indexed by the polygon's vertices.
    #[error(
        "the polygon has {vertices} vertices, so control points need {vertices} index parts, not {parts}"
    )]
    IndexParts {
        /// The polygon's vertices.
        vertices: usize,
        /// The index parts of the control points.
        parts: usize,
    },
    /// An input that, rounded to the float program's precision, violates a precondition
    /// (`what`: `"the polygon"`).
    #[error("{what} rounded to {precision}: {error}")]
    Rounded {
        /// What was rounded.
        what: &'static str,
        /// `"f64"` or `"f32"`.
        precision: &'static str,
        /// What is wrong once rounded.
        error: Box<CoreError>,
    },
    /// A float program without a proven error bound.
    #[error("{precision}: the float program has no proven bound")]
    NoProvenBound {
        /// `"f64"` or `"f32"`.
        precision: &'static str,
    },
    /// A float program of `precision` that cannot be built.
    #[error("{precision}: {error}")]
    InPrecision {
        /// `"f64"` or `"f32"`.
        precision: &'static str,
        /// Why.
        error: Box<CoreError>,
    },
}

/// A facet of the `m`-simplex in words: an edge of a triangle, else a facet.
fn facet_word(m: usize) -> &'static str {
    if m == 2 { "edge" } else { "facet" }
}
