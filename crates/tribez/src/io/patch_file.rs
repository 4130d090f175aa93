//! Patch files: TOML or JSON (chosen by extension), documented in docs/guide.md (§3).
//!
//! ```toml
//! name = "Finn, day 30, worked example"
//! degree = 2
//! # domain = [["1","0"], ["0","1"], ["0","0"]]   # optional: m+1 vertices in R^m
//! [control_points]
//! "2,0,0" = ["0", "0", "0"]
//! "1,1,0" = ["1", "0", "2"]
//! # … every multi-index of degree 2 exactly once
//! ```
//!
//! Keys are multi-indices with `m + 1` comma-separated parts (`m = 1` curves, `2` triangles,
//! `3` tetrahedra, …), summing to `degree`; values are arrays of `d >= 1` numbers, written as
//! strings in the number syntax of [`crate::number::parse_rational`] or as plain numbers (taken
//! from their text, exactly).
//!
//! Three optional additions make the other kinds of [`AnyPatch`] (docs/guide.md §3,
//! "Rational patches, S-patches and functional patches"):
//!
//! * `[weights]`, keyed like `control_points`, one number per control point: a **rational**
//!   patch. Every control point needs exactly one weight; zero and negative weights are
//!   accepted (evaluating where the denominator vanishes is an error).
//! * `polygon = [["x", "y"], …]`: an **S-patch** over that convex polygon (counter-clockwise);
//!   the control-point keys then have one part per polygon vertex, summing to `degree` (the
//!   depth). No `domain` and no `weights` with a polygon.
//! * `kind = "functional"`: a **functional** (nonparametric) patch: one control ordinate per
//!   control point (`d = 1`) over `domain` (default: the reference simplex).
//!
//! `kind` may also be written `"bezier"`, `"rational"` or `"s-patch"`; it must then agree with
//! the keys present. [`read_patch`] returns plain and functional patches as a [`Patch`] and
//! rejects the other kinds with a located error; [`read_any_patch`] returns every kind.

use std::path::Path;

use num_rational::BigRational;
use serde_json::{Map, Value as Json, json};

use super::InputError;
use super::tree::{Document, Node};
use crate::any_patch::AnyPatch;
use crate::domain::Domain;
use crate::patch::{BezierPatch as Patch, ControlNet};
use crate::rational::RationalPatch;
use crate::simplex::{self, Simplex};
use crate::spatch::{Polygon, SPatch};

/// The largest degree a patch file may have. Exact evaluation at degree 200 costs tens of
/// milliseconds per point (docs/performance.md, "Scaling"); beyond that, results run to many kilobits.
pub const MAX_DEGREE: usize = 200;
/// The largest number of control points a patch file may have.
pub const MAX_CONTROL_POINTS: usize = 250_000;
/// The largest simplex dimension `m` (number of barycentric coordinates minus one).
pub const MAX_SIMPLEX_DIMENSION: usize = 16;

/// The keys a patch file may have.
pub const PATCH_KEYS: &[&str] = &[
    "name",
    "degree",
    "domain",
    "control_points",
    "domain_in_parent",
    "weights",
    "polygon",
    "kind",
];

/// Read a patch file: a polynomial Bézier simplex (or a functional patch, as its scalar net).
/// Rational patches and S-patches are rejected with a located error.
pub fn read_patch(path: &Path) -> Result<Patch, InputError> {
    let doc = Document::read(path)?;
    patch_from_document(&doc, &doc.root, "")
}

/// Read a patch file of any kind.
pub fn read_any_patch(path: &Path) -> Result<AnyPatch, InputError> {
    let doc = Document::read(path)?;
    any_patch_from_document(&doc, &doc.root, "")
}

