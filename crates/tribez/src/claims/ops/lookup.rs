//! `lookup` claims: the value of a mesh of functional Bézier triangles at a point (docs/theory.md
//! §17), as another implementation (a GPU lookup) found it.
//!
//! ```toml
//! [[claim]]
//! id = "centre"
//! op = "lookup"
//! mesh = "hexagon_cubic.toml"     # a mesh file, relative to this claim file
//! at = ["1/3", "1/5"]             # the point x, y (or the text "1/3,1/5")
//! expect = "0.41"                 # the claimed value
//! triangle = 0                    # optional: the triangle the code found the point in
//! precision = "f64"               # optional, with any tolerance but `bound`
//! tolerance = "ulps=4"
//! ```
//!
//! The exact value is the mesh's value at the point ([`Mesh::lookup`]; by C0 every triangle
//! containing the point gives it). A claimed `triangle` must contain the point (any of them on
//! a shared edge or vertex). With `precision`, as for the other operations, the numbers denote
//! the floats nearest their text: the point and the mesh's ordinates are rounded (the vertices,
//! the mesh's domain, stay exact, as a patch's domain does), and the claim is judged against the
//! exact value at the point as seen. `cond=K` scales with `Σ|b_α| B_α(|λ|)` in the triangle
//! found (`cond`: `K = 3n`, de Casteljau's constant; the barycentric coordinates a float lookup
//! computes first add their own error, which `cond` does not cover); `bound` is refused.

use num_rational::BigRational;

use super::super::value::{Mismatch, Value, compare};
use super::super::{Claim, ClaimFile, Judged, Verdict};
use super::Inputs;
use crate::certify::measures::{Leaf, Tolerance, as_float};
use crate::float::Precision;
use crate::io::tree::Value as NodeValue;
use crate::io::{ClaimProblem, InputError, NamedAt, Problem};
use crate::mesh::{Located, Mesh, MeshError, MeshFileProblem, read_mesh};

type Q = BigRational;

/// A `lookup` claim's inputs.
#[derive(Clone, Debug)]
pub struct LookupOp {
    /// The mesh (valid, every ordinate given).
    pub mesh: Mesh,
    /// Its file, as the claim names it.
    pub mesh_file: String,
    /// The point.
    pub at: [Q; 2],
    /// The triangle claimed, if any.
    pub triangle: Option<usize>,
}

impl LookupOp {
    /// Parse the inputs: read the mesh file (relative to the claim file) and check it.
    pub fn parse(inputs: &Inputs<'_>) -> Result<Self, InputError> {
        let doc = &inputs.file.doc;
        let node = inputs.required("mesh")?;
        let rel = doc.string(node, &inputs.key("mesh"))?;
        let dir = inputs
            .file
            .path
            .parent()
            .unwrap_or(std::path::Path::new("."));
        let (mesh, lines) = read_mesh(&dir.join(rel)).map_err(|mut e| {
            if e.line.is_none() {
                e.named_at = Some(Box::new(NamedAt {
                    file: doc.file.clone(),
                    line: node.line,
                    key: inputs.key("mesh"),
                }));
            }
            e
        })?;
        if let Some(p) = mesh.check().into_iter().next() {
            return Err(lines.locate(p));
        }
        let at = point(inputs)?;
        let triangle = inputs.opt_usize("triangle")?;
        if let Some(t) = triangle {
            let count = mesh.triangles().len();
            if t >= count {
                return Err(inputs.error(
                    "triangle",
                    MeshFileProblem::Mesh(MeshError::TriangleOutOfRange {
                        triangle: t,
                        last: count - 1,
                    }),
                ));
            }
        }
        Ok(LookupOp {
            mesh,
            mesh_file: rel.to_string(),
            at,
            triangle,
        })
    }

    /// The lookup as a float code saw it: the point and the ordinates rounded to `p` (the
    /// vertices stay exact).
    pub fn seen(&self, inputs: &Inputs<'_>, p: Precision) -> Result<Self, InputError> {
        let overflows = |name: &str, what: &'static str| {
            inputs.error(name, Problem::Overflows { what, precision: p })
        };
        let at = [as_float(&self.at[0], p), as_float(&self.at[1], p)];
        let [Some(x), Some(y)] = at else {
            return Err(overflows("at", "the point"));
        };
        let ordinates: Vec<Q> = self
            .mesh
            .ordinates()
            .iter()
            .map(|o| o.as_ref().and_then(|q| as_float(q, p)))
            .collect::<Option<_>>()
            .ok_or_else(|| overflows("mesh", "an ordinate of the mesh"))?;
        let mesh = self
            .mesh
            .with_ordinates(ordinates)
            .map_err(|e| inputs.error("mesh", MeshFileProblem::Mesh(e)))?;
        Ok(LookupOp {
            mesh,
            mesh_file: self.mesh_file.clone(),
            at: [x, y],
            triangle: self.triangle,
        })
    }

    /// Every triangle containing the point and the exact value there; a point outside the mesh
    /// is an error at `at`.
    pub fn answer(&self, inputs: &Inputs<'_>) -> Result<(Vec<Located>, Q), InputError> {
        let hits = self
            .mesh
            .lookup(&self.at)
            .map_err(|e| inputs.error("mesh", MeshFileProblem::Mesh(e)))?;
        let value = hits.first().map(|(_, v)| v.clone()).ok_or_else(|| {
            inputs.error(
                "at",
                ClaimProblem::OutsideMesh {
                    x: self.at[0].to_string(),
                    y: self.at[1].to_string(),
                    mesh: self.mesh_file.clone(),
                },
            )
        })?;
        Ok((hits.into_iter().map(|(l, _)| l).collect(), value))
    }

    /// The exact value (the value at the point; with a claimed triangle, a table of the
    /// triangle and the value).
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let (hits, value) = self.answer(inputs)?;
        Ok(self.value_of(&hits, value).0)
    }

    /// The exact value and the triangle judged in: the claimed one if it contains the point,
    /// else the lowest-numbered one that does.
    fn value_of(&self, hits: &[Located], value: Q) -> (Value, usize) {
        let found = self
            .triangle
            .filter(|t| hits.iter().any(|l| l.triangle == *t))
            .unwrap_or(hits[0].triangle);
        match self.triangle {
            None => (Value::Number(value), found),
            Some(_) => (
                Value::Map(vec![
                    ("triangle".into(), Value::Integer(found as i64)),
                    ("value".into(), Value::Number(value)),
                ]),
                found,
            ),
        }
    }
}

