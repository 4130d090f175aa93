//! Reading patch files: the document tree of a TOML or JSON file to a patch of any kind, every
//! check a located [`PatchFileProblem`].

use std::path::Path;

use num_rational::BigRational;

use super::{
    MAX_CONTROL_POINTS, MAX_DEGREE, MAX_SIMPLEX_DIMENSION, PATCH_KEYS, PatchFileProblem, index_key,
};
use crate::any_patch::AnyPatch;
use crate::domain::Domain;
use crate::io::InputError;
use crate::io::tree::{Document, Node};
use crate::patch::{BezierPatch, ControlNet};
use crate::rational::RationalPatch;
use crate::simplex::{self, Simplex};
use crate::spatch::{Polygon, SPatch};

/// Read a patch file: a polynomial Bézier simplex (or a functional patch, as its scalar net).
/// Rational patches and S-patches are rejected with a located error.
pub fn read_patch(path: &Path) -> Result<BezierPatch, InputError> {
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
pub fn patch_from_document(
    doc: &Document,
    node: &Node,
    prefix: &str,
) -> Result<BezierPatch, InputError> {
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
            crate::io::Problem::MissingKey { key: "degree" },
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
    let patch = BezierPatch { name, net, domain };
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
