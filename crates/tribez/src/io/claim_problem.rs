//! What is wrong in a claim file ([`super::Problem::Claim`]): one variant per check of the
//! claim file format and of the claim operations' inputs, with the figures of the message as
//! data. `Display` is the message after the location (file, line, key).
//!
//! A new claim operation reports its bad inputs through these variants (or
//! [`super::Problem`]'s general ones: `MissingKey`, `WrongType`, `Overflows`, `Core`, …); a
//! check no variant covers gets a new variant here, never a message written at the call site.

use crate::certify::measures::Tolerance;
use crate::error::CoreError;
use crate::float::Precision;
use crate::judge_refusal::{Lacks, Refusal};

/// What is wrong in a claim file or a claim's inputs.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ClaimProblem {
    /// `patch` (or an entry of `[patches]`) that is neither a file name nor a table.
    #[error("expected a patch file name or an inline patch table, found {found}")]
    NotAPatch {
        /// What it is (`"a number"`, …).
        found: &'static str,
    },
    /// A path given to check that names no claim file and no directory holding one.
    #[error("no claim files (*.claims.toml, *.claims.json)")]
    NoClaimFiles,
    /// No `[[claim]]` table.
    #[error("no claims (expected [[claim]] tables)")]
    NoClaims,
    /// Two claims with one id.
    #[error("duplicate claim id `{id}`")]
    DuplicateId {
        /// The id.
        id: String,
    },
    /// A claim without `expect`.
    #[error("missing key `expect` (the claimed value)")]
    MissingExpect,
    /// An operation that tribez does not know.
    #[error("unknown operation `{op}` (known: {})", known.join(", "))]
    UnknownOp {
        /// The operation given.
        op: String,
        /// The operations tribez knows.
        known: Vec<&'static str>,
    },
    /// A `lookup` claim at a point outside its mesh (as seen, with `precision`).
    #[error("the point ({x}, {y}) lies outside the mesh {mesh}")]
    OutsideMesh {
        /// `x`, exact.
        x: String,
        /// `y`, exact.
        y: String,
        /// The mesh file.
        mesh: String,
    },
    /// `tolerance = "bound"` on a `lookup` claim: de Casteljau's bound does not cover the
    /// barycentric coordinates a float lookup computes first.
    #[error(
        "tolerance `bound` does not apply to `lookup` claims (the float lookup's barycentric coordinates are not covered by de Casteljau's bound); use cond=K, ulps=N, abs=E or rel=E"
    )]
    BoundNotForLookup,
    /// An operation given a kind of patch it does not take.
    #[error("operation `{op}` does not take a {kind} patch")]
    KindNotTaken {
        /// The operation.
        op: String,
        /// The kind (`"rational"`, `"S-patch"`, …).
        kind: &'static str,
    },
    /// An operation that needs one kind of patch.
    #[error("`{op}` needs {needs}")]
    NeedsKind {
        /// The operation.
        op: &'static str,
        /// The kind it needs.
        needs: NeededKind,
    },
    /// A claim without a patch in a file without a default one.
    #[error("this claim needs a patch: give `patch` at the top of the file")]
    NeedsPatch,
    /// A patch name not under `[patches]`.
    #[error("no patch named `{name}` under [patches]")]
    NoSuchPatch {
        /// The name.
        name: String,
    },
    /// A float tolerance without a precision.
    #[error("tolerance `{tolerance}` needs `precision = \"f64\"` or `\"f32\"`")]
    ToleranceNeedsPrecision {
        /// The tolerance.
        tolerance: Tolerance,
    },
    /// A tolerance relative to the condition number on an operation other than `eval`.
    #[error(
        "tolerance `{tolerance}` applies to `eval` claims only (`cond` also to `lookup`; it needs the condition number Σ|c_i|B_i)"
    )]
    ToleranceEvalOnly {
        /// The tolerance.
        tolerance: Tolerance,
    },
    /// The float view asked of an operation other than `eval`.
    #[error("the float view is defined for `eval` claims only")]
    FloatViewEvalOnly,
    /// A required input is absent.
    #[error("missing input `{name}`{}", hint.map_or(String::new(), |h| format!(" ({h})")))]
    MissingInput {
        /// The input.
        name: String,
        /// What it takes (`"two corner numbers, like [1, 2]"`), when the message says it.
        hint: Option<&'static str>,
    },
    /// A required corner number is absent.
    #[error("missing input `{name}` (a corner, 1 to {corners})")]
    MissingCorner {
        /// The input.
        name: String,
        /// The number of corners.
        corners: usize,
    },
    /// A corner number out of range.
    #[error("corner {corner} does not exist: corners are numbered 1 to {corners}")]
    NoSuchCorner {
        /// The corner given.
        corner: usize,
        /// The number of corners.
        corners: usize,
    },
    /// An edge curve from a corner to itself.
    #[error("`from` and `to` must be different corners")]
    SameCorners,
    /// Text that is none of the words an input takes.
    #[error("`{text}`: expected {}", one_of(choices))]
    NotOneOf {
        /// The text given.
        text: String,
        /// The words it takes.
        choices: &'static [&'static str],
    },
    /// An input that takes one of a few words, given something else (`kind` of `matrix`).
    #[error("`{name}` must be {}", one_of(choices))]
    MustBeOneOf {
        /// The input.
        name: &'static str,
        /// The words it takes.
        choices: &'static [&'static str],
    },
    /// Not a boolean.
    #[error("expected true or false")]
    NotABool,
    /// A claimed integer that is not one.
    #[error("`{text}` is not an integer")]
    NotAnInteger {
        /// The text.
        text: String,
    },
    /// A claimed value of another shape than the exact value's.
    #[error("expected {expected}, found {found}")]
    ClaimedShape {
        /// What the exact value is (`"a polynomial (string)"`, `"an array"`, …).
        expected: &'static str,
        /// What the claim has.
        found: &'static str,
    },
    /// A claimed table with a key the exact value does not have.
    #[error("unexpected key")]
    UnexpectedKey,
    /// A polynomial that does not parse (`reason`: what the polynomial parser found, and where).
    #[error("`{text}`: {reason}")]
    BadPolynomial {
        /// The text.
        text: String,
        /// What is wrong.
        reason: crate::symbolic::PolyError,
    },
    /// A point with the wrong number of coordinates.
    #[error("{found} coordinates, expected {expected}")]
    CoordinateCount {
        /// Coordinates given.
        found: usize,
        /// Coordinates needed.
        expected: usize,
    },
    /// Barycentric `at` for a kind that takes Cartesian points.
    #[error("{kind} takes Cartesian points: use `cartesian`")]
    CartesianOnly {
        /// The kind, with its article (`"an S-patch"`).
        kind: &'static str,
    },
    /// Neither or both of `at` and `cartesian`.
    #[error("give exactly one of `at` (barycentric) or `cartesian`")]
    AtOrCartesian,
    /// Neither or both of `at` and `midpoints` (`subdivide`).
    #[error("give exactly one of `at` (a barycentric point) or `midpoints = true`")]
    AtOrMidpoints,
    /// Variable names that do not match the variables.
    #[error("{given} names given, {needed} variables needed")]
    VariableNames {
        /// Names given.
        given: usize,
        /// Variables.
        needed: usize,
    },
    /// Coordinate names that do not match the points' dimension.
    #[error("{given} names given, the points have {dim} coordinates")]
    CoordinateNames {
        /// Names given.
        given: usize,
        /// The points' dimension.
        dim: usize,
    },
    /// A `part` that the operation does not offer.
    #[error("`{part}` is not available here (available: {})", known.join(", "))]
    UnknownPart {
        /// The part asked for.
        part: String,
        /// The parts offered.
        known: Vec<String>,
    },
    /// A component index at or above the points' dimension.
    #[error("component {component} does not exist: the points have {dim} coordinates (0-based)")]
    NoSuchComponent {
        /// The component (0-based).
        component: usize,
        /// The points' dimension.
        dim: usize,
    },
    /// An edge that is not two numbers.
    #[error("an edge is two corner numbers, like [1, 2]")]
    EdgeShape,
    /// A simplex dimension out of range.
    #[error("the simplex dimension must be 1 to {limit}")]
    SimplexDimension {
        /// The largest simplex dimension.
        limit: usize,
    },
    /// A number of vertices that makes no simplex of at most the largest dimension.
    #[error("{count} vertices: the simplex dimension must be 1 to {limit}")]
    VertexCount {
        /// Vertices given.
        count: usize,
        /// The largest simplex dimension.
        limit: usize,
    },
    /// Fewer than two vertices.
    #[error("give m+1 vertices (3 for a triangle)")]
    TooFewVertices,
    /// A piece number other than 1 or 2 (`halve`).
    #[error("the piece is 1 or 2")]
    PieceNumber,
    /// A degree and simplex with too many control points.
    #[error(
        "degree {degree} on a {m}-simplex has {count} control points, above the limit of {limit}"
    )]
    TooManyControlPoints {
        /// The degree.
        degree: usize,
        /// The simplex dimension.
        m: usize,
        /// The number of control points, C(degree + m, m).
        count: u128,
        /// The limit.
        limit: usize,
    },
    /// A degree or simplex dimension out of range.
    #[error(
        "degree {degree} on a {m}-simplex is out of range (degree at most {max_degree}, simplex dimension 1 to {max_m})"
    )]
    DegreeOutOfRange {
        /// The degree.
        degree: usize,
        /// The simplex dimension.
        m: usize,
        /// The largest degree.
        max_degree: usize,
        /// The largest simplex dimension.
        max_m: usize,
    },
    /// A degree above the limit.
    #[error("degree {degree} is above the limit of {limit}")]
    DegreeAbove {
        /// The degree.
        degree: usize,
        /// The limit.
        limit: usize,
    },
    /// An elevation that is zero or passes the degree limit.
    #[error("elevate by 1 to {most} (the degree is capped at {limit})")]
    ElevateBy {
        /// The largest elevation allowed from this degree.
        most: usize,
        /// The degree limit.
        limit: usize,
    },
    /// A matrix with more rows than the limit.
    #[error(
        "the matrix would be too large (at most {limit} rows, the control points of the degree)"
    )]
    MatrixTooLarge {
        /// The largest number of rows.
        limit: usize,
    },
    /// A join given other than two patches.
    #[error("a join needs two patches, {named} named")]
    JoinCount {
        /// Patches named.
        named: usize,
    },
    /// A join given a patch of a kind it does not take.
    #[error("`join` does not take a {kind} patch (`{name}`)")]
    JoinKind {
        /// The kind.
        kind: &'static str,
        /// The patch's name.
        name: String,
    },
    /// A derivative without directions.
    #[error("give at least one direction in `dirs` (barycentric) or `vectors` (Cartesian)")]
    NoDirections,
    /// A patch or domain that, rounded to the precision of the float program, violates a
    /// precondition (`what`: `None` for the whole input, or `"the polygon"`).
    #[error("{}rounded to {precision}: {error}", what.map_or(String::new(), |w| format!("{w} ")))]
    Rounded {
        /// What was rounded, when the message names it.
        what: Option<&'static str>,
        /// The precision.
        precision: Precision,
        /// What is wrong once rounded.
        error: CoreError,
    },
    /// The condition number is undefined at the input as the float program saw it.
    #[error("the condition number is undefined as the code saw it")]
    ConditionUndefined,
    /// The float program of a claim cannot be judged (see [`Refusal`]).
    #[error(transparent)]
    Judge(#[from] Refusal),
    /// What the tolerance needs and the kind lacks.
    #[error(transparent)]
    Lacks(#[from] Lacks),
}

/// The kind an operation needs ([`ClaimProblem::NeedsKind`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum NeededKind {
    /// A functional patch.
    #[error("a functional patch (kind = \"functional\")")]
    Functional,
    /// An S-patch.
    #[error("an S-patch (a patch file with `polygon`)")]
    SPatch,
}

/// `"a"`, `"a" or "b"`, `"a", "b" or "c"`.
fn one_of(choices: &[&str]) -> String {
    let quoted: Vec<String> = choices.iter().map(|c| format!("\"{c}\"")).collect();
    match quoted.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => quoted.join(""),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn choices_read_as_a_list() {
        assert_eq!(one_of(&["halve"]), "\"halve\"");
        assert_eq!(one_of(&["a", "b"]), "\"a\" or \"b\"");
        assert_eq!(one_of(&["a", "b", "c"]), "\"a\", \"b\" or \"c\"");
    }
}
