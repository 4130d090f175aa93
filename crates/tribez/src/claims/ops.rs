//! The operations a claim can name, each computing its exact value from the claim's inputs.
//!
//! | op | inputs | value |
//! |---|---|---|
//! | `eval` | `at` (barycentric, summing to 1; with `precision` any sum: the homogeneous form) or `cartesian`; optional `algorithm` (`casteljau`, `bernstein`: for `tolerance = "bound"`) | the point |
//! | `symbolic` | `variables` = `"barycentric"` (default) or `"cartesian"`; optional `names`, `component` (0-based) | one polynomial per coordinate (or the one selected) |
//! | `basis` | `degree`, optional `simplex` (m, default 2), `names`, `at` | the Bernstein polynomials (or their values at `at`) keyed by multi-index |
//! | `basis_sum` | as `basis`, optional `variables = "cartesian"` | `Σ_α B^n_α` as a polynomial (or value) |
//! | `blossom` | `args`: exactly n barycentric points | the point `b[args]` (rational patches: `X[args]/W[args]`, the homogeneous net's blossom projected) |
//! | `subpatch` | `vertices`: m+1 barycentric points | control points keyed like a patch file (`"2,0,0" = [...]`) |
//! | `subdivide` | `at` (a barycentric point) or `midpoints = true` | a list of such tables, one per piece |
//! | `halve` | `edge = [I, J]`; optional `method` = `"blossom"` (default), `"add-and-halve"`, `"add-and-halve-bottom-first"` | the two halves, a list of tables |
//! | `elevate` | optional `by` (default 1) | control points keyed like a patch file |
//! | `matrix` | `kind` = `"halve"` (`degree`, optional `simplex`, `edge`, `piece`) or `"subpatch"` (`degree`, `vertices`) | the rows, a list of lists |
//! | `derivative` | `at` or `cartesian`; `dirs` (barycentric directions) and/or `vectors` (Cartesian) | the derivative of order `len(dirs) + len(vectors)` |
//! | `tangent` | `at` or `cartesian`; optional `part` | `{point, intermediate, partials, regular, normal, spans_tangent_plane}` (or that part) |
//! | `edge_curve` | `from`, `to` (corners, 1-based) | control points of `t ↦ p((1−t) e_from + t e_to)` |
//! | `join` | `patches = ["a", "b"]` (names under `[patches]`); optional `part` | `{c0, c1, g1, coplanarity, max_smoothness, mu, violations, g1_determinant}` (or that part) |
//! | `barycentric` | `domain` (m+1 vertices), `point` (Cartesian) | the barycentric coordinates (Cramer) |
//! | `direction` | `domain`, `vector` (Cartesian) | the directional coordinates (they sum to 0) |
//! | `implicit` | `equation` (a polynomial in the coordinates), optional `coordinates` (their names, default `x, y, z`), `names` | the residual `W^k F(X/W)` as a polynomial in the patch's variables (barycentric; `x, y` for an S-patch); `"0"` proves the whole patch lies on `F = 0` |
//! | `wachspress` | `cartesian` (a point of an S-patch's polygon) | `{ A = [A_j], C = [C_i], lambda = [λ_i] }` (docs/theory.md §12) |
//! | `abscissae` | (a functional or Bézier patch) | the Bézier abscissae `ξ_α` keyed by multi-index |
//! | `ordinates` | `domain`, `degree`, `function` (polynomial in `x, y`, or `names`) | the control ordinates `b_α` keyed by multi-index |
//! | `graph` | (a functional patch) | the control points `(ξ_α, b_α)` of its graph, keyed by multi-index |
//!
//! `eval` also takes rational patches (`at` or `cartesian`) and S-patches (`cartesian` only).
//!
//! Each op lists the keys it reads; any other key in a claim is an error (a typo must not be
//! silently ignored).

use num_rational::BigRational;
use num_traits::Zero;

use super::value::Value;
use super::{CLAIM_KEYS, Claim, ClaimFile};
use crate::any_patch::AnyPatch;
use crate::bernstein;
use crate::exact::{Algorithm, ExactEvaluator};
use crate::io::InputError;
use crate::io::patch_file::{MAX_CONTROL_POINTS, MAX_DEGREE, index_key};
use crate::io::tree::{Document, Node, Value as NodeValue};
use crate::simplex::{Simplex, multinomial};
use crate::symbolic::{
    Polynomial, barycentric_form, barycentric_names, cartesian_form, cartesian_names,
};

/// Every operation name, for messages.
pub const OPS: &[&str] = &[
    "eval",
    "symbolic",
    "basis",
    "basis_sum",
    "blossom",
    "subpatch",
    "subdivide",
    "halve",
    "elevate",
    "matrix",
    "barycentric",
    "direction",
    "derivative",
    "tangent",
    "edge_curve",
    "join",
    "implicit",
    "wachspress",
    "abscissae",
    "ordinates",
    "graph",
];

/// The input keys of an operation (besides [`CLAIM_KEYS`]).
fn op_keys(op: &str) -> Option<&'static [&'static str]> {
    Some(match op {
        "eval" => &["patch", "at", "cartesian", "algorithm"],
        "symbolic" => &["patch", "variables", "names", "component"],
        "barycentric" => &["domain", "point"],
        "direction" => &["domain", "vector"],
        "basis" | "basis_sum" => &["degree", "simplex", "names", "at", "variables"],
        "blossom" => &["patch", "args"],
        "subpatch" => &["patch", "vertices"],
        "subdivide" => &["patch", "at", "midpoints"],
        "halve" => &["patch", "edge", "method"],
        "elevate" => &["patch", "by"],
        "matrix" => &["kind", "degree", "simplex", "edge", "piece", "vertices"],
        "derivative" => &["patch", "at", "cartesian", "dirs", "vectors"],
        "tangent" => &["patch", "at", "cartesian", "part"],
        "edge_curve" => &["patch", "from", "to"],
        "join" => &["patches", "part"],
        "implicit" => &["patch", "equation", "coordinates", "names"],
        "wachspress" => &["patch", "cartesian"],
        "abscissae" | "graph" => &["patch"],
        "ordinates" => &["domain", "degree", "function", "names"],
        _ => return None,
    })
}

/// Typed access to one claim's inputs.
pub struct Inputs<'a> {
    /// The claim file.
    pub file: &'a ClaimFile,
    /// The claim.
    pub claim: &'a Claim,
    table: &'a [(String, Node)],
}

impl<'a> Inputs<'a> {
    fn key(&self, name: &str) -> String {
        format!("{}.{name}", self.claim.id)
    }

