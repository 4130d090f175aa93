//! Shared by the construction commands (blossom, subpatch, subdivide, halve, elevate, matrix,
//! graph): parsing of points and edges, child patches, and patch-valued reports written in the
//! patch-file format (polynomial or any kind) so that commands compose.

use num_rational::BigRational;
use serde::Serialize;
use serde_json::Value as Json;

use super::{CliError, check_barycentric, parse_list};
use crate::report::{Render, to_json};
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::domain::Domain;
use tribez::hazmat::io::patch_file::{
    MAX_CONTROL_POINTS, MAX_DEGREE, any_patch_to_json, any_patch_to_toml, patch_to_json,
    patch_to_toml,
};
use tribez::hazmat::patch::{BezierPatch as Patch, ControlNet};
use tribez::hazmat::simplex;

/// Parse barycentric points given as `--{flag} a,b,c`, each with `m + 1` coordinates summing to 1.
pub fn barycentric_points(
    texts: &[String],
    flag: &str,
    m: usize,
) -> Result<Vec<Vec<BigRational>>, CliError> {
    texts
        .iter()
        .map(|t| {
            let what = format!("--{flag} {t}");
            let p = parse_list(t, &format!("--{flag}"))?;
            check_barycentric(&p, m, "point").map_err(|e| CliError::core(&what, e))?;
            Ok(p)
        })
        .collect()
}

/// Parse `I,J`: two distinct corners numbered 1 to `m + 1`; returns them 0-based.
pub fn parse_edge(text: &str, m: usize) -> Result<(usize, usize), CliError> {
    let what = format!("--edge {text}");
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let nums: Option<Vec<usize>> = parts.iter().map(|p| p.parse::<usize>().ok()).collect();
    match nums.as_deref() {
        Some([i, j]) => {
            tribez::hazmat::subdivide::check_edge(m, *i, *j).map_err(|e| CliError::core(what, e))
        }
        _ => Err(CliError::check(
            what,
            format!(
                "an edge is two corner numbers separated by a comma, like 1,2 (corners 1 to {})",
                m + 1
            ),
        )),
    }
}

/// Check that a degree and simplex dimension give a net small enough to write as a patch file.
pub fn check_size(m: usize, n: usize, what: &str) -> Result<(), CliError> {
    if n > MAX_DEGREE {
        return Err(CliError::check(
            what,
            format!(
                "the result would have degree {n}, above the patch-file limits (degree {MAX_DEGREE}, {MAX_CONTROL_POINTS} points)"
            ),
        ));
    }
    let total = simplex::binomial((n + m) as u64, m as u64);
    if total > MAX_CONTROL_POINTS as u128 {
        return Err(CliError::check(
            what,
            format!(
                "the result would have degree {n} and {total} control points, above the patch-file limits (degree {MAX_DEGREE}, {MAX_CONTROL_POINTS} points)"
            ),
        ));
    }
    Ok(())
}

/// The patch with `net` over the sub-simplex `f` of `parent` (barycentric vertices); its
/// Cartesian domain, if the parent has one, is the image of `f`.
pub fn child_patch(
    parent: &Patch,
    net: ControlNet<BigRational>,
    f: Option<&[Vec<BigRational>]>,
    label: &str,
) -> Result<Patch, CliError> {
    let domain = match (&parent.domain, f) {
        (Some(d), Some(f)) => Some(
            Domain::new(f.iter().map(|v| d.cartesian(v)).collect())
                .map_err(|e| CliError::core("the sub-simplex", e))?,
        ),
        (d, _) => d.clone(),
    };
    let name = Some(match &parent.name {
        Some(n) => format!("{n}, {label}"),
        None => label.to_string(),
    });
    Ok(Patch { name, net, domain })
}

/// The patch whose net a construction runs on: a polynomial patch itself; for a rational patch
/// its homogeneous net `(w c, w)` (every construction here is linear in the net, so it commutes
/// with the projection), with the rational parent to map the pieces back.
pub fn construction_net(
    file: &str,
    command: &str,
    patch: tribez::hazmat::any_patch::AnyPatch,
) -> Result<(Patch, Option<tribez::hazmat::rational::RationalPatch>), CliError> {
    let (mut p, rational) = super::points_patch(file, command, patch)?;
    if let Some(r) = &rational {
        p.net = r.homogeneous();
    }
    Ok((p, rational))
}

/// Pieces of the homogeneous net of `parent` back to rational patches (points and weights),
/// each over its sub-simplex; `label(k)` names piece `k` (0-based).
pub fn rational_pieces(
    file: &str,
    parent: &tribez::hazmat::rational::RationalPatch,
    pieces: Vec<tribez::hazmat::subdivide::Piece<BigRational>>,
    label: impl Fn(usize) -> String,
) -> Result<AnyPiecesReport, CliError> {
    let mut out = Vec::with_capacity(pieces.len());
    for (k, p) in pieces.into_iter().enumerate() {
        let mut piece =
            tribez::hazmat::rational::RationalPatch::from_homogeneous(&p.net, &parent.patch)
                .map_err(|e| CliError::core(format!("{file}: piece {}", k + 1), e))?;
        piece.patch = child_patch(
            &parent.patch,
            piece.patch.net,
            Some(&p.domain_in_parent),
            &label(k),
        )?;
        out.push((p.domain_in_parent, AnyPatch::Rational(piece)));
    }
    Ok(AnyPiecesReport(out))
}

fn strings(p: &[BigRational]) -> Vec<String> {
    p.iter().map(ToString::to_string).collect()
}

