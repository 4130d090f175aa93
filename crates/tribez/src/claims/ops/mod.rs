//! The operations a claim can name: [`ClaimOp`], one variant per operation with its inputs
//! parsed and typed ([`ClaimOp::parse`]), then computed exactly ([`ClaimOp::compute`]).
//!
//! | op | inputs | value |
//! |---|---|---|
//! | `eval` | `at` (barycentric, summing to 1; with `precision` any sum: the homogeneous form) or `cartesian`; optional `algorithm` (`casteljau`, `bernstein`: for `tolerance = "bound"`) | the point |
//! | `symbolic` | `variables` = `"barycentric"` (default) or `"cartesian"`; optional `names`, `component` (0-based) | one polynomial per coordinate (or the one selected) |
//! | `basis` | `degree`, optional `simplex` (m, default 2), `names`, `at` | the Bernstein polynomials (or their values at `at`) keyed by multi-index |
//! | `basis_sum` | as `basis`, optional `variables = "cartesian"` | `Σ_α B^n_α` as a polynomial (or value) |
//! | `blossom` | `args`: exactly n barycentric points | the point `b[args]` (rational patches: `X[args]/W[args]`, the homogeneous net's blossom projected) |
//! | `subpatch` | `vertices`: m+1 barycentric points | control points keyed like a patch file (`"2,0,0" = [...]`); rational patches: `{control_points, weights, domain_in_parent}` |
//! | `subdivide` | `at` (a barycentric point) or `midpoints = true` | a list of such tables, one per piece |
//! | `halve` | `edge = [I, J]`; optional `method` = `"blossom"` (default), `"add-and-halve"`, `"add-and-halve-bottom-first"` | the two halves, a list of tables |
//! | `elevate` | optional `by` (default 1; the degree reached is at most 200) | control points keyed like a patch file |
//! | `matrix` | `kind` = `"halve"` (`degree`, optional `simplex`, `edge`, `piece`) or `"subpatch"` (`degree`, `vertices`); at most 1000 rows | the rows, a list of lists |
//! | `derivative` | `at` or `cartesian`; `dirs` (barycentric directions) and/or `vectors` (Cartesian) | the derivative of order `len(dirs) + len(vectors)` |
//! | `tangent` | `at` or `cartesian`; optional `part` | `{point, intermediate, partials, regular, normal, spans_tangent_plane}` (or that part) |
//! | `edge_curve` | `from`, `to` (corners, 1-based) | control points of `t ↦ p((1−t) e_from + t e_to)` |
//! | `join` | `patches = ["a", "b"]` (names under `[patches]`); optional `part` | `{c0, c1, g1, coplanarity, max_smoothness, mu, violations, g1_determinant}` (or that part) |
//! | `barycentric` | `domain` (m+1 vertices), `point` (Cartesian) | the barycentric coordinates (Cramer) |
//! | `direction` | `domain`, `vector` (Cartesian) | the directional coordinates (they sum to 0) |
//! | `implicit` | `equation` (a polynomial in the coordinates), optional `coordinates` (their names, default `x, y, z`), `names` | the residual `W^k F(X/W)` as a polynomial in the patch's variables (barycentric; `x, y` for an S-patch); `"0"` proves the whole patch lies on `F = 0`. A polynomial patch is homogenised: `X` is its barycentric form (homogeneous of degree n) and `W = (Σλ)^n` |
//! | `wachspress` | `cartesian` (a point of an S-patch's polygon) | `{ A = [A_j], C = [C_i], lambda = [λ_i] }` (docs/theory.md §12) |
//! | `abscissae` | (a functional or Bézier patch) | the Bézier abscissae `ξ_α` keyed by multi-index |
//! | `ordinates` | `domain`, `degree`, `function` (polynomial in `x, y`, or `names`) | the control ordinates `b_α` keyed by multi-index |
//! | `graph` | (a functional patch) | the control points `(ξ_α, b_α)` of its graph, keyed by multi-index |
//! | `intersect` | `patches = ["a", "b"]` (two planar curves) | the intersections' `(s, t)`: `expect` lists claimed pairs, or is a count ([`inverse`]) |
//! | `locate` | `point` (x, y), optional `anywhere` | the parameters `(s, t)` mapping to the point ([`inverse`]) |
//! | `ray` | `origin`, `direction`; or `height` (x, y) on a functional patch | the hits `(τ, s, t)` with `τ ≥ 0`; with `height`, `(z, s, t)` ([`inverse`]) |
//! | `lookup` | `mesh` (a mesh file beside the claim file), `at` (x, y); optional `triangle` (claimed) | the value of the mesh at the point (with `triangle`: `{triangle, value}`) ([`lookup`]) |
//!
//! `eval` also takes rational patches (`at` or `cartesian`) and S-patches (`cartesian` only).
//!
//! Each op lists the keys it reads ([`OpName::keys`]); any other key in a claim is an error (a
//! typo must not be silently ignored). Sizes the claim controls (degrees, `by`, matrix rows,
//! control-point counts) are checked against the documented limits before anything is allocated.
//!
//! **Precision.** With `precision = "f64"` or `"f32"`, every number of the claim denotes the
//! float nearest its text, and every operation computes from the inputs *as the float code saw
//! them* ([`ClaimOp::seen`]): the patch's control points (for a rational patch its homogeneous
//! net `(w c, w)`, for an S-patch its polygon too) and the op's numeric inputs (points,
//! directions, vertices, domains) rounded to the precision; a Cartesian point is rounded, then
//! converted with the patch's exact domain. Polynomial texts (`equation`, `function`) and
//! integers (degrees, corners) stay exact. `eval` keeps both views ([`FloatEval`]): the verdict at
//! the inputs as seen, the error at the intended inputs beside it.