/// Parse a polynomial patch from a table node (the whole file, or an inline `patch` table in a
/// claim file); other kinds are an error naming the key that makes them so.
pub fn patch_from_document(doc: &Document, node: &Node, prefix: &str) -> Result<Patch, InputError> {
    let any = any_patch_from_document(doc, node, prefix)?;
    match any {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => Ok(p),
        other => {
            let table = doc.table(node, prefix)?;
            let k = if matches!(other, AnyPatch::Rational(_)) {
                "weights"
            } else {
                "polygon"
            };
            let at = Document::get(table, k).unwrap_or(node);
            let key = if prefix.is_empty() {
                k.to_string()
            } else {
                format!("{prefix}.{k}")
            };
            Err(doc.error(
                at,
                &key,
                PatchFileProblem::NotPolynomial {
                    kind: other.described(),
                },
            ))
        }
    }
}

/// What is wrong in a patch file ([`super::Problem::Patch`]): one variant per check, with the
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

/// Parse a patch of any kind from a table node.
pub fn any_patch_from_document(
    doc: &Document,
    node: &Node,
    prefix: &str,
) -> Result<AnyPatch, InputError> {
    let key = |k: &str| {
        if prefix.is_empty() {
            k.to_string()
        } else {
            format!("{prefix}.{k}")
        }
    };
    let table = doc.table(node, prefix)?;
    doc.check_keys(node, table, PATCH_KEYS, prefix)?;
    let name = Document::get(table, "name")
        .map(|n| doc.string(n, &key("name")).map(str::to_string))
        .transpose()?;
    let degree_node = Document::get(table, "degree").ok_or_else(|| {
        doc.error(
            node,
            &key("degree"),
            super::Problem::MissingKey { key: "degree" },
        )
    })?;
    let degree = doc.usize(degree_node, &key("degree"))?;
    if degree > MAX_DEGREE {
        return Err(doc.error(
            degree_node,
            &key("degree"),
            PatchFileProblem::DegreeTooLarge {
                degree,
                limit: MAX_DEGREE,
            },
        ));
    }
    let cp_node = Document::get(table, "control_points").ok_or_else(|| {
        doc.error(
            node,
            &key("control_points"),
            PatchFileProblem::NoControlPointsTable,
        )
    })?;
    let net = control_points(doc, cp_node, degree, &key("control_points"))?;
    let kind_node = Document::get(table, "kind");
    let kind = kind_node.map(|n| doc.string(n, &key("kind"))).transpose()?;
    let kind_error =
        |problem: PatchFileProblem| doc.error(kind_node.unwrap_or(node), &key("kind"), problem);
    if let Some(k) = kind
        && !["bezier", "rational", "functional", "s-patch"].contains(&k)
    {
        return Err(kind_error(PatchFileProblem::UnknownKind {
            kind: k.to_string(),
        }));
    }
    let weights_node = Document::get(table, "weights");
    if let Some(poly_node) = Document::get(table, "polygon") {
        for other in ["domain", "weights"] {
            if let Some(n) = Document::get(table, other) {
                return Err(doc.error(
                    n,
                    &key(other),
                    PatchFileProblem::NotWithPolygon { key: other },
                ));
            }
        }
        if kind.is_some_and(|k| k != "s-patch") {
            return Err(kind_error(PatchFileProblem::KindContradictsPolygon {
                kind: kind.unwrap_or_default().to_string(),
            }));
        }
        let rows = doc.array(poly_node, &key("polygon"))?;
        let vertices = rows
            .iter()
            .enumerate()
            .map(|(i, r)| doc.rationals(r, &format!("{}[{i}]", key("polygon"))))
            .collect::<Result<Vec<_>, _>>()?;
        let polygon =
            Polygon::new(vertices).map_err(|e| doc.error(poly_node, &key("polygon"), e))?;
        let mut s =
            SPatch::new(polygon, net).map_err(|e| doc.error(cp_node, &key("control_points"), e))?;
        s.name = name;
        return Ok(AnyPatch::SPatch(s));
    }
    let domain = match Document::get(table, "domain") {
        None => None,
        Some(d) => Some(domain(doc, d, net.m(), &key("domain"))?),
    };
    let patch = Patch { name, net, domain };
    match (kind, weights_node) {
        (Some("s-patch"), _) => Err(kind_error(PatchFileProblem::SPatchNeedsPolygon)),
        (Some("bezier" | "functional"), Some(w)) => Err(doc.error(
            w,
            &key("weights"),
            PatchFileProblem::NoWeightsFor {
                kind: kind.unwrap_or_default().to_string(),
            },
        )),
        (Some("rational"), None) => Err(kind_error(PatchFileProblem::RationalNeedsWeights)),
        (_, Some(w)) => {
            let weights = weights(doc, w, &patch.net, &key("weights"))?;
            Ok(AnyPatch::Rational(RationalPatch::new(patch, weights)))
        }
        (Some("functional"), None) => {
            if patch.net.dim() != 1 {
                return Err(doc.error(
                    cp_node,
                    &key("control_points"),
                    PatchFileProblem::FunctionalDimension {
                        dim: patch.net.dim(),
                    },
                ));
            }
            Ok(AnyPatch::Functional(patch))
        }
        _ => Ok(AnyPatch::Bezier(patch)),
    }
}