/// `at`: two numbers, as an array or the text `"x,y"`.
fn point(inputs: &Inputs<'_>) -> Result<[Q; 2], InputError> {
    let node = inputs.required("at")?;
    let key = inputs.key("at");
    let v = match &node.value {
        NodeValue::String(s) if s.contains(',') => s
            .split(',')
            .map(|t| {
                crate::number::parse_rational(t).map_err(|e| inputs.file.doc.error(node, &key, e))
            })
            .collect::<Result<Vec<Q>, _>>()?,
        _ => inputs.file.doc.rationals(node, &key)?,
    };
    let n = v.len();
    v.try_into().map_err(|_| {
        inputs.error(
            "at",
            Problem::FieldCount {
                found: n,
                expected: 2,
            },
        )
    })
}

/// Judge a `lookup` claim (module documentation).
pub fn judge(
    file: &ClaimFile,
    claim: &Claim,
    inputs: &Inputs<'_>,
    op: &LookupOp,
) -> Result<Judged, InputError> {
    let (tolerance, precision) = file.tolerance_of(claim)?;
    if tolerance == Tolerance::Bound {
        return Err(inputs.error("tolerance", ClaimProblem::BoundNotForLookup));
    }
    let seen_op;
    let op = match precision {
        Some(p) => {
            seen_op = op.seen(inputs, p)?;
            &seen_op
        }
        None => op,
    };
    let (hits, value) = op.answer(inputs)?;
    let (exact, found) = op.value_of(&hits, value);
    // invariant: `value_of` picks `found` from these hits
    let located = hits
        .iter()
        .find(|l| l.triangle == found)
        .expect("found among the hits");
    let condition = op
        .mesh
        .condition(located)
        .map_err(|e| inputs.error("mesh", MeshFileProblem::Mesh(e)))?;
    let tolerance = tolerance.for_patch(2, op.mesh.degree());
    let expect = inputs.get("expect").ok_or_else(|| {
        file.doc
            .error(&claim.node, &claim.id, ClaimProblem::MissingExpect)
    })?;
    let key = inputs.key("expect");
    let mut claimed_value = file.doc.rational(expect, &key)?;
    if let Some(p) = precision {
        claimed_value = as_float(&claimed_value, p).ok_or_else(|| {
            file.doc.error(
                expect,
                &key,
                Problem::Overflows {
                    what: "a claimed number",
                    precision: p,
                },
            )
        })?;
    }
    let claimed = match op.triangle {
        None => Value::Number(claimed_value),
        Some(t) => Value::Map(vec![
            ("triangle".into(), Value::Integer(t as i64)),
            ("value".into(), Value::Number(claimed_value)),
        ]),
    };
    let leaf = |_: usize| Leaf {
        precision,
        condition: tolerance.is_cond().then(|| condition.clone()),
        bound: None,
    };
    let mut mismatches: Vec<Mismatch> = Vec::new();
    compare(
        &claimed,
        &exact,
        &tolerance,
        &leaf,
        &mut 0,
        "",
        &mut mismatches,
    )
    .map_err(|e| inputs.error("tolerance", e))?;
    if let Some(m) = mismatches.iter_mut().find(|m| m.path == ".\"triangle\"") {
        let containing: Vec<String> = hits.iter().map(|l| l.triangle.to_string()).collect();
        m.reason = format!(
            "the point is not in triangle {}; it is in triangle {}",
            m.claimed,
            containing.join(" and ")
        );
    }
    Ok(Judged {
        file: file.path.display().to_string(),
        id: claim.id.clone(),
        op: claim.op.clone(),
        source: claim.source.clone().or_else(|| file.source.clone()),
        erratum: claim.erratum.clone(),
        exact,
        claimed,
        verdict: Verdict::of(mismatches, claim.erratum.is_some()),
        tolerance,
        precision,
        floats: Vec::new(),
    })
}