    /// The node of input `name`, if present.
    pub fn get(&self, name: &str) -> Option<&'a Node> {
        Document::get(self.table, name)
    }

    /// An error at this claim (or at its input `name`).
    pub fn error(&self, name: &str, message: impl Into<String>) -> InputError {
        let node = self.get(name).unwrap_or(&self.claim.node);
        self.file.doc.error(node, &self.key(name), message)
    }

    /// A required list of rationals.
    pub fn rationals(&self, name: &str) -> Result<Vec<BigRational>, InputError> {
        let node = self
            .get(name)
            .ok_or_else(|| self.error(name, format!("missing input `{name}`")))?;
        self.file.doc.rationals(node, &self.key(name))
    }

    /// An optional list of rationals.
    pub fn opt_rationals(&self, name: &str) -> Result<Option<Vec<BigRational>>, InputError> {
        self.get(name).map(|_| self.rationals(name)).transpose()
    }

    /// An optional string.
    pub fn opt_string(&self, name: &str) -> Result<Option<String>, InputError> {
        self.get(name)
            .map(|n| self.file.doc.string(n, &self.key(name)).map(str::to_string))
            .transpose()
    }

    /// An optional non-negative integer.
    pub fn opt_usize(&self, name: &str) -> Result<Option<usize>, InputError> {
        self.get(name)
            .map(|n| self.file.doc.usize(n, &self.key(name)))
            .transpose()
    }

    /// An optional list of strings.
    pub fn opt_strings(&self, name: &str) -> Result<Option<Vec<String>>, InputError> {
        let Some(node) = self.get(name) else {
            return Ok(None);
        };
        let items = self.file.doc.array(node, &self.key(name))?;
        items
            .iter()
            .map(|n| self.file.doc.string(n, &self.key(name)).map(str::to_string))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// The claim's patch.
    pub fn patch(&self) -> Result<&'a crate::patch::BezierPatch, InputError> {
        self.file.patch_for(self.claim)
    }

    /// A barycentric point from `at` (checked to sum to one, except for float claims: what a
    /// float program uses need not), or a Cartesian one from `cartesian`.
    pub fn point(&self, patch: &crate::patch::BezierPatch) -> Result<Vec<BigRational>, InputError> {
        let m = patch.net.m();
        match (self.opt_rationals("at")?, self.opt_rationals("cartesian")?) {
            (Some(at), None) if self.get("precision").is_some() => {
                if at.len() != m + 1 {
                    return Err(self.error(
                        "at",
                        format!("{} coordinates, expected {}", at.len(), m + 1),
                    ));
                }
                Ok(at)
            }
            (Some(at), None) => {
                crate::domain::check_barycentric(&at, m, "point `at`")
                    .map_err(|e| self.error("at", e.to_string()))?;
                Ok(at)
            }
            (None, Some(x)) => patch
                .domain_or_reference()
                .barycentric(&x)
                .map_err(|e| self.error("cartesian", e.to_string())),
            _ => Err(self.error(
                "at",
                "give exactly one of `at` (barycentric) or `cartesian`",
            )),
        }
    }

    /// Variable names: `names` if given (checked against the count), else `default`.
    pub fn names(&self, default: Vec<String>) -> Result<Vec<String>, InputError> {
        match self.opt_strings("names")? {
            Some(n) if n.len() != default.len() => Err(self.error(
                "names",
                format!(
                    "{} names given, {} variables needed",
                    n.len(),
                    default.len()
                ),
            )),
            Some(n) => Ok(n),
            None => Ok(default),
        }
    }
}

/// The exact value of a claim's operation.
pub fn exact_value(file: &ClaimFile, claim: &Claim) -> Result<Value, InputError> {
    let table = file.doc.table(&claim.node, &claim.id)?;
    let keys = op_keys(&claim.op).ok_or_else(|| {
        let node = Document::get(table, "op").unwrap_or(&claim.node);
        file.doc.error(
            node,
            &format!("{}.op", claim.id),
            format!(
                "unknown operation `{}` (known: {})",
                claim.op,
                OPS.join(", ")
            ),
        )
    })?;
    let allowed: Vec<&str> = CLAIM_KEYS.iter().chain(keys).copied().collect();
    file.doc
        .check_keys(&claim.node, table, &allowed, &claim.id)?;
    let inputs = Inputs { file, claim, table };
    match claim.op.as_str() {
        "eval"
            if !matches!(
                file.any_patch_for(claim)?,
                AnyPatch::Bezier(_) | AnyPatch::Functional(_)
            ) =>
        {
            beyond::eval(&inputs)
        }
        "implicit" => beyond::implicit(&inputs),
        "wachspress" => beyond::wachspress(&inputs),
        "abscissae" => beyond::abscissae(&inputs),
        "ordinates" => beyond::ordinates(&inputs),
        "graph" => beyond::graph(&inputs),
        "eval" => {
            let patch = inputs.patch()?;
            let at = inputs.point(patch)?;
            Ok(Value::numbers(
                &ExactEvaluator::new(&patch.net).evaluate_fast(&at),
            ))
        }
        "symbolic" => {
            let patch = inputs.patch()?;
            let m = patch.net.m();
            let (names, polys) = match inputs.opt_string("variables")?.as_deref() {
                None | Some("barycentric") => (
                    inputs.names(barycentric_names(m))?,
                    barycentric_form(&patch.net),
                ),
                Some("cartesian") => (
                    inputs.names(cartesian_names(m))?,
                    cartesian_form(&patch.net, &patch.domain_or_reference()),
                ),
                Some(other) => {
                    return Err(inputs.error(
                        "variables",
                        format!("`{other}`: expected \"barycentric\" or \"cartesian\""),
                    ));
                }
            };
            match inputs.opt_usize("component")? {
                None => Ok(Value::List(
                    polys
                        .into_iter()
                        .map(|p| Value::Poly(p, names.clone()))
                        .collect(),
                )),
                Some(c) => {
                    let p = polys.get(c).cloned().ok_or_else(|| inputs.error("component", format!("component {c} does not exist: the points have {} coordinates (0-based)", polys.len())))?;
                    Ok(Value::Poly(p, names))
                }
            }
        }
        "barycentric" | "direction" => {
            let node = inputs
                .get("domain")
                .ok_or_else(|| inputs.error("domain", "missing input `domain`"))?;
            let rows = file.doc.array(node, &inputs.key("domain"))?;
            let domain = crate::io::patch_file::domain(
                &file.doc,
                node,
                rows.len().saturating_sub(1),
                &inputs.key("domain"),
            )?;
            let (name, result) = if claim.op == "barycentric" {
                ("point", domain.barycentric(&inputs.rationals("point")?))
            } else {
                ("vector", domain.direction(&inputs.rationals("vector")?))
            };
            Ok(Value::numbers(
                &result.map_err(|e| inputs.error(name, e.to_string()))?,
            ))
        }
        "basis" | "basis_sum" => basis(&inputs, claim.op == "basis_sum"),
        "blossom" => blossom(&inputs),
        "subpatch" | "subdivide" | "halve" | "elevate" | "matrix" => {
            construction(&inputs, &claim.op)
        }
        "derivative" => derivative(&inputs),
        "tangent" => tangent(&inputs),
        "edge_curve" => edge_curve(&inputs),
        "join" => join(&inputs),
        _ => unreachable!("op_keys covers every operation"),
    }
}