/// Parse `[weights]`: one number per control point, keyed like `control_points`.
fn weights(
    doc: &Document,
    node: &Node,
    net: &ControlNet<BigRational>,
    key: &str,
) -> Result<Vec<BigRational>, InputError> {
    let table = doc.table(node, key)?;
    let simplex = net.simplex();
    let mut slots: Vec<Option<(String, BigRational)>> = vec![None; simplex.len()];
    for (k, v) in table {
        let here = format!("{key}.\"{k}\"");
        let alpha: Option<Vec<u32>> = k.split(',').map(|p| p.trim().parse::<u32>().ok()).collect();
        let r = alpha
            .filter(|a| {
                a.len() == net.m() + 1
                    && a.iter().map(|&x| u64::from(x)).sum::<u64>() == net.degree() as u64
            })
            .map(|a| simplex.rank(&a))
            .ok_or_else(|| {
                doc.error(
                    v,
                    &here,
                    PatchFileProblem::WeightWithoutPoint { key: k.clone() },
                )
            })?;
        if let Some((other, _)) = &slots[r] {
            return Err(doc.error(
                v,
                &here,
                PatchFileProblem::DuplicateWeight {
                    other: other.clone(),
                },
            ));
        }
        slots[r] = Some((k.clone(), doc.rational(v, &here)?));
    }
    let mut out = Vec::with_capacity(slots.len());
    for (r, slot) in slots.into_iter().enumerate() {
        match slot {
            Some((_, w)) => out.push(w),
            None => {
                return Err(doc.error(
                    node,
                    key,
                    PatchFileProblem::MissingWeight {
                        index: index_key(simplex.index(r)),
                    },
                ));
            }
        }
    }
    if out.iter().all(num_traits::Zero::is_zero) {
        return Err(doc.error(node, key, PatchFileProblem::AllWeightsZero));
    }
    Ok(out)
}

/// `; write "2,0,0"` after the message of a key written without commas, else nothing.
fn comma_hint(comma_form: &Option<String>) -> String {
    comma_form
        .as_ref()
        .map(|k| format!("; write \"{k}\""))
        .unwrap_or_default()
}

/// `key` with commas between its digits (`"200"` → `"2,0,0"`), when it is 2 to
/// `MAX_SIMPLEX_DIMENSION + 1` decimal digits that sum to `degree`: the way textbooks write
/// multi-indices of low degree.
fn comma_form(key: &str, degree: usize) -> Option<String> {
    let digits = key.as_bytes();
    if !(2..=MAX_SIMPLEX_DIMENSION + 1).contains(&digits.len())
        || !digits.iter().all(u8::is_ascii_digit)
    {
        return None;
    }
    let sum: usize = digits.iter().map(|d| usize::from(d - b'0')).sum();
    (sum == degree).then(|| key.chars().map(String::from).collect::<Vec<_>>().join(","))
}