fn toml_points(f: &[Vec<BigRational>]) -> String {
    let rows: Vec<String> = f
        .iter()
        .map(|p| {
            format!(
                "[{}]",
                strings(p)
                    .iter()
                    .map(|x| format!("\"{x}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

/// The TOML patch file, with `domain_in_parent` if given, and every table under `prefix`.
fn toml_with(patch: &Patch, f: Option<&[Vec<BigRational>]>, prefix: &str) -> String {
    let text = patch_to_toml(patch);
    let (head, tail) = text
        .split_once("\n[control_points]\n")
        .expect("patch_to_toml writes a control_points table");
    let mut out = head.to_string();
    if !out.is_empty() && !out.ends_with('\n') {
        out.push('\n');
    }
    if let Some(f) = f {
        out += &format!("domain_in_parent = {}\n", toml_points(f));
    }
    out += &format!("\n[{prefix}control_points]\n{tail}");
    out
}

/// A patch file's JSON, followed by `domain_in_parent` when the patch is a subpatch.
#[derive(Serialize)]
struct PatchJson {
    #[serde(flatten)]
    patch: Json,
    #[serde(skip_serializing_if = "Option::is_none")]
    domain_in_parent: Option<Vec<Vec<String>>>,
}

/// One piece of a split: its simplex in the parent's barycentric coordinates and its patch file.
#[derive(Serialize)]
pub struct PieceJson {
    /// The piece's simplex.
    pub domain_in_parent: Vec<Vec<String>>,
    /// The patch file's JSON.
    pub patch: Json,
}

/// The pieces of a split, as JSON.
#[derive(Serialize)]
pub struct PiecesJson {
    /// The pieces.
    pub pieces: Vec<PieceJson>,
}

/// Points as lists of exact strings.
pub fn point_strings(f: &[Vec<BigRational>]) -> Vec<Vec<String>> {
    f.iter().map(|p| strings(p)).collect()
}

/// The JSON patch file, with `domain_in_parent` if given.
pub fn json_with(patch: &Patch, f: Option<&[Vec<BigRational>]>) -> Json {
    to_json(&PatchJson {
        patch: patch_to_json(patch),
        domain_in_parent: f.map(point_strings),
    })
}

/// The JSON patch file of a patch of any kind, with `domain_in_parent` if given.
pub fn json_with_any(patch: &AnyPatch, f: Option<&[Vec<BigRational>]>) -> Json {
    to_json(&PatchJson {
        patch: any_patch_to_json(patch),
        domain_in_parent: f.map(point_strings),
    })
}

/// A patch-valued result: text is the TOML patch file, JSON the JSON patch file.
pub struct PatchReport {
    /// The patch.
    pub patch: Patch,
    /// Its simplex in the parent's barycentric coordinates, if it is a subpatch.
    pub domain_in_parent: Option<Vec<Vec<BigRational>>>,
}

impl Render for PatchReport {
    fn text(&self) -> String {
        toml_with(&self.patch, self.domain_in_parent.as_deref(), "")
    }
    fn json(&self) -> Json {
        json_with(&self.patch, self.domain_in_parent.as_deref())
    }
}

/// Several pieces: JSON `{"pieces": [{"domain_in_parent": …, "patch": {…}}, …]}`; text is the
/// same as a TOML document (`[[pieces]]`).
pub struct PiecesReport {
    /// Each piece's simplex in the parent's barycentric coordinates, and its patch.
    pub pieces: Vec<(Vec<Vec<BigRational>>, Patch)>,
}

impl Render for PiecesReport {
    fn text(&self) -> String {
        let mut out = String::new();
        for (i, (f, p)) in self.pieces.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            out += &format!(
                "[[pieces]]\ndomain_in_parent = {}\n\n[pieces.patch]\n",
                toml_points(f)
            );
            out += &toml_with(p, None, "pieces.patch.");
        }
        out
    }
    fn json(&self) -> Json {
        to_json(&PiecesJson {
            pieces: self
                .pieces
                .iter()
                .map(|(f, p)| PieceJson {
                    domain_in_parent: point_strings(f),
                    patch: patch_to_json(p),
                })
                .collect(),
        })
    }
}

/// A patch of any kind, written as a patch file (TOML text, or JSON): the output of commands that
/// construct rational patches (`elevate`, `subpatch`).
pub struct AnyPatchReport(pub AnyPatch);

impl Render for AnyPatchReport {
    fn text(&self) -> String {
        any_patch_to_toml(&self.0)
    }

    fn json(&self) -> Json {
        any_patch_to_json(&self.0)
    }
}

/// Pieces of a rational patch (`subdivide`), in the layout of the polynomial pieces report:
/// `[[pieces]]` with `domain_in_parent` and a `[pieces.patch]` table (now with `weights`).
pub struct AnyPiecesReport(pub Vec<(Vec<Vec<num_rational::BigRational>>, AnyPatch)>);

fn toml_rows(f: &[Vec<num_rational::BigRational>]) -> String {
    let rows: Vec<String> = f
        .iter()
        .map(|p| {
            let xs: Vec<String> = p.iter().map(|x| format!("\"{x}\"")).collect();
            format!("[{}]", xs.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

impl Render for AnyPiecesReport {
    fn text(&self) -> String {
        let mut out = String::new();
        for (i, (f, p)) in self.0.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            out += &format!(
                "[[pieces]]\ndomain_in_parent = {}\n\n[pieces.patch]\n",
                toml_rows(f)
            );
            out += &any_patch_to_toml(p)
                .replace("\n[control_points]\n", "\n[pieces.patch.control_points]\n")
                .replace("\n[weights]\n", "\n[pieces.patch.weights]\n");
        }
        out
    }

    fn json(&self) -> Json {
        to_json(&PiecesJson {
            pieces: self
                .0
                .iter()
                .map(|(f, p)| PieceJson {
                    domain_in_parent: point_strings(f),
                    patch: any_patch_to_json(p),
                })
                .collect(),
        })
    }
}