/// A float evaluation claim's exact values both ways, its condition numbers and bounds.
pub struct FloatEval {
    /// The exact values of the inputs as the code saw them (rounded to the precision).
    pub seen_inputs: Vec<BigRational>,
    /// `P` at those inputs, with the control points rounded to the precision too (homogeneous form).
    pub exact_seen: Vec<BigRational>,
    /// `P` at the intended inputs (the exact text, the exact patch).
    pub exact_intended: Vec<BigRational>,
    /// `Σ|c_i| B_i(|λ|)` per coordinate, at the inputs as seen.
    pub condition: Vec<BigRational>,
    /// The a-priori bound of the claim's `algorithm` per coordinate.
    pub bound: Vec<Option<BigRational>>,
}

/// The float view of an `eval` claim in precision `p`. A Cartesian point is rounded to `p` and
/// converted to barycentric coordinates exactly.
pub fn eval_float(
    file: &ClaimFile,
    claim: &Claim,
    p: crate::float::Precision,
) -> Result<FloatEval, InputError> {
    let table = file.doc.table(&claim.node, &claim.id)?;
    let inputs = Inputs { file, claim, table };
    match file.any_patch_for(claim)? {
        AnyPatch::Rational(r) => return beyond::eval_float_rational(&inputs, r, p),
        AnyPatch::SPatch(s) => return beyond::eval_float_spatch(&inputs, s, p),
        AnyPatch::Bezier(_) | AnyPatch::Functional(_) => {}
    }
    let patch = inputs.patch()?;
    let algorithm = match inputs.opt_string("algorithm")?.as_deref() {
        None | Some("casteljau") => Algorithm::Casteljau,
        Some("bernstein") => Algorithm::Bernstein,
        Some(other) => {
            return Err(inputs.error(
                "algorithm",
                format!("unknown algorithm `{other}` (known: casteljau, bernstein)"),
            ));
        }
    };
    let round = |q: &BigRational| crate::certify::measures::as_float(q, p);
    let overflow = |name: &str| inputs.error(name, format!("an input overflows {}", p.name()));
    let intended = inputs.point(patch)?;
    let seen_inputs: Vec<BigRational> = match inputs.opt_rationals("cartesian")? {
        Some(x) => {
            let xr: Vec<BigRational> = x
                .iter()
                .map(round)
                .collect::<Option<_>>()
                .ok_or_else(|| overflow("cartesian"))?;
            patch
                .domain_or_reference()
                .barycentric(&xr)
                .map_err(|e| inputs.error("cartesian", e.to_string()))?
        }
        None => intended
            .iter()
            .map(round)
            .collect::<Option<_>>()
            .ok_or_else(|| overflow("at"))?,
    };
    if patch.net.coords().iter().any(|q| round(q).is_none()) {
        return Err(inputs.error("patch", format!("a control point overflows {}", p.name())));
    }
    let seen_net = patch.net.map(|q| round(q).unwrap_or_default());
    let exact_seen = ExactEvaluator::new(&seen_net).evaluate(&seen_inputs, Algorithm::Casteljau);
    let exact_intended = ExactEvaluator::new(&patch.net).evaluate(&intended, Algorithm::Casteljau);
    let condition = crate::certify::bound::condition(&seen_net, &seen_inputs);
    let (m, n) = (patch.net.m(), patch.net.degree());
    let bound = condition
        .iter()
        .map(|s| crate::certify::bound::a_priori(algorithm, p, m, n, s, &seen_inputs))
        .collect();
    Ok(FloatEval {
        seen_inputs,
        exact_seen,
        exact_intended,
        condition,
        bound,
    })
}

/// Control points keyed like a patch file: `{"2,0,0": [...], ...}`.
pub fn net_value(net: &crate::patch::ControlNet<BigRational>) -> Value {
    Value::Map(
        net.entries()
            .map(|(alpha, p)| (index_key(alpha), Value::numbers(p)))
            .collect(),
    )
}

impl Inputs<'_> {
    /// A required list of barycentric points (each with `m + 1` coordinates summing to one).
    fn bary_points(&self, name: &str, m: usize) -> Result<Vec<Vec<BigRational>>, InputError> {
        let node = self
            .get(name)
            .ok_or_else(|| self.error(name, format!("missing input `{name}`")))?;
        let items = self.file.doc.array(node, &self.key(name))?;
        items
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let key = format!("{}[{i}]", self.key(name));
                let p = self.file.doc.rationals(n, &key)?;
                crate::domain::check_barycentric(&p, m, "point")
                    .map_err(|e| self.file.doc.error(n, &key, e.to_string()))?;
                Ok(p)
            })
            .collect()
    }

    /// An edge `[I, J]` (corners numbered from 1), returned 0-based.
    fn edge(&self, m: usize) -> Result<(usize, usize), InputError> {
        let node = self.get("edge").ok_or_else(|| {
            self.error(
                "edge",
                "missing input `edge` (two corner numbers, like [1, 2])",
            )
        })?;
        let items = self.file.doc.array(node, &self.key("edge"))?;
        let nums = items
            .iter()
            .map(|n| self.file.doc.usize(n, &self.key("edge")))
            .collect::<Result<Vec<_>, _>>()?;
        match nums.as_slice() {
            [i, j] => crate::subdivide::check_edge(m, *i, *j)
                .map_err(|e| self.error("edge", e.to_string())),
            _ => Err(self.error("edge", "an edge is two corner numbers, like [1, 2]")),
        }
    }
}

/// `blossom` of a polynomial patch, or of a rational one: `X[args] / W[args]`, the blossom of the
/// homogeneous net projected (an error where `W[args]` is 0).
fn blossom(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let AnyPatch::Rational(r) = inputs.file.any_patch_for(inputs.claim)? else {
        return construction(inputs, "blossom");
    };
    let args = inputs.bary_points("args", r.patch.net.m())?;
    r.blossom(&args)
        .map(|v| Value::numbers(&v))
        .map_err(|e| inputs.error("args", e.to_string()))
}