fn control_points(
    doc: &Document,
    node: &Node,
    degree: usize,
    key: &str,
) -> Result<ControlNet<BigRational>, InputError> {
    let table = doc.table(node, key)?;
    let Some((first_key, first)) = table.first() else {
        return Err(doc.error(node, key, PatchFileProblem::NoControlPoints));
    };
    let parts = |k: &str, n: &Node| -> Result<Vec<u32>, InputError> {
        k.split(',')
            .map(|p| p.trim().parse::<u32>())
            .collect::<Result<Vec<_>, _>>()
            .map_err(|_| {
                doc.error(
                    n,
                    &format!("{key}.\"{k}\""),
                    PatchFileProblem::NotAMultiIndex,
                )
            })
    };
    let m = parts(first_key, first)?.len().saturating_sub(1);
    if m == 0 || m > MAX_SIMPLEX_DIMENSION {
        return Err(doc.error(
            first,
            &format!("{key}.\"{first_key}\""),
            PatchFileProblem::MultiIndexLength {
                max_parts: MAX_SIMPLEX_DIMENSION + 1,
                comma_form: comma_form(first_key.trim(), degree),
            },
        ));
    }
    let total = simplex::binomial((degree + m) as u64, m as u64);
    if total > MAX_CONTROL_POINTS as u128 {
        return Err(doc.error(
            node,
            key,
            PatchFileProblem::TooManyControlPoints {
                degree,
                m,
                total,
                limit: MAX_CONTROL_POINTS,
            },
        ));
    }
    let simplex = Simplex::new(m, degree);
    // For each rank, the position in `table` of the entry that filled it; the keys of messages
    // (`control_points."1,0,1"`) are only spelled out on an error.
    let here = |k: &str| format!("{key}.\"{k}\"");
    let mut slots: Vec<Option<(usize, Vec<BigRational>)>> = vec![None; simplex.len()];
    let mut dim: Option<(usize, &str)> = None;
    for (pos, (k, v)) in table.iter().enumerate() {
        let alpha = parts(k, v)?;
        if alpha.len() != m + 1 {
            return Err(doc.error(
                v,
                &here(k),
                PatchFileProblem::MultiIndexParts {
                    parts: alpha.len(),
                    first: first_key.clone(),
                    expected: m + 1,
                },
            ));
        }
        let sum: u64 = alpha.iter().map(|&a| u64::from(a)).sum();
        if sum != degree as u64 {
            return Err(doc.error(v, &here(k), PatchFileProblem::MultiIndexSum { sum, degree }));
        }
        let r = simplex.rank(&alpha);
        if let Some((other, _)) = &slots[r] {
            let other = &table[*other].0;
            return Err(doc.error(
                v,
                &here(k),
                PatchFileProblem::DuplicateControlPoint {
                    other: other.clone(),
                },
            ));
        }
        let point = doc.rationals(v, &here(k))?;
        if point.is_empty() {
            return Err(doc.error(v, &here(k), PatchFileProblem::EmptyPoint));
        }
        match dim {
            None => dim = Some((point.len(), k.as_str())),
            Some((d, other)) if d != point.len() => {
                return Err(doc.error(
                    v,
                    &here(k),
                    PatchFileProblem::PointDimension {
                        dim: point.len(),
                        other: other.to_string(),
                        expected: d,
                    },
                ));
            }
            _ => {}
        }
        slots[r] = Some((pos, point));
    }
    let d = dim.map_or(1, |(d, _)| d);
    let mut coords = Vec::with_capacity(slots.len() * d);
    for (r, slot) in slots.into_iter().enumerate() {
        match slot {
            Some((_, p)) => coords.extend(p),
            None => {
                let missing = index_key(simplex.index(r));
                return Err(doc.error(
                    node,
                    key,
                    PatchFileProblem::MissingControlPoint {
                        index: missing,
                        degree,
                    },
                ));
            }
        }
    }
    Ok(ControlNet::new(simplex, d, coords))
}