mod claimed;
mod construct;
mod forms;
mod inputs;
pub mod inverse;
mod join;
pub mod lookup;
mod point;
pub(crate) mod seen;
#[cfg(test)]
mod tests;

use std::borrow::Cow;

use num_rational::BigRational;

use super::value::Value;
use super::{CLAIM_KEYS, Claim, ClaimFile};
use crate::io::patch_file::index_key;
use crate::io::{ClaimProblem, InputError};

pub use claimed::read_claimed;
pub use construct::{Construction, HalveMethod, MatrixKind, SubdivideMode};
pub use forms::{Basis, Form};
pub use inputs::{Inputs, Point};
pub use inverse::InverseOp;
pub use join::JoinOp;
pub use lookup::LookupOp;
pub use point::{FloatEval, PointOp, eval_float as float_view};

macro_rules! op_names {
    ($($variant:ident = $name:literal [$($key:literal),*];)*) => {
        /// The name of a claim operation, with the input keys it reads (besides [`CLAIM_KEYS`]):
        /// the one table of names and keys.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum OpName {
            $(
                #[doc = concat!("`", $name, "`")]
                $variant,
            )*
        }

        impl OpName {
            /// Every operation, in the order of the module's table.
            pub const ALL: &'static [OpName] = &[$(OpName::$variant),*];

            /// The name a claim file writes (`op = "…"`).
            pub fn name(self) -> &'static str {
                match self {
                    $(OpName::$variant => $name,)*
                }
            }

            /// The input keys of the operation (besides [`CLAIM_KEYS`]).
            pub fn keys(self) -> &'static [&'static str] {
                match self {
                    $(OpName::$variant => &[$($key),*],)*
                }
            }

            /// The operation named `name`, if any.
            pub fn from_name(name: &str) -> Option<Self> {
                match name {
                    $($name => Some(OpName::$variant),)*
                    _ => None,
                }
            }
        }
    };
}