/// The construction operations: blossom, subpatch, subdivide, halve, elevate, matrix.
fn construction(inputs: &Inputs<'_>, op: &str) -> Result<Value, InputError> {
    use crate::subdivide::{HalvingOrder, add_and_halve, halve, midpoint_split, split_at_pieces};
    if op == "matrix" {
        return matrix(inputs);
    }
    let patch = inputs.patch()?;
    let net = &patch.net;
    let m = net.m();
    let pieces = |ps: Vec<crate::subdivide::Piece<BigRational>>| {
        Value::List(ps.iter().map(|p| net_value(&p.net)).collect())
    };
    Ok(match op {
        "blossom" => {
            let args = inputs.bary_points("args", m)?;
            Value::numbers(
                &crate::blossom::blossom(net, &args)
                    .map_err(|e| inputs.error("args", e.to_string()))?,
            )
        }
        "subpatch" => {
            let f = inputs.bary_points("vertices", m)?;
            net_value(
                &crate::blossom::subpatch(net, &f)
                    .map_err(|e| inputs.error("vertices", e.to_string()))?,
            )
        }
        "subdivide" => {
            let midpoints = match inputs.get("midpoints") {
                None => false,
                Some(n) => match &n.value {
                    NodeValue::Bool(b) => *b,
                    _ => return Err(inputs.error("midpoints", "expected true or false")),
                },
            };
            match (inputs.opt_rationals("at")?, midpoints) {
                (Some(t), false) => {
                    crate::domain::check_barycentric(&t, m, "point `at`")
                        .map_err(|e| inputs.error("at", e.to_string()))?;
                    pieces(split_at_pieces(net, &t).map_err(|e| inputs.error("at", e.to_string()))?)
                }
                (None, true) => pieces(
                    midpoint_split(net).map_err(|e| inputs.error("midpoints", e.to_string()))?,
                ),
                _ => {
                    return Err(inputs.error(
                        "at",
                        "give exactly one of `at` (a barycentric point) or `midpoints = true`",
                    ));
                }
            }
        }
        "halve" => {
            let (i, j) = inputs.edge(m)?;
            match inputs.opt_string("method")?.as_deref() {
                None | Some("blossom") => pieces(halve(net, i, j).to_vec()),
                Some(method @ ("add-and-halve" | "add-and-halve-bottom-first")) => {
                    let order = if method == "add-and-halve" { HalvingOrder::TopDown } else { HalvingOrder::BottomFirst };
                    Value::List(vec![net_value(&add_and_halve(net, i, j, order)), net_value(&add_and_halve(net, j, i, order))])
                }
                Some(other) => return Err(inputs.error("method", format!("`{other}`: expected \"blossom\", \"add-and-halve\" or \"add-and-halve-bottom-first\""))),
            }
        }
        "elevate" => {
            let r = inputs.opt_usize("by")?.unwrap_or(1);
            let to = net.degree().checked_add(r).filter(|_| r > 0);
            let Some(to) = to.filter(|&t| t <= MAX_DEGREE) else {
                return Err(inputs.error(
                    "by",
                    format!(
                        "elevate by 1 to {} (the degree is capped at {MAX_DEGREE})",
                        MAX_DEGREE - net.degree()
                    ),
                ));
            };
            check_count(inputs, "by", m, to)?;
            net_value(&crate::elevate::elevate(net, r))
        }
        _ => unreachable!("construction ops only"),
    })
}

/// An error unless degree `n` on the `m`-simplex has at most
/// [`crate::io::patch_file::MAX_CONTROL_POINTS`] control points (checked before allocating).
fn check_count(inputs: &Inputs<'_>, key: &str, m: usize, n: usize) -> Result<(), InputError> {
    let total = crate::simplex::binomial((n + m) as u64, m as u64);
    if total > MAX_CONTROL_POINTS as u128 {
        return Err(inputs.error(
            key,
            format!("degree {n} on a {m}-simplex has {total} control points, above the limit of {MAX_CONTROL_POINTS}"),
        ));
    }
    Ok(())
}

/// The matrix of a halving or a subpatch, as a list of rows.
fn matrix(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let n = inputs
        .opt_usize("degree")?
        .ok_or_else(|| inputs.error("degree", "missing input `degree`"))?;
    let (m, f) = match inputs.opt_string("kind")?.as_deref() {
        Some("halve") => {
            let m = inputs.opt_usize("simplex")?.unwrap_or(2);
            if !(1..=crate::io::patch_file::MAX_SIMPLEX_DIMENSION).contains(&m) {
                return Err(inputs.error("simplex", "the simplex dimension must be 1 to 16"));
            }
            let (i, j) = if inputs.get("edge").is_some() {
                inputs.edge(m)?
            } else {
                (0, 1)
            };
            let [a, b] = crate::subdivide::halve_domains(m, i, j);
            match inputs.opt_usize("piece")?.unwrap_or(1) {
                1 => (m, a),
                2 => (m, b),
                _ => return Err(inputs.error("piece", "the piece is 1 or 2")),
            }
        }
        Some("subpatch") => {
            let node = inputs
                .get("vertices")
                .ok_or_else(|| inputs.error("vertices", "missing input `vertices`"))?;
            let count = inputs.file.doc.array(node, &inputs.key("vertices"))?.len();
            if count < 2 {
                return Err(inputs.error("vertices", "give m+1 vertices (3 for a triangle)"));
            }
            (count - 1, inputs.bary_points("vertices", count - 1)?)
        }
        _ => return Err(inputs.error("kind", "`kind` must be \"halve\" or \"subpatch\"")),
    };
    if n > MAX_DEGREE
        || crate::simplex::binomial((n + m) as u64, m as u64)
            > crate::blossom::MAX_MATRIX_ROWS as u128
    {
        return Err(inputs.error(
            "degree",
            format!(
                "the matrix would be too large (at most {} rows, the control points of the degree)",
                crate::blossom::MAX_MATRIX_ROWS
            ),
        ));
    }
    let rows = crate::blossom::subpatch_matrix(m, n, &f)
        .map_err(|e| inputs.error("vertices", e.to_string()))?;
    Ok(Value::List(
        rows.iter().map(|r| Value::numbers(r)).collect(),
    ))
}

/// A list of lists of rationals (`dirs = [["1", "0", "-1"], …]`), possibly absent.
fn opt_rational_rows(inputs: &Inputs<'_>, name: &str) -> Result<Vec<Vec<BigRational>>, InputError> {
    let Some(node) = inputs.get(name) else {
        return Ok(Vec::new());
    };
    let key = format!("{}.{name}", inputs.claim.id);
    let items = inputs.file.doc.array(node, &key)?;
    items
        .iter()
        .enumerate()
        .map(|(i, n)| inputs.file.doc.rationals(n, &format!("{key}[{i}]")))
        .collect()
}