/// Parse a domain simplex: `m + 1` vertices in `ℝ^m`.
pub fn domain(doc: &Document, node: &Node, m: usize, key: &str) -> Result<Domain, InputError> {
    let rows = doc.array(node, key)?;
    if rows.len() != m + 1 {
        return Err(doc.error(
            node,
            key,
            PatchFileProblem::DomainVertices {
                expected: m + 1,
                m,
                found: rows.len(),
            },
        ));
    }
    let vertices = rows
        .iter()
        .enumerate()
        .map(|(i, r)| doc.rationals(r, &format!("{key}[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Domain::new(vertices).map_err(|e| doc.error(node, key, e))
}

/// `"1,0,2"` for a multi-index.
pub fn index_key(alpha: &[u32]) -> String {
    alpha
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(",")
}

fn strings(xs: &[BigRational]) -> Vec<String> {
    xs.iter().map(ToString::to_string).collect()
}

/// The patch as JSON, in the patch-file layout (numbers as exact strings, canonical order).
pub fn patch_to_json(patch: &Patch) -> Json {
    let mut obj = Map::new();
    if let Some(name) = &patch.name {
        obj.insert("name".into(), json!(name));
    }
    obj.insert("degree".into(), json!(patch.net.degree()));
    if let Some(d) = &patch.domain {
        obj.insert(
            "domain".into(),
            json!(d.vertices().iter().map(|v| strings(v)).collect::<Vec<_>>()),
        );
    }
    let mut cps = Map::new();
    for (alpha, p) in patch.net.entries() {
        cps.insert(index_key(alpha), json!(strings(p)));
    }
    obj.insert("control_points".into(), Json::Object(cps));
    Json::Object(obj)
}

fn toml_string(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_else(|_| format!("\"{s}\""))
}

fn toml_list(xs: &[BigRational]) -> String {
    format!(
        "[{}]",
        xs.iter()
            .map(|x| toml_string(&x.to_string()))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// The patch as a TOML patch file.
pub fn patch_to_toml(patch: &Patch) -> String {
    let mut out = String::new();
    if let Some(name) = &patch.name {
        out += &format!("name = {}\n", toml_string(name));
    }
    out += &format!("degree = {}\n", patch.net.degree());
    if let Some(d) = &patch.domain {
        out += &format!(
            "domain = [{}]\n",
            d.vertices()
                .iter()
                .map(|v| toml_list(v))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    out += "\n[control_points]\n";
    for (alpha, p) in patch.net.entries() {
        out += &format!("\"{}\" = {}\n", index_key(alpha), toml_list(p));
    }
    out
}

/// A patch of any kind as a TOML patch file (`kind` for functional patches, `polygon` for
/// S-patches, `[weights]` for rational patches).
pub fn any_patch_to_toml(patch: &AnyPatch) -> String {
    match patch {
        AnyPatch::Bezier(p) => patch_to_toml(p),
        AnyPatch::Functional(p) => format!("kind = \"functional\"\n{}", patch_to_toml(p)),
        AnyPatch::Rational(r) => {
            let mut out = patch_to_toml(&r.patch);
            out += "\n[weights]\n";
            for (alpha, w) in r.patch.net.simplex().iter().zip(&r.weights) {
                out += &format!(
                    "\"{}\" = {}\n",
                    index_key(alpha),
                    toml_string(&w.to_string())
                );
            }
            out
        }
        AnyPatch::SPatch(s) => {
            let mut out = String::new();
            if let Some(name) = &s.name {
                out += &format!("name = {}\n", toml_string(name));
            }
            out += &format!("degree = {}\n", s.net.degree());
            let vs: Vec<String> = s.polygon.vertices().iter().map(|v| toml_list(v)).collect();
            out += &format!("polygon = [{}]\n\n[control_points]\n", vs.join(", "));
            for (alpha, p) in s.net.entries() {
                out += &format!("\"{}\" = {}\n", index_key(alpha), toml_list(p));
            }
            out
        }
    }
}

/// A patch of any kind as JSON, in the patch-file layout.
pub fn any_patch_to_json(patch: &AnyPatch) -> Json {
    match patch {
        AnyPatch::Bezier(p) => patch_to_json(p),
        AnyPatch::Functional(p) => {
            let mut j = patch_to_json(p);
            j["kind"] = json!("functional");
            j
        }
        AnyPatch::Rational(r) => {
            let mut j = patch_to_json(&r.patch);
            let w: Map<String, Json> = r
                .patch
                .net
                .simplex()
                .iter()
                .zip(&r.weights)
                .map(|(a, w)| (index_key(a), json!(w.to_string())))
                .collect();
            j["weights"] = Json::Object(w);
            j
        }
        AnyPatch::SPatch(s) => {
            let mut obj = Map::new();
            if let Some(name) = &s.name {
                obj.insert("name".into(), json!(name));
            }
            obj.insert("degree".into(), json!(s.net.degree()));
            obj.insert(
                "polygon".into(),
                json!(
                    s.polygon
                        .vertices()
                        .iter()
                        .map(|v| strings(v))
                        .collect::<Vec<_>>()
                ),
            );
            let cps: Map<String, Json> = s
                .net
                .entries()
                .map(|(a, p)| (index_key(a), json!(strings(p))))
                .collect();
            obj.insert("control_points".into(), Json::Object(cps));
            Json::Object(obj)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::Problem;

    const FINN: &str = r#"
name = "Finn"
degree = 2
[control_points]
"2,0,0" = ["0", "0", "0"]
"1,1,0" = ["1", "0", "2"]
"0,2,0" = ["0", "2", "0"]
"1,0,1" = ["0", "1", "0"]
"0,1,1" = ["1", "1", "1"]
"0,0,2" = ["0", "2", "1"]
"#;

    fn parse(text: &str) -> Result<Patch, InputError> {
        let doc = Document::parse_toml("p.toml", text)?;
        patch_from_document(&doc, &doc.root, "")
    }

    #[test]
    fn reads_the_worked_example() {
        let p = parse(FINN).unwrap();
        assert_eq!(p.net.degree(), 2);
        assert_eq!(p.net.dim(), 3);
        assert_eq!(strings(p.net.at(&[1, 1, 0])), ["1", "0", "2"]);
    }

    /// Errors are data: the variant, the key and the line, with the figures of the message
    /// as fields (the sentence is the `Display` of the variant).
    #[test]
    fn errors_carry_the_problem_as_data() {
        let problem = |text: &str| {
            let e = parse(text).unwrap_err();
            (*e.problem, e.key, e.line)
        };
        let missing = FINN.replace("\"0,0,2\" = [\"0\", \"2\", \"1\"]\n", "");
        assert_eq!(
            problem(&missing),
            (
                Problem::Patch(PatchFileProblem::MissingControlPoint {
                    index: "0,0,2".into(),
                    degree: 2
                }),
                Some("control_points".into()),
                Some(4)
            )
        );
        let wrong_sum = FINN.replace("\"0,0,2\"", "\"0,0,3\"");
        assert_eq!(
            problem(&wrong_sum).0,
            Problem::Patch(PatchFileProblem::MultiIndexSum { sum: 3, degree: 2 })
        );
        let mixed = FINN.replace("[\"0\", \"2\", \"1\"]", "[\"0\", \"2\"]");
        assert_eq!(
            problem(&mixed),
            (
                Problem::Patch(PatchFileProblem::PointDimension {
                    dim: 2,
                    other: "2,0,0".into(),
                    expected: 3
                }),
                Some("control_points.\"0,0,2\"".into()),
                Some(10)
            )
        );
        let big = FINN.replace("degree = 2", "degree = 100000");
        assert_eq!(
            problem(&big).0,
            Problem::Patch(PatchFileProblem::DegreeTooLarge {
                degree: 100_000,
                limit: MAX_DEGREE
            })
        );
    }

    #[test]
    fn round_trips_through_toml_and_json() {
        let p = parse(FINN).unwrap();
        let again = parse(&patch_to_toml(&p)).unwrap();
        assert_eq!(p, again);
        let json = patch_to_json(&p).to_string();
        let doc = Document::parse_json("p.json", &json).unwrap();
        assert_eq!(patch_from_document(&doc, &doc.root, "").unwrap(), p);
    }

    fn err(text: &str) -> String {
        parse(text).unwrap_err().to_string()
    }

    #[test]
    fn bad_patches_name_the_place() {
        let missing = FINN.replace("\"0,1,1\" = [\"1\", \"1\", \"1\"]\n", "");
        assert!(
            err(&missing).contains("missing control point \"0,1,1\""),
            "{}",
            err(&missing)
        );
        let dup = FINN
            .replace("\"0,1,1\"", "\"0, 1,1\"")
            .replace("\"0,0,2\"", "\"0,1,1\"");
        assert!(
            err(&dup).contains("duplicated multi-index"),
            "{}",
            err(&dup)
        );
        let sum = FINN.replace("\"0,0,2\"", "\"0,0,3\"");
        assert!(
            err(&sum).starts_with("p.toml:10: control_points.\"0,0,3\": multi-index sums to 3"),
            "{}",
            err(&sum)
        );
        let len = FINN.replace("\"0,0,2\"", "\"0,0,0,2\"");
        assert!(err(&len).contains("has 4 parts"), "{}", err(&len));
        let dim = FINN.replace("[\"0\", \"2\", \"1\"]", "[\"0\", \"2\"]");
        assert!(err(&dim).contains("different dimensions"), "{}", err(&dim));
        let num = FINN.replace("\"1\", \"1\", \"1\"", "\"1\", \"x\", \"1\"");
        assert!(
            err(&num).contains("control_points.\"0,1,1\"[1]"),
            "{}",
            err(&num)
        );
        let zero = FINN.replace("\"1\", \"1\", \"1\"", "\"1\", \"1/0\", \"1\"");
        assert!(err(&zero).contains("zero denominator"), "{}", err(&zero));
        let big = FINN.replace("degree = 2", "degree = 201");
        assert!(
            err(&big).contains("above the limit of 200"),
            "{}",
            err(&big)
        );
        let degenerate = FINN.replace(
            "degree = 2",
            "degree = 2\ndomain = [[\"0\",\"0\"],[\"1\",\"1\"],[\"2\",\"2\"]]",
        );
        assert!(
            err(&degenerate).contains("degenerate domain"),
            "{}",
            err(&degenerate)
        );
        let unknown = FINN.replace("degree = 2", "degree = 2\ndegre = 3");
        assert!(
            err(&unknown).contains("degre: unknown key"),
            "{}",
            err(&unknown)
        );
    }

    #[test]
    fn every_kind_round_trips_through_toml_and_json() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/beyond");
        for f in [
            "octant_quartic.toml",
            "pentagon_depth2.toml",
            "functional_linear.toml",
            "tetra_quadratic.toml",
        ] {
            let p = read_any_patch(&dir.join(f)).unwrap();
            let doc = Document::parse_toml("p.toml", &any_patch_to_toml(&p)).unwrap();
            assert_eq!(
                any_patch_from_document(&doc, &doc.root, "").unwrap(),
                p,
                "{f}"
            );
            let doc = Document::parse_json("p.json", &any_patch_to_json(&p).to_string()).unwrap();
            assert_eq!(
                any_patch_from_document(&doc, &doc.root, "").unwrap(),
                p,
                "{f}"
            );
        }
    }
}
