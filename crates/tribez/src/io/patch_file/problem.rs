//! What is wrong in a patch file, as data.

#[cfg(doc)]
use super::{MAX_CONTROL_POINTS, MAX_DEGREE};

/// What is wrong in a patch file ([`crate::io::Problem::Patch`]): one variant per check, with the
/// figures of the message as data.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum PatchFileProblem {
    /// A kind other than a polynomial Bézier patch where only those are accepted.
    #[error("this is {kind}; only polynomial Bézier patches are accepted here")]
    NotPolynomial {
        /// The kind found (`"a rational patch"`, …).
        kind: &'static str,
    },
    /// A degree above the limit.
    #[error("degree {degree} is above the limit of {limit} (see docs/performance.md, Scaling)")]
    DegreeTooLarge {
        /// The degree.
        degree: usize,
        /// [`MAX_DEGREE`].
        limit: usize,
    },
    /// No `control_points` table.
    #[error("missing table `control_points`")]
    NoControlPointsTable,
    /// A `kind` that tribez does not know.
    #[error(
        "unknown kind `{kind}` (expected \"bezier\", \"rational\", \"functional\" or \"s-patch\")"
    )]
    UnknownKind {
        /// The kind given.
        kind: String,
    },
    /// `domain` or `weights` beside `polygon`.
    #[error("an S-patch (with `polygon`) cannot have `{key}`")]
    NotWithPolygon {
        /// The key (`"domain"` or `"weights"`).
        key: &'static str,
    },
    /// A `kind` other than `s-patch` beside `polygon`.
    #[error("kind `{kind}` contradicts `polygon` (an S-patch)")]
    KindContradictsPolygon {
        /// The kind given.
        kind: String,
    },
    /// `kind = "s-patch"` without `polygon`.
    #[error("an S-patch needs `polygon`")]
    SPatchNeedsPolygon,
    /// Weights on a Bézier or functional patch.
    #[error("a {kind} patch has no weights")]
    NoWeightsFor {
        /// The kind given.
        kind: String,
    },
    /// `kind = "rational"` without weights.
    #[error("a rational patch needs a [weights] table")]
    RationalNeedsWeights,
    /// A functional patch whose points are not ordinates.
    #[error(
        "a functional patch has one control ordinate per control point (d = 1), but its points have {dim} coordinates"
    )]
    FunctionalDimension {
        /// The points' dimension.
        dim: usize,
    },
    /// A weight keyed by something that is not a control point's multi-index.
    #[error(
        "no control point \"{key}\" (weights are keyed by the multi-indices of the control points)"
    )]
    WeightWithoutPoint {
        /// The key.
        key: String,
    },
    /// Two weight keys naming one control point.
    #[error("duplicated weight: \"{other}\" names the same control point")]
    DuplicateWeight {
        /// The earlier key.
        other: String,
    },
    /// A control point without a weight.
    #[error("missing weight \"{index}\" (every control point needs one)")]
    MissingWeight {
        /// Its multi-index.
        index: String,
    },
    /// Every weight zero.
    #[error("every weight is zero: the rational patch is undefined everywhere")]
    AllWeightsZero,
    /// An empty `control_points` table.
    #[error("no control points")]
    NoControlPoints,
    /// A key that is not a multi-index.
    #[error(
        "a key must be a multi-index of non-negative integers separated by commas, like \"1,0,1\""
    )]
    NotAMultiIndex,
    /// A multi-index with too few or too many parts.
    #[error("a multi-index needs 2 to {max_parts} parts separated by commas{}", comma_hint(.comma_form))]
    MultiIndexLength {
        /// `MAX_SIMPLEX_DIMENSION + 1`.
        max_parts: usize,
        /// The key with a comma between its digits, when it is written without commas as in
        /// the textbooks (`"200"` for `"2,0,0"`) and its digits sum to the degree.
        comma_form: Option<String>,
    },
    /// More control points than allowed.
    #[error(
        "degree {degree} on a {m}-simplex has {total} control points, above the limit of {limit}"
    )]
    TooManyControlPoints {
        /// The degree.
        degree: usize,
        /// The simplex dimension.
        m: usize,
        /// `C(degree + m, m)`.
        total: u128,
        /// [`MAX_CONTROL_POINTS`].
        limit: usize,
    },
    /// Multi-indices with different numbers of parts.
    #[error(
        "multi-index has {parts} parts, but \"{first}\" has {expected} (all keys need the same number)"
    )]
    MultiIndexParts {
        /// Parts of this key.
        parts: usize,
        /// The first key.
        first: String,
        /// Its parts.
        expected: usize,
    },
    /// A multi-index whose parts do not sum to the degree.
    #[error("multi-index sums to {sum}, but the degree is {degree}")]
    MultiIndexSum {
        /// The sum.
        sum: u64,
        /// The degree.
        degree: usize,
    },
    /// Two keys naming one control point.
    #[error("duplicated multi-index: \"{other}\" names the same control point")]
    DuplicateControlPoint {
        /// The earlier key.
        other: String,
    },
    /// A control point without coordinates.
    #[error("a control point needs at least one coordinate")]
    EmptyPoint,
    /// Control points of different dimensions.
    #[error(
        "point has {dim} coordinates, but \"{other}\" has {expected} (points of different dimensions)"
    )]
    PointDimension {
        /// This point's dimension.
        dim: usize,
        /// The key of the first point.
        other: String,
        /// Its dimension.
        expected: usize,
    },
    /// A multi-index without a control point.
    #[error(
        "missing control point \"{index}\" (every multi-index of degree {degree} must appear once)"
    )]
    MissingControlPoint {
        /// The multi-index.
        index: String,
        /// The degree.
        degree: usize,
    },
    /// A domain with the wrong number of vertices.
    #[error("the domain needs {expected} vertices for a {m}-simplex, found {found}")]
    DomainVertices {
        /// `m + 1`.
        expected: usize,
        /// The simplex dimension.
        m: usize,
        /// Vertices given.
        found: usize,
    },
}

/// `; write "2,0,0"` after the message of a key written without commas, else nothing.
fn comma_hint(comma_form: &Option<String>) -> String {
    comma_form
        .as_ref()
        .map(|k| format!("; write \"{k}\""))
        .unwrap_or_default()
}