fn derivative(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let any = inputs.file.any_patch_for(inputs.claim)?;
    let rational = match any {
        AnyPatch::Rational(r) => Some(r),
        _ => None,
    };
    let patch = match rational {
        Some(r) => &r.patch,
        None => inputs.patch()?,
    };
    let at = inputs.point(patch)?;
    let m = patch.net.m();
    let mut dirs = Vec::new();
    for (i, d) in opt_rational_rows(inputs, "dirs")?.into_iter().enumerate() {
        crate::domain::check_direction(&d, m, "direction")
            .map_err(|e| inputs.error("dirs", format!("direction {}: {e}", i + 1)))?;
        dirs.push(d);
    }
    let domain = patch.domain_or_reference();
    for (i, v) in opt_rational_rows(inputs, "vectors")?
        .into_iter()
        .enumerate()
    {
        dirs.push(
            domain
                .direction(&v)
                .map_err(|e| inputs.error("vectors", format!("vector {}: {e}", i + 1)))?,
        );
    }
    if dirs.is_empty() {
        return Err(inputs.error(
            "dirs",
            "give at least one direction in `dirs` (barycentric) or `vectors` (Cartesian)",
        ));
    }
    let refs: Vec<&[BigRational]> = dirs.iter().map(Vec::as_slice).collect();
    if let Some(r) = rational {
        // rational patches: any order, by Leibniz's rule on the homogeneous net
        let key = if inputs.get("at").is_some() {
            "at"
        } else {
            "cartesian"
        };
        return r
            .derivative_of_order(&at, &refs)
            .map(|v| Value::numbers(&v))
            .map_err(|e| inputs.error(key, e.to_string()));
    }
    crate::derivative::check_order(dirs.len(), patch.net.degree())
        .map_err(|e| inputs.error("dirs", e.to_string()))?;
    Ok(Value::numbers(&crate::derivative::directional_derivative(
        &patch.net, &refs, &at,
    )))
}

/// Select `part` of a map value, if the claim names one.
fn select_part(inputs: &Inputs<'_>, value: Value) -> Result<Value, InputError> {
    let Some(part) = inputs.opt_string("part")? else {
        return Ok(value);
    };
    let Value::Map(kv) = value else {
        unreachable!("parts are of maps")
    };
    let known: Vec<String> = kv.iter().map(|(k, _)| k.clone()).collect();
    kv.into_iter()
        .find(|(k, _)| *k == part)
        .map(|(_, v)| v)
        .ok_or_else(|| {
            inputs.error(
                "part",
                format!(
                    "`{part}` is not available here (available: {})",
                    known.join(", ")
                ),
            )
        })
}

fn tangent(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let f = match inputs.file.any_patch_for(inputs.claim)? {
        AnyPatch::Rational(r) => {
            let at = inputs.point(&r.patch)?;
            r.tangent_frame(&r.patch.domain_or_reference(), &at)
        }
        _ => {
            let patch = inputs.patch()?;
            let at = inputs.point(patch)?;
            crate::derivative::tangent_frame(&patch.net, &patch.domain_or_reference(), &at)
        }
    }
    .map_err(|e| inputs.error("at", e.to_string()))?;
    let rows = |v: &[Vec<BigRational>]| Value::List(v.iter().map(|p| Value::numbers(p)).collect());
    let mut kv = vec![
        ("point".to_string(), Value::numbers(&f.point)),
        ("intermediate".to_string(), rows(&f.intermediate)),
        ("partials".to_string(), rows(&f.partials)),
        ("regular".to_string(), Value::Bool(f.regular)),
    ];
    if let Some(nrm) = &f.normal {
        kv.push(("normal".into(), Value::numbers(nrm)));
        // the plane through the intermediate points contains the point and has normal ∥ p_x × p_y
        let c = &f.intermediate;
        let d = |a: &[BigRational], b: &[BigRational]| {
            a.iter().zip(b).map(|(x, y)| x - y).collect::<Vec<_>>()
        };
        let plane = crate::derivative::cross(&d(&c[1], &c[0]), &d(&c[2], &c[0]));
        let parallel = crate::derivative::cross(&plane, nrm)
            .iter()
            .all(Zero::is_zero)
            && plane.iter().any(|x| !x.is_zero());
        let on: BigRational = d(&f.point, &c[0])
            .iter()
            .zip(&plane)
            .map(|(a, b)| a * b)
            .sum();
        kv.push((
            "spans_tangent_plane".into(),
            Value::Bool(parallel && on.is_zero()),
        ));
    }
    select_part(inputs, Value::Map(kv))
}

fn edge_curve(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let patch = inputs.patch()?;
    let m = patch.net.m();
    let corner = |name: &str| -> Result<usize, InputError> {
        let k = inputs.opt_usize(name)?.ok_or_else(|| {
            inputs.error(
                name,
                format!("missing input `{name}` (a corner, 1 to {})", m + 1),
            )
        })?;
        if !(1..=m + 1).contains(&k) {
            return Err(inputs.error(
                name,
                format!(
                    "corner {k} does not exist: corners are numbered 1 to {}",
                    m + 1
                ),
            ));
        }
        Ok(k - 1)
    };
    let (from, to) = (corner("from")?, corner("to")?);
    if from == to {
        return Err(inputs.error("to", "`from` and `to` must be different corners"));
    }
    let face = patch.net.face(&[from, to]);
    Ok(Value::List(face.points().map(Value::numbers).collect()))
}

fn join(inputs: &Inputs<'_>) -> Result<Value, InputError> {
    let names = inputs.opt_strings("patches")?.ok_or_else(|| {
        inputs.error(
            "patches",
            "missing input `patches` (two names under [patches])",
        )
    })?;
    if names.len() != 2 {
        return Err(inputs.error(
            "patches",
            format!("a join needs two patches, {} named", names.len()),
        ));
    }
    let find = |name: &str| {
        inputs
            .file
            .patches
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p)
            .ok_or_else(|| {
                inputs.error(
                    "patches",
                    format!("no patch named `{name}` under [patches]"),
                )
            })
            .and_then(|p| {
                p.polynomial().ok_or_else(|| {
                    inputs.error(
                        "patches",
                        format!("`join` does not take a {} patch (`{name}`)", p.kind_name()),
                    )
                })
            })
    };
    let (a, b) = (find(&names[0])?, find(&names[1])?);
    let j = crate::join::analyse(a, b).map_err(|e| inputs.error("patches", e.to_string()))?;
    let mut kv = vec![
        ("c0".to_string(), Value::Bool(j.c0)),
        ("c1".to_string(), Value::Bool(j.c1)),
        (
            "max_smoothness".to_string(),
            Value::Integer(j.max_smoothness),
        ),
        ("mu".to_string(), Value::numbers(&j.mu)),
    ];
    if let Some(g) = j.g1 {
        kv.push(("g1".into(), Value::Bool(g)));
    }
    if let Some(c) = j.coplanarity {
        kv.push(("coplanarity".into(), Value::Bool(c)));
    }
    if j.g1_minors.len() == 1 {
        kv.push((
            "g1_determinant".into(),
            Value::Poly(j.g1_minors[0].clone(), vec!["t".into()]),
        ));
    }
    // row and coplanarity violations, keyed "C1 1,0,1" / "coplanarity 0,1,1"
    let mut viol = Vec::new();
    for v in &j.violations {
        match v {
            crate::join::Violation::Row {
                rho,
                index,
                difference,
                ..
            } => viol.push((
                format!("C{rho} {}", index_key(index)),
                Value::numbers(difference),
            )),
            crate::join::Violation::Coplanarity { index, volume, .. } => viol.push((
                format!("coplanarity {}", index_key(index)),
                Value::Number(volume.clone()),
            )),
            crate::join::Violation::G1 { .. } => {}
        }
    }
    kv.push(("violations".into(), Value::Map(viol)));
    select_part(inputs, Value::Map(kv))
}

