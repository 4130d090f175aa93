//! Shared by the construction commands (blossom, subpatch, subdivide, halve, elevate, matrix,
//! graph): parsing of points and edges, child patches, and patch-valued reports written in the
//! patch-file format (polynomial or any kind) so that commands compose.

use num_rational::BigRational;
use serde::Serialize;
use serde_json::Value as Json;

use super::{CliError, check_barycentric, parse_list};
use crate::report::{Render, to_json};
use tribez::constructions::binomial;
use tribez::limits::{MAX_CONTROL_POINTS, MAX_DEGREE};
use tribez::{Constructions, Patch, SubPatch};

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
            tribez::constructions::check_edge(m, *i, *j).map_err(|e| CliError::core(what, e))
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
    let total = binomial((n + m) as u64, m as u64);
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

/// The constructions of `patch` (every kind but S-patches, which are a usage error naming
/// `command`).
pub fn constructions<'a>(
    file: &str,
    command: &str,
    patch: &'a tribez::Patch,
) -> Result<Box<dyn Constructions + 'a>, CliError> {
    patch.constructions().ok_or_else(|| {
        CliError::Usage(format!(
            "{file}: `tribez {command}` does not take S-patches"
        ))
    })
}

/// Name a constructed patch after its parent: `"<parent's name>, <label>"`, or `label`.
pub fn relabel(patch: &mut Patch, label: &str) {
    let name = match patch.name() {
        Some(n) => format!("{n}, {label}"),
        None => label.to_string(),
    };
    patch.set_name(Some(name));
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

/// The JSON patch file of a patch of any kind, with `domain_in_parent` if given.
pub fn json_with_any(patch: &Patch, f: Option<&[Vec<BigRational>]>) -> Json {
    to_json(&PatchJson {
        patch: patch.to_json_value(),
        domain_in_parent: f.map(point_strings),
    })
}

/// A patch-valued result of any kind: text is the TOML patch file, JSON the JSON patch file,
/// each with `domain_in_parent` when the patch is a subpatch.
pub struct PatchReport {
    /// The patch.
    pub patch: Patch,
    /// Its simplex in the parent's barycentric coordinates, if it is a subpatch.
    pub domain_in_parent: Option<Vec<Vec<BigRational>>>,
}

impl PatchReport {
    /// The patch alone (not a subpatch).
    pub fn of(patch: impl Into<Patch>) -> Self {
        PatchReport {
            patch: patch.into(),
            domain_in_parent: None,
        }
    }
}

impl Render for PatchReport {
    fn text(&self) -> String {
        let text = self.patch.to_toml();
        let Some(f) = &self.domain_in_parent else {
            return text;
        };
        // a top-level key: after the others, before the blank line that opens the first table
        let line = format!("domain_in_parent = {}\n", toml_points(f));
        match text.find("\n[") {
            Some(k) => format!("{}{line}{}", &text[..k], &text[k..]),
            None => text + &line,
        }
    }
    fn json(&self) -> Json {
        json_with_any(&self.patch, self.domain_in_parent.as_deref())
    }
}

/// The pieces of a split: JSON `{"pieces": [{"domain_in_parent": …, "patch": {…}}, …]}`; text
/// the same as a TOML document (`[[pieces]]` with `domain_in_parent` and a `[pieces.patch]`
/// table, its own tables under `pieces.patch.`).
pub struct PiecesReport(pub Vec<Piece>);

/// One piece of a split: its simplex in the parent's barycentric coordinates, and its patch.
pub struct Piece {
    /// The piece's simplex.
    pub domain_in_parent: Vec<Vec<BigRational>>,
    /// The patch.
    pub patch: Patch,
}

impl PiecesReport {
    /// The pieces of a split, each named after its parent with `label(index)` ([`relabel`]).
    pub fn relabelled(pieces: Vec<SubPatch>, label: impl Fn(usize) -> String) -> Self {
        PiecesReport(
            pieces
                .into_iter()
                .map(|p| {
                    let mut patch = Patch::from(p.patch);
                    relabel(&mut patch, &label(p.index));
                    Piece {
                        domain_in_parent: p.domain_in_parent,
                        patch,
                    }
                })
                .collect(),
        )
    }
}

impl Render for PiecesReport {
    fn text(&self) -> String {
        let mut out = String::new();
        for (i, piece) in self.0.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            out += &format!(
                "[[pieces]]\ndomain_in_parent = {}\n\n[pieces.patch]\n",
                toml_points(&piece.domain_in_parent)
            );
            out += &piece
                .patch
                .to_toml()
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
                .map(|piece| PieceJson {
                    domain_in_parent: point_strings(&piece.domain_in_parent),
                    patch: piece.patch.to_json_value(),
                })
                .collect(),
        })
    }
}