op_names! {
    Eval = "eval" ["patch", "at", "cartesian", "algorithm"];
    Symbolic = "symbolic" ["patch", "variables", "names", "component"];
    Basis = "basis" ["degree", "simplex", "names", "at", "variables"];
    BasisSum = "basis_sum" ["degree", "simplex", "names", "at", "variables"];
    Blossom = "blossom" ["patch", "args"];
    Subpatch = "subpatch" ["patch", "vertices"];
    Subdivide = "subdivide" ["patch", "at", "midpoints"];
    Halve = "halve" ["patch", "edge", "method"];
    Elevate = "elevate" ["patch", "by"];
    Matrix = "matrix" ["kind", "degree", "simplex", "edge", "piece", "vertices"];
    Barycentric = "barycentric" ["domain", "point"];
    Direction = "direction" ["domain", "vector"];
    Derivative = "derivative" ["patch", "at", "cartesian", "dirs", "vectors"];
    Tangent = "tangent" ["patch", "at", "cartesian", "part"];
    EdgeCurve = "edge_curve" ["patch", "from", "to"];
    Join = "join" ["patches", "part"];
    Implicit = "implicit" ["patch", "equation", "coordinates", "names"];
    Wachspress = "wachspress" ["patch", "cartesian"];
    Abscissae = "abscissae" ["patch"];
    Ordinates = "ordinates" ["domain", "degree", "function", "names"];
    Graph = "graph" ["patch"];
    Intersect = "intersect" ["patches"];
    Locate = "locate" ["patch", "point", "anywhere"];
    Ray = "ray" ["patch", "origin", "direction", "height"];
    Lookup = "lookup" ["mesh", "at", "triangle"];
}

/// Every operation name, for messages.
pub fn op_names() -> Vec<&'static str> {
    OpName::ALL.iter().map(|o| o.name()).collect()
}