/// The operations of issue 5 (rational patches, S-patches, functional patches).
mod beyond {
    use num_rational::BigRational;

    use super::{Inputs, MAX_DEGREE, Value};
    use crate::any_patch::AnyPatch;
    use crate::functional;
    use crate::io::InputError;
    use crate::io::patch_file::index_key;
    use crate::rational::homogenised_residual;
    use crate::symbolic::{Polynomial, barycentric_form, barycentric_names, cartesian_names};

    fn map(simplex: &crate::simplex::Simplex, values: impl Iterator<Item = Value>) -> Value {
        Value::Map(simplex.iter().map(index_key).zip(values).collect())
    }

    /// `eval` on a rational patch or an S-patch.
    pub fn eval(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        match inputs.file.any_patch_for(inputs.claim)? {
            AnyPatch::Rational(r) => {
                let at = inputs.point(&r.patch)?;
                let key = if inputs.get("at").is_some() {
                    "at"
                } else {
                    "cartesian"
                };
                r.evaluate(&at)
                    .map(|v| Value::numbers(&v))
                    .map_err(|e| inputs.error(key, e.to_string()))
            }
            AnyPatch::SPatch(s) => {
                if inputs.get("at").is_some() {
                    return Err(
                        inputs.error("at", "an S-patch takes Cartesian points: use `cartesian`")
                    );
                }
                let x = inputs.rationals("cartesian")?;
                s.evaluate(&x)
                    .map(|(_, v)| Value::numbers(&v))
                    .map_err(|e| inputs.error("cartesian", e.to_string()))
            }
            AnyPatch::Bezier(_) | AnyPatch::Functional(_) => {
                unreachable!("handled by the plain `eval`")
            }
        }
    }

    /// Float claims (`precision`) on rational patches and S-patches are judged against the exact
    /// value at the inputs as the code saw them (point, control points, weights, polygon rounded
    /// to the precision; for a rational patch the homogeneous net `(w c, w)` is what is rounded)
    /// and at the intended inputs.
    ///
    /// Rational patches: `bound` is the proven a-priori bound
    /// [`crate::certify::bound::rational_a_priori`] of homogeneous de Casteljau plus one division,
    /// and `cond=K` means `|y − q| ≤ K ε κ` with the rational condition number
    /// [`crate::certify::bound::rational_condition`].
    ///
    /// S-patches: `bound` is the proven bound of the whole float path (float Wachspress
    /// coordinates, then de Casteljau: [`crate::certify::beyond::SPatchCase::total_bound`]);
    /// `cond=K` is refused (the coordinates have a condition of their own that `Σ|P_α|B_α` does
    /// not measure). The condition shown is `Σ|P_α|B_α(λ)` at the exact Wachspress coordinates of
    /// the rounded point.
    fn refuse_cond_tolerance(inputs: &Inputs<'_>) -> Result<(), InputError> {
        let (tolerance, _) = inputs.file.tolerance_of(inputs.claim)?;
        if matches!(tolerance, crate::certify::measures::Tolerance::Cond(_)) {
            return Err(inputs.error(
                "tolerance",
                format!("tolerance `{tolerance}` is not defined for S-patches (the float Wachspress coordinates add an error Σ|P_α|B_α does not measure): use `bound`, the proven bound of the whole float path"),
            ));
        }
        Ok(())
    }

    fn rounded(
        inputs: &Inputs<'_>,
        xs: &[BigRational],
        p: crate::float::Precision,
        name: &str,
    ) -> Result<Vec<BigRational>, InputError> {
        xs.iter()
            .map(|q| crate::certify::measures::as_float(q, p))
            .collect::<Option<_>>()
            .ok_or_else(|| inputs.error(name, format!("a number overflows {}", p.name())))
    }

    /// The float view of an `eval` claim on a rational patch.
    pub fn eval_float_rational(
        inputs: &Inputs<'_>,
        r: &crate::rational::RationalPatch,
        p: crate::float::Precision,
    ) -> Result<super::FloatEval, InputError> {
        match inputs.opt_string("algorithm")?.as_deref() {
            None | Some("casteljau") => {}
            Some(other) => {
                return Err(inputs.error(
                    "algorithm",
                    format!("`{other}`: a rational patch's float path is homogeneous de Casteljau (algorithm `casteljau`) only"),
                ));
            }
        }
        let intended = inputs.point(&r.patch)?;
        let key = if inputs.get("at").is_some() {
            "at"
        } else {
            "cartesian"
        };
        let seen_inputs = match inputs.opt_rationals("cartesian")? {
            Some(x) => {
                let xr = rounded(inputs, &x, p, "cartesian")?;
                r.patch
                    .domain_or_reference()
                    .barycentric(&xr)
                    .map_err(|e| inputs.error("cartesian", e.to_string()))?
            }
            None => rounded(inputs, &intended, p, "at")?,
        };
        let h = r.homogeneous();
        let hr = h.map(|q| crate::certify::measures::as_float(q, p));
        if hr.coords().iter().any(Option::is_none) {
            return Err(inputs.error(
                "patch",
                format!("a weighted control point overflows {}", p.name()),
            ));
        }
        let hr = hr.map(|q| q.clone().unwrap_or_default());
        let seen = crate::rational::RationalPatch::from_homogeneous(&hr, &r.patch)
            .map_err(|e| inputs.error("patch", format!("rounded to {}: {e}", p.name())))?;
        let exact_seen = seen
            .evaluate(&seen_inputs)
            .map_err(|e| inputs.error(key, format!("as the code saw it: {e}")))?;
        let exact_intended = r
            .evaluate(&intended)
            .map_err(|e| inputs.error(key, e.to_string()))?;
        use crate::certify::bound;
        let condition = bound::rational_condition(&hr, &seen_inputs)
            .ok_or_else(|| inputs.error(key, "the denominator vanishes as the code saw it"))?;
        let (m, n) = (hr.m(), hr.degree());
        let errs: Option<Vec<BigRational>> = bound::condition(&hr, &seen_inputs)
            .iter()
            .map(|s| bound::a_priori(crate::exact::Algorithm::Casteljau, p, m, n, s, &seen_inputs))
            .collect();
        let den = crate::exact::ExactEvaluator::new(&seen.denominator())
            .evaluate(&seen_inputs, crate::exact::Algorithm::Casteljau)
            .remove(0);
        let bounds = errs.and_then(|e| {
            let (e_den, e_num) = e.split_last()?;
            bound::rational_a_priori(p, e_num, e_den, &exact_seen, &den)
        });
        let (tolerance, _) = inputs.file.tolerance_of(inputs.claim)?;
        if tolerance == crate::certify::measures::Tolerance::Bound && bounds.is_none() {
            return Err(inputs.error(
                "tolerance",
                format!("no bound at this point: the denominator's error bound e_D is not below |D| in {} (its sign is not certain)", p.name()),
            ));
        }
        let d = exact_seen.len();
        let bound = bounds.map_or_else(|| vec![None; d], |b| b.into_iter().map(Some).collect());
        Ok(super::FloatEval {
            seen_inputs,
            exact_seen,
            exact_intended,
            condition,
            bound,
        })
    }

    /// The float view of an `eval` claim on an S-patch (Cartesian point).
    pub fn eval_float_spatch(
        inputs: &Inputs<'_>,
        s: &crate::spatch::SPatch,
        p: crate::float::Precision,
    ) -> Result<super::FloatEval, InputError> {
        refuse_cond_tolerance(inputs)?;
        let x = inputs.rationals("cartesian")?;
        let (_, exact_intended) = s
            .evaluate(&x)
            .map_err(|e| inputs.error("cartesian", e.to_string()))?;
        let seen_inputs = rounded(inputs, &x, p, "cartesian")?;
        let mut verts = Vec::new();
        for v in s.polygon.vertices() {
            verts.push(rounded(inputs, v, p, "patch")?);
        }
        let polygon = crate::spatch::Polygon::new(verts).map_err(|e| {
            inputs.error("patch", format!("the polygon rounded to {}: {e}", p.name()))
        })?;
        let net = s.net.map(|q| crate::certify::measures::as_float(q, p));
        if net.coords().iter().any(Option::is_none) {
            return Err(inputs.error("patch", format!("a control point overflows {}", p.name())));
        }
        let seen = crate::spatch::SPatch::new(polygon, net.map(|q| q.clone().unwrap_or_default()))
            .map_err(|e| inputs.error("patch", e.to_string()))?;
        let (lambda, exact_seen) = seen
            .evaluate(&seen_inputs)
            .map_err(|e| inputs.error("cartesian", format!("as the code saw it: {e}")))?;
        let condition = crate::certify::bound::condition(&seen.net, &lambda);
        let d = exact_seen.len();
        // the proven bound of the float path, run as the code runs it
        use crate::certify::beyond::SPatchCertifier;
        use crate::float::Precision;
        use crate::number::{round_f32, round_f64};
        let total = match p {
            Precision::F64 => SPatchCertifier::<f64>::new(s).ok().and_then(|c| {
                c.check(&[round_f64(&seen_inputs[0]), round_f64(&seen_inputs[1])])
                    .total_bound
            }),
            Precision::F32 => SPatchCertifier::<f32>::new(s).ok().and_then(|c| {
                c.check(&[round_f32(&seen_inputs[0]), round_f32(&seen_inputs[1])])
                    .total_bound
            }),
        };
        let (tolerance, _) = inputs.file.tolerance_of(inputs.claim)?;
        if tolerance == crate::certify::measures::Tolerance::Bound && total.is_none() {
            return Err(inputs.error(
                "tolerance",
                format!("no bound at this point in {}: it is on or too near an edge of the polygon (or its numbers too small) for the float Wachspress coordinates' bound", p.name()),
            ));
        }
        let bound = total.map_or_else(|| vec![None; d], |b| b.into_iter().map(Some).collect());
        Ok(super::FloatEval {
            seen_inputs,
            exact_seen,
            exact_intended,
            condition,
            bound,
        })
    }

    /// The residual of an implicit equation on a patch of any kind.
    pub fn implicit(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let any = inputs.file.any_patch_for(inputs.claim)?;
        let (x, w, default_names) = match any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => {
                // the barycentric form is homogeneous of degree n, so its weight is
                // W = (Σλ)^n (ΣB_α = (Σλ)^n), not 1: W^k F(X/W) is then homogeneous too
                let m = p.net.m();
                let sum = (0..=m).fold(Polynomial::zero(m + 1), |acc, i| {
                    acc.add(&Polynomial::variable(m + 1, i))
                });
                let n = u32::try_from(p.net.degree()).expect("degrees are capped");
                (barycentric_form(&p.net), sum.pow(n), barycentric_names(m))
            }
            AnyPatch::Rational(r) => {
                let mut h = r.homogeneous_form();
                let w = h.pop().expect("weight component");
                (h, w, barycentric_names(r.patch.net.m()))
            }
            AnyPatch::SPatch(s) => {
                let (nums, den) = s.rational_form();
                (nums, den, cartesian_names(2))
            }
        };
        let d = x.len();
        let coords: Vec<String> = match inputs.opt_strings("coordinates")? {
            Some(c) if c.len() != d => {
                return Err(inputs.error(
                    "coordinates",
                    format!("{} names given, the points have {d} coordinates", c.len()),
                ));
            }
            Some(c) => c,
            None => cartesian_names(d),
        };
        let text = inputs
            .opt_string("equation")?
            .ok_or_else(|| inputs.error("equation", "missing input `equation`"))?;
        let refs: Vec<&str> = coords.iter().map(String::as_str).collect();
        let f = Polynomial::parse(&text, &refs)
            .map_err(|e| inputs.error("equation", format!("`{text}`: {e}")))?;
        let names = inputs.names(default_names)?;
        Ok(Value::Poly(homogenised_residual(&f, &x, &w), names))
    }

    /// Wachspress data of an S-patch's polygon at a point.
    pub fn wachspress(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let AnyPatch::SPatch(s) = inputs.file.any_patch_for(inputs.claim)? else {
            return Err(inputs.error(
                "patch",
                "`wachspress` needs an S-patch (a patch file with `polygon`)",
            ));
        };
        let x = inputs.rationals("cartesian")?;
        let lambda = s
            .polygon
            .wachspress(&x)
            .map_err(|e| inputs.error("cartesian", e.to_string()))?;
        let p = [x[0].clone(), x[1].clone()];
        Ok(Value::Map(vec![
            ("A".into(), Value::numbers(&s.polygon.areas(&p))),
            ("C".into(), Value::numbers(&s.polygon.corner_areas())),
            ("lambda".into(), Value::numbers(&lambda)),
        ]))
    }

    /// The Bézier abscissae of a patch's domain and degree.
    pub fn abscissae(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let p = inputs.patch()?;
        let xi = functional::abscissae(&p.domain_or_reference(), p.net.degree());
        Ok(map(p.net.simplex(), xi.iter().map(|x| Value::numbers(x))))
    }

    /// The graph of a functional patch.
    pub fn graph(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let AnyPatch::Functional(p) = inputs.file.any_patch_for(inputs.claim)? else {
            return Err(inputs.error(
                "patch",
                "`graph` needs a functional patch (kind = \"functional\")",
            ));
        };
        let g = functional::graph(p).map_err(|e| inputs.error("patch", e.to_string()))?;
        Ok(map(g.net.simplex(), g.net.points().map(Value::numbers)))
    }

    /// Control ordinates of a polynomial over a domain.
    pub fn ordinates(inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let node = inputs
            .get("domain")
            .ok_or_else(|| inputs.error("domain", "missing input `domain`"))?;
        let doc = &inputs.file.doc;
        let m = doc.array(node, "domain")?.len().saturating_sub(1);
        let domain =
            crate::io::patch_file::domain(doc, node, m, &format!("{}.domain", inputs.claim.id))?;
        let n = inputs
            .opt_usize("degree")?
            .ok_or_else(|| inputs.error("degree", "missing input `degree`"))?;
        if n > crate::io::patch_file::MAX_DEGREE {
            return Err(inputs.error(
                "degree",
                format!("degree {n} is above the limit of {MAX_DEGREE}"),
            ));
        }
        super::check_count(inputs, "degree", m, n)?;
        let names = inputs.names(cartesian_names(m))?;
        let text = inputs
            .opt_string("function")?
            .ok_or_else(|| inputs.error("function", "missing input `function`"))?;
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let f = Polynomial::parse(&text, &refs)
            .map_err(|e| inputs.error("function", format!("`{text}`: {e}")))?;
        let b: Vec<BigRational> = functional::ordinates(&domain, n, &f)
            .map_err(|e| inputs.error("function", e.to_string()))?;
        Ok(map(
            &crate::simplex::Simplex::new(m, n),
            b.into_iter().map(Value::Number),
        ))
    }
}