/// A claim's operation with its parsed, typed inputs. Patches are borrowed from the claim file
/// ([`Cow::Borrowed`]) until [`ClaimOp::seen`] rounds them ([`Cow::Owned`]).
#[derive(Clone, Debug)]
pub enum ClaimOp<'a> {
    /// `eval`, `derivative`, `tangent`, `wachspress`, `barycentric`, `direction`.
    Point(PointOp<'a>),
    /// `symbolic`, `basis`, `basis_sum`, `implicit`, `abscissae`, `ordinates`, `graph`.
    Form(Form<'a>),
    /// `blossom`, `subpatch`, `subdivide`, `halve`, `elevate`, `matrix`, `edge_curve`.
    Construction(Construction<'a>),
    /// `join`.
    Join(JoinOp<'a>),
    /// `intersect`, `locate`, `ray` (judged by [`inverse::judge`]).
    Inverse(InverseOp<'a>),
    /// `lookup` (judged by [`lookup::judge`]).
    Lookup(LookupOp),
}

impl<'a> ClaimOp<'a> {
    /// Parse a claim's operation and inputs (unknown operation or key, missing or malformed
    /// input, sizes above the limits: a located error). Nothing is computed.
    pub fn parse(inputs: &Inputs<'a>) -> Result<Self, InputError> {
        let claim = inputs.claim;
        let name = OpName::from_name(&claim.op).ok_or_else(|| {
            let node = inputs.get("op").unwrap_or(&claim.node);
            inputs.file.doc.error(
                node,
                &format!("{}.op", claim.id),
                ClaimProblem::UnknownOp {
                    op: claim.op.clone(),
                    known: op_names(),
                },
            )
        })?;
        let allowed: Vec<&str> = CLAIM_KEYS.iter().chain(name.keys()).copied().collect();
        inputs
            .file
            .doc
            .check_keys(&claim.node, inputs.table, &allowed, &claim.id)?;
        use OpName as N;
        Ok(match name {
            N::Eval
            | N::Derivative
            | N::Tangent
            | N::Wachspress
            | N::Barycentric
            | N::Direction => ClaimOp::Point(PointOp::parse(inputs, name)?),
            N::Symbolic
            | N::Basis
            | N::BasisSum
            | N::Implicit
            | N::Abscissae
            | N::Ordinates
            | N::Graph => ClaimOp::Form(Form::parse(inputs, name)?),
            N::Blossom
            | N::Subpatch
            | N::Subdivide
            | N::Halve
            | N::Elevate
            | N::Matrix
            | N::EdgeCurve => ClaimOp::Construction(Construction::parse(inputs, name)?),
            N::Join => ClaimOp::Join(JoinOp::parse(inputs)?),
            N::Intersect | N::Locate | N::Ray => ClaimOp::Inverse(InverseOp::parse(inputs, name)?),
            N::Lookup => ClaimOp::Lookup(LookupOp::parse(inputs)?),
        })
    }

    /// The same operation on the inputs as the float code saw them: every patch and numeric
    /// input rounded to `p` (module doc, **Precision**). An error names the input that
    /// overflows `p` or that rounding makes invalid.
    pub fn seen(
        &self,
        inputs: &Inputs<'_>,
        p: crate::float::Precision,
    ) -> Result<Self, InputError> {
        Ok(match self {
            ClaimOp::Point(o) => ClaimOp::Point(o.seen(inputs, p)?),
            ClaimOp::Form(o) => ClaimOp::Form(o.seen(inputs, p)?),
            ClaimOp::Construction(o) => ClaimOp::Construction(o.seen(inputs, p)?),
            ClaimOp::Join(o) => ClaimOp::Join(o.seen(inputs, p)?),
            ClaimOp::Inverse(o) => ClaimOp::Inverse(o.seen(inputs, p)?),
            ClaimOp::Lookup(o) => ClaimOp::Lookup(o.seen(inputs, p)?),
        })
    }

    /// The exact value of the operation.
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        match self {
            ClaimOp::Point(o) => o.compute(inputs),
            ClaimOp::Form(o) => o.compute(inputs),
            ClaimOp::Construction(o) => o.compute(inputs),
            ClaimOp::Join(o) => o.compute(inputs),
            ClaimOp::Inverse(o) => o.compute(inputs),
            ClaimOp::Lookup(o) => o.compute(inputs),
        }
    }

    /// Is this an `eval` claim (judged by its float view with `precision`)?
    pub fn is_eval(&self) -> bool {
        matches!(self, ClaimOp::Point(PointOp::Eval { .. }))
    }
}

/// The exact value of a claim's operation: parsed, then (with `precision`, for every operation
/// but `eval`, whose float view is [`float_view`]) rounded as the code saw it, then
/// computed.
pub fn exact_value(file: &ClaimFile, claim: &Claim) -> Result<Value, InputError> {
    let inputs = Inputs::new(file, claim)?;
    let op = ClaimOp::parse(&inputs)?;
    let (_, precision) = file.tolerance_of(claim)?;
    match precision {
        Some(p) if !op.is_eval() => op.seen(&inputs, p)?.compute(&inputs),
        _ => op.compute(&inputs),
    }
}

/// The float view of an `eval` claim in precision `p` (an error for another operation).
pub fn eval_float(
    file: &ClaimFile,
    claim: &Claim,
    p: crate::float::Precision,
) -> Result<FloatEval, InputError> {
    let inputs = Inputs::new(file, claim)?;
    match ClaimOp::parse(&inputs)? {
        ClaimOp::Point(o @ PointOp::Eval { .. }) => point::eval_float(&inputs, &o, p),
        _ => Err(inputs.error("op", ClaimProblem::FloatViewEvalOnly)),
    }
}

/// Control points keyed like a patch file: `{"2,0,0": [...], ...}`.
pub fn net_value(net: &crate::patch::ControlNet<BigRational>) -> Value {
    Value::Map(
        net.entries()
            .map(|(alpha, p)| (index_key(alpha), Value::numbers(p)))
            .collect(),
    )
}

/// Values keyed by the multi-indices of a simplex, in canonical order.
fn keyed(simplex: &crate::simplex::Simplex, values: impl Iterator<Item = Value>) -> Value {
    Value::Map(simplex.iter().map(index_key).zip(values).collect())
}

/// A borrowed patch, until [`ClaimOp::seen`] replaces it by a rounded one.
pub type PatchRef<'a, P> = Cow<'a, P>;