/// The Bernstein basis of a degree (symbolic or at a point), or its sum.
fn basis(inputs: &Inputs<'_>, sum: bool) -> Result<Value, InputError> {
    let n = inputs
        .opt_usize("degree")?
        .ok_or_else(|| inputs.error("degree", "missing input `degree`"))?;
    let m = inputs.opt_usize("simplex")?.unwrap_or(2);
    if !(1..=crate::io::patch_file::MAX_SIMPLEX_DIMENSION).contains(&m)
        || n > crate::io::patch_file::MAX_DEGREE
    {
        return Err(inputs.error(
            "degree",
            format!("degree {n} on a {m}-simplex is out of range (degree at most {MAX_DEGREE}, simplex dimension 1 to {})", crate::io::patch_file::MAX_SIMPLEX_DIMENSION),
        ));
    }
    check_count(inputs, "degree", m, n)?;
    let simplex = Simplex::new(m, n);
    if let Some(at) = inputs.opt_rationals("at")? {
        if at.len() != m + 1 {
            return Err(inputs.error(
                "at",
                format!("{} coordinates, expected {}", at.len(), m + 1),
            ));
        }
        let b = bernstein::basis(&simplex, &at);
        return Ok(if sum {
            Value::Number(b.iter().sum())
        } else {
            Value::Map(
                simplex
                    .iter()
                    .map(index_key)
                    .zip(b.into_iter().map(Value::Number))
                    .collect(),
            )
        });
    }
    let cartesian = match inputs.opt_string("variables")?.as_deref() {
        None | Some("barycentric") => false,
        Some("cartesian") => true,
        Some(other) => {
            return Err(inputs.error(
                "variables",
                format!("`{other}`: expected \"barycentric\" or \"cartesian\""),
            ));
        }
    };
    let bary_names = inputs.names(barycentric_names(m))?;
    let polys: Vec<Polynomial> = simplex
        .iter()
        .map(|alpha| {
            Polynomial::monomial(
                m + 1,
                alpha.to_vec(),
                BigRational::from_integer(multinomial(alpha).into()),
            )
        })
        .collect();
    let (names, polys) = if cartesian {
        let subs = crate::symbolic::barycentric_of_cartesian(&crate::domain::Domain::reference(m));
        (
            cartesian_names(m),
            polys.iter().map(|p| p.compose(&subs)).collect::<Vec<_>>(),
        )
    } else {
        (bary_names, polys)
    };
    Ok(if sum {
        let total = polys
            .iter()
            .fold(Polynomial::zero(names.len()), |acc, p| acc.add(p));
        Value::Poly(total, names)
    } else {
        Value::Map(
            simplex
                .iter()
                .map(index_key)
                .zip(polys.into_iter().map(|p| Value::Poly(p, names.clone())))
                .collect(),
        )
    })
}

/// Read the claimed value at `node`, guided by the shape of the exact value.
pub fn read_claimed(
    doc: &Document,
    node: &Node,
    exact: &Value,
    key: &str,
) -> Result<Value, InputError> {
    Ok(match (exact, &node.value) {
        (Value::Number(_), _) => Value::Number(doc.rational(node, key)?),
        (Value::Poly(_, names), NodeValue::String(s) | NodeValue::Number(s)) => {
            let n: Vec<&str> = names.iter().map(String::as_str).collect();
            let p = Polynomial::parse(s, &n)
                .map_err(|e| doc.error(node, key, format!("`{s}`: {e}")))?;
            Value::Poly(p, names.clone())
        }
        (Value::Bool(_), NodeValue::Bool(b)) => Value::Bool(*b),
        (Value::Integer(_), NodeValue::Number(t)) => Value::Integer(
            t.parse()
                .map_err(|_| doc.error(node, key, format!("`{t}` is not an integer")))?,
        ),
        (Value::List(xs), NodeValue::Array(items)) => {
            let fallback = xs
                .first()
                .cloned()
                .unwrap_or(Value::Number(BigRational::default()));
            Value::List(
                items
                    .iter()
                    .enumerate()
                    .map(|(i, it)| {
                        read_claimed(
                            doc,
                            it,
                            xs.get(i).unwrap_or(&fallback),
                            &format!("{key}[{i}]"),
                        )
                    })
                    .collect::<Result<_, _>>()?,
            )
        }
        (Value::Map(kv), NodeValue::Table(items)) => Value::Map(
            items
                .iter()
                .map(|(k, it)| {
                    let like = kv
                        .iter()
                        .find(|(ek, _)| ek == k)
                        .map(|(_, v)| v)
                        .or_else(|| kv.first().map(|(_, v)| v));
                    let like = like.ok_or_else(|| doc.error(it, key, "unexpected key"))?;
                    Ok((
                        k.clone(),
                        read_claimed(doc, it, like, &format!("{key}.\"{k}\""))?,
                    ))
                })
                .collect::<Result<_, InputError>>()?,
        ),
        (want, _) => {
            let kind = match want {
                Value::Poly(..) => "a polynomial (string)",
                Value::Bool(_) => "true or false",
                Value::Integer(_) => "an integer",
                Value::List(_) => "an array",
                Value::Map(_) => "a table",
                Value::Number(_) => "a number",
            };
            return Err(doc.error(
                node,
                key,
                format!("expected {kind}, found {}", node.value.kind()),
            ));
        }
    })
}
